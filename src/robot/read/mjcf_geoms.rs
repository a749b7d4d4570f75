//! Each MJCF body's `<geom>`s as solids, for inertials from geometry
//! (`export --from-geometry`, and a body without `<inertial>` in `report`):
//! what MuJoCo's compiler (`inertiafromgeom`) sums. MJCF has no
//! collision/visual split: as MuJoCo's compiler does for inertia, the geoms
//! whose `group` (default 0) lies within `<compiler inertiagrouprange>`
//! (default 0 5) count: the body's own and those inside its `<frame>`s
//! (placed by each frame's pose, nested frames composed). Sizes as MuJoCo
//! reads them: a box's half-extents, a sphere's radius, a capsule's or
//! cylinder's radius and half-length (or its `fromto`), an ellipsoid's
//! radii; a mesh's file through `mjcf_mesh`. SI.
//!
//! A geom's placement is its own or its default class's, as MuJoCo 4
//! applies it: `pos` and `fromto` each the nearest that writes it (both at
//! once is MuJoCo's error); the orientation is the one form written at the
//! nearest level (the geom, then its class, its parent class, …) that
//! writes any (`quat`, `axisangle`, `xyaxes`, `zaxis` or `euler`), so a
//! geom's own `euler` overrides its class's `quat`; `fromto` overrides
//! both `pos` and the orientation.

use super::geometry::{Amount, Geometry, Solid, positive};
use super::mjcf_class::{Class, Classes};
use super::mjcf_include::Model;
use super::mjcf_mesh::{MeshWarning, Meshes};
use super::orient::{Settings, orientation, quat_to_matrix, z_to_quat};
use super::{Value, Xml, qname};
use crate::diag::Diagnostic;
use crate::robot::Description;
use crate::robot::kinematics::Pose;
use roxmltree::Node;

/// The `<frame>`s an element is in (file, element), outermost first.
type Frames<'a, 'i> = Vec<(usize, Node<'a, 'i>)>;

const ORIENTATIONS: [&str; 5] = ["quat", "axisangle", "xyaxes", "zaxis", "euler"];

/// What reading a body's geoms shares.
struct Ctx<'x, 's, 'a, 'i> {
    m: &'x Model<'s, 'a, 'i>,
    /// The file of the element being read.
    xml: &'x Xml<'s>,
    settings: Settings,
    classes: Classes<'s, 'a, 'i>,
    meshes: Meshes<'s, 'a, 'i>,
    /// Read for `export --from-geometry` (not for the whole robot).
    export: bool,
}

