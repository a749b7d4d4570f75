//! The commands: each a thin file that takes its options (plain library
//! types; `cli` converts the command line into them), runs the load
//! pipeline (`analysis`) and hands its result to the output layer
//! (`render`). Only `main.rs` turns an `Outcome` into a process exit.

pub mod budget;
pub mod check;
pub mod diff;
pub mod explain;
pub mod export;
pub mod geometry;
pub mod init;
pub mod materials;
pub mod render;
pub mod report;
pub mod robot;

use crate::diag::Diagnostic;
use crate::io::{FileId, write_atomically_with};
use crate::output::Style;
use std::path::{Path, PathBuf};

/// What a run prints on standard output (or into `-o`'s file).
#[derive(Debug, Clone)]
pub enum Stdout {
    /// Made already (small).
    Text(String),
    /// A report, written as it is made: its rows, one per part and per
    /// sub-assembly, are never all in memory.
    Report {
        summary: Box<crate::analysis::summary::Summary>,
        /// The name of the part file.
        source: String,
        format: crate::output::Format,
        /// How much of it a table shows (`--full`, `--about`).
        detail: crate::output::report::Detail,
        /// Where it goes: standard output's, or `-o`'s file's.
        style: Style,
    },
    /// A drawing (`render`), written as it is made: its document is never
    /// all in memory.
    Drawing(Box<render::Drawing>),
}

impl Stdout {
    /// Write it to `w`.
    pub fn write_to(&self, w: &mut dyn std::io::Write) -> std::io::Result<()> {
        match self {
            Stdout::Text(t) => w.write_all(t.as_bytes()),
            Stdout::Report {
                summary,
                source,
                format,
                detail,
                style,
            } => crate::output::write(
                &crate::output::Output::Report(summary, source, *detail),
                *format,
                *style,
                w,
            ),
            Stdout::Drawing(d) => d.write_to(w),
        }
    }

    /// All of it, in memory (for tests).
    pub fn text(&self) -> String {
        let mut out = Vec::new();
        self.write_to(&mut out)
            .expect("invariant: writing to memory does not fail");
        String::from_utf8(out).expect("invariant: every output is UTF-8")
    }
}

/// What a run that completed prints and the exit status it ends with
/// (`check` reports invalid files on stderr and still checks the rest).
#[derive(Debug, Clone)]
pub struct Outcome {
    pub stdout: Stdout,
    pub stderr: String,
    pub status: u8,
    /// Every file the run read (part files, the files they include, the
    /// files found in directories): `-o` may not name any of them.
    pub read: Vec<PathBuf>,
}

impl Outcome {
    /// Success with `stdout`, having read `read`.
    pub fn ok(stdout: String, read: Vec<PathBuf>) -> Outcome {
        Outcome {
            stdout: Stdout::Text(stdout),
            stderr: String::new(),
            status: 0,
            read,
        }
    }
}

/// The files a loaded part file was read from: itself (unless standard
/// input) and every file it includes.
pub fn files_of(loaded: &crate::analysis::Loaded) -> Vec<PathBuf> {
    let own = std::fs::canonicalize(loaded.source.path()).ok();
    own.into_iter()
        .chain(loaded.model.included.iter().cloned())
        .collect()
}

/// The accuracy warnings of a loaded part file (`--rtol` not met), a line
/// each for standard error: `warning: FILE: …`, `warning` coloured when
/// `colour`; then its plausibility warnings (`analysis::plausible`),
/// `warning: FILE:LINE:COL: …`.
/// An MJCF mesh file's warning (`robot::read::MeshWarning`, said at its
/// `<mesh>` asset) as the report's warnings carry it: for `report` and
/// `export --from-geometry` alike.
pub(crate) fn mesh_warning(
    w: &crate::robot::read::MeshWarning,
) -> crate::analysis::plausible::Warning {
    crate::analysis::plausible::Warning {
        kind: crate::analysis::plausible::Kind::Mesh,
        path: w.path.clone(),
        span: w.span,
        message: w.message.clone(),
    }
}

