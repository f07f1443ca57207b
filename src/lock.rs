//! One symbolica process at a time: a machine-wide lock file that queues `torseur` runs.
//!
//! Without a licence key symbolica allows one process per user on the machine and aborts a
//! second one. A run takes this lock before its first symbolica call and keeps it until it
//! exits; the next run waits for the lock, then also waits until the previous holder's process
//! has fully exited (the kernel releases the lock when the file is closed, a moment before the
//! process is gone), so the limit is respected, never bypassed.

use fs4::fs_std::FileExt;
use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// The held lock; released when dropped or when the process exits.
#[derive(Debug)]
pub struct ProcessLock {
    _file: File,
}

/// Where the lock lives: `$TORSEUR_LOCK`, else `torseur-<uid>.lock` in the temp directory.
pub fn lock_path() -> PathBuf {
    if let Some(p) = std::env::var_os("TORSEUR_LOCK") {
        return PathBuf::from(p);
    }
    // SAFETY: getuid has no preconditions and cannot fail.
    let uid = unsafe { libc::getuid() };
    std::env::temp_dir().join(format!("torseur-{uid}.lock"))
}

fn process_alive(pid: i32) -> bool {
    match std::fs::read_to_string(format!("/proc/{pid}/stat")) {
        // A zombie has released everything it held.
        Ok(stat) => !stat
            .rsplit_once(')')
            .is_some_and(|(_, rest)| rest.trim_start().starts_with('Z')),
        Err(_) => false,
    }
}

impl ProcessLock {
    /// Waits for the lock (calling `waiting` once if it has to wait), then for the previous
    /// holder to be gone, and records this process as the holder.
    pub fn acquire(mut waiting: impl FnMut()) -> std::io::Result<ProcessLock> {
        let path = lock_path();
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)?;
        if !FileExt::try_lock_exclusive(&file)? {
            waiting();
            FileExt::lock_exclusive(&file)?;
        }
        let mut previous = String::new();
        file.seek(SeekFrom::Start(0))?;
        file.read_to_string(&mut previous)?;
        if let Ok(pid) = previous.trim().parse::<i32>() {
            let me = std::process::id() as i32;
            let start = Instant::now();
            while pid != me && process_alive(pid) && start.elapsed() < Duration::from_secs(30) {
                std::thread::sleep(Duration::from_millis(5));
            }
        }
        file.set_len(0)?;
        file.seek(SeekFrom::Start(0))?;
        write!(file, "{}", std::process::id())?;
        file.flush()?;
        Ok(ProcessLock { _file: file })
    }
}
