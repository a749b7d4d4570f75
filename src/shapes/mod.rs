//! The primitive shapes, one module each (`src/shapes/<shape>.rs`): its
//! description and its closed forms, second moments of mass about the
//! shape's own centroid along its own local axes, ∫x² dm, ∫y² dm, ∫z² dm,
//! behind one trait, `ShapeKind`, and named once in `registry!`. Each
//! module's opening comment gives its local frame and the derivation of
//! its closed forms.
//!
//! Every shape but the prism is symmetric about its local x–z and y–z
//! planes, so its second moments about its centroid are diagonal in local
//! axes and need no products of inertia. A plate's real `thickness` and a
//! rod's `diameter` never enter these: the composition is the idealised
//! one, and `report::ideal` compares it with the solid box and cylinder
//! they describe.

#[macro_use]
mod centred;
mod common;
pub mod error;
mod info;
mod lift;
pub mod outline;
mod place;
#[cfg(test)]
mod quadrature;
pub mod read;

use crate::diag::Diagnostic;
pub use error::{Own, Units};
pub use lift::{Dep, Fixed, Lift, Seed, Slot, lift3, xyz};
pub use outline::Outline;
pub use place::{Mover, Placed};
pub use read::Reader;

#[cfg(test)]
pub use info::PROBE;
pub use info::{
    DensityKind, Explain, Fill, Key, Kind, MaterialRule, PER_AREA, PER_LENGTH, PER_VOLUME, Scope,
    ShapeInfo, Solid, Spanned, Symbol, own_key, symbol,
};

use crate::la::Vector3;
use crate::numeric::{DD, M3, Real};
use serde::Serialize;

/// Everything one shape's module says of it: its description (`INFO`:
/// keys, density, dimensions, placements, help), its closed forms generic
/// over the arithmetic, with the roundings its error model counts, its
/// mirror symmetry; and, implemented by the shape's placed form (its
/// numbers in its file's units, named), all that reads or moves them: its
/// physics generic over the arithmetic and over how its numbers are read
/// (`Lift`), its error model, a frame's move, a mirror, a tolerance's
/// slots, and its outline. Each shape is one module,
/// `src/shapes/<shape>.rs`, and one line of `registry!`; the `Shape` and
/// `Place` enums and their dispatch are made from that list, so a shape
/// whose module does not answer in full does not compile.
pub trait ShapeKind: Clone + std::fmt::Debug + PartialEq + Sized {
    const INFO: ShapeInfo;
    /// How `massprop explain` writes its closed forms (`info::Explain`).
    const EXPLAIN: Explain;
    /// The keys this shape declares itself (a key no other part has, such
    /// as an ellipsoid's `radii`): each also listed in `INFO.keys`, read
    /// by the model's reader as declared (kind, dimension, "±", > 0) and
    /// kept on the part generically, and asked for in `read` through
    /// `Reader::quantity` or `Reader::quantities`. Keys every part may
    /// have are declared in `model::keys`.
    const OWN_KEYS: &'static [Key] = &[];
    /// Roundings of the measure (volume, area or length) formed from its
    /// dimensions, beyond the density's product (`part::error::mass_error`).
    const MEASURE_ROUNDINGS: f64;
    /// Roundings of its local second moments beyond its mass's
    /// (`shapes::error`), counted over the operations of `moments_of`,
    /// every sum of terms of one sign.
    const MOMENT_ROUNDINGS: f64;
    /// The local axis in whose plane through the local origin the shape,
    /// as its closed forms take it, is its own mirror image; `None`: in no
    /// plane (its data reflected instead, `mirror`).
    const MIRROR_AXIS: Option<usize>;
    /// Volume, area or length of a shape of dimensions `d` (in the order
    /// its closed forms take them), the measure that the density multiplies.
    fn measure_of<T: Real>(d: &[T]) -> T;
    /// ∫x² dm, ∫y² dm, ∫z² dm about the centroid in local axes, of mass
    /// `m` and dimensions `d`.
    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3];
    /// The offset of the centroid from the origin of the local frame,
    /// along local z.
    fn offset_of<T: Real>(d: &[T]) -> T;

    /// Its placed form from a part's numbers, in the order it asks for
    /// them (`read::Reader`).
    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic>;

    /// Volume, area or length of the placed shape, the measure its
    /// density multiplies, its numbers read through `l`.
    fn measure<T: Real, L: Lift>(&self, l: L) -> T;
    /// Roundings of `measure` (`part::error::mass_error`).
    fn measure_error(&self) -> f64;
    /// Its centroid in the file's frame, in the arithmetic `T`, its
    /// numbers read through `l`.
    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3];
    /// How far each component of its centroid, as `centroid` forms it in
    /// double-double, may lie from the exact one, with the frames'
    /// rounding of its position `at`.
    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3];
    /// ∫ρρᵀ dm about its centroid, in the file's axes and units, for the
    /// mass `m`; with its error model when `units` are given.
    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        l: L,
    ) -> (M3<T>, Option<Own>);
    /// The shortest span between the points that place it (a rod's ends,
    /// a triangle's vertices), over which the frames' rounding of them
    /// counts (`error::placed_units`); infinite for a shape placed by one
    /// point.
    fn shortest_span(&self) -> f64;
    /// The second moments (mass `m`, own second moment `j`) that must each
    /// be a normal f64 in the file's units, how many, and how many must be
    /// non-zero.
    fn independent_moments(&self, m: f64, j: &M3<f64>) -> ([f64; 3], usize, usize);
    /// Its numbers moved by `m`, in place: points moved, edges and sizes
    /// scaled (and edges turned), turns turned.
    fn moved(&mut self, m: &impl Mover);
    /// The power of length its density is per: how it scales when a
    /// sub-assembly's units are converted.
    fn density_power(&self) -> i32;
    /// The units of its sizes by which scaling it in its own frame changes
    /// its shape (a prism's polygon); `None` if nothing is so scaled.
    fn scaled_rounding(&self) -> Option<f64>;
    /// The largest |p|₁ of the points that place it, before a frame moves
    /// them.
    fn reach(&self) -> f64;
    /// The points that place it, and its edges (`common::points`).
    fn positions(&self) -> ([[f64; 3]; 4], usize);
    /// Each of its numbers a tolerance can move (all but the mass), with
    /// its slot.
    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64));
    /// Made `src` again in place, field by field (a walk places each copy
    /// of a part afresh: no temporary, no clone of a turn or a shared
    /// mesh that is the same).
    fn reset_from(&mut self, src: &Self);
    /// Completed as its mirror image, once a reflection has moved its
    /// points and turned its turn (S R becomes S R F).
    fn mirror(&mut self);
    /// The direction of its real size: a plate's normal, a rod's axis, of
    /// any length (`analysis::ideal`); `None` for a shape with none.
    fn real_size_direction(&self) -> Option<[DD; 3]>;
    /// Its outline in 3-D in the file's frame (`outline`).
    fn outline(&self) -> Outline;
    /// Its turn R into the file's axes, as composed (`Place::turn`).
    fn turn(&self) -> Option<M3<f64>>;
}

