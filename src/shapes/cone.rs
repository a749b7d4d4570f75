//! A cone or frustum about local z, solid or hollow, from z = −L/2 (base,
//! radius R₀, bore a₀) to z = +L/2 (top, radius R₁, bore a₁): dimensions
//! [R₀, a₀, R₁, a₁, L]. Its centroid lies on the axis, off the origin.
//!
//! NOTE: the derivation. With t = z/L + ½ ∈ [0, 1], the outer and inner
//! radii are linear in t: ρ(t) = R₀(1 − t) + R₁t, α(t) = a₀(1 − t) + a₁t.
//! The section is the annulus α ≤ r ≤ ρ, of area π(ρ² − α²) = π d s with
//! d = ρ − α and s = ρ + α, both linear in t and non-negative; and
//! ∫x² dA over it is π(ρ⁴ − α⁴)/4 = π d s q/4 with q = ρ² + α². In the
//! Bernstein basis of degree 2 (B₀ = (1 − t)², B₁ = 2t(1 − t), B₂ = t²)
//! w = d s has the coefficients w₀ = d₀s₀, w₁ = (d₀s₁ + d₁s₀)/2, w₂ = d₁s₁
//! and q has q₀ = R₀² + a₀², q₁ = R₀R₁ + a₀a₁, q₂ = R₁² + a₁²: each a sum of
//! non-negative terms, with d₀ = R₀ − a₀ and d₁ = R₁ − a₁ the file's own
//! differences, so a thin wall is no difference of large numbers. Then
//! (∫ Bₖ dt = ⅓, ∫ t Bₖ dt = (k + 1)/12, ∫ t² Bₖ dt = 1/30, 1/10, 1/5):
//!
//! - V = π L (w₀ + w₁ + w₂)/3;
//! - t̄ − ½ = (w₂ − w₀)/(4W), W = w₀ + w₁ + w₂: the centroid at
//!   z̄ = L (w₂ − w₀)/(4W);
//! - ∫(z − z̄)² dm = m L² Var t, and Var t = E(t²) − t̄², which written out
//!   over the common denominator 80W² is
//!   (3w₀² + 12w₀w₁ + 26w₀w₂ + 4w₁² + 12w₁w₂ + 3w₂²)/(80W²): every
//!   coefficient positive, so no cancellation (a cylinder: 1/12);
//! - ∫x² dm = m ∫ w q dt/(4 ∫ w dt), and the product of two quadratics in
//!   Bernstein form integrates to Σᵢⱼ wᵢqⱼ C(2,i)C(2,j)/(5 C(4,i+j)):
//!   ∫x² dm = m S/(40W), S = 6w₀q₀ + 3(w₀q₁ + w₁q₀) + (w₀q₂ + w₂q₀) +
//!   4w₁q₁ + 3(w₁q₂ + w₂q₁) + 6w₂q₂ (a cylinder: m R²/4; a full cone:
//!   3m R²/20).

