//! An exact reference composer, for the accuracy tests, the benchmark and
//! the accuracy example only (issue 4).
//!
//! Every finite f64 is a dyadic rational, so a scene's inputs are taken
//! *exactly*, and every unit factor is an exact fraction (0.0254 m, 0.45359237
//! kg, …). The "true answer" of a scene is the exact result for those f64
//! inputs: mass, centre of mass, C = ∫ρρᵀ dm about it and the inertia tensor
//! I = tr(C)·E − C, all as `BigRational`s with no rounding at all. The only
//! inexact steps are square roots (measures of parts placed by edges, and
//! of triangles, with a density: relative 2⁻²⁰⁰), π (a 100-digit fraction,
//! for cylinders, disks and spheres with a density: relative < 1e-100) and
//! eigenvalues (relative 2⁻¹⁴¹, ≈ 43 digits).
//!
//! Every shape of massprop is here: box, plate, rod, point, cylinder (and
//! tube), disk (and annulus), sphere (hollow, and thin shell), triangle and
//! a given inertia tensor. The derivation is independent of massprop's
//! code: rotations come from the quaternion sandwich product q v q̄ / |q|²
//! (or an exactly orthonormal matrix), shapes from closed forms derived
//! from their definitions in the comments of [`centered_form`] and
//! [`triangle_form`], and composition sums exact first and second moments. Eigenvalues come from the exact
//! characteristic polynomial (see [`CharPoly`]), never from an iterative
//! solver.
//!
//! The module also holds the scene description the stress and property
//! tests share, and [`to_toml`], which writes a scene as a part file whose
//! numbers parse back to exactly the same f64 values.

use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt::Write as _;

/// An exact rational number.
pub type Q = BigRational;
pub type V3 = [Q; 3];
/// Rows of a 3×3 matrix.
pub type M3 = [[Q; 3]; 3];

// ---------------------------------------------------------------------------
// Rational helpers

/// The exact value of a finite f64.
pub fn q(x: f64) -> Q {
    Q::from_float(x).expect("reference inputs are finite")
}

pub fn int(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

pub fn frac(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

/// The f64 nearest to `x` (correctly rounded by num-rational).
pub fn f(x: &Q) -> f64 {
    x.to_f64().expect("a rational converts to f64")
}

pub fn fv(v: &V3) -> [f64; 3] {
    [f(&v[0]), f(&v[1]), f(&v[2])]
}

pub fn fm(m: &M3) -> [[f64; 3]; 3] {
    [fv(&m[0]), fv(&m[1]), fv(&m[2])]
}

pub fn qv(v: [f64; 3]) -> V3 {
    v.map(q)
}

fn add(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| &a[i] + &b[i])
}

fn sub(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| &a[i] - &b[i])
}

fn scale(a: &V3, s: &Q) -> V3 {
    std::array::from_fn(|i| &a[i] * s)
}

pub fn dot(a: &V3, b: &V3) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

pub fn cross(a: &V3, b: &V3) -> V3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn zero_v() -> V3 {
    std::array::from_fn(|_| Q::zero())
}

fn zero_m() -> M3 {
    std::array::from_fn(|_| zero_v())
}

/// a bᵀ
fn outer(a: &V3, b: &V3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| &a[i] * &b[j]))
}

fn madd(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| add(&a[i], &b[i]))
}

fn mscale(a: &M3, s: &Q) -> M3 {
    std::array::from_fn(|i| scale(&a[i], s))
}

pub fn mmul(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| &a[i][0] * &b[0][j] + &a[i][1] * &b[1][j] + &a[i][2] * &b[2][j])
    })
}

pub fn transpose(a: &M3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i].clone()))
}

pub fn mvec(a: &M3, v: &V3) -> V3 {
    std::array::from_fn(|i| dot(&a[i], v))
}

/// I = tr(C)·E − C: tensor convention, off-diagonals −∫xy dm.
pub fn inertia_of(c: &M3) -> M3 {
    let tr = &c[0][0] + &c[1][1] + &c[2][2];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i == j {
                &tr - &c[i][j]
            } else {
                -c[i][j].clone()
            }
        })
    })
}

/// √x for x ≥ 0, to relative 2⁻²⁰⁰ (a lower bound): √(n/d) = √(n·d)/d, with
/// the integer square root of n·d·4ᵏ for a k that makes it at least 2⁴⁰⁰,
/// so the floor loses less than 1 part in 2²⁰⁰.
pub fn sqrt(x: &Q) -> Q {
    assert!(!x.is_negative(), "sqrt of a negative number");
    if x.is_zero() {
        return Q::zero();
    }
    let nd = x.numer() * x.denom();
    let k = (400u64.saturating_sub(nd.bits()) / 2 + 1) as usize;
    let root = (nd << (2 * k)).sqrt();
    Q::new(root, x.denom() << k)
}

/// Hamilton product of quaternions [w, x, y, z].
fn qmul(a: &[Q; 4], b: &[Q; 4]) -> [Q; 4] {
    let [aw, ax, ay, az] = a;
    let [bw, bx, by, bz] = b;
    [
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    ]
}

/// The rotation of a quaternion of any non-zero length, exactly: column k
/// is q eₖ q̄ / |q|² (the sandwich product, not a closed-form matrix).
pub fn rotation(qn: &[Q; 4]) -> M3 {
    let n2: Q = qn.iter().map(|x| x * x).sum();
    let conj = [
        qn[0].clone(),
        -qn[1].clone(),
        -qn[2].clone(),
        -qn[3].clone(),
    ];
    let mut r = zero_m();
    for k in 0..3 {
        let mut e: [Q; 4] = std::array::from_fn(|_| Q::zero());
        e[k + 1] = Q::one();
        let v = qmul(&qmul(qn, &e), &conj);
        for i in 0..3 {
            r[i][k] = &v[i + 1] / &n2;
        }
    }
    r
}

// ---------------------------------------------------------------------------
// Scenes

/// File length units, with their exact size in metres.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Length {
    M,
    Cm,
    Mm,
    Um,
    Km,
    In,
    Ft,
}

impl Length {
    pub fn symbol(self) -> &'static str {
        match self {
            Length::M => "m",
            Length::Cm => "cm",
            Length::Mm => "mm",
            Length::Um => "um",
            Length::Km => "km",
            Length::In => "in",
            Length::Ft => "ft",
        }
    }

    /// Metres per unit, exactly.
    pub fn si(self) -> Q {
        match self {
            Length::M => int(1),
            Length::Cm => frac(1, 100),
            Length::Mm => frac(1, 1000),
            Length::Um => frac(1, 1_000_000),
            Length::Km => int(1000),
            Length::In => frac(254, 10_000),
            Length::Ft => frac(3048, 10_000),
        }
    }
}

/// File mass units, with their exact size in kilograms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mass {
    Kg,
    G,
    Mg,
    T,
    Lb,
}

impl Mass {
    pub fn symbol(self) -> &'static str {
        match self {
            Mass::Kg => "kg",
            Mass::G => "g",
            Mass::Mg => "mg",
            Mass::T => "t",
            Mass::Lb => "lb",
        }
    }

    /// Kilograms per unit, exactly.
    pub fn si(self) -> Q {
        match self {
            Mass::Kg => int(1),
            Mass::G => frac(1, 1000),
            Mass::Mg => frac(1, 1_000_000),
            Mass::T => int(1000),
            Mass::Lb => frac(45_359_237, 100_000_000),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    Box,
    Plate,
    Rod,
    Point,
    /// Solid cylinder, or with an inner radius a tube (thin at r = R).
    Cylinder,
    /// Thin disk, or with an inner radius an annulus (a ring at r = R).
    Disk,
    /// Solid sphere, or with an inner radius hollow (a shell at r = R).
    Sphere,
    /// Thin triangular plate given by its vertices.
    Triangle,
    /// A given mass, centre and inertia tensor.
    Inertia,
    /// A cone or frustum, solid or hollow (`solids::cone`).
    Cone,
    /// A torus, solid or hollow (`solids::torus`).
    Torus,
    /// A hemisphere, solid or hollow (`solids::hemisphere`).
    Hemisphere,
    /// A polygon extruded along local z (`solids::polygon`).
    Prism,
    /// A cylinder with hemispherical ends, solid or hollow
    /// (`solids::capsule`).
    Capsule,
    /// A solid ellipsoid of semi-axes [a, b, c] (`solids::ellipsoid`).
    Ellipsoid,
}

impl Shape {
    fn name(self) -> &'static str {
        match self {
            Shape::Box => "box",
            Shape::Plate => "plate",
            Shape::Rod => "rod",
            Shape::Point => "point",
            Shape::Cylinder => "cylinder",
            Shape::Disk => "disk",
            Shape::Sphere => "sphere",
            Shape::Triangle => "triangle",
            Shape::Inertia => "inertia",
            Shape::Cone => "cone",
            Shape::Torus => "torus",
            Shape::Hemisphere => "hemisphere",
            Shape::Prism => "prism",
            Shape::Capsule => "capsule",
            Shape::Ellipsoid => "ellipsoid",
        }
    }

    fn density_key(self) -> &'static str {
        match self {
            Shape::Box
            | Shape::Cylinder
            | Shape::Sphere
            | Shape::Cone
            | Shape::Torus
            | Shape::Hemisphere
            | Shape::Prism
            | Shape::Capsule
            | Shape::Ellipsoid => "density",
            Shape::Plate | Shape::Disk | Shape::Triangle => "areal_density",
            Shape::Rod => "linear_density",
            Shape::Point | Shape::Inertia => panic!("a {} takes only a mass", self.name()),
        }
    }

    /// Volume, area, length: the power of length a density is per.
    fn dim(self) -> i32 {
        match self {
            Shape::Box
            | Shape::Cylinder
            | Shape::Sphere
            | Shape::Cone
            | Shape::Torus
            | Shape::Hemisphere
            | Shape::Prism
            | Shape::Capsule
            | Shape::Ellipsoid => 3,
            Shape::Plate | Shape::Disk | Shape::Triangle => 2,
            Shape::Rod => 1,
            Shape::Point | Shape::Inertia => 0,
        }
    }
}

/// A part's mass, in file units: `mass`, or the shape's density.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Amount {
    Mass(f64),
    Density(f64),
}

/// A part's `rotation`, in one of two of massprop's forms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rotation {
    /// `{ quaternion = [w, x, y, z] }`, taken exactly as written (any
    /// non-zero length: R = q v q̄ / |q|² is a rotation for every q).
    Quaternion([f64; 4]),
    /// `{ matrix = [[..], [..], [..]] }` by rows, columns the local axes.
    /// The reference takes only matrices that are exactly rotations (in
    /// practice signed permutations: quarter turns), so the part file and
    /// the reference describe the same body to the last bit.
    Matrix([[f64; 3]; 3]),
}

/// The sign convention of a given inertia's products (`products = ..`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Products {
    /// Off-diagonals −∫xy dm: the default, the key left out.
    Tensor,
    /// `products = "positive"`: off-diagonals +∫xy dm, as CAD reports them.
    Positive,
}

/// Where a part sits, in file units.
#[derive(Clone, Debug, PartialEq)]
pub enum Place {
    /// `size` (box [a, b, c], plate [a, b], rod [L] written as `length`,
    /// point []; cylinder [R, L] or [R, L, r], disk and sphere [R] or
    /// [R, r], written as `radius`, `length` and `inner_radius`), `center`,
    /// optional `rotation`.
    Center {
        size: Vec<f64>,
        center: [f64; 3],
        rotation: Option<Rotation>,
    },
    /// Box or plate: `corner` and 3 or 2 perpendicular `edges`.
    Edges {
        corner: [f64; 3],
        edges: Vec<[f64; 3]>,
    },
    /// Rod: `from` and `to`.
    FromTo { from: [f64; 3], to: [f64; 3] },
    /// Triangle: its three `vertices`.
    Vertices([[f64; 3]; 3]),
    /// Given inertia: `inertia` (rows, file mass × length², about the
    /// centre in local axes), its `products` convention, `center` and an
    /// optional `rotation`.
    Given {
        inertia: [[f64; 3]; 3],
        products: Products,
        center: [f64; 3],
        rotation: Option<Rotation>,
    },
    /// Prism: its `polygon` (local x–y), `length` (local z), `origin` and
    /// optional `rotation`.
    Prism {
        polygon: Vec<[f64; 2]>,
        length: f64,
        origin: [f64; 3],
        rotation: Option<Rotation>,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    pub shape: Shape,
    pub amount: Amount,
    pub place: Place,
}

impl Part {
    fn centered(
        shape: Shape,
        size: Vec<f64>,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        Part {
            shape,
            amount,
            place: Place::Center {
                size,
                center,
                rotation,
            },
        }
    }

    pub fn cuboid(
        size: [f64; 3],
        center: [f64; 3],
        quaternion: Option<[f64; 4]>,
        amount: Amount,
    ) -> Part {
        let rotation = quaternion.map(Rotation::Quaternion);
        Part::centered(Shape::Box, size.to_vec(), center, rotation, amount)
    }

    pub fn plate(
        size: [f64; 2],
        center: [f64; 3],
        quaternion: Option<[f64; 4]>,
        amount: Amount,
    ) -> Part {
        let rotation = quaternion.map(Rotation::Quaternion);
        Part::centered(Shape::Plate, size.to_vec(), center, rotation, amount)
    }

    pub fn rod(
        length: f64,
        center: [f64; 3],
        quaternion: Option<[f64; 4]>,
        amount: Amount,
    ) -> Part {
        let rotation = quaternion.map(Rotation::Quaternion);
        Part::centered(Shape::Rod, vec![length], center, rotation, amount)
    }

    pub fn point(mass: f64, center: [f64; 3]) -> Part {
        Part::centered(Shape::Point, vec![], center, None, Amount::Mass(mass))
    }

