//! `--color auto|always|never` and `NO_COLOR`, as cargo and ripgrep take
//! them: colour only where asked for or on a terminal, and the coloured
//! text, its escape sequences taken out, byte for byte the plain text.
//! (The tests' pipes are never terminals: `auto` is the plain case here;
//! the unit tests of `cli::terminal` cover a terminal's answer.)

use crate::common::scratch;
use std::process::{Command, Output};

const ESC: u8 = 0x1b;

/// `massprop ARGS…` with `env` set and every colour variable of the
/// caller's environment removed, so the test sees only its own.
fn run(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_massprop"));
    for v in ["NO_COLOR", "CLICOLOR", "CLICOLOR_FORCE", "TERM"] {
        c.env_remove(v);
    }
    c.args(args).envs(env.iter().copied());
    c.output().expect("the massprop binary runs")
}

fn has_escapes(bytes: &[u8]) -> bool {
    bytes.contains(&ESC)
}

/// The text with every ANSI escape sequence taken out: anstream's own
/// stripping, as what a terminal shows.
fn stripped(bytes: &[u8]) -> String {
    anstream::adapter::strip_str(std::str::from_utf8(bytes).unwrap()).to_string()
}

/// Files that make each kind of message: a diagnostic with place, source
/// line, carets, label and help; an accuracy warning; a failed
/// expectation (check's `error:` on standard output).
struct Files {
    bad: String,
    needle: String,
    failing: String,
}

fn files(name: &str) -> Files {
    let dir = scratch("colour", name);
    let write = |file: &str, text: &str| {
        let p = dir.join(file);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    Files {
        bad: write(
            "bad.toml",
            "[[part]]\nshape = \"box\"\nmass = 1\nsizee = [1, 1, 1]\ncenter = [0, 0, 0]\n",
        ),
        // A turned 1e-9-slender needle: its smallest moment misses the
        // default --rtol even in extended (tests/integration/auto.rs).
        needle: write(
            "needle.toml",
            "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1e-9, 1e-9]\ncenter = [0, 0, 0]\nrotation = { axis = [1, 2, 3], degrees = 30 }\n",
        ),
        failing: write(
            "failing.toml",
            "[[part]]\nshape = \"point\"\nmass = 12\ncenter = [0, 0, 0]\n\n[expect]\nmass = { value = 12.5, tol = \"0.5%\" }\n",
        ),
    }
}

/// Every kind of coloured output: (what, arguments, which stream).
fn cases(f: &Files) -> Vec<(&'static str, Vec<String>, bool)> {
    let v = |args: &[&str]| args.iter().map(|a| a.to_string()).collect::<Vec<_>>();
    vec![
        ("a diagnostic", v(&["report", &f.bad]), false),
        ("a warning", v(&["report", &f.needle]), false),
        ("check's errors", v(&["check", &f.failing]), true),
        ("check's invalid file", v(&["check", &f.bad]), false),
        ("a usage error", v(&["report", "--nope"]), false),
    ]
}

/// The stream the case colours: standard output or error.
fn stream(out: &Output, stdout: bool) -> &[u8] {
    if stdout { &out.stdout } else { &out.stderr }
}

#[test]
fn always_colours_and_the_colours_stripped_are_never_byte_for_byte() {
    let f = files("always");
    for (what, args, on_stdout) in cases(&f) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let mut always = vec!["--color", "always"];
        always.extend(&args);
        let mut never = vec!["--color=never"];
        never.extend(&args);
        let (always, never) = (run(&always, &[]), run(&never, &[]));
        assert!(
            has_escapes(stream(&always, on_stdout)),
            "{what}: no colour with --color always: {}",
            String::from_utf8_lossy(stream(&always, on_stdout))
        );
        assert!(
            !has_escapes(&never.stdout) && !has_escapes(&never.stderr),
            "{what}"
        );
        assert_eq!(
            stripped(&always.stdout),
            String::from_utf8(never.stdout).unwrap(),
            "{what}"
        );
        assert_eq!(
            stripped(&always.stderr),
            String::from_utf8(never.stderr).unwrap(),
            "{what}"
        );
        assert_eq!(always.status.code(), never.status.code(), "{what}");
    }
}

#[test]
fn always_colours_the_level_words_as_cargo_does() {
    let f = files("words");
    let red = "\u{1b}[1m\u{1b}[31merror\u{1b}[0m: ";
    let yellow = "\u{1b}[1m\u{1b}[33mwarning\u{1b}[0m: ";
    let out = run(&["report", "--color", "always", &f.bad], &[]);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.contains(&format!("bad.toml:4:1: {red}")),
        "{stderr:?}"
    );
    let out = run(&["report", "--color", "always", &f.needle], &[]);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.starts_with(yellow), "{stderr:?}");
    // The report itself has no colour to give: the same as uncoloured.
    let plain = run(&["report", &f.needle], &[]);
    assert_eq!(out.stdout, plain.stdout);
    let out = run(&["check", "--color", "always", &f.failing], &[]);
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains(&format!(":7:8: {red}mass 12 kg")),
        "{stdout:?}"
    );
}

