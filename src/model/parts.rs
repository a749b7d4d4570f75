//! One `[[part]]` table validated into a `Part`: its keys against its
//! shape's description (`shapes::SHAPES`), its placement, mass and
//! dimensions, every range check — and its numbers kept in the file's units.

use super::Ctx;
use super::ctx::{Value, Whose};
use super::keys::{first, key_spans, quantity_key, span_of};
use super::material::is_thin_shell;
use super::raw::{RawPart, Vector};
use super::rotation::Orientation;
use super::tolerance::{Index, Recorder};
use crate::diag::Diagnostic;
use crate::la::Vector3;
use crate::part::{MassSpec, Part, Place, Solid, Spec};
use crate::shapes::{Fixed, Mover, Reader, Shape, Spanned as Spans};
use crate::units::{self, Dim};
use std::ops::Range;
use toml::Spanned;

impl Ctx<'_> {
    /// One part, and the solid it idealises with its real size (file
    /// units) when the file gives a plate's `thickness` or a rod's
    /// `diameter`.
    pub(super) fn part(
        &self,
        rec: &mut Recorder,
        index: usize,
        raw: &Spanned<RawPart>,
    ) -> Result<(Part, Option<(Solid, f64)>), Diagnostic> {
        let p = raw.get_ref();
        let Some(shape_raw) = &p.shape else {
            return Err(self.err(raw.span(), "missing key `shape`").help(format!(
                "every part needs `shape`, one of {} (or `include` of another part file)",
                Shape::quoted_names()
            )));
        };
        let shape = Shape::from_name(shape_raw.get_ref()).ok_or_else(|| {
            let names: Vec<&str> = crate::shapes::SHAPES.iter().map(|s| s.name).collect();
            self.err(
                shape_raw.span(),
                format!("unknown shape {:?}", shape_raw.get_ref()),
            )
            .label(
                match units::suggest(shape_raw.get_ref(), names.iter().copied()) {
                    Some(s) => format!("did you mean \"{s}\"?"),
                    None => format!("expected one of {}", names.join(", ")),
                },
            )
        })?;
        let s = shape.name();
        rec.enter_part(shape, super::keys::COMMON);
        self.tol_needs_mass(p)?;

        // Keys that exist in part files but do not apply to this shape.
        let keys = key_spans(p);
        let info = shape.info();
        let accepted = info.keys;
        if let Some((key, span)) = keys
            .iter()
            .filter(|(k, _)| !super::tolerance::accepts(accepted, k))
            .find_map(|(k, s)| s.clone().map(|s| (*k, s)))
        {
            return Err(self
                .err(span, format!("`{key}` does not apply to {}", info.a_name()))
                .help(info.help));
        }

        // Placement: canonical (size/length, center, rotation) or by edges.
        let spans_of = |names: &[&'static str]| -> Vec<(&'static str, Option<Range<usize>>)> {
            names.iter().map(|k| (*k, span_of(&keys, k))).collect()
        };
        let by_edges = spans_of(info.spanned.map_or(&[][..], Spans::keys));
        let canonical = spans_of(info.centred);
        let (by_edges, canonical) = (&by_edges[..], &canonical[..]);
        if let (Some((a, sa)), Some((b, sb))) = (first(canonical), first(by_edges)) {
            let (later, earlier, span) = if sa.start > sb.start {
                (a, b, sa)
            } else {
                (b, a, sb)
            };
            return Err(self
                .err(
                    span,
                    format!(
                        "`{later}` conflicts with `{earlier}`: a {s} is placed one way or the other"
                    ),
                )
                .help(info.help));
        }
        let orientation = match &p.rotation {
            Some(r) => self.rotation(r)?,
            None => Orientation::Identity,
        };
        // Its mass or density first (its tolerance the part's first
        // source), then its other numbers, each read once in the file's
        // units and checked as its module asks for them.
        let density = info
            .density
            .and_then(|k| Some((quantity_key(p, k.key)?, k)));
        let given = match (&p.mass, density) {
            (Some(m), _) => {
                let v = self.value(rec, m, "mass", Dim::MASS)?;
                self.mass_tol(rec, p, m, v.file)?;
                Some(v)
            }
            (None, Some((d, k))) => Some(self.value(rec, d, k.key, k.dim)?),
            (None, None) => None,
        };
        let place = Place::read(
            shape,
            &mut PartReader {
                ctx: self,
                rec: &mut *rec,
                p,
                shape,
                span: raw.span(),
                by_edges: first(by_edges).is_some(),
                orientation,
                from: None,
            },
        )?;
        // The checks of its mass and moments are in SI, on its numbers
        // converted there.
        let mut si_place = place.clone();
        si_place.moved(&InSi {
            length: self.units.factor(Dim::LENGTH).value(),
            mass: self.units.factor(Dim::MASS).value(),
        });

        // Mass: exactly one of `mass` and the shape's density.
        let density = density.map(|(d, _)| d);
        let positive = |q: &Spanned<super::raw::Quantity>, key: &str| {
            let v = given.expect("invariant: a given mass or density is read above");
            if v.si > 0.0 {
                Ok(v)
            } else {
                Err(self.err(q.span(), format!("`{key}` must be positive")))
            }
        };
        let material = self.material(rec, shape, p, raw.span())?;
        if let Some(super::material::Material { span, .. }) = &material {
            let other = [
                ("mass", p.mass.as_ref()),
                (shape.density_key().unwrap_or("density"), density),
            ];
            if let Some((k, q)) = other.iter().find_map(|(k, q)| q.map(|q| (*k, q))) {
                let (span, later, earlier) = if q.span().start > span.start {
                    (q.span(), k, "material")
                } else {
                    (span.clone(), "material", k)
                };
                return Err(self.err(
                    span,
                    format!("`{later}` conflicts with `{earlier}`: give exactly one"),
                ));
            }
        }
        let measure = || si_place.measure::<f64, _>(Fixed);
        let roundings = material.as_ref().map_or(0.0, |m| m.roundings);
        let (mass, mass_spec) = match (&p.mass, density, shape.density_key(), &material) {
            (None, None, _, Some(super::material::Material { si, file, span, .. })) => {
                if is_thin_shell(&mut si_place.clone()) {
                    return Err(self.thin_shell(span.clone(), s));
                }
                let m = si * measure();
                if !(m >= f64::MIN_POSITIVE && m.is_finite()) {
                    return Err(self.err(span.clone(), "the material's density times the size gives a mass out of the range of f64"));
                }
                (m, MassSpec::Density(*file))
            }
            (Some(m), Some(d), Some(dk), _) => {
                let (span, later, earlier) = if d.span().start > m.span().start {
                    (d.span(), dk, "mass")
                } else {
                    (m.span(), "mass", dk)
                };
                return Err(self.err(
                    span,
                    format!("`{later}` conflicts with `{earlier}`: give exactly one"),
                ));
            }
            (Some(m), _, _, _) => {
                let m = positive(m, "mass")?;
                (m.si, MassSpec::Given(m.file))
            }
            (None, Some(d), Some(dk), _) => {
                let rho = positive(d, dk)?;
                if is_thin_shell(&mut si_place.clone()) {
                    return Err(self.thin_shell(d.span(), s));
                }
                let m = rho.si * measure();
                if !(m >= f64::MIN_POSITIVE && m.is_finite()) {
                    let what = if m.is_finite() {
                        "too small"
                    } else {
                        "too large"
                    };
                    return Err(self.err(
                        d.span(),
                        format!("`{dk}` times the size gives a mass {what} for f64"),
                    ));
                }
                (m, MassSpec::Density(rho.file))
            }
            (None, _, Some(dk), _) => {
                return Err(self.err(
                    raw.span(),
                    format!("this {s} needs `mass`, `{dk}` or `material`"),
                ));
            }
            (None, _, None, _) => {
                return Err(self.err(raw.span(), format!("this {s} needs `mass`")));
            }
        };
        let name = match &p.name {
            Some(n) => n.get_ref().clone(),
            None => format!("part {}", index + 1),
        };
        // Each edge contributes m a²/12: it must neither overflow nor vanish
        // (in SI, the moments the shape's module counts as independent).
        let (j, _) = si_place.own_second_moment::<f64, _>(mass, None, Fixed);
        let (parts, count, _) = si_place.independent_moments(mass, &j);
        let parts = &parts[..count];
        let nonzero = parts.iter().filter(|x| **x >= f64::MIN_POSITIVE).count();
        if !parts.iter().all(|x| x.is_finite()) {
            // At the key that gives the size (m·a² overflows through it).
            let sizes: Vec<&str> = info
                .sizes
                .iter()
                .chain(info.spanned.map_or(&[][..], Spans::keys))
                .copied()
                .filter(|k| *k != "corner")
                .collect();
            let size = keys.iter().find_map(|(k, span)| {
                sizes
                    .contains(k)
                    .then(|| span.clone().map(|s| (*k, s)))
                    .flatten()
            });
            let (span, what) = match size {
                Some((k, span)) => (span, format!("`{k}`: ")),
                None => (raw.span(), String::new()),
            };
            return Err(self
                .err(
                    span,
                    format!("{what}the second moments of `{name}` overflow the range of f64"),
                )
                .help("are its sizes or mass in the wrong units?"));
        }
        if nonzero < shape.nonzero_moments() {
            return Err(self.err(
                raw.span(),
                format!("the second moments of `{name}` underflow the range of f64"),
            ));
        }
        let real = match info.real_size {
            Some((key, solid)) => match quantity_key(p, key) {
                Some(q) => {
                    let read = material.as_ref().and_then(|m| m.size);
                    Some(self.real_size(rec, solid, q, key, mass, read)?)
                }
                None => None,
            },
            None => None,
        };
        let spec = Spec {
            mass: mass_spec,
            place,
            removed: matches!(&p.remove, Some(r) if *r.get_ref()),
            placed: crate::part::Placed::default().with_mass(roundings),
        };
        self.in_file_range(&spec, &name, raw.span())?;
        rec.record_material(p, &spec);
        let tol = rec.leave_part();
        let part = Part {
            tol,
            material: p.material.as_deref().map(|m| m.get_ref().as_str().into()),
            // NOTE: a part the file does not name keeps no name: the walk
            // names it `part N` when a name is asked for (`model::walk`).
            // A string of its own for each of a million parts, made
            // between the reader's short-lived allocations, left the heap
            // fragmented: 60 % more memory than the parts themselves.
            name: if p.name.is_some() {
                name
            } else {
                String::new()
            },
            named: p.name.is_some(),
            spec,
            assembly: Vec::new(),
            span: raw.span(),
        };
        Ok((part, real))
    }

    /// The composer works in the file's units (see `Spec`), so the part's
    /// mass and second moments must be normal f64 there too, not only in
    /// SI: a tiny part in a file of kilometres and tonnes can be subnormal
    /// (a few bits of precision) in file units while fine in SI, and a huge
    /// one in micrometres and milligrams can overflow.
    pub(super) fn in_file_range(
        &self,
        spec: &Spec,
        name: &str,
        span: Range<usize>,
    ) -> Result<(), Diagnostic> {
        let m = crate::part::mass_of::<f64>(spec).abs();
        let j = crate::part::own_second_moment::<f64>(spec, m);
        let (parts, count, expected) = spec.place.independent_moments(m, &j);
        let parts = &parts[..count];
        let u = self.units;
        let units = || format!("{} and {}", u.length, u.mass);
        let fix =
            "give the file units closer to the part's size (`units = { length = .., mass = .. }`)";
        if !(m.is_finite()
            && j.iter().flatten().all(|x| x.is_finite())
            && parts.iter().all(|x| x.is_finite()))
        {
            return Err(self
                .err(span, format!("the mass properties of `{name}` overflow the range of f64 in the file's units ({})", units()))
                .help(fix));
        }
        let normal = parts.iter().filter(|x| **x >= f64::MIN_POSITIVE).count();
        if m < f64::MIN_POSITIVE || normal < expected {
            return Err(self
                .err(span, format!("the mass properties of `{name}` underflow the range of f64 in the file's units ({}): too few digits to compute with", units()))
                .help(fix));
        }
        Ok(())
    }
}

