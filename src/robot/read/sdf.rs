//! SDFormat: every `<link>` of the file's models (`<sdf><model>`,
//! `<sdf><world><model>`, and models nested in them) with its `<inertial>`
//! (`<pose>`, `<mass>`, `<inertia><ixx>…</inertia>`, each with the spec's
//! default when absent), and which links move: the child of a joint that is
//! not `fixed`, or a link of a model that is not static and is the child of
//! no joint, which floats freely.
//!
//! Names are scoped as SDFormat scopes them: a link of a nested model is
//! `nested::link`, relative to the outermost model, whose own name is left
//! out unless the file has several top-level models.

use super::{Value, Xml, child, proper, qname, quoted, rpy, turn};
use crate::diag::Diagnostic;
use crate::numeric::M3;
use crate::robot::{Description, Dialect, Inertial, Link, MujocoCompiler, Tensor, Written};
use crate::rotation::{quaternion, sin_cos_deg};
use roxmltree::Node;
use std::collections::HashMap;

/// How deep a joint's child may lead through frames and models' canonical
/// links before it is taken as unresolved (a cycle, say).
const MAX_HOPS: usize = 32;

pub(super) fn read(xml: &Xml, sdf: Node) -> Result<Description, Diagnostic> {
    // Each world is a namespace of its own; so are the models written
    // straight under `<sdf>`.
    let mut scopes = vec![Scope::new(sdf)];
    scopes.extend(elements(sdf).filter(|c| is(c, "world")).map(Scope::new));
    // A world's includes are top-level models too (the whole robot reads
    // them, `sdf_tree`): names are prefixed as it prefixes them.
    let top_level: Vec<Node> = scopes
        .iter()
        .flat_map(|s| {
            let world = is(&s.node, "world");
            elements(s.node).filter(move |c| is(c, "model") || world && is(c, "include"))
        })
        .collect();
    let mut found = Vec::new();
    for scope in &mut scopes {
        scope.walk(xml)?;
        found.extend(scope.moving());
    }
    // Links in document order, whatever scope they were found in.
    found.sort_by_key(|(f, _)| f.node.range().start);
    let prefixed = top_level.len() > 1;
    let mut links = Vec::new();
    for (f, moving) in found {
        let name = if prefixed {
            f.path.clone()
        } else {
            // The outermost model's name left out: `model::link` → `link`.
            f.path
                .split_once("::")
                .map_or(f.path.clone(), |(_, rest)| rest.to_string())
        };
        let owner = format!("link {}", quoted(&name));
        let local = f.node.attribute("name").unwrap_or_default();
        let inertial = match child(f.node, "inertial") {
            Some(i) => inertial(xml, i, local, &owner)?,
            None => None,
        };
        links.push(Link {
            name,
            range: f.node.range(),
            site: crate::robot::Site::main(
                f.node.range(),
                inertial.as_ref().map(|i| i.range.clone()),
            ),
            inertial,
            moving,
            parent: None,
        });
    }
    let name = match top_level.as_slice() {
        [one] if is(one, "model") => one.attribute("name"),
        _ => elements(sdf)
            .find(|c| is(c, "world"))
            .and_then(|w| w.attribute("name")),
    };
    Ok(Description {
        format: Dialect::Sdf,
        name: name.map(str::to_string),
        links,
        compiler: MujocoCompiler::default(),
        files: Default::default(),
    })
}

fn elements<'a, 'i>(node: Node<'a, 'i>) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children().filter(Node::is_element)
}

fn is(node: &Node, name: &str) -> bool {
    qname(*node) == name
}

/// `scope::name`, or `name` at the top.
fn join(scope: &str, name: &str) -> String {
    if scope.is_empty() {
        name.to_string()
    } else {
        format!("{scope}::{name}")
    }
}

/// A link found: its element, its path from its world, and whether a model
/// around it is static.
struct Found<'a, 'i> {
    node: Node<'a, 'i>,
    path: String,
    fixed_model: bool,
}

/// A joint found: the model it is in (its names are relative to it), its
/// `<child>`, and whether it is `fixed`.
struct Joint {
    scope: String,
    child: String,
    fixed: bool,
}

