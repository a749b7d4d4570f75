//! The frame graph of an SDFormat robot read whole (`sdf_tree` builds
//! it): every link, joint, `<frame>` and model of every scope, each placed
//! in the report frame on demand, names looked up scope by scope
//! (SDFormat 1.8 "Model composition": `a::b` is `b` in the nested model
//! `a`, `__model__` the scope's model frame), and the link each frame is
//! attached to (a frame's `attached_to`, a joint's child, a model's
//! canonical link).

use super::{Value, Xml, quoted, sdf};
use crate::diag::Diagnostic;
use crate::robot::kinematics::Pose;
use roxmltree::Node;
use std::collections::HashMap;
use std::ops::Range;

/// How deep models may nest (inline or included) for the whole robot.
pub(super) const MAX_NESTING: usize = 64;
/// How many models (nested and included, each time it is included) the
/// whole robot may hold.
pub(super) const MAX_MODELS: usize = 10_000;

#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// The report frame: the top model's, or the world's.
    Top,
    /// Link `k` of the description.
    Link(usize),
    Joint,
    Frame,
    /// A nested or included model, whose scope is the one given.
    Model(usize),
}

/// A frame of some scope: a link, a joint, a `<frame>` or a model.
pub(super) struct Frame<'a, 'i> {
    pub(super) name: String,
    pub(super) kind: Kind,
    pub(super) element: Node<'a, 'i>,
    /// The file `element` and `default` are in.
    pub(super) file: usize,
    /// The scope its names are looked up in (a model's: its parent's).
    pub(super) scope: usize,
    /// The frame its pose is in when its `<pose>` names none: None is the
    /// scope's model frame.
    pub(super) default: Option<Value>,
    /// Its `<pose>` and the file that writes it (an include's own, else
    /// the included model's).
    pub(super) pose: Option<(Node<'a, 'i>, usize)>,
    /// A model's `placement_frame`, in its own scope, and its file.
    pub(super) placement: Option<(Value, usize)>,
}

/// A model's (or the world's) namespace.
pub(super) struct Scope<'a, 'i> {
    /// Its path from the top scope (`""` there).
    pub(super) path: String,
    /// Its model frame.
    pub(super) frame: usize,
    /// Its model's own name, which names its model frame.
    pub(super) own: String,
    pub(super) element: Node<'a, 'i>,
    pub(super) file: usize,
    pub(super) names: HashMap<String, usize>,
    pub(super) shared: Vec<String>,
    /// Within an include: the top file's outermost `<include>`, which
    /// messages about its links and joints point at.
    pub(super) anchor: Option<Range<usize>>,
    /// The `<include>`s that bring it in, innermost first: `FILE:LINE:COL`
    /// of each one's `<uri>` (`Site::from`).
    pub(super) from: Vec<String>,
    pub(super) depth: usize,
    pub(super) world: bool,
    pub(super) fixed: bool,
}

/// Every frame of the whole robot.
pub(super) struct Graph<'a, 'i, 'x> {
    pub(super) xmls: &'x [Xml<'x>],
    pub(super) frames: Vec<Frame<'a, 'i>>,
    pub(super) scopes: Vec<Scope<'a, 'i>>,
    pub(super) placed: Vec<Option<Pose>>,
    /// Each link's frame, in the description's order.
    pub(super) links: Vec<usize>,
    pub(super) joints: Vec<usize>,
    /// Whether the outermost model's name is left out of paths.
    pub(super) strip: bool,
}

