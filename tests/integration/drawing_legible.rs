//! `massprop render`'s drawing is legible (issue 31, item 8): its colours
//! differ visibly from their neighbours (CIEDE2000 computed here from the
//! sRGB values in the SVG's `<style>`), its legend tells one kind apart,
//! no label overlaps another, the centre-of-mass symbol or an axis tip
//! (label boxes from the font size and the characters, by the rule
//! docs/render.md states), and cut-outs are painted after the parts they
//! overlap. Drawings of every part file in shapes/ and tests/, read with
//! roxmltree.

use super::common::{massprop, massprop_stdin};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

// ---- colour: sRGB → CIELAB (D65) → CIEDE2000 --------------------------

fn hex(c: &str) -> [f64; 3] {
    let v = u32::from_str_radix(c.trim_start_matches('#'), 16).expect("a #rrggbb colour");
    [16, 8, 0].map(|s| f64::from((v >> s) & 0xff) / 255.0)
}

/// IEC 61966-2-1: an sRGB channel to linear light.
fn linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// WCAG 2 relative luminance.
fn luminance(c: &str) -> f64 {
    let [r, g, b] = hex(c).map(linear);
    0.2126 * r + 0.7152 * g + 0.0722 * b
}

/// CIELAB of an sRGB colour, D65 white.
fn lab(c: &str) -> [f64; 3] {
    let [r, g, b] = hex(c).map(linear);
    let x = 0.412_456_4 * r + 0.357_576_1 * g + 0.180_437_5 * b;
    let y = 0.212_672_9 * r + 0.715_152_2 * g + 0.072_175_0 * b;
    let z = 0.019_333_9 * r + 0.119_192_0 * g + 0.950_304_1 * b;
    let f = |t: f64| {
        if t > 216.0 / 24389.0 {
            t.cbrt()
        } else {
            (24389.0 / 27.0 * t + 16.0) / 116.0
        }
    };
    let (fx, fy, fz) = (f(x / 0.950_47), f(y), f(z / 1.088_83));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

/// CIEDE2000 (Sharma, Wu and Dalal 2005, equations 1–17; kL = kC = kH = 1).
fn ciede2000(p: [f64; 3], q: [f64; 3]) -> f64 {
    let [l1, a1, b1] = p;
    let [l2, a2, b2] = q;
    let c7 = |c: f64| c.powi(7) / (c.powi(7) + 25f64.powi(7));
    let cbar = (a1.hypot(b1) + a2.hypot(b2)) / 2.0;
    let g = 0.5 * (1.0 - c7(cbar).sqrt());
    let (a1, a2) = ((1.0 + g) * a1, (1.0 + g) * a2);
    let (c1, c2) = (a1.hypot(b1), a2.hypot(b2));
    let hue = |b: f64, a: f64| {
        if a == 0.0 && b == 0.0 {
            0.0
        } else {
            b.atan2(a).to_degrees().rem_euclid(360.0)
        }
    };
    let (h1, h2) = (hue(b1, a1), hue(b2, a2));
    let dl = l2 - l1;
    let dc = c2 - c1;
    let dh = if c1 * c2 == 0.0 {
        0.0
    } else if (h2 - h1).abs() <= 180.0 {
        h2 - h1
    } else if h2 - h1 > 180.0 {
        h2 - h1 - 360.0
    } else {
        h2 - h1 + 360.0
    };
    let dhh = 2.0 * (c1 * c2).sqrt() * (dh / 2.0).to_radians().sin();
    let lbar = (l1 + l2) / 2.0;
    let cbar = (c1 + c2) / 2.0;
    let hbar = if c1 * c2 == 0.0 {
        h1 + h2
    } else if (h1 - h2).abs() <= 180.0 {
        (h1 + h2) / 2.0
    } else if h1 + h2 < 360.0 {
        (h1 + h2 + 360.0) / 2.0
    } else {
        (h1 + h2 - 360.0) / 2.0
    };
    let cos = |d: f64| d.to_radians().cos();
    let t = 1.0 - 0.17 * cos(hbar - 30.0) + 0.24 * cos(2.0 * hbar) + 0.32 * cos(3.0 * hbar + 6.0)
        - 0.20 * cos(4.0 * hbar - 63.0);
    let dtheta = 30.0 * (-((hbar - 275.0) / 25.0).powi(2)).exp();
    let rc = 2.0 * c7(cbar).sqrt();
    let sl = 1.0 + 0.015 * (lbar - 50.0).powi(2) / (20.0 + (lbar - 50.0).powi(2)).sqrt();
    let sc = 1.0 + 0.045 * cbar;
    let sh = 1.0 + 0.015 * cbar * t;
    let rt = -(2.0 * dtheta).to_radians().sin() * rc;
    let (x, y, z) = (dl / sl, dc / sc, dhh / sh);
    (x * x + y * y + z * z + rt * y * z).sqrt()
}

#[test]
fn the_colour_difference_matches_sharmas_published_pairs() {
    // Sharma, Wu and Dalal (2005), table 1: pairs 1, 7, 17, 25 and 11.
    for (p, q, want) in [
        ([50.0, 2.6772, -79.7751], [50.0, 0.0, -82.7485], 2.0425),
        ([50.0, 0.0, 0.0], [50.0, -1.0, 2.0], 2.3669),
        ([50.0, 2.5, 0.0], [73.0, 25.0, -18.0], 27.1492),
        (
            [60.2574, -34.0099, 36.2677],
            [60.4626, -34.1751, 39.4387],
            1.2644,
        ),
        ([50.0, 2.5, 0.0], [50.0, 0.0, -2.5], 4.3065),
    ] {
        let got = ciede2000(p, q);
        assert!(
            (got - want).abs() < 5e-5,
            "{p:?} {q:?}: {got} against {want}"
        );
    }
}

// ---- the drawings ------------------------------------------------------

/// Every part file in shapes/ and tests/ that `render` draws (exit 0),
/// with its SVG; drawn once for all the tests here.
fn drawings() -> &'static [(String, String)] {
    static ALL: OnceLock<Vec<(String, String)>> = OnceLock::new();
    ALL.get_or_init(|| {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut files = Vec::new();
        for dir in ["shapes", "tests"] {
            collect(&root.join(dir), &mut files);
        }
        files.sort();
        // Two at a time: the machine has two cores.
        let half = files.len().div_ceil(2);
        let mut all: Vec<(String, String)> = std::thread::scope(|s| {
            let parts: Vec<_> = files
                .chunks(half.max(1))
                .map(|chunk| {
                    s.spawn(move || {
                        chunk
                            .iter()
                            .filter_map(|f| draw(root, f))
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            parts
                .into_iter()
                .flat_map(|h| h.join().expect("a drawing thread"))
                .collect::<Vec<_>>()
        });
        all.sort();
        assert!(all.len() > 50, "only {} files drew", all.len());
        all
    })
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).expect("a test directory").flatten() {
        let path = e.path();
        if path.is_dir() {
            collect(&path, out);
        } else if path.extension().is_some_and(|x| x == "toml") {
            out.push(path);
        }
    }
}

fn draw(root: &Path, file: &Path) -> Option<(String, String)> {
    let name = file
        .strip_prefix(root)
        .unwrap_or(file)
        .display()
        .to_string();
    let out = massprop(&["render", file.to_str()?]);
    (out.status.code() == Some(0)).then(|| {
        let svg = String::from_utf8(out.stdout).expect("the SVG is UTF-8");
        (name, svg)
    })
}

fn render(text: &str, args: &[&str]) -> String {
    let mut all = vec!["render", "-"];
    all.extend_from_slice(args);
    let out = massprop_stdin(&all, text);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("the SVG is UTF-8")
}

// ---- what the SVG says -------------------------------------------------

/// The `.cN{stroke:#…}` rules of the `<style>`, in N's order.
fn palette(doc: &roxmltree::Document) -> Vec<String> {
    let style = doc
        .descendants()
        .find(|n| n.has_tag_name("style"))
        .and_then(|n| n.text())
        .expect("a <style>");
    let mut out: Vec<(usize, String)> = style
        .lines()
        .filter_map(|l| {
            let rest = l.strip_prefix(".c")?;
            let (n, rule) = rest.split_once('{')?;
            let colour = rule.strip_prefix("stroke:")?.strip_suffix('}')?;
            Some((n.parse().ok()?, colour.to_string()))
        })
        .collect();
    out.sort();
    out.into_iter().map(|(_, c)| c).collect()
}

/// The `text{…font-size:Npx…}` rule's N.
fn font_size(doc: &roxmltree::Document) -> f64 {
    let style = doc
        .descendants()
        .find(|n| n.has_tag_name("style"))
        .and_then(|n| n.text())
        .expect("a <style>");
    let rule = style
        .lines()
        .find(|l| l.starts_with("text{"))
        .expect("a text rule");
    let size = rule.split("font-size:").nth(1).expect("a font size");
    size[..size.find("px").expect("px")]
        .parse()
        .expect("a number")
}

/// A character's advance in em, as docs/render.md ("Labels") states it.
fn advance(c: char) -> f64 {
    use unicode_width::UnicodeWidthChar;
    if "mwMW@%…—".contains(c) {
        1.0
    } else if "ijlftI .,:;'|!()[]".contains(c) {
        0.4
    } else if c.is_ascii_lowercase() || c.is_ascii_digit() {
        0.64
    } else {
        match c.width() {
            Some(0) => 0.0,
            Some(2) => 1.0,
            _ => 0.85,
        }
    }
}

/// A label as drawn: its words and its box (left, top, right, bottom),
/// 0.95 em above the baseline to 0.25 em below.
#[derive(Debug)]
struct Label {
    words: String,
    b: [f64; 4],
}

fn number(n: roxmltree::Node, key: &str) -> f64 {
    n.attribute(key)
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{key} of {n:?}"))
}

fn labels_in(n: roxmltree::Node, font: f64) -> Vec<Label> {
    n.descendants()
        .filter(|t| t.has_tag_name("text"))
        .map(|t| {
            assert!(
                t.attribute("text-anchor").is_none(),
                "anchored at its start"
            );
            let words: String = t.text().unwrap_or("").to_string();
            let (x, y) = (number(t, "x"), number(t, "y"));
            let w = font * words.chars().map(advance).sum::<f64>();
            Label {
                b: [x, y - 0.95 * font, x + w, y + 0.25 * font],
                words,
            }
        })
        .collect()
}

fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

fn distance(b: &[f64; 4], p: [f64; 2]) -> f64 {
    let dx = (b[0] - p[0]).max(p[0] - b[2]).max(0.0);
    let dy = (b[1] - p[1]).max(p[1] - b[3]).max(0.0);
    dx.hypot(dy)
}

/// The views (`<g data-scale>`) of a drawing.
fn views<'a>(doc: &'a roxmltree::Document) -> Vec<roxmltree::Node<'a, 'a>> {
    doc.descendants()
        .filter(|n| n.has_tag_name("g") && n.attribute("data-scale").is_some())
        .collect()
}

/// The centre-of-mass symbol in a view: its circle (radius 7, black
/// outline, white inside), centre and radius.
fn centre_of_mass(view: roxmltree::Node) -> ([f64; 2], f64) {
    let c = view
        .children()
        .find(|n| {
            n.has_tag_name("circle")
                && n.attribute("style")
                    .is_some_and(|s| s.contains("fill:#fff;stroke:#000"))
        })
        .expect("a centre-of-mass symbol");
    ([number(c, "cx"), number(c, "cy")], number(c, "r"))
}

/// The principal axes' tips in a view: the ends of the three 2.5 px
/// lines `M centre L tip` in the axes' colours.
fn axis_tips(view: roxmltree::Node) -> Vec<[f64; 2]> {
    let tips: Vec<[f64; 2]> = view
        .children()
        .filter(|n| {
            n.attribute("style").is_some_and(|s| {
                s.contains("stroke-width:2.5")
                    && ["#e00000", "#00a000", "#0000e0"]
                        .iter()
                        .any(|c| s.contains(&format!("stroke:{c}")))
            })
        })
        .map(|n| {
            let d = n.attribute("d").expect("a path");
            let to = d.split('L').nth(1).expect("M centre L tip");
            let v: Vec<f64> = to.split(' ').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1]]
        })
        .collect();
    assert_eq!(tips.len(), 3, "three axes");
    tips
}

