//! Each simulator's own rule for an inertial, as its source applies it, and
//! the margin by which each part of the rule holds or fails.
//!
//! - **MuJoCo** (4.0, `mjCBody::Compile` in user_objects.cc; measured with
//!   the mujoco Python package, tests/oracle/MUJOCO-RULES.md);
//! - **Gazebo**: gz-math's `MassMatrix3::IsValid()` with its default
//!   tolerance 10, which libsdformat applies to every link ("A link named X
//!   has invalid inertia"), on gz-math's own principal moments;
//! - **Drake**: `RotationalInertia::CouldBePhysicallyValid()` and the mass
//!   as its parser takes it (tests/oracle/ENGINE-RULES.md).
//!
//! MuJoCo and Drake are judged on accurate principal moments (Jacobi in
//! double-double), each engine's comparisons made in f64 in its source's
//! order; their own solvers are within tens of ulps (`Rule::close`).
//! gz-math's is not (~1e-8 near a double moment): its rule runs on its own
//! formulas (`gz_principal_moments`). tests/oracle/ checks all three.

use super::{MujocoCompiler, Tensor, Written};
use crate::numeric::{DD, Real};
use serde::Serialize;

/// A simulator whose rule is checked (`--engine`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, PartialOrd, Ord)]
#[serde(rename_all = "lowercase")]
pub enum Engine {
    Mujoco,
    Gazebo,
    Drake,
}

impl Engine {
    /// Every engine, in the order outputs list them.
    pub const ALL: [Engine; 3] = [Engine::Mujoco, Engine::Gazebo, Engine::Drake];

    pub fn name(self) -> &'static str {
        match self {
            Engine::Mujoco => "mujoco",
            Engine::Gazebo => "gazebo",
            Engine::Drake => "drake",
        }
    }
}

/// MuJoCo's `mjEPS`: the smallest eigenvalue a `fullinertia` (and every
/// URDF inertial, imported as one) may have.
pub const MJ_EPS: f64 = 1e-14;
/// MuJoCo's `mjMINVAL`: the least mass and principal moment of a body that
/// moves.
pub const MJ_MINVAL: f64 = 1e-15;
/// gz-math's default tolerance factor in `MassMatrix3::IsValid`.
pub const GZ_TOLERANCE: f64 = 10.0;
/// Drake's factor in `CouldBePhysicallyValid`.
pub const DRAKE_TOLERANCE: f64 = 16.0;

/// What an engine is judged on: one inertial as the file gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Facts {
    pub mass: f64,
    /// As written (in the inertial frame: a turn does not change a rule).
    pub tensor: Tensor,
    pub written: Written,
    pub moving: bool,
    /// A moving body that a jointless descendant with mass and inertia
    /// carries (reached through jointless bodies only): MuJoCo waives the
    /// moving body's floor for it.
    pub rescued: bool,
}

/// One part of an engine's rule, and how it came out.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Rule {
    /// Its key: `mass`, `eigenvalues`, `nonnegative`, `triangle`,
    /// `leading_minors`, `moving_mass`, `moving_inertia`.
    pub rule: &'static str,
    /// The rule as the engine's source states it, with its constants.
    pub statement: String,
    pub holds: bool,
    /// The quantity compared (SI), and the limit it is compared with:
    /// `triangle`: A + B − C against −ε; `eigenvalues`: the smallest
    /// principal moment against the floor; `mass`: the mass against 0.
    pub value: f64,
    pub limit: f64,
    /// How far it holds (positive) or fails (negative), relative:
    /// `triangle` (A + B − C + ε)/C; a moment's rule (λ − limit)/(tr/2),
    /// tr/2 being the largest moment the tensor could have. None where
    /// there is no scale (a mass rule, a zero tensor).
    pub margin: Option<f64>,
    /// The margin is within a few roundings of zero: the engine's own
    /// eigen solver may decide it the other way.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub close: bool,
}

/// An engine's verdict on one inertial.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Verdict {
    pub engine: Engine,
    pub valid: bool,
    pub rules: Vec<Rule>,
    /// Why the rule is not applied, or what the engine does instead.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// The principal moments of `t`, ascending, accurate to about an ulp each
