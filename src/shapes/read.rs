//! How a shape's module reads its numbers: `Reader`, what the model's
//! reader of a part file gives it (each number in the file's units, read
//! once and range-checked as it is read), so that each module builds its
//! placed form, named, from the keys it declares.

use crate::diag::Diagnostic;
use crate::rotation::Orientation;

/// A part's numbers as a shape's module asks for them, in the file's
/// units. Each is read once, in the order the module asks, and checked
/// as it is read (a missing key, a value out of range, a tolerance
/// recorded: hence `&mut`).
pub trait Reader {
    /// The point under `key` (`center`, `corner`, `from`, `to`).
    fn point(&mut self, key: &'static str) -> Result<[f64; 3], Diagnostic>;
    /// The optional `origin`, or the file's origin.
    fn origin(&mut self) -> Result<[f64; 3], Diagnostic>;
    /// The rows of vectors under `key` (`edges`, `vertices`).
    fn vectors<const N: usize>(&mut self, key: &'static str) -> Result<[[f64; 3]; N], Diagnostic>;
    /// The lengths of `size`.
    fn sizes<const N: usize>(&mut self) -> Result<[f64; N], Diagnostic>;
    /// The length under `key`.
    fn length(&mut self, key: &'static str) -> Result<f64, Diagnostic>;
    /// `radius` (or half `diameter`), then `inner_radius` (or half
    /// `inner_diameter`; 0 when absent).
    fn radii(&mut self) -> Result<[f64; 2], Diagnostic>;
    /// A cone's radii and length: [R₀, a₀, R₁, a₁, L].
    fn cone(&mut self) -> Result<[f64; 5], Diagnostic>;
    /// A torus's radii: [R, a, b].
    fn torus(&mut self) -> Result<[f64; 3], Diagnostic>;
    /// A prism's polygon.
    fn polygon(&mut self) -> Result<Vec<[f64; 2]>, Diagnostic>;
    /// A given `inertia`, in the tensor convention.
    fn inertia(&mut self) -> Result<[[f64; 3]; 3], Diagnostic>;
    /// The part's turn (`rotation`, or none).
    fn orientation(&self) -> Orientation;
    /// Whether the part is placed by the vectors that span it (`corner`
    /// and `edges`, `from` and `to`).
    fn by_edges(&self) -> bool;
    /// The shape's own key `key` (`ShapeKind::OWN_KEYS`), declared
    /// `Kind::Quantity`: in the file's units, checked as declared (> 0),
    /// its tolerance recorded if it may have one.
    fn quantity(&mut self, key: &'static str) -> Result<f64, Diagnostic>;
    /// The shape's own key `key`, declared `Kind::Quantities(Some(N))`:
    /// each of its N quantities as `quantity` reads one.
    fn quantities<const N: usize>(&mut self, key: &'static str) -> Result<[f64; N], Diagnostic>;
    /// Said of a shape that is read with its own file (a mesh,
    /// `model::mesh`), never here.
    fn elsewhere(&self) -> Diagnostic;
}
