//! The validated part file: every part reduced to mass, centroid, local axes
//! and local second moments in SI, and to the numbers the file gave in the
//! file's own units (`Spec`), from which the composer works in the precision
//! asked for. This module owns every check on the input; a `Model` that
//! exists is valid.

pub mod expect;
pub mod fast;
mod include;
pub mod raw;
pub mod rotation;
mod toml_error;

use crate::diag::{Diagnostic, Source};
use crate::part::{MassSpec, Part, Place, RealSize, Solid, Spec};
use crate::shapes::Shape;
use crate::tolerance::{
    COLLINEAR_TOLERANCE, PERPENDICULAR_TOLERANCE, SYMMETRY_TOLERANCE, VALIDITY_RTOL,
};
use crate::units::{self, Dim, FileUnits, UnitError};
use nalgebra::{Matrix3, Vector3};
use raw::{Quantity, RawAnalysis, RawFile, RawPart, Vector};
use rotation::Orientation;
use std::ops::Range;
use toml::Spanned;

/// The most parts a body may have, included ones counted: ~1 KB of memory
/// each while reading.
pub const MAX_PARTS: usize = 2_000_000;

#[derive(Debug, Clone)]
pub struct Model {
    /// The file's `name`, if given.
    pub name: Option<String>,
    pub units: FileUnits,
    pub parts: Vec<Part>,
    pub analysis: Analysis,
    /// `[expect]`, one scalar check per component.
    pub expect: Vec<expect::Check>,
    /// The real thickness of plates and diameter of rods that give one, in
    /// file order; empty when none does.
    ///
    /// NOTE: kept beside the parts, not in `Spec`, so that the composer
    /// cannot see them: the composition is the idealised one whatever these
    /// say, and only the report compares it with the solids.
    pub real_sizes: Vec<RealSize>,
    /// `[materials]`: name → density, kg/m³.
    pub materials: std::collections::BTreeMap<String, f64>,
}

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

/// `[analysis]` in the file's units: reference point (file length), ω
/// (rad/s), α (rad/s²) — the file's units name no time, so ω and α are SI.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Analysis {
    pub about: Option<Vector3<f64>>,
    pub omega: Option<Vector3<f64>>,
    pub alpha: Option<Vector3<f64>>,
    /// Where the file gave `alpha`, to point at it if ω is missing.
    pub alpha_span: Option<Range<usize>>,
    /// Where the file gave `about` and `omega`, to point at them when a
    /// result overflows.
    pub about_span: Option<Range<usize>>,
    pub omega_span: Option<Range<usize>>,
}

impl Model {
    /// Parse and validate a part file.
    pub fn parse(source: &Source) -> Result<Model, Diagnostic> {
        let mut files = include::Files::default();
        if let Ok(p) = std::fs::canonicalize(&source.name) {
            files.stack.push((p, source.name.clone()));
        }
        Model::parse_in(source, &mut files)
    }

