//! The part keys, each declared once: the keys any part may have here
//! (`part_keys!`), a shape's own in its module (`ShapeKind::OWN_KEYS`).
//! From the declarations come the reader's assignment of a key
//! (`fast`), where each key is when present (`key_spans`), a quantity by
//! its key (`quantity_key`), the messages' "expected …" (`expected`), the
//! did-you-mean candidates (`names`), and the reading of a shape's own
//! key (`read_own`).

use super::Ctx;
use super::ctx::Whose;
use super::raw::{OwnValue, Params, Quantity, RawArray, RawMirror, RawPart, RawRotation, Vector};
use super::tolerance::{Index, Recorder};
use crate::diag::Diagnostic;
use crate::shapes::{Fill, Key, Kind, Scope, Shape, Slot};
use crate::units::Dim;
use std::ops::Range;
use toml::Spanned;

/// Keys of a part with the span of each that is present.
pub(super) type Present<'k> = Vec<(&'k str, Option<Range<usize>>)>;

/// Every key a part of any shape may have, declared once: `name: kind,
/// dimension, the number a "±" on it moves (`Fill`), scope, doc`, each
/// the name of a `RawPart` field of its kind. Hands the list to the macro
/// `$then` (here `declare`, in `fast` its reader's assignment).
///
/// NOTE: a `Fill::Size` or `Fill::Dim` moves a number only on the shapes
/// whose `ShapeInfo::sizes` name the key (a `size` on a box, not a
/// prism: `ShapeInfo::slot`). The `Listed` keys are in the order a part's keys are checked
/// against its shape's (`Ctx::part`: the first that does not apply is
/// named).
macro_rules! part_keys {
    ($then:ident) => {
        $then! {
            name: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Every, "its name in reports (else `part N`)";
            shape: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Every, "the primitive; absent only in a part that `include`s a file";
            density: Kind::Quantity, Dim::DENSITY, Fill::Density, Listed, "its mass per volume";
            areal_density: Kind::Quantity, Dim::AREAL_DENSITY, Fill::Density, Listed, "its mass per area (a thin plate)";
            linear_density: Kind::Quantity, Dim::LINEAR_DENSITY, Fill::Density, Listed, "its mass per length (a slender rod)";
            size: Kind::Quantities(None), Dim::LENGTH, Fill::Size, Listed, "a box's or plate's sizes along its local axes";
            length: Kind::Quantity, Dim::LENGTH, Fill::Dim(Slot::Length), Listed, "its length along its local z (a rod's along x)";
            center: Kind::Point, Dim::LENGTH, Fill::At, Listed, "where its centre is";
            rotation: Kind::Rotation, Dim::DIMENSIONLESS, Fill::No, Listed, "its turn from the file's axes";
            corner: Kind::Point, Dim::LENGTH, Fill::At, Listed, "the corner its `edges` start from";
            edges: Kind::Rows { width: 3, says: Some(("an edge vector", "3 edge vectors")) }, Dim::LENGTH, Fill::Edge, Listed, "the perpendicular edge vectors from its `corner`";
            from: Kind::Point, Dim::LENGTH, Fill::At, Listed, "a rod's first end";
            to: Kind::Point, Dim::LENGTH, Fill::To, Listed, "a rod's second end";
            mass: Kind::Quantity, Dim::MASS, Fill::Mass, Listed, "its mass";
            thickness: Kind::Quantity, Dim::LENGTH, Fill::No, Listed, "a plate's real thickness: reported against, never composed";
            diameter: Kind::Quantity, Dim::LENGTH, Fill::Half("radius"), Listed, "a cylinder's, disk's, sphere's, cone's, hemisphere's or capsule's: twice its `radius`; a rod's real diameter: reported against, never composed";
            radius: Kind::Quantity, Dim::LENGTH, Fill::Dim(Slot::Radius), Listed, "its outer radius (a torus's: its axis to the tube's centre)";
            inner_radius: Kind::Quantity, Dim::LENGTH, Fill::Dim(Slot::InnerRadius), Listed, "the radius of its hollow";
            remove: Kind::Bool, Dim::DIMENSIONLESS, Fill::No, Listed, "a cut-out: subtracted from the body";
            inertia: Kind::Rows { width: 3, says: Some(("a row", "3 rows")) }, Dim::INERTIA, Fill::No, Listed, "a given inertia tensor (rows) about the centroid, local axes";
            products: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Listed, "the sign convention of `inertia`'s products: \"tensor\" or \"positive\"";
            vertices: Kind::Rows { width: 3, says: Some(("a point", "3 points")) }, Dim::LENGTH, Fill::Vertex, Listed, "a triangle's three vertices";
            material: Kind::Str, Dim::DIMENSIONLESS, Fill::Mass, Listed, "a named material instead of a density";
            area: Kind::Quantity, Dim::AREA, Fill::No, Listed, "a rod's cross-section area (with `material`)";
            include: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Listed, "another part file placed here as a sub-assembly";
            origin: Kind::Point, Dim::LENGTH, Fill::At, Listed, "where an included file's origin goes, or a prism's or mesh's local origin";
            params: Kind::ParamsTable, Dim::DIMENSIONLESS, Fill::No, Listed, "parameters passed to the included file";
            joints: Kind::ParamsTable, Dim::DIMENSIONLESS, Fill::No, Listed, "an included robot description's joint positions: name → a number (rad or m) or a quantity";
            inner_diameter: Kind::Quantity, Dim::LENGTH, Fill::Half("inner_radius"), Listed, "the inner diameter, instead of `inner_radius` (`diameter` gives the outer one)";
            top_radius: Kind::Quantity, Dim::LENGTH, Fill::Dim(Slot::TopRadius), Listed, "a cone's radius at its top (local z = +length/2)";
            top_inner_radius: Kind::Quantity, Dim::LENGTH, Fill::Dim(Slot::TopInnerRadius), Listed, "a hollow cone's inner radius at its top";
            tube_radius: Kind::Quantity, Dim::LENGTH, Fill::Dim(Slot::TubeRadius), Listed, "a torus's tube radius";
            inner_tube_radius: Kind::Quantity, Dim::LENGTH, Fill::Dim(Slot::InnerTubeRadius), Listed, "a hollow torus's inner tube radius";
            polygon: Kind::Rows { width: 2, says: None }, Dim::LENGTH, Fill::No, Listed, "a prism's polygon: [x, y] vertices in its local x-y plane";
            file: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Listed, "a mesh's file (STL or OBJ), relative to the part file";
            mesh_unit: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Listed, "the length unit of a mesh file's coordinates";
            mode: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Listed, "a mesh's mode: \"solid\" (the default) or \"shell\"";
            weld: Kind::Quantity, Dim::LENGTH, Fill::No, Listed, "a solid mesh's corners closer than this merged before it is checked (never by default); the bounds count what that changes";
            tol: Kind::Quantity, Dim::MASS, Fill::No, Listed, "the tolerance of `mass`: `0.1`, `\"0.1 kg\"`, `\"2 %\"`, `\"± 0.1 kg uniform\"`";
            array: Kind::ArrayTable, Dim::DIMENSIONLESS, Fill::No, Every, "copies of the part along a step or about an axis, named `NAME[i]`";
            mirror: Kind::MirrorTable, Dim::DIMENSIONLESS, Fill::No, Every, "the part and its mirror image in a plane: `NAME[0]` and `NAME[1]`";
            group: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Every, "its group in the weight statement (`propulsion/tanks`)";
            maturity: Kind::Str, Dim::DIMENSIONLESS, Fill::No, Every, "its design maturity: a key of the file's `[growth]`";
        }
    };
}
pub(super) use part_keys;

