//! `report`'s flags of uncertainty: `--uncertainty`, `--samples`,
//! `--seed`, and the rule between them.

use clap::{Args, ValueEnum};

/// `--uncertainty` and the Monte Carlo flags.
#[derive(Args, Debug, Clone)]
pub struct UncertaintyArgs {
    /// Propagate the file's tolerances (`"700 mm ± 0.5 mm"`) to the mass,
    /// centre of mass, inertia and principal moments: their standard
    /// deviations, covariance, main contributors and the chance of each
    /// `[expect]` entry to fail.
    #[arg(long = "uncertainty", value_enum, value_name = "METHOD")]
    pub method: Option<UncertaintyChoice>,

    /// Monte Carlo: how many samples, 2 to 10,000,000 [default: 10000].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(2..=10_000_000))]
    pub samples: Option<u64>,

    /// Monte Carlo: the seed; the same seed gives the same samples on any
    /// machine and number of cores [default: 1].
    #[arg(long, value_name = "S")]
    pub seed: Option<u64>,
}

/// `--uncertainty`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum UncertaintyChoice {
    /// First-order propagation with exact derivatives (automatic
    /// differentiation): standard deviations and covariance.
    Linear,
    /// Sampling of the tolerances: mean, σ and the 5/50/95 % percentiles.
    Montecarlo,
}

impl UncertaintyArgs {
    /// `--uncertainty` with `--samples` and `--seed`, which only Monte
    /// Carlo takes.
    pub(crate) fn method(&self) -> Result<Option<crate::analysis::uncertainty::Method>, String> {
        use crate::analysis::uncertainty::Method;
        match (self.method, self.samples, self.seed) {
            (Some(UncertaintyChoice::Montecarlo), n, s) => Ok(Some(Method::MonteCarlo {
                samples: n.unwrap_or(10_000) as usize,
                seed: s.unwrap_or(1),
            })),
            (Some(UncertaintyChoice::Linear), None, None) => Ok(Some(Method::Linear)),
            (None, None, None) => Ok(None),
            (choice, n, _) => Err(format!(
                "`{}` needs `--uncertainty montecarlo`{}",
                if n.is_some() { "--samples" } else { "--seed" },
                if choice.is_some() {
                    ", not `linear`"
                } else {
                    ""
                }
            )),
        }
    }

    /// The rules across `report`'s flags that clap cannot state.
    pub(crate) fn check_rules(&self) -> Result<(), String> {
        self.method().map(|_| ())
    }
}
