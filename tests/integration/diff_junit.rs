//! massprop's own line diff (`diff_lines`) and JUnit writer
//! (`output::junit`), which replaced the `similar` and `quick-junit`
//! crates in the release build (issue 32): each held against the crate it
//! replaced, now a dev-dependency, over generated inputs.
//!
//! - diff: random texts from a few lines (so that there are many equal
//!   lines and many shortest scripts to choose among), with LF, CRLF and
//!   lone-CR endings and with or without a final newline: the same edit
//!   script as `similar::capture_diff_slices` (so `--bless` maps every
//!   line's ending as before), the same length D, and the same unified
//!   diff, byte for byte; and a hostile input that cannot hang.
//!
//! Deterministic (fixed ChaCha seed, no persistence), as in invariants.rs.

use massprop::diff_lines::{self, MAX_WORK, Op};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

fn runner(cases: u32) -> TestRunner {
    TestRunner::new_with_rng(
        Config {
            cases,
            failure_persistence: None,
            ..Config::default()
        },
        TestRng::deterministic_rng(RngAlgorithm::ChaCha),
    )
}

/// Pieces a text is made of: few distinct lines, every ending, and pieces
/// without one (which join the next piece, or end the text unterminated).
const PIECES: [&str; 10] = [
    "a\n", "b\n", "c\n", "a\r\n", "b\r\n", "\n", "a", "b", "c\r", "[x]\n",
];

fn text(max: usize) -> impl Strategy<Value = String> {
    proptest::collection::vec(0..PIECES.len(), 0..max)
        .prop_map(|v| v.into_iter().map(|i| PIECES[i]).collect())
}

/// A pair of texts: independent, or the second an edit of the first (a
/// few pieces changed), as `--bless` and `--update` make them.
fn pair(max: usize) -> impl Strategy<Value = (String, String)> {
    let independent = (text(max), text(max));
    let edited = (
        proptest::collection::vec(0..PIECES.len(), 0..max),
        proptest::collection::vec((0..max.max(1), 0..PIECES.len() + 1), 0..6),
    )
        .prop_map(|(base, edits)| {
            let old: String = base.iter().map(|&i| PIECES[i]).collect();
            let mut new = base;
            for (at, piece) in edits {
                let at = at.min(new.len());
                if piece == PIECES.len() {
                    if at < new.len() {
                        new.remove(at);
                    }
                } else {
                    new.insert(at, piece);
                }
            }
            (old, new.iter().map(|&i| PIECES[i]).collect())
        });
    prop_oneof![independent, edited]
}

/// An op as `similar` spells it, for comparison.
fn from_similar(op: &similar::DiffOp) -> Op {
    match *op {
        similar::DiffOp::Equal {
            old_index,
            new_index,
            len,
        } => Op::Equal {
            old: old_index,
            new: new_index,
            len,
        },
        similar::DiffOp::Delete {
            old_index,
            old_len,
            new_index,
        } => Op::Delete {
            old: old_index,
            old_len,
            new: new_index,
        },
        similar::DiffOp::Insert {
            old_index,
            new_index,
            new_len,
        } => Op::Insert {
            old: old_index,
            new: new_index,
            new_len,
        },
        similar::DiffOp::Replace {
            old_index,
            old_len,
            new_index,
            new_len,
        } => Op::Replace {
            old: old_index,
            old_len,
            new: new_index,
            new_len,
        },
    }
}

/// Lines deleted plus lines inserted: the script's length D.
fn cost(ops: &[Op]) -> usize {
    ops.iter()
        .map(|op| match op {
            Op::Equal { .. } => 0,
            Op::Delete { .. } | Op::Insert { .. } | Op::Replace { .. } => {
                op.old_range().len() + op.new_range().len()
            }
        })
        .sum()
}

