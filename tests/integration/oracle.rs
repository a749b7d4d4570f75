//! The engines as independent oracles: `tests/oracle/mujoco_oracle.py`
//! checks on a generated corpus that `check --engine mujoco` agrees with
//! MuJoCo's own compiler on every file, and that `export --to mjcf` loads
//! into MuJoCo with the report's mass, centre and principal moments;
//! `tests/oracle/engines_oracle.py` that `--engine drake` and `--engine
//! gazebo` agree with pydrake and gz-math on every link;
//! `tests/oracle/drake_body_oracle.py` that the whole robot agrees with
//! Drake's MultibodyPlant.
//!
//! It needs Python with the `mujoco` package: `MASSPROP_ORACLE_PYTHON` if
//! set, else `python3`. Without it the test says why on stderr and passes,
//! so that `cargo test` needs nothing beyond cargo.

use std::path::Path;
use std::process::Command;

/// The interpreter to try: `MASSPROP_ORACLE_PYTHON`, else `python3`.
pub(crate) fn python() -> String {
    std::env::var("MASSPROP_ORACLE_PYTHON").unwrap_or_else(|_| "python3".to_string())
}

#[test]
fn check_and_export_agree_with_mujocos_own_compiler() {
    let python = python();
    if let Some(why) = missing(&python, "mujoco") {
        eprintln!(
            "skipped: the MuJoCo oracle needs Python with the mujoco package; {why}. \
             Set MASSPROP_ORACLE_PYTHON to such an interpreter to run it."
        );
        return;
    }
    run_oracle(&python, "mujoco_oracle.py", "300", &[], "MuJoCo");
}

/// Run `tests/oracle/SCRIPT` with `python` on `cases` cases, `args` added,
/// and fail with its report unless it agrees on every one.
fn run_oracle(python: &str, script: &str, cases: &str, args: &[&str], engine: &str) {
    let script = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/oracle")
        .join(script);
    let out = Command::new(python)
        .arg(&script)
        .args([
            "--massprop",
            env!("CARGO_BIN_EXE_massprop"),
            "--cases",
            cases,
        ])
        .args(args)
        .output()
        .expect("the oracle script runs");
    assert!(
        out.status.success(),
        "the {engine} oracle found disagreements (exit {:?}):\n{}\n{}",
        out.status.code(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Why `python` cannot import `module`, or None when it can.
fn missing(python: &str, module: &str) -> Option<String> {
    match Command::new(python)
        .args(["-c", &format!("import {module}")])
        .output()
    {
        Err(e) => Some(format!("`{python}` does not run ({e})")),
        Ok(out) if !out.status.success() => {
            let stderr = String::from_utf8_lossy(&out.stderr);
            let why = stderr.trim().lines().last().unwrap_or("no message");
            Some(format!("`{python} -c \"import {module}\"` fails: {why}"))
        }
        Ok(_) => None,
    }
}

/// tests/oracle/engines_oracle.py for one engine, with the interpreter
/// that has its library: Drake's (pydrake, a pip wheel) from
/// `MASSPROP_DRAKE_PYTHON`, else `MASSPROP_ORACLE_PYTHON`, else `python3`;
/// gz-math's (Debian's python3-ignition-math, for the system Python) from
/// `MASSPROP_GZ_PYTHON`, else `/usr/bin/python3`. Skipped, saying why,
/// where the library is absent.
fn engine_oracle(engine: &str, python: String, module: &str) {
    if let Some(why) = missing(&python, module) {
        eprintln!(
            "skipped: the {engine} oracle needs Python with `{module}`; {why}. docs/robots.md says how to run it."
        );
        return;
    }
    run_oracle(
        &python,
        "engines_oracle.py",
        "300",
        &["--engine", engine],
        engine,
    );
}

#[test]
fn check_agrees_with_drakes_own_library() {
    let python = std::env::var("MASSPROP_DRAKE_PYTHON").unwrap_or_else(|_| python());
    engine_oracle("drake", python, "pydrake.multibody.tree");
}

#[test]
fn check_agrees_with_gz_maths_own_library() {
    let python =
        std::env::var("MASSPROP_GZ_PYTHON").unwrap_or_else(|_| "/usr/bin/python3".to_string());
    engine_oracle("gazebo", python, "ignition.math");
}

/// tests/oracle/drake_body_oracle.py: the whole robot (mass, centre, inertia
/// about the centre) against Drake's MultibodyPlant at random
/// configurations, on every robot file and generated SDFormat models, with
/// Drake's interpreter (as `check_agrees_with_drakes_own_library`). Four
/// configurations per model here; .ci/run runs forty.
#[test]
fn the_whole_robot_agrees_with_drakes_multibody_plant() {
    let python = std::env::var("MASSPROP_DRAKE_PYTHON").unwrap_or_else(|_| python());
    oracle_or_skip(
        &python,
        "pydrake.multibody.plant",
        "drake_body_oracle.py",
        "4",
        "Drake whole-body",
    );
}

/// `tests/oracle/SCRIPT` on `cases` cases, run by `python` (from
/// [`python`], or an engine's own variable) where it can import `module`;
/// else skipped, saying why: how every oracle test calls its script.
pub(crate) fn oracle_or_skip(python: &str, module: &str, script: &str, cases: &str, engine: &str) {
    if let Some(why) = missing(python, module) {
        eprintln!(
            "skipped: the {engine} oracle needs Python with `{module}`; {why}. \
             Set MASSPROP_ORACLE_PYTHON (MASSPROP_DRAKE_PYTHON for Drake) to such an interpreter to run it."
        );
        return;
    }
    run_oracle(python, script, cases, &[], engine);
}
