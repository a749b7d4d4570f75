//! The walk's work per copy, counted without a clock (issue 28, item 6):
//! copies in one place (an array's step or turn of zero) come from a walk
//! of runs (`Model::each_run`, the drawing's walks) as a count after the
//! first, whatever their number, and every other copy one by one; what it
//! hands out and counts is, part for part, what a walk of events hands
//! out. A coincident copy, not placed again but kept from the copy before
//! it, is to the bit the copy a file of two copies places afresh.

use crate::common::scratch_files;
use massprop::diag::Source;
use massprop::model::walk::Run;
use massprop::model::{Event, Model};

fn model(text: &str) -> Model {
    Model::parse(&Source::new("f.toml", text)).unwrap_or_else(|d| panic!("{d}\n{text}"))
}

/// `file` (with `sub.toml` beside it) read from disk, so that it may
/// include.
fn model_with_sub(name: &str, file: &str, sub: &str) -> Model {
    let path = scratch_files(
        "copies_walk",
        name,
        &[("sub.toml", sub), ("main.toml", file)],
    );
    let source = Source::new(path.display().to_string(), file).read_from(path);
    Model::parse(&source).unwrap_or_else(|d| panic!("{d}\n{file}"))
}

/// A part `body` (its keys, without `array` or `mirror`) with `copies`.
fn part(body: &str, copies: &str) -> String {
    format!("[[part]]\n{body}\n{copies}\n")
}

/// Each part a walk of events meets: its index and the part to the bit
/// (Debug writes each float's shortest exact form).
fn events(m: &Model) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    m.each_event(&mut |e| {
        if let Event::Part(l) = e {
            out.push((l.index, format!("{:?}", l.part)));
        }
    });
    out
}

/// What a walk of runs meets: the parts handed out (as `events`), and
/// each count with the index of the part it follows.
struct Runs {
    parts: Vec<(usize, String)>,
    counts: Vec<(usize, usize)>,
}

fn runs(m: &Model) -> Runs {
    let mut r = Runs {
        parts: Vec::new(),
        counts: Vec::new(),
    };
    m.each_run(&mut |run| match run {
        Run::Event(Event::Part(l)) => r.parts.push((l.index, format!("{:?}", l.part))),
        Run::Event(Event::Enter(_) | Event::Exit) => {}
        Run::Again(n) => {
            let last = r.parts.last().expect("a count follows a part").0;
            r.counts.push((last, n));
        }
    });
    r
}

/// The walk of runs spelt out: each count as that many copies of the
/// part before it, at the indices that follow.
fn expanded(r: &Runs) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut counts = r.counts.iter().peekable();
    for (index, part) in &r.parts {
        out.push((*index, part.clone()));
        while let Some((_, n)) = counts.next_if(|(after, _)| after == index) {
            out.extend((1..=*n).map(|k| (index + k, part.clone())));
        }
    }
    out
}

const BOX: &str = "shape = \"box\"\nmass = 1\nsize = [0.1, 0.2, 0.3]\ncenter = [0, 0, 0]";

#[test]
fn two_million_copies_in_one_place_are_two_parts_and_a_count() {
    let m = model(&part(BOX, "array = { count = 2000000, step = [0, 0, 0] }"));
    let r = runs(&m);
    // Copy 0 as written, copy 1 placed by its frame, then the rest.
    assert_eq!(r.parts.len(), 2);
    assert_eq!(r.counts, vec![(1, 1_999_998)]);
}

#[test]
fn the_images_of_coincident_copies_are_a_second_run() {
    let m = model(&part(
        BOX,
        "array = { count = 1000, step = [0, -0.0, 0] }\nmirror = { normal = [1, 1, 0] }",
    ));
    let r = runs(&m);
    let indices: Vec<usize> = r.parts.iter().map(|p| p.0).collect();
    assert_eq!(indices, vec![0, 1, 1000, 1001]);
    assert_eq!(r.counts, vec![(1, 998), (1001, 998)]);
}

#[test]
fn copies_turned_by_zero_degrees_are_one_run() {
    let m = model(&part(
        "shape = \"rod\"\nmass = 1\nfrom = [1, 0, 0]\nto = [2, 0, 0]",
        "array = { count = 500, axis = [0, 0, 1], step_degrees = 0, origin = [0, 1, 0] }",
    ));
    let r = runs(&m);
    assert_eq!(r.parts.len(), 2);
    assert_eq!(r.counts, vec![(1, 498)]);
}

