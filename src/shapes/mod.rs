//! The primitive shapes and their closed forms: second moments of mass about
//! the shape's own centroid along its own local axes, ∫x² dm, ∫y² dm, ∫z² dm
//! (kg·m²). The local frames are:
//!
//! - box: edges `a, b, c` along local x, y, z, centred on the origin;
//! - plate: thin rectangle `a × b` in the local x–y plane, zero thickness;
//! - rod: slender segment of length `L` along local z, zero radius;
//! - cylinder: radius `R`, length `L` along local z, centred on the origin;
//!   with an inner radius `r` a tube;
//! - disk: thin circular plate of radius `R` in the local x–y plane; with
//!   an inner radius an annulus;
//! - sphere: radius `R` about the origin; with an inner radius a hollow
//!   sphere, and with r = R a thin shell;
//! - point: a point mass at the origin;
//! - cone (`cone`): a frustum about local z from the base at z = −L/2 to
//!   the top at +L/2, solid or hollow; its centroid off the origin on z;
//! - torus (`torus`): its tube's centre line a circle in the local x–y
//!   plane about the origin;
//! - hemisphere (`hemisphere`): the half z ≥ 0 of a sphere about the
//!   origin; its centroid off the origin on z;
//! - prism (`prism`): a polygon in the local x–y plane extruded from
//!   z = −L/2 to +L/2 (its second moment has an x–y product).
//! - mesh: a triangle mesh's own file coordinates (`mesh`), placed by
//!   `origin` and `rotation` as an include is.
//!
//! For a uniform segment of length a centred on 0, ∫x² dm = m a²/12; box,
//! plate and rod are products of such segments. Every shape but the prism
//! is symmetric about its local x–z and y–z planes, so its second moments
//! about its centroid are diagonal in local axes and need no products of
//! inertia.
//!
//! A plate's real `thickness` and a rod's `diameter` never enter these: the
//! composition is the idealised one, and `report::ideal` compares it with
//! the solid box and cylinder they describe.

pub mod cone;
pub mod hemisphere;
mod info;
pub mod prism;
#[cfg(test)]
mod quadrature;
pub mod torus;

pub use info::{
    DensityKind, Dims, Drawn, MaterialRule, PER_AREA, PER_LENGTH, PER_VOLUME, SHAPES, ShapeInfo,
    Solid, Spanned,
};

use crate::numeric::Real;
use nalgebra::Vector3;
use serde::Serialize;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Shape {
    Box,
    Plate,
    Rod,
    Cylinder,
    Disk,
    Sphere,
    /// A thin triangular plate given by its three vertices.
    Triangle,
    Point,
    /// A bought or previously computed component: mass, centre and inertia
    /// tensor given (no closed form here; see `model::Place::Given`).
    Inertia,
    /// A cone or frustum, solid or hollow (`shapes::cone`).
    Cone,
    /// A torus, solid or hollow (`shapes::torus`).
    Torus,
    /// A hemisphere, solid or hollow (`shapes::hemisphere`).
    Hemisphere,
    /// A polygon extruded along local z (`shapes::prism`).
    Prism,
    /// A triangle mesh read from a file: its integrals are computed from
    /// the file (`mesh`, `part::Place::Mesh`), no closed form here.
    Mesh,
}

impl Shape {
    pub const ALL: [Shape; 14] = [
        Shape::Box,
        Shape::Plate,
        Shape::Rod,
        Shape::Cylinder,
        Shape::Disk,
        Shape::Sphere,
        Shape::Triangle,
        Shape::Point,
        Shape::Inertia,
        Shape::Cone,
        Shape::Torus,
        Shape::Hemisphere,
        Shape::Prism,
        Shape::Mesh,
    ];

