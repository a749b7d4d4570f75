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
//! Refused with their place: worlds, nested models and includes; a
//! `relative_to` or `attached_to` naming no frame; frames placed relative
//! to each other in a cycle.

use super::links::{axis, joint_named, limits, link_named, names, set_parent, unplaced};
use super::{Value, Xml, child, children, qname, quoted, sdf};
use crate::diag::Diagnostic;
use crate::robot::Description;
use crate::robot::kinematics::{Follow, Joint, Motion, Pose, Tree};
use roxmltree::Node;
use std::collections::HashMap;

/// A frame of the model's scope: a link, a joint or a `<frame>`.
struct Frame<'a, 'i> {
    name: String,
    /// "link", "joint" or "frame", for messages.
    kind: &'static str,
    element: Node<'a, 'i>,
    /// The frame its pose is in when its `<pose>` names none: None is the
    /// model frame.
    default: Option<Value>,
}

/// The frames of a model, each placed in the model frame once asked.
struct Frames<'a, 'i> {
    frames: Vec<Frame<'a, 'i>>,
    by_name: HashMap<String, usize>,
    /// Names two frames share: naming one is ambiguous.
    shared: Vec<String>,
    /// Names that are the model frame: `__model__`, and the model's own.
    model: [String; 2],
    placed: Vec<Option<Pose>>,
}

impl<'a, 'i> Frames<'a, 'i> {
    fn new(model: Node<'a, 'i>) -> Frames<'a, 'i> {
        Frames {
            frames: Vec::new(),
            by_name: HashMap::new(),
            shared: Vec::new(),
            model: [
                "__model__".to_string(),
                model.attribute("name").unwrap_or("__model__").to_string(),
            ],
            placed: Vec::new(),
        }
    }

    fn add(&mut self, f: Frame<'a, 'i>) -> usize {
        let k = self.frames.len();
        if self.by_name.contains_key(&f.name) {
            self.shared.push(f.name.clone());
        } else {
            self.by_name.insert(f.name.clone(), k);
        }
        self.frames.push(f);
        self.placed.push(None);
        k
    }

    /// The frame `v` names (None: the model frame), or an error at it.
    fn named(&self, xml: &Xml, v: &Value, owner: &str) -> Result<Option<usize>, Diagnostic> {
        if v.text.is_empty() || self.model.contains(&v.text) {
            return Ok(None);
        }
        if self.shared.contains(&v.text) {
            return Err(xml.error(
                v.range.clone(),
                format!(
                    "{} of {owner} names {}, which two frames (links, joints or `<frame>`s) share: the frame is ambiguous",
                    v.name,
                    quoted(&v.text)
                ),
            ));
        }
        match self.by_name.get(&v.text) {
            Some(&k) => Ok(Some(k)),
            None => {
                let near = crate::units::suggest(
                    &v.text,
                    self.by_name.keys().map(String::as_str).chain(["__model__"]),
                )
                .map(|s| format!("; did you mean {}?", quoted(s)))
                .unwrap_or_default();
                Err(xml.error(
                    v.range.clone(),
                    format!(
                        "{} of {owner} names no frame of the model: {}{near}",
                        v.name,
                        quoted(&v.text)
                    ),
                ))
            }
        }
    }

    fn owner(&self, k: usize) -> String {
        let f = &self.frames[k];
        format!("{} {}", f.kind, quoted(&f.name))
    }

    /// The frame frame `k`'s pose is in (None: the model's), and the pose
    /// as written there.
    fn local(&self, xml: &Xml, k: usize) -> Result<(Option<usize>, Pose), Diagnostic> {
        let f = &self.frames[k];
        let owner = self.owner(k);
        let Some(p) = child(f.element, "pose") else {
            let base = match &f.default {
                Some(v) => self.named(xml, v, &owner)?,
                None => None,
            };
            return Ok((base, Pose::IDENTITY));
        };
        let (base, relative) = match xml.attr(p, "relative_to").filter(|v| !v.text.is_empty()) {
            Some(v) => (self.named(xml, &v, &owner)?, v.text),
            None => (
                match &f.default {
                    Some(v) => self.named(xml, v, &owner)?,
                    None => None,
                },
                String::new(),
            ),
        };
        // `sdf::pose` reads the numbers; `relative_to` is resolved here.
        let (pos, r) = sdf::pose(xml, p, &relative, &owner)?;
        Ok((
            base,
            Pose {
                p: pos,
                r: r.unwrap_or(Pose::IDENTITY.r),
            },
        ))
    }

    /// Frame `k`'s pose in the model frame: up the chain of frames each is
    /// relative to, then down again (no recursion: a chain may be long),
    /// a cycle refused at the `relative_to` that closes it.
    fn in_model(&mut self, xml: &Xml, k: usize) -> Result<Pose, Diagnostic> {
        let mut chain: Vec<(usize, Pose)> = Vec::new();
        let mut at = Some(k);
        let mut base = Pose::IDENTITY;
        while let Some(c) = at {
            if let Some(p) = self.placed[c] {
                base = p;
                break;
            }
            if let Some(i) = chain.iter().position(|(f, _)| *f == c) {
                let names: Vec<String> = chain[i..]
                    .iter()
                    .map(|(f, _)| quoted(&self.frames[*f].name))
                    .chain([quoted(&self.frames[c].name)])
                    .collect();
                let start = self.frames[c].element;
                let v = child(start, "pose")
                    .and_then(|p| xml.attr(p, "relative_to"))
                    .filter(|v| !v.text.is_empty())
                    .or_else(|| xml.attr(start, "attached_to"))
                    .map_or_else(|| xml.tag(start), |v| v.range);
                return Err(xml
                    .error(
                        v,
                        format!(
                            "the pose of {} is relative to frames in a cycle: {}",
                            self.owner(c),
                            names.join(" → ")
                        ),
                    )
                    .help("place one of them relative to the model frame (`__model__`) or a link outside the cycle"));
            }
            let (up, pose) = self.local(xml, c)?;
            chain.push((c, pose));
            at = up;
        }
        for (c, pose) in chain.into_iter().rev() {
            base = base.then(&pose);
            self.placed[c] = Some(base);
        }
        Ok(base)
    }
}