/// The product of the dimensions (a box's volume, a plate's area, a rod's
/// length).
fn product<T: Real>(d: &[T]) -> T {
    d.iter().fold(T::of(1.0), |a, &x| a * x)
}

/// ∫x² dm of a uniform segment of length a centred on 0: m a²/12.
fn segment<T: Real>(m: T, a: T) -> T {
    m * a * a / T::of(12.0)
}

/// π(R − r)(R + r): the area of an annulus, no difference of squares.
fn ring<T: Real>(d: &[T]) -> T {
    T::pi() * (d[0] - d[1]) * (d[0] + d[1])
}

/// m (R² + r²)/4: a disk's or annulus's ∫x² dm about a diameter.
fn across_ring<T: Real>(m: T, r_out: T, r_in: T) -> T {
    m * (r_out * r_out + r_in * r_in) / T::of(4.0)
}

/// R C Rᵀ, symmetric by construction (the upper triangle formed, the
/// lower its mirror): a full local tensor C in the file's axes (a given
/// inertia, a prism's).
pub(crate) fn turned<T: Real>(r: &M3<T>, local: &M3<T>) -> M3<T> {
    let mut j = [[T::of(0.0); 3]; 3];
    for a in 0..3 {
        for b in a..3 {
            let mut v = T::of(0.0);
            for k in 0..3 {
                for l in 0..3 {
                    v = v + r[a][k] * local[k][l] * r[b][l];
                }
            }
            j[a][b] = v;
            j[b][a] = v;
        }
    }
    j
}

