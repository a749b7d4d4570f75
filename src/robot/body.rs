//! A robot description as one composite body (`report`, `diff`, and a part
//! file's `include`): its links at a configuration (`--joints`, followers
//! followed, unset joints at their zero), which the model composes as
//! sub-assemblies (`model::Model::of_robot_at`), with the warnings of what is
//! composed as written (a link without an inertial, one that is not
//! physically valid, a value beyond a joint's limits). docs/robots.md,
//! "The whole robot", is the contract.

use super::kinematics::{Motion, Tree};
use super::{Description, Dialect, Tensor};
use crate::diag::{Diagnostic, Source};
use crate::units::{self, Dim};

/// A robot description read whole: its links and its tree.
#[derive(Clone, Debug)]
pub struct Robot {
    pub description: Description,
    pub tree: Tree,
    /// The warnings of the MJCF mesh files weighed (`weigh`), each at its
    /// `<mesh>` asset, in whichever file that is written.
    pub mesh_warnings: Vec<super::read::MeshWarning>,
}

/// What a robot's body warns of: where (a byte range of its text) and
/// what.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    pub range: std::ops::Range<usize>,
    pub message: String,
}

impl Robot {
    /// `source`, a robot description of `format`, read with its tree; an
    /// MJCF body weighed from its geoms where MuJoCo's compiler would
    /// (`weigh`).
    pub fn read(source: &Source, format: Dialect) -> Result<Robot, Diagnostic> {
        Robot::read_in(source, format, &Default::default())
    }

    /// `read`, an SDFormat or MJCF file's includes resolved by `r`.
    pub fn read_in(
        source: &Source,
        format: Dialect,
        r: &super::read::Resolve,
    ) -> Result<Robot, Diagnostic> {
        let mut description = super::read::read_in(source, format, r)?;
        let mesh_warnings = super::weigh::mjcf_inertials(source, &mut description, r)?;
        let tree = super::read::tree(source, &mut description, r)?;
        // NOTE: a body of no mass has no centre: said here, in words,
        // rather than as the centre's division by zero overflowing.
        if !description
            .links
            .iter()
            .any(|l| l.inertial.as_ref().is_some_and(|i| i.mass != 0.0))
        {
            let n = description.links.len();
            let root = super::read::parse(source)?.root_element().range();
            return Err(source
                .error(
                    super::read::start_tag(&source.text, root),
                    format!(
                        "the robot has no mass: none of its {n} link{} has an `<inertial>` with mass{}",
                        if n == 1 { "" } else { "s" },
                        match format {
                            Dialect::Mjcf => " or a geom that counts for inertia",
                            Dialect::Urdf | Dialect::Sdf => "",
                        }
                    ),
                )
                .help("a link without an `<inertial>` is massless (URDF, SDFormat); `export ROBOT --from-geometry collision --density …` computes inertials from the geometry"));
        }
        Ok(Robot {
            description,
            tree,
            mesh_warnings,
        })
    }

    /// The joints' values: each at its zero, then `set` (joint index,
    /// value), then the followers from their leaders.
    pub fn values(&self, set: &[(usize, f64)]) -> Vec<f64> {
        let mut v = self.tree.zeros();
        for &(j, x) in set {
            v[j] = x;
        }
        // A cycle of followers is refused when the tree is read
        // (`read::tree`): here every follower has a leader's value.
        let _ = self.tree.follow(&mut v);
        v
    }

