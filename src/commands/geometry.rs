//! `massprop export ROBOT --from-geometry collision|visual --density D`:
//! each link's inertial computed from its geometry elements — each a
//! shape of massprop's own (box, cylinder, sphere, capsule, ellipsoid) or
//! a mesh read by its mesh reader, at the element's pose, summed per link
//! by the composer — printed, or written in place (`--update`).
//!
//! NOTE: each link's geometry is handed to the model as a part file in SI
//! (written here, numbers in shortest round-trip form, so exactly the
//! robot's), so that every shape's closed form, the mesh reader and the
//! composer are the ones a part file uses; an error in it is said at the
//! geometry element in the robot file.

use super::Outcome;
use super::export::FromGeometry;
use crate::analysis::{self, Settings};
use crate::diag::{Diagnostic, Source};
use crate::numeric::{DD, Real};
use crate::output::inertial::inertial_element;
use crate::robot::Dialect;
use crate::robot::read::{Amount, Geometry, MeshMass, Solid};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// What each part is made of, as its part file writes it, and its density
/// (kg/m³, for a scaled mesh's `inertia` part).
fn made_of(g: &FromGeometry, mjcf: bool) -> Result<(String, f64), Diagnostic> {
    match (&g.density, &g.material) {
        (Some(d), None) => {
            let rho = match crate::units::split_number(d) {
                Ok((x, "")) => x,
                _ => crate::units::parse_quantity(d, crate::units::Dim::DENSITY).map_err(|e| {
                    Diagnostic::plain(format!("invalid value {d:?} for `--density`: {e}; expected kg/m³ or a density with its unit, such as \"1.2 g/cm^3\""))
                })?,
            };
            if !(rho > 0.0 && rho.is_finite()) {
                return Err(Diagnostic::plain(format!(
                    "invalid value {d:?} for `--density`: expected a density > 0"
                )));
            }
            Ok((format!("density = {rho:?}\n"), rho))
        }
        (None, Some(m)) => match crate::materials::built_in(m) {
            Some(mat) => Ok((format!("material = {:?}\n", m), mat.density)),
            None => Err(Diagnostic::plain(format!(
                "`--material {}`: no built-in material of that name (`massprop materials` lists them)",
                crate::diag::shorten(m)
            ))),
        },
        (None, None) if mjcf => Ok(("density = 1000.0\n".to_string(), 1000.0)),
        (None, None) => Err(Diagnostic::plain(
            "`--from-geometry` needs `--density` (kg/m³, or with its unit) or `--material NAME`",
        )),
        (Some(_), Some(_)) => Err(Diagnostic::plain(
            "`--density` and `--material` both given: give one",
        )),
    }
}

/// The mesh file a `filename` or `<uri>` names, absolute.
///
/// NOTE: absolute because the part file written for the link resolves a
/// relative `file` against the robot's own directory again: a robot
/// given as `ex/u.urdf` with `meshes/c.stl` would be looked for at
/// `ex/ex/meshes/c.stl`.
fn mesh_path(uri: &str, base: &Path, packages: &[(String, PathBuf)]) -> Result<PathBuf, String> {
    let path = if let Some(rest) = uri.strip_prefix("package://") {
        let (name, path) = rest.split_once('/').unwrap_or((rest, ""));
        match packages.iter().find(|(n, _)| n == name) {
            Some((_, dir)) => dir.join(path),
            None => {
                return Err(format!(
                    "the mesh `{}` names the package `{}`: give its directory with `--package {}=DIR`",
                    crate::diag::shorten(uri),
                    crate::diag::shorten(name),
                    crate::diag::shorten(name)
                ));
            }
        }
    } else {
        base.join(uri.strip_prefix("file://").unwrap_or(uri))
    };
    Ok(match std::env::current_dir() {
        Ok(here) if path.is_relative() => here.join(path),
        _ => path,
    })
}

/// The length unit whose factor a mesh's uniform `scale` is: a URDF or
/// SDFormat mesh's coordinates times its scale are metres.
fn mesh_unit(scale: [f64; 3]) -> Option<&'static str> {
    if scale[0] != scale[1] || scale[1] != scale[2] {
        return None;
    }
    [
        (1.0, "m"),
        (0.01, "cm"),
        (0.001, "mm"),
        (0.0254, "in"),
        (0.3048, "ft"),
    ]
    .into_iter()
    .find(|(f, _)| *f == scale[0])
    .map(|(_, u)| u)
}

fn point(p: [f64; 3]) -> String {
    format!("[{:?}, {:?}, {:?}]", p[0], p[1], p[2])
}

