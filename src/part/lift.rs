//! A part's numbers by the slot a tolerance moves (`Spec::number_mut`),
//! and each shape's derivatives by its numbers (tests).

use super::{MassSpec, Spec};
use crate::shapes::Slot;

impl Spec {
    /// The number in `slot`, if the part has it (the one map from a
    /// `Slot` to a `Spec`'s number: the mass or density here, the rest
    /// its placement's, `Place::number_mut`).
    pub fn number_mut(&mut self, slot: Slot) -> Option<&mut f64> {
        match slot {
            Slot::Mass => Some(match &mut self.mass {
                MassSpec::Given(m) => m,
                MassSpec::Density(d) => d,
            }),
            Slot::At(_)
            | Slot::Size(_)
            | Slot::Length
            | Slot::Radius
            | Slot::InnerRadius
            | Slot::TopRadius
            | Slot::TopInnerRadius
            | Slot::TubeRadius
            | Slot::InnerTubeRadius
            | Slot::Edge(..)
            | Slot::To(_)
            | Slot::Vertex(..)
            | Slot::Own(..) => self.place.number_mut(slot),
        }
    }
}

/// Each shape's derivatives by its numbers, from dual numbers through the
/// composer's own functions (`physics_in`), against the derivatives of its
/// closed forms worked by hand.
#[cfg(test)]
mod tests {
    use crate::dual::Dual;
    use crate::numeric::M3;
    use crate::part::{MassSpec, Place, Spec, physics_in};
    use crate::rotation::Orientation;
    use crate::shapes::{Seed, Slot};
    use crate::shapes::{
        r#box::Cuboid, cone::Cone, cylinder::Cylinder, disk::Disk, hemisphere::Hemisphere,
        plate::Plate, point::Point, prism::Prism, rod::Rod, sphere::Sphere, torus::Torus,
        triangle::Triangle,
    };
    use std::f64::consts::PI;

    /// (∂m, ∂centroid, ∂C) by the number in `slot`.
    fn d(spec: &Spec, slot: Slot) -> (f64, [f64; 3], M3<f64>) {
        let (m, c, j) = physics_in::<Dual<f64>, Seed>(spec, Seed(slot));
        (m.d, c.map(|x| x.d), j.map(|r| r.map(|x| x.d)))
    }

    const AT: [f64; 3] = [1.0, 2.0, 3.0];
    const NONE: Orientation = Orientation::Identity;

    fn by_density(rho: f64, place: Place) -> Spec {
        spec(MassSpec::Density(rho), place)
    }

    fn spec(mass: MassSpec, place: Place) -> Spec {
        Spec {
            mass,
            place,
            removed: false,
            placed: Default::default(),
        }
    }

    fn close(a: f64, b: f64) {
        assert!(
            (a - b).abs() <= 1e-13 * a.abs().max(b.abs()).max(1e-300),
            "{a} against {b}"
        );
    }

    #[test]
    fn a_box_by_its_sides_and_its_density() {
        // m = ρabc, C = m/12 diag(a², b², c²): ∂m/∂a = ρbc,
        // ∂C_xx/∂a = ρbc a²/4, ∂C_yy/∂a = ρbc b²/12.
        let (rho, a, b, c) = (7.0, 0.3, 0.2, 0.1);
        let s = by_density(
            rho,
            Place::Box(Cuboid::Centred {
                center: AT,
                size: [a, b, c],
                orientation: NONE,
            }),
        );
        let (dm, dc, dj) = d(&s, Slot::Size(0));
        close(dm, rho * b * c);
        close(dj[0][0], rho * b * c * a * a / 4.0);
        close(dj[1][1], rho * b * c * b * b / 12.0);
        assert_eq!(dc, [0.0; 3]);
        // By the density: m/ρ, C/ρ.
        let (dm, _, dj) = d(&s, Slot::Mass);
        close(dm, a * b * c);
        close(dj[2][2], a * b * c * c * c / 12.0);
        // By the centre: the centroid moves with it, nothing else.
        let (dm, dc, dj) = d(&s, Slot::At(1));
        assert_eq!((dm, dc, dj), (0.0, [0.0, 1.0, 0.0], [[0.0; 3]; 3]));
    }

