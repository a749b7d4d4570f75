//! `massprop init [FILE]`: a commented starter part file, on standard
//! output or into a new FILE (never over an existing one).
//!
//! NOTE: the starter carries no live `#:schema` line: the schema is a file
//! the user makes (`massprop schema > massprop.schema.json`), and a
//! directive naming a file that is not there is an error in the editor.
//! The comment says how to add one. That the starter passes `check` and
//! the schema is tested (tests/integration/schema.rs).

use super::Outcome;
use crate::diag::Diagnostic;

/// What to write where.
#[derive(Debug, Clone)]
pub struct Options {
    /// The new file; `None` or `-`: standard output.
    pub file: Option<String>,
}

/// The starter part file.
pub const STARTER: &str = r#"# A massprop part file: one rigid body as a list of primitive shapes.
#
#   massprop report FILE    mass, centre of mass, inertia, principal axes
#   massprop check FILE     the [expect] values below, and validity
#
# The format: `massprop help part-file` (every shape and key), and
# docs/part-file.md in massprop's repository. For completion and checking as you type
# (Taplo, Even Better TOML): run `massprop schema > massprop.schema.json`
# beside this file and make this the first line:
#   #:schema ./massprop.schema.json

name = "camera mast"

# Plain numbers are in these units (length m, cm, mm, um, km, in or ft;
# mass kg, g, mg, t or lb). Any quantity may carry its own unit instead,
# as a string: "350 g", "2.7 g/cm^3", "90 deg", "3000 rpm".
units = { length = "mm", mass = "kg" }

# Each [[part]] is one shape: box, plate, rod, cylinder, disk, sphere,
# triangle, point, inertia (a given tensor), cone, torus, hemisphere,
# prism, mesh, capsule or ellipsoid, or `include = "other.toml"`
# for a sub-assembly. Its mass is exactly one of `mass`, the shape's
# density (`density` per volume, `areal_density` for a plate or disk,
# `linear_density` for a rod) and a `material` (`massprop materials` lists
# them). It is placed by `center`, its centroid in this file's frame, with
# its size and an optional `rotation` of its local axes; a box or plate may
# instead give `corner` and `edges`, a rod `from` and `to`.

[[part]]
name = "base"
shape = "box"
material = "aluminium-6061"
size = [200, 150, 10]                 # full edge lengths along local x, y, z
center = [0, 0, 5]                    # its underside on z = 0

[[part]]
name = "mast"
shape = "cylinder"                    # its axis along local z
material = "aluminium-6061"
radius = 15
inner_radius = 12                     # a tube; leave it out for a solid rod
length = 400
center = [0, 0, 210]

[[part]]
name = "camera"
shape = "box"
mass = "350 g"                        # a bought part: its mass as weighed
size = [60, 80, 50]
center = [0, 0, 435]
rotation = { axis = [0, 0, 1], degrees = 30 }   # turned 30° about z

[[part]]
name = "cable hole"
shape = "cylinder"
material = "aluminium-6061"
radius = 10
length = 10
center = [60, 0, 5]
remove = true                         # a cut-out: subtracted from the base

# A reference point and a motion, for angular momentum and energy
# (optional; ω in rad/s unless it carries a unit):
# [analysis]
# about = [0, 0, 0]
# omega = [0, 0, "60 rpm"]

# What `massprop check` holds the body to: `value` with a `tol` (in file
# units, with a unit of its own, or a percentage), or `min` and/or `max`.
# `massprop check --bless FILE` writes today's values in.
[expect]
mass = { value = 1.4263, tol = "0.01%" }
center_of_mass.z = { value = 150.01, tol = 0.01 }    # mm
Izz = { max = "5000 kg*mm^2" }
"#;

/// Print the starter, or write it to a new file.
pub fn run(o: &Options) -> Result<Outcome, Diagnostic> {
    match o.file.as_deref() {
        None | Some("-") => Ok(Outcome::ok(STARTER.to_string(), Vec::new())),
        Some(path) => {
            crate::io::write_new(path, STARTER, "the part file")?;
            Ok(Outcome::ok(String::new(), Vec::new()))
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_starter_names_every_shape_of_the_registry() {
        let list = super::STARTER
            .split("one shape:")
            .nth(1)
            .and_then(|t| t.split("`include").next())
            .expect("the starter's shape list");
        for s in crate::shapes::SHAPES.iter() {
            let word = |w: &str| w.trim_matches(|c: char| !c.is_ascii_alphanumeric()) == s.name;
            assert!(list.split_whitespace().any(word), "{} is missing", s.name);
        }
    }
}
