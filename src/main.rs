//! The `massprop` binary: parse the command line, run, print, choose the
//! exit status. Everything else lives in the library.

use clap::Parser;
use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = massprop::cli::Cli::parse();
    match massprop::run(&cli) {
        Ok(out) => {
            eprint!("{}", out.stderr);
            let mut stdout = std::io::stdout().lock();
            match stdout
                .write_all(out.stdout.as_bytes())
                .and_then(|()| stdout.flush())
            {
                Ok(()) => ExitCode::from(out.status),
                // A closed pipe (`massprop report x.toml | head -1`) is not an error.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::from(out.status),
                Err(e) => {
                    eprintln!("error: cannot write output: {e}");
                    ExitCode::from(2)
                }
            }
        }
        Err(diag) => {
            eprint!("{diag}");
            ExitCode::from(2)
        }
    }
}
