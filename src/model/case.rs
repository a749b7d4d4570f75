//! `[[case]]`: the body in another state, each case the file as it would
//! be edited by hand — its `params` in place of the file's `[params]`
//! definitions (so they reach includes through their `params`, as the
//! file's own do), the parts and sub-assemblies it names `without` and the
//! `group`s it names `without_groups` taken out — with its own `expect`.
//!
//! NOTE: a case is converted from the file's raw tables again (`from_raw`
//! with the case's values in `[params]` and its `expect` as `[expect]`),
//! not patched into the base model: every key that uses a parameter, at
//! any depth, then takes the case's value exactly as a file that defines
//! it so would, bit for bit. `--set` replaces a definition the case gives
//! too (the command line wins). An included file's own cases are not
//! applied (only the file named is read for them).

use super::raw::{Params as RawParams, RawCase, RawFile};
use super::{Include, Item, Model, include, params};
use crate::diag::{Diagnostic, Source, shorten};
use crate::expr::Value;
use crate::units;
use std::ops::Range;
use std::sync::Arc;
use toml::Spanned;

/// One `[[case]]`, read and its body made.
#[derive(Debug, Clone)]
pub struct Case {
    pub name: String,
    /// The `[[case]]` table, and its `name`'s value.
    pub span: Range<usize>,
    pub name_span: Range<usize>,
    /// The parameters the case gives, in name order, each as the case
    /// evaluates it.
    pub params: Vec<Param>,
    /// `without` and `without_groups`, as written, each with its span.
    pub without: Vec<(String, Range<usize>)>,
    pub without_groups: Vec<(String, Range<usize>)>,
    /// Where the case's `expect` table is, if it has one.
    pub expect_span: Option<Range<usize>>,
    /// The body in this case; its `expect` is the case's `expect` (each
    /// check's span in the file), its `cases` none.
    pub model: Arc<Model>,
}

/// A parameter a case gives.
#[derive(Debug, Clone)]
pub struct Param {
    pub name: String,
    /// Its key in the case's `params`.
    pub span: Range<usize>,
    /// Its value, evaluated in the case (its dimension the definition's).
    pub value: Value,
    /// The value in SI (`Value::in_units` of 1).
    pub si: f64,
}

/// A value of dimension `like`'s, `si` in SI: for a parameter passed in
/// (`Model::parse_case`), such as one between two cases' values.
pub fn value_like(like: &Value, si: f64) -> Value {
    Value {
        dim: like.dim,
        ..Value::of_f64(si)
    }
}

impl Model {
    /// The file's cases (`raw.case`), each converted with the values
    /// `passed` (`--set`, then any passed in).
    pub(super) fn read_cases(
        source: &Source,
        raw: &mut RawFile,
        files: &mut include::Files,
        passed: &[params::Pass],
    ) -> Result<Vec<Case>, Diagnostic> {
        let Some(mut list) = raw.case.take() else {
            return Ok(Vec::new());
        };
        let mut out: Vec<Case> = Vec::new();
        let mut failed = None;
        for c in list.get_mut().iter_mut() {
            let span = c.span();
            let made = Model::read_case(source, raw, c.get_mut(), span, files, passed, &out);
            match made {
                Ok(case) => out.push(case),
                Err(d) => {
                    failed = Some(d);
                    break;
                }
            }
        }
        raw.case = Some(list);
        match failed {
            Some(d) => Err(d),
            None => Ok(out),
        }
    }

