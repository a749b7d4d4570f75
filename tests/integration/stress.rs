//! Stress tests of massprop's accuracy against the exact reference
//! (`crate::support::reference`, tests/support/reference.rs, issue 4), through the public JSON contract:
//! `massprop report FILE --format json --precision MODE`, run in-process.
//!
//! Each scene is written as a part file whose numbers are exactly the f64
//! values the reference takes, so every error measured is massprop's own.
//! Every test prints its worst error/bound ratio per quantity (run with
//! `--nocapture` to see the margins) and fails listing every check over its
//! bound.
//!
//! Tests named `…_extended` run `--precision extended` and hold it to the
//! same bounds as standard, and the slender-body tests to much tighter ones.
//!
//! Tolerances, all from f64's unit roundoff u = ε/2 = 2⁻⁵³ and conditioning:
//! - [`TENSOR`]: the inertia tensor about the centre of mass, relative
//!   Frobenius, 1e-15 ≈ 4.5ε: the requirement.
//! - [`MOMENT`]: principal moments, absolute over the largest moment. By
//!   Weyl, |Δλ| ≤ ‖ΔI‖₂ ≤ ‖ΔI‖_F ≤ TENSOR·√3·I_max; the eigen solver adds a
//!   backward error of a few ε: 12ε in all.
//! - axes: Davis–Kahan, sin θ ≤ ‖ΔI‖₂ / gap ≤ MOMENT·I_max / gap.
//! - mass and centre of mass: a priori bounds of sums, [`mass_bound`] and
//!   [`com_bound`].

use crate::support::num_traits::Signed;
use crate::support::reference::{
    self as r, Amount, Exact, Length, Mass, Part, Place, Scene, axis_sin, f, fm, rel, rel_frobenius,
};
use clap::Parser;
use std::sync::atomic::{AtomicUsize, Ordering};

pub(crate) const EPS: f64 = f64::EPSILON;

/// Relative Frobenius bound on the inertia tensor about the centre of mass:
/// issue 4's requirement, 1e-15 ≈ 4.5ε. Each entry of a part's R diag(s) Rᵀ
/// rounds a few times (≈ 3u–6u of ‖Cᵢ‖); the composed tensor, a sum of
/// positive semi-definite terms with compensated sums, keeps that relative
/// size, and the Frobenius norm averages the entries' errors, which do not
/// all align: a worst case could exceed 1e-15 slightly, typical ones stay
/// at a third of it.
pub(crate) const TENSOR: f64 = 1e-15;

/// Principal moments, |Δ| over the largest moment: Weyl's bound on TENSOR
/// (√3 · 4.5ε ≈ 7.8ε, since ‖I‖_F ≤ √3 I_max) plus the solver's ~4ε.
pub(crate) const MOMENT: f64 = 12.0 * EPS;

/// u = ε/2, the unit roundoff of f64.
pub(crate) const U: f64 = EPS / 2.0;

/// Unit roundoff of double-double, 2⁻¹⁰⁴ (the `extended` arithmetic).
pub(crate) const U_DD: f64 = 4.930380657631324e-32;

/// Mass: a part's mass is its input or ρ·a·b·c (≤ 3 roundings, plus ≤ 2 for
/// each unit conversion of ρ and the sizes: 11u), and a sum of n positive
/// terms adds (n − 1)u; the result is rounded to SI once more.
pub(crate) fn mass_bound(n: usize) -> f64 {
    (n as f64 + 11.0) * U
}

/// Centre of mass, |Δc| over Σ mᵢ|cᵢ|/m (the scale rounding is relative
/// to; |c| itself can be small by cancellation): each mᵢcᵢ carries its
/// mass's error and one product, the sum (n − 1)u, the division one.
pub(crate) fn com_bound(n: usize) -> f64 {
    (n as f64 + 14.0) * U
}

/// Unit roundoffs beyond a box's that one part's own mass (`mass`) and its
/// own second moment (`tensor`, relative to the part's trace, and
/// including the mass's) may carry, for shapes whose closed forms take more
/// operations than a box's m = ρabc (3 roundings) and m a²/12 (3 per
/// entry), which TENSOR and [`mass_bound`] already budget. Counted for a
/// stable evaluation of each closed form from exact inputs: the inputs
/// hold the digits, and each form is well conditioned in them (its
/// differences R − r and vertex differences are exact or rounded once, and
/// the rest are sums of positive terms), so only the operations count.
///
/// | part | mass | tensor | why |
/// |---|---|---|---|
/// | box, plate, rod, point | 0 | 0 | the budget itself |
/// | cylinder by density | 4 | 4 | π rounded (1), R − r and R + r (2), one product more (1); (R² + r²)/4 rounds as often as a²/12 |
/// | disk by density | 3 | 3 | the same without the length |
/// | sphere | 7 by density | 13 more | ⁴⁄₃ and π (2), R − r (1), R² + Rr + r² (3), one product (1); (1 + ρ + … + ρ⁴)/(1 + ρ + ρ²) with ρ = r/R: ρ's rounding moves the ratio by ≤ 1u (ρ f′/f ≤ 1), its powers and sums by ≤ 7u and 3u, the division 1u, and m R²/5 · ratio one product more than m a²/12 |
/// | triangle by density | 1 + 2/sin θ | 2 more | the area \|e₁ × e₂\|/2 from exact edges: each component a difference of products, 2u of \|e₁\|\|e₂\| in all, i.e. 2u/sin θ of the area for the smallest vertex angle θ, and one rounding more; vertex differences rounded (if inexact) add 2u max\|vᵢ\|/min\|eᵢ\|; the vertices less the centroid round once each |
/// | ellipsoid by density | 4 | 4 | ⁴⁄₃ and π (2), their product and one product more than ρabc's three (2); (m a) a/5 rounds as often as m a²/12 |
/// | given inertia | 0 | 9 | C = tr(I)/2 · E − I, each diagonal entry ((I_jj − I_aa) + I_kk)/2: 2 roundings at most (`part::diagonal_second_moment`; the difference is exact when small), budgeted at 3; R C Rᵀ with a full C sums 9 products per entry where a box sums 3: 6 more |
///
/// Thin shells, tubes and rings take only a mass; their closed forms round
/// no more often than the solids'.
pub(crate) struct Extra {
    pub mass: f64,
    pub tensor: f64,
}

pub(crate) fn extra_ulps(p: &Part) -> Extra {
    use r::Shape;
    let density = matches!(p.amount, Amount::Density(_));
    let by_density = |x: f64| if density { x } else { 0.0 };
    let (mass, shape) = match p.shape {
        Shape::Box | Shape::Plate | Shape::Rod | Shape::Point => (0.0, 0.0),
        Shape::Cylinder => (by_density(4.0), 0.0),
        Shape::Disk => (by_density(3.0), 0.0),
        Shape::Sphere => (by_density(7.0), 13.0),
        Shape::Triangle => {
            let Place::Vertices(v) = &p.place else {
                unreachable!("a triangle is placed by its vertices")
            };
            (by_density(triangle_area_ulps(v)), 2.0)
        }
        Shape::Inertia => (0.0, 9.0),
        // massprop's own counts (`part::error`): these shapes' closed forms
        // are sums of positive terms, counted there operation by operation.
        Shape::Cone => (by_density(15.0), 40.0),
        Shape::Torus => (by_density(11.0), 8.0),
        Shape::Hemisphere => (by_density(12.0), 40.0),
        Shape::Capsule => (by_density(17.0), 48.0),
        // The table's row: ⁴⁄₃π abc, and m a²/5 rounded as m a²/12.
        Shape::Ellipsoid => (by_density(4.0), 0.0),
        // The polygon's figures in double-double, rounded once; R C Rᵀ of
        // a full x–y block as a given tensor's.
        Shape::Prism => (by_density(4.0), 12.0),
    };
    Extra {
        mass,
        tensor: mass + shape,
    }
}