#[test]
fn auto_gives_pipes_no_colour() {
    let f = files("auto");
    for (what, args, _) in cases(&f) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let default = run(&args, &[]);
        let mut auto = vec!["--color", "auto"];
        auto.extend(&args);
        let auto = run(&auto, &[]);
        for out in [&default, &auto] {
            assert!(
                !has_escapes(&out.stdout) && !has_escapes(&out.stderr),
                "{what}"
            );
        }
        assert_eq!(default.stderr, auto.stderr, "{what}");
    }
}

#[test]
fn no_color_turns_auto_off_and_clicolor_force_on_but_never_is_never() {
    let f = files("env");
    for (what, args, on_stdout) in cases(&f) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        // CLICOLOR_FORCE colours pipes in auto…
        let forced = run(&args, &[("CLICOLOR_FORCE", "1")]);
        assert!(has_escapes(stream(&forced, on_stdout)), "{what}");
        // …but not with NO_COLOR (which wins) or --color never.
        let both = run(&args, &[("CLICOLOR_FORCE", "1"), ("NO_COLOR", "1")]);
        let mut never = vec!["--color", "never"];
        never.extend(&args);
        let never = run(&never, &[("CLICOLOR_FORCE", "1")]);
        for out in [&both, &never] {
            assert!(
                !has_escapes(&out.stdout) && !has_escapes(&out.stderr),
                "{what}"
            );
        }
        // --color always wins over NO_COLOR.
        let mut always = vec!["--color", "always"];
        always.extend(&args);
        let always = run(&always, &[("NO_COLOR", "1")]);
        assert!(has_escapes(stream(&always, on_stdout)), "{what}");
    }
}

#[test]
fn help_follows_color() {
    let always = run(&["--color", "always", "report", "--help"], &[]);
    assert!(has_escapes(&always.stdout));
    let never = run(
        &["report", "--help", "--color=never"],
        &[("CLICOLOR_FORCE", "1")],
    );
    assert!(!has_escapes(&never.stdout));
    assert_eq!(
        stripped(&always.stdout),
        String::from_utf8(never.stdout).unwrap()
    );
}

#[test]
fn an_output_file_is_never_coloured() {
    let f = files("file");
    let dir = scratch("colour", "file-out");
    let out_path = dir.join("out.txt");
    let out = run(
        &[
            "--color",
            "always",
            "check",
            &f.failing,
            "-o",
            out_path.to_str().unwrap(),
        ],
        &[],
    );
    assert_eq!(out.status.code(), Some(1));
    let written = std::fs::read(&out_path).unwrap();
    assert!(!has_escapes(&written));
    assert!(
        String::from_utf8(written)
            .unwrap()
            .contains("error: mass 12 kg")
    );
}

// Width: tables split to fit `--width` (or a terminal's width), never a
// number cut, never a column hidden; pipes and files get them whole.

/// A table as its rows of cells (the header first).
type Table = Vec<Vec<String>>;

/// The cells of a table line, `│ a ┆ b │`.
fn cells(line: &str) -> Vec<String> {
    let inner = line.trim_start_matches('│').trim_end_matches('│');
    inner.split('┆').map(|c| c.trim().to_string()).collect()
}

/// Every table of an output, a table split into parts joined back (each
/// part's repeated leading columns once), and the number of notes of a
/// split.
fn tables(text: &str) -> (Vec<Table>, usize) {
    let lines: Vec<&str> = text.lines().collect();
    // Groups of adjacent parts.
    let mut groups: Vec<Vec<Table>> = Vec::new();
    let mut notes = 0;
    let mut i = 0;
    let mut adjacent = false;
    while i < lines.len() {
        let line = lines[i];
        if line.starts_with('┌') {
            let mut part = Vec::new();
            i += 1;
            while !lines[i].starts_with('└') {
                if lines[i].starts_with('│') {
                    part.push(cells(lines[i]));
                }
                i += 1;
            }
            match groups.last_mut() {
                Some(g) if adjacent => g.push(part),
                _ => groups.push(vec![part]),
            }
            adjacent = true;
        } else {
            if let Some(rest) = line.strip_prefix("note: table split into ") {
                let k: usize = rest.split(' ').next().unwrap().parse().unwrap();
                let g = groups.last().expect("a note follows a table");
                assert!(adjacent, "the note follows its table's last part");
                assert_eq!(g.len(), k, "the note counts the parts");
                notes += 1;
            }
            adjacent = false;
        }
        i += 1;
    }
    let joined = groups
        .into_iter()
        .map(|parts| {
            let first = &parts[0];
            // The leading columns every part repeats: those the parts'
            // headers begin with alike.
            let keys = parts.get(1).map_or(0, |second| {
                first[0]
                    .iter()
                    .zip(&second[0])
                    .take_while(|(a, b)| a == b)
                    .count()
            });
            let mut table = first.clone();
            for part in &parts[1..] {
                assert_eq!(part.len(), first.len(), "every part has every row");
                for (row, more) in table.iter_mut().zip(part) {
                    assert_eq!(&more[..keys], &row[..keys], "the labels repeat");
                    row.extend(more[keys..].iter().cloned());
                }
            }
            table
        })
        .collect();
    (joined, notes)
}

