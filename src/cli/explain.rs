//! `explain`'s arguments: the file, the format (text, markdown, LaTeX),
//! and the options it shares with `report` (`--only`, `--about`,
//! `--omega`, `--products`, the includes).

use super::IncludeArgs;
use crate::analysis::{Overrides, Products, Settings};
use crate::commands;
use crate::explain::render::Style;
use clap::Args;

pub(super) const EXPLAIN_HELP: &str = "\
Examples:
  massprop explain shapes/bent-plate.toml                 the worked solution, as text
  massprop explain arm.toml --only elbow                  one sub-assembly, part by part
  massprop explain arm.toml --format markdown             tables and $…$ maths
  massprop explain arm.toml --format latex > arm.tex      an align* per step, for pdflatex";

#[derive(Args, Debug)]
pub struct ExplainArgs {
    /// The part file (`-` reads standard input).
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    pub format: StyleArg,

    /// Sign convention of products of inertia in the working.
    #[arg(long, value_enum, default_value_t)]
    pub products: Products,

    /// Explain one sub-assembly (an `include`, by its name) part by part,
    /// in the file's frame.
    #[arg(long, value_name = "NAME")]
    pub only: Option<String>,

    /// Reference point, overriding `[analysis].about`: x,y,z in the
    /// file's length unit, or with units, e.g. "0,0,10 mm".
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub about: Option<String>,

    /// Angular velocity ω for H and T, overriding `[analysis].omega`:
    /// x,y,z in rad/s, or with units, e.g. "0,0,3000 rpm".
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub omega: Option<String>,

    #[command(flatten)]
    pub includes: IncludeArgs,
}

/// `explain --format`'s values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum StyleArg {
    /// For the terminal
    Text,
    /// Tables and $…$ maths, for a report or a notebook
    Markdown,
    /// A LaTeX document, an align* environment per step
    Latex,
}

impl ExplainArgs {
    pub(super) fn options(&self) -> commands::explain::Options {
        commands::explain::Options {
            file: self.file.clone(),
            style: match self.format {
                StyleArg::Text => Style::Text,
                StyleArg::Markdown => Style::Markdown,
                StyleArg::Latex => Style::Latex,
            },
            settings: Settings {
                products: self.products,
                only: self.only.clone(),
                includes: self.includes.includes(),
                overrides: Overrides {
                    about: self.about.clone(),
                    omega: self.omega.clone(),
                    ..Default::default()
                },
                ..Settings::default()
            },
        }
    }
}
