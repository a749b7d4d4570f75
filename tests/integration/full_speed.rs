//! `report --full`'s tables of a row per part and per sub-assembly
//! (issue 33, item 3: written at disk speed, their columns measured from
//! the numbers' digits without their text) are, byte for byte, the tables
//! this test renders itself from the JSON rows of the same file: its own
//! six- and three-digit formatting (from `{:e}`'s exact rounding), its own
//! cut of long names, its own layout of comfy-table's style. Trees of
//! includes with many rows, numbers of every notation, names past the
//! limit a table shows. No clocks: the speed is benches/output.sh's.

use crate::common::{massprop, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A binary tree of includes under `dir`: `levels` files, each including
/// the next twice at `origin = [k·step, l, 0]` (k = 0, 1; l its level),
/// named `name` when given, the last holding `leaf` (a part's keys). The
/// root's path.
fn tree(dir: &Path, levels: usize, step: f64, name: Option<&str>, leaf: &str) -> PathBuf {
    for l in 0..levels {
        let body = if l == levels - 1 {
            format!("[[part]]\n{leaf}")
        } else {
            (0..2)
                .map(|k| {
                    let named = name.map_or(String::new(), |n| format!("name = \"{n}{l}-{k}\"\n"));
                    format!(
                        "[[part]]\n{named}include = \"t{}.toml\"\norigin = [{}, {l}, 0]\n",
                        l + 1,
                        k as f64 * step
                    )
                })
                .collect()
        };
        std::fs::write(dir.join(format!("t{l}.toml")), body).unwrap();
    }
    dir.join("t0.toml")
}

/// The trees: point masses at whole metres; turned boxes in copies at
/// tiny, huge and negative coordinates (both notations, signs); long
/// sub-assembly names (every row's name cut). Written under a directory
/// of the `test`'s own (the tests run at once).
fn trees(test: &str) -> Vec<PathBuf> {
    let leaves = [
        (
            10,
            1.0,
            None,
            "shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
        ),
        (
            7,
            -3.7e-5,
            None,
            "name = \"bolt\"\nshape = \"box\"\nmass = 3.3e-7\nsize = [1, 2, 3]\n\
             center = [-1.5e-5, 2e7, 0.000123456789]\n\
             rotation = { axis = [1, 2, 3], degrees = 25 }\n\
             array = { count = 3, axis = [0, 0, 1], step_degrees = 37.5 }\n",
        ),
        (
            6,
            123_456.5,
            Some("a-rather-long-sub-assembly-name-"),
            "shape = \"rod\"\nmass = 2\nfrom = [0, 0, 0]\nto = [1, 1, 0]\n",
        ),
    ];
    leaves
        .iter()
        .enumerate()
        .map(|(i, (levels, step, name, leaf))| {
            let dir = scratch("full_speed", &format!("{test}-tree{i}"));
            tree(&dir, *levels, *step, *name, leaf)
        })
        .collect()
}

/// `x` to `digits` significant digits as the tables show numbers:
/// rounded exactly (`{:e}`), with an exponent outside −4..6 (trailing
/// zeros dropped), else fixed (trailing zeros and a bare point dropped).
fn sig(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let sci = format!("{x:.prec$e}", prec = digits - 1);
    let (mantissa, exp) = sci.split_once('e').unwrap();
    let exp: i32 = exp.parse().unwrap();
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if !(-4..6).contains(&exp) {
        return format!("{}e{exp}", trim(mantissa));
    }
    // Fixed: past the digits, the whole number (`{:.0}`); else the rounded
    // value's digits placed by its exponent.
    if exp > digits as i32 - 1 {
        return format!("{x:.0}");
    }
    let neg = mantissa.starts_with('-');
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let fixed = if exp >= 0 {
        let (whole, rest) = digits.split_at(exp as usize + 1);
        format!("{whole}.{rest}")
    } else {
        format!("0.{}{digits}", "0".repeat((-exp - 1) as usize))
    };
    format!("{}{}", if neg { "-" } else { "" }, trim(&fixed))
}

fn percent(share: &Value) -> String {
    match share.as_f64() {
        Some(f) => format!("{} %", sig(100.0 * f, 3)),
        None => "—".into(),
    }
}

/// A name as the tables show it: at most 100 characters, the rest cut
/// with the length said (the trees' names are printable ASCII).
fn shown(name: &str) -> String {
    assert!(name.bytes().all(|b| (0x20..0x7f).contains(&b)), "{name:?}");
    if name.len() <= 100 {
        name.into()
    } else {
        format!("{}… ({} characters)", &name[..99], name.len())
    }
}

/// A table in comfy-table's condensed UTF-8 style: columns as wide as
/// their widest cell (every character here one column), one space of
/// padding, `right[i]` aligned right.
fn render(header: &[&str], rows: &[Vec<String>], right: &[bool]) -> String {
    let cols = |s: &str| s.chars().count();
    let widths: Vec<usize> = (0..header.len())
        .map(|i| {
            rows.iter()
                .map(|r| cols(&r[i]))
                .chain([cols(header[i]), 1])
                .max()
                .unwrap()
        })
        .collect();
    let rule = |l: &str, f: &str, j: &str, r: &str| {
        let spans: Vec<String> = widths.iter().map(|w| f.repeat(w + 2)).collect();
        format!("{l}{}{r}\n", spans.join(j))
    };
    let line = |cells: &[&str]| {
        let padded: Vec<String> = cells
            .iter()
            .zip(&widths)
            .zip(right)
            .map(|((c, w), r)| {
                let pad = " ".repeat(w - cols(c));
                if *r {
                    format!(" {pad}{c} ")
                } else {
                    format!(" {c}{pad} ")
                }
            })
            .collect();
        format!("│{}│\n", padded.join("┆"))
    };
    let mut out = rule("┌", "─", "┬", "┐");
    out += &line(header);
    out += &rule("╞", "═", "╪", "╡");
    for r in rows {
        out += &line(&r.iter().map(String::as_str).collect::<Vec<_>>());
    }
    out + &rule("└", "─", "┴", "┘")
}

/// The cells both tables end with: mass, its share, the centre, the
/// shares of the principal moments.
fn figures(row: &Value) -> Vec<String> {
    let mut cells = vec![
        sig(row["mass"].as_f64().unwrap(), 6),
        percent(&row["mass_fraction"]),
    ];
    cells.extend((0..3).map(|i| sig(row["center_of_mass"][i].as_f64().unwrap(), 6)));
    cells.extend((0..3).map(|i| percent(&row["principal_moment_share"][i])));
    cells
}

fn parts_table(v: &Value) -> String {
    let rows: Vec<Vec<String>> = v["parts"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let mut cells = vec![
                (k + 1).to_string(),
                shown(r["name"].as_str().unwrap()),
                r["shape"].as_str().unwrap().to_string(),
            ];
            cells.extend(figures(r));
            cells
        })
        .collect();
    let header = [
        "#",
        "name",
        "shape",
        "mass (kg)",
        "mass share",
        "centroid x (m)",
        "y",
        "z",
        "I1 share",
        "I2 share",
        "I3 share",
    ];
    let right: Vec<bool> = (0..11).map(|i| !(1..3).contains(&i)).collect();
    render(&header, &rows, &right)
}

