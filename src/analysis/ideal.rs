//! What the model's simplifications cost, for the report:
//!
//! - the idealisation: how much each principal moment would change if the
//!   thin plates that give their real `thickness` were solid boxes and the
//!   slender rods that give their `diameter` solid cylinders (same mass,
//!   centroid and orientation), all together and one part at a time;
//! - each part's share of each principal moment, so that parts too small
//!   to matter at the user's tolerance show up.
//!
//! Neither changes the composition: both are read off the composed body.

use super::errors::{Blame, Contribution, SummaryError};
use crate::compose::{self, Precision, Principal};
use crate::mass::Body;
use crate::model::Model;
use crate::numeric::{DD, M3, Real, pow2_scaled};
use crate::part::{Part, Solid};
use crate::thresholds::{NEGLIGIBLE_ROUNDOFFS, ROUNDING_CHANGE};
use serde::Serialize;

/// The fraction of the largest principal moment below which a moment counts
/// as zero, for the arithmetic that produced it.
fn negligible(precision: Precision) -> f64 {
    NEGLIGIBLE_ROUNDOFFS
        * match precision {
            Precision::Standard => <f64 as Real>::EPS,
            Precision::Extended => <DD as Real>::EPS,
        }
}

/// The JSON `idealisation`: present when at least one part gives its real
/// size. SI.
#[derive(Debug, Clone, Serialize)]
pub struct Idealisation {
    /// Principal moments about the centre of mass (kg·m², ascending) with
    /// every part that gives its real size made solid.
    pub principal_moments_solid: [f64; 3],
    /// (solid − idealised) / idealised for each principal moment, ascending
    /// (the k-th moment of each; not necessarily about the same axis).
    /// `None` (JSON null) where the idealised moment is zero to rounding.
    pub relative_change: [Option<f64>; 3],
    /// One entry per part that gives its real size, in file order.
    pub parts: Vec<IdealPart>,
}

#[derive(Debug, Clone, Serialize)]
pub struct IdealPart {
    pub name: String,
    /// `"box"` for a plate, `"cylinder"` for a rod.
    pub solid: Solid,
    /// As `Idealisation::relative_change`, with this part alone solid.
    pub relative_change: [Option<f64>; 3],
}

/// What making `part` solid adds to its second moment ∫ρρᵀ dm about its
/// centroid (file axes and units); `size` is the plate's thickness or the
/// rod's diameter. Mass and centroid are the same, so the composite's centre
/// of mass does not move and its second moment grows by exactly this.
///
/// NOTE: the derivations. Plate → box a × b × t: the box is the plate spread
/// evenly through its thickness, symmetric about the mid-plane, so in local
/// axes (z the normal n) ∫x² dm, ∫y² dm and the products are the plate's,
/// and ∫z² dm is that of a uniform segment of length t, m t²/12, where the
/// plate has 0: the extra is (m t²/12) n nᵀ. Rod → cylinder of radius
/// r = d/2: uniform over the disc, ∫(x² + y²) dm = m/(πr²) ∫₀ʳ ρ² 2πρ dρ =
/// m r²/2, so ∫x² dm = ∫y² dm = m r²/4 by symmetry; ∫xy dm = 0, ∫z² dm =
/// m L²/12 as for the rod, and products with z vanish by symmetry about the
/// mid-plane: the extra is (m r²/4)(E − u uᵀ), u the unit axis. (Then
/// I_zz = m r²/2 and I_xx = m(3r² + L²)/12, the textbook cylinder.)
pub fn solid_extra(part: &Part, solid: Solid, size: f64) -> M3<DD> {
    let m: DD = part.mass();
    let w = pow2_scaled(
        part.spec
            .place
            .real_size_direction()
            .expect("only plates and rods give a real size"),
    );
    let ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    let s = DD::of(size);
    match solid {
        Solid::Box => {
            let k = m * s * s / DD::of(12.0);
            std::array::from_fn(|i| std::array::from_fn(|j| k * (w[i] * w[j] / ww)))
        }
        Solid::Cylinder => {
            let k = m * s * s / DD::of(16.0);
            std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    if i == j {
                        // 1 − wᵢ²/|w|² as a sum: no cancellation when w ≈ eᵢ.
                        let (a, b) = (w[(i + 1) % 3], w[(i + 2) % 3]);
                        k * ((a * a + b * b) / ww)
                    } else {
                        -(k * (w[i] * w[j] / ww))
                    }
                })
            })
        }
    }
}

fn plus(a: &M3<DD>, b: &M3<DD>) -> M3<DD> {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] + b[i][j]))
}

/// (solid − ideal) / ideal for each principal moment; `None` where the
/// idealised moment is zero to rounding.
///
/// NOTE: the solid adds a positive semi-definite term to the inertia
/// tensor (tr(X)E − X for a PSD second moment X), so by Weyl's inequality no
/// sorted moment decreases, and a small negative change is rounding, shown
/// as 0. (A cut-out made solid removes such a term: its changes are
/// negative, and shown.)
fn relative_change(solid: &Principal, ideal: &Principal, zero: f64) -> [Option<f64>; 3] {
    let top = ideal.moments[2].f64();
    std::array::from_fn(|k| {
        let i = ideal.moments[k];
        (i.f64() > zero * top).then(|| {
            let change = ((solid.moments[k] - i) / i).f64();
            if change < 0.0 && change > -ROUNDING_CHANGE {
                0.0
            } else {
                change
            }
        })
    })
}

