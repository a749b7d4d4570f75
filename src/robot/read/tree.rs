//! The kinematic tree of a robot description (`robot::kinematics::Tree`),
//! read for the whole robot (`report`, `diff`, `include`): the joints, the
//! links' poses and the followers (URDF `<mimic>`, MJCF `<equality><joint>`),
//! parallel to the `Description` of the same text (links in the same order).
//!
//! What is not read is refused with its place (SDFormat's: `sdf_tree`):
//! MJCF default classes that set a joint's or a body's placement; URDF
//! joint types it does not know.

use super::links::{
    Head, axis, joint_head, joint_named, limits, link_named, names, set_parent, unplaced,
};
use super::mjcf_class::Classes;
use super::mjcf_include::Model;
use super::orient::{Settings, orientation, quat_to_matrix};
pub use super::sdf_include::Resolve;
use super::{Xml, child, children, mjcf, proper, qname, quoted, rpy};
use crate::diag::{Diagnostic, Source};
use crate::robot::kinematics::{Follow, Joint, Motion, Pose, Tree};
use crate::robot::{Description, Dialect};
use roxmltree::Node;
use std::collections::HashMap;

/// The tree of `source`, whose links `d` holds (read from the same text).
/// An SDFormat file's includes are resolved by `r`, and `d` then holds
/// their links too (`sdf_tree`).
pub fn tree(source: &Source, d: &mut Description, r: &Resolve) -> Result<Tree, Diagnostic> {
    let doc = super::parse(source)?;
    let xml = Xml { source };
    let root = doc.root_element();
    let tree = match d.format {
        Dialect::Urdf => urdf(&xml, root, d)?,
        Dialect::Sdf => super::sdf_tree::sdformat(&xml, d, r)?,
        Dialect::Mjcf => super::mjcf_include::with_model(source, r, |m| mujoco(m, d))?,
    };
    depth(&xml, &tree, d)?;
    followers(&xml, &tree)?;
    Ok(tree)
}

/// Refuse followers in a cycle (`<mimic>`, joint equalities), at the first
/// joint of the cycle, naming each: no configuration satisfies them.
fn followers(xml: &Xml, t: &Tree) -> Result<(), Diagnostic> {
    if t.follow(&mut t.zeros()).is_some() {
        return Ok(());
    }
    for start in 0..t.joints.len() {
        // Up the leaders from `start`: back at `start` within as many
        // steps as there are joints, or never.
        let mut chain = vec![start];
        let mut at = start;
        while let Some(l) = t.joints[at].follows.as_ref().and_then(|f| f.leader) {
            if l == start {
                let names: Vec<String> = chain
                    .iter()
                    .chain([&start])
                    .map(|&j| quoted(&t.joints[j].name))
                    .collect();
                return Err(xml.error(
                    super::start_tag(&xml.source.text, t.joints[start].range.clone()),
                    format!(
                        "joint {} follows itself through a cycle of followers (`<mimic>` or joint equalities): {}; no configuration satisfies them",
                        quoted(&t.joints[start].name),
                        names.join(" → ")
                    ),
                ));
            }
            if chain.len() > t.joints.len() {
                break;
            }
            chain.push(l);
            at = l;
        }
    }
    unreachable!("`follow` fails only on a cycle of leaders")
}

/// Refuse a chain deeper than `MAX_CHAIN` links.
fn depth(xml: &Xml, t: &Tree, d: &Description) -> Result<(), Diagnostic> {
    let mut depth = vec![0usize; t.links.len()];
    for i in 0..t.links.len() {
        // Up to a link whose depth is known, then down again.
        let mut chain = vec![i];
        while let Some(p) = t.links[*chain.last().expect("not empty")].parent {
            if depth[p] > 0 || chain.len() > crate::robot::kinematics::MAX_CHAIN {
                break;
            }
            chain.push(p);
        }
        let base = t.links[*chain.last().expect("not empty")]
            .parent
            .map_or(0, |p| depth[p]);
        for (k, &l) in chain.iter().rev().enumerate() {
            depth[l] = base + k + 1;
        }
        if depth[i] > crate::robot::kinematics::MAX_CHAIN {
            let link = &d.links[i];
            return Err(xml.error(
                super::start_tag(&xml.source.text, link.range.clone()),
                format!(
                    "link {} is {} links from its root: a chain deeper than {} links is not composed",
                    quoted(&link.name),
                    depth[i],
                    crate::robot::kinematics::MAX_CHAIN
                ),
            ));
        }
    }
    Ok(())
}

