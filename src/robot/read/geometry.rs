//! Each link's `<collision>` or `<visual>` geometry (URDF, SDFormat), for
//! inertials computed from it (`export --from-geometry`): the solid, its
//! pose in the link frame and its element. SI.

use super::{Xml, child, children, qname, quoted, rpy};
use crate::diag::{Diagnostic, Source};
use crate::robot::kinematics::Pose;
use crate::robot::{Description, Dialect};
use roxmltree::Node;
use std::ops::Range;

/// A geometry's solid, in its own frame (cylinder and capsule along z).
#[derive(Clone, Debug, PartialEq)]
pub enum Solid {
    /// Full sizes along x, y, z.
    Box([f64; 3]),
    Cylinder {
        radius: f64,
        length: f64,
    },
    Sphere(f64),
    /// `length` between the hemispheres' centres.
    Capsule {
        radius: f64,
        length: f64,
    },
    Ellipsoid([f64; 3]),
    /// The file as written (`package://…`, `file://…`, or a path) and its
    /// `scale`.
    Mesh {
        uri: String,
        scale: [f64; 3],
    },
}

/// One `<collision>` or `<visual>` element.
#[derive(Clone, Debug, PartialEq)]
pub struct Geometry {
    pub solid: Solid,
    pub pose: Pose,
    /// The element's start tag.
    pub range: Range<usize>,
    /// MJCF: the geom's own `mass`, else its `density`; None where it
    /// gives neither (MJCF: `--density`/`--material`, else MuJoCo's 1000
    /// kg/m³) and for URDF and SDFormat (the command's flag).
    pub amount: Option<Amount>,
    /// MJCF: a mesh geom's integrals as MuJoCo weighs them (`mjcf_mesh`);
    /// None for every other geometry.
    pub mesh: Option<std::sync::Arc<MeshMass>>,
}

/// An MJCF mesh's integrals per unit density, in the geom's frame (its
/// `scale` applied): volume (a shell's area), centroid, and ∫ρρᵀ about the
/// centroid.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshMass {
    pub measure: crate::numeric::DD,
    pub centroid: [crate::numeric::DD; 3],
    pub second: crate::numeric::M3<crate::numeric::DD>,
}

/// What an MJCF geom says it weighs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Amount {
    Mass(f64),
    Density(f64),
}

/// Per link of `d` (in its order), its geometries of the kind asked for
/// (`visual`, else collision), read only for the links `need` marks (all
/// where None): another link's geometry is not read, so what it says
/// cannot stop the export of the link asked for (`--link`). Each link's
/// geometry is read where the link is written (`Link::site`: the file
/// `source` includes it from, if so), and its ranges are in that file; an
/// MJCF file's includes are followed, resolved by `r`.
pub fn geometry(
    source: &Source,
    d: &Description,
    visual: bool,
    need: Option<&[bool]>,
    r: &super::Resolve,
) -> Result<(Vec<Vec<Geometry>>, Vec<super::MeshWarning>), Diagnostic> {
    if d.format == Dialect::Mjcf {
        let doc = super::parse(source)?;
        let root = doc.root_element();
        if !root.descendants().any(|n| qname(n) == "include") {
            return super::geoms_of_mjcf(&Xml { source }, root, d, need);
        }
        let all = vec![true; d.links.len()];
        return super::mjcf_geometry_in(source, d, need.unwrap_or(&all), r, true);
    }
    let kind = if visual { "visual" } else { "collision" };
    // Each file a link is written in, parsed once, its links' elements by
    // where they start.
    let count = d.files.sources.len() + 1;
    let docs = (0..count)
        .map(|k| super::parse(d.files.source(source, k)))
        .collect::<Result<Vec<_>, _>>()?;
    let starts: Vec<std::collections::HashMap<usize, Node>> = docs
        .iter()
        .map(|doc| {
            doc.descendants()
                .filter(|n| qname(*n) == "link")
                .map(|n| (n.range().start, n))
                .collect()
        })
        .collect();
    let mut out = Vec::with_capacity(d.links.len());
    for (i, l) in d.links.iter().enumerate() {
        if need.is_some_and(|n| !n[i]) {
            out.push(Vec::new());
            continue;
        }
        let xml = Xml {
            source: d.files.source(source, l.site.file),
        };
        let link = starts[l.site.file]
            .get(&l.site.element.start)
            .copied()
            .expect("invariant: the reader found the link's element where its site says");
        let items = link_geometry(&xml, link, d, &l.name, kind).map_err(|e| d.files.located(e))?;
        out.push(items);
    }
    // URDF and SDFormat meshes are read by `export` itself (their
    // warnings said there).
    Ok((out, Vec::new()))
}

