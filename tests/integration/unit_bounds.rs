//! Quantities written in another unit than the file's, and a material's
//! density turned into a mass by a `thickness`, `area` or `diameter`
//! (issue 30 item 1): every value of the JSON within its `error_bounds`
//! entry of the exact one, in both arithmetics.
//!
//! "Exact" is what docs/accuracy.md defines: the result for the f64 values
//! the file's numbers read as, a number with its own unit converted to the
//! file's units by the nearest f64 (here num-rational's correctly rounded
//! conversion of the exact rational product; for the angle units with π,
//! the reference's 100-digit π), a built-in material's density (kg/m³)
//! likewise; a material's density times a thickness, an area or π/4 d² is
//! *not* rounded: the exact product, which massprop forms in f64 and must
//! count.
//!
//! Generated scenes (proptest, deterministic ChaCha seed): every file
//! length and mass unit, each number of a size, a centre, `about`, `omega`,
//! a density, a mass, a thickness, an area or a diameter written in the
//! file's units or in another (every length and mass symbol, densities per
//! volume, area and length in mixed units, angular velocities in rad/s,
//! rpm, deg/s, Hz and rev/s), built-in materials in any units.

use crate::stress::Rng;
use crate::support::num_traits::{Signed, Zero};
use crate::support::reference::{self as r, Amount, ExactPart, Length, M3, Mass, Part, Q, V3};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use serde_json::Value;
use std::cell::RefCell;

const LENGTHS: [Length; 7] = [
    Length::M,
    Length::Cm,
    Length::Mm,
    Length::Um,
    Length::Km,
    Length::In,
    Length::Ft,
];
const MASSES: [Mass; 5] = [Mass::Kg, Mass::G, Mass::Mg, Mass::T, Mass::Lb];

/// Every length symbol a quantity string may use, with metres per unit.
fn length_symbols() -> Vec<(&'static str, Q)> {
    let mut v: Vec<_> = LENGTHS.iter().map(|l| (l.symbol(), l.si())).collect();
    v.push(("\u{b5}m", Length::Um.si()));
    v.push(("\u{3bc}m", Length::Um.si()));
    v
}

/// Every mass symbol a quantity string may use, with kilograms per unit.
fn mass_symbols() -> Vec<(&'static str, Q)> {
    let mut v: Vec<_> = MASSES.iter().map(|m| (m.symbol(), m.si())).collect();
    v.push(("oz", Mass::Lb.si() / r::int(16)));
    v
}

/// x^k, k of either sign.
fn pow(x: &Q, k: i32) -> Q {
    let p = (0..k.abs()).fold(r::int(1), |a, _| a * x);
    if k < 0 { r::int(1) / p } else { p }
}

/// Writes a scene's numbers, each in the file's units or in another, and
/// keeps the f64 each must read as.
struct Writer<'a> {
    rng: &'a mut Rng,
    /// Metres and kilograms per file unit.
    l: Q,
    m: Q,
}

