//! The derivatives of an expression's value by the sources of uncertainty
//! its parameters depend on (`model::tolerance`): forward mode over the
//! same postfix steps `Expr::eval` runs, each step's value in f64 beside
//! its sparse gradient.

use super::{Expr, Func, Op, Value};
use crate::units;

/// ∂value/∂z for each source z the value depends on (SI per unit of the
/// source's standardised variable), by source index, sorted.
pub type Grad = Vec<(u32, f64)>;

/// `out += k · g`, by source.
pub fn axpy(out: &mut Grad, k: f64, g: &Grad) {
    for &(s, d) in g {
        match out.binary_search_by_key(&s, |e| e.0) {
            Ok(i) => out[i].1 += k * d,
            Err(i) => out.insert(i, (s, k * d)),
        }
    }
}

fn scaled(k: f64, g: &Grad) -> Grad {
    g.iter().map(|&(s, d)| (s, k * d)).collect()
}

impl Expr {
    /// The gradient of the value (`eval`'s, which must have succeeded) by
    /// the sources of the parameters it names: `params` gives a
    /// parameter's value and gradient. Empty when no parameter it uses
    /// has a tolerance. A derivative that does not exist (√ at 0) is
    /// infinite.
    pub fn tangent(&self, params: &dyn Fn(&str) -> Option<(Value, Grad)>) -> Grad {
        let mut stack: Vec<(f64, Grad)> = Vec::new();
        let pop = |stack: &mut Vec<(f64, Grad)>| stack.pop().expect("invariant: a parsed operand");
        for (op, _) in &self.steps {
            let next = match op {
                Op::Push(v) => (v.num.dd().hi, Grad::new()),
                Op::Name(n) => match params(n) {
                    Some((v, g)) => (v.num.dd().hi, g),
                    None if n == "pi" => (std::f64::consts::PI, Grad::new()),
                    None => (
                        units::parse_unit(n).map_or(f64::NAN, |u| u.factor.value()),
                        Grad::new(),
                    ),
                },
                Op::Neg => {
                    let (a, g) = pop(&mut stack);
                    (-a, scaled(-1.0, &g))
                }
                Op::Call(f, argc) => {
                    let args = stack.split_off(stack.len() - argc);
                    call(*f, args)
                }
                _ => {
                    let (b, gb) = pop(&mut stack);
                    let (a, mut ga) = pop(&mut stack);
                    match op {
                        Op::Add => {
                            axpy(&mut ga, 1.0, &gb);
                            (a + b, ga)
                        }
                        Op::Sub => {
                            axpy(&mut ga, -1.0, &gb);
                            (a - b, ga)
                        }
                        Op::Mul => {
                            let mut g = scaled(b, &ga);
                            axpy(&mut g, a, &gb);
                            (a * b, g)
                        }
                        Op::Div => {
                            let q = a / b;
                            let mut g = scaled(1.0 / b, &ga);
                            axpy(&mut g, -q / b, &gb);
                            (q, g)
                        }
                        Op::Pow => {
                            let p = a.powf(b);
                            let mut g = if ga.is_empty() {
                                Grad::new()
                            } else {
                                scaled(b * a.powf(b - 1.0), &ga)
                            };
                            if !gb.is_empty() {
                                axpy(&mut g, p * a.ln(), &gb);
                            }
                            (p, g)
                        }
                        _ => unreachable!("invariant: only binary operators here"),
                    }
                }
            };
            stack.push(next);
        }
        stack.pop().map(|(_, g)| g).unwrap_or_default()
    }
}

fn call(f: Func, mut args: Vec<(f64, Grad)>) -> (f64, Grad) {
    let (a, ga) = args[0].clone();
    match f {
        Func::Sqrt => {
            let r = a.sqrt();
            (r, scaled(0.5 / r, &ga))
        }
        Func::Sin => (a.sin(), scaled(a.cos(), &ga)),
        Func::Cos => (a.cos(), scaled(-a.sin(), &ga)),
        Func::Tan => {
            let c = a.cos();
            (a.tan(), scaled(1.0 / (c * c), &ga))
        }
        Func::Abs => (a.abs(), scaled(if a < 0.0 { -1.0 } else { 1.0 }, &ga)),
        Func::Min | Func::Max => {
            // The argument `eval` chose: the first of the extreme values.
            let mut best = 0;
            for (i, (x, _)) in args.iter().enumerate().skip(1) {
                let better = match f {
                    Func::Min => *x < args[best].0,
                    _ => *x > args[best].0,
                };
                if better {
                    best = i;
                }
            }
            args.swap_remove(best)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Grad, Value};
    use crate::expr::Expr;

    /// The gradient of `text` at `d` = 0.5 with ∂d/∂z₀ = 1, `n` = 3 with
    /// ∂n/∂z₁ = 1.
    fn grad(text: &str) -> Grad {
        let e = Expr::parse(text).unwrap();
        e.tangent(&|n| match n {
            "d" => Some((Value::of_f64(0.5), vec![(0, 1.0)])),
            "n" => Some((Value::of_f64(3.0), vec![(1, 1.0)])),
            "k" => Some((Value::of_f64(2.0), Grad::new())),
            _ => None,
        })
    }

    fn close(g: &Grad, want: &[(u32, f64)]) -> bool {
        g.len() == want.len()
            && g.iter()
                .zip(want)
                .all(|(a, b)| a.0 == b.0 && (a.1 - b.1).abs() <= 1e-15 * b.1.abs().max(1.0))
    }

    #[test]
    fn sums_products_and_quotients_follow_their_rules() {
        // ∂(d·n + k)/∂d = n = 3, ∂/∂n = d = 0.5.
        assert!(close(&grad("d * n + k"), &[(0, 3.0), (1, 0.5)]));
        // ∂(d / n)/∂d = 1/3, ∂/∂n = −d/n² = −1/18.
        assert!(close(&grad("d / n"), &[(0, 1.0 / 3.0), (1, -0.5 / 9.0)]));
        assert!(close(&grad("k - d"), &[(0, -1.0)]));
    }

    #[test]
    fn powers_roots_and_functions_follow_their_rules() {
        // ∂(π d²/4)/∂d = π d/2.
        assert!(close(
            &grad("pi * d^2 / 4"),
            &[(0, std::f64::consts::PI * 0.25)]
        ));
        // ∂√d/∂d = 1/(2√d).
        assert!(close(&grad("sqrt(d)"), &[(0, 0.5 / 0.5f64.sqrt())]));
        assert!(close(&grad("sin(d)"), &[(0, 0.5f64.cos())]));
        assert!(close(&grad("max(d, n)"), &[(1, 1.0)]));
        assert!(close(&grad("-abs(-d)"), &[(0, -1.0)]));
    }

    #[test]
    fn a_unit_carries_its_factor() {
        // d in metres per "mm": ∂(d · 1 mm)/∂d = 0.001.
        assert!(close(&grad("d * 1 mm"), &[(0, 0.001)]));
        assert!(grad("k * 3").is_empty());
    }
}