pub fn accuracy_warnings(loaded: &crate::analysis::Loaded, colour: bool) -> String {
    warning_lines(
        &loaded.source.name,
        &loaded.summary.accuracy_warnings,
        colour,
    ) + &crate::analysis::plausible::lines(&loaded.summary.warnings, colour)
}

pub use crate::analysis::check_run::warning_lines;

/// Where a run's output goes and how it is dressed there: `cli` resolves
/// `--color` and `--width` against what the process's standard output and
/// error are. The default is plain everywhere: pipes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Terminal {
    /// Standard output's.
    pub stdout: Style,
    /// Standard error's (diagnostics and warnings).
    pub stderr: Style,
    /// `-o FILE`'s: never coloured.
    pub file: Style,
}

/// One command with its options.
#[derive(Debug, Clone)]
pub enum Request {
    Report(report::Options),
    Budget(budget::Options),
    Check(check::Options),
    Diff(diff::Options),
    Export(export::Options),
    Explain(explain::Options),
    Materials(materials::Options),
    Render(render::Options),
    Init(init::Options),
    /// A text made before the run, printed as it is: `completions` and
    /// `man` from the command line's own definition (`cli` makes them, the
    /// only module that knows clap), `schema` from the part file's types
    /// (`model::schema`).
    Text(String),
}

impl Request {
    /// `-o FILE`, where the command takes it; `-o -` is standard output,
    /// as `-` is standard input wherever a file is read.
    fn output(&self) -> Option<&str> {
        let o = match self {
            Request::Report(o) | Request::Budget(o) => o.output.as_deref(),
            Request::Check(o) => o.output.as_deref(),
            Request::Diff(o) => o.output.as_deref(),
            Request::Export(o) => o.output.as_deref(),
            Request::Render(o) => o.output.as_deref(),
            Request::Materials(_) | Request::Init(_) | Request::Text(_) | Request::Explain(_) => {
                None
            }
        };
        o.filter(|o| *o != "-")
    }

    /// The part files the command reads, as named.
    fn inputs(&self) -> Vec<&str> {
        match self {
            Request::Report(o) | Request::Budget(o) => vec![&o.file],
            // A name that is not UTF-8 is left to the check after the run,
            // against every file read.
            Request::Check(o) => o.paths.iter().filter_map(|p| p.to_str()).collect(),
            Request::Diff(o) => vec![&o.old, &o.new],
            Request::Export(o) => vec![&o.file],
            Request::Render(o) => vec![&o.file],
            Request::Explain(o) => vec![&o.file],
            Request::Materials(_) | Request::Init(_) | Request::Text(_) => Vec::new(),
        }
    }
}

/// The input that `-o PATH` names, if any: the one rule for "this output
/// is a file the run reads", used before the run (against the files named)
/// and after it (against every file read). The same file, not the same
/// path: a hard link or a symlink to an input is that input (`FileId`), and
/// `-` is the file behind standard input when that is a regular file
/// (`report - -o x.toml < x.toml`).
fn input_named_by<'a>(
    output: &str,
    inputs: impl IntoIterator<Item = &'a Path>,
) -> Option<&'a Path> {
    let output = FileId::of(Path::new(output))?;
    inputs.into_iter().find(|i| {
        let id = if *i == Path::new("-") {
            FileId::of_stdin()
        } else {
            FileId::of(i)
        };
        id.as_ref() == Some(&output)
    })
}

/// `-o PATH` names `input`, a file the run reads.
fn onto_input(path: &str, input: &Path) -> Diagnostic {
    let input = if input == Path::new("-") {
        "the file on standard input".to_string()
    } else {
        let what = if crate::mesh::FileType::of(input).is_some() {
            "the mesh file"
        } else {
            "the part file"
        };
        format!("{what} `{}`", crate::diag::display_path(input))
    };
    Diagnostic::plain(format!(
        "`-o {path}` is {input}: the report would replace it"
    ))
}

