//! Output files: each output replaces a regular file atomically, or creates one, or is written
//! through to a device, a FIFO or standard output; a run writes them only once all succeeded.
//!
//! What an output path may name, and what happens to it:
//!
//! | the path names | what is written |
//! |---|---|
//! | `-`, `/dev/stdout`, `/dev/fd/1`, `/proc/self/fd/1` | standard output |
//! | nothing yet (its directory exists) | a new file, `rw-rw-rw-` less the umask |
//! | a regular file | replaced atomically: a reader sees the old text or the new, never a part |
//! | a regular file with other hard links | rewritten in place, so that every name sees the new text |
//! | a symbolic link | followed: its target is written as above, in the target's own directory |
//! | a character device or a FIFO | written through, never replaced |
//! | a directory, a block device or a socket | refused |
//!
//! Temporary files live in the target's directory while they are written; they are removed on
//! an error, and by [`remove_pending`] (which the CLI calls on a time-out or a signal).

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Why an output cannot be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The file system refused.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The output, as given.
        path: String,
        /// What the system said.
        source: std::io::Error,
    },
    /// The path names something that is not a file to write (a directory, a block device, a
    /// socket) or a directory that does not exist.
    #[error("cannot write {path}: {reason}")]
    Refused {
        /// The output, as given.
        path: String,
        /// Why.
        reason: String,
    },
    /// Two outputs of one run, or an output and an input, are the same file.
    #[error("{first} and {second} name the same file: give another output path")]
    Same {
        /// The first, with what it is (`-o out.tex`).
        first: String,
        /// The second.
        second: String,
    },
}

/// Where an output's bytes go once the run has succeeded (see [`target`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Sink {
    /// The process's standard output.
    Stdout,
    /// A character device or a FIFO, opened and written as it is.
    Through(PathBuf),
    /// A regular file (or a new one) at this path, every symbolic link resolved: replaced
    /// atomically, or rewritten in place when `in_place` (it has other hard links).
    Replace {
        /// The resolved path.
        path: PathBuf,
        /// Rewrite the existing file instead of replacing it.
        in_place: bool,
    },
}

/// An output path, resolved: what it names and where its bytes go.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Target {
    /// The path as the user gave it (for messages).
    pub given: PathBuf,
    /// Where the bytes go.
    pub sink: Sink,
    /// Device and inode of what the path names now, if it exists.
    id: Option<(u64, u64)>,
}

impl Target {
    /// The resolved path of a regular file to create or replace, if that is what this is
    /// (the directory of an answer key's figures).
    pub fn file(&self) -> Option<&Path> {
        match &self.sink {
            Sink::Replace { path, .. } => Some(path),
            _ => None,
        }
    }
}

/// The names of standard output: the CLI points its file descriptor 1 elsewhere (at stderr,
/// for symbolica's notice), so these are written to the saved standard output instead.
fn is_stdout(path: &Path) -> bool {
    let s = path.as_os_str();
    s == "-" || s == "/dev/stdout" || s == "/dev/fd/1" || s == "/proc/self/fd/1"
}

fn id_of(md: &fs::Metadata) -> (u64, u64) {
    use std::os::unix::fs::MetadataExt;
    (md.dev(), md.ino())
}

/// Resolves an output path (see the module's table). Nothing is created or changed.
///
/// ```
/// use torseur::output::{target, Sink};
/// let dir = tempfile::tempdir().unwrap();
/// let new = dir.path().join("key.tex");
/// assert!(matches!(target(&new).unwrap().sink, Sink::Replace { in_place: false, .. }));
/// assert_eq!(target(std::path::Path::new("-")).unwrap().sink, Sink::Stdout);
/// assert!(target(dir.path()).is_err()); // a directory
/// ```
pub fn target(path: &Path) -> Result<Target, OutputError> {
    use std::os::unix::fs::{FileTypeExt, MetadataExt};
    let given = path.to_path_buf();
    let shown = path.display().to_string();
    let refused = |reason: &str| OutputError::Refused {
        path: shown.clone(),
        reason: reason.to_string(),
    };
    let io = |source| OutputError::Io {
        path: shown.clone(),
        source,
    };
    if is_stdout(path) {
        return Ok(Target {
            given,
            sink: Sink::Stdout,
            id: None,
        });
    }
    match fs::metadata(path) {
        Ok(md) => {
            let kind = md.file_type();
            let sink = if kind.is_file() {
                Sink::Replace {
                    path: fs::canonicalize(path).map_err(io)?,
                    in_place: md.nlink() > 1,
                }
            } else if kind.is_char_device() || kind.is_fifo() {
                Sink::Through(given.clone())
            } else if kind.is_dir() {
                return Err(refused("it is a directory; give a file name"));
            } else if kind.is_block_device() {
                return Err(refused("it is a block device; give a file name"));
            } else {
                return Err(refused("it is a socket; give a file name"));
            };
            Ok(Target {
                given,
                sink,
                id: Some(id_of(&md)),
            })
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let end = dangling_end(path).map_err(io)?;
            let name = end
                .file_name()
                .ok_or_else(|| refused("it names no file"))?
                .to_owned();
            let dir = match end.parent() {
                Some(d) if !d.as_os_str().is_empty() => d,
                _ => Path::new("."),
            };
            let dir = match fs::canonicalize(dir) {
                Ok(d) if d.is_dir() => d,
                _ => {
                    return Err(refused(&format!(
                        "its directory {} does not exist",
                        dir.display()
                    )));
                }
            };
            Ok(Target {
                given,
                sink: Sink::Replace {
                    path: dir.join(name),
                    in_place: false,
                },
                id: None,
            })
        }
        Err(e) => Err(io(e)),
    }
}

