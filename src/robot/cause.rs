//! The likely cause of an inertial an engine refuses: the slips that put
//! wrong tensors in robot description files, each tried as a repair — if
//! the repaired inertial is valid under the engine, that slip is named.
//! And the mirrored links whose products disagree in sign, a slip whether
//! or not an engine notices it.
//!
//! The slips, in the order they are tried (the most specific evidence
//! first):
//! 1. `mirror`: a link whose mirror partner (by name, `left_x`/`right_x`,
//!    `FL_x`/`FR_x`, …) has the same mass and moments, but whose products
//!    have the signs of no mirror image or half turn of the partner's;
//! 2. `products_sign`: all three products with the wrong sign (CAD tools
//!    and Meriam write +∫xy dm; URDF, SDFormat and MJCF want −∫xy dm);
//! 3. `order`: the six numbers in the other format's order (URDF's
//!    xx xy xz yy yz zz against MuJoCo's xx yy zz xy xz yz);
//! 4. `units`: the products, or one moment, off by a factor 10³, 10⁶ or
//!    10⁹ from the rest (g or mm against kg and m);
//! 5. `shifted`: a tensor about the centre of mass moved by the
//!    parallel-axis term as if it were about the link origin
//!    (I − m(|c|²𝟙 − c cᵀ), c the inertial's position).

use super::engine::{Engine, Facts, accepts};
use super::{Description, Link, Tensor, Written};
use serde::Serialize;

/// Which slip.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    Mirror,
    ProductsSign,
    Order,
    Units,
    Shifted,
    /// Not a slip: the tensor fails by a hair, at the edge of physical.
    Boundary,
}

/// A likely cause: the slip, and what to do about it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Cause {
    pub kind: Kind,
    pub message: String,
}

/// The names a link and its mirror image differ by: one token (split at
/// `_`, `-`, `.`, `/` or a space) swapped for its pair, any case.
const MIRROR_TOKENS: [(&str, &str); 9] = [
    ("left", "right"),
    ("l", "r"),
    ("fl", "fr"),
    ("hl", "hr"),
    ("rl", "rr"),
    ("bl", "br"),
    ("lf", "rf"),
    ("lh", "rh"),
    ("lb", "rb"),
];

fn tokens(name: &str) -> Vec<&str> {
    name.split(['_', '-', '.', '/', ' ', ':']).collect()
}

/// Whether two names are a mirror pair (names of more than `MAX_TOKENS`
/// tokens never are).
pub fn mirror_names(a: &str, b: &str) -> bool {
    let (ta, tb) = (tokens(a), tokens(b));
    if ta.len() != tb.len() || ta.len() > MAX_TOKENS {
        return false;
    }
    let mut swapped = 0;
    for (x, y) in ta.iter().zip(&tb) {
        if x == y {
            continue;
        }
        let (lx, ly) = (x.to_ascii_lowercase(), y.to_ascii_lowercase());
        if MIRROR_TOKENS
            .iter()
            .any(|&(p, q)| (lx == p && ly == q) || (lx == q && ly == p))
        {
            swapped += 1;
        } else {
            return false;
        }
    }
    swapped == 1
}

/// The link whose mirror `links[i]` is, if exactly one has a mirror name
/// and an inertial. (One link; `Mirrors` answers for every link at once.)
pub fn partner(links: &[Link], i: usize) -> Option<usize> {
    let mut found = links
        .iter()
        .enumerate()
        .filter(|(j, l)| *j != i && l.inertial.is_some() && mirror_names(&links[i].name, &l.name));
    let (j, _) = found.next()?;
    found.next().is_none().then_some(j)
}

/// A name of more tokens than this has no mirror partner: no link's name
/// is that long, and a key per token of such a name would cost its square.
const MAX_TOKENS: usize = 32;

