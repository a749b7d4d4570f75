//! A part: one primitive as the file gave it (`Spec`, file units), and its
//! physics — mass, centroid and own second moment — in the precision asked
//! for. The composer, the per-part figures of every report and the checks
//! on the input all use these functions: one path per quantity.

use crate::numeric::{DD, M3, Real, norm_of};
use crate::rotation::Orientation;
use crate::shapes::Shape;
use crate::units::{Dim, FileUnits};
use nalgebra::{Matrix3, Vector3};
use std::ops::Range;
use std::sync::Arc;

pub mod error;
mod lift;
pub mod mirror;
mod offset;

pub use error::Own;
pub use lift::{Dep, Fixed, Lift, Seed, Slot};
use lift::{lift3, xyz};

pub use crate::shapes::Solid;

/// A plate's `thickness` or a rod's `diameter`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RealSize {
    /// Index of the part in `Model::parts`.
    pub part: usize,
    pub solid: Solid,
    /// Thickness (box) or diameter (cylinder), in the file's length unit.
    pub size: f64,
}

/// One primitive: its shape and its numbers as the file gave them, in the
/// file's units. This is the only representation of a part; the SI view
/// (`Part::si`) and everything the composer uses are derived from `spec` by
/// the functions below, so a part's own figures and the composite's come
/// from the same arithmetic.
#[derive(Debug, Clone)]
pub struct Part {
    /// The part's `name`, or `part N` (1-based position in the file); for
    /// a part of a sub-assembly, its path: `elbow / motor / stator`. Empty
    /// in a model's items for a part the file does not name (`named`
    /// false): a walk that names parts (`Model::each_part`) gives it
    /// `part N`.
    pub name: String,
    /// Whether the file gave `name` (which may be `""`).
    pub named: bool,
    pub shape: Shape,
    /// The part as the file gave it, in the file's units.
    pub spec: Spec,
    /// The sub-assemblies the part is in, outermost first (empty for a
    /// part of the file itself).
    pub assembly: Vec<String>,
    /// Its `[[part]]` table in the file (for a part of a sub-assembly, the
    /// table that includes it), to point at it when a sum overflows.
    pub span: Range<usize>,
    /// How its numbers move with its file's tolerances (none for most
    /// parts), in its own file's units and frame.
    pub tol: Option<Arc<[Dep]>>,
    /// The `material` it is made of, by name (drawings colour by it).
    pub material: Option<Arc<str>>,
}

/// A body's parts, for the passes of the composer and of the per-part
/// figures: a list, or a model walked (`model::walk`).
pub trait Parts {
    /// Each part, in order.
    fn each(&self, f: &mut dyn FnMut(&Part));
}

impl Parts for [Part] {
    fn each(&self, f: &mut dyn FnMut(&Part)) {
        self.iter().for_each(f);
    }
}

impl Parts for Vec<Part> {
    fn each(&self, f: &mut dyn FnMut(&Part)) {
        self.iter().for_each(f);
    }
}

/// A part's mass properties in SI, derived from its `Spec` by exact unit
/// factors in double-double, the product rounded to f64.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartSi {
    /// kg; negative for a cut-out (`remove = true`).
    pub mass: f64,
    /// Centroid in the file's frame, m.
    pub center: Vector3<f64>,
    /// ∫ρρᵀ dm about the centroid in the file's axes, kg·m² (negative
    /// semi-definite for a cut-out).
    pub second_moment: Matrix3<f64>,
}

/// The exact factors from a file's units to SI, formed once (each is a
/// rational computed in i128) for all the parts of a body.
#[derive(Debug, Clone, Copy)]
pub struct SiFactors {
    pub mass: DD,
    pub length: DD,
    /// kg·m² per file unit of inertia, rounded once.
    pub inertia: f64,
}

