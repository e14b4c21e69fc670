//! The whole impact to separation (`docs/impact.md`, section 9): Signorini's unilateral
//! conditions at every step (no pull, no interpenetration), the striker's separation and free
//! flight, its rebound with estimates, the energy audit, and the shared time levels of driven
//! runs.

use crate::common;

use common::m2;
use impact::march::StepState;
use impact::{Drive, EdgeLaw, ImpactCase, ImpactError, Profile, SolvedImpact};

/// The mean of the profile over cell i of width dx (cell 0 over its right half), by the
/// same 3-point Gauss-Legendre rule as the march's conditions.
fn cell_mean(profile: &Profile, dx: f64, i: usize) -> Option<f64> {
    let (lo, hi) = if i == 0 {
        (0.0, 0.5 * dx)
    } else {
        (dx * i as f64 - 0.5 * dx, dx * i as f64 + 0.5 * dx)
    };
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    let u = (0.6f64).sqrt();
    let mut s = 0.0;
    for (x, w) in [(-u, 5.0 / 9.0), (0.0, 8.0 / 9.0), (u, 5.0 / 9.0)] {
        s += w * profile.height::<f64>(mid + half * x)?;
    }
    Some(0.5 * s)
}

/// Checks Signorini's conditions on every step of every level: no pressure below zero, and
/// no cell beyond the contact (within the displacements the step kept) whose mean gap
/// w - (h - mean f) is below -`tol` times the largest penetration. Returns the most negative
/// pressure over the largest and the most negative relative gap.
fn unilateral(sol: &SolvedImpact, tol: f64) -> (f64, f64) {
    let mut worst = (0.0f64, 0.0f64);
    for run in &sol.runs {
        let dx = run.dx;
        let hmax = run.steps.iter().map(|s| s.h.abs()).fold(1e-300, f64::max);
        let pmax = run
            .steps
            .iter()
            .flat_map(|s| s.pressure.iter().copied())
            .fold(1e-300, f64::max);
        for s in &run.steps {
            let pmin = s.pressure.iter().copied().fold(0.0, f64::min);
            worst.0 = worst.0.min(pmin / pmax);
            assert!(
                pmin >= 0.0,
                "a pulling cell at t = {}: {pmin} (dx = {dx})",
                s.t
            );
            // the cells beyond the contact (the edge cell of a free edge carries the local
            // model's gap, so from the next cell on)
            let first = if s.pressure.is_empty() { 0 } else { s.k + 2 };
            for i in first..s.w.len() {
                let Some(f) = cell_mean(&sol.case.profile, dx, i) else {
                    continue;
                };
                let w = s.w[i] + s.ws.get(i).copied().unwrap_or(0.0);
                let gap = (w - (s.h - f)) / hmax;
                worst.1 = worst.1.min(gap);
                assert!(
                    gap >= -tol,
                    "interpenetration at t = {}, cell {i}: gap {gap:e} of the largest h (dx = {dx}, contact to cell {})",
                    s.t,
                    s.k
                );
            }
        }
    }
    worst
}

/// After the last separation the striker flies free: its speed is constant and h grows
/// linearly, on every level.
fn flies_free(sol: &SolvedImpact) {
    for run in &sol.runs {
        let sep = *run.separations.last().expect("a separation");
        let after: Vec<&StepState> = run.steps.iter().filter(|s| s.t > sep + run.dt).collect();
        assert!(after.len() >= 2, "too few steps after the separation");
        let v = after[0].v;
        for w in after.windows(2) {
            assert!(w[1].pressure.is_empty() && w[1].force == 0.0);
            assert_eq!(w[1].v, v, "the speed changes in free flight");
            let dh = w[1].h - w[0].h - v * (w[1].t - w[0].t);
            assert!(
                dh.abs() <= 1e-12 * w[1].h.abs().max(1e-3),
                "h not linear: {dh:e}"
            );
        }
        assert!(v < 0.0, "the striker moves away: {v}");
    }
}