/// Whether `path` is a regular file that reads as a part file
/// (`model::looks_like_a_part_file`, on its first MiB: a part file's first
/// `[[part]]` comes early, and an old report is never read whole).
fn is_a_part_file(path: &str) -> bool {
    use std::io::Read;
    let Ok(file) = std::fs::File::open(path) else {
        return false;
    };
    if !file.metadata().is_ok_and(|m| m.is_file()) {
        return false;
    }
    let mut head = Vec::new();
    file.take(1 << 20).read_to_end(&mut head).is_ok()
        && crate::model::looks_like_a_part_file(&String::from_utf8_lossy(&head))
}

/// Run a command, its output dressed for `terminal`. Errors are
/// user-facing diagnostics (exit 2), which the caller renders for standard
/// error (`Diagnostic::render`).
pub fn run(request: &Request, terminal: &Terminal) -> Result<Outcome, Diagnostic> {
    let output = request.output();
    refuse_output(request, output)?;
    // The command's output goes to `-o`'s file or to standard output:
    // dressed for the one it goes to.
    let terminal = &Terminal {
        stdout: if output.is_some() {
            terminal.file
        } else {
            terminal.stdout
        },
        ..*terminal
    };
    let out = dispatch(request, terminal)?;
    match output {
        Some(path) => write_output(request, path, out),
        None => Ok(out),
    }
}

/// `-o` refused before anything is read or written: an empty name, a part
/// file being read (it would replace the design with the report), or any
/// part file (one that a file includes is not known to be read when that
/// file is refused before its includes are: `check` goes on).
fn refuse_output(request: &Request, output: Option<&str>) -> Result<(), Diagnostic> {
    // NOTE: an empty name would reach the file system as "" and come back
    // as "No such file or directory" after a colon with nothing before it.
    if output == Some("") {
        return Err(
            Diagnostic::plain("`-o` (`--output`) was given an empty file name")
                .help("name a file, or give `-o -` for standard output"),
        );
    }
    let Some(path) = output else {
        return Ok(());
    };
    if let Some(i) = input_named_by(path, request.inputs().into_iter().map(Path::new)) {
        return Err(onto_input(path, i));
    }
    if is_a_part_file(path) {
        return Err(Diagnostic::plain(format!(
            "`-o {path}` is a part file: the report would replace it"
        ))
        .help("`-o` never replaces a part file; name another file"));
    }
    Ok(())
}

/// The command run.
fn dispatch(request: &Request, terminal: &Terminal) -> Result<Outcome, Diagnostic> {
    Ok(match request {
        Request::Report(o) => report::run(o, terminal)?,
        Request::Budget(o) => budget::run(o, terminal)?,
        Request::Check(o) => check::run(o, terminal)?,
        Request::Diff(o) => diff::run(o, terminal)?,
        Request::Export(o) => match &o.from_geometry {
            Some(g) => geometry::run(&o.file, g, &o.settings)?,
            None => export::run(o, terminal)?,
        },
        Request::Materials(o) => materials::run(o, terminal)?,
        Request::Render(o) => render::run(o, terminal)?,
        Request::Explain(o) => explain::run(o)?,
        Request::Init(o) => init::run(o)?,
        Request::Text(text) => Outcome {
            stdout: Stdout::Text(text.clone()),
            stderr: String::new(),
            status: 0,
            read: Vec::new(),
        },
    })
}

/// `-o FILE`: the whole result or nothing, never half a file, and never
/// onto a file the run read (one found in a directory, or included by one
/// named; asked again now that they are known).
fn write_output(request: &Request, path: &str, out: Outcome) -> Result<Outcome, Diagnostic> {
    let named = request.inputs().into_iter().map(Path::new);
    let read = out.read.iter().map(PathBuf::as_path);
    if let Some(i) = input_named_by(path, named.chain(read)) {
        return Err(onto_input(path, i));
    }
    write_atomically_with(path, &|w| out.stdout.write_to(w), "the output file")?;
    Ok(Outcome {
        stdout: Stdout::Text(String::new()),
        ..out
    })
}