    fn read_case(
        source: &Source,
        raw: &mut RawFile,
        c: &mut RawCase,
        span: Range<usize>,
        files: &mut include::Files,
        passed: &[params::Pass],
        before: &[Case],
    ) -> Result<Case, Diagnostic> {
        let name = c
            .name
            .clone()
            .expect("invariant: the reader refuses a case without `name`");
        let (name, name_span) = (name.get_ref().clone(), name.span());
        let shown = shorten(&name);
        if let Some(first) = before.iter().find(|b| b.name == name) {
            let (line, col) = source.line_col(first.name_span.start);
            return Err(source
                .error(name_span, format!("a second case named `{shown}`"))
                .note(format!(
                    "the first is at {}:{line}:{col}; each case needs a name of its own",
                    source.name
                )));
        }
        let in_case = |d: Diagnostic| d.note(format!("in case `{shown}`"));
        let params = case_params(source, raw.params.as_ref(), c.params.as_ref(), &shown)?;
        let given: Vec<(String, Range<usize>)> = (c.params.iter())
            .flat_map(|p| p.get_ref().keys())
            .map(|k| (k.get_ref().clone(), k.span()))
            .collect();
        let expect = c.expect.take();
        let expect_span = expect.as_ref().map(Spanned::span);
        let saved_params = std::mem::replace(&mut raw.params, params);
        let saved_expect = std::mem::replace(&mut raw.expect, expect);
        let made = Model::from_raw(source, raw, files, passed, None);
        let values = match &made {
            Ok(_) => Model::context(source, raw, passed, None).map(|(ctx, _)| {
                (given.iter())
                    .filter_map(|(n, s)| {
                        let v = ctx.params.get(n)?;
                        let si = v.in_units(units::Factor::ONE);
                        Some(Param {
                            name: n.clone(),
                            span: s.clone(),
                            value: v,
                            si,
                        })
                    })
                    .collect::<Vec<_>>()
            }),
            Err(_) => Ok(Vec::new()),
        };
        c.expect = std::mem::replace(&mut raw.expect, saved_expect);
        raw.params = saved_params;
        let mut model = made.map_err(in_case)?;
        let params = values.map_err(in_case)?;
        let list = |l: &Option<Spanned<Vec<Spanned<String>>>>| -> Vec<(String, Range<usize>)> {
            (l.iter().flat_map(|l| l.get_ref()))
                .map(|s| (s.get_ref().clone(), s.span()))
                .collect()
        };
        let (without, without_groups) = (list(&c.without), list(&c.without_groups));
        // Each name found in the case's whole body first, then taken out.
        let mut paths = Vec::new();
        for (text, at) in &without {
            let path = model
                .item_path(text)
                .map_err(|e| source.error(at.clone(), format!("case `{shown}`: {e}")))?;
            paths.push(path);
        }
        let mut groups = Vec::new();
        for (text, at) in &without_groups {
            let path = model
                .group_path(text)
                .map_err(|e| source.error(at.clone(), format!("case `{shown}`: {e}")))?;
            groups.push(path);
        }
        for p in &paths {
            model = model.without(p);
        }
        for g in &groups {
            model = model.without_group(g);
        }
        if model.count == 0 {
            return Err(source.error(
                span,
                format!("case `{shown}` takes out every part of the body"),
            ));
        }
        model.cases = Vec::new();
        Ok(Case {
            name,
            span,
            name_span,
            params,
            without,
            without_groups,
            expect_span,
            model: Arc::new(model),
        })
    }

    /// The path of the part or sub-assembly `name` names: its own name at
    /// any depth, if one alone has it, or its path (`cargo / box[2]`); a
    /// copy is `name[i]`.
    fn item_path(&self, name: &str) -> Result<Vec<String>, String> {
        const LISTED: usize = 12;
        let (mut matching, mut listed, mut near) = (Vec::new(), Vec::new(), Vec::new());
        let mut total = 0usize;
        self.each_item(&mut Vec::new(), &mut |path| {
            total += 1;
            let joined = path.join(" / ");
            if path.last().is_some_and(|l| l == name) || joined == name {
                matching.push(path.to_vec());
            }
            if listed.len() < LISTED {
                listed.push(format!("`{}`", shorten(&joined)));
            }
            if joined.len() <= 4 * 1024 {
                near.push(joined);
            }
        });
        let shown = shorten(name);
        match matching.len() {
            1 => Ok(matching.pop().expect("one")),
            0 => {
                let more = total.saturating_sub(listed.len());
                let near = units::suggest(name, near.iter().map(String::as_str))
                    .map(|s| format!("; did you mean `{}`?", shorten(s)))
                    .unwrap_or_default();
                let more = if more > 0 {
                    format!(" and {more} more")
                } else {
                    String::new()
                };
                Err(format!(
                    "`without`: no part or sub-assembly `{shown}`{near} (the body has {}{more})",
                    listed.join(", ")
                ))
            }
            _ => {
                let names: Vec<String> = (matching.iter().take(LISTED))
                    .map(|p| format!("`{}`", shorten(&p.join(" / "))))
                    .collect();
                Err(format!(
                    "`without`: `{shown}` is ambiguous: {}; give the path",
                    names.join(", ")
                ))
            }
        }
    }

