//! Deformable strikers (`docs/strikers.md`), each check against an independent quantity: the
//! one-dimensional impedance law of two half-planes in flat contact, the identity "a striker of
//! the half-plane's own material is a rigid striker on a half-plane of half the density", the
//! rigid limit, the shell's modes against the classical ring formulas and against an
//! independent mpmath derivation with a numerical ODE integration
//! (`tests/reference/shell_mpmath.py`), and the energy balance with the striker's strain and
//! vibration energy from an exact modal recursion.

use crate::common;

use common::{history, m2};
use impact::striker::Ring;
use impact::{
    Drive, EdgeLaw, ImpactCase, ImpactError, Profile, ShellStriker, Striker, StrikerMaterial,
};

fn own_material(nu: f64) -> StrikerMaterial {
    StrikerMaterial {
        c1_ratio: 1.0,
        c2_ratio: m2(nu).sqrt(),
        density_ratio: 1.0,
    }
}

/// A free parabola on one grid (no refinement levels).
fn free_parabola(nu: f64, mass_ratio: f64, v0: f64, end: f64, dx: f64) -> ImpactCase {
    let mut case = common::free_parabola(nu, mass_ratio, v0, end, dx);
    case.levels = 1;
    case
}

/// A driven flat punch of an elastic material on the half-plane: wherever the edges' waves
/// (in either body) have not arrived, the two bodies are one-dimensional half-spaces in flat
/// contact and the pressure is the impedance law V / (1/(rho c1) + 1/(rho_s c1s)); for two
/// identical bodies each surface moves at V/2 and p = rho c1 V/2.
#[test]
fn flat_contact_follows_the_impedance_law() {
    let nu = 0.3;
    let v = 0.01;
    for mat in [
        own_material(nu),
        StrikerMaterial {
            c1_ratio: 1.3,
            c2_ratio: 0.7,
            density_ratio: 0.8,
        },
    ] {
        let mut case = ImpactCase::new(
            nu,
            Profile::Flat { half_width: 1.0 },
            Drive::Speed(v),
            EdgeLaw::Signorini,
            1.2,
        )
        .with_striker(Striker::Elastic(mat));
        case.dx = 0.0125;
        case.levels = 1;
        let sol = case.solve(|_| {}).unwrap();
        let run = &sol.runs[0];
        // over rho c1^2: p = (V/c1) / (1 + rho c1/(rho_s c1s))
        let want = v / (1.0 + 1.0 / (mat.density_ratio * mat.c1_ratio));
        let fastest = mat.c1_ratio.max(1.0);
        let mut checked = 0;
        for st in &run.steps {
            for (j, p) in st.pressure.iter().enumerate() {
                let x = j as f64 * run.dx;
                // a margin of 16 cells: the implicit step solve spreads an edge's influence
                // beyond the light cone, falling about tenfold a cell
                if 1.0 - x > fastest * st.t + 16.0 * run.dx {
                    let rel = p * m2(nu) / want - 1.0;
                    assert!(rel.abs() < 1e-9, "t = {}, x = {x}: {rel:e}", st.t);
                    checked += 1;
                }
            }
        }
        assert!(checked > 150, "only {checked} cells checked");
        // the surfaces' velocities at the centre: (rho_s c1s) V/(rho c1 + rho_s c1s) for the
        // half-plane, the rest for the striker (each V/2 for identical bodies)
        let st = &run.steps[10];
        let prev = &run.steps[9];
        let share = 1.0 / (1.0 + 1.0 / (mat.density_ratio * mat.c1_ratio));
        let vw = (st.w[0] - prev.w[0]) / run.dt / v;
        let vs = (st.ws[0] - prev.ws[0]) / run.dt / v;
        assert!((vw - share).abs() < 1e-9, "half-plane surface speed {vw}");
        assert!(
            (vs - (1.0 - share)).abs() < 1e-9,
            "striker surface speed {vs}"
        );
    }
}

