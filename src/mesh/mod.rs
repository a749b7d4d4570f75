//! Triangle meshes (`shape = "mesh"`): a mesh file read (`read`: binary
//! and ASCII STL, Wavefront OBJ), its corners welded into a surface (and
//! with a part's `weld`, corners closer than a distance: `near`) and
//! checked (`check`, `classes`: closed, consistently oriented, outward;
//! zero-area triangles left out; T-junctions and pieces touching along an
//! edge answered with a warning), and its mass properties integrated exactly over the
//! polyhedron (`MeshBody`), once, when the model is read.
//!
//! The integrals, a solid's by the divergence theorem as a sum of signed
//! tetrahedra (the mesh's triangles joined to a reference point p; Tonon
//! 2004, the form libigl and parry use), a shell's as a sum over its
//! triangles:
//!
//! - tetrahedron (p, a, b, c), offsets a, b, c from p and w = a · (b × c)
//!   (six times its signed volume): ∫1 = w/6, ∫x = w/24 · s,
//!   ∫xxᵀ = w/120 · (aaᵀ + bbᵀ + ccᵀ + ssᵀ), s = a + b + c;
//! - triangle (a, b, c) of twice its area w = |(b − a) × (c − a)|:
//!   ∫1 = w/2, ∫x = w/6 · s, ∫xxᵀ = w/24 · (aaᵀ + bbᵀ + ccᵀ + ssᵀ).
//!
//! NOTE: accumulated about p, the centre of the mesh's bounding box, never
//! about the file's origin: a mesh 10⁶ of its sizes from its origin has
//! second moments about the origin 10¹² times its own, which cancel when
//! moved to its centroid (numpy-stl returns negative moments there). Each
//! offset from p is exact in double-double (a difference of two f64), and
//! every term and sum is double-double: the stored values are the
//! integrals of the file's numbers to ~10⁻³⁰ of their magnitudes, whatever
//! precision composes them, with a bound (`Bound`) from the same terms'
//! magnitudes.

pub mod bvh;
pub mod check;
mod classes;
pub mod exact;
mod lanes;
pub mod near;
pub mod read;
pub mod shells;
pub mod weld;

pub use read::FileType;

use std::cell::Cell;

thread_local! {
    /// Threads forced for this thread's meshes (`with_threads`).
    static FORCED: Cell<Option<usize>> = const { Cell::new(None) };
}

/// Runs `f` with every stage of the meshes this thread loads on
/// `threads` threads, however few their items: for the tests, which hold
/// the answers on 1, 2 and 3 threads equal bit for bit on small meshes.
/// The answers never depend on it (the work is cut into pieces fixed by
/// the mesh alone, and merged in a fixed order), only the speed.
#[doc(hidden)]
pub fn with_threads<T>(threads: usize, f: impl FnOnce() -> T) -> T {
    let before = FORCED.with(|c| c.replace(Some(threads.max(1))));
    let out = f();
    FORCED.with(|c| c.set(before));
    out
}

/// The threads a stage of `items` items runs on: one per core, each with
/// at least `grain` items (few items are not worth a thread), or as
/// `with_threads` forces (at most one a item).
pub(crate) fn threads_for(items: usize, grain: usize) -> usize {
    match FORCED.with(Cell::get) {
        Some(n) => n.clamp(1, items.max(1)),
        None => std::thread::available_parallelism()
            .map_or(1, |t| t.get())
            .clamp(1, items.div_ceil(grain.max(1)).max(1)),
    }
}

/// `f` of 0, 1, … `n` − 1, on every core (a run of them each, written in
/// place over `zero`).
pub(crate) fn filled<T: Copy + Send + Sync>(
    n: usize,
    zero: T,
    f: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    let threads = threads_for(n, 1 << 16);
    if threads == 1 {
        return (0..n).map(f).collect();
    }
    let piece = n.div_ceil(threads).max(1);
    let mut out = vec![zero; n];
    std::thread::scope(|scope| {
        for (c, out) in out.chunks_mut(piece).enumerate() {
            let f = &f;
            scope.spawn(move || {
                for (k, x) in out.iter_mut().enumerate() {
                    *x = f(c * piece + k);
                }
            });
        }
    });
    out
}