    /// Each part's and sub-assembly's path, parents before children; a
    /// part or sub-assembly with copies by its own name (all of them) and
    /// by each copy's, a sub-assembly's parts under each copy's.
    fn each_item(&self, path: &mut Vec<String>, f: &mut dyn FnMut(&[String])) {
        for (k, item) in self.items.iter().enumerate() {
            let (name, copies, inner) = named(k, item);
            path.push(name.clone());
            f(path);
            match copies {
                None => {
                    if let Some(m) = inner {
                        m.each_item(path, f);
                    }
                }
                Some(c) => {
                    for i in c.indices() {
                        let last = path.last_mut().expect("just pushed");
                        last.clear();
                        super::push_copy_name(last, &name, i);
                        f(path);
                        if let Some(m) = inner {
                            m.each_item(path, f);
                        }
                    }
                }
            }
            path.pop();
        }
    }

    /// This body without the part, sub-assembly or copy at `path` (one
    /// `item_path` found).
    fn without(&self, path: &[String]) -> Model {
        let Some((first, rest)) = path.split_first() else {
            return self.clone();
        };
        let mut items = Vec::with_capacity(self.items.len());
        for (k, item) in self.items.iter().enumerate() {
            let (name, copies, _) = named(k, item);
            if name == *first {
                match item {
                    Item::Include(inc) if !rest.is_empty() => {
                        items.push(Item::Include(Box::new(Include {
                            model: Arc::new(inc.model.without(rest)),
                            ..(**inc).clone()
                        })));
                    }
                    Item::Include(_) | Item::Part { .. } => {}
                }
                continue;
            }
            let copy = copies.and_then(|c| c.index_in(&name, first).map(|i| (c, i)));
            let Some((c, i)) = copy else {
                items.push(item.clone());
                continue;
            };
            // NOTE: the copies kept, each an item of its own (`keeping`):
            // the same bodies in the same frames, one term each.
            for j in c.indices() {
                let kept = Some(Box::new(c.keeping(j)));
                match item {
                    Item::Part { .. } if j == i => {}
                    Item::Part {
                        part, real, tag, ..
                    } => items.push(Item::Part {
                        part: part.clone(),
                        real: *real,
                        copies: kept,
                        tag: tag.clone(),
                    }),
                    Item::Include(_) if j == i && rest.is_empty() => {}
                    Item::Include(inc) => {
                        let model = match j == i {
                            true => Arc::new(inc.model.without(rest)),
                            false => inc.model.clone(),
                        };
                        items.push(Item::Include(Box::new(Include {
                            model,
                            copies: kept,
                            ..(**inc).clone()
                        })));
                    }
                }
            }
        }
        self.with_items(items)
    }

    /// The `group` path `text` names (`payload/camera`), if some part's
    /// group is it or lies under it.
    fn group_path(&self, text: &str) -> Result<Vec<String>, String> {
        let path: Vec<String> = text.split('/').map(|s| s.trim().to_string()).collect();
        let mut known: Vec<String> = Vec::new();
        self.each_group(&mut Vec::new(), &mut |g| {
            for n in 1..=g.len() {
                let joined = g[..n].join("/");
                if !known.contains(&joined) {
                    known.push(joined);
                }
            }
        });
        let joined = path.join("/");
        if known.contains(&joined) {
            return Ok(path);
        }
        let shown = shorten(text);
        let near = units::suggest(&joined, known.iter().map(String::as_str));
        let d = match (known.is_empty(), near) {
            (true, _) => {
                format!("`without_groups`: no group `{shown}`: no part of the body has a `group`")
            }
            (false, Some(n)) => format!(
                "`without_groups`: no group `{shown}`; did you mean `{}`?",
                shorten(n)
            ),
            (false, None) => {
                let listed: Vec<String> = (known.iter().take(12))
                    .map(|g| format!("`{}`", shorten(g)))
                    .collect();
                format!(
                    "`without_groups`: no group `{shown}` (the body has {})",
                    listed.join(", ")
                )
            }
        };
        Err(d)
    }

