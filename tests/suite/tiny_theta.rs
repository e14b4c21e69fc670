//! Sharp wedges (Theta from 1e-8 to 0.01 degrees, coupling on): the f64 path gives a positive
//! V that agrees with the 30-digit path to its own estimate, or refuses on one line naming
//! theta_deg; never a negative speed with exit code 0. The edge exponent of these cases lies
//! within 1e-4 .. 1e-10 of -1 (`docs/errata.md`, section 11). And the flags and the grid of
//! `wedge curve`: the admissibility flags per row, a grid spaced at f64's resolution at
//! least, the requested alpha kept whatever `--digits` prints.

use crate::common;

use common::{num, run};
use rug::Float;
use serde_json::Value;
use wedge::Material;

fn wedge(args: &[&str]) -> (i32, String, String) {
    run(env!("CARGO_BIN_EXE_wedge"), args)
}

/// The angles of the tests, in degrees.
const THETAS: [&str; 8] = [
    "1e-8", "1e-6", "1e-4", "0.001", "0.003", "0.005", "0.007", "0.01",
];

/// Half the Rayleigh speed of the paper's material (m/s), and the slow speed of the report
/// that found the f64 path wrong.
fn alphas() -> [String; 2] {
    let c_r = Material::paper().m_r().unwrap() * 1870.83;
    [format!("{:.6}", 0.5 * c_r), "42.13196158036146".to_string()]
}

/// A JSON number read exactly (all its digits) at 200 bits.
fn big(v: &Value) -> Float {
    Float::with_val(200, Float::parse(v.to_string()).unwrap())
}

/// `wedge solve` at `theta` and `alpha`, f64 (`digits` None) or more digits: the JSON report,
/// or the refusal's message after checking that it is one line with exit code 2 naming theta.
fn solve(theta: &str, alpha: &str, digits: Option<&str>) -> Result<Value, String> {
    let mut args = vec!["solve", "--theta-deg", theta, "--alpha", alpha, "--json"];
    if let Some(d) = digits {
        args.extend(["--digits", d]);
    }
    let (code, out, err) = wedge(&args);
    if code == 0 {
        return Ok(serde_json::from_str(&out).unwrap());
    }
    assert_eq!(code, 2, "{args:?}: {err}");
    assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{err}");
    Err(err)
}

#[test]
fn sharp_wedges_give_a_positive_speed_or_refuse_naming_theta() {
    let mut answered = 0;
    for theta in THETAS {
        for alpha in alphas() {
            let what = format!("theta {theta} deg, alpha {alpha} m/s");
            // the 30-digit path answers every one of these angles
            let fine = solve(theta, &alpha, Some("30")).unwrap_or_else(|e| panic!("{what}: {e}"));
            let v30 = big(&fine["v_over_c1_cot_theta"]);
            assert!(v30 > 0, "{what}: 30 digits: V = {v30}");
            match solve(theta, &alpha, None) {
                Ok(r) => {
                    let v = num(&r["v_over_c1_cot_theta"]);
                    let speed = num(&r["speed"]);
                    assert!(v > 0.0 && speed > 0.0, "{what}: V = {v}, speed {speed}");
                    assert_eq!(r["speed_positive"], true, "{what}");
                    assert_eq!(r["force_compressive"], true, "{what}");
                    // agrees with the 30-digit path to the f64 path's own estimate
                    let est = num(&r["error_estimates"]["v_over_c1_cot_theta"]);
                    let est30 = num(&fine["error_estimates"]["v_over_c1_cot_theta"]);
                    let diff = (big(&r["v_over_c1_cot_theta"]) - &v30).abs().to_f64();
                    assert!(
                        diff <= est + est30,
                        "{what}: |{v} - {v30}| = {diff:e} > {est:e}"
                    );
                    assert!(est < wedge::MAX_REL_ERROR * v, "{what}: estimate {est:e}");
                    answered += 1;
                }
                Err(e) => assert!(e.contains("theta_deg"), "{what}: {e}"),
            }
        }
    }
    // the f64 path reaches every angle down to 1e-6 degrees (it used to print the wrong sign
    // below 0.005)
    assert!(answered >= 14, "only {answered} of 16 answered in f64");
}

