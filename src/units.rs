//! Units at the edge: the file's default units and quantity strings such as
//! `"3 mm"` or `"7.85 g/cm^3"`, converted to SI exactly once.
//!
//! Every factor is kept as an exact rational (times a power of π for angle
//! units) until the single conversion of a value, so `"7.85 g/cm^3"` becomes
//! `7850.0` kg/m³ rather than `7849.999999999999`. The inch and the pound are
//! the exact defined ones (0.0254 m, 0.45359237 kg).

use std::fmt;

mod round;

/// Physical dimension as exponents of (mass, length, time). Angles are
/// dimensionless (radians), as in SI.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dim {
    pub mass: i32,
    pub length: i32,
    pub time: i32,
}

impl Dim {
    const fn new(mass: i32, length: i32, time: i32) -> Dim {
        Dim { mass, length, time }
    }
    /// A plain number (an angle in radians, a count).
    pub const DIMENSIONLESS: Dim = Dim::new(0, 0, 0);
    pub const LENGTH: Dim = Dim::new(0, 1, 0);
    pub const AREA: Dim = Dim::new(0, 2, 0);
    pub const MASS: Dim = Dim::new(1, 0, 0);
    pub const DENSITY: Dim = Dim::new(1, -3, 0);
    pub const AREAL_DENSITY: Dim = Dim::new(1, -2, 0);
    pub const LINEAR_DENSITY: Dim = Dim::new(1, -1, 0);
    pub const ANGULAR_VELOCITY: Dim = Dim::new(0, 0, -1);
    pub const ANGULAR_ACCELERATION: Dim = Dim::new(0, 0, -2);
    pub const INERTIA: Dim = Dim::new(1, 2, 0);
    pub const ANGULAR_MOMENTUM: Dim = Dim::new(1, 2, -1);
    pub const ENERGY: Dim = Dim::new(1, 2, -2);
    /// A point's velocity (`[analysis] velocity`) and a linear momentum.
    pub const VELOCITY: Dim = Dim::new(0, 1, -1);
    pub const MOMENTUM: Dim = Dim::new(1, 1, -1);
    /// `[analysis] g`.
    pub const ACCELERATION: Dim = Dim::new(0, 1, -2);

    fn add(self, o: Dim, sign: i32) -> Dim {
        Dim::new(
            self.mass + sign * o.mass,
            self.length + sign * o.length,
            self.time + sign * o.time,
        )
    }

    /// What the quantity is called in messages.
    pub fn describe(self) -> &'static str {
        match self {
            Dim::LENGTH => "a length",
            Dim::AREA => "an area",
            Dim::MASS => "a mass",
            Dim::DENSITY => "a density (mass per volume)",
            Dim::AREAL_DENSITY => "an areal density (mass per area)",
            Dim::LINEAR_DENSITY => "a linear density (mass per length)",
            Dim::ANGULAR_VELOCITY => "an angular velocity",
            Dim::ANGULAR_ACCELERATION => "an angular acceleration",
            Dim::INERTIA => "a moment of inertia",
            Dim::ANGULAR_MOMENTUM => "an angular momentum",
            Dim::ENERGY => "an energy",
            Dim::VELOCITY => "a velocity",
            Dim::MOMENTUM => "a linear momentum",
            Dim::ACCELERATION => "an acceleration",
            _ => "a quantity of another kind",
        }
    }

    /// An example unit, for "expected" hints.
    pub fn example(self) -> &'static str {
        match self {
            Dim::LENGTH => "\"3 mm\"",
            Dim::AREA => "\"12 mm^2\"",
            Dim::MASS => "\"2 lb\"",
            Dim::DENSITY => "\"7.85 g/cm^3\"",
            Dim::AREAL_DENSITY => "\"70 kg/m^2\"",
            Dim::LINEAR_DENSITY => "\"0.4 kg/m\"",
            Dim::ANGULAR_VELOCITY => "\"3000 rpm\"",
            Dim::ANGULAR_ACCELERATION => "\"2 rad/s^2\"",
            Dim::INERTIA => "\"1.2 kg*m^2\"",
            Dim::ANGULAR_MOMENTUM => "\"0.5 N*m*s\"",
            Dim::ENERGY => "\"8.25 J\"",
            Dim::VELOCITY => "\"3 m/s\"",
            Dim::MOMENTUM => "\"6 kg*m/s\"",
            Dim::ACCELERATION => "\"9.81 m/s^2\"",
            _ => "\"1 m\"",
        }
    }
}

