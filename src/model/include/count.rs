//! The parts a body holds with its includes, counted before any include
//! is expanded (`Ctx::check_part_count`): a body past `MAX_PARTS` is
//! refused before it is built.

use super::{Files, MAX_INCLUDE_DEPTH, Parsed};
use crate::diag::Diagnostic;
use crate::model::raw::RawPart;
use crate::model::{Ctx, Model};
use toml::Spanned;

impl Ctx<'_> {
    /// Refuse a body of more than `MAX_PARTS` parts before any include is
    /// expanded: the parts of `raw_parts` counted with every file they
    /// include, each file read and counted once however often it is
    /// included. A binary tree of 32 files describing 2³¹ parts was
    /// refused only once 2²¹ of them had been built, after 7 GB.
    ///
    /// NOTE: an included file that includes others is parsed here and
    /// again when it is expanded; one that includes nothing (most, and the
    /// large ones) has its `[[part]]` lines counted, not parsed (parsing
    /// every included file twice cost 40 % on a file that includes one of
    /// 60,000 parts). Either count may miss parts written otherwise (a
    /// `part = [...]` array) or count a `[[part]]` line inside a multi-line
    /// string: the limit is enforced exactly again as parts are expanded.
    /// An include that cannot be counted (any error, a cycle) counts as one
    /// part: expanding it reports the error where it is.
    pub(in crate::model) fn check_part_count(
        &self,
        raw_parts: &[Spanned<RawPart>],
        files: &mut Files,
    ) -> Result<(), Diagnostic> {
        if !raw_parts.iter().any(|p| p.get_ref().include.is_some()) {
            return Ok(());
        }
        let max = crate::model::MAX_PARTS as u64;
        let mut total = 0u64;
        for p in raw_parts {
            // Its copies (`array`, `mirror`) count it again each.
            let copies = crate::model::copies::raw_multiplicity(p.get_ref());
            let Some(inc) = &p.get_ref().include else {
                total = total.saturating_add(copies);
                continue;
            };
            let (n, shown) = match self.count_include(inc, files) {
                Some((n, shown)) => (n, shown),
                None => (1, String::new()),
            };
            let n = n.saturating_mul(copies);
            total = total.saturating_add(n);
            if total > max {
                // A count that saturated is past u64.
                let said = |n: u64| match n {
                    u64::MAX => "more than 2⁶⁴".to_string(),
                    n => n.to_string(),
                };
                return Err(self
                    .err(
                        inc.span(),
                        format!(
                            "with this include the body has {} parts, past the limit of {max}: `{shown}` holds {} with its includes",
                            said(total),
                            said(n)
                        ),
                    )
                    .help("each copy of a sub-assembly counts its parts again"));
            }
        }
        Ok(())
    }

    /// The parts the file `inc` names holds with its includes, and its name
    /// as shown; `None` if it cannot be counted.
    fn count_include(&self, inc: &Spanned<String>, files: &mut Files) -> Option<(u64, String)> {
        let t = self.target(inc, files).ok()?;
        if let Some(n) = files.counts.get(&t.canonical) {
            return Some((*n, t.shown_name));
        }
        if files.stack.len() >= MAX_INCLUDE_DEPTH
            || files.stack.iter().any(|(c, _)| *c == t.canonical)
        {
            return None;
        }
        files.read.push(t.canonical.clone());
        let bytes = std::fs::read(&t.shown).ok()?;
        let source = crate::io::source_of(&t.shown_name, bytes)
            .ok()?
            .read_from(t.shown.clone());
        // A file that includes nothing holds its `[[part]]` tables: counted
        // from the text, not parsed (it is parsed when it is expanded).
        if !["include", "array", "mirror"]
            .iter()
            .any(|k| source.text.contains(k))
        {
            let n = crate::model::part_tables(&source.text);
            files.counts.insert(t.canonical, n);
            return Some((n, t.shown_name));
        }
        files.reads += 1;
        let raw = Model::raw(&source).ok()?;
        // Kept, not parsed again when it is expanded, if it has parameters.
        let (raw, kept) = match raw.params {
            Some(_) => {
                let kept = Parsed::keep(source.clone(), raw);
                files.parsed.insert(t.canonical.clone(), kept.clone());
                (None, Some(kept))
            }
            None => (Some(raw), None),
        };
        let raw = raw.as_ref().or(kept.as_ref().map(|k| &k.raw))?;
        let child = Ctx {
            source: &source,
            units: Default::default(),
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        files
            .stack
            .push((t.canonical.clone(), t.shown_name.clone()));
        let n = raw.part.as_ref().map_or(0, |parts| {
            parts.get_ref().iter().fold(0u64, |n, p| {
                let copies = crate::model::copies::raw_multiplicity(p.get_ref());
                n.saturating_add(copies.saturating_mul(match &p.get_ref().include {
                    None => 1,
                    Some(inc) => child.count_include(inc, files).map_or(1, |(n, _)| n),
                }))
            })
        });
        files.stack.pop();
        files.counts.insert(t.canonical, n);
        Some((n, t.shown_name))
    }
}
