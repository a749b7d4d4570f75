//! A triangle: a thin triangular plate given by its three vertices in
//! the file's frame. Its one "dimension" is its area; its mass, centroid
//! and second moment come from its vertices (`part::Place::Vertices`),
//! not from closed forms here.

use super::common::{density_power, norm1, points, spanned};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::error;
use super::lift::{Fixed, Lift, lift3, xyz};
use super::outline::{Outline, Piece};
use super::{
    MaterialRule, Mover, Own, PER_AREA, Shape, ShapeInfo, ShapeKind, Slot, Units, product,
};
use crate::numeric::{DD, M3, Real, norm_of};

/// A thin triangular plate by its three vertices, in its file's frame and
/// units.
#[derive(Debug, Clone, PartialEq)]
pub struct Triangle {
    pub vertices: [[f64; 3]; 3],
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

/// |b − a|.
fn distance(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3)
        .map(|i| (a[i] - b[i]) * (a[i] - b[i]))
        .sum::<f64>()
        .sqrt()
}

impl ShapeKind for Triangle {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Triangle,
        name: "triangle",
        keys: &[
            "areal_density",
            "vertices",
            "mass",
            "remove",
            "material",
            "thickness",
        ],
        density: Some(PER_AREA),
        sizes: &["vertices"],
        size_items: 0,
        centred: &[],
        spanned: None,
        material: MaterialRule::Thickness,
        real_size: None,
        nonzero_moments: 0,
        degenerate: "(nearly) collinear vertices",
        help: "a triangle takes `mass` or `areal_density`, and three `vertices` = [[x, y, z], [x, y, z], [x, y, z]] in the file's frame",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "thin triangle: (m/12) Σ eₖeₖᵀ over its vertices less its centroid, in the file's axes",
        dims: &[],
        measure: "",
        moments: [
            "",
            "",
            "",
        ],
    };

    /// (its area is formed from its vertices: `shapes::error`).
    const MEASURE_ROUNDINGS: f64 = 1.0;

    /// (its second moment is formed from its vertices: `part::error::OUTER`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn moments_of<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [_] = d else {
            unreachable!("the model passes a triangle its area")
        };
        [T::of(0.0); 3]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    /// Its area, |a × b|/2 from its edges from the first vertex.
    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        Ok(Triangle {
            vertices: r.vectors("vertices")?,
        })
    }

    fn measure<T: Real, L: Lift>(&self, l: L) -> T {
        let d = triangle_offsets::<T, L>(&self.vertices, l);
        let (a, b) = (sub3(d[1], d[0]), sub3(d[2], d[0]));
        let c = [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ];
        norm_of(&c) / T::of(2.0)
    }

    fn measure_error(&self) -> f64 {
        error::triangle_area(&self.vertices)
    }

    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        triangle_centroid(&self.vertices, l)
    }

    /// 2⁻⁹⁸ of it along each axis its vertices do not share, and the
    /// frames' `at`.
    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
        let v = &self.vertices;
        std::array::from_fn(|j| {
            at + if !(v[0][j] == v[1][j] && v[1][j] == v[2][j]) {
                centroid[j].abs() * 3.155_443_620_884_047e-30
            } else {
                0.0
            }
        })
    }

    /// ∫ρρᵀ dm of a uniform triangle about its centroid g is (m/12) Σ dᵢdᵢᵀ
    /// with dᵢ = vᵢ − g (from ∫ρρᵀ dA = (A/12)(Σ vᵢvᵢᵀ + s sᵀ), s = Σ vᵢ,
    /// about any origin).
    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        l: L,
    ) -> (M3<T>, Option<Own>) {
        spanned(m, &triangle_offsets(&self.vertices, l), units)
    }

    /// Its shortest edge: the frames' rounding of its vertices over it.
    fn shortest_span(&self) -> f64 {
        let v = &self.vertices;
        distance(&v[0], &v[1])
            .min(distance(&v[1], &v[2]))
            .min(distance(&v[2], &v[0]))
    }

    /// Its one moment checked is the trace.
    fn independent_moments(&self, _: f64, j: &M3<f64>) -> ([f64; 3], usize, usize) {
        ([j[0][0] + j[1][1] + j[2][2], 0.0, 0.0], 1, 1)
    }

    fn moved(&mut self, m: &impl Mover) {
        self.vertices = self.vertices.map(|x| m.point(x));
    }

    fn density_power(&self) -> i32 {
        density_power::<Self>()
    }

    fn scaled_rounding(&self) -> Option<f64> {
        None
    }

    fn reach(&self) -> f64 {
        self.vertices.iter().map(norm1).fold(0.0, f64::max)
    }

    fn positions(&self) -> ([[f64; 3]; 4], usize) {
        points(&self.vertices)
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        for (k, v) in self.vertices.iter_mut().enumerate() {
            for (i, x) in v.iter_mut().enumerate() {
                f(Slot::Vertex(k as u8, i as u8), x);
            }
        }
    }

    fn reset_from(&mut self, src: &Self) {
        self.vertices = src.vertices;
    }

    /// Its vertices alone place it, already reflected.
    fn mirror(&mut self) {}

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn turn(&self) -> Option<M3<f64>> {
        None
    }

    fn outline(&self) -> Outline {
        Outline::Pieces(vec![Piece::Line {
            points: self.vertices.to_vec(),
            closed: true,
        }])
    }
}
