//! The command line as users and scripts see it.

use crate::common::{massprop, massprop_stdin};
use serde_json::Value;

const BENT_PLATE: &str = "shapes/bent-plate.toml";

#[test]
fn every_case_in_tests_cmd_gives_its_pinned_output() {
    // Every case in tests/cmd/*.md (bad input, check, diff, report):
    // exit status and full output pinned.
    trycmd::TestCases::new().case("tests/cmd/*.md");
}

/// tests/cmd/report.md pins `report` of every example in shapes/, as the
/// short table, the full one and JSON, so adding an example forces its
/// snapshots. Each
/// command must open a `console` block (not `text`, not `ignore`: trycmd
/// runs it) and expect success.
#[test]
fn every_example_has_a_table_and_a_json_snapshot() {
    let md = std::fs::read_to_string("tests/cmd/report.md").unwrap();
    let lines: Vec<&str> = md.lines().collect();
    let mut examples = 0;
    for path in crate::common::example_part_files() {
        // Every part file: anything in shapes/ is an example users will run.
        let path = path.to_str().unwrap();
        for command in [
            format!("$ massprop report {path}"),
            format!("$ massprop report {path} --full"),
            format!("$ massprop report {path} --format json"),
        ] {
            let at = lines.iter().position(|l| *l == command);
            let at = at.unwrap_or_else(|| {
                panic!(
                    "tests/cmd/report.md has no `{command}`: add a console block \
                     and run TRYCMD=overwrite cargo test --test integration cli::every_case_in_tests_cmd"
                )
            });
            assert_eq!(lines[at - 1], "```console", "{command}: not a run block");
            // No `? ...` line is trycmd's default: status 0.
            let status = lines[at + 1];
            assert!(
                !status.starts_with("? ") || status == "? 0" || status == "? success",
                "{command}: must expect success, not {status}"
            );
        }
        examples += 1;
    }
    assert!(examples >= 7, "only {examples} files in shapes/");
}

/// The catalogue's promises, beyond the pinned text: for every `report`
/// case of tests/cmd/bad-input.md, nothing on stdout (trycmd shows stdout
/// and stderr together), status 2, a first line `file[:line:col]: error:`,
/// and, when it has a line and column, the source line with carets. At
/// least 40 hostile files (issue 6).
#[test]
fn every_bad_input_case_errors_on_stderr_alone_with_its_place() {
    let dir = std::path::Path::new("tests/cmd/bad-input.in");
    let md = std::fs::read_to_string("tests/cmd/bad-input.md").unwrap();
    let mut files = std::collections::BTreeSet::new();
    for line in md.lines().filter(|l| l.starts_with("$ massprop report ")) {
        let words: Vec<&str> = line.split_whitespace().skip(2).collect();
        let file = words[1];
        if dir.join(file).exists() && !file.starts_with("..") {
            files.insert(file.to_string());
        }
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
            .args(&words)
            .current_dir(dir)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{line}: {stderr}");
        assert!(out.stdout.is_empty(), "{line}: printed on stdout");
        let first = stderr.lines().next().unwrap_or("");
        if first.starts_with("error: ") {
            // A bad flag: nothing in a file to point at.
            assert!(words.iter().any(|w| w.starts_with("--")), "{line}: {first}");
            continue;
        }
        let place = first.split(": error: ").next().unwrap();
        assert!(first.contains(": error: "), "{line}: {first}");
        let mut parts = place.rsplitn(3, ':');
        let (col, row) = (parts.next().unwrap(), parts.next());
        if let (Ok(_), Some(Ok(_))) = (col.parse::<usize>(), row.map(str::parse::<usize>)) {
            assert!(
                stderr.lines().nth(3).is_some_and(|l| l.contains('^')),
                "{line}: no carets under the source line:\n{stderr}"
            );
        } else {
            // Only errors about a whole file (unreadable, a directory) or
            // a flag have no line.
            assert!(
                place == file || first.contains("given on the command line"),
                "{line}: no line and column: {first}"
            );
        }
    }
    assert!(files.len() >= 40, "only {} hostile files", files.len());
}

