//! `explain`'s document written as text (the terminal), markdown (tables
//! and `$…$` maths) or LaTeX (an `align*` environment per step, a whole
//! document that pdflatex compiles). A name from input is shown through
//! `output::format::push_name` (no control character acts, no line is
//! added), then escaped for markdown or TeX.

use super::number;
use super::{Doc, Math, Piece, Row};

/// The formats of `explain`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Style {
    #[default]
    Text,
    Markdown,
    Latex,
}

/// The document in `style`.
pub fn write(doc: &Doc, style: Style) -> String {
    match style {
        Style::Text => text(doc),
        Style::Markdown => markdown(doc),
        Style::Latex => latex(doc),
    }
}

fn name(n: &str) -> String {
    let mut out = String::new();
    crate::output::format::push_name(&mut out, n);
    out
}

/// Markdown's special characters escaped with a backslash.
fn md_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        if "\\`*_{}[]<>()#+-.!|~$&".contains(c) {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// TeX's special characters, and every character past ASCII, made safe
/// for pdflatex: specials as their commands, a character past ASCII as
/// its code point, `[U+00FC]`; the program's own symbols as maths.
fn tex_escape(s: &str, own: bool) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' | '}' | '#' | '$' | '%' | '&' | '_' => {
                out.push('\\');
                out.push(c);
            }
            '~' => out.push_str("\\textasciitilde{}"),
            '^' => out.push_str("\\textasciicircum{}"),
            '<' => out.push_str("\\textless{}"),
            '>' => out.push_str("\\textgreater{}"),
            '|' => out.push_str("\\textbar{}"),
            '`' => out.push_str("\\textasciigrave{}"),
            '\'' => out.push_str("\\textquotesingle{}"),
            '"' => out.push_str("\\textquotedbl{}"),
            '-' => out.push_str("-{}"),
            c if c.is_ascii() && !c.is_ascii_control() => out.push(c),
            c if own => out.push_str(match c {
                '·' => "$\\cdot$",
                '×' => "$\\times$",
                '²' => "$^2$",
                '³' => "$^3$",
                '−' => "$-$",
                '–' => "--",
                'ρ' => "$\\rho$",
                'ω' => "$\\omega$",
                'λ' => "$\\lambda$",
                'π' => "$\\pi$",
                '∫' => "$\\int$",
                '′' => "$'$",
                'ᵀ' => "$^T$",
                '½' => "$\\frac12$",
                '₁' => "$_1$",
                '₂' => "$_2$",
                '₃' => "$_3$",
                '⁴' => "$^4$",
                'Σ' => "$\\Sigma$",
                _ => "?",
            }),
            c => out.push_str(&format!("[U+{:04X}]", c as u32)),
        }
    }
    out
}

fn pieces(ps: &[Piece], style: Style) -> String {
    ps.iter()
        .map(|p| match (p, style) {
            (Piece::Text(s), Style::Text | Style::Markdown) => s.clone(),
            (Piece::Text(s), Style::Latex) => tex_escape(s, true),
            (Piece::Name(n), Style::Text) => format!("\"{}\"", name(n)),
            (Piece::Name(n), Style::Markdown) => format!("“{}”", md_escape(&name(n))),
            (Piece::Name(n), Style::Latex) => format!("``{}''", tex_escape(&name(n), false)),
            (Piece::Math(m), Style::Text) => m.text.clone(),
            (Piece::Math(m), Style::Markdown | Style::Latex) => format!("${}$", m.tex),
        })
        .collect()
}

fn unit_text(u: &Math) -> String {
    if u.text.is_empty() {
        String::new()
    } else {
        format!(" {}", u.text)
    }
}

fn text(doc: &Doc) -> String {
    let mut out = pieces(&doc.title, Style::Text);
    out.push('\n');
    for c in &doc.conventions {
        out.push_str("  ");
        out.push_str(&pieces(c, Style::Text));
        out.push('\n');
    }
    for step in &doc.steps {
        out.push('\n');
        out.push_str(&pieces(&step.heading, Style::Text));
        out.push('\n');
        for row in &step.rows {
            out.push_str("   ");
            match row {
                Row::Note(p) => out.push_str(&pieces(p, Style::Text)),
                Row::Eq {
                    lhs,
                    form,
                    subst,
                    value,
                    unit,
                    reported,
                } => {
                    out.push_str(&lhs.text);
                    for m in [form, subst].into_iter().flatten() {
                        out.push_str(" = ");
                        out.push_str(&m.text);
                    }
                    out.push_str(" = ");
                    out.push_str(&value_text(*value, *reported));
                    out.push_str(&unit_text(unit));
                }
                Row::Summary { label, items } => {
                    out.push_str(&pieces(label, Style::Text));
                    out.push(':');
                    for (n, (m, v, u)) in items.iter().enumerate() {
                        out.push_str(if n == 0 { " " } else { "; " });
                        out.push_str(&format!(
                            "{} = {}{}",
                            m.text,
                            number::text(*v),
                            unit_text(u)
                        ));
                    }
                }
            }
            out.push('\n');
        }
    }
    out
}

