//! Whether cut-outs (`remove = true`) leave a physical body: checked
//! before anything is derived from the composed body, and, where they do
//! not, which cut-out to name.

use super::SummaryError;
use crate::la::{Matrix3, Vector3};
use crate::model::Model;
use crate::numeric::{M3, Real};
use crate::part::{Part, SiFactors};
use crate::thresholds::VALIDITY_RTOL;

/// With cut-outs (`remove = true`) the composed body can be impossible: no
/// mass left, or a second moment that is negative along some direction (a
/// cut-out reaching beyond the material it is cut from; its principal
/// moments then include a negative one or break the triangle inequality
/// I1 + I2 ≥ I3, which is the same thing). Checked before anything is
/// derived from the body, also when its second moment overflows f64 (a
/// cut-out placed far away), and said so, naming the cut-out that removes
/// the most, rather than reported.
pub(super) fn leave_a_body(
    model: &Model,
    body: &crate::mass::Body,
    mass: f64,
) -> Result<(), SummaryError> {
    // NOTE: a body with no cut-out anywhere is not walked at all.
    if !model.has_cut_outs() {
        return Ok(());
    }
    // Relative to the masses that cancel: what is left of equal and
    // opposite masses is rounding, not a body.
    let factors = SiFactors::of(model.units);
    // The cut-outs, the first and the heaviest, and the gross mass.
    let (mut cuts, mut index) = (0usize, 0usize);
    let (mut first, mut heaviest, mut heaviest_mass) = (0, 0, f64::NEG_INFINITY);
    let mut gross = 0.0;
    model.each_body_part(&mut |p| {
        let m = p.mass_si(&factors).abs();
        gross += m;
        if p.spec.removed {
            if cuts == 0 {
                first = index;
            }
            cuts += 1;
            if m > heaviest_mass {
                (heaviest, heaviest_mass) = (index, m);
            }
        }
        index += 1;
    });
    if cuts == 0 {
        return Ok(());
    }
    // "the cut-out `a` removes …", or "the 3 cut-outs remove …, `a` the most".
    let them = |worst: usize, what: &str| {
        // Quoted as messages quote names: a 2 MB name is cut.
        let part = model.part(worst).expect("a part of the body");
        let name = crate::diag::shorten(&part.name);
        match cuts {
            1 => format!("the cut-out `{name}` removes {what}"),
            n => format!("the {n} cut-outs remove {what}, `{name}` the most"),
        }
    };
    if !(mass > VALIDITY_RTOL * gross) {
        let worst = heaviest;
        return Err(SummaryError::NotPhysical {
            message: format!(
                "the total mass is {mass:.4e} kg of {gross:.4e} kg of parts: {}",
                them(worst, "all of the material")
            ),
            cut: worst,
        });
    }
    let scaled = std::cell::LazyCell::new(|| Scaled::of(model));
    let c = body.second_moment.map(|r| r.map(|x| x.f64()));
    // The composed second moment where it fits f64; else the same sum made
    // in scaled units, where it does (whether a matrix has a negative
    // eigenvalue does not depend on its scale).
    let c = if c.iter().flatten().all(|x| x.is_finite()) {
        c
    } else {
        scaled.total()
    };
    let big = c.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
    if !(big > 0.0 && big.is_finite()) {
        // A body of point masses at one place, or a sum that overflows even
        // scaled: the checks after this one say what it is.
        return Ok(());
    }
    let Some((lam, v)) = crate::eigen::jacobi(c.map(|r| r.map(|x| x / big))) else {
        return Ok(());
    };
    let top = lam.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let k = (0..3).fold(0, |k, i| if lam[i] < lam[k] { i } else { k });
    if !(lam[k] < -VALIDITY_RTOL * top) {
        return Ok(());
    }
    // The cut-out that removes the most along the direction.
    let u = Vector3::new(v[0][k], v[1][k], v[2][k]);
    // Shown with its largest component positive, and no `-0.000`.
    let u = if u[u.iamax()] < 0.0 { -u } else { u };
    let shown = u.map(|x| if x.abs() < 5e-4 { 0.0 } else { x });
    // The first of the cut-outs that remove the most.
    let (mut worst, mut least, mut index) = (first, f64::INFINITY, 0);
    model.each_body_part(&mut |p| {
        if p.spec.removed {
            let a = scaled.along(p, &u);
            if a < least || (index == first && !(least <= a)) {
                (worst, least) = (index, a);
            }
        }
        index += 1;
    });
    Err(SummaryError::NotPhysical {
        message: format!(
            "the body is not physical: its second moment along ({:.3}, {:.3}, {:.3}) is negative; {}",
            shown.x,
            shown.y,
            shown.z,
            them(worst, "more material along it than the body has")
        ),
        cut: worst,
    })
}

