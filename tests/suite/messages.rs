//! The seams a new user meets first: every usage error names every missing or bad flag in
//! its one line; a call without a subcommand prints the usage; a closed standard output ends
//! quietly; numbers in messages stay readable; the help texts say what each program is and
//! name every striker kind.

use std::process::{Command, Stdio};

const WEDGE: &str = env!("CARGO_BIN_EXE_wedge");
const IMPACT: &str = env!("CARGO_BIN_EXE_impact");

/// (exit code, stdout, stderr).
fn call(bin: &str, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(bin).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn every_usage_error_names_its_flags() {
    let cases: Vec<(&str, Vec<&str>, Vec<&str>)> = vec![
        (
            WEDGE,
            vec!["solve", "--theta-deg", "86"],
            vec!["--alpha or --speed"],
        ),
        (
            WEDGE,
            vec!["solve"],
            vec!["--theta-deg", "--alpha or --speed"],
        ),
        (
            WEDGE,
            vec!["stress", "--theta-deg", "86", "--alpha", "500"],
            vec!["--at"],
        ),
        (
            WEDGE,
            vec!["field", "--theta-deg", "86"],
            vec!["--at", "--alpha or --speed"],
        ),
        (
            WEDGE,
            vec!["curve", "--gamma", "0.4"],
            vec!["--theta-deg", "--alpha-range"],
        ),
        (
            WEDGE,
            vec!["solve", "--theta-deg", "abc", "--alpha", "500"],
            vec!["theta_deg"],
        ),
        (
            WEDGE,
            vec!["solve", "--theta-deg", "86", "--alpha", "500", "--bogus"],
            vec!["--bogus"],
        ),
        (
            WEDGE,
            vec![
                "solve",
                "--theta-deg",
                "86",
                "--alpha",
                "500",
                "--speed",
                "10",
            ],
            vec!["--alpha", "--speed"],
        ),
        (
            IMPACT,
            vec!["run"],
            vec!["--profile", "--mass-ratio", "--v0-over-c1", "--end"],
        ),
        (
            IMPACT,
            vec!["run", "--poisson", "0.25", "--profile", "circle:R=1"],
            vec!["--mass-ratio", "--v0-over-c1", "--end"],
        ),
        (
            IMPACT,
            vec![
                "run",
                "--poisson",
                "0.25",
                "--profile",
                "circle:R=1",
                "--mass-ratio",
                "10",
                "--end",
                "c1t/R=1",
            ],
            vec!["--v0-over-c1"],
        ),
        (
            IMPACT,
            vec![
                "run",
                "--poisson",
                "0.25",
                "--profile",
                "circle:R=1",
                "--v0-over-c1",
                "0.01",
                "--end",
                "c1t/R=1",
                "--kappa",
                "x",
            ],
            vec!["--kappa"],
        ),
        (
            IMPACT,
            vec![
                "run",
                "--poisson",
                "abc",
                "--profile",
                "circle:R=1",
                "--mass-ratio",
                "1",
                "--v0-over-c1",
                "0.01",
                "--end",
                "c1t/R=1",
            ],
            vec!["--poisson"],
        ),
        (
            IMPACT,
            vec!["edge", "--poisson", "0.25"],
            vec!["--speed-over-c1"],
        ),
        (IMPACT, vec!["edge", "--c1", "1870"], vec!["--c1 and --c2"]),
        (IMPACT, vec!["green", "--at", "0.1"], vec!["--poisson"]),
        (
            IMPACT,
            vec!["green", "--poisson", "0.25"],
            vec!["--at", "--cells", "--constants"],
        ),
        (IMPACT, vec!["bogus"], vec!["bogus"]),
    ];
    for (bin, args, flags) in cases {
        let (code, out, err) = call(bin, &args);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        for f in flags {
            assert!(err.contains(f), "{args:?}: {f} not named in {err}");
        }
    }
}

#[test]
fn a_missing_subcommand_prints_the_usage() {
    for (bin, name, first, sub) in [
        (WEDGE, "wedge", "rigid wedge", "curve"),
        (IMPACT, "impact", "transient impact", "green"),
    ] {
        let (code, out, err) = call(bin, &[]);
        assert_eq!(code, 2, "{name}: {out}");
        assert!(err.contains("Usage:"), "{name}: {err}");
        assert!(err.contains(first), "{name}: {err}");
        assert!(err.contains(sub), "{name}: {err}");
    }
}

#[test]
fn help_says_what_each_program_is() {
    let (_, wedge_help, _) = call(WEDGE, &["--help"]);
    let first = wedge_help.lines().next().unwrap();
    assert!(first.contains("rigid wedge"), "{first}");
    let (_, impact_help, _) = call(IMPACT, &["--help"]);
    let first = impact_help.lines().next().unwrap();
    assert!(first.contains("transient impact"), "{first}");
    for kind in ["rigid", "elastic", "cylinder", "shell"] {
        assert!(impact_help.contains(kind), "impact --help: {kind}");
    }
    let (_, run_help, _) = call(IMPACT, &["run", "--help"]);
    for kind in ["rigid", "elastic", "cylinder", "shell"] {
        assert!(run_help.contains(kind), "impact run --help: {kind}");
    }
}

/// A closed standard output (`... | true`, `... | head -1`) ends the program quietly: no
/// panic, exit code 0, nothing on stderr.
#[test]
fn a_closed_stdout_ends_quietly() {
    let runs: Vec<Vec<&str>> = vec![
        vec![
            WEDGE,
            "solve",
            "--theta-deg",
            "86",
            "--gamma",
            "0.6",
            "--alpha",
            "561.249",
            "--json",
        ],
        vec![
            WEDGE,
            "stress",
            "--theta-deg",
            "86",
            "--alpha",
            "561.249",
            "--at",
            "0.5",
            "--json",
        ],
        vec![
            WEDGE,
            "field",
            "--theta-deg",
            "86",
            "--alpha",
            "561.249",
            "--at",
            "0.1:-0.1",
        ],
        vec![
            WEDGE,
            "curve",
            "--theta-deg",
            "86",
            "--gamma",
            "0.4",
            "--alpha-range",
            "10,920,400",
        ],
        vec![
            IMPACT,
            "green",
            "--poisson",
            "0.3",
            "--at",
            "0.1,0.5",
            "--json",
        ],
        vec![IMPACT, "edge", "--poisson", "0.3", "--speed-over-c1", "0.3"],
        vec![
            IMPACT,
            "run",
            "--poisson",
            "0.25",
            "--profile",
            "circle:R=1",
            "--mass-ratio",
            "10",
            "--v0-over-c1",
            "0.01",
            "--end",
            "c1t/R=1",
            "--dx",
            "0.02",
        ],
    ];
    for args in runs {
        let mut child = Command::new(args[0])
            .args(&args[1..])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // the reader goes away before the program writes
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
        assert!(err.is_empty(), "{args:?}: {err}");
    }
}

/// A refusal quotes its numbers at a readable width, however many digits they were given
/// or computed with.
#[test]
fn numbers_in_messages_are_short() {
    let long = format!("0.{}", "3".repeat(400));
    for args in [
        vec![
            "solve",
            "--theta-deg",
            "86",
            "--gamma",
            "cot",
            "--alpha",
            "5000",
        ],
        vec!["solve", "--theta-deg", long.as_str(), "--alpha", "5000"],
        vec!["solve", "--theta-deg", "91", "--alpha", long.as_str()],
        vec![
            "solve",
            "--theta-deg",
            "86",
            "--alpha",
            "5000",
            "--digits",
            "300",
        ],
    ] {
        let (code, _, err) = call(WEDGE, &args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.len() < 400, "{args:?}: {} characters: {err}", err.len());
    }
}
