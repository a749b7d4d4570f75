//! The command line, declared with clap derive; doc comments are the help.
//! The only module that knows clap: `Cli::request` turns what was typed into
//! the library's own options (`commands::Request`), and the library's
//! enums get their command-line names and help here.

use crate::analysis::{Overrides, Products, Settings};
use crate::commands::{self, Request};
use crate::output::Format;
use clap::builder::PossibleValue;
use clap::{Args, Parser, Subcommand, ValueEnum};

mod accuracy;
mod cases;
mod explain;
mod help;
mod reference;
mod render;
mod robot;
mod terminal;
mod uncertainty;
use accuracy::{AccuracyArgs, parse_fraction};
use help::*;
pub use render::{RenderArgs, ViewArg};
pub use terminal::{OutputArgs, Streams};

/// Mass properties of composite rigid bodies described by TOML part files.
#[derive(Parser, Debug)]
#[command(name = "massprop", version, after_help = EXIT_STATUS)]
pub struct Cli {
    #[command(flatten)]
    pub output: OutputArgs,

    #[command(subcommand)]
    pub command: Command,

    /// What the process's streams are (`Cli::parse_args` looks; for
    /// `try_parse_from`, pipes).
    #[arg(skip)]
    pub streams: Streams,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Report mass, centre of mass, inertia, principal axes, H, T and M of a part file.
    #[command(after_help = REPORT_HELP)]
    Report(ReportArgs),
    /// The weight statement: basic mass, growth by maturity and predicted mass per group, the margin against the limit.
    #[command(after_help = BUDGET_HELP)]
    Budget(BudgetArgs),
    /// Check part files' `[expect]` blocks and physical validity, and robot descriptions' inertials by each engine's rule (for CI).
    #[command(after_help = CHECK_HELP)]
    Check(CheckArgs),
    /// Compare the mass properties of two part files, or of a part file and a robot description's link.
    #[command(after_help = DIFF_HELP)]
    Diff(DiffArgs),
    /// Write the body's `<inertial>` for URDF, SDFormat or MJCF, or put it in place of a link's.
    #[command(after_help = EXPORT_HELP)]
    Export(ExportArgs),
    /// Print the worked solution step by step, as a textbook writes it: each part's mass, centroid and inertia, the sums, the principal moments, H and T.
    #[command(after_help = explain::EXPLAIN_HELP)]
    Explain(explain::ExplainArgs),
    /// Draw the body as SVG: front, top, side and isometric views, each part's outline, the centre of mass, the principal axes and the inertia ellipsoid.
    #[command(after_help = RENDER_HELP)]
    Render(RenderArgs),
    /// List the materials `material = "NAME"` may name, with their densities.
    #[command(after_help = MATERIALS_HELP)]
    Materials(MaterialsArgs),
    /// Print a shell completion script (install: see `massprop man`).
    #[command(after_help = COMPLETIONS_HELP)]
    Completions(CompletionsArgs),
    /// Print the manual page (roff), for `man`.
    #[command(after_help = MAN_HELP)]
    Man,
    /// Print the part file's JSON Schema, for editors (`#:schema` in Taplo, Even Better TOML).
    #[command(after_help = SCHEMA_HELP)]
    Schema,
    /// The part-file reference: every shape, key, unit, material (`massprop help part-file`).
    #[command(name = "part-file", hide = true)]
    PartFile,
    /// Write a commented starter part file that `check` passes.
    #[command(after_help = INIT_HELP)]
    Init(InitArgs),
}

#[derive(Args, Debug)]
pub struct InitArgs {
    /// The new part file (`-` or none: standard output); never replaced if it exists.
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
}

#[derive(Args, Debug)]
pub struct CompletionsArgs {
    /// The shell to complete in.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
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

    #[command(flatten)]
    pub includes: IncludeArgs,
}