use crate::numeric::{DD, M3, Real};

/// The most triangles a mesh may have: 72 bytes of corners each while it
/// is read, then 12 of indices and a vertex's 24.
pub const MAX_TRIANGLES: usize = 5_000_000;

/// Where in a mesh file something is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum At {
    /// A line of a text file, from 1.
    Line(usize),
    /// A byte offset in a binary file.
    Byte(u64),
    /// The file as a whole.
    Whole,
}

impl std::fmt::Display for At {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            At::Line(n) => write!(f, "line {n}"),
            At::Byte(b) => write!(f, "byte {b}"),
            At::Whole => Ok(()),
        }
    }
}

/// A mesh file that cannot be read or is not a valid surface.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MeshError {
    pub at: At,
    pub message: String,
}

impl MeshError {
    /// The message with where it is in front: `line 12: …`.
    pub fn located(self) -> MeshError {
        match self.at {
            At::Whole => self,
            at => MeshError {
                message: format!("{at}: {}", self.message),
                at,
            },
        }
    }

    pub fn new(at: At, message: impl Into<String>) -> MeshError {
        MeshError {
            at,
            message: message.into(),
        }
    }
}

/// What a mesh is the surface of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mode {
    /// The solid it encloses (closed, oriented, outward): per volume.
    Solid,
    /// A thin sheet of the surface itself (open allowed): per area.
    Shell,
}

impl Mode {
    /// The power of length of the measure: 3 (volume) or 2 (area).
    pub fn power(self) -> i32 {
        match self {
            Mode::Solid => 3,
            Mode::Shell => 2,
        }
    }
}

/// A mesh's mass properties per unit density, in its file's coordinates
/// and units: computed once when the model is read, shared by every part
/// that uses the file (`part::Place::Mesh`).
#[derive(Debug, Clone, PartialEq)]
pub struct MeshBody {
    pub mode: Mode,
    pub triangles: usize,
    /// Volume (solid) or area (shell), positive.
    pub measure: DD,
    /// The centroid, in the file's coordinates.
    pub centroid: [DD; 3],
    /// ∫ρρᵀ over the volume or area about the centroid (file units⁵ or ⁴).
    pub second: M3<DD>,
    /// How far each stored value may lie from the exact integral of the
    /// file's numbers: absolute, in the file's units.
    pub bound: Bound,
    /// The box of its vertices, least then greatest coordinates, in the
    /// file's coordinates.
    pub extent: [[f64; 3]; 2],
    /// Its welded corners (the file's coordinates) and triangles (indices,
    /// outward by the right-hand rule): `render` draws its silhouette.
    /// Shared: a mesh's copies and the model's clones hold them once.
    pub points: std::sync::Arc<Vec<[f64; 3]>>,
    pub faces: std::sync::Arc<Vec<[u32; 3]>>,
}

/// Absolute error bounds of a `MeshBody`'s values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bound {
    pub measure: f64,
    /// Of each coordinate of the centroid.
    pub centroid: f64,
    /// Of each entry of the second moment.
    pub second: f64,
}

impl MeshBody {
    /// Read, weld, check and integrate a mesh file's bytes.
    pub fn load(format: FileType, bytes: &[u8], mode: Mode) -> Result<MeshBody, MeshError> {
        Ok(MeshBody::load_with(format, bytes, mode, None)?.0)
    }

