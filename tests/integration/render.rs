//! `massprop render`: the SVG parsed and rasterised by resvg, and pixels
//! looked at where the centre of mass and the principal axes' tips must
//! be, by projection maths written here from docs/render.md's conventions
//! (not the renderer's own).

use super::common::{massprop, massprop_stdin, scratch, scratch_files};

/// `massprop render - ARGS…` on `text`: the SVG, checked to parse.
fn render(text: &str, args: &[&str]) -> String {
    let mut all = vec!["render", "-"];
    all.extend_from_slice(args);
    let out = massprop_stdin(&all, text);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let svg = String::from_utf8(out.stdout).expect("the SVG is UTF-8");
    parse(&svg);
    svg
}

fn parse(svg: &str) -> resvg::usvg::Tree {
    resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default())
        .unwrap_or_else(|e| panic!("not SVG: {e}\n{svg}"))
}

/// The SVG rasterised at one pixel per user unit.
fn raster(svg: &str) -> resvg::tiny_skia::Pixmap {
    let tree = parse(svg);
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    pixmap
}

/// The colour at page point `p` (rounded to the pixel it falls in).
fn pixel(map: &resvg::tiny_skia::Pixmap, p: [f64; 2]) -> [u8; 3] {
    let c = map
        .pixel(p[0].floor() as u32, p[1].floor() as u32)
        .unwrap_or_else(|| panic!("{p:?} is off the page"));
    [c.red(), c.green(), c.blue()]
}

fn near(a: [u8; 3], b: [u8; 3], tol: i32) -> bool {
    (0..3).all(|k| (i32::from(a[k]) - i32::from(b[k])).abs() <= tol)
}

fn hex(c: &str) -> [u8; 3] {
    let v = u32::from_str_radix(c.trim_start_matches('#'), 16).unwrap();
    [(v >> 16) as u8, (v >> 8) as u8, v as u8]
}

/// A view's placing as the SVG states it: pixels per length unit and the
/// page position of the origin.
fn placing(svg: &str, view: &str) -> (f64, [f64; 2]) {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let g = doc
        .descendants()
        .find(|n| n.attribute("id") == Some(view))
        .unwrap_or_else(|| panic!("no view {view}"));
    let scale: f64 = g.attribute("data-scale").unwrap().parse().unwrap();
    let o: Vec<f64> = g
        .attribute("data-origin")
        .unwrap()
        .split(' ')
        .map(|x| x.parse().unwrap())
        .collect();
    (scale, [o[0], o[1]])
}

