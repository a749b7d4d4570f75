//! `material = "NAME"`: a named density made the shape's (times a
//! thickness or a section where the shape is thin or slender), and the real
//! sizes (`thickness`, `diameter`) of idealised plates and rods.

use super::Ctx;
use super::ctx::Value;
use super::keys::quantity_key;
use super::raw::{Quantity, RawPart};
use crate::diag::Diagnostic;
use crate::part::Solid;
use crate::shapes::{MaterialRule, Shape};
use crate::units::{self, Dim};
use std::ops::Range;
use toml::Spanned;

impl super::Model {
    /// A materials file's `[materials]`, name → density (kg/m³): a file
    /// with no parts whose tables are `[materials]` and, for its densities,
    /// `[units]` and `[params]` alone (materials kept apart from the part
    /// files that use them; `massprop materials FILE`). Each density is
    /// checked as in a part file. `Ok(None)` for any other file: it is read
    /// as the part file it is.
    pub fn materials_file(
        source: &crate::diag::Source,
        includes: &super::Includes,
    ) -> Result<Option<std::collections::BTreeMap<String, f64>>, Diagnostic> {
        if super::looks_like_a_part_file(&source.text) {
            return Ok(None);
        }
        let raw = super::Model::raw(source)?;
        let only_materials = raw.part.is_none()
            && raw.name.is_none()
            && raw.analysis.is_none()
            && raw.expect.is_none()
            && raw.growth.is_none()
            && raw.budget.is_none()
            && raw.envelope.is_none();
        let Some(table) = raw.materials.as_ref().filter(|_| only_materials) else {
            return Ok(None);
        };
        let mut ctx = Ctx {
            source,
            units: units::FileUnits::default(),
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        if let Some(u) = &raw.units {
            ctx.units = ctx.file_units(u)?;
        }
        let mut rec = super::tolerance::Recorder::default();
        ctx.read_params(
            &mut rec,
            raw.params.as_ref(),
            &super::params::flags(&includes.set)?,
        )?;
        ctx.read_materials(&mut rec, table)?;
        Ok(Some(
            ctx.materials
                .into_iter()
                .map(|(name, (si, _))| (name, si))
                .collect(),
        ))
    }
}

/// A part's material (`Ctx::material`): its density made the shape's.
pub(super) struct Material {
    /// In SI.
    pub si: f64,
    /// In the file's units.
    pub file: f64,
    /// Where `material` is.
    pub span: Range<usize>,
    /// The `thickness` or `diameter` it read, which is a real size too.
    pub size: Option<Value>,
    /// Units of f64's unit roundoff by which `file` was rounded as the
    /// density times the thickness, area or π/4 d² (`Placed::mass`; the
    /// density itself is the correctly rounded conversion the file's
    /// numbers are taken as).
    pub roundings: f64,
}

impl Ctx<'_> {
    /// The file's `[materials]`, each density checked, into `materials`.
    pub(super) fn read_materials(
        &mut self,
        rec: &mut super::tolerance::Recorder,
        table: &super::raw::Materials,
    ) -> Result<(), Diagnostic> {
        for (name, m) in table.get_ref() {
            let key = format!("density` of material `{}", crate::diag::shorten(name));
            rec.in_materials = true;
            let v = self.positive_value(rec, &m.get_ref().density, &key, Dim::DENSITY)?;
            rec.in_materials = false;
            rec.material_tolerance(name, v.file);
            self.materials.insert(name.clone(), (v.si, v.file));
        }
        Ok(())
    }

    /// A density (at `span`) on a thin shell, which has no volume.
    pub(super) fn thin_shell(&self, span: Range<usize>, shape: &str) -> Diagnostic {
        let equal = match shape {
            "cone" => "`inner_radius` = `radius` and `top_inner_radius` = `top_radius`",
            "torus" => "`inner_tube_radius` = `tube_radius`",
            _ => "`inner_radius` = `radius`",
        };
        self.err(
            span,
            format!(
                "this {shape} is a thin shell ({equal}): it has no volume for a density to fill"
            ),
        )
        .help("give its `mass`")
    }

