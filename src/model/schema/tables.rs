//! The schema's tables besides `[[part]]` (`[units]`, `[analysis]` and
//! its `axes`, `rotation`, `array`, `mirror`, `[expect]` and its
//! expectations, `[materials]`, `[budget]`), each declared here, and the
//! values they and the parts share (a quantity, a plain number, an
//! expected value, the names and patterns the model checks a string
//! against), and the small builders of a schema the parent uses too (a
//! reference, an array, a table). `[expect]`'s keys and its expectations'
//! components come from the table of quantities (`crate::quantity`).

use crate::quantity::{ALIASES, ORDINALS, QUANTITIES, UPPER, XYZ};
use crate::shapes::SHAPES;
use crate::units;
use serde_json::{Map, Value, json};

/// Every definition but `Part`'s: the tables a file may hold besides its
/// parts, and the values they and the parts share.
pub(super) fn definitions() -> Map<String, Value> {
    let mut defs = Map::new();
    let mut def = |name: &str, v: Value| defs.insert(name.into(), v);
    def(
        "Units",
        table(
            None,
            json!({ "length": r("LengthUnit"), "mass": r("MassUnit") }),
            &[],
        ),
    );
    def(
        "Material",
        table(None, json!({ "density": r("Quantity") }), &["density"]),
    );
    def(
        "Budget",
        table(
            Some("`[budget]`."),
            json!({ "limit": doc(r("Quantity"), "The not-to-exceed limit of the predicted mass: a mass.") }),
            &["limit"],
        ),
    );
    def(
        "Envelope",
        table(
            Some("`[envelope]`."),
            json!({
                "axis": doc(json!({ "enum": ["x", "y", "z"] }), "The coordinate of the centre of mass, in the report axes, that the envelope bounds."),
                "points": doc(
                    json!({ "type": "array", "items": quantities(2), "minItems": 3, "maxItems": super::super::envelope::MAX_POINTS }),
                    "The polygon's corners in order, each `[coordinate, mass]`: numbers in the file's units, or quantities with units; a simple polygon of non-zero area.",
                ),
                "mac": table(
                    Some("The mean aerodynamic chord, to show the coordinate in % MAC."),
                    json!({
                        "leading_edge": doc(r("Quantity"), "Where the chord begins along `axis`: a length."),
                        "length": doc(r("Quantity"), "The chord's length: a positive length."),
                    }),
                    &["leading_edge", "length"],
                ),
                "sequences": doc(
                    array(array(json!({ "type": "string" }), None), None),
                    "Paths between cases that differ only in `params`, each parameter moving linearly, e.g. [[\"ramp\", \"landing\"]]: at least two case names each.",
                ),
            }),
            &["axis", "points"],
        ),
    );
    def(
        "Analysis",
        table(
            None,
            json!({
                "about": quantities(3),
                "omega": quantities(3),
                "alpha": quantities(3),
                "velocity": doc(quantities(3), "The reference point's velocity in the report axes: numbers in the file's length unit per second, or quantities such as \"3 m/s\"; needs `omega`."),
                "axles": r("Axles"),
                "g": doc(r("Quantity"), "The acceleration of gravity for the axle loads: m/s² as a plain number, or a quantity such as \"9.81 m/s^2\"; default 9.80665."),
                "axes": r("Axes"),
                "warnings": doc(json!({ "type": "boolean" }), "A boolean (default `true`); `false` silences this file's plausibility warnings (a body over 100 m or 100 t without `units`, a density outside 1–25,000 kg/m³)."),
            }),
            &[],
        ),
    );
    def(
        "Axles",
        table(
            Some(
                "`[analysis] axles`: two axles along a report axis; a third is statically indeterminate without suspension data.",
            ),
            json!({
                "axis": { "enum": ["x", "y", "z"] },
                "front": doc(r("Quantity"), "The front axle's position along `axis`: a length."),
                "rear": doc(r("Quantity"), "The rear axle's position along `axis`: a length, not the front's."),
            }),
            &["axis", "front", "rear"],
        ),
    );
    let mut axes = json!({ "x": floats(3), "y": floats(3) });
    let rotation = rotation_keys();
    for (k, v) in rotation.as_object().expect("invariant: an object") {
        axes[k] = v.clone();
    }
    def(
        "Axes",
        table(
            Some(
                "`[analysis] axes`: the report axes' x and y directions in the file's\nframe, or a rotation of the file's axes in any form a part's `rotation`\ntakes (the same keys; `model::rotation` reads them).",
            ),
            axes,
            &[],
        ),
    );
    def("Rotation", table(None, rotation, &[]));
    def("Array", array_table());
    def(
        "Mirror",
        table(
            Some(
                "`mirror = { normal = [x, y, z], origin = [x, y, z] }`: the part and its\nmirror image in the plane through `origin` normal to `normal`.",
            ),
            json!({
                "normal": doc(floats(3), "The plane's normal (a direction, any non-zero length)."),
                "origin": doc(quantities(3), "A point of the plane (lengths); [0, 0, 0] if not given."),
            }),
            &["normal"],
        ),
    );
    def("Expect", expect_table());
    def("Expectation", expectation_table());
    def("Quantity", quantity());
    def("PlainNumber", plain_number());
    def("ExpectValue", expect_value());
    def(
        "Angles",
        json!({
            "description": "an angle in degrees (with `axis`), or three (with `intrinsic` or `extrinsic`)",
            "anyOf": [{ "type": "number" }, floats(3)],
        }),
    );
    def(
        "ShapeName",
        json!({
            "description": "the primitive (or leave it out and give `include`)",
            "enum": SHAPES.iter().map(|s| s.name).collect::<Vec<_>>(),
        }),
    );
    def(
        "LengthUnit",
        json!({ "description": "the unit of plain lengths", "enum": units::LENGTH_UNITS }),
    );
    def(
        "MassUnit",
        json!({ "description": "the unit of plain masses", "enum": units::MASS_UNITS }),
    );
    def(
        "MeshMode",
        json!({
            "description": "what a mesh weighs: \"solid\" (the volume it encloses, the default) or \"shell\" (its surface as a thin sheet)",
            "enum": ["solid", "shell"],
        }),
    );
    // `[growth]`'s values (`model::budget::percentage`).
    def(
        "Percentage",
        json!({
            "description": "a mass growth allowance as a percentage, such as \"15 %\"",
            "type": "string",
            "pattern": "^\\s*[+]?(?:[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][+-]?[0-9]+)?\\s*%\\s*$",
        }),
    );
    // `group`: names joined by `/`, none empty (`model::budget::group_path`).
    def(
        "GroupPath",
        json!({
            "description": "the part's group: names joined by `/`, such as \"propulsion/tanks\"",
            "type": "string",
            "pattern": "^[^/]*[^/\\s][^/]*(?:/[^/]*[^/\\s][^/]*)*$",
        }),
    );
    // A part's `tol`: a given mass's tolerance (`model::tolerance`).
    def(
        "TolAmount",
        json!({
            "description": "the tolerance of `mass`: a number in the file's mass unit, or \"0.1 kg\", \"3 %\", \"± 0.1 kg uniform\" (one standard deviation of a normal, or `uniform` within ± the amount)",
            "anyOf": [
                { "type": "number", "minimum": 0 },
                { "type": "string", "pattern": "^\\s*(?:±|\\+/-)?\\s*[^±\\s][^±]*$" },
            ],
        }),
    );
    def(
        "Products",
        json!({
            "description": "the sign of `inertia`'s products: \"tensor\" (−∫xy dm, the default) or \"positive\" (+∫xy dm, as CAD reports them)",
            "enum": super::super::place::PRODUCTS,
        }),
    );
    def(
        "MaterialName",
        json!({
            "description": format!(
                "a material of the file's [materials], or a built-in one: {}",
                crate::materials::BUILT_IN.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
            ),
            "type": "string",
        }),
    );
    // `intrinsic`, `extrinsic`: the sequences `rotation::parse_sequence`
    // reads, either case.
    def(
        "EulerAxes",
        json!({
            "description": "an Euler sequence: three axes, no axis twice in a row, such as \"zyx\" or \"zxz\"",
            "type": "string",
            "pattern": euler_pattern(),
        }),
    );
    // An expectation's `tol`: a quantity, or a percentage.
    def(
        "Tolerance",
        json!({
            "description": "a tolerance: a number in the file's units, a quantity string such as \"10 g\", or a percentage such as \"0.5%\"",
            "anyOf": [
                { "type": "number" },
                quantity_string(),
                expression_string(),
                // `tolerance`: the text before its trailing `%`s is an f64.
                { "type": "string", "pattern": "^\\s*[+-]?(?:[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][+-]?[0-9]+)?\\s*%+\\s*$" },
            ],
        }),
    );
    defs
}

