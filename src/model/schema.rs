//! The part file's JSON Schema (draft 2020-12; `massprop schema`), for
//! editors: Taplo and Even Better TOML complete and check a part file that
//! names it in a `#:schema` comment (docs/part-file.md).
//!
//! Nothing here lists keys of its own. The tables, their keys and their
//! types come from the reader's serde mirror (`raw`, deriving
//! `JsonSchema`), so a key added there is in the schema, and a shape's
//! own keys from their declarations (`ShapeKind::OWN_KEYS`); which keys each
//! shape takes, which it needs and how many numbers its `size` and
//! `edges` hold come from the shape table (`shapes::SHAPES`); the units
//! and the quantity strings from `units`. The schema says less than the
//! model checks (ranges, perpendicular edges, a key's dimension): a file it
//! accepts may still be refused by `massprop check`, never the other way
//! round (tests/integration/schema.rs).
//!
//! Draft 2020-12 by its `$schema`, but in draft 7's keywords alone (with
//! `$defs`, which a draft-7 validator reaches by its JSON pointer): Taplo
//! 0.9, the engine of Even Better TOML, validates as draft 7 and skips any
//! keyword it does not know.

use super::raw::{Angles, ExpectValue, Quantity, RawFile};
use crate::shapes::{Dims, Key, Kind, MaterialRule, SHAPES, Spanned as Spans};
use crate::units;
use schemars::{JsonSchema, Schema, SchemaGenerator, json_schema};
use serde_json::{Map, Value, json};
use std::borrow::Cow;

/// The schema's `$id`: a name, not an address (no copy of it is served
/// anywhere; `massprop schema` prints it). It names version 1 of the part
/// file (docs/part-file.md) and changes only with the format.
pub const ID: &str = "urn:massprop:part-file:1";

/// The schema, pretty-printed, with a final newline.
pub fn text() -> String {
    let mut s =
        serde_json::to_string_pretty(&schema()).expect("invariant: a JSON value always serializes");
    s.push('\n');
    s
}

/// The JSON Schema of a part file.
pub fn schema() -> Value {
    let generator = schemars::generate::SchemaSettings::draft2020_12().into_generator();
    let mut root = generator.into_root_schema_for::<RawFile>().to_value();
    // TOML has no null: an absent key is the only `None`.
    without_nulls(&mut root);
    let obj = root
        .as_object_mut()
        .expect("invariant: a struct's schema is an object");
    obj.insert("$id".into(), ID.into());
    obj.insert("title".into(), "massprop part file".into());
    obj.insert(
        "description".into(),
        "A massprop part file, version 1: `massprop check FILE` checks it all (docs/part-file.md)."
            .into(),
    );
    obj.insert("required".into(), json!(["part"]));
    let props = &mut obj["properties"];
    props["part"]["minItems"] = 1.into();
    let part = obj
        .get_mut("$defs")
        .and_then(|d| d.get_mut("Part"))
        .and_then(Value::as_object_mut)
        .expect("invariant: `RawPart` is named `Part` in `$defs`");
    part.insert("allOf".into(), Value::Array(part_rules()));
    // A shape's own keys (`ShapeKind::OWN_KEYS`) are no field of the serde
    // mirror: each from its declaration.
    for s in &SHAPES {
        for key in s.shape.own_keys() {
            part["properties"][key.name] = own_key(key);
        }
    }
    // A plain number may be written as a string (`count = "32"`): a
    // count, an angle in degrees, a parameter.
    let defs = root
        .get_mut("$defs")
        .and_then(Value::as_object_mut)
        .expect("invariant: the schema has `$defs`");
    defs.insert("PlainNumber".into(), plain_number());
    for (def, key) in [("Array", "count"), ("Array", "step_degrees")] {
        defs[def]["properties"][key]["$ref"] = "#/$defs/PlainNumber".into();
    }
    defs["Part"]["properties"]["params"]["additionalProperties"] =
        json!({ "$ref": "#/$defs/PlainNumber" });
    root["properties"]["params"]["additionalProperties"] = json!({ "$ref": "#/$defs/PlainNumber" });
    // An array is along a step or about an axis (`model::copies`).
    if let Some(array) = root
        .get_mut("$defs")
        .and_then(|d| d.get_mut("Array"))
        .and_then(Value::as_object_mut)
    {
        array.insert(
            "oneOf".into(),
            json!([
                {
                    "required": ["step"],
                    "not": { "anyOf": each_required(&["axis", "step_degrees", "origin"]) },
                },
                {
                    "required": ["axis", "step_degrees"],
                    "not": { "required": ["step"] },
                },
            ]),
        );
    }
    root
}

