//! The mesh file readers: binary and ASCII STL, and Wavefront OBJ, into a
//! list of triangles' corners in the file's coordinates (f64), each with
//! the place in the file it came from. Nothing here panics or allocates
//! more than the file's own size allows, whatever the bytes.
//!
//! NOTE: hand-written, not the `stl_io` and `tobj` crates. `stl_io` reads
//! an ASCII STL's coordinates into f32, which drops the digits a text file
//! can carry (a mesh 10⁶ sizes from its origin loses its shape), and
//! neither reports where in the file a bad value is (a line, a byte
//! offset); `tobj` refuses or accepts faces without a line number either.
//! The three formats' grammars are small: the readers are ~250 lines with
//! their positions.

use super::{At, MeshError};

/// Which reader a file takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Stl,
    Obj,
}

impl Format {
    /// By the file's extension (case-insensitive): `.stl` or `.obj`.
    pub fn of(path: &std::path::Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "stl" => Some(Format::Stl),
            "obj" => Some(Format::Obj),
            _ => None,
        }
    }
}

/// A file's triangles: their corners, and for each the place it came from
/// (the line of its `facet` or `f`, or its record's byte offset).
#[derive(Debug, Default)]
pub struct Triangles {
    pub corners: Vec<[[f64; 3]; 3]>,
    pub at: Vec<At>,
}

/// Read a mesh file's bytes; at most `limit` triangles.
pub fn read(format: Format, bytes: &[u8], limit: usize) -> Result<Triangles, MeshError> {
    match format {
        Format::Stl if is_binary_stl(bytes) => binary_stl(bytes, limit),
        Format::Stl => ascii_stl(bytes, limit),
        Format::Obj => obj(bytes, limit),
    }
}

/// A binary STL: an 80-byte header, a u32 count, 50 bytes per triangle.
/// A file whose size is exactly that for its count is binary even when its
/// header begins with `solid` (some exporters write that); else a file
/// that begins with `solid` is ASCII.
fn is_binary_stl(bytes: &[u8]) -> bool {
    if bytes.len() >= 84 {
        let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as u64;
        if bytes.len() as u64 == 84 + 50 * n {
            return true;
        }
    }
    let start = bytes.iter().position(|b| !b.is_ascii_whitespace());
    // Keywords in any case, as most readers take them (`SOLID`).
    !start.is_some_and(|s| {
        bytes[s..]
            .get(..5)
            .is_some_and(|w| w.eq_ignore_ascii_case(b"solid"))
    })
}

fn binary_stl(bytes: &[u8], limit: usize) -> Result<Triangles, MeshError> {
    if bytes.len() < 84 {
        return Err(MeshError::new(
            At::Byte(bytes.len() as u64),
            format!(
                "a binary STL needs an 80-byte header and a triangle count: the file ends after {} bytes",
                bytes.len()
            ),
        ));
    }
    let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as u64;
    let needed = 84 + 50 * n;
    if bytes.len() as u64 != needed {
        return Err(MeshError::new(
            At::Byte(80),
            format!(
                "the header says {n} triangles, {needed} bytes, but the file has {} bytes (truncated, or not a binary STL)",
                bytes.len()
            ),
        ));
    }
    if n > limit as u64 {
        return Err(too_many(At::Byte(80), limit));
    }
    let mut t = Triangles {
        corners: Vec::with_capacity(n as usize),
        at: Vec::with_capacity(n as usize),
    };
    for (i, rec) in bytes[84..].chunks_exact(50).enumerate() {
        // 12 bytes of normal (ignored: the winding gives the orientation),
        // three vertices of three f32, 2 bytes of attributes.
        let f = |k: usize| {
            let o = 12 + 4 * k;
            f64::from(f32::from_le_bytes([
                rec[o],
                rec[o + 1],
                rec[o + 2],
                rec[o + 3],
            ]))
        };
        t.corners.push(std::array::from_fn(|v| {
            std::array::from_fn(|c| f(3 * v + c))
        }));
        t.at.push(At::Byte(84 + 50 * i as u64));
    }
    Ok(t)
}

fn too_many(at: At, limit: usize) -> MeshError {
    MeshError::new(
        at,
        format!("the mesh has more than {limit} triangles, the limit"),
    )
}

/// The lines of a text file, numbered from 1, as bytes (a non-UTF-8 byte
/// is an error only where a number or keyword is read).
fn lines(bytes: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    bytes
        .split(|b| *b == b'\n')
        .enumerate()
        .map(|(i, l)| (i + 1, l.strip_suffix(b"\r").unwrap_or(l)))
}

fn words(line: &[u8]) -> impl Iterator<Item = &[u8]> {
    line.split(|b| b.is_ascii_whitespace())
        .filter(|w| !w.is_empty())
}

/// A word shown in a message: at most 40 characters, escaped.
fn shown(word: &[u8]) -> String {
    let text = String::from_utf8_lossy(&word[..word.len().min(40)]);
    crate::diag::visible(&text)
}

fn number(word: Option<&[u8]>, line: usize, what: &str) -> Result<f64, MeshError> {
    let Some(w) = word else {
        return Err(MeshError::new(
            At::Line(line),
            format!("{what}: a coordinate is missing"),
        ));
    };
    std::str::from_utf8(w)
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .ok_or_else(|| {
            MeshError::new(
                At::Line(line),
                format!("{what}: `{}` is not a number", shown(w)),
            )
        })
}