    /// `load`, with corners closer than `weld` (in the file's units, > 0;
    /// a solid's) merged first (`near`), and the warnings of what the
    /// answer survives (`check`), one a class.
    pub fn load_with(
        format: FileType,
        bytes: &[u8],
        mode: Mode,
        weld: Option<f64>,
    ) -> Result<(MeshBody, Vec<String>), MeshError> {
        let t = read::corners(format, bytes, MAX_TRIANGLES).map_err(MeshError::located)?;
        let mut mesh = check::Mesh::weld_corners(t)?;
        let mut notes = Vec::new();
        let mut moved = [0.0; 10];
        if let Some(d) = weld {
            let (welded, w) = mesh.weld_within(d);
            mesh = welded;
            moved = w.moved;
            notes.push(format!(
                "`weld` merged {} corner{} into corners closer than {d} (the mesh file's units); the bounds count what that can change",
                w.merged,
                if w.merged == 1 { "" } else { "s" }
            ));
        }
        notes.extend(mesh.leave_out_degenerate()?);
        let p = mesh.reference();
        let sums = if mode == Mode::Solid {
            // NOTE: the integrals are summed on a thread of their own while
            // the surface is checked (closed, oriented, its shells), which
            // they do not depend on (the triangles are final once those of
            // zero area are left out): its threads fill the cores the
            // checks' one-thread steps leave idle (the edges' sort, the
            // closedness pass, the shells' union, the scaled corners, the
            // tree's top split). The same sums, chunk by chunk, as after
            // the checks; a refusal by the checks still comes first, its
            // sums thrown away.
            let mesh = &mesh;
            let (checked, sums) = std::thread::scope(|scope| {
                let handle = scope.spawn(move || mesh.sums_dd(mode, p));
                let mut handle = Some(handle);
                let mut join = || {
                    handle.take().map(|h| {
                        h.join()
                            .expect("invariant: summing a mesh's terms does not panic")
                    })
                };
                // The sums, joined when a single shell's winding asks them.
                let mut sums = None;
                let checked = (|| {
                    let edges = mesh.edges();
                    notes.extend(mesh.closed_and_oriented(&edges)?);
                    shells::check_with(mesh, edges, || {
                        shells::volume_sign(sums.insert(join().expect("asked once")))
                    })
                })();
                let sums = sums.or_else(join).expect("invariant: joined here or above");
                (checked, sums)
            });
            checked?;
            sums
        } else {
            mesh.sums_dd(mode, p)
        };
        let body = mesh.into_body(mode, p, sums, moved);
        if weld.is_some() && !(body.bound.measure <= body.measure.hi.abs() / 2.0) {
            return Err(MeshError::new(
                At::Whole,
                format!(
                    "`weld` could change the mesh's volume by up to {:e}, more than half of it ({:e}); give a smaller distance",
                    body.bound.measure, body.measure.hi
                ),
            ));
        }
        if mode == Mode::Solid && body.measure.hi <= 0.0 {
            return Err(if body.measure.hi < 0.0 {
                MeshError::new(
                    At::Whole,
                    "the mesh is inside out: its volume is negative, its faces point inward; flip the winding (every triangle's corners counter-clockwise seen from outside)",
                )
            } else {
                MeshError::new(At::Whole, "the mesh encloses no volume")
            });
        }
        // A closed, oriented surface that crosses itself (an inside-out
        // part inside or beside an outward one) has a signed "volume":
        // its second moment can be negative along an axis.
        if (0..3).any(|k| body.second[k][k].hi < 0.0) {
            return Err(MeshError::new(
                At::Whole,
                "the mesh's second moment is negative along an axis: the surface crosses itself or has a part wound inward",
            ));
        }
        if mode == Mode::Shell && body.measure.hi <= 0.0 {
            return Err(MeshError::new(At::Whole, "the mesh has no area"));
        }
        Ok((body, notes))
    }

    /// The data reflected through the plane normal to local axis `axis`
    /// through the file's origin (a mirror image): the centroid's
    /// coordinate and the second moment's products with that axis change
    /// sign; measure and diagonal stay.
    pub fn reflected(&self, axis: usize) -> MeshBody {
        let mut m = self.clone();
        m.centroid[axis] = -m.centroid[axis];
        let [lo, hi] = self.extent;
        m.extent[0][axis] = -hi[axis];
        m.extent[1][axis] = -lo[axis];
        // The image's corners, and its triangles wound the other way so
        // that they face out still.
        m.points = std::sync::Arc::new(
            self.points
                .iter()
                .map(|p| {
                    let mut q = *p;
                    q[axis] = -q[axis];
                    q
                })
                .collect(),
        );
        m.faces = std::sync::Arc::new(self.faces.iter().map(|f| [f[0], f[2], f[1]]).collect());
        for k in 0..3 {
            if k != axis {
                m.second[axis][k] = -m.second[axis][k];
                m.second[k][axis] = -m.second[k][axis];
            }
        }
        m
    }
}

