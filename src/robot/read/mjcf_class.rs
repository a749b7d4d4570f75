//! MJCF default classes, as MuJoCo applies them (MuJoCo's XML reference,
//! "default" and "Default settings"; `xml_native_reader.cc`): the
//! `<default>` directly under `<mujoco>` is the class "main"; a
//! `<default class="name">` inside another inherits every value of its
//! parent's that it does not set itself. An element that admits a class
//! (`<joint>`, `<geom>`, `<equality>`'s children, …) takes its own `class`,
//! else the `childclass` of its nearest enclosing `<body>` or `<frame>`
//! that has one, else "main"; each of its attributes is its own, else its
//! class's (that class's `<joint>`, `<geom>`, … element), else the parent
//! class's, up to "main", else MuJoCo's built-in default (the caller's).
//! An `<include>` inside a `<default>` (or a `<body>` with a `childclass`)
//! is spliced there (`Model::children`, `Model::parent`).

use super::mjcf_include::Model;
use super::{Value, Xml, qname, quoted};
use crate::diag::{Diagnostic, Source};
use roxmltree::Node;
use std::collections::HashMap;

/// An element of a file of the model, with that file.
type Placed<'s, 'a, 'i> = (Node<'a, 'i>, &'s Source);

/// The default classes of an MJCF model (its included files' too).
pub(super) struct Classes<'s, 'a, 'i> {
    /// Each class: its parent class, and its elements other than
    /// `<default>`s (`<joint>`, `<geom>`, …), each with the file it is
    /// written in (an included one, where an `<include>` stands there).
    classes: Vec<(Option<usize>, Vec<Placed<'s, 'a, 'i>>)>,
    by_name: HashMap<String, usize>,
}

/// The class an element takes: an index into `Classes`, or none (no
/// `<default>` at all).
pub(super) type Class = Option<usize>;

