//! The `impact green` command line: documented keys, agreement with the library (and with
//! the independent limits), arbitrary precision, and one-line errors with exit code 2.

mod common;

use common::{num, run, run_json};
use lamb::HalfPlane;
use serde_json::Value;

fn impact(args: &[&str]) -> (i32, String, String) {
    run(env!("CARGO_BIN_EXE_impact"), args)
}

fn json(args: &[&str]) -> Value {
    run_json(env!("CARGO_BIN_EXE_impact"), args)
}

#[test]
fn green_points_cells_and_constants_carry_their_keys() {
    let v = json(&[
        "green",
        "--poisson",
        "0.3",
        "--at",
        "0.1,0.52,0.6,0.9,1.2",
        "--cells",
        "0.1:0.95,0.6:1",
        "--constants",
        "--json",
    ]);
    let hp = HalfPlane::from_poisson(0.3).unwrap();
    let pts = v["points"].as_array().unwrap();
    assert_eq!(pts.len(), 5);
    for p in pts {
        for k in ["s", "g_zz", "g_xz", "g_xx", "W_zz", "U_xz", "U_xx"] {
            assert!(p[k].is_number(), "{k}: {p}");
            assert!(p["error_estimate"][k].is_number() || k == "s", "{k}");
        }
        let s = num(&p["s"]);
        let g = hp.impulse(&s).unwrap();
        assert_eq!(num(&p["g_zz"]), g.zz.value);
        let w = hp.step(&s).unwrap();
        assert_eq!(num(&p["U_xx"]), w.xx.value);
    }
    // behind the Rayleigh front the tangential step displacement is Flamant's
    let u = num(&pts[0]["U_xz"]);
    assert!((u + std::f64::consts::PI * 0.4 / 4.0).abs() < 1e-14, "{u}");
    let cells = v["cells"].as_array().unwrap();
    for c in cells {
        for k in [
            "sa", "sb", "Ix_zz", "Ix_xz", "Ix_xx", "It_zz", "It_xz", "It_xx",
        ] {
            assert!(c[k].is_number(), "{k}: {c}");
        }
    }
    // It = W(sa) - W(sb) with the pointwise step responses
    let it = num(&cells[1]["It_zz"]);
    assert!((it - num(&pts[2]["W_zz"])).abs() < 1e-14, "{it}");
    let c = &v["constants"];
    for k in ["s_R", "r_zz", "r_xx", "K_R"] {
        assert!(c[k].is_number(), "{k}");
    }
    assert_eq!(num(&c["s_R"]), *hp.s_r());
}

#[test]
fn wave_speeds_and_digits() {
    let a = json(&[
        "green", "--c1", "1870.83", "--c2", "1000", "--at", "0.3", "--json",
    ]);
    let m = 1000.0 / 1870.83;
    let hp = HalfPlane::new(m).unwrap();
    assert!((num(&a["points"][0]["g_zz"]) - hp.impulse(&0.3).unwrap().zz.value).abs() < 1e-15);
    let hi = json(&[
        "green",
        "--poisson",
        "0.25",
        "--at",
        "0.3",
        "--constants",
        "--digits",
        "40",
        "--json",
    ]);
    let text = hi["constants"]["K_R"].to_string();
    // nu = 1/4: K_R = -1/8 exactly
    assert!(
        text.starts_with("-1.24999999999999999999999999999999999")
            || text.starts_with("-1.250000000000000000000000000000000000"),
        "{text}"
    );
    assert!(hi["precision_bits"].as_u64().unwrap() > 133);
}

#[test]
fn a_cell_from_zero_gives_the_plane_wave_momentum_and_declares_it_unavailable() {
    // Int_0^1 g_zz ds = pi m^2/2, Int_0^1 g_xx ds = pi m/2 (the P and S plane waves)
    let v = json(&["green", "--poisson", "0.3", "--cells", "0:1", "--json"]);
    let c = &v["cells"][0];
    let m = num(&v["c2_over_c1"]);
    let pi = std::f64::consts::PI;
    assert!((num(&c["Ix_zz"]) - pi * m * m / 2.0).abs() < 1e-14);
    assert!((num(&c["Ix_xx"]) - pi * m / 2.0).abs() < 1e-14);
    assert!(c["It_zz"].is_null());
    assert!(c["unavailable"]["It"]
        .as_str()
        .unwrap()
        .contains("diverges"));
}

#[test]
fn csv_output_has_a_header_and_columns() {
    let (code, out, _) = impact(&["green", "--poisson", "0.25", "--at", "0.2,0.7"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("# impact"));
    let header = out.lines().find(|l| !l.starts_with('#')).unwrap();
    assert!(
        header.starts_with("s,g_zz,g_xz,g_xx,W_zz,U_xz,U_xx,err_g_zz"),
        "{header}"
    );
    assert_eq!(out.lines().filter(|l| !l.starts_with('#')).count(), 3);
}

#[test]
fn bad_input_exits_2_with_one_line_naming_the_parameter() {
    let s_r = HalfPlane::from_poisson(0.25).unwrap().s_r().to_string();
    for (args, word) in [
        (vec!["green", "--poisson", "0.5", "--at", "0.1"], "Poisson"),
        (vec!["green", "--poisson", "-1.2", "--at", "0.1"], "Poisson"),
        (vec!["green", "--poisson", "0.25", "--at", "-0.1"], "s"),
        (
            vec!["green", "--poisson", "0.25", "--at", s_r.as_str()],
            "s_R",
        ),
        (
            vec!["green", "--poisson", "0.25", "--cells", "0.5:0.4"],
            "sa <= sb",
        ),
        (
            vec!["green", "--poisson", "0.25", "--cells", "0.5"],
            "sa:sb",
        ),
        (vec!["green", "--poisson", "0.25", "--at", "abc"], "s"),
        (vec!["green", "--at", "0.1"], "material"),
        (
            vec![
                "green",
                "--poisson",
                "0.25",
                "--c1",
                "2",
                "--c2",
                "1",
                "--at",
                "0.1",
            ],
            "contradictory",
        ),
        (
            vec!["green", "--c1", "1000", "--c2", "1000", "--at", "0.1"],
            "c2/c1",
        ),
        (vec!["green", "--poisson", "0.25"], "nothing asked"),
        (
            vec!["green", "--poisson", "0.25", "--at", "0.1", "--bogus"],
            "bogus",
        ),
    ] {
        let (code, out, err) = impact(&args);
        assert_eq!(code, 2, "{args:?}: {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(word), "{args:?}: {err}");
    }
}
