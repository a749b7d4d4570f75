//! The speed–accuracy trade of docs/accuracy.md: for each stress scene and a
//! 100,000-part assembly, and for each precision mode (plus two plain-f64
//! composers for comparison), the time per part of composition and
//! eigen-solution, and the error against the exact reference.
//!
//!     cargo run --release --example accuracy [-- --svg docs/accuracy.svg] [--parts N]
//!
//! Prints a Markdown table; with `--svg` also writes the plot of error
//! against time. Times are medians of repeated runs on whatever machine runs
//! it; errors are exact (the reference is rational arithmetic).

use massprop::analysis::Products;
use massprop::analysis::summary::{Accuracy, Summary, summarize};
use massprop::bounds;
use massprop::compose::{self, Precision};
use massprop::diag::Source;
use massprop::model::Model;
use massprop::numeric::{M3, Real};
use massprop::units::Dim;
#[path = "../tests/support/mod.rs"]
#[allow(dead_code)]
mod support;
use nalgebra::{Matrix3, SymmetricEigen};
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;
use support::{reference, scenes};

#[derive(Clone, Copy, PartialEq)]
enum Method {
    /// What a quick script does: sum about the origin, shift back, eigen of I.
    Origin,
    /// About the centre of mass, two passes, plain f64 sums, nalgebra's
    /// eigen solver: what `standard` would be without compensation.
    Plain,
    Mode(Precision),
    /// `--precision auto` (the default): standard with its error bounds,
    /// and extended too where a bound exceeds --rtol; `true` when it does
    /// for the scene (found by a run before timing).
    Auto(bool),
}

impl Method {
    fn name(self) -> &'static str {
        match self {
            Method::Origin => "f64, sum about origin (quick script)",
            Method::Plain => "f64, about the centre, no compensation",
            Method::Mode(Precision::Standard) => "massprop standard",
            Method::Mode(Precision::Extended) => "massprop extended",
            Method::Auto(_) => "massprop auto",
        }
    }
    fn short(self) -> &'static str {
        match self {
            Method::Origin => "origin",
            Method::Plain => "plain",
            Method::Mode(Precision::Standard) => "standard",
            Method::Mode(Precision::Extended) => "extended",
            Method::Auto(false) => "auto → standard",
            Method::Auto(true) => "auto → extended",
        }
    }
}

const METHODS: [Method; 5] = [
    Method::Origin,
    Method::Plain,
    Method::Mode(Precision::Standard),
    Method::Mode(Precision::Extended),
    Method::Auto(false),
];

/// massprop's report of a model, in the accuracy asked for.
fn summary(model: &Model, accuracy: &Accuracy) -> Summary {
    summarize(model, &model.analysis, Products::Tensor, accuracy).expect("a valid scene")
}

/// Which arithmetic `auto` chooses for a model.
fn auto_escalates(model: &Model) -> bool {
    summary(model, &Accuracy::default()).precision == Precision::Extended
}

/// Inertia about the centre of mass and principal moments (ascending), SI.
struct Result {
    inertia: [[f64; 3]; 3],
    moments: [f64; 3],
}

fn inertia_rows(c: &Matrix3<f64>) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i == j {
                c[((i + 1) % 3, (i + 1) % 3)] + c[((i + 2) % 3, (i + 2) % 3)]
            } else {
                -c[(i, j)]
            }
        })
    })
}

/// The two plain-f64 composers, from the same parsed parts (file units).
fn baseline(model: &Model, method: Method) -> Result {
    let parts = &model.flattened();
    let own = |p: &massprop::part::Part| -> Matrix3<f64> {
        let m: f64 = p.mass();
        let j: M3<f64> = p.own_second_moment(m);
        Matrix3::from_fn(|i, k| j[i][k])
    };
    let center = |p: &massprop::part::Part| nalgebra::Vector3::from(p.centroid().map(|c| c.f64()));
    let mut mass = 0.0;
    let mut first = nalgebra::Vector3::zeros();
    for p in parts {
        let m: f64 = p.mass();
        mass += m;
        first += center(p) * m;
    }
    let com = first / mass;
    let mut c = Matrix3::zeros();
    for p in parts {
        let m: f64 = p.mass();
        let d = match method {
            Method::Origin => center(p),
            _ => center(p) - com,
        };
        c += own(p) + d * d.transpose() * m;
    }
    if method == Method::Origin {
        c -= com * com.transpose() * mass;
    }
    let f = model.units.factor(Dim::INERTIA).value();
    let c = c * f;
    let inertia = inertia_rows(&c);
    let mut moments: [f64; 3] = match method {
        // A script diagonalises I itself.
        Method::Origin => {
            let e = SymmetricEigen::new(Matrix3::from_fn(|i, j| inertia[i][j])).eigenvalues;
            [e[0], e[1], e[2]]
        }
        _ => {
            let e = SymmetricEigen::new(c).eigenvalues;
            [e[1] + e[2], e[0] + e[2], e[0] + e[1]]
        }
    };
    moments.sort_by(f64::total_cmp);
    Result { inertia, moments }
}