fn assemblies_table(v: &Value) -> String {
    let rows: Vec<Vec<String>> = v["assemblies"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let path = r["path"].as_array().unwrap();
            let name = shown(path.last().unwrap().as_str().unwrap());
            let mut cells = vec![
                format!("{}{name}", "  ".repeat(path.len() - 1)),
                r["parts"].to_string(),
            ];
            cells.extend(figures(r));
            cells
        })
        .collect();
    let header = [
        "sub-assembly",
        "parts",
        "mass (kg)",
        "mass share",
        "centre of mass x (m)",
        "y",
        "z",
        "I1 share",
        "I2 share",
        "I3 share",
    ];
    let right: Vec<bool> = (0..10).map(|i| i >= 1).collect();
    render(&header, &rows, &right)
}

/// `report --full`'s text and `report --format json`'s rows of `root`.
fn reports(root: &Path) -> (String, Value) {
    let root = root.to_str().unwrap();
    let full = massprop(&["report", "--full", "--width", "0", root]);
    assert!(full.status.success(), "{full:?}");
    let json = massprop(&["report", "--format", "json", root]);
    assert!(json.status.success(), "{json:?}");
    (
        String::from_utf8(full.stdout).unwrap(),
        serde_json::from_slice(&json.stdout).unwrap(),
    )
}

