//! `check DIR`'s own search (`massprop::analysis::search::find`, its
//! walker and gitignore matcher) against what it replaced:
//!
//! - random trees of directories and `*.toml` files, with random
//!   `.gitignore` and `.ignore` files (lines drawn from a grammar of
//!   gitignore patterns: negation, anchoring, escapes, trailing spaces
//!   and slashes, `*`, `?`, classes, `**`, alternates, broken globs), a
//!   repository or none, `--hidden` and `--exclude`, searched at the top
//!   or in a subdirectory: the files found, in order, must be those
//!   ripgrep's `ignore` crate finds, configured as massprop configured it
//!   (`WalkBuilder` with `hidden`, overrides, no links followed, sorted
//!   by name);
//! - gitignore(5)'s documented examples, each a table row whose expected
//!   files are read off the manual, not off either program.
//!
//! Deterministic (fixed ChaCha seed, no persistence), as in hostile.rs.

use massprop::analysis::search::{Found, Search, find};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use std::path::{Path, PathBuf};

/// Random trees searched.
const CASES: u32 = 400;

/// Names of directories, and of files (with `.toml` added).
const NAMES: [&str; 9] = ["a", "b", ".h", "ab", "c.d", "[a]", "!x", "#y", "s p"];
/// The pieces a pattern's path components are made of.
const ATOMS: [&str; 26] = [
    "a",
    "b",
    "ab",
    ".h",
    "c.d",
    "*",
    "?",
    "**",
    "[ab]",
    "[!a]",
    "[a-c]",
    "[^b]",
    "*.toml",
    "a*",
    "{a,b}*",
    "[",
    "\\*",
    "a.toml",
    "b.toml",
    ".h*",
    "\\[a]",
    "[[:alpha:]]*",
    "#y",
    "!x*",
    "{a",
    "b}",
];
const PREFIXES: [&str; 9] = ["", "", "", "!", "/", "!/", "\\!", "\\#", "#"];
const SUFFIXES: [&str; 7] = ["", "", "", "/", "/**", "  ", "\\ "];

/// A scratch directory outside any repository (cargo's target directory
/// is inside this one, whose `.gitignore` would apply to it).
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir()
        .join(format!("massprop-search-rules-{}", std::process::id()))
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn put(root: &Path, name: &str, text: &str) {
    let p = root.join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(p, text).unwrap();
}

/// What `find` finds in `dir`: each file's path, `!` and the message for
/// a part of the tree it could not search; `Err` for a bad `--exclude`,
/// with its message.
fn own(dir: &Path, hidden: bool, exclude: &[String]) -> Result<Vec<String>, String> {
    let search = Search {
        hidden,
        exclude: exclude.to_vec(),
        verbose: false,
    };
    let found = find(&[dir.to_path_buf()], &search).map_err(|d| d.message().to_string())?;
    Ok(found
        .iter()
        .map(|f| match f {
            Found::File(p, _) => p.display().to_string(),
            Found::Skipped(_, d) => format!("! {}", d.message()),
        })
        .collect())
}

/// What the `ignore` crate finds in `dir`, configured as massprop
/// configured it before (src/analysis/search.rs, until this test came):
/// its `*.toml` regular files and robot descriptions, `!` and the message massprop made of an
/// error.
fn reference(dir: &Path, hidden: bool, exclude: &[String]) -> Result<Vec<String>, String> {
    let mut excluded = ignore::overrides::OverrideBuilder::new(dir);
    for glob in exclude {
        excluded
            .add(&format!("!{glob}"))
            .map_err(|e| format!("--exclude `{glob}`: {e}"))?;
    }
    let excluded = excluded.build().map_err(|e| format!("--exclude: {e}"))?;
    let walk = ignore::WalkBuilder::new(dir)
        .hidden(!hidden)
        .overrides(excluded)
        .follow_links(false)
        .sort_by_file_name(|a, b| a.cmp(b))
        .build();
    Ok(walk
        .filter_map(|e| match e {
            Ok(e) => {
                let file = e.file_type().is_some_and(|t| t.is_file());
                // The names `find` looks at: part files and robot
                // descriptions.
                let p = e.path();
                let wanted = massprop::io::is_toml(p) || massprop::robot::may_be_robot(p);
                (file && wanted).then(|| p.display().to_string())
            }
            Err(e) => Some(format!("! cannot search: {e}")),
        })
        .collect())
}