/// (Jacobi in double-double). None for a tensor with a non-finite entry.
pub fn principal_moments(t: &Tensor) -> Option<[f64; 3]> {
    let m = t.matrix().map(|r| r.map(DD::of));
    let (lam, _) = crate::eigen::jacobi(m)?;
    let mut lam = lam.map(Real::f64);
    lam.sort_by(f64::total_cmp);
    Some(lam)
}

/// The relative size of a few roundings of the eigenvalues, below which a
/// margin is `close`. NOTE: engines solve in f64 (MuJoCo's `mju_eig3`,
/// gz-math's closed-form cubic, Eigen's solver in Drake), each with a
/// backward error of some tens of ulps of the largest moment.
const CLOSE: f64 = 64.0 * f64::EPSILON;

fn rel(x: f64, scale: f64) -> Option<f64> {
    (scale > 0.0).then(|| x / scale).filter(|r| r.is_finite())
}

/// `engine`'s verdict on `f`; `compiler`: the file's MuJoCo compiler
/// settings (MuJoCo only).
pub fn judge(engine: Engine, f: &Facts, compiler: &MujocoCompiler) -> Verdict {
    judge_with(engine, f, principal_moments(&f.tensor), compiler)
}

/// `judge` with `f`'s `principal_moments` found once for every engine.
pub fn judge_with(
    engine: Engine,
    f: &Facts,
    moments: Option<[f64; 3]>,
    compiler: &MujocoCompiler,
) -> Verdict {
    let Some(moments) = moments else {
        // The reader refuses non-finite numbers; a sum of huge finite ones
        // can still overflow.
        return overflow(engine, "the tensor's principal moments overflow");
    };
    let mut v = match engine {
        Engine::Mujoco => mujoco(f, moments, compiler),
        Engine::Gazebo => gazebo(f),
        Engine::Drake => drake(f, moments),
    };
    // NOTE: values near f64::MAX make the engine's own sums and products
    // (A + B − C, the tolerance from A + B + C, a determinant) infinite or
    // NaN, and then its comparisons mean nothing: no verdict is given on
    // them, and no infinite value is shown.
    if !v
        .rules
        .iter()
        .all(|r| r.value.is_finite() && r.limit.is_finite())
    {
        return overflow(
            engine,
            &format!(
                "the values overflow f64 in {}'s rule: a sum or product of them is beyond 1.8e308",
                engine.name()
            ),
        );
    }
    // Without products every solver returns the diagonal as written: no
    // solver's rounding can decide a margin the other way.
    if f.tensor.products().iter().all(|&p| p == 0.0) {
        for r in &mut v.rules {
            r.close = false;
        }
    }
    v
}

