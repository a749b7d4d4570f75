//! Plausibility warnings (issue 31, item 4): a file without `units` whose
//! parts span more than 100 m or weigh more than 100 t, a density outside
//! 1–25,000 kg/m³ after conversion, a robot link whose radius of gyration
//! its geometry cannot hold. Each is a warning on standard error and in
//! the JSON `warnings`, never a change of result, and `[analysis]
//! warnings = false` silences a file's. The expected spans, factors and
//! radii are worked out here from the files' numbers.

use crate::common::{massprop, massprop_stdin, scratch_files};
use serde_json::Value;

/// A desk lamp in millimetres: a cast base (Ø 200, 20 high), a tube arm
/// of 160 up from it (z from 20 to 180), a cone shade (Ø 150, z from 125
/// to 175). Without `units` the base is 200 m across, the widest extent of
/// the parts: x and y from −100 to 100, z from 0 to 180.
const LAMP: &str = r#"[[part]]
name = "base"
shape = "cylinder"
material = "aluminium-6061"
radius = 100
length = 20
center = [0, 0, 10]

[[part]]
name = "arm"
shape = "cylinder"
material = "steel"
radius = 6
inner_radius = 5
length = 160
center = [0, 0, 100]

[[part]]
name = "shade"
shape = "cone"
material = "aluminium-6061"
radius = 75
top_radius = 20
inner_radius = 74
top_inner_radius = 19
length = 50
center = [0, 0, 150]
"#;

fn run(args: &[&str], text: &str) -> (String, String, Option<i32>) {
    let out = massprop_stdin(args, text);
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
        out.status.code(),
    )
}

fn json_of(text: &str) -> (Value, String) {
    let (stdout, stderr, status) = run(&["report", "--format", "json", "-"], text);
    assert_eq!(status, Some(0), "{stderr}");
    (serde_json::from_str(&stdout).unwrap(), stderr)
}

fn warnings(v: &Value) -> Vec<Value> {
    v["warnings"].as_array().cloned().unwrap_or_default()
}

#[test]
fn the_lamp_in_millimetres_without_units_is_warned_of_at_its_first_part() {
    let (v, stderr) = json_of(LAMP);
    let w = warnings(&v);
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(w[0]["kind"], "units");
    assert_eq!(
        (w[0]["line"].as_u64(), w[0]["column"].as_u64()),
        (Some(1), Some(1))
    );
    let message = w[0]["message"].as_str().unwrap();
    assert!(message.contains("span 200 m"), "{message}");
    assert!(
        message.contains("lengths are read in metres")
            && message.contains("did you mean `units = { length = \"mm\" }`?"),
        "{message}"
    );
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("warning: "), "{stderr}");
    assert!(
        stderr.contains(":1:1: ") && stderr.contains(message),
        "{stderr}"
    );
}

#[test]
fn the_lamp_with_its_units_is_not_warned_of() {
    let (v, stderr) = json_of(&format!("units = {{ length = \"mm\" }}\n{LAMP}"));
    assert_eq!(v.get("warnings"), None);
    assert_eq!(stderr, "");
}

#[test]
fn a_warning_changes_no_result() {
    let (warned, _) = json_of(LAMP);
    let (silent, _) = json_of(&format!("{LAMP}[analysis]\nwarnings = false\n"));
    let mut without = warned.clone();
    without.as_object_mut().unwrap().remove("warnings");
    assert_eq!(without, silent);
}

/// `text`'s JSON with its `"warnings":[…]` entry cut out, by a scanner of
/// the text (strings skipped), not by the writer.
fn cut_warnings(text: &str) -> String {
    let key = ",\"warnings\":[";
    let Some(start) = text.find(key) else {
        return text.to_string();
    };
    let (mut depth, mut in_string, mut escaped) = (0, false, false);
    for (i, c) in text[start + key.len() - 1..].char_indices() {
        match (in_string, escaped, c) {
            (true, true, _) => escaped = false,
            (true, false, '\\') => escaped = true,
            (true, false, '"') => in_string = false,
            (true, false, _) => {}
            (false, _, '"') => in_string = true,
            (false, _, '[' | '{') => depth += 1,
            (false, _, ']' | '}') => {
                depth -= 1;
                if depth == 0 {
                    let end = start + key.len() - 1 + i + 1;
                    return format!("{}{}", &text[..start], &text[end..]);
                }
            }
            (false, _, _) => {}
        }
    }
    panic!("unclosed warnings in {text}")
}

