//! The `wedge` command line: the documented forms work, outputs carry their keys and digits
//! and agree with library calls, and bad input gives a one-line message and exit code 2.

use std::process::Command;

use serde_json::Value;
use wedge::{Case, Coupling, Indenter, Material, Solution};

fn wedge(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_wedge"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> Value {
    let (code, out, err) = wedge(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| v.to_string().parse().unwrap())
}

#[test]
fn solve_json_has_every_key_and_matches_the_library() {
    let v = json(&[
        "solve",
        "--c1",
        "1870.83",
        "--c2",
        "1000",
        "--theta-deg",
        "86",
        "--gamma",
        "0.6",
        "--coupling",
        "on",
        "--alpha",
        "561.249",
        "--json",
    ]);
    for k in [
        "m",
        "m_r",
        "p",
        "alpha",
        "speed",
        "omega0",
        "s0",
        "regime",
        "apex_exponent",
        "v_over_c1_cot_theta",
        "force_over_a_mu_cot_theta",
        "edge_slip_velocity_over_speed",
        "edge_following_rate_over_speed",
        "apex_u_r_over_speed_t",
        "slip_direction_ok",
        "solution",
        "error_estimate",
        "digits",
    ] {
        assert!(v.get(k).is_some(), "missing {k}");
    }
    assert_eq!(v["solution"], "paper");
    assert_eq!(v["regime"], "power");
    let case = Case::with_alpha(
        &Material::paper(),
        &Indenter::new(86.0, 0.6, Coupling::On).unwrap(),
        561.249,
        &0.0_f64,
        Solution::Paper,
    )
    .unwrap();
    let vh = case.v_hat().unwrap();
    assert!((num(&v["v_over_c1_cot_theta"]) - vh).abs() < 1e-14 * vh);
    assert!((num(&v["apex_exponent"]) - 2.0 * case.omega0()).abs() < 1e-15);
    assert!(num(&v["error_estimate"]) < 1e-12);
}

#[test]
fn digits_are_carried_and_the_error_estimate_is_honest() {
    let v = json(&[
        "solve",
        "--theta-deg",
        "89",
        "--gamma",
        "0.6",
        "--alpha",
        "561.249",
        "--digits",
        "40",
        "--json",
    ]);
    let s = v["v_over_c1_cot_theta"].to_string();
    let mantissa: String = s
        .split('e')
        .next()
        .unwrap()
        .chars()
        .filter(|c| c.is_ascii_digit())
        .collect();
    assert_eq!(mantissa.len(), 40, "{s}");
    // against the mpmath reference (30 digits): V/(c1 cot Theta) = 0.370557526573515463551231275931
    let ref30 = "3705575265735154635512312759";
    assert!(mantissa.starts_with(ref30), "{mantissa}");
    let err = num(&v["error_estimate"]);
    assert!(err < 1e-40 && err > 0.0, "{err}");
    assert_eq!(v["digits"], 40);
}

#[test]
fn speed_instead_of_alpha_and_the_as_printed_variant() {
    let v = json(&[
        "solve",
        "--theta-deg",
        "86",
        "--gamma",
        "0.001",
        "--speed",
        "10",
        "--json",
    ]);
    assert!((num(&v["speed"]) - 10.0).abs() < 1e-9);
    let a = json(&[
        "solve",
        "--theta-deg",
        "89",
        "--gamma",
        "0.6",
        "--alpha",
        "561.249",
        "--solution",
        "as-printed",
        "--json",
    ]);
    assert_eq!(a["solution"], "as-printed");
    let g = json(&[
        "solve",
        "--theta-deg",
        "86",
        "--gamma",
        "cot",
        "--alpha",
        "400",
        "--json",
    ]);
    assert_eq!(g["regime"], "logarithmic");
}

