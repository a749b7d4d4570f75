//! What the shapes placed by their `center` and turned by their
//! `orientation` (or by a corner and edges: `by_corner_or_centre!`)
//! share, written once: the methods of `ShapeKind` that
//! follow from their named dimensions (`placed_by_centre!`) and from a
//! centroid that is their centre (`centred_centroid!`), used inside each
//! such shape's `impl ShapeKind`.

/// The methods of `ShapeKind` that every shape placed by its `center` and
/// turned by its `orientation`, its dimensions named, shares: its measure
/// and own second moment from its closed forms (R diag(d) Rᵀ,
/// `common::diagonal`), the moments checked for range, a frame's move,
/// its numbers by slot, its mirror image and the rest (`centre_placed!`).
/// Its dimensions are scalar fields, each in a slot of its own (`radius:
/// Radius, length: Length`, in the order its closed forms take them), or
/// one array field of n, a shape's own key, its component k in
/// `Slot::Own(key, k)` (`radii: [Own(0); 3]`). `centroid` and `centroid_error` are
/// `centred_centroid!`'s for a shape whose centroid is its centre.
///
/// NOTE: both forms hand the per-field code to `@methods` with the names
/// it binds (`self`, the lift, the mover, the callback, the source): a
/// macro's `self` is hygienic, so the methods' parameters must be the
/// tokens the field code was written with.
macro_rules! placed_by_centre {
    (@methods $s:ident, $l:ident, $m:ident, $f:ident, $src:ident;
        dims: $dims:expr,
        values: $values:expr,
        moved: { $($moved:tt)* },
        numbers: { $($numbers:tt)* },
        reset: { $($reset:tt)* }
    ) => {
        centre_placed!();

        fn measure<T: Real, L: Lift>(&$s, $l: L) -> T {
            let _ = &$l;
            Self::measure_of::<T>(&$dims)
        }

        fn own_second_moment<T: Real, L: Lift>(
            &$s,
            m: T,
            units: Option<Units>,
            $l: L,
        ) -> (M3<T>, Option<Own>) {
            let _ = &$l;
            let d = Self::moments_of::<T>(m, &$dims);
            $crate::shapes::common::diagonal(d, &$s.orientation, units, Self::MOMENT_ROUNDINGS)
        }

        fn independent_moments(&$s, m: f64, _: &M3<f64>) -> ([f64; 3], usize, usize) {
            (
                Self::moments_of(m, &$values),
                3,
                Self::INFO.nonzero_moments,
            )
        }

        fn moved(&mut $s, $m: &impl Mover) {
            $s.center = $m.point($s.center);
            $($moved)*
            $m.turn(&mut $s.orientation);
        }

        fn numbers<'a>(&'a mut $s, $f: &mut dyn FnMut(Slot, &'a mut f64)) {
            let [x, y, z] = &mut $s.center;
            $f(Slot::At(0), x);
            $f(Slot::At(1), y);
            $f(Slot::At(2), z);
            $($numbers)*
        }

        fn reset_from(&mut $s, $src: &Self) {
            $s.center = $src.center;
            $($reset)*
            $crate::shapes::common::reset_turn(&mut $s.orientation, &$src.orientation);
        }

        fn mirror(&mut self) {
            $crate::shapes::common::flip(
                $crate::shapes::common::mirror_axis::<Self>(),
                &mut self.orientation,
            );
        }

        fn turn(&self) -> Option<$crate::numeric::M3<f64>> {
            Some(self.orientation.matrix())
        }
    };
    ($field:ident: [Own($key:literal); $n:literal]) => {
        placed_by_centre!(@methods self, l, m, f, src;
            dims: std::array::from_fn::<_, $n, _>(|k| {
                $crate::shapes::common::var(self.$field[k], Slot::Own($key, k as u8), l)
            }),
            values: self.$field,
            moved: { self.$field = self.$field.map(|x| x * m.length()); },
            numbers: {
                for (k, x) in self.$field.iter_mut().enumerate() {
                    f(Slot::Own($key, k as u8), x);
                }
            },
            reset: { self.$field = src.$field; }
        );
    };
    ($($field:ident: $slot:ident),* $(,)?) => {
        placed_by_centre!(@methods self, l, m, f, src;
            dims: [$($crate::shapes::common::var(self.$field, Slot::$slot, l)),*],
            values: [$(self.$field),*],
            moved: { $(self.$field *= m.length();)* },
            numbers: { $(f(Slot::$slot, &mut self.$field);)* },
            reset: { $(self.$field = src.$field;)* }
        );
    };
}

