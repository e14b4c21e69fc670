//! The `impact green` command line: documented keys, agreement with the library (and with
//! the independent limits), arbitrary precision, and one-line errors with exit code 2.

use crate::common;

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

const RUN_BASE: [&str; 14] = [
    "run",
    "--poisson",
    "0.25",
    "--striker",
    "rigid",
    "--profile",
    "circle:R=1",
    "--mass-ratio",
    "10",
    "--v0-over-c1",
    "0.01",
    "--law",
    "signorini",
    "--json",
];

#[test]
fn run_reports_histories_with_their_errors() {
    let mut args = RUN_BASE.to_vec();
    args.extend([
        "--end",
        "c1t/R=0.5",
        "--dx",
        "0.01",
        "--pressure-at",
        "c1t/R=0.4",
    ]);
    let v = json(&args);
    assert_eq!(v["law"], "signorini");
    assert_eq!(v["grid"]["edge_cell"], "model");
    // whole cells instead: labelled, and another edge
    let mut whole = args.clone();
    whole.extend(["--edge-cell", "whole"]);
    let w = json(&whole);
    assert_eq!(w["grid"]["edge_cell"], "whole");
    assert_ne!(w["b_over_R"], v["b_over_R"]);
    let n = v["c1t_over_R"].as_array().unwrap().len();
    assert!(n >= 4);
    for key in [
        "h_over_R",
        "hdot_over_v0",
        "b_over_R",
        "bdot_over_c1",
        "stage",
        "force_over_rho_c1sq_R",
    ] {
        assert_eq!(v[key].as_array().unwrap().len(), n, "{key}");
    }
    for key in ["h_over_R", "b_over_R", "force_over_rho_c1sq_R"] {
        let e = v["error_estimate"][key].as_array().unwrap();
        assert!(e.iter().all(|x| num(x) >= 0.0), "{key}");
    }
    // early times: h = V0 t to first order
    let t0 = num(&v["c1t_over_R"][0]);
    let h0 = num(&v["h_over_R"][0]);
    assert!((h0 / (0.01 * t0) - 1.0).abs() < 1e-3);
    let p = &v["pressure"][0];
    assert!(p["x_over_R"].as_array().unwrap().len() >= 3);
    // the same run as CSV: a header and one row per time
    let mut csv_args: Vec<&str> = args.iter().copied().filter(|a| *a != "--json").collect();
    csv_args.truncate(csv_args.len() - 2);
    let (code, out, _) = impact(&csv_args);
    assert_eq!(code, 0);
    assert!(out.starts_with("# impact run"));
    let rows = out
        .lines()
        .filter(|l| !l.starts_with('#') && l.chars().next().is_some_and(|c| c.is_ascii_digit()))
        .count();
    assert_eq!(rows, n);
}

#[test]
fn run_driven_flat_punch_gives_the_plane_wave_pressure() {
    let v = json(&[
        "run",
        "--poisson",
        "0.3",
        "--profile",
        "flat:a=1",
        "--driven",
        "speed:V_over_c1=0.01",
        "--end",
        "c1t/R=0.3",
        "--dx",
        "0.0125",
        "--levels",
        "2",
        "--pressure-at",
        "c1t/R=0.2",
        "--json",
    ]);
    assert!(v["hdot_over_c1"].is_array());
    let p = &v["pressure"][0]["p_over_rho_c1sq"];
    // the centre is far from both edges: rho c1 V exactly
    assert!((num(&p[0]) / 0.01 - 1.0).abs() < 1e-10);
    // every cell carries its error estimate, from the second grid: near zero where the
    // pressure is the exact plane wave on both grids
    let e = v["pressure"][0]["error_estimate"].as_array().unwrap();
    assert_eq!(e.len(), p.as_array().unwrap().len());
    assert!(e.iter().all(|x| num(x) >= 0.0 && num(x).is_finite()));
    assert!(num(&e[0]) < 1e-10, "{}", e[0]);
}

/// A wedge driven so that its prescribed edge runs at 0.555 c1 (between c_R and c2, where a
/// steadily moving prescribed edge has no solution, `docs/edge.md`, section 5) is reported as
/// such over its whole run, in the JSON and in the CSV's header; the same wedge under
/// Signorini's law has a solution (its free edge runs ahead of the geometric one) and reports
/// none; an edge below c_R reports none.
#[test]
fn run_reports_where_a_prescribed_edge_has_no_solution() {
    let wedge = |d: f64, law: &str, csv: bool| {
        let v = format!("speed:V_over_c1={}", d / 80f64.to_radians().tan());
        let mut args = vec![
            "run",
            "--poisson",
            "0.25",
            "--profile",
            "wedge:theta_deg=80",
            "--length",
            "1",
            "--driven",
            &v,
            "--law",
            law,
            "--end",
            "c1t/R=0.5",
            "--dx",
            "0.02",
            "--levels",
            "1",
        ];
        if !csv {
            args.push("--json");
        }
        let (code, out, err) = impact(&args);
        assert_eq!(code, 0, "{err}");
        out
    };
    let v: Value = serde_json::from_str(&wedge(0.555, "kinematic", false)).unwrap();
    let list = v["edge_without_solution"].as_array().unwrap();
    assert_eq!(list.len(), 1, "{list:?}");
    let last = num(v["c1t_over_R"].as_array().unwrap().last().unwrap());
    assert!(num(&list[0]["from_c1t_over_R"]) <= 0.1);
    assert!((num(&list[0]["to_c1t_over_R"]) - last).abs() < 1e-12);
    assert!(list[0]["reason"].as_str().unwrap().contains("no solution"));
    assert!(wedge(0.555, "kinematic", true).contains("# edge without solution: c1 t/R from"));
    for (d, law) in [(0.555, "signorini"), (0.3, "kinematic")] {
        let v: Value = serde_json::from_str(&wedge(d, law, false)).unwrap();
        assert_eq!(
            v["edge_without_solution"],
            serde_json::json!([]),
            "{law} at {d}"
        );
    }
}

