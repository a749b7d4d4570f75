//! Each MJCF body's `<geom>`s as solids, for inertials from geometry
//! (`export --from-geometry`, and a body without `<inertial>` in `report`):
//! what MuJoCo's compiler (`inertiafromgeom`) sums. MJCF has no
//! collision/visual split: as MuJoCo's compiler does for inertia, the geoms
//! whose `group` (default 0) lies within `<compiler inertiagrouprange>`
//! (default 0 5) count. Sizes as MuJoCo reads them: a box's half-extents,
//! a sphere's radius, a capsule's or cylinder's radius and half-length (or
//! its `fromto`), an ellipsoid's radii. SI.

use super::geometry::{Amount, Geometry, Solid, positive};
use super::mjcf_class::{Class, Classes};
use super::orient::{Settings, orientation, quat_to_matrix, z_to_quat};
use super::{Value, Xml, children, qname};
use crate::diag::Diagnostic;
use crate::robot::Description;
use crate::robot::kinematics::Pose;
use roxmltree::Node;

const ORIENTATIONS: [&str; 5] = ["quat", "axisangle", "xyaxes", "zaxis", "euler"];

/// The geom attributes that place it, read only where the geom writes
/// them.
const PLACED: [&str; 7] = [
    "pos",
    "fromto",
    "quat",
    "axisangle",
    "xyaxes",
    "zaxis",
    "euler",
];

/// Per body of `d` (in its order), its geoms that count for inertia; none
/// read for a body `need` leaves out (None: every body).
pub(super) fn geoms(
    xml: &Xml,
    mujoco: Node,
    d: &Description,
    need: Option<&[bool]>,
) -> Result<Vec<Vec<Geometry>>, Diagnostic> {
    let mut settings = Settings::default();
    let mut range = (0.0, 5.0);
    for c in children(mujoco, "compiler") {
        super::mjcf::compiler(xml, c, &mut settings)?;
        if let Some(v) = xml.attr(c, "inertiagrouprange") {
            let [lo, hi] = xml.numbers::<2>(&v, "`<compiler>`")?;
            range = (lo, hi);
        }
    }
    let classes = Classes::read(xml, mujoco)?;
    let mut out = Vec::with_capacity(d.links.len());
    for world in children(mujoco, "worldbody") {
        for body in world.descendants().skip(1).filter(|n| qname(*n) == "body") {
            let owner = format!("body {}", super::quoted(&d.links[out.len()].name));
            let mut items = Vec::new();
            if need.is_some_and(|n| !n[out.len()]) {
                out.push(items);
                continue;
            }
            if let Some(g) = children(body, "frame")
                .flat_map(|f| f.descendants())
                .find(|n| qname(*n) == "geom")
            {
                return Err(xml
                    .error(
                        xml.tag(g),
                        format!("a geom inside a `<frame>` of {owner}: not read for inertia"),
                    )
                    .help("give the body an `<inertial>`"));
            }
            for g in children(body, "geom") {
                let class = classes.of(xml, g)?;
                let group = match classes.attr(xml, g, class, "geom", "group") {
                    Some(v) => xml.number(&v, &owner)?,
                    None => 0.0,
                };
                if group < range.0 || group > range.1 {
                    continue;
                }
                items.push(geom(xml, g, &owner, &settings, &classes, class)?);
            }
            out.push(items);
        }
    }
    Ok(out)
}

