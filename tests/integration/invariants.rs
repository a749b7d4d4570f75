//! Property tests over random assemblies (proptest): 2 to 8 parts of every
//! shape and placement, random sizes, orientations, masses and densities,
//! run through massprop's JSON output in both precision modes.
//!
//! - translating the whole assembly leaves the inertia about its centre of
//!   mass unchanged;
//! - the order of the parts does not matter;
//! - a quarter turn of the whole assembly permutes the tensor and keeps the
//!   principal moments;
//! - splitting a box in two halves changes nothing;
//! - every result is within its bound of the exact reference.
//!
//! The transformations are chosen to be exact on the f64 inputs (positions
//! on a binary grid, integer-grid offsets, halving), so each pair of runs
//! describes exactly the same body and may differ only by massprop's own
//! rounding: each run is within TENSOR (MOMENT, …) of the same exact result,
//! so two runs are within twice that of each other. Each property prints
//! its worst error/bound over all cases.

use crate::stress::{
    self, MOMENT, Margins, Precision, Report, TENSOR, check_against_reference, check_axes,
    com_bound, mass_bound, report, turn_tensor,
};
use massprop_support::reference::{self as r, Amount, Length, Mass, Part, Scene, fm};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use std::cell::RefCell;

/// Cases per property: enough to meet every shape and placement in many
/// combinations, few enough for a debug build (the exact reference costs
/// ~0.1 s per assembly there).
const CASES: u32 = 48;

/// Run `body` on `CASES` inputs from `strategy`; fail with the smallest
/// failing input proptest finds, and print the worst error/bound of each
/// quantity over all cases.
fn property<S: Strategy>(
    name: &str,
    cases: u32,
    strategy: S,
    body: impl Fn(&S::Value, &mut Margins),
) where
    S::Value: std::fmt::Debug,
{
    let mut config = Config::with_cases(cases);
    // No regression files in the source tree: the seeds are fixed anyway.
    config.failure_persistence = None;
    config.rng_algorithm = proptest::test_runner::RngAlgorithm::ChaCha;
    let mut runner = TestRunner::new_with_rng(
        config.clone(),
        proptest::test_runner::TestRng::deterministic_rng(config.rng_algorithm),
    );
    let all = RefCell::new(Margins::new(format!("property {name}")));
    let count = RefCell::new(0usize);
    let result = runner.run(&strategy, |input| {
        let mut m = Margins::new("");
        body(&input, &mut m);
        let failed = m.failures();
        *count.borrow_mut() += 1;
        all.borrow_mut()
            .absorb(m, &format!("case {}: ", count.borrow()));
        if failed.is_empty() {
            Ok(())
        } else {
            Err(TestCaseError::fail(failed.join("\n")))
        }
    });
    if let Err(e) = result {
        panic!("property {name}: {e}");
    }
    all.into_inner().finish();
}

// ---------------------------------------------------------------------------
// Strategies

/// The 2⁻²⁰ grid: positions within ±4 on it plus offsets below 2²⁸ on it
/// stay exact in f64 (48 bits).
const GRID: f64 = 1048576.0;

fn grid_point() -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-4 * 1048576i64..=4 * 1048576).prop_map(|a| a.map(|i| i as f64 / GRID))
}

fn on_grid(x: f64, grid: f64) -> f64 {
    (x * grid).round() / grid
}

fn quaternion() -> impl Strategy<Value = [f64; 4]> {
    prop::array::uniform4(-1.0f64..1.0)
        .prop_filter("not too short to normalise", |q| {
            q.iter().map(|x| x * x).sum::<f64>() > 0.04
        })
        .prop_map(|q| {
            let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
            q.map(|x| x / n)
        })
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    BoxTurned,
    BoxUpright,
    BoxEdges,
    PlateTurned,
    PlateEdges,
    RodTurned,
    RodFromTo,
    Point,
}