#[derive(Args, Debug)]
pub struct CheckArgs {
    /// Part files, and directories searched recursively for `*.toml` part
    /// files (`.gitignore` and `.ignore` honoured, hidden files skipped).
    #[arg(value_name = "PATH", required = true)]
    pub paths: Vec<std::path::PathBuf>,

    /// Search hidden files and directories too.
    #[arg(long)]
    pub hidden: bool,

    /// Skip paths matching GLOB in directory searches (gitignore syntax,
    /// relative to the directory named; repeatable), e.g. `--exclude
    /// 'fixtures/'`.
    #[arg(long, value_name = "GLOB")]
    pub exclude: Vec<String>,

    /// Name, on standard error, each file a directory's search passes over
    /// and why (a `*.toml` with none of massprop's top-level tables or
    /// keys, a materials file, an `*.xml` that is no robot description).
    #[arg(long)]
    pub verbose: bool,

    /// Print only what failed (failed expectations and validity checks,
    /// invalid files) and the summary line: no line per file that passed.
    /// The table's alone: the other formats are unchanged.
    #[arg(short = 'q', long)]
    pub quiet: bool,

    /// Write the output to FILE instead of standard output, atomically
    /// (through a temporary file and a rename): a failed or interrupted run
    /// leaves FILE as it was. `-o -` is standard output.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    /// Write the computed values into each file's `[expect]` entries first,
    /// keeping tolerances (adding defaults where missing), bounds, comments
    /// and formatting; files that cannot be parsed are left untouched.
    #[arg(long)]
    pub bless: bool,

    #[command(flatten)]
    pub accuracy: AccuracyArgs,

    /// Output format: one line per file or failure, one JSON document, or
    /// for CI: GitHub annotations, JUnit XML or SARIF.
    #[arg(long, value_enum, default_value_t)]
    pub format: CheckFormat,

    /// Robot descriptions: the engines whose rules each inertial is checked
    /// by (repeatable).
    #[arg(long, value_enum, value_name = "ENGINE", default_value = "all")]
    pub engine: Vec<EngineArg>,

    /// Robot descriptions: the directory an SDFormat `<include>`'s
    /// `model://NAME` names (repeatable), as `report`'s.
    #[arg(long, value_name = "NAME=DIR")]
    pub package: Vec<String>,

    #[command(flatten)]
    pub axes: AxesArgs,

    #[command(flatten)]
    pub includes: IncludeArgs,
}

#[derive(Args, Debug)]
pub struct DiffArgs {
    /// The old part file (`-` reads standard input).
    #[arg(value_name = "OLD")]
    pub old: String,

    /// The new part file (`-` reads standard input; not both).
    #[arg(value_name = "NEW")]
    pub new: String,

    /// When OLD or NEW is a robot description (URDF, SDFormat, MJCF): the
    /// link (MJCF body) whose inertial is compared.
    #[arg(long, value_name = "NAME", visible_alias = "body")]
    pub link: Option<String>,

    /// With a robot description: the link frame's origin in the part
    /// file's frame, overriding `[analysis].about`: x,y,z in the file's
    /// length unit, or with units.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub about: Option<String>,

    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,

    /// Write the output to FILE instead of standard output, atomically
    /// (through a temporary file and a rename): a failed or interrupted run
    /// leaves FILE as it was. `-o -` is standard output.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    /// Relative tolerance: a value counts as changed when it moves by more
    /// than this fraction of its scale (`1e-6`, or a percentage: `1%`).
    #[arg(
        long,
        value_name = "REL",
        default_value = "1e-9",
        value_parser = parse_fraction,
        allow_hyphen_values = true
    )]
    pub tol: f64,

    /// Fail (exit status 1) when parts were added, removed or changed by
    /// name, too: without it only the whole body's mass properties decide,
    /// and a renamed part is reported but passes.
    #[arg(long)]
    pub names: bool,

    #[command(flatten)]
    pub robot: robot::RobotArgs,

    #[command(flatten)]
    pub accuracy: AccuracyArgs,

    #[command(flatten)]
    pub axes: AxesArgs,

    #[command(flatten)]
    pub includes: IncludeArgs,
}

