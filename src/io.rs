//! Reading part files and writing outputs: the only module that touches
//! the file system for them (`include` reads through `source_of` too).

mod utf16;
use crate::diag::{Diagnostic, Source, display_path};
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};

/// A file as the system knows it, so that two names of one file compare
/// equal: on unix its device and inode (a hard link, a symlink, another
/// spelling of its path, the file a shell redirected onto standard input);
/// elsewhere its canonical path.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileId(Key);

#[cfg(unix)]
type Key = (u64, u64);
#[cfg(not(unix))]
type Key = PathBuf;

impl FileId {
    /// The file `path` names (following symlinks), if it exists.
    pub fn of(path: &Path) -> Option<FileId> {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let meta = std::fs::metadata(path).ok()?;
            Some(FileId((meta.dev(), meta.ino())))
        }
        #[cfg(not(unix))]
        {
            std::fs::canonicalize(path).ok().map(FileId)
        }
    }

    /// The file `meta` describes (`path` names it, for systems without
    /// inodes).
    fn of_meta(meta: &std::fs::Metadata, path: &str) -> Option<FileId> {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let _ = path;
            Some(FileId((meta.dev(), meta.ino())))
        }
        #[cfg(not(unix))]
        {
            let _ = meta;
            FileId::of(Path::new(path))
        }
    }

    /// The regular file behind standard input (`massprop report - < x.toml`),
    /// if it is one; not a pipe or a terminal, which no path can name.
    pub fn of_stdin() -> Option<FileId> {
        #[cfg(unix)]
        {
            use std::os::fd::AsFd;
            FileId::of_regular_fd(std::io::stdin().as_fd())
        }
        #[cfg(not(unix))]
        {
            None
        }
    }

    /// The regular file behind standard output (`> out.txt`), likewise.
    pub fn of_stdout() -> Option<FileId> {
        #[cfg(unix)]
        {
            use std::os::fd::AsFd;
            FileId::of_regular_fd(std::io::stdout().as_fd())
        }
        #[cfg(not(unix))]
        {
            None
        }
    }

    #[cfg(unix)]
    fn of_regular_fd(fd: std::os::fd::BorrowedFd<'_>) -> Option<FileId> {
        use std::os::unix::fs::MetadataExt;
        // fstat through a duplicate, so nothing closes the stream.
        let fd = fd.try_clone_to_owned().ok()?;
        let meta = std::fs::File::from(fd).metadata().ok()?;
        meta.is_file().then(|| FileId((meta.dev(), meta.ino())))
    }
}

/// Whether `path` is named as a part file is: `*.toml` (any case). The one
/// rule for the files `check DIR` takes and that `include` may name.
pub fn is_toml(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"))
}

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
    if path.as_os_str() == "-" {
        let name = "<stdin>";
        let mut source = source_of(name, read_capped(&mut std::io::stdin(), name, true, 0)?)?;
        source.piped = true;
        return Ok(source);
    }
    let name = display_path(path);
    let meta = std::fs::metadata(path).map_err(|e| {
        // Any visible file: the user named this one themselves.
        let near = near_name(path, |_| true);
        cannot_read(&name, false, e).suggest(near.as_deref())
    })?;
    check_size(&name, &meta)?;
    // Not only regular files: `massprop report <(generate)` is a pipe.
    let mut file = std::fs::File::open(path).map_err(|e| cannot_read(&name, false, e))?;
    let mut source = source_of(&name, read_capped(&mut file, &name, false, meta.len())?)?
        .read_from(path.to_path_buf());
    source.piped = !meta.is_file();
    Ok(source)
}

/// The most entries of a directory `near_name` looks at: a suggestion is
/// not worth reading a directory of millions.
const MAX_LISTED: usize = 10_000;

