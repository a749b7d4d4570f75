//! `massprop schema` and `massprop init` (issue 14, item 3): the JSON
//! Schema accepts every part file the reader accepts (the examples, the
//! test catalogue's valid files, `init`'s starter), rejects misspelt keys
//! and shapes, and agrees with the reader shape by shape, key by key — so
//! the two cannot drift apart. A property test (issue 28) writes part
//! files of every shape and key from the shape table, each value in the
//! forms the reader takes, and holds the schema to accepting every one
//! the reader accepts.

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
        "capsule" => vec![
            "mass = 1\nradius = 10\nlength = 30\ncenter = [0, 0, 0]",
            "density = \"1 g/cm^3\"\ndiameter = 20\ninner_diameter = 18\nlength = 30\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 90 }",
            "material = \"steel\"\nradius = 10\ninner_radius = 9\nlength = 30\ncenter = [0, 0, 0]",
        ],
        "ellipsoid" => vec![
            "mass = 1\nradii = [10, 20, 30]\ncenter = [0, 0, 0]",
            "density = \"1 g/cm^3\"\nradii = [\"1 cm\", 20, 5]\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 90 }",
            "material = \"steel\"\nradii = [10, 10, 4]\ncenter = [0, 0, 0]",
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
        "radii" => "[1, 2, 3]",
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
        "joints" => "{ elbow = \"30 deg\" }",
        "file" => "\"shapes/meshes/bracket.stl\"",
        "mesh_unit" => "\"mm\"",
        "mode" => "\"shell\"",
        "weld" => "\"0.001 mm\"",
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

/// A number written as a string without a unit, where the number has no
/// dimension (an array's `count` and `step_degrees`, a parameter), is read
/// by the reader and so taken by the schema; on a key with a dimension it
/// is neither (it needs its unit).
#[test]
fn a_unitless_number_string_is_taken_where_the_reader_takes_it() {
    let point = "shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]";
    for text in [
        one_part(&format!(
            "{point}\narray = {{ count = \"32\", step = [1, 0, 0] }}"
        )),
        one_part(&format!(
            "{point}\narray = {{ count = \" 4 \", axis = [0, 0, 1], step_degrees = \"30\" }}"
        )),
        format!("{}\n[params]\nn = \"24\"\n", one_part(point)),
    ] {
        assert_eq!(reader(&text), Ok(()), "{text}");
        assert_eq!(schema_errors(&text), Vec::<String>::new(), "{text}");
    }
    both_reject(&one_part(
        "shape = \"point\"\nmass = \"3\"\ncenter = [0, 0, 0]",
    ));
}

/// An expression is a value, a bound and a tolerance in `[expect]` to the
/// reader, and so to the schema.
#[test]
fn an_expression_in_expect_is_taken_as_the_reader_takes_it() {
    let text = format!(
        "{}\n[expect]\nmass = {{ value = \"2 * 0.5 kg\", tol = \"1 g * 10\" }}\ncenter_of_mass = {{ max = [\"1 m / 2\", 1, \"(1 + 1) * m\"] }}\n",
        one_part("shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]")
    );
    assert_eq!(reader(&text), Ok(()), "{text}");
    assert_eq!(schema_errors(&text), Vec::<String>::new());
}

/// `·` multiplies in an expression, and a name may be in any script.
#[test]
fn a_middle_dot_and_a_name_in_any_script_are_expressions_to_the_schema() {
    let quantity = json!({ "$ref": "#/$defs/Quantity", "$defs": SCHEMA["$defs"] });
    let v = jsonschema::validator_for(&quantity).unwrap();
    for e in ["2·leg", "länge", "mm²", "Δx_2"] {
        assert!(v.is_valid(&json!(e)), "{e:?}");
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

// ---------------------------------------------------------------------------
// Drift: generated part files of every shape and key, in every form the
// reader takes. Whenever the reader accepts a file, the schema must too.

use massprop::shapes::{MaterialRule, ShapeInfo, Spanned as Spans};
use massprop::units::Dim;

/// Choices drawn from proptest's bytes: shrinking the bytes toward zero
/// makes each choice the first (simplest) one, so a failure shrinks to a
/// small file.
struct Picker<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Picker<'_> {
    /// A number below `n`.
    fn below(&mut self, n: usize) -> usize {
        let b = self.bytes.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        usize::from(b) % n.max(1)
    }

    /// One chance in `n` (never, once the bytes are shrunk to zeros).
    fn one_in(&mut self, n: usize) -> bool {
        self.below(n) == 1
    }

    fn of<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.below(xs.len())]
    }
}