/// Right and up on the page for each view, from docs/render.md: front
/// x right z up; top x right y up; side y right z up; iso right
/// (1, 1, 0)/√2, up (−1, 1, 2)/√6.
fn plane(view: &str) -> [[f64; 3]; 2] {
    match view {
        "front" => [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        "top" => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        "side" => [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        "iso" => {
            let (a, b) = (1.0 / 2f64.sqrt(), 1.0 / 6f64.sqrt());
            [[a, a, 0.0], [-b, b, 2.0 * b]]
        }
        _ => unreachable!(),
    }
}

fn on_page(svg: &str, view: &str, p: [f64; 3]) -> [f64; 2] {
    let (s, o) = placing(svg, view);
    let [r, u] = plane(view);
    let dot = |a: [f64; 3]| a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
    [o[0] + s * dot(r), o[1] - s * dot(u)]
}

const BLACK: [u8; 3] = [0, 0, 0];
const WHITE: [u8; 3] = [255, 255, 255];

/// A box 6 × 3 × 1.5 m turned 30° about z, at (1, 2, 3): its principal
/// axes (long edge first: I1 is the least moment) and radii of gyration
/// derived here, k² = (b² + c²)/12.
const BOX: &str = r#"
units = { length = "m", mass = "kg" }
[[part]]
shape = "box"
size = [6, 3, 1.5]
center = [1, 2, 3]
rotation = { axis = [0, 0, 1], degrees = 30 }
mass = 10
"#;

#[test]
fn the_centre_of_mass_and_the_axis_tips_are_drawn_where_they_must_be() {
    let svg = render(BOX, &[]);
    let map = raster(&svg);
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    let k = |a: f64, b: f64| ((a * a + b * b) / 12.0).sqrt();
    // Each axis up to its sign (the sign rule is report's business).
    let axes = [
        ([c, s, 0.0], k(3.0, 1.5)),
        ([-s, c, 0.0], k(6.0, 1.5)),
        ([0.0, 0.0, 1.0], k(6.0, 3.0)),
    ];
    let cg = [1.0, 2.0, 3.0];
    let colours = ["#e00000", "#00a000", "#0000e0"];
    let mut checked = 0;
    for view in ["front", "top", "side", "iso"] {
        let at = on_page(&svg, view, cg);
        // The quartered symbol: upper right and lower left black.
        assert_eq!(pixel(&map, [at[0] + 3.0, at[1] - 3.0]), BLACK, "{view}");
        assert_eq!(pixel(&map, [at[0] - 3.0, at[1] + 3.0]), BLACK, "{view}");
        assert_eq!(pixel(&map, [at[0] + 3.0, at[1] + 3.0]), WHITE, "{view}");
        assert_eq!(pixel(&map, [at[0] - 3.0, at[1] - 3.0]), WHITE, "{view}");
        for (n, ((dir, k), colour)) in axes.iter().zip(colours).enumerate() {
            let ends = [1.0, -1.0].map(|sign| {
                let p = std::array::from_fn(|i| cg[i] + sign * 0.9 * k * dir[i]);
                on_page(&svg, view, p)
            });
            let len = (ends[0][0] - at[0]).hypot(ends[0][1] - at[1]);
            if len < 20.0 {
                continue; // seen end-on
            }
            // An axis drawn later over this one, both seen in one line.
            let covered = axes[n + 1..].iter().any(|(d, k)| {
                let [a, b] = [1.0, -1.0].map(|sign| {
                    on_page(&svg, view, std::array::from_fn(|i| cg[i] + sign * k * d[i]))
                });
                ends.iter().any(|p| distance_to_segment(*p, a, b) < 3.0)
            });
            if covered {
                continue;
            }
            // 90 % of the way to the tip, on one side or the other.
            let drawn = ends
                .iter()
                .filter(|p| near(pixel(&map, **p), hex(colour), 60))
                .count();
            assert_eq!(drawn, 1, "{view}: {colour} at {ends:?}");
            // Past the tip: not the axis.
            let beyond = [1.0, -1.0].map(|sign| {
                let p = std::array::from_fn(|i| cg[i] + sign * 1.3 * k * dir[i]);
                on_page(&svg, view, p)
            });
            assert!(
                beyond
                    .iter()
                    .all(|p| !near(pixel(&map, *p), hex(colour), 60)),
                "{view}: {colour} past its tip"
            );
            checked += 1;
        }
    }
    // Front: I1 and I2 both lie off the page plane by 30°, I3 up; every
    // axis somewhere.
    assert!(checked >= 8, "{checked}");
}

/// The distance from `p` to the segment from `a` to `b`, px.
fn distance_to_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - t * dx).hypot(p[1] - a[1] - t * dy)
}