    /// A part's `material`: its density made the shape's (per volume; times
    /// `thickness` for a plate, disk or triangle; times `area` or the area
    /// of `diameter` for a rod), in SI and in file units, with the span of
    /// `material`, and the `thickness` or `diameter` it read (a real size
    /// too: `real_size` takes it, not a second reading). `None` without
    /// one; `thickness` and `area` where they only serve a material are
    /// errors without it.
    pub(super) fn material(
        &self,
        rec: &mut super::tolerance::Recorder,
        shape: Shape,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<Option<Material>, Diagnostic> {
        let s = shape.name();
        let Some(name) = &p.material else {
            // The keys that serve only to turn a material into a mass (a
            // plate's `thickness` is also its real size, a rod's `diameter`
            // too: those stand alone).
            let info = shape.info();
            let only_with = material_keys(info.material)
                .iter()
                .filter(|k| info.real_size.is_none_or(|(r, _)| r != **k))
                .find_map(|k| quantity_key(p, k).map(|q| (*k, q)));
            if let Some((key, q)) = only_with {
                return Err(self
                    .err(
                        q.span(),
                        format!(
                            "`{key}` on a {s} goes with `material`, which it turns into a mass"
                        ),
                    )
                    .help(format!(
                        "give `material`, or drop `{key}` and give `mass` or `{}`",
                        shape.density_key().unwrap_or("density")
                    )));
            }
            return Ok(None);
        };
        let (si, file) = match self.materials.get(name.get_ref()) {
            Some(&(si, file)) => (si, file),
            None => match crate::materials::built_in(name.get_ref()) {
                Some(m) => {
                    // kg/m³ to file units by the exact factor, as a unit
                    // string is converted: one rounding, not two.
                    let to_file = units::Factor::ONE
                        .per(self.units.factor(Dim::DENSITY))
                        .expect("density factors are small fractions");
                    (m.density, to_file.apply(m.density))
                }
                None => {
                    let names: Vec<&str> = crate::materials::BUILT_IN
                        .iter()
                        .map(|m| m.name)
                        .chain(self.materials.keys().map(String::as_str))
                        .collect();
                    let d = self.err(
                        name.span(),
                        format!(
                            "unknown material {:?}",
                            crate::diag::shorten(name.get_ref())
                        ),
                    );
                    return Err(match crate::materials::suggest(name.get_ref(), names.iter().copied()) {
                        Some(s) => d.label(format!("did you mean \"{s}\"?")),
                        None => d.help("`massprop materials` lists them; add one in `[materials]`, e.g. foam = { density = \"30 kg/m^3\" }"),
                    });
                }
            },
        };
        let factor = |si_mult: f64, file_mult: f64| (si * si_mult, file * file_mult);
        let needs = |key: &str| {
            self.err(
                span.clone(),
                format!(
                    "this {s} of `{}` needs `{key}` to turn the density into a mass",
                    crate::diag::shorten(name.get_ref())
                ),
            )
        };
        let mut size = None;
        // NOTE: the product rounds once (thickness, area); π/4 d² four
        // times: π's own rounding, then three products.
        let mut roundings = 1.0;
        let out = match shape.info().material {
            MaterialRule::Volume => {
                roundings = 0.0;
                (si, file)
            }
            MaterialRule::Thickness => {
                let t = p.thickness.as_deref().ok_or_else(|| needs("thickness"))?;
                let t = self.positive_value(rec, t, "thickness", Dim::LENGTH)?;
                size = Some(t);
                factor(t.si, t.file)
            }
            MaterialRule::Section => match (&p.area, &p.diameter) {
                (Some(a), Some(_)) => {
                    return Err(self
                        .err(a.span(), "`area` conflicts with `diameter`: give one to turn the material's density into a mass")
                        .help("`diameter` (a round rod) also feeds the idealisation report; `area` is any section"));
                }
                (Some(a), None) => {
                    let a = self.positive_value(rec, a, "area", Dim::AREA)?;
                    factor(a.si, a.file)
                }
                (None, Some(d)) => {
                    let d = self.positive_value(rec, d, "diameter", Dim::LENGTH)?;
                    size = Some(d);
                    roundings = 4.0;
                    let q = std::f64::consts::PI / 4.0;
                    factor(q * d.si * d.si, q * d.file * d.file)
                }
                (None, None) => return Err(needs("area` or `diameter")),
            },
            MaterialRule::None => {
                return Err(self.err(
                    name.span(),
                    format!(
                        "`material` does not apply to {}: give `mass`",
                        shape.info().a_name()
                    ),
                ));
            }
        };
        if !(out.0.is_finite() && out.1.is_finite()) {
            // The density times the thickness, area or diameter²: point at
            // that size when the file gives one.
            let (span, what) = match (&p.thickness, &p.area, &p.diameter) {
                (Some(q), _, _) => (q.span(), "its thickness"),
                (_, Some(q), _) => (q.span(), "its area"),
                (_, _, Some(q)) => (q.span(), "its diameter"),
                _ => (name.span(), "its size"),
            };
            return Err(self.err(
                span,
                format!("the material's density times {what} overflows the range of f64"),
            ));
        }
        Ok(Some(Material {
            si: out.0,
            file: out.1,
            span: name.span(),
            size,
            roundings,
        }))
    }

    /// A plate's `thickness` or a rod's `diameter` (`key`), positive, in the
    /// file's length unit (`read` if `material` read it already). `mass` (kg) checks that the second moment it
    /// adds in `report::ideal` stays within f64: m t²/12 for the box, m d²/16
    /// = m (d/2)²/4 for the cylinder.
    pub(super) fn real_size(
        &self,
        rec: &mut super::tolerance::Recorder,
        solid: Solid,
        q: &Spanned<Quantity>,
        key: &str,
        mass: f64,
        read: Option<Value>,
    ) -> Result<(Solid, f64), Diagnostic> {
        let size = match read {
            Some(v) => v,
            None => self.positive_value(rec, q, key, Dim::LENGTH)?,
        };
        let si = size.si;
        let extra = match solid {
            Solid::Box => mass * si * si / 12.0,
            Solid::Cylinder => mass * si * si / 16.0,
        };
        if !extra.is_finite() {
            return Err(self.err(
                q.span(),
                format!(
                    "`{key}` is too large: the solid's second moment overflows the range of f64"
                ),
            ));
        }
        Ok((solid, size.file))
    }
}

/// The keys a `MaterialRule` reads beside `material`.
pub(super) fn material_keys(rule: MaterialRule) -> &'static [&'static str] {
    match rule {
        MaterialRule::Thickness => &["thickness"],
        MaterialRule::Section => &["area", "diameter"],
        MaterialRule::Volume | MaterialRule::None => &[],
    }
}