impl<'s, 'a, 'i> Classes<'s, 'a, 'i> {
    /// The classes under `<mujoco>` (in every file of the model), a name
    /// given twice refused at its second `class`.
    pub fn read(m: &Model<'s, 'a, 'i>) -> Result<Classes<'s, 'a, 'i>, Diagnostic> {
        let mut out = Classes {
            classes: Vec::new(),
            by_name: HashMap::new(),
        };
        // Depth first, parents before children, with an explicit stack (a
        // nesting as deep as the parser allows must not overflow ours).
        let mut stack: Vec<(usize, Node, Option<usize>)> = m
            .sections("default")
            .map(|(_, f, d)| (f, d, None))
            .collect();
        stack.reverse();
        while let Some((file, d, parent)) = stack.pop() {
            let xml = m.xml(file);
            let name = match (xml.attr(d, "class"), parent) {
                (Some(v), _) => v,
                (None, None) => Value {
                    name: "`class`".to_string(),
                    text: "main".to_string(),
                    range: xml.tag(d),
                    exact: false,
                },
                (None, Some(_)) => {
                    return Err(xml.error(
                        xml.tag(d),
                        "a `<default>` inside another needs a `class` name (MuJoCo requires one)",
                    ));
                }
            };
            let k = out.classes.len();
            if out.by_name.insert(name.text.clone(), k).is_some() {
                return Err(xml.error(
                    name.range.clone(),
                    format!(
                        "`class` {}: two default classes have this name (MuJoCo refuses a repeated class name)",
                        quoted(&name.text)
                    ),
                ));
            }
            let (kids, elems): (Vec<_>, Vec<_>) = m
                .children(file, d)
                .partition(|(_, c)| qname(*c) == "default");
            for &(f, e) in &elems {
                m.in_place(f, e)?;
            }
            out.classes.push((
                parent,
                elems
                    .into_iter()
                    .map(|(f, e)| (e, m.xml(f).source))
                    .collect(),
            ));
            stack.extend(kids.into_iter().rev().map(|(f, c)| (f, c, Some(k))));
        }
        Ok(out)
    }

    /// The class `v` (a `class` or `childclass` attribute) names, or an
    /// error at it with the nearest name.
    fn named(&self, xml: &Xml, v: &Value) -> Result<usize, Diagnostic> {
        self.by_name.get(&v.text).copied().ok_or_else(|| {
            let near = crate::units::suggest(&v.text, self.by_name.keys().map(String::as_str))
                .map(|s| format!("; did you mean {}?", quoted(s)))
                .unwrap_or_default();
            xml.error(
                v.range.clone(),
                format!(
                    "{} names no default class: {}{near}",
                    v.name,
                    quoted(&v.text)
                ),
            )
        })
    }

    /// The class `node` (of file `file`) takes: its own `class`, else the
    /// nearest enclosing `childclass` (through the `<include>`s that bring
    /// it in), else "main" (where there is a `<default>`).
    pub fn of(&self, m: &Model, file: usize, node: Node) -> Result<Class, Diagnostic> {
        let xml = m.xml(file);
        if let Some(v) = xml.attr(node, "class") {
            return self.named(xml, &v).map(Some);
        }
        let mut up = m.parent(file, node);
        while let Some((f, n)) = up {
            let xml = m.xml(f);
            if matches!(qname(n), "body" | "frame")
                && let Some(v) = xml.attr(n, "childclass")
            {
                return self.named(xml, &v).map(Some);
            }
            up = m.parent(f, n);
        }
        Ok(self.by_name.get("main").copied())
    }

    /// Every `class` and `childclass` in the file names a class: checked
    /// once, so that a misspelt name is refused even on an element whose
    /// values are not read. NOTE: a walk of each file's own elements, not
    /// of the spliced model: every file is spliced somewhere in it, and
    /// the order of the check does not matter.
    pub fn check_names(&self, m: &Model) -> Result<(), Diagnostic> {
        for (xml, root) in m.xmls.iter().zip(&m.roots) {
            for n in root.descendants().filter(|n| n.is_element()) {
                if qname(n) == "default" {
                    continue;
                }
                for a in ["class", "childclass"] {
                    if let Some(v) = xml.attr(n, a) {
                        self.named(xml, &v)?;
                    }
                }
            }
        }
        Ok(())
    }

    /// The attribute `name` of `node`, a `<kind>` element of class `class`:
    /// its own, else the nearest class's up the chain that sets it.
    pub fn attr(
        &self,
        xml: &Xml,
        node: Node,
        class: Class,
        kind: &str,
        name: &str,
    ) -> Option<Value> {
        xml.attr(node, name).or_else(|| {
            let (v, from) = self.inherited(class, kind, name)?;
            // NOTE: a value a class of another file gives is pointed at
            // the element that takes it: a place names one file.
            Some(if std::ptr::eq(from, xml.source) {
                v
            } else {
                Value {
                    range: xml.tag(node),
                    exact: false,
                    ..v
                }
            })
        })
    }

    /// The `<kind>` elements of class `class` and the classes it inherits
    /// from, nearest first.
    pub fn defaults(&self, class: Class, kind: &str) -> Vec<(Node<'a, 'i>, &'s Source)> {
        let mut out = Vec::new();
        let mut c = class;
        while let Some(k) = c {
            let (parent, ref elems) = self.classes[k];
            out.extend(elems.iter().filter(|(e, _)| qname(*e) == kind).copied());
            // Parents come before their children: the chain ends.
            c = parent;
        }
        out
    }

    /// The value class `class` (or a class it inherits from) gives the
    /// attribute `name` of a `<kind>` element, and the file it is in.
    fn inherited(&self, class: Class, kind: &str, name: &str) -> Option<(Value, &'s Source)> {
        let mut c = class;
        let mut hops = 0;
        while let Some(k) = c {
            let (parent, ref elems) = self.classes[k];
            if let Some(found) = elems
                .iter()
                .filter(|(e, _)| qname(*e) == kind)
                .find_map(|&(e, source)| Some((Xml { source }.attr(e, name)?, source)))
            {
                return Some(found);
            }
            c = parent;
            // Parents come before their children: the chain ends.
            hops += 1;
            debug_assert!(
                hops <= self.classes.len(),
                "a class's parent is read before it"
            );
        }
        None
    }
}