/// Every way a drawing's labels fail to be legible, in words.
fn label_faults(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses");
    let font = font_size(&doc);
    let page = number(doc.root_element(), "width");
    let mut faults = Vec::new();
    let all = labels_in(doc.root_element(), font);
    for (i, a) in all.iter().enumerate() {
        if a.b[0] < 0.0 || a.b[2] > page {
            faults.push(format!("{:?} runs off the page", a.words));
        }
        for b in &all[i + 1..] {
            if overlap(&a.b, &b.b) {
                faults.push(format!("{:?} overlaps {:?}", a.words, b.words));
            }
        }
    }
    for view in views(&doc) {
        let (cg, r) = centre_of_mass(view);
        let tips = axis_tips(view);
        for l in labels_in(view, font) {
            // The symbol's outline is 1.5 px wide: 0.75 outside its radius.
            if distance(&l.b, cg) <= r + 0.75 {
                faults.push(format!("{:?} overlaps the centre of mass", l.words));
            }
            for tip in &tips {
                // The axes are 2.5 px wide: their tips reach 1.25 px.
                if distance(&l.b, *tip) <= 1.25 {
                    faults.push(format!("{:?} overlaps an axis tip at {tip:?}", l.words));
                }
            }
        }
    }
    faults
}

#[test]
fn no_label_overlaps_another_the_centre_of_mass_or_an_axis_tip_in_any_drawing() {
    let mut faults = Vec::new();
    for (name, svg) in drawings() {
        faults.extend(
            label_faults(svg)
                .into_iter()
                .map(|f| format!("{name}: {f}")),
        );
    }
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}

