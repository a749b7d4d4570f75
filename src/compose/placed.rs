//! Compose once, place many: each distinct sub-assembly (an `include`'s
//! model, shared by `Arc` when its file, parameters and so tolerances are
//! the same) is composed once per composition into a body (`Lump`), bottom
//! up, and that body is placed per instance through its frames in the
//! arithmetic asked for (`place`); a part's `array` and `mirror` copies
//! place the part's physics, formed once in its own file's frame, the same
//! way. The work of a tree of includes is then its distinct files, not
//! its instances.
//!
//! A body is kept about a pivot ĉ of its own, with the residual first
//! moment s = Σ mᵢ(cᵢ − ĉ), never divided by its mass: a sub-assembly of
//! cut-outs only (negative mass) or of no mass composes as any other. Its
//! pivot is weighted by |mᵢ|, so it lies among its parts whatever their
//! signs.
//!
//! Error bounds are absolute, per entry, against the exact body for the
//! files' numbers about the same pivot (`bounds::RawError`), and placed
//! with the body (`place`: the frame's own errors and the placement's
//! roundings added); the composer that takes a placed body adds them as
//! they are (`bounds::Tally::add_body`).

use crate::bounds::{BodyTerm, Tally, safe};
use crate::mass::Body;
use crate::model::frame::Placement;
use crate::model::{Copies, Item, Model};
use crate::numeric::{DD, M3, Precision, Real, Sum};
use crate::part::Part;
use crate::part::error::{U_DD, centroid_error, unit_of};
use std::collections::HashMap;
use std::sync::Arc;

/// The arithmetic a composition is in: its numbers and its running sums
/// (compensated f64, or double-double).
pub(super) trait Arith: Real + Into<DD> {
    type Acc: Copy;
    const PRECISION: Precision;
    fn zero() -> Self::Acc;
    fn push(acc: &mut Self::Acc, x: Self);
    fn total(acc: Self::Acc) -> Self;
}

impl Arith for f64 {
    type Acc = Sum;
    const PRECISION: Precision = Precision::Standard;
    fn zero() -> Sum {
        Sum::default()
    }
    fn push(acc: &mut Sum, x: f64) {
        acc.add(x);
    }
    fn total(acc: Sum) -> f64 {
        acc.value()
    }
}

impl Arith for DD {
    type Acc = DD;
    const PRECISION: Precision = Precision::Extended;
    fn zero() -> DD {
        DD::of(0.0)
    }
    fn push(acc: &mut DD, x: DD) {
        *acc += x;
    }
    fn total(acc: DD) -> DD {
        acc
    }
}

/// A body composed in its own file's frame and units: mass m, a pivot ĉ
/// (exact as the double-double it is), the residual first moment
/// s = Σ mᵢ(cᵢ − ĉ) and the second moment about the pivot
/// C = Σ (Cᵢ + mᵢ dᵢ dᵢᵀ); with the absolute bound of each against the
/// exact values for the file's numbers, about the same ĉ.
#[derive(Debug, Clone, Copy)]
pub struct Lump<T> {
    pub mass: T,
    pub pivot: [DD; 3],
    pub first: [T; 3],
    pub second: M3<T>,
    pub e_mass: f64,
    pub e_first: [f64; 3],
    pub e_second: M3<f64>,
    /// A bound on the Frobenius norm of the second moment's error, which a
    /// turn or a reflection keeps (`place`): a body turned twice (an
    /// include's frame, then a mirror) is then bounded by its norm, not by
    /// |R| applied twice entry by entry.
    pub e_norm: f64,
}

/// √(Σ eᵢⱼ²) of a bound's entries: a bound on the Frobenius norm of the
/// error they bound, scaled so that no square overflows.
fn frobenius(e: &M3<f64>) -> f64 {
    let top = e.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if top == 0.0 || !top.is_finite() {
        return top;
    }
    safe(
        top * e
            .iter()
            .flatten()
            .map(|x| (x / top) * (x / top))
            .sum::<f64>()
            .sqrt(),
    )
}

