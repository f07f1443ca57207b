//! Inputs read with a bound: a file, or standard input for `-`, never more than a limit.
//!
//! The bound is enforced while reading, not from the file's size as the system reports it:
//! `/dev/zero`, a `/proc` file or a pipe say nothing true of their length.

use std::io::Read;
use std::path::Path;

/// Largest spec accepted (a hand-written spec is a few kilobytes).
pub const MAX_SPEC_BYTES: u64 = 4 << 20;
/// Largest values file accepted by `eval --at`.
pub const MAX_VALUES_BYTES: u64 = 1 << 20;
/// Largest text accepted by `verify --expr @FILE` (a chain's equation of motion is long).
pub const MAX_EXPR_BYTES: u64 = 16 << 20;

/// Why an input could not be read.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    /// The system refused.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The input, as given.
        path: String,
        /// What the system said.
        source: std::io::Error,
    },
    /// Longer than its bound.
    #[error("cannot read {path}: larger than {limit} bytes")]
    TooLarge {
        /// The input, as given.
        path: String,
        /// The bound, in bytes.
        limit: u64,
    },
    /// Not UTF-8 text.
    #[error("cannot read {path}: not UTF-8 text (invalid byte at offset {offset})")]
    NotText {
        /// The input, as given.
        path: String,
        /// Byte offset of the first invalid byte.
        offset: usize,
    },
}

/// Reads the UTF-8 text of `path` (standard input for `-`), refusing it as soon as it passes
/// `limit` bytes.
///
/// ```
/// use torseur::input::read_text;
/// let dir = tempfile::tempdir().unwrap();
/// let p = dir.path().join("spec.json");
/// std::fs::write(&p, "{}").unwrap();
/// assert_eq!(read_text(&p, 10).unwrap(), "{}");
/// std::fs::write(&p, "x".repeat(11)).unwrap();
/// assert!(read_text(&p, 10).unwrap_err().to_string().ends_with("larger than 10 bytes"));
/// ```
pub fn read_text(path: &Path, limit: u64) -> Result<String, InputError> {
    let shown = if path.as_os_str() == "-" {
        "standard input".to_string()
    } else {
        path.display().to_string()
    };
    let io = |source| InputError::Io {
        path: shown.clone(),
        source,
    };
    let mut bytes = Vec::new();
    if path.as_os_str() == "-" {
        std::io::stdin()
            .lock()
            .take(limit + 1)
            .read_to_end(&mut bytes)
            .map_err(io)?;
    } else {
        let file = std::fs::File::open(path).map_err(io)?;
        if file.metadata().map_err(io)?.is_dir() {
            return Err(io(std::io::Error::other("it is a directory")));
        }
        file.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    }
    if bytes.len() as u64 > limit {
        return Err(InputError::TooLarge { path: shown, limit });
    }
    String::from_utf8(bytes).map_err(|e| InputError::NotText {
        path: shown,
        offset: e.utf8_error().valid_up_to(),
    })
}