/// The declarations, where each key is (`key_spans`) and a quantity by its
/// key (`quantity_key`), from `part_keys!`.
macro_rules! declare {
    ($($name:ident: $kind:expr, $dim:expr, $fill:expr, $scope:ident, $doc:literal;)+) => {
        /// The keys any part may have (a shape's own: `Shape::own_keys`).
        pub(crate) const COMMON: &[Key] = &[$(Key {
            name: stringify!($name),
            kind: $kind,
            dim: $dim,
            fill: $fill,
            positive: false,
            scope: Scope::$scope,
            doc: $doc,
        },)+];

        /// The common keys' spans where present, in `COMMON`'s order.
        fn common_spans(p: &RawPart) -> [Option<Range<usize>>; COMMON.len()] {
            [$(p.$name.as_ref().map(Value::span),)+]
        }

        /// A part's quantity by its key: the density kinds' keys and the
        /// sizes `ShapeInfo` names (`thickness`, `diameter`, `area`).
        pub(super) fn quantity_key<'p>(p: &'p RawPart, key: &str) -> Option<&'p Spanned<Quantity>> {
            match key {
                $(stringify!($name) => p.$name.as_ref().and_then(Value::quantity),)+
                _ => unreachable!("`{key}` is not a quantity key of `ShapeInfo`"),
            }
        }
    };
}
part_keys!(declare);

