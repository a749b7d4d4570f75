//! Copies of a part or a sub-assembly: `array = { .. }` and `mirror =
//! { .. }` on any `[[part]]`, read and checked (`Ctx::copies`), and each
//! copy's frames (the mirror's, made once: `Copies::image`; the array's,
//! `Copies::array_frame`, moved from copy to copy in place:
//! `Copies::move_array_frame`).
//!
//! NOTE: a copy is a frame, as an include is (`model::frame::Frame`): nothing
//! holds the copies; a walk (`walk`) places each as it reaches it, through
//! the frame of its array and then its mirror's, and drops it. Copy 0 is
//! the part as written (no frame at all, so not one bit changes); copy i
//! of a linear array is moved by i·step; of a polar one turned by
//! `AxisAngle(axis, i·θ)`, the very turn a part written with `rotation =
//! { axis, degrees = i·θ }` has, about `origin` (`origin + R (p − origin)`),
//! so an array composes to what its copies spelt out give: to the last bit
//! at quarter turns, to the rounding of the turn otherwise. With a mirror,
//! the copies [0, N) are the array's, [N, 2N) their images in the same
//! order: copy N + i is the image of copy i.

use super::frame::Pattern;
use super::raw::{Floats, Quantity, RawArray, RawMirror, RawPart, Vector};
use super::tolerance::Recorder;
use super::{Ctx, Frame, Item, MAX_PARTS, Model};
use crate::diag::Diagnostic;
use crate::rotation::Orientation;
use crate::units::Dim;
use std::collections::HashMap;
use std::ops::Range;
use toml::Spanned;

/// The keys any part may have besides its shape's or an include's (the
/// JSON Schema reads them too: `model::schema`).
pub(super) const COPY_KEYS: [&str; 2] = ["array", "mirror"];

/// A part's copies: its array's and its mirror's.
#[derive(Debug, Clone, PartialEq)]
pub struct Copies {
    pattern: Pattern,
    /// The mirror's plane: its normal and a point of it (file units).
    mirror: Option<([f64; 3], [f64; 3])>,
    /// The mirror's frame, made once: the same for every image.
    image: Option<Frame>,
    /// `--only` kept this copy alone (`Model::only`).
    only: Option<usize>,
}

impl Copies {
    /// The array's copies (1 without an array).
    fn count(&self) -> usize {
        match self.pattern {
            Pattern::One => 1,
            Pattern::Linear { count, .. } | Pattern::Polar { count, .. } => count,
        }
    }

    /// All the copies: the array's, twice with a mirror.
    pub fn len(&self) -> usize {
        self.count() * if self.mirror.is_some() { 2 } else { 1 }
    }

    /// Never: a part has at least one copy, itself.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The copies a walk makes: all, or the one `--only` kept.
    pub fn indices(&self) -> Range<usize> {
        match self.only {
            Some(i) => i..i + 1,
            None => 0..self.len(),
        }
    }

    /// These copies, with only copy `i` kept.
    pub(super) fn keeping(&self, i: usize) -> Copies {
        Copies {
            only: Some(i),
            ..self.clone()
        }
    }

    /// Which copy of the array copy `i` is, and whether it is its image
    /// in the mirror.
    pub(super) fn which(&self, i: usize) -> (usize, bool) {
        let n = self.count();
        // No division: i < 2n.
        if i < n { (i, false) } else { (i - n, true) }
    }

    /// Copy `i`'s frames, innermost first: its array's (none for copy 0
    /// of the array) and its mirror's (for an image): what the composer
    /// places the part's or the sub-assembly's body through.
    pub fn frames(&self, i: usize) -> (Option<Frame>, Option<&Frame>) {
        let (k, image) = self.which(i);
        let array = (k > 0).then(|| self.array_frame(k));
        (array, if image { self.image() } else { None })
    }

    /// A bound on the largest coordinate of any copy of a body whose
    /// coordinates are at most `pos` (`frame::Reach`): a step's multiple
    /// added, or a turn or an image about a point (|R x|∞ ≤ √3 |x|∞).
    pub(super) fn reach(&self, pos: f64) -> f64 {
        let inf = |v: &[f64; 3]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let turned = |o: &[f64; 3], p: f64| inf(o) + 1.8 * (p + inf(o));
        let pos = match &self.pattern {
            Pattern::One => pos,
            Pattern::Linear { count, step } => pos + (*count as f64) * inf(step),
            Pattern::Polar { origin, .. } => turned(origin, pos),
        };
        match &self.mirror {
            None => pos,
            Some((_, origin)) => turned(origin, pos),
        }
    }

