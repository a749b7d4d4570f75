//! Property tests over random assemblies (proptest): 2 to 8 parts of every
//! shape and placement — box, plate, rod, point, cylinder, tube, disk,
//! annulus, sphere, hollow sphere, thin shell, triangle, given inertia —
//! random sizes, orientations, masses and densities, run through massprop's
//! JSON output in both precision modes.
//!
//! - translating the whole assembly leaves the inertia about its centre of
//!   mass unchanged;
//! - the order of the parts does not matter;
//! - a quarter turn of the whole assembly permutes the tensor and keeps the
//!   principal moments;
//! - splitting a box in two halves changes nothing;
//! - every result is within its bound of the exact reference, and so is
//!   each shape alone (printed per shape).
//!
//! The transformations are chosen to be exact on the f64 inputs (positions
//! on a binary grid, integer-grid offsets, halving, signed permutations),
//! so each pair of runs describes exactly the same body and may differ only
//! by massprop's own rounding: each run is within the scene's bounds
//! ([`Bounds::of`]: TENSOR, MOMENT, … plus what its shapes add) of the same
//! exact result, so two runs are within twice that of each other. Each
//! property prints its worst error/bound over all cases.

use crate::stress::{
    self, Bounds, Margins, Precision, Report, check_against_reference, check_against_reference_as,
    check_axes, check_axes_as, report, turn_tensor,
};
use crate::support::reference::{
    self as r, Amount, Length, Mass, Part, Products, Rotation, Scene, fm,
};
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
    Cylinder,
    Tube,
    Disk,
    Annulus,
    Sphere,
    HollowSphere,
    Shell,
    Triangle,
    Given,
    Cone,
    HollowCone,
    Torus,
    Hemisphere,
    Prism,
    Capsule,
    Ellipsoid,
}

impl Kind {
    /// Every kind of part; `turnable` keeps to those a quarter turn maps
    /// exactly (no part rotated by a quaternion: the new shapes are then
    /// unrotated or turned by a signed permutation).
    fn all(turnable: bool) -> Vec<Kind> {
        use Kind::*;
        let mut kinds = if turnable {
            vec![BoxUpright, BoxEdges, PlateEdges, RodFromTo, Point]
        } else {
            vec![
                BoxTurned,
                BoxUpright,
                BoxEdges,
                PlateTurned,
                PlateEdges,
                RodTurned,
                RodFromTo,
                Point,
            ]
        };
        kinds.extend(Kind::NEW);
        kinds
    }

    /// The shapes beyond box, plate, rod and point.
    const NEW: [Kind; 16] = [
        Kind::Cylinder,
        Kind::Tube,
        Kind::Disk,
        Kind::Annulus,
        Kind::Sphere,
        Kind::HollowSphere,
        Kind::Shell,
        Kind::Triangle,
        Kind::Given,
        Kind::Cone,
        Kind::HollowCone,
        Kind::Torus,
        Kind::Hemisphere,
        Kind::Prism,
        Kind::Capsule,
        Kind::Ellipsoid,
    ];

    fn name(self) -> &'static str {
        match self {
            Kind::Cylinder => "cylinder",
            Kind::Tube => "tube",
            Kind::Disk => "disk",
            Kind::Annulus => "annulus",
            Kind::Sphere => "sphere",
            Kind::HollowSphere => "hollow sphere",
            Kind::Shell => "shell",
            Kind::Triangle => "triangle",
            Kind::Given => "given inertia",
            Kind::Cone => "cone",
            Kind::HollowCone => "hollow cone",
            Kind::Torus => "torus",
            Kind::Hemisphere => "hemisphere",
            Kind::Prism => "prism",
            Kind::Capsule => "capsule",
            Kind::Ellipsoid => "ellipsoid",
            _ => "box, plate, rod or point",
        }
    }
}

/// A rotation by a signed permutation with determinant +1 (one of the 24
/// quarter-turn rotations), exact in any part file.
fn signed_permutation() -> impl Strategy<Value = Rotation> {
    (0usize..6, 0usize..4).prop_map(|(perm, signs)| {
        let order = [
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ][perm];
        // Odd permutations need an odd number of sign flips.
        let odd = matches!(perm, 1 | 2 | 5);
        let mut s = [1.0, 1.0, 1.0];
        if signs & 1 == 1 {
            s[0] = -1.0;
            s[1] = -1.0;
        }
        if signs & 2 == 2 {
            s[1] = -s[1];
            s[2] = -s[2];
        }
        if odd {
            s[2] = -s[2];
        }
        let mut m = [[0.0; 3]; 3];
        for (row, &col) in order.iter().enumerate() {
            m[row][col] = s[row];
        }
        Rotation::Matrix(m)
    })
}

