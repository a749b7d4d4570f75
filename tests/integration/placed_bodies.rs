//! Sub-assemblies and copies composed once and placed as bodies (issue 30
//! item 2, issue 33 item 2): random trees of includes — turned by general
//! quaternions, in other units, nested two deep, with arrays and mirrors
//! of parts and of includes — against their exact bodies formed here in
//! rationals, in both arithmetics: every value within its bound, and in
//! `extended` every bound within 1000× of the larger of the actual error
//! and what storing the exact result leaves (docs/accuracy.md); a tree of
//! 2^k instances of d files composes d bodies; a sub-assembly of cut-outs
//! only composes to the exact answer.

use crate::stress::{Rng, every_shape, twelve_boxes};
use crate::support::num_traits::Signed;
use crate::support::reference::{self as r, Amount, ExactPart, Length, Mass, Q};
use serde_json::Value;
use std::path::Path;

const U: f64 = f64::EPSILON / 2.0;
const U_DD: f64 = 7.0 * U * U;
const TIGHT: f64 = 1000.0;

fn num(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

fn list(v: [f64; 3]) -> String {
    format!("[{:?}, {:?}, {:?}]", v[0], v[1], v[2])
}

fn quat(q: [f64; 4]) -> String {
    format!("[{:?}, {:?}, {:?}, {:?}]", q[0], q[1], q[2], q[3])
}

/// A part moved exactly: its centre to o + R (c − q), its second moment
/// R C Rᵀ (R a turn or a reflection), its mass unchanged (SI).
fn moved(p: &ExactPart, o: &r::V3, rot: &r::M3, q: &r::V3) -> ExactPart {
    let d: r::V3 = std::array::from_fn(|i| &p.center[i] - &q[i]);
    let rd = r::mvec(rot, &d);
    ExactPart {
        mass: p.mass.clone(),
        center: std::array::from_fn(|i| &o[i] + &rd[i]),
        second_moment: r::mmul(&r::mmul(rot, &p.second_moment), &r::transpose(rot)),
    }
}

fn identity() -> r::M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| r::int(i64::from(i == j))))
}

/// E − 2 n nᵀ/|n|², exactly.
fn reflection(n: [f64; 3]) -> r::M3 {
    let n = r::qv(n);
    let nn = r::dot(&n, &n);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let e = r::int(i64::from(i == j));
            e - r::int(2) * &n[i] * &n[j] / &nn
        })
    })
}

/// A quarter turn about z, k times.
fn quarter_z(k: usize) -> r::M3 {
    let (c, s) = [(1, 0), (0, 1), (-1, 0), (0, -1)][k % 4];
    [
        [r::int(c), r::int(-s), r::int(0)],
        [r::int(s), r::int(c), r::int(0)],
        [r::int(0), r::int(0), r::int(1)],
    ]
}

/// A point of a file in `length` units, in metres.
fn si_point(p: [f64; 3], length: Length) -> r::V3 {
    r::qv(p).map(|x| x * length.si())
}

/// The exact body: mass, centre, inertia about the centre (SI).
struct Body {
    mass: Q,
    com: r::V3,
    inertia: r::M3,
    /// Σ|mᵢ||cᵢ|/|m|: what the centre's rounding is relative to.
    com_scale: f64,
}

fn body(parts: &[ExactPart]) -> Body {
    let mass: Q = parts.iter().map(|p| p.mass.clone()).sum();
    let com: r::V3 =
        std::array::from_fn(|i| parts.iter().map(|p| &p.mass * &p.center[i]).sum::<Q>() / &mass);
    let c: r::M3 = std::array::from_fn(|j| {
        std::array::from_fn(|k| {
            parts
                .iter()
                .map(|p| {
                    let (dj, dk) = (&p.center[j] - &com[j], &p.center[k] - &com[k]);
                    &p.second_moment[j][k] + &p.mass * dj * dk
                })
                .sum::<Q>()
        })
    });
    let com_scale = parts
        .iter()
        .map(|p| r::f(&p.mass).abs() * r::norm(&p.center))
        .sum::<f64>()
        / r::f(&mass).abs();
    Body {
        mass,
        com,
        inertia: r::inertia_of(&c),
        com_scale,
    }
}

