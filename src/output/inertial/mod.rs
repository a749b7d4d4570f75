//! Writing an `<inertial>` element in each format (here), replacing a
//! link's in a file with every other byte kept (`update`, failing with an
//! `UpdateError`), and the diff that `--dry-run` shows instead of writing
//! (`unified_diff`).
//!
//! Numbers are written by `output::format::shortest`: the shortest decimal
//! that reads back as the same f64, so that a file written and read again
//! holds exactly the values computed, with no digit more than that needs.

mod error;
mod update;

pub use error::UpdateError;
pub use update::{update, update_at};

use crate::output::format::push_shortest;
use crate::robot::{Dialect, Tensor};

/// What `export` writes: a body's inertial in the link frame, SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Export {
    /// kg.
    pub mass: f64,
    /// The centre of mass in the link frame, m.
    pub pos: [f64; 3],
    /// The tensor about the centre of mass in the link frame (tensor
    /// convention), kg·m².
    pub tensor: Tensor,
    /// MJCF under `--principal`: the principal moments (ascending) and the
    /// rotation whose columns are the principal axes in the link frame
    /// (right-handed), written as `diaginertia` and `quat`.
    pub principal: Option<([f64; 3], [[f64; 3]; 3])>,
}

/// The `<inertial>` element of `e` in `format`, its lines after the first
/// indented by `indent` (the element's own indentation) plus one level of
/// two spaces, the closing tag at `indent`; the first line is not indented
/// (the caller has put it after its own indentation), and there is no
/// trailing newline.
///
/// URDF and SDFormat write the full tensor in the link frame with a zero
/// rotation (`principal` is for MJCF alone: a turned URDF inertial frame is
/// where importers have dropped the rotation, mujoco#3559). MJCF writes
/// `fullinertia` in MuJoCo's order (xx yy zz xy xz yz), or under
/// `principal` the `diaginertia` and the `quat` of the principal axes.
pub fn inertial_element(format: Dialect, e: &Export, indent: &str) -> String {
    let t = &e.tensor;
    let mut out = String::new();
    match format {
        Dialect::Urdf => {
            out.push_str("<inertial>\n");
            line(&mut out, indent, 1, "<origin xyz=\"");
            numbers(&mut out, &e.pos);
            out.push_str("\" rpy=\"0 0 0\"/>\n");
            line(&mut out, indent, 1, "<mass value=\"");
            numbers(&mut out, &[e.mass]);
            out.push_str("\"/>\n");
            line(&mut out, indent, 1, "<inertia");
            for (name, v) in t.named() {
                out.push(' ');
                out.push_str(name);
                out.push_str("=\"");
                push_shortest(&mut out, v);
                out.push('"');
            }
            out.push_str("/>\n");
            line(&mut out, indent, 0, "</inertial>");
        }
        Dialect::Sdf => {
            out.push_str("<inertial>\n");
            line(&mut out, indent, 1, "<pose>");
            numbers(&mut out, &e.pos);
            out.push_str(" 0 0 0</pose>\n");
            line(&mut out, indent, 1, "<mass>");
            push_shortest(&mut out, e.mass);
            out.push_str("</mass>\n");
            line(&mut out, indent, 1, "<inertia>\n");
            for (name, v) in t.named() {
                line(&mut out, indent, 2, "<");
                out.push_str(name);
                out.push('>');
                push_shortest(&mut out, v);
                out.push_str("</");
                out.push_str(name);
                out.push_str(">\n");
            }
            line(&mut out, indent, 1, "</inertia>\n");
            line(&mut out, indent, 0, "</inertial>");
        }
        Dialect::Mjcf => {
            out.push_str("<inertial pos=\"");
            numbers(&mut out, &e.pos);
            out.push_str("\" mass=\"");
            push_shortest(&mut out, e.mass);
            match &e.principal {
                None => {
                    out.push_str("\" fullinertia=\"");
                    numbers(&mut out, &[t.xx, t.yy, t.zz, t.xy, t.xz, t.yz]);
                }
                Some((moments, axes)) => {
                    out.push_str("\" diaginertia=\"");
                    numbers(&mut out, moments);
                    out.push_str("\" quat=\"");
                    numbers(&mut out, &quaternion(axes));
                }
            }
            out.push_str("\"/>");
        }
    }
    out
}