fn markdown(doc: &Doc) -> String {
    let mut out = format!("# {}\n\n", pieces(&doc.title, Style::Markdown));
    for c in &doc.conventions {
        out.push_str(&format!("- {}\n", pieces(c, Style::Markdown)));
    }
    for step in &doc.steps {
        out.push_str(&format!(
            "\n## {}\n\n",
            pieces(&step.heading, Style::Markdown)
        ));
        let mut table = false;
        for row in &step.rows {
            match row {
                Row::Eq {
                    lhs,
                    form,
                    subst,
                    value,
                    unit,
                    reported,
                } => {
                    if !table {
                        out.push_str("| quantity | formula | with the numbers | value |\n|---|---|---|---|\n");
                        table = true;
                    }
                    let cell = |m: &Option<Math>| {
                        m.as_ref()
                            .map_or(String::new(), |m| format!("$= {}$", m.tex))
                    };
                    out.push_str(&format!(
                        "| ${}$ | {} | {} | {}{} |\n",
                        lhs.tex,
                        cell(form),
                        cell(subst),
                        md_escape(&value_text(*value, *reported)),
                        md_escape(&unit_text(unit))
                    ));
                }
                Row::Note(p) => {
                    if table {
                        out.push('\n');
                        table = false;
                    }
                    out.push_str(&format!("{}\n\n", pieces(p, Style::Markdown)));
                }
                Row::Summary { label, items } => {
                    if table {
                        out.push('\n');
                        table = false;
                    }
                    let items: Vec<String> = items
                        .iter()
                        .map(|(m, v, u)| {
                            format!(
                                "${}$ = {}{}",
                                m.tex,
                                md_escape(&number::text(*v)),
                                md_escape(&unit_text(u))
                            )
                        })
                        .collect();
                    out.push_str(&format!(
                        "- {}: {}\n",
                        pieces(label, Style::Markdown),
                        items.join("; ")
                    ));
                }
            }
        }
        if table {
            out.push('\n');
        }
    }
    out
}

fn tex_value(v: super::exact::Exact, reported: Option<f64>, u: &Math) -> String {
    let n = match reported {
        Some(r) => number::tex_reported(v, r),
        None => number::tex(v),
    };
    if u.tex.is_empty() {
        n
    } else {
        format!("{n}\\;{}", u.tex)
    }
}

/// A value as text: a final figure as the report's (`number::text_reported`).
fn value_text(v: super::exact::Exact, reported: Option<f64>) -> String {
    match reported {
        Some(r) => number::text_reported(v, r),
        None => number::text(v),
    }
}

fn latex(doc: &Doc) -> String {
    let mut out = String::from(
        "\\documentclass{article}\n\\usepackage{amsmath}\n\\usepackage[margin=1.5cm,landscape]{geometry}\n\\allowdisplaybreaks\n\\begin{document}\n\\small\n",
    );
    out.push_str(&format!(
        "\\section*{{{}}}\n\\begin{{itemize}}\n",
        pieces(&doc.title, Style::Latex)
    ));
    for c in &doc.conventions {
        out.push_str(&format!("\\item {}\n", pieces(c, Style::Latex)));
    }
    out.push_str("\\end{itemize}\n");
    for step in &doc.steps {
        out.push_str(&format!(
            "\\subsection*{{{}}}\n",
            pieces(&step.heading, Style::Latex)
        ));
        let mut align = false;
        for row in &step.rows {
            match row {
                Row::Eq {
                    lhs,
                    form,
                    subst,
                    value,
                    unit,
                    reported,
                } => {
                    if !align {
                        out.push_str("\\begin{align*}\n");
                        align = true;
                    }
                    out.push_str(&lhs.tex);
                    out.push_str(" &");
                    for m in [form, subst].into_iter().flatten() {
                        out.push_str(&format!("= {} ", m.tex));
                    }
                    out.push_str(&format!("= {} \\\\\n", tex_value(*value, *reported, unit)));
                }
                Row::Note(p) | Row::Summary { label: p, .. } => {
                    if align {
                        out.push_str("\\end{align*}\n");
                        align = false;
                    }
                    out.push_str(&pieces(p, Style::Latex));
                    if let Row::Summary { items, .. } = row {
                        let items: Vec<String> = items
                            .iter()
                            .map(|(m, v, u)| format!("${} = {}$", m.tex, tex_value(*v, None, u)))
                            .collect();
                        out.push_str(": ");
                        out.push_str(&items.join("; "));
                    }
                    out.push_str("\n\n");
                }
            }
        }
        if align {
            out.push_str("\\end{align*}\n");
        }
    }
    out.push_str("\\end{document}\n");
    out
}
