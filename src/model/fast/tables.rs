//! The file's own tables as the reader converts them: `units`,
//! `[analysis]`, `[expect]`, `[materials]`, `[params]`, `[growth]`,
//! `[budget]`, from the tree of `Node`s it built of them (they are small;
//! the parts are converted one at a time as each ends, `fast`).

use super::super::raw::{
    ExpectValue, Growth, Materials, Params, RawAnalysis, RawAxes, RawAxles, RawBudget, RawEnvelope,
    RawExpect, RawExpectation, RawMac, RawMaterial, RawRotation, RawUnits,
};
use super::failure::{Failure, Read, What};
use super::values::{
    Entry, FromNode, Node, array_of, keyed, quantity, rotation_key, set, string, table, units_key,
    unknown, vector,
};
use toml::Spanned;

/// `units = { .. }` or `[units]`.
pub(super) fn units(node: Node<'_>) -> Read<Spanned<RawUnits>> {
    let (entries, span) = table(node, "a table such as { length = \"mm\", mass = \"kg\" }")?;
    let mut u = RawUnits::default();
    for (k, ks, v) in entries {
        units_key(&mut u, &k, &ks, v)?;
    }
    Ok(Spanned::new(span, u))
}

/// `[analysis]`.
pub(super) fn analysis(node: Node<'_>) -> Read<Spanned<RawAnalysis>> {
    const KEYS: &[&str] = &[
        "about", "omega", "alpha", "velocity", "axles", "g", "axes", "warnings",
    ];
    let (entries, span) = table(
        node,
        "a table with `about`, `omega`, `alpha`, `velocity`, `axles`, `g`, `axes` or `warnings`",
    )?;
    let mut a = RawAnalysis::default();
    for (k, ks, v) in entries {
        match &*k {
            "about" => set(&mut a.about, keyed(&k, vector(v))?, &ks),
            "omega" => set(&mut a.omega, keyed(&k, vector(v))?, &ks),
            "alpha" => set(&mut a.alpha, keyed(&k, vector(v))?, &ks),
            "velocity" => set(&mut a.velocity, keyed(&k, vector(v))?, &ks),
            "axles" => set(&mut a.axles, keyed(&k, axles(v))?, &ks),
            "g" => set(&mut a.g, keyed(&k, quantity(v))?, &ks),
            "axes" => set(&mut a.axes, keyed(&k, axes(v))?, &ks),
            "warnings" => {
                let b = keyed(&k, toml::Spanned::<bool>::from_node(v))?;
                set(&mut a.warnings, b.into_inner(), &ks)
            }
            _ => unknown(&k, &ks, KEYS),
        }?;
    }
    Ok(Spanned::new(span, a))
}

/// `[analysis] axles`: `axis`, `front` and `rear`, and no other key: a
/// third axle is refused with the reason.
fn axles(node: Node<'_>) -> Read<Spanned<RawAxles>> {
    let (entries, span) = table(
        node,
        "a table such as { axis = \"x\", front = \"1.35 m\", rear = \"-1.25 m\" }",
    )?;
    let mut a = RawAxles::default();
    for (k, ks, v) in entries {
        match &*k {
            "axis" => set(&mut a.axis, keyed(&k, string(v))?, &ks),
            "front" => set(&mut a.front, keyed(&k, quantity(v))?, &ks),
            "rear" => set(&mut a.rear, keyed(&k, quantity(v))?, &ks),
            _ => Err(Failure::new(
                ks,
                What::Other(format!(
                    "`axles` takes `axis`, `front` and `rear` only, not `{k}`: more than two axles are statically indeterminate without suspension data"
                )),
            )),
        }?;
    }
    Ok(Spanned::new(span, a))
}

