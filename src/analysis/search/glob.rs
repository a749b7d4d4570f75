//! The globs of ignore files and `--exclude`: parsed as the `globset`
//! crate parses a gitignore line's glob (`*`, `?`, `[...]` with ranges,
//! `!`/`^` negation and `[:name:]`, `**/`, `/**`, `/**/`, `\` escapes and
//! `{a,b}` alternates, as ripgrep reads them), and matched on a path's
//! bytes by a small automaton: no regular expressions.
//!
//! NOTE: hand-written rather than `globset` (via the `ignore` crate) to
//! drop `globset`, `regex-automata`, `regex-syntax`, `aho-corasick` and
//! `bstr` from the build (docs/performance.md, "Build time: the directory
//! search without `ignore`"). Each rule below is `globset`'s translation
//! of a token into a byte-level regular expression (its `(?-u)` mode: a
//! path need not be UTF-8), matched here by simulating that expression
//! directly; tests/integration/search_rules.rs holds the whole search
//! equal to the `ignore` crate's on random trees and ignore files.

/// Why a glob is not one.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GlobError {
    UnclosedClass,
    InvalidRange(char, char),
    UnopenedAlternates,
    UnclosedAlternates,
    TooManyNestedAlternates,
    DanglingEscape,
}

impl std::fmt::Display for GlobError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // NOTE: globset's own wording, which `check DIR` has always shown.
        match self {
            GlobError::UnclosedClass => write!(f, "unclosed character class; missing ']'"),
            GlobError::InvalidRange(s, e) => write!(f, "invalid range; '{s}' > '{e}'"),
            GlobError::UnopenedAlternates => write!(
                f,
                "unopened alternate group; missing '{{' (maybe escape '}}' with '[}}]'?)"
            ),
            GlobError::UnclosedAlternates => write!(
                f,
                "unclosed alternate group; missing '}}' (maybe escape '{{' with '[{{]'?)"
            ),
            GlobError::TooManyNestedAlternates => write!(f, "alternate groups nested too deeply"),
            GlobError::DanglingEscape => write!(f, "dangling '\\'"),
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
enum Token {
    Literal(char),
    /// `?`: one byte but `/`.
    Any,
    /// `*`: any bytes but `/`.
    ZeroOrMore,
    /// `**/` at the start: nothing, `/`, or anything (but a newline)
    /// ending in `/`.
    RecursivePrefix,
    /// `/**` at the end: `/` and anything (but a newline).
    RecursiveSuffix,
    /// `/**/`: `/`, or `/`, anything (but a newline), `/`.
    RecursiveZeroOrMore,
    Class {
        negated: bool,
        ranges: Vec<(char, char)>,
    },
    Alternates(Vec<Vec<Token>>),
}

/// A set of bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Bytes([u64; 4]);

impl Bytes {
    const NONE: Bytes = Bytes([0; 4]);
    fn one(b: u8) -> Bytes {
        let mut s = Bytes::NONE;
        s.add(b);
        s
    }
    fn all_but(b: u8) -> Bytes {
        Bytes::one(b).not()
    }
    fn add(&mut self, b: u8) {
        self.0[usize::from(b / 64)] |= 1 << (b % 64);
    }
    fn has(&self, b: u8) -> bool {
        self.0[usize::from(b / 64)] & (1 << (b % 64)) != 0
    }
    fn not(self) -> Bytes {
        Bytes(self.0.map(|w| !w))
    }
}

#[derive(Debug, Clone)]
enum Inst {
    Byte(Bytes),
    Split(usize, usize),
    Jmp(usize),
    Match,
}

/// A compiled glob: matches a whole path (as bytes) or not.
#[derive(Debug, Clone)]
pub struct Glob {
    prog: Vec<Inst>,
}

impl Glob {
    /// `glob` as globset parses it with `literal_separator` and
    /// `backslash_escape` on; `allow_unclosed_class`: a `[` without its
    /// `]` is a literal `[` (ignore files) rather than an error
    /// (`--exclude`). `Ok(None)`: a class of non-ASCII ranges that the
    /// regular expression globset writes for it would reject (a
    /// reversed byte range); the ignore file it is in then has no rules.
    pub fn new(glob: &str, allow_unclosed_class: bool) -> Result<Option<Glob>, GlobError> {
        let tokens = Parser::parse(glob, allow_unclosed_class)?;
        let mut c = Compiler {
            prog: Vec::new(),
            bad: false,
        };
        if tokens == [Token::RecursivePrefix] {
            // globset's special case: `**` alone matches everything.
            c.dot_star();
        } else {
            c.tokens(&tokens);
        }
        c.prog.push(Inst::Match);
        Ok((!c.bad).then_some(Glob { prog: c.prog }))
    }

    /// Whether the whole of `path` matches.
    pub fn is_match(&self, path: &[u8]) -> bool {
        let n = self.prog.len();
        let mut now = vec![false; n];
        let mut next = vec![false; n];
        let mut stack = Vec::new();
        self.add(&mut now, &mut stack, 0);
        for &b in path {
            next.fill(false);
            let mut any = false;
            for (pc, inst) in self.prog.iter().enumerate() {
                if now[pc]
                    && let Inst::Byte(set) = inst
                    && set.has(b)
                {
                    self.add(&mut next, &mut stack, pc + 1);
                    any = true;
                }
            }
            if !any {
                return false;
            }
            std::mem::swap(&mut now, &mut next);
        }
        self.prog
            .iter()
            .zip(&now)
            .any(|(inst, &on)| on && matches!(inst, Inst::Match))
    }

    /// `pc` and every instruction reached from it without a byte.
    fn add(&self, set: &mut [bool], stack: &mut Vec<usize>, pc: usize) {
        stack.push(pc);
        while let Some(pc) = stack.pop() {
            if set[pc] {
                continue;
            }
            set[pc] = true;
            match self.prog[pc] {
                Inst::Split(a, b) => {
                    stack.push(b);
                    stack.push(a);
                }
                Inst::Jmp(a) => stack.push(a),
                Inst::Byte(_) | Inst::Match => {}
            }
        }
    }
}

struct Compiler {
    prog: Vec<Inst>,
    /// A class globset's regular expression would not compile.
    bad: bool,
}

impl Compiler {
    fn byte(&mut self, set: Bytes) {
        self.prog.push(Inst::Byte(set));
    }

    /// `set*`.
    fn star(&mut self, set: Bytes) {
        let l = self.prog.len();
        self.prog.push(Inst::Split(l + 1, l + 3));
        self.byte(set);
        self.prog.push(Inst::Jmp(l));
    }

    /// `.*` (`.`: any byte but a newline, as in a regular expression).
    fn dot_star(&mut self) {
        self.star(Bytes::all_but(b'\n'));
    }

    /// One of `alts`, each compiled by `f`.
    fn alternation(&mut self, n: usize, mut f: impl FnMut(&mut Compiler, usize)) {
        let mut jumps = Vec::new();
        for i in 0..n {
            let split = self.prog.len();
            if i + 1 < n {
                self.prog.push(Inst::Split(split + 1, 0));
            }
            f(self, i);
            if i + 1 < n {
                jumps.push(self.prog.len());
                self.prog.push(Inst::Jmp(0));
                let here = self.prog.len();
                self.prog[split] = Inst::Split(split + 1, here);
            }
        }
        let end = self.prog.len();
        for j in jumps {
            self.prog[j] = Inst::Jmp(end);
        }
    }

    fn tokens(&mut self, tokens: &[Token]) {
        for t in tokens {
            self.token(t);
        }
    }

    fn token(&mut self, t: &Token) {
        let slash = Bytes::one(b'/');
        match t {
            Token::Literal(c) => {
                for &b in c.encode_utf8(&mut [0; 4]).as_bytes() {
                    self.byte(Bytes::one(b));
                }
            }
            Token::Any => self.byte(Bytes::all_but(b'/')),
            Token::ZeroOrMore => self.star(Bytes::all_but(b'/')),
            // (?:/?|.*/)
            Token::RecursivePrefix => self.alternation(3, |c, i| match i {
                0 => {}
                1 => c.byte(slash),
                _ => {
                    c.dot_star();
                    c.byte(slash);
                }
            }),
            // /.*
            Token::RecursiveSuffix => {
                self.byte(slash);
                self.dot_star();
            }
            // (?:/|/.*/)
            Token::RecursiveZeroOrMore => {
                self.byte(slash);
                self.alternation(2, |c, i| {
                    if i == 1 {
                        c.dot_star();
                        c.byte(slash);
                    }
                });
            }
            Token::Class { negated, ranges } => match class_bytes(*negated, ranges) {
                Some(set) => self.byte(set),
                None => self.bad = true,
            },
            Token::Alternates(branches) => {
                // NOTE: globset drops a branch whose expression is empty
                // (`a{,b}` is `a(?:b)`), and writes nothing for a group
                // left with none.
                let kept: Vec<&Vec<Token>> =
                    branches.iter().filter(|b| !writes_nothing(b)).collect();
                if !kept.is_empty() {
                    self.alternation(kept.len(), |c, i| c.tokens(kept[i]));
                }
            }
        }
    }
}

/// Whether globset writes no expression for `tokens`.
fn writes_nothing(tokens: &[Token]) -> bool {
    tokens.iter().all(|t| match t {
        Token::Alternates(bs) => bs.iter().all(|b| writes_nothing(b)),
        Token::Literal(_)
        | Token::Any
        | Token::ZeroOrMore
        | Token::RecursivePrefix
        | Token::RecursiveSuffix
        | Token::RecursiveZeroOrMore
        | Token::Class { .. } => false,
    })
}

/// The bytes a class matches, as globset's byte-level class for it
/// (`/` never: a separator is literal). NOTE: a non-ASCII character is
/// written as its UTF-8 bytes inside the class, each a member of its own
/// (a range's ends join its last byte to the other's first); `None` where
/// that range is reversed, which the regular expression rejects.
fn class_bytes(negated: bool, ranges: &[(char, char)]) -> Option<Bytes> {
    let mut filtered = Vec::new();
    let ranges = if negated {
        ranges
    } else {
        for &(s, e) in ranges {
            if s > '/' || e < '/' {
                filtered.push((s, e));
            } else if s == '/' && e == '/' {
            } else if s == '/' {
                filtered.push(('0', e));
            } else if e == '/' {
                filtered.push((s, '.'));
            } else {
                filtered.push((s, '.'));
                filtered.push(('0', e));
            }
        }
        if filtered.is_empty() {
            return Some(Bytes::NONE);
        }
        &filtered[..]
    };
    let mut set = Bytes::NONE;
    for &(s, e) in ranges {
        let (mut sb, mut eb) = ([0; 4], [0; 4]);
        let (sb, eb) = (
            s.encode_utf8(&mut sb).as_bytes(),
            e.encode_utf8(&mut eb).as_bytes(),
        );
        if s == e {
            sb.iter().for_each(|&b| set.add(b));
            continue;
        }
        let (lo, hi) = (sb[sb.len() - 1], eb[0]);
        if lo > hi {
            return None;
        }
        sb[..sb.len() - 1].iter().for_each(|&b| set.add(b));
        (lo..=hi).for_each(|b| set.add(b));
        eb[1..].iter().for_each(|&b| set.add(b));
    }
    if negated {
        set.add(b'/');
        set = set.not();
    }
    Some(set)
}

/// globset's glob parser (its `Parser`), on the options the ignore files
/// use.
struct Parser {
    chars: Vec<char>,
    pos: usize,
    prev: Option<char>,
    cur: Option<char>,
    alternates_stack: Vec<usize>,
    branches: Vec<Vec<Token>>,
    found_unclosed_class: bool,
    allow_unclosed_class: bool,
}

impl Parser {
    fn parse(glob: &str, allow_unclosed_class: bool) -> Result<Vec<Token>, GlobError> {
        let mut p = Parser {
            chars: glob.chars().collect(),
            pos: 0,
            prev: None,
            cur: None,
            alternates_stack: Vec::new(),
            branches: vec![Vec::new()],
            found_unclosed_class: false,
            allow_unclosed_class,
        };
        while let Some(c) = p.bump() {
            match c {
                '?' => p.push(Token::Any)?,
                '*' => p.star()?,
                '[' if !p.found_unclosed_class => p.class()?,
                '{' => p.push_alternate()?,
                '}' => p.pop_alternate()?,
                ',' if !p.alternates_stack.is_empty() => p.branches.push(Vec::new()),
                '\\' => match p.bump() {
                    None => return Err(GlobError::DanglingEscape),
                    Some(c) => p.push(Token::Literal(c))?,
                },
                c => p.push(Token::Literal(c))?,
            }
        }
        if p.branches.len() > 1 {
            return Err(GlobError::UnclosedAlternates);
        }
        Ok(p.branches.pop().unwrap_or_default())
    }

    fn bump(&mut self) -> Option<char> {
        self.prev = self.cur;
        self.cur = self.chars.get(self.pos).copied();
        if self.cur.is_some() {
            self.pos += 1;
        }
        self.cur
    }

    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).copied()
    }

    fn push(&mut self, t: Token) -> Result<(), GlobError> {
        self.branches
            .last_mut()
            .ok_or(GlobError::UnopenedAlternates)
            .map(|b| b.push(t))
    }

    fn push_alternate(&mut self) -> Result<(), GlobError> {
        if self.alternates_stack.len() >= 100 {
            return Err(GlobError::TooManyNestedAlternates);
        }
        self.alternates_stack.push(self.branches.len());
        self.branches.push(Vec::new());
        Ok(())
    }

    fn pop_alternate(&mut self) -> Result<(), GlobError> {
        let start = self
            .alternates_stack
            .pop()
            .ok_or(GlobError::UnopenedAlternates)?;
        let alts = Token::Alternates(self.branches.drain(start..).collect());
        self.push(alts)
    }

    fn star(&mut self) -> Result<(), GlobError> {
        let prev = self.prev;
        if self.peek() != Some('*') {
            return self.push(Token::ZeroOrMore);
        }
        self.bump();
        let have_tokens = !self
            .branches
            .last()
            .ok_or(GlobError::UnopenedAlternates)?
            .is_empty();
        if !have_tokens {
            if self.peek().is_some_and(|c| c != '/') {
                self.push(Token::ZeroOrMore)?;
                return self.push(Token::ZeroOrMore);
            }
            self.push(Token::RecursivePrefix)?;
            self.bump();
            return Ok(());
        }
        if prev != Some('/')
            && (self.branches.len() <= 1 || (prev != Some(',') && prev != Some('{')))
        {
            self.push(Token::ZeroOrMore)?;
            return self.push(Token::ZeroOrMore);
        }
        let is_suffix = match self.peek() {
            None => true,
            Some(',' | '}') if self.branches.len() >= 2 => true,
            Some('/') => {
                self.bump();
                false
            }
            Some(_) => {
                self.push(Token::ZeroOrMore)?;
                return self.push(Token::ZeroOrMore);
            }
        };
        let last = self
            .branches
            .last_mut()
            .and_then(Vec::pop)
            .ok_or(GlobError::UnopenedAlternates)?;
        match last {
            Token::RecursivePrefix => self.push(Token::RecursivePrefix),
            Token::RecursiveSuffix => self.push(Token::RecursiveSuffix),
            _ if is_suffix => self.push(Token::RecursiveSuffix),
            _ => self.push(Token::RecursiveZeroOrMore),
        }
    }

    fn class(&mut self) -> Result<(), GlobError> {
        let saved = (self.pos, self.prev, self.cur);
        let mut ranges: Vec<(char, char)> = Vec::new();
        let negated = matches!(self.peek(), Some('!' | '^'));
        if negated {
            self.bump();
        }
        let mut first = true;
        let mut in_range = false;
        loop {
            let Some(c) = self.bump() else {
                if !self.allow_unclosed_class {
                    return Err(GlobError::UnclosedClass);
                }
                (self.pos, self.prev, self.cur) = saved;
                self.found_unclosed_class = true;
                return self.push(Token::Literal('['));
            };
            match c {
                ']' if !first => break,
                ']' => ranges.push((']', ']')),
                '-' if first => ranges.push(('-', '-')),
                '-' if in_range => {
                    extend_range(&mut ranges, '-')?;
                    in_range = false;
                }
                '-' => in_range = true,
                '[' if !in_range && self.peek() == Some(':') => {
                    match self.posix_class() {
                        Some(rs) => ranges.extend_from_slice(rs),
                        None => ranges.push(('[', '[')),
                    }
                    in_range = false;
                }
                c if in_range => {
                    extend_range(&mut ranges, c)?;
                    in_range = false;
                }
                c => ranges.push((c, c)),
            }
            first = false;
        }
        if in_range {
            ranges.push(('-', '-'));
        }
        self.push(Token::Class { negated, ranges })
    }

    /// `[:name:]` after a `[` in a class.
    fn posix_class(&mut self) -> Option<&'static [(char, char)]> {
        let saved = (self.pos, self.prev, self.cur);
        self.bump();
        let mut name = String::new();
        loop {
            match self.bump() {
                Some(':') if self.peek() == Some(']') => {
                    self.bump();
                    return posix_ranges(&name);
                }
                Some(c) if c.is_ascii_lowercase() && name.len() < 8 => name.push(c),
                _ => {
                    (self.pos, self.prev, self.cur) = saved;
                    return None;
                }
            }
        }
    }
}

