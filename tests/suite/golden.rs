//! The command lines' output, byte for byte, for the fixed runs of `tests/golden/cases.txt`
//! against the outputs saved before the report layer's refactor (`tests/golden/*.out`,
//! written by `tests/golden/capture.sh`): the reports are typed now, and their JSON and CSV
//! must not have changed but for the inputs the stress and field reports now echo.

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

/// The key an impact run's grid gained after the refactor (the memory the run was estimated
/// to need), removed before the comparison.
const ADDED_GRID_KEY: &str = "estimated_memory_gib";

/// The quantity an impact run declared under `unavailable` after the refactor (the edge's
/// speed, which has no estimate), removed before the comparison.
const ADDED_UNAVAILABLE: &str = "bdot_over_c1";

/// The histories whose estimates became sharper after the refactor (`docs/impact.md`,
/// section 5): each new estimate must be finite and at most the saved one, which the
/// comparison then takes.
const SHARPENED: &[&str] = &["h_over_R", "b_over_R", "force_over_rho_c1sq_R"];

/// A sharpened estimate checked against the saved one.
fn sharpened(new: f64, old: f64, what: &str) {
    assert!(
        new.is_finite() && new >= 0.0 && new <= old * (1.0 + 1e-12),
        "{what}: the estimate {new} is not within the saved {old}"
    );
}

/// The CSV table of an impact run with the sharpened estimates checked against the saved
/// table and replaced by its cells, and the added `# error_model` lines removed.
fn with_saved_estimates(text: &str, expected: &str) -> String {
    assert!(
        text.lines().any(|l| l.starts_with("# error_model: ")),
        "the CSV states its error models"
    );
    let mut old = expected.lines().filter(|l| !l.starts_with('#'));
    let mut header: Option<Vec<&str>> = None;
    let mut out = String::new();
    for line in text.lines() {
        if line.starts_with("# error_model: ") {
            continue;
        }
        let saved = if line.starts_with('#') {
            None
        } else {
            old.next()
        };
        let mut cells: Vec<&str> = line.split(',').collect();
        match (&header, saved) {
            (None, Some(_)) => header = Some(cells.clone()),
            (Some(h), Some(o)) => {
                let oc: Vec<&str> = o.split(',').collect();
                if cells.len() == h.len() && oc.len() == h.len() {
                    for (i, key) in h.iter().enumerate() {
                        let sharp = SHARPENED
                            .iter()
                            .any(|s| key.strip_prefix("err_") == Some(*s));
                        if let (true, Ok(a), Ok(b)) = (sharp, cells[i].parse(), oc[i].parse()) {
                            sharpened(a, b, key);
                            cells[i] = oc[i];
                        }
                    }
                }
            }
            _ => {}
        }
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    out
}

/// An impact run's output with the grid's added key removed: from the JSON's grid object, or
/// from the grid echoed in the CSV's header; the added `error_model` removed and the sharpened
/// estimates checked against the saved ones ([`SHARPENED`]).
fn without_added_grid_key(text: &str, expected: &str) -> String {
    if text.starts_with('{') {
        let mut v: Value = serde_json::from_str(text).expect("JSON output");
        let saved: Value = serde_json::from_str(expected).expect("saved JSON output");
        let models = v
            .as_object_mut()
            .and_then(|o| o.shift_remove("error_model"));
        assert!(
            models.is_some_and(|m| m.is_object()),
            "the run states its error models"
        );
        for key in SHARPENED {
            let (Some(new), Some(old)) = (
                v["error_estimate"].get(*key).and_then(Value::as_array),
                saved["error_estimate"].get(*key),
            ) else {
                continue;
            };
            for (a, b) in new.iter().zip(old.as_array().into_iter().flatten()) {
                sharpened(
                    a.as_f64().unwrap_or(f64::NAN),
                    b.as_f64().unwrap_or(0.0),
                    key,
                );
            }
            v["error_estimate"][*key] = old.clone();
        }
        let removed = v
            .get_mut("grid")
            .and_then(Value::as_object_mut)
            .and_then(|g| g.remove(ADDED_GRID_KEY));
        assert!(
            removed.is_some_and(|m| m.as_f64().is_some_and(|x| x > 0.0)),
            "the grid states its estimated memory"
        );
        let declared = v
            .get_mut("unavailable")
            .and_then(Value::as_object_mut)
            .and_then(|u| u.shift_remove(ADDED_UNAVAILABLE));
        assert!(
            declared.is_some_and(|r| r.is_string()),
            "the edge's speed is declared without an estimate"
        );
        return if expected.trim_end().contains('\n') {
            serde_json::to_string_pretty(&v).unwrap() + "\n"
        } else {
            v.to_string() + "\n"
        };
    }
    let text = with_saved_estimates(text, expected);
    let key = format!(",\"{ADDED_GRID_KEY}\":");
    let declared = format!("# unavailable: {ADDED_UNAVAILABLE}: ");
    text.lines()
        .filter(|line| !line.starts_with(&declared))
        .map(|line| match line.find(&key) {
            Some(at) if line.starts_with('#') => {
                let rest = &line[at + key.len()..];
                let end = rest.find([',', '}']).unwrap_or(rest.len());
                format!("{}{}\n", &line[..at], &rest[end..])
            }
            _ => format!("{line}\n"),
        })
        .collect()
}

/// The output with the added keys of the stress and field reports removed (the solve
/// report echoed its inputs already), serialised as the programs do.
fn without_added(name: &str, text: &str, expected: &str) -> String {
    if name.starts_with("impact_run") {
        return without_added_grid_key(text, expected);
    }
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