use super::common::{add, axes, offset_centroid, offset_centroid_error, rim, scaled, var};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::{MaterialRule, Mover, Own, PER_VOLUME, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;

/// The Bernstein coefficients w (of d s, the section's area over π) and q
/// (of ρ² + α²) of the dimensions `d` = [R₀, a₀, R₁, a₁, L].
///
/// A thin shell (a₀ = R₀ and a₁ = R₁) has w = 0: its moments are the
/// limit of a wall of even thickness, d₀ = d₁ → 0, whose mass spreads
/// evenly over the conical surface (per unit area); its w is taken with
/// d₀ = d₁ = 1, the scale cancelling in every ratio. Its measure is 0.
fn coefficients<T: Real>(d: &[T], shell: bool) -> ([T; 3], [T; 3]) {
    let (r0, a0, r1, a1) = (d[0], d[1], d[2], d[3]);
    let (mut d0, mut d1, s0, s1) = (r0 - a0, r1 - a1, r0 + a0, r1 + a1);
    let zero = T::of(0.0);
    if shell && d0 == zero && d1 == zero {
        (d0, d1) = (T::of(1.0), T::of(1.0));
    }
    let w = [d0 * s0, (d0 * s1 + d1 * s0) / T::of(2.0), d1 * s1];
    let q = [r0 * r0 + a0 * a0, r0 * r1 + a0 * a1, r1 * r1 + a1 * a1];
    (w, q)
}

/// The volume π L W/3.
pub fn measure<T: Real>(d: &[T]) -> T {
    let (w, _) = coefficients(d, false);
    T::pi() * d[4] * (w[0] + w[1] + w[2]) / T::of(3.0)
}

/// The centroid's offset from the origin along local z, L (w₂ − w₀)/(4W).
pub fn offset<T: Real>(d: &[T]) -> T {
    let (w, _) = coefficients(d, true);
    d[4] * (w[2] - w[0]) / (T::of(4.0) * (w[0] + w[1] + w[2]))
}

/// ∫x² dm, ∫y² dm, ∫z² dm about the centroid, local axes.
pub fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
    let (w, q) = coefficients(d, true);
    let total = w[0] + w[1] + w[2];
    let (three, six) = (T::of(3.0), T::of(6.0));
    let s = six * w[0] * q[0]
        + three * (w[0] * q[1] + w[1] * q[0])
        + (w[0] * q[2] + w[2] * q[0])
        + T::of(4.0) * w[1] * q[1]
        + three * (w[1] * q[2] + w[2] * q[1])
        + six * w[2] * q[2];
    let across = m * s / (T::of(40.0) * total);
    let var = (three * w[0] * w[0]
        + T::of(12.0) * w[0] * w[1]
        + T::of(26.0) * w[0] * w[2]
        + T::of(4.0) * w[1] * w[1]
        + T::of(12.0) * w[1] * w[2]
        + three * w[2] * w[2])
        / (T::of(80.0) * total * total);
    let l = d[4];
    [across, across, m * l * l * var]
}
/// A cone or frustum, solid or hollow, placed by its `center` and turned by its `orientation`,
/// in its file's units; its centroid lies off its centre along local z.
#[derive(Debug, Clone, PartialEq)]
pub struct Cone {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `inner_radius`.
    pub inner_radius: f64,
    /// `top_radius`.
    pub top_radius: f64,
    /// `top_inner_radius`.
    pub top_inner_radius: f64,
    /// `length`.
    pub length: f64,
    pub orientation: Orientation,
}

impl Cone {
    /// Its dimensions as its closed forms take them, read through `l`.
    fn dims<T: Real, L: Lift>(&self, l: L) -> [T; 5] {
        [var(self.radius, Slot::Radius, l), var(self.inner_radius, Slot::InnerRadius, l), var(self.top_radius, Slot::TopRadius, l), var(self.top_inner_radius, Slot::TopInnerRadius, l), var(self.length, Slot::Length, l)]
    }
}