#[test]
fn the_reported_case_is_positive_and_matches_the_higher_precisions() {
    // Theta = 0.001 deg, alpha = 42.13196158036146 m/s: V/(c1 cot Theta) = +3.3404920460e-6
    // (it was -0.116 in f64 with every flag true, and refused at 30 digits)
    let alpha = "42.13196158036146";
    let f = solve("0.001", alpha, None).unwrap();
    let d30 = solve("0.001", alpha, Some("30")).unwrap();
    let d40 = solve("0.001", alpha, Some("40")).unwrap();
    let (v, v30, v40) = (
        big(&f["v_over_c1_cot_theta"]),
        big(&d30["v_over_c1_cot_theta"]),
        big(&d40["v_over_c1_cot_theta"]),
    );
    let rel = |a: &Float, b: &Float| (Float::with_val(200, a - b) / b).abs().to_f64();
    assert!(rel(&v, &v40) < 1e-10, "f64 {v} vs {v40}");
    assert!(rel(&v30, &v40) < 1e-24, "30 digits {v30} vs {v40}");
    assert!((num(&f["v_over_c1_cot_theta"]) - 3.340492046e-6).abs() < 1e-15);
    for k in [
        "slip_direction_ok",
        "contact_compressive",
        "no_interpenetration",
        "speed_positive",
        "force_compressive",
    ] {
        assert_eq!(f[k], true, "{k}");
        assert_eq!(d30[k], true, "{k}");
    }
}

#[test]
fn below_the_resolved_angles_f64_refuses_naming_theta() {
    // V is lost to the cancellation of eq (53) once cot Theta nears 1/eps: f64 refuses with
    // the angles it resolves, the 30-digit path still answers
    for theta in ["1e-12", "1e-20"] {
        let e = solve(theta, "463.7", None).unwrap_err();
        assert!(e.contains(&format!("theta_deg = {theta}")), "{e}");
        assert!(e.contains("degrees") && e.contains("cancel"), "{e}");
        let fine = solve(theta, "463.7", Some("30")).unwrap();
        assert!(num(&fine["v_over_c1_cot_theta"]) > 0.0);
    }
    // cot Theta beyond the f64 range
    let e = solve("1e-310", "463.7", None).unwrap_err();
    assert!(e.contains("theta_deg"), "{e}");
}

#[test]
fn sharp_wedge_curves_give_positive_speeds_or_refuse_naming_theta() {
    for theta in THETAS {
        let args = [
            "curve",
            "--theta-deg",
            theta,
            "--alpha-range",
            "40,900,3",
            "--json",
        ];
        let (code, out, err) = wedge(&args);
        if code != 0 {
            assert_eq!(code, 2, "{args:?}: {err}");
            assert_eq!(err.trim().lines().count(), 1, "{err}");
            assert!(err.contains("theta_deg"), "{err}");
            continue;
        }
        let rows: Value = serde_json::from_str(&out).unwrap();
        let rows = rows.as_array().unwrap();
        assert_eq!(rows.len(), 3, "{theta}");
        for r in rows {
            assert!(num(&r["v_over_c1_cot_theta"]) > 0.0, "{theta}: {r}");
            assert!(num(&r["speed"]) > 0.0, "{theta}: {r}");
            for k in ["speed_positive", "force_compressive", "contact_compressive"] {
                assert_eq!(r[k], true, "{theta}: {k}");
            }
        }
    }
}

/// The CSV of `wedge curve`: the '#' lines and the rows as maps from the header's columns.
fn csv(args: &[&str]) -> (Vec<String>, Vec<Vec<(String, String)>>) {
    let (code, out, err) = wedge(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    let comments: Vec<String> = out
        .lines()
        .filter(|l| l.starts_with('#'))
        .map(String::from)
        .collect();
    let mut data = out.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = data.next().unwrap().split(',').collect();
    let rows = data
        .map(|l| {
            header
                .iter()
                .zip(l.split(','))
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect()
        })
        .collect();
    (comments, rows)
}

fn cell<'a>(row: &'a [(String, String)], key: &str) -> &'a str {
    &row.iter().find(|(k, _)| k == key).unwrap().1
}

