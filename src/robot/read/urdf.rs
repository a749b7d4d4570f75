//! URDF: each `<link>` of `<robot>` with its `<inertial>` (`<origin xyz
//! rpy>`, `<mass value>`, `<inertia ixx … izz>`, as urdfdom requires them),
//! which links a joint that is not `fixed` moves, and MuJoCo's
//! `<mujoco><compiler>` extension, which MuJoCo honours when it loads a URDF.

use super::{Value, Xml, child, children, mjcf, quoted, rpy, turn};
use crate::diag::Diagnostic;
use crate::robot::{Description, Dialect, Inertial, Link, Tensor, Written};
use roxmltree::Node;
use std::collections::{HashMap, HashSet};

pub(super) fn read(xml: &Xml, robot: Node) -> Result<Description, Diagnostic> {
    // A link moves when it is the child of a joint that lets it (revolute,
    // continuous, prismatic, floating, planar): every type but `fixed`. The
    // root link is the child of no joint, fixed to the world.
    let moving: HashSet<&str> = children(robot, "joint")
        .filter(|j| j.attribute("type") != Some("fixed"))
        .filter_map(|j| child(j, "child")?.attribute("link"))
        .collect();
    let mut links = Vec::new();
    for link in children(robot, "link") {
        xml.required(link, "name", "`<robot>`")?;
        let name = link.attribute("name").unwrap_or_default();
        let owner = format!("link {}", quoted(name));
        let inertial = child(link, "inertial")
            .map(|i| inertial(xml, i, &owner))
            .transpose()?;
        links.push(Link {
            name: name.to_string(),
            range: link.range(),
            site: crate::robot::Site::main(
                link.range(),
                inertial.as_ref().map(|i| i.range.clone()),
            ),
            inertial,
            moving: moving.contains(name),
            parent: None,
        });
    }
    // Each link's parent: the parent of the first joint naming it as the
    // child (the first link of that name). Names looked up in a map: a
    // search of the links per joint would make a large robot quadratic.
    let mut first: HashMap<&str, usize> = HashMap::with_capacity(links.len());
    for (i, l) in links.iter().enumerate() {
        first.entry(l.name.as_str()).or_insert(i);
    }
    let mut parents = vec![None; links.len()];
    for j in children(robot, "joint") {
        let end = |tag| child(j, tag).and_then(|e| e.attribute("link"));
        let (Some(parent), Some(kid)) = (end("parent"), end("child")) else {
            continue;
        };
        let p = first.get(parent).copied();
        if let Some(&k) = first.get(kid)
            && parents[k].is_none()
            && p != Some(k)
        {
            parents[k] = p;
        }
    }
    for (l, p) in links.iter_mut().zip(parents) {
        l.parent = p;
    }
    let mut settings = super::orient::Settings::default();
    for mujoco in children(robot, "mujoco") {
        for compiler in children(mujoco, "compiler") {
            mjcf::compiler(xml, compiler, &mut settings)?;
        }
    }
    Ok(Description {
        format: Dialect::Urdf,
        name: robot.attribute("name").map(str::to_string),
        links,
        compiler: settings.compiler,
        files: Default::default(),
    })
}

fn inertial(xml: &Xml, node: Node, owner: &str) -> Result<Inertial, Diagnostic> {
    let origin = child(node, "origin");
    let attr = |name: &str| origin.and_then(|o| xml.attr(o, name));
    let pos = match attr("xyz") {
        Some(v) => xml.numbers::<3>(&v, owner)?,
        None => [0.0; 3],
    };
    // Radians, always: URDF has no degrees.
    let rotation = match attr("rpy") {
        Some(v) => {
            let [r, p, y] = xml.numbers::<3>(&v, owner)?;
            turn(rpy(r.sin_cos(), p.sin_cos(), y.sin_cos()))
        }
        None => None,
    };
    let needs = |name: &str| {
        xml.error(
            xml.tag(node),
            format!("`<inertial>` of {owner} is missing the required element `<{name}>`"),
        )
    };
    let mass = child(node, "mass").ok_or_else(|| needs("mass"))?;
    let mass = xml.number(&xml.required(mass, "value", owner)?, owner)?;
    let inertia = child(node, "inertia").ok_or_else(|| needs("inertia"))?;
    let entry = |name: &str| -> Result<f64, Diagnostic> {
        let v: Value = xml.required(inertia, name, owner)?;
        xml.number(&v, owner)
    };
    let tensor = Tensor {
        xx: entry("ixx")?,
        xy: entry("ixy")?,
        xz: entry("ixz")?,
        yy: entry("iyy")?,
        yz: entry("iyz")?,
        zz: entry("izz")?,
    };
    Ok(Inertial {
        mass,
        pos,
        rotation,
        tensor,
        written: Written::Attributes,
        range: node.range(),
    })
}

#[cfg(test)]
mod tests {
    use super::super::read;
    use super::super::tests::{assert_matrix, source};
    use crate::robot::{Dialect, MujocoCompiler, Tensor, Written};

    const INERTIA: &str = "<inertia ixx='1' ixy='0.1' ixz='0.2' iyy='2' iyz='0.3' izz='3'/>";