fn extend_range(ranges: &mut [(char, char)], end: char) -> Result<(), GlobError> {
    let Some(r) = ranges.last_mut() else {
        return Err(GlobError::UnclosedClass);
    };
    r.1 = end;
    if r.1 < r.0 {
        return Err(GlobError::InvalidRange(r.0, r.1));
    }
    Ok(())
}

fn posix_ranges(name: &str) -> Option<&'static [(char, char)]> {
    Some(match name {
        "alnum" => &[('0', '9'), ('A', 'Z'), ('a', 'z')],
        "alpha" => &[('A', 'Z'), ('a', 'z')],
        "blank" => &[('\t', '\t'), (' ', ' ')],
        "cntrl" => &[('\x00', '\x1f'), ('\x7f', '\x7f')],
        "digit" => &[('0', '9')],
        "graph" => &[('!', '~')],
        "lower" => &[('a', 'z')],
        "print" => &[(' ', '~')],
        "punct" => &[('!', '/'), (':', '@'), ('[', '`'), ('{', '~')],
        "space" => &[('\t', '\r'), (' ', ' ')],
        "upper" => &[('A', 'Z')],
        "xdigit" => &[('0', '9'), ('A', 'F'), ('a', 'f')],
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matches(glob: &str, path: &[u8]) -> bool {
        Glob::new(glob, true).unwrap().unwrap().is_match(path)
    }

    #[test]
    fn a_star_matches_within_one_component_only() {
        assert!(matches("a/*.toml", b"a/x.toml"));
        assert!(!matches("a/*.toml", b"a/b/x.toml"));
    }

    #[test]
    fn a_path_that_is_not_utf8_matches_by_its_bytes() {
        assert!(matches("**/caf*.toml", b"d/caf\xe9.toml"));
        assert!(matches("caf?.toml", b"caf\xe9.toml"));
    }

    #[test]
    fn a_double_star_alone_matches_everything_but_a_newline() {
        assert!(matches("**", b"a/b/c"));
        assert!(!matches("**", b"a\nb"));
    }

    #[test]
    fn a_middle_double_star_matches_zero_or_more_components() {
        for p in [&b"a/b"[..], b"a/x/b", b"a/x/y/b"] {
            assert!(matches("a/**/b", p));
        }
        assert!(!matches("a/**/b", b"ab"));
    }

    #[test]
    fn a_class_never_matches_a_slash() {
        assert!(!matches("a[-0]b", b"a/b"));
        assert!(!matches("a[!x]b", b"a/b"));
        assert!(matches("a[!x]b", b"a.b"));
    }

    #[test]
    fn an_unclosed_class_is_a_literal_in_an_ignore_file_and_an_error_elsewhere() {
        assert!(matches("a[b", b"a[b"));
        assert_eq!(
            Glob::new("a[b", false).unwrap_err(),
            GlobError::UnclosedClass
        );
    }

    #[test]
    fn an_alternate_group_matches_either_branch_and_drops_an_empty_one() {
        assert!(matches("{a,b}.toml", b"b.toml"));
        assert!(matches("x{,y}", b"xy"));
        assert!(!matches("x{,y}", b"x"));
    }

    #[test]
    fn a_reversed_range_and_a_trailing_backslash_are_errors() {
        assert_eq!(
            Glob::new("[z-a]", true).unwrap_err(),
            GlobError::InvalidRange('z', 'a')
        );
        assert_eq!(
            Glob::new("a\\", true).unwrap_err(),
            GlobError::DanglingEscape
        );
        assert_eq!(
            Glob::new("{a", true).unwrap_err(),
            GlobError::UnclosedAlternates
        );
        assert_eq!(
            Glob::new("a}", true).unwrap_err(),
            GlobError::UnopenedAlternates
        );
    }

    #[test]
    fn a_posix_class_matches_its_characters() {
        assert!(matches("[[:digit:]]x", b"7x"));
        assert!(!matches("[[:digit:]]x", b"ax"));
    }
}
