//! Issue 35: loading cases, and the body moving (`[analysis] velocity`).
//! Expected values are derived by hand here, never pasted from a run.

use crate::common::{massprop, report_json, report_json_file};
use serde_json::Value;

fn num(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

fn triple(v: &Value) -> [f64; 3] {
    std::array::from_fn(|j| num(&v[j]))
}

/// |value − want| within the value's own error bound (and a few ulps).
fn within(v: &Value, key: &str, want: &[f64]) {
    let (value, bound) = (&v[key], &v["error_bounds"][key]);
    for (j, w) in want.iter().enumerate() {
        let (x, b) = match value {
            Value::Array(_) => (num(&value[j]), num(&bound[j])),
            _ => (num(value), num(bound)),
        };
        assert!(
            (x - w).abs() <= b + 4.0 * f64::EPSILON * w.abs(),
            "{key}[{j}]: {x} is not {w} within {b}"
        );
    }
}

/// A 2 kg box 1 × 2 × 3 m centred at (1, 0, 0), about the origin.
const BOX: &str = "[[part]]\nshape = \"box\"\nmass = 2\nsize = [1, 2, 3]\ncenter = [1, 0, 0]\n[analysis]\nabout = [0, 0, 0]\n";

#[test]
fn the_bent_plate_turning_about_a_still_o_gives_todays_h_and_t_bit_for_bit() {
    let path = std::path::Path::new("shapes/bent-plate.toml");
    let (today, _) = report_json_file(path, &[]);
    let (still, _) = report_json_file(path, &["--velocity", "0,0,0"]);
    assert_eq!(today["kinetic_energy"], still["kinetic_energy"]);
    assert_eq!(today["angular_momentum"], still["angular_momentum"]);
    assert_eq!(
        today["error_bounds"]["kinetic_energy"],
        still["error_bounds"]["kinetic_energy"]
    );
    // The published T ≈ 8.25 J, by hand 15 · 0.55015625 J.
    within(&still, "kinetic_energy", &[8.25234375]);
}

#[test]
fn the_bent_plates_energy_splits_into_its_mass_centres_motion_and_the_turning_about_it() {
    let (v, _) = report_json_file(
        std::path::Path::new("shapes/bent-plate.toml"),
        &["--velocity", "0,0,0"],
    );
    // v̄ = ω × r with ω = 30 k and r the centre of mass (m, from O):
    // (−30 y, 30 x, 0); by hand from the file's comment.
    let m = 1.6625;
    let c = [
        0.7875 * 0.0375 / m,
        (0.875 * 0.0625 + 0.7875 * 0.125) / m,
        (0.875 * 0.05 + 0.7875 * 0.075) / m,
    ];
    let vbar = [-30.0 * c[1], 30.0 * c[0], 0.0];
    within(&v, "velocity_com", &vbar);
    let t_trans = 0.5 * m * (vbar[0] * vbar[0] + vbar[1] * vbar[1]);
    let tol = 1e-12;
    assert!((num(&v["kinetic_energy_translational"]) - t_trans).abs() < tol);
    let t_rot = 8.25234375 - t_trans;
    assert!((num(&v["kinetic_energy_rotational"]) - t_rot).abs() < tol);
}

#[test]
fn a_box_moving_and_turning_has_the_momenta_and_energies_derived_by_hand() {
    let (v, _) = report_json(BOX, &["--omega", "0,0,3", "--velocity", "0,1,0"]);
    // r = (1, 0, 0): ω × r = (0, 3, 0), v̄ = (0, 4, 0), G = m v̄ = (0, 8, 0).
    within(&v, "velocity", &[0.0, 1.0, 0.0]);
    within(&v, "velocity_com", &[0.0, 4.0, 0.0]);
    within(&v, "linear_momentum", &[0.0, 8.0, 0.0]);
    // I_G,zz = m (1² + 2²)/12 = 5/6: H_G = (0, 0, 2.5); H_O = H_G + r × G
    // = (0, 0, 2.5 + 8).
    within(&v, "angular_momentum_com", &[0.0, 0.0, 2.5]);
    within(&v, "angular_momentum", &[0.0, 0.0, 10.5]);
    // T = ½ · 2 · 16 + ½ · 3 · 2.5.
    within(&v, "kinetic_energy_translational", &[16.0]);
    within(&v, "kinetic_energy_rotational", &[3.75]);
    within(&v, "kinetic_energy", &[19.75]);
}

#[test]
fn a_body_translating_without_turning_has_half_m_v_squared_and_r_cross_g() {
    let (v, _) = report_json(BOX, &["--omega", "0,0,0", "--velocity", "0,0,5"]);
    within(&v, "kinetic_energy", &[25.0]);
    within(&v, "kinetic_energy_rotational", &[0.0]);
    // r × G = (1, 0, 0) × (0, 0, 10) = (0, −10, 0).
    within(&v, "angular_momentum", &[0.0, -10.0, 0.0]);
}

#[test]
fn in_any_direction_h_about_the_point_is_h_g_plus_r_cross_g_and_t_is_the_sum() {
    let (v, _) = report_json(
        BOX,
        &["--omega", "0.3,-1.2,2.5", "--velocity", "-4,0.5,1.75"],
    );
    let (r, g, hg) = (
        triple(&v["center_of_mass_ref"]),
        triple(&v["linear_momentum"]),
        triple(&v["angular_momentum_com"]),
    );
    let rxg = [
        r[1] * g[2] - r[2] * g[1],
        r[2] * g[0] - r[0] * g[2],
        r[0] * g[1] - r[1] * g[0],
    ];
    let h: Vec<f64> = (0..3).map(|j| hg[j] + rxg[j]).collect();
    let h_got = triple(&v["angular_momentum"]);
    for j in 0..3 {
        assert!((h_got[j] - h[j]).abs() < 1e-12, "{h_got:?} vs {h:?}");
    }
    let sum = num(&v["kinetic_energy_translational"]) + num(&v["kinetic_energy_rotational"]);
    assert!((num(&v["kinetic_energy"]) - sum).abs() < 1e-12 * sum);
}

#[test]
fn a_velocity_with_units_per_component_is_the_same_velocity() {
    let mm = BOX.replace("[[part]]", "units = { length = \"mm\" }\n[[part]]");
    let (a, _) = report_json(&mm, &["--omega", "0,0,1", "--velocity", "0,0,3000"]);
    let (b, _) = report_json(&mm, &["--omega", "0,0,1", "--velocity", "0,0,3 m/s"]);
    assert_eq!(a["velocity"], b["velocity"]);
    within(&a, "velocity", &[0.0, 0.0, 3.0]);
    let file = format!("{mm}omega = [0, 0, 1]\nvelocity = [0, 0, \"3 m/s\"]\n");
    let (c, _) = report_json(&file, &[]);
    assert_eq!(a["linear_momentum"], c["linear_momentum"]);
}

#[test]
fn without_a_velocity_the_report_has_none_of_the_motions_keys() {
    let (v, _) = report_json(BOX, &["--omega", "0,0,3"]);
    for key in [
        "velocity",
        "velocity_com",
        "linear_momentum",
        "angular_momentum_com",
        "kinetic_energy_translational",
        "kinetic_energy_rotational",
    ] {
        assert!(v.get(key).is_none(), "{key}");
        assert!(v["error_bounds"].get(key).is_none(), "{key}");
    }
}

#[test]
fn a_velocity_without_omega_is_refused_at_its_key() {
    let path = std::env::temp_dir().join(format!("massprop-v-{}.toml", std::process::id()));
    std::fs::write(&path, format!("{BOX}velocity = [1, 0, 0]\n")).unwrap();
    let out = massprop(&["report", path.to_str().unwrap()]);
    std::fs::remove_file(&path).ok();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(":8:12: error: `velocity` needs `omega`"),
        "{err}"
    );
}

