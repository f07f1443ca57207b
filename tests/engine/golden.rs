//! Golden files: committed expected outputs compared byte for byte. A mismatch is shown as a
//! unified diff with a few lines of context under a header naming the file and how to
//! re-approve it; a reviewed change is re-approved by running the failing test with
//! `TORSEUR_BLESS=1`, which writes the files instead of comparing them.

use std::path::Path;

/// The variable that re-approves: set, the golden files are written instead of compared.
pub const BLESS: &str = "TORSEUR_BLESS";

/// Lines of unchanged context around each change.
const CONTEXT: usize = 3;

/// Diff lines shown at most; past them the message says how many more there are.
const MAX_LINES: usize = 200;

/// Compares `actual` with the committed file `dir/name` (relative to the crate; `dir` empty for
/// the crate's root), or writes it under [`BLESS`].
#[track_caller]
pub fn golden_in(dir: &str, name: &str, actual: &str) {
    let rel = if dir.is_empty() {
        name.to_string()
    } else {
        format!("{dir}/{name}")
    };
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(&rel);
    if std::env::var_os(BLESS).is_some() {
        std::fs::write(&path, actual).unwrap_or_else(|e| panic!("{rel}: {e}"));
        return;
    }
    let Ok(expected) = std::fs::read_to_string(&path) else {
        panic!("golden file {rel} missing: write it with {}", rerun());
    };
    assert_same_text(&rel, &expected, actual);
}

/// Panics with a unified diff (`-` the golden file `what`, `+` the output) unless `expected`
/// and `actual` are the same text.
#[track_caller]
pub fn assert_same_text(what: &str, expected: &str, actual: &str) {
    if expected != actual {
        panic!("{}", mismatch(what, expected, actual));
    }
}

/// The message of a mismatch: a header, then the unified diff, cut at [`MAX_LINES`] lines.
pub fn mismatch(what: &str, expected: &str, actual: &str) -> String {
    let diff = similar::TextDiff::from_lines(expected, actual)
        .unified_diff()
        .context_radius(CONTEXT)
        .header(&format!("{what} (golden)"), &format!("{what} (output)"))
        .to_string();
    let lines: Vec<&str> = diff.lines().collect();
    let mut shown = lines[..lines.len().min(MAX_LINES)].join("\n");
    if lines.len() > MAX_LINES {
        shown += &format!("\n… {} more diff lines", lines.len() - MAX_LINES);
    }
    format!(
        "golden file {what} differs from the output; if the change is intended, re-approve it \
         with {}\n{shown}",
        rerun()
    )
}

/// The command that re-runs the current test (libtest names each test's thread after it)
/// with [`BLESS`] set.
fn rerun() -> String {
    let test = std::thread::current()
        .name()
        .filter(|n| *n != "main")
        .unwrap_or("<test>")
        .to_string();
    format!("`{BLESS}=1 cargo test --release --test engine {test}`")
}

#[test]
fn a_mismatch_is_a_unified_diff_with_context_and_the_way_to_re_approve() {
    let expected: String = (1..=20).map(|i| format!("line {i}\n")).collect();
    let actual = expected.replace("line 10\n", "line ten\n");
    let m = mismatch("latex/x.tex", &expected, &actual);
    let want = "golden file latex/x.tex differs from the output; if the change is intended, \
         re-approve it with `TORSEUR_BLESS=1 cargo test --release --test engine \
         golden::a_mismatch_is_a_unified_diff_with_context_and_the_way_to_re_approve`\n\
         --- latex/x.tex (golden)\n\
         +++ latex/x.tex (output)\n\
         @@ -7,7 +7,7 @@\n line 7\n line 8\n line 9\n-line 10\n+line ten\n line 11\n line 12\n \
         line 13";
    assert_eq!(m, want);
    // Identical texts pass; a missing final newline is a difference, and is shown.
    assert_same_text("x", &expected, &expected);
    let m = mismatch("x", "a\nb\n", "a\nb");
    assert!(m.contains("-b\n+b\n\\ No newline at end of file"), "{m}");
    // A long diff is cut, and says by how much.
    let other: String = (1..=300).map(|i| format!("other {i}\n")).collect();
    let m = mismatch("x", &expected, &other);
    assert!(m.ends_with("… 123 more diff lines"), "{m}");
    assert_eq!(m.lines().count(), 1 + MAX_LINES + 1);
}
