//! The built-in materials: `material = "NAME"` on a part instead of a
//! density (and what `massprop materials` lists). A part file's
//! `[materials]` table adds to or overrides these.
//!
//! Densities are typical values at room temperature for the common grade;
//! a part whose mass matters to better than a few per cent should give its
//! own (`[materials]`, or a density or mass on the part).

use serde::Serialize;

/// A named material: density in kg/m³ and where the value comes from.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Material {
    pub name: &'static str,
    /// kg/m³
    pub density: f64,
    pub source: &'static str,
}

const fn m(name: &'static str, density: f64, source: &'static str) -> Material {
    Material {
        name,
        density,
        source,
    }
}

/// Sources: the ASM Handbooks (vol. 1, 2 for metals), MatWeb's typical
/// values, EN 1991-1-1 (Eurocode 1) Annex A for construction materials, and
/// the Wood Handbook (USDA FPL-GTR-282) for wood at 12 % moisture.
pub const BUILT_IN: &[Material] = &[
    m(
        "steel",
        7850.0,
        "structural carbon steel, EN 1993-1-1 §3.2.6",
    ),
    m("stainless-304", 8000.0, "AISI 304, ASM Handbook vol. 1"),
    m("stainless-316", 8000.0, "AISI 316, ASM Handbook vol. 1"),
    m(
        "cast-iron",
        7200.0,
        "grey cast iron EN-GJL-250, ASM Handbook vol. 1",
    ),
    m("aluminium-6061", 2700.0, "6061-T6, ASM Handbook vol. 2"),
    m("aluminium-7075", 2810.0, "7075-T6, ASM Handbook vol. 2"),
    m("aluminium-5083", 2660.0, "5083-H116, ASM Handbook vol. 2"),
    m(
        "titanium-6al-4v",
        4430.0,
        "Ti-6Al-4V (grade 5), ASM Handbook vol. 2",
    ),
    m(
        "brass-c360",
        8500.0,
        "free-cutting brass C36000, ASM Handbook vol. 2",
    ),
    m("copper", 8940.0, "C11000 ETP copper, ASM Handbook vol. 2"),
    m("lead", 11340.0, "pure lead, ASM Handbook vol. 2"),
    m("abs", 1040.0, "ABS, MatWeb typical value"),
    m("pla", 1240.0, "PLA, MatWeb typical value"),
    m("nylon-6", 1140.0, "PA6, MatWeb typical value"),
    m("polycarbonate", 1200.0, "PC, MatWeb typical value"),
    m("pmma", 1180.0, "acrylic, MatWeb typical value"),
    m(
        "cfrp",
        1600.0,
        "carbon/epoxy laminate, 60 % fibre, MatWeb typical value",
    ),
    m(
        "gfrp",
        1900.0,
        "glass/epoxy laminate (FR-4), MatWeb typical value",
    ),
    m("plywood", 600.0, "EN 1991-1-1 Table A.3: plywood 5–6 kN/m³"),
    m("birch", 670.0, "Wood Handbook Table 5-3a, 12 % moisture"),
    m("balsa", 160.0, "Wood Handbook, 12 % moisture"),
    m("glass", 2500.0, "soda-lime glass, EN 1991-1-1 Table A.4"),
    m(
        "concrete",
        2400.0,
        "normal-weight concrete, EN 1991-1-1 Table A.1",
    ),
    m("water", 998.0, "at 20 °C"),
];

/// A built-in material by name.
pub fn built_in(name: &str) -> Option<&'static Material> {
    BUILT_IN.iter().find(|m| m.name == name)
}

/// Other spellings and common names of the built-in materials, each as
/// the start of a name (`aluminum-6061`, `aluminum 7075`) and the start of
/// the names it stands for: US and British spellings, trade names, words
/// for a family whose members carry a grade (`aluminium` → the first
/// `aluminium-…`).
const VARIANTS: &[(&str, &str)] = &[
    ("aluminum", "aluminium"),
    ("aluminium", "aluminium"),
    ("stainless-steel", "stainless"),
    ("inox", "stainless"),
    ("titanium", "titanium"),
    ("brass", "brass"),
    ("polyamide", "nylon"),
    ("nylon", "nylon"),
    ("pa6", "nylon-6"),
    ("acrylic", "pmma"),
    ("plexiglass", "pmma"),
    ("plexiglas", "pmma"),
    ("perspex", "pmma"),
    ("carbon-fibre", "cfrp"),
    ("carbon-fiber", "cfrp"),
    ("fibreglass", "gfrp"),
    ("fiberglass", "gfrp"),
    ("fr4", "gfrp"),
    ("fr-4", "gfrp"),
    ("grey-iron", "cast-iron"),
    ("gray-iron", "cast-iron"),
    ("iron", "cast-iron"),
    ("mild-steel", "steel"),
    ("carbon-steel", "steel"),
];