#[test]
fn copies_along_a_step_are_each_handed_out() {
    for copies in [
        "array = { count = 300, step = [1e-9, 0, 0] }",
        "array = { count = 300, axis = [0, 0, 1], step_degrees = 1.2 }",
        "array = { count = 150, step = [0, 0, 2] }\nmirror = { normal = [0, 0, 1] }",
    ] {
        let m = model(&part(BOX, copies));
        let r = runs(&m);
        assert_eq!(r.parts.len(), 300, "{copies}");
        assert!(r.counts.is_empty(), "{copies}");
    }
}

/// Parts of every kind of placement, each with coincident copies, and a
/// sub-assembly with copies (each copy of it walked whole).
fn assembly() -> Model {
    let sub = concat!(
        "[[part]]\nname = \"pin\"\nshape = \"cylinder\"\nmass = 0.2\nradius = 0.01\nlength = 0.1\n",
        "center = [0.1, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 30 }\n",
        "array = { count = 4, step = [0, 0, 0] }\n",
        "[[part]]\nname = \"tip\"\nshape = \"point\"\nmass = 0.1\ncenter = [0, 0.2, 0]\n",
    );
    let mut file = String::from("units = { length = \"mm\", mass = \"kg\" }\n");
    for (body, copies) in [
        (
            "name = \"stack\"\nshape = \"box\"\nmass = 1\nsize = [10, 20, 30]\ncenter = [5, -0.0, 7]\nrotation = { axis = [1, 1, 0], degrees = 30 }",
            "array = { count = 6, step = [0, -0.0, 0] }\nmirror = { normal = [1, 0, 1], origin = [1, 2, 3] }",
        ),
        (
            "shape = \"cone\"\ndensity = 7.8e-6\nradius = 10\ntop_radius = 2\nlength = 30\ncenter = [40, 0, 0]",
            "array = { count = 5, axis = [0, 0, 1], step_degrees = 0, origin = [1, 0, 0] }",
        ),
        (
            "shape = \"rod\"\nmass = 0.1\nfrom = [0, 0, 0]\nto = [0, 0, 100]",
            "array = { count = 3, step = [0, 0, 0] }",
        ),
        (
            "shape = \"triangle\"\nmass = 0.1\nvertices = [[0, 0, 0], [10, 0, 0], [0, 10, 5]]",
            "array = { count = 4, step = [0, 0, 0] }\nmirror = { normal = [0, 1, 0] }",
        ),
        (
            "name = \"arm\"\ninclude = \"sub.toml\"\norigin = [0, 0, 200]\nrotation = { axis = [0, 1, 0], degrees = 10 }",
            "array = { count = 3, step = [0, 0, 0] }\nmirror = { normal = [0, 0, 1] }",
        ),
        (
            "shape = \"sphere\"\nmass = 0.5\nradius = 3\ncenter = [1, 1, 1]",
            "array = { count = 3, step = [4, 0, 0] }",
        ),
    ] {
        file.push_str(&part(body, copies));
    }
    model_with_sub("assembly", &file, sub)
}

#[test]
fn a_walk_of_runs_hands_out_and_counts_what_a_walk_of_events_meets() {
    let m = assembly();
    let r = runs(&m);
    assert!(!r.counts.is_empty(), "the fixture has coincident copies");
    assert!(r.parts.len() < m.count, "the counts stand for parts");
    assert_eq!(expanded(&r), events(&m));
    assert_eq!(expanded(&r).len(), m.count);
}

/// Copy `k`'s numbers (its `spec`), to the bit, as a walk of events places
/// it.
fn spec(m: &Model, k: usize) -> String {
    format!("{:?}", m.part(k).expect("the copy").spec)
}

#[test]
fn a_coincident_copy_kept_from_the_last_is_the_copy_placed_afresh() {
    for body in [
        "shape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [5, -0.0, 7]\nrotation = { axis = [1, 1, 0], degrees = 30 }",
        "shape = \"cone\"\ndensity = 7.8\nradius = 1\ntop_radius = 0.2\nlength = 3\ncenter = [4, 0, 0]",
        "shape = \"rod\"\nmass = 0.1\nfrom = [0, 0.5, 0]\nto = [0, 0, 1]",
        "shape = \"plate\"\nmass = 0.1\ncorner = [0, 0, 1]\nedges = [[1, 0, 0], [0, 2, 0]]",
    ] {
        for (pattern, mirror) in [
            ("step = [0, 0, 0]", ""),
            ("axis = [0, 1, 1], step_degrees = 0, origin = [1, 2, 3]", ""),
            (
                "step = [0, -0.0, 0]",
                "mirror = { normal = [1, 0, 1], origin = [0, 1, 0] }",
            ),
        ] {
            let copies = |n: usize| format!("array = {{ count = {n}, {pattern} }}\n{mirror}");
            let many = model(&part(body, &copies(40)));
            // Two copies: copy 1 (and its image, copy 3) placed afresh.
            let two = model(&part(body, &copies(2)));
            let images = usize::from(!mirror.is_empty());
            for k in 1..40 {
                assert_eq!(spec(&many, k), spec(&two, 1), "copy {k}: {body}, {pattern}");
                if images == 1 {
                    assert_eq!(spec(&many, 40 + k), spec(&two, 3), "image {k}: {body}");
                }
            }
        }
    }
}