/// For a file that does not exist: `path` with its file name replaced by
/// the nearest name its directory holds (`units::suggest`, a few edits
/// away: `lamp.tom` → `lamp.toml`), among visible regular files that
/// `wanted` accepts, so that "did you mean" names only a file of the kind
/// asked for. `None` when `path` exists, has no such neighbour, or its
/// directory cannot be read. The name is as `path` writes it, its last
/// component changed, so the user can type it back.
pub fn near_name(path: &Path, wanted: impl Fn(&Path) -> bool) -> Option<String> {
    if std::fs::symlink_metadata(path).is_ok() {
        return None;
    }
    let asked = path.file_name()?.to_str()?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let names: Vec<String> = std::fs::read_dir(dir)
        .ok()?
        .take(MAX_LISTED)
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file() || t.is_symlink()))
        .filter_map(|e| e.file_name().into_string().ok())
        .filter(|n| !n.starts_with('.') && wanted(Path::new(n)))
        .collect();
    let near = crate::units::suggest(asked, names.iter().map(String::as_str))?;
    Some(display_path(&path.with_file_name(near)))
}

fn cannot_read(name: &str, stdin: bool, e: std::io::Error) -> Diagnostic {
    let what = if stdin { "standard input" } else { "file" };
    Diagnostic::file(name, format!("cannot read {what}: {e}"))
}

fn too_big(name: &str, stdin: bool) -> Diagnostic {
    Diagnostic::file(
        name,
        format!(
            "{} is larger than the limit of {} MiB for a part file",
            if stdin { "standard input" } else { "the file" },
            MAX_FILE_BYTES >> 20
        ),
    )
}

/// Refuse a directory, and a file over the limit before reading it
/// (`name` as shown).
fn check_size(name: &str, meta: &std::fs::Metadata) -> Result<(), Diagnostic> {
    if meta.is_dir() {
        return Err(Diagnostic::file(
            name,
            "cannot read file: it is a directory (`check` searches directories)",
        ));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(too_big(name, false));
    }
    Ok(())
}

/// At most the limit and one byte, so that /dev/zero or an endless pipe
/// cannot read forever.
/// `size`: the bytes expected (the file's size; 0 if not known), so that
/// the buffer is made once at its size, not doubled up to it (a 12 MB file
/// took 16 MiB).
fn read_capped(
    reader: &mut dyn Read,
    name: &str,
    stdin: bool,
    size: u64,
) -> Result<Vec<u8>, Diagnostic> {
    let mut bytes = Vec::with_capacity(size.min(MAX_FILE_BYTES) as usize + 1);
    reader
        .take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| cannot_read(name, stdin, e))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(too_big(name, stdin));
    }
    Ok(bytes)
}

/// A part file's bytes as its source: UTF-8, or an error at the first byte
/// that is not (with its line and column, as any other error).
pub fn source_of(name: &str, bytes: Vec<u8>) -> Result<Source, Diagnostic> {
    if let Some(utf16) = utf16::Utf16::of(&bytes) {
        return Err(utf16.error(name, &bytes));
    }
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
                .help("massprop reads UTF-8 text; re-save the file as UTF-8"))
        }
    }
}

/// The text of a file that does not read as UTF-8, as far as a search
/// needs it to tell a part file from another (`search::likely_part_file`):
/// its first MiB, decoded from UTF-16 when it is that, else with each bad
/// byte as U+FFFD. `None` when it cannot be read.
pub fn sniffed_text(path: &Path) -> Option<String> {
    let mut head = Vec::new();
    std::fs::File::open(path)
        .ok()?
        .take(1 << 20)
        .read_to_end(&mut head)
        .ok()?;
    Some(match utf16::Utf16::of(&head) {
        Some(u) => u.decoded(&head),
        None => String::from_utf8_lossy(&head).into_owned(),
    })
}

/// Replace the output file `path` by `text` (`what` names it in errors):
/// atomically with `replace_by_rename`, or in place with `write_in_place`
/// when it has hard links. A symlink is written through (the link stays a
/// link, its target gets the text), and something that is not a regular
/// file (/dev/stdout, a FIFO, a device) is written directly.
pub fn write_atomically(path: &str, text: &str, what: &str) -> Result<(), Diagnostic> {
    write_atomically_with(path, &|w| w.write_all(text.as_bytes()), what)
}