#[derive(Args, Debug)]
pub struct ExportArgs {
    /// The part file (`-` reads standard input).
    #[arg(value_name = "FILE")]
    pub file: String,

    /// The robot description format (with `--update`, the file tells it).
    #[arg(
        long,
        value_enum,
        value_name = "FORMAT",
        required_unless_present_any = ["update", "from_geometry"]
    )]
    pub to: Option<RobotFormat>,

    /// MJCF: `diaginertia` (the principal moments) and `quat` (the
    /// principal axes) instead of `fullinertia`.
    #[arg(long)]
    pub principal: bool,

    /// Export one sub-assembly (an `include`, by its name) alone.
    #[arg(long, value_name = "NAME")]
    pub only: Option<String>,

    /// The link frame's origin in the part file's frame, overriding
    /// `[analysis].about`: x,y,z in the file's length unit, or with units.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub about: Option<String>,

    #[command(flatten)]
    pub axes: AxesArgs,

    /// Replace a link's inertial in this URDF, SDFormat or MJCF file,
    /// leaving every other byte as it was.
    #[arg(long, value_name = "ROBOT_FILE", conflicts_with = "output")]
    pub update: Option<std::path::PathBuf>,

    /// The link (MJCF: body) whose inertial `--update` replaces.
    #[arg(long, value_name = "NAME", visible_alias = "body")]
    pub link: Option<String>,

    #[command(flatten)]
    pub geometry: robot::GeometryArgs,

    /// With `--update`: print the change as a unified diff; write nothing.
    #[arg(long, requires = "update")]
    pub dry_run: bool,

    /// Write the element to FILE instead of standard output, atomically
    /// (`-o -`: standard output).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    #[command(flatten)]
    pub accuracy: AccuracyArgs,

    #[command(flatten)]
    pub includes: IncludeArgs,
}

/// `export --to`'s values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RobotFormat {
    /// URDF: `<inertial>` with `<origin>`, `<mass>` and `<inertia ixx … izz>`
    Urdf,
    /// SDFormat: `<inertial>` with `<pose>`, `<mass>` and `<inertia>`, `<ixx>`…
    Sdf,
    /// MJCF: `<inertial pos mass fullinertia>` (or diaginertia and quat)
    Mjcf,
}

impl RobotFormat {
    fn format(self) -> crate::robot::Dialect {
        match self {
            RobotFormat::Urdf => crate::robot::Dialect::Urdf,
            RobotFormat::Sdf => crate::robot::Dialect::Sdf,
            RobotFormat::Mjcf => crate::robot::Dialect::Mjcf,
        }
    }
}

/// `check --engine`'s values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum EngineArg {
    /// MuJoCo's compiler (mjCBody::Compile)
    Mujoco,
    /// Gazebo: gz-math MassMatrix3::IsValid, as libsdformat applies it
    Gazebo,
    /// Drake: SpatialInertia::IsPhysicallyValid
    Drake,
    /// All three (the default)
    All,
}

/// The engines `--engine` names, each once, in `Engine::ALL`'s order.
fn engines(args: &[EngineArg]) -> Vec<crate::robot::engine::Engine> {
    use crate::robot::engine::Engine;
    Engine::ALL
        .into_iter()
        .filter(|e| {
            args.iter().any(|a| {
                *a == EngineArg::All
                    || matches!(
                        (a, e),
                        (EngineArg::Mujoco, Engine::Mujoco)
                            | (EngineArg::Gazebo, Engine::Gazebo)
                            | (EngineArg::Drake, Engine::Drake)
                    )
            })
        })
        .collect()
}

#[derive(Args, Debug)]
pub struct ReportArgs {
    #[command(flatten)]
    pub body: BodyArgs,

