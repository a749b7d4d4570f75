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

/// The largest part file read, in bytes: a 100,000-part file of 17-digit
/// numbers is ~30 MB and takes ~15 bytes of memory per byte to read, so this
/// allows ~1.7 million parts in ~8 GB.
pub const MAX_FILE_BYTES: u64 = 512 << 20;

/// Read a part file, or standard input for `-`, refusing directories and
/// anything over `MAX_FILE_BYTES`.
pub fn read_source(path: &str) -> Result<Source, Diagnostic> {
    let stdin = path == "-";
    let name = if stdin { "<stdin>" } else { path };
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
            path,
            "cannot read file: it is a directory (`check` searches directories)",
        ));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(too_big());
    }
    // Not only regular files: `massprop report <(generate)` is a pipe.
    let mut file = std::fs::File::open(path).map_err(cannot_read)?;
    source_of(path, capped(&mut file)?)
}

/// A part file's bytes as its source: UTF-8, or an error at the first byte
/// that is not (with its line and column, as any other error).
pub(crate) fn source_of(name: &str, bytes: Vec<u8>) -> Result<Source, Diagnostic> {
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

/// Replace `path` by `text` through a temporary file in the same directory
/// and a rename, so an interrupted or failed run never leaves half a file
/// (`what` names it in the error).
pub(crate) fn write_atomically(path: &str, text: &str, what: &str) -> Result<(), Diagnostic> {
    let fail = |e: std::io::Error| Diagnostic::file(path, format!("cannot write {what}: {e}"));
    // A symlink is written through (the link stays a link, its target gets
    // the text); something that is not a regular file (/dev/stdout, a FIFO,
    // a device) cannot be replaced by a rename and is written directly.
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
