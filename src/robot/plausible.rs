//! A link's inertia that looks written in other units (issue 31, item 4):
//! its largest radius of gyration, √(I₃/m), beyond what its geometry
//! allows. About the centre of mass, which lies in the body's convex hull,
//! no point of the body is farther than the body's diameter, so k ≤ 2R,
//! R the distance from the link origin to the farthest point of its
//! `<visual>` and `<collision>` geometry (MJCF: the body's own `<geom>`s).
//! A link with no geometry whose extent can be read here (none, a mesh, a
//! size from an MJCF default class) is held to `NO_GEOMETRY` instead.
//!
//! The warning names the unit factor that brings k nearest a typical
//! radius of gyration (half of R; with no geometry, the edge of a cube of
//! water of the link's mass), and the engines that refuse the link: one
//! warning per link, whatever the engines say. A link with a negative
//! principal moment, or whose slip of units an engine's likely cause
//! already names (`cause`: one number in other units), is not warned of.

use super::Dialect;
use super::engine::Engine;
use roxmltree::{Document, Node};

/// The largest radius of gyration, m, of a link without readable geometry.
pub const NO_GEOMETRY: f64 = 10.0;

/// The unit slips tried: the factor that takes the tensor to kg·m², and
/// the unit it was then written in.
const FACTORS: [(f64, &str, &str); 5] = [
    (1e-3, "1e-3", "g·m²"),
    (1e-4, "1e-4", "kg·cm²"),
    (1e-6, "1e-6", "kg·mm²"),
    (1e-7, "1e-7", "g·cm²"),
    (1e-9, "1e-9", "g·mm²"),
];

/// What `gyration` judges of a link: its inertial, and the engines'
/// verdicts on it.
pub struct Link<'a> {
    /// The link's element in the text (URDF and SDFormat `<link>`, MJCF
    /// `<body>`).
    pub element: &'a str,
    /// kg.
    pub mass: f64,
    /// Ascending, kg·m².
    pub principal_moments: [f64; 3],
    /// The engines that refuse it.
    pub refused: Vec<Engine>,
    /// Whether an engine's likely cause is already a slip of units.
    pub units_named: bool,
}

/// The warning for a link whose radius of gyration its geometry cannot
/// hold, if it is one.
pub fn gyration(dialect: Dialect, link: &Link) -> Option<String> {
    let m = link.mass;
    let [i1, _, i3] = link.principal_moments;
    // NOTE: a negative moment has no radius of gyration, and a slip of
    // units some engine's likely cause already names (one number in other
    // units than the rest) is said there, not twice.
    if !(m > 0.0 && i1 >= 0.0 && i3 > 0.0) || link.units_named {
        return None;
    }
    let k = (i3 / m).sqrt();
    let reach = reach(dialect, link.element);
    let (limit, what) = match reach {
        Some(r) => (2.0 * r, "twice its geometry's reach from the link origin"),
        None => (NO_GEOMETRY, "the limit for a link without geometry read"),
    };
    if !(k > limit) || !k.is_finite() {
        return None;
    }
    let typical = reach.map_or((m / 1000.0).cbrt(), |r| 0.5 * r);
    let slip = FACTORS
        .iter()
        .map(|&(f, written, unit)| (k * f.sqrt(), written, unit))
        .filter(|(scaled, ..)| *scaled <= limit)
        .min_by(|a, b| {
            let off = |k: f64| (k / typical).ln().abs();
            off(a.0).total_cmp(&off(b.0))
        });
    let fix = match slip {
        Some((scaled, written, unit)) => format!(
            "the inertia looks like it is in {unit}: ×{written} gives {} m",
            short(scaled)
        ),
        None => "check the inertia's and the mass's units".to_string(),
    };
    let refused: Vec<&str> = link.refused.iter().map(|e| e.name()).collect();
    let engines = match refused.as_slice() {
        [] => "no engine checked refuses it as written".to_string(),
        names => format!("refused by {}", names.join(", ")),
    };
    Some(format!(
        "its radius of gyration √(I₃/m) is {} m, more than {} m ({what}): {fix}; {engines}",
        short(k),
        short(limit)
    ))
}

/// `x` to 3 significant digits (`numeric::significant`).
fn short(x: f64) -> String {
    crate::numeric::significant(x, 3)
}

/// The farthest any of the link's geometry reaches from its origin, m;
/// None when it has none, or any whose extent is not read here.
fn reach(dialect: Dialect, element: &str) -> Option<f64> {
    let doc = Document::parse(element).ok()?;
    let link = doc.root_element();
    let mut far = None::<f64>;
    let mut add = |r: Option<f64>| -> Option<()> {
        let r = r.filter(|r| r.is_finite() && *r >= 0.0)?;
        far = Some(far.map_or(r, |f| f.max(r)));
        Some(())
    };
    match dialect {
        Dialect::Urdf | Dialect::Sdf => {
            let holders = link
                .descendants()
                .filter(|n| matches!(n.tag_name().name(), "visual" | "collision"));
            for h in holders {
                add(held(dialect, h))?;
            }
        }
        Dialect::Mjcf => {
            for g in link.children().filter(|n| n.has_tag_name("geom")) {
                add(geom(g))?;
            }
        }
    }
    far
}

