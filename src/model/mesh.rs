//! A `shape = "mesh"` part: its keys checked, its `file` resolved and
//! confined as an include's is (`include::Ctx::target_of`), read, welded,
//! checked and integrated once per file and mode (`mesh::MeshBody`, kept in
//! `include::Files`), and its mass and placement read into a `Part` whose
//! `Place::Mesh` shares the integrals.
//!
//! Every error about the mesh file is said at the part's `file` key,
//! naming the mesh file and where in it (a line, a byte offset, a
//! triangle and its edge).

use super::Ctx;
use super::include::{Files, Kind};
use super::raw::RawPart;
use super::rotation::Orientation;
use super::tolerance::Recorder;
use crate::diag::Diagnostic;
use crate::mesh::{FileType, MeshBody, Mode};
use crate::part::{MassSpec, Part, Place, Spec};
use crate::shapes::Shape;
use crate::units::{self, Dim, FileUnits};
use std::ops::Range;
use std::sync::Arc;
use toml::Spanned;

/// Whether a raw part is a mesh (read here, with its file).
pub(super) fn is_mesh(p: &RawPart) -> bool {
    p.shape.as_ref().is_some_and(|s| s.get_ref() == "mesh")
}

impl Ctx<'_> {
    /// The mesh part at position `index`.
    pub(super) fn mesh_part(
        &self,
        rec: &mut Recorder,
        index: usize,
        raw: &Spanned<RawPart>,
        files: &mut Files,
    ) -> Result<Part, Diagnostic> {
        let p = raw.get_ref();
        let info = Shape::Mesh.info();
        if let Some((key, span)) = super::keys::present_keys(p)
            .into_iter()
            .filter(|(k, _)| *k != "shape" && !super::tolerance::accepts(info.keys, k))
            .find_map(|(k, s)| s.map(|s| (k, s)))
        {
            return Err(self
                .err(span, format!("`{key}` does not apply to a mesh"))
                .help(info.help));
        }
        let needs = |key: &str, why: &str| {
            self.err(raw.span(), format!("this mesh needs `{key}`{why}"))
                .help(info.help)
        };
        let file = p.file.as_deref().ok_or_else(|| needs("file", ""))?;
        let unit = p.mesh_unit.as_deref().ok_or_else(|| {
            needs(
                "mesh_unit",
                ", the length unit of its file's coordinates (an STL or OBJ file carries none)",
            )
        })?;
        let scale = self.mesh_scale(unit)?;
        let mode = match p.mode.as_deref() {
            None => Mode::Solid,
            Some(m) => match m.get_ref().as_str() {
                "solid" => Mode::Solid,
                "shell" => Mode::Shell,
                other => {
                    let d = self.err(m.span(), format!("unknown mesh mode {other:?}"));
                    return Err(match units::suggest(other, ["solid", "shell"]) {
                        Some(s) => d.label(format!("did you mean \"{s}\"?")),
                        None => d.label("expected \"solid\" or \"shell\""),
                    });
                }
            },
        };
        rec.enter_part(Shape::Mesh, super::keys::COMMON);
        self.tol_needs_mass(p)?;
        let density = self.mesh_density(rec, p, mode, raw.span())?;
        let origin = match &p.origin {
            Some(o) => self.value3(rec, 0, o, "origin", Dim::LENGTH)?.0,
            None => [0.0; 3],
        };
        let orientation = match &p.rotation {
            Some(r) => self.rotation(r)?,
            None => Orientation::Identity,
        };
        let weld = match p.weld.as_deref() {
            None => None,
            Some(w) => {
                if mode == Mode::Shell {
                    return Err(self
                        .err(w.span(), "`weld` applies to a solid mesh")
                        .help("a shell weighs its surface as it is, open or not"));
                }
                let d = self.positive_file(rec, w, "weld", Dim::LENGTH)?;
                // In the mesh file's units: `scale` is its unit in this file's.
                let d = d / scale.hi;
                if !(d.is_finite() && d > 0.0) {
                    return Err(self.err(
                        w.span(),
                        "`weld` is out of the range of the mesh file's coordinates",
                    ));
                }
                Some((d, w.span()))
            }
        };
        let mesh = self.mesh_body(file, mode, weld, files)?;
        let roundings = match density {
            Density::Per(_, _, r) => r,
            Density::Mass(_) => 0.0,
        };
        let mass = match density {
            Density::Mass(m) => MassSpec::Given(m),
            Density::Per(rho, span, _) => {
                let spec = Spec {
                    mass: MassSpec::Density(rho),
                    place: Place::Mesh(crate::shapes::mesh::Mesh {
                        origin,
                        orientation: orientation.clone(),
                        scale,
                        mesh: mesh.clone(),
                    }),
                    removed: false,
                    placed: Default::default(),
                };
                let m: f64 = crate::part::mass_of(&spec);
                let si = m * self.units.factor(Dim::MASS).value();
                if !(m >= f64::MIN_POSITIVE && m.is_finite() && si.is_finite()) {
                    let what = if m.is_finite() {
                        "too small"
                    } else {
                        "too large"
                    };
                    return Err(self.err(
                        span,
                        format!(
                            "the density times the mesh's {} gives a mass {what} for f64",
                            measure_name(mode)
                        ),
                    ));
                }
                MassSpec::Density(rho)
            }
        };
        let name = match &p.name {
            Some(n) => n.get_ref().clone(),
            None => format!("part {}", index + 1),
        };
        let spec = Spec {
            mass,
            place: Place::Mesh(crate::shapes::mesh::Mesh {
                origin,
                orientation,
                scale,
                mesh,
            }),
            removed: matches!(&p.remove, Some(r) if *r.get_ref()),
            placed: crate::part::Placed::default().with_mass(roundings),
        };
        self.in_file_range(&spec, &name, raw.span())?;
        rec.record_material(p, &spec);
        let tol = rec.leave_part();
        Ok(Part {
            tol,
            material: p.material.as_deref().map(|m| m.get_ref().as_str().into()),
            name: if p.name.is_some() {
                name
            } else {
                String::new()
            },
            named: p.name.is_some(),
            spec,
            assembly: Vec::new(),
            span: raw.span(),
        })
    }

    /// `mesh_unit` in this file's length unit, exactly (double-double).
    fn mesh_scale(&self, unit: &Spanned<String>) -> Result<crate::numeric::DD, Diagnostic> {
        let allowed = units::LENGTH_UNITS;
        let Some(name) = allowed.iter().copied().find(|a| *a == unit.get_ref()) else {
            let d = self.err(
                unit.span(),
                format!("unknown length unit {:?} in `mesh_unit`", unit.get_ref()),
            );
            return Err(
                match units::suggest(unit.get_ref(), allowed.iter().copied()) {
                    Some(s) => d.label(format!("did you mean \"{s}\"?")),
                    None => d.label(format!("expected one of {}", allowed.join(", "))),
                },
            );
        };
        let of = FileUnits {
            length: name,
            mass: "kg",
        }
        .factor(Dim::LENGTH);
        let ratio = of
            .per(self.units.factor(Dim::LENGTH))
            .expect("length units are small fractions");
        Ok(ratio.dd())
    }

    /// The mass, or the density per volume (solid) or area (shell) in the
    /// file's units, from exactly one of the keys the mode takes.
    fn mesh_density(
        &self,
        rec: &mut Recorder,
        p: &RawPart,
        mode: Mode,
        span: Range<usize>,
    ) -> Result<Density, Diagnostic> {
        let given: Vec<(&str, Range<usize>)> = [
            ("mass", p.mass.as_ref().map(Spanned::span)),
            ("density", p.density.as_deref().map(Spanned::span)),
            (
                "areal_density",
                p.areal_density.as_deref().map(Spanned::span),
            ),
            ("material", p.material.as_deref().map(Spanned::span)),
        ]
        .into_iter()
        .filter_map(|(k, s)| s.map(|s| (k, s)))
        .collect();
        if let [(first, _), (later, s), ..] = given.as_slice() {
            let (first, later, s) = if given[0].1.start < s.start {
                (*first, *later, s.clone())
            } else {
                (*later, *first, given[0].1.clone())
            };
            return Err(self.err(
                s,
                format!("`{later}` conflicts with `{first}`: give exactly one"),
            ));
        }
        let thickness = p.thickness.as_deref();
        match (mode, given.first().map(|g| g.0), thickness) {
            (Mode::Solid, Some("areal_density"), _) | (Mode::Solid, _, Some(_)) => {
                let (key, s) = match (&p.areal_density, thickness) {
                    (Some(a), _) => ("areal_density", a.span()),
                    (_, Some(t)) => ("thickness", t.span()),
                    _ => unreachable!("one of them is given"),
                };
                Err(self
                    .err(s, format!("`{key}` applies to a mesh with `mode = \"shell\"`"))
                    .help("a solid mesh weighs the volume it encloses: `mass`, `density` or `material`"))
            }
            (Mode::Shell, Some("areal_density"), Some(t)) | (Mode::Shell, Some("mass"), Some(t)) => {
                Err(self
                    .err(t.span(), "`thickness` goes with `density` or `material`, which it turns into an areal density")
                    .help("give `thickness` with `density` or `material`, or `mass` or `areal_density` alone"))
            }
            (Mode::Shell, Some(k @ ("density" | "material")), None) => Err(self
                .err(
                    given[0].1.clone(),
                    format!("a shell mesh's `{k}` needs `thickness`, which turns it into an areal density"),
                )
                .help("or give `areal_density` or `mass`")),
            (_, None, _) => Err(self
                .err(
                    span,
                    match mode {
                        Mode::Solid => "this mesh needs `mass`, `density` or `material`",
                        Mode::Shell => "this shell mesh needs `mass`, `areal_density`, or `thickness` with `density` or `material`",
                    },
                )),
            (_, Some("mass"), _) => {
                let m = p.mass.as_ref().expect("given");
                let v = self.value(rec, m, "mass", Dim::MASS)?;
                self.mass_tol(rec, p, m, v.file)?;
                if !(v.si > 0.0) {
                    return Err(self.err(m.span(), "`mass` must be positive"));
                }
                Ok(Density::Mass(v.file))
            }
            (_, Some("areal_density"), _) => {
                let q = p.areal_density.as_deref().expect("given");
                let d = self.positive_file(rec, q, "areal_density", Dim::AREAL_DENSITY)?;
                Ok(Density::Per(d, q.span(), 0.0))
            }
            (_, Some("density"), _) => {
                let q = p.density.as_deref().expect("given");
                let d = self.positive_file(rec, q, "density", Dim::DENSITY)?;
                self.times_thickness(rec, d, thickness, q.span())
            }
            (_, Some(_), _) => {
                let m = self
                    .material(rec, Shape::Mesh, p, span)?
                    .expect("a material is given");
                self.times_thickness(rec, m.file, thickness, m.span)
            }
        }
    }

    /// A density per volume, times the shell's thickness if it has one.
    fn times_thickness(
        &self,
        rec: &mut Recorder,
        d: f64,
        thickness: Option<&Spanned<super::raw::Quantity>>,
        span: Range<usize>,
    ) -> Result<Density, Diagnostic> {
        let Some(t) = thickness else {
            return Ok(Density::Per(d, span, 0.0));
        };
        let t = self.positive_file(rec, t, "thickness", Dim::LENGTH)?;
        // The number kept is the areal density: a density's tolerance
        // moves it t times as fast.
        rec.scale_readings("density", t);
        let a = d * t;
        if !(a.is_finite() && a >= f64::MIN_POSITIVE) {
            return Err(self.err(
                span,
                "the density times the thickness is out of the range of f64",
            ));
        }
        Ok(Density::Per(a, span, 1.0))
    }

    /// A positive quantity in the file's units (checked in SI too).
    fn positive_file(
        &self,
        rec: &mut Recorder,
        q: &Spanned<super::raw::Quantity>,
        key: &str,
        dim: Dim,
    ) -> Result<f64, Diagnostic> {
        Ok(self.positive_value(rec, q, key, dim)?.file)
    }

    /// The mesh file `file` names, read once per mode however many parts
    /// use it.
    ///
    /// Its warnings (`MeshBody::load_with`) go to `files.mesh_warnings`,
    /// once per file, mode and weld, said at the part's `file` key (or
    /// `weld`'s, for the weld's own).
    fn mesh_body(
        &self,
        file: &Spanned<String>,
        mode: Mode,
        weld: Option<(f64, Range<usize>)>,
        files: &mut Files,
    ) -> Result<Arc<MeshBody>, Diagnostic> {
        let t = self.target_of(file, files, Kind::Mesh)?;
        files.read.push(t.canonical.clone());
        let key = (
            t.canonical.clone(),
            mode,
            weld.as_ref().map(|w| w.0.to_bits()),
        );
        if let Some(m) = files.meshes.get(&key) {
            return Ok(m.clone());
        }
        let format = FileType::of(&t.canonical).expect("`target_of` checked the extension");
        let bytes = crate::mesh::read::file(&t.shown).map_err(|e| {
            self.err(
                file.span(),
                format!("cannot read the mesh file `{}`: {e}", t.shown_name),
            )
        })?;
        let (body, notes) = MeshBody::load_with(format, &bytes, mode, weld.as_ref().map(|w| w.0))
            .map_err(|e| {
            self.err(
                file.span(),
                format!("the mesh file `{}`: {}", t.shown_name, e.message),
            )
        })?;
        for (i, note) in notes.into_iter().enumerate() {
            // The weld's own warning first, at `weld`.
            let span = match &weld {
                Some((_, s)) if i == 0 => s.clone(),
                _ => file.span(),
            };
            files.mesh_warnings.push(super::include::MeshNote {
                path: self.source.name.clone(),
                span: self.source.span(span),
                message: format!("the mesh file `{}`: {note}", t.shown_name),
            });
        }
        let body = Arc::new(body);
        files.meshes.insert(key, body.clone());
        Ok(body)
    }
}

/// A mesh's weight as the file gives it.
enum Density {
    /// `mass`, in the file's units.
    Mass(f64),
    /// Per volume or area in the file's units, the key that gave it, and
    /// the f64 roundings that formed it (`Placed::mass`: a density times
    /// a shell's thickness).
    Per(f64, Range<usize>, f64),
}

fn measure_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Solid => "volume",
        Mode::Shell => "area",
    }
}