impl Writer<'_> {
    fn pick<T: Clone>(&mut self, v: &[T]) -> T {
        v[(self.rng.next_u64() % v.len() as u64) as usize].clone()
    }

    fn coin(&mut self) -> bool {
        self.rng.next_u64().is_multiple_of(2)
    }

    /// `x` of dimension mass^a length^b: as a plain number in file units,
    /// or as `x` of a random unit, the text and the file-unit f64 (the
    /// correctly rounded exact conversion).
    fn quantity(&mut self, x: f64, a: i32, b: i32) -> (String, f64) {
        if self.coin() {
            return (r::number(x), x);
        }
        let (ms, mq) = self.pick(&mass_symbols());
        let (ls, lq) = self.pick(&length_symbols());
        let (text, si) = match (a, b) {
            (0, 1) => (ls.to_string(), lq),
            (0, 2) => (format!("{ls}^2"), pow(&lq, 2)),
            (1, 0) => (ms.to_string(), mq),
            // A volume in litres or millilitres now and then.
            (1, -3) if self.rng.next_u64().is_multiple_of(3) => {
                let (vs, vq) = self.pick(&[("L", r::frac(1, 1000)), ("mL", r::frac(1, 1_000_000))]);
                (format!("{ms}/{vs}"), mq / vq)
            }
            (1, k) => (format!("{ms}/{ls}^{}", -k), mq / pow(&lq, -k)),
            _ => unreachable!("the test writes lengths, areas, masses and densities"),
        };
        // The file's unit of the same dimension: kg^a m^b of it.
        let file = if a == 1 { self.m.clone() } else { r::int(1) } * pow(&self.l, b);
        let value = r::f(&(r::q(x) * si / file));
        (format!("\"{} {text}\"", r::number(x)), value)
    }

    fn length(&mut self, x: f64) -> (String, f64) {
        self.quantity(x, 0, 1)
    }

    /// `quantity` of a number drawn from [lo, hi).
    fn quantity_in(&mut self, lo: f64, hi: f64, a: i32, b: i32) -> (String, f64) {
        let x = self.rng.range(lo, hi);
        self.quantity(x, a, b)
    }

    fn length_in(&mut self, lo: f64, hi: f64) -> (String, f64) {
        self.quantity_in(lo, hi, 0, 1)
    }

    fn omega_in(&mut self, lo: f64, hi: f64) -> (String, Q) {
        let x = self.rng.range(lo, hi);
        self.omega(x)
    }

    /// Three lengths: the TOML array and the values.
    fn point(&mut self, p: [f64; 3]) -> (String, [f64; 3]) {
        let w: Vec<(String, f64)> = p.iter().map(|x| self.length(*x)).collect();
        (
            format!("[{}, {}, {}]", w[0].0, w[1].0, w[2].0),
            [w[0].1, w[1].1, w[2].1],
        )
    }

    /// An angular velocity component: its text and its exact value, rad/s.
    fn omega(&mut self, x: f64) -> (String, Q) {
        let pi = r::pi();
        let (unit, factor) = self.pick(&[
            ("", r::int(1)),
            ("rad/s", r::int(1)),
            ("rpm", &pi / r::int(30)),
            ("deg/s", &pi / r::int(180)),
            ("Hz", &pi * r::int(2)),
            ("rev/s", &pi * r::int(2)),
        ]);
        let value = r::q(r::f(&(r::q(x) * factor)));
        match unit {
            "" => (r::number(x), value),
            u => (format!("\"{} {u}\"", r::number(x)), value),
        }
    }
}

/// A generated part: its TOML, its shape at unit density (file units), and
/// the exact factor its density contributes (file units).
struct Generated {
    toml: String,
    part: Part,
    density: Q,
}