/// An exact conversion factor to SI: `num / den · π^pi`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Factor {
    num: i128,
    den: i128,
    pi: i32,
}

impl Factor {
    pub const ONE: Factor = Factor::ratio(1, 1);

    const fn ratio(num: i128, den: i128) -> Factor {
        Factor { num, den, pi: 0 }
    }

    fn mul(self, o: Factor) -> Option<Factor> {
        Factor {
            num: self.num.checked_mul(o.num)?,
            den: self.den.checked_mul(o.den)?,
            pi: self.pi + o.pi,
        }
        .reduced()
    }

    fn inv(self) -> Factor {
        Factor {
            num: self.den,
            den: self.num,
            pi: -self.pi,
        }
    }

    fn pow(self, n: i32) -> Option<Factor> {
        let base = if n < 0 { self.inv() } else { self };
        let mut out = Factor::ONE;
        for _ in 0..n.unsigned_abs() {
            out = out.mul(base)?;
        }
        Some(out)
    }

    fn reduced(self) -> Option<Factor> {
        let g = gcd(self.num, self.den);
        Some(Factor {
            num: self.num / g,
            den: self.den / g,
            pi: self.pi,
        })
    }

    /// `x` in SI (or in whatever unit the factor converts to): the f64
    /// nearest to x times the exact factor, one rounding (`round::ratio`:
    /// `"10.1 in"` in a millimetre file is the f64 nearest to 256.54, not
    /// `10.1 * 127 / 5`, which rounds twice and may be an ulp off). A
    /// factor with π (angle units) is formed in double-double and the
    /// product rounded once: within half an ulp and 2⁻¹⁰⁰ of the value.
    pub fn apply(self, x: f64) -> f64 {
        if self.pi == 0 {
            round::ratio(x, self.num, self.den)
        } else {
            use crate::numeric::{DD, Real};
            (DD::of(x) * self.dd()).f64()
        }
    }

    /// self / o, exactly, or `None` if the fraction outgrows i128.
    pub fn per(self, o: Factor) -> Option<Factor> {
        self.mul(o.inv())
    }

    /// The factor as a double-double (π to double-double precision).
    pub fn dd(self) -> crate::numeric::DD {
        use crate::numeric::DD;
        let mut v = DD::of_i128(self.num) / DD::of_i128(self.den);
        for _ in 0..self.pi.unsigned_abs() {
            v = if self.pi > 0 { v * DD::PI } else { v / DD::PI };
        }
        v
    }

    /// The exact factor: numerator, denominator and power of π.
    pub fn parts(self) -> (i128, i128, i32) {
        (self.num, self.den, self.pi)
    }

    /// The SI value of one unit: `apply(1.0)`.
    pub fn value(self) -> f64 {
        self.apply(1.0)
    }
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.abs().max(1)
}

/// A unit symbol, its dimension and its exact factor to SI.
struct Symbol {
    name: &'static str,
    dim: Dim,
    factor: Factor,
}

const fn sym(name: &'static str, dim: Dim, num: i128, den: i128, pi: i32) -> Symbol {
    Symbol {
        name,
        dim,
        factor: Factor { num, den, pi },
    }
}

const NONE: Dim = Dim::new(0, 0, 0);
const TIME: Dim = Dim::new(0, 0, 1);