/// Write `text` to the new file `path` (`what` names it in errors), never
/// over one that exists: the way `replace_by_rename` writes, but the
/// temporary file takes the name only if nothing has it yet
/// (`persist_noclobber`), so a file made meanwhile is not replaced either.
pub fn write_new(path: &str, text: &str, what: &str) -> Result<(), Diagnostic> {
    let exists = || {
        Diagnostic::file(path, format!("{what} already exists; it is left as it is"))
            .help("name a file that does not exist yet, or `-` for standard output")
    };
    // (`symlink_metadata`: a dangling symlink is a name taken too.)
    if std::fs::symlink_metadata(path).is_ok() {
        return Err(exists());
    }
    let content = |w: &mut dyn Write| w.write_all(text.as_bytes());
    match replace_by_rename(Path::new(path), None, &content, path, what, false) {
        Err(_) if std::fs::symlink_metadata(path).is_ok() => Err(exists()),
        other => other,
    }
}

/// What is written: called once, with the file (or standard output) to
/// write it to, so that a long output is written as it is made.
pub type Content<'a> = dyn Fn(&mut dyn Write) -> std::io::Result<()> + 'a;

/// `write_atomically`, the text written by `content`.
pub fn write_atomically_with(path: &str, content: &Content, what: &str) -> Result<(), Diagnostic> {
    let fail = |e: std::io::Error| Diagnostic::file(path, format!("cannot write {what}: {e}"));
    let write_directly = |to: &Path| {
        std::fs::OpenOptions::new()
            .write(true)
            .open(to)
            .and_then(|f| {
                let mut w = std::io::BufWriter::new(f);
                content(&mut w)?;
                w.flush()
            })
            .map_err(fail)
    };
    // `-o /dev/stdout` (or any name of the file) with standard output a
    // file (`{ echo head; massprop … -o /dev/stdout; } > out.txt`): written
    // to standard output, after what the shell wrote there. A rename put a
    // new file in place of out.txt and lost the rest.
    if FileId::of_stdout().is_some_and(|out| FileId::of(Path::new(path)) == Some(out)) {
        let mut out = std::io::BufWriter::new(std::io::stdout().lock());
        return content(&mut out).and_then(|()| out.flush()).map_err(fail);
    }
    // NOTE: asked first, of the path itself (stat follows the links): with
    // stdout a pipe, /dev/stdout resolves to /proc/self/fd/1 and on to
    // `pipe:[N]`, which `canonicalize` cannot resolve — a rename then
    // replaced the /dev/stdout symlink itself.
    if let Ok(meta) = std::fs::metadata(path)
        && !meta.is_file()
        && !meta.is_dir()
    {
        return write_directly(Path::new(path));
    }
    let target = match std::fs::canonicalize(path) {
        Ok(real) => match std::fs::metadata(&real) {
            Ok(meta) if !meta.is_file() && !meta.is_dir() => return write_directly(&real),
            _ => real,
        },
        // A symlink to a file not there yet: the file is made where the
        // link points, and the link stays (a rename replaced the link).
        Err(_) => match std::fs::read_link(path) {
            Ok(to) => Path::new(path).parent().unwrap_or(Path::new("")).join(to),
            Err(_) => PathBuf::from(path),
        },
    };
    match std::fs::metadata(&target) {
        Ok(meta) if links(&meta) > 1 => {
            let mut file = std::fs::OpenOptions::new()
                .read(true)
                .write(true)
                .open(&target)
                .map_err(fail)?;
            // Best effort: it keeps a bless of the same file out meanwhile.
            let _ = file.lock();
            // Its old text is kept to be written back should the write
            // fail: only as much as a part file may hold.
            if meta.len() > MAX_FILE_BYTES {
                return Err(Diagnostic::file(
                    path,
                    format!(
                        "cannot write {what} in place (it has {} hard links): its old text is over {} MiB, too large to keep for a restore; name another file",
                        links(&meta),
                        MAX_FILE_BYTES >> 20
                    ),
                ));
            }
            let old = read_capped(&mut file, path, false, meta.len())?;
            // NOTE: made in memory first: a write in place that fails
            // puts the old text back, and must not have begun before the
            // new text is whole.
            let mut text = Vec::new();
            content(&mut text).map_err(fail)?;
            write_in_place(&mut file, &old, &text, links(&meta), path, what)
        }
        meta => replace_by_rename(&target, meta.ok().as_ref(), content, path, what, true),
    }
}

