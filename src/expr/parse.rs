//! An expression's text into postfix steps: tokens, then precedence
//! climbing whose recursion is bounded by `MAX_DEPTH` (a chain of `+` or
//! `*` is a loop, not recursion).

use super::{Error, Expr, FUNCTIONS, Func, MAX_DEPTH, Num, Op, Q, Value, fail, of_f64};
use crate::numeric::DD;
use crate::units::{self, Dim};
use std::ops::Range;

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(Num),
    Name,
    /// `+ - * / ^ ( ) ,` (`·` is `*`).
    Sym(char),
}

struct Token {
    tok: Tok,
    at: Range<usize>,
}

fn tokens(text: &str) -> Result<Vec<Token>, Error> {
    let mut out = Vec::new();
    let b = text.as_bytes();
    let mut i = 0;
    while i < text.len() {
        let c = text[i..].chars().next().expect("invariant: i < len");
        let start = i;
        if c.is_whitespace() {
            i += c.len_utf8();
        } else if c.is_ascii_digit() || c == '.' {
            // Where a quantity's number ends (`units::number_end`).
            i = crate::units::number_end(b, i);
            out.push(Token {
                tok: Tok::Num(number(&text[start..i], start..i)?),
                at: start..i,
            });
        } else if c.is_alphabetic() || c == '_' {
            while let Some(c) = text[i..].chars().next()
                && (c.is_alphanumeric() || c == '_' || c == '²' || c == '³')
            {
                i += c.len_utf8();
            }
            out.push(Token {
                tok: Tok::Name,
                at: start..i,
            });
        } else if "+-*/^(),·".contains(c) {
            i += c.len_utf8();
            out.push(Token {
                tok: Tok::Sym(if c == '·' { '*' } else { c }),
                at: start..i,
            });
        } else {
            let at = start..start + c.len_utf8();
            return fail(at, format!("unexpected character {c:?} in an expression"));
        }
    }
    Ok(out)
}

/// A decimal number, exactly: digits (with `_`), one `.`, an exponent.
fn number(text: &str, at: Range<usize>) -> Result<Num, Error> {
    let clean: String = text.chars().filter(|c| *c != '_').collect();
    let (mantissa, exp) = match clean.find(['e', 'E']) {
        Some(k) => (&clean[..k], &clean[k + 1..]),
        None => (clean.as_str(), "0"),
    };
    let bad = || fail(at.clone(), format!("cannot read the number `{text}`"));
    if mantissa.matches('.').count() > 1 || !mantissa.chars().any(|c| c.is_ascii_digit()) {
        return bad();
    }
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = format!("{int}{frac}");
    let digits = digits.trim_start_matches('0');
    let exp: i64 = exp.parse().unwrap_or(if exp.starts_with('-') {
        -100_000
    } else {
        100_000
    });
    // Trailing zeros into the scale: `3.000…0` with 40 zeros is exactly 3.
    let significant = digits.trim_end_matches('0');
    let scale = (exp - frac.len() as i64).saturating_add((digits.len() - significant.len()) as i64);
    let digits = significant;
    let exact = (|| {
        if digits.is_empty() {
            return Some(Q::ZERO);
        }
        // Up to 39 digits: i128 holds them to 1.7e38 (the parse refuses more).
        if digits.len() > 39 || scale.unsigned_abs() > 38 {
            return None;
        }
        let n: i128 = digits.parse().ok()?;
        let p = 10i128.checked_pow(scale.unsigned_abs() as u32)?;
        if scale >= 0 {
            Q::new(n.checked_mul(p)?, 1, 0)
        } else {
            Q::new(n, p, 0)
        }
    })();
    if let Some(q) = exact {
        return Ok(Num::Exact(q));
    }
    // Beyond i128: the nearest f64 (Rust's parse rounds correctly).
    let Ok(x) = clean.parse::<f64>() else {
        return bad();
    };
    if !x.is_finite() {
        return fail(
            at,
            format!("the number `{text}` is beyond the range of f64"),
        );
    }
    // Not zero as written (`digits` has a non-zero digit), but zero or
    // subnormal in f64: too small, as a plain value is (`1e-400`).
    if x.abs() < f64::MIN_POSITIVE {
        return fail(
            at,
            format!(
                "the number `{text}` is too small: below {:e}, f64 loses precision",
                f64::MIN_POSITIVE
            ),
        );
    }
    Ok(match of_f64(x) {
        Num::Exact(q) => Num::Exact(q),
        Num::Float(_) => Num::Float(DD::from(x)),
    })
}