/// One generated tree.
#[derive(Debug, Clone)]
struct Tree {
    /// Files: directories then a file name (`.toml` added).
    files: Vec<Vec<usize>>,
    /// Ignore files: the directory, `.ignore` (or `.gitignore`), lines.
    ignores: Vec<(Vec<usize>, bool, Vec<String>)>,
    /// Where a `.git` directory is, if anywhere.
    git: Option<Vec<usize>>,
    /// The directory searched, below the top.
    searched: Vec<usize>,
    hidden: bool,
    exclude: Vec<String>,
}

fn component(i: usize) -> &'static str {
    NAMES[i]
}

fn dir_of(parts: &[usize]) -> PathBuf {
    parts.iter().map(|&i| component(i)).collect()
}

/// A name: mostly one of the first three, so that rules meet.
fn name() -> impl Strategy<Value = usize> {
    prop_oneof![3 => 0..3usize, 1 => 0..NAMES.len()]
}

fn pattern() -> impl Strategy<Value = String> {
    (
        0..PREFIXES.len(),
        prop::collection::vec(prop::collection::vec(0..ATOMS.len(), 1..=2), 1..=3),
        0..SUFFIXES.len(),
    )
        .prop_map(|(p, parts, s)| {
            let parts: Vec<String> = parts
                .iter()
                .map(|c| c.iter().map(|&i| ATOMS[i]).collect())
                .collect();
            format!("{}{}{}", PREFIXES[p], parts.join("/"), SUFFIXES[s])
        })
}

fn tree() -> impl Strategy<Value = Tree> {
    let path = |max| prop::collection::vec(name(), 0..=max);
    (
        prop::collection::vec(prop::collection::vec(name(), 1..=4), 1..16),
        prop::collection::vec(
            (
                path(1),
                any::<bool>(),
                prop::collection::vec(pattern(), 1..6),
            ),
            1..8,
        ),
        // Mostly a repository at the top (where `.gitignore` applies).
        prop_oneof![3 => Just(Some(Vec::new())), 1 => Just(None), 1 => prop::option::of(path(1))],
        path(1),
        any::<bool>(),
        prop::collection::vec(pattern(), 0..=2),
    )
        .prop_map(|(files, ignores, git, searched, hidden, exclude)| Tree {
            files,
            ignores,
            git,
            searched,
            hidden,
            exclude: exclude
                .into_iter()
                .map(|g| g.trim_start_matches(['!', '\\', '#']).to_string())
                .collect(),
        })
}

/// `t` written under `root`.
fn write(root: &Path, t: &Tree) {
    for f in &t.files {
        let (name, dirs) = f.split_last().unwrap();
        put(
            root,
            &dir_of(dirs)
                .join(format!("{}.toml", component(*name)))
                .to_string_lossy(),
            "",
        );
    }
    for (dir, dot_ignore, lines) in &t.ignores {
        let name = if *dot_ignore { ".ignore" } else { ".gitignore" };
        let path = root.join(dir_of(dir)).join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        // NOTE: appended, so that two draws of one file both count.
        let mut text = std::fs::read_to_string(&path).unwrap_or_default();
        text.extend(lines.iter().map(|l| format!("{l}\n")));
        std::fs::write(&path, text).unwrap();
    }
    if let Some(git) = &t.git {
        std::fs::create_dir_all(root.join(dir_of(git)).join(".git")).unwrap();
    }
    std::fs::create_dir_all(root.join(dir_of(&t.searched))).unwrap();
}

