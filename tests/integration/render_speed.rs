//! `render`'s work cut (issue 33, item 4) without its drawing moving: a
//! part the walk meets once is written at once, only copies of one part
//! are compared by their text (`Drawn`), and the views are drawn two at a
//! time. Copies in one place, or closer to it than the drawing's
//! resolution (0.01 px), are drawn once per view and counted; copies
//! apart, and parts written apart in one place, are each drawn; and one
//! thread and two write the same document, byte for byte.

use crate::common::scratch_files;
use massprop::analysis::Settings;
use massprop::commands::robot::{Configuration, load_any};
use massprop::output::drawing::{self, View};

/// `main.toml` (with the other files beside it) drawn on `threads`
/// threads, all four views or `view`.
fn draw(name: &str, files: &[(&str, &str)], threads: usize, view: Option<View>) -> String {
    let path = scratch_files("render_speed", name, files);
    let loaded = load_any(
        &path.display().to_string(),
        &Settings::default(),
        &Configuration::default(),
    )
    .unwrap_or_else(|d| panic!("{d}"));
    let o = drawing::Options {
        view,
        about: None,
        omega: None,
        title: "t".into(),
    };
    drawing::with_threads(threads, || drawing::svg(&loaded.model, &loaded.summary, &o))
}

/// Each view's group: its name and its text.
fn views(svg: &str) -> Vec<(String, String)> {
    svg.split("<g id=\"")
        .skip(1)
        .filter(|g| {
            View::ALL
                .iter()
                .any(|v| g.starts_with(&format!("{}\"", v.name())))
        })
        .map(|g| {
            let name = g.split('"').next().unwrap().to_string();
            let body = g.split("</g>").next().unwrap().to_string();
            (name, body)
        })
        .collect()
}

/// The parts' outlines in a view (each `<path class="c…`, a colour's).
fn outlines(view: &str) -> usize {
    view.matches("<path class=\"c").count()
}

/// The view's note of copies not drawn again, if any: their number.
fn not_again(view: &str) -> Option<usize> {
    let at = view.find(" coincident cop")?;
    let digits = view[..at]
        .rsplit('>')
        .next()
        .unwrap()
        .trim()
        .parse()
        .unwrap();
    Some(digits)
}

fn main_file(body: &str) -> String {
    format!("units = {{ length = \"mm\", mass = \"kg\" }}\n{body}")
}

const BOX: &str = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [10, 20, 30]\ncenter = [0, 0, 0]\n";

#[test]
fn an_included_pair_copied_in_one_place_is_drawn_once_a_view() {
    // Its copies come box, cylinder, box, cylinder…: no copy follows its
    // own, so each is found by its text, not as the part met last.
    let sub = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [10, 20, 30]\ncenter = [0, 0, 0]\n\
               [[part]]\nshape = \"cylinder\"\nmass = 1\nradius = 5\nlength = 40\ncenter = [50, 0, 0]\n";
    let main =
        main_file("[[part]]\ninclude = \"sub.toml\"\narray = { count = 3, step = [0, 0, 0] }\n");
    let svg = draw("pair", &[("sub.toml", sub), ("main.toml", &main)], 1, None);
    let v = views(&svg);
    assert_eq!(v.len(), 4);
    for (name, body) in &v {
        assert_eq!(outlines(body), 2, "{name}");
        assert_eq!(not_again(body), Some(4), "{name}");
    }
}

#[test]
fn copies_closer_than_the_resolution_are_drawn_once_a_view() {
    // A nanometre apart: the same text to the hundredth of a pixel.
    let main = main_file(&format!(
        "{BOX}array = {{ count = 4, step = [1e-6, 0, 0] }}\n"
    ));
    let svg = draw("close", &[("main.toml", &main)], 1, None);
    for (name, body) in views(&svg) {
        assert_eq!(outlines(&body), 1, "{name}");
        assert_eq!(not_again(&body), Some(3), "{name}");
    }
}

#[test]
fn copies_apart_are_each_drawn() {
    let main = main_file(&format!(
        "{BOX}array = {{ count = 4, step = [25, 25, 25] }}\n"
    ));
    let svg = draw("apart", &[("main.toml", &main)], 1, None);
    for (name, body) in views(&svg) {
        assert_eq!(outlines(&body), 4, "{name}");
        assert_eq!(not_again(&body), None, "{name}");
    }
}

#[test]
fn parts_written_apart_in_one_place_are_each_drawn() {
    let main = main_file(&format!("{BOX}{BOX}"));
    let svg = draw("written-apart", &[("main.toml", &main)], 1, None);
    for (name, body) in views(&svg) {
        assert_eq!(outlines(&body), 2, "{name}");
        assert_eq!(not_again(&body), None, "{name}");
    }
}

