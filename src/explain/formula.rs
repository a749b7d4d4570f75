//! The shapes' formula templates (`shapes::Explain`): `m*(b^2 + c^2)/12`
//! read once into a tree, then written as text (`m(b² + c²)/12`) or TeX,
//! with the symbols or with a part's numbers, and evaluated in f64 (the
//! shapes' tests hold each template to its closed form).

/// A template read: numbers, symbols (by their index in the names given,
/// or `m`), π and the operations, parentheses kept as written.
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    Number(String),
    Symbol(usize),
    Pi,
    Add(Box<Node>, Box<Node>),
    Sub(Box<Node>, Box<Node>),
    Mul(Box<Node>, Box<Node>),
    Div(Box<Node>, Box<Node>),
    Neg(Box<Node>),
    Pow(Box<Node>, u32),
    Paren(Box<Node>),
}

/// Read `template` over the symbols `names`; an error names what is wrong
/// (a template is the program's own text: `shapes`' tests read them all).
pub fn parse(template: &str, names: &[&str]) -> Result<Node, String> {
    let tokens = tokens(template)?;
    let mut p = Parser {
        tokens,
        at: 0,
        names,
    };
    let node = p.sum()?;
    if p.at != p.tokens.len() {
        return Err(format!("`{template}`: unexpected `{}`", p.tokens[p.at]));
    }
    Ok(node)
}

fn tokens(s: &str) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    let mut chars = s.chars().peekable();
    while let Some(&c) = chars.peek() {
        if c.is_whitespace() {
            chars.next();
        } else if c.is_ascii_digit() || c == '.' {
            let mut t = String::new();
            while let Some(&d) = chars.peek().filter(|d| d.is_ascii_digit() || **d == '.') {
                t.push(d);
                chars.next();
            }
            out.push(t);
        } else if c.is_ascii_alphabetic() || c == '_' {
            let mut t = String::new();
            while let Some(&d) = chars
                .peek()
                .filter(|d| d.is_ascii_alphanumeric() || **d == '_')
            {
                t.push(d);
                chars.next();
            }
            out.push(t);
        } else if "+-*/^()".contains(c) {
            out.push(c.to_string());
            chars.next();
        } else {
            return Err(format!("`{s}`: unexpected `{c}`"));
        }
    }
    Ok(out)
}

struct Parser<'a> {
    tokens: Vec<String>,
    at: usize,
    names: &'a [&'a str],
}

impl Parser<'_> {
    fn peek(&self) -> Option<&str> {
        self.tokens.get(self.at).map(String::as_str)
    }

    fn next(&mut self) -> Result<String, String> {
        let t = self.tokens.get(self.at).cloned().ok_or("unexpected end")?;
        self.at += 1;
        Ok(t)
    }

    fn sum(&mut self) -> Result<Node, String> {
        let mut left = self.product()?;
        while let Some(op @ ("+" | "-")) = self.peek() {
            let add = op == "+";
            self.at += 1;
            let right = Box::new(self.product()?);
            left = if add {
                Node::Add(Box::new(left), right)
            } else {
                Node::Sub(Box::new(left), right)
            };
        }
        Ok(left)
    }

    fn product(&mut self) -> Result<Node, String> {
        let mut left = self.unary()?;
        while let Some(op @ ("*" | "/")) = self.peek() {
            let mul = op == "*";
            self.at += 1;
            let right = Box::new(self.unary()?);
            left = if mul {
                Node::Mul(Box::new(left), right)
            } else {
                Node::Div(Box::new(left), right)
            };
        }
        Ok(left)
    }

    fn unary(&mut self) -> Result<Node, String> {
        if self.peek() == Some("-") {
            self.at += 1;
            return Ok(Node::Neg(Box::new(self.unary()?)));
        }
        let base = self.atom()?;
        if self.peek() == Some("^") {
            self.at += 1;
            let e = self.next()?;
            let n = e.parse().map_err(|_| format!("exponent `{e}`"))?;
            return Ok(Node::Pow(Box::new(base), n));
        }
        Ok(base)
    }

    fn atom(&mut self) -> Result<Node, String> {
        let t = self.next()?;
        if t == "(" {
            let inner = self.sum()?;
            if self.next()? != ")" {
                return Err("unclosed `(`".into());
            }
            return Ok(Node::Paren(Box::new(inner)));
        }
        if t.starts_with(|c: char| c.is_ascii_digit() || c == '.') {
            return Ok(Node::Number(t));
        }
        if t == "pi" {
            return Ok(Node::Pi);
        }
        if t == "m" {
            return Ok(Node::Symbol(usize::MAX));
        }
        self.names
            .iter()
            .position(|n| *n == t)
            .map(Node::Symbol)
            .ok_or(format!("unknown symbol `{t}`"))
    }
}

/// How a symbol is written: its text and TeX, or a number.
pub trait Symbols {
    /// Symbol `i` (`usize::MAX`: the mass), as text or TeX.
    fn symbol(&self, i: usize, tex: bool) -> String;
    /// Whether symbol `i` is written as a number that needs parentheses
    /// under a power or after a sign (negative).
    fn negative(&self, i: usize) -> bool;
    /// Whether the symbols are numbers (products written ×).
    fn numeric(&self) -> bool;
}