/// A part's numbers as its shape's module reads them (`shapes::Reader`):
/// each key read once, in the file's units, and checked as it is read
/// (missing, out of range, its tolerance recorded).
pub(super) struct PartReader<'c, 'p, 'r> {
    pub(super) ctx: &'c Ctx<'c>,
    /// The file's tolerances: the part's are recorded as it is read.
    pub(super) rec: &'r mut Recorder,
    pub(super) p: &'p RawPart,
    pub(super) shape: Shape,
    /// The part's table, where a missing key is reported.
    pub(super) span: Range<usize>,
    pub(super) by_edges: bool,
    pub(super) orientation: Orientation,
    /// A rod's `from` (SI) once read: `to` must differ from it.
    pub(super) from: Option<Vector3<f64>>,
}

impl<'p> PartReader<'_, 'p, '_> {
    /// The key `key` is missing.
    fn missing(&self, key: &str) -> Diagnostic {
        self.ctx.missing(self.shape, self.span.clone(), key)
    }

    /// The rows under `key` (`edges`, `vertices`, `inertia`), or the
    /// error that they are missing.
    fn rows(&self, key: &str) -> Result<&'p Spanned<Vec<Vector>>, Diagnostic> {
        let p = self.p;
        match key {
            "edges" => p.edges.as_deref(),
            "vertices" => p.vertices.as_deref(),
            "inertia" => p.inertia.as_deref(),
            _ => unreachable!("`{key}` is no key of rows"),
        }
        .ok_or_else(|| self.missing(key))
    }
}