/// The one list of shapes: `Variant => module::Kind`, in the order the
/// docs and messages list them. Makes the `Shape` enum, `Shape::ALL`,
/// `SHAPES` (each module's `INFO`), the `Place` enum (each shape's placed
/// form, `module::Kind`) and the dispatch of both to each module's
/// `ShapeKind`.
macro_rules! registry {
    ($($(#[$doc:meta])* $variant:ident => $module:ident :: $kind:ident,)+) => {
        $(pub mod $module;)+

        #[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
        #[serde(rename_all = "lowercase")]
        pub enum Shape {
            $($(#[$doc])* $variant,)+
        }

        /// A placed shape: its numbers in its file's units, as its module
        /// names them.
        #[derive(Clone, Debug, PartialEq)]
        pub enum Place {
            $($variant($module::$kind),)+
        }

        impl Shape {
            pub const ALL: [Shape; [$(Shape::$variant),+].len()] = [$(Shape::$variant),+];

            /// Volume, area or length of a shape of dimensions `d` (in the
            /// order its closed forms take them), the measure that the density
            /// multiplies.
            pub fn measure_of<T: Real>(self, d: &[T]) -> T {
                match self {
                    $(Shape::$variant => <$module::$kind as ShapeKind>::measure_of(d),)+
                }
            }

            /// ∫x² dm, ∫y² dm, ∫z² dm about the centroid in local axes, of
            /// mass `m` and dimensions `d`.
            pub fn second_moments<T: Real>(self, m: T, d: &[T]) -> [T; 3] {
                match self {
                    $(Shape::$variant => <$module::$kind as ShapeKind>::moments_of(m, d),)+
                }
            }

            /// How `explain` writes its closed forms (`ShapeKind::EXPLAIN`).
            pub fn explain(self) -> &'static Explain {
                match self {
                    $(Shape::$variant => &<$module::$kind as ShapeKind>::EXPLAIN,)+
                }
            }

            /// The keys its module declares itself (`ShapeKind::OWN_KEYS`).
            pub fn own_keys(self) -> &'static [Key] {
                #[cfg(test)]
                if self == Shape::Point {
                    return &[PROBE];
                }
                match self {
                    $(Shape::$variant => <$module::$kind as ShapeKind>::OWN_KEYS,)+
                }
            }

            /// The offset of the centroid from the origin of the local
            /// frame, along local z, of a shape of dimensions `d`.
            pub fn axial_offset<T: Real>(self, d: &[T]) -> T {
                match self {
                    $(Shape::$variant => <$module::$kind as ShapeKind>::offset_of(d),)+
                }
            }

        }

        /// Each shape's description, in the order of `Shape`'s variants.
        pub const SHAPES: [ShapeInfo; Shape::ALL.len()] =
            [$(<$module::$kind as ShapeKind>::INFO,)+];

        impl Place {
            /// A part of `shape`'s placed form, read by its module.
            pub fn read(shape: Shape, r: &mut impl Reader) -> Result<Place, Diagnostic> {
                Ok(match shape {
                    $(Shape::$variant => Place::$variant(<$module::$kind as ShapeKind>::read(r)?),)+
                })
            }

            /// Its shape.
            pub fn shape(&self) -> Shape {
                match self {
                    $(Place::$variant(_) => Shape::$variant,)+
                }
            }

            /// `ShapeKind::measure`.
            pub fn measure<T: Real, L: Lift>(&self, l: L) -> T {
                match self {
                    $(Place::$variant(s) => s.measure(l),)+
                }
            }

            /// `ShapeKind::measure_error`.
            pub fn measure_error(&self) -> f64 {
                match self {
                    $(Place::$variant(s) => s.measure_error(),)+
                }
            }

            /// `ShapeKind::centroid`.
            pub fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
                match self {
                    $(Place::$variant(s) => s.centroid(l),)+
                }
            }

            /// `ShapeKind::centroid_error`.
            pub fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
                match self {
                    $(Place::$variant(s) => s.centroid_error(at, centroid),)+
                }
            }

            /// `ShapeKind::own_second_moment`.
            pub fn own_second_moment<T: Real, L: Lift>(
                &self,
                m: T,
                units: Option<Units>,
                l: L,
            ) -> (M3<T>, Option<Own>) {
                match self {
                    $(Place::$variant(s) => s.own_second_moment(m, units, l),)+
                }
            }

            /// `ShapeKind::shortest_span`.
            pub fn shortest_span(&self) -> f64 {
                match self {
                    $(Place::$variant(s) => s.shortest_span(),)+
                }
            }

            /// `ShapeKind::independent_moments`.
            pub fn independent_moments(&self, m: f64, j: &M3<f64>) -> ([f64; 3], usize, usize) {
                match self {
                    $(Place::$variant(s) => s.independent_moments(m, j),)+
                }
            }

            /// `ShapeKind::moved`.
            pub fn moved(&mut self, m: &impl Mover) {
                match self {
                    $(Place::$variant(s) => s.moved(m),)+
                }
            }

            /// `ShapeKind::density_power`.
            pub fn density_power(&self) -> i32 {
                match self {
                    $(Place::$variant(s) => s.density_power(),)+
                }
            }

            /// `ShapeKind::scaled_rounding`.
            pub fn scaled_rounding(&self) -> Option<f64> {
                match self {
                    $(Place::$variant(s) => s.scaled_rounding(),)+
                }
            }

            /// `ShapeKind::reach`.
            pub fn reach(&self) -> f64 {
                match self {
                    $(Place::$variant(s) => s.reach(),)+
                }
            }

            /// Every coordinate of the points that place it, and its
            /// edges' (`ShapeKind::positions`; held in place: asked of
            /// every copy).
            pub fn positions(&self) -> impl Iterator<Item = f64> {
                let (points, n) = match self {
                    $(Place::$variant(s) => s.positions(),)+
                };
                points.into_iter().take(n).flatten()
            }

            /// `ShapeKind::numbers`.
            pub fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
                match self {
                    $(Place::$variant(s) => s.numbers(f),)+
                }
            }

            /// `ShapeKind::reset_from` where both are one shape's; another
            /// shape's made whole.
            pub fn reset_from(&mut self, src: &Place) {
                match (self, src) {
                    $((Place::$variant(d), Place::$variant(s)) => d.reset_from(s),)+
                    (d, s) => *d = s.clone(),
                }
            }

            /// `ShapeKind::mirror`.
            pub fn mirror(&mut self) {
                match self {
                    $(Place::$variant(s) => s.mirror(),)+
                }
            }

            /// `ShapeKind::real_size_direction`.
            pub fn real_size_direction(&self) -> Option<[DD; 3]> {
                match self {
                    $(Place::$variant(s) => s.real_size_direction(),)+
                }
            }

            /// `ShapeKind::outline`.
            pub fn outline(&self) -> Outline {
                match self {
                    $(Place::$variant(s) => s.outline(),)+
                }
            }
        }
    };
}