/// The idealisation report for `model`, composed as `body` with principal
/// moments `ideal` (file units); `f_inertia` converts inertia to SI. `None`
/// when no part gives its real size.
pub fn idealisation(
    model: &Model,
    body: &Body,
    ideal: &Principal,
    precision: Precision,
    f_inertia: DD,
) -> Result<Option<Idealisation>, SummaryError> {
    if !model.has_real_sizes {
        return Ok(None);
    }
    let zero = negligible(precision);
    // `None` only for a principal moment beyond f64 (finite input).
    let principal = |c: &M3<DD>| {
        compose::principal(c, precision).ok_or(SummaryError::NotFinite {
            what: "principal moments of the solid body",
            blame: crate::analysis::errors::Blame::Parts(
                crate::analysis::errors::Contribution::SecondMoment,
            ),
        })
    };
    let mut all = body.second_moment;
    let mut parts = Vec::new();
    let mut failed = Ok(());
    model.each_part(&mut |l| {
        let Some(r) = l.real else { return };
        if failed.is_err() {
            return;
        }
        let extra = solid_extra(l.part, r.solid, r.size);
        all = plus(&all, &extra);
        match principal(&plus(&body.second_moment, &extra)) {
            Ok(alone) => parts.push(IdealPart {
                name: l.part.name.clone(),
                solid: r.solid,
                relative_change: relative_change(&alone, ideal, zero),
            }),
            Err(e) => failed = Err(e),
        }
    });
    failed?;
    let solid = principal(&all)?;
    let moments = solid.moments.map(|m| (m * f_inertia).f64());
    if !moments.iter().all(|x| x.is_finite()) {
        return Err(SummaryError::NotFinite {
            what: "principal moments with the parts made solid",
            blame: Blame::Parts(Contribution::SecondMoment),
        });
    }
    Ok(Some(Idealisation {
        principal_moments_solid: moments,
        relative_change: relative_change(&solid, ideal, zero),
        parts,
    }))
}

/// Each part's share of each principal moment about the centre of mass:
/// aₖᵀ Iₚ aₖ / Iₖ, with Iₚ the part's inertia about the composite centre of
/// mass and aₖ the k-th principal axis. The shares of all parts sum to 1
/// for each k. `None` where the moment is zero to rounding (a lone rod's
/// axial moment): no share is defined.
///
/// NOTE: aₖᵀ I aₖ = tr C − aₖᵀ C aₖ = Σ_{j≠k} aⱼᵀ C aⱼ for orthonormal axes,
/// so each share is formed as a sum of the part's non-negative second
/// moments along the other two axes, with no cancellation; and C about the
/// composite centre is the part's own plus m d dᵀ, aⱼᵀ(m d dᵀ)aⱼ = m (aⱼ·d)²,
/// with d taken from the double-double centroid and centre, as `compose`
/// does, so parts far from the origin keep their digits. The sums are in
/// f64 whatever the precision (a share is a fraction to show, and this runs
/// for every part of every report), so the zero threshold is f64's: above
/// it the error of a share, a few roundoffs of the largest moment over Iₖ,
/// stays below 1e-3 of it.
#[derive(Debug, Clone)]
pub struct Shares {
    moments: [f64; 3],
    zero: f64,
    axes: [[f64; 3]; 3],
    com: [DD; 3],
}

impl Shares {
    /// The shares of the parts of `body`, of principal moments and axes
    /// `principal`.
    pub fn new(body: &Body, principal: &Principal) -> Shares {
        let moments = principal.moments.map(DD::f64);
        Shares {
            moments,
            zero: negligible(Precision::Standard) * moments[2],
            axes: principal.axes.map(|a| [a.x, a.y, a.z]),
            com: body.center_of_mass,
        }
    }

