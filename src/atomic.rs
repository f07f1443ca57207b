//! Atomic file output: nothing half-written, never a truncated existing file.

use std::io::Write;
use std::path::Path;

/// Writes `bytes` to `path` atomically: into a temporary file in the same directory, synced,
/// then renamed over `path`. A reader sees the old file or the new one, never a partial one;
/// on error the temporary file is removed and an existing file is untouched. An existing
/// file keeps its mode; a new one gets `rw-r--r--`.
///
/// ```
/// let dir = tempfile::tempdir().unwrap();
/// let p = dir.path().join("key.tex");
/// torseur::output::write_atomic(&p, b"\\documentclass{article}").unwrap();
/// assert_eq!(std::fs::read(&p).unwrap(), b"\\documentclass{article}");
/// assert!(torseur::output::write_atomic(&dir.path().join("no/such/dir/x"), b"").is_err());
/// ```
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let with_path = |e: std::io::Error| {
        std::io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display()))
    };
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::Builder::new()
        .prefix(".tmp-")
        .tempfile_in(dir)
        .map_err(with_path)?;
    tmp.write_all(bytes).map_err(with_path)?;
    tmp.as_file().sync_all().map_err(with_path)?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path)
            .map(|m| m.permissions().mode())
            .unwrap_or(0o644);
        tmp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(mode))
            .map_err(with_path)?;
    }
    tmp.persist(path).map_err(|e| with_path(e.error))?;
    Ok(())
}
