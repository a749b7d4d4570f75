//! Reading URDF, SDFormat and MJCF files into a `Description`: the XML is
//! parsed once (roxmltree, which keeps every node's and attribute's bytes),
//! then read by the format's own module (`urdf`, `sdf`, `mjcf`). This file
//! holds what they share: values with the bytes a message points at, numbers
//! and lists of numbers, keywords, and the roll-pitch-yaw turn that URDF and
//! SDFormat both write.
//!
//! A reader reads what the file says and refuses only what it cannot read
//! (a word where a number belongs, a required value missing); whether the
//! values make a valid inertial is the engine checks' question, so negative
//! masses and moments are read as given.

mod follow;
mod geometry;
mod links;
mod mjcf;
mod mjcf_class;
mod mjcf_geoms;
mod mjcf_include;
mod mjcf_mesh;
mod orient;
mod sdf;
mod sdf_frames;
mod sdf_include;
mod sdf_tree;
mod tree;
mod urdf;

pub use geometry::{Amount, Geometry, MeshMass, Solid, geometry, scaled};
pub use mjcf_mesh::MeshWarning;
pub use tree::{Resolve, tree};

/// An MJCF file's bodies' geoms that count for inertia (`mjcf_geoms.rs`),
/// for `geometry.rs`: through here, so that neither imports the other.
fn geoms_of_mjcf(
    xml: &Xml,
    mujoco: Node,
    d: &Description,
    need: Option<&[bool]>,
) -> Result<(Vec<Vec<Geometry>>, Vec<MeshWarning>), Diagnostic> {
    mjcf_geoms::geoms(
        &mjcf_include::Model::single(xml.source, mujoco),
        d,
        need,
        true,
    )
}

/// Per body of the MJCF description `d`, its geoms that count for inertia,
/// read only for the bodies `need` marks (a geom massprop cannot weigh is
/// refused only where it is needed); the file's includes followed,
/// resolved by `r` (`robot::weigh`; `export --from-geometry` with
/// `export`, which weighs solids); with the warnings of the mesh files
/// read.
pub fn mjcf_geometry_in(
    source: &Source,
    d: &Description,
    need: &[bool],
    r: &Resolve,
    export: bool,
) -> Result<(Vec<Vec<Geometry>>, Vec<MeshWarning>), Diagnostic> {
    mjcf_include::with_model(source, r, |m| mjcf_geoms::geoms(m, d, Some(need), export))
}

pub use follow::{canonical_dir, read_in};
pub use sdf_include::{chain, located};

use super::{Description, Dialect};
use crate::diag::{Diagnostic, Source, shorten};
use crate::numeric::M3;
use roxmltree::{Document, Node, ParsingOptions};
use std::ops::Range;

/// Read `source` as a robot description of `format` (from `Dialect::of_path`
/// or `Dialect::of_text`), its includes followed from the file's own
/// directory (`read_in` without `--package` or `--include-root`).
pub fn read(source: &Source, format: Dialect) -> Result<Description, Diagnostic> {
    read_in(source, format, &Resolve::default())
}

/// Refuse a root element that is not `format`'s.
fn root(xml: &Xml, root: Node, format: Dialect) -> Result<(), Diagnostic> {
    let expected = match format {
        Dialect::Urdf => "robot",
        Dialect::Sdf => "sdf",
        Dialect::Mjcf => "mujoco",
    };
    let found = qname(root);
    if found != expected {
        return Err(xml.error(
            xml.tag(root),
            format!(
                "expected the root element `<{expected}>` of a {} file, found `<{}>`",
                format.name(),
                shorten(found)
            ),
        ));
    }
    Ok(())
}