/// A joint's `<mimic>` waiting for every joint to be read: the follower,
/// its leader's name, multiplier, offset and reference.
struct Mimic {
    follower: usize,
    leader: Value,
    multiplier: f64,
    offset: f64,
    reference: f64,
}

/// The model's links and joints, `d`'s links in the same order.
pub(super) fn sdformat(xml: &Xml, sdf_node: Node, d: &Description) -> Result<Tree, Diagnostic> {
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
                    "`<{}>` here: the whole robot is composed from one `<model>` of links, joints and frames, without worlds, nested models or includes",
                    qname(n)
                ),
            )
            .help("`check` reads every link of such a file; compose one model at a time"));
    }
    let Some(&model) = models.first() else {
        return Ok(Tree::default());
    };
    let names = names(xml, d)?;
    let mut t = Tree {
        links: unplaced(d.links.len()),
        joints: Vec::new(),
    };
    let model_name = model.attribute("name").unwrap_or_default();
    let mut frames = Frames::new(model);
    for (i, l) in children(model, "link").enumerate() {
        frames.add(Frame {
            name: d.links[i].name.clone(),
            kind: "link",
            element: l,
            default: None,
        });
    }
    let joints: Vec<Node> = children(model, "joint").collect();
    let mut joint_frame = Vec::with_capacity(joints.len());
    for &j in &joints {
        let name = xml.required(j, "name", "`<model>`")?;
        let owner = format!("joint {}", quoted(&name.text));
        let kid = child(j, "child").ok_or_else(|| {
            xml.error(
                xml.tag(j),
                format!("{owner} is missing the required element `<child>`"),
            )
        })?;
        joint_frame.push(frames.add(Frame {
            name: name.text.clone(),
            kind: "joint",
            element: j,
            default: Some(xml.text(kid)),
        }));
    }
    for f in children(model, "frame") {
        let name = xml.required(f, "name", "`<model>`")?;
        frames.add(Frame {
            name: name.text.clone(),
            kind: "frame",
            element: f,
            default: xml.attr(f, "attached_to").filter(|v| !v.text.is_empty()),
        });
    }
    // Each link's pose in the model frame.
    let mut world = vec![Pose::IDENTITY; d.links.len()];
    for (i, w) in world.iter_mut().enumerate() {
        *w = frames.in_model(xml, i)?;
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
    let mut mimics = Vec::new();
    for (&j, &jf) in joints.iter().zip(&joint_frame) {
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
        // The joint frame in the child link's.
        let joint_pose = world[c].inverse().then(&frames.in_model(xml, jf)?);
        let ax = child(j, "axis");
        let (axis_in_joint, lower, upper, expressed) = match ax {
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
                // Where the axis is expressed: Some(None) the model frame,
                // Some(Some(k)) frame k, None the joint's own.
                let expressed = match xyz.and_then(|x| xml.attr(x, "expressed_in")) {
                    Some(e) if e.text.is_empty() || e.text == name.text => None,
                    Some(e) if e.text == "__model__" || e.text == model_name => Some(None),
                    Some(e) => Some(frames.named(xml, &e, &owner)?),
                    None if old && parent_model => Some(None),
                    None => None,
                };
                let lim = child(a, "limit");
                let bound = |n: &str| -> Result<Option<f64>, Diagnostic> {
                    lim.and_then(|l| child(l, n))
                        .map(|e| xml.number(&xml.text(e), &owner))
                        .transpose()
                };
                if let Some(m) = child(a, "mimic") {
                    mimics.push(mimic(xml, m, t.joints.len(), &owner)?);
                }
                (v, bound("lower")?, bound("upper")?, expressed)
            }
            None => ([0.0, 0.0, 1.0], None, None, None),
        };
        // The axis in the child's frame: turned by the joint's pose, or
        // from the frame it is expressed in (in the model frame) by the
        // child's.
        let axis = match expressed {
            None => {
                let r = joint_pose.r;
                std::array::from_fn(|i| (0..3).map(|k| r[i][k] * axis_in_joint[k]).sum())
            }
            Some(frame) => {
                let e = match frame {
                    Some(k) => frames.in_model(xml, k)?.r,
                    None => Pose::IDENTITY.r,
                };
                let in_model: [f64; 3] =
                    std::array::from_fn(|i| (0..3).map(|k| e[i][k] * axis_in_joint[k]).sum());
                let r = world[c].r;
                std::array::from_fn(|i| (0..3).map(|k| r[k][i] * in_model[k]).sum())
            }
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
    for m in mimics {
        let owner = format!(
            "the `<mimic>` of joint {}",
            quoted(&t.joints[m.follower].name)
        );
        let l = joint_named(xml, &t, &m.leader, &owner)?;
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

/// A `<mimic>` element of joint `follower`'s `<axis>`.
fn mimic(xml: &Xml, m: Node, follower: usize, owner: &str) -> Result<Mimic, Diagnostic> {
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
        // sdf/1.11/mimic.sdf: multiplier 1, offset 0, reference 0.
        multiplier: number("multiplier", 1.0)?,
        offset: number("offset", 0.0)?,
        reference: number("reference", 0.0)?,
    })
}
