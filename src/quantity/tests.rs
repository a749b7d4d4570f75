//! The table's own invariants: positions, places, keys.

use super::*;

#[test]
fn each_row_stands_at_its_variants_position() {
    for (k, info) in QUANTITIES.iter().enumerate() {
        assert_eq!(info.quantity as usize, k, "{}", info.key);
    }
}

#[test]
fn the_sigma_outputs_of_one_body_are_numbered_without_overlap() {
    let mut taken = [false; 2 * OUTPUTS + MOTION_OUTPUTS];
    for info in &QUANTITIES {
        let Some(first) = info.sigma else { continue };
        let n = match info.layout {
            Layout::Matrix => UPPER.len(),
            Layout::Scalar | Layout::Vector | Layout::Ordered | Layout::Axes => info.layout.count(),
        };
        for (o, t) in taken.iter_mut().enumerate().skip(first).take(n) {
            assert!(!*t, "{} overlaps output {o}", info.key);
            *t = true;
        }
    }
    // Every output of the basic body is some quantity's (the predicted
    // body's principal moments have no `[expect]` key).
    assert!(taken[..OUTPUTS].iter().all(|t| *t), "{taken:?}");
    // And every output of the body moving.
    assert!(taken[2 * OUTPUTS..].iter().all(|t| *t), "{taken:?}");
}

/// The places of `place` are 0, 1, 2, … each once.
fn dense(place: fn(&Info) -> Option<u8>, what: &str) {
    let mut places: Vec<u8> = QUANTITIES.iter().filter_map(place).collect();
    places.sort_unstable();
    let n = u8::try_from(places.len()).unwrap();
    assert_eq!(places, (0..n).collect::<Vec<_>>(), "{what}");
}

#[test]
fn the_places_in_the_report_in_error_bounds_and_among_the_warnings_are_each_taken_once() {
    dense(|i| i.report, "report");
    dense(|i| i.bound, "error_bounds");
    dense(|i| i.judge.place(), "warnings");
}

#[test]
fn a_set_of_axes_in_the_report_names_its_equal_moments_and_nothing_else_does() {
    for info in &QUANTITIES {
        let axes = info.layout == Layout::Axes && info.report.is_some();
        assert_eq!(info.equal.is_some(), axes, "{}", info.key);
    }
}

#[test]
fn only_a_bounded_quantity_is_judged_and_an_angle_only_for_axes() {
    for info in &QUANTITIES {
        if info.judge.place().is_some() {
            assert!(info.bound.is_some(), "{}", info.key);
        }
        let angle = matches!(info.judge, Judge::Angle(_));
        if angle {
            assert_eq!(info.layout, Layout::Axes, "{}", info.key);
        }
    }
}

#[test]
fn every_key_is_distinct() {
    let mut keys: Vec<&str> = QUANTITIES.iter().map(|i| i.key).collect();
    keys.extend(ALIASES.iter().map(|a| a.0));
    let n = keys.len();
    keys.sort_unstable();
    keys.dedup();
    assert_eq!(keys.len(), n);
}

#[test]
fn a_quantity_compared_by_angle_is_a_set_of_axes() {
    for info in QUANTITIES.iter().filter(|i| i.expected) {
        assert_eq!(
            info.compare == Compare::Angle,
            info.layout == Layout::Axes,
            "{}",
            info.key
        );
    }
}
