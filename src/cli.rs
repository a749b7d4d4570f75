//! The command line, declared with clap derive; doc comments are the help.

use crate::compose::Precision;
use crate::report::Products;
use clap::{Args, Parser, Subcommand, ValueEnum};

const EXIT_STATUS: &str = "\
Exit status:
  0  success
  1  `check`: an expectation or validity check failed; `diff`: something changed beyond --tol
  2  an error: bad input, unreadable file, bad flag (nothing is printed on stdout)";

/// Mass properties of composite rigid bodies described by TOML part files.
#[derive(Parser, Debug)]
#[command(name = "massprop", version, after_help = EXIT_STATUS)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Report mass, centre of mass, inertia, principal axes, H, T and M of a part file.
    Report(ReportArgs),
    /// Check part files' `[expect]` blocks and physical validity (for CI).
    Check(CheckArgs),
    /// Compare the mass properties of two part files (or two versions of one).
    Diff(DiffArgs),
    /// List the materials `material = "NAME"` may name, with their densities.
    Materials(MaterialsArgs),
}

#[derive(Args, Debug)]
pub struct MaterialsArgs {
    /// A part file whose `[materials]` table is listed too (it adds to and
    /// overrides the built-in ones).
    #[arg(value_name = "FILE")]
    pub file: Option<String>,

    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,
}

#[derive(Args, Debug)]
pub struct CheckArgs {
    /// Part files, and directories searched recursively for `*.toml`.
    #[arg(value_name = "PATH", required = true)]
    pub paths: Vec<String>,

    /// Write the output to FILE instead of standard output, atomically
    /// (through a temporary file and a rename): a failed or interrupted run
    /// leaves FILE as it was.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    /// Write the computed values into each file's `[expect]` entries first,
    /// keeping tolerances (adding defaults where missing), bounds, comments
    /// and formatting; files that cannot be parsed are left untouched.
    #[arg(long)]
    pub bless: bool,

    /// Arithmetic: `standard` (f64, compensated sums) or `extended`
    /// (double-double, ~32 digits; for the smallest moments of very slender
    /// or flat bodies). See docs/accuracy.md.
    #[arg(long, value_enum, default_value_t)]
    pub precision: Precision,

    /// Output format: one line per file or failure, or one JSON document.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,
}

#[derive(Args, Debug)]
pub struct DiffArgs {
    /// The old part file (`-` reads standard input).
    #[arg(value_name = "OLD")]
    pub old: String,

    /// The new part file (`-` reads standard input; not both).
    #[arg(value_name = "NEW")]
    pub new: String,

    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,

    /// Write the output to FILE instead of standard output, atomically
    /// (through a temporary file and a rename): a failed or interrupted run
    /// leaves FILE as it was.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    /// Relative tolerance: a value counts as changed when it moves by more
    /// than this fraction of its scale.
    #[arg(
        long,
        value_name = "REL",
        default_value_t = 1e-9,
        allow_negative_numbers = true
    )]
    pub tol: f64,

    /// Arithmetic: `standard` (f64, compensated sums) or `extended`
    /// (double-double, ~32 digits; for the smallest moments of very slender
    /// or flat bodies). See docs/accuracy.md.
    #[arg(long, value_enum, default_value_t)]
    pub precision: Precision,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Format {
    /// Tables for people, in the file's units.
    #[default]
    Table,
    /// One JSON object in SI units (see docs/json.md).
    Json,
}

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// The part file (`-` reads standard input).
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,

    /// Write the output to FILE instead of standard output, atomically
    /// (through a temporary file and a rename): a failed or interrupted run
    /// leaves FILE as it was.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    /// Sign convention of products of inertia in the output.
    #[arg(long, value_enum, default_value_t)]
    pub products: Products,

    /// Report one sub-assembly (an `include`, by its name) alone, in the
    /// file's frame.
    #[arg(long, value_name = "NAME")]
    pub only: Option<String>,

    /// Arithmetic: `standard` (f64, compensated sums) or `extended`
    /// (double-double, ~32 digits; for the smallest moments of very slender
    /// or flat bodies). See docs/accuracy.md.
    #[arg(long, value_enum, default_value_t)]
    pub precision: Precision,

    /// Reference point, overriding `[analysis].about`: x,y,z in the file's
    /// length unit, or with units, e.g. "0,0,10 mm".
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub about: Option<String>,

    /// Angular velocity ω, overriding `[analysis].omega`: x,y,z in rad/s, or
    /// with units, e.g. "0,0,3000 rpm".
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub omega: Option<String>,

    /// Angular acceleration α, overriding `[analysis].alpha`: x,y,z in
    /// rad/s², or with units, e.g. "0,0,90 deg/s^2". Needs ω.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub alpha: Option<String>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