// ---- paint order of cut-outs -------------------------------------------

/// The box of an element's path data or circle, px: every point the
/// commands reach (`M L H V Z`, relative too), an arc widened to the
/// square of twice its larger radius about its chord's midpoint (which
/// holds any arc of those radii).
fn bbox(n: roxmltree::Node) -> [f64; 4] {
    if n.has_tag_name("circle") {
        let (x, y, r) = (number(n, "cx"), number(n, "cy"), number(n, "r"));
        return [x - r, y - r, x + r, y + r];
    }
    let d = n.attribute("d").expect("path data");
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    let add = |p: [f64; 2], b: &mut [f64; 4]| {
        b[0] = b[0].min(p[0]);
        b[1] = b[1].min(p[1]);
        b[2] = b[2].max(p[0]);
        b[3] = b[3].max(p[1]);
    };
    // Commands and their numbers.
    let mut commands: Vec<(char, Vec<f64>)> = Vec::new();
    let mut word = String::new();
    let flush = |word: &mut String, commands: &mut Vec<(char, Vec<f64>)>| {
        if !word.is_empty() {
            let x = word.parse().unwrap_or_else(|_| panic!("a number: {word}"));
            commands.last_mut().expect("a command first").1.push(x);
            word.clear();
        }
    };
    for c in d.chars() {
        if c.is_ascii_alphabetic() {
            flush(&mut word, &mut commands);
            commands.push((c, Vec::new()));
        } else if c == ' ' || c == ',' || (c == '-' && !word.is_empty()) {
            flush(&mut word, &mut commands);
            if c == '-' {
                word.push(c);
            }
        } else {
            word.push(c);
        }
    }
    flush(&mut word, &mut commands);
    let (mut at, mut start) = ([0.0, 0.0], [0.0, 0.0]);
    for (c, v) in commands {
        let rel = c.is_ascii_lowercase();
        let base = |at: [f64; 2]| if rel { at } else { [0.0, 0.0] };
        match c.to_ascii_uppercase() {
            'M' | 'L' => {
                for (k, p) in v.chunks(2).enumerate() {
                    let base = base(at);
                    at = [base[0] + p[0], base[1] + p[1]];
                    if c.eq_ignore_ascii_case(&'M') && k == 0 {
                        start = at;
                    }
                    add(at, &mut b);
                }
            }
            'H' => {
                at[0] = base(at)[0] + v[0];
                add(at, &mut b);
            }
            'V' => {
                at[1] = base(at)[1] + v[0];
                add(at, &mut b);
            }
            'A' => {
                for a in v.chunks(7) {
                    let base = base(at);
                    let to = [base[0] + a[5], base[1] + a[6]];
                    let mid = [(at[0] + to[0]) / 2.0, (at[1] + to[1]) / 2.0];
                    let r = 2.0 * a[0].abs().max(a[1].abs());
                    add([mid[0] - r, mid[1] - r], &mut b);
                    add([mid[0] + r, mid[1] + r], &mut b);
                    at = to;
                    add(at, &mut b);
                }
            }
            'Z' => at = start,
            other => panic!("path command {other} in {d}"),
        }
    }
    b
}

