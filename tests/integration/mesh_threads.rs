//! A mesh's answer does not depend on the number of threads (issue 33,
//! item 4): every stage's work is cut into pieces fixed by the mesh alone
//! and merged in a fixed order, so one, two and three threads
//! (`mesh::with_threads`, which forces them however small the mesh) give
//! the same bits — the integrals, their bounds, the warnings — and the
//! same refusal, naming the same triangles, wherever a crossing lies:
//! first in the file, last, across the border of two threads' shares, or
//! two crossings of which the earlier must win.

use massprop::mesh::{FileType, MeshBody, Mode, with_threads};

type Tri = [[f64; 3]; 3];

/// A binary STL of the triangles (f32 corners).
fn stl(tris: &[Tri]) -> Vec<u8> {
    let mut out = vec![b' '; 80];
    out.extend((tris.len() as u32).to_le_bytes());
    for t in tris {
        out.extend([0u8; 12]);
        for c in t.iter().flatten() {
            out.extend((*c as f32).to_le_bytes());
        }
        out.extend([0u8; 2]);
    }
    out
}

/// An ASCII STL of the triangles (f64 corners, shortest round trip).
fn ascii(tris: &[Tri]) -> Vec<u8> {
    let mut s = String::from("solid s\n");
    for t in tris {
        s += "facet normal 0 0 0\nouter loop\n";
        for v in t {
            s += &format!("vertex {:?} {:?} {:?}\n", v[0], v[1], v[2]);
        }
        s += "endloop\nendfacet\n";
    }
    s += "endsolid s\n";
    s.into_bytes()
}

/// A UV sphere of radius r about c, n bands, 2n longitudes, wound outward.
fn sphere(n: usize, r: f64, c: [f64; 3]) -> Vec<Tri> {
    let m = 2 * n;
    let p = |i: usize, j: usize| -> [f64; 3] {
        let (th, ph) = (
            std::f64::consts::PI * i as f64 / n as f64,
            2.0 * std::f64::consts::PI * (j % m) as f64 / m as f64,
        );
        let (x, y, z) = if i == 0 {
            (0.0, 0.0, r)
        } else if i == n {
            (0.0, 0.0, -r)
        } else {
            (
                r * th.sin() * ph.cos(),
                r * th.sin() * ph.sin(),
                r * th.cos(),
            )
        };
        [c[0] + x, c[1] + y, c[2] + z]
    };
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b, cc, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            if i != 0 {
                t.push([a, b, d]);
            }
            if i != n - 1 {
                t.push([b, cc, d]);
            }
        }
    }
    t
}

/// A cube of side s from lo, two triangles a face; wound outward, or
/// inward (a cavity).
fn cube(lo: [f64; 3], s: f64, inward: bool) -> Vec<Tri> {
    let c = |i: usize| -> [f64; 3] {
        std::array::from_fn(|k| lo[k] + if (i >> k) & 1 == 1 { s } else { 0.0 })
    };
    let quads = [
        (0, 2, 3, 1),
        (4, 5, 7, 6),
        (0, 1, 5, 4),
        (2, 6, 7, 3),
        (0, 4, 6, 2),
        (1, 3, 7, 5),
    ];
    let mut t = Vec::new();
    for (a, b, cc, d) in quads {
        for tri in [[c(a), c(b), c(cc)], [c(a), c(cc), c(d)]] {
            t.push(if inward {
                [tri[0], tri[2], tri[1]]
            } else {
                tri
            });
        }
    }
    t
}

/// The cubes of a k × k × k grid, unit cubes 2 apart, in the grid's order.
fn grid(k: usize) -> Vec<Vec<Tri>> {
    let mut out = Vec::new();
    for i in 0..k {
        for j in 0..k {
            for l in 0..k {
                out.push(cube(
                    [2.0 * i as f64, 2.0 * j as f64, 2.0 * l as f64],
                    1.0,
                    false,
                ));
            }
        }
    }
    out
}

/// The body and warnings, or the error, on `threads` threads.
fn load(bytes: &[u8], threads: usize) -> Result<(MeshBody, Vec<String>), String> {
    with_threads(threads, || {
        MeshBody::load_with(FileType::Stl, bytes, Mode::Solid, None).map_err(|e| e.message)
    })
}

