//! No file is ever damaged: `-o` never writes onto a file the run reads,
//! however it is named; outputs and blessed files are replaced through
//! temporary files with unpredictable names; `check --bless` keeps each
//! line's ending, hard links and ownership, and serialises concurrent
//! blesses of one file.

use crate::common::{assert_refused, massprop, scratch};
use std::path::Path;
use std::process::{Command, Stdio};

const WHEEL: &str = "name = \"wheel\"\n[[part]]\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 0]\n";
const CART: &str = "[[part]]\nshape = \"point\"\nmass = 5\ncenter = [0, 0, 1]\n\
                    [[part]]\ninclude = \"wheel.toml\"\norigin = [1, 0, 0]\n";

fn s(p: &Path) -> &str {
    p.to_str().expect("scratch paths are UTF-8")
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

/// The old temporary name, `.NAME.massprop.PID`, could be guessed: a file
/// planted there made the write fail and was then deleted. Files planted
/// under every name the next few thousand processes would have used are
/// neither deleted nor in the way, and no temporary file is left behind.
#[test]
fn a_file_at_a_guessable_temporary_name_is_neither_deleted_nor_in_the_way() {
    let dir = scratch("files", "planted-tmp");
    let part = dir.join("part.toml");
    std::fs::write(&part, WHEEL).unwrap();
    let report = dir.join("report.txt");
    std::fs::write(&report, "old report\n").unwrap();
    let next = Command::new("true").spawn().unwrap().id();
    let planted: Vec<_> = (next..next + 3000)
        .flat_map(|pid| {
            [
                dir.join(format!(".report.txt.massprop.{pid}")),
                dir.join(format!(".part.toml.massprop.{pid}")),
            ]
        })
        .collect();
    for p in &planted {
        std::fs::write(p, "planted").unwrap();
    }
    let out = massprop(&["report", s(&part), "-o", s(&report)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        std::fs::read_to_string(&report)
            .unwrap()
            .starts_with("wheel")
    );
    let out = massprop(&["check", "--bless", s(&part)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::read_to_string(&part).unwrap().contains("[expect]"));
    for p in &planted {
        assert_eq!(std::fs::read_to_string(p).unwrap(), "planted", "{p:?}");
    }
    let entries = std::fs::read_dir(&dir).unwrap().count();
    assert_eq!(
        entries,
        planted.len() + 2,
        "a temporary file was left behind"
    );
    std::fs::remove_dir_all(&dir).ok();
}

fn mode(p: &Path) -> u32 {
    use std::os::unix::fs::PermissionsExt;
    std::fs::metadata(p).unwrap().permissions().mode() & 0o7777
}

fn set_mode(p: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(p, std::fs::Permissions::from_mode(mode)).unwrap();
}

/// A replaced file keeps its permissions; a new output file gets what any
/// new file gets, 0666 less the umask (not the temporary file's 0600).
#[test]
fn replaced_files_keep_their_permissions_and_new_ones_follow_the_umask() {
    let dir = scratch("files", "permissions");
    let part = dir.join("part.toml");
    std::fs::write(&part, WHEEL).unwrap();
    set_mode(&part, 0o640);
    let report = dir.join("report.txt");
    std::fs::write(&report, "old\n").unwrap();
    set_mode(&report, 0o604);
    let out = massprop(&["report", s(&part), "-o", s(&report)]);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(mode(&report), 0o604);
    let out = massprop(&["check", "--bless", s(&part)]);
    assert_eq!(out.status.code(), Some(0));
    assert!(std::fs::read_to_string(&part).unwrap().contains("[expect]"));
    assert_eq!(mode(&part), 0o640);

    let new = dir.join("new.txt");
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "umask 027 && exec '{}' report '{}' -o '{}'",
            env!("CARGO_BIN_EXE_massprop"),
            s(&part),
            s(&new)
        ))
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(mode(&new), 0o640);
    std::fs::remove_dir_all(&dir).ok();
}

/// A file of mixed LF and CRLF lines: every line `--bless` leaves as it was
/// keeps its exact bytes, a changed line keeps its own ending, and a new
/// line takes the ending most lines have (CRLF here, LF in the second).
#[test]
fn bless_keeps_each_lines_own_ending() {
    let dir = scratch("files", "mixed-endings");
    let part = dir.join("mixed.toml");
    let text = "# mixed endings\n[[part]]\r\nshape = \"point\"\nmass = 12\r\n\
                center = [0, 0, 0]\r\n\n[expect]\r\nmass = { value = 11, tol = \"0.1%\" }\n\
                [expect.center_of_mass]\r\nvalue = [1, 0, 0]\r\n# after\r\n";
    std::fs::write(&part, text).unwrap();
    let out = massprop(&["check", "--bless", s(&part)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let blessed = std::fs::read_to_string(&part).unwrap();
    let expected = "# mixed endings\n[[part]]\r\nshape = \"point\"\nmass = 12\r\n\
                    center = [0, 0, 0]\r\n\n[expect]\r\nmass = { value = 12.0, tol = \"0.1%\" }\n\
                    [expect.center_of_mass]\r\nvalue = [0.0, 0.0, 0.0]\r\ntol = 0.000001\r\n# after\r\n";
    assert_eq!(blessed, expected);
    let out = massprop(&["check", s(&part)]);
    assert_eq!(out.status.code(), Some(0));

    // Mostly LF, no [expect], no final line ending: the original lines stay
    // as they were, the new block is LF.
    let text = "[[part]]\nshape = \"point\"\r\nmass = 12\ncenter = [0, 0, 0]";
    std::fs::write(&part, text).unwrap();
    let out = massprop(&["check", "--bless", s(&part)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let blessed = std::fs::read_to_string(&part).unwrap();
    assert!(blessed.starts_with(&format!("{text}\n")), "{blessed:?}");
    assert!(blessed.contains("[expect]"), "{blessed:?}");
    assert_eq!(blessed.matches("\r\n").count(), 1, "{blessed:?}");
    std::fs::remove_dir_all(&dir).ok();
}

fn ino(p: &Path) -> (u64, u64) {
    use std::os::unix::fs::MetadataExt;
    let m = std::fs::metadata(p).unwrap();
    (m.ino(), m.nlink())
}

/// A file with hard links is written in place, so every name still shows
/// the one file: a rename would have given this name a new file and left
/// the others with the old text.
#[test]
fn hard_links_are_kept_by_bless_and_by_output() {
    let dir = scratch("files", "hard-links");
    let part = dir.join("part.toml");
    let other = dir.join("other-name.toml");
    std::fs::write(&part, WHEEL).unwrap();
    std::fs::hard_link(&part, &other).unwrap();
    let before = ino(&part);
    let out = massprop(&["check", "--bless", s(&part)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let blessed = std::fs::read_to_string(&part).unwrap();
    assert!(
        blessed.starts_with(WHEEL) && blessed.contains("[expect]"),
        "{blessed}"
    );
    assert_eq!(std::fs::read_to_string(&other).unwrap(), blessed);
    assert_eq!(ino(&part), before);
    assert_eq!(massprop(&["check", s(&other)]).status.code(), Some(0));

    // A shorter text in place leaves no tail of the longer one.
    let report = dir.join("report.txt");
    let linked = dir.join("report-link.txt");
    std::fs::write(&report, "x".repeat(100_000)).unwrap();
    std::fs::hard_link(&report, &linked).unwrap();
    let out = massprop(&["report", s(&part), "-o", s(&report)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let written = std::fs::read_to_string(&linked).unwrap();
    assert!(
        written.starts_with("wheel") && !written.contains("xxx"),
        "{written}"
    );
    assert_eq!(std::fs::read_to_string(&report).unwrap(), written);
    assert_eq!(ino(&report).1, 2);
    std::fs::remove_dir_all(&dir).ok();
}

fn owner(p: &Path) -> (u32, u32) {
    use std::os::unix::fs::MetadataExt;
    let m = std::fs::metadata(p).unwrap();
    (m.uid(), m.gid())
}

/// Run as root, a replaced file keeps its owner and group; run as a user
/// who may not give a file away, `--bless` of someone else's file (in a
/// directory that user may write) is refused and the file left as it was,
/// rather than the file changing hands. Skipped unless root.
#[test]
fn owners_are_kept_or_the_bless_is_refused() {
    let dir = scratch("files", "owners");
    let part = dir.join("part.toml");
    std::fs::write(&part, WHEEL).unwrap();
    if std::os::unix::fs::chown(&part, Some(4321), Some(4321)).is_err() {
        eprintln!("skipped: not running as root");
        return;
    }
    set_mode(&part, 0o664);
    let out = massprop(&["check", "--bless", s(&part)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::read_to_string(&part).unwrap().contains("[expect]"));
    assert_eq!(owner(&part), (4321, 4321));
    assert_eq!(mode(&part), 0o664);
    let report = dir.join("report.txt");
    std::fs::write(&report, "old\n").unwrap();
    std::os::unix::fs::chown(&report, Some(4321), Some(4322)).unwrap();
    let out = massprop(&["report", s(&part), "-o", s(&report)]);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(owner(&report), (4321, 4322));

    // As another user: a file that needs no change is `unchanged`, even
    // one this user may not write.
    let as_other_user = || {
        Command::new("setpriv")
            .args(["--reuid=4322", "--regid=4322", "--clear-groups"])
            .arg(env!("CARGO_BIN_EXE_massprop"))
            .args(["check", "--bless", s(&part)])
            .output()
    };
    set_mode(&part, 0o644);
    let Ok(out) = as_other_user() else {
        eprintln!("skipped the rest: setpriv is not available");
        return;
    };
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("unchanged"), "{stderr}");

    // One that needs a change is refused, though the directory would
    // allow a rename.
    set_mode(&dir, 0o777);
    std::fs::write(&part, WHEEL).unwrap();
    let out = as_other_user().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("this user may not write the file"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&part).unwrap(), WHEEL);

    // Another user's file, writable by all, in a directory all may write.
    set_mode(&part, 0o666);
    let out = as_other_user().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("cannot keep the file's owner (user 4321, group 4321)"),
        "{stderr}"
    );
    assert!(stderr.contains("not blessed"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&part).unwrap(), WHEEL);
    assert_eq!(owner(&part), (4321, 4321));

    // The same rule for `-o` onto another user's file.
    set_mode(&report, 0o666);
    let out = Command::new("setpriv")
        .args(["--reuid=4322", "--regid=4322", "--clear-groups"])
        .arg(env!("CARGO_BIN_EXE_massprop"))
        .args(["report", s(&part), "-o", s(&report)])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("cannot keep the file's owner (user 4321, group 4322)"),
        "{stderr}"
    );
    assert_eq!(owner(&report), (4321, 4322));
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        2,
        "a temporary file was left"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Spawn `massprop check --bless FILE`.
fn spawn_bless(file: &Path) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(["check", "--bless", s(file)])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Wait for a bless, which must succeed.
fn blessed(child: std::process::Child) {
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn point(mass: u32) -> String {
    format!("[[part]]\nshape = \"point\"\nmass = {mass}\ncenter = [0, 0, 0]\n")
}

/// `--bless` waits for the lock on the file, then reads it: what another
/// holder of the lock wrote meanwhile is what it blesses, not the text it
/// would have read before waiting.
#[test]
fn bless_waits_for_the_lock_and_then_reads_the_file() {
    let dir = scratch("files", "lock-wait");
    let part = dir.join("part.toml");
    std::fs::write(&part, point(12)).unwrap();
    let mut held = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(&part)
        .unwrap();
    held.lock().unwrap();
    let mut child = spawn_bless(&part);
    std::thread::sleep(std::time::Duration::from_millis(700));
    assert!(
        child.try_wait().unwrap().is_none(),
        "bless did not wait for the lock"
    );
    assert_eq!(std::fs::read_to_string(&part).unwrap(), point(12));
    held.set_len(0).unwrap();
    std::io::Write::write_all(&mut held, point(13).as_bytes()).unwrap();
    drop(held);
    blessed(child);
    let text = std::fs::read_to_string(&part).unwrap();
    assert!(text.starts_with(&point(13)), "{text}");
    assert!(text.contains("value = 13.0"), "{text}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A bless that waited for the lock while the file was replaced (renamed
/// over, as another bless does) blesses the file now there, not the one it
/// locked.
#[test]
fn bless_that_waited_blesses_the_file_that_replaced_the_locked_one() {
    let dir = scratch("files", "lock-replaced");
    let part = dir.join("part.toml");
    std::fs::write(&part, point(12)).unwrap();
    let held = std::fs::File::open(&part).unwrap();
    held.lock().unwrap();
    let mut child = spawn_bless(&part);
    std::thread::sleep(std::time::Duration::from_millis(700));
    assert!(
        child.try_wait().unwrap().is_none(),
        "bless did not wait for the lock"
    );
    let new = dir.join("new.toml");
    std::fs::write(&new, point(14)).unwrap();
    std::fs::rename(&new, &part).unwrap();
    drop(held);
    blessed(child);
    let text = std::fs::read_to_string(&part).unwrap();
    assert!(text.starts_with(&point(14)), "{text}");
    assert!(text.contains("value = 14.0"), "{text}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Eight blesses of one file at once, in rounds from differing previous
/// values, with the file alone and with a hard link (written in place):
/// the file always ends as one bless makes it, and passes `check`. (The
/// `[expect]` comes first, so a text read half-written differs from the
/// start. Without the lock this passes only by luck of timing; the two
/// tests above fail without it.)
#[test]
fn concurrent_blesses_leave_the_file_as_one_bless_would() {
    let dir = scratch("files", "concurrent");
    let part = dir.join("many.toml");
    let alone = dir.join("alone");
    std::fs::create_dir_all(&alone).unwrap();
    let reference = alone.join("many.toml");
    let mut body = String::new();
    for i in 0..3000 {
        body.push_str(&format!(
            "[[part]]\nshape = \"point\"\nmass = {}\ncenter = [{i}, {}, 0.5]\n",
            1 + i % 7,
            i % 11
        ));
    }
    for round in 0..4 {
        let text = format!(
            "[expect]\nmass = {{ value = {}, tol = \"0.1%\" }}\n\
             center_of_mass = {{ value = [{round}, 1, 2], tol = 0.1 }}\n{body}",
            round * 100 + 1
        );
        std::fs::write(&reference, &text).unwrap();
        blessed(spawn_bless(&reference));
        let one = std::fs::read_to_string(&reference).unwrap();
        assert_ne!(one, text);
        let link = dir.join("link.toml");
        let _ = std::fs::remove_file(&link);
        std::fs::write(&part, &text).unwrap();
        if round % 2 == 1 {
            std::fs::hard_link(&part, &link).unwrap();
        }
        let children: Vec<_> = (0..8).map(|_| spawn_bless(&part)).collect();
        children.into_iter().for_each(blessed);
        assert_eq!(
            std::fs::read_to_string(&part).unwrap(),
            one,
            "round {round}"
        );
        assert_eq!(massprop(&["check", s(&part)]).status.code(), Some(0));
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// An output that cannot be written says why, naming the directory, not
/// the random name of the temporary file.
#[test]
fn a_failed_write_names_no_temporary_file() {
    let dir = scratch("files", "failed-write");
    let part = dir.join("part.toml");
    std::fs::write(&part, WHEEL).unwrap();
    let missing = dir.join("missing").join("report.txt");
    let out = massprop(&["report", s(&part), "-o", s(&missing)]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    let expected = format!(
        "{}: error: cannot write the output file: cannot create a file in `{}`: ",
        s(&missing),
        s(&dir.join("missing"))
    );
    assert!(stderr.starts_with(&expected), "{stderr}");
    assert!(!stderr.contains("massprop.tmp"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `-o /dev/stdout` (or any other name of the file) with standard output
/// redirected to a file appends to what the shell wrote there, as writing
/// to standard output does; a rename once put a new file in its place, and
/// everything before and after was lost.
#[test]
fn output_onto_the_file_behind_standard_output_is_written_to_it() {
    use std::io::Write;
    let dir = scratch("files", "onto-stdout");
    let part = dir.join("wheel.toml");
    std::fs::write(&part, WHEEL).unwrap();
    let out = dir.join("out.txt");
    for name in ["/dev/stdout", "/proc/self/fd/1", out.to_str().unwrap()] {
        let mut file = std::fs::File::create(&out).unwrap();
        file.write_all(b"HEADER\n").unwrap();
        let before = ino(&out).0;
        let status = Command::new(env!("CARGO_BIN_EXE_massprop"))
            .args(["report", "--format", "json", s(&part), "-o", name])
            .stdout(Stdio::from(file.try_clone().unwrap()))
            .status()
            .unwrap();
        assert!(status.success(), "{name}");
        file.write_all(b"TRAILER\n").unwrap();
        let text = std::fs::read_to_string(&out).unwrap();
        assert_eq!(ino(&out).0, before, "{name}: the file was replaced");
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 3, "{name}: {text}");
        assert_eq!((lines[0], lines[2]), ("HEADER", "TRAILER"), "{name}");
        let json: serde_json::Value = serde_json::from_str(lines[1]).unwrap();
        assert_eq!(json["mass"], 2.0);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `check -o` may not write onto a file that a part file includes, even
/// when that part file turns out invalid after its includes were read
/// (here an unknown key in `[expect]`): the check's report once replaced
/// the sub-assembly.
#[test]
fn check_output_onto_a_file_an_invalid_part_file_includes_is_refused() {
    let dir = scratch("files", "onto-include-of-invalid");
    let sub = dir.join("sub.toml");
    std::fs::write(&sub, WHEEL).unwrap();
    let top = dir.join("top.toml");
    std::fs::write(
        &top,
        "[[part]]\ninclude = \"sub.toml\"\n\n[expect]\nmass = { value = 2, tol = 0.1, bogus = 1 }\n",
    )
    .unwrap();
    let args = ["check", s(&top), "-o", s(&sub)];
    let out = massprop(&args);
    assert_refused(&out, &args);
    assert_eq!(std::fs::read_to_string(&sub).unwrap(), WHEEL);
    std::fs::remove_dir_all(&dir).ok();
}

/// `-o` onto a file with hard links writes in place and keeps the old text
/// to write back should that fail: not past the size a part file may have
/// (a sparse file of 513 MiB here), which is refused, the file untouched.
#[test]
fn output_in_place_onto_a_huge_hard_linked_file_is_refused() {
    let dir = scratch("files", "huge-hard-link");
    let part = dir.join("wheel.toml");
    std::fs::write(&part, WHEEL).unwrap();
    let out = dir.join("out.json");
    std::fs::File::create(&out)
        .unwrap()
        .set_len(513 << 20)
        .unwrap();
    std::fs::hard_link(&out, dir.join("other.json")).unwrap();
    let o = massprop(&["report", s(&part), "-o", s(&out)]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("too large to keep for a restore"),
        "{stderr}"
    );
    assert_eq!(std::fs::metadata(&out).unwrap().len(), 513 << 20);
    std::fs::remove_dir_all(&dir).ok();
}

/// `-o` through a symlink whose target does not exist yet makes the target
/// and leaves the link a link (a rename once replaced the link by a file).
#[test]
fn output_through_a_dangling_symlink_makes_its_target() {
    let dir = scratch("files", "dangling-link");
    let part = dir.join("wheel.toml");
    std::fs::write(&part, WHEEL).unwrap();
    std::fs::create_dir_all(dir.join("reports")).unwrap();
    let link = dir.join("latest.json");
    std::os::unix::fs::symlink("reports/wheel.json", &link).unwrap();
    let o = massprop(&["report", "--format", "json", s(&part), "-o", s(&link)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("reports/wheel.json")).unwrap()).unwrap();
    assert_eq!(json["mass"], 2.0);
    std::fs::remove_dir_all(&dir).ok();
}