/// `[analysis] axes`: `x` and `y`, or a rotation's keys.
fn axes(node: Node<'_>) -> Read<Spanned<RawAxes>> {
    const KEYS: &[&str] = super::values::AXES_KEYS;
    let (entries, span) = table(
        node,
        "a table such as { x = [1, 0, 0], y = [0, -1, 0] } or a rotation such as { axis = [0, 0, 1], degrees = 90 }",
    )?;
    let mut a = RawAxes::default();
    let mut r = RawRotation::default();
    for (k, ks, v) in entries {
        match &*k {
            "x" => set(&mut a.x, keyed(&k, super::values::floats(v))?, &ks)?,
            "y" => set(&mut a.y, keyed(&k, super::values::floats(v))?, &ks)?,
            _ => {
                if !rotation_key(&mut r, &k, &ks, v)? {
                    return unknown(&k, &ks, KEYS);
                }
            }
        }
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
    Ok(Spanned::new(span, a))
}

/// `[params]`.
pub(super) fn params(node: Node<'_>) -> Read<Params> {
    Params::from_node(node)
}

/// `[growth]`: the same form as `[params]`.
pub(super) fn growth(node: Node<'_>) -> Read<Growth> {
    Params::from_node(node)
}

/// `[budget]`: `limit`, required.
pub(super) fn budget(node: Node<'_>) -> Read<Spanned<RawBudget>> {
    let (entries, span) = table(node, "a table such as { limit = \"120 kg\" }")?;
    let mut limit = None;
    for (k, ks, v) in entries {
        match &*k {
            "limit" => set(&mut limit, keyed(&k, quantity(v))?, &ks),
            _ => unknown(&k, &ks, &["limit"]),
        }?;
    }
    let limit = limit.ok_or_else(|| Failure::new(span.clone(), What::Missing("limit")))?;
    Ok(Spanned::new(span, RawBudget { limit }))
}

/// `[envelope]`: `axis`, `points`, `mac`, `sequences` (checked in
/// `model::envelope`).
pub(super) fn envelope(node: Node<'_>) -> Read<Spanned<RawEnvelope>> {
    const KEYS: &[&str] = &["axis", "points", "mac", "sequences"];
    let (entries, span) = table(
        node,
        "a table such as { axis = \"x\", points = [[2.0, 600], [2.4, 600], [2.4, 1100], [2.1, 1100]] }",
    )?;
    let mut e = RawEnvelope::default();
    for (k, ks, v) in entries {
        match &*k {
            "axis" => set(&mut e.axis, keyed(&k, string(v))?, &ks),
            "points" => set(&mut e.points, keyed(&k, array_of(v, vector))?, &ks),
            "mac" => set(&mut e.mac, keyed(&k, mac(v))?, &ks),
            "sequences" => set(&mut e.sequences, keyed(&k, array_of(v, names))?, &ks),
            _ => unknown(&k, &ks, KEYS),
        }?;
    }
    Ok(Spanned::new(span, e))
}

/// One sequence: an array of case names.
fn names(node: Node<'_>) -> Read<Spanned<Vec<Spanned<String>>>> {
    array_of(node, string)
}

/// `[envelope] mac`: `leading_edge` and `length`.
fn mac(node: Node<'_>) -> Read<Spanned<RawMac>> {
    let (entries, span) = table(
        node,
        "a table such as { leading_edge = \"2.05 m\", length = \"1.5 m\" }",
    )?;
    let mut m = RawMac::default();
    for (k, ks, v) in entries {
        match &*k {
            "leading_edge" => set(&mut m.leading_edge, keyed(&k, quantity(v))?, &ks),
            "length" => set(&mut m.length, keyed(&k, quantity(v))?, &ks),
            _ => unknown(&k, &ks, &["leading_edge", "length"]),
        }?;
    }
    Ok(Spanned::new(span, m))
}

/// `[materials]`: name → `{ density }`, required.
pub(super) fn materials(node: Node<'_>) -> Read<Materials> {
    let (entries, span) = table(
        node,
        "a table of materials such as { foam = { density = \"30 kg/m^3\" } }",
    )?;
    let map = entries
        .into_iter()
        .map(|(k, _, v)| Ok((k.to_string(), keyed(&k, material(v))?)))
        .collect::<Read<_>>()?;
    Ok(Spanned::new(span, map))
}

fn material(node: Node<'_>) -> Read<Spanned<RawMaterial>> {
    let (entries, span) = table(node, "a table such as { density = \"30 kg/m^3\" }")?;
    let mut density = None;
    for (k, ks, v) in entries {
        match &*k {
            "density" => set(&mut density, keyed(&k, quantity(v))?, &ks),
            _ => unknown(&k, &ks, &["density"]),
        }?;
    }
    let density = density.ok_or_else(|| Failure::new(span.clone(), What::Missing("density")))?;
    Ok(Spanned::new(span, RawMaterial { density }))
}

/// `[expect]`'s keys: the expected quantities (`quantity::QUANTITIES`
/// rows that are expected) and the aliases (`quantity::ALIASES`), in
/// their order (held to them by a test).
pub(in crate::model) const EXPECT_KEYS: &[&str] = &[
    "mass",
    "center_of_mass",
    "principal_moments",
    "inertia_com",
    "inertia_ref",
    "radii_of_gyration",
    "radii_of_gyration_axes",
    "angular_momentum",
    "kinetic_energy",
    "predicted_mass",
    "predicted_center_of_mass",
    "predicted_inertia_com",
    "principal_axes",
    "velocity_com",
    "linear_momentum",
    "angular_momentum_com",
    "kinetic_energy_translational",
    "kinetic_energy_rotational",
    "Ixx",
    "Iyy",
    "Izz",
    "Ixy",
    "Ixz",
    "Iyz",
];

/// `[expect]`.
pub(super) fn expect(node: Node<'_>) -> Read<Spanned<RawExpect>> {
    let (entries, span) = table(node, "a table of expected quantities")?;
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
        velocity_com: None,
        linear_momentum: None,
        angular_momentum_com: None,
        kinetic_energy_translational: None,
        kinetic_energy_rotational: None,
        ixx: None,
        iyy: None,
        izz: None,
        ixy: None,
        ixz: None,
        iyz: None,
    };
    for (k, ks, v) in entries {
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
            "velocity_com" => &mut e.velocity_com,
            "linear_momentum" => &mut e.linear_momentum,
            "angular_momentum_com" => &mut e.angular_momentum_com,
            "kinetic_energy_translational" => &mut e.kinetic_energy_translational,
            "kinetic_energy_rotational" => &mut e.kinetic_energy_rotational,
            "Ixx" => &mut e.ixx,
            "Iyy" => &mut e.iyy,
            "Izz" => &mut e.izz,
            "Ixy" => &mut e.ixy,
            "Ixz" => &mut e.ixz,
            "Iyz" => &mut e.iyz,
            _ => return unknown(&k, &ks, EXPECT_KEYS),
        };
        set(field, keyed(&k, expectation(v))?, &ks)?;
    }
    Ok(Spanned::new(span, e))
}

