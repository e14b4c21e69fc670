//! Computing only what is asked for: a report restricted to selected quantities
//! (`--quantities`) carries the same digits and estimates as the full report, and nothing
//! else; the shortcut of an identically vanishing Omega (no inner rule: b, Lambda0, S0 are
//! exact zeros) gives what the general path gives for an Omega below the working precision.

use crate::common;

use dyncontact::{curve_row, solve, CaseInput, Entry, Selection, Speed, SOLVE_KEYS};
use rug::Float;
use serde_json::Value;
use wedge::{Case, ContactSolution, Coupling, Indenter, Material, Param, Solution};

fn input(
    theta: f64,
    gamma: &str,
    coupling: Coupling,
    solution: Solution,
    digits: Option<u32>,
) -> CaseInput {
    CaseInput {
        material: Material::paper(),
        indenter: Indenter::new(theta, Param::parse("gamma", gamma).unwrap(), coupling).unwrap(),
        solution,
        digits,
    }
}

#[test]
fn selected_quantities_equal_the_full_report_to_the_last_digit() {
    let cases = [
        input(89.0, "0.6", Coupling::On, Solution::Paper, None),
        input(89.0, "0.6", Coupling::On, Solution::Paper, Some(30)),
        input(86.0, "0", Coupling::Off, Solution::Paper, Some(30)),
        input(86.0, "0.4", Coupling::On, Solution::Genuine, None),
    ];
    let picks: [&[&str]; 3] = [
        &["v_over_c1_cot_theta"],
        &["force_over_a_mu_cot_theta", "omega0"],
        &[
            "apex_amplitude_over_mu_cot_theta",
            "edge_slip_velocity_over_speed",
        ],
    ];
    for inp in &cases {
        let alpha = Param::parse("alpha", "561.249").unwrap();
        let full = curve_row(inp, &alpha, &Selection::all()).unwrap();
        for keys in picks {
            let sel = Selection::of(keys).unwrap();
            let part = curve_row(inp, &alpha, &sel).unwrap();
            for (k, q) in part.quantities() {
                let whole = full.quantity(k).expect("in the full report");
                assert_eq!(q.text(), whole.text(), "{k}");
                assert_eq!(q.error(), whole.error(), "{k}");
            }
            // exactly the selected keys and the ones that always come along, nothing else
            for (k, item) in part.items() {
                let omitted = matches!(item, dyncontact::Item::Omitted);
                assert_eq!(omitted, !sel.wants(k), "{k} with {keys:?}");
            }
            assert_eq!(part.error_estimate, full.error_estimate);
        }
    }
    // solve: the admissibility flags only when selected
    let inp = input(86.0, "0.6", Coupling::On, Solution::Paper, None);
    let speed = Speed::Alpha(Param::parse("alpha", "500").unwrap());
    let r = solve(
        &inp,
        &speed,
        &Selection::of(&["slip_direction_ok"]).unwrap(),
    )
    .unwrap();
    assert!(matches!(r.slip_direction_ok, Entry::Value(_)));
    assert_eq!(r.contact_compressive, Entry::Omitted);
    assert_eq!(r.omega0, Entry::Omitted);
}

fn run(args: &[&str]) -> (i32, String, String) {
    common::run(env!("CARGO_BIN_EXE_wedge"), args)
}

#[test]
fn quantities_flag_prints_the_selection_and_refuses_unknown_keys() {
    let (code, out, _) = run(&[
        "solve",
        "--theta-deg",
        "86",
        "--gamma",
        "0.6",
        "--alpha",
        "500",
        "--quantities",
        "force_over_a_mu_cot_theta",
        "--json",
    ]);
    assert_eq!(code, 0);
    let v: Value = serde_json::from_str(&out).unwrap();
    let o = v.as_object().unwrap();
    for k in SOLVE_KEYS {
        let expected = dyncontact::ALWAYS_KEYS.contains(k) || *k == "force_over_a_mu_cot_theta";
        assert_eq!(o.contains_key(*k), expected, "{k}");
    }
    let est = o["error_estimates"].as_object().unwrap();
    assert!(est.contains_key("force_over_a_mu_cot_theta") && !est.contains_key("omega0"));

    let (code, out, _) = run(&[
        "curve",
        "--theta-deg",
        "86",
        "--alpha-range",
        "100,800,3",
        "--quantities",
        "omega0",
    ]);
    assert_eq!(code, 0);
    let header = out.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(
        header,
        "solution,alpha,speed,p,m,m_r,omega0,regime,v_over_c1_cot_theta,error_estimate,digits,\
         err_alpha,err_speed,err_p,err_m,err_m_r,err_omega0,err_v_over_c1_cot_theta"
    );
    for row in out.lines().filter(|l| !l.starts_with('#')).skip(1) {
        assert_eq!(row.split(',').count(), header.split(',').count(), "{row}");
    }

    let (code, _, err) = run(&[
        "solve",
        "--theta-deg",
        "86",
        "--alpha",
        "500",
        "--quantities",
        "v_over_c1_cot_theta,speeed",
    ]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("quantities") && err.contains("speeed"),
        "{err}"
    );
}

/// Omega vanishes identically for beta + gamma = 0 (the classical case, and gamma = cot Theta
/// with coupling): the case has no inner rule. With gamma = 1e-60 (uncoupled) Omega is of that
/// size and the general path runs; at 100 bits the two agree to the working precision in V,
/// the force, the stress and the edge quantities.
#[test]
fn vanishing_omega_shortcut_equals_the_general_path() {
    let bits = 100;
    let p = Float::with_val(bits, 0.3);
    let at = |gamma: &str| {
        let ind =
            Indenter::new(86.0, Param::parse("gamma", gamma).unwrap(), Coupling::Off).unwrap();
        Case::new(&Material::paper(), &ind, p.clone(), Solution::Paper).unwrap()
    };
    let (short, general) = (at("0"), at("1e-60"));
    assert!(short.inner().is_empty());
    assert!(!general.inner().is_empty());
    let tol = 1e-27;
    let close = |a: &Float, b: &Float, what: &str| {
        let d = Float::with_val(bits, a - b).abs().to_f64() / b.to_f64().abs();
        assert!(d < tol, "{what}: {d:e}");
    };
    close(
        &ContactSolution::v_hat(&short).unwrap().value,
        &ContactSolution::v_hat(&general).unwrap().value,
        "V",
    );
    close(
        &ContactSolution::force_hat(&short).unwrap().value,
        &ContactSolution::force_hat(&general).unwrap().value,
        "force",
    );
    close(
        &ContactSolution::edge_slip_velocity_over_speed(&short)
            .unwrap()
            .value,
        &ContactSolution::edge_slip_velocity_over_speed(&general)
            .unwrap()
            .value,
        "edge slip velocity",
    );
    for frac in [0.05, 0.5, 0.95] {
        // r/(c1 t) inside the contact (0, p]
        let x = Float::with_val(bits, &p * frac);
        close(
            &ContactSolution::stress_hat(&short, &x).unwrap().value,
            &ContactSolution::stress_hat(&general, &x).unwrap().value,
            "stress",
        );
    }
    // and the shortcut's S0 is an exact zero
    assert_eq!(ContactSolution::s0(&short).unwrap().value, 0.0);
}
