//! `[params]`: a file's named quantities, evaluated once in the order
//! their uses need (any order in the file; a cycle is an error), with the
//! values given from outside: `--set NAME=VALUE` for the file named on the
//! command line, `params = { … }` on an include for the file it includes.
//! And the one place an expression in a quantity string is evaluated for a
//! key (`Ctx::expression`), its errors located at the token inside the
//! string.

use super::Ctx;
use super::raw::{Params as RawParams, Quantity};
use super::tolerance::{Index, Recorder};
use crate::diag::{Diagnostic, Source};
use crate::expr::big::Big;
use crate::expr::tangent::{Grad, axpy};
use crate::expr::{self, Expr, Value};
use crate::units::{self, Dim, Factor};
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

mod over;
mod set;
pub(super) use over::Base;

/// A file's parameters, evaluated.
#[derive(Clone, Debug, Default)]
pub(crate) struct Params {
    values: BTreeMap<String, Value>,
    /// The file's own values, shared by every set of `params` it is
    /// included with (`Base`); `values` then holds those that differ.
    base: std::sync::Arc<BTreeMap<String, Value>>,
    /// How the parameters with a tolerance (their own, or of the
    /// parameters they use) move with the file's sources (SI per z).
    grads: BTreeMap<String, Grad>,
    /// The parameters `--set` gives, each with the note an error it may
    /// have caused carries (`Params::blame_set`).
    set: BTreeMap<String, String>,
    /// The exact value of each parameter evaluated in double-double that
    /// is rational after all (`Expr::exact`): the expressions that use it
    /// round to the nearest f64 of their exact value too.
    exact: BTreeMap<String, Big>,
}

impl Params {
    pub(crate) fn get(&self, name: &str) -> Option<Value> {
        self.values
            .get(name)
            .or_else(|| self.base.get(name))
            .copied()
    }

    /// A parameter's exact value, where it is known.
    fn exact_of(&self, name: &str) -> Option<Big> {
        match self.get(name)?.num {
            expr::Num::Exact(q) => Some(Big::of(q)),
            expr::Num::Float(_) => self.exact.get(name).cloned(),
        }
    }

    /// The nearest f64 of `e`'s value `v` in units of `factor`: `v`'s own
    /// rounding, or where `v` went through double-double, its exact value
    /// rounded once, if it is rational.
    fn nearest(&self, e: &Expr, v: Value, factor: Factor) -> f64 {
        let x = v.in_units(factor);
        if let expr::Num::Float(_) = v.num
            && let Some(b) = e.exact(&|n| self.exact_of(n))
            && let (n, d, pi) = factor.parts()
            && let Some(y) = b.nearest_over(n, d, pi)
        {
            return y;
        }
        x
    }

    /// `v`, the value of `e`, exactly if it went through double-double and
    /// is rational.
    fn exact_value(&self, e: Option<&Expr>, v: Value) -> Option<Big> {
        match v.num {
            expr::Num::Exact(_) => None,
            expr::Num::Float(x) => match e {
                Some(e) => e.exact(&|n| self.exact_of(n)),
                None => Big::of_f64(x.hi + x.lo).filter(|_| x.lo == 0.0),
            },
        }
    }

    /// A parameter's value and gradient (empty without a tolerance).
    fn with_grad(&self, name: &str) -> Option<(Value, Grad)> {
        let v = self.get(name)?;
        Some((v, self.grads.get(name).cloned().unwrap_or_default()))
    }

    /// The gradient of an expression evaluated in these parameters (empty
    /// when none of them has a tolerance).
    fn grad_of(&self, e: &Expr) -> Grad {
        if self.grads.is_empty() || !e.names().any(|(n, _)| self.grads.contains_key(n)) {
            return Grad::new();
        }
        e.tangent(&|n| self.with_grad(n))
    }

    fn is_empty(&self) -> bool {
        self.values.is_empty() && self.base.is_empty()
    }