/// Moves a placed shape from the file's units to SI (`Place::moved`).
struct InSi {
    length: f64,
    mass: f64,
}

impl Mover for InSi {
    fn point(&self, p: [f64; 3]) -> [f64; 3] {
        p.map(|x| x * self.length)
    }

    fn dir(&self, e: [f64; 3]) -> [f64; 3] {
        e.map(|x| x * self.length)
    }

    fn turn(&self, _: &mut Orientation) {}

    fn length(&self) -> f64 {
        self.length
    }

    fn mass(&self) -> f64 {
        self.mass
    }
}

impl Reader for PartReader<'_, '_, '_> {
    fn point(&mut self, key: &'static str) -> Result<[f64; 3], Diagnostic> {
        let p = self.p;
        let v = match key {
            "center" => p.center.as_ref(),
            "corner" => p.corner.as_deref(),
            "from" => p.from.as_deref(),
            "to" => p.to.as_deref(),
            _ => unreachable!("`{key}` is no point key"),
        }
        .ok_or_else(|| self.missing(key))?;
        let (file, si) = self.ctx.value3(self.rec, 0, v, key, Dim::LENGTH)?;
        match (key, self.from) {
            ("from", _) => self.from = Some(si),
            ("to", Some(from)) => self.ctx.rod_ends(from, si, v)?,
            _ => {}
        }
        Ok(file)
    }

    fn origin(&mut self) -> Result<[f64; 3], Diagnostic> {
        match &self.p.origin {
            Some(o) => Ok(self.ctx.value3(self.rec, 0, o, "origin", Dim::LENGTH)?.0),
            None => Ok([0.0; 3]),
        }
    }

    fn vectors<const N: usize>(&mut self, key: &'static str) -> Result<[[f64; 3]; N], Diagnostic> {
        let rows = self.rows(key)?;
        match key {
            "edges" => self.ctx.edges(self.rec, self.shape, rows),
            "vertices" => {
                let v = self.ctx.triangle(self.rec, rows)?;
                // A triangle's module asks for its 3.
                Ok(std::array::from_fn(|k| v[k]))
            }
            _ => unreachable!("`{key}` is no key of vectors"),
        }
    }

    fn sizes<const N: usize>(&mut self) -> Result<[f64; N], Diagnostic> {
        let size = self.p.size.as_ref().ok_or_else(|| self.missing("size"))?;
        let items = self
            .ctx
            .exactly(size, N, Whose::Key("size"), "components")?;
        let mut out = [Value { file: 0.0, si: 0.0 }; N];
        for (k, (e, q)) in out.iter_mut().zip(items).enumerate() {
            *e = self
                .ctx
                .value_at(self.rec, Index::component(k), q, "size", Dim::LENGTH)?;
        }
        if let Some((_, q)) = out.iter().zip(items).find(|(v, _)| !(v.si > 0.0)) {
            return Err(self.ctx.err(q.span(), "`size` must be positive"));
        }
        Ok(out.map(|v| v.file))
    }

    fn length(&mut self, key: &'static str) -> Result<f64, Diagnostic> {
        let l = self.p.length.as_deref().ok_or_else(|| self.missing(key))?;
        Ok(self.ctx.positive_value(self.rec, l, key, Dim::LENGTH)?.file)
    }

    fn radii(&mut self) -> Result<[f64; 2], Diagnostic> {
        let (ctx, shape, span) = (self.ctx, self.shape, self.span.clone());
        ctx.radii(self.rec, self.p, || ctx.missing(shape, span, "radius"))
    }

    fn cone(&mut self) -> Result<[f64; 5], Diagnostic> {
        self.ctx.cone(self.rec, self.p, self.span.clone())
    }

    fn torus(&mut self) -> Result<[f64; 3], Diagnostic> {
        self.ctx.torus(self.rec, self.p, self.span.clone())
    }

    fn polygon(&mut self) -> Result<Vec<[f64; 2]>, Diagnostic> {
        self.ctx.polygon(self.rec, self.p, self.span.clone())
    }

    fn inertia(&mut self) -> Result<[[f64; 3]; 3], Diagnostic> {
        let rows = self.rows("inertia")?;
        self.ctx.given_inertia(self.rec, self.p, rows)
    }

    fn orientation(&self) -> Orientation {
        self.orientation.clone()
    }

    fn by_edges(&self) -> bool {
        self.by_edges
    }

    fn quantity(&mut self, key: &'static str) -> Result<f64, Diagnostic> {
        Ok(super::keys::read_own(self.ctx, self.rec, self.p, key, 1)?[0])
    }

    fn quantities<const N: usize>(&mut self, key: &'static str) -> Result<[f64; N], Diagnostic> {
        let v = super::keys::read_own(self.ctx, self.rec, self.p, key, N)?;
        Ok(std::array::from_fn(|i| v[i]))
    }

    /// A mesh is read with its file (`model::mesh`); a part here without
    /// one lacks it.
    fn elsewhere(&self) -> Diagnostic {
        self.missing("file")
    }
}