/// The document, or roxmltree's message at the place it names.
pub(crate) fn parse(source: &Source) -> Result<Document<'_>, Diagnostic> {
    // NOTE: a DTD is allowed (some exporters write one, and MuJoCo's and
    // urdfdom's parsers accept it), and so are the entities it declares,
    // but not a reference to one (`entity_in_use`); roxmltree still guards
    // against entity expansion bombs.
    let options = ParsingOptions {
        allow_dtd: true,
        ..ParsingOptions::default()
    };
    let doc = Document::parse_with_options(&source.text, options).map_err(|e| {
        let pos = e.pos();
        let at = offset_of(&source.text, pos.row, pos.col);
        let width = source.text[at..].chars().next().map_or(0, char::len_utf8);
        // The place is in the diagnostic's own `line:col`, so the message
        // need not repeat it.
        let message = e.to_string().replace(&format!(" at {pos}"), "");
        source.error(at..at + width, format!("not well-formed xml: {message}"))
    })?;
    if let Some(deep) = too_deep(&doc) {
        let xml = Xml { source };
        return Err(xml
            .error(
                xml.tag(deep),
                format!(
                    "`<{}>` is nested {MAX_DEPTH} elements deep: no robot description nests that deep, and the simulators' XML parser (tinyxml2) refuses it",
                    shorten(qname(deep))
                ),
            )
            .help("a chain of bodies this long is a generated or damaged file"));
    }
    if let Some(e) = entity_in_use(&source.text, &doc) {
        return Err(e.diagnostic(source));
    }
    Ok(doc)
}

/// A reference to an entity the document's doctype declares (`&name;`),
/// where it is and where the entity is declared.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct EntityInUse {
    /// The reference's bytes, `&name;`.
    pub at: Range<usize>,
    /// Where the doctype declares it (`<!ENTITY name`), if found.
    pub declared: Option<usize>,
}

impl EntityInUse {
    /// Why the file is refused, in a sentence for `export --update` too.
    pub(crate) fn message(&self, text: &str) -> String {
        let reference = &text[self.at.clone()];
        let declared = match self.declared {
            Some(d) => {
                let line = text[..d].matches('\n').count() + 1;
                format!(" (declared on line {line})")
            }
            None => String::new(),
        };
        format!(
            "`{}` refers to an entity of the doctype{declared}: the simulators' XML parser (tinyxml2, in MuJoCo and Gazebo) does not expand it, and reads `{}` itself",
            shorten(reference),
            shorten(reference)
        )
    }

    pub(crate) const HELP: &'static str = "write the entity's text in place of each reference (`xmllint --noent FILE` prints the file so); XML's own `&lt;` `&gt;` `&amp;` `&apos;` `&quot;` and character references such as `&#48;` are read alike everywhere";

    fn diagnostic(&self, source: &Source) -> Diagnostic {
        source
            .error(self.at.clone(), self.message(&source.text))
            .help(Self::HELP)
    }
}

/// The first reference (in document order) to an entity other than XML's
/// five (`lt`, `gt`, `amp`, `apos`, `quot`) and character references
/// (`&#48;`): an entity the doctype declares, which roxmltree expands and
/// tinyxml2 (MuJoCo, libsdformat) does not. MuJoCo 4 refuses
/// `mass="&m;"` ("bad format in attribute 'mass'") and names a body
/// `name="&n;"` literally `&n;`; so a reference is refused, while a
/// declaration no element uses is read as the simulators read it, passed
/// over.
///
/// NOTE: `doc` is well-formed, so in the root element every `&` outside a
/// comment, CDATA section or processing instruction begins a reference
/// ending at the next `;` (an attribute value holds no `<`, so neither of
/// those can begin inside one). Without a doctype roxmltree has already
/// refused any reference but the predefined ones.
pub(crate) fn entity_in_use(text: &str, doc: &Document) -> Option<EntityInUse> {
    let root = doc.root_element().range();
    let prolog = &text[..root.start];
    if !prolog.contains("<!DOCTYPE") {
        return None;
    }
    let bytes = text.as_bytes();
    let mut i = root.start;
    while i < root.end {
        match bytes[i] {
            b'<' => {
                let rest = &text[i..root.end];
                let close = if rest.starts_with("<!--") {
                    "-->"
                } else if rest.starts_with("<![CDATA[") {
                    "]]>"
                } else if rest.starts_with("<?") {
                    "?>"
                } else {
                    i += 1;
                    continue;
                };
                i += rest.find(close).map_or(rest.len(), |k| k + close.len());
            }
            b'&' => {
                let end = i + text[i..root.end].find(';')?;
                let name = &text[i + 1..end];
                if !name.starts_with('#') && !matches!(name, "lt" | "gt" | "amp" | "apos" | "quot")
                {
                    return Some(EntityInUse {
                        at: i..end + 1,
                        declared: declaration(prolog, name),
                    });
                }
                i = end + 1;
            }
            _ => i += 1,
        }
    }
    None
}