fn superscript(n: u32) -> String {
    n.to_string()
        .chars()
        .map(|d| match d {
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// `n` written as text (`tex` false) or TeX, its symbols by `s`.
pub fn write(n: &Node, s: &dyn Symbols, tex: bool) -> String {
    let minus = if tex { "-" } else { "−" };
    match n {
        Node::Number(t) => t.clone(),
        Node::Symbol(i) => {
            let v = s.symbol(*i, tex);
            if s.negative(*i) {
                if tex {
                    format!("\\left({v}\\right)")
                } else {
                    format!("({v})")
                }
            } else {
                v
            }
        }
        Node::Pi => (if tex { "\\pi" } else { "π" }).into(),
        Node::Add(a, b) => format!("{} + {}", write(a, s, tex), write(b, s, tex)),
        Node::Sub(a, b) => format!("{} {minus} {}", write(a, s, tex), write(b, s, tex)),
        Node::Mul(a, b) => {
            let (l, r) = (write(a, s, tex), write(b, s, tex));
            let right_opens = matches!(**b, Node::Paren(_) | Node::Pi);
            let left_number = matches!(**a, Node::Number(_)) && !matches!(**b, Node::Number(_));
            if s.numeric() {
                let times = if tex { " \\times " } else { " × " };
                format!("{l}{times}{r}")
            } else if right_opens && !matches!(**a, Node::Paren(_)) || left_number {
                let gap = if tex { "\\," } else { "" };
                format!("{l}{gap}{r}")
            } else {
                let dot = if tex { " \\cdot " } else { "·" };
                format!("{l}{dot}{r}")
            }
        }
        Node::Div(a, b) => format!("{}/{}", write(a, s, tex), write(b, s, tex)),
        Node::Neg(a) => format!("{minus}{}", write(a, s, tex)),
        Node::Pow(b, e) => {
            let base = write(b, s, tex);
            if tex {
                format!("{{{base}}}^{{{e}}}")
            } else {
                format!("{base}{}", superscript(*e))
            }
        }
        Node::Paren(a) => {
            if tex {
                format!("\\left({}\\right)", write(a, s, tex))
            } else {
                format!("({})", write(a, s, tex))
            }
        }
    }
}

/// `n` evaluated in f64, symbol i as `values[i]`, the mass as `m`.
pub fn eval(n: &Node, m: f64, values: &[f64]) -> f64 {
    match n {
        Node::Number(t) => t.parse().unwrap_or(f64::NAN),
        Node::Symbol(i) => {
            if *i == usize::MAX {
                m
            } else {
                values[*i]
            }
        }
        Node::Pi => std::f64::consts::PI,
        Node::Add(a, b) => eval(a, m, values) + eval(b, m, values),
        Node::Sub(a, b) => eval(a, m, values) - eval(b, m, values),
        Node::Mul(a, b) => eval(a, m, values) * eval(b, m, values),
        Node::Div(a, b) => eval(a, m, values) / eval(b, m, values),
        Node::Neg(a) => -eval(a, m, values),
        Node::Pow(b, e) => eval(b, m, values).powi(*e as i32),
        Node::Paren(a) => eval(a, m, values),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::{SHAPES, Shape};

    struct Names<'a>(&'a [&'a str]);

    impl Symbols for Names<'_> {
        fn symbol(&self, i: usize, _: bool) -> String {
            if i == usize::MAX {
                "m".into()
            } else {
                self.0[i].into()
            }
        }
        fn negative(&self, _: usize) -> bool {
            false
        }
        fn numeric(&self) -> bool {
            false
        }
    }

    #[test]
    fn a_box_moment_is_written_as_a_textbook_writes_it() {
        let n = parse("m*(b^2 + c^2)/12", &["a", "b", "c"]).unwrap();
        assert_eq!(write(&n, &Names(&["a", "b", "c"]), false), "m(b² + c²)/12");
        assert_eq!(
            write(&n, &Names(&["a", "b", "c"]), true),
            "m\\,\\left({b}^{2} + {c}^{2}\\right)/12"
        );
    }

    /// Every shape's templates read, and each is its closed form: the
    /// measure `measure_of`, Ixx = ∫(y² + z²) dm from `moments_of`, at
    /// dimensions of no special relation (inner below outer).
    #[test]
    fn every_shape_template_is_its_closed_form() {
        for info in &SHAPES {
            let shape = info.shape;
            let e = shape.explain();
            let names: Vec<&str> = e.dims.iter().map(|d| d.name).collect();
            // Outer sizes first, inner ones smaller.
            let d: Vec<f64> = (0..names.len())
                .map(|i| match names[i] {
                    "r" | "r_t" | "a_i" => 0.37 + 0.05 * i as f64,
                    _ => 1.3 + 0.41 * i as f64,
                })
                .collect();
            let m = 2.7;
            if !e.measure.is_empty() {
                let n = parse(e.measure, &names).unwrap();
                let want = shape.measure_of(&d);
                let got = eval(&n, m, &d);
                assert!(
                    (got - want).abs() <= 1e-12 * want.abs(),
                    "{}: {got} vs {want}",
                    info.name
                );
            }
            if e.moments.iter().all(|f| f.is_empty()) {
                continue;
            }
            let s = shape.second_moments(m, &d);
            for k in 0..3 {
                if e.moments[k].is_empty() {
                    continue;
                }
                let n = parse(e.moments[k], &names).unwrap();
                let want = s[(k + 1) % 3] + s[(k + 2) % 3];
                let got = eval(&n, m, &d);
                assert!(
                    (got - want).abs() <= 1e-12 * want.abs().max(1e-300),
                    "{} moment {k}: {got} vs {want}",
                    info.name
                );
            }
        }
        assert!(Shape::ALL.len() == SHAPES.len());
    }
}