#[cfg(test)]
mod tests {
    use crate::diag::Source;
    use crate::model::Model;

    fn parse(text: &str) -> Result<Model, String> {
        Model::parse(&Source::new("f.toml", text)).map_err(|e| e.to_string())
    }

    fn part(keys: &str) -> String {
        format!("[[part]]\n{keys}\n")
    }

    #[test]
    fn a_density_on_a_capsule_whose_inner_radius_is_its_radius_is_refused() {
        let e = parse(&part(
            "shape = \"capsule\"\ndensity = 1\nradius = 1\ninner_radius = 1\nlength = 2\ncenter = [0, 0, 0]",
        ))
        .unwrap_err();
        assert!(e.contains("is a thin shell"), "{e}");
    }

    #[test]
    fn a_cone_hollow_to_its_rim_at_one_end_only_has_a_volume() {
        let m = parse(&part(
            "shape = \"cone\"\ndensity = 1\nradius = 1\ninner_radius = 1\ntop_radius = 1\ntop_inner_radius = 0.5\nlength = 2\ncenter = [0, 0, 0]",
        ));
        assert!(m.is_ok(), "{m:?}");
    }

    #[test]
    fn a_torus_is_a_thin_shell_by_its_tube_not_its_centre_line() {
        let torus = |inner: &str| {
            parse(&part(&format!(
                "shape = \"torus\"\ndensity = 1\nradius = 2\ntube_radius = 1\n{inner}center = [0, 0, 0]"
            )))
        };
        assert!(torus("").is_ok());
        let e = torus("inner_tube_radius = 1\n").unwrap_err();
        assert!(e.contains("is a thin shell"), "{e}");
    }

