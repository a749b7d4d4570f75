//! What `cargo package` needs of the committed tree.

use std::process::Command;

/// `cargo package` archives each committed file by following it, so a
/// symlink loop (once tests/cmd/bad-input.in/loop-a.toml) or a dangling
/// link makes it fail; links are also lost on checkouts without them
/// (Windows). A fixture that needs a link makes it at test time, as
/// `cli::an_include_of_a_symlink_loop_is_an_error_at_the_include` does.
#[test]
fn no_committed_file_is_a_symlink() {
    let out = Command::new("git")
        .args(["ls-files", "--stage", "-z"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output();
    let out = match out {
        Ok(out) if out.status.success() => out,
        Ok(out) => {
            // A packaged copy, or a checkout git refuses to read.
            let why = String::from_utf8_lossy(&out.stderr);
            eprintln!("skipped: `git ls-files` failed: {}", why.trim());
            return;
        }
        Err(e) => {
            eprintln!("skipped: no git to list the committed files: {e}");
            return;
        }
    };
    // Entries are `MODE OBJECT STAGE\tPATH`; 120000 is a symlink.
    let links: Vec<String> = out
        .stdout
        .split(|&b| b == 0)
        .filter(|entry| entry.starts_with(b"120000 "))
        .map(|entry| {
            let entry = String::from_utf8_lossy(entry);
            entry
                .split_once('\t')
                .map_or(entry.to_string(), |(_, p)| p.to_string())
        })
        .collect();
    assert!(
        links.is_empty(),
        "committed symlinks (make them at test time instead): {links:?}"
    );
}