    /// A cylinder of `radius` and `length` along local z; with `inner` a
    /// tube (`inner_radius`; equal to the radius a thin tube, mass only).
    pub fn cylinder(
        radius: f64,
        inner: Option<f64>,
        length: f64,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        let mut size = vec![radius, length];
        size.extend(inner);
        Part::centered(Shape::Cylinder, size, center, rotation, amount)
    }

    /// A disk in the local x–y plane; with `inner` an annulus (a ring at
    /// `inner` = `radius`, mass only).
    pub fn disk(
        radius: f64,
        inner: Option<f64>,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        let mut size = vec![radius];
        size.extend(inner);
        Part::centered(Shape::Disk, size, center, rotation, amount)
    }

    /// A sphere; with `inner` hollow (a thin shell at `inner` = `radius`,
    /// mass only).
    pub fn sphere(
        radius: f64,
        inner: Option<f64>,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        let mut size = vec![radius];
        size.extend(inner);
        Part::centered(Shape::Sphere, size, center, rotation, amount)
    }

    /// A cone or frustum along local z, base `radius` at −length/2, `top`
    /// at +length/2; `inner` = (base, top) bore radii.
    pub fn cone(
        radius: f64,
        top: f64,
        length: f64,
        inner: Option<(f64, f64)>,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        let mut size = vec![radius, top, length];
        if let Some((a0, a1)) = inner {
            size.extend([a0, a1]);
        }
        Part::centered(Shape::Cone, size, center, rotation, amount)
    }

    /// A torus about local z; `inner` the inner tube radius.
    pub fn torus(
        radius: f64,
        tube: f64,
        inner: Option<f64>,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        let mut size = vec![radius, tube];
        size.extend(inner);
        Part::centered(Shape::Torus, size, center, rotation, amount)
    }

    /// A hemisphere (dome toward local +z) of the sphere about `center`.
    pub fn hemisphere(
        radius: f64,
        inner: Option<f64>,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        let mut size = vec![radius];
        size.extend(inner);
        Part::centered(Shape::Hemisphere, size, center, rotation, amount)
    }

    /// A capsule: `radius`, `length` between its ends' centres, along
    /// local z about `center`.
    pub fn capsule(
        radius: f64,
        length: f64,
        inner: Option<f64>,
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        let mut size = vec![radius, length];
        size.extend(inner);
        Part::centered(Shape::Capsule, size, center, rotation, amount)
    }

    /// A solid ellipsoid of semi-axes `radii` along its local x, y, z
    /// about `center`.
    pub fn ellipsoid(
        radii: [f64; 3],
        center: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        Part::centered(Shape::Ellipsoid, radii.to_vec(), center, rotation, amount)
    }

    pub fn prism(
        polygon: Vec<[f64; 2]>,
        length: f64,
        origin: [f64; 3],
        rotation: Option<Rotation>,
        amount: Amount,
    ) -> Part {
        Part {
            shape: Shape::Prism,
            amount,
            place: Place::Prism {
                polygon,
                length,
                origin,
                rotation,
            },
        }
    }

    pub fn triangle(vertices: [[f64; 3]; 3], amount: Amount) -> Part {
        Part {
            shape: Shape::Triangle,
            amount,
            place: Place::Vertices(vertices),
        }
    }

    /// A given inertia tensor (file mass × length², about `center` in the
    /// part's local axes) of a part of mass `mass`.
    pub fn given(
        mass: f64,
        inertia: [[f64; 3]; 3],
        products: Products,
        center: [f64; 3],
        rotation: Option<Rotation>,
    ) -> Part {
        Part {
            shape: Shape::Inertia,
            amount: Amount::Mass(mass),
            place: Place::Given {
                inertia,
                products,
                center,
                rotation,
            },
        }
    }

    pub fn box_edges(corner: [f64; 3], edges: [[f64; 3]; 3], amount: Amount) -> Part {
        Part {
            shape: Shape::Box,
            amount,
            place: Place::Edges {
                corner,
                edges: edges.to_vec(),
            },
        }
    }

    pub fn plate_edges(corner: [f64; 3], edges: [[f64; 3]; 2], amount: Amount) -> Part {
        Part {
            shape: Shape::Plate,
            amount,
            place: Place::Edges {
                corner,
                edges: edges.to_vec(),
            },
        }
    }

    pub fn rod_from_to(from: [f64; 3], to: [f64; 3], amount: Amount) -> Part {
        Part {
            shape: Shape::Rod,
            amount,
            place: Place::FromTo { from, to },
        }
    }

    /// The same part with another rotation (parts placed by `center`, and
    /// given inertias, only).
    pub fn with_rotation(mut self, rotation: Option<Rotation>) -> Part {
        match &mut self.place {
            Place::Center { rotation: r, .. }
            | Place::Given { rotation: r, .. }
            | Place::Prism { rotation: r, .. } => *r = rotation,
            _ => panic!("only parts placed by `center` take a rotation"),
        }
        self
    }
}

/// A part file: units, parts, and an optional reference point (`about`).
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub length: Length,
    pub mass: Mass,
    pub parts: Vec<Part>,
    pub about: Option<[f64; 3]>,
}

impl Scene {
    /// A scene in metres and kilograms.
    pub fn si(parts: Vec<Part>) -> Scene {
        Scene {
            length: Length::M,
            mass: Mass::Kg,
            parts,
            about: None,
        }
    }

    /// Every position (centre, corner, rod end, vertex, reference point)
    /// mapped by `point` and every direction (edge) by `dir`; rotations of
    /// parts placed by `center` by `rot`. Sizes, given tensors, masses and
    /// densities are unchanged.
    pub fn map(
        &self,
        point: impl Fn([f64; 3]) -> [f64; 3],
        dir: impl Fn([f64; 3]) -> [f64; 3],
        rot: impl Fn(Option<Rotation>, &Part) -> Option<Rotation>,
    ) -> Scene {
        let parts = self
            .parts
            .iter()
            .map(|p| {
                let place = match &p.place {
                    Place::Center {
                        size,
                        center,
                        rotation,
                    } => Place::Center {
                        size: size.clone(),
                        center: point(*center),
                        rotation: rot(*rotation, p),
                    },
                    Place::Edges { corner, edges } => Place::Edges {
                        corner: point(*corner),
                        edges: edges.iter().map(|e| dir(*e)).collect(),
                    },
                    Place::FromTo { from, to } => Place::FromTo {
                        from: point(*from),
                        to: point(*to),
                    },
                    Place::Vertices(v) => Place::Vertices(v.map(&point)),
                    Place::Given {
                        inertia,
                        products,
                        center,
                        rotation,
                    } => Place::Given {
                        inertia: *inertia,
                        products: *products,
                        center: point(*center),
                        rotation: rot(*rotation, p),
                    },
                    Place::Prism {
                        polygon,
                        length,
                        origin,
                        rotation,
                    } => Place::Prism {
                        polygon: polygon.clone(),
                        length: *length,
                        origin: point(*origin),
                        rotation: rot(*rotation, p),
                    },
                };
                Part { place, ..p.clone() }
            })
            .collect();
        Scene {
            parts,
            about: self.about.map(&point),
            ..self.clone()
        }
    }

    /// The scene moved by `t` (each coordinate rounded to f64; check
    /// [`Scene::translation_is_exact`] when the test needs it exact).
    pub fn translated(&self, t: [f64; 3]) -> Scene {
        self.map(|p| std::array::from_fn(|i| p[i] + t[i]), |e| e, |q, _| q)
    }

    /// Whether every position plus `t` is exact in f64.
    pub fn translation_is_exact(&self, t: [f64; 3]) -> bool {
        let exact = std::cell::Cell::new(true);
        self.map(
            |p| {
                for i in 0..3 {
                    let s = p[i] + t[i];
                    if q(s) != q(p[i]) + q(t[i]) {
                        exact.set(false);
                    }
                }
                p
            },
            |e| e,
            |q, _| q,
        );
        exact.get()
    }

    /// The scene turned a quarter turn about file axis `axis` (0, 1, 2),
    /// exactly: (x, y, z) → (x, −z, y) about x, and so on. Unrotated boxes
    /// swap sizes; every other part placed by `center` (or a given inertia)
    /// gains the turn as a `matrix` rotation, P·R, a signed permutation when
    /// R is one (or none). Parts rotated by a quaternion cannot be turned
    /// exactly (the composed quaternion rounds) and are refused.
    pub fn quarter_turn(&self, axis: usize) -> Scene {
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        let turn = move |p: [f64; 3]| {
            let mut r = p;
            r[i] = -p[j];
            r[j] = p[i];
            r
        };
        let mut out = self.map(turn, turn, |rot, part| {
            let m = match (part.shape, rot) {
                (Shape::Box | Shape::Point, None) => return None,
                (_, Some(Rotation::Quaternion(_))) => {
                    panic!("quarter_turn: parts rotated by a quaternion cannot turn exactly")
                }
                (_, Some(Rotation::Matrix(m))) => m,
                (_, None) => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            };
            // P·R turns each column (local axis) of R: exact, as P only
            // moves entries and flips signs.
            let cols: [[f64; 3]; 3] = std::array::from_fn(|k| turn([m[0][k], m[1][k], m[2][k]]));
            Some(Rotation::Matrix(std::array::from_fn(|r| {
                std::array::from_fn(|k| cols[k][r])
            })))
        });
        for p in &mut out.parts {
            if let (
                Shape::Box,
                Place::Center {
                    size,
                    rotation: None,
                    ..
                },
            ) = (p.shape, &mut p.place)
            {
                size.swap(i, j);
            }
        }
        out
    }

    /// The scene turned by the rotation of the integer quaternion `r`
    /// (exactly rational, e.g. [2, 1, 0, 0] has entries 3/5 and 4/5): every
    /// position and edge is rotated exactly and rounded to f64, and each
    /// part's quaternion is composed and rounded. The reference takes the
    /// rounded values, so the rotated scene is a scene of its own.
    pub fn rotated(&self, r: [i64; 4]) -> Scene {
        let rq = r.map(int);
        let rot = rotation(&rq);
        let turn = |p: [f64; 3]| fv(&mvec(&rot, &qv(p)));
        let norm = r.iter().map(|x| (x * x) as f64).sum::<f64>().sqrt();
        self.map(turn, turn, |rot, part| {
            // An unrotated part gains the rotation itself; a point none.
            (part.shape != Shape::Point).then(|| {
                let qq = match rot {
                    None => [1.0, 0.0, 0.0, 0.0],
                    Some(Rotation::Quaternion(qq)) => qq,
                    Some(Rotation::Matrix(_)) => {
                        panic!("rotated: a matrix rotation would not stay exactly orthonormal")
                    }
                };
                let prod = qmul(&rq, &qq.map(q));
                Rotation::Quaternion(std::array::from_fn(|k| f(&prod[k]) / norm))
            })
        })
    }

    /// The same parts in the order of `order` (indices into `parts`).
    pub fn reordered(&self, order: &[usize]) -> Scene {
        Scene {
            parts: order.iter().map(|&i| self.parts[i].clone()).collect(),
            ..self.clone()
        }
    }

    /// This scene (in m and kg) written in other units: every number is
    /// converted exactly and rounded once to f64. The reference then takes
    /// those rounded numbers with the new units' exact factors.
    pub fn in_units(&self, length: Length, mass: Mass) -> Scene {
        assert_eq!((self.length, self.mass), (Length::M, Mass::Kg));
        let l = length.si();
        let m = mass.si();
        let len = |x: f64| f(&(q(x) / &l));
        let pos = |p: [f64; 3]| p.map(len);
        let parts = self
            .parts
            .iter()
            .map(|p| {
                let amount = match p.amount {
                    Amount::Mass(x) => Amount::Mass(f(&(q(x) / &m))),
                    // kg/m^k → (mass unit)/(length unit)^k
                    Amount::Density(x) => Amount::Density(f(&(q(x) * pow(&l, p.shape.dim()) / &m))),
                };
                let place = match &p.place {
                    Place::Center {
                        size,
                        center,
                        rotation,
                    } => Place::Center {
                        size: size.iter().map(|&s| len(s)).collect(),
                        center: pos(*center),
                        rotation: *rotation,
                    },
                    Place::Edges { corner, edges } => Place::Edges {
                        corner: pos(*corner),
                        edges: edges.iter().map(|e| pos(*e)).collect(),
                    },
                    Place::FromTo { from, to } => Place::FromTo {
                        from: pos(*from),
                        to: pos(*to),
                    },
                    Place::Vertices(v) => Place::Vertices(v.map(pos)),
                    // kg·m² → (mass unit)·(length unit)²
                    Place::Given {
                        inertia,
                        products,
                        center,
                        rotation,
                    } => Place::Given {
                        inertia: inertia.map(|row| row.map(|x| f(&(q(x) / (&m * &l * &l))))),
                        products: *products,
                        center: pos(*center),
                        rotation: *rotation,
                    },
                    Place::Prism {
                        polygon,
                        length,
                        origin,
                        rotation,
                    } => Place::Prism {
                        polygon: polygon.iter().map(|v| v.map(len)).collect(),
                        length: len(*length),
                        origin: pos(*origin),
                        rotation: *rotation,
                    },
                };
                Part {
                    shape: p.shape,
                    amount,
                    place,
                }
            })
            .collect();
        Scene {
            length,
            mass,
            parts,
            about: self.about.map(pos),
        }
    }
}

fn pow(x: &Q, k: i32) -> Q {
    (0..k).fold(Q::one(), |acc, _| acc * x)
}

// ---------------------------------------------------------------------------
// The exact composition