impl<'a, 'i> Graph<'a, 'i, '_> {
    pub(super) fn add(&mut self, f: Frame<'a, 'i>, scope: usize) -> usize {
        let k = self.frames.len();
        let s = &mut self.scopes[scope];
        if s.names.contains_key(&f.name) {
            s.shared.push(f.name.clone());
        } else {
            s.names.insert(f.name.clone(), k);
        }
        self.frames.push(f);
        self.placed.push(None);
        k
    }

    /// A path from the top as messages and `--only` name it.
    pub(super) fn shown(&self, scope: usize, name: &str) -> String {
        let full = join(&self.scopes[scope].path, name);
        if self.strip {
            full.split_once("::")
                .map_or(full.clone(), |(_, r)| r.to_string())
        } else {
            full
        }
    }

    /// The frame `v` (written in file `file`) names in `scope`, or an
    /// error at it.
    pub(super) fn named(
        &self,
        scope: usize,
        file: usize,
        v: &Value,
        owner: &str,
    ) -> Result<usize, Diagnostic> {
        let xml = &self.xmls[file];
        let mut s = scope;
        let mut rest = v.text.as_str();
        loop {
            let sc = &self.scopes[s];
            if rest.is_empty() || rest == "__model__" || rest == sc.own {
                return Ok(sc.frame);
            }
            if sc.world && rest == "world" {
                return Ok(sc.frame);
            }
            if sc.shared.iter().any(|n| n == rest) {
                return Err(xml.error(
                    v.range.clone(),
                    format!(
                        "{} of {owner} names {}, which two frames (links, joints or `<frame>`s) share: the frame is ambiguous",
                        v.name,
                        quoted(&v.text)
                    ),
                ));
            }
            if let Some(&k) = sc.names.get(rest) {
                return Ok(k);
            }
            // `a::b`: `b` in the nested model `a`.
            if let Some((head, _)) = rest.split_once("::")
                && sc.shared.iter().any(|n| n == head)
            {
                return Err(xml.error(
                    v.range.clone(),
                    format!(
                        "{} of {owner} names {}, in {}, which two frames (links, joints, `<frame>`s or models) share: the frame is ambiguous",
                        v.name,
                        quoted(&v.text),
                        quoted(head)
                    ),
                ));
            }
            let inner = rest.split_once("::").and_then(|(head, tail)| {
                match self.frames[*sc.names.get(head)?].kind {
                    Kind::Model(m) => Some((m, tail)),
                    Kind::Top | Kind::Link(_) | Kind::Joint | Kind::Frame => None,
                }
            });
            match inner {
                Some((m, tail)) => (s, rest) = (m, tail),
                None => {
                    let near = crate::units::suggest(
                        rest,
                        sc.names.keys().map(String::as_str).chain(["__model__"]),
                    )
                    .map(|s| format!("; did you mean {}?", quoted(s)))
                    .unwrap_or_default();
                    return Err(xml.error(
                        v.range.clone(),
                        format!(
                            "{} of {owner} names no frame of the model: {}{near}",
                            v.name,
                            quoted(&v.text)
                        ),
                    ));
                }
            }
        }
    }

    pub(super) fn owner(&self, k: usize) -> String {
        let f = &self.frames[k];
        let kind = match f.kind {
            Kind::Top | Kind::Model(_) => "model",
            Kind::Link(_) => "link",
            Kind::Joint => "joint",
            Kind::Frame => "frame",
        };
        let scope = match f.kind {
            Kind::Model(m) => self.scopes[m].path.clone(),
            _ => self.shown(f.scope, &f.name),
        };
        format!("{kind} {}", quoted(&scope))
    }

    /// The frame frame `k`'s pose is in, and the pose as written there.
    pub(super) fn local(&self, k: usize) -> Result<(usize, Pose), Diagnostic> {
        let f = &self.frames[k];
        let owner = self.owner(k);
        let home = self.scopes[f.scope].frame;
        let default = match &f.default {
            Some(v) => self.named(f.scope, f.file, v, &owner)?,
            None => home,
        };
        let mut pose = Pose::IDENTITY;
        let mut base = default;
        if let Some((p, file)) = f.pose {
            let xml = &self.xmls[file];
            let relative = match xml.attr(p, "relative_to").filter(|v| !v.text.is_empty()) {
                Some(v) => {
                    base = self.named(f.scope, file, &v, &owner)?;
                    v.text
                }
                None => String::new(),
            };
            // `sdf::pose` reads the numbers; `relative_to` is resolved here.
            let (pos, r) = sdf::pose(xml, p, &relative, &owner)?;
            pose = Pose {
                p: pos,
                r: r.unwrap_or(Pose::IDENTITY.r),
            };
        }
        if let (Kind::Model(m), Some((v, file))) = (f.kind, &f.placement) {
            // The pose places the placement frame: the model frame is
            // that pose after the placement frame's pose in it, inverted.
            let target = self.named(m, *file, v, &format!("the `placement_frame` of {owner}"))?;
            pose = pose.then(&self.within(target, k, v, *file)?.inverse());
        }
        Ok((base, pose))
    }

    /// Frame `target`'s pose in frame `stop`, which its chain of frames
    /// reaches (a model's frames are all placed, at last, in its frame).
    pub(super) fn within(
        &self,
        target: usize,
        stop: usize,
        v: &Value,
        file: usize,
    ) -> Result<Pose, Diagnostic> {
        let mut at = target;
        let mut acc = Pose::IDENTITY;
        for _ in 0..=self.frames.len() {
            if at == stop {
                return Ok(acc);
            }
            let (up, pose) = self.local(at)?;
            acc = pose.then(&acc);
            at = up;
        }
        Err(self.xmls[file].error(
            v.range.clone(),
            format!(
                "`placement_frame` {}: its pose is relative to frames in a cycle",
                quoted(&v.text)
            ),
        ))
    }

    /// Frame `k`'s pose in the report frame: up the chain of frames each
    /// is relative to, then down again (no recursion: a chain may be
    /// long), a cycle refused at the `relative_to` that closes it.
    pub(super) fn in_model(&mut self, k: usize) -> Result<Pose, Diagnostic> {
        let mut chain: Vec<(usize, Pose)> = Vec::new();
        let mut at = k;
        let base;
        loop {
            if let Some(p) = self.placed[at] {
                base = p;
                break;
            }
            if let Some(i) = chain.iter().position(|(f, _)| *f == at) {
                let names: Vec<String> = chain[i..]
                    .iter()
                    .map(|(f, _)| quoted(&self.frames[*f].name))
                    .chain([quoted(&self.frames[at].name)])
                    .collect();
                let f = &self.frames[at];
                let (xml, v) = match f.pose.and_then(|(p, file)| {
                    let v = self.xmls[file]
                        .attr(p, "relative_to")
                        .filter(|v| !v.text.is_empty())?;
                    Some((&self.xmls[file], v.range))
                }) {
                    Some(found) => found,
                    None => {
                        let xml = &self.xmls[f.file];
                        let r = xml
                            .attr(f.element, "attached_to")
                            .map_or_else(|| xml.tag(f.element), |v| v.range);
                        (xml, r)
                    }
                };
                return Err(xml
                    .error(
                        v,
                        format!(
                            "the pose of {} is relative to frames in a cycle: {}",
                            self.owner(at),
                            names.join(" → ")
                        ),
                    )
                    .help("place one of them relative to the model frame (`__model__`) or a link outside the cycle"));
            }
            let (up, pose) = self.local(at)?;
            chain.push((at, pose));
            at = up;
        }
        let mut base = base;
        for (c, pose) in chain.into_iter().rev() {
            base = base.then(&pose);
            self.placed[c] = Some(base);
        }
        Ok(base)
    }

    /// The link frame `k` is attached to (a joint: its child's; a frame:
    /// its `attached_to`'s; a model: its canonical link's), or an error at
    /// `v`, which names `k`.
    pub(super) fn body(
        &self,
        k: usize,
        v: &Value,
        file: usize,
        owner: &str,
    ) -> Result<usize, Diagnostic> {
        let mut at = k;
        for _ in 0..=self.frames.len() {
            let f = &self.frames[at];
            at = match f.kind {
                Kind::Link(l) => return Ok(l),
                Kind::Joint | Kind::Frame => match &f.default {
                    Some(d) => self.named(f.scope, f.file, d, &self.owner(at))?,
                    None => self.scopes[f.scope].frame,
                },
                Kind::Model(m) => self.canonical(m)?,
                // The top model's frame is attached to its canonical link
                // too; a world's frame to none.
                Kind::Top if !self.scopes[0].world => self.canonical(0)?,
                Kind::Top => {
                    return Err(self.xmls[file].error(
                        v.range.clone(),
                        format!(
                            "{} of {owner} names {}, the report frame, which no link is attached to",
                            v.name,
                            quoted(&v.text)
                        ),
                    ));
                }
            };
        }
        Err(self.xmls[file].error(
            v.range.clone(),
            format!(
                "{} of {owner} names {}, which is attached to frames in a cycle",
                v.name,
                quoted(&v.text)
            ),
        ))
    }

    /// Model `m`'s canonical frame: `canonical_link`, else its first
    /// link, else its first nested model.
    pub(super) fn canonical(&self, m: usize) -> Result<usize, Diagnostic> {
        let s = &self.scopes[m];
        let xml = &self.xmls[s.file];
        let this = self.owner(s.frame);
        if let Some(v) = xml
            .attr(s.element, "canonical_link")
            .filter(|v| !v.text.is_empty())
        {
            let k = self.named(m, s.file, &v, &this)?;
            return match self.frames[k].kind {
                Kind::Link(_) => Ok(k),
                Kind::Top | Kind::Model(_) | Kind::Joint | Kind::Frame => Err(xml.error(
                    v.range.clone(),
                    format!(
                        "`canonical_link` of {this} names {}, which is not a link",
                        quoted(&v.text)
                    ),
                )),
            };
        }
        // NOTE: the scope's own names, not every frame: a joint asks for
        // it, and a robot may hold thousands of models.
        let first = |want: fn(Kind) -> bool| {
            s.names
                .values()
                .copied()
                .filter(|&k| want(self.frames[k].kind))
                .min()
        };
        first(|k| matches!(k, Kind::Link(_)))
            .or_else(|| first(|k| matches!(k, Kind::Model(_))))
            .ok_or_else(|| {
                xml.error(
                    xml.tag(s.element),
                    format!("{this} has no link, nor a nested model with one: it has no canonical link for a joint or a frame to be attached to"),
                )
            })
    }
}