fn urdf(xml: &Xml, robot: Node, d: &Description) -> Result<Tree, Diagnostic> {
    let names = names(xml, d)?;
    let mut t = Tree {
        links: unplaced(d.links.len()),
        joints: Vec::new(),
    };
    let mut mimics = Vec::new();
    for j in children(robot, "joint") {
        let Head {
            name,
            owner,
            kind,
            motion,
            parent,
            child: kid,
        } = joint_head(
            xml,
            j,
            "`<robot>`",
            &[
                ("revolute", Motion::Revolute),
                ("continuous", Motion::Revolute),
                ("prismatic", Motion::Prismatic),
                ("fixed", Motion::Fixed),
                ("floating", Motion::Stays),
                ("planar", Motion::Stays),
            ],
            |e, owner| xml.required(e, "link", owner),
        )?;
        let p = link_named(xml, &names, &parent, &owner)?;
        let c = link_named(xml, &names, &kid, &owner)?;
        set_parent(xml, &mut t, c, p, &kid, &owner)?;
        let origin = child(j, "origin");
        let attr = |n: &str| origin.and_then(|o| xml.attr(o, n));
        let mut place = Pose::IDENTITY;
        if let Some(v) = attr("xyz") {
            place.p = xml.numbers::<3>(&v, &owner)?;
        }
        if let Some(v) = attr("rpy") {
            let [r, p, y] = xml.numbers::<3>(&v, &owner)?;
            place.r = rpy(r.sin_cos(), p.sin_cos(), y.sin_cos());
        }
        let axis = match child(j, "axis").and_then(|a| xml.attr(a, "xyz")) {
            Some(v) => axis(xml, &v, &owner)?,
            None => [1.0, 0.0, 0.0],
        };
        let limit = child(j, "limit");
        let bound = |n: &str| -> Result<Option<f64>, Diagnostic> {
            limit
                .and_then(|l| xml.attr(l, n))
                .map(|v| xml.number(&v, &owner))
                .transpose()
        };
        let limits = match (kind.text.as_str(), limit) {
            ("revolute" | "prismatic", Some(_)) => limits(
                Some(bound("lower")?.unwrap_or(0.0)),
                Some(bound("upper")?.unwrap_or(0.0)),
            ),
            _ => None,
        };
        if let Some(m) = child(j, "mimic") {
            let leader = xml.required(m, "joint", &owner)?;
            let number = |n: &str, default: f64| -> Result<f64, Diagnostic> {
                xml.attr(m, n)
                    .map_or(Ok(default), |v| xml.number(&v, &owner))
            };
            mimics.push((
                t.joints.len(),
                leader,
                number("offset", 0.0)?,
                number("multiplier", 1.0)?,
            ));
        }
        t.links[c].place = place;
        t.links[c].joints.push(t.joints.len());
        t.joints.push(Joint {
            name: name.text.clone(),
            motion,
            axis,
            anchor: [0.0; 3],
            zero: 0.0,
            limits,
            follows: None,
            range: j.range(),
        });
    }
    for (i, leader, offset, multiplier) in mimics {
        let owner = format!("joint {}", quoted(&t.joints[i].name));
        let l = joint_named(xml, &t, &leader, &owner)?;
        t.joints[i].follows = Some(Follow {
            leader: Some(l),
            coef: [offset, multiplier, 0.0, 0.0, 0.0],
        });
    }
    let roots: Vec<usize> = t.roots().collect();
    if let [_, second, ..] = roots.as_slice() {
        let first = &d.links[roots[0]].name;
        let l = &d.links[*second];
        return Err(xml
            .error(
                super::start_tag(&xml.source.text, l.range.clone()),
                format!(
                    "link {} is a second root: no joint has it as its child, nor {}",
                    quoted(&l.name),
                    quoted(first)
                ),
            )
            .help("a URDF robot is one tree: join the link to it with a joint"));
    }
    Ok(t)
}

/// The pose `pos` and an orientation attribute give an MJCF element (a
/// body or a frame).
fn mj_pose(xml: &Xml, node: Node, owner: &str, s: &Settings) -> Result<Pose, Diagnostic> {
    let mut pose = Pose::IDENTITY;
    if let Some(v) = xml.attr(node, "pos") {
        pose.p = xml.numbers::<3>(&v, owner)?;
    }
    let forms = ["quat", "axisangle", "xyaxes", "zaxis", "euler"];
    if let Some((form, v)) = forms.iter().find_map(|f| Some((*f, xml.attr(node, f)?))) {
        let m = quat_to_matrix(orientation(xml, form, &v, owner, s)?);
        pose.r = proper(xml, &v, owner, m)?;
    }
    Ok(pose)
}

