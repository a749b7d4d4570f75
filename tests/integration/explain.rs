//! `massprop explain` (issue 36): the bent plate of ME101's lecture 39
//! worked as the lecture works it, every number of an explanation the
//! report's, random files' explanations summing to their reports, its
//! formats, its bad input and hostile names, and the exact arithmetic
//! against num-rational.

use crate::common::massprop;
use massprop::explain::exact::Exact;
use massprop::numeric::Real;
use num_rational::Ratio;
use proptest::prelude::*;
use serde_json::Value;

const BENT: &str = "shapes/bent-plate.toml";

/// `massprop explain ARGS…`, in process: its standard output.
fn explain(args: &[&str]) -> String {
    let mut argv = vec!["massprop", "explain"];
    argv.extend(args);
    let cli = <massprop::cli::Cli as clap::Parser>::try_parse_from(argv).unwrap();
    let out = massprop::run(&cli).unwrap_or_else(|d| panic!("{d}"));
    out.stdout.text()
}

/// `massprop report --format json ARGS…`, in process.
fn report(args: &[&str]) -> Value {
    let mut argv = vec!["massprop", "report", "--format", "json"];
    argv.extend(args);
    let cli = <massprop::cli::Cli as clap::Parser>::try_parse_from(argv).unwrap();
    let out = massprop::run(&cli).unwrap_or_else(|d| panic!("{d}"));
    serde_json::from_str(&out.stdout.text()).unwrap()
}

/// The value of each text line `LHS = … = VALUE [(exactly n/d)] UNIT`, in
/// order: the number after the last ` = `, exact where a fraction is
/// given (parsed here, not by the program).
fn values(text: &str, lhs: &str) -> Vec<f64> {
    let head = format!("{lhs} = ");
    text.lines()
        .map(str::trim)
        .filter(|l| l.starts_with(&head))
        .map(|l| {
            let last = l.rsplit(" = ").next().unwrap();
            if let Some(i) = last.find("(exactly ") {
                let f = &last[i + 9..last[i..].find(')').unwrap() + i];
                let (n, d) = f.split_once('/').unwrap();
                return n.parse::<f64>().unwrap() / d.parse::<f64>().unwrap();
            }
            last.split_whitespace().next().unwrap().parse().unwrap()
        })
        .collect()
}

fn one(text: &str, lhs: &str) -> f64 {
    let v = values(text, lhs);
    assert!(!v.is_empty(), "no line `{lhs} = …` in:\n{text}");
    *v.last().unwrap()
}

fn close(got: f64, want: f64, scale: f64, what: &str) {
    assert!(
        (got - want).abs() <= 1e-12 * scale.abs().max(want.abs()),
        "{what}: {got} vs {want}"
    );
}

#[test]
fn the_bent_plate_masses_are_the_lectures() {
    let text = explain(&[BENT]);
    assert!(
        text.contains("m = ρ·a·b = 0.00007 × 125 × 100 = 0.875 kg"),
        "{text}"
    );
    assert!(
        text.contains("m = ρ·a·b = 0.00007 × 75 × 150 = 0.7875 kg"),
        "{text}"
    );
    // The sum as the report's f64, the lecture's 1.6625 exactly beside it.
    assert!(
        text.contains("m = Σ m = 0.875 + 0.7875 = 1.6624999999999999 (exactly 133/80) kg"),
        "{text}"
    );
    assert_eq!(one(&text, "m"), 1.6625);
}

/// Each plate about O, by hand: a thin plate's ∫u² dm over [0, a] is
/// m a²/3, its ∫uv dm m (a/2)(b/2); products in the tensor convention.
#[test]
fn each_plate_moments_and_products_about_o_are_the_lectures() {
    let text = explain(&[BENT]);
    let (ma, mb) = (0.875, 0.7875);
    let a = [
        ma * (125.0 * 125.0 + 100.0 * 100.0) / 3.0,
        ma * 100.0 * 100.0 / 3.0,
        ma * 125.0 * 125.0 / 3.0,
        0.0,
        0.0,
        -ma * 62.5 * 50.0,
    ];
    let b = [
        mb * (125.0 * 125.0 + 150.0 * 150.0 / 3.0),
        mb * (75.0 * 75.0 + 150.0 * 150.0) / 3.0,
        mb * (75.0 * 75.0 / 3.0 + 125.0 * 125.0),
        -mb * 37.5 * 125.0,
        -mb * 37.5 * 75.0,
        -mb * 125.0 * 75.0,
    ];
    for (k, lhs) in ["Ixx(O)", "Iyy(O)", "Izz(O)", "Ixy(O)", "Ixz(O)", "Iyz(O)"]
        .iter()
        .enumerate()
    {
        let v = values(&text, lhs);
        // Plate A's, plate B's, their sum.
        assert_eq!(v.len(), 3, "{lhs}: {v:?}");
        close(v[0], a[k], 1e4, &format!("A {lhs}"));
        close(v[1], b[k], 1e4, &format!("B {lhs}"));
        close(v[2], a[k] + b[k], 1e4, &format!("Σ {lhs}"));
    }
}