/// A tree of three files written into `dir`: `leaf.toml` (a random scene
/// in mm and g), `mid.toml` (cm and kg: the leaf included twice, one
/// turned, a box arrayed along a step, a turned box mirrored, a box
/// arrayed by quarter turns) and `top.toml` (m and kg: the mid included
/// turned, and again arrayed; the leaf mirrored; a box). The exact parts
/// of the body, SI.
fn tree(rng: &mut Rng, trial: usize, dir: &Path) -> Vec<ExactPart> {
    let scene = if trial.is_multiple_of(2) {
        every_shape(rng)
    } else {
        twelve_boxes(rng)
    };
    let leaf = scene.in_units(Length::Mm, Mass::G);
    std::fs::write(dir.join("leaf.toml"), r::to_toml(&leaf)).unwrap();
    let leaf_parts: Vec<ExactPart> = leaf
        .parts
        .iter()
        .map(|p| r::exact_part(p, Length::Mm, Mass::G))
        .collect();
    let zero: r::V3 = std::array::from_fn(|_| r::int(0));

    // mid.toml, in cm and kg.
    let (q1, o1, o2) = (rng.quaternion(), rng.grid_point(), rng.grid_point());
    let (ca, step) = (rng.grid_point(), [0.5, -0.25, 1.5]);
    let (cb, qb, normal, plane) = (
        rng.grid_point(),
        rng.quaternion(),
        [1.0, 2.0, -2.0],
        [0.25, 0.0, -0.5],
    );
    let (cc, pivot) = (rng.grid_point(), [1.0, -0.5, 0.0]);
    let mid = format!(
        "units = {{ length = \"cm\", mass = \"kg\" }}\n\
         [[part]]\nname = \"a\"\ninclude = \"leaf.toml\"\norigin = {}\nrotation = {{ quaternion = {} }}\n\
         [[part]]\nname = \"b\"\ninclude = \"leaf.toml\"\norigin = {}\n\
         [[part]]\nname = \"row\"\nshape = \"box\"\nmass = 2.5\nsize = [3, 1.5, 0.75]\ncenter = {}\narray = {{ count = 3, step = {} }}\n\
         [[part]]\nname = \"pair\"\nshape = \"box\"\nmass = 1.25\nsize = [2, 1, 0.5]\ncenter = {}\nrotation = {{ quaternion = {} }}\nmirror = {{ normal = {}, origin = {} }}\n\
         [[part]]\nname = \"ring\"\nshape = \"box\"\nmass = 0.75\nsize = [1, 0.5, 0.25]\ncenter = {}\narray = {{ count = 4, axis = [0, 0, 1], step_degrees = 90, origin = {} }}\n",
        list(o1),
        quat(q1),
        list(o2),
        list(ca),
        list(step),
        list(cb),
        quat(qb),
        list(normal),
        list(plane),
        list(cc),
        list(pivot),
    );
    std::fs::write(dir.join("mid.toml"), mid).unwrap();
    let cm = Length::Cm;
    let mut mid_parts = Vec::new();
    let r1 = r::rotation(&q1.map(r::q));
    for p in &leaf_parts {
        mid_parts.push(moved(p, &si_point(o1, cm), &r1, &zero));
    }
    for p in &leaf_parts {
        mid_parts.push(moved(p, &si_point(o2, cm), &identity(), &zero));
    }
    let part = |center: [f64; 3], size: [f64; 3], rot: Option<[f64; 4]>, mass: f64| {
        r::exact_part(
            &r::Part::cuboid(size, center, rot, Amount::Mass(mass)),
            cm,
            Mass::Kg,
        )
    };
    let row = part(ca, [3.0, 1.5, 0.75], None, 2.5);
    for k in 0..3 {
        let shift = si_point(step, cm).map(|x| x * r::int(k));
        mid_parts.push(moved(&row, &shift, &identity(), &zero));
    }
    let pair = part(cb, [2.0, 1.0, 0.5], Some(qb), 1.25);
    let plane_si = si_point(plane, cm);
    mid_parts.push(pair.clone());
    mid_parts.push(moved(&pair, &plane_si, &reflection(normal), &plane_si));
    let ring = part(cc, [1.0, 0.5, 0.25], None, 0.75);
    let pivot_si = si_point(pivot, cm);
    for k in 0..4 {
        mid_parts.push(moved(&ring, &pivot_si, &quarter_z(k), &pivot_si));
    }

    // top.toml, in m and kg.
    let (qt, ot, ot2, st) = (
        rng.quaternion(),
        rng.grid_point(),
        rng.grid_point(),
        [0.125, 2.0, -0.75],
    );
    let (nt, pt) = ([-3.0, 1.0, 0.5], rng.grid_point());
    let top = format!(
        "[[part]]\nname = \"m1\"\ninclude = \"mid.toml\"\norigin = {}\nrotation = {{ quaternion = {} }}\n\
         [[part]]\nname = \"m2\"\ninclude = \"mid.toml\"\norigin = {}\narray = {{ count = 2, step = {} }}\n\
         [[part]]\nname = \"l\"\ninclude = \"leaf.toml\"\nmirror = {{ normal = {}, origin = {} }}\n\
         [[part]]\nname = \"base\"\nshape = \"box\"\nmass = 3\nsize = [0.5, 0.25, 0.125]\ncenter = [0.5, 0.5, -0.25]\n",
        list(ot),
        quat(qt),
        list(ot2),
        list(st),
        list(nt),
        list(pt),
    );
    std::fs::write(dir.join("top.toml"), top).unwrap();
    let m = Length::M;
    let rt = r::rotation(&qt.map(r::q));
    let mut parts = Vec::new();
    for p in &mid_parts {
        parts.push(moved(p, &si_point(ot, m), &rt, &zero));
    }
    for k in 0..2 {
        let o: r::V3 = std::array::from_fn(|i| &si_point(ot2, m)[i] + &(r::q(st[i]) * r::int(k)));
        for p in &mid_parts {
            parts.push(moved(p, &o, &identity(), &zero));
        }
    }
    let pt_si = si_point(pt, m);
    for p in &leaf_parts {
        parts.push(p.clone());
    }
    for p in &leaf_parts {
        parts.push(moved(p, &pt_si, &reflection(nt), &pt_si));
    }
    parts.push(r::exact_part(
        &r::Part::cuboid(
            [0.5, 0.25, 0.125],
            [0.5, 0.5, -0.25],
            None,
            Amount::Mass(3.0),
        ),
        m,
        Mass::Kg,
    ));
    parts
}