#[test]
fn genuine_variant_from_the_command_line() {
    // for gamma = 0 the genuine solution is the paper's (tested to 1e-10 in crates/genuine);
    // here: the command routes to it, names it, and refuses --digits with a reason
    let g = json(&[
        "solve",
        "--theta-deg",
        "89",
        "--gamma",
        "0",
        "--alpha",
        "400",
        "--solution",
        "genuine",
        "--json",
    ]);
    let p = json(&[
        "solve",
        "--theta-deg",
        "89",
        "--gamma",
        "0",
        "--alpha",
        "400",
        "--json",
    ]);
    assert_eq!(g["solution"], "genuine");
    let (a, b) = (
        num(&g["v_over_c1_cot_theta"]),
        num(&p["v_over_c1_cot_theta"]),
    );
    assert!((a - b).abs() < 1e-9 * b, "{a} {b}");
    let (code, _, err) = wedge(&[
        "solve",
        "--theta-deg",
        "89",
        "--gamma",
        "0.6",
        "--alpha",
        "400",
        "--solution",
        "genuine",
        "--digits",
        "30",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("genuine") && err.contains("f64"), "{err}");
}

#[test]
fn stress_field_and_curve_commands() {
    let s = json(&[
        "stress",
        "--theta-deg",
        "86",
        "--gamma",
        "0.6",
        "--alpha",
        "561.249",
        "--at",
        "0.001,0.5,0.9",
        "--json",
    ]);
    assert_eq!(s["r_over_alpha_t"].as_array().unwrap().len(), 3);
    let sig: Vec<f64> = s["sigma_over_mu_cot_theta"]
        .as_array()
        .unwrap()
        .iter()
        .map(num)
        .collect();
    assert!(sig[0] < sig[1] && sig[1] < sig[2] && sig[2] < 0.0);
    let f = json(&[
        "field",
        "--theta-deg",
        "86",
        "--gamma",
        "0.6",
        "--alpha",
        "561.249",
        "--at",
        "0.1:-0.1,0.6:-0.5",
        "--json",
    ]);
    for k in dyncontact::FIELD_KEYS {
        assert_eq!(f[*k].as_array().unwrap().len(), 2, "{k}");
    }
    let (code, out, err) = wedge(&[
        "curve",
        "--theta-deg",
        "86",
        "--gamma",
        "0.4",
        "--alpha-range",
        "10,920,6",
        "--csv",
    ]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].starts_with("# dyncontact"));
    let header = lines.iter().find(|l| !l.starts_with('#')).unwrap();
    assert!(header.starts_with("solution,alpha,speed"));
    let rows: Vec<&str> = lines
        .iter()
        .filter(|l| l.starts_with("paper,"))
        .copied()
        .collect();
    assert_eq!(rows.len(), 6);
    // the alpha-V relation is increasing
    let col = header
        .split(',')
        .position(|c| c == "v_over_c1_cot_theta")
        .unwrap();
    let v: Vec<f64> = rows
        .iter()
        .map(|r| r.split(',').nth(col).unwrap().parse().unwrap())
        .collect();
    assert!(v.windows(2).all(|w| w[1] > w[0]), "{v:?}");
}

#[test]
fn bad_input_exits_2_with_one_line_naming_the_parameter() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["solve", "--theta-deg", "95", "--alpha", "100"],
            "theta_deg",
        ),
        (
            &[
                "solve",
                "--theta-deg",
                "86",
                "--gamma",
                "-0.1",
                "--alpha",
                "100",
            ],
            "gamma",
        ),
        (&["solve", "--theta-deg", "86", "--alpha", "1000"], "alpha"),
        (&["solve", "--theta-deg", "86", "--alpha", "nan"], "alpha"),
        (
            &[
                "solve",
                "--theta-deg",
                "86",
                "--c2",
                "1700",
                "--alpha",
                "100",
            ],
            "c2",
        ),
        (
            &[
                "solve",
                "--theta-deg",
                "86",
                "--alpha",
                "100",
                "--digits",
                "0",
            ],
            "digits",
        ),
        (
            &[
                "solve",
                "--theta-deg",
                "86",
                "--alpha",
                "100",
                "--solution",
                "exact",
            ],
            "solution",
        ),
        (&["solve", "--theta-deg", "86", "--speed", "1e12"], "speed"),
        (
            &[
                "stress",
                "--theta-deg",
                "86",
                "--alpha",
                "100",
                "--at",
                "1.5",
            ],
            "at",
        ),
        (
            &[
                "field",
                "--theta-deg",
                "86",
                "--alpha",
                "100",
                "--at",
                "0.1:0.2",
            ],
            "at",
        ),
        (
            &["curve", "--theta-deg", "86", "--alpha-range", "10,5,3"],
            "alpha-range",
        ),
    ];
    for (args, name) in cases {
        let (code, out, err) = wedge(args);
        assert_eq!(code, 2, "{args:?}: {out} {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(name), "{args:?}: {err}");
        assert!(!err.contains("panicked"));
    }
    // conflicting or missing flags: clap's message, exit 2
    let (code, _, err) = wedge(&[
        "solve",
        "--theta-deg",
        "86",
        "--alpha",
        "100",
        "--speed",
        "3",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--speed"));
    let (code, _, _) = wedge(&["solve", "--theta-deg", "86"]);
    assert_eq!(code, 2);
}
