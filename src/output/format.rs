//! Everything about how a value looks, in one place: numbers to
//! significant digits for people, the shortest exact decimal for files
//! other programs read (`shortest`: robot descriptions), percentages, the
//! mark of an undefined ratio, the display unit of each dimension, and the
//! labels of conventions. Every table renderer takes its words and digits
//! from here; JSON prints full precision in SI and needs none of it.

use crate::analysis::Products;
use crate::compose::{EQUAL_MOMENT_RTOL, Precision};
use crate::units::{Dim, FileUnits};
use std::fmt::Write;

mod bytes;
mod rounded;
mod scaled;
pub use bytes::{
    ascii_name, ascii_name_width, count_len, extend_ascii_name, extend_count, extend_percent,
    extend_sig,
};

/// How an undefined ratio (a share of a zero moment, a change relative to
/// zero) is shown in every table.
pub const UNDEFINED: &str = "—";

/// The unit of a moment (torque), N·m: the dimension of an energy, J.
pub const MOMENT_UNIT: &str = "N·m";

/// The most characters of a name (a part's, a sub-assembly's, a
/// material's, a file's) that a table or a title shows; JSON has every
/// name whole.
pub const SHOWN_NAME: usize = 100;

/// Append a name from input as tables and titles show it: control
/// characters as their pictures (`diag::push_visible`: it cannot act on the
/// terminal or add a line), and at most `SHOWN_NAME` characters, the rest
/// cut with the length said (`abc… (20971520 characters)`). A 20 MB name
/// made every rule of its table 20 million columns wide.
pub fn push_name(out: &mut String, name: &str) {
    // Within the limit in bytes, within it in characters: one comparison
    // for almost every name.
    if name.len() <= SHOWN_NAME {
        return crate::diag::push_visible(out, name);
    }
    let n = name.chars().count();
    if n <= SHOWN_NAME {
        return crate::diag::push_visible(out, name);
    }
    let head = name
        .char_indices()
        .nth(SHOWN_NAME - 1)
        .map_or(name, |(i, _)| &name[..i]);
    crate::diag::push_visible(out, head);
    let _ = write!(out, "{}{n}{}", CUT[0], CUT[1]);
}

/// What follows a name cut to `SHOWN_NAME` characters, before and after
/// its length.
const CUT: [&str; 2] = ["… (", " characters)"];

/// `push_name` into a new string.
pub fn name(name: &str) -> String {
    let mut out = String::new();
    push_name(&mut out, name);
    out
}

/// A name from input at the start of a line (a report's title): as
/// `name` shows it, in backticks unless it begins with a letter or digit,
/// so that text from input never chooses how a line begins (`::error::…`
/// at the start of a line is a command to a CI runner; a name beginning
/// with a blank could pass for an indented line). A path is shown by
/// `diag::display_path`, which has its own rule (`./`).
pub fn line_name(text: &str) -> String {
    let shown = name(text);
    if shown.chars().next().is_some_and(char::is_alphanumeric) {
        shown
    } else {
        format!("`{shown}`")
    }
}

/// `x` to six significant digits: fixed notation for moderate magnitudes,
/// scientific otherwise, trailing zeros dropped.
pub fn fmt_num(x: f64) -> String {
    fmt_sig(x, 6)
}

/// Significant digits a table shows.
pub const SHOWN_DIGITS: i32 = 6;

