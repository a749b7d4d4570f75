//! An SDFormat model's kinematic tree (`tree`'s SDFormat half): its links'
//! poses through the pose frame semantics of SDFormat 1.7+ (sdformat.org,
//! "Pose frame semantics": a `<pose relative_to="F">` is in frame F; a
//! link's pose by default in the model frame, a joint's in its child
//! link's, a `<frame>`'s in the frame it is `attached_to`, itself by default
//! the model frame; libsdformat's `FrameSemantics.cc` resolves the same
//! graph), its joints, and their followers (SDFormat 1.11's
//! `<axis><mimic joint><multiplier/><offset/><reference/></mimic>`:
//! follower = multiplier·(leader − reference) + offset, sdf/1.11/mimic.sdf).
//!
//! Nested models and includes are scopes (SDFormat 1.8, "Model
//! composition"): a name is looked up in the scope of the element that
//! writes it, `a::b` in the nested model `a`'s, `__model__` is the scope's
//! own model frame; a nested model's `<pose>` is in its parent's scope
//! (by default the parent model frame), of its `placement_frame` when it
//! names one; a model's frame is attached to its canonical link
//! (`canonical_link`, else its first link, else its first nested model's).
//! A joint's `<parent>` and `<child>` may name any frame: the link it is
//! attached to is the one the tree joins. A `<world>` (or several models
//! under `<sdf>`) is the scope of its models, each at its `<pose>` in the
//! world frame, which is the report frame. Names in the tree are paths
//! from the top, the outermost model's name left out unless there are
//! several (as `sdf::read` names links for `check`).
//!
//! Refused with their place: two worlds; a `relative_to`, `attached_to`,
//! `canonical_link` or `placement_frame` naming no frame; frames placed
//! relative to each other in a cycle; models nested deeper than
//! `MAX_NESTING`; more than `MAX_MODELS` models.

use super::links::{Head, axis, joint_head, joint_named, limits, set_parent, unplaced};
use super::sdf_frames::{Frame, Graph, Kind, MAX_MODELS, MAX_NESTING, Scope, join};
use super::sdf_include::{self, Files, Resolve};
use super::{Value, Xml, child, children, qname, quoted, sdf};
use crate::diag::{Diagnostic, Source};
use crate::robot::kinematics::{Follow, Joint, Motion, Pose, Tree};
use crate::robot::{Description, Link};
use roxmltree::Node;
use std::collections::HashMap;

/// A `<mimic>` waiting for every joint to be read: the follower, its
/// leader's name (in the scope given, written in the file given),
/// multiplier, offset and reference.
struct Mimic {
    follower: usize,
    leader: Value,
    scope: usize,
    file: usize,
    multiplier: f64,
    offset: f64,
    reference: f64,
}

/// The whole robot's tree, `d`'s links replaced by every link of the
/// models read (the top file's as `sdf::read` read them, in the same
/// order, then each include's in its place), with includes resolved by
/// `r`.
pub(super) fn sdformat(xml: &Xml, d: &mut Description, r: &Resolve) -> Result<Tree, Diagnostic> {
    let files = sdf_include::load(xml.source, r)?;
    of_files(xml, d, &files)
}

/// Each link whose place in the tree says whether it moves: the child of
/// a joint that is not `fixed` moves; a link that is the child of no joint
/// keeps what the model says (a static model's links stay). As `sdf::read`
/// judges the links of the file's own models; here for the links of its
/// included ones, which only the tree reads.
pub(super) fn moving(d: &mut Description, t: &Tree) {
    for (l, n) in d.links.iter_mut().zip(&t.links) {
        if l.site.file == 0 {
            continue;
        }
        if let Some(&j) = n.joints.first() {
            l.moving = t.joints[j].motion != Motion::Fixed;
        }
    }
}

