//! No silent wrong number from `wedge`: a non-finite integral is an error naming the case's
//! inputs (never a null or a zero with exit code 0), an optional quantity that cannot be
//! computed is declared unavailable with its reason while the rest of the report stands, and
//! over random valid inputs no reported field is null unless declared so.

use crate::common;

use common::{num, run, run_json};
use serde_json::Value;

fn wedge(args: &[&str]) -> (i32, String, String) {
    run(env!("CARGO_BIN_EXE_wedge"), args)
}

/// Run `wedge`, require success, parse its JSON.
fn json(args: &[&str]) -> Value {
    run_json(env!("CARGO_BIN_EXE_wedge"), args)
}

/// Every key is a finite number, a string or a boolean, or it is null and declared under
/// `unavailable` with a reason.
fn assert_declared(v: &Value, what: &str) {
    let o = v.as_object().expect("a JSON object");
    let declared = o.get("unavailable").and_then(Value::as_object);
    for (k, x) in o {
        match x {
            Value::Null => {
                let reason = declared.and_then(|d| d.get(k)).and_then(Value::as_str);
                assert!(
                    reason.is_some_and(|r| !r.is_empty()),
                    "{what}: {k} is null without a reason"
                );
            }
            Value::Number(_) => assert!(num(x).is_finite(), "{what}: {k} = {x}"),
            _ => {}
        }
    }
}