/// One expectation, its components' expectations within it.
fn expectation(node: Node<'_>) -> Read<Spanned<RawExpectation>> {
    const KEYS: &[&str] = &[
        "value",
        "tol",
        "tol_degrees",
        "min",
        "max",
        "x",
        "y",
        "z",
        "xx",
        "yy",
        "zz",
        "xy",
        "xz",
        "yz",
        "1",
        "2",
        "3",
    ];
    let (entries, span): (Vec<Entry<'_>>, _) = table(
        node,
        "an expectation such as { value = 1.2, tol = \"0.5%\" } or { max = \"2 kg\" }",
    )?;
    let mut e = RawExpectation::default();
    for (k, ks, v) in entries {
        match &*k {
            "value" => set(&mut e.value, keyed(&k, expect_value(v))?, &ks),
            "min" => set(&mut e.min, keyed(&k, expect_value(v))?, &ks),
            "max" => set(&mut e.max, keyed(&k, expect_value(v))?, &ks),
            "tol" => set(&mut e.tol, keyed(&k, quantity(v))?, &ks),
            "tol_degrees" => set(&mut e.tol_degrees, keyed(&k, quantity(v))?, &ks),
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
                    _ => return unknown(&k, &ks, KEYS),
                };
                set(field, Box::new(keyed(&k, expectation(v))?), &ks)
            }
        }?;
    }
    Ok(Spanned::new(span, e))
}

/// An expected value: a quantity, or an array (of arrays) of them.
fn expect_value(node: Node<'_>) -> Read<Spanned<ExpectValue>> {
    const EXPECTING: &str = "a number, a string with a unit, or an array of them";
    fn inner(node: Node<'_>) -> Read<ExpectValue> {
        match node {
            Node::Array(items, _) => Ok(ExpectValue::Many(
                items
                    .into_iter()
                    .map(|n| inner(n).map_err(Failure::in_array))
                    .collect::<Read<_>>()?,
            )),
            Node::Num(..) | Node::Str(..) => Ok(ExpectValue::One(quantity(node)?.into_inner())),
            other => super::values::wrong(&other, EXPECTING),
        }
    }
    let span = node.span();
    Ok(Spanned::new(span, inner(node)?))
}

/// `name`.
pub(super) fn name(node: Node<'_>) -> Read<Spanned<String>> {
    string(node)
}