/// A number in a note: as written in a file, with an exponent when it is
/// very large or small (`Display` writes 1e300 with 300 digits).
fn num(x: f64) -> String {
    if x == 0.0 || (1e-5..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// No verdict, invalid: the rule cannot be applied in f64.
fn overflow(engine: Engine, why: &str) -> Verdict {
    Verdict {
        engine,
        valid: false,
        rules: Vec::new(),
        note: Some(why.into()),
    }
}

/// Whether `engine` accepts `f`: `judge`'s `valid`.
pub fn accepts(engine: Engine, f: &Facts, compiler: &MujocoCompiler) -> bool {
    judge(engine, f, compiler).valid
}

/// The triangle inequality on ascending moments [A, B, C] with tolerance
/// `eps`, as the engines write it: A + B + ε ≥ C (the other two
/// inequalities hold for sorted non-negative moments; they are checked
/// too, in the engines' order, for negative ones).
fn triangle(m: [f64; 3], eps: f64, statement: String) -> Rule {
    let [a, b, c] = m;
    let holds = a + b + eps >= c && b + c + eps >= a && c + a + eps >= b;
    let value = a + b - c;
    Rule {
        rule: "triangle",
        statement,
        holds,
        value,
        limit: -eps,
        margin: rel(value + eps, c.abs()),
        close: (value + eps).abs() <= CLOSE * c.abs(),
    }
}

/// A moment rule: the smallest principal moment against `limit`.
fn smallest(rule: &'static str, m: [f64; 3], limit: f64, holds: bool, statement: String) -> Rule {
    let scale = (m[0] + m[1] + m[2]).abs() / 2.0;
    Rule {
        rule,
        statement,
        holds,
        value: m[0],
        limit,
        margin: rel(m[0] - limit, scale),
        close: (m[0] - limit).abs() <= CLOSE * scale,
    }
}

fn mass_rule(rule: &'static str, mass: f64, limit: f64, holds: bool, statement: &str) -> Rule {
    Rule {
        rule,
        statement: statement.into(),
        holds,
        value: mass,
        limit,
        margin: None,
        close: false,
    }
}

fn verdict(engine: Engine, rules: Vec<Rule>, note: Option<String>) -> Verdict {
    Verdict {
        engine,
        valid: rules.iter().all(|r| r.holds),
        rules,
        note,
    }
}

/// MuJoCo 4.0, in its order per body (tests/oracle/MUJOCO-RULES.md has
/// the experiments): the `fullinertia` eigenvalue floor; mass and moments
/// raised to `boundmass` and `boundinertia` (so a negative value is
/// clamped to 0 by default, silently); the triangle inequality on the
/// sums rounded to f64, no tolerance (or `balanceinertia`'s mean); a
/// moving body's floor mjMINVAL, unless a jointless descendant carries it.
fn mujoco(f: &Facts, moments: [f64; 3], c: &MujocoCompiler) -> Verdict {
    let mut rules = Vec::new();
    let mut notes = Vec::new();
    let t = &f.tensor;
    // URDF's all-zero tensor is no fullinertia: zero inertia, fine on a
    // link that does not move.
    let zero = [t.xx, t.yy, t.zz, t.xy, t.xz, t.yz]
        .iter()
        .all(|&x| x == 0.0);
    let full = match f.written {
        Written::Diagonal => false,
        Written::Attributes => !zero,
        _ => true,
    };
    if full {
        rules.push(if c.boundinertia > 0.0 {
            let limit = -MJ_EPS * moments[2].max(1.0);
            smallest(
                "eigenvalues",
                moments,
                limit,
                moments[0] >= limit,
                "with boundinertia > 0: smallest eigenvalue of fullinertia ≥ −mjEPS · max(1, largest) (mjEPS = 1e-14)".into(),
            )
        } else {
            smallest(
                "eigenvalues",
                moments,
                MJ_EPS,
                moments[0] >= MJ_EPS,
                format!("smallest eigenvalue of fullinertia ≥ mjEPS = {MJ_EPS:e} kg·m²"),
            )
        });
    }
    if c.inertiafromgeom == Some(true) {
        return verdict(
            Engine::Mujoco,
            rules,
            Some(
                "`inertiafromgeom=\"true\"`: MuJoCo takes the body's mass and inertia from its geoms; of the <inertial> only a fullinertia's eigenvalue floor applies"
                    .into(),
            ),
        );
    }
    // The bounds, which clamp what is below them (0 by default).
    let mass = f.mass.max(c.boundmass);
    if f.mass < mass {
        notes.push(format!(
            "MuJoCo raises the mass {} to {} (boundmass) without a word",
            num(f.mass),
            num(mass)
        ));
    }
    let (diagonal, source) = if f.written == Written::Diagonal {
        ([t.xx, t.yy, t.zz], "diaginertia value")
    } else if full {
        (moments, "principal moment")
    } else {
        ([0.0; 3], "principal moment")
    };
    let mut bounded = diagonal.map(|x| x.max(c.boundinertia));
    if diagonal.iter().zip(&bounded).any(|(a, b)| a < b)
        && (f.written == Written::Diagonal || c.boundinertia > 0.0)
    {
        notes.push(format!(
            "MuJoCo raises each {source} below {} (boundinertia) to it without a word",
            num(c.boundinertia)
        ));
    }
    bounded.sort_by(f64::total_cmp);
    // Only a negative bound lets a negative value through the clamp.
    if mass < 0.0 || bounded[0] < 0.0 {
        rules.push(if mass < 0.0 {
            mass_rule(
                "nonnegative",
                mass,
                0.0,
                false,
                "mass ≥ 0 after boundmass (a negative boundmass lets a negative mass through)",
            )
        } else {
            smallest(
                "nonnegative",
                bounded,
                0.0,
                false,
                "each moment ≥ 0 after boundinertia (a negative boundinertia lets a negative moment through)".into(),
            )
        });
    }
    let [a, b, cc] = bounded;
    let breaks = a + b < cc || a + cc < b || b + cc < a;
    if c.balanceinertia && breaks {
        let mean = ((a + b) + cc) / 3.0;
        if !mean.is_finite() {
            return overflow(
                Engine::Mujoco,
                "the values overflow f64 in mujoco's rule: balanceinertia's mean of the moments is beyond 1.8e308",
            );
        }
        bounded = [mean; 3];
        notes.push(format!(
            "`balanceinertia=\"true\"`: MuJoCo replaces the moments, which break the triangle inequality, by their mean {}",
            num(mean)
        ));
    } else {
        let mut r = triangle(
            bounded,
            0.0,
            "A + B ≥ C for the principal moments, the sum rounded to f64, no tolerance".into(),
        );
        r.holds = !breaks;
        rules.push(r);
    }
    if f.moving && f.rescued {
        notes.push(
            "a moving body, whose mass and inertia a jointless child carries (MuJoCo then waives its floor)".into(),
        );
    } else if f.moving {
        rules.push(mass_rule(
            "moving_mass",
            mass,
            MJ_MINVAL,
            mass >= MJ_MINVAL,
            "a moving body's mass ≥ mjMINVAL = 1e-15 kg",
        ));
        rules.push(smallest(
            "moving_inertia",
            bounded,
            MJ_MINVAL,
            bounded[0] >= MJ_MINVAL,
            "a moving body's principal moments ≥ mjMINVAL = 1e-15 kg·m²".into(),
        ));
    }
    let note = (!notes.is_empty()).then(|| notes.join("; "));
    verdict(Engine::Mujoco, rules, note)
}

/// gz-math's `MassMatrix3::PrincipalMoments()` (default tolerance 1e-6),
/// operation for operation, and a bound on how far its closed form may be
/// from the exact moments (None on its exact paths).
///
/// NOTE: gz-math does not solve for the eigenvalues accurately, and its
/// verdict is on its own moments, so this port is what its rule is judged
/// on (tests/oracle/ENGINE-RULES.md). When every product is within
/// 1e-6 × the largest diagonal entry it returns the diagonal as written,
/// products ignored; else Kronenburg's closed form, whose `acos` near a
/// double moment turns the rounding of q into an error of up to ~√ε (a
/// thin rod's pair of equal moments split or merged by 1e-8). `powf`, not
/// `powi`: C++'s `std::pow(b, 3)` is libm's pow, which the port calls too.
pub fn gz_principal_moments(t: &Tensor) -> ([f64; 3], Option<f64>) {
    let tol = 1e-6 * t.xx.max(t.yy).max(t.zz);
    let (id, ip) = ([t.xx, t.yy, t.zz], [t.xy, t.xz, t.yz]);
    if ip.iter().all(|p| (p - 0.0).abs() <= tol) {
        return (id, None);
    }
    let b = id[0] + id[1] + id[2];
    let c = id[0] * id[1] - ip[0].powf(2.0) + id[0] * id[2] - ip[1].powf(2.0) + id[1] * id[2]
        - ip[2].powf(2.0);
    let d = id[0] * ip[2].powf(2.0) + id[1] * ip[1].powf(2.0) + id[2] * ip[0].powf(2.0)
        - id[0] * id[1] * id[2]
        - 2.0 * ip[0] * ip[1] * ip[2];
    let p = b.powf(2.0) - 3.0 * c;
    if p < tol.powf(2.0) {
        return ([b / 3.0; 3], None);
    }
    let q = 2.0 * b.powf(3.0) - 9.0 * b * c - 27.0 * d;
    let x = (0.5 * q / p.powf(1.5)).clamp(-1.0, 1.0);
    let delta = x.acos();
    let pi = std::f64::consts::PI;
    let mut m = [
        (b + 2.0 * p.sqrt() * (delta / 3.0).cos()) / 3.0,
        (b + 2.0 * p.sqrt() * ((delta + 2.0 * pi) / 3.0).cos()) / 3.0,
        (b + 2.0 * p.sqrt() * ((delta - 2.0 * pi) / 3.0).cos()) / 3.0,
    ];
    m.sort_by(f64::total_cmp);
    // The closed form's error: x's rounding (q cancels terms of size b³),
    // through acos (whose slope grows as 1/√(1 − x²), capped by √(2Δx)
    // at ±1), then the rest's few roundings of b.
    let e = f64::EPSILON;
    let c_terms = (id[0] * id[1]).abs()
        + ip[0] * ip[0]
        + (id[0] * id[2]).abs()
        + ip[1] * ip[1]
        + (id[1] * id[2]).abs()
        + ip[2] * ip[2];
    let d_terms = (id[0] * ip[2] * ip[2]).abs()
        + (id[1] * ip[1] * ip[1]).abs()
        + (id[2] * ip[0] * ip[0]).abs()
        + (id[0] * id[1] * id[2]).abs()
        + (2.0 * ip[0] * ip[1] * ip[2]).abs();
    let dx = 8.0 * e * (2.0 * b.abs().powf(3.0) + 9.0 * b.abs() * c_terms + 27.0 * d_terms)
        / (2.0 * p.powf(1.5))
        + 8.0 * e * x.abs();
    let dd = (dx / (1.0 - x * x).max(0.0).sqrt()).min((2.0 * dx).sqrt());
    let bound = 2.0 / 3.0 * p.sqrt() * dd + 8.0 * e * b.abs();
    (m, Some(bound))
}

/// gz-math `MassMatrix3::IsValid(10)`: `IsNearPositive` (the mass, the
/// leading minors, with ε from the diagonal as written) and `ValidMoments`
/// of gz-math's own principal moments (`gz_principal_moments`), with
/// ε = 10 · DBL_EPSILON · ½ |(m₀ + m₁) + m₂|, in its order.
fn gazebo(f: &Facts) -> Verdict {
    let t = &f.tensor;
    let eps1 = GZ_TOLERANCE * f64::EPSILON * (0.5 * (t.xx + t.yy + t.zz).abs());
    let minor2 = t.xx * t.yy - t.xy.powf(2.0) + eps1;
    let det = determinant(t);
    let minors_hold = t.xx + eps1 >= 0.0 && minor2 >= 0.0 && det + eps1 >= 0.0;
    let failing = if t.xx + eps1 < 0.0 {
        t.xx
    } else if minor2 < 0.0 {
        minor2 - eps1
    } else {
        det
    };
    let (gm, bound) = gz_principal_moments(t);
    let eps = GZ_TOLERANCE * f64::EPSILON * (0.5 * (gm[0] + gm[1] + gm[2]).abs());
    let holds_moments = gm[0] + eps >= 0.0 && gm[1] + eps >= 0.0 && gm[2] + eps >= 0.0;
    let holds_triangle = gm[0] + gm[1] + eps >= gm[2]
        && gm[1] + gm[2] + eps >= gm[0]
        && gm[2] + gm[0] + eps >= gm[1];
    let mut sorted = gm;
    sorted.sort_by(f64::total_cmp);
    let mut moments = smallest(
        "eigenvalues",
        sorted,
        -eps,
        holds_moments,
        "each of gz-math's principal moments + ε ≥ 0, ε = 10·DBL_EPSILON·(A + B + C)/2".into(),
    );
    let mut tri = triangle(
        sorted,
        eps,
        "A + B + ε ≥ C for gz-math's principal moments, ε = 10·DBL_EPSILON·(A + B + C)/2".into(),
    );
    tri.holds = holds_triangle;
    // Close: within the closed form's own error of the limit.
    if let Some(bound) = bound {
        moments.close = (sorted[0] + eps).abs() <= bound;
        tri.close = (sorted[0] + sorted[1] - sorted[2] + eps).abs() <= 3.0 * bound;
    } else {
        moments.close = false;
        tri.close = false;
    }
    let rules = vec![
        mass_rule("mass", f.mass, 0.0, f.mass >= 0.0, "mass ≥ 0"),
        Rule {
            rule: "leading_minors",
            statement: "Ixx + ε ≥ 0, Ixx·Iyy − Ixy² + ε ≥ 0 and det I + ε ≥ 0 (IsNearPositive), ε = 10·DBL_EPSILON·(Ixx + Iyy + Izz)/2".into(),
            holds: minors_hold,
            value: failing,
            limit: -eps1,
            margin: None,
            close: false,
        },
        moments,
        tri,
    ];
    let note = match bound {
        None if t.products().iter().any(|&p| p != 0.0) => Some(
            "gz-math takes the diagonal as its principal moments: every product is within 1e-6 of the largest diagonal entry, and it ignores them".to_string(),
        ),
        _ => None,
    };
    verdict(Engine::Gazebo, rules, note)
}

/// Drake: `RotationalInertia::CouldBePhysicallyValid()` of the central
/// inertia as written, with ε = 16 · DBL_EPSILON · max(1, ½ |tr I|), and
/// the mass as Drake's parser takes it: > 0, or 0 with an all-zero tensor
/// (`SpatialInertia::IsPhysicallyValid` alone allows any mass ≥ 0, but the
/// parser's `mass > 0` condition refuses 0 with a tensor;
/// tests/oracle/ENGINE-RULES.md). For an inertial that breaks the rule the
/// parser warns and puts a solid sphere of water in its place.
fn drake(f: &Facts, m: [f64; 3]) -> Verdict {
    let t = &f.tensor;
    let eps = DRAKE_TOLERANCE * f64::EPSILON * (0.5 * (t.xx + t.yy + t.zz).abs()).max(1.0);
    let zero = [t.xx, t.yy, t.zz, t.xy, t.xz, t.yz]
        .iter()
        .all(|&x| x == 0.0);
    let rules = vec![
        mass_rule(
            "mass",
            f.mass,
            0.0,
            f.mass > 0.0 || (f.mass == 0.0 && zero),
            "mass > 0, or 0 with an all-zero tensor (Drake's parser)",
        ),
        smallest(
            "eigenvalues",
            m,
            -eps,
            m[0] + eps >= 0.0 && m[1] + eps >= 0.0 && m[2] + eps >= 0.0,
            "each principal moment + ε ≥ 0, ε = 16·DBL_EPSILON·max(1, |tr I|/2)".into(),
        ),
        triangle(
            m,
            eps,
            "A + B + ε ≥ C for the principal moments, ε = 16·DBL_EPSILON·max(1, |tr I|/2)".into(),
        ),
    ];
    let note = (!rules.iter().all(|r| r.holds)).then(|| {
        "Drake's parser warns and puts a solid sphere of water of the link's mass in its place (an error under strict parsing)".to_string()
    });
    verdict(Engine::Drake, rules, note)
}

/// det I, as gz-math's `Matrix3::Determinant` forms it.
fn determinant(t: &Tensor) -> f64 {
    let m = t.matrix();
    let t0 = m[2][2] * m[1][1] - m[2][1] * m[1][2];
    let t1 = -(m[2][2] * m[1][0] - m[2][0] * m[1][2]);
    let t2 = m[2][1] * m[1][0] - m[2][0] * m[1][1];
    t0 * m[0][0] + t1 * m[0][1] + t2 * m[0][2]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn facts(xx: f64, yy: f64, zz: f64, written: Written, moving: bool) -> Facts {
        Facts {
            mass: 1.0,
            tensor: Tensor {
                xx,
                yy,
                zz,
                ..Tensor::default()
            },
            written,
            moving,
            rescued: false,
        }
    }

    fn valid(e: Engine, f: &Facts) -> bool {
        accepts(e, f, &MujocoCompiler::default())
    }

    #[test]
    fn values_whose_sums_overflow_get_no_verdict_and_no_infinite_number() {
        // Moments near f64::MAX: A + B − C, gz-math's and Drake's tolerance
        // from A + B + C overflow.
        let f = facts(1.7e308, 1.7e308, 1.7e308, Written::Full, true);
        for e in Engine::ALL {
            let v = judge(e, &f, &MujocoCompiler::default());
            assert!(!v.valid && v.rules.is_empty(), "{v:?}");
            assert!(v.note.unwrap().contains("overflow"));
        }
        // balanceinertia's mean of moments that break the triangle.
        let f = facts(0.5e308, 0.5e308, 1.7e308, Written::Diagonal, false);
        let c = MujocoCompiler {
            balanceinertia: true,
            ..MujocoCompiler::default()
        };
        let v = judge(Engine::Mujoco, &f, &c);
        assert!(!v.valid && v.rules.is_empty(), "{v:?}");
        // A note writes a large mean with an exponent, not 300 digits.
        let f = facts(1.0, 1.0, 1e300, Written::Diagonal, false);
        let note = judge(Engine::Mujoco, &f, &c).note.unwrap();
        assert!(
            note.ends_with("by their mean 3.3333333333333335e299"),
            "{note}"
        );
        // Large but representable: judged as usual.
        let f = facts(1e100, 1e100, 1e100, Written::Full, true);
        for e in Engine::ALL {
            assert!(accepts(e, &f, &MujocoCompiler::default()), "{e:?}");
        }
    }

    #[test]
    fn mujoco_accepts_the_triangle_inequality_at_equality_and_refuses_one_ulp_over() {
        assert!(valid(
            Engine::Mujoco,
            &facts(1.0, 1.0, 2.0, Written::Full, true)
        ));
        let over = 2.0f64.next_up();
        assert!(!valid(
            Engine::Mujoco,
            &facts(1.0, 1.0, over, Written::Full, true)
        ));
    }

    #[test]
    fn gazebo_and_drake_allow_the_triangle_inequality_a_few_ulps_over() {
        // ε = 10 eps · 2 for gazebo, 16 eps · 2 for drake: 2 + 2 ulps of 2 is within.
        let over = 2.0f64.next_up().next_up();
        let f = facts(1.0, 1.0, over, Written::Attributes, true);
        assert!(valid(Engine::Gazebo, &f));
        assert!(valid(Engine::Drake, &f));
        let far = facts(1.0, 1.0, 2.0 + 1e-12, Written::Attributes, true);
        assert!(!valid(Engine::Gazebo, &far));
        assert!(!valid(Engine::Drake, &far));
    }

    #[test]
    fn the_triangle_margin_is_a_plus_b_minus_c_over_c() {
        let v = judge(
            Engine::Mujoco,
            &facts(1.0, 2.0, 4.0, Written::Full, false),
            &MujocoCompiler::default(),
        );
        let t = v.rules.iter().find(|r| r.rule == "triangle").unwrap();
        assert!(!t.holds);
        assert_eq!(t.margin, Some(-0.25));
    }

    #[test]
    fn mujoco_needs_fullinertia_eigenvalues_to_reach_mj_eps() {
        assert!(!valid(
            Engine::Mujoco,
            &facts(1e-15, 1.0, 1.0, Written::Full, false)
        ));
        assert!(valid(
            Engine::Mujoco,
            &facts(1e-14, 1.0, 1.0, Written::Full, false)
        ));
    }

    #[test]
    fn a_moving_mujoco_body_needs_mass_and_moments_of_mj_minval() {
        let mut f = facts(1e-16, 1e-16, 1e-16, Written::Diagonal, true);
        assert!(!valid(Engine::Mujoco, &f));
        f.rescued = true;
        assert!(valid(Engine::Mujoco, &f));
        f.rescued = false;
        f.moving = false;
        assert!(valid(Engine::Mujoco, &f));
    }

    #[test]
    fn mujoco_clamps_a_negative_mass_or_diagonal_on_a_fixed_body() {
        let mut f = facts(1.0, 1.0, -1.0, Written::Diagonal, false);
        f.mass = -2.0;
        let v = judge(Engine::Mujoco, &f, &MujocoCompiler::default());
        assert!(v.valid, "{v:?}");
        assert!(v.note.unwrap().contains("boundmass"));
        // (1, 2, −1) clamps to (1, 2, 0), which breaks the triangle.
        assert!(!valid(
            Engine::Mujoco,
            &facts(1.0, 2.0, -1.0, Written::Diagonal, false)
        ));
    }

    #[test]
    fn mujoco_rounds_the_triangle_sum_to_f64() {
        // fl(0.1 + 0.2) = 0.30000000000000004: equal, so it holds.
        assert!(valid(
            Engine::Mujoco,
            &facts(0.1, 0.2, 0.30000000000000004, Written::Diagonal, false)
        ));
    }

    #[test]
    fn balanceinertia_replaces_the_moments_by_their_mean_which_must_still_reach_mj_minval() {
        let c = MujocoCompiler {
            balanceinertia: true,
            ..MujocoCompiler::default()
        };
        assert!(accepts(
            Engine::Mujoco,
            &facts(1.0, 1.0, 3.0, Written::Diagonal, true),
            &c
        ));
        assert!(!accepts(
            Engine::Mujoco,
            &facts(0.0, 0.0, 3e-15, Written::Diagonal, true),
            &c
        ));
        assert!(accepts(
            Engine::Mujoco,
            &facts(0.0, 0.0, 3.0000000000000004e-15, Written::Diagonal, true),
            &c
        ));
    }

    #[test]
    fn boundinertia_relaxes_the_eigenvalue_floor_to_a_relative_one() {
        let c = MujocoCompiler {
            boundinertia: 1e-3,
            ..MujocoCompiler::default()
        };
        assert!(accepts(
            Engine::Mujoco,
            &facts(1.0, 1.0, -1e-14, Written::Full, false),
            &c
        ));
        assert!(!accepts(
            Engine::Mujoco,
            &facts(1.0, 1.0, (-1e-14f64).next_down(), Written::Full, false),
            &c
        ));
    }

    #[test]
    fn a_urdf_all_zero_tensor_is_no_fullinertia_on_a_fixed_link() {
        let f = facts(0.0, 0.0, 0.0, Written::Attributes, false);
        assert!(valid(Engine::Mujoco, &f));
        assert!(!valid(
            Engine::Mujoco,
            &facts(0.0, 0.0, 0.0, Written::Full, false)
        ));
        assert!(!valid(Engine::Mujoco, &Facts { moving: true, ..f }));
    }

    #[test]
    fn drake_floors_its_tolerance_at_sixteen_ulps_of_one() {
        // A tiny tensor breaking the triangle inequality by 1e-16 passes
        // Drake (ε ≥ 16 eps ≈ 3.6e-15) and fails gazebo (ε scales with it).
        let f = facts(1e-6, 1e-6, 2e-6 + 1e-16, Written::Attributes, true);
        assert!(valid(Engine::Drake, &f));
        assert!(!valid(Engine::Gazebo, &f));
    }

    #[test]
    fn negative_mass_fails_every_engine() {
        let mut f = facts(1.0, 1.0, 1.0, Written::Attributes, true);
        f.mass = -1.0;
        for e in Engine::ALL {
            assert!(!valid(e, &f), "{e:?}");
        }
    }

    #[test]
    fn principal_moments_of_a_turned_tensor_are_accurate() {
        // diag(1, 2, 3) turned 45° about z: xx = yy = 1.5, xy = ∓0.5.
        let t = Tensor {
            xx: 1.5,
            yy: 1.5,
            zz: 3.0,
            xy: -0.5,
            ..Tensor::default()
        };
        assert_eq!(principal_moments(&t), Some([1.0, 2.0, 3.0]));
    }
}
