//! The double-double path of the paper's construction against MPFR at 256 bits: every
//! reported quantity's stated estimate bounds its actual error (never optimistic), the
//! estimates are useful (within 1e-24 relative away from the Rayleigh speed), and the
//! command line serves `--digits 30` through it with the digits MPFR gives.

use crate::common;

use complexfn::{Dd, Real};
use dyncontact::{build_dd, build_mpfr, curve_row, CaseInput, Selection, Speed};
use rug::Float;
use wedge::{ContactSolution, Coupling, Indenter, Material, Param, Result, Solution, WithError};

const REF_BITS: u32 = 256;

fn input(theta: f64, gamma: &str, coupling: Coupling, solution: Solution) -> CaseInput {
    CaseInput {
        material: Material::paper(),
        indenter: Indenter::new(theta, Param::parse("gamma", gamma).unwrap(), coupling).unwrap(),
        solution,
        digits: Some(30),
    }
}

/// Actual error |dd - ref| against the stated one; returns actual/stated.
fn check(name: &str, dd: Result<WithError<Dd>>, reference: Result<WithError<Float>>) -> f64 {
    match (dd, reference) {
        (Ok(d), Ok(r)) => {
            let actual = Float::with_val(REF_BITS, d.value.to_mpfr(REF_BITS) - &r.value)
                .abs()
                .to_f64();
            assert!(
                actual <= d.error,
                "{name}: actual error {actual:e} above the stated {:e}",
                d.error
            );
            if d.error == 0.0 {
                0.0
            } else {
                actual / d.error
            }
        }
        (Err(_), Err(_)) => 0.0,
        (d, r) => panic!(
            "{name}: one precision failed: {:?} / {:?}",
            d.err(),
            r.err()
        ),
    }
}

#[test]
fn double_double_estimates_bound_the_actual_errors() {
    let cases = [
        input(86.0, "0", Coupling::Off, Solution::Paper),
        input(89.0, "0.6", Coupling::On, Solution::Paper),
        input(89.0, "0.6", Coupling::On, Solution::AsPrinted),
        input(30.0, "0.2", Coupling::On, Solution::Paper),
        input(5.0, "0.3", Coupling::On, Solution::Paper),
    ];
    let mut worst: f64 = 0.0;
    for inp in &cases {
        assert!(inp.uses_double_double());
        // up to within 0.1 percent of the Rayleigh speed (c_R = 927.4 m/s)
        for a in ["93.5", "400.1", "700", "841.8", "926.5"] {
            let sp = Speed::Alpha(Param::parse("alpha", a).unwrap());
            let d = build_dd(inp, &sp).unwrap();
            let r = build_mpfr(inp, &sp, REF_BITS).unwrap();
            let at = format!("{} alpha {a}", dyncontact::describe(inp, &sp));
            let q = |name: &str| format!("{at}: {name}");
            worst = worst.max(check(&q("V"), d.v_hat(), r.v_hat()));
            worst = worst.max(check(&q("force"), d.force_hat(), r.force_hat()));
            worst = worst.max(check(&q("Q"), d.q_hat(), r.q_hat()));
            worst = worst.max(check(&q("Omega0"), d.omega0(), r.omega0()));
            worst = worst.max(check(&q("S0"), d.s0(), r.s0()));
            worst = worst.max(check(
                &q("slip"),
                d.edge_slip_velocity_over_speed(),
                r.edge_slip_velocity_over_speed(),
            ));
            worst = worst.max(check(
                &q("following rate"),
                d.edge_following_rate_over_speed(),
                r.edge_following_rate_over_speed(),
            ));
            worst = worst.max(check(
                &q("apex u_r"),
                d.apex_u_r_over_speed_t(),
                r.apex_u_r_over_speed_t(),
            ));
            let amp = |x: Result<wedge::ApexLeading<Dd>>| x.map(|l| l.amplitude);
            let amp_r = |x: Result<wedge::ApexLeading<Float>>| x.map(|l| l.amplitude);
            worst = worst.max(check(
                &q("apex amplitude"),
                amp(d.apex_leading()),
                amp_r(r.apex_leading()),
            ));
            let p = d.p().to_f64();
            for frac in [0.1, 0.5, 0.9] {
                let x = Dd::from_f64(frac * p);
                worst = worst.max(check(
                    &q(&format!("stress at {frac} p")),
                    d.stress_hat(&x),
                    r.stress_hat(&x.to_mpfr(REF_BITS)),
                ));
            }
            // useful estimates away from the Rayleigh speed
            if a != "926.5" {
                let v = d.v_hat().unwrap();
                assert!(
                    v.error <= 1e-27 * v.value.to_f64().abs(),
                    "{at}: V's estimate {:e}",
                    v.error
                );
            }
        }
    }
    eprintln!("worst actual/stated over all quantities: {worst:.3}");
}

#[test]
fn thirty_digit_rows_agree_with_mpfr_to_their_estimates() {
    // the same row through the library at 30 digits (double-double) and at 60 (MPFR)
    for inp in [
        input(86.0, "0", Coupling::Off, Solution::Paper),
        input(89.0, "0.6", Coupling::On, Solution::Paper),
    ] {
        let fine = CaseInput {
            digits: Some(60),
            ..inp.clone()
        };
        assert!(!fine.uses_double_double());
        for a in ["200", "561.249", "900"] {
            let alpha = Param::parse("alpha", a).unwrap();
            let dd = curve_row(&inp, &alpha, &Selection::all()).unwrap();
            let mp = curve_row(&fine, &alpha, &Selection::all()).unwrap();
            let mut compared = 0;
            for (k, q) in dd.quantities() {
                let Some(r) = mp.quantity(k) else { continue };
                let (x, y): (f64, f64) = (q.value(), r.value());
                // the printed digits of both, read back exactly
                let xs = Float::with_val(200, Float::parse(q.text()).unwrap());
                let ys = Float::with_val(200, Float::parse(r.text()).unwrap());
                let diff = Float::with_val(200, xs - ys).abs().to_f64();
                assert!(
                    diff <= q.error() + r.error(),
                    "{k} at alpha {a}: {x} vs {y}, difference {diff:e}, estimate {:e}",
                    q.error()
                );
                compared += 1;
            }
            assert!(compared >= 10, "only {compared} quantities compared");
        }
    }
}

#[test]
fn the_command_line_serves_thirty_digits_in_double_double() {
    let exe = env!("CARGO_BIN_EXE_wedge");
    let args = |digits: &'static str| {
        [
            "solve",
            "--theta-deg",
            "89",
            "--gamma",
            "0.6",
            "--solution",
            "paper",
            "--alpha",
            "561.249",
            "--digits",
            digits,
            "--json",
        ]
    };
    let dd = common::run_json(exe, &args("30"));
    let mp = common::run_json(exe, &args("31"));
    let v = |j: &serde_json::Value| j["v_over_c1_cot_theta"].to_string();
    // 30 digits in double-double equal 31 MPFR digits rounded to 30
    let (a, b) = (v(&dd), v(&mp));
    let fa = Float::with_val(200, Float::parse(&a).unwrap());
    let fb = Float::with_val(200, Float::parse(&b).unwrap());
    let rel = (Float::with_val(200, fa - &fb) / fb).abs().to_f64();
    assert!(rel < 1e-29, "{a} vs {b}");
    let est = common::num(&dd["error_estimates"]["v_over_c1_cot_theta"]);
    assert!(est > 0.0 && est < 1e-27, "{est}");
}