    /// The shares of the part `p`.
    pub fn of(&self, p: &Part) -> [Option<f64>; 3] {
        let m: f64 = p.mass();
        let c = p.centroid();
        let d: [f64; 3] = std::array::from_fn(|i| (c[i] - self.com[i]).f64());
        let own: M3<f64> = p.own_second_moment(m);
        let along: [f64; 3] = self.axes.map(|a| {
            let mut q = 0.0;
            for i in 0..3 {
                q += a[i] * a[i] * own[i][i];
                for j in i + 1..3 {
                    q += 2.0 * a[i] * a[j] * own[i][j];
                }
            }
            let ad = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
            // Exactly of the sign of m (negative for a cut-out);
            // rounding may leave a trace of the other sign.
            let q = if m >= 0.0 { q.max(0.0) } else { q.min(0.0) };
            q + (m * ad) * ad
        });
        std::array::from_fn(|k| {
            (self.moments[k] > self.zero)
                .then(|| (along[(k + 1) % 3] + along[(k + 2) % 3]) / self.moments[k])
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Source;

    fn model(text: &str) -> Model {
        Model::parse(&Source::new("t.toml", text)).unwrap_or_else(|d| panic!("{d}"))
    }

    fn extra_of(text: &str) -> M3<f64> {
        let m = model(text);
        let r = m.real_sizes()[0];
        solid_extra(&m.flattened()[r.part], r.solid, r.size).map(|row| row.map(DD::f64))
    }

    fn assert_close(a: &M3<f64>, b: &M3<f64>, scale: f64) {
        let tol = 8.0 * f64::EPSILON * scale;
        for i in 0..3 {
            for j in 0..3 {
                assert!((a[i][j] - b[i][j]).abs() <= tol, "{a:?} vs {b:?}");
            }
        }
    }

    #[test]
    fn a_plate_gains_m_t_squared_over_12_along_its_normal() {
        // Normal along y after a quarter turn about x.
        let e = extra_of(
            "[[part]]\nshape = \"plate\"\nmass = 3\nsize = [2, 1]\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 90 }\nthickness = 0.2\n",
        );
        let k = 3.0 * 0.04 / 12.0;
        assert_close(&e, &[[0.0; 3], [0.0, k, 0.0], [0.0; 3]], k);
    }

    #[test]
    fn a_plate_by_edges_takes_the_normal_from_their_cross_product() {
        // Edges in the plane x + y = const: normal (1, 1, 0)/√2.
        let e = extra_of(
            "[[part]]\nshape = \"plate\"\nmass = 6\ncorner = [1e9, 0, 0]\nedges = [[1e-3, -1e-3, 0], [0, 0, 5e3]]\nthickness = 1\n",
        );
        let k = 6.0 / 12.0 / 2.0;
        assert_close(&e, &[[k, k, 0.0], [k, k, 0.0], [0.0, 0.0, 0.0]], 2.0 * k);
    }

    #[test]
    fn a_rod_gains_m_r_squared_over_4_across_its_axis() {
        let e = extra_of(
            "[[part]]\nshape = \"rod\"\nmass = 2\nfrom = [0, 0, 0]\nto = [0, 0, 7]\ndiameter = 0.5\n",
        );
        let k = 2.0 * 0.25 * 0.25 / 4.0;
        assert_close(&e, &[[k, 0.0, 0.0], [0.0, k, 0.0], [0.0; 3]], k);
    }

    #[test]
    fn a_skew_rod_gains_the_projector_across_its_axis() {
        let e = extra_of(
            "[[part]]\nshape = \"rod\"\nmass = 4\nfrom = [1, 2, 3]\nto = [2, 4, 5]\ndiameter = 2\n",
        );
        // u = (1, 2, 2)/3, k = m r²/4 = 1: E − u uᵀ.
        let u = [1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0];
        let want: M3<f64> = std::array::from_fn(|i| {
            std::array::from_fn(|j| f64::from(u8::from(i == j)) - u[i] * u[j])
        });
        assert_close(&e, &want, 1.0);
    }

    #[test]
    fn thickness_and_diameter_are_kept_in_file_units() {
        let m = model(
            "units = { length = \"mm\" }\n[[part]]\nshape = \"plate\"\nmass = 1\nsize = [10, 10]\ncenter = [0, 0, 0]\nthickness = \"0.2 cm\"\n[[part]]\nshape = \"rod\"\nmass = 1\nlength = 10\ncenter = [0, 0, 0]\ndiameter = 3\n",
        );
        let rs = m.real_sizes();
        assert_eq!(rs.len(), 2);
        assert_eq!((rs[0].part, rs[0].solid, rs[0].size), (0, Solid::Box, 2.0));
        assert_eq!(
            (rs[1].part, rs[1].solid, rs[1].size),
            (1, Solid::Cylinder, 3.0)
        );
    }

    #[test]
    fn thickness_and_diameter_apply_only_to_plates_and_rods() {
        for (shape, key) in [
            ("box", "thickness"),
            ("box", "diameter"),
            ("rod", "thickness"),
            ("plate", "diameter"),
            ("point", "thickness"),
        ] {
            let place = match shape {
                "box" => "size = [1, 1, 1]\n",
                "plate" => "size = [1, 1]\n",
                "rod" => "length = 1\n",
                _ => "",
            };
            let text = format!(
                "[[part]]\nshape = \"{shape}\"\nmass = 1\n{place}center = [0, 0, 0]\n{key} = 0.1\n"
            );
            let err = Model::parse(&Source::new("t.toml", &text)).unwrap_err();
            assert!(
                err.to_string()
                    .contains(&format!("`{key}` does not apply to a {shape}")),
                "{err}"
            );
        }
    }

    #[test]
    fn a_non_positive_thickness_is_refused() {
        for t in ["0", "-1", "\"-2 mm\""] {
            let text = format!(
                "[[part]]\nshape = \"plate\"\nmass = 1\nsize = [1, 1]\ncenter = [0, 0, 0]\nthickness = {t}\n"
            );
            let err = Model::parse(&Source::new("t.toml", &text)).unwrap_err();
            assert!(
                err.to_string().contains("`thickness` must be positive"),
                "{err}"
            );
        }
    }
}
