//! Robot descriptions (docs/robots.md): `export` reads back to the last
//! bit in every format, `--update` changes nothing but the inertial,
//! `check` judges robot files by each engine's rule with the likely
//! cause, in every output format, and `diff` compares a part file with a
//! link both ways.

use super::common::{massprop, scratch};
use massprop::diag::Source;
use massprop::robot::{Dialect, Inertial, read::read};
use std::path::{Path, PathBuf};

fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// The part files of shapes/ (each a body every engine takes).
fn part_files() -> Vec<PathBuf> {
    let files = super::common::example_part_files();
    assert!(files.len() >= 5, "{files:?}");
    files
}

fn stdout(args: &[&str]) -> String {
    let out = massprop(args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// A one-link document of `format` holding `element`.
fn document(format: Dialect, element: &str) -> String {
    match format {
        Dialect::Urdf => {
            format!("<robot name=\"r\">\n  <link name=\"l\">\n    {element}\n  </link>\n</robot>\n")
        }
        Dialect::Sdf => format!(
            "<sdf version=\"1.9\">\n  <model name=\"m\">\n    <link name=\"l\">\n      {element}\n    </link>\n  </model>\n</sdf>\n"
        ),
        Dialect::Mjcf => format!(
            "<mujoco>\n  <worldbody>\n    <body name=\"l\">\n      <freejoint/>\n      {element}\n    </body>\n  </worldbody>\n</mujoco>\n"
        ),
    }
}

fn read_back(format: Dialect, element: &str) -> Inertial {
    let text = document(format, element);
    let d =
        read(&Source::new("t", text.as_str()), format).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(d.links.len(), 1, "{text}");
    d.links[0].inertial.clone().expect("an inertial")
}

#[test]
fn export_reads_back_to_the_last_bit_in_every_format() {
    for file in part_files() {
        let s = massprop::summarize(&file, &massprop::Settings::default()).unwrap();
        let path = file.to_str().unwrap();
        for (format, to) in [
            (Dialect::Urdf, "urdf"),
            (Dialect::Sdf, "sdf"),
            (Dialect::Mjcf, "mjcf"),
        ] {
            let element = stdout(&["export", path, "--to", to]);
            let i = read_back(format, element.trim_end());
            let ctx = format!("{} --to {to}:\n{element}", file.display());
            assert_eq!(i.mass.to_bits(), s.mass.to_bits(), "{ctx}");
            assert_eq!(i.rotation, None, "{ctx}");
            // The link origin is the reference point when the file gives one
            // (`[analysis] about`), else the file's origin.
            let c = if s.reference_given {
                s.center_of_mass_ref
            } else {
                s.center_of_mass
            };
            let bits = |v: [f64; 3]| v.map(f64::to_bits);
            assert_eq!(bits(i.pos), bits(c), "{ctx}");
            let m = i.tensor.matrix();
            #[allow(clippy::needless_range_loop, reason = "two matrices by index")]
            for r in 0..3 {
                for c in 0..3 {
                    // −0 is written 0: the same value, and the only
                    // difference in bits allowed.
                    assert!(
                        m[r][c].to_bits() == s.inertia_com[r][c].to_bits()
                            || (m[r][c] == 0.0 && s.inertia_com[r][c] == 0.0),
                        "{ctx}: [{r}][{c}] {} against {}",
                        m[r][c],
                        s.inertia_com[r][c]
                    );
                }
            }
        }
    }
}

#[test]
fn principal_mjcf_reads_back_the_principal_moments_to_the_bit_and_the_axes_to_rounding() {
    for file in part_files() {
        let s = massprop::summarize(&file, &massprop::Settings::default()).unwrap();
        let element = stdout(&[
            "export",
            file.to_str().unwrap(),
            "--to",
            "mjcf",
            "--principal",
        ]);
        let i = read_back(Dialect::Mjcf, element.trim_end());
        let ctx = format!("{}:\n{element}", file.display());
        let d = [i.tensor.xx, i.tensor.yy, i.tensor.zz];
        assert_eq!(
            d.map(f64::to_bits),
            s.principal_moments.map(f64::to_bits),
            "{ctx}"
        );
        // The tensor in the link frame, R D Rᵀ, is the file's tensor to a
        // few roundings of its largest moment (a quaternion's own rounding).
        let t = i.tensor_in_link().matrix();
        let big = s.principal_moments[2];
        #[allow(clippy::needless_range_loop, reason = "two matrices by index")]
        for r in 0..3 {
            for c in 0..3 {
                let err = (t[r][c] - s.inertia_com[r][c]).abs();
                assert!(
                    err <= 16.0 * f64::EPSILON * big,
                    "{ctx}: [{r}][{c}] off by {err:e}"
                );
            }
        }
    }
}

#[test]
fn principal_is_refused_for_urdf_and_sdformat() {
    let out = massprop(&[
        "export",
        "shapes/flywheel.toml",
        "--to",
        "urdf",
        "--principal",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("`--principal` is for"));
}

const ARM: &str = r#"<?xml version="1.0"?>
<!-- a two-link arm -->
<robot name='arm'>
	<link name="base">
		<inertial>
			<origin xyz="0 0 0.05" rpy="0 0 0"/>
			<mass value="2.5"/>
			<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.02"/>
		</inertial>
	</link>
	<link name='forearm'>
		<inertial>
			<mass value="1"/>
			<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>
		</inertial>
		<visual><geometry><box size="0.1 0.1 0.4"/></geometry></visual>
	</link>
	<joint name="elbow" type="revolute">
		<parent link="base"/><child link="forearm"/>
	</joint>
</robot>
"#;

#[test]
fn update_replaces_the_inertial_and_keeps_every_other_byte() {
    let dir = scratch("robots", "update");
    let urdf = dir.join("arm.urdf");
    std::fs::write(&urdf, ARM).unwrap();
    let u = urdf.to_str().unwrap();
    let part = "shapes/robot-arm.toml";
    // --dry-run: a diff on stdout, the file untouched.
    let diff = stdout(&[
        "export",
        part,
        "--update",
        u,
        "--link",
        "forearm",
        "--dry-run",
    ]);
    assert!(diff.contains("--- a/") && diff.contains("+++ b/"), "{diff}");
    assert!(diff.contains("-\t\t\t<mass value=\"1\"/>"), "{diff}");
    assert_eq!(std::fs::read_to_string(&urdf).unwrap(), ARM);
    // The update: only the forearm's inertial changes.
    stdout(&["export", part, "--update", u, "--link", "forearm"]);
    let new = std::fs::read_to_string(&urdf).unwrap();
    let start = ARM.find("<inertial>\n\t\t\t<mass").unwrap();
    let end = start + ARM[start..].find("</inertial>").unwrap() + "</inertial>".len();
    assert!(new.starts_with(&ARM[..start]), "{new}");
    assert!(new.ends_with(&ARM[end..]), "{new}");
    // Read back: the part file's values, to the bit.
    let s = massprop::summarize(repo(part), &massprop::Settings::default()).unwrap();
    let d = read(&Source::new("arm.urdf", new.as_str()), Dialect::Urdf).unwrap();
    let i = d.links[1].inertial.clone().unwrap();
    assert_eq!(i.mass.to_bits(), s.mass.to_bits());
    assert_eq!(
        i.tensor.matrix()[0][1].to_bits(),
        s.inertia_com[0][1].to_bits()
    );
    // Once more: nothing to change.
    let out = massprop(&["export", part, "--update", u, "--link", "forearm"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("unchanged"));
    assert_eq!(std::fs::read_to_string(&urdf).unwrap(), new);
    // And `diff` agrees with the link, both ways round.
    for args in [[part, u], [u, part]] {
        let out = massprop(&["diff", args[0], args[1], "--link", "forearm"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
    // The base's inertial is not the part file's: a change.
    let out = massprop(&["diff", part, u, "--link", "base", "--format", "json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["link"], "base");
    assert_eq!(v["changed"], true);
}

#[test]
fn update_names_a_link_that_does_not_exist() {
    let dir = scratch("robots", "no-link");
    let urdf = dir.join("arm.urdf");
    std::fs::write(&urdf, ARM).unwrap();
    let out = massprop(&[
        "export",
        "shapes/robot-arm.toml",
        "--update",
        urdf.to_str().unwrap(),
        "--link",
        "forarm",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("forarm"), "{err}");
    assert_eq!(std::fs::read_to_string(&urdf).unwrap(), ARM);
}

/// A URDF of two links whose tensors have all three products equal, p:
/// their eigenvalues are d + 2p and d − p (twice). `good` (d = 2,
/// p = −0.9) has moments 0.2, 2.9, 2.9; `bad` is it with the products'
/// signs flipped (the CAD convention), moments 1.1, 1.1, 3.8, which break
/// the triangle inequality: 1.1 + 1.1 − 3.8 = −1.6.
const FLIPPED: &str = r#"<robot name="r">
  <link name="good">
    <inertial>
      <mass value="1"/>
      <inertia ixx="2" ixy="-0.9" ixz="-0.9" iyy="2" iyz="-0.9" izz="2"/>
    </inertial>
  </link>
  <link name="bad">
    <inertial>
      <mass value="1"/>
      <inertia ixx="2" ixy="0.9" ixz="0.9" iyy="2" iyz="0.9" izz="2"/>
    </inertial>
  </link>
</robot>
"#;

#[test]
fn check_judges_each_link_by_each_engine_and_names_the_cause() {
    let dir = scratch("robots", "check");
    let f = dir.join("r.urdf");
    std::fs::write(&f, FLIPPED).unwrap();
    let p = f.to_str().unwrap();
    let out = massprop(&["check", p, "--format", "json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let file = &v["files"][0];
    assert_eq!(file["kind"], "urdf");
    assert_eq!(file["status"], "failed");
    let links = file["links"].as_array().unwrap();
    assert_eq!(links[0]["name"], "good");
    assert!(
        links[0]["engines"]
            .as_array()
            .unwrap()
            .iter()
            .all(|e| e["valid"] == true)
    );
    assert_eq!(links[1]["name"], "bad");
    // At the `<inertial>` start tag: line 9, column 5.
    assert_eq!(
        (links[1]["line"].as_u64(), links[1]["column"].as_u64()),
        (Some(9), Some(5))
    );
    for e in links[1]["engines"].as_array().unwrap() {
        assert_eq!(e["valid"], false, "{e}");
        assert_eq!(e["cause"]["kind"], "products_sign", "{e}");
        let t = e["rules"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["rule"] == "triangle")
            .unwrap();
        // A + B − C = −1.6 and the margin −1.6/3.8, to a few roundings.
        assert!((t["value"].as_f64().unwrap() + 1.6).abs() < 1e-14, "{t}");
        let margin = t["margin"].as_f64().unwrap();
        assert!((margin + 1.6 / 3.8).abs() < 1e-12, "{t}");
        assert_eq!(t["holds"], false);
    }
    // --engine narrows the verdicts.
    let out = massprop(&["check", p, "--format", "json", "--engine", "drake"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let engines = v["files"][0]["links"][1]["engines"].as_array().unwrap();
    assert_eq!(engines.len(), 1);
    assert_eq!(engines[0]["engine"], "drake");
    // The table: a line per failure at path:line:col, with the cause.
    let out = massprop(&["check", p]);
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(
        table.contains(&format!(
            "{p}:9:5: error: link \"bad\" is invalid under mujoco"
        )),
        "{table}"
    );
    assert!(
        table.contains("likely cause: the products of inertia have the wrong sign"),
        "{table}"
    );
    // GitHub annotations point at the element.
    let out = massprop(&["check", p, "--format", "github"]);
    let gh = String::from_utf8(out.stdout).unwrap();
    assert!(gh.contains(",line=9,col=5,"), "{gh}");
}

#[test]
fn a_directory_search_finds_robot_descriptions_and_passes_over_other_xml() {
    let dir = scratch("robots", "walk");
    std::fs::write(dir.join("r.urdf"), ARM).unwrap();
    std::fs::write(dir.join("pom.xml"), "<project/>\n").unwrap();
    std::fs::write(
        dir.join("scene.xml"),
        "<mujoco><worldbody><body name=\"b\"><inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 1\"/></body></worldbody></mujoco>\n",
    )
    .unwrap();
    let out = massprop(&["check", dir.to_str().unwrap(), "--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let kinds: Vec<&str> = v["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["urdf", "mjcf"], "{v}");
    assert_eq!(out.status.code(), Some(0), "{v}");
}

#[test]
fn a_malformed_robot_description_is_invalid_with_its_place() {
    let dir = scratch("robots", "malformed");
    let f = dir.join("bad.urdf");
    std::fs::write(&f, "<robot name=\"r\">\n  <link name=\"a\">\n</robot>\n").unwrap();
    let out = massprop(&["check", f.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.urdf:3:"), "{err}");
}

/// Every robot description in shapes/robots/ is valid under every engine.
#[test]
fn the_example_robot_descriptions_are_valid_under_every_engine() {
    let out = massprop(&["check", "shapes/robots", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{v}");
    let kinds: Vec<&str> = v["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["urdf", "mjcf", "sdf"], "{v}");
}

/// tests/robots/README.md's table is the specification of the known-bad
/// files: for each, the link at fault, the cause `check` must name and
/// which engines reject it. (Its "triangle" rows, a hair over the limit,
/// are no slip: `check` names them `boundary`.)
#[test]
fn each_known_bad_robot_file_fails_where_and_why_its_readme_says() {
    let readme = std::fs::read_to_string(repo("tests/robots/README.md")).unwrap();
    let rows: Vec<Vec<String>> = readme
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            l.trim_matches('|')
                .split(" | ")
                .map(|c| c.trim().trim_matches('`').to_string())
                .collect()
        })
        .collect();
    assert!(rows.len() >= 15, "{rows:?}");
    let mut causes = std::collections::BTreeSet::new();
    for row in &rows {
        let [file, link, cause, mujoco, gazebo, drake] = row.as_slice() else {
            panic!("a row of six cells: {row:?}");
        };
        let path = repo(&format!("tests/robots/{file}"));
        let out = massprop(&["check", path.to_str().unwrap(), "--format", "json"]);
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        if cause.starts_with("reader error") {
            assert_eq!(out.status.code(), Some(2), "{file}: {v}");
            assert_eq!(v["files"][0]["status"], "invalid", "{file}");
            continue;
        }
        assert_eq!(out.status.code(), Some(1), "{file}: {v}");
        let kind = match cause.split([':', ' ']).next().unwrap() {
            "triangle" => "boundary",
            k => k,
        };
        causes.insert(kind.to_string());
        let links = v["files"][0]["links"].as_array().unwrap();
        let l = links
            .iter()
            .find(|l| l["name"] == link.as_str())
            .unwrap_or_else(|| panic!("{file}: no link {link}: {v}"));
        for (engine, says) in [("mujoco", mujoco), ("gazebo", gazebo), ("drake", drake)] {
            let e = l["engines"]
                .as_array()
                .unwrap()
                .iter()
                .find(|e| e["engine"] == engine)
                .unwrap();
            let rejects = says.as_str() == "rejects";
            assert_eq!(e["valid"], !rejects, "{file} {link} under {engine}: {e}");
            if rejects {
                assert_eq!(
                    e["cause"]["kind"], kind,
                    "{file} {link} under {engine}: {e}"
                );
            }
        }
        // Every other link of the file is valid.
        for other in links.iter().filter(|o| o["name"] != link.as_str()) {
            assert!(
                other["engines"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .all(|e| e["valid"] == true),
                "{file}: {other}"
            );
        }
    }
    let all = [
        "boundary",
        "mirror",
        "order",
        "products_sign",
        "shifted",
        "units",
    ];
    assert_eq!(causes.into_iter().collect::<Vec<_>>(), all);
}

/// The CI formats carry a robot description's failures at the
/// `<inertial>` element: GitHub annotations, a JUnit test case per link
/// and engine, SARIF valid against its schema.
#[test]
fn the_ci_formats_point_at_each_failing_inertial() {
    let path = repo("tests/robots/mirror.urdf");
    let p = path.to_str().unwrap();
    let run = |format: &str| {
        let out = massprop(&["check", p, "--format", format]);
        assert_eq!(out.status.code(), Some(1), "{format}");
        String::from_utf8(out.stdout).unwrap()
    };
    // GitHub: one error for right_finger at 23:5, naming the three engines
    // (issue 31, item 4: not one per engine), the mirror warning on
    // left_finger at 12:5.
    let gh = run("github");
    let errors: Vec<&str> = gh.lines().filter(|l| l.starts_with("::error ")).collect();
    assert_eq!(errors.len(), 1, "{gh}");
    assert!(errors[0].contains(",line=23,col=5,"), "{gh}");
    assert!(
        errors[0].contains("under mujoco%2C gazebo%2C drake::"),
        "{gh}"
    );
    for engine in ["mujoco", "gazebo", "drake"] {
        assert!(
            errors[0].contains(&format!("is invalid under {engine}: ")),
            "{gh}"
        );
    }
    let warnings: Vec<&str> = gh.lines().filter(|l| l.starts_with("::warning ")).collect();
    assert_eq!(warnings.len(), 1, "{gh}");
    assert!(warnings[0].contains(",line=12,col=5,"), "{gh}");
    // JUnit: a suite with `valid urdf file` and a case per link and engine.
    let xml = run("junit");
    let doc = roxmltree::Document::parse(&xml).expect("well-formed XML");
    let cases: Vec<_> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "testcase")
        .collect();
    let links = read(
        &Source::new("m", std::fs::read_to_string(&path).unwrap()),
        Dialect::Urdf,
    )
    .unwrap()
    .links
    .iter()
    .filter(|l| l.inertial.is_some())
    .count();
    assert_eq!(cases.len(), 1 + 3 * links, "{xml}");
    assert_eq!(cases[0].attribute("name"), Some("valid urdf file"));
    let failed: Vec<_> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "failure")
        .map(|n| n.parent().unwrap().attribute("name").unwrap())
        .collect();
    assert_eq!(
        failed,
        [
            "link right_finger: mujoco",
            "link right_finger: gazebo",
            "link right_finger: drake"
        ]
    );
    // SARIF: valid, one `inertial` error (for the three engines) and one
    // `inertial-warning`.
    let schema: serde_json::Value =
        serde_json::from_str(include_str!("../schemas/sarif-2.1.0.json")).unwrap();
    let validator = jsonschema::validator_for(&schema).unwrap();
    let v: serde_json::Value = serde_json::from_str(&run("sarif")).unwrap();
    let errors: Vec<String> = validator.iter_errors(&v).map(|e| e.to_string()).collect();
    assert!(errors.is_empty(), "{errors:#?}");
    let results = v["runs"][0]["results"].as_array().unwrap();
    let ids: Vec<&str> = results
        .iter()
        .map(|r| r["ruleId"].as_str().unwrap())
        .collect();
    assert_eq!(ids, ["inertial-warning", "inertial"]);
    let region = &results[1]["locations"][0]["physicalLocation"]["region"];
    assert_eq!(
        (region["startLine"].as_u64(), region["startColumn"].as_u64()),
        (Some(23), Some(5))
    );
}

/// The link frame is the report's: `--about` moves the origin, `--axes`
/// turns the axes; what is written is what `report` gives in that frame,
/// to the bit. `--only` exports a sub-assembly as `report --only` reports it.
#[test]
fn export_writes_the_report_frames_values() {
    let part = repo("shapes/robot-arm.toml");
    let p = part.to_str().unwrap();
    let frame = ["--about", "0.1,-0.02,0.3", "--axes", "x=0,1,0;y=0,0,1"];
    let mut args = vec!["export", p, "--to", "sdf"];
    args.extend(frame);
    let element = stdout(&args);
    let i = read_back(Dialect::Sdf, element.trim_end());
    let (r, _) = super::common::report_json_file(&part, &frame);
    let f = |v: &serde_json::Value| v.as_f64().unwrap().to_bits();
    for k in 0..3 {
        assert_eq!(
            i.pos[k].to_bits(),
            f(&r["center_of_mass_ref"][k]),
            "{element}"
        );
    }
    let m = i.tensor.matrix();
    for (a, row) in m.iter().enumerate() {
        for (b, x) in row.iter().enumerate() {
            let want = r["inertia_com"][a][b].as_f64().unwrap();
            assert!(
                x.to_bits() == want.to_bits() || (*x == 0.0 && want == 0.0),
                "[{a}][{b}]: {x} against {want}\n{element}"
            );
        }
    }
    // --only: the sub-assembly's mass.
    let (whole, _) = super::common::report_json_file(&part, &[]);
    let name = whole["assemblies"][0]["path"][0]
        .as_str()
        .unwrap()
        .to_string();
    let element = stdout(&["export", p, "--to", "mjcf", "--only", &name]);
    let i = read_back(Dialect::Mjcf, element.trim_end());
    let (only, _) = super::common::report_json_file(&part, &["--only", &name]);
    assert_eq!(i.mass.to_bits(), f(&only["mass"]));
    assert!(i.mass < whole["mass"].as_f64().unwrap());
}

/// `--update` in an SDFormat model (a nested link's scoped name) and an
/// MJCF body (`--body`): only the inertial changes, and the file checks
/// clean after.
#[test]
fn update_works_in_sdformat_and_mjcf_files() {
    let dir = scratch("robots", "update-sdf-mjcf");
    for (file, link) in [("quadruped_leg.sdf", "FL_calf"), ("gripper.xml", "palm")] {
        let original = std::fs::read_to_string(repo(&format!("shapes/robots/{file}"))).unwrap();
        let target = dir.join(file);
        std::fs::write(&target, &original).unwrap();
        let t = target.to_str().unwrap();
        let flag = if file.ends_with(".xml") {
            "--body"
        } else {
            "--link"
        };
        stdout(&["export", "shapes/flywheel.toml", "--update", t, flag, link]);
        let new = std::fs::read_to_string(&target).unwrap();
        assert_ne!(new, original);
        // The bytes before and after the replaced element are the same.
        let format = Dialect::of_path(&target).unwrap_or(Dialect::Mjcf);
        let old_range = read(&Source::new(file, original.as_str()), format)
            .unwrap()
            .links
            .into_iter()
            .find(|l| l.name == link)
            .unwrap()
            .inertial
            .unwrap()
            .range;
        assert!(new.starts_with(&original[..old_range.start]), "{new}");
        assert!(new.ends_with(&original[old_range.end..]), "{new}");
        let out = massprop(&["check", t]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
}
