//! A robot description's kinematic tree (`read::tree` reads it): each
//! link's frame in its parent's, and the joints between them, so that the
//! whole robot can be composed at a configuration (`model::robot_body`).
//!
//! Every link frame is placed in its parent's as `place` (the written pose:
//! URDF the joint's `<origin>`, MJCF the body's `pos` and orientation,
//! SDFormat the parent's pose inverted times the child's, both in the
//! model frame), then moved by its joints in order, each a turn about, or
//! a slide along, an axis through an anchor point, both in the child's
//! frame (MuJoCo's `mj_kinematics`: a hinge turns the body about its
//! anchor, a slide moves it along its axis, each joint after the one
//! before). A joint's motion is its value less its `zero` (MJCF: `ref`,
//! the value at which the written pose holds; URDF and SDFormat: 0).
//!
//! SI throughout: radians and metres.

use crate::numeric::M3;
use std::ops::Range;

/// A rigid placement: a point p of the child frame goes to `p + r p`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub p: [f64; 3],
    /// Columns: the child frame's axes in the parent's.
    pub r: M3<f64>,
}

const I3: M3<f64> = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

impl Pose {
    pub const IDENTITY: Pose = Pose { p: [0.0; 3], r: I3 };

    /// `self` after `inner`: a point of `inner`'s child frame placed
    /// through `inner`, then through `self`.
    pub fn then(&self, inner: &Pose) -> Pose {
        Pose {
            p: std::array::from_fn(|i| self.p[i] + dot(&self.r[i], &inner.p)),
            r: std::array::from_fn(|i| {
                std::array::from_fn(|j| (0..3).map(|k| self.r[i][k] * inner.r[k][j]).sum())
            }),
        }
    }

    /// The inverse placement.
    pub fn inverse(&self) -> Pose {
        let rt: M3<f64> = std::array::from_fn(|i| std::array::from_fn(|j| self.r[j][i]));
        Pose {
            p: std::array::from_fn(|i| -dot(&rt[i], &self.p)),
            r: rt,
        }
    }

    /// A turn by `angle` (rad) about the unit `axis` through `anchor`.
    pub fn turn_about(anchor: [f64; 3], axis: [f64; 3], angle: f64) -> Pose {
        let r = axis_angle(axis, angle);
        Pose {
            p: std::array::from_fn(|i| anchor[i] - dot(&r[i], &anchor)),
            r,
        }
    }

    /// A slide by `d` (m) along the unit `axis`.
    pub fn slide(axis: [f64; 3], d: f64) -> Pose {
        Pose {
            p: axis.map(|a| a * d),
            r: I3,
        }
    }

    /// Whether it is exactly no turn (its matrix the identity to the bit).
    pub fn unturned(&self) -> bool {
        self.r == I3
    }
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Rodrigues' formula: the turn by `angle` about the unit `axis`.
pub fn axis_angle(k: [f64; 3], angle: f64) -> M3<f64> {
    if angle == 0.0 {
        return I3;
    }
    let (s, c) = angle.sin_cos();
    let t = 1.0 - c;
    let [x, y, z] = k;
    [
        [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
        [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
    ]
}

/// How a joint moves its child.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Motion {
    /// Not at all (URDF and SDFormat `fixed`).
    Fixed,
    /// A turn about its axis (URDF `revolute`, `continuous`; SDFormat
    /// `revolute`, `continuous`; MJCF `hinge`): its value in radians.
    Revolute,
    /// A slide along its axis (`prismatic`; MJCF `slide`): metres.
    Prismatic,
    /// Free in more than one direction (URDF `floating`, `planar`;
    /// SDFormat `ball`; MJCF `ball`, `free`, `<freejoint>`): its child
    /// stays at its written pose, and it takes no value.
    Stays,
}

/// A joint whose value follows another's: URDF `<mimic>`, MJCF
/// `<equality><joint polycoef>`. Its value is `zero + Σ cₖ (x − x₀)ᵏ`, x
/// the leader's value and x₀ its `zero` (MuJoCo's rule, relative to
/// `qpos0`; a URDF mimic is `offset + multiplier x`, every zero 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Follow {
    /// None: an MJCF equality without `joint2`, which holds the joint at
    /// `zero + c₀`.
    pub leader: Option<usize>,
    pub coef: [f64; 5],
}

/// A joint, SI.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    pub name: String,
    pub motion: Motion,
    /// Unit, in the child link's frame.
    pub axis: [f64; 3],
    /// The point the axis passes through, in the child link's frame.
    pub anchor: [f64; 3],
    /// The value at which the child is at its written pose.
    pub zero: f64,
    /// (lower, upper), where the file limits it.
    pub limits: Option<(f64, f64)>,
    pub follows: Option<Follow>,
    /// The joint's element, start tag to end tag.
    pub range: Range<usize>,
}

/// A link (MJCF: a body) in the tree; `Tree::links` is parallel to the
/// description's links.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// None for a root: placed in the report frame (URDF: its root link's;
    /// SDFormat: the model frame; MJCF: the world body's).
    pub parent: Option<usize>,
    /// Its frame in its parent's at every joint's zero.
    pub place: Pose,
    /// The joints between it and its parent, applied in order.
    pub joints: Vec<usize>,
}

/// The kinematic tree of a robot description.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Tree {
    pub links: Vec<Node>,
    pub joints: Vec<Joint>,
}