/// One namespace (a world, or `<sdf>` itself) and everything named in it.
struct Scope<'a, 'i> {
    node: Node<'a, 'i>,
    found: Vec<Found<'a, 'i>>,
    joints: Vec<Joint>,
    /// Path → index in `found`.
    links: HashMap<String, usize>,
    models: HashMap<String, Node<'a, 'i>>,
    /// Path → (the path of the model it is in, `attached_to`).
    frames: HashMap<String, (String, String)>,
}

impl<'a, 'i> Scope<'a, 'i> {
    fn new(node: Node<'a, 'i>) -> Self {
        Scope {
            node,
            found: Vec::new(),
            joints: Vec::new(),
            links: HashMap::new(),
            models: HashMap::new(),
            frames: HashMap::new(),
        }
    }

    fn walk(&mut self, xml: &Xml) -> Result<(), Diagnostic> {
        let owner = match self.node.attribute("name") {
            Some(n) if is(&self.node, "world") => format!("world {}", quoted(n)),
            _ => format!("`<{}>`", qname(self.node)),
        };
        for c in elements(self.node) {
            match qname(c) {
                "model" => self.model(xml, c, "", false, &owner)?,
                // A world's own joints name links as `model::link`.
                "joint" => self.joint(xml, c, ""),
                _ => {}
            }
        }
        Ok(())
    }

    /// A model and the models nested in it, depth first in document order,
    /// as a recursion would, but with a stack of its own: models nest as
    /// deep as the reader allows (`MAX_DEPTH`), deeper than a thread's
    /// stack of recursive calls goes in a debug build.
    fn model(
        &mut self,
        xml: &Xml,
        model: Node<'a, 'i>,
        scope: &str,
        fixed: bool,
        owner: &str,
    ) -> Result<(), Diagnostic> {
        /// A model being walked: its children still to read, its path, and
        /// whether it is static.
        struct Open<'a, 'i> {
            children: roxmltree::Children<'a, 'i>,
            path: String,
            fixed: bool,
            this: String,
        }
        let mut stack: Vec<Open<'a, 'i>> = Vec::new();
        let mut next = Some((model, scope.to_string(), fixed, owner.to_string()));
        loop {
            if let Some((model, scope, fixed, owner)) = next.take() {
                xml.required(model, "name", &owner)?;
                let path = join(&scope, model.attribute("name").unwrap_or_default());
                let this = format!("model {}", quoted(&path));
                // A nested model of a static model is static with it.
                let fixed = fixed
                    || match child(model, "static") {
                        Some(s) => flag(xml, &xml.text(s), &this)?,
                        None => false,
                    };
                self.models.insert(path.clone(), model);
                stack.push(Open {
                    children: model.children(),
                    path,
                    fixed,
                    this,
                });
            }
            let Some(open) = stack.last_mut() else {
                return Ok(());
            };
            let Some(c) = open.children.next() else {
                stack.pop();
                continue;
            };
            let (path, fixed) = (open.path.clone(), open.fixed);
            match qname(c) {
                "link" => {
                    xml.required(c, "name", &open.this)?;
                    let p = join(&path, c.attribute("name").unwrap_or_default());
                    self.links.insert(p.clone(), self.found.len());
                    self.found.push(Found {
                        node: c,
                        path: p,
                        fixed_model: fixed,
                    });
                }
                "frame" => {
                    if let Some(name) = c.attribute("name") {
                        let attached = c.attribute("attached_to").unwrap_or_default();
                        self.frames
                            .insert(join(&path, name), (path.clone(), attached.to_string()));
                    }
                }
                "joint" => self.joint(xml, c, &path),
                "model" => next = Some((c, path, fixed, open.this.clone())),
                _ => {}
            }
        }
    }

    fn joint(&mut self, xml: &Xml, joint: Node, scope: &str) {
        if let Some(c) = child(joint, "child") {
            self.joints.push(Joint {
                scope: scope.to_string(),
                child: xml.text(c).text,
                fixed: joint.attribute("type") == Some("fixed"),
            });
        }
    }

