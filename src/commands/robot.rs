//! A robot description where a command takes a part file (`report`,
//! `diff`): which files are robots (the rule `check` uses), the whole
//! robot loaded at a configuration (`--joints`), and `--sweep`'s samples.

use crate::analysis::{self, Loaded, Settings, plausible};
use crate::diag::{Diagnostic, Source};
use crate::robot::Dialect;
use crate::robot::body::Robot;
use std::fmt::Write as _;

/// `--joints` and `--sweep`, as typed.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Configuration {
    /// `--joints "shoulder=30deg, elbow=-0.5"`.
    pub joints: Option<String>,
    /// `--sweep "elbow=-90deg..90deg:19"`, one joint each.
    pub sweep: Vec<String>,
}

impl Configuration {
    /// Whether either flag was given.
    pub fn given(&self) -> bool {
        self.joints.is_some() || !self.sweep.is_empty()
    }

    /// Refused for a part file.
    pub fn refuse_for_part_file(&self, file: &str) -> Result<(), Diagnostic> {
        let flag = if self.joints.is_some() {
            "--joints"
        } else if !self.sweep.is_empty() {
            "--sweep"
        } else {
            return Ok(());
        };
        Err(Diagnostic::plain(format!(
            "`{flag}` sets a robot description's joints, and `{}` is a part file",
            crate::diag::shorten(file)
        ))
        .help("a robot description is a `*.urdf`, `*.sdf`, or an `*.xml` whose root is `<robot>`, `<sdf>` or `<mujoco>`"))
    }
}

/// The file `path` names, read: a robot description with its format by
/// the rule `check` applies to a file not named `*.toml` (its name, else
/// its root element), or a part file. Standard input is a part file.
pub fn source(path: &str) -> Result<Input, Diagnostic> {
    let p = std::path::Path::new(path);
    if path == "-" || crate::io::is_toml(p) {
        return Ok(Input::Part(None));
    }
    let source = crate::io::read_source(path)?;
    match Dialect::of_path(p).or_else(|| Dialect::of_text(&source.text)) {
        Some(f) => Ok(Input::Robot(source, f)),
        None => Ok(Input::Part(Some(source))),
    }
}

/// The body `file` names, a part file or a robot description at
/// `c`'s joints (`--sweep` is the caller's to refuse or run).
pub fn load_any(file: &str, settings: &Settings, c: &Configuration) -> Result<Loaded, Diagnostic> {
    match source(file)? {
        Input::Robot(source, format) => {
            Loading::new(source, format, c, &settings.includes)?.load(settings, &[])
        }
        Input::Part(source) => {
            c.refuse_for_part_file(file)?;
            match source {
                Some(s) => analysis::load_source(s, settings),
                None => analysis::load(file, settings),
            }
        }
    }
}

/// What a command's file is.
pub enum Input {
    /// A part file, read already unless standard input or `*.toml`.
    Part(Option<Source>),
    Robot(Source, Dialect),
}

/// A robot description read whole, with the joints `--joints` sets.
pub struct Loading {
    pub source: Source,
    pub robot: Robot,
    pub set: Vec<(usize, f64)>,
}

impl Loading {
    /// Its includes found through `includes` (`--package`,
    /// `--include-root`).
    pub fn new(
        source: Source,
        format: Dialect,
        c: &Configuration,
        includes: &crate::model::Includes,
    ) -> Result<Loading, Diagnostic> {
        let robot = Robot::read_in(&source, format, &includes.resolve())?;
        let set = match &c.joints {
            Some(t) => robot.joints(t, "--joints")?,
            None => Vec::new(),
        };
        Ok(Loading { source, robot, set })
    }

    /// The body with the joints `set` (then `extra`), through the pipeline.
    pub fn load(&self, settings: &Settings, extra: &[(usize, f64)]) -> Result<Loaded, Diagnostic> {
        let robot = &self.robot;
        let mut set = self.set.clone();
        for &(j, x) in extra {
            set.retain(|(k, _)| *k != j);
            set.push((j, x));
        }
        let values = robot.values(&set);
        let model = crate::model::Model::of_robot_at(robot, &values);
        let mut loaded = analysis::load_model(self.source.clone(), model, settings)?;
        loaded.summary.warnings = robot
            .notes(&values)
            .into_iter()
            .map(|n| {
                let range = crate::robot::read::start_tag(&self.source.text, n.range);
                plausible::Warning {
                    kind: plausible::Kind::Robot,
                    path: self.source.name.clone(),
                    span: self.source.span(range),
                    message: n.message,
                }
            })
            .chain(robot.mesh_warnings.iter().map(super::mesh_warning))
            .collect();
        Ok(loaded)
    }