/// Start a line at `indent` plus `levels` steps of two spaces, then `text`.
fn line(out: &mut String, indent: &str, levels: usize, text: &str) {
    out.push_str(indent);
    for _ in 0..levels {
        out.push_str("  ");
    }
    out.push_str(text);
}

/// Numbers separated by single spaces, as every format's lists are.
fn numbers(out: &mut String, xs: &[f64]) {
    for (i, &x) in xs.iter().enumerate() {
        if i > 0 {
            out.push(' ');
        }
        push_shortest(out, x);
    }
}

/// The unit quaternion [w, x, y, z] of the rotation `r` (rows; its columns
/// are the turned frame's axes), as MuJoCo's `quat` means it: w ≥ 0, and
/// for w = 0 the first nonzero of x, y, z positive, so that one rotation
/// is always written the same way.
///
/// NOTE: Shepperd's method (1978). Each of 4w², 4x², 4y², 4z² is a sum of
/// diagonal entries (1 + trace, 1 + 2·r_ii − trace); the largest is at
/// least 1, so taking the square root of that one and the others from
/// off-diagonal sums divided by it never divides by a small number. The
/// textbook w = ½√(1 + trace) alone loses every digit near a half turn.
/// The largest of those four is found by comparing trace and diagonal
/// entries, which orders them the same way.
fn quaternion(r: &[[f64; 3]; 3]) -> [f64; 4] {
    let [[m00, m01, m02], [m10, m11, m12], [m20, m21, m22]] = *r;
    let trace = m00 + m11 + m22;
    let q = if trace >= m00 && trace >= m11 && trace >= m22 {
        let w = 0.5 * (1.0 + trace).sqrt();
        let f = 0.25 / w;
        [w, (m21 - m12) * f, (m02 - m20) * f, (m10 - m01) * f]
    } else if m00 >= m11 && m00 >= m22 {
        let x = 0.5 * (1.0 + m00 - m11 - m22).sqrt();
        let f = 0.25 / x;
        [(m21 - m12) * f, x, (m01 + m10) * f, (m02 + m20) * f]
    } else if m11 >= m22 {
        let y = 0.5 * (1.0 - m00 + m11 - m22).sqrt();
        let f = 0.25 / y;
        [(m02 - m20) * f, (m01 + m10) * f, y, (m12 + m21) * f]
    } else {
        let z = 0.5 * (1.0 - m00 - m11 + m22).sqrt();
        let f = 0.25 / z;
        [(m10 - m01) * f, (m02 + m20) * f, (m12 + m21) * f, z]
    };
    // Unit length even when the axes are a rounding off orthonormal:
    // MuJoCo normalises a quat anyway, and a reader comparing with ours
    // should find the same one.
    let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
    let q = q.map(|v| v / n);
    // q and −q are the same rotation: pick the one with w ≥ 0, and at
    // w = 0 (exactly: any other w has a sign) the first nonzero of x, y, z
    // positive.
    let first = q.iter().copied().find(|&v| v != 0.0).unwrap_or(1.0);
    if first < 0.0 { q.map(|v| -v) } else { q }
}