    /// The link `name` (relative to the model `scope`) names: a link, or
    /// the canonical link of a model, or the link a frame is attached to.
    fn resolve(&self, scope: &str, name: &str, hops: usize) -> Option<usize> {
        if hops > MAX_HOPS {
            return None;
        }
        let full = join(scope, name);
        if let Some(model) = full
            .strip_suffix("::__model__")
            .or((full == "__model__").then_some(""))
        {
            return self.canonical(model, hops + 1);
        }
        if let Some(&i) = self.links.get(&full) {
            return Some(i);
        }
        if self.models.contains_key(&full) {
            return self.canonical(&full, hops + 1);
        }
        let (model, attached) = self.frames.get(&full)?;
        if attached.is_empty() {
            self.canonical(model, hops + 1)
        } else {
            self.resolve(model, attached, hops + 1)
        }
    }

    /// A model's canonical link: `canonical_link`, else its first link,
    /// else its first nested model's.
    fn canonical(&self, path: &str, hops: usize) -> Option<usize> {
        let model = self.models.get(path)?;
        if let Some(c) = model.attribute("canonical_link").filter(|c| !c.is_empty()) {
            return self.resolve(path, c, hops + 1);
        }
        if let Some(link) = elements(*model).find(|c| is(c, "link")) {
            return self
                .links
                .get(&join(path, link.attribute("name").unwrap_or_default()))
                .copied();
        }
        let nested = elements(*model).find(|c| is(c, "model"))?;
        self.canonical(&join(path, nested.attribute("name")?), hops + 1)
    }

    /// Each link with whether it moves.
    fn moving(&mut self) -> Vec<(Found<'a, 'i>, bool)> {
        // Per link: None, the child of no joint; Some(true), of a joint
        // that is not fixed; Some(false), of fixed joints only.
        let mut child_of: Vec<Option<bool>> = vec![None; self.found.len()];
        for j in &self.joints {
            if let Some(i) = self.resolve(&j.scope, &j.child, 0) {
                child_of[i] = Some(child_of[i].unwrap_or(false) || !j.fixed);
            }
        }
        std::mem::take(&mut self.found)
            .into_iter()
            .zip(child_of)
            .map(|(f, c)| {
                let moving = !f.fixed_model && c.unwrap_or(true);
                (f, moving)
            })
            .collect()
    }
}

/// An SDFormat bool: `true`, `false`, `1` or `0`, any case, as
/// libsdformat reads it.
pub(super) fn flag(xml: &Xml, v: &Value, owner: &str) -> Result<bool, Diagnostic> {
    match v.text.to_ascii_lowercase().as_str() {
        "true" | "1" => Ok(true),
        "false" | "0" => Ok(false),
        _ => xml.keyword(v, owner, &[("true", true), ("false", false)]),
    }
}

/// The `<inertial>` `node` of the link named `local` in its model; None
/// when the simulator computes it (`auto="true"`, SDFormat 1.11).
pub(super) fn inertial(
    xml: &Xml,
    node: Node,
    local: &str,
    owner: &str,
) -> Result<Option<Inertial>, Diagnostic> {
    if let Some(v) = xml.attr(node, "auto")
        && flag(xml, &v, owner)?
    {
        return Ok(None);
    }
    let (pos, rotation) = match child(node, "pose") {
        Some(p) => pose(xml, p, local, owner)?,
        None => ([0.0; 3], None),
    };
    let mass = match child(node, "mass") {
        Some(m) => xml.number(&xml.text(m), owner)?,
        None => 1.0,
    };
    // The spec's defaults, for each element absent and for no `<inertia>`.
    let inertia = child(node, "inertia");
    let entry = |name: &str, default: f64| -> Result<f64, Diagnostic> {
        match inertia.and_then(|i| child(i, name)) {
            Some(e) => xml.number(&xml.text(e), owner),
            None => Ok(default),
        }
    };
    let tensor = Tensor {
        xx: entry("ixx", 1.0)?,
        xy: entry("ixy", 0.0)?,
        xz: entry("ixz", 0.0)?,
        yy: entry("iyy", 1.0)?,
        yz: entry("iyz", 0.0)?,
        zz: entry("izz", 1.0)?,
    };
    Ok(Some(Inertial {
        mass,
        pos,
        rotation,
        tensor,
        written: Written::Elements,
        range: node.range(),
    }))
}

