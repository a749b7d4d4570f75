//! One `[[part]]` table validated into a `Part`: its keys against its
//! shape's description (`shapes::SHAPES`), its placement, mass and
//! dimensions, every range check — and its numbers kept in the file's units.

use super::Ctx;
use super::keys::{first, key_spans, quantity_key, span_of};
use super::material::is_thin_shell;
use super::place::{positive_products, tensor_convention};
use super::raw::{RawPart, Vector};
use super::rotation::Orientation;
use crate::diag::Diagnostic;
use crate::part::{MassSpec, Part, Place, Solid, Spec};
use crate::shapes::Reader;
use crate::shapes::{Dims, Shape, Spanned as Spans};
use crate::units::{self, Dim};
use std::ops::Range;
use toml::Spanned;

impl Ctx<'_> {
    /// The part's numbers in the file's units, read after `part` has
    /// validated them (so only a conversion overflow can fail here).
    pub(super) fn spec(
        &self,
        shape: Shape,
        p: &RawPart,
        by_edges: bool,
        orientation: Orientation,
        material: Option<f64>,
    ) -> Result<Spec, Diagnostic> {
        let info = shape.info();
        let density = info
            .density
            .and_then(|k| Some((quantity_key(p, k.key)?, k)));
        let mass = match (&p.mass, density) {
            (Some(m), _) => MassSpec::Given(self.mass_with_tol(p, m)?),
            (None, Some((d, kind))) => {
                MassSpec::Density(self.file_quantity(d, kind.key, kind.dim)?)
            }
            (None, None) => MassSpec::Density(
                material.expect("`part` checked that a mass, density or material is given"),
            ),
        };
        let place = Place::read(
            shape,
            &PartReader {
                ctx: self,
                p,
                by_edges,
                orientation,
            },
        )?;
        self.spec_of(mass, p, place)
    }

    /// A part's `Spec` from its mass and placement.
    fn spec_of(&self, mass: MassSpec, p: &RawPart, place: Place) -> Result<Spec, Diagnostic> {
        Ok(Spec {
            mass,
            place,
            removed: matches!(&p.remove, Some(r) if *r.get_ref()),
            placed: Default::default(),
        })
    }

    /// One part, and the solid it idealises with its real size (file
    /// units) when the file gives a plate's `thickness` or a rod's
    /// `diameter`.
    pub(super) fn part(
        &self,
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
        self.enter_part(shape);
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
                .err(span, format!("`{key}` does not apply to a {s}"))
                .help(info.help));
        }

        // Placement: canonical (size/length, center, rotation) or by edges.
        let spans_of = |names: &[&'static str]| -> Vec<(&'static str, Option<Range<usize>>)> {
            names.iter().map(|k| (*k, span_of(&keys, k))).collect()
        };
        let by_edges = spans_of(info.spanned.map_or(&[][..], Spans::keys));
        let canonical = spans_of(info.centred);
        let (by_edges, canonical) = (&by_edges[..], &canonical[..]);
        let edges_given = first(by_edges).is_some();
        let (orientation, dims) = match (first(canonical), first(by_edges)) {
            (Some((a, sa)), Some((b, sb))) => {
                let (later, earlier, span) = if sa.start > sb.start {
                    (a, b, sa)
                } else {
                    (b, a, sb)
                };
                return Err(self
                    .err(span, format!("`{later}` conflicts with `{earlier}`: a {s} is placed one way or the other"))
                    .help(info.help));
            }
            (_, Some(_)) => self.placement_by_edges(shape, p, raw.span())?,
            _ => self.placement_canonical(shape, p, raw.span())?,
        };

        // Mass: exactly one of `mass` and the shape's density.
        let density = info.density.and_then(|k| quantity_key(p, k.key));
        let material = self.material(shape, p, raw.span())?;
        if let Some((_, _, span)) = &material {
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
        let mass = match (&p.mass, density, shape.density_key()) {
            (None, None, _) if material.is_some() => {
                let (si, _, span) = material.clone().expect("checked");
                if is_thin_shell(shape, &dims) {
                    return Err(self.thin_shell(span, s));
                }
                let m = si * shape.measure(&dims);
                if !(m >= f64::MIN_POSITIVE && m.is_finite()) {
                    return Err(self.err(span, "the material's density times the size gives a mass out of the range of f64"));
                }
                m
            }
            (Some(m), Some(d), Some(dk)) => {
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
            (Some(m), _, _) => self.positive(m, "mass", Dim::MASS)?,
            (None, Some(d), Some(dk)) => {
                let dim = info.density.expect("a density key has a kind").dim;
                let rho = self.positive(d, dk, dim)?;
                if is_thin_shell(shape, &dims) {
                    return Err(self.thin_shell(d.span(), s));
                }
                let m = rho * shape.measure(&dims);
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
                m
            }
            (None, _, Some(dk)) => {
                return Err(self.err(
                    raw.span(),
                    format!("this {s} needs `mass`, `{dk}` or `material`"),
                ));
            }
            (None, _, None) => return Err(self.err(raw.span(), format!("this {s} needs `mass`"))),
        };
        let name = match &p.name {
            Some(n) => n.get_ref().clone(),
            None => format!("part {}", index + 1),
        };
        let local_second_moment = shape.local_second_moment(mass, &dims);
        // Each edge contributes m a²/12: it must neither overflow nor vanish.
        let expected_nonzero = shape.nonzero_moments();
        let nonzero = local_second_moment
            .iter()
            .filter(|x| **x >= f64::MIN_POSITIVE)
            .count();
        if !local_second_moment.iter().all(|x| x.is_finite()) {
            // At the key that gives the size (m·a² overflows through it).
            let sizes: Vec<&str> = info
                .dims
                .keys()
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
        if nonzero < expected_nonzero {
            return Err(self.err(
                raw.span(),
                format!("the second moments of `{name}` underflow the range of f64"),
            ));
        }
        let real = match info.real_size {
            Some((key, solid)) => match quantity_key(p, key) {
                Some(q) => Some(self.real_size(solid, q, key, mass)?),
                None => None,
            },
            None => None,
        };
        if info.dims == Dims::Given {
            self.given_inertia(p)?;
        }
        let spec = self.spec(
            shape,
            p,
            edges_given,
            orientation.clone(),
            material.map(|m| m.1),
        )?;
        self.in_file_range(&spec, &name, raw.span())?;
        self.record_material(p, &spec);
        let tol = self.leave_part();
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

/// A part's numbers as its shape's module reads them (`shapes::Reader`),
/// in the file's units, after `Ctx::part` has validated them: so a key a
/// module asks for is there, and only a conversion can fail.
pub(super) struct PartReader<'c, 'p> {
    pub(super) ctx: &'c Ctx<'c>,
    pub(super) p: &'p RawPart,
    pub(super) by_edges: bool,
    pub(super) orientation: Orientation,
}

/// A key `Ctx::part` checked is given.
fn given<V: std::borrow::Borrow<Vector>>(v: &Option<V>) -> &Vector {
    v.as_ref()
        .expect("`part` checked the placement keys")
        .borrow()
}

impl Reader for PartReader<'_, '_> {
    fn point(&self, key: &'static str) -> Result<[f64; 3], Diagnostic> {
        let p = self.p;
        let v = match key {
            "center" => given(&p.center),
            "corner" => given(&p.corner),
            "from" => given(&p.from),
            "to" => given(&p.to),
            _ => unreachable!("`{key}` is no point key"),
        };
        self.ctx.file_vec3(v, key, Dim::LENGTH)
    }

    fn origin(&self) -> Result<[f64; 3], Diagnostic> {
        match &self.p.origin {
            Some(o) => self.ctx.file_vec3(o, "origin", Dim::LENGTH),
            None => Ok([0.0; 3]),
        }
    }

    fn vectors<const N: usize>(&self, key: &'static str) -> Result<[[f64; 3]; N], Diagnostic> {
        let rows = match key {
            "edges" => self.p.edges.as_deref(),
            "vertices" => self.p.vertices.as_deref(),
            _ => unreachable!("`{key}` is no key of vectors"),
        }
        .expect("`part` checked the placement keys");
        let mut out = [[0.0; 3]; N];
        for (k, (v, raw)) in out.iter_mut().zip(rows.get_ref()).enumerate() {
            self.ctx.tol.borrow_mut().row = k;
            *v = self.ctx.file_vec3(raw, key, Dim::LENGTH)?;
        }
        Ok(out)
    }

    fn sizes<const N: usize>(&self) -> Result<[f64; N], Diagnostic> {
        let size = self.p.size.as_ref().expect("`part` checked the size");
        let mut out = [0.0; N];
        for (k, (e, q)) in out.iter_mut().zip(size.get_ref()).enumerate() {
            self.ctx.tol.borrow_mut().component = k;
            *e = self.ctx.file_quantity(q, "size", Dim::LENGTH)?;
        }
        Ok(out)
    }

    fn length(&self, key: &'static str) -> Result<f64, Diagnostic> {
        let l = self.p.length.as_deref().expect("`part` checked the length");
        self.ctx.file_quantity(l, key, Dim::LENGTH)
    }

    fn radii(&self) -> Result<[f64; 2], Diagnostic> {
        let r = self
            .ctx
            .radius_of(self.p, false)?
            .expect("`part` checked the radius");
        let outer = self.ctx.radius_file(&r)?;
        let inner = match self.ctx.radius_of(self.p, true)? {
            Some(q) => self.ctx.radius_file(&q)?,
            None => 0.0,
        };
        Ok([outer, inner])
    }

    fn cone(&self) -> Result<[f64; 5], Diagnostic> {
        self.ctx.cone_file(self.p)
    }

    fn torus(&self) -> Result<[f64; 3], Diagnostic> {
        self.ctx.torus_file(self.p)
    }

    fn polygon(&self) -> Result<Vec<[f64; 2]>, Diagnostic> {
        self.ctx.polygon_file(self.p)
    }

    fn inertia(&self) -> Result<[[f64; 3]; 3], Diagnostic> {
        let rows = self
            .p
            .inertia
            .as_deref()
            .expect("`part` checked the inertia");
        let mut m = [[0.0; 3]; 3];
        for (r, raw) in m.iter_mut().zip(rows.get_ref()) {
            *r = self.ctx.file_vec3(raw, "inertia", Dim::INERTIA)?;
        }
        Ok(tensor_convention(m, positive_products(self.p)))
    }

    fn orientation(&self) -> Orientation {
        self.orientation.clone()
    }

    fn by_edges(&self) -> bool {
        self.by_edges
    }

    fn quantity(&self, key: &'static str) -> Result<f64, Diagnostic> {
        Ok(super::keys::read_own(self.ctx, self.p, key, 1)?[0])
    }

    fn quantities<const N: usize>(&self, key: &'static str) -> Result<[f64; N], Diagnostic> {
        let v = super::keys::read_own(self.ctx, self.p, key, N)?;
        Ok(std::array::from_fn(|i| v[i]))
    }

    fn elsewhere(&self) -> Diagnostic {
        self.ctx.err(0..0, "a mesh is read with its file")
    }
}
