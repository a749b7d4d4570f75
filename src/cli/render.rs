//! `render`'s arguments: the file, the view, and the options it shares
//! with `report` (`--only`, `--about`, `--omega`, `--axes`, the includes).

use super::{AxesArgs, IncludeArgs};
use crate::analysis::{Overrides, Settings};
use crate::commands;
use clap::Args;

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The part file (`-` reads standard input).
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Write the SVG to FILE instead of standard output, atomically
    /// (through a temporary file and a rename). `-o -` is standard output.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    /// Draw one view alone, larger (default: all four).
    #[arg(long, value_enum, value_name = "VIEW")]
    pub view: Option<ViewArg>,

    /// Draw one sub-assembly (an `include`, by its name) alone, in the
    /// file's frame.
    #[arg(long, value_name = "NAME")]
    pub only: Option<String>,

    /// Reference point to mark, overriding `[analysis].about`: x,y,z in
    /// the file's length unit, or with units, e.g. "0,0,10 mm".
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub about: Option<String>,

    /// Angular velocity ω to draw as an arrow, overriding
    /// `[analysis].omega`: x,y,z in rad/s, or with units, e.g.
    /// "0,0,3000 rpm".
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub omega: Option<String>,

    #[command(flatten)]
    pub axes: AxesArgs,

    #[command(flatten)]
    pub includes: IncludeArgs,

    /// Draw the loading envelope's chart (`[envelope]`) instead of the
    /// body: the polygon, the base's and each case's centre of mass, the
    /// sequences' paths; the axis in the file's length unit and in % MAC
    /// when `mac` is given.
    #[arg(long, conflicts_with = "view")]
    pub envelope: bool,

    /// A robot description's joint positions, as `report --joints`.
    #[arg(long, value_name = "JOINT=VALUE,…", allow_hyphen_values = true)]
    pub joints: Option<String>,
}

/// `render --view`'s values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ViewArg {
    /// x right, z up (seen from −y)
    Front,
    /// x right, y up (seen from +z)
    Top,
    /// y right, z up (seen from +x)
    Side,
    /// isometric, seen from (1, −1, 1), z up
    Iso,
}

impl ViewArg {
    fn view(self) -> crate::output::drawing::View {
        use crate::output::drawing::View;
        match self {
            ViewArg::Front => View::Front,
            ViewArg::Top => View::Top,
            ViewArg::Side => View::Side,
            ViewArg::Iso => View::Iso,
        }
    }
}

impl RenderArgs {
    /// The command's options.
    pub(super) fn options(&self) -> commands::render::Options {
        commands::render::Options {
            file: self.file.clone(),
            output: self.output.clone(),
            view: self.view.map(ViewArg::view),
            envelope: self.envelope,
            settings: Settings {
                only: self.only.clone(),
                includes: self.includes.includes(),
                overrides: Overrides {
                    about: self.about.clone(),
                    omega: self.omega.clone(),
                    axes: self.axes.axes.clone(),
                    ..Default::default()
                },
                ..Settings::default()
            },
            configuration: commands::robot::Configuration {
                joints: self.joints.clone(),
                ..Default::default()
            },
        }
    }
}