/// `new`, rebuilt from `old` by the script (every op checked in place).
fn apply<'a>(old: &[&'a str], new: &[&'a str], ops: &[Op]) -> Vec<&'a str> {
    let mut out = Vec::new();
    let (mut i, mut j) = (0, 0);
    for op in ops {
        assert_eq!((op.old_range().start, op.new_range().start), (i, j));
        if let Op::Equal {
            old: o,
            new: n,
            len,
        } = *op
        {
            assert_eq!(old[o..o + len], new[n..n + len]);
        }
        out.extend_from_slice(&new[op.new_range()]);
        i = op.old_range().end;
        j = op.new_range().end;
    }
    assert_eq!((i, j), (old.len(), new.len()));
    out
}

fn similar_unified(old: &str, new: &str) -> String {
    similar::TextDiff::from_lines(old, new)
        .unified_diff()
        .context_radius(3)
        .header("a/robot.urdf", "b/robot.urdf")
        .to_string()
}

#[test]
fn the_edit_script_is_similars_so_bless_maps_every_ending_as_before() {
    runner(3000)
        .run(&pair(40), |(old, new)| {
            let (a, b) = (diff_lines::split_lines(&old), diff_lines::split_lines(&new));
            let theirs: Vec<Op> = similar::capture_diff_slices(similar::Algorithm::Myers, &a, &b)
                .iter()
                .map(from_similar)
                .collect();
            prop_assert_eq!(diff_lines::diff(&a, &b), theirs);
            Ok(())
        })
        .unwrap();
}

#[test]
fn the_edit_script_is_as_short_as_similars_and_rebuilds_the_new_text() {
    runner(2000)
        .run(&pair(60), |(old, new)| {
            let (a, b) = (diff_lines::split_lines(&old), diff_lines::split_lines(&new));
            let ours = diff_lines::diff(&a, &b);
            let theirs: Vec<Op> = similar::capture_diff_slices(similar::Algorithm::Myers, &a, &b)
                .iter()
                .map(from_similar)
                .collect();
            prop_assert_eq!(cost(&ours), cost(&theirs));
            prop_assert_eq!(apply(&a, &b, &ours), b);
            Ok(())
        })
        .unwrap();
}

#[test]
fn the_unified_diff_is_similars_byte_for_byte() {
    runner(3000)
        .run(&pair(40), |(old, new)| {
            let ours = diff_lines::unified(&old, &new, 3, "a/robot.urdf", "b/robot.urdf");
            prop_assert_eq!(ours, similar_unified(&old, &new));
            Ok(())
        })
        .unwrap();
}

#[test]
fn the_unified_diff_of_long_texts_is_similars_byte_for_byte() {
    // Past 100 lines `similar` diffs the trimmed middle of integer ids and
    // past 64 ops compacts in a gap buffer: the same answer, other paths.
    runner(200)
        .run(&pair(260), |(old, new)| {
            let ours = diff_lines::unified(&old, &new, 3, "a/robot.urdf", "b/robot.urdf");
            prop_assert_eq!(ours, similar_unified(&old, &new));
            Ok(())
        })
        .unwrap();
}

#[test]
fn no_newline_at_the_end_is_marked_as_similar_marks_it() {
    for (old, new) in [
        ("a\nb", "a\nb\n"),
        ("a\nb\n", "a\nb"),
        ("", "x"),
        ("x", ""),
        ("a\r\nb\r", "a\r\nc\r"),
    ] {
        let ours = diff_lines::unified(old, new, 3, "a/robot.urdf", "b/robot.urdf");
        assert_eq!(ours, similar_unified(old, new), "{old:?} → {new:?}");
    }
}

#[test]
fn two_large_texts_with_nothing_in_common_stop_at_the_work_budget() {
    // 200 000 lines each, no line shared: an exact search would take
    // about 4·10¹⁰ steps, D = 400 000 at every one of them.
    let old: Vec<String> = (0..200_000).map(|i| format!("{}", i % 3)).collect();
    let new: Vec<String> = (0..200_000).map(|i| format!("{}", 3 + i % 2)).collect();
    let (ops, work) = diff_lines::diff_counting(&old, &new);
    assert!(work <= MAX_WORK + 1, "{work} steps");
    assert_eq!(
        ops,
        [Op::Replace {
            old: 0,
            old_len: 200_000,
            new: 0,
            new_len: 200_000
        }]
    );
}

#[test]
fn a_large_text_with_many_repeated_lines_stops_at_the_work_budget_with_a_valid_script() {
    let old: Vec<&str> = (0..100_000)
        .map(|i| if i % 7 == 0 { "x" } else { "y" })
        .collect();
    let new: Vec<&str> = (0..100_000)
        .map(|i| if i % 5 == 0 { "x" } else { "z" })
        .collect();
    let (ops, work) = diff_lines::diff_counting(&old, &new);
    assert!(work <= MAX_WORK + 100_000, "{work} steps");
    assert_eq!(apply(&old, &new, &ops), new);
}

// JUnit: massprop's writer and quick-junit given the same report.

use massprop::output::junit;

/// Characters a hostile name or message is made of: XML's specials, the
/// CDATA end, every kind of control (C0 but ESC, DEL, C1), noncharacters,
/// separators, bidirectional overrides, non-ASCII.
const HOSTILE: [&str; 24] = [
    "a", "Z", " ", "<", ">", "&", "\"", "'", "]]>", "\n", "\r", "\t", "\0", "\x07", "\x1f", "\x7f",
    "\u{85}", "\u{9b}", "\u{fffe}", "\u{ffff}", "é", "𝄞", "\u{202e}", "\u{2028}",
];

fn hostile() -> impl Strategy<Value = String> {
    proptest::collection::vec(0..HOSTILE.len(), 0..12)
        .prop_map(|v| v.into_iter().map(|i| HOSTILE[i]).collect())
}

/// A test case's parts: name, class, and none (success) or a failure or
/// error's type, message and text.
type CaseParts = (String, String, Option<(bool, String, String, String)>);
/// A suite's parts: name, cases, standard error.
type SuiteParts = (String, Vec<CaseParts>, Option<String>);

fn suites() -> impl Strategy<Value = Vec<SuiteParts>> {
    let status = proptest::option::of((any::<bool>(), hostile(), hostile(), hostile()));
    let case = (hostile(), hostile(), status);
    let suite = (
        hostile(),
        proptest::collection::vec(case, 0..5),
        proptest::option::of(hostile()),
    );
    proptest::collection::vec(suite, 0..4)
}

/// Both writers' output for the same report, every text first mapped by
/// `text` (as `check --format junit` maps each by `diag::visible`).
fn both(name: &str, suites: &[SuiteParts], text: impl Fn(&str) -> String) -> (String, String) {
    use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};
    let mut theirs = Report::new(text(name));
    let mut ours = junit::Report {
        name: text(name),
        suites: Vec::new(),
    };
    for (suite_name, cases, err) in suites {
        let mut suite = TestSuite::new(text(suite_name));
        let mut our_cases = Vec::new();
        for (case_name, class, status) in cases {
            let (their_status, our_status) = match status {
                None => (TestCaseStatus::success(), junit::Status::Success),
                Some((error, ty, message, description)) => {
                    let kind = if *error {
                        NonSuccessKind::Error
                    } else {
                        NonSuccessKind::Failure
                    };
                    let mut s = TestCaseStatus::non_success(kind);
                    s.set_type(text(ty))
                        .set_message(text(message))
                        .set_description(text(description));
                    let ours = junit::Status::NonSuccess {
                        error: *error,
                        ty: text(ty),
                        message: text(message),
                        description: text(description),
                    };
                    (s, ours)
                }
            };
            let mut c = TestCase::new(text(case_name), their_status);
            c.set_classname(text(class));
            suite.add_test_case(c);
            our_cases.push(junit::Case {
                name: text(case_name),
                classname: text(class),
                status: our_status,
            });
        }
        if let Some(e) = err {
            suite.set_system_err(text(e));
        }
        theirs.add_test_suite(suite);
        ours.suites.push(junit::Suite {
            name: text(suite_name),
            cases: our_cases,
            system_err: err.as_deref().map(&text),
        });
    }
    let mut theirs = theirs.to_string().unwrap();
    if !theirs.ends_with('\n') {
        theirs.push('\n');
    }
    (junit::write(&ours), theirs)
}

#[test]
fn the_junit_xml_is_quick_junits_byte_for_byte_for_hostile_raw_text() {
    runner(2000)
        .run(&(hostile(), suites()), |(name, suites)| {
            let (ours, theirs) = both(&name, &suites, str::to_string);
            prop_assert_eq!(ours, theirs);
            Ok(())
        })
        .unwrap();
}

#[test]
fn the_junit_xml_is_quick_junits_byte_for_byte_for_text_shown_as_check_shows_it() {
    // With ESC too: `diag::visible` shows it as a picture, as every text
    // `check --format junit` writes.
    let with_esc = (hostile(), suites()).prop_map(|(n, s)| (format!("\x1b[31m{n}"), s));
    runner(1000)
        .run(&with_esc, |(name, suites)| {
            let (ours, theirs) = both(&name, &suites, massprop::diag::visible);
            prop_assert_eq!(ours, theirs);
            Ok(())
        })
        .unwrap();
}

#[test]
fn a_report_without_suites_is_quick_junits() {
    let (ours, theirs) = both("massprop check", &[], str::to_string);
    assert_eq!(ours, theirs);
}