    /// `parse`, inside the chain of files that include each other (for
    /// cycles).
    fn parse_in(source: &Source, files: &mut include::Files) -> Result<Model, Diagnostic> {
        // The fast path where it can (most part files); else, and for every
        // error in the TOML, serde via the toml crate's value tree.
        let raw: RawFile = match fast::parse(&source.text) {
            Some(raw) => raw,
            None => toml::from_str(&source.text).map_err(|e| toml_error::toml_error(source, &e))?,
        };
        let ctx = Ctx {
            source,
            units: FileUnits::default(),
            materials: Default::default(),
        };
        let units = match &raw.units {
            Some(u) => ctx.file_units(u)?,
            None => FileUnits::default(),
        };
        let mut ctx = Ctx {
            source,
            units,
            materials: Default::default(),
        };
        if let Some(table) = &raw.materials {
            for (name, m) in table.get_ref() {
                let key = format!("density` of material `{name}");
                let si = ctx.positive(&m.get_ref().density, &key, Dim::DENSITY)?;
                let file = ctx.file_quantity(&m.get_ref().density, &key, Dim::DENSITY)?;
                ctx.materials.insert(name.clone(), (si, file));
            }
        }
        let ctx = ctx;
        let raw_parts = match &raw.part {
            Some(p) if !p.get_ref().is_empty() => p.get_ref(),
            Some(p) => {
                return Err(ctx.err(
                    p.span(),
                    "`part` is empty: a part file needs at least one part",
                ));
            }
            None => {
                return Err(ctx
                    .err(0..0, "the file has no parts")
                    .help("add at least one `[[part]]` table with a `shape`"));
            }
        };
        if raw_parts.len() > MAX_PARTS {
            return Err(ctx.err(
                0..0,
                format!(
                    "the file has {} parts; the limit is {MAX_PARTS}",
                    raw_parts.len()
                ),
            ));
        }
        let mut parts = Vec::with_capacity(raw_parts.len());
        let mut real_sizes = Vec::new();
        // The names given to sub-assemblies so far (`wheel`, `wheel #2`).
        let mut assembly_names = include::AssemblyNames::default();
        for (i, p) in raw_parts.iter().enumerate() {
            if p.get_ref().include.is_some() {
                ctx.include(
                    i,
                    p,
                    files,
                    &mut parts,
                    &mut real_sizes,
                    &mut assembly_names,
                )?;
                continue;
            }
            let (part, real) = ctx.part(i, p)?;
            if let Some((solid, size)) = real {
                real_sizes.push(RealSize {
                    part: parts.len(),
                    solid,
                    size,
                });
            }
            parts.push(part);
        }
        let analysis = match &raw.analysis {
            Some(a) => ctx.analysis(a)?,
            None => Analysis::default(),
        };
        let expect = match &raw.expect {
            Some(e) => ctx.expectations(e, analysis.omega.is_some())?,
            None => Vec::new(),
        };
        Ok(Model {
            name: raw.name.map(|n| n.into_inner()),
            units,
            parts,
            analysis,
            expect,
            materials: ctx
                .materials
                .iter()
                .map(|(k, v)| (k.clone(), v.0))
                .collect(),
            real_sizes,
        })
    }
}

impl Model {
    /// Keep only the parts of the sub-assembly `name`: its own name at any
    /// depth, if only one sub-assembly has it, or its path
    /// (`front / wheel #2`). Returns the sub-assembly's path.
    pub fn only(&mut self, name: &str) -> Result<Vec<String>, String> {
        let mut prefixes: Vec<&[String]> = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for p in &self.parts {
            for depth in 1..=p.assembly.len() {
                let prefix = &p.assembly[..depth];
                if seen.insert(prefix) {
                    prefixes.push(prefix);
                }
            }
        }
        // At most this many names in a message; the rest are counted.
        const LISTED: usize = 12;
        let list = |names: Vec<String>| {
            let more = names.len().saturating_sub(LISTED);
            let mut text = names
                .into_iter()
                .take(LISTED)
                .map(|n| format!("`{n}`"))
                .collect::<Vec<_>>()
                .join(", ");
            if more > 0 {
                text.push_str(&format!(" and {more} more"));
            }
            text
        };
        let matching: Vec<&[String]> = prefixes
            .iter()
            .copied()
            .filter(|q| q.join(" / ") == name || q.last().is_some_and(|l| l == name))
            .collect();
        let target: Vec<String> = match matching.as_slice() {
            [one] => one.to_vec(),
            [] => {
                let names: Vec<String> = prefixes.iter().map(|q| q.join(" / ")).collect();
                return Err(if names.is_empty() {
                    format!("`--only {name}`: the file has no sub-assemblies (`include`)")
                } else {
                    let near = units::suggest(name, names.iter().map(String::as_str))
                        .map(|s| format!("; did you mean `{s}`?"))
                        .unwrap_or_default();
                    format!(
                        "`--only {name}`: no sub-assembly of that name{near} (the file has {})",
                        list(names)
                    )
                });
            }
            many => {
                return Err(format!(
                    "`--only {name}` is ambiguous: {}; give the path",
                    list(many.iter().map(|q| q.join(" / ")).collect())
                ));
            }
        };
        let keep: Vec<bool> = self
            .parts
            .iter()
            .map(|p| p.assembly.starts_with(&target))
            .collect();
        let mut index = Vec::with_capacity(keep.len());
        let mut next = 0;
        for k in &keep {
            index.push(next);
            next += usize::from(*k);
        }
        self.real_sizes.retain(|r| keep[r.part]);
        for r in &mut self.real_sizes {
            r.part = index[r.part];
        }
        let mut k = keep.iter();
        self.parts.retain(|_| *k.next().expect("one flag per part"));
        Ok(target)
    }
}