/// A name's keys in `Mirrors`: for each token that is one of a mirror
/// pair, the tokens with that one blanked, its position, the pair, and the
/// side of the pair it is on.
fn mirror_keys(name: &str) -> Vec<(MirrorKey<'_>, usize)> {
    let t = tokens(name);
    if t.len() > MAX_TOKENS {
        return Vec::new();
    }
    let mut out = Vec::new();
    for (k, tok) in t.iter().enumerate() {
        let lower = tok.to_ascii_lowercase();
        for (pair, &(p, q)) in MIRROR_TOKENS.iter().enumerate() {
            let side = if lower == p {
                0
            } else if lower == q {
                1
            } else {
                continue;
            };
            let mut rest = t.clone();
            rest[k] = "";
            out.push(((rest, k, pair), side));
        }
    }
    out
}

/// The other tokens, the position of the swapped one, its pair.
type MirrorKey<'a> = (Vec<&'a str>, usize, usize);

/// Every link's mirror partner (`partner`'s answer for each), found through
/// a map of names with their swappable token taken out, in time linear in
/// the links: comparing every pair of names would take minutes for 10⁵
/// links.
pub struct Mirrors {
    partner: Vec<Option<usize>>,
}

impl Mirrors {
    pub fn of(links: &[Link]) -> Mirrors {
        // A name's keys: for each token that is one of a mirror pair, the
        // tokens with that one left out, its position and the pair. Two
        // names are mirror names exactly when they share a key and stand on
        // its two sides (`mirror_names`).
        let mut map: std::collections::HashMap<MirrorKey, [Vec<usize>; 2]> =
            std::collections::HashMap::new();
        let all: Vec<Vec<(MirrorKey, usize)>> =
            links.iter().map(|l| mirror_keys(&l.name)).collect();
        for (j, keys) in all.iter().enumerate() {
            if links[j].inertial.is_none() {
                continue;
            }
            for (key, side) in keys {
                super::steps::step(1);
                map.entry(key.clone()).or_default()[*side].push(j);
            }
        }
        let partner = all
            .iter()
            .enumerate()
            .map(|(i, keys)| {
                let mut found = keys
                    .iter()
                    .filter_map(|(key, side)| map.get(key).map(|s| &s[1 - side]))
                    .flatten()
                    .inspect(|_| super::steps::step(1))
                    .filter(|&&j| j != i);
                let j = *found.next()?;
                found.next().is_none().then_some(j)
            })
            .collect();
        Mirrors { partner }
    }

    /// The link whose mirror link `i` is: `partner(links, i)`.
    pub fn partner(&self, i: usize) -> Option<usize> {
        self.partner[i]
    }
}

/// Relative closeness of mirrored values: equal to this fraction of the
/// tensor's size (files round their numbers to 4 to 6 digits).
const SAME: f64 = 1e-3;

/// Whether two link-frame tensors have the same mass and magnitudes, all
/// three products non-zero, and products whose signs no reflection or half
/// turn about the axes maps onto each other: such maps flip an even number
/// of the three products' signs (diag(s₁, s₂, s₃) flips xy by s₁s₂, xz by
/// s₁s₃, yz by s₂s₃, whose product is +1), so an odd number of flips is a
/// slip.
fn disagree(ma: f64, a: &Tensor, mb: f64, b: &Tensor) -> bool {
    let size = (a.xx.abs() + a.yy.abs() + a.zz.abs()).max(f64::MIN_POSITIVE);
    let near = |x: f64, y: f64, s: f64| (x - y).abs() <= SAME * s;
    if !near(ma, mb, ma.abs().max(mb.abs())) {
        return false;
    }
    let (pa, pb) = (a.products(), b.products());
    let same_size = near(a.xx, b.xx, size)
        && near(a.yy, b.yy, size)
        && near(a.zz, b.zz, size)
        && (0..3).all(|k| near(pa[k].abs(), pb[k].abs(), size));
    let nonzero = (0..3).all(|k| pa[k].abs() > SAME * size && pb[k].abs() > SAME * size);
    let flips = (0..3).filter(|&k| (pa[k] < 0.0) != (pb[k] < 0.0)).count();
    same_size && nonzero && flips % 2 == 1
}