fn stdout(args: &[&str]) -> String {
    let out = run(args, &[]);
    assert_eq!(out.status.code(), Some(0), "{args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The widest table line (a prose line, such as the short report's last,
/// is not fitted).
fn widest(text: &str) -> usize {
    use unicode_width::UnicodeWidthStr;
    text.lines()
        .filter(|l| l.starts_with(['┌', '│', '╞', '└']))
        .map(UnicodeWidthStr::width)
        .max()
        .unwrap_or(0)
}

/// The report, short and `--full`, of each example.
fn report_args() -> Vec<Vec<&'static str>> {
    EXAMPLES
        .iter()
        .flat_map(|f| [vec!["report", f], vec!["report", "--full", f]])
        .collect()
}

const EXAMPLES: &[&str] = &[
    "shapes/quadcopter.toml",
    "shapes/robot-arm.toml",
    "shapes/motor-bracket.toml",
    "shapes/bent-plate.toml",
];

#[test]
fn a_narrow_width_splits_tables_into_parts_that_hold_every_value_whole() {
    for args in report_args() {
        let file = args.join(" ");
        let whole = stdout(&args);
        let (full, notes) = tables(&whole);
        assert_eq!(notes, 0, "{file}");
        for width in [100, 80, 60, 40, 1] {
            let w = width.to_string();
            let narrow = stdout(&[&args[..], &["--width", &w]].concat());
            let (split, notes) = tables(&narrow);
            // Each value in its row and column as the whole table has it:
            // none cut, none missing, none moved.
            assert_eq!(split, full, "{file} at {width} columns:\n{narrow}");
            if widest(&whole) > width {
                assert!(notes > 0, "{file} at {width}: no table split");
            }
            // Every table line fits, down to where a part's labels and a
            // single column do not.
            if width >= 60 {
                for line in narrow.lines().filter(|l| l.starts_with(['┌', '│', '└'])) {
                    use unicode_width::UnicodeWidthStr;
                    assert!(line.width() <= width, "{file} at {width}: {line}");
                }
            }
        }
    }
}

#[test]
fn a_width_the_tables_fit_in_changes_nothing() {
    for args in report_args() {
        let file = args.join(" ");
        let whole = stdout(&args);
        let w = widest(&whole);
        assert_eq!(
            stdout(&[&args[..], &["--width", &w.to_string()]].concat()),
            whole
        );
        assert_eq!(stdout(&[&["--width", "0"][..], &args[..]].concat()), whole);
        // A column less, and the widest table splits.
        let less = stdout(&[&args[..], &["--width", &(w - 1).to_string()]].concat());
        assert_ne!(less, whole, "{file}");
        assert!(less.contains("note: table split into 2 to fit"), "{file}");
    }
}

#[test]
fn diffs_quantities_split_as_the_reports_tables() {
    let (old, new) = ("shapes/quadcopter.toml", "shapes/robot-arm.toml");
    let run_diff = |extra: &[&str]| {
        let mut args = vec!["diff", old, new];
        args.extend(extra);
        let out = run(&args, &[]);
        assert_eq!(out.status.code(), Some(1));
        String::from_utf8(out.stdout).unwrap()
    };
    let whole = run_diff(&[]);
    let narrow = run_diff(&["--width", "50"]);
    assert!(narrow.contains("note: table split into"), "{narrow}");
    // The parts table (text, not split) aside, every value kept.
    let (full, _) = tables(&whole);
    let (split, _) = tables(&narrow);
    assert_eq!(split[0], full[0], "{narrow}");
}

#[test]
fn an_output_file_is_whole_unless_a_width_is_asked_for() {
    let dir = scratch("colour", "width-file");
    let f = "shapes/quadcopter.toml";
    let o = dir.join("report.txt");
    let o = o.to_str().unwrap();
    stdout(&["report", f, "-o", o]);
    assert_eq!(std::fs::read_to_string(o).unwrap(), stdout(&["report", f]));
    stdout(&["report", "--width", "80", f, "-o", o]);
    assert_eq!(
        std::fs::read_to_string(o).unwrap(),
        stdout(&["report", "--width", "80", f])
    );
}
