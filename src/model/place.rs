//! Where a part is and how it is turned: its placement by `center`,
//! `rotation` and its dimensions, or by the vectors that span it (`corner`
//! and `edges`, `from` and `to`), a triangle's `vertices`, a given
//! `inertia` — each validated.

use super::Ctx;
use super::ctx::Whose;
use super::raw::RawPart;
use super::rotation::Orientation;
use crate::diag::Diagnostic;
use crate::shapes::{Dims, Shape, Spanned as Spans};
use crate::tolerance::{
    COLLINEAR_TOLERANCE, PERPENDICULAR_TOLERANCE, SYMMETRY_TOLERANCE, VALIDITY_RTOL,
};
use crate::units::Dim;
use nalgebra::{Matrix3, Vector3};
use std::ops::Range;

/// How a part is turned, and its dimensions (m) as `Shape::second_moments`
/// takes them.
pub(super) type Placement = (Orientation, Vec<f64>);

/// `numeric::norm` of a vector.
fn vnorm(v: &Vector3<f64>) -> f64 {
    crate::numeric::norm(v.as_slice())
}

/// `numeric::unit` of a vector.
fn vunit(v: &Vector3<f64>) -> Vector3<f64> {
    Vector3::from(crate::numeric::unit(&[v.x, v.y, v.z]))
}