/// An inertial `<pose>`: `x y z roll pitch yaw` (radians, or degrees under
/// `degrees="true"`), or `x y z qx qy qz qw` under
/// `rotation_format="quat_xyzw"`.
pub(super) fn pose(
    xml: &Xml,
    node: Node,
    local: &str,
    owner: &str,
) -> Result<([f64; 3], Option<M3<f64>>), Diagnostic> {
    if let Some(v) = xml.attr(node, "relative_to")
        && !v.text.is_empty()
        && v.text != local
    {
        let message = format!(
            "`relative_to` of the inertial `<pose>` of {owner} names {}: only the link's own frame is supported",
            quoted(&v.text)
        );
        return Err(xml
            .error(v.range.clone(), message)
            .help("give the inertial pose in the link frame and drop `relative_to`"));
    }
    let quat = match xml.attr(node, "rotation_format") {
        Some(v) => xml.keyword(&v, owner, &[("euler_rpy", false), ("quat_xyzw", true)])?,
        None => false,
    };
    let degrees = match xml.attr(node, "degrees") {
        Some(v) => flag(xml, &v, owner)?,
        None => false,
    };
    let v = xml.text(node);
    if v.text.is_empty() {
        return Ok(([0.0; 3], None));
    }
    let n = xml.list(&v, owner)?;
    let (want, form) = if quat {
        (7, "x y z qx qy qz qw")
    } else {
        (6, "x y z roll pitch yaw")
    };
    if n.len() != want {
        return Err(xml.error(
            v.range.clone(),
            format!(
                "{} of {owner}: expected {want} numbers ({form}), found {}",
                v.name,
                n.len()
            ),
        ));
    }
    let pos = [n[0], n[1], n[2]];
    let rotation = if quat {
        let [x, y, z, w] = [n[3], n[4], n[5], n[6]];
        if [x, y, z, w].iter().all(|&c| c == 0.0) {
            return Err(xml.error(
                v.range.clone(),
                format!("{} of {owner}: a zero quaternion is no orientation", v.name),
            ));
        }
        // Normalised: divided by |q|², not first made unit.
        proper(xml, &v, owner, quaternion::<f64>([w, x, y, z]))?
    } else {
        let sc = |a: f64| if degrees { sin_cos_deg(a) } else { a.sin_cos() };
        rpy(sc(n[3]), sc(n[4]), sc(n[5]))
    };
    Ok((pos, turn(rotation)))
}

#[cfg(test)]
mod tests {
    use super::super::read;
    use super::super::tests::{assert_matrix, source};
    use crate::robot::{Description, Dialect, Inertial, Tensor, Written};