/// What the conversion step needs to read values: the source (for spans)
/// and the file's units.
pub(crate) struct Ctx<'a> {
    source: &'a Source,
    units: FileUnits,
    /// `[materials]`: name → density (kg/m³, and in file units).
    materials: std::collections::BTreeMap<String, (f64, f64)>,
}

impl Ctx<'_> {
    fn err(&self, span: Range<usize>, message: impl Into<String>) -> Diagnostic {
        self.source.error(span, message)
    }

    fn file_units(&self, u: &Spanned<raw::RawUnits>) -> Result<FileUnits, Diagnostic> {
        let pick = |v: &Option<Spanned<String>>,
                    allowed: &'static [&'static str],
                    key: &str,
                    default: &'static str| {
            let Some(v) = v else { return Ok(default) };
            allowed
                .iter()
                .copied()
                .find(|a| *a == v.get_ref())
                .ok_or_else(|| {
                    self.err(
                        v.span(),
                        format!("unknown {key} unit {:?} in `units`", v.get_ref()),
                    )
                    .label(
                        match units::suggest(v.get_ref(), allowed.iter().copied()) {
                            Some(s) => format!("did you mean \"{s}\"?"),
                            None => format!("expected one of {}", allowed.join(", ")),
                        },
                    )
                })
        };
        Ok(FileUnits {
            length: pick(&u.get_ref().length, units::LENGTH_UNITS, "length", "m")?,
            mass: pick(&u.get_ref().mass, units::MASS_UNITS, "mass", "kg")?,
        })
    }

    /// A scalar of dimension `dim` in SI: a plain number in file units, or a
    /// string with its own unit. Always finite.
    fn quantity(&self, q: &Spanned<Quantity>, key: &str, dim: Dim) -> Result<f64, Diagnostic> {
        let value = match q.get_ref() {
            Quantity::Number(x) => {
                if !x.is_finite() {
                    return Err(self.err(
                        q.span(),
                        format!("`{key}` must be a finite number, got {x}"),
                    ));
                }
                self.units.factor(dim).apply(*x)
            }
            Quantity::Text(t) => units::parse_quantity(t, dim).map_err(|e| {
                let d = self.err(q.span(), format!("`{key}`: {e}"));
                match e {
                    UnitError::Unknown {
                        suggestion: Some(s),
                        ..
                    } => d.suggest(Some(s)),
                    _ => d.help(format!(
                        "`{key}` is {}, e.g. {}",
                        dim.describe(),
                        dim.example()
                    )),
                }
            })?,
        };
        if !value.is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` overflows when converted to SI units"),
            ));
        }
        // Results are shown in the file's units: a value within a rounding
        // of the largest f64 there can overflow on its way back from SI.
        if !(value / self.units.factor(dim).value()).is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` is beyond the largest number in the file's units"),
            ));
        }
        Ok(value)
    }

    /// A scalar of dimension `dim` in the file's units (see `Spec`).
    fn file_quantity(&self, q: &Spanned<Quantity>, key: &str, dim: Dim) -> Result<f64, Diagnostic> {
        let value = match q.get_ref() {
            Quantity::Number(x) => *x,
            Quantity::Text(t) => units::parse_quantity_in(t, dim, self.units)
                .map_err(|e| self.err(q.span(), format!("`{key}`: {e}")))?,
        };
        if !value.is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` overflows when converted to the file's units"),
            ));
        }
        Ok(value)
    }

    fn file_vec3(&self, v: &Vector, key: &str, dim: Dim) -> Result<[f64; 3], Diagnostic> {
        let mut out = [0.0; 3];
        for (o, q) in out.iter_mut().zip(v.get_ref()) {
            *o = self.file_quantity(q, key, dim)?;
        }
        Ok(out)
    }

    /// The part's numbers in the file's units, read after `part` has
    /// validated them (so only a conversion overflow can fail here).
    fn spec(
        &self,
        shape: Shape,
        p: &RawPart,
        by_edges: bool,
        orientation: Orientation,
        material: Option<f64>,
    ) -> Result<Spec, Diagnostic> {
        let density = match shape {
            Shape::Box | Shape::Cylinder | Shape::Sphere => (&p.density, Dim::DENSITY),
            Shape::Plate | Shape::Disk | Shape::Triangle => (&p.areal_density, Dim::AREAL_DENSITY),
            Shape::Rod => (&p.linear_density, Dim::LINEAR_DENSITY),
            Shape::Point | Shape::Inertia => (&None, Dim::MASS),
        };
        let mass = match (&p.mass, density) {
            (Some(m), _) => MassSpec::Given(self.file_quantity(m, "mass", Dim::MASS)?),
            (None, (Some(d), dim)) => MassSpec::Density(self.file_quantity(
                d,
                shape.density_key().unwrap_or("density"),
                dim,
            )?),
            (None, (None, _)) => MassSpec::Density(
                material.expect("`part` checked that a mass, density or material is given"),
            ),
        };
        fn req(v: &Option<Vector>) -> &Vector {
            v.as_ref().expect("`part` checked the placement keys")
        }
        let place = match (shape, by_edges) {
            (Shape::Triangle, _) => {
                let rows = p.vertices.as_ref().expect("`part` checked the vertices");
                let mut vertices = [[0.0; 3]; 3];
                for (v, raw) in vertices.iter_mut().zip(rows.get_ref()) {
                    *v = self.file_vec3(raw, "vertices", Dim::LENGTH)?;
                }
                Place::Vertices(vertices)
            }
            (Shape::Inertia, _) => {
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
            (Shape::Rod, true) => Place::FromTo {
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
                match shape {
                    Shape::Box | Shape::Plate => {
                        let size = p.size.as_ref().expect("`part` checked the size");
                        for (e, q) in extent.iter_mut().zip(size.get_ref()) {
                            *e = self.file_quantity(q, "size", Dim::LENGTH)?;
                        }
                    }
                    Shape::Rod => {
                        let l = p.length.as_ref().expect("`part` checked the length");
                        extent[0] = self.file_quantity(l, "length", Dim::LENGTH)?;
                    }
                    Shape::Cylinder | Shape::Disk | Shape::Sphere => {
                        let r = p.radius.as_ref().expect("`part` checked the radius");
                        extent[0] = self.file_quantity(r, "radius", Dim::LENGTH)?;
                        if let Some(q) = &p.inner_radius {
                            extent[1] = self.file_quantity(q, "inner_radius", Dim::LENGTH)?;
                        }
                        if let (Shape::Cylinder, Some(l)) = (shape, &p.length) {
                            extent[2] = self.file_quantity(l, "length", Dim::LENGTH)?;
                        }
                    }
                    Shape::Point | Shape::Inertia | Shape::Triangle => {}
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
    fn positive(&self, q: &Spanned<Quantity>, key: &str, dim: Dim) -> Result<f64, Diagnostic> {
        let v = self.quantity(q, key, dim)?;
        if v >= f64::MIN_POSITIVE {
            Ok(v)
        } else if v > 0.0 {
            Err(self.err(
                q.span(),
                format!(
                    "`{key}` is too small: below {:e} in SI units, f64 loses precision",
                    f64::MIN_POSITIVE
                ),
            ))
        } else {
            Err(self.err(q.span(), format!("`{key}` must be positive")))
        }
    }

    /// A vector of exactly `n` quantities of dimension `dim`, in SI.
    fn vector(&self, v: &Vector, key: &str, dim: Dim, n: usize) -> Result<Vec<f64>, Diagnostic> {
        if v.get_ref().len() != n {
            return Err(self.err(
                v.span(),
                format!("`{key}` needs {n} components, got {}", v.get_ref().len()),
            ));
        }
        v.get_ref()
            .iter()
            .map(|q| self.quantity(q, key, dim))
            .collect()
    }

    fn vec3(&self, v: &Vector, key: &str, dim: Dim) -> Result<Vector3<f64>, Diagnostic> {
        let c = self.vector(v, key, dim, 3)?;
        Ok(Vector3::new(c[0], c[1], c[2]))
    }

    /// One part, and the solid it idealises with its real size (file
    /// units) when the file gives a plate's `thickness` or a rod's
    /// `diameter`.
    fn part(
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
        let accepted: &[&str] = match shape {
            Shape::Box => &[
                "density", "size", "center", "rotation", "corner", "edges", "mass", "remove",
                "material",
            ],
            Shape::Plate => &[
                "areal_density",
                "size",
                "center",
                "rotation",
                "corner",
                "edges",
                "mass",
                "remove",
                "thickness",
                "material",
            ],
            Shape::Rod => &[
                "linear_density",
                "length",
                "center",
                "rotation",
                "from",
                "to",
                "mass",
                "remove",
                "diameter",
                "material",
                "area",
            ],
            Shape::Cylinder => &[
                "density",
                "radius",
                "inner_radius",
                "material",
                "length",
                "center",
                "rotation",
                "mass",
                "remove",
            ],
            Shape::Disk => &[
                "areal_density",
                "radius",
                "inner_radius",
                "material",
                "thickness",
                "center",
                "rotation",
                "mass",
                "remove",
            ],
            Shape::Sphere => &[
                "density",
                "radius",
                "inner_radius",
                "material",
                "center",
                "rotation",
                "mass",
                "remove",
            ],
            Shape::Point => &["center", "mass"],
            Shape::Inertia => &[
                "mass", "center", "rotation", "inertia", "products", "remove",
            ],
            Shape::Triangle => &[
                "areal_density",
                "vertices",
                "mass",
                "remove",
                "material",
                "thickness",
            ],
        };
        if let Some((key, span)) = keys
            .iter()
            .filter(|(k, _)| !accepted.contains(k))
            .find_map(|(k, s)| s.clone().map(|s| (*k, s)))
        {
            return Err(self
                .err(span, format!("`{key}` does not apply to a {s}"))
                .help(shape_help(shape)));
        }

        // Placement: canonical (size/length, center, rotation) or by edges.
        let by_edges: &[(&str, Option<Range<usize>>)] = match shape {
            Shape::Box | Shape::Plate => &keys[7..9],
            Shape::Rod => &keys[9..11],
            Shape::Cylinder
            | Shape::Disk
            | Shape::Sphere
            | Shape::Point
            | Shape::Inertia
            | Shape::Triangle => &[],
        };
        let canonical: &[(&str, Option<Range<usize>>)] = match shape {
            Shape::Box | Shape::Plate => &[keys[3].clone(), keys[5].clone(), keys[6].clone()],
            Shape::Rod => &keys[4..7],
            Shape::Cylinder
            | Shape::Disk
            | Shape::Sphere
            | Shape::Point
            | Shape::Inertia
            | Shape::Triangle => &keys[5..6],
        };
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
                    .help(shape_help(shape)));
            }
            (_, Some(_)) => self.placement_by_edges(shape, p, raw.span())?,
            _ => self.placement_canonical(shape, p, raw.span())?,
        };

        // Mass: exactly one of `mass` and the shape's density.
        let density = match shape {
            Shape::Box | Shape::Cylinder | Shape::Sphere => &p.density,
            Shape::Plate | Shape::Disk | Shape::Triangle => &p.areal_density,
            Shape::Rod => &p.linear_density,
            Shape::Point | Shape::Inertia => &None,
        };
        let material = self.material(shape, p, raw.span())?;
        if let Some((_, _, span)) = &material {
            let other = [
                ("mass", &p.mass),
                (shape.density_key().unwrap_or("density"), density),
            ];
            if let Some((k, q)) = other.iter().find_map(|(k, q)| q.as_ref().map(|q| (*k, q))) {
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
                let dim = match shape {
                    Shape::Box | Shape::Cylinder | Shape::Sphere => Dim::DENSITY,
                    Shape::Plate | Shape::Disk | Shape::Triangle => Dim::AREAL_DENSITY,
                    _ => Dim::LINEAR_DENSITY,
                };
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
            let size = keys.iter().find_map(|(k, span)| {
                matches!(*k, "size" | "length" | "radius" | "edges" | "from" | "to")
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
        let real = match (shape, &p.thickness, &p.diameter) {
            (Shape::Plate, Some(q), _) => Some(self.real_size(Solid::Box, q, "thickness", mass)?),
            (Shape::Rod, _, Some(q)) => {
                Some(self.real_size(Solid::Cylinder, q, "diameter", mass)?)
            }
            _ => None,
        };
        if shape == Shape::Inertia {
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
            let only_with = match shape {
                Shape::Disk | Shape::Triangle => p.thickness.as_ref().map(|q| ("thickness", q)),
                Shape::Rod => p.area.as_ref().map(|q| ("area", q)),
                _ => None,
            };
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
        let out = match shape {
            Shape::Box | Shape::Cylinder | Shape::Sphere => (si, file),
            Shape::Plate | Shape::Disk | Shape::Triangle => {
                let t = p.thickness.as_ref().ok_or_else(|| needs("thickness"))?;
                factor(
                    self.positive(t, "thickness", Dim::LENGTH)?,
                    self.file_quantity(t, "thickness", Dim::LENGTH)?,
                )
            }
            Shape::Rod => match (&p.area, &p.diameter) {
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
            Shape::Point | Shape::Inertia => {
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
    fn in_file_range(
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
        let expected = match shape {
            Shape::Triangle => 1,
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
                .help(shape_help(shape))
        };
        let dims = match shape {
            Shape::Box | Shape::Plate => {
                let size = p.size.as_ref().ok_or_else(|| missing("size"))?;
                let dims = self.vector(size, "size", Dim::LENGTH, shape.edge_count())?;
                for q in size.get_ref() {
                    self.positive(q, "size", Dim::LENGTH)?;
                }
                dims
            }
            Shape::Rod => {
                let l = p.length.as_ref().ok_or_else(|| missing("length"))?;
                vec![self.positive(l, "length", Dim::LENGTH)?]
            }
            Shape::Cylinder | Shape::Disk | Shape::Sphere => {
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
                if shape == Shape::Cylinder {
                    let l = p.length.as_ref().ok_or_else(|| missing("length"))?;
                    dims.push(self.positive(l, "length", Dim::LENGTH)?);
                }
                dims
            }
            Shape::Point => vec![],
            Shape::Inertia => {
                p.inertia.as_ref().ok_or_else(|| missing("inertia"))?;
                vec![]
            }
            Shape::Triangle => {
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
                .help(shape_help(shape))
        };
        let (origin, edges) = if shape == Shape::Rod {
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

    fn analysis(&self, a: &Spanned<RawAnalysis>) -> Result<Analysis, Diagnostic> {
        let r = a.get_ref();
        let about = r
            .about
            .as_ref()
            .map(|v| self.file_vec3(v, "about", Dim::LENGTH).map(Vector3::from))
            .transpose()?;
        let omega = r
            .omega
            .as_ref()
            .map(|v| {
                self.file_vec3(v, "omega", Dim::ANGULAR_VELOCITY)
                    .map(Vector3::from)
            })
            .transpose()?;
        let alpha = r
            .alpha
            .as_ref()
            .map(|v| {
                self.file_vec3(v, "alpha", Dim::ANGULAR_ACCELERATION)
                    .map(Vector3::from)
            })
            .transpose()?;
        Ok(Analysis {
            about,
            omega,
            alpha,
            alpha_span: r.alpha.as_ref().map(Spanned::span),
            about_span: r.about.as_ref().map(Spanned::span),
            omega_span: r.omega.as_ref().map(Spanned::span),
        })
    }
}

/// Every key a part may have, with where it is when present. The order is
/// the one `Ctx::part` indexes.
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

/// The keys of `key_spans`, and `shape`.
pub(super) fn present_keys(p: &RawPart) -> include::Present<'static> {
    let mut keys: include::Present<'static> = key_spans(p).to_vec();
    keys.push(("shape", p.shape.as_ref().map(Spanned::span)));
    keys
}

/// A cylinder, disk or sphere whose inner radius is its radius.
fn is_thin_shell(shape: Shape, dims: &[f64]) -> bool {
    matches!(shape, Shape::Cylinder | Shape::Disk | Shape::Sphere) && dims[1] == dims[0]
}

/// The earliest present key of a set, with its span.
fn first<'k>(set: &[(&'k str, Option<Range<usize>>)]) -> Option<(&'k str, Range<usize>)> {
    set.iter()
        .filter_map(|(k, s)| s.clone().map(|s| (*k, s)))
        .min_by_key(|(_, s)| s.start)
}

fn shape_help(shape: Shape) -> &'static str {
    match shape {
        Shape::Box => {
            "a box takes `mass` or `density`, and `size` with `center` (and optional `rotation`), or `corner` with three `edges`"
        }
        Shape::Plate => {
            "a plate takes `mass` or `areal_density`, and `size` = [x, y] with `center` (and optional `rotation`), or `corner` with two `edges`; optionally its real `thickness`"
        }
        Shape::Rod => {
            "a rod takes `mass` or `linear_density`, and `length` with `center` (and optional `rotation`), or `from` and `to`; optionally its real `diameter`"
        }
        Shape::Cylinder => {
            "a cylinder takes `mass` or `density`, `radius` and `length` (along its local z) with `center` (and optional `rotation`); an `inner_radius` makes it a tube"
        }
        Shape::Disk => {
            "a disk takes `mass` or `areal_density`, and `radius` (in its local x–y plane) with `center` (and optional `rotation`); an `inner_radius` makes it an annulus"
        }
        Shape::Sphere => {
            "a sphere takes `mass` or `density`, and `radius` with `center`; an `inner_radius` makes it hollow (equal to `radius`: a thin shell)"
        }
        Shape::Point => "a point takes `mass` and `center`",
        Shape::Triangle => {
            "a triangle takes `mass` or `areal_density`, and three `vertices` = [[x, y, z], [x, y, z], [x, y, z]] in the file's frame"
        }
        Shape::Inertia => {
            "an inertia part takes `mass`, `center`, `inertia` = [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] about its centroid in its local axes (optional `rotation`), tensor convention unless `products = \"positive\"`"
        }
    }
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