/// `x` to the digits its error bound `bound` guarantees, judged against
/// `scale` (|x| for a value on its own; the largest entry for an entry of
/// a vector or tensor, which is read to the same resolution as the rest):
/// as `fmt_num` when the bound is within half a unit of the last digit
/// shown; rounded to the scale's last digit shown when the bound is within
/// half of that (`0` for a product of inertia that is zero within its
/// bound); else to the digits the bound leaves, with `± bound`.
pub fn fmt_bounded(x: f64, bound: f64, scale: f64) -> String {
    // A bound past f64 (made so by a unit's scale) is still a bound.
    let bound = bound.min(f64::MAX);
    // Decimal exponents as f64 (no overflow at the ends of the range): of
    // x's lead digit, and of the unit of the last digit shown of `of`.
    let lead = |v: f64| v.abs().log10().floor();
    let last_shown = |of: f64| lead(of) - f64::from(SHOWN_DIGITS - 1);
    let within = |of: f64| of != 0.0 && bound <= 0.5 * 10f64.powf(last_shown(of));
    if bound == 0.0 || !x.is_finite() || within(x) {
        return fmt_num(x);
    }
    // x rounded to a multiple of the unit 10^last, to the digits that are
    // left (0 when it rounds to nothing).
    let shown = |last: f64| {
        let unit = 10f64.powf(last);
        let y = (x / unit).round() * unit;
        if y == 0.0 || !y.is_finite() {
            if y.is_finite() {
                "0".to_string()
            } else {
                fmt_num(x)
            }
        } else {
            let digits = (lead(y) - last + 1.0).clamp(1.0, f64::from(SHOWN_DIGITS));
            fmt_sig(y, digits as usize)
        }
    };
    let top = scale.max(x.abs());
    if within(top) {
        return shown(last_shown(top));
    }
    // The last digit whose half unit covers the bound.
    let last = (2.0 * bound).log10().ceil();
    format!("{} ± {}", shown(last), fmt_bound(bound))
}

/// A bound to one significant digit, rounded up (a bound shown must still
/// bound); past 1e308 said so, not rounded to a number beyond f64.
fn fmt_bound(bound: f64) -> String {
    if bound > 9e307 {
        return ">9e307".to_string();
    }
    let e = bound.log10().floor();
    let unit = 10f64.powf(e);
    let digit = (bound / unit).ceil();
    // 10 × 10^e is 1 × 10^(e+1); a unit a rounding below the bound, one up.
    let mut up = digit * unit;
    if up < bound {
        up += unit;
    }
    fmt_sig(up, 1)
}

/// A fraction as a percentage to three significant digits (shares and
/// relative changes are read as orders of magnitude, not to six digits);
/// `None`, an undefined ratio, as `UNDEFINED`.
pub fn fmt_percent(fraction: Option<f64>) -> String {
    let mut s = String::new();
    push_percent(&mut s, fraction);
    s
}

/// Append `fmt_percent(fraction)` to `out`.
pub fn push_percent(out: &mut String, fraction: Option<f64>) {
    match percent(fraction) {
        Ok(p) => {
            push_sig(out, p, 3);
            out.push_str(" %");
        }
        Err(word) => out.push_str(word),
    }
}

/// A fraction as a percentage, or the words that stand for it: a ratio
/// beyond f64 as a percentage said, never `inf %`; `None` as `UNDEFINED`.
fn percent(fraction: Option<f64>) -> Result<f64, &'static str> {
    match fraction.map(|f| (f, f * 100.0)) {
        Some((_, p)) if p.is_finite() => Ok(p),
        Some((f, _)) if f > 0.0 => Err("> 1e306 %"),
        Some((f, _)) if f < 0.0 => Err("< -1e306 %"),
        _ => Err(UNDEFINED),
    }
}

/// `x` to `digits` significant digits (1 to 40), as `fmt_num`.
pub fn fmt_sig(x: f64, digits: usize) -> String {
    let mut s = String::new();
    push_sig(&mut s, x, digits);
    s
}

/// Append `fmt_sig(x, digits)` to `out`, without allocating.
///
/// NOTE: one `{:.N$e}` formatting gives the digits of both notations where
/// the fixed one keeps `digits` significant digits (exponent ≤ digits − 1,
/// always so for six): both round at the same decimal place. Above that the
/// fixed notation rounds to a whole number, a second formatting. The table
/// of 100,000 parts formats ~800,000 numbers.
pub fn push_sig(out: &mut String, x: f64, digits: usize) {
    debug_assert!((1..=40).contains(&digits), "the buffers hold 40 digits");
    // NOTE: almost every number: the same text from the shortest digits,
    // rounded (`rounded`: the table of 2²⁰ parts formats 18 million).
    if !rounded::push_sig_fast(out, x, digits.max(1) - 1) {
        push_sig_exact(out, x, digits);
    }
}

