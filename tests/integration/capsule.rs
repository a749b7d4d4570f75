//! Issue 29's capsule through the whole program. Its closed forms are
//! checked against quadrature of its own definition in
//! src/shapes/capsule.rs and against the exact reference
//! (`support::solids::capsule`, the every-shape scene of `stress`, the
//! property tests of `invariants`); here, built from other shapes: a
//! capsule is a cylinder and two hemispheres, a hollow one the solid less
//! its core, `diameter` twice `radius`; copies and mirrors of it; its
//! derivatives by its sizes against finite differences; and export.

use crate::common::{massprop_stdin, report_json, same_body};

const TURN: &str = "rotation = { axis = [1, 2, 3], degrees = 37 }";

/// A capsule of radius R and length L about `center`, turned: a cylinder
/// of that length and a hemisphere on each end, domes outward (the lower
/// one turned half a turn about local x), all by the same density, in a
/// sub-assembly turned as the capsule is.
fn as_pieces(r: f64, inner: f64, l: f64) -> String {
    let half = l / 2.0;
    format!(
        "[[part]]\nshape = \"cylinder\"\ndensity = 7850\nradius = {r}\ninner_radius = {inner}\nlength = {l}\ncenter = [0, 0, 0]\n\
         [[part]]\nshape = \"hemisphere\"\ndensity = 7850\nradius = {r}\ninner_radius = {inner}\ncenter = [0, 0, {half}]\n\
         [[part]]\nshape = \"hemisphere\"\ndensity = 7850\nradius = {r}\ninner_radius = {inner}\ncenter = [0, 0, -{half}]\nrotation = {{ axis = [1, 0, 0], degrees = 180 }}\n"
    )
}

#[test]
fn a_capsule_is_a_cylinder_and_two_hemispheres() {
    for (r, inner, l) in [(0.5, 0.0, 2.0), (0.3, 0.25, 0.4), (1.0, 0.0, 0.05)] {
        let capsule = format!(
            "[[part]]\nshape = \"capsule\"\ndensity = 7850\nradius = {r}\ninner_radius = {inner}\nlength = {l}\ncenter = [0, 0, 0]\n"
        );
        same_body(&capsule, &as_pieces(r, inner, l), 1e-13);
    }
}

#[test]
fn a_hollow_capsule_is_the_solid_less_its_core_moved_and_turned() {
    let at = format!("density = 2700\ncenter = [3, -1, 2]\n{TURN}\n");
    let hollow = format!(
        "[[part]]\nshape = \"capsule\"\nradius = 0.5\ninner_radius = 0.45\nlength = 1.5\n{at}"
    );
    let cut = format!(
        "[[part]]\nshape = \"capsule\"\nradius = 0.5\nlength = 1.5\n{at}\n[[part]]\nshape = \"capsule\"\nradius = 0.45\nlength = 1.5\n{at}remove = true\n"
    );
    same_body(&hollow, &cut, 1e-12);
}

#[test]
fn a_diameter_is_twice_the_radius() {
    let by_radius = format!(
        "[[part]]\nshape = \"capsule\"\ndensity = 1000\nradius = 0.5\ninner_radius = 0.2\nlength = 2\ncenter = [1, 2, 3]\n{TURN}\n"
    );
    let by_diameter = by_radius
        .replace("radius = 0.5", "diameter = 1")
        .replace("inner_radius = 0.2", "inner_diameter = \"400 mm\"");
    assert_ne!(by_radius, by_diameter);
    same_body(&by_radius, &by_diameter, 1e-15);
}

#[test]
fn a_mirrored_and_arrayed_capsule_is_each_copy_written_out() {
    // Two copies 3 m apart along x and their mirror images in y = 0, of a
    // capsule off the plane and turned: four capsules written out, each
    // image turned by the reflection of the turn (its axis reflected).
    let part = "shape = \"capsule\"\nmass = 2\nradius = 0.25\nlength = 1\ncenter = [1, 2, 0.5]\nrotation = { axis = [1, 0, 0], degrees = 30 }\n";
    let copied = format!(
        "[[part]]\n{part}array = {{ count = 2, step = [3, 0, 0] }}\nmirror = {{ normal = [0, 1, 0] }}\n"
    );
    let written = [(0.0, 2.0, 30.0), (3.0, 2.0, 30.0), (0.0, -2.0, -30.0), (3.0, -2.0, -30.0)]
        .iter()
        .map(|(dx, y, deg)| {
            format!(
                "[[part]]\nshape = \"capsule\"\nmass = 2\nradius = 0.25\nlength = 1\ncenter = [{}, {y}, 0.5]\nrotation = {{ axis = [1, 0, 0], degrees = {deg} }}\n",
                1.0 + dx
            )
        })
        .collect::<String>();
    same_body(&copied, &written, 1e-14);
}

#[test]
fn the_linear_sigma_of_the_mass_by_the_radius_is_the_derivative_times_the_tolerance() {
    // m(R) = ρπ(R²L + 4R³/3): dm/dR = ρπ(2RL + 4R²), so σ_m = dm/dR σ_R.
    let (rho, r, l, sigma) = (7850.0, 0.2, 1.0, 0.001);
    let text = format!(
        "[[part]]\nshape = \"capsule\"\ndensity = {rho}\nradius = \"{r} m ± {sigma} m\"\nlength = {l}\ncenter = [0, 0, 0]\n"
    );
    let (v, _) = report_json(&text, &["--uncertainty", "linear"]);
    let got = v["uncertainty"]["outputs"]
        .as_array()
        .expect("outputs")
        .iter()
        .find(|o| o["quantity"] == "mass")
        .and_then(|o| o["sigma"].as_f64())
        .expect("σ of the mass");
    let want = rho * std::f64::consts::PI * (2.0 * r * l + 4.0 * r * r) * sigma;
    assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}\n{v:#}");
}

#[test]
fn export_writes_the_capsules_inertia() {
    // A solid capsule about its centre: I_zz = m (R²/2 · L + 8R³/15)/(L + 4R/3)
    // (the cylinder's m R²/2 and each hemisphere's ⅖ m R², by mass).
    let (r, l, m): (f64, f64, f64) = (0.5, 2.0, 3.0);
    let text = format!(
        "[[part]]\nshape = \"capsule\"\nmass = {m}\nradius = {r}\nlength = {l}\ncenter = [0, 0, 0]\n"
    );
    let out = massprop_stdin(&["export", "-", "--to", "urdf"], &text);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let xml = String::from_utf8(out.stdout).unwrap();
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let inertia = doc
        .descendants()
        .find(|n| n.has_tag_name("inertia"))
        .expect("<inertia>");
    let izz: f64 = inertia.attribute("izz").unwrap().parse().unwrap();
    let want = m * (r * r / 2.0 * l + 8.0 * r.powi(3) / 15.0) / (l + 4.0 * r / 3.0);
    assert!((izz - want).abs() <= 1e-14 * want, "{izz} vs {want}\n{xml}");
}