/// A warning for a link whose products disagree in sign with its mirror
/// partner's, valid or not.
pub fn mirror_warning(d: &Description, mirrors: &Mirrors, i: usize) -> Option<String> {
    let j = mirrors.partner(i)?;
    let (a, b) = (d.links[i].inertial.as_ref()?, d.links[j].inertial.as_ref()?);
    disagree(a.mass, &a.tensor_in_link(), b.mass, &b.tensor_in_link()).then(|| {
        let s = |t: &Tensor| {
            t.products()
                .map(|p| if p < 0.0 { "−" } else { "+" })
                .join("")
        };
        format!(
            "its products of inertia (signs {} for xy xz yz) disagree with those of its mirror link \"{}\" ({}): no reflection or half turn maps one onto the other, so one of them has a product with the wrong sign",
            s(&a.tensor_in_link()),
            d.links[j].name,
            s(&b.tensor_in_link())
        )
    })
}

/// The axis across whose plane two centres of mass are mirror images: the
/// one component opposite and non-zero, the others equal (to `SAME` of the
/// distance).
fn mirror_axis(a: [f64; 3], b: [f64; 3]) -> Option<usize> {
    let size = a.iter().chain(&b).fold(0.0f64, |m, x| m.max(x.abs()));
    let near = |x: f64, y: f64| (x - y).abs() <= SAME * size;
    let mut found = None;
    for k in 0..3 {
        if near(a[k], b[k]) {
            continue;
        }
        if near(a[k], -b[k]) && found.is_none() {
            found = Some(k);
        } else {
            return None;
        }
    }
    found
}

fn facts_with(f: &Facts, tensor: Tensor) -> Facts {
    Facts { tensor, ..*f }
}

/// A failure by less than this (relative margin) is at the boundary of
/// physical rather than a slip: the slips above break a rule by a large
/// fraction, and any repair (adding the parallel-axis term, scaling a
/// moment) would "fix" a hair's breadth. NOTE: 1e-4, as part files and CAD
/// reports round moments to 4 to 6 digits, which can tip a flat plate's
/// A + B = C either way.
const MARGINAL: f64 = 1e-4;