/// The geometries of kind `kind` of the link element `link` (named `name`).
fn link_geometry(
    xml: &Xml,
    link: Node,
    d: &Description,
    name: &str,
    kind: &str,
) -> Result<Vec<Geometry>, Diagnostic> {
    let owner = format!("link {}", quoted(name));
    let mut items = Vec::new();
    for g in children(link, kind) {
        let pose = match d.format {
            Dialect::Urdf => urdf_origin(xml, g, &owner)?,
            Dialect::Sdf | Dialect::Mjcf => sdf_pose(xml, g, &owner)?,
        };
        let Some(geo) = child(g, "geometry") else {
            return Err(xml.error(
                xml.tag(g),
                format!("`<{kind}>` of {owner} has no `<geometry>`"),
            ));
        };
        let solid = match d.format {
            Dialect::Urdf => urdf_solid(xml, geo, &owner)?,
            Dialect::Sdf | Dialect::Mjcf => sdf_solid(xml, geo, &owner)?,
        };
        items.push(Geometry {
            solid,
            pose,
            range: xml.tag(g),
            amount: None,
            mesh: None,
        });
    }
    Ok(items)
}

fn urdf_origin(xml: &Xml, g: Node, owner: &str) -> Result<Pose, Diagnostic> {
    let mut pose = Pose::IDENTITY;
    if let Some(o) = child(g, "origin") {
        if let Some(v) = xml.attr(o, "xyz") {
            pose.p = xml.numbers::<3>(&v, owner)?;
        }
        if let Some(v) = xml.attr(o, "rpy") {
            let [r, p, y] = xml.numbers::<3>(&v, owner)?;
            pose.r = rpy(r.sin_cos(), p.sin_cos(), y.sin_cos());
        }
    }
    Ok(pose)
}

fn sdf_pose(xml: &Xml, g: Node, owner: &str) -> Result<Pose, Diagnostic> {
    let Some(p) = child(g, "pose") else {
        return Ok(Pose::IDENTITY);
    };
    if let Some(v) = xml.attr(p, "relative_to")
        && !v.text.is_empty()
    {
        return Err(xml.error(
            v.range.clone(),
            format!(
                "`relative_to` of a geometry's `<pose>` of {owner}: only the link frame is read"
            ),
        ));
    }
    let (p, r) = super::sdf::pose(xml, p, "", owner)?;
    Ok(Pose {
        p,
        r: r.unwrap_or(Pose::IDENTITY.r),
    })
}

/// A positive size, or an error at it.
pub(super) fn positive(
    xml: &Xml,
    v: &super::Value,
    x: f64,
    owner: &str,
) -> Result<f64, Diagnostic> {
    if x > 0.0 {
        Ok(x)
    } else {
        Err(xml.error(
            v.range.clone(),
            format!("{} of {owner}: expected a size > 0, found {x}", v.name),
        ))
    }
}

/// A mesh's `scale`: three finite numbers, none zero (a negative one
/// mirrors the mesh), or an error at it.
fn nonzero_scale(xml: &Xml, v: &super::Value, owner: &str) -> Result<[f64; 3], Diagnostic> {
    let s = xml.numbers::<3>(v, owner)?;
    if s.iter().any(|&x| x == 0.0 || !x.is_finite()) {
        return Err(xml.error(
            v.range.clone(),
            format!(
                "`scale` of {owner}'s mesh: expected three finite numbers, none zero (a zero flattens the mesh to no volume), found {} {} {}",
                s[0], s[1], s[2]
            ),
        ));
    }
    Ok(s)
}

