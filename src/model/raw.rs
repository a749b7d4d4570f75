//! The part file exactly as written, as the reader (`fast`) reads it:
//! every value `Spanned`, so the conversion step in `model` can point at
//! it.
//!
//! NOTE: parts are one *flat* struct with `shape` as a string, not an enum
//! by shape: the reader takes a part's keys as they come, before it knows
//! the shape. Which keys apply to which shape is checked in `model`.

use toml::Spanned;

mod own;
pub use own::{Own, OwnValue, holdable};

/// An array of quantities, e.g. `center = [0, "5 mm", 1]`.
pub type Vector = Spanned<Vec<Spanned<Quantity>>>;
/// An array of plain numbers (rotation parameters carry no unit).
pub type Floats = Spanned<Vec<Spanned<f64>>>;

#[derive(Debug)]
pub struct RawFile {
    pub name: Option<Spanned<String>>,
    pub units: Option<Spanned<RawUnits>>,
    pub part: Option<Spanned<Vec<Spanned<RawPart>>>>,
    pub analysis: Option<Spanned<RawAnalysis>>,
    pub expect: Option<Spanned<RawExpect>>,
    /// `[materials]`: name → { density }, adding to the built-in ones.
    pub materials: Option<Materials>,
    /// `[params]`: named quantities that any quantity string may use
    /// (`model::params`).
    pub params: Option<Params>,
    /// `[growth]`: maturity name → mass growth allowance, a percentage
    /// string (`estimated = "15 %"`; `model::budget`).
    pub growth: Option<Growth>,
    /// `[budget]`: the not-to-exceed limit of the predicted mass.
    pub budget: Option<Spanned<RawBudget>>,
    /// `[envelope]`: the loading envelope (`model::envelope`).
    pub envelope: Option<Spanned<RawEnvelope>>,
    /// `[[case]]`: the body's loading cases, in file order (`model::case`).
    pub case: Option<Spanned<Vec<Spanned<RawCase>>>>,
}

/// `[envelope]`: the axis, the polygon's `points` (`[x, mass]` pairs), the
/// optional `mac` and the `sequences` of case names.
#[derive(Debug, Default)]
pub struct RawEnvelope {
    pub axis: Option<Spanned<String>>,
    pub points: Option<Spanned<Vec<Vector>>>,
    pub mac: Option<Spanned<RawMac>>,
    pub sequences: Option<Spanned<Vec<Names>>>,
}

/// An array of names, e.g. one of `sequences`.
pub type Names = Spanned<Vec<Spanned<String>>>;

/// `[envelope] mac = { leading_edge, length }`.
#[derive(Debug, Default)]
pub struct RawMac {
    pub leading_edge: Option<Spanned<Quantity>>,
    pub length: Option<Spanned<Quantity>>,
}

/// One `[[case]]`: the file in another state (`model::case`).
#[derive(Debug, Default)]
pub struct RawCase {
    pub name: Option<Spanned<String>>,
    /// Values in place of the file's `[params]` definitions.
    pub params: Option<Params>,
    /// Parts and sub-assemblies absent, named as `--only` names them.
    pub without: Option<Spanned<Vec<Spanned<String>>>>,
    /// `group` paths absent, with their sub-groups.
    pub without_groups: Option<Spanned<Vec<Spanned<String>>>>,
    /// The case's own `[expect]`.
    pub expect: Option<Spanned<RawExpect>>,
}

/// `[params]`, or an include's `params`: name → a number or a quantity
/// string, which may be an expression over the others.
pub type Params = Spanned<std::collections::BTreeMap<Spanned<String>, Spanned<Quantity>>>;

/// `[growth]`: maturity name → allowance (a percentage string; a plain
/// number is read only to be refused with a hint).
pub type Growth = Spanned<std::collections::BTreeMap<Spanned<String>, Spanned<Quantity>>>;

/// `[budget]`.
#[derive(Debug)]
pub struct RawBudget {
    /// The not-to-exceed limit of the predicted mass: a mass.
    pub limit: Spanned<Quantity>,
}

