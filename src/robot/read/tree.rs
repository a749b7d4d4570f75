//! The kinematic tree of a robot description (`robot::kinematics::Tree`),
//! read for the whole robot (`report`, `diff`, `include`): the joints, the
//! links' poses and the followers (URDF `<mimic>`, MJCF `<equality><joint>`),
//! parallel to the `Description` of the same text (links in the same order).
//!
//! What is not read is refused with its place: SDFormat nested models,
//! worlds, and poses relative to other frames; MJCF default classes that
//! set a joint's or a body's placement; URDF joint types it does not know.

use super::orient::{Settings, orientation, quat_to_matrix};
use super::{Value, Xml, child, children, mjcf, proper, qname, quoted, rpy, sdf};
use crate::diag::{Diagnostic, Source};
use crate::robot::kinematics::{Follow, Joint, Motion, Node as TreeNode, Pose, Tree};
use crate::robot::{Description, Dialect};
use roxmltree::Node;
use std::collections::HashMap;

/// The tree of `source`, whose links `d` holds (read from the same text).
pub fn tree(source: &Source, d: &Description) -> Result<Tree, Diagnostic> {
    let doc = super::parse(source)?;
    let xml = Xml { source };
    let root = doc.root_element();
    let tree = match d.format {
        Dialect::Urdf => urdf(&xml, root, d)?,
        Dialect::Sdf => sdformat(&xml, root, d)?,
        Dialect::Mjcf => mujoco(&xml, root, d)?,
    };
    depth(&xml, &tree, d)?;
    Ok(tree)
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

/// A unit axis from `v` (three numbers, not all zero).
fn axis(xml: &Xml, v: &Value, owner: &str) -> Result<[f64; 3], Diagnostic> {
    let a = xml.numbers::<3>(v, owner)?;
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    if !(n > 0.0 && n.is_finite()) {
        return Err(xml.error(
            v.range.clone(),
            format!("{} of {owner}: a zero axis gives no direction", v.name),
        ));
    }
    Ok(a.map(|x| x / n))
}

/// Link names to indices (the first of a name), refusing a name twice.
fn names<'d>(xml: &Xml, d: &'d Description) -> Result<HashMap<&'d str, usize>, Diagnostic> {
    let mut out = HashMap::with_capacity(d.links.len());
    for (i, l) in d.links.iter().enumerate() {
        if out.insert(l.name.as_str(), i).is_some() {
            return Err(xml
                .error(
                    super::start_tag(&xml.source.text, l.range.clone()),
                    format!(
                        "two links are named {}: the kinematic tree cannot be followed",
                        quoted(&l.name)
                    ),
                )
                .help("name each link once"));
        }
    }
    Ok(out)
}

/// The link `name` names, or an error at `v` with the nearest name.
fn link_named(
    xml: &Xml,
    names: &HashMap<&str, usize>,
    v: &Value,
    owner: &str,
) -> Result<usize, Diagnostic> {
    names.get(v.text.as_str()).copied().ok_or_else(|| {
        let near = crate::units::suggest(&v.text, names.keys().copied())
            .map(|s| format!("; did you mean {}?", quoted(s)))
            .unwrap_or_default();
        xml.error(
            v.range.clone(),
            format!(
                "{} of {owner} names no link: {}{near}",
                v.name,
                quoted(&v.text)
            ),
        )
    })
}

/// Each child given its parent once, and no cycle.
fn set_parent(
    xml: &Xml,
    t: &mut Tree,
    child: usize,
    parent: usize,
    at: &Value,
    owner: &str,
) -> Result<(), Diagnostic> {
    if t.links[child].parent.is_some() {
        return Err(xml.error(
            at.range.clone(),
            format!(
                "{} of {owner}: the link already has a parent joint",
                at.name
            ),
        ));
    }
    let mut p = Some(parent);
    let mut hops = 0;
    while let Some(k) = p {
        if k == child || hops > t.links.len() {
            return Err(xml.error(
                at.range.clone(),
                format!("{owner} closes a loop: the link is its own ancestor"),
            ));
        }
        p = t.links[k].parent;
        hops += 1;
    }
    t.links[child].parent = Some(parent);
    Ok(())
}