/// `sdformat` of the files read (`sdf_include::load`); `d` keeps them
/// (`Description::files`).
pub(super) fn of_files(xml: &Xml, d: &mut Description, files: &Files) -> Result<Tree, Diagnostic> {
    d.files = crate::robot::Included {
        sources: files.included.clone(),
        from: files.from.clone(),
    };
    let count = files.included.len() + 1;
    let sources: Vec<&Source> = (0..count).map(|k| files.source(k)).collect();
    let docs = sources
        .iter()
        .map(|s| super::parse(s))
        .collect::<Result<Vec<_>, _>>()?;
    let xmls: Vec<Xml> = sources.iter().map(|s| Xml { source: s }).collect();
    let sdf_node = docs[0].root_element();
    let worlds: Vec<Node> = children(sdf_node, "world").collect();
    let models: Vec<Node> = children(sdf_node, "model").collect();
    if let Some(n) = worlds.get(1).or(worlds.first().and(models.first())) {
        return Err(xml
            .error(
                xml.tag(*n),
                format!(
                    "`<{}>` here: the whole robot is composed from one `<world>`, or the models written under `<sdf>`",
                    qname(*n)
                ),
            )
            .help("compose one world at a time"));
    }
    let (top, world) = match (worlds.first(), models.as_slice()) {
        (Some(w), _) => (*w, true),
        (None, [m]) => (*m, false),
        (None, []) => return Ok(Tree::default()),
        (None, [_, _, ..]) => (sdf_node, true),
    };
    let entries = top
        .children()
        .filter(|c| matches!(qname(*c), "model" | "include"))
        .count();
    let mut g = Graph {
        xmls: &xmls,
        frames: Vec::new(),
        scopes: Vec::new(),
        placed: Vec::new(),
        links: Vec::new(),
        joints: Vec::new(),
        strip: world && entries == 1,
    };
    let own = if world {
        "__model__".to_string()
    } else {
        top.attribute("name").unwrap_or("__model__").to_string()
    };
    g.scopes.push(Scope {
        path: String::new(),
        frame: 0,
        own: own.clone(),
        element: top,
        file: 0,
        names: HashMap::new(),
        shared: Vec::new(),
        anchor: None,
        from: Vec::new(),
        depth: 0,
        world,
        fixed: false,
    });
    g.frames.push(Frame {
        name: own,
        kind: Kind::Top,
        element: top,
        file: 0,
        scope: 0,
        default: None,
        pose: None,
        placement: None,
    });
    g.placed.push(Some(Pose::IDENTITY));
    let mut links = walk(&mut g, files, &docs, d).map_err(|e| files.located(e))?;
    std::mem::swap(&mut d.links, &mut links);
    super::links::names(xml, d)?;
    build(&mut g, d).map_err(|e| files.located(e))
}