/// The area's rounding of a triangle (see [`extra_ulps`]), in u.
fn triangle_area_ulps(v: &[[f64; 3]; 3]) -> f64 {
    let diff = |a: usize, b: usize| -> [f64; 3] { std::array::from_fn(|i| v[a][i] - v[b][i]) };
    let len = |e: [f64; 3]| (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt();
    let edges = [diff(1, 0), diff(2, 1), diff(0, 2)];
    let c = cross3(edges[0], edges[1]);
    let twice_area = len(c);
    // 1/sin of the smallest angle: the largest |a||b| over 2·area.
    let inv_sin = (0..3)
        .map(|k| len(edges[k]) * len(edges[(k + 1) % 3]))
        .fold(0.0, f64::max)
        / twice_area;
    let exact = (0..3).all(|k| {
        let (a, b) = (k, (k + 1) % 3);
        (0..3).all(|i| r::q(v[b][i] - v[a][i]) == r::q(v[b][i]) - r::q(v[a][i]))
    });
    let rounding = if exact {
        0.0
    } else {
        let far = v.iter().map(|p| len(*p)).fold(0.0, f64::max);
        let short = edges.iter().map(|e| len(*e)).fold(f64::INFINITY, f64::min);
        2.0 * far / short
    };
    1.0 + 2.0 * inv_sin + rounding
}

/// The bounds of one scene against its exact reference: TENSOR, MOMENT,
/// [`mass_bound`] and [`com_bound`] plus what its parts add
/// ([`extra_ulps`], the largest of any part: a relative error δᵢ of each
/// part's contribution Pᵢ = Cᵢ + mᵢdᵢdᵢᵀ (positive semi-definite, so
/// ‖Pᵢ‖_F ≤ tr Pᵢ) moves C by at most δ·tr C; I = tr(C)E − C then by
/// ‖ΔI‖_F ≤ 2‖ΔC‖_F ≤ 2δ tr C = δ tr I ≤ √3 δ ‖I‖_F, and a moment by at
/// most 2δ tr C ≤ 3δ I_max; masses by δ m, the centre by 2δ of its scale).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Bounds {
    pub tensor: f64,
    pub moment: f64,
    pub mass: f64,
    pub com: f64,
}

impl Bounds {
    pub(crate) fn of(scene: &Scene) -> Bounds {
        let n = scene.parts.len();
        let (mass, tensor) = scene
            .parts
            .iter()
            .map(extra_ulps)
            .fold((0.0f64, 0.0f64), |(m, t), e| {
                (m.max(e.mass), t.max(e.tensor))
            });
        Bounds {
            tensor: TENSOR + 3f64.sqrt() * tensor * U,
            moment: MOMENT + 3.0 * tensor * U,
            mass: mass_bound(n) + mass * U,
            com: com_bound(n) + 2.0 * mass * U,
        }
    }
}

// ---------------------------------------------------------------------------
// Running massprop

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Precision {
    Standard,
    Extended,
}

impl Precision {
    pub(crate) fn flag(self) -> &'static str {
        match self {
            Precision::Standard => "standard",
            Precision::Extended => "extended",
        }
    }
}

/// What `report --format json` printed, parsed.
#[derive(Clone, Debug)]
pub(crate) struct Report {
    pub mass: f64,
    pub com: [f64; 3],
    pub inertia: [[f64; 3]; 3],
    pub inertia_ref: [[f64; 3]; 3],
    pub moments: [f64; 3],
    pub axes: [[f64; 3]; 3],
    pub equal: Vec<usize>,
    /// Each part's mass and centroid, SI.
    pub parts: Vec<(f64, [f64; 3])>,
    /// `error_bounds`: what massprop claims of its own error.
    pub bounds: Claimed,
    pub precision: Precision,
    pub stdout: String,
}

/// The error bounds a report claims (`error_bounds`, SI, absolute; axes
/// as angles).
#[derive(Clone, Debug)]
pub(crate) struct Claimed {
    pub mass: f64,
    pub com: [f64; 3],
    pub inertia: [[f64; 3]; 3],
    pub moments: [f64; 3],
    pub axes: [f64; 3],
}

impl Report {
    /// Σ mᵢ|cᵢ| / m: the scale of the centre of mass's rounding.
    pub(crate) fn com_scale(&self) -> f64 {
        let first: f64 = self
            .parts
            .iter()
            .map(|(m, c)| m * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt())
            .sum();
        first / self.mass
    }
}

/// A part file in the temporary directory, removed when dropped.
struct TempFile(std::path::PathBuf);

