//! The part file's JSON Schema (draft 2020-12; `massprop schema`), for
//! editors: Taplo and Even Better TOML complete and check a part file that
//! names it in a `#:schema` comment (docs/part-file.md).
//!
//! A part's keys come from their declarations (`keys::COMMON`, a shape's
//! own in `ShapeKind::OWN_KEYS`): each key's type from its `Kind`, its
//! description from its doc, so a key declared there is in the schema.
//! The other tables (`[units]`, `[analysis]` and its `axes`, `rotation`,
//! `array`, `mirror`, `[expect]`, `[materials]`, `[params]`, `[growth]`,
//! `[budget]`) are declared below, `[expect]`'s keys from the table of
//! quantities (`quantity::QUANTITIES`). Which keys each shape takes,
//! which it needs and how many numbers its `size` and `edges` hold come
//! from the shape table (`shapes::SHAPES`); the units and the quantity
//! strings from `units`. The schema says less than the model checks
//! (ranges, perpendicular edges, a key's dimension): a file it accepts may
//! still be refused by `massprop check`, never the other way round
//! (tests/integration/schema.rs).
//!
//! Draft 2020-12 by its `$schema`, but in draft 7's keywords alone (with
//! `$defs`, which a draft-7 validator reaches by its JSON pointer): Taplo
//! 0.9, the engine of Even Better TOML, validates as draft 7 and skips any
//! keyword it does not know.

use super::keys::COMMON;
use crate::shapes::{Key, Kind, MaterialRule, SHAPES, Spanned as Spans};
use serde_json::{Map, Value, json};
use tables::{array, definitions, doc, each_required, map_of, r};

mod tables;

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
    let mut defs = definitions();
    defs.insert("Part".into(), part());
    defs.insert("Case".into(), case());
    json!({
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": ID,
        "title": "massprop part file",
        "description": "A massprop part file, version 1: `massprop check FILE` checks it all (docs/part-file.md).",
        "type": "object",
        "additionalProperties": false,
        "required": ["part"],
        "properties": {
            "name": { "type": "string" },
            "units": r("Units"),
            "part": { "type": "array", "items": r("Part"), "minItems": 1 },
            "analysis": r("Analysis"),
            "expect": r("Expect"),
            "materials": map_of(
                r("Material"),
                "`[materials]`: name → { density }, adding to the built-in ones.",
            ),
            "params": map_of(
                r("PlainNumber"),
                "`[params]`: named quantities that any quantity string may use\n(`model::params`).",
            ),
            "growth": map_of(
                r("Percentage"),
                "`[growth]`: maturity name → mass growth allowance, a percentage\nstring (`estimated = \"15 %\"`; `model::budget`).",
            ),
            "budget": doc(r("Budget"), "`[budget]`: the not-to-exceed limit of the predicted mass."),
            "envelope": doc(r("Envelope"), "`[envelope]`: the loading envelope (docs/cases.md): a polygon in (centre-of-mass coordinate, mass) the base and every case must lie in."),
            "case": doc(
                json!({ "type": "array", "items": r("Case") }),
                "`[[case]]`: the body's loading cases, each the file in another state (docs/cases.md).",
            ),
        },
        "$defs": defs,
    })
}

/// `[[case]]` (`model::case`): its name, the `[params]` values it
/// replaces, what it takes out and its own `[expect]`.
fn case() -> Value {
    let names = |d: &str| doc(array(json!({ "type": "string" }), None), d);
    json!({
        "description": "a loading case: the file with other parameter values and without some parts",
        "type": "object",
        "additionalProperties": false,
        "required": ["name"],
        "properties": {
            "name": doc(json!({ "type": "string" }), "the case's name, unique in the file (`report --case NAME`)"),
            "params": map_of(r("PlainNumber"), "values in place of the file's `[params]` definitions"),
            "without": names("parts and sub-assemblies absent in this case, named as `--only` names them (`cargo / box[2]`)"),
            "without_groups": doc(array(r("GroupPath"), None), "`group` paths absent in this case, with their sub-groups"),
            "expect": r("Expect"),
        },
    })
}

/// Every part key as declared: the common ones (`keys::COMMON`), then
/// each shape's own in `SHAPES`' order. What the schema's `[[part]]` and
/// docs/part-file.md's table of part keys list (tests/integration/keys_docs.rs).
pub fn part_keys() -> impl Iterator<Item = &'static Key> {
    let own = SHAPES.iter().flat_map(|s| s.shape.own_keys());
    COMMON.iter().chain(own)
}

/// `[[part]]`: its keys from their declarations, its rules from `SHAPES`.
fn part() -> Value {
    let mut props = Map::new();
    for key in part_keys() {
        props.insert(key.name.into(), key_schema(key));
    }
    json!({
        "description": "a part: a shape, or another part file placed here (`include`)",
        "type": "object",
        "additionalProperties": false,
        "properties": props,
        "allOf": part_rules(),
    })
}

