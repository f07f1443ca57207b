//! Quantity notation: never panics; what parses prints back to the same quantity.
#![no_main]
use libfuzzer_sys::fuzz_target;
use torseur::quantity::Quantity;

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data)
        && let Ok(q) = Quantity::parse(s)
    {
        let back = Quantity::parse(&q.to_string()).expect("printed quantity parses");
        assert_eq!(back, q);
    }
});