    /// Every table: besides the short report's mass, centre of mass,
    /// inertia, principal moments and axes (and H, T, α, M), the radii of
    /// gyration, the tensors about the reference point, the precision used,
    /// a row per part and per sub-assembly, and the idealisation. JSON
    /// always has everything.
    #[arg(long)]
    pub full: bool,

    /// Reference point, overriding `[analysis].about` (the short report then
    /// shows the tensors about it): x,y,z in the file's length unit, or with
    /// units, e.g. "0,0,10 mm".
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

    // NOTE: issue 35's flags (`cases`), one block.
    /// Velocity of the reference point, overriding `[analysis].velocity`:
    /// x,y,z in the report axes, in the file's length unit per second, or
    /// with units, e.g. "0,0,3 m/s". Needs ω; adds the mass centre's
    /// velocity, the linear momentum and the translational kinetic energy.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub velocity: Option<String>,

    #[command(flatten)]
    pub axes: AxesArgs,

    #[command(flatten)]
    pub includes: IncludeArgs,

    #[command(flatten)]
    pub uncertainty: uncertainty::UncertaintyArgs,

    #[command(flatten)]
    pub robot: robot::RobotArgs,

    #[command(flatten)]
    pub cases: cases::CaseArgs,
}

/// What every command that reports one body takes: the file, the output
/// and how the body is computed (`report`, `budget`).
#[derive(Args, Debug)]
pub struct BodyArgs {
    /// The part file (`-` reads standard input).
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,

    /// Write the output to FILE instead of standard output, atomically
    /// (through a temporary file and a rename): a failed or interrupted run
    /// leaves FILE as it was. `-o -` is standard output.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<String>,

    /// Sign convention of products of inertia in the output.
    #[arg(long, value_enum, default_value_t)]
    pub products: Products,

    /// Report one sub-assembly (an `include`, by its name) alone, in the
    /// file's frame.
    #[arg(long, value_name = "NAME")]
    pub only: Option<String>,

    #[command(flatten)]
    pub accuracy: AccuracyArgs,
}

impl BodyArgs {
    /// `report`'s options (which `budget` takes too), with the
    /// `[analysis]` overrides and the includes the command has.
    fn options(&self, overrides: Overrides, includes: &IncludeArgs) -> commands::report::Options {
        commands::report::Options {
            file: self.file.clone(),
            format: self.format,
            output: self.output.clone(),
            settings: Settings {
                products: self.products,
                accuracy: self.accuracy.accuracy(),
                only: self.only.clone(),
                includes: includes.includes(),
                overrides,
                uncertainty: None,
                predicted: false,
            },
            full: false,
            configuration: Default::default(),
            cases: Default::default(),
        }
    }
}

#[derive(Args, Debug)]
pub struct BudgetArgs {
    #[command(flatten)]
    pub body: BodyArgs,

    #[command(flatten)]
    pub axes: AxesArgs,

    #[command(flatten)]
    pub includes: IncludeArgs,
}

impl ValueEnum for Format {
    fn value_variants<'a>() -> &'a [Self] {
        &[Format::Table, Format::Json]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            Format::Table => {
                PossibleValue::new("table").help("Tables for people, in the file's units")
            }
            Format::Json => PossibleValue::new("json")
                .help("One JSON object in SI units (its keys: JSON OUTPUT in `massprop man`)"),
            // `check`'s alone (`CheckFormat`).
            Format::Github | Format::Junit | Format::Sarif => return None,
        })
    }
}

/// `check`'s formats: the two of every command and those of CI systems.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct CheckFormat(pub Format);

impl ValueEnum for CheckFormat {
    fn value_variants<'a>() -> &'a [Self] {
        &[
            CheckFormat(Format::Table),
            CheckFormat(Format::Json),
            CheckFormat(Format::Github),
            CheckFormat(Format::Junit),
            CheckFormat(Format::Sarif),
        ]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self.0 {
            Format::Table => PossibleValue::new("table")
                .help("`FILE:LINE:COL: error: …` per failure, `FILE: ok` per file"),
            Format::Json => Format::Json.to_possible_value()?,
            Format::Github => PossibleValue::new("github")
                .help("GitHub Actions annotations (`::error file=…,line=…::…`)"),
            Format::Junit => {
                PossibleValue::new("junit").help("JUnit XML: a test suite per file, as nextest's")
            }
            Format::Sarif => PossibleValue::new("sarif").help("SARIF 2.1.0, for code scanning"),
        })
    }
}

