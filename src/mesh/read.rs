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
pub enum FileType {
    Stl,
    Obj,
}

impl FileType {
    /// By the file's extension (case-insensitive): `.stl` or `.obj`.
    pub fn of(path: &std::path::Path) -> Option<FileType> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "stl" => Some(FileType::Stl),
            "obj" => Some(FileType::Obj),
            _ => None,
        }
    }
}

/// A file's triangles: their corners as indices into `points`, and for
/// each the place it came from (the line of its `facet` or `f`, or its
/// record's byte offset). An STL's triangles have three points each; an
/// OBJ's share its `v` list, so a face costs its 12 bytes of indices and
/// its place however many triangles a long `f` line fans into.
#[derive(Debug, Default)]
pub struct Triangles {
    pub points: Vec<[f64; 3]>,
    pub faces: Vec<[u32; 3]>,
    pub at: Vec<At>,
}

impl Triangles {
    /// Triangles given by their corners, each its own three points.
    pub fn of_corners(corners: Vec<[[f64; 3]; 3]>, at: Vec<At>) -> Triangles {
        let faces = (0..corners.len() as u32)
            .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
            .collect();
        Triangles {
            points: corners.into_iter().flatten().collect(),
            faces,
            at,
        }
    }

    fn push(&mut self, corners: [[f64; 3]; 3], at: At) {
        let i = self.points.len() as u32;
        self.points.extend(corners);
        self.faces.push([i, i + 1, i + 2]);
        self.at.push(at);
    }
}

/// A mesh file's bytes, as `std::fs::read` gives them.
///
/// NOTE: a large file is read in one piece a core (`read_exact_at` at
/// each piece's offset, into one buffer whose pages each thread faults in
/// as it writes them): a 50 MB STL's copy out of the page cache took 25
/// ms on one core, a twentieth of its whole report. A file that is not
/// the size it was when asked (written meanwhile) is read again whole.
pub fn file(path: &std::path::Path) -> std::io::Result<Vec<u8>> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileExt;
        let f = std::fs::File::open(path)?;
        let size = f.metadata()?.len();
        let len = usize::try_from(size).unwrap_or(usize::MAX);
        let threads = super::threads_for(len, 1 << 23);
        // A file grown past the limit since its size was checked
        // (`io::MAX_FILE_BYTES`) is not given a buffer of its size here.
        if threads > 1 && size <= crate::io::MAX_FILE_BYTES {
            let mut bytes = vec![0u8; len];
            let piece = len.div_ceil(threads);
            let f = &f;
            let read = std::thread::scope(|scope| {
                let handles: Vec<_> = bytes
                    .chunks_mut(piece)
                    .enumerate()
                    .map(|(k, out)| scope.spawn(move || f.read_exact_at(out, (k * piece) as u64)))
                    .collect();
                handles
                    .into_iter()
                    .all(|h| h.join().is_ok_and(|r| r.is_ok()))
            });
            // Nothing past the end: the file is the size it was.
            if read && f.read_at(&mut [0u8], len as u64).is_ok_and(|n| n == 0) {
                return Ok(bytes);
            }
        }
    }
    std::fs::read(path)
}

/// Read a mesh file's bytes; at most `limit` triangles.
pub fn read(format: FileType, bytes: &[u8], limit: usize) -> Result<Triangles, MeshError> {
    Ok(match corners(format, bytes, limit)? {
        Corners::Listed(t) => t,
        Corners::Stl(s) => s.decoded(),
    })
}

/// A file's corners as the weld reads them: a binary STL's straight from
/// its records, every other file's as read into a list (`Triangles`).
///
/// NOTE: a binary STL is not decoded into a list first: its 1,000,000
/// triangles' 3,000,000 corners would take 72 MB of fresh memory (and
/// 12 MB of indices), written once and read once by the weld, which reads
/// the 50 MB of records as cheaply.
pub enum Corners<'a> {
    Listed(Triangles),
    Stl(StlRecords<'a>),
}

