//! The weight statement's inputs: a part's `group` and `maturity`, the
//! file's `[growth]` table (maturity → mass growth allowance) and its
//! `[budget]` limit, validated. `analysis::budget` forms the statement.
//!
//! A maturity is resolved to its allowance here, in the file that names it:
//! a sub-assembly's parts use their own file's `[growth]`, an include's
//! `maturity` the including file's.

use super::Ctx;
use super::raw::{Growth, Quantity, RawBudget, RawPart};
use crate::diag::Diagnostic;
use crate::units::{self, Dim};
use std::ops::Range;
use toml::Spanned;

/// The keys every part and include may have, besides `name`: they place
/// it in the weight statement, not in space (`model::schema` reads them).
pub const TAG_KEYS: [&str; 2] = ["group", "maturity"];

/// A part's (or an include's) place in the weight statement, as its
/// `[[part]]` gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct Tag {
    /// `group`, split at `/`, each name trimmed: `["propulsion", "tanks"]`.
    pub group: Option<Vec<String>>,
    pub maturity: Option<Maturity>,
}

/// The most names a part's group path may have, the groups of the
/// sub-assemblies that hold it counted (`"a/b"` in a sub-assembly of group
/// `"c"` is three: `c/a/b`).
///
/// NOTE: a weight statement's groups nest a few levels deep (SAWE RP-8's
/// and MIL-STD-1374's are three or four); each group's row and JSON `path`
/// name every group above it, so a statement's size grows with the
/// depth times the number of groups, and the bound keeps it within a fixed
/// multiple of the file's text.
pub const MAX_GROUP_DEPTH: usize = 64;

/// A design maturity and the allowance its file's `[growth]` gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct Maturity {
    pub name: String,
    /// The mass growth allowance, a fraction of the basic mass (0.15 for
    /// `"15 %"`), from 0 to `MAX_ALLOWANCE`.
    pub allowance: f64,
}

/// The largest allowance `[growth]` takes, 1000 % (a fraction): past it a
/// "growth" is no allowance but a basic mass not yet known, and a body
/// eleven times its basic mass would no longer be the design weighed.
pub const MAX_ALLOWANCE: f64 = 10.0;

const GROUP_DEPTH_HELP: &str = "a group path names a subsystem and its sub-groups, a few levels deep (\"propulsion/tanks\"); each level is a row of the weight statement";

/// The deepest group path of `items`' parts, in names, their
/// sub-assemblies' groups counted (`Model::group_depth`).
pub(super) fn group_depth(items: &[super::Item]) -> usize {
    let len = |tag: &Option<Box<Tag>>| {
        tag.as_ref()
            .and_then(|t| t.group.as_ref())
            .map_or(0, Vec::len)
    };
    items
        .iter()
        .map(|item| match item {
            super::Item::Part { tag, .. } => len(tag),
            super::Item::Include(inc) => len(&inc.tag) + inc.model.group_depth,
        })
        .max()
        .unwrap_or(0)
}

/// `[budget]`, read: the not-to-exceed limit of the predicted mass.
#[derive(Debug, Clone, PartialEq)]
pub struct Limit {
    /// kg.
    pub mass: f64,
    pub span: Range<usize>,
}

/// `[growth]`, read: maturity name → allowance (a fraction).
pub(super) type Allowances = std::collections::BTreeMap<String, f64>;

/// A percentage as `[growth]` writes it, `"15 %"` or `"15%"`, as a
/// fraction; `None` if `text` is not a number followed by one `%`.
pub fn percentage(text: &str) -> Option<f64> {
    let number = text.trim().strip_suffix('%')?.trim_end();
    number.parse::<f64>().ok().map(|p| p / 100.0)
}

