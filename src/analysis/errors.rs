//! Why a summary could not be formed from valid parts, and which part or
//! input to blame: the error at the `[[part]]`, `about`, `omega` or
//! `alpha` that made a result overflow, or at the cut-out that removes
//! more than the body has.

use crate::diag::{Diagnostic, Source};
use crate::la::Vector3;
use crate::model::{Analysis, Model};
use crate::part::SiFactors;

/// Why a summary could not be formed from valid parts.
#[derive(Debug, Clone, PartialEq)]
pub enum SummaryError {
    /// A result overflowed f64: every part is representable, but a sum,
    /// the conversion to SI, or a product with `about`, ω or α is not.
    NotFinite { what: &'static str, blame: Blame },
    /// Cut-outs left a body that is not physical: no mass, or a second
    /// moment negative along some direction. `cut` is the index in
    /// `model.parts` of the cut-out that removes the most, which the
    /// message names.
    NotPhysical { message: String, cut: usize },
}

/// What a result that overflows is blamed on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Blame {
    /// The parts, through a sum of what each contributes: the one that
    /// contributes most is named.
    Parts(Contribution),
    /// The reference point (`about`), through m·d².
    About,
    /// The angular velocity (H, T) or acceleration (M).
    Omega,
    Alpha,
    /// The reference point's velocity (G, T, H about the point).
    Velocity,
}

impl std::fmt::Display for SummaryError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SummaryError::NotFinite { what, .. } => {
                write!(f, "the {what} overflows the range of f64")
            }
            SummaryError::NotPhysical { message, .. } => f.write_str(message),
        }
    }
}

/// What each part adds to a sum that overflows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Contribution {
    /// m (the total mass).
    Mass,
    /// m·c (the centre of mass).
    FirstMoment,
    /// m·d² about the centre of mass and its own tensor (the inertia).
    SecondMoment,
}

const WRONG_UNITS: &str = "are sizes, masses or offsets in the wrong units?";
const CUT_OUT_HELP: &str = "a cut-out removes material the body has: it lies inside the parts it is cut from, with at most their mass; are its size, place and units right?";

impl SummaryError {
    /// The error as a diagnostic at its cause in `source`: the `[[part]]`
    /// that contributes most to a sum that overflows, or the `[analysis]`
    /// key whose value makes a result overflow (or its flag, when the
    /// command line gave it: `analysis` is what `summarize` was given).
    pub fn diagnostic(&self, model: &Model, analysis: &Analysis, source: &Source) -> Diagnostic {
        let message = self.to_string();
        let blame = match self {
            SummaryError::NotFinite { blame, .. } => *blame,
            SummaryError::NotPhysical { cut, .. } => {
                return match model.part(*cut) {
                    Some(p) => source
                        .error(p.span.clone(), message)
                        .label(match p.assembly.first() {
                            None => "this cut-out".to_string(),
                            Some(a) => format!("the sub-assembly `{a}` with the cut-out"),
                        })
                        .help(CUT_OUT_HELP),
                    None => Diagnostic::file(&source.name, message).help(CUT_OUT_HELP),
                };
            }
        };
        let at =
            |span: &Option<std::ops::Range<usize>>, flag: &str, label: &str, help: &str| match span
            {
                Some(span) => source.error(span.clone(), &message).label(label).help(help),
                None => Diagnostic::file(
                    &source.name,
                    format!("{message} with the `--{flag}` given on the command line"),
                )
                .help(help),
            };
        match blame {
            Blame::Parts(kind) => match largest_contributor(model, kind) {
                Some(p) => source
                    .error(p.span.clone(), &message)
                    .label(format!(
                        "`{}` contributes the most",
                        crate::diag::shorten(&p.name)
                    ))
                    .help(WRONG_UNITS),
                None => Diagnostic::file(&source.name, message).help(WRONG_UNITS),
            },
            Blame::About => at(
                &analysis.about_span,
                "about",
                "this far from the centre of mass",
                "m·d², d the distance from the centre of mass, exceeds the largest f64 in SI units; is `about` in the file's length unit?",
            ),
            Blame::Omega => at(
                &analysis.omega_span,
                "omega",
                "too fast for this body",
                "H = I·ω and T = ½ ωᵀIω exceed the largest f64 in SI units; is ω in rad/s (or written as \"N rpm\")?",
            ),
            Blame::Alpha => at(
                &analysis.alpha_span,
                "alpha",
                "with this `omega`, too large for this body",
                "M = I·α + ω × I·ω exceeds the largest f64 in SI units; are α and ω in the intended units?",
            ),
            Blame::Velocity => at(
                &analysis.velocity_span,
                "velocity",
                "too fast for this body",
                "G = m·v̄ and T = ½ m v̄·v̄ exceed the largest f64 in SI units; is `velocity` in the file's length unit per second (or written as \"N m/s\")?",
            ),
        }
    }
}

/// The part whose contribution is largest: its |mass|, |m|·|c|, or the
/// larger of |m|·d² (d from the centre of mass) and the trace of its own
/// tensor, compared by logarithm so that none of them overflows.
fn largest_contributor(model: &Model, kind: Contribution) -> Option<crate::part::Part> {
    let factors = SiFactors::of(model.units);
    let ln_norm = |v: Vector3<f64>| {
        // ln |v| without overflow: scale by the largest component.
        let big = v.amax();
        if big == 0.0 {
            f64::NEG_INFINITY
        } else {
            big.ln() + (v / big).norm().ln()
        }
    };
    let mut total = 0.0;
    model.each_body_part(&mut |p| total += p.si_in(&factors).mass);
    let mut com = Vector3::zeros();
    if total.is_finite() && total != 0.0 {
        model.each_body_part(&mut |p| {
            let si = p.si_in(&factors);
            com += si.center * (si.mass / total);
        });
    }
    let score = |p: &crate::part::PartSi| {
        let ln_m = p.mass.abs().ln();
        match kind {
            Contribution::Mass => ln_m,
            Contribution::FirstMoment => ln_m + ln_norm(p.center),
            Contribution::SecondMoment => {
                // (c − com) / 2 cannot overflow; add ln 2 back.
                let d = ln_norm(p.center / 2.0 - com / 2.0) + std::f64::consts::LN_2;
                let own = p.second_moment.trace().abs().ln();
                (ln_m + 2.0 * d).max(own)
            }
        }
    };
    // Of equal scores, the last.
    let (mut best, mut index) = (None::<(f64, usize)>, 0);
    model.each_body_part(&mut |p| {
        let s = score(&p.si_in(&factors));
        if !s.is_nan() && best.is_none_or(|(b, _)| s >= b) {
            best = Some((s, index));
        }
        index += 1;
    });
    model.part(best?.1)
}