/// The schema of a shape's own key, from its declaration: its kind, and
/// its one line of docs.
fn own_key(key: &Key) -> Value {
    let quantity = json!({ "$ref": "#/$defs/Quantity" });
    let array = |items: Value, n: Option<usize>| match n {
        Some(n) => json!({ "type": "array", "items": items, "minItems": n, "maxItems": n }),
        None => json!({ "type": "array", "items": items }),
    };
    let mut v = match key.kind {
        Kind::Quantity => quantity,
        Kind::Point => array(quantity, Some(3)),
        Kind::Quantities(n) => array(quantity, n),
        Kind::Rows { width, .. } => array(array(quantity, Some(width)), None),
        Kind::Str => json!({ "type": "string" }),
        Kind::Bool => json!({ "type": "boolean" }),
        Kind::Rotation => json!({ "$ref": "#/$defs/Rotation" }),
        Kind::ArrayTable => json!({ "$ref": "#/$defs/Array" }),
        Kind::MirrorTable => json!({ "$ref": "#/$defs/Mirror" }),
        Kind::ParamsTable => json!({
            "type": "object",
            "additionalProperties": { "$ref": "#/$defs/PlainNumber" },
        }),
    };
    v["description"] = key.doc.into();
    v
}

/// A part is a shape or an include; each shape's rules, from its entry in
/// `SHAPES`.
fn part_rules() -> Vec<Value> {
    let mut include_keys = vec!["name"];
    include_keys.extend(super::include::INCLUDE_KEYS);
    include_keys.extend(super::budget::TAG_KEYS);
    include_keys.extend(super::copies::COPY_KEYS);
    let mut rules = vec![json!({
        "if": { "required": ["include"] },
        "then": {
            "description": "a sub-assembly: another part file placed here",
            "propertyNames": { "enum": include_keys },
        },
        "else": { "required": ["shape"] },
    })];
    for s in &SHAPES {
        let mut keys = vec!["name", "shape"];
        keys.extend(s.keys);
        if super::tolerance::accepts(s.keys, super::tolerance::TOL_KEY) {
            keys.push(super::tolerance::TOL_KEY);
        }
        keys.extend(super::budget::TAG_KEYS);
        keys.extend(super::copies::COPY_KEYS);
        let mut then = Map::new();
        then.insert("description".into(), s.help.into());
        then.insert("propertyNames".into(), json!({ "enum": keys }));
        let mut counts = Map::new();
        if let Dims::Size(n) = s.dims {
            counts.insert("size".into(), json!({ "minItems": n, "maxItems": n }));
        }
        if let Some(Spans::CornerEdges(n)) = s.spanned {
            counts.insert("edges".into(), json!({ "minItems": n, "maxItems": n }));
        }
        if !counts.is_empty() {
            then.insert("properties".into(), Value::Object(counts));
        }
        let mut own = rules_of(s);
        // `tol` is the tolerance of a given mass.
        own.push(json!({
            "if": { "required": [super::tolerance::TOL_KEY] },
            "then": { "required": ["mass"] },
        }));
        then.insert("allOf".into(), Value::Array(own));
        rules.push(json!({
            "if": {
                "properties": { "shape": { "const": s.name } },
                "required": ["shape"],
            },
            "then": then,
        }));
    }
    rules
}

/// What a part of shape `s` needs, and what goes together.
///
/// NOTE: written with `if`/`then` (draft 7), not `dependentSchemas` and
/// `dependentRequired` (2019-09): Taplo 0.9 validates as draft 7 and
/// skips keywords it does not know, so those rules did not reach the
/// editor.
fn rules_of(s: &crate::shapes::ShapeInfo) -> Vec<Value> {
    if s.dims == Dims::Mesh {
        return mesh_rules();
    }
    let mut rules = vec![mass_rule(s), placement_rule(s)];
    // A material needs exactly one of the keys that turn its density into
    // the shape's (a thickness, a section); those that do nothing else
    // need the material (a plate's `thickness` and a rod's `diameter` are
    // real sizes too).
    let turning = super::material::material_keys(s.material);
    if !turning.is_empty() {
        rules.push(json!({
            "if": { "required": ["material"] },
            "then": { "oneOf": each_required(turning) },
        }));
    }
    for k in turning {
        if s.real_size.is_none_or(|(r, _)| r != *k) {
            rules.push(json!({
                "if": { "required": [k] },
                "then": { "required": ["material"] },
            }));
        }
    }
    rules
}

