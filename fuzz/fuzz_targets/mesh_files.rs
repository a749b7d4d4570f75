//! Fuzz the mesh readers, checks and integrals (`mesh::MeshBody::load`):
//! any bytes, read as STL (binary or ASCII, by its size and first word)
//! and as OBJ, in both modes, are either refused with a message that names
//! where (a line, a byte, a triangle), or give a body whose measure is
//! positive and finite, whose centroid, second moment and bounds are
//! finite, and whose second moment is symmetric with a non-negative
//! diagonal to its bound. Panics, hangs and out-of-memory are the
//! findings.
//!
//! Shells (issue 28): the same bytes also read as a list of boxes (7
//! bytes each: a corner and sizes on a small grid, and whether it is wound
//! inward), some corners nudged, written as one OBJ: any mix of disjoint,
//! touching, overlapping, nested and inside-out pieces. Every accepted
//! solid has a positive volume, and when the boxes are wound outward and
//! pairwise disjoint (the generator knows) it is accepted and weighs their
//! sum.
//!
//! `weld` (issue 30): the same bytes are read again as a solid with
//! corners closer than a distance the bytes choose merged first (a part's
//! `weld = "…"`): refused in words, or a body of positive, finite volume
//! whose bounds are finite, with the weld's note first among the
//! warnings. Disjoint outward boxes are half a unit apart at least, so a
//! weld below that merges nothing and weighs what the boxes do.
#![no_main]

use libfuzzer_sys::fuzz_target;
use massprop::mesh::{At, FileType, MeshBody, Mode};

type Box3 = ([f64; 3], [f64; 3], bool);

/// Boxes from the bytes: corner 0..16 and size 1..8 on a grid of halves,
/// the high bit of the seventh byte inward, its low bits a nudge of one
/// corner of the box by a quarter (so faces can fold or tilt).
fn boxes(data: &[u8]) -> Vec<(Box3, u8)> {
    data.chunks_exact(7)
        .take(12)
        .map(|c| {
            let lo = [0, 1, 2].map(|k| f64::from(c[k] % 32) / 2.0);
            let size = [3, 4, 5].map(|k| f64::from(c[k] % 16 + 1) / 2.0);
            ((lo, size, c[6] & 0x80 != 0), c[6] & 0x7f)
        })
        .collect()
}

fn box_obj(list: &[(Box3, u8)]) -> String {
    let mut v = String::new();
    let mut f = String::new();
    for (n, ((lo, s, inward), nudge)) in list.iter().enumerate() {
        for i in 0..8usize {
            let mut p: [f64; 3] =
                std::array::from_fn(|k| lo[k] + if i >> k & 1 == 1 { s[k] } else { 0.0 });
            if usize::from(nudge & 7) == i && nudge & 8 != 0 {
                p[usize::from(nudge >> 4) % 3] += 0.25;
            }
            v.push_str(&format!("v {} {} {}\n", p[0], p[1], p[2]));
        }
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        for q in quads {
            for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
                let t = if *inward { [t[0], t[2], t[1]] } else { t };
                f.push_str(&format!(
                    "f {} {} {}\n",
                    8 * n + t[0] + 1,
                    8 * n + t[1] + 1,
                    8 * n + t[2] + 1
                ));
            }
        }
    }
    v + &f
}

fn disjoint(a: &Box3, b: &Box3) -> bool {
    // Apart by a gap (touching may weld corners into shared edges).
    (0..3).any(|k| a.0[k] + a.1[k] < b.0[k] || b.0[k] + b.1[k] < a.0[k])
}

fn shells(data: &[u8]) {
    let list = boxes(data);
    if list.is_empty() {
        return;
    }
    let text = box_obj(&list);
    let result = MeshBody::load(FileType::Obj, text.as_bytes(), Mode::Solid);
    if let Ok(m) = &result {
        assert!(
            m.measure.hi > 0.0,
            "an accepted solid has a positive volume"
        );
    }
    let plain = list
        .iter()
        .all(|((_, _, inward), nudge)| !inward && nudge & 8 == 0);
    let apart = (0..list.len()).all(|i| (0..i).all(|j| disjoint(&list[i].0, &list[j].0)));
    if plain && apart {
        let m = result.expect("outward disjoint boxes are one solid");
        let sum: f64 = list.iter().map(|((_, s, _), _)| s[0] * s[1] * s[2]).sum();
        let v = m.measure.hi + m.measure.lo;
        assert!((v - sum).abs() <= 1e-12 * sum, "{v} against {sum}");
        // A weld closer than the boxes' gaps (half a unit at least)
        // merges no corner of two boxes, nor of one (sizes ≥ ½).
        let (w, notes) =
            MeshBody::load_with(FileType::Obj, text.as_bytes(), Mode::Solid, Some(0.1))
                .expect("a weld closer than every gap changes nothing");
        assert!(notes[0].starts_with("`weld` merged 0 corners"), "{notes:?}");
        let vw = w.measure.hi + w.measure.lo;
        assert!((vw - sum).abs() <= 1e-12 * sum, "{vw} against {sum}");
    }
}

/// The weld distance the bytes choose: from 2⁻⁴⁰ to 2⁷ of the file's
/// units (the last byte's bits), so that it merges nothing, some corners
/// or whole triangles.
fn weld_distance(data: &[u8]) -> Option<f64> {
    let b = *data.last()?;
    Some(2f64.powi(i32::from(b % 48) - 40))
}

/// `data` read as a welded solid, in each format.
fn welded(data: &[u8]) {
    let Some(d) = weld_distance(data) else {
        return;
    };
    for format in [FileType::Stl, FileType::Obj] {
        match MeshBody::load_with(format, data, Mode::Solid, Some(d)) {
            Err(e) => assert!(!e.message.is_empty()),
            Ok((m, notes)) => {
                assert!(
                    notes
                        .first()
                        .is_some_and(|n| n.starts_with("`weld` merged ")),
                    "{notes:?}"
                );
                let v = m.measure.hi + m.measure.lo;
                if !(v > 0.0 && v.is_finite()) {
                    continue;
                }
                // A weld that could change the volume by half is refused.
                assert!(
                    m.bound.measure <= v.abs() / 2.0 * (1.0 + 1e-12),
                    "{:?}",
                    m.bound
                );
                assert!(m.bound.centroid >= 0.0 && m.bound.second >= 0.0);
            }
        }
    }
}

fuzz_target!(|data: &[u8]| {
    shells(data);
    welded(data);
    for format in [FileType::Stl, FileType::Obj] {
        for mode in [Mode::Solid, Mode::Shell] {
            match MeshBody::load(format, data, mode) {
                Err(e) => {
                    assert!(!e.message.is_empty());
                    if let At::Line(n) = e.at {
                        assert!(n >= 1 && n <= data.len() + 1);
                    }
                    if let At::Byte(b) = e.at {
                        assert!(b as usize <= data.len());
                    }
                }
                Ok(m) => {
                    let v = m.measure.hi + m.measure.lo;
                    if !(v > 0.0 && v.is_finite()) {
                        // Overflowing sums of huge coordinates: refused
                        // by the model's range checks, never a panic.
                        continue;
                    }
                    for i in 0..3 {
                        for j in 0..3 {
                            let (a, b) = (m.second[i][j].hi, m.second[j][i].hi);
                            assert!(a == b || a.is_nan() && b.is_nan());
                        }
                        let d = m.second[i][i].hi;
                        assert!(!(d < -m.bound.second), "{d} {:?}", m.bound);
                    }
                }
            }
        }
    }
});
