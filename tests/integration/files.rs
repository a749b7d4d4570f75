//! No file is ever damaged: `-o` never writes onto a file the run reads,
//! however it is named; outputs and blessed files are replaced through
//! temporary files with unpredictable names; `check --bless` keeps each
//! line's ending, hard links and ownership, and serialises concurrent
//! blesses of one file.

use crate::common::{massprop, scratch};
use std::path::Path;
use std::process::{Command, Stdio};

const WHEEL: &str = "name = \"wheel\"\n[[part]]\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 0]\n";
const CART: &str = "[[part]]\nshape = \"point\"\nmass = 5\ncenter = [0, 0, 1]\n\
                    [[part]]\ninclude = \"wheel.toml\"\norigin = [1, 0, 0]\n";

fn s(p: &Path) -> &str {
    p.to_str().expect("scratch paths are UTF-8")
}

/// A run refused for `-o` onto one of its inputs: status 2, nothing on
/// stdout, the reason on stderr.
fn assert_refused(out: &std::process::Output, args: &[&str]) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "{args:?}");
    assert!(
        stderr.contains("the report would replace it"),
        "{args:?}: {stderr}"
    );
}

/// `-o` onto a hard link to the part file, to an included file, or to a file
/// `check DIR` finds is refused: the same file under another name (paths
/// alone did not tell them apart).
#[test]
fn output_onto_a_hard_link_to_an_input_is_refused() {
    let dir = scratch("files", "hard-link-output");
    let parts = dir.join("parts");
    std::fs::create_dir_all(&parts).unwrap();
    let (cart, wheel) = (parts.join("cart.toml"), parts.join("wheel.toml"));
    std::fs::write(&cart, CART).unwrap();
    std::fs::write(&wheel, WHEEL).unwrap();
    // Outside `parts`, so that `check parts` does not find the links.
    let (to_cart, to_wheel) = (dir.join("cart.out"), dir.join("wheel.out"));
    std::fs::hard_link(&cart, &to_cart).unwrap();
    std::fs::hard_link(&wheel, &to_wheel).unwrap();
    for args in [
        vec!["report", s(&cart), "-o", s(&to_cart)],
        vec!["report", s(&cart), "-o", s(&to_wheel)],
        vec!["check", s(&cart), "-o", s(&to_cart)],
        vec!["check", s(&cart), "-o", s(&to_wheel)],
        vec!["check", s(&parts), "-o", s(&to_wheel)],
        vec!["check", s(&parts), "-o", s(&to_cart)],
        vec!["diff", s(&wheel), s(&cart), "-o", s(&to_wheel)],
    ] {
        assert_refused(&massprop(&args), &args);
        assert_eq!(std::fs::read_to_string(&cart).unwrap(), CART, "{args:?}");
        assert_eq!(std::fs::read_to_string(&wheel).unwrap(), WHEEL, "{args:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `massprop report - -o x.toml < x.toml` is refused: the file behind
/// standard input is an input like any other (and so is a hard link to it).
#[test]
fn output_onto_the_file_behind_standard_input_is_refused() {
    let dir = scratch("files", "stdin-output");
    let part = dir.join("wheel.toml");
    std::fs::write(&part, WHEEL).unwrap();
    let link = dir.join("link.toml");
    std::fs::hard_link(&part, &link).unwrap();
    for (command, output) in [("report", &part), ("check", &part), ("report", &link)] {
        let args = [command, "-", "-o", s(output)];
        let out = Command::new(env!("CARGO_BIN_EXE_massprop"))
            .args(args)
            .stdin(std::fs::File::open(&part).unwrap())
            .output()
            .unwrap();
        assert_refused(&out, &args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains("the file on standard input"), "{stderr}");
        assert_eq!(std::fs::read_to_string(&part).unwrap(), WHEEL);
    }
    // Another file on standard input: written as usual.
    let other = dir.join("other.toml");
    std::fs::write(&other, WHEEL).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(["report", "-", "-o", s(&dir.join("report.txt"))])
        .stdin(std::fs::File::open(&other).unwrap())
        .stdout(Stdio::piped())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(
        std::fs::read_to_string(dir.join("report.txt"))
            .unwrap()
            .starts_with("wheel")
    );
    std::fs::remove_dir_all(&dir).ok();
}
