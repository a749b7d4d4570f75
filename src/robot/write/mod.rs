//! Writing an `<inertial>` element in each format, and replacing a link's
//! in a file, every other byte kept.

use super::{Format, Tensor};

/// What `export` writes: a body's inertial in the link frame, SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Export {
    /// kg.
    pub mass: f64,
    /// The centre of mass in the link frame, m.
    pub pos: [f64; 3],
    /// The tensor about the centre of mass in the link frame (tensor
    /// convention), kg·m².
    pub tensor: Tensor,
    /// MJCF under `--principal`: the principal moments (ascending) and the
    /// rotation whose columns are the principal axes in the link frame
    /// (right-handed), written as `diaginertia` and `quat`.
    pub principal: Option<([f64; 3], [[f64; 3]; 3])>,
}

/// The `<inertial>` element of `e` in `format`, its lines after the first
/// indented by `indent` (the element's own indentation) plus one level.
pub fn inertial_element(format: Format, e: &Export, indent: &str) -> String {
    let _ = (format, e, indent);
    String::new()
}
