//! `massprop schema` and `massprop init` (issue 14, item 3): the JSON
//! Schema accepts every part file the reader accepts (the examples, the
//! test catalogue's valid files, `init`'s starter), rejects misspelt keys
//! and shapes, and agrees with the reader shape by shape, key by key — so
//! the two cannot drift apart.

use crate::common::{massprop, scratch};
use massprop::shapes::SHAPES;
use serde_json::{Value, json};
use std::path::Path;
use std::sync::LazyLock;

static SCHEMA: LazyLock<Value> = LazyLock::new(massprop::model::schema::schema);
static VALIDATOR: LazyLock<jsonschema::Validator> =
    LazyLock::new(|| jsonschema::validator_for(&SCHEMA).expect("the schema compiles"));
/// The schema read as draft 7, as Taplo 0.9 (Even Better TOML) reads it.
static DRAFT_7: LazyLock<jsonschema::Validator> =
    LazyLock::new(|| jsonschema::draft7::new(&SCHEMA).expect("the schema compiles as draft 7"));

/// A part file as the JSON an editor validates (Taplo reads TOML into
/// JSON the same way).
fn as_json(text: &str) -> Value {
    let table: toml::Table = toml::from_str(text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    serde_json::to_value(table).unwrap()
}

/// The schema's complaints about a part file, one line each; read as
/// draft 7 it judges the file alike.
fn schema_errors(text: &str) -> Vec<String> {
    let json = as_json(text);
    let errors: Vec<String> = VALIDATOR
        .iter_errors(&json)
        .map(|e| format!("{}: {e} (at {})", e.instance_path(), e.schema_path()))
        .collect();
    assert_eq!(
        DRAFT_7.is_valid(&json),
        errors.is_empty(),
        "draft 2020-12 and draft 7 disagree on:\n{text}"
    );
    errors
}

/// The reader's verdict on a part file (no includes).
fn reader(text: &str) -> Result<(), String> {
    let source = massprop::diag::Source::new("t.toml", text);
    massprop::model::Model::parse(&source)
        .map(|_| ())
        .map_err(|d| d.to_string())
}

/// Rejected by both the schema and the reader.
fn both_reject(text: &str) {
    assert!(
        !schema_errors(text).is_empty(),
        "the schema accepts:\n{text}"
    );
    assert!(reader(text).is_err(), "the reader accepts:\n{text}");
}

const HEAD: &str = "units = { length = \"mm\", mass = \"kg\" }\n";

/// A part file of one part; its `[growth]` gives `maturity`'s sample a
/// meaning.
fn one_part(lines: &str) -> String {
    format!("{HEAD}\n[growth]\nsample = \"5 %\"\n\n[[part]]\n{lines}\n")
}

#[test]
fn schema_prints_a_json_schema_of_draft_2020_12_with_its_id() {
    let out = massprop(&["schema"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stderr.is_empty());
    let v: Value = serde_json::from_slice(&out.stdout).expect("stdout is JSON");
    assert_eq!(v["$schema"], "https://json-schema.org/draft/2020-12/schema");
    assert_eq!(v["$id"], massprop::model::schema::ID);
    assert_eq!(v, *SCHEMA, "the command prints the library's schema");
    jsonschema::meta::validate(&v).expect("valid against its meta-schema");
}

#[test]
fn every_example_in_shapes_validates() {
    let mut n = 0;
    for path in crate::common::example_part_files() {
        let text = std::fs::read_to_string(&path).unwrap();
        let errors = schema_errors(&text);
        assert!(
            errors.is_empty(),
            "{}:\n{}",
            path.display(),
            errors.join("\n")
        );
        n += 1;
    }
    assert!(n >= 7, "only {n} examples");
}

/// Every part file in tests/cmd that the reader accepts, the schema
/// accepts: it never refuses a file massprop reads. (On a thread with the
/// stack of a main thread: the catalogue's hostile nesting, refused by the
/// binary, needs more than a test thread's 2 MiB in a debug build.)
#[test]
fn every_file_the_reader_accepts_in_the_test_catalogue_validates() {
    std::thread::Builder::new()
        .stack_size(16 << 20)
        .spawn(catalogue_validates)
        .unwrap()
        .join()
        .unwrap();
}

fn catalogue_validates() {
    let mut files = Vec::new();
    for dir in [
        "tests/cmd/bad-input.in",
        "tests/cmd/check.in",
        "tests/cmd/diff.in",
    ] {
        collect_toml(Path::new(dir), &mut files);
    }
    let mut accepted = 0;
    for path in &files {
        let Ok(source) = massprop::io::read_source_at(path) else {
            continue;
        };
        if massprop::model::Model::parse(&source).is_err() {
            continue;
        }
        accepted += 1;
        let errors = schema_errors(&source.text);
        assert!(
            errors.is_empty(),
            "{}:\n{}",
            path.display(),
            errors.join("\n")
        );
    }
    assert!(accepted >= 20, "only {accepted} files read");
}

fn collect_toml(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            collect_toml(&p, out);
        } else if p.extension().is_some_and(|x| x == "toml") {
            out.push(p);
        }
    }
}

