//! `massprop materials [FILE]`: the built-in materials, and a file's own
//! `[materials]` (marked as overriding where they share a name): a part
//! file's, or a materials file's (`[materials]` with no parts,
//! `Model::materials_file`).

use super::Outcome;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::materials::BUILT_IN;
use crate::model::Model;
use crate::output::materials::Listed;
use crate::output::{self, Format};

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
        let settings = Settings {
            includes: o.includes.clone(),
            ..Settings::default()
        };
        // A materials file (`[materials]`, with its `[units]` and
        // `[params]`, no parts) is read for its materials alone; any other
        // file through the whole pipeline: a file `report` rejects is
        // rejected here too.
        let source = crate::io::read_source(path)?;
        let materials = match Model::materials_file(&source, &o.includes)? {
            Some(materials) => materials,
            None => analysis::load_source(source, &settings)?.model.materials,
        };
        for (name, &density) in &materials {
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
        output::render(&output::Output::Materials(&list), o.format, terminal.stdout),
        Vec::new(),
    ))
}