/// One part in SI: mass, centroid and ∫ρρᵀ dm about the centroid.
#[derive(Clone, Debug)]
pub struct ExactPart {
    pub mass: Q,
    pub center: V3,
    pub second_moment: M3,
}

/// A scene's exact mass properties, SI.
#[derive(Clone, Debug)]
pub struct Exact {
    pub mass: Q,
    pub com: V3,
    /// ∫ρρᵀ dm about the centre of mass.
    pub second_moment: M3,
    /// Inertia tensor about the centre of mass (tensor convention).
    pub inertia: M3,
    pub parts: Vec<ExactPart>,
    /// The scene's `about` in SI, if any.
    pub about: Option<V3>,
}

/// The second moment of a uniform parallelepiped (or parallelogram, or
/// segment) of mass m spanned by `edges` about its centroid. With
/// ρ = Σ tₖ eₖ, tₖ uniform on [−½, ½] and independent, the cross terms
/// vanish and ∫tₖ² = 1/12: C = (m/12) Σ eₖ eₖᵀ.
fn spanned(mass: &Q, edges: &[V3]) -> M3 {
    let twelfth = mass / int(12);
    edges.iter().fold(zero_m(), |acc, e| {
        madd(&acc, &mscale(&outer(e, e), &twelfth))
    })
}

/// π to 100 decimal places: |PI − π| < 10⁻¹⁰⁰, a relative error 84 orders
/// of magnitude below f64's unit roundoff (2⁻⁵³ ≈ 1.1e-16), so a mass with
/// π in it (a cylinder, disk or sphere by density) is "exact" far beyond
/// anything a test resolves. The digits are checked against Machin's
/// formula in the tests below.
pub fn pi() -> Q {
    const DIGITS: &str = "31415926535897932384626433832795028841971693993751\
                          05820974944592307816406286208998628034825342117067\
                          9";
    Q::new(
        DIGITS.parse::<BigInt>().expect("decimal digits"),
        BigInt::from(10).pow(100),
    )
}

fn identity() -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { Q::one() } else { Q::zero() }))
}

/// R C Rᵀ: a second moment in local axes seen in the file's axes (the
/// columns of R are the local axes, a local point p lies at center + R p).
fn turned(r: &M3, c: &M3) -> M3 {
    mmul(&mmul(r, c), &transpose(r))
}

fn diag_of(d: [Q; 3]) -> M3 {
    let mut m = zero_m();
    for (k, x) in d.into_iter().enumerate() {
        m[k][k] = x;
    }
    m
}

/// A rotation's matrix, exactly: the quaternion's sandwich product, or the
/// given matrix, which must be exactly a rotation (RᵀR = E, det R = +1).
pub fn rotation_matrix(rot: Option<&Rotation>) -> M3 {
    match rot {
        None => identity(),
        Some(Rotation::Quaternion(qq)) => rotation(&qq.map(q)),
        Some(Rotation::Matrix(m)) => {
            let r = m.map(qv);
            assert_eq!(
                mmul(&transpose(&r), &r),
                identity(),
                "the reference takes only matrices that are exactly orthonormal"
            );
            assert_eq!(dot(&r[0], &cross(&r[1], &r[2])), Q::one(), "det R = +1");
            r
        }
    }
}

/// A shape placed by `size`, per unit mass, in its local axes: the
/// diagonal of ∫xxᵀ dm / m and the measure (volume, area or length) that a
/// density multiplies; `None` for a thin shell, tube or ring (and a point),
/// which has no measure and takes only a mass.
///
/// The closed forms, derived here from the definitions (not taken from
/// massprop):
///
/// - box, plate, rod: a uniform segment of length a, x uniform on
///   [−a/2, a/2], has ∫x² dm / m = (1/a)∫x² dx = a²/12, independently per
///   edge.
/// - cylinder of radius R, bore r, length L (along z): the cross-section is
///   the annulus r ≤ ρ ≤ R, and z is uniform on [−L/2, L/2] independently
///   (z²: L²/12). Over the annulus, with x = ρ cos θ,
///   ∫x² dA = ∫∫ ρ² cos²θ ρ dρ dθ = π (R⁴ − r⁴)/4 and A = π (R² − r²), so
///   ∫x² dm / m = (R⁴ − r⁴)/(4 (R² − r²)) = (R² + r²)/4, the same for y;
///   the factored form holds at r = R too, a thin tube (R²/2 = R²/4 + R²/4:
///   all its mass at distance R from the axis, ∫(x² + y²) dm = m R²).
///   Volume π (R² − r²) L.
/// - disk and annulus: the cylinder's cross-section alone, L = 0; area
///   π (R² − r²).
/// - sphere of radius R, cavity r: by symmetry ∫x² dm = ⅓∫|p|² dm, and in
///   shells of radius s, ∫|p|² dV = ∫ s² 4π s² ds = 4π (R⁵ − r⁵)/5 with
///   V = 4π (R³ − r³)/3, so ∫x² dm / m = (R⁵ − r⁵)/(5 (R³ − r³))
///   = (R⁴ + R³r + R²r² + Rr³ + r⁴)/(5 (R² + Rr + r²)) after dividing both
///   differences by R − r; the second form is exact at r = R as well, the
///   thin shell (5R⁴/(15R²) = R²/3, i.e. I = ⅔ m R²). Solid: R²/5
///   (I = ⅖ m R²).
fn centered_form(shape: Shape, size: &[Q]) -> ([Q; 3], Option<Q>) {
    let twelfth = |a: &Q| a * a / int(12);
    // The inner radius, 0 when not given.
    let inner = |k: usize| size.get(k).cloned().unwrap_or_else(Q::zero);
    match shape {
        Shape::Box => {
            let [a, b, c] = [&size[0], &size[1], &size[2]];
            ([twelfth(a), twelfth(b), twelfth(c)], Some(a * b * c))
        }
        Shape::Plate => {
            let [a, b] = [&size[0], &size[1]];
            ([twelfth(a), twelfth(b), Q::zero()], Some(a * b))
        }
        Shape::Rod => (
            [Q::zero(), Q::zero(), twelfth(&size[0])],
            Some(size[0].clone()),
        ),
        Shape::Point => (std::array::from_fn(|_| Q::zero()), None),
        Shape::Cylinder | Shape::Disk => {
            let big = &size[0];
            let (len, r) = if shape == Shape::Cylinder {
                (size[1].clone(), inner(2))
            } else {
                (Q::zero(), inner(1))
            };
            let across = (big * big + &r * &r) / int(4);
            let area = pi() * (big * big - &r * &r);
            let measure = if shape == Shape::Cylinder {
                area * &len
            } else {
                area
            };
            (
                [across.clone(), across, twelfth(&len)],
                (!measure.is_zero()).then_some(measure),
            )
        }
        Shape::Sphere => {
            let (big, r) = (&size[0], inner(1));
            let num = pow(big, 4)
                + pow(big, 3) * &r
                + pow(big, 2) * pow(&r, 2)
                + big * pow(&r, 3)
                + pow(&r, 4);
            let den = int(5) * (big * big + big * &r + &r * &r);
            let each = num / den;
            let volume = int(4) * pi() * (pow(big, 3) - pow(&r, 3)) / int(3);
            (
                std::array::from_fn(|_| each.clone()),
                (!volume.is_zero()).then_some(volume),
            )
        }
        Shape::Triangle
        | Shape::Inertia
        | Shape::Cone
        | Shape::Torus
        | Shape::Hemisphere
        | Shape::Prism
        | Shape::Capsule
        | Shape::Ellipsoid => {
            panic!("a {} has no form here (`solids`)", shape.name())
        }
    }
}

/// A thin triangle with vertices v₀, v₁, v₂: its centroid g, ∫ddᵀ dm / m
/// about it, and its area.
///
/// A uniform point of the triangle is p = Σ λᵢvᵢ with (λ₀, λ₁, λ₂) uniform
/// on the simplex (Dirichlet(1, 1, 1)), whose moments are E[λᵢ] = 1/3,
/// E[λᵢ²] = 1/6 and E[λᵢλⱼ] = 1/12 (i ≠ j) (E[λ₀²] = ∫₀¹ t² 2(1 − t) dt).
/// With dᵢ = vᵢ − g, so that Σ dᵢ = 0 and p − g = Σ λᵢdᵢ:
/// E[(p − g)(p − g)ᵀ] = Σᵢⱼ E[λᵢλⱼ] dᵢdⱼᵀ
///   = (1/12)(Σᵢ dᵢdᵢᵀ + Σᵢⱼ dᵢdⱼᵀ) = (1/12) Σᵢ dᵢdᵢᵀ,
/// since Σᵢⱼ dᵢdⱼᵀ = (Σ dᵢ)(Σ dⱼ)ᵀ = 0. The area is |(v₁ − v₀) × (v₂ − v₀)|/2,
/// a square root of a rational (to relative 2⁻²⁰⁰).
fn triangle_form(v: &[V3; 3]) -> (V3, M3, Q) {
    let g = scale(&add(&add(&v[0], &v[1]), &v[2]), &frac(1, 3));
    let c = v.iter().fold(zero_m(), |acc, vi| {
        let d = sub(vi, &g);
        madd(&acc, &outer(&d, &d))
    });
    let n = cross(&sub(&v[1], &v[0]), &sub(&v[2], &v[0]));
    let area = sqrt(&dot(&n, &n)) / int(2);
    (g, mscale(&c, &frac(1, 12)), area)
}

/// One part reduced to SI, exactly.
pub fn exact_part(part: &Part, length: Length, mass_unit: Mass) -> ExactPart {
    let l = length.si();
    let mu = mass_unit.si();
    let pos = |p: &[f64; 3]| scale(&qv(*p), &l);
    // The measure (volume, area, length) a density multiplies, in SI.
    let by_mass = |measure: Option<Q>| -> Q {
        match part.amount {
            Amount::Mass(m) => q(m) * &mu,
            Amount::Density(rho) => {
                let measure = measure.unwrap_or_else(|| {
                    panic!("a {} of no volume takes only a mass", part.shape.name())
                });
                q(rho) * &mu / pow(&l, part.shape.dim()) * measure
            }
        }
    };
    match &part.place {
        Place::Center {
            size,
            center,
            rotation,
        } => {
            let r = rotation_matrix(rotation.as_ref());
            let size: Vec<Q> = size.iter().map(|&s| q(s) * &l).collect();
            let solid = match part.shape {
                Shape::Cone => Some(super::solids::cone(&size)),
                Shape::Torus => Some(super::solids::torus(&size)),
                Shape::Hemisphere => Some(super::solids::hemisphere(&size)),
                Shape::Capsule => Some(super::solids::capsule(&size)),
                Shape::Ellipsoid => Some(super::solids::ellipsoid(&size)),
                _ => None,
            };
            let (per_mass, measure, offset) = match solid {
                Some((per_mass, offset, measure)) => (per_mass, measure, offset),
                None => {
                    let (per_mass, measure) = centered_form(part.shape, &size);
                    (per_mass, measure, Q::zero())
                }
            };
            let mass = by_mass(measure);
            // The centroid: off `center` along local z by `offset`.
            let shift = mvec(&r, &[Q::zero(), Q::zero(), offset]);
            ExactPart {
                second_moment: mscale(&turned(&r, &diag_of(per_mass)), &mass),
                mass,
                center: add(&pos(center), &shift),
            }
        }
        Place::Edges { .. } | Place::FromTo { .. } => {
            // The part's centroid and spanning edges, SI.
            let (center, edges): (V3, Vec<V3>) = match &part.place {
                Place::Edges { corner, edges } => {
                    let e: Vec<V3> = edges.iter().map(&pos).collect();
                    let half = e
                        .iter()
                        .fold(zero_v(), |acc, x| add(&acc, &scale(x, &frac(1, 2))));
                    (add(&pos(corner), &half), e)
                }
                Place::FromTo { from, to } => {
                    let (a, b) = (pos(from), pos(to));
                    let e = sub(&b, &a);
                    (scale(&add(&a, &b), &frac(1, 2)), vec![e])
                }
                _ => unreachable!("matched above"),
            };
            // Volume, area or length: the product of the edge lengths
            // (edges are perpendicular), a square root of a rational.
            let mass = by_mass(Some(sqrt(&edges.iter().map(|e| dot(e, e)).product())));
            ExactPart {
                second_moment: spanned(&mass, &edges),
                mass,
                center,
            }
        }
        Place::Vertices(v) => {
            let (center, per_mass, area) = triangle_form(&v.map(|p| pos(&p)));
            let mass = by_mass(Some(area));
            ExactPart {
                second_moment: mscale(&per_mass, &mass),
                mass,
                center,
            }
        }
        Place::Prism {
            polygon,
            length,
            origin,
            rotation,
        } => {
            let r = rotation_matrix(rotation.as_ref());
            let poly: Vec<[Q; 2]> = polygon.iter().map(|v| v.map(|x| q(x) * &l)).collect();
            let len = q(*length) * &l;
            let (area, g, s) = super::solids::polygon(&poly);
            let mass = by_mass(Some(&area * &len));
            let mut local = zero_m();
            local[0][0] = s[0].clone();
            local[1][1] = s[1].clone();
            local[0][1] = s[2].clone();
            local[1][0] = s[2].clone();
            local[2][2] = &len * &len / int(12);
            let [gx, gy] = g;
            ExactPart {
                second_moment: mscale(&turned(&r, &local), &mass),
                center: add(&pos(origin), &mvec(&r, &[gx, gy, Q::zero()])),
                mass,
            }
        }
        Place::Given {
            inertia,
            products,
            center,
            rotation,
        } => {
            // The tensor in SI and the tensor convention (off-diagonals
            // −∫xy dm), symmetrised as massprop documents.
            let unit = &mu * &l * &l;
            let sign = match products {
                Products::Tensor => int(1),
                Products::Positive => int(-1),
            };
            let i: M3 = std::array::from_fn(|a| {
                std::array::from_fn(|b| {
                    let x = (q(inertia[a][b]) + q(inertia[b][a])) / int(2) * &unit;
                    if a == b { x } else { x * &sign }
                })
            });
            // I = tr(C)·E − C, so tr I = 2 tr C and C = (tr I / 2)·E − I.
            let half = (&i[0][0] + &i[1][1] + &i[2][2]) / int(2);
            let c: M3 = std::array::from_fn(|a| {
                std::array::from_fn(|b| {
                    if a == b {
                        &half - &i[a][b]
                    } else {
                        -i[a][b].clone()
                    }
                })
            });
            ExactPart {
                second_moment: turned(&rotation_matrix(rotation.as_ref()), &c),
                mass: by_mass(None),
                center: pos(center),
            }
        }
    }
}

