//! `massprop diff OLD NEW`: two part files compared (docs/diff.md). Exit
//! status 1 when a mass property changed beyond the tolerance (with
//! `--names`, also when parts were added, removed or changed by name).

use super::Outcome;
use crate::analysis::diff::Diff;
use crate::analysis::summary::Accuracy;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::output::{self, Format};

#[derive(Debug, Clone)]
pub struct Options {
    pub old: String,
    pub new: String,
    pub format: Format,
    /// `-o FILE`.
    pub output: Option<String>,
    /// Relative tolerance.
    pub tol: f64,
    /// `--names`: parts added, removed or changed by name fail too.
    pub names: bool,
    /// `--precision` and `--rtol`.
    pub accuracy: Accuracy,
    /// `--axes`, as typed.
    pub axes: Option<String>,
    /// `--include-root` and `--base-dir`.
    pub includes: crate::model::Includes,
    /// `--about`, as typed (the link frame's origin, against a robot
    /// description).
    pub about: Option<String>,
    /// `--link`: the link compared when a side is a robot description.
    pub link: Option<String>,
    /// `--joints`, applied to each side that is a robot description (as a
    /// whole body, without `--link`).
    pub configuration: super::robot::Configuration,
}

/// `terminal.stdout` is the output's style (`-o`'s file's when it has one).
pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    refuse_flags(o)?;
    let settings = settings(o);
    // A robot description on either side: a part file against a link.
    let (old_robot, new_robot) = (robot_source(&o.old)?, robot_source(&o.new)?);
    if let Some(s) = o.configuration.sweep.first() {
        return Err(Diagnostic::plain(format!(
            "`--sweep {s}`: `diff` compares two bodies at one configuration each; `--joints` sets it"
        )));
    }
    if (old_robot.is_some() || new_robot.is_some()) && o.link.is_some() {
        if o.configuration.joints.is_some() {
            return Err(Diagnostic::plain(
                "`--joints` poses a robot as a whole body, and `--link` compares one link's inertial, which no joint moves: give one of them",
            ));
        }
        return against_link(o, &settings, old_robot, new_robot, terminal);
    }
    if old_robot.is_none() && new_robot.is_none() {
        refuse_link_flags(o)?;
        o.configuration.refuse_for_part_file(&o.old)?;
    } else if o.about.is_some() {
        return Err(Diagnostic::plain(
            "`--about` sets the link frame with `--link`: a robot as a whole body is compared in its root frame",
        ));
    }
    // A robot description on a side without `--link`: the whole robot,
    // at `--joints`.
    let side = |path: &str, robot: Option<Robot>| match robot {
        Some((source, format)) => {
            super::robot::Loading::new(source, format, &o.configuration, &settings.includes)?
                .load(&settings, &[])
        }
        None => analysis::load(path, &settings),
    };
    let old = side(&o.old, old_robot)?;
    let new = side(&o.new, new_robot)?;
    let read = [&old, &new].into_iter().flat_map(super::files_of).collect();
    let colour = terminal.stderr.colour;
    let stderr = super::accuracy_warnings(&old, colour) + &super::accuracy_warnings(&new, colour);
    let diff = Diff::of(old, new, o.tol, o.names)?;
    Ok(Outcome {
        stdout: super::Stdout::Text(output::render(
            &output::Output::Diff(&diff),
            o.format,
            terminal.stdout,
        )),
        stderr,
        status: u8::from(diff.changed),
        read,
    })
}

/// `--tol` out of range, or standard input named twice.
fn refuse_flags(o: &Options) -> Result<(), Diagnostic> {
    let tol = o.tol;
    if !(tol >= 0.0 && tol.is_finite()) {
        return Err(Diagnostic::plain(format!(
            "invalid value {tol} for `--tol`: expected a finite relative tolerance ≥ 0, such as 1e-6"
        )));
    }
    if o.old == "-" && o.new == "-" {
        return Err(Diagnostic::plain(
            "OLD and NEW cannot both be `-`: standard input can be read only once",
        ));
    }
    Ok(())
}