/// A rotation's keys (`model::rotation`), which `[analysis] axes` takes
/// too.
fn rotation_keys() -> Value {
    json!({
        "quaternion": floats(4),
        "axis": floats(3),
        "degrees": r("Angles"),
        "matrix": array(floats(3), Some(3)),
        "intrinsic": r("EulerAxes"),
        "extrinsic": r("EulerAxes"),
    })
}

/// `array`: along a step or about an axis (`model::copies`), not both.
fn array_table() -> Value {
    let mut t = table(
        Some(
            "`array = { count = N, step = [dx, dy, dz] }`, or `{ count = N, axis =\n[x, y, z], step_degrees = θ, origin = [x, y, z] }`: N copies of a part,\ncopy i moved by i·step, or turned by i·θ about the axis through\n`origin`.",
        ),
        json!({
            "count": doc(r("PlainNumber"), "How many copies, the part itself the first: a positive integer."),
            "step": doc(quantities(3), "A linear array: the step from each copy to the next (lengths)."),
            "axis": doc(floats(3), "A polar array: the axis the copies turn about (a direction, any\nnon-zero length)."),
            "step_degrees": doc(r("PlainNumber"), "A polar array: the turn from each copy to the next, in degrees."),
            "origin": doc(quantities(3), "A polar array: a point of the axis (lengths); [0, 0, 0] if not given."),
        }),
        &["count"],
    );
    t["oneOf"] = json!([
        {
            "required": ["step"],
            "not": { "anyOf": each_required(&["axis", "step_degrees", "origin"]) },
        },
        {
            "required": ["axis", "step_degrees"],
            "not": { "required": ["step"] },
        },
    ]);
    t
}

