//! Hostile inputs for the binary, by family: outputs (what an output path may name), inputs
//! (bounded while read, read before the lock), the time limit and signals, the lock, and the
//! PDF. Each case states its exit code and the shape of its message. Nothing here writes to a
//! real device: the device, FIFO and links are made inside a temporary directory.

use super::{bin, files_in, run, spec, stderr, stdout, tmp};
use std::os::unix::fs::{FileTypeExt, MetadataExt};
use std::path::{Path, PathBuf};
use std::process::Output;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A small spec (a skate on ice) whose key compiles fast.
fn small_spec() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/specs/patin.json")
}

fn exit2(o: &Output, shape: &str) {
    assert_eq!(o.status.code(), Some(2), "{}", stderr(o));
    let e = stderr(o);
    let line = e
        .lines()
        .find(|l| l.starts_with("torseur: error:"))
        .unwrap_or_else(|| panic!("no error line: {e}"));
    assert!(line.contains(shape), "{line}");
    assert!(line.len() < 400, "message too long: {line}");
    assert!(!e.contains("panicked"), "{e}");
}

// ---- outputs -----------------------------------------------------------------------------

/// A character device like /dev/null, made inside the temporary directory (root only: the
/// test is skipped otherwise). It is written through and stays a device.
#[test]
fn an_output_that_is_a_device_is_written_through_never_replaced() {
    let d = tmp();
    let node = d.path().join("null");
    let c = std::ffi::CString::new(s(&node)).unwrap();
    // SAFETY: mknod on a path inside our temporary directory; (1, 3) is the null device.
    let made = unsafe { libc::mknod(c.as_ptr(), libc::S_IFCHR | 0o666, libc::makedev(1, 3)) };
    if made != 0 {
        eprintln!("skipped: cannot make a device node here (not root)");
        return;
    }
    for args in [
        vec!["answer-key", s(&small_spec()), "-o", s(&node)],
        vec!["derive", s(&small_spec()), "--json", s(&node)],
        vec![
            "answer-key",
            s(&small_spec()),
            "--manifest",
            s(&node),
            "-o",
            "-",
        ],
    ] {
        let o = run(&args);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        let md = std::fs::symlink_metadata(&node).unwrap();
        assert!(md.file_type().is_char_device(), "the device was replaced");
    }
    // Nothing else appeared beside it: no figure, no temporary file.
    assert_eq!(files_in(d.path()), vec!["null"]);
}

#[test]
fn an_output_that_is_a_fifo_is_written_through() {
    let d = tmp();
    let fifo = d.path().join("pipe");
    let c = std::ffi::CString::new(s(&fifo)).unwrap();
    // SAFETY: mkfifo on a path inside our temporary directory.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    let o = run(&[
        "derive",
        s(&small_spec()),
        "-q",
        "Ec(1/0)",
        "--json",
        s(&fifo),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = reader.join().unwrap();
    assert!(text.contains("\"quantities\""), "{text}");
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
}