/// The README's reference case run past its rebound: it separates, never pulls, flies free,
/// and its energy closes with the restitution reported.
#[test]
fn reference_case_separates_and_flies_free() {
    let mut case = ImpactCase::reference(EdgeLaw::Signorini);
    case.end = 40.0;
    case.dx = 0.005;
    let sol = case.solve(|_| {}).unwrap();
    let (pmin, gmin) = unilateral(&sol, 1e-6);
    flies_free(&sol);
    let (rows, _) = sol.history();
    let peak = rows.iter().map(|r| r.force.value).fold(0.0, f64::max);
    for r in &rows {
        assert!(
            r.force.value >= -1e-12 * peak,
            "force {} at {}",
            r.force.value,
            r.t
        );
    }
    let worst = rows
        .iter()
        .map(|r| r.energy_defect.unwrap().value.abs())
        .fold(0.0, f64::max);
    let rb = sol.rebound().unwrap();
    let e = rb.restitution;
    // the energy left: the striker's (1/2) m0 V^2 = e^2 of the impact energy, the rest in
    // the half-plane
    let closure = e.value * e.value + rb.energy_to_half_plane.value - 1.0;
    eprintln!(
        "separation {:.4} +- {:?}, restitution {:.6} +- {:?}, to the half-plane {:.6}, closure {closure:.2e}, largest |defect| {worst:.2e}, least p/pmax {pmin:.1e}, least gap/hmax {gmin:.1e}",
        rb.separation.value, rb.separation.error, e.value, e.error, rb.energy_to_half_plane.value
    );
    assert!(worst < 1e-3, "energy defect {worst:e}");
    assert!(closure.abs() < 1e-3, "energy closure {closure:e}");
    assert!(e.value > 0.0 && e.value < 1.0);
    let err = e.error.expect("an estimate of the restitution");
    assert!(err > 0.0 && err < 5e-4, "restitution estimate {err:e}");
    assert!(rb.separation.error.unwrap() <= 0.05);
    assert_eq!(rb.reimpacts, 0);
}

/// The restitution and the separation of the default grid against a grid four times finer
/// (R/800, one level): within the stated estimates, and within the accuracy asked of the
/// default grid (5e-4 and 0.05 R/c1).
#[test]
#[ignore = "about a minute: the R/800 run to the separation (run with --ignored)"]
fn rebound_against_a_finer_grid() {
    let mut case = ImpactCase::reference(EdgeLaw::Signorini);
    case.end = 30.0;
    case.stop = impact::Stop::AtSeparation;
    case.dx = 0.005;
    let coarse = case.solve(|_| {}).unwrap().rebound().unwrap();
    case.dx = 0.00125;
    case.levels = 1;
    let fine = case.solve(|_| {}).unwrap().rebound().unwrap();
    let de = (coarse.restitution.value - fine.restitution.value).abs();
    let ds = (coarse.separation.value - fine.separation.value).abs();
    eprintln!(
        "restitution {:.6} (R/200) against {:.6} (R/800): {de:.1e}, stated {:.1e}; separation {:.4} against {:.4}: {ds:.3}, stated {:.3}",
        coarse.restitution.value,
        fine.restitution.value,
        coarse.restitution.error.unwrap(),
        coarse.separation.value,
        fine.separation.value,
        coarse.separation.error.unwrap()
    );
    assert!(de < 5e-4 && de <= coarse.restitution.error.unwrap());
    assert!(ds < 0.05 && ds <= coarse.separation.error.unwrap());
}

/// To the separation: the run ends shortly after the striker leaves, at the same rebound as
/// a run to a fixed later time.
#[test]
fn a_run_to_the_separation_ends_there() {
    let mut case = common::free_parabola(0.3, 1.0, 0.01, 50.0, 0.01);
    case.stop = impact::Stop::AtSeparation;
    let sol = case.solve(|_| {}).unwrap();
    let rb = sol.rebound().unwrap();
    let last = sol.runs[0].steps.last().unwrap().t;
    assert!(
        last > rb.separation.value && last < rb.separation.value + 0.2,
        "{last}"
    );
    case.stop = impact::Stop::AtEnd;
    // twice as long: a whole number of the same coarsest steps, so the same time levels
    case.end = 2.0 * last;
    let long = case.solve(|_| {}).unwrap().rebound().unwrap();
    assert_eq!(long.separation.value, rb.separation.value);
    assert!((long.restitution.value - rb.restitution.value).abs() < 1e-14);
}