#[test]
fn the_bent_plate_h_and_t_are_the_lectures_exactly() {
    let text = explain(&[BENT]);
    for line in [
        "= -0.0664453125 N·m·s",
        "= -0.30351562499999996 (exactly -777/2560) N·m·s",
        "= 0.55015625 N·m·s",
        "= 8.25234375 J",
    ] {
        assert!(text.contains(line), "{line} in:\n{text}");
    }
    assert_eq!(one(&text, "Hy"), -0.303515625);
}

/// The totals of an explanation against the report's JSON (SI): the
/// file's length unit is `l` metres, its mass unit `k` kilograms.
fn agrees_with_report(args: &[&str], l: f64, k: f64) {
    let text = explain(args);
    let json = report(args);
    let num = |v: &Value| v.as_f64().unwrap();
    let mass = num(&json["mass"]);
    close(one(&text, "m") * k, mass, mass, "mass");
    for (i, a) in ["x_G", "y_G", "z_G"].iter().enumerate() {
        let g = num(&json["center_of_mass"][i]);
        close(one(&text, a) * l, g, 1.0, a);
    }
    let i = &json["inertia_com"];
    let scale: f64 = (0..3).map(|a| num(&i[a][a]).abs()).fold(0.0, f64::max);
    for (name, (a, b)) in [
        ("Ixx(G)", (0, 0)),
        ("Iyy(G)", (1, 1)),
        ("Izz(G)", (2, 2)),
        ("Ixy(G)", (0, 1)),
        ("Ixz(G)", (0, 2)),
        ("Iyz(G)", (1, 2)),
    ] {
        close(one(&text, name) * k * l * l, num(&i[a][b]), scale, name);
    }
    for (n, name) in ["λ1", "λ2", "λ3"].iter().enumerate() {
        let want = num(&json["principal_moments"][n]);
        close(one(&text, name) * k * l * l, want, scale, name);
    }
    if let Some(h) = json["angular_momentum"].as_array() {
        let hs = h.iter().map(num).fold(0.0, |a: f64, x| a.max(x.abs()));
        for (n, name) in ["Hx", "Hy", "Hz"].iter().enumerate() {
            close(one(&text, name), num(&h[n]), hs, name);
        }
        let t = num(&json["kinetic_energy"]);
        close(one(&text, "T"), t, t, "T");
    }
    // Each part's mass and centroid, where the part is explained whole.
    for p in json["parts"].as_array().unwrap() {
        let name = p["name"].as_str().unwrap();
        if !p["assembly"].as_array().unwrap().is_empty() {
            continue;
        }
        let heading = format!(". part \"{name}\":");
        let Some(at) = text.find(&heading) else {
            continue;
        };
        let step = &text[at..];
        let step = &step[..step[1..].find("\n\n").map_or(step.len(), |e| e + 1)];
        close(one(step, "m") * k, num(&p["mass"]), mass, name);
        for (i, a) in ["x_c", "y_c", "z_c"].iter().enumerate() {
            close(one(step, a) * l, num(&p["center_of_mass"][i]), 1.0, a);
        }
    }
}

#[test]
fn every_number_of_the_bent_plate_is_the_reports() {
    agrees_with_report(&[BENT], 1e-3, 1.0);
}

#[test]
fn every_number_of_the_example_files_is_the_reports() {
    for f in [
        "shapes/flywheel.toml",
        "shapes/motor-bracket.toml",
        "shapes/quickstart.toml",
    ] {
        let text = std::fs::read_to_string(f).unwrap();
        let (l, k) = units_of(&text);
        agrees_with_report(&[f], l, k);
    }
}

