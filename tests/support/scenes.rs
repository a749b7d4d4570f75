//! The stress scenes of docs/accuracy.md, shared by the benchmark
//! (benches/compose.rs) and the accuracy table (examples/accuracy.rs). They
//! are built with the exact reference's scene description
//! ([`super::reference`]), so each can be written as a part file and
//! composed exactly.

use super::reference::{Amount, Length, Mass, Part, Scene};

/// A stress scene: a short name for tables and what it stresses.
pub struct Named {
    pub name: &'static str,
    pub what: &'static str,
    pub scene: Scene,
}

/// splitmix64: a fixed-seed generator, so every run sees the same scenes.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }

    /// In [−s, s]³ on a grid of s·2⁻²⁰, so offsets below 2³² s stay exact.
    pub fn point(&mut self, s: f64) -> [f64; 3] {
        std::array::from_fn(|_| (self.range(-1.0, 1.0) * 1048576.0).round() / 1048576.0 * s)
    }

    /// A unit quaternion in a uniformly random direction.
    pub fn quaternion(&mut self) -> [f64; 4] {
        loop {
            let q: [f64; 4] = std::array::from_fn(|_| self.range(-1.0, 1.0));
            let n2: f64 = q.iter().map(|x| x * x).sum();
            if (0.04..=1.0).contains(&n2) {
                let n = n2.sqrt();
                return q.map(|x| x / n);
            }
        }
    }
}

/// Twelve boxes of sizes 0.2–1 m in random orientations, the whole offset
/// by `offset` times (1, −2, 3)/√14 (so |offset| part sizes).
fn twelve_boxes(offset: f64) -> Scene {
    let mut rng = Rng::new(12);
    let dir = [1.0, -2.0, 3.0].map(|x: f64| x / 14f64.sqrt());
    // The offset on a grid coarse enough that centre + offset is exact.
    let shift = dir.map(|d| (d * offset).round());
    let parts = (0..12)
        .map(|_| {
            let size = std::array::from_fn(|_| rng.range(0.2, 1.0));
            let p = rng.point(2.0);
            let center = std::array::from_fn(|i| p[i] + shift[i]);
            Part::cuboid(
                size,
                center,
                Some(rng.quaternion()),
                Amount::Density(rng.range(1000.0, 8000.0)),
            )
        })
        .collect();
    Scene::si(parts)
}

fn one_box(size: [f64; 3], seed: u64) -> Scene {
    let mut rng = Rng::new(seed);
    Scene::si(vec![Part::cuboid(
        size,
        rng.point(1.0),
        Some(rng.quaternion()),
        Amount::Mass(1.0),
    )])
}

/// A heavy box and light points around it: masses 1e6 and 1e-6 kg.
fn mass_ratio() -> Scene {
    let mut rng = Rng::new(7);
    let mut parts = vec![Part::cuboid(
        [2.0, 1.0, 0.5],
        [0.0; 3],
        Some(rng.quaternion()),
        Amount::Mass(1e6),
    )];
    for _ in 0..6 {
        parts.push(Part::point(1e-6, rng.point(1e3)));
    }
    Scene::si(parts)
}

/// The twelve boxes, 10⁶ sizes out, written in micrometres and milligrams.
fn micro_units() -> Scene {
    let mut s = twelve_boxes(1e6);
    s.length = Length::Um;
    s.mass = Mass::Mg;
    // Same numbers, now in µm and mg: densities in mg/µm³ scaled to stay
    // physical (1000–8000 kg/m³ is 1e-9–8e-9 mg/µm³).
    for p in &mut s.parts {
        if let Amount::Density(d) = &mut p.amount {
            *d *= 1e-12;
        }
    }
    s
}

/// The stress scenes of the table, and the others the accuracy
/// tests cover.
pub fn stress() -> Vec<Named> {
    vec![
        Named {
            name: "offset 1e6",
            what: "12 boxes, random orientations, 10⁶ part sizes from the origin",
            scene: twelve_boxes(1e6),
        },
        Named {
            name: "offset 1e9",
            what: "the same, 10⁹ part sizes from the origin",
            scene: twelve_boxes(1e9),
        },
        Named {
            name: "slender 1e-6",
            what: "box 10⁻⁶ × 10⁻⁶ × 1, random orientation",
            scene: one_box([1e-6, 1e-6, 1.0], 61),
        },
        Named {
            name: "slender 1e-9",
            what: "box 10⁻⁹ × 10⁻⁹ × 1, random orientation",
            scene: one_box([1e-9, 1e-9, 1.0], 91),
        },
        Named {
            name: "flat 1e-9",
            what: "box 1 × 1 × 10⁻⁹, random orientation",
            scene: one_box([1.0, 1.0, 1e-9], 92),
        },
        Named {
            name: "near-equal 1e-8",
            what: "box 1 × (1 + 10⁻⁸) × 0.5: two moments 10⁻⁸ apart",
            scene: one_box([1.0, 1.0 + 1e-8, 0.5], 8),
        },
        Named {
            name: "mass ratio 1e12",
            what: "a 10⁶ kg box and six 10⁻⁶ kg points up to 1 km away",
            scene: mass_ratio(),
        },
        Named {
            name: "µm and mg",
            what: "the 10⁶ offset scene written in micrometres and milligrams",
            scene: micro_units(),
        },
    ]
}

/// An assembly of `n` parts of every shape and placement: boxes, plates and
/// rods in random orientations (centre and quaternion, or corner and edges,
/// or from/to), points, masses and densities, spread over a 10 m cube.
pub fn assembly(n: usize) -> Scene {
    let mut rng = Rng::new(100_000);
    let parts = (0..n)
        .map(|i| {
            let c = rng.point(5.0);
            let q = Some(rng.quaternion());
            match i % 6 {
                0 => Part::cuboid(
                    std::array::from_fn(|_| rng.range(0.01, 0.2)),
                    c,
                    q,
                    Amount::Density(rng.range(1000.0, 8000.0)),
                ),
                1 => Part::plate(
                    [rng.range(0.05, 0.3), rng.range(0.05, 0.3)],
                    c,
                    q,
                    Amount::Density(rng.range(5.0, 40.0)),
                ),
                2 => Part::rod(
                    rng.range(0.1, 1.0),
                    c,
                    q,
                    Amount::Mass(rng.range(0.01, 1.0)),
                ),
                3 => Part::point(rng.range(0.001, 0.5), c),
                4 => {
                    // Integer edge directions, exactly perpendicular.
                    let s = rng.range(0.01, 0.1);
                    let e = [[2.0, 1.0, 2.0], [1.0, 2.0, -2.0], [2.0, -2.0, -1.0]]
                        .map(|v| v.map(|x| x * s));
                    Part::box_edges(c, e, Amount::Mass(rng.range(0.1, 2.0)))
                }
                _ => {
                    let d = rng.point(0.5);
                    Part::rod_from_to(
                        c,
                        std::array::from_fn(|k| c[k] + d[k]),
                        Amount::Density(rng.range(0.1, 2.0)),
                    )
                }
            }
        })
        .collect();
    Scene::si(parts)
}
