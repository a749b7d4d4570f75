//! `--color` and `--width`: how output is dressed, resolved once against what the
//! process's standard output and error are (as ripgrep's `HiArgs` resolves
//! its colour choice), and clap's own help and errors coloured the same
//! way.

use super::Cli;
use crate::commands::Terminal;
use crate::output::Style;
use clap::{Args, ColorChoice, CommandFactory, FromArgMatches, ValueEnum};
use std::ffi::OsString;

/// The options of every command that say how output is dressed.
#[derive(Args, Debug, Clone, Default)]
pub struct OutputArgs {
    /// When to use colour: in diagnostics, warnings and `check`'s errors.
    ///
    /// `auto` colours standard output and standard error each where it is
    /// a terminal, unless NO_COLOR is set (CLICOLOR_FORCE colours pipes
    /// too); `always` and `never` override both. `-o FILE` is never
    /// coloured.
    #[arg(
        long,
        value_name = "WHEN",
        global = true,
        default_value_t = ColorChoice::Auto
    )]
    pub color: ColorChoice,

    /// Fit tables to N columns (0: no limit).
    ///
    /// A wider table is split into parts, each with the rows' labels and a
    /// note after the last: no number is cut and no column hidden. Default:
    /// the terminal's width when standard output is a terminal; no limit
    /// for pipes and `-o FILE`.
    #[arg(long, value_name = "N", global = true)]
    pub width: Option<usize>,
}

/// What `--color auto` and the default width depend on: whether each
/// stream takes colour, anstream's answer (a terminal, NO_COLOR, CLICOLOR,
/// CLICOLOR_FORCE, TERM=dumb), and standard output's width when it is a
/// terminal. The default, neither, is a pipe's: `Cli::try_parse_from`
/// (the tests) never looks at the process's own streams, only
/// `Cli::parse_args` does.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Streams {
    pub stdout_colour: bool,
    pub stderr_colour: bool,
    /// Standard output's width in columns, when it is a terminal.
    pub stdout_width: Option<usize>,
}

impl Streams {
    /// This process's standard output and error, and its environment.
    pub fn of_process() -> Streams {
        use anstream::{AutoStream, ColorChoice};
        Streams {
            stdout_colour: AutoStream::choice(&std::io::stdout()) != ColorChoice::Never,
            stderr_colour: AutoStream::choice(&std::io::stderr()) != ColorChoice::Never,
            stdout_width: terminal_size::terminal_size_of(std::io::stdout())
                .map(|(w, _)| usize::from(w.0))
                .filter(|w| *w > 0),
        }
    }
}

impl Cli {
    /// This process's command line, with its streams looked at; clap's
    /// help and errors are coloured as its `--color` asks.
    pub fn parse_args() -> Result<Cli, clap::Error> {
        let mut cli = Cli::try_parse_coloured(std::env::args_os())?;
        cli.streams = Streams::of_process();
        Ok(cli)
    }

    /// `try_parse_from`, with clap's help and errors coloured as the
    /// command line's `--color` asks (clap decides its colour before it
    /// has parsed anything, so `--color` is looked for first).
    pub fn try_parse_coloured<I, T>(args: I) -> Result<Cli, clap::Error>
    where
        I: IntoIterator<Item = T>,
        T: Into<OsString>,
    {
        let mut args: Vec<OsString> = args.into_iter().map(Into::into).collect();
        // NOTE: clap's own `help` subcommand takes a subcommand's name, and
        // `part-file` is a topic, not a command: `massprop help part-file`
        // is read as the hidden `part-file` command; `help report` and the
        // rest stay clap's.
        if args.len() == 3 && args[1] == "help" && args[2] == "part-file" {
            args.remove(1);
        }
        let mut command = Cli::command().color(asked_colour(&args));
        let mut matches = command.try_get_matches_from_mut(args)?;
        let cli = Cli::from_arg_matches_mut(&mut matches).map_err(|e| e.format(&mut command))?;
        if let Some(includes) = cli.command.includes() {
            includes
                .check_rules()
                .map_err(|m| command.error(clap::error::ErrorKind::ArgumentConflict, m))?;
        }
        if let super::Command::Report(a) = &cli.command {
            a.uncertainty
                .check_rules()
                .map_err(|m| command.error(clap::error::ErrorKind::ArgumentConflict, m))?;
        }
        if let super::Command::Export(a) = &cli.command
            && a.geometry.from_geometry.is_none()
        {
            // Without `--from-geometry`, `--update` and `--link` go
            // together (with it, each alone: all links, or one printed).
            let missing = match (&a.update, &a.link) {
                (Some(_), None) => Some(
                    "`--update` replaces one link's inertial: give `--link NAME` (or compute every link's with `--from-geometry`)",
                ),
                (None, Some(_)) => Some(
                    "`--link` names the link `--update ROBOT_FILE` replaces: give `--update` (or print that link's inertial from its geometry with `--from-geometry`)",
                ),
                _ => None,
            };
            if let Some(m) = missing {
                let export = command
                    .find_subcommand_mut("export")
                    .expect("invariant: `export` is a subcommand");
                return Err(export.error(clap::error::ErrorKind::MissingRequiredArgument, m));
            }
        }
        if let super::Command::Check(a) = &cli.command
            && a.paths.iter().filter(|p| p.as_os_str() == "-").count() > 1
        {
            // Located as clap locates its own: the usage of `check`.
            let check = command
                .find_subcommand_mut("check")
                .expect("invariant: `check` is a subcommand");
            return Err(check.error(
                clap::error::ErrorKind::ArgumentConflict,
                "`-` (standard input) is given twice among `check`'s PATHs: standard input can be read only once",
            ));
        }
        Ok(cli)
    }

