//! `massprop report FILE`: the mass properties of one part file.

use super::Outcome;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::output::Format;

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// The part file; `-` is standard input.
    pub file: String,
    pub format: Format,
    /// `-o FILE`.
    pub output: Option<String>,
    /// Products convention, precision, `--only` and the `[analysis]`
    /// overrides.
    pub settings: Settings,
    /// Every table (`--full`), not the short report's essentials.
    pub full: bool,
    /// A robot description's `--joints` and `--sweep`.
    pub configuration: super::robot::Configuration,
    /// `--case NAME`, `--cases` (`[[case]]`).
    pub cases: Cases,
}

/// Which of a file's states a report shows (`analysis::cases`).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub enum Cases {
    /// The file as written.
    #[default]
    Base,
    /// `--case NAME`: that case, as a plain report.
    One(String),
    /// `--cases`: the base and a row (an object) per case.
    All,
}

/// `terminal.stdout` is the output's style (`-o`'s file's when it has one).
pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    let loaded = match super::robot::source(&o.file)? {
        super::robot::Input::Robot(source, format) => {
            refuse_cases_for_robot(&o.cases)?;
            let loading =
                super::robot::Loading::new(source, format, &o.configuration, &o.settings.includes)?;
            if !o.configuration.sweep.is_empty() {
                return sweep(o, &loading, terminal);
            }
            loading.load(&o.settings, &[])?
        }
        super::robot::Input::Part(source) => {
            o.configuration.refuse_for_part_file(&o.file)?;
            let source = match source {
                Some(s) => s,
                None => crate::io::read_source(&o.file)?,
            };
            match &o.cases {
                Cases::Base => analysis::load_source(source, &o.settings)?,
                Cases::One(name) => analysis::cases::load_case(source, &o.settings, name)?,
                Cases::All => return all_cases(o, source, terminal),
            }
        }
    };
    let read = super::files_of(&loaded);
    let stderr = super::accuracy_warnings(&loaded, terminal.stderr.colour);
    Ok(Outcome {
        stdout: super::Stdout::Report {
            summary: Box::new(loaded.summary),
            source: loaded.source.name,
            format: o.format,
            detail: crate::output::report::Detail {
                full: o.full,
                // A reference point the command line gives was asked for:
                // its tensors are shown (one in the file is for H, T, M).
                about_flag: o.settings.overrides.about.is_some(),
            },
            style: terminal.stdout,
        },
        stderr,
        status: 0,
        read,
    })
}

/// `report ROBOT --sweep …`: the body at every sample of the grid.
fn sweep(
    o: &Options,
    loading: &super::robot::Loading,
    terminal: &super::Terminal,
) -> Result<Outcome, Diagnostic> {
    let mut samples = Vec::new();
    let mut stderr = String::new();
    for sample in loading.samples(&o.configuration.sweep)? {
        let loaded = loading.load(&o.settings, &sample)?;
        if stderr.is_empty() {
            stderr = super::accuracy_warnings(&loaded, terminal.stderr.colour);
        }
        let s = &loaded.summary;
        let joints = sample
            .iter()
            .map(|&(j, x)| {
                (
                    loading.robot.tree.joints[j].name.clone(),
                    serde_json::Value::from(x),
                )
            })
            .collect();
        samples.push(super::robot::Sample {
            joints,
            mass: s.mass,
            center_of_mass: s.center_of_mass,
            inertia_com: s.inertia_com,
            principal_moments: s.principal_moments,
            report: crate::output::report::json(s),
        });
    }
    let read = std::fs::canonicalize(loading.source.path())
        .ok()
        .into_iter()
        .collect();
    Ok(Outcome {
        stdout: super::Stdout::Text(super::robot::render_samples(
            &loading.source.name,
            &samples,
            o.format,
        )),
        stderr,
        status: 0,
        read,
    })
}

/// `--case` and `--cases` take a part file's `[[case]]`s.
fn refuse_cases_for_robot(cases: &Cases) -> Result<(), Diagnostic> {
    let flag = match cases {
        Cases::Base => return Ok(()),
        Cases::One(_) => "--case",
        Cases::All => "--cases",
    };
    Err(Diagnostic::plain(format!(
        "`{flag}` takes a part file's `[[case]]`s; a robot description has none"
    )))
}

/// `report --cases`: the base and every case, a row (a JSON object) each.
fn all_cases(
    o: &Options,
    source: crate::diag::Source,
    terminal: &super::Terminal,
) -> Result<Outcome, Diagnostic> {
    let (base, cases) = analysis::cases::load_all(source, &o.settings)?;
    if cases.is_empty() {
        return Err(Diagnostic::plain(format!(
            "`--cases`: {} has no `[[case]]`",
            base.source.name
        ))
        .help("add a `[[case]]` table with a `name` for each state of the body"));
    }
    let read = super::files_of(&base);
    let stderr = super::accuracy_warnings(&base, terminal.stderr.colour);
    let summaries: Vec<(&str, &analysis::summary::Summary)> = (cases.iter())
        .map(|(name, l)| (name.as_str(), &l.summary))
        .collect();
    let text = crate::output::report::cases::render(
        &base.summary,
        &summaries,
        o.format,
        o.full,
        terminal.stdout.width,
    );
    Ok(Outcome {
        stdout: super::Stdout::Text(text),
        stderr,
        status: 0,
        read,
    })
}
