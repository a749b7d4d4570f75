//! The file's own tables as the reader converts them: `units`,
//! `[analysis]`, `[expect]`, `[materials]`, `[params]`, `[growth]`,
//! `[budget]`, from the tree of `Node`s it built of them (they are small;
//! the parts are converted one at a time as each ends, `fast`).

use super::super::raw::{
    ExpectValue, Growth, Materials, Params, RawAnalysis, RawAxes, RawBudget, RawExpect,
    RawExpectation, RawMaterial, RawRotation, RawUnits,
};
use super::values::{
    Entry, FromNode, Node, quantity, rotation_key, set, string, table, units_key, vector,
};
use toml::Spanned;

/// `units = { .. }` or `[units]`.
pub(super) fn units(node: Node<'_>) -> Option<Spanned<RawUnits>> {
    let (entries, span) = table(node)?;
    let mut u = RawUnits::default();
    for (k, _, v) in entries {
        units_key(&mut u, &k, v)?;
    }
    Some(Spanned::new(span, u))
}

/// `[analysis]`.
pub(super) fn analysis(node: Node<'_>) -> Option<Spanned<RawAnalysis>> {
    let (entries, span) = table(node)?;
    let mut a = RawAnalysis::default();
    for (k, _, v) in entries {
        match &*k {
            "about" => set(&mut a.about, vector(v)?),
            "omega" => set(&mut a.omega, vector(v)?),
            "alpha" => set(&mut a.alpha, vector(v)?),
            "axes" => set(&mut a.axes, axes(v)?),
            "warnings" => match v {
                Node::Bool(b, _) => set(&mut a.warnings, b),
                _ => None,
            },
            _ => None,
        }?;
    }
    Some(Spanned::new(span, a))
}

/// `[analysis] axes`: `x` and `y`, or a rotation's keys.
fn axes(node: Node<'_>) -> Option<Spanned<RawAxes>> {
    let (entries, span) = table(node)?;
    let mut a = RawAxes::default();
    let mut r = RawRotation::default();
    for (k, _, v) in entries {
        match &*k {
            "x" => set(&mut a.x, super::values::floats(v)?),
            "y" => set(&mut a.y, super::values::floats(v)?),
            _ => rotation_key(&mut r, &k, v),
        }?;
    }
    let RawRotation {
        quaternion,
        axis,
        degrees,
        matrix,
        intrinsic,
        extrinsic,
    } = r;
    a.quaternion = quaternion;
    a.axis = axis;
    a.degrees = degrees;
    a.matrix = matrix;
    a.intrinsic = intrinsic;
    a.extrinsic = extrinsic;
    Some(Spanned::new(span, a))
}

/// `[params]`.
pub(super) fn params(node: Node<'_>) -> Option<Params> {
    Params::from_node(node)
}

/// `[growth]`: the same form as `[params]`.
pub(super) fn growth(node: Node<'_>) -> Option<Growth> {
    Params::from_node(node)
}

/// `[budget]`: `limit`, required.
pub(super) fn budget(node: Node<'_>) -> Option<Spanned<RawBudget>> {
    let (entries, span) = table(node)?;
    let mut limit = None;
    for (k, _, v) in entries {
        match &*k {
            "limit" => set(&mut limit, quantity(v)?),
            _ => None,
        }?;
    }
    Some(Spanned::new(span, RawBudget { limit: limit? }))
}

/// `[materials]`: name → `{ density }`, required.
pub(super) fn materials(node: Node<'_>) -> Option<Materials> {
    let (entries, span) = table(node)?;
    let map = entries
        .into_iter()
        .map(|(k, _, v)| Some((k.into_owned(), material(v)?)))
        .collect::<Option<_>>()?;
    Some(Spanned::new(span, map))
}

fn material(node: Node<'_>) -> Option<Spanned<RawMaterial>> {
    let (entries, span) = table(node)?;
    let mut density = None;
    for (k, _, v) in entries {
        match &*k {
            "density" => set(&mut density, quantity(v)?),
            _ => None,
        }?;
    }
    Some(Spanned::new(span, RawMaterial { density: density? }))
}