    /// How each stream's output is dressed: `--color` and `--width`
    /// against what the streams are (`streams`).
    pub fn terminal(&self) -> Terminal {
        let colour = |auto: bool| match self.output.color {
            ColorChoice::Always => true,
            ColorChoice::Never => false,
            ColorChoice::Auto => auto,
        };
        // `--width 0`: no limit.
        let asked = self.output.width.map(|w| (w > 0).then_some(w));
        Terminal {
            stdout: Style {
                colour: colour(self.streams.stdout_colour),
                width: asked.unwrap_or(self.streams.stdout_width),
            },
            stderr: Style {
                colour: colour(self.streams.stderr_colour),
                width: None,
            },
            // A file is as a pipe: the width asked for, or none.
            file: Style {
                colour: false,
                width: asked.flatten(),
            },
        }
    }
}

/// The last `--color WHEN` or `--color=WHEN` before any `--`, or `auto`
/// (also for a value clap will refuse, so that its error is coloured as
/// the environment says).
fn asked_colour(args: &[OsString]) -> ColorChoice {
    let mut choice = ColorChoice::Auto;
    let mut it = args.iter().skip(1);
    while let Some(arg) = it.next() {
        let value = match arg.to_str() {
            Some("--") => break,
            Some("--color") => it.next().and_then(|v| v.to_str()),
            Some(a) => a.strip_prefix("--color="),
            None => None,
        };
        if let Some(c) = value.and_then(|v| ColorChoice::from_str(v, false).ok()) {
            choice = c;
        }
    }
    choice
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(line: &str) -> Vec<OsString> {
        line.split(' ').map(OsString::from).collect()
    }

    fn terminal(line: &str, streams: Streams) -> Terminal {
        let mut cli = Cli::try_parse_coloured(args(line)).unwrap();
        cli.streams = streams;
        cli.terminal()
    }

    const TERMINALS: Streams = Streams {
        stdout_colour: true,
        stderr_colour: true,
        stdout_width: Some(100),
    };

    #[test]
    fn the_colour_asked_for_is_the_last_before_a_double_dash() {
        let asked = |line: &str| asked_colour(&args(line));
        assert_eq!(asked("massprop report f.toml"), ColorChoice::Auto);
        assert_eq!(
            asked("massprop --color never report f.toml"),
            ColorChoice::Never
        );
        assert_eq!(
            asked("massprop report --color=always f.toml"),
            ColorChoice::Always
        );
        assert_eq!(
            asked("massprop report --color always --color never f"),
            ColorChoice::Never
        );
        assert_eq!(asked("massprop report -- --color=never"), ColorChoice::Auto);
        assert_eq!(asked("massprop --color sometimes"), ColorChoice::Auto);
    }

    #[test]
    fn auto_colours_each_stream_that_takes_colour() {
        let t = terminal("massprop report f.toml", TERMINALS);
        assert!(t.stdout.colour && t.stderr.colour && !t.file.colour);
        let only_stderr = Streams {
            stdout_colour: false,
            ..TERMINALS
        };
        let t = terminal("massprop report f.toml", only_stderr);
        assert!(!t.stdout.colour && t.stderr.colour);
        // Pipes: what `try_parse_from` assumes.
        let t = terminal("massprop report f.toml", Streams::default());
        assert_eq!(t, Terminal::default());
    }

    #[test]
    fn always_and_never_override_the_streams() {
        let t = terminal("massprop report --color always f", Streams::default());
        assert!(t.stdout.colour && t.stderr.colour && !t.file.colour);
        let t = terminal("massprop --color never check f", TERMINALS);
        assert!(!t.stdout.colour && !t.stderr.colour);
    }

    #[test]
    fn tables_fit_a_terminal_unless_a_width_is_asked_for() {
        let width = |line: &str, streams: Streams| {
            let t = terminal(line, streams);
            (t.stdout.width, t.file.width, t.stderr.width)
        };
        assert_eq!(
            width("massprop report f", TERMINALS),
            (Some(100), None, None)
        );
        assert_eq!(
            width("massprop report f", Streams::default()),
            (None, None, None)
        );
        assert_eq!(
            width("massprop report --width 60 f", Streams::default()),
            (Some(60), Some(60), None)
        );
        assert_eq!(
            width("massprop --width 0 report f", TERMINALS),
            (None, None, None)
        );
        // Colour is not width: NO_COLOR on a terminal still fits it.
        let no_colour = Streams {
            stdout_colour: false,
            stderr_colour: false,
            ..TERMINALS
        };
        assert_eq!(
            width("massprop report f", no_colour),
            (Some(100), None, None)
        );
    }

    #[test]
    fn color_takes_auto_always_and_never_only() {
        let e = Cli::try_parse_coloured(args("massprop report --color yes f")).unwrap_err();
        assert_eq!(e.kind(), clap::error::ErrorKind::InvalidValue);
        assert!(
            e.to_string()
                .contains("[possible values: auto, always, never]")
        );
    }
}
