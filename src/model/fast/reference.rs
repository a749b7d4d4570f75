//! The reader against the reference parser (the toml crate's spanned
//! tree, `toml::de::DeTable`), for the tests, the property test
//! (tests/integration/hostile.rs) and the fuzz target: where the reader
//! reads a file, the reference parser accepts it, and every scalar it
//! finds is in the `RawFile` at the same span with the same value (or, for
//! an element the `RawFile` keeps without a span, in its array at that
//! array's span).

use super::read_file;
use std::ops::Range;
use toml::de::{DeTable, DeValue};

/// What a leaf is checked by: its span, its value's forms in a
/// `RawFile`'s `Debug`, the span of the outermost array it is in.
type Leaf<'f> = dyn FnMut(Range<usize>, Vec<String>, Option<&Range<usize>>) + 'f;

/// `Ok` where the reader reads `text` as the reference parser does, or
/// refuses it; why not otherwise.
#[doc(hidden)]
pub fn agrees(text: &str) -> Result<(), String> {
    let Some(fast) = read_file(text) else {
        return Ok(());
    };
    let debug = format!("{fast:?}");
    let root = DeTable::parse(text).map_err(|e| {
        format!("the reader reads a file the reference parser refuses: {e}\n{text}")
    })?;
    let mut missing = None;
    visit(
        &DeValue::Table(root.into_inner()),
        None,
        &mut |span, forms, array| {
            let at = |a: &Range<usize>, f: &str| {
                debug.contains(&format!("span: {}..{}, value: {f}", a.start, a.end))
            };
            let read = forms.iter().any(|f| at(&span, f));
            let kept_whole = array.is_some_and(|a| ["Three(", "Many("].iter().any(|f| at(a, f)));
            if !read && !kept_whole && missing.is_none() {
                missing = Some(format!("{span:?} as {forms:?} not read:\n{text}\n{debug}"));
            }
        },
    );
    missing.map_or(Ok(()), Err)
}

fn visit(v: &DeValue<'_>, array: Option<Range<usize>>, f: &mut Leaf<'_>) {
    match v {
        DeValue::Table(t) => {
            for (_, v) in t.iter() {
                scalar(v, None, f);
            }
        }
        DeValue::Array(a) => {
            for v in a.iter() {
                scalar(v, array.clone(), f);
            }
        }
        DeValue::String(_)
        | DeValue::Integer(_)
        | DeValue::Float(_)
        | DeValue::Boolean(_)
        | DeValue::Datetime(_) => {}
    }
}

fn scalar(v: &toml::Spanned<DeValue<'_>>, array: Option<Range<usize>>, f: &mut Leaf<'_>) {
    let span = v.span();
    let number = |x: f64| {
        vec![
            format!("Number({x:?})"),
            format!("{x:?}"),
            format!("One({x:?})"),
            format!("One(Number({x:?}))"),
        ]
    };
    let forms = match v.get_ref() {
        DeValue::Integer(i) => {
            let r = i.radix();
            match i64::from_str_radix(i.as_str(), r)
                .map(|i| i as f64)
                .or_else(|_| u64::from_str_radix(i.as_str(), r).map(|u| u as f64))
            {
                Ok(x) => number(x),
                // Beyond 64 bits: no key takes it, so never read.
                Err(_) => vec!["an integer beyond 64 bits".into()],
            }
        }
        DeValue::Float(x) => match x.as_str().parse::<f64>() {
            Ok(x) => number(x),
            Err(_) => vec!["a float".into()],
        },
        DeValue::String(s) => vec![
            format!("Text({s:?})"),
            format!("{s:?}"),
            format!("One(Text({s:?}))"),
        ],
        DeValue::Boolean(b) => vec![format!("{b}")],
        DeValue::Datetime(_) => vec!["a date-time".into()],
        // An element kept without a span is in its outermost array.
        DeValue::Array(_) => return visit(v.get_ref(), Some(array.unwrap_or(span)), f),
        DeValue::Table(_) => return visit(v.get_ref(), None, f),
    };
    f(span, forms, array.as_ref());
}