/// Two identical bodies, the striker free and heavy: at the start each surface moves at V0/2
/// and the pressure is rho c1 V0/2 (the one-dimensional result).
#[test]
fn identical_bodies_share_the_impact_speed() {
    let nu = 0.25;
    let v0 = 0.01;
    let mut case = ImpactCase::new(
        nu,
        Profile::Flat { half_width: 1.0 },
        Drive::Free {
            mass_ratio: 1e4,
            v0_over_c1: v0,
        },
        EdgeLaw::Signorini,
        0.5,
    )
    .with_striker(Striker::Elastic(own_material(nu)));
    case.dx = 0.0125;
    case.levels = 1;
    let sol = case.solve(|_| {}).unwrap();
    let st = &sol.runs[0].steps[0];
    let rel = st.pressure[0] * m2(nu) / (0.5 * v0) - 1.0;
    // the heavy striker slows by F dt/m0 ~ 1e-6 relative over the step
    assert!(rel.abs() < 1e-5, "p/(rho c1 V0/2) - 1 = {rel:e}");
}

/// A striker of the half-plane's own material (local model) doubles the compliance, i.e. it is
/// the rigid striker on a half-plane of half the density and the same wave speeds: with
/// m0 fixed, the rigid case has twice the mass ratio, and its force over rho_B c1^2 R is twice
/// the elastic case's over rho c1^2 R. Over the whole history, both edge laws.
#[test]
fn own_material_striker_is_rigid_on_half_the_density() {
    let nu = 0.25;
    for law in [EdgeLaw::Signorini, EdgeLaw::Kinematic] {
        // to c1 t/R = 0.7, so that both runs march past their end for the smoothing windows
        // of their last reports (`Run::beyond`: the local model holds to c1 t/R = 2)
        let mut elastic = free_parabola(nu, 10.0, 0.01, 0.7, 0.01)
            .with_striker(Striker::Elastic(own_material(nu)));
        elastic.law = law;
        let mut rigid = free_parabola(nu, 20.0, 0.01, 0.7, 0.01);
        rigid.law = law;
        // on the elastic striker's grid throughout (only a rigid striker starts on finer
        // grids)
        rigid.start_halvings = 0;
        let (re, _) = elastic.solve(|_| {}).unwrap().history();
        let (rr, _) = rigid.solve(|_| {}).unwrap().history();
        assert_eq!(re.len(), rr.len());
        let fmax = rr.iter().map(|r| r.force.value).fold(0.0, f64::max);
        let wmax = rr.iter().map(|r| r.work.value).fold(0.0, f64::max);
        for (e, r) in re.iter().zip(&rr) {
            assert!((e.h.value - r.h.value).abs() < 1e-12, "t = {}", e.t);
            assert!((e.b.value - r.b.value).abs() < 1e-12, "t = {}", e.t);
            assert!(
                (2.0 * e.force.value - r.force.value).abs() < 1e-10 * fmax,
                "t = {}: {} against {}",
                e.t,
                2.0 * e.force.value,
                r.force.value
            );
            // the work splits equally between the two bodies
            let ew = e.work.value;
            let es = e.striker_energy.unwrap().value;
            assert!((ew - es).abs() < 1e-10 * wmax, "t = {}: {ew} {es}", e.t);
            assert!((2.0 * (ew + es) - r.work.value).abs() < 1e-10 * wmax);
            // the striker flattens as much as the half-plane sinks
            assert!(e.striker_deformation.unwrap().value > 0.0 || e.force.value == 0.0);
        }
    }
}

