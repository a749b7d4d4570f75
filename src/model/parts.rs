//! One `[[part]]` table validated into a `Part`: its keys against its
//! shape's description (`shapes::SHAPES`), its placement, mass and
//! dimensions, every range check — and its numbers kept in the file's units.

use super::Ctx;
use super::raw::{Quantity, RawPart, Vector};
use super::rotation::Orientation;
use crate::diag::Diagnostic;
use crate::part::{MassSpec, Part, Place, Solid, Spec};
use crate::shapes::{Dims, MaterialRule, Shape, Spanned as Spans};
use crate::tolerance::{
    COLLINEAR_TOLERANCE, PERPENDICULAR_TOLERANCE, SYMMETRY_TOLERANCE, VALIDITY_RTOL,
};
use crate::units::{self, Dim};
use nalgebra::{Matrix3, Vector3};
use std::ops::Range;
use toml::Spanned;

/// How a part is turned, and its dimensions (m) as `Shape::second_moments`
/// takes them.
type Placement = (Orientation, Vec<f64>);

/// `numeric::norm` of a vector.
fn vnorm(v: &Vector3<f64>) -> f64 {
    crate::numeric::norm(v.as_slice())
}

/// `numeric::unit` of a vector.
fn vunit(v: &Vector3<f64>) -> Vector3<f64> {
    Vector3::from(crate::numeric::unit(&[v.x, v.y, v.z]))
}