/// One part of each shape, to draw alone.
fn shape_parts(mesh: &str) -> Vec<(&'static str, String)> {
    vec![
        ("box", "shape = \"box\"\nsize = [2, 1, 1]\ncenter = [0, 0, 0]".into()),
        ("plate", "shape = \"plate\"\nsize = [2, 1]\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 30 }".into()),
        ("rod", "shape = \"rod\"\nfrom = [0, 0, 0]\nto = [2, 1, 1]".into()),
        ("cylinder", "shape = \"cylinder\"\nradius = 0.5\nlength = 2\ncenter = [0, 0, 0]\nrotation = { axis = [1, 1, 0], degrees = 40 }".into()),
        ("tube", "shape = \"cylinder\"\nradius = 0.5\ninner_radius = 0.4\nlength = 2\ncenter = [0, 0, 0]".into()),
        ("disk", "shape = \"disk\"\nradius = 1\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 60 }".into()),
        ("sphere", "shape = \"sphere\"\nradius = 1\ncenter = [0, 0, 0]".into()),
        ("triangle", "shape = \"triangle\"\nvertices = [[0, 0, 0], [2, 0, 0], [0, 1, 1]]".into()),
        ("cone", "shape = \"cone\"\nradius = 1\ntop_radius = 0.3\nlength = 2\ncenter = [0, 0, 0]\nrotation = { axis = [0, 1, 0], degrees = 30 }".into()),
        ("torus", "shape = \"torus\"\nradius = 1\ntube_radius = 0.25\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 50 }".into()),
        ("hemisphere", "shape = \"hemisphere\"\nradius = 1\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 120 }".into()),
        ("capsule", "shape = \"capsule\"\nradius = 0.5\nlength = 1.5\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 35 }".into()),
        ("ellipsoid", "shape = \"ellipsoid\"\nradii = [1, 0.6, 0.3]\ncenter = [0, 0, 0]\nrotation = { axis = [1, 1, 0], degrees = 40 }".into()),
        ("prism", "shape = \"prism\"\npolygon = [[0, 0], [2, 0], [2, 1], [1, 0.4], [0, 1]]\nlength = 0.5".into()),
        ("mesh", format!("shape = \"mesh\"\nfile = \"{mesh}\"\nmesh_unit = \"mm\"")),
    ]
}