std::thread_local! {
    static COMPOSED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// How many sub-assembly bodies this thread has composed: the tests count
/// the work of a tree of includes with it, not the time.
#[doc(hidden)]
pub fn bodies_composed() -> u64 {
    COMPOSED.with(std::cell::Cell::get)
}

/// The bodies of one composition's sub-assemblies, by their model's
/// address (one arithmetic per composition).
pub(super) struct Memo<T> {
    bodies: HashMap<*const Model, Lump<T>>,
}

impl<T: Arith> Memo<T> {
    /// Every sub-assembly of `model`, at any depth, composed once, the
    /// innermost first.
    pub(super) fn of(model: &Model) -> Memo<T> {
        let mut memo = Memo {
            bodies: HashMap::new(),
        };
        memo.fill(model);
        memo
    }

    fn fill(&mut self, model: &Model) {
        for item in model.items.iter() {
            let Item::Include(inc) = item else { continue };
            let key = Arc::as_ptr(&inc.model);
            if self.bodies.contains_key(&key) {
                continue;
            }
            self.fill(&inc.model);
            let lump = compose_sub(&inc.model, self);
            COMPOSED.with(|c| c.set(c.get() + 1));
            self.bodies.insert(key, lump);
        }
    }

    fn get(&self, model: &Arc<Model>) -> &Lump<T> {
        self.bodies
            .get(&Arc::as_ptr(model))
            .expect("invariant: every sub-assembly is composed before its includer")
    }
}

/// What a pass over a file's items needs of each: its mass, its mass and
/// pivot, or everything.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Need {
    Mass,
    Point,
    All,
}

/// One term of a file's composition: a part of its own, or a body placed
/// (a sub-assembly's instance, a part's copy).
pub(super) enum Entry<'a, T> {
    Part(&'a Part),
    Body(Lump<T>),
}

impl<T: Arith> Entry<'_, T> {
    fn mass(&self) -> T {
        match self {
            Entry::Part(p) => p.mass(),
            Entry::Body(b) => b.mass,
        }
    }

    fn pivot(&self) -> [DD; 3] {
        match self {
            Entry::Part(p) => p.centroid(),
            Entry::Body(b) => b.pivot,
        }
    }
}

