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
pub mod io;
pub mod mass;
pub mod materials;
pub mod model;
pub mod numeric;
pub mod part;
pub mod report;
pub mod shapes;
pub mod units;

use cli::{Cli, Command, Format, ReportArgs};
use diag::Diagnostic;
use model::Model;
pub use io::{MAX_FILE_BYTES, read_source};
use io::write_atomically;
use units::Dim;

/// What a run that completed prints and the exit status it ends with
/// (`check` reports invalid files on stderr and still checks the rest).
pub struct Output {
    pub stdout: String,
    pub stderr: String,
    pub status: u8,
}

/// Run a parsed command line. Errors are user-facing diagnostics (exit 2).
pub fn run(cli: &Cli) -> Result<Output, Diagnostic> {
    // `-o` onto a part file being read would replace the design with the
    // report: refused before anything is read or written.
    let (output, inputs): (&Option<String>, Vec<&String>) = match &cli.command {
        Command::Report(a) => (&a.output, vec![&a.file]),
        Command::Check(a) => (&a.output, a.paths.iter().collect()),
        Command::Diff(a) => (&a.output, vec![&a.old, &a.new]),
        Command::Materials(_) => (&None, Vec::new()),
    };
    if let Some(o) = output.as_ref().and_then(|o| std::fs::canonicalize(o).ok()) {
        for i in inputs {
            if std::fs::canonicalize(i).is_ok_and(|i| i == o) {
                return Err(Diagnostic::plain(format!(
                    "`-o {}` is the part file `{i}`: the report would replace it",
                    output.as_deref().unwrap_or_default()
                )));
            }
        }
    }
    let (out, file) = match &cli.command {
        Command::Report(args) => (report(args)?, &args.output),
        Command::Check(args) => (check::run(args)?, &args.output),
        Command::Diff(args) => (diff::run(args)?, &args.output),
        Command::Materials(args) => return materials::run(args),
    };
    match file {
        // `-o FILE`: the whole result or nothing, never half a file.
        Some(path) => {
            write_atomically(path, &out.stdout, "the output file")?;
            Ok(Output {
                stdout: String::new(),
                ..out
            })
        }
        None => Ok(out),
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
    // A flag's value has no place in the file: its span goes.
    if let Some(v) = flag(&args.about, "about", Dim::LENGTH)? {
        analysis.about = Some(v);
        analysis.about_span = None;
    }
    if let Some(v) = flag(&args.omega, "omega", Dim::ANGULAR_VELOCITY)? {
        analysis.omega = Some(v);
        analysis.omega_span = None;
    }
    if let Some(v) = flag(&args.alpha, "alpha", Dim::ANGULAR_ACCELERATION)? {
        analysis.alpha = Some(v);
        analysis.alpha_span = None;
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
    let summary = report::summarize(&model, &analysis, args.products, args.precision)
        .map_err(|e| e.diagnostic(&model, &analysis, &source))?;
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