impl Ctx<'_> {
    /// `[growth]`: each value a percentage, finite and not negative.
    pub(super) fn read_growth(&mut self, growth: Option<&Growth>) -> Result<(), Diagnostic> {
        let Some(table) = growth else { return Ok(()) };
        for (name, value) in table.get_ref() {
            let key = name.get_ref();
            let text = match value.get_ref() {
                Quantity::Text(t) => t,
                Quantity::Number(x) => {
                    return Err(self
                        .err(
                            value.span(),
                            format!("`growth.{key}` must be a percentage string, got {x}"),
                        )
                        .help(format!(
                            "write the allowance as a percentage: `{key} = \"{x} %\"`"
                        )));
                }
            };
            let allowance = match percentage(text) {
                // NOTE: "-0 %" is 0 %; `abs` keeps its sign from showing
                // as a growth of "-0".
                Some(a) if (0.0..=MAX_ALLOWANCE).contains(&a) => a.abs(),
                Some(a) if a > MAX_ALLOWANCE && a.is_finite() => {
                    return Err(self
                        .err(
                            value.span(),
                            format!("`growth.{key}` is {text:?}, above 1000 %: a growth that large is not an allowance"),
                        )
                        .help("an allowance covers what a part's mass will still grow, a fraction of it; a part expected to weigh more than eleven times its basic mass needs a new basic mass"));
                }
                Some(_) => {
                    return Err(self
                        .err(
                            value.span(),
                            format!("`growth.{key}` must be a finite percentage ≥ 0, got {text:?}"),
                        )
                        .help("a growth allowance adds mass: 0 % for a part that is weighed, more for one less mature"));
                }
                None => {
                    return Err(self
                        .err(
                            value.span(),
                            format!("`growth.{key}`: cannot read {text:?} as a percentage"),
                        )
                        .help("write a number and `%`, e.g. \"15 %\""));
                }
            };
            self.growth.insert(key.clone(), allowance);
        }
        Ok(())
    }

    /// `[budget]`: its `limit`, a positive mass.
    pub(super) fn budget(
        &self,
        rec: &super::tolerance::Recorder,
        raw: &Spanned<RawBudget>,
    ) -> Result<Limit, Diagnostic> {
        let limit = &raw.get_ref().limit;
        Ok(Limit {
            mass: self.positive(rec, limit, "limit", Dim::MASS)?,
            span: limit.span(),
        })
    }

    /// A part's or an include's `group` and `maturity`; `None` if it has
    /// neither. A cut-out takes both like any part: it grows by its
    /// (negative) mass, so the part it is cut from grows as a whole.
    pub(super) fn tag(&self, p: &RawPart) -> Result<Option<Box<Tag>>, Diagnostic> {
        let group = p.group.as_deref().map(|g| self.group_path(g)).transpose()?;
        let maturity = p
            .maturity
            .as_deref()
            .map(|m| self.maturity(m))
            .transpose()?;
        Ok((group.is_some() || maturity.is_some()).then(|| Box::new(Tag { group, maturity })))
    }

    /// An include's `group` and `maturity`, as `tag`; its group and the
    /// included file's deepest group path (`child`) together at most
    /// `MAX_GROUP_DEPTH` names.
    pub(super) fn include_tag(
        &self,
        p: &RawPart,
        child: &super::Model,
    ) -> Result<Option<Box<Tag>>, Diagnostic> {
        let tag = self.tag(p)?;
        let own = tag
            .as_ref()
            .and_then(|t| t.group.as_ref())
            .map_or(0, Vec::len);
        if let Some(g) = p.group.as_deref()
            && own + child.group_depth > MAX_GROUP_DEPTH
        {
            return Err(self
                .err(
                    g.span(),
                    format!(
                        "`group` puts the included parts {} groups deep ({own} here, {} in the included file), past the limit of {MAX_GROUP_DEPTH}",
                        own + child.group_depth,
                        child.group_depth
                    ),
                )
                .help(GROUP_DEPTH_HELP));
        }
        Ok(tag)
    }

    /// `group = "a/b"`: names joined by `/`, none empty, at most
    /// `MAX_GROUP_DEPTH`.
    fn group_path(&self, g: &Spanned<String>) -> Result<Vec<String>, Diagnostic> {
        let text = g.get_ref();
        // Counted before any name is copied.
        let depth = text.split('/').count();
        if depth > MAX_GROUP_DEPTH {
            return Err(self
                .err(
                    g.span(),
                    format!("`group` has {depth} names, past the limit of {MAX_GROUP_DEPTH}"),
                )
                .help(GROUP_DEPTH_HELP));
        }
        let names: Vec<String> = text.split('/').map(|n| n.trim().to_string()).collect();
        if names.iter().any(String::is_empty) {
            let what = if text.trim().is_empty() {
                "`group` is empty".to_string()
            } else if text.trim_start().starts_with('/') || text.trim_end().ends_with('/') {
                format!("`group` {text:?} begins or ends with `/`")
            } else {
                format!("`group` {text:?} has an empty name between two `/`")
            };
            return Err(self.err(g.span(), what).help(
                "a group is a subsystem and its sub-groups, names joined by `/`, e.g. \"propulsion/tanks\"",
            ));
        }
        Ok(names)
    }

    /// `maturity = "NAME"`: a key of this file's `[growth]`.
    fn maturity(&self, m: &Spanned<String>) -> Result<Maturity, Diagnostic> {
        let name = m.get_ref();
        if let Some(a) = self.growth.get(name) {
            return Ok(Maturity {
                name: name.clone(),
                allowance: *a,
            });
        }
        let known = || {
            self.growth
                .keys()
                .map(|k| format!("`{k}`"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let d = if self.growth.is_empty() {
            self.err(m.span(), format!("unknown maturity {name:?}: the file has no `[growth]` table"))
                .help("add a `[growth]` table giving each maturity its allowance, e.g. `[growth]` with `estimated = \"15 %\"`")
        } else {
            self.err(m.span(), format!("unknown maturity {name:?}"))
                .help(format!("the file's `[growth]` table has {}", known()))
        };
        Err(
            match units::suggest(name, self.growth.keys().map(String::as_str)) {
                Some(s) => d.label(format!("did you mean \"{s}\"?")),
                None => d,
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::percentage;

    #[test]
    fn a_percentage_is_a_number_and_one_percent_sign() {
        assert_eq!(percentage("15 %"), Some(0.15));
        assert_eq!(percentage(" 15%"), Some(0.15));
        assert_eq!(percentage("0 %"), Some(0.0));
        assert_eq!(percentage("15"), None);
        assert_eq!(percentage("15 %%"), None);
        assert_eq!(percentage("% 15"), None);
    }
}
