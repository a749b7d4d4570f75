//! MJCF bodies weighed from their geoms, as MuJoCo's compiler does
//! (`<compiler inertiafromgeom>`, MuJoCo's XML reference): under "auto"
//! (the default) each body without an `<inertial>`, under "true" every
//! body, takes the sum of its geoms that count for inertia (`read`'s
//! `mjcf_geometry_in`: their group within `inertiagrouprange`), each of its
//! own `mass`, else its `density`, else MuJoCo's 1000 kg/m³; a body without
//! such geoms keeps what it has. URDF and SDFormat links are unchanged.
//!
//! This is the one place a robot's geoms are weighed for the whole robot:
//! `Robot::read` calls it, so `report arm.xml` and a part file's
//! `include = "arm.xml"` compose the same body.
//!
//! NOTE: each geom's volume and second moments are the closed forms of
//! massprop's own shapes (`shapes::Shape::measure_of`, `second_moments`),
//! evaluated and summed in double-double about the body's centre of mass,
//! and rounded once to f64: the inertial a file would carry.

use super::read::{Amount, Geometry, MeshMass, MeshWarning, Solid};
use super::{Description, Dialect, Inertial, Tensor, Written};
use crate::diag::{Diagnostic, Source};
use crate::numeric::{DD, Real};
use crate::shapes::Shape;

/// MuJoCo's default geom density, kg/m³ (`<geom density>`).
const MUJOCO_DENSITY: f64 = 1000.0;

/// Fill the inertials MuJoCo's compiler gives an MJCF description's bodies
/// from their geoms (see the module's comment); the warnings of the mesh
/// files weighed.
/// An MJCF file's includes are resolved by `r`.
pub fn mjcf_inertials(
    source: &Source,
    d: &mut Description,
    r: &super::read::Resolve,
) -> Result<Vec<MeshWarning>, Diagnostic> {
    if d.format != Dialect::Mjcf || d.compiler.inertiafromgeom == Some(false) {
        return Ok(Vec::new());
    }
    let all = d.compiler.inertiafromgeom == Some(true);
    if !all && d.links.iter().all(|l| l.inertial.is_some()) {
        return Ok(Vec::new());
    }
    let need: Vec<bool> = d
        .links
        .iter()
        .map(|l| all || l.inertial.is_none())
        .collect();
    let (geos, warnings) = super::read::mjcf_geometry_in(source, d, &need, r, false)?;
    for (l, g) in d.links.iter_mut().zip(&geos) {
        if g.is_empty() {
            continue;
        }
        let (mass, pos, tensor) = weigh(g);
        l.inertial = Some(Inertial {
            mass,
            pos,
            rotation: None,
            tensor,
            written: Written::Full,
            range: l.range.clone(),
        });
    }
    Ok(warnings)
}

/// One geom's mass, centre and second moments about its centre, in the
/// body frame: a shape's closed forms, or a mesh's integrals (`MeshMass`:
/// MuJoCo's weighing of it, read with the geom).
fn part(geo: &Geometry) -> (DD, [DD; 3], [[DD; 3]; 3]) {
    let d = |x: &[f64]| x.iter().map(|&v| DD::of(v)).collect::<Vec<_>>();
    let (shape, dims) = match &geo.solid {
        Solid::Box(size) => (Shape::Box, d(size)),
        Solid::Sphere(r) => (Shape::Sphere, d(&[*r, 0.0])),
        Solid::Cylinder { radius, length } => (Shape::Cylinder, d(&[*radius, 0.0, *length])),
        Solid::Capsule { radius, length } => (Shape::Capsule, d(&[*radius, 0.0, *length])),
        Solid::Ellipsoid(r) => (Shape::Ellipsoid, d(r)),
        Solid::Mesh { .. } => {
            let mesh = geo
                .mesh
                .as_ref()
                .expect("invariant: an MJCF mesh geom is weighed when it is read");
            return mesh_part(geo, mesh);
        }
    };
    let m = match geo.amount {
        Some(Amount::Mass(m)) => DD::of(m),
        Some(Amount::Density(rho)) => DD::of(rho) * shape.measure_of(&dims),
        None => DD::of(MUJOCO_DENSITY) * shape.measure_of(&dims),
    };
    let s = shape.second_moments(m, &dims);
    let r = geo.pose.r;
    let own = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3).fold(DD::of(0.0), |acc, k| {
                acc + DD::of(r[i][k]) * DD::of(r[j][k]) * s[k]
            })
        })
    });
    (m, geo.pose.p.map(DD::of), own)
}