/// The path a chain of symbolic links ends at, when that end does not exist yet (a dangling
/// link is followed, and its target created).
fn dangling_end(path: &Path) -> std::io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match fs::symlink_metadata(&p) {
            Ok(md) if md.file_type().is_symlink() => {
                let to = fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(std::io::Error::other("too many levels of symbolic links"))
}

/// Refuses outputs that are the same file as each other or as an input, before any work:
/// `outputs` and `inputs` are (what it is, e.g. `-o key.tex`, and the target or path).
///
/// ```
/// use torseur::output::{distinct, target};
/// let dir = tempfile::tempdir().unwrap();
/// let spec = dir.path().join("s.json");
/// std::fs::write(&spec, "{}").unwrap();
/// let o = target(&spec).unwrap();
/// assert!(distinct(&[("-o s.json".into(), &o)], &[("the spec".into(), &spec)]).is_err());
/// let a = target(&dir.path().join("a.tex")).unwrap();
/// let b = target(&dir.path().join("./a.tex")).unwrap();
/// assert!(distinct(&[("-o".into(), &a), ("--manifest".into(), &b)], &[]).is_err());
/// ```
pub fn distinct(
    outputs: &[(String, &Target)],
    inputs: &[(String, &Path)],
) -> Result<(), OutputError> {
    let same = |a: &str, b: &str| OutputError::Same {
        first: a.to_string(),
        second: b.to_string(),
    };
    for (what, t) in outputs {
        let Some(id) = t.id else { continue };
        for (input, path) in inputs {
            if fs::metadata(path).is_ok_and(|md| id_of(&md) == id) {
                return Err(same(input, what));
            }
        }
    }
    for (k, (a, ta)) in outputs.iter().enumerate() {
        for (b, tb) in &outputs[..k] {
            let clash = match (&ta.sink, &tb.sink) {
                (Sink::Stdout, Sink::Stdout) => true,
                _ if ta.id.is_some() && ta.id == tb.id => true,
                (Sink::Replace { path: p, .. }, Sink::Replace { path: q, .. }) => p == q,
                _ => false,
            };
            if clash {
                return Err(same(b, a));
            }
        }
    }
    Ok(())
}

/// Temporary files and directories to remove if the process is stopped (a time-out, a signal).
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Records a temporary file or directory that [`remove_pending`] removes if the run is stopped.
pub fn register_pending(path: &Path) {
    PENDING
        .lock()
        .unwrap_or_else(|p| p.into_inner())
        .push(path.to_path_buf());
}

/// Forgets a temporary file or directory (it was renamed or removed).
pub fn forget_pending(path: &Path) {
    PENDING
        .lock()
        .unwrap_or_else(|p| p.into_inner())
        .retain(|p| p != path);
}

/// Removes every temporary file and directory still recorded: the CLI calls it before it stops
/// on a time-out or a signal, so that nothing it created survives.
pub fn remove_pending() {
    let paths = std::mem::take(&mut *PENDING.lock().unwrap_or_else(|p| p.into_inner()));
    for p in paths {
        if p.is_dir() {
            let _ = fs::remove_dir_all(&p);
        } else {
            let _ = fs::remove_file(&p);
        }
    }
}

/// The process's umask, read without changing it (`/proc/self/status`), else the usual 022.
fn umask() -> u32 {
    fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("Umask:"))
                .and_then(|v| u32::from_str_radix(v.trim(), 8).ok())
        })
        .unwrap_or(0o022)
}

/// A file being written beside the file it replaces.
struct Staged {
    tmp: tempfile::NamedTempFile,
    path: PathBuf,
    given: String,
}