/// A part file opened to be rewritten (`check --bless`), under an exclusive
/// advisory lock (`File::lock`: flock on unix) held until it is replaced or
/// dropped, so that two blesses of one file take turns: each reads the
/// text the one before it wrote.
#[derive(Debug)]
pub struct Rewrite {
    file: std::fs::File,
    /// Whether `file` was opened to write (this user may write it).
    writable: bool,
    /// The name it is reported under, as given.
    name: String,
    /// The file itself, symlinks resolved: what a rename replaces.
    target: PathBuf,
    meta: std::fs::Metadata,
    /// Its bytes when read, under the lock.
    old: Vec<u8>,
}

impl Rewrite {
    /// Open the regular file `path` to read and write, lock it, and read it
    /// (as `read_source`, under the same limit).
    pub fn open(path: &str) -> Result<(Rewrite, Source), Diagnostic> {
        // NOTE: a bless that waited for the lock may find that the one
        // before it replaced the file (a rename): the lock it holds is then
        // on a file no longer at `path`, so it starts again with the one
        // there now. Bounded, in case something else keeps replacing it.
        for _ in 0..1000 {
            let meta = std::fs::metadata(path).map_err(|e| cannot_read(path, false, e))?;
            check_size(path, &meta)?;
            if !meta.is_file() {
                return Err(Diagnostic::file(
                    path,
                    "not a regular file (a pipe, socket or device): `--bless` rewrites files",
                ));
            }
            let cannot_open = |e: std::io::Error| {
                Diagnostic::file(path, format!("cannot open the file to write it: {e}"))
            };
            // A file this user may not write is opened to read (and lock):
            // it may need no change (`unchanged`); a change is refused.
            let writable = std::fs::OpenOptions::new()
                .read(true)
                .write(true)
                .open(path);
            let (mut file, writable) = match writable {
                Ok(file) => (file, true),
                Err(e)
                    if matches!(
                        e.kind(),
                        std::io::ErrorKind::PermissionDenied
                            | std::io::ErrorKind::ReadOnlyFilesystem
                    ) =>
                {
                    (std::fs::File::open(path).map_err(cannot_open)?, false)
                }
                Err(e) => return Err(cannot_open(e)),
            };
            match file.lock() {
                // A file system without locks (some network or FUSE ones):
                // blessed as before locks, one at a time being the user's
                // care there.
                Err(e) if e.kind() == std::io::ErrorKind::Unsupported => {}
                Err(e) => {
                    return Err(Diagnostic::file(
                        path,
                        format!("cannot lock the file to bless it: {e}"),
                    ));
                }
                Ok(()) => {}
            }
            let meta = file.metadata().map_err(cannot_open)?;
            if FileId::of(Path::new(path)) != FileId::of_meta(&meta, path) {
                continue;
            }
            let old = read_capped(&mut file, path, false, meta.len())?;
            let source = source_of(path, old.clone())?;
            let target = std::fs::canonicalize(path).map_err(cannot_open)?;
            let rewrite = Rewrite {
                file,
                writable,
                name: path.to_string(),
                target,
                meta,
                old,
            };
            return Ok((rewrite, source));
        }
        Err(Diagnostic::file(
            path,
            "the file kept being replaced while waiting to write it: not written",
        ))
    }

    /// Replace the file's text by `text` (`what` names it in errors); the
    /// lock is held until it is done.
    pub fn replace(mut self, text: &str, what: &str) -> Result<(), Diagnostic> {
        // A rename replaces a read-only file as easily as any other (and
        // root writes anything): the mode is the owner's word that it is
        // not to be changed. Asked only of a change: a read-only file that
        // needs none is `unchanged`, as one this user may not write is.
        if self.meta.permissions().readonly() {
            return Err(Diagnostic::file(
                &self.name,
                format!(
                    "the file is read-only: {what} is not written (make it writable to write it)"
                ),
            ));
        }
        // What this user may not write is not replaced either (a rename
        // could: it asks only the directory).
        if !self.writable {
            return Err(Diagnostic::file(
                &self.name,
                format!(
                    "cannot write {what}: this user may not write the file (permission denied)"
                ),
            ));
        }
        let links = links(&self.meta);
        if links > 1 {
            let old = std::mem::take(&mut self.old);
            write_in_place(
                &mut self.file,
                &old,
                text.as_bytes(),
                links,
                &self.name,
                what,
            )
        } else {
            replace_by_rename(
                &self.target,
                Some(&self.meta),
                &|w| w.write_all(text.as_bytes()),
                &self.name,
                what,
                true,
            )
        }
    }
}

