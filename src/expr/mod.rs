//! Expressions in quantity strings: `"2 * leg + 5 mm"`, `"pi * d^2 / 4"`,
//! `"7850 kg/m^3"`. Read once into postfix steps (`Expr::parse`), then
//! evaluated without recursion (`Expr::eval`), so the time is linear in the
//! length and the stack is bounded whatever the input.
//!
//! Values carry their dimension (`units::Dim`) and are exact rationals
//! (`exact::Q`, times a power of π) while they can be: sums, differences,
//! products, quotients and integer powers of decimal numbers and unit
//! factors. `sqrt` of a non-square, the trigonometric functions, a
//! non-integer power, a sum of different powers of π and a rational that
//! outgrows i128 go on in double-double (`numeric::DD`). The one rounding
//! to f64 is at the end (`Value::in_units`); where double-double was used
//! and the value is rational after all, `Expr::exact` evaluates it again
//! in big rationals (`big`), so that it is rounded to the nearest f64.
//!
//! Grammar (precedence from low to high):
//!
//! ```text
//! expr  := term (("+" | "-") term)*
//! term  := unary (("*" | "/") unary)*
//! unary := ("-" | "+") unary | power
//! power := atom ("^" unary)?                 right-associative
//! atom  := NUMBER unit? | NAME "(" expr ("," expr)* ")" | NAME | "(" expr ")"
//! unit  := SYMBOL ("^" INT)? (("*" | "·" | " ") SYMBOL ("^" INT)?)*
//!          ("/" SYMBOL ...)?                 at most one "/"
//! ```
//!
//! A number directly followed by a unit symbol is one quantity (`7850
//! kg/m^3`, `2 m^2` is 2 m², not (2 m)²). A bare name is a parameter if
//! one is given that name, else `pi`, else a unit symbol (one of it:
//! `3 * mm`).

pub mod big;
mod exact;

use crate::numeric::{DD, Real};
use crate::units::{self, Dim, Factor};
pub use exact::Q;
use std::ops::Range;

/// How deep parentheses, unary signs, powers and calls may nest.
pub const MAX_DEPTH: usize = 64;

/// The functions an expression may call, with their arities (`None`: one
/// or more).
const FUNCTIONS: &[(&str, Option<usize>)] = &[
    ("sqrt", Some(1)),
    ("sin", Some(1)),
    ("cos", Some(1)),
    ("tan", Some(1)),
    ("abs", Some(1)),
    ("min", None),
    ("max", None),
];

/// Names a parameter may not take: the constant and the functions (unit
/// symbols are refused too, by `reserved`).
const CONSTANTS: &[&str] = &["pi"];

/// Why a name cannot be a parameter's: it is `pi`, a function or a unit.
pub fn reserved(name: &str) -> Option<&'static str> {
    if CONSTANTS.contains(&name) {
        return Some("the constant π");
    }
    if FUNCTIONS.iter().any(|(f, _)| *f == name) {
        return Some("a function");
    }
    if units::symbol_names().any(|s| s == name) {
        return Some("a unit symbol");
    }
    None
}

/// Whether `name` is a well-formed parameter name: a letter or `_`, then
/// letters, digits and `_`.
pub fn is_name(name: &str) -> bool {
    let mut c = name.chars();
    c.next().is_some_and(|f| f.is_alphabetic() || f == '_')
        && c.all(|x| x.is_alphanumeric() || x == '_')
}

/// A number of some dimension.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Value {
    pub dim: Dim,
    pub num: Num,
    /// Whether an angle unit (`rad`, `deg`, `rev`: dimensionless, as
    /// angles are) went into it other than through `sin`, `cos` or `tan`,
    /// for a key that is a plain number of its own unit (`step_degrees`):
    /// `"90 deg"` there would be read as 1.5708.
    pub angle: bool,
}

/// Exact while it can be, double-double after.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Num {
    Exact(Q),
    Float(DD),
}

