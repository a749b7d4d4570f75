//! What the shapes placed by their `center` and turned by their
//! `orientation` share, written once: the methods of `ShapeKind` that
//! follow from their named dimensions (`placed_by_centre!`) and from a
//! centroid that is their centre (`centred_centroid!`), used inside each
//! such shape's `impl ShapeKind`.

/// The methods of `ShapeKind` that every shape placed by its `center` and
/// turned by its `orientation`, its dimensions named (`field: Slot`, in
/// the order its closed forms take them), shares: its measure and own
/// second moment from its closed forms (R diag(d) Rᵀ, `common::diagonal`),
/// the moments checked for range, a frame's move, its numbers by slot,
/// its mirror image and the rest. `centroid` and `centroid_error` are
/// `centred_centroid!`'s for a shape whose centroid is its centre.
macro_rules! placed_by_centre {
    ($($field:ident: $slot:ident),* $(,)?) => {
        fn measure<T: Real, L: Lift>(&self, l: L) -> T {
            let _ = &l;
            Self::measure_of::<T>(&[$($crate::shapes::common::var(self.$field, Slot::$slot, l)),*])
        }

        fn measure_error(&self) -> f64 {
            Self::MEASURE_ROUNDINGS
        }

        fn own_second_moment<T: Real, L: Lift>(
            &self,
            m: T,
            units: Option<Units>,
            l: L,
        ) -> (M3<T>, Option<Own>) {
            let _ = &l;
            let d = Self::moments_of::<T>(
                m,
                &[$($crate::shapes::common::var(self.$field, Slot::$slot, l)),*],
            );
            $crate::shapes::common::diagonal(d, &self.orientation, units, Self::MOMENT_ROUNDINGS)
        }

        fn independent_moments(&self, m: f64, _: &M3<f64>) -> ([f64; 3], usize, usize) {
            (
                Self::moments_of(m, &[$(self.$field),*]),
                3,
                Self::INFO.nonzero_moments,
            )
        }

        fn moved(&mut self, m: &impl Mover) {
            self.center = m.point(self.center);
            $(self.$field *= m.length();)*
            m.turn(&mut self.orientation);
        }

        fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
            let [x, y, z] = &mut self.center;
            f(Slot::At(0), x);
            f(Slot::At(1), y);
            f(Slot::At(2), z);
            $(f(Slot::$slot, &mut self.$field);)*
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

        fn reset_from(&mut self, src: &Self) {
            self.center = src.center;
            $(self.$field = src.$field;)*
            $crate::shapes::common::reset_turn(&mut self.orientation, &src.orientation);
        }

        fn mirror(&mut self) {
            $crate::shapes::common::flip(
                $crate::shapes::common::mirror_axis::<Self>(),
                &mut self.orientation,
            );
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
