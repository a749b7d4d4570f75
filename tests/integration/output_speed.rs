//! The report's rows written at disk speed (issue 33, item 3): JSON's
//! `parts` and `assemblies` written by hand, each sub-assembly's part of a
//! row made once, are the bytes of the summary serialized element by
//! element (`report::json`, the path that writes nothing by hand), on
//! trees with names that need escaping; each row is its part placed
//! instance by instance through every frame of its path (derived here, in
//! this test's own arithmetic, from the tree as written); `--full`'s parts
//! table shows the JSON's rows; a write that fails mid-stream stops the
//! writing with its error, and a closed pipe ends the command quietly. No
//! clocks: the speed is benches/output.sh's.

use massprop::output::report::{self, write_json_to, write_table_to};
use massprop::{Settings, Summary};
use serde_json::Value;
use std::io::Write;
use std::path::Path;

/// benches/instances.sh's tree under `dir`: `levels` files, each including
/// the next twice at [k, l, 0] (k = 0, 1; l its level), the last holding
/// `leaf` (a part table's keys, without `[[part]]`). The root's path.
fn tree(dir: &Path, levels: usize, leaf: &str) -> std::path::PathBuf {
    for l in 0..levels {
        let body = if l == levels - 1 {
            format!("[[part]]\n{leaf}")
        } else {
            (0..2)
                .map(|k| {
                    format!(
                        "[[part]]\ninclude = \"t{}.toml\"\norigin = [{k}, {l}, 0]\n",
                        l + 1
                    )
                })
                .collect()
        };
        std::fs::write(dir.join(format!("t{l}.toml")), body).unwrap();
    }
    dir.join("t0.toml")
}

fn summary(path: &Path) -> Summary {
    massprop::summarize(path, &Settings::default()).unwrap_or_else(|e| panic!("{e}"))
}

fn json(s: &Summary) -> Vec<u8> {
    let mut out = Vec::new();
    write_json_to(s, &mut out).unwrap();
    out
}

fn table(s: &Summary, width: Option<usize>) -> Vec<u8> {
    let mut out = Vec::new();
    write_table_to(s, "t0.toml", width, &mut out).unwrap();
    out
}

/// A part of the leaf file in a tree of includes: turned boxes in copies
/// (names with `[i]`, paths with `#2`); names that JSON escapes (quotes, a
/// backslash, controls, the runner's `##[`, bidirectional marks, C1).
const LEAVES: [&str; 3] = [
    "shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    "name = \"bolt\"\nshape = \"box\"\nmass = 0.3\nsize = [1, 2, 3]\ncenter = [0.1, 0.2, 0.3]\n\
     rotation = { axis = [1, 2, 3], degrees = 25 }\narray = { count = 3, axis = [0, 0, 1], step_degrees = 37.5 }\n",
    "name = \"a \\\"q\\\" \\\\ \\u001b[31m ##[x] \\u202e é \\u0085 #\"\nshape = \"rod\"\nmass = 2\nfrom = [0, 0, 0]\nto = [1, 1, 0]\n",
];

/// The three-file tree of `placed`, with sub-assemblies named as JSON
/// escapes them.
fn hostile_tree(dir: &Path) -> std::path::PathBuf {
    std::fs::write(
        dir.join("leaf.toml"),
        format!("[[part]]\n{}[[part]]\n{}", LEAVES[2], LEAVES[1]),
    )
    .unwrap();
    std::fs::write(
        dir.join("mid.toml"),
        "[[part]]\nname = \"x\\\"##[y\\\\\"\ninclude = \"leaf.toml\"\norigin = [1, 2, 3]\n\
         [[part]]\nname = \"\\u2028 é\"\ninclude = \"leaf.toml\"\narray = { count = 2, step = [0, 0, 5] }\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("top.toml"),
        "[[part]]\ninclude = \"mid.toml\"\nrotation = { axis = [0, 1, 1], degrees = 33 }\n\
         [[part]]\ninclude = \"mid.toml\"\nmirror = { normal = [1, 0, 0], origin = [2, 0, 0] }\n",
    )
    .unwrap();
    dir.join("top.toml")
}