impl SiFactors {
    pub fn of(units: FileUnits) -> SiFactors {
        SiFactors {
            mass: units.factor(Dim::MASS).dd(),
            length: units.factor(Dim::LENGTH).dd(),
            inertia: units.factor(Dim::INERTIA).value(),
        }
    }
}

impl Part {
    /// Mass in file units: given, or density times volume, area or length;
    /// negative for a cut-out.
    pub fn mass<T: Real>(&self) -> T {
        mass_of(self.shape, &self.spec)
    }

    /// `own_second_moment` with its error model (`part::error`).
    pub fn own_second_moment_bounded<T: Real>(&self, m: T) -> (M3<T>, Own) {
        own_second_moment_bounded(self.shape, &self.spec, m)
    }

    /// Centroid in file units, in double-double (see `centroid`).
    pub fn centroid(&self) -> [DD; 3] {
        centroid(self.shape, &self.spec.place)
    }

    /// ∫ρρᵀ dm about the centroid, file axes and units, for the mass `m`
    /// (see `own_second_moment`).
    pub fn own_second_moment<T: Real>(&self, m: T) -> M3<T> {
        own_second_moment(self.shape, &self.spec, m)
    }

    /// The part in SI: mass and centroid from the same arithmetic the
    /// composer uses, times the exact unit factors in double-double, the
    /// product rounded to f64; the second
    /// moment in f64 (it serves comparisons and blame, not sums).
    pub fn si(&self, units: FileUnits) -> PartSi {
        self.si_in(&SiFactors::of(units))
    }

    /// `si` with the unit factors formed once for many parts.
    pub fn si_in(&self, f: &SiFactors) -> PartSi {
        let m: f64 = self.mass();
        let own: M3<f64> = self.own_second_moment(m);
        PartSi {
            mass: (DD::of(m) * f.mass).f64(),
            center: self.center_si(f),
            second_moment: Matrix3::from_fn(|i, j| own[i][j] * f.inertia),
        }
    }

    /// The mass in SI (kg): the f64 mass in file units that the `standard`
    /// composer sums (a density already converted to file units, so with
    /// the rounding of that conversion), times the exact unit factor in
    /// double-double, rounded to f64.
    ///
    /// NOTE: f64, not double-double: in `standard` this is exactly the mass
    /// the composite is made of, so the parts' masses add up to the body's
    /// to the rounding of the sum; in `extended` the composite's parts
    /// carry ~16 more digits that a figure rounded to f64 would not show.
    /// Double-double square roots for parts placed by edges would cost
    /// ~5 % of a 100,000-part report for none of those digits.
    pub fn mass_si(&self, f: &SiFactors) -> f64 {
        (DD::of(self.mass::<f64>()) * f.mass).f64()
    }

    /// The centroid in SI (m), as in `si`.
    pub fn center_si(&self, f: &SiFactors) -> Vector3<f64> {
        Vector3::from(self.centroid().map(|x| (x * f.length).f64()))
    }
}

/// A part's numbers as the file gave them, in the file's units (a quantity
/// written with its own unit converted once, by an exact ratio).
///
/// NOTE: the composer works from these, not from the SI values above, and
/// converts only its results to SI. Converting every input first would
/// round each coordinate on its own: for parts 10⁹ sizes from the origin in
/// a millimetre file that alone moves them relative to each other by 1e-7
/// of their size.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    pub mass: MassSpec,
    pub place: Place,
    /// `remove = true`: a cut-out, composed with negative mass.
    pub removed: bool,
    /// How far the frames of the sub-assemblies the part is in moved its
    /// numbers by rounding (`model::frame::Frame::place`); none for a
    /// part of the file itself.
    pub placed: Placed,
}

/// The rounding of a part's numbers by the frames that placed it, for its
/// error bounds (`part::error`): `units` of f64's unit roundoff, relative,
/// in its sizes, edges, mass or density and tensor entries; `at`, absolute
/// (file units), in each coordinate of its position. Rounded up to f32
/// (they are bounds; a part stays small).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Placed {
    pub units: f32,
    pub at: f32,
}

