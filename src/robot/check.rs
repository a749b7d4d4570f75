//! A robot description checked: each link's inertial under each engine
//! asked for, with the margins of the engine's rule, the likely cause of a
//! failure, and warnings a reader of the file would want (mirrored links
//! whose products disagree, duplicate names, links without an inertial).
//! `analysis::check_run` reads the files; `output::check` and `output::ci`
//! write the results.

use super::cause::{self, Cause};
use super::engine::{self, Engine, Facts, Verdict};
use super::steps;
pub use super::steps::steps;
use super::{Description, Dialect};
use crate::diag::{Source, Span, floor_char_boundary};
use serde::Serialize;

/// One engine's verdict on a link, with the likely cause when it fails.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EngineResult {
    #[serde(flatten)]
    pub verdict: Verdict,
    pub cause: Option<Cause>,
}

/// What the file gives of a link's inertial, SI, in the link frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Values {
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    /// The tensor about the centre of mass in the link frame (the
    /// inertial's turn applied), tensor convention: xx, yy, zz, xy, xz, yz.
    pub inertia: [f64; 6],
    /// Ascending.
    pub principal_moments: [f64; 3],
}

/// One link checked.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LinkResult {
    pub name: String,
    /// The file the link is written in when the main file includes it
    /// (as the include names it; None: the main file, whose path the
    /// file's result gives).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// The `<include>`s that bring its file in, innermost first:
    /// `FILE:LINE:COL` each.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub included_from: Vec<String>,
    /// The `<inertial>` element (the link's, when it has none), in the
    /// file it is written in.
    #[serde(flatten)]
    pub span: Span,
    pub moving: bool,
    /// None when the link has no `<inertial>` (or its principal moments,
    /// or its tensor in the link frame, overflow).
    pub inertial: Option<Values>,
    pub engines: Vec<EngineResult>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
}

impl LinkResult {
    /// Whether every engine accepts it.
    pub fn valid(&self) -> bool {
        self.engines.iter().all(|e| e.verdict.valid)
    }

    /// The path of the file it is written in: its own, else `main`'s.
    pub fn path<'a>(&'a self, main: &'a str) -> &'a str {
        self.file.as_deref().unwrap_or(main)
    }
}

/// A robot description's links checked.
#[derive(Clone, Debug, PartialEq)]
pub struct RobotResult {
    pub format: Dialect,
    /// The engines asked for (`--engine`).
    pub engines: Vec<Engine>,
    pub links: Vec<LinkResult>,
}

impl RobotResult {
    pub fn failed(&self) -> bool {
        !self.links.iter().all(LinkResult::valid)
    }
}