/// One geometry as a `[[part]]` table.
fn part(g: &Geometry, k: usize, made: &str, file: Option<&Path>) -> String {
    let own = match g.amount {
        Some(Amount::Mass(m)) => format!("mass = {m:?}\n"),
        Some(Amount::Density(d)) => format!("density = {d:?}\n"),
        None => made.to_string(),
    };
    let mut t = format!("[[part]]\nname = \"geometry {k}\"\n{own}");
    let at = match &g.solid {
        Solid::Mesh { .. } => "origin",
        _ => "center",
    };
    let _ = writeln!(t, "{at} = {}", point(g.pose.p));
    if !g.pose.unturned() {
        let r = g.pose.r;
        let _ = writeln!(
            t,
            "rotation = {{ matrix = [{}, {}, {}] }}",
            point(r[0]),
            point(r[1]),
            point(r[2])
        );
    }
    let shape = match &g.solid {
        Solid::Box(s) => format!("shape = \"box\"\nsize = {}\n", point(*s)),
        Solid::Cylinder { radius, length } => {
            format!("shape = \"cylinder\"\nradius = {radius:?}\nlength = {length:?}\n")
        }
        Solid::Capsule { radius, length } => {
            format!("shape = \"capsule\"\nradius = {radius:?}\nlength = {length:?}\n")
        }
        Solid::Sphere(r) => format!("shape = \"sphere\"\nradius = {r:?}\n"),
        Solid::Ellipsoid(r) => format!("shape = \"ellipsoid\"\nradii = {}\n", point(*r)),
        Solid::Mesh { scale, .. } => format!(
            "shape = \"mesh\"\nfile = {:?}\nmesh_unit = {:?}\n",
            file.expect("a mesh's file resolved").to_string_lossy(),
            mesh_unit(*scale).expect("a scale checked")
        ),
    };
    t + &shape
}

/// Run `export ROBOT --from-geometry …`.
pub fn run(robot: &str, g: &FromGeometry, settings: &Settings) -> Result<Outcome, Diagnostic> {
    let source = crate::io::read_source(robot)?;
    let format = Dialect::of_path(Path::new(robot))
        .or_else(|| Dialect::of_text(&source.text))
        .ok_or_else(|| {
            Diagnostic::file(
                &source.name,
                "`--from-geometry` reads a robot description: its root element is not <robot> (URDF), <sdf> or <mujoco> (MJCF)",
            )
        })?;
    let made = made_of(g, format == Dialect::Mjcf)?;
    let packages = settings.includes.packages.clone();
    // Includes followed (SDFormat worlds and models, MJCF `<include>`s):
    // each link's geometry is read in the file it is written in.
    let resolve = crate::robot::read::Resolve {
        packages: packages.clone(),
        roots: settings.includes.roots.clone(),
    };
    let d = crate::robot::read::read_in(&source, format, &resolve)?;
    let kind = if g.visual { "visual" } else { "collision" };
    let chosen: Vec<usize> = match &g.link {
        Some(name) => match d.links.iter().position(|l| l.name == *name) {
            Some(i) => vec![i],
            None => {
                let near = crate::units::suggest(name, d.links.iter().map(|l| l.name.as_str()))
                    .map(|s| format!("; did you mean `{}`?", crate::diag::shorten(s)))
                    .unwrap_or_default();
                return Err(Diagnostic::plain(format!(
                    "`--link {}`: `{}` has no link of that name{near}",
                    crate::diag::shorten(name),
                    source.name
                )));
            }
        },
        None => (0..d.links.len()).collect(),
    };
    // NOTE: only the chosen links' geometry is read: another link's (a
    // missing mesh, a bad `scale`) cannot stop `--link NAME`.
    let mut need = vec![false; d.links.len()];
    chosen.iter().for_each(|&i| need[i] = true);
    let (geos, mesh_warnings) =
        crate::robot::read::geometry(&source, &d, g.visual, Some(&need), &resolve)?;
    let base = source
        .path()
        .parent()
        .map_or_else(PathBuf::new, Path::to_path_buf);
    let mut includes = settings.includes.clone();
    includes.roots.push(if base.as_os_str().is_empty() {
        PathBuf::from(".")
    } else {
        base.clone()
    });
    includes
        .roots
        .extend(packages.iter().map(|(_, d)| d.clone()));
    // A file the robot includes was confined when it was read: the meshes
    // it names are relative to its directory, and may be read from it.
    let dir = |s: &Source| {
        s.path()
            .parent()
            .map_or_else(PathBuf::new, Path::to_path_buf)
    };
    includes.roots.extend(d.files.sources.iter().map(&dir));
    let mut read: Vec<PathBuf> = std::iter::once(&source)
        .chain(&d.files.sources)
        .filter_map(|s| std::fs::canonicalize(s.path()).ok())
        .collect();
    let (mut stdout, mut stderr) = (String::new(), String::new());
    // An MJCF mesh's warnings, each once, at its `<mesh>` asset.
    for w in &mesh_warnings {
        stderr.push_str(&super::mesh_warning(w).line(false));
    }
    let mut computed = Vec::new();
    for i in chosen {
        let name = &d.links[i].name;
        let site = &d.links[i].site;
        let own = d.files.source(&source, site.file);
        if geos[i].is_empty() {
            let _ = writeln!(
                stderr,
                "note: {}: link \"{}\" has no <{kind}> geometry: it keeps its inertial",
                own.name,
                crate::diag::shorten(name)
            );
            continue;
        }
        let base = if site.file == 0 {
            base.clone()
        } else {
            dir(own)
        };
        let (e, files, warnings) = link_inertial(
            &geos[i], name, own, &made, &base, &packages, &includes, settings,
        )
        .map_err(|e| d.files.located(e))?;
        read.extend(files);
        // MJCF: said once per mesh file, at its `<mesh>` asset, above.
        if format != Dialect::Mjcf {
            for w in &warnings {
                stderr.push_str(&w.line(false));
            }
        }
        computed.push((name.clone(), e));
    }
    match &g.update {
        None => {
            for (name, e) in &computed {
                let _ = writeln!(stdout, "<!-- link \"{}\" -->", crate::diag::shorten(name));
                stdout.push_str(&inertial_element(format, e, ""));
                stdout.push('\n');
            }
            Ok(Outcome {
                stderr,
                ..Outcome::ok(stdout, read)
            })
        }
        Some(path) => {
            let name = path.to_string_lossy().into_owned();
            let (file, target) = if g.dry_run {
                (None, crate::io::read_source_at(path)?)
            } else {
                let (file, target) = crate::io::Rewrite::open(&name)?;
                (Some(file), target)
            };
            read.extend(std::fs::canonicalize(path).ok());
            let tformat = Dialect::of_path(path)
                .or_else(|| Dialect::of_text(&target.text))
                .ok_or_else(|| Diagnostic::file(&target.name, "not a robot description: its root element is not <robot> (URDF), <sdf> or <mujoco> (MJCF)"))?;
            let r = crate::robot::read::Resolve {
                packages: packages.clone(),
                roots: settings.includes.roots.clone(),
            };
            let (out, err, files) = super::export::update_robot(
                file, &target, tformat, &computed, &r, g.dry_run, stderr,
            )?;
            read.extend(files);
            Ok(Outcome {
                stderr: err,
                ..Outcome::ok(out, read)
            })
        }
    }
}

