//! Robot description files: the `<inertial>` elements of URDF, SDFormat and
//! MJCF files, read (`read`; written and replaced in place by
//! `output::inertial`), and
//! judged by each simulator's own rule (`engine`, with the likely cause of
//! a failure in `cause`). docs/robots.md is the contract.
//!
//! Every value here is SI (kg, m, kg·m²) and every tensor is in the tensor
//! convention (I_xy = −∫xy dm), as URDF, SDFormat and MJCF all write it.

pub mod body;
pub mod cause;
pub mod check;
pub mod engine;
pub mod kinematics;
pub mod plausible;
pub mod read;
mod steps;
pub mod weigh;

use std::ops::Range;

/// A robot description format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Dialect {
    /// ROS's Unified Robot Description Format: `<robot>`.
    Urdf,
    /// SDFormat (Gazebo): `<sdf>`.
    Sdf,
    /// MuJoCo's MJCF: `<mujoco>`.
    Mjcf,
}

impl Dialect {
    /// Its name on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Dialect::Urdf => "urdf",
            Dialect::Sdf => "sdf",
            Dialect::Mjcf => "mjcf",
        }
    }

    /// The format a file's name says: `*.urdf`, `*.sdf` (any case). `*.xml`
    /// says nothing alone: its root element decides (`of_text`).
    pub fn of_path(path: &std::path::Path) -> Option<Dialect> {
        let ext = path.extension()?.to_str()?;
        if ext.eq_ignore_ascii_case("urdf") {
            Some(Dialect::Urdf)
        } else if ext.eq_ignore_ascii_case("sdf") {
            Some(Dialect::Sdf)
        } else {
            None
        }
    }

    /// The format a text's root element says (`<robot>`, `<sdf>`,
    /// `<mujoco>`), looked for without parsing the whole document: after
    /// an optional XML declaration, comments, processing instructions and
    /// a doctype. None when the root is none of those.
    pub fn of_text(text: &str) -> Option<Dialect> {
        let mut rest = text.trim_start_matches('\u{feff}');
        loop {
            rest = rest.trim_start();
            if let Some(r) = rest.strip_prefix("<?") {
                rest = &r[r.find("?>")? + 2..];
            } else if let Some(r) = rest.strip_prefix("<!--") {
                rest = &r[r.find("-->")? + 3..];
            } else if let Some(r) = rest.strip_prefix("<!") {
                // A doctype's internal subset, `[…]`, holds declarations
                // that end in `>` themselves: skip to its `]` first.
                let end = r.find('>')?;
                let r = match r[..end].find('[') {
                    Some(open) => &r[open + r[open..].find(']')?..],
                    None => r,
                };
                rest = &r[r.find('>')? + 1..];
            } else {
                break;
            }
        }
        let tag = rest.strip_prefix('<')?;
        let end = tag
            .find(|c: char| c.is_whitespace() || c == '>' || c == '/')
            .unwrap_or(tag.len());
        match &tag[..end] {
            "robot" => Some(Dialect::Urdf),
            "sdf" => Some(Dialect::Sdf),
            "mujoco" => Some(Dialect::Mjcf),
            _ => None,
        }
    }
}

/// Whether a directory search looks at a file of this name as a possible
/// robot description: `*.urdf`, `*.sdf`, `*.xml` (any case); an `*.xml` is
/// one only if its root element says so (`Dialect::of_text`).
pub fn may_be_robot(path: &std::path::Path) -> bool {
    Dialect::of_path(path).is_some()
        || path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}

/// The six independent entries of a symmetric inertia tensor, kg·m², in
/// the tensor convention: `xy` is I_xy = −∫xy dm.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Tensor {
    pub xx: f64,
    pub yy: f64,
    pub zz: f64,
    pub xy: f64,
    pub xz: f64,
    pub yz: f64,
}

impl Tensor {
    /// Rows of the full matrix.
    pub fn matrix(&self) -> [[f64; 3]; 3] {
        [
            [self.xx, self.xy, self.xz],
            [self.xy, self.yy, self.yz],
            [self.xz, self.yz, self.zz],
        ]
    }

    /// The upper triangle of `m` (assumed symmetric).
    pub fn of_matrix(m: &[[f64; 3]; 3]) -> Tensor {
        Tensor {
            xx: m[0][0],
            yy: m[1][1],
            zz: m[2][2],
            xy: m[0][1],
            xz: m[0][2],
            yz: m[1][2],
        }
    }