/// Each term of `model`'s own items, in file order, as far as `need`.
pub(super) fn each_entry<T: Arith>(
    model: &Model,
    memo: &Memo<T>,
    need: Need,
    f: &mut dyn FnMut(Entry<'_, T>),
) {
    for item in model.items.iter() {
        match item {
            Item::Part {
                part, copies: None, ..
            } => f(Entry::Part(part)),
            Item::Part {
                part,
                copies: Some(c),
                ..
            } => {
                let lump = part_lump::<T>(part, need);
                each_copy(c, &lump, need, &mut |b| match b {
                    None => f(Entry::Part(part)),
                    Some(b) => f(Entry::Body(b)),
                });
            }
            Item::Include(inc) => {
                let placed = place(memo.get(&inc.model), &inc.frame.placement::<T>(), need);
                match &inc.copies {
                    None => f(Entry::Body(placed)),
                    Some(c) => {
                        each_copy(c, &placed, need, &mut |b| {
                            f(Entry::Body(b.unwrap_or(placed)))
                        });
                    }
                }
            }
        }
    }
}

/// `body` placed through each copy's frames (its array's, then its
/// mirror's); `None` for a copy with none (the part as written).
fn each_copy<T: Arith>(c: &Copies, body: &Lump<T>, need: Need, f: &mut dyn FnMut(Option<Lump<T>>)) {
    let mut mirror: Option<Placement<T>> = None;
    for i in c.indices() {
        let (array, image) = c.frames(i);
        if array.is_none() && image.is_none() {
            f(None);
            continue;
        }
        // A copy's frames scale nothing: its mass is the body's.
        if need == Need::Mass {
            f(Some(*body));
            continue;
        }
        let mut b = *body;
        if let Some(a) = &array {
            b = place(&b, &a.placement::<T>(), need);
        }
        if let Some(m) = image {
            let p = mirror.get_or_insert_with(|| m.placement::<T>());
            b = place(&b, p, need);
        }
        f(Some(b));
    }
}

/// A part's physics as a body about its centroid: its mass, centroid and
/// own second moment, with their errors (`part::error`: the same model
/// the composer's `Tally::add` takes for a part).
fn part_lump<T: Arith>(p: &Part, need: Need) -> Lump<T> {
    let m: T = p.mass();
    let zero = T::of(0.0);
    let mut lump = Lump {
        mass: m,
        pivot: p.centroid(),
        first: [zero; 3],
        second: [[zero; 3]; 3],
        e_mass: 0.0,
        e_first: [0.0; 3],
        e_second: [[0.0; 3]; 3],
        e_norm: 0.0,
    };
    if need == Need::Mass {
        return lump;
    }
    let u = unit_of::<T>();
    let (own, error) = p.own_second_moment_bounded::<T>(m);
    let off = centroid_error(&p.spec, &lump.pivot.map(|x| x.hi));
    let am = m.f64().abs();
    lump.second = own;
    lump.e_mass = safe(u * error.mass * am);
    // About the centroid as computed, the exact first moment is
    // m (c − ĉ): within |m| o of zero; and the exact second moment moves
    // by m (c − ĉ)(c − ĉ)ᵀ.
    lump.e_first = off.map(|o| safe(am * o));
    lump.e_second = std::array::from_fn(|j| {
        std::array::from_fn(|k| {
            let own = if j == k {
                error.kappa * error.mag[j]
            } else if error.diagonal {
                0.0
            } else {
                error.kappa * (error.mag[j] * error.mag[k]).sqrt()
            };
            safe(u * (own + error.rot) + am * off[j] * off[k])
        })
    });
    lump.e_norm = frobenius(&lump.e_second);
    lump
}

/// A body placed through a frame: m' = k m, ĉ' = o + L R (ĉ − q),
/// s' = k L R s, C' = k L² R C Rᵀ (R a turn or a reflection), in the
/// arithmetic `T` (the pivot in double-double), with its bounds.
///
/// The bounds, first order, each from the exact frame (`Placement`: R̂
/// within ρ of R entrywise, L̂ and k̂ within their relative errors):
/// - m': |k| δm, k̂'s error and the product's rounding, relative to m';
/// - the pivot: ĉ' is exact as a number, but the exact placement of ĉ
///   lies δ from it: L(ρ Σ|v| + (|R̂| + ρ) δv) (R̂'s error, and the
///   difference v = ĉ − q rounded once in double-double), L's error over
///   L|R̂||v|, and ten double-double units of |o| + L|R̂||v| (three
///   products and sums in R v, the product by L, the sum with o). The
///   exact body about ĉ' is the exact body about ĉ moved, plus δ:
///   s'ₓ = k L R sₓ + m' δ, C'ₓ = k L² R Cₓ Rᵀ + (kLR sₓ) δᵀ + δ (kLR sₓ)ᵀ
///   + m' δ δᵀ; so δ enters s' and C' as |m'|δ, |s'|δ + δ|s'| + |m'|δδ;
/// - s': k L (|R̂| + ρ)|δs| and ρ Σ|s| for R's error; k's and L's relative
///   errors and the products' roundings (3 in R̂ s unless R̂ is a signed
///   permutation, whose products are exact; 2 for the scale) over
///   kL|R̂||s|;
/// - C': k L² ((|R̂| + ρ)|δC|(|R̂| + ρ)ᵀ, (2ρ + ρ²) Σ|C| for R's error
///   (|R| ≤ 1 entrywise for an orthogonal R: ΔR C Rᵀ and R C ΔRᵀ each
///   at most ρ Σ|C|), and k's, twice L's and the products' roundings (6
///   in R̂ C R̂ᵀ, 3 for the scale) over |R̂||C||R̂|ᵀ).
fn place<T: Arith>(b: &Lump<T>, p: &Placement<T>, need: Need) -> Lump<T> {
    let u = unit_of::<T>();
    let one = T::of(1.0);
    let unit_mass = p.rel_mass == 0.0 && p.mass == one;
    let unit_length = p.rel_length == 0.0 && p.length == one;
    let mass = if unit_mass { b.mass } else { p.mass * b.mass };
    let e_mass = if unit_mass {
        b.e_mass
    } else {
        safe(p.mass.f64().abs() * b.e_mass + (p.rel_mass + u) * mass.f64().abs())
    };
    let mut out = Lump { mass, e_mass, ..*b };
    if need == Need::Mass {
        return out;
    }
    let (v, ev): ([DD; 3], [f64; 3]) = match p.pivot {
        None => (b.pivot, [0.0; 3]),
        Some(q) => {
            let v: [DD; 3] = std::array::from_fn(|i| b.pivot[i] - q[i]);
            (v, v.map(|x| U_DD * x.f64().abs()))
        }
    };
    let w: [DD; 3] =
        std::array::from_fn(|j| (0..3).fold(DD::of(0.0), |acc, k| acc + p.r_dd[j][k] * v[k]));
    out.pivot = std::array::from_fn(|j| {
        if unit_length {
            p.origin[j] + w[j]
        } else {
            p.origin[j] + p.length_dd * w[j]
        }
    });
    if need == Need::Point {
        return out;
    }
    let ra: M3<f64> = p.r_dd.map(|r| r.map(|x| x.f64().abs()));
    let rho = p.rho;
    let l = p.length_dd.f64().abs();
    let va = v.map(|x| x.f64().abs());
    let vsum: f64 = va.iter().sum();
    let delta: [f64; 3] = std::array::from_fn(|j| {
        let rv: f64 = (0..3).map(|k| ra[j][k] * va[k]).sum();
        let re: f64 = (0..3).map(|k| (ra[j][k] + rho) * ev[k]).sum();
        safe(
            l * (rho * vsum + re)
                + p.rel_length_dd * l * rv
                + 10.0 * U_DD * (p.origin[j].f64().abs() + l * rv),
        )
    });
    let r = &p.r;
    let kl = p.mass * p.length;
    let kl2 = kl * p.length;
    let scaled = !(unit_mass && unit_length);
    let first: [T; 3] = std::array::from_fn(|j| {
        let rs = (0..3).fold(T::of(0.0), |acc, k| acc + r[j][k] * b.first[k]);
        if scaled { kl * rs } else { rs }
    });
    let rc: M3<T> = std::array::from_fn(|j| {
        std::array::from_fn(|m| (0..3).fold(T::of(0.0), |acc, k| acc + r[j][k] * b.second[k][m]))
    });
    let mut second = [[T::of(0.0); 3]; 3];
    for j in 0..3 {
        for l2 in j..3 {
            let x = (0..3).fold(T::of(0.0), |acc, m| acc + rc[j][m] * r[l2][m]);
            second[j][l2] = if scaled { kl2 * x } else { x };
            second[l2][j] = second[j][l2];
        }
    }
    let turn_ops = if p.exact_turn { 0.0 } else { 1.0 };
    let scale_ops = if scaled { 1.0 } else { 0.0 };
    let rel1 = p.rel_mass + p.rel_length + (3.0 * turn_ops + 2.0 * scale_ops) * u;
    let rel2 = p.rel_mass + 2.0 * p.rel_length + (6.0 * turn_ops + 3.0 * scale_ops) * u;
    let kla = kl.f64().abs();
    let kl2a = kl2.f64().abs();
    let sa = b.first.map(|x| x.f64().abs());
    let ssum: f64 = sa.iter().sum();
    let mass_a = mass.f64().abs() + e_mass;
    let e_first: [f64; 3] = std::array::from_fn(|j| {
        let carried: f64 = (0..3).map(|k| (ra[j][k] + rho) * b.e_first[k]).sum();
        let rs: f64 = (0..3).map(|k| ra[j][k] * sa[k]).sum();
        safe(
            kla * (carried + rho * ssum + rel1 * rs) * (1.0 + 4.0 * crate::bounds::U64)
                + mass_a * delta[j],
        )
    });
    let ca = b.second.map(|r| r.map(|x| x.f64().abs()));
    let spread: f64 = ca.iter().flatten().sum();
    let sp = first.map(|x| x.f64().abs());
    // NOTE: R̂ ΔC R̂ᵀ's entries are at most its 2-norm, ‖R̂‖₂² ‖ΔC‖₂, with
    // ‖R̂‖₂ ≤ 1 + ‖R̂ − R‖_F ≤ 1 + 3ρ: the carried error is the smaller of
    // that and the entrywise (|R̂| + ρ)|δC|(|R̂| + ρ)ᵀ, and its norm is
    // carried on (`Lump::e_norm`), so that a second turn does not grow it
    // by |R| again.
    let keep = (1.0 + 3.0 * rho) * (1.0 + 3.0 * rho);
    let cap = keep * b.e_norm;
    let grow = 1.0 + 8.0 * crate::bounds::U64;
    let mut rest = [[0.0f64; 3]; 3];
    let e_second: M3<f64> = std::array::from_fn(|j| {
        std::array::from_fn(|l2| {
            let mut carried = 0.0;
            let mut mag = 0.0;
            for k in 0..3 {
                for m in 0..3 {
                    carried += (ra[j][k] + rho) * b.e_second[k][m] * (ra[l2][m] + rho);
                    mag += ra[j][k] * ca[k][m] * ra[l2][m];
                }
            }
            let others = safe(
                kl2a * ((2.0 * rho + rho * rho) * spread + rel2 * mag) * grow
                    + (sp[j] + e_first[j]) * delta[l2]
                    + delta[j] * (sp[l2] + e_first[l2])
                    + mass_a * delta[j] * delta[l2],
            );
            rest[j][l2] = others;
            safe(kl2a * carried.min(cap) * grow + others)
        })
    });
    out.first = first;
    out.second = second;
    out.e_first = e_first;
    out.e_second = e_second;
    // The carried error's norm is at most k L² ‖R̂‖₂² ‖ΔC‖_F; the rest's,
    // that of its entries' bounds; and never more than all the entries'.
    out.e_norm = safe(kl2a * cap * grow + frobenius(&rest)).min(frobenius(&e_second));
    out
}

/// How a file's pivot weighs its terms: by mᵢ/m (the body's centre, for
/// the file composed; `compose_standard`'s), or by |mᵢ|/Σ|m| (for a
/// sub-assembly, whose mass may be zero or negative).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Weights {
    Mass,
    Magnitude,
}