/// A link's geometry, as a part file, composed.
fn body(
    text: &str,
    robot: &Source,
    includes: &crate::model::Includes,
    settings: &Settings,
) -> Result<analysis::Loaded, Diagnostic> {
    let source = Source::new(format!("{} (geometry)", robot.name), text.to_string());
    let model = crate::model::Model::parse_with(&source, includes)?;
    analysis::load_model(source, model, settings)
}

/// One link's inertial from its geometries `geos` (each alone first, so
/// that its error is said at its element), the files read, and the
/// warnings of its geometries (a mesh's: a triangle of zero area left out,
/// …), each at its geometry's element, as `report` says them.
#[allow(clippy::too_many_arguments)]
fn link_inertial(
    geos: &[Geometry],
    name: &str,
    source: &Source,
    made: &(String, f64),
    base: &Path,
    packages: &[(String, PathBuf)],
    includes: &crate::model::Includes,
    settings: &Settings,
) -> Result<
    (
        crate::output::inertial::Export,
        Vec<PathBuf>,
        Vec<crate::analysis::plausible::Warning>,
    ),
    Diagnostic,
> {
    let mut text = String::from("units = { length = \"m\", mass = \"kg\" }\n");
    let mut files = Vec::new();
    let mut warnings = Vec::new();
    for (k, geo) in geos.iter().enumerate() {
        let at = |m: String| {
            source.error(
                geo.range.clone(),
                format!("link \"{}\": {m}", crate::diag::shorten(name)),
            )
        };
        // The mesh's warnings, said at its geometry's element in the robot
        // file (the part file written for it is no file of the user's).
        // NOTE: only the mesh's: the part file's plausibility warnings
        // (density, units) would speak of keys the user never wrote.
        let mut said = |loaded: &analysis::Loaded| {
            let span = source.span(crate::robot::read::start_tag(
                &source.text,
                geo.range.clone(),
            ));
            let mesh = loaded
                .summary
                .warnings
                .iter()
                .filter(|w| w.kind == crate::analysis::plausible::Kind::Mesh);
            for w in mesh {
                let message = format!("link \"{}\": {}", crate::diag::shorten(name), w.message);
                if !warnings
                    .iter()
                    .any(|x: &crate::analysis::plausible::Warning| {
                        x.message == message && x.span == span
                    })
                {
                    warnings.push(crate::analysis::plausible::Warning {
                        kind: w.kind,
                        path: source.name.clone(),
                        span,
                        message,
                    });
                }
            }
        };
        let one = match &geo.solid {
            Solid::Mesh { uri, scale } => {
                let file = mesh_path(uri, base, packages).map_err(at)?;
                if mesh_unit(*scale).is_some() {
                    part(geo, k + 1, &made.0, Some(&file))
                } else {
                    let unit = format!(
                        "[[part]]\nname = \"geometry {}\"\ndensity = 1.0\norigin = [0.0, 0.0, 0.0]\nshape = \"mesh\"\nfile = {:?}\nmesh_unit = \"m\"\n",
                        k + 1,
                        file.to_string_lossy()
                    );
                    let loaded = body(&unit, source, includes, settings)
                        .map_err(|e| at(e.message().to_string()))?;
                    said(&loaded);
                    files.extend(loaded.model.included.iter().cloned());
                    let mass = scaled_mesh(&loaded.model, *scale);
                    inertia_part(geo, k + 1, made.1, &mass).ok_or_else(|| {
                        at(format!(
                            "the mesh's `scale` {} {} {} takes its volume, centre or moments out of the range of f64; expected a `scale` that keeps them finite and the volume above zero",
                            scale[0], scale[1], scale[2]
                        ))
                    })?
                }
            }
            _ => part(geo, k + 1, &made.0, None),
        };
        let loaded =
            body(&one, source, includes, settings).map_err(|e| at(e.message().to_string()))?;
        said(&loaded);
        text.push_str(&one);
    }
    let loaded = body(&text, source, includes, settings)?;
    files.extend(loaded.model.included.iter().cloned());
    Ok((
        super::export::export_of(&loaded.summary, false),
        files,
        warnings,
    ))
}