#[test]
fn warnings_false_silences_the_file_and_leaves_its_json_byte_identical() {
    let args = ["report", "--format", "json", "-"];
    let (warned, stderr, _) = run(&args, LAMP);
    assert!(stderr.contains("warning: "), "{stderr}");
    let (silent, stderr, status) = run(&args, &format!("{LAMP}[analysis]\nwarnings = false\n"));
    assert_eq!((stderr.as_str(), status), ("", Some(0)));
    assert!(warned.contains(",\"warnings\":["), "{warned}");
    assert_eq!(cut_warnings(&warned), silent);
}

#[test]
fn warnings_true_is_the_default() {
    let (v, _) = json_of(&format!("{LAMP}[analysis]\nwarnings = true\n"));
    assert_eq!(warnings(&v).len(), 1);
}

#[test]
fn warnings_that_is_not_a_boolean_is_refused_at_its_value() {
    let (stdout, stderr, status) = run(
        &["report", "-"],
        &format!("{LAMP}[analysis]\nwarnings = \"no\"\n"),
    );
    assert_eq!((stdout.as_str(), status), ("", Some(2)));
    let line = LAMP.lines().count() + 2;
    assert!(
        stderr.contains(&format!(":{line}:12:"))
            && stderr.contains("`warnings`")
            && stderr.contains("boolean"),
        "{stderr}"
    );
}

/// A box of 10 × 10 × 10 mm at density `rho`, in a file in mm and g.
fn cube(rho: &str) -> String {
    format!(
        "units = {{ length = \"mm\", mass = \"g\" }}\n[[part]]\nshape = \"box\"\ndensity = {rho}\nsize = [10, 10, 10]\ncenter = [0, 0, 0]\n"
    )
}

fn density_warnings(text: &str) -> Vec<Value> {
    let (v, _) = json_of(text);
    warnings(&v)
        .into_iter()
        .filter(|w| w["kind"] == "density")
        .collect()
}

#[test]
fn a_density_below_1_kg_per_cubic_metre_is_warned_of_at_its_key() {
    let w = density_warnings(&cube("\"0.9 kg/m^3\""));
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(
        (w[0]["line"].as_u64(), w[0]["column"].as_u64()),
        (Some(4), Some(1))
    );
    assert!(
        w[0]["message"].as_str().unwrap().contains("0.9 kg/m³"),
        "{w:?}"
    );
}

#[test]
fn a_density_of_1_kg_per_cubic_metre_is_not() {
    assert_eq!(density_warnings(&cube("\"1 kg/m^3\"")), Vec::<Value>::new());
}

#[test]
fn a_density_of_25000_kg_per_cubic_metre_is_not() {
    assert_eq!(
        density_warnings(&cube("\"25000 kg/m^3\"")),
        Vec::<Value>::new()
    );
}

#[test]
fn a_density_above_25000_kg_per_cubic_metre_is_warned_of() {
    let w = density_warnings(&cube("\"25001 kg/m^3\""));
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0]["message"].as_str().unwrap().contains("25001 kg/m³"),
        "{w:?}"
    );
}

#[test]
fn a_plain_density_is_judged_in_the_files_units() {
    // 0.0027 g/mm³ = 0.0027 × 10⁻³ kg / 10⁻⁹ m³ = 2700 kg/m³: aluminium.
    assert_eq!(density_warnings(&cube("0.0027")), Vec::<Value>::new());
    // 2700 g/mm³ = 2700 × 10⁶ kg/m³: kg/m³ written in a file in g and mm.
    let w = density_warnings(&cube("2700"));
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0]["message"].as_str().unwrap().contains("2.7e9 kg/m³"),
        "{w:?}"
    );
}

#[test]
fn a_material_of_the_file_outside_the_range_is_warned_of_at_its_name() {
    let text = "[materials]\nfoam = { density = 0.5 }\n[[part]]\nshape = \"box\"\nmaterial = \"foam\"\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n";
    let w = density_warnings(text);
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(
        (w[0]["line"].as_u64(), w[0]["column"].as_u64()),
        (Some(2), Some(1))
    );
    assert!(
        w[0]["message"].as_str().unwrap().contains("`foam`"),
        "{w:?}"
    );
}