/// One part of a random shape, its numbers in random units, its mass by a
/// density, a mass or a material (times a thickness, area or diameter).
fn part(w: &mut Writer) -> Generated {
    let (centre_text, centre) = {
        let p = [(); 3].map(|_| w.rng.range(-5.0, 5.0));
        w.point(p)
    };
    let mut toml = format!("\n[[part]]\ncenter = {centre_text}\n");
    // The material's density in file units, as massprop converts it.
    let material = |w: &mut Writer, toml: &mut String| -> Q {
        let m = w.pick(massprop::materials::BUILT_IN);
        toml.push_str(&format!("material = \"{}\"\n", m.name));
        r::q(r::f(&(r::q(m.density) * pow(&w.l, 3) / &w.m)))
    };
    let shape = w.rng.next_u64() % 5;
    let (part, density) = match shape {
        // Volumes: box, cylinder, sphere; a density, a mass or a material.
        0..=2 => {
            let part = match shape {
                0 => {
                    let t: Vec<(String, f64)> = (0..3).map(|_| w.length_in(0.2, 3.0)).collect();
                    toml.push_str(&format!(
                        "shape = \"box\"\nsize = [{}, {}, {}]\n",
                        t[0].0, t[1].0, t[2].0
                    ));
                    let v = [t[0].1, t[1].1, t[2].1];
                    Part::cuboid(v, centre, None, Amount::Density(1.0))
                }
                1 => {
                    let (rt, rv) = w.length_in(0.2, 3.0);
                    let (lt, lv) = w.length_in(0.2, 3.0);
                    toml.push_str(&format!(
                        "shape = \"cylinder\"\nradius = {rt}\nlength = {lt}\n"
                    ));
                    Part::cylinder(rv, None, lv, centre, None, Amount::Density(1.0))
                }
                _ => {
                    let (rt, rv) = w.length_in(0.2, 3.0);
                    toml.push_str(&format!("shape = \"sphere\"\nradius = {rt}\n"));
                    Part::sphere(rv, None, centre, None, Amount::Density(1.0))
                }
            };
            match w.rng.next_u64() % 3 {
                0 => {
                    let (t, v) = w.quantity_in(0.5, 9.0, 1, -3);
                    toml.push_str(&format!("density = {t}\n"));
                    (part, r::q(v))
                }
                1 => {
                    let (t, v) = w.quantity_in(0.5, 9.0, 1, 0);
                    toml.push_str(&format!("mass = {t}\n"));
                    let mut given = part;
                    given.amount = Amount::Mass(v);
                    (given, r::int(1))
                }
                _ => {
                    let d = material(w, &mut toml);
                    (part, d)
                }
            }
        }
        // A plate or a disk: an areal density, or a material times a
        // thickness.
        3 => {
            let part = if w.coin() {
                let (a, b) = (w.length_in(0.2, 3.0), w.length_in(0.2, 3.0));
                toml.push_str(&format!("shape = \"plate\"\nsize = [{}, {}]\n", a.0, b.0));
                Part::plate([a.1, b.1], centre, None, Amount::Density(1.0))
            } else {
                let (rt, rv) = w.length_in(0.2, 3.0);
                toml.push_str(&format!("shape = \"disk\"\nradius = {rt}\n"));
                Part::disk(rv, None, centre, None, Amount::Density(1.0))
            };
            if w.coin() {
                let (t, v) = w.quantity_in(0.5, 9.0, 1, -2);
                toml.push_str(&format!("areal_density = {t}\n"));
                (part, r::q(v))
            } else {
                let d = material(w, &mut toml);
                let (t, v) = w.length_in(0.001, 0.1);
                toml.push_str(&format!("thickness = {t}\n"));
                (part, d * r::q(v))
            }
        }
        // A rod: a linear density, or a material times an area or the
        // area of a diameter.
        _ => {
            let (lt, lv) = w.length_in(0.2, 3.0);
            toml.push_str(&format!("shape = \"rod\"\nlength = {lt}\n"));
            let part = Part::rod(lv, centre, None, Amount::Density(1.0));
            match w.rng.next_u64() % 3 {
                0 => {
                    let (t, v) = w.quantity_in(0.5, 9.0, 1, -1);
                    toml.push_str(&format!("linear_density = {t}\n"));
                    (part, r::q(v))
                }
                1 => {
                    let d = material(w, &mut toml);
                    let (t, v) = w.quantity_in(1e-4, 1e-2, 0, 2);
                    toml.push_str(&format!("area = {t}\n"));
                    (part, d * r::q(v))
                }
                _ => {
                    let d = material(w, &mut toml);
                    let (t, v) = w.length_in(0.01, 0.2);
                    toml.push_str(&format!("diameter = {t}\n"));
                    let v = r::q(v);
                    (part, d * r::pi() * &v * &v / r::int(4))
                }
            }
        }
    };
    Generated {
        toml,
        part,
        density,
    }
}

/// A generated file and what the reference needs of it.
struct Case {
    toml: String,
    length: Length,
    mass: Mass,
    parts: Vec<Generated>,
    /// File units.
    about: Option<[f64; 3]>,
    omega: [Q; 3],
}

fn case(length: Length, mass: Mass, seed: u64) -> Case {
    let mut rng = Rng::new(seed);
    let mut w = Writer {
        rng: &mut rng,
        l: length.si(),
        m: mass.si(),
    };
    let n = 2 + w.rng.next_u64() % 3;
    let parts: Vec<Generated> = (0..n).map(|_| part(&mut w)).collect();
    let mut toml = format!(
        "units = {{ length = \"{}\", mass = \"{}\" }}\n\n[analysis]\n",
        length.symbol(),
        mass.symbol()
    );
    let about = w.coin().then(|| {
        let p = [(); 3].map(|_| w.rng.range(-8.0, 8.0));
        let (t, v) = w.point(p);
        toml.push_str(&format!("about = {t}\n"));
        v
    });
    let omega: Vec<(String, Q)> = (0..3).map(|_| w.omega_in(-20.0, 20.0)).collect();
    toml.push_str(&format!(
        "omega = [{}, {}, {}]\n",
        omega[0].0, omega[1].0, omega[2].0
    ));
    for p in &parts {
        toml.push_str(&p.toml);
    }
    Case {
        toml,
        length,
        mass,
        parts,
        about,
        omega: [0, 1, 2].map(|j| omega[j].1.clone()),
    }
}

/// The exact values of a case, SI.
struct Exact {
    mass: Q,
    com: V3,
    inertia: M3,
    point: V3,
    inertia_ref: M3,
    omega: [Q; 3],
}