/// The integrals of the mesh `b` with its vertices scaled by `s` (D =
/// diag(s), each finite and nonzero; a negative one mirrors it): measure
/// |det D| V (a shell's: s² A, `s` uniform), centroid D c, second moments
/// |det D| D S D (a shell's: s⁴ S). The one rule for a scaled mesh: MJCF's
/// mesh geoms (`mjcf_mesh`) and `export --from-geometry`'s URDF and
/// SDFormat meshes are both weighed by it.
pub fn scaled(b: &crate::mesh::MeshBody, s: [f64; 3]) -> MeshMass {
    use crate::mesh::Mode;
    use crate::numeric::{DD, Real};
    let d = s.map(DD::of);
    let det = (d[0] * d[1] * d[2]).abs();
    let k = match b.mode {
        Mode::Solid => det,
        // Uniform: |s|³ / |s| = s², area's factor.
        Mode::Shell => det / DD::of(s[0].abs()),
    };
    MeshMass {
        measure: k * b.measure,
        centroid: std::array::from_fn(|i| d[i] * b.centroid[i]),
        second: std::array::from_fn(|i| std::array::from_fn(|j| k * d[i] * d[j] * b.second[i][j])),
    }
}

fn urdf_solid(xml: &Xml, geo: Node, owner: &str) -> Result<Solid, Diagnostic> {
    let Some(s) = geo.children().find(Node::is_element) else {
        return Err(xml.error(xml.tag(geo), format!("`<geometry>` of {owner} is empty")));
    };
    let num = |name: &str| -> Result<f64, Diagnostic> {
        let v = xml.required(s, name, owner)?;
        let x = xml.number(&v, owner)?;
        positive(xml, &v, x, owner)
    };
    Ok(match qname(s) {
        "box" => {
            let v = xml.required(s, "size", owner)?;
            let n = xml.numbers::<3>(&v, owner)?;
            for x in n {
                positive(xml, &v, x, owner)?;
            }
            Solid::Box(n)
        }
        "cylinder" => Solid::Cylinder {
            radius: num("radius")?,
            length: num("length")?,
        },
        "capsule" => Solid::Capsule {
            radius: num("radius")?,
            length: num("length")?,
        },
        "sphere" => Solid::Sphere(num("radius")?),
        "mesh" => Solid::Mesh {
            uri: xml.required(s, "filename", owner)?.text,
            scale: match xml.attr(s, "scale") {
                Some(v) => nonzero_scale(xml, &v, owner)?,
                None => [1.0; 3],
            },
        },
        other => {
            return Err(xml.error(
                xml.tag(s),
                format!(
                    "`<{}>` of {owner}: expected `<box>`, `<cylinder>`, `<sphere>`, `<capsule>` or `<mesh>`",
                    crate::diag::shorten(other)
                ),
            ));
        }
    })
}

fn sdf_solid(xml: &Xml, geo: Node, owner: &str) -> Result<Solid, Diagnostic> {
    let Some(s) = geo.children().find(Node::is_element) else {
        return Err(xml.error(xml.tag(geo), format!("`<geometry>` of {owner} is empty")));
    };
    let text = |name: &str| -> Result<super::Value, Diagnostic> {
        child(s, name).map(|e| xml.text(e)).ok_or_else(|| {
            xml.error(
                xml.tag(s),
                format!("`<{}>` of {owner} is missing `<{name}>`", qname(s)),
            )
        })
    };
    let num = |name: &str| -> Result<f64, Diagnostic> {
        let v = text(name)?;
        let x = xml.number(&v, owner)?;
        positive(xml, &v, x, owner)
    };
    let three = |name: &str| -> Result<[f64; 3], Diagnostic> {
        let v = text(name)?;
        let n = xml.numbers::<3>(&v, owner)?;
        for x in n {
            positive(xml, &v, x, owner)?;
        }
        Ok(n)
    };
    Ok(match qname(s) {
        "box" => Solid::Box(three("size")?),
        "cylinder" => Solid::Cylinder {
            radius: num("radius")?,
            length: num("length")?,
        },
        "capsule" => Solid::Capsule {
            radius: num("radius")?,
            length: num("length")?,
        },
        "sphere" => Solid::Sphere(num("radius")?),
        "ellipsoid" => Solid::Ellipsoid(three("radii")?),
        "mesh" => Solid::Mesh {
            uri: text("uri")?.text,
            scale: match child(s, "scale") {
                Some(e) => nonzero_scale(xml, &xml.text(e), owner)?,
                None => [1.0; 3],
            },
        },
        other => {
            return Err(xml.error(
                xml.tag(s),
                format!(
                    "`<{}>` of {owner}: expected `<box>`, `<cylinder>`, `<sphere>`, `<capsule>`, `<ellipsoid>` or `<mesh>`",
                    crate::diag::shorten(other)
                ),
            ));
        }
    })
}
