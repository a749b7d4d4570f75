//! `massprop completions SHELL` and `massprop man` (issue 14, item 4): made
//! from the command line's own definition, so every subcommand and flag is
//! in them; the scripts are checked by the shells themselves where they are
//! installed, the page by `man` where it is.

use crate::common::massprop;
use clap::CommandFactory;

/// Every subcommand and every long flag of the command line.
fn every_name() -> Vec<String> {
    let command = massprop::cli::Cli::command();
    let mut names = Vec::new();
    for sub in command.get_subcommands() {
        names.push(sub.get_name().to_string());
        for arg in sub.get_arguments() {
            if let Some(long) = arg.get_long() {
                names.push(format!("--{long}"));
            }
        }
    }
    names
}

fn text(args: &[&str]) -> String {
    let out = massprop(args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty(), "{args:?}");
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// Run `shell` with `flags` on `script` (a file) if it is installed: its
/// own syntax check.
fn shell_accepts(shell: &str, flags: &[&str], script: &str) {
    let dir = crate::common::scratch("shell", shell);
    let path = dir.join("completion");
    std::fs::write(&path, script).unwrap();
    match std::process::Command::new(shell)
        .args(flags)
        .arg(&path)
        .output()
    {
        Ok(out) => assert!(
            out.status.success(),
            "{shell} rejects its completion script: {}",
            String::from_utf8_lossy(&out.stderr)
        ),
        Err(_) => {
            eprintln!("{shell} is not installed: its completion script's syntax is not checked")
        }
    }
}

#[test]
fn completions_cover_every_subcommand_and_flag_in_every_shell() {
    for shell in ["bash", "zsh", "fish", "powershell", "elvish"] {
        let script = text(&["completions", shell]);
        for name in every_name() {
            // Each must offer every subcommand and flag; fish names a long
            // flag `-l NAME`.
            let spelt = match name.strip_prefix("--") {
                Some(long) if shell == "fish" => format!("-l {long}"),
                _ => name.clone(),
            };
            assert!(script.contains(&spelt), "{shell}: no {spelt}");
        }
    }
    shell_accepts("bash", &["-n"], &text(&["completions", "bash"]));
    shell_accepts("zsh", &["-n"], &text(&["completions", "zsh"]));
    shell_accepts("fish", &["--no-execute"], &text(&["completions", "fish"]));
}

#[test]
fn an_unknown_shell_is_refused_with_the_ones_known() {
    let out = massprop(&["completions", "tcsh"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("bash") && stderr.contains("zsh"),
        "{stderr}"
    );
}

#[test]
fn the_man_page_is_roff_with_every_subcommand_and_flag() {
    let page = text(&["man"]);
    assert!(
        page.contains(".TH massprop 1"),
        "{}",
        &page[..200.min(page.len())]
    );
    for name in every_name() {
        // roff escapes a hyphen as \-.
        assert!(page.contains(&name.replace('-', "\\-")), "no {name}");
    }
    // `man` renders it, where it is installed.
    let dir = crate::common::scratch("shell", "man");
    let path = dir.join("massprop.1");
    std::fs::write(&path, &page).unwrap();
    match std::process::Command::new("man")
        .arg("-l")
        .arg(&path)
        .env("MANWIDTH", "80")
        .output()
    {
        Ok(out) if out.status.success() => {
            let shown = String::from_utf8_lossy(&out.stdout);
            assert!(
                shown.contains("SYNOPSIS") && shown.contains("--rtol"),
                "{shown}"
            );
        }
        _ => eprintln!("man is not installed: the page is not rendered"),
    }
}

/// Flags as people type them (issue 14, item 8): `--tol 1%`, a vector in
/// the file's brackets, ω in Hz (revolutions per second).
#[test]
fn flags_take_percentages_brackets_and_hertz() {
    let json = |args: &[&str]| -> serde_json::Value { serde_json::from_str(&text(args)).unwrap() };
    let f = "shapes/flywheel.toml";
    let v = json(&["diff", f, f, "--tol", "1%", "--format", "json"]);
    assert_eq!(v["tolerance"], 0.01);
    let v = json(&["diff", f, f, "--tol", "0.5 %", "--format", "json"]);
    assert_eq!(v["tolerance"], 0.005);
    let a = json(&[
        "report",
        f,
        "--format",
        "json",
        "--about",
        "[0, 0, 10]",
        "--omega",
        "0,0,50 Hz",
    ]);
    let b = json(&[
        "report",
        f,
        "--format",
        "json",
        "--about",
        "0,0,10",
        "--omega",
        "0,0,50 rev/s",
    ]);
    assert_eq!(a["reference_point"], b["reference_point"]);
    assert_eq!(a["omega"], b["omega"]);
    assert_eq!(
        a["omega"][2].as_f64().unwrap(),
        100.0 * std::f64::consts::PI
    );
    let out = massprop(&["diff", f, f, "--tol", "one percent"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("such as 1%"));
}

/// Help stands alone (issue 14, item 6): no subcommand's `--help` sends an
/// installed user to a file of the source tree; the man page carries the
/// JSON contract's keys (from docs/json.md, its one statement).
#[test]
fn help_names_no_source_file_and_the_man_page_carries_the_json_keys() {
    let command = massprop::cli::Cli::command();
    let mut subs: Vec<String> = command
        .get_subcommands()
        .map(|s| s.get_name().to_string())
        .collect();
    subs.push(String::new());
    for sub in subs {
        let args: Vec<&str> = if sub.is_empty() {
            vec!["--help"]
        } else {
            vec![&sub, "--help"]
        };
        let help = text(&args);
        assert!(
            !help.contains("docs/") && !help.contains(".md"),
            "{sub} --help names a source file:\n{help}"
        );
    }
    let page = text(&["man"]);
    assert!(page.contains(".SH \"JSON OUTPUT\""));
    let doc = std::fs::read_to_string("docs/json.md").unwrap();
    for row in doc.lines().filter(|l| l.starts_with("| `")) {
        let key = row.split('`').nth(1).unwrap();
        assert!(
            page.contains(&format!("\\fB{}\\fR", key.replace('-', "\\-"))),
            "no {key}"
        );
    }
}