/// Every unit symbol a quantity string may use.
const SYMBOLS: &[Symbol] = &[
    sym("m", Dim::LENGTH, 1, 1, 0),
    sym("cm", Dim::LENGTH, 1, 100, 0),
    sym("mm", Dim::LENGTH, 1, 1000, 0),
    // Micrometre: ASCII `um`, the micro sign U+00B5 and the Greek mu U+03BC.
    sym("um", Dim::LENGTH, 1, 1_000_000, 0),
    sym("\u{b5}m", Dim::LENGTH, 1, 1_000_000, 0),
    sym("\u{3bc}m", Dim::LENGTH, 1, 1_000_000, 0),
    sym("km", Dim::LENGTH, 1000, 1, 0),
    sym("in", Dim::LENGTH, 254, 10_000, 0),
    sym("ft", Dim::LENGTH, 3048, 10_000, 0),
    sym("kg", Dim::MASS, 1, 1, 0),
    sym("g", Dim::MASS, 1, 1000, 0),
    sym("mg", Dim::MASS, 1, 1_000_000, 0),
    // Tonne (metric ton), 1000 kg.
    sym("t", Dim::MASS, 1000, 1, 0),
    sym("lb", Dim::MASS, 45_359_237, 100_000_000, 0),
    // The avoirdupois ounce, 1/16 lb: 28.349523125 g.
    sym("oz", Dim::MASS, 45_359_237, 1_600_000_000, 0),
    // Litre and millilitre: 1e-3 and 1e-6 m³.
    sym("L", Dim::new(0, 3, 0), 1, 1000, 0),
    sym("mL", Dim::new(0, 3, 0), 1, 1_000_000, 0),
    sym("N", Dim::new(1, 1, -2), 1, 1, 0),
    sym("J", Dim::ENERGY, 1, 1, 0),
    sym("s", TIME, 1, 1, 0),
    sym("min", TIME, 60, 1, 0),
    sym("rad", NONE, 1, 1, 0),
    sym("deg", NONE, 1, 180, 1),
    sym("rev", NONE, 2, 1, 1),
    // Revolutions per minute: 2π/60 rad/s.
    sym("rpm", Dim::new(0, 0, -1), 1, 30, 1),
    // Hertz as an angular velocity is revolutions per second: 2π rad/s
    // (`rev/s` says the same).
    sym("Hz", Dim::new(0, 0, -1), 2, 1, 1),
];

/// Length units allowed as a file's default (`units.length`).
pub const LENGTH_UNITS: &[&str] = &[
    "m", "cm", "mm", "um", "\u{b5}m", "\u{3bc}m", "km", "in", "ft",
];
/// Mass units allowed as a file's default (`units.mass`).
pub const MASS_UNITS: &[&str] = &["kg", "g", "mg", "t", "lb"];

/// A unit expression: its dimension and factor to SI.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unit {
    pub dim: Dim,
    pub factor: Factor,
}

/// Why a quantity string could not be read. `Display` gives the message;
/// `suggestion` a near symbol for an unknown one.
#[derive(Debug, PartialEq)]
pub enum UnitError {
    NoNumber,
    NotFinite,
    NoUnit,
    Unknown {
        symbol: String,
        suggestion: Option<&'static str>,
    },
    Syntax(String),
    Overflow,
    WrongDim {
        unit: String,
        expected: Dim,
    },
}

impl fmt::Display for UnitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UnitError::NoNumber => write!(f, "a quantity string must start with a number"),
            UnitError::NotFinite => write!(f, "the number must be finite"),
            UnitError::NoUnit => write!(
                f,
                "a quantity string needs a unit (write a plain number, without quotes, for the file's units)"
            ),
            UnitError::Unknown { symbol, .. } => write!(f, "unknown unit `{symbol}`"),
            UnitError::Syntax(s) => write!(f, "cannot read unit `{s}`"),
            UnitError::Overflow => write!(f, "unit exponent too large"),
            UnitError::WrongDim { unit, expected } => {
                write!(f, "`{unit}` is not {}", expected.describe())
            }
        }
    }
}

/// Parse a unit expression such as `kg/m^2`, `g/cm³`, `rad/s` or `rpm`:
/// symbols joined by `*`, `·` or spaces, at most one `/`, exponents as `^n`
/// (negative too: `g cm^-3`), `²`, `³` or a digit after the symbol (`m3`).
/// No symbol ends in a digit, so `cm3` can only be cm³.
pub fn parse_unit(text: &str) -> Result<Unit, UnitError> {
    let text = text.trim();
    let (numer, denom) = match text.split_once('/') {
        Some((n, d)) => (n.trim(), Some(d.trim())),
        None => (text, None),
    };
    if numer.is_empty() {
        return Err(UnitError::Syntax(text.to_string()));
    }
    let mut unit = Unit {
        dim: NONE,
        factor: Factor::ONE,
    };
    // A leading "1/s" is a pure denominator.
    if numer != "1" {
        unit = product(unit, numer, 1)?;
    }
    if let Some(d) = denom {
        if d.is_empty() || d.contains('/') {
            return Err(UnitError::Syntax(text.to_string()));
        }
        unit = product(unit, d, -1)?;
    }
    Ok(unit)
}