/// The rigid limit: as the striker's modulus grows (elastic: density at fixed wave speeds,
/// shell: wave speeds at fixed mass), the histories tend to the rigid striker's, the
/// difference falling like the compliance.
#[test]
fn stiff_strikers_tend_to_the_rigid_one() {
    let nu = 0.3;
    let (v0, end, dx) = (0.01, 1.3, 0.02);
    let gap = |a: &[impact::HistoryRow], b: &[impact::HistoryRow]| -> f64 {
        let fmax = b.iter().map(|r| r.force.value).fold(0.0, f64::max);
        a.iter()
            .zip(b)
            .map(|(x, y)| (x.force.value - y.force.value).abs() / fmax)
            .fold(0.0, f64::max)
    };
    // elastic: modulus ratio 4, 16, 64 through the density
    // the rigid limit on the strikers' grid throughout (only a rigid striker starts on
    // finer grids)
    let mut one_grid = free_parabola(nu, 10.0, v0, end, dx);
    one_grid.start_halvings = 0;
    let rigid = history(one_grid, Striker::Rigid);
    let gaps: Vec<f64> = [1.0, 4.0, 16.0]
        .iter()
        .map(|&d| {
            let mat = StrikerMaterial {
                c1_ratio: 1.5,
                c2_ratio: 0.8,
                density_ratio: d,
            };
            let rows = history(free_parabola(nu, 10.0, v0, end, dx), Striker::Elastic(mat));
            gap(&rows, &rigid)
        })
        .collect();
    assert!(gaps[0] > 1e-3, "elastic gaps {gaps:?}");
    for w in gaps.windows(2) {
        let ratio = w[0] / w[1];
        assert!(ratio > 2.5 && ratio < 6.0, "elastic gaps {gaps:?}");
    }
    // shell: thickness 0.05, wave speeds 16, 64, 256 times the half-plane's. A thin shell is
    // locally soft whatever its modulus (its wall's mass per area, 0.15 rho R here, moves
    // under the pressure until its waves spread the load round the ring), so the rigid limit
    // sets in once c2s t reaches a few R and then falls quickly
    let end = 2.0;
    let shell = |s: f64| ShellStriker {
        thickness: 0.05,
        material: StrikerMaterial {
            c1_ratio: s,
            c2_ratio: 0.55 * s,
            density_ratio: 3.0,
        },
    };
    let mass = shell(1.0).mass_ratio();
    let rigid = history(free_parabola(nu, mass, v0, end, dx), Striker::Rigid);
    let gaps: Vec<f64> = [16.0, 64.0, 256.0]
        .iter()
        .map(|&s| {
            let rows = history(
                free_parabola(nu, mass, v0, end, dx),
                Striker::Shell(shell(s)),
            );
            gap(&rows, &rigid)
        })
        .collect();
    for w in gaps.windows(2) {
        assert!(w[0] / w[1] > 2.5, "shell gaps {gaps:?}");
    }
    assert!(gaps[2] < 0.03, "shell gaps {gaps:?}");
}

fn reference() -> serde_json::Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/reference/shell_reference.json"
    );
    serde_json::from_str(&std::fs::read_to_string(path).expect("reference file")).unwrap()
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_str().expect("a decimal string").parse().unwrap()
}

/// A ring in the reference's units: the shell's own c1 = 1 and density 1 (the half-plane's
/// speed ratio m_hp only sets the units, so density_ratio = m_hp^2 gives rho_s = 1).
fn ring(h: f64, m: f64) -> Ring {
    let m_hp = 0.5;
    Ring::new(
        &ShellStriker {
            thickness: h,
            material: StrikerMaterial {
                c1_ratio: 1.0,
                c2_ratio: m,
                density_ratio: m_hp * m_hp,
            },
        },
        m_hp,
    )
    .unwrap()
}