impl ShapeKind for Cone {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Cone,
        name: "cone",
        keys: &[
            "density",
            "radius",
            "inner_radius",
            "top_radius",
            "top_inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "length",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        sizes: &[
            "radius",
            "inner_radius",
            "top_radius",
            "top_inner_radius",
            "length",
        ],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a zero `length` (a disk), both radii 0, or a density on a thin shell (each inner radius equal to its outer)",
        help: "a cone takes `mass` or `density`, `radius` (or `diameter`) at its base, `top_radius` (0 for a full cone) and `length` along its local z, with `center` at the middle of its axis (and optional `rotation`); `inner_radius` and `top_inner_radius` make it hollow",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "cone or frustum: base radius R (bore r), top radius R_t (bore r_t), length L; its section A(1−t)² + 2Bt(1−t) + Ct² along the axis, A = R² − r², B = R·R_t − r·r_t, C = R_t² − r_t²",
        dims: &[
            super::symbol("R", "R", super::Slot::Radius),
            super::symbol("r", "r", super::Slot::InnerRadius),
            super::symbol("R_t", "R_t", super::Slot::TopRadius),
            super::symbol("r_t", "r_t", super::Slot::TopInnerRadius),
            super::symbol("L", "L", super::Slot::Length),
        ],
        measure: "pi*L*(R^2 - r^2 + R*R_t - r*r_t + R_t^2 - r_t^2)/3",
        // NOTE: ∫x² dm = 3m(S₄ − s₄)/(20(S₂ − s₂)), Sₙ the complete
        // homogeneous sums of degree n in R, R_t (sₙ in r, r_t); ∫z² dm about
        // the centroid is m L² times the variance of the section's height,
        // its area along the axis in Bernstein form A(1−t)² + 2Bt(1−t) + Ct².
        moments: [
            "3*m*(R^4 + R^3*R_t + R^2*R_t^2 + R*R_t^3 + R_t^4 - r^4 - r^3*r_t - r^2*r_t^2 - r*r_t^3 - r_t^4)/(20*(R^2 + R*R_t + R_t^2 - r^2 - r*r_t - r_t^2)) + m*L^2*(((R^2 - r^2) + 3*(R*R_t - r*r_t) + 6*(R_t^2 - r_t^2))/(10*((R^2 - r^2) + (R*R_t - r*r_t) + (R_t^2 - r_t^2))) - ((R^2 - r^2) + 2*(R*R_t - r*r_t) + 3*(R_t^2 - r_t^2))^2/(16*((R^2 - r^2) + (R*R_t - r*r_t) + (R_t^2 - r_t^2))^2))",
            "3*m*(R^4 + R^3*R_t + R^2*R_t^2 + R*R_t^3 + R_t^4 - r^4 - r^3*r_t - r^2*r_t^2 - r*r_t^3 - r_t^4)/(20*(R^2 + R*R_t + R_t^2 - r^2 - r*r_t - r_t^2)) + m*L^2*(((R^2 - r^2) + 3*(R*R_t - r*r_t) + 6*(R_t^2 - r_t^2))/(10*((R^2 - r^2) + (R*R_t - r*r_t) + (R_t^2 - r_t^2))) - ((R^2 - r^2) + 2*(R*R_t - r*r_t) + 3*(R_t^2 - r_t^2))^2/(16*((R^2 - r^2) + (R*R_t - r*r_t) + (R_t^2 - r_t^2))^2))",
            "2*3*m*(R^4 + R^3*R_t + R^2*R_t^2 + R*R_t^3 + R_t^4 - r^4 - r^3*r_t - r^2*r_t^2 - r*r_t^3 - r_t^4)/(20*(R^2 + R*R_t + R_t^2 - r^2 - r*r_t - r_t^2))",
        ],
    };

    /// Π, L and W (the Bernstein coefficients' sum, 6), /3, two products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 14.0;

    /// ∫x² dm (d, s, the Bernstein coefficients 4 deep, S's ten products summed, over 40W) about 26 and ∫z² dm (the variance's six products summed over 80W²) about 33: 40.
    const MOMENT_ROUNDINGS: f64 = 40.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        measure(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        second_moments(m, d)
    }

    fn offset_of<T: Real>(d: &[T]) -> T {
        offset(d)
    }

    /// Its centre read before its sizes, as the file's other shapes' after.
    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let center = r.point("center")?;
        let [radius, inner_radius, top_radius, top_inner_radius, length] = r.cone()?;
        Ok(Cone {
            center,
            radius,
            inner_radius,
            top_radius,
            top_inner_radius,
            length,
            orientation: r.orientation(),
        })
    }



    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        let z = Self::offset_of(&self.dims(l));
        offset_centroid([T::of(0.0), T::of(0.0), z], &self.center, &self.orientation, l)
    }

    /// The offset's error: 64 double-double units of the larger of the
    /// radius and the length it is formed from.
    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
        let big = self.radius.abs().max(self.length.abs()).max(self.top_radius.abs());
        offset_centroid_error(
            [0.0, 0.0, 64.0 * big],
            [0.0, 0.0, big],
            &self.orientation,
            at,
            centroid,
        )
    }












    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn outline(&self) -> Outline {
        let c = self.center;
        let [x, y, z] = axes(&self.orientation.matrix());
        let ends = [
            add(c, scaled(-self.length / 2.0, z)),
            add(c, scaled(self.length / 2.0, z)),
        ];
        let mut p = vec![Piece::Side {
            c: ends,
            r: [self.radius, self.top_radius],
            u: x,
            v: y,
        }];
        for (at, r) in [
            (ends[0], self.radius),
            (ends[0], self.inner_radius),
            (ends[1], self.top_radius),
            (ends[1], self.top_inner_radius),
        ] {
            if r > 0.0 {
                p.push(rim(at, r, &x, &y));
            }
        }
        Outline::Pieces(p)
    }

    placed_by_centre!(radius: Radius, inner_radius: InnerRadius, top_radius: TopRadius, top_inner_radius: TopInnerRadius, length: Length);
}