/// The deepest chain of links composed: each link is a sub-assembly of its
/// parent's, and walks of sub-assemblies nest as deep.
pub const MAX_CHAIN: usize = 256;

impl Tree {
    /// The links with no parent, in order.
    pub fn roots(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.links.len()).filter(|&i| self.links[i].parent.is_none())
    }

    /// Each link's children, in order.
    pub fn children(&self) -> Vec<Vec<usize>> {
        let mut out = vec![Vec::new(); self.links.len()];
        for (i, l) in self.links.iter().enumerate() {
            if let Some(p) = l.parent {
                out[p].push(i);
            }
        }
        out
    }

    /// The joints' values at their zeros.
    pub fn zeros(&self) -> Vec<f64> {
        self.joints.iter().map(|j| j.zero).collect()
    }

    /// `values` with every following joint's value set from its leader's
    /// (a follower of a follower after its leader). None if the followers
    /// make a cycle.
    pub fn follow(&self, values: &mut [f64]) -> Option<()> {
        let n = self.joints.len();
        let mut done: Vec<bool> = self.joints.iter().map(|j| j.follows.is_none()).collect();
        for _ in 0..=n {
            let mut progress = false;
            for (i, j) in self.joints.iter().enumerate() {
                let Some(f) = &j.follows else { continue };
                if done[i] {
                    continue;
                }
                let x = match f.leader {
                    Some(l) if !done[l] => continue,
                    Some(l) => values[l] - self.joints[l].zero,
                    None => 0.0,
                };
                let mut y = 0.0;
                for c in f.coef.iter().rev() {
                    y = y * x + c;
                }
                values[i] = j.zero + y;
                done[i] = true;
                progress = true;
            }
            if done.iter().all(|d| *d) {
                return Some(());
            }
            if !progress {
                return None;
            }
        }
        None
    }

    /// Link `i`'s frame in its parent's with the joints at `values`.
    pub fn relative(&self, i: usize, values: &[f64]) -> Pose {
        let node = &self.links[i];
        let mut pose = node.place;
        for &j in &node.joints {
            let joint = &self.joints[j];
            let q = values[j] - joint.zero;
            let m = match joint.motion {
                Motion::Fixed | Motion::Stays => continue,
                Motion::Revolute => Pose::turn_about(joint.anchor, joint.axis, q),
                Motion::Prismatic => Pose::slide(joint.axis, q),
            };
            pose = pose.then(&m);
        }
        pose
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-15
    }

    #[test]
    fn a_quarter_turn_about_z_takes_x_to_y() {
        let r = axis_angle([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2);
        assert!(close(r[1][0], 1.0) && close(r[0][1], -1.0) && close(r[2][2], 1.0));
    }

    #[test]
    fn a_turn_about_an_anchor_keeps_the_anchor_in_place() {
        let a = [1.0, 2.0, 0.5];
        let p = Pose::turn_about(a, [0.0, 0.6, 0.8], 1.1);
        let moved = Pose::IDENTITY.then(&p).then(&Pose { p: a, r: I3 });
        for (got, want) in moved.p.iter().zip(a) {
            assert!(close(*got, want), "{moved:?}");
        }
    }

    #[test]
    fn a_pose_then_its_inverse_is_no_move() {
        let p = Pose {
            p: [1.0, -2.0, 3.0],
            r: axis_angle([0.0, 0.6, 0.8], 0.7),
        };
        let id = p.then(&p.inverse());
        assert!(id.p.iter().all(|x| close(*x, 0.0)));
        for (row, want) in id.r.iter().zip(I3) {
            for (x, w) in row.iter().zip(want) {
                assert!(close(*x, w));
            }
        }
    }

    fn joint(follows: Option<Follow>, zero: f64) -> Joint {
        Joint {
            name: String::new(),
            motion: Motion::Revolute,
            axis: [0.0, 0.0, 1.0],
            anchor: [0.0; 3],
            zero,
            limits: None,
            follows,
            range: 0..0,
        }
    }

    #[test]
    fn a_follower_of_a_follower_takes_its_value_after_its_leader() {
        let t = Tree {
            links: Vec::new(),
            joints: vec![
                joint(
                    Some(Follow {
                        leader: Some(1),
                        coef: [1.0, 2.0, 0.0, 0.0, 0.0],
                    }),
                    0.5,
                ),
                joint(
                    Some(Follow {
                        leader: Some(2),
                        coef: [0.0, -1.0, 0.0, 0.0, 0.0],
                    }),
                    0.0,
                ),
                joint(None, 0.25),
            ],
        };
        let mut v = vec![0.0, 0.0, 1.25];
        t.follow(&mut v).unwrap();
        // Joint 1: 0 + (−1)(1.25 − 0.25) = −1; joint 0: 0.5 + 1 + 2(−1 − 0).
        assert_eq!(v, vec![-0.5, -1.0, 1.25]);
    }

    #[test]
    fn followers_in_a_cycle_are_no_configuration() {
        let f = |l| {
            Some(Follow {
                leader: Some(l),
                coef: [0.0, 1.0, 0.0, 0.0, 0.0],
            })
        };
        let t = Tree {
            links: Vec::new(),
            joints: vec![joint(f(1), 0.0), joint(f(0), 0.0)],
        };
        assert_eq!(t.follow(&mut [0.0, 0.0]), None);
    }
}
