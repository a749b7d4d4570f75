//! Reading part files and writing outputs: the only module that touches
//! the file system for them (`include` reads through `source_of` too).

use crate::diag::{Diagnostic, Source, display_path};
use std::io::Read;
use std::path::Path;

/// The largest part file read, in bytes: a 100,000-part file of 17-digit
/// numbers is ~30 MB and takes ~15 bytes of memory per byte to read, so this
/// allows ~1.7 million parts in ~8 GB.
pub const MAX_FILE_BYTES: u64 = 512 << 20;

/// Read a part file, or standard input for `-`, refusing directories and
/// anything over `MAX_FILE_BYTES`.
pub fn read_source(path: &str) -> Result<Source, Diagnostic> {
    read_source_at(Path::new(path))
}

/// `read_source` of any path, UTF-8 or not (`check DIR` finds such
/// names): the source is named by `display_path` and opened by `path`.
pub fn read_source_at(path: &Path) -> Result<Source, Diagnostic> {
    let stdin = path.as_os_str() == "-";
    let shown = display_path(path);
    let name = if stdin { "<stdin>" } else { shown.as_str() };
    let too_big = || {
        Diagnostic::file(
            name,
            format!(
                "{} is larger than the limit of {} MiB for a part file",
                if stdin { "standard input" } else { "the file" },
                MAX_FILE_BYTES >> 20
            ),
        )
    };
    let cannot_read = |e: std::io::Error| {
        let what = if stdin { "standard input" } else { "file" };
        Diagnostic::file(name, format!("cannot read {what}: {e}"))
    };
    // At most the limit and one byte, so that /dev/zero or an endless pipe
    // cannot read forever.
    let capped = |reader: &mut dyn Read| -> Result<Vec<u8>, Diagnostic> {
        let mut bytes = Vec::new();
        reader
            .take(MAX_FILE_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(cannot_read)?;
        if bytes.len() as u64 > MAX_FILE_BYTES {
            return Err(too_big());
        }
        Ok(bytes)
    };
    if stdin {
        return source_of(name, capped(&mut std::io::stdin())?);
    }
    let meta = std::fs::metadata(path).map_err(cannot_read)?;
    if meta.is_dir() {
        return Err(Diagnostic::file(
            name,
            "cannot read file: it is a directory (`check` searches directories)",
        ));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(too_big());
    }
    // Not only regular files: `massprop report <(generate)` is a pipe.
    let mut file = std::fs::File::open(path).map_err(cannot_read)?;
    Ok(source_of(name, capped(&mut file)?)?.read_from(path.to_path_buf()))
}

/// A part file's bytes as its source: UTF-8, or an error at the first byte
/// that is not (with its line and column, as any other error).
pub fn source_of(name: &str, bytes: Vec<u8>) -> Result<Source, Diagnostic> {
    match String::from_utf8(bytes) {
        Ok(text) => Ok(Source::new(name, text)),
        Err(e) => {
            let at = e.utf8_error().valid_up_to();
            let byte = e.as_bytes()[at];
            // The text up to `at` is valid, so the lossy copy has the same
            // offsets there; the bad byte shows as U+FFFD under the caret.
            let lossy = String::from_utf8_lossy(e.as_bytes()).into_owned();
            let source = Source::new(name, lossy);
            let at = at.saturating_sub(if source.bom { 3 } else { 0 });
            Err(source
                .error(at..at + 1, format!("invalid UTF-8 (byte 0x{byte:02x})"))
                .help("a part file is UTF-8 text; re-save it as UTF-8"))
        }
    }
}

/// Replace `path` by `text` through a temporary file in the same directory
/// and a rename, so an interrupted or failed run never leaves half a file
/// (`what` names it in the error).
pub fn write_atomically(path: &str, text: &str, what: &str) -> Result<(), Diagnostic> {
    let fail = |e: std::io::Error| Diagnostic::file(path, format!("cannot write {what}: {e}"));
    // A symlink is written through (the link stays a link, its target gets
    // the text); something that is not a regular file (/dev/stdout, a FIFO,
    // a device) cannot be replaced by a rename and is written directly.
    // NOTE: asked first, of the path itself (stat follows the links): with
    // stdout a pipe, /dev/stdout resolves to /proc/self/fd/1 and on to
    // `pipe:[N]`, which `canonicalize` cannot resolve — the rename below
    // then replaced the /dev/stdout symlink itself.
    if let Ok(meta) = std::fs::metadata(path)
        && !meta.is_file()
        && !meta.is_dir()
    {
        return std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .and_then(|mut f| std::io::Write::write_all(&mut f, text.as_bytes()))
            .map_err(fail);
    }
    let resolved = match std::fs::canonicalize(path) {
        Ok(real) => match std::fs::metadata(&real) {
            Ok(meta) if !meta.is_file() && !meta.is_dir() => {
                return std::fs::OpenOptions::new()
                    .write(true)
                    .open(&real)
                    .and_then(|mut f| std::io::Write::write_all(&mut f, text.as_bytes()))
                    .map_err(fail);
            }
            _ => real,
        },
        Err(_) => std::path::PathBuf::from(path),
    };
    let target = resolved.as_path();
    let dir = target
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(std::path::Path::new("."));
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{name}.massprop.{}", std::process::id()));
    // create_new: never through a symlink or file already at that name.
    let written = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&tmp)
        .and_then(|mut f| std::io::Write::write_all(&mut f, text.as_bytes()));
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(fail(e));
    }
    if let Ok(meta) = std::fs::metadata(target) {
        let _ = std::fs::set_permissions(&tmp, meta.permissions());
    }
    std::fs::rename(&tmp, target).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        fail(e)
    })
}