#[test]
fn run_refuses_bad_input_with_one_line() {
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--mass-ratio", "0", "--end", "c1t/R=1"], "mass ratio"),
        (vec!["--end", "c1t/R=0"], "end time"),
        (vec!["--end", "c1t/R=1", "--kappa", "0.25"], "kappa"),
        (
            vec!["--end", "c1t/R=1", "--driven", "speed:V_over_c1=0.01"],
            "contradictory",
        ),
        (vec!["--end", "t=1"], "--end"),
        (
            vec!["--end", "c1t/R=1", "--edge-cell", "half"],
            "--edge-cell",
        ),
    ];
    for (extra, word) in cases {
        let mut args: Vec<&str> = RUN_BASE.to_vec();
        // later flags override: drop the base mass ratio when a case sets its own
        if extra.contains(&"--mass-ratio") {
            let i = args.iter().position(|a| *a == "--mass-ratio").unwrap();
            args.drain(i..i + 2);
        }
        args.extend(extra);
        let (code, out, err) = impact(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(out.is_empty());
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(word), "{word}: {err}");
    }
    let (code, _, err) = impact(&[
        "run",
        "--poisson",
        "0.25",
        "--profile",
        "wedge:theta_deg=120",
        "--mass-ratio",
        "1",
        "--v0-over-c1",
        "0.01",
        "--end",
        "c1t/R=1",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("theta_deg"), "{err}");
}

