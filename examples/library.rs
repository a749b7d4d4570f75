//! massprop as a library: the mass properties of a part file, and of a
//! part file made in the program, with the error of a bad one.
//!
//!     cargo run --example library [FILE]
//!
//! FILE defaults to shapes/robot-arm.toml.

use massprop::{Settings, summarize, summarize_str};
use std::process::ExitCode;

fn main() -> ExitCode {
    let file = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "shapes/robot-arm.toml".into());
    let settings = Settings::default();
    let summary = match summarize(&file, &settings) {
        Ok(s) => s,
        Err(e) => {
            // Rendered as the command renders it, with the source line.
            eprint!("{e}");
            return ExitCode::from(2);
        }
    };
    println!("{file}: {} kg", summary.mass);
    println!("  centre of mass {:?} m", summary.center_of_mass);
    println!("  principal moments {:?} kg·m²", summary.principal_moments);
    println!(
        "  each within {:?} kg·m² ({:?})",
        summary.error_bounds.principal_moments, summary.precision
    );

    // A part file written by the program: a 2 kg rod, 1 m along x.
    let rod = "[[part]]\nshape = \"rod\"\nmass = 2\nfrom = [0, 0, 0]\nto = [1, 0, 0]\n";
    let s = summarize_str("rod.toml", rod, &settings).expect("a valid rod");
    // m L² / 12 about its centre, across it.
    println!(
        "rod: Izz = {} kg·m² (m L²/12 = {})",
        s.inertia_com[2][2],
        2.0 / 12.0
    );

    // A bad one: the error's parts as fields.
    let e = summarize_str("bad.toml", "[[part]]\nshape = \"cuboid\"\n", &settings).unwrap_err();
    if let Some(place) = e.place() {
        println!("bad.toml: {place}: {}", e.message());
    }
    ExitCode::SUCCESS
}
