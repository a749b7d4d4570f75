//! The description of each shape that the rules of a part file read: one
//! `ShapeInfo` per shape in `SHAPES`. Adding a shape is its closed form in
//! `shapes`, one entry here and its tests (docs/architecture.md).

use super::Shape;
use crate::units::Dim;
use serde::Serialize;

/// What a shape's density is per, and so which key gives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DensityKind {
    /// The key: `density`, `areal_density` or `linear_density`.
    pub key: &'static str,
    pub dim: Dim,
    /// The power of length the density is per (3, 2 or 1): how it scales
    /// when a sub-assembly's units are converted.
    pub length_power: i32,
}

/// Per volume: `density`, kg/m³.
pub const PER_VOLUME: DensityKind = DensityKind {
    key: "density",
    dim: Dim::DENSITY,
    length_power: 3,
};
/// Per area: `areal_density`, kg/m², for thin plates.
pub const PER_AREA: DensityKind = DensityKind {
    key: "areal_density",
    dim: Dim::AREAL_DENSITY,
    length_power: 2,
};
/// Per length: `linear_density`, kg/m, for slender rods.
pub const PER_LENGTH: DensityKind = DensityKind {
    key: "linear_density",
    dim: Dim::LINEAR_DENSITY,
    length_power: 1,
};

/// The dimensions a shape is given by, in the order `second_moments`
/// takes them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dims {
    /// `size`, an array of this many positive lengths (box, plate).
    Size(usize),
    /// `length`, one positive length (rod).
    Length,
    /// `radius`, an optional `inner_radius` from 0 to it, and a positive
    /// `length` if `length` is true: [R, r] or [R, r, L].
    Radii { length: bool },
    /// `vertices`: three points; the one dimension is the area.
    Vertices,
    /// A given tensor, `inertia` (rows, about the centroid in local axes).
    Given,
    /// None (a point).
    None,
    /// A cone: `radius` (or `diameter`), `inner_radius`, `top_radius`,
    /// `top_inner_radius` and `length`: [R₀, a₀, R₁, a₁, L].
    Cone,
    /// A torus: `radius` (centre line), `tube_radius`, `inner_tube_radius`:
    /// [R, a, b].
    Torus,
    /// A prism: `polygon` and `length`; the dimensions [area, length].
    Polygon,
    /// A mesh `file` (`mesh`): its integrals come from the file.
    Mesh,
}

impl Dims {
    /// How many numbers the closed forms take (see `Shape::second_moments`).
    pub fn count(self) -> usize {
        match self {
            Dims::Size(n) => n,
            Dims::Radii { length: true } => 3,
            Dims::Radii { length: false } => 2,
            // A triangle's one "dimension" is its area (see `measure_of`).
            Dims::Length | Dims::Vertices => 1,
            Dims::Given | Dims::None | Dims::Mesh => 0,
            Dims::Cone => 5,
            Dims::Torus => 3,
            Dims::Polygon => 2,
        }
    }

    /// The keys that give the dimensions.
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            Dims::Size(_) => &["size"],
            Dims::Length => &["length"],
            Dims::Radii { length: true } => &["radius", "inner_radius", "length"],
            Dims::Radii { length: false } => &["radius", "inner_radius"],
            Dims::Vertices => &["vertices"],
            Dims::Given => &["inertia"],
            Dims::None => &[],
            Dims::Cone => &[
                "radius",
                "inner_radius",
                "top_radius",
                "top_inner_radius",
                "length",
            ],
            Dims::Torus => &["radius", "tube_radius", "inner_tube_radius"],
            Dims::Polygon => &["polygon", "length"],
            Dims::Mesh => &["file"],
        }
    }
}

/// A second way to place a shape, by the vectors that span it, beside the
/// centred one (`center` and `rotation` with the dimensions).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spanned {
    /// `corner` and this many perpendicular `edges` (box 3, plate 2).
    CornerEdges(usize),
    /// `from` and `to` (rod).
    FromTo,
}

impl Spanned {
    /// The keys of this placement.
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            Spanned::CornerEdges(_) => &["corner", "edges"],
            Spanned::FromTo => &["from", "to"],
        }
    }

    /// The number of edge vectors.
    pub fn edges(self) -> usize {
        match self {
            Spanned::CornerEdges(n) => n,
            Spanned::FromTo => 1,
        }
    }
}

/// What turns a named `material`'s density (per volume) into the shape's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MaterialRule {
    /// Per volume already.
    Volume,
    /// Times the `thickness` (plates, disks, triangles).
    Thickness,
    /// Times the section: `area`, or the disc of `diameter` (rods).
    Section,
    /// The shape takes no material (`mass` only).
    None,
}