/// The units a quantity of `dim` may be written in, with their factors
/// to SI: every symbol of the unit table of that dimension, and compound
/// units in each spelling the unit reader takes.
fn units_of(dim: Dim) -> Vec<(String, f64)> {
    let compound: &[&str] = if dim == Dim::DENSITY {
        &[
            "kg/m^3", "g/cm^3", "g/cm³", "kg/L", "g/mL", "kg m^-3", "kg·m^-3", "g/mm3", "lb/in^3",
            "kg / m^3",
        ]
    } else if dim == Dim::AREAL_DENSITY {
        &["kg/m^2", "g/cm²", "kg·m^-2", "g/mm2", "kg*m^-2"]
    } else if dim == Dim::LINEAR_DENSITY {
        &["kg/m", "g/mm", "kg m^-1", "lb/ft"]
    } else if dim == Dim::INERTIA {
        &["kg*m^2", "kg m^2", "g·mm²", "kg*m2", "lb in^2", "kg * m^2"]
    } else if dim == Dim::AREA {
        &["mm^2", "m²", "cm2", "in^2", "mm*mm"]
    } else if dim == Dim::ANGULAR_VELOCITY {
        &["rad/s", "deg/s", "1/s", "rev/min", "rad s^-1"]
    } else if dim == Dim::ANGULAR_ACCELERATION {
        &["rad/s^2", "deg/s^2", "rad/s²", "1/s^2", "rpm/s"]
    } else {
        &[]
    };
    let mut out: Vec<(String, f64)> = massprop::units::symbol_names()
        .map(str::to_string)
        .chain(compound.iter().map(|c| c.to_string()))
        .filter_map(|u| {
            let unit = massprop::units::parse_unit(&u).ok()?;
            (unit.dim == dim).then(|| (u, unit.factor.value()))
        })
        .collect();
    // Each compound spelling is one the reader takes (else the list above
    // has a typo and tests nothing).
    for c in compound {
        assert!(
            out.iter().any(|(u, _)| u == c),
            "`{c}` is no unit of {dim:?}"
        );
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// A number as TOML writes it: an integer when whole and small, else the
/// shortest float.
fn toml_number(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{}", x as i64)
    } else {
        format!("{x:?}")
    }
}

/// What a key holds, for the generator: the reader's own kinds of value.
#[derive(Clone, Copy)]
enum Kind {
    /// A quantity of a dimension (a number in the file's units, or a
    /// string: quantity, expression, parameter, tolerance).
    Quantity(Dim),
    /// A whole number (`count`): a number or a unitless string.
    Count,
    /// A plain number of degrees (`step_degrees`).
    Degrees,
}

/// The file being made: its units, its parameters, its lines.
struct Gen<'a, 'b> {
    p: &'a mut Picker<'b>,
    /// The file's units.
    units: massprop::units::FileUnits,
    /// `[params]` lines, in order (a parameter may use those before it).
    params: Vec<String>,
    /// Whether the file has `[growth]` (a maturity to name) and
    /// `[materials]` (a material to name).
    growth: bool,
    foam: bool,
}

impl Gen<'_, '_> {
    /// SI per file unit of `dim`.
    fn file_factor(&self, dim: Dim) -> f64 {
        self.units.factor(dim).value()
    }

    /// A quantity of `dim` whose value is about `si` (SI), in one of the
    /// forms the reader takes for it, or one it refuses (the property
    /// holds only where the reader accepts).
    fn quantity(&mut self, si: f64, kind: Kind) -> String {
        let dim = match kind {
            Kind::Quantity(d) => d,
            Kind::Count | Kind::Degrees => Dim::DIMENSIONLESS,
        };
        let plain = si
            / if dim == Dim::DIMENSIONLESS {
                1.0
            } else {
                self.file_factor(dim)
            };
        // A whole number or a plain number of degrees takes no unit.
        let units = if dim == Dim::DIMENSIONLESS {
            Vec::new()
        } else {
            units_of(dim)
        };
        let (u, uf) = if units.is_empty() {
            (String::new(), 1.0)
        } else {
            let (u, f) = self.p.of(&units
                .iter()
                .map(|(u, f)| (u.as_str(), *f))
                .collect::<Vec<_>>());
            (u.to_string(), f)
        };
        let n = toml_number(si / uf);
        let half = toml_number(si / uf / 2.0);
        let q = |text: String| format!("\"{text}\"");
        // What multiplies by the unit (by 1 where there is none).
        let by = if u.is_empty() {
            "1".to_string()
        } else {
            u.clone()
        };
        // Half of them plain numbers; the forms the reader takes only on
        // some keys (a tolerance, a number string without its unit) rarely,
        // so that most files are read and reach the schema.
        let form = if self.p.one_in(2) {
            0
        } else {
            self.p.below(17)
        };
        let form = match form {
            6 if !self.p.one_in(20) => 1,
            7 | 8 if dim != Dim::DIMENSIONLESS && !self.p.one_in(20) => 1,
            f => f,
        };
        match form {
            0 => toml_number(plain),
            1 => q(format!("{n} {u}")),
            2 => q(format!("{n}{u}")),
            3 => q(format!("{half} {u} * 2")),
            4 => q(format!("({half} + {half}) * {by}")),
            5 => {
                // A parameter, in any of these forms itself.
                // A parameter written as a plain number is a plain number,
                // not one in the file's units.
                let mut value = self.quantity(si, kind);
                if dim != Dim::DIMENSIONLESS && !value.starts_with(['"', '\'']) {
                    value = q(format!("{n} {u}"));
                }
                let mut name = format!("p{}", self.params.len());
                // A name in another script, a quoted key in TOML.
                if self.p.one_in(4) {
                    name = format!("länge_{name}");
                }
                self.params.push(format!("\"{name}\" = {value}"));
                match self.p.below(3) {
                    0 => q(name),
                    1 => q(format!("{name} * 1")),
                    _ => q(format!("  {name}  ")),
                }
            }
            6 => {
                let tol = match self.p.below(4) {
                    0 => format!("{} {u}", toml_number(si / uf / 100.0)),
                    1 => "2 %".to_string(),
                    2 => "1% uniform".to_string(),
                    _ => format!("{} {u} normal", toml_number(si / uf / 50.0)),
                };
                let pm = self.p.of(&["±", "+/-", " ± "]);
                q(format!("{n} {u} {pm} {tol}"))
            }
            7 => q(toml_number(plain)),
            8 => q(format!(" {}  ", toml_number(plain))),
            9 => format!("'{n} {u}'"),
            10 => q(format!("{:e} {u}", si / uf)),
            11 => q(format!("+{n} {u}")),
            // NOTE: not for zero: the reader calls "0·kg*m^2" too small
            // (the exponent's digit read as the number's), a reader bug.
            12 if si != 0.0 => q(format!("{n}·{by}")),
            12 => q(format!("{n} {u}")),
            13 => q(format!("{n} {u} * sqrt(1)")),
            14 => q(format!("{n} * {by}")),
            15 => q(format!("max({n} {u}, {half} {u})")),
            // A unit alone is one of it (`"mm²"`, `"kg/m^3"`).
            _ if !u.is_empty() => q(u.clone()),
            _ => q(format!("abs(-{n})")),
        }
    }

    /// `[a, b, c]` of quantities of `kind` about `si` each.
    fn vector(&mut self, si: [f64; 3], kind: Kind) -> String {
        let items: Vec<String> = si.iter().map(|x| self.quantity(*x, kind)).collect();
        format!("[{}]", items.join(", "))
    }

    /// A rotation table in one of its forms.
    fn rotation(&mut self) -> String {
        let angle = toml_number(self.p.of(&[30.0, 90.0, -45.5, 0.0, 1e-3]));
        match self.p.below(6) {
            0 => format!("{{ axis = [0, 0, 1], degrees = {angle} }}"),
            1 => "{ quaternion = [1, 0, 0, 0] }".to_string(),
            2 => "{ quaternion = [0.5, 0.5, 0.5, 0.5] }".to_string(),
            3 => "{ matrix = [[0, -1, 0], [1, 0, 0], [0, 0, 1]] }".to_string(),
            4 => format!(
                "{{ {} = \"{}\", degrees = [{angle}, 10, 20.5] }}",
                self.p.of(&["intrinsic", "extrinsic"]),
                self.p.of(&["zyx", "ZYX", "xyz", "zxz", "XzY"])
            ),
            // Refused by the reader (a string angle), rarely.
            _ if self.p.one_in(10) => format!("{{ axis = [1, 1, 0], degrees = \"{angle}\" }}"),
            _ => format!("{{ axis = [1, 1, 0], degrees = {angle} }}"),
        }
    }

    /// The value of a length in metres.
    fn len(&mut self, si: f64) -> String {
        self.quantity(si, Kind::Quantity(Dim::LENGTH))
    }

    fn point(&mut self, si: [f64; 3]) -> String {
        self.vector(si, Kind::Quantity(Dim::LENGTH))
    }
}

const LENGTH: Kind = Kind::Quantity(Dim::LENGTH);

impl Gen<'_, '_> {
    /// A part of shape `s`, placed and weighed as its entry in `SHAPES`
    /// says it may be, each key in one of its forms, with the keys every
    /// part may have (`name`, copies, the weight statement's, `tol`).
    fn part(&mut self, s: &ShapeInfo) -> Vec<String> {
        let mut lines = vec![format!("shape = \"{}\"", s.name)];
        let mode_shell = s.sizes.contains(&"file") && self.p.one_in(3);
        // Weighed by `mass`, its density or a material (with what turns
        // the material's density into the shape's).
        let mut weighs = vec!["mass"];
        weighs.extend(s.density.map(|d| d.key));
        if s.material != MaterialRule::None {
            weighs.push("material");
        }
        if mode_shell {
            weighs = vec!["mass", "areal_density", "thickness"];
        }
        let by = self.p.of(&weighs);
        let mut by_mass = false;
        match by {
            "mass" => {
                by_mass = true;
                let m = self.quantity(2.0, Kind::Quantity(Dim::MASS));
                lines.push(format!("mass = {m}"));
            }
            "material" => {
                let name = if self.foam && self.p.one_in(2) {
                    "foam"
                } else {
                    "steel"
                };
                lines.push(format!("material = \"{name}\""));
                match s.material {
                    MaterialRule::Thickness => {
                        lines.push(format!("thickness = {}", self.len(0.002)))
                    }
                    MaterialRule::Section => {
                        if self.p.one_in(2) {
                            let a = self.quantity(3e-6, Kind::Quantity(Dim::AREA));
                            lines.push(format!("area = {a}"));
                        } else {
                            lines.push(format!("diameter = {}", self.len(0.002)));
                        }
                    }
                    MaterialRule::Volume | MaterialRule::None => {}
                }
            }
            "thickness" => {
                lines.push(format!("thickness = {}", self.len(0.001)));
                let d = self.quantity(2700.0, Kind::Quantity(Dim::DENSITY));
                lines.push(format!("density = {d}"));
            }
            key => {
                let dim = [
                    ("density", Dim::DENSITY),
                    ("areal_density", Dim::AREAL_DENSITY),
                    ("linear_density", Dim::LINEAR_DENSITY),
                ]
                .into_iter()
                .find(|(k, _)| *k == key)
                .map(|(_, d)| d)
                .expect("a density key");
                let si = if dim == Dim::DENSITY {
                    2700.0
                } else if dim == Dim::AREAL_DENSITY {
                    5.0
                } else {
                    0.04
                };
                let d = self.quantity(si, Kind::Quantity(dim));
                lines.push(format!("{key} = {d}"));
            }
        }
        if mode_shell {
            lines.push(format!("mode = \"{}\"", "shell"));
        } else if s.sizes.contains(&"file") && self.p.one_in(3) {
            lines.push("mode = \"solid\"".to_string());
        }
        // A solid mesh's `weld` (issue 30): far below the bracket's sizes.
        if !mode_shell && s.sizes.contains(&"file") && self.p.one_in(3) {
            lines.push(format!("weld = {}", self.len(1e-7)));
        }
        let spanned = self.dims(s, &mut lines);
        // The real size of an idealised shape.
        if let Some((key, _)) = s.real_size
            && !lines
                .iter()
                .any(|l| l.starts_with(&format!("{key} ")) || l.starts_with("area "))
            && self.p.one_in(3)
        {
            lines.push(format!("{key} = {}", self.len(0.002)));
        }
        if s.keys.contains(&"rotation") && !spanned && self.p.one_in(2) {
            lines.push(format!("rotation = {}", self.rotation()));
        }
        self.common(&mut lines, by_mass, s.keys.contains(&"remove"));
        lines
    }

    /// The sizes and the placement, as `s.sizes`, `s.centred` and
    /// `s.spanned` say; whether it is the spanned placement.
    fn dims(&mut self, s: &ShapeInfo, lines: &mut Vec<String>) -> bool {
        let spanned = s.spanned.filter(|_| self.p.one_in(2));
        if let Some(spanned) = spanned {
            match spanned {
                Spans::CornerEdges(n) => {
                    lines.push(format!("corner = {}", self.point([0.0, 0.01, -0.02])));
                    let axes = [[0.01, 0.0, 0.0], [0.0, 0.02, 0.0], [0.0, 0.0, 0.03]];
                    let edges: Vec<String> = axes[..n].iter().map(|e| self.point(*e)).collect();
                    lines.push(format!("edges = [{}]", edges.join(", ")));
                }
                Spans::FromTo => {
                    lines.push(format!("from = {}", self.point([0.0, 0.0, 0.0])));
                    lines.push(format!("to = {}", self.point([0.0, 0.0, 0.1])));
                }
            }
            return true;
        }
        let by_diameter = s.keys.contains(&"diameter") && s.real_size.is_none() && self.p.one_in(2);
        let radius = |g: &mut Self, lines: &mut Vec<String>, si: f64| {
            if by_diameter {
                lines.push(format!("diameter = {}", g.len(2.0 * si)));
            } else {
                lines.push(format!("radius = {}", g.len(si)));
            }
        };
        let inner = |g: &mut Self, lines: &mut Vec<String>, si: f64| {
            if by_diameter {
                lines.push(format!("inner_diameter = {}", g.len(2.0 * si)));
            } else {
                lines.push(format!("inner_radius = {}", g.len(si)));
            }
        };
        // Each key that gives the shape's size, by its name.
        let has = |k: &str| s.sizes.contains(&k);
        // (A shape's own keys are written below, from their declarations.)
        let own = |k: &str| s.shape.own_keys().iter().any(|o| o.name == k);
        for key in s.sizes.iter().filter(|k| !own(k)) {
            match *key {
                "size" => {
                    let sizes: Vec<String> = [0.01, 0.02, 0.03][..s.size_items]
                        .iter()
                        .map(|x| self.len(*x))
                        .collect();
                    lines.push(format!("size = [{}]", sizes.join(", ")));
                }
                "length" => {
                    let l = match (has("radius"), has("polygon")) {
                        (_, true) => 0.02,
                        (true, false) => 0.05,
                        (false, false) => 0.1,
                    };
                    lines.push(format!("length = {}", self.len(l)));
                }
                "radius" if has("tube_radius") => {
                    lines.push(format!("radius = {}", self.len(0.1)));
                }
                "radius" => radius(self, lines, 0.01),
                // A cone's bore is given at both ends or at neither.
                "inner_radius" if self.p.one_in(2) => {
                    inner(self, lines, 0.005);
                    if has("top_inner_radius") {
                        lines.push(format!("top_inner_radius = {}", self.len(0.002)));
                    }
                }
                "inner_radius" | "top_inner_radius" => {}
                "top_radius" => lines.push(format!("top_radius = {}", self.len(0.004))),
                "tube_radius" => lines.push(format!("tube_radius = {}", self.len(0.02))),
                "inner_tube_radius" => {
                    if self.p.one_in(2) {
                        lines.push(format!("inner_tube_radius = {}", self.len(0.01)));
                    }
                }
                "vertices" => {
                    let v: Vec<String> = [[0.0, 0.0, 0.0], [0.01, 0.0, 0.0], [0.0, 0.01, 0.0]]
                        .iter()
                        .map(|p| self.point(*p))
                        .collect();
                    lines.push(format!("vertices = [{}]", v.join(", ")));
                }
                "inertia" => {
                    let i = Kind::Quantity(Dim::INERTIA);
                    let rows = [
                        self.vector([2e-3, 0.0, 0.0], i),
                        self.vector([0.0, 2e-3, 0.0], i),
                        self.vector([0.0, 0.0, 3e-3], i),
                    ];
                    lines.push(format!("inertia = [{}]", rows.join(", ")));
                    if self.p.one_in(2) {
                        lines.push(format!(
                            "products = \"{}\"",
                            self.p.of(&["tensor", "positive"])
                        ));
                    }
                }
                "polygon" => {
                    let l = LENGTH;
                    let v: Vec<String> = [[0.0, 0.0], [0.01, 0.0], [0.01, 0.01], [0.0, 0.02]]
                        .iter()
                        .map(|p| {
                            format!("[{}, {}]", self.quantity(p[0], l), self.quantity(p[1], l))
                        })
                        .collect();
                    lines.push(format!("polygon = [{}]", v.join(", ")));
                }
                "file" => {
                    lines.push("file = \"shapes/meshes/bracket.stl\"".to_string());
                    let unit = self.p.of(massprop::units::LENGTH_UNITS);
                    lines.push(format!("mesh_unit = \"{unit}\""));
                }
                // A new shape's key: this generator must learn to write it.
                other => panic!("{}: no generator for the size key `{other}`", s.name),
            }
        }
        // A shape's own keys (an ellipsoid's `radii`): lengths, each > 0.
        for key in s.shape.own_keys() {
            let massprop::shapes::Kind::Quantities(Some(n)) = key.kind else {
                panic!("`{}`: no sample for an own key of {:?}", key.name, key.kind)
            };
            assert_eq!(key.dim, Dim::LENGTH, "`{}`", key.name);
            let values: Vec<String> = (1..=n).map(|k| self.len(0.005 * k as f64)).collect();
            lines.push(format!("{} = [{}]", key.name, values.join(", ")));
        }
        if s.centred.contains(&"center") {
            lines.push(format!("center = {}", self.point([0.0, 0.01, 0.02])));
        }
        if s.keys.contains(&"origin") && self.p.one_in(2) {
            lines.push(format!("origin = {}", self.point([0.0, 0.01, 0.02])));
        }
        false
    }

    /// The keys any part may have.
    fn common(&mut self, lines: &mut Vec<String>, by_mass: bool, remove: bool) {
        if self.p.one_in(2) {
            let name = self
                .p
                .of(&["wheel", "Rad vorn", "\\u00e9t\\u00e9", "a/b", "x[1]", ""]);
            lines.push(format!("name = \"{name}\""));
        }
        if remove && self.p.one_in(4) {
            lines.push(format!("remove = {}", self.p.of(&["false", "true"])));
        }
        if self.p.one_in(3) {
            let g = self
                .p
                .of(&["structure", "propulsion/tanks", " a / b ", "x/y/z"]);
            lines.push(format!("group = \"{g}\""));
        }
        if self.growth && self.p.one_in(3) {
            lines.push("maturity = \"sample\"".to_string());
        }
        if by_mass && self.p.one_in(3) {
            let tol = match self.p.below(5) {
                0 => "0.1".to_string(),
                1 => "\"2 %\"".to_string(),
                2 => "\"± 0.1 kg uniform\"".to_string(),
                3 => "\"100 g\"".to_string(),
                _ => "\"0.1\"".to_string(),
            };
            lines.push(format!("tol = {tol}"));
        }
        if self.p.one_in(3) {
            let count = self.quantity(3.0, Kind::Count);
            let array = if self.p.one_in(2) {
                format!(
                    "{{ count = {count}, step = {} }}",
                    self.point([0.5, 0.0, 0.0])
                )
            } else {
                let step = self.quantity(30.0, Kind::Degrees);
                let origin = if self.p.one_in(2) {
                    format!(", origin = {}", self.point([1.0, 0.0, 0.0]))
                } else {
                    String::new()
                };
                format!("{{ count = {count}, axis = [0, 0, 1], step_degrees = {step}{origin} }}")
            };
            lines.push(format!("array = {array}"));
        } else if self.p.one_in(3) {
            let origin = if self.p.one_in(2) {
                format!(", origin = {}", self.point([1.0, 0.0, 0.0]))
            } else {
                String::new()
            };
            lines.push(format!("mirror = {{ normal = [1, 0, 0]{origin} }}"));
        }
    }

    /// A sub-assembly: an example file placed here.
    fn include(&mut self) -> Vec<String> {
        let mut lines = vec!["include = \"shapes/bent-plate.toml\"".to_string()];
        if self.p.one_in(2) {
            lines.push(format!("origin = {}", self.point([0.0, 0.0, 1.0])));
        }
        if self.p.one_in(2) {
            lines.push(format!("rotation = {}", self.rotation()));
        }
        self.common(&mut lines, false, false);
        lines
    }

    /// An `[expect]` entry of `key` (a vector or matrix when `n` is 3 or 9).
    fn expectation(&mut self, kind: Kind, n: usize) -> String {
        let value = |g: &mut Self, si: f64| {
            let mut one = || g.quantity(si, kind);
            match n {
                1 => one(),
                3 => format!("[{}, {}, {}]", one(), one(), one()),
                _ => {
                    let rows: Vec<String> = (0..3)
                        .map(|_| format!("[{}, {}, {}]", one(), one(), one()))
                        .collect();
                    format!("[{}]", rows.join(", "))
                }
            }
        };
        match self.p.below(4) {
            0 => {
                let tol = match self.p.below(5) {
                    0 => "0.5".to_string(),
                    1 => "\"0.5%\"".to_string(),
                    2 => "\" 1 %\"".to_string(),
                    3 => "\"5%%\"".to_string(),
                    _ => self.quantity(0.01, kind),
                };
                format!("{{ value = {}, tol = {tol} }}", value(self, 1.0))
            }
            1 => format!("{{ max = {} }}", value(self, 1.0)),
            2 => format!(
                "{{ min = {}, max = {} }}",
                value(self, 0.5),
                value(self, 2.0)
            ),
            _ => format!("{{ min = {} }}", value(self, 1.0)),
        }
    }
}

/// A whole part file: `[units]`, `[params]`, `[materials]`, `[growth]`,
/// `[budget]`, `[analysis]`, parts of the shapes drawn (or includes) and
/// `[expect]`, each key in one of the forms its reader takes.
fn generated_file(bytes: &[u8]) -> String {
    let mut p = Picker { bytes, at: 0 };
    let units = if p.one_in(2) {
        massprop::units::FileUnits {
            length: p.of(massprop::units::LENGTH_UNITS),
            mass: p.of(massprop::units::MASS_UNITS),
        }
    } else {
        massprop::units::FileUnits::default()
    };
    let explicit_units = units != massprop::units::FileUnits::default() || p.one_in(4);
    let growth = p.one_in(3);
    let foam = p.one_in(3);
    let mut g = Gen {
        p: &mut p,
        units,
        params: Vec::new(),
        growth,
        foam,
    };
    let mut head = Vec::new();
    if explicit_units {
        head.push(format!(
            "units = {{ length = \"{}\", mass = \"{}\" }}",
            units.length, units.mass
        ));
    }
    if g.p.one_in(4) {
        head.push(format!("name = \"{}\"", g.p.of(&["sat", "a b", ""])));
    }
    let mut tables = Vec::new();
    if foam {
        let d = g.quantity(30.0, Kind::Quantity(Dim::DENSITY));
        tables.push(format!("[materials]\nfoam = {{ density = {d} }}"));
    }
    if growth {
        let pct =
            g.p.of(&["5 %", "5%", " 15 % ", "+5%", "5.%", "1e1 %", ".5%", "0 %"]);
        tables.push(format!("[growth]\nsample = \"{pct}\""));
    }
    if g.p.one_in(4) {
        let limit = g.quantity(100.0, Kind::Quantity(Dim::MASS));
        tables.push(format!("[budget]\nlimit = {limit}"));
    }
    let omega = g.p.one_in(3);
    if omega || g.p.one_in(3) {
        let mut a = vec!["[analysis]".to_string()];
        if g.p.one_in(2) {
            a.push(format!("about = {}", g.point([0.0, 0.0, 0.1])));
        }
        if omega {
            let w = g.vector([0.0, 0.0, 10.0], Kind::Quantity(Dim::ANGULAR_VELOCITY));
            a.push(format!("omega = {w}"));
            if g.p.one_in(2) {
                let al = g.vector([0.0, 1.0, 0.0], Kind::Quantity(Dim::ANGULAR_ACCELERATION));
                a.push(format!("alpha = {al}"));
            }
        }
        if g.p.one_in(3) {
            let axes = if g.p.one_in(2) {
                "{ x = [0, 1, 0], y = [-1, 0, 0] }".to_string()
            } else {
                g.rotation()
            };
            a.push(format!("axes = {axes}"));
        }
        tables.push(a.join("\n"));
    }
    let mut parts = Vec::new();
    for _ in 0..=g.p.below(3) {
        let lines = if g.p.one_in(8) {
            g.include()
        } else {
            let s = g.p.of(&SHAPES);
            g.part(&s)
        };
        parts.push(format!("[[part]]\n{}", lines.join("\n")));
    }
    if g.p.one_in(3) {
        let l = Kind::Quantity(Dim::LENGTH);
        let i = Kind::Quantity(Dim::INERTIA);
        let mut e = vec!["[expect]".to_string()];
        for (key, kind, n) in [
            ("mass", Kind::Quantity(Dim::MASS), 1),
            ("center_of_mass", l, 3),
            ("principal_moments", i, 3),
            ("inertia_com", i, 9),
            ("radii_of_gyration", l, 3),
            ("Ixx", i, 1),
            (
                "kinetic_energy",
                Kind::Quantity(Dim::ENERGY),
                if omega { 1 } else { 0 },
            ),
            ("predicted_mass", Kind::Quantity(Dim::MASS), 1),
        ] {
            if n > 0 && g.p.one_in(3) {
                let entry = g.expectation(kind, n);
                e.push(format!("{key} = {entry}"));
            }
        }
        if g.p.one_in(4) {
            // Axes, unit and at right angles, within an angle.
            let axes = g.p.of(&[
                "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]",
                "[[0, 0, -1], [0.6, 0.8, 0], [-0.8, 0.6, 0]]",
            ]);
            let tol = g.p.of(&["0.5", "0", "10"]);
            e.push(format!(
                "principal_axes = {{ value = {axes}, tol_degrees = {tol} }}"
            ));
        }
        if !e.iter().any(|l| l.starts_with("center_of_mass ")) && g.p.one_in(3) {
            let entry = g.expectation(l, 1);
            e.push(format!("center_of_mass.z = {entry}"));
        }
        tables.push(e.join("\n"));
    }
    let mut text = head.join("\n");
    if !g.params.is_empty() {
        text.push_str(&format!("\n[params]\n{}\n", g.params.join("\n")));
    }
    for t in tables {
        text.push_str(&format!("\n{t}\n"));
    }
    for part in parts {
        text.push_str(&format!("\n{part}\n"));
    }
    text
}

/// Whenever the reader accepts a generated file (every shape, every key,
/// each in the forms the reader takes: numbers, quantity strings in every
/// unit of the unit table, expressions, parameters, tolerances, unitless
/// number strings), the schema accepts it: the schema never refuses what
/// massprop reads.
#[test]
fn the_schema_never_refuses_a_generated_file_the_reader_accepts() {
    let accepted = crate::hostile::property(
        "the schema never refuses what the reader accepts",
        1000,
        proptest::collection::vec(proptest::prelude::any::<u8>(), 0..300),
        |bytes| {
            let text = generated_file(bytes);
            let Ok(table) = toml::from_str::<toml::Table>(&text) else {
                return Err(format!("the generator wrote bad TOML:\n{text}"));
            };
            if reader(&text).is_err() {
                return Ok(false);
            }
            let json = serde_json::to_value(table).unwrap();
            let errors: Vec<String> = VALIDATOR
                .iter_errors(&json)
                .map(|e| format!("{}: {e}", e.instance_path()))
                .collect();
            if errors.is_empty() {
                Ok(true)
            } else {
                Err(format!(
                    "the reader accepts, the schema refuses:\n{text}\n{}",
                    errors.join("\n")
                ))
            }
        },
    );
    // The property reaches the schema only through accepted files.
    assert!(accepted >= 500, "only {accepted} generated files accepted");
}

/// The generator draws every shape and every key of every shape.
#[test]
fn the_generator_writes_every_shape_and_every_key() {
    let mut seen = std::collections::BTreeSet::new();
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..3000 {
        let bytes: Vec<u8> = (0..300)
            .map(|_| {
                rng ^= rng << 13;
                rng ^= rng >> 7;
                rng ^= rng << 17;
                (rng >> 24) as u8
            })
            .collect();
        let table: toml::Table = toml::from_str(&generated_file(&bytes)).unwrap();
        for part in table
            .get("part")
            .and_then(|p| p.as_array())
            .into_iter()
            .flatten()
        {
            let t = part.as_table().unwrap();
            let shape = t.get("shape").and_then(|s| s.as_str()).unwrap_or("include");
            for k in t.keys() {
                seen.insert(format!("{shape}.{k}"));
            }
        }
    }
    for s in &SHAPES {
        for k in s
            .keys
            .iter()
            .chain(&["name", "array", "mirror", "group", "maturity"])
        {
            assert!(
                seen.contains(&format!("{}.{k}", s.name)),
                "never wrote `{k}` on a {}",
                s.name
            );
        }
    }
}