fn mujoco(m: &Model, d: &Description) -> Result<Tree, Diagnostic> {
    let mut s = Settings::default();
    for (xml, _, c) in m.sections("compiler") {
        mjcf::compiler(xml, c, &mut s)?;
    }
    // Default classes give a joint the values it does not write itself
    // (`mjcf_class`).
    let classes = Classes::read(m)?;
    classes.check_names(m)?;
    let radians = |a: f64| if s.degree { a.to_radians() } else { a };
    let mut t = Tree {
        links: unplaced(d.links.len()),
        joints: Vec::new(),
    };
    // Keyed by file too: each file is a document of its own.
    let mut index: HashMap<(usize, roxmltree::NodeId), usize> = HashMap::new();
    let mut count = 0;
    for (_, file, world) in m.sections("worldbody") {
        // Includes spliced (`Model::descendants`, `parent`, `children`).
        for (file, body) in m.descendants(file, world) {
            if qname(body) != "body" {
                continue;
            }
            let xml = m.xml(file);
            let i = count;
            count += 1;
            index.insert((file, body.id()), i);
            let owner = format!("body {}", quoted(&d.links[i].name));
            // Its pose in the enclosing body's frame, through any frames.
            let mut place = mj_pose(xml, body, &owner, &s)?;
            let mut up = m.parent(file, body);
            while let Some((f, n)) = up {
                if qname(n) != "frame" {
                    break;
                }
                place = mj_pose(m.xml(f), n, &owner, &s)?.then(&place);
                up = m.parent(f, n);
            }
            t.links[i].parent = up.and_then(|(f, n)| index.get(&(f, n.id())).copied());
            t.links[i].place = place;
            for (jf, j) in m
                .children(file, body)
                .filter(|(_, c)| matches!(qname(*c), "joint" | "freejoint"))
            {
                let xml = m.xml(jf);
                let name = j
                    .attribute("name")
                    .map_or_else(|| format!("joint {}", t.joints.len() + 1), str::to_string);
                let jowner = format!("joint {}", quoted(&name));
                let class = classes.of(m, jf, j)?;
                let attr = |n: &str| classes.attr(xml, j, class, "joint", n);
                let motion = if qname(j) == "freejoint" {
                    Motion::Stays
                } else {
                    match attr("type") {
                        Some(v) => xml.keyword(
                            &v,
                            &jowner,
                            &[
                                ("hinge", Motion::Revolute),
                                ("slide", Motion::Prismatic),
                                ("ball", Motion::Stays),
                                ("free", Motion::Stays),
                            ],
                        )?,
                        None => Motion::Revolute,
                    }
                };
                let angular = motion == Motion::Revolute;
                let scale = |x: f64| if angular { radians(x) } else { x };
                let axis = match attr("axis") {
                    Some(v) => axis(xml, &v, &jowner)?,
                    None => [0.0, 0.0, 1.0],
                };
                let anchor = match attr("pos") {
                    Some(v) => xml.numbers::<3>(&v, &jowner)?,
                    None => [0.0; 3],
                };
                let zero = match attr("ref") {
                    Some(v) if matches!(motion, Motion::Revolute | Motion::Prismatic) => {
                        scale(xml.number(&v, &jowner)?)
                    }
                    _ => 0.0,
                };
                let range = match attr("range") {
                    Some(v) => Some(xml.numbers::<2>(&v, &jowner)?.map(scale)),
                    None => None,
                };
                let limited = match attr("limited") {
                    Some(v) => xml.keyword(
                        &v,
                        &jowner,
                        &[("true", true), ("false", false), ("auto", range.is_some())],
                    )?,
                    None => range.is_some(),
                };
                t.links[i].joints.push(t.joints.len());
                t.joints.push(Joint {
                    name,
                    motion,
                    axis,
                    anchor,
                    zero,
                    limits: range.filter(|_| limited).map(|[a, b]| (a, b)),
                    follows: None,
                    range: m.range(jf, j.range()),
                });
            }
        }
    }
    for (_, file, eq) in m.sections("equality") {
        for (ef, e) in m.named(file, eq, "joint") {
            let xml = m.xml(ef);
            let owner = "`<equality><joint>`".to_string();
            let class = classes.of(m, ef, e)?;
            let attr = |n: &str| classes.attr(xml, e, class, "equality", n);
            if let Some(v) = attr("active")
                && !xml.keyword(&v, &owner, &[("true", true), ("false", false)])?
            {
                continue;
            }
            let j1 = xml.required(e, "joint1", &owner)?;
            let y = joint_named(xml, &t, &j1, &owner)?;
            let x = xml
                .attr(e, "joint2")
                .map(|v| joint_named(xml, &t, &v, &owner))
                .transpose()?;
            let mut coef = [0.0, 1.0, 0.0, 0.0, 0.0];
            if let Some(v) = attr("polycoef") {
                let list = xml.list(&v, &owner)?;
                if list.len() > 5 {
                    return Err(xml.error(
                        v.range.clone(),
                        format!(
                            "`polycoef` of {owner}: expected at most 5 numbers, found {}",
                            list.len()
                        ),
                    ));
                }
                coef = [0.0; 5];
                coef[..list.len()].copy_from_slice(&list);
            }
            if t.joints[y].follows.is_some() {
                return Err(xml.error(
                    j1.range.clone(),
                    format!(
                        "`joint1` of {owner}: joint {} already follows another joint",
                        quoted(&j1.text)
                    ),
                ));
            }
            t.joints[y].follows = Some(Follow { leader: x, coef });
        }
    }
    Ok(t)
}