/// The light strikers that used to be held by a pull: a flat punch whose deceleration time
/// is shorter than the default step is refused, and on a step that resolves it neither it
/// nor a light parabola pulls or gains energy (beyond the defect's stated error: with the
/// start on finer grids the parabola's defect is about 6e-5, against 1e-3 stated, where one
/// grid throughout gives -2.2e-3).
#[test]
fn light_strikers_neither_pull_nor_gain_energy() {
    let flat = |dx: f64, kappa: f64| {
        let mut c = ImpactCase::new(
            0.3,
            Profile::Flat { half_width: 1.0 },
            Drive::Free {
                mass_ratio: 0.00372818,
                v0_over_c1: 0.1,
            },
            EdgeLaw::Signorini,
            1.0,
        );
        c.dx = dx;
        c.kappa = kappa;
        c
    };
    match flat(0.005, 2.0).solve(|_| {}) {
        Err(ImpactError::Grid { name, reason }) => {
            assert_eq!(name, "dx");
            assert!(reason.contains("deceleration time"), "{reason}");
        }
        other => panic!("the unresolved light punch is not refused: {other:?}"),
    }
    let mut light_parabola = common::free_parabola(0.3, 0.1, 0.01, 4.0, 0.005);
    light_parabola.levels = 2;
    for (name, case) in [
        ("flat punch", flat(0.0025, 0.5)),
        ("parabola", light_parabola),
    ] {
        let sol = case.solve(|_| {}).unwrap();
        unilateral(&sol, 1e-6);
        let (rows, _) = sol.history();
        // the largest defect and its stated error: a gain, if any, is not resolved
        let (gain, stated) = rows
            .iter()
            .map(|r| r.energy_defect.unwrap())
            .map(|d| (d.value, d.error.unwrap_or(0.0)))
            .fold((f64::MIN, 0.0), |a, b| if b.0 > a.0 { b } else { a });
        let rb = sol.rebound().unwrap();
        eprintln!(
            "{name}: restitution {:.4} +- {:?}, largest defect {gain:.2e}",
            rb.restitution.value, rb.restitution.error
        );
        assert!(
            gain < 1e-6_f64.max(stated),
            "{name} gains energy: {gain:e} (stated error {stated:e})"
        );
        flies_free(&sol);
    }
}

/// A small deterministic generator for the property test.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.next()).exp()
    }
}

/// Random free impacts (profiles, mass ratios 1e-3 to 1e3, V0/c1 1e-4 to 0.5, Poisson's
/// ratios) under Signorini's law: no pull and no interpenetration at any step, the reported
/// force never below zero, the energy defect within its estimate, and no contact while the
/// striker is above the undisturbed surface (a striker moving away separates).
#[test]
fn random_free_impacts_keep_the_unilateral_conditions() {
    let mut rng = Lcg(20261127);
    let mut solved = 0;
    let mut separated = 0;
    for case_no in 0..14 {
        let profile = match case_no % 5 {
            0 => Profile::Parabola { radius: 1.0 },
            1 => Profile::Circle { radius: 1.0 },
            2 => Profile::Power {
                a: 0.5,
                k: 1.5 + rng.next(),
            },
            3 => Profile::Wedge {
                theta_deg: 60.0 + 29.0 * rng.next(),
            },
            _ => Profile::Flat { half_width: 0.2 },
        };
        let mass_ratio = rng.log_uniform(1e-3, 1e3);
        let v0 = rng.log_uniform(1e-4, 0.5);
        let nu = -0.5 + 0.95 * rng.next();
        let mut case = ImpactCase::new(
            nu,
            profile.clone(),
            Drive::Free {
                mass_ratio,
                v0_over_c1: v0,
            },
            EdgeLaw::Signorini,
            3.0,
        );
        case.dx = 0.02;
        case.levels = 2;
        let label = format!(
            "{} m {mass_ratio:.3e} v0 {v0:.3e} nu {nu:.3}",
            profile.label()
        );
        let sol = match case.solve(|_| {}) {
            Ok(s) => s,
            Err(ImpactError::Grid { reason, .. }) if reason.contains("deceleration") => {
                eprintln!("{label}: refused ({reason})");
                continue;
            }
            Err(e) => panic!("{label}: {e}"),
        };
        solved += 1;
        unilateral(&sol, 1e-6);
        for run in &sol.runs {
            for s in &run.steps {
                if s.h < 0.0 && !matches!(profile, Profile::Flat { .. }) {
                    assert!(
                        s.pressure.is_empty(),
                        "{label}: contact above the surface at {}",
                        s.t
                    );
                }
            }
        }
        let (rows, _) = sol.history();
        for r in &rows {
            assert!(
                r.force.value >= 0.0,
                "{label}: force {} at {}",
                r.force.value,
                r.t
            );
            let d = r.energy_defect.unwrap();
            let err = d.error.unwrap();
            assert!(
                d.value.abs() <= err + 1e-12,
                "{label}: energy defect {:e} beyond its estimate {err:e} at {}",
                d.value,
                r.t
            );
        }
        if sol.rebound().is_ok() {
            separated += 1;
        }
        eprintln!(
            "{label}: largest force {:.3e}, separated {}",
            rows.iter().map(|r| r.force.value).fold(0.0, f64::max) / m2(nu),
            sol.rebound().is_ok()
        );
    }
    assert!(solved >= 10, "only {solved} of 14 cases solved");
    assert!(separated >= 3, "only {separated} cases separated");
}

