//! The commands: each a thin file that takes its options (plain library
//! types; `cli` converts the command line into them), runs the load
//! pipeline (`analysis`) and hands its result to the output layer
//! (`render`). Only `main.rs` turns an `Outcome` into a process exit.

pub mod bless;
pub mod check;
pub mod diff;
pub mod materials;
pub mod report;

use crate::diag::Diagnostic;
use crate::io::write_atomically;
use std::path::PathBuf;

/// What a run that completed prints and the exit status it ends with
/// (`check` reports invalid files on stderr and still checks the rest).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Outcome {
    pub stdout: String,
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
            stdout,
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

/// One command with its options.
#[derive(Debug, Clone)]
pub enum Request {
    Report(report::Options),
    Check(check::Options),
    Diff(diff::Options),
    Materials(materials::Options),
}

impl Request {
    /// `-o FILE`, where the command takes it; `-o -` is standard output,
    /// as `-` is standard input wherever a file is read.
    fn output(&self) -> Option<&str> {
        let o = match self {
            Request::Report(o) => o.output.as_deref(),
            Request::Check(o) => o.output.as_deref(),
            Request::Diff(o) => o.output.as_deref(),
            Request::Materials(_) => None,
        };
        o.filter(|o| *o != "-")
    }

    /// The part files the command reads, as named.
    fn inputs(&self) -> Vec<&str> {
        match self {
            Request::Report(o) => vec![&o.file],
            // A name that is not UTF-8 is left to the check after the run,
            // against every file read.
            Request::Check(o) => o.paths.iter().filter_map(|p| p.to_str()).collect(),
            Request::Diff(o) => vec![&o.old, &o.new],
            Request::Materials(_) => Vec::new(),
        }
    }
}

/// `-o PATH` names `input`, a file the run reads.
fn onto_input(path: &str, input: &str) -> Diagnostic {
    Diagnostic::plain(format!(
        "`-o {path}` is the part file `{input}`: the report would replace it"
    ))
}

/// Run a command. Errors are user-facing diagnostics (exit 2).
pub fn run(request: &Request) -> Result<Outcome, Diagnostic> {
    // `-o` onto a part file being read would replace the design with the
    // report: refused before anything is read or written.
    let output = request.output();
    if let Some(path) = output
        && let Ok(o) = std::fs::canonicalize(path)
        && let Some(i) = request
            .inputs()
            .into_iter()
            .find(|i| std::fs::canonicalize(i).is_ok_and(|i| i == o))
    {
        return Err(onto_input(path, i));
    }
    let out = match request {
        Request::Report(o) => report::run(o)?,
        Request::Check(o) => check::run(o)?,
        Request::Diff(o) => diff::run(o)?,
        Request::Materials(o) => materials::run(o)?,
    };
    match output {
        // `-o FILE`: the whole result or nothing, never half a file, and
        // never onto a file the run read (one found in a directory, or
        // included by one named).
        Some(path) => {
            if let Ok(o) = std::fs::canonicalize(path)
                && let Some(i) = out.read.iter().find(|i| **i == o)
            {
                return Err(onto_input(path, &i.display().to_string()));
            }
            write_atomically(path, &out.stdout, "the output file")?;
            Ok(Outcome {
                stdout: String::new(),
                ..out
            })
        }
        None => Ok(out),
    }
}