/// The material meant by an unknown `name`, among `names` (the built-in
/// ones and the file's own): first by spelling variant or family
/// (`aluminum` → `aluminium-6061`, `Aluminium 7075` → `aluminium-7075`,
/// `plexiglass` → `pmma`), else the nearest by a few edits
/// (`units::suggest`: `steal` → `steel`).
pub fn suggest<'a>(name: &str, names: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let names: Vec<&'a str> = names.into_iter().collect();
    let spelled = respelled(name);
    let family = format!("{spelled}-");
    names
        .iter()
        .find(|n| **n == spelled)
        .or_else(|| names.iter().find(|n| n.starts_with(&family)))
        .copied()
        .or_else(|| crate::units::suggest(name, names.iter().copied()))
        .or_else(|| crate::units::suggest(&spelled, names.iter().copied()))
}

/// `name` in lower case, blanks and `_` as `-`, a variant's start
/// (`VARIANTS`) replaced by the built-in spelling.
fn respelled(name: &str) -> String {
    let s: String = name
        .trim()
        .chars()
        .map(|c| {
            if c.is_whitespace() || c == '_' {
                '-'
            } else {
                c
            }
        })
        .flat_map(char::to_lowercase)
        .collect();
    VARIANTS
        .iter()
        .find_map(|(from, to)| {
            let rest = s.strip_prefix(from)?;
            (rest.is_empty() || rest.starts_with('-')).then(|| format!("{to}{rest}"))
        })
        .unwrap_or(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn built_in_suggestion(name: &str) -> Option<&'static str> {
        suggest(name, BUILT_IN.iter().map(|m| m.name))
    }

    #[test]
    fn the_us_spelling_of_aluminium_suggests_the_first_aluminium() {
        assert_eq!(built_in_suggestion("aluminum"), Some("aluminium-6061"));
        assert_eq!(built_in_suggestion("Aluminum"), Some("aluminium-6061"));
    }

    #[test]
    fn a_grade_in_another_spelling_suggests_that_grade() {
        assert_eq!(built_in_suggestion("aluminum-7075"), Some("aluminium-7075"));
        assert_eq!(
            built_in_suggestion("Aluminium 5083"),
            Some("aluminium-5083")
        );
        assert_eq!(
            built_in_suggestion("stainless steel 316"),
            Some("stainless-316")
        );
    }

    #[test]
    fn a_family_name_suggests_its_first_grade() {
        assert_eq!(built_in_suggestion("titanium"), Some("titanium-6al-4v"));
        assert_eq!(built_in_suggestion("brass"), Some("brass-c360"));
    }

    #[test]
    fn a_trade_or_common_name_suggests_the_material() {
        assert_eq!(built_in_suggestion("plexiglass"), Some("pmma"));
        assert_eq!(built_in_suggestion("carbon fiber"), Some("cfrp"));
        assert_eq!(built_in_suggestion("fiberglass"), Some("gfrp"));
    }

    #[test]
    fn every_variant_names_a_built_in_material_or_family() {
        for (from, to) in VARIANTS {
            assert!(
                BUILT_IN
                    .iter()
                    .any(|m| m.name == *to || m.name.starts_with(&format!("{to}-"))),
                "{from} → {to}"
            );
        }
    }

    #[test]
    fn a_plain_typo_still_suggests_the_nearest_name() {
        assert_eq!(built_in_suggestion("steal"), Some("steel"));
        assert_eq!(suggest("fom", ["foam"]), Some("foam"));
    }

    #[test]
    fn a_name_unlike_any_suggests_nothing() {
        assert_eq!(built_in_suggestion("unobtainium"), None);
    }

    #[test]
    fn names_are_unique_lowercase_and_densities_plausible() {
        for (i, a) in BUILT_IN.iter().enumerate() {
            assert!(
                BUILT_IN[i + 1..].iter().all(|b| b.name != a.name),
                "{}",
                a.name
            );
            assert_eq!(a.name, a.name.to_lowercase());
            assert!((100.0..=23_000.0).contains(&a.density), "{}", a.name);
            assert!(!a.source.is_empty());
        }
        assert_eq!(built_in("steel").map(|m| m.density), Some(7850.0));
        assert!(built_in("unobtainium").is_none());
    }
}