#[test]
fn each_shape_draws_an_outline_in_its_colour() {
    let dir = scratch("render", "shapes");
    let mesh = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shapes/meshes/bracket.stl");
    std::fs::copy(&mesh, dir.join("bracket.stl")).unwrap();
    for (name, part) in shape_parts("bracket.stl") {
        let file = dir.join(format!("{name}.toml"));
        std::fs::write(
            &file,
            format!("units = {{ length = \"m\", mass = \"kg\" }}\n[[part]]\n{part}\nmass = 1\n"),
        )
        .unwrap();
        let out = massprop(&["render", file.to_str().unwrap()]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let svg = String::from_utf8(out.stdout).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let paths: Vec<_> = doc
            .descendants()
            .filter(|n| n.attribute("class") == Some("c0"))
            .collect();
        assert_eq!(paths.len(), 4, "{name}: one path a view");
        assert!(
            paths
                .iter()
                .all(|p| p.attribute("d").is_some_and(|d| d.len() > 10)),
            "{name}: an empty path"
        );
        // The first colour shows on the page.
        let map = raster(&svg);
        let coloured = map
            .pixels()
            .iter()
            .filter(|c| near([c.red(), c.green(), c.blue()], hex("#1b9e77"), 40))
            .count();
        assert!(coloured > 50, "{name}: {coloured} pixels of its colour");
    }
}

#[test]
fn point_masses_and_given_inertias_are_markers() {
    let svg = render(
        r#"
[[part]]
shape = "point"
mass = 1
center = [0, 0, 0]
[[part]]
shape = "inertia"
mass = 1
center = [1, 0, 0]
inertia = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
"#,
        &[],
    );
    assert_eq!(svg.matches("r=\"3.50\" style=\"fill:#1b9e77\"").count(), 4);
    assert!(svg.contains("point mass"), "{svg}");
    assert!(svg.contains("given inertia"), "{svg}");
}

#[test]
fn cut_outs_are_dashed() {
    let svg = render(
        r#"
[[part]]
shape = "box"
size = [2, 2, 2]
center = [0, 0, 0]
density = 1
[[part]]
shape = "cylinder"
radius = 0.3
length = 2
center = [0, 0, 0]
density = 1
remove = true
"#,
        &[],
    );
    let tree = parse(&svg);
    let mut dashed = Vec::new();
    fn walk(g: &resvg::usvg::Group, out: &mut Vec<Vec<f32>>) {
        for n in g.children() {
            match n {
                resvg::usvg::Node::Group(g) => walk(g, out),
                resvg::usvg::Node::Path(p) => {
                    if let Some(d) = p.stroke().and_then(|s| s.dasharray()) {
                        out.push(d.to_vec());
                    }
                }
                _ => {}
            }
        }
    }
    walk(tree.root(), &mut dashed);
    // Four views of the cut-out (the ellipsoid's dots are 2 3), and the
    // legend's sample.
    assert_eq!(
        dashed.iter().filter(|d| **d == [5.0, 3.0]).count(),
        5,
        "{dashed:?}"
    );
    assert!(svg.contains("cut-out (remove = true)"));
}

#[test]
fn parts_smaller_than_a_pixel_are_counted_not_drawn() {
    let svg = render(
        r#"
[[part]]
shape = "box"
size = [1000, 1000, 1000]
center = [0, 0, 0]
mass = 1
[[part]]
shape = "box"
size = [0.001, 0.001, 0.001]
center = [100, 0, 0]
mass = 1
[[part]]
shape = "sphere"
radius = 0.001
center = [0, 100, 0]
mass = 1
"#,
        &[],
    );
    assert!(
        svg.contains("2 parts smaller than a pixel not drawn"),
        "{svg}"
    );
}

#[test]
fn groups_colour_the_parts_and_name_the_legend() {
    let svg = render(
        r#"
[[part]]
shape = "box"
size = [1, 1, 1]
center = [0, 0, 0]
mass = 1
group = "structure"
[[part]]
shape = "sphere"
radius = 0.5
center = [2, 0, 0]
mass = 1
group = "payload"
"#,
        &[],
    );
    assert!(svg.contains(">structure</text>") && svg.contains(">payload</text>"));
    assert_eq!(svg.matches("class=\"c1\"").count(), 4);
}

#[test]
fn materials_colour_the_parts_without_a_group() {
    // Two aluminium parts (one inside a sub-assembly, which the walk
    // places) and a steel one. (A group on any part would colour the
    // drawing by group: tests/integration/drawing_legible.rs.)
    let path = scratch_files(
        "render",
        "materials",
        &[
            (
                "sub.toml",
                "[[part]]\nshape = \"box\"\nmaterial = \"aluminium-6061\"\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n",
            ),
            (
                "top.toml",
                r#"
[[part]]
shape = "sphere"
material = "steel"
radius = 0.5
center = [2, 0, 0]
[[part]]
include = "sub.toml"
origin = [0, 3, 0]
[[part]]
shape = "box"
material = "aluminium-6061"
size = [1, 1, 1]
center = [0, 0, 0]
"#,
            ),
        ],
    );
    let out = super::common::massprop(&["render", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0));
    let svg = String::from_utf8(out.stdout).unwrap();
    for name in ["steel", "aluminium-6061"] {
        assert!(svg.contains(&format!(">{name}</text>")), "{name}");
    }
    // steel c0, aluminium c1 (both of its parts, four views each).
    assert_eq!(svg.matches("class=\"c0\"").count(), 4);
    assert_eq!(svg.matches("class=\"c1\"").count(), 8);
}

#[test]
fn one_view_is_drawn_alone() {
    let svg = render(BOX, &["--view", "iso"]);
    assert!(svg.contains("<g id=\"iso\""));
    for v in ["front", "top", "side"] {
        assert!(!svg.contains(&format!("<g id=\"{v}\"")), "{v}");
    }
}

#[test]
fn the_reference_point_and_omega_are_drawn_when_given() {
    let plain = render(BOX, &[]);
    assert!(!plain.contains(">ω</text>") && !plain.contains(">ref</text>"));
    let svg = render(BOX, &["--about", "0,0,0", "--omega", "0,0,3"]);
    assert!(
        svg.contains(">ω</text>") && svg.contains(">ref</text>"),
        "{svg}"
    );
}

#[test]
fn the_output_is_the_same_on_every_run() {
    assert_eq!(render(BOX, &[]), render(BOX, &[]));
}

#[test]
fn bad_input_is_refused_with_its_place_and_nothing_on_stdout() {
    let out = massprop_stdin(
        &["render", "-"],
        "[[part]]\nshape = \"box\"\nsizes = [1, 1, 1]\n",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("<stdin>:3:1"), "{stderr}");
}

/// The README's images: `massprop render` of each, byte for byte.
#[test]
fn the_readme_images_are_current() {
    // Cargo runs the tests in the package's root: the paths as documented.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    for name in ["bent-plate", "cubesat-6u"] {
        let out = massprop(&["render", &format!("shapes/{name}.toml")]);
        assert_eq!(out.status.code(), Some(0));
        let committed =
            std::fs::read(root.join(format!("docs/images/{name}.svg"))).unwrap_or_default();
        assert!(
            out.stdout == committed,
            "docs/images/{name}.svg is not what `massprop render` draws now; regenerate it with\n  \
             cargo run --release -- render shapes/{name}.toml -o docs/images/{name}.svg"
        );
    }
}

