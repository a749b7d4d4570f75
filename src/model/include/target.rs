//! Where an include (or a mesh file) may point: resolved against the
//! including file (or `--base-dir`), confined to the allowed directory
//! trees (the top-level file's, the working directory, `--include-root`),
//! a regular file within the size limit, of its kind's extension. The one
//! place these rules live (`Ctx::target_of`).

use super::Files;
use crate::diag::Diagnostic;
use crate::model::Ctx;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// Where an include points, checked.
pub(in crate::model) struct Target {
    /// Canonical: symlinks followed.
    pub(in crate::model) canonical: PathBuf,
    /// As the including file names it, relative to the working directory.
    pub(in crate::model) shown: PathBuf,
    pub(in crate::model) shown_name: String,
}

/// What a path a part names is: a part file to include, or a mesh file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(in crate::model) enum Kind {
    Include,
    Mesh,
}

impl Kind {
    /// "the included `x`" or "the mesh file `x`".
    fn the(self, shown: &str) -> String {
        match self {
            Kind::Include => format!("the included `{shown}`"),
            Kind::Mesh => format!("the mesh file `{shown}`"),
        }
    }

    fn plural(self) -> &'static str {
        match self {
            Kind::Include => "includes",
            Kind::Mesh => "mesh files",
        }
    }

    fn key(self) -> &'static str {
        match self {
            Kind::Include => "include",
            Kind::Mesh => "file",
        }
    }
}

impl Ctx<'_> {
    /// Resolve `include = ".."` (see `target_of`).
    pub(in crate::model) fn target(
        &self,
        inc: &Spanned<String>,
        files: &Files,
    ) -> Result<Target, Diagnostic> {
        self.target_of(inc, files, Kind::Include)
    }

    /// Resolve a path a part names (`include = ".."`, a mesh's `file`)
    /// and apply every rule on where it may point before anything of it is
    /// read: relative to the part file (or `--base-dir` for a piped one),
    /// inside the allowed directory trees, a regular file, within the size
    /// limit, of the kind's extension. The one place these rules live:
    /// counting and expanding includes, and reading meshes, all come
    /// through here.
    pub(in crate::model) fn target_of(
        &self,
        inc: &Spanned<String>,
        files: &Files,
        kind: Kind,
    ) -> Result<Target, Diagnostic> {
        let key = kind.key();
        let base = match (self.source.piped, &files.base_dir) {
            (false, _) => self.source.path().parent().unwrap_or(Path::new("")),
            (true, Some(dir)) => dir.as_path(),
            (true, None) => {
                // Relative to what? Not silently the working directory: a
                // file piped in (`git show OLD:arm.toml | massprop diff -
                // arm.toml`) would include today's sub-assemblies unasked.
                let what = if self.source.name == "<stdin>" {
                    "standard input"
                } else {
                    "a pipe"
                };
                return Err(self
                    .err(inc.span(), format!("`{key}` in a file read from {what}: its path has nothing to be relative to"))
                    .help(format!("give `--base-dir DIR`, the directory its {} are relative to, or the file by its path", kind.plural())));
            }
        };
        let shown = base.join(inc.get_ref());
        let shown_name = crate::diag::display_path(&shown);
        let the = kind.the(&shown_name);
        let unreadable = |e: std::io::Error| {
            let what = match kind {
                Kind::Include => "the included file",
                Kind::Mesh => "the mesh file",
            };
            self.err(
                inc.span(),
                format!("cannot read {what} `{shown_name}`: {e}"),
            )
            .help(match kind {
                Kind::Include => "the path is relative to the including file",
                Kind::Mesh => "the path is relative to the part file",
            })
        };
        let canonical = std::fs::canonicalize(&shown).map_err(|e| {
            let d = unreadable(e);
            match near_include(&shown, inc.get_ref(), &files.roots, kind) {
                Some(near) => {
                    let why = d.help_text().unwrap_or_default().to_string();
                    d.help(format!("did you mean `{near}`? ({why})"))
                }
                None => d,
            }
        })?;
        // Confined: a part file from a pull request must not read, and
        // quote in an error, any file it names (`/proc/self/environ`).
        if !files.roots.iter().any(|r| canonical.starts_with(r)) {
            return Err(self
                .err(
                    inc.span(),
                    format!(
                        "{the} is outside the directory of the part file and the working directory"
                    ),
                )
                .help(format!("{} stay inside those directory trees (after following symlinks); `--include-root DIR` allows another", kind.plural())));
        }
        let meta = std::fs::metadata(&canonical).map_err(unreadable)?;
        if meta.len() > crate::io::MAX_FILE_BYTES {
            return Err(self.err(
                inc.span(),
                format!(
                    "{the} is larger than the limit of {} MiB",
                    crate::io::MAX_FILE_BYTES >> 20
                ),
            ));
        }
        if !meta.is_file() {
            return Err(self
                .err(inc.span(), format!("{the} is not a regular file"))
                .help(match kind {
                    Kind::Include => "`include` names a part file",
                    Kind::Mesh => "`file` names a mesh file",
                }));
        }
        match kind {
            // Only part files: `.env` or `.git/config` (where a CI checkout
            // keeps its token) would be parsed as TOML and quoted in the error.
            Kind::Include
                if !crate::io::is_toml(&canonical) && !crate::robot::may_be_robot(&canonical) =>
            {
                return Err(self
                    .err(inc.span(), format!("{the} is not a part file (`*.toml`) or a robot description (`*.urdf`, `*.sdf`, `*.xml`)"))
                    .help("`include` names a part file or a robot description, after following symlinks"));
            }
            // Only mesh files, by their extension (after following
            // symlinks): nothing else is read and quoted as a mesh.
            Kind::Mesh if crate::mesh::FileType::of(&canonical).is_none() => {
                return Err(self
                    .err(
                        inc.span(),
                        format!("{the} is not a mesh file (`*.stl` or `*.obj`)"),
                    )
                    .help("`file` names an STL or Wavefront OBJ file, after following symlinks"));
            }
            _ => {}
        }
        Ok(Target {
            canonical,
            shown,
            shown_name,
        })
    }
}

/// For an include or a mesh that does not exist: the path as the file
/// writes it, its file name replaced by the nearest name of its kind in
/// its directory (`io::near_name`: `arm.tom` → `arm.toml`), when that
/// directory lies inside the roots includes may read: no name outside
/// them is listed.
fn near_include(shown: &Path, written: &str, roots: &[PathBuf], kind: Kind) -> Option<String> {
    let dir = shown
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let dir = std::fs::canonicalize(dir).ok()?;
    if !roots.iter().any(|r| dir.starts_with(r)) {
        return None;
    }
    let near = crate::io::near_name(shown, |p| match kind {
        Kind::Include => crate::io::is_toml(p),
        Kind::Mesh => crate::mesh::FileType::of(p).is_some(),
    })?;
    let name = Path::new(&near).file_name()?;
    Some(crate::diag::display_path(
        &Path::new(written).with_file_name(name),
    ))
}