/// Where the prolog declares the general entity `name` (`<!ENTITY name`),
/// comments passed over.
fn declaration(prolog: &str, name: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(k) = prolog[from..].find("<!") {
        let at = from + k;
        let rest = &prolog[at..];
        if rest.starts_with("<!--") {
            from = at + rest.find("-->").map_or(rest.len(), |e| e + 3);
            continue;
        }
        if let Some(decl) = rest.strip_prefix("<!ENTITY") {
            let decl = decl.trim_start_matches(|c: char| c.is_ascii_whitespace());
            let declared = decl
                .split(|c: char| c.is_ascii_whitespace())
                .next()
                .unwrap_or("");
            if declared == name {
                return Some(at);
            }
        }
        from = at + 2;
    }
    None
}

/// The deepest an element may be nested (the root element is at depth 1).
/// NOTE: deep enough for any robot (a chain of a few hundred MJCF bodies,
/// each with a joint and a geom, stays far below it); beyond it a reader's
/// walk of a tree, or the nested names of SDFormat models, would grow with
/// the square of the depth. tinyxml2, which MuJoCo and libsdformat parse
/// with, stops at a fixed depth too (`TINYXML2_MAX_ELEMENT_DEPTH`).
pub(crate) const MAX_DEPTH: usize = 1000;

/// The start tag, `<name …>` (`/>` included), of the element whose bytes
/// are `range` in `text`: found by scanning past quoted attribute values,
/// which may hold `>`.
pub fn start_tag(text: &str, range: Range<usize>) -> Range<usize> {
    let bytes = &text.as_bytes()[range.clone()];
    let mut quote = None;
    for (i, &b) in bytes.iter().enumerate() {
        match (quote, b) {
            (None, b'"' | b'\'') => quote = Some(b),
            (Some(q), _) if q == b => quote = None,
            (None, b'>') => return range.start..range.start + i + 1,
            _ => {}
        }
    }
    range
}

/// The first element (in document order) nested `MAX_DEPTH` deep, if any;
/// in one pass, without recursion: each node's depth is its parent's plus
/// one, and a parent comes before its children.
pub(crate) fn too_deep<'a, 'i>(doc: &'a Document<'i>) -> Option<Node<'a, 'i>> {
    let mut depth: Vec<usize> = Vec::new();
    for n in doc.root().descendants() {
        let d = n.parent().map_or(0, |p| {
            depth.get(p.id().get() as usize).copied().unwrap_or(0) + 1
        });
        let i = n.id().get() as usize;
        if depth.len() <= i {
            depth.resize(i + 1, 0);
        }
        depth[i] = d;
        if n.is_element() && d >= MAX_DEPTH {
            return Some(n);
        }
    }
    None
}

/// An element's name as written, its prefix included: `xacro:link` is no
/// `link`, as the simulators' parsers (tinyxml2, which knows no namespaces)
/// read it. Empty for a node that is not an element.
pub(crate) fn qname<'i>(node: Node<'_, 'i>) -> &'i str {
    if !node.is_element() {
        return "";
    }
    let text = node.document().input_text();
    let tag = &text[node.range().start + 1..];
    let end = tag
        .find(|c: char| c.is_ascii_whitespace() || c == '>' || c == '/')
        .unwrap_or(tag.len());
    &tag[..end]
}

/// The byte offset of roxmltree's 1-based row and column (columns count
/// characters, as `Source::line_col` does).
fn offset_of(text: &str, row: u32, col: u32) -> usize {
    let mut start = 0;
    for _ in 1..row {
        match text[start..].find('\n') {
            Some(i) => start += i + 1,
            None => return text.len(),
        }
    }
    text[start..]
        .char_indices()
        .nth(col.saturating_sub(1) as usize)
        .map_or(text.len(), |(i, _)| start + i)
}