/// The table after the line `title` in `text`.
fn section<'a>(text: &'a str, title: &str) -> &'a str {
    let start = text.find(&format!("\n{title}\n")).unwrap() + title.len() + 2;
    let rest = &text[start..];
    let end = rest.find("┘\n").unwrap() + "┘\n".len();
    &rest[..end]
}

#[test]
fn the_full_parts_table_is_the_json_rows_rendered_independently() {
    for root in trees("parts") {
        let (text, v) = reports(&root);
        assert!(v["parts"].as_array().unwrap().len() >= 32);
        assert_eq!(section(&text, "parts"), parts_table(&v), "{root:?}");
    }
}

#[test]
fn the_full_sub_assemblies_table_is_the_json_rows_rendered_independently() {
    for root in trees("assemblies") {
        let (text, v) = reports(&root);
        assert!(v["assemblies"].as_array().unwrap().len() >= 30);
        assert_eq!(
            section(&text, "sub-assemblies"),
            assemblies_table(&v),
            "{root:?}"
        );
    }
}

#[test]
fn the_trees_show_both_notations_signs_and_cut_names() {
    let all: Vec<String> = trees("notations").iter().map(|r| reports(r).0).collect();
    let text = all.concat();
    for needle in ["e-7 ", "e7 ", " -", "… (", "—"] {
        assert!(text.contains(needle), "{needle:?} is shown somewhere");
    }
}

#[test]
fn the_test_formatting_rounds_as_its_examples_say() {
    assert_eq!(sig(1.0, 6), "1");
    assert_eq!(sig(123_456.5, 6), "123456");
    assert_eq!(sig(123_457.5, 6), "123458");
    assert_eq!(sig(1_234_567.0, 6), "1.23457e6");
    assert_eq!(sig(-0.000_123_456_789, 6), "-0.000123457");
    assert_eq!(sig(0.000_012_5, 6), "1.25e-5");
    assert_eq!(sig(99_999.95, 6), "99999.9");
    assert_eq!(sig(999_999.5, 6), "1e6");
    assert_eq!(sig(31.25, 3), "31.2");
    assert_eq!(sig(100.0, 3), "100");
    assert_eq!(
        shown(&"a".repeat(101)),
        format!("{}… (101 characters)", "a".repeat(99))
    );
}

#[test]
fn the_full_report_is_the_same_bytes_on_one_thread_and_on_two() {
    use massprop::output::grid::with_threads;
    use massprop::output::report::write_table_to;
    let mut roots = trees("threads");
    // Rows enough for several blocks on each thread (a block is 1,024).
    let dir = scratch("full_speed", "threads-big");
    roots.push(tree(
        &dir,
        13,
        0.25,
        None,
        "shape = \"point\"\nmass = 1.5\ncenter = [0, 0, 0]\n",
    ));
    for root in roots {
        let s = massprop::summarize(&root, &massprop::Settings::default()).unwrap();
        let write = |threads, width| {
            with_threads(threads, || {
                let mut out = Vec::new();
                write_table_to(&s, "t0.toml", width, &mut out).unwrap();
                out
            })
        };
        for width in [None, Some(80)] {
            let one = write(1, width);
            assert!(one.len() > 1000);
            assert!(one == write(2, width), "{root:?}, width {width:?}");
        }
    }
}
