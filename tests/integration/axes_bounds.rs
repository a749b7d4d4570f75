//! Report axes given as two directions are bounded honestly in both
//! precisions (issue 30, item 1: entries turned by axes rounded to f64
//! first carried f64-level error under a double-double bound, up to 154×
//! over it). The directions here have rational lengths (Pythagorean
//! quadruples), so the exact turn A C Aᵀ is rational: every entry of the
//! JSON is compared with it, exactly, against its `error_bounds` entry.

use crate::common::report_json;
use crate::support::reference::{self as r, Amount, Part, Q, Scene, f, q, qv};
use num_traits::{Signed, Zero};
use serde_json::Value;

/// Three boxes off the origin with every product of inertia non-zero
/// (one turned by a quaternion), and a reference point.
fn scene() -> Scene {
    let mut scene = Scene::si(vec![
        Part::cuboid(
            [1.0, 0.5, 0.25],
            [0.5, -0.25, 0.125],
            None,
            Amount::Mass(2.0),
        ),
        Part::cuboid([0.75, 1.5, 0.5], [-1.0, 0.5, 0.75], None, Amount::Mass(3.0)),
        Part::cuboid(
            [0.25, 0.375, 2.0],
            [0.25, 1.25, -0.5],
            Some([0.5, 0.5, 0.5, 0.5]),
            Amount::Mass(1.5),
        ),
    ]);
    scene.about = Some([0.25, -0.5, 1.0]);
    scene
}

/// v / n, exactly.
fn unit(v: [f64; 3], n: f64) -> [Q; 3] {
    qv(v).map(|c| c / q(n))
}

/// The rows of A: x/|x|, y/|y|, and their cross product.
fn rows(x: [f64; 3], nx: f64, y: [f64; 3], ny: f64) -> [[Q; 3]; 3] {
    let (a, b) = (unit(x, nx), unit(y, ny));
    let c = [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ];
    [a, b, c]
}

/// A M Aᵀ, exactly.
fn turned(a: &[[Q; 3]; 3], m: &[[Q; 3]; 3]) -> [[Q; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|l| {
            let mut s = Q::zero();
            for j in 0..3 {
                for k in 0..3 {
                    s += &a[i][j] * &m[j][k] * &a[l][k];
                }
            }
            s
        })
    })
}

fn num(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

/// |got − want| ≤ bound, exactly.
fn within(what: &str, got: f64, want: &Q, bound: f64) {
    let err = (q(got) - want).abs();
    assert!(
        err <= q(bound),
        "{what}: {got:e} is {:e} from the exact {:e}, bound {bound:e} ({:.1}× over)",
        f(&err),
        f(want),
        f(&err) / bound
    );
}

#[test]
fn tensors_and_offsets_in_axes_given_as_directions_are_within_their_bounds_in_both_precisions() {
    // (x, |x|, y, |y|), x · y = 0.
    let axes = [
        ([1.0, 2.0, 2.0], 3.0, [2.0, 1.0, -2.0], 3.0),
        ([-3.0, -4.0, -12.0], 13.0, [4.0, -3.0, 0.0], 5.0),
        ([2.0, 3.0, 6.0], 7.0, [6.0, 2.0, -3.0], 7.0),
        ([-3.0, -4.0, -12.0], 13.0, [12.0, -9.0, 0.0], 15.0),
    ];
    let scene = scene();
    let exact = r::compose(&scene);
    let about = qv(scene.about.expect("a reference point"));
    for (x, nx, y, ny) in axes {
        let a = rows(x, nx, y, ny);
        let want_com = turned(&a, &exact.inertia);
        let want_ref = turned(&a, &exact.inertia_about(&about));
        let offset: [Q; 3] = std::array::from_fn(|j| &exact.com[j] - &about[j]);
        let want_offset: [Q; 3] =
            std::array::from_fn(|i| (0..3).fold(Q::zero(), |s, j| s + &a[i][j] * &offset[j]));
        let mut text = r::to_toml(&scene);
        if scene.about.is_none() {
            text.push_str("\n[analysis]\n");
        }
        text.push_str(&format!("axes = {{ x = {x:?}, y = {y:?} }}\n"));
        for precision in ["standard", "extended"] {
            let (json, _) = report_json(&text, &["--precision", precision]);
            let b = &json["error_bounds"];
            let what = |k: &str| format!("{k} in axes x = {x:?}, y = {y:?}, {precision}");
            for i in 0..3 {
                within(
                    &what("center_of_mass_ref"),
                    num(&json["center_of_mass_ref"][i]),
                    &want_offset[i],
                    num(&b["center_of_mass_ref"][i]),
                );
                for j in 0..3 {
                    for (key, want) in [("inertia_com", &want_com), ("inertia_ref", &want_ref)] {
                        within(
                            &what(key),
                            num(&json[key][i][j]),
                            &want[i][j],
                            num(&b[key][i][j]),
                        );
                    }
                }
            }
        }
    }
}
