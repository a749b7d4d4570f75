//! The report's JSON with its rows, `parts` and `assemblies` (one per
//! instance of a tree of includes: a gigabyte for 2²⁰ of them) written by hand between the
//! tokens serde_json writes (`summary::deferred`): the same bytes as the
//! rows serialized in place (`json_line`), each sub-assembly's part of them
//! (the start of the names, the `assembly` and `path` arrays) escaped once as it is
//! entered, not once per row.
//!
//! Every number and every string a row holds is still written by the
//! serializer `json_line` uses (`output::json_serializer`); only the
//! punctuation and the keys are written here, as serde_json's compact
//! form writes them, and escaped strings are joined. (Escaping is per
//! character: JSON's escapes and `ControlsEscaped`'s hidden characters;
//! its one rule with context, the runner's `##[`, cannot span the ` / `
//! that joins a path's names.)

use crate::analysis::summary::{AssemblyRow, Row, Summary, deferred};
use serde::Serialize;
use std::io::{self, Write};

/// Written to the stream in pieces of about this many bytes.
const PIECE: usize = 1 << 16;

/// `summary` as `json_line` writes it, to `w`.
pub fn write(summary: &Summary, w: &mut dyn Write) -> io::Result<()> {
    let mut splice = Splice {
        out: w,
        buf: Vec::with_capacity(2 * PIECE),
        summary,
    };
    deferred::while_armed(|| {
        summary
            .serialize(&mut crate::output::json_serializer(&mut splice))
            .map_err(io::Error::from)
    })?;
    splice.buf.push(b'\n');
    splice.out.write_all(&splice.buf)?;
    splice.out.flush()
}

/// The stream under the serializer: buffered, and the rows written where
/// the serialization left them out (`deferred::take`).
struct Splice<'a> {
    out: &'a mut dyn Write,
    buf: Vec<u8>,
    summary: &'a Summary,
}

impl Write for Splice<'_> {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        match deferred::take() {
            None => {}
            Some(deferred::Rows::Parts) => parts(self.summary, &mut self.buf, &mut *self.out)?,
            Some(deferred::Rows::Assemblies) => {
                assemblies(self.summary, &mut self.buf, &mut *self.out)?;
            }
        }
        self.buf.extend_from_slice(bytes);
        if self.buf.len() >= PIECE {
            self.out.write_all(&self.buf)?;
            self.buf.clear();
        }
        Ok(bytes.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        self.out.write_all(&self.buf)?;
        self.buf.clear();
        self.out.flush()
    }
}

/// `x` (a string, a number, a share) as the report's serializer writes it.
fn put<T: Serialize + ?Sized>(out: &mut Vec<u8>, x: &T) {
    // Strings and numbers always serialize (a number that is not finite is
    // `null`), and into memory, which does not fail.
    x.serialize(&mut crate::output::json_serializer(&mut *out))
        .expect("invariant: a string or a number serializes into memory");
}

/// `s` escaped, without its quotes, after `out`.
///
/// NOTE: printable ASCII but `"`, `\` and the runner's `##[` is written as
/// it is by the serializer (`ControlsEscaped`'s one-pass path): a row's
/// own name almost always; any other text goes through the serializer.
fn put_inner(out: &mut Vec<u8>, s: &str, scratch: &mut Vec<u8>) {
    let plain = s
        .bytes()
        .all(|b| (0x20..0x7f).contains(&b) && b != b'"' && b != b'\\');
    if plain && !s.contains(crate::diag::LEGACY_COMMAND) {
        out.extend_from_slice(s.as_bytes());
        return;
    }
    scratch.clear();
    put(scratch, s);
    out.extend_from_slice(&scratch[1..scratch.len() - 1]);
}