    /// Rz(90°), by hand: x̂ → ŷ, ŷ → −x̂.
    const RZ: [[f64; 3]; 3] = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];

    fn sdf(body: &str) -> String {
        format!("<?xml version='1.0'?>\n<sdf version='1.11'>\n{body}\n</sdf>\n")
    }

    /// A model `m` with one link `l` holding `inertial`.
    fn link(inertial: &str) -> String {
        sdf(&format!(
            "<model name='m'>\n  <link name='l'>\n    {inertial}\n  </link>\n</model>"
        ))
    }

    fn read_ok(text: &str) -> Description {
        read(&source(text), Dialect::Sdf).unwrap()
    }

    fn first(text: &str) -> Inertial {
        read_ok(text).links[0].inertial.clone().unwrap()
    }

    fn error(text: &str) -> String {
        read(&source(text), Dialect::Sdf).unwrap_err().to_string()
    }

    fn moving(d: &Description) -> Vec<(&str, bool)> {
        d.links
            .iter()
            .map(|l| (l.name.as_str(), l.moving))
            .collect()
    }

    #[test]
    fn an_inertial_is_read_as_written() {
        let i = first(&link(
            "<inertial><pose>1 2 3 0 0 0</pose><mass>4.5</mass><inertia><ixx>1</ixx><ixy>0.1</ixy><ixz>0.2</ixz><iyy>2</iyy><iyz>0.3</iyz><izz>3</izz></inertia></inertial>",
        ));
        assert_eq!((i.mass, i.pos, i.rotation), (4.5, [1.0, 2.0, 3.0], None));
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
        assert_eq!(i.written, Written::Elements);
    }

    #[test]
    fn absent_values_take_the_specs_defaults() {
        let unit = Tensor {
            xx: 1.0,
            yy: 1.0,
            zz: 1.0,
            ..Tensor::default()
        };
        let i = first(&link("<inertial/>"));
        assert_eq!(
            (i.mass, i.pos, i.rotation, i.tensor),
            (1.0, [0.0; 3], None, unit)
        );
        let i = first(&link(
            "<inertial><inertia><ixx>2</ixx><iyz>0.5</iyz></inertia></inertial>",
        ));
        assert_eq!(
            i.tensor,
            Tensor {
                xx: 2.0,
                yz: 0.5,
                ..unit
            }
        );
    }

    #[test]
    fn a_quarter_yaw_in_radians_turns_x_onto_y() {
        let i = first(&link(
            "<inertial><pose>0 0 0 0 0 1.5707963267948966</pose></inertial>",
        ));
        assert_matrix(i.rotation.unwrap(), RZ);
    }

    #[test]
    fn pose_angles_may_be_degrees() {
        let i = first(&link(
            "<inertial><pose degrees='true'>0 0 0 0 0 90</pose></inertial>",
        ));
        assert_matrix(i.rotation.unwrap(), RZ);
    }

    #[test]
    fn a_pose_may_be_a_quaternion_x_y_z_w() {
        let i = first(&link(
            "<inertial><pose rotation_format='quat_xyzw'>1 2 3 0 0 1 1</pose></inertial>",
        ));
        assert_eq!(i.pos, [1.0, 2.0, 3.0]);
        assert_matrix(i.rotation.unwrap(), RZ);
    }

    #[test]
    fn a_quaternion_whose_square_overflows_or_vanishes_is_refused() {
        // Divided by |q|², which is infinite or 0: NaN entries, once
        // shown as null in check's JSON.
        for q in ["0 0 1e200 1e200", "0 0 1e-200 0"] {
            let text = link(&format!(
                "<inertial><pose rotation_format='quat_xyzw'>1 2 3 {q}</pose></inertial>"
            ));
            let d = read(&source(&text), Dialect::Sdf).unwrap_err().to_string();
            assert!(
                d.contains("error: `<pose>` of link \"l\" gives no rotation"),
                "{q}: {d}"
            );
        }
    }

    #[test]
    fn an_automatic_inertial_is_none() {
        let d = read_ok(&link("<inertial auto='true'><mass>3</mass></inertial>"));
        assert_eq!(d.links[0].inertial, None);
    }

    #[test]
    fn a_pose_relative_to_the_link_itself_is_read() {
        let i = first(&link(
            "<inertial><pose relative_to='l'>1 0 0 0 0 0</pose></inertial>",
        ));
        assert_eq!(i.pos, [1.0, 0.0, 0.0]);
    }

    #[test]
    fn a_pose_relative_to_another_frame_is_refused() {
        let text = link("<inertial><pose relative_to='base'>1 0 0 0 0 0</pose></inertial>");
        let d = error(&text);
        assert!(
            d.starts_with("r.xml:5:34: error: `relative_to` of the inertial `<pose>` of link \"l\" names \"base\": only the link's own frame is supported\n"),
            "{d}"
        );
    }

    #[test]
    fn a_word_in_an_element_is_refused_at_its_text() {
        let text = link("<inertial><inertia><ixx> abc </ixx></inertia></inertial>");
        let d = error(&text);
        assert!(
            d.starts_with(
                "r.xml:5:30: error: `<ixx>` of link \"l\": expected a number, found \"abc\"\n"
            ),
            "{d}"
        );
    }

    #[test]
    fn a_pose_needs_six_numbers() {
        let d = error(&link("<inertial><pose>1 2 3</pose></inertial>"));
        assert!(
            d.starts_with("r.xml:5:21: error: `<pose>` of link \"l\": expected 6 numbers (x y z roll pitch yaw), found 3\n"),
            "{d}"
        );
    }

    #[test]
    fn nested_links_are_named_from_the_outermost_model() {
        let d = read_ok(&sdf(
            "<model name='a'><link name='base'/><model name='b'><link name='l'/><model name='c'><link name='l'/></model></model></model>",
        ));
        let names: Vec<&str> = d.links.iter().map(|l| l.name.as_str()).collect();
        assert_eq!(names, ["base", "b::l", "b::c::l"]);
        assert_eq!(d.name.as_deref(), Some("a"));
    }

    #[test]
    fn one_model_in_a_world_is_not_prefixed() {
        let d = read_ok(&sdf(
            "<world name='w'><model name='m'><link name='l'/></model></world>",
        ));
        assert_eq!(d.links[0].name, "l");
    }

    #[test]
    fn several_top_level_models_prefix_their_links() {
        let d = read_ok(&sdf(
            "<world name='w'><model name='m1'><link name='l'/></model><model name='m2'><link name='l'/></model></world>",
        ));
        let names: Vec<&str> = d.links.iter().map(|l| l.name.as_str()).collect();
        assert_eq!(names, ["m1::l", "m2::l"]);
        assert_eq!(d.name.as_deref(), Some("w"));
    }

    #[test]
    fn a_worlds_include_is_a_top_level_model_that_prefixes_the_names() {
        // `super::read` alone: `read::read` follows the include (issue 34),
        // which names no file here.
        let read_ok = |text: &str| {
            let src = source(text);
            let doc = roxmltree::Document::parse(text).unwrap();
            super::read(&super::super::Xml { source: &src }, doc.root_element()).unwrap()
        };
        let d = read_ok(&sdf(
            "<world name='w'><model name='m'><link name='l'/></model><include><uri>x</uri></include></world>",
        ));
        assert_eq!(d.links[0].name, "m::l");
        assert_eq!(d.name.as_deref(), Some("w"));
    }

    #[test]
    fn a_free_root_link_and_a_jointed_child_move_and_a_fixed_child_does_not() {
        let d = read_ok(&sdf(
            "<model name='m'><link name='base'/><link name='arm'/><link name='tool'/>\
             <joint name='j1' type='revolute'><parent>base</parent><child>arm</child></joint>\
             <joint name='j2' type='fixed'><parent>arm</parent><child>tool</child></joint></model>",
        ));
        assert_eq!(moving(&d), [("base", true), ("arm", true), ("tool", false)]);
    }

    #[test]
    fn a_root_link_fixed_to_the_world_does_not_move() {
        let d = read_ok(&sdf(
            "<model name='m'><link name='base'/><joint name='j' type='fixed'><parent>world</parent><child>base</child></joint></model>",
        ));
        assert_eq!(moving(&d), [("base", false)]);
    }

    #[test]
    fn links_of_a_static_model_and_its_nested_models_never_move() {
        let d = read_ok(&sdf(
            "<model name='m'><static>true</static><link name='base'/><link name='arm'/>\
             <joint name='j' type='revolute'><parent>base</parent><child>arm</child></joint>\
             <model name='n'><link name='l'/></model></model>",
        ));
        assert_eq!(
            moving(&d),
            [("base", false), ("arm", false), ("n::l", false)]
        );
    }

    #[test]
    fn a_joint_may_name_a_nested_link_or_a_nested_model() {
        let d = read_ok(&sdf("<model name='m'><link name='base'/>\
             <model name='n'><link name='l'/><link name='k'/></model>\
             <model name='o'><link name='p'/></model>\
             <joint name='j1' type='fixed'><parent>base</parent><child>n::l</child></joint>\
             <joint name='j2' type='fixed'><parent>base</parent><child>o</child></joint></model>"));
        assert_eq!(
            moving(&d),
            [
                ("base", true),
                ("n::l", false),
                ("n::k", true),
                ("o::p", false)
            ]
        );
    }

    #[test]
    fn a_world_joint_names_a_link_by_its_model() {
        let d = read_ok(&sdf(
            "<world name='w'><model name='m'><link name='l'/></model>\
             <joint name='j' type='fixed'><parent>world</parent><child>m::l</child></joint></world>",
        ));
        assert_eq!(moving(&d), [("l", false)]);
    }

    #[test]
    fn the_ranges_cover_the_link_and_the_inertial() {
        let text = link("<inertial><mass>1</mass></inertial>");
        let d = read_ok(&text);
        let l = &text[d.links[0].range.clone()];
        assert!(
            l.starts_with("<link name='l'>") && l.ends_with("</link>"),
            "{l}"
        );
        let i = &text[d.links[0].inertial.as_ref().unwrap().range.clone()];
        assert!(
            i.starts_with("<inertial>") && i.ends_with("</inertial>"),
            "{i}"
        );
    }
}