/// A placed shape whose every inner radius equals its outer one (a
/// cylinder's, disk's, sphere's, hemisphere's or capsule's `inner_radius`
/// its `radius`; a cone's at both ends; a torus's `inner_tube_radius` its
/// `tube_radius`): a thin shell, of no volume (its mass spread evenly over
/// the surface). Read by the slots its module names (`Place::numbers`).
pub(super) fn is_thin_shell(place: &mut crate::part::Place) -> bool {
    use crate::shapes::Slot;
    let mut radii = [None; 6];
    place.numbers(&mut |slot, x| {
        let at = match slot {
            Slot::Radius => 0,
            Slot::InnerRadius => 1,
            Slot::TopRadius => 2,
            Slot::TopInnerRadius => 3,
            Slot::TubeRadius => 4,
            Slot::InnerTubeRadius => 5,
            Slot::Mass
            | Slot::At(_)
            | Slot::Size(_)
            | Slot::Length
            | Slot::Edge(..)
            | Slot::To(_)
            | Slot::Vertex(..)
            | Slot::Own(..) => return,
        };
        radii[at] = Some(*x);
    });
    let pairs = [(0, 1), (2, 3), (4, 5)];
    let inner = pairs.iter().filter(|(_, i)| radii[*i].is_some()).count();
    inner > 0
        && pairs
            .iter()
            .all(|&(o, i)| radii[i].is_none() || radii[i] == radii[o])
}