/// One `<geom>`: its solid, pose and what it weighs.
fn geom(
    xml: &Xml,
    g: Node,
    owner: &str,
    s: &Settings,
    classes: &Classes,
    class: Class,
) -> Result<Geometry, Diagnostic> {
    let attr = |n: &str| classes.attr(xml, g, class, "geom", n);
    // NOTE: a geom's placement from a default class is refused: MuJoCo
    // keeps a default's alternative orientation (`euler`, …) even where
    // the geom writes its own `quat`, a rule not worth copying for a value
    // real files write on each geom.
    if let Some(v) = PLACED
        .iter()
        .filter(|a| xml.attr(g, a).is_none())
        .find_map(|a| classes.inherited(xml, class, "geom", a))
    {
        return Err(xml
            .error(
                v.range.clone(),
                format!("{} of a default class's `<geom>`: a geom's placement is read only where the geom writes it ({owner} takes its inertia from its geoms)", v.name),
            )
            .help("write the placement on each geom, or give the body an `<inertial>`"));
    }
    if let Some(v) = attr("shellinertia")
        && v.text == "true"
    {
        return Err(xml.error(
            v.range.clone(),
            format!("`shellinertia` of a geom of {owner}: a shell's inertia is not read; expected a solid"),
        ));
    }
    let kind = attr("type");
    let kind_text = kind.as_ref().map_or("sphere", |v| v.text.as_str());
    let size = attr("size");
    let sizes = match &size {
        Some(v) => xml.list(v, owner)?,
        None => Vec::new(),
    };
    let at = |i: usize, what: &str| -> Result<f64, Diagnostic> {
        match (&size, sizes.get(i)) {
            (Some(v), Some(&x)) => positive(xml, v, x, owner),
            (Some(v), None) => Err(xml.error(
                v.range.clone(),
                format!(
                    "`size` of a {kind_text} geom of {owner}: expected its {what} as number {}",
                    i + 1
                ),
            )),
            (None, _) => Err(xml.error(
                xml.tag(g),
                format!("a {kind_text} geom of {owner} is missing `size` (its {what})"),
            )),
        }
    };
    let fromto = attr("fromto");
    let ends = fromto
        .as_ref()
        .map(|v| xml.numbers::<6>(v, owner))
        .transpose()?;
    let (solid, along) = match kind_text {
        "sphere" => (Solid::Sphere(at(0, "radius")?), None),
        "box" => (
            Solid::Box([
                2.0 * at(0, "x half-size")?,
                2.0 * at(1, "y half-size")?,
                2.0 * at(2, "z half-size")?,
            ]),
            None,
        ),
        "ellipsoid" => (
            Solid::Ellipsoid([at(0, "x radius")?, at(1, "y radius")?, at(2, "z radius")?]),
            None,
        ),
        "capsule" | "cylinder" => {
            let radius = at(0, "radius")?;
            let (length, along) = match ends {
                Some(e) => {
                    let v = [e[3] - e[0], e[4] - e[1], e[5] - e[2]];
                    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                    if !(l > 0.0) {
                        let f = fromto.as_ref().expect("ends read from it");
                        return Err(xml.error(f.range.clone(), format!("`fromto` of a {kind_text} geom of {owner}: expected two different points")));
                    }
                    let mid = [
                        (e[0] + e[3]) / 2.0,
                        (e[1] + e[4]) / 2.0,
                        (e[2] + e[5]) / 2.0,
                    ];
                    (l, Some((mid, [v[0] / l, v[1] / l, v[2] / l])))
                }
                None => (2.0 * at(1, "half-length")?, None),
            };
            let solid = if kind_text == "capsule" {
                Solid::Capsule { radius, length }
            } else {
                Solid::Cylinder { radius, length }
            };
            (solid, along)
        }
        other => {
            let range = kind
                .as_ref()
                .map_or_else(|| xml.tag(g), |v| v.range.clone());
            return Err(xml.error(
                range,
                format!(
                    "`type` of a geom of {owner}: `{}` is not read for inertia; expected sphere, box, capsule, cylinder or ellipsoid",
                    crate::diag::shorten(other)
                ),
            ).help("give the body an `<inertial>`, or put the geom in a `group` outside `<compiler inertiagrouprange>`"));
        }
    };
    let pose = match along {
        Some((mid, z)) => Pose {
            p: mid,
            r: quat_to_matrix(z_to_quat(&z)),
        },
        None => {
            let p = match attr("pos") {
                Some(v) => xml.numbers::<3>(&v, owner)?,
                None => [0.0; 3],
            };
            let mut forms: Vec<(&str, Value)> = ORIENTATIONS
                .iter()
                .filter_map(|&f| Some((f, xml.attr(g, f)?)))
                .collect();
            forms.sort_by_key(|(_, v)| v.range.start);
            if let [(first, _), (second, v), ..] = forms.as_slice() {
                return Err(xml.error(
                    v.range.clone(),
                    format!("a geom of {owner} gives two orientations, `{first}` and `{second}`: MuJoCo allows one"),
                ));
            }
            let r = match forms.first() {
                Some((form, v)) => quat_to_matrix(orientation(xml, form, v, owner, s)?),
                None => Pose::IDENTITY.r,
            };
            Pose { p, r }
        }
    };
    let amount = match (attr("mass"), attr("density")) {
        (Some(m), _) => Amount::Mass(positive(xml, &m, xml.number(&m, owner)?, owner)?),
        (None, Some(d)) => Amount::Density(positive(xml, &d, xml.number(&d, owner)?, owner)?),
        (None, None) => {
            return Ok(Geometry {
                solid,
                pose,
                range: xml.tag(g),
                amount: None,
            });
        }
    };
    Ok(Geometry {
        solid,
        pose,
        range: xml.tag(g),
        amount: Some(amount),
    })
}
