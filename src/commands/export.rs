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
    // The link may be written in a file the robot includes.
    let r = crate::robot::read::Resolve {
        packages: Vec::new(),
        roots: o.settings.includes.roots.clone(),
    };
    let links = [(link.clone(), e)];
    let (stdout, stderr, files) =
        update_robot(file, &source, format, &links, &r, o.dry_run, stderr)?;
    read.extend(files);
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

/// `--update ROBOT` of several links (`links`: name and inertial), each
/// written in the file where it is written (issue 34, item 3): the robot
/// file `target` (opened as `file`, None under `--dry-run`), or a file it
/// includes, found by the reader (`robot::Site`), includes resolved by
/// `r`. Returns standard output (`--dry-run`: one diff per file changed,
/// each with its path), standard error, and the files read.
///
/// A file the robot includes is written only inside the robot file's
/// directory or an `--include-root` (`r.roots`): a `--package` or
/// `model://` directory elsewhere is another project's, refused with the
/// link's place. One element that several links share (a file included
/// twice) takes one inertial: different ones are refused.
pub(super) fn update_robot(
    file: Option<crate::io::Rewrite>,
    target: &Source,
    format: Dialect,
    links: &[(String, Export)],
    r: &crate::robot::read::Resolve,
    dry_run: bool,
    mut stderr: String,
) -> Result<(String, String, Vec<PathBuf>), Diagnostic> {
    let error = |err: crate::output::inertial::UpdateError, source: &Source| match err.at() {
        Some(at) => source.error(at..at + 1, err.to_string()),
        None => Diagnostic::file(&source.name, err.to_string()),
    };
    let d = match crate::robot::read::read_in(target, format, r) {
        Ok(d) if !d.files.sources.is_empty() => d,
        // NOTE: a file that includes none is written as before, by name
        // (a file the reader refuses too: the updater says its own word).
        Err(e) if target.text.contains("<include") => return Err(e),
        _ => {
            let mut new = target.text.clone();
            for (link, e) in links {
                new = update(&new, format, link, e).map_err(|err| error(err, target))?;
            }
            let names: Vec<&str> = links.iter().map(|(n, _)| n.as_str()).collect();
            let (out, err) = written(file, target, &new, &names.join("\", \""), dry_run, stderr)?;
            return Ok((out, err, Vec::new()));
        }
    };
    // Per file, its links' elements: (start, name, inertial).
    let mut per: std::collections::BTreeMap<usize, Vec<(usize, &str, &Export)>> =
        std::collections::BTreeMap::new();
    for (name, e) in links {
        let Some(l) = d.links.iter().find(|l| l.name == *name) else {
            let near = crate::units::suggest(name, d.links.iter().map(|l| l.name.as_str()))
                .map(|s| format!("; did you mean \"{}\"?", visible(s)))
                .unwrap_or_default();
            return Err(Diagnostic::file(
                &target.name,
                format!(
                    "no link named \"{}\" in the robot (its files included){near}",
                    visible(name)
                ),
            ));
        };
        if l.site.elsewhere {
            // NOTE: an MJCF `<include>` inside the body brings its
            // `<inertial>` from another file; writing one into the body
            // would give it two (MuJoCo's error).
            let source = d.files.source(target, l.site.file);
            let tag = crate::robot::read::start_tag(&source.text, l.site.element.clone());
            return Err(d.files.located(source.error(
                tag,
                format!(
                    "`--update` does not write body \"{}\": its `<inertial>` is brought in by an `<include>` inside it, from another file",
                    visible(name)
                ),
            ))
            .help("write the inertial in the body itself, or update the included file's `<inertial>` by hand"));
        }
        per.entry(l.site.file)
            .or_default()
            .push((l.site.element.start, name, e));
    }
    let top = crate::robot::read::canonical_dir(target);
    let roots: Vec<PathBuf> = std::iter::once(top)
        .chain(r.roots.iter().filter_map(|p| std::fs::canonicalize(p).ok()))
        .collect();
    let mut changed = Vec::new();
    for (&k, entries) in &mut per {
        let source = d.files.source(target, k);
        // The link's start tag (a `>` inside an attribute's quotes is not
        // its end: `start_tag`).
        let at = |start: usize, message: String| {
            let tag = crate::robot::read::start_tag(&source.text, start..source.text.len());
            d.files.located(source.error(tag, message))
        };
        entries.sort_by_key(|&(start, _, _)| std::cmp::Reverse(start));
        for w in entries.windows(2) {
            if w[0].0 == w[1].0 && w[0].2 != w[1].2 {
                return Err(at(
                    w[0].0,
                    format!(
                        "links \"{}\" and \"{}\" are one element of `{}` (a file included twice): it cannot hold two different inertials",
                        visible(w[1].1),
                        visible(w[0].1),
                        visible(&source.name)
                    ),
                )
                .help("update one of them (`--link NAME`), or give each copy a file of its own"));
            }
        }
        entries.dedup_by_key(|&mut (start, _, _)| start);
        if k > 0 {
            let canonical = std::fs::canonicalize(source.path()).unwrap_or_default();
            if !roots.iter().any(|root| canonical.starts_with(root)) {
                let (start, name, _) = entries[0];
                return Err(at(
                    start,
                    format!(
                        "`--update` does not write link \"{}\" into `{}`: the included file lies outside the robot file's directory and the `--include-root`s",
                        visible(name),
                        visible(&source.name)
                    ),
                )
                .help("a `--package` or `model://` directory is written only when an `--include-root` names it (or one above it)"));
            }
        }
        let mut new = source.text.clone();
        for &(start, name, e) in entries.iter() {
            new = crate::output::inertial::update_at(&new, format, start, name, e)
                .map_err(|err| error(err, source))?;
        }
        let names: Vec<&str> = entries.iter().rev().map(|&(_, n, _)| n).collect();
        changed.push((k, new, names.join("\", \"")));
    }
    let mut file = file;
    let mut stdout = String::new();
    let mut read = Vec::new();
    for (k, new, names) in changed {
        let source = d.files.source(target, k);
        let (rewrite, source) = match (k, dry_run) {
            (0, _) => (file.take(), source.clone()),
            (_, true) => (None, source.clone()),
            (_, false) => {
                let (rewrite, fresh) = crate::io::Rewrite::open(&source.path().to_string_lossy())?;
                if fresh.text != source.text {
                    return Err(Diagnostic::file(
                        &source.name,
                        "the file changed while it was read: not written",
                    ));
                }
                (
                    Some(rewrite),
                    Source {
                        name: source.name.clone(),
                        ..fresh
                    },
                )
            }
        };
        read.extend(std::fs::canonicalize(source.path()).ok());
        let (out, err) = written(rewrite, &source, &new, &names, dry_run, stderr)?;
        stdout.push_str(&out);
        stderr = err;
    }
    Ok((stdout, stderr, read))
}