/// The part keys whose text the model checks against a table or a
/// pattern: the definition that says which, instead of a plain string (or,
/// for `tol`, a quantity).
const NAMED: [(&str, &str); 7] = [
    ("shape", "ShapeName"),
    ("material", "MaterialName"),
    ("products", "Products"),
    ("mesh_unit", "LengthUnit"),
    ("mode", "MeshMode"),
    ("group", "GroupPath"),
    ("tol", "TolAmount"),
];

/// The part keys whose rows are as many on every shape (`edges` are not:
/// a plate's 2, a box's 3, which its rule says).
const ROWS: [(&str, usize); 2] = [("vertices", 3), ("inertia", 3)];

/// The schema of a part key, from its declaration: its kind (or the
/// definition `NAMED` gives it), and its one line of docs.
fn key_schema(key: &Key) -> Value {
    let quantity = r("Quantity");
    let mut v = match key.kind {
        Kind::Quantity => quantity,
        Kind::Point => array(quantity, Some(3)),
        Kind::Quantities(n) => array(quantity, n),
        Kind::Rows { width, .. } => {
            let rows = ROWS.iter().find(|(k, _)| *k == key.name).map(|r| r.1);
            array(array(quantity, Some(width)), rows)
        }
        Kind::Str => json!({ "type": "string" }),
        Kind::Bool => json!({ "type": "boolean" }),
        Kind::Rotation => r("Rotation"),
        Kind::ArrayTable => r("Array"),
        Kind::MirrorTable => r("Mirror"),
        Kind::ParamsTable => json!({
            "type": "object",
            "additionalProperties": r("PlainNumber"),
        }),
    };
    if let Some((_, def)) = NAMED.iter().find(|(k, _)| *k == key.name) {
        v = r(def);
    }
    doc(v, key.doc)
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
        if s.size_items > 0 {
            let n = s.size_items;
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
    if s.sizes.contains(&"file") {
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
/// exactly one of `density` and `material`, and no `weld`.
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
            // `weld` is a solid's alone.
            "then": { "oneOf": [
                only(&["mass"]),
                only(&["areal_density"]),
                only(&["thickness", "density"]),
                only(&["thickness", "material"]),
            ], "not": { "required": ["weld"] } },
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

/// The centred placement (its dimensions, and `center` where it has one),
/// or the spanned one (`corner` and `edges`, `from` and `to`), not both.
fn placement_rule(s: &crate::shapes::ShapeInfo) -> Value {
    // The inner radii may be left out: a solid. A radius may be given as
    // its diameter (not a rod's: that is its real size), one or the other.
    let by_diameter = s.keys.contains(&"diameter") && s.real_size.is_none();
    let mut centred: Vec<&str> = s
        .sizes
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
    for k in s.shape.own_keys() {
        if !centred.contains(&k.name) {
            centred.push(k.name);
        }
    }
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

#[cfg(test)]
mod tests {
    use super::tables::euler_pattern;
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

    /// A part's properties are exactly the declared keys, common and
    /// every shape's own, each described by its declaration's doc.
    #[test]
    fn every_declared_key_is_a_part_property_with_its_doc() {
        let s = schema();
        let props = s["$defs"]["Part"]["properties"]
            .as_object()
            .expect("properties");
        let own = SHAPES.iter().flat_map(|s| s.shape.own_keys());
        let mut n = 0;
        for key in COMMON.iter().chain(own) {
            n += 1;
            assert_eq!(props[key.name]["description"], key.doc, "{}", key.name);
        }
        assert_eq!(props.len(), n);
    }

    /// A refinement names a declared key of the kind it refines: a key
    /// renamed in the registry cannot leave its refinement behind.
    #[test]
    fn every_refinement_names_a_declared_key_of_its_kind() {
        let declared = |name: &str| COMMON.iter().find(|k| k.name == name);
        for (key, _) in NAMED {
            let k = declared(key).unwrap_or_else(|| panic!("`{key}` is not declared"));
            assert!(matches!(k.kind, Kind::Str | Kind::Quantity), "{key}");
        }
        for (key, _) in ROWS {
            let k = declared(key).unwrap_or_else(|| panic!("`{key}` is not declared"));
            assert!(matches!(k.kind, Kind::Rows { .. }), "{key}");
        }
    }

    /// Every `$ref` names a definition that is there.
    #[test]
    fn every_reference_is_defined() {
        fn refs(v: &Value, out: &mut Vec<String>) {
            match v {
                Value::Object(o) => {
                    if let Some(Value::String(r)) = o.get("$ref") {
                        out.push(r.clone());
                    }
                    o.values().for_each(|v| refs(v, out));
                }
                Value::Array(a) => a.iter().for_each(|v| refs(v, out)),
                Value::Null | Value::Bool(_) | Value::Number(_) | Value::String(_) => {}
            }
        }
        let s = schema();
        let mut all = Vec::new();
        refs(&s, &mut all);
        assert!(!all.is_empty());
        for r in all {
            let name = r.strip_prefix("#/$defs/").expect("a local reference");
            assert!(s["$defs"].get(name).is_some(), "{r}");
        }
    }
}