struct Parser<'t> {
    text: &'t str,
    toks: Vec<Token>,
    i: usize,
    steps: Vec<(Op, Range<usize>)>,
}

pub(super) fn parse(text: &str) -> Result<Expr, Error> {
    let toks = tokens(text)?;
    if toks.is_empty() {
        return fail(0..text.len(), "an empty expression");
    }
    let mut p = Parser {
        text,
        toks,
        i: 0,
        steps: Vec::new(),
    };
    p.expr(0)?;
    if let Some(t) = p.toks.get(p.i) {
        let at = t.at.clone();
        let after_number = p.i > 0 && matches!(p.toks[p.i - 1].tok, Tok::Num(_));
        if t.tok == Tok::Name && after_number {
            let word = &text[at.clone()];
            // A unit, but after a power of something other than a number
            // (`(-1)^3 kg`, `x^2 m`): it binds to a number only.
            if units::parse_unit(word).is_ok() {
                return Err(Error {
                    at,
                    message: format!("expected an operator before the unit `{word}`"),
                    help: Some(format!(
                        "a unit follows a number directly (`2 {word}`, `10^3 {word}`); after a parenthesis, a name or a power of either, write `* {word}`"
                    )),
                });
            }
            return Err(Error {
                at,
                message: format!("unknown unit `{word}`"),
                help: units::suggest(word, units::symbol_names())
                    .map(|s| format!("did you mean `{s}`?")),
            });
        }
        return fail(
            at,
            format!("expected an operator before `{}`", &text[t.at.clone()]),
        );
    }
    Ok(Expr {
        steps: p.steps,
        text: text.to_string(),
    })
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.i).map(|t| &t.tok)
    }

    fn sym(&self, c: char) -> bool {
        self.peek() == Some(&Tok::Sym(c))
    }

    fn here(&self) -> Range<usize> {
        match self.toks.get(self.i) {
            Some(t) => t.at.clone(),
            None => self.text.len()..self.text.len(),
        }
    }

    fn deeper(&self, depth: usize) -> Result<usize, Error> {
        if depth >= MAX_DEPTH {
            return fail(
                self.here(),
                format!("the expression nests deeper than {MAX_DEPTH} levels"),
            );
        }
        Ok(depth + 1)
    }

    fn expr(&mut self, depth: usize) -> Result<(), Error> {
        self.term(depth)?;
        while self.sym('+') || self.sym('-') {
            let at = self.here();
            let op = if self.sym('+') { Op::Add } else { Op::Sub };
            self.i += 1;
            self.term(depth)?;
            self.steps.push((op, at));
        }
        Ok(())
    }

    fn term(&mut self, depth: usize) -> Result<(), Error> {
        self.unary(depth)?;
        while self.sym('*') || self.sym('/') {
            let at = self.here();
            let op = if self.sym('*') { Op::Mul } else { Op::Div };
            self.i += 1;
            self.unary(depth)?;
            self.steps.push((op, at));
        }
        Ok(())
    }

    /// A signed power; in an exponent (`bare`) a number takes no unit, and
    /// a unit after a power of a number is the power's: `10^3 kg` is
    /// 10³ kg, not 10 to the power 3 kg.
    fn unary(&mut self, depth: usize) -> Result<(), Error> {
        self.signed(depth, false)
    }

    fn signed(&mut self, depth: usize, bare: bool) -> Result<(), Error> {
        if self.sym('-') || self.sym('+') {
            let at = self.here();
            let minus = self.sym('-');
            self.i += 1;
            self.signed(self.deeper(depth)?, bare)?;
            if minus {
                self.steps.push((Op::Neg, at));
            }
            return Ok(());
        }
        let number = matches!(self.peek(), Some(Tok::Num(_)));
        self.atom(depth, bare)?;
        if self.sym('^') {
            let at = self.here();
            self.i += 1;
            self.signed(self.deeper(depth)?, true)?;
            self.steps.push((Op::Pow, at));
            let first = self.here().start;
            if number
                && !bare
                && let Some((u, end)) = self.unit()
            {
                let one = Value {
                    dim: Dim::DIMENSIONLESS,
                    num: Num::Exact(Q::ONE),
                    angle: false,
                };
                self.steps.push((Op::Push(quantity(one, u)), first..end));
                self.steps.push((Op::Mul, first..end));
            }
        }
        Ok(())
    }

    fn atom(&mut self, depth: usize, bare: bool) -> Result<(), Error> {
        let at = self.here();
        match self.peek().cloned() {
            Some(Tok::Num(n)) => {
                self.i += 1;
                let mut v = Value {
                    dim: Dim::DIMENSIONLESS,
                    num: n,
                    angle: false,
                };
                let mut end = at.end;
                if !bare && let Some((u, e)) = self.unit() {
                    v = quantity(v, u);
                    end = e;
                }
                self.steps.push((Op::Push(v), at.start..end));
                Ok(())
            }
            Some(Tok::Name)
                if self.toks.get(self.i + 1).map(|t| &t.tok) == Some(&Tok::Sym('(')) =>
            {
                self.call(depth, at)
            }
            Some(Tok::Name) => {
                self.i += 1;
                self.steps
                    .push((Op::Name(self.text[at.clone()].to_string()), at));
                Ok(())
            }
            Some(Tok::Sym('(')) => {
                self.i += 1;
                self.expr(self.deeper(depth)?)?;
                if !self.sym(')') {
                    return fail(self.here(), "expected `)`").map_err(|e| Error {
                        help: Some(format!("the `(` at byte {} is not closed", at.start + 1)),
                        ..e
                    });
                }
                self.i += 1;
                Ok(())
            }
            Some(Tok::Sym(c)) => fail(at, format!("expected a number, a name or `(`, found `{c}`")),
            None => fail(at, "the expression ends where a value was expected"),
        }
    }

    fn call(&mut self, depth: usize, at: Range<usize>) -> Result<(), Error> {
        let name = &self.text[at.clone()];
        let Some(&(_, arity)) = FUNCTIONS.iter().find(|(f, _)| *f == name) else {
            let help = units::suggest(name, FUNCTIONS.iter().map(|(f, _)| *f))
                .map(|s| format!("did you mean `{s}`?"))
                .unwrap_or_else(|| {
                    let all: Vec<&str> = FUNCTIONS.iter().map(|(f, _)| *f).collect();
                    format!("the functions are {}", all.join(", "))
                });
            return Err(Error {
                at,
                message: format!("unknown function `{name}`"),
                help: Some(help),
            });
        };
        let func = match name {
            "sqrt" => Func::Sqrt,
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "tan" => Func::Tan,
            "abs" => Func::Abs,
            "min" => Func::Min,
            _ => Func::Max,
        };
        self.i += 2;
        let depth = self.deeper(depth)?;
        let mut argc = 0;
        loop {
            self.expr(depth)?;
            argc += 1;
            if self.sym(',') {
                self.i += 1;
                continue;
            }
            if self.sym(')') {
                self.i += 1;
                break;
            }
            return fail(self.here(), format!("expected `,` or `)` in `{name}(…)`"));
        }
        if arity.is_some_and(|n| n != argc) {
            return fail(at, format!("`{name}` takes 1 argument, got {argc}"));
        }
        self.steps.push((Op::Call(func, argc), at));
        Ok(())
    }

    /// A unit right after a number: symbols with exponents, joined by `*`,
    /// `·` or space, at most one `/`; each symbol a unit, not a parameter
    /// name (a name that is a unit cannot be a parameter's). Returns the
    /// unit and where its text ends.
    fn unit(&mut self) -> Option<(units::Unit, usize)> {
        let mut text = String::new();
        let mut end = 0;
        let mut slash = false;
        let start = self.i;
        loop {
            // A joiner, then a symbol; or, first, a symbol alone.
            let mut j = self.i;
            let mut joiner = "";
            if !text.is_empty() {
                match self.toks.get(j).map(|t| &t.tok) {
                    Some(Tok::Sym('*')) => {
                        joiner = "*";
                        j += 1;
                    }
                    Some(Tok::Sym('/')) if !slash => {
                        joiner = "/";
                        j += 1;
                    }
                    Some(Tok::Name) => joiner = " ",
                    _ => break,
                }
            }
            let Some((term, next, term_end)) = self.unit_term(j) else {
                break;
            };
            if joiner == "/" {
                slash = true;
            }
            text.push_str(joiner);
            text.push_str(&term);
            end = term_end;
            self.i = next;
        }
        if text.is_empty() {
            self.i = start;
            return None;
        }
        match units::parse_unit(&text) {
            Ok(u) => Some((u, end)),
            Err(_) => {
                self.i = start;
                None
            }
        }
    }

    /// A unit symbol at token `j` with its exponent (`m`, `m^-3`, `cm3`,
    /// `m²`): its text, the next token and where it ends.
    fn unit_term(&self, j: usize) -> Option<(String, usize, usize)> {
        let t = self.toks.get(j)?;
        if t.tok != Tok::Name {
            return None;
        }
        // A call, not a unit: `min(…)`.
        if self.toks.get(j + 1).map(|t| &t.tok) == Some(&Tok::Sym('(')) {
            return None;
        }
        let name = &self.text[t.at.clone()];
        units::parse_unit(name).ok()?;
        // `^n` with an integer n (signed).
        if self.toks.get(j + 1).map(|t| &t.tok) == Some(&Tok::Sym('^')) {
            let mut k = j + 2;
            let mut sign = "";
            if let Some(Tok::Sym(c @ ('-' | '+'))) = self.toks.get(k).map(|t| &t.tok) {
                sign = if *c == '-' { "-" } else { "" };
                k += 1;
            }
            if let Some(n) = self.toks.get(k)
                && matches!(n.tok, Tok::Num(Num::Exact(q)) if q.integer().is_some())
                && self.text[n.at.clone()].chars().all(|c| c.is_ascii_digit())
            {
                let term = format!("{name}^{sign}{}", &self.text[n.at.clone()]);
                if units::parse_unit(&term).is_ok() {
                    return Some((term, k + 1, n.at.end));
                }
            }
            // `2 m^5` is not (2 m)^5: a unit's power is the unit's.
            return None;
        }
        Some((name.to_string(), j + 1, t.at.end))
    }
}

/// A number times a unit: exact where the factor is.
fn quantity(v: Value, u: units::Unit) -> Value {
    let (n, d, pi) = u.factor.parts();
    let num = match (v.num, Q::new(n, d, pi)) {
        (Num::Exact(x), _) if x.is_zero() => Num::Exact(Q::ZERO),
        (Num::Exact(x), Some(f)) => match x.times(f) {
            Some(q) => Num::Exact(q),
            None => Num::Float(x.dd() * u.factor.dd()),
        },
        (x, _) => Num::Float(x.dd() * u.factor.dd()),
    };
    // The only dimensionless units are the angles'.
    Value {
        dim: u.dim,
        num,
        angle: v.angle || u.dim == Dim::DIMENSIONLESS,
    }
}