/// The constant of the error bound: roundings of one term (the offsets,
/// the cross and dot products or the norm, the sums s and aaᵀ + … + ssᵀ,
/// the product with w), with slack: |δ| ≤ unit · (TERM + n) · Σ|terms|,
/// n the recursive sum's length.
pub const TERM: f64 = 24.0;

/// The sums of a mesh's terms, and of their magnitudes.
#[derive(Debug, Clone, Copy)]
pub struct Sums<T> {
    /// w, w s, w (aaᵀ + bbᵀ + ccᵀ + ssᵀ) (upper triangle, row by row).
    pub value: [T; 10],
    pub magnitude: [f64; 10],
    pub n: usize,
    /// How far each sum may be from the file's own corners' by a `weld`
    /// (`near`), absolute: 0 without one.
    pub moved: [f64; 10],
}

/// Index of (i, j), i ≤ j, in the six entries of an upper triangle.
pub(crate) const PAIRS: [(usize, usize); 6] = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)];

impl<T: Real> Sums<T> {
    pub fn new() -> Sums<T> {
        Sums {
            value: [T::of(0.0); 10],
            magnitude: [0.0; 10],
            n: 0,
            moved: [0.0; 10],
        }
    }

    /// One triangle's terms, its corners' offsets from p given exactly in
    /// double-double and rounded to T.
    #[inline]
    pub fn add(&mut self, mode: Mode, v: [[DD; 3]; 3]) {
        let [a, b, c]: [[T; 3]; 3] = v.map(|p| p.map(T::of_dd));
        let abs = |x: T| x.f64().abs();
        let (w, wmag) = match mode {
            Mode::Solid => volume_term([a, b, c]),
            Mode::Shell => {
                let d1: [T; 3] = std::array::from_fn(|i| b[i] - a[i]);
                let d2: [T; 3] = std::array::from_fn(|i| c[i] - a[i]);
                let x = cross(d1, d2);
                let w = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
                let (m1, m2) = (d1.map(abs), d2.map(abs));
                let mag = m1[1] * m2[2]
                    + m1[2] * m2[1]
                    + m1[2] * m2[0]
                    + m1[0] * m2[2]
                    + m1[0] * m2[1]
                    + m1[1] * m2[0];
                (w, mag)
            }
        };
        let s: [T; 3] = std::array::from_fn(|i| a[i] + b[i] + c[i]);
        let sm: [f64; 3] = std::array::from_fn(|i| abs(a[i]) + abs(b[i]) + abs(c[i]));
        self.value[0] = self.value[0] + w;
        self.magnitude[0] += wmag;
        for i in 0..3 {
            self.value[1 + i] = self.value[1 + i] + w * s[i];
            self.magnitude[1 + i] += wmag * sm[i];
        }
        for (k, &(i, j)) in PAIRS.iter().enumerate() {
            let q = a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j];
            let qm = abs(a[i]) * abs(a[j])
                + abs(b[i]) * abs(b[j])
                + abs(c[i]) * abs(c[j])
                + sm[i] * sm[j];
            self.value[4 + k] = self.value[4 + k] + w * q;
            self.magnitude[4 + k] += wmag * qm;
        }
        self.n += 1;
    }

    /// The volume's sum alone (`value[0]`, `magnitude[0]`, `n`), the
    /// other sums left as they are: the same bits in them as `add` gives.
    #[inline]
    pub fn add_volume(&mut self, v: [[DD; 3]; 3]) {
        let (w, wmag) = volume_term(v.map(|p| p.map(T::of_dd)));
        self.value[0] = self.value[0] + w;
        self.magnitude[0] += wmag;
        self.n += 1;
    }

    /// The error bound of each sum, absolute.
    pub fn error(&self) -> [f64; 10] {
        let unit = unit_of::<T>();
        std::array::from_fn(|k| {
            unit * (TERM + self.n as f64) * self.magnitude[k] * (1.0 + 1e-10) + self.moved[k]
        })
    }
}