/// A `RawPart` field's value: its span, and itself if a quantity.
trait Value {
    fn span(&self) -> Range<usize>;
    fn quantity(&self) -> Option<&Spanned<Quantity>> {
        None
    }
}

impl<T: Value> Value for Box<T> {
    fn span(&self) -> Range<usize> {
        (**self).span()
    }
    fn quantity(&self) -> Option<&Spanned<Quantity>> {
        (**self).quantity()
    }
}

impl Value for Spanned<Quantity> {
    fn span(&self) -> Range<usize> {
        Spanned::span(self)
    }
    fn quantity(&self) -> Option<&Spanned<Quantity>> {
        Some(self)
    }
}

macro_rules! spanned_value {
    ($($t:ty),+) => {
        $(impl Value for $t {
            fn span(&self) -> Range<usize> {
                Spanned::span(self)
            }
        })+
    };
}
spanned_value!(
    Spanned<String>,
    Spanned<bool>,
    Vector,
    Spanned<Vec<Vector>>,
    Spanned<RawRotation>,
    Spanned<RawArray>,
    Spanned<RawMirror>,
    Params
);

/// The declaration of a part key: a common one, or a shape's own.
pub(super) fn declared(name: &str) -> Option<&'static Key> {
    COMMON
        .iter()
        .find(|k| k.name == name)
        .or_else(|| crate::shapes::own_key(name))
}

/// Every key a part may have that is checked against its shape's
/// (`Scope::Listed`), with where it is when present: the common keys,
/// then the shape's own keys the part gives.
pub(super) fn key_spans(p: &RawPart) -> Present<'static> {
    let mut keys: Present<'static> = COMMON
        .iter()
        .zip(common_spans(p))
        .filter(|(k, _)| k.scope == Scope::Listed)
        .map(|(k, s)| (k.name, s))
        .collect();
    if let Some(own) = &p.own {
        keys.extend(own.iter().map(|(k, v)| (*k, Some(v.span()))));
    }
    keys
}

/// The keys a part may have (for a did-you-mean): the common ones and
/// those the shapes list (their own among them).
pub(super) fn names() -> impl Iterator<Item = &'static str> {
    let listed = crate::shapes::SHAPES
        .iter()
        .flat_map(|s| s.keys.iter().copied())
        .filter(|k| COMMON.iter().all(|c| c.name != *k));
    COMMON.iter().map(|k| k.name).chain(listed)
}

/// What the value of a part key is, in a message, `depth` arrays inside
/// it; `n` the length of a `size` its shape says. `None` where a key's
/// kind has no more to say than the value's type.
pub(super) fn expected(key: &Key, depth: usize, n: Option<usize>) -> Option<String> {
    const QUANTITIES: &str = "numbers or strings with units";
    let noun = if key.dim == Dim::LENGTH {
        "lengths"
    } else {
        "quantities"
    };
    match (key.kind, depth) {
        (Kind::Point, 0) => Some(format!(
            "an array of 3 {QUANTITIES}, such as [0, 0, \"5 mm\"]"
        )),
        (Kind::Quantities(own), 0) => Some(match own.or(n) {
            Some(n) => format!("an array of {n} {noun} ({QUANTITIES})"),
            None => format!("an array of {noun} ({QUANTITIES})"),
        }),
        (
            Kind::Rows {
                width,
                says: Some((_, rows)),
            },
            0,
        ) => Some(format!("{rows}, each an array of {width} {QUANTITIES}")),
        (
            Kind::Rows {
                width,
                says: Some((row, _)),
            },
            1,
        ) => Some(format!("{row}, an array of {width} {QUANTITIES}")),
        (
            Kind::Quantity
            | Kind::Point
            | Kind::Quantities(_)
            | Kind::Rows { .. }
            | Kind::Str
            | Kind::Bool
            | Kind::Rotation
            | Kind::ArrayTable
            | Kind::MirrorTable
            | Kind::ParamsTable,
            _,
        ) => None,
    }
}