/// The methods of `ShapeKind` that a shape placed by its `center` shares
/// whatever its dimensions (a given inertia's too): one rounding count,
/// no span, its density's power of length from its kind, no scaled
/// rounding, and its centre as its reach and its one position.
macro_rules! centre_placed {
    () => {
        fn measure_error(&self) -> f64 {
            Self::MEASURE_ROUNDINGS
        }

        fn shortest_span(&self) -> f64 {
            f64::INFINITY
        }

        fn density_power(&self) -> i32 {
            $crate::shapes::common::density_power::<Self>()
        }

        fn scaled_rounding(&self) -> Option<f64> {
            None
        }

        fn reach(&self) -> f64 {
            $crate::shapes::common::norm1(&self.center)
        }

        fn positions(&self) -> ([[f64; 3]; 4], usize) {
            $crate::shapes::common::points(&[self.center])
        }
    };
}

/// `centroid` and `centroid_error` of a shape whose centroid is its
/// `center`: a number of the file, its error the frames' rounding alone.
macro_rules! centred_centroid {
    () => {
        fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
            $crate::shapes::common::at(&self.center, l)
        }

        fn centroid_error(&self, at: f64, _: &[f64; 3]) -> [f64; 3] {
            $crate::shapes::common::exact_centroid_error(at)
        }
    };
}