/// Check every link of `d` (read from `source`) under `engines`.
pub fn check(source: &Source, d: &Description, engines: &[Engine]) -> RobotResult {
    let mut links = Vec::with_capacity(d.links.len());
    // Each pass over all links is done once, here, not once per link: a
    // description may have 10⁵ links.
    let mut names = std::collections::HashSet::with_capacity(d.links.len());
    let mut tree = Tree::of(d);
    let mirrors = cause::Mirrors::of(&d.links);
    // One `Spans` per file a link is written in, made when first needed.
    let mut spans: Vec<Option<Spans>> = vec![None; d.files.sources.len() + 1];
    for (i, link) in d.links.iter().enumerate() {
        let site = &link.site;
        let text = &d.files.source(source, site.file).text;
        let spans = spans[site.file].get_or_insert_with(|| Spans::new(text));
        let (file, included_from) = match site.file {
            0 => (None, Vec::new()),
            _ => (
                Some(d.files.source(source, site.file).name.clone()),
                site.from.clone(),
            ),
        };
        steps::step(1 + engines.len());
        let mut warnings = Vec::new();
        if !names.insert(link.name.as_str()) {
            warnings.push(format!(
                "another link before this one is named \"{}\": engines refuse duplicate names, and `export --update` cannot tell them apart",
                link.name
            ));
        }
        let Some(inertial) = &link.inertial else {
            // Massless: MuJoCo's verdict where the file leaves it massless
            // (URDF; MJCF without inertia from the geoms); the other
            // engines' inertia for it is their converters' choice, not
            // judged here.
            let massless = match d.format {
                Dialect::Urdf => true,
                Dialect::Mjcf => d.compiler.inertiafromgeom == Some(false),
                Dialect::Sdf => false,
            };
            let mut results = Vec::new();
            if massless && engines.contains(&Engine::Mujoco) {
                let facts = Facts {
                    mass: 0.0,
                    tensor: super::Tensor::default(),
                    written: if d.format == Dialect::Urdf {
                        super::Written::Attributes
                    } else {
                        super::Written::Diagonal
                    },
                    moving: link.moving,
                    rescued: link.moving && tree.carried(d, i),
                };
                let verdict = engine::judge(Engine::Mujoco, &facts, &d.compiler);
                results.push(EngineResult {
                    verdict,
                    cause: None,
                });
            }
            match d.format {
                Dialect::Urdf if link.moving => warnings.push(
                    "no <inertial> on a moving link: URDF takes it as massless, which engines refuse unless a fixed child carries mass (MuJoCo fuses it in); Gazebo and Drake not checked".to_string(),
                ),
                Dialect::Sdf => warnings.push(
                    "no explicit <inertial> (or `auto=\"true\"`): Gazebo gives it a mass of 1 kg and a unit tensor, or computes one from its collisions; not checked".to_string(),
                ),
                _ => {}
            }
            links.push(LinkResult {
                name: link.name.clone(),
                file,
                included_from,
                span: spans.span(super::read::start_tag(text, site.element.clone())),
                moving: link.moving,
                inertial: None,
                engines: results,
                warnings,
            });
            continue;
        };
        let facts = Facts {
            mass: inertial.mass,
            tensor: inertial.tensor,
            written: inertial.written,
            moving: link.moving,
            rescued: link.moving && tree.carried(d, i),
        };
        let in_link = inertial.tensor_in_link();
        // NOTE: the turn into the link frame can overflow what the file
        // gives within f64 (a sum of nine products): no values then, as
        // for moments that overflow, rather than infinities.
        let finite = [
            in_link.xx, in_link.yy, in_link.zz, in_link.xy, in_link.xz, in_link.yz,
        ]
        .iter()
        .all(|x| x.is_finite());
        let moments = engine::principal_moments(&inertial.tensor);
        let values = moments.filter(|_| finite).map(|m| Values {
            mass: inertial.mass,
            center_of_mass: inertial.pos,
            inertia: [
                in_link.xx, in_link.yy, in_link.zz, in_link.xy, in_link.xz, in_link.yz,
            ],
            principal_moments: m,
        });
        let results: Vec<EngineResult> = engines
            .iter()
            .map(|&e| {
                let verdict = engine::judge_with(e, &facts, moments, &d.compiler);
                let cause = (!verdict.valid)
                    .then(|| cause::likely(d, &mirrors, i, &facts, e))
                    .flatten();
                EngineResult { verdict, cause }
            })
            .collect();
        // The mirror slip is said once: as the cause where it is one.
        let mirror_cause = results.iter().any(|r: &EngineResult| {
            r.cause
                .as_ref()
                .is_some_and(|c| c.kind == cause::Kind::Mirror)
        });
        if !mirror_cause {
            warnings.extend(cause::mirror_warning(d, &mirrors, i));
        }
        if let (Some(v), Some(element)) = (&values, text.get(site.element.clone())) {
            let judged = super::plausible::Link {
                element,
                mass: v.mass,
                principal_moments: v.principal_moments,
                refused: results
                    .iter()
                    .filter(|r| !r.verdict.valid)
                    .map(|r| r.verdict.engine)
                    .collect(),
                units_named: results.iter().any(|r| {
                    r.cause
                        .as_ref()
                        .is_some_and(|c| c.kind == cause::Kind::Units)
                }),
            };
            warnings.extend(super::plausible::gyration(d.format, &judged));
        }
        // NOTE: an inertial MuJoCo computes from the geoms (`weigh`) is
        // written nowhere: the link's element is its place.
        let at = site.inertial.clone().unwrap_or(site.element.clone());
        links.push(LinkResult {
            name: link.name.clone(),
            file,
            included_from,
            span: spans.span(super::read::start_tag(text, at)),
            moving: link.moving,
            inertial: values,
            engines: results,
            warnings,
        });
    }
    RobotResult {
        format: d.format,
        engines: engines.to_vec(),
        links,
    }
}

/// The links' tree, for the walks down from a link: each link's children
/// that do not move.
struct Tree {
    fixed_children: Vec<Vec<usize>>,
    /// Per link, the walk that last saw it (`i + 1` for the walk from link
    /// `i`; 0 for none): one vector for every walk, not one per walk.
    seen: Vec<usize>,
}

impl Tree {
    fn of(d: &Description) -> Tree {
        let mut fixed_children = vec![Vec::new(); d.links.len()];
        for (j, l) in d.links.iter().enumerate() {
            if let Some(p) = l.parent
                && !l.moving
            {
                fixed_children[p].push(j);
            }
        }
        Tree {
            fixed_children,
            seen: vec![0; d.links.len()],
        }
    }

