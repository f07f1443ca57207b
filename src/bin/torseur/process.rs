//! The process around a run: what it does on SIGABRT (symbolica's refusal, memory that ran
//! out), on SIGINT/SIGTERM/SIGHUP and on `--timeout` (pdflatex killed, temporary files
//! removed, nothing written), and standard output kept for the run's own output.

use super::{Failure, args, bad_input};
use anyhow::{Result, anyhow};
use std::fs::File;
use std::os::fd::FromRawFd;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use torseur::output;

/// Set once symbolica has answered: an abort before that is its refusal to start.
pub(crate) static STARTED: AtomicBool = AtomicBool::new(false);
/// The pdflatex child's process id while it runs (0 otherwise), stopped with the run.
pub(crate) static CHILD: AtomicI32 = AtomicI32::new(0);
/// Set when a time-out or a signal is stopping the process: the main thread then waits for the
/// end instead of reporting pdflatex's death as its failure.
pub(crate) static STOPPING: AtomicBool = AtomicBool::new(false);
/// Held while the outputs are written, and `true` once they are: a time-out or a signal that
/// comes then lets the writing finish, and the run ends as it would have.
pub(crate) static WRITTEN: std::sync::Mutex<bool> = std::sync::Mutex::new(false);

/// What the process says if it aborts (SIGABRT): symbolica refusing a second process, or an
/// allocation that failed. Only async-signal-safe calls: a fixed message, then `_exit(2)`.
extern "C" fn on_abort(_: libc::c_int) {
    let msg: &[u8] = if STARTED.load(Ordering::SeqCst) {
        b"torseur: error: the run was aborted: memory ran out (ask for fewer or smaller \
quantities)\n"
    } else {
        b"torseur: error: symbolica refused to start: another process of this user is using it \
(without a licence key it allows one at a time); wait for it to end, or set SYMBOLICA_LICENSE\n"
    };
    // SAFETY: write(2) and _exit(2) are async-signal-safe; the buffer is a static.
    unsafe {
        libc::write(2, msg.as_ptr().cast(), msg.len());
        libc::_exit(2);
    }
}

pub(crate) fn catch_abort() {
    // SAFETY: a zeroed sigaction with a plain handler and an empty mask is valid.
    unsafe {
        let mut action: libc::sigaction = std::mem::zeroed();
        action.sa_sigaction = on_abort as *const () as libc::sighandler_t;
        libc::sigemptyset(&mut action.sa_mask);
        libc::sigaction(libc::SIGABRT, &action, std::ptr::null_mut());
    }
}

/// Stops the process: pdflatex killed, every temporary file and directory removed, the
/// message on stderr. Used on a time-out and on a signal.
pub(crate) fn stop(message: &str, code: i32) {
    // Held until the process exits: outputs are either all written before, or never.
    let written = WRITTEN.lock().unwrap_or_else(|p| p.into_inner());
    if *written {
        return;
    }
    STOPPING.store(true, Ordering::SeqCst);
    let pid = CHILD.swap(0, Ordering::SeqCst);
    if pid > 0 {
        // SAFETY: kill(2) on our own child's id.
        unsafe { libc::kill(pid, libc::SIGKILL) };
        let start = std::time::Instant::now();
        while std::path::Path::new(&format!("/proc/{pid}/fd")).exists()
            && start.elapsed() < std::time::Duration::from_secs(2)
        {
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
    }
    output::remove_pending();
    eprintln!("torseur: error: {message}");
    std::process::exit(code)
}

/// SIGINT, SIGTERM and SIGHUP stop the run cleanly (exit 128 + the signal's number).
pub(crate) fn watch_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) {
        std::thread::spawn(move || {
            if let Some(sig) = signals.forever().next() {
                let name = match sig {
                    SIGINT => "SIGINT",
                    SIGTERM => "SIGTERM",
                    _ => "SIGHUP",
                };
                stop(&format!("interrupted ({name}): nothing written"), 128 + sig);
            }
        });
    }
}

/// Ends the process with a clear message once `limit` has passed, removing its temporary
/// files first. Outputs are written at the very end, so nothing half-written is left.
pub(crate) fn watchdog(seconds: f64) -> Result<(), Failure> {
    let d = args::time_limit(seconds).map_err(|e| bad_input(anyhow!(e)))?;
    std::thread::spawn(move || {
        std::thread::sleep(d);
        stop(
            &format!("stopped after the time limit of {seconds} s (--timeout): nothing written"),
            2,
        );
    });
    Ok(())
}

pub(crate) fn redirect_stdout() -> Result<File> {
    // SAFETY: dup and dup2 on the standard descriptors; the duplicate is owned by the File.
    unsafe {
        let saved = libc::dup(1);
        if saved < 0 {
            return Err(anyhow!("cannot duplicate stdout"));
        }
        if libc::dup2(2, 1) < 0 {
            return Err(anyhow!("cannot redirect stdout"));
        }
        Ok(File::from_raw_fd(saved))
    }
}