/// `[materials]`.
pub type Materials = Spanned<std::collections::BTreeMap<String, Spanned<RawMaterial>>>;

#[derive(Debug)]
pub struct RawMaterial {
    pub density: Spanned<Quantity>,
}

#[derive(Debug, Default)]
pub struct RawUnits {
    pub length: Option<Spanned<String>>,
    pub mass: Option<Spanned<String>>,
}

/// NOTE: the keys most parts give (`name`, `shape`, `mass`, `size`,
/// `center`) are kept in the struct; every other key is boxed, so that a
/// part is 368 bytes, not 1,240: a file's parts are all held at once while
/// it is read, and they were most of the memory of reading a large file.
#[derive(Debug, Default)]
pub struct RawPart {
    pub name: Option<Spanned<String>>,
    /// The primitive; absent only in a part that `include`s a file.
    pub shape: Option<Spanned<String>>,
    pub mass: Option<Spanned<Quantity>>,
    pub density: Option<Box<Spanned<Quantity>>>,
    pub areal_density: Option<Box<Spanned<Quantity>>>,
    pub linear_density: Option<Box<Spanned<Quantity>>>,
    pub size: Option<Vector>,
    pub length: Option<Box<Spanned<Quantity>>>,
    pub center: Option<Vector>,
    pub rotation: Option<Box<Spanned<RawRotation>>>,
    pub corner: Option<Box<Vector>>,
    pub edges: Option<Box<Spanned<Vec<Vector>>>>,
    pub from: Option<Box<Vector>>,
    pub to: Option<Box<Vector>>,
    /// A plate's real thickness: reported against, never composed.
    pub thickness: Option<Box<Spanned<Quantity>>>,
    /// A rod's real diameter: reported against, never composed. For a
    /// cylinder, disk, sphere, cone or hemisphere, twice its `radius`.
    pub diameter: Option<Box<Spanned<Quantity>>>,
    /// Cylinder, disk, sphere, cone, hemisphere (outer radius, and the
    /// optional inner one), torus (its axis to the tube's centre).
    pub radius: Option<Box<Spanned<Quantity>>>,
    pub inner_radius: Option<Box<Spanned<Quantity>>>,
    /// Cylinder, disk, sphere, cone and hemisphere: the inner diameter,
    /// instead of `inner_radius` (`diameter` gives the outer one).
    pub inner_diameter: Option<Box<Spanned<Quantity>>>,
    /// A cone's radius at its top (local z = +length/2).
    pub top_radius: Option<Box<Spanned<Quantity>>>,
    /// A hollow cone's inner radius at its top.
    pub top_inner_radius: Option<Box<Spanned<Quantity>>>,
    /// A torus's tube radius.
    pub tube_radius: Option<Box<Spanned<Quantity>>>,
    /// A hollow torus's inner tube radius.
    pub inner_tube_radius: Option<Box<Spanned<Quantity>>>,
    /// A prism's polygon: [x, y] vertices in its local x–y plane.
    pub polygon: Option<Box<Spanned<Vec<Vector>>>>,
    /// Another part file placed here as a sub-assembly.
    pub include: Option<Box<Spanned<String>>>,
    /// Where the included file's origin goes (with `include`), or a
    /// prism's local origin.
    pub origin: Option<Box<Vector>>,
    /// Parameters passed to the included file (with `include`).
    pub params: Option<Box<Params>>,
    /// An included robot description's joint positions (with `include`).
    pub joints: Option<Box<Params>>,
    /// A named material instead of a density.
    pub material: Option<Box<Spanned<String>>>,
    /// A rod's cross-section area (with `material`).
    pub area: Option<Box<Spanned<Quantity>>>,
    /// A triangle's three vertices.
    pub vertices: Option<Box<Spanned<Vec<Vector>>>>,
    /// A given inertia tensor (rows) about the centroid, local axes.
    pub inertia: Option<Box<Spanned<Vec<Vector>>>>,
    /// Sign convention of `inertia`'s products: "tensor" or "positive".
    pub products: Option<Box<Spanned<String>>>,
    /// A cut-out: subtracted from the body.
    pub remove: Option<Box<Spanned<bool>>>,
    /// Copies of the part along a step or about an axis, named `NAME[i]`.
    pub array: Option<Box<Spanned<RawArray>>>,
    /// The part and its mirror image in a plane: `NAME[0]` and `NAME[1]`.
    pub mirror: Option<Box<Spanned<RawMirror>>>,
    /// A mesh's file (STL or OBJ), relative to the part file.
    pub file: Option<Box<Spanned<String>>>,
    /// The length unit of a mesh file's coordinates.
    pub mesh_unit: Option<Box<Spanned<String>>>,
    /// A solid mesh's corners closer than this merged (`mesh::near`).
    pub weld: Option<Box<Spanned<Quantity>>>,
    /// A mesh's mode: "solid" (the default) or "shell".
    pub mode: Option<Box<Spanned<String>>>,
    /// The part's group in the weight statement: a path of names joined
    /// by `/` (`propulsion/tanks`; `model::budget`).
    pub group: Option<Box<Spanned<String>>>,
    /// Its design maturity: a key of the file's `[growth]`.
    pub maturity: Option<Box<Spanned<String>>>,
    /// The tolerance of `mass` (`model::tolerance`): `0.1`, `"0.1 kg"`,
    /// `"2 %"`, `"± 0.1 kg uniform"`.
    pub tol: Option<Box<Spanned<Quantity>>>,
    /// The keys its shape declares itself (`ShapeKind::OWN_KEYS`).
    pub own: Option<Box<Own>>,
}