/// Driven runs of every profile: h = V t to rounding at every reported time, the last at the
/// requested end exactly (the levels share their time levels, also where the flat punch's
/// cells are fitted to its width).
#[test]
fn driven_runs_stand_at_their_times() {
    let table: Vec<(f64, f64)> = (0..=200)
        .map(|i| {
            let x = i as f64 * 0.01;
            (x, x * x / 2.0)
        })
        .collect();
    for profile in [
        Profile::Parabola { radius: 1.0 },
        Profile::Circle { radius: 1.0 },
        Profile::Power { a: 0.5, k: 1.5 },
        Profile::Wedge { theta_deg: 80.0 },
        Profile::Flat { half_width: 0.37 },
        Profile::Table(std::sync::Arc::new(table.clone())),
    ] {
        let v = 0.01;
        let end = 1.2345;
        let mut case = ImpactCase::new(
            0.3,
            profile.clone(),
            Drive::Speed(v),
            EdgeLaw::Signorini,
            end,
        );
        case.dx = 0.01;
        let sol = case.solve(|_| {}).unwrap();
        let (rows, _) = sol.history();
        assert_eq!(
            rows.last().unwrap().t,
            end,
            "{}: the last time",
            profile.label()
        );
        for r in &rows {
            let rel = (r.h.value - v * r.t).abs() / (v * r.t);
            assert!(
                rel <= 1e-14,
                "{}: h {} against V t {} at {}",
                profile.label(),
                r.h.value,
                v * r.t,
                r.t
            );
        }
        // every level has a value at every reported time, so every row has its estimate
        assert!(rows
            .iter()
            .all(|r| r.h.error.is_some() && r.force.error.is_some()));
    }
}

/// The energy defect of the two laws under refinement (`docs/impact.md`, section 9): the
/// kinematic law's converges to a positive value (the prescribed edge's energy flux), flagged
/// by the audit's bound; Signorini's to zero.
#[test]
fn kinematic_energy_defect_converges_away_from_zero() {
    let defect = |law: EdgeLaw, dx: f64| {
        let mut case = ImpactCase::reference(law);
        case.end = 2.0;
        case.dx = dx;
        case.levels = 1;
        // refined at every time: the start on the coarser run's schedule
        case.start_grid = Some(0.01);
        let (rows, _) = case.solve(|_| {}).unwrap().history();
        rows.last().unwrap().energy_defect.unwrap().value
    };
    let k: Vec<f64> = [0.01, 0.005]
        .iter()
        .map(|&dx| defect(EdgeLaw::Kinematic, dx))
        .collect();
    let s: Vec<f64> = [0.01, 0.005]
        .iter()
        .map(|&dx| defect(EdgeLaw::Signorini, dx))
        .collect();
    eprintln!("kinematic {k:?}, signorini {s:?}");
    assert!(k[0] > 0.05 && k[1] > 0.05, "kinematic defects {k:?}");
    assert!((k[1] - k[0]).abs() < 0.1 * k[1], "kinematic defects {k:?}");
    assert!(
        s[1].abs() < 1e-3 && s[1].abs() < s[0].abs(),
        "signorini defects {s:?}"
    );
}