/// The length of `fmt_sig(x, digits)` (ASCII: its width in columns too),
/// from the rounded digits without writing them where `push_sig` writes
/// from those, else by writing it aside (zero, a tie of the shortest
/// digits, a number not normal).
pub fn sig_width(x: f64, digits: usize) -> usize {
    debug_assert!((1..=40).contains(&digits), "the buffers hold 40 digits");
    if x == 0.0 {
        // `push_sig_exact`'s `0`, either sign.
        return 1;
    }
    rounded::sig_len(x, digits.max(1) - 1).unwrap_or_else(|| {
        let mut s = String::new();
        push_sig_exact(&mut s, x, digits);
        s.len()
    })
}

/// The width in columns of `fmt_percent(fraction)`, without writing it.
pub fn percent_width(fraction: Option<f64>) -> usize {
    use unicode_width::UnicodeWidthStr;
    match percent(fraction) {
        Ok(p) => sig_width(p, 3) + " %".len(),
        Err(word) => word.width(),
    }
}

/// Whether `fmt_percent(fraction)` is ASCII (as wide as it is long): a
/// number, not `UNDEFINED`.
pub fn percent_is_ascii(fraction: Option<f64>) -> bool {
    percent(fraction).map_or_else(|word| word.is_ascii(), |_| true)
}

/// `push_sig` from the exact rounding (`{:.N$e}`): a tie of the shortest
/// digits, and the reference in the tests.
fn push_sig_exact(out: &mut String, x: f64, digits: usize) {
    if x == 0.0 {
        out.push('0');
        return;
    }
    if !x.is_finite() {
        // Unreachable through `summarize`, which refuses non-finite
        // results; printed honestly rather than panicking if it ever is.
        let _ = write!(out, "{x}");
        return;
    }
    let places = digits.max(1) - 1;
    let mut sci = Ascii::<64>::new();
    let _ = write!(sci, "{x:.places$e}");
    let sci = sci.as_str();
    let (mantissa, exp) = sci.split_once('e').expect("{:e} always has an exponent");
    let exp: i32 = exp.parse().expect("{:e} exponent is an integer");
    if !(-4..6).contains(&exp) {
        out.push_str(trim_zeros(mantissa));
        let _ = write!(out, "e{exp}");
        return;
    }
    let mut fixed = Ascii::<64>::new();
    if exp > places as i32 {
        let _ = write!(fixed, "{x:.0}");
    } else {
        let (sign, m) = match mantissa.strip_prefix('-') {
            Some(m) => ("-", m),
            None => ("", mantissa),
        };
        // m is "d" or "d.ddd…": `digits` digits.
        let (first, rest) = m.split_at(1);
        let rest = rest.strip_prefix('.').unwrap_or(rest);
        let _ = fixed.write_str(sign);
        if exp >= 0 {
            let e = exp as usize;
            let _ = fixed.write_str(first);
            let _ = fixed.write_str(&rest[..e]);
            if e < places {
                let _ = fixed.write_str(".");
                let _ = fixed.write_str(&rest[e..]);
            }
        } else {
            let _ = fixed.write_str("0.");
            for _ in 0..(-exp - 1) {
                let _ = fixed.write_str("0");
            }
            let _ = fixed.write_str(first);
            let _ = fixed.write_str(rest);
        }
    }
    out.push_str(trim_zeros(fixed.as_str()));
}