impl ValueEnum for Products {
    fn value_variants<'a>() -> &'a [Self] {
        &[Products::Tensor, Products::Positive]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            Products::Tensor => {
                PossibleValue::new("tensor").help("Tensor entries: I_xy = −∫xy dm (the default)")
            }
            Products::Positive => {
                PossibleValue::new("positive").help("CAD and Meriam convention: I_xy = +∫xy dm")
            }
        })
    }
}

impl Cli {
    /// What was typed, as the library's options.
    pub fn request(&self) -> Request {
        match &self.command {
            Command::Report(a) => {
                let mut options = a.body.options(
                    Overrides {
                        about: a.about.clone(),
                        omega: a.omega.clone(),
                        alpha: a.alpha.clone(),
                        velocity: a.velocity.clone(),
                        axes: a.axes.axes.clone(),
                    },
                    &a.includes,
                );
                // Checked as the command line was parsed (`check_rules`).
                options.settings.uncertainty = a.uncertainty.method().ok().flatten();
                options.full = a.full;
                options.configuration = a.robot.configuration(&a.includes.include_root);
                options.cases = a.cases.selection();
                Request::Report(options)
            }
            Command::Budget(a) => Request::Budget(a.body.options(
                Overrides {
                    axes: a.axes.axes.clone(),
                    ..Default::default()
                },
                &a.includes,
            )),
            Command::Check(a) => Request::Check(commands::check::Options {
                paths: a.paths.clone(),
                output: a.output.clone(),
                bless: a.bless,
                accuracy: a.accuracy.accuracy(),
                format: a.format.0,
                axes: a.axes.axes.clone(),
                includes: a.includes.includes(),
                search: commands::check::Search {
                    hidden: a.hidden,
                    exclude: a.exclude.clone(),
                    verbose: a.verbose,
                },
                engines: engines(&a.engine),
                quiet: a.quiet,
                packages: a.package.clone(),
            }),
            Command::Export(a) => Request::Export(commands::export::Options {
                file: a.file.clone(),
                to: a.to.map(RobotFormat::format),
                principal: a.principal,
                settings: Settings {
                    accuracy: a.accuracy.accuracy(),
                    only: a.only.clone(),
                    includes: a.includes.includes(),
                    overrides: Overrides {
                        about: a.about.clone(),
                        axes: a.axes.axes.clone(),
                        ..Default::default()
                    },
                    ..Settings::default()
                },
                update: a.update.clone().zip(a.link.clone()),
                dry_run: a.dry_run,
                output: a.output.clone(),
                from_geometry: a
                    .geometry
                    .options(a.link.clone(), a.update.clone(), a.dry_run),
            }),
            Command::Diff(a) => Request::Diff(commands::diff::Options {
                old: a.old.clone(),
                new: a.new.clone(),
                format: a.format,
                output: a.output.clone(),
                tol: a.tol,
                names: a.names,
                accuracy: a.accuracy.accuracy(),
                axes: a.axes.axes.clone(),
                about: a.about.clone(),
                link: a.link.clone(),
                includes: a.includes.includes(),
                configuration: a.robot.configuration(&a.includes.include_root),
            }),
            Command::Render(a) => Request::Render(a.options()),
            Command::Explain(a) => Request::Explain(a.options()),
            Command::Materials(a) => Request::Materials(commands::materials::Options {
                file: a.file.clone(),
                format: a.format,
                includes: a.includes.includes(),
            }),
            Command::Completions(a) => Request::Text(completions(a.shell)),
            Command::Man => Request::Text(man_page()),
            Command::PartFile => Request::Text(reference::text()),
            Command::Schema => Request::Text(crate::model::schema::text()),
            Command::Init(a) => Request::Init(commands::init::Options {
                file: a.file.clone(),
            }),
        }
    }
}

