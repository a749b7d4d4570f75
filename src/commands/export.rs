//! `massprop export FILE --to urdf|sdf|mjcf`: the body's (or a
//! sub-assembly's) `<inertial>` element for a robot description, printed,
//! or put in place of a link's in an existing file (`--update`), every
//! other byte of that file kept (docs/robots.md).
//!
//! The link frame is the part file's frame, or the reference frame the
//! report uses: its origin at `about` (the reference point), its axes
//! `axes` (`[analysis]`, or `--about` and `--axes`).

use super::Outcome;
use crate::analysis::summary::Summary;
use crate::analysis::{self, Settings};
use crate::diag::{Diagnostic, Source, visible};
use crate::output::inertial::{Export, inertial_element, unified_diff, update};
use crate::robot::{Dialect, Tensor};
use std::path::PathBuf;

#[derive(Debug, Clone)]
pub struct Options {
    /// The part file; `-` is standard input.
    pub file: String,
    /// `--to`; None with `--update`, whose file tells it.
    pub to: Option<Dialect>,
    /// `--principal`: MJCF `diaginertia` and `quat`.
    pub principal: bool,
    /// `--only`, `--about`, `--axes`, precision and includes.
    pub settings: Settings,
    /// `--update FILE --link NAME`.
    pub update: Option<(PathBuf, String)>,
    /// `--dry-run`: the change as a unified diff, nothing written.
    pub dry_run: bool,
    /// `-o FILE`.
    pub output: Option<String>,
    /// `--from-geometry`: FILE is a robot description whose links'
    /// inertials are computed from their geometry.
    pub from_geometry: Option<FromGeometry>,
}

/// `--from-geometry` and the flags that go with it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FromGeometry {
    /// `visual`, else `collision`.
    pub visual: bool,
    /// `--density`, as typed.
    pub density: Option<String>,
    /// `--material`.
    pub material: Option<String>,
    /// `--link`: one link only.
    pub link: Option<String>,
    /// `--update FILE`.
    pub update: Option<PathBuf>,
    pub dry_run: bool,
}

/// The inertial of a summary in its link frame: the centre of mass from
/// the reference point (the file's origin when none is given) in the
/// report axes, and the tensor about the centre of mass in them.
pub fn export_of(s: &Summary, principal: bool) -> Export {
    let pos = if s.reference_given {
        s.center_of_mass_ref
    } else {
        // A c: exact when the axes are the file's (the identity).
        let (a, c) = (&s.axes, &s.center_of_mass);
        std::array::from_fn(|i| a[i][0] * c[0] + a[i][1] * c[1] + a[i][2] * c[2])
    };
    Export {
        mass: s.mass,
        pos,
        tensor: Tensor::of_matrix(&s.inertia_com),
        // Columns the principal axes: the transpose of their rows.
        principal: principal.then(|| {
            let p = &s.principal_axes;
            (
                s.principal_moments,
                std::array::from_fn(|r| std::array::from_fn(|c| p[c][r])),
            )
        }),
    }
}

pub fn run(o: &Options, _terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    if o.principal && o.to.is_some_and(|f| f != Dialect::Mjcf) {
        return Err(Diagnostic::plain(
            "`--principal` is for `--to mjcf` (diaginertia and quat); URDF and SDFormat write the full tensor",
        ));
    }
    let loaded = analysis::load(&o.file, &o.settings)?;
    let mut read = super::files_of(&loaded);
    refuse_unphysical(&loaded)?;
    let stderr = super::accuracy_warnings(&loaded, false);
    let Some((path, link)) = &o.update else {
        let to = o.to.expect("invariant: cli requires --to without --update");
        let e = export_of(&loaded.summary, o.principal);
        let mut text = inertial_element(to, &e, "");
        text.push('\n');
        return Ok(Outcome {
            stderr,
            ..Outcome::ok(text, read)
        });
    };
    let name = path.to_string_lossy().into_owned();
    let (file, source) = if o.dry_run {
        (None, crate::io::read_source_at(path)?)
    } else {
        let (file, source) = crate::io::Rewrite::open(&name)?;
        (Some(file), source)
    };
    read.extend(std::fs::canonicalize(path).ok());
    let format = dialect(o, path, &source)?;
    let e = export_of(&loaded.summary, o.principal);
    let new = update(&source.text, format, link, &e).map_err(|err| match err.at() {
        Some(at) => source.error(at..at + 1, err.to_string()),
        None => Diagnostic::file(&source.name, err.to_string()),
    })?;
    let (stdout, stderr) = written(file, &source, &new, link, o.dry_run, stderr)?;
    Ok(Outcome {
        stderr,
        ..Outcome::ok(stdout, read)
    })
}

/// A body that no engine takes is not written into a robot description.
fn refuse_unphysical(loaded: &crate::analysis::Loaded) -> Result<(), Diagnostic> {
    let failures = crate::analysis::check::validity_failures(&loaded.summary);
    if failures.is_empty() {
        return Ok(());
    }
    Err(Diagnostic::file(
        &loaded.source.name,
        format!(
            "not exported: the body is not physical: {}",
            failures.join("; ")
        ),
    ))
}

/// The dialect of the robot description `--update` names (`source`, read
/// from `path`): by its name, else its root element; it must be `--to`'s,
/// and MJCF under `--principal`.
fn dialect(o: &Options, path: &std::path::Path, source: &Source) -> Result<Dialect, Diagnostic> {
    let format = Dialect::of_path(path)
        .or_else(|| Dialect::of_text(&source.text))
        .ok_or_else(|| {
            Diagnostic::file(
                &source.name,
                "not a robot description: its root element is not <robot> (URDF), <sdf> or <mujoco> (MJCF)",
            )
        })?;
    if let Some(to) = o.to
        && to != format
    {
        return Err(Diagnostic::file(
            &source.name,
            format!(
                "`--to {}` does not match the file, which is {}",
                to.name(),
                format.name()
            ),
        ));
    }
    if o.principal && format != Dialect::Mjcf {
        return Err(Diagnostic::plain(
            "`--principal` is for MJCF files (diaginertia and quat); URDF and SDFormat write the full tensor",
        ));
    }
    Ok(format)
}

/// The updated text `new` of `source`: shown as a unified diff
/// (`--dry-run`, `file` None), or written over `file`, said on standard
/// error (after `stderr`, what was there). Returns standard output and
/// standard error.
pub(super) fn written(
    file: Option<crate::io::Rewrite>,
    source: &Source,
    new: &str,
    link: &str,
    dry_run: bool,
    mut stderr: String,
) -> Result<(String, String), Diagnostic> {
    let name = visible(&source.name);
    if new == source.text {
        stderr.push_str(&format!("{name}: unchanged\n"));
    }
    if dry_run {
        return Ok((unified_diff(&source.text, new, &source.name), stderr));
    }
    if new != source.text {
        let bom = if source.bom { "\u{feff}" } else { "" };
        file.expect("invariant: opened to rewrite unless --dry-run")
            .replace(&format!("{bom}{new}"), "the updated robot description")?;
        stderr.push_str(&format!("{name}: link \"{}\" updated\n", visible(link)));
    }
    Ok((String::new(), stderr))
}
