//! massprop: mass properties of composite rigid bodies from TOML part files.
//!
//! raw TOML (`model::raw`) → validated model (`model`) → per-shape closed
//! forms (`shapes`) → composed body (`compose`, `mass`) → summary and
//! renderers (`report`). Only `main.rs` knows about processes and exit codes.

pub mod bless;
pub mod check;
pub mod cli;
pub mod compose;
pub mod diag;
pub mod diff;
pub mod eigen;
pub mod mass;
pub mod materials;
pub mod model;
pub mod numeric;
pub mod report;
pub mod shapes;
pub mod units;

use cli::{Cli, Command, Format, ReportArgs};
use diag::{Diagnostic, Source};
use model::Model;
use std::io::Read;
use units::Dim;

/// What a run that completed prints and the exit status it ends with
/// (`check` reports invalid files on stderr and still checks the rest).
pub struct Output {
    pub stdout: String,
    pub stderr: String,
    pub status: u8,
}

/// Read a part file, or standard input for `-`.
pub fn read_source(path: &str) -> Result<Source, Diagnostic> {
    if path == "-" {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| Diagnostic::file("<stdin>", format!("cannot read standard input: {e}")))?;
        return Ok(Source::new("<stdin>", text));
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| Diagnostic::file(path, format!("cannot read file: {e}")))?;
    Ok(Source::new(path, text))
}

/// Run a parsed command line. Errors are user-facing diagnostics (exit 2).
pub fn run(cli: &Cli) -> Result<Output, Diagnostic> {
    match &cli.command {
        Command::Report(args) => report(args),
        Command::Check(args) => check::run(args),
        Command::Diff(args) => diff::run(args),
        Command::Materials(args) => materials::run(args),
    }
}

fn report(args: &ReportArgs) -> Result<Output, Diagnostic> {
    let source = read_source(&args.file)?;
    let mut model = Model::parse(&source)?;
    if let Some(name) = &args.only {
        model.only(name).map_err(Diagnostic::plain)?;
    }
    let mut analysis = model.analysis.clone();
    let flag = |text: &Option<String>, name: &str, dim: Dim| {
        text.as_deref()
            .map(|t| {
                model::parse_flag_vector(t, model.units, dim).map_err(|e| {
                    Diagnostic::plain(format!("invalid value {t:?} for `--{name}`: {e}"))
                })
            })
            .transpose()
    };
    if let Some(v) = flag(&args.about, "about", Dim::LENGTH)? {
        analysis.about = Some(v);
    }
    if let Some(v) = flag(&args.omega, "omega", Dim::ANGULAR_VELOCITY)? {
        analysis.omega = Some(v);
    }
    if let Some(v) = flag(&args.alpha, "alpha", Dim::ANGULAR_ACCELERATION)? {
        analysis.alpha = Some(v);
    }
    // α without ω: point at the file's `alpha` unless it came from the flag.
    if analysis.alpha.is_some() && analysis.omega.is_none() {
        return Err(match (&model.analysis.alpha_span, &args.alpha) {
            (Some(span), None) => source
                .error(span.clone(), "`alpha` needs `omega`: the Euler moment depends on both")
                .help("give `omega` here or `--omega`; for a body starting from rest, `omega = [0, 0, 0]`"),
            _ => Diagnostic::plain("`--alpha` needs ω: give `--omega` or `[analysis].omega`"),
        });
    }
    let flags_given = args.about.is_some() || args.omega.is_some() || args.alpha.is_some();
    let summary =
        report::summarize(&model, &analysis, args.products, args.precision).map_err(|e| {
            let with = if flags_given {
                " (with the values given on the command line)"
            } else {
                ""
            };
            Diagnostic::file(&source.name, format!("{e}{with}"))
        })?;
    let stdout = match args.format {
        Format::Table => report::table::render(&summary, &source.name),
        Format::Json => report::json::render(&summary),
    };
    Ok(Output {
        stdout,
        stderr: String::new(),
        status: 0,
    })
}