/// The cut-outs (class `cut`) of each view painted before a part element
/// whose box meets theirs: a part is an element with a colour class, or
/// a marker in a palette colour.
fn order_faults(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses");
    let colours = palette(&doc);
    let mut faults = Vec::new();
    for view in views(&doc) {
        let mut cuts: Vec<(usize, [f64; 4])> = Vec::new();
        let mut parts: Vec<(usize, [f64; 4])> = Vec::new();
        for (k, n) in view.children().filter(|n| n.is_element()).enumerate() {
            let class = n.attribute("class").unwrap_or("");
            let style = n.attribute("style").unwrap_or("");
            let coloured = class.split(' ').any(|c| {
                c.strip_prefix('c')
                    .is_some_and(|d| d.parse::<usize>().is_ok())
            }) || colours
                .iter()
                .any(|c| style == format!("fill:{c}") || style == format!("stroke:{c}"));
            if !coloured {
                continue;
            }
            if class.split(' ').any(|c| c == "cut") {
                cuts.push((k, bbox(n)));
            } else {
                parts.push((k, bbox(n)));
            }
        }
        for (i, cut) in &cuts {
            for (j, part) in &parts {
                if j > i && overlap(cut, part) {
                    faults.push(format!(
                        "{}: cut-out (element {i}) painted under a part (element {j})",
                        view.attribute("id").unwrap_or("?")
                    ));
                }
            }
        }
    }
    faults
}

