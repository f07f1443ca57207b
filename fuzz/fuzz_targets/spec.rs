//! Spec loading (JSON, validation, expressions, quantities): never panics.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(s) = std::str::from_utf8(data) else { return };
    if s.len() > 20_000 {
        return;
    }
    let _ = torseur::spec::from_str(s);
});
