//! Plain `report` is the short answer (issue 31 item 3): the essentials in
//! about 25 lines, no row per part; `--full` is every table, as before;
//! JSON is the same either way; `check --quiet` prints what failed and
//! the summary line only.

use crate::common::{example_part_files, massprop, scratch};

const BENT_PLATE: &str = "shapes/bent-plate.toml";

fn stdout(args: &[&str]) -> String {
    let out = massprop(args);
    assert_eq!(out.status.code(), Some(0), "{args:?}: {out:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// A value to six significant digits as the tables print it (`%g`-like:
/// no trailing zeros), from the hand formula, not from massprop.
fn six(x: f64) -> String {
    let digits = 5 - x.abs().log10().floor() as i32;
    let s = format!("{:.*}", digits.max(0) as usize, x);
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// Every number printed in `text` (the cells and lines of a table).
fn numbers(text: &str) -> Vec<String> {
    text.split(|c: char| c.is_whitespace() || "│┆(),;:".contains(c))
        .filter(|w| !w.is_empty() && w.parse::<f64>().is_ok())
        .map(str::to_string)
        .collect()
}

#[test]
fn the_bent_plates_short_report_is_at_most_25_lines() {
    let text = stdout(&["report", BENT_PLATE]);
    let lines = text.lines().count();
    assert!(lines <= 25, "{lines} lines:\n{text}");
}

#[test]
fn the_bent_plates_short_report_fits_80_columns_unsplit() {
    let text = stdout(&["report", "--width", "80", BENT_PLATE]);
    assert!(!text.contains("table split"), "{text}");
    use unicode_width::UnicodeWidthStr;
    for line in text.lines() {
        assert!(line.width() <= 80, "{line}");
    }
}

/// The file's hand values (its comments, Beer & Johnston): m = 70 kg/m² ×
/// (0.0125 + 0.01125) m², the centre of mass from the plates' centroids,
/// H = 30 (−∫xz, −∫yz, ∫(x² + y²)) dm, T = ½ ω H_z.
#[test]
fn the_short_report_shows_mass_centre_of_mass_h_and_t_of_the_hand_computation() {
    let text = stdout(&["report", BENT_PLATE]);
    let (ma, mb) = (70.0 * 0.0125, 70.0 * 0.01125);
    let m: f64 = ma + mb;
    let com = [
        mb * 37.5 / m,
        (ma * 62.5 + mb * 125.0) / m,
        (ma * 50.0 + mb * 75.0) / m,
    ];
    let h = [-0.0664453125, -0.303515625, 0.55015625];
    let t = 0.5 * 30.0 * h[2];
    assert!(text.contains(&format!("mass: {} kg", six(m))), "{text}");
    assert!(
        text.contains(&format!("kinetic energy T: {} J", six(t))),
        "{text}"
    );
    let row = |label: &str| {
        text.lines()
            .find(|l| l.starts_with(&format!("│ {label} ")))
            .unwrap_or_else(|| panic!("no row {label:?} in\n{text}"))
            .to_string()
    };
    assert_eq!(
        numbers(&row("centre of mass")),
        com.map(six).to_vec(),
        "{text}"
    );
    assert_eq!(
        numbers(&row("angular momentum H about O")),
        h.map(six).to_vec(),
        "{text}"
    );
    // H is about the file's reference point O = (0, 0, 0), which the
    // table gives.
    assert_eq!(numbers(&row("reference point O")), ["0", "0", "0"]);
}

#[test]
fn the_short_report_keeps_the_conventions_the_tensor_and_the_principal_axes() {
    let text = stdout(&["report", BENT_PLATE]);
    for want in [
        "units: mass kg, length mm, inertia kg·mm²",
        "products of inertia: tensor convention, Ixy = −∫xy dm",
        "│ inertia about it x ",
        "principal moments and axes about the centre of mass (ascending)",
        "│ I1 ",
        "│ I3 ",
    ] {
        assert!(text.contains(want), "missing {want:?} in\n{text}");
    }
}

#[test]
fn the_short_report_ends_with_one_line_saying_what_full_adds() {
    let text = stdout(&["report", BENT_PLATE]);
    let last = text.lines().last().unwrap();
    assert!(last.starts_with("`--full` for "), "{last}");
    assert!(last.contains("the 2 parts"), "{last}");
}

#[test]
fn the_short_report_lists_no_part_and_the_full_one_does() {
    let dir = scratch("short_report", "names");
    let file = dir.join("two.toml");
    let part = |name: &str, x: f64| {
        format!(
            "[[part]]\nname = \"{name}\"\nshape = \"point\"\nmass = 1\ncenter = [{x}, 0, 0]\n\n"
        )
    };
    std::fs::write(&file, part("zebra-left", 0.0) + &part("zebra-right", 1.0)).unwrap();
    let file = file.to_str().unwrap();
    let short = stdout(&["report", file]);
    assert!(!short.contains("zebra"), "{short}");
    let full = stdout(&["report", "--full", file]);
    assert!(
        full.contains("zebra-left") && full.contains("zebra-right"),
        "{full}"
    );
}

/// The old report's sections, by the headings and rows it printed: the
/// full report of a file with a reference point, sub-assemblies and
/// thin parts has every one.
#[test]
fn the_full_report_has_every_table_of_the_old_report() {
    for (file, headings) in [
        (
            BENT_PLATE,
            &[
                "axes: the file's",
                "precision: ",
                "│ radius of gyration k_xx, k_yy, k_zz ",
                "│ reference point ",
                "│ centre of mass from the point ",
                "│ k_xx, k_yy, k_zz through the point ",
                "inertia about the centre of mass (kg·mm²)",
                "inertia about the reference point (0, 0, 0) mm (kg·mm²)",
                "principal moments and axes about the centre of mass (ascending)",
                "radius of gyration (mm)",
                "principal moments and axes about the reference point (ascending)",
                "\nparts\n",
                "I1–I3 share: ",
            ][..],
        ),
        (
            "shapes/robot-arm.toml",
            &[
                "\nsub-assemblies\n",
                "\nidealisation (thin plates and slender rods as solids)\n",
            ][..],
        ),
    ] {
        let text = stdout(&["report", "--full", file]);
        for h in headings {
            assert!(text.contains(h), "{file}: missing {h:?} in\n{text}");
        }
    }
}

#[test]
fn every_number_of_each_examples_short_report_is_one_its_full_report_prints() {
    for path in example_part_files() {
        let file = path.to_str().unwrap();
        let short = stdout(&["report", file]);
        let full = numbers(&stdout(&["report", "--full", file]));
        for n in numbers(&short) {
            assert!(full.contains(&n), "{file}: {n} is not in the full report");
        }
    }
}

#[test]
fn json_is_the_same_with_and_without_full() {
    for path in example_part_files() {
        let file = path.to_str().unwrap();
        assert_eq!(
            stdout(&["report", "--format", "json", file]),
            stdout(&["report", "--format", "json", "--full", file]),
            "{file}"
        );
    }
}

#[test]
fn accuracy_warnings_are_the_same_on_stderr_with_and_without_full() {
    let args = [
        "report",
        "shapes/robot-arm.toml",
        "--precision",
        "standard",
        "--rtol",
        "3e-16",
    ];
    let short = massprop(&args);
    let full = massprop(&[&args[..], &["--full"]].concat());
    let warnings = String::from_utf8(short.stderr).unwrap();
    assert!(warnings.contains("warning: "), "{warnings}");
    assert_eq!(warnings, String::from_utf8(full.stderr).unwrap());
    // And the short table says how many values fall short.
    let text = String::from_utf8(short.stdout).unwrap();
    assert!(
        text.contains("are not within it (see the warnings)"),
        "{text}"
    );
}

#[test]
fn a_reference_point_given_by_about_shows_its_tensors_in_the_short_report() {
    let text = stdout(&["report", "shapes/welded-bracket.toml", "--about", "0,0,0"]);
    for want in [
        "inertia about the reference point (0, 0, 0) mm (kg·mm²)",
        "principal moments and axes about the reference point (ascending)",
    ] {
        assert!(text.contains(want), "missing {want:?} in\n{text}");
    }
}

#[test]
fn a_reference_point_in_the_file_leaves_its_tensors_to_full() {
    let text = stdout(&["report", "shapes/welded-bracket.toml"]);
    assert!(!text.contains("about the reference point"), "{text}");
    assert!(
        text.lines()
            .last()
            .unwrap()
            .contains("the reference point's tensors"),
        "{text}"
    );
}

#[test]
fn uncertainty_asked_for_is_in_the_short_report() {
    let text = stdout(&["report", "shapes/smallsat.toml", "--uncertainty", "linear"]);
    assert!(text.contains("\nuncertainty (linear"), "{text}");
}

#[test]
fn check_quiet_prints_no_ok_line_and_counts_every_file() {
    let out = massprop(&["check", "--quiet", "shapes"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{text}");
    let n = example_part_files().len();
    // The robot descriptions in shapes/robots/ are checked too.
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 1, "{text}");
    assert!(lines[0].starts_with("checked "), "{text}");
    let files: usize = lines[0]["checked ".len()..]
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(files >= n, "{text}");
    assert!(
        lines[0].contains(&format!("{files} ok, 0 failed")),
        "{text}"
    );
}

#[test]
fn check_quiet_prints_a_failure_and_the_summary() {
    let dir = scratch("short_report", "quiet");
    let point = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n\n";
    std::fs::write(
        dir.join("good.toml"),
        format!("{point}[expect]\nmass = {{ value = 1, tol = 1e-9 }}\n"),
    )
    .unwrap();
    std::fs::write(
        dir.join("bad.toml"),
        format!("{point}[expect]\nmass = {{ value = 2, tol = 1e-9 }}\n"),
    )
    .unwrap();
    let out = massprop(&["check", "-q", dir.to_str().unwrap()]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{text}");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "{text}");
    assert!(
        lines[0].contains("bad.toml:7:") && lines[0].contains("error: mass"),
        "{text}"
    );
    assert_eq!(lines[1], "checked 2 files: 1 ok, 1 failed, 0 invalid");
}