/// The shell's natural frequencies against the independent derivation (to 1e-12), and the
/// classical ring formulas: the breathing mode omega^2 = E'/(rho R^2) exactly, the lowest
/// flexural modes within the Timoshenko correction of the inextensional formula
/// omega^2 = (E' h^2/(12 rho R^4)) n^2 (n^2 - 1)^2/(n^2 + 1), which shrinks with h/R.
#[test]
fn shell_frequencies_match_the_reference_and_the_ring_formulas() {
    let r = reference();
    let mut checked = 0;
    for case in r["frequencies"].as_object().unwrap().values() {
        let (h, m) = (num(&case["h_over_R"]), num(&case["m"]));
        let ring = ring(h, m);
        for (n, list) in case["by_n"].as_object().unwrap() {
            let n: usize = n.parse().unwrap();
            let want: Vec<f64> = list
                .as_array()
                .unwrap()
                .iter()
                .map(num)
                .filter(|w| *w > 0.0)
                .collect();
            let got: Vec<f64> = ring
                .harmonic(n)
                .unwrap()
                .modes
                .iter()
                .map(|x| x.0)
                .collect();
            // n = 0: the breathing mode alone carries a radial load (the torsional pair, a
            // rigid rotation and a thickness-shear mode, decouples)
            let want = if n == 0 { vec![want[0]] } else { want };
            assert_eq!(got.len(), want.len(), "h = {h}, n = {n}");
            for (g, w) in got.iter().zip(&want) {
                assert!((g / w - 1.0).abs() < 1e-12, "h = {h}, n = {n}: {g} vs {w}");
                checked += 1;
            }
        }
        let e = 4.0 * m * m * (1.0 - m * m);
        let breathing = ring.harmonic(0).unwrap().modes[0].0;
        assert!((breathing / e.sqrt() - 1.0).abs() < 1e-14);
    }
    assert!(checked > 60);
    // inextensional limit: the Timoshenko lowest mode over the classical one tends to 1 as
    // h/R -> 0, the deviation shrinking like (h/R)^2
    let m = 0.5;
    let e = 4.0 * m * m * (1.0 - m * m);
    let dev = |h: f64, n: usize| {
        let nf = n as f64;
        let classical =
            (e * h * h / 12.0 * nf * nf * (nf * nf - 1.0).powi(2) / (nf * nf + 1.0)).sqrt();
        ring(h, m).harmonic(n).unwrap().modes[0].0 / classical - 1.0
    };
    for n in 2..=5 {
        let (d1, d2) = (dev(0.04, n), dev(0.02, n));
        assert!(d1.abs() < 0.02, "n = {n}: {d1}");
        let ratio = d1 / d2;
        assert!(ratio > 3.0 && ratio < 5.0, "n = {n}: {d1} {d2}");
    }
}

/// The response of one harmonic to a step load cos(n theta) H(t) by the library's modes
/// against the reference's direct numerical integration of the modal ODEs, and its static
/// value.
#[test]
fn shell_step_response_matches_the_ode_integration() {
    let r = reference();
    let s = &r["step_response"];
    let (h, m) = (num(&s["h_over_R"]), num(&s["m"]));
    let ring = ring(h, m);
    let mut checked = 0;
    for (n, entry) in s["by_n"].as_object().unwrap() {
        let n: usize = n.parse().unwrap();
        let har = ring.harmonic(n).unwrap();
        let inward = |t: f64| -> f64 {
            har.c_n
                * har
                    .modes
                    .iter()
                    .map(|(w, p)| p * (1.0 - (w * t).cos()) / (w * w))
                    .sum::<f64>()
        };
        for (t, want) in entry["minus_w0"].as_object().unwrap() {
            let (t, want): (f64, f64) = (t.parse().unwrap(), num(want));
            let got = inward(t);
            assert!(
                (got - want).abs() < 1e-10 * want.abs(),
                "n = {n}, t = {t}: {got} vs {want}"
            );
            checked += 1;
        }
        let stat = num(&entry["static_minus_w0"]);
        let got = har.c_n * har.modes.iter().map(|(w, p)| p / (w * w)).sum::<f64>();
        assert!((got / stat - 1.0).abs() < 1e-10, "n = {n}: {got} vs {stat}");
    }
    assert!(checked >= 16);
}