/// A shape's own key `key` as its module asks for it (`Reader::quantity`
/// with `n` 1, `Reader::quantities`): its `n` quantities in the file's
/// units, each checked > 0 if so declared, a tolerance recorded where it
/// is declared to take one.
pub(super) fn read_own(
    ctx: &Ctx,
    rec: &mut Recorder,
    p: &RawPart,
    key: &str,
    n: usize,
) -> Result<Vec<f64>, Diagnostic> {
    let shape = p
        .shape
        .as_ref()
        .expect("a part read by its shape's module has a shape");
    let decl = Shape::from_name(shape.get_ref())
        .and_then(|s| s.own_keys().iter().find(|k| k.name == key))
        .unwrap_or_else(|| {
            unreachable!("`{key}` is asked for by a shape that does not declare it")
        });
    let value = p
        .own
        .as_deref()
        .and_then(|own| own.iter().find(|(k, _)| *k == key));
    let Some((_, value)) = value else {
        return Err(ctx.err(
            shape.span(),
            format!("this {} needs `{key}`", shape.get_ref()),
        ));
    };
    let mut one = |at: Index, q: &Spanned<Quantity>| -> Result<f64, Diagnostic> {
        let x = ctx.value_at(rec, at, q, key, decl.dim)?.file;
        if decl.positive && !(x > 0.0) {
            return Err(ctx.err(q.span(), format!("`{key}` must be positive")));
        }
        Ok(x)
    };
    match (decl.kind, value) {
        (Kind::Quantity, OwnValue::Quantity(q)) if n == 1 => Ok(vec![one(Index::SCALAR, q)?]),
        (Kind::Quantities(Some(m)), OwnValue::Quantities(v)) if m == n => {
            let items = ctx.exactly(v, n, Whose::Key(key), "components")?;
            let mut out = Vec::with_capacity(n);
            for (i, q) in items.iter().enumerate() {
                out.push(one(Index::component(i), q)?);
            }
            Ok(out)
        }
        _ => unreachable!(
            "`{key}` is asked for as {n} quantities, declared {:?}",
            decl.kind
        ),
    }
}

/// The span of `key` among `keys` (from `key_spans`), if present.
pub(super) fn span_of(keys: &[(&str, Option<Range<usize>>)], key: &str) -> Option<Range<usize>> {
    keys.iter()
        .find(|(k, _)| *k == key)
        .and_then(|(_, s)| s.clone())
}

/// The keys of `key_spans`, and `shape`.
pub(super) fn present_keys(p: &RawPart) -> Present<'static> {
    let mut keys: Present<'static> = key_spans(p);
    keys.push(("shape", p.shape.as_ref().map(Spanned::span)));
    keys
}

