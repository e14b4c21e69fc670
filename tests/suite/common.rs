//! Running the binaries from the integration tests.
#![allow(dead_code)]

use std::process::Command;

use serde_json::Value;

/// Run `exe` with `args`: (exit code, stdout, stderr).
pub fn run(exe: &str, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(exe).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Run `exe` with `args`, require success and parse its JSON output.
pub fn run_json(exe: &str, args: &[&str]) -> Value {
    let (code, out, err) = run(exe, args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// A JSON number (arbitrary-precision numbers included) as f64.
pub fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| v.to_string().parse().unwrap())
}