    fn robot(body: &str) -> String {
        format!("<?xml version='1.0'?>\n<robot name='r'>\n{body}\n</robot>\n")
    }

    fn link(inertial: &str) -> String {
        robot(&format!("  <link name='arm'>\n    {inertial}\n  </link>"))
    }

    fn error(text: &str) -> String {
        read(&source(text), Dialect::Urdf).unwrap_err().to_string()
    }

    #[test]
    fn an_inertial_is_read_as_written() {
        let text = link(&format!(
            "<inertial><origin xyz='1 2 3'/><mass value='4.5'/>{INERTIA}</inertial>"
        ));
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        assert_eq!(d.format, Dialect::Urdf);
        assert_eq!(d.name.as_deref(), Some("r"));
        assert_eq!(d.links.len(), 1);
        let i = d.links[0].inertial.as_ref().unwrap();
        assert_eq!(i.mass, 4.5);
        assert_eq!(i.pos, [1.0, 2.0, 3.0]);
        assert_eq!(i.rotation, None);
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
        assert_eq!(i.written, Written::Attributes);
    }

    #[test]
    fn the_origin_is_optional_and_defaults_to_zero() {
        let text = link(&format!("<inertial><mass value='1'/>{INERTIA}</inertial>"));
        let i = read(&source(&text), Dialect::Urdf).unwrap().links[0]
            .inertial
            .clone()
            .unwrap();
        assert_eq!((i.pos, i.rotation), ([0.0; 3], None));
        let text = link(&format!(
            "<inertial><origin/><mass value='1'/>{INERTIA}</inertial>"
        ));
        let i = read(&source(&text), Dialect::Urdf).unwrap().links[0]
            .inertial
            .clone()
            .unwrap();
        assert_eq!((i.pos, i.rotation), ([0.0; 3], None));
    }

    #[test]
    fn zero_angles_are_no_turn() {
        let text = link(&format!(
            "<inertial><origin rpy='0 0 0'/><mass value='1'/>{INERTIA}</inertial>"
        ));
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        assert_eq!(d.links[0].inertial.as_ref().unwrap().rotation, None);
    }