    /// The mirror's frame, that places the images (none without a
    /// mirror).
    pub(super) fn image(&self) -> Option<&Frame> {
        self.image.as_ref()
    }

    /// The frame that places copy `k` (from 1) of the array
    /// (`Frame::of_copy`).
    pub(super) fn array_frame(&self, k: usize) -> Frame {
        Frame::of_copy(&self.pattern, k)
    }

    /// `f`, another copy's frame, moved in place to copy `k`'s; whether
    /// any bit of it changed (`Frame::move_to_copy`).
    pub(super) fn move_array_frame(&self, k: usize, f: &mut Frame) -> bool {
        f.move_to_copy(&self.pattern, k)
    }

    /// The copy `name` names of the part or sub-assembly `base`
    /// (`base[i]`), if one of these.
    pub(super) fn index_in(&self, base: &str, name: &str) -> Option<usize> {
        let digits = name
            .strip_prefix(base)?
            .strip_prefix('[')?
            .strip_suffix(']')?;
        // Written as the names are: no sign, no leading zeros.
        if digits.is_empty() || (digits.len() > 1 && digits.starts_with('0')) {
            return None;
        }
        let i: usize = digits
            .bytes()
            .all(|b| b.is_ascii_digit())
            .then(|| digits.parse().ok())??;
        (i < self.len()).then_some(i)
    }
}

/// Copy `i` of `base`'s name: `base[i]`, the one form every output shows.
pub fn push_copy_name(out: &mut String, base: &str, i: usize) {
    use std::fmt::Write as _;
    let _ = write!(out, "{base}[{i}]");
}

/// How many parts `p` stands for, as written, before any of it is
/// checked (for the part limit counted before anything is expanded,
/// `include::Ctx::check_part_count`): its array's `count` (1 if it cannot
/// be read: the array is refused where it is read), twice with a mirror.
pub(super) fn raw_multiplicity(p: &RawPart) -> u64 {
    let count = p
        .array
        .as_deref()
        .and_then(|a| a.get_ref().count.as_ref())
        .and_then(|c| match c.get_ref() {
            Quantity::Number(x) if *x >= 1.0 && x.fract() == 0.0 => Some(if *x < u64::MAX as f64 {
                *x as u64
            } else {
                u64::MAX
            }),
            _ => None,
        })
        .unwrap_or(1);
    count.saturating_mul(if p.mirror.is_some() { 2 } else { 1 })
}

