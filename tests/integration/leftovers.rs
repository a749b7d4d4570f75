//! The second round's leftovers (issue 28, item 8): `check --bless`'s
//! default tolerances (from the value written, never zero), command-line
//! vectors below f64's range, `-o -` and `-o ""`, help that cannot be
//! written, `check - -`, and `materials` of a materials file.

use crate::common::{massprop, massprop_stdin, scratch, scratch_files};
use std::process::{Command, Stdio};

const BENT_PLATE: &str = "shapes/bent-plate.toml";

/// A box 2 × 4 × 6 m of density 1 kg/m³ (48 kg) at `center`.
///
/// Its moments about its centre: m(b² + c²)/12 = 48·52/12 = 208 kg·m²
/// about x, 48·40/12 = 160 about y, 48·20/12 = 80 about z; its largest
/// radius of gyration √(208/48) = √(52/12) ≈ 2.08 m.
fn box_at(center: &str, expect: &str) -> String {
    format!(
        "[[part]]\nname = \"b\"\nshape = \"box\"\nsize = [2, 4, 6]\ncenter = {center}\ndensity = 1\n{expect}"
    )
}

/// Bless the file `text` in a scratch directory; the blessed file, read
/// by the toml crate, and the exit status of `check` of it afterwards.
fn blessed(name: &str, text: &str) -> (toml::Table, Option<i32>) {
    let file = scratch_files("leftovers", name, &[("part.toml", text)]);
    let path = file.to_str().unwrap();
    let out = massprop(&["check", "--bless", path]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let written = std::fs::read_to_string(&file).unwrap();
    let table = toml::from_str(&written).unwrap_or_else(|e| panic!("{e}\n{written}"));
    let again = massprop(&["check", path]).status.code();
    (table, again)
}

/// `expect.KEY.tol` (a path of keys), as a number.
fn tol(t: &toml::Table, path: &[&str]) -> toml::Value {
    let mut v = &t["expect"];
    for k in path {
        v = &v[*k];
    }
    v["tol"].clone()
}

#[test]
fn bless_computes_a_missing_tolerance_from_the_new_value_not_the_stale_one() {
    // The stale value 1000 m would give 1e-3; the body's centre of mass
    // is at 10 m, larger than its size (2.08 m): 1e-6 × 10 m.
    let (t, again) = blessed(
        "stale",
        &box_at(
            "[10, 0, 0]",
            "\n[expect]\ncenter_of_mass = { value = [1000, 0, 0] }\n",
        ),
    );
    let value = t["expect"]["center_of_mass"]["value"].as_array().unwrap();
    assert_eq!(value[0].as_float(), Some(10.0));
    assert_eq!(tol(&t, &["center_of_mass"]).as_float(), Some(1e-5));
    assert_eq!(again, Some(0));
}

#[test]
fn a_new_expect_on_a_zero_centre_of_mass_gets_a_tolerance_from_the_bodys_size() {
    let (t, again) = blessed("zero-com", &box_at("[0, 0, 0]", ""));
    let value = t["expect"]["center_of_mass"]["value"].as_array().unwrap();
    assert!(value.iter().all(|v| v.as_float() == Some(0.0)), "{value:?}");
    // 1e-6 × √(52/12) m = 2.08e-6 m, to one digit.
    assert_eq!(tol(&t, &["center_of_mass"]).as_float(), Some(2e-6));
    // 1e-6 × 208 kg·m², to one digit.
    assert_eq!(tol(&t, &["principal_moments"]).as_float(), Some(2e-4));
    assert_eq!(tol(&t, &["mass"]).as_str(), Some("0.0001%"));
    assert_eq!(again, Some(0));
}

#[test]
fn a_component_on_a_zero_coordinate_gets_an_absolute_tolerance_not_a_relative_zero() {
    let (t, again) = blessed(
        "zero-component",
        &box_at(
            "[10, 0, 0]",
            "\n[expect]\ncenter_of_mass.x = { value = 3 }\ncenter_of_mass.y = { value = 5 }\nIxy = { value = 1 }\n",
        ),
    );
    // x = 10 m, larger than the body: relative, 1e-6 of itself.
    assert_eq!(tol(&t, &["center_of_mass", "x"]).as_str(), Some("0.0001%"));
    // y = 0: 1e-6 of the body's size, absolute.
    assert_eq!(tol(&t, &["center_of_mass", "y"]).as_float(), Some(2e-6));
    // A product of inertia of a box in its own axes is 0: 1e-6 × 208.
    assert_eq!(tol(&t, &["Ixy"]).as_float(), Some(2e-4));
    assert_eq!(again, Some(0));
}

#[test]
fn a_point_mass_at_the_origin_gets_a_millionth_of_the_files_unit() {
    // No size at all: the floor, 1e-6 of the unit the value is in (mm).
    let (t, again) = blessed(
        "point",
        "units = { length = \"mm\" }\n[[part]]\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 0]\n",
    );
    assert_eq!(tol(&t, &["center_of_mass"]).as_float(), Some(1e-6));
    assert_eq!(again, Some(0));
}

#[test]
fn a_zero_tolerance_written_by_hand_is_kept() {
    let (t, _) = blessed(
        "hand-zero",
        &box_at(
            "[0, 0, 0]",
            "\n[expect]\ncenter_of_mass = { value = [1, 0, 0], tol = 0.0 }\n",
        ),
    );
    assert_eq!(tol(&t, &["center_of_mass"]).as_float(), Some(0.0));
}

#[test]
fn a_command_line_vector_below_f64s_range_is_too_small() {
    for args in [
        vec!["--omega", "0,0,1e-400"],
        vec!["--omega", "0,0,1e-400 rpm"],
        vec!["--omega", "0 rpm,1e-400 rpm,0 rpm"],
        vec!["--omega", "0,0,1", "--alpha", "1e-400,0,0"],
        vec!["--about", "0,0,-1e-400"],
        vec!["--about", "1e-310,0,0"],
        vec!["--axes", "x=1,0,1e-400;y=0,1,0"],
        vec!["--axes", "axis=0,0,1;degrees=1e-400"],
    ] {
        let mut all = vec!["report", BENT_PLATE];
        all.extend(&args);
        let out = massprop(&all);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
        let flag = args[args.len() - 2];
        assert!(
            stderr.contains(&format!("for `{flag}`")),
            "{args:?}: {stderr}"
        );
        assert!(stderr.contains("is too small"), "{args:?}: {stderr}");
    }
}

#[test]
fn a_zero_written_as_zero_on_the_command_line_is_a_value() {
    for args in [["--omega", "0,0,0e-400"], ["--about", "-0.0,0,0"]] {
        let mut all = vec!["report", BENT_PLATE];
        all.extend(&args);
        let out = massprop(&all);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// Every command with `-o`, with a file to read.
fn with_output() -> Vec<Vec<&'static str>> {
    vec![
        vec!["report", BENT_PLATE],
        vec!["budget", BENT_PLATE],
        vec!["check", BENT_PLATE],
        vec!["diff", BENT_PLATE, BENT_PLATE],
        vec!["export", BENT_PLATE, "--to", "urdf"],
        vec!["render", BENT_PLATE],
    ]
}

#[test]
fn dash_o_dash_writes_standard_output_and_no_file() {
    let dir = scratch("leftovers", "dash-o-dash");
    let root = std::env::current_dir().unwrap();
    for args in with_output() {
        // Run in the scratch directory, the file named by its full path.
        let run = |extra: &[&str]| {
            Command::new(env!("CARGO_BIN_EXE_massprop"))
                .args(args.iter().map(|a| {
                    if a.ends_with(".toml") {
                        root.join(a).to_str().unwrap().to_string()
                    } else {
                        a.to_string()
                    }
                }))
                .args(extra)
                .current_dir(&dir)
                .output()
                .unwrap()
        };
        let plain = run(&[]);
        let dash = run(&["-o", "-"]);
        assert_eq!(dash.status.code(), Some(0), "{args:?}");
        assert!(!dash.stdout.is_empty(), "{args:?}");
        assert_eq!(dash.stdout, plain.stdout, "{args:?}");
        assert!(!dir.join("-").exists(), "{args:?}: wrote a file named `-`");
        let long = run(&["--output", "-"]);
        assert_eq!(long.stdout, plain.stdout, "{args:?}");
    }
}

#[test]
fn an_empty_dash_o_is_refused_with_a_sentence_naming_the_flag() {
    for args in with_output() {
        let mut all = args.clone();
        all.extend(["-o", ""]);
        let out = massprop(&all);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(
            stderr.starts_with("error: `-o` (`--output`) was given an empty file name"),
            "{args:?}: {stderr}"
        );
    }
}

/// `massprop ARGS > /dev/full`: what it prints cannot be written.
fn into_a_full_device(args: &[&str]) -> Option<std::process::Output> {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .ok()?;
    Some(
        Command::new(env!("CARGO_BIN_EXE_massprop"))
            .args(args)
            .stdout(Stdio::from(full))
            .stderr(Stdio::piped())
            .output()
            .unwrap(),
    )
}

#[test]
fn help_version_and_texts_into_a_full_device_exit_2_saying_so() {
    for args in [
        vec!["--help"],
        vec!["-h"],
        vec!["report", "--help"],
        vec!["check", "--help"],
        vec!["help", "diff"],
        vec!["--version"],
        vec!["man"],
        vec!["completions", "bash"],
        vec!["schema"],
        vec!["materials"],
        vec!["init"],
    ] {
        let Some(out) = into_a_full_device(&args) else {
            eprintln!("no /dev/full here: not tested");
            return;
        };
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains("error: cannot write output"),
            "{args:?}: {stderr}"
        );
    }
}

#[test]
fn help_that_can_be_written_still_exits_0() {
    for args in [["--help"], ["--version"]] {
        let out = massprop(&args);
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        assert!(!out.stdout.is_empty());
        assert!(out.stderr.is_empty());
    }
}

#[test]
fn check_of_standard_input_twice_is_refused_before_anything_is_read() {
    let text = std::fs::read_to_string(BENT_PLATE).unwrap();
    for args in [vec!["check", "-", "-"], vec!["check", "-", BENT_PLATE, "-"]] {
        let out = massprop_stdin(&args, &text);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(
            stderr.starts_with("error: `-` (standard input) is given twice"),
            "{stderr}"
        );
        assert!(stderr.contains("Usage: massprop check"), "{stderr}");
    }
    // Once is fine.
    let out = massprop_stdin(&["check", "-"], &text);
    assert_eq!(out.status.code(), Some(0));
}

/// `materials --format json FILE`: each listed material's density
/// (kg/m³) by name, and its source.
fn listed(file: &std::path::Path) -> Result<Vec<(String, f64, String)>, String> {
    let out = massprop(&["materials", "--format", "json", file.to_str().unwrap()]);
    if out.status.code() != Some(0) {
        return Err(String::from_utf8_lossy(&out.stderr).into_owned());
    }
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    Ok(v["materials"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| {
            (
                m["name"].as_str().unwrap().to_string(),
                m["density"].as_f64().unwrap(),
                m["source"].as_str().unwrap().to_string(),
            )
        })
        .collect())
}

#[test]
fn materials_lists_a_materials_only_file_in_its_own_units() {
    let file = scratch_files(
        "leftovers",
        "materials-only",
        &[(
            "library.toml",
            "units = { length = \"mm\", mass = \"g\" }\n\n[params]\nrho = \"1.5 g/cm^3\"\n\n[materials]\nresin = { density = \"2 * rho\" }\nfoam = { density = 3e-5 }\nsteel = { density = \"7.9 g/cm^3\" }\n",
        )],
    );
    let list = listed(&file).unwrap();
    let find = |n: &str| list.iter().find(|m| m.0 == n).unwrap().clone();
    // 2 × 1.5 g/cm³ = 3000 kg/m³; 3e-5 g/mm³ = 3e-5 × 1e-3 kg / 1e-9 m³.
    assert_eq!(find("resin").1, 3000.0);
    assert!((find("foam").1 - 30.0).abs() < 1e-12, "{:?}", find("foam"));
    assert!(find("resin").2.contains("library.toml"));
    // It overrides the built-in steel.
    assert!((find("steel").1 - 7900.0).abs() < 1e-9);
    assert!(find("steel").2.contains("overriding"));
}

#[test]
fn a_file_without_parts_that_is_no_materials_file_is_still_refused() {
    for (name, text) in [
        ("empty.toml", ""),
        ("units-only.toml", "units = { length = \"mm\" }\n"),
        (
            "with-expect.toml",
            "[materials]\nfoam = { density = 30 }\n[expect]\nmass = { max = 1 }\n",
        ),
    ] {
        let file = scratch_files("leftovers", "no-materials-file", &[(name, text)]);
        let e = listed(&file).unwrap_err();
        assert!(e.contains("the file has no parts"), "{name}: {e}");
    }
}

#[test]
fn a_part_files_materials_are_listed_as_before() {
    let file = scratch_files(
        "leftovers",
        "part-file-materials",
        &[(
            "p.toml",
            "[materials]\nfoam = { density = 30 }\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
        )],
    );
    let list = listed(&file).unwrap();
    assert!(list.iter().any(|m| m.0 == "foam" && m.1 == 30.0));
}