/// A file's units in metres and kilograms, read from its `units` line.
fn units_of(text: &str) -> (f64, f64) {
    let line = text.lines().find(|l| l.starts_with("units")).unwrap_or("");
    let l = if line.contains("\"mm\"") {
        1e-3
    } else if line.contains("\"cm\"") {
        1e-2
    } else {
        1.0
    };
    let k = if line.contains("\"g\"") { 1e-3 } else { 1.0 };
    (l, k)
}

/// A box 0.2 × 0.1 × 0.05 m of 1 kg turned 90° about z: its local x′
/// lies along the file's y, so the file's Ixx is its Iy′y′ = m(a² + c²)/12
/// = (0.04 + 0.0025)/12 = 17/4800; and a bored cut-out counts negative.
#[test]
fn a_turned_part_shows_its_own_moments_then_the_files() {
    let dir = crate::common::scratch("explain", "turned");
    let f = dir.join("t.toml");
    std::fs::write(
        &f,
        "[[part]]\nname = \"block\"\nshape = \"box\"\ndensity = 1000\nsize = [0.2, 0.1, 0.05]\n\
         center = [1, 0, 0]\nrotation = { intrinsic = \"zyx\", degrees = [90, 0, 0] }\n\n\
         [[part]]\nname = \"hole\"\nshape = \"cylinder\"\ndensity = 1000\nradius = 0.01\n\
         length = 0.05\ncenter = [1, 0, 0]\nremove = true\n",
    )
    .unwrap();
    let text = explain(&[f.to_str().unwrap()]);
    assert!(text.contains("Ix′x′ = m(b² + c²)/12 = 1 × (0.1² + 0.05²)/12 = 0.0010416666666666667 (exactly 1/960) kg·m²"), "{text}");
    assert!(text.contains("turned into the file's axes"), "{text}");
    assert_eq!(values(&text, "Ixx")[0], 17.0 / 4800.0);
    assert!(
        text.contains("its mass and inertia count negative"),
        "{text}"
    );
    assert!(one(&text, "m") < 1.0);
    agrees_with_report(&[f.to_str().unwrap()], 1.0, 1.0);
}

#[test]
fn positive_products_flip_the_products_and_keep_t() {
    let text = explain(&[BENT, "--products", "positive"]);
    assert!(text.contains("Ixy = +∫xy dm"));
    assert_eq!(*values(&text, "Iyz(O)").last().unwrap(), 10117.1875);
    assert!(text.contains("= 8.25234375 J"), "{text}");
}

#[test]
fn a_sub_assembly_array_or_mesh_is_one_line() {
    let text = explain(&["shapes/bicycle-wheel.toml"]);
    let json = report(&["shapes/bicycle-wheel.toml"]);
    let lines = text
        .lines()
        .filter(|l| l.contains("and its copies ("))
        .count();
    assert!(lines >= 1, "{text}");
    // Fewer steps than parts: copies are not explained one by one.
    let parts = json["parts"].as_array().unwrap().len();
    let steps = text.lines().filter(|l| l.contains(". part \"")).count();
    assert!(steps < parts, "{steps} steps for {parts} parts");
    agrees_with_report(
        &["shapes/bicycle-wheel.toml"],
        units_of(&std::fs::read_to_string("shapes/bicycle-wheel.toml").unwrap()).0,
        1.0,
    );
}

#[test]
fn only_explains_a_sub_assembly_part_by_part() {
    let args = ["shapes/robot-arm.toml", "--only", "shoulder"];
    let text = explain(&args);
    let parts = report(&args)["parts"].as_array().unwrap().len();
    let steps = text.lines().filter(|l| l.contains(". part \"")).count();
    assert_eq!(steps, parts, "{text}");
    assert!(!text.contains("sub-assembly \"shoulder\""), "{text}");
    agrees_with_report(&args, 1e-3, 1.0);
}

