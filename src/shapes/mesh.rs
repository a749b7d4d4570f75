//! A triangle mesh read from a file (`shape = "mesh"`): its own file's
//! coordinates, placed by `origin` and `rotation` as an include is. Its
//! integrals come from the file (the `mesh` module, `part::Place::Mesh`), no
//! closed form here.

use super::common::{add, at, axes, comb, flip, mirror_axis, norm1, points, reset_turn};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::error::{self, Own};
use super::lift::Lift;
use super::outline::{Outline, Piece, V3};
use super::{MaterialRule, Mover, PER_VOLUME, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::mesh::MeshBody;
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use std::sync::Arc;

/// A triangle mesh's integrals (`mesh::MeshBody`, in its file's
/// coordinates and units), scaled by `scale` (its file's unit in this
/// file's length unit, exact in double-double), turned by `orientation`
/// and its file's origin put at `origin`, as an include is placed.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    pub origin: [f64; 3],
    pub orientation: Orientation,
    pub scale: DD,
    pub mesh: Arc<MeshBody>,
}

/// A mesh's own second moment, C = m s² R (J/V) Rᵀ for its integrals'
/// J about the centroid and measure V (volume or area) in its file's
/// units and the scale s to this file's, with its error model: J/V's
/// bound (absolute, from `mesh::Bound`) moved through R into every entry
/// (at most 3 of it, |R| rows of 1-norm √3 twice), and the mass's.
fn mesh_second_moment<T: Real>(
    units: Option<Units>,
    orientation: &Orientation,
    scale: DD,
    mesh: &crate::mesh::MeshBody,
    m: T,
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
    let own = units.map(|u| {
        let unit = error::unit_of::<T>();
        let rel_v = mesh.bound.measure / mesh.measure.hi.abs();
        let measured = if u.by_density { rel_v / unit } else { 0.0 };
        let mu = u.mass + u.placed + measured;
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

impl Mesh {
    /// The outline's box, its corners placed one at a time (no list of
    /// a million placed corners for a plausibility check).
    pub fn extent(&self) -> [V3; 2] {
        let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
        for q in self.placed_points() {
            for k in 0..3 {
                // As `Outline::extent` adds a corner (−0 + 0 is +0).
                b[0][k] = b[0][k].min(q[k] - 0.0);
                b[1][k] = b[1][k].max(q[k] + 0.0);
            }
        }
        b
    }

    /// Its welded corners in the file's frame: scaled, turned and moved.
    fn placed_points(&self) -> impl Iterator<Item = V3> + '_ {
        let [x, y, z] = axes(&self.orientation.matrix());
        let s = self.scale.f64();
        self.mesh.points.iter().map(move |p| {
            add(
                self.origin,
                comb(&[(p[0] * s, x), (p[1] * s, y), (p[2] * s, z)]),
            )
        })
    }
}

impl ShapeKind for Mesh {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Mesh,
        name: "mesh",
        keys: &[
            "file",
            "mesh_unit",
            "mode",
            "weld",
            "origin",
            "rotation",
            "mass",
            "density",
            "areal_density",
            "thickness",
            "material",
            "remove",
        ],
        density: Some(PER_VOLUME),
        sizes: &["file"],
        size_items: 0,
        centred: &["origin"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 0,
        degenerate: "an open or inside-out surface, or a triangle repeated (zero-area triangles, T-junctions and pieces touching along an edge are answered, with a warning)",
        help: "a mesh takes `file` (STL or OBJ, relative to the part file), `mesh_unit` (the file's length unit), `mass`, `density` or `material`, optional `origin` and `rotation`, and `weld` (corners closer than it merged; never by default); `mode = \"shell\"` weighs the surface as a sheet: `mass`, `areal_density`, or `thickness` with `density` or `material`",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "triangle mesh: exact polyhedral integrals (src/mesh)",
        dims: &[],
        measure: "",
        moments: [
            "",
            "",
            "",
        ],
    };

    /// (its measure is its file’s: `shapes::error`).
    const MEASURE_ROUNDINGS: f64 = 0.0;

    /// (its integrals carry their own bound: `part`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = None;

    fn measure_of<T: Real>(d: &[T]) -> T {
        let [] = d else {
            unreachable!("the model passes a mesh no dimensions")
        };
        T::of(1.0)
    }

    fn moments_of<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [] = d else {
            unreachable!("the model passes a mesh no dimensions")
        };
        [T::of(0.0); 3]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    /// Its measure in its file's units times the scale to the power of
    /// its mode (volume or area).
    /// Read with its file (`model::mesh`), never here.
    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        Err(r.elsewhere())
    }

    fn measure<T: Real, L: Lift>(&self, _: L) -> T {
        let s = T::of_dd(self.scale);
        let mut m = T::of_dd(self.mesh.measure);
        for _ in 0..self.mesh.mode.power() {
            m = m * s;
        }
        m
    }

    /// s^k (k products, and s's own rounding to T k times); the
    /// measure's own bound, relative, is added in its second moment's
    /// error model.
    fn measure_error(&self) -> f64 {
        2.0 * f64::from(self.mesh.mode.power()) + 1.0
    }

    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        let r: M3<T> = self.orientation.matrix();
        let c = self.mesh.centroid.map(|x| T::of_dd(x * self.scale));
        let o: [T; 3] = at(&self.origin, l);
        std::array::from_fn(|i| o[i] + r[i][0] * c[0] + r[i][1] * c[1] + r[i][2] * c[2])
    }

    /// Its integrals' bound, scaled and turned (a row of R has 1-norm at
    /// most √3 < 2), and 2⁻⁹⁸ of it along every axis.
    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
        let mesh = 2.0 * self.mesh.bound.centroid * self.scale.hi.abs();
        std::array::from_fn(|j| at + mesh + centroid[j].abs() * 3.155_443_620_884_047e-30)
    }

    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        _: L,
    ) -> (M3<T>, Option<Own>) {
        mesh_second_moment(units, &self.orientation, self.scale, &self.mesh, m)
    }

    fn shortest_span(&self) -> f64 {
        f64::INFINITY
    }

    /// Its one moment checked is the trace.
    fn independent_moments(&self, _: f64, j: &M3<f64>) -> ([f64; 3], usize, usize) {
        (
            [j[0][0] + j[1][1] + j[2][2], 0.0, 0.0],
            1,
            Self::INFO.nonzero_moments,
        )
    }

    fn moved(&mut self, m: &impl Mover) {
        self.origin = m.point(self.origin);
        self.scale = self.scale.mul_f64(m.length());
        m.turn(&mut self.orientation);
    }

    /// Per volume or per area by its mode.
    fn density_power(&self) -> i32 {
        self.mesh.mode.power()
    }

    fn scaled_rounding(&self) -> Option<f64> {
        None
    }

    fn reach(&self) -> f64 {
        norm1(&self.origin)
    }

    fn positions(&self) -> ([[f64; 3]; 4], usize) {
        points(&[self.origin])
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        for (i, x) in self.origin.iter_mut().enumerate() {
            f(Slot::At(i as u8), x);
        }
    }

    fn reset_from(&mut self, src: &Self) {
        self.origin = src.origin;
        self.scale = src.scale;
        if !Arc::ptr_eq(&self.mesh, &src.mesh) {
            self.mesh = src.mesh.clone();
        }
        reset_turn(&mut self.orientation, &src.orientation);
    }

    /// Symmetric in no local plane in general: its turn completed as S R F
    /// and its data reflected in the same local plane (the centroid's
    /// coordinate and the products with that axis change sign), so the
    /// image is S R F (F p) = S R p, for every point p of the mesh.
    fn mirror(&mut self) {
        let k = mirror_axis::<Self>();
        flip(k, &mut self.orientation);
        self.mesh = Arc::new(self.mesh.reflected(k));
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn turn(&self) -> Option<M3<f64>> {
        Some(self.orientation.matrix())
    }

    /// Its silhouette edges in each view.
    fn outline(&self) -> Outline {
        let points = self.placed_points().collect();
        Outline::Pieces(vec![Piece::Silhouette {
            points,
            faces: self.mesh.faces.clone(),
        }])
    }

}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{FileType, Mode};

    /// A tetrahedron with a corner at −0 and odd coordinates.
    const TET: &str = "v -0.0 0 0\nv 1.375 -0.25 0.5\nv 0.125 2.5 -0.75\nv 0.3 0.7 1.9\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

    #[test]
    fn a_mesh_gives_the_box_of_its_outline_bit_for_bit_without_making_it() {
        let body = Arc::new(MeshBody::load(FileType::Obj, TET.as_bytes(), Mode::Solid).unwrap());
        for (orientation, scale, origin) in [
            (Orientation::Identity, 1.0, [0.0; 3]),
            (Orientation::AxisAngle([1.0, 2.0, 3.0], 37.0), 0.001, [1e4, -3.0, -0.0]),
            (Orientation::AxisAngle([0.0, 0.0, 1.0], 90.0), 25.4, [-0.5, 0.25, 7.0]),
        ] {
            let m = Mesh {
                origin,
                orientation,
                scale: DD::of(scale),
                mesh: body.clone(),
            };
            let bits = |b: [V3; 2]| b.map(|c| c.map(f64::to_bits));
            assert_eq!(bits(m.extent()), bits(m.outline().extent()));
            let place = super::super::Place::Mesh(m.clone());
            assert_eq!(bits(place.extent()), bits(m.outline().extent()));
        }
    }
}