fn product(mut unit: Unit, terms: &str, sign: i32) -> Result<Unit, UnitError> {
    for term in terms.split(['*', '·', ' ']).filter(|t| !t.is_empty()) {
        let term = term.trim();
        let (name, exp) = split_exponent(term)?;
        let symbol = SYMBOLS
            .iter()
            .find(|s| s.name == name)
            .ok_or_else(|| UnitError::Unknown {
                symbol: name.to_string(),
                suggestion: suggest(name, SYMBOLS.iter().map(|s| s.name)),
            })?;
        let power = sign * exp;
        let dim = Dim::new(
            symbol.dim.mass * power,
            symbol.dim.length * power,
            symbol.dim.time * power,
        );
        unit.dim = unit.dim.add(dim, 1);
        unit.factor = symbol
            .factor
            .pow(power)
            .and_then(|f| unit.factor.mul(f))
            .ok_or(UnitError::Overflow)?;
    }
    Ok(unit)
}

fn split_exponent(term: &str) -> Result<(&str, i32), UnitError> {
    let bad = || UnitError::Syntax(term.to_string());
    if let Some(base) = term.strip_suffix('²') {
        return Ok((base, 2));
    }
    if let Some(base) = term.strip_suffix('³') {
        return Ok((base, 3));
    }
    // `m3`, `cm2`: a digit after a symbol's letters.
    if let Some(last) = term.chars().last()
        && let Some(exp) = last.to_digit(10)
        && term.len() > 1
        && !term.contains('^')
    {
        if !(1..=4).contains(&exp) {
            return Err(bad());
        }
        return Ok((&term[..term.len() - 1], exp as i32));
    }
    match term.split_once('^') {
        Some((base, exp)) => {
            let exp: i32 = exp.trim().parse().map_err(|_| bad())?;
            // (unsigned_abs: i32::MIN has no i32 absolute value.)
            if exp == 0 || exp.unsigned_abs() > 4 {
                return Err(bad());
            }
            Ok((base.trim(), exp))
        }
        None if term.is_empty() => Err(bad()),
        None => Ok((term, 1)),
    }
}

/// Every unit symbol, in the order of the table (for the JSON Schema's
/// description of a quantity).
pub fn symbol_names() -> impl Iterator<Item = &'static str> {
    SYMBOLS.iter().map(|s| s.name)
}

/// The quantity strings `split_number` and `parse_unit` read, of any
/// dimension, as a regular expression (JSON Schema's `pattern`: ECMA-262,
/// anchored here): a number, then symbols of `SYMBOLS` with their
/// exponents, joined by `*`, `·` or spaces, with at most one `/`. Made
/// from the table, so a symbol added there is in it; the key's dimension
/// is the model's to check. (Stricter than the reader only where a unit is
/// no symbol at all, such as `"3 */s"`.)
pub fn quantity_pattern() -> String {
    let symbol = SYMBOLS.iter().map(|s| s.name).collect::<Vec<_>>().join("|");
    // `^n` (1 ≤ |n| ≤ 4), `²`, `³`, or one digit 1–4 (see `split_exponent`).
    let term = format!("(?:{symbol})(?:\\^[+-]?0*[1-4]|[1-4²³])?");
    let sep = "[*· ]";
    let terms = format!("{sep}*{term}(?:{sep}+{term})*{sep}*");
    // `split_number`: digits, `.` and `_`, one number once the `_` are
    // gone; an exponent only with its digits.
    let number = "[+-]?(?:[0-9_]*[0-9][0-9_]*(?:\\.[0-9_]*)?|[0-9_]*\\.[0-9_]*[0-9][0-9_]*)(?:[eE][+-]?[0-9]+)?";
    format!("^\\s*{number}\\s*(?:1|{terms})(?:\\s*/\\s*{terms})?\\s*$")
}

/// Where the unsigned number that starts at `i` in `b` ends: digits, `.`
/// and `_`, then an exponent only if digits follow it (so "3 m" is not
/// read as "3 e…"); `i` itself if no digit or point is there. The one rule
/// of a number's extent, for quantities (`split_number`) and expressions
/// (`expr`).
pub fn number_end(b: &[u8], mut i: usize) -> usize {
    let start = i;
    while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.' || b[i] == b'_') {
        i += 1;
    }
    if i > start && i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if j < b.len() && b[j].is_ascii_digit() {
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            i = j;
        }
    }
    i
}