    fn names(&self) -> Vec<String> {
        let mut names: Vec<String> = self.values.keys().cloned().collect();
        names.extend(
            self.base
                .keys()
                .filter(|k| !self.values.contains_key(*k))
                .cloned(),
        );
        names.sort_unstable();
        names
    }

    /// `d`, located at `span` of `file`, with a note for each parameter
    /// given by `--set` that the span's text names (`["leg", 0, 0]`): an
    /// error there may be the flag's doing, not the file's. A span of
    /// several lines (a whole table) is not read: what it names need not
    /// be what failed.
    pub(super) fn blame_set(
        &self,
        file: &str,
        span: Range<usize>,
        mut d: Diagnostic,
    ) -> Diagnostic {
        if self.set.is_empty() {
            return d;
        }
        let Some(text) = file.get(span).filter(|t| !t.contains('\n')) else {
            return d;
        };
        let mut named: Vec<&str> = text
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .filter(|w| self.set.contains_key(*w))
            .collect();
        named.sort_unstable();
        named.dedup();
        for n in named {
            d = d.note(self.set[n].clone());
        }
        d
    }
}

/// A parameter given from outside a file.
#[derive(Clone, Debug)]
pub(crate) struct Pass {
    pub(crate) name: String,
    pub(crate) given: Given,
    /// The error if the file does not define `name` (located where it was
    /// given: the flag, or the include's key).
    pub(crate) undefined: Diagnostic,
    /// A passed value's exact value, where it went through double-double
    /// and is rational (`Params::exact`).
    pub(crate) exact: Option<Big>,
}

#[derive(Clone, Debug)]
pub(crate) enum Given {
    /// `--set NAME=VALUE`: VALUE replaces the definition, read in the
    /// file's own parameters (so it may use them); the source is VALUE,
    /// named after the flag.
    Set(Source),
    /// An include's `params`: a value, read in the including file.
    Value(Value),
}

impl Pass {
    /// `value` passed in for the parameter `name` (`Model::parse_passing`).
    pub(crate) fn value(name: &str, value: Value) -> Pass {
        Pass {
            name: name.to_string(),
            given: Given::Value(value),
            undefined: Diagnostic::plain(format!(
                "the file defines no parameter `{}` in `[params]`",
                crate::diag::shorten(name)
            )),
            exact: None,
        }
    }
}

/// `--set NAME=VALUE` flags as passes; a flag without `=`, or with a name
/// that cannot be a parameter's, is an error.
pub(crate) fn flags(set: &[String]) -> Result<Vec<Pass>, Diagnostic> {
    let mut out: Vec<Pass> = Vec::new();
    for flag in set {
        let Some((name, value)) = flag.split_once('=') else {
            return Err(Diagnostic::plain(format!(
                "invalid value {flag:?} for `--set`: expected NAME=VALUE, such as `--set leg=\"700 mm\"`"
            )));
        };
        let name = name.trim();
        // `--set 'leg="700 mm"'`: the quotes of TOML taken off.
        let value = value.trim();
        let value = ['"', '\'']
            .iter()
            .find_map(|q| value.strip_prefix(*q).and_then(|v| v.strip_suffix(*q)))
            .unwrap_or(value);
        // NOTE: a name that cannot be a parameter's (`base-d`) is refused
        // by the file that defines none such (`Ctx::read_params`), where
        // its parameters' names can be suggested.
        if name.is_empty() {
            return Err(Diagnostic::plain(format!(
                "invalid value {flag:?} for `--set`: no parameter name before `=`"
            ))
            .help("expected NAME=VALUE, such as `--set leg=\"700 mm\"`"));
        }
        if out.iter().any(|p| p.name == name) {
            return Err(Diagnostic::plain(format!("`--set {name}` is given twice")));
        }
        out.push(Pass {
            name: name.to_string(),
            given: Given::Set(Source::new(format!("--set {name}"), value)),
            undefined: Diagnostic::plain(format!(
                "`--set {name}`: the file defines no parameter `{name}` in `[params]`"
            )),
            exact: None,
        });
    }
    Ok(out)
}

