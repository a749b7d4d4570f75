//! `massprop check`: expectations, validity, exit statuses, locations.
//!
//! The body: one 12 kg box, 1 × 2 × 3 m, centred at (1, 2, 3) m, turning
//! at ω = 2 rad/s about z. By hand: I = m/12 (b² + c², a² + c², a² + b²) =
//! (13, 10, 5) kg·m², no products; principal moments (5, 10, 13); radii
//! √(I/m); about the origin I_ref,xy = −m x y = −24; H = (0, 0, 10) N·m·s
//! about the centre of mass and T = ½ ω·H = 10 J.

use crate::common::massprop;
use serde_json::Value;
use std::path::{Path, PathBuf};

const BODY: &str = "[[part]]\nshape = \"box\"\nmass = 12\nsize = [1, 2, 3]\ncenter = [1, 2, 3]\n\n[analysis]\nomega = [0, 0, 2]\n\n[expect]\n";

/// A scratch directory for one test, emptied first.
fn scratch(name: &str) -> PathBuf {
    crate::common::scratch("check", name)
}

fn write(dir: &Path, file: &str, expect: &str) -> String {
    let path = dir.join(file);
    std::fs::write(&path, format!("{BODY}{expect}\n")).unwrap();
    path.display().to_string()
}

fn check(paths: &[&str]) -> (i32, String, String) {
    let mut args = vec!["check"];
    args.extend_from_slice(paths);
    let out = massprop(&args);
    (
        out.status.code().expect("exit status"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// Each expectation true by the hand derivation, and a wrong twin.
const CASES: &[(&str, &str)] = &[
    // 12.01 ± 0.1 % holds only if the tolerance is 0.1 % of 12.01 (0.012).
    (
        "mass = { value = 12.01, tol = \"0.1%\" }",
        "mass = { value = 12.5, tol = \"0.1%\" }",
    ),
    (
        "mass = { value = 12.001, tol = 0.01 }",
        "mass = { value = 12.1, tol = 0.01 }",
    ),
    (
        "mass = { value = \"12.005 kg\", tol = \"10 g\" }",
        "mass = { value = \"12.02 kg\", tol = \"10 g\" }",
    ),
    (
        "mass = { min = 11, max = 13 }",
        "mass = { max = \"11.9 kg\" }",
    ),
    ("mass = { min = \"26 lb\" }", "mass = { min = \"27 lb\" }"),
    (
        "center_of_mass = { value = [1, 2, 3], tol = 1e-9 }",
        "center_of_mass = { value = [1, 2, 3.1], tol = 1e-9 }",
    ),
    (
        "center_of_mass = { min = [0, 0, 0], max = [2, 3, 4] }",
        "center_of_mass = { min = [0, 0, 0], max = [2, 3, 2.9] }",
    ),
    (
        "center_of_mass.z = { value = \"3000 mm\", tol = \"1 mm\" }",
        "center_of_mass.z = { value = \"3002 mm\", tol = \"1 mm\" }",
    ),
    (
        "principal_moments = { value = [5, 10, 13], tol = \"1e-9%\" }",
        "principal_moments = { value = [5, 13, 10], tol = \"1e-9%\" }",
    ),
    (
        "principal_moments.1 = { max = 5.0000001 }",
        "principal_moments.1 = { max = 4.9999 }",
    ),
    (
        "inertia_com = { value = [[13, 0, 0], [0, 10, 0], [0, 0, 5]], tol = 1e-12 }",
        "inertia_com = { value = [[13, 0, 0], [0, 10, 0], [0, 0, 6]], tol = 1e-12 }",
    ),
    (
        "Ixx = { value = 13, tol = \"0.001%\" }",
        "Ixx = { value = 12.9, tol = \"0.001%\" }",
    ),
    (
        "Ixy = { min = -1e-12, max = 1e-12 }",
        "Ixy = { min = 1e-6 }",
    ),
    (
        "inertia_com.yy = { value = 10, tol = 1e-12 }",
        "inertia_com.yy = { value = 10.1, tol = 1e-12 }",
    ),
    (
        "radii_of_gyration.3 = { value = 1.0408329997330663, tol = 1e-12 }",
        "radii_of_gyration.3 = { value = 1.05, tol = 1e-12 }",
    ),
    // k_zz = √(Izz/m) = √(5/12), about the z axis through the centre.
    (
        "radii_of_gyration_axes.z = { value = 0.6454972243679028, tol = 1e-12 }",
        "radii_of_gyration_axes.z = { value = 0.646, tol = 1e-12 }",
    ),
    (
        "angular_momentum = { value = [0, 0, 10], tol = 1e-12 }",
        "angular_momentum = { value = [0, 0, 10.5], tol = 1e-12 }",
    ),
    (
        "kinetic_energy = { value = \"10 J\", tol = \"0.1%\" }",
        "kinetic_energy = { value = 9, tol = \"0.1%\" }",
    ),
];

#[test]
fn each_kind_of_expectation_passes_when_true_and_fails_when_not() {
    let dir = scratch("kinds");
    for (i, (good, bad)) in CASES.iter().enumerate() {
        let ok = write(&dir, &format!("good{i}.toml"), good);
        let (code, stdout, stderr) = check(&[&ok]);
        assert_eq!(code, 0, "{good}: {stdout}{stderr}");
        assert_eq!(
            stdout,
            format!("{ok}: ok\nchecked 1 file: 1 ok, 0 failed, 0 invalid\n")
        );

        let fail = write(&dir, &format!("bad{i}.toml"), bad);
        let (code, stdout, stderr) = check(&[&fail]);
        assert_eq!(code, 1, "{bad}: {stdout}{stderr}");
        // The failure points at the expectation's line: the last of the file.
        let line = BODY.lines().count() + 1;
        assert!(
            stdout.starts_with(&format!("{fail}:{line}:")),
            "{bad}: {stdout}"
        );
        assert!(stdout.contains(": error: "), "{stdout}");
        assert!(stderr.is_empty());
    }
}

#[test]
fn inertia_about_the_reference_point_uses_the_parallel_axis_shift() {
    // About the origin: I_xy = −m x y = −12 · 1 · 2 = −24.
    let dir = scratch("ref");
    let text = "[analysis]\nabout = [0, 0, 0]\n";
    let body = BODY.replace("[analysis]\nomega = [0, 0, 2]\n", text);
    let path = dir.join("ref.toml");
    std::fs::write(
        &path,
        format!("{body}inertia_ref.xy = {{ value = -24, tol = 1e-12 }}\n"),
    )
    .unwrap();
    let (code, stdout, _) = check(&[path.to_str().unwrap()]);
    assert_eq!(code, 0, "{stdout}");
}

#[test]
fn failure_messages_give_measured_expected_and_offset() {
    let dir = scratch("message");
    let f = write(&dir, "m.toml", "mass = { value = 12.5, tol = \"0.5%\" }");
    let (_, stdout, _) = check(&[&f]);
    // 12 against 12.5: off by −4 %.
    assert!(
        stdout.contains("error: mass 12 kg is outside 12.5 kg ± 0.5 % (off by -4.000 %)"),
        "{stdout}"
    );
    let f = write(&dir, "b.toml", "center_of_mass.z = { max = 2.5 }");
    let (_, stdout, _) = check(&[&f]);
    assert!(
        stdout.contains("error: center_of_mass.z 3 m is above the maximum 2.5 m (by 0.5 m)"),
        "{stdout}"
    );
}

#[test]
fn mixed_inputs_exit_two_and_every_file_is_still_checked() {
    let dir = scratch("mixed");
    let sub = dir.join("sub");
    std::fs::create_dir_all(&sub).unwrap();
    write(&dir, "a-ok.toml", CASES[0].0);
    write(&sub, "b-fails.toml", CASES[0].1);
    std::fs::write(dir.join("c-invalid.toml"), "[[part]]\nshape = \"cube\"\n").unwrap();
    std::fs::write(dir.join("notes.txt"), "not a part file").unwrap();
    let d = dir.display().to_string();
    let (code, stdout, stderr) = check(&[&d]);
    assert_eq!(code, 2);
    // Sorted, recursive, *.toml only: a-ok, c-invalid, sub/b-fails.
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines[0], format!("{d}/a-ok.toml: ok"));
    assert_eq!(
        lines[1],
        format!("{d}/c-invalid.toml: invalid (see the error above)")
    );
    assert!(lines[2].starts_with(&format!("{d}/sub/b-fails.toml:")));
    assert_eq!(lines[3], "checked 3 files: 1 ok, 1 failed, 1 invalid");
    assert!(
        stderr.contains("c-invalid.toml:2:9: error: unknown shape \"cube\""),
        "{stderr}"
    );

    // Without the invalid file: status 1.
    std::fs::remove_file(dir.join("c-invalid.toml")).unwrap();
    assert_eq!(check(&[&d]).0, 1);
    // Only the passing file: status 0.
    assert_eq!(check(&[&format!("{d}/a-ok.toml")]).0, 0);
}

#[test]
fn json_lists_every_file_and_expectation() {
    let dir = scratch("json");
    let good = write(
        &dir,
        "good.toml",
        &format!("{}\n{}", CASES[0].0, CASES[7].0),
    );
    let bad = write(&dir, "bad.toml", CASES[3].1);
    let out = massprop(&["check", &good, &bad, "--format", "json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: Value = serde_json::from_slice(&out.stdout).expect("one JSON document");
    assert_eq!(v["format_version"], 2);
    assert_eq!(v["summary"]["files"], 2);
    assert_eq!(v["summary"]["failed"], 1);
    let files = v["files"].as_array().unwrap();
    assert_eq!(files[0]["status"], "ok");
    let checks = files[0]["checks"].as_array().unwrap();
    assert_eq!(checks.len(), 2);
    assert_eq!(checks[0]["quantity"], "mass");
    assert_eq!(checks[0]["value"], 12.01);
    assert_eq!(checks[0]["tol_relative"], 0.001);
    assert_eq!(checks[1]["quantity"], "center_of_mass.z");
    assert_eq!(checks[1]["measured"], 3.0);
    assert_eq!(checks[1]["tol"], 0.001); // "1 mm" in SI
    let bad_check = &files[1]["checks"][0];
    assert_eq!(bad_check["pass"], false);
    assert_eq!(bad_check["max"], 11.9);
    assert_eq!(bad_check["line"], BODY.lines().count() + 1);
    assert_eq!(bad_check["column"], 8);
    // The failure's message is the table's, after `error: `; a passing
    // check has none.
    assert_eq!(
        bad_check["message"],
        "mass 12 kg is above the maximum 11.9 kg (by 0.1 kg)"
    );
    assert!(checks[0].get("message").is_none(), "{}", checks[0]);
}

#[test]
fn the_example_files_hold_their_expectations() {
    let (code, stdout, stderr) = check(&["shapes"]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    // The part files and the robot descriptions of shapes/robots/.
    let n = crate::common::example_part_files().len()
        + std::fs::read_dir("shapes/robots").unwrap().count();
    assert!(
        stdout.ends_with(&format!("checked {n} files: {n} ok, 0 failed, 0 invalid\n")),
        "{stdout}"
    );
}

#[test]
fn bless_writes_values_keeps_everything_else_and_then_check_passes() {
    let dir = scratch("bless");
    // Hand values as in the module doc: mass 12, centre (1, 2, 3) in mm
    // here, principal moments (5, 10, 13) kg·m² = (5e6, 1e7, 1.3e7) kg·mm².
    let text = "# A comment that must survive.\n\
        units = { length = \"mm\" }   # trailing comment\n\n\
        [[part]]\nshape = \"box\"\nmass = 12\nsize = [1000, 2000, 3000]\ncenter = [1000, 2000, 3000]\n\n\
        [expect]\n\
        mass = { value = 11, tol = \"1%\" }   # kept\n\
        center_of_mass.z = { value = 2500 }\n\
        principal_moments = { value = [1, 2, 3], tol = 10 }\n\
        Izz = { max = 1 }   # a limit: never blessed\n";
    let path = dir.join("part.toml");
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    // A `value` without `tol` is invalid until blessed.
    assert_eq!(check(&[p]).0, 2);

    let (code, _, stderr) = check(&["--bless", p]);
    assert!(stderr.contains("part.toml: blessed"), "{stderr}");
    // The limit on Izz (5e6 > 1) still fails: bless never moves a limit.
    assert_eq!(code, 1);
    let blessed = std::fs::read_to_string(&path).unwrap();
    let want = "# A comment that must survive.\n\
        units = { length = \"mm\" }   # trailing comment\n\n\
        [[part]]\nshape = \"box\"\nmass = 12\nsize = [1000, 2000, 3000]\ncenter = [1000, 2000, 3000]\n\n\
        [expect]\n\
        mass = { value = 12.0, tol = \"1%\" }   # kept\n\
        center_of_mass.z = { value = 3000.0, tol = \"0.0001%\" }\n\
        principal_moments = { value = [5000000.0, 10000000.0, 13000000.0], tol = 10 }\n\
        Izz = { max = 1 }   # a limit: never blessed\n";
    assert_eq!(blessed, want);

    // Without the limit, the blessed file passes.
    std::fs::write(
        &path,
        blessed.replace("Izz = { max = 1 }", "Izz = { max = 5000001 }"),
    )
    .unwrap();
    assert_eq!(check(&[p]).0, 0);
    // Blessing again changes nothing.
    let before = std::fs::read_to_string(&path).unwrap();
    let (_, _, stderr) = check(&["--bless", p]);
    assert!(stderr.contains("unchanged"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), before);
}

/// `--bless` writes the fewest digits within 1/1000 of each tolerance, in
/// the form the file wrote: a box of 0.1 × 0.2 × 0.3 m³ of steel (7850
/// kg/m³) is 47.1 kg, written in the file's `kg` string; its centre at
/// (12.3456 mm, 0.02 m, 0.033333 m) within 1 µm (1 mm / 1000) is
/// 12.346 mm (12.35 is 4.4 µm off), 0.02 and 0.033333 (0.03333 is 3 µm
/// off), each component in its own form.
#[test]
fn bless_keeps_each_values_form_with_the_fewest_digits_within_its_tolerance() {
    let dir = scratch("bless-form");
    let text = "[[part]]\nshape = \"box\"\ndensity = 7850\nsize = [0.1, 0.2, 0.3]\n\
        center = [0.0123456, 0.02, 0.033333]\n\n[expect]\n\
        mass = { value = \"4.176 kg\", tol = \"1%\" }\n\
        center_of_mass = { value = [\"12 mm\", 0, 0.03], tol = 0.001 }\n";
    let path = dir.join("part.toml");
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    let (code, _, stderr) = check(&["--bless", p]);
    assert_eq!(code, 0, "{stderr}");
    let blessed = std::fs::read_to_string(&path).unwrap();
    assert!(
        blessed.ends_with(
            "mass = { value = \"47.1 kg\", tol = \"1%\" }\n\
            center_of_mass = { value = [\"12.346 mm\", 0.02, 0.033333], tol = 0.001 }\n"
        ),
        "{blessed}"
    );
    // A tidy file is blessed into itself.
    let (_, _, stderr) = check(&["--bless", p]);
    assert!(stderr.contains("unchanged"), "{stderr}");
}

#[test]
fn bless_adds_an_expect_block_and_leaves_invalid_files_untouched() {
    let dir = scratch("bless-new");
    let body = BODY.replace("\n[expect]\n", "");
    let good = dir.join("good.toml");
    std::fs::write(&good, &body).unwrap();
    let bad = dir.join("bad.toml");
    let bad_text = "[[part]]\nshape = \"cube\"   # a typo\n";
    std::fs::write(&bad, bad_text).unwrap();
    let d = dir.display().to_string();
    let (code, _, stderr) = check(&["--bless", &d]);
    assert_eq!(code, 2, "{stderr}");
    assert_eq!(std::fs::read_to_string(&bad).unwrap(), bad_text);
    let blessed = std::fs::read_to_string(&good).unwrap();
    assert!(
        blessed.starts_with(&body),
        "everything before [expect] is kept"
    );
    assert!(
        blessed.contains("mass = { value = 12.0, tol = \"0.0001%\" }"),
        "{blessed}"
    );
    assert!(
        blessed.contains("center_of_mass = { value = [1.0, 2.0, 3.0], tol = 0.000003 }"),
        "{blessed}"
    );
    assert!(
        blessed.contains("principal_moments = { value = [5.0"),
        "{blessed}"
    );
    assert_eq!(check(&[good.to_str().unwrap()]).0, 0);
    // No temporary files are left behind.
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
}

#[test]
fn symlinked_directories_are_not_followed() {
    // `up -> ..` twice in one directory: followed, the walk would grow
    // without end; a symlinked file is still checked.
    let dir = scratch("symlink-loop");
    let sub = dir.join("sub");
    std::fs::create_dir_all(&sub).unwrap();
    let a = write(&sub, "a.toml", "mass = { value = 12, tol = \"0.1%\" }");
    std::os::unix::fs::symlink("..", sub.join("up")).unwrap();
    std::os::unix::fs::symlink("..", sub.join("up2")).unwrap();
    std::os::unix::fs::symlink("a.toml", sub.join("b.toml")).unwrap();
    let (code, stdout, stderr) = check(&[dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains(&format!("{a}: ok")), "{stdout}");
    assert!(stdout.contains("checked 2 files: 2 ok"), "{stdout}");
}

#[test]
fn bless_keeps_crlf_line_endings_and_refuses_stdin_by_saying_so() {
    let dir = scratch("bless-crlf");
    let path = dir.join("crlf.toml");
    let text = format!("{BODY}mass = {{ value = 11, tol = \"0.1%\" }}\n").replace('\n', "\r\n");
    std::fs::write(&path, &text).unwrap();
    let (code, _, stderr) = check(&["--bless", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let blessed = std::fs::read_to_string(&path).unwrap();
    assert!(blessed.contains("value = 12"), "{blessed}");
    assert_eq!(
        blessed.matches('\n').count(),
        blessed.matches("\r\n").count(),
        "a bare LF crept in:\n{blessed:?}"
    );
    assert_eq!(blessed.replace("value = 12.0", "value = 11"), text);

    let out = crate::common::massprop_stdin(&["check", "--bless", "-"], &text);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("cannot bless standard input"), "{stderr}");
}

/// A FIFO named `*.toml` in a directory is reported as not a part file and
/// never opened (opening it blocked `check` forever); the other files are
/// still checked and the summary line is printed.
#[test]
fn a_fifo_found_in_a_directory_is_reported_not_opened() {
    let dir = crate::common::scratch("check", "fifo");
    std::fs::copy("shapes/bent-plate.toml", dir.join("a.toml")).unwrap();
    let made = std::process::Command::new("mkfifo")
        .arg(dir.join("b.toml"))
        .status();
    if !made.is_ok_and(|s| s.success()) {
        eprintln!("skipped: mkfifo is not available");
        return;
    }
    // A FIFO opened would block `check` forever: past the guard, a hang.
    let out = crate::common::within_a_minute(&["check", dir.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stdout}{stderr}");
    assert!(stderr.contains("not a regular file"), "{stderr}");
    assert!(stdout.contains("a.toml: ok"), "{stdout}");
    assert!(
        stdout.contains("checked 2 files: 1 ok, 0 failed, 1 invalid"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `check --bless` refuses to change a read-only file and leaves it as it
/// was (a rename replaced it regardless of its mode); one that needs no
/// change is `unchanged`, and passes.
#[test]
fn bless_refuses_a_read_only_file() {
    let dir = crate::common::scratch("check", "bless-read-only");
    let f = dir.join("ro.toml");
    let text = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    std::fs::write(&f, text).unwrap();
    let mut perms = std::fs::metadata(&f).unwrap().permissions();
    perms.set_readonly(true);
    std::fs::set_permissions(&f, perms).unwrap();
    let out = crate::common::massprop(&["check", "--bless", f.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("read-only: the blessed file is not written"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&f).unwrap(), text);
    // Blessed while writable, then read-only: nothing to change.
    let mut perms = std::fs::metadata(&f).unwrap().permissions();
    #[allow(
        clippy::permissions_set_readonly_false,
        reason = "the test makes it writable again on purpose"
    )]
    perms.set_readonly(false);
    std::fs::set_permissions(&f, perms.clone()).unwrap();
    let out = crate::common::massprop(&["check", "--bless", f.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let blessed = std::fs::read_to_string(&f).unwrap();
    perms.set_readonly(true);
    std::fs::set_permissions(&f, perms).unwrap();
    let out = crate::common::massprop(&["check", "--bless", f.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("ro.toml: unchanged"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&f).unwrap(), blessed);
    std::fs::remove_dir_all(&dir).ok();
}

/// File names that are not UTF-8 are checked like any other (they were
/// reported as missing), and shown with each such byte as `\xNN` and
/// control characters as their pictures, on stdout and stderr alike;
/// includes resolve from a directory whose name is not UTF-8.
#[cfg(unix)]
#[test]
fn names_that_are_not_utf8_are_checked_and_shown_escaped() {
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;
    let dir = scratch("not-utf8");
    let named = |bytes: &[u8]| dir.join(OsStr::from_bytes(bytes));
    let body = |expect: &str| format!("{BODY}{expect}\n");
    std::fs::write(
        named(b"ok-\xff.toml"),
        body("mass = { value = 12.001, tol = 0.01 }"),
    )
    .unwrap();
    std::fs::write(
        named(b"bad-\xfe.toml"),
        body("mass = { value = 12.5, tol = 0.01 }"),
    )
    .unwrap();
    let shown = |name: &str| format!("{}/{name}", dir.display());
    let out = massprop(&["check", dir.to_str().unwrap()]);
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    // `[expect]` is line 10 of BODY: the mass entry is line 11.
    let lines: Vec<&str> = stdout.lines().collect();
    assert!(
        lines[0].starts_with(&format!("{}:11:8: error: mass ", shown("bad-\\xfe.toml"))),
        "{stdout}"
    );
    assert_eq!(
        lines[1],
        format!("{}: ok", shown("ok-\\xff.toml")),
        "{stdout}"
    );
    assert_eq!(lines[2], "checked 2 files: 1 ok, 1 failed, 0 invalid");

    let out = massprop(&["check", "--format", "json", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let json: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    let files = json["files"].as_array().unwrap();
    let entry = |i: usize| (files[i]["path"].as_str(), files[i]["status"].as_str());
    let (bad, ok) = (shown("bad-\\xfe.toml"), shown("ok-\\xff.toml"));
    assert_eq!(entry(0), (Some(bad.as_str()), Some("failed")));
    assert_eq!(entry(1), (Some(ok.as_str()), Some("ok")));

    // `--bless` cannot write such a name: it says so and leaves the file.
    let before = std::fs::read(named(b"bad-\xfe.toml")).unwrap();
    let out = massprop(&["check", "--bless", dir.to_str().unwrap()]);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(&format!(
            "{bad}: error: `--bless` cannot write a file whose name is not UTF-8"
        )),
        "{stderr}"
    );
    assert_eq!(std::fs::read(named(b"bad-\xfe.toml")).unwrap(), before);

    // A sub-assembly in a directory whose name is not UTF-8, and an
    // invalid file whose name has an escape character too.
    std::fs::create_dir(named(b"sub\xfd")).unwrap();
    std::fs::write(
        named(b"sub\xfd/asm.toml"),
        "[[part]]\ninclude = \"wheel.toml\"\norigin = [0, 0, 1]\n",
    )
    .unwrap();
    std::fs::write(named(b"sub\xfd/wheel.toml"), body("")).unwrap();
    std::fs::write(named(b"broken-\xfc\x1b.toml"), "[[part]]\nmass = \n").unwrap();
    let out = massprop(&["check", dir.to_str().unwrap()]);
    let stdout = String::from_utf8(out.stdout).unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{stdout}{stderr}");
    let broken = shown("broken-\\xfc\u{241b}.toml");
    assert!(
        stderr.starts_with(&format!("{broken}:2:8: error: ")),
        "{stderr}"
    );
    assert!(stdout.contains(&format!("\n{broken}: invalid")), "{stdout}");
    assert!(
        stdout.contains(&format!("\n{}: ok\n", shown("sub\\xfd/asm.toml"))),
        "{stdout}"
    );
    assert!(
        stdout.ends_with("checked 5 files: 3 ok, 1 failed, 1 invalid\n"),
        "{stdout}"
    );
    for text in [&stdout, &stderr] {
        assert!(!text.contains(['\u{fffd}', '\u{1b}']), "{text}");
    }
    // In JSON the escape character is data, written as a JSON escape.
    let out = massprop(&["check", "--format", "json", dir.to_str().unwrap()]);
    let json: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    let invalid: Vec<&str> = json["files"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["status"] == "invalid")
        .filter_map(|f| f["path"].as_str())
        .collect();
    assert_eq!(invalid, [shown("broken-\\xfc\u{1b}.toml").as_str()]);

    // Named on the command line (clap refused such an argument), and `-o`
    // through a link onto one of them is refused.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .arg("check")
        .arg(named(b"ok-\xff.toml"))
        .output()
        .unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert_eq!(stdout.lines().next(), Some(format!("{ok}: ok").as_str()));
    std::os::unix::fs::symlink(named(b"ok-\xff.toml"), dir.join("link.toml")).unwrap();
    let link = dir.join("link.toml");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .arg("check")
        .arg(named(b"ok-\xff.toml"))
        .args(["-o", link.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8(out.stderr)
            .unwrap()
            .contains("the report would replace it")
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `check DIR` on `dir`, which holds an invalid entry: status 2, and
/// `secret` nowhere in stdout or stderr. Returns both.
fn check_invalid_quoting_nothing_of(dir: &std::path::Path, secret: &str) -> (String, String) {
    let out = massprop(&["check", dir.to_str().unwrap()]);
    let (stdout, stderr) = (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    );
    assert_eq!(out.status.code(), Some(2), "{stdout}{stderr}");
    assert!(
        !stdout.contains(secret) && !stderr.contains(secret),
        "{stdout}{stderr}"
    );
    (stdout, stderr)
}

/// `check DIR` follows a symlinked `*.toml` only to a `*.toml` file inside
/// DIR: one to a file outside (`~/.cargo/credentials.toml`) or to one of
/// another kind (`.git/config`) is reported as not checked, and nothing of
/// it is read or quoted; the rest is checked.
#[test]
fn check_dir_follows_symlinks_only_to_part_files_inside_it() {
    const SECRET: &str = "SECRET-7c1f";
    let root = crate::common::scratch("check", "dir-links");
    let (tree, outside) = (root.join("tree"), root.join("outside"));
    std::fs::create_dir_all(tree.join(".git")).unwrap();
    std::fs::create_dir_all(&outside).unwrap();
    std::fs::write(
        outside.join("credentials.toml"),
        format!("token = \"{SECRET}\"\n"),
    )
    .unwrap();
    std::fs::write(
        tree.join(".git/config"),
        format!("[http]\n\textraheader = {SECRET}\n"),
    )
    .unwrap();
    let part = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    std::fs::write(tree.join("real.toml"), part).unwrap();
    let link =
        |to: &std::path::Path, name: &str| std::os::unix::fs::symlink(to, tree.join(name)).unwrap();
    link(&outside.join("credentials.toml"), "a.toml");
    link(&tree.join(".git/config"), "b.toml");
    link(&tree.join("real.toml"), "c.toml");
    let (stdout, stderr) = check_invalid_quoting_nothing_of(&tree, SECRET);
    for skipped in ["a.toml", "b.toml"] {
        assert!(
            stderr.contains(&format!(
                "{skipped}: error: not checked: a symlink to a file outside"
            )),
            "{stderr}"
        );
    }
    assert!(
        stdout.ends_with("checked 4 files: 2 ok, 0 failed, 2 invalid\n"),
        "{stdout}"
    );
}

/// A `*.toml` that `check DIR` finds but that is no part file (no
/// top-level table or key of massprop's: `Cargo.toml`, settings,
/// credentials) is passed over: counted as skipped, nothing of it quoted,
/// not blessed; one named on the command
/// line is checked (and its error quoted) as before.
#[test]
fn check_dir_passes_over_a_toml_file_that_is_not_a_part_file() {
    const SECRET: &str = "SECRET-91d2";
    let dir = crate::common::scratch("check", "dir-non-part");
    let secret = format!("token = \"{SECRET}\"\n");
    std::fs::write(dir.join("settings.toml"), &secret).unwrap();
    std::fs::write(dir.join("Cargo.toml"), "[package]\nname = \"x\"\n").unwrap();
    // A part file with a byte-order mark and a quoted header is one.
    std::fs::write(
        dir.join("real.toml"),
        "\u{feff}[[\"part\"]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    for bless in [false, true] {
        let mut args = vec!["check", dir.to_str().unwrap()];
        if bless {
            args.push("--bless");
        }
        let out = massprop(&args);
        let (stdout, stderr) = (
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
        );
        assert_eq!(out.status.code(), Some(0), "{stdout}{stderr}");
        assert!(!stdout.contains(SECRET) && !stderr.contains(SECRET));
        assert!(
            stdout
                .ends_with("real.toml: ok\nchecked 1 file: 1 ok, 0 failed, 0 invalid, 2 skipped\n"),
            "{stdout}"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("settings.toml")).unwrap(),
            secret
        );
    }
    // Named, it is read as the part file it is asked to be.
    let named = dir.join("settings.toml");
    let out = massprop(&["check", named.to_str().unwrap()]);
    assert!(
        String::from_utf8(out.stderr)
            .unwrap()
            .contains("unknown key `token`")
    );
}
