//! What the kinematic-tree readers (`tree`, `sdf_tree`) share: a joint's
//! head (name, type, parent and child), links and joints found by name
//! (with the nearest name when none is), a child given its parent once and
//! without a loop, a unit axis, the unplaced links.

use super::{Value, Xml, child, quoted};
use crate::diag::Diagnostic;
use crate::robot::Description;
use crate::robot::kinematics::{Motion, Node as TreeNode, Pose, Tree};
use roxmltree::Node;
use std::collections::HashMap;

/// A unit axis from `v` (three numbers, not all zero).
pub(super) fn axis(xml: &Xml, v: &Value, owner: &str) -> Result<[f64; 3], Diagnostic> {
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
pub(super) fn names<'d>(
    xml: &Xml,
    d: &'d Description,
) -> Result<HashMap<&'d str, usize>, Diagnostic> {
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
pub(super) fn link_named(
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
pub(super) fn set_parent(
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

pub(super) fn unplaced(n: usize) -> Vec<TreeNode> {
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
pub(super) fn limits(lower: Option<f64>, upper: Option<f64>) -> Option<(f64, f64)> {
    Some((lower?, upper?))
}

/// The joint `v` names, or an error with the nearest name.
pub(super) fn joint_named(
    xml: &Xml,
    t: &Tree,
    v: &Value,
    owner: &str,
) -> Result<usize, Diagnostic> {
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

/// A joint's name, its `type` (one of `kinds`), and its `<parent>` and
/// `<child>` as `end` reads them: what the URDF and SDFormat readers
/// share, with the same messages.
pub(super) struct Head {
    pub name: Value,
    /// `joint "NAME"`, for messages.
    pub owner: String,
    pub kind: Value,
    pub motion: Motion,
    pub parent: Value,
    pub child: Value,
}

/// Read a joint's `Head`; `within` names the element that holds joints
/// (`` `<robot>` ``, `` `<model>` ``).
pub(super) fn joint_head(
    xml: &Xml,
    j: Node,
    within: &str,
    kinds: &[(&str, Motion)],
    end: impl Fn(Node, &str) -> Result<Value, Diagnostic>,
) -> Result<Head, Diagnostic> {
    let name = xml.required(j, "name", within)?;
    let owner = format!("joint {}", quoted(&name.text));
    let kind = xml.required(j, "type", &owner)?;
    let motion = xml.keyword(&kind, &owner, kinds)?;
    let element = |tag: &str| -> Result<Value, Diagnostic> {
        let e = child(j, tag).ok_or_else(|| {
            xml.error(
                xml.tag(j),
                format!("{owner} is missing the required element `<{tag}>`"),
            )
        })?;
        end(e, &owner)
    };
    let (parent, child) = (element("parent")?, element("child")?);
    Ok(Head {
        name,
        owner,
        kind,
        motion,
        parent,
        child,
    })
}
