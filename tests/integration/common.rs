//! Helpers shared by the integration tests.

use std::io::Write;
use std::path::PathBuf;
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
    // A program that refuses its arguments before reading its input
    // (`check - -`) may exit before the write ends: a broken pipe then is
    // its answer, not the test's failure; the caller checks the output.
    match child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(input.as_bytes())
    {
        Ok(()) => {}
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {}
        Err(e) => panic!("stdin accepts the input: {e}"),
    }
    child.wait_with_output().expect("massprop finishes")
}

/// A scratch directory for one test, under cargo's per-target temporary
/// directory, emptied first: `group/name`.
pub fn scratch(group: &str, name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(group)
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `files` (name, text) written into the scratch directory
/// `group/name`; the path of the last, the one to run.
pub fn scratch_files(group: &str, name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = scratch(group, name);
    let mut last = dir.clone();
    for (file, text) in files {
        last = dir.join(file);
        std::fs::write(&last, text).unwrap();
    }
    last
}

/// A run refused for `-o` onto one of its inputs: status 2, nothing on
/// stdout, the reason on stderr.
pub fn assert_refused(out: &std::process::Output, args: &[&str]) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "{args:?}");
    assert!(
        stderr.contains("the report would replace it"),
        "{args:?}: {stderr}"
    );
}

/// `massprop report --format json ARGS… FILE` on `text`, in process: the
/// JSON and what went to standard error.
pub fn report_json(text: &str, args: &[&str]) -> (serde_json::Value, String) {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static COUNT: AtomicUsize = AtomicUsize::new(0);
    let path = std::env::temp_dir().join(format!(
        "massprop-report-{}-{}.toml",
        std::process::id(),
        COUNT.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::write(&path, text).unwrap();
    let out = std::panic::catch_unwind(|| report_json_file(&path, args));
    std::fs::remove_file(&path).ok();
    out.unwrap_or_else(|_| panic!("for:\n{text}"))
}

/// `massprop report --format json ARGS… PATH`, in process: the JSON and
/// what went to standard error.
pub fn report_json_file(path: &std::path::Path, args: &[&str]) -> (serde_json::Value, String) {
    let mut argv = vec!["massprop", "report", "--format", "json"];
    argv.extend(args);
    argv.push(path.to_str().expect("a UTF-8 path"));
    let cli = <massprop::cli::Cli as clap::Parser>::try_parse_from(argv).unwrap();
    let out = massprop::run(&cli).unwrap_or_else(|d| panic!("{d}"));
    let v = serde_json::from_str(&out.stdout.text()).expect("stdout is JSON");
    (v, out.stderr)
}

/// The example part files, `shapes/*.toml`, sorted (shapes/robots/ holds
/// robot descriptions, checked in robots.rs).
pub fn example_part_files() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir("shapes")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    files
}

/// `massprop ARGS`, killed and failed if it runs past a minute: a hang
/// guard, the only clock these tests keep (their times are
/// docs/performance.md's).
pub fn within_a_minute(args: &[&str]) -> std::process::Output {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > std::time::Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("massprop {args:?} ran past a minute: a hang");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// Mass, centre of mass and inertia about it, from a report, and the
/// report's JSON.
pub fn figures(text: &str, args: &[&str]) -> (f64, [f64; 3], [[f64; 3]; 3], serde_json::Value) {
    let (v, _) = report_json(text, args);
    let m = v["mass"].as_f64().expect("mass");
    let c = std::array::from_fn(|i| v["center_of_mass"][i].as_f64().expect("com"));
    let i = std::array::from_fn(|a| {
        std::array::from_fn(|b| v["inertia_com"][a][b].as_f64().expect("inertia"))
    });
    (m, c, i, v)
}

/// The two files describe the same body, to `tol` relative to each
/// quantity's scale (mass; the largest coordinate and the body's size for
/// the centre; the largest entry for the tensor).
pub fn same_body(a: &str, b: &str, tol: f64) {
    let (ma, ca, ia, _) = figures(a, &[]);
    let (mb, cb, ib, _) = figures(b, &[]);
    assert!((ma - mb).abs() <= tol * mb, "mass {ma} vs {mb}\n{a}\n{b}");
    let big = ib.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let size = (big / mb).sqrt();
    for k in 0..3 {
        assert!(
            (ca[k] - cb[k]).abs() <= tol * (cb[k].abs() + size),
            "centre {ca:?} vs {cb:?}\n{a}\n{b}"
        );
        for l in 0..3 {
            assert!(
                (ia[k][l] - ib[k][l]).abs() <= tol * big,
                "inertia {ia:?} vs {ib:?}\n{a}\n{b}"
            );
        }
    }
}

/// `massprop report PATH --format json ARGS` as a user runs it, which must
/// succeed: its JSON.
pub fn report_cli(path: &std::path::Path, args: &[&str]) -> serde_json::Value {
    let mut argv = vec!["report", path.to_str().unwrap(), "--format", "json"];
    argv.extend(args);
    let out = massprop(&argv);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Every number of a JSON number or (nested) array, in order.
pub fn numbers(v: &serde_json::Value) -> Vec<f64> {
    match v {
        serde_json::Value::Number(n) => vec![n.as_f64().unwrap()],
        serde_json::Value::Array(a) => a.iter().flat_map(numbers).collect(),
        _ => panic!("{v}"),
    }
}

/// A report's mass, centre of mass and inertia about it, flattened.
pub fn figures_flat(v: &serde_json::Value) -> Vec<f64> {
    let mut out = numbers(&v["mass"]);
    out.extend(numbers(&v["center_of_mass"]));
    out.extend(numbers(&v["inertia_com"]));
    out
}

/// `a` and `b` agree to `rtol` of their largest entry.
pub fn assert_close(a: &[f64], b: &[f64], rtol: f64) {
    assert_eq!(a.len(), b.len());
    let scale = a.iter().chain(b).fold(0.0f64, |m, x| m.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= rtol * scale, "{a:?}\n{b:?}");
    }
}

/// `report` of `path` refused: status 2, nothing on stdout, no panic; its
/// standard error.
pub fn report_refused(path: &std::path::Path) -> String {
    let out = massprop(&["report", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr
}

/// The numbers of the XML attribute `name="…"` in `text`, in order.
pub fn attr(text: &str, name: &str) -> Vec<f64> {
    let key = format!(" {name}=\"");
    text.split(&key)
        .skip(1)
        .flat_map(|r| {
            r[..r.find('"').unwrap()]
                .split_whitespace()
                .map(|x| x.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .collect()
}