/// `array = { count = N, step = [dx, dy, dz] }`, or `{ count = N, axis =
/// [x, y, z], step_degrees = θ, origin = [x, y, z] }`: N copies of a part,
/// copy i moved by i·step, or turned by i·θ about the axis through
/// `origin`.
#[derive(Debug, Default, Clone)]
pub struct RawArray {
    /// How many copies, the part itself the first: a positive integer.
    pub count: Option<Spanned<Quantity>>,
    /// A linear array: the step from each copy to the next (lengths).
    pub step: Option<Vector>,
    /// A polar array: the axis the copies turn about (a direction, any
    /// non-zero length).
    pub axis: Option<Floats>,
    /// A polar array: the turn from each copy to the next, in degrees.
    pub step_degrees: Option<Spanned<Quantity>>,
    /// A polar array: a point of the axis (lengths); [0, 0, 0] if not given.
    pub origin: Option<Vector>,
}

/// `mirror = { normal = [x, y, z], origin = [x, y, z] }`: the part and its
/// mirror image in the plane through `origin` normal to `normal`.
#[derive(Debug, Default, Clone)]
pub struct RawMirror {
    /// The plane's normal (a direction, any non-zero length).
    pub normal: Option<Floats>,
    /// A point of the plane (lengths); [0, 0, 0] if not given.
    pub origin: Option<Vector>,
}

#[derive(Debug, Default)]
pub struct RawRotation {
    pub quaternion: Option<Floats>,
    pub axis: Option<Floats>,
    pub degrees: Option<Spanned<Angles>>,
    pub matrix: Option<Spanned<Vec<Floats>>>,
    pub intrinsic: Option<Spanned<String>>,
    pub extrinsic: Option<Spanned<String>>,
}

#[derive(Debug, Default)]
pub struct RawAnalysis {
    pub about: Option<Vector>,
    pub omega: Option<Vector>,
    pub alpha: Option<Vector>,
    /// The reference point's velocity, report axes (`analysis::motion`).
    pub velocity: Option<Vector>,
    /// Two axles' positions along an axis (`analysis::axles`).
    pub axles: Option<Spanned<RawAxles>>,
    /// The acceleration of gravity for the axle loads.
    pub g: Option<Spanned<Quantity>>,
    pub axes: Option<Spanned<RawAxes>>,
    /// `false`: no plausibility warnings for this file (`analysis::plausible`).
    pub warnings: Option<bool>,
}