/// Everything the rules of a part file know about a shape: the one
/// description every reader consults (validation, includes, idealisation,
/// suggestions, docs/part-file.md). See docs/architecture.md for adding a
/// shape.
#[derive(Clone, Copy, Debug)]
pub struct ShapeInfo {
    pub shape: Shape,
    /// The name in part files (`shape = "box"`).
    pub name: &'static str,
    /// Every key a part of this shape accepts, besides `name` and `shape`.
    pub keys: &'static [&'static str],
    /// The density it takes instead of `mass`; `None`: `mass` only.
    pub density: Option<DensityKind>,
    pub dims: Dims,
    /// The keys of the centred placement that conflict with `spanned`'s.
    pub centred: &'static [&'static str],
    /// The other placement, if the shape has one.
    pub spanned: Option<Spanned>,
    pub material: MaterialRule,
    /// The key giving the real size of a thin or slender idealisation, and
    /// the solid it describes (`report::ideal`).
    pub real_size: Option<(&'static str, Solid)>,
    /// How many of the three local second moments are non-zero (0 where
    /// the model checks the shape's own way: a triangle, a given tensor).
    pub nonzero_moments: usize,
    /// How `render` draws it (`render::drawing::outline`).
    pub drawn: Drawn,
    /// What makes it degenerate, for the docs and messages.
    pub degenerate: &'static str,
    /// The help shown with an error about its keys.
    pub help: &'static str,
}

/// How `render` draws a shape (`render::drawing::outline`) from its
/// placed dimensions (`part::Place`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Drawn {
    /// The convex hull of its corners (box, plate).
    Corners,
    /// Its segment along local z (rod).
    Segment,
    /// Its rims at ±L/2 and the lines tangent to both (cylinder, cone).
    Frustum,
    /// Its rims in the local x–y plane (disk).
    Rims,
    /// Its outline circle (sphere).
    Ball,
    /// Its rim and its dome's outline (hemisphere).
    Dome,
    /// Its tube's outline (torus).
    Ring,
    /// Its three edges (triangle).
    Edges,
    /// Its end polygons and the edges between them (prism).
    Extruded,
    /// Its silhouette edges in each view (mesh).
    Silhouette,
    /// A dot (point mass).
    Point,
    /// A square with its diagonals (a given inertia).
    Given,
}

/// The solid that a thin plate or slender rod idealises.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Solid {
    /// A plate a × b of thickness t: the box a × b × t.
    Box,
    /// A rod of length L and diameter d: the solid circular cylinder.
    Cylinder,
}

impl Solid {
    pub fn name(self) -> &'static str {
        match self {
            Solid::Box => "box",
            Solid::Cylinder => "cylinder",
        }
    }
}