/// Per body of `d` (in its order), its geoms that count for inertia; none
/// read for a body `need` leaves out (None: every body); and the warnings
/// of the mesh files read. `export`: read for `export --from-geometry`,
/// which weighs solids (a mesh MuJoCo weighs otherwise is refused).
pub(super) fn geoms(
    m: &Model,
    d: &Description,
    need: Option<&[bool]>,
    export: bool,
) -> Result<(Vec<Vec<Geometry>>, Vec<MeshWarning>), Diagnostic> {
    let mut settings = Settings::default();
    let mut range = (0.0, 5.0);
    for (xml, _, c) in m.sections("compiler") {
        super::mjcf::compiler(xml, c, &mut settings)?;
        if let Some(v) = xml.attr(c, "inertiagrouprange") {
            let [lo, hi] = xml.numbers::<2>(&v, "`<compiler>`")?;
            range = (lo, hi);
        }
    }
    let mut cx = Ctx {
        m,
        xml: &m.xmls[0],
        settings,
        classes: Classes::read(m)?,
        meshes: Meshes::read(m)?,
        export,
    };
    let mut out = Vec::with_capacity(d.links.len());
    for (_, file, world) in m.sections("worldbody") {
        // Bodies at any depth, includes spliced, in document order (as
        // `mjcf` reads them).
        for (file, body) in m.descendants(file, world) {
            if qname(body) != "body" {
                continue;
            }
            // An unnamed body is "body N", as `mjcf` names it.
            let owner = match body.attribute("name").filter(|n| !n.is_empty()) {
                Some(_) => format!("body {}", super::quoted(&d.links[out.len()].name)),
                None => d.links[out.len()].name.clone(),
            };
            let mut items = Vec::new();
            if need.is_some_and(|n| !n[out.len()]) {
                out.push(items);
                continue;
            }
            // The body's geoms, also those inside its frames (not those
            // of the bodies inside it), in document order: a walk into
            // frames only, with a stack of its own (a long chain of bodies
            // is not walked once per body). Each with the frames it is
            // in, outermost first.
            let mut stack: Vec<(usize, Node, Frames)> = m
                .children(file, body)
                .map(|(f, n)| (f, n, Vec::new()))
                .collect();
            stack.reverse();
            while let Some((f, g, frames)) = stack.pop() {
                match qname(g) {
                    "frame" => {
                        let from = stack.len();
                        let mut within = frames.clone();
                        within.push((f, g));
                        stack.extend(m.children(f, g).map(|(k, n)| (k, n, within.clone())));
                        stack[from..].reverse();
                        continue;
                    }
                    "geom" => {}
                    _ => continue,
                }
                // A geom is read in its own file (an included one too).
                let xml = m.xml(f);
                cx.xml = xml;
                let class = cx.classes.of(m, f, g)?;
                let group = match cx.classes.attr(xml, g, class, "geom", "group") {
                    Some(v) => xml.number(&v, &owner)?,
                    None => 0.0,
                };
                if group < range.0 || group > range.1 {
                    let kind = cx.classes.attr(xml, g, class, "geom", "type");
                    let kind = kind.as_ref().map_or("sphere", |v| v.text.as_str());
                    segment(xml, g, &cx.classes, class, kind, &owner)?;
                    continue;
                }
                let mut geo = geom(&mut cx, g, &owner, class)?;
                // Outermost frame first: body ← frame ← … ← geom.
                let mut at = Pose::IDENTITY;
                for &(k, fr) in &frames {
                    cx.xml = m.xml(k);
                    at = at.then(&frame_pose(&cx, fr, &owner)?);
                }
                geo.pose = at.then(&geo.pose);
                items.push(geo);
            }
            out.push(items);
        }
    }
    Ok((out, cx.meshes.warnings))
}

/// A `<frame>`'s pose in what encloses it: its `pos` and orientation.
fn frame_pose(cx: &Ctx, f: Node, owner: &str) -> Result<Pose, Diagnostic> {
    let xml = cx.xml;
    let p = match xml.attr(f, "pos") {
        Some(v) => xml.numbers::<3>(&v, owner)?,
        None => [0.0; 3],
    };
    let r = match one_orientation(xml, f, &format!("a `<frame>` of {owner}"))? {
        Some((form, v)) => quat_to_matrix(orientation(xml, form, &v, owner, &cx.settings)?),
        None => Pose::IDENTITY.r,
    };
    Ok(Pose { p, r })
}

/// The orientation `node` writes, at most one form (MuJoCo refuses two).
fn one_orientation(
    xml: &Xml,
    node: Node,
    what: &str,
) -> Result<Option<(&'static str, Value)>, Diagnostic> {
    let mut forms: Vec<(&str, Value)> = ORIENTATIONS
        .iter()
        .filter_map(|&f| Some((f, xml.attr(node, f)?)))
        .collect();
    forms.sort_by_key(|(_, v)| v.range.start);
    if let [(first, _), (second, v), ..] = forms.as_slice() {
        return Err(xml.error(
            v.range.clone(),
            format!("{what} gives two orientations, `{first}` and `{second}`: MuJoCo allows one"),
        ));
    }
    Ok(forms.pop())
}