/// What `[expect]` notes of a key, beyond its name.
const EXPECT_NOTES: [(&str, &str); 2] = [
    (
        "predicted_mass",
        "The predicted body's (basic mass and growth: `massprop budget`).",
    ),
    (
        "principal_axes",
        "Three unit rows, compared by angle (`tol_degrees`).",
    ),
];

/// `[expect]`: the quantities `[expect]` takes (`quantity::Info::expected`)
/// and the tensor's entries by name (`quantity::ALIASES`).
fn expect_table() -> Value {
    let mut props = Map::new();
    let keys = QUANTITIES.iter().filter(|q| q.expected).map(|q| q.key);
    for key in keys.chain(ALIASES.iter().map(|a| a.0)) {
        let mut v = r("Expectation");
        if let Some((_, note)) = EXPECT_NOTES.iter().find(|(k, _)| *k == key) {
            v = doc(v, note);
        }
        props.insert(key.into(), v);
    }
    table(
        Some("`[expect]`: the quantities a check compares, each optional."),
        Value::Object(props),
        &[],
    )
}

/// One expectation, or expectations on a vector's or matrix's components
/// (`quantity::XYZ`, `UPPER`, `ORDINALS`).
fn expectation_table() -> Value {
    let mut props = json!({
        "value": r("ExpectValue"),
        "tol": r("Tolerance"),
        "tol_degrees": doc(json!({ "type": "number" }), "`principal_axes`'s tolerance: an angle in degrees, not negative."),
        "min": r("ExpectValue"),
        "max": r("ExpectValue"),
    });
    let components = XYZ
        .iter()
        .chain(UPPER.iter().map(|u| &u.0))
        .chain(&ORDINALS);
    for c in components {
        props[*c] = r("Expectation");
    }
    table(
        Some(
            "One expectation: `value` with `tol`, or `min` and/or `max`; or, for a\nvector or matrix, expectations on its components (`center_of_mass.z`,\n`inertia_com.xy`, `principal_moments.1`).",
        ),
        props,
        &[],
    )
}

/// A quantity: a number in the file's units, or a string with its own
/// unit, an expression, or either with a tolerance.
fn quantity() -> Value {
    let symbols: Vec<&str> = units::symbol_names().collect();
    json!({
        "description": format!(
            "a number in the file's units, or a string with its own unit such as \"3 mm\", \"7.85 g/cm^3\" or \"3000 rpm\", or an expression over `[params]`, numbers and units such as \"2 * leg + 5 mm\" or \"pi * d^2 / 4\"; units: {}",
            symbols.join(", ")
        ),
        "anyOf": [{ "type": "number" }, quantity_string(), expression_string(), toleranced_string()],
    })
}

/// An expected value: a quantity, or an array (of arrays) of them.
fn expect_value() -> Value {
    json!({
        "description": "a quantity (a number, a string with its unit, an expression), or an array (of arrays) of them for a vector or matrix",
        "anyOf": [
            { "type": "number" },
            quantity_string(),
            expression_string(),
            { "type": "array", "items": r("ExpectValue") },
        ],
    })
}

/// A quantity: a number in the file's units, or a string with its unit.
fn quantity_string() -> Value {
    json!({ "type": "string", "pattern": units::quantity_pattern() })
}

