//! `--only`: the body reduced to one sub-assembly, found by its name or
//! its path among every sub-assembly's (`Model::only`).

use super::{Include, Item, Model, push_copy_name};
use crate::units;

impl Model {
    /// Keep only the parts of the sub-assembly `name`: its own name at any
    /// depth, if only one sub-assembly has it, or its path
    /// (`front / wheel #2`). Returns the sub-assembly's path.
    pub fn only(&mut self, name: &str) -> Result<Vec<String>, String> {
        // At most this many names in a message; the rest are counted.
        const LISTED: usize = 12;
        // NOTE: the paths are walked, not gathered: a file whose copies
        // make 2,000,000 sub-assemblies held each path (and again each
        // joined) to answer one name. What is kept is bounded: the first
        // matches, the first `LISTED` paths for the message, and, for a
        // name short enough for "did you mean" (`units::suggest` compares
        // names of up to 256 characters), the paths short enough too.
        let mut matching: Vec<Vec<String>> = Vec::new();
        let mut matches = 0usize;
        let (mut listed, mut total) = (Vec::new(), 0usize);
        let mut near: Vec<String> = Vec::new();
        let short = name.len() <= 1024;
        self.each_assembly(&mut Vec::new(), &mut |path| {
            total += 1;
            let joined_len =
                path.iter().map(String::len).sum::<usize>() + 3 * path.len().saturating_sub(1);
            let is = path.last().is_some_and(|l| l == name)
                || (joined_len == name.len() && path.join(" / ") == name);
            if is {
                matches += 1;
                if matching.len() < LISTED {
                    matching.push(path.to_vec());
                }
            }
            if listed.len() < LISTED {
                listed.push(path.join(" / "));
            }
            if short && joined_len <= 4 * 1024 {
                near.push(path.join(" / "));
            }
        });
        let list = |names: &[String], total: usize| {
            let more = total.saturating_sub(names.len());
            let mut text = names
                .iter()
                .map(|n| format!("`{}`", crate::diag::shorten(n)))
                .collect::<Vec<_>>()
                .join(", ");
            if more > 0 {
                text.push_str(&format!(" and {more} more"));
            }
            text
        };
        let shown = crate::diag::shorten(name);
        let target: Vec<String> = match (matches, matching.pop()) {
            (1, Some(one)) => one,
            (0, _) | (_, None) => {
                return Err(if total == 0 {
                    format!("`--only {shown}`: the file has no sub-assemblies (`include`)")
                } else {
                    let near = units::suggest(name, near.iter().map(String::as_str))
                        .map(|s| format!("; did you mean `{}`?", crate::diag::shorten(s)))
                        .unwrap_or_default();
                    format!(
                        "`--only {shown}`: no sub-assembly of that name{near} (the file has {})",
                        list(&listed, total)
                    )
                });
            }
            (many, Some(last)) => {
                matching.push(last);
                let names: Vec<String> = matching.iter().map(|q| q.join(" / ")).collect();
                return Err(format!(
                    "`--only {shown}` is ambiguous: {}; give the path",
                    list(&names, many)
                ));
            }
        };
        *self = self.keeping(&target);
        Ok(target)
    }

    /// Each sub-assembly's path, parents before children.
    ///
    /// NOTE: a sub-assembly with copies is listed by its own name (all its
    /// copies) and by each copy's, `wheel[2]`, whose sub-assemblies follow.
    fn each_assembly(&self, path: &mut Vec<String>, f: &mut dyn FnMut(&[String])) {
        for item in self.items.iter() {
            if let Item::Include(inc) = item {
                path.push(inc.name.clone());
                f(path);
                match &inc.copies {
                    None => inc.model.each_assembly(path, f),
                    Some(c) => {
                        for i in c.indices() {
                            let last = path.last_mut().expect("just pushed");
                            last.clear();
                            push_copy_name(last, &inc.name, i);
                            f(path);
                            inc.model.each_assembly(path, f);
                        }
                    }
                }
                path.pop();
            }
        }
    }

    /// This model with only the sub-assembly at `path` (a path `only`
    /// found, so every step of it names one include).
    fn keeping(&self, path: &[String]) -> Model {
        let Some((first, rest)) = path.split_first() else {
            return self.clone();
        };
        let mut items = Vec::new();
        let (mut count, mut has_real_sizes) = (0, false);
        for item in self.items.iter() {
            let Item::Include(inc) = item else { continue };
            // The sub-assembly with all its copies, or one copy of it.
            let copies = match &inc.copies {
                _ if inc.name == *first => inc.copies.clone(),
                Some(c) => match c.index_in(&inc.name, first) {
                    Some(i) => Some(Box::new(c.keeping(i))),
                    None => continue,
                },
                None => continue,
            };
            let model = std::sync::Arc::new(inc.model.keeping(rest));
            count = model.count * copies.as_ref().map_or(1, |c| c.indices().len());
            has_real_sizes = model.has_real_sizes;
            items.push(Item::Include(Box::new(Include {
                model,
                copies,
                ..(**inc).clone()
            })));
        }
        Model {
            group_depth: super::budget::group_depth(&items),
            items: std::sync::Arc::new(items),
            count,
            has_real_sizes,
            ..self.clone_without_items()
        }
    }

    /// Everything but the parts.
    fn clone_without_items(&self) -> Model {
        Model {
            name: self.name.clone(),
            analysis: self.analysis.clone(),
            expect: self.expect.clone(),
            materials: self.materials.clone(),
            budget: self.budget.clone(),
            envelope: self.envelope.clone(),
            included: self.included.clone(),
            units_given: self.units_given,
            ..Model::empty(self.units)
        }
    }
}
