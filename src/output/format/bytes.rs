//! Text written straight into a byte buffer (the `--full` tables' rows,
//! issue 33 item 3): the same bytes as `push_sig`, `push_percent` and
//! `push_name` write, without a `String` between.

use super::{CUT, SHOWN_NAME, percent, push_sig_exact, rounded};

/// How `push_name` shows a name of printable ASCII without the runner's
/// command prefix (`diag::LEGACY_COMMAND`), known without counting its
/// characters (each is a byte): whole, or its first `SHOWN_NAME` − 1 bytes
/// and its length (`… (n characters)` after them). `None` for any other
/// name.
pub fn ascii_name(name: &str) -> Option<(&str, Option<usize>)> {
    if !name.bytes().all(|b| (0x20..0x7f).contains(&b))
        || name.contains(crate::diag::LEGACY_COMMAND)
    {
        return None;
    }
    Some(if name.len() <= SHOWN_NAME {
        (name, None)
    } else {
        (&name[..SHOWN_NAME - 1], Some(name.len()))
    })
}

/// The columns `push_name` takes for an `ascii_name`.
pub fn ascii_name_width((head, cut): (&str, Option<usize>)) -> usize {
    use unicode_width::UnicodeWidthStr;
    head.len() + cut.map_or(0, |n| CUT[0].width() + count_len(n) + CUT[1].len())
}

/// `push_name`'s text of an `ascii_name`, after bytes.
pub fn extend_ascii_name(out: &mut Vec<u8>, (head, cut): (&str, Option<usize>)) {
    out.extend_from_slice(head.as_bytes());
    if let Some(n) = cut {
        out.extend_from_slice(CUT[0].as_bytes());
        extend_count(out, n);
        out.extend_from_slice(CUT[1].as_bytes());
    }
}

/// `n` in decimal after bytes, as `{n}` writes it.
pub fn extend_count(out: &mut Vec<u8>, mut n: usize) {
    let mut digits = [0u8; 20];
    let mut k = digits.len();
    loop {
        k -= 1;
        digits[k] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend_from_slice(&digits[k..]);
}

/// The length of `n` in decimal.
pub fn count_len(mut n: usize) -> usize {
    let mut len = 1;
    while n >= 10 {
        n /= 10;
        len += 1;
    }
    len
}

/// `push_sig` after bytes: the digits written straight after `out`.
pub fn extend_sig(out: &mut Vec<u8>, x: f64, digits: usize) {
    if x == 0.0 {
        out.push(b'0');
    } else if !rounded::extend_sig_fast(out, x, digits.max(1) - 1) {
        let mut s = String::new();
        push_sig_exact(&mut s, x, digits);
        out.extend_from_slice(s.as_bytes());
    }
}

/// `push_percent` after bytes.
pub fn extend_percent(out: &mut Vec<u8>, fraction: Option<f64>) {
    match percent(fraction) {
        Ok(p) => {
            extend_sig(out, p, 3);
            out.extend_from_slice(b" %");
        }
        Err(word) => out.extend_from_slice(word.as_bytes()),
    }
}
