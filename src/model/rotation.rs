//! The rotation forms of a part file (`rotation = { .. }`) read and
//! validated into an `Orientation` (the forms and their matrices are
//! `crate::rotation`).

pub use crate::rotation::*;

use super::Ctx;
use super::ctx::Whose;
use super::raw::{Angles, Floats, RawAxes, RawRotation};
use crate::diag::Diagnostic;
use crate::la::Matrix3;
use crate::thresholds::{MATRIX_TOLERANCE, QUATERNION_TOLERANCE};
use toml::Spanned;

/// The rotation form keys present (not `degrees`, which goes with some),
/// in file order, so that a message names the second.
fn forms(r: &RawRotation) -> Vec<(&'static str, std::ops::Range<usize>)> {
    let mut forms: Vec<(&str, std::ops::Range<usize>)> = [
        ("quaternion", r.quaternion.as_ref().map(|v| v.span())),
        ("axis", r.axis.as_ref().map(|v| v.span())),
        ("matrix", r.matrix.as_ref().map(|v| v.span())),
        ("intrinsic", r.intrinsic.as_ref().map(|v| v.span())),
        ("extrinsic", r.extrinsic.as_ref().map(|v| v.span())),
    ]
    .into_iter()
    .filter_map(|(k, s)| s.map(|s| (k, s)))
    .collect();
    forms.sort_by_key(|(_, s)| s.start);
    forms
}