/// Sharp wedges with strong coupling overflow the f64 path: refused on one line naming the
/// inputs, not printed as null (or as V = 0).
#[test]
fn overflowing_cases_are_refused_with_their_inputs() {
    for (theta, alpha) in [("1", "98"), ("2", "98"), ("3", "800"), ("6", "10")] {
        let (code, out, err) = wedge(&["solve", "--theta-deg", theta, "--alpha", alpha, "--json"]);
        if code == 0 {
            // computed after all: then every number is finite and declared
            let v: Value = serde_json::from_str(&out).unwrap();
            assert_declared(&v, &format!("theta {theta}, alpha {alpha}"));
            assert!(num(&v["v_over_c1_cot_theta"]) != 0.0);
            continue;
        }
        assert_eq!(code, 2, "theta {theta}: {out}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.contains(&format!("theta_deg = {theta}"))
                && err.contains(&format!("alpha = {alpha} m/s")),
            "{err}"
        );
    }
    // a stress point at 1e-200 of the half-width: refused, naming the point
    let (code, _, err) = wedge(&[
        "stress",
        "--theta-deg",
        "86",
        "--alpha",
        "500",
        "--at",
        "1e-200",
        "--json",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("r/(alpha t) = 1e-200"), "{err}");
}

/// Strong friction: the apex amplitude of the power regime is the closed form (43), so the
/// report stands whole (it used to fail on the finite-regime constant's quadrature).
#[test]
fn strong_friction_reports_stand_whole() {
    for alpha in ["600", "800", "900"] {
        let v = json(&[
            "solve",
            "--theta-deg",
            "86",
            "--gamma",
            "2",
            "--solution",
            "paper",
            "--alpha",
            alpha,
            "--json",
        ]);
        assert_declared(&v, alpha);
        assert_eq!(v["regime"], "power");
        // the exponent of the power regime is 2 Omega0
        assert!((num(&v["apex_exponent"]) - 2.0 * num(&v["omega0"])).abs() < 1e-14);
        assert!(num(&v["apex_amplitude_over_mu_cot_theta"]).is_finite());
    }
}

/// The genuine solution declares the paper-only keys unavailable, with the reason.
#[test]
fn genuine_reports_declare_the_paper_only_keys() {
    let v = json(&[
        "solve",
        "--theta-deg",
        "86",
        "--gamma",
        "0.6",
        "--alpha",
        "561.249",
        "--json",
    ]);
    assert_eq!(v["solution"], "genuine");
    assert_declared(&v, "genuine");
    assert!(v["unavailable"]["q_over_c1sq_cot_theta"].is_string());
}

/// At gamma = 0 the genuine solution and the paper's construction coincide, and so does the
/// finite apex stress S(0+), which the stress approaches only like x^(2 Omega0) with Omega0
/// near 0: the genuine limit is integrated with the apex behaviour subtracted, not sampled at
/// a small x (where it was -15.6 against the limit -72.2). Both carry their own estimates.
#[test]
fn genuine_finite_apex_limit_is_the_papers() {
    let run = |sol: &str| {
        json(&[
            "solve",
            "--theta-deg",
            "86",
            "--gamma",
            "0",
            "--alpha",
            "561.249",
            "--solution",
            sol,
            "--json",
        ])
    };
    let (g, p) = (run("genuine"), run("paper"));
    assert_eq!(g["regime"], "finite");
    let key = "apex_amplitude_over_mu_cot_theta";
    let (a, b) = (num(&g[key]), num(&p[key]));
    assert!((a + 72.19).abs() < 0.01, "{a}");
    let (ea, eb) = (
        num(&g["error_estimates"][key]),
        num(&p["error_estimates"][key]),
    );
    assert!(ea > 0.0 && eb > 0.0 && ea < 1e-6 && eb < 1e-6, "{ea} {eb}");
    assert!((a - b).abs() <= ea + eb, "{a} {b} {ea} {eb}");
}

/// Random valid inputs (angles, friction, coupling, speeds, both variants of the paper's
/// construction): every output is complete or declares what it lacks; a refusal is one line
/// with exit code 2, never a null or a panic.
#[test]
fn random_inputs_never_print_an_undeclared_null() {
    // a small linear congruential generator: reproducible without a dependency
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut solved = 0;
    for _ in 0..40 {
        let theta = format!("{:.3}", 30.0 + 59.9 * next());
        let gamma = format!("{:.3}", 2.0 * next());
        let alpha = format!("{:.3}", 10.0 + 900.0 * next());
        let coupling = if next() < 0.5 { "on" } else { "off" };
        let solution = if next() < 0.5 { "paper" } else { "as-printed" };
        let args = [
            "solve",
            "--theta-deg",
            &theta,
            "--gamma",
            &gamma,
            "--coupling",
            coupling,
            "--alpha",
            &alpha,
            "--solution",
            solution,
            "--json",
        ];
        let (code, out, err) = wedge(&args);
        if code == 0 {
            let v: Value = serde_json::from_str(&out).unwrap();
            assert_declared(&v, &format!("{args:?}"));
            solved += 1;
        } else {
            assert_eq!(code, 2, "{args:?}: {err}");
            assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        }
    }
    assert!(solved >= 30, "only {solved} of 40 solved");
}

/// Messages and limits: usage errors on one line, negative points parsed and refused by range,
/// readable numbers and physical names in range errors, a cap on curve grids, rows streamed.
#[test]
fn messages_are_one_readable_line_and_grids_are_capped() {
    for (args, word) in [
        (
            vec![
                "stress",
                "--theta-deg",
                "86",
                "--alpha",
                "500",
                "--at",
                "-0.5",
            ],
            "invalid at = -0.5",
        ),
        (vec!["solve", "--theta-deg", "86", "--bogus"], "--bogus"),
        (
            vec!["solve", "--theta-deg", "86", "--speed", "1e300"],
            "1.0000e300 m/s",
        ),
        (
            vec![
                "curve",
                "--theta-deg",
                "86.9",
                "--alpha-range",
                "10,920,1000000",
            ],
            "--force",
        ),
        (
            vec![
                "solve",
                "--theta-deg",
                "86",
                "--gamma",
                "0.5",
                "--speed",
                "1e6",
            ],
            "indenter speeds reached",
        ),
    ] {
        let (code, out, err) = wedge(&args);
        assert_eq!(code, 2, "{args:?}: {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(word), "{args:?}: {err}");
        assert!(!err.contains("v_hat"), "{args:?}: {err}");
        // no number printed with more than 20 digits in a row
        let longest = err
            .split(|c: char| !c.is_ascii_digit())
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(longest <= 20, "{args:?}: {err}");
    }
    // the speed range is the real one, not (0, 0)
    let (_, _, err) = wedge(&["solve", "--theta-deg", "86", "--speed", "1e300"]);
    assert!(!err.contains("(0, 0)"), "{err}");
    // a streamed JSON curve is one valid array, in order
    let v = json(&[
        "curve",
        "--theta-deg",
        "86",
        "--alpha-range",
        "10,900,70",
        "--json",
    ]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 70);
    let alphas: Vec<f64> = rows.iter().map(|r| num(&r["alpha"])).collect();
    assert!(alphas.windows(2).all(|w| w[1] > w[0]));
    for r in rows {
        assert_declared(r, "curve row");
    }
}

/// Exact decimal inputs: `--alpha`, `--speed` and `--poisson` are kept as decimal text and
/// parsed at the working precision, and `curve` spaces its grid at that precision (each value
/// checked here against MPFR at 300 bits).
#[test]
fn decimal_inputs_keep_their_digits() {
    use rug::Float;
    let prec = 300;
    let dec = |s: &str| Float::with_val(prec, Float::parse(s).unwrap());
    let text = |v: &Value| v.to_string();
    let rel = |a: &Float, b: &Float| Float::with_val(prec, a - b).abs().to_f64() / b.to_f64().abs();
    // alpha to 28 digits at 40 digits: p = alpha/c1 keeps them
    let alpha = "561.2490000000000000000000123";
    let v = json(&[
        "solve",
        "--theta-deg",
        "86",
        "--alpha",
        alpha,
        "--digits",
        "40",
        "--json",
    ]);
    let want = Float::with_val(prec, dec(alpha) / dec("1870.83"));
    assert!(rel(&dec(&text(&v["p"])), &want) < 1e-38, "p = {}", v["p"]);
    // Poisson's ratio as text: m = c2/c1 = ((1 - 2 nu)/(2 (1 - nu)))^(1/2) to 40 digits
    let v = json(&[
        "solve",
        "--poisson",
        "0.2500000000000000000000001",
        "--theta-deg",
        "86",
        "--alpha",
        "500",
        "--digits",
        "40",
        "--json",
    ]);
    let nu = dec("0.2500000000000000000000001");
    let one = Float::with_val(prec, 1);
    let m2 = Float::with_val(prec, &one - Float::with_val(prec, &nu * 2u32))
        / Float::with_val(prec, Float::with_val(prec, &one - &nu) * 2u32);
    assert!(
        rel(&dec(&text(&v["m"])), &m2.sqrt()) < 1e-38,
        "m = {}",
        v["m"]
    );
    // the curve grid at 30 digits: 10 + 910 i/91 exactly (i = 69 gives 700)
    let v = json(&[
        "curve",
        "--theta-deg",
        "86",
        "--alpha-range",
        "10,920,92",
        "--digits",
        "30",
        "--json",
    ]);
    for (i, row) in v.as_array().unwrap().iter().enumerate().step_by(13) {
        let a = Float::with_val(prec, dec("910") * (i as u32) / 91u32) + dec("10");
        let p = Float::with_val(prec, &a / dec("1870.83"));
        assert!(
            rel(&dec(&text(&row["p"])), &p) < 1e-29,
            "row {i}: p = {}",
            row["p"]
        );
    }
}

/// In the classical case (gamma = 0, no coupling) the genuine solution is the paper's, and
/// the one interface reports the same apex behaviour for both, in the paper's normalisation
/// sigma ~ A ln(2 p/x) (the genuine amplitude once had the opposite sign), with V, the force
/// and the stress at the same values, each within the two estimates.
#[test]
fn both_variants_report_the_classical_case_alike() {
    use dyncontact::{solve, stress, CaseInput, Selection, Speed};
    use wedge::{ApexRegime, Coupling, Indenter, Material, Param, Solution};
    let input = |solution| CaseInput {
        material: Material::paper(),
        indenter: Indenter::new(80.0, 0.0, Coupling::Off).unwrap(),
        solution,
        digits: None,
    };
    let speed = Speed::Alpha(Param::parse("alpha", "500").unwrap());
    let at = [Param::parse("at", "0.25").unwrap()];
    let (g, p) = (
        solve(
            &input(Solution::Genuine),
            &speed,
            &Selection::without_admissibility(),
        )
        .unwrap(),
        solve(
            &input(Solution::Paper),
            &speed,
            &Selection::without_admissibility(),
        )
        .unwrap(),
    );
    assert_eq!(g.regime, ApexRegime::Logarithmic);
    assert_eq!(p.regime, ApexRegime::Logarithmic);
    for key in [
        "apex_amplitude_over_mu_cot_theta",
        "v_over_c1_cot_theta",
        "force_over_a_mu_cot_theta",
    ] {
        let (a, b) = (g.quantity(key).unwrap(), p.quantity(key).unwrap());
        assert!(
            (a.value() - b.value()).abs() <= a.error() + b.error(),
            "{key}: genuine {} +- {:e}, paper {} +- {:e}",
            a.text(),
            a.error(),
            b.text(),
            b.error()
        );
    }
    // the paper's amplitude is -Q/p (eq (41)): negative, as the compressive stress
    assert!(
        g.quantity("apex_amplitude_over_mu_cot_theta")
            .unwrap()
            .value()
            < 0.0
    );
    let (sg, sp) = (
        stress(&input(Solution::Genuine), &speed, &at).unwrap(),
        stress(&input(Solution::Paper), &speed, &at).unwrap(),
    );
    let (a, b) = (
        &sg.sigma_over_mu_cot_theta[0],
        &sp.sigma_over_mu_cot_theta[0],
    );
    assert!((a.value() - b.value()).abs() <= a.error() + b.error());
}