/// One `<geom>`: its solid, pose and what it weighs.
fn geom(cx: &mut Ctx, g: Node, owner: &str, class: Class) -> Result<Geometry, Diagnostic> {
    let xml = cx.xml;
    let classes = &cx.classes;
    let attr = |n: &str| classes.attr(xml, g, class, "geom", n);
    let kind = attr("type");
    let kind_text = kind
        .as_ref()
        .map_or("sphere", |v| v.text.as_str())
        .to_string();
    let kind_text = kind_text.as_str();
    let kind_range = || {
        kind.as_ref()
            .map_or_else(|| xml.tag(g), |v| v.range.clone())
    };
    let mesh_name = attr("mesh");
    if let Some(v) = attr("shellinertia")
        && v.text == "true"
    {
        if kind_text == "mesh" {
            return Err(xml.error(
                v.range.clone(),
                format!("`shellinertia` of a mesh geom of {owner}: MuJoCo refuses it (a mesh's inertia is set by its `<mesh inertia>`, `shell` for a surface)"),
            ));
        }
        return Err(xml.error(
            v.range.clone(),
            format!("`shellinertia` of a geom of {owner}: a shell's inertia is not read; expected a solid"),
        ));
    }
    if let Some(m) = &mesh_name
        && kind_text != "mesh"
    {
        return Err(xml
            .error(
                m.range.clone(),
                format!("`mesh` of a {kind_text} geom of {owner}: MuJoCo fits a {kind_text} to the mesh, which is not read for inertia; expected `type=\"mesh\"`"),
            )
            .help("give the body an `<inertial>`, or put the geom in a `group` outside `<compiler inertiagrouprange>`"));
    }
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
    let along = segment(xml, g, classes, class, kind_text, owner)?;
    let mut mesh = None;
    let solid = match kind_text {
        "sphere" => Solid::Sphere(at(0, "radius")?),
        // NOTE: with `fromto`, MuJoCo sizes a box or an ellipsoid by its
        // first `size` across and the segment along (half-length l/2).
        "box" => Solid::Box(match along {
            Some((_, _, l)) => {
                let r = at(0, "x half-size")?;
                [2.0 * r, 2.0 * r, l]
            }
            None => [
                2.0 * at(0, "x half-size")?,
                2.0 * at(1, "y half-size")?,
                2.0 * at(2, "z half-size")?,
            ],
        }),
        "ellipsoid" => Solid::Ellipsoid(match along {
            Some((_, _, l)) => {
                let r = at(0, "x radius")?;
                [r, r, l / 2.0]
            }
            None => [at(0, "x radius")?, at(1, "y radius")?, at(2, "z radius")?],
        }),
        "capsule" | "cylinder" => {
            let radius = at(0, "radius")?;
            let length = match along {
                Some((_, _, l)) => l,
                None => 2.0 * at(1, "half-length")?,
            };
            if kind_text == "capsule" {
                Solid::Capsule { radius, length }
            } else {
                Solid::Cylinder { radius, length }
            }
        }
        "mesh" => {
            let Some(name) = &mesh_name else {
                return Err(xml.error(
                    kind_range(),
                    format!("a mesh geom of {owner} names no `mesh` asset"),
                ));
            };
            let l = cx.meshes.load(cx.m, xml, name, owner, classes)?;
            if cx.export && (l.shell || l.legacy) {
                let why = if l.shell {
                    "a shell mesh (`inertia=\"shell\"`)"
                } else {
                    "a mesh MuJoCo's default `inertia=\"legacy\"` weighs otherwise than the solid it bounds"
                };
                return Err(xml
                    .error(
                        name.range.clone(),
                        format!("`mesh` of a geom of {owner}: {why} is weighed by `report`, not by `export --from-geometry`, which weighs the solid"),
                    )
                    .help("set `inertia=\"exact\"` on the `<mesh>` to export the solid's inertial"));
            }
            mesh = Some(l.mass);
            Solid::Mesh {
                uri: l.uri,
                scale: l.scale,
            }
        }
        "plane" | "hfield" => {
            return Err(xml
                .error(
                    kind_range(),
                    format!("`type` of a geom of {owner}: a `{kind_text}` has no volume to weigh, and MuJoCo allows one only in a static body (without joints), never in a moving one"),
                )
                .help("give the body an `<inertial>`, or put the geom in a `group` outside `<compiler inertiagrouprange>`"));
        }
        other => {
            return Err(xml.error(
                kind_range(),
                format!(
                    "`type` of a geom of {owner}: `{}` is not read for inertia; expected sphere, box, capsule, cylinder, ellipsoid or mesh",
                    crate::diag::shorten(other)
                ),
            ).help("give the body an `<inertial>`, or put the geom in a `group` outside `<compiler inertiagrouprange>`"));
        }
    };
    let pose = match along {
        Some((mid, z, _)) => Pose {
            p: mid,
            r: quat_to_matrix(z_to_quat(&z)),
        },
        None => {
            let p = match attr("pos") {
                Some(v) => xml.numbers::<3>(&v, owner)?,
                None => [0.0; 3],
            };
            // The nearest level that writes an orientation: the geom,
            // then its class, its parent class, …
            let mut found = None;
            let levels = std::iter::once((g, xml.source)).chain(classes.defaults(class, "geom"));
            for (level, source) in levels {
                let what = if level == g {
                    format!("a geom of {owner}")
                } else {
                    "a default class's `<geom>`".to_string()
                };
                if let Some((form, v)) = one_orientation(&Xml { source }, level, &what)? {
                    // NOTE: a class of another file is pointed at the
                    // geom that takes it (`Classes::attr`).
                    let v = if std::ptr::eq(source, xml.source) {
                        v
                    } else {
                        Value {
                            range: xml.tag(g),
                            exact: false,
                            ..v
                        }
                    };
                    found = Some((form, v));
                    break;
                }
            }
            let r = match found {
                Some((form, v)) => quat_to_matrix(orientation(xml, form, &v, owner, &cx.settings)?),
                None => Pose::IDENTITY.r,
            };
            Pose { p, r }
        }
    };
    let amount = match (attr("mass"), attr("density")) {
        (Some(m), _) => Some(Amount::Mass(positive(
            xml,
            &m,
            xml.number(&m, owner)?,
            owner,
        )?)),
        (None, Some(d)) => Some(Amount::Density(positive(
            xml,
            &d,
            xml.number(&d, owner)?,
            owner,
        )?)),
        (None, None) => None,
    };
    Ok(Geometry {
        solid,
        pose,
        range: xml.tag(g),
        amount,
        mesh,
    })
}