fn run(model: &Model, method: Method) -> Result {
    let accuracy = match method {
        Method::Mode(p) => Accuracy::fixed(p),
        Method::Auto(_) => Accuracy::default(),
        _ => return baseline(model, method),
    };
    let s = summary(model, &accuracy);
    Result {
        inertia: s.inertia_com,
        moments: s.principal_moments,
    }
}

/// What is timed: composition and principal moments, nothing else.
fn work(model: &Model, method: Method) {
    match method {
        Method::Mode(p) => {
            let body = compose::compose(model, p);
            black_box(compose::principal(&body.second_moment, p));
        }
        // The same work with the error bounds of both, in standard, and
        // again in extended where auto goes on.
        Method::Auto(escalates) => {
            let modes: &[Precision] = if escalates {
                &[Precision::Standard, Precision::Extended]
            } else {
                &[Precision::Standard]
            };
            for &p in modes {
                let (body, error) = compose::compose_bounded(model, p);
                let principal =
                    compose::principal_bounded(&body.second_moment, p).expect("converges");
                let c = body.second_moment.map(|r| r.map(|x| x.f64()));
                black_box(bounds::eigen(
                    &c,
                    &error.second_moment,
                    &principal.solved(),
                    p,
                ));
            }
        }
        _ => {
            black_box(baseline(model, method));
        }
    }
}

/// Median time per call over 7 batches of at least 30 ms each, in seconds.
fn time(model: &Model, method: Method) -> f64 {
    let mut reps = 1usize;
    loop {
        let t = Instant::now();
        for _ in 0..reps {
            work(model, method);
        }
        if t.elapsed().as_secs_f64() > 0.03 {
            break;
        }
        reps *= 2;
    }
    let mut per: Vec<f64> = (0..7)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..reps {
                work(model, method);
            }
            t.elapsed().as_secs_f64() / reps as f64
        })
        .collect();
    per.sort_by(f64::total_cmp);
    per[3]
}

struct Row {
    scene: &'static str,
    parts: usize,
    method: Method,
    seconds_per_part: f64,
    inertia_err: f64,
    worst_moment_err: f64,
}

