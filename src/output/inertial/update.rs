//! Replacing one link's `<inertial>` in a robot description file, every
//! other byte kept: comments, quoting, indentation, line endings, the
//! declaration, trailing whitespace. A file under version control should
//! show a diff of the inertial alone.
//!
//! NOTE: the file is parsed (roxmltree) only to find byte ranges; the
//! result is the original text with one range replaced (or one element
//! inserted), never a re-serialised tree, which would re-quote, re-indent
//! and drop comments.

use super::error::{LISTED, UpdateError, root_name};
use super::{Export, inertial_element};
use crate::robot::Dialect;
use roxmltree::{Document, Node, ParsingOptions};
use std::ops::Range;

/// `text` with the `<inertial>` of the link (URDF, SDFormat) or body (MJCF)
/// named `link` replaced by `e`'s, or inserted as its first child when it
/// has none; every other byte as it was.
///
/// Names: a URDF `<link>` child of `<robot>`; an SDFormat `<link>` of a
/// `<model>`, a nested model's as `inner::link` (relative to the outermost
/// model, as `robot::Link` names it); a named MJCF `<body>` anywhere under
/// `<worldbody>`. The text has no byte-order mark (the caller strips and
/// re-adds it).
pub fn update(text: &str, format: Dialect, link: &str, e: &Export) -> Result<String, UpdateError> {
    // A doctype is allowed (some exporters write one); roxmltree still
    // bounds entity expansion.
    let options = ParsingOptions {
        allow_dtd: true,
        ..ParsingOptions::default()
    };
    let doc = Document::parse_with_options(text, options).map_err(|err| {
        // The place goes in `at`, for the caller's `file:line:col`; most
        // of roxmltree's messages end with it too.
        let message = err.to_string();
        let place = format!(" at {}", err.pos());
        UpdateError::Xml {
            message: message.strip_suffix(&place).unwrap_or(&message).to_string(),
            at: Some(offset_of(text, err.pos())),
        }
    })?;
    // As the reader: a tree nested this deep is refused, before the
    // recursive walk of SDFormat models below could overflow the stack.
    if let Some(deep) = crate::robot::read::too_deep(&doc) {
        return Err(UpdateError::Xml {
            message: format!(
                "`<{}>` is nested {} elements deep: no robot description nests that deep",
                crate::diag::shorten(qname(text, deep)),
                crate::robot::read::MAX_DEPTH
            ),
            at: Some(deep.range().start),
        });
    }
    // As the reader: a reference to an entity the doctype declares is
    // refused (the simulators would not expand it).
    if let Some(e) = crate::robot::read::entity_in_use(text, &doc) {
        return Err(UpdateError::Entity {
            message: e.message(text),
            at: e.at.start,
        });
    }
    let root = doc.root_element();
    if qname(text, root) != root_name(format) {
        return Err(UpdateError::Root {
            format,
            found: qname(text, root).to_string(),
            at: Some(root.range().start),
        });
    }
    let links = links(text, root, format);
    let mut named = links
        .iter()
        .filter(|(n, _)| n == link)
        .map(|&(_, node)| node);
    let Some(node) = named.next() else {
        let names: Vec<&str> = links.iter().map(|(n, _)| n.as_str()).collect();
        return Err(UpdateError::NoLink {
            format,
            link: link.to_string(),
            names: names.iter().take(LISTED).map(|n| n.to_string()).collect(),
            more: names.len().saturating_sub(LISTED),
            suggestion: crate::units::suggest(link, names.iter().copied()).map(str::to_string),
        });
    };
    if let Some(second) = named.next() {
        return Err(UpdateError::Duplicate {
            format,
            link: link.to_string(),
            at: Some(second.range().start),
        });
    }
    let inertials: Vec<Node> = node
        .children()
        .filter(|c| c.is_element() && qname(text, *c) == "inertial")
        .collect();
    match inertials[..] {
        [] => Ok(insert(text, format, node, e)),
        [one] => {
            let range = one.range();
            let indent = indentation(text, range.start);
            let element = inertial_element(format, e, indent);
            let element = with_newline(&element, newline(text, range.start));
            Ok(splice(text, range, &element))
        }
        [_, second, ..] => Err(UpdateError::Inertials {
            format,
            link: link.to_string(),
            at: Some(second.range().start),
        }),
    }
}