/// A mesh geom: its mass (its `mass`, else its density times the mesh's
/// volume or area), its centroid placed by the geom's pose, and R S Rᵀ of
/// its second moments scaled to that mass.
fn mesh_part(geo: &Geometry, mesh: &MeshMass) -> (DD, [DD; 3], [[DD; 3]; 3]) {
    let m = match geo.amount {
        Some(Amount::Mass(m)) => DD::of(m),
        Some(Amount::Density(rho)) => DD::of(rho) * mesh.measure,
        None => DD::of(MUJOCO_DENSITY) * mesh.measure,
    };
    let per = m / mesh.measure;
    let r = geo.pose.r.map(|row| row.map(DD::of));
    let center = std::array::from_fn(|i| {
        (0..3).fold(DD::of(geo.pose.p[i]), |a, k| a + r[i][k] * mesh.centroid[k])
    });
    // R S Rᵀ, then times the density.
    let rs: [[DD; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..3).fold(DD::of(0.0), |a, k| a + r[i][k] * mesh.second[k][j]))
    });
    let own = std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..3).fold(DD::of(0.0), |a, k| a + rs[i][k] * r[j][k]) * per)
    });
    (m, center, own)
}

/// Mass (kg), centre (m) and inertia tensor about the centre (kg·m², the
/// tensor convention) of the geoms `g`, in the body frame.
pub fn weigh(g: &[Geometry]) -> (f64, [f64; 3], Tensor) {
    let parts: Vec<(DD, [DD; 3], [[DD; 3]; 3])> = g.iter().map(part).collect();
    let mass = parts.iter().fold(DD::of(0.0), |a, p| a + p.0);
    let center: [DD; 3] =
        std::array::from_fn(|i| parts.iter().fold(DD::of(0.0), |a, p| a + p.0 * p.1[i]) / mass);
    // Second moments about the centre: each geom's own, and its mass at
    // its offset (the parallel-axis terms m d dᵀ).
    let mut s = [[DD::of(0.0); 3]; 3];
    for (m, c, own) in &parts {
        let dv: [DD; 3] = std::array::from_fn(|i| c[i] - center[i]);
        for i in 0..3 {
            for j in 0..3 {
                s[i][j] = s[i][j] + own[i][j] + *m * dv[i] * dv[j];
            }
        }
    }
    // NOTE: the inertia from the second moments S: I = tr(S)·E − S, so
    // I_xx = S_yy + S_zz and I_xy = −S_xy (the tensor convention).
    let tensor = Tensor {
        xx: (s[1][1] + s[2][2]).f64(),
        yy: (s[0][0] + s[2][2]).f64(),
        zz: (s[0][0] + s[1][1]).f64(),
        xy: (-s[0][1]).f64(),
        xz: (-s[0][2]).f64(),
        yz: (-s[1][2]).f64(),
    };
    (mass.f64(), center.map(Real::f64), tensor)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::kinematics::Pose;

    fn geom(solid: Solid, p: [f64; 3], amount: Option<Amount>) -> Geometry {
        Geometry {
            solid,
            pose: Pose {
                p,
                r: Pose::IDENTITY.r,
            },
            range: 0..0,
            amount,
            mesh: None,
        }
    }

    #[test]
    fn a_box_of_default_density_weighs_a_thousand_times_its_volume() {
        let (m, c, t) = weigh(&[geom(Solid::Box([1.0, 2.0, 3.0]), [1.0, 0.0, 0.0], None)]);
        assert!((m - 6000.0).abs() < 1e-9);
        assert_eq!(c, [1.0, 0.0, 0.0]);
        // I_xx = m (b² + c²)/12.
        assert!((t.xx - 6000.0 * 13.0 / 12.0).abs() < 1e-9);
    }

    #[test]
    fn two_point_like_spheres_apart_add_their_parallel_axis_terms() {
        let tiny = 1e-6;
        let g = [
            geom(
                Solid::Sphere(tiny),
                [0.0, 0.0, -1.0],
                Some(Amount::Mass(2.0)),
            ),
            geom(
                Solid::Sphere(tiny),
                [0.0, 0.0, 1.0],
                Some(Amount::Mass(2.0)),
            ),
        ];
        let (m, c, t) = weigh(&g);
        assert_eq!(m, 4.0);
        assert_eq!(c, [0.0; 3]);
        // Two 2 kg masses at ±1 m along z: I_xx = I_yy = 4, I_zz ≈ 0.
        assert!((t.xx - 4.0).abs() < 1e-9 && (t.yy - 4.0).abs() < 1e-9);
        assert!(t.zz.abs() < 1e-9);
    }

    #[test]
    fn an_offset_in_x_and_y_gives_the_product_its_sign() {
        let tiny = 1e-6;
        let g = [
            geom(
                Solid::Sphere(tiny),
                [1.0, 1.0, 0.0],
                Some(Amount::Mass(1.0)),
            ),
            geom(
                Solid::Sphere(tiny),
                [-1.0, -1.0, 0.0],
                Some(Amount::Mass(1.0)),
            ),
        ];
        let (_, _, t) = weigh(&g);
        // I_xy = −Σ m x y = −2.
        assert!((t.xy + 2.0).abs() < 1e-9, "{t:?}");
    }
}