    #[test]
    fn a_quarter_yaw_turns_x_onto_y() {
        let text = link(&format!(
            "<inertial><origin rpy='0 0 1.5707963267948966'/><mass value='1'/>{INERTIA}</inertial>"
        ));
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        let r = d.links[0].inertial.as_ref().unwrap().rotation.unwrap();
        assert_matrix(r, [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    }

    #[test]
    fn roll_is_applied_before_yaw() {
        // rpy = (π/2, 0, π/2): R = Rz·Rx, by hand: x̂ → ŷ, ŷ → ẑ, ẑ → x̂.
        let text = link(&format!(
            "<inertial><origin rpy='1.5707963267948966 0 1.5707963267948966'/><mass value='1'/>{INERTIA}</inertial>"
        ));
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        let r = d.links[0].inertial.as_ref().unwrap().rotation.unwrap();
        assert_matrix(r, [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    }

    #[test]
    fn a_link_without_an_inertial_has_none() {
        let text = robot("<link name='base'/>");
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        assert_eq!(d.links[0].name, "base");
        assert_eq!(d.links[0].inertial, None);
    }

    #[test]
    fn negative_values_are_read_as_given() {
        let text = link(
            "<inertial><mass value='-1'/><inertia ixx='-1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial>",
        );
        let i = read(&source(&text), Dialect::Urdf).unwrap().links[0]
            .inertial
            .clone()
            .unwrap();
        assert_eq!((i.mass, i.tensor.xx), (-1.0, -1.0));
    }

    #[test]
    fn duplicate_link_names_are_both_kept() {
        let text = robot("<link name='a'/><link name='a'/>");
        assert_eq!(read(&source(&text), Dialect::Urdf).unwrap().links.len(), 2);
    }

    #[test]
    fn a_child_of_a_joint_that_is_not_fixed_moves() {
        let text = robot(
            "<link name='base'/><link name='arm'/><link name='tool'/><link name='wheel'/>\
             <joint name='j1' type='revolute'><parent link='base'/><child link='arm'/></joint>\
             <joint name='j2' type='fixed'><parent link='arm'/><child link='tool'/></joint>\
             <joint name='j3' type='continuous'><parent link='base'/><child link='wheel'/></joint>",
        );
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        let moving: Vec<(&str, bool)> = d
            .links
            .iter()
            .map(|l| (l.name.as_str(), l.moving))
            .collect();
        assert_eq!(
            moving,
            [
                ("base", false),
                ("arm", true),
                ("tool", false),
                ("wheel", true)
            ]
        );
    }

    #[test]
    fn a_links_parent_is_that_of_the_first_joint_naming_it_as_the_first_link_of_that_name() {
        let text = robot(
            "<link name='base'/><link name='arm'/><link name='arm'/><link name='tool'/>\
             <joint name='j0' type='fixed'><parent link='nowhere'/><child link='tool'/></joint>\
             <joint name='j1' type='revolute'><parent link='base'/><child link='arm'/></joint>\
             <joint name='j2' type='fixed'><parent link='arm'/><child link='tool'/></joint>\
             <joint name='j3' type='fixed'><parent link='tool'/><child link='arm'/></joint>\
             <joint name='j4' type='fixed'><parent link='base'/><child link='base'/></joint>",
        );
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        let parents: Vec<Option<usize>> = d.links.iter().map(|l| l.parent).collect();
        assert_eq!(parents, [None, Some(0), None, Some(1)]);
    }

    #[test]
    fn the_mujoco_compiler_extension_is_read() {
        let text = robot(
            "<mujoco><compiler balanceinertia='true' boundmass='0.01' boundinertia='1e-6' inertiafromgeom='false'/></mujoco>",
        );
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        assert_eq!(
            d.compiler,
            MujocoCompiler {
                balanceinertia: true,
                boundmass: 0.01,
                boundinertia: 1e-6,
                inertiafromgeom: Some(false),
            }
        );
    }

    #[test]
    fn without_the_extension_the_compiler_is_mujocos_default() {
        let d = read(&source(&robot("")), Dialect::Urdf).unwrap();
        assert_eq!(d.compiler, MujocoCompiler::default());
    }

    #[test]
    fn the_ranges_cover_the_link_and_the_inertial() {
        let text = link(&format!("<inertial><mass value='1'/>{INERTIA}</inertial>"));
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        let l = &d.links[0];
        assert!(text[l.range.clone()].starts_with("<link name='arm'>"));
        assert!(text[l.range.clone()].ends_with("</link>"));
        let i = &text[l.inertial.as_ref().unwrap().range.clone()];
        assert!(
            i.starts_with("<inertial>") && i.ends_with("</inertial>"),
            "{i}"
        );
    }

    #[test]
    fn a_word_for_a_number_is_refused_at_its_attribute() {
        let text = link(&format!(
            "<inertial><mass value='1'/>{}</inertial>",
            INERTIA.replace("ixy='0.1'", "ixy='abc'")
        ));
        let col = text.lines().nth(3).unwrap().find("abc").unwrap() + 1;
        let d = error(&text);
        assert!(
            d.starts_with(&format!(
                "r.xml:4:{col}: error: `ixy` of link \"arm\": expected a number, found \"abc\"\n"
            )),
            "{d}"
        );
    }

    #[test]
    fn a_value_that_is_not_finite_is_refused() {
        let text = link(&format!(
            "<inertial><mass value='inf'/>{INERTIA}</inertial>"
        ));
        assert!(
            error(&text).contains(
                "error: `value` of link \"arm\": expected a finite number, found \"inf\"\n"
            ),
            "{}",
            error(&text)
        );
    }

    #[test]
    fn a_missing_mass_is_refused_at_the_inertial() {
        let text = link(&format!("<inertial>{INERTIA}</inertial>"));
        let d = error(&text);
        assert!(
            d.starts_with(
                "r.xml:4:5: error: `<inertial>` of link \"arm\" is missing the required element `<mass>`\n"
            ),
            "{d}"
        );
    }

    #[test]
    fn a_mass_without_a_value_is_refused() {
        let text = link(&format!("<inertial><mass/>{INERTIA}</inertial>"));
        let d = error(&text);
        assert!(
            d.starts_with("r.xml:4:15: error: `<mass>` of link \"arm\" is missing the required attribute `value`\n"),
            "{d}"
        );
    }

    #[test]
    fn every_inertia_attribute_is_required() {
        let text = link(&format!(
            "<inertial><mass value='1'/>{}</inertial>",
            INERTIA.replace(" iyz='0.3'", "")
        ));
        let d = error(&text);
        assert!(
            d.starts_with(
                "r.xml:4:32: error: `<inertia>` of link \"arm\" is missing the required attribute `iyz`\n"
            ),
            "{d}"
        );
    }

    #[test]
    fn a_missing_inertia_is_refused() {
        let text = link("<inertial><mass value='1'/></inertial>");
        assert!(
            error(&text).contains(
                "`<inertial>` of link \"arm\" is missing the required element `<inertia>`"
            )
        );
    }

    #[test]
    fn an_origin_with_two_numbers_is_refused() {
        let text = link(&format!(
            "<inertial><origin xyz='1 2'/><mass value='1'/>{INERTIA}</inertial>"
        ));
        let d = error(&text);
        assert!(
            d.starts_with(
                "r.xml:4:28: error: `xyz` of link \"arm\": expected 3 numbers, found 2\n"
            ),
            "{d}"
        );
    }

    #[test]
    fn a_list_with_commas_is_refused() {
        let text = link(&format!(
            "<inertial><origin xyz='1,2,3'/><mass value='1'/>{INERTIA}</inertial>"
        ));
        assert!(error(&text).contains("`xyz` of link \"arm\": expected a number, found \"1,2,3\""));
    }

    #[test]
    fn a_link_needs_a_name() {
        let d = error(&robot("<link/>"));
        assert!(
            d.starts_with(
                "r.xml:3:1: error: `<link>` of `<robot>` is missing the required attribute `name`\n"
            ),
            "{d}"
        );
    }
}