/// A value as the file wrote it, an attribute's or an element's text, with
/// the bytes a message points at.
#[derive(Clone, Debug)]
struct Value {
    /// How messages name it: `` `ixy` `` for an attribute, `` `<ixx>` ``
    /// for an element's text.
    name: String,
    /// The text, trimmed (an attribute's as XML normalises it).
    text: String,
    /// The value's bytes (the element's start tag when it has no text).
    range: Range<usize>,
    /// Whether `range` holds `text` byte for byte (no entity or character
    /// reference), so that one number of a list can be pointed at.
    exact: bool,
}

/// The text being read, for located messages.
struct Xml<'s> {
    source: &'s Source,
}

impl Xml<'_> {
    fn error(&self, range: Range<usize>, message: impl Into<String>) -> Diagnostic {
        self.source.error(range, message)
    }

    /// An element's start tag, `<name …>` (`/>` included), found by
    /// scanning past quoted attribute values, which may hold `>`.
    fn tag(&self, node: Node) -> Range<usize> {
        start_tag(&self.source.text, node.range())
    }

    /// The attribute `name` of `node`, when given.
    fn attr(&self, node: Node, name: &str) -> Option<Value> {
        let a = node.attribute_node(name)?;
        let raw = a.range_value();
        let text = a.value();
        let trimmed = trim_range(&self.source.text, raw.clone());
        let exact = &self.source.text[raw.clone()] == text;
        Some(Value {
            name: format!("`{name}`"),
            text: text.trim().to_string(),
            // A value with references keeps its whole range: the trimmed
            // bytes might not be the trimmed text's.
            range: if exact { trimmed } else { raw },
            exact,
        })
    }

    /// The attribute `name` of `node`, which `owner`'s element needs.
    fn required(&self, node: Node, name: &str, owner: &str) -> Result<Value, Diagnostic> {
        self.attr(node, name).ok_or_else(|| {
            self.error(
                self.tag(node),
                format!(
                    "`<{}>` of {owner} is missing the required attribute `{name}`",
                    qname(node)
                ),
            )
        })
    }

    /// An element's text (its text children, comments left out).
    fn text(&self, node: Node) -> Value {
        let texts: Vec<Node> = node.children().filter(|c| c.is_text()).collect();
        let text: String = texts.iter().filter_map(|t| t.text()).collect();
        let range = match (texts.first(), texts.last()) {
            (Some(a), Some(b)) => trim_range(&self.source.text, a.range().start..b.range().end),
            _ => 0..0,
        };
        let text = text.trim();
        let exact = texts.len() == 1 && &self.source.text[range.clone()] == text;
        Value {
            name: format!("`<{}>`", qname(node)),
            text: text.to_string(),
            range: if range.is_empty() {
                self.tag(node)
            } else {
                range
            },
            exact,
        }
    }

    /// `v` as one finite number.
    fn number(&self, v: &Value, owner: &str) -> Result<f64, Diagnostic> {
        self.parse_number(&v.text, v.range.clone(), v, owner)
    }

    /// `v` as exactly `N` numbers separated by whitespace.
    fn numbers<const N: usize>(&self, v: &Value, owner: &str) -> Result<[f64; N], Diagnostic> {
        let list = self.list(v, owner)?;
        <[f64; N]>::try_from(list.as_slice()).map_err(|_| {
            self.error(
                v.range.clone(),
                format!(
                    "{} of {owner}: expected {N} numbers, found {}",
                    v.name,
                    list.len()
                ),
            )
        })
    }

    /// `v` as numbers separated by whitespace (ASCII whitespace, as
    /// urdfdom, libsdformat and MuJoCo split them; not commas).
    fn list(&self, v: &Value, owner: &str) -> Result<Vec<f64>, Diagnostic> {
        tokens(&v.text)
            .map(|(at, token)| {
                let range = if v.exact {
                    v.range.start + at..v.range.start + at + token.len()
                } else {
                    v.range.clone()
                };
                self.parse_number(token, range, v, owner)
            })
            .collect()
    }

    fn parse_number(
        &self,
        text: &str,
        range: Range<usize>,
        v: &Value,
        owner: &str,
    ) -> Result<f64, Diagnostic> {
        let text = text.trim();
        match text.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            Ok(_) => Err(self.error(
                range,
                format!(
                    "{} of {owner}: expected a finite number, found {}",
                    v.name,
                    quoted(text)
                ),
            )),
            Err(_) => Err(self.error(
                range,
                format!(
                    "{} of {owner}: expected a number, found {}",
                    v.name,
                    if text.is_empty() {
                        "nothing".to_string()
                    } else {
                        quoted(text)
                    }
                ),
            )),
        }
    }

    /// `v` as one of `choices`' words (exact, case included).
    fn keyword<T: Copy>(
        &self,
        v: &Value,
        owner: &str,
        choices: &[(&str, T)],
    ) -> Result<T, Diagnostic> {
        if let Some((_, t)) = choices.iter().find(|(word, _)| *word == v.text) {
            return Ok(*t);
        }
        let words: Vec<String> = choices.iter().map(|(w, _)| format!("`{w}`")).collect();
        Err(self.error(
            v.range.clone(),
            format!(
                "{} of {owner}: expected {}, found {}",
                v.name,
                or_list(&words),
                quoted(&v.text)
            ),
        ))
    }
}