#[test]
fn a_misspelt_key_in_a_part_is_rejected() {
    both_reject(&one_part(
        "shape = \"box\"\nmass = 1\nsizee = [1, 1, 1]\ncenter = [0, 0, 0]",
    ));
}

#[test]
fn a_misspelt_top_level_table_is_rejected() {
    let text = format!(
        "{}\n[analysys]\nomega = [0, 0, 1]\n",
        one_part("shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]")
    );
    both_reject(&text);
    both_reject(
        "unit = { length = \"mm\" }\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    );
}

#[test]
fn a_misspelt_key_in_a_nested_table_is_rejected() {
    both_reject(&one_part(
        "shape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nrotation = { axis = [0, 0, 1], degrees = 9, degree = 9 }",
    ));
    let point = one_part("shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]");
    both_reject(&format!(
        "{point}\n[expect]\nmass = {{ value = 1, tol = 0.1, tolerance = 1 }}\n"
    ));
    both_reject(&format!(
        "{point}\n[expect]\nmas = {{ value = 1, tol = 0.1 }}\n"
    ));
    both_reject(&format!("{point}\n[materials]\nfoam = {{ densty = 30 }}\n"));
    both_reject(
        "units = { length = \"mm\", mas = \"kg\" }\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    );
}

#[test]
fn an_unknown_or_misspelt_shape_is_rejected() {
    for shape in ["cube", "sphre", "Box", ""] {
        both_reject(&one_part(&format!(
            "shape = \"{shape}\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]"
        )));
    }
}

#[test]
fn a_value_of_the_wrong_type_is_rejected() {
    for bad in [
        "shape = \"box\"\nmass = 1\nsize = \"big\"\ncenter = [0, 0, 0]",
        "shape = \"box\"\nmass = true\nsize = [1, 1, 1]\ncenter = [0, 0, 0]",
        "shape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nremove = \"yes\"",
        "shape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0]",
        "shape = \"box\"\nmass = \"1 kilo\"\nsize = [1, 1, 1]\ncenter = [0, 0, 0]",
        "shape = \"box\"\nmass = 1\nsize = [1, 1]\ncenter = [0, 0, 0]",
        "shape = 3\nmass = 1\ncenter = [0, 0, 0]",
        "shape = \"inertia\"\nmass = 1\ncenter = [0, 0, 0]\ninertia = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\nproducts = \"cad\"",
        "shape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nrotation = { intrinsic = \"zzx\", degrees = [1, 2, 3] }",
    ] {
        both_reject(&one_part(bad));
    }
    both_reject(
        "units = { length = \"furlong\" }\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    );
}

#[test]
fn a_part_is_a_shape_or_an_include_not_both_nor_neither() {
    both_reject(&one_part("mass = 1\ncenter = [0, 0, 0]"));
    both_reject(&one_part(
        "shape = \"point\"\ninclude = \"other.toml\"\nmass = 1\ncenter = [0, 0, 0]",
    ));
    both_reject(&one_part("include = \"other.toml\"\nmass = 1"));
    let include = one_part(
        "name = \"sub\"\ninclude = \"other.toml\"\norigin = [0, 0, 1]\nrotation = { axis = [0, 0, 1], degrees = 90 }",
    );
    assert_eq!(schema_errors(&include), Vec::<String>::new());
}

#[test]
fn a_file_without_parts_is_rejected() {
    both_reject(HEAD);
    both_reject(&format!("{HEAD}part = []\n"));
}

/// The shape names of the schema are the shape table's.
#[test]
fn the_schema_names_every_shape_of_the_registry() {
    let names: Vec<&str> = SHAPES.iter().map(|s| s.name).collect();
    assert_eq!(SCHEMA["$defs"]["ShapeName"]["enum"], json!(names));
    for s in &SHAPES {
        // The shape is taken (a part of it fails only on its other keys,
        // never on `shape`).
        let errors = schema_errors(&one_part(&format!("shape = \"{}\"", s.name)));
        assert!(
            errors.iter().all(|e| !e.starts_with("/part/0/shape")),
            "{}: {errors:?}",
            s.name
        );
    }
}

/// A minimal part of each shape that the reader accepts, in millimetres
/// and kilograms, with every way to place and weigh it that the shape has.
fn samples(shape: &str) -> Vec<&'static str> {
    match shape {
        "box" => vec![
            "mass = 1\nsize = [10, 20, 30]\ncenter = [0, 0, 0]",
            "density = \"2.7 g/cm^3\"\ncorner = [0, 0, 0]\nedges = [[10, 0, 0], [0, 20, 0], [0, 0, 30]]",
            "material = \"steel\"\nsize = [10, 20, 30]\ncenter = [0, 0, 0]\nrotation = { axis = [0, 0, 1], degrees = 30 }",
        ],
        "plate" => vec![
            "mass = 1\nsize = [10, 20]\ncenter = [0, 0, 0]",
            "areal_density = \"5 kg/m^2\"\ncorner = [0, 0, 0]\nedges = [[10, 0, 0], [0, 20, 0]]",
            "material = \"steel\"\nthickness = 2\nsize = [10, 20]\ncenter = [0, 0, 0]",
        ],
        "rod" => vec![
            "mass = 1\nlength = 100\ncenter = [0, 0, 0]",
            "linear_density = \"40 g/m\"\nfrom = [0, 0, 0]\nto = [0, 0, 100]",
            "material = \"steel\"\narea = 3\nlength = 100\ncenter = [0, 0, 0]",
            "material = \"steel\"\ndiameter = 2\nfrom = [0, 0, 0]\nto = [0, 0, 100]",
        ],
        "cylinder" => vec![
            "mass = 1\nradius = 10\nlength = 50\ncenter = [0, 0, 0]",
            "density = 7.85e-6\nradius = 10\ninner_radius = 8\nlength = 50\ncenter = [0, 0, 0]",
            "material = \"steel\"\nradius = 10\nlength = 50\ncenter = [0, 0, 0]",
        ],
        "disk" => vec![
            "mass = 1\nradius = 10\ncenter = [0, 0, 0]",
            "areal_density = \"5 kg/m^2\"\nradius = 10\ninner_radius = 2\ncenter = [0, 0, 0]",
            "material = \"steel\"\nthickness = 2\nradius = 10\ncenter = [0, 0, 0]",
        ],
        "sphere" => vec![
            "mass = 1\nradius = 10\ncenter = [0, 0, 0]",
            "density = \"1 g/cm^3\"\nradius = 10\ninner_radius = 9\ncenter = [0, 0, 0]",
            "material = \"water\"\nradius = 10\ncenter = [0, 0, 0]",
        ],
        "triangle" => vec![
            "mass = 1\nvertices = [[0, 0, 0], [10, 0, 0], [0, 10, 0]]",
            "areal_density = \"5 kg/m^2\"\nvertices = [[0, 0, 0], [10, 0, 0], [0, 10, 0]]",
            "material = \"steel\"\nthickness = 2\nvertices = [[0, 0, 0], [10, 0, 0], [0, 10, 0]]",
        ],
        "point" => vec!["mass = 1\ncenter = [0, 0, 0]"],
        "inertia" => vec![
            "mass = 1\ncenter = [0, 0, 0]\ninertia = [[2, 0, 0], [0, 2, 0], [0, 0, 2]]",
            "mass = 1\ncenter = [0, 0, 0]\ninertia = [[2, 0, 0], [0, 2, 0], [0, 0, 2]]\nproducts = \"positive\"\nrotation = { quaternion = [1, 0, 0, 0] }",
        ],
        "cone" => vec![
            "mass = 1\nradius = 10\ntop_radius = 0\nlength = 5\ncenter = [0, 0, 0]",
            "density = \"1 g/cm^3\"\ndiameter = 20\ninner_diameter = 10\ntop_radius = 4\ntop_inner_radius = 2\nlength = 5\ncenter = [0, 0, 0]",
            "material = \"steel\"\nradius = 0\ntop_radius = 3\nlength = 5\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 90 }",
        ],
        "torus" => vec![
            "mass = 1\nradius = 10\ntube_radius = 2\ncenter = [0, 0, 0]",
            "density = \"1 g/cm^3\"\nradius = 10\ntube_radius = 2\ninner_tube_radius = 1\ncenter = [0, 0, 0]",
        ],
        "hemisphere" => vec![
            "mass = 1\nradius = 10\ncenter = [0, 0, 0]",
            "material = \"water\"\ndiameter = 10\ninner_diameter = 8\ncenter = [0, 0, 0]",
        ],
        "prism" => vec![
            "mass = 1\npolygon = [[0, 0], [10, 0], [0, 10]]\nlength = 2",
            "density = \"1 g/cm^3\"\npolygon = [[0, 0], [10, 0], [10, 10], [0, 10]]\nlength = 2\norigin = [1, 2, 3]\nrotation = { axis = [0, 0, 1], degrees = 90 }",
        ],
        // The mesh file from the working directory (the crate's root).
        "mesh" => vec![
            "file = \"shapes/meshes/bracket.stl\"\nmesh_unit = \"mm\"\nmass = 1",
            "file = \"shapes/meshes/bracket.stl\"\nmesh_unit = \"mm\"\nmaterial = \"steel\"\norigin = [1, 2, 3]\nrotation = { axis = [0, 0, 1], degrees = 30 }",
            "file = \"shapes/meshes/bracket.stl\"\nmesh_unit = \"mm\"\nmode = \"shell\"\nthickness = 1\ndensity = \"1 g/cm^3\"",
            "file = \"shapes/meshes/bracket.stl\"\nmesh_unit = \"mm\"\nmode = \"shell\"\nareal_density = \"5 kg/m^2\"",
            "file = \"shapes/meshes/bracket.stl\"\nmesh_unit = \"mm\"\nmode = \"solid\"\ndensity = \"2.7 g/cm^3\"",
        ],
        other => panic!("no sample of a {other}: add one here"),
    }
}

/// A value of the right type for each key a part may have, to add it.
fn sample_value(key: &str, shape: &str) -> &'static str {
    match key {
        "name" => "\"added\"",
        "shape" => "\"point\"",
        "mass" => "2",
        "density" => "\"1 g/cm^3\"",
        "areal_density" => "\"1 kg/m^2\"",
        "linear_density" => "\"1 kg/m\"",
        "size" if shape == "plate" => "[5, 5]",
        "size" => "[5, 5, 5]",
        "length" => "7",
        "center" | "corner" | "from" | "origin" => "[1, 2, 3]",
        "to" => "[1, 2, 30]",
        "rotation" => "{ axis = [0, 0, 1], degrees = 90 }",
        "edges" if shape == "plate" => "[[5, 0, 0], [0, 5, 0]]",
        "edges" => "[[5, 0, 0], [0, 5, 0], [0, 0, 5]]",
        "thickness" | "diameter" => "1",
        "radius" => "20",
        "inner_radius" | "inner_tube_radius" | "top_inner_radius" => "1",
        "inner_diameter" => "2",
        "top_radius" | "tube_radius" => "3",
        "polygon" => "[[0, 0], [5, 0], [0, 5]]",
        "include" => "\"other.toml\"",
        "material" => "\"steel\"",
        "area" => "2",
        "vertices" => "[[0, 0, 0], [5, 0, 0], [0, 5, 0]]",
        "inertia" => "[[3, 0, 0], [0, 3, 0], [0, 0, 3]]",
        "products" => "\"tensor\"",
        "remove" => "false",
        "array" => "{ count = 2, step = [1, 0, 0] }",
        "mirror" => "{ normal = [1, 0, 0] }",
        "params" => "{ a = \"1 m\" }",
        "file" => "\"shapes/meshes/bracket.stl\"",
        "mesh_unit" => "\"mm\"",
        "mode" => "\"shell\"",
        "group" => "\"structure/panels\"",
        "maturity" => "\"sample\"",
        "tol" => "\"1 %\"",
        other => panic!("no sample value for `{other}`: add one here"),
    }
}

/// Every key the schema lets a part have.
fn part_keys() -> Vec<String> {
    SCHEMA["$defs"]["Part"]["properties"]
        .as_object()
        .expect("a part's properties")
        .keys()
        .cloned()
        .collect()
}

/// The keys of a sample, in order.
fn keys_of(sample: &str) -> Vec<&str> {
    sample
        .lines()
        .map(|l| l.split('=').next().unwrap().trim())
        .collect()
}

/// For each shape, from each sample: with each key the sample lacks added,
/// and with each key it has taken away, the schema accepts exactly when
/// the reader does. Which keys a shape takes, which it needs, which go
/// together and which conflict are the reader's (`SHAPES` and the model's
/// checks); this holds the schema to them, whatever either is made from.
#[test]
fn the_schema_and_the_reader_agree_on_each_shapes_keys() {
    let keys = part_keys();
    let mut compared = 0;
    let mut disagree = Vec::new();
    for s in &SHAPES {
        for sample in samples(s.name) {
            let base = format!("shape = \"{}\"\n{sample}", s.name);
            let mut variants = vec![base.clone()];
            for k in &keys {
                if !keys_of(&base).contains(&k.as_str()) {
                    variants.push(format!("{base}\n{k} = {}", sample_value(k, s.name)));
                }
            }
            let lines: Vec<&str> = base.lines().collect();
            for i in 0..lines.len() {
                let mut without = lines.clone();
                without.remove(i);
                variants.push(without.join("\n"));
            }
            for v in variants {
                let text = one_part(&v);
                let by_reader = reader(&text);
                let by_schema = schema_errors(&text);
                compared += 1;
                if by_reader.is_ok() != by_schema.is_empty() {
                    disagree.push(format!(
                        "--- {}\n{v}\nreader: {by_reader:?}\nschema: {by_schema:#?}",
                        s.name
                    ));
                }
            }
        }
    }
    assert!(
        disagree.is_empty(),
        "{} of {compared} parts judged differently:\n{}",
        disagree.len(),
        disagree.join("\n")
    );
    assert!(compared > 500, "only {compared} parts compared");
}

/// Every key the schema knows for a part is one the reader reads (not an
/// unknown key to it), and the other way round: every key of the shape
/// table and of an include is in the schema.
#[test]
fn the_schema_knows_exactly_the_keys_the_reader_reads() {
    let keys = part_keys();
    for k in &keys {
        // On a point, every key but its own is refused, but as a key that
        // does not apply, never as an unknown one.
        let text = one_part(&format!(
            "shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n{k} = {}",
            sample_value(k, "point")
        ));
        if let Err(e) = reader(&text) {
            assert!(!e.contains("unknown"), "`{k}`: {e}");
        }
    }
    for s in &SHAPES {
        for k in s.keys {
            assert!(keys.iter().any(|x| x == k), "`{k}` of a {}", s.name);
        }
    }
    for k in ["name", "shape", "include", "origin"] {
        assert!(keys.iter().any(|x| x == k), "`{k}`");
    }
}

/// The quantity strings the schema's pattern takes are those the unit
/// reader takes (any dimension; the key's dimension is the model's).
#[test]
fn the_quantity_pattern_takes_what_the_unit_reader_takes() {
    // The pattern of a plain quantity string (an expression, the other
    // string a quantity may be, is the expression reader's to judge:
    // `an_expression_is_a_quantity_to_the_schema`).
    let quantity = json!({ "type": "string", "pattern": massprop::units::quantity_pattern() });
    let v = jsonschema::validator_for(&quantity).unwrap();
    let reads = |s: &str| {
        massprop::units::split_number(s)
            .ok()
            .filter(|(_, unit)| !unit.is_empty())
            .is_some_and(|(_, unit)| massprop::units::parse_unit(unit).is_ok())
    };
    let cases = [
        "3 mm",
        "3mm",
        " 3 mm ",
        "-2.5e3 mm",
        "+4 m",
        "1_000 mm",
        "1. m",
        ".5 m",
        "7.85 g/cm^3",
        "7.85 g/cm³",
        "7850 kg/m3",
        "7.85 g cm^-3",
        "7.85 g·cm^-3",
        "2 kg*m^2",
        "2 kg * m^2",
        "0.5 N*m*s",
        "3000 rpm",
        "90 deg/s^2",
        "2 1/s",
        "2 1 / s",
        "5 Hz",
        "1.2 g/mL",
        "7.85 kg/L",
        "3 µm",
        "3 μm",
        "3 um",
        "2 oz",
        "1 t",
        "8.25 J",
        "1 rev/min",
        "3 m^+2",
        "3 m^02",
        // Refused by both.
        "3",
        "mm",
        "3 mmm",
        "3 m^5",
        "3 m5",
        "3 m^0",
        "3 kg/m/m",
        "3 kg/m^",
        "3 /s",
        "3 m^ 2",
        "e3 m",
        "3 e",
        "3 m²²",
        "three mm",
        "3..5 m",
        "1.2.3 m",
        "3 1",
        "",
    ];
    for c in cases {
        assert_eq!(
            v.is_valid(&json!(c)),
            reads(c),
            "{c:?}: the pattern {} and the reader disagree",
            if v.is_valid(&json!(c)) {
                "takes it"
            } else {
                "refuses it"
            }
        );
    }
}

/// Expressions over parameters are quantities to the schema too; a
/// percentage (`tol`'s) is not one.
#[test]
fn an_expression_is_a_quantity_to_the_schema() {
    let quantity = json!({ "$ref": "#/$defs/Quantity", "$defs": SCHEMA["$defs"] });
    let v = jsonschema::validator_for(&quantity).unwrap();
    for e in [
        "2 * leg + 5 mm",
        "pi * d^2 / 4",
        "rim_mass / 32",
        "(a + b) / 2",
        "leg",
        "-x",
    ] {
        assert!(v.is_valid(&json!(e)), "{e:?}");
    }
    for e in ["", "3", "5%", "   "] {
        assert!(!v.is_valid(&json!(e)), "{e:?}");
    }
}

/// `tol` takes a percentage as `[expect]` reads it.
#[test]
fn a_percentage_tolerance_is_taken_as_the_reader_takes_it() {
    for (tol, ok) in [
        ("0.5%", true),
        (" 1 %", true),
        ("1e-3%", true),
        ("5%%", true),
        ("+2.%", true),
        ("% 5", false),
        ("five %", false),
        ("5 % %", false),
    ] {
        let text = format!(
            "{}\n[expect]\nmass = {{ value = 1, tol = \"{tol}\" }}\n",
            one_part("shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]")
        );
        assert_eq!(reader(&text).is_ok(), ok, "{tol:?}: {:?}", reader(&text));
        assert_eq!(schema_errors(&text).is_empty(), ok, "{tol:?}");
    }
}

/// Taplo's `#:schema` directive is a TOML comment: a file that starts with
/// one reads as it did without it.
#[test]
fn a_schema_directive_on_the_first_line_changes_nothing() {
    // Every example, with the files it includes, copied with the line.
    let dir = scratch("schema", "directive");
    let mut n = 0;
    for path in crate::common::example_part_files() {
        let text = std::fs::read_to_string(&path).unwrap();
        let with = format!("#:schema ./massprop.schema.json\n{text}");
        std::fs::write(dir.join(path.file_name().unwrap()), with).unwrap();
    }
    // And the mesh files the examples read.
    std::fs::create_dir_all(dir.join("meshes")).unwrap();
    for entry in std::fs::read_dir("shapes/meshes").unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, dir.join("meshes").join(path.file_name().unwrap())).unwrap();
    }
    for path in crate::common::example_part_files() {
        let copy = dir.join(path.file_name().unwrap());
        let (mut a, _) = crate::common::report_json_file(&path, &[]);
        let (mut b, _) = crate::common::report_json_file(&copy, &[]);
        a.as_object_mut().unwrap().remove("source");
        b.as_object_mut().unwrap().remove("source");
        assert_eq!(a, b, "{}", path.display());
        n += 1;
    }
    assert!(n >= 7);
}