fn stage(path: &Path, given: &str, bytes: &[u8]) -> Result<Staged, OutputError> {
    use std::os::unix::fs::{MetadataExt, PermissionsExt};
    let io = |source| OutputError::Io {
        path: given.to_string(),
        source,
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut tmp = tempfile::Builder::new()
        .prefix(".tmp-")
        .tempfile_in(dir)
        .map_err(io)?;
    register_pending(tmp.path());
    let old = fs::metadata(path).ok();
    let mode = old
        .as_ref()
        .map(|m| m.permissions().mode() & 0o7777)
        .unwrap_or(0o666 & !umask());
    let done = tmp
        .write_all(bytes)
        .and_then(|_| {
            tmp.as_file()
                .set_permissions(fs::Permissions::from_mode(mode))
        })
        .and_then(|_| tmp.as_file().sync_all());
    if let Err(e) = done {
        forget_pending(tmp.path());
        return Err(io(e));
    }
    // A file replaced by root keeps its owner (best effort: only root may change it).
    if let Some(m) = &old {
        let _ = std::os::unix::fs::fchown(tmp.as_file(), Some(m.uid()), Some(m.gid()));
    }
    Ok(Staged {
        tmp,
        path: path.to_path_buf(),
        given: given.to_string(),
    })
}

/// Writes every output, once the run has succeeded: the files to replace are first written in
/// full beside their targets, then standard output and devices are written, then the files
/// are renamed into place. On an error, no temporary file is left, and no file has been
/// replaced by a partial one.
///
/// ```
/// use torseur::output::{target, write_outputs};
/// let dir = tempfile::tempdir().unwrap();
/// let a = target(&dir.path().join("a.txt")).unwrap();
/// let b = target(&dir.path().join("b.txt")).unwrap();
/// let mut stdout = Vec::new();
/// write_outputs(&[(&a, b"one".as_slice()), (&b, b"two".as_slice())], &mut stdout).unwrap();
/// assert_eq!(std::fs::read(dir.path().join("b.txt")).unwrap(), b"two");
/// assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2); // no temporary file left
/// ```
pub fn write_outputs(
    items: &[(&Target, &[u8])],
    stdout: &mut dyn Write,
) -> Result<(), OutputError> {
    let mut staged = Vec::new();
    let result = (|| {
        for (t, bytes) in items {
            if let Sink::Replace {
                path,
                in_place: false,
            } = &t.sink
            {
                staged.push(stage(path, &t.given.display().to_string(), bytes)?);
            }
        }
        for (t, bytes) in items {
            let given = t.given.display().to_string();
            let io = |source| OutputError::Io {
                path: given.clone(),
                source,
            };
            match &t.sink {
                Sink::Stdout => stdout
                    .write_all(bytes)
                    .and_then(|_| stdout.flush())
                    .map_err(io)?,
                Sink::Through(p) => fs::OpenOptions::new()
                    .write(true)
                    .open(p)
                    .and_then(|mut f| f.write_all(bytes))
                    .map_err(io)?,
                Sink::Replace { .. } => {}
            }
        }
        for s in staged.drain(..) {
            // What the path names may have changed since it was resolved: replace a regular
            // file or nothing, never a device or a link planted meanwhile.
            if let Ok(md) = fs::symlink_metadata(&s.path)
                && !md.file_type().is_file()
            {
                forget_pending(s.tmp.path());
                return Err(OutputError::Refused {
                    path: s.given,
                    reason: "it is no longer a regular file".to_string(),
                });
            }
            let tmp_path = s.tmp.path().to_path_buf();
            let persisted = s.tmp.persist(&s.path);
            forget_pending(&tmp_path);
            persisted.map_err(|e| OutputError::Io {
                path: s.given.clone(),
                source: e.error,
            })?;
        }
        for (t, bytes) in items {
            if let Sink::Replace {
                path,
                in_place: true,
            } = &t.sink
            {
                fs::OpenOptions::new()
                    .write(true)
                    .truncate(true)
                    .open(path)
                    .and_then(|mut f| f.write_all(bytes).and_then(|_| f.sync_all()))
                    .map_err(|source| OutputError::Io {
                        path: t.given.display().to_string(),
                        source,
                    })?;
            }
        }
        Ok(())
    })();
    for s in &staged {
        forget_pending(s.tmp.path());
    }
    result
}

/// Writes `bytes` to `path` as an output of its own (see the module's table): a regular file
/// is replaced atomically, a symbolic link is followed, a device or a FIFO is written through,
/// `-` is standard output. A reader sees the old file or the new one, never a partial one; on
/// error no temporary file is left and an existing file is untouched. An existing file keeps
/// its mode.
///
/// ```
/// let dir = tempfile::tempdir().unwrap();
/// let p = dir.path().join("key.tex");
/// torseur::output::write_atomic(&p, b"\\documentclass{article}").unwrap();
/// assert_eq!(std::fs::read(&p).unwrap(), b"\\documentclass{article}");
/// assert!(torseur::output::write_atomic(&dir.path().join("no/such/dir/x"), b"").is_err());
/// ```
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let t = target(path).map_err(std::io::Error::other)?;
    write_outputs(&[(&t, bytes)], &mut std::io::stdout()).map_err(std::io::Error::other)
}