#[test]
fn every_cut_out_is_painted_after_every_part_it_overlaps_in_any_drawing() {
    let mut faults = Vec::new();
    let mut cut = 0;
    for (name, svg) in drawings() {
        cut += usize::from(svg.contains(" cut\""));
        faults.extend(
            order_faults(svg)
                .into_iter()
                .map(|f| format!("{name}: {f}")),
        );
    }
    assert!(cut >= 2, "only {cut} drawings have cut-outs");
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}

/// A plate with a small hole near its start, and a foot written after
/// it across the hole: in file order the foot would hide the hole.
const HOLE_UNDER_A_FOOT: &str = r#"
units = { length = "mm", mass = "g" }
[[part]]
shape = "box"
size = [200, 200, 10]
center = [0, 0, 5]
density = "2.7 g/cm^3"
[[part]]
shape = "cylinder"
radius = 6
length = 10
center = [60, 60, 5]
density = "2.7 g/cm^3"
remove = true
[[part]]
shape = "box"
size = [30, 30, 20]
center = [60, 60, -10]
density = "2.7 g/cm^3"
"#;

#[test]
fn a_hole_written_before_a_foot_that_covers_it_is_painted_after_the_foot() {
    let svg = render(HOLE_UNDER_A_FOOT, &[]);
    assert_eq!(svg.matches(" cut\"").count(), 4, "the hole in each view");
    assert!(order_faults(&svg).is_empty(), "{:?}", order_faults(&svg));
    // In file order (the hole before the foot) the same test sees the
    // foot painted over the hole.
    let mut lines: Vec<&str> = svg.lines().collect();
    for i in 1..lines.len() {
        if lines[i].contains(" cut\"") && lines[i - 1].starts_with("<path class=\"c") {
            lines.swap(i - 1, i);
        }
    }
    let file_order = lines.join("\n");
    assert!(!order_faults(&file_order).is_empty(), "{file_order}");
}

// ---- the palette -------------------------------------------------------

/// The two figures docs/render.md states: the least ΔE00 between
/// neighbouring colours, and between any two.
fn stated_differences() -> [f64; 2] {
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/render.md"))
        .expect("docs/render.md");
    let figures: Vec<f64> = doc
        .split("ΔE00 = ")
        .skip(1)
        .map(|s| {
            let n: String = s
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.')
                .collect();
            n.trim_end_matches('.').parse().expect("a figure")
        })
        .collect();
    assert_eq!(figures.len(), 2, "two figures: {figures:?}");
    [figures[0], figures[1]]
}

fn drawn_palette() -> Vec<String> {
    let svg = render(HOLE_UNDER_A_FOOT, &[]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    palette(&doc)
}

#[test]
fn neighbouring_colours_differ_by_at_least_the_documented_ciede2000() {
    let p = drawn_palette();
    assert!(p.len() >= 6, "{p:?}");
    // Past the last the colours repeat from the first: those neighbour too.
    let least = (0..p.len())
        .map(|k| ciede2000(lab(&p[k]), lab(&p[(k + 1) % p.len()])))
        .fold(f64::INFINITY, f64::min);
    let [stated, _] = stated_differences();
    assert!(
        least >= stated && least < stated + 0.1,
        "least ΔE00 between neighbours {least:.2}, docs/render.md says {stated}"
    );
}

#[test]
fn any_two_colours_differ_by_at_least_the_documented_ciede2000() {
    let p = drawn_palette();
    let mut least = f64::INFINITY;
    for i in 0..p.len() {
        for j in i + 1..p.len() {
            least = least.min(ciede2000(lab(&p[i]), lab(&p[j])));
        }
    }
    let [_, stated] = stated_differences();
    assert!(
        least >= stated && least < stated + 0.1,
        "least ΔE00 of any two {least:.2}, docs/render.md says {stated}"
    );
    // Visibly different: well past the just-noticeable difference (~1–2).
    assert!(least > 20.0, "{least}");
}

#[test]
fn every_colour_is_at_least_three_to_one_against_white() {
    for c in drawn_palette() {
        let ratio = 1.05 / (luminance(&c) + 0.05);
        assert!(ratio >= 3.0, "{c}: {ratio:.2}:1");
    }
}

// ---- one legend kind -----------------------------------------------------

/// The names of the legend's colours (the words after each colour
/// sample, a 3 px line).
fn legend_names(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let legend = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("legend"))
        .expect("a legend");
    let items: Vec<_> = legend.children().filter(|n| n.is_element()).collect();
    items
        .windows(2)
        .filter(|w| {
            w[0].attribute("style")
                .is_some_and(|s| s.ends_with(";stroke-width:3"))
                && w[1].has_tag_name("text")
        })
        .map(|w| w[1].text().unwrap_or("").to_string())
        .collect()
}