fn exact(c: &Case) -> Exact {
    let parts: Vec<ExactPart> = c
        .parts
        .iter()
        .map(|g| {
            let p = r::exact_part(&g.part, c.length, c.mass);
            ExactPart {
                mass: &p.mass * &g.density,
                center: p.center,
                second_moment: p.second_moment.map(|row| row.map(|x| x * &g.density)),
            }
        })
        .collect();
    let mass: Q = parts.iter().map(|p| p.mass.clone()).sum();
    let com: V3 =
        [0, 1, 2].map(|j| parts.iter().map(|p| &p.mass * &p.center[j]).sum::<Q>() / &mass);
    let about = |point: &V3| -> M3 {
        let c: M3 = [0, 1, 2].map(|j| {
            [0, 1, 2].map(|k| {
                parts
                    .iter()
                    .map(|p| {
                        let (dj, dk) = (&p.center[j] - &point[j], &p.center[k] - &point[k]);
                        &p.second_moment[j][k] + &p.mass * dj * dk
                    })
                    .sum::<Q>()
            })
        });
        r::inertia_of(&c)
    };
    let point = match c.about {
        Some(a) => a.map(|x| r::q(x) * c.length.si()),
        None => com.clone(),
    };
    Exact {
        inertia: about(&com),
        inertia_ref: about(&point),
        mass,
        com,
        point,
        omega: c.omega.clone(),
    }
}

/// Each value of `v` against its exact value and its bound.
fn honest(v: &Value, e: &Exact) -> Vec<String> {
    let b = &v["error_bounds"];
    let mut failures = vec![];
    let mut check = |what: String, value: &Value, exact: &Q, bound: &Value| {
        let (x, bound) = (value.as_f64().unwrap(), bound.as_f64().unwrap());
        let err = r::f(&(r::q(x) - exact).abs());
        if !(err <= bound) {
            failures.push(format!("{what}: {x:e} is {err:e} off, bound {bound:e}"));
        }
    };
    check("mass".into(), &v["mass"], &e.mass, &b["mass"]);
    let moments = r::principal(&e.inertia).moments;
    let moments_ref = r::principal(&e.inertia_ref).moments;
    let h: V3 = [0, 1, 2].map(|j| {
        (0..3)
            .map(|k| &e.inertia_ref[j][k] * &e.omega[k])
            .sum::<Q>()
    });
    let t = (0..3).map(|j| &h[j] * &e.omega[j]).sum::<Q>() / r::int(2);
    for j in 0..3 {
        let at = |key: &str| format!("{key}[{j}]");
        check(
            at("center_of_mass"),
            &v["center_of_mass"][j],
            &e.com[j],
            &b["center_of_mass"][j],
        );
        check(
            at("reference_point"),
            &v["reference_point"][j],
            &e.point[j],
            &b["reference_point"][j],
        );
        check(
            at("center_of_mass_ref"),
            &v["center_of_mass_ref"][j],
            &(&e.com[j] - &e.point[j]),
            &b["center_of_mass_ref"][j],
        );
        check(
            at("principal_moments"),
            &v["principal_moments"][j],
            &moments[j],
            &b["principal_moments"][j],
        );
        check(
            at("principal_moments_ref"),
            &v["principal_moments_ref"][j],
            &moments_ref[j],
            &b["principal_moments_ref"][j],
        );
        check(at("omega"), &v["omega"][j], &e.omega[j], &Value::from(0.0));
        check(
            at("angular_momentum"),
            &v["angular_momentum"][j],
            &h[j],
            &b["angular_momentum"][j],
        );
        for k in 0..3 {
            for (key, m) in [("inertia_com", &e.inertia), ("inertia_ref", &e.inertia_ref)] {
                check(
                    format!("{key}[{j}][{k}]"),
                    &v[key][j][k],
                    &m[j][k],
                    &b[key][j][k],
                );
            }
        }
    }
    check(
        "kinetic_energy".into(),
        &v["kinetic_energy"],
        &t,
        &b["kinetic_energy"],
    );
    failures
}

