//! MJCF mesh geoms for inertia: `<asset><mesh name file scale inertia>`
//! (its values also from the mesh default classes), the file found as
//! MuJoCo finds it (`<compiler meshdir>`, else `assetdir`, relative to the
//! model file; an absolute path as it is) and confined as a part file's
//! includes are (the model file's directory and the working directory),
//! read by massprop's mesh reader (STL, OBJ: a closed, consistently
//! oriented surface, else refused with the mesh's own message), and
//! weighed as MuJoCo's compiler weighs it (`user_mesh.cc`,
//! `mjCMesh::Process`).
//!
//! MuJoCo moves a mesh's vertices into its inertial frame and moves the
//! geom by the same pose, so the body's mass lies where the file's
//! vertices, scaled and placed at the geom's pose, put it: the exact
//! integrals of that solid, in the geom's frame. Per `<mesh inertia>`:
//!
//! - `exact`: those integrals.
//! - `shell` (mass on the surface, per area): the surface's integrals (a
//!   uniform `scale` only: a non-uniform one changes areas unevenly).
//! - `legacy` (MuJoCo's default): the sum of the tetrahedra joining each
//!   triangle to the surface's centroid (for the centre of mass), then to
//!   the centre of mass (for the volume and the second moments), each
//!   counted positive. Equal to the exact solid's when no tetrahedron is
//!   negative (a convex mesh, or any mesh star-shaped about those points);
//!   otherwise MuJoCo over-counts, and massprop copies it (MuJoCo's
//!   formula, in f64): what MuJoCo simulates.
//! - `convex`: the convex hull's. Equal to the exact solid's when the mesh
//!   is convex (every corner on or behind every triangle's plane); a mesh
//!   that is not is refused.
//!
//! NOTE: MuJoCo keeps vertices in f32 (binary STL is f32 already; an OBJ's
//! decimals, and a `scale` that is not a power of two, are rounded to f32
//! there): massprop reads them in f64, so the two differ by up to ~1e-7 of
//! the mesh's size where the file's numbers are not f32 numbers.

use super::geometry::{MeshMass, scaled};
use super::mjcf_include::Model;
use super::{Value, Xml, qname, quoted};
use crate::diag::{Diagnostic, Source, shorten};
use crate::mesh::{FileType, MeshBody, Mode};
use crate::numeric::{DD, Real};
use roxmltree::Node;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// How MuJoCo weighs a mesh (`<mesh inertia>`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Inertia {
    Legacy,
    Convex,
    Exact,
    Shell,
}

/// A mesh asset, read.
#[derive(Clone, Debug)]
pub(super) struct Loaded {
    pub mass: Arc<MeshMass>,
    /// The file, relative to the model file's directory (or absolute).
    pub uri: String,
    pub scale: [f64; 3],
    /// Weighed as a shell (`inertia="shell"`).
    pub shell: bool,
    /// Weighed by MuJoCo's legacy formula, not as the solid.
    pub legacy: bool,
}

/// A warning of a mesh file MuJoCo weighs (`MeshBody::load_with`: what
/// its exact answer survives, such as a triangle of zero area left out):
/// the file its `<mesh>` asset is written in, as named, and the place of
/// that asset there. Once per mesh file, however many assets or geoms
/// name it.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshWarning {
    pub path: String,
    pub span: crate::diag::Span,
    pub message: String,
}

/// An MJCF model's mesh assets (its included files' too), each read once
/// when a geom needs it.
pub(super) struct Meshes<'s, 'a, 'i> {
    /// Each mesh, with the file it is written in (its index in the model).
    by_name: HashMap<String, (Node<'a, 'i>, usize)>,
    /// `meshdir`, else `assetdir`, as written (empty: none).
    dir: String,
    /// The model file's directory.
    base: PathBuf,
    roots: Vec<PathBuf>,
    /// By name (unique).
    loaded: HashMap<String, Loaded>,
    /// The warnings of the mesh files read, in the order read.
    pub warnings: Vec<MeshWarning>,
    /// (canonical mesh file, warning) said already.
    warned: std::collections::HashSet<(PathBuf, String)>,
    /// The model's files, for a mesh's place.
    sources: Vec<&'s Source>,
}

