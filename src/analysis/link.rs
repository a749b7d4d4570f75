//! A link of a robot description as `diff PART ROBOT --link NAME` compares
//! it: found by its name, its inertial's mass properties (`diff::Props`).

use super::diff::Props;
use crate::diag::{Diagnostic, Source};
use crate::robot::{Dialect, Link};

/// The mass properties of the link named `name` in the robot description
/// `source` (of `format`): an error when no link, or more than one, has
/// that name, or it has no inertial.
pub fn props(source: &Source, format: Dialect, name: &str) -> Result<Props, Diagnostic> {
    let description = crate::robot::read::read(source, format)?;
    let link = named(source, &description.links, name)?;
    let Some(inertial) = &link.inertial else {
        return Err(source.error(
            link.range.start..link.range.start + 1,
            format!("link \"{name}\" has no <inertial> to compare"),
        ));
    };
    let t = inertial.tensor_in_link().matrix();
    let moments =
        crate::robot::engine::principal_moments(&inertial.tensor_in_link()).ok_or_else(|| {
            source.error(
                crate::robot::read::start_tag(&source.text, inertial.range.clone()),
                format!("link \"{name}\": its principal moments overflow"),
            )
        })?;
    Ok(Props {
        mass: inertial.mass,
        center_of_mass: inertial.pos,
        principal_moments: moments,
        inertia_com: t,
        principal_axes: None,
    })
}

/// The one link named `name`.
fn named<'a>(source: &Source, links: &'a [Link], name: &str) -> Result<&'a Link, Diagnostic> {
    let matching: Vec<_> = links.iter().filter(|l| l.name == name).collect();
    match matching.as_slice() {
        [one] => Ok(*one),
        [] => {
            let names: Vec<&str> = links.iter().map(|l| l.name.as_str()).collect();
            let shown = names
                .iter()
                .take(8)
                .map(|n| format!("\"{n}\""))
                .collect::<Vec<_>>();
            Err(Diagnostic::file(
                &source.name,
                format!(
                    "no link named \"{name}\" (links: {}{})",
                    shown.join(", "),
                    if names.len() > 8 { ", …" } else { "" }
                ),
            ))
        }
        _ => Err(Diagnostic::file(
            &source.name,
            format!("more than one link is named \"{name}\": `--link` cannot tell them apart"),
        )),
    }
}