/// Every shape and placement; `turnable` keeps to those a quarter turn maps
/// exactly (no part rotated by a quaternion, no canonical plate).
fn part(turnable: bool) -> impl Strategy<Value = Part> {
    let kinds = if turnable {
        vec![
            Kind::BoxUpright,
            Kind::BoxEdges,
            Kind::PlateEdges,
            Kind::RodFromTo,
            Kind::Point,
        ]
    } else {
        vec![
            Kind::BoxTurned,
            Kind::BoxUpright,
            Kind::BoxEdges,
            Kind::PlateTurned,
            Kind::PlateEdges,
            Kind::RodTurned,
            Kind::RodFromTo,
            Kind::Point,
        ]
    };
    (
        prop::sample::select(kinds),
        prop::array::uniform3(0.05f64..3.0),
        grid_point(),
        quaternion(),
        0.1f64..10.0,
        any::<bool>(),
    )
        .prop_map(|(kind, s, at, q, amount, by_density)| {
            let amount = if by_density && kind != Kind::Point {
                Amount::Density(amount)
            } else {
                Amount::Mass(amount)
            };
            let rot = fm(&r::rotation(&q.map(r::q)));
            let edge = |k: usize| stress::edge(&rot, k, s[k]);
            match kind {
                Kind::BoxTurned => Part::cuboid(s, at, Some(q), amount),
                Kind::BoxUpright => Part::cuboid(s, at, None, amount),
                Kind::BoxEdges => Part::box_edges(at, [edge(0), edge(1), edge(2)], amount),
                Kind::PlateTurned => Part::plate([s[0], s[1]], at, Some(q), amount),
                Kind::PlateEdges => Part::plate_edges(at, [edge(0), edge(1)], amount),
                Kind::RodTurned => Part::rod(s[2], at, Some(q), amount),
                // Both ends on the grid, so translations stay exact.
                Kind::RodFromTo => Part::rod_from_to(
                    at,
                    std::array::from_fn(|i| on_grid(at[i] + edge(2)[i], GRID)),
                    amount,
                ),
                Kind::Point => Part::point(amount_value(amount), at),
            }
        })
}

fn amount_value(a: Amount) -> f64 {
    match a {
        Amount::Mass(x) | Amount::Density(x) => x,
    }
}

fn assembly(turnable: bool) -> impl Strategy<Value = Scene> {
    prop::collection::vec(part(turnable), 2..=8).prop_map(Scene::si)
}

fn precision() -> impl Strategy<Value = Precision> {
    prop_oneof![Just(Precision::Standard), Just(Precision::Extended)]
}

// ---------------------------------------------------------------------------
// Comparing two runs of the same body

/// Two runs of exactly the same body: each within TENSOR, MOMENT, the mass
/// and centre-of-mass bounds of the same exact result, so within twice
/// those of each other. `tensor` and `com` are the first run's, mapped into
/// the second's frame (turned, or moved: then the subtraction of the offset
/// rounds once more, u of the larger scale).
struct Expect {
    tensor: [[f64; 3]; 3],
    com: [f64; 3],
}

fn same_body(m: &mut Margins, what: &str, a: &Report, b: &Report, expect: Expect) {
    let n = a.parts.len().max(b.parts.len());
    m.check(
        "I_com",
        what,
        r::rel_frobenius_f64(&b.inertia, &expect.tensor, &a.inertia),
        2.0 * TENSOR,
    );
    for k in 0..3 {
        m.check(
            "moments",
            format_args!("{what}, moment {k}"),
            (a.moments[k] - b.moments[k]).abs() / a.moments[2],
            2.0 * MOMENT,
        );
    }
    m.check(
        "mass",
        what,
        (a.mass - b.mass).abs() / a.mass,
        2.0 * mass_bound(n),
    );
    let scale = a.com_scale().max(b.com_scale());
    let d = (0..3)
        .map(|i| (b.com[i] - expect.com[i]).powi(2))
        .sum::<f64>()
        .sqrt();
    m.check("com", what, d / scale, 2.0 * com_bound(n) + 2.0 * stress::U);
}

// ---------------------------------------------------------------------------
// Properties

#[test]
fn translating_an_assembly_leaves_its_inertia_about_the_centre_of_mass_unchanged() {
    let offset = prop::array::uniform3(-1e8f64..1e8).prop_map(|t| t.map(|x| on_grid(x, GRID)));
    property(
        "translation",
        CASES,
        (assembly(false), offset, precision()),
        |(scene, t, p), m| {
            assert!(
                scene.translation_is_exact(*t),
                "grid positions translate exactly"
            );
            let a = report(scene, *p);
            let b = report(&scene.translated(*t), *p);
            let com = std::array::from_fn(|i| a.com[i] + t[i]);
            same_body(
                m,
                "translated",
                &a,
                &b,
                Expect {
                    tensor: a.inertia,
                    com,
                },
            );
        },
    );
}

