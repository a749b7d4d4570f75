//! The man page's own sections, and `massprop help part-file` (the man
//! page's PART FILE section too): the
//! part-file reference, made from the registries the reader itself uses, so
//! it cannot drift from it: each part key and its line from the JSON Schema
//! (itself made from `keys::COMMON` and each shape's `own_keys`), each
//! shape from `shapes::SHAPES`, `[expect]`'s keys from
//! `quantity::QUANTITIES`, units from `units`, materials from `materials`.

use serde_json::Value;
use std::fmt::Write;

/// The reference, as plain text.
pub fn text() -> String {
    let schema = crate::model::schema::schema();
    let defs = &schema["$defs"];
    let mut out = String::from(
        "THE PART FILE (docs/part-file.md has the long form)\n\n\
         A part file is TOML: top-level `name`, `units`, `[params]`, `[materials]`,\n\
         `[analysis]`, `[expect]`, `[growth]`, `[budget]`, and one `[[part]]` table per\n\
         part. A quantity is a number in the file's units or a string with its unit\n\
         (\"350 g\", \"2.7 g/cm^3\", \"90 deg\"); a string may use `[params]`\n\
         (\"2 * wall\"), which `--set NAME=VALUE` overrides. A part is a shape, or\n\
         `include = \"other.toml\"` (a sub-assembly placed at `origin`, rotated by\n\
         `rotation`, with `params` passed); `array` and `mirror` copy a part;\n\
         `tol` and a quantity's \"± …\" give tolerances for `--uncertainty`.\n",
    );
    let _ = writeln!(
        out,
        "\nUNITS (`units = {{ length = \"mm\", mass = \"g\" }}`)"
    );
    let _ = writeln!(out, "  length: {}", crate::units::LENGTH_UNITS.join(", "));
    let _ = writeln!(out, "  mass: {}", crate::units::MASS_UNITS.join(", "));

    let _ = writeln!(
        out,
        "\nPART KEYS (any `[[part]]`; a shape takes those its entry lists)"
    );
    if let Some(props) = defs["Part"]["properties"].as_object() {
        for (key, v) in props {
            let _ = writeln!(out, "  {key}: {}", description(v));
        }
    }

    let _ = writeln!(out, "\nSHAPES (`shape = \"NAME\"`)");
    for s in crate::shapes::SHAPES.iter() {
        let _ = writeln!(out, "  {}: {}", s.name, s.help);
        let _ = writeln!(out, "    keys: {}", s.keys.join(", "));
        let mass = match s.density {
            Some(d) => format!("`mass` or `{}` or `material`", d.key),
            None => "`mass`".to_string(),
        };
        let _ = writeln!(out, "    mass from: {mass}");
        let mut placements = vec![if s.centred.is_empty() {
            "`center` (with `rotation`)".to_string()
        } else {
            format!("centred: {}", s.centred.join(", "))
        }];
        if let Some(sp) = s.spanned {
            placements.push(format!("spanned: {}", sp.keys().join(", ")));
        }
        let _ = writeln!(out, "    placement: {}", placements.join("; or "));
        if !s.degenerate.is_empty() {
            let _ = writeln!(out, "    degenerate: {}", s.degenerate);
        }
    }

    for (title, def) in [
        ("[analysis]", "Analysis"),
        ("ARRAYS (`array = { … }`)", "Array"),
        ("MIRRORS (`mirror = { … }`)", "Mirror"),
    ] {
        let _ = writeln!(out, "\n{title}");
        if let Some(props) = defs[def]["properties"].as_object() {
            for (key, v) in props {
                let _ = writeln!(out, "  {key}: {}", description(v));
            }
        }
    }

    let _ = writeln!(
        out,
        "\n[expect] (each a value, `{{ value, tol }}`, `{{ min, max }}`; SI unit shown)"
    );
    for q in crate::quantity::QUANTITIES.iter().filter(|q| q.expected) {
        let _ = writeln!(out, "  {}: {}", q.key, q.unit);
    }

    let _ = writeln!(
        out,
        "\nMATERIALS (built in; `[materials] NAME = {{ density = … }}` adds; `massprop materials`)"
    );
    let names: Vec<&str> = crate::materials::BUILT_IN.iter().map(|m| m.name).collect();
    for line in wrap(&names.join(", "), 76) {
        let _ = writeln!(out, "  {line}");
    }
    out
}

/// The part-file reference (`text`) as a roff section.
pub fn roff() -> String {
    let mut out = String::from(".SH \"PART FILE\"\n.nf\n");
    for line in text().lines() {
        let line = line.replace('\\', "\\e").replace('-', "\\-");
        // A leading dot or quote would be a roff request.
        if line.starts_with('.') || line.starts_with('\'') {
            out.push_str("\\&");
        }
        out.push_str(&line);
        out.push('\n');
    }
    out.push_str(".fi\n");
    out
}

/// A schema entry's description, on one line; without one, its form
/// (`[x, y, z]`, the definition it refers to).
fn description(v: &Value) -> String {
    let text = v["description"].as_str().unwrap_or("");
    if !text.is_empty() {
        return text.split_whitespace().collect::<Vec<_>>().join(" ");
    }
    if let Some(n) = v["maxItems"].as_u64() {
        return format!("an array of {n} quantities, [x, y, z]");
    }
    match v["$ref"].as_str().and_then(|r| r.rsplit('/').next()) {
        Some(def) => format!("{} (docs/part-file.md)", def.to_lowercase()),
        None => v["type"].as_str().unwrap_or("a value").to_string(),
    }
}

/// `text` in lines of at most `width` characters, broken at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let last = lines.last_mut().expect("invariant: one line at least");
        if !last.is_empty() && last.chars().count() + 1 + word.chars().count() > width {
            lines.push(word.to_string());
        } else {
            if !last.is_empty() {
                last.push(' ');
            }
            last.push_str(word);
        }
    }
    lines
}

/// The JSON contract's table of keys (docs/json.md, the one statement of
/// it) as a roff section, so that an installed massprop carries it.
pub fn json_section(doc: &str) -> String {
    // roff: a backslash and a leading dot or quote are special; `code` in
    // bold.
    let roff = |text: &str| {
        let escaped = text.replace('\\', "\\e").replace('-', "\\-");
        let mut out = String::new();
        for (i, piece) in escaped.split('`').enumerate() {
            if i % 2 == 1 {
                out.push_str("\\fB");
                out.push_str(piece);
                out.push_str("\\fR");
            } else {
                out.push_str(piece);
            }
        }
        if out.starts_with(['.', '\'']) {
            out.insert_str(0, "\\&");
        }
        out
    };
    let mut s = String::from(
        ".SH \"JSON OUTPUT\"\n\\fBmassprop report \\-\\-format json\\fR prints one object, SI units; keys are only ever added.\n",
    );
    for row in doc.lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = row.trim_matches('|').split(" | ").map(str::trim).collect();
        if let [key, kind, meaning] = cells[..] {
            s.push_str(&format!(
                ".TP\n{} ({})\n{}\n",
                roff(key),
                roff(kind),
                roff(meaning)
            ));
        }
    }
    s
}