impl Ctx<'_> {
    /// A part's `array` and `mirror`, checked; `None` without either.
    pub(super) fn copies(
        &self,
        rec: &mut Recorder,
        p: &RawPart,
    ) -> Result<Option<Box<Copies>>, Diagnostic> {
        if p.array.is_none() && p.mirror.is_none() {
            return Ok(None);
        }
        let pattern = match p.array.as_deref() {
            Some(a) => self.array(rec, a)?,
            None => Pattern::One,
        };
        let mirror = match p.mirror.as_deref() {
            Some(m) => Some(self.mirror(rec, m)?),
            None => None,
        };
        let image = mirror.map(|(normal, origin)| {
            Frame::copy(origin, origin, Orientation::Reflect(normal), true)
        });
        let copies = Copies {
            pattern,
            mirror,
            image,
            only: None,
        };
        if copies.len() > MAX_PARTS {
            let span = p.mirror.as_deref().map_or(0..0, Spanned::span);
            return Err(self.err(
                span,
                format!(
                    "the mirror doubles the array's {} copies past the limit of {MAX_PARTS} parts",
                    copies.count()
                ),
            ));
        }
        Ok(Some(Box::new(copies)))
    }

    fn array(&self, rec: &mut Recorder, a: &Spanned<RawArray>) -> Result<Pattern, Diagnostic> {
        let r = a.get_ref();
        let help = "write `array = { count = N, step = [dx, dy, dz] }` (copies along a step) or `array = { count = N, axis = [x, y, z], step_degrees = θ, origin = [x, y, z] }` (copies about an axis)";
        let Some(count) = &r.count else {
            return Err(self
                .err(a.span(), "`array` needs `count`, the number of copies")
                .help(help));
        };
        let count = self.count(rec, count)?;
        match (&r.step, &r.axis) {
            (Some(step), Some(axis)) => {
                let (later, earlier, span) = if axis.span().start > step.span().start {
                    ("axis", "step", axis.span())
                } else {
                    ("step", "axis", step.span())
                };
                Err(self
                    .err(
                        span,
                        format!("`{later}` conflicts with `{earlier}`: an array is along a step or about an axis"),
                    )
                    .help(help))
            }
            (Some(step), None) => {
                for (key, span) in [
                    ("step_degrees", r.step_degrees.as_ref().map(Spanned::span)),
                    ("origin", r.origin.as_ref().map(Spanned::span)),
                ] {
                    if let Some(span) = span {
                        return Err(self
                            .err(span, format!("`{key}` applies to an array about an axis (with `axis`), not along a `step`"))
                            .help(help));
                    }
                }
                let step = self.point(rec, step, "step")?;
                // The last copy's step, representable.
                let last = (count - 1) as f64;
                if step.iter().any(|s| !(last * s).is_finite()) {
                    return Err(self.err(
                        step_span(r),
                        format!("`step` times {} copies overflows", count - 1),
                    ));
                }
                Ok(Pattern::Linear { count, step })
            }
            (None, Some(axis)) => {
                let axis = self.direction(axis, "axis")?;
                let Some(deg) = &r.step_degrees else {
                    return Err(self
                        .err(a.span(), "an array about an `axis` needs `step_degrees`, the turn from each copy to the next")
                        .help(help));
                };
                let degrees = self.dimensionless(rec, deg, "step_degrees")?;
                if !((count - 1) as f64 * degrees).is_finite() {
                    return Err(self.err(
                        deg.span(),
                        format!("`step_degrees` times {} copies overflows", count - 1),
                    ));
                }
                let origin = match &r.origin {
                    Some(o) => self.point(rec, o, "origin")?,
                    None => [0.0; 3],
                };
                Ok(Pattern::Polar {
                    count,
                    axis,
                    degrees,
                    origin,
                })
            }
            (None, None) => Err(self
                .err(
                    a.span(),
                    "`array` needs `step` (copies along a step) or `axis` and `step_degrees` (copies about an axis)",
                )
                .help(help)),
        }
    }

    fn mirror(
        &self,
        rec: &mut Recorder,
        m: &Spanned<RawMirror>,
    ) -> Result<([f64; 3], [f64; 3]), Diagnostic> {
        let r = m.get_ref();
        let Some(normal) = &r.normal else {
            return Err(self
                .err(m.span(), "`mirror` needs `normal`, the direction normal to its plane")
                .help("write `mirror = { normal = [x, y, z], origin = [x, y, z] }` (the plane through `origin`; [0, 0, 0] if not given)"));
        };
        let normal = self.direction(normal, "normal")?;
        let origin = match &r.origin {
            Some(o) => self.point(rec, o, "origin")?,
            None => [0.0; 3],
        };
        Ok((normal, origin))
    }

    /// `count`: a whole number of copies, 1 to the part limit.
    fn count(&self, rec: &mut Recorder, q: &Spanned<Quantity>) -> Result<usize, Diagnostic> {
        let x = self.dimensionless(rec, q, "count")?;
        // NOTE: whole in the exact rationals the value is read in, not
        // only after its rounding to f64: `"(1 + 1e-20) * 3"` rounds to 3.
        let exact = self.written_value(q);
        if x >= 1.0 && x.fract() == 0.0 && exact.is_some_and(|v| !v.is_whole()) {
            let written = match q.get_ref() {
                Quantity::Text(t) => format!("{t:?}"),
                Quantity::Number(_) => self.source.text[q.span()].to_string(),
            };
            return Err(self
                .err(
                    q.span(),
                    format!("`count` must be a whole number of copies: {written} is not exactly whole (it is {x} only once rounded to f64)"),
                )
                .help("`count` is read exactly, as an expression is: write the whole number, or an expression whose value is exactly one"));
        }
        if !(x >= 1.0 && x.fract() == 0.0) {
            return Err(self
                .err(
                    q.span(),
                    format!("`count` must be a whole number of copies, 1 or more, got {x}"),
                )
                .help("`count` counts the part itself: `count = 4` is the part and 3 copies"));
        }
        if x > MAX_PARTS as f64 {
            return Err(self.err(
                q.span(),
                format!(
                    "`count` of {} copies is past the limit of {MAX_PARTS} parts",
                    if x < 1e15 {
                        format!("{x}")
                    } else {
                        format!("{x:e}")
                    }
                ),
            ));
        }
        Ok(x as usize)
    }

    /// A plain number: a TOML number, or a dimensionless quantity string
    /// or expression (`"32"`, `"spokes / 2"`, `"360 / n"`), read as every
    /// quantity is (`Ctx::value`).
    fn dimensionless(
        &self,
        rec: &mut Recorder,
        q: &Spanned<Quantity>,
        key: &str,
    ) -> Result<f64, Diagnostic> {
        let finite = |x: f64| x.is_finite();
        if matches!(q.get_ref(), Quantity::Number(x) if !finite(*x)) {
            return Err(self.err(q.span(), format!("`{key}` must be finite")));
        }
        let x = self.value(rec, q, key, Dim::DIMENSIONLESS)?.file;
        if !finite(x) {
            return Err(self.err(q.span(), format!("`{key}` must be finite")));
        }
        Ok(x)
    }

    /// A point or step in the file's units, representable in SI too.
    fn point(&self, rec: &mut Recorder, v: &Vector, key: &str) -> Result<[f64; 3], Diagnostic> {
        Ok(self.value3(rec, 0, v, key, Dim::LENGTH)?.0)
    }

    /// A direction: three finite numbers, not all zero.
    fn direction(&self, v: &Floats, key: &str) -> Result<[f64; 3], Diagnostic> {
        let c = self.exactly(v, 3, super::ctx::Whose::Key(key), "numbers")?;
        let mut out = [0.0; 3];
        for (o, x) in out.iter_mut().zip(c) {
            if !x.get_ref().is_finite() {
                return Err(self.err(x.span(), format!("`{key}` must be finite")));
            }
            *o = *x.get_ref();
        }
        if out.iter().all(|x| *x == 0.0) {
            return Err(self.err(v.span(), format!("`{key}` must be a non-zero direction")));
        }
        Ok(out)
    }
}

