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

/// Print clap's error about the command line, with the arguments it quotes
/// shown as every text from input is (`diag::visible`): a file name found
/// by a shell's glob (`massprop check *.toml`) may hold a newline and
/// `::error::…`. clap's message is made again from the arguments so shown,
/// which it refuses the same way (only control, bidirectional and separator
/// characters change, and no flag or value massprop takes needs one).
/// (An argument that is not UTF-8 is not quoted: clap says only that one
/// is not.)
fn usage_error(e: clap::Error) {
    use massprop::diag::{may_hide, visible};
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    if !args
        .iter()
        .skip(1)
        .any(|a| a.to_str().is_some_and(may_hide))
    {
        let _ = e.print();
        return;
    }
    let again = args.iter().enumerate().map(|(i, a)| match a.to_str() {
        Some(s) if i > 0 => std::ffi::OsString::from(visible(s)),
        _ => a.clone(),
    });
    match massprop::cli::Cli::try_parse_coloured(again) {
        Err(e) => {
            let _ = e.print();
        }
        Ok(_) => to_stderr(
            &massprop::diag::Diagnostic::plain(
                "the command line is not valid; an argument holds a control character",
            )
            .to_string(),
        ),
    }
}

/// The message of a panic (a bug in massprop, never an answer to input),
/// shown as text from input always is (`diag::visible`): the default hook
/// prints it raw, and a panic's message may quote input, so a line of
/// standard error could begin with text the input chose.
fn panic_hook(info: &std::panic::PanicHookInfo<'_>) {
    let payload = info.payload();
    let what = payload
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
        .unwrap_or("");
    let at = info
        .location()
        .map(|l| format!(" at {}:{}", l.file(), l.line()))
        .unwrap_or_default();
    let mut text = format!(
        "error: internal error{at}: {}\n  = help: a bug in massprop, not in the input: please report it, with the input\n",
        massprop::diag::visible(&massprop::diag::shorten(what))
    );
    if std::env::var_os("RUST_BACKTRACE").is_some_and(|v| v != "0") {
        text.push_str(&std::backtrace::Backtrace::force_capture().to_string());
    }
    to_stderr(&text);
}

fn main() -> ExitCode {
    std::panic::set_hook(Box::new(panic_hook));
    let cli = match massprop::cli::Cli::parse_args() {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout, usage errors to stderr; a
            // closed pipe on either is not a panic, nor an error. Help that
            // cannot be written (`--help > /dev/full`) is one: exit 2.
            let status = u8::try_from(e.exit_code()).unwrap_or(2);
            if e.use_stderr() {
                usage_error(e);
                return ExitCode::from(status);
            }
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