    /// The entries by their URDF and SDFormat names, in the order both
    /// write them: ixx ixy ixz iyy iyz izz.
    pub fn named(&self) -> [(&'static str, f64); 6] {
        [
            ("ixx", self.xx),
            ("ixy", self.xy),
            ("ixz", self.xz),
            ("iyy", self.yy),
            ("iyz", self.yz),
            ("izz", self.zz),
        ]
    }

    /// The three products, xy, xz, yz.
    pub fn products(&self) -> [f64; 3] {
        [self.xy, self.xz, self.yz]
    }
}

/// How a file wrote its tensor: what a writer writes back.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Written {
    /// URDF: `<inertia ixx ixy ixz iyy iyz izz>` attributes.
    Attributes,
    /// SDFormat: `<inertia><ixx>…</izz></inertia>` elements.
    Elements,
    /// MJCF `fullinertia="xx yy zz xy xz yz"`.
    Full,
    /// MJCF `diaginertia="a b c"`, turned by the inertial's orientation.
    Diagonal,
}

/// One `<inertial>` element as the file gives it, SI.
#[derive(Clone, Debug, PartialEq)]
pub struct Inertial {
    /// kg.
    pub mass: f64,
    /// The centre of mass in the link's (MJCF: body's) frame, m.
    pub pos: [f64; 3],
    /// The inertial frame's orientation in the link frame, as a rotation
    /// matrix whose columns are the inertial frame's axes (URDF `rpy`,
    /// SDFormat `<pose>` angles, MJCF `quat`/`axisangle`/`euler`/`xyaxes`/
    /// `zaxis`); None when not turned (exactly the identity).
    pub rotation: Option<[[f64; 3]; 3]>,
    /// The tensor about the centre of mass in the inertial frame, exactly
    /// as written (MJCF `diaginertia`: the diagonal).
    pub tensor: Tensor,
    pub written: Written,
    /// The `<inertial>` element's bytes in the text, start tag to end tag.
    pub range: Range<usize>,
}

impl Inertial {
    /// The tensor about the centre of mass in the link frame: R I Rᵀ.
    pub fn tensor_in_link(&self) -> Tensor {
        let Some(r) = self.rotation else {
            return self.tensor;
        };
        let i = self.tensor.matrix();
        let mut out = [[0.0; 3]; 3];
        for (a, row) in out.iter_mut().enumerate() {
            for (b, v) in row.iter_mut().enumerate() {
                let mut s = 0.0;
                for k in 0..3 {
                    for l in 0..3 {
                        s += r[a][k] * i[k][l] * r[b][l];
                    }
                }
                *v = s;
            }
        }
        Tensor::of_matrix(&out)
    }
}

/// A URDF or SDFormat `<link>`, or an MJCF `<body>`.
#[derive(Clone, Debug, PartialEq)]
pub struct Link {
    /// Its name: URDF and MJCF `name`; SDFormat `model::link` for a link
    /// of a nested model (the outermost model's name left out). An
    /// unnamed MJCF body is `body N` (1-based, in document order).
    pub name: String,
    /// The element's bytes in the text, start tag to end tag.
    pub range: Range<usize>,
    /// None when the element has no `<inertial>`.
    pub inertial: Option<Inertial>,
    /// Whether it moves relative to its parent, so that an engine needs it
    /// to have mass and inertia: URDF and SDFormat, the child of a joint
    /// whose type is not `fixed` (a root link of a model that is not
    /// `<static>` too, in SDFormat: it floats); MJCF, a body with a
    /// `<joint>` or `<freejoint>` child.
    pub moving: bool,
    /// The link it hangs from, an index into `Description::links`: URDF,
    /// the parent of the joint whose child it is; MJCF, the enclosing
    /// body. None for a root (and for SDFormat, whose tree is not read).
    pub parent: Option<usize>,
    /// Where it is written: its file and its bytes there. `range` (and
    /// its inertial's) stand in the main file, at the outermost
    /// `<include>` for a link of an included file; this is the link's own
    /// place, which `check`'s verdicts and `export --update` use.
    pub site: Site,
}

/// Where a link is written (`Link::site`).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Site {
    /// 0: the main file; k: `Description::files`' k-th included file.
    pub file: usize,
    /// The element's bytes in that file, start tag to end tag.
    pub element: Range<usize>,
    /// Its `<inertial>` element's bytes there (None: none written there).
    pub inertial: Option<Range<usize>>,
    /// Its `<inertial>` is written in another file: MJCF, brought in by an
    /// `<include>` inside the body (`--update` does not write such a body).
    pub elsewhere: bool,
    /// The `<include>`s that bring it in, innermost first: `FILE:LINE:COL`
    /// of each (empty in the main file). An SDFormat file included twice
    /// has links brought in by each include: this is this link's chain.
    pub from: Vec<String>,
}

impl Site {
    /// A link of the main file: its element's and inertial's bytes.
    pub fn main(element: Range<usize>, inertial: Option<Range<usize>>) -> Site {
        Site {
            file: 0,
            element,
            inertial,
            elsewhere: false,
            from: Vec::new(),
        }
    }
}

