//! The ASCII STL read in pieces (`ascii_stl_on`) against the one-piece
//! reading: the same triangles, or the same error at the same line,
//! whatever the number of pieces, on valid and broken files.

use super::*;
use proptest::prelude::*;

/// A reading's outcome in a form that compares exactly (the corners'
/// bits).
type Outcome = Result<(Vec<[u64; 3]>, Vec<[u32; 3]>, Vec<At>), (At, String)>;

fn outcome(r: Result<Triangles, MeshError>) -> Outcome {
    r.map(|t| {
        (
            t.points.iter().map(|p| p.map(f64::to_bits)).collect(),
            t.faces,
            t.at,
        )
    })
    .map_err(|e| (e.at, e.message))
}

/// The lines of an ASCII STL of `n` facets.
fn facets(n: usize) -> Vec<String> {
    let mut out = vec!["solid s".to_string()];
    for i in 0..n {
        let x = i as f64 * 0.25;
        out.push("facet normal 0 0 1".into());
        out.push("  outer loop".into());
        for v in [[x, 0.0, 1.0], [x + 1.0, 0.5, -2.0], [x, 1.5, 0.125]] {
            out.push(format!("    vertex {} {} {}", v[0], v[1], v[2]));
        }
        out.push("  endloop".into());
        out.push("endfacet".into());
    }
    out.push("endsolid s".into());
    out
}

/// Lines a broken file may hold where a good one holds another.
const ODD: [&str; 12] = [
    "facet normal 0 0 0",
    "FACET NORMAL 1 2 3",
    "endfacet",
    "outer loop",
    "endloop",
    "vertex 1 2",
    "vertex 1 2 x",
    "vertex 0.5 0.25 1e3",
    "",
    "solid t",
    "endsolid t",
    "bogus",
];

fn same_on_every_cut(bytes: &[u8], limit: usize) -> Result<(), TestCaseError> {
    let want = outcome(ascii_stl(bytes, limit));
    for threads in [2, 3, 7, 40] {
        let got = outcome(ascii_stl_on(bytes, limit, threads));
        prop_assert_eq!(&got, &want, "{} threads", threads);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn a_file_read_in_pieces_reads_as_in_one(
        n in 0usize..30,
        edits in proptest::collection::vec((any::<proptest::sample::Index>(), 0usize..ODD.len(), 0u8..3), 0..4),
        limit in prop_oneof![Just(usize::MAX), 1usize..12],
        crlf in any::<bool>(),
    ) {
        let mut lines = facets(n);
        for (at, odd, how) in edits {
            let i = at.index(lines.len());
            match how {
                0 => lines[i] = ODD[odd].to_string(),
                1 => lines.insert(i, ODD[odd].to_string()),
                _ => {
                    lines.remove(i);
                    if lines.is_empty() {
                        lines.push(String::new());
                    }
                }
            }
        }
        let text = lines.join(if crlf { "\r\n" } else { "\n" });
        same_on_every_cut(text.as_bytes(), limit)?;
        same_on_every_cut(format!("{text}\n").as_bytes(), limit)?;
    }
}

#[test]
fn a_piece_that_ends_inside_a_facet_is_refused_at_the_next_facet_line() {
    // Facet 2 lacks its `endfacet`: the one-piece reading refuses facet
    // 3's first line (a `facet` inside a facet), wherever the cuts fall:
    // line 1 + 2 · 7 + 1 = 16 of the whole file, 15 with a line removed.
    let mut lines = facets(6);
    let drop = 1 + 7 + 6;
    assert_eq!(lines[drop], "endfacet");
    lines.remove(drop);
    let text = lines.join("\n");
    let want = outcome(ascii_stl(text.as_bytes(), usize::MAX));
    assert_eq!(
        want,
        Err((
            At::Line(15),
            "unexpected `facet` in an ASCII STL (expected `facet`, `outer loop`, `vertex`, `endloop`, `endfacet`, `solid` or `endsolid`)".to_string()
        ))
    );
    for threads in 2..12 {
        assert_eq!(
            outcome(ascii_stl_on(text.as_bytes(), usize::MAX, threads)),
            want
        );
    }
}

#[test]
fn the_limit_is_met_at_the_same_facet_in_pieces() {
    let text = facets(50).join("\n");
    let want = outcome(ascii_stl(text.as_bytes(), 17));
    assert!(matches!(&want, Err((At::Line(_), m)) if m.contains("more than 17")));
    for threads in 2..9 {
        assert_eq!(outcome(ascii_stl_on(text.as_bytes(), 17, threads)), want);
    }
}

#[test]
fn the_cuts_fall_on_facet_lines() {
    let text = facets(40).join("\n");
    let cuts = facet_cuts(text.as_bytes(), 5);
    assert_eq!(cuts.len(), 6);
    for c in &cuts[1..5] {
        assert!(text[*c..].starts_with("facet"), "{c}");
    }
}

#[test]
fn a_file_read_in_pieces_is_the_file() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    for len in [0usize, 1, 2, 3, 1000, 1 << 20] {
        let bytes: Vec<u8> = (0..len).map(|i| (i * 7 + i / 251) as u8).collect();
        let path = dir.path().join(format!("m{len}.stl"));
        std::fs::write(&path, &bytes).expect("written");
        for threads in [1, 2, 3] {
            let got = crate::mesh::with_threads(threads, || file(&path)).expect("read");
            assert_eq!(got, bytes, "{len} bytes, {threads} threads");
        }
    }
    let missing = dir.path().join("none.stl");
    let e = crate::mesh::with_threads(2, || file(&missing)).expect_err("no file");
    assert_eq!(e.kind(), std::io::ErrorKind::NotFound);
}