/// Read a mesh file's bytes as the weld takes them; at most `limit`
/// triangles. The same checks and errors as `read`.
pub fn corners(format: FileType, bytes: &[u8], limit: usize) -> Result<Corners<'_>, MeshError> {
    Ok(match format {
        FileType::Stl if is_binary_stl(bytes) => Corners::Stl(binary_stl(bytes, limit)?),
        FileType::Stl => Corners::Listed(ascii_stl_on(
            bytes,
            limit,
            super::threads_for(bytes.len(), 1 << 22),
        )?),
        FileType::Obj => Corners::Listed(obj(bytes, limit)?),
    })
}

/// A binary STL's triangle records (50 bytes each, after the 84 bytes of
/// header and count), its size checked against its count.
#[derive(Debug, Clone, Copy)]
pub struct StlRecords<'a> {
    records: &'a [u8],
}

impl StlRecords<'_> {
    /// Its triangles' count.
    pub(super) fn len(&self) -> usize {
        self.records.len() / 50
    }

    /// Corner `k` (0, 1, 2) of triangle `i`: 12 bytes of normal (ignored:
    /// the winding gives the orientation), three vertices of three f32, 2
    /// bytes of attributes.
    #[inline]
    pub fn corner(&self, i: usize, k: usize) -> [f64; 3] {
        let o = 50 * i + 12 + 12 * k;
        let r = &self.records[o..o + 12];
        std::array::from_fn(|c| {
            f64::from(f32::from_le_bytes([
                r[4 * c],
                r[4 * c + 1],
                r[4 * c + 2],
                r[4 * c + 3],
            ]))
        })
    }

    /// Where triangle `i`'s record is: its byte offset in the file.
    pub fn at(i: usize) -> At {
        At::Byte(84 + 50 * i as u64)
    }

    /// Every corner decoded into a list (`read`'s form).
    fn decoded(self) -> Triangles {
        let n = self.len();
        Triangles {
            points: (0..3 * n).map(|c| self.corner(c / 3, c % 3)).collect(),
            faces: (0..n as u32)
                .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
                .collect(),
            at: (0..n).map(StlRecords::at).collect(),
        }
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
    // NOTE: a header that begins with `solid` but a size that does not fit
    // its count: binary all the same when the bytes after the header are
    // not text (a control character other than white space: a binary
    // STL's count and f32 coordinates nearly always hold one, a text file
    // never), so that a truncated binary STL is called that, not an ASCII
    // file with a bad first line.
    if bytes.len() >= 84
        && bytes[80..]
            .iter()
            .any(|&b| (b < 0x20 && !b.is_ascii_whitespace() && b != 0x0b) || b == 0x7f)
    {
        return true;
    }
    let start = bytes.iter().position(|b| !b.is_ascii_whitespace());
    // Keywords in any case, as most readers take them (`SOLID`).
    !start.is_some_and(|s| {
        bytes[s..]
            .get(..5)
            .is_some_and(|w| w.eq_ignore_ascii_case(b"solid"))
    })
}

fn binary_stl(bytes: &[u8], limit: usize) -> Result<StlRecords<'_>, MeshError> {
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
            if (bytes.len() as u64) < needed {
                format!(
                    "the header says {n} triangles, {needed} bytes, but the file has {} bytes: a truncated binary STL",
                    bytes.len()
                )
            } else {
                format!(
                    "the header says {n} triangles, {needed} bytes, but the file has {} bytes: a binary STL with bytes after its triangles, or not a binary STL",
                    bytes.len()
                )
            },
        ));
    }
    if n > limit as u64 {
        return Err(too_many(At::Byte(80), limit));
    }
    Ok(StlRecords {
        records: &bytes[84..],
    })
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
    let (t, end) = ascii_stl_from(bytes, 1, limit);
    match end {
        End::Done => Ok(t),
        End::Open { last, start } => Err(open(last, start)),
        End::Error(e) => Err(e),
    }
}

/// How the reading of an ASCII STL's lines ended.
enum End {
    Done,
    /// Inside the facet begun on line `start`, at line `last`.
    Open {
        last: usize,
        start: usize,
    },
    Error(MeshError),
}