#[test]
fn only_draws_the_sub_assembly_in_the_files_frame() {
    let dir = scratch("render", "only");
    std::fs::write(
        dir.join("payload.toml"),
        "[[part]]\nshape = \"sphere\"\nradius = 1\ncenter = [0, 0, 0]\nmass = 1\n",
    )
    .unwrap();
    let main = dir.join("sat.toml");
    std::fs::write(
        &main,
        "[[part]]\nshape = \"box\"\nsize = [4, 4, 4]\ncenter = [0, 0, 0]\nmass = 1\n\
         [[part]]\nname = \"payload\"\ninclude = \"payload.toml\"\norigin = [10, 0, 0]\n",
    )
    .unwrap();
    let out = massprop(&["render", main.to_str().unwrap(), "--only", "payload"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = String::from_utf8(out.stdout).unwrap();
    // The sphere alone, its centre of mass at (10, 0, 0) of the file's frame.
    assert_eq!(svg.matches("<path class=\"c0\"").count(), 4, "{svg}");
    assert!(!svg.contains(">box</text>"));
    let map = raster(&svg);
    let at = on_page(&svg, "front", [10.0, 0.0, 0.0]);
    assert_eq!(pixel(&map, [at[0] + 3.0, at[1] - 3.0]), BLACK);
}

/// Whether a pixel within one of `p` is near `colour`.
fn drawn_near(map: &resvg::tiny_skia::Pixmap, p: [f64; 2], colour: [u8; 3]) -> bool {
    (-1..=1).any(|dx| {
        (-1..=1).any(|dy| {
            near(
                pixel(map, [p[0] + f64::from(dx), p[1] + f64::from(dy)]),
                colour,
                60,
            )
        })
    })
}

#[test]
fn a_cylinders_rims_and_sides_are_drawn_where_they_project() {
    // Radius 1, length 4 along z: from the front and the side a 2 × 4
    // rectangle, from the top a circle of radius 1.
    let svg = render(
        "[[part]]\nshape = \"cylinder\"\nradius = 1\nlength = 4\ncenter = [0, 0, 0]\nmass = 1\n",
        &[],
    );
    let map = raster(&svg);
    let colour = hex("#1b9e77");
    for (view, points) in [
        (
            "front",
            vec![
                [1.0, 0.0, 0.5],
                [-1.0, 0.0, -0.5],
                [0.3, 0.0, 2.0],
                [-0.3, 0.0, -2.0],
            ],
        ),
        (
            "side",
            vec![[0.0, 1.0, 0.5], [0.0, -1.0, -0.5], [0.0, 0.3, 2.0]],
        ),
        ("top", {
            let h = 0.5f64.sqrt();
            vec![[h, h, 0.0], [-h, h, 0.0], [-h, -h, 0.0], [h, -h, 0.0]]
        }),
    ] {
        for p in points {
            let at = on_page(&svg, view, p);
            assert!(
                drawn_near(&map, at, colour),
                "{view}: nothing at {p:?} ({at:?})"
            );
        }
        // Inside the outline, away from the symbols: nothing.
        let inside = on_page(&svg, view, [0.45, 0.45, 0.9]);
        assert!(
            !drawn_near(&map, inside, colour),
            "{view}: ink inside at {inside:?}"
        );
    }
}

#[test]
fn a_boxs_equivalent_ellipsoid_has_its_edges_times_the_root_of_five_twelfths() {
    // A uniform box a × b × c: I_x = m (b² + c²)/12, so
    // a_x² = 5/(2m) (I_y + I_z − I_x) = 5 a²/12; seen from the front the
    // outline's semi-axes are those along x and z.
    let svg = render(
        "[[part]]\nshape = \"box\"\nsize = [6, 3, 1.5]\ncenter = [0, 0, 0]\nmass = 2\n",
        &["--view", "front"],
    );
    let (scale, _) = placing(&svg, "front");
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let d = doc
        .descendants()
        .find(|n| n.attribute("style").is_some_and(|s| s.contains("#444444")))
        .and_then(|n| n.attribute("d"))
        .expect("the ellipsoid's path");
    // M x y A rx ry angle …
    let arc: Vec<f64> = d
        .split('A')
        .nth(1)
        .unwrap()
        .split(' ')
        .take(3)
        .map(|x| x.parse().unwrap())
        .collect();
    let k = (5.0f64 / 12.0).sqrt() * scale;
    let (rx, rz, angle) = (arc[0], arc[1], arc[2]);
    assert!((rx - 6.0 * k).abs() < 0.01, "{rx} against {}", 6.0 * k);
    assert!((rz - 1.5 * k).abs() < 0.01, "{rz} against {}", 1.5 * k);
    assert!(
        angle.abs() < 0.01 || (angle.abs() - 180.0).abs() < 0.01,
        "{angle}"
    );
}

/// An L-shaped prism as an OBJ mesh: the L (0,0)–(2,0)–(2,1)–(1,1)–(1,2)–
/// (0,2) in x–z, extruded 1 along y, its faces wound outward.
fn l_prism_obj() -> String {
    let l = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]];
    let mut obj = String::new();
    for y in [0, 1] {
        for [x, z] in l {
            obj.push_str(&format!("v {x} {y} {z}\n"));
        }
    }
    // The ends (fans from a convex split: 0 1 2 3, 0 3 4 5), one end
    // wound against the other; the six sides.
    let mut faces: Vec<[usize; 3]> = Vec::new();
    for t in [[0, 3, 2], [0, 2, 1], [0, 5, 4], [0, 4, 3]] {
        faces.push(t);
        faces.push([t[0] + 6, t[2] + 6, t[1] + 6]);
    }
    for i in 0..6 {
        let j = (i + 1) % 6;
        faces.push([i, j, j + 6]);
        faces.push([i, j + 6, i + 6]);
    }
    // (Each triangle as c b a: the order above turns inward.)
    for f in faces {
        obj.push_str(&format!("f {} {} {}\n", f[2] + 1, f[1] + 1, f[0] + 1));
    }
    obj
}

