//! Expression parsing into the canonical form: never panics; what parses prints to a text that
//! parses back to the same canonical form.
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::rc::Rc;
use torseur::expr::Registry;
use torseur::spec::wire::CoordinateKind;

thread_local! {
    static REG: Rc<Registry> = Registry::new(
        &["m".into(), "L".into(), "A2".into()],
        &[("theta1".into(), CoordinateKind::Angle), ("x".into(), CoordinateKind::Length)],
    )
    .expect("registry");
}

fuzz_target!(|data: &[u8]| {
    let Ok(s) = std::str::from_utf8(data) else { return };
    if s.len() > 300 {
        return; // keep each run short: expansions of long inputs are legitimately slow
    }
    REG.with(|reg| {
        if let Ok(e) = reg.parse(s)
            && e.nterms() < 2_000
        {
            let text = e.to_string();
            // The round trip is promised within the parser's input limit.
            if text.len() <= torseur::expr::MAX_INPUT_LEN {
                let back = reg.parse(&text).expect("printed expression parses");
                assert_eq!(back, e);
            }
        }
    });
});