/// The earliest present key of a set, with its span.
pub(super) fn first<'k>(
    set: &[(&'k str, Option<Range<usize>>)],
) -> Option<(&'k str, Range<usize>)> {
    set.iter()
        .filter_map(|(k, s)| s.clone().map(|s| (*k, s)))
        .min_by_key(|(_, s)| s.start)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::{PROBE, Reader, SHAPES, Slot};
    use std::collections::BTreeSet;

    /// A point with the test's own key `probe_radii` (`shapes::PROBE`:
    /// three lengths, "±" allowed, each > 0) as `value`, read by the fast
    /// path and by serde alike; its reading through the shape's `Reader`
    /// (values in the file's units, and the slots of the tolerances it
    /// recorded), or the message.
    fn probe(value: &str) -> Result<(Vec<f64>, Vec<Slot>), String> {
        let text = format!(
            "units = {{ length = \"mm\" }}\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\nprobe_radii = {value}\n"
        );
        super::super::fast::tests::same(&text);
        let raw = super::super::fast::read_file(&text).expect("read");
        let source = crate::diag::Source::new("probe.toml", text);
        let mut ctx = Ctx {
            source: &source,
            units: Default::default(),
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        ctx.units = ctx
            .file_units(raw.units.as_ref().expect("units"))
            .expect("units");
        let part = &raw.part.as_ref().expect("a part").get_ref()[0];
        let mut rec = Recorder::default();
        rec.enter_part(Shape::Point, COMMON);
        let mut reader = super::super::parts::PartReader {
            ctx: &ctx,
            rec: &mut rec,
            p: part.get_ref(),
            shape: Shape::Point,
            span: part.span(),
            by_edges: false,
            orientation: crate::rotation::Orientation::Identity,
            from: None,
        };
        let read = reader.quantities::<3>("probe_radii");
        let deps = rec.leave_part();
        let read = read.map_err(|d| d.message().to_string())?;
        let slots = deps.iter().flat_map(|d| d.iter().map(|d| d.slot)).collect();
        Ok((read.to_vec(), slots))
    }

    #[test]
    fn a_shapes_own_key_is_read_in_the_files_units() {
        assert_eq!(PROBE.name, "probe_radii");
        let (read, slots) = probe("[1, \"2 cm\", \"0.003 m\"]").expect("read");
        // In mm, the file's length unit: 1, 20, 3.
        assert_eq!(read.len(), 3);
        for (got, want) in read.iter().zip([1.0, 20.0, 3.0]) {
            assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
        }
        assert!(slots.is_empty(), "no tolerance given: {slots:?}");
    }

    #[test]
    fn a_shapes_own_key_takes_a_tolerance_on_each_component() {
        let (read, slots) = probe("[1, \"2 mm ± 0.1 mm\", \"3 mm ± 0.2 mm\"]").expect("read");
        assert_eq!(read, vec![1.0, 2.0, 3.0]);
        assert_eq!(slots, vec![Slot::Own(0, 1), Slot::Own(0, 2)]);
    }

    #[test]
    fn a_negative_or_zero_own_length_is_refused_by_its_key() {
        for value in ["[1, -2, 3]", "[0, 2, 3]", "[1, 2, \"-3 mm\"]"] {
            let e = probe(value).expect_err(value);
            assert_eq!(e, "`probe_radii` must be positive", "{value}");
        }
    }

    #[test]
    fn an_own_key_of_the_wrong_length_or_type_is_refused() {
        let e = probe("[1, 2]").expect_err("two");
        assert!(e.contains("`probe_radii`") && e.contains('3'), "{e}");
        // The wrong type: the reader refuses it, naming the key.
        let text = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\nprobe_radii = 2\n";
        super::super::fast::tests::declines(text);
        let d = super::super::fast::explain(&crate::diag::Source::new("t.toml", text)).to_string();
        assert!(
            d.contains("`probe_radii` has the wrong type: integer `2`"),
            "{d}"
        );
    }

    /// Every key is declared once, among the common keys and every
    /// shape's own, and each own key is one `OwnValue` holds.
    #[test]
    fn every_key_is_declared_once() {
        let mut seen = BTreeSet::new();
        let own = Shape::ALL.iter().flat_map(|s| s.own_keys());
        for k in COMMON.iter().chain(own) {
            assert!(seen.insert(k.name), "`{}` declared twice", k.name);
        }
        for s in Shape::ALL {
            for k in s.own_keys() {
                assert!(super::super::raw::holdable(k.kind), "{}", k.name);
            }
        }
    }

    /// The keys the model reads off a part (`key_spans`) are exactly the
    /// keys the shapes accept and those of an include: a key added to one
    /// and not the other fails here.
    #[test]
    fn the_part_keys_read_are_the_keys_the_shapes_and_includes_accept() {
        let read: BTreeSet<&str> = key_spans(&RawPart::default()).iter().map(|k| k.0).collect();
        // A shape's own keys come from the part (none here), and each is
        // listed by its shape.
        for s in Shape::ALL {
            for k in s.own_keys().iter().filter(|k| k.name != PROBE.name) {
                assert!(
                    s.info().keys.contains(&k.name),
                    "{}: `{}`",
                    s.name(),
                    k.name
                );
            }
        }
        let mut accepted: BTreeSet<&str> =
            SHAPES.iter().flat_map(|s| s.keys.iter().copied()).collect();
        accepted.extend(["include", "origin", "params", "joints"]);
        // `tol` goes wherever `mass` does (`tolerance::accepts`).
        accepted.insert(crate::model::tolerance::TOL_KEY);
        // A shape's own keys are not among the common ones read here.
        accepted.retain(|k| crate::shapes::own_key(k).is_none());
        assert_eq!(read, accepted);
    }

    /// Every quantity key the shape table names (density, real size,
    /// material section) is one `quantity_key` reads.
    #[test]
    fn every_quantity_key_of_the_shape_table_is_read() {
        let p = RawPart::default();
        for s in &SHAPES {
            let keys = s
                .density
                .map(|d| d.key)
                .into_iter()
                .chain(s.real_size.map(|r| r.0))
                .chain(
                    super::super::material::material_keys(s.material)
                        .iter()
                        .copied(),
                );
            for k in keys {
                // Unknown keys are unreachable!: reaching the end is the test.
                assert!(quantity_key(&p, k).is_none(), "{}: `{k}`", s.name);
            }
        }
    }
}