    /// `--sweep`'s samples: per sample, the joints swept with their values
    /// (SI), in the order of the flags (the first outermost).
    pub fn samples(&self, sweeps: &[String]) -> Result<Vec<Vec<(usize, f64)>>, Diagnostic> {
        let mut axes: Vec<(usize, Vec<f64>)> = Vec::new();
        for s in sweeps {
            let (j, values) = self.sweep(s)?;
            if axes.iter().any(|(k, _)| *k == j) || self.set.iter().any(|(k, _)| *k == j) {
                return Err(Diagnostic::plain(format!(
                    "`--sweep {s}`: joint `{}` is set twice (by `--joints` or another `--sweep`)",
                    crate::diag::shorten(&self.robot.tree.joints[j].name)
                )));
            }
            axes.push((j, values));
        }
        let total = axes
            .iter()
            .try_fold(1usize, |n, (_, v)| n.checked_mul(v.len()))
            .filter(|n| *n <= MAX_SAMPLES)
            .ok_or_else(|| {
                Diagnostic::plain(format!(
                    "`--sweep`: the grid has more than {MAX_SAMPLES} samples"
                ))
            })?;
        let mut out = Vec::with_capacity(total);
        for k in 0..total {
            let mut rest = k;
            let mut sample = vec![(0, 0.0); axes.len()];
            for (a, (j, v)) in axes.iter().enumerate().rev() {
                sample[a] = (*j, v[rest % v.len()]);
                rest /= v.len();
            }
            out.push(sample);
        }
        Ok(out)
    }

    /// One `--sweep`: `JOINT=FROM..TO:COUNT`.
    fn sweep(&self, text: &str) -> Result<(usize, Vec<f64>), Diagnostic> {
        let bad = || {
            Diagnostic::plain(format!(
                "invalid value {text:?} for `--sweep`: expected `JOINT=FROM..TO:COUNT`, such as `elbow=-90deg..90deg:19`"
            ))
        };
        let (name, range) = text.split_once('=').ok_or_else(bad)?;
        let (span, count) = range.rsplit_once(':').ok_or_else(bad)?;
        let (from, to) = span.split_once("..").ok_or_else(bad)?;
        let j = self.robot.joint(name.trim(), "--sweep")?;
        let from = self.robot.value(j, from.trim(), "--sweep")?;
        let to = self.robot.value(j, to.trim(), "--sweep")?;
        let n: usize = count.trim().parse().map_err(|_| {
            Diagnostic::plain(format!(
                "invalid count {:?} in `--sweep {text}`: expected a whole number of samples ≥ 1",
                count.trim()
            ))
        })?;
        if n == 0 {
            return Err(Diagnostic::plain(format!(
                "invalid count 0 in `--sweep {text}`: expected a whole number of samples ≥ 1"
            )));
        }
        let values = (0..n)
            .map(|i| {
                if n == 1 {
                    from
                } else if i == n - 1 {
                    to
                } else {
                    from + (to - from) * (i as f64) / ((n - 1) as f64)
                }
            })
            .collect();
        Ok((j, values))
    }
}

/// The most samples a sweep's grid may have.
pub const MAX_SAMPLES: usize = 100_000;

/// One sample of a sweep: its joints and the body's summary.
pub struct Sample {
    /// Joint name → value, SI.
    pub joints: serde_json::Map<String, serde_json::Value>,
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    pub inertia_com: [[f64; 3]; 3],
    pub principal_moments: [f64; 3],
    /// The plain report's JSON object of the body at this sample
    /// (`output::report::json`), every key of it.
    pub report: String,
}

/// The samples' document: JSON, or a table.
pub fn render_samples(name: &str, samples: &[Sample], format: crate::output::Format) -> String {
    use crate::output::Format;
    match format {
        Format::Json => {
            // NOTE: each sample is `{"joints": …,` and then the plain
            // report's own JSON object (its writer, so every key and every
            // number exactly as `report --format json` writes them), one
            // line per sample.
            let mut s = format!(
                "{{\n  \"source\": {},\n  \"units\": {{\"mass\": \"kg\", \"length\": \"m\", \"inertia\": \"kg*m^2\", \"angle\": \"rad\"}},\n  \"samples\": [",
                crate::output::json_line(name).trim_end()
            );
            for (k, sample) in samples.iter().enumerate() {
                let report = sample.report.trim_end();
                let rest = report.strip_prefix('{').unwrap_or(report);
                let _ = write!(
                    s,
                    "{}\n    {{\"joints\":{}{}{rest}",
                    if k == 0 { "" } else { "," },
                    crate::output::json_line(&sample.joints).trim_end(),
                    if rest == "}" { "" } else { "," }
                );
            }
            s.push_str("\n  ]\n}\n");
            s
        }
        Format::Table | Format::Github | Format::Junit | Format::Sarif => {
            use crate::output::format::fmt_num;
            let mut t = crate::output::grid::new_table();
            let mut header: Vec<String> = samples
                .first()
                .map(|s| s.joints.keys().cloned().collect())
                .unwrap_or_default();
            header.extend(
                [
                    "mass (kg)",
                    "x (m)",
                    "y (m)",
                    "z (m)",
                    "Ixx (kg·m²)",
                    "Iyy",
                    "Izz",
                    "Ixy",
                    "Ixz",
                    "Iyz",
                ]
                .map(String::from),
            );
            t.set_header(header);
            for s in samples {
                let mut row: Vec<String> = s
                    .joints
                    .values()
                    .map(|v| fmt_num(v.as_f64().unwrap_or(f64::NAN)))
                    .collect();
                row.push(fmt_num(s.mass));
                row.extend(s.center_of_mass.map(fmt_num));
                let i = s.inertia_com;
                row.extend([i[0][0], i[1][1], i[2][2], i[0][1], i[0][2], i[1][2]].map(fmt_num));
                t.add_row(row);
            }
            format!(
                "{} at {} configurations: mass, centre of mass and inertia about it (joints: rad or m)\n{t}\n",
                crate::output::format::line_name(name),
                samples.len()
            )
        }
    }
}
