//! MJCF: every `<body>` under `<worldbody>` with its `<inertial>` (`pos`,
//! `mass`, `diaginertia` turned by an orientation or `fullinertia`), which
//! bodies have a joint, and the `<compiler>` settings that change MuJoCo's
//! verdict or how an orientation reads (`angle`, `eulerseq`).
//!
//! Orientations are turned into a matrix as MuJoCo's compiler turns them
//! (`orient`).

use super::mjcf_include::Model;
use super::orient::{Settings, orientation, quat_to_matrix};
use super::{Value, Xml, proper, qname, quoted, turn};
use crate::diag::Diagnostic;
use crate::robot::{Description, Dialect, Inertial, Link, Tensor, Written};
use roxmltree::Node;

/// The orientation attributes of an `<inertial>`, in MuJoCo's order.
const ORIENTATIONS: [&str; 5] = ["quat", "axisangle", "xyaxes", "zaxis", "euler"];

/// Apply one `<compiler>` element: each attribute it gives replaces the
/// earlier value, as MuJoCo reads several `<compiler>`s into one.
pub(super) fn compiler(xml: &Xml, node: Node, s: &mut Settings) -> Result<(), Diagnostic> {
    let owner = "`<compiler>`";
    let boolean = [("false", false), ("true", true)];
    if let Some(v) = xml.attr(node, "balanceinertia") {
        s.compiler.balanceinertia = xml.keyword(&v, owner, &boolean)?;
    }
    if let Some(v) = xml.attr(node, "boundmass") {
        s.compiler.boundmass = xml.number(&v, owner)?;
    }
    if let Some(v) = xml.attr(node, "boundinertia") {
        s.compiler.boundinertia = xml.number(&v, owner)?;
    }
    if let Some(v) = xml.attr(node, "inertiafromgeom") {
        s.compiler.inertiafromgeom = xml.keyword(
            &v,
            owner,
            &[("false", Some(false)), ("true", Some(true)), ("auto", None)],
        )?;
    }
    if let Some(v) = xml.attr(node, "angle") {
        s.degree = xml.keyword(&v, owner, &[("radian", false), ("degree", true)])?;
    }
    if let Some(v) = xml.attr(node, "eulerseq") {
        s.eulerseq = <[u8; 3]>::try_from(v.text.as_bytes())
            .ok()
            .filter(|seq| seq.iter().all(|c| b"xyzXYZ".contains(c)))
            .ok_or_else(|| {
                xml.error(
                    v.range.clone(),
                    format!(
                        "`eulerseq` of `<compiler>`: expected three of x, y, z (turns about the rotating axes) or X, Y, Z (about the fixed axes), found {}",
                        quoted(&v.text)
                    ),
                )
            })?;
    }
    Ok(())
}

pub(super) fn read(xml: &Xml, mujoco: Node) -> Result<Description, Diagnostic> {
    // An included file may hold bodies and compiler settings: reading
    // around it would judge a different model than MuJoCo compiles. The
    // whole robot follows includes (`read_in`, `mjcf_include`).
    if let Some(include) = mujoco.descendants().find(|n| qname(*n) == "include") {
        let (range, file) = match xml.attr(include, "file") {
            Some(v) => (v.range.clone(), format!(" of {}", quoted(&v.text))),
            None => (xml.tag(include), String::new()),
        };
        return Err(xml
            .error(
                range,
                format!("`<include>`{file} is not followed: only one file is read"),
            )
            .help("`report` and `diff` follow includes (the whole robot); to judge or export links, write the model as one file: MuJoCo's `mj_saveLastXML` writes the model it loaded, includes inlined"));
    }
    model(&Model::single(xml.source, mujoco))
}