/// The integrals of the one mesh part of `model` (read at unit scale, at
/// the origin), scaled by the geometry's `scale` (`read::scaled`, the rule
/// MJCF's mesh geoms are weighed by).
fn scaled_mesh(model: &crate::model::Model, scale: [f64; 3]) -> MeshMass {
    let mesh = model
        .items
        .iter()
        .find_map(|item| match item {
            crate::model::Item::Part { part, .. } => match &part.spec.place {
                crate::shapes::Place::Mesh(m) => Some(m.mesh.clone()),
                _ => None,
            },
            crate::model::Item::Include(_) => None,
        })
        .expect("invariant: the part file written for a mesh has its mesh part");
    crate::robot::read::scaled(&mesh, scale)
}

/// A mesh scaled by a `scale` that is no length unit's, as a `[[part]]` of
/// `shape = "inertia"`: its mass (the geometry's own, else `rho` times its
/// volume), its centroid placed by the geometry's pose, its tensor about
/// the centroid in the geometry's axes, turned by its rotation. None where
/// a number leaves the range of f64 or the volume is not above zero.
///
/// NOTE: the part file's mesh shape takes one length unit, not a scale per
/// axis (nor a mirror): the scaled solid's integrals are computed here, in
/// double-double, and given to the composer as the part they are.
fn inertia_part(g: &Geometry, k: usize, rho: f64, m: &MeshMass) -> Option<String> {
    let mass = match g.amount {
        Some(Amount::Mass(mass)) => DD::of(mass),
        Some(Amount::Density(d)) => DD::of(d) * m.measure,
        None => DD::of(rho) * m.measure,
    };
    let per = mass / m.measure;
    let r = g.pose.r.map(|row| row.map(DD::of));
    let center: [f64; 3] = std::array::from_fn(|i| {
        (0..3)
            .fold(DD::of(g.pose.p[i]), |a, j| a + r[i][j] * m.centroid[j])
            .f64()
    });
    let trace = m.second[0][0] + m.second[1][1] + m.second[2][2];
    let tensor: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let own = if i == j { trace } else { DD::of(0.0) };
            ((own - m.second[i][j]) * per).f64()
        })
    });
    let finite = m.measure.f64() > 0.0
        && m.measure.f64().is_finite()
        && mass.f64().is_finite()
        && center
            .iter()
            .chain(tensor.iter().flatten())
            .all(|x| x.is_finite());
    if !finite {
        return None;
    }
    let mut t = format!(
        "[[part]]\nname = \"geometry {k}\"\nshape = \"inertia\"\nmass = {:?}\ncenter = {}\n",
        mass.f64(),
        point(center)
    );
    if !g.pose.unturned() {
        let r = g.pose.r;
        let _ = writeln!(
            t,
            "rotation = {{ matrix = [{}, {}, {}] }}",
            point(r[0]),
            point(r[1]),
            point(r[2])
        );
    }
    let _ = writeln!(
        t,
        "inertia = [{}, {}, {}]",
        point(tensor[0]),
        point(tensor[1]),
        point(tensor[2])
    );
    Some(t)
}