impl Ctx<'_> {
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
            (Some(m), _) => MassSpec::Given(self.file_quantity(m, "mass", Dim::MASS)?),
            (None, Some((d, kind))) => {
                MassSpec::Density(self.file_quantity(d, kind.key, kind.dim)?)
            }
            (None, None) => MassSpec::Density(
                material.expect("`part` checked that a mass, density or material is given"),
            ),
        };
        fn req(v: &Option<Vector>) -> &Vector {
            v.as_ref().expect("`part` checked the placement keys")
        }
        let place = match (info.dims, by_edges) {
            (Dims::Vertices, _) => {
                let rows = p.vertices.as_ref().expect("`part` checked the vertices");
                let mut vertices = [[0.0; 3]; 3];
                for (v, raw) in vertices.iter_mut().zip(rows.get_ref()) {
                    *v = self.file_vec3(raw, "vertices", Dim::LENGTH)?;
                }
                Place::Vertices(vertices)
            }
            (Dims::Given, _) => {
                let rows = p.inertia.as_ref().expect("`part` checked the inertia");
                let mut m = [[0.0; 3]; 3];
                for (r, raw) in m.iter_mut().zip(rows.get_ref()) {
                    *r = self.file_vec3(raw, "inertia", Dim::INERTIA)?;
                }
                Place::Given {
                    center: self.file_vec3(req(&p.center), "center", Dim::LENGTH)?,
                    inertia: tensor_convention(m, positive_products(p)),
                    orientation,
                }
            }
            (_, true) if info.spanned == Some(Spans::FromTo) => Place::FromTo {
                from: self.file_vec3(req(&p.from), "from", Dim::LENGTH)?,
                to: self.file_vec3(req(&p.to), "to", Dim::LENGTH)?,
            },
            (_, true) => {
                let mut edges = [[0.0; 3]; 3];
                let raw = p.edges.as_ref().expect("`part` checked the placement keys");
                for (e, r) in edges.iter_mut().zip(raw.get_ref()) {
                    *e = self.file_vec3(r, "edges", Dim::LENGTH)?;
                }
                Place::Edges {
                    corner: self.file_vec3(req(&p.corner), "corner", Dim::LENGTH)?,
                    edges,
                }
            }
            _ => {
                let mut extent = [0.0; 3];
                match info.dims {
                    Dims::Size(_) => {
                        let size = p.size.as_ref().expect("`part` checked the size");
                        for (e, q) in extent.iter_mut().zip(size.get_ref()) {
                            *e = self.file_quantity(q, "size", Dim::LENGTH)?;
                        }
                    }
                    Dims::Length => {
                        let l = p.length.as_ref().expect("`part` checked the length");
                        extent[0] = self.file_quantity(l, "length", Dim::LENGTH)?;
                    }
                    Dims::Radii { length } => {
                        let r = p.radius.as_ref().expect("`part` checked the radius");
                        extent[0] = self.file_quantity(r, "radius", Dim::LENGTH)?;
                        if let Some(q) = &p.inner_radius {
                            extent[1] = self.file_quantity(q, "inner_radius", Dim::LENGTH)?;
                        }
                        if let (true, Some(l)) = (length, &p.length) {
                            extent[2] = self.file_quantity(l, "length", Dim::LENGTH)?;
                        }
                    }
                    Dims::None | Dims::Given | Dims::Vertices => {}
                }
                Place::Centered {
                    center: self.file_vec3(req(&p.center), "center", Dim::LENGTH)?,
                    extent,
                    orientation,
                }
            }
        };
        Ok(Spec {
            mass,
            place,
            removed: matches!(&p.remove, Some(r) if *r.get_ref()),
        })
    }

    /// A positive quantity. Subnormal values (below 2.2e-308 in SI) are
    /// refused too: they carry too few digits to compute with.
    pub(super) fn part(
        &self,
        index: usize,
        raw: &Spanned<RawPart>,
    ) -> Result<(Part, Option<(Solid, f64)>), Diagnostic> {
        let p = raw.get_ref();
        let Some(shape_raw) = &p.shape else {
            return Err(self.err(raw.span(), "missing key `shape`").help(format!(
                "every part needs `shape`, one of {} (or `include` of another part file)",
                Shape::ALL.map(|s| format!("\"{}\"", s.name())).join(", ")
            )));
        };
        let shape = Shape::from_name(shape_raw.get_ref()).ok_or_else(|| {
            let names = Shape::ALL.map(Shape::name);
            self.err(
                shape_raw.span(),
                format!("unknown shape {:?}", shape_raw.get_ref()),
            )
            .label(match units::suggest(shape_raw.get_ref(), names) {
                Some(s) => format!("did you mean \"{s}\"?"),
                None => format!("expected one of {}", names.join(", ")),
            })
        })?;
        let s = shape.name();

        // Keys that exist in part files but do not apply to this shape.
        let keys = key_spans(p);
        let info = shape.info();
        let accepted = info.keys;
        if let Some((key, span)) = keys
            .iter()
            .filter(|(k, _)| !accepted.contains(k))
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
        self.in_file_range(shape, &spec, &name, raw.span())?;
        let part = Part {
            name,
            shape,
            spec,
            assembly: Vec::new(),
            span: raw.span(),
        };
        Ok((part, real))
    }

    /// A density (at `span`) on a thin shell, which has no volume.
    fn thin_shell(&self, span: Range<usize>, shape: &str) -> Diagnostic {
        self.err(
            span,
            format!("this {shape} is a thin shell (`inner_radius` = `radius`): it has no volume for a density to fill"),
        )
        .help("give its `mass`")
    }

    /// A part's `material`: its density made the shape's (per volume; times
    /// `thickness` for a plate, disk or triangle; times `area` or the area
    /// of `diameter` for a rod), in SI and in file units, with the span of
    /// `material`. `None` without one; `thickness` and `area` where they
    /// only serve a material are errors without it.
    fn material(
        &self,
        shape: Shape,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<Option<(f64, f64, Range<usize>)>, Diagnostic> {
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
                        format!("unknown material {:?}", name.get_ref()),
                    );
                    return Err(match units::suggest(name.get_ref(), names.iter().copied()) {
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
                    name.get_ref()
                ),
            )
        };
        let out = match shape.info().material {
            MaterialRule::Volume => (si, file),
            MaterialRule::Thickness => {
                let t = p.thickness.as_ref().ok_or_else(|| needs("thickness"))?;
                factor(
                    self.positive(t, "thickness", Dim::LENGTH)?,
                    self.file_quantity(t, "thickness", Dim::LENGTH)?,
                )
            }
            MaterialRule::Section => match (&p.area, &p.diameter) {
                (Some(a), Some(_)) => {
                    return Err(self
                        .err(a.span(), "`area` conflicts with `diameter`: give one to turn the material's density into a mass")
                        .help("`diameter` (a round rod) also feeds the idealisation report; `area` is any section"));
                }
                (Some(a), None) => factor(
                    self.positive(a, "area", Dim::AREA)?,
                    self.file_quantity(a, "area", Dim::AREA)?,
                ),
                (None, Some(d)) => {
                    let (ds, df) = (
                        self.positive(d, "diameter", Dim::LENGTH)?,
                        self.file_quantity(d, "diameter", Dim::LENGTH)?,
                    );
                    let q = std::f64::consts::PI / 4.0;
                    factor(q * ds * ds, q * df * df)
                }
                (None, None) => return Err(needs("area` or `diameter")),
            },
            MaterialRule::None => {
                return Err(self.err(
                    name.span(),
                    format!("`material` does not apply to a {s}: give `mass`"),
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
        Ok(Some((out.0, out.1, name.span())))
    }

    /// The composer works in the file's units (see `Spec`), so the part's
    /// mass and second moments must be normal f64 there too, not only in
    /// SI: a tiny part in a file of kilometres and tonnes can be subnormal
    /// (a few bits of precision) in file units while fine in SI, and a huge
    /// one in micrometres and milligrams can overflow.
    pub(super) fn in_file_range(
        &self,
        shape: Shape,
        spec: &Spec,
        name: &str,
        span: Range<usize>,
    ) -> Result<(), Diagnostic> {
        let m = crate::part::mass_of::<f64>(shape, spec).abs();
        let j = crate::part::own_second_moment::<f64>(shape, spec, m);
        // Each independent second moment: along the local axes, per edge,
        // or (a triangle, a given tensor) the trace.
        // (No allocation: this runs for every part of every file.)
        let (parts, count): ([f64; 3], usize) = match &spec.place {
            Place::Centered { extent, .. } => {
                (shape.second_moments(m, &extent[..shape.dim_count()]), 3)
            }
            Place::Edges { edges, .. } => (
                // (m e) e, not m (e e): e² alone can underflow or overflow.
                edges.map(|e| e.iter().map(|x| (m / 12.0 * x) * x).sum()),
                shape.edge_count(),
            ),
            _ => ([j[0][0] + j[1][1] + j[2][2], 0.0, 0.0], 1),
        };
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
        // A triangle's one moment checked is the trace.
        let expected = match shape.info().dims {
            Dims::Vertices => 1,
            _ => shape.nonzero_moments(),
        };
        let normal = parts.iter().filter(|x| **x >= f64::MIN_POSITIVE).count();
        if m < f64::MIN_POSITIVE || normal < expected {
            return Err(self
                .err(span, format!("the mass properties of `{name}` underflow the range of f64 in the file's units ({}): too few digits to compute with", units()))
                .help(fix));
        }
        Ok(())
    }

    /// A triangle's area (SI) from its `vertices`, which must
    /// span a triangle: area above `COLLINEAR_TOLERANCE` of the square of the
    /// longest edge.
    fn triangle(&self, p: &RawPart, missing: Diagnostic) -> Result<f64, Diagnostic> {
        let raw = p.vertices.as_ref().ok_or(missing)?;
        if raw.get_ref().len() != 3 {
            return Err(self.err(
                raw.span(),
                format!("a triangle needs 3 `vertices`, got {}", raw.get_ref().len()),
            ));
        }
        let mut v = [Vector3::zeros(); 3];
        for (out, r) in v.iter_mut().zip(raw.get_ref()) {
            *out = self.vec3(r, "vertices", Dim::LENGTH)?;
        }
        let (e1, e2) = (v[1] - v[0], v[2] - v[0]);
        let longest = vnorm(&e1).max(vnorm(&e2)).max(vnorm(&(v[2] - v[1])));
        // Scaled by the longest edge, so the cross product cannot overflow.
        let area = if longest > 0.0 && longest.is_finite() {
            vnorm(&(e1 / longest).cross(&(e2 / longest))) / 2.0 * longest * longest
        } else {
            0.0
        };
        if !(area * 4.0).is_finite() || !longest.is_finite() {
            return Err(self.err(
                raw.span(),
                "this triangle is too large for f64: its area overflows",
            ));
        }
        if !(longest > 0.0 && area > COLLINEAR_TOLERANCE * longest * longest) {
            return Err(self
                .err(
                    raw.span(),
                    "the `vertices` of this triangle are (nearly) collinear: it has no area",
                )
                .help(format!(
                    "its area must exceed {COLLINEAR_TOLERANCE:e} of the square of its longest edge"
                )));
        }
        Ok(area)
    }

    /// A given `inertia` (SI), checked: 3 × 3, symmetric to
    /// `SYMMETRY_TOLERANCE`, and physically valid — its second moment
    /// tr(I)/2 E − I positive semi-definite (no principal moment negative,
    /// I₁ + I₂ ≥ I₃) to `VALIDITY_RTOL` of the largest. Returns that
    /// second moment, local axes.
    fn given_inertia(&self, p: &RawPart) -> Result<Matrix3<f64>, Diagnostic> {
        let raw = p.inertia.as_ref().expect("`part` checked the inertia");
        if let Some(pr) = &p.products
            && !matches!(pr.get_ref().as_str(), "tensor" | "positive")
        {
            return Err(self
                .err(pr.span(), format!("unknown `products` convention {:?}", pr.get_ref()))
                .help("\"tensor\" (off-diagonals −∫xy dm, the default) or \"positive\" (+∫xy dm, CAD and Meriam)"));
        }
        if raw.get_ref().len() != 3 {
            return Err(self.err(
                raw.span(),
                format!("`inertia` needs 3 rows, got {}", raw.get_ref().len()),
            ));
        }
        let mut m = [[0.0; 3]; 3];
        for (row, r) in m.iter_mut().zip(raw.get_ref()) {
            let v = self.vec3(r, "inertia", Dim::INERTIA)?;
            *row = [v.x, v.y, v.z];
        }
        let big = m.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
        if m.iter()
            .flatten()
            .any(|x| *x != 0.0 && x.abs() < f64::MIN_POSITIVE)
        {
            return Err(self
                .err(raw.span(), "`inertia` has an entry too small for f64 (below 2.2e-308 in SI): too few digits to compute with")
                .help("give it in smaller units, e.g. \"1.2e-7 kg*mm^2\""));
        }
        // Its second moment must fit in f64 (the eigen check forms it).
        if !(big * 4.0).is_finite() {
            return Err(self.err(raw.span(), "`inertia` overflows the range of f64"));
        }
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            if !((m[i][j] - m[j][i]).abs() <= SYMMETRY_TOLERANCE * big) {
                return Err(self
                    .err(raw.span(), format!("`inertia` is not symmetric: row {}, column {} is {:e} but row {}, column {} is {:e}", i + 1, j + 1, m[i][j], j + 1, i + 1, m[j][i]))
                    .help(format!("an inertia tensor is symmetric (to {SYMMETRY_TOLERANCE:e} of its largest entry)")));
            }
        }
        let t = tensor_convention(m, positive_products(p));
        let half = (t[0][0] + t[1][1] + t[2][2]) / 2.0;
        let c: crate::numeric::M3<f64> = std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { half - t[i][i] } else { -t[i][j] })
        });
        let (lam, _) = crate::eigen::jacobi(c)
            .ok_or_else(|| self.err(raw.span(), "`inertia`: the eigen solver did not converge"))?;
        let top = lam.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        if lam.iter().any(|&l| l < -VALIDITY_RTOL * top) {
            let mut moments = [lam[1] + lam[2], lam[0] + lam[2], lam[0] + lam[1]];
            moments.sort_by(f64::total_cmp);
            return Err(self
                .err(raw.span(), format!(
                    "`inertia` is not physically valid: its principal moments {:.6e}, {:.6e}, {:.6e} kg·m² {}",
                    moments[0], moments[1], moments[2],
                    if moments[0] < -VALIDITY_RTOL * moments[2] { "include a negative one" } else { "break the triangle inequality I1 + I2 ≥ I3" }
                ))
                .help("check the signs of the products (`products = \"positive\"` if they are +∫xy dm, as CAD reports them) and the units"));
        }
        Ok(Matrix3::from_fn(|i, j| c[i][j]))
    }

    /// A plate's `thickness` or a rod's `diameter` (`key`), positive, in the
    /// file's length unit. `mass` (kg) checks that the second moment it
    /// adds in `report::ideal` stays within f64: m t²/12 for the box, m d²/16
    /// = m (d/2)²/4 for the cylinder.
    fn real_size(
        &self,
        solid: Solid,
        q: &Spanned<Quantity>,
        key: &str,
        mass: f64,
    ) -> Result<(Solid, f64), Diagnostic> {
        let si = self.positive(q, key, Dim::LENGTH)?;
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
        Ok((solid, self.file_quantity(q, key, Dim::LENGTH)?))
    }

    fn placement_canonical(
        &self,
        shape: Shape,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<Placement, Diagnostic> {
        let s = shape.name();
        let missing = |key: &str| {
            self.err(span.clone(), format!("this {s} needs `{key}`"))
                .help(shape.info().help)
        };
        let dims = match shape.info().dims {
            Dims::Size(n) => {
                let size = p.size.as_ref().ok_or_else(|| missing("size"))?;
                let dims = self.vector(size, "size", Dim::LENGTH, n)?;
                for q in size.get_ref() {
                    self.positive(q, "size", Dim::LENGTH)?;
                }
                dims
            }
            Dims::Length => {
                let l = p.length.as_ref().ok_or_else(|| missing("length"))?;
                vec![self.positive(l, "length", Dim::LENGTH)?]
            }
            Dims::Radii { length } => {
                let r = p.radius.as_ref().ok_or_else(|| missing("radius"))?;
                let outer = self.positive(r, "radius", Dim::LENGTH)?;
                let inner = match &p.inner_radius {
                    None => 0.0,
                    Some(q) => {
                        let v = self.quantity(q, "inner_radius", Dim::LENGTH)?;
                        if !(v >= 0.0 && v <= outer) {
                            return Err(self
                                .err(q.span(), "`inner_radius` must be from 0 to `radius`")
                                .help("0 (or leaving it out) is a solid; equal to `radius`, a thin shell"));
                        }
                        v
                    }
                };
                let mut dims = vec![outer, inner];
                if length {
                    let l = p.length.as_ref().ok_or_else(|| missing("length"))?;
                    dims.push(self.positive(l, "length", Dim::LENGTH)?);
                }
                dims
            }
            Dims::None => vec![],
            Dims::Given => {
                p.inertia.as_ref().ok_or_else(|| missing("inertia"))?;
                vec![]
            }
            Dims::Vertices => {
                let area = self.triangle(p, missing("vertices"))?;
                return Ok((Orientation::Identity, vec![area]));
            }
        };
        let center = p.center.as_ref().ok_or_else(|| missing("center"))?;
        self.vec3(center, "center", Dim::LENGTH)?;
        let orientation = match &p.rotation {
            Some(r) => self.rotation(r)?,
            None => Orientation::Identity,
        };
        Ok((orientation, dims))
    }

    fn placement_by_edges(
        &self,
        shape: Shape,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<Placement, Diagnostic> {
        let s = shape.name();
        let missing = |key: &str| {
            self.err(span.clone(), format!("this {s} needs `{key}`"))
                .help(shape.info().help)
        };
        let (origin, edges) = if shape.info().spanned == Some(Spans::FromTo) {
            let from = self.vec3(
                p.from.as_ref().ok_or_else(|| missing("from"))?,
                "from",
                Dim::LENGTH,
            )?;
            let to_raw = p.to.as_ref().ok_or_else(|| missing("to"))?;
            let to = self.vec3(to_raw, "to", Dim::LENGTH)?;
            let e = to - from;
            if e.amax() == 0.0 {
                return Err(self.err(
                    to_raw.span(),
                    "`to` must differ from `from`: the rod has no length",
                ));
            }
            if !e.amax().is_finite() {
                return Err(self.err(
                    to_raw.span(),
                    "the rod from `from` to `to` is too long for f64",
                ));
            }
            (from, vec![(e, to_raw.span())])
        } else {
            let corner = p.corner.as_ref().ok_or_else(|| missing("corner"))?;
            let corner = self.vec3(corner, "corner", Dim::LENGTH)?;
            let edges_raw = p.edges.as_ref().ok_or_else(|| missing("edges"))?;
            let n = shape.edge_count();
            if edges_raw.get_ref().len() != n {
                return Err(self.err(
                    edges_raw.span(),
                    format!("a {s} needs {n} `edges`, got {}", edges_raw.get_ref().len()),
                ));
            }
            let mut edges = Vec::with_capacity(n);
            for e in edges_raw.get_ref() {
                let v = self.vec3(e, "edges", Dim::LENGTH)?;
                if v.amax() == 0.0 {
                    return Err(self.err(e.span(), "an edge must not be zero"));
                }
                edges.push((v, e.span()));
            }
            for i in 0..n {
                for j in i + 1..n {
                    let cos = vunit(&edges[i].0).dot(&vunit(&edges[j].0));
                    if !(cos.abs() <= PERPENDICULAR_TOLERANCE) {
                        return Err(self
                            .err(
                                edges[j].1.clone(),
                                format!(
                                    "edges {} and {} are not perpendicular (angle {:.6}°)",
                                    i + 1,
                                    j + 1,
                                    cos.clamp(-1.0, 1.0).acos().to_degrees()
                                ),
                            )
                            .help(format!("edges must be perpendicular to a relative {PERPENDICULAR_TOLERANCE:e}")));
                    }
                }
            }
            (corner, edges)
        };
        // Validated only: the composer works from the corner and edges.
        let _ = origin;
        let dims: Vec<f64> = edges.iter().map(|(e, _)| vnorm(e)).collect();
        Ok((Orientation::Identity, dims))
    }
}

/// Every key a part may have, with where it is when present.
fn key_spans(p: &RawPart) -> [(&'static str, Option<Range<usize>>); 24] {
    [
        ("density", p.density.as_ref().map(Spanned::span)),
        ("areal_density", p.areal_density.as_ref().map(Spanned::span)),
        (
            "linear_density",
            p.linear_density.as_ref().map(Spanned::span),
        ),
        ("size", p.size.as_ref().map(Spanned::span)),
        ("length", p.length.as_ref().map(Spanned::span)),
        ("center", p.center.as_ref().map(Spanned::span)),
        ("rotation", p.rotation.as_ref().map(Spanned::span)),
        ("corner", p.corner.as_ref().map(Spanned::span)),
        ("edges", p.edges.as_ref().map(Spanned::span)),
        ("from", p.from.as_ref().map(Spanned::span)),
        ("to", p.to.as_ref().map(Spanned::span)),
        ("mass", p.mass.as_ref().map(Spanned::span)),
        ("thickness", p.thickness.as_ref().map(Spanned::span)),
        ("diameter", p.diameter.as_ref().map(Spanned::span)),
        ("radius", p.radius.as_ref().map(Spanned::span)),
        ("inner_radius", p.inner_radius.as_ref().map(Spanned::span)),
        ("remove", p.remove.as_ref().map(Spanned::span)),
        ("inertia", p.inertia.as_ref().map(Spanned::span)),
        ("products", p.products.as_ref().map(Spanned::span)),
        ("vertices", p.vertices.as_ref().map(Spanned::span)),
        ("material", p.material.as_ref().map(Spanned::span)),
        ("area", p.area.as_ref().map(Spanned::span)),
        ("include", p.include.as_ref().map(Spanned::span)),
        ("origin", p.origin.as_ref().map(Spanned::span)),
    ]
}

/// The span of `key` among `keys` (from `key_spans`), if present.
fn span_of(keys: &[(&str, Option<Range<usize>>)], key: &str) -> Option<Range<usize>> {
    keys.iter()
        .find(|(k, _)| *k == key)
        .and_then(|(_, s)| s.clone())
}

/// A part's quantity by its key: the density kinds' keys and the sizes
/// `ShapeInfo` names (`thickness`, `diameter`, `area`).
fn quantity_key<'p>(p: &'p RawPart, key: &str) -> Option<&'p Spanned<Quantity>> {
    match key {
        "density" => p.density.as_ref(),
        "areal_density" => p.areal_density.as_ref(),
        "linear_density" => p.linear_density.as_ref(),
        "thickness" => p.thickness.as_ref(),
        "diameter" => p.diameter.as_ref(),
        "area" => p.area.as_ref(),
        _ => unreachable!("`{key}` is not a quantity key of `ShapeInfo`"),
    }
}

