//! An included file's parameters kept evaluated (`Base`), and a set of
//! `params` passed to it evaluated over them: only the parameters passed
//! and those that use them, so an include with `params` is parsed once
//! however many sets it is included with (`include::Parsed`).

use super::{Def, Given, Params, Pass, Quantity, RawParams, Recorder};
use crate::diag::{Diagnostic, Source};
use crate::expr::{Expr, Value};
use crate::model::Ctx;
use std::collections::BTreeMap;

/// A file's parameters as it defines them, evaluated once, with what uses
/// each: an included file converted again for another set of `params`
/// re-evaluates only the parameters passed and those that use them, at
/// any remove, not every one of them (`include::Parsed`).
pub(in crate::model) struct Base {
    values: std::sync::Arc<BTreeMap<String, Value>>,
    exprs: std::collections::HashMap<String, Expr>,
    users: std::collections::HashMap<String, Vec<String>>,
    /// Each parameter's place in an order in which it follows those it
    /// uses.
    rank: std::collections::HashMap<String, usize>,
}

impl Base {
    /// The parameters of the file `source` as its `[params]` defines them;
    /// `None` where they cannot be evaluated alone (an error that a set of
    /// `params` may mend) or have a tolerance (whose source belongs to
    /// each conversion): each set of `params` is then read in full.
    pub(in crate::model) fn of(source: &Source, raw: Option<&RawParams>) -> Option<Base> {
        let table = raw?;
        let mut ctx = Ctx {
            source,
            units: Default::default(),
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        let mut rec = Recorder::default();
        ctx.read_params(&mut rec, Some(table), &[]).ok()?;
        // NOTE: a parameter evaluated in double-double keeps its exact
        // value beside (`Params::exact`); such files, rare, are read in
        // full for each set of `params`, which keeps it.
        if !ctx.params.grads.is_empty() || !rec.sources.is_empty() || !ctx.params.exact.is_empty() {
            return None;
        }
        let mut defs: BTreeMap<&str, Def> = BTreeMap::new();
        let mut exprs: BTreeMap<&str, Expr> = BTreeMap::new();
        for (key, q) in table.get_ref() {
            let name = key.get_ref().as_str();
            if let Quantity::Text(t) = q.get_ref() {
                if crate::model::tolerance::split(t).is_some() {
                    return None;
                }
                exprs.insert(name, Expr::parse(t).ok()?);
            }
            defs.insert(name, Def::File(key.span(), q));
        }
        let order = ctx.order(&defs, &exprs).ok()?;
        let rank = order
            .iter()
            .enumerate()
            .map(|(i, n)| (n.to_string(), i))
            .collect();
        let mut users: std::collections::HashMap<String, Vec<String>> = Default::default();
        for (name, e) in &exprs {
            let mut used: Vec<&str> = e
                .names()
                .map(|(n, _)| n)
                .filter(|n| defs.contains_key(n))
                .collect();
            used.sort_unstable();
            used.dedup();
            for u in used {
                users
                    .entry(u.to_string())
                    .or_default()
                    .push(name.to_string());
            }
        }
        Some(Base {
            values: std::sync::Arc::new(std::mem::take(&mut ctx.params.values)),
            exprs: exprs.into_iter().map(|(k, e)| (k.to_string(), e)).collect(),
            users,
            rank,
        })
    }
}

impl Ctx<'_> {
    /// `read_params` for a file whose own parameters are `base`: the
    /// values passed, and the parameters that use them evaluated again,
    /// over the base. Anything out of the ordinary (a name the file does
    /// not define, `--set`, an error) is read again in full by
    /// `read_params`, so that its error is the one it always was.
    pub(in crate::model) fn read_params_over(
        &mut self,
        rec: &mut Recorder,
        raw: Option<&RawParams>,
        passed: &[Pass],
        base: &Base,
    ) -> Result<(), Diagnostic> {
        match over(passed, base) {
            Some(params) => {
                self.params = params;
                Ok(())
            }
            None => self.read_params(rec, raw, passed),
        }
    }
}

/// The parameters of `base` with the values `passed`, re-evaluating only
/// those that use a passed one; `None` if anything needs `read_params`.
fn over(passed: &[Pass], base: &Base) -> Option<Params> {
    let mut values = BTreeMap::new();
    for p in passed {
        let Given::Value(v) = &p.given else {
            return None;
        };
        if !base.rank.contains_key(&p.name) || p.exact.is_some() {
            return None;
        }
        values.insert(p.name.clone(), *v);
    }
    // A passed value replaces its definition: it is not evaluated again.
    let mut seen: std::collections::HashSet<&str> =
        passed.iter().map(|p| p.name.as_str()).collect();
    let mut stack: Vec<&str> = seen.iter().copied().collect();
    let mut affected = Vec::new();
    while let Some(n) = stack.pop() {
        for u in base.users.get(n).map_or(&[][..], Vec::as_slice) {
            if seen.insert(u) {
                affected.push(u.as_str());
                stack.push(u);
            }
        }
    }
    affected.sort_unstable_by_key(|n| base.rank[*n]);
    let mut params = Params {
        values,
        base: base.values.clone(),
        grads: BTreeMap::new(),
        set: BTreeMap::new(),
        exact: BTreeMap::new(),
    };
    for name in affected {
        let v = base.exprs[name]
            .eval(&|n| params.get(n), &|| params.names())
            .ok()?;
        // Through double-double: read in full, to keep its exact value.
        if let crate::expr::Num::Float(_) = v.num {
            return None;
        }
        params.values.insert(name.to_string(), v);
    }
    Some(params)
}