#[test]
fn the_search_finds_what_the_ignore_crate_finds_on_random_trees() {
    let config = Config {
        cases: CASES,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let root = scratch("random");
    let result = runner.run(&tree(), |t| {
        let _ = std::fs::remove_dir_all(&root);
        write(&root, &t);
        let dir = root.join(dir_of(&t.searched));
        let mine = own(&dir, t.hidden, &t.exclude);
        let theirs = reference(&dir, t.hidden, &t.exclude);
        if mine != theirs {
            return Err(TestCaseError::fail(format!(
                "found {mine:?}\nthe ignore crate {theirs:?}"
            )));
        }
        Ok(())
    });
    let _ = std::fs::remove_dir_all(&root);
    result.unwrap();
}

/// Every `*.toml` file under `dir`.
fn toml_files(dir: &Path) -> usize {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .map(|p| {
            if p.is_dir() {
                toml_files(&p)
            } else {
                usize::from(p.extension().is_some_and(|x| x == "toml"))
            }
        })
        .sum()
}

#[test]
fn the_random_trees_find_files_and_pass_files_over() {
    // The comparison above means something only if the trees exercise
    // both: count, over the same draws, files found and files passed over.
    let config = Config {
        cases: 100,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let root = scratch("coverage");
    let (mut found, mut passed_over) = (0usize, 0usize);
    for _ in 0..100 {
        let t = tree().new_tree(&mut runner).unwrap().current();
        let _ = std::fs::remove_dir_all(&root);
        write(&root, &t);
        let dir = root.join(dir_of(&t.searched));
        let all = toml_files(&dir);
        let some = own(&dir, t.hidden, &t.exclude)
            .map(|f| f.len())
            .unwrap_or(0);
        found += some;
        passed_over += all.saturating_sub(some);
    }
    let _ = std::fs::remove_dir_all(&root);
    assert!(
        found > 100 && passed_over > 100,
        "found {found}, passed over {passed_over}"
    );
}

// ---------------------------------------------------------------------------
// gitignore(5)'s examples, and ripgrep's precedence, one fact a test

/// The files `find` finds in `root/dir` of a tree of `files` (path,
/// text; every directory with a `.git` entry in it written as such),
/// relative to `root`, sorted.
fn found_in(name: &str, files: &[(&str, &str)], dir: &str) -> Vec<String> {
    let root = scratch(name);
    for (path, text) in files {
        if path.ends_with(".git") {
            std::fs::create_dir_all(root.join(path)).unwrap();
        } else {
            put(&root, path, text);
        }
    }
    let search = Search::default();
    let found = find(&[root.join(dir)], &search).unwrap();
    let mut names: Vec<String> = found
        .iter()
        .filter_map(|f| match f {
            Found::File(p, _) => Some(
                p.strip_prefix(&root)
                    .unwrap()
                    .to_string_lossy()
                    .into_owned(),
            ),
            Found::Skipped(..) => None,
        })
        .collect();
    names.sort();
    let _ = std::fs::remove_dir_all(&root);
    names
}

/// `found_in` a repository whose `.gitignore` is `rules`.
fn kept(name: &str, rules: &str, files: &[&str]) -> Vec<String> {
    let mut tree = vec![(".git", ""), (".gitignore", rules)];
    tree.extend(files.iter().map(|f| (*f, "")));
    found_in(name, &tree, "")
}

#[test]
fn blank_lines_and_comments_match_nothing() {
    assert_eq!(kept("blank", "\n# a.toml\n   \n", &["a.toml"]), ["a.toml"]);
}

#[test]
fn a_backslash_before_a_hash_or_bang_makes_it_literal() {
    let files = ["#y.toml", "!x.toml", "y.toml", "x.toml"];
    assert_eq!(
        kept("escapes", "\\#y.toml\n\\!x.toml\n", &files),
        ["x.toml", "y.toml"]
    );
}

#[test]
fn trailing_spaces_are_ignored_unless_escaped() {
    let files = ["a.toml", "b.toml", "b.toml /c.toml"];
    assert_eq!(kept("spaces", "a.toml   \nb.toml\\ \n", &files), ["b.toml"]);
}

#[test]
fn a_negation_re_includes_what_an_earlier_pattern_excluded() {
    assert_eq!(
        kept("negation", "*.toml\n!keep.toml\n", &["a.toml", "keep.toml"]),
        ["keep.toml"]
    );
}

#[test]
fn a_file_is_not_re_included_when_its_directory_is_excluded() {
    assert_eq!(
        kept("parent", "dir/\n!dir/a.toml\n", &["dir/a.toml", "a.toml"]),
        ["a.toml"]
    );
}

#[test]
fn a_trailing_slash_matches_directories_only() {
    let files = ["a.toml", "d/a.toml/x.toml"];
    assert_eq!(kept("dir-only", "a.toml/\n", &files), ["a.toml"]);
}

#[test]
fn a_slash_in_the_middle_anchors_to_the_ignore_files_directory() {
    let files = ["doc/frotz/x.toml", "a/doc/frotz/x.toml"];
    assert_eq!(
        kept("middle", "doc/frotz/\n", &files),
        ["a/doc/frotz/x.toml"]
    );
}

#[test]
fn a_name_without_a_slash_matches_at_any_depth() {
    let files = ["doc/frotz/x.toml", "a/frotz/x.toml", "frotz.toml"];
    assert_eq!(kept("any-depth", "frotz/\n", &files), ["frotz.toml"]);
}

#[test]
fn a_leading_slash_anchors_to_the_ignore_files_directory() {
    let files = ["hello.toml", "a/hello.toml"];
    assert_eq!(kept("leading", "/hello.*\n", &files), ["a/hello.toml"]);
    assert!(kept("unanchored", "hello.*\n", &files).is_empty());
}

#[test]
fn a_leading_double_star_matches_in_all_directories() {
    let files = ["foo/bar.toml", "a/foo/bar.toml", "foo/a/bar.toml"];
    assert_eq!(
        kept("double-star", "**/foo/bar.toml\n", &files),
        ["foo/a/bar.toml"]
    );
}

#[test]
fn a_trailing_double_star_matches_everything_inside() {
    let files = ["abc/x.toml", "abc/d/y.toml", "a/abc/x.toml", "abc.toml"];
    assert_eq!(
        kept("trailing", "abc/**\n", &files),
        ["a/abc/x.toml", "abc.toml"]
    );
}

#[test]
fn a_middle_double_star_matches_zero_or_more_directories() {
    let files = ["a/b.toml", "a/x/b.toml", "a/x/y/b.toml", "c/a/b.toml"];
    assert_eq!(kept("middle-star", "a/**/b.toml\n", &files), ["c/a/b.toml"]);
}

#[test]
fn everything_but_one_directory_is_excluded_as_the_manual_shows() {
    let files = ["a.toml", "foo/a.toml", "foo/bar/a.toml", "baz/a.toml"];
    let rules = "/*\n!/foo\n/foo/*\n!/foo/bar\n";
    assert_eq!(kept("all-but", rules, &files), ["foo/bar/a.toml"]);
}

#[test]
fn a_star_does_not_match_a_slash() {
    let files = ["a/x.toml", "a/b/x.toml"];
    assert_eq!(kept("star", "a/*.toml\n", &files), ["a/b/x.toml"]);
}

#[test]
fn a_question_mark_matches_one_character() {
    let files = ["a.toml", "ab.toml"];
    assert_eq!(kept("question", "?.toml\n", &files), ["ab.toml"]);
}

#[test]
fn a_class_matches_one_of_its_characters_or_range() {
    let files = ["a.toml", "b.toml", "c.toml", "d.toml"];
    assert_eq!(kept("class", "[ab].toml\n", &files), ["c.toml", "d.toml"]);
    assert_eq!(kept("range", "[b-c].toml\n", &files), ["a.toml", "d.toml"]);
}

#[test]
fn a_negated_class_matches_any_other_character() {
    let files = ["a.toml", "b.toml", "c.toml"];
    assert_eq!(kept("bang-class", "[!a].toml\n", &files), ["a.toml"]);
    assert_eq!(kept("caret-class", "[^a].toml\n", &files), ["a.toml"]);
}

#[test]
fn a_deeper_ignore_file_overrides_a_shallower_one() {
    let tree = [
        (".git", ""),
        (".gitignore", "*.toml\n"),
        ("sub/.gitignore", "!b.toml\n"),
        ("sub/b.toml", ""),
        ("a.toml", ""),
    ];
    assert_eq!(found_in("deeper", &tree, ""), ["sub/b.toml"]);
}

#[test]
fn a_dot_ignore_rule_wins_over_a_dot_gitignore_rule() {
    let tree = [
        (".git", ""),
        (".gitignore", "a.toml\n"),
        (".ignore", "!a.toml\n"),
        ("a.toml", ""),
    ];
    assert_eq!(found_in("dot-ignore", &tree, ""), ["a.toml"]);
}

#[test]
fn a_gitignore_applies_only_inside_a_repository() {
    let tree = [
        (".gitignore", "a.toml\n"),
        (".ignore", "b.toml\n"),
        ("a.toml", ""),
        ("b.toml", ""),
    ];
    assert_eq!(found_in("no-repo", &tree, ""), ["a.toml"]);
}

#[test]
fn a_gitignore_above_the_repository_does_not_apply() {
    let tree = [
        (".gitignore", "*.toml\n"),
        ("repo/.git", ""),
        ("repo/a.toml", ""),
    ];
    assert_eq!(found_in("above-repo", &tree, "repo"), ["repo/a.toml"]);
}

#[test]
fn a_gitignore_above_the_directory_searched_applies_within_the_repository() {
    let tree = [
        (".git", ""),
        (".gitignore", "/sub/a.toml\n"),
        ("sub/a.toml", ""),
        ("sub/b.toml", ""),
    ];
    assert_eq!(found_in("parent-rules", &tree, "sub"), ["sub/b.toml"]);
}

#[test]
fn the_repositorys_info_exclude_applies() {
    let tree = [
        (".git", ""),
        (".git/info/exclude", "a.toml\n"),
        ("a.toml", ""),
        ("b.toml", ""),
    ];
    assert_eq!(found_in("exclude", &tree, ""), ["b.toml"]);
}

#[test]
fn a_negation_finds_a_hidden_file_without_hidden() {
    let tree = [(".ignore", "!.h.toml\n"), (".h.toml", ""), (".g.toml", "")];
    assert_eq!(found_in("hidden", &tree, ""), [".h.toml"]);
}

#[test]
fn a_worktrees_info_exclude_is_its_common_directorys() {
    let root = scratch("worktree");
    let gitdir = root.join("main/.git/worktrees/w");
    put(&root, "main/.git/info/exclude", "a.toml\n");
    put(&root, "main/.git/worktrees/w/commondir", "../..\n");
    put(&root, "w/.git", &format!("gitdir: {}\n", gitdir.display()));
    put(&root, "w/a.toml", "");
    put(&root, "w/b.toml", "");
    let w = root.join("w");
    let found = own(&w, false, &[]).unwrap();
    assert_eq!(found, [w.join("b.toml").display().to_string()]);
    assert_eq!(Ok(found), reference(&w, false, &[]));
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn the_search_of_this_repository_finds_what_the_ignore_crate_finds() {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    for hidden in [false, true] {
        let found = own(repo, hidden, &[]);
        assert!(found.as_ref().is_ok_and(|f| f.len() > 10), "{found:?}");
        assert_eq!(found, reference(repo, hidden, &[]), "hidden: {hidden}");
    }
}
