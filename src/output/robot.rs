//! A robot description's check for people: a table of its links, each
//! engine's verdict with its tightest margin, then a line per failure and
//! warning in the form compilers use (`path:line:col: error: …`).

use super::format::fmt_sig;
use super::grid::{Fit, write_rows};
use crate::diag::{Palette, visible};
use crate::robot::check::{EngineResult, LinkResult, RobotResult};
use crate::robot::engine::Rule;

/// One rule, its values and margin: `STATEMENT (A + B − C = x < limit),
/// margin m`.
pub fn rule_text(r: &Rule) -> String {
    let mut s = format!(
        "{} ({} {} {} {}",
        r.statement,
        match r.rule {
            "triangle" => "A + B − C =",
            "mass" | "moving_mass" => "mass =",
            "leading_minors" => "minor =",
            _ => "smallest moment =",
        },
        fmt_sig(r.value, 6),
        if r.holds { "≥" } else { "<" },
        fmt_sig(r.limit, 6),
    );
    if let Some(m) = r.margin {
        s.push_str(&format!(", margin {}", fmt_sig(m, 3)));
    }
    s.push(')');
    if r.close {
        s.push_str(" — within rounding: the engine's own eigen solver may decide otherwise");
    }
    s
}

/// What is wrong with a link under an engine: each failed rule, then the
/// likely cause. (After `path:line:col: error: ` in the table; the message
/// of CI annotations and of check's JSON.)
pub fn failure(link: &LinkResult, e: &EngineResult) -> String {
    let failed: Vec<String> = e
        .verdict
        .rules
        .iter()
        .filter(|r| !r.holds)
        .map(rule_text)
        .collect();
    // A verdict without a failed rule (values that overflow) says why in
    // its note.
    let why = if failed.is_empty() {
        e.verdict.note.clone().unwrap_or_default()
    } else {
        failed.join("; ")
    };
    let mut s = format!(
        "link \"{}\" is invalid under {}: {why}",
        link.name,
        e.verdict.engine.name(),
    );
    if let Some(c) = &e.cause {
        s.push_str("; likely cause: ");
        s.push_str(&c.message);
    }
    s
}

/// A warning's text, with its link named.
pub fn warning(link: &LinkResult, w: &str) -> String {
    format!("link \"{}\": {w}", link.name)
}

/// An engine's cell: `ok` or `INVALID`, and the tightest margin of its
/// rules (the smallest; negative when it fails).
fn cell(e: &EngineResult) -> String {
    let tightest = e
        .verdict
        .rules
        .iter()
        .filter_map(|r| r.margin)
        .min_by(f64::total_cmp);
    let word = if e.verdict.valid { "ok" } else { "INVALID" };
    match tightest {
        Some(m) => format!("{word} {}", fmt_sig(m, 3)),
        None if e.verdict.rules.is_empty() => "not used".to_string(),
        None => word.to_string(),
    }
}

/// The table of `r`'s links and the lines of its failures and warnings,
/// appended to `out`. `width`: `Fit`'s.
pub fn table(out: &mut String, path: &str, r: &RobotResult, colour: bool, width: Option<usize>) {
    let p = Palette::of(colour);
    let (e, w) = (p.error, p.warning);
    let path = visible(path);
    let engines = &r.engines;
    out.push_str(&format!(
        "{path}: {} file, {} link{}; margins: the tightest rule's, relative ((A + B − C)/C for the triangle inequality)\n",
        r.format.name(),
        r.links.len(),
        if r.links.len() == 1 { "" } else { "s" },
    ));
    let mut header: Vec<String> = ["link", "at", "moving", "mass kg", "I1 kg·m²", "I3 kg·m²"]
        .map(String::from)
        .to_vec();
    header.extend(engines.iter().map(|e| e.name().to_string()));
    let rows: Vec<Vec<String>> = r
        .links
        .iter()
        .map(|l| {
            let mut row = vec![
                super::format::name(&l.name),
                match &l.file {
                    // A link of an included file: its file too.
                    Some(f) => format!("{}:{}:{}", visible(f), l.span.line, l.span.column),
                    None => format!("{}:{}", l.span.line, l.span.column),
                },
                if l.moving { "yes" } else { "no" }.to_string(),
            ];
            match &l.inertial {
                Some(v) => {
                    row.push(fmt_sig(v.mass, 6));
                    row.push(fmt_sig(v.principal_moments[0], 6));
                    row.push(fmt_sig(v.principal_moments[2], 6));
                }
                None => row.extend(["—".to_string(), "—".to_string(), "—".to_string()]),
            }
            row.extend(engines.iter().map(|e| {
                l.engines
                    .iter()
                    .find(|x| x.verdict.engine == *e)
                    .map_or_else(|| "not checked".to_string(), cell)
            }));
            row
        })
        .collect();
    let right: Vec<bool> = (0..header.len()).map(|i| (3..6).contains(&i)).collect();
    if !rows.is_empty() {
        write_rows(out, &header, &rows, &right, Fit::new(width, 1));
    }
    for l in &r.links {
        let at = match &l.file {
            Some(f) => format!("{}:{}:{}", visible(f), l.span.line, l.span.column),
            None => format!("{path}:{}:{}", l.span.line, l.span.column),
        };
        // Where an included file is included from, as a diagnostic's
        // notes say it.
        let from: String = l
            .included_from
            .iter()
            .map(|site| format!("   = note: included from {}\n", visible(site)))
            .collect();
        for x in l.engines.iter().filter(|x| !x.verdict.valid) {
            out.push_str(&format!(
                "{at}: {e}error{e:#}: {}\n{from}",
                visible(&failure(l, x))
            ));
        }
        for text in &l.warnings {
            out.push_str(&format!(
                "{at}: {w}warning{w:#}: {}\n{from}",
                visible(&warning(l, text))
            ));
        }
    }
}