/// Parse a command-line vector into the file's units (rad/s for ω, rad/s²
/// for α): three comma-separated components. Plain numbers are in the
/// file's units. A unit on
/// the last component only applies to all three (`0,0,10 mm`); otherwise
/// each component carries its own unit (`1 mm,2 in,0 m`) or none does.
pub fn parse_flag_vector(text: &str, units: FileUnits, dim: Dim) -> Result<Vector3<f64>, String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!(
            "expected three comma-separated components, got {}",
            parts.len()
        ));
    }
    let plain: Vec<Option<f64>> = parts.iter().map(|p| p.parse::<f64>().ok()).collect();
    let shared_unit = match (plain[0], plain[1], plain[2]) {
        (Some(_), Some(_), None) => {
            let (_, unit) =
                units::split_number(parts[2]).map_err(|e| format!("component 3: {e}"))?;
            Some(unit)
        }
        (Some(_), Some(_), Some(_)) => None,
        _ if plain.iter().all(Option::is_none) => None,
        _ => {
            return Err(
                "give a unit on every component, on none, or on the last one only (for all three)"
                    .to_string(),
            );
        }
    };
    let mut out = Vector3::zeros();
    for (i, p) in parts.iter().enumerate() {
        let v = match (plain[i], shared_unit) {
            (Some(x), _) if !x.is_finite() => {
                return Err(format!("component {} must be finite", i + 1));
            }
            (Some(x), None) => x,
            // The unit given once, at the end, for all three.
            (Some(x), Some(u)) => units::parse_quantity_in(&format!("{x:?} {u}"), dim, units)
                .map_err(|e| e.to_string())?,
            (None, _) => units::parse_quantity_in(p, dim, units)
                .map_err(|e| format!("component {}: {e}", i + 1))?,
        };
        if !v.is_finite() {
            return Err(format!(
                "component {} overflows when converted to the file's units",
                i + 1
            ));
        }
        out[i] = v;
    }
    Ok(out)
}