#[test]
fn check_compares_the_motions_expectations() {
    let text = format!(
        "{BOX}omega = [0, 0, 3]\nvelocity = [0, 1, 0]\n[expect]\nlinear_momentum = {{ value = [0, 8, 0], tol = 1e-9 }}\nkinetic_energy_translational = {{ value = 16.5, tol = 1e-9 }}\n"
    );
    let path = std::env::temp_dir().join(format!("massprop-vx-{}.toml", std::process::id()));
    std::fs::write(&path, text).unwrap();
    let out = massprop(&["check", path.to_str().unwrap()]);
    std::fs::remove_file(&path).ok();
    assert_eq!(out.status.code(), Some(1));
    let err =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("kinetic_energy_translational 16 J is outside 16.5 J"),
        "{err}"
    );
    assert!(!err.contains("linear_momentum"), "{err}");
}

/// A point of `mass` kg at `x` m, on axles at `front` and `rear` m along
/// x, with `extra` in `[analysis]`.
fn on_axles(mass: f64, x: f64, front: &str, rear: &str, extra: &str) -> Value {
    let text = format!(
        "[[part]]\nshape = \"point\"\nmass = {mass}\ncenter = [{x}, 0.3, -2]\n[analysis]\naxles = {{ axis = \"x\", front = {front}, rear = {rear} }}\n{extra}"
    );
    report_json(&text, &[]).0
}