/// Split `"7.85 g/cm^3"` into the number and the unit text.
pub fn split_number(text: &str) -> Result<(f64, &str), UnitError> {
    let t = text.trim_start();
    let b = t.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let digits_start = i;
    i = number_end(b, i);
    if i == digits_start {
        return Err(UnitError::NoNumber);
    }
    let number: f64 = t[..i]
        .replace('_', "")
        .parse()
        .map_err(|_| UnitError::NoNumber)?;
    if !number.is_finite() {
        return Err(UnitError::NotFinite);
    }
    Ok((number, t[i..].trim()))
}

/// Read a quantity string of the expected dimension and return it in SI.
pub fn parse_quantity(text: &str, expected: Dim) -> Result<f64, UnitError> {
    let (number, unit_text) = split_number(text)?;
    if unit_text.is_empty() {
        return Err(UnitError::NoUnit);
    }
    let unit = parse_unit(unit_text)?;
    if unit.dim != expected {
        return Err(UnitError::WrongDim {
            unit: unit_text.to_string(),
            expected,
        });
    }
    Ok(unit.factor.apply(number))
}

/// Read a quantity string of the expected dimension and return it in the
/// file's units: one conversion by the exact ratio of the two factors, so
/// `"2 m"` in a millimetre file is exactly 2000.
pub fn parse_quantity_in(text: &str, expected: Dim, file: FileUnits) -> Result<f64, UnitError> {
    let (number, unit_text) = split_number(text)?;
    if unit_text.is_empty() {
        return Err(UnitError::NoUnit);
    }
    let unit = parse_unit(unit_text)?;
    if unit.dim != expected {
        return Err(UnitError::WrongDim {
            unit: unit_text.to_string(),
            expected,
        });
    }
    match unit.factor.per(file.factor(expected)) {
        Some(f) => Ok(f.apply(number)),
        // A ratio too large for i128: two roundings instead of one.
        None => Ok(unit.factor.apply(number) / file.factor(expected).value()),
    }
}

/// The nearest of `candidates` to a misspelt `word`, if one is close enough
/// to be a likely typo.
pub fn suggest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    // NOTE: the edit distance is at least the difference of the lengths, so
    // a candidate whose length is too far off is not compared at all: a
    // 200 KB key or name costs one count of its characters, not a
    // quadratic comparison with every candidate.
    // And a word longer than `COMPARED` characters is compared with
    // nothing: the distance costs the product of the lengths, and a
    // 100,000-character material or sub-assembly name misspelt against
    // its definition cost 10¹⁰ steps, for a suggestion no one needs.
    const COMPARED: usize = 256;
    let n = word.chars().count();
    if n > COMPARED {
        return None;
    }
    // NOTE: case-aware: the distance is first that of the lowercased
    // words, then the exact one, so `MM` is `mm` (0 apart but for case),
    // not `µm` (as many edits apart as `mm` by the exact distance, and
    // 1000× off); of `Mg` and `mg` for `MG`, the one nearer by case wins.
    let lower = word.to_lowercase();
    candidates
        .into_iter()
        .filter(|c| {
            c.len() <= 4 * 2 * COMPARED && n.abs_diff(c.chars().count()) <= 2.max(c.len() / 3)
        })
        .map(|c| {
            let folded = strsim::damerau_levenshtein(&lower, &c.to_lowercase());
            ((folded, strsim::damerau_levenshtein(word, c)), c)
        })
        .filter(|&((d, _), c)| d <= 2.max(c.len() / 3) && d < c.len().max(word.len()))
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// The file's default units: plain numbers are in these.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FileUnits {
    pub length: &'static str,
    pub mass: &'static str,
}

impl Default for FileUnits {
    fn default() -> Self {
        FileUnits {
            length: "m",
            mass: "kg",
        }
    }
}

impl FileUnits {
    fn symbol(name: &str) -> Factor {
        SYMBOLS
            .iter()
            .find(|s| s.name == name)
            .map(|s| s.factor)
            .expect("file units are validated against LENGTH_UNITS and MASS_UNITS")
    }