impl Ctx<'_> {
    pub(super) fn rotation(&self, raw: &Spanned<RawRotation>) -> Result<Orientation, Diagnostic> {
        self.rotation_of(raw, "rotation")
    }

    /// `[analysis] axes`: the report axes' x and y directions in the
    /// file's frame (z = x × y), or a rotation of the file's axes in any
    /// form a part's `rotation` takes. The axes are R's columns.
    pub(super) fn axes(&self, raw: &Spanned<RawAxes>) -> Result<Orientation, Diagnostic> {
        let a = raw.get_ref();
        let (x, y) = match (&a.x, &a.y) {
            (None, None) => {
                let r = a.rotation();
                if forms(&r).is_empty() {
                    return Err(self
                        .err(raw.span(), "`axes` needs the report axes")
                        .help("write `{ x = [..], y = [..] }` (their directions in the file's frame; z = x × y) or a rotation of the file's axes: `{ axis = [x, y, z], degrees = θ }`, `{ quaternion = [w, x, y, z] }`, `{ matrix = [[..], [..], [..]] }`, `{ intrinsic = \"zyx\", degrees = [a, b, c] }`"));
                }
                return self.rotation_of(&Spanned::new(raw.span(), r), "axes");
            }
            (Some(x), Some(y)) => (x, y),
            (Some(_), None) => {
                return Err(self.err(raw.span(), "`axes` with `x` needs `y` (z is x × y)"));
            }
            (None, Some(_)) => return Err(self.err(raw.span(), "`axes` with `y` needs `x`")),
        };
        let r = a.rotation();
        let degrees = r.degrees.as_ref().map(|d| ("degrees", d.span()));
        if let Some((key, span)) = forms(&r).into_iter().chain(degrees).next() {
            return Err(self
                .err(span, format!("`axes` takes `x` and `y` or a rotation, not both: `{key}` conflicts with `x`"))
                .help("give the report axes as two directions, `{ x = [..], y = [..] }`, or as the rotation that turns the file's axes onto them"));
        }
        let unit = |v: &Floats, key: &str| -> Result<[f64; 3], Diagnostic> {
            let c = self.floats(v, key, 3)?;
            let n = crate::numeric::norm(&c);
            if !(n > 0.0 && n.is_finite()) {
                return Err(self.err(v.span(), format!("`{key}` must be a non-zero direction")));
            }
            Ok([c[0] / n, c[1] / n, c[2] / n])
        };
        let (xh, yh) = (unit(x, "x")?, unit(y, "y")?);
        let dot: f64 = (0..3).map(|i| xh[i] * yh[i]).sum();
        if !(dot.abs() <= MATRIX_TOLERANCE) {
            return Err(self
                .err(
                    y.span(),
                    format!(
                        "`y` is not perpendicular to `x`: they are {:.6}° apart",
                        dot.clamp(-1.0, 1.0).acos().to_degrees()
                    ),
                )
                .help(format!("the report axes are perpendicular: y at 90° to x (to {MATRIX_TOLERANCE:e} in the cosine); z is x × y")));
        }
        // The directions as given: normalised, crossed and made
        // orthonormal in the arithmetic of the report (`Orientation::Axes`).
        let given = |v: &Floats, key: &str| self.floats(v, key, 3).map(|c| [c[0], c[1], c[2]]);
        Ok(Orientation::Axes(given(x, "x")?, given(y, "y")?))
    }

    /// A rotation form, `key` naming it in messages (`rotation`, `axes`).
    fn rotation_of(
        &self,
        raw: &Spanned<RawRotation>,
        key: &str,
    ) -> Result<Orientation, Diagnostic> {
        let r = raw.get_ref();
        let forms = forms(r);
        let (form, _) = match forms.as_slice() {
            [] => {
                return Err(self
                    .err(raw.span(), format!("`{key}` needs one form"))
                    .help("write `{ quaternion = [w, x, y, z] }`, `{ axis = [x, y, z], degrees = θ }`, `{ matrix = [[..], [..], [..]] }`, or `{ intrinsic = \"zyx\", degrees = [a, b, c] }` (or `extrinsic`)"));
            }
            [one] => one.clone(),
            [first, second, ..] => {
                return Err(self
                    .err(
                        second.1.clone(),
                        format!(
                            "`{key}` takes one form: `{}` conflicts with `{}`",
                            second.0, first.0
                        ),
                    )
                    .label("second form"));
            }
        };
        let takes_degrees = matches!(form, "axis" | "intrinsic" | "extrinsic");
        if let (false, Some(d)) = (takes_degrees, &r.degrees) {
            return Err(self.err(
                d.span(),
                format!("`degrees` does not go with `{form}`; it goes with `axis`, `intrinsic` or `extrinsic`"),
            ));
        }
        let degrees = || {
            r.degrees.as_ref().ok_or_else(|| {
                self.err(raw.span(), format!("`{key}` with `{form}` needs `degrees`"))
            })
        };
        match form {
            "quaternion" => {
                let q = r.quaternion.as_ref().expect("form is quaternion");
                let v = self.floats(q, "quaternion", 4)?;
                // Scaled, so that a huge component gives its length, not inf.
                let norm = crate::numeric::norm(&v);
                if !((norm - 1.0).abs() <= QUATERNION_TOLERANCE) {
                    // (`{}` of 1e300 is 301 digits; `norm` stops at f64::MAX.)
                    let length = if norm < 1e6 {
                        format!("{norm}")
                    } else if norm < f64::MAX {
                        format!("{norm:e}")
                    } else {
                        format!("above {:e}", f64::MAX)
                    };
                    return Err(self
                        .err(q.span(), format!("`quaternion` must have unit length, got length {length}"))
                        .help(format!("only rounding is tolerated (|‖q‖ − 1| ≤ {QUATERNION_TOLERANCE:e}); the order is [w, x, y, z]")));
                }
                Ok(Orientation::Quaternion([v[0], v[1], v[2], v[3]]))
            }
            "axis" => {
                let a = r.axis.as_ref().expect("form is axis");
                let v = self.floats(a, "axis", 3)?;
                let k = [v[0], v[1], v[2]];
                if k.iter().all(|x| *x == 0.0) {
                    return Err(self.err(a.span(), "`axis` must be a non-zero vector"));
                }
                let d = degrees()?;
                match d.get_ref() {
                    Angles::One(deg) if deg.is_finite() => Ok(Orientation::AxisAngle(k, *deg)),
                    Angles::One(_) => Err(self.err(d.span(), "`degrees` must be finite")),
                    Angles::Three(_) => Err(self.err(
                        d.span(),
                        "with `axis`, `degrees` is one angle, not an array",
                    )),
                }
            }
            "matrix" => {
                let m = r.matrix.as_ref().expect("form is matrix");
                let rows = self.exactly(m, 3, Whose::Key("matrix"), "rows")?;
                let mut out = Matrix3::zeros();
                for (i, row) in rows.iter().enumerate() {
                    let v = self.floats(row, "matrix row", 3)?;
                    for j in 0..3 {
                        out[(i, j)] = v[j];
                    }
                }
                let defect = (out.transpose() * out - Matrix3::identity()).amax();
                if !defect.is_finite() {
                    return Err(self.err(
                        m.span(),
                        format!(
                            "`matrix` is not a rotation: it has an entry {:e}, where a rotation's lie between −1 and 1",
                            out.iter().copied().fold(0.0_f64, |a, x| if x.abs() > a.abs() { x } else { a })
                        ),
                    ));
                }
                if !(defect <= MATRIX_TOLERANCE) {
                    return Err(self
                        .err(m.span(), format!("`matrix` is not orthonormal (RᵀR differs from the identity by {defect:.3e})"))
                        .help(format!("rows must be orthonormal to {MATRIX_TOLERANCE:e}; give the rotation as a quaternion or axis and angle if its entries are rounded")));
                }
                if out.determinant() < 0.0 {
                    return Err(self
                        .err(
                            m.span(),
                            "`matrix` has determinant −1: it is a reflection, not a rotation",
                        )
                        .help("negate one row or column to make the axes right-handed"));
                }
                Ok(Orientation::Matrix(Box::new(std::array::from_fn(|i| {
                    std::array::from_fn(|j| out[(i, j)])
                }))))
            }
            _ => {
                let intrinsic = form == "intrinsic";
                let s = if intrinsic {
                    &r.intrinsic
                } else {
                    &r.extrinsic
                };
                let s = s.as_ref().expect("form is intrinsic or extrinsic");
                let seq = parse_sequence(s.get_ref()).ok_or_else(|| {
                    self.err(s.span(), format!("`{form}` must be three axes such as \"zyx\" or \"zxz\", no axis twice in a row, got {:?}", s.get_ref()))
                })?;
                let d = degrees()?;
                match d.get_ref() {
                    Angles::Three(a) if a.len() == 3 && a.iter().all(|x| x.is_finite()) => {
                        Ok(Orientation::Euler(
                            seq.map(|a| a as u8),
                            [a[0], a[1], a[2]],
                            intrinsic,
                        ))
                    }
                    Angles::Three(a) if a.len() == 3 => {
                        Err(self.err(d.span(), "`degrees` must be finite"))
                    }
                    _ => Err(self.err(
                        d.span(),
                        format!("with `{form}`, `degrees` is an array of three angles, one for each axis of the sequence"),
                    )),
                }
            }
        }
    }

    /// A plain array of `n` finite numbers (rotation parameters carry no unit).
    fn floats(&self, v: &Floats, key: &str, n: usize) -> Result<Vec<f64>, Diagnostic> {
        self.exactly(v, n, Whose::Key(key), "numbers")?
            .iter()
            .map(|x| {
                if x.get_ref().is_finite() {
                    Ok(*x.get_ref())
                } else {
                    Err(self.err(x.span(), format!("`{key}` must be finite")))
                }
            })
            .collect()
    }
}