impl<'s, 'a, 'i> Meshes<'s, 'a, 'i> {
    /// The `<mesh>` assets under `<mujoco>` (in every file of the model),
    /// a name given twice refused.
    pub fn read(m: &Model<'s, 'a, 'i>) -> Result<Meshes<'s, 'a, 'i>, Diagnostic> {
        // NOTE: a mesh's file is relative to the main model file's
        // directory, wherever the `<mesh>` or the `<compiler meshdir>` is
        // written (MuJoCo's `ModelFileDir`).
        let source = m.xmls[0].source;
        let (mut meshdir, mut assetdir) = (None, None);
        for (xml, _, c) in m.sections("compiler") {
            if let Some(v) = xml.attr(c, "meshdir") {
                meshdir = Some(v.text);
            }
            if let Some(v) = xml.attr(c, "assetdir") {
                assetdir = Some(v.text);
            }
        }
        let base = source
            .path()
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."))
            .to_path_buf();
        // Confined as the model's includes are (`sdf_include::roots`): the
        // main file's directory, the working directory, `--include-root`
        // and `--package` directories.
        let roots = m.dirs.clone();
        let mut by_name = HashMap::new();
        for (_, file, asset) in m.sections("asset") {
            // An `<include>` in an `<asset>` brings its meshes there.
            for (file, mesh) in m.children(file, asset) {
                m.in_place(file, mesh)?;
                if qname(mesh) != "mesh" {
                    continue;
                }
                let xml = m.xml(file);
                let m = mesh;
                // MuJoCo names an unnamed mesh after its file, without
                // the directory and the extension.
                let name = match (xml.attr(m, "name"), xml.attr(m, "file")) {
                    (Some(n), _) => n,
                    (None, Some(f)) => Value {
                        text: Path::new(&f.text)
                            .file_stem()
                            .map_or_else(String::new, |s| s.to_string_lossy().into_owned()),
                        ..f
                    },
                    (None, None) => continue,
                };
                if by_name.insert(name.text.clone(), (m, file)).is_some() {
                    return Err(xml.error(
                        name.range.clone(),
                        format!(
                            "`<mesh>` {}: two meshes have this name (MuJoCo refuses a repeated name)",
                            quoted(&name.text)
                        ),
                    ));
                }
            }
        }
        Ok(Meshes {
            by_name,
            dir: meshdir.or(assetdir).unwrap_or_default(),
            base,
            roots,
            loaded: HashMap::new(),
            warnings: Vec::new(),
            warned: std::collections::HashSet::new(),
            sources: m.xmls.iter().map(|x| x.source).collect(),
        })
    }

    /// The mesh a geom's `mesh` attribute `v` names, read and weighed.
    pub fn load(
        &mut self,
        m: &Model,
        xml: &Xml,
        v: &Value,
        owner: &str,
        classes: &super::mjcf_class::Classes,
    ) -> Result<Loaded, Diagnostic> {
        let Some(&(node, file)) = self.by_name.get(&v.text) else {
            let near = crate::units::suggest(&v.text, self.by_name.keys().map(String::as_str))
                .map(|s| format!("; did you mean {}?", quoted(s)))
                .unwrap_or_default();
            return Err(xml.error(
                v.range.clone(),
                format!(
                    "`mesh` of a geom of {owner}: no `<mesh>` asset is named {}{near}",
                    quoted(&v.text)
                ),
            ));
        };
        if let Some(l) = self.loaded.get(&v.text) {
            return Ok(l.clone());
        }
        // The mesh's own values are read, and refused, in its file.
        let source = self.sources[file];
        let mesh_xml = Xml { source };
        let xml = &mesh_xml;
        let class = classes.of(m, file, node)?;
        let attr = |n: &str| classes.attr(xml, node, class, "mesh", n);
        let what = format!("`<mesh>` {}", quoted(&v.text));
        for refused in ["vertex", "face", "refpos", "refquat"] {
            if let Some(r) = attr(refused) {
                return Err(xml
                    .error(
                        r.range.clone(),
                        format!("`{refused}` of {what}: not read for inertia; expected a mesh `file` in its own frame"),
                    )
                    .help(format!("give {owner} an `<inertial>`")));
            }
        }
        if let Some(b) = attr("builtin").filter(|b| b.text != "none") {
            return Err(xml
                .error(
                    b.range.clone(),
                    format!("`builtin` of {what}: a built-in mesh is not read for inertia; expected a mesh `file`"),
                )
                .help(format!("give {owner} an `<inertial>`")));
        }
        let file = attr("file").ok_or_else(|| {
            xml.error(
                xml.tag(node),
                format!("{what} has no `file`: expected an STL or OBJ file"),
            )
        })?;
        let inertia = match attr("inertia") {
            Some(i) => xml.keyword(
                &i,
                &what,
                &[
                    ("convex", Inertia::Convex),
                    ("exact", Inertia::Exact),
                    ("legacy", Inertia::Legacy),
                    ("shell", Inertia::Shell),
                ],
            )?,
            None => Inertia::Legacy,
        };
        let scale_value = attr("scale");
        let scale = match &scale_value {
            Some(s) => {
                let n = xml.numbers::<3>(s, &what)?;
                if n.contains(&0.0) {
                    return Err(xml.error(
                        s.range.clone(),
                        format!(
                            "`scale` of {what}: expected no zero factor (it flattens the mesh)"
                        ),
                    ));
                }
                n
            }
            None => [1.0; 3],
        };
        let uri = Path::new(&self.dir).join(&file.text);
        let shown = if self.base == Path::new(".") {
            uri.clone()
        } else {
            self.base.join(&uri)
        };
        let (bytes, canonical) = self.bytes(xml, &file, &shown)?;
        let format = FileType::of(&shown).expect("`bytes` checked the extension");
        let mode = match inertia {
            Inertia::Shell => Mode::Shell,
            Inertia::Legacy | Inertia::Convex | Inertia::Exact => Mode::Solid,
        };
        let shown_name = crate::diag::display_path(&shown);
        let (body, notes) = MeshBody::load_with(format, &bytes, mode, None).map_err(|e| {
            let d = xml.error(
                file.range.clone(),
                format!("the mesh file `{shown_name}`: {}", e.message),
            );
            match mode {
                Mode::Solid => d.help(format!("MuJoCo weighs this mesh as a solid, which needs a closed surface; `inertia=\"shell\"` on the `<mesh>` weighs the surface itself, or give {owner} an `<inertial>`")),
                Mode::Shell => d,
            }
        })?;
        for note in notes {
            if self.warned.insert((canonical.clone(), note.clone())) {
                self.warnings.push(MeshWarning {
                    path: source.name.clone(),
                    span: source.span(xml.tag(node)),
                    message: format!("the mesh file `{shown_name}`: {note}"),
                });
            }
        }
        let uniform = scale[0].abs() == scale[1].abs() && scale[1].abs() == scale[2].abs();
        if inertia == Inertia::Shell && !uniform {
            let at = scale_value.map_or_else(|| file.range.clone(), |s| s.range);
            return Err(xml.error(
                at,
                format!("`scale` of {what}: a shell (`inertia=\"shell\"`) is read with the same scale on each axis"),
            ));
        }
        let mut mass = scaled(&body, scale);
        let mut by_legacy = false;
        match inertia {
            // NOTE: where no tetrahedron is negative MuJoCo's legacy
            // weighing is the solid's, which the exact integrals give to
            // the last bits; elsewhere its own formula, in f64.
            Inertia::Legacy if legacy_differs(&body, scale, &mass) => {
                mass = legacy(&body, scale);
                by_legacy = true;
            }
            Inertia::Legacy => {}
            Inertia::Convex => {
                if let Some(why) = not_convex(&body) {
                    return Err(xml
                        .error(
                            file.range.clone(),
                            format!("{what}: `inertia=\"convex\"` weighs the mesh's convex hull, and the mesh is not convex ({why}); the hull is not computed"),
                        )
                        .help("set `inertia=\"exact\"` on the `<mesh>` (what the solid weighs), or give the body an `<inertial>`"));
                }
            }
            Inertia::Exact | Inertia::Shell => {}
        }
        // A scale (or mesh) far beyond f64's range: the integrals
        // overflow or vanish.
        let finite = mass.measure.f64() > 0.0
            && mass.measure.f64().is_finite()
            && mass.centroid.iter().all(|c| c.f64().is_finite())
            && mass.second.iter().flatten().all(|x| x.f64().is_finite());
        if !finite {
            let at = scale_value.map_or_else(|| file.range.clone(), |s| s.range);
            return Err(xml.error(
                at,
                format!("{what}: its volume, centre or moments, scaled, leave the range of f64; expected a `scale` that keeps them finite and the volume above zero"),
            ));
        }
        let l = Loaded {
            mass: Arc::new(mass),
            uri: uri.to_string_lossy().into_owned(),
            scale,
            shell: inertia == Inertia::Shell,
            legacy: by_legacy,
        };
        self.loaded.insert(v.text.clone(), l.clone());
        Ok(l)
    }

    /// The bytes of the mesh file `shown` (`file` names it), confined.
    /// Also its canonical path.
    fn bytes(
        &self,
        xml: &Xml,
        file: &Value,
        shown: &Path,
    ) -> Result<(Vec<u8>, PathBuf), Diagnostic> {
        let shown_name = crate::diag::display_path(shown);
        let at = |m: String| xml.error(file.range.clone(), m);
        let canonical = std::fs::canonicalize(shown).map_err(|e| {
            at(format!("cannot read the mesh file `{shown_name}`: {e}"))
                .help("the path is relative to the model file, after `<compiler meshdir>` (else `assetdir`)")
        })?;
        if !super::sdf_include::inside(&self.roots, &canonical) {
            return Err(at(format!(
                "the mesh file `{shown_name}` is outside the directory of the model file and the working directory"
            ))
            .help("mesh files stay inside those directory trees (after following symlinks); `--include-root DIR` allows another"));
        }
        if FileType::of(&canonical).is_none() {
            return Err(at(format!(
                "the mesh file `{shown_name}` is not a mesh file massprop reads (`*.stl` or `*.obj`)"
            )));
        }
        let meta = std::fs::metadata(&canonical)
            .map_err(|e| at(format!("cannot read the mesh file `{shown_name}`: {e}")))?;
        if !meta.is_file() {
            return Err(at(format!(
                "the mesh file `{shown_name}` is not a regular file"
            )));
        }
        if meta.len() > crate::io::MAX_FILE_BYTES {
            return Err(at(format!(
                "the mesh file `{shown_name}` is larger than the limit of {} MiB",
                crate::io::MAX_FILE_BYTES >> 20
            )));
        }
        let bytes = crate::mesh::read::file(&canonical).map_err(|e| {
            at(format!(
                "cannot read the mesh file `{}`: {e}",
                shorten(&shown_name)
            ))
        })?;
        Ok((bytes, canonical))
    }
}

/// Six times the signed volume of the tetrahedron (apex, a, b, c).
fn tet6(apex: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    let u = sub(a, apex);
    let v = sub(b, apex);
    let w = sub(c, apex);
    dot(u, cross(v, w))
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The mesh's triangles with its corners scaled by `s`.
fn scaled_triangles(b: &MeshBody, s: [f64; 3]) -> Vec<[[f64; 3]; 3]> {
    b.faces
        .iter()
        .map(|f| f.map(|i| std::array::from_fn(|k| b.points[i as usize][k] * s[k])))
        .collect()
}

/// The surface's centroid (each triangle's centroid weighted by its area).
fn face_centroid(tris: &[[[f64; 3]; 3]]) -> [f64; 3] {
    let (mut area, mut first) = (0.0, [0.0; 3]);
    for [a, b, c] in tris {
        let w = dot(
            cross(sub(*b, *a), sub(*c, *a)),
            cross(sub(*b, *a), sub(*c, *a)),
        )
        .sqrt();
        area += w;
        for i in 0..3 {
            first[i] += w * (a[i] + b[i] + c[i]) / 3.0;
        }
    }
    first.map(|x| x / area)
}

/// Whether MuJoCo's legacy weighing of the mesh (scaled by `s`) differs
/// from the solid's `m`: a tetrahedron from the surface's centroid or from
/// the centre of mass to a triangle that is negative (beyond round-off).
fn legacy_differs(b: &MeshBody, s: [f64; 3], m: &MeshMass) -> bool {
    let tris = scaled_triangles(b, s);
    // A mirroring scale turns the outward triangles inward.
    let sign = if s[0] * s[1] * s[2] < 0.0 { -1.0 } else { 1.0 };
    let tol = 1e-12 * 6.0 * m.measure.f64();
    let com = m.centroid.map(|x| x.f64());
    [face_centroid(&tris), com].into_iter().any(|apex| {
        tris.iter()
            .any(|[a, bb, c]| sign * tet6(apex, *a, *bb, *c) < -tol)
    })
}

/// MuJoCo's legacy weighing (`mjCMesh::ComputeVolume` and
/// `ComputeInertia` with `mjMESH_INERTIA_LEGACY`), in f64 as MuJoCo
/// computes it: the centre of mass of the tetrahedra from the surface's
/// centroid to each triangle, each volume counted positive; then the
/// second moments and the volume (the mass's) of the tetrahedra from that
/// centre, each counted positive.
fn legacy(b: &MeshBody, s: [f64; 3]) -> MeshMass {
    let tris = scaled_triangles(b, s);
    let facecen = face_centroid(&tris);
    let (mut volume, mut first) = (0.0, [0.0; 3]);
    for [a, bb, c] in &tris {
        let v = (tet6(facecen, *a, *bb, *c) / 6.0).abs();
        volume += v;
        for i in 0..3 {
            first[i] += v * ((a[i] + bb[i] + c[i]) / 3.0 * 0.75 + facecen[i] * 0.25);
        }
    }
    let com = first.map(|x| x / volume);
    let (mut total, mut p) = (0.0, [[0.0; 3]; 3]);
    for t in &tris {
        let [d, e, f] = t.map(|x| sub(x, com));
        let v = (tet6([0.0; 3], d, e, f) / 6.0).abs();
        total += v;
        for i in 0..3 {
            for j in 0..3 {
                p[i][j] += v / 20.0
                    * (2.0 * (d[i] * d[j] + e[i] * e[j] + f[i] * f[j])
                        + d[i] * e[j]
                        + d[j] * e[i]
                        + d[i] * f[j]
                        + d[j] * f[i]
                        + e[i] * f[j]
                        + e[j] * f[i]);
            }
        }
    }
    MeshMass {
        measure: DD::of(total),
        centroid: com.map(DD::of),
        second: p.map(|row| row.map(DD::of)),
    }
}

/// The most corner-plane tests the convexity check makes.
const CONVEX_WORK: usize = 50_000_000;

/// Why the mesh is not convex (a corner in front of a triangle's plane),
/// or too large to check.
fn not_convex(b: &MeshBody) -> Option<String> {
    let (pts, faces) = (&b.points, &b.faces);
    if pts.len().saturating_mul(faces.len()) > CONVEX_WORK {
        return Some(format!(
            "not checked: {} corners by {} triangles is past the {CONVEX_WORK} tests the check makes",
            pts.len(),
            faces.len()
        ));
    }
    let size = (0..3)
        .map(|i| b.extent[1][i] - b.extent[0][i])
        .fold(0.0, f64::max);
    for f in faces.iter() {
        let [a, bb, c] = f.map(|i| pts[i as usize]);
        let u = [bb[0] - a[0], bb[1] - a[1], bb[2] - a[2]];
        let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let n = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        for p in pts.iter() {
            let h = (n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2])) / len;
            if h > 1e-12 * size {
                return Some(format!(
                    "its corner {} lies in front of a triangle's plane",
                    crate::mesh::check::point(*p)
                ));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit cube from (1, 2, 3) to (2, 3, 4), triangles outward.
    const CUBE: &str = "v 1 2 3\nv 2 2 3\nv 2 3 3\nv 1 3 3\nv 1 2 4\nv 2 2 4\nv 2 3 4\nv 1 3 4\n\
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

    fn cube(mode: Mode) -> MeshBody {
        MeshBody::load(FileType::Obj, CUBE.as_bytes(), mode).unwrap()
    }

    fn f(x: DD) -> f64 {
        x.f64()
    }

    #[test]
    fn a_scale_stretches_the_volume_and_mirrors_the_centroid() {
        // Scaled by (2, −1, 3): a 2 × 1 × 3 box of volume 6, centroid
        // (3, −2.5, 10.5); ∫x² about it = V a²/12 with a = 2.
        let m = scaled(&cube(Mode::Solid), [2.0, -1.0, 3.0]);
        assert!((f(m.measure) - 6.0).abs() < 1e-14);
        let c = m.centroid.map(f);
        assert!(
            (c[0] - 3.0).abs() < 1e-14 && (c[1] + 2.5).abs() < 1e-14 && (c[2] - 10.5).abs() < 1e-14
        );
        assert!((f(m.second[0][0]) - 6.0 * 4.0 / 12.0).abs() < 1e-13);
        assert!((f(m.second[2][2]) - 6.0 * 9.0 / 12.0).abs() < 1e-13);
        assert!(f(m.second[0][1]).abs() < 1e-13);
    }

    #[test]
    fn a_uniform_scale_multiplies_a_shells_area_by_its_square() {
        let m = scaled(&cube(Mode::Shell), [-2.0, 2.0, 2.0]);
        assert!((f(m.measure) - 24.0).abs() < 1e-13);
    }

    #[test]
    fn mujocos_legacy_formula_on_a_cube_is_the_cube() {
        // Convex: no tetrahedron negative, and the formula itself gives
        // the solid: volume 1, centroid (1.5, 2.5, 3.5), ∫x² = 1/12.
        let b = cube(Mode::Solid);
        let exact = scaled(&b, [1.0; 3]);
        assert!(!legacy_differs(&b, [1.0; 3], &exact));
        let l = legacy(&b, [1.0; 3]);
        assert!((f(l.measure) - 1.0).abs() < 1e-14);
        let c = l.centroid.map(f);
        assert!(
            (c[0] - 1.5).abs() < 1e-14 && (c[1] - 2.5).abs() < 1e-14 && (c[2] - 3.5).abs() < 1e-14
        );
        assert!((f(l.second[1][1]) - 1.0 / 12.0).abs() < 1e-14);
        assert!(f(l.second[0][2]).abs() < 1e-14);
    }

    #[test]
    fn a_cube_is_convex_and_an_l_is_not() {
        assert_eq!(not_convex(&cube(Mode::Solid)), None);
        let l = "v 0 0 1\nv 2 0 1\nv 2 1 1\nv 1 1 1\nv 1 2 1\nv 0 2 1\n\
v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n\
f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 6\nf 7 9 8\nf 7 10 9\nf 7 11 10\nf 7 12 11\n\
f 7 8 2\nf 7 2 1\nf 8 9 3\nf 8 3 2\nf 9 10 4\nf 9 4 3\nf 10 11 5\nf 10 5 4\nf 11 12 6\nf 11 6 5\nf 12 7 1\nf 12 1 6\n";
        let b = MeshBody::load(FileType::Obj, l.as_bytes(), Mode::Solid).unwrap();
        assert!(not_convex(&b).is_some_and(|w| w.contains("in front of a triangle's plane")));
    }
}