/// `[analysis] axles = { axis, front, rear }`.
#[derive(Debug, Default)]
pub struct RawAxles {
    pub axis: Option<Spanned<String>>,
    pub front: Option<Spanned<Quantity>>,
    pub rear: Option<Spanned<Quantity>>,
}

/// `[analysis] axes`: the report axes' x and y directions in the file's
/// frame, or a rotation of the file's axes in any form a part's `rotation`
/// takes (the same keys; `model::rotation` reads them).
/// (`rotation()` hands the rotation's keys to the one reader of them.)
#[derive(Debug, Default)]
pub struct RawAxes {
    pub x: Option<Floats>,
    pub y: Option<Floats>,
    pub quaternion: Option<Floats>,
    pub axis: Option<Floats>,
    pub degrees: Option<Spanned<Angles>>,
    pub matrix: Option<Spanned<Vec<Floats>>>,
    pub intrinsic: Option<Spanned<String>>,
    pub extrinsic: Option<Spanned<String>>,
}

impl RawAxes {
    /// The rotation form's keys, as a part's `rotation` holds them.
    pub fn rotation(&self) -> RawRotation {
        RawRotation {
            quaternion: self.quaternion.clone(),
            axis: self.axis.clone(),
            degrees: self.degrees.clone(),
            matrix: self.matrix.clone(),
            intrinsic: self.intrinsic.clone(),
            extrinsic: self.extrinsic.clone(),
        }
    }
}

/// A number in the file's units, or a string with its own unit (`"3 mm"`).
#[derive(Debug, Clone, PartialEq)]
pub enum Quantity {
    Number(f64),
    Text(String),
}

/// `degrees`: one angle (axis–angle) or three (Euler angles).
#[derive(Debug, Clone, PartialEq)]
pub enum Angles {
    One(f64),
    Three(Vec<f64>),
}

/// `[expect]`: the quantities a check compares, each optional.
#[derive(Debug)]
pub struct RawExpect {
    pub mass: Option<Spanned<RawExpectation>>,
    pub center_of_mass: Option<Spanned<RawExpectation>>,
    pub principal_moments: Option<Spanned<RawExpectation>>,
    pub inertia_com: Option<Spanned<RawExpectation>>,
    pub inertia_ref: Option<Spanned<RawExpectation>>,
    pub radii_of_gyration: Option<Spanned<RawExpectation>>,
    pub radii_of_gyration_axes: Option<Spanned<RawExpectation>>,
    pub angular_momentum: Option<Spanned<RawExpectation>>,
    pub kinetic_energy: Option<Spanned<RawExpectation>>,
    /// The predicted body's (basic mass and growth: `massprop budget`).
    pub predicted_mass: Option<Spanned<RawExpectation>>,
    pub predicted_center_of_mass: Option<Spanned<RawExpectation>>,
    pub predicted_inertia_com: Option<Spanned<RawExpectation>>,
    /// Three unit rows, compared by angle (`tol_degrees`).
    pub principal_axes: Option<Spanned<RawExpectation>>,
    /// The body moving with `velocity` (`analysis::motion`).
    pub velocity_com: Option<Spanned<RawExpectation>>,
    pub linear_momentum: Option<Spanned<RawExpectation>>,
    pub angular_momentum_com: Option<Spanned<RawExpectation>>,
    pub kinetic_energy_translational: Option<Spanned<RawExpectation>>,
    pub kinetic_energy_rotational: Option<Spanned<RawExpectation>>,
    pub ixx: Option<Spanned<RawExpectation>>,
    pub iyy: Option<Spanned<RawExpectation>>,
    pub izz: Option<Spanned<RawExpectation>>,
    pub ixy: Option<Spanned<RawExpectation>>,
    pub ixz: Option<Spanned<RawExpectation>>,
    pub iyz: Option<Spanned<RawExpectation>>,
}

