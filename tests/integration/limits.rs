//! Every cost bounded by the work asked for (issue 28, item 6): an include
//! with `params` parsed once however many sets of values it is given, the
//! part limit counting every part however its parts are multiplied, and
//! "did you mean" bounded for names of any length. Work is counted, not
//! timed (`Model::texts_read`); the only clocks
//! are hang guards of a minute.

use crate::common::scratch_files;
use massprop::diag::Source;
use massprop::model::{MAX_PARTS, Model};
use std::path::Path;

/// The file at `path` parsed, as `report` reads it; its error as shown.
fn parse(path: &Path) -> Result<Model, String> {
    let text = std::fs::read_to_string(path).unwrap();
    let name = path.to_str().unwrap();
    Model::parse(&Source::new(name, text)).map_err(|d| d.to_string())
}

/// How many part files `path`'s parse read (0 if it failed), and its
/// result.
fn parses(path: &Path) -> (u64, Result<Model, String>) {
    let model = parse(path);
    (model.as_ref().map_or(0, |m| m.texts_read), model)
}

/// `f` on a thread of its own, failing after five minutes: a hang guard,
/// not a measure of speed (reaching the part limit walks 2,000,000 parts,
/// slow in a debug build on a loaded machine).
fn within_minutes<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(std::time::Duration::from_secs(300))
        .expect("finished within five minutes")
}

/// A library file of `n` parameters besides `leg`, whose part, a point
/// mass, weighs `double` = 2·`leg` kilograms.
fn library(n: usize) -> String {
    let mut text = String::from("[params]\nleg = 1\ndouble = \"2 * leg\"\n");
    for k in 0..n {
        text.push_str(&format!("p{k} = \"{k} mm\"\n"));
    }
    text.push_str("[[part]]\nshape = \"point\"\nmass = \"double * 1 kg\"\ncenter = [0, 0, 0]\n");
    text
}

/// `count` includes of `lib.toml`, each passing `leg` = k + 1.
fn includes(count: usize) -> String {
    (0..count)
        .map(|k| {
            format!(
                "[[part]]\ninclude = \"lib.toml\"\nparams = {{ leg = {} }}\norigin = [{k}, 0, 0]\n",
                k + 1
            )
        })
        .collect()
}

#[test]
fn forty_includes_with_different_params_parse_the_file_no_more_than_one_does() {
    let lib = library(1000);
    let one = scratch_files(
        "limits",
        "params-once-1",
        &[("lib.toml", &lib), ("top.toml", &includes(1))],
    );
    let forty = scratch_files(
        "limits",
        "params-once-40",
        &[("lib.toml", &lib), ("top.toml", &includes(40))],
    );
    let (n1, m1) = parses(&one);
    let (n40, m40) = parses(&forty);
    m1.unwrap();
    m40.unwrap();
    // The top file and the library, once each.
    assert_eq!(n1, 2);
    assert_eq!(n40, n1);
}

#[test]
fn each_set_of_params_gives_the_values_that_use_it() {
    let top = scratch_files(
        "limits",
        "params-values",
        &[("lib.toml", &library(10)), ("top.toml", &includes(40))],
    );
    let m = parse(&top).unwrap();
    // Include k weighs 2 (k + 1) kg: in all 2 · (1 + … + 40) = 1640 kg.
    let masses: Vec<f64> = m.flattened().iter().map(|p| p.si(m.units).mass).collect();
    let expected: Vec<f64> = (1..=40).map(|k| 2.0 * k as f64).collect();
    assert_eq!(masses, expected);
}

#[test]
fn the_same_params_in_another_order_of_includes_give_the_same_values() {
    // The second and fourth includes pass what the first and third did:
    // converted once each, the values of each set kept apart.
    let text = [2, 5, 2, 5]
        .iter()
        .enumerate()
        .map(|(k, leg)| {
            format!("[[part]]\ninclude = \"lib.toml\"\nparams = {{ leg = {leg} }}\norigin = [{k}, 0, 0]\n")
        })
        .collect::<String>();
    let top = scratch_files(
        "limits",
        "params-repeat",
        &[("lib.toml", &library(3)), ("top.toml", &text)],
    );
    let (n, m) = parses(&top);
    let m = m.unwrap();
    assert_eq!(n, 2);
    let masses: Vec<f64> = m.flattened().iter().map(|p| p.si(m.units).mass).collect();
    assert_eq!(masses, [4.0, 10.0, 4.0, 10.0]);
}

#[test]
fn a_passed_value_that_mends_the_files_own_definition_is_read() {
    // The file alone cannot evaluate `leg` (it names nothing defined):
    // every include passes it, so it never has to.
    let lib = "[params]\nleg = \"nothing_here\"\n[[part]]\nshape = \"point\"\nmass = \"leg * 1 kg\"\ncenter = [0, 0, 0]\n";
    let top = scratch_files(
        "limits",
        "params-mended",
        &[("lib.toml", lib), ("top.toml", &includes(3))],
    );
    let m = parse(&top).unwrap();
    let masses: Vec<f64> = m.flattened().iter().map(|p| p.si(m.units).mass).collect();
    assert_eq!(masses, [1.0, 2.0, 3.0]);
}