/// The likely cause of `engine` refusing link `i` (whose facts are `f`), if
/// one slip, undone, makes it valid, or the failure is marginal.
pub fn likely(
    d: &Description,
    mirrors: &Mirrors,
    i: usize,
    f: &Facts,
    engine: Engine,
) -> Option<Cause> {
    super::steps::step(1);
    let link = &d.links[i];
    let inertial = link.inertial.as_ref()?;
    let ok = |t: Tensor| accepts(engine, &facts_with(f, t), &d.compiler);
    let e = engine.name();
    let verdict = super::engine::judge(engine, f, &d.compiler);
    let failed: Vec<_> = verdict.rules.iter().filter(|r| !r.holds).collect();
    if !failed.is_empty()
        && failed
            .iter()
            .all(|r| r.margin.is_some_and(|m| m > -MARGINAL))
    {
        let worst = failed
            .iter()
            .filter_map(|r| r.margin)
            .fold(0.0f64, f64::min);
        return Some(Cause {
            kind: Kind::Boundary,
            message: format!(
                "no slip: it fails by only {worst:.1e} (relative), a tensor at the edge of physical — a thin rod's or a flat plate's moments rounded the wrong way (A + B = C exactly for a plate), or a moment at zero; round the largest moment down (or the others up), or give the body its real thickness"
            ),
        });
    }
    // 1. Mirror: the partner's products with this link's signs made even.
    if let Some(j) = mirrors.partner(i) {
        let other = d.links[j].inertial.as_ref()?;
        let (mine, theirs) = (inertial.tensor_in_link(), other.tensor_in_link());
        if inertial.rotation.is_none()
            && disagree(inertial.mass, &mine, other.mass, &theirs)
            && accepts(
                engine,
                &Facts {
                    mass: other.mass,
                    tensor: theirs,
                    ..*f
                },
                &d.compiler,
            )
        {
            // The product to flip: the one that differs from the partner's
            // mirror image across the plane its centre of mass says (the
            // axis along which the two centres are opposite); else each
            // in turn.
            let order = match mirror_axis(inertial.pos, other.pos) {
                Some(axis) => {
                    // A reflection across the plane normal to `axis` flips
                    // the products involving it: xy (x, y), xz (x, z), yz (y, z).
                    let involves = [[0, 1], [0, 2], [1, 2]].map(|p| p.contains(&axis));
                    let (mp, tp) = (mine.products(), theirs.products());
                    (0..3)
                        .filter(|&k| (mp[k] < 0.0) != ((tp[k] < 0.0) != involves[k]))
                        .collect::<Vec<_>>()
                }
                None => vec![0, 1, 2],
            };
            for k in order {
                let mut t = mine;
                match k {
                    0 => t.xy = -t.xy,
                    1 => t.xz = -t.xz,
                    _ => t.yz = -t.yz,
                }
                if ok(t) {
                    let name = ["ixy", "ixz", "iyz"][k];
                    return Some(Cause {
                        kind: Kind::Mirror,
                        message: format!(
                            "its products disagree in sign with its mirror link \"{}\": with the sign of `{name}` flipped it mirrors that link and is valid under {e}",
                            d.links[j].name
                        ),
                    });
                }
            }
        }
    }
    let t = f.tensor;
    // 2. Products' sign.
    if t.products().iter().any(|&p| p != 0.0) {
        let flipped = Tensor {
            xy: -t.xy,
            xz: -t.xz,
            yz: -t.yz,
            ..t
        };
        if ok(flipped) {
            return Some(Cause {
                kind: Kind::ProductsSign,
                message: format!(
                    "the products of inertia have the wrong sign: with ixy, ixz and iyz negated it is valid under {e}; the file wants the tensor's entries (−∫xy dm), CAD tools often show +∫xy dm"
                ),
            });
        }
    }
    // 3. The other format's order.
    if f.written != Written::Diagonal {
        let (other, read_as) = match f.written {
            Written::Full => (
                // Written in URDF's order xx xy xz yy yz zz.
                Tensor {
                    xx: t.xx,
                    xy: t.yy,
                    xz: t.zz,
                    yy: t.xy,
                    yz: t.xz,
                    zz: t.yz,
                },
                "URDF's order (xx xy xz yy yz zz), not fullinertia's (xx yy zz xy xz yz)",
            ),
            _ => (
                // Written in MuJoCo's order xx yy zz xy xz yz.
                Tensor {
                    xx: t.xx,
                    yy: t.xy,
                    zz: t.xz,
                    xy: t.yy,
                    xz: t.yz,
                    yz: t.zz,
                },
                "MuJoCo's fullinertia order (xx yy zz xy xz yz), not ixx ixy ixz iyy iyz izz",
            ),
        };
        if ok(other) {
            return Some(Cause {
                kind: Kind::Order,
                message: format!(
                    "the six numbers look written in {read_as}: read that way it is valid under {e}"
                ),
            });
        }
    }
    // 4. Units: products or one moment off by 10^±3, 10^±6, 10^±9.
    for k in [3, 6, 9] {
        for s in [10f64.powi(-k), 10f64.powi(k)] {
            let scaled = Tensor {
                xy: t.xy * s,
                xz: t.xz * s,
                yz: t.yz * s,
                ..t
            };
            if t.products().iter().any(|&p| p != 0.0) && ok(scaled) {
                return Some(Cause {
                    kind: Kind::Units,
                    message: format!(
                        "the products look {} in other units (g or mm against kg and m): multiplied by {} it is valid under {e}",
                        if s < 1.0 {
                            "too large, written"
                        } else {
                            "too small, written"
                        },
                        if s < 1.0 {
                            format!("1e-{k}")
                        } else {
                            format!("1e{k}")
                        }
                    ),
                });
            }
            for (m, name) in ["ixx", "iyy", "izz"].iter().enumerate() {
                let mut u = t;
                match m {
                    0 => u.xx *= s,
                    1 => u.yy *= s,
                    _ => u.zz *= s,
                }
                if ok(u) {
                    return Some(Cause {
                        kind: Kind::Units,
                        message: format!(
                            "`{name}` looks written in other units than the rest (g or mm against kg and m): multiplied by {} it is valid under {e}",
                            if s < 1.0 {
                                format!("1e-{k}")
                            } else {
                                format!("1e{k}")
                            }
                        ),
                    });
                }
            }
        }
    }
    // 5. Shifted: add back m(|c|²𝟙 − c cᵀ), in the inertial frame.
    if inertial.rotation.is_none() && f.mass > 0.0 {
        let c = inertial.pos;
        let c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        if c2 > 0.0 {
            let m = f.mass;
            let back = Tensor {
                xx: t.xx + m * (c2 - c[0] * c[0]),
                yy: t.yy + m * (c2 - c[1] * c[1]),
                zz: t.zz + m * (c2 - c[2] * c[2]),
                xy: t.xy - m * c[0] * c[1],
                xz: t.xz - m * c[0] * c[2],
                yz: t.yz - m * c[1] * c[2],
            };
            if ok(back) {
                return Some(Cause {
                    kind: Kind::Shifted,
                    message: format!(
                        "the tensor looks moved by the parallel-axis term m(|c|²𝟙 − c cᵀ) as if it were about the link origin, though it was about the centre of mass: with the term added back it is valid under {e}; the file wants the tensor about the centre of mass"
                    ),
                });
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mirror_names_differ_by_one_swapped_token() {
        assert!(mirror_names("left_finger", "right_finger"));
        assert!(mirror_names("FL_thigh", "FR_thigh"));
        assert!(mirror_names("arm_l_link", "arm_r_link"));
        assert!(mirror_names("LF_HIP", "RF_HIP"));
        assert!(!mirror_names("left_finger", "left_finger"));
        assert!(!mirror_names("left_finger", "right_thumb"));
        assert!(!mirror_names("FL_thigh", "RR_thigh"));
        assert!(!mirror_names("l", "link"));
    }

    fn link(name: &str, inertial: bool) -> Link {
        Link {
            name: name.to_string(),
            range: 0..0,
            inertial: inertial.then(|| super::super::Inertial {
                mass: 1.0,
                pos: [0.0; 3],
                rotation: None,
                tensor: Tensor::default(),
                written: Written::Attributes,
                range: 0..0,
            }),
            moving: false,
            parent: None,
            site: Default::default(),
        }
    }

    #[test]
    fn the_map_of_mirrors_finds_what_comparing_every_pair_finds() {
        let long_l = vec!["l"; MAX_TOKENS + 1].join("_");
        let long_r = format!("r{}", &long_l[1..]);
        let names = [
            ("left_finger", true),
            ("right_finger", true),
            ("RIGHT_finger", false),
            ("FL_thigh", true),
            ("FR_thigh", true),
            ("FR-thigh", true),
            ("RR_thigh", true),
            ("arm_l_link", true),
            ("arm_r_link", true),
            ("arm_r_link", true),
            ("l_r", true),
            ("r_r", true),
            ("l_l", true),
            ("a__l", true),
            ("a__r", true),
            ("left", true),
            ("Left", true),
            ("right", false),
            (long_l.as_str(), true),
            (long_r.as_str(), true),
        ];
        let links: Vec<Link> = names.iter().map(|&(n, i)| link(n, i)).collect();
        let mirrors = Mirrors::of(&links);
        for i in 0..links.len() {
            assert_eq!(mirrors.partner(i), partner(&links, i), "{}", links[i].name);
        }
        // Some found, some ambiguous (two candidates: the separators do
        // not count), some none.
        assert_eq!(mirrors.partner(0), Some(1));
        assert_eq!(mirrors.partner(4), Some(3));
        assert_eq!(mirrors.partner(3), None);
        assert_eq!(mirrors.partner(7), None);
        assert_eq!(mirrors.partner(18), None);
    }

    #[test]
    fn an_odd_number_of_sign_flips_is_no_mirror_image() {
        let a = Tensor {
            xx: 1.0,
            yy: 1.0,
            zz: 1.0,
            xy: 0.1,
            xz: 0.1,
            yz: 0.1,
        };
        // A reflection across y = 0 flips xy and yz: even, fine.
        let mirrored = Tensor {
            xy: -0.1,
            yz: -0.1,
            ..a
        };
        assert!(!disagree(1.0, &a, 1.0, &mirrored));
        let slip = Tensor { xy: -0.1, ..a };
        assert!(disagree(1.0, &a, 1.0, &slip));
        // Different masses are not a mirror pair.
        assert!(!disagree(1.0, &a, 2.0, &slip));
    }
}