    /// Factor from a plain number in file units of dimension `dim` to SI.
    /// Quantities involving time (ω in rad/s, α in rad/s², H in N·m·s, T in
    /// J) are always SI: the file's units name no unit of time. A velocity
    /// (`[analysis] velocity`) is in the file's length unit per second.
    pub fn factor(&self, dim: Dim) -> Factor {
        if dim.time != 0 && dim != Dim::VELOCITY {
            return Factor::ONE;
        }
        // NOTE: asked for every number a part file holds (~20 a part),
        // and made by a search of the symbol table and exact i128 powers
        // and gcds (18 % of reading a large file, perf): kept per thread
        // for the few (units, dimension) a file asks for. The same value
        // (`a_factor_kept_is_the_factor_made`).
        thread_local! {
            static MADE: std::cell::RefCell<Vec<(FileUnits, Dim, Factor)>> =
                const { std::cell::RefCell::new(Vec::new()) };
        }
        MADE.with(|made| {
            let found = made
                .borrow()
                .iter()
                .find(|(u, d, _)| u == self && *d == dim)
                .map(|&(_, _, f)| f);
            found.unwrap_or_else(|| {
                let f = self.factor_made(dim);
                let mut made = made.borrow_mut();
                if made.len() >= 32 {
                    made.clear();
                }
                made.push((*self, dim, f));
                f
            })
        })
    }

    /// `factor`, made from the symbol table.
    fn factor_made(&self, dim: Dim) -> Factor {
        let l = Self::symbol(self.length);
        let m = Self::symbol(self.mass);
        m.pow(dim.mass)
            .and_then(|f| l.pow(dim.length).and_then(|g| f.mul(g)))
            .expect("file-unit factors are small rationals")
    }

