//! A robot as a composite body: each link a sub-assembly placed in its
//! parent link's frame (at the configuration the caller chose), holding
//! the link's inertial as a given-inertia part (`shapes::inertia`) and its
//! child links' sub-assemblies; the roots placed in the report frame. So
//! the composer, its bounds, the precision modes, `--only` (a link's
//! subtree) and every table and JSON key of a part file's report apply
//! unchanged.
//!
//! Each link is handed to the builder as a `BodyLink`, SI (kg, m, kg·m²):
//! its frame in its parent's at the configuration (`robot::kinematics`)
//! and its inertial.

use super::rotation::Orientation;
use super::{Frame, Include, Item, Model};
use crate::numeric::M3;
use crate::part::{MassSpec, Part, Place, Spec};
use crate::units::FileUnits;
use std::ops::Range;
use std::sync::Arc;

/// A link's inertial, SI: its tensor about its centre in the inertial
/// frame, turned by `rotation` (columns: the inertial frame's axes in the
/// link's) into the link frame.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct LinkInertial {
    pub mass: f64,
    pub center: [f64; 3],
    pub tensor: M3<f64>,
    pub rotation: Option<M3<f64>>,
    /// Its `<inertial>` element in the robot file.
    pub span: Range<usize>,
}

/// A link, its frame placed in its parent's (a root's in the report
/// frame): a point p of the link frame is `origin + turn p` there.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct BodyLink {
    pub name: String,
    /// An index into the links given with it, before it.
    pub parent: Option<usize>,
    pub origin: [f64; 3],
    /// None: not turned.
    pub turn: Option<M3<f64>>,
    /// None: massless.
    pub inertial: Option<LinkInertial>,
    /// Its element in the robot file.
    pub span: Range<usize>,
}

fn orientation(m: &Option<M3<f64>>) -> Orientation {
    match m {
        Some(m) => Orientation::Matrix(Box::new(*m)),
        None => Orientation::Identity,
    }
}

impl Model {
    /// The body of `robot` with its joints at `values` (one per joint of
    /// its tree, `Robot::values`): each link placed in its parent's
    /// through its joints.
    pub fn of_robot_at(robot: &crate::robot::body::Robot, values: &[f64]) -> Model {
        let d = &robot.description;
        let t = &robot.tree;
        // Parents before children: breadth first from the roots.
        let children = t.children();
        let mut order: Vec<usize> = t.roots().collect();
        let mut k = 0;
        while k < order.len() {
            order.extend(children[order[k]].iter().copied());
            k += 1;
        }
        let mut at = vec![usize::MAX; d.links.len()];
        for (n, &i) in order.iter().enumerate() {
            at[i] = n;
        }
        let links: Vec<BodyLink> =
            order
                .iter()
                .map(|&i| {
                    let l = &d.links[i];
                    let pose = t.relative(i, values);
                    BodyLink {
                        name: l.name.clone(),
                        parent: t.links[i].parent.map(|p| at[p]),
                        origin: pose.p,
                        turn: (!pose.unturned()).then_some(pose.r),
                        // NOTE: a mass of exactly 0 is massless whatever its
                        // tensor (a tensor without mass has no centre to
                        // place it at); `notes` says so.
                        inertial: l.inertial.as_ref().filter(|i| i.mass != 0.0).map(|i| {
                            LinkInertial {
                                mass: i.mass,
                                center: i.pos,
                                tensor: i.tensor.matrix(),
                                rotation: i.rotation,
                                span: i.range.clone(),
                            }
                        }),
                        span: l.range.clone(),
                    }
                })
                .collect();
        Model::of_robot(d.name.clone(), &links)
    }

    /// The body of `links` (each after its parent), named `name`.
    fn of_robot(name: Option<String>, links: &[BodyLink]) -> Model {
        let mut children: Vec<Vec<usize>> = vec![Vec::new(); links.len()];
        let mut roots = Vec::new();
        for (i, l) in links.iter().enumerate() {
            match l.parent {
                Some(p) => children[p].push(i),
                None => roots.push(i),
            }
        }
        // Children after parents: each link's model made after its
        // children's, from the last link back.
        let mut made: Vec<Option<Arc<Model>>> = vec![None; links.len()];
        for i in (0..links.len()).rev() {
            let l = &links[i];
            let mut items = Vec::with_capacity(children[i].len() + 1);
            let mut count = 0;
            if let Some(inertial) = &l.inertial {
                items.push(Item::Part {
                    part: part(&l.name, inertial),
                    real: None,
                    copies: None,
                    tag: None,
                });
                count += 1;
            }
            for &c in &children[i] {
                let (inc, n) = include(&links[c], made[c].take().expect("a child made first"));
                items.push(inc);
                count += n;
            }
            made[i] = Some(Arc::new(Model {
                name: Some(l.name.clone()),
                items: Arc::new(items),
                count,
                ..Model::empty(FileUnits::default())
            }));
        }
        let mut items = Vec::with_capacity(roots.len());
        let mut count = 0;
        for r in roots {
            let (inc, n) = include(&links[r], made[r].take().expect("every link made"));
            items.push(inc);
            count += n;
        }
        Model {
            name,
            items: Arc::new(items),
            count,
            ..Model::empty(FileUnits::default())
        }
    }
}