/// Honesty (error ≤ bound) of every value, and tightness (bound ≤ 1000 ×
/// max(error, floor)) where a floor is given; failures listed at the end.
#[derive(Default)]
struct Judge {
    failures: Vec<String>,
    checked: usize,
    worst_honest: (f64, String),
    worst_tight: (f64, String),
}

impl Judge {
    fn check(&mut self, what: String, value: f64, exact: &Q, bound: f64, floor: Option<f64>) {
        let err = r::f(&(r::q(value) - exact).abs());
        self.checked += 1;
        if bound > 0.0 && err / bound > self.worst_honest.0 {
            self.worst_honest = (err / bound, what.clone());
        }
        if !(err <= bound) {
            self.failures.push(format!(
                "dishonest {what}: {value:e} is {err:e} off, bound {bound:e}"
            ));
        }
        if let Some(floor) = floor {
            let limit = TIGHT * err.max(floor);
            if bound / limit > self.worst_tight.0 {
                self.worst_tight = (bound / limit, what.clone());
            }
            if !(bound <= limit) {
                self.failures.push(format!(
                    "loose {what}: bound {bound:e} for an error of {err:e} (floor {floor:e})"
                ));
            }
        }
    }

    /// Mass, centre, inertia about the centre and principal moments of
    /// the report `v` against `exact`; tight too in `extended`.
    fn report(&mut self, what: &str, v: &Value, exact: &Body) {
        let b = &v["error_bounds"];
        let tight = v["precision"] == "extended";
        let floor = |x: f64| tight.then_some(x);
        let mass = num(&v["mass"]);
        self.check(
            format!("{what}: mass"),
            mass,
            &exact.mass,
            num(&b["mass"]),
            floor(U * mass.abs()),
        );
        for j in 0..3 {
            self.check(
                format!("{what}: center_of_mass[{j}]"),
                num(&v["center_of_mass"][j]),
                &exact.com[j],
                num(&b["center_of_mass"][j]),
                floor(U * exact.com_scale),
            );
        }
        let top = (0..9)
            .map(|i| num(&v["inertia_com"][i / 3][i % 3]).abs())
            .fold(0.0, f64::max);
        for j in 0..3 {
            for k in 0..3 {
                self.check(
                    format!("{what}: inertia_com[{j}][{k}]"),
                    num(&v["inertia_com"][j][k]),
                    &exact.inertia[j][k],
                    num(&b["inertia_com"][j][k]),
                    floor(U * top),
                );
            }
        }
        let moments = r::principal(&exact.inertia).moments;
        let largest = num(&v["principal_moments"][2]);
        for k in 0..3 {
            let m = num(&v["principal_moments"][k]);
            self.check(
                format!("{what}: principal_moments[{k}]"),
                m,
                &moments[k],
                num(&b["principal_moments"][k]),
                floor(U_DD * largest + U * m),
            );
        }
    }