/// The elements of `parts`, `,` between them, after `buf`, written to `w`
/// as `buf` fills.
fn parts(s: &Summary, buf: &mut Vec<u8>, w: &mut dyn Write) -> io::Result<()> {
    // The escaped path as a name begins (`a / b / `) and as the `assembly`
    // array holds it (`"a","b"`), with their lengths before each name.
    let mut prefix: Vec<u8> = Vec::new();
    let mut assembly: Vec<u8> = Vec::new();
    let mut open: Vec<(usize, usize)> = Vec::new();
    let mut scratch = Vec::new();
    let mut name = String::new();
    let mut shape: Option<(crate::shapes::Shape, Vec<u8>)> = None;
    let mut first = true;
    let mut failed = None;
    s.parts.each_row(&mut |r| match r {
        Row::Enter(n) => {
            open.push((prefix.len(), assembly.len()));
            put_inner(&mut prefix, n, &mut scratch);
            prefix.extend_from_slice(b" / ");
            if !assembly.is_empty() {
                assembly.push(b',');
            }
            put(&mut assembly, n);
        }
        Row::Exit => {
            let (p, a) = open.pop().expect("an Exit follows its Enter");
            prefix.truncate(p);
            assembly.truncate(a);
        }
        Row::Part(p) => {
            if failed.is_some() {
                return;
            }
            if !first {
                buf.push(b',');
            }
            first = false;
            buf.extend_from_slice(b"{\"name\":\"");
            buf.extend_from_slice(&prefix);
            name.clear();
            p.push_name(&mut name);
            put_inner(buf, &name, &mut scratch);
            buf.extend_from_slice(b"\",\"shape\":");
            let bytes = match &mut shape {
                Some((k, bytes)) if *k == p.shape => bytes,
                _ => {
                    let mut bytes = Vec::new();
                    put(&mut bytes, &p.shape);
                    &mut shape.insert((p.shape, bytes)).1
                }
            };
            buf.extend_from_slice(bytes);
            buf.extend_from_slice(b",\"mass\":");
            put(buf, &p.mass);
            buf.extend_from_slice(b",\"mass_fraction\":");
            put(buf, &p.mass_fraction);
            buf.extend_from_slice(b",\"center_of_mass\":");
            put(buf, &p.center_of_mass);
            buf.extend_from_slice(b",\"principal_moment_share\":");
            put(buf, &p.principal_moment_share);
            buf.extend_from_slice(b",\"assembly\":[");
            buf.extend_from_slice(&assembly);
            buf.extend_from_slice(b"]}");
            spill(buf, w, &mut failed);
        }
    });
    match failed {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// `buf` written to `w` once it holds a piece; the first error kept, and
/// nothing written after it.
fn spill(buf: &mut Vec<u8>, w: &mut dyn Write, failed: &mut Option<io::Error>) {
    if buf.len() >= PIECE {
        if let Err(e) = w.write_all(buf) {
            *failed = Some(e);
        }
        buf.clear();
    }
}

/// The elements of `assemblies`, as `parts`'s.
fn assemblies(s: &Summary, buf: &mut Vec<u8>, w: &mut dyn Write) -> io::Result<()> {
    // The escaped path as the `path` array holds it (`"a","b"`), with its
    // length before each name.
    let mut path: Vec<u8> = Vec::new();
    let mut open: Vec<usize> = Vec::new();
    let mut first = true;
    let mut failed = None;
    s.assemblies.each_row(&mut |r| match r {
        AssemblyRow::Enter(name, a) => {
            open.push(path.len());
            if !path.is_empty() {
                path.push(b',');
            }
            put(&mut path, name);
            if failed.is_some() {
                return;
            }
            if !first {
                buf.push(b',');
            }
            first = false;
            buf.extend_from_slice(b"{\"path\":[");
            buf.extend_from_slice(&path);
            buf.extend_from_slice(b"],\"parts\":");
            put(buf, &a.parts);
            buf.extend_from_slice(b",\"mass\":");
            put(buf, &a.mass);
            buf.extend_from_slice(b",\"mass_fraction\":");
            put(buf, &a.mass_fraction);
            buf.extend_from_slice(b",\"center_of_mass\":");
            put(buf, &a.center_of_mass);
            buf.extend_from_slice(b",\"principal_moment_share\":");
            put(buf, &a.principal_moment_share);
            buf.push(b'}');
            spill(buf, w, &mut failed);
        }
        AssemblyRow::Exit => path.truncate(open.pop().expect("an Exit follows its Enter")),
    });
    match failed {
        Some(e) => Err(e),
        None => Ok(()),
    }
}