/// The one case of tests/cmd/bad-input.md that cannot be a committed file:
/// `cargo package` fails on a symlink loop, so the loop is made here, in a
/// scratch directory. The expected stderr is the catalogue's own `text`
/// block that starts with `include-symlink-loop.toml:`, so the catalogue
/// shows what is tested.
#[test]
fn an_include_of_a_symlink_loop_is_an_error_at_the_include() {
    let md = std::fs::read_to_string("tests/cmd/bad-input.md").unwrap();
    let want = md
        .split("```text\n")
        .filter_map(|rest| rest.split("```").next())
        .find(|block| block.starts_with("include-symlink-loop.toml:"))
        .expect("tests/cmd/bad-input.md shows the symlink loop's message");
    let dir = crate::common::scratch("cli", "include-symlink-loop");
    std::fs::write(
        dir.join("include-symlink-loop.toml"),
        "[[part]]\ninclude = \"loop-a.toml\"\n",
    )
    .unwrap();
    std::os::unix::fs::symlink("loop-b.toml", dir.join("loop-a.toml")).unwrap();
    std::os::unix::fs::symlink("loop-a.toml", dir.join("loop-b.toml")).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(["report", "include-symlink-loop.toml"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty(), "printed on stdout");
    assert_eq!(String::from_utf8_lossy(&out.stderr), want);
    std::fs::remove_dir_all(&dir).ok();
}

fn json(args: &[&str]) -> Value {
    let out = massprop(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty());
    serde_json::from_slice(&out.stdout).expect("stdout is one JSON document")
}

fn vec3(v: &Value) -> [f64; 3] {
    let a = v.as_array().expect("a 3-vector is an array");
    assert_eq!(a.len(), 3);
    [0, 1, 2].map(|i| a[i].as_f64().expect("numbers"))
}

/// The worked example by hand. Plate A (x = 0, y ∈ [0, .125], z ∈ [0, .1])
/// and plate B (y = .125, x ∈ [0, .075], z ∈ [0, .15]), 70 kg/m². For a
/// uniform rectangle ∫uv dm = m ū v̄ and ∫u² dm = m a²/3 from an edge, so
/// about O with ω = 30 k: H = ω (−∫xz, −∫yz, ∫(x² + y²)) dm.
fn bent_plate_by_hand() -> ([f64; 3], f64, f64) {
    let (ma, mb) = (70.0 * 0.125 * 0.1, 70.0 * 0.075 * 0.15);
    let ixz = mb * 0.0375 * 0.075;
    let iyz = ma * 0.0625 * 0.05 + mb * 0.125 * 0.075;
    let izz = ma * 0.125 * 0.125 / 3.0 + mb * (0.075 * 0.075 / 3.0 + 0.125 * 0.125);
    let h = [-30.0 * ixz, -30.0 * iyz, 30.0 * izz];
    (h, 0.5 * 30.0 * h[2], ma + mb)
}

#[test]
fn bent_plate_json_matches_the_hand_derivation_and_the_published_answer() {
    let v = json(&["report", BENT_PLATE, "--format", "json"]);
    let (h, t, m) = bent_plate_by_hand();
    let got_h = vec3(&v["angular_momentum"]);
    for i in 0..3 {
        assert!(
            (got_h[i] - h[i]).abs() <= 1e-15,
            "H[{i}] {} vs {}",
            got_h[i],
            h[i]
        );
    }
    let got_t = v["kinetic_energy"].as_f64().unwrap();
    assert!((got_t - t).abs() <= 1e-14 * t);
    assert!((v["mass"].as_f64().unwrap() - m).abs() <= 1e-15);
    // Published (rounded, with m_B rounded to 0.788 kg): m_A = 0.875 kg,
    // H_O ≈ −0.0665 i − 0.3034 j + 0.5502 k N·m·s, T ≈ 8.25 J.
    let parts = v["parts"].as_array().unwrap();
    // 70 kg/m² is not a binary fraction in kg/mm², the file's units, in
    // which parts and body are composed alike: within an ulp.
    assert!((parts[0]["mass"].as_f64().unwrap() - 0.875).abs() < 1e-15);
    assert!((parts[1]["mass"].as_f64().unwrap() - 0.7875).abs() < 1e-15);
    for (g, p) in got_h.iter().zip([-0.0665, -0.3034, 0.5502]) {
        assert!((g - p).abs() <= 2e-4, "{g} vs published {p}");
    }
    assert!((got_t - 8.25).abs() <= 0.005);
}

#[test]
fn bent_plate_table_shows_the_results_with_units() {
    let out = massprop(&["report", "--full", BENT_PLATE]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    // Six significant digits of the hand values: m = 1.6625 kg,
    // T = 15 · 0.55015625 = 8.25234375 J, H = (−0.06644531, −0.30351563, 0.55015625).
    for want in [
        "mass: 1.6625 kg",
        "kinetic energy T: 8.25234 J",
        "-0.0664453",
        "-0.303516",
        "0.550156",
        "N·m·s",
        "tensor convention, Ixy = −∫xy dm",
        "inertia about the reference point (0, 0, 0) mm (kg·mm²)",
        "principal moments and axes about the reference point",
    ] {
        assert!(text.contains(want), "missing {want:?} in\n{text}");
    }
}

#[test]
fn json_carries_every_documented_key() {
    let v = json(&["report", BENT_PLATE, "--format", "json", "--alpha", "0,0,2"]);
    for key in ["mass", "kinetic_energy"] {
        assert!(v[key].is_f64(), "{key}");
    }
    for key in [
        "center_of_mass",
        "reference_point",
        "principal_moments",
        "radii_of_gyration",
        "principal_moments_ref",
        "omega",
        "angular_momentum",
        "alpha",
        "euler_moment",
    ] {
        vec3(&v[key]);
    }
    for key in [
        "inertia_com",
        "inertia_ref",
        "principal_axes",
        "principal_axes_ref",
    ] {
        let rows = v[key].as_array().unwrap_or_else(|| panic!("{key}"));
        assert_eq!(rows.len(), 3);
        for r in rows {
            vec3(r); // asserts three numbers
        }
    }
    for key in ["equal_moments", "equal_moments_ref", "parts"] {
        assert!(v[key].is_array(), "{key}");
    }
    for p in v["parts"].as_array().unwrap() {
        assert!(p["name"].is_string() && p["shape"].is_string() && p["mass"].is_f64());
        vec3(&p["center_of_mass"]);
        assert!(p["mass_fraction"].is_f64());
    }
    assert_eq!(v["products_convention"], "tensor");
    assert_eq!(v["format_version"], 1);
    assert_eq!(v["name"], "bent plate");
    let units = &v["units"];
    for (k, u) in [
        ("mass", "kg"),
        ("length", "m"),
        ("inertia", "kg*m^2"),
        ("angular_velocity", "rad/s"),
        ("angular_momentum", "N*m*s"),
        ("energy", "J"),
        ("moment", "N*m"),
    ] {
        assert_eq!(units[k], u);
    }
}

#[test]
fn dynamics_keys_appear_only_when_asked_for() {
    let out = massprop_stdin(
        &["report", "-", "--format", "json"],
        "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [1, 0, 0]\n",
    );
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "omega",
        "angular_momentum",
        "kinetic_energy",
        "alpha",
        "euler_moment",
    ] {
        assert!(v.get(key).is_none(), "{key} without ω");
    }
    // No reference point given: it is the centre of mass.
    assert_eq!(v["reference_point"], v["center_of_mass"]);
    assert_eq!(v["inertia_ref"], v["inertia_com"]);
}

#[test]
fn standard_input_gives_the_same_report_as_the_file() {
    let text = std::fs::read_to_string(BENT_PLATE).unwrap();
    let from_stdin = massprop_stdin(&["report", "-", "--format", "json"], &text);
    let from_file = massprop(&["report", BENT_PLATE, "--format", "json"]);
    assert!(from_stdin.status.success());
    // The same report but for `source`, which names where it came from.
    let json = |out: &std::process::Output| -> serde_json::Value {
        serde_json::from_slice(&out.stdout).unwrap()
    };
    let (mut a, mut b) = (json(&from_stdin), json(&from_file));
    assert_eq!(a["source"], "<stdin>");
    assert_eq!(b["source"], BENT_PLATE);
    a.as_object_mut().unwrap().remove("source");
    b.as_object_mut().unwrap().remove("source");
    assert_eq!(a, b);
}

#[test]
fn flags_override_the_file_analysis() {
    let base = json(&["report", BENT_PLATE, "--format", "json"]);
    // Twice the angular velocity, as a quantity string: twice H, four times T.
    let v = json(&[
        "report",
        BENT_PLATE,
        "--format",
        "json",
        "--omega",
        "0,0,60 rad/s",
    ]);
    let (h0, h) = (
        vec3(&base["angular_momentum"]),
        vec3(&v["angular_momentum"]),
    );
    for i in 0..3 {
        assert!((h[i] - 2.0 * h0[i]).abs() <= 1e-15);
    }
    let t0 = base["kinetic_energy"].as_f64().unwrap();
    assert!((v["kinetic_energy"].as_f64().unwrap() - 4.0 * t0).abs() <= 1e-14 * t0);
    // 60 rpm is one revolution a second, 2π rad/s.
    let rpm = json(&[
        "report",
        BENT_PLATE,
        "--format",
        "json",
        "--omega",
        "0,0,60 rpm",
    ]);
    assert!((vec3(&rpm["omega"])[2] - 2.0 * std::f64::consts::PI).abs() < 1e-15);
    // --about moves the reference point; in the file's units (mm).
    let v = json(&[
        "report", BENT_PLATE, "--format", "json", "--about", "0,125,0",
    ]);
    assert_eq!(vec3(&v["reference_point"]), [0.0, 0.125, 0.0]);
}

#[test]
fn alpha_on_the_command_line_gives_the_euler_moment() {
    // With ω along z and α = 2 k about O: M = I α + ω × (I ω), and
    // I α = (2/30) H, ω × H = 30 (−H_y, H_x, 0).
    let v = json(&["report", BENT_PLATE, "--format", "json", "--alpha", "0,0,2"]);
    let (h, _, _) = bent_plate_by_hand();
    let want = [
        h[0] * 2.0 / 30.0 - 30.0 * h[1],
        h[1] * 2.0 / 30.0 + 30.0 * h[0],
        h[2] * 2.0 / 30.0,
    ];
    let got = vec3(&v["euler_moment"]);
    for i in 0..3 {
        assert!(
            (got[i] - want[i]).abs() <= 1e-14,
            "M[{i}] {} vs {}",
            got[i],
            want[i]
        );
    }
}

#[test]
fn positive_products_are_stated_and_flip_the_off_diagonals() {
    let t = json(&["report", BENT_PLATE, "--format", "json"]);
    let p = json(&[
        "report",
        BENT_PLATE,
        "--format",
        "json",
        "--products",
        "positive",
    ]);
    assert_eq!(p["products_convention"], "positive");
    let (ti, pi) = (&t["inertia_ref"], &p["inertia_ref"]);
    assert_eq!(pi[0][0], ti[0][0]);
    assert_eq!(pi[0][2].as_f64().unwrap(), -ti[0][2].as_f64().unwrap());
    // +∫xz dm of plate B about O is positive (x, z ≥ 0).
    assert!(pi[0][2].as_f64().unwrap() > 0.0);
    let table =
        String::from_utf8(massprop(&["report", BENT_PLATE, "--products", "positive"]).stdout)
            .unwrap();
    assert!(table.contains("positive convention (CAD, Meriam), Ixy = +∫xy dm"));
}

#[test]
fn every_shape_file_reports_in_both_formats() {
    for path in crate::common::example_part_files() {
        let path = path.to_str().unwrap();
        for format in ["table", "json"] {
            let out = massprop(&["report", path, "--format", format]);
            assert!(
                out.status.success(),
                "{path}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            assert!(out.stderr.is_empty());
        }
    }
}

#[test]
fn the_documented_full_example_is_the_bent_plate() {
    // docs/part-file.md places plate B by size, center and a quarter turn
    // about x instead of by corner and edges: the same body.
    let doc = std::fs::read_to_string("docs/part-file.md").unwrap();
    let example = doc
        .split("```toml\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("docs/part-file.md opens with a toml example");
    let out = massprop_stdin(
        &["report", "-", "--format", "json", "--alpha", "0,0,2"],
        example,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let doc_json: Value = serde_json::from_slice(&out.stdout).unwrap();
    let file_json = json(&["report", BENT_PLATE, "--format", "json", "--alpha", "0,0,2"]);
    for key in ["inertia_ref", "inertia_com"] {
        for i in 0..3 {
            let (a, b) = (vec3(&doc_json[key][i]), vec3(&file_json[key][i]));
            for j in 0..3 {
                assert!(
                    (a[j] - b[j]).abs() <= 1e-17,
                    "{key}[{i}][{j}] {} vs {}",
                    a[j],
                    b[j]
                );
            }
        }
    }
}

/// README's sample of `massprop report shapes/bent-plate.toml` is the real
/// output up to its `…`, and README names every example in shapes/.
#[test]
fn the_readme_shows_the_real_report_and_every_example() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let sample = readme
        .split("```console\n$ massprop report shapes/bent-plate.toml\n")
        .nth(1)
        // Up to its `…`, or whole when the block ends first.
        .and_then(|rest| rest.split('…').next())
        .and_then(|rest| rest.split("```").next())
        .expect("README shows `massprop report shapes/bent-plate.toml`");
    let out = massprop(&["report", BENT_PLATE]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.starts_with(sample),
        "README's sample:\n{sample}\nis not how the output starts:\n{text}"
    );
    for path in crate::common::example_part_files() {
        let name = format!("`{}`", path.file_name().unwrap().to_str().unwrap());
        assert!(readme.contains(&name), "README does not name {name}");
    }
}

/// docs/json.md's example prints the bent plate's `angular_momentum`: its
/// numbers are the ones massprop prints, digit for digit.
#[test]
fn the_json_doc_example_shows_the_printed_numbers() {
    let doc = std::fs::read_to_string("docs/json.md").unwrap();
    let command =
        "$ massprop report shapes/bent-plate.toml --format json | jq '.angular_momentum'\n";
    let shown: Vec<&str> = doc
        .split(command)
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("docs/json.md shows the bent plate's angular momentum")
        .split(['[', ']', ',', ' ', '\n'])
        .filter(|w| !w.is_empty())
        .collect();
    let out = massprop(&["report", BENT_PLATE, "--format", "json"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let printed: Vec<&str> = text
        .split("\"angular_momentum\":[")
        .nth(1)
        .and_then(|rest| rest.split(']').next())
        .expect("the JSON has angular_momentum")
        .split(',')
        .collect();
    assert_eq!(shown, printed);
}

#[test]
fn help_documents_exit_statuses() {
    let out = massprop(&["--help"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("Exit status:") && text.contains("2  an error"));
}

#[test]
fn equal_principal_moments_are_flagged_in_both_formats() {
    // A cube: all three moments m a²/6. A square plate: I1 = I2 = m a²/12,
    // I3 = m a²/6 about its normal.
    let cube = "[[part]]\nshape = \"box\"\nmass = 6\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nrotation = { axis = [1, 2, 3], degrees = 17 }\n";
    let plate = "[[part]]\nshape = \"plate\"\nmass = 12\nsize = [1, 1]\ncenter = [0, 0, 0]\n";
    for (text, equal, moments, note) in [
        (
            cube,
            vec![0, 1, 2],
            [1.0, 1.0, 1.0],
            "note: I1 = I2 = I3 are equal",
        ),
        (
            plate,
            vec![0, 1],
            [1.0, 1.0, 2.0],
            "note: I1 = I2 are equal",
        ),
    ] {
        let out = massprop_stdin(&["report", "-", "--format", "json"], text);
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        let got: Vec<u64> = v["equal_moments"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap())
            .collect();
        assert_eq!(got, equal.iter().map(|&i| i as u64).collect::<Vec<_>>());
        let m = vec3(&v["principal_moments"]);
        for i in 0..3 {
            assert!((m[i] - moments[i]).abs() <= 8.0 * f64::EPSILON, "{m:?}");
        }
        let table = String::from_utf8(massprop_stdin(&["report", "-"], text).stdout).unwrap();
        assert!(table.contains(note), "{table}");
    }
}

#[test]
fn flag_omega_completes_a_file_alpha() {
    let file = "[[part]]\nshape = \"point\"\nmass = 2\ncenter = [1, 0, 0]\n[analysis]\nalpha = [0, 0, 3]\n";
    let out = massprop_stdin(
        &["report", "-", "--format", "json", "--omega", "0,0,0"],
        file,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    // About the centre of mass (the point itself) the inertia is zero.
    assert_eq!(vec3(&v["euler_moment"]), [0.0, 0.0, 0.0]);
    assert_eq!(vec3(&v["alpha"]), [0.0, 0.0, 3.0]);
}

#[test]
fn a_unit_on_the_last_flag_component_applies_to_all_three() {
    let file = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    let run = |about: &str| {
        let out = massprop_stdin(&["report", "-", "--format", "json", "--about", about], file);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        vec3(&v["reference_point"])
    };
    assert_eq!(run("5,0,10 mm"), [0.005, 0.0, 0.01]);
    assert_eq!(run("5 mm,0 mm,1 in"), [0.005, 0.0, 0.0254]);
    assert_eq!(run("5,0,10"), [5.0, 0.0, 10.0]);
}

#[test]
fn materials_lists_the_built_in_table_and_a_files_own() {
    let out = massprop(&["materials", "--format", "json"]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["units"]["density"], "kg/m^3");
    let list = v["materials"].as_array().expect("an array");
    let steel = list
        .iter()
        .find(|m| m["name"] == "steel")
        .expect("steel is built in");
    assert_eq!(steel["density"], 7850.0);
    assert!(
        list.iter()
            .all(|m| m["source"].as_str().is_some_and(|s| !s.is_empty()))
    );

    let dir = std::env::temp_dir().join(format!("massprop-materials-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("m.toml");
    std::fs::write(
        &file,
        "[materials]\nfoam = { density = 30 }\nsteel = { density = \"7.9 g/cm^3\" }\n\
         [[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    let out = massprop(&["materials", "--format", "json", file.to_str().unwrap()]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let find = |n: &str| {
        v["materials"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["name"] == n)
            .cloned()
    };
    assert_eq!(find("foam").expect("added")["density"], 30.0);
    assert_eq!(find("steel").expect("overridden")["density"], 7900.0);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_include_in_standard_input_is_an_error_not_a_guess() {
    let out = massprop_stdin(&["report", "-"], "[[part]]\ninclude = \"motor.toml\"\n");
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("<stdin>:2:11") && err.contains("standard input"),
        "{err}"
    );
}

#[test]
fn output_file_is_written_whole_or_not_at_all() {
    let dir = std::env::temp_dir().join(format!("massprop-output-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out_path = dir.join("report.json");
    let out = massprop(&[
        "report",
        "shapes/bent-plate.toml",
        "--format",
        "json",
        "-o",
        out_path.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stdout.is_empty(), "nothing on stdout with -o");
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&out_path).unwrap()).unwrap();
    assert!(v["mass"].as_f64().is_some());
    // A failing run leaves the previous result untouched, and no temporary file.
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[[part]]\nshape = \"box\"\n").unwrap();
    let before = std::fs::read(&out_path).unwrap();
    let out = massprop(&[
        "report",
        bad.to_str().unwrap(),
        "-o",
        out_path.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read(&out_path).unwrap(), before);
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
    // check and diff take -o too.
    let c = dir.join("check.json");
    let out = massprop(&[
        "check",
        "shapes/",
        "--format",
        "json",
        "-o",
        c.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    assert!(std::fs::read_to_string(&c).unwrap().contains("\"files\""));
    let d = dir.join("diff.txt");
    let out = massprop(&[
        "diff",
        "shapes/flywheel.toml",
        "shapes/flywheel.toml",
        "-o",
        d.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    assert!(!std::fs::read_to_string(&d).unwrap().is_empty());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn output_through_a_symlink_keeps_the_link_and_a_device_is_written_not_replaced() {
    let dir = crate::common::scratch("cli", "output-link");
    let real = dir.join("real.json");
    std::fs::write(&real, "old").unwrap();
    let link = dir.join("link.json");
    std::os::unix::fs::symlink("real.json", &link).unwrap();
    let out = massprop(&[
        "report",
        BENT_PLATE,
        "--format",
        "json",
        "-o",
        link.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&real).unwrap()).unwrap();
    assert!(v["mass"].as_f64().is_some());
    // /dev/null stays a device (a rename would replace it, as root).
    let out = massprop(&["report", BENT_PLATE, "-o", "/dev/null"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(!std::fs::metadata("/dev/null").unwrap().is_file());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_closed_stderr_is_not_a_panic() {
    use std::process::{Command, Stdio};
    // Closed before massprop writes its error (and if not, the write lands
    // in the pipe: either way the status must be 2, never 101).
    for _ in 0..5 {
        let mut child = Command::new(env!("CARGO_BIN_EXE_massprop"))
            .args(["report", "tests/cmd/bad-input.in/unknown-key.toml"])
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stderr.take());
        assert_eq!(child.wait().unwrap().code(), Some(2));
    }
}

#[test]
fn output_onto_an_input_part_file_is_refused() {
    let dir = crate::common::scratch("cli", "output-self");
    let part = dir.join("part.toml");
    std::fs::copy(BENT_PLATE, &part).unwrap();
    let before = std::fs::read(&part).unwrap();
    let p = part.to_str().unwrap();
    for args in [
        vec!["report", p, "-o", p],
        vec!["check", p, "-o", p],
        vec!["diff", BENT_PLATE, p, "-o", p],
    ] {
        let out = massprop(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(stderr.contains("would replace it"), "{args:?}: {stderr}");
        assert_eq!(std::fs::read(&part).unwrap(), before, "{args:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_named_pipe_is_read_like_a_file() {
    // `massprop report <(generate)` hands over a pipe, not a regular file.
    let dir = crate::common::scratch("cli", "fifo");
    let fifo = dir.join("part.toml");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo (coreutils) failed");
    let writer = {
        let fifo = fifo.clone();
        std::thread::spawn(move || {
            std::fs::write(&fifo, std::fs::read(BENT_PLATE).unwrap()).unwrap();
        })
    };
    let out = massprop(&["report", fifo.to_str().unwrap(), "--format", "json"]);
    writer.join().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let direct = json(&["report", BENT_PLATE, "--format", "json"]);
    let piped: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(piped["mass"], direct["mass"]);
    std::fs::remove_dir_all(&dir).ok();
}

/// `-o` never writes onto a file the run reads: not only the files named,
/// but a file `check` finds in a directory and a file a part file includes
/// (once both were overwritten with the report).
#[test]
fn output_onto_a_found_or_included_file_is_refused_and_leaves_it_intact() {
    let dir = crate::common::scratch("cli", "output-onto-read");
    let wheel = "name = \"wheel\"\n[[part]]\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 0]\n";
    let cart = "[[part]]\nshape = \"point\"\nmass = 5\ncenter = [0, 0, 1]\n\
                [[part]]\ninclude = \"wheel.toml\"\norigin = [1, 0, 0]\n";
    std::fs::write(dir.join("wheel.toml"), wheel).unwrap();
    std::fs::write(dir.join("cart.toml"), cart).unwrap();
    let path = |f: &str| dir.join(f).to_str().unwrap().to_string();
    for args in [
        vec![
            "report".to_string(),
            path("cart.toml"),
            "-o".into(),
            path("wheel.toml"),
        ],
        vec![
            "check".to_string(),
            dir.to_str().unwrap().into(),
            "-o".into(),
            path("wheel.toml"),
        ],
        vec![
            "check".to_string(),
            path("cart.toml"),
            "-o".into(),
            path("wheel.toml"),
        ],
        vec![
            "diff".to_string(),
            path("cart.toml"),
            path("cart.toml"),
            "-o".into(),
            path("wheel.toml"),
        ],
    ] {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        crate::common::assert_refused(&massprop(&args), &args);
        assert_eq!(
            std::fs::read_to_string(dir.join("wheel.toml")).unwrap(),
            wheel
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("cart.toml")).unwrap(),
            cart
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `-o -` is standard output, as `-` is standard input: no file named `-`.
#[test]
fn output_dash_is_standard_output() {
    let dir = crate::common::scratch("cli", "output-dash");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args([
            "report",
            &std::fs::canonicalize(BENT_PLATE).unwrap().to_string_lossy(),
            "-o",
            "-",
        ])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("bent plate ("));
    assert!(!dir.join("-").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// Text from input is shown with its control characters as their pictures
/// on stdout too, as on stderr: a part's name cannot colour the terminal or
/// add a line, nor can a file's name add a line to `check`'s output.
#[test]
fn names_from_input_cannot_forge_output() {
    let dir = crate::common::scratch("cli", "forged-names");
    let text = "name = \"body\\u001b[2J\"\n\
                [[part]]\nname = \"evil\\u001b[31m\\nfake.toml: ok\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    let file = dir.join("x\nfake.toml: ok\n.toml");
    std::fs::write(&file, text).unwrap();
    let f = file.to_str().unwrap();
    for args in [
        vec!["report", f],
        vec!["check", dir.to_str().unwrap()],
        vec!["diff", f, f],
    ] {
        let out = massprop(&args);
        let stdout = String::from_utf8(out.stdout).unwrap();
        assert!(!stdout.contains('\u{1b}'), "{args:?}: {stdout}");
        assert!(
            !stdout.lines().any(|l| l.starts_with("fake.toml: ok")),
            "{args:?}: {stdout}"
        );
        assert!(
            stdout.contains('\u{241b}') || stdout.contains('\u{240a}'),
            "{args:?}: {stdout}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `-o` onto a link to the process's own standard output, when that is a
/// pipe, writes into the pipe; it once renamed a file over the link (for
/// `/dev/stdout`, run as root, over /dev/stdout itself). The link here is a
/// scratch one, so a regression cannot damage the machine.
#[test]
fn output_onto_a_link_to_a_piped_stdout_writes_into_the_pipe() {
    let dir = crate::common::scratch("cli", "output-stdout-pipe");
    let link = dir.join("stdout");
    std::os::unix::fs::symlink("/proc/self/fd/1", &link).unwrap();
    let out = massprop(&["report", BENT_PLATE, "-o", link.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("bent plate ("));
    assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
    std::fs::remove_dir_all(&dir).ok();
}

/// An include outside the part file's directory tree and the working
/// directory is refused; `--include-root` allows it.
#[test]
fn includes_are_confined_unless_a_root_allows_them() {
    let dir = crate::common::scratch("cli", "include-root");
    std::fs::create_dir_all(dir.join("a")).unwrap();
    std::fs::create_dir_all(dir.join("b")).unwrap();
    std::fs::write(
        dir.join("b/sub.toml"),
        "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("a/top.toml"),
        "[[part]]\ninclude = \"../b/sub.toml\"\n",
    )
    .unwrap();
    let run = |extra: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
            .args(["report", "top.toml"])
            .args(extra)
            .current_dir(dir.join("a"))
            .output()
            .unwrap()
    };
    let out = run(&[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is outside the directory"));
    let b = dir.join("b");
    let out = run(&["--include-root", b.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// An include names a part file: a file of another kind inside the tree
/// (`.env`, `.git/config`, a symlink to one) is refused before it is read,
/// and a TOML file that is not a part file (no `[[part]]`) is refused
/// without quoting a line of it; a part file's own errors are quoted.
#[test]
fn includes_of_files_that_are_not_part_files_quote_nothing_of_them() {
    const SECRET: &str = "ghp_0123456789abcdefSECRET";
    let dir = crate::common::scratch("cli", "include-non-part");
    std::fs::create_dir_all(dir.join(".git")).unwrap();
    std::fs::write(dir.join(".env"), format!("API_TOKEN={SECRET}\n")).unwrap();
    std::fs::write(
        dir.join(".git/config"),
        format!("[http]\n\textraheader = AUTHORIZATION: basic {SECRET}\n"),
    )
    .unwrap();
    std::fs::write(dir.join("secrets.toml"), format!("token = \"{SECRET}\"\n")).unwrap();
    std::os::unix::fs::symlink(dir.join(".env"), dir.join("env.toml")).unwrap();
    std::fs::write(
        dir.join("broken.toml"),
        format!("[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0]  # {SECRET}\n"),
    )
    .unwrap();
    // A byte-order mark and a quoted header: a part file all the same.
    std::fs::write(
        dir.join("bom.toml"),
        format!("\u{feff}[[ 'part' ]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0]  # {SECRET}\n"),
    )
    .unwrap();
    for (target, says, quoted) in [
        (".env", "is not a part file (`*.toml`)", false),
        (".git/config", "is not a part file (`*.toml`)", false),
        ("env.toml", "is not a part file (`*.toml`)", false),
        (
            "secrets.toml",
            "is not a part file: it has no `[[part]]` table",
            false,
        ),
        ("broken.toml", "`center` needs 3 components, got 2", true),
        ("bom.toml", "`center` needs 3 components, got 2", true),
    ] {
        let top = dir.join("top.toml");
        std::fs::write(&top, format!("[[part]]\ninclude = \"{target}\"\n")).unwrap();
        let out = massprop(&["report", top.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{target}: {err}");
        assert!(out.stdout.is_empty());
        assert!(err.contains(says), "{target}: {err}");
        assert_eq!(err.contains(SECRET), quoted, "{target}: {err}");
    }
}
