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
    pub fn configuration(&self) -> crate::commands::robot::Configuration {
        crate::commands::robot::Configuration {
            joints: self.joints.clone(),
            sweep: self.sweep.clone(),
        }
    }
}