impl Ctx<'_> {
    /// The body's parts with `raw`'s: `count` before it, `each` per copy
    /// (1 for a part, an included file's parts), refused past the limit
    /// before any copy is made.
    pub(super) fn count_copies(
        &self,
        raw: &Spanned<RawPart>,
        count: usize,
        each: usize,
        copies: Option<&Copies>,
    ) -> Result<usize, Diagnostic> {
        let Some(c) = copies else {
            return Ok(count + each);
        };
        let total = each
            .checked_mul(c.len())
            .and_then(|n| n.checked_add(count))
            .filter(|n| *n <= MAX_PARTS);
        total.ok_or_else(|| {
            self.err(
                copies_span(raw),
                format!(
                    "with its {} copies of {each} part{} this takes the body past {MAX_PARTS} parts, the limit",
                    c.len(),
                    if each == 1 { "" } else { "s" }
                ),
            )
            .help("each copy counts its parts again")
        })
    }

    /// Every copy of `item` representable in the file's units and in SI:
    /// its mass properties (as every part's are checked) and its position.
    /// Walked once, as a body is (nothing held); the failing copy named.
    pub(super) fn copies_in_range(
        &self,
        item: &Item,
        raw: &Spanned<RawPart>,
    ) -> Result<(), Diagnostic> {
        let (Item::Part {
            copies: Some(_), ..
        }
        | Item::Include(_)) = item
        else {
            return Ok(());
        };
        if let Item::Include(inc) = item
            && inc.copies.is_none()
        {
            return Ok(());
        }
        let span = copies_span(raw);
        let one = Model {
            items: std::sync::Arc::new(vec![item.clone()]),
            ..Model::empty(self.units)
        };
        let si = self.units.factor(Dim::LENGTH).value();
        // NOTE: no copy placed when a bound on every instance, formed once
        // per distinct file, is far inside the range (`frame::Reach`).
        if super::frame::Reach::of(&one, &mut HashMap::new()).safe(si) {
            return Ok(());
        }
        let mut bad = None;
        // A coincident copy is the copy before it to the bit: its check is
        // that one's (`each_run`).
        one.each_run(&mut |run| {
            let super::walk::Run::Event(super::Event::Part(leaf)) = run else {
                return;
            };
            let p = leaf.part;
            if bad.is_some() {
                return;
            }
            if !p
                .spec
                .place
                .positions()
                .all(|x| x.is_finite() && (x * si).is_finite())
            {
                bad = Some(true);
            } else if self.in_file_range(&p.spec, "", 0..0).is_err() {
                bad = Some(false);
            }
        });
        let Some(far) = bad else { return Ok(()) };
        // Again, named (the walk names only the copy that fails).
        let mut failed = None;
        one.each_part(&mut |l| {
            let p = l.part;
            if failed.is_none()
                && (!p
                    .spec
                    .place
                    .positions()
                    .all(|x| x.is_finite() && (x * si).is_finite())
                    || self.in_file_range(&p.spec, "", 0..0).is_err())
            {
                failed = Some(p.clone());
            }
        });
        let p = failed.expect("the walk that named it met the part that failed");
        if far {
            return Err(self
                .err(
                    span,
                    format!(
                        "the copy `{}` lies beyond the range of f64 (in the file's units or in SI)",
                        p.name
                    ),
                )
                .help("the array's step or the mirror's plane takes the copies too far"));
        }
        self.in_file_range(&p.spec, &p.name, span)
    }
}