/// An expression (`expr`): its names are the file's parameters, which a
/// schema of every part file cannot know, so only its shape is checked
/// here (an operator — `·` is `*` — or a parenthesis in it, or a name
/// alone: letters of any script, digits, `_`, `²`, `³`); the reader
/// judges the rest, with located errors.
fn expression_string() -> Value {
    json!({
        "type": "string",
        "description": "an expression: + - * / ^, parentheses, numbers with units, the file's `[params]`, pi, sqrt, sin, cos, tan, abs, min, max",
        "pattern": "^[^%\"\\\\]*[-+*/^(),\u{b7}][^%\"\\\\]*$|^\\s*[A-Za-z_\\u0080-\\uFFFF][A-Za-z0-9_\\u0080-\\uFFFF]*\\s*$",
    })
}

/// A number written as a string without a unit (`"32"`, `" 1e3 "`): the
/// number `units::split_number` reads (digits, `.` and `_`, an exponent),
/// with blanks around it.
fn number_string() -> Value {
    json!({
        "type": "string",
        "pattern": "^\\s*[+-]?(?:[0-9_]*[0-9][0-9_]*(?:\\.[0-9_]*)?|[0-9_]*\\.[0-9_]*[0-9][0-9_]*)(?:[eE][+-]?[0-9]+)?\\s*$",
    })
}

/// What a plain-number key takes (an array's `count` and `step_degrees`,
/// a parameter): a quantity in any of its forms, or a number written as a
/// string without a unit (`count = "32"`), which the reader takes where
/// the number has no dimension.
fn plain_number() -> Value {
    json!({
        "description": "a number, or a string giving one: \"32\", \"n / 2\", a parameter's name",
        "anyOf": [{ "$ref": "#/$defs/Quantity" }, number_string()],
    })
}

/// A value with a tolerance (`model::tolerance`): a quantity or an
/// expression, `±` or `+/-`, an amount or a percentage, maybe `uniform`
/// or `normal`. Where a tolerance may stand is the reader's to judge.
fn toleranced_string() -> Value {
    json!({
        "type": "string",
        "description": "a value with a tolerance: \"700 mm ± 0.5 mm\", \"7850 kg/m^3 ± 2 %\", \"10 mm +/- 1 mm uniform\" (one standard deviation of a normal, or `uniform` within ± the amount)",
        "pattern": "^[^±%\"\\\\]*[^±%\"\\\\\\s][^±%\"\\\\]*(?:±|\\+/-)\\s*[^±\\s][^±]*$",
    })
}

/// Every sequence of three axes `parse_sequence` takes, either case.
pub(super) fn euler_pattern() -> String {
    let class = |c: char| format!("[{c}{}]", c.to_ascii_uppercase());
    let mut seqs = Vec::new();
    for a in ['x', 'y', 'z'] {
        for b in ['x', 'y', 'z'] {
            for c in ['x', 'y', 'z'] {
                if super::super::rotation::parse_sequence(&format!("{a}{b}{c}")).is_some() {
                    seqs.push(format!("{}{}{}", class(a), class(b), class(c)));
                }
            }
        }
    }
    format!("^(?:{})$", seqs.join("|"))
}

/// `{"$ref": "#/$defs/NAME"}`.
pub(super) fn r(name: &str) -> Value {
    json!({ "$ref": format!("#/$defs/{name}") })
}

/// `v` with `description`.
pub(super) fn doc(mut v: Value, description: &str) -> Value {
    v["description"] = description.into();
    v
}

/// An array of `items`, exactly `n` of them if given.
pub(super) fn array(items: Value, n: Option<usize>) -> Value {
    match n {
        Some(n) => json!({ "type": "array", "items": items, "minItems": n, "maxItems": n }),
        None => json!({ "type": "array", "items": items }),
    }
}

/// `n` plain numbers (a direction, a quaternion: no unit).
pub(super) fn floats(n: usize) -> Value {
    array(json!({ "type": "number" }), Some(n))
}

/// `n` quantities (a point, a step).
pub(super) fn quantities(n: usize) -> Value {
    array(r("Quantity"), Some(n))
}

/// A table of names to `values`.
pub(super) fn map_of(values: Value, description: &str) -> Value {
    json!({ "type": "object", "additionalProperties": values, "description": description })
}

/// A table of `props` (no other key), the `required` among them.
pub(super) fn table(description: Option<&str>, props: Value, required: &[&str]) -> Value {
    let mut t = json!({ "type": "object", "additionalProperties": false, "properties": props });
    if let Some(d) = description {
        t["description"] = d.into();
    }
    if !required.is_empty() {
        t["required"] = json!(required);
    }
    t
}

/// `{"required": [key]}` for each key: with `oneOf`, exactly one of them;
/// with `anyOf`, at least one.
pub(super) fn each_required(keys: &[&str]) -> Value {
    keys.iter().map(|k| json!({ "required": [k] })).collect()
}