/// How many names (hard links) a file has; 1 where that is not known.
fn links(meta: &std::fs::Metadata) -> u64 {
    #[cfg(unix)]
    {
        std::os::unix::fs::MetadataExt::nlink(meta)
    }
    #[cfg(not(unix))]
    {
        let _ = meta;
        1
    }
}

/// Replace `target` by `text` the safe way: a temporary file in the same
/// directory (a rename does not cross file systems), its contents synced to
/// disk, renamed over the target, so that a reader, a crash or a full disk
/// sees the whole old file or the whole new one, never half of either.
///
/// - The temporary file comes from the `tempfile` crate: an unpredictable
///   name (`.NAME.XXXXXX.massprop.tmp`), created exclusively (`O_EXCL`,
///   never through a symlink or onto a file already there), another name
///   tried on a clash; on failure only that file is removed, never a file
///   massprop did not create.
/// - It keeps the replaced file's permissions and its owner and group; when
///   the owner cannot be kept (not running as root or as the owner), the
///   target is not touched and the error says why, rather than a file
///   silently changing hands. A new file gets the permissions any new file
///   gets (0666 less the umask).
/// - The directory is synced after the rename (best effort), so that the
///   rename itself survives a crash.
/// - With `replace` false, the rename happens only if `target` does not
///   exist (`write_new`).
fn replace_by_rename(
    target: &Path,
    meta: Option<&std::fs::Metadata>,
    content: &Content,
    name: &str,
    what: &str,
    replace: bool,
) -> Result<(), Diagnostic> {
    let fail = |e: std::io::Error| Diagnostic::file(name, format!("cannot write {what}: {e}"));
    let dir = target
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let mut prefix = std::ffi::OsString::from(".");
    prefix.push(target.file_name().unwrap_or_default());
    prefix.push(".");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".massprop.tmp");
    #[cfg(unix)]
    if meta.is_none() {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let tmp = builder.tempfile_in(dir).map_err(|e| {
        Diagnostic::file(
            name,
            format!(
                "cannot write {what}: cannot create a file in `{}`: {}",
                dir.display(),
                without_path(&e)
            ),
        )
    })?;
    if let Some(meta) = meta {
        keep_owner(tmp.as_file(), meta, name, what)?;
    }
    let mut w = std::io::BufWriter::new(tmp.as_file());
    content(&mut w).and_then(|()| w.flush()).map_err(fail)?;
    drop(w);
    if let Some(meta) = meta {
        // After the owner: chown clears the set-user-ID and set-group-ID bits.
        tmp.as_file()
            .set_permissions(meta.permissions())
            .map_err(fail)?;
    }
    tmp.as_file().sync_all().map_err(fail)?;
    // On failure the error holds the temporary file, whose drop removes it.
    let persisted = if replace {
        tmp.persist(target)
    } else {
        tmp.persist_noclobber(target)
    };
    persisted.map_err(|e| {
        Diagnostic::file(
            name,
            format!("cannot write {what}: {}", without_path(&e.error)),
        )
    })?;
    #[cfg(unix)]
    {
        // Best effort: some file systems cannot sync a directory.
        let _ = std::fs::File::open(dir).and_then(|d| d.sync_all());
    }
    Ok(())
}

/// An error from `tempfile` without the temporary file's name, which it
/// appends (`… at path "/dir/.x.toml.yYUCHJ.massprop.tmp"`): random, and
/// of no use to the reader.
fn without_path(e: &std::io::Error) -> String {
    let text = e.to_string();
    match text.find(" at path ") {
        Some(at) => text[..at].to_string(),
        None => text,
    }
}