/// The starter of `init`: on standard output, it validates and `check`
/// passes it.
#[test]
fn init_prints_a_starter_that_validates_and_passes_check() {
    let out = massprop(&["init"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text, massprop::commands::init::STARTER);
    assert_eq!(massprop(&["init", "-"]).stdout, text.as_bytes());
    let errors = schema_errors(&text);
    assert!(errors.is_empty(), "{}", errors.join("\n"));
    let dir = scratch("schema", "init-check");
    let file = dir.join("starter.toml");
    std::fs::write(&file, &text).unwrap();
    let check = massprop(&["check", file.to_str().unwrap()]);
    assert_eq!(
        check.status.code(),
        Some(0),
        "{}{}",
        String::from_utf8_lossy(&check.stdout),
        String::from_utf8_lossy(&check.stderr)
    );
    // It has expectations for `check` to hold, and comments.
    assert!(text.contains("[expect]"));
    assert!(
        text.lines()
            .filter(|l| l.trim_start().starts_with('#'))
            .count()
            >= 20
    );
    // No live directive: it would name a file that is not there.
    assert!(!text.lines().any(|l| l.starts_with("#:schema")));
}

#[test]
fn init_writes_a_new_file_and_refuses_an_existing_one() {
    let dir = scratch("schema", "init-file");
    let file = dir.join("new.toml");
    let path = file.to_str().unwrap();
    let out = massprop(&["init", path]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    assert!(out.stdout.is_empty());
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        massprop::commands::init::STARTER
    );
    // Again: refused, the file as it was.
    std::fs::write(&file, "# mine\n").unwrap();
    let out = massprop(&["init", path]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(stderr.contains(path), "{stderr}");
    assert!(stderr.contains("already exists"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "# mine\n");
    // A symlink, even one to nothing, is a name taken.
    #[cfg(unix)]
    {
        let link = dir.join("link.toml");
        std::os::unix::fs::symlink(dir.join("nowhere.toml"), &link).unwrap();
        let out = massprop(&["init", link.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2));
        assert!(!dir.join("nowhere.toml").exists());
    }
    // Nothing left behind: no temporary file.
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(names.iter().all(|n| !n.contains(".tmp")), "{names:?}");
}