/// The numbers of a space-separated list.
fn numbers(text: &str) -> Option<Vec<f64>> {
    text.split_whitespace().map(|t| t.parse().ok()).collect()
}

fn child<'a, 'i>(n: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    n.children().find(|c| c.has_tag_name(name))
}

/// A child element's text as numbers (SDFormat `<size>1 2 3</size>`).
fn child_numbers(n: Node, name: &str) -> Option<Vec<f64>> {
    numbers(child(n, name)?.text()?)
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// A URDF or SDFormat `<visual>` or `<collision>`: the distance of its
/// origin plus its shape's bounding radius.
fn held(dialect: Dialect, h: Node) -> Option<f64> {
    let at = match dialect {
        Dialect::Urdf => child(h, "origin")
            .and_then(|o| o.attribute("xyz"))
            .map_or(Some(vec![0.0; 3]), numbers)?,
        _ => child(h, "pose")
            .and_then(|p| p.text())
            .map_or(Some(vec![0.0; 3]), numbers)?,
    };
    let geometry = child(h, "geometry")?;
    let shape = geometry.children().find(Node::is_element)?;
    let attr = |n: &str| -> Option<f64> { shape.attribute(n)?.parse().ok() };
    let value = |n: &str| -> Option<f64> {
        match dialect {
            Dialect::Urdf => attr(n),
            _ => child_numbers(shape, n).and_then(|v| v.first().copied()),
        }
    };
    let radius = match shape.tag_name().name() {
        "box" => {
            let size = match dialect {
                Dialect::Urdf => numbers(shape.attribute("size")?)?,
                _ => child_numbers(shape, "size")?,
            };
            0.5 * norm(&size)
        }
        "sphere" => value("radius")?,
        "cylinder" => value("radius")?.hypot(0.5 * value("length")?),
        "capsule" => value("radius")? + 0.5 * value("length")?,
        "ellipsoid" => child_numbers(shape, "radii")?
            .into_iter()
            .fold(0.0, f64::max),
        _ => return None,
    };
    Some(norm(at.get(..3)?) + radius)
}

/// An MJCF `<geom>`: the farther end of its `fromto` or its `pos`, plus
/// its bounding radius from `size` (MuJoCo's half-sizes).
fn geom(g: Node) -> Option<f64> {
    let size = numbers(g.attribute("size")?)?;
    let kind = g.attribute("type").unwrap_or("sphere");
    if let Some(fromto) = g.attribute("fromto") {
        let p = numbers(fromto)?;
        let ends = norm(p.get(..3)?).max(norm(p.get(3..6)?));
        return Some(ends + size.first().copied()?);
    }
    let at = g.attribute("pos").map_or(Some(vec![0.0; 3]), numbers)?;
    let s = |i: usize| size.get(i).copied();
    let radius = match kind {
        "sphere" => s(0)?,
        "capsule" => s(0)? + s(1)?,
        "cylinder" => s(0)?.hypot(s(1)?),
        "box" => norm(size.get(..3)?),
        "ellipsoid" => size.get(..3)?.iter().copied().fold(0.0, f64::max),
        _ => return None,
    };
    Some(norm(at.get(..3)?) + radius)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_urdf_box_reaches_its_half_diagonal_past_its_origin() {
        let link = "<link name='a'><visual><origin xyz='0 0 1'/><geometry><box size='2 2 1'/></geometry></visual></link>";
        assert_eq!(reach(Dialect::Urdf, link), Some(2.5));
    }

    #[test]
    fn an_sdf_cylinder_reaches_the_rim_of_its_end() {
        let link = "<link name='a'><collision name='c'><geometry><cylinder><radius>3</radius><length>8</length></cylinder></geometry></collision></link>";
        assert_eq!(reach(Dialect::Sdf, link), Some(5.0));
    }

    #[test]
    fn an_mjcf_capsule_by_fromto_reaches_past_its_far_end() {
        let body = "<body><geom type='capsule' fromto='0 0 0 0 0 2' size='0.5'/><body><geom size='100'/></body></body>";
        assert_eq!(reach(Dialect::Mjcf, body), Some(2.5));
    }

    #[test]
    fn a_mesh_leaves_the_reach_unknown() {
        let link = "<link name='a'><visual><geometry><box size='1 1 1'/></geometry></visual><visual><geometry><mesh filename='a.stl'/></geometry></visual></link>";
        assert_eq!(reach(Dialect::Urdf, link), None);
    }
}
