//! `materials`' output: the table of materials, or one JSON document.

use super::format::{fmt_num, name};
use super::grid::new_table;
use crate::analysis::summary::FORMAT_VERSION;
use serde::Serialize;

/// One listed material; `density` in kg/m³.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Listed {
    pub name: String,
    pub density: f64,
    pub source: String,
}

pub fn json(list: &[Listed]) -> String {
    super::json_line(&serde_json::json!({
        "format_version": FORMAT_VERSION,
        "massprop_version": crate::analysis::summary::MASSPROP_VERSION,
        "units": { "density": "kg/m^3" },
        "materials": list,
    }))
}

pub fn table(list: &[Listed]) -> String {
    let mut t = new_table();
    t.set_header(vec!["material", "density (kg/m³)", "source"]);
    for l in list {
        t.add_row(vec![name(&l.name), fmt_num(l.density), name(&l.source)]);
    }
    format!("{t}\n")
}