/// Trees whose rows are many: point masses, turned boxes in copies, names
/// to escape.
fn trees() -> Vec<(String, Summary)> {
    let mut all: Vec<(String, Summary)> = LEAVES
        .iter()
        .enumerate()
        .map(|(i, leaf)| {
            let dir = crate::common::scratch("output_speed", &format!("tree{i}"));
            let root = tree(&dir, 9, leaf);
            (leaf.to_string(), summary(&root))
        })
        .collect();
    let dir = crate::common::scratch("output_speed", "hostile");
    all.push(("hostile".into(), summary(&hostile_tree(&dir))));
    all
}

#[test]
fn json_with_its_rows_written_by_hand_is_the_summary_serialized_element_by_element() {
    for (leaf, s) in trees() {
        // `report::json` serializes `parts` and `assemblies` row by row in
        // place (`json_line`), the writer that writes nothing by hand.
        let by_hand = json(&s);
        let serialized = report::json(&s).into_bytes();
        assert!(
            by_hand == serialized,
            "leaf {leaf}:\n{}\n{}",
            String::from_utf8_lossy(&by_hand),
            String::from_utf8_lossy(&serialized)
        );
    }
}

#[test]
fn the_json_rows_read_back_as_the_names_written_in_the_files() {
    let dir = crate::common::scratch("output_speed", "names");
    let s = summary(&hostile_tree(&dir));
    let v: Value = serde_json::from_slice(&json(&s)).unwrap();
    let names: Vec<&str> = v["parts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    let hostile = "a \"q\" \\ \u{1b}[31m ##[x] \u{202e} é \u{85} #";
    assert_eq!(names[0], format!("mid / x\"##[y\\ / {hostile}"));
    assert_eq!(names[2], "mid / x\"##[y\\ / bolt[1]");
    assert_eq!(names[4], format!("mid / \u{2028} é[0] / {hostile}"));
    assert_eq!(names[12], format!("mid #2[0] / x\"##[y\\ / {hostile}"));
    assert_eq!(names[24], format!("mid #2[1] / x\"##[y\\ / {hostile}"));
    let row = &v["parts"][4]["assembly"];
    assert_eq!(*row, serde_json::json!(["mid", "\u{2028} é[0]"]));
    let paths: Vec<Value> = v["assemblies"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["path"].clone())
        .collect();
    assert_eq!(paths[0], serde_json::json!(["mid"]));
    assert_eq!(paths[2], serde_json::json!(["mid", "\u{2028} é[0]"]));
    assert_eq!(paths.len(), 12);
}

/// An affine map p ↦ a p + b, in this test's own f64 arithmetic.
#[derive(Clone, Copy)]
struct Affine {
    a: [[f64; 3]; 3],
    b: [f64; 3],
}

impl Affine {
    const ID: Affine = Affine {
        a: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        b: [0.0; 3],
    };

    fn moved(b: [f64; 3]) -> Affine {
        Affine { b, ..Affine::ID }
    }

    /// A turn by `deg` about `axis` (Rodrigues), about the point `o`.
    fn turn(axis: [f64; 3], deg: f64, o: [f64; 3]) -> Affine {
        let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
        let [x, y, z] = axis.map(|v| v / n);
        let (s, c) = deg.to_radians().sin_cos();
        let t = 1.0 - c;
        let a = [
            [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
        ];
        Affine::about(a, o)
    }

    /// The reflection in the plane through `o` of normal `n`.
    fn mirror(n: [f64; 3], o: [f64; 3]) -> Affine {
        let nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        let a = std::array::from_fn(|i| {
            std::array::from_fn(|j| f64::from(u8::from(i == j)) - 2.0 * n[i] * n[j] / nn)
        });
        Affine::about(a, o)
    }

    /// p ↦ o + a (p − o).
    fn about(a: [[f64; 3]; 3], o: [f64; 3]) -> Affine {
        let ao = Affine { a, b: [0.0; 3] }.apply(o);
        Affine {
            a,
            b: std::array::from_fn(|i| o[i] - ao[i]),
        }
    }

    fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|i| (0..3).map(|k| self.a[i][k] * p[k]).sum::<f64>() + self.b[i])
    }

    /// This map after `inner`.
    fn after(&self, inner: &Affine) -> Affine {
        Affine {
            a: std::array::from_fn(|i| {
                std::array::from_fn(|j| (0..3).map(|k| self.a[i][k] * inner.a[k][j]).sum())
            }),
            b: self.apply(inner.b),
        }
    }
}