impl TempFile {
    fn new(text: &str) -> TempFile {
        static COUNT: AtomicUsize = AtomicUsize::new(0);
        let path = std::env::temp_dir().join(format!(
            "massprop-stress-{}-{}.toml",
            std::process::id(),
            COUNT.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::write(&path, text).expect("the temporary directory is writable");
        TempFile(path)
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// Run `massprop report --format json --precision MODE` on a scene.
pub(crate) fn report(scene: &Scene, precision: Precision) -> Report {
    report_text(&r::to_toml(scene), precision)
}

pub(crate) fn report_text(text: &str, precision: Precision) -> Report {
    let file = TempFile::new(text);
    let path = file.0.to_str().expect("a UTF-8 temporary path");
    let cli = massprop::cli::Cli::try_parse_from([
        "massprop",
        "report",
        "--format",
        "json",
        "--precision",
        precision.flag(),
        path,
    ])
    .unwrap_or_else(|e| panic!("command line: {e}"));
    let out = massprop::run(&cli).unwrap_or_else(|d| panic!("{d}\nfor the part file:\n{text}"));
    let v: serde_json::Value = serde_json::from_str(&out.stdout.text()).expect("stdout is JSON");
    let num = |x: &serde_json::Value| x.as_f64().expect("a number");
    let vec3 = |x: &serde_json::Value| -> [f64; 3] { std::array::from_fn(|i| num(&x[i])) };
    let mat3 = |x: &serde_json::Value| -> [[f64; 3]; 3] { std::array::from_fn(|i| vec3(&x[i])) };
    let rep = Report {
        mass: num(&v["mass"]),
        com: vec3(&v["center_of_mass"]),
        inertia: mat3(&v["inertia_com"]),
        inertia_ref: mat3(&v["inertia_ref"]),
        moments: vec3(&v["principal_moments"]),
        axes: mat3(&v["principal_axes"]),
        equal: v["equal_moments"]
            .as_array()
            .expect("equal_moments is an array")
            .iter()
            .map(|i| i.as_u64().expect("an index") as usize)
            .collect(),
        parts: v["parts"]
            .as_array()
            .expect("parts is an array")
            .iter()
            .map(|p| (num(&p["mass"]), vec3(&p["center_of_mass"])))
            .collect(),
        bounds: {
            let b = &v["error_bounds"];
            Claimed {
                mass: num(&b["mass"]),
                com: vec3(&b["center_of_mass"]),
                inertia: mat3(&b["inertia_com"]),
                moments: vec3(&b["principal_moments"]),
                axes: vec3(&b["principal_axes"]),
            }
        },
        precision,
        // Less `source`, the temporary file's name: runs of one scene
        // compare equal.
        stdout: {
            let mut v = v.clone();
            v.as_object_mut()
                .expect("the report is an object")
                .remove("source");
            v.to_string()
        },
    };
    assert_eq!(
        v["precision"].as_str(),
        Some(precision.flag()),
        "{}",
        out.stdout.text()
    );
    assert_sane(&rep);
    rep
}

/// What holds of every output, whatever the scene: finite, non-negative,
/// ascending moments ("never a negative or NaN principal moment"), unit
/// right-handed axes, and a well-formed equality flag.
fn assert_sane(rep: &Report) {
    let m = rep.moments;
    assert!(
        m.iter().all(|x| x.is_finite() && *x >= 0.0) && m[0] <= m[1] && m[1] <= m[2],
        "principal moments must be finite, non-negative and ascending: {m:?}"
    );
    // Normalising rounds a unit vector's length by ~1u per step; 8ε leaves
    // room for the cross product that forms the third axis.
    let a = rep.axes;
    for axis in &a {
        let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
        assert!((n - 1.0).abs() <= 8.0 * EPS, "axis {axis:?} is not unit");
    }
    let triple = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    assert!(
        (triple - 1.0).abs() <= 16.0 * EPS,
        "axes not right-handed: {a:?}"
    );
    assert!(
        [vec![], vec![0, 1], vec![1, 2], vec![0, 1, 2]].contains(&rep.equal),
        "equal_moments {:?}",
        rep.equal
    );
}

// ---------------------------------------------------------------------------
// Margins: every check recorded, the worst per quantity printed

/// One check: `err ≤ bound` for a quantity `kind` in a case `what`. A
/// condition with no size (flags, determinism) has err 0 or ∞ and bound 0.
#[derive(Clone, Debug)]
pub(crate) struct Check {
    kind: String,
    what: String,
    err: f64,
    bound: f64,
}

impl Check {
    fn ok(&self) -> bool {
        self.err <= self.bound // false for NaN
    }

    fn ratio(&self) -> f64 {
        if self.bound == 0.0 {
            0.0
        } else {
            self.err / self.bound
        }
    }
}

impl std::fmt::Display for Check {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.bound == 0.0 {
            write!(f, "{}: {}: does not hold", self.kind, self.what)
        } else {
            write!(
                f,
                "{}: {}: error {:.3e} > bound {:.3e}",
                self.kind, self.what, self.err, self.bound
            )
        }
    }
}

/// Checks of one test. `finish` prints the worst error/bound per quantity
/// and fails listing every violation.
pub(crate) struct Margins {
    name: String,
    checks: Vec<Check>,
}

impl Margins {
    pub(crate) fn new(name: impl Into<String>) -> Margins {
        Margins {
            name: name.into(),
            checks: Vec::new(),
        }
    }

    /// Record `err ≤ bound` for quantity `kind` in case `what`.
    pub(crate) fn check(&mut self, kind: &str, what: impl std::fmt::Display, err: f64, bound: f64) {
        self.checks.push(Check {
            kind: kind.to_string(),
            what: what.to_string(),
            err,
            bound,
        });
    }

    /// Record a condition that has no size (flags, determinism).
    pub(crate) fn require(&mut self, kind: &str, what: impl std::fmt::Display, ok: bool) {
        self.check(kind, what, if ok { 0.0 } else { f64::INFINITY }, 0.0);
    }

    /// The violations so far, one line each.
    pub(crate) fn failures(&self) -> Vec<String> {
        self.checks
            .iter()
            .filter(|c| !c.ok())
            .map(|c| c.to_string())
            .collect()
    }

    /// Take over another set's checks, each case prefixed with `case`.
    pub(crate) fn absorb(&mut self, other: Margins, case: &str) {
        self.checks.extend(other.checks.into_iter().map(|c| Check {
            what: format!("{case}{}", c.what),
            ..c
        }));
    }

    pub(crate) fn finish(self) {
        let mut kinds: Vec<&str> = Vec::new();
        for c in &self.checks {
            if !kinds.contains(&c.kind.as_str()) {
                kinds.push(&c.kind);
            }
        }
        for k in kinds {
            let of_kind = || self.checks.iter().filter(|c| c.kind == k);
            let worst = of_kind()
                .max_by(|a, b| a.ratio().total_cmp(&b.ratio()))
                .expect("at least one check of the kind");
            if worst.bound == 0.0 {
                let held = of_kind().filter(|c| c.ok()).count();
                eprintln!("{}: {k}: {held} of {} hold", self.name, of_kind().count());
            } else {
                eprintln!(
                    "{}: {k}: worst error/bound {:.3} ({}: {:.3e} vs {:.3e})",
                    self.name,
                    worst.ratio(),
                    worst.what,
                    worst.err,
                    worst.bound
                );
            }
        }
        let failed = self.failures();
        assert!(
            failed.is_empty(),
            "{}: {} of {} checks fail:\n  {}",
            self.name,
            failed.len(),
            self.checks.len(),
            failed.join("\n  ")
        );
    }
}

/// The standard checks of one scene against its reference: tensor, moments,
/// mass and centre of mass, within [`Bounds::of`] the scene; returns the
/// reference for further checks.
pub(crate) fn check_against_reference(
    m: &mut Margins,
    what: &str,
    scene: &Scene,
    rep: &Report,
) -> (Exact, r::Principal) {
    check_against_reference_as(m, "", what, scene, rep)
}

/// [`check_against_reference`], each quantity's name followed by `label`
/// (so that a test can print its margins per shape, say).
pub(crate) fn check_against_reference_as(
    m: &mut Margins,
    label: &str,
    what: &str,
    scene: &Scene,
    rep: &Report,
) -> (Exact, r::Principal) {
    let exact = r::compose(scene);
    let pr = exact.principal();
    let top = f(&pr.moments[2]);
    let b = Bounds::of(scene);
    m.check(
        &format!("I_com{label}"),
        what,
        rel_frobenius(&rep.inertia, &exact.inertia),
        b.tensor,
    );
    for k in 0..3 {
        m.check(
            &format!("moments{label}"),
            format_args!("{what}, moment {k}"),
            r::err_over(rep.moments[k], &pr.moments[k], top),
            b.moment,
        );
    }
    m.check(
        &format!("mass{label}"),
        what,
        rel(rep.mass, &exact.mass),
        b.mass,
    );
    m.check(
        &format!("com{label}"),
        what,
        r::vec_err_over(&rep.com, &exact.com, exact.com_scale()),
        b.com,
    );
    check_claimed_bounds(m, label, what, rep, &exact, &pr);
    (exact, pr)
}

/// How much looser than the actual error a claimed bound may be (issue 13:
/// tight enough that `auto` escalates only where it must).
pub(crate) const TIGHT: f64 = 1000.0;

/// The error bounds the report claims (`error_bounds`) are honest — the
/// actual error against the exact reference is within each — and tight:
/// each is within [`TIGHT`] times the larger of the actual error and the
/// error that storing the exact result in the arithmetic used would leave
/// (u of the value for a scalar, of the largest entry for a vector or
/// tensor; for a principal moment, the unit of the arithmetic times the
/// largest moment, by which storing the tensor moves an eigenvalue, plus
/// the moment's own rounding; for an axis, u times the moments over their
/// gap). The floor keeps an error that happens to be zero, or small by
/// luck, from asking a bound to be as small: the bound cannot know it.
pub(crate) fn check_claimed_bounds(
    m: &mut Margins,
    label: &str,
    what: &str,
    rep: &Report,
    exact: &Exact,
    pr: &r::Principal,
) {
    let unit = match rep.precision {
        Precision::Standard => U,
        Precision::Extended => U_DD,
    };
    let c = &rep.bounds;
    let mut both = |kind: &str, item: String, err: f64, bound: f64, floor: f64| {
        m.check(
            &format!("honest {kind}{label}"),
            format_args!("{what}, {item}"),
            err,
            bound,
        );
        m.check(
            &format!("tight {kind}{label}"),
            format_args!("{what}, {item}"),
            bound,
            TIGHT * err.max(floor),
        );
    };
    let diff = |a: f64, b: &r::Q| r::f(&(r::q(a) - b).abs());
    both(
        "mass",
        String::new(),
        diff(rep.mass, &exact.mass),
        c.mass,
        U * rep.mass.abs(),
    );
    let com_floor = U * exact.com_scale();
    for j in 0..3 {
        let err = diff(rep.com[j], &exact.com[j]);
        both("com", format!("[{j}]"), err, c.com[j], com_floor);
    }
    let top = rep
        .inertia
        .iter()
        .flatten()
        .fold(0.0f64, |a, x| a.max(x.abs()));
    for j in 0..3 {
        for k in 0..3 {
            let err = diff(rep.inertia[j][k], &exact.inertia[j][k]);
            both(
                "I_com",
                format!("[{j}][{k}]"),
                err,
                c.inertia[j][k],
                U * top,
            );
        }
    }
    for k in 0..3 {
        let err = diff(rep.moments[k], &pr.moments[k]);
        let floor = unit * rep.moments[2] + U * rep.moments[k];
        both("moment", format!("{k}"), err, c.moments[k], floor);
    }
    for k in 0..3 {
        if let Some(axis) = &pr.axes[k]
            && !rep.equal.contains(&k)
        {
            let err = axis_sin(&rep.axes[k], axis).asin();
            both("axis", format!("{k}"), err, c.axes[k], U / pr.gap(k));
        }
    }
}

/// Check the axes of separated moments: sin θ ≤ moment bound / (gap / I_max)
/// (`moment`: MOMENT, or [`Bounds::of`] the scene's).
pub(crate) fn check_axes(
    m: &mut Margins,
    what: &str,
    rep: &Report,
    pr: &r::Principal,
    moment: f64,
) {
    check_axes_as(m, "", what, rep, pr, moment);
}

/// [`check_axes`], the quantity's name followed by `label`.
pub(crate) fn check_axes_as(
    m: &mut Margins,
    label: &str,
    what: &str,
    rep: &Report,
    pr: &r::Principal,
    moment: f64,
) {
    for k in 0..3 {
        if let Some(axis) = &pr.axes[k]
            && !rep.equal.contains(&k)
        {
            m.check(
                &format!("axes{label}"),
                format_args!("{what}, axis {k}"),
                axis_sin(&rep.axes[k], axis),
                moment / pr.gap(k),
            );
        }
    }
}

// ---------------------------------------------------------------------------
// Random scenes, from a fixed seed

/// SplitMix64: a tiny, fixed-seed generator, so every run sees the same
/// scenes.
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1), 53 random bits.
    pub(crate) fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform in [−1, 1]³, rounded to multiples of 2⁻²⁰: such coordinates
    /// plus offsets below 2³² stay exact in f64.
    pub(crate) fn grid_point(&mut self) -> [f64; 3] {
        std::array::from_fn(|_| (self.range(-1.0, 1.0) * 1048576.0).round() / 1048576.0)
    }

    /// A random unit quaternion (normalised in f64: its length is 1 to a
    /// few ε, and the reference uses it exactly as written).
    pub(crate) fn quaternion(&mut self) -> [f64; 4] {
        loop {
            let q: [f64; 4] = std::array::from_fn(|_| self.range(-1.0, 1.0));
            let n2: f64 = q.iter().map(|x| x * x).sum();
            if (0.04..=1.0).contains(&n2) {
                let n = n2.sqrt();
                return q.map(|x| x / n);
            }
        }
    }

    /// A random rotation as a matrix with f64 entries (columns: local axes),
    /// from a random quaternion.
    pub(crate) fn rotation(&mut self) -> [[f64; 3]; 3] {
        fm(&r::rotation(&self.quaternion().map(r::q)))
    }
}

/// Column k of a matrix scaled by s: an edge vector of a turned box.
pub(crate) fn edge(rot: &[[f64; 3]; 3], k: usize, s: f64) -> [f64; 3] {
    [rot[0][k] * s, rot[1][k] * s, rot[2][k] * s]
}

/// Twelve boxes of random sizes (0.2 to 1), masses or densities and
/// orientations, centred on the 2⁻²⁰ grid within [−1, 1]³.
pub(crate) fn twelve_boxes(rng: &mut Rng) -> Scene {
    Scene::si(
        (0..12)
            .map(|k| {
                let size = [
                    rng.range(0.2, 1.0),
                    rng.range(0.2, 1.0),
                    rng.range(0.2, 1.0),
                ];
                let amount = if k % 3 == 0 {
                    Amount::Density(rng.range(500.0, 9000.0))
                } else {
                    Amount::Mass(rng.range(0.5, 2.0))
                };
                Part::cuboid(size, rng.grid_point(), Some(rng.quaternion()), amount)
            })
            .collect(),
    )
}

/// A given inertia tensor (file mass × length², rows) of a body of mass
/// `mass` whose principal second moments are m sₖ² along the axes of the
/// rotation of `q`: C = Q diag(m sₖ²) Qᵀ rounded, and I = tr(C)E − C,
/// symmetric by construction and valid while every sₖ is well above
/// √ε of the largest.
pub(crate) fn given_tensor(mass: f64, s: [f64; 3], q: [f64; 4]) -> [[f64; 3]; 3] {
    let rot = fm(&r::rotation(&q.map(r::q)));
    let c: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3)
                .map(|k| rot[i][k] * mass * s[k] * s[k] * rot[j][k])
                .sum()
        })
    });
    let tr = c[0][0] + c[1][1] + c[2][2];
    let mut out = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in i..3 {
            out[i][j] = if i == j { tr - c[i][i] } else { -c[i][j] };
            out[j][i] = out[i][j];
        }
    }
    out
}