/// The first line of an error inside `lib.toml`: its place and message.
fn first_line(err: &str) -> &str {
    err.lines().next().unwrap()
}

#[test]
fn an_error_in_a_parameter_evaluated_again_is_said_where_the_file_says_it() {
    // `leg = 0` makes `inverse` divide by zero, in lib.toml's line 3.
    let lib = "[params]\nleg = 1\ninverse = \"1 / leg\"\n[[part]]\nshape = \"point\"\nmass = \"inverse * 1 kg\"\ncenter = [0, 0, 0]\n";
    let zero = "[[part]]\ninclude = \"lib.toml\"\nparams = { leg = 0 }\n";
    let one = "[[part]]\ninclude = \"lib.toml\"\nparams = { leg = 1 }\n";
    let alone = scratch_files(
        "limits",
        "params-error-alone",
        &[("lib.toml", lib), ("top.toml", zero)],
    );
    let after = scratch_files(
        "limits",
        "params-error-after",
        &[("lib.toml", lib), ("top.toml", &format!("{one}{zero}"))],
    );
    let alone = parse(&alone).unwrap_err();
    let after = parse(&after).unwrap_err();
    let at = |err: &str| {
        first_line(err)
            .split_once("lib.toml")
            .unwrap()
            .1
            .to_string()
    };
    assert!(at(&alone).starts_with(":3:"), "{alone}");
    assert_eq!(at(&alone), at(&after), "{after}");
}

#[test]
fn a_name_the_included_file_does_not_define_is_refused_at_the_include() {
    let text = "[[part]]\ninclude = \"lib.toml\"\nparams = { leg = 2 }\n[[part]]\ninclude = \"lib.toml\"\nparams = { legg = 2 }\n";
    let top = scratch_files(
        "limits",
        "params-undefined",
        &[("lib.toml", &library(3)), ("top.toml", text)],
    );
    let err = parse(&top).unwrap_err();
    assert!(err.contains("top.toml:6:12:"), "{err}");
    assert!(err.contains("defines no parameter `legg`"), "{err}");
}

// The part limit, for each way of multiplying parts.

const POINT: &str = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";

/// `POINT` with `extra` keys.
fn point(extra: &str) -> String {
    format!("{POINT}{extra}")
}

/// Whether `err` is the part limit's error at `file:line:col`.
fn refused_at(err: &str, file: &str, line: usize, col: usize) -> bool {
    first_line(err).contains(&format!("{file}:{line}:{col}: error:"))
        && err.contains(&MAX_PARTS.to_string())
}

#[test]
fn a_part_written_alone_after_an_array_at_the_limit_is_refused_at_its_shape() {
    let text = format!(
        "{}{}",
        point(&format!(
            "array = {{ count = {MAX_PARTS}, step = [1, 0, 0] }}\n"
        )),
        point("")
    );
    let top = scratch_files("limits", "alone-after-array", &[("top.toml", &text)]);
    let err = within_minutes(move || parse(&top).unwrap_err());
    // The second part's `shape`, line 7.
    assert!(refused_at(&err, "top.toml", 7, 9), "{err}");
}

#[test]
fn a_part_written_alone_after_a_mirrored_array_at_the_limit_is_refused() {
    let half = MAX_PARTS / 2;
    let text = format!(
        "{}{}",
        point(&format!(
            "array = {{ count = {half}, step = [1, 0, 0] }}\nmirror = {{ normal = [1, 0, 0] }}\n"
        )),
        point("")
    );
    let top = scratch_files("limits", "alone-after-mirror", &[("top.toml", &text)]);
    let err = within_minutes(move || parse(&top).unwrap_err());
    assert!(refused_at(&err, "top.toml", 8, 9), "{err}");
}

#[test]
fn an_array_of_an_included_array_past_the_limit_is_refused_at_its_array() {
    // Both counts numbers: the count made before expanding refuses the
    // include.
    let sub = point("array = { count = 1000, step = [1, 0, 0] }\n");
    let text = format!(
        "[[part]]\ninclude = \"sub.toml\"\narray = {{ count = {}, step = [0, 1, 0] }}\n",
        MAX_PARTS / 1000 + 1
    );
    let top = scratch_files(
        "limits",
        "array-of-arrays-counted",
        &[("sub.toml", &sub), ("top.toml", &text)],
    );
    let err = within_minutes(move || parse(&top).unwrap_err());
    assert!(refused_at(&err, "top.toml", 2, 11), "{err}");
    // Its count a string, which that count takes for 1: the exact count
    // refuses it at its array, before any copy is made.
    let text = format!(
        "[[part]]\ninclude = \"sub.toml\"\narray = {{ count = \"{}\", step = [0, 1, 0] }}\n",
        MAX_PARTS / 1000 + 1
    );
    let top = scratch_files(
        "limits",
        "array-of-arrays",
        &[("sub.toml", &sub), ("top.toml", &text)],
    );
    let err = within_minutes(move || parse(&top).unwrap_err());
    assert!(refused_at(&err, "top.toml", 3, 9), "{err}");
}