/// A mesh's (`model::mesh`): `file` and `mesh_unit`; a solid weighed by
/// exactly one of `mass`, `density` and `material`; a shell
/// (`mode = "shell"`) by `mass`, `areal_density`, or `thickness` with
/// exactly one of `density` and `material`.
fn mesh_rules() -> Vec<Value> {
    let only = |given: &[&str]| {
        let others: Vec<&str> = ["mass", "density", "areal_density", "material", "thickness"]
            .into_iter()
            .filter(|k| !given.contains(k))
            .collect();
        json!({ "required": given, "not": { "anyOf": each_required(&others) } })
    };
    vec![
        json!({ "required": ["file", "mesh_unit"] }),
        json!({
            "if": { "properties": { "mode": { "const": "shell" } }, "required": ["mode"] },
            "then": { "oneOf": [
                only(&["mass"]),
                only(&["areal_density"]),
                only(&["thickness", "density"]),
                only(&["thickness", "material"]),
            ] },
            "else": { "oneOf": [only(&["mass"]), only(&["density"]), only(&["material"])] },
        }),
    ]
}

/// Exactly one of `mass`, the shape's density and `material`.
fn mass_rule(s: &crate::shapes::ShapeInfo) -> Value {
    let mut one_of = vec!["mass"];
    one_of.extend(s.density.map(|d| d.key));
    if s.material != MaterialRule::None {
        one_of.push("material");
    }
    json!({ "oneOf": each_required(&one_of) })
}

/// `{"required": [key]}` for each key: with `oneOf`, exactly one of them;
/// with `anyOf`, at least one.
fn each_required(keys: &[&str]) -> Value {
    keys.iter().map(|k| json!({ "required": [k] })).collect()
}

/// The centred placement (its dimensions, and `center` where it has one),
/// or the spanned one (`corner` and `edges`, `from` and `to`), not both.
fn placement_rule(s: &crate::shapes::ShapeInfo) -> Value {
    // The inner radii may be left out: a solid. A radius may be given as
    // its diameter (not a rod's: that is its real size), one or the other.
    let by_diameter = s.keys.contains(&"diameter") && s.real_size.is_none();
    let mut centred: Vec<&str> = s
        .dims
        .keys()
        .iter()
        .copied()
        .filter(|k| {
            !matches!(
                *k,
                "inner_radius" | "top_inner_radius" | "inner_tube_radius"
            )
        })
        .filter(|k| !(by_diameter && *k == "radius"))
        .collect();
    // A shape's own keys: its module asks for each (`Reader::quantity`,
    // `quantities`), which refuses a part without it.
    centred.extend(s.shape.own_keys().iter().map(|k| k.name));
    if s.centred.contains(&"center") {
        centred.push("center");
    }
    let none_of = |keys: &[&str]| json!({ "not": { "anyOf": each_required(keys) } });
    if by_diameter {
        let mut all = vec![
            json!({ "required": centred }),
            json!({ "oneOf": each_required(&["radius", "diameter"]) }),
            json!({ "not": { "required": ["inner_radius", "inner_diameter"] } }),
        ];
        // A hollow cone gives its bore at both ends.
        if s.keys.contains(&"top_inner_radius") {
            let base = json!({ "anyOf": each_required(&["inner_radius", "inner_diameter"]) });
            all.push(json!({ "if": base, "then": { "required": ["top_inner_radius"] } }));
            all.push(json!({
                "if": { "required": ["top_inner_radius"] },
                "then": base,
            }));
        }
        return json!({ "allOf": all });
    }
    match s.spanned {
        None => json!({ "required": centred }),
        Some(spanned) => json!({ "oneOf": [
            { "allOf": [{ "required": centred }, none_of(spanned.keys())] },
            { "allOf": [{ "required": spanned.keys() }, none_of(s.centred)] },
        ] }),
    }
}