/// The names a file gives its parts and sub-assemblies, kept as the
/// items are made (`note`) and checked once after (`check`), so that each
/// name the file writes selects one thing: a copy's name `NAME[i]`
/// (`array`, `mirror`) may not be a name written in the file, and a
/// sub-assembly numbered automatically (`wheel #2`, for a second
/// sub-assembly named `wheel`) may not take or skip a number another
/// sub-assembly's name has written (`--only "wheel #2"` would select
/// another sub-assembly than the one so named, or none).
///
/// NOTE: only what can clash is kept (the items with copies, the
/// sub-assemblies numbered, and the names written that look like a copy's
/// or a numbered one), so a file of plain parts costs nothing here, and
/// the check is linear in the items.
#[derive(Default)]
pub(super) struct Names {
    /// Written names of the form `BASE[i]`: BASE → (i, where).
    copy_like: HashMap<String, Vec<(usize, Range<usize>)>>,
    /// Sub-assemblies' written names of the form `BASE #k`: BASE → (k,
    /// where).
    numbered_like: HashMap<String, Vec<(usize, Range<usize>)>>,
    /// The items with copies: their base name, how many, where asked.
    copied: Vec<(String, usize, Range<usize>)>,
    /// Sub-assemblies numbered automatically: base, number, where.
    numbered: Vec<(String, usize, Range<usize>)>,
}

/// `BASE[i]` as a copy's name is written (`Copies::index_in`'s form).
fn copy_like(name: &str) -> Option<(&str, usize)> {
    let (base, rest) = name.strip_suffix(']')?.rsplit_once('[')?;
    let ok = !rest.is_empty()
        && rest.bytes().all(|b| b.is_ascii_digit())
        && (rest.len() == 1 || !rest.starts_with('0'));
    Some((base, rest.parse().ok().filter(|_| ok)?))
}

/// `BASE #k`, k ≥ 2, as an automatic number is written.
fn numbered_like(name: &str) -> Option<(&str, usize)> {
    let (base, k) = name.rsplit_once(" #")?;
    let ok = !k.is_empty() && k.bytes().all(|b| b.is_ascii_digit()) && !k.starts_with('0');
    Some((base, k.parse().ok().filter(|k| ok && *k >= 2)?))
}