impl<T: Real> Default for Sums<T> {
    fn default() -> Self {
        Sums::new()
    }
}

/// The unit in which `T`'s roundings are counted: f64's 2⁻⁵³, or
/// double-double's 7·2⁻¹⁰⁶ — `part::error::unit_of`'s (a test in `part`
/// holds them equal; this layer comes before `part`).
pub fn unit_of<T: Real>() -> f64 {
    let u = f64::EPSILON / 2.0;
    if T::EPS < 1e-20 { 7.0 * u * u } else { u }
}

/// A solid's term w = a · (b × c) and its magnitude's bound.
#[inline]
fn volume_term<T: Real>([a, b, c]: [[T; 3]; 3]) -> (T, f64) {
    let abs = |x: T| x.f64().abs();
    let x = cross(b, c);
    let w = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
    let bm = b.map(abs);
    let cm = c.map(abs);
    let xm = [
        bm[1] * cm[2] + bm[2] * cm[1],
        bm[2] * cm[0] + bm[0] * cm[2],
        bm[0] * cm[1] + bm[1] * cm[0],
    ];
    let am = a.map(abs);
    (w, am[0] * xm[0] + am[1] * xm[1] + am[2] * xm[2])
}

fn cross<T: Real>(b: [T; 3], c: [T; 3]) -> [T; 3] {
    [
        b[1] * c[2] - b[2] * c[1],
        b[2] * c[0] - b[0] * c[2],
        b[0] * c[1] - b[1] * c[0],
    ]
}

/// The measure, centroid offset from p and second moment about the
/// centroid from the sums, with their bounds (absolute): for the mode's
/// constants, measure = W/k₀, first moment S/k₁, second moment about p
/// Q/k₂ (solid 6, 24, 120; shell 2, 6, 24).
pub fn finish<T: Real>(mode: Mode, sums: &Sums<T>) -> (T, [T; 3], M3<T>, Bound) {
    let (k0, k1, k2) = match mode {
        Mode::Solid => (6.0, 24.0, 120.0),
        Mode::Shell => (2.0, 6.0, 24.0),
    };
    let unit = unit_of::<T>();
    let e = sums.error();
    let w = sums.value[0];
    let measure = w / T::of(k0);
    let wf = w.f64().abs();
    let e_measure = e[0] / k0 + 2.0 * unit * wf / k0;
    // g = (S/k₁)/(W/k₀) = S k₀/(k₁ W).
    let ratio = T::of(k0) / T::of(k1);
    let g: [T; 3] = std::array::from_fn(|i| sums.value[1 + i] * ratio / w);
    let gmax = g.iter().fold(0.0f64, |m, x| m.max(x.f64().abs()));
    let rel_w = e[0] / wf;
    let e_g = (1..4).fold(0.0f64, |m, i| m.max(e[i] * k0 / k1 / wf))
        + gmax * (rel_w * (1.0 + 2.0 * rel_w) + 4.0 * unit);
    let mut second = [[T::of(0.0); 3]; 3];
    let mut e_second = 0.0f64;
    let mf = measure.f64().abs();
    for (k, &(i, j)) in PAIRS.iter().enumerate() {
        let about_p = sums.value[4 + k] / T::of(k2);
        let shift = measure * g[i] * g[j];
        let v = about_p - shift;
        second[i][j] = v;
        second[j][i] = v;
        let (gi, gj) = (g[i].f64().abs(), g[j].f64().abs());
        let err = e[4 + k] / k2
            + 2.0 * unit * about_p.f64().abs()
            + e_measure * gi * gj
            + mf * (e_g * (gi + gj) + e_g * e_g)
            + 5.0 * unit * mf * gi * gj;
        e_second = e_second.max(err);
    }
    let bound = Bound {
        measure: e_measure,
        centroid: e_g,
        second: e_second,
    };
    (measure, g, second, bound)
}

#[cfg(test)]
mod tests;