#[test]
fn a_mesh_is_drawn_by_its_silhouette_not_its_box() {
    // Seen from the front (along y) the L prism's silhouette is the L:
    // six edges, the inner corner (1, 1) among their ends; its box would
    // be four edges with no corner there. From the top (along z) it is
    // the 2 × 1 rectangle, its long sides two edges each (split at x = 1
    // by the mesh), its short sides one, and the step at x = 1 twice:
    // the top of the low part (z = 1) and of the tall part (z = 2) each
    // meet the wall between them there: 8 edges.
    let obj = l_prism_obj();
    let path = scratch_files(
        "render",
        "mesh-silhouette",
        &[
            ("l.obj", &obj),
            (
                "l.toml",
                "[[part]]\nshape = \"mesh\"\nfile = \"l.obj\"\nmesh_unit = \"m\"\ndensity = 1000\n",
            ),
        ],
    );
    for (view, edges) in [("front", 6), ("top", 8)] {
        let out = massprop(&["render", path.to_str().unwrap(), "--view", view]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let svg = String::from_utf8(out.stdout).unwrap();
        parse(&svg);
        let d = svg
            .lines()
            .find(|l| l.starts_with("<path class=\"c0\""))
            .expect("the mesh's path");
        assert_eq!(d.matches('M').count(), edges, "{view}: {d}");
    }
}