/// The hostile tree's parts as this test places them: each copy of each
/// include composed outermost first, the part's centre through it.
fn placed_hostile() -> Vec<(String, [f64; 3])> {
    // leaf.toml: the rod's centre, then the bolt's three turned copies.
    let rod = [0.5, 0.5, 0.0];
    let bolt = [0.1, 0.2, 0.3];
    let mut leaf = vec![("rod", rod)];
    for k in 0..3 {
        let turn = Affine::turn([0.0, 0.0, 1.0], 37.5 * k as f64, [0.0; 3]);
        leaf.push(("bolt", turn.apply(bolt)));
    }
    // mid.toml: `x"##[y\` at [1, 2, 3]; the array's two copies 5 apart.
    let mid = [
        Affine::moved([1.0, 2.0, 3.0]),
        Affine::ID,
        Affine::moved([0.0, 0.0, 5.0]),
    ];
    // top.toml: `mid` turned; `mid #2` and its image in the mirror.
    let top = [
        Affine::turn([0.0, 1.0, 1.0], 33.0, [0.0; 3]),
        Affine::ID,
        Affine::mirror([1.0, 0.0, 0.0], [2.0, 0.0, 0.0]),
    ];
    let mut out = Vec::new();
    for (t, outer) in top.iter().enumerate() {
        for (m, inner) in mid.iter().enumerate() {
            let frame = outer.after(inner);
            for (name, c) in &leaf {
                out.push((format!("{t} {m} {name}"), frame.apply(*c)));
            }
        }
    }
    out
}