#[test]
fn curve_rows_carry_the_admissibility_flags() {
    let flags = [
        "slip_direction_ok",
        "contact_compressive",
        "no_interpenetration",
        "speed_positive",
        "force_compressive",
    ];
    // an admissible curve: every flag present and true, in f64 and at 30 digits (the sampled
    // checks on the f64 twin), for both solution variants
    for extra in [
        &["--theta-deg", "86", "--gamma", "0"][..],
        &["--theta-deg", "86", "--gamma", "0", "--digits", "30"],
        &["--theta-deg", "86", "--gamma", "0.4"],
        &["--theta-deg", "0.001", "--gamma", "0"],
    ] {
        let mut args = vec!["curve", "--alpha-range", "10,600,4"];
        args.extend_from_slice(extra);
        let (comments, rows) = csv(&args);
        assert!(
            comments.iter().any(|l| l.starts_with("# admissibility")),
            "{args:?}: {comments:?}"
        );
        assert_eq!(rows.len(), 4, "{args:?}");
        for row in &rows {
            for k in flags {
                assert_eq!(cell(row, k), "true", "{args:?}: {k} in {row:?}");
            }
        }
        // and in the JSON rows
        args.push("--json");
        let (code, out, err) = wedge(&args);
        assert_eq!(code, 0, "{err}");
        let v: Value = serde_json::from_str(&out).unwrap();
        for row in v.as_array().unwrap() {
            for k in flags {
                assert_eq!(row[k], true, "{args:?}: {k}");
            }
        }
    }
    // a row whose sampled checks cannot be made says why on a '#' line after it: at 30
    // digits below the angles f64 resolves, the f64 twin refuses
    let (comments, rows) = csv(&[
        "curve",
        "--theta-deg",
        "1e-12",
        "--alpha-range",
        "400,500,2",
        "--digits",
        "30",
    ]);
    for row in &rows {
        assert_eq!(cell(row, "speed_positive"), "true");
        assert_eq!(cell(row, "no_interpenetration"), "");
    }
    assert!(
        comments
            .iter()
            .any(|l| l.contains("no_interpenetration unavailable") && l.contains("theta_deg")),
        "{comments:?}"
    );
}

#[test]
fn a_grid_spaced_below_f64_resolution_is_refused() {
    for range in ["100,100.00000000000001,3", "500,500.0000000000001,1000"] {
        let (code, out, err) = wedge(&["curve", "--theta-deg", "86", "--alpha-range", range]);
        assert_eq!(code, 2, "{range}: {out}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(
            err.contains("alpha_range") && err.contains("resolution"),
            "{err}"
        );
    }
    // at f64's resolution it is computed, each point a different double
    let (code, out, err) = wedge(&[
        "curve",
        "--theta-deg",
        "86",
        "--alpha-range",
        "500,500.0000000000003,3",
        "--json",
        "--quantities",
        "p",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let alphas: Vec<f64> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|r| num(&r["alpha"]))
        .collect();
    assert!(alphas.windows(2).all(|w| w[1] > w[0]), "{alphas:?}");
}

#[test]
fn digits_keep_the_requested_grid() {
    // 177.18 .. 676.719 in 5 steps: the grid of the request at full precision, whatever
    // digits the other quantities print (it used to come out as 200 .. 700 at 1 digit)
    let exact = ["177.18", "302.06475", "426.9495", "551.83425", "676.719"];
    for digits in ["1", "2", "3", "30"] {
        let args = [
            "curve",
            "--theta-deg",
            "86",
            "--alpha-range",
            "177.18,676.719,5",
            "--digits",
            digits,
        ];
        let (_, rows) = csv(&args);
        let got: Vec<&str> = rows.iter().map(|r| cell(r, "alpha")).collect();
        assert_eq!(got, exact, "--digits {digits}");
        let mut json = args.to_vec();
        json.push("--json");
        let (code, out, err) = wedge(&json);
        assert_eq!(code, 0, "{err}");
        let v: Value = serde_json::from_str(&out).unwrap();
        let rows = v.as_array().expect("a list of rows");
        let got: Vec<String> = rows.iter().map(|r| r["alpha"].to_string()).collect();
        assert_eq!(got, exact, "--digits {digits} (JSON)");
        // p is alpha/c1 of those values, to the digits printed
        for (r, a) in rows.iter().zip(exact) {
            let p = num(&r["p"]);
            let want = a.parse::<f64>().unwrap() / 1870.83;
            let d: usize = digits.parse().unwrap();
            let tol = (0.5 * 10f64.powi(1 - d as i32)).max(4.0 * f64::EPSILON);
            assert!((p - want).abs() <= tol * want, "{p} {want}");
        }
    }
    // a grid value that is not a short decimal keeps the working precision's digits
    let (_, rows) = csv(&[
        "curve",
        "--theta-deg",
        "86",
        "--alpha-range",
        "100,200,4",
        "--digits",
        "2",
    ]);
    let a = cell(&rows[1], "alpha");
    assert!(a.starts_with("133.33333333333333333333333333"), "{a}");
    // solve echoes the alpha it was given
    let v = solve("86", "177.18", Some("2")).unwrap();
    assert_eq!(v["alpha"].to_string(), "177.18");
}
