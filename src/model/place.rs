//! The checks of the keys that place a part: the vectors that span it
//! (`edges`, `from` and `to`), a triangle's `vertices`, a given `inertia`
//! — each read once (`Ctx::value`) and validated as the part's shape asks
//! for it (`parts::PartReader`).

use super::Ctx;
use super::ctx::Whose;
use super::raw::{RawPart, Vector};
use super::tolerance::Recorder;
use crate::diag::Diagnostic;
use crate::la::Vector3;
use crate::shapes::Shape;
use crate::thresholds::{
    COLLINEAR_TOLERANCE, PERPENDICULAR_TOLERANCE, SYMMETRY_TOLERANCE, VALIDITY_RTOL,
};
use crate::units::Dim;
use std::ops::Range;
use toml::Spanned;

/// `numeric::norm` of a vector.
fn vnorm(v: &Vector3<f64>) -> f64 {
    crate::numeric::norm(&v.as_array())
}

/// `numeric::unit` of a vector.
fn vunit(v: &Vector3<f64>) -> Vector3<f64> {
    Vector3::from(crate::numeric::unit(&[v.x, v.y, v.z]))
}

impl Ctx<'_> {
    /// "this SHAPE needs `KEY`", at the part, with the shape's help.
    pub(super) fn missing(&self, shape: Shape, span: Range<usize>, key: &str) -> Diagnostic {
        self.err(span, format!("this {} needs `{key}`", shape.name()))
            .help(shape.info().help)
    }

    /// A rod's `to` (`to_raw`, read as `to`, SI), which must differ from
    /// its `from` (SI) by a finite span.
    pub(super) fn rod_ends(
        &self,
        from: Vector3<f64>,
        to: Vector3<f64>,
        to_raw: &Vector,
    ) -> Result<(), Diagnostic> {
        let e = to - from;
        if e.amax() == 0.0 {
            return Err(self.err(
                to_raw.span(),
                "`to` must differ from `from`: the rod has no length",
            ));
        }
        if !e.amax().is_finite() {
            return Err(self.err(
                to_raw.span(),
                "the rod from `from` to `to` is too long for f64",
            ));
        }
        Ok(())
    }

    /// The `edges` that span a box or plate (`N` of them, for `shape`),
    /// in the file's units: none zero, each pair perpendicular.
    pub(super) fn edges<const N: usize>(
        &self,
        rec: &mut Recorder,
        shape: Shape,
        raw: &Spanned<Vec<Vector>>,
    ) -> Result<[[f64; 3]; N], Diagnostic> {
        let mut file = [[0.0; 3]; N];
        let mut si: [(Vector3<f64>, Range<usize>); N] =
            std::array::from_fn(|_| (Vector3::zeros(), 0..0));
        let rows = self.exactly(raw, N, Whose::Shape(shape.name()), "`edges`")?;
        for (k, e) in rows.iter().enumerate() {
            let (f, v) = self.value3(rec, k, e, "edges", Dim::LENGTH)?;
            if v.amax() == 0.0 {
                return Err(self.err(e.span(), "an edge must not be zero"));
            }
            (file[k], si[k]) = (f, (v, e.span()));
        }
        for i in 0..N {
            for j in i + 1..N {
                let cos = vunit(&si[i].0).dot(&vunit(&si[j].0));
                if !(cos.abs() <= PERPENDICULAR_TOLERANCE) {
                    return Err(self
                        .err(
                            si[j].1.clone(),
                            format!(
                                "edges {} and {} are not perpendicular (angle {:.6}°)",
                                i + 1,
                                j + 1,
                                cos.clamp(-1.0, 1.0).acos().to_degrees()
                            ),
                        )
                        .help(format!(
                            "edges must be perpendicular to a relative {PERPENDICULAR_TOLERANCE:e}"
                        )));
                }
            }
        }
        Ok(file)
    }

    /// A triangle's `vertices` (file units), which must span a triangle:
    /// area (SI) above `COLLINEAR_TOLERANCE` of the square of the longest
    /// edge.
    pub(super) fn triangle(
        &self,
        rec: &mut Recorder,
        raw: &Spanned<Vec<Vector>>,
    ) -> Result<[[f64; 3]; 3], Diagnostic> {
        let rows = self.exactly(raw, 3, Whose::Shape("triangle"), "`vertices`")?;
        let mut file = [[0.0; 3]; 3];
        let mut v = [Vector3::zeros(); 3];
        for (k, r) in rows.iter().enumerate() {
            (file[k], v[k]) = self.value3(rec, k, r, "vertices", Dim::LENGTH)?;
        }
        let (e1, e2) = (v[1] - v[0], v[2] - v[0]);
        let longest = vnorm(&e1).max(vnorm(&e2)).max(vnorm(&(v[2] - v[1])));
        // Scaled by the longest edge, so the cross product can neither
        // overflow nor underflow: the shape (`relative`, the area over the
        // longest edge squared) is judged apart from the size.
        let relative = if longest > 0.0 && longest.is_finite() {
            vnorm(&(e1 / longest).cross(&(e2 / longest))) / 2.0
        } else {
            0.0
        };
        let area = relative * longest * longest;
        if !(area * 4.0).is_finite() || !longest.is_finite() {
            return Err(self.err(
                raw.span(),
                "this triangle is too large for f64: its area overflows",
            ));
        }
        if longest > 0.0 && relative > COLLINEAR_TOLERANCE && area < f64::MIN_POSITIVE {
            return Err(self.err(
                raw.span(),
                format!(
                    "this triangle is too small for f64: its area is below {:e} in SI units",
                    f64::MIN_POSITIVE
                ),
            ));
        }
        if !(longest > 0.0 && relative > COLLINEAR_TOLERANCE) {
            return Err(self
                .err(
                    raw.span(),
                    "the `vertices` of this triangle are (nearly) collinear: it has no area",
                )
                .help(format!(
                    "its area must exceed {COLLINEAR_TOLERANCE:e} of the square of its longest edge"
                )));
        }
        Ok(file)
    }

    /// A given `inertia` (`raw`, of part `p`), checked in SI: 3 × 3,
    /// symmetric to `SYMMETRY_TOLERANCE`, and physically valid — its
    /// second moment tr(I)/2 E − I positive semi-definite (no principal
    /// moment negative, I₁ + I₂ ≥ I₃) to `VALIDITY_RTOL` of the largest.
    /// Returns it in the file's units, in the tensor convention.
    pub(super) fn given_inertia(
        &self,
        rec: &mut Recorder,
        p: &RawPart,
        raw: &Spanned<Vec<Vector>>,
    ) -> Result<[[f64; 3]; 3], Diagnostic> {
        if let Some(pr) = &p.products
            && !PRODUCTS.contains(&pr.get_ref().as_str())
        {
            return Err(self
                .err(pr.span(), format!("unknown `products` convention {:?}", pr.get_ref()))
                .help("\"tensor\" (off-diagonals −∫xy dm, the default) or \"positive\" (+∫xy dm, CAD and Meriam)"));
        }
        let rows = self.exactly(raw, 3, Whose::Key("inertia"), "rows")?;
        let (mut file, mut m) = ([[0.0; 3]; 3], [[0.0; 3]; 3]);
        for (k, ((f, row), r)) in file.iter_mut().zip(m.iter_mut()).zip(rows).enumerate() {
            let v;
            (*f, v) = self.value3(rec, k, r, "inertia", Dim::INERTIA)?;
            *row = [v.x, v.y, v.z];
        }
        let big = m.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
        if m.iter()
            .flatten()
            .any(|x| *x != 0.0 && x.abs() < f64::MIN_POSITIVE)
        {
            return Err(self
                .err(raw.span(), "`inertia` has an entry too small for f64 (below 2.2e-308 in SI): too few digits to compute with")
                .help("give it in smaller units, e.g. \"1.2e-7 kg*mm^2\""));
        }
        // Its second moment must fit in f64 (the eigen check forms it).
        if !(big * 4.0).is_finite() {
            return Err(self.err(raw.span(), "`inertia` overflows the range of f64"));
        }
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            if !((m[i][j] - m[j][i]).abs() <= SYMMETRY_TOLERANCE * big) {
                return Err(self
                    .err(raw.span(), format!("`inertia` is not symmetric: row {}, column {} is {:e} but row {}, column {} is {:e}", i + 1, j + 1, m[i][j], j + 1, i + 1, m[j][i]))
                    .help(format!("an inertia tensor is symmetric (to {SYMMETRY_TOLERANCE:e} of its largest entry)")));
            }
        }
        let t = tensor_convention(m, positive_products(p));
        let half = (t[0][0] + t[1][1] + t[2][2]) / 2.0;
        let c: crate::numeric::M3<f64> = std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { half - t[i][i] } else { -t[i][j] })
        });
        // The entries are finite, so `None` means an eigenvalue beyond f64
        // (|λ| can reach 4.5 times the largest entry).
        let (lam, _) = crate::eigen::jacobi(c)
            .ok_or_else(|| self.err(raw.span(), "`inertia` overflows the range of f64"))?;
        let top = lam.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        if lam.iter().any(|&l| l < -VALIDITY_RTOL * top) {
            let mut moments = [lam[1] + lam[2], lam[0] + lam[2], lam[0] + lam[1]];
            moments.sort_by(f64::total_cmp);
            return Err(self
                .err(raw.span(), format!(
                    "`inertia` is not physically valid: its principal moments {:.6e}, {:.6e}, {:.6e} kg·m² {}",
                    moments[0], moments[1], moments[2],
                    if moments[0] < -VALIDITY_RTOL * moments[2] { "include a negative one" } else { "break the triangle inequality I1 + I2 ≥ I3" }
                ))
                .help("check the signs of the products (`products = \"positive\"` if they are +∫xy dm, as CAD reports them) and the units"));
        }
        Ok(tensor_convention(file, positive_products(p)))
    }
}

/// The sign conventions `products` may name: "tensor" (the default,
/// off-diagonals −∫xy dm) and "positive" (+∫xy dm).
pub(super) const PRODUCTS: [&str; 2] = ["tensor", "positive"];

/// Whether a part's `products = "positive"` (checked in `part`).
pub(super) fn positive_products(p: &RawPart) -> bool {
    matches!(&p.products, Some(s) if s.get_ref() == "positive")
}

/// A given inertia matrix in the tensor convention (off-diagonals −∫xy dm),
/// symmetrised: the average of the two entries each product appears in.
pub(super) fn tensor_convention(m: [[f64; 3]; 3], positive: bool) -> [[f64; 3]; 3] {
    let sign = if positive { -1.0 } else { 1.0 };
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i == j {
                m[i][i]
            } else {
                sign * (m[i][j] * 0.5 + m[j][i] * 0.5)
            }
        })
    })
}
