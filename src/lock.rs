//! One symbolica process at a time: a per-user lock file that queues `torseur` runs.
//!
//! Without a licence key symbolica allows one process per user on the machine and aborts a
//! second one. A run takes this lock before its first symbolica call and keeps it until it
//! exits; the next run waits for the lock, then also waits until the previous holder's process
//! has fully exited (the kernel releases the lock when the file is closed, a moment before the
//! process is gone), so the limit is respected, never bypassed.
//!
//! The lock cannot be moved or planted: it lives in `/tmp/torseur-<uid>/` whatever `TMPDIR`
//! says (symbolica's rule does not follow `TMPDIR` either); that directory is created `0700`
//! and must belong to the user; the file is opened without following a symbolic link, must be
//! a regular file of the user's, and is never truncated before it is locked. Its content (the
//! holder's process id) is only a hint: whatever it holds is tolerated.

use fs4::fs_std::FileExt;
use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, SeekFrom, Write};
use std::os::unix::fs::{DirBuilderExt, MetadataExt, OpenOptionsExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The held lock; released when dropped or when the process exits.
#[derive(Debug)]
pub struct ProcessLock {
    _file: File,
}

/// Why the lock could not be taken: its place is not safe, or the system refused.
#[derive(Debug, thiserror::Error)]
pub enum LockError {
    /// The lock's directory or file is not what it must be (another user's, a link, open to
    /// others): nothing was written.
    #[error("the lock {path} is unsafe: {reason}")]
    Unsafe {
        /// The directory or file.
        path: String,
        /// What is wrong, and the fix.
        reason: String,
    },
    /// Another process of the user holds the lock ([`ProcessLock::try_acquire`] only).
    #[error(
        "another process of this user is using torseur{}: unlicensed symbolica allows one \
         process at a time; let it finish, or set SYMBOLICA_LICENSE",
        .holder.map(|p| format!(" (pid {p})")).unwrap_or_default()
    )]
    Held {
        /// The holder's process id, as the lock file says (a hint).
        holder: Option<i32>,
    },
    /// The system refused.
    #[error("cannot use the lock {path}: {source}")]
    Io {
        /// The directory or file.
        path: String,
        /// What the system said.
        source: std::io::Error,
    },
}

fn uid() -> u32 {
    // SAFETY: getuid has no preconditions and cannot fail.
    unsafe { libc::getuid() }
}

/// The user's lock directory, `/tmp/torseur-<uid>`: the same for every run of the user,
/// whatever its environment.
pub fn lock_dir() -> PathBuf {
    PathBuf::from(format!("/tmp/torseur-{}", uid()))
}

/// Where the lock lives: `lock` in [`lock_dir`].
pub fn lock_path() -> PathBuf {
    lock_dir().join("lock")
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

/// Creates `dir` (`0700`) or checks it: a real directory (not a link), the user's, closed to
/// others (a directory of the user's that is open to others is closed again).
fn safe_dir(dir: &Path) -> Result<(), LockError> {
    let shown = dir.display().to_string();
    let io = |source| LockError::Io {
        path: shown.clone(),
        source,
    };
    let unsafe_ = |reason: String| LockError::Unsafe {
        path: shown.clone(),
        reason,
    };
    match std::fs::DirBuilder::new().mode(0o700).create(dir) {
        Ok(()) => {}
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
        Err(e) => return Err(io(e)),
    }
    let md = std::fs::symlink_metadata(dir).map_err(io)?;
    if !md.file_type().is_dir() {
        return Err(unsafe_(
            "it is not a directory (a link or a file was put there); remove it".to_string(),
        ));
    }
    if md.uid() != uid() {
        return Err(unsafe_(format!(
            "it belongs to another user (uid {}); remove it",
            md.uid()
        )));
    }
    if md.permissions().mode() & 0o077 != 0 {
        std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o700)).map_err(io)?;
    }
    Ok(())
}

impl ProcessLock {
    /// Waits for the user's lock (calling `waiting` once if it has to wait), then for the
    /// previous holder to be gone, and records this process as the holder.
    pub fn acquire(waiting: impl FnMut()) -> Result<ProcessLock, LockError> {
        Self::acquire_in(&lock_dir(), waiting)
    }