fn open(last: usize, start: usize) -> MeshError {
    MeshError::new(
        At::Line(last),
        format!("the file ends inside the facet begun on line {start}"),
    )
}

/// `ascii_stl`, the file cut into `threads` pieces read on a thread each.
///
/// NOTE: each cut is moved on to the start of a line whose keyword is
/// `facet` (issue 33, item 4: a 258 MB ASCII STL was read on one core);
/// a piece is read from there as from a file's start (outside a facet,
/// its lines numbered on from the lines before it). A file read in one
/// piece would be outside a facet at that line too, or refuse it (a
/// `facet` inside a facet), or refuse something before: the pieces'
/// triangles, joined in order, are its triangles, and the first piece to
/// end inside a facet (or to refuse a line, or to pass the triangle
/// limit) gives the error the one-piece reading gives. `tests` hold the
/// two equal, errors and their lines included.
pub(crate) fn ascii_stl_on(
    bytes: &[u8],
    limit: usize,
    threads: usize,
) -> Result<Triangles, MeshError> {
    let cuts = facet_cuts(bytes, threads);
    if cuts.len() <= 2 {
        return ascii_stl(bytes, limit);
    }
    let pieces: Vec<&[u8]> = cuts.windows(2).map(|w| &bytes[w[0]..w[1]]).collect();
    // A piece's lines: one more than its newlines, but for the piece that
    // ends on a newline before the next piece's first line.
    let newlines: Vec<usize> = pieces
        .iter()
        .map(|p| p.iter().filter(|b| **b == b'\n').count())
        .collect();
    let read: Vec<(Triangles, End)> = std::thread::scope(|scope| {
        let mut first = 1;
        let handles: Vec<_> = pieces
            .iter()
            .zip(&newlines)
            .map(|(piece, nl)| {
                let from = first;
                first += nl;
                scope.spawn(move || ascii_stl_from(piece, from, limit))
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("invariant: reading a piece does not panic"))
            .collect()
    });
    let mut t = Triangles::default();
    let count = read.len();
    for (k, (piece, end)) in read.into_iter().enumerate() {
        if t.faces.len() + piece.faces.len() > limit {
            return Err(too_many(piece.at[limit - t.faces.len()], limit));
        }
        match end {
            End::Done => {}
            // The file goes on with a `facet` line where this piece ends
            // inside a facet: the one-piece reading refuses that line.
            End::Open { .. } if k + 1 < count => {
                let line = 1 + newlines[..=k].iter().sum::<usize>();
                return Err(MeshError::new(At::Line(line), unexpected(b"facet")));
            }
            End::Open { last, start } => return Err(open(last, start)),
            End::Error(e) => return Err(e),
        }
        let base = t.points.len() as u32;
        t.points.extend(piece.points);
        t.faces
            .extend(piece.faces.into_iter().map(|f| f.map(|i| i + base)));
        t.at.extend(piece.at);
    }
    Ok(t)
}

/// Where the pieces of `ascii_stl_on` begin and end: 0, each `threads`th
/// share of the file moved on to the start of the next line whose keyword
/// is `facet`, and the file's length (duplicates left out).
fn facet_cuts(bytes: &[u8], threads: usize) -> Vec<usize> {
    let mut cuts = vec![0];
    for k in 1..threads.max(1) {
        let mut at = (k * bytes.len() / threads).max(*cuts.last().expect("0 is in"));
        let cut = loop {
            // The start of the next line.
            let Some(nl) = bytes[at..].iter().position(|b| *b == b'\n') else {
                break None;
            };
            at += nl + 1;
            let line = &bytes[at..];
            let end = line.iter().position(|b| *b == b'\n').unwrap_or(line.len());
            if words(&line[..end])
                .next()
                .is_some_and(|w| w.eq_ignore_ascii_case(b"facet"))
            {
                break Some(at);
            }
        };
        match cut {
            Some(c) if c > *cuts.last().expect("0 is in") => cuts.push(c),
            Some(_) => {}
            None => break,
        }
    }
    cuts.push(bytes.len());
    cuts
}

/// The message of an unexpected keyword in an ASCII STL.
fn unexpected(key: &[u8]) -> String {
    format!(
        "unexpected `{}` in an ASCII STL (expected `facet`, `outer loop`, `vertex`, `endloop`, `endfacet`, `solid` or `endsolid`)",
        shown(key)
    )
}

/// An ASCII STL's lines from line `first` on, read as from outside a
/// facet: the triangles read (before the error, if one stopped it), and
/// how the reading ended.
fn ascii_stl_from(bytes: &[u8], first: usize, limit: usize) -> (Triangles, End) {
    let mut t = Triangles::default();
    let end = match ascii_stl_into(&mut t, bytes, first, limit) {
        Ok(None) => End::Done,
        Ok(Some((last, start))) => End::Open { last, start },
        Err(e) => End::Error(e),
    };
    (t, end)
}

fn ascii_stl_into(
    t: &mut Triangles,
    bytes: &[u8],
    first: usize,
    limit: usize,
) -> Result<Option<(usize, usize)>, MeshError> {
    // The facet being read: its line and its vertices so far.
    let mut facet: Option<(usize, Vec<[f64; 3]>)> = None;
    let mut last = 0;
    for (n, line) in lines(bytes) {
        let n = n + first - 1;
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
                if t.faces.len() == limit {
                    return Err(too_many(At::Line(start), limit));
                }
                t.push([vs[0], vs[1], vs[2]], At::Line(start));
            }
            _ => return Err(MeshError::new(At::Line(n), unexpected(key))),
        }
    }
    // Ending inside a facet: the last line and the facet's first.
    Ok(facet.map(|(start, _)| (last, start)))
}