#[test]
fn a_heavy_file_without_units_is_told_of_grams() {
    // 200 t of point masses 1 m apart: mass in grams read as kilograms.
    let text = "[[part]]\nshape = \"point\"\nmass = 100000\ncenter = [0, 0, 0]\n[[part]]\nshape = \"point\"\nmass = 100000\ncenter = [1, 0, 0]\n";
    let (v, _) = json_of(text);
    let w = warnings(&v);
    assert_eq!(w.len(), 1, "{w:?}");
    let message = w[0]["message"].as_str().unwrap();
    assert!(
        message.contains("weigh 200000 kg") && message.contains("mass = \"g\""),
        "{message}"
    );
}

const ARM_MM: &str = "units = { length = \"mm\" }\n[[part]]\nshape = \"box\"\nmass = 0.4\nsize = [300, 20, 20]\ncenter = [150, 0, 0]\n";
const ARM_NO_UNITS: &str =
    "[[part]]\nshape = \"box\"\nmass = 0.4\nsize = [300, 20, 20]\ncenter = [150, 0, 0]\n";
const TOP: &str = "[[part]]\nname = \"base\"\nshape = \"box\"\nmass = 2\nsize = [0.2, 0.2, 0.02]\ncenter = [0, 0, 0]\n\n[[part]]\nname = \"arm\"\ninclude = \"arm.toml\"\norigin = [0, 0, 0.1]\n";

#[test]
fn a_sub_assembly_in_mm_included_from_a_metre_file_is_fine() {
    let top = scratch_files(
        "plausible",
        "included-mm",
        &[("arm.toml", ARM_MM), ("top.toml", TOP)],
    );
    let out = massprop(&["report", top.to_str().unwrap()]);
    assert!(out.status.success());
    assert_eq!(String::from_utf8_lossy(&out.stderr), "");
}

#[test]
fn a_sub_assembly_without_units_is_warned_of_at_its_include() {
    let top = scratch_files(
        "plausible",
        "included-no-units",
        &[("arm.toml", ARM_NO_UNITS), ("top.toml", TOP)],
    );
    let out = massprop(&["report", top.to_str().unwrap()]);
    assert!(out.status.success());
    let stderr = String::from_utf8(out.stderr).unwrap();
    // The arm's own parts span 300 m (its box's length): the top file's
    // parts, 0.2 m, are fine; the warning points at the include (line 8).
    // (A body 300 m long also has axes not certified to `--rtol`.)
    let plausible: Vec<&str> = stderr.lines().filter(|l| !l.contains("--rtol")).collect();
    assert_eq!(plausible.len(), 1, "{stderr}");
    assert!(
        stderr.contains("top.toml:8:1: ")
            && stderr.contains("the sub-assembly `arm` has no `units`")
            && stderr.contains("span 300 m"),
        "{stderr}"
    );
}

#[test]
fn check_carries_the_warnings_in_its_json_and_on_standard_error() {
    let (stdout, stderr, status) = run(&["check", "--format", "json", "-"], LAMP);
    assert_eq!(status, Some(0), "{stderr}");
    let v: Value = serde_json::from_str(&stdout).unwrap();
    let w = &v["files"][0]["warnings"];
    assert_eq!(w[0]["kind"], "units", "{v}");
    assert!(stderr.contains("did you mean `units"), "{stderr}");
}

#[test]
fn github_annotations_place_the_warning_at_its_line() {
    let (stdout, _, _) = run(&["check", "--format", "github", "-"], LAMP);
    assert!(
        stdout.contains("::warning ")
            && stdout.contains("line=1,col=1")
            && stdout.contains("plausibility::"),
        "{stdout}"
    );
}

#[test]
fn no_file_in_shapes_is_warned_of() {
    let mut files: Vec<_> = std::fs::read_dir("shapes")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() > 10);
    for f in files {
        let out = massprop(&["report", "--format", "json", f.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!stderr.contains("warning: "), "{}: {stderr}", f.display());
        if out.status.success() {
            let v: Value = serde_json::from_slice(&out.stdout).unwrap();
            assert_eq!(v.get("warnings"), None, "{}", f.display());
        }
    }
}

/// A URDF of one link with a box of `size` as its visual, `mass` kg and
/// the diagonal tensor `i`.
fn urdf(mass: f64, i: [f64; 3], geometry: &str) -> String {
    format!(
        "<robot name='r'><link name='l'>{geometry}<inertial><mass value='{mass}'/><inertia ixx='{}' ixy='0' ixz='0' iyy='{}' iyz='0' izz='{}'/></inertial></link></robot>",
        i[0], i[1], i[2]
    )
}