    #[test]
    fn each_toleranced_key_of_a_part_is_one_source() {
        let m = parse(&part(
            "shape = \"box\"\nmass = \"2 kg ± 0.1 kg\"\nsize = [\"1 m ± 1 mm\", 1, \"1 m ± 2 mm\"]\ncenter = [\"0 m ± 1 mm\", 0, 0]",
        ))
        .unwrap();
        let keys: Vec<&str> = m.sources.iter().map(|s| s.key.as_str()).collect();
        assert_eq!(keys, ["mass", "size[0]", "size[2]", "center[0]"]);
    }

    #[test]
    fn a_key_in_the_file_s_units_is_range_checked_in_si_as_it_is_read() {
        // 1e-306 mm is normal in the file's units and subnormal in SI.
        let e = parse(&format!(
            "units = {{ length = \"mm\" }}\n{}",
            part("shape = \"box\"\nmass = 1\nsize = [1e-306, 1, 1]\ncenter = [0, 0, 0]")
        ))
        .unwrap_err();
        assert!(e.contains("f.toml:5:9: error: `size` is too small"), "{e}");
    }

    #[test]
    fn a_tolerance_on_a_prism_s_length_moves_its_length_and_none_stands_on_its_polygon() {
        let prism = |length: &str, x: &str| {
            parse(&part(&format!(
                "shape = \"prism\"\nmass = 1\npolygon = [[0, 0], [{x}, 0], [0, 1]]\nlength = {length}"
            )))
        };
        let m = prism("\"2 m ± 1 mm\"", "1").unwrap();
        assert_eq!(m.sources.len(), 1);
        let e = prism("2", "\"1 m ± 1 mm\"").unwrap_err();
        assert!(e.contains("a tolerance is not allowed on `polygon`"), "{e}");
    }

    #[test]
    fn a_rod_s_diameter_is_its_real_size_and_takes_no_tolerance() {
        let e = parse(&part(
            "shape = \"rod\"\nmass = 1\nlength = 1\ndiameter = \"1 cm ± 1 mm\"\ncenter = [0, 0, 0]",
        ))
        .unwrap_err();
        assert!(
            e.contains("a tolerance is not allowed on `diameter`"),
            "{e}"
        );
    }

    #[test]
    fn a_diameter_s_tolerance_moves_the_radius_it_gives() {
        let m = parse(&part(
            "shape = \"sphere\"\nmass = 1\ndiameter = \"2 m ± 2 mm\"\ncenter = [0, 0, 0]",
        ))
        .unwrap();
        let crate::model::Item::Part { part, .. } = &m.items[0] else {
            panic!("a part");
        };
        let deps = part.tol.as_deref().expect("a tolerance");
        assert_eq!(deps.len(), 1);
        assert_eq!(deps[0].slot, crate::shapes::Slot::Radius);
        assert_eq!(deps[0].rate, 0.001);
    }
}
