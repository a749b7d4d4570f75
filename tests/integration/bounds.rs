//! The error bounds of the quantities the stress tests do not compare
//! (those check mass, centre of mass, the tensor about the centre of mass,
//! its principal moments and axes: `stress::check_claimed_bounds`): the
//! tensor and principal moments about a reference point, the radii of
//! gyration, H, T and M, against the exact reference, in both arithmetics.
//! Each actual error must be within its claimed bound.

use crate::stress::{Rng, every_shape, twelve_boxes};
use massprop_support::num_traits::Signed;
use massprop_support::reference::{self as r, Q, Scene};
use serde_json::Value;

fn run(scene: &Scene, args: &[&str]) -> Value {
    crate::common::report_json(&r::to_toml(scene), args).0
}

fn num(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

/// Records `|value − exact| ≤ bound` for each value; `finish` fails on any
/// violation, listing them.
#[derive(Default)]
struct Honest {
    failures: Vec<String>,
    checked: usize,
    /// The largest error/bound, and where.
    worst: (f64, String),
}

impl Honest {
    fn check(&mut self, what: String, value: &Value, exact: &Q, bound: &Value) {
        let (v, b) = (num(value), num(bound));
        let err = r::f(&(r::q(v) - exact).abs());
        self.checked += 1;
        if b > 0.0 && err / b > self.worst.0 {
            self.worst = (err / b, what.clone());
        }
        if !(err <= b) {
            self.failures
                .push(format!("{what}: {v:e} is {err:e} off, bound {b:e}"));
        }
    }

    fn finish(self) {
        assert!(self.checked > 0);
        eprintln!("worst error/bound {:.3} ({})", self.worst.0, self.worst.1);
        assert!(
            self.failures.is_empty(),
            "{} of {} bounds are not honest:\n  {}",
            self.failures.len(),
            self.checked,
            self.failures.join("\n  ")
        );
    }
}

#[test]
fn bounds_about_a_point_and_of_the_dynamics_are_honest() {
    let mut rng = Rng::new(31);
    let mut honest = Honest::default();
    for trial in 0..4 {
        for (kind, mut scene) in [
            ("boxes", twelve_boxes(&mut rng)),
            ("every shape", every_shape(&mut rng)),
        ] {
            let about = rng.grid_point().map(|x| 3.0 * x);
            scene.about = Some(about);
            let w: [f64; 3] = std::array::from_fn(|_| rng.range(-50.0, 50.0));
            let a: [f64; 3] = std::array::from_fn(|_| rng.range(-5.0, 5.0));
            let omega = format!("{},{},{}", w[0], w[1], w[2]);
            let alpha = format!("{},{},{}", a[0], a[1], a[2]);
            let exact = r::compose(&scene);
            let point: r::V3 = about.map(r::q);
            let i_ref = exact.inertia_about(&point);
            let moments_ref = r::principal(&i_ref).moments;
            let (wq, aq) = (w.map(r::q), a.map(r::q));
            let times = |m: &r::M3, v: &r::V3| -> r::V3 {
                std::array::from_fn(|j| (0..3).map(|k| &m[j][k] * &v[k]).sum())
            };
            let h = times(&i_ref, &wq);
            let t = r::dot(&wq, &h) / r::int(2);
            let ia = times(&i_ref, &aq);
            let wxh = r::cross(&wq, &h);
            let m: r::V3 = std::array::from_fn(|j| &ia[j] + &wxh[j]);
            let moments = exact.principal().moments;
            for p in ["standard", "extended"] {
                let v = run(
                    &scene,
                    &["--precision", p, "--omega", &omega, "--alpha", &alpha],
                );
                let b = &v["error_bounds"];
                let what = |q: &str| format!("{kind}, trial {trial}, {p}: {q}");
                for j in 0..3 {
                    for k in 0..3 {
                        honest.check(
                            what(&format!("inertia_ref[{j}][{k}]")),
                            &v["inertia_ref"][j][k],
                            &i_ref[j][k],
                            &b["inertia_ref"][j][k],
                        );
                    }
                    honest.check(
                        what(&format!("principal_moments_ref[{j}]")),
                        &v["principal_moments_ref"][j],
                        &moments_ref[j],
                        &b["principal_moments_ref"][j],
                    );
                    honest.check(
                        what(&format!("angular_momentum[{j}]")),
                        &v["angular_momentum"][j],
                        &h[j],
                        &b["angular_momentum"][j],
                    );
                    honest.check(
                        what(&format!("euler_moment[{j}]")),
                        &v["euler_moment"][j],
                        &m[j],
                        &b["euler_moment"][j],
                    );
                    // k = √(I/m) is irrational: (k ∓ b)² brackets I/m.
                    let (k, kb) = (
                        num(&v["radii_of_gyration"][j]),
                        num(&b["radii_of_gyration"][j]),
                    );
                    let ratio = &moments[j] / &exact.mass;
                    let (lo, hi) = ((k - kb).max(0.0), k + kb);
                    let inside = r::q(lo) * r::q(lo) <= ratio && ratio <= r::q(hi) * r::q(hi);
                    honest.checked += 1;
                    if !inside {
                        honest.failures.push(format!(
                            "{}: {k:e} ± {kb:e} does not hold √(I/m) = {:e}",
                            what(&format!("radii_of_gyration[{j}]")),
                            r::f(&ratio).sqrt()
                        ));
                    }
                }
                honest.check(
                    what("kinetic_energy"),
                    &v["kinetic_energy"],
                    &t,
                    &b["kinetic_energy"],
                );
            }
        }
    }
    honest.finish();
}