#[test]
fn copies_one_pixel_apart_in_one_view_only_are_drawn_once_there_only() {
    // A step along z: the top view (x right, y up) sees the copies in one
    // place, the others a step apart. 25 mm is many pixels at any scale
    // that fits a 100 mm body in a 600 px cell.
    let main = main_file(&format!(
        "{BOX}array = {{ count = 3, step = [0, 0, 25] }}\n"
    ));
    let svg = draw("one-view", &[("main.toml", &main)], 1, None);
    for (name, body) in views(&svg) {
        let (n, again) = if name == "top" {
            (1, Some(2))
        } else {
            (3, None)
        };
        assert_eq!(outlines(&body), n, "{name}");
        assert_eq!(not_again(&body), again, "{name}");
    }
}

/// A file with what each walk must get right: groups (the colours), an
/// included pair copied in one place and apart, a cut-out (a second walk),
/// point masses, an array in one place (a run), and parts too small to
/// draw (the legend's count, made by the first view).
fn busy() -> (String, String) {
    let sub = "units = { length = \"mm\", mass = \"kg\" }\n\
               [[part]]\nshape = \"box\"\nmass = 1\nsize = [10, 20, 30]\ncenter = [0, 0, 0]\ngroup = \"frame\"\n\
               [[part]]\nshape = \"sphere\"\nmass = 1\nradius = 8\ncenter = [40, 0, 0]\ngroup = \"hub\"\n\
               [[part]]\nshape = \"point\"\nmass = 0.1\ncenter = [0, 30, 0]\n";
    let mut main = String::from(
        "[[part]]\ninclude = \"sub.toml\"\narray = { count = 3, step = [0, 0, 0] }\n\
         [[part]]\ninclude = \"sub.toml\"\narray = { count = 5, step = [0, 120, 0] }\n\
         [[part]]\nshape = \"box\"\nmass = 8\nsize = [300, 300, 10]\ncenter = [0, 200, -60]\ngroup = \"plate\"\n\
         [[part]]\nshape = \"cylinder\"\nmass = 0.5\nradius = 20\nlength = 10\ncenter = [0, 200, -60]\nremove = true\n\
         [[part]]\nshape = \"torus\"\nmass = 1\nradius = 30\ntube_radius = 5\ncenter = [100, 300, 50]\nrotation = { axis = [1, 1, 0], degrees = 30 }\n\
         [[part]]\nshape = \"box\"\nmass = 0.001\nsize = [0.01, 0.01, 0.01]\ncenter = [5, 5, 5]\narray = { count = 40, step = [0, 0, 0] }\n",
    );
    for k in 0..60 {
        main += &format!(
            "[[part]]\nshape = \"cone\"\nmass = 0.1\nradius = {}\ntop_radius = 0\nlength = 12\n\
             center = [{}, {}, {}]\nrotation = {{ axis = [1, {k}, 2], degrees = {} }}\n",
            2 + k % 5,
            -150 + 5 * k,
            -40 + 7 * (k % 13),
            3 * (k % 7),
            6 * k,
        );
    }
    (sub.to_string(), main_file(&main))
}

#[test]
fn one_thread_and_two_draw_the_same_document() {
    let (sub, main) = busy();
    let files = [("sub.toml", sub.as_str()), ("main.toml", main.as_str())];
    let one = draw("threads", &files, 1, None);
    let two = draw("threads", &files, 2, None);
    assert!(one.contains("smaller than a pixel"), "{one}");
    assert!(one.contains("coincident cop"), "{one}");
    assert!(one.contains(" cut\""), "{one}");
    assert_eq!(views(&one).len(), 4);
    assert!(one == two, "one thread and two differ");
}

#[test]
fn one_view_on_two_threads_is_the_view_on_one() {
    let (sub, main) = busy();
    let files = [("sub.toml", sub.as_str()), ("main.toml", main.as_str())];
    for view in View::ALL {
        let one = draw("one-view-threads", &files, 1, Some(view));
        let two = draw("one-view-threads", &files, 2, Some(view));
        assert!(one == two, "{view:?}");
    }
}

#[test]
fn every_example_is_drawn_the_same_on_one_thread_and_two() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shapes");
    let mut seen = 0;
    for entry in std::fs::read_dir(&root).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let Ok(loaded) = load_any(
            &path.display().to_string(),
            &Settings::default(),
            &Configuration::default(),
        ) else {
            continue;
        };
        let o = drawing::Options {
            title: "t".into(),
            ..Default::default()
        };
        let [one, two] = [1, 2]
            .map(|n| drawing::with_threads(n, || drawing::svg(&loaded.model, &loaded.summary, &o)));
        assert!(one == two, "{}", path.display());
        seen += 1;
    }
    assert!(seen >= 10, "{seen} examples drawn");
}