/// The description of the model `m` (its included files' bodies in their
/// places, each standing at the `<include>` that brings it in).
pub(super) fn model(m: &Model) -> Result<Description, Diagnostic> {
    // MuJoCo reads every `<compiler>` before the bodies, wherever it
    // stands in the file.
    let mut settings = Settings::default();
    for (xml, _, c) in m.sections("compiler") {
        compiler(xml, c, &mut settings)?;
    }
    let mut links = Vec::new();
    let mut count = 0;
    for (_, file, world) in m.sections("worldbody") {
        // Bodies at any depth, also inside `<frame>`s and included files;
        // the world body itself is not one. Depth first in document
        // order, each element with the index of the body it is in (None
        // in the world body itself), with a stack of our own: a body's
        // parent is known in one step, however deep the tree.
        let mut stack: Vec<(usize, Node, Option<usize>)> =
            m.children(file, world).map(|(f, n)| (f, n, None)).collect();
        stack.reverse();
        while let Some((file, node, parent)) = stack.pop() {
            m.in_place(file, node)?;
            let inside = if qname(node) == "body" {
                let l = body(m, file, node, parent, &settings, &mut count)?;
                links.push(l);
                Some(links.len() - 1)
            } else {
                parent
            };
            let from = stack.len();
            stack.extend(m.children(file, node).map(|(f, n)| (f, n, inside)));
            stack[from..].reverse();
        }
    }
    Ok(Description {
        format: Dialect::Mjcf,
        name: m.root.attribute("model").map(str::to_string),
        links,
        compiler: settings.compiler,
        files: Default::default(),
    })
}

/// The link of `node`, a `<body>` of file `file` (the `count`th of the
/// model, counting it), in the body `parent`.
fn body(
    m: &Model,
    file: usize,
    node: Node,
    parent: Option<usize>,
    settings: &Settings,
    count: &mut usize,
) -> Result<Link, Diagnostic> {
    *count += 1;
    let (name, owner) = match node.attribute("name").filter(|n| !n.is_empty()) {
        Some(n) => (n.to_string(), format!("body {}", quoted(n))),
        None => (format!("body {count}"), format!("body {count}")),
    };
    // An `<inertial>` may come from an included file: read in its own.
    let mut inertials = m.named(file, node, "inertial");
    let first = inertials.next();
    let inertial = first
        .map(|(f, i)| {
            inertial(m.xml(f), i, &owner, settings).map(|i| Inertial {
                range: m.range(f, i.range.clone()),
                ..i
            })
        })
        .transpose()?;
    if let Some((f, second)) = inertials.next() {
        let xml = m.xml(f);
        return Err(xml.error(
            xml.tag(second),
            format!("{owner} has a second `<inertial>`: MuJoCo allows one"),
        ));
    }
    // Any joint moves the body (a hinge, a slide, a ball, a free joint):
    // MuJoCo then needs its mass and inertia.
    let moving = m
        .children(file, node)
        .any(|(_, c)| matches!(qname(c), "joint" | "freejoint"));
    Ok(Link {
        name,
        range: m.range(file, node.range()),
        inertial,
        moving,
        parent,
        site: crate::robot::Site {
            file,
            element: node.range(),
            inertial: first.filter(|&(f, _)| f == file).map(|(_, i)| i.range()),
            elsewhere: first.is_some_and(|(f, _)| f != file),
            from: Vec::new(),
        },
    })
}