/// The keys a `MaterialRule` reads beside `material`.
fn material_keys(rule: MaterialRule) -> &'static [&'static str] {
    match rule {
        MaterialRule::Thickness => &["thickness"],
        MaterialRule::Section => &["area", "diameter"],
        MaterialRule::Volume | MaterialRule::None => &[],
    }
}

/// The keys of `key_spans`, and `shape`.
pub(super) fn present_keys(p: &RawPart) -> super::include::Present<'static> {
    let mut keys: super::include::Present<'static> = key_spans(p).to_vec();
    keys.push(("shape", p.shape.as_ref().map(Spanned::span)));
    keys
}

/// A cylinder, disk or sphere whose inner radius is its radius.
fn is_thin_shell(shape: Shape, dims: &[f64]) -> bool {
    matches!(shape.info().dims, Dims::Radii { .. }) && dims[1] == dims[0]
}

/// The earliest present key of a set, with its span.
fn first<'k>(set: &[(&'k str, Option<Range<usize>>)]) -> Option<(&'k str, Range<usize>)> {
    set.iter()
        .filter_map(|(k, s)| s.clone().map(|s| (*k, s)))
        .min_by_key(|(_, s)| s.start)
}

/// Whether a part's `products = "positive"` (checked in `part`).
fn positive_products(p: &RawPart) -> bool {
    matches!(&p.products, Some(s) if s.get_ref() == "positive")
}

/// A given inertia matrix in the tensor convention (off-diagonals −∫xy dm),
/// symmetrised: the average of the two entries each product appears in.
fn tensor_convention(m: [[f64; 3]; 3], positive: bool) -> [[f64; 3]; 3] {
    let sign = if positive { -1.0 } else { 1.0 };
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i == j {
                m[i][i]
            } else {
                sign * (m[i][j] * 0.5 + m[j][i] * 0.5)
            }
        })
    })
}