/// `[expect]`.
pub(super) fn expect(node: Node<'_>) -> Option<Spanned<RawExpect>> {
    let (entries, span) = table(node)?;
    let mut e = RawExpect {
        mass: None,
        center_of_mass: None,
        principal_moments: None,
        inertia_com: None,
        inertia_ref: None,
        radii_of_gyration: None,
        radii_of_gyration_axes: None,
        angular_momentum: None,
        kinetic_energy: None,
        predicted_mass: None,
        predicted_center_of_mass: None,
        predicted_inertia_com: None,
        principal_axes: None,
        ixx: None,
        iyy: None,
        izz: None,
        ixy: None,
        ixz: None,
        iyz: None,
    };
    for (k, _, v) in entries {
        let field = match &*k {
            "mass" => &mut e.mass,
            "center_of_mass" => &mut e.center_of_mass,
            "principal_moments" => &mut e.principal_moments,
            "inertia_com" => &mut e.inertia_com,
            "inertia_ref" => &mut e.inertia_ref,
            "radii_of_gyration" => &mut e.radii_of_gyration,
            "radii_of_gyration_axes" => &mut e.radii_of_gyration_axes,
            "angular_momentum" => &mut e.angular_momentum,
            "kinetic_energy" => &mut e.kinetic_energy,
            "predicted_mass" => &mut e.predicted_mass,
            "predicted_center_of_mass" => &mut e.predicted_center_of_mass,
            "predicted_inertia_com" => &mut e.predicted_inertia_com,
            "principal_axes" => &mut e.principal_axes,
            "Ixx" => &mut e.ixx,
            "Iyy" => &mut e.iyy,
            "Izz" => &mut e.izz,
            "Ixy" => &mut e.ixy,
            "Ixz" => &mut e.ixz,
            "Iyz" => &mut e.iyz,
            _ => return None,
        };
        set(field, expectation(v)?)?;
    }
    Some(Spanned::new(span, e))
}

/// One expectation, its components' expectations within it.
fn expectation(node: Node<'_>) -> Option<Spanned<RawExpectation>> {
    let (entries, span): (Vec<Entry<'_>>, _) = table(node)?;
    let mut e = RawExpectation::default();
    for (k, _, v) in entries {
        match &*k {
            "value" => set(&mut e.value, expect_value(v)?),
            "min" => set(&mut e.min, expect_value(v)?),
            "max" => set(&mut e.max, expect_value(v)?),
            "tol" => set(&mut e.tol, quantity(v)?),
            "tol_degrees" => set(&mut e.tol_degrees, quantity(v)?),
            key => {
                let field = match key {
                    "x" => &mut e.x,
                    "y" => &mut e.y,
                    "z" => &mut e.z,
                    "xx" => &mut e.xx,
                    "yy" => &mut e.yy,
                    "zz" => &mut e.zz,
                    "xy" => &mut e.xy,
                    "xz" => &mut e.xz,
                    "yz" => &mut e.yz,
                    "1" => &mut e.c1,
                    "2" => &mut e.c2,
                    "3" => &mut e.c3,
                    _ => return None,
                };
                set(field, Box::new(expectation(v)?))
            }
        }?;
    }
    Some(Spanned::new(span, e))
}

/// An expected value: a quantity, or an array (of arrays) of them.
fn expect_value(node: Node<'_>) -> Option<Spanned<ExpectValue>> {
    fn inner(node: Node<'_>) -> Option<ExpectValue> {
        match node {
            Node::Array(items, _) => Some(ExpectValue::Many(
                items.into_iter().map(inner).collect::<Option<_>>()?,
            )),
            other => Some(ExpectValue::One(quantity(other)?.into_inner())),
        }
    }
    let span = node.span();
    Some(Spanned::new(span, inner(node)?))
}

/// `name`.
pub(super) fn name(node: Node<'_>) -> Option<Spanned<String>> {
    string(node)
}