/// The shortest decimal that reads back as exactly `x`, for files another
/// program reads (robot descriptions): plain (`0.25`, `1200`) for
/// 1e-5 ≤ |x| < 1e16 and zero, else with an exponent (`1.5e-7`, `2e20`),
/// which C's `strtod`, `std::stod` and MuJoCo's parser all read. −0 is
/// written `0`: a file has no use for the sign of a zero.
///
/// NOTE: Rust's `{}` and `{:e}` print the shortest digits that round-trip
/// (Grisu with a Dragon4 fallback), so neither loses a bit nor adds a digit;
/// only the notation is chosen here. The plain range stops short of 1e16,
/// where `{}` would start writing zeros that are not digits of `x`, and of
/// 1e-5, below which it writes runs of leading zeros.
pub fn shortest(x: f64) -> String {
    let mut s = String::new();
    push_shortest(&mut s, x);
    s
}

/// Append `shortest(x)` to `out`.
pub fn push_shortest(out: &mut String, x: f64) {
    debug_assert!(x.is_finite(), "a non-finite number cannot be written: {x}");
    if x == 0.0 {
        out.push('0');
    } else if (1e-5..1e16).contains(&x.abs()) {
        let _ = write!(out, "{x}");
    } else {
        let _ = write!(out, "{x:e}");
    }
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

/// A fixed-size ASCII buffer on the stack for `write!`.
struct Ascii<const N: usize> {
    bytes: [u8; N],
    len: usize,
}

impl<const N: usize> Ascii<N> {
    fn new() -> Self {
        Ascii {
            bytes: [0; N],
            len: 0,
        }
    }

    fn as_str(&self) -> &str {
        std::str::from_utf8(&self.bytes[..self.len]).expect("only str is written")
    }
}

impl<const N: usize> Write for Ascii<N> {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let end = self.len + s.len();
        self.bytes
            .get_mut(self.len..end)
            .ok_or(std::fmt::Error)?
            .copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

/// The display units of a file: tables show mass, length and inertia in
/// the file's own units and the dynamics in SI. The one mapping from a
/// dimension to a display scale and label.
#[derive(Debug, Clone)]
pub struct DisplayUnits {
    /// SI per display unit.
    pub mass: f64,
    pub length: f64,
    pub inertia: f64,
    pub mass_label: &'static str,
    pub length_label: &'static str,
    pub inertia_label: String,
}

impl DisplayUnits {
    pub fn of(f: FileUnits) -> DisplayUnits {
        DisplayUnits {
            mass: f.factor(Dim::MASS).value(),
            length: f.factor(Dim::LENGTH).value(),
            inertia: f.factor(Dim::INERTIA).value(),
            mass_label: f.mass,
            length_label: f.length,
            inertia_label: f.inertia_label(),
        }
    }

    /// Scale (SI per display unit) and label of a value of dimension `dim`:
    /// the file's units for mass, length and inertia, SI for the rest.
    pub fn of_dim(&self, dim: Dim) -> (f64, &str) {
        match dim {
            Dim::MASS => (self.mass, self.mass_label),
            Dim::LENGTH => (self.length, self.length_label),
            Dim::INERTIA => (self.inertia, &self.inertia_label),
            Dim::ANGULAR_VELOCITY => (1.0, "rad/s"),
            Dim::ANGULAR_ACCELERATION => (1.0, "rad/s²"),
            Dim::ANGULAR_MOMENTUM => (1.0, "N·m·s"),
            // Also the dimension of a moment, which the report labels
            // with `MOMENT_UNIT` instead.
            Dim::ENERGY => (1.0, "J"),
            Dim::VELOCITY => (1.0, "m/s"),
            Dim::MOMENTUM => (1.0, "kg·m/s"),
            _ => (1.0, ""),
        }
    }

    /// `x` (SI) in display units with its unit, e.g. `12.5 mm`.
    pub fn show(&self, x: f64, dim: Dim) -> String {
        let (scale, unit) = self.of_dim(dim);
        let mut s = fmt_num(x / scale);
        if !unit.is_empty() {
            s.push(' ');
            s.push_str(unit);
        }
        s
    }
}

/// The line that says which sign convention products of inertia use.
pub fn products_label(p: Products) -> &'static str {
    match p {
        Products::Tensor => "tensor convention, Ixy = −∫xy dm",
        Products::Positive => "positive convention (CAD, Meriam), Ixy = +∫xy dm",
    }
}

/// The line that says which arithmetic was used.
pub fn precision_label(p: Precision) -> &'static str {
    match p {
        Precision::Standard => "standard (f64, compensated sums)",
        Precision::Extended => "extended (double-double, ~32 digits)",
    }
}