    fn finish(self) {
        assert!(self.checked > 0);
        eprintln!(
            "{} values; worst error/bound {:.3} ({}); worst bound/limit {:.3} ({})",
            self.checked,
            self.worst_honest.0,
            self.worst_honest.1,
            self.worst_tight.0,
            self.worst_tight.1
        );
        assert!(
            self.failures.is_empty(),
            "{} of {} checks failed:\n  {}",
            self.failures.len(),
            self.checked,
            self.failures.join("\n  ")
        );
    }
}

#[test]
fn trees_of_turned_scaled_and_copied_sub_assemblies_are_within_tight_bounds_in_both_precisions() {
    let mut rng = Rng::new(3033);
    let mut judge = Judge::default();
    for trial in 0..6 {
        let dir = crate::common::scratch("placed_bodies", &format!("tree-{trial}"));
        let exact = body(&tree(&mut rng, trial, &dir));
        for p in ["standard", "extended"] {
            let (v, _) =
                crate::common::report_json_file(&dir.join("top.toml"), &["--precision", p]);
            judge.report(&format!("tree {trial}, {p}"), &v, &exact);
        }
    }
    judge.finish();
}

/// A binary tree of `levels` files, each including the next twice (the
/// last a point), as benches/cost.sh writes it: 2^(levels − 1) instances.
fn binary_tree(name: &str, levels: usize) -> std::path::PathBuf {
    let dir = crate::common::scratch("placed_bodies", name);
    for l in 0..levels {
        let body = if l == levels - 1 {
            "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n".to_string()
        } else {
            (0..2)
                .map(|k| {
                    format!(
                        "[[part]]\ninclude = \"t{}.toml\"\norigin = [{k}, {l}, 0]\n",
                        l + 1
                    )
                })
                .collect()
        };
        std::fs::write(dir.join(format!("t{l}.toml")), body).unwrap();
    }
    dir.join("t0.toml")
}

#[test]
fn a_tree_of_two_to_the_k_instances_of_d_files_composes_d_bodies() {
    use massprop::compose::{bodies_composed, compose_model};
    for (levels, name) in [(5, "tree-16"), (13, "tree-4096")] {
        let path = binary_tree(name, levels);
        let source = massprop::read_source(path.to_str().unwrap()).unwrap();
        let model = massprop::model::Model::parse(&source).unwrap();
        assert_eq!(model.count, 1 << (levels - 1));
        for precision in [massprop::Precision::Standard, massprop::Precision::Extended] {
            let before = bodies_composed();
            let (body, _) = compose_model(&model, precision);
            // The file itself, and each of the levels − 1 files it
            // includes once.
            assert_eq!(
                bodies_composed() - before,
                levels as u64 - 1,
                "{name}, {precision:?}"
            );
            assert_eq!(
                massprop::numeric::Real::f64(body.mass),
                (1u64 << (levels - 1)) as f64
            );
        }
    }
}