    /// Whether a jointless descendant of link `i`, reached through
    /// jointless links only, has mass and three principal moments of at
    /// least mjMINVAL: MuJoCo then accepts `i` moving without mass of its
    /// own (tests/oracle/MUJOCO-RULES.md, rule 4).
    ///
    /// NOTE: linear in the links walked: a link that does not move has one
    /// parent, so the walks from the moving links cover each link once at
    /// most; `seen` guards a malformed file's cycle of joints.
    fn carried(&mut self, d: &Description, i: usize) -> bool {
        let floor = engine::MJ_MINVAL;
        let heavy = |l: &super::Link| {
            l.inertial.as_ref().is_some_and(|x| {
                x.mass >= floor
                    && engine::principal_moments(&x.tensor).is_some_and(|m| m[0] >= floor)
            })
        };
        let walk = i + 1;
        let mut stack = vec![i];
        self.seen[i] = walk;
        while let Some(p) = stack.pop() {
            steps::step(1 + self.fixed_children[p].len());
            for &j in &self.fixed_children[p] {
                if self.seen[j] != walk {
                    if heavy(&d.links[j]) {
                        return true;
                    }
                    self.seen[j] = walk;
                    stack.push(j);
                }
            }
        }
        false
    }
}

/// `Source::span` for many ranges of one text, each in time proportional
/// to the distance from the one before (links come in document order)
/// rather than from the start of the text: `Source::span` counts the lines
/// before each range, which for 10⁵ links made `check` quadratic.
#[derive(Clone)]
struct Spans<'t> {
    text: &'t str,
    /// The byte offset each line starts at.
    line_starts: Vec<usize>,
    /// The last offset placed and its column, to count a column on from.
    cursor: (usize, usize),
}

impl<'t> Spans<'t> {
    fn new(text: &'t str) -> Spans<'t> {
        steps::step(text.len());
        let line_starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Spans {
            text,
            line_starts,
            cursor: (0, 1),
        }
    }

    /// The 1-based line and column (in characters) of `offset`, as
    /// `Source::line_col` gives them.
    fn line_col(&mut self, offset: usize) -> (usize, usize) {
        let offset = floor_char_boundary(self.text, offset);
        let line = self.line_starts.partition_point(|&s| s <= offset);
        let start = self.line_starts[line - 1];
        let (from, col) = if self.cursor.0 >= start && self.cursor.0 <= offset {
            self.cursor
        } else {
            (start, 1)
        };
        steps::step(1 + offset - from);
        let col = col + self.text[from..offset].chars().count();
        self.cursor = (offset, col);
        (line, col)
    }

    /// `Source::span`, by the same rule (`diag::span_by`).
    fn span(&mut self, range: std::ops::Range<usize>) -> Span {
        let text = self.text;
        crate::diag::span_by(text, range, |offset| self.line_col(offset))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tensor_that_overflows_in_the_link_frame_has_no_values() {
        // Moments at f64::MAX, turned: R I Rᵀ rounds past it, though the
        // moments as written are finite.
        let max = "1.7976931348623157e308";
        let text = format!(
            "<robot name='r'><link name='a'><inertial><origin rpy='0.3 0.4 0.5'/><mass value='1'/><inertia ixx='{max}' ixy='0' ixz='0' iyy='{max}' iyz='0' izz='{max}'/></inertial></link></robot>"
        );
        let source = Source::new("r.urdf", text);
        let d = super::super::read::read(&source, Dialect::Urdf).unwrap();
        let i = d.links[0].inertial.as_ref().unwrap();
        assert!(engine::principal_moments(&i.tensor).is_some());
        let t = i.tensor_in_link();
        assert!(
            !(t.xx.is_finite() && t.yy.is_finite() && t.zz.is_finite()),
            "{t:?}"
        );
        let r = check(&source, &d, &Engine::ALL);
        assert_eq!(r.links[0].inertial, None);
    }

    #[test]
    fn spans_are_those_of_the_source_in_any_order() {
        let text = "<a>\r\n  <é b='ü'>\n<c/>…<d/>\n\n<e/>";
        let source = Source::new("t.xml", text);
        let mut spans = Spans::new(&source.text);
        let n = text.len();
        // Forwards, backwards, and ranges inside characters or past the end.
        let ranges: Vec<std::ops::Range<usize>> = (0..=n + 1)
            .map(|i| i..(i + 3).min(n + 2))
            .chain((0..=n).rev().map(|i| i..i))
            .chain([7..8, 0..n, std::ops::Range { start: 12, end: 9 }])
            .collect();
        for r in ranges {
            assert_eq!(spans.span(r.clone()), source.span(r.clone()), "{r:?}");
        }
    }
}