/// The note under a table of principal moments some of which are equal.
pub fn equal_note(out: &mut String, equal: &[usize]) {
    if !equal.is_empty() {
        let names: Vec<String> = equal.iter().map(|i| format!("I{}", i + 1)).collect();
        let _ = writeln!(
            out,
            "note: {} are equal within {EQUAL_MOMENT_RTOL:e} relative: their axes are not unique",
            names.join(" = "),
        );
    }
}

/// `x` (SI) in display units; should the conversion overflow (a value near
/// the limit of f64, shown in smaller units), the SI value, marked as such.
pub fn show_or_si(x: f64, factor: f64) -> String {
    let v = x / factor;
    if v.is_finite() {
        fmt_num(v)
    } else {
        format!("{} (SI)", fmt_num(x))
    }
}

/// A relative change as a percentage, to six significant digits as `diff`
/// shows it (`diff` is read for small changes; shares are read as orders
/// of magnitude, `fmt_percent`); beyond f64 as such, never `inf`.
pub fn change_percent(r: Option<f64>) -> String {
    match r.map(|r| r * 100.0) {
        Some(p) if p.is_finite() => format!("{} %", fmt_num(p)),
        Some(_) => "> 1e306 %".to_string(),
        None => UNDEFINED.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_that_would_begin_a_line_with_its_own_text_is_in_backticks() {
        assert_eq!(line_name("robot arm"), "robot arm");
        assert_eq!(line_name("部品"), "部品");
        assert_eq!(line_name("::error::x"), "`::error::x`");
        assert_eq!(line_name("\u{a0}::error::x"), "`\u{a0}::error::x`");
        assert_eq!(line_name("a\n::error::x"), "a\u{240a}::error::x");
        assert_eq!(line_name(""), "``");
    }

    #[test]
    fn a_value_shows_only_the_digits_its_bound_guarantees() {
        // Within half a unit of the sixth digit: all six.
        assert_eq!(fmt_bounded(0.1234567, 1e-12, 0.1234567), "0.123457");
        // An entry of a tensor read to its largest entry's resolution,
        // rounded there (9e-6 on a scale of 1 is 1e-5, not 0).
        assert_eq!(fmt_bounded(9e-6, 1e-11, 1.0), "1e-5");
        assert_eq!(fmt_bounded(3e-20, 1e-17, 0.5), "0");
        // Else the digits left, and the bound rounded up.
        assert_eq!(fmt_bounded(2.5e-18, 2.07e-15, 2.5e-18), "0 ± 3e-15");
        assert_eq!(fmt_bounded(1.0, 1.4e-3, 1.0), "1 ± 0.002");
        assert_eq!(fmt_bounded(123.456789, 0.3, 123.456789), "123 ± 0.3");
        // A bound beyond f64 is not printed as a number that reads as inf.
        assert!(fmt_bounded(1.0, f64::MAX, 1.0).ends_with("± >9e307"));
    }

    #[test]
    fn numbers_show_six_significant_digits() {
        assert_eq!(fmt_num(1.6625), "1.6625");
        assert_eq!(fmt_num(0.5501562), "0.550156");
        assert_eq!(fmt_num(-0.06644531), "-0.0664453");
        assert_eq!(fmt_num(123456.7), "123457");
        assert_eq!(fmt_num(1234567.0), "1.23457e6");
        assert_eq!(fmt_num(0.00001234567), "1.23457e-5");
        assert_eq!(fmt_num(0.0), "0");
        assert_eq!(fmt_num(2.0), "2");
    }

    #[test]
    fn percentages_show_three_significant_digits_and_a_dash_for_none() {
        assert_eq!(fmt_percent(Some(1.0 / 3.0)), "33.3 %");
        assert_eq!(fmt_percent(Some(1e-6)), "0.0001 %");
        assert_eq!(fmt_percent(Some(1.234_567e-9)), "1.23e-7 %");
        assert_eq!(fmt_percent(Some(1.0)), "100 %");
        assert_eq!(fmt_percent(Some(0.0)), "0 %");
        assert_eq!(fmt_percent(None), "—");
        // Never `inf %` or `NaN %`.
        assert_eq!(fmt_percent(Some(f64::MAX)), "> 1e306 %");
        assert_eq!(fmt_percent(Some(-f64::INFINITY)), "< -1e306 %");
        assert_eq!(fmt_percent(Some(f64::NAN)), "—");
    }

    /// `fmt_sig` formats once where it can; this reference, as it was,
    /// twice (`{:.N$e}`, then fixed). Rounding that bumps the exponent
    /// (9.999996 → 10.0000) and decimal ties (123456.5) included.
    #[test]
    fn one_formatting_gives_the_digits_of_two() {
        fn reference(x: f64, digits: usize) -> String {
            let trim = |s: &str| {
                if s.contains('.') {
                    s.trim_end_matches('0').trim_end_matches('.').to_string()
                } else {
                    s.to_string()
                }
            };
            if x == 0.0 {
                return "0".to_string();
            }
            let places = digits.max(1) - 1;
            let sci = format!("{x:.places$e}");
            let (mantissa, exp) = sci.split_once('e').unwrap();
            let exp: i32 = exp.parse().unwrap();
            if (-4..6).contains(&exp) {
                let decimals = (places as i32 - exp).max(0) as usize;
                trim(&format!("{x:.decimals$}"))
            } else {
                format!("{}e{exp}", trim(mantissa))
            }
        }
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut xs = vec![
            9.999995,
            9.999996,
            99999.95,
            999999.5,
            0.000099999995,
            123456.5,
            2.5,
            99.95,
            0.5,
        ];
        for _ in 0..50_000 {
            xs.push(f64::from_bits(next()));
            // Uniform in [0, 10) times 1e-6 … 1e7: the fixed range and its edges.
            let m = (next() >> 11) as f64 / (1u64 << 53) as f64 * 10.0;
            xs.push(m * 10f64.powi((next() % 14) as i32 - 6));
        }
        for x in xs.into_iter().filter(|x| x.is_finite()) {
            for digits in [1, 3, 6, 17] {
                assert_eq!(
                    super::fmt_sig(x, digits),
                    reference(x, digits),
                    "{x:e}, {digits}"
                );
                assert_eq!(
                    super::fmt_sig(-x, digits),
                    reference(-x, digits),
                    "{:e}, {digits}",
                    -x
                );
            }
        }
    }

    /// The significant digits of a number as written: no sign, exponent,
    /// point, leading zeros, or zeros that only place an integer's point.
    fn significant(s: &str) -> String {
        let mantissa = s.split('e').next().unwrap().trim_start_matches('-');
        let digits = if mantissa.contains('.') {
            mantissa.replace('.', "")
        } else {
            mantissa.trim_end_matches('0').to_string()
        };
        digits.trim_start_matches('0').to_string()
    }

    /// `shortest(x)` reads back as `x` to the bit, and has no digit more
    /// than needed: as many as `{:e}` (shortest round-trip) gives, and the
    /// correctly rounded decimal of one digit fewer reads back as another
    /// number.
    fn assert_shortest(x: f64) {
        let s = shortest(x);
        let back: f64 = s.parse().unwrap();
        let expected = if x == 0.0 { 0.0 } else { x };
        assert_eq!(back.to_bits(), expected.to_bits(), "{x:e} written {s}");
        let sci = format!("{x:e}");
        let n = significant(&sci).len();
        assert_eq!(significant(&s).len(), n, "{x:e} written {s}");
        if n > 1 {
            let places = n - 2;
            let fewer: f64 = format!("{x:.places$e}").parse().unwrap();
            assert_ne!(fewer.to_bits(), x.to_bits(), "{x:e} needs fewer digits");
        }
        let plain = x == 0.0 || (1e-5..1e16).contains(&x.abs());
        assert_eq!(!s.contains('e'), plain, "{x:e} written {s}");
    }

    #[test]
    fn the_shortest_decimal_of_random_bits_reads_back_exactly() {
        let mut state = 0x2545_F491_4F6C_DD1D_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut checked = 0;
        while checked < 100_000 {
            let x = f64::from_bits(next());
            if x.is_finite() {
                assert_shortest(x);
                checked += 1;
            }
        }
        // Moderate magnitudes too, where the plain form is used: random
        // bits are almost all far from 1.
        for _ in 0..20_000 {
            let m = (next() >> 11) as f64 / (1u64 << 53) as f64;
            assert_shortest(m * 10f64.powi((next() % 26) as i32 - 8));
        }
    }

    #[test]
    fn the_shortest_decimal_of_edge_values_reads_back_exactly() {
        let edges = [
            0.0,
            -0.0,
            f64::MAX,
            f64::MIN,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            f64::MIN_POSITIVE - f64::from_bits(1),
            f64::from_bits(1),
            f64::from_bits(0x000F_FFFF_FFFF_FFFF),
            f64::EPSILON,
            0.1,
            0.2 + 0.1,
            1.0 / 3.0,
            2.0 / 3.0,
            1e-5,
            1e-5 - 1e-21,
            1e16,
            1e16 - 2.0,
            9007199254740993.0,
        ];
        for x in edges {
            assert_shortest(x);
        }
    }

    #[test]
    fn the_shortest_decimal_is_plain_in_the_middle_and_exponent_at_the_ends() {
        assert_eq!(shortest(0.0), "0");
        assert_eq!(shortest(-0.0), "0");
        assert_eq!(shortest(0.1), "0.1");
        assert_eq!(shortest(-2.5), "-2.5");
        assert_eq!(shortest(1200.0), "1200");
        assert_eq!(shortest(1.0 / 3.0), "0.3333333333333333");
        assert_eq!(shortest(1e-5), "0.00001");
        assert_eq!(shortest(9.9e-6), "9.9e-6");
        assert_eq!(shortest(1.5e-7), "1.5e-7");
        assert_eq!(shortest(9999999999999998.0), "9999999999999998");
        assert_eq!(shortest(1e16), "1e16");
        assert_eq!(shortest(2e20), "2e20");
        assert_eq!(shortest(-2e20), "-2e20");
        assert_eq!(shortest(f64::MAX), "1.7976931348623157e308");
        assert_eq!(shortest(f64::from_bits(1)), "5e-324");
    }

    #[test]
    fn a_value_beyond_f64_in_display_units_is_shown_in_si() {
        assert_eq!(show_or_si(2.5e-3, 1e-3), "2.5");
        assert_eq!(show_or_si(1e308, 1e-3), "1e308 (SI)");
    }

    #[test]
    fn percentages_never_print_infinity() {
        assert_eq!(change_percent(Some(0.5)), "50 %");
        assert_eq!(change_percent(Some(f64::MAX)), "> 1e306 %");
        assert_eq!(change_percent(None), UNDEFINED);
    }

    #[test]
    fn a_name_past_the_limit_is_cut_with_its_length_and_one_within_is_whole() {
        let exact = "é".repeat(SHOWN_NAME);
        assert_eq!(name(&exact), exact);
        let long = format!("{exact}x");
        let shown = name(&long);
        assert_eq!(
            shown,
            format!(
                "{}… ({} characters)",
                "é".repeat(SHOWN_NAME - 1),
                SHOWN_NAME + 1
            )
        );
        // Control characters are shown as pictures, cut or not.
        assert_eq!(name("a\u{1b}[31mb\n"), "a\u{241b}[31mb\u{240a}");
        assert!(!name(&"\u{1b}".repeat(500)).contains('\u{1b}'));
    }
}