#[test]
fn a_copy_along_a_step_moved_from_the_last_is_the_copy_placed_afresh() {
    // Copy k of a step of 0.5 is moved by k·0.5, exact: copy 1 of a step
    // of k·0.5, placed by a frame made for it alone.
    let body = "shape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [5, -0.0, 7]\nrotation = { axis = [1, 1, 0], degrees = 30 }";
    let many = model(&part(body, "array = { count = 9, step = [0.5, 0, -0.5] }"));
    for k in 1..9 {
        let s = 0.5 * k as f64;
        let one = model(&part(
            body,
            &format!("array = {{ count = 2, step = [{s}, 0, -{s}] }}"),
        ));
        assert_eq!(spec(&many, k), spec(&one, 1), "copy {k}");
    }
}

/// Each sub-assembly's row as bits: its name, parts, mass, mass share,
/// centre and shares (`None` apart from every float).
fn assembly_bits(
    rows: impl FnOnce(&mut dyn FnMut(massprop::analysis::summary::AssemblyRow<'_>)),
) -> Vec<(String, usize, Vec<Option<u64>>)> {
    use massprop::analysis::summary::AssemblyRow;
    let mut out = Vec::new();
    rows(&mut |r| {
        if let AssemblyRow::Enter(name, a) = r {
            let mut bits = vec![Some(a.mass.to_bits()), Some(a.mass_fraction.to_bits())];
            bits.extend(a.center_of_mass.iter().map(|x| Some(x.to_bits())));
            bits.extend(a.principal_moment_share.iter().map(|x| x.map(f64::to_bits)));
            out.push((name.to_string(), a.parts, bits));
        }
    });
    out
}

#[test]
fn sub_assemblies_summed_from_the_parts_rows_are_the_walk_s_to_the_bit() {
    // The `--full` report sums the sub-assemblies from its parts table's
    // rows (`Summing` fed by `Parts::each_row`), not from a walk of its
    // own (`Assemblies::summed`): the same rows, bit for bit. Copies of a
    // sub-assembly turned, arrayed and mirrored, far from the origin,
    // beside a part of the body's own.
    use massprop::analysis::Products;
    use massprop::analysis::summary::{Accuracy, Row, Summing, summarize};
    let sub = "[[part]]\nname = \"a\"\nshape = \"box\"\nmass = 1.3\nsize = [0.1, 0.2, 0.3]\ncenter = [0.7, -0.1, 0.2]\n\
               [[part]]\nshape = \"rod\"\nmass = 0.21\nfrom = [0, 0, 0]\nto = [0.3, 0.1, -0.4]\narray = { count = 3, step = [0.01, 0.3, 0] }\n";
    let file = "[[part]]\ninclude = \"sub.toml\"\norigin = [1, 2, 3]\nrotation = { axis = [1, 1, 0], degrees = 33 }\n\
                array = { count = 4, step = [0.5, 0, 0.1] }\n\
                [[part]]\ninclude = \"sub.toml\"\norigin = [-1e3, 0.25, 7]\nmirror = { normal = [1, 0, 0], origin = [0.5, 0, 0] }\n\
                [[part]]\nshape = \"sphere\"\nmass = 2.5\nradius = 0.4\ncenter = [0.3, 0.3, 0.3]\n";
    let m = model_with_sub("summed", file, sub);
    let s = summarize(&m, &m.analysis, Products::Tensor, &Accuracy::default()).expect("a body");
    let mut summing = Summing::default();
    s.parts.each_row(&mut |r| match r {
        Row::Enter(_) => summing.enter(),
        Row::Part(p) => summing.part(p.mass, p.center_of_mass, p.principal_moment_share),
        Row::Exit => summing.exit(),
    });
    let from_rows = s.assemblies.summed_from(summing);
    let walked = s.assemblies.summed();
    let want = assembly_bits(|f| walked.each_row(f));
    assert_eq!(want.len(), 6, "{want:?}");
    assert_eq!(assembly_bits(|f| from_rows.each_row(f)), want);
}