/// Every number of a body as bits (−0 and +0, and NaN, told apart).
fn bits(b: &MeshBody) -> Vec<u64> {
    let mut v = vec![b.measure.hi.to_bits(), b.measure.lo.to_bits()];
    v.extend(
        b.centroid
            .iter()
            .flat_map(|x| [x.hi.to_bits(), x.lo.to_bits()]),
    );
    v.extend(
        b.second
            .iter()
            .flatten()
            .flat_map(|x| [x.hi.to_bits(), x.lo.to_bits()]),
    );
    v.extend([b.bound.measure, b.bound.centroid, b.bound.second].map(f64::to_bits));
    v.extend(b.extent.iter().flatten().map(|x| x.to_bits()));
    v
}

/// The answer on 1 thread, held equal to the answers on 2 and 3.
fn same_on_every_thread_count(bytes: &[u8]) -> Result<(MeshBody, Vec<String>), String> {
    let one = load(bytes, 1);
    for threads in [2, 3] {
        let other = load(bytes, threads);
        match (&one, &other) {
            (Ok((a, wa)), Ok((b, wb))) => {
                assert_eq!(bits(a), bits(b), "{threads} threads");
                assert_eq!(a, b, "{threads} threads");
                assert_eq!(wa, wb, "{threads} threads");
            }
            (a, b) => assert_eq!(a.as_ref().err(), b.as_ref().err(), "{threads} threads"),
        }
    }
    one
}

/// The two triangle numbers (from 1) a crossing's message names first.
fn crossing_pair(message: &str) -> (usize, usize) {
    let words: Vec<&str> = message.split_whitespace().collect();
    assert_eq!(words[0], "triangle", "{message}");
    assert!(message.contains(" cross: "), "{message}");
    let first = words[1].parse().expect("a triangle number");
    let and = words
        .iter()
        .position(|w| *w == "and")
        .expect("two triangles");
    let second = words[and + 2].parse().expect("a triangle number");
    (first, second)
}

#[test]
fn a_sphere_s_integrals_are_the_same_bits_on_one_two_and_three_threads() {
    // 70,224 triangles: three chunks of the integrals, the last partial.
    let t = sphere(133, 0.05, [0.01, -0.02, 0.03]);
    assert!(t.len() > 2 * (1 << 15), "{}", t.len());
    let (body, _) = same_on_every_thread_count(&stl(&t)).expect("a closed sphere");
    // Its volume within the tessellation's reach of 4/3 π r³ (a check that
    // the sums were taken at all, not of their accuracy).
    let v = 4.0 / 3.0 * std::f64::consts::PI * 0.05f64.powi(3);
    assert!((body.measure.hi - v).abs() < 1e-3 * v, "{:?}", body.measure);
}

#[test]
fn an_ascii_sphere_reads_the_same_on_one_two_and_three_threads() {
    let t = sphere(40, 3.0, [100.0, 0.0, 0.0]);
    same_on_every_thread_count(&ascii(&t)).expect("a closed sphere");
}

#[test]
fn hollow_cubes_with_cavities_are_the_same_bits_on_one_two_and_three_threads() {
    // 1,331 cubes each with an inward cube inside: 2,662 shells, windings
    // and volumes judged per shell on every thread.
    let mut t = Vec::new();
    for c in grid(11) {
        let lo = c[0][0];
        t.extend(c);
        t.extend(cube(lo.map(|x| x + 0.25), 0.5, true));
    }
    let (body, _) = same_on_every_thread_count(&stl(&t)).expect("hollow cubes");
    assert_eq!(body.measure.hi, 1331.0 * 0.875);
}

#[test]
fn a_zero_area_triangle_s_warning_is_the_same_on_every_thread_count() {
    // A zero-area triangle (three corners on a line) in the second half:
    // left out with a warning naming it, on every thread count.
    let mut t: Vec<Tri> = grid(6).concat();
    let at = t.len() * 2 / 3;
    t.insert(at, [[0.0; 3], [0.5, 0.0, 0.0], [1.0, 0.0, 0.0]]);
    let (_, warnings) = same_on_every_thread_count(&stl(&t)).expect("left out");
    let named = format!("triangle {} ", at + 1);
    assert!(warnings.iter().any(|w| w.contains(&named)), "{warnings:?}");
}