/// What tells two sets of passed values apart (an include's cache key):
/// each name and its exact value.
pub(super) fn cache_key(passes: &[Pass]) -> String {
    let mut key = String::new();
    for p in passes {
        if let Given::Value(v) = &p.given {
            key.push_str(&format!("{}={v:?};", p.name));
        }
    }
    key
}

impl Ctx<'_> {
    /// An include's `params`, each value read here (in this file's
    /// parameters) and passed as a value; a name the included file
    /// (`shown`) does not define is an error at its key.
    pub(super) fn include_params(
        &self,
        table: &RawParams,
        shown: &str,
    ) -> Result<Vec<Pass>, Diagnostic> {
        let mut out = Vec::new();
        for (key, q) in table.get_ref() {
            let name = key.get_ref();
            if !expr::is_name(name) {
                return Err(self.err(key.span(), format!("`{name}` is not a parameter name")));
            }
            let exact;
            let value = match q.get_ref() {
                Quantity::Number(x) => {
                    let v = self.number_param(q, *x, &format!("parameter `{name}`"))?;
                    exact = self.params.exact_value(None, v);
                    v
                }
                Quantity::Text(t) => {
                    let what = format!("parameter `{name}`");
                    // NOTE: a tolerance's source belongs to one file's
                    // instance; carried into another file it would need
                    // the including instance's key. Refused, not dropped.
                    if let Some((_, _, at)) = super::tolerance::split(t) {
                        return Err(self
                            .not_allowed(self.source, q.span(), t, at, "params")
                            .help("a tolerance cannot be passed to an included file yet: give it in that file's `[params]`"));
                    }
                    let e = Expr::parse(t).map_err(|e| self.located_here(q, t, e, &what))?;
                    let params = &self.params;
                    let v = e
                        .eval(&|n| params.get(n), &|| params.names())
                        .map_err(|e| self.located_here(q, t, e, &what))?;
                    if !params.grad_of(&e).is_empty() {
                        return Err(self
                            .err(
                                q.span(),
                                format!("{what} uses a parameter with a tolerance, which cannot be passed to an included file yet"),
                            )
                            .help("give the tolerance in the included file's `[params]`"));
                    }
                    exact = self.params.exact_value(Some(&e), v);
                    v
                }
            };
            out.push(Pass {
                name: name.clone(),
                given: Given::Value(value),
                undefined: self.err(
                    key.span(),
                    format!("`params`: the included `{shown}` defines no parameter `{name}`"),
                ),
                exact,
            });
        }
        Ok(out)
    }
}

/// One parameter's definition, as read.
enum Def<'a> {
    /// In the file: the key's span and its value.
    File(Range<usize>, &'a Spanned<Quantity>),
    /// `--set`, with the definition it replaces.
    Set(&'a Source, Option<(Range<usize>, &'a Spanned<Quantity>)>),
    Value(Value),
}

/// `--set NAME=VALUE` as given (the value without its quotes).
fn flag(name: &str, source: &Source) -> String {
    format!("--set {name}={}", source.text)
}