/// `a`, `a or b`, `a, b or c`.
fn or_list(words: &[String]) -> String {
    match words {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} or {last}", rest.join(", ")),
    }
}

/// A name or value from the file as a message quotes it.
fn quoted(text: &str) -> String {
    format!("\"{}\"", shorten(text))
}

/// The whitespace-separated words of `text` with their byte offsets.
fn tokens(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.split(|c: char| c.is_ascii_whitespace())
        .filter(|t| !t.is_empty())
        .map(move |t| (t.as_ptr() as usize - text.as_ptr() as usize, t))
}

/// `range` without the whitespace at its ends.
fn trim_range(text: &str, range: Range<usize>) -> Range<usize> {
    let s = &text[range.clone()];
    let start = range.start + (s.len() - s.trim_start().len());
    let end = range.end - (s.len() - s.trim_end().len());
    start..end.max(start)
}

/// The element children of `node` named `name`, in document order.
fn children<'a, 'i>(node: Node<'a, 'i>, name: &'a str) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children().filter(move |c| qname(*c) == name)
}

/// The first element child of `node` named `name`.
fn child<'a, 'i>(node: Node<'a, 'i>, name: &'a str) -> Option<Node<'a, 'i>> {
    children(node, name).next()
}

/// `m`, or None when it is exactly no turn: the reader's `rotation` is None
/// exactly when the file gives no turn.
fn turn(m: M3<f64>) -> Option<M3<f64>> {
    let identity = (0..3).all(|i| (0..3).all(|j| m[i][j] == if i == j { 1.0 } else { 0.0 }));
    (!identity).then_some(m)
}

/// `m`, formed from `v`, if it is a rotation: finite, its columns unit
/// length and perpendicular (to 1e-9). A quaternion or axis whose length
/// overflows f64 or is too small to normalise gives none (MuJoCo's
/// normalisation leaves a tiny quaternion as it is, and divides a huge one
/// by infinity): a frame that is no rotation would scale or zero the
/// tensor in the link frame without a word.
fn proper(xml: &Xml, v: &Value, owner: &str, m: M3<f64>) -> Result<M3<f64>, Diagnostic> {
    let mut ok = m.iter().flatten().all(|x| x.is_finite());
    for i in 0..3 {
        for j in 0..3 {
            let dot: f64 = (0..3).map(|k| m[k][i] * m[k][j]).sum();
            let want = if i == j { 1.0 } else { 0.0 };
            ok &= (dot - want).abs() <= 1e-9;
        }
    }
    if ok {
        Ok(m)
    } else {
        Err(xml.error(
            v.range.clone(),
            format!(
                "{} of {owner} gives no rotation: its length is too small or too large to normalise in f64",
                v.name
            ),
        ))
    }
}