    /// The shape's description.
    pub fn info(self) -> &'static ShapeInfo {
        &SHAPES[self as usize]
    }

    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// Every shape's name, quoted and in order, for messages:
    /// `"box", "plate", …`.
    pub fn quoted_names() -> String {
        SHAPES
            .iter()
            .map(|s| format!("\"{}\"", s.name))
            .collect::<Vec<_>>()
            .join(", ")
    }

    pub fn from_name(name: &str) -> Option<Shape> {
        SHAPES.iter().find(|s| s.name == name).map(|s| s.shape)
    }

    /// Number of edge vectors that span the shape when it is placed by
    /// `corner`/`edges` or `from`/`to`; 0 for shapes that are only placed by
    /// `center`.
    pub fn edge_count(self) -> usize {
        self.info().spanned.map_or(0, Spanned::edges)
    }

    /// Number of dimensions the closed forms take (see `second_moments`).
    pub fn dim_count(self) -> usize {
        self.info().dims.count()
    }

    /// How many of the three local second moments are non-zero.
    pub fn nonzero_moments(self) -> usize {
        self.info().nonzero_moments
    }

    /// The key of the density that this shape takes instead of `mass`.
    pub fn density_key(self) -> Option<&'static str> {
        self.info().density.map(|d| d.key)
    }

    /// Volume, area or length of a shape of dimensions `d` (see
    /// `second_moments`), the measure that the density multiplies.
    /// R² − r² is formed as (R − r)(R + r) and R³ − r³ as
    /// (R − r)(R² + Rr + r²), so a thin wall is not a difference of large
    /// numbers.
    pub fn measure_of<T: Real>(self, d: &[T]) -> T {
        let ring = |d: &[T]| T::pi() * (d[0] - d[1]) * (d[0] + d[1]);
        match self {
            Shape::Box | Shape::Plate | Shape::Rod | Shape::Triangle => {
                d.iter().fold(T::of(1.0), |a, &x| a * x)
            }
            Shape::Cylinder => ring(d) * d[2],
            Shape::Disk => ring(d),
            Shape::Sphere => {
                let (r_out, r_in) = (d[0], d[1]);
                T::of(4.0) / T::of(3.0)
                    * T::pi()
                    * (r_out - r_in)
                    * (r_out * r_out + r_out * r_in + r_in * r_in)
            }
            Shape::Point | Shape::Inertia | Shape::Mesh => T::of(1.0),
            Shape::Cone => cone::measure(d),
            Shape::Torus => torus::measure(d),
            Shape::Hemisphere => hemisphere::measure(d),
            // [area, length]: the area from the polygon (`part`).
            Shape::Prism => d[0] * d[1],
        }
    }

    /// ∫x² dm, ∫y² dm, ∫z² dm about the centroid in local axes, of mass
    /// `m` and dimensions `d`: box [a, b, c]; plate [a, b]; rod [L];
    /// cylinder [R, r, L]; disk [R, r]; sphere [R, r] (outer and inner
    /// radius, r = 0 for a solid, r = R for a thin shell); point [];
    /// cone [R₀, a₀, R₁, a₁, L] (base and top radii and bores);
    /// torus [R, a, b] (centre line, tube, inner tube); hemisphere [R, r].
    /// Each about the shape's centroid (`cone::offset`,
    /// `hemisphere::offset`: off the origin of the local frame).
    ///
    /// - segment of length a: m a²/12;
    /// - cylinder or tube, about a diameter in its mid-plane: m (R² + r²)/4
    ///   (half the axial m (R² + r²)/2), and m L²/12 along the axis; a disk
    ///   or annulus is the same with L = 0;
    /// - sphere or hollow sphere: m/5 · (R⁵ − r⁵)/(R³ − r³) along every
    ///   axis, written as m R²/5 · (1 + ρ + ρ² + ρ³ + ρ⁴)/(1 + ρ + ρ²) with
    ///   ρ = r/R: no cancellation for thin walls, no overflow in R⁵, and
    ///   m R²/3 for a thin shell.
    pub fn second_moments<T: Real>(self, m: T, d: &[T]) -> [T; 3] {
        let zero = T::of(0.0);
        let seg = |a: T| m * a * a / T::of(12.0);
        let ring = |r_out: T, r_in: T| m * (r_out * r_out + r_in * r_in) / T::of(4.0);
        match (self, d) {
            (Shape::Box, &[a, b, c]) => [seg(a), seg(b), seg(c)],
            (Shape::Plate, &[a, b]) => [seg(a), seg(b), zero],
            (Shape::Rod, &[l]) => [zero, zero, seg(l)],
            (Shape::Cylinder, &[r_out, r_in, l]) => {
                let q = ring(r_out, r_in);
                [q, q, seg(l)]
            }
            (Shape::Disk, &[r_out, r_in]) => {
                let q = ring(r_out, r_in);
                [q, q, zero]
            }
            (Shape::Sphere, &[r_out, r_in]) => {
                let one = T::of(1.0);
                let rho = r_in / r_out;
                let rho2 = rho * rho;
                let ratio = (one + rho + rho2 + rho2 * rho + rho2 * rho2) / (one + rho + rho2);
                let q = m * r_out * r_out / T::of(5.0) * ratio;
                [q, q, q]
            }
            // A given inertia is composed from `Place::Given` instead.
            (Shape::Point | Shape::Inertia | Shape::Mesh, &[]) => [zero; 3],
            // A triangle is composed from `Place::Vertices` instead.
            (Shape::Triangle, &[_]) => [zero; 3],
            (Shape::Cone, &[_, _, _, _, _]) => cone::second_moments(m, d),
            (Shape::Torus, &[_, _, _]) => torus::second_moments(m, d),
            (Shape::Hemisphere, &[_, _]) => hemisphere::second_moments(m, d),
            // A prism is composed from `Place::Prism` instead.
            (Shape::Prism, &[_, _]) => [zero; 3],
            _ => unreachable!("the model passes each shape its dim_count() dimensions"),
        }
    }

    /// The offset of the centroid from the origin of the local frame,
    /// along local z, of a shape of dimensions `d`: the cone's and the
    /// hemisphere's; 0 for the others (a prism's is in its polygon).
    pub fn axial_offset<T: Real>(self, d: &[T]) -> T {
        match self {
            Shape::Cone => cone::offset(d),
            Shape::Hemisphere => hemisphere::offset(d),
            _ => T::of(0.0),
        }
    }

    /// `measure_of` in f64.
    pub fn measure(self, dims: &[f64]) -> f64 {
        self.measure_of(dims)
    }

    /// `second_moments` in f64, as a vector.
    pub fn local_second_moment(self, mass: f64, dims: &[f64]) -> Vector3<f64> {
        Vector3::from(self.second_moments(mass, dims))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_has_one_entry_per_shape_in_order() {
        for (i, shape) in Shape::ALL.into_iter().enumerate() {
            assert_eq!(SHAPES[i].shape, shape);
            assert_eq!(Shape::from_name(shape.name()), Some(shape));
        }
    }

    #[test]
    fn every_key_a_shape_names_is_one_it_accepts() {
        for info in &SHAPES {
            let named = info
                .density
                .map(|d| d.key)
                .into_iter()
                .chain(info.spanned.map_or(&[][..], Spanned::keys).iter().copied())
                .chain(info.real_size.map(|r| r.0))
                .chain(
                    info.centred
                        .iter()
                        .copied()
                        .filter(|k| *k != "center" || info.keys.contains(&"center")),
                );
            for k in named {
                assert!(info.keys.contains(&k), "{}: `{k}`", info.name);
            }
            assert!(
                info.help.starts_with(&format!("a {} ", info.name))
                    || info.help.starts_with(&format!("an {} ", info.name)),
                "{}",
                info.name
            );
        }
    }

    /// Gauss–Legendre nodes and weights on [−½, ½] (n = 5, exact to degree 9).
    fn gauss5() -> [(f64, f64); 5] {
        let a = (5.0 - 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
        let b = (5.0 + 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
        let wa = (322.0 + 13.0 * 70.0f64.sqrt()) / 900.0;
        let wb = (322.0 - 13.0 * 70.0f64.sqrt()) / 900.0;
        [(0.0, 128.0 / 225.0), (a, wa), (-a, wa), (b, wb), (-b, wb)]
            .map(|(x, w)| (x / 2.0, w / 2.0))
    }

    /// ∫ρρᵀ dm of a uniform parallelepiped by direct quadrature over its
    /// parameter cube: independent of the closed form's a²/12.
    fn quadrature(mass: f64, dims: &[f64]) -> Vector3<f64> {
        let g = gauss5();
        let mut out = Vector3::zeros();
        let n = dims.len();
        let mut idx = vec![0usize; n];
        loop {
            let mut w = mass;
            let mut p = Vector3::zeros();
            for k in 0..n {
                let (t, wt) = g[idx[k]];
                w *= wt;
                p[k + 3 - n] = t * dims[k]; // rods lie along z
            }
            if n == 2 {
                // plates lie in x–y
                p = Vector3::new(p[1], p[2], 0.0);
            }
            out += p.component_mul(&p) * w;
            let mut k = 0;
            while k < n {
                idx[k] += 1;
                if idx[k] < g.len() {
                    break;
                }
                idx[k] = 0;
                k += 1;
            }
            if k == n {
                break;
            }
        }
        out
    }

    fn assert_close(a: Vector3<f64>, b: Vector3<f64>) {
        let tol = 8.0 * f64::EPSILON * b.amax().max(f64::MIN_POSITIVE);
        assert!((a - b).amax() <= tol, "{a} vs {b}");
    }

    #[test]
    fn box_closed_form_matches_quadrature() {
        let dims = [0.3, 1.7, 0.05];
        assert_close(
            Shape::Box.local_second_moment(2.5, &dims),
            quadrature(2.5, &dims),
        );
    }

    #[test]
    fn plate_closed_form_matches_quadrature() {
        let dims = [0.125, 0.1];
        assert_close(
            Shape::Plate.local_second_moment(0.875, &dims),
            quadrature(0.875, &dims),
        );
    }

    #[test]
    fn rod_closed_form_matches_quadrature() {
        assert_close(
            Shape::Rod.local_second_moment(3.0, &[2.0]),
            quadrature(3.0, &[2.0]),
        );
    }

    #[test]
    fn point_has_no_second_moment() {
        assert_eq!(Shape::Point.local_second_moment(5.0, &[]), Vector3::zeros());
    }

    #[test]
    fn measure_is_volume_area_or_length() {
        assert_eq!(Shape::Box.measure(&[2.0, 3.0, 4.0]), 24.0);
        assert_eq!(Shape::Plate.measure(&[2.0, 3.0]), 6.0);
        assert_eq!(Shape::Rod.measure(&[2.0]), 2.0);
    }

    /// Gauss–Legendre on [lo, hi] (5 nodes, exact to degree 9).
    fn gauss(lo: f64, hi: f64) -> Vec<(f64, f64)> {
        gauss5()
            .iter()
            .map(|(x, w)| (lo + (hi - lo) * (x + 0.5), w * (hi - lo)))
            .collect()
    }

    /// The trapezoid rule on a full turn, exact for trigonometric
    /// polynomials of degree below `n`.
    fn turn(n: usize) -> Vec<(f64, f64)> {
        let h = 2.0 * std::f64::consts::PI / n as f64;
        (0..n).map(|k| (k as f64 * h, h)).collect()
    }

    /// Mass-weighted ∫x², ∫y², ∫z² over the region `points` (x, y, z,
    /// weight) samples, for a total mass m: m · ∫x² dV / ∫dV. Independent of
    /// the closed forms, the measure included.
    fn moments(m: f64, points: impl Iterator<Item = ([f64; 3], f64)>) -> Vector3<f64> {
        let (mut vol, mut acc) = (0.0, Vector3::zeros());
        for (p, w) in points {
            vol += w;
            acc += Vector3::new(p[0] * p[0], p[1] * p[1], p[2] * p[2]) * w;
        }
        acc * (m / vol)
    }

    /// Cylinder or tube by quadrature in cylindrical coordinates.
    fn cylinder_quadrature(m: f64, r_out: f64, r_in: f64, l: f64) -> Vector3<f64> {
        let mut pts = Vec::new();
        for (r, wr) in gauss(r_in, r_out) {
            for (t, wt) in turn(8) {
                for (z, wz) in gauss(-l / 2.0, l / 2.0) {
                    pts.push(([r * t.cos(), r * t.sin(), z], r * wr * wt * wz));
                }
            }
        }
        moments(m, pts.into_iter())
    }

    fn disk_quadrature(m: f64, r_out: f64, r_in: f64) -> Vector3<f64> {
        let mut pts = Vec::new();
        for (r, wr) in gauss(r_in, r_out) {
            for (t, wt) in turn(8) {
                pts.push(([r * t.cos(), r * t.sin(), 0.0], r * wr * wt));
            }
        }
        moments(m, pts.into_iter())
    }

    /// Sphere or hollow sphere, in r, u = cos φ and θ (dV = r² dr du dθ).
    fn sphere_quadrature(m: f64, r_out: f64, r_in: f64) -> Vector3<f64> {
        let mut pts = Vec::new();
        for (r, wr) in gauss(r_in, r_out) {
            for (u, wu) in gauss(-1.0, 1.0) {
                for (t, wt) in turn(8) {
                    let s = (1.0 - u * u).sqrt();
                    pts.push((
                        [r * s * t.cos(), r * s * t.sin(), r * u],
                        r * r * wr * wu * wt,
                    ));
                }
            }
        }
        moments(m, pts.into_iter())
    }

    fn assert_rel(a: Vector3<f64>, b: Vector3<f64>, what: &str) {
        let tol = 16.0 * f64::EPSILON * b.amax();
        assert!((a - b).amax() <= tol, "{what}: {a} vs {b}");
    }

    #[test]
    fn cylinder_and_tube_closed_forms_match_quadrature() {
        for (r_in, what) in [(0.0, "solid"), (0.3, "tube"), (0.69, "thin tube")] {
            assert_rel(
                Shape::Cylinder.local_second_moment(2.5, &[0.7, r_in, 1.9]),
                cylinder_quadrature(2.5, 0.7, r_in, 1.9),
                what,
            );
        }
    }

    #[test]
    fn disk_and_annulus_closed_forms_match_quadrature() {
        for r_in in [0.0, 0.05, 0.1249] {
            assert_rel(
                Shape::Disk.local_second_moment(0.8, &[0.125, r_in]),
                disk_quadrature(0.8, 0.125, r_in),
                "disk",
            );
        }
    }

    #[test]
    fn sphere_and_hollow_sphere_closed_forms_match_quadrature() {
        for r_in in [0.0, 0.2, 0.39] {
            assert_rel(
                Shape::Sphere.local_second_moment(3.0, &[0.4, r_in]),
                sphere_quadrature(3.0, 0.4, r_in),
                "sphere",
            );
        }
    }

    #[test]
    fn a_thin_spherical_shell_is_the_surface_average() {
        // r = R: ∫x² dA / A over the sphere, by quadrature in u and θ.
        let mut pts = Vec::new();
        for (u, wu) in gauss(-1.0, 1.0) {
            for (t, wt) in turn(8) {
                let s = (1.0 - u * u).sqrt();
                pts.push(([1.5 * s * t.cos(), 1.5 * s * t.sin(), 1.5 * u], wu * wt));
            }
        }
        assert_rel(
            Shape::Sphere.local_second_moment(2.0, &[1.5, 1.5]),
            moments(2.0, pts.into_iter()),
            "shell",
        );
    }

    #[test]
    fn hollow_shapes_are_the_solid_minus_the_core() {
        // Same density: (m I)_hollow = (m I)_outer − (m I)_inner, with each
        // mass from the measure.
        let rho = 7850.0;
        for (shape, outer, inner, hollow) in [
            (
                Shape::Cylinder,
                vec![0.5, 0.0, 2.0],
                vec![0.3, 0.0, 2.0],
                vec![0.5, 0.3, 2.0],
            ),
            (Shape::Disk, vec![0.5, 0.0], vec![0.3, 0.0], vec![0.5, 0.3]),
            (
                Shape::Sphere,
                vec![0.5, 0.0],
                vec![0.3, 0.0],
                vec![0.5, 0.3],
            ),
        ] {
            let (mo, mi, mh) = (
                rho * shape.measure(&outer),
                rho * shape.measure(&inner),
                rho * shape.measure(&hollow),
            );
            assert!(
                (mo - mi - mh).abs() <= 8.0 * f64::EPSILON * mo,
                "{shape:?} mass"
            );
            let diff =
                shape.local_second_moment(mo, &outer) - shape.local_second_moment(mi, &inner);
            assert_rel(shape.local_second_moment(mh, &hollow), diff, shape.name());
        }
    }

    #[test]
    fn measures_are_the_textbook_volumes_and_areas() {
        use std::f64::consts::PI;
        let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b;
        assert!(close(Shape::Cylinder.measure(&[2.0, 0.0, 3.0]), 12.0 * PI));
        assert!(close(Shape::Disk.measure(&[2.0, 1.0]), 3.0 * PI));
        assert!(close(Shape::Sphere.measure(&[3.0, 0.0]), 36.0 * PI));
        assert_eq!(Shape::Sphere.measure(&[3.0, 3.0]), 0.0);
    }
}