/// `scope::name`, or `name` at the top.
pub(super) fn join(scope: &str, name: &str) -> String {
    if scope.is_empty() {
        name.to_string()
    } else {
        format!("{scope}::{name}")
    }
}

impl Graph<'_, '_, '_> {
    /// The link a joint's `<parent>` or `<child>` `v` is attached to.
    pub(super) fn end(
        &self,
        s: usize,
        file: usize,
        v: &Value,
        owner: &str,
    ) -> Result<usize, Diagnostic> {
        let sc = &self.scopes[s];
        let known = !v.text.is_empty()
            && (sc.names.contains_key(&v.text)
                || v.text.contains("::")
                || v.text == "__model__"
                || sc.shared.contains(&v.text));
        if !known {
            // As `links::link_named` says it: the scope's links nearest.
            let links = sc
                .names
                .iter()
                .filter(|(_, k)| matches!(self.frames[**k].kind, Kind::Link(_)))
                .map(|(n, _)| n.as_str());
            let near = crate::units::suggest(&v.text, links)
                .map(|s| format!("; did you mean {}?", quoted(s)))
                .unwrap_or_default();
            return Err(self.xmls[file].error(
                v.range.clone(),
                format!(
                    "{} of {owner} names no link: {}{near}",
                    v.name,
                    quoted(&v.text)
                ),
            ));
        }
        let k = self.named(s, file, v, owner)?;
        self.body(k, v, file, owner)
    }
}