impl Ctx<'_> {
    /// "this SHAPE needs `KEY`", at the part, with the shape's help.
    fn missing(&self, shape: Shape, span: Range<usize>, key: &str) -> Diagnostic {
        self.err(span, format!("this {} needs `{key}`", shape.name()))
            .help(shape.info().help)
    }

    /// The centred placement: the dimensions, `center` and `rotation`.
    pub(super) fn placement_canonical(
        &self,
        shape: Shape,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<Placement, Diagnostic> {
        let missing = |key: &str| self.missing(shape, span.clone(), key);
        let dims = match shape.info().dims {
            Dims::Size(n) => {
                let size = p.size.as_ref().ok_or_else(|| missing("size"))?;
                let dims = self.vector(size, "size", Dim::LENGTH, n)?;
                for q in size.get_ref() {
                    self.positive(q, "size", Dim::LENGTH)?;
                }
                dims
            }
            Dims::Length => {
                let l = p.length.as_deref().ok_or_else(|| missing("length"))?;
                vec![self.positive(l, "length", Dim::LENGTH)?]
            }
            Dims::Radii { length } => {
                let r = self.radius_of(p, false)?.ok_or_else(|| missing("radius"))?;
                let outer = self.radius_si(&r)?;
                if !(outer > 0.0) {
                    return Err(self.err(r.q.span(), format!("`{}` must be positive", r.key)));
                }
                let inner = match self.radius_of(p, true)? {
                    None => 0.0,
                    Some(q) => {
                        let v = self.radius_si(&q)?;
                        if !(v >= 0.0 && v <= outer) {
                            let (ik, ok) = (q.key, r.key);
                            return Err(self
                                .err(q.q.span(), format!("`{ik}` must be from 0 to `{ok}`"))
                                .help("0 (or leaving it out) is a solid; equal to `radius`, a thin shell"));
                        }
                        v
                    }
                };
                let mut dims = vec![outer, inner];
                if length {
                    let l = p.length.as_deref().ok_or_else(|| missing("length"))?;
                    dims.push(self.positive(l, "length", Dim::LENGTH)?);
                }
                dims
            }
            Dims::None => vec![],
            // Read with its file (`model::mesh`), never here.
            Dims::Mesh => return Err(missing("file")),
            Dims::Given => {
                p.inertia.as_deref().ok_or_else(|| missing("inertia"))?;
                vec![]
            }
            Dims::Vertices => {
                let area = self.triangle(p, missing("vertices"))?;
                return Ok((Orientation::Identity, vec![area]));
            }
            Dims::Cone => self.cone(p, span.clone())?,
            Dims::Torus => self.torus(p, span.clone())?,
            Dims::Polygon => self.prism(p, span.clone())?,
        };
        if shape.info().dims == Dims::Polygon {
            // Placed by its optional `origin`.
            if let Some(o) = &p.origin {
                self.vec3(o, "origin", Dim::LENGTH)?;
            }
        } else {
            let center = p.center.as_ref().ok_or_else(|| missing("center"))?;
            self.vec3(center, "center", Dim::LENGTH)?;
        }
        let orientation = match &p.rotation {
            Some(r) => self.rotation(r)?,
            None => Orientation::Identity,
        };
        Ok((orientation, dims))
    }

    /// The placement by the vectors that span the part: `corner` and
    /// perpendicular `edges`, or `from` and `to`.
    pub(super) fn placement_by_edges(
        &self,
        shape: Shape,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<Placement, Diagnostic> {
        let s = shape.name();
        let missing = |key: &str| self.missing(shape, span.clone(), key);
        let (origin, edges) = if shape.info().spanned == Some(Spans::FromTo) {
            let from = self.vec3(
                p.from.as_deref().ok_or_else(|| missing("from"))?,
                "from",
                Dim::LENGTH,
            )?;
            let to_raw = p.to.as_deref().ok_or_else(|| missing("to"))?;
            let to = self.vec3(to_raw, "to", Dim::LENGTH)?;
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
            (from, vec![(e, to_raw.span())])
        } else {
            let corner = p.corner.as_deref().ok_or_else(|| missing("corner"))?;
            let corner = self.vec3(corner, "corner", Dim::LENGTH)?;
            let edges_raw = p.edges.as_deref().ok_or_else(|| missing("edges"))?;
            let n = shape.edge_count();
            let mut edges = Vec::with_capacity(n);
            for e in self.exactly(edges_raw, n, Whose::Shape(s), "`edges`")? {
                let v = self.vec3(e, "edges", Dim::LENGTH)?;
                if v.amax() == 0.0 {
                    return Err(self.err(e.span(), "an edge must not be zero"));
                }
                edges.push((v, e.span()));
            }
            for i in 0..n {
                for j in i + 1..n {
                    let cos = vunit(&edges[i].0).dot(&vunit(&edges[j].0));
                    if !(cos.abs() <= PERPENDICULAR_TOLERANCE) {
                        return Err(self
                            .err(
                                edges[j].1.clone(),
                                format!(
                                    "edges {} and {} are not perpendicular (angle {:.6}°)",
                                    i + 1,
                                    j + 1,
                                    cos.clamp(-1.0, 1.0).acos().to_degrees()
                                ),
                            )
                            .help(format!("edges must be perpendicular to a relative {PERPENDICULAR_TOLERANCE:e}")));
                    }
                }
            }
            (corner, edges)
        };
        // Validated only: the composer works from the corner and edges.
        let _ = origin;
        let dims: Vec<f64> = edges.iter().map(|(e, _)| vnorm(e)).collect();
        Ok((Orientation::Identity, dims))
    }

    /// A triangle's area (SI) from its `vertices`, which must
    /// span a triangle: area above `COLLINEAR_TOLERANCE` of the square of the
    /// longest edge.
    pub(super) fn triangle(&self, p: &RawPart, missing: Diagnostic) -> Result<f64, Diagnostic> {
        let raw = p.vertices.as_deref().ok_or(missing)?;
        let rows = self.exactly(raw, 3, Whose::Shape("triangle"), "`vertices`")?;
        let mut v = [Vector3::zeros(); 3];
        for (out, r) in v.iter_mut().zip(rows) {
            *out = self.vec3(r, "vertices", Dim::LENGTH)?;
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
        Ok(area)
    }

    /// A given `inertia` (SI), checked: 3 × 3, symmetric to
    /// `SYMMETRY_TOLERANCE`, and physically valid — its second moment
    /// tr(I)/2 E − I positive semi-definite (no principal moment negative,
    /// I₁ + I₂ ≥ I₃) to `VALIDITY_RTOL` of the largest. Returns that
    /// second moment, local axes.
    pub(super) fn given_inertia(&self, p: &RawPart) -> Result<Matrix3<f64>, Diagnostic> {
        let raw = p.inertia.as_deref().expect("`part` checked the inertia");
        if let Some(pr) = &p.products
            && !PRODUCTS.contains(&pr.get_ref().as_str())
        {
            return Err(self
                .err(pr.span(), format!("unknown `products` convention {:?}", pr.get_ref()))
                .help("\"tensor\" (off-diagonals −∫xy dm, the default) or \"positive\" (+∫xy dm, CAD and Meriam)"));
        }
        let rows = self.exactly(raw, 3, Whose::Key("inertia"), "rows")?;
        let mut m = [[0.0; 3]; 3];
        for (row, r) in m.iter_mut().zip(rows) {
            let v = self.vec3(r, "inertia", Dim::INERTIA)?;
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
        Ok(Matrix3::from_fn(|i, j| c[i][j]))
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