/// The shapes, in the order of `Shape`'s variants.
pub const SHAPES: [ShapeInfo; 14] = [
    ShapeInfo {
        shape: Shape::Box,
        name: "box",
        keys: &[
            "density", "size", "center", "rotation", "corner", "edges", "mass", "remove",
            "material",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Size(3),
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(3)),
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Corners,
        degenerate: "a zero or non-perpendicular edge",
        help: "a box takes `mass` or `density`, and `size` with `center` (and optional `rotation`), or `corner` with three `edges`",
    },
    ShapeInfo {
        shape: Shape::Plate,
        name: "plate",
        keys: &[
            "areal_density",
            "size",
            "center",
            "rotation",
            "corner",
            "edges",
            "mass",
            "remove",
            "thickness",
            "material",
        ],
        density: Some(PER_AREA),
        dims: Dims::Size(2),
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(2)),
        material: MaterialRule::Thickness,
        real_size: Some(("thickness", Solid::Box)),
        nonzero_moments: 2,
        drawn: Drawn::Corners,
        degenerate: "a zero or non-perpendicular edge",
        help: "a plate takes `mass` or `areal_density`, and `size` = [x, y] with `center` (and optional `rotation`), or `corner` with two `edges`; optionally its real `thickness`",
    },
    ShapeInfo {
        shape: Shape::Rod,
        name: "rod",
        keys: &[
            "linear_density",
            "length",
            "center",
            "rotation",
            "from",
            "to",
            "mass",
            "remove",
            "diameter",
            "material",
            "area",
        ],
        density: Some(PER_LENGTH),
        dims: Dims::Length,
        centred: &["length", "center", "rotation"],
        spanned: Some(Spanned::FromTo),
        material: MaterialRule::Section,
        real_size: Some(("diameter", Solid::Cylinder)),
        nonzero_moments: 1,
        drawn: Drawn::Segment,
        degenerate: "`to` equal to `from`",
        help: "a rod takes `mass` or `linear_density`, and `length` with `center` (and optional `rotation`), or `from` and `to`; optionally its real `diameter`",
    },
    ShapeInfo {
        shape: Shape::Cylinder,
        name: "cylinder",
        keys: &[
            "density",
            "radius",
            "inner_radius",
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
        dims: Dims::Radii { length: true },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Frustum,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a cylinder takes `mass` or `density`, `radius` (or `diameter`) and `length` (along its local z) with `center` (and optional `rotation`); an `inner_radius` makes it a tube",
    },
    ShapeInfo {
        shape: Shape::Disk,
        name: "disk",
        keys: &[
            "areal_density",
            "radius",
            "inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "thickness",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_AREA),
        dims: Dims::Radii { length: false },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Thickness,
        real_size: None,
        nonzero_moments: 2,
        drawn: Drawn::Rims,
        degenerate: "a density on a thin ring (`inner_radius` = `radius`)",
        help: "a disk takes `mass` or `areal_density`, and `radius` or `diameter` (in its local x–y plane) with `center` (and optional `rotation`); an `inner_radius` makes it an annulus",
    },
    ShapeInfo {
        shape: Shape::Sphere,
        name: "sphere",
        keys: &[
            "density",
            "radius",
            "inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Radii { length: false },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Ball,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a sphere takes `mass` or `density`, and `radius` (or `diameter`) with `center`; an `inner_radius` makes it hollow (equal to `radius`: a thin shell)",
    },
    ShapeInfo {
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
        dims: Dims::Vertices,
        centred: &[],
        spanned: None,
        material: MaterialRule::Thickness,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Edges,
        degenerate: "(nearly) collinear vertices",
        help: "a triangle takes `mass` or `areal_density`, and three `vertices` = [[x, y, z], [x, y, z], [x, y, z]] in the file's frame",
    },
    ShapeInfo {
        shape: Shape::Point,
        name: "point",
        keys: &["center", "mass"],
        density: None,
        dims: Dims::None,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::None,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Point,
        degenerate: "none",
        help: "a point takes `mass` and `center`",
    },
    ShapeInfo {
        shape: Shape::Inertia,
        name: "inertia",
        keys: &[
            "mass", "center", "rotation", "inertia", "products", "remove",
        ],
        density: None,
        dims: Dims::Given,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::None,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Given,
        degenerate: "a tensor that is not symmetric or not physically valid",
        help: "an inertia part takes `mass`, `center`, `inertia` = [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] about its centroid in its local axes (optional `rotation`), tensor convention unless `products = \"positive\"`",
    },
    ShapeInfo {
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
        dims: Dims::Cone,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Frustum,
        degenerate: "a zero `length` (a disk), both radii 0, or a density on a thin shell (each inner radius equal to its outer)",
        help: "a cone takes `mass` or `density`, `radius` (or `diameter`) at its base, `top_radius` (0 for a full cone) and `length` along its local z, with `center` at the middle of its axis (and optional `rotation`); `inner_radius` and `top_inner_radius` make it hollow",
    },
    ShapeInfo {
        shape: Shape::Torus,
        name: "torus",
        keys: &[
            "density",
            "radius",
            "tube_radius",
            "inner_tube_radius",
            "material",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Torus,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Ring,
        degenerate: "a `tube_radius` above `radius` (self-intersecting), or a density on a thin shell (`inner_tube_radius` = `tube_radius`)",
        help: "a torus takes `mass` or `density`, `radius` (its axis to the tube's centre) and `tube_radius` (at most `radius`), with `center` (and optional `rotation`; its axis is local z); an `inner_tube_radius` makes the tube hollow",
    },
    ShapeInfo {
        shape: Shape::Hemisphere,
        name: "hemisphere",
        keys: &[
            "density",
            "radius",
            "inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Radii { length: false },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Dome,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a hemisphere takes `mass` or `density`, and `radius` (or `diameter`) with `center`, the centre of its sphere (flat face in its local x–y plane, dome toward +z; optional `rotation`); an `inner_radius` makes it hollow (equal to `radius`: a thin shell)",
    },
    ShapeInfo {
        shape: Shape::Prism,
        name: "prism",
        keys: &[
            "density", "polygon", "length", "origin", "rotation", "mass", "remove", "material",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Polygon,
        centred: &[],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Extruded,
        degenerate: "fewer than 3 vertices, a repeated vertex, crossing edges or no area",
        help: "a prism takes `mass` or `density`, a `polygon` = [[x, y], …] in its local x–y plane (either orientation) and `length` along its local z (from −length/2 to +length/2), with optional `origin` (where its local origin goes) and `rotation`",
    },
    ShapeInfo {
        shape: Shape::Mesh,
        name: "mesh",
        keys: &[
            "file",
            "mesh_unit",
            "mode",
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
        dims: Dims::Mesh,
        centred: &["origin"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Silhouette,
        degenerate: "an open, inconsistently oriented or inside-out surface, or a triangle of zero area",
        help: "a mesh takes `file` (STL or OBJ, relative to the part file), `mesh_unit` (the file's length unit), `mass`, `density` or `material`, optional `origin` and `rotation`; `mode = \"shell\"` weighs the surface as a sheet: `mass`, `areal_density`, or `thickness` with `density` or `material`",
    },
];