/// Give the new file `tmp` the owner and group of the file `meta` describes,
/// or refuse (nothing replaced yet) when that is not allowed.
fn keep_owner(
    tmp: &std::fs::File,
    meta: &std::fs::Metadata,
    name: &str,
    what: &str,
) -> Result<(), Diagnostic> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let mine = tmp
            .metadata()
            .map_err(|e| Diagnostic::file(name, format!("cannot write {what}: {e}")))?;
        if (mine.uid(), mine.gid()) == (meta.uid(), meta.gid()) {
            return Ok(());
        }
        std::os::unix::fs::fchown(tmp, Some(meta.uid()), Some(meta.gid())).map_err(|e| {
            Diagnostic::file(
                name,
                format!(
                    "cannot keep the file's owner (user {}, group {}): a file massprop writes belongs to user {}, group {}, and giving it away is not allowed ({e}); {what} not written",
                    meta.uid(),
                    meta.gid(),
                    mine.uid(),
                    mine.gid()
                ),
            )
            .help("run massprop as the file's owner (or as root), or copy the file to one of your own")
        })
    }
    #[cfg(not(unix))]
    {
        let _ = (tmp, meta, name, what);
        Ok(())
    }
}

/// Write `new` over the file's own bytes, for a file with hard links (a
/// rename would give this name a new file and cut it from the others). Not
/// atomic: a reader may see it half written, and a crash mid-write may
/// leave it so; a failed write (a full disk) puts `old` back, which fits
/// in the space the file already had.
fn write_in_place(
    file: &mut std::fs::File,
    old: &[u8],
    new: &[u8],
    links: u64,
    name: &str,
    what: &str,
) -> Result<(), Diagnostic> {
    let write = |file: &mut std::fs::File, bytes: &[u8]| -> std::io::Result<()> {
        file.seek(std::io::SeekFrom::Start(0))?;
        file.write_all(bytes)?;
        file.set_len(bytes.len() as u64)?;
        file.sync_all()
    };
    write(file, new).map_err(|e| {
        let back = match write(file, old) {
            Ok(()) => "its previous text was written back".to_string(),
            Err(e) => format!("writing its previous text back failed too ({e}): it may be damaged"),
        };
        Diagnostic::file(
            name,
            format!("cannot write {what} in place (it has {links} hard links): {e}; {back}"),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_file_suggests_the_near_name_of_its_kind_in_its_directory() {
        let dir = tempfile::tempdir().unwrap();
        for n in ["lamp.toml", "lamp.txt", ".lamp.tom"] {
            std::fs::write(dir.path().join(n), "").unwrap();
        }
        let asked = dir.path().join("lamp.tom");
        let near = near_name(&asked, is_toml);
        assert_eq!(near, Some(display_path(&dir.path().join("lamp.toml"))));
        assert_eq!(near_name(&dir.path().join("lamp.toml"), is_toml), None);
        assert_eq!(near_name(&dir.path().join("zebra.toml"), is_toml), None);
    }

    #[test]
    fn a_hard_link_and_a_symlink_name_the_same_file() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.toml");
        std::fs::write(&file, "").unwrap();
        let hard = dir.path().join("hard.toml");
        std::fs::hard_link(&file, &hard).unwrap();
        let id = FileId::of(&file);
        assert!(id.is_some());
        assert_eq!(FileId::of(&hard), id);
        #[cfg(unix)]
        {
            let soft = dir.path().join("soft.toml");
            std::os::unix::fs::symlink(&file, &soft).unwrap();
            assert_eq!(FileId::of(&soft), id);
        }
        let other = dir.path().join("b.toml");
        std::fs::write(&other, "").unwrap();
        assert_ne!(FileId::of(&other), id);
        assert_eq!(FileId::of(&dir.path().join("missing.toml")), None);
    }

    #[test]
    fn a_tempfile_error_loses_the_random_name_and_keeps_the_reason() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("missing");
        let e = tempfile::Builder::new().tempfile_in(&missing).unwrap_err();
        assert!(e.to_string().contains(" at path "), "{e}");
        let text = without_path(&e);
        assert!(!text.contains("at path"), "{text}");
        assert!(text.contains("os error"), "{text}");
    }
}