    /// Read `--joints` (`flag` names the flag in messages): `name=value`
    /// pairs separated by commas, a value a plain number (SI: rad or m) or
    /// a quantity with its unit (`30 deg`, `20 mm`).
    pub fn joints(&self, text: &str, flag: &str) -> Result<Vec<(usize, f64)>, Diagnostic> {
        let mut out: Vec<(usize, f64)> = Vec::new();
        for pair in text.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            let Some((name, value)) = pair.split_once('=') else {
                return Err(Diagnostic::plain(format!(
                    "invalid value {pair:?} for `{flag}`: expected `JOINT=VALUE`, such as `elbow=30deg`"
                )));
            };
            let j = self.joint(name.trim(), flag)?;
            let x = self.value(j, value.trim(), flag)?;
            if out.iter().any(|(k, _)| *k == j) {
                return Err(Diagnostic::plain(format!(
                    "`{flag}` sets joint `{}` twice",
                    crate::diag::shorten(name.trim())
                )));
            }
            out.push((j, x));
        }
        Ok(out)
    }

    /// The joint `name` names, one that takes a value.
    pub fn joint(&self, name: &str, flag: &str) -> Result<usize, Diagnostic> {
        let t = &self.tree;
        let shown = crate::diag::shorten(name);
        let Some(j) = t.joints.iter().position(|j| j.name == name) else {
            let movable = t
                .joints
                .iter()
                .filter(|j| matches!(j.motion, Motion::Revolute | Motion::Prismatic))
                .map(|j| j.name.as_str());
            let near = units::suggest(name, movable.clone())
                .map(|s| format!("; did you mean `{}`?", crate::diag::shorten(s)))
                .unwrap_or_default();
            let list: Vec<String> = movable
                .take(12)
                .map(|n| format!("`{}`", crate::diag::shorten(n)))
                .collect();
            let has = if list.is_empty() {
                "no joint that moves".to_string()
            } else {
                list.join(", ")
            };
            return Err(Diagnostic::plain(format!(
                "`{flag}`: the robot has no joint `{shown}`{near} (it has {has})"
            )));
        };
        let joint = &t.joints[j];
        match joint.motion {
            Motion::Revolute | Motion::Prismatic => {}
            Motion::Fixed => {
                return Err(Diagnostic::plain(format!(
                    "`{flag}`: joint `{shown}` is fixed: it takes no value"
                )));
            }
            Motion::Stays => {
                return Err(Diagnostic::plain(format!(
                    "`{flag}`: joint `{shown}` moves in more than one direction (floating, planar, ball or free): its child stays at its written pose, and it takes no value"
                )));
            }
        }
        if let Some(f) = &joint.follows {
            let leader = match f.leader {
                Some(l) => format!(
                    "joint `{}`: set that one",
                    crate::diag::shorten(&t.joints[l].name)
                ),
                None => "nothing: it is held at one value".to_string(),
            };
            return Err(Diagnostic::plain(format!(
                "`{flag}`: joint `{shown}` follows {leader} (a URDF `<mimic>` or an MJCF joint equality)"
            )));
        }
        Ok(j)
    }

    /// A value for joint `j`: a plain number, SI, or a quantity.
    pub fn value(&self, j: usize, text: &str, flag: &str) -> Result<f64, Diagnostic> {
        let joint = &self.tree.joints[j];
        let (dim, what) = match joint.motion {
            Motion::Prismatic => (Dim::LENGTH, "a length (a plain number is metres)"),
            Motion::Revolute | Motion::Fixed | Motion::Stays => {
                (Dim::DIMENSIONLESS, "an angle (a plain number is radians)")
            }
        };
        let bad = |e: String| {
            Diagnostic::plain(format!(
                "invalid value {text:?} for joint `{}` in `{flag}`: {e}; expected {what}",
                crate::diag::shorten(&joint.name)
            ))
        };
        let (number, unit) = units::split_number(text).map_err(|e| bad(e.to_string()))?;
        if unit.is_empty() {
            return Ok(number);
        }
        units::parse_quantity(text, dim).map_err(|e| match e {
            units::UnitError::WrongDim { unit, .. } => bad(format!("`{unit}` is not its unit")),
            e => bad(e.to_string()),
        })
    }

    /// The warnings of the body at `values`: links without an inertial,
    /// inertials that are not physically valid, values beyond limits.
    pub fn notes(&self, values: &[f64]) -> Vec<Note> {
        let mut out = Vec::new();
        let d = &self.description;
        for l in &d.links {
            match &l.inertial {
                None => out.push(Note {
                    range: l.range.clone(),
                    message: match d.format {
                        Dialect::Mjcf => format!(
                            "body \"{}\" has no `<inertial>` and no geom that counts for inertia: composed massless",
                            crate::diag::shorten(&l.name)
                        ),
                        Dialect::Urdf | Dialect::Sdf => {
                            format!("link \"{}\" has no `<inertial>`: composed massless", crate::diag::shorten(&l.name))
                        }
                    },
                }),
                Some(i) if i.mass == 0.0 => out.push(Note {
                    range: i.range.clone(),
                    message: format!(
                        "link \"{}\" has mass 0: composed massless (its tensor left out)",
                        crate::diag::shorten(&l.name)
                    ),
                }),
                Some(i) => {
                    if let Some(why) = invalid(i.mass, &i.tensor) {
                        out.push(Note {
                            range: i.range.clone(),
                            message: format!(
                                "link \"{}\": its inertial is not physically valid ({why}); composed as written (`massprop check` judges it by each engine's rule)",
                                crate::diag::shorten(&l.name)
                            ),
                        });
                    }
                }
            }
        }
        for (j, joint) in self.tree.joints.iter().enumerate() {
            let Some((lo, hi)) = joint.limits else {
                continue;
            };
            let x = values[j];
            let (side, limit) = if x < lo {
                ("lower", lo)
            } else if x > hi {
                ("upper", hi)
            } else {
                continue;
            };
            out.push(Note {
                range: joint.range.clone(),
                message: format!(
                    "joint \"{}\" at {x} is beyond its {side} limit {limit} ({}); the value is used as given",
                    crate::diag::shorten(&joint.name),
                    if joint.motion == Motion::Prismatic { "m" } else { "rad" }
                ),
            });
        }
        out
    }
}

/// Why an inertial is not physically valid, if it is not: a negative mass,
/// a negative principal moment, or moments that break the triangle
/// inequality (beyond a few roundings of the largest).
fn invalid(mass: f64, t: &Tensor) -> Option<String> {
    if mass < 0.0 {
        return Some(format!("mass {mass} < 0"));
    }
    let [a, b, c] = super::engine::principal_moments(t)?;
    let slack = 8.0 * f64::EPSILON * c.abs();
    if a < -slack {
        return Some(format!("principal moment {a} < 0"));
    }
    if a + b < c - slack {
        return Some(format!("principal moments {a}, {b}, {c} break A + B ≥ C"));
    }
    None
}