/// A link's sub-assembly, and the parts it holds.
fn include(l: &BodyLink, model: Arc<Model>) -> (Item, usize) {
    let count = model.count;
    let item = Item::Include(Box::new(Include {
        name: l.name.clone(),
        frame: Frame::of_link(l.origin, orientation(&l.turn)),
        model,
        span: l.span.clone(),
        copies: None,
        tol: None,
        tag: None,
    }));
    (item, count)
}

/// A link's inertial as a given-inertia part named for the link.
fn part(name: &str, i: &LinkInertial) -> Part {
    Part {
        name: name.to_string(),
        named: true,
        spec: Spec {
            mass: MassSpec::Given(i.mass),
            place: Place::Inertia(crate::shapes::inertia::Given {
                center: i.center,
                inertia: Box::new(i.tensor),
                orientation: orientation(&i.rotation),
            }),
            removed: false,
            placed: Default::default(),
        },
        assembly: Vec::new(),
        span: i.span.clone(),
        tol: None,
        material: None,
    }
}

impl super::Ctx<'_> {
    /// `include = "arm.urdf"` with `joints = { elbow = "30 deg" }`: the
    /// robot description `shown` names, read whole, at those joints (the
    /// rest at their zero), as a body of its own in SI. Errors inside the
    /// robot file say where it was included from; a joint's, at its key.
    /// An SDFormat robot's `<include>`s are resolved by `resolve` (the
    /// part file's include roots and `--package`s) and may read the robot
    /// file's directory.
    pub(super) fn robot_include(
        &self,
        inc: &toml::Spanned<String>,
        shown: &std::path::Path,
        shown_name: &str,
        joints: Option<&super::raw::Params>,
        resolve: &crate::robot::read::Resolve,
    ) -> Result<Model, crate::diag::Diagnostic> {
        use crate::robot::Dialect;
        use crate::robot::body::Robot;
        let included_here = |d: crate::diag::Diagnostic| {
            let (line, col) = self.source.line_col(inc.span().start);
            d.included_from(format!("{}:{line}:{col}", self.source.name))
        };
        let bytes = std::fs::read(shown).map_err(|e| {
            self.err(
                inc.span(),
                format!("cannot read the included file `{shown_name}`: {e}"),
            )
        })?;
        let source = crate::io::source_of(shown_name, bytes)
            .map_err(included_here)?
            .read_from(shown.to_path_buf());
        let format = Dialect::of_path(shown)
            .or_else(|| Dialect::of_text(&source.text))
            .ok_or_else(|| {
                self.err(
                    inc.span(),
                    format!("the included `{shown_name}` is not a robot description: its root element is not `<robot>`, `<sdf>` or `<mujoco>`"),
                )
            })?;
        let robot = Robot::read_in(&source, format, resolve).map_err(included_here)?;
        let mut set = Vec::new();
        for (key, q) in joints.map(|t| t.get_ref().iter()).into_iter().flatten() {
            let here = |d: crate::diag::Diagnostic, at: std::ops::Range<usize>| {
                self.err(at, d.message().to_string())
            };
            let j = robot
                .joint(key.get_ref(), "joints")
                .map_err(|d| here(d, key.span()))?;
            let x = match q.get_ref() {
                super::raw::Quantity::Number(x) if x.is_finite() => *x,
                super::raw::Quantity::Number(_) => {
                    return Err(self.err(q.span(), "`joints`: expected a finite joint position"));
                }
                super::raw::Quantity::Text(t) => {
                    robot.value(j, t, "joints").map_err(|d| here(d, q.span()))?
                }
            };
            set.push((j, x));
        }
        Ok(Model::of_robot_at(&robot, &robot.values(&set)))
    }
}
