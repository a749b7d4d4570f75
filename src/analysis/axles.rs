//! Axle loads (`[analysis] axles = { axis, front, rear }`): the static load
//! on each of two axles of a body standing on them, and its share of the
//! weight, from the centre of mass's coordinate along the axis. Two
//! supports and the weight are a statically determinate beam: moments
//! about the rear axle give F_front (x_f − x_r) = W (x_c − x_r), and the
//! loads sum to W = m g. A centre of mass beyond an axle gives a negative
//! load on the other: the body tips, which the numbers show.

use serde::Serialize;

/// Standard gravity, m/s² (`[analysis] g` replaces it).
pub const G: f64 = 9.80665;

/// One axle: its position along the axis (m, from the file's origin), its
/// load (N) and its share of the weight (a fraction).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Axle {
    pub position: f64,
    pub load: f64,
    pub share: f64,
}

/// Both axles' loads, and the g they are formed with (m/s²; not in the
/// JSON, which gives loads in N; the table shows kg by it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AxleLoads {
    pub front: Axle,
    pub rear: Axle,
    #[serde(skip)]
    pub g: f64,
}

/// The loads of a body of `mass` (kg) whose centre of mass is at `along`
/// (m) along the axis, on axles at `front` and `rear` (m, distinct), under
/// gravity `g` (m/s²); `None` where a number overflows f64.
pub fn loads(mass: f64, along: f64, front: f64, rear: f64, g: f64) -> Option<AxleLoads> {
    let weight = mass * g;
    let base = front - rear;
    let share_front = (along - rear) / base;
    let share_rear = (front - along) / base;
    let axle = |position: f64, share: f64| Axle {
        position,
        load: share * weight,
        share,
    };
    let out = AxleLoads {
        front: axle(front, share_front),
        rear: axle(rear, share_rear),
        g,
    };
    let all = [
        out.front.load,
        out.front.share,
        out.rear.load,
        out.rear.share,
        front,
        rear,
    ];
    all.iter().all(|x| x.is_finite()).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_centre_of_mass_midway_puts_half_the_weight_on_each_axle() {
        let l = loads(1000.0, 0.5, 1.5, -0.5, 10.0).unwrap();
        assert_eq!((l.front.share, l.rear.share), (0.5, 0.5));
        assert_eq!((l.front.load, l.rear.load), (5000.0, 5000.0));
    }

    #[test]
    fn moments_about_either_axle_balance() {
        let (m, c, f, r, g) = (1234.5, 0.31, 1.35, -1.25, G);
        let l = loads(m, c, f, r, g).unwrap();
        // About the rear axle: F_f (f − r) = W (c − r); and about the front.
        let w = m * g;
        assert!((l.front.load * (f - r) - w * (c - r)).abs() < 1e-9 * w);
        assert!((l.rear.load * (f - r) - w * (f - c)).abs() < 1e-9 * w);
        assert!((l.front.load + l.rear.load - w).abs() < 1e-9 * w);
    }

    #[test]
    fn a_centre_of_mass_beyond_the_front_axle_lifts_the_rear() {
        let l = loads(1.0, 2.0, 1.0, 0.0, G).unwrap();
        assert!(l.rear.load < 0.0 && l.front.share > 1.0);
    }
}
