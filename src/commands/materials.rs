//! `massprop materials [FILE]`: the built-in materials, and a file's own
//! `[materials]` (marked as overriding where they share a name).

use super::Outcome;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::materials::BUILT_IN;
use crate::render::materials::Listed;
use crate::render::{self, Format};

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// A part file whose `[materials]` are listed too.
    pub file: Option<String>,
    pub format: Format,
    /// `--include-root` and `--base-dir`.
    pub includes: crate::model::Includes,
}

pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    let mut list: Vec<Listed> = BUILT_IN
        .iter()
        .map(|m| Listed {
            name: m.name.to_string(),
            density: m.density,
            source: m.source.to_string(),
        })
        .collect();
    if let Some(path) = &o.file {
        // The whole pipeline: a file `report` rejects is rejected here too.
        let settings = Settings {
            includes: o.includes.clone(),
            ..Settings::default()
        };
        let model = analysis::load(path, &settings)?.model;
        for (name, &density) in &model.materials {
            match list.iter_mut().find(|l| &l.name == name) {
                Some(l) => {
                    l.density = density;
                    l.source = format!("[materials] in {path}, overriding the built-in value");
                }
                None => list.push(Listed {
                    name: name.clone(),
                    density,
                    source: format!("[materials] in {path}"),
                }),
            }
        }
    }
    Ok(Outcome::ok(
        render::render(&render::Output::Materials(&list), o.format, terminal.stdout),
        Vec::new(),
    ))
}
