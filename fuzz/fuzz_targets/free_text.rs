//! Free texts (titles, statements, labels) to LaTeX: the escaper and the formula whitelist
//! never panic, and what they print is safe by the reader of `tests/engine/latex_safe.rs`,
//! which shares no code with them (balanced braces, no raw `% # & $` outside formulas, no
//! control character, only macros TeX takes, scripts with an argument, bounded nesting).
#![no_main]
use libfuzzer_sys::fuzz_target;
use torseur::latex::{escape_text, rich_text, rich_text_or_escaped};

#[path = "../../tests/engine/latex_safe.rs"]
#[allow(dead_code)]
mod latex_safe;

fuzz_target!(|data: &[u8]| {
    let Ok(s) = std::str::from_utf8(data) else {
        return;
    };
    let e = escape_text(s);
    assert_eq!(latex_safe::check(&e), Ok(()), "escape_text({s:?}) = {e:?}");
    if let Ok(r) = rich_text(s) {
        assert_eq!(latex_safe::check(&r), Ok(()), "rich_text({s:?}) = {r:?}");
    }
    let r = rich_text_or_escaped(s);
    assert_eq!(
        latex_safe::check(&r),
        Ok(()),
        "rich_text_or_escaped({s:?}) = {r:?}"
    );
});