const STEEL_AND_A_SPHERE: &str = r#"
[[part]]
shape = "box"
material = "steel"
size = [1, 1, 1]
center = [0, 0, 0]
[[part]]
shape = "sphere"
radius = 0.5
center = [2, 0, 0]
mass = 1
[[part]]
shape = "cylinder"
material = "aluminium-6061"
radius = 0.2
length = 1
center = [0, 2, 0]
"#;

#[test]
fn a_drawing_with_materials_names_materials_only() {
    let svg = render(STEEL_AND_A_SPHERE, &[]);
    assert_eq!(
        legend_names(&svg),
        ["steel", "(no material)", "aluminium-6061"],
        "{svg}"
    );
    assert!(svg.contains("colours by material"));
}

#[test]
fn a_drawing_with_groups_names_groups_only() {
    let text = format!("{STEEL_AND_A_SPHERE}group = \"frame\"\n");
    let svg = render(&text, &[]);
    assert_eq!(legend_names(&svg), ["(no group)", "frame"], "{svg}");
    assert!(svg.contains("colours by group"));
}

#[test]
fn a_drawing_without_groups_or_materials_names_shapes() {
    let svg = render(
        "[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nmass = 1\n\
         [[part]]\nshape = \"sphere\"\nradius = 0.5\ncenter = [2, 0, 0]\nmass = 1\n",
        &[],
    );
    assert_eq!(legend_names(&svg), ["box", "sphere"], "{svg}");
    assert!(svg.contains("colours by shape"));
}

#[test]
fn every_drawing_names_one_kind_in_its_legend() {
    for (name, svg) in drawings() {
        let kinds = ["group", "material", "shape"]
            .iter()
            .filter(|k| svg.contains(&format!("colours by {k}<")))
            .count();
        assert_eq!(kinds, 1, "{name}");
    }
}

// ---- crowded drawings ------------------------------------------------------

#[test]
fn labels_stay_clear_where_an_axis_is_seen_end_on_with_omega_and_about_at_the_centre() {
    // A long rod along z: I3 end-on from the top, its tip on the centre
    // of mass; ω along z and `about` there too.
    let svg = render(
        "[[part]]\nshape = \"cylinder\"\nradius = 0.1\nlength = 4\ncenter = [0, 0, 0]\nmass = 1\n",
        &["--omega", "0,0,3", "--about", "0,0,0"],
    );
    let faults = label_faults(&svg);
    assert!(faults.is_empty(), "{faults:?}");
}

#[test]
fn labels_stay_clear_for_a_cube_whose_axes_are_all_alike() {
    let svg = render(
        "[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nmass = 1\n",
        &["--omega", "1,1,1", "--about", "0.1,0.1,0.1"],
    );
    let faults = label_faults(&svg);
    assert!(faults.is_empty(), "{faults:?}");
}

#[test]
fn long_names_in_the_legend_neither_meet_nor_leave_the_page() {
    let mut text = String::new();
    for (k, name) in [
        "a",
        "power / battery / cells / the long row of them on the left",
        &"W".repeat(200),
        "structure",
        "thermal / radiator panels and their heat pipes",
        "中文名称的部件组",
    ]
    .iter()
    .enumerate()
    {
        text.push_str(&format!(
            "[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [{k}, 0, 0]\nmass = 1\ngroup = \"{name}\"\n"
        ));
    }
    let svg = render(&text, &[]);
    let faults = label_faults(&svg);
    assert!(faults.is_empty(), "{faults:?}");
    assert_eq!(legend_names(&svg).len(), 6);
}