impl Num {
    fn dd(self) -> DD {
        match self {
            Num::Exact(q) => q.dd(),
            Num::Float(x) => x,
        }
    }
    fn is_zero(self) -> bool {
        match self {
            Num::Exact(q) => q.is_zero(),
            Num::Float(x) => x.hi == 0.0,
        }
    }
    fn negative(self) -> bool {
        match self {
            Num::Exact(q) => q.n < 0,
            Num::Float(x) => x.hi < 0.0,
        }
    }
}

/// What went wrong, and where in the expression's text (byte offsets).
#[derive(Clone, Debug, PartialEq)]
pub struct Error {
    pub at: Range<usize>,
    pub message: String,
    pub help: Option<String>,
}

fn fail<T>(at: Range<usize>, message: impl Into<String>) -> Result<T, Error> {
    Err(Error {
        at,
        message: message.into(),
        help: None,
    })
}

impl Value {
    pub const fn exact(dim: Dim, q: Q) -> Value {
        Value {
            dim,
            num: Num::Exact(q),
            angle: false,
        }
    }

    /// A plain number from the file (dimensionless): exact, as every
    /// finite f64 is a binary fraction (in double-double beyond i128).
    pub fn of_f64(x: f64) -> Value {
        Value {
            dim: Dim::DIMENSIONLESS,
            num: of_f64(x),
            angle: false,
        }
    }

    /// The value (SI) as the nearest f64.
    pub fn num_f64(self) -> f64 {
        self.num.dd().f64()
    }

    /// The value in units of `factor` (of the value's dimension), rounded
    /// once to the nearest f64 where it is exact and the ratio is too.
    pub fn in_units(self, factor: Factor) -> f64 {
        let (n, d, pi) = factor.parts();
        match self.num {
            Num::Exact(q) => match Q::new(d, n, -pi).and_then(|f| q.times(f)) {
                Some(v) => v.f64(),
                None => {
                    let v = q.dd() / factor.dd();
                    v.hi + v.lo
                }
            },
            Num::Float(x) => {
                let v = x / factor.dd();
                v.hi + v.lo
            }
        }
    }

    /// Whether this is exactly a whole number: an integer rational (no
    /// power of π), or a double-double value both of whose parts are
    /// integers. `"10 / 3 * 3"` is, `"(1 + 1e-20) * 3"` is not (though it
    /// rounds to 3 in f64).
    pub fn is_whole(self) -> bool {
        match self.num {
            Num::Exact(q) => q.integer().is_some(),
            Num::Float(x) => power::is_integer(x),
        }
    }

    /// Whether this is a finite, exact or double-double value.
    fn finite(self) -> bool {
        match self.num {
            Num::Exact(_) => true,
            Num::Float(x) => x.hi.is_finite() && x.lo.is_finite(),
        }
    }
}

/// An f64 as an exact rational where it fits i128.
fn of_f64(x: f64) -> Num {
    if x == 0.0 {
        return Num::Exact(Q::ZERO);
    }
    if x.fract() == 0.0 && x.abs() < 1.6e38 {
        return Num::Exact(Q::new(x as i128, 1, 0).expect("an integer below 2^127"));
    }
    // x = m·2^e with m < 2^53.
    let bits = x.abs().to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let (m, e) = if exp == 0 {
        ((bits & ((1 << 52) - 1)) as i128, -1074)
    } else {
        (((bits & ((1 << 52) - 1)) | (1 << 52)) as i128, exp - 1075)
    };
    let m = if x < 0.0 { -m } else { m };
    if (-126..0).contains(&e)
        && let Some(q) = Q::new(m, 1i128 << (-e), 0)
    {
        return Num::Exact(q);
    }
    Num::Float(DD::from(x))
}