impl Ctx<'_> {
    /// Read `[params]` (if any) with the values passed in, into
    /// `self.params` (a parameter's tolerance recorded in `rec`, as a
    /// source shared by every key that uses it).
    pub(super) fn read_params(
        &mut self,
        rec: &mut Recorder,
        raw: Option<&RawParams>,
        passed: &[Pass],
    ) -> Result<(), Diagnostic> {
        if raw.is_none() && passed.is_empty() {
            return Ok(());
        }
        let mut defs: BTreeMap<&str, Def> = BTreeMap::new();
        if let Some(table) = raw {
            for (key, value) in table.get_ref() {
                let name = key.get_ref().as_str();
                if !expr::is_name(name) {
                    return Err(self
                        .err(key.span(), format!("`{name}` is not a parameter name"))
                        .help("a name is a letter or `_`, then letters, digits and `_`"));
                }
                if let Some(what) = expr::reserved(name) {
                    return Err(self
                        .err(
                            key.span(),
                            format!("the parameter `{name}` is named as {what}"),
                        )
                        .help("an expression reads the name as that: choose another"));
                }
                defs.insert(name, Def::File(key.span(), value));
            }
        }
        for p in passed {
            let Some(def) = defs.get_mut(p.name.as_str()) else {
                let near = units::suggest(&p.name, defs.keys().copied());
                // `--set` names the file (a `diff` reads two), an include's
                // `params` is said at its key.
                let d = match &p.given {
                    Given::Set(_) => Diagnostic::plain(format!(
                        "`--set {}`: {} defines no parameter `{}` in `[params]`",
                        p.name, self.source.name, p.name
                    )),
                    Given::Value(_) => p.undefined.clone(),
                };
                return Err(match near {
                    None if !expr::is_name(&p.name) => d.help(
                        "a parameter's name is a letter or `_`, then letters, digits and `_`",
                    ),
                    _ => d.suggest(near),
                });
            };
            let file = match def {
                Def::File(key, q) => Some((key.clone(), *q)),
                Def::Set(..) | Def::Value(_) => None,
            };
            *def = match &p.given {
                Given::Set(source) => {
                    let mut note = format!("`{}` gives `{}` here", flag(&p.name, source), p.name);
                    if let Some((key, _)) = &file {
                        let (line, col) = self.source.line_col(key.start);
                        note.push_str(&format!(
                            ", in place of its definition at {}:{line}:{col}",
                            self.source.name
                        ));
                    }
                    self.params.set.insert(p.name.clone(), note);
                    Def::Set(source, file)
                }
                Given::Value(v) => Def::Value(*v),
            };
        }
        // The file's own value of each parameter a `--set` replaces, its
        // dimension the one the flag must give (`same_dimension`): its
        // `[params]` read alone, where they can be.
        let own = if defs.values().any(|d| matches!(d, Def::Set(_, Some(_)))) {
            self.own_params(raw)
        } else {
            None
        };
        // Each definition read, and the parameters it uses.
        let mut exprs: BTreeMap<&str, Expr> = BTreeMap::new();
        for (name, def) in &defs {
            let (text, span, source) = match def {
                Def::File(_, q) => match q.get_ref() {
                    Quantity::Text(t) => (t.as_str(), q.span(), self.source),
                    Quantity::Number(_) => continue,
                },
                Def::Set(source, _) => (source.text.as_str(), 0..source.text.len(), *source),
                Def::Value(_) => continue,
            };
            // The value before a tolerance (`"2 mm ± 0.1 mm"`): read after.
            let text = super::tolerance::split(text).map_or(text, |s| s.0);
            let e =
                Expr::parse(text).map_err(|e| located(source, span, text, e, &what(name, def)))?;
            exprs.insert(name, e);
        }
        let order = self.order(&defs, &exprs)?;
        for name in order {
            let value = match &defs[name] {
                Def::Value(v) => {
                    if let Some(b) = passed
                        .iter()
                        .find(|p| p.name == name)
                        .and_then(|p| p.exact.clone())
                    {
                        self.params.exact.insert(name.to_string(), b);
                    }
                    *v
                }
                Def::File(_, q) if matches!(q.get_ref(), Quantity::Number(_)) => {
                    let Quantity::Number(x) = q.get_ref() else {
                        unreachable!("invariant: matched above")
                    };
                    let v = self.number_param(q, *x, &format!("parameter `{name}`"))?;
                    if let Some(b) = self.params.exact_value(None, v) {
                        self.params.exact.insert(name.to_string(), b);
                    }
                    v
                }
                def => {
                    let (text, span, source) = match def {
                        Def::File(_, q) => match q.get_ref() {
                            Quantity::Text(t) => (t.as_str(), q.span(), self.source),
                            Quantity::Number(_) => unreachable!("invariant: matched above"),
                        },
                        Def::Set(s, _) => (s.text.as_str(), 0..s.text.len(), *s),
                        Def::Value(_) => unreachable!("invariant: matched above"),
                    };
                    let params = &self.params;
                    let value = exprs[name]
                        .eval(&|n| params.get(n), &|| {
                            defs.keys().map(|k| k.to_string()).collect()
                        })
                        .map_err(|e| {
                            let d = located(source, span.clone(), text, e, &what(name, def));
                            // A definition in the file may fail for a value
                            // `--set` gave another parameter.
                            match def {
                                Def::File(..) => {
                                    self.params.blame_set(&self.source.text, span.clone(), d)
                                }
                                Def::Set(..) | Def::Value(_) => d,
                            }
                        })?;
                    if let Def::Set(s, Some(replaced)) = def {
                        let own = own.as_ref().and_then(|o| o.get(name).copied());
                        self.same_dimension(name, s, replaced, own, value)?;
                    }
                    // Its gradient: through the parameters it uses, and
                    // its own tolerance, a source shared by every use.
                    let mut grad = self.params.grad_of(&exprs[name]);
                    if super::tolerance::split(text).is_some() {
                        let key = format!("param `{name}`");
                        let tol = self.amount(source, span.clone(), text, value.dim, &key)?;
                        let si = value.num_f64();
                        let at = if std::ptr::eq(source, self.source) {
                            span
                        } else {
                            0..0
                        };
                        let k = rec.shared_source(name, at, &tol);
                        axpy(&mut grad, 1.0, &vec![(k, tol.sigma_of(si))]);
                    }
                    if !grad.is_empty() {
                        self.params.grads.insert(name.to_string(), grad);
                    }
                    if let Some(b) = self.params.exact_value(Some(&exprs[name]), value) {
                        self.params.exact.insert(name.to_string(), b);
                    }
                    value
                }
            };
            self.params.values.insert(name.to_string(), value);
        }
        Ok(())
    }

    /// The parameters in an order in which each comes after those it uses
    /// (Kahn's algorithm, no recursion); a cycle is an error at the first
    /// of its parameters, naming the cycle.
    fn order<'n>(
        &self,
        defs: &BTreeMap<&'n str, Def>,
        exprs: &BTreeMap<&'n str, Expr>,
    ) -> Result<Vec<&'n str>, Diagnostic> {
        let uses = |name: &str| -> Vec<&'n str> {
            exprs.get(name).map_or_else(Vec::new, |e| {
                let mut u: Vec<&'n str> = e
                    .names()
                    .filter_map(|(n, _)| defs.get_key_value(n).map(|(k, _)| *k))
                    .collect();
                u.sort_unstable();
                u.dedup();
                u
            })
        };
        let mut waiting: BTreeMap<&str, usize> = BTreeMap::new();
        let mut users: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
        for name in defs.keys() {
            let u = uses(name);
            waiting.insert(name, u.len());
            for d in u {
                users.entry(d).or_default().push(name);
            }
        }
        let mut ready: Vec<&str> = waiting
            .iter()
            .filter(|(_, n)| **n == 0)
            .map(|(k, _)| *k)
            .collect();
        let mut order = Vec::with_capacity(defs.len());
        while let Some(name) = ready.pop() {
            order.push(name);
            for u in users.get(name).map_or(&[][..], Vec::as_slice) {
                let n = waiting
                    .get_mut(u)
                    .expect("invariant: every user is a parameter");
                *n -= 1;
                if *n == 0 {
                    ready.push(u);
                }
            }
        }
        if order.len() == defs.len() {
            return Ok(order);
        }
        // A cycle: from a parameter left waiting, follow uses that are
        // waiting too until one repeats.
        let left = |n: &str| waiting.get(n).is_some_and(|w| *w > 0);
        let start = *waiting
            .keys()
            .find(|k| left(k))
            .expect("invariant: one is left");
        let mut path = vec![start];
        loop {
            let last = *path.last().expect("invariant: not empty");
            let next = uses(last)
                .into_iter()
                .find(|u| left(u))
                .expect("invariant: a waiting parameter uses a waiting one");
            if let Some(at) = path.iter().position(|p| *p == next) {
                let mut cycle: Vec<&str> = path[at..].to_vec();
                cycle.push(next);
                let message = format!("parameters form a cycle: {}", cycle.join(" → "));
                return Err(match &defs[cycle[0]] {
                    Def::File(key, _) => self.err(key.clone(), message),
                    Def::Set(s, _) => s.error(0..s.text.len(), message),
                    Def::Value(_) => Diagnostic::plain(message),
                }
                .help("a parameter cannot be defined by itself, directly or through others"));
            }
            path.push(next);
        }
    }

    /// A quantity string that the unit reader refused, read as an
    /// expression: `Ok(None)` where it is a plain quantity after all (its
    /// error is the unit reader's), else its value in units of `factor`
    /// (of dimension `dim`), or the expression's located error.
    pub(super) fn expression(
        &self,
        rec: &Recorder,
        q: &Spanned<Quantity>,
        text: &str,
        key: &str,
        dim: Dim,
        factor: Factor,
    ) -> Result<Option<f64>, Diagnostic> {
        Ok(self
            .expression_grad(rec, Index::SCALAR, q, text, key, dim, factor)?
            .map(|(x, _)| x))
    }

    /// `expression`, with the gradient of its value by the sources of the
    /// parameters it uses (in units of `factor`; empty without), refused
    /// where no tolerance may stand (`rec` says where one may, and names a
    /// parameter's source; `at` is where the value stands in its key).
    #[allow(clippy::too_many_arguments)] // the recorder and where the value stands, beside the text
    pub(super) fn expression_grad(
        &self,
        rec: &Recorder,
        at: Index,
        q: &Spanned<Quantity>,
        text: &str,
        key: &str,
        dim: Dim,
        factor: Factor,
    ) -> Result<Option<(f64, Grad)>, Diagnostic> {
        if dim != Dim::DIMENSIONLESS && self.looks_plain(text) {
            return Ok(None);
        }
        let what = format!("`{key}`");
        let e = Expr::parse(text).map_err(|e| self.located_here(q, text, e, &what))?;
        let params = &self.params;
        let v = e
            .eval(&|n| params.get(n), &|| params.names())
            .map_err(|e| self.located_here(q, text, e, &what))?;
        if v.dim != dim {
            return Err(self
                .err(
                    q.span(),
                    format!(
                        "`{key}` is {}, but the expression gives {}",
                        expr::describe(dim),
                        expr::describe(v.dim)
                    ),
                )
                .help(format!("e.g. {}", dim.example())));
        }
        if dim == Dim::DIMENSIONLESS && v.angle {
            return Err(self
                .err(
                    q.span(),
                    format!("`{key}` is a plain number, but the expression has an angle unit in it"),
                )
                .help(format!(
                    "angles are dimensionless, so `90 deg` would be read as 1.5708 (radians); write `{key}` without `deg`, `rad` or `rev` (in a parameter too)"
                )));
        }
        let mut grad = params.grad_of(&e);
        if !grad.is_empty() {
            self.tolerable_grad(rec, at, q, key, &grad)?;
            let f = factor.value();
            grad.iter_mut().for_each(|(_, d)| *d /= f);
        }
        let x = params.nearest(&e, v, factor);
        if !x.is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` overflows the range of f64 in its units"),
            ));
        }
        if x != 0.0 && x.abs() < f64::MIN_POSITIVE || x == 0.0 && !is_zero(v) {
            return Err(self.err(
                q.span(),
                format!(
                    "`{key}` is too small: below {:e} in its units, f64 loses precision",
                    f64::MIN_POSITIVE
                ),
            ));
        }
        Ok(Some((x, grad)))
    }

    /// The exact value of a plain number as written, for a key that must
    /// be whole (`count`): a TOML number's text read as an expression's
    /// number is (`3.0000000000000001` is not 3, though f64 makes it 3), a
    /// string's expression evaluated; `None` where it cannot be read so
    /// (the key's own reader says why, or the text is TOML's alone, `0x10`).
    pub(super) fn written_value(&self, q: &Spanned<Quantity>) -> Option<Value> {
        let text = match q.get_ref() {
            Quantity::Number(_) => self.source.text.get(q.span())?,
            Quantity::Text(t) => super::tolerance::split(t).map_or(t.as_str(), |s| s.0),
        };
        let params = &self.params;
        Expr::parse(text)
            .ok()?
            .eval(&|n| params.get(n), &Vec::new)
            .ok()
    }

    /// Whether `text` is a plain quantity, right or wrong (`"3 furlongs"`,
    /// `"2 m^5"`): a number, then only unit words and their joiners, none
    /// a parameter, a function or `pi`, and no number after `*` or `/`.
    fn looks_plain(&self, text: &str) -> bool {
        let Ok((_, unit)) = units::split_number(text) else {
            return false;
        };
        let mut prev = ' ';
        let mut word = String::new();
        let mut after_word = false;
        for c in unit.chars().chain([' ']) {
            if c.is_alphanumeric() || c == '_' {
                if word.is_empty() && c.is_ascii_digit() && matches!(prev, '*' | '/' | '·') {
                    return false;
                }
                word.push(c);
                continue;
            }
            if !word.is_empty() {
                // With parameters, a word that is no unit is read as a
                // name (the error then suggests among both).
                let unit = units::parse_unit(&word).is_ok();
                if self.params.get(&word).is_some()
                    || expr::reserved(&word).is_some_and(|r| r != "a unit symbol")
                    || !unit && !self.params.is_empty()
                {
                    return false;
                }
                word.clear();
                after_word = true;
            }
            match c {
                ' ' | '\t' => continue,
                // `2 * leg`, `3 / n`: an operator before any unit.
                '*' | '/' | '·' if prev == ' ' && !after_word => return false,
                // A power of a unit, not of the number (`10^3 kg`).
                '^' if !after_word => return false,
                '*' | '/' | '·' | '^' | '²' | '³' => after_word = false,
                '-' | '+' if prev == '^' => {}
                _ => return false,
            }
            prev = c;
        }
        true
    }
}

fn is_zero(v: Value) -> bool {
    match v.num {
        expr::Num::Exact(q) => q.is_zero(),
        expr::Num::Float(x) => x.hi == 0.0,
    }
}

/// Who a definition's error is about: "parameter `leg`", or the flag and
/// its value, "`--set leg=3 kg`".
fn what(name: &str, def: &Def) -> String {
    match def {
        Def::Set(s, _) => format!("`{}`", flag(name, s)),
        Def::File(..) | Def::Value(_) => format!("parameter `{name}`"),
    }
}

impl Ctx<'_> {
    /// `located` in this file, with the notes of `Params::blame_set`.
    fn located_here(
        &self,
        q: &Spanned<Quantity>,
        text: &str,
        e: expr::Error,
        what: &str,
    ) -> Diagnostic {
        let d = located(self.source, q.span(), text, e, what);
        self.params.blame_set(&self.source.text, q.span(), d)
    }
}

/// An expression's error as a diagnostic at its token in the file: `span`
/// is the string's (quotes included) in `source`, `text` its value.
fn located(
    source: &Source,
    span: Range<usize>,
    text: &str,
    e: expr::Error,
    what: &str,
) -> Diagnostic {
    let at = super::span::sub_span(&source.text, span, text, e.at);
    let d = source.error(at, format!("{what}: {}", e.message));
    match e.help {
        Some(h) => d.help(h),
        None => d,
    }
}