/// R = Rz(yaw)·Ry(pitch)·Rx(roll), URDF's `rpy` and SDFormat's pose angles
/// (turns about the fixed x, then y, then z axes), from each angle's sine
/// and cosine: the columns are the turned frame's axes.
fn rpy(roll: (f64, f64), pitch: (f64, f64), yaw: (f64, f64)) -> M3<f64> {
    let ((sr, cr), (sp, cp), (sy, cy)) = (roll, pitch, yaw);
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(super) fn source(text: &str) -> Source {
        Source::new("r.xml", text)
    }

    /// Each column of `m` against the expected column, within 1e-15.
    pub(super) fn assert_matrix(m: M3<f64>, expected: M3<f64>) {
        for i in 0..3 {
            for j in 0..3 {
                assert!(
                    (m[i][j] - expected[i][j]).abs() <= 1e-15,
                    "{m:?} is not {expected:?}"
                );
            }
        }
    }

    #[test]
    fn malformed_xml_is_reported_at_roxmltrees_place_without_repeating_it() {
        let text = "<robot name='r'>\n  <link name='a'>\n</robot>\n";
        let d = read(&source(text), Dialect::Urdf).unwrap_err().to_string();
        assert!(
            d.starts_with(
                "r.xml:3:1: error: not well-formed xml: expected 'link' tag, not 'robot'\n"
            ),
            "{d}"
        );
    }

    #[test]
    fn a_root_element_of_another_format_is_refused() {
        let text = "<?xml version='1.0'?>\n<mujoco model='m'/>\n";
        let d = read(&source(text), Dialect::Urdf).unwrap_err().to_string();
        assert!(
            d.starts_with(
                "r.xml:2:1: error: expected the root element `<robot>` of a urdf file, found `<mujoco>`\n"
            ),
            "{d}"
        );
    }

    /// A URDF of one link of mass `mass`, after the doctype `doctype`.
    fn with_doctype(doctype: &str, mass: &str) -> String {
        format!(
            "<?xml version='1.0'?>\n{doctype}\n<robot name='r'><link name='a'><inertial><mass value='{mass}'/><inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link></robot>"
        )
    }

    #[test]
    fn a_doctype_declaring_entities_no_element_uses_is_allowed() {
        let text = with_doctype("<!DOCTYPE robot [<!ENTITY m '2'>]>", "2");
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        assert_eq!(d.links[0].inertial.as_ref().unwrap().mass, 2.0);
    }

    #[test]
    fn a_reference_to_a_declared_entity_is_refused_at_the_reference() {
        let text = with_doctype("<!DOCTYPE robot [\n<!ENTITY m '2'>\n]>", "&m;");
        let d = read(&source(&text), Dialect::Urdf).unwrap_err().to_string();
        // Line 5 (the declaration, the doctype's lines, then the robot),
        // column of `&m;` in `<mass value='&m;'/>`.
        let column = text.lines().nth(4).unwrap().find("&m;").unwrap() + 1;
        assert!(
            d.starts_with(&format!(
                "r.xml:5:{column}: error: `&m;` refers to an entity of the doctype (declared on line 3): "
            )),
            "{d}"
        );
    }

    #[test]
    fn xmls_own_entities_and_character_references_are_read() {
        let text = with_doctype("<!DOCTYPE robot [<!ENTITY m '3'>]>", "&#50;");
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        assert_eq!(d.links[0].inertial.as_ref().unwrap().mass, 2.0);
        let text = text.replace("name='a'", "name='a&amp;b&lt;&gt;&apos;&quot;'");
        let d = read(&source(&text), Dialect::Urdf).unwrap();
        assert_eq!(d.links[0].name, "a&b<>'\"");
    }

    #[test]
    fn an_ampersand_in_a_comment_or_cdata_is_no_reference() {
        let text = with_doctype("<!DOCTYPE robot [<!ENTITY m '2'>]>", "2").replace(
            "<link name='a'>",
            "<!-- &m; --><link name='a'><![CDATA[&m;]]><?pi &m;?>",
        );
        assert!(read(&source(&text), Dialect::Urdf).is_ok());
    }

    #[test]
    fn a_declaration_inside_a_comment_is_not_the_one_named() {
        let text = with_doctype(
            "<!DOCTYPE robot [\n<!-- <!ENTITY m 'no'> -->\n<!ENTITY m '2'>\n]>",
            "&m;",
        );
        let d = read(&source(&text), Dialect::Urdf).unwrap_err().to_string();
        assert!(d.contains("(declared on line 4)"), "{d}");
    }

    #[test]
    fn elements_nested_too_deep_are_refused_at_the_first_too_deep() {
        // The root is at depth 1: MAX_DEPTH - 1 nested bodies under the
        // world body reach MAX_DEPTH exactly.
        let nest = |n: usize| {
            format!(
                "<mujoco>\n<worldbody>\n{}{}</worldbody></mujoco>",
                "<body>\n".repeat(n),
                "</body>".repeat(n)
            )
        };
        assert!(read(&source(&nest(MAX_DEPTH - 3)), Dialect::Mjcf).is_ok());
        let d = read(&source(&nest(MAX_DEPTH - 2)), Dialect::Mjcf).unwrap_err();
        assert!(
            d.to_string().starts_with(&format!(
                "r.xml:{}:1: error: `<body>` is nested {MAX_DEPTH} elements deep",
                MAX_DEPTH
            )),
            "{d}"
        );
    }

    #[test]
    fn a_prefixed_element_is_not_the_element_of_that_name() {
        // `<x:link>` is no link to urdfdom (tinyxml knows no namespaces),
        // and `update` does not take it for one either.
        let text = "<robot name='r' xmlns:x='u'><x:link name='a'/><link name='b'><x:inertial/></link></robot>";
        let d = read(&source(text), Dialect::Urdf).unwrap();
        assert_eq!(d.links.len(), 1);
        assert_eq!(d.links[0].name, "b");
        assert_eq!(d.links[0].inertial, None);
    }

    #[test]
    fn roll_pitch_yaw_is_z_then_y_then_x() {
        // A quarter roll, then a quarter pitch about the fixed y, no yaw:
        // R = Ry·Rx, by hand. Its first column, x turned, is Ry x̂ = −ẑ.
        let quarter = (1.0, 0.0);
        let none = (0.0, 1.0);
        let m = rpy(quarter, quarter, none);
        assert_matrix(m, [[0.0, 1.0, 0.0], [0.0, 0.0, -1.0], [-1.0, 0.0, 0.0]]);
    }

    #[test]
    fn an_identity_is_no_turn() {
        let zero = (0.0, 1.0);
        assert_eq!(turn(rpy(zero, zero, zero)), None);
        assert!(turn(rpy((-0.0, 1.0), zero, (1e-300, 1.0))).is_some());
    }

    #[test]
    fn tokens_keep_their_offsets() {
        let t: Vec<_> = tokens(" 1\t2.5  x ").collect();
        assert_eq!(t, vec![(1, "1"), (3, "2.5"), (8, "x")]);
    }

    #[test]
    fn a_word_in_a_list_is_pointed_at() {
        let text = "<robot name='r'><link name='a'><inertial><origin xyz='0 abc 0'/><mass value='1'/><inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link></robot>";
        let d = read(&source(text), Dialect::Urdf).unwrap_err();
        assert_eq!(
            d.message(),
            "`xyz` of link \"a\": expected a number, found \"abc\""
        );
        let at = text.find("abc").unwrap();
        assert!(
            d.to_string().starts_with(&format!("r.xml:1:{}:", at + 1)),
            "{d}"
        );
    }

    #[test]
    fn a_start_tag_ends_at_the_first_unquoted_bracket() {
        let text = "<robot name='a>b'><link name=\"x>\"/></robot>";
        let src = source(text);
        let doc = Document::parse(text).unwrap();
        let xml = Xml { source: &src };
        let root = doc.root_element();
        assert_eq!(&text[xml.tag(root)], "<robot name='a>b'>");
        let link = child(root, "link").unwrap();
        assert_eq!(&text[xml.tag(link)], "<link name=\"x>\"/>");
    }
}