/// A file's own terms composed about a pivot: the raw sums, before a
/// sub-assembly's body is kept or the file's finished.
struct Level<T: Arith> {
    mass: T,
    pivot: [T; 3],
    first: [T; 3],
    sum: [[T::Acc; 3]; 3],
    tally: Tally,
}

/// The three passes of the composer over `model`'s own terms (its mass,
/// its pivot, then the sums about the pivot and their error terms), its
/// sub-assemblies' bodies from `memo`.
fn level<T: Arith>(model: &Model, memo: &Memo<T>, weights: Weights) -> Level<T> {
    let (mut total, mut gross) = (T::zero(), T::zero());
    each_entry(model, memo, Need::Mass, &mut |e| {
        let m = e.mass();
        T::push(&mut total, m);
        T::push(&mut gross, m.abs());
    });
    let total = T::total(total);
    let gross = T::total(gross);
    let zero = T::of(0.0);
    let weight = match weights {
        Weights::Mass => total,
        Weights::Magnitude => gross,
    };
    let mut first = [T::zero(); 3];
    // NOTE: no division by a zero weight: a sub-assembly of no mass at
    // all keeps its pivot at its origin (its sums are all zero).
    if weights == Weights::Mass || gross > zero {
        each_entry(model, memo, Need::Point, &mut |e| {
            let m = e.mass();
            let w = match weights {
                Weights::Mass => m,
                Weights::Magnitude => m.abs(),
            } / weight;
            for (f, c) in first.iter_mut().zip(e.pivot()) {
                T::push(f, w * T::of_dd(c));
            }
        });
    }
    let c0 = first.map(T::total);
    let c0_dd: [DD; 3] = c0.map(Into::into);
    let mut sum = [[T::zero(); 3]; 3];
    let mut s = [T::zero(); 3];
    let mut tally = Tally::default();
    each_entry(model, memo, Need::All, &mut |e| match e {
        Entry::Part(p) => {
            let m: T = p.mass();
            let c = p.centroid();
            let d: [T; 3] = std::array::from_fn(|i| T::of_dd(c[i] - c0_dd[i]));
            let (own, error) = p.own_second_moment_bounded::<T>(m);
            let off = centroid_error(&p.spec, &c.map(|x| x.hi));
            tally.add(m.f64(), d.map(Real::f64), off, &error);
            for i in 0..3 {
                let md = m * d[i];
                T::push(&mut s[i], md);
                for j in i..3 {
                    T::push(&mut sum[i][j], own[i][j]);
                    T::push(&mut sum[i][j], md * d[j]);
                }
            }
        }
        Entry::Body(b) => {
            let d: [T; 3] = std::array::from_fn(|i| T::of_dd(b.pivot[i] - c0_dd[i]));
            tally.add_body(
                T::PRECISION,
                &BodyTerm {
                    mass: b.mass.f64(),
                    d: d.map(Real::f64),
                    first: b.first.map(Real::f64),
                    second: b.second.map(|r| r.map(Real::f64)),
                    e_mass: b.e_mass,
                    e_first: b.e_first,
                    e_second: b.e_second,
                },
            );
            for i in 0..3 {
                let md = b.mass * d[i];
                T::push(&mut s[i], md);
                T::push(&mut s[i], b.first[i]);
                for j in i..3 {
                    T::push(&mut sum[i][j], b.second[i][j]);
                    T::push(&mut sum[i][j], md * d[j]);
                    T::push(&mut sum[i][j], b.first[i] * d[j]);
                    T::push(&mut sum[i][j], d[i] * b.first[j]);
                }
            }
        }
    });
    Level {
        mass: total,
        pivot: c0,
        first: s.map(T::total),
        sum,
        tally,
    }
}