    #[test]
    fn a_plate_and_a_rod_by_their_sizes() {
        let (sigma, a, b) = (3.0, 0.5, 0.25);
        let plate = Place::Plate(Plate::Centred {
            center: AT,
            size: [a, b],
            orientation: NONE,
        });
        let (dm, _, dj) = d(&by_density(sigma, plate), Slot::Size(1));
        close(dm, sigma * a);
        close(dj[1][1], sigma * a * b * b / 4.0);
        close(dj[0][0], sigma * a * a * a / 12.0);
        // A rod along local z: m = λL, ∫z² dm = λL³/12.
        let (lambda, l) = (0.2, 1.5);
        let rod = Place::Rod(Rod::Centred {
            center: AT,
            length: l,
            orientation: NONE,
        });
        let (dm, _, dj) = d(&by_density(lambda, rod), Slot::Length);
        close(dm, lambda);
        close(dj[2][2], lambda * l * l / 4.0);
    }

    #[test]
    fn a_tube_by_its_radii_and_length() {
        // m = ρπ(R² − r²)L, ∫x² dm = m(R² + r²)/4, ∫z² dm = mL²/12.
        let (rho, r_out, r_in, l) = (2.0, 0.05, 0.03, 0.4);
        let s = by_density(
            rho,
            Place::Cylinder(Cylinder {
                center: AT,
                radius: r_out,
                inner_radius: r_in,
                length: l,
                orientation: NONE,
            }),
        );
        let m = rho * PI * (r_out * r_out - r_in * r_in) * l;
        let (dm, _, dj) = d(&s, Slot::Radius);
        let dm_dr = 2.0 * PI * rho * r_out * l;
        close(dm, dm_dr);
        close(
            dj[0][0],
            dm_dr * (r_out * r_out + r_in * r_in) / 4.0 + m * r_out / 2.0,
        );
        let (dm, _, dj) = d(&s, Slot::InnerRadius);
        let dm_di = -2.0 * PI * rho * r_in * l;
        close(dm, dm_di);
        close(
            dj[1][1],
            dm_di * (r_out * r_out + r_in * r_in) / 4.0 + m * r_in / 2.0,
        );
        let (dm, _, dj) = d(&s, Slot::Length);
        close(dm, m / l);
        close(dj[2][2], m * l / 4.0);
    }

    #[test]
    fn a_disk_and_a_sphere_by_their_radii() {
        let (sigma, r) = (5.0, 0.2);
        let disk = Place::Disk(Disk {
            center: AT,
            radius: r,
            inner_radius: 0.0,
            orientation: NONE,
        });
        let (dm, _, dj) = d(&by_density(sigma, disk), Slot::Radius);
        let m = sigma * PI * r * r;
        close(dm, 2.0 * PI * sigma * r);
        close(dj[0][0], 2.0 * PI * sigma * r * r * r / 4.0 + m * r / 2.0);
        // A solid sphere: m = 4πρR³/3, ∫x² dm = mR²/5: ∂ = 4πρR⁴/5 + 2mR/5.
        let (rho, r) = (1000.0, 0.1);
        let sphere = Place::Sphere(Sphere {
            center: AT,
            radius: r,
            inner_radius: 0.0,
            orientation: NONE,
        });
        let (dm, _, dj) = d(&by_density(rho, sphere), Slot::Radius);
        let m = 4.0 / 3.0 * PI * rho * r.powi(3);
        close(dm, 4.0 * PI * rho * r * r);
        close(
            dj[2][2],
            4.0 * PI * rho * r.powi(4) / 5.0 + 2.0 * m * r / 5.0,
        );
    }

    #[test]
    fn a_cone_a_hemisphere_and_a_torus_by_their_sizes() {
        let cone = |rho: f64, d: [f64; 5]| {
            by_density(
                rho,
                Place::Cone(Cone {
                    center: [0.0; 3],
                    radius: d[0],
                    inner_radius: d[1],
                    top_radius: d[2],
                    top_inner_radius: d[3],
                    length: d[4],
                    orientation: NONE,
                }),
            )
        };
        // A frustum: m = ρπL(R₀² + R₀R₁ + R₁²)/3.
        let (rho, r0, r1, l) = (3.0, 0.2, 0.1, 0.5);
        let s = cone(rho, [r0, 0.0, r1, 0.0, l]);
        let m = rho * PI * l * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
        close(d(&s, Slot::Radius).0, rho * PI * l * (2.0 * r0 + r1) / 3.0);
        close(d(&s, Slot::Length).0, m / l);
        // A full cone's centroid lies L/4 from its base, a quarter of L
        // from the middle of its axis: it moves a quarter as fast as L.
        let full = cone(rho, [r0, 0.0, 0.0, 0.0, l]);
        close(d(&full, Slot::Length).1[2].abs(), 0.25);
        // A hemisphere: m = 2πρR³/3; its centroid 3R/8 from the centre.
        let h = by_density(
            rho,
            Place::Hemisphere(Hemisphere {
                center: [0.0; 3],
                radius: r0,
                inner_radius: 0.0,
                orientation: NONE,
            }),
        );
        let (dm, dc, _) = d(&h, Slot::Radius);
        close(dm, 2.0 * PI * rho * r0 * r0);
        close(dc[2].abs(), 0.375);
        // A torus: m = 2π²ρRa², ∫z² dm = ma²/4: ∂m/∂a = 2m/a, ∂/∂a = ma.
        let (big, a) = (0.3, 0.05);
        let t = by_density(
            rho,
            Place::Torus(Torus {
                center: AT,
                radius: big,
                tube_radius: a,
                inner_tube_radius: 0.0,
                orientation: NONE,
            }),
        );
        let m = 2.0 * PI * PI * rho * big * a * a;
        close(d(&t, Slot::Radius).0, m / big);
        let (dm, _, dj) = d(&t, Slot::TubeRadius);
        close(dm, 2.0 * m / a);
        close(dj[2][2], m * a);
    }