    /// [`ProcessLock::acquire`] with the lock in `dir` (created `0700` if absent): for tests.
    ///
    /// ```
    /// let dir = tempfile::tempdir().unwrap();
    /// let d = dir.path().join("locks");
    /// let lock = torseur::lock::ProcessLock::acquire_in(&d, || {}).unwrap();
    /// let pid = std::fs::read_to_string(d.join("lock")).unwrap();
    /// assert_eq!(pid, std::process::id().to_string());
    /// drop(lock);
    /// // A link planted in place of the lock is refused, and its target is untouched.
    /// std::fs::remove_file(d.join("lock")).unwrap();
    /// std::fs::write(dir.path().join("victim"), "keep").unwrap();
    /// std::os::unix::fs::symlink(dir.path().join("victim"), d.join("lock")).unwrap();
    /// assert!(torseur::lock::ProcessLock::acquire_in(&d, || {}).is_err());
    /// assert_eq!(std::fs::read_to_string(dir.path().join("victim")).unwrap(), "keep");
    /// ```
    pub fn acquire_in(dir: &Path, mut waiting: impl FnMut()) -> Result<ProcessLock, LockError> {
        Self::take(dir, Some(&mut waiting))
    }

    /// Takes the user's lock if it is free, else fails at once with [`LockError::Held`]: for
    /// a caller that must not wait (an interactive Python session).
    pub fn try_acquire() -> Result<ProcessLock, LockError> {
        Self::try_acquire_in(&lock_dir())
    }

    /// [`ProcessLock::try_acquire`] with the lock in `dir`: for tests.
    ///
    /// ```
    /// use torseur::lock::{LockError, ProcessLock};
    /// let dir = tempfile::tempdir().unwrap();
    /// let first = ProcessLock::try_acquire_in(dir.path()).unwrap();
    /// // A second holder in this process is refused at once, naming the holder.
    /// let e = ProcessLock::try_acquire_in(dir.path()).unwrap_err();
    /// assert!(matches!(e, LockError::Held { holder: Some(p) } if p == std::process::id() as i32));
    /// drop(first);
    /// assert!(ProcessLock::try_acquire_in(dir.path()).is_ok());
    /// ```
    pub fn try_acquire_in(dir: &Path) -> Result<ProcessLock, LockError> {
        Self::take(dir, None)
    }

    /// Takes the lock in `dir`: waits for it when `waiting` is given (calling it once), else
    /// fails with [`LockError::Held`].
    fn take(dir: &Path, waiting: Option<&mut dyn FnMut()>) -> Result<ProcessLock, LockError> {
        safe_dir(dir)?;
        let path = dir.join("lock");
        let shown = path.display().to_string();
        let io = |source| LockError::Io {
            path: shown.clone(),
            source,
        };
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .mode(0o600)
            .custom_flags(libc::O_NOFOLLOW | libc::O_CLOEXEC | libc::O_NONBLOCK)
            .open(&path)
            .map_err(|e| {
                if e.raw_os_error() == Some(libc::ELOOP) {
                    LockError::Unsafe {
                        path: shown.clone(),
                        reason: "it is a symbolic link; remove it".to_string(),
                    }
                } else {
                    io(e)
                }
            })?;
        let md = file.metadata().map_err(io)?;
        if !md.file_type().is_file() || md.uid() != uid() {
            return Err(LockError::Unsafe {
                path: shown.clone(),
                reason: "it is not a regular file of this user's; remove it".to_string(),
            });
        }
        if !FileExt::try_lock_exclusive(&file).map_err(io)? {
            let Some(waiting) = waiting else {
                let mut held = Vec::new();
                let _ = (&mut file).take(64).read_to_end(&mut held);
                let holder = String::from_utf8_lossy(&held).trim().parse().ok();
                return Err(LockError::Held { holder });
            };
            waiting();
            FileExt::lock_exclusive(&file).map_err(io)?;
        }
        // The previous holder's process id, whatever the file holds (bounded).
        let mut previous = Vec::new();
        file.seek(SeekFrom::Start(0)).map_err(io)?;
        (&mut file)
            .take(64)
            .read_to_end(&mut previous)
            .map_err(io)?;
        let previous = String::from_utf8_lossy(&previous);
        if let Ok(pid) = previous.trim().parse::<i32>() {
            let me = std::process::id() as i32;
            let start = Instant::now();
            while pid > 0
                && pid != me
                && process_alive(pid)
                && start.elapsed() < Duration::from_secs(30)
            {
                std::thread::sleep(Duration::from_millis(5));
            }
        }
        file.set_len(0).map_err(io)?;
        file.seek(SeekFrom::Start(0)).map_err(io)?;
        write!(file, "{}", std::process::id()).map_err(io)?;
        file.flush().map_err(io)?;
        Ok(ProcessLock { _file: file })
    }
}