/// The methods of `ShapeKind` of a shape placed either by its `center`,
/// `size` (`n` lengths) and turn, or by a `corner` and its `n`
/// perpendicular `edges` (`$ty::Centred`, `$ty::Spanned`: a box, a plate):
/// its reading, physics, moves, slots, mirror and outline.
macro_rules! by_corner_or_centre {
    ($ty:ident, $n:literal) => {
        fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
            if r.by_edges() {
                let edges = r.vectors("edges")?;
                return Ok($ty::Spanned {
                    corner: r.point("corner")?,
                    edges,
                });
            }
            let size = r.sizes()?;
            Ok($ty::Centred {
                center: r.point("center")?,
                size,
                orientation: r.orientation(),
            })
        }

        fn measure<T: Real, L: Lift>(&self, l: L) -> T {
            match self {
                $ty::Centred { size, .. } => {
                    Self::measure_of(&$crate::shapes::common::sizes(size, l))
                }
                $ty::Spanned { edges, .. } => $crate::shapes::common::edges_measure(edges, l),
            }
        }

        /// Centred, its own count; spanned, a norm per edge (3 for the
        /// squares' sum, 2 for the root) and a product.
        fn measure_error(&self) -> f64 {
            match self {
                $ty::Centred { .. } => Self::MEASURE_ROUNDINGS,
                $ty::Spanned { .. } => 6.0 * $n as f64,
            }
        }

        fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
            match self {
                $ty::Centred { center, .. } => $crate::shapes::common::at(center, l),
                $ty::Spanned { corner, edges } => {
                    $crate::shapes::common::edges_centroid(corner, edges, l)
                }
            }
        }

        fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
            match self {
                $ty::Centred { .. } => $crate::shapes::common::exact_centroid_error(at),
                $ty::Spanned { edges, .. } => {
                    $crate::shapes::common::edges_centroid_error(edges, at, centroid)
                }
            }
        }

        fn own_second_moment<T: Real, L: Lift>(
            &self,
            m: T,
            units: Option<Units>,
            l: L,
        ) -> (M3<T>, Option<Own>) {
            match self {
                $ty::Centred {
                    size, orientation, ..
                } => {
                    let d = Self::moments_of(m, &$crate::shapes::common::sizes(size, l));
                    $crate::shapes::common::diagonal(d, orientation, units, Self::MOMENT_ROUNDINGS)
                }
                $ty::Spanned { edges, .. } => $crate::shapes::common::spanned(
                    m,
                    &$crate::shapes::common::edges_in(edges, l),
                    units,
                ),
            }
        }

        fn shortest_span(&self) -> f64 {
            f64::INFINITY
        }

        fn independent_moments(&self, m: f64, _: &M3<f64>) -> ([f64; 3], usize, usize) {
            let parts = match self {
                $ty::Centred { size, .. } => Self::moments_of(m, size),
                $ty::Spanned { edges, .. } => {
                    let mut parts = [0.0; 3];
                    for (p, e) in parts.iter_mut().zip(edges) {
                        // (m e) e, not m (e e): e² alone can underflow or
                        // overflow.
                        *p = e.iter().map(|x| (m / 12.0 * x) * x).sum();
                    }
                    parts
                }
            };
            let count = match self {
                $ty::Centred { .. } => 3,
                $ty::Spanned { .. } => $n,
            };
            (parts, count, Self::INFO.nonzero_moments)
        }

        fn moved(&mut self, m: &impl Mover) {
            match self {
                $ty::Centred {
                    center,
                    size,
                    orientation,
                } => {
                    *center = m.point(*center);
                    *size = size.map(|x| x * m.length());
                    m.turn(orientation);
                }
                $ty::Spanned { corner, edges } => {
                    *corner = m.point(*corner);
                    *edges = edges.map(|e| m.dir(e));
                }
            }
        }

        fn density_power(&self) -> i32 {
            $crate::shapes::common::density_power::<Self>()
        }

        fn scaled_rounding(&self) -> Option<f64> {
            None
        }

        fn reach(&self) -> f64 {
            match self {
                $ty::Centred { center, .. } => $crate::shapes::common::norm1(center),
                $ty::Spanned { corner, .. } => $crate::shapes::common::norm1(corner),
            }
        }

        fn positions(&self) -> ([[f64; 3]; 4], usize) {
            match self {
                $ty::Centred { center, .. } => $crate::shapes::common::points(&[*center]),
                $ty::Spanned { corner, edges } => {
                    $crate::shapes::common::spanned_points(corner, edges)
                }
            }
        }

        fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
            match self {
                $ty::Centred { center, size, .. } => {
                    for (i, x) in center.iter_mut().enumerate() {
                        f(Slot::At(i as u8), x);
                    }
                    for (k, x) in size.iter_mut().enumerate() {
                        f(Slot::Size(k as u8), x);
                    }
                }
                $ty::Spanned { corner, edges } => {
                    for (i, x) in corner.iter_mut().enumerate() {
                        f(Slot::At(i as u8), x);
                    }
                    for (e, v) in edges.iter_mut().enumerate() {
                        for (i, x) in v.iter_mut().enumerate() {
                            f(Slot::Edge(e as u8, i as u8), x);
                        }
                    }
                }
            }
        }

        fn reset_from(&mut self, src: &Self) {
            match (self, src) {
                (
                    $ty::Centred {
                        center,
                        size,
                        orientation,
                    },
                    $ty::Centred {
                        center: c,
                        size: s,
                        orientation: o,
                    },
                ) => {
                    *center = *c;
                    *size = *s;
                    $crate::shapes::common::reset_turn(orientation, o);
                }
                (
                    $ty::Spanned { corner, edges },
                    $ty::Spanned {
                        corner: c,
                        edges: e,
                    },
                ) => {
                    *corner = *c;
                    *edges = *e;
                }
                (d, s) => *d = s.clone(),
            }
        }

        /// Centred, its turn completed as its mirror image; spanned, its
        /// points alone place it, already reflected.
        fn mirror(&mut self) {
            match self {
                $ty::Centred { orientation, .. } => $crate::shapes::common::flip(
                    $crate::shapes::common::mirror_axis::<Self>(),
                    orientation,
                ),
                $ty::Spanned { .. } => {}
            }
        }

        /// Centred, its `rotation`'s; spanned, its edges' directions
        /// (the third of a plate, their cross product's).
        fn turn(&self) -> Option<$crate::numeric::M3<f64>> {
            match self {
                $ty::Centred { orientation, .. } => Some(orientation.matrix()),
                $ty::Spanned { edges, .. } => {
                    let unit = |e: [f64; 3]| {
                        let n = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt();
                        e.map(|x| x / n)
                    };
                    let a = unit(edges[0]);
                    let b = unit(edges[1]);
                    let c = match edges.get(2) {
                        Some(e) => unit(*e),
                        None => unit([
                            a[1] * b[2] - a[2] * b[1],
                            a[2] * b[0] - a[0] * b[2],
                            a[0] * b[1] - a[1] * b[0],
                        ]),
                    };
                    Some(std::array::from_fn(|i| [a[i], b[i], c[i]]))
                }
            }
        }

        fn outline(&self) -> Outline {
            match self {
                $ty::Centred {
                    center,
                    size,
                    orientation,
                } => Outline::Pieces(vec![$crate::shapes::common::centred_hull(
                    *center,
                    &$crate::shapes::common::pad(size),
                    &$crate::shapes::common::axes(&orientation.matrix()),
                )]),
                $ty::Spanned { corner, edges } => Outline::Pieces(vec![Piece::Hull(
                    $crate::shapes::common::corners(*corner, &edges[..]),
                )]),
            }
        }
    };
}