fn point<'a>(
    ws: &mut impl Iterator<Item = &'a [u8]>,
    line: usize,
    what: &str,
) -> Result<[f64; 3], MeshError> {
    Ok([
        number(ws.next(), line, what)?,
        number(ws.next(), line, what)?,
        number(ws.next(), line, what)?,
    ])
}

/// An ASCII STL: `solid`, then `facet normal …`, `outer loop`, three
/// `vertex x y z`, `endloop`, `endfacet`, …, `endsolid`; more than one
/// solid may follow each other. The normals are not read (the winding
/// gives the orientation).
fn ascii_stl(bytes: &[u8], limit: usize) -> Result<Triangles, MeshError> {
    let mut t = Triangles::default();
    // The facet being read: its line and its vertices so far.
    let mut facet: Option<(usize, Vec<[f64; 3]>)> = None;
    let mut last = 0;
    for (n, line) in lines(bytes) {
        last = n;
        let mut ws = words(line);
        let Some(key) = ws.next() else { continue };
        let upper;
        let key = if key.iter().any(u8::is_ascii_uppercase) {
            upper = key.to_ascii_lowercase();
            &upper[..]
        } else {
            key
        };
        match key {
            b"solid" | b"endsolid" if facet.is_none() => {}
            b"facet" if facet.is_none() => facet = Some((n, Vec::with_capacity(3))),
            b"outer" | b"endloop" if facet.is_some() => {}
            b"vertex" => {
                let Some((_, vs)) = &mut facet else {
                    return Err(MeshError::new(At::Line(n), "`vertex` outside a `facet`"));
                };
                let p = point(&mut ws, n, "vertex")?;
                if vs.len() == 3 {
                    return Err(MeshError::new(
                        At::Line(n),
                        "a facet with more than 3 vertices: STL facets are triangles",
                    ));
                }
                vs.push(p);
            }
            b"endfacet" => {
                let Some((start, vs)) = facet.take() else {
                    return Err(MeshError::new(At::Line(n), "`endfacet` without `facet`"));
                };
                if vs.len() != 3 {
                    return Err(MeshError::new(
                        At::Line(n),
                        format!(
                            "a facet with {} vertices: STL facets are triangles",
                            vs.len()
                        ),
                    ));
                }
                if t.corners.len() == limit {
                    return Err(too_many(At::Line(start), limit));
                }
                t.corners.push([vs[0], vs[1], vs[2]]);
                t.at.push(At::Line(start));
            }
            _ => {
                return Err(MeshError::new(
                    At::Line(n),
                    format!(
                        "unexpected `{}` in an ASCII STL (expected `facet`, `outer loop`, `vertex`, `endloop`, `endfacet`, `solid` or `endsolid`)",
                        shown(key)
                    ),
                ));
            }
        }
    }
    if let Some((start, _)) = facet {
        return Err(MeshError::new(
            At::Line(last),
            format!("the file ends inside the facet begun on line {start}"),
        ));
    }
    Ok(t)
}

/// A Wavefront OBJ: `v x y z [w]` vertices and `f a b c …` faces, each
/// index `i`, `i/t`, `i//n` or `i/t/n`, from 1, or negative counting back
/// from the last vertex read. A face of more than three vertices is
/// fanned from its first vertex into triangles (exact for a planar convex
/// polygon; a non-planar one's fan is one of its triangulations). Other
/// statements (`vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`,
/// comments) are passed over.
fn obj(bytes: &[u8], limit: usize) -> Result<Triangles, MeshError> {
    let mut vertices: Vec<[f64; 3]> = Vec::new();
    let mut t = Triangles::default();
    let mut face: Vec<usize> = Vec::new();
    for (n, line) in lines(bytes) {
        let mut ws = words(line);
        match ws.next() {
            Some(b"v") => {
                if vertices.len() >= 3 * limit {
                    return Err(MeshError::new(
                        At::Line(n),
                        format!("the mesh has more than {} vertices, the limit", 3 * limit),
                    ));
                }
                vertices.push(point(&mut ws, n, "vertex")?);
            }
            Some(b"f") => {
                face.clear();
                for w in ws {
                    let index = w.split(|b| *b == b'/').next().unwrap_or(w);
                    let i = std::str::from_utf8(index)
                        .ok()
                        .and_then(|s| s.parse::<i64>().ok())
                        .ok_or_else(|| {
                            MeshError::new(
                                At::Line(n),
                                format!("face: `{}` is not a vertex index", shown(w)),
                            )
                        })?;
                    let count = vertices.len() as i64;
                    let k = if i < 0 { count + i } else { i - 1 };
                    if i == 0 || !(0..count).contains(&k) {
                        return Err(MeshError::new(
                            At::Line(n),
                            format!(
                                "face: vertex {i} does not exist ({count} vertices are read so far)"
                            ),
                        ));
                    }
                    face.push(k as usize);
                }
                if face.len() < 3 {
                    return Err(MeshError::new(
                        At::Line(n),
                        format!("a face of {} vertices: a face needs 3 or more", face.len()),
                    ));
                }
                for k in 1..face.len() - 1 {
                    if t.corners.len() == limit {
                        return Err(too_many(At::Line(n), limit));
                    }
                    let c = [face[0], face[k], face[k + 1]].map(|i| vertices[i]);
                    t.corners.push(c);
                    t.at.push(At::Line(n));
                }
            }
            _ => {}
        }
    }
    Ok(t)
}