fn inertial(xml: &Xml, node: Node, owner: &str, s: &Settings) -> Result<Inertial, Diagnostic> {
    let pos = xml.numbers::<3>(&xml.required(node, "pos", owner)?, owner)?;
    let mass = xml.number(&xml.required(node, "mass", owner)?, owner)?;
    let mut forms: Vec<(&str, Value)> = ORIENTATIONS
        .iter()
        .filter_map(|&f| Some((f, xml.attr(node, f)?)))
        .collect();
    forms.sort_by_key(|(_, v)| v.range.start);
    if let [(first, _), (second, v), ..] = forms.as_slice() {
        return Err(xml.error(
            v.range.clone(),
            format!("`<inertial>` of {owner} gives two orientations, `{first}` and `{second}`: MuJoCo allows one"),
        ));
    }
    let full = xml.attr(node, "fullinertia");
    let diagonal = xml.attr(node, "diaginertia");
    let (tensor, written) = match (full, diagonal) {
        (Some(f), None) => {
            if let Some((form, v)) = forms.first() {
                return Err(xml
                    .error(
                        v.range.clone(),
                        format!("`{form}` of {owner} cannot turn a `fullinertia`: MuJoCo refuses an inertial orientation with a full tensor"),
                    )
                    .help(format!("`fullinertia` is in the body frame already: drop `{form}`, or write the principal moments as `diaginertia` turned by `{form}`")));
            }
            let [xx, yy, zz, xy, xz, yz] = xml.numbers::<6>(&f, owner)?;
            let t = Tensor::of_matrix(&[[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]);
            (t, Written::Full)
        }
        (None, Some(d)) => {
            let [xx, yy, zz] = xml.numbers::<3>(&d, owner)?;
            let t = Tensor {
                xx,
                yy,
                zz,
                ..Tensor::default()
            };
            (t, Written::Diagonal)
        }
        (Some(f), Some(d)) => {
            let later = if f.range.start > d.range.start { f } else { d };
            return Err(xml.error(
                later.range,
                format!("`<inertial>` of {owner} gives both `fullinertia` and `diaginertia`: MuJoCo allows one"),
            ));
        }
        (None, None) => {
            return Err(xml.error(
                xml.tag(node),
                format!("`<inertial>` of {owner} is missing the required attribute `diaginertia` or `fullinertia`"),
            ));
        }
    };
    let rotation = match forms.first() {
        Some((form, v)) => {
            let m = quat_to_matrix(orientation(xml, form, v, owner, s)?);
            turn(proper(xml, v, owner, m)?)
        }
        None => None,
    };
    Ok(Inertial {
        mass,
        pos,
        rotation,
        tensor,
        written,
        range: node.range(),
    })
}

#[cfg(test)]
mod tests {
    use super::super::read;
    use super::super::tests::{assert_matrix, source};
    use crate::robot::{Description, Dialect, MujocoCompiler, Tensor, Written};

    /// Rz(90°), by hand: x̂ → ŷ, ŷ → −x̂.
    const RZ: [[f64; 3]; 3] = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
    /// Ry(90°), by hand: ẑ → x̂, x̂ → −ẑ.
    const RY: [[f64; 3]; 3] = [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]];
    /// A half turn about x.
    const RX2: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]];

    fn mujoco(head: &str, bodies: &str) -> String {
        format!("<mujoco model='m'>\n{head}\n<worldbody>\n{bodies}\n</worldbody>\n</mujoco>\n")
    }

    /// One body, `b`, with an inertial of `attrs` (and `pos`, `mass`).
    fn inertial(head: &str, attrs: &str) -> String {
        mujoco(
            head,
            &format!("  <body name='b'>\n    <inertial pos='1 2 3' mass='2' {attrs}/>\n  </body>"),
        )
    }

    fn read_ok(text: &str) -> Description {
        read(&source(text), Dialect::Mjcf).unwrap()
    }

    fn error(text: &str) -> String {
        read(&source(text), Dialect::Mjcf).unwrap_err().to_string()
    }

    /// The inertial rotation of the first body.
    fn rotation(head: &str, attrs: &str) -> Option<[[f64; 3]; 3]> {
        read_ok(&inertial(head, attrs)).links[0]
            .inertial
            .as_ref()
            .unwrap()
            .rotation
    }

    #[test]
    fn a_diagonal_inertial_is_read_as_written() {
        let d = read_ok(&inertial("", "diaginertia='4 5 6'"));
        assert_eq!((d.format, d.name.as_deref()), (Dialect::Mjcf, Some("m")));
        let i = d.links[0].inertial.as_ref().unwrap();
        assert_eq!((i.mass, i.pos, i.rotation), (2.0, [1.0, 2.0, 3.0], None));
        assert_eq!(
            i.tensor,
            Tensor {
                xx: 4.0,
                yy: 5.0,
                zz: 6.0,
                ..Tensor::default()
            }
        );
        assert_eq!(i.written, Written::Diagonal);
    }

    #[test]
    fn a_full_inertia_is_in_the_order_xx_yy_zz_xy_xz_yz() {
        let d = read_ok(&inertial("", "fullinertia='1 2 3 0.1 0.2 0.3'"));
        let i = d.links[0].inertial.as_ref().unwrap();
        assert_eq!(
            i.tensor,
            Tensor {
                xx: 1.0,
                yy: 2.0,
                zz: 3.0,
                xy: 0.1,
                xz: 0.2,
                yz: 0.3
            }
        );
        assert_eq!((i.written, i.rotation), (Written::Full, None));
    }

    #[test]
    fn a_quaternion_is_normalised() {
        let r = rotation("", "diaginertia='1 1 1' quat='1 0 0 1'").unwrap();
        assert_matrix(r, RZ);
    }

    #[test]
    fn an_identity_quaternion_is_no_turn() {
        assert_eq!(rotation("", "diaginertia='1 1 1' quat='1 0 0 0'"), None);
        assert_eq!(rotation("", "diaginertia='1 1 1' quat='2 0 0 0'"), None);
    }

    #[test]
    fn euler_angles_are_degrees_about_rotating_axes_by_default() {
        // xyz on rotating axes: R = Rx(90°)·Ry(90°), by hand.
        let r = rotation("", "diaginertia='1 1 1' euler='90 90 0'").unwrap();
        assert_matrix(r, [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    }

    #[test]
    fn an_uppercase_euler_sequence_turns_about_fixed_axes() {
        // XYZ on fixed axes: R = Ry(90°)·Rx(90°), by hand.
        let r = rotation(
            "<compiler eulerseq='XYZ'/>",
            "diaginertia='1 1 1' euler='90 90 0'",
        )
        .unwrap();
        assert_matrix(r, [[0.0, 1.0, 0.0], [0.0, 0.0, -1.0], [-1.0, 0.0, 0.0]]);
    }

    #[test]
    fn euler_angles_are_radians_under_angle_radian() {
        let r = rotation(
            "<compiler angle='radian'/>",
            "diaginertia='1 1 1' euler='0 0 1.5707963267948966'",
        )
        .unwrap();
        assert_matrix(r, RZ);
    }

    #[test]
    fn zero_euler_angles_are_no_turn() {
        assert_eq!(rotation("", "diaginertia='1 1 1' euler='0 0 0'"), None);
    }

    #[test]
    fn an_axis_and_angle_turns_about_the_normalised_axis_in_degrees() {
        let r = rotation("", "diaginertia='1 1 1' axisangle='0 0 2 90'").unwrap();
        assert_matrix(r, RZ);
    }

    #[test]
    fn an_axis_and_angle_is_radians_under_angle_radian() {
        let r = rotation(
            "<compiler angle='radian'/>",
            "diaginertia='1 1 1' axisangle='1 0 0 3.141592653589793'",
        )
        .unwrap();
        assert_matrix(r, RX2);
    }

    #[test]
    fn xy_axes_are_the_first_two_columns() {
        // x = ẑ, y = ŷ, so z = x × y = −x̂: R = Ry(−90°), by hand.
        let r = rotation("", "diaginertia='1 1 1' xyaxes='0 0 1 0 1 0'").unwrap();
        assert_matrix(r, [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]);
    }

    #[test]
    fn xy_axes_are_made_perpendicular_as_mujoco_does() {
        // y = (1, 1, 0) less its x part is ŷ: no turn at all.
        assert_eq!(
            rotation("", "diaginertia='1 1 1' xyaxes='1 0 0 1 1 0'"),
            None
        );
    }

    #[test]
    fn a_z_axis_is_reached_by_the_smallest_turn() {
        let r = rotation("", "diaginertia='1 1 1' zaxis='1 0 0'").unwrap();
        assert_matrix(r, RY);
    }

    #[test]
    fn a_z_axis_pointing_down_is_a_half_turn_about_x() {
        let r = rotation("", "diaginertia='1 1 1' zaxis='0 0 -1'").unwrap();
        assert_matrix(r, RX2);
    }

    #[test]
    fn unnamed_bodies_are_counted_among_all_bodies() {
        let d = read_ok(&mujoco(
            "",
            "<body name='a'><body/></body><frame><body/></frame><body name=''/>",
        ));
        let names: Vec<&str> = d.links.iter().map(|l| l.name.as_str()).collect();
        assert_eq!(names, ["a", "body 2", "body 3", "body 4"]);
    }

    #[test]
    fn a_bodys_parent_is_the_body_it_is_in_through_frames() {
        let d = read_ok(&mujoco(
            "",
            "<body name='a'><frame><frame><body name='b'><body name='c'/></body></frame></frame><body name='d'/></body><frame><body name='e'/></frame>",
        ));
        let parents: Vec<Option<usize>> = d.links.iter().map(|l| l.parent).collect();
        assert_eq!(parents, [None, Some(0), Some(1), Some(0), None]);
    }

    #[test]
    fn the_world_body_is_not_a_link() {
        let d = read_ok(&mujoco("", "<geom size='1'/>"));
        assert!(d.links.is_empty());
    }

    #[test]
    fn a_body_with_a_joint_or_free_joint_moves() {
        let d = read_ok(&mujoco(
            "",
            "<body name='free'><freejoint/><body name='hinged'><joint/><body name='welded'><geom size='1'/></body></body></body>",
        ));
        let moving: Vec<bool> = d.links.iter().map(|l| l.moving).collect();
        assert_eq!(moving, [true, true, false]);
    }

    #[test]
    fn compiler_settings_are_read_and_a_later_compiler_wins() {
        let d = read_ok(&mujoco(
            "<compiler balanceinertia='true' boundmass='1' inertiafromgeom='true'/>\n<compiler boundmass='2' boundinertia='3' inertiafromgeom='auto'/>",
            "",
        ));
        assert_eq!(
            d.compiler,
            MujocoCompiler {
                balanceinertia: true,
                boundmass: 2.0,
                boundinertia: 3.0,
                inertiafromgeom: None,
            }
        );
    }

    #[test]
    fn a_compiler_after_the_bodies_still_sets_their_angles() {
        let text = "<mujoco><worldbody><body><inertial pos='0 0 0' mass='1' diaginertia='1 1 1' euler='0 0 1.5707963267948966'/></body></worldbody><compiler angle='radian'/></mujoco>";
        let r = read_ok(text).links[0].inertial.as_ref().unwrap().rotation;
        assert_matrix(r.unwrap(), RZ);
    }

    #[test]
    fn the_ranges_cover_the_body_and_the_inertial() {
        let text = inertial("", "diaginertia='1 1 1'");
        let d = read_ok(&text);
        let b = &text[d.links[0].range.clone()];
        assert!(
            b.starts_with("<body name='b'>") && b.ends_with("</body>"),
            "{b}"
        );
        let i = &text[d.links[0].inertial.as_ref().unwrap().range.clone()];
        assert!(i.starts_with("<inertial ") && i.ends_with("/>"), "{i}");
    }

    #[test]
    fn an_orientation_with_a_full_inertia_is_refused_at_the_orientation() {
        let text = inertial("", "fullinertia='1 1 1 0 0 0' quat='1 0 0 0'");
        let col = text.lines().nth(4).unwrap().find("quat='").unwrap() + 7;
        let d = error(&text);
        assert!(
            d.starts_with(&format!("r.xml:5:{col}: error: `quat` of body \"b\" cannot turn a `fullinertia`: MuJoCo refuses an inertial orientation with a full tensor\n")),
            "{d}"
        );
    }

    #[test]
    fn an_include_is_refused_naming_its_file() {
        // `super::read` alone: `read::read` follows includes (issue 34).
        let text = mujoco("<include file='arm.xml'/>", "");
        let src = source(&text);
        let doc = roxmltree::Document::parse(&text).unwrap();
        let xml = super::super::Xml { source: &src };
        let d = super::read(&xml, doc.root_element())
            .unwrap_err()
            .to_string();
        assert!(
            d.starts_with("r.xml:2:16: error: `<include>` of \"arm.xml\" is not followed: only one file is read\n"),
            "{d}"
        );
    }

    #[test]
    fn a_missing_mass_is_refused_at_the_inertial() {
        let text = mujoco(
            "",
            "  <body name='b'>\n    <inertial pos='0 0 0' diaginertia='1 1 1'/>\n  </body>",
        );
        let d = error(&text);
        assert!(
            d.starts_with("r.xml:5:5: error: `<inertial>` of body \"b\" is missing the required attribute `mass`\n"),
            "{d}"
        );
    }

    #[test]
    fn an_inertial_needs_one_inertia_form() {
        let d = error(&inertial("", ""));
        assert!(
            d.starts_with("r.xml:5:5: error: `<inertial>` of body \"b\" is missing the required attribute `diaginertia` or `fullinertia`\n"),
            "{d}"
        );
        let d = error(&inertial(
            "",
            "diaginertia='1 1 1' fullinertia='1 1 1 0 0 0'",
        ));
        assert!(
            d.contains("error: `<inertial>` of body \"b\" gives both `fullinertia` and `diaginertia`: MuJoCo allows one\n"),
            "{d}"
        );
    }

    #[test]
    fn two_orientations_are_refused_at_the_second() {
        let text = inertial("", "diaginertia='1 1 1' euler='0 0 0' quat='1 0 0 0'");
        let col = text.lines().nth(4).unwrap().find("quat='").unwrap() + 7;
        let d = error(&text);
        assert!(
            d.starts_with(&format!("r.xml:5:{col}: error: `<inertial>` of body \"b\" gives two orientations, `euler` and `quat`: MuJoCo allows one\n")),
            "{d}"
        );
    }

    #[test]
    fn a_zero_quaternion_is_refused() {
        let d = error(&inertial("", "diaginertia='1 1 1' quat='0 0 0 0'"));
        assert!(
            d.contains("error: `quat` of body \"b\": a zero quaternion is no orientation\n"),
            "{d}"
        );
    }

    #[test]
    fn a_quaternion_too_small_or_too_large_to_normalise_is_refused() {
        // MuJoCo leaves a quaternion shorter than √mjEPS as it is, and
        // divides one whose square overflows by infinity: neither is a
        // rotation, and either would scale the tensor without a word.
        for q in ["1e-8 0 0 0", "1e200 0 0 0", "0 1e160 1e160 0"] {
            let d = error(&inertial("", &format!("diaginertia='1 1 1' quat='{q}'")));
            assert!(
                d.contains("error: `quat` of body \"b\" gives no rotation: its length is too small or too large to normalise in f64\n"),
                "{q}: {d}"
            );
        }
        let d = error(&inertial(
            "",
            "diaginertia='1 1 1' axisangle='1e200 0 0 30'",
        ));
        assert!(
            d.contains("`axisangle` of body \"b\" gives no rotation"),
            "{d}"
        );
    }

    #[test]
    fn a_zero_axis_is_refused() {
        let d = error(&inertial("", "diaginertia='1 1 1' zaxis='0 0 0'"));
        assert!(
            d.contains(
                "error: `zaxis` of body \"b\": the z axis is too short to give a direction\n"
            ),
            "{d}"
        );
    }

    #[test]
    fn a_word_in_a_position_is_refused_with_the_unnamed_bodys_number() {
        let text = mujoco(
            "",
            "<body><inertial pos='0 x 0' mass='1' diaginertia='1 1 1'/></body>",
        );
        let d = error(&text);
        assert!(
            d.starts_with("r.xml:4:24: error: `pos` of body 1: expected a number, found \"x\"\n"),
            "{d}"
        );
    }

    #[test]
    fn numbers_are_separated_by_whitespace_not_commas() {
        // MuJoCo splits on whitespace only ("problem reading attribute").
        let d = error(&inertial("", "diaginertia='1,1,1'"));
        assert!(
            d.contains("error: `diaginertia` of body \"b\": expected a number, found \"1,1,1\"\n"),
            "{d}"
        );
    }

    #[test]
    fn a_second_inertial_is_refused() {
        let text = mujoco(
            "",
            "<body name='b'><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/></body>",
        );
        assert!(
            error(&text)
                .contains("error: body \"b\" has a second `<inertial>`: MuJoCo allows one\n")
        );
    }

    #[test]
    fn compiler_keywords_are_checked() {
        let d = error(&mujoco("<compiler balanceinertia='yes'/>", ""));
        assert!(
            d.starts_with("r.xml:2:27: error: `balanceinertia` of `<compiler>`: expected `false` or `true`, found \"yes\"\n"),
            "{d}"
        );
        let d = error(&mujoco("<compiler eulerseq='xyw'/>", ""));
        assert!(
            d.contains("error: `eulerseq` of `<compiler>`: expected three of x, y, z"),
            "{d}"
        );
        let d = error(&mujoco("<compiler angle='grad'/>", ""));
        assert!(
            d.contains("`angle` of `<compiler>`: expected `radian` or `degree`, found \"grad\""),
            "{d}"
        );
    }
}
