//! Part files from pipes: the includes of a file read from standard input
//! or a process substitution resolve against `--base-dir`, and without it
//! are refused (never silently against the working directory).

use crate::common::{massprop_stdin, scratch};
use std::path::{Path, PathBuf};
use std::process::Command;

const LEAF: &str = "[[part]]\nshape = \"box\"\nmass = 2\nsize = [1, 2, 3]\ncenter = [1, 0, 0]\n";
const TOP: &str = "[[part]]\nname = \"leaf\"\ninclude = \"sub/leaf.toml\"\norigin = [0, 0, 5]\n\n[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n";

/// `base/top.toml` including `base/sub/leaf.toml`.
fn tree(name: &str) -> PathBuf {
    let root = scratch("pipes", name);
    let base = root.join("base");
    std::fs::create_dir_all(base.join("sub")).unwrap();
    std::fs::write(base.join("sub/leaf.toml"), LEAF).unwrap();
    std::fs::write(base.join("top.toml"), TOP).unwrap();
    base
}

fn json(out: &std::process::Output) -> serde_json::Value {
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    v.as_object_mut().unwrap().remove("source");
    v
}

#[test]
fn stdin_includes_resolve_against_base_dir_and_are_refused_without_it() {
    let base = tree("stdin");
    let b = base.to_str().unwrap();
    let refused = massprop_stdin(&["report", "-"], TOP);
    assert_eq!(refused.status.code(), Some(2));
    assert!(refused.stdout.is_empty());
    let stderr = String::from_utf8(refused.stderr).unwrap();
    assert!(
        stderr.contains("`include` in a file read from standard input")
            && stderr.contains("--base-dir DIR"),
        "{stderr}"
    );
    let piped = massprop_stdin(&["report", "-", "--format", "json", "--base-dir", b], TOP);
    let file = crate::common::massprop(&[
        "report",
        base.join("top.toml").to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert_eq!(json(&piped), json(&file));
    assert_eq!(json(&file)["mass"], 3.0);
}

/// A file on disk keeps its own directory: `--base-dir` is for pipes.
#[test]
fn a_file_on_disk_ignores_base_dir() {
    let base = tree("on-disk");
    let elsewhere = base.parent().unwrap().join("elsewhere");
    std::fs::create_dir_all(&elsewhere).unwrap();
    let out = crate::common::massprop(&[
        "report",
        base.join("top.toml").to_str().unwrap(),
        "--base-dir",
        elsewhere.to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert_eq!(json(&out)["mass"], 3.0);
}

/// The base directory's tree is the piped file's: an include out of it is
/// refused as for a file on disk (run from that directory, so that the
/// working directory allows nothing more).
#[test]
fn a_piped_files_includes_stay_inside_the_base_dir() {
    let base = tree("confined");
    std::fs::write(base.parent().unwrap().join("outside.toml"), LEAF).unwrap();
    let top = "[[part]]\nname = \"o\"\ninclude = \"../outside.toml\"\n";
    let mut child = Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(["report", "-", "--base-dir", "."])
        .current_dir(&base)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write;
    child
        .stdin
        .take()
        .unwrap()
        .write_all(top.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.contains("is outside the directory"), "{stderr}");
}

/// The recipe of docs/diff.md: the old version from a process
/// substitution, its includes from the working tree.
#[test]
fn diff_of_a_process_substitution_with_base_dir() {
    let base = tree("diff");
    if !Path::new("/bin/bash").exists() {
        eprintln!("skipped: no /bin/bash for a process substitution");
        return;
    }
    let run = |extra: &str| {
        Command::new("/bin/bash")
            .arg("-c")
            .arg(format!(
                "\"$MASSPROP\" diff <(cat top.toml) top.toml {extra}"
            ))
            .env("MASSPROP", env!("CARGO_BIN_EXE_massprop"))
            .current_dir(&base)
            .output()
            .unwrap()
    };
    let out = run("--base-dir .");
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("no change beyond the tolerance"),
        "{stdout}"
    );
    let out = run("");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("read from a pipe"));
}