    #[test]
    fn a_prism_by_its_length() {
        // A 0.2 × 0.1 rectangle: A = 0.02, m = ρAL, ∫z² dm = mL²/12.
        let (rho, l) = (4.0, 0.3);
        let s = spec(
            MassSpec::Density(rho),
            Place::Prism(Prism {
                origin: [0.0; 3],
                polygon: vec![[0.0, 0.0], [0.2, 0.0], [0.2, 0.1], [0.0, 0.1]].into(),
                length: l,
                orientation: NONE,
            }),
        );
        let (dm, _, dj) = d(&s, Slot::Length);
        close(dm, rho * 0.02);
        close(dj[2][2], rho * 0.02 * l * l / 4.0);
    }

    #[test]
    fn spanned_shapes_by_their_points_and_vectors() {
        // A box by a corner and edges a x̂, b ŷ, c ẑ: ∂m/∂(edge 0's x) =
        // ρbc, the centroid half as fast as an edge and as fast as the corner.
        let (rho, a, b, c) = (2.0, 0.4, 0.3, 0.2);
        let s = spec(
            MassSpec::Density(rho),
            Place::Box(Cuboid::Spanned {
                corner: [1.0, 1.0, 1.0],
                edges: [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]],
            }),
        );
        let (dm, dc, dj) = d(&s, Slot::Edge(0, 0));
        close(dm, rho * b * c);
        close(dc[0], 0.5);
        close(dj[0][0], rho * b * c * a * a / 4.0);
        assert_eq!(d(&s, Slot::At(2)).1, [0.0, 0.0, 1.0]);
        // A rod from → to: m = λ|to − from|, ∂m/∂to = λ (to − from)/L.
        let s = spec(
            MassSpec::Density(0.5),
            Place::Rod(Rod::Ends {
                from: [0.0; 3],
                to: [3.0, 4.0, 0.0],
            }),
        );
        let (dm, dc, _) = d(&s, Slot::To(1));
        close(dm, 0.5 * 4.0 / 5.0);
        close(dc[1], 0.5);
        // A triangle (0,0,0), (a,0,0), (0,b,0): area ab/2, ∂/∂(v₁ x) = b/2;
        // its centroid a third as fast as a vertex.
        let s = spec(
            MassSpec::Density(6.0),
            Place::Triangle(Triangle {
                vertices: [[0.0; 3], [a, 0.0, 0.0], [0.0, b, 0.0]],
            }),
        );
        let (dm, dc, _) = d(&s, Slot::Vertex(1, 0));
        close(dm, 6.0 * b / 2.0);
        close(dc[0], 1.0 / 3.0);
        // A point by its mass.
        let s = spec(
            MassSpec::Given(2.0),
            Place::Point(Point {
                center: [0.0; 3],
                orientation: NONE,
            }),
        );
        assert_eq!(d(&s, Slot::Mass).0, 1.0);
    }

    #[test]
    fn a_turned_part_turns_its_derivatives() {
        // A quarter turn about z swaps x and y: ∂C_yy/∂a of the turned box
        // is ∂C_xx/∂a of the box, and ∂C_xx/∂a its ∂C_yy/∂a.
        let (rho, a, b, c) = (7.0, 0.3, 0.2, 0.1);
        let s = spec(
            MassSpec::Density(rho),
            Place::Box(Cuboid::Centred {
                center: [0.0; 3],
                size: [a, b, c],
                orientation: Orientation::AxisAngle([0.0, 0.0, 1.0], 90.0),
            }),
        );
        let (_, _, dj) = d(&s, Slot::Size(0));
        close(dj[1][1], rho * b * c * a * a / 4.0);
        close(dj[0][0], rho * b * c * b * b / 12.0);
        assert!(dj[0][1].abs() <= 1e-15 * dj[1][1]);
    }
}
