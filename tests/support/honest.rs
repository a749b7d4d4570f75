//! Every value of a `report --format json` against the exact body, with
//! its `error_bounds` entry (issue 30): the actual error of each, the
//! bound claimed, and the storage floor docs/accuracy.md defines (what
//! storing the exact result in the arithmetic would leave: u of a scalar,
//! of the largest entry of a vector or tensor; for a principal moment the
//! arithmetic's unit of the largest moment plus u of itself; for an axis u
//! over the relative gap). A key of `error_bounds` this module does not
//! know is a failure: every value with a bound is compared.

use super::reference::{self as r, Exact, M3, Q, V3};
use num_traits::{Signed, Zero};
use serde_json::Value;

/// f64's unit roundoff, and double-double's as the stress tests take it (2⁻¹⁰⁴).
pub const U: f64 = f64::EPSILON / 2.0;
pub const U_DD: f64 = 4.930380657631324e-32;

/// What a report must be compared with, SI.
pub struct Expected {
    pub body: Exact,
    /// The reference point (`about`, else the centre of mass).
    pub point: V3,
    /// Report axes: rows are the report axes in the file's frame.
    pub axes: M3,
    /// ω and α as read, in the report axes (rad/s, rad/s²).
    pub omega: V3,
    pub alpha: V3,
}