impl Names {
    /// The item made of raw part `i` (`p`).
    pub(super) fn note(&mut self, i: usize, p: &Spanned<RawPart>, item: &Item) {
        let raw = p.get_ref();
        let (written, base, copies) = match item {
            Item::Part { copies, .. } => (
                raw.name.as_ref().map(|n| (n.get_ref().clone(), n.span())),
                raw.name.as_ref().map(|n| n.get_ref().clone()),
                copies.as_deref(),
            ),
            Item::Include(inc) => {
                // NOTE: as `include::Ctx::include` names it: its `name`,
                // else its file's `name`, else its file name's stem.
                let (written, at) = match (&raw.name, &inc.model.name, &raw.include) {
                    (Some(n), _, _) => (n.get_ref().clone(), n.span()),
                    (None, Some(n), Some(f)) => (n.clone(), f.span()),
                    (None, None, Some(f)) => (
                        std::path::Path::new(f.get_ref())
                            .file_stem()
                            .map(|s| s.to_string_lossy().into_owned())
                            .unwrap_or_else(|| format!("part {}", i + 1)),
                        f.span(),
                    ),
                    (None, _, None) => (inc.name.clone(), p.span()),
                };
                if let Some((b, k)) = numbered_like(&written) {
                    self.numbered_like
                        .entry(b.to_string())
                        .or_default()
                        .push((k, at.clone()));
                }
                if inc.name != written
                    && let Some(k) = inc
                        .name
                        .strip_prefix(written.as_str())
                        .and_then(|r| r.strip_prefix(" #"))
                        .and_then(|k| k.parse().ok())
                {
                    let at = raw.include.as_ref().map_or_else(|| p.span(), |f| f.span());
                    self.numbered.push((written.clone(), k, at));
                }
                (
                    Some((written, at)),
                    Some(inc.name.clone()),
                    inc.copies.as_deref(),
                )
            }
        };
        if let Some((name, at)) = &written
            && let Some((b, k)) = copy_like(name)
        {
            self.copy_like
                .entry(b.to_string())
                .or_default()
                .push((k, at.clone()));
        }
        if let Some(c) = copies {
            let base = base.unwrap_or_else(|| format!("part {}", i + 1));
            self.copied.push((base, c.len(), copies_span(p)));
        }
    }

    /// Refuse the first clash, at the name the file writes, the other
    /// place in a note.
    pub(super) fn check(&self, ctx: &Ctx) -> Result<(), Diagnostic> {
        let place = |at: &Range<usize>| {
            let (line, col) = ctx.source.line_col(at.start);
            format!("{}:{line}:{col}", ctx.source.name)
        };
        for (base, len, at) in &self.copied {
            if let Some((i, written)) = self
                .copy_like
                .get(base)
                .and_then(|w| w.iter().find(|(i, _)| i < len))
            {
                let mut name = String::new();
                push_copy_name(&mut name, base, *i);
                return Err(ctx
                    .err(
                        written.clone(),
                        format!("the name `{name}` is also the name of a copy: `{base}` has {len} copies, `{base}[0]` to `{base}[{}]`", len - 1),
                    )
                    .label("written here")
                    .note(format!("`{base}`'s copies are asked for at {}", place(at)))
                    .help("give it another name: a copy is named by its index, and the tables, `--only`, `check` and `diff` name it so"));
            }
        }
        for (base, k, at) in &self.numbered {
            if let Some((j, written)) = self
                .numbered_like
                .get(base)
                .and_then(|w| w.iter().find(|(j, _)| j <= k))
            {
                return Err(ctx
                    .err(
                        written.clone(),
                        format!(
                            "the sub-assembly name `{base} #{j}` is also a number given automatically: {}",
                            if *k == 2 {
                                format!("a second sub-assembly named `{base}` is numbered `{base} #2`")
                            } else {
                                format!("the sub-assemblies named `{base}` are numbered `{base} #2` to `{base} #{k}`")
                            }
                        ),
                    )
                    .label("written here")
                    .note(format!("the sub-assembly numbered `{base} #{k}` is included at {}", place(at)))
                    .help(format!("name the sub-assemblies apart, each `name` its own (`--only` selects a sub-assembly by its name; a second `{base}` is numbered `{base} #2`, a third `{base} #3`, …)")));
            }
        }
        Ok(())
    }
}