registry! {
    Box => r#box::Cuboid,
    Plate => plate::Plate,
    Rod => rod::Rod,
    Cylinder => cylinder::Cylinder,
    Disk => disk::Disk,
    Sphere => sphere::Sphere,
    /// A thin triangular plate given by its three vertices.
    Triangle => triangle::Triangle,
    Point => point::Point,
    /// A bought or previously computed component: mass, centre and inertia
    /// tensor given (no closed form here; see `part::Place::Given`).
    Inertia => inertia::Given,
    /// A cone or frustum, solid or hollow.
    Cone => cone::Cone,
    /// A torus, solid or hollow.
    Torus => torus::Torus,
    /// A hemisphere, solid or hollow.
    Hemisphere => hemisphere::Hemisphere,
    /// A polygon extruded along local z.
    Prism => prism::Prism,
    /// A triangle mesh read from a file: its integrals are computed from
    /// the file (`mesh`, `part::Place::Mesh`), no closed form here.
    Mesh => mesh::Mesh,
    /// A cylinder with hemispherical ends, solid or hollow.
    Capsule => capsule::Capsule,
    /// A solid ellipsoid given by its three semi-axes.
    Ellipsoid => ellipsoid::Ellipsoid,
}

impl Shape {
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

    /// How many of the three local second moments are non-zero.
    pub fn nonzero_moments(self) -> usize {
        self.info().nonzero_moments
    }

    /// The key of the density that this shape takes instead of `mass`.
    pub fn density_key(self) -> Option<&'static str> {
        self.info().density.map(|d| d.key)
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
            assert!(info.a_name().ends_with(info.name), "{}", info.name);
        }
    }

    #[test]
    fn a_shape_is_named_with_its_article() {
        assert_eq!(Shape::Box.info().a_name(), "a box");
        assert_eq!(Shape::Ellipsoid.info().a_name(), "an ellipsoid");
        assert_eq!(Shape::Inertia.info().a_name(), "an inertia");
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