/// One part of every shape but box, plate, rod and point, sizes 0.2 to 1,
/// centres and vertices on the 2⁻²⁰ grid within [−1, 1]³ (translations by
/// offsets on that grid below 2³² are exact), random orientations, masses
/// and densities: cylinder, tube, thin tube, disk, annulus, ring, sphere,
/// hollow sphere, shell, triangle and a given inertia (CAD products).
pub(crate) fn every_shape(rng: &mut Rng) -> Scene {
    let mut turn = || Some(r::Rotation::Quaternion(rng.quaternion()));
    let rotations: Vec<_> = (0..8).map(|_| turn()).collect();
    let size = |rng: &mut Rng| rng.range(0.2, 1.0);
    let density = |rng: &mut Rng| Amount::Density(rng.range(500.0, 9000.0));
    let mass = |rng: &mut Rng| Amount::Mass(rng.range(0.5, 2.0));
    let (a, b) = (size(rng), size(rng));
    let mut parts = vec![
        Part::cylinder(a, None, b, rng.grid_point(), rotations[0], density(rng)),
        Part::cylinder(
            a,
            Some(0.7 * a),
            b,
            rng.grid_point(),
            rotations[1],
            mass(rng),
        ),
        Part::cylinder(b, Some(b), a, rng.grid_point(), rotations[2], mass(rng)),
        Part::disk(
            a,
            None,
            rng.grid_point(),
            rotations[3],
            Amount::Density(rng.range(5.0, 40.0)),
        ),
        Part::disk(
            b,
            Some(0.25 * b),
            rng.grid_point(),
            None,
            Amount::Density(rng.range(5.0, 40.0)),
        ),
        Part::disk(a, Some(a), rng.grid_point(), rotations[4], mass(rng)),
        Part::sphere(a, None, rng.grid_point(), None, density(rng)),
        Part::sphere(
            b,
            Some(b * (1.0 - 1e-6)),
            rng.grid_point(),
            None,
            density(rng),
        ),
        Part::sphere(a, Some(a), rng.grid_point(), None, mass(rng)),
    ];
    let at = rng.grid_point();
    let rot = rng.rotation();
    let (e0, e1) = (edge(&rot, 0, a), edge(&rot, 1, b));
    let grid = |x: f64| (x * 1048576.0).round() / 1048576.0;
    parts.push(Part::triangle(
        [
            at,
            std::array::from_fn(|i| grid(at[i] + e0[i])),
            std::array::from_fn(|i| grid(at[i] + 0.3 * e0[i] + e1[i])),
        ],
        Amount::Density(rng.range(5.0, 40.0)),
    ));
    let m = rng.range(0.5, 2.0);
    let tensor = given_tensor(m, [0.3, 0.5, 0.6], rng.quaternion());
    let cad = std::array::from_fn(|i| {
        std::array::from_fn(|j| if i == j { tensor[i][j] } else { -tensor[i][j] })
    });
    parts.push(Part::given(
        m,
        cad,
        r::Products::Positive,
        rng.grid_point(),
        rotations[5],
    ));
    // Issue 17's shapes: solid, hollow and inverted cones, a torus and a
    // hollow one, hemispheres, and prisms (an L and a triangle).
    parts.extend([
        Part::cone(
            a,
            0.0,
            b,
            None,
            rng.grid_point(),
            rotations[6],
            density(rng),
        ),
        Part::cone(
            a,
            0.5 * b,
            b,
            Some((0.5 * a, 0.25 * b)),
            rng.grid_point(),
            rotations[7],
            mass(rng),
        ),
        Part::cone(0.0, b, a, None, rng.grid_point(), None, density(rng)),
        Part::torus(
            a + b,
            0.4 * a,
            None,
            rng.grid_point(),
            rotations[0],
            density(rng),
        ),
        Part::torus(
            b,
            0.5 * b,
            Some(0.25 * b),
            rng.grid_point(),
            None,
            mass(rng),
        ),
        Part::hemisphere(a, None, rng.grid_point(), rotations[1], density(rng)),
        Part::hemisphere(b, Some(0.9 * b), rng.grid_point(), None, mass(rng)),
        // Issue 29's capsules: solid, turned, by density; hollow by mass.
        Part::capsule(a, b, None, rng.grid_point(), rotations[2], density(rng)),
        Part::capsule(b, a, Some(0.8 * b), rng.grid_point(), None, mass(rng)),
        // Issue 29's ellipsoids: turned by density, and by mass.
        Part::ellipsoid(
            [a, b, 0.5 * a],
            rng.grid_point(),
            rotations[3],
            density(rng),
        ),
        Part::ellipsoid([b, 0.3 * a, a], rng.grid_point(), None, mass(rng)),
        Part::prism(
            vec![
                [0.0, 0.0],
                [a, 0.0],
                [a, 0.5 * b],
                [0.5 * a, 0.5 * b],
                [0.5 * a, b],
                [0.0, b],
            ],
            b,
            rng.grid_point(),
            rotations[2],
            density(rng),
        ),
        Part::prism(
            vec![[0.25, 0.5], [a + 0.25, 0.5], [0.25, b + 0.5]],
            a,
            rng.grid_point(),
            None,
            mass(rng),
        ),
    ]);
    Scene::si(parts)
}