impl Placed {
    /// `units` and `at`, each rounded up to f32.
    pub fn new(units: f64, at: f64) -> Placed {
        let up = |x: f64| {
            let y = x as f32;
            if f64::from(y) < x { y.next_up() } else { y }
        };
        Placed {
            units: up(units),
            at: up(at),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassSpec {
    Given(f64),
    /// Density per volume, area or length, times the shape's measure.
    Density(f64),
}

#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// `center`, the shape's dimensions as `Shape::second_moments` takes
    /// them (box [a, b, c], plate [a, b], rod `[L]`, cylinder [R, r, L], disk
    /// and sphere [R, r]), padded with 0, and the turn of the local axes.
    Centered {
        center: [f64; 3],
        extent: [f64; 3],
        orientation: Orientation,
    },
    /// `corner` and the shape's edges (a plate uses the first two).
    Edges {
        corner: [f64; 3],
        edges: [[f64; 3]; 3],
    },
    /// A rod `from` → `to`.
    FromTo { from: [f64; 3], to: [f64; 3] },
    /// A thin triangular plate's three vertices in the file's frame.
    Vertices([[f64; 3]; 3]),
    /// A given inertia tensor (tensor convention, symmetric, local axes,
    /// file units) about the centroid `center`, turned by `orientation`.
    Given {
        center: [f64; 3],
        inertia: Box<[[f64; 3]; 3]>,
        orientation: Orientation,
    },
    /// A cone or a hemisphere: `center` (the middle of the cone's axis,
    /// the centre of the hemisphere's sphere), the dimensions as
    /// `Shape::second_moments` takes them (cone [R₀, a₀, R₁, a₁, L],
    /// hemisphere [R, r]), padded with 0, and the turn of the local axes.
    /// Its centroid lies off `center` along local z
    /// (`Shape::axial_offset`).
    Axial {
        center: [f64; 3],
        dims: [f64; 5],
        orientation: Orientation,
    },
    /// A prism: where its local origin goes, its polygon in the local x–y
    /// plane (file units, either orientation), its length along local z
    /// (from −length/2 to +length/2) and the turn of the local axes.
    Prism {
        origin: [f64; 3],
        polygon: Arc<[[f64; 2]]>,
        length: f64,
        orientation: Orientation,
    },
    /// A triangle mesh's integrals (`mesh::MeshBody`, in its file's
    /// coordinates and units), scaled by `scale` (its file's unit in this
    /// file's length unit, exact in double-double), turned by
    /// `orientation` and its file's origin put at `origin`, as an include
    /// is placed.
    Mesh {
        origin: [f64; 3],
        orientation: Orientation,
        scale: DD,
        mesh: std::sync::Arc<crate::mesh::MeshBody>,
    },
}

/// The diagonal entry `a` of ∫ρρᵀ dm = tr(I)/2 E − I of a given tensor:
/// (I_jj + I_kk − I_aa)/2, formed as ((I_jj − I_aa) + I_kk)/2 with I_jj
/// the one of the other two closer to I_aa.
///
/// NOTE: not tr(I)/2 − I_aa: for a long thin component given by its
/// datasheet (principal moments 1e-12, 1, 1: an antenna), tr(I)/2 rounds
/// to an ulp of 1 and the two small entries lost all but 4 digits (2e-4).
/// I_jj − I_aa of the closer pair is exact when they are within a factor
/// of 2 (Sterbenz), which the triangle inequality of a valid tensor makes
/// the case whenever the result is small; so the entry rounds once.
fn diagonal_second_moment<T: Real>(i: &M3<T>, a: usize) -> T {
    let (j, k) = ((a + 1) % 3, (a + 2) % 3);
    let distance = |b: usize| {
        let d = i[b][b] - i[a][a];
        if d < T::of(0.0) { -d } else { d }
    };
    let (j, k) = if distance(j) <= distance(k) {
        (j, k)
    } else {
        (k, j)
    };
    ((i[j][j] - i[a][a]) + i[k][k]) / T::of(2.0)
}

/// The magnitude the diagonal entry `a` of a given tensor's second moment
/// is formed from in `diagonal_second_moment`: (|I_jj − I_aa| + |I_kk|)/2,
/// its error at most 2 units of it.
fn diagonal_magnitude<T: Real>(i: &M3<T>, a: usize) -> f64 {
    let (j, k) = ((a + 1) % 3, (a + 2) % 3);
    let f = |x: T| x.f64();
    let dist = |b: usize| (f(i[b][b]) - f(i[a][a])).abs();
    let (j, k) = if dist(j) <= dist(k) { (j, k) } else { (k, j) };
    (dist(j) + f(i[k][k]).abs()) / 2.0
}

/// Mass of a part (file units): given, or density times volume, area or
/// length; negative for a cut-out.
pub fn mass_of<T: Real>(shape: Shape, spec: &Spec) -> T {
    mass_in(shape, spec, Fixed)
}

/// `mass_of`, the spec's numbers read through `l`.
pub fn mass_in<T: Real, L: Lift>(shape: Shape, spec: &Spec, l: L) -> T {
    let m: T = unsigned_mass_of(shape, spec, l);
    if spec.removed { -m } else { m }
}

/// The dimensions of a centred or axial part, read through `l`.
fn dims_in<T: Real, L: Lift, const N: usize>(d: &[f64; N], l: L) -> [T; N] {
    std::array::from_fn(|k| T::var(d[k], l.rate(Slot::Dim(k as u8))))
}

/// A corner-and-edges part's edges, read through `l`.
fn edges_in<T: Real, L: Lift>(edges: &[[f64; 3]; 3], l: L) -> [[T; 3]; 3] {
    std::array::from_fn(|e| lift3(l, &edges[e], xyz(|i| Slot::Edge(e as u8, i))))
}

/// A rod's `to − from`, read through `l`.
fn span_in<T: Real, L: Lift>(from: &[f64; 3], to: &[f64; 3], l: L) -> [T; 3] {
    let a: [T; 3] = lift3(l, from, xyz(Slot::At));
    let b: [T; 3] = lift3(l, to, xyz(Slot::To));
    std::array::from_fn(|i| b[i] - a[i])
}

fn unsigned_mass_of<T: Real, L: Lift>(shape: Shape, spec: &Spec, l: L) -> T {
    match spec.mass {
        MassSpec::Given(m) => T::var(m, l.rate(Slot::Mass)),
        MassSpec::Density(rho) => {
            let measure = match (&spec.place, shape) {
                (Place::Centered { extent: e, .. }, _) => {
                    let e: [T; 3] = dims_in(e, l);
                    shape.measure_of(&e[..shape.dim_count()])
                }
                (Place::Edges { edges, .. }, _) => edges_in::<T, L>(edges, l)[..shape.edge_count()]
                    .iter()
                    .fold(T::of(1.0), |acc, e| acc * norm_of(e)),
                (Place::FromTo { from, to }, _) => norm_of(&span_in::<T, L>(from, to, l)),
                (Place::Given { .. }, _) => T::of(1.0),
                (Place::Axial { dims, .. }, _) => {
                    let d: [T; 5] = dims_in(dims, l);
                    shape.measure_of(&d[..shape.dim_count()])
                }
                (
                    Place::Prism {
                        polygon, length, ..
                    },
                    _,
                ) => {
                    let area = crate::shapes::prism::polygon(polygon).area;
                    T::of_dd(area) * T::var(*length, l.rate(Slot::Dim(0)))
                }
                (Place::Mesh { scale, mesh, .. }, _) => {
                    let s = T::of_dd(*scale);
                    let mut m = T::of_dd(mesh.measure);
                    for _ in 0..mesh.mode.power() {
                        m = m * s;
                    }
                    m
                }
                (Place::Vertices(v), _) => {
                    let d = triangle_offsets::<T, L>(v, l);
                    let (a, b) = (sub3(d[1], d[0]), sub3(d[2], d[0]));
                    let c = [
                        a[1] * b[2] - a[2] * b[1],
                        a[2] * b[0] - a[0] * b[2],
                        a[0] * b[1] - a[1] * b[0],
                    ];
                    norm_of(&c) / T::of(2.0)
                }
            };
            T::var(rho, l.rate(Slot::Mass)) * measure
        }
    }
}

/// Centroid of a part (file units), in double-double: a corner plus half
/// its edges is not an f64 in general, and far from the origin its rounding
/// would move the part relative to its neighbours.
pub fn centroid(shape: Shape, place: &Place) -> [DD; 3] {
    centroid_in(shape, place, Fixed)
}

/// `centroid` in the arithmetic `T`, the numbers read through `l` (in
/// double-double with `Fixed`, the same operations as `centroid`).
pub fn centroid_in<T: Real, L: Lift>(shape: Shape, place: &Place, l: L) -> [T; 3] {
    let half = T::of(0.5);
    match place {
        Place::Axial { .. } | Place::Prism { .. } => offset::centroid(shape, place, l),
        Place::Centered { center, .. } | Place::Given { center, .. } => {
            lift3(l, center, xyz(Slot::At))
        }
        Place::Vertices(v) => triangle_centroid(v, l),
        Place::Edges { corner, edges } => {
            let c: [T; 3] = lift3(l, corner, xyz(Slot::At));
            let e: [[T; 3]; 3] = edges_in(edges, l);
            std::array::from_fn(|i| e.iter().fold(c[i], |acc, e| acc + e[i] * half))
        }
        Place::FromTo { from, to } => {
            let a: [T; 3] = lift3(l, from, xyz(Slot::At));
            let b: [T; 3] = lift3(l, to, xyz(Slot::To));
            std::array::from_fn(|i| (a[i] + b[i]) * half)
        }
        Place::Mesh {
            origin,
            orientation,
            scale,
            mesh,
        } => {
            let r: M3<T> = orientation.matrix();
            let c = mesh.centroid.map(|x| T::of_dd(x * *scale));
            let o: [T; 3] = lift3(l, origin, xyz(Slot::At));
            std::array::from_fn(|i| o[i] + r[i][0] * c[0] + r[i][1] * c[1] + r[i][2] * c[2])
        }
    }
}

/// A mesh's own second moment, C = m s² R (J/V) Rᵀ for its integrals'
/// J about the centroid and measure V (volume or area) in its file's
/// units and the scale s to this file's, with its error model: J/V's
/// bound (absolute, from `mesh::Bound`) moved through R into every entry
/// (at most 3 of it, |R| rows of 1-norm √3 twice), and the mass's.
fn mesh_second_moment<T: Real>(
    spec: &Spec,
    orientation: &Orientation,
    scale: DD,
    mesh: &crate::mesh::MeshBody,
    m: T,
    bound: bool,
) -> (M3<T>, Option<Own>) {
    let v = T::of_dd(mesh.measure);
    let s = T::of_dd(scale);
    let k = m * s * s / v;
    let local: M3<T> = mesh.second.map(|row| row.map(|x| k * T::of_dd(x)));
    let r: M3<T> = orientation.matrix();
    let mut j = [[T::of(0.0); 3]; 3];
    for a in 0..3 {
        for b in a..3 {
            let mut x = T::of(0.0);
            for p in 0..3 {
                for q in 0..3 {
                    x = x + r[a][p] * local[p][q] * r[b][q];
                }
            }
            j[a][b] = x;
            j[b][a] = x;
        }
    }
    let own = bound.then(|| {
        let unit = error::unit_of::<T>();
        let rel_v = mesh.bound.measure / mesh.measure.hi.abs();
        let measured = match spec.mass {
            MassSpec::Density(_) => rel_v / unit,
            MassSpec::Given(_) => 0.0,
        };
        let mu = error::mass_error(Shape::Mesh, spec)
            + error::placed_units::<T>(&spec.place, &spec.placed)
            + measured;
        let kf = k.f64().abs();
        let rf = r.map(|row| row.map(T::f64));
        let rho = error::turn_error(orientation, &rf);
        let spread: f64 = (0..3).map(|a| local[a][a].f64().abs()).sum::<f64>()
            + (0..3)
                .flat_map(|p| (0..3).filter(move |q| *q != p).map(move |q| (p, q)))
                .map(|(p, q)| local[p][q].f64().abs())
                .sum::<f64>();
        // J/V's relative rounding of V (its bound) and J's absolute bound.
        let mut own = Own::turned(
            mu,
            mu + rel_v / unit + error::GIVEN + 4.0,
            std::array::from_fn(|a| j[a][a].f64().abs()),
            rho,
            spread,
        );
        own.rot += 3.0 * kf * mesh.bound.second / unit + spread * rel_v / unit;
        own
    });
    (j, own)
}

fn triangle_centroid<T: Real, L: Lift>(v: &[[f64; 3]; 3], l: L) -> [T; 3] {
    let p: [[T; 3]; 3] =
        std::array::from_fn(|k| lift3(l, &v[k], xyz(|i| Slot::Vertex(k as u8, i))));
    std::array::from_fn(|i| (p[0][i] + p[1][i] + p[2][i]) / T::of(3.0))
}

/// A triangle's vertices less its centroid, in double-double before the
/// rounding to T: far from the origin the offsets keep their digits (the
/// rates through `l` beside them: the vertex's less the centroid's).
fn triangle_offsets<T: Real, L: Lift>(v: &[[f64; 3]; 3], l: L) -> [[T; 3]; 3] {
    let g: [DD; 3] = triangle_centroid(v, Fixed);
    let rate = |k: usize, i: usize| l.rate(Slot::Vertex(k as u8, i as u8));
    std::array::from_fn(|k| {
        std::array::from_fn(|i| {
            let mean = (rate(0, i) + rate(1, i) + rate(2, i)) / 3.0;
            T::var_dd(DD::of(v[k][i]) - g[i], rate(k, i) - mean)
        })
    })
}

fn sub3<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    std::array::from_fn(|i| a[i] - b[i])
}

/// R C Rᵀ, symmetric by construction (the upper triangle formed, the
/// lower its mirror): a full local tensor C in the file's axes (a given
/// inertia, a prism's).
fn turned<T: Real>(r: &M3<T>, local: &M3<T>) -> M3<T> {
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

/// ∫ρρᵀ dm of a part about its own centroid, in the file's axes and units.
///
/// A uniform segment of length a centred on 0 has ∫x² dm = m a²/12, and each
/// shape is a product of such segments: R diag(m aₖ²/12) Rᵀ for a turned
/// shape, and Σₖ (m/12) eₖ eₖᵀ for one spanned by edge vectors eₖ, which
/// needs neither their lengths nor a rotation.
pub fn own_second_moment<T: Real>(shape: Shape, spec: &Spec, m: T) -> M3<T> {
    own_second_moment_in(shape, spec, m, false, Fixed).0
}

/// A part's mass, centroid and own second moment (file units and axes)
/// in the arithmetic `T`, its numbers read through `l`: in `dual::Dual`
/// with a `Seed`, each with its derivative by the seeded number (the
/// same functions as the composer's, so the derivatives are those of
/// the figures it composes).
pub fn physics_in<T: Real, L: Lift>(shape: Shape, spec: &Spec, l: L) -> (T, [T; 3], M3<T>) {
    let m: T = mass_in(shape, spec, l);
    let c = centroid_in(shape, &spec.place, l);
    let (j, _) = own_second_moment_in(shape, spec, m, false, l);
    (m, c, j)
}

/// `own_second_moment`, with the error model of the arithmetic that formed
/// it (`part::error`): the error bounds' share of each part.
pub fn own_second_moment_bounded<T: Real>(shape: Shape, spec: &Spec, m: T) -> (M3<T>, Own) {
    let (j, own) = own_second_moment_in(shape, spec, m, true, Fixed);
    (j, own.expect("invariant: the error model was asked for"))
}

/// The one path of both: the error model formed only when `bound` asks
/// (the per-part figures and the checks on the input need none of it).
fn own_second_moment_in<T: Real, L: Lift>(
    shape: Shape,
    spec: &Spec,
    m: T,
    bound: bool,
    l: L,
) -> (M3<T>, Option<Own>) {
    // The frames' rounding of the part's numbers, on top of its own: its
    // sizes and mass relative; a shape spanned by vectors the frames
    // turned numerically (edges, ends, vertices) absolute in every entry,
    // as a turn's own error is (a component that should be 0 is not).
    // Returns (placed, μ): the frames' units and the mass's.
    let errors = || {
        let placed = error::placed_units::<T>(&spec.place, &spec.placed);
        (placed, error::mass_error(shape, spec) + placed)
    };
    let outer = |j: &M3<T>| {
        let (placed, mu) = errors();
        let mag: [f64; 3] = std::array::from_fn(|a| j[a][a].f64().abs());
        Own {
            mass: mu,
            kappa: mu + error::OUTER,
            mag,
            rot: placed * mag.iter().sum::<f64>(),
            diagonal: false,
        }
    };
    let zero = T::of(0.0);
    let twelfth = m / T::of(12.0);
    let mut j = [[zero; 3]; 3];
    let mut add_outer = |e: [T; 3]| {
        for a in 0..3 {
            for b in 0..3 {
                j[a][b] = j[a][b] + twelfth * e[a] * e[b];
            }
        }
    };
    if let Place::Mesh {
        orientation,
        scale,
        mesh,
        ..
    } = &spec.place
    {
        return mesh_second_moment(spec, orientation, *scale, mesh, m, bound);
    }
    let centred = match &spec.place {
        Place::Centered {
            extent,
            orientation,
            ..
        } => Some((&extent[..], orientation)),
        Place::Axial {
            dims, orientation, ..
        } => Some((&dims[..], orientation)),
        _ => None,
    };
    match &spec.place {
        Place::Centered { .. } | Place::Axial { .. } => {
            let (extent, orientation) = centred.expect("matched");
            let mut dims = [zero; 5];
            for (k, (d, x)) in dims.iter_mut().zip(extent).enumerate() {
                *d = T::var(*x, l.rate(Slot::Dim(k as u8)));
            }
            let d = shape.second_moments(m, &dims[..shape.dim_count()]);
            if let Orientation::Identity = orientation {
                let own = bound.then(|| {
                    let mu = errors().1;
                    Own {
                        mass: mu,
                        kappa: mu + error::closed_form(shape),
                        mag: d.map(|x| x.f64().abs()),
                        rot: 0.0,
                        diagonal: true,
                    }
                });
                let j = std::array::from_fn(|a| {
                    std::array::from_fn(|b| if a == b { d[a] } else { zero })
                });
                return (j, own);
            }
            let r: M3<T> = orientation.matrix();
            for a in 0..3 {
                for b in a..3 {
                    j[a][b] = r[a][0] * d[0] * r[b][0]
                        + r[a][1] * d[1] * r[b][1]
                        + r[a][2] * d[2] * r[b][2];
                    j[b][a] = j[a][b];
                }
            }
            let own = bound.then(|| {
                let mu = errors().1;
                let rho = error::turn_error(orientation, &r.map(|row| row.map(T::f64)));
                let spread: f64 = d.iter().map(|x| x.f64().abs()).sum();
                let mag = std::array::from_fn(|a| j[a][a].f64().abs());
                let kappa = mu + error::closed_form(shape) + error::TURN;
                Own::turned(mu, kappa, mag, rho, spread)
            });
            return (j, own);
        }
        Place::Edges { edges, .. } => {
            for e in &edges_in::<T, L>(edges, l)[..shape.edge_count()] {
                add_outer(*e);
            }
        }
        Place::FromTo { from, to } => add_outer(span_in(from, to, l)),
        // ∫ρρᵀ dm of a uniform triangle about its centroid g is
        // (m/12) Σ dᵢdᵢᵀ with dᵢ = vᵢ − g (from ∫ρρᵀ dA = (A/12)(Σ vᵢvᵢᵀ + s sᵀ),
        // s = Σ vᵢ, about any origin).
        Place::Vertices(v) => {
            for d in triangle_offsets::<T, L>(v, l) {
                add_outer(d);
            }
        }
        Place::Prism { .. } => {
            let (j, own) = offset::prism_second_moment(spec, m, bound, errors, l);
            return (j, own);
        }
        Place::Mesh { .. } => unreachable!("a mesh returned above"),
        Place::Given {
            inertia,
            orientation,
            ..
        } => {
            // ∫ρρᵀ dm = tr(I)/2 E − I; a cut-out's is subtracted.
            let i: M3<T> = inertia.map(|r| r.map(T::of));
            let sign = T::of(if m < zero { -1.0 } else { 1.0 });
            let local: M3<T> = std::array::from_fn(|a| {
                std::array::from_fn(|b| {
                    sign * if a == b {
                        diagonal_second_moment(&i, a)
                    } else {
                        -i[a][b]
                    }
                })
            });
            let r: M3<T> = orientation.matrix();
            let j = turned(&r, &local);
            let own = bound.then(|| {
                let mu = errors().1;
                let r = r.map(|row| row.map(T::f64));
                let rho = error::turn_error(orientation, &r);
                // |C_kl| ≤ √(ℓ_k ℓ_l) for the positive semi-definite local
                // C, ℓ the magnitudes its diagonal is formed from; so each
                // entry of R C Rᵀ is at most v_a v_b, v = |R| √ℓ.
                let spread: [f64; 3] = std::array::from_fn(|a| diagonal_magnitude(&i, a));
                let v: [f64; 3] =
                    std::array::from_fn(|a| (0..3).map(|k| r[a][k].abs() * spread[k].sqrt()).sum());
                let total: f64 = spread.iter().sum::<f64>()
                    + (0..3)
                        .flat_map(|k| (0..3).filter(move |l| *l != k).map(move |l| (k, l)))
                        .map(|(k, l)| inertia[k][l].abs())
                        .sum::<f64>();
                Own::turned(mu, mu + error::GIVEN, v.map(|x| x * x), rho, total)
            });
            return (j, own);
        }
    }
    let own = bound.then(|| outer(&j));
    (j, own)
}

/// A mesh part's mirror image, for mirrors (`array`/`mirror`): its mesh's
/// data reflected through the plane through the mesh file's origin normal
/// to local axis `axis` (`mesh::MeshBody::reflected`: the centroid's
/// coordinate and the products with that axis change sign). The caller
/// composes the rest of the mirror (a proper turn and the origin's image).
/// Returns false, changing nothing, for a part that is not a mesh.
pub fn reflect_mesh(place: &mut Place, axis: usize) -> bool {
    match place {
        Place::Mesh { mesh, .. } => {
            *mesh = std::sync::Arc::new(mesh.reflected(axis));
            true
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use crate::numeric::DD;

    /// `mesh` counts roundings in the same unit as the error model (it
    /// comes before `part` and keeps its own copy of the rule).
    #[test]
    fn mesh_and_part_count_roundings_in_one_unit() {
        assert_eq!(
            crate::mesh::unit_of::<f64>(),
            super::error::unit_of::<f64>()
        );
        assert_eq!(crate::mesh::unit_of::<DD>(), super::error::unit_of::<DD>());
    }
}