/// The files a description's main file includes (SDFormat and MJCF
/// `<include>`s, read by `read::read_in`), kept for the messages that
/// point into them and for the writers that write into them.
#[derive(Clone, Debug, Default)]
pub struct Included {
    /// Index k − 1 holds file k (`Site::file`).
    pub sources: Vec<crate::diag::Source>,
    /// Per file, where it was first included: `FILE:LINE:COL`.
    pub from: Vec<String>,
}

impl PartialEq for Included {
    fn eq(&self, other: &Self) -> bool {
        self.from == other.from
            && self.sources.len() == other.sources.len()
            && self
                .sources
                .iter()
                .zip(&other.sources)
                .all(|(a, b)| a.name == b.name && a.text == b.text)
    }
}

impl Included {
    /// The source of file `file` (`Site::file`), `main` for 0.
    pub fn source<'a>(
        &'a self,
        main: &'a crate::diag::Source,
        file: usize,
    ) -> &'a crate::diag::Source {
        match file {
            0 => main,
            k => &self.sources[k - 1],
        }
    }

    /// `d` with where its file was included from, up to the main file
    /// (`read::located`, the one rule for every robot reader).
    pub fn located(&self, d: crate::diag::Diagnostic) -> crate::diag::Diagnostic {
        read::located(&self.sources, &self.from, d)
    }

    /// The chain of includes that brings file `file` in, innermost first.
    pub fn chain(&self, file: usize) -> Vec<String> {
        read::chain(&self.sources, &self.from, file)
    }
}

/// The MJCF `<compiler>` settings (or URDF `<mujoco><compiler>`) that change
/// MuJoCo's verdict on an inertial.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MujocoCompiler {
    /// `balanceinertia`: moments that break the triangle inequality are
    /// replaced by their mean.
    pub balanceinertia: bool,
    /// `boundmass`, kg: a smaller mass is raised to it (0: off).
    pub boundmass: f64,
    /// `boundinertia`, kg·m²: a smaller principal moment is raised to it.
    pub boundinertia: f64,
    /// `inertiafromgeom`: Some(true) ignores every `<inertial>`; None is
    /// `auto` (the default: an `<inertial>` is used where given).
    pub inertiafromgeom: Option<bool>,
}

impl Default for MujocoCompiler {
    fn default() -> Self {
        MujocoCompiler {
            balanceinertia: false,
            boundmass: 0.0,
            boundinertia: 0.0,
            inertiafromgeom: None,
        }
    }
}

/// A robot description file read: its links in document order.
#[derive(Clone, Debug, PartialEq)]
pub struct Description {
    pub format: Dialect,
    /// `<robot name>`, the SDFormat model's, `<mujoco model>`.
    pub name: Option<String>,
    pub links: Vec<Link>,
    pub compiler: MujocoCompiler,
    /// The files the main one includes (empty when it includes none).
    pub files: Included,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_root_element_tells_the_format() {
        assert_eq!(Dialect::of_text("<robot name='a'/>"), Some(Dialect::Urdf));
        assert_eq!(
            Dialect::of_text("\u{feff}<?xml version='1.0'?>\n<!-- c -->\n<sdf version='1.9'>"),
            Some(Dialect::Sdf)
        );
        assert_eq!(Dialect::of_text("<mujoco>"), Some(Dialect::Mjcf));
        // A doctype whose internal subset declares entities, each ending
        // in `>` (an `*.xml` with one was checked as a part file).
        assert_eq!(
            Dialect::of_text(
                "<!DOCTYPE mujoco [\n<!ENTITY a \"1\">\n<!ENTITY b \"&a;\">\n]>\n<mujoco model='&b;'/>"
            ),
            Some(Dialect::Mjcf)
        );
        assert_eq!(Dialect::of_text("<!DOCTYPE mujoco [<!ENTITY a '1'>"), None);
        assert_eq!(Dialect::of_text("<robots>"), None);
        assert_eq!(Dialect::of_text("<project>"), None);
        assert_eq!(Dialect::of_text("[[part]]"), None);
    }

    #[test]
    fn a_turned_inertial_frame_turns_the_tensor_into_the_link_frame() {
        // A quarter turn about z: the inertial frame's x is the link's y.
        let i = Inertial {
            mass: 1.0,
            pos: [0.0; 3],
            rotation: Some([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]),
            tensor: Tensor {
                xx: 1.0,
                yy: 2.0,
                zz: 3.0,
                ..Tensor::default()
            },
            written: Written::Attributes,
            range: 0..0,
        };
        let t = i.tensor_in_link();
        assert_eq!((t.xx, t.yy, t.zz), (2.0, 1.0, 3.0));
    }
}