fn svg(rows: &[Row]) -> String {
    let (w, h, l, r, t, b) = (760.0, 480.0, 70.0, 210.0, 20.0, 50.0);
    let (x0, x1) = (0.0f64, 4.0f64); // log10 ns per part: 1 ns … 10 µs
    let (y0, y1) = (-18.0f64, 4.0f64); // log10 relative error
    let px = |v: f64| l + (v.log10().clamp(x0, x1) - x0) / (x1 - x0) * (w - l - r);
    let py = |e: f64| t + (y1 - e.max(1e-18).log10().clamp(y0, y1)) / (y1 - y0) * (h - t - b);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    for k in (y0 as i32..=y1 as i32).step_by(2) {
        let y = py(10f64.powi(k));
        let _ = writeln!(
            s,
            r##"<line x1="{l}" y1="{y}" x2="{}" y2="{y}" stroke="#ddd"/><text x="{}" y="{}" text-anchor="end">1e{k}</text>"##,
            w - r,
            l - 6.0,
            y + 4.0
        );
    }
    for k in x0 as i32..=x1 as i32 {
        let x = px(10f64.powi(k));
        let label = ["1 ns", "10 ns", "100 ns", "1 µs", "10 µs"][k as usize];
        let _ = writeln!(
            s,
            r##"<line x1="{x}" y1="{t}" x2="{x}" y2="{}" stroke="#ddd"/><text x="{x}" y="{}" text-anchor="middle">{label}</text>"##,
            h - b,
            h - b + 16.0
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle">time per part (composition and principal axes)</text>"#,
        (l + w - r) / 2.0,
        h - 12.0
    );
    let _ = writeln!(
        s,
        r#"<text transform="translate(16 {}) rotate(-90)" text-anchor="middle">worst relative error (inertia or a principal moment)</text>"#,
        (t + h - b) / 2.0
    );
    let colors = ["#d62728", "#ff7f0e", "#1f77b4", "#2ca02c", "#9467bd"];
    for (i, m) in METHODS.iter().enumerate() {
        // Auto's rows, whichever arithmetic it chose, share a colour.
        let kind = |m: Method| match m {
            Method::Auto(_) => Method::Auto(false),
            m => m,
        };
        for row in rows.iter().filter(|r| kind(r.method) == kind(*m)) {
            let e = row.inertia_err.max(row.worst_moment_err);
            let _ = writeln!(
                s,
                r#"<circle cx="{:.1}" cy="{:.1}" r="4" fill="{}" fill-opacity="0.8"><title>{}: {} — {:.2e}</title></circle>"#,
                px(row.seconds_per_part * 1e9),
                py(if e.is_finite() { e } else { 1e4 }),
                colors[i],
                row.scene,
                m.name(),
                e
            );
        }
        let y = t + 20.0 + 18.0 * i as f64;
        let _ = writeln!(
            s,
            r#"<circle cx="{}" cy="{y}" r="4" fill="{}"/><text x="{}" y="{}">{}</text>"#,
            w - r + 12.0,
            colors[i],
            w - r + 22.0,
            y + 4.0,
            match m {
                Method::Auto(_) => "auto",
                m => m.short(),
            }
        );
    }
    let _ = writeln!(s, "</svg>");
    s
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let flag = |name: &str| {
        args.iter()
            .position(|a| a == name)
            .map(|i| args[i + 1].clone())
    };
    let svg_path = flag("--svg");
    let n: usize = flag("--parts").map_or(100_000, |v| v.parse().expect("--parts N"));

    let mut named = scenes::stress();
    named.push(scenes::Named {
        name: "assembly 100k",
        what: "mixed assembly",
        scene: scenes::assembly(n),
    });
    let mut rows = Vec::new();
    println!(
        "| scene | parts | method | time per part | inertia error (Frobenius) | worst principal-moment error |"
    );
    println!("|---|---|---|---|---|---|");
    for s in &named {
        let text = reference::to_toml(&s.scene);
        let model = Model::parse(&Source::new(s.name, text)).unwrap_or_else(|d| panic!("{d}"));
        // Exact sums of many quaternion-turned parts are out of reach (see
        // `compose_rounded`); 400-bit rounding of each part is 1e-115 away.
        let exact = if s.scene.parts.len() > 100 {
            reference::compose_rounded(&s.scene, 400)
        } else {
            reference::compose(&s.scene)
        };
        let pr = exact.principal();
        for method in METHODS {
            let method = match method {
                Method::Auto(_) => Method::Auto(auto_escalates(&model)),
                m => m,
            };
            let res = run(&model, method);
            let inertia_err = reference::rel_frobenius(&res.inertia, &exact.inertia);
            let worst_moment_err = (0..3)
                .map(|k| reference::rel(res.moments[k], &pr.moments[k]))
                .fold(0.0f64, |a, e| {
                    if e.is_nan() || a.is_nan() {
                        f64::NAN
                    } else {
                        a.max(e)
                    }
                });
            let seconds_per_part = time(&model, method) / model.count as f64;
            println!(
                "| {} | {} | {} | {:.1} ns | {:.1e} | {:.1e} |",
                s.name,
                model.count,
                method.short(),
                seconds_per_part * 1e9,
                inertia_err,
                worst_moment_err
            );
            rows.push(Row {
                scene: s.name,
                parts: model.count,
                method,
                seconds_per_part,
                inertia_err,
                worst_moment_err,
            });
        }
    }
    let _ = rows.iter().map(|r| r.parts).max();
    if let Some(path) = svg_path {
        std::fs::write(&path, svg(&rows)).expect("the SVG file can be written");
        eprintln!("wrote {path}");
    }
}