#[test]
fn the_order_of_parts_does_not_matter() {
    let shuffled = assembly(false).prop_flat_map(|s| {
        let n = s.parts.len();
        (Just(s), Just((0..n).collect::<Vec<usize>>()).prop_shuffle())
    });
    property(
        "order",
        CASES,
        (shuffled, precision()),
        |((scene, order), p), m| {
            let a = report(scene, *p);
            let b = report(&scene.reordered(order), *p);
            same_body(
                m,
                "reordered",
                &a,
                &b,
                Expect {
                    tensor: a.inertia,
                    com: a.com,
                },
            );
        },
    );
}

#[test]
fn a_quarter_turn_permutes_the_tensor_and_keeps_the_moments() {
    property(
        "quarter turn",
        CASES,
        (assembly(true), 0usize..3, precision()),
        |(scene, axis, p), m| {
            let a = report(scene, *p);
            let b = report(&scene.quarter_turn(*axis), *p);
            let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
            let mut com = a.com;
            com[i] = -a.com[j];
            com[j] = a.com[i];
            let tensor = turn_tensor(&a.inertia, *axis);
            same_body(m, "turned", &a, &b, Expect { tensor, com });
        },
    );
}

/// A box placed by corner and edges on the 2⁻⁴⁰ grid (|corner| ≤ 4, edges
/// ≤ 3), so halving an edge and adding it to the corner is exact. Rounding
/// the edges to the grid tilts them by at most 2⁻⁴¹/0.05 ≈ 1e-11 rad, well
/// within the 1e-9 perpendicularity massprop asks for.
fn grid_box() -> impl Strategy<Value = ([f64; 3], [[f64; 3]; 3], Amount)> {
    (
        grid_point(),
        quaternion(),
        prop::array::uniform3(0.05f64..3.0),
        0.1f64..10.0,
        any::<bool>(),
    )
        .prop_map(|(corner, q, s, x, by_density)| {
            let rot = fm(&r::rotation(&q.map(r::q)));
            let g = (1u64 << 40) as f64;
            let edges = [0, 1, 2].map(|k| stress::edge(&rot, k, s[k]).map(|x| on_grid(x, g)));
            let amount = if by_density {
                Amount::Density(x)
            } else {
                Amount::Mass(x)
            };
            (corner, edges, amount)
        })
}

#[test]
fn splitting_a_box_in_halves_changes_nothing() {
    property(
        "split",
        CASES,
        (
            prop::collection::vec(part(false), 1..=6),
            grid_box(),
            0usize..3,
            precision(),
        ),
        |(others, (corner, edges, amount), k, p), m| {
            let half_amount = match amount {
                Amount::Mass(x) => Amount::Mass(x / 2.0),
                d => *d,
            };
            let mut half = *edges;
            half[*k] = edges[*k].map(|x| x / 2.0);
            let far = std::array::from_fn(|i| corner[i] + half[*k][i]);
            let mut whole = others.clone();
            whole.push(Part::box_edges(*corner, *edges, *amount));
            let mut split = others.clone();
            split.push(Part::box_edges(*corner, half, half_amount));
            split.push(Part::box_edges(far, half, half_amount));
            let (whole, split) = (Scene::si(whole), Scene::si(split));
            // The halves are exactly the box (up to the reference's square
            // roots of 2⁻²⁰⁰, for a mass from a density and edges).
            let (ew, es) = (r::compose(&whole), r::compose(&split));
            assert!(
                r::rel_frobenius_exact(&es.inertia, &ew.inertia) < 1e-55,
                "exact split"
            );
            let a = report(&whole, *p);
            let b = report(&split, *p);
            same_body(
                m,
                "split",
                &a,
                &b,
                Expect {
                    tensor: a.inertia,
                    com: a.com,
                },
            );
        },
    );
}

#[test]
fn random_assemblies_in_any_units_match_the_exact_reference() {
    let units = (
        prop::sample::select(vec![
            Length::M,
            Length::Cm,
            Length::Mm,
            Length::Um,
            Length::Km,
            Length::In,
            Length::Ft,
        ]),
        prop::sample::select(vec![Mass::Kg, Mass::G, Mass::Mg, Mass::T, Mass::Lb]),
    );
    property(
        "reference",
        CASES,
        (assembly(false), units, precision()),
        |(scene, (length, mass), p), m| {
            let scene = Scene {
                length: *length,
                mass: *mass,
                ..scene.clone()
            };
            let rep = report(&scene, *p);
            let what = format!("{} {} {}", length.symbol(), mass.symbol(), p.flag());
            let (_, pr) = check_against_reference(m, &what, &scene, &rep);
            check_axes(m, &what, &rep, &pr);
        },
    );
}