/// Every scope's frames, depth first in document order (an include's
/// model in its place); the links of the whole robot.
fn walk<'a, 'i>(
    g: &mut Graph<'a, 'i, '_>,
    files: &Files,
    docs: &'a [roxmltree::Document<'i>],
    d: &Description,
) -> Result<Vec<Link>, Diagnostic> {
    let written: HashMap<usize, &Link> = d.links.iter().map(|l| (l.range.start, l)).collect();
    let mut out = Vec::new();
    let mut stack: Vec<(usize, roxmltree::Children<'a, 'i>)> =
        vec![(0, g.scopes[0].element.children())];
    while let Some((s, it)) = stack.last_mut() {
        let s = *s;
        let Some(c) = it.next() else {
            stack.pop();
            continue;
        };
        let file = g.scopes[s].file;
        let xml = &g.xmls[file];
        let this = match s {
            0 if g.scopes[0].world => "`<world>`".to_string(),
            _ => "`<model>`".to_string(),
        };
        let scope_name = |g: &Graph, s: usize| match s {
            0 => "`<model>`".to_string(),
            _ => g.owner(g.scopes[s].frame),
        };
        match qname(c) {
            "link" if !g.scopes[s].world => {
                let name = xml.required(c, "name", &scope_name(g, s))?;
                let k = out.len();
                let shown = g.shown(s, &name.text);
                let anchor = g.scopes[s].anchor.clone();
                let link = match (file, written.get(&c.range().start)) {
                    (0, Some(l)) => Link {
                        name: shown,
                        ..(*l).clone()
                    },
                    _ => {
                        let owner = format!("link {}", quoted(&shown));
                        let range = anchor.clone().unwrap_or(c.range());
                        let mut inertial = match child(c, "inertial") {
                            Some(i) => sdf::inertial(xml, i, &name.text, &owner)?,
                            None => None,
                        };
                        let site = crate::robot::Site {
                            file,
                            element: c.range(),
                            inertial: inertial.as_ref().map(|i| i.range.clone()),
                            elsewhere: false,
                            from: g.scopes[s].from.clone(),
                        };
                        if let Some(i) = &mut inertial {
                            i.range = anchor.unwrap_or(i.range.clone());
                        }
                        Link {
                            name: shown,
                            range,
                            inertial,
                            moving: !g.scopes[s].fixed,
                            parent: None,
                            site,
                        }
                    }
                };
                out.push(link);
                let f = g.add(
                    Frame {
                        name: name.text,
                        kind: Kind::Link(k),
                        element: c,
                        file,
                        scope: s,
                        default: None,
                        pose: child(c, "pose").map(|p| (p, file)),
                        placement: None,
                    },
                    s,
                );
                g.links.push(f);
            }
            "joint" => {
                let name = xml.required(c, "name", &this)?;
                let owner = format!("joint {}", quoted(&name.text));
                let kid = child(c, "child").ok_or_else(|| {
                    xml.error(
                        xml.tag(c),
                        format!("{owner} is missing the required element `<child>`"),
                    )
                })?;
                let f = g.add(
                    Frame {
                        name: name.text,
                        kind: Kind::Joint,
                        element: c,
                        file,
                        scope: s,
                        default: Some(xml.text(kid)),
                        pose: child(c, "pose").map(|p| (p, file)),
                        placement: None,
                    },
                    s,
                );
                g.joints.push(f);
            }
            "frame" => {
                let name = xml.required(c, "name", &this)?;
                g.add(
                    Frame {
                        name: name.text,
                        kind: Kind::Frame,
                        element: c,
                        file,
                        scope: s,
                        default: xml.attr(c, "attached_to").filter(|v| !v.text.is_empty()),
                        pose: child(c, "pose").map(|p| (p, file)),
                        placement: None,
                    },
                    s,
                );
            }
            "model" | "include" => {
                let included = qname(c) == "include";
                // NOTE: an `<include>` straight under `<sdf>` (beside
                // several models) is no include of SDFormat's, and
                // `sdf_include` did not read it: passed over, as `check`
                // passes it.
                let target = files.targets.get(&(file, c.range().start));
                if included && target.is_none() {
                    continue;
                }
                let (element, mfile) = if let Some(&t) = target {
                    let root = docs[t].root_element();
                    let models: Vec<Node> = children(root, "model").collect();
                    let [m] = models.as_slice() else {
                        return Err(xml.error(
                            xml.tag(c),
                            format!(
                                "the included `{}` holds {} `<model>`s under `<sdf>`: an include names one model",
                                files.source(t).name,
                                models.len()
                            ),
                        ));
                    };
                    (*m, t)
                } else {
                    (c, file)
                };
                let mxml = &g.xmls[mfile];
                let name = match child(c, "name").filter(|_| included) {
                    Some(n) => xml.text(n),
                    None => mxml.required(element, "name", &scope_name(g, s))?,
                };
                let pose = match child(c, "pose").filter(|_| included) {
                    Some(p) => Some((p, file)),
                    None => child(element, "pose").map(|p| (p, mfile)),
                };
                let placement = match child(c, "placement_frame").filter(|_| included) {
                    Some(p) => Some((xml.text(p), file)),
                    None => mxml
                        .attr(element, "placement_frame")
                        .filter(|v| !v.text.is_empty())
                        .map(|v| (v, mfile)),
                };
                let stat = match child(c, "static") {
                    Some(v) => Some(sdf::flag(xml, &xml.text(v), &scope_name(g, s))?),
                    None => None,
                };
                let stat = match (stat, child(element, "static")) {
                    (Some(v), _) => v,
                    (None, Some(v)) => sdf::flag(mxml, &mxml.text(v), &scope_name(g, s))?,
                    (None, None) => false,
                };
                let depth = g.scopes[s].depth + 1;
                let path = join(&g.scopes[s].path, &name.text);
                if depth > MAX_NESTING {
                    return Err(xml.error(
                        xml.tag(c),
                        format!(
                            "model {} is nested {depth} models deep: the whole robot is composed of models nested at most {MAX_NESTING} deep",
                            quoted(&path)
                        ),
                    ));
                }
                if g.scopes.len() > MAX_MODELS {
                    return Err(xml.error(
                        xml.tag(c),
                        format!(
                            "model {} is one model more than {MAX_MODELS}, the most the whole robot is composed of (an include counts each time it is read)",
                            quoted(&path)
                        ),
                    ));
                }
                let anchor = g.scopes[s]
                    .anchor
                    .clone()
                    .or_else(|| included.then(|| c.range()));
                let m = g.scopes.len();
                let fixed = g.scopes[s].fixed || stat;
                let mut from = g.scopes[s].from.clone();
                if included && let Some(u) = child(c, "uri") {
                    let (line, col) = xml.source.line_col(xml.text(u).range.start);
                    from.insert(0, format!("{}:{line}:{col}", xml.source.name));
                }
                let f = g.add(
                    Frame {
                        name: name.text.clone(),
                        kind: Kind::Model(m),
                        element,
                        file: mfile,
                        scope: s,
                        default: None,
                        pose,
                        placement,
                    },
                    s,
                );
                g.scopes.push(Scope {
                    path,
                    frame: f,
                    own: name.text,
                    element,
                    file: mfile,
                    names: HashMap::new(),
                    shared: Vec::new(),
                    anchor,
                    from,
                    depth,
                    world: false,
                    fixed,
                });
                stack.push((m, element.children()));
            }
            _ => {}
        }
    }
    Ok(out)
}