/// An inner radius as a fraction of the outer: anywhere in (0, 1), or
/// within 2⁻¹⁰ … 2⁻⁴⁰ of 1 (thin walls, where R − r must not cancel), or
/// exactly 1 (thin: mass only).
fn inner_ratio() -> impl Strategy<Value = f64> {
    prop_oneof![
        2 => 0.02f64..0.98,
        1 => (10i32..=40).prop_map(|k| 1.0 - 0.5f64.powi(k)),
        1 => Just(1.0),
    ]
}

/// One part of a kind from `kinds`; parts of the new shapes are turned by a
/// quaternion, by a signed permutation or not at all (only the latter two
/// when `turnable`).
fn part_of(kinds: Vec<Kind>, turnable: bool) -> impl Strategy<Value = (Kind, Part)> {
    let rotation = if turnable {
        prop_oneof![Just(None), signed_permutation().prop_map(Some)].boxed()
    } else {
        prop_oneof![
            2 => quaternion().prop_map(|q| Some(Rotation::Quaternion(q))),
            1 => Just(None),
            1 => signed_permutation().prop_map(Some),
        ]
        .boxed()
    };
    (
        prop::sample::select(kinds),
        prop::array::uniform3(0.05f64..3.0),
        grid_point(),
        quaternion(),
        0.1f64..10.0,
        any::<bool>(),
        (rotation, inner_ratio(), -0.5f64..1.5, any::<bool>()),
    )
        .prop_map(
            |(kind, s, at, q, amount, by_density, (rotation, ratio, skew, positive))| {
                // Thin walls, points and given tensors take only a mass.
                let thin = match kind {
                    Kind::Shell => true,
                    Kind::Tube
                    | Kind::Annulus
                    | Kind::HollowSphere
                    | Kind::Torus
                    | Kind::Hemisphere
                    | Kind::Capsule => ratio == 1.0,
                    _ => false,
                };
                let amount = if by_density && !thin && !matches!(kind, Kind::Point | Kind::Given) {
                    Amount::Density(amount)
                } else {
                    Amount::Mass(amount)
                };
                let rot = fm(&r::rotation(&q.map(r::q)));
                let edge = |k: usize| stress::edge(&rot, k, s[k]);
                let inner = Some(s[0] * ratio);
                let part = match kind {
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
                    Kind::Cylinder => Part::cylinder(s[0], None, s[2], at, rotation, amount),
                    Kind::Tube => Part::cylinder(s[0], inner, s[2], at, rotation, amount),
                    Kind::Disk => Part::disk(s[0], None, at, rotation, amount),
                    Kind::Annulus => Part::disk(s[0], inner, at, rotation, amount),
                    Kind::Sphere => Part::sphere(s[0], None, at, rotation, amount),
                    Kind::HollowSphere => Part::sphere(s[0], inner, at, rotation, amount),
                    Kind::Shell => Part::sphere(s[0], Some(s[0]), at, rotation, amount),
                    // A full cone, apex up or down by `positive`.
                    Kind::Cone => {
                        let (base, top) = if positive { (s[0], 0.0) } else { (0.0, s[0]) };
                        Part::cone(base, top, s[2], None, at, rotation, amount)
                    }
                    // A frustum and its bore (never a thin shell: the
                    // reference takes none).
                    Kind::HollowCone => {
                        let r = ratio.min(0.99);
                        let bore = Some((s[0] * r, s[1] * r * skew.abs().min(1.0)));
                        Part::cone(s[0], s[1], s[2], bore, at, rotation, amount)
                    }
                    Kind::Torus => {
                        Part::torus(s[0] + s[1], s[1], Some(s[1] * ratio), at, rotation, amount)
                    }
                    Kind::Hemisphere => Part::hemisphere(s[0], inner, at, rotation, amount),
                    Kind::Capsule => Part::capsule(s[0], s[2], inner, at, rotation, amount),
                    Kind::Ellipsoid => Part::ellipsoid(s, at, rotation, amount),
                    // An L in its local x–y plane, off its origin.
                    Kind::Prism => {
                        let (a, b) = (s[0], s[1]);
                        let p = |x: f64, y: f64| [on_grid(x + skew, GRID), on_grid(y, GRID)];
                        Part::prism(
                            vec![
                                p(0.0, 0.0),
                                p(a, 0.0),
                                p(a, b / 2.0),
                                p(a / 2.0, b / 2.0),
                                p(a / 2.0, b),
                                p(0.0, b),
                            ],
                            s[2],
                            at,
                            rotation,
                            amount,
                        )
                    }
                    // Vertices on the grid (translations stay exact): two
                    // perpendicular legs, the second 0.2 to 1 times the
                    // first and slid along it by −0.5 to 1.5 of it, so no
                    // angle is below about 7° (the area's conditioning).
                    Kind::Triangle => {
                        let v = |e: [f64; 3]| std::array::from_fn(|i| on_grid(at[i] + e[i], GRID));
                        let leg = stress::edge(&rot, 1, s[0] * (0.2 + 0.8 * s[1] / 3.0));
                        let far = std::array::from_fn(|i| skew * edge(0)[i] + leg[i]);
                        Part::triangle([at, v(edge(0)), v(far)], amount)
                    }
                    Kind::Given => {
                        let factors = [0.02 + 0.48 * ratio.min(0.99), 0.26, 0.5];
                        // Principal second moments m sₖ² times 0.02 to 0.5:
                        // valid with room to spare for the rounding.
                        let tensor = stress::given_tensor(
                            amount_value(amount),
                            std::array::from_fn(|k| s[k] * factors[k].sqrt()),
                            q,
                        );
                        let products = if positive {
                            Products::Positive
                        } else {
                            Products::Tensor
                        };
                        let written = if positive {
                            std::array::from_fn(|i| {
                                std::array::from_fn(|j| {
                                    if i == j { tensor[i][j] } else { -tensor[i][j] }
                                })
                            })
                        } else {
                            tensor
                        };
                        Part::given(amount_value(amount), written, products, at, rotation)
                    }
                };
                (kind, part)
            },
        )
}