/// `--link` and `--about`, which are for a robot description, given for
/// two part files.
fn refuse_link_flags(o: &Options) -> Result<(), Diagnostic> {
    if o.link.is_some() {
        return Err(Diagnostic::plain(
            "`--link` names a link of a robot description (URDF, SDFormat, MJCF), and neither OLD nor NEW is one",
        ));
    }
    if o.about.is_some() {
        return Err(Diagnostic::plain(
            "`--about` sets the link frame against a robot description, and neither OLD nor NEW is one: two part files are compared in their own frames",
        ));
    }
    Ok(())
}

/// What the pipeline is asked for each side. Tensor convention: the JSON
/// contract of diff is fixed to it.
fn settings(o: &Options) -> Settings {
    Settings {
        accuracy: o.accuracy,
        includes: o.includes.clone(),
        overrides: crate::analysis::Overrides {
            axes: o.axes.clone(),
            about: o.about.clone(),
            ..Default::default()
        },
        ..Settings::default()
    }
}

/// The robot description a path names, read, with its format: by its name
/// (`*.urdf`, `*.sdf`), else an `*.xml` by its root element. None for a
/// part file (and for standard input, which is read as one).
fn robot_source(path: &str) -> Result<Option<Robot>, Diagnostic> {
    use crate::robot::Dialect;
    let p = std::path::Path::new(path);
    if path == "-" || crate::io::is_toml(p) || !crate::robot::may_be_robot(p) {
        return Ok(None);
    }
    let source = crate::io::read_source(path)?;
    match Dialect::of_path(p).or_else(|| Dialect::of_text(&source.text)) {
        Some(f) => Ok(Some((source, f))),
        None => Err(Diagnostic::file(
            path,
            "not a robot description: its root element is not <robot> (URDF), <sdf> or <mujoco> (MJCF)",
        )),
    }
}

/// A robot description read, with its dialect.
type Robot = (crate::diag::Source, crate::robot::Dialect);

/// `diff PART ROBOT --link NAME` (either way round): the part file's body
/// in its link frame against the link's inertial.
fn against_link(
    o: &Options,
    settings: &Settings,
    old_robot: Option<Robot>,
    new_robot: Option<Robot>,
    terminal: &super::Terminal,
) -> Result<Outcome, Diagnostic> {
    use crate::analysis::diff::{LinkDiff, Props};
    let ((source, format), part, robot_is_old) = sides(o, old_robot, new_robot)?;
    let Some(name) = &o.link else {
        return Err(Diagnostic::plain(format!(
            "`{}` is a robot description: name the link to compare with `--link NAME`",
            source.name
        )));
    };
    let link_props = crate::analysis::link::props(&source, format, name)?;
    let loaded = analysis::load(part, settings)?;
    let e = super::export::export_of(&loaded.summary, false);
    let part_props = Props {
        center_of_mass: e.pos,
        // The link's axes are not compared: its inertial gives a tensor.
        principal_axes: None,
        ..Props::of(&loaded.summary)
    };
    let mut read = super::files_of(&loaded);
    read.extend(std::fs::canonicalize(source.path()).ok());
    let stderr = super::accuracy_warnings(&loaded, terminal.stderr.colour);
    let part_side = (loaded.source.name.clone(), part_props);
    let link_side = (source.name.clone(), link_props);
    let (old, new) = if robot_is_old {
        (link_side, part_side)
    } else {
        (part_side, link_side)
    };
    let diff = LinkDiff::of(old, new, name.clone(), loaded.summary.file_units, o.tol)?;
    Ok(Outcome {
        stdout: super::Stdout::Text(output::render(
            &output::Output::LinkDiff(&diff),
            o.format,
            terminal.stdout,
        )),
        stderr,
        status: u8::from(diff.changed),
        read,
    })
}

/// The robot description, the part file's path, and whether the robot
/// is OLD: an error when both are robot descriptions.
fn sides(
    o: &Options,
    old_robot: Option<Robot>,
    new_robot: Option<Robot>,
) -> Result<(Robot, &str, bool), Diagnostic> {
    match (old_robot, new_robot) {
        (Some(r), None) => Ok((r, &o.new, true)),
        (None, Some(r)) => Ok((r, &o.old, false)),
        _ => Err(Diagnostic::plain(format!(
            "`{}` and `{}` are both robot descriptions: `diff` compares a part file with a link (check each with `massprop check`)",
            o.old, o.new
        ))),
    }
}
