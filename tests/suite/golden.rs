//! The command lines' output, byte for byte, for the fixed runs of `tests/golden/cases.txt`
//! against the outputs saved before the report layer's refactor (`tests/golden/*.out`,
//! written by `tests/golden/capture.sh`): the reports are typed now, and their JSON and CSV
//! must not have changed but for the inputs the stress and field reports now echo. The impact
//! runs' outputs were captured again when the histories' estimates were sharpened
//! (`docs/impact.md`, section 5): every value was checked unchanged, the estimates of h, b and
//! the force no larger, the work's no smaller (it reads its own level differences now, and a
//! driven run's work gained an estimate), beside the added `error_model`, the grid's
//! `estimated_memory_gib` and the edge's speed declared under `unavailable`; b's estimate was
//! then raised to half the finest cell where the edge is captured cell by cell (the elastic
//! striker and the shell, no smaller than before). They were captured again when the levels
//! began to start on finer grids (`docs/impact.md`, section 11): every changed value moved by
//! at most half the sum of its old and new stated errors (the early b and force most), and
//! the grid gained `start_halvings`.

use std::path::Path;
use std::process::Command;

use serde_json::Value;

/// Keys the JSON of a report gained in the refactor (the inputs echoed), removed before the
/// comparison.
const ADDED_KEYS: &[&str] = &[
    "c1",
    "c2",
    "theta_deg",
    "gamma",
    "coupling",
    "alpha",
    "speed",
];

fn bin(name: &str) -> &'static str {
    match name {
        "wedge" => env!("CARGO_BIN_EXE_wedge"),
        "impact" => env!("CARGO_BIN_EXE_impact"),
        other => panic!("no program {other}"),
    }
}

/// The output with the added keys of the stress and field reports removed (the solve
/// report echoed its inputs already), serialised as the programs do.
fn without_added(name: &str, text: &str, expected: &str) -> String {
    let added = name.starts_with("wedge_stress") || name.starts_with("wedge_field");
    if !added || !name.ends_with("json") {
        return text.to_string();
    }
    let mut v: Value = serde_json::from_str(text).expect("JSON output");
    if let Value::Object(m) = &mut v {
        for k in ADDED_KEYS {
            assert!(
                m.remove(*k).is_some() || *k == "speed" || *k == "alpha",
                "{name}: {k} not echoed"
            );
        }
    }
    if expected.trim_end().contains('\n') {
        serde_json::to_string_pretty(&v).unwrap() + "\n"
    } else {
        v.to_string() + "\n"
    }
}

/// The runs that cost seconds each, left to the `--ignored` tier: the genuine solution's
/// inverse solve at 40 digits (about 12 s).
const HEAVY: &[&str] = &["wedge_solve_speed_digits40"];

/// Every run but the heavy ones.
#[test]
fn outputs_are_unchanged_byte_for_byte() {
    check(false);
}

/// Every run.
#[test]
#[ignore]
fn outputs_are_unchanged_byte_for_byte_every_run() {
    check(true);
}

fn check(heavy: bool) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let cases = std::fs::read_to_string(dir.join("cases.txt")).unwrap();
    let mut checked = 0;
    for line in cases.lines() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let (name, cmd) = line.split_once('\t').expect("NAME<TAB>COMMAND");
        if !heavy && HEAVY.contains(&name) {
            continue;
        }
        let mut words = cmd.split_whitespace();
        let program = words.next().unwrap();
        let path = bin(program);
        let out = Command::new(path)
            .args(words)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout)
            .unwrap()
            .replace(path, program);
        let expected = std::fs::read_to_string(dir.join(format!("{name}.out"))).unwrap();
        let got = without_added(name, &text, &expected);
        if got != expected {
            let first = got
                .lines()
                .zip(expected.lines())
                .position(|(a, b)| a != b)
                .unwrap_or(0);
            panic!(
                "{name}: the output changed at line {}:\n got: {:.300}\nwant: {:.300}",
                first + 1,
                got.lines().nth(first).unwrap_or(""),
                expected.lines().nth(first).unwrap_or("")
            );
        }
        checked += 1;
    }
    assert!(checked >= 20, "only {checked} cases");
}
