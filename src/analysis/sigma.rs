//! The uncertainty of a body as it is reported (JSON `uncertainty`): each
//! output's nominal value and σ, its largest contributors, the covariance,
//! the chance an expectation is missed. `uncertainty` computes it;
//! `summary::Summary` carries it, without depending on how it is computed.

use serde::Serialize;

/// One output's uncertainty.
#[derive(Debug, Clone, Serialize)]
pub struct Output {
    /// As `[expect]` names it: `mass`, `center_of_mass.z`, …
    pub quantity: &'static str,
    /// SI: kg, m or kg·m².
    pub nominal: f64,
    /// One standard deviation, SI.
    pub sigma: f64,
    /// Monte Carlo: the samples' mean and 5th, 50th and 95th percentiles.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub percentiles: Option<[f64; 3]>,
    /// The sources that contribute most to its variance, largest first.
    pub contributors: Vec<Contributor>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Contributor {
    /// `PART: KEY ± AMOUNT`, the part by its path.
    pub source: String,
    /// Its share of the variance, from 0 to 1.
    pub share: f64,
}

/// The chance that an `[expect]` entry's value falls outside its bounds.
#[derive(Debug, Clone, Serialize)]
pub struct Exceed {
    pub quantity: String,
    pub line: usize,
    pub column: usize,
    pub probability: f64,
}

/// The uncertainty of a body: JSON `uncertainty`.
#[derive(Debug, Clone, Serialize)]
pub struct Uncertainty {
    /// `linear` or `montecarlo`.
    pub method: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Monte Carlo: samples in which a part's size, radius, density or
    /// mass fell to zero or below, or its inner radius past its outer
    /// (left out of the statistics).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rejected: Option<usize>,
    /// Independent sources of uncertainty (see the module's comment).
    pub sources: usize,
    pub outputs: Vec<Output>,
    /// The covariance of the outputs, rows and columns in `outputs`'
    /// order, SI.
    pub covariance: Vec<Vec<f64>>,
    /// The predicted body's (a file with a weight statement that `check`
    /// holds: `predicted_*` expectations or `[budget] limit`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub predicted: Option<Predicted>,
    /// For each `[expect]` entry on an output, and `[budget] limit`.
    pub exceed: Vec<Exceed>,
    /// Principal moments equal within tolerance: their derivatives are
    /// not defined, and their σ is first order in a direction the
    /// tolerances choose (the axis the nominal solution picked).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub equal_moments: Vec<usize>,
}

/// The predicted body's uncertainty: its outputs (`PREDICTED`) and their
/// covariance.
#[derive(Debug, Clone, Serialize)]
pub struct Predicted {
    pub outputs: Vec<Output>,
    pub covariance: Vec<Vec<f64>>,
}