#[test]
fn includes_whose_params_make_arrays_past_the_limit_are_refused_at_the_include() {
    // The count comes from `params`: the count made before expanding
    // cannot know it, so the exact count refuses it as it is included.
    let sub = point("array = { count = \"n\", step = [1, 0, 0] }\n");
    let sub = format!("[params]\nn = 1\n{sub}");
    let text = format!(
        "[[part]]\ninclude = \"sub.toml\"\nparams = {{ n = {} }}\n[[part]]\ninclude = \"sub.toml\"\nparams = {{ n = {} }}\n",
        MAX_PARTS / 2,
        MAX_PARTS / 2 + 1
    );
    let top = scratch_files(
        "limits",
        "params-arrays",
        &[("sub.toml", &sub), ("top.toml", &text)],
    );
    let err = within_minutes(move || parse(&top).unwrap_err());
    assert!(refused_at(&err, "top.toml", 5, 11), "{err}");
}

#[test]
fn a_mirror_of_an_array_at_the_limit_is_refused_at_the_mirror() {
    let text = point(&format!(
        "array = {{ count = {MAX_PARTS}, step = [1, 0, 0] }}\nmirror = {{ normal = [1, 0, 0] }}\n"
    ));
    let top = scratch_files("limits", "mirrored-array", &[("top.toml", &text)]);
    let err = within_minutes(move || parse(&top).unwrap_err());
    assert!(refused_at(&err, "top.toml", 6, 10), "{err}");
}

// "Did you mean" over names of any length.

/// A name of 100,000 characters.
fn long(last: char) -> String {
    let mut s = "a".repeat(100_000);
    s.push(last);
    s
}

#[test]
fn a_long_unknown_material_against_a_long_defined_one_gets_its_error() {
    let text = format!(
        "[materials]\n{} = {{ density = 1000 }}\n[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nmaterial = \"{}\"\n",
        long('b'),
        long('c')
    );
    let top = scratch_files("limits", "long-material", &[("top.toml", &text)]);
    let err = within_minutes(move || parse(&top).unwrap_err());
    assert!(
        first_line(&err).contains("top.toml:7:12: error: unknown material"),
        "{err}"
    );
    // The name said in 64 characters, its length counted.
    assert!(err.contains("(100001 characters)"), "{err}");
    assert!(first_line(&err).chars().count() < 200, "{err}");
}

#[test]
fn a_long_unknown_only_name_against_a_long_sub_assembly_gets_its_error() {
    let text = format!(
        "[[part]]\nname = \"{}\"\ninclude = \"sub.toml\"\n",
        long('b')
    );
    let top = scratch_files(
        "limits",
        "long-only",
        &[("sub.toml", POINT), ("top.toml", &text)],
    );
    let err = within_minutes(move || {
        let mut m = parse(&top).unwrap();
        m.only(&long('c')).unwrap_err()
    });
    assert!(err.starts_with("`--only aaaa"), "{err}");
    assert!(err.contains("no sub-assembly of that name"), "{err}");
    // Both names shortened: the asked and the listed.
    assert_eq!(err.matches("(100001 characters)").count(), 2, "{err}");
    assert!(err.chars().count() < 300, "{err}");
}

#[test]
fn a_short_misspelt_only_name_is_still_given_its_suggestion() {
    let text = "[[part]]\nname = \"front wheel\"\ninclude = \"sub.toml\"\n";
    let top = scratch_files(
        "limits",
        "short-only",
        &[("sub.toml", POINT), ("top.toml", text)],
    );
    let mut m = parse(&top).unwrap();
    let err = m.only("front wheal").unwrap_err();
    assert!(err.contains("did you mean `front wheel`?"), "{err}");
}

#[test]
fn the_list_of_sub_assemblies_in_an_only_error_is_cut_at_twelve() {
    let sub = scratch_files("limits", "only-list", &[("sub.toml", POINT)]);
    let dir = sub.parent().unwrap();
    let text = "[[part]]\nname = \"wheel\"\ninclude = \"sub.toml\"\narray = { count = 1000, step = [1, 0, 0] }\n";
    std::fs::write(dir.join("top.toml"), text).unwrap();
    let mut m = parse(&dir.join("top.toml")).unwrap();
    let err = m.only("tyre").unwrap_err();
    // `wheel` and its 1000 copies: 12 named, 989 counted.
    assert_eq!(err.matches("`wheel").count(), 12, "{err}");
    assert!(err.ends_with("and 989 more)"), "{err}");
}