fn unplaced(n: usize) -> Vec<TreeNode> {
    vec![
        TreeNode {
            parent: None,
            place: Pose::IDENTITY,
            joints: Vec::new(),
        };
        n
    ]
}

/// `(lower, upper)` if both are given.
fn limits(lower: Option<f64>, upper: Option<f64>) -> Option<(f64, f64)> {
    Some((lower?, upper?))
}

fn urdf(xml: &Xml, robot: Node, d: &Description) -> Result<Tree, Diagnostic> {
    let names = names(xml, d)?;
    let mut t = Tree {
        links: unplaced(d.links.len()),
        joints: Vec::new(),
    };
    let mut mimics = Vec::new();
    for j in children(robot, "joint") {
        let name = xml.required(j, "name", "`<robot>`")?;
        let owner = format!("joint {}", quoted(&name.text));
        let kind = xml.required(j, "type", &owner)?;
        let motion = xml.keyword(
            &kind,
            &owner,
            &[
                ("revolute", Motion::Revolute),
                ("continuous", Motion::Revolute),
                ("prismatic", Motion::Prismatic),
                ("fixed", Motion::Fixed),
                ("floating", Motion::Stays),
                ("planar", Motion::Stays),
            ],
        )?;
        let end = |tag: &str| -> Result<Value, Diagnostic> {
            let e = child(j, tag).ok_or_else(|| {
                xml.error(
                    xml.tag(j),
                    format!("{owner} is missing the required element `<{tag}>`"),
                )
            })?;
            xml.required(e, "link", &owner)
        };
        let (parent, kid) = (end("parent")?, end("child")?);
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

/// The joint `v` names, or an error with the nearest name.
fn joint_named(xml: &Xml, t: &Tree, v: &Value, owner: &str) -> Result<usize, Diagnostic> {
    t.joints
        .iter()
        .position(|j| j.name == v.text)
        .ok_or_else(|| {
            let near = crate::units::suggest(&v.text, t.joints.iter().map(|j| j.name.as_str()))
                .map(|s| format!("; did you mean {}?", quoted(s)))
                .unwrap_or_default();
            xml.error(
                v.range.clone(),
                format!(
                    "{} of {owner} names no joint: {}{near}",
                    v.name,
                    quoted(&v.text)
                ),
            )
        })
}

/// A link's or joint's `<pose>` in the model frame (no `relative_to` but
/// the one allowed, `allowed`).
fn sdf_pose(xml: &Xml, node: Node, allowed: &str, owner: &str) -> Result<Pose, Diagnostic> {
    let Some(p) = child(node, "pose") else {
        return Ok(Pose::IDENTITY);
    };
    if let Some(v) = xml.attr(p, "relative_to")
        && !v.text.is_empty()
        && v.text != allowed
    {
        return Err(xml
            .error(
                v.range.clone(),
                format!(
                    "`relative_to` of the `<pose>` of {owner} names {}: the whole robot is composed from poses in their default frames only",
                    quoted(&v.text)
                ),
            )
            .help("give the pose in its default frame (a link's: the model's; a joint's: its child link's) and drop `relative_to`"));
    }
    let (p, r) = sdf::pose(xml, p, allowed, owner)?;
    Ok(Pose {
        p,
        r: r.unwrap_or(Pose::IDENTITY.r),
    })
}

fn sdformat(xml: &Xml, sdf_node: Node, d: &Description) -> Result<Tree, Diagnostic> {
    let models: Vec<Node> = sdf_node
        .children()
        .filter(|c| qname(*c) == "model")
        .collect();
    let unsupported = sdf_node
        .children()
        .find(|c| qname(*c) == "world")
        .or_else(|| models.get(1).copied())
        .or_else(|| {
            models.first().and_then(|m| {
                m.children()
                    .find(|c| qname(*c) == "model" || qname(*c) == "include")
            })
        });
    if let Some(n) = unsupported {
        return Err(xml
            .error(
                xml.tag(n),
                format!(
                    "`<{}>` here: the whole robot is composed from one `<model>` of links and joints, without worlds, nested models or includes",
                    qname(n)
                ),
            )
            .help("`check` reads every link of such a file; compose one model at a time"));
    }
    let Some(model) = models.first() else {
        return Ok(Tree::default());
    };
    let names = names(xml, d)?;
    let mut t = Tree {
        links: unplaced(d.links.len()),
        joints: Vec::new(),
    };
    // Each link's pose in the model frame.
    let model_name = model.attribute("name").unwrap_or_default();
    let mut world = vec![Pose::IDENTITY; d.links.len()];
    for (i, l) in children(*model, "link").enumerate() {
        let owner = format!("link {}", quoted(&d.links[i].name));
        world[i] = sdf_pose(xml, l, model_name, &owner)?;
    }
    let old = sdf_node
        .attribute("version")
        .and_then(|v| v.split('.').nth(1)?.parse::<u32>().ok())
        .is_some_and(|minor| {
            sdf_node
                .attribute("version")
                .is_some_and(|v| v.starts_with("1."))
                && minor < 7
        });
    for j in children(*model, "joint") {
        let name = xml.required(j, "name", "`<model>`")?;
        let owner = format!("joint {}", quoted(&name.text));
        let kind = xml.required(j, "type", &owner)?;
        let motion = xml.keyword(
            &kind,
            &owner,
            &[
                ("revolute", Motion::Revolute),
                ("continuous", Motion::Revolute),
                ("prismatic", Motion::Prismatic),
                ("fixed", Motion::Fixed),
                ("ball", Motion::Stays),
            ],
        )?;
        let end = |tag: &str| -> Result<Value, Diagnostic> {
            let e = child(j, tag).ok_or_else(|| {
                xml.error(
                    xml.tag(j),
                    format!("{owner} is missing the required element `<{tag}>`"),
                )
            })?;
            Ok(xml.text(e))
        };
        let (parent, kid) = (end("parent")?, end("child")?);
        let c = link_named(xml, &names, &kid, &owner)?;
        let p = if parent.text == "world" {
            None
        } else {
            let p = link_named(xml, &names, &parent, &owner)?;
            set_parent(xml, &mut t, c, p, &kid, &owner)?;
            Some(p)
        };
        let joint_pose = sdf_pose(xml, j, &kid.text, &owner)?;
        let ax = child(j, "axis");
        let (axis_in_joint, lower, upper, in_model) = match ax {
            Some(a) => {
                let xyz = child(a, "xyz");
                let v = xyz
                    .map(|x| axis(xml, &xml.text(x), &owner))
                    .transpose()?
                    .unwrap_or([0.0, 0.0, 1.0]);
                let expressed = xyz.and_then(|x| x.attribute("expressed_in"));
                let parent_model = child(a, "use_parent_model_frame")
                    .map(|u| sdf::flag(xml, &xml.text(u), &owner))
                    .transpose()?
                    .unwrap_or(false);
                let in_model = match expressed {
                    Some("__model__") => true,
                    Some(e) if e == model_name => true,
                    Some(e) if e.is_empty() || e == name.text => false,
                    Some(e) => {
                        let v = xml.attr(xyz.expect("has the attribute"), "expressed_in");
                        let range = v.map_or(xml.tag(j), |v| v.range);
                        return Err(xml.error(
                            range,
                            format!(
                                "`expressed_in` of the axis of {owner} names {}: only the joint's frame and the model's are supported",
                                quoted(e)
                            ),
                        ));
                    }
                    None => old && parent_model,
                };
                let lim = child(a, "limit");
                let bound = |n: &str| -> Result<Option<f64>, Diagnostic> {
                    lim.and_then(|l| child(l, n))
                        .map(|e| xml.number(&xml.text(e), &owner))
                        .transpose()
                };
                (v, bound("lower")?, bound("upper")?, in_model)
            }
            None => ([0.0, 0.0, 1.0], None, None, false),
        };
        // The axis in the child's frame: turned by the joint's pose, or
        // from the model frame by the child's.
        let axis = if in_model {
            let r = world[c].r;
            std::array::from_fn(|i| (0..3).map(|k| r[k][i] * axis_in_joint[k]).sum())
        } else {
            let r = joint_pose.r;
            std::array::from_fn(|i| (0..3).map(|k| r[i][k] * axis_in_joint[k]).sum())
        };
        if p.is_some() {
            t.links[c].joints.push(t.joints.len());
        }
        let limits = match (motion, kind.text.as_str()) {
            (Motion::Revolute, "continuous") => None,
            (Motion::Revolute | Motion::Prismatic, _) => limits(lower, upper),
            _ => None,
        };
        t.joints.push(Joint {
            name: name.text.clone(),
            motion,
            axis,
            anchor: joint_pose.p,
            zero: 0.0,
            limits,
            follows: None,
            range: j.range(),
        });
    }
    for i in 0..t.links.len() {
        t.links[i].place = match t.links[i].parent {
            Some(p) => world[p].inverse().then(&world[i]),
            None => world[i],
        };
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

fn mujoco(xml: &Xml, root: Node, d: &Description) -> Result<Tree, Diagnostic> {
    let mut s = Settings::default();
    for c in children(root, "compiler") {
        mjcf::compiler(xml, c, &mut s)?;
    }
    // Default classes may set a joint's type, axis, anchor, range or ref,
    // or a body's frame: not read, so refused where they would apply.
    for def in root.descendants().filter(|n| qname(*n) == "default") {
        for n in def
            .children()
            .filter(|n| matches!(qname(*n), "joint" | "body"))
        {
            if let Some(a) = n.attributes().find(|a| {
                matches!(
                    a.name(),
                    "type" | "axis" | "pos" | "ref" | "range" | "limited"
                )
            }) {
                let v = xml.attr(n, a.name()).expect("the attribute is there");
                return Err(xml
                    .error(
                        v.range,
                        format!(
                            "a default class sets `{}` of `<{}>`: the whole robot is composed only from values written on each element",
                            a.name(),
                            qname(n)
                        ),
                    )
                    .help("write the value on each joint (MuJoCo's `mj_saveLastXML` writes a model with its defaults applied)"));
            }
        }
    }
    let radians = |a: f64| if s.degree { a.to_radians() } else { a };
    let mut t = Tree {
        links: unplaced(d.links.len()),
        joints: Vec::new(),
    };
    let mut index: HashMap<roxmltree::NodeId, usize> = HashMap::new();
    let mut count = 0;
    for world in children(root, "worldbody") {
        for body in world.descendants().skip(1).filter(|n| qname(*n) == "body") {
            let i = count;
            count += 1;
            index.insert(body.id(), i);
            let owner = format!("body {}", quoted(&d.links[i].name));
            // Its pose in the enclosing body's frame, through any frames.
            let mut place = mj_pose(xml, body, &owner, &s)?;
            let mut up = body.parent();
            while let Some(n) = up {
                if qname(n) != "frame" {
                    break;
                }
                place = mj_pose(xml, n, &owner, &s)?.then(&place);
                up = n.parent();
            }
            t.links[i].parent = up.and_then(|n| index.get(&n.id()).copied());
            t.links[i].place = place;
            for j in body
                .children()
                .filter(|c| matches!(qname(*c), "joint" | "freejoint"))
            {
                let name = j
                    .attribute("name")
                    .map_or_else(|| format!("joint {}", t.joints.len() + 1), str::to_string);
                let jowner = format!("joint {}", quoted(&name));
                let motion = if qname(j) == "freejoint" {
                    Motion::Stays
                } else {
                    match xml.attr(j, "type") {
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
                let axis = match xml.attr(j, "axis") {
                    Some(v) => axis(xml, &v, &jowner)?,
                    None => [0.0, 0.0, 1.0],
                };
                let anchor = match xml.attr(j, "pos") {
                    Some(v) => xml.numbers::<3>(&v, &jowner)?,
                    None => [0.0; 3],
                };
                let zero = match xml.attr(j, "ref") {
                    Some(v) if matches!(motion, Motion::Revolute | Motion::Prismatic) => {
                        scale(xml.number(&v, &jowner)?)
                    }
                    _ => 0.0,
                };
                let range = match xml.attr(j, "range") {
                    Some(v) => Some(xml.numbers::<2>(&v, &jowner)?.map(scale)),
                    None => None,
                };
                let limited = match xml.attr(j, "limited") {
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
                    range: j.range(),
                });
            }
        }
    }
    for eq in children(root, "equality") {
        for e in children(eq, "joint") {
            let owner = "`<equality><joint>`".to_string();
            if let Some(v) = xml.attr(e, "active")
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
            if let Some(v) = xml.attr(e, "polycoef") {
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