/// The cubes of a 10 × 10 × 10 grid with one more cube, shifted half a
/// side from grid cube `of` so that their surfaces cross, put in the
/// file's order before cube `at`: the crossing's triangles.
fn with_intruder(
    of: usize,
    at: usize,
) -> (Vec<Tri>, std::ops::Range<usize>, std::ops::Range<usize>) {
    let mut cubes = grid(10);
    let lo = cubes[of][0][0];
    let intruder = cube(lo.map(|x| x + 0.5), 1.0, false);
    cubes.insert(at, intruder);
    let of = if at <= of { of + 1 } else { of };
    let range = |c: usize| 12 * c + 1..12 * c + 13;
    (cubes.concat(), range(of), range(at))
}

#[test]
fn a_crossing_is_found_wherever_it_lies_on_one_two_and_three_threads() {
    // First and last in the file, far apart in space and file, across the
    // borders of two and of three threads' shares (12,012 triangles: 6,006
    // and 4,004), and in the middle of the grid.
    let n = 1001 * 12;
    for (of, at) in [
        (0, 0),
        (999, 1000),
        (0, 1000),
        (999, 0),
        (500, n / 2 / 12),
        (333, n / 3 / 12),
        (555, 2 * n / 3 / 12),
        (123, 700),
    ] {
        let (t, a, b) = with_intruder(of, at);
        assert_eq!(t.len(), n);
        let e = same_on_every_thread_count(&stl(&t)).expect_err("the cubes cross");
        let (i, j) = crossing_pair(&e);
        let (lo, hi) = if a.start < b.start { (a, b) } else { (b, a) };
        assert!(lo.contains(&i) && hi.contains(&j), "({of}, {at}): {e}");
    }
}

#[test]
fn the_earlier_of_two_crossings_is_named_on_every_thread_count() {
    // Two intruders: one crossing cube 900 late in the file, one crossing
    // cube 100 early; the crossing whose first triangle comes first in
    // the file is the one named, however the threads share the work.
    let mut cubes = grid(10);
    let shift = |c: &Vec<Tri>| cube(c[0][0].map(|x| x + 0.5), 1.0, false);
    let (late, early) = (shift(&cubes[900]), shift(&cubes[100]));
    cubes.push(early);
    cubes.insert(950, late);
    let t = cubes.concat();
    let e = same_on_every_thread_count(&stl(&t)).expect_err("the cubes cross");
    let (i, j) = crossing_pair(&e);
    assert!((12 * 100 + 1..12 * 100 + 13).contains(&i), "{e}");
    assert!(j > 12 * 1001, "{e}");
}

#[test]
fn a_pole_fan_folded_over_is_refused_on_every_thread_count() {
    // A sphere of 80,000 triangles (its corners' stars tiled on a thread
    // of their own) with two neighbouring corners of the north pole's fan
    // swapped: that fan folds over itself, so two of its triangles that
    // share only the pole cross (their far edges cross, seen from above).
    let t = sphere(200, 1.0, [0.0; 3]);
    assert!(t.len() > 1 << 16);
    let ring = |j: f64| {
        let (th, ph) = (
            std::f64::consts::PI / 200.0,
            std::f64::consts::PI * j / 200.0,
        );
        [th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]
    };
    let (a, b) = (ring(0.0), ring(1.0));
    let swapped: Vec<Tri> = t
        .iter()
        .map(|f| {
            f.map(|p| {
                if p == a {
                    b
                } else if p == b {
                    a
                } else {
                    p
                }
            })
        })
        .collect();
    assert_ne!(swapped, t, "the two corners are the sphere's");
    let e = same_on_every_thread_count(&stl(&swapped)).expect_err("the fan crosses itself");
    crossing_pair(&e);
    assert!(e.contains("the surface intersects itself"), "{e}");
    // Unswapped, it is a sphere.
    assert!(same_on_every_thread_count(&stl(&t)).is_ok());
}