/// One value: its JSON key, the value, its actual error, the bound claimed
/// and the storage floor.
#[derive(Clone, Debug)]
pub struct Item {
    pub key: String,
    pub value: f64,
    pub error: f64,
    pub bound: f64,
    pub floor: f64,
    /// Whether error ≤ bound, decided exactly (a radius's by squaring).
    pub honest: bool,
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

fn turn(a: &M3, m: &M3) -> M3 {
    r::mmul(&r::mmul(a, m), &r::transpose(a))
}

fn top(m: &M3) -> f64 {
    m.iter()
        .flatten()
        .map(|x| r::f(&x.abs()))
        .fold(0.0, f64::max)
}

fn vtop(v: &V3) -> f64 {
    v.iter().map(|x| r::f(&x.abs())).fold(0.0, f64::max)
}

/// The exact values every report of one body is compared with, formed
/// once (the eigenvalues are the cost).
pub struct Prepared {
    i_com: M3,
    i_ref: M3,
    com_ref: V3,
    h: V3,
    t: Q,
    m: V3,
    pr: r::Principal,
    pr_ref: r::Principal,
    com_scale: f64,
}

pub fn prepare(e: &Expected) -> Prepared {
    let a = &e.axes;
    let body = &e.body;
    let i_ref_file = body.inertia_about(&e.point);
    let i_ref = turn(a, &i_ref_file);
    let offset: V3 = std::array::from_fn(|j| &body.com[j] - &e.point[j]);
    let h = r::mvec(&i_ref, &e.omega);
    let ia = r::mvec(&i_ref, &e.alpha);
    let wxh = r::cross(&e.omega, &h);
    Prepared {
        i_com: turn(a, &body.inertia),
        com_ref: r::mvec(a, &offset),
        t: r::dot(&e.omega, &h) / r::int(2),
        m: std::array::from_fn(|j| &ia[j] + &wxh[j]),
        h,
        i_ref,
        pr: r::principal(&body.inertia),
        pr_ref: r::principal(&i_ref_file),
        com_scale: body.com_scale(),
    }
}

/// Every value of `v` that has an `error_bounds` entry (`p`: `prepare` of
/// `e`).
pub fn measure(v: &Value, e: &Expected, p: &Prepared) -> Vec<Item> {
    let unit = match v["precision"].as_str() {
        Some("extended") => U_DD,
        _ => U,
    };
    let b = &v["error_bounds"];
    let a = &e.axes;
    let body = &e.body;
    let Prepared {
        i_com,
        i_ref,
        com_ref,
        h,
        t,
        m,
        pr,
        pr_ref,
        com_scale,
    } = p;
    let com_scale = *com_scale;
    let mut out = Vec::new();
    let plain =
        |out: &mut Vec<Item>, key: String, value: &Value, exact: &Q, bound: &Value, floor: f64| {
            let x = num(value);
            let error = r::f(&(r::q(x) - exact).abs());
            let bound = num(bound);
            out.push(Item {
                honest: error <= bound,
                key,
                value: x,
                error,
                bound,
                floor,
            });
        };
    let keys: Vec<String> = b
        .as_object()
        .expect("error_bounds is an object")
        .keys()
        .cloned()
        .collect();
    let abs_sum = |m: &M3, w: &V3| -> f64 {
        (0..3)
            .map(|j| (0..3).map(|k| r::f(&(&m[j][k] * &w[k]).abs())).sum::<f64>())
            .fold(0.0, f64::max)
    };
    for key in keys {
        let at = |j: usize| format!("{key}[{j}]");
        match key.as_str() {
            "mass" => {
                let f = U * r::f(&body.mass);
                plain(&mut out, key.clone(), &v["mass"], &body.mass, &b["mass"], f);
            }
            "kinetic_energy" => {
                let f = U * r::f(&t.abs()).max(0.5 * vtop(&e.omega) * abs_sum(i_ref, &e.omega));
                plain(&mut out, key.clone(), &v[&key], t, &b[&key], f);
            }
            "center_of_mass" | "reference_point" | "center_of_mass_ref" | "angular_momentum"
            | "euler_moment" => {
                let (exact, floor) = match key.as_str() {
                    "center_of_mass" => (body.com.clone(), U * com_scale),
                    "reference_point" => (e.point.clone(), U * vtop(&e.point)),
                    "center_of_mass_ref" => (
                        com_ref.clone(),
                        U * com_scale.max(vtop(&e.point)).max(vtop(com_ref)),
                    ),
                    "angular_momentum" => (h.clone(), U * abs_sum(i_ref, &e.omega)),
                    _ => (
                        m.clone(),
                        U * (abs_sum(i_ref, &e.alpha) + vtop(&e.omega) * abs_sum(i_ref, &e.omega)),
                    ),
                };
                for j in 0..3 {
                    plain(&mut out, at(j), &v[&key][j], &exact[j], &b[&key][j], floor);
                }
            }
            "inertia_com" | "inertia_ref" => {
                let exact = if key == "inertia_com" { i_com } else { i_ref };
                let floor = U * top(exact);
                for j in 0..3 {
                    for k in 0..3 {
                        let what = format!("{key}[{j}][{k}]");
                        plain(
                            &mut out,
                            what,
                            &v[&key][j][k],
                            &exact[j][k],
                            &b[&key][j][k],
                            floor,
                        );
                    }
                }
            }
            "principal_moments" | "principal_moments_ref" => {
                let p = if key == "principal_moments" {
                    pr
                } else {
                    pr_ref
                };
                let largest = r::f(&p.moments[2]);
                for j in 0..3 {
                    let floor = unit * largest + U * r::f(&p.moments[j].abs());
                    plain(
                        &mut out,
                        at(j),
                        &v[&key][j],
                        &p.moments[j],
                        &b[&key][j],
                        floor,
                    );
                }
            }
            "principal_axes" | "principal_axes_ref" => {
                let (p, eq) = if key == "principal_axes" {
                    (pr, "equal_moments")
                } else {
                    (pr_ref, "equal_moments_ref")
                };
                let equal: Vec<u64> = v[eq]
                    .as_array()
                    .map(|l| l.iter().filter_map(Value::as_u64).collect())
                    .unwrap_or_default();
                for j in 0..3 {
                    let Some(axis) = &p.axes[j] else { continue };
                    if equal.contains(&(j as u64)) {
                        continue;
                    }
                    let turned = r::mvec(a, axis);
                    let got: [f64; 3] = std::array::from_fn(|k| num(&v[&key][j][k]));
                    let error = r::axis_sin(&got, &turned).min(1.0).asin();
                    let bound = num(&b[&key][j]);
                    out.push(Item {
                        key: at(j),
                        value: 0.0,
                        error,
                        bound,
                        floor: U / p.gap(j),
                        // asin of a sine computed to 2⁻⁵⁰ or so: an
                        // error within a part in 10¹² of its bound
                        // counts as honest only if below it.
                        honest: error <= bound,
                    });
                }
            }
            "radii_of_gyration" | "radii_of_gyration_axes" | "radii_of_gyration_axes_ref" => {
                for j in 0..3 {
                    let moment = match key.as_str() {
                        "radii_of_gyration" => pr.moments[j].clone(),
                        "radii_of_gyration_axes" => i_com[j][j].clone(),
                        _ => i_ref[j][j].clone(),
                    };
                    let ratio = if moment.is_negative() {
                        Q::zero()
                    } else {
                        moment / &body.mass
                    };
                    let k = num(&v[&key][j]);
                    let bound = num(&b[&key][j]);
                    let (lo, hi) = ((k - bound).max(0.0), k + bound);
                    let honest = r::q(lo) * r::q(lo) <= ratio && ratio <= r::q(hi) * r::q(hi);
                    let exact = r::sqrt(&ratio);
                    // A radius is √(I/m): storing the tensor moves I by
                    // the arithmetic's unit of its largest moment (entry,
                    // for a radius about an axis), as a principal
                    // moment's floor says, and so the radius by
                    // δ/(√(I + δ) + √I)/√m.
                    let largest = match key.as_str() {
                        "radii_of_gyration" => r::f(&pr.moments[2]),
                        "radii_of_gyration_axes" => top(i_com),
                        _ => top(i_ref),
                    };
                    let delta = unit * largest;
                    let lam = r::f(&ratio) * r::f(&body.mass);
                    let moved = delta
                        / (((lam + delta).max(0.0)).sqrt() + lam.max(0.0).sqrt())
                        / r::f(&body.mass).abs().sqrt();
                    out.push(Item {
                        key: at(j),
                        value: k,
                        error: r::f(&(r::q(k) - &exact).abs()),
                        bound,
                        floor: U * r::f(&exact) + moved,
                        honest,
                    });
                }
            }
            other => out.push(Item {
                key: format!("{other} (a bound this test does not know)"),
                value: f64::NAN,
                error: f64::INFINITY,
                bound: 0.0,
                floor: 0.0,
                honest: false,
            }),
        }
    }
    out
}

/// The items over their bounds, as lines.
pub fn dishonest(items: &[Item]) -> Vec<String> {
    items
        .iter()
        .filter(|i| !i.honest)
        .map(|i| {
            format!(
                "{}: {:e} is {:e} off, bound {:e}",
                i.key, i.value, i.error, i.bound
            )
        })
        .collect()
}