/// The links of a document, named as `robot::Link` names them, with their
/// elements, in document order.
fn links<'a, 'i>(text: &str, root: Node<'a, 'i>, format: Dialect) -> Vec<(String, Node<'a, 'i>)> {
    let mut out = Vec::new();
    let named = |node: Node<'a, 'i>| node.attribute("name").map(str::to_string);
    match format {
        Dialect::Urdf => {
            for child in root.children().filter(|c| qname(text, *c) == "link") {
                out.extend(named(child).map(|n| (n, child)));
            }
        }
        Dialect::Sdf => {
            // Models are children of <sdf>, <world> or <model>; links
            // children of a model. Not every element is looked into: a
            // <plugin>'s contents are free-form and may say <link>. Depth
            // first in document order, with a stack of its own rather than
            // recursive calls (models nest up to read::MAX_DEPTH deep).
            // Each entry: the children still to walk, and the prefix of
            // their names (None outside every model).
            let top = |n: Node| n.children().filter(|c| qname(text, *c) == "model").count();
            let worlds = root.children().filter(|c| qname(text, *c) == "world");
            let several = top(root) + worlds.map(top).sum::<usize>() > 1;
            let mut stack = vec![(root.children(), None::<String>)];
            while let Some((children, prefix)) = stack.last_mut() {
                let Some(child) = children.next() else {
                    stack.pop();
                    continue;
                };
                let prefix = prefix.clone();
                match (qname(text, child), prefix) {
                    ("world", None) => stack.push((child.children(), None)),
                    // The outermost model's name is left out, unless the
                    // file has several (robot::read's names).
                    ("model", None) => {
                        let name = child.attribute("name").unwrap_or("");
                        let p = if several {
                            format!("{name}::")
                        } else {
                            String::new()
                        };
                        stack.push((child.children(), Some(p)));
                    }
                    ("model", Some(p)) => {
                        let name = child.attribute("name").unwrap_or("");
                        stack.push((child.children(), Some(format!("{p}{name}::"))));
                    }
                    ("link", Some(p)) => {
                        if let Some(name) = child.attribute("name") {
                            out.push((format!("{p}{name}"), child));
                        }
                    }
                    _ => {}
                }
            }
        }
        Dialect::Mjcf => {
            for world in root.children().filter(|c| qname(text, *c) == "worldbody") {
                for body in world.descendants().filter(|c| qname(text, *c) == "body") {
                    out.extend(named(body).map(|n| (n, body)));
                }
            }
        }
    }
    out
}

/// An element's name as written, prefix included (`xacro:link` is not a
/// `link`); empty for a node that is not an element.
fn qname<'t>(text: &'t str, node: Node) -> &'t str {
    if !node.is_element() {
        return "";
    }
    let tag = &text[node.range().start + 1..];
    let end = tag
        .find(|c: char| c.is_ascii_whitespace() || c == '>' || c == '/')
        .unwrap_or(tag.len());
    &tag[..end]
}

/// Insert `e`'s inertial as the first child of `link`, which has none: on
/// its own line after the start tag, one indentation step in. An empty
/// element `<link name="x"/>` is opened and closed.
fn insert(text: &str, format: Dialect, link: Node, e: &Export) -> String {
    let start = link.range().start;
    let tag_end = start_tag_end(text, start);
    let own = indentation(text, start);
    let nl = newline(text, start);
    let inner = format!("{own}{}", step(text, link));
    let element = with_newline(&inertial_element(format, e, &inner), nl);
    let opened = format!("{nl}{inner}{element}");
    if text[..tag_end].ends_with("/>") {
        // `<link name="x" />` → `<link name="x">`, then the element and
        // the end tag on a line of its own.
        let before = text[start..tag_end - 2].trim_end();
        let tag = format!("{before}>{opened}{nl}{own}</{}>", qname(text, link));
        return splice(text, start..tag_end, &tag);
    }
    // An element with nothing but spaces in it (`<link name="x"></link>`)
    // gets its end tag on a line of its own too.
    let end_tag = text[..link.range().end].rfind("</").unwrap_or(tag_end);
    let content = &text[tag_end..end_tag];
    if content.trim().is_empty() && !content.contains('\n') {
        return splice(text, tag_end..tag_end, &format!("{opened}{nl}{own}"));
    }
    splice(text, tag_end..tag_end, &opened)
}