/// The completion script for `shell`, from the command line's definition.
fn completions(shell: clap_complete::Shell) -> String {
    use clap::CommandFactory;
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "massprop", &mut out);
    String::from_utf8(out).expect("invariant: a completion script is UTF-8")
}

/// The manual page in roff: the command and each subcommand's options,
/// from the command line's definition.
fn man_page() -> String {
    use clap::CommandFactory;
    let command = Cli::command();
    let mut out = Vec::new();
    let man = clap_mangen::Man::new(command.clone());
    man.render(&mut out)
        .expect("invariant: writing to memory does not fail");
    // Each subcommand as a section of its own, as git's and cargo's pages
    // list theirs.
    for sub in command.get_subcommands().filter(|s| s.get_name() != "help") {
        let name = format!("massprop-{}", sub.get_name());
        let page = clap_mangen::Man::new(sub.clone()).title(name);
        page.render(&mut out)
            .expect("invariant: writing to memory does not fail");
    }
    let mut page = String::from_utf8(out).expect("invariant: a man page is UTF-8");
    page.push_str(&reference::json_section(include_str!("../docs/json.md")));
    page.push_str(&reference::roff());
    page
}

/// `--axes`, of every command that computes a body.
#[derive(Args, Debug, Clone, Default)]
pub struct AxesArgs {
    /// The axes to report in, overriding `[analysis].axes`: their x and y
    /// directions in the file's frame, "x=1,0,0;y=0,-1,0" (z = x × y), or a
    /// rotation of the file's axes: "quaternion=w,x,y,z",
    /// "axis=0,0,1;degrees=90", "intrinsic=zyx;degrees=a,b,c". ω and α are
    /// read in them.
    #[arg(long, value_name = "AXES", allow_hyphen_values = true)]
    pub axes: Option<String>,
}

/// How far includes may reach; every command that reads part files takes it.
#[derive(Args, Debug, Clone, Default)]
pub struct IncludeArgs {
    /// Allow `include`s from this directory tree too (repeatable). By
    /// default an included file must lie, after following symlinks, inside
    /// the directory of the part file that names it at the top, or the
    /// working directory.
    #[arg(long = "include-root", value_name = "DIR")]
    pub include_root: Vec<std::path::PathBuf>,

    /// The directory that includes in a file read from standard input or a
    /// pipe are relative to (`massprop diff <(git show HEAD:sat.toml)
    /// sat.toml --base-dir .`); without it such a file may not include.
    #[arg(long = "base-dir", value_name = "DIR")]
    pub base_dir: Option<std::path::PathBuf>,

    /// Override a parameter of the part file's `[params]` (repeatable):
    /// `--set leg="750 mm"`, `--set n=24`, `--set d="2 * r"`. VALUE is a
    /// number or a quantity string, which may use the file's other
    /// parameters; NAME must be one the file defines. Included files take
    /// their parameters from `params` on the include, not from `--set`.
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<String>,
}

impl IncludeArgs {
    fn includes(&self) -> crate::model::Includes {
        crate::model::Includes {
            roots: self.include_root.clone(),
            base_dir: self.base_dir.clone(),
            set: self.set.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    /// `--rtol`'s default is written as users write it ("1e-12", not
    /// 0.000000000001) and is the library's own.
    #[test]
    fn the_default_rtol_is_the_librarys() {
        let cli = Cli::try_parse_from(["massprop", "report", "f.toml"]).unwrap();
        let Command::Report(a) = cli.command else {
            panic!("a report")
        };
        assert_eq!(
            a.body.accuracy.rtol,
            crate::analysis::summary::accuracy::DEFAULT_RTOL
        );
    }
}