/// Runs `CASES` generated files in both arithmetics.
fn property(cases: u32, filter: impl Fn(&Case) -> bool) -> usize {
    let mut config = Config::with_cases(cases);
    config.failure_persistence = None;
    config.rng_algorithm = RngAlgorithm::ChaCha;
    let mut runner = TestRunner::new_with_rng(
        config.clone(),
        TestRng::deterministic_rng(config.rng_algorithm),
    );
    let checked = RefCell::new(0usize);
    let strategy = (0..LENGTHS.len(), 0..MASSES.len(), any::<u64>());
    let result = runner.run(&strategy, |(l, m, seed)| {
        let c = case(LENGTHS[l], MASSES[m], seed);
        if !filter(&c) {
            return Ok(());
        }
        let e = exact(&c);
        for p in ["standard", "extended"] {
            let (v, _) = crate::common::report_json(&c.toml, &["--precision", p]);
            let failures = honest(&v, &e);
            *checked.borrow_mut() += 1;
            if !failures.is_empty() {
                return Err(TestCaseError::fail(format!(
                    "{p}:\n  {}\nfor:\n{}",
                    failures.join("\n  "),
                    c.toml
                )));
            }
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    checked.into_inner()
}

#[test]
fn every_value_of_a_file_in_any_units_with_quantities_in_others_is_within_its_bound() {
    assert!(property(48, |_| true) >= 96);
}

/// Every file unit of each kind, crossed: 7 × 5 pairs, one scene each.
#[test]
fn every_pair_of_file_units_is_honest() {
    for (i, &l) in LENGTHS.iter().enumerate() {
        for (j, &m) in MASSES.iter().enumerate() {
            check_case(&case(l, m, 1000 + (7 * j + i) as u64));
        }
    }
}

/// `c` in both arithmetics: every value within its bound.
fn check_case(c: &Case) {
    let e = exact(c);
    for p in ["standard", "extended"] {
        let (v, _) = crate::common::report_json(&c.toml, &["--precision", p]);
        let failures = honest(&v, &e);
        assert!(
            failures.is_empty(),
            "{p}:\n  {}\nfor:\n{}",
            failures.join("\n  "),
            c.toml
        );
    }
}

/// The nearest f64 to x·num/den (num-rational's correctly rounded
/// conversion).
fn nearest(x: f64, num: i64, den: i64) -> f64 {
    r::f(&(r::q(x) * r::frac(num, den)))
}

fn alone(part: Part, density: Q) -> Generated {
    Generated {
        toml: String::new(),
        part,
        density,
    }
}

/// The first case: a reference point in inches in a millimetre
/// file (its bound failed in both arithmetics).
#[test]
fn a_reference_point_in_inches_in_a_millimetre_file_is_within_its_bound() {
    let toml = "units = { length = \"mm\", mass = \"g\" }\n[analysis]\n\
                about = [\"10.1 in\", 0, \"-7.3 in\"]\nomega = [0, 0, 1]\n\
                [[part]]\nshape = \"box\"\nsize = [1, 2, 3]\ncenter = [0.3, 0.7, 0]\nmass = 5\n";
    check_case(&Case {
        toml: toml.to_string(),
        length: Length::Mm,
        mass: Mass::G,
        parts: vec![alone(
            Part::cuboid([1.0, 2.0, 3.0], [0.3, 0.7, 0.0], None, Amount::Mass(5.0)),
            r::int(1),
        )],
        about: Some([nearest(10.1, 254, 10), 0.0, nearest(-7.3, 254, 10)]),
        omega: [r::int(0), r::int(0), r::int(1)],
    });
}

/// A density in kg/m³ in a pound-and-inch file and a built-in material
/// there (mass and inertia bounds failed in `extended`).
#[test]
fn a_density_in_kilograms_per_cubic_metre_in_a_pound_file_is_within_its_bound() {
    let toml = "units = { length = \"in\", mass = \"lb\" }\n[analysis]\nomega = [0, 1, 0]\n\
                [[part]]\nshape = \"box\"\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n\
                density = \"999.9 kg/m^3\"\n[[part]]\nshape = \"sphere\"\nradius = 1.1\n\
                center = [2, 0.1, 0]\nmaterial = \"copper\"\n";
    // kg/m³ to lb/in³: 0.0254³ / 0.45359237.
    let to_file = |rho: f64| {
        r::f(
            &(r::q(rho) * r::frac(254, 10_000) * r::frac(254, 10_000) * r::frac(254, 10_000)
                / r::frac(45_359_237, 100_000_000)),
        )
    };
    check_case(&Case {
        toml: toml.to_string(),
        length: Length::In,
        mass: Mass::Lb,
        parts: vec![
            alone(
                Part::cuboid([1.0, 2.0, 3.0], [0.0; 3], None, Amount::Density(1.0)),
                r::q(to_file(999.9)),
            ),
            alone(
                Part::sphere(1.1, None, [2.0, 0.1, 0.0], None, Amount::Density(1.0)),
                r::q(to_file(8940.0)),
            ),
        ],
        about: None,
        omega: [r::int(0), r::int(1), r::int(0)],
    });
}

/// A material times a thickness, an area and a diameter: the exact
/// product, not the f64 one, is the answer (in `extended` the f64
/// product's rounding shows in the products of inertia).
#[test]
fn a_material_times_a_thickness_an_area_or_a_diameter_is_within_its_bound() {
    let toml = "units = { length = \"m\", mass = \"kg\" }\n[analysis]\nomega = [1, 0, 0]\n\
                [[part]]\nshape = \"plate\"\nsize = [1.3, 0.7]\ncenter = [0.3, 0.2, 0.1]\n\
                material = \"aluminium-6061\"\nthickness = 0.0029\n\
                [[part]]\nshape = \"rod\"\nlength = 1.7\ncenter = [-0.2, 0.9, 0.4]\n\
                material = \"titanium-6al-4v\"\ndiameter = 0.0087\n\
                [[part]]\nshape = \"rod\"\nlength = 2.1\ncenter = [0.5, 0, 1]\n\
                material = \"steel\"\narea = 3.3e-6\n\
                [[part]]\nshape = \"point\"\nmass = 0.1\ncenter = [0, 0, 0]\n";
    let d = r::q(0.0087);
    check_case(&Case {
        toml: toml.to_string(),
        length: Length::M,
        mass: Mass::Kg,
        parts: vec![
            alone(
                Part::plate([1.3, 0.7], [0.3, 0.2, 0.1], None, Amount::Density(1.0)),
                r::q(2700.0) * r::q(0.0029),
            ),
            alone(
                Part::rod(1.7, [-0.2, 0.9, 0.4], None, Amount::Density(1.0)),
                r::q(4430.0) * r::pi() * &d * &d / r::int(4),
            ),
            alone(
                Part::rod(2.1, [0.5, 0.0, 1.0], None, Amount::Density(1.0)),
                r::q(7850.0) * r::q(3.3e-6),
            ),
            alone(Part::point(0.1, [0.0; 3]), r::int(1)),
        ],
        about: None,
        omega: [r::int(1), r::int(0), r::int(0)],
    });
}

/// Generated cases whose parts turn a material into a mass by a size.
#[test]
fn generated_materials_times_a_size_are_within_their_bounds() {
    let with_products = |c: &Case| {
        c.parts.iter().any(|g| {
            ["thickness", "area =", "diameter"]
                .iter()
                .any(|k| g.toml.contains(k))
        })
    };
    assert!(property(24, with_products) > 0);
}

/// The generated quantities in other units are really written so: the
/// generator is not testing only plain numbers.
#[test]
fn the_generator_writes_quantities_in_other_units_in_each_kind_of_key() {
    let mut seen = std::collections::BTreeSet::new();
    let mut litres = false;
    for seed in 0..60 {
        let c = case(
            LENGTHS[(seed % 7) as usize],
            MASSES[(seed % 5) as usize],
            seed,
        );
        litres |= c.toml.contains("/L\"") || c.toml.contains("/mL\"");
        for line in c.toml.lines() {
            if let Some((key, value)) = line.split_once(" = ")
                && value.contains('"')
                && !["material", "shape", "units"].contains(&key)
            {
                seen.insert(key.to_string());
            }
            if line.starts_with("material") {
                seen.insert("material".to_string());
            }
        }
        assert!(!c.omega.iter().all(Zero::is_zero));
    }
    for key in [
        "size",
        "center",
        "radius",
        "length",
        "about",
        "omega",
        "density",
        "areal_density",
        "linear_density",
        "mass",
        "thickness",
        "area",
        "diameter",
        "material",
    ] {
        assert!(seen.contains(key), "no {key} in another unit: {seen:?}");
    }
    assert!(litres, "no density per litre or millilitre");
}

/// A mesh shell's density times its `thickness` is a product formed in
/// f64 too: a box's surface a × b × c as twelve triangles, against its six
/// faces as plates of the exact areal density, in both arithmetics.
#[test]
fn a_mesh_shell_s_density_times_its_thickness_is_within_its_bound() {
    let (a, b, c) = (1.25, 0.75, 2.5);
    let (x, y, z) = (a / 2.0, b / 2.0, c / 2.0);
    // Each face's corners counter-clockwise seen from outside.
    let faces: [[[f64; 3]; 4]; 6] = [
        [[x, -y, -z], [x, y, -z], [x, y, z], [x, -y, z]],
        [[-x, -y, -z], [-x, -y, z], [-x, y, z], [-x, y, -z]],
        [[-x, y, -z], [-x, y, z], [x, y, z], [x, y, -z]],
        [[-x, -y, -z], [x, -y, -z], [x, -y, z], [-x, -y, z]],
        [[-x, -y, z], [x, -y, z], [x, y, z], [-x, y, z]],
        [[-x, -y, -z], [-x, y, -z], [x, y, -z], [x, -y, -z]],
    ];
    let mut stl = String::from("solid box\n");
    for f in &faces {
        for tri in [[f[0], f[1], f[2]], [f[0], f[2], f[3]]] {
            stl.push_str(" facet normal 0 0 0\n  outer loop\n");
            for p in tri {
                stl.push_str(&format!("   vertex {:?} {:?} {:?}\n", p[0], p[1], p[2]));
            }
            stl.push_str("  endloop\n endfacet\n");
        }
    }
    stl.push_str("endsolid box\n");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("box.stl"), stl).unwrap();
    // Thicknesses whose product with the density rounds by a good part
    // of an ulp.
    for t in [0.0037, 0.0029, 0.0013, 0.0063, 0.0077] {
        let toml = format!(
            "units = {{ length = \"m\", mass = \"kg\" }}\n[analysis]\nomega = [0, 0, 1]\n\
             [[part]]\nshape = \"mesh\"\nfile = \"box.stl\"\nmesh_unit = \"m\"\n\
             mode = \"shell\"\ndensity = \"2.7 g/cm^3\"\nthickness = {t:?}\n\
             [[part]]\nshape = \"point\"\nmass = 0.5\ncenter = [0.3, 0.2, 0.1]\n"
        );
        // The exact areal density: 2.7 g/cm³ (the nearest f64 of 2700)
        // times the thickness, not rounded.
        shell_against_plates(
            dir.path(),
            &toml,
            r::q(nearest(2.7, 1000, 1)) * r::q(t),
            [a, b, c],
        );
    }
}

/// `toml` (a box's surface a × b × c as a shell mesh `box.stl` in `dir`,
/// and a point) against six plates of `areal` density and the point.
fn shell_against_plates(dir: &std::path::Path, toml: &str, areal: Q, [a, b, c]: [f64; 3]) {
    let (x, y, z) = (a / 2.0, b / 2.0, c / 2.0);
    let path = dir.join("parts.toml");
    std::fs::write(&path, toml).unwrap();
    let turn = |m: [[f64; 3]; 3]| Some(r::Rotation::Matrix(m));
    let x_normal = turn([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]);
    let y_normal = turn([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]);
    let plate = |size: [f64; 2], center: [f64; 3], rotation: Option<r::Rotation>| {
        alone(
            Part::plate(size, center, None, Amount::Density(1.0)).with_rotation(rotation),
            areal.clone(),
        )
    };
    let case = Case {
        toml: String::new(),
        length: Length::M,
        mass: Mass::Kg,
        parts: vec![
            // x faces: a plate c × b turned so its normal is x (its local
            // x is the file's −z, its local y the file's y).
            plate([c, b], [x, 0.0, 0.0], x_normal),
            plate([c, b], [-x, 0.0, 0.0], x_normal),
            // y faces: local x is x, local y is z.
            plate([a, c], [0.0, y, 0.0], y_normal),
            plate([a, c], [0.0, -y, 0.0], y_normal),
            plate([a, b], [0.0, 0.0, z], None),
            plate([a, b], [0.0, 0.0, -z], None),
            alone(Part::point(0.5, [0.3, 0.2, 0.1]), r::int(1)),
        ],
        about: None,
        omega: [r::int(0), r::int(0), r::int(1)],
    };
    let e = exact(&case);
    for p in ["standard", "extended"] {
        let (v, _) = crate::common::report_json_file(&path, &["--precision", p]);
        let failures = honest(&v, &e);
        assert!(
            failures.is_empty(),
            "{p}:\n  {}\nfor:\n{toml}",
            failures.join("\n  ")
        );
    }
}