/// The offset just past the `>` of the start tag at `start`: the first
/// `>` outside quotes (an attribute value may hold one).
fn start_tag_end(text: &str, start: usize) -> usize {
    let mut quote = None;
    for (i, b) in text.bytes().enumerate().skip(start) {
        match (quote, b) {
            (None, b'"' | b'\'') => quote = Some(b),
            (Some(q), _) if q == b => quote = None,
            (None, b'>') => return i + 1,
            _ => {}
        }
    }
    // roxmltree parsed the tag, so it is closed.
    text.len()
}

/// The indentation step the file uses at `link`: its first child
/// element's indentation beyond its own, else its own beyond its parent's,
/// else two spaces.
fn step<'t>(text: &'t str, link: Node) -> &'t str {
    let beyond = |inner: Node, outer: Node| {
        let (i, o) = (inner.range().start, outer.range().start);
        if !own_line(text, i) || !own_line(text, o) {
            return None;
        }
        indentation(text, i)
            .strip_prefix(indentation(text, o))
            .filter(|s| !s.is_empty())
    };
    link.children()
        .find(Node::is_element)
        .and_then(|child| beyond(child, link))
        .or_else(|| link.parent_element().and_then(|p| beyond(link, p)))
        .unwrap_or("  ")
}

/// The spaces and tabs that start the line `at` is on.
fn indentation(text: &str, at: usize) -> &str {
    let line = &text[line_start(text, at)..at];
    let end = line
        .find(|c: char| c != ' ' && c != '\t')
        .unwrap_or(line.len());
    &line[..end]
}

/// Whether only spaces and tabs come before `at` on its line.
fn own_line(text: &str, at: usize) -> bool {
    text[line_start(text, at)..at]
        .bytes()
        .all(|b| b == b' ' || b == b'\t')
}

fn line_start(text: &str, at: usize) -> usize {
    text[..at].rfind('\n').map_or(0, |i| i + 1)
}

/// The line ending the file uses where `at` is: that of the first line
/// break after it, else of the last before it, else `\n`. (Looked up
/// where the edit is, so that a file with mixed endings stays as mixed.)
fn newline(text: &str, at: usize) -> &'static str {
    let crlf = |i: usize| i > 0 && text.as_bytes()[i - 1] == b'\r';
    let after = text[at..].find('\n').map(|i| at + i);
    match after.or_else(|| text[..at].rfind('\n')) {
        Some(i) if crlf(i) => "\r\n",
        _ => "\n",
    }
}

/// `element` (written with `\n`) with `nl` for its line breaks.
fn with_newline(element: &str, nl: &str) -> String {
    if nl == "\n" {
        element.to_string()
    } else {
        element.replace('\n', nl)
    }
}

fn splice(text: &str, range: Range<usize>, with: &str) -> String {
    let mut out = String::with_capacity(text.len() - range.len() + with.len());
    out.push_str(&text[..range.start]);
    out.push_str(with);
    out.push_str(&text[range.end..]);
    out
}