#[test]
fn a_missing_file_is_exit_2_with_nothing_on_stdout() {
    let out = massprop(&["explain", "no/such/file.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("no/such/file.toml"));
}

#[test]
fn a_bad_file_is_exit_2_at_its_line_and_column() {
    let dir = crate::common::scratch("explain", "bad");
    let f = dir.join("bad.toml");
    std::fs::write(
        &f,
        "[[part]]\nname = \"a\"\nshape = \"box\"\nmass = 1\nsize = [1, 1]\n",
    )
    .unwrap();
    let out = massprop(&["explain", f.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert!(err.contains("bad.toml:5:"), "{err}");
    assert!(err.contains("`size`"), "{err}");
}

#[test]
fn an_unknown_only_is_exit_2() {
    let out = massprop(&["explain", BENT, "--only", "nothing"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("nothing"));
}

const HOSTILE: &str = "[[part]]\nname = \"a|b_c$d%e&f#g{h}i\\\\j~k^l*m[n]o<p>\\u001b[31mq\\nr\"\nshape = \"point\"\nmass = 1\ncenter = [1, 2, 3]\n";

fn hostile(format: &str) -> String {
    let dir = crate::common::scratch("explain", &format!("hostile-{format}"));
    let f = dir.join("h.toml");
    std::fs::write(&f, HOSTILE).unwrap();
    explain(&[f.to_str().unwrap(), "--format", format])
}

#[test]
fn a_hostile_name_neither_acts_nor_adds_a_line_in_text() {
    let text = hostile("text");
    assert!(!text.contains('\u{1b}'));
    let heading = text.lines().find(|l| l.starts_with("1. part")).unwrap();
    assert!(heading.contains("␛[31mq␊r"), "{heading}");
}

#[test]
fn a_hostile_name_is_escaped_in_markdown() {
    let md = hostile("markdown");
    assert!(!md.contains('\u{1b}'));
    let heading = md.lines().find(|l| l.starts_with("## 1. part")).unwrap();
    assert!(
        heading.contains(r"a\|b\_c\$d%e\&f\#g\{h\}i\\j\~k^l\*m\[n\]o\<p\>"),
        "{heading}"
    );
}

#[test]
fn a_hostile_name_is_escaped_in_latex() {
    let tex = hostile("latex");
    let heading = tex
        .lines()
        .find(|l| l.starts_with("\\subsection*{1. part"))
        .unwrap();
    assert!(
        heading.contains(r"a\textbar{}b\_c\$d\%e\&f\#g\{h\}i\textbackslash{}j\textasciitilde{}k\textasciicircum{}l*m[n]o\textless{}p\textgreater{}[U+241B][31mq[U+240A]r"),
        "{heading}"
    );
}

#[test]
fn markdown_has_a_table_and_maths_per_step() {
    let md = explain(&[BENT, "--format", "markdown"]);
    assert!(md.contains("| quantity | formula | with the numbers | value |"));
    assert!(md.contains("| $m$ | $= \\rho \\cdot a \\cdot b$ | $= 0.00007 \\times 125 \\times 100$ | 0\\.875 kg |"), "{md}");
    assert!(md.contains("8\\.25234375 J"));
}

/// The LaTeX compiles with pdflatex where it is installed.
#[test]
fn latex_compiles_with_pdflatex_where_installed() {
    let tex = explain(&[BENT, "--format", "latex"]);
    assert!(tex.starts_with("\\documentclass{article}"));
    assert_eq!(
        tex.matches("\\begin{align*}").count(),
        tex.matches("\\end{align*}").count()
    );
    assert!(tex.is_ascii(), "pdflatex reads ASCII safely");
    let Ok(found) = std::process::Command::new("pdflatex")
        .arg("--version")
        .output()
    else {
        eprintln!("note: pdflatex is not installed; the LaTeX was not compiled");
        return;
    };
    assert!(found.status.success());
    for (name, text) in [("bent", tex), ("hostile", hostile("latex"))] {
        let dir = crate::common::scratch("explain", &format!("latex-{name}"));
        std::fs::write(dir.join("x.tex"), text).unwrap();
        let out = std::process::Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error", "x.tex"])
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
}

/// A random file: a few parts of several shapes, offset and turned.
fn part_strategy() -> impl Strategy<Value = String> {
    let at = prop::array::uniform3(-40i32..40);
    let size = prop::array::uniform3(1u32..30);
    let deg = prop::array::uniform3(-180i32..180);
    (0usize..6, at, size, deg, 1u32..50).prop_map(|(kind, at, s, deg, rho)| {
        let c = format!("center = [{}, {}, {}]", at[0], at[1], at[2]);
        let rot = format!("rotation = {{ intrinsic = \"zyx\", degrees = [{}, {}, {}] }}", deg[0], deg[1], deg[2]);
        match kind {
            0 => format!("shape = \"box\"\ndensity = {rho}\nsize = [{}, {}, {}]\n{c}\n{rot}", s[0], s[1], s[2]),
            1 => format!("shape = \"sphere\"\nmass = {rho}\nradius = {}\n{c}", s[0]),
            2 => format!("shape = \"cylinder\"\ndensity = {rho}\nradius = {}\nlength = {}\n{c}\n{rot}", s[0], s[1]),
            3 => format!(
                "shape = \"plate\"\nareal_density = {rho}\ncorner = [{}, {}, {}]\nedges = [[{}, 0, 0], [0, {}, 0]]",
                at[0], at[1], at[2], s[0], s[1]
            ),
            4 => format!(
                "shape = \"rod\"\nlinear_density = {rho}\nfrom = [{}, {}, {}]\nto = [{}, {}, {}]",
                at[0], at[1], at[2], at[0] + s[0] as i32, at[1] - s[1] as i32, at[2] + s[2] as i32
            ),
            _ => format!("shape = \"point\"\nmass = {rho}\n{c}"),
        }
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// The explanation of a random file sums to its report.
    #[test]
    fn the_explanation_of_a_random_file_sums_to_its_report(
        parts in prop::collection::vec(part_strategy(), 1..5),
        omega in prop::array::uniform3(-5i32..5),
        n in 0u32..1_000_000,
    ) {
        let mut text = String::new();
        for (i, p) in parts.iter().enumerate() {
            text.push_str(&format!("[[part]]\nname = \"p{i}\"\n{p}\n\n"));
        }
        text.push_str(&format!("[analysis]\nabout = [1, -2, 3]\nomega = [{}, {}, {}]\n", omega[0], omega[1], omega[2]));
        let dir = crate::common::scratch("explain", &format!("random-{n}"));
        let f = dir.join("r.toml");
        std::fs::write(&f, &text).unwrap();
        agrees_with_report(&[f.to_str().unwrap()], 1.0, 1.0);
    }

    /// `Exact` is num-rational's arithmetic wherever it stays exact.
    #[test]
    fn exact_arithmetic_is_num_rationals(
        a in -10_000i64..10_000, b in 1i64..10_000,
        c in -10_000i64..10_000, d in 1i64..10_000,
    ) {
        let (x, y) = (Exact::ratio(a as i128, b as i128), Exact::ratio(c as i128, d as i128));
        let (p, q) = (Ratio::new(a as i128, b as i128), Ratio::new(c as i128, d as i128));
        let same = |e: Exact, r: Ratio<i128>| e.exact == Some((*r.numer(), *r.denom()));
        prop_assert!(same(x + y, p + q));
        prop_assert!(same(x - y, p - q));
        prop_assert!(same(x * y, p * q));
        if c != 0 {
            prop_assert!(same(x / y, p / q));
        }
        prop_assert_eq!(x < y, p < q);
    }
}

#[test]
fn an_input_decimal_is_exact_and_pi_is_not() {
    assert_eq!(Exact::of(0.1).exact, Some((1, 10)));
    assert_eq!((Exact::of(0.1) + Exact::of(0.2)).exact, Some((3, 10)));
    assert!(Exact::pi().exact.is_none());
}

/// Every part file of the catalogues and of the fuzz corpus: explained,
/// or refused with a diagnostic; never a panic, never inf or NaN shown.
#[test]
fn no_input_of_the_catalogues_or_the_corpus_makes_explain_panic() {
    let mut files = Vec::new();
    for dir in std::fs::read_dir("tests/cmd").unwrap() {
        let dir = dir.unwrap().path();
        if dir.is_dir() {
            files.extend(std::fs::read_dir(&dir).unwrap().map(|f| f.unwrap().path()));
        }
    }
    // The packaged crate has no fuzz/ (Cargo.toml excludes it): the
    // catalogues alone are then read.
    match std::fs::read_dir("fuzz/corpus/parse_and_compose") {
        Ok(corpus) => files.extend(corpus.map(|f| f.unwrap().path())),
        Err(_) => eprintln!("no fuzz/corpus here (the packaged crate): the catalogues alone"),
    }
    files.retain(|f| f.extension().is_some_and(|e| e == "toml") || f.starts_with("fuzz"));
    assert!(files.len() > 100, "{} files", files.len());
    // The binary's main thread's stack (8 MiB), not a test thread's: the
    // catalogues hold inputs nested as deep as the reader allows.
    std::thread::Builder::new()
        .stack_size(16 << 20)
        .spawn(move || explain_each(files))
        .unwrap()
        .join()
        .unwrap();
}

fn explain_each(files: Vec<std::path::PathBuf>) {
    for f in files {
        let path = f.to_str().unwrap().to_string();
        let argv = ["massprop", "explain", &path, "--format", "markdown"];
        let cli = <massprop::cli::Cli as clap::Parser>::try_parse_from(argv).unwrap();
        let run = std::panic::catch_unwind(|| massprop::run(&cli).map(|o| o.stdout.text()));
        let Ok(out) = run else {
            panic!("explain panicked on {path}")
        };
        if let Ok(text) = out {
            assert!(
                !text.contains("NaN") && !text.contains("inf "),
                "{path}:\n{text}"
            );
        }
    }
}

/// A body whose tensor is finite but whose invariant I₃ ~ I³ is not: the
/// invariant is said to be beyond f64's range, never printed as inf.
#[test]
fn a_huge_body_says_beyond_range_and_never_prints_inf() {
    let dir = crate::common::scratch("explain", "huge");
    let f = dir.join("h.toml");
    std::fs::write(
        &f,
        "[[part]]\nshape = \"sphere\"\nmass = 1\nradius = 1e120\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    for format in ["text", "markdown", "latex"] {
        let text = explain(&[f.to_str().unwrap(), "--format", format]);
        assert!(text.contains("beyond f64's range"), "{text}");
        assert!(!text.contains("inf") && !text.contains("NaN"), "{text}");
    }
}

/// The nine numbers `R11 … R33` the explanation prints for its first
/// turned part, and the tensor it prints after them (tensor entries).
fn printed_turn(text: &str) -> ([[f64; 3]; 3], [f64; 3], [[f64; 3]; 3]) {
    let r = std::array::from_fn(|a| {
        std::array::from_fn(|b| values(text, &format!("R{}{}", a + 1, b + 1))[0])
    });
    let own = ["Ix′x′", "Iy′y′", "Iz′z′"].map(|n| values(text, n)[0]);
    let after = text.split("R33 = ").nth(1).unwrap();
    let at = |n: &str| values(after, n)[0];
    let (xy, xz, yz) = (at("Ixy"), at("Ixz"), at("Iyz"));
    let i = [
        [at("Ixx"), xy, xz],
        [xy, at("Iyy"), yz],
        [xz, yz, at("Izz")],
    ];
    (r, own, i)
}

/// R diag(own) Rᵀ, formed here from the printed numbers, is the printed
/// tensor to rounding; R is a rotation (RᵀR = 1).
fn turn_reproduces_tensor(toml: &str, name: &str) {
    let dir = crate::common::scratch("explain", name);
    let f = dir.join("t.toml");
    std::fs::write(&f, toml).unwrap();
    let text = explain(&[f.to_str().unwrap()]);
    assert!(text.contains("turned into the file's axes"), "{text}");
    let (r, own, i) = printed_turn(&text);
    let scale = own.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    for a in 0..3 {
        for b in 0..3 {
            let want: f64 = (0..3).map(|k| r[a][k] * own[k] * r[b][k]).sum();
            close(i[a][b], want, scale, &format!("I[{a}][{b}]"));
            let dot: f64 = (0..3).map(|k| r[k][a] * r[k][b]).sum();
            close(dot, if a == b { 1.0 } else { 0.0 }, 1.0, "RᵀR");
        }
    }
    assert!(
        r.iter()
            .flatten()
            .any(|x| x.abs() > 1e-3 && (x.abs() - 1.0).abs() > 1e-3),
        "{text}"
    );
}

#[test]
fn a_box_turned_by_a_quaternion_prints_r_and_r_i_rt_is_its_tensor() {
    turn_reproduces_tensor(
        "[[part]]\nname = \"block\"\nshape = \"box\"\ndensity = 1000\nsize = [0.2, 0.1, 0.05]\n\
         center = [1, 0, 0]\nrotation = { quaternion = [0.8, 0.4, -0.4, 0.2] }\n",
        "turn-box",
    );
}

#[test]
fn a_cylinder_turned_by_euler_angles_prints_r_and_r_i_rt_is_its_tensor() {
    turn_reproduces_tensor(
        "[[part]]\nname = \"can\"\nshape = \"cylinder\"\ndensity = 1000\nradius = 0.05\n\
         length = 0.3\ncenter = [0, 1, 0]\nrotation = { intrinsic = \"zyx\", degrees = [30, 20, 10] }\n",
        "turn-cylinder",
    );
}

const TRIANGLE_AND_GIVEN: &str = "[[part]]\nname = \"tri\"\nshape = \"triangle\"\nmass = 2\n\
    vertices = [[0, 0, 0], [0.3, 0, 0], [0, 0.2, 0.1]]\n\n\
    [[part]]\nname = \"bought\"\nshape = \"inertia\"\nmass = 1.5\ncenter = [0, 0, 0]\n\
    inertia = [[0.02, -0.001, 0], [-0.001, 0.03, 0.002], [0, 0.002, 0.04]]\n\
    rotation = { quaternion = [0.8, 0.4, -0.4, 0.2] }\n";

fn triangle_and_given() -> String {
    let dir = crate::common::scratch("explain", "triangle-given");
    let f = dir.join("t.toml");
    std::fs::write(&f, TRIANGLE_AND_GIVEN).unwrap();
    explain(&[f.to_str().unwrap()])
}

/// The printed tensor entries after `from` (tensor convention).
fn tensor_after(text: &str, from: &str) -> [[f64; 3]; 3] {
    let after = text.split(from).nth(1).unwrap();
    let at = |n: &str| values(after, n)[0];
    let (xy, xz, yz) = (at("Ixy"), at("Ixz"), at("Iyz"));
    [
        [at("Ixx"), xy, xz],
        [xy, at("Iyy"), yz],
        [xz, yz, at("Izz")],
    ]
}

#[test]
fn a_triangle_prints_its_e_k_and_m_over_12_sum_gives_its_tensor() {
    let text = triangle_and_given();
    let e: Vec<[f64; 3]> = (1..=3)
        .map(|n| ["x", "y", "z"].map(|k| values(&text, &format!("e{n}{k}"))[0]))
        .collect();
    // ∫ρρᵀ dm = (m/12) Σ eₖeₖᵀ; I = tr E − it (here, not by the program).
    let s: [[f64; 3]; 3] = std::array::from_fn(|a| {
        std::array::from_fn(|b| 2.0 / 12.0 * e.iter().map(|v| v[a] * v[b]).sum::<f64>())
    });
    let tr = s[0][0] + s[1][1] + s[2][2];
    let i = tensor_after(&text, "e3z = ");
    for a in 0..3 {
        for b in 0..3 {
            let want = if a == b { tr - s[a][a] } else { -s[a][b] };
            close(i[a][b], want, tr, &format!("I[{a}][{b}]"));
        }
    }
}

#[test]
fn a_given_inertia_prints_the_tensor_as_given_then_r_then_r_i_rt() {
    let text = triangle_and_given();
    assert!(text.contains("Ix′x′ = 0.02 kg·m²"), "{text}");
    assert!(text.contains("Iy′z′ = 0.002 kg·m²"), "{text}");
    let g = [
        [0.02, -0.001, 0.0],
        [-0.001, 0.03, 0.002],
        [0.0, 0.002, 0.04],
    ];
    let r: [[f64; 3]; 3] = std::array::from_fn(|a| {
        std::array::from_fn(|b| values(&text, &format!("R{}{}", a + 1, b + 1))[0])
    });
    let i = tensor_after(&text, "R33 = ");
    for a in 0..3 {
        for b in 0..3 {
            let want: f64 = (0..3)
                .flat_map(|k| (0..3).map(move |l| (k, l)))
                .map(|(k, l)| r[a][k] * g[k][l] * r[b][l])
                .sum();
            close(i[a][b], want, 0.04, &format!("I[{a}][{b}]"));
        }
    }
}

/// The value a line `LHS = … = VALUE …` prints first (not its exact
/// fraction): the last such line's.
fn printed(text: &str, lhs: &str) -> f64 {
    let head = format!("{lhs} = ");
    let line = text
        .lines()
        .map(str::trim)
        .rfind(|l| l.starts_with(&head))
        .unwrap_or_else(|| panic!("no line `{lhs} = …` in:\n{text}"));
    let last = line.rsplit(" = ").next().unwrap();
    last.split_whitespace().next().unwrap().parse().unwrap()
}

/// The explanation's final figures are the report's own f64s, bit for
/// bit, wherever the file's units are the report's (SI): the mass in kg,
/// G in m, I(G) and λ in kg·m², and always H and T.
fn final_figures_are_the_reports(args: &[&str], l: f64, k: f64) -> usize {
    let text = explain(args);
    let json = report(args);
    let num = |v: &Value| v.as_f64().unwrap();
    let same = |got: f64, want: &Value, what: &str| {
        assert_eq!(
            got.to_bits(),
            num(want).to_bits(),
            "{what}: {got} vs {want}"
        );
    };
    let mut n = 0;
    if k == 1.0 {
        same(printed(&text, "m"), &json["mass"], "mass");
        n += 1;
    }
    if l == 1.0 {
        for (i, a) in ["x_G", "y_G", "z_G"].iter().enumerate() {
            same(printed(&text, a), &json["center_of_mass"][i], a);
            n += 1;
        }
    }
    if l == 1.0 && k == 1.0 {
        for (name, (a, b)) in [
            ("Ixx(G)", (0, 0)),
            ("Iyy(G)", (1, 1)),
            ("Izz(G)", (2, 2)),
            ("Ixy(G)", (0, 1)),
            ("Ixz(G)", (0, 2)),
            ("Iyz(G)", (1, 2)),
        ] {
            same(printed(&text, name), &json["inertia_com"][a][b], name);
            n += 1;
        }
        for (i, name) in ["λ1", "λ2", "λ3"].iter().enumerate() {
            same(printed(&text, name), &json["principal_moments"][i], name);
            n += 1;
        }
    }
    if json["angular_momentum"].is_array() {
        for (i, name) in ["Hx", "Hy", "Hz"].iter().enumerate() {
            same(printed(&text, name), &json["angular_momentum"][i], name);
        }
        same(printed(&text, "T"), &json["kinetic_energy"], "T");
        n += 4;
    }
    n
}

#[test]
fn the_bent_plates_final_figures_are_the_reports_own_numbers() {
    // Its file is in mm: its mass (kg), H and T are the report's units.
    assert_eq!(final_figures_are_the_reports(&[BENT], 1e-3, 1.0), 5);
    let text = explain(&[BENT]);
    // The report's f64, then the exact sum beside it.
    assert!(
        text.contains("= 1.6624999999999999 (exactly 133/80) kg"),
        "{text}"
    );
}

#[test]
fn the_example_files_final_figures_are_the_reports_own_numbers() {
    let mut n = 0;
    for f in [
        "shapes/flywheel.toml",
        "shapes/motor-bracket.toml",
        "shapes/quickstart.toml",
    ] {
        let text = std::fs::read_to_string(f).unwrap();
        let (l, k) = units_of(&text);
        n += final_figures_are_the_reports(&[f], l, k);
    }
    // Each file in mm and kg: its mass; the flywheel's H and T.
    assert!(n >= 7, "{n} figures compared");
}

#[test]
fn an_si_files_final_figures_are_all_the_reports_own_numbers() {
    let dir = crate::common::scratch("explain", "si-figures");
    let f = dir.join("t.toml");
    std::fs::write(
        &f,
        "[[part]]\nname = \"block\"\nshape = \"box\"\ndensity = 1000\n\
         size = [0.2, 0.1, 0.05]\ncenter = [1, 0.3, 0]\nrotation = { quaternion = [0.8, 0.4, -0.4, 0.2] }\n\n\
         [[part]]\nname = \"can\"\nshape = \"cylinder\"\ndensity = 1000\nradius = 0.05\nlength = 0.3\n\
         center = [0, 1, 0.1]\nrotation = { intrinsic = \"zyx\", degrees = [30, 20, 10] }\n\n\
         [analysis]\nomega = [1.5, -2, 30]\n",
    )
    .unwrap();
    // m, G (3), I(G) (6), λ (3), H (3) and T.
    assert_eq!(
        final_figures_are_the_reports(&[f.to_str().unwrap()], 1.0, 1.0),
        17
    );
}
