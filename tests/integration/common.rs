//! Helpers shared by the integration tests.

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Run the built `massprop` binary.
pub fn massprop(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(args)
        .output()
        .expect("the massprop binary runs")
}

/// Run `massprop` with `input` on standard input.
pub fn massprop_stdin(args: &[&str], input: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the massprop binary runs");
    child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(input.as_bytes())
        .expect("stdin accepts the input");
    child.wait_with_output().expect("massprop finishes")
}