/// Every shape and placement; `turnable` keeps to those a quarter turn maps
/// exactly (no part rotated by a quaternion).
fn part(turnable: bool) -> impl Strategy<Value = Part> {
    part_of(Kind::all(turnable), turnable).prop_map(|(_, p)| p)
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

/// `scenes`: the two scenes run, whose bounds (the larger of each) apply.
fn same_body(
    m: &mut Margins,
    what: &str,
    scenes: [&Scene; 2],
    [a, b]: [&Report; 2],
    expect: Expect,
) {
    let [x, y] = scenes.map(Bounds::of);
    let bound = Bounds {
        tensor: x.tensor.max(y.tensor),
        moment: x.moment.max(y.moment),
        mass: x.mass.max(y.mass),
        com: x.com.max(y.com),
    };
    m.check(
        "I_com",
        what,
        r::rel_frobenius_f64(&b.inertia, &expect.tensor, &a.inertia),
        2.0 * bound.tensor,
    );
    for k in 0..3 {
        m.check(
            "moments",
            format_args!("{what}, moment {k}"),
            (a.moments[k] - b.moments[k]).abs() / a.moments[2],
            2.0 * bound.moment,
        );
    }
    m.check(
        "mass",
        what,
        (a.mass - b.mass).abs() / a.mass,
        2.0 * bound.mass,
    );
    let scale = a.com_scale().max(b.com_scale());
    let d = (0..3)
        .map(|i| (b.com[i] - expect.com[i]).powi(2))
        .sum::<f64>()
        .sqrt();
    m.check("com", what, d / scale, 2.0 * bound.com + 2.0 * stress::U);
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
            let moved = scene.translated(*t);
            let a = report(scene, *p);
            let b = report(&moved, *p);
            let com = std::array::from_fn(|i| a.com[i] + t[i]);
            same_body(
                m,
                "translated",
                [scene, &moved],
                [&a, &b],
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
            let reordered = scene.reordered(order);
            let a = report(scene, *p);
            let b = report(&reordered, *p);
            same_body(
                m,
                "reordered",
                [scene, &reordered],
                [&a, &b],
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
            let turned = scene.quarter_turn(*axis);
            let a = report(scene, *p);
            let b = report(&turned, *p);
            let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
            let mut com = a.com;
            com[i] = -a.com[j];
            com[j] = a.com[i];
            let tensor = turn_tensor(&a.inertia, *axis);
            same_body(
                m,
                "turned",
                [scene, &turned],
                [&a, &b],
                Expect { tensor, com },
            );
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
                [&whole, &split],
                [&a, &b],
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
            check_axes(m, &what, &rep, &pr, Bounds::of(&scene).moment);
        },
    );
}

/// Each new shape alone (one to three parts of one kind, in any units and
/// placement), so that the margins print per shape: the worst error/bound
/// of `I_com cylinder`, `mass shell`, and so on.
#[test]
fn each_shape_alone_matches_the_exact_reference() {
    let alone = prop::sample::select(Kind::NEW.to_vec()).prop_flat_map(|kind| {
        (
            prop::collection::vec(part_of(vec![kind], false), 1..=3),
            prop::sample::select(vec![Length::M, Length::Mm, Length::In, Length::Km]),
            prop::sample::select(vec![Mass::Kg, Mass::G, Mass::Lb]),
        )
    });
    property(
        "each shape",
        CASES,
        (alone, precision()),
        |((parts, length, mass), p), m| {
            let kind = parts[0].0;
            let scene = Scene {
                length: *length,
                mass: *mass,
                parts: parts.iter().map(|(_, part)| part.clone()).collect(),
                about: None,
            };
            let rep = report(&scene, *p);
            let what = format!("{} {} {}", length.symbol(), mass.symbol(), p.flag());
            let label = format!(" {}", kind.name());
            let (_, pr) = check_against_reference_as(m, &label, &what, &scene, &rep);
            check_axes_as(m, &label, &what, &rep, &pr, Bounds::of(&scene).moment);
        },
    );
}