/// Compose a scene exactly.
pub fn compose(scene: &Scene) -> Exact {
    let parts: Vec<ExactPart> = scene
        .parts
        .iter()
        .map(|p| exact_part(p, scene.length, scene.mass))
        .collect();
    let l = scene.length.si();
    let about = scene.about.map(|a| scale(&qv(a), &l));
    compose_parts(parts, about)
}

/// Compose parts given exactly (SI), with a reference point (SI): what
/// `compose` does for a scene, for bodies a `Scene` cannot write
/// (sub-assemblies, copies, meshes: tests/support/placed.rs).
pub fn compose_parts(parts: Vec<ExactPart>, about: Option<V3>) -> Exact {
    let mass: Q = parts.iter().map(|p| p.mass.clone()).sum();
    let first = parts
        .iter()
        .fold(zero_v(), |acc, p| add(&acc, &scale(&p.center, &p.mass)));
    let com = scale(&first, &(Q::one() / &mass));
    let second_moment = parts.iter().fold(zero_m(), |acc, p| {
        let d = sub(&p.center, &com);
        madd(
            &madd(&acc, &p.second_moment),
            &mscale(&outer(&d, &d), &p.mass),
        )
    });
    Exact {
        inertia: inertia_of(&second_moment),
        about,
        mass,
        com,
        second_moment,
        parts,
    }
}

/// `x` rounded to the nearest multiple of 2⁻ᵇⁱᵗˢ, as the integer x·2ᵇⁱᵗˢ.
fn fixed(x: &Q, bits: usize) -> BigInt {
    (x * Q::from_integer(BigInt::one() << bits))
        .round()
        .to_integer()
}

/// `compose` for scenes of very many parts: each part's exact mass, first
/// moment and second moment about the (rounded) centre are rounded to
/// multiples of 2⁻ᵇⁱᵗˢ (SI) before they are summed.
///
/// NOTE: exact sums of thousands of quaternion-turned parts are out of
/// reach: every R(q) divides by its own |q|², and the denominator of the sum
/// becomes the product of all of them. Rounded to a common power of two the
/// sums stay integers. The centre is rounded too, and its rounding removed
/// exactly (C = Σ(Cᵢ + mᵢdᵢdᵢᵀ) − s sᵀ/m with s = Σ mᵢdᵢ), so the result is
/// within N·2⁻ᵇⁱᵗˢ of the exact one in every entry: with 400 bits, 1e-115
/// for a million parts.
pub fn compose_rounded(scene: &Scene, bits: usize) -> Exact {
    let one = Q::from_integer(BigInt::one() << bits);
    let part = |p: &Part| exact_part(p, scene.length, scene.mass);
    let mut mass = BigInt::zero();
    let mut first: [BigInt; 3] = std::array::from_fn(|_| BigInt::zero());
    for p in &scene.parts {
        let e = part(p);
        mass += fixed(&e.mass, bits);
        for (f, c) in first.iter_mut().zip(&e.center) {
            *f += fixed(&(&e.mass * c), bits);
        }
    }
    let m = Q::from_integer(mass.clone()) / &one;
    let com: V3 = std::array::from_fn(|i| {
        Q::from_integer(fixed(
            &(Q::from_integer(first[i].clone()) / Q::from_integer(mass.clone())),
            bits,
        )) / &one
    });
    let mut c: [[BigInt; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| BigInt::zero()));
    let mut s: [BigInt; 3] = std::array::from_fn(|_| BigInt::zero());
    for p in &scene.parts {
        let e = part(p);
        let d = sub(&e.center, &com);
        let md = scale(&d, &e.mass);
        for i in 0..3 {
            s[i] += fixed(&md[i], bits);
            for j in 0..3 {
                c[i][j] += fixed(&(&e.second_moment[i][j] + &md[i] * &d[j]), bits);
            }
        }
    }
    let s: V3 = std::array::from_fn(|i| Q::from_integer(s[i].clone()) / &one);
    let second_moment: M3 = std::array::from_fn(|i| {
        std::array::from_fn(|j| Q::from_integer(c[i][j].clone()) / &one - &s[i] * &s[j] / &m)
    });
    let l = scene.length.si();
    Exact {
        inertia: inertia_of(&second_moment),
        about: scene.about.map(|a| scale(&qv(a), &l)),
        com: add(&com, &scale(&s, &(Q::one() / &m))),
        mass: m,
        second_moment,
        parts: Vec::new(),
    }
}

impl Exact {
    /// Inertia tensor about `point` (SI): the shift C + m d dᵀ, d = c − point.
    pub fn inertia_about(&self, point: &V3) -> M3 {
        let d = sub(&self.com, point);
        inertia_of(&madd(
            &self.second_moment,
            &mscale(&outer(&d, &d), &self.mass),
        ))
    }

    /// Σ mᵢ|cᵢ| / m, the scale of the centre of mass that rounding in the
    /// first moments is relative to (|c| itself can be tiny by cancellation).
    pub fn com_scale(&self) -> f64 {
        self.parts
            .iter()
            .map(|p| f(&p.mass) * norm(&p.center))
            .sum::<f64>()
            / f(&self.mass)
    }

    pub fn principal(&self) -> Principal {
        principal(&self.inertia)
    }
}

/// |v| in f64 (for scales, not for comparisons).
pub fn norm(v: &V3) -> f64 {
    f(&dot(v, v)).sqrt()
}

// ---------------------------------------------------------------------------
// Eigenvalues

/// The characteristic polynomial p(λ) = det(λE − A) = λ³ − tλ² + c₁λ − det A
/// of a rational symmetric matrix, times the least common denominator D of
/// its coefficients, so that it has integer coefficients.
///
/// NOTE: the roots are located by counting, not by sign changes of p alone,
/// so equal and nearly equal eigenvalues need no special care. Shifted to a
/// point x, p(x + μ) = μ³ + ½p″(x) μ² + p′(x) μ + p(x). A polynomial whose
/// roots are all real (A is symmetric) has exactly as many positive roots as
/// its coefficients have sign changes (Descartes' rule is exact then), so
/// the sign changes of (1, ½p″(x), p′(x), p(x)) count the eigenvalues above
/// x, and the trailing zeros among them the eigenvalues equal to x. Those
/// counts, at dyadic x, drive a bisection for each eigenvalue in turn.
pub struct CharPoly {
    /// [D, −tD, c₁D, −det·D]
    coeffs: [BigInt; 4],
}

impl CharPoly {
    pub fn new(a: &M3) -> CharPoly {
        let t = &a[0][0] + &a[1][1] + &a[2][2];
        let minor = |i: usize, j: usize| &a[i][i] * &a[j][j] - &a[i][j] * &a[j][i];
        let c1 = minor(0, 1) + minor(0, 2) + minor(1, 2);
        let det = dot(&a[0], &cross(&a[1], &a[2]));
        let raw = [Q::one(), -t, c1, -det];
        let lcm = raw
            .iter()
            .fold(BigInt::one(), |acc, c| num_integer_lcm(&acc, c.denom()));
        let coeffs = raw.map(|c| (c * Q::from_integer(lcm.clone())).to_integer());
        CharPoly { coeffs }
    }

    /// (number of roots below x, number equal to x) for x = n·2⁻ᵏ.
    pub fn locate(&self, n: &BigInt, k: i64) -> (usize, usize) {
        // Scale to an integer numerator over 2^k with k ≥ 0.
        let (n, k) = if k < 0 {
            (n << (-k) as usize, 0usize)
        } else {
            (n.clone(), k as usize)
        };
        let [d, a, b, c] = &self.coeffs;
        let s = BigInt::one() << k;
        let s2 = &s * &s;
        let n2 = &n * &n;
        // 8ᵏ·D·p(x), 4ᵏ·D·p′(x), 2ᵏ·D·½p″(x): positive multiples, same signs.
        let p0 = d * &n2 * &n + a * &n2 * &s + b * &n * &s2 + c * &s2 * &s;
        let (two, three) = (BigInt::from(2), BigInt::from(3));
        let p1 = d * &n2 * &three + a * &n * &s * &two + b * &s2;
        let p2 = d * &n * &three + a * &s;
        let multiplicity = if !p0.is_zero() {
            0
        } else if !p1.is_zero() {
            1
        } else if !p2.is_zero() {
            2
        } else {
            3
        };
        let signs: Vec<Sign> = [d, &p2, &p1, &p0]
            .into_iter()
            .map(BigInt::sign)
            .filter(|s| *s != Sign::NoSign)
            .collect();
        let above = signs.windows(2).filter(|w| w[0] != w[1]).count();
        (3 - above - multiplicity, multiplicity)
    }

    /// The k-th smallest root (k = 0, 1, 2), within relative 2⁻¹⁴¹ (exact
    /// when a bisection point hits it: always for 0, and for dyadic roots
    /// with few bits). All roots lie in (−2ᵉ, 2ᵉ).
    fn root(&self, k: usize, e: i64) -> Q {
        let dyadic = |n: &BigInt, k: i64| -> Q {
            if k >= 0 {
                Q::new(n.clone(), BigInt::one() << k as usize)
            } else {
                Q::from_integer(n << (-k) as usize)
            }
        };
        let (below, equal) = self.locate(&BigInt::zero(), 0);
        if (below..below + equal).contains(&k) {
            return Q::zero();
        }
        // The root lies in [lo, lo + 1]·2⁻ˢ: [0, 2ᵉ] or [−2ᵉ, 0].
        let mut scale = -e;
        let mut lo = if k >= below + equal {
            BigInt::zero()
        } else {
            BigInt::from(-1)
        };
        let fine = BigInt::one() << 141usize;
        loop {
            // Narrow enough when the interval is within 2⁻¹⁴¹ of its ends.
            let hi: BigInt = &lo + 1;
            if lo >= fine || -&hi >= fine {
                return dyadic(&(&lo * 2 + 1), scale + 1);
            }
            let mid = &lo * 2 + 1;
            scale += 1;
            let (below, equal) = self.locate(&mid, scale);
            if k < below {
                lo = &lo * 2;
            } else if k < below + equal {
                return dyadic(&mid, scale);
            } else {
                lo = mid;
            }
        }
    }
}

fn num_integer_lcm(a: &BigInt, b: &BigInt) -> BigInt {
    let g = gcd(a.clone(), b.clone());
    (a / g * b).abs()
}

fn gcd(mut a: BigInt, mut b: BigInt) -> BigInt {
    while !b.is_zero() {
        let r = &a % &b;
        a = b;
        b = r;
    }
    a.abs()
}

/// The eigenvalues of a rational symmetric matrix, ascending, each within
/// relative 2⁻¹⁴¹ (≈ 3.5e-43), equal ones equal.
pub fn eigenvalues(a: &M3) -> [Q; 3] {
    // Gershgorin: every eigenvalue is within the largest absolute row sum.
    let g: Q = a
        .iter()
        .map(|row| row.iter().map(|x| x.abs()).sum::<Q>())
        .max()
        .expect("three rows");
    if g.is_zero() {
        return std::array::from_fn(|_| Q::zero());
    }
    let mut e = g.numer().bits() as i64 - g.denom().bits() as i64 + 1;
    let two_to = |e: i64| {
        if e >= 0 {
            Q::from_integer(BigInt::one() << e as usize)
        } else {
            Q::new(BigInt::one(), BigInt::one() << (-e) as usize)
        }
    };
    // 2ᵉ > G strictly, so a dyadic eigenvalue ±G is a bisection point.
    while two_to(e - 1) > g {
        e -= 1;
    }
    while two_to(e) <= g {
        e += 1;
    }
    let p = CharPoly::new(a);
    std::array::from_fn(|k| p.root(k, e))
}

/// Principal moments (ascending) and, where a moment is separated from the
/// others, its axis (not normalised).
#[derive(Clone, Debug)]
pub struct Principal {
    pub moments: [Q; 3],
    /// `None` where the moment equals another within relative 2⁻¹²⁰: the
    /// axis is not unique.
    pub axes: [Option<V3>; 3],
}

impl Principal {
    /// Relative gap of moment k to its nearest neighbour, over the largest
    /// moment.
    pub fn gap(&self, k: usize) -> f64 {
        let top = f(&self.moments[2]);
        (0..3)
            .filter(|&j| j != k)
            .map(|j| f(&(&self.moments[j] - &self.moments[k]).abs()) / top)
            .fold(f64::INFINITY, f64::min)
    }
}