/// The tree: each link's pose, the joints joining them, their followers.
fn build(g: &mut Graph, d: &Description) -> Result<Tree, Diagnostic> {
    let mut t = Tree {
        links: unplaced(d.links.len()),
        joints: Vec::new(),
    };
    // Each link's pose in the report frame.
    let mut world = vec![Pose::IDENTITY; d.links.len()];
    for (i, w) in world.iter_mut().enumerate() {
        *w = g.in_model(g.links[i])?;
    }
    let mut mimics = Vec::new();
    for jf in g.joints.clone() {
        let (j, file, s) = (g.frames[jf].element, g.frames[jf].file, g.frames[jf].scope);
        let xml = &g.xmls[file];
        let old = old_version(j);
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
            "`<model>`",
            &[
                ("revolute", Motion::Revolute),
                ("continuous", Motion::Revolute),
                ("prismatic", Motion::Prismatic),
                ("fixed", Motion::Fixed),
                ("ball", Motion::Stays),
            ],
            |e, _| Ok(xml.text(e)),
        )?;
        let c = g.end(s, file, &kid, &owner)?;
        if parent.text != "world" {
            let p = g.end(s, file, &parent, &owner)?;
            set_parent(xml, &mut t, c, p, &kid, &owner)?;
        }
        // The joint frame in the child link's.
        let joint_pose = world[c].inverse().then(&g.in_model(jf)?);
        let home = g.scopes[s].frame;
        let (axis_in_joint, lower, upper, expressed) = match child(j, "axis") {
            Some(a) => {
                let xyz = child(a, "xyz");
                let v = xyz
                    .map(|x| axis(xml, &xml.text(x), &owner))
                    .transpose()?
                    .unwrap_or([0.0, 0.0, 1.0]);
                let parent_model = child(a, "use_parent_model_frame")
                    .map(|u| sdf::flag(xml, &xml.text(u), &owner))
                    .transpose()?
                    .unwrap_or(false);
                // Where the axis is expressed: Some(k) frame k, None the
                // joint's own.
                let expressed = match xyz.and_then(|x| xml.attr(x, "expressed_in")) {
                    Some(e) if e.text.is_empty() || e.text == name.text => None,
                    Some(e) => Some(g.named(s, file, &e, &owner)?),
                    None if old && parent_model => Some(home),
                    None => None,
                };
                let lim = child(a, "limit");
                let bound = |n: &str| -> Result<Option<f64>, Diagnostic> {
                    lim.and_then(|l| child(l, n))
                        .map(|e| xml.number(&xml.text(e), &owner))
                        .transpose()
                };
                if let Some(m) = child(a, "mimic") {
                    mimics.push(mimic(xml, m, t.joints.len(), s, file, &owner)?);
                }
                (v, bound("lower")?, bound("upper")?, expressed)
            }
            None => ([0.0, 0.0, 1.0], None, None, None),
        };
        // The axis in the child's frame: turned by the joint's pose, or
        // from the frame it is expressed in (in the report frame) by the
        // child's.
        let axis = match expressed {
            None => {
                let r = joint_pose.r;
                std::array::from_fn(|i| (0..3).map(|k| r[i][k] * axis_in_joint[k]).sum())
            }
            Some(frame) => {
                let e = g.in_model(frame)?.r;
                let in_model: [f64; 3] =
                    std::array::from_fn(|i| (0..3).map(|k| e[i][k] * axis_in_joint[k]).sum());
                let r = world[c].r;
                std::array::from_fn(|i| (0..3).map(|k| r[k][i] * in_model[k]).sum())
            }
        };
        // NOTE: a joint from `world` moves its child too (the child is a
        // root, placed in the model frame): Drake and Gazebo turn it, and
        // it was dropped here (found by tests/oracle/drake_body_oracle.py).
        // One joint per child, whichever its parent.
        if !t.links[c].joints.is_empty() {
            return Err(xml.error(
                kid.range.clone(),
                format!(
                    "{} of {owner}: the link already has a parent joint",
                    kid.name
                ),
            ));
        }
        t.links[c].joints.push(t.joints.len());
        let limits = match (motion, kind.text.as_str()) {
            (Motion::Revolute, "continuous") => None,
            (Motion::Revolute | Motion::Prismatic, _) => limits(lower, upper),
            _ => None,
        };
        t.joints.push(Joint {
            name: g.shown(s, &name.text),
            motion,
            axis,
            anchor: joint_pose.p,
            zero: 0.0,
            limits,
            follows: None,
            range: g.scopes[s].anchor.clone().unwrap_or(j.range()),
        });
    }
    for m in mimics {
        let owner = format!(
            "the `<mimic>` of joint {}",
            quoted(&t.joints[m.follower].name)
        );
        let leader = Value {
            text: g.shown(m.scope, &m.leader.text),
            ..m.leader
        };
        let l = joint_named(&g.xmls[m.file], &t, &leader, &owner)?;
        // NOTE: multiplier·(x − reference) + offset, as the polynomial
        // c₀ + c₁x that `Follow` holds (every SDFormat joint's zero is 0).
        t.joints[m.follower].follows = Some(Follow {
            leader: Some(l),
            coef: [
                m.offset - m.multiplier * m.reference,
                m.multiplier,
                0.0,
                0.0,
                0.0,
            ],
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

/// Whether the file of `node` is SDFormat older than 1.7 (where
/// `use_parent_model_frame` still counts).
fn old_version(node: Node) -> bool {
    let v = node.document().root_element().attribute("version");
    v.is_some_and(|v| v.starts_with("1."))
        && v.and_then(|v| v.split('.').nth(1)?.parse::<u32>().ok())
            .is_some_and(|minor| minor < 7)
}

/// A `<mimic>` element of joint `follower`'s `<axis>`.
fn mimic(
    xml: &Xml,
    m: Node,
    follower: usize,
    scope: usize,
    file: usize,
    owner: &str,
) -> Result<Mimic, Diagnostic> {
    let owner = format!("the `<mimic>` of {owner}");
    let leader = xml.required(m, "joint", &owner)?;
    if let Some(a) = xml.attr(m, "axis") {
        match a.text.as_str() {
            "axis" => {}
            "axis2" => {
                return Err(xml.error(
                    a.range.clone(),
                    format!("`axis` of {owner}: `axis2` is the second axis of a joint with two, and no joint read for the whole robot has one"),
                ));
            }
            other => {
                return Err(xml.error(
                    a.range.clone(),
                    format!(
                        "`axis` of {owner}: expected `axis` or `axis2`, found {}",
                        quoted(other)
                    ),
                ));
            }
        }
    }
    let number = |n: &str, default: f64| -> Result<f64, Diagnostic> {
        child(m, n).map_or(Ok(default), |e| xml.number(&xml.text(e), &owner))
    };
    Ok(Mimic {
        follower,
        leader,
        scope,
        file,
        // sdf/1.11/mimic.sdf: multiplier 1, offset 0, reference 0.
        multiplier: number("multiplier", 1.0)?,
        offset: number("offset", 0.0)?,
        reference: number("reference", 0.0)?,
    })
}