#[test]
fn a_symlink_is_followed_and_its_target_replaced_in_its_own_directory() {
    let d = tmp();
    let real_dir = d.path().join("real");
    std::fs::create_dir(&real_dir).unwrap();
    let target = real_dir.join("k.json");
    std::fs::write(&target, "old").unwrap();
    let link = d.path().join("link.json");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let o = run(&[
        "derive",
        s(&small_spec()),
        "-q",
        "Ec(1/0)",
        "--json",
        s(&link),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(
        std::fs::read_to_string(&target)
            .unwrap()
            .contains("Ec(1/0)")
    );
    assert_eq!(files_in(&real_dir), vec!["k.json"]);
    // A dangling link: its target is created.
    let dangling = d.path().join("dangling.json");
    let new = real_dir.join("new.json");
    std::os::unix::fs::symlink(&new, &dangling).unwrap();
    let o = run(&[
        "derive",
        s(&small_spec()),
        "-q",
        "Ec(1/0)",
        "--json",
        s(&dangling),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&new).unwrap().contains("Ec(1/0)"));
    assert!(
        std::fs::symlink_metadata(&dangling)
            .unwrap()
            .file_type()
            .is_symlink()
    );
}

#[test]
fn a_hard_link_keeps_both_names_on_the_new_text() {
    let d = tmp();
    let a = d.path().join("a.json");
    let b = d.path().join("b.json");
    std::fs::write(&a, "old").unwrap();
    std::fs::hard_link(&a, &b).unwrap();
    let o = run(&["derive", s(&small_spec()), "-q", "Ec(1/0)", "--json", s(&a)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&b).unwrap().contains("Ec(1/0)"));
    assert_eq!(std::fs::metadata(&a).unwrap().nlink(), 2);
}

#[test]
fn an_output_that_is_an_input_or_another_output_is_refused_before_any_work() {
    let d = tmp();
    let spec_copy = d.path().join("s.json");
    std::fs::copy(small_spec(), &spec_copy).unwrap();
    let before = std::fs::read(&spec_copy).unwrap();
    // The key over its own spec, directly and through a link.
    exit2(
        &run(&["answer-key", s(&spec_copy), "-o", s(&spec_copy)]),
        "name the same file",
    );
    let link = d.path().join("l.tex");
    std::os::unix::fs::symlink(&spec_copy, &link).unwrap();
    exit2(
        &run(&["answer-key", s(&spec_copy), "-o", s(&link)]),
        "name the same file",
    );
    assert_eq!(std::fs::read(&spec_copy).unwrap(), before);
    // Two outputs of one run on one file, new or not; the PDF over its own .tex.
    let k = d.path().join("k.tex");
    exit2(
        &run(&[
            "answer-key",
            s(&spec_copy),
            "-o",
            s(&k),
            "--manifest",
            s(&k),
        ]),
        "name the same file",
    );
    let kpdf = d.path().join("k.pdf");
    exit2(
        &run(&["answer-key", s(&spec_copy), "-o", s(&kpdf), "--pdf"]),
        "name the same file",
    );
    exit2(
        &run(&["derive", s(&spec_copy), "--json", "-"]),
        "name the same file",
    );
    exit2(
        &run(&[
            "simulate",
            s(&spec_copy),
            "--scenario",
            "x",
            "-o",
            s(&spec_copy),
        ]),
        "name the same file",
    );
    assert_eq!(files_in(d.path()), vec!["l.tex", "s.json"]);
}

#[test]
fn outputs_that_are_not_files_are_refused_with_the_reason() {
    let d = tmp();
    exit2(
        &run(&["answer-key", s(&small_spec()), "-o", s(d.path())]),
        "is a directory",
    );
    exit2(
        &run(&[
            "answer-key",
            s(&small_spec()),
            "-o",
            s(&d.path().join("no/such/k.tex")),
        ]),
        "does not exist",
    );
    exit2(
        &run(&["answer-key", s(&small_spec()), "-o", "-", "--pdf"]),
        "--pdf writes FILE.pdf beside -o FILE.tex",
    );
    assert!(files_in(d.path()).is_empty());
}

#[test]
fn a_dash_writes_to_standard_output() {
    let o = run(&["answer-key", s(&small_spec()), "-o", "-"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("\\documentclass"));
    let o = run(&["answer-key", s(&small_spec()), "-o", "/dev/stdout"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("\\documentclass"));
}

#[test]
fn figures_are_named_after_the_key_and_written_only_on_success() {
    let d = tmp();
    let tex = d.path().join("corrige.tex");
    let o = run(&["answer-key", s(&spec()), "-o", s(&tex)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let names = files_in(d.path());
    assert!(
        names.iter().any(|n| n.starts_with("corrige-simulation-")),
        "{names:?}"
    );
    assert!(
        !names.iter().any(|n| n.starts_with("simulation-")),
        "{names:?}"
    );
    assert!(!names.iter().any(|n| n.starts_with(".tmp-")), "{names:?}");
    let t = std::fs::read_to_string(&tex).unwrap();
    for n in names.iter().filter(|n| n.ends_with(".png")) {
        assert!(t.contains(&format!("{{{n}}}")), "{n} not included");
    }
    // A failing run writes no figure and no key.
    let e = tmp();
    let bad = e.path().join("bad.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(spec()).unwrap()).unwrap();
    v["quantities"] = serde_json::json!(["delta(O9,2/0)"]);
    std::fs::write(&bad, v.to_string()).unwrap();
    let out = e.path().join("k.tex");
    let o = run(&["answer-key", s(&bad), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(files_in(e.path()), vec!["bad.json"]);
}

// ---- inputs ------------------------------------------------------------------------------

#[test]
fn inputs_are_bounded_while_they_are_read() {
    // /dev/zero says its size is 0 and never ends: it is only read, never written.
    exit2(&run(&["derive", "/dev/zero"]), "larger than 4194304 bytes");
    exit2(
        &run(&["eval", s(&small_spec()), "--at", "/dev/zero"]),
        "--at: cannot read /dev/zero: larger than 1048576 bytes",
    );
    exit2(
        &run(&[
            "verify",
            s(&small_spec()),
            "-q",
            "Ec(1/0)",
            "-e",
            "@/dev/zero",
        ]),
        "larger than 16777216 bytes",
    );
    let d = tmp();
    let bin_file = d.path().join("b.json");
    std::fs::write(&bin_file, [b'{', 0xff, b'}']).unwrap();
    exit2(
        &run(&["derive", s(&bin_file)]),
        "not UTF-8 text (invalid byte at offset 1)",
    );
    exit2(&run(&["derive", s(d.path())]), "is a directory");
}

#[test]
fn a_spec_on_standard_input_is_read_and_only_one_input_may_use_it() {
    use std::io::Write;
    let mut c = bin()
        .args(["derive", "-", "-q", "Ec(1/0)"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    c.stdin
        .take()
        .unwrap()
        .write_all(&std::fs::read(small_spec()).unwrap())
        .unwrap();
    let o = c.wait_with_output().unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("Ec(1/0) = "), "{}", stdout(&o));
    exit2(
        &run(&["verify", "-", "-q", "Ec(1/0)", "-e", "@-"]),
        "standard input already gives another input",
    );
}

/// A spec that is a FIFO nobody writes holds its own run only: the next run does not queue
/// behind it, since inputs are read before the lock is taken.
#[test]
fn a_fifo_without_a_writer_holds_only_its_own_run() {
    let d = tmp();
    let fifo = d.path().join("spec.json");
    let c = std::ffi::CString::new(s(&fifo)).unwrap();
    // SAFETY: mkfifo on a path inside our temporary directory.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let mut stuck = bin()
        .args(["derive", s(&fifo)])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(200));
    let start = std::time::Instant::now();
    let o = run(&[
        "derive",
        s(&small_spec()),
        "-q",
        "Ec(1/0)",
        "--timeout",
        "20",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(start.elapsed().as_secs() < 15);
    stuck.kill().unwrap();
    stuck.wait().unwrap();
}

// ---- time limit and signals ---------------------------------------------------------------

#[test]
fn an_absurd_time_limit_is_refused_not_a_panic() {
    for t in ["1e300", "inf", "NaN", "0", "-3"] {
        exit2(
            &run(&["derive", s(&small_spec()), &format!("--timeout={t}")]),
            "--timeout takes a positive number of seconds",
        );
    }
}

/// A time-out while pdflatex runs leaves no temporary directory (in `TMPDIR`) and no
/// temporary file beside the outputs, whatever the moment it strikes.
#[test]
fn a_time_out_during_the_pdf_leaves_nothing_behind() {
    if std::process::Command::new("pdflatex")
        .arg("-version")
        .output()
        .is_err()
    {
        eprintln!("skipped: pdflatex is not installed");
        return;
    }
    for limit in ["0.5", "1.5", "3"] {
        let t = tmp();
        let out = tmp();
        let tex = out.path().join("k.tex");
        let o = bin()
            .env("TMPDIR", t.path())
            .args([
                "answer-key",
                s(&small_spec()),
                "-o",
                s(&tex),
                "--pdf",
                "--timeout",
                limit,
            ])
            .output()
            .unwrap();
        assert!(
            matches!(o.status.code(), Some(0) | Some(2)),
            "{}",
            stderr(&o)
        );
        assert!(files_in(t.path()).is_empty(), "{:?}", files_in(t.path()));
        let left = files_in(out.path());
        assert!(!left.iter().any(|n| n.starts_with(".tmp-")), "{left:?}");
        if o.status.code() == Some(2) {
            assert!(left.is_empty(), "a stopped run wrote {left:?}");
            assert!(stderr(&o).contains("time limit"), "{}", stderr(&o));
        }
    }
}

#[test]
fn a_signal_stops_the_run_and_writes_nothing() {
    let d = tmp();
    let out = d.path().join("chain.json");
    let chain = Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain/chain_9.json");
    let c = bin()
        .args(["derive", s(&chain), "--json", s(&out)])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(600));
    // SAFETY: kill(2) on our own child.
    unsafe { libc::kill(c.id() as i32, libc::SIGTERM) };
    let o = c.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(128 + libc::SIGTERM), "{}", stderr(&o));
    assert!(stderr(&o).contains("interrupted (SIGTERM): nothing written"));
    assert!(files_in(d.path()).is_empty());
}

// ---- the lock ------------------------------------------------------------------------------

#[test]
fn runs_with_different_temporary_directories_still_queue() {
    let dirs: Vec<_> = (0..3).map(|_| tmp()).collect();
    let children: Vec<_> = dirs
        .iter()
        .map(|t| {
            bin()
                .env("TMPDIR", t.path())
                .args(["derive", s(&spec())])
                .stdout(std::process::Stdio::piped())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for c in children {
        let o = c.wait_with_output().unwrap();
        assert!(o.status.success(), "exit {:?}: {}", o.status, stderr(&o));
    }
}

#[test]
fn the_lock_refuses_planted_links_and_foreign_directories_and_tolerates_any_content() {
    use torseur::lock::ProcessLock;
    let d = tmp();
    // A link planted in place of the directory: refused, its target untouched.
    let victim = d.path().join("victim");
    std::fs::create_dir(&victim).unwrap();
    let dir = d.path().join("locks");
    std::os::unix::fs::symlink(&victim, &dir).unwrap();
    let e = ProcessLock::acquire_in(&dir, || {})
        .unwrap_err()
        .to_string();
    assert!(e.contains("not a directory"), "{e}");
    assert!(files_in(&victim).is_empty());
    std::fs::remove_file(&dir).unwrap();
    // Any content, even not UTF-8 or huge, is tolerated and replaced by our process id.
    std::fs::create_dir(&dir).unwrap();
    let mut junk = vec![0xff_u8, 0xfe, b'\n'];
    junk.extend(std::iter::repeat_n(b'9', 100_000));
    std::fs::write(dir.join("lock"), &junk).unwrap();
    let lock = ProcessLock::acquire_in(&dir, || {}).unwrap();
    assert_eq!(
        std::fs::read_to_string(dir.join("lock")).unwrap(),
        std::process::id().to_string()
    );
    drop(lock);
    // A directory open to others is closed again.
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o777)).unwrap();
    drop(ProcessLock::acquire_in(&dir, || {}).unwrap());
    assert_eq!(std::fs::metadata(&dir).unwrap().mode() & 0o777, 0o700);
    // Another user's directory (made so by root only).
    // SAFETY: chown on a path inside our temporary directory.
    let c = std::ffi::CString::new(s(&dir)).unwrap();
    if unsafe { libc::chown(c.as_ptr(), 12345, 12345) } == 0 {
        let e = ProcessLock::acquire_in(&dir, || {})
            .unwrap_err()
            .to_string();
        assert!(e.contains("belongs to another user (uid 12345)"), "{e}");
    }
    // The user's lock ignores TMPDIR.
    assert!(torseur::lock::lock_path().starts_with("/tmp/"));
}

// ---- the PDF ------------------------------------------------------------------------------

#[test]
fn the_pdf_is_byte_reproducible() {
    if std::process::Command::new("pdflatex")
        .arg("-version")
        .output()
        .is_err()
    {
        eprintln!("skipped: pdflatex is not installed");
        return;
    }
    let pdfs: Vec<Vec<u8>> = (0..2)
        .map(|_| {
            let d = tmp();
            let tex = d.path().join("k.tex");
            let o = run(&["answer-key", s(&small_spec()), "-o", s(&tex), "--pdf"]);
            assert!(o.status.success(), "{}", stderr(&o));
            std::thread::sleep(std::time::Duration::from_millis(1100));
            std::fs::read(d.path().join("k.pdf")).unwrap()
        })
        .collect();
    assert!(pdfs[0].starts_with(b"%PDF"));
    assert!(pdfs[0] == pdfs[1], "two runs gave different PDFs");
}