// ---------------------------------------------------------------------------
// 1. Translation: 12 boxes, and every other shape, moved 10⁰ … 10⁹ part
// sizes

fn translation(precision: Precision, name: &str, scene: fn(&mut Rng) -> Scene) {
    let mut m = Margins::new(format!("translation {name} {}", precision.flag()));
    let mut rng = Rng::new(1);
    for trial in 0..2 {
        let base = scene(&mut rng);
        let b = Bounds::of(&base);
        let at_origin = report(&base, precision);
        let exact0 = r::compose(&base);
        check_against_reference(
            &mut m,
            &format!("trial {trial}, untranslated"),
            &base,
            &at_origin,
        );
        for k in [0, 3, 6, 9] {
            // Offsets on the 2⁻²⁰ grid, below 2³⁰: centre + offset is exact,
            // so the translated scene is exactly the same body.
            let t: [f64; 3] =
                [1.0, -0.6, 0.3].map(|d: f64| (d * 10f64.powi(k) * 1048576.0).round() / 1048576.0);
            assert!(base.translation_is_exact(t), "the translation is exact");
            let mut moved = base.translated(t);
            // About the origin, 10ᵏ away: the shifted tensor is checked too.
            moved.about = Some([0.0; 3]);
            let what = format!("trial {trial}, offset 1e{k}");
            let rep = report(&moved, precision);
            let (exact, pr) = check_against_reference(&mut m, &what, &moved, &rep);
            assert_eq!(exact.inertia, exact0.inertia, "exact translation");
            check_axes(&mut m, &what, &rep, &pr, b.moment);
            // The same result as the untranslated body, to the same bound.
            m.check(
                "I_com vs untranslated",
                &what,
                r::rel_frobenius_f64(&rep.inertia, &at_origin.inertia, &at_origin.inertia),
                b.tensor,
            );
            for i in 0..3 {
                m.check(
                    "moments vs untranslated",
                    format_args!("{what}, moment {i}"),
                    (rep.moments[i] - at_origin.moments[i]).abs() / at_origin.moments[2],
                    b.moment,
                );
            }
            // About the origin: C + m d dᵀ with |d| = 10ᵏ, a sum of positive
            // semi-definite terms: the same relative bound.
            let about = exact.inertia_about(exact.about.as_ref().expect("the scene has `about`"));
            m.check(
                "I_ref",
                &what,
                rel_frobenius(&rep.inertia_ref, &about),
                b.tensor,
            );
        }
    }
    m.finish();
}

#[test]
fn twelve_boxes_translated_up_to_1e9_sizes_keep_their_inertia_standard() {
    translation(Precision::Standard, "boxes", twelve_boxes);
}

/// Needs `--precision extended`.
#[test]
fn twelve_boxes_translated_up_to_1e9_sizes_keep_their_inertia_extended() {
    translation(Precision::Extended, "boxes", twelve_boxes);
}

#[test]
fn every_shape_translated_up_to_1e9_sizes_keeps_its_inertia_standard() {
    translation(Precision::Standard, "every shape", every_shape);
}

/// Needs `--precision extended`.
#[test]
fn every_shape_translated_up_to_1e9_sizes_keeps_its_inertia_extended() {
    translation(Precision::Extended, "every shape", every_shape);
}

// ---------------------------------------------------------------------------
// 2. Slender and flat boxes

/// The bound on the smallest moment of a slender box, relative to itself.
///
/// Standard: f64 rounds C's entries by ~ε‖C‖, and the small eigenvalues of
/// C move by that much (Weyl), so the smallest moment can be no better
/// than ε·I_max absolute, i.e. ε·I_max/I_min relative: ~100% at aspect
/// 10⁻⁹, where I_min/I_max ≈ 2·10⁻¹⁸. The test asserts that weaker bound,
/// MOMENT·I_max/I_min, to document what f64 achieves.
///
/// Extended: the same argument with double-double's u₂ = 2⁻¹⁰⁴: 40·u₂ ·
/// I_max/I_min, which is ≈ 1e-12 at aspect 10⁻⁹ (the bound), capped
/// there, plus 2ε for the final rounding to f64.
fn smallest_moment_bound(precision: Precision, top_over_min: f64) -> f64 {
    match precision {
        Precision::Standard => MOMENT * top_over_min,
        Precision::Extended => (40.0 * U_DD * top_over_min).min(1e-12) + 2.0 * EPS,
    }
}

fn slender_and_flat(precision: Precision) {
    let mut m = Margins::new(format!("slender and flat {}", precision.flag()));
    let mut rng = Rng::new(2);
    for e in 3..=9 {
        let a = 10f64.powi(-e);
        for trial in 0..2 {
            for (kind, size, flag, unique) in [
                ("slender", [a, a, 1.0], vec![1, 2], 0),
                ("flat", [1.0, 1.0, a], vec![0, 1], 2),
            ] {
                let amount = if trial == 0 {
                    Amount::Mass(rng.range(0.5, 2.0))
                } else {
                    Amount::Density(rng.range(500.0, 9000.0))
                };
                let scene = Scene::si(vec![Part::cuboid(
                    size,
                    rng.grid_point(),
                    Some(rng.quaternion()),
                    amount,
                )]);
                let what = format!("{kind} 1e-{e}, trial {trial}");
                let rep = report(&scene, precision);
                let (_, pr) = check_against_reference(&mut m, &what, &scene, &rep);
                // The smallest moment, relative to itself.
                let top_over_min = f(&(&pr.moments[2] / &pr.moments[0]));
                m.check(
                    &format!("{kind} I_min"),
                    &what,
                    rel(rep.moments[0], &pr.moments[0]),
                    smallest_moment_bound(precision, top_over_min),
                );
                // Two moments are exactly equal: flagged, and the third axis
                // (the long axis, or the normal) is well separated.
                m.require(
                    "flags",
                    format_args!("{what}: {:?}", rep.equal),
                    rep.equal == flag,
                );
                m.check(
                    "axes",
                    &what,
                    axis_sin(
                        &rep.axes[unique],
                        pr.axes[unique].as_ref().expect("distinct"),
                    ),
                    MOMENT / pr.gap(unique),
                );
            }
        }
    }
    m.finish();
}

#[test]
fn slender_and_flat_boxes_standard() {
    slender_and_flat(Precision::Standard);
}

/// Needs `--precision extended`: the smallest moment of a 1 × 10⁻⁹ × 10⁻⁹
/// box to 1e-12 relative.
#[test]
fn slender_and_flat_boxes_extended() {
    slender_and_flat(Precision::Extended);
}

// ---------------------------------------------------------------------------
// 3. Equal moments

/// Integer edges, mutually perpendicular, all of length 3, oblique to the
/// file axes.
const OBLIQUE: [[f64; 3]; 3] = [[2.0, 1.0, 2.0], [1.0, 2.0, -2.0], [2.0, -2.0, -1.0]];

fn scaled(v: [f64; 3], s: f64) -> [f64; 3] {
    v.map(|x| x * s)
}

fn plus(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| a[i] + b[i])
}

/// The sign rule of docs/part-file.md: largest component positive, the
/// first among components equal within 1e-9.
fn sign_rule(v: [f64; 3]) -> [f64; 3] {
    let max = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let lead = v.iter().find(|x| x.abs() >= max - 1e-9).expect("a largest");
    if *lead < 0.0 { v.map(|x| -x) } else { v }
}

/// The pair rule of docs/part-file.md for the equal moments' axes, given
/// the distinct axis u: the file axis most nearly perpendicular to u
/// (first among ties within 1e-9), projected off u.
fn in_plane(u: [f64; 3]) -> [f64; 3] {
    let min = u.iter().fold(f64::INFINITY, |m, x| m.min(x.abs()));
    let k = u
        .iter()
        .position(|x| x.abs() <= min + 1e-9)
        .expect("a smallest");
    let mut v = u.map(|x| -x * u[k]);
    v[k] += 1.0;
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|x| x / n)
}

fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn max_diff(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> f64 {
    (0..9)
        .map(|i| (a[i / 3][i % 3] - b[i / 3][i % 3]).abs())
        .fold(0.0, f64::max)
}

fn equal_moment_scenes(rng: &mut Rng) -> Vec<(&'static str, Scene, Vec<usize>)> {
    let s = 0.5;
    // A cube of 8 oblique sub-cubes, placed by integer corners and edges.
    let mut cube8 = Vec::new();
    for i in 0..8 {
        let corner = (0..3).fold([1.0, 2.0, 3.0], |c, k| {
            if i >> k & 1 == 1 {
                plus(c, scaled(OBLIQUE[k], s))
            } else {
                c
            }
        });
        cube8.push(Part::box_edges(
            corner,
            OBLIQUE.map(|e| scaled(e, s)),
            Amount::Mass(0.5),
        ));
    }
    // A square plate in two halves, oblique.
    let half = scaled(OBLIQUE[0], 0.5);
    let plate2 = vec![
        Part::plate_edges([1.0, -1.0, 2.0], [half, OBLIQUE[1]], Amount::Density(3.0)),
        Part::plate_edges(
            plus([1.0, -1.0, 2.0], half),
            [half, OBLIQUE[1]],
            Amount::Density(3.0),
        ),
    ];
    // Three equal rods along the oblique axes, crossing at (1, 1, 1).
    let rods = OBLIQUE
        .iter()
        .map(|e| {
            Part::rod_from_to(
                plus([1.0; 3], scaled(*e, -0.5)),
                plus([1.0; 3], scaled(*e, 0.5)),
                Amount::Mass(1.5),
            )
        })
        .collect();
    vec![
        (
            "cube",
            Scene::si(vec![Part::cuboid(
                [0.3; 3],
                rng.grid_point(),
                Some(rng.quaternion()),
                Amount::Density(7850.0),
            )]),
            vec![0, 1, 2],
        ),
        (
            "square plate",
            Scene::si(vec![Part::plate(
                [0.7; 2],
                rng.grid_point(),
                Some(rng.quaternion()),
                Amount::Mass(2.0),
            )]),
            vec![0, 1],
        ),
        ("three orthogonal rods", Scene::si(rods), vec![0, 1, 2]),
        ("cube of eight boxes", Scene::si(cube8), vec![0, 1, 2]),
        ("plate of two halves", Scene::si(plate2), vec![0, 1]),
    ]
}

fn equal_moments(precision: Precision) {
    let mut m = Margins::new(format!("equal moments {}", precision.flag()));
    let mut rng = Rng::new(3);
    for (what, scene, flag) in equal_moment_scenes(&mut rng) {
        let rep = report(&scene, precision);
        let (_, pr) = check_against_reference(&mut m, what, &scene, &rep);
        m.require(
            "flags",
            format_args!("{what}: {:?}", rep.equal),
            rep.equal == flag,
        );
        // The same file twice: the same bytes.
        let again = report(&scene, precision);
        m.require(
            "determinism",
            format_args!("{what}, run twice"),
            again.stdout == rep.stdout,
        );
        // The parts reversed: the sums round differently, so moments agree
        // to MOMENT; the axes follow the rule, which is continuous away
        // from its ties: all equal → exactly the file axes.
        let order: Vec<usize> = (0..scene.parts.len()).rev().collect();
        let rev = report(&scene.reordered(&order), precision);
        m.require(
            "flags",
            format_args!("{what}, reversed: {:?}", rev.equal),
            rev.equal == flag,
        );
        for k in 0..3 {
            m.check(
                "moments reordered",
                format_args!("{what}, moment {k}"),
                (rev.moments[k] - rep.moments[k]).abs() / rep.moments[2],
                MOMENT,
            );
        }
        if flag.len() == 3 {
            let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
            m.require(
                "axes rule",
                format_args!("{what}: {:?}", rep.axes),
                rep.axes == identity,
            );
            m.require(
                "axes rule",
                format_args!("{what}, reversed"),
                rev.axes == identity,
            );
        } else {
            // Pair [0, 1]: axis 2 is unique, within MOMENT/gap of the
            // reference; axes 0 and 1 follow from it by the documented rule
            // (evaluated here on the reference axis, so within the same
            // bound, times a small factor for the projection).
            let u_exact = pr.axes[2].as_ref().expect("distinct");
            let bound = MOMENT / pr.gap(2);
            m.check("axes", what, axis_sin(&rep.axes[2], u_exact), bound);
            let norm = r::norm(u_exact);
            let u = sign_rule(r::fv(u_exact).map(|x| x / norm));
            let v = in_plane(u);
            let expect = [v, cross3(u, v), u];
            m.check("axes rule", what, max_diff(&rep.axes, &expect), 4.0 * bound);
            m.check(
                "axes reordered",
                what,
                max_diff(&rev.axes, &rep.axes),
                4.0 * bound,
            );
        }
    }
    m.finish();
}

#[test]
fn equal_moments_are_flagged_with_deterministic_axes_standard() {
    equal_moments(Precision::Standard);
}

/// Needs `--precision extended`.
#[test]
fn equal_moments_are_flagged_with_deterministic_axes_extended() {
    equal_moments(Precision::Extended);
}

// ---------------------------------------------------------------------------
// 4. Nearly equal moments

fn nearly_equal(precision: Precision) {
    let mut m = Margins::new(format!("nearly equal {}", precision.flag()));
    let mut rng = Rng::new(4);
    // A box 1 × (1 + δ) × 2: moments (m/12)·(b² + 4, 5, 1 + b²), the top two
    // a relative 2δ/5 apart.
    for g in [1e-4, 1e-6, 1e-8, 1e-10, 1e-12] {
        for trial in 0..3 {
            let b = 1.0 + 2.5 * g;
            let scene = Scene::si(vec![Part::cuboid(
                [1.0, b, 2.0],
                rng.grid_point(),
                Some(rng.quaternion()),
                Amount::Mass(rng.range(0.5, 2.0)),
            )]);
            let what = format!("gap {g:e}, trial {trial}");
            let rep = report(&scene, precision);
            let (_, pr) = check_against_reference(&mut m, &what, &scene, &rep);
            let gap = pr.gap(2);
            assert!(
                (gap / g - 1.0).abs() < 1e-3,
                "the scene has the gap it says: {gap:e}"
            );
            // Above the equality tolerance (1e-9 of the largest moment) the
            // pair is distinct and its axes are within MOMENT/gap; below it,
            // flagged. The gaps stay a factor 10 from the tolerance.
            let flag = if g > 1e-9 { vec![] } else { vec![1, 2] };
            m.require(
                "flags",
                format_args!("{what}: {:?}", rep.equal),
                rep.equal == flag,
            );
            check_axes(&mut m, &what, &rep, &pr, MOMENT);
        }
    }
    m.finish();
}

#[test]
fn nearly_equal_moments_standard() {
    nearly_equal(Precision::Standard);
}

/// Needs `--precision extended`.
#[test]
fn nearly_equal_moments_extended() {
    nearly_equal(Precision::Extended);
}

// ---------------------------------------------------------------------------
// 5. Mass ratios up to 10¹²

fn random_direction(rng: &mut Rng) -> [f64; 3] {
    let q = rng.quaternion();
    [q[1], q[2], q[3]].map(|x| x / (q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt())
}

fn mass_ratios(precision: Precision) {
    let mut m = Margins::new(format!("mass ratios {}", precision.flag()));
    let mut rng = Rng::new(5);
    for e in [3, 6, 9, 12] {
        let light = 10f64.powi(-e);
        // A heavy box and light parts 10³ away (their m d² is 10⁶·10⁻ᵉ of
        // the box's own moments: visible down to 1e-12).
        let mut heavy_centre = vec![Part::cuboid(
            [1.0, 2.0, 0.5],
            [2.0, 3.0, 4.0],
            Some(rng.quaternion()),
            Amount::Mass(1.0),
        )];
        for k in 0..5 {
            let at = plus([2.0, 3.0, 4.0], scaled(random_direction(&mut rng), 1e3));
            heavy_centre.push(match k % 3 {
                0 => Part::point(light * rng.range(0.5, 2.0), at),
                1 => Part::cuboid([1.0; 3], at, Some(rng.quaternion()), Amount::Mass(light)),
                _ => Part::rod(5.0, at, Some(rng.quaternion()), Amount::Mass(light)),
            });
        }
        // The reverse: a light, large plate at the centre and heavy small
        // parts 10³ away.
        let mut light_centre = vec![Part::plate(
            [10.0, 20.0],
            [-1.0, 0.5, 2.0],
            Some(rng.quaternion()),
            Amount::Mass(light),
        )];
        for k in 0..4 {
            let at = plus([-1.0, 0.5, 2.0], scaled(random_direction(&mut rng), 1e3));
            light_centre.push(match k % 2 {
                0 => Part::point(rng.range(0.5, 2.0), at),
                _ => Part::cuboid([0.1; 3], at, Some(rng.quaternion()), Amount::Mass(1.0)),
            });
        }
        for (kind, parts) in [
            ("heavy centre", heavy_centre),
            ("light centre", light_centre),
        ] {
            let scene = Scene::si(parts);
            let what = format!("{kind}, ratio 1e{e}");
            let rep = report(&scene, precision);
            let (_, pr) = check_against_reference(&mut m, &what, &scene, &rep);
            check_axes(&mut m, &what, &rep, &pr, MOMENT);
        }
    }
    m.finish();
}

#[test]
fn mass_ratios_up_to_1e12_standard() {
    mass_ratios(Precision::Standard);
}

/// Needs `--precision extended`.
#[test]
fn mass_ratios_up_to_1e12_extended() {
    mass_ratios(Precision::Extended);
}

// ---------------------------------------------------------------------------
// 6. Units

/// One physical scene in m and kg, with densities of every kind.
pub(crate) fn steel_assembly(rng: &mut Rng) -> Scene {
    let mut parts = Vec::new();
    for _ in 0..3 {
        let size = [
            rng.range(0.01, 0.1),
            rng.range(0.01, 0.1),
            rng.range(0.01, 0.1),
        ];
        let at = [
            rng.range(0.1, 1.0),
            rng.range(0.1, 1.0),
            rng.range(0.1, 1.0),
        ];
        parts.push(Part::cuboid(
            size,
            at,
            Some(rng.quaternion()),
            Amount::Density(7850.0),
        ));
    }
    let rot = rng.rotation();
    parts.push(Part::box_edges(
        [0.3, 0.2, 0.5],
        [
            edge(&rot, 0, 0.05),
            edge(&rot, 1, 0.02),
            edge(&rot, 2, 0.08),
        ],
        Amount::Density(2700.0),
    ));
    parts.push(Part::plate(
        [0.2, 0.3],
        [0.5, 0.4, 0.3],
        Some(rng.quaternion()),
        Amount::Density(15.7),
    ));
    parts.push(Part::rod_from_to(
        [0.1, 0.9, 0.2],
        [0.8, 0.7, 0.6],
        Amount::Density(0.4),
    ));
    parts.push(Part::rod(
        0.25,
        [0.6, 0.6, 0.6],
        Some(rng.quaternion()),
        Amount::Mass(0.3),
    ));
    parts.push(Part::point(1.25, [0.9, 0.1, 0.4]));
    let mut s = Scene::si(parts);
    s.about = Some([0.0, 0.0, 0.0]);
    s
}

/// The bound for every quantity in the units test: 1e-15 relative.
/// (Mass and centre of mass of these 8 parts have a priori bounds of
/// 19u ≈ 2.1e-15 and 22u ≈ 2.4e-15; the issue asks for better, which holds
/// because rounding errors do not all align.)
const UNITS_BOUND: f64 = 1e-15;

fn units(precision: Precision) {
    let mut m = Margins::new(format!("units {}", precision.flag()));
    let mut rng = Rng::new(6);
    let si = steel_assembly(&mut rng);
    let exact_si = r::compose(&si);
    for (length, mass) in [
        (Length::Um, Mass::Mg),
        (Length::Mm, Mass::G),
        (Length::M, Mass::Kg),
        (Length::Km, Mass::T),
        (Length::Cm, Mass::G),
        (Length::In, Mass::Lb),
        (Length::Ft, Mass::Lb),
    ] {
        let scene = si.in_units(length, mass);
        let what = format!("{} and {}", length.symbol(), mass.symbol());
        let rep = report(&scene, precision);
        let exact = r::compose(&scene);
        // The converted scene is the same body up to one rounding per number.
        assert!(rel_frobenius(&fm(&exact.inertia), &exact_si.inertia) < 1e-14);
        m.check(
            "I_com",
            &what,
            rel_frobenius(&rep.inertia, &exact.inertia),
            UNITS_BOUND,
        );
        let about = exact.inertia_about(exact.about.as_ref().expect("the scene has `about`"));
        m.check(
            "I_ref",
            &what,
            rel_frobenius(&rep.inertia_ref, &about),
            UNITS_BOUND,
        );
        m.check("mass", &what, rel(rep.mass, &exact.mass), UNITS_BOUND);
        m.check("com", &what, r::rel_vec(&rep.com, &exact.com), UNITS_BOUND);
        let pr = exact.principal();
        for k in 0..3 {
            m.check(
                "moments",
                format_args!("{what}, moment {k}"),
                rel(rep.moments[k], &pr.moments[k]),
                UNITS_BOUND,
            );
        }
    }
    m.finish();
}

#[test]
fn the_same_body_in_any_units_standard() {
    units(Precision::Standard);
}

/// Needs `--precision extended`.
#[test]
fn the_same_body_in_any_units_extended() {
    units(Precision::Extended);
}

// ---------------------------------------------------------------------------
// 7. Rotation of the whole assembly

/// Parts that a quarter turn maps exactly: placed by edges, from/to, points,
/// unrotated boxes.
pub(crate) fn turnable_assembly(rng: &mut Rng) -> Scene {
    let mut parts = Vec::new();
    for k in 0..6 {
        let rot = rng.rotation();
        let s = [
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
        ];
        let at = rng.grid_point();
        let mass = Amount::Mass(rng.range(0.5, 2.0));
        parts.push(match k % 3 {
            0 => Part::box_edges(at, [0, 1, 2].map(|i| edge(&rot, i, s[i])), mass),
            1 => Part::plate_edges(at, [edge(&rot, 0, s[0]), edge(&rot, 1, s[1])], mass),
            _ => Part::rod_from_to(at, plus(at, edge(&rot, 2, s[2])), mass),
        });
    }
    parts.push(Part::cuboid(
        [0.3, 0.5, 0.7],
        rng.grid_point(),
        None,
        Amount::Density(1000.0),
    ));
    parts.push(Part::point(0.75, rng.grid_point()));
    Scene::si(parts)
}

/// The tensor turned a quarter turn about `axis`: P I Pᵀ, with P the
/// permutation with one sign that `Scene::quarter_turn` applies.
pub(crate) fn turn_tensor(i: &[[f64; 3]; 3], axis: usize) -> [[f64; 3]; 3] {
    let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
    let p = |v: usize| -> (usize, f64) {
        if v == a {
            (b, 1.0)
        } else if v == b {
            (a, -1.0)
        } else {
            (v, 1.0)
        }
    };
    // New coordinate b is old a; new a is −old b.
    let mut out = [[0.0; 3]; 3];
    for (r, row) in i.iter().enumerate() {
        for (c, x) in row.iter().enumerate() {
            let (r2, sr) = p(r);
            let (c2, sc) = p(c);
            out[r2][c2] = sr * sc * x;
        }
    }
    out
}

/// An a priori bound on how much rounding each input of `scene` (relative
/// u per coordinate, 3u per quaternion component) can move its second
/// moment C, ‖ΔC‖_F: a part's own C changes by 2u·tr Cᵢ per edge
/// (12u·tr Cᵢ for a rounded quaternion: angle ≤ 6u), and its centroid by
/// δᵢ ≤ u·Pᵢ (Pᵢ the size of the numbers it is formed from) moves
/// mᵢdᵢdᵢᵀ by 2mᵢ|dᵢ|δᵢ + mᵢδᵢ². A moment is tr C − λ(C), so it moves by
/// at most (√3 + 1)‖ΔC‖_F.
fn rounding_bound(scene: &Scene, exact: &Exact) -> f64 {
    let mut dc = 0.0;
    for (p, e) in scene.parts.iter().zip(&exact.parts) {
        let tr = f(&(&e.second_moment[0][0] + &e.second_moment[1][1] + &e.second_moment[2][2]));
        let len = |v: &[f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        let turned = |rotation: &Option<r::Rotation>| match rotation {
            Some(r::Rotation::Quaternion(_)) => 12.0 * U * tr,
            // None, or a signed permutation: no rounding.
            _ => 0.0,
        };
        let (own, size) = match &p.place {
            Place::Center {
                center, rotation, ..
            }
            | Place::Given {
                center, rotation, ..
            } => (turned(rotation), len(center)),
            Place::Edges { corner, edges } => (
                2.0 * U * tr,
                len(corner) + edges.iter().map(len).sum::<f64>() / 2.0,
            ),
            Place::FromTo { from, to } => (2.0 * U * tr, (len(from) + len(to)) / 2.0),
            Place::Prism {
                origin, rotation, ..
            } => (turned(rotation), len(origin)),
            // Each vertex moves by u|vᵢ|, an edge by up to 2u max|vᵢ|: the
            // triangle's own C by 2·(2u max|vᵢ| / shortest edge) of itself.
            Place::Vertices(v) => {
                let far = v.iter().map(len).fold(0.0, f64::max);
                let edge = |a: usize, b: usize| len(&std::array::from_fn(|i| v[a][i] - v[b][i]));
                let short = edge(0, 1).min(edge(1, 2)).min(edge(2, 0));
                (
                    4.0 * U * far / short * tr,
                    v.iter().map(len).sum::<f64>() / 3.0,
                )
            }
        };
        let d = r::norm(&std::array::from_fn(|i| &e.center[i] - &exact.com[i]));
        let delta = U * size;
        let mass = f(&e.mass);
        dc += own + 2.0 * mass * d * delta + mass * delta * delta;
    }
    (3f64.sqrt() + 1.0) * dc
}

fn rotations(precision: Precision) {
    let mut m = Margins::new(format!("rotations {}", precision.flag()));
    let mut rng = Rng::new(7);
    for trial in 0..2 {
        let scene = turnable_assembly(&mut rng);
        let rep = report(&scene, precision);
        let what = format!("trial {trial}");
        check_against_reference(&mut m, &what, &scene, &rep);
        // Quarter turns are exact on the inputs: the tensor is permuted, the
        // moments the same to rounding (the sums meet the numbers in another
        // order).
        for axis in 0..3 {
            let turned = scene.quarter_turn(axis);
            let what = format!(
                "trial {trial}, quarter turn about {}",
                ["x", "y", "z"][axis]
            );
            let t = report(&turned, precision);
            let (exact, pr) = check_against_reference(&mut m, &what, &turned, &t);
            check_axes(&mut m, &what, &t, &pr, MOMENT);
            let permuted = turn_tensor(&rep.inertia, axis);
            assert_eq!(
                fm(&exact.inertia),
                turn_tensor(&fm(&r::compose(&scene).inertia), axis)
            );
            m.check(
                "I_com turned",
                &what,
                r::rel_frobenius_f64(&t.inertia, &permuted, &rep.inertia),
                2.0 * TENSOR,
            );
            for k in 0..3 {
                m.check(
                    "moments turned",
                    format_args!("{what}, moment {k}"),
                    (t.moments[k] - rep.moments[k]).abs() / rep.moments[2],
                    2.0 * MOMENT,
                );
            }
        }
    }
    // Rational rotations (entries 3/5, 4/5 and 3/7, 2/7, 6/7) of a general
    // assembly, canonical rotated parts included: inputs rotated exactly and
    // rounded, so the moments agree with the original's to the rounding
    // bound plus both computations' errors.
    let mut parts = turnable_assembly(&mut rng).parts;
    parts.extend(twelve_boxes(&mut rng).parts.into_iter().take(4));
    parts.push(Part::rod(
        0.8,
        rng.grid_point(),
        Some(rng.quaternion()),
        Amount::Density(2.0),
    ));
    let scene = Scene::si(parts);
    let rep = report(&scene, precision);
    let exact0 = r::compose(&scene);
    let pr0 = exact0.principal();
    for quat in [[2, 1, 0, 0], [2, 1, 1, 1]] {
        let turned = scene.rotated(quat);
        let what = format!("rotation by quaternion {quat:?}");
        let t = report(&turned, precision);
        let (_, pr) = check_against_reference(&mut m, &what, &turned, &t);
        check_axes(&mut m, &what, &t, &pr, MOMENT);
        // Placements of the turned scene (unrotated boxes gain a rounded
        // quaternion), masses and offsets of the original.
        let rounding = rounding_bound(&turned, &exact0);
        let top = f(&pr0.moments[2]);
        for k in 0..3 {
            // The a priori bound must cover the exact change.
            let exact_change = f(&(&pr.moments[k] - &pr0.moments[k]).abs());
            m.check(
                "rounding bound",
                format_args!("{what}, moment {k}"),
                exact_change,
                rounding,
            );
            m.check(
                "moments rotated",
                format_args!("{what}, moment {k}"),
                (t.moments[k] - rep.moments[k]).abs(),
                rounding + 2.0 * MOMENT * top,
            );
        }
    }
    m.finish();
}

#[test]
fn rotating_the_assembly_permutes_the_tensor_and_keeps_the_moments_standard() {
    rotations(Precision::Standard);
}

/// Needs `--precision extended`.
#[test]
fn rotating_the_assembly_permutes_the_tensor_and_keeps_the_moments_extended() {
    rotations(Precision::Extended);
}

// ---------------------------------------------------------------------------
// 8. Degenerate bodies: zero moments

fn zero_moments(precision: Precision) {
    let mut m = Margins::new(format!("zero moments {}", precision.flag()));
    let mut rng = Rng::new(8);
    let mut scenes = Vec::new();
    for _ in 0..4 {
        scenes.push((
            "rod",
            Scene::si(vec![Part::rod(
                rng.range(0.1, 10.0),
                rng.grid_point(),
                Some(rng.quaternion()),
                Amount::Mass(1.0),
            )]),
        ));
        let dir = random_direction(&mut rng);
        let base = rng.grid_point();
        // Collinear points: exactly on a line only if the offsets are exact,
        // so the line runs along a file axis through the random base.
        let line = (0..4)
            .map(|k| Part::point(rng.range(0.5, 2.0), plus(base, [0.0, 0.0, k as f64 * 0.75])))
            .collect();
        scenes.push(("collinear points", Scene::si(line)));
        let rods = (0..3)
            .map(|k| {
                Part::rod_from_to(
                    scaled(dir, k as f64),
                    scaled(dir, k as f64 + 0.5),
                    Amount::Mass(1.0),
                )
            })
            .collect();
        scenes.push(("rods end to end", Scene::si(rods)));
    }
    scenes.push((
        "a point",
        Scene::si(vec![Part::point(3.0, [1e9, -2.0, 0.5])]),
    ));
    for (what, scene) in scenes {
        // `report` asserts finite, non-negative, ascending moments.
        let rep = report(&scene, precision);
        let exact = r::compose(&scene);
        let pr = exact.principal();
        let top = f(&pr.moments[2]);
        let err = if top == 0.0 {
            rep.moments[2]
        } else {
            r::err_over(rep.moments[0], &pr.moments[0], top)
        };
        m.check("smallest moment", what, err, MOMENT);
        // Relative to an exact zero tensor, only an exact zero passes.
        m.check(
            "I_com",
            what,
            rel_frobenius(&rep.inertia, &exact.inertia),
            TENSOR,
        );
    }
    m.finish();
}

#[test]
fn no_negative_or_nan_moment_in_degenerate_bodies_standard() {
    zero_moments(Precision::Standard);
}

/// Needs `--precision extended`.
#[test]
fn no_negative_or_nan_moment_in_degenerate_bodies_extended() {
    zero_moments(Precision::Extended);
}

/// The every-shape scene draws every shape massprop has (`shapes::SHAPES`)
/// beyond the box, plate, rod and point that every other scene is made of:
/// a shape added without its exact reference and its place here fails this
/// test (docs/architecture.md, "Adding a shape").
#[test]
fn the_every_shape_scene_has_every_shape() {
    let scene = every_shape(&mut Rng::new(1));
    let text = crate::support::reference::to_toml(&scene);
    let model = massprop::model::Model::parse(&massprop::diag::Source::new("s.toml", text))
        .unwrap_or_else(|d| panic!("{d}"));
    let mut drawn: std::collections::BTreeSet<&str> =
        model.flattened().iter().map(|p| p.shape().name()).collect();
    // A mesh is read from a file, which a scene's text cannot carry: its
    // exact integrals are tested against their own references in
    // src/mesh/tests.rs and tests/integration/meshes.rs.
    drawn.extend(["box", "plate", "rod", "point", "mesh"]);
    let all: std::collections::BTreeSet<&str> =
        massprop::shapes::SHAPES.iter().map(|s| s.name).collect();
    assert_eq!(drawn, all);
}