/// The parts in units scaled so that no sum of their second moments
/// overflows: masses by the largest |m|, lengths by the largest distance
/// from the origin or radius of gyration. Only for deciding whether a body
/// is physical and which cut-out is to blame, in f64; each part's figures
/// are formed when asked for (no copy of a 2,000,000-part model).
struct Scaled<'m> {
    model: &'m Model,
    /// The largest |m| and the length scale.
    mass: f64,
    length: f64,
    /// The centre of mass, scaled.
    com: Vector3<f64>,
}

impl<'m> Scaled<'m> {
    fn of(model: &'m Model) -> Scaled<'m> {
        let mut mass = f64::MIN_POSITIVE;
        model.each_body_part(&mut |p| mass = mass.max(p.mass::<f64>().abs()));
        let mut s = Scaled {
            model,
            mass,
            length: 1.0,
            com: Vector3::zeros(),
        };
        // √|tr| / √|m|, not √(|tr| / |m|): the ratio alone can overflow.
        let mut length = 0.0f64;
        model.each_body_part(&mut |p| {
            let (m, c, own) = s.part(p);
            let gyration = own.trace().abs().sqrt() / m.abs().sqrt();
            length = length
                .max(c.amax())
                .max(if gyration.is_finite() { gyration } else { 0.0 });
        });
        s.length = if length > 0.0 && length.is_finite() {
            length
        } else {
            1.0
        };
        let mut total = 0.0;
        model.each_body_part(&mut |p| total += p.mass::<f64>() / mass);
        let mut com = Vector3::zeros();
        model.each_body_part(&mut |p| {
            let (m, c, _) = s.part(p);
            com += c * (m / total);
        });
        s.com = com;
        s
    }

    /// The part's m (signed), centroid, and ∫ρρᵀ dm about it, scaled.
    fn part(&self, p: &Part) -> (f64, Vector3<f64>, Matrix3<f64>) {
        let m = p.mass::<f64>() / self.mass;
        let own = p.own_second_moment(m);
        let c = Vector3::from(p.centroid().map(|x| x.f64())) / self.length;
        let own = Matrix3::from_fn(|i, j| own[i][j] / self.length / self.length);
        (m, c, own)
    }

    /// The part's second moment about the centre of mass.
    fn of_part(&self, p: &Part) -> Matrix3<f64> {
        let (m, c, own) = self.part(p);
        let d = c - self.com;
        own + d * d.transpose() * m
    }

    /// The body's second moment about its centre of mass.
    fn total(&self) -> M3<f64> {
        let mut t = Matrix3::zeros();
        self.model.each_body_part(&mut |p| t += self.of_part(p));
        std::array::from_fn(|i| std::array::from_fn(|j| t[(i, j)]))
    }

    /// The part's second moment along the unit direction `u`: uᵀ C u
    /// (negative for a cut-out).
    fn along(&self, p: &Part, u: &Vector3<f64>) -> f64 {
        (u.transpose() * self.of_part(p) * u)[(0, 0)]
    }
}