/// A `fromto` segment: its midpoint, unit direction and length.
type Segment = ([f64; 3], [f64; 3], f64);

/// The segment a geom's `fromto` (its own or its class's) gives: its
/// midpoint, direction and length; checked as MuJoCo checks it (not with
/// `pos`, only on a capsule, cylinder, box or ellipsoid) also for a geom
/// that is not weighed, since MuJoCo refuses the model.
fn segment(
    xml: &Xml,
    g: Node,
    classes: &Classes,
    class: Class,
    kind_text: &str,
    owner: &str,
) -> Result<Option<Segment>, Diagnostic> {
    let attr = |n: &str| classes.attr(xml, g, class, "geom", n);
    let fromto = attr("fromto");
    if let (Some(f), Some(p)) = (&fromto, attr("pos")) {
        let later = if f.range.start > p.range.start {
            f.range.clone()
        } else {
            p.range
        };
        return Err(xml.error(
            later,
            format!("a geom of {owner} has both `pos` and `fromto` (its own or its default class's): MuJoCo refuses both"),
        ));
    }
    Ok(match &fromto {
        Some(f) => {
            if !matches!(kind_text, "capsule" | "cylinder" | "box" | "ellipsoid") {
                return Err(xml.error(
                    f.range.clone(),
                    format!("`fromto` of a {kind_text} geom of {owner}: MuJoCo allows it only on a capsule, cylinder, box or ellipsoid"),
                ));
            }
            let e = xml.numbers::<6>(f, owner)?;
            let v = [e[3] - e[0], e[4] - e[1], e[5] - e[2]];
            let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if !(l > 0.0) {
                return Err(xml.error(
                    f.range.clone(),
                    format!(
                        "`fromto` of a {kind_text} geom of {owner}: expected two different points"
                    ),
                ));
            }
            let mid = [
                (e[0] + e[3]) / 2.0,
                (e[1] + e[4]) / 2.0,
                (e[2] + e[5]) / 2.0,
            ];
            Some((mid, [v[0] / l, v[1] / l, v[2] / l], l))
        }
        None => None,
    })
}