#[test]
fn axle_loads_are_the_statics_of_a_beam_on_two_supports() {
    // 1000 kg at x = 0.3 on axles at 1.5 and −0.5: moments about the rear
    // axle, F_f · 2 = W · 0.8, so 40 % front and 60 % rear.
    let v = on_axles(1000.0, 0.3, "1.5", "-0.5", "");
    let a = &v["axle_loads"];
    let w = 1000.0 * 9.80665;
    assert!((num(&a["front"]["share"]) - 0.4).abs() < 1e-15);
    assert!((num(&a["rear"]["share"]) - 0.6).abs() < 1e-15);
    assert!((num(&a["front"]["load"]) - 0.4 * w).abs() < 1e-9);
    assert!((num(&a["rear"]["load"]) - 0.6 * w).abs() < 1e-9);
    assert_eq!(num(&a["front"]["position"]), 1.5);
    assert_eq!(num(&a["rear"]["position"]), -0.5);
}

#[test]
fn axle_positions_take_units_and_g_replaces_standard_gravity() {
    let a = on_axles(10.0, 0.3, "\"1500 mm\"", "\"-50 cm\"", "g = 10\n");
    let a = &a["axle_loads"];
    assert_eq!(num(&a["front"]["position"]), 1.5);
    assert!((num(&a["front"]["load"]) - 40.0).abs() < 1e-12);
    assert!((num(&a["rear"]["load"]) - 60.0).abs() < 1e-12);
}

#[test]
fn a_centre_of_mass_behind_the_rear_axle_gives_the_front_a_negative_load() {
    let v = on_axles(1.0, -1.5, "1.5", "-0.5", "");
    let a = &v["axle_loads"];
    assert!(num(&a["front"]["load"]) < 0.0);
    let sum = num(&a["front"]["share"]) + num(&a["rear"]["share"]);
    assert!((sum - 1.0).abs() < 1e-15);
}

#[test]
fn the_axle_axis_is_one_of_the_report_axes() {
    // Report axes turned a quarter about z: their x is the file's y, where
    // the point is at 0.3; axles at ±1 along it share it 65 / 35.
    let v = on_axles(
        1.0,
        7.0,
        "1",
        "-1",
        "axes = { x = [0, 1, 0], y = [-1, 0, 0] }\n",
    );
    let a = &v["axle_loads"];
    assert!((num(&a["front"]["share"]) - 0.65).abs() < 1e-15);
}

#[test]
fn without_axles_the_report_has_no_axle_loads() {
    let (v, _) = report_json(BOX, &[]);
    assert!(v.get("axle_loads").is_none());
}