/// `{"type": "null"}` out of every `anyOf`, `"null"` out of every `type`
/// list, and the `format` that only says a number is an f64.
fn without_nulls(v: &mut Value) {
    match v {
        Value::Object(o) => {
            if o.get("format").and_then(Value::as_str) == Some("double") {
                o.remove("format");
            }
            if let Some(Value::Array(types)) = o.get_mut("type") {
                types.retain(|t| t != "null");
                if let [one] = &types[..] {
                    let one = one.clone();
                    o.insert("type".into(), one);
                }
            }
            if let Some(Value::Array(any)) = o.get_mut("anyOf") {
                any.retain(|s| s != &json!({ "type": "null" }));
                if let [one] = &any[..] {
                    let one = one.clone();
                    o.remove("anyOf");
                    if let Value::Object(inner) = one {
                        o.extend(inner);
                    }
                }
            }
            o.values_mut().for_each(without_nulls);
        }
        Value::Array(a) => a.iter_mut().for_each(without_nulls),
        _ => {}
    }
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

impl JsonSchema for Quantity {
    fn schema_name() -> Cow<'static, str> {
        "Quantity".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        let symbols: Vec<&str> = units::symbol_names().collect();
        json_schema!({
            "description": format!(
                "a number in the file's units, or a string with its own unit such as \"3 mm\", \"7.85 g/cm^3\" or \"3000 rpm\", or an expression over `[params]`, numbers and units such as \"2 * leg + 5 mm\" or \"pi * d^2 / 4\"; units: {}",
                symbols.join(", ")
            ),
            "anyOf": [{ "type": "number" }, quantity_string(), expression_string(), toleranced_string()],
        })
    }
}

impl JsonSchema for Angles {
    fn schema_name() -> Cow<'static, str> {
        "Angles".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "an angle in degrees (with `axis`), or three (with `intrinsic` or `extrinsic`)",
            "anyOf": [
                { "type": "number" },
                { "type": "array", "items": { "type": "number" }, "minItems": 3, "maxItems": 3 },
            ],
        })
    }
}

impl JsonSchema for ExpectValue {
    fn schema_name() -> Cow<'static, str> {
        "ExpectValue".into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "a quantity (a number, a string with its unit, an expression), or an array (of arrays) of them for a vector or matrix",
            "anyOf": [
                { "type": "number" },
                quantity_string(),
                expression_string(),
                { "type": "array", "items": generator.subschema_for::<ExpectValue>() },
            ],
        })
    }
}