/// The byte offset of roxmltree's row and column (1-based; the column in
/// characters), clamped to the text.
fn offset_of(text: &str, pos: roxmltree::TextPos) -> usize {
    let mut start = 0;
    for _ in 1..pos.row {
        match text[start..].find('\n') {
            Some(i) => start += i + 1,
            None => return text.len(),
        }
    }
    text[start..]
        .char_indices()
        .nth(pos.col.saturating_sub(1) as usize)
        .map_or(text.len(), |(i, _)| start + i)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::Tensor;

    /// Numbers no short decimal holds, and one that needs an exponent.
    fn export() -> Export {
        Export {
            mass: 1.0 / 3.0,
            pos: [0.1 + 0.2, -2.5e-7, 0.0],
            tensor: Tensor {
                xx: 2.0 / 3.0,
                yy: 0.7,
                zz: 1e-9 / 7.0,
                xy: -1.0 / 7.0,
                xz: 0.0,
                yz: 3e20,
            },
            principal: None,
        }
    }

    /// Mass, position and the tensor (xx yy zz xy xz yz) of an inertial
    /// element as written, read back with roxmltree alone.
    fn read_back(format: Dialect, element: &str) -> (f64, Vec<f64>, Vec<f64>) {
        let doc = Document::parse(element).unwrap();
        let root = doc.root_element();
        let child = |name: &str| {
            root.descendants()
                .find(|n| n.has_tag_name(name))
                .unwrap_or_else(|| panic!("no <{name}> in {element}"))
        };
        let list =
            |s: &str| -> Vec<f64> { s.split_whitespace().map(|v| v.parse().unwrap()).collect() };
        let one = |s: &str| -> f64 { s.trim().parse().unwrap() };
        let order = ["ixx", "iyy", "izz", "ixy", "ixz", "iyz"];
        match format {
            Dialect::Urdf => {
                let inertia = child("inertia");
                (
                    one(child("mass").attribute("value").unwrap()),
                    list(child("origin").attribute("xyz").unwrap()),
                    order
                        .iter()
                        .map(|k| one(inertia.attribute(*k).unwrap()))
                        .collect(),
                )
            }
            Dialect::Sdf => (
                one(child("mass").text().unwrap()),
                list(child("pose").text().unwrap())[..3].to_vec(),
                order
                    .iter()
                    .map(|k| one(child(k).text().unwrap()))
                    .collect(),
            ),
            Dialect::Mjcf => (
                one(root.attribute("mass").unwrap()),
                list(root.attribute("pos").unwrap()),
                list(root.attribute("fullinertia").unwrap()),
            ),
        }
    }

    /// `update` changes `text` only where `old` (once in it) was: the bytes
    /// before and after are the same, and in its place is `e`'s element at
    /// `indent`, with the file's line endings, whose numbers read back to
    /// the bit. Returns the result.
    fn assert_replaced(text: &str, format: Dialect, link: &str, old: &str, indent: &str) -> String {
        assert_eq!(
            text.matches(old).count(),
            1,
            "the test's old element is in the text once"
        );
        let e = export();
        let start = text.find(old).unwrap();
        let suffix = &text[start + old.len()..];
        let out = update(text, format, link, &e).unwrap();
        assert_eq!(out[..start], text[..start], "the bytes before are kept");
        assert!(out.ends_with(suffix), "the bytes after are kept:\n{out}");
        let new = &out[start..out.len() - suffix.len()];
        let nl = if text.contains("\r\n") { "\r\n" } else { "\n" };
        assert_eq!(new, inertial_element(format, &e, indent).replace('\n', nl));
        let (mass, pos, tensor) = read_back(format, new);
        let t = e.tensor;
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(mass.to_bits(), e.mass.to_bits());
        assert_eq!(bits(&pos), bits(&e.pos));
        assert_eq!(bits(&tensor), bits(&[t.xx, t.yy, t.zz, t.xy, t.xz, t.yz]));
        let options = ParsingOptions {
            allow_dtd: true,
            ..ParsingOptions::default()
        };
        Document::parse_with_options(&out, options).unwrap();
        out
    }

    const URDF: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<!-- A two-link arm. <link name="arm"> in a comment is not a link. -->
<robot name='arm' xmlns:xacro="http://www.ros.org/wiki/xacro">
   <link name='base'>
      <inertial>
        <origin xyz="0 0 0.1" rpy="0 0 0" />
        <mass value='5.0'/>
        <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>
      </inertial>
      <visual><geometry><box size="1 1 1"/></geometry></visual>
   </link>
   <joint name="shoulder" type='revolute'>
      <parent link="base"/>  <child link="arm"/>
   </joint>
   <link name="arm" >   <!-- from CAD, 2019 -->
      <!-- the inertial below is stale -->
      <inertial>
         <origin xyz='0 0 0.5'/>
         <mass value="1"/>
         <inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/>
      </inertial>
      <collision name="c&gt;"><geometry><cylinder radius=".05" length="1"/></geometry></collision>
   </link>
</robot>   
"#;

    const URDF_ARM: &str = r#"<inertial>
         <origin xyz='0 0 0.5'/>
         <mass value="1"/>
         <inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/>
      </inertial>"#;

    #[test]
    fn a_urdf_links_inertial_is_replaced_and_nothing_else() {
        assert_replaced(URDF, Dialect::Urdf, "arm", URDF_ARM, "      ");
    }

    #[test]
    fn a_crlf_file_keeps_its_line_endings() {
        let crlf = URDF.replace('\n', "\r\n");
        let out = assert_replaced(
            &crlf,
            Dialect::Urdf,
            "arm",
            &URDF_ARM.replace('\n', "\r\n"),
            "      ",
        );
        assert_eq!(out.matches('\n').count(), out.matches("\r\n").count());
    }

    #[test]
    fn a_tab_indented_file_keeps_its_tabs() {
        let tabs = URDF.replace("      <", "\t\t<");
        let old = URDF_ARM.replace("      <", "\t\t<");
        assert_replaced(&tabs, Dialect::Urdf, "arm", &old, "\t\t");
    }

    #[test]
    fn an_inertial_on_the_line_of_its_link_is_replaced_in_place() {
        let text = "<robot>\n  <link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>\n</robot>\n";
        let out = assert_replaced(
            text,
            Dialect::Urdf,
            "a",
            "<inertial><mass value=\"1\"/></inertial>",
            "  ",
        );
        assert!(out.starts_with("<robot>\n  <link name=\"a\"><inertial>\n    <origin"));
    }

    #[test]
    fn a_doctype_is_no_obstacle() {
        let text = format!(
            "<!DOCTYPE robot>\n{}",
            &URDF[URDF.find("<robot").unwrap()..]
        );
        assert_replaced(&text, Dialect::Urdf, "arm", URDF_ARM, "      ");
    }

    const SDF: &str = "<?xml version='1.0'?>
<sdf version=\"1.9\">
  <model name=\"robot\">
    <link name=\"base\">
      <inertial><mass>10</mass></inertial>
    </link>
    <model name='gripper'>
      <plugin name=\"p\" filename=\"p.so\"><link name=\"finger\"/></plugin>
      <link name=\"finger\">
        <pose>0 0 0.1 0 0 0</pose>
        <inertial auto=\"false\">
          <pose>0 0 0 0 0 0</pose>
          <mass>0.1</mass>
          <!-- no inertia given -->
        </inertial>
      </link>
    </model>
  </model>
</sdf>
";

    const SDF_FINGER: &str = "<inertial auto=\"false\">
          <pose>0 0 0 0 0 0</pose>
          <mass>0.1</mass>
          <!-- no inertia given -->
        </inertial>";

    #[test]
    fn links_of_several_top_level_models_are_named_with_their_model() {
        // As robot::read names them: `a::l` and `b::l`, and `l` is none.
        let text = "<sdf version='1.9'><world name='w'><model name='a'><link name='l'/></model><model name='b'><link name='l'/></model></world></sdf>";
        let out = update(text, Dialect::Sdf, "b::l", &export()).unwrap();
        assert!(out.starts_with(&text[..text.find("<model name='b'>").unwrap()]));
        assert!(matches!(
            update(text, Dialect::Sdf, "l", &export()),
            Err(UpdateError::NoLink { .. })
        ));
        let names: Vec<String> =
            crate::robot::read::read(&crate::diag::Source::new("w.sdf", text), Dialect::Sdf)
                .unwrap()
                .links
                .into_iter()
                .map(|l| l.name)
                .collect();
        assert_eq!(names, ["a::l", "b::l"]);
    }

    #[test]
    fn a_nested_sdformat_models_link_is_named_from_the_outermost() {
        assert_replaced(SDF, Dialect::Sdf, "gripper::finger", SDF_FINGER, "        ");
        assert_replaced(
            SDF,
            Dialect::Sdf,
            "base",
            "<inertial><mass>10</mass></inertial>",
            "      ",
        );
    }

    #[test]
    fn an_sdformat_crlf_file_keeps_its_line_endings() {
        let crlf = SDF.replace('\n', "\r\n");
        assert_replaced(
            &crlf,
            Dialect::Sdf,
            "gripper::finger",
            &SDF_FINGER.replace('\n', "\r\n"),
            "        ",
        );
    }

    const MJCF: &str = r#"<mujoco model="arm">
  <compiler angle="radian"/>
  <default><joint damping="1"/></default>
  <worldbody>
    <light pos="0 0 3"/>
    <body name="upper" pos="0 0 1">
      <joint name="shoulder"/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <geom type="capsule" size=".05 .5"/>
      <body name='lower' pos="0 0 1">
	<joint name="elbow"/>
	<inertial pos='0 0 0.2' mass='0.5' fullinertia='1 1 1 0 0 0' />
      </body>
    </body>
  </worldbody>
</mujoco>
"#;

    #[test]
    fn an_mjcf_body_anywhere_under_worldbody_is_found() {
        let lower = "<inertial pos='0 0 0.2' mass='0.5' fullinertia='1 1 1 0 0 0' />";
        assert_replaced(MJCF, Dialect::Mjcf, "lower", lower, "\t");
        let upper = r#"<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>"#;
        assert_replaced(MJCF, Dialect::Mjcf, "upper", upper, "      ");
    }

    #[test]
    fn an_mjcf_crlf_file_keeps_its_line_endings() {
        let lower = "<inertial pos='0 0 0.2' mass='0.5' fullinertia='1 1 1 0 0 0' />";
        assert_replaced(
            &MJCF.replace('\n', "\r\n"),
            Dialect::Mjcf,
            "lower",
            lower,
            "\t",
        );
    }

    #[test]
    fn a_missing_inertial_is_inserted_as_the_first_child_one_step_in() {
        let text =
            "<robot name=\"r\">\n    <link name=\"a\">\n        <visual/>\n    </link>\n</robot>\n";
        let e = export();
        let element = inertial_element(Dialect::Urdf, &e, "        ");
        assert_eq!(
            update(text, Dialect::Urdf, "a", &e).unwrap(),
            format!(
                "<robot name=\"r\">\n    <link name=\"a\">\n        {element}\n        <visual/>\n    </link>\n</robot>\n"
            )
        );
    }

    #[test]
    fn an_inserted_inertial_takes_the_files_tabs_and_crlf() {
        let text = "<mujoco>\r\n<worldbody>\r\n\t<body name=\"b\">\r\n\t\t<geom size=\"1\"/>\r\n\t</body>\r\n</worldbody>\r\n</mujoco>";
        let e = export();
        let element = inertial_element(Dialect::Mjcf, &e, "\t\t");
        assert_eq!(
            update(text, Dialect::Mjcf, "b", &e).unwrap(),
            format!(
                "<mujoco>\r\n<worldbody>\r\n\t<body name=\"b\">\r\n\t\t{element}\r\n\t\t<geom size=\"1\"/>\r\n\t</body>\r\n</worldbody>\r\n</mujoco>"
            )
        );
        let sdf = "<sdf>\r\n\t<model name=\"m\">\r\n\t\t<link name=\"l\">\r\n\t\t\t<pose>0 0 0 0 0 0</pose>\r\n\t\t</link>\r\n\t</model>\r\n</sdf>\r\n";
        let element = inertial_element(Dialect::Sdf, &e, "\t\t\t").replace('\n', "\r\n");
        assert_eq!(
            update(sdf, Dialect::Sdf, "l", &e).unwrap(),
            format!(
                "<sdf>\r\n\t<model name=\"m\">\r\n\t\t<link name=\"l\">\r\n\t\t\t{element}\r\n\t\t\t<pose>0 0 0 0 0 0</pose>\r\n\t\t</link>\r\n\t</model>\r\n</sdf>\r\n"
            )
        );
    }

    #[test]
    fn an_empty_element_link_is_opened_around_its_new_inertial() {
        let text = "<robot>\n\t<link name=\"base\"/>\n\t<link name='tip' />\n</robot>";
        let e = export();
        let element = inertial_element(Dialect::Urdf, &e, "\t\t");
        let out = update(text, Dialect::Urdf, "tip", &e).unwrap();
        assert_eq!(
            out,
            format!(
                "<robot>\n\t<link name=\"base\"/>\n\t<link name='tip'>\n\t\t{element}\n\t</link>\n</robot>"
            )
        );
        // And one with nothing inside its two tags.
        let text = "<robot>\n  <link name=\"tip\"></link>\n</robot>";
        let element = inertial_element(Dialect::Urdf, &e, "    ");
        assert_eq!(
            update(text, Dialect::Urdf, "tip", &e).unwrap(),
            format!("<robot>\n  <link name=\"tip\">\n    {element}\n  </link>\n</robot>")
        );
    }

    #[test]
    fn a_missing_link_is_an_error_that_lists_names_and_suggests_one() {
        let err = update(URDF, Dialect::Urdf, "armm", &export()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "no link named \"armm\" (the file has \"base\", \"arm\"); did you mean \"arm\"?"
        );
        assert_eq!(err.at(), None);
        let many: String = (1..=8).map(|i| format!("<body name=\"b{i}\"/>")).collect();
        let text = format!("<mujoco><worldbody>{many}</worldbody></mujoco>");
        let err = update(&text, Dialect::Mjcf, "hand", &export()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "no body named \"hand\" (the file has \"b1\", \"b2\", \"b3\", \"b4\", \"b5\" and 3 more)"
        );
        // A <link> inside an SDFormat plugin is not one of the model's.
        let err = update(SDF, Dialect::Sdf, "finger", &export()).unwrap_err();
        assert!(
            matches!(err, UpdateError::NoLink { ref names, .. } if names == &["base", "gripper::finger"])
        );
        let err = update("<robot/>", Dialect::Urdf, "a", &export()).unwrap_err();
        assert_eq!(err.to_string(), "no link named \"a\": the file has none");
    }

    #[test]
    fn two_links_of_one_name_are_an_error_at_the_second() {
        let text = "<robot>\n<link name=\"a\"/>\n<link name=\"a\"/>\n</robot>";
        let err = update(text, Dialect::Urdf, "a", &export()).unwrap_err();
        assert_eq!(err.to_string(), "more than one link named \"a\"");
        assert_eq!(err.at(), Some(text.rfind("<link").unwrap()));
    }

    #[test]
    fn two_inertials_in_a_link_are_an_error_at_the_second() {
        let text = "<mujoco><worldbody><body name=\"b\">\n<inertial mass=\"1\"/>\n<inertial mass=\"2\"/>\n</body></worldbody></mujoco>";
        let err = update(text, Dialect::Mjcf, "b", &export()).unwrap_err();
        assert_eq!(err.to_string(), "body \"b\" has more than one <inertial>");
        assert_eq!(err.at(), Some(text.rfind("<inertial").unwrap()));
    }

    #[test]
    fn text_that_is_not_xml_is_an_error_with_its_place() {
        let text = "<robot>\n  <link name=\"a\">\n</robot>";
        let err = update(text, Dialect::Urdf, "a", &export()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "not well-formed XML: expected 'link' tag, not 'robot'"
        );
        assert_eq!(err.at(), text.find("</robot>"));
        // Past the first line, the column counts characters, not bytes.
        let text = "<robot>\n<link name=\"é\" x=1/></robot>";
        let err = update(text, Dialect::Urdf, "a", &export()).unwrap_err();
        assert_eq!(err.at(), text.find('1'));
    }

    #[test]
    fn models_nested_too_deep_are_an_error_not_a_stack_overflow() {
        // SDFormat models are walked recursively: 100,000 nested ones
        // overflowed the stack.
        let n = 100_000;
        let text = format!(
            "<sdf version='1.9'>{}{}</sdf>",
            "<model name='m'><link name='l'/>".repeat(n),
            "</model>".repeat(n)
        );
        let err = update(&text, Dialect::Sdf, "l", &export()).unwrap_err();
        assert!(
            err.to_string().contains("is nested 1000 elements deep"),
            "{err}"
        );
        // The first element at depth 1000 (`<sdf>` is at 1): the link of
        // the 998th model.
        let model = |k: usize| "<sdf version='1.9'>".len() + 32 * (k - 1);
        assert_eq!(err.at(), Some(model(998) + "<model name='m'>".len()));
    }

    #[test]
    fn a_root_element_of_another_format_is_an_error() {
        let err = update(SDF, Dialect::Urdf, "base", &export()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "the root element is <sdf>, not the <robot> of a urdf file"
        );
        assert_eq!(err.at(), Some(SDF.find("<sdf").unwrap()));
    }

    #[test]
    fn the_diff_of_an_update_shows_the_old_and_new_inertial() {
        let out = update(MJCF, Dialect::Mjcf, "upper", &export()).unwrap();
        let diff = super::super::unified_diff(MJCF, &out, "arm.xml");
        let old = r#"      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>"#;
        let new = format!(
            "      {}",
            inertial_element(Dialect::Mjcf, &export(), "      ")
        );
        assert_eq!(
            diff,
            format!(
                "--- a/arm.xml\n+++ b/arm.xml\n@@ -5,7 +5,7 @@\n     <light pos=\"0 0 3\"/>\n     <body name=\"upper\" pos=\"0 0 1\">\n       <joint name=\"shoulder\"/>\n-{old}\n+{new}\n       <geom type=\"capsule\" size=\".05 .5\"/>\n       <body name='lower' pos=\"0 0 1\">\n \t<joint name=\"elbow\"/>\n"
            )
        );
    }
}