/// `--dry-run`'s view of an update: a unified diff of `old` to `new` with
/// three lines of context, headed `--- a/PATH` and `+++ b/PATH` as git
/// writes it (so `git apply` and `patch -p1` take it); empty when the two
/// are equal.
///
/// The diff is shown as text from input always is (`diag::push_visible`):
/// control characters as pictures, C1 controls, bidirectional overrides,
/// separators, U+FFFE and U+FFFF as �, so a robot file's line can neither
/// act on the terminal nor start a line of its own; a CR before a line's
/// newline (a CRLF file) is kept, so the diff still applies there. A
/// context line that would begin with `::` (a CI runner's command) has its
/// first colon shown as �.
pub fn unified_diff(old: &str, new: &str, path: &str) -> String {
    if old == new {
        return String::new();
    }
    // The path escaped before it is put in the header: its newline would
    // be a line break there.
    let path = crate::diag::visible(path);
    let diff = crate::diff_lines::unified(old, new, 3, &format!("a/{path}"), &format!("b/{path}"));
    let mut out = String::with_capacity(diff.len());
    for line in diff.split_inclusive('\n') {
        let (text, end) = match line.strip_suffix("\r\n") {
            Some(text) => (text, "\r\n"),
            None => line
                .strip_suffix('\n')
                .map_or((line, ""), |text| (text, "\n")),
        };
        let start = out.len();
        crate::diag::push_visible(&mut out, text);
        // NOTE: a context line is ` ` and the file's own line, and a CI
        // runner reads a line that begins with `::` after blanks as a
        // command: its first `:` is shown as �. (The diff does not apply
        // there; no robot description needs such a line.)
        let shown = &out[start..];
        if let Some(rest) = shown.strip_prefix(' ')
            && rest.trim_start().starts_with("::")
        {
            let colon = start + 1 + (rest.len() - rest.trim_start().len());
            out.replace_range(colon..colon + 1, "\u{fffd}");
        }
        out.push_str(end);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Export {
        Export {
            mass: 2.5,
            pos: [0.1, -0.2, 0.0],
            tensor: Tensor {
                xx: 0.01,
                yy: 0.02,
                zz: 0.03,
                xy: -0.001,
                xz: 0.0,
                yz: 1.5e-7,
            },
            principal: None,
        }
    }

    #[test]
    fn a_urdf_inertial_is_written_with_attributes() {
        assert_eq!(
            inertial_element(Dialect::Urdf, &example(), "    "),
            "<inertial>
      <origin xyz=\"0.1 -0.2 0\" rpy=\"0 0 0\"/>
      <mass value=\"2.5\"/>
      <inertia ixx=\"0.01\" ixy=\"-0.001\" ixz=\"0\" iyy=\"0.02\" iyz=\"1.5e-7\" izz=\"0.03\"/>
    </inertial>"
        );
    }

    #[test]
    fn an_sdformat_inertial_is_written_with_elements() {
        assert_eq!(
            inertial_element(Dialect::Sdf, &example(), "\t"),
            "<inertial>
\t  <pose>0.1 -0.2 0 0 0 0</pose>
\t  <mass>2.5</mass>
\t  <inertia>
\t    <ixx>0.01</ixx>
\t    <ixy>-0.001</ixy>
\t    <ixz>0</ixz>
\t    <iyy>0.02</iyy>
\t    <iyz>1.5e-7</iyz>
\t    <izz>0.03</izz>
\t  </inertia>
\t</inertial>"
        );
    }

    #[test]
    fn an_mjcf_inertial_is_one_line_with_fullinertia_in_mujocos_order() {
        assert_eq!(
            inertial_element(Dialect::Mjcf, &example(), "      "),
            "<inertial pos=\"0.1 -0.2 0\" mass=\"2.5\" fullinertia=\"0.01 0.02 0.03 -0.001 0 1.5e-7\"/>"
        );
    }

    #[test]
    fn an_mjcf_inertial_under_principal_has_diaginertia_and_the_axes_quat() {
        let e = Export {
            // A quarter turn about z: principal x is the link's y.
            principal: Some((
                [0.01, 0.02, 0.03],
                [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
            )),
            ..example()
        };
        // w = ½√2 is the f64 nearest 1/√2; z = (r10 − r01)/4w = 0.5/w is
        // within an ulp of it, below.
        assert_eq!(
            inertial_element(Dialect::Mjcf, &e, ""),
            "<inertial pos=\"0.1 -0.2 0\" mass=\"2.5\" diaginertia=\"0.01 0.02 0.03\" \
             quat=\"0.7071067811865476 0 0 0.7071067811865475\"/>"
        );
    }

    #[test]
    fn every_format_writes_xml_that_parses() {
        let e = example();
        let principal = Export {
            principal: Some((
                [1.0, 2.0, 3.0],
                [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            )),
            ..e
        };
        for (format, e) in [
            (Dialect::Urdf, e),
            (Dialect::Sdf, e),
            (Dialect::Mjcf, e),
            (Dialect::Mjcf, principal),
        ] {
            let text = inertial_element(format, &e, "  ");
            let doc = roxmltree::Document::parse(&text).unwrap();
            assert_eq!(doc.root_element().tag_name().name(), "inertial");
        }
    }

    /// R of a quaternion by the formula MuJoCo's `mju_quat2Mat` uses (the
    /// parts' own, `rotation::quaternion`, which divides by |q|², 1 to a
    /// rounding here).
    fn mujoco_matrix(q: [f64; 4]) -> [[f64; 3]; 3] {
        crate::rotation::quaternion::<f64>(q)
    }

    fn assert_quat(q: [f64; 4], expected: [f64; 4]) {
        for (a, b) in q.iter().zip(expected) {
            assert!((a - b).abs() <= 1e-15, "{q:?} is not {expected:?}");
        }
    }

    #[test]
    fn the_quaternion_of_the_identity_is_one() {
        let i = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        assert_eq!(quaternion(&i), [1.0, 0.0, 0.0, 0.0]);
    }

    #[test]
    fn the_quaternions_of_quarter_turns_are_cos_and_sin_of_an_eighth() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        // Columns are the turned axes: about x, y turns into z.
        let about_x = [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
        let about_y = [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]];
        let about_z = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
        assert_quat(quaternion(&about_x), [h, h, 0.0, 0.0]);
        assert_quat(quaternion(&about_y), [h, 0.0, h, 0.0]);
        assert_quat(quaternion(&about_z), [h, 0.0, 0.0, h]);
    }

    #[test]
    fn a_third_of_a_turn_about_the_diagonal_is_the_cyclic_permutation() {
        // x → y → z → x: cos 60° = ½ and sin 60° (1, 1, 1)/√3 = (½, ½, ½).
        let r = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        assert_eq!(quaternion(&r), [0.5, 0.5, 0.5, 0.5]);
    }

    #[test]
    fn a_half_turn_has_w_zero_and_its_first_nonzero_component_positive() {
        // About x, and about −y written as a half turn about y.
        assert_eq!(
            quaternion(&[[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]),
            [0.0, 1.0, 0.0, 0.0]
        );
        assert_eq!(
            quaternion(&[[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]),
            [0.0, 0.0, 1.0, 0.0]
        );
        // About (1, −1, 0)/√2: the first nonzero (x) positive.
        let q = quaternion(&[[0.0, -1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, -1.0]]);
        let h = std::f64::consts::FRAC_1_SQRT_2;
        assert_quat(q, [0.0, h, -h, 0.0]);
    }

    #[test]
    fn a_random_rotations_quaternion_gives_back_its_matrix() {
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut uniform = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for _ in 0..10_000 {
            let q = [uniform(), uniform(), uniform(), uniform()];
            let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
            if n < 0.1 {
                continue;
            }
            let r = mujoco_matrix(q.map(|v| v / n));
            let p = quaternion(&r);
            assert!(p[0] >= 0.0, "{p:?}");
            let back = mujoco_matrix(p);
            for (row, want) in back.iter().zip(&r) {
                for (a, b) in row.iter().zip(want) {
                    assert!((a - b).abs() <= 1e-15, "{back:?} is not {r:?}");
                }
            }
        }
    }

    #[test]
    fn a_diff_shows_hidden_characters_as_everything_else_does() {
        let hostile = "<!-- \u{202e}\u{85}\u{2028}\u{fffe}\u{ffff}\u{1b}[2J\r::error::x -->";
        let old = format!("<robot>\n{hostile}\n<link/>\n</robot>\n");
        let new = old.replace("<link/>", "<link>\n</link>");
        let diff = unified_diff(&old, &new, "a\u{202e}\r\n::error::x.urdf");
        assert!(
            !diff
                .chars()
                .any(|c| c != '\n' && c != '\t' && crate::diag::is_hidden(c)),
            "{diff:?}"
        );
        // similar ends a line at a lone CR too: the rest of the line is
        // the next line of context, after its space, on the same line.
        assert!(
            diff.contains(
                " <!-- \u{fffd}\u{fffd}\u{fffd}\u{fffd}\u{fffd}\u{241b}[2J\u{240d} ::error::x -->\n"
            ),
            "{diff}"
        );
        assert!(
            diff.starts_with("--- a/a\u{fffd}\u{240d}\u{240a}::error::x.urdf\n"),
            "{diff}"
        );
    }

    #[test]
    fn a_context_line_never_begins_with_a_ci_command() {
        let old = "<robot>\n<!--\n \u{a0}::error file=x::forged\n-->\n<link/>\n</robot>\n";
        let new = old.replace("<link/>", "<link></link>");
        let diff = unified_diff(old, &new, "x.urdf");
        assert!(
            diff.contains("\n  \u{a0}\u{fffd}:error file=x::forged\n"),
            "{diff}"
        );
        assert!(
            diff.lines().all(|l| !l.trim_start().starts_with("::")),
            "{diff}"
        );
    }

    #[test]
    fn a_crlf_file_keeps_its_line_ends_in_the_diff() {
        let old = "<robot>\r\n<!-- \u{202e} -->\r\n<link/>\r\n</robot>\r\n";
        let new = old.replace("<link/>", "<link></link>");
        let diff = unified_diff(old, &new, "x.urdf");
        assert!(diff.contains("-<link/>\r\n+<link></link>\r\n"), "{diff:?}");
        assert!(diff.contains(" <!-- \u{fffd} -->\r\n"), "{diff:?}");
    }

    #[test]
    fn equal_texts_have_an_empty_diff() {
        assert_eq!(unified_diff("a\nb\n", "a\nb\n", "x.urdf"), "");
    }

    /// `diff` applied to `old` by the unified format's rules, as `patch`
    /// does, each context and removed line checked against `old`.
    fn apply(old: &str, diff: &str) -> String {
        let old: Vec<&str> = old.split_inclusive('\n').collect();
        let mut lines = diff.split_inclusive('\n');
        assert!(lines.next().unwrap().starts_with("--- a/"));
        assert!(lines.next().unwrap().starts_with("+++ b/"));
        let (mut out, mut next) = (String::new(), 0);
        for line in lines {
            if let Some(header) = line.strip_prefix("@@ -") {
                let start: usize = header.split([',', ' ']).next().unwrap().parse().unwrap();
                old[next..start - 1].iter().for_each(|l| out.push_str(l));
                next = start - 1;
            } else if let Some(l) = line.strip_prefix(' ') {
                assert_eq!(old[next], l);
                out.push_str(l);
                next += 1;
            } else if let Some(l) = line.strip_prefix('-') {
                assert_eq!(old[next], l);
                next += 1;
            } else if let Some(l) = line.strip_prefix('+') {
                out.push_str(l);
            } else {
                panic!("not a line of a unified diff: {line:?}");
            }
        }
        old[next..].iter().for_each(|l| out.push_str(l));
        out
    }

    #[test]
    fn the_diff_of_two_updates_far_apart_applies_as_two_hunks() {
        let links: String = (0..4)
            .map(|i| format!("  <link name=\"l{i}\">\n    <visual/>\n    <collision/>\n    <sensor/>\n  </link>\n"))
            .collect();
        for nl in ["\n", "\r\n"] {
            let old = format!("<?xml version=\"1.0\"?>\n<robot name=\"r\">\n{links}</robot>\n")
                .replace('\n', nl);
            let new = update(&old, Dialect::Urdf, "l0", &example()).unwrap();
            let new = update(&new, Dialect::Urdf, "l3", &example()).unwrap();
            let diff = unified_diff(&old, &new, "r.urdf");
            assert_eq!(diff.matches("\n@@ ").count(), 2, "{diff}");
            assert_eq!(apply(&old, &diff), new);
        }
    }

    #[test]
    fn the_diff_of_one_changed_line_has_its_hunk_and_context() {
        let old = "1\n2\n3\n4\n5\n6\n7\n8\n9\n";
        let new = "1\n2\n3\n4\nfive\n6\n7\n8\n9\n";
        assert_eq!(
            unified_diff(old, new, "robots/arm.urdf"),
            "--- a/robots/arm.urdf\n+++ b/robots/arm.urdf\n@@ -2,7 +2,7 @@\n 2\n 3\n 4\n-5\n+five\n 6\n 7\n 8\n"
        );
    }
}
