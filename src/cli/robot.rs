//! The flags that take a robot description as a whole body: `--joints`
//! and `--sweep` (`report`, `diff`).

use clap::Args;

#[derive(Args, Debug, Default)]
pub struct RobotArgs {
    /// A robot description's joint positions: `"shoulder=30deg,
    /// elbow=-0.5, slider=20 mm"`, a plain number SI (rad or m), or with
    /// its unit; unset joints at 0 (MJCF: their `ref`), mimic joints and
    /// MJCF joint equalities followed.
    #[arg(long, value_name = "JOINT=VALUE,…", allow_hyphen_values = true)]
    pub joints: Option<String>,

    /// A robot description's joint swept, `"elbow=-90deg..90deg:19"`
    /// (repeatable, one joint each; several make a grid): mass, centre of
    /// mass and inertia at every sample.
    #[arg(long, value_name = "JOINT=FROM..TO:COUNT", allow_hyphen_values = true)]
    pub sweep: Vec<String>,
}

impl RobotArgs {
    /// The configuration (`--package` and `--include-root`, where a
    /// robot's includes are found, are `IncludeArgs`').
    pub fn configuration(&self) -> crate::commands::robot::Configuration {
        crate::commands::robot::Configuration {
            joints: self.joints.clone(),
            sweep: self.sweep.clone(),
        }
    }
}

/// `export --from-geometry`'s flags.
#[derive(Args, Debug, Default)]
pub struct GeometryArgs {
    /// FILE is a robot description: compute each link's inertial from its
    /// `<collision>` or `<visual>` geometry (box, cylinder, sphere, capsule,
    /// ellipsoid, STL/OBJ meshes), summed per link, and print them (or
    /// write them with `--update`).
    #[arg(long, value_enum, value_name = "KIND")]
    pub from_geometry: Option<GeometryKind>,

    /// With `--from-geometry`: the density, kg/m³ (or with its unit, e.g.
    /// "1.2 g/cm^3").
    #[arg(long, value_name = "DENSITY", requires = "from_geometry")]
    pub density: Option<String>,

    /// With `--from-geometry`: a built-in material instead of `--density`.
    #[arg(long, value_name = "NAME", requires = "from_geometry")]
    pub material: Option<String>,
}

/// `--from-geometry`'s values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum GeometryKind {
    /// The `<collision>` elements
    Collision,
    /// The `<visual>` elements
    Visual,
}

impl GeometryArgs {
    /// The options, with `--link`, `--update` and `--dry-run` (export's).
    pub fn options(
        &self,
        link: Option<String>,
        update: Option<std::path::PathBuf>,
        dry_run: bool,
    ) -> Option<crate::commands::export::FromGeometry> {
        Some(crate::commands::export::FromGeometry {
            visual: self.from_geometry? == GeometryKind::Visual,
            density: self.density.clone(),
            material: self.material.clone(),
            link,
            update,
            dry_run,
        })
    }
}