fn robot_stderr(name: &str, text: &str) -> String {
    let dir = scratch_files("plausible", name, &[("r.urdf", text)]);
    let out = massprop(&["check", dir.to_str().unwrap()]);
    String::from_utf8(out.stderr).unwrap() + &String::from_utf8(out.stdout).unwrap()
}

const CUBE: &str = "<visual><geometry><box size='0.1 0.1 0.1'/></geometry></visual>";

#[test]
fn a_link_in_grams_and_millimetres_squared_is_warned_of_with_its_factor() {
    // A 1 kg cube of 0.1 m: I = m (a² + a²)/12 = 1/600 kg·m², written ×1e9.
    let i = 1e9 / 600.0;
    let text = robot_stderr("robot-1", &urdf(1.0, [i; 3], CUBE));
    let k = (1.0f64 / 600.0).sqrt();
    assert!((k - 0.0408).abs() < 5e-5);
    assert_eq!(text.matches("radius of gyration").count(), 1, "{text}");
    assert!(
        text.contains("g·mm²: ×1e-9 gives 0.0408 m")
            && text.contains("no engine checked refuses it"),
        "{text}"
    );
}

#[test]
fn the_same_link_in_kilograms_and_metres_is_not() {
    let i = 1.0 / 600.0;
    let text = robot_stderr("robot-2", &urdf(1.0, [i; 3], CUBE));
    assert!(!text.contains("radius of gyration"), "{text}");
}

#[test]
fn a_link_without_geometry_is_held_to_10_m() {
    // 10 kg, I3 = 0.5 kg·m² written in kg·mm²: k = √(5e5/10) = 224 m,
    // and ×1e-6 gives √(0.05) = 0.224 m.
    let text = robot_stderr("robot-3", &urdf(10.0, [5e5, 5e5, 2e5], ""));
    assert!(
        text.contains("is 224 m, more than 10 m") && text.contains("kg·mm²: ×1e-6 gives 0.224 m"),
        "{text}"
    );
    // 9.9 m of radius of gyration without geometry passes.
    let text = robot_stderr("robot-4", &urdf(1.0, [98.01, 98.01, 98.01], ""));
    assert!(!text.contains("radius of gyration"), "{text}");
}

#[test]
fn a_link_an_engine_refuses_is_warned_of_once_naming_it() {
    // Moments 1e6, 1e6 and 2e6 + 1e-9 (g·mm² of a flat plate): A + B < C
    // by a hair, which MuJoCo refuses (no tolerance) and Gazebo and Drake
    // accept (theirs is ~1e-9 here).
    let text = robot_stderr("robot-5", &urdf(1.0, [1e6, 1e6, 2000000.000000001], CUBE));
    assert_eq!(text.matches("radius of gyration").count(), 1, "{text}");
    assert!(text.contains("; refused by mujoco\n"), "{text}");
}

#[test]
fn massprop_schema_gives_analysis_warnings_as_a_boolean() {
    let out = massprop(&["schema"]);
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        v["$defs"]["Analysis"]["properties"]["warnings"]["type"],
        "boolean"
    );
    let validator = jsonschema::validator_for(&v).unwrap();
    let file = |w: &str| -> Value {
        let t: toml::Table =
            toml::from_str(&format!("{LAMP}[analysis]\nwarnings = {w}\n")).unwrap();
        serde_json::to_value(t).unwrap()
    };
    assert!(validator.is_valid(&file("false")));
    assert!(!validator.is_valid(&file("\"no\"")));
}

/// A row of copies is the body: 150 boxes a metre apart span 150 m, so a
/// file without `units` is warned of, though each box is a metre; 50 of
/// them span 50 m and are not.
#[test]
fn copies_count_in_the_span_of_a_file_without_units() {
    let row = |n: u32| {
        format!(
            "[[part]]\nname = \"slat\"\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\narray = {{ count = {n}, step = [1, 0, 0] }}\n"
        )
    };
    let (v, _) = json_of(&row(150));
    let w = warnings(&v);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0]["message"].as_str().unwrap().contains("span 150 m"),
        "{w:?}"
    );
    let (v, _) = json_of(&row(50));
    assert_eq!(v.get("warnings"), None);
}

/// Mirror images count too: a box 60 m off the plane and its image span
/// 121 m.
#[test]
fn a_mirror_image_counts_in_the_span_of_a_file_without_units() {
    let text = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [60, 0, 0]\nmirror = { normal = [1, 0, 0] }\n";
    let (v, _) = json_of(text);
    let w = warnings(&v);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0]["message"].as_str().unwrap().contains("span 121 m"),
        "{w:?}"
    );
}
