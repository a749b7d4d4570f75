//! A robot description checked: each link's inertial under each engine
//! asked for, with the margins of the engine's rule, the likely cause of a
//! failure, and warnings a reader of the file would want (mirrored links
//! whose products disagree, duplicate names, links without an inertial).
//! `commands::check` reads the files; `render::check` and `render::ci`
//! write the results.

use super::cause::{self, Cause};
use super::engine::{self, Engine, Facts, Verdict};
use super::{Description, Format};
use crate::diag::{Source, Span};
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
    /// The `<inertial>` element (the link's, when it has none).
    #[serde(flatten)]
    pub span: Span,
    pub moving: bool,
    /// None when the link has no `<inertial>` (or its principal moments
    /// overflow).
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
}

/// A robot description's links checked.
#[derive(Clone, Debug, PartialEq)]
pub struct RobotResult {
    pub format: Format,
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
    for (i, link) in d.links.iter().enumerate() {
        let mut warnings = Vec::new();
        if d.links[..i].iter().any(|l| l.name == link.name) {
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
                Format::Urdf => true,
                Format::Mjcf => d.compiler.inertiafromgeom == Some(false),
                Format::Sdf => false,
            };
            let mut results = Vec::new();
            if massless && engines.contains(&Engine::Mujoco) {
                let facts = Facts {
                    mass: 0.0,
                    tensor: super::Tensor::default(),
                    written: if d.format == Format::Urdf {
                        super::Written::Attributes
                    } else {
                        super::Written::Diagonal
                    },
                    moving: link.moving,
                    rescued: link.moving && carried(d, i),
                };
                let verdict = engine::judge(Engine::Mujoco, &facts, &d.compiler);
                results.push(EngineResult {
                    verdict,
                    cause: None,
                });
            }
            match d.format {
                Format::Urdf if link.moving => warnings.push(
                    "no <inertial> on a moving link: URDF takes it as massless, which engines refuse unless a fixed child carries mass (MuJoCo fuses it in); Gazebo and Drake not checked".to_string(),
                ),
                Format::Sdf => warnings.push(
                    "no explicit <inertial> (or `auto=\"true\"`): Gazebo gives it a mass of 1 kg and a unit tensor, or computes one from its collisions; not checked".to_string(),
                ),
                _ => {}
            }
            links.push(LinkResult {
                name: link.name.clone(),
                span: source.span(start_tag(source, link.range.clone())),
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
            rescued: link.moving && carried(d, i),
        };
        let in_link = inertial.tensor_in_link();
        let values = engine::principal_moments(&inertial.tensor).map(|m| Values {
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
                let verdict = engine::judge(e, &facts, &d.compiler);
                let cause = (!verdict.valid)
                    .then(|| cause::likely(d, i, &facts, e))
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
            warnings.extend(cause::mirror_warning(d, i));
        }
        links.push(LinkResult {
            name: link.name.clone(),
            span: source.span(start_tag(source, inertial.range.clone())),
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

/// Whether a jointless descendant of link `i`, reached through jointless
/// links only, has mass and three principal moments of at least
/// mjMINVAL: MuJoCo then accepts `i` moving without mass of its own
/// (tests/oracle/MUJOCO-RULES.md, rule 4).
fn carried(d: &Description, i: usize) -> bool {
    let floor = engine::MJ_MINVAL;
    let heavy = |l: &super::Link| {
        l.inertial.as_ref().is_some_and(|x| {
            x.mass >= floor && engine::principal_moments(&x.tensor).is_some_and(|m| m[0] >= floor)
        })
    };
    // Breadth first over fixed children; `seen` guards a malformed file's
    // cycle of joints.
    let mut seen = vec![false; d.links.len()];
    let mut queue = vec![i];
    seen[i] = true;
    while let Some(p) = queue.pop() {
        for (j, l) in d.links.iter().enumerate() {
            if l.parent == Some(p) && !l.moving && !seen[j] {
                if heavy(l) {
                    return true;
                }
                seen[j] = true;
                queue.push(j);
            }
        }
    }
    false
}

/// An element's start tag: where a message points (the whole element may
/// be many lines).
fn start_tag(source: &Source, range: std::ops::Range<usize>) -> std::ops::Range<usize> {
    let text = &source.text[range.clone()];
    let end = text.find('>').map_or(text.len(), |i| i + 1);
    range.start..range.start + end
}