/// Eigenvalues and axes of a symmetric rational matrix. An axis of a simple
/// eigenvalue λ is the largest of the cross products of pairs of rows of
/// A − λE (rows span the plane perpendicular to it); with λ accurate to
/// 2⁻¹⁴¹, the axis is accurate to about 2⁻¹⁴¹‖A‖/gap.
pub fn principal(a: &M3) -> Principal {
    let moments = eigenvalues(a);
    let top = moments.iter().map(|m| m.abs()).max().expect("three");
    let tiny = &top * Q::new(BigInt::one(), BigInt::one() << 120usize);
    let axes = std::array::from_fn(|k| {
        let separated = (0..3)
            .filter(|&j| j != k)
            .all(|j| (&moments[j] - &moments[k]).abs() > tiny);
        separated.then(|| {
            let m: M3 = std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    if i == j {
                        &a[i][j] - &moments[k]
                    } else {
                        a[i][j].clone()
                    }
                })
            });
            [(0, 1), (1, 2), (2, 0)]
                .map(|(i, j)| cross(&m[i], &m[j]))
                .into_iter()
                .max_by(|x, y| dot(x, x).cmp(&dot(y, y)))
                .expect("three candidates")
        })
    });
    Principal { moments, axes }
}

// ---------------------------------------------------------------------------
// Comparisons, computed exactly and returned as f64

/// ‖a − b‖_F / ‖b‖_F for a computed f64 matrix `a` and an exact `b`.
pub fn rel_frobenius(a: &[[f64; 3]; 3], b: &M3) -> f64 {
    let mut num = Q::zero();
    let mut den = Q::zero();
    for i in 0..3 {
        for j in 0..3 {
            let d = q(a[i][j]) - &b[i][j];
            num += &d * &d;
            den += &b[i][j] * &b[i][j];
        }
    }
    ratio_sqrt(&num, &den)
}

/// ‖a − b‖_F / ‖b‖_F for two exact matrices.
pub fn rel_frobenius_exact(a: &M3, b: &M3) -> f64 {
    let mut num = Q::zero();
    let mut den = Q::zero();
    for i in 0..3 {
        for j in 0..3 {
            let d = &a[i][j] - &b[i][j];
            num += &d * &d;
            den += &b[i][j] * &b[i][j];
        }
    }
    ratio_sqrt(&num, &den)
}

/// ‖a − b‖_F / ‖c‖_F, all f64 computed matrices (differences taken exactly).
pub fn rel_frobenius_f64(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3], c: &[[f64; 3]; 3]) -> f64 {
    rel_frobenius(a, &b.map(qv)) * norm_f(c) / norm_f(b)
}

fn norm_f(m: &[[f64; 3]; 3]) -> f64 {
    m.iter().flatten().map(|x| x * x).sum::<f64>().sqrt()
}

/// √(num/den), ∞ for x/0 with x ≠ 0 and 0 for 0/0.
fn ratio_sqrt(num: &Q, den: &Q) -> f64 {
    match (num.is_zero(), den.is_zero()) {
        (true, _) => 0.0,
        (false, true) => f64::INFINITY,
        _ => f(&(num / den)).sqrt(),
    }
}

/// |a − b| / |b|.
pub fn rel(a: f64, b: &Q) -> f64 {
    let d = (q(a) - b).abs();
    ratio_sqrt(&(&d * &d), &(b * b))
}

/// |a − b| / scale.
pub fn err_over(a: f64, b: &Q, scale: f64) -> f64 {
    f(&(q(a) - b).abs()) / scale
}

/// |a − b| / |b| for vectors.
pub fn rel_vec(a: &[f64; 3], b: &V3) -> f64 {
    let d = sub(&qv(*a), b);
    ratio_sqrt(&dot(&d, &d), &dot(b, b))
}

/// |a − b| / scale for vectors; 0 when a = b (also for a zero scale: a
/// body whose parts all sit at the origin).
pub fn vec_err_over(a: &[f64; 3], b: &V3, scale: f64) -> f64 {
    let d = sub(&qv(*a), b);
    let d = dot(&d, &d);
    if d.is_zero() {
        0.0
    } else {
        f(&d).sqrt() / scale
    }
}

/// sin of the angle between the lines of `a` (computed) and `b` (exact, any
/// length): √(1 − (a·b)²/(|a|²|b|²)), with the difference taken exactly.
pub fn axis_sin(a: &[f64; 3], b: &V3) -> f64 {
    let a = qv(*a);
    let ab = dot(&a, b);
    let s2 = Q::one() - &ab * &ab / (dot(&a, &a) * dot(b, b));
    f(&s2).max(0.0).sqrt()
}

// ---------------------------------------------------------------------------
// Writing a scene as a part file

/// An f64 as TOML text that parses back to exactly the same value: Rust's
/// `{:?}` is the shortest round-trip form, and always a TOML float (`1.0`,
/// `0.1`, `1e-9`, `1.5e16`, `-0.0`: TOML allows an exponent on an integer
/// part, and Rust never writes `inf`, `NaN` or a bare `1.` for finite values).
pub fn number(x: f64) -> String {
    assert!(x.is_finite(), "part files hold finite numbers");
    let s = format!("{x:?}");
    debug_assert_eq!(s.parse::<f64>().map(f64::to_bits), Ok(x.to_bits()));
    s
}

fn array(v: &[f64]) -> String {
    let items: Vec<String> = v.iter().map(|&x| number(x)).collect();
    format!("[{}]", items.join(", "))
}

/// Three rows: `[[..], [..], [..]]`.
fn matrix(m: &[[f64; 3]; 3]) -> String {
    let rows: Vec<String> = m.iter().map(|r| array(r)).collect();
    format!("[{}]", rows.join(", "))
}

fn write_rotation(s: &mut String, rotation: Option<&Rotation>) {
    match rotation {
        None => {}
        Some(Rotation::Quaternion(qq)) => {
            writeln!(s, "rotation = {{ quaternion = {} }}", array(qq)).unwrap()
        }
        Some(Rotation::Matrix(m)) => {
            writeln!(s, "rotation = {{ matrix = {} }}", matrix(m)).unwrap()
        }
    }
}

/// The scene as a part file.
pub fn to_toml(scene: &Scene) -> String {
    let mut s = String::new();
    writeln!(
        s,
        "units = {{ length = \"{}\", mass = \"{}\" }}",
        scene.length.symbol(),
        scene.mass.symbol()
    )
    .unwrap();
    for p in &scene.parts {
        writeln!(s, "\n[[part]]\nshape = \"{}\"", p.shape.name()).unwrap();
        match p.amount {
            Amount::Mass(m) => writeln!(s, "mass = {}", number(m)).unwrap(),
            Amount::Density(d) => writeln!(s, "{} = {}", p.shape.density_key(), number(d)).unwrap(),
        }
        match &p.place {
            Place::Center {
                size,
                center,
                rotation,
            } => {
                match p.shape {
                    Shape::Box | Shape::Plate => writeln!(s, "size = {}", array(size)).unwrap(),
                    Shape::Rod => writeln!(s, "length = {}", number(size[0])).unwrap(),
                    Shape::Point => {}
                    Shape::Cylinder => {
                        writeln!(
                            s,
                            "radius = {}\nlength = {}",
                            number(size[0]),
                            number(size[1])
                        )
                        .unwrap();
                        if let Some(r) = size.get(2) {
                            writeln!(s, "inner_radius = {}", number(*r)).unwrap();
                        }
                    }
                    Shape::Disk | Shape::Sphere => {
                        writeln!(s, "radius = {}", number(size[0])).unwrap();
                        if let Some(r) = size.get(1) {
                            writeln!(s, "inner_radius = {}", number(*r)).unwrap();
                        }
                    }
                    Shape::Cone => {
                        writeln!(
                            s,
                            "radius = {}\ntop_radius = {}\nlength = {}",
                            number(size[0]),
                            number(size[1]),
                            number(size[2])
                        )
                        .unwrap();
                        if let [_, _, _, a0, a1] = size[..] {
                            writeln!(
                                s,
                                "inner_radius = {}\ntop_inner_radius = {}",
                                number(a0),
                                number(a1)
                            )
                            .unwrap();
                        }
                    }
                    Shape::Torus => {
                        writeln!(
                            s,
                            "radius = {}\ntube_radius = {}",
                            number(size[0]),
                            number(size[1])
                        )
                        .unwrap();
                        if let Some(b) = size.get(2) {
                            writeln!(s, "inner_tube_radius = {}", number(*b)).unwrap();
                        }
                    }
                    Shape::Hemisphere => {
                        writeln!(s, "radius = {}", number(size[0])).unwrap();
                        if let Some(r) = size.get(1) {
                            writeln!(s, "inner_radius = {}", number(*r)).unwrap();
                        }
                    }
                    Shape::Capsule => {
                        writeln!(
                            s,
                            "radius = {}\nlength = {}",
                            number(size[0]),
                            number(size[1])
                        )
                        .unwrap();
                        if let Some(r) = size.get(2) {
                            writeln!(s, "inner_radius = {}", number(*r)).unwrap();
                        }
                    }
                    Shape::Ellipsoid => {
                        writeln!(
                            s,
                            "radii = [{}, {}, {}]",
                            number(size[0]),
                            number(size[1]),
                            number(size[2])
                        )
                        .unwrap();
                    }
                    Shape::Triangle | Shape::Inertia | Shape::Prism => {
                        panic!("a {} is not placed by size", p.shape.name())
                    }
                }
                writeln!(s, "center = {}", array(center)).unwrap();
                write_rotation(&mut s, rotation.as_ref());
            }
            Place::Edges { corner, edges } => {
                let e: Vec<String> = edges.iter().map(|e| array(e)).collect();
                writeln!(s, "corner = {}\nedges = [{}]", array(corner), e.join(", ")).unwrap();
            }
            Place::FromTo { from, to } => {
                writeln!(s, "from = {}\nto = {}", array(from), array(to)).unwrap();
            }
            Place::Vertices(v) => {
                writeln!(s, "vertices = {}", matrix(v)).unwrap();
            }
            Place::Given {
                inertia,
                products,
                center,
                rotation,
            } => {
                writeln!(s, "inertia = {}", matrix(inertia)).unwrap();
                if *products == Products::Positive {
                    writeln!(s, "products = \"positive\"").unwrap();
                }
                writeln!(s, "center = {}", array(center)).unwrap();
                write_rotation(&mut s, rotation.as_ref());
            }
            Place::Prism {
                polygon,
                length,
                origin,
                rotation,
            } => {
                let v: Vec<String> = polygon.iter().map(|v| array(v)).collect();
                writeln!(
                    s,
                    "polygon = [{}]\nlength = {}\norigin = {}",
                    v.join(", "),
                    number(*length),
                    array(origin)
                )
                .unwrap();
                write_rotation(&mut s, rotation.as_ref());
            }
        }
    }
    if let Some(a) = scene.about {
        writeln!(s, "\n[analysis]\nabout = {}", array(&a)).unwrap();
    }
    s
}

// ---------------------------------------------------------------------------
// Self-tests: the reference must be able to fail.

#[cfg(test)]
mod tests {
    use super::*;

    fn diag(a: i64, b: i64, c: i64) -> M3 {
        let mut m = zero_m();
        m[0][0] = int(a);
        m[1][1] = int(b);
        m[2][2] = int(c);
        m
    }

    fn rel_q(a: &Q, b: &Q) -> f64 {
        f(&((a - b) / b).abs())
    }

    /// The rotation of a Pythagorean quadruple: [[3,−2,6],[6,3,−2],[−2,6,3]]/7.
    fn pythagorean() -> M3 {
        [[3, -2, 6], [6, 3, -2], [-2, 6, 3]].map(|row| row.map(|x| frac(x, 7)))
    }

    #[test]
    fn a_unit_cube_has_moments_of_a_sixth_of_its_mass() {
        let s = Scene::si(vec![Part::cuboid(
            [1.0, 1.0, 1.0],
            [0.5, -2.0, 7.0],
            None,
            Amount::Mass(3.0),
        )]);
        let e = compose(&s);
        assert_eq!(e.inertia, mscale(&diag(1, 1, 1), &frac(3, 6)));
        assert_eq!(e.principal().moments, std::array::from_fn(|_| frac(1, 2)));
    }

    #[test]
    fn a_rotated_cube_by_density_is_still_isotropic() {
        // A non-unit quaternion: R = poly(q)/|q|² is still exactly a rotation.
        let s = Scene::si(vec![Part::cuboid(
            [2.0, 2.0, 2.0],
            [0.0; 3],
            Some([0.9, 0.1, -0.3, 0.2]),
            Amount::Density(0.5),
        )]);
        let e = compose(&s);
        assert_eq!(e.mass, int(4));
        assert_eq!(e.inertia, mscale(&diag(1, 1, 1), &(int(4) * frac(8, 12))));
    }

    #[test]
    fn quaternion_rotations_are_exactly_orthonormal() {
        let r = rotation(&[0.9, 0.1, -0.3, 0.2].map(q));
        assert_eq!(mmul(&r, &transpose(&r)), diag(1, 1, 1));
        assert_eq!(dot(&r[0], &cross(&r[1], &r[2])), int(1));
        // A quarter turn about z takes x to y.
        let h = q(0.5f64.sqrt());
        let z = rotation(&[h.clone(), int(0), int(0), h]);
        assert_eq!(
            mvec(&z, &[int(1), int(0), int(0)]),
            [int(0), int(1), int(0)]
        );
    }