/// Energy: the striker's lost kinetic energy equals the work on the half-plane plus the
/// energy taken up by the striker; for the shell, that energy (work of the pressure on its
/// surface through the coefficient tables) equals its strain plus vibration kinetic energy
/// from an exact modal recursion driven by the same pressures.
#[test]
fn energy_balance_with_deformable_strikers() {
    let nu = 0.3;
    let (v0, end, dx) = (0.01, 4.0, 0.01);
    let shell = ShellStriker {
        thickness: 0.05,
        material: StrikerMaterial {
            c1_ratio: 2.0,
            c2_ratio: 1.1,
            density_ratio: 3.0,
        },
    };
    let mass = shell.mass_ratio();
    let case = free_parabola(nu, mass, v0, end, dx).with_striker(Striker::Shell(shell));
    let sol = case.solve(|_| {}).unwrap();
    let (rows, _) = sol.history();
    let ke0 = 0.5 * mass * v0 * v0;
    let modal = sol.striker_energies().unwrap().unwrap();
    let run = &sol.runs[0];
    let mut worst: f64 = 0.0;
    let mut taken: f64 = 0.0;
    for r in &rows {
        let es = r.striker_energy.unwrap().value;
        let e = modal[(r.t / run.dt).round() as usize - 1];
        let (u, k) = (e.strain, e.kinetic);
        // two routes to the shell's energy
        assert!(
            (es - (u + k)).abs() < 1e-9 * ke0,
            "t = {}: work {es}, modal {}",
            r.t,
            u + k
        );
        let gap = (ke0 - r.kinetic.unwrap().value - r.work.value - es).abs() / ke0;
        worst = worst.max(gap);
        taken = taken.max(es / ke0);
    }
    assert!(worst < 3e-3, "energy gap {worst}");
    // the shell does take a visible share
    assert!(taken > 0.01, "largest share of the shell {taken}");
    // the elastic striker, within its model's time
    let mat = StrikerMaterial {
        c1_ratio: 1.5,
        c2_ratio: 0.8,
        density_ratio: 1.0,
    };
    let case = free_parabola(nu, 10.0, v0, 1.3, dx).with_striker(Striker::Elastic(mat));
    let (rows, _) = case.solve(|_| {}).unwrap().history();
    let ke0 = 0.5 * 10.0 * v0 * v0;
    for r in &rows {
        let es = r.striker_energy.unwrap().value;
        let gap = (ke0 - r.kinetic.unwrap().value - r.work.value - es).abs() / ke0;
        assert!(gap < 3e-3, "t = {}: gap {gap}", r.t);
    }
}

/// Bad input names the parameter: the elastic model past its validity, a shell with a wrong
/// mass ratio or a profile it cannot have, inadmissible materials.
#[test]
fn deformable_striker_inputs_are_checked() {
    let named = |c: ImpactCase, what: &str| match c.solve(|_| {}) {
        Err(ImpactError::InvalidParameter(p)) => {
            let name = p.name;
            assert!(name.contains(what), "{name} does not name {what}")
        }
        other => panic!("{what}: expected a refusal, got {:?}", other.map(|_| ())),
    };
    let mat = StrikerMaterial {
        c1_ratio: 1.5,
        c2_ratio: 0.8,
        density_ratio: 1.0,
    };
    named(
        free_parabola(0.3, 10.0, 0.01, 1.5, 0.01).with_striker(Striker::Elastic(mat)),
        "end time",
    );
    // at the validity end itself the march stops on the last step before it, not the nearest
    let valid = Striker::Elastic(mat).validity_end();
    let sol = free_parabola(0.3, 10.0, 0.01, valid, 0.01)
        .with_striker(Striker::Elastic(mat))
        .solve(|_| {})
        .unwrap();
    let last = sol.runs[0].steps.last().unwrap().t;
    assert!(
        last <= valid && last > valid - 0.02,
        "last step {last}, valid to {valid}"
    );
    let bad = StrikerMaterial {
        c2_ratio: 1.4,
        ..mat
    };
    named(
        free_parabola(0.3, 10.0, 0.01, 1.0, 0.01).with_striker(Striker::Elastic(bad)),
        "striker c2",
    );
    let shell = ShellStriker {
        thickness: 0.05,
        material: mat,
    };
    named(
        free_parabola(0.3, 10.0, 0.01, 1.0, 0.01).with_striker(Striker::Shell(shell)),
        "mass ratio",
    );
    let mut c =
        free_parabola(0.3, shell.mass_ratio(), 0.01, 1.0, 0.01).with_striker(Striker::Shell(shell));
    c.profile = Profile::Wedge { theta_deg: 80.0 };
    named(c, "profile");
    named(
        free_parabola(0.3, 1.0, 0.01, 1.0, 0.01).with_striker(Striker::Shell(ShellStriker {
            thickness: 0.5,
            material: mat,
        })),
        "thickness",
    );
}