    /// How the inertia unit is written, e.g. `kg·mm²`.
    pub fn inertia_label(&self) -> String {
        format!("{}·{}²", self.mass, self.length)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_factor_kept_is_the_factor_made() {
        for length in LENGTH_UNITS {
            for mass in MASS_UNITS {
                let u = FileUnits { length, mass };
                for dim in [
                    Dim::LENGTH,
                    Dim::MASS,
                    Dim::DENSITY,
                    Dim::new(1, 2, 0),
                    Dim::new(0, -3, 0),
                ] {
                    // Asked twice: made, then kept.
                    assert_eq!(u.factor(dim), u.factor_made(dim), "{length} {mass} {dim:?}");
                    assert_eq!(u.factor(dim), u.factor_made(dim), "{length} {mass} {dim:?}");
                }
            }
        }
    }

    /// The spellings people type (issue 14): each the same unit as its
    /// canonical form, exactly.
    #[test]
    fn units_as_people_type_them() {
        let same = |a: &str, b: &str| {
            assert_eq!(parse_unit(a).unwrap(), parse_unit(b).unwrap(), "{a} vs {b}");
        };
        same("kg/m3", "kg/m^3");
        same("g/cm3", "g/cm^3");
        same("g cm^-3", "g/cm^3");
        same("g  cm^-3", "g/cm³");
        same("kg m^-3", "kg/m^3");
        same("kg/L", "g/cm^3");
        same("g/mL", "g/cm^3");
        same("rev/s", "Hz");
        let (oz, lb) = (parse_unit("oz").unwrap(), parse_unit("lb").unwrap());
        assert_eq!(oz.dim, lb.dim);
        assert!((16.0 * oz.factor.value() - lb.factor.value()).abs() <= 1e-16);
        assert_eq!(parse_unit("L").unwrap().dim, Dim::new(0, 3, 0));
        assert!(parse_unit("m5").is_err());
    }

    /// `quantity_pattern` joins the symbols unescaped, and reads a digit
    /// after one as its exponent.
    #[test]
    fn unit_symbols_are_letters_alone() {
        for s in symbol_names() {
            assert!(s.chars().all(char::is_alphabetic), "{s}");
        }
    }

    #[test]
    fn grams_per_cubic_centimetre_is_exactly_one_thousand_si() {
        assert_eq!(parse_quantity("7.85 g/cm^3", Dim::DENSITY), Ok(7850.0));
        assert_eq!(parse_quantity("1 g/cm³", Dim::DENSITY), Ok(1000.0));
    }

    #[test]
    fn inch_and_pound_are_the_defined_ones() {
        assert_eq!(parse_quantity("1 in", Dim::LENGTH), Ok(0.0254));
        assert_eq!(parse_quantity("1 ft", Dim::LENGTH), Ok(0.3048));
        assert_eq!(parse_quantity("1 lb", Dim::MASS), Ok(0.45359237));
        // 1 lb/in³ = 0.45359237 / 0.0254³ kg/m³, to one rounding.
        let v = parse_quantity("1 lb/in^3", Dim::DENSITY).unwrap();
        let exact = 0.45359237 / (0.0254f64 * 0.0254 * 0.0254);
        assert!((v - exact).abs() <= 4.0 * f64::EPSILON * exact);
    }

    #[test]
    fn millimetres_divide_rather_than_multiply_by_a_rounded_thousandth() {
        assert_eq!(parse_quantity("3 mm", Dim::LENGTH), Ok(3.0 / 1000.0));
        assert_eq!(parse_quantity("-2.5e3 mm", Dim::LENGTH), Ok(-2.5));
        assert_eq!(parse_quantity("3mm", Dim::LENGTH), Ok(0.003));
    }

    #[test]
    fn angular_units_convert_through_pi() {
        let rpm = parse_quantity("60 rpm", Dim::ANGULAR_VELOCITY).unwrap();
        assert!((rpm - 2.0 * std::f64::consts::PI).abs() < 1e-15);
        let deg = parse_quantity("180 deg/s", Dim::ANGULAR_VELOCITY).unwrap();
        assert!((deg - std::f64::consts::PI).abs() < 1e-15);
        assert_eq!(
            parse_quantity("2 rad/s^2", Dim::ANGULAR_ACCELERATION),
            Ok(2.0)
        );
        assert_eq!(parse_quantity("2 1/s", Dim::ANGULAR_VELOCITY), Ok(2.0));
    }

    #[test]
    fn wrong_dimension_is_rejected() {
        assert!(matches!(
            parse_quantity("3 kg", Dim::LENGTH),
            Err(UnitError::WrongDim { .. })
        ));
    }

    #[test]
    fn an_unknown_unit_in_capitals_suggests_the_same_letters_in_lowercase() {
        let cases = [
            ("180 MM", Dim::LENGTH, "mm"),
            ("2 KG", Dim::MASS, "kg"),
            ("3 IN", Dim::LENGTH, "in"),
        ];
        for (written, dim, meant) in cases {
            match parse_quantity(written, dim) {
                Err(UnitError::Unknown { suggestion, .. }) => {
                    assert_eq!(suggestion, Some(meant), "{written}")
                }
                other => panic!("{written}: {other:?}"),
            }
        }
    }

    #[test]
    fn of_two_candidates_alike_but_for_case_the_nearer_by_case_is_suggested() {
        assert_eq!(suggest("MG", ["mg", "Mg"]), Some("Mg"));
        assert_eq!(suggest("mG", ["Mg", "mg"]), Some("mg"));
    }

    #[test]
    fn unknown_unit_suggests_the_nearest() {
        match parse_quantity("3 mmm", Dim::LENGTH) {
            Err(UnitError::Unknown { suggestion, .. }) => assert_eq!(suggestion, Some("mm")),
            other => panic!("unexpected {other:?}"),
        }
    }

    #[test]
    fn malformed_strings_are_rejected() {
        assert_eq!(parse_quantity("mm", Dim::LENGTH), Err(UnitError::NoNumber));
        assert_eq!(parse_quantity("3", Dim::LENGTH), Err(UnitError::NoUnit));
        assert_eq!(
            parse_quantity("inf m", Dim::LENGTH),
            Err(UnitError::NoNumber)
        );
        assert_eq!(
            parse_quantity("1e999 m", Dim::LENGTH),
            Err(UnitError::NotFinite)
        );
        assert!(parse_quantity("3 kg/m/m", Dim::AREAL_DENSITY).is_err());
        assert!(parse_quantity("3 kg/m^", Dim::AREAL_DENSITY).is_err());
        // i32::MIN has no i32 absolute value: once a 2³¹-step loop (and a
        // panic in debug builds).
        assert!(parse_quantity("2 kg^-2147483648", Dim::MASS).is_err());
        assert!(parse_quantity("2 m^2147483647", Dim::LENGTH).is_err());
    }

    #[test]
    fn file_units_scale_plain_numbers() {
        let u = FileUnits {
            length: "mm",
            mass: "g",
        };
        // 1 g/mm³ = 1e-3 kg / 1e-9 m³ = 1e6 kg/m³.
        assert_eq!(u.factor(Dim::DENSITY).value(), 1e6);
        assert_eq!(u.factor(Dim::LENGTH).apply(5.0), 0.005);
        assert_eq!(u.factor(Dim::ANGULAR_VELOCITY), Factor::ONE);
        assert_eq!(u.factor(Dim::ENERGY), Factor::ONE);
        assert_eq!(u.factor(Dim::INERTIA).value(), 1e-9);
    }
}