/// Where a part's copies are asked for: its `array`, else its `mirror`.
fn copies_span(raw: &Spanned<RawPart>) -> Range<usize> {
    let p = raw.get_ref();
    p.array
        .as_deref()
        .map(Spanned::span)
        .or_else(|| p.mirror.as_deref().map(Spanned::span))
        .unwrap_or_else(|| raw.span())
}

fn step_span(r: &RawArray) -> Range<usize> {
    r.step.as_ref().map_or(0..0, Spanned::span)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn copies(count: usize, mirror: bool) -> Copies {
        let plane = ([1.0, 0.0, 0.0], [0.0; 3]);
        Copies {
            pattern: Pattern::Linear {
                count,
                step: [1.0, 0.0, 0.0],
            },
            mirror: mirror.then_some(plane),
            image: mirror
                .then(|| Frame::copy(plane.1, plane.1, Orientation::Reflect(plane.0), true)),
            only: None,
        }
    }

    #[test]
    fn a_mirror_doubles_the_copies_and_its_images_follow_the_array() {
        let c = copies(3, true);
        assert_eq!(c.len(), 6);
        assert!(c.image().is_some());
        assert_eq!(c.which(0), (0, false));
        assert_eq!(c.which(2), (2, false));
        assert_eq!(c.which(3), (0, true));
        assert_eq!(c.which(4), (1, true));
        assert!(copies(3, false).image().is_none());
    }

    #[test]
    fn a_copy_is_named_by_its_index_as_written() {
        let c = copies(12, false);
        assert_eq!(c.index_in("leg", "leg[11]"), Some(11));
        assert_eq!(c.index_in("leg", "leg[0]"), Some(0));
        for no in [
            "leg[12]", "leg[01]", "leg[+1]", "leg[]", "leg", "leg[1", "le[1]",
        ] {
            assert_eq!(c.index_in("leg", no), None, "{no}");
        }
        let mut s = String::new();
        push_copy_name(&mut s, "part 3", 7);
        assert_eq!(s, "part 3[7]");
    }

    /// A part with copies, inline or as a sub-table, is read as the reference parser
    /// reads it.
    #[test]
    fn arrays_and_mirrors_read_as_serde_reads_them() {
        let part = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
        for extra in [
            "array = { count = 2, step = [1, 0, 0] }\n",
            "mirror = { normal = [1, 0, 0] }\n",
            "[part.array]\ncount = 2\nstep = [1, 0, 0]\n",
        ] {
            let text = format!("{part}{extra}");
            super::super::fast::tests::same(&text);
            let raw = super::super::fast::read_file(&text).expect("read");
            let p = raw.part.unwrap().into_inner().remove(0).into_inner();
            assert!(p.array.is_some() || p.mirror.is_some(), "{text}");
        }
    }

    #[test]
    fn a_written_name_looks_like_a_copy_as_copies_are_named() {
        assert_eq!(copy_like("leg[3]"), Some(("leg", 3)));
        assert_eq!(copy_like("a[1][0]"), Some(("a[1]", 0)));
        for no in [
            "leg[03]",
            "leg[]",
            "leg[+1]",
            "leg",
            "leg[1] ",
            "leg[99999999999999999999999]",
        ] {
            assert_eq!(copy_like(no), None, "{no}");
        }
    }

    #[test]
    fn a_written_name_looks_numbered_as_automatic_numbers_are() {
        assert_eq!(numbered_like("wheel #2"), Some(("wheel", 2)));
        assert_eq!(numbered_like("wheel #2 #3"), Some(("wheel #2", 3)));
        for no in ["wheel #1", "wheel #02", "wheel #", "wheel#2", "wheel #2[0]"] {
            assert_eq!(numbered_like(no), None, "{no}");
        }
    }

    #[test]
    fn the_raw_count_is_read_before_any_check() {
        let mut p = RawPart::default();
        assert_eq!(raw_multiplicity(&p), 1);
        p.array = Some(Box::new(Spanned::new(
            0..0,
            RawArray {
                count: Some(Spanned::new(0..0, Quantity::Number(1e12))),
                ..RawArray::default()
            },
        )));
        assert_eq!(raw_multiplicity(&p), 1_000_000_000_000);
        p.mirror = Some(Box::new(Spanned::new(0..0, RawMirror::default())));
        assert_eq!(raw_multiplicity(&p), 2_000_000_000_000);
    }
}