#[test]
fn a_sub_assembly_of_cut_outs_only_included_and_placed_composes_to_the_exact_answer() {
    let dir = crate::common::scratch("placed_bodies", "cut-outs");
    // Two pockets (negative mass), and a pocket with its own plug (mass
    // zero): sub-assemblies whose mass no one may divide by.
    let pockets = "units = { length = \"mm\", mass = \"g\" }\n\
        [[part]]\nshape = \"box\"\nmass = 30\nsize = [20, 10, 5]\ncenter = [15, 5, 2.5]\nremove = true\n\
        [[part]]\nshape = \"cylinder\"\nmass = 12.5\nradius = 4\nlength = 6\ncenter = [-10, 2, 1]\nremove = true\n";
    let plugged = "[[part]]\nshape = \"box\"\nmass = 0.25\nsize = [0.1, 0.1, 0.1]\ncenter = [0.3, 0.1, 0]\n\
        [[part]]\nshape = \"box\"\nmass = 0.25\nsize = [0.1, 0.1, 0.1]\ncenter = [0.3, 0.1, 0]\nremove = true\n";
    std::fs::write(dir.join("pockets.toml"), pockets).unwrap();
    std::fs::write(dir.join("plugged.toml"), plugged).unwrap();
    let q = [0.5, -0.5, 0.5, 0.5];
    let top = format!(
        "[[part]]\nname = \"block\"\nshape = \"box\"\nmass = 8\nsize = [0.4, 0.3, 0.2]\ncenter = [0, 0, 0]\n\
         [[part]]\nname = \"p\"\ninclude = \"pockets.toml\"\norigin = [0.05, -0.025, 0.0125]\nrotation = {{ quaternion = {} }}\n\
         [[part]]\nname = \"z\"\ninclude = \"plugged.toml\"\norigin = [-0.5, 0.25, 0]\nrotation = {{ quaternion = [0.6, 0.8, 0, 0] }}\n",
        quat(q)
    );
    std::fs::write(dir.join("top.toml"), &top).unwrap();
    let rot = r::rotation(&q.map(r::q));
    let zero: r::V3 = std::array::from_fn(|_| r::int(0));
    let o = r::qv([0.05, -0.025, 0.0125]);
    let mut parts = vec![r::exact_part(
        &r::Part::cuboid([0.4, 0.3, 0.2], [0.0; 3], None, Amount::Mass(8.0)),
        Length::M,
        Mass::Kg,
    )];
    let cut = |p: r::Part| {
        let mut e = r::exact_part(&p, Length::Mm, Mass::G);
        e.mass = -e.mass;
        e.second_moment = e.second_moment.map(|row| row.map(|x| -x));
        e
    };
    for p in [
        cut(r::Part::cuboid(
            [20.0, 10.0, 5.0],
            [15.0, 5.0, 2.5],
            None,
            Amount::Mass(30.0),
        )),
        cut(r::Part::cylinder(
            4.0,
            None,
            6.0,
            [-10.0, 2.0, 1.0],
            None,
            Amount::Mass(12.5),
        )),
    ] {
        parts.push(moved(&p, &o, &rot, &zero));
    }
    // The plugged pocket adds nothing at all.
    let exact = body(&parts);
    let mut judge = Judge::default();
    for p in ["standard", "extended"] {
        let (v, _) = crate::common::report_json_file(&dir.join("top.toml"), &["--precision", p]);
        judge.report(&format!("cut-outs, {p}"), &v, &exact);
        // And the answer itself, to the last few units.
        let mass = num(&v["mass"]);
        assert!(
            r::f(&(r::q(mass) - &exact.mass).abs()) <= 4.0 * U * mass,
            "{p}: {mass}"
        );
        for j in 0..3 {
            for k in 0..3 {
                let x = num(&v["inertia_com"][j][k]);
                let err = r::f(&(r::q(x) - &exact.inertia[j][k]).abs());
                assert!(
                    err <= 1e-15 * r::f(&exact.inertia[0][0]).abs().max(1e-300),
                    "{p}: [{j}][{k}] {err:e}"
                );
            }
        }
    }
    judge.finish();
}