#[test]
fn the_table_gives_the_axle_loads_in_newtons_kilograms_and_percent() {
    let out = massprop(&["report", "shapes/car.toml"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("axle loads (g = 9.80665 m/s²)"), "{text}");
    // The car's front share by hand: (281500/1330 + 1250) / 2600.
    let share = (281500.0 / 1330.0 + 1250.0) / 2600.0;
    let kg = format!("{:.3}", 1330.0 * share);
    assert!(text.contains(&kg), "{kg} not in\n{text}");
    assert!(text.contains("56.2175"), "{text}");
}

// ---- Loading cases (`[[case]]`, issue 35 item 1) ----

/// A report's JSON without its `source` (the files compared differ in it).
fn body_of(mut v: Value) -> Value {
    v.as_object_mut().expect("an object").remove("source");
    v
}

/// A small aircraft-like body: parameters used by expressions, an
/// array, a group, and its cases.
const LOADED: &str = r#"units = { length = "mm", mass = "kg" }
[params]
fuel = "120 kg"
crew = "80 kg"
arm = "300 mm"

[[part]]
name = "airframe"
shape = "box"
mass = 600
size = [6000, 1200, 1000]
center = [0, 0, 0]

[[part]]
name = "pilot"
shape = "point"
mass = "crew"
center = ["-arm", 0, 200]
group = "payload/crew"

[[part]]
name = "tank"
shape = "cylinder"
mass = "fuel"
radius = 200
length = 800
center = ["2 * arm", 0, -100]

[[part]]
name = "box"
shape = "box"
mass = 10
size = [100, 100, 100]
center = [-2000, 0, 0]
array = { count = 3, step = [250, 0, 0] }
group = "payload/cargo"
"#;

/// The cases of `LOADED`, appended.
const CASES: &str = r#"
[[case]]
name = "ferry"
params = { fuel = "200 kg", arm = "350 mm" }
without = ["pilot"]

[[case]]
name = "light"
without_groups = ["payload"]

[[case]]
name = "two boxes"
without = ["box[1]"]
"#;

#[test]
fn a_case_is_the_file_edited_by_hand_to_it_bit_for_bit() {
    let file = format!("{LOADED}{CASES}");
    let (case, _) = report_json(&file, &["--case", "ferry"]);
    // Edited by hand: the parameters' definitions replaced, the pilot's
    // table deleted.
    let edited = LOADED
        .replace("fuel = \"120 kg\"", "fuel = \"200 kg\"")
        .replace("arm = \"300 mm\"", "arm = \"350 mm\"");
    let start = edited.find("[[part]]\nname = \"pilot\"").unwrap();
    let end = edited.find("[[part]]\nname = \"tank\"").unwrap();
    let edited = format!("{}{}", &edited[..start], &edited[end..]);
    assert!(!edited.contains("pilot") && edited.contains("200 kg"));
    let (plain, _) = report_json(&edited, &[]);
    assert_eq!(body_of(case), body_of(plain));
}

#[test]
fn a_case_without_groups_drops_every_part_under_them() {
    let file = format!("{LOADED}{CASES}");
    let (case, _) = report_json(&file, &["--case", "light"]);
    // The pilot (payload/crew) and the boxes (payload/cargo) gone: the
    // airframe and the tank, by hand.
    let (m, x) = (600.0 + 120.0, 120.0 * 0.6 / 720.0);
    assert_eq!(num(&case["mass"]), m);
    within(&case, "center_of_mass", &[x, 0.0, -120.0 * 0.1 / 720.0]);
}

#[test]
fn a_case_without_one_copy_keeps_the_others() {
    let file = format!("{LOADED}{CASES}");
    let (case, _) = report_json(&file, &["--case", "two boxes"]);
    // The boxes at x = −2000 and −1500 mm stay, −1750 goes: by hand.
    let m = 600.0 + 80.0 + 120.0 + 20.0;
    let x = (80.0 * -0.3 + 120.0 * 0.6 + 10.0 * (-2.0 - 1.5)) / m;
    assert_eq!(num(&case["mass"]), m);
    within(
        &case,
        "center_of_mass",
        &[x, 0.0, (80.0 * 0.2 - 120.0 * 0.1) / m],
    );
}

#[test]
fn every_object_of_cases_json_is_that_cases_own_report() {
    let file = format!("{LOADED}{CASES}");
    let (all, _) = report_json(&file, &["--cases"]);
    let list = all["cases"].as_array().expect("`cases` is an array");
    let names: Vec<&str> = list.iter().map(|c| c["case"].as_str().unwrap()).collect();
    assert_eq!(names, ["ferry", "light", "two boxes"], "file order");
    for object in list {
        let name = object["case"].as_str().unwrap();
        let (one, _) = report_json(&file, &["--case", name]);
        let mut object = object.clone();
        object.as_object_mut().unwrap().remove("case");
        assert_eq!(body_of(object), body_of(one), "case {name}");
    }
}

#[test]
fn the_base_stays_the_top_level_of_cases_json() {
    let file = format!("{LOADED}{CASES}");
    let (all, _) = report_json(&file, &["--cases"]);
    let (plain, _) = report_json(&file, &[]);
    let mut top = all.clone();
    top.as_object_mut().unwrap().remove("cases");
    assert_eq!(body_of(top), body_of(plain));
}

#[test]
fn a_file_with_cases_reports_its_base_as_it_did_without_them() {
    let (with, _) = report_json(&format!("{LOADED}{CASES}"), &[]);
    let (without, _) = report_json(LOADED, &[]);
    assert_eq!(body_of(with), body_of(without));
}

#[test]
fn cases_reach_an_included_file_through_its_params() {
    let wheel = "[params]\nrim_mass = \"5 kg\"\n[[part]]\nname = \"rim\"\nshape = \"point\"\nmass = \"rim_mass\"\ncenter = [0, 0, 0]\n";
    let car = "[params]\nw = \"5 kg\"\n[[part]]\nname = \"hub\"\ninclude = \"wheel.toml\"\nparams = { rim_mass = \"w\" }\norigin = [1, 0, 0]\n[[part]]\nname = \"frame\"\nshape = \"point\"\nmass = 15\ncenter = [0, 0, 0]\n[[case]]\nname = \"heavy\"\nparams = { w = \"25 kg\" }\n[[case]]\nname = \"bare\"\nwithout = [\"hub / rim\"]\n";
    let path = crate::common::scratch_files(
        "cases",
        "include",
        &[("wheel.toml", wheel), ("car.toml", car)],
    );
    let (heavy, _) = report_json_file(&path, &["--case", "heavy"]);
    assert_eq!(num(&heavy["mass"]), 40.0);
    assert_eq!(triple(&heavy["center_of_mass"])[0], 25.0 / 40.0);
    let (bare, _) = report_json_file(&path, &["--case", "bare"]);
    assert_eq!(num(&bare["mass"]), 15.0);
}

#[test]
fn cases_json_and_table_give_each_cases_axle_loads() {
    let file = format!(
        "{BOX}axles = {{ axis = \"x\", front = 2, rear = 0 }}\n[[part]]\nname = \"load\"\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 0]\n[[case]]\nname = \"unloaded\"\nwithout = [\"load\"]\n"
    );
    let (all, _) = report_json(&file, &["--cases"]);
    // Base: 4 kg at x = 0.5 → front share 0.25; unloaded: 2 kg at 1 → 0.5.
    assert_eq!(num(&all["axle_loads"]["front"]["share"]), 0.25);
    let case = &all["cases"][0];
    assert_eq!(num(&case["axle_loads"]["front"]["share"]), 0.5);
    assert!((num(&case["axle_loads"]["rear"]["load"]) - 2.0 * 9.80665 * 0.5).abs() < 1e-12);
    let dir = crate::common::scratch_files("cases", "axles", &[("a.toml", &file)]);
    let out = massprop(&["report", "--cases", dir.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("front (%)") && text.contains("unloaded"),
        "{text}"
    );
    let row = text.lines().find(|l| l.contains("unloaded")).unwrap();
    assert!(row.contains(" 50 ") && row.contains("9.80665"), "{row}");
}

/// `:LINE:COL: error:` of the first `needle` in `text`, as a message
/// begins.
fn at(text: &str, needle: &str) -> String {
    let start = text
        .find(needle)
        .unwrap_or_else(|| panic!("{needle} in the file"));
    let line = text[..start].matches('\n').count() + 1;
    let col = text[..start].rfind('\n').map_or(start, |n| start - n - 1) + 1;
    format!(":{line}:{col}: error:")
}

/// `massprop report ARGS… FILE` on `text`: refused with status 2, nothing
/// on stdout; its stderr.
fn refused(text: &str, args: &[&str]) -> String {
    static COUNT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = COUNT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let path = crate::common::scratch_files("cases", &format!("refused-{n}"), &[("f.toml", text)]);
    let mut argv = vec!["report"];
    argv.extend(args);
    argv.push(path.to_str().unwrap());
    let out = massprop(&argv);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty(), "{stderr}");
    stderr
}

#[test]
fn an_unknown_name_in_without_is_a_located_error_with_a_suggestion() {
    let file = format!("{LOADED}{CASES}").replace("[\"pilot\"]", "[\"pilto\"]");
    let e = refused(&file, &[]);
    assert!(
        e.contains(&at(&file, "\"pilto\"")) && e.contains("`pilto`"),
        "{e}"
    );
    assert!(
        e.contains("did you mean `pilot`?") && e.contains("case `ferry`"),
        "{e}"
    );
}

#[test]
fn an_unknown_group_is_a_located_error_with_a_suggestion() {
    let file = format!("{LOADED}{CASES}").replace("[\"payload\"]", "[\"payload/crw\"]");
    let e = refused(&file, &[]);
    assert!(
        e.contains(&at(&file, "\"payload/crw")) && e.contains("did you mean `payload/crew`?"),
        "{e}"
    );
}

#[test]
fn an_unknown_parameter_of_a_case_is_a_located_error_with_a_suggestion() {
    let file = format!("{LOADED}{CASES}").replace("fuel = \"200", "fule = \"200");
    let e = refused(&file, &[]);
    assert!(
        e.contains(&at(&file, "fule")) && e.contains("`fule`"),
        "{e}"
    );
    assert!(e.contains("did you mean `fuel`?"), "{e}");
}

#[test]
fn two_cases_of_one_name_are_a_located_error() {
    let file = format!("{LOADED}{CASES}").replace("\"light\"", "\"ferry\"");
    let e = refused(&file, &[]);
    let second = file.rfind("\"ferry\"").unwrap();
    let line = file[..second].matches('\n').count() + 1;
    assert!(
        e.contains(&format!(":{line}:8: error:")) && e.contains("`ferry`"),
        "{e}"
    );
}

#[test]
fn an_unknown_key_of_a_case_is_a_located_error_with_a_suggestion() {
    let file = format!("{LOADED}{CASES}").replace("without_groups", "without_group");
    let e = refused(&file, &[]);
    assert!(
        e.contains(&at(&file, "without_group ")) && e.contains("did you mean `without_groups`?"),
        "{e}"
    );
}

#[test]
fn an_unknown_case_on_the_command_line_names_the_flag_and_suggests() {
    let e = refused(&format!("{LOADED}{CASES}"), &["--case", "feryy"]);
    assert!(
        e.contains("`--case feryy`") && e.contains("did you mean `ferry`?"),
        "{e}"
    );
}

/// `LOADED` with an expectation of the `ferry` case that fails: 200 kg
/// of fuel and no pilot weigh 600 + 200 + 30 = 830 kg, not 900.
fn failing() -> String {
    format!("{LOADED}{CASES}").replace(
        "without = [\"pilot\"]\n",
        "without = [\"pilot\"]\nexpect = { mass = { value = 900, tol = 1 } }\n",
    )
}

#[test]
fn check_names_the_case_in_every_format() {
    let file = failing();
    let path = crate::common::scratch_files("cases", "check-formats", &[("f.toml", &file)]);
    let p = path.to_str().unwrap();
    let place = at(&file, "{ value = 900").replace(": error:", "");
    for format in ["table", "json", "github", "junit", "sarif"] {
        let out = massprop(&["check", "--format", format, p]);
        let text = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(1), "{format}: {text}");
        assert!(
            text.contains("case `ferry`: mass 830 kg is outside 900 kg"),
            "{format}: {text}"
        );
        if format == "table" {
            assert!(text.contains(&format!("{p}{place}")), "{text}");
        }
    }
    let out = massprop(&["check", "--format", "json", p]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let checks = v["files"][0]["checks"].as_array().unwrap();
    assert_eq!(checks.len(), 1);
    assert_eq!(checks[0]["case"], "ferry");
    assert_eq!(checks[0]["measured"], 830.0);
    let junit =
        String::from_utf8_lossy(&massprop(&["check", "--format", "junit", p]).stdout).to_string();
    assert!(junit.contains("name=\"ferry: mass\""), "{junit}");
}

#[test]
fn check_holds_the_files_own_expect_against_the_base_not_a_case() {
    // The base weighs 600 + 80 + 120 + 30 = 830 kg too: the file's own
    // `[expect]` of 830 passes while the case's 900 fails.
    let file = format!(
        "{}\n[expect]\nmass = {{ value = 830, tol = 1e-9 }}\n",
        failing()
    );
    let path = crate::common::scratch_files("cases", "check-base", &[("f.toml", &file)]);
    let out = massprop(&["check", "--format", "json", path.to_str().unwrap()]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let checks = v["files"][0]["checks"].as_array().unwrap();
    let pass: Vec<(Option<&str>, bool)> = checks
        .iter()
        .map(|c| (c["case"].as_str(), c["pass"].as_bool().unwrap()))
        .collect();
    assert_eq!(pass, [(None, true), (Some("ferry"), false)]);
}

#[test]
fn bless_writes_each_cases_expect_into_its_own_table() {
    let file = failing();
    let path = crate::common::scratch_files("cases", "bless", &[("f.toml", &file)]);
    let p = path.to_str().unwrap();
    let out = massprop(&["check", "--bless", p]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let blessed = std::fs::read_to_string(&path).unwrap();
    // The case's inline table has the case's mass; the file gained its
    // own `[expect]` (it had none) with the base's.
    assert!(
        blessed.contains("expect = { mass = { value = 830"),
        "{blessed}"
    );
    let doc: toml::Table = blessed.parse().unwrap();
    let case = &doc["case"].as_array().unwrap()[0];
    assert_eq!(case["expect"]["mass"]["value"].as_float(), Some(830.0));
    assert_eq!(doc["expect"]["mass"]["value"].as_float(), Some(830.0));
    assert_eq!(massprop(&["check", p]).status.code(), Some(0));
}

#[test]
fn a_case_with_its_own_values_passed_in_is_that_case() {
    use massprop::analysis::cases;
    let file = format!("{LOADED}{CASES}");
    let source = massprop::diag::Source::new("f.toml", file.clone());
    let settings = massprop::analysis::Settings::default();
    let model = massprop::model::Model::parse(&source).unwrap();
    let ferry = &model.cases[0];
    let names: Vec<&str> = ferry.params.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["arm", "fuel"]);
    assert_eq!(ferry.params[1].si, 200.0);
    // Half way from the base's 120 kg of fuel to the ferry's 200 kg.
    let half = massprop::model::case::value_like(&ferry.params[1].value, 160.0);
    let values = [("fuel".to_string(), half)];
    let mid = cases::load_with(source.clone(), &settings, Some("ferry"), &values).unwrap();
    assert_eq!(mid.summary.mass, 600.0 + 160.0 + 30.0);
    let same = [
        ("fuel".to_string(), ferry.params[1].value),
        ("arm".to_string(), ferry.params[0].value),
    ];
    let again = cases::load_with(source.clone(), &settings, Some("ferry"), &same).unwrap();
    let case = cases::load_case(source, &settings, "ferry").unwrap();
    assert_eq!(again.summary.center_of_mass, case.summary.center_of_mass);
    assert_eq!(again.summary.inertia_com, case.summary.inertia_com);
}

/// A seat (a 70 kg point at its origin, group `crew`) and a crate of
/// cargo, included; the seat twice by an array.
const SEAT: &str = "[[part]]\nname = \"occupant\"\nshape = \"point\"\nmass = 70\ncenter = [0, 0, 0]\ngroup = \"crew\"\n[[part]]\nname = \"cushion\"\nshape = \"point\"\nmass = 5\ncenter = [0, 0, 0]\n";

fn cabin(case: &str) -> String {
    format!(
        "[[part]]\nname = \"floor\"\nshape = \"point\"\nmass = 100\ncenter = [0, 0, 0]\n[[part]]\nname = \"seat\"\ninclude = \"seat.toml\"\norigin = [1, 0, 0]\narray = {{ count = 2, step = [1, 0, 0] }}\ngroup = \"cabin\"\n[[case]]\n{case}\n"
    )
}

#[test]
fn a_case_without_one_copy_of_a_sub_assembly_keeps_the_other() {
    let file = cabin("name = \"one seat\"\nwithout = [\"seat[1]\"]");
    let path = crate::common::scratch_files(
        "cases",
        "seat-copy",
        &[("seat.toml", SEAT), ("cabin.toml", &file)],
    );
    let (v, _) = report_json_file(&path, &["--case", "one seat"]);
    // The floor at 0 and the first seat's 75 kg at x = 1: by hand.
    assert_eq!(num(&v["mass"]), 175.0);
    within(&v, "center_of_mass", &[75.0 / 175.0, 0.0, 0.0]);
}

#[test]
fn a_case_without_a_group_reaches_into_a_sub_assembly() {
    // `cabin/crew`: each seat's occupant (its group under the include's).
    let file = cabin("name = \"empty\"\nwithout_groups = [\"cabin/crew\"]");
    let path = crate::common::scratch_files(
        "cases",
        "seat-group",
        &[("seat.toml", SEAT), ("cabin.toml", &file)],
    );
    let (v, _) = report_json_file(&path, &["--case", "empty"]);
    // The floor and two 5 kg cushions at x = 1 and 2.
    assert_eq!(num(&v["mass"]), 110.0);
    within(&v, "center_of_mass", &[15.0 / 110.0, 0.0, 0.0]);
    // A path inside a copy of a sub-assembly, by name.
    let file = cabin("name = \"x\"\nwithout = [\"seat[0] / occupant\"]");
    let path = crate::common::scratch_files(
        "cases",
        "seat-path",
        &[("seat.toml", SEAT), ("cabin.toml", &file)],
    );
    let (v, _) = report_json_file(&path, &["--case", "x"]);
    assert_eq!(num(&v["mass"]), 180.0);
    within(
        &v,
        "center_of_mass",
        &[(5.0 + 75.0 * 2.0) / 180.0, 0.0, 0.0],
    );
}

#[test]
fn an_ambiguous_name_in_without_asks_for_the_path() {
    let file = cabin("name = \"x\"\nwithout = [\"occupant\"]");
    let path = crate::common::scratch_files(
        "cases",
        "seat-ambiguous",
        &[("seat.toml", SEAT), ("cabin.toml", &file)],
    );
    let out = massprop(&["report", path.to_str().unwrap()]);
    let e = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{e}");
    assert!(
        e.contains("is ambiguous") && e.contains("`seat[0] / occupant`"),
        "{e}"
    );
}