/// A schema-only type: what `schemars(with)` names for a raw value whose
/// text the model checks against a table.
macro_rules! schema_only {
    ($(#[$doc:meta])* $t:ident, $name:literal, $schema:expr) => {
        $(#[$doc])*
        pub struct $t;
        impl JsonSchema for $t {
            fn schema_name() -> Cow<'static, str> {
                $name.into()
            }
            fn json_schema(_: &mut SchemaGenerator) -> Schema {
                Schema::try_from($schema).expect("invariant: a schema is an object")
            }
        }
    };
}

schema_only!(
    /// `shape`: a name in `SHAPES`.
    ShapeName,
    "ShapeName",
    json!({
        "description": "the primitive (or leave it out and give `include`)",
        "enum": SHAPES.iter().map(|s| s.name).collect::<Vec<_>>(),
    })
);

schema_only!(
    /// `units.length`: one of `units::LENGTH_UNITS`.
    LengthUnit,
    "LengthUnit",
    json!({ "description": "the unit of plain lengths", "enum": units::LENGTH_UNITS })
);

schema_only!(
    /// A mesh's `mode`: `mesh::Mode`'s names.
    MeshMode,
    "MeshMode",
    json!({
        "description": "what a mesh weighs: \"solid\" (the volume it encloses, the default) or \"shell\" (its surface as a thin sheet)",
        "enum": ["solid", "shell"],
    })
);

schema_only!(
    /// `[growth]`'s values: a percentage (`model::budget::percentage`).
    Percentage,
    "Percentage",
    json!({
        "description": "a mass growth allowance as a percentage, such as \"15 %\"",
        "type": "string",
        "pattern": "^\\s*[+]?(?:[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][+-]?[0-9]+)?\\s*%\\s*$",
    })
);

schema_only!(
    /// `group`: names joined by `/`, none empty (`model::budget::group_path`).
    GroupPath,
    "GroupPath",
    json!({
        "description": "the part's group: names joined by `/`, such as \"propulsion/tanks\"",
        "type": "string",
        "pattern": "^[^/]*[^/\\s][^/]*(?:/[^/]*[^/\\s][^/]*)*$",
    })
);

schema_only!(
    /// `tol`: a given mass's tolerance (`model::tolerance`).
    TolAmount,
    "TolAmount",
    json!({
        "description": "the tolerance of `mass`: a number in the file's mass unit, or \"0.1 kg\", \"3 %\", \"± 0.1 kg uniform\" (one standard deviation of a normal, or `uniform` within ± the amount)",
        "anyOf": [
            { "type": "number", "minimum": 0 },
            { "type": "string", "pattern": "^\\s*(?:±|\\+/-)?\\s*[^±\\s][^±]*$" },
        ],
    })
);

schema_only!(
    /// `units.mass`: one of `units::MASS_UNITS`.
    MassUnit,
    "MassUnit",
    json!({ "description": "the unit of plain masses", "enum": units::MASS_UNITS })
);

schema_only!(
    /// `products`: a convention of `place::PRODUCTS`.
    Products,
    "Products",
    json!({
        "description": "the sign of `inertia`'s products: \"tensor\" (−∫xy dm, the default) or \"positive\" (+∫xy dm, as CAD reports them)",
        "enum": super::place::PRODUCTS,
    })
);

schema_only!(
    /// `material`: a built-in material or one of the file's `[materials]`.
    MaterialName,
    "MaterialName",
    json!({
        "description": format!(
            "a material of the file's [materials], or a built-in one: {}",
            crate::materials::BUILT_IN.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
        ),
        "type": "string",
    })
);

schema_only!(
    /// `intrinsic`, `extrinsic`: the sequences `rotation::parse_sequence`
    /// reads, either case.
    EulerAxes,
    "EulerAxes",
    json!({
        "description": "an Euler sequence: three axes, no axis twice in a row, such as \"zyx\" or \"zxz\"",
        "type": "string",
        "pattern": euler_pattern(),
    })
);

schema_only!(
    /// `tol`: a quantity, or a percentage (`expect`'s `tolerance`).
    Tolerance,
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
    })
);

/// Every sequence of three axes `parse_sequence` takes, either case.
fn euler_pattern() -> String {
    let class = |c: char| format!("[{c}{}]", c.to_ascii_uppercase());
    let mut seqs = Vec::new();
    for a in ['x', 'y', 'z'] {
        for b in ['x', 'y', 'z'] {
            for c in ['x', 'y', 'z'] {
                if super::rotation::parse_sequence(&format!("{a}{b}{c}")).is_some() {
                    seqs.push(format!("{}{}{}", class(a), class(b), class(c)));
                }
            }
        }
    }
    format!("^(?:{})$", seqs.join("|"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_schema_names_its_draft_and_its_id() {
        let s = schema();
        assert_eq!(
            s["$schema"], "https://json-schema.org/draft/2020-12/schema",
            "{s:#}"
        );
        assert_eq!(s["$id"], ID);
    }

    #[test]
    fn no_schema_allows_null() {
        let text = text();
        assert!(!text.contains("\"null\""), "{text}");
    }

    /// Taplo validates as draft 7: a keyword of 2019-09 or later would be
    /// skipped there (see the module's comment).
    #[test]
    fn the_schema_uses_no_keyword_newer_than_draft_7() {
        let text = text();
        for newer in [
            "dependentRequired",
            "dependentSchemas",
            "unevaluatedProperties",
            "unevaluatedItems",
            "prefixItems",
            "$anchor",
            "$dynamicRef",
            "minContains",
            "maxContains",
        ] {
            assert!(!text.contains(&format!("\"{newer}\"")), "{newer}");
        }
    }

    #[test]
    fn every_shape_has_its_rule() {
        let rules = part_rules();
        for s in &SHAPES {
            assert!(
                rules
                    .iter()
                    .any(|r| r["if"]["properties"]["shape"]["const"] == s.name),
                "{}",
                s.name
            );
        }
    }

    #[test]
    fn the_euler_pattern_has_the_twelve_sequences() {
        assert_eq!(euler_pattern().matches('|').count(), 11);
    }
}