    /// Each part's whole group path (its sub-assemblies' groups first).
    fn each_group(&self, prefix: &mut Vec<String>, f: &mut dyn FnMut(&[String])) {
        for item in self.items.iter() {
            let (tag, inner) = match item {
                Item::Part { tag, .. } => (tag, None),
                Item::Include(inc) => (&inc.tag, Some(&inc.model)),
            };
            let own = tag.as_ref().and_then(|t| t.group.as_ref());
            let n = prefix.len();
            prefix.extend(own.iter().flat_map(|g| g.iter().cloned()));
            f(prefix);
            if let Some(m) = inner {
                m.each_group(prefix, f);
            }
            prefix.truncate(n);
        }
    }

    /// This body without the parts whose group is `group` or under it.
    fn without_group(&self, group: &[String]) -> Model {
        let mut items = Vec::with_capacity(self.items.len());
        for item in self.items.iter() {
            let (tag, inc) = match item {
                Item::Part { tag, .. } => (tag, None),
                Item::Include(inc) => (&inc.tag, Some(inc)),
            };
            let own: &[String] = tag.as_ref().and_then(|t| t.group.as_deref()).unwrap_or(&[]);
            if own.starts_with(group) {
                continue;
            }
            match inc {
                Some(inc) if group.starts_with(own) => {
                    let model = inc.model.without_group(&group[own.len()..]);
                    if model.count > 0 {
                        items.push(Item::Include(Box::new(Include {
                            model: Arc::new(model),
                            ..(**inc).clone()
                        })));
                    }
                }
                Some(_) | None => items.push(item.clone()),
            }
        }
        self.with_items(items)
    }

    /// This model with `items` for its own, its counts made again.
    fn with_items(&self, items: Vec<Item>) -> Model {
        let (mut count, mut has_real_sizes) = (0, false);
        for item in &items {
            match item {
                Item::Part { real, copies, .. } => {
                    count += copies.as_ref().map_or(1, |c| c.indices().len());
                    has_real_sizes |= real.is_some();
                }
                Item::Include(inc) => {
                    count += inc.model.count * inc.copies.as_ref().map_or(1, |c| c.indices().len());
                    has_real_sizes |= inc.model.has_real_sizes;
                }
            }
        }
        Model {
            group_depth: super::budget::group_depth(&items),
            items: Arc::new(items),
            count,
            has_real_sizes,
            ..self.clone()
        }
    }
}

/// An item's name in its file (a part the file does not name: `part N`),
/// its copies, and a sub-assembly's model.
fn named(k: usize, item: &Item) -> (String, Option<&super::Copies>, Option<&Model>) {
    match item {
        Item::Part { part, copies, .. } => {
            let name = match part.named {
                true => part.name.clone(),
                false => format!("part {}", k + 1),
            };
            (name, copies.as_deref(), None)
        }
        Item::Include(inc) => (inc.name.clone(), inc.copies.as_deref(), Some(&inc.model)),
    }
}

/// The file's `[params]` with a case's values in place of its
/// definitions; a parameter the file does not define is refused at its
/// key.
fn case_params(
    source: &Source,
    file: Option<&RawParams>,
    case: Option<&RawParams>,
    shown: &str,
) -> Result<Option<RawParams>, Diagnostic> {
    let Some(case) = case else {
        return Ok(file.cloned());
    };
    let mut out = file.cloned();
    for (k, v) in case.get_ref() {
        let defined = file.map(|f| f.get_ref().keys().map(|k| k.get_ref().as_str()));
        let has = file.is_some_and(|f| f.get_ref().keys().any(|d| d.get_ref() == k.get_ref()));
        if !has {
            let near = defined.and_then(|d| units::suggest(k.get_ref(), d));
            let d = source.error(
                k.span(),
                format!(
                    "case `{shown}` gives the parameter `{}`, which `[params]` does not define",
                    shorten(k.get_ref())
                ),
            );
            return Err(match (file, near) {
                (None, _) => d.help("a case's `params` replace the file's `[params]` definitions: define it there first"),
                (Some(_), near) => d.suggest(near),
            });
        }
        let map = out
            .as_mut()
            .expect("defined, so `[params]` is there")
            .get_mut();
        map.retain(|d, _| d.get_ref() != k.get_ref());
        map.insert(k.clone(), v.clone());
    }
    Ok(out)
}