/// `impact edge`: the keys of each record, the exponents of each range (the closed forms of
/// `docs/edge.md`: +-1/2 below c2, Freund's q - 1/2 transonic, 0 supersonic) and refusals.
#[test]
fn edge_prints_exponents_per_range_and_refuses_bad_speeds() {
    let nu: f64 = 0.25;
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_impact"))
        .args([
            "edge",
            "--poisson",
            "0.25",
            "--speed-over-c1",
            "0.3,0.55,0.7,1.2",
            "--json",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let recs = v["records"].as_array().unwrap();
    let ranges: Vec<&str> = recs.iter().map(|r| r["range"].as_str().unwrap()).collect();
    assert_eq!(
        ranges,
        ["sub-rayleigh", "rayleigh-shear", "transonic", "supersonic"]
    );
    let sel: Vec<f64> = recs
        .iter()
        .map(|r| r["selected"].as_f64().unwrap())
        .collect();
    assert_eq!(&sel[..2], &[0.5, -0.5]);
    let m2 = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let d: f64 = 0.7;
    let a1 = (1.0 - d * d).sqrt();
    let b2 = (d * d / m2 - 1.0).sqrt();
    let q = (4.0 * a1 * b2 / (1.0 - b2 * b2).powi(2)).atan() / std::f64::consts::PI;
    assert!(
        (sel[2] - (q - 0.5)).abs() < 1e-12,
        "{} vs {}",
        sel[2],
        q - 0.5
    );
    assert_eq!(sel[3], 0.0);
    for r in recs {
        for key in ["speed_over_c1", "range", "exponents", "selected", "law"] {
            assert!(!r[key].is_null(), "missing {key}");
        }
    }
    // CSV: one row per local solution
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_impact"))
        .args([
            "edge",
            "--c1",
            "1870.83",
            "--c2",
            "1000",
            "--speed-over-c1",
            "0.2",
            "--law",
            "kinematic",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with('#'));
    assert!(text.contains("0.2,sub-rayleigh,-0.5,"));
    for (args, word) in [
        (
            vec!["--poisson", "0.25", "--speed-over-c1", "0"],
            "speed_over_c1",
        ),
        (
            vec!["--poisson", "0.25", "--speed-over-c1", "1"],
            "speed_over_c1",
        ),
        (
            vec![
                "--poisson",
                "0.25",
                "--speed-over-c1",
                "0.2",
                "--law",
                "sticky",
            ],
            "--law",
        ),
        (vec!["--poisson", "0.25"], "--speed-over-c1"),
    ] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_impact"))
            .arg("edge")
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(word), "{err}");
    }
}

/// Deformable strikers through the command line: the striker's model, its deformation and
/// energy with error estimates, the shell's strain and vibration energies; a driven flat punch
/// of an elastic material gives the one-dimensional impedance pressure
/// V/(1/(rho c1) + 1/(rho_s c1s)); the flags that contradict the model are refused.
#[test]
fn run_deformable_strikers() {
    let base = [
        "run",
        "--c1",
        "1870.83",
        "--c2",
        "1000",
        "--profile",
        "circle:R=1",
        "--v0-over-c1",
        "0.01",
        "--dx",
        "0.02",
        "--json",
    ];
    let mut args = base.to_vec();
    args.extend([
        "--striker",
        "shell:thickness_over_R=0.05,c1=5000,c2=3000,density_ratio=3",
        "--end",
        "c1t/R=1.5",
    ]);
    let v = json(&args);
    assert_eq!(v["striker"], "shell");
    let mass = num(&v["striker_model"]["mass_ratio"]);
    assert!((mass - 2.0 * std::f64::consts::PI * 0.05 * 3.0).abs() < 1e-12);
    let n = v["c1t_over_R"].as_array().unwrap().len();
    for k in [
        "striker_deformation_over_R",
        "striker_energy_over_rho_c1sq_Rsq",
        "striker_strain_energy_over_rho_c1sq_Rsq",
        "striker_vibration_energy_over_rho_c1sq_Rsq",
    ] {
        assert_eq!(v[k].as_array().unwrap().len(), n, "{k}");
        assert!(v["error_estimate"][k][n - 1].is_number(), "{k}");
    }
    // strain + vibration = the work of the pressure on the shell
    let last = |k: &str| num(&v[k][n - 1]);
    let parts = last("striker_strain_energy_over_rho_c1sq_Rsq")
        + last("striker_vibration_energy_over_rho_c1sq_Rsq");
    let total = last("striker_energy_over_rho_c1sq_Rsq");
    assert!((parts - total).abs() < 1e-9 * total, "{parts} vs {total}");

    // the full cylinder: its mass from its geometry, its energies in two parts
    let mut args = base.to_vec();
    args.extend([
        "--striker",
        "cylinder:c1=1870.83,c2=1000,density_ratio=1",
        "--end",
        "c1t/R=1",
        "--levels",
        "2",
    ]);
    let v = json(&args);
    assert_eq!(v["striker"], "cylinder");
    let mass = num(&v["striker_model"]["mass_ratio"]);
    assert!((mass - std::f64::consts::PI).abs() < 1e-12);
    assert!((num(&v["mass_ratio"]) - mass).abs() < 1e-12);
    let n = v["c1t_over_R"].as_array().unwrap().len();
    let last = |k: &str| num(&v[k][n - 1]);
    for k in [
        "striker_deformation_over_R",
        "striker_energy_over_rho_c1sq_Rsq",
        "striker_strain_energy_over_rho_c1sq_Rsq",
        "striker_vibration_energy_over_rho_c1sq_Rsq",
    ] {
        assert_eq!(v[k].as_array().unwrap().len(), n, "{k}");
        assert!(v["error_estimate"][k][n - 1].is_number(), "{k}");
        assert!(last(k) > 0.0, "{k}");
    }
    let parts = last("striker_strain_energy_over_rho_c1sq_Rsq")
        + last("striker_vibration_energy_over_rho_c1sq_Rsq");
    assert!((parts - last("striker_energy_over_rho_c1sq_Rsq")).abs() < 1e-9 * parts);

    // elastic, driven flat punch: the plane-wave pressure of two impedances in series
    let (c1, rho_ratio, c1s) = (1870.83, 2.0, 4000.0);
    let v = json(&[
        "run",
        "--c1",
        "1870.83",
        "--c2",
        "1000",
        "--striker",
        "elastic:c1=4000,c2=2000,density_ratio=2",
        "--profile",
        "flat:a=1",
        "--driven",
        "speed:V_over_c1=0.01",
        "--end",
        "c1t/R=0.5",
        "--pressure-at",
        "c1t/R=0.2",
        "--dx",
        "0.02",
        "--levels",
        "1",
        "--json",
    ]);
    assert_eq!(v["striker"], "elastic");
    let p = &v["pressure"][0];
    let want = 0.01 / (1.0 + c1 / (rho_ratio * c1s));
    let p0 = num(&p["p_over_rho_c1sq"][0]);
    assert!((p0 / want - 1.0).abs() < 1e-9, "{p0} vs {want}");

    // refusals, one line each
    for (extra, word) in [
        (
            vec![
                "--striker",
                "shell:thickness_over_R=0.05,c1=5000,c2=3000,density_ratio=3",
                "--mass-ratio",
                "2",
                "--end",
                "c1t/R=1",
            ],
            "--mass-ratio",
        ),
        (
            vec![
                "--striker",
                "elastic:c1=5900,c2=3200,density_ratio=3",
                "--mass-ratio",
                "2",
                "--end",
                "c1t/R=1",
            ],
            "end time",
        ),
        (
            vec![
                "--striker",
                "elastic:c1=5900,c2=3200",
                "--mass-ratio",
                "2",
                "--end",
                "c1t/R=0.5",
            ],
            "density_ratio",
        ),
        (
            vec![
                "--striker",
                "shell:thickness_over_R=0.9,c1=5000,c2=3000,density_ratio=3",
                "--end",
                "c1t/R=0.5",
            ],
            "thickness",
        ),
        (
            vec![
                "--striker",
                "cylinder:c1=5900,c2=3200,density_ratio=3",
                "--mass-ratio",
                "2",
                "--end",
                "c1t/R=1",
            ],
            "--mass-ratio",
        ),
        (
            vec![
                "--striker",
                "cylinder:c1=5900,c2=3200,density_ratio=3",
                "--end",
                "c1t/R=400",
            ],
            "end time",
        ),
        (
            vec![
                "--striker",
                "cylinder:c1=1414.2135623730951,c2=1000,density_ratio=1",
                "--end",
                "c1t/R=1",
            ],
            "striker's Poisson's ratio 0",
        ),
    ] {
        let mut args = base.to_vec();
        args.extend(extra);
        let (code, out, err) = impact(&args);
        assert_eq!(code, 2, "{args:?}: {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(word), "{args:?}: {err}");
    }
    // the cylinder's own profile only
    let (code, _, err) = impact(&[
        "run",
        "--c1",
        "1870.83",
        "--c2",
        "1000",
        "--striker",
        "cylinder:c1=5900,c2=3200,density_ratio=3",
        "--profile",
        "wedge:theta_deg=10",
        "--v0-over-c1",
        "0.01",
        "--end",
        "c1t/R=0.5",
    ]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("profile") && err.contains("circle:R=1"),
        "{err}"
    );
    // a cell narrower than the disk's response serves, named as the march's cell width
    let (code, _, err) = impact(&[
        "run",
        "--c1",
        "1870.83",
        "--c2",
        "1000",
        "--striker",
        "cylinder:c1=5900,c2=3200,density_ratio=3",
        "--profile",
        "parabola:R=1",
        "--v0-over-c1",
        "0.01",
        "--dx",
        "0.001",
        "--levels",
        "1",
        "--end",
        "c1t/R=0.05",
    ]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("cell width dx/R") && err.contains("cylinder"),
        "{err}"
    );
    let (code, _, err) = impact(&[
        "run",
        "--poisson",
        "0.3",
        "--striker",
        "elastic:c1=5900,c2=3200,density_ratio=3",
        "--profile",
        "circle:R=1",
        "--mass-ratio",
        "2",
        "--v0-over-c1",
        "0.01",
        "--end",
        "c1t/R=0.5",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--c1"), "{err}");
}

/// `impact run --digits`: the march in double-double, every value printed to the digits asked
/// for, the same solution as the f64 run to f64's rounding (with the same error estimates),
/// labelled; more digits than double-double holds, or a deformable striker, refused.
#[test]
fn run_digits_prints_the_double_double_march() {
    let mut args = RUN_BASE.to_vec();
    // the end a whole number of the coarsest steps, c1 dt/R = 4 kappa dx = 0.16
    args.extend([
        "--end",
        "c1t/R=0.96",
        "--dx",
        "0.02",
        "--pressure-at",
        "c1t/R=0.8",
    ]);
    let f = json(&args);
    let mut dd_args = args.clone();
    dd_args.extend(["--digits", "30"]);
    let d = json(&dd_args);
    assert_eq!(d["precision"]["digits"], 30);
    assert_eq!(d["precision"]["arithmetic"], "double-double");
    assert!(f.get("precision").is_none());
    // the significant digits of a printed number
    let significant = |v: &Value| -> String {
        v.to_string()
            .split(['e', 'E'])
            .next()
            .unwrap()
            .chars()
            .filter(|c| c.is_ascii_digit())
            .skip_while(|c| *c == '0')
            .collect()
    };
    let digits = |v: &Value| significant(v).len();
    for key in [
        "h_over_R",
        "b_over_R",
        "force_over_rho_c1sq_R",
        "c1t_over_R",
    ] {
        let (a, b) = (f[key].as_array().unwrap(), d[key].as_array().unwrap());
        assert_eq!(a.len(), b.len(), "{key}");
        for (x, y) in a.iter().zip(b) {
            assert_eq!(digits(y), 30, "{key}: {y}");
            let (x, y) = (num(x), num(y));
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(1e-6),
                "{key}: {x} against {y}"
            );
        }
        // the error estimates are the discretisation's, the same in both
        if let (Some(ea), Some(eb)) = (
            f["error_estimate"][key].as_array(),
            d["error_estimate"][key].as_array(),
        ) {
            assert_eq!(ea.len(), eb.len(), "{key}");
            for (x, y) in ea.iter().zip(eb) {
                assert!(
                    (num(x) - num(y)).abs() <= 1e-6 * num(x).abs() + 1e-15,
                    "{key}"
                );
            }
        }
    }
    // the inputs are their decimal values: the first report time, c1 dt/R = 4 kappa dx on
    // the coarsest grid, is 0.16 to every printed digit
    assert_eq!(
        significant(&d["c1t_over_R"][0]),
        format!("16{}", "0".repeat(28))
    );
    let p = d["pressure"][0]["p_over_rho_c1sq"].as_array().unwrap();
    assert!(p.iter().all(|v| digits(v) == 30));
    // refusals, one line each
    for (extra, word) in [
        (vec!["--digits", "40"], "--digits"),
        (vec!["--digits", "0"], "--digits"),
    ] {
        let mut a = args.clone();
        a.retain(|x| *x != "--json");
        a.extend(extra);
        let (code, out, err) = impact(&a);
        assert_eq!(code, 2, "{a:?}");
        assert!(out.is_empty());
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(word), "{err}");
    }
}

/// Every null, anywhere in a report, is an error: values and estimates that cannot be formed
/// are absent, with their reason under `unavailable`.
fn assert_no_null(v: &Value, path: &str) {
    match v {
        Value::Null => panic!("{path} is null"),
        Value::Number(_) => assert!(num(v).is_finite(), "{path} = {v}"),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .for_each(|(i, x)| assert_no_null(x, &format!("{path}[{i}]"))),
        Value::Object(o) => o
            .iter()
            .for_each(|(k, x)| assert_no_null(x, &format!("{path}.{k}"))),
        _ => {}
    }
}

const REFERENCE_40: [&str; 14] = [
    "run",
    "--c1",
    "1870.83",
    "--c2",
    "1000",
    "--profile",
    "parabola:R=1",
    "--mass-ratio",
    "10",
    "--v0-over-c1",
    "0.01",
    "--end",
    "c1t/R=40",
    "--json",
];

/// The README's reference case past its rebound: it separates, the force never pulls, the
/// rebound and the energy audit are reported with their estimates, the inputs are echoed,
/// and no value is null; the CSV carries the same as `#` lines and the energy defect column.
#[test]
fn run_past_the_rebound_reports_the_separation() {
    let v = json(&REFERENCE_40);
    assert_no_null(&v, "run");
    let f = v["force_over_rho_c1sq_R"].as_array().unwrap();
    let peak = f.iter().map(num).fold(0.0, f64::max);
    assert!(f.iter().all(|x| num(x) >= -1e-12 * peak));
    let sep = num(&v["separation_c1t_over_R"]["value"]);
    assert!(sep > 15.0 && sep < 20.0, "{sep}");
    let e = num(&v["restitution"]);
    assert!(e > 0.5 && e < 0.7, "{e}");
    assert!(num(&v["error_estimate"]["restitution"]) < 5e-4);
    let closure = e * e + num(&v["energy_to_half_plane"]) - 1.0;
    assert!(closure.abs() < 1e-3, "{closure}");
    assert_eq!(v["energy_audit"]["within_bound"], true);
    assert_eq!(num(&v["mass_ratio"]), 10.0);
    assert_eq!(num(&v["v0_over_c1"]), 0.01);
    assert!(v["peak_force"]["force_over_rho_c1sq_R"].is_number());
    let t = v["c1t_over_R"].as_array().unwrap();
    assert_eq!(num(t.last().unwrap()), 40.0);
    let d = v["energy_defect"].as_array().unwrap();
    assert_eq!(d.len(), t.len());
    assert_eq!(
        v["error_estimate"]["energy_defect"]
            .as_array()
            .unwrap()
            .len(),
        t.len()
    );
    // after the separation the striker flies free at its rebound speed
    let hdot = v["hdot_over_v0"].as_array().unwrap();
    let last = num(hdot.last().unwrap());
    assert!((last + e).abs() <= 1e-14 * e, "{last} against {e}");
    // the CSV
    let csv_args: Vec<&str> = REFERENCE_40
        .iter()
        .copied()
        .filter(|a| *a != "--json")
        .collect();
    let (code, out, _) = impact(&csv_args);
    assert_eq!(code, 0);
    assert!(out.contains("# restitution: "), "{out:.400}");
    assert!(out.contains("# separation_c1t_over_R: "));
    let header = out.lines().find(|l| l.starts_with("c1t_over_R")).unwrap();
    assert!(header.contains(",energy_defect,") && header.contains("err_energy_defect"));
}

/// Before the separation, on one level: the rebound, the estimates and the orders are declared
/// unavailable with their reasons, and the largest force is not called a peak while it rises.
#[test]
fn run_declares_what_it_cannot_form() {
    let args = [
        "run",
        "--poisson",
        "0.3",
        "--profile",
        "parabola:R=1",
        "--mass-ratio",
        "10",
        "--v0-over-c1",
        "0.01",
        "--end",
        "c1t/R=2",
        "--dx",
        "0.01",
        "--levels",
        "1",
    ];
    let mut with_json = args.to_vec();
    with_json.push("--json");
    let v = json(&with_json);
    assert_no_null(&v, "run");
    let why = v["unavailable"].as_object().unwrap();
    for key in [
        "restitution",
        "separation_c1t_over_R",
        "error_estimate",
        "peak_force",
    ] {
        assert!(why[key].as_str().is_some_and(|r| !r.is_empty()), "{key}");
    }
    assert!(v.get("restitution").is_none() && v.get("peak_force").is_none());
    assert!(v["largest_force"]["force_over_rho_c1sq_R"].is_number());
    assert!(v["error_estimate"].as_object().unwrap().is_empty());
    // the CSV says the same in # lines
    let (code, out, _) = impact(&args);
    assert_eq!(code, 0);
    assert!(out.contains("# unavailable: restitution: "));
}

/// `--end separation`, the refusals of the time and the memory, and a driven run's time
/// levels: h = V t at every reported time, the last at `--end` exactly.
#[test]
fn run_to_separation_and_refusals() {
    let v = json(&[
        "run",
        "--poisson",
        "0.3",
        "--profile",
        "parabola:R=1",
        "--mass-ratio",
        "1",
        "--v0-over-c1",
        "0.01",
        "--end",
        "separation",
        "--dx",
        "0.01",
        "--json",
    ]);
    let sep = num(&v["separation_c1t_over_R"]["value"]);
    let t = v["c1t_over_R"].as_array().unwrap();
    let last = num(t.last().unwrap());
    assert!(last > sep && last < sep + 0.2, "{sep} {last}");
    assert_eq!(v["end"]["separation"], true);
    let cases: Vec<(Vec<&str>, &str)> = vec![
        // a pressure profile past the end
        (
            vec![
                "--mass-ratio",
                "10",
                "--v0-over-c1",
                "0.01",
                "--end",
                "c1t/R=1",
                "--pressure-at",
                "c1t/R=1.5",
            ],
            "--pressure-at",
        ),
        // to the separation, a driven striker
        (
            vec!["--driven", "speed:V_over_c1=0.01", "--end", "separation"],
            "separation",
        ),
        // a grid whose history would not fit the memory limit
        (
            vec![
                "--mass-ratio",
                "10",
                "--v0-over-c1",
                "0.01",
                "--end",
                "c1t/R=200",
                "--dx",
                "0.0005",
            ],
            "GiB",
        ),
        // a light punch whose deceleration the step does not resolve
        (
            vec![
                "--mass-ratio",
                "0.00372818",
                "--v0-over-c1",
                "0.1",
                "--end",
                "c1t/R=1",
            ],
            "deceleration",
        ),
    ];
    for (extra, word) in cases {
        let mut args = vec!["run", "--poisson", "0.3"];
        args.extend(if word == "deceleration" {
            ["--profile", "flat:a=1.0"]
        } else {
            ["--profile", "parabola:R=1"]
        });
        args.extend(extra);
        let (code, out, err) = impact(&args);
        assert_eq!(code, 2, "{args:?}: {out:.200}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(word), "{word}: {err}");
    }
    // the driven punch of the README: h = V t at every reported time, the end exactly
    let v = json(&[
        "run",
        "--poisson",
        "0.3",
        "--profile",
        "flat:a=1",
        "--driven",
        "speed:V_over_c1=0.01",
        "--end",
        "c1t/R=1",
        "--json",
    ]);
    let t = v["c1t_over_R"].as_array().unwrap();
    let h = v["h_over_R"].as_array().unwrap();
    assert_eq!(num(t.last().unwrap()), 1.0);
    for (t, h) in t.iter().zip(h) {
        assert!(
            (num(h) - 0.01 * num(t)).abs() <= 1e-14 * 0.01 * num(t),
            "{t} {h}"
        );
    }
    assert!(v["unavailable"]["energy_defect"].as_str().is_some());
}

/// A run states the memory it was estimated to need before it started (`grid`), and that
/// statement is the one the limit is held to: a limit just below it refuses the run in one
/// line naming --dx, just above it runs the case (with the start on finer grids, whose grids
/// the statement covers); on one grid throughout the statement grows with the grid about as
/// its space-time cells do (halving dx doubles the steps and the contact's cells).
#[test]
fn run_states_its_memory_need_and_the_limit_holds_it() {
    let mut args = RUN_BASE.to_vec();
    args.extend(["--end", "c1t/R=1", "--levels", "1"]);
    let with_dx = |dx: &'static str| {
        let mut a = args.clone();
        a.extend(["--dx", dx]);
        a
    };
    // one grid throughout: the history's part grows with the grid's space-time cells
    let one_grid = |dx: &'static str| {
        let mut a = with_dx(dx);
        a.extend(["--start-halvings", "0"]);
        a
    };
    let coarse = json(&one_grid("0.01"));
    let fine = json(&one_grid("0.0025"));
    let gib = |v: &Value| v["grid"]["estimated_memory_gib"].as_f64().unwrap();
    let (gc, gf) = (gib(&coarse), gib(&fine));
    assert!(gc > 0.0 && gf > gc, "{gc} {gf}");
    // beyond the fixed part (64 MiB), the history's part grows 16-fold for 4 times finer
    let base = 64.0 / 1024.0;
    let growth = (gf - base) / (gc - base);
    assert!((8.0..=32.0).contains(&growth), "growth {growth}");
    // with the start on finer grids (the default) the statement covers its grids too
    let fine = json(&with_dx("0.0025"));
    let gf = gib(&fine);
    assert_eq!(fine["grid"]["start_halvings"].as_u64(), Some(6));
    for (factor, refused) in [(0.99, true), (1.01, false)] {
        let mut a = with_dx("0.0025");
        let limit = format!("{}", gf * factor);
        a.extend(["--memory-limit-gib", &limit]);
        let (code, out, err) = impact(&a);
        if refused {
            assert_eq!(code, 2, "{err}");
            assert_eq!(err.trim().lines().count(), 1, "{err}");
            assert!(err.contains("GiB") && err.contains("--dx"), "{err}");
        } else {
            assert_eq!(code, 0, "{err}");
            let v: Value = serde_json::from_str(&out).unwrap();
            assert_eq!(gib(&v), gf);
        }
    }
}

/// `impact striker-green`: the keys, arrays [angle][time] equal to the library's, the
/// deformation the total minus the arc-averaged translation in closed form, every value with
/// its estimate; refusals in one line naming the flag.
#[test]
fn striker_green_prints_the_cylinder_response_with_its_keys() {
    let v = json(&[
        "striker-green",
        "--striker",
        "cylinder",
        "--poisson",
        "0.25",
        "--arc-over-R",
        "0.05",
        "--at-deg",
        "0,2.8648,90,180",
        "--times",
        "c2t/R=0.1,1,3",
        "--json",
    ]);
    for key in [
        "c2t_over_R",
        "angle_deg",
        "w_over_p0R_mu",
        "w_def_over_p0R_mu",
        "error_estimate",
    ] {
        assert!(v.get(key).is_some(), "{key} missing");
    }
    let times: Vec<f64> = serde_json::from_value(v["c2t_over_R"].clone()).unwrap();
    let angles: Vec<f64> = serde_json::from_value(v["angle_deg"].clone()).unwrap();
    assert_eq!(times, [0.1, 1.0, 3.0]);
    assert_eq!(angles, [0.0, 2.8648, 90.0, 180.0]);
    let w: Vec<Vec<f64>> = serde_json::from_value(v["w_over_p0R_mu"].clone()).unwrap();
    let d: Vec<Vec<f64>> = serde_json::from_value(v["w_def_over_p0R_mu"].clone()).unwrap();
    let e: Vec<Vec<f64>> =
        serde_json::from_value(v["error_estimate"]["w_over_p0R_mu"].clone()).unwrap();
    let ed: Vec<Vec<f64>> =
        serde_json::from_value(v["error_estimate"]["w_def_over_p0R_mu"].clone()).unwrap();
    let disk = impact::striker::disk::Disk::new(0.25).unwrap();
    let radians: Vec<f64> = angles.iter().map(|a| a.to_radians()).collect();
    let lib = disk.arc_step_response(0.05, &radians, &times).unwrap();
    let theta0: f64 = 0.025;
    for j in 0..4 {
        assert_eq!(w[j].len(), 3);
        for i in 0..3 {
            assert_eq!(w[j][i], lib.total[j][i]);
            assert_eq!(e[j][i], lib.error[j][i]);
            assert_eq!(ed[j][i], e[j][i]);
            assert!(e[j][i] > 0.0 && e[j][i] < 1e-5, "{j} {i}: {}", e[j][i]);
            // X = F t^2/(2 m), F = 2 sin(theta0), m = pi
            let x = 2.0 * theta0.sin() * times[i] * times[i] / (2.0 * std::f64::consts::PI);
            let mean = x * radians[j].cos() * theta0.sin() / theta0;
            assert!((w[j][i] - d[j][i] - mean).abs() < 1e-15, "{j} {i}");
        }
    }
    // nothing has reached the far side at c2 t/R = 1 (the P wave needs 2 sin(...)/c1s)
    assert!(w[3][1].abs() <= e[3][1]);
    // the flags of a small case, each pair replaceable
    let base = [
        "striker-green",
        "--poisson",
        "0.25",
        "--arc-over-R",
        "0.05",
        "--at-deg",
        "0",
        "--times",
        "c2t/R=1",
    ];
    let with = |args: &[&'static str]| -> Vec<&'static str> {
        let mut argv = base.to_vec();
        for pair in args.chunks(2) {
            // the later flag replaces the earlier: drop the default pair first
            if let Some(p) = argv.iter().position(|a| *a == pair[0]) {
                argv.drain(p..p + 2);
            }
            argv.extend(pair.iter());
        }
        argv
    };
    // CSV: a header and one row per angle and time
    let (code, out, _) = impact(&with(&["--at-deg", "0,10", "--times", "c2t/R=0.5"]));
    assert_eq!(code, 0);
    let rows: Vec<&str> = out.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(
        rows[0],
        "angle_deg,c2t_over_R,w_over_p0R_mu,w_def_over_p0R_mu,error_estimate"
    );
    assert_eq!(rows.len(), 3);
    for (args, flag) in [
        (vec!["--arc-over-R", "0.0001"], "arc"),
        (vec!["--arc-over-R", "5"], "arc"),
        (vec!["--times", "c2t/R=0"], "c2 t/R"),
        (vec!["--times", "c2t/R=200"], "c2 t/R"),
        (vec!["--times", "c1t/R=1"], "--times"),
        (vec!["--at-deg", "a"], "--at-deg"),
        (vec!["--striker", "shell"], "--striker"),
        (vec!["--poisson", "0.6"], "poisson"),
    ] {
        let argv = with(&args);
        let (code, _, err) = impact(&argv);
        assert_eq!(code, 2, "{argv:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{argv:?}: {err}");
        assert!(
            err.to_lowercase().contains(&flag.to_lowercase()),
            "{argv:?}: {err}"
        );
    }
}

/// `impact run --geometry axisymmetric`: the sphere on the half-space, the documented command
/// line (no material flag: Poisson's solid), its keys with their estimates, Hertz beside it; and its refusals, one line each.
#[test]
fn run_axisymmetric_reports_the_sphere_and_refuses_what_does_not_apply() {
    let v = json(&[
        "run",
        "--geometry",
        "axisymmetric",
        "--profile",
        "sphere:R=1",
        "--mass-ratio",
        "4.18879",
        "--v0-over-c1",
        "0.02",
        "--law",
        "signorini",
        "--end",
        "c1t/R=14",
        "--json",
    ]);
    assert_eq!(v["geometry"], "axisymmetric");
    // no material given: Poisson's solid
    assert_eq!(num(&v["poisson"]), 0.25);
    // the edge's speed names the stage, without an estimate: declared
    assert!(v["unavailable"]["adot_over_c1"].is_string());
    assert!(v["error_estimate"].get("adot_over_c1").is_none());
    let n = v["c1t_over_R"].as_array().unwrap().len();
    for k in [
        "h_over_R",
        "hdot_over_v0",
        "a_over_R",
        "force_over_rho_c1sq_Rsq",
        "kinetic_energy_over_rho_c1sq_Rcu",
        "work_over_rho_c1sq_Rcu",
        "radiated_energy_fraction",
        "energy_defect",
    ] {
        assert_eq!(v[k].as_array().unwrap().len(), n, "{k}");
        assert_eq!(v["error_estimate"][k].as_array().unwrap().len(), n, "{k}");
    }
    assert_eq!(v["stage"].as_array().unwrap().len(), n);
    // Signorini's energy defect is its own error: every estimate covers the defect
    for (d, e) in v["energy_defect"]
        .as_array()
        .unwrap()
        .iter()
        .zip(v["error_estimate"]["energy_defect"].as_array().unwrap())
    {
        assert!(e.as_f64().unwrap() >= d.as_f64().unwrap().abs());
    }
    // the default grid puts about 30 rings across the largest contact radius
    let rings = v["resolution"]["largest_contact_rings"].as_u64().unwrap();
    assert!((25..=45).contains(&rings), "{rings}");
    // it separated before c1 t/R = 14: the rebound, its loss, Hertz's numbers beside it
    let e = num(&v["restitution"]);
    let rad = num(&v["energy_to_half_space"]);
    assert!(
        e > 0.8 && e < 1.0 && (e * e + rad - 1.0).abs() < 1e-12,
        "{e} {rad}"
    );
    assert!(v["error_estimate"]["restitution"].is_number());
    let hertz_peak = num(&v["hertz"]["peak_force_over_rho_c1sq_Rsq"]);
    let peak = num(&v["peak_force"]["force_over_rho_c1sq_Rsq"]);
    assert!(
        peak < hertz_peak && peak > 0.9 * hertz_peak,
        "{peak} {hertz_peak}"
    );
    assert!(v["first_order_radiation"]["prefactor"].is_number());
    assert_no_null(&v, "");
    let base = [
        "run",
        "--geometry",
        "axisymmetric",
        "--profile",
        "sphere:R=1",
        "--poisson",
        "0.25",
        "--end",
        "c1t/R=1",
        "--mass-ratio",
        "4",
        "--v0-over-c1",
        "0.01",
    ];
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--dx", "0.01"], "--dr"),
        (vec!["--digits", "20"], "digits"),
        (vec!["--edge-cell", "whole"], "edge-cell"),
        (
            vec!["--striker", "elastic:c1=6000,c2=3000,density_ratio=1"],
            "rigid",
        ),
        (vec!["--profile", "wedge:theta_deg=80"], "sphere"),
        (vec!["--profile", "cone:theta_deg=95"], "theta_deg"),
        (vec!["--geometry", "spherical"], "geometry"),
        (vec!["--dr", "0"], "dr"),
    ];
    for (extra, word) in cases {
        let mut args: Vec<&str> = base.to_vec();
        // a case's flag replaces the base's
        if let Some(i) = args.iter().position(|a| *a == extra[0]) {
            args.drain(i..i + 2);
        }
        args.extend(extra);
        let (code, out, err) = impact(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(out.is_empty());
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(word), "{word}: {err}");
    }
    // a punch too light for the step (it would bounce back from step to step, a restitution
    // of (r - 1)/(r + 1) = 0.98 at r = 105) is refused, naming the ring width
    let (code, _, err) = impact(&[
        "run",
        "--geometry",
        "axisymmetric",
        "--profile",
        "flat:a=1",
        "--mass-ratio",
        "1e-3",
        "--v0-over-c1",
        "0.01",
        "--end",
        "separation",
    ]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("dr") && err.contains("deceleration"), "{err}");
    // and the plane run refuses the rings' width
    let (code, _, err) = impact(&[
        "run",
        "--poisson",
        "0.25",
        "--profile",
        "parabola:R=1",
        "--mass-ratio",
        "10",
        "--v0-over-c1",
        "0.01",
        "--end",
        "c1t/R=1",
        "--dr",
        "0.01",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--dx"), "{err}");
}