/// A Wavefront OBJ: `v x y z [w]` vertices and `f a b c …` faces, each
/// index `i`, `i/t`, `i//n` or `i/t/n`, from 1, or negative counting back
/// from the last vertex read. A face of more than three vertices is
/// fanned from its first vertex into triangles (exact for a planar convex
/// polygon; a non-planar one's fan is one of its triangulations). Other
/// statements (`vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`,
/// comments) are passed over.
fn obj(bytes: &[u8], limit: usize) -> Result<Triangles, MeshError> {
    let mut t = Triangles::default();
    for (n, line) in lines(bytes) {
        let mut ws = words(line);
        match ws.next() {
            Some(b"v") => {
                if t.points.len() >= 3 * limit {
                    return Err(MeshError::new(
                        At::Line(n),
                        format!("the mesh has more than {} vertices, the limit", 3 * limit),
                    ));
                }
                t.points.push(point(&mut ws, n, "vertex")?);
            }
            Some(b"f") => {
                // NOTE: each index checked and each triangle of the fan
                // kept as it is read (the first corner, the last, this
                // one): a face line of any length holds no list of its own,
                // and meets the triangle limit at the index that passes it.
                let mut first = 0u32;
                let mut last = 0u32;
                let mut count = 0usize;
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
                    let vertices = t.points.len() as i64;
                    let k = if i < 0 { vertices + i } else { i - 1 };
                    if i == 0 || !(0..vertices).contains(&k) {
                        return Err(MeshError::new(
                            At::Line(n),
                            format!(
                                "face: vertex {i} does not exist ({vertices} vertices are read so far)"
                            ),
                        ));
                    }
                    let k = k as u32;
                    match count {
                        0 => first = k,
                        1 => {}
                        _ => {
                            if t.faces.len() == limit {
                                return Err(too_many(At::Line(n), limit));
                            }
                            t.faces.push([first, last, k]);
                            t.at.push(At::Line(n));
                        }
                    }
                    last = k;
                    count += 1;
                }
                if count < 3 {
                    return Err(MeshError::new(
                        At::Line(n),
                        format!("a face of {count} vertices: a face needs 3 or more"),
                    ));
                }
            }
            _ => {}
        }
    }
    Ok(t)
}

#[cfg(test)]
mod tests;