/// An Euler sequence such as "zyx": three axes, no axis twice in a row.
pub(super) fn parse_sequence(s: &str) -> Option<[usize; 3]> {
    let axes: Vec<usize> = s
        .chars()
        .map(|c| match c.to_ascii_lowercase() {
            'x' => Some(0),
            'y' => Some(1),
            'z' => Some(2),
            _ => None,
        })
        .collect::<Option<_>>()?;
    match axes[..] {
        [a, b, c] if a != b && b != c => Some([a, b, c]),
        _ => None,
    }
}

/// `--axes`: `key=values` pairs separated by `;`, the keys of `[analysis]
/// axes` (`x=1,0,0;y=0,-1,0`, `quaternion=w,x,y,z`, `axis=0,0,1;degrees=90`,
/// `intrinsic=zyx;degrees=a,b,c`, `matrix=` nine numbers by rows), read by
/// the same rules as the file's `axes`.
pub fn parse_flag_axes(text: &str) -> Result<Orientation, String> {
    let mut pairs = Vec::new();
    for pair in text.split(';').map(str::trim).filter(|p| !p.is_empty()) {
        let (key, value) = pair
            .split_once('=')
            .ok_or_else(|| format!("expected `key=values`, got {pair:?}"))?;
        let key = key.trim();
        let value = value.trim();
        let toml = match key {
            "intrinsic" | "extrinsic" => {
                if !value.chars().all(|c| c.is_ascii_alphabetic()) {
                    return Err(format!("`{key}` is three axes such as zyx, got {value:?}"));
                }
                format!("\"{value}\"")
            }
            "x" | "y" | "quaternion" | "axis" | "degrees" | "matrix" => {
                let numbers = value
                    .trim_start_matches('[')
                    .trim_end_matches(']')
                    .split(',')
                    .map(|n| {
                        let x = n.trim().parse::<f64>().ok().filter(|x| x.is_finite());
                        match x {
                            // As in a file: not zero as written, zero or
                            // subnormal in f64.
                            Some(x)
                                if x.abs() < f64::MIN_POSITIVE
                                    && (x != 0.0 || super::ctx::nonzero_literal(n)) =>
                            {
                                Err(format!(
                                    "`{key}`: {:?} is too small: below {:e}, f64 loses precision",
                                    n.trim(),
                                    f64::MIN_POSITIVE
                                ))
                            }
                            Some(x) => Ok(format!("{x:?}")),
                            None => Err(format!("`{key}`: {:?} is not a finite number", n.trim())),
                        }
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                match (key, numbers.len()) {
                    ("degrees", 1) => numbers[0].clone(),
                    ("matrix", 9) => format!(
                        "[[{}], [{}], [{}]]",
                        numbers[0..3].join(", "),
                        numbers[3..6].join(", "),
                        numbers[6..9].join(", ")
                    ),
                    ("matrix", n) => {
                        return Err(format!("`matrix` is nine numbers, row by row, got {n}"));
                    }
                    _ => format!("[{}]", numbers.join(", ")),
                }
            }
            _ => {
                return Err(format!(
                    "unknown key `{key}`: give `x` and `y`, or `quaternion`, `axis` with `degrees`, `matrix`, or `intrinsic`/`extrinsic` with `degrees`"
                ));
            }
        };
        pairs.push(format!("{key} = {toml}"));
    }
    // Read as `[analysis] axes` is, by the one reader.
    let text = format!("analysis.axes = {{ {} }}\n", pairs.join(", "));
    let source = crate::diag::Source::new("--axes", text);
    let axes = super::fast::read_file(&source.text)
        .and_then(|raw| raw.analysis?.into_inner().axes)
        .ok_or_else(|| super::fast::explain(&source).message().to_string())?;
    let ctx = Ctx {
        source: &source,
        units: crate::units::FileUnits::default(),
        materials: Default::default(),
        params: Default::default(),
        growth: Default::default(),
    };
    ctx.axes(&axes).map_err(|d| match d.help_text() {
        Some(help) => format!("{} ({help})", d.message()),
        None => d.message().to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::la::Vector3;

    fn q(x: [f64; 4]) -> Matrix3<f64> {
        to_matrix3(&quaternion(x))
    }
    fn aa(k: Vector3<f64>, deg: f64) -> Matrix3<f64> {
        to_matrix3(&axis_angle([k.x, k.y, k.z], deg))
    }
    fn eu(seq: [usize; 3], deg: [f64; 3], intrinsic: bool) -> Matrix3<f64> {
        to_matrix3(&euler(seq, deg, intrinsic))
    }

    fn close(a: &Matrix3<f64>, b: &Matrix3<f64>, tol: f64) -> bool {
        (a - b).amax() <= tol
    }

    #[test]
    fn multiples_of_ninety_degrees_are_exact() {
        assert_eq!(sin_cos_deg(0.0), (0.0, 1.0));
        assert_eq!(sin_cos_deg(90.0), (1.0, 0.0));
        assert_eq!(sin_cos_deg(180.0), (0.0, -1.0));
        assert_eq!(sin_cos_deg(-90.0), (-1.0, 0.0));
        assert_eq!(sin_cos_deg(450.0), (1.0, 0.0));
    }

    #[test]
    fn degree_sin_cos_matches_radians_elsewhere() {
        for d in [1.0, 29.0, 44.9, 45.0, 91.0, 200.0, -377.5, 1e6 + 0.25] {
            let (s, c) = sin_cos_deg(d);
            let (s2, c2) = (d.to_radians()).sin_cos();
            assert!((s - s2).abs() < 1e-9 && (c - c2).abs() < 1e-9, "{d}");
        }
    }

    #[test]
    fn quarter_turn_about_z_is_the_same_in_every_form() {
        let expect = Matrix3::new(0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);
        assert_eq!(aa(Vector3::z(), 90.0), expect);
        assert_eq!(q([1.0, 0.0, 0.0, 1.0]), expect);
        assert_eq!(eu([2, 1, 0], [90.0, 0.0, 0.0], true), expect);
        assert_eq!(eu([0, 1, 2], [0.0, 0.0, 90.0], false), expect);
    }

    #[test]
    fn intrinsic_sequence_equals_reversed_extrinsic_sequence() {
        let a = eu([2, 1, 0], [30.0, 20.0, 10.0], true);
        let b = eu([0, 1, 2], [10.0, 20.0, 30.0], false);
        assert!(close(&a, &b, 1e-15));
    }

    #[test]
    fn intrinsic_rotation_turns_about_the_new_axes() {
        // Intrinsic zy by 90° and 90°: Ry takes e_z to e_x, then Rz takes
        // e_x to e_y. (Extrinsic zy would give Ry Rz e_z = e_x instead.)
        let r = eu([2, 1, 0], [90.0, 90.0, 0.0], true);
        assert_eq!(r * Vector3::z(), Vector3::y());
        let e = eu([2, 1, 0], [90.0, 90.0, 0.0], false);
        assert_eq!(e * Vector3::z(), Vector3::x());
    }

    #[test]
    fn quaternion_and_axis_angle_agree_for_a_general_rotation() {
        let k = Vector3::new(1.0, -2.0, 0.5).normalize();
        let t = 37.0_f64;
        let (s, c) = (t / 2.0).to_radians().sin_cos();
        let quat = [c, s * k.x, s * k.y, s * k.z];
        assert!(close(&q(quat), &aa(k, t), 1e-15));
        let r = aa(k, t);
        assert!(close(&(r.transpose() * r), &Matrix3::identity(), 1e-15));
        assert!((r.determinant() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn sequences_parse_and_reject_repeats() {
        assert_eq!(parse_sequence("ZYX"), Some([2, 1, 0]));
        assert_eq!(parse_sequence("zxz"), Some([2, 0, 2]));
        assert_eq!(parse_sequence("zzx"), None);
        assert_eq!(parse_sequence("zy"), None);
        assert_eq!(parse_sequence("abc"), None);
    }
}