/// The dimension as units: `kg·m^-3`, or "dimensionless".
pub fn dim_text(d: Dim) -> String {
    let mut parts = Vec::new();
    for (s, p) in [("kg", d.mass), ("m", d.length), ("s", d.time)] {
        match p {
            0 => {}
            1 => parts.push(s.to_string()),
            p => parts.push(format!("{s}^{p}")),
        }
    }
    if parts.is_empty() {
        "dimensionless".into()
    } else {
        parts.join("·")
    }
}

/// The dimension in words, with its units: "a length (m)".
pub fn describe(d: Dim) -> String {
    match d.describe() {
        "a quantity of another kind" if d == Dim::DIMENSIONLESS => {
            "a plain number (dimensionless)".into()
        }
        "a quantity of another kind" => format!("a quantity in {}", dim_text(d)),
        w => format!("{w} ({})", dim_text(d)),
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Func {
    Sqrt,
    Sin,
    Cos,
    Tan,
    Abs,
    Min,
    Max,
}

#[derive(Clone, Debug, PartialEq)]
enum Op {
    /// A number or a number with its unit.
    Push(Value),
    /// A parameter, `pi` or a unit: resolved when evaluated.
    Name(String),
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Call(Func, usize),
}

/// An expression read: postfix steps, each with the text it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    steps: Vec<(Op, Range<usize>)>,
    /// The text read: a literal beyond i128 is read again from it,
    /// exactly (`exact`).
    text: String,
}

mod parse;
mod power;
pub mod tangent;

impl Expr {
    /// Read `text`; nothing is looked up yet.
    pub fn parse(text: &str) -> Result<Expr, Error> {
        parse::parse(text)
    }

    /// Whether this is a single number, with or without a unit and a sign
    /// (what a plain quantity string is: its errors are the unit reader's).
    pub fn is_plain(&self) -> bool {
        matches!(
            self.steps.as_slice(),
            [(Op::Push(_), _)] | [(Op::Push(_), _), (Op::Neg, _)]
        )
    }

    /// Every name it uses, with where.
    pub fn names(&self) -> impl Iterator<Item = (&str, Range<usize>)> {
        self.steps.iter().filter_map(|(op, at)| match op {
            Op::Name(n) => Some((n.as_str(), at.clone())),
            _ => None,
        })
    }

    /// The value, names looked up in `params` (a name it does not know is
    /// `pi` or a unit, else an error that suggests a near name among
    /// `known` and the units).
    pub fn eval(
        &self,
        params: &dyn Fn(&str) -> Option<Value>,
        known: &dyn Fn() -> Vec<String>,
    ) -> Result<Value, Error> {
        let mut stack: Vec<Value> = Vec::new();
        for (op, at) in &self.steps {
            let at = at.clone();
            let v = match op {
                Op::Push(v) => *v,
                Op::Name(n) => name(n, params, known, at.clone())?,
                Op::Neg => {
                    let a = stack.pop().expect("invariant: a parsed operand");
                    neg(a)
                }
                Op::Call(f, argc) => {
                    let args = stack.split_off(stack.len() - argc);
                    call(*f, &args, at.clone())?
                }
                _ => {
                    let b = stack.pop().expect("invariant: a parsed operand");
                    let a = stack.pop().expect("invariant: a parsed operand");
                    binary(op, a, b, at.clone())?
                }
            };
            if !v.finite() {
                return fail(at, "the value overflows the range of f64 here");
            }
            // NOTE: a double-double value whose leading part is subnormal
            // has lost digits (a literal there, or a step's result): it
            // would go on with as few as one significant bit. A literal
            // f64 made zero is refused by the reader (`parse::number`).
            if let Num::Float(x) = v.num
                && x.hi != 0.0
                && x.hi.abs() < f64::MIN_POSITIVE
            {
                return fail(at, "the value underflows f64 here (below 2.2e-308)");
            }
            stack.push(v);
        }
        Ok(stack
            .pop()
            .expect("invariant: a parsed expression has a value"))
    }
}

impl Expr {
    /// The exact value, where it is rational (no `pi` left, no function
    /// but `abs`, `min`, `max` and a `sqrt` of a square, integer powers)
    /// and its numbers stay within `big::MAX_BITS`; parameters looked up in
    /// `params` (`None`: not known exactly). Else `None`. Call it after
    /// `eval` succeeded: it assumes the dimensions and names checked.
    pub fn exact(&self, params: &dyn Fn(&str) -> Option<big::Big>) -> Option<big::Big> {
        use big::Big;
        let mut stack: Vec<Big> = Vec::new();
        for (op, at) in &self.steps {
            let v = match op {
                Op::Push(v) => match v.num {
                    Num::Exact(q) => Big::of(q),
                    Num::Float(_) => literal(self.text.get(at.clone())?)?,
                },
                Op::Name(n) => match params(n) {
                    Some(b) => b,
                    None if n == "pi" => Big::of(Q { n: 1, d: 1, pi: 1 }),
                    None => {
                        let u = units::parse_unit(n).ok()?;
                        let (num, den, pi) = u.factor.parts();
                        Big::of(Q::new(num, den, pi)?)
                    }
                },
                Op::Neg => stack.pop()?.negated(),
                Op::Call(f, argc) => {
                    let args = stack.split_off(stack.len().checked_sub(*argc)?);
                    match f {
                        Func::Abs => args.into_iter().next()?.abs(),
                        Func::Sqrt => args.first()?.sqrt()?,
                        Func::Min | Func::Max => {
                            let mut best = args.first()?.clone();
                            for b in &args[1..] {
                                let o = b.compare(&best)?;
                                if (*f == Func::Min && o.is_lt()) || (*f == Func::Max && o.is_gt())
                                {
                                    best = b.clone();
                                }
                            }
                            best
                        }
                        Func::Sin | Func::Cos | Func::Tan => return None,
                    }
                }
                Op::Add | Op::Sub | Op::Mul | Op::Div | Op::Pow => {
                    let b = stack.pop()?;
                    let a = stack.pop()?;
                    match op {
                        Op::Add => a.plus(&b)?,
                        Op::Sub => a.plus(&b.negated())?,
                        Op::Mul => a.times(&b)?,
                        Op::Div => a.over(&b)?,
                        _ => a.powi(&b)?,
                    }
                }
            };
            stack.push(v);
        }
        stack.pop()
    }
}

/// A number token, or a number and its unit, exactly: the decimal's digits
/// and the unit's rational factor.
fn literal(text: &str) -> Option<big::Big> {
    let end = units::number_end(text.as_bytes(), 0);
    let number = big::Big::decimal(text.get(..end)?)?;
    let unit = text.get(end..)?.trim();
    if unit.is_empty() {
        return Some(number);
    }
    let (num, den, pi) = units::parse_unit(unit).ok()?.factor.parts();
    number.times(&big::Big::of(Q::new(num, den, pi)?))
}

fn name(
    n: &str,
    params: &dyn Fn(&str) -> Option<Value>,
    known: &dyn Fn() -> Vec<String>,
    at: Range<usize>,
) -> Result<Value, Error> {
    if let Some(v) = params(n) {
        return Ok(v);
    }
    if n == "pi" {
        return Ok(Value::exact(Dim::DIMENSIONLESS, Q { n: 1, d: 1, pi: 1 }));
    }
    if let Ok(u) = units::parse_unit(n) {
        let (num, den, pi) = u.factor.parts();
        if let Some(q) = Q::new(num, den, pi) {
            return Ok(Value {
                angle: u.dim == Dim::DIMENSIONLESS,
                ..Value::exact(u.dim, q)
            });
        }
    }
    let names = known();
    let mut candidates: Vec<&str> = names.iter().map(String::as_str).collect();
    for s in units::symbol_names().chain(CONSTANTS.iter().copied()) {
        candidates.push(s);
    }
    let help: Option<String> =
        units::suggest(n, candidates).map(|s| format!("did you mean `{s}`?"));
    Err(Error {
        at,
        message: format!("unknown name `{n}`: not a parameter, a unit or `pi`"),
        help: help.or_else(|| Some("define it in `[params]`".into())),
    })
}

fn neg(a: Value) -> Value {
    Value {
        dim: a.dim,
        num: match a.num {
            Num::Exact(q) => Num::Exact(q.negated()),
            Num::Float(x) => Num::Float(-x),
        },
        angle: a.angle,
    }
}

fn same_dim(op: &str, a: Value, b: Value, at: Range<usize>) -> Result<Dim, Error> {
    if a.dim != b.dim {
        return Err(Error {
            at,
            message: format!("`{op}` of {} and {}", describe(a.dim), describe(b.dim)),
            help: Some("both sides must have the same dimension".into()),
        });
    }
    Ok(a.dim)
}

fn dims(a: Dim, b: Dim, sign: i32, at: Range<usize>) -> Result<Dim, Error> {
    let f = |x: i32, y: i32| {
        y.checked_mul(sign)
            .and_then(|y| x.checked_add(y))
            .filter(|v| v.unsigned_abs() <= 1 << 20)
    };
    match (f(a.mass, b.mass), f(a.length, b.length), f(a.time, b.time)) {
        (Some(mass), Some(length), Some(time)) => Ok(Dim { mass, length, time }),
        _ => fail(at, "the dimension's exponents grow too large"),
    }
}

fn binary(op: &Op, a: Value, b: Value, at: Range<usize>) -> Result<Value, Error> {
    let exact = |f: fn(Q, Q) -> Option<Q>, g: fn(DD, DD) -> DD| match (a.num, b.num) {
        (Num::Exact(x), Num::Exact(y)) => match f(x, y) {
            Some(q) => Num::Exact(q),
            None => Num::Float(g(x.dd(), y.dd())),
        },
        (x, y) => Num::Float(g(x.dd(), y.dd())),
    };
    let out = match op {
        Op::Add => Value {
            dim: same_dim("+", a, b, at.clone())?,
            num: exact(Q::plus, |x, y| x + y),
            angle: a.angle || b.angle,
        },
        Op::Sub => Value {
            dim: same_dim("-", a, b, at.clone())?,
            num: exact(|x, y| x.plus(y.negated()), |x, y| x - y),
            angle: a.angle || b.angle,
        },
        Op::Mul => Value {
            dim: dims(a.dim, b.dim, 1, at.clone())?,
            num: exact(Q::times, |x, y| x * y),
            angle: a.angle || b.angle,
        },
        Op::Div => {
            if b.num.is_zero() {
                return fail(at.clone(), "division by zero");
            }
            Value {
                dim: dims(a.dim, b.dim, -1, at.clone())?,
                num: exact(|x, y| x.times(y.recip()?), |x, y| x / y),
                angle: a.angle || b.angle,
            }
        }
        Op::Pow => power::pow(a, b, at.clone())?,
        _ => unreachable!("invariant: only binary operators here"),
    };
    // A product, quotient or power of values that are not zero is not
    // zero: in floating point it underflowed.
    if let Num::Float(x) = out.num
        && x.hi == 0.0
        && matches!(op, Op::Mul | Op::Div | Op::Pow)
        && !a.num.is_zero()
        && !b.num.is_zero()
    {
        return fail(at, "the value underflows f64 here (below 2.2e-308)");
    }
    Ok(out)
}

fn call(f: Func, args: &[Value], at: Range<usize>) -> Result<Value, Error> {
    let a = args[0];
    let plain = |what: &str| -> Result<(), Error> {
        if a.dim != Dim::DIMENSIONLESS {
            return fail(
                at.clone(),
                format!(
                    "`{what}` takes an angle (a plain number in radians, or `deg`), not {}",
                    describe(a.dim)
                ),
            );
        }
        Ok(())
    };
    let float = |x: DD| Num::Float(x);
    Ok(match f {
        Func::Sqrt => {
            let (m, l, t) = (a.dim.mass, a.dim.length, a.dim.time);
            if m % 2 != 0 || l % 2 != 0 || t % 2 != 0 {
                return fail(
                    at,
                    format!("`sqrt` of {}: an odd power of a unit", describe(a.dim)),
                );
            }
            if a.num.negative() {
                return fail(at, "`sqrt` of a negative number");
            }
            let num = match a.num {
                Num::Exact(q) => q.sqrt().map_or_else(|| float(q.dd().sqrt()), Num::Exact),
                Num::Float(x) => float(x.sqrt()),
            };
            Value {
                dim: Dim {
                    mass: m / 2,
                    length: l / 2,
                    time: t / 2,
                },
                num,
                angle: a.angle,
            }
        }
        Func::Sin | Func::Cos | Func::Tan => {
            plain(match f {
                Func::Sin => "sin",
                Func::Cos => "cos",
                _ => "tan",
            })?;
            let (s, c) = sin_cos(a.num);
            let num = match f {
                Func::Sin => s,
                Func::Cos => c,
                _ => {
                    if c.hi == 0.0 {
                        return fail(at, "`tan` of an odd multiple of 90°: division by zero");
                    }
                    s / c
                }
            };
            Value::exact(Dim::DIMENSIONLESS, Q::ZERO).with(float(num))
        }
        Func::Abs => Value {
            dim: a.dim,
            num: match a.num {
                Num::Exact(q) if q.n < 0 => Num::Exact(q.negated()),
                Num::Float(x) if x.hi < 0.0 => Num::Float(-x),
                n => n,
            },
            angle: a.angle,
        },
        Func::Min | Func::Max => {
            let mut best = a;
            for &b in &args[1..] {
                same_dim(
                    if f == Func::Min { "min" } else { "max" },
                    best,
                    b,
                    at.clone(),
                )?;
                let less = match (b.num, best.num) {
                    (Num::Exact(x), Num::Exact(y)) => x.compare(y).map(|o| o.is_lt()),
                    _ => None,
                }
                .unwrap_or_else(|| b.num.dd() < best.num.dd());
                let more = match (b.num, best.num) {
                    (Num::Exact(x), Num::Exact(y)) => x.compare(y).map(|o| o.is_gt()),
                    _ => None,
                }
                .unwrap_or_else(|| b.num.dd() > best.num.dd());
                if (f == Func::Min && less) || (f == Func::Max && more) {
                    best = Value {
                        angle: best.angle || b.angle,
                        ..b
                    };
                } else {
                    best.angle |= b.angle;
                }
            }
            best
        }
    })
}

impl Value {
    fn with(self, num: Num) -> Value {
        Value { num, ..self }
    }
}

/// sin and cos in double-double: exact multiples of π (an angle in `deg`)
/// through the project's degree reduction, else the f64 functions of the
/// leading part corrected by the trailing one (sin(h + l) ≈ sin h + l cos h).
fn sin_cos(x: Num) -> (DD, DD) {
    if let Num::Exact(q) = x {
        if q.is_zero() {
            return (DD::from(0.0), DD::from(1.0));
        }
        if q.pi == 1
            && let Some(deg) = q.times(Q {
                n: 180,
                d: 1,
                pi: 0,
            })
            && (deg.n as f64) as i128 == deg.n
            && (deg.d as f64) as i128 == deg.d
        {
            let d = deg.n as f64 / deg.d as f64;
            if d * deg.d as f64 == deg.n as f64 {
                return DD::sin_cos_deg(d);
            }
        }
    }
    let v = x.dd();
    let (s, c) = (v.hi.sin(), v.hi.cos());
    (
        DD::from(s) + DD::from(v.lo * c),
        DD::from(c) - DD::from(v.lo * s),
    )
}
