//! The wedge solution against an independent mpmath implementation written from the paper and
//! its errata only (tests/reference/wedge_mpmath.py, 30 digits kept where its 40- and
//! 50-digit runs agree). The Rust code shares no code path with it.

use complexfn::Real;
use rug::Float;
use serde_json::Value;
use wedge::{Case, Coupling, Indenter, Material, Solution};

fn reference() -> Value {
    serde_json::from_str(include_str!("../reference/wedge_reference.json")).unwrap()
}

fn s(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        Value::Object(o) => s(&o["value"]),
        other => other.to_string(),
    }
}

fn indenter(c: &Value) -> Indenter {
    let coupling = if c["coupled"].as_bool().unwrap() {
        Coupling::On
    } else {
        Coupling::Off
    };
    let th = wedge::Param::parse("theta_deg", &s(&c["theta_deg"])).unwrap();
    let g = wedge::Param::parse("gamma", &s(&c["gamma"])).unwrap();
    Indenter::new(th, g, coupling).unwrap()
}

/// Every quantity of one variant, as (name, value) pairs, computed at the precision of `like`.
fn quantities<T: complexfn::quadrature::CachedRules>(
    case: &Case<T>,
    with_apex: bool,
) -> Vec<(&'static str, T)> {
    let mut v = vec![
        ("q_hat", case.q_hat().unwrap()),
        ("v_hat", case.v_hat().unwrap()),
        ("force_over_a_mu_cot_theta", case.force_hat().unwrap()),
        (
            "edge_slip_velocity_over_speed",
            case.edge_slip_velocity_over_speed().unwrap(),
        ),
        (
            "edge_following_rate_over_speed",
            case.edge_following_rate_over_speed().unwrap(),
        ),
    ];
    if with_apex {
        v.push((
            "apex_u_r_over_speed_t",
            case.apex_u_r_over_speed_t().unwrap().value,
        ));
    }
    v
}

fn check<T: complexfn::quadrature::CachedRules>(like: &T, tol: f64, names: &[&str]) {
    let r = reference();
    let mat = Material::paper();
    for (name, c) in r["cases"].as_object().unwrap() {
        if !names.contains(&name.as_str()) {
            continue;
        }
        let ind = indenter(c);
        let p = T::parse_prec(&s(&c["p"]), like.prec()).unwrap();
        let close = |what: &str, got: &T, want: &str| {
            let w = T::parse_prec(want, like.prec()).unwrap();
            let err = if w == 0.0 {
                got.clone().abs().to_f64()
            } else {
                complexfn::scalar::rel_diff(got, &w)
            };
            assert!(err <= tol, "case {name} {what}: {got} vs {want} ({err:e})");
        };
        for (variant, sol) in [
            ("paper", Solution::Paper),
            ("as_printed", Solution::AsPrinted),
        ] {
            let case = Case::new(&mat, &ind, p.clone(), sol).unwrap();
            close("m_r", case.m_r(), &s(&c["m_r"]));
            close("omega0", &case.omega0(), &s(&c["omega0"]));
            close("s0", &case.s0(), &s(&c["s0"]));
            let refs = &c[variant];
            for (key, got) in quantities(&case, sol == Solution::Paper) {
                if let Some(want) = refs.get(key) {
                    close(key, &got, &s(want));
                }
            }
            if let Some(Value::Array(st)) = refs.get("sigma_over_mu_cot_theta") {
                for e in st {
                    let f = T::parse_prec(&s(&e["r_over_alpha_t"]), like.prec()).unwrap();
                    let x = p.clone() * f;
                    let got = case.stress_hat(&x).unwrap().value;
                    close("sigma", &got, &s(&e["value"]));
                }
            }
        }
    }
}

#[test]
fn f64_path_matches_the_mpmath_reference_to_1e_12() {
    check(&0.0_f64, 1e-12, &["A", "B", "C", "D", "E", "F", "G"]);
}

#[test]
fn arbitrary_precision_matches_the_mpmath_reference_to_28_digits() {
    // 30 digits are kept in the reference; 140 bits hold 42.
    check(&Float::with_val(140, 0), 1e-28, &["A", "B", "D", "G"]);
}

#[test]
fn rayleigh_root_matches_the_second_reference() {
    let r = reference();
    let want = s(&r["m_r_80"]);
    let m = Material::paper().m(&Float::with_val(300, 0));
    let ray = complexfn::Rayleigh::new(m).unwrap();
    let w = Float::parse_prec(&want, 300).unwrap();
    assert!(complexfn::scalar::rel_diff(ray.m_r(), &w) < 1e-78);
}
