//! The `massprop` binary: parse the command line, run, print, choose the
//! exit status. Everything else lives in the library.

use std::io::Write;
use std::process::ExitCode;

/// Write to stderr, ignoring failure: with stderr closed (`2>&1 | head -1`)
/// there is nowhere left to say anything, and `eprint!` would panic.
fn to_stderr(text: &str) {
    let mut stderr = std::io::stderr().lock();
    let _ = stderr
        .write_all(text.as_bytes())
        .and_then(|()| stderr.flush());
}

fn main() -> ExitCode {
    let cli = match massprop::cli::Cli::parse_args() {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout, usage errors to stderr; a
            // closed pipe on either is not a panic, nor an error. Help that
            // cannot be written (`--help > /dev/full`) is one: exit 2.
            let status = u8::try_from(e.exit_code()).unwrap_or(2);
            return match e.print().and_then(|()| std::io::stdout().flush()) {
                Ok(()) => ExitCode::from(status),
                Err(w) if w.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::from(status),
                Err(w) => {
                    let d = massprop::diag::Diagnostic::plain(format!("cannot write output: {w}"));
                    let colour = massprop::cli::Streams::of_process().stderr_colour;
                    to_stderr(&d.render(colour));
                    ExitCode::from(2)
                }
            };
        }
    };
    // Standard error's colour, for what `main` itself prints.
    let colour = cli.terminal().stderr.colour;
    match massprop::run(&cli) {
        Ok(out) => {
            to_stderr(&out.stderr);
            // Written as it is made: a report of 2²⁰ parts is never all in
            // memory.
            let mut stdout = std::io::BufWriter::with_capacity(1 << 16, std::io::stdout().lock());
            match out
                .stdout
                .write_to(&mut stdout)
                .and_then(|()| stdout.flush())
            {
                Ok(()) => ExitCode::from(out.status),
                // A closed pipe (`massprop report x.toml | head -1`) is not an error.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::from(out.status),
                Err(e) => {
                    let d = massprop::diag::Diagnostic::plain(format!("cannot write output: {e}"));
                    to_stderr(&d.render(colour));
                    ExitCode::from(2)
                }
            }
        }
        Err(diag) => {
            to_stderr(&diag.render(colour));
            ExitCode::from(2)
        }
    }
}
