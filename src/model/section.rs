//! The tables of a part file that the fast path (`fast`) passes over,
//! `[expect]` and `[materials]`: read by serde alone, each from its own
//! slice of the file, their spans moved to the file's (`raw::Shift`).

use super::raw::{RawFile, Section, Shift};
use toml::Spanned;

impl Section {
    /// The `[expect]` and `[materials]` of `sections`, each read by serde
    /// from its own slice of `text` (no copy), spans shifted to the file's.
    /// `None` if serde finds anything wrong there, or a table is split over
    /// more than one section (`[materials]` and `[materials.steel]`): the
    /// whole file is then read by serde, which says what is wrong.
    pub fn read(text: &str, sections: &[Section]) -> Option<Sections> {
        let mut out = Sections::default();
        for s in sections {
            let raw: RawFile = toml::from_str(&text[s.span.clone()]).ok()?;
            if let Some(e) = raw.expect {
                if out.expect.is_some() {
                    return None;
                }
                out.expect = Some(e.shift(s.span.start));
            }
            if let Some(m) = raw.materials {
                if out.materials.is_some() {
                    return None;
                }
                out.materials = Some(m.shift(s.span.start));
            }
        }
        Some(out)
    }
}

/// What the sections hold.
#[derive(Default)]
pub struct Sections {
    pub expect: Option<Spanned<super::raw::RawExpect>>,
    pub materials: Option<super::raw::Materials>,
}

#[cfg(test)]
mod tests {
    use super::super::fast::tests::{declines, same};

    /// `[expect]` and `[materials]` are read by serde alone, each from its
    /// own slice of the file, with the file's spans; the rest by the fast
    /// path. A table split over two sections, or written as dotted keys,
    /// goes to serde whole.
    #[test]
    fn expectations_and_materials_are_read_by_serde_alone_with_the_files_spans() {
        let part = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
        let expect = "[expect]\nmass = { max = 2 }\ncenter_of_mass.x = { value = \"0 mm\", tol = \"1 mm\" }\n";
        let materials = "[materials]\nfoam = { density = \"30 kg/m^3\" }\n";
        same(&format!("{part}{expect}"));
        same(&format!(
            "{materials}{part}{part}{expect}[analysis]\nomega = [0, 0, 1]\n"
        ));
        same(&format!("{part}[ expect ]\nmass = {{ max = 2 }}\n{part}"));
        same(&format!("{part}[expect.inertia_com]\nxx = {{ max = 2 }}\n"));
        same(&format!("{part}[materials.steel]\ndensity = 7850\n"));
        same(&format!(
            "# expected by Monday\nname = \"as expected\"\n{part}"
        ));
        declines(&format!("expect.mass = {{ max = 2 }}\n{part}"));
        declines(&format!(
            "{materials}{part}[materials.steel]\ndensity = 7850\n"
        ));
        declines(&format!(
            "{part}{expect}[expect.inertia_com]\nxx = {{ max = 2 }}\n"
        ));
        // An error inside a section: serde says it, for the whole file.
        declines(&format!("{part}[expect]\nmass = {{ max = }}\n"));
        declines(&format!("{part}[expect]\nmass = {{ maks = 2 }}\n"));
        declines(&format!("{part}[expect]\n[expect]\n"));
        declines(&format!("{part}[[expect]]\n"));
    }
}
