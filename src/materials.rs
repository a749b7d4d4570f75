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

#[cfg(test)]
mod tests {
    use super::*;

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