    #[test]
    fn rod_and_plate_match_their_closed_forms() {
        // Rod of mass m, length L about its middle: m L²/12 perpendicular.
        let rod = compose(&Scene::si(vec![Part::rod_from_to(
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 4.0],
            Amount::Density(2.0),
        )]));
        assert_eq!(rod.mass, int(6));
        assert_eq!(rod.com, [int(0), int(0), frac(5, 2)]);
        assert_eq!(rod.inertia, mscale(&diag(1, 1, 0), &frac(6 * 9, 12)));
        // Plate a × b: m(a² + b²)/12 about its normal, m b²/12 about x.
        let plate = compose(&Scene::si(vec![Part::plate(
            [3.0, 4.0],
            [1.0, 1.0, 1.0],
            None,
            Amount::Mass(12.0),
        )]));
        assert_eq!(plate.inertia, diag(16, 9, 25));
    }

    #[test]
    fn a_rod_by_density_from_an_irrational_length_uses_the_square_root() {
        // From (0,0,0) to (1,1,0): length √2, mass √2·3.
        let rod = compose(&Scene::si(vec![Part::rod_from_to(
            [0.0; 3],
            [1.0, 1.0, 0.0],
            Amount::Density(3.0),
        )]));
        let exact = 3.0 * 2f64.sqrt();
        assert!(rel(exact, &rod.mass) < 2e-16);
        assert!(rel_q(&(&rod.mass * &rod.mass), &int(18)) < 1e-59);
    }

    #[test]
    fn edges_and_size_placements_agree_exactly() {
        let a = compose(&Scene::si(vec![Part::cuboid(
            [2.0, 4.0, 6.0],
            [1.0, 2.0, 3.0],
            None,
            Amount::Density(0.25),
        )]));
        let b = compose(&Scene::si(vec![Part::box_edges(
            [0.0; 3],
            [[0.0, 4.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 6.0]],
            Amount::Density(0.25),
        )]));
        assert_eq!((a.mass, a.com, a.inertia), (b.mass, b.com, b.inertia));
    }

    #[test]
    fn splitting_a_box_in_exact_halves_changes_nothing() {
        let whole = compose(&Scene::si(vec![Part::box_edges(
            [1.0, 2.0, 3.0],
            [[2.0, 1.0, 2.0], [1.0, 2.0, -2.0], [2.0, -2.0, -1.0]],
            Amount::Mass(2.0),
        )]));
        let halves = compose(&Scene::si(vec![
            Part::box_edges(
                [1.0, 2.0, 3.0],
                [[1.0, 0.5, 1.0], [1.0, 2.0, -2.0], [2.0, -2.0, -1.0]],
                Amount::Mass(1.0),
            ),
            Part::box_edges(
                [2.0, 2.5, 4.0],
                [[1.0, 0.5, 1.0], [1.0, 2.0, -2.0], [2.0, -2.0, -1.0]],
                Amount::Mass(1.0),
            ),
        ]));
        assert_eq!(whole.com, halves.com);
        assert_eq!(whole.inertia, halves.inertia);
    }

    #[test]
    fn units_convert_with_exact_factors() {
        let p = Part::cuboid([10.0, 20.0, 30.0], [1.0, 2.0, 3.0], None, Amount::Mass(2.0));
        let s = Scene {
            length: Length::In,
            mass: Mass::Lb,
            parts: vec![p],
            about: None,
        };
        let e = compose(&s);
        assert_eq!(e.mass, frac(2 * 45_359_237, 100_000_000));
        assert_eq!(e.com[2], frac(3 * 254, 10_000));
        // I_zz = m (a² + b²)/12, exactly in SI.
        let l = Length::In.si();
        assert_eq!(e.inertia[2][2], &e.mass * int(500) * &l * &l / int(12));
    }

    #[test]
    fn the_roots_of_a_diagonal_matrix_are_its_entries() {
        let ev = eigenvalues(&diag(3, -1, 2));
        assert_eq!(ev, [int(-1), int(2), int(3)]);
        let ev = eigenvalues(&mscale(&diag(1, 7, 5), &frac(1, 3)));
        for (e, x) in ev.iter().zip([frac(1, 3), frac(5, 3), frac(7, 3)]) {
            assert!(rel_q(e, &x) < 1e-42, "{e} vs {x}");
        }
    }

    #[test]
    fn roots_of_a_rotated_diagonal_matrix_and_its_axes() {
        let r = pythagorean();
        let a = mmul(
            &mmul(&transpose(&r), &mscale(&diag(11, 2, 5), &frac(1, 10))),
            &r,
        );
        assert!(a[0][1] != int(0), "the test matrix is not diagonal");
        let p = principal(&a);
        for (e, x) in p
            .moments
            .iter()
            .zip([frac(2, 10), frac(5, 10), frac(11, 10)])
        {
            assert!(rel_q(e, &x) < 1e-42, "{e} vs {x}");
        }
        // Aᵀ diag A: the eigenvector of diagonal entry k is row k of R.
        for (k, row) in [1, 2, 0].into_iter().enumerate() {
            let axis = fv(p.axes[k].as_ref().expect("distinct"));
            assert!(axis_sin(&axis, &r[row]) < 1e-15);
            let wrong = fv(&r[(row + 1) % 3]);
            assert!(axis_sin(&wrong, p.axes[k].as_ref().unwrap()) > 0.99);
        }
    }

    #[test]
    fn equal_and_nearly_equal_roots_are_separated() {
        let r = pythagorean();
        let rotate = |d: M3| mmul(&mmul(&transpose(&r), &d), &r);
        let p = principal(&rotate(diag(2, 2, 5)));
        assert_eq!(p.moments[0], p.moments[1]);
        assert!(rel_q(&p.moments[0], &int(2)) < 1e-42);
        assert!(p.axes[0].is_none() && p.axes[1].is_none() && p.axes[2].is_some());
        // Triple and zero roots come out exact.
        assert_eq!(
            eigenvalues(&rotate(diag(4, 4, 4))),
            std::array::from_fn(|_| int(4))
        );
        assert_eq!(eigenvalues(&rotate(diag(0, 0, 1)))[1], int(0));
        // Nearly equal: 1 and 1 + 10⁻³⁰ are told apart.
        let mut d = diag(1, 1, 3);
        d[1][1] = int(1) + Q::new(BigInt::one(), BigInt::from(10).pow(30));
        let p = principal(&rotate(d.clone()));
        assert!(p.moments[1] > p.moments[0]);
        assert!(rel_q(&(&p.moments[1] - &p.moments[0]), &(&d[1][1] - int(1))) < 1e-10);
        assert!(axis_sin(&fv(&r[1]), p.axes[1].as_ref().unwrap()) < 1e-9);
    }

    #[test]
    fn a_turned_slender_box_has_its_closed_form_moments() {
        // R(q) is exactly orthogonal for any q, so the moments of a turned
        // 1 × a × a box are exactly m(a² + a²)/12 and m(1 + a²)/12 (twice).
        let a = 1e-6;
        let s = Scene::si(vec![Part::cuboid(
            [a, 1.0, a],
            [0.25, -0.5, 3.0],
            Some([0.3, -0.7, 0.2, 0.9]),
            Amount::Mass(1.5),
        )]);
        let p = compose(&s).principal();
        let (m, a) = (q(1.5), q(a));
        let small = &m * int(2) * &a * &a / int(12);
        let large = &m * (int(1) + &a * &a) / int(12);
        assert!(rel_q(&p.moments[0], &small) < 1e-42);
        assert_eq!(p.moments[1], p.moments[2]);
        assert!(rel_q(&p.moments[2], &large) < 1e-42);
        // The long axis is the local y axis, turned.
        let r = rotation(&[0.3, -0.7, 0.2, 0.9].map(q));
        let y = [r[0][1].clone(), r[1][1].clone(), r[2][1].clone()];
        let axis = p.axes[0].as_ref().expect("distinct");
        assert!(
            f(&(int(1) - dot(axis, &y) * dot(axis, &y) / (dot(axis, axis) * dot(&y, &y)))) < 1e-60
        );
    }

    #[test]
    fn a_wrong_product_sign_is_caught() {
        let s = Scene::si(vec![
            Part::cuboid([1.0, 2.0, 3.0], [1.0, 2.0, 0.5], None, Amount::Mass(1.0)),
            Part::point(2.0, [-1.0, 0.25, 2.0]),
        ]);
        let e = compose(&s);
        let good = fm(&e.inertia);
        assert!(rel_frobenius(&good, &e.inertia) < 1e-16);
        // Both parts' x and y offsets from the centre of mass have the same
        // sign, so ∫xy dm > 0 and the tensor entry I_xy = −∫xy dm < 0.
        assert!(good[0][1] < 0.0);
        let mut bad = good;
        bad[0][1] = -bad[0][1];
        bad[1][0] = -bad[1][0];
        assert!(rel_frobenius(&bad, &e.inertia) > 0.1);
    }

    #[test]
    fn axis_and_error_helpers_measure_what_they_say() {
        let b = [int(3), int(4), int(0)];
        // −0.6 and −0.8 round in f64 by up to 1.1e-16 relative.
        assert!(axis_sin(&[-0.6, -0.8, 0.0], &b) < 1e-16);
        assert!((axis_sin(&[0.0, 0.0, 1.0], &b) - 1.0).abs() < 1e-16);
        assert!((axis_sin(&[1e-10, 0.0, 1.0], &[int(1), int(0), int(0)]) - 1.0).abs() < 1e-16);
        assert!((axis_sin(&[1.0, 1e-10, 0.0], &[int(1), int(0), int(0)]) - 1e-10).abs() < 1e-20);
        assert_eq!(rel(1.5, &int(1)), 0.5);
        assert!((rel_vec(&[3.0, 4.0, 1.0], &[int(3), int(4), int(0)]) - 0.2).abs() < 1e-16);
    }

    /// A plain f64 composition about the origin, shifted back: fine for a
    /// benign scene near the origin, so the two must agree to rounding.
    #[test]
    fn agrees_with_a_naive_f64_composition_on_a_benign_scene() {
        let h = 0.5f64.sqrt();
        let quats = [[h, 0.0, 0.0, h], [0.5, 0.5, 0.5, 0.5], [0.8, 0.6, 0.0, 0.0]];
        let mut parts = Vec::new();
        for (k, qq) in quats.iter().enumerate() {
            let x = k as f64;
            parts.push(Part::cuboid(
                [0.3 + x, 0.7, 1.1],
                [x, 1.0 - x, 0.5],
                Some(*qq),
                Amount::Mass(1.0 + x),
            ));
        }
        parts.push(Part::rod(
            2.0,
            [0.2, 0.1, -1.0],
            Some(quats[1]),
            Amount::Mass(0.7),
        ));
        parts.push(Part::plate(
            [0.4, 0.9],
            [-0.3, 0.2, 0.1],
            Some(quats[2]),
            Amount::Density(5.0),
        ));
        parts.push(Part::point(0.3, [1.0, -1.0, 2.0]));
        let e = compose(&Scene::si(parts.clone()));

        // Naive: rotation matrix from the textbook closed form, I about the
        // origin summed, then shifted back with the parallel-axis theorem.
        let mut mass = 0.0;
        let mut first = [0.0; 3];
        let mut i_origin = [[0.0; 3]; 3];
        for p in &parts {
            let Place::Center {
                size,
                center,
                rotation,
            } = &p.place
            else {
                unreachable!()
            };
            let [w, x, y, z] = match rotation {
                None => [1.0, 0.0, 0.0, 0.0],
                Some(Rotation::Quaternion(qq)) => *qq,
                Some(Rotation::Matrix(_)) => unreachable!("quaternions only here"),
            };
            let r = [
                [
                    w * w + x * x - y * y - z * z,
                    2.0 * (x * y - w * z),
                    2.0 * (x * z + w * y),
                ],
                [
                    2.0 * (x * y + w * z),
                    w * w - x * x + y * y - z * z,
                    2.0 * (y * z - w * x),
                ],
                [
                    2.0 * (x * z - w * y),
                    2.0 * (y * z + w * x),
                    w * w - x * x - y * y + z * z,
                ],
            ];
            let dims: Vec<f64> = size.clone();
            let m = match p.amount {
                Amount::Mass(m) => m,
                Amount::Density(d) => d * dims.iter().product::<f64>(),
            };
            let local: [f64; 3] = match p.shape {
                Shape::Box => dims.clone().try_into().unwrap(),
                Shape::Plate => [dims[0], dims[1], 0.0],
                Shape::Rod => [0.0, 0.0, dims[0]],
                Shape::Point => [0.0; 3],
                _ => unreachable!("boxes, plates, rods and points only here"),
            };
            let s = local.map(|a| m * a * a / 12.0);
            let c = center;
            mass += m;
            let r2 = c.iter().map(|v| v * v).sum::<f64>();
            for a in 0..3 {
                first[a] += m * c[a];
                for b in 0..3 {
                    let cab: f64 = (0..3).map(|k| r[a][k] * s[k] * r[b][k]).sum();
                    let tr: f64 = s.iter().sum();
                    let delta = if a == b { 1.0 } else { 0.0 };
                    i_origin[a][b] += tr * delta - cab + m * (r2 * delta - c[a] * c[b]);
                }
            }
        }
        let com = first.map(|v| v / mass);
        let d2 = com.iter().map(|v| v * v).sum::<f64>();
        let i_com: [[f64; 3]; 3] = std::array::from_fn(|a| {
            std::array::from_fn(|b| {
                let delta = if a == b { 1.0 } else { 0.0 };
                i_origin[a][b] - mass * (d2 * delta - com[a] * com[b])
            })
        });
        assert!(rel(mass, &e.mass) < 1e-15);
        assert!(rel_vec(&com, &e.com) < 1e-14);
        let err = rel_frobenius(&i_com, &e.inertia);
        assert!(err < 1e-13, "naive vs exact: {err:e}");
        // And the comparison is not vacuous: a 1e-6 change is seen.
        let mut off = i_com;
        off[2][2] *= 1.0 + 1e-6;
        assert!(rel_frobenius(&off, &e.inertia) > 1e-7);
    }

    #[test]
    fn the_part_file_writer_round_trips_every_number() {
        for x in [
            1.0,
            0.1,
            1e-9,
            1.5e16,
            -2.5e-300,
            123456.789,
            1e22,
            5e-324,
            f64::MAX,
        ] {
            let v: toml::Value = toml::from_str(&format!("x = {}", number(x))).unwrap();
            assert_eq!(
                v["x"].as_float().map(f64::to_bits),
                Some(x.to_bits()),
                "{x:?}"
            );
        }
        let s = Scene {
            length: Length::Um,
            mass: Mass::Mg,
            parts: vec![
                Part::cuboid(
                    [1e-9, 2.0, 3.0],
                    [0.1, 0.2, 0.3],
                    Some([0.5, 0.5, 0.5, 0.5]),
                    Amount::Density(7.85e-9),
                ),
                Part::plate_edges(
                    [0.0; 3],
                    [[1.0, 0.0, 0.0], [0.0, 1e20, 0.0]],
                    Amount::Mass(1.0),
                ),
                Part::rod_from_to([0.0; 3], [1.0, 2.0, 3.0], Amount::Density(4.0)),
                Part::rod(2.0, [1.0; 3], None, Amount::Mass(1.0)),
                Part::point(1.0 / 3.0, [1.0; 3]),
            ],
            about: Some([1.0, 2.0, 3.0]),
        };
        let text = to_toml(&s);
        let v: toml::Value = toml::from_str(&text).unwrap();
        let part = &v["part"][0];
        assert_eq!(part["size"][0].as_float(), Some(1e-9));
        assert_eq!(part["density"].as_float(), Some(7.85e-9));
        assert_eq!(v["part"][1]["edges"][1][1].as_float(), Some(1e20));
        assert_eq!(v["part"][4]["mass"].as_float(), Some(1.0 / 3.0));
        assert_eq!(v["units"]["length"].as_str(), Some("um"));
    }

    #[test]
    fn square_roots_are_accurate_to_two_hundred_bits() {
        let x = frac(2, 3);
        let r = sqrt(&x);
        let err = (&r * &r - &x).abs() / &x;
        assert!(err < Q::new(BigInt::one(), BigInt::one() << 198usize));
        assert_eq!(sqrt(&int(49)), int(7));
    }

    #[test]
    fn rounded_composition_agrees_with_the_exact_one() {
        // Quaternion-turned boxes far from the origin, and a plate by edges.
        let q = |a: f64, b: f64, c: f64, d: f64| {
            let n = (a * a + b * b + c * c + d * d).sqrt();
            Some([a / n, b / n, c / n, d / n])
        };
        let scene = Scene::si(vec![
            Part::cuboid(
                [0.3, 0.7, 1.1],
                [1e6, 2.5, -3.0],
                q(0.1, 0.7, -0.2, 0.3),
                Amount::Mass(2.5),
            ),
            Part::cuboid(
                [0.2, 0.2, 0.9],
                [1e6 + 1.0, 0.5, 1.0],
                q(0.9, 0.1, 0.2, -0.4),
                Amount::Density(7850.0),
            ),
            Part::plate_edges(
                [1e6, 0.0, 0.0],
                [[0.0, 0.5, 0.0], [0.0, 0.0, 0.25]],
                Amount::Mass(0.75),
            ),
        ]);
        let exact = compose(&scene);
        let rounded = compose_rounded(&scene, 200);
        // N·2⁻²⁰⁰ absolute in each entry; the entries are ~1e12 here.
        let d = rel_frobenius_exact(&rounded.inertia, &exact.inertia);
        assert!(d < 1e-45, "{d:e}");
        assert_eq!(rounded.mass, exact.mass);
        for k in 0..3 {
            assert!(f(&(&rounded.com[k] - &exact.com[k]).abs()) < 1e-45);
        }
    }

    // -----------------------------------------------------------------------
    // Cylinders, disks, spheres, triangles and given inertias

    fn one(part: Part) -> ExactPart {
        exact_part(&part, Length::M, Mass::Kg)
    }

    /// ∫xxᵀ dm / m of a part, about its centroid.
    fn per_mass(p: &ExactPart) -> M3 {
        mscale(&p.second_moment, &(Q::one() / &p.mass))
    }

    fn msub(a: &M3, b: &M3) -> M3 {
        std::array::from_fn(|i| sub(&a[i], &b[i]))
    }

    /// arctan(1/x) = Σ (−1)ᵏ / ((2k + 1) x²ᵏ⁺¹), with the alternating
    /// series' error below its first omitted term.
    fn arctan_inv(x: i64, terms: u32) -> Q {
        (0..terms)
            .map(|k| {
                let t = Q::new(
                    BigInt::one(),
                    BigInt::from(2 * k + 1) * BigInt::from(x).pow(2 * k + 1),
                );
                if k % 2 == 0 { t } else { -t }
            })
            .sum()
    }

    #[test]
    fn pi_agrees_with_machins_formula_to_a_hundred_digits_and_rounds_to_f64_pi() {
        // π = 16 arctan(1/5) − 4 arctan(1/239); 80 and 50 terms leave
        // errors below 5⁻¹⁶⁰ and 239⁻¹⁰⁰, far below 10⁻¹⁰⁰.
        let machin = int(16) * arctan_inv(5, 80) - int(4) * arctan_inv(239, 50);
        let tiny = Q::new(BigInt::one(), BigInt::from(10).pow(100));
        assert!((pi() - machin).abs() < tiny);
        assert_eq!(f(&pi()), std::f64::consts::PI);
        // And the test can fail: the 100th digit matters.
        assert!(
            (pi() + &tiny * int(2) - int(16) * arctan_inv(5, 80) + int(4) * arctan_inv(239, 50))
                .abs()
                > tiny
        );
    }

    #[test]
    fn cylinders_disks_and_spheres_have_their_textbook_moments() {
        let (m, r, l) = (q(3.0), q(0.5), q(2.0));
        let moments = |p: Part| inertia_of(&one(p).second_moment);
        // Solid cylinder: I_zz = m R²/2, I_xx = I_yy = m (3R² + L²)/12.
        let i = moments(Part::cylinder(
            0.5,
            None,
            2.0,
            [1.0; 3],
            None,
            Amount::Mass(3.0),
        ));
        let across = &m * (int(3) * &r * &r + &l * &l) / int(12);
        let axial = &m * &r * &r / int(2);
        assert_eq!(i, diag_of([across.clone(), across, axial.clone()]));
        // Thin tube: all the mass at R from the axis, I_zz = m R².
        let i = moments(Part::cylinder(
            0.5,
            Some(0.5),
            2.0,
            [0.0; 3],
            None,
            Amount::Mass(3.0),
        ));
        assert_eq!(i[2][2], &m * &r * &r);
        // Disk: I_zz = m R²/2, I_xx = m R²/4; a ring: m R² and m R²/2.
        let i = moments(Part::disk(0.5, None, [0.0; 3], None, Amount::Mass(3.0)));
        assert_eq!(
            i,
            diag_of([&axial / int(2), &axial / int(2), axial.clone()])
        );
        let i = moments(Part::disk(
            0.5,
            Some(0.5),
            [0.0; 3],
            None,
            Amount::Mass(3.0),
        ));
        assert_eq!(i, diag_of([axial.clone(), axial.clone(), &axial * int(2)]));
        // Sphere: ⅖ m R² solid, ⅔ m R² a thin shell, on every axis.
        let solid = &m * &r * &r * frac(2, 5);
        let i = moments(Part::sphere(0.5, None, [0.0; 3], None, Amount::Mass(3.0)));
        assert_eq!(i, diag_of(std::array::from_fn(|_| solid.clone())));
        let shell = &m * &r * &r * frac(2, 3);
        let i = moments(Part::sphere(
            0.5,
            Some(0.5),
            [0.0; 3],
            None,
            Amount::Mass(3.0),
        ));
        assert_eq!(i, diag_of(std::array::from_fn(|_| shell.clone())));
        // Masses from densities: ρ π R² L, σ π R², ρ ⁴⁄₃ π R³.
        let rho = q(7.5);
        let c = one(Part::cylinder(
            0.5,
            None,
            2.0,
            [0.0; 3],
            None,
            Amount::Density(7.5),
        ));
        assert_eq!(c.mass, &rho * pi() * &r * &r * &l);
        let d = one(Part::disk(0.5, None, [0.0; 3], None, Amount::Density(7.5)));
        assert_eq!(d.mass, &rho * pi() * &r * &r);
        let b = one(Part::sphere(
            0.5,
            None,
            [0.0; 3],
            None,
            Amount::Density(7.5),
        ));
        assert_eq!(b.mass, &rho * pi() * pow(&r, 3) * frac(4, 3));
    }

    #[test]
    fn hollow_shapes_are_the_solid_less_the_bore_at_equal_density() {
        let h = 0.5f64.sqrt();
        let turn = Some(Rotation::Quaternion([0.3, -0.7, 0.2, 0.9]));
        let rot = Some(Rotation::Quaternion([h, 0.0, h, 0.0]));
        let cases: [(Part, Part, Part); 3] = [
            (
                Part::cylinder(
                    1.5,
                    Some(0.625),
                    3.0,
                    [1.0, 2.0, 3.0],
                    turn,
                    Amount::Density(2.0),
                ),
                Part::cylinder(1.5, None, 3.0, [1.0, 2.0, 3.0], turn, Amount::Density(2.0)),
                Part::cylinder(
                    0.625,
                    None,
                    3.0,
                    [1.0, 2.0, 3.0],
                    turn,
                    Amount::Density(2.0),
                ),
            ),
            (
                Part::disk(1.5, Some(0.625), [0.0; 3], rot, Amount::Density(0.3)),
                Part::disk(1.5, None, [0.0; 3], rot, Amount::Density(0.3)),
                Part::disk(0.625, None, [0.0; 3], rot, Amount::Density(0.3)),
            ),
            (
                Part::sphere(1.5, Some(0.625), [0.0; 3], None, Amount::Density(5.0)),
                Part::sphere(1.5, None, [0.0; 3], None, Amount::Density(5.0)),
                Part::sphere(0.625, None, [0.0; 3], None, Amount::Density(5.0)),
            ),
        ];
        for (hollow, outer, inner) in cases {
            let (h, o, i) = (one(hollow), one(outer), one(inner));
            assert_eq!(h.mass, &o.mass - &i.mass);
            assert_eq!(h.second_moment, msub(&o.second_moment, &i.second_moment));
        }
        // A cylinder is its two halves end to end (the L²/12 term).
        let whole = compose(&Scene::si(vec![Part::cylinder(
            0.5,
            Some(0.25),
            2.0,
            [0.0, 0.0, 1.0],
            None,
            Amount::Density(4.0),
        )]));
        let halves = compose(&Scene::si(vec![
            Part::cylinder(
                0.5,
                Some(0.25),
                1.0,
                [0.0, 0.0, 0.5],
                None,
                Amount::Density(4.0),
            ),
            Part::cylinder(
                0.5,
                Some(0.25),
                1.0,
                [0.0, 0.0, 1.5],
                None,
                Amount::Density(4.0),
            ),
        ]));
        assert_eq!((whole.mass, whole.inertia), (halves.mass, halves.inertia));
    }

    #[test]
    fn a_disk_is_a_cylinder_of_length_zero() {
        let rot = Some(Rotation::Quaternion([0.9, 0.1, -0.3, 0.2]));
        for inner in [None, Some(0.25), Some(1.25)] {
            let d = one(Part::disk(1.25, inner, [1.0; 3], rot, Amount::Mass(2.0)));
            let c = one(Part::cylinder(
                1.25,
                inner,
                0.0,
                [1.0; 3],
                rot,
                Amount::Mass(2.0),
            ));
            assert_eq!(d.second_moment, c.second_moment);
        }
    }

    #[test]
    fn thin_walls_tend_to_the_thin_shell() {
        for k in [10, 20, 40] {
            let h = 0.5f64.powi(k);
            let r = 1.0 - h;
            for (thin, thick) in [
                (
                    Part::sphere(1.0, Some(1.0), [0.0; 3], None, Amount::Mass(1.0)),
                    Part::sphere(1.0, Some(r), [0.0; 3], None, Amount::Mass(1.0)),
                ),
                (
                    Part::cylinder(1.0, Some(1.0), 0.5, [0.0; 3], None, Amount::Mass(1.0)),
                    Part::cylinder(1.0, Some(r), 0.5, [0.0; 3], None, Amount::Mass(1.0)),
                ),
            ] {
                let (a, b) = (one(thin).second_moment, one(thick).second_moment);
                // Moving mass inwards by at most h only lowers ∫x² dm, by a
                // relative amount below 2h.
                let d = f(&((&a[0][0] - &b[0][0]) / &a[0][0]));
                assert!(d > 0.0 && d < 2.0 * h, "2^-{k}: {d:e}");
            }
        }
    }

    #[test]
    fn a_sphere_is_a_stack_of_thin_cylinders() {
        // Midpoint quadrature of the unit ball in 64 slabs of height 1/32,
        // each a cylinder of radius √(1 − z²) (the cylinder's own closed
        // form, not the sphere's): ∫x² dm / m and ∫z² dm / m tend to 1/5
        // with errors of order 1/N² (0.5/N² and 3.7/N² here).
        let n = 64;
        let hgt = 2.0 / n as f64;
        let slabs = (0..n)
            .map(|k| {
                let z = -1.0 + (k as f64 + 0.5) * hgt;
                Part::cylinder(
                    (1.0 - z * z).sqrt(),
                    None,
                    hgt,
                    [0.0, 0.0, z],
                    None,
                    Amount::Density(1.0),
                )
            })
            .collect();
        let stack = compose(&Scene::si(slabs));
        let ball = one(Part::sphere(1.0, None, [0.0; 3], None, Amount::Mass(1.0)));
        let c = per_mass(&ExactPart {
            mass: stack.mass.clone(),
            center: stack.com.clone(),
            second_moment: stack.second_moment.clone(),
        });
        assert_eq!(
            per_mass(&ball),
            diag_of(std::array::from_fn(|_| frac(1, 5)))
        );
        let bound = 4.0 / (n * n) as f64;
        for k in [0, 2] {
            let err = f(&((&c[k][k] - frac(1, 5)) / frac(1, 5))).abs();
            assert!(err < bound, "axis {k}: {err:e}");
        }
    }

    /// The triangle (a, b, c) split at its edge midpoints into four
    /// half-scale triangles (three at the corners, one turned in the middle).
    fn four_halves(v: [[f64; 3]; 3]) -> [[[f64; 3]; 3]; 4] {
        let mid =
            |i: usize, j: usize| -> [f64; 3] { std::array::from_fn(|k| (v[i][k] + v[j][k]) / 2.0) };
        let (ab, bc, ca) = (mid(0, 1), mid(1, 2), mid(2, 0));
        [[v[0], ab, ca], [ab, v[1], bc], [ca, bc, v[2]], [ab, bc, ca]]
    }

    #[test]
    fn a_triangle_is_its_four_half_scale_triangles() {
        // NOTE: this pins the constant: if C = k m Σ dᵢdᵢᵀ, the four halves
        // give 4 · k (m/4) Σ (dᵢ/2)(dᵢ/2)ᵀ plus the parallel-axis terms of
        // the corner triangles' centroids at g + dᵢ/2, (m/4) Σ dᵢdᵢᵀ/4:
        // k = k/4 + 1/16 holds only for k = 1/12.
        let v = [[0.25, -1.0, 2.0], [3.0, 0.5, 1.0], [-1.0, 2.0, -0.5]];
        let whole = compose(&Scene::si(vec![Part::triangle(v, Amount::Mass(4.0))]));
        let split = compose(&Scene::si(
            four_halves(v)
                .map(|t| Part::triangle(t, Amount::Mass(1.0)))
                .to_vec(),
        ));
        assert_eq!(whole.com, split.com);
        assert_eq!(whole.inertia, split.inertia);
        // By density: the areas are square roots (to 2⁻²⁰⁰).
        let whole = compose(&Scene::si(vec![Part::triangle(v, Amount::Density(0.75))]));
        let split = compose(&Scene::si(
            four_halves(v)
                .map(|t| Part::triangle(t, Amount::Density(0.75)))
                .to_vec(),
        ));
        assert!(rel_q(&split.mass, &whole.mass) < 1e-55);
        assert!(rel_frobenius_exact(&split.inertia, &whole.inertia) < 1e-55);
    }

    #[test]
    fn an_ellipsoid_has_its_textbook_moments_and_volume() {
        // I_xx = m (b² + c²)/5, and so round; V = ⁴⁄₃π abc.
        let (m, a, b, c) = (q(3.0), q(0.5), q(2.0), q(0.25));
        let i = inertia_of(
            &one(Part::ellipsoid(
                [0.5, 2.0, 0.25],
                [1.0; 3],
                None,
                Amount::Mass(3.0),
            ))
            .second_moment,
        );
        let fifth = |x: &Q, y: &Q| &m * (x * x + y * y) / int(5);
        assert_eq!(i, diag_of([fifth(&b, &c), fifth(&a, &c), fifth(&a, &b)]));
        let by_density = one(Part::ellipsoid(
            [0.5, 2.0, 0.25],
            [0.0; 3],
            None,
            Amount::Density(3.0),
        ));
        assert_eq!(by_density.mass, int(4) * pi() * &a * &b * &c);
    }

    #[test]
    fn a_right_triangle_has_the_textbook_centroidal_moments() {
        // Legs b along x and h along y: per unit area, ∫y² dA = b h³/36 and
        // ∫xy dA = −b² h²/72 about the centroid (b/3, h/3), so per unit mass
        // h²/18 and −b h/36; the tensor's I_xy = −∫xy dm = m b h/36.
        let (b, h) = (3.0, 2.0);
        let t = compose(&Scene::si(vec![Part::triangle(
            [[0.0; 3], [b, 0.0, 0.0], [0.0, h, 0.0]],
            Amount::Density(2.0),
        )]));
        let m = int(6); // 2 · (3 · 2)/2, exactly: √36 = 6
        assert_eq!(t.mass, m);
        assert_eq!(t.com, [frac(1, 1), frac(2, 3), int(0)]);
        let (b, h) = (q(b), q(h));
        assert_eq!(t.second_moment[1][1], &m * &h * &h / int(18));
        assert_eq!(t.second_moment[0][0], &m * &b * &b / int(18));
        assert_eq!(t.inertia[0][1], &m * &b * &h / int(36));
        assert_eq!(t.second_moment[2][2], int(0));
    }

    #[test]
    fn a_polygon_of_many_triangles_tends_to_the_disk() {
        // A regular n-gon inscribed in the unit circle, as n triangles of
        // equal mass from its centre. Its polar moment per unit area is
        // (1 + 2cos²(π/n))/6 (each isosceles slice: ∫|p|² dA =
        // (A/6)(|a|² + a·b + |b|²)), so ∫x² dm / m = (1 + 2cos²(π/n))/12,
        // which tends to the disk's 1/4 from below, short by (2/3) sin²(π/n).
        let n = 256;
        let vertex = |k: usize| {
            let t = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            [t.cos(), t.sin(), 0.0]
        };
        let slices = (0..n)
            .map(|k| Part::triangle([[0.0; 3], vertex(k), vertex(k + 1)], Amount::Mass(1.0)))
            .collect();
        let poly = compose(&Scene::si(slices));
        let xx = f(&(&poly.second_moment[0][0] / &poly.mass));
        let c = (std::f64::consts::PI / n as f64).cos();
        let regular = (1.0 + 2.0 * c * c) / 12.0;
        // Vertices and slice masses rounded in f64: a few ε.
        assert!((xx - regular).abs() < 1e-14, "{xx} vs {regular}");
        let disk = per_mass(&one(Part::disk(
            1.0,
            None,
            [0.0; 3],
            None,
            Amount::Mass(1.0),
        )));
        let gap = (f(&disk[0][0]) - xx) / f(&disk[0][0]);
        let step = std::f64::consts::PI / n as f64;
        assert!(gap > 0.0 && gap < step * step, "{gap:e}");
    }

    /// Integer edges, exactly perpendicular, all of length 3.
    const OBLIQUE: [[f64; 3]; 3] = [[2.0, 1.0, 2.0], [1.0, 2.0, -2.0], [2.0, -2.0, -1.0]];

    #[test]
    fn a_given_inertia_is_the_body_it_describes() {
        // A box of mass 12 by integer edges of lengths 3, 6 and 9:
        // C = Σ eₖeₖᵀ and its tensor I = tr(C)E − C are integer matrices
        // with products, exact in f64.
        let edges: [[f64; 3]; 3] = std::array::from_fn(|k| OBLIQUE[k].map(|x| x * (k + 1) as f64));
        let boxed = one(Part::box_edges([0.0; 3], edges, Amount::Mass(12.0)));
        let i = fm(&inertia_of(&boxed.second_moment));
        assert!(i[0][1] != 0.0 && i[0][2] != 0.0 && i[1][2] != 0.0);
        let center = fv(&boxed.center);
        let given = one(Part::given(12.0, i, Products::Tensor, center, None));
        assert_eq!(given.second_moment, boxed.second_moment);
        assert_eq!(
            (given.mass, given.center),
            (boxed.mass.clone(), boxed.center.clone())
        );
        // The same products written as CAD does, +∫xy dm.
        let mut cad = i;
        for (a, b) in [(0, 1), (1, 0), (0, 2), (2, 0), (1, 2), (2, 1)] {
            cad[a][b] = -cad[a][b];
        }
        let given = one(Part::given(12.0, cad, Products::Positive, center, None));
        assert_eq!(given.second_moment, boxed.second_moment);
        // Turned: a box's local tensor and the box's own rotation.
        let qq = [0.3, -0.7, 0.2, 0.9];
        let turned_box = one(Part::cuboid(
            [1.0, 2.0, 3.0],
            [0.5; 3],
            Some(qq),
            Amount::Mass(12.0),
        ));
        let local = [[13.0, 0.0, 0.0], [0.0, 10.0, 0.0], [0.0, 0.0, 5.0]];
        let given = one(Part::given(
            12.0,
            local,
            Products::Tensor,
            [0.5; 3],
            Some(Rotation::Quaternion(qq)),
        ));
        assert_eq!(given.second_moment, turned_box.second_moment);
        // And a wrong convention is seen.
        let wrong = one(Part::given(12.0, cad, Products::Tensor, center, None));
        assert!(rel_frobenius_exact(&wrong.second_moment, &boxed.second_moment) > 0.1);
    }

    /// One part of every shape and placement that a quarter turn maps
    /// exactly: unrotated or turned by a signed permutation.
    fn turnable_every_shape() -> Scene {
        let swap = Some(Rotation::Matrix([
            [0.0, 0.0, 1.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
        ]));
        Scene::si(vec![
            Part::cuboid([0.5, 1.0, 1.5], [1.0, 0.0, 0.5], None, Amount::Density(3.0)),
            Part::plate([0.5, 2.0], [0.0, 1.0, 0.25], None, Amount::Mass(1.0)).with_rotation(swap),
            Part::rod(2.5, [-1.0, 0.5, 0.0], None, Amount::Density(0.5)),
            Part::point(0.75, [0.5, -1.5, 2.0]),
            Part::cylinder(
                0.5,
                Some(0.25),
                2.0,
                [2.0, 1.0, -1.0],
                None,
                Amount::Density(2.0),
            ),
            Part::cylinder(0.75, None, 0.5, [0.0, 0.0, 0.0], swap, Amount::Mass(3.0)),
            Part::disk(1.0, Some(0.5), [-2.0, 0.0, 1.0], swap, Amount::Density(1.5)),
            Part::disk(0.25, Some(0.25), [0.5, 0.5, 0.5], None, Amount::Mass(0.5)),
            Part::sphere(
                0.5,
                Some(0.375),
                [1.0, -1.0, 0.0],
                None,
                Amount::Density(8.0),
            ),
            Part::sphere(0.25, Some(0.25), [0.0, 2.0, 0.0], swap, Amount::Mass(0.25)),
            Part::triangle(
                [[0.0, 0.0, 1.0], [1.0, 0.5, 0.0], [0.25, 2.0, 0.5]],
                Amount::Density(4.0),
            ),
            Part::given(
                2.0,
                [[3.0, 0.5, -0.25], [0.5, 2.5, 0.75], [-0.25, 0.75, 4.0]],
                Products::Positive,
                [0.0, -1.0, -1.0],
                swap,
            ),
        ])
    }

    #[test]
    fn a_quarter_turn_of_every_shape_permutes_the_exact_tensor() {
        let scene = turnable_every_shape();
        let e = compose(&scene);
        for axis in 0..3 {
            let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
            // P: x_i ← −x_j, x_j ← x_i.
            let mut p = zero_m();
            p[axis][axis] = int(1);
            p[i][j] = int(-1);
            p[j][i] = int(1);
            let t = compose(&scene.quarter_turn(axis));
            assert_eq!(t.inertia, turned(&p, &e.inertia), "axis {axis}");
            assert_eq!(t.com, mvec(&p, &e.com));
            assert_eq!(t.mass, e.mass);
        }
    }

    #[test]
    fn only_exact_rotation_matrices_are_taken() {
        let r = std::panic::catch_unwind(|| {
            rotation_matrix(Some(&Rotation::Matrix([
                [0.6, 0.8, 0.0],
                [-0.8, 0.6, 0.0],
                [0.0, 0.0, 1.0],
            ])))
        });
        assert!(r.is_err(), "0.6 and 0.8 are not exact in binary");
        let m = rotation_matrix(Some(&Rotation::Matrix([
            [0.0, -1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
        ])));
        assert_eq!(
            mvec(&m, &[int(1), int(0), int(0)]),
            [int(0), int(1), int(0)]
        );
    }

    #[test]
    fn the_part_file_writer_writes_every_shape() {
        let scene = turnable_every_shape();
        let v: toml::Value = toml::from_str(&to_toml(&scene)).unwrap();
        let part = |k: usize| &v["part"][k];
        assert_eq!(part(4)["shape"].as_str(), Some("cylinder"));
        assert_eq!(part(4)["radius"].as_float(), Some(0.5));
        assert_eq!(part(4)["inner_radius"].as_float(), Some(0.25));
        assert_eq!(part(4)["length"].as_float(), Some(2.0));
        assert_eq!(part(4)["density"].as_float(), Some(2.0));
        assert!(part(5).get("inner_radius").is_none());
        assert_eq!(part(5)["rotation"]["matrix"][1][0].as_float(), Some(-1.0));
        assert_eq!(part(6)["areal_density"].as_float(), Some(1.5));
        assert_eq!(part(8)["shape"].as_str(), Some("sphere"));
        assert_eq!(part(10)["vertices"][2][1].as_float(), Some(2.0));
        assert_eq!(part(10)["areal_density"].as_float(), Some(4.0));
        assert_eq!(part(11)["shape"].as_str(), Some("inertia"));
        assert_eq!(part(11)["inertia"][1][2].as_float(), Some(0.75));
        assert_eq!(part(11)["products"].as_str(), Some("positive"));
        assert_eq!(part(11)["mass"].as_float(), Some(2.0));
    }

    #[test]
    fn every_shape_converts_to_other_units_with_exact_factors() {
        // One rounding per number: the same body to a few ε.
        let si = turnable_every_shape();
        let e = compose(&si);
        for (length, mass) in [
            (Length::In, Mass::Lb),
            (Length::Mm, Mass::G),
            (Length::Km, Mass::T),
        ] {
            let c = compose(&si.in_units(length, mass));
            assert!(rel_q(&c.mass, &e.mass) < 1e-15);
            assert!(rel_frobenius_exact(&c.inertia, &e.inertia) < 1e-15);
        }
    }
}