/// A sub-assembly's body: its file's terms composed about a pivot
/// weighted by |m|, with the bounds of its raw sums.
#[allow(clippy::needless_range_loop)] // a symmetric matrix by its upper triangle
fn compose_sub<T: Arith>(model: &Model, memo: &Memo<T>) -> Lump<T> {
    let lv = level(model, memo, Weights::Magnitude);
    let mut second = [[T::of(0.0); 3]; 3];
    for i in 0..3 {
        for j in i..3 {
            second[i][j] = T::total(lv.sum[i][j]);
            second[j][i] = second[i][j];
        }
    }
    let e = lv.tally.raw(
        T::PRECISION,
        lv.mass.f64(),
        lv.first.map(Real::f64),
        &second.map(|r| r.map(Real::f64)),
    );
    Lump {
        mass: lv.mass,
        pivot: lv.pivot.map(Into::into),
        first: lv.first,
        second,
        e_mass: e.mass,
        e_first: e.first,
        e_second: e.second,
        e_norm: frobenius(&e.second),
    }
}

/// A file with sub-assemblies or copies composed (`compose_model`): its
/// own terms about the pivot Σ (mᵢ/m) ĉᵢ, then the centre and the second
/// moment about it corrected by the residual first moment, as
/// `compose_standard` and `compose_extended` do for parts.
pub(super) fn compose_root<T: Arith>(model: &Model) -> (Body, crate::bounds::BodyError) {
    let memo = Memo::<T>::of(model);
    let mut lv = level(model, &memo, Weights::Mass);
    let total = lv.mass;
    let s = lv.first;
    let mut c = [[DD::of(0.0); 3]; 3];
    for i in 0..3 {
        for j in i..3 {
            // s (s/m)ᵀ, not s sᵀ/m: the square of s may overflow.
            T::push(&mut lv.sum[i][j], -(s[i] * (s[j] / total)));
            c[i][j] = T::total(lv.sum[i][j]).into();
            c[j][i] = c[i][j];
        }
    }
    let body = Body {
        mass: total.into(),
        center_of_mass: std::array::from_fn(|i| {
            let c0: DD = lv.pivot[i].into();
            let shift: DD = (s[i] / total).into();
            c0 + shift
        }),
        second_moment: c,
    };
    let error = lv.tally.finish(
        T::PRECISION,
        body.mass.f64(),
        s.map(Real::f64),
        body.center_of_mass.map(DD::f64),
        &body.second_moment.map(|r| r.map(DD::f64)),
    );
    (body, error)
}