impl RawExpect {
    /// The entry of quantity `q`, if the file gives it.
    pub fn entry(&self, q: crate::quantity::Quantity) -> Option<&Spanned<RawExpectation>> {
        use crate::quantity::Quantity as Q;
        match q {
            Q::Mass => &self.mass,
            Q::CenterOfMass => &self.center_of_mass,
            Q::PrincipalMoments => &self.principal_moments,
            Q::InertiaCom => &self.inertia_com,
            Q::InertiaRef => &self.inertia_ref,
            Q::RadiiOfGyration => &self.radii_of_gyration,
            Q::RadiiOfGyrationAxes => &self.radii_of_gyration_axes,
            Q::AngularMomentum => &self.angular_momentum,
            Q::KineticEnergy => &self.kinetic_energy,
            Q::PredictedMass => &self.predicted_mass,
            Q::PredictedCenterOfMass => &self.predicted_center_of_mass,
            Q::PredictedInertiaCom => &self.predicted_inertia_com,
            Q::PrincipalAxes => &self.principal_axes,
            Q::VelocityCom => &self.velocity_com,
            Q::LinearMomentum => &self.linear_momentum,
            Q::AngularMomentumCom => &self.angular_momentum_com,
            Q::KineticEnergyTranslational => &self.kinetic_energy_translational,
            Q::KineticEnergyRotational => &self.kinetic_energy_rotational,
            // Reported, not expected (`quantity::Info::expected`).
            Q::ReferencePoint
            | Q::CenterOfMassRef
            | Q::ReportAxes
            | Q::Omega
            | Q::Alpha
            | Q::EulerMoment
            | Q::Velocity
            | Q::PrincipalMomentsRef
            | Q::PrincipalAxesRef
            | Q::RadiiOfGyrationAxesRef => &None,
        }
        .as_ref()
    }

    /// The entries of `quantity::ALIASES` (`Ixx` …), in its order.
    pub fn aliases(&self) -> [Option<&Spanned<RawExpectation>>; 6] {
        [
            &self.ixx, &self.iyy, &self.izz, &self.ixy, &self.ixz, &self.iyz,
        ]
        .map(Option::as_ref)
    }
}

/// One expectation: `value` with `tol`, or `min` and/or `max`; or, for a
/// vector or matrix, expectations on its components (`center_of_mass.z`,
/// `inertia_com.xy`, `principal_moments.1`).
#[derive(Debug, Default)]
pub struct RawExpectation {
    pub value: Option<Spanned<ExpectValue>>,
    pub tol: Option<Spanned<Quantity>>,
    /// `principal_axes`'s tolerance: an angle in degrees, not negative.
    pub tol_degrees: Option<Spanned<Quantity>>,
    pub min: Option<Spanned<ExpectValue>>,
    pub max: Option<Spanned<ExpectValue>>,
    pub x: Option<Box<Spanned<RawExpectation>>>,
    pub y: Option<Box<Spanned<RawExpectation>>>,
    pub z: Option<Box<Spanned<RawExpectation>>>,
    pub xx: Option<Box<Spanned<RawExpectation>>>,
    pub yy: Option<Box<Spanned<RawExpectation>>>,
    pub zz: Option<Box<Spanned<RawExpectation>>>,
    pub xy: Option<Box<Spanned<RawExpectation>>>,
    pub xz: Option<Box<Spanned<RawExpectation>>>,
    pub yz: Option<Box<Spanned<RawExpectation>>>,
    pub c1: Option<Box<Spanned<RawExpectation>>>,
    pub c2: Option<Box<Spanned<RawExpectation>>>,
    pub c3: Option<Box<Spanned<RawExpectation>>>,
}

/// An expected value: a quantity, or an array (of arrays) of quantities.
#[derive(Debug, Clone, PartialEq)]
pub enum ExpectValue {
    One(Quantity),
    Many(Vec<ExpectValue>),
}