#[test]
fn each_part_row_is_its_part_placed_through_every_frame_of_its_path() {
    let dir = crate::common::scratch("output_speed", "placed");
    let s = summary(&hostile_tree(&dir));
    let v: Value = serde_json::from_slice(&json(&s)).unwrap();
    let rows = v["parts"].as_array().unwrap();
    let expected = placed_hostile();
    assert_eq!(rows.len(), expected.len());
    let total: f64 = 9.0 * (2.0 + 3.0 * 0.3);
    for (row, (what, c)) in rows.iter().zip(&expected) {
        let got: Vec<f64> = row["center_of_mass"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        // Three frames deep, numbers below 20: each coordinate within a few
        // roundings of this test's own composition.
        for i in 0..3 {
            assert!(
                (got[i] - c[i]).abs() <= 64.0 * f64::EPSILON * 20.0,
                "{what}: {got:?} vs {c:?}"
            );
        }
        let mass = if what.ends_with("rod") { 2.0 } else { 0.3 };
        assert_eq!(row["mass"].as_f64().unwrap(), mass, "{what}");
        let fraction = row["mass_fraction"].as_f64().unwrap();
        assert!(
            (fraction - mass / total).abs() <= 4.0 * f64::EPSILON,
            "{what}"
        );
    }
}

#[test]
fn each_row_of_a_binary_tree_is_its_leaf_moved_by_every_include_of_its_path() {
    let levels = 10;
    let dir = crate::common::scratch("output_speed", "binary");
    let root = tree(&dir, levels, LEAVES[0]);
    let s = summary(&root);
    let v: Value = serde_json::from_slice(&json(&s)).unwrap();
    let parts = v["parts"].as_array().unwrap();
    assert_eq!(parts.len(), 1 << (levels - 1));
    // Row i in file order: bit l (from the top) of i picks the second
    // include at level l, which moves x by 1; every level moves y by l.
    let y: f64 = (0..levels - 1).map(|l| l as f64).sum();
    let n = (1 << (levels - 1)) as f64;
    for (i, row) in parts.iter().enumerate() {
        let bits: Vec<bool> = (0..levels - 1)
            .map(|l| (i >> (levels - 2 - l)) & 1 == 1)
            .collect();
        let x = bits.iter().filter(|b| **b).count() as f64;
        assert_eq!(
            row["center_of_mass"],
            serde_json::json!([x, y, 0.0]),
            "row {i}"
        );
        assert_eq!(row["mass"], 1.0);
        assert_eq!(row["mass_fraction"], 1.0 / n);
        let path: Vec<String> = bits
            .iter()
            .enumerate()
            .map(|(l, b)| format!("t{}{}", l + 1, if *b { " #2" } else { "" }))
            .collect();
        assert_eq!(row["name"], format!("{} / part 1", path.join(" / ")));
        assert_eq!(row["assembly"], serde_json::json!(path));
    }
}

/// A number of the table: `x` to `digits` significant digits, read back
/// (`{:e}` rounds exactly; the table's text, fixed or not, reads back as
/// the same number).
fn rounded(x: f64, digits: usize) -> f64 {
    format!("{x:.prec$e}", prec = digits - 1).parse().unwrap()
}

#[test]
fn the_full_tables_part_rows_show_the_json_rows() {
    for (leaf, s) in trees().into_iter().take(2) {
        let v: Value = serde_json::from_slice(&json(&s)).unwrap();
        let rows = v["parts"].as_array().unwrap();
        let text = String::from_utf8(table(&s, None)).unwrap();
        let body: Vec<&str> = text
            .split("\nparts\n")
            .nth(1)
            .unwrap()
            .lines()
            .skip(3)
            .take_while(|l| l.starts_with('│'))
            .collect();
        assert_eq!(body.len(), rows.len(), "leaf {leaf}");
        for (k, (line, row)) in body.iter().zip(rows).enumerate() {
            let cells: Vec<&str> = line.trim_matches('│').split('┆').map(str::trim).collect();
            assert_eq!(cells[0], (k + 1).to_string());
            assert_eq!(cells[1], row["name"].as_str().unwrap());
            assert_eq!(cells[2], row["shape"].as_str().unwrap());
            let num = |c: &str| -> f64 { c.parse().unwrap() };
            let percent = |c: &str| -> f64 { c.strip_suffix(" %").unwrap().parse().unwrap() };
            let f = |v: &Value| v.as_f64().unwrap();
            assert_eq!(num(cells[3]), rounded(f(&row["mass"]), 6), "{line}");
            assert_eq!(
                percent(cells[4]),
                rounded(100.0 * f(&row["mass_fraction"]), 3),
                "{line}"
            );
            for i in 0..3 {
                let c = f(&row["center_of_mass"][i]);
                assert_eq!(num(cells[5 + i]), rounded(c, 6), "{line}");
                let share = &row["principal_moment_share"][i];
                match share.as_f64() {
                    Some(x) => assert_eq!(percent(cells[8 + i]), rounded(100.0 * x, 3)),
                    None => assert_eq!(cells[8 + i], "—"),
                }
            }
        }
    }
}

/// A writer that takes `left` bytes, then fails as a closed pipe does.
struct Closing {
    taken: Vec<u8>,
    left: usize,
}

impl Write for Closing {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if self.left == 0 {
            return Err(std::io::ErrorKind::BrokenPipe.into());
        }
        let n = buf.len().min(self.left);
        self.taken.extend_from_slice(&buf[..n]);
        self.left -= n;
        Ok(n)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[test]
fn a_write_that_fails_mid_stream_ends_the_writing_with_its_error_after_a_prefix() {
    let (_, s) = trees().swap_remove(0);
    let whole_json = json(&s);
    let whole_table = table(&s, None);
    for left in [10, 70_000, whole_json.len() / 2] {
        let mut w = Closing {
            taken: Vec::new(),
            left,
        };
        let e = write_json_to(&s, &mut w).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe);
        assert!(whole_json.starts_with(&w.taken), "{left}");
        let mut w = Closing {
            taken: Vec::new(),
            left,
        };
        let e = write_table_to(&s, "t0.toml", None, &mut w).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe);
        assert!(whole_table.starts_with(&w.taken), "{left}");
    }
}

#[test]
fn a_closed_pipe_mid_stream_ends_the_report_quietly() {
    use std::io::Read;
    let dir = crate::common::scratch("output_speed", "pipe");
    let root = tree(&dir, 14, LEAVES[0]);
    for args in [&["--format", "json"][..], &["--full"][..]] {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
            .arg("report")
            .args(args)
            .arg(&root)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let mut head = [0u8; 4096];
        child.stdout.take().unwrap().read_exact(&mut head).unwrap();
        // The read end dropped: the next write fails with a broken pipe.
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        assert_eq!(String::from_utf8_lossy(&out.stderr), "", "{args:?}");
    }
}
