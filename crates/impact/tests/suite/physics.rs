//! Physics checks of the rigid-striker impact engine, each against an independent quantity:
//! the exact plane-wave pressure of a driven flat punch, the one-dimensional acoustic limit at
//! first contact, the energy balance through the kernels, the 2-D Hertz relation in the
//! quasi-static limit, convergence under refinement with the stated error estimates.

use crate::common;

use common::{free_parabola, m2};
use impact::{Drive, EdgeLaw, ImpactCase, ImpactError, Profile};
use num_complex::Complex64;

/// A driven flat punch: wherever the P waves of both edges have not arrived, the pressure is
/// exactly rho c1 V (a plane wave), in every step.
#[test]
fn driven_flat_punch_plane_wave_region_is_exact() {
    let nu = 0.3;
    let v = 0.01;
    let mut case = ImpactCase::new(
        nu,
        Profile::Flat { half_width: 1.0 },
        Drive::Speed(v),
        EdgeLaw::Signorini,
        1.4,
    );
    case.dx = 0.0125;
    case.levels = 1;
    let sol = case.solve(|_| {}).unwrap();
    let run = &sol.runs[0];
    let a = 1.0;
    let mut checked = 0;
    for st in &run.steps {
        for (j, p) in st.pressure.iter().enumerate() {
            let x = j as f64 * run.dx;
            // the edge's cell acts from a - dx on (margin: the edge pressure is large, and the
            // solve's rounding scales with it)
            if a - x > st.t + 12.0 * run.dx {
                let rel = p * m2(nu) / v - 1.0;
                assert!(
                    rel.abs() < 1e-10,
                    "t = {}, x = {x}: p/(rho c1 V) - 1 = {rel:e}",
                    st.t
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 200, "only {checked} cells checked");
    // and the edges do change the pressure once their waves arrive
    let last = run.steps.last().unwrap();
    assert!((last.pressure[0] * m2(nu) / v - 1.0).abs() > 1e-4);
}

/// Long marches stay stable: a driven flat punch (fixed contact, so nothing but the march
/// itself can grow) over 800 steps, and a free cylinder through its rebound on a fine grid
/// (1600 steps). Collocating at the cell centres instead of on the cell means made a mode
/// about 2.4 cells long grow by about 3 % a step: the flat punch's pressure alternated in sign
/// after about 200 steps and the cylinder's force doubled after about 1200.
#[test]
fn long_marches_have_no_growing_modes() {
    let (nu, v) = (0.25, 0.01);
    let mut case = ImpactCase::new(
        nu,
        Profile::Flat { half_width: 0.1 },
        Drive::Speed(v),
        EdgeLaw::Kinematic,
        8.0,
    );
    case.dx = 0.005;
    case.levels = 1;
    let sol = case.solve(|_| {}).unwrap();
    let steps = &sol.runs[0].steps;
    assert!(steps.len() >= 800);
    for w in steps[steps.len() - 200..].windows(3) {
        let p: Vec<f64> = w.iter().map(|s| s.pressure[0]).collect();
        assert!(p[2] > 0.0 && p[2] > p[0], "t = {}: p(0) = {}", w[2].t, p[2]);
        let saw = (p[2] - 2.0 * p[1] + p[0]).abs() / p[2];
        assert!(saw < 1e-5, "t = {}: second difference {saw:e}", w[2].t);
    }
    // the free cylinder on a grid twice as fine as the reference runs' finest
    let mut case = free_parabola(nu, 10.0, 0.01, 8.0, 0.0025);
    case.levels = 1;
    let sol = case.solve(|_| {}).unwrap();
    let steps = &sol.runs[0].steps;
    let peak = steps.iter().map(|s| s.force).fold(0.0, f64::max);
    let late = steps.last().unwrap();
    assert!(
        late.force < peak && late.force > 0.8 * peak,
        "{} {peak}",
        late.force
    );
    for w in steps[steps.len() / 2..].windows(3) {
        let f: Vec<f64> = w.iter().map(|s| s.force).collect();
        let saw = (f[2] - 2.0 * f[1] + f[0]).abs() / f[2];
        assert!(
            saw < 1e-2,
            "t = {}: second difference of the force {saw:e}",
            w[2].t
        );
    }
}

/// The supersonic start: the contact pressure at the centre tends to the 1-D acoustic value
/// rho c1 dh/dt, with a correction that vanishes linearly as t -> 0.
#[test]
fn supersonic_start_tends_to_the_acoustic_pressure() {
    let nu = 0.25;
    let v0 = 0.1;
    let mut case = free_parabola(nu, 10.0, v0, 0.04, 0.0005);
    case.levels = 1;
    let sol = case.solve(|_| {}).unwrap();
    let run = &sol.runs[0];
    let ratio = |n: usize| {
        let st = &run.steps[n - 1];
        // the centre's pressure over rho c1 times the speed at mid-step
        let prev_v = if n > 1 { run.steps[n - 2].v } else { v0 };
        st.pressure[0] * m2(nu) / (0.5 * (st.v + prev_v))
    };
    let d = |n: usize| ratio(n) - 1.0;
    // well inside the supersonic stage (b > c1 t + a few cells)
    let (n1, n2) = (10, 20);
    let (t1, t2) = (run.steps[n1 - 1].t, run.steps[n2 - 1].t);
    assert!(run.steps[n2 - 1].b > t2 + 4.0 * run.dx);
    assert!(
        d(n1).abs() < 0.01,
        "p/(rho c1 v) - 1 = {} at t = {t1}",
        d(n1)
    );
    // linear in t: the deviation doubles with t (to 20 percent)
    let slope_ratio = (d(n2) / t2) / (d(n1) / t1);
    assert!(
        (slope_ratio - 1.0).abs() < 0.2,
        "deviations {} at t = {t1}, {} at t = {t2}",
        d(n1),
        d(n2)
    );
}

/// Energy: the striker's lost kinetic energy equals the work of the contact pressure on the
/// surface computed through the kernels, to the grid's accuracy, better on a finer grid.
#[test]
fn energy_balance_through_the_kernels() {
    let gaps: Vec<f64> = [0.02, 0.01]
        .iter()
        .map(|&dx| {
            let mut case = free_parabola(0.3, 10.0, 0.01, 6.0, dx);
            case.levels = 1;
            // refined at every time: the start on the coarser run's schedule
            case.start_grid = Some(0.02);
            let sol = case.solve(|_| {}).unwrap();
            let (rows, _) = sol.history();
            let ke0 = 0.5 * 10.0 * 0.01f64.powi(2);
            rows.iter()
                .map(|r| (ke0 - r.kinetic.unwrap().value - r.work.value).abs() / ke0)
                .fold(0.0, f64::max)
        })
        .collect();
    assert!(gaps[1] < 2e-3, "energy gaps {gaps:?}");
    assert!(gaps[1] < gaps[0], "energy gaps {gaps:?}");
}

/// Quasi-static limit: near the peak force (db/dt ~ 0) the force and the contact half-width
/// follow the 2-D Hertz relation R = pi E* b^2/(4 R_c), E* = E/(1 - nu^2) = 2 mu/(1 - nu); the
/// deviation shrinks with the impact speed.
#[test]
fn quasi_static_limit_is_hertz() {
    let nu = 0.3;
    let dev: Vec<f64> = [(0.01, 10.0, 10.0), (0.003, 10.0, 30.0)]
        .iter()
        .map(|&(v0, mass, end)| {
            let case = {
                let mut c = free_parabola(nu, mass, v0, end, 0.004);
                c.kappa = 2.0;
                c.levels = 2;
                c
            };
            let sol = case.solve(|_| {}).unwrap();
            let (rows, _) = sol.history();
            let peak = rows
                .iter()
                .max_by(|a, b| a.force.value.total_cmp(&b.force.value))
                .unwrap();
            // force over rho c1^2 R; Hertz: pi E* b^2/(4 R) over rho c1^2 R = m^2 pi b^2/(2 (1 - nu))
            let hertz = m2(nu) * std::f64::consts::PI * peak.b.value.powi(2) / (2.0 * (1.0 - nu));
            peak.force.value / hertz - 1.0
        })
        .collect();
    assert!(dev[0].abs() < 0.03, "deviations from Hertz {dev:?}");
    assert!(
        dev[1].abs() < dev[0].abs() + 0.005,
        "deviations from Hertz {dev:?}"
    );
}

/// Hertz's quasi-static limit at 1e-4 of the peaks, at the default grid (R/200, three levels,
/// the start on finer grids; `docs/impact.md`, section 6): a heavy parabola, m0/(rho R^2) =
/// 1000, at V0/c1 = 1e-3. Around the largest force the edge stands nearly still (|db/dt| below
/// 1e-4 c1, c1 t/R from about 86 to 100) and the contact is static to O((b/(c1 T))^2), about
/// 1e-6 (T ~ 200 R/c1 the contact's duration), so b and F satisfy F = pi E* b^2/(4 R) there:
/// b within 1e-4 of its peak of Hertz's half-width for the reported force over those rows
/// (measured 5.4e-5), each within its stated error, and the largest force within 1e-4 of
/// Hertz's force for its b (measured 7.7e-5; the force's relation doubles b's error), and
/// the cell pressures there Hertz's cell means for the profile's own force within 1e-4 of the
/// central pressure over the cells more than six cells inside the edge (measured 6.8e-5; 4e-6
/// in the middle, 1.8e-4 four cells from the edge). While the edge still advances (1.8e-3 c1
/// at c1 t/R = 20) b is off by up to 1.1e-4 of its peak, the crossings' phase.
#[test]
fn heavy_slow_parabola_is_hertz_at_its_peak() {
    let nu = 0.25;
    let case = free_parabola(nu, 1000.0, 1e-3, 100.0, 0.005);
    let sol = case.solve(|_| {}).unwrap();
    let (rows, _) = sol.history();
    let e_star = 2.0 * m2(nu) / (1.0 - nu); // E*/(rho c1^2)
    let hertz_force = |b: f64| std::f64::consts::PI * e_star * b * b / 4.0;
    let hertz_b = |f: f64| (4.0 * f / (std::f64::consts::PI * e_star)).sqrt();
    let b_peak = rows.iter().map(|r| r.b.value).fold(0.0, f64::max);
    let f_peak = rows.iter().map(|r| r.force.value).fold(0.0, f64::max);
    let still: Vec<_> = rows.iter().filter(|r| r.bdot.abs() < 1e-4).collect();
    assert!(
        still.iter().any(|r| r.force.value == f_peak),
        "the largest force is not where the edge stands still"
    );
    assert!(still.len() > 100, "{} rows with a still edge", still.len());
    let mut worst_b: f64 = 0.0;
    for r in &still {
        let (b, f) = (r.b.value, r.force.value);
        let db = b - hertz_b(f);
        assert!(
            db.abs() <= r.b.error.unwrap(),
            "c1 t/R = {}: b - Hertz {db:e} beyond its stated error",
            r.t
        );
        worst_b = worst_b.max(db.abs() / b_peak);
    }
    let peak = still.iter().find(|r| r.force.value == f_peak).unwrap();
    let df = (f_peak - hertz_force(peak.b.value)) / f_peak;
    assert!(
        worst_b < 1e-4 && df.abs() < 1e-4,
        "b off Hertz's by {worst_b:e} of its peak; F at its peak by {df:e}"
    );
    // the pressure at the largest force: Hertz's (E*/(2R)) (b_H^2 - x^2)^(1/2) for the
    // profile's own force, its means over the cells more than six cells inside b_H
    let prof = sol.pressure_profile(peak.t).unwrap();
    let dx = prof.x[1] - prof.x[0];
    let force = dx * (prof.p[0] + 2.0 * prof.p[1..].iter().sum::<f64>());
    let b_h = hertz_b(force);
    let p0 = e_star * b_h / 2.0;
    // Int_0^x (b^2 - s^2)^(1/2) ds
    let area = |x: f64| 0.5 * (x * (b_h * b_h - x * x).sqrt() + b_h * b_h * (x / b_h).asin());
    let mut worst_p: f64 = 0.0;
    for (j, &p) in prof.p.iter().enumerate() {
        let (lo, hi) = (
            if j == 0 { 0.0 } else { (j as f64 - 0.5) * dx },
            (j as f64 + 0.5) * dx,
        );
        if b_h - prof.x[j] < 6.0 * dx {
            break;
        }
        let mean = e_star / 2.0 * (area(hi) - area(lo)) / (hi - lo);
        worst_p = worst_p.max((p - mean).abs() / p0);
    }
    assert!(
        worst_p < 1e-4,
        "the pressure off Hertz's by {worst_p:e} of its peak"
    );
}

/// The free edge's position: a parabola driven slowly (V = 1e-3 c1, the edge below 0.01 c_R)
/// is quasi-static, so its contact half-width follows Hertz's relation with its own force,
/// b = (4 R F/(pi E*))^(1/2), to the dynamic correction (about 1e-4). The shape correction
/// of the edge cell's condition and its neighbour's (`docs/impact.md`, section 4) brought b at
/// the last step to 4.1e-4 at dx = R/200 and 1.7e-4 at R/400 (the edge cell's alone: 1.5e-3
/// and 6.9e-4; none: 7e-3 and 3.7e-3, the cells' constant pressures behind the edge displacing
/// the edge cell by as much as the model's gap); the test now bounds the largest distance
/// over a time range, which the edge's phase in its cell sets.
#[test]
fn slow_free_edge_follows_hertz() {
    let nu = 0.25;
    for dx in [0.005, 0.0025] {
        let mut c = ImpactCase::new(
            nu,
            Profile::Parabola { radius: 1.0 },
            Drive::Speed(1e-3),
            EdgeLaw::Signorini,
            5.0,
        );
        c.dx = dx;
        c.levels = 1;
        let sol = c.solve(|_| {}).unwrap();
        let run = &sol.runs[0];
        // the largest distance of b from Hertz's edge for the same force, over
        // c1 t/R in [2, 5] (13 to 20 cells at dx = R/200), in cells: 0.028 and 0.014 at
        // R/200 and R/400 with the mid-step edge condition alone, before the other edge's factor
        // (`docs/impact.md`, section 4), 0.0062 and 0.0043 with them, 0.0069 and 0.0047 as
        // reported (the edge's report averages over at most 40 steps, under one crossing here)
        let worst = (1..=run.steps.len())
            .filter(|&n| run.step(n).unwrap().t >= 2.0)
            .map(|n| {
                let (b, force) = (run.edge_at(n).unwrap(), run.force_at(n).unwrap());
                // force in units mu R; E* = 2 mu/(1 - nu)
                let hertz = (force * 2.0 * (1.0 - nu) / std::f64::consts::PI).sqrt();
                (b - hertz).abs() / dx
            })
            .fold(0.0f64, f64::max);
        eprintln!("dx = {dx}: b off Hertz's edge by at most {worst:.4} cells");
        assert!(
            worst < 0.01,
            "dx = {dx}: b off Hertz's edge by {worst} cells"
        );
    }
}

/// Convergence: the observed order of h, R and b is about one or more (the method's order:
/// pressure constant per cell and step), and halving the cells changes h, R and b by less than
/// the error estimate stated on the coarser grid.
#[test]
fn refinement_converges_within_the_stated_errors() {
    let solve = |dx: f64| {
        // an end that is a whole number of both runs' coarsest steps (0.08 and 0.04), so
        // that they share their times
        let case = free_parabola(0.3, 10.0, 0.01, 3.2, dx);
        case.solve(|_| {}).unwrap()
    };
    let coarse = solve(0.01);
    let fine = solve(0.005);
    let (rc, oc) = coarse.history();
    let (rf, _) = fine.history();
    for (name, o) in [("h", oc.h), ("force", oc.force), ("b", oc.b)] {
        let o = o.expect("three levels give an order");
        assert!(o > 0.7 && o < 3.0, "observed order of {name}: {o}");
    }
    let mut checked = 0;
    for r in &rc {
        if let Some(f) = rf.iter().find(|x| (x.t - r.t).abs() < 1e-9) {
            for (c, fv) in [(r.h, f.h), (r.force, f.force), (r.b, f.b)] {
                let err = c.error.unwrap();
                assert!(
                    (c.value - fv.value).abs() <= err + 1e-14,
                    "t = {}: change {} against stated {} (value {})",
                    r.t,
                    (c.value - fv.value).abs(),
                    err,
                    c.value
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 10);
}

/// The kinematic law (eq (4)) puts the edge at f(b) = h; the Signorini edge lies inside it
/// once the edge is slower than c1.
#[test]
fn kinematic_edge_is_geometric_and_wider() {
    let mut case = free_parabola(0.25, 10.0, 0.01, 2.0, 0.01);
    case.levels = 1;
    let sig = case.solve(|_| {}).unwrap();
    case.law = EdgeLaw::Kinematic;
    let kin = case.solve(|_| {}).unwrap();
    let (rs, _) = sig.history();
    let (rk, _) = kin.history();
    let last_k = rk.last().unwrap();
    assert!(((2.0 * last_k.h.value).sqrt() - last_k.b.value).abs() < 1e-12);
    assert!(rs.last().unwrap().b.value < last_k.b.value * 0.9);
}

#[test]
fn bad_input_is_refused_with_the_parameter_named() {
    let base = free_parabola(0.3, 10.0, 0.01, 1.0, 0.01);
    let cases: Vec<(ImpactCase, &str)> = vec![
        (
            ImpactCase {
                drive: Drive::Free {
                    mass_ratio: 0.0,
                    v0_over_c1: 0.01,
                },
                ..base.clone()
            },
            "mass ratio",
        ),
        (
            ImpactCase {
                drive: Drive::Free {
                    mass_ratio: 1.0,
                    v0_over_c1: -0.01,
                },
                ..base.clone()
            },
            "V0/c1",
        ),
        (
            ImpactCase {
                end: 0.0,
                ..base.clone()
            },
            "end time",
        ),
        (
            ImpactCase {
                kappa: 0.25,
                ..base.clone()
            },
            "kappa",
        ),
        (
            ImpactCase {
                profile: Profile::Power { a: 1.0, k: 0.5 },
                ..base.clone()
            },
            "exponent k",
        ),
        (
            ImpactCase {
                profile: Profile::Table(std::sync::Arc::new(vec![
                    (0.0, 0.0),
                    (1.0, 1.0),
                    (2.0, 1.5),
                ])),
                ..base.clone()
            },
            "profile table",
        ),
        (
            ImpactCase {
                poisson: 0.5,
                ..base.clone()
            },
            "Poisson",
        ),
    ];
    for (c, name) in cases {
        let e = c.solve(|_| {}).unwrap_err();
        assert!(e.to_string().contains(name), "{name}: {e}");
        assert!(matches!(
            e,
            ImpactError::InvalidParameter { .. } | ImpactError::Lamb(_)
        ));
    }
}

/// The next term of the supersonic start (`docs/impact.md`, section 6): at the centre of a
/// parabola, p/(rho c1 dh/dt) = 1 + 2 K3 t/t_s + O((t/t_s)^2), with t_s = 2 R V0/c1^2 (the
/// supersonic stage ends at t_s/4) and K3 = 4 c2^2/c1^2 - 4 c2^3/c1^3 - 1/2 from the expansion
/// of the half-plane's symbol in kappa^2/s^2. The slope fitted over 0.02 < t/t_s < 0.2 (with a
/// quadratic term) tends to 2 K3 under refinement.
#[test]
fn supersonic_start_next_term_is_k3() {
    let slope_error = |nu: f64, dx: f64| -> f64 {
        let v0 = 0.1;
        let ts = 2.0 * v0;
        let mut case = free_parabola(nu, 10.0, v0, ts / 4.0, dx);
        case.levels = 1;
        let sol = case.solve(|_| {}).unwrap();
        let run = &sol.runs[0];
        let [k3, _, _] = impedance_coefficients(nu);
        // least squares d = a u + b u^2, u = t/t_s
        let (mut s11, mut s12, mut s22, mut r1, mut r2) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for (i, st) in run.steps.iter().enumerate() {
            let prev = if i > 0 { run.steps[i - 1].v } else { v0 };
            let d = st.pressure[0] * m2(nu) / (0.5 * (st.v + prev)) - 1.0;
            let u = st.t / ts;
            if !(0.02..=0.2).contains(&u) {
                continue;
            }
            s11 += u * u;
            s12 += u * u * u;
            s22 += u * u * u * u;
            r1 += u * d;
            r2 += u * u * d;
        }
        let a = (r1 * s22 - r2 * s12) / (s11 * s22 - s12 * s12);
        a / (2.0 * k3) - 1.0
    };
    let coarse = slope_error(0.25, 0.001);
    let fine = slope_error(0.25, 0.0005);
    assert!(
        fine.abs() < 0.1,
        "slope over 2 K3 - 1: {fine} (dx = R/2000)"
    );
    assert!(
        fine.abs() < 0.5 * coarse.abs(),
        "no convergence: {coarse} then {fine}"
    );
    let other = slope_error(0.2, 0.0005);
    assert!(other.abs() < 0.1, "nu = 0.2: slope over 2 K3 - 1: {other}");
}

/// The half-plane's normal impedance over rho c1 s at kappa = q s/c1 (`docs/impact.md`,
/// section 6): zeta(q) = m^4 Delta/nu1 with nu1 = (q^2 + 1)^(1/2), nu2 = (q^2 + 1/m^2)^(1/2),
/// Delta = (2 q^2 + 1/m^2)^2 - 4 q^2 nu1 nu2, m = c2/c1 (zeta(0) = 1, the acoustic law); for
/// |q| < 1 (the principal roots).
fn impedance(nu: f64, q: Complex64) -> Complex64 {
    let m2 = m2(nu);
    let q2 = q * q;
    let (n1, n2) = ((q2 + 1.0).sqrt(), (q2 + 1.0 / m2).sqrt());
    let delta = (q2 * 2.0 + 1.0 / m2).powi(2) - q2 * n1 * n2 * 4.0;
    delta * (m2 * m2) / n1
}

/// The impedance's Taylor coefficients zeta_1, zeta_2, zeta_3 in q^2 (`docs/impact.md`,
/// section 6; zeta_1 = K3/c1^3, the next term of the supersonic start).
fn impedance_coefficients(nu: f64) -> [f64; 3] {
    let m = m2(nu).sqrt();
    [
        4.0 * m.powi(2) - 4.0 * m.powi(3) - 0.5,
        3.0 / 8.0 - 2.0 * m.powi(2) + 4.0 * m.powi(4) - 2.0 * m.powi(5),
        -5.0 / 16.0 + 1.5 * m.powi(2) - 2.0 * m.powi(4) + 0.5 * m.powi(7),
    ]
}

/// The pressure under a parabola driven at a constant speed V, over rho c1 V, during the
/// supersonic stage (`docs/impact.md`, section 6), at u = t/t_s < 1/4 and xi = x/b inside
/// the cone's bound: (1/pi) Int_0^pi Re[e^(i beta) zeta(2 u^(1/2) cos phi e^(i beta))]/cos beta
/// dphi, sin beta = xi |cos phi|, by the midpoint rule (the integrand is an even, periodic,
/// analytic function of phi: the rule converges geometrically).
fn supersonic_pressure(nu: f64, u: f64, xi: f64) -> f64 {
    let n = 128;
    (0..n)
        .map(|k| {
            let c = ((k as f64 + 0.5) * std::f64::consts::PI / n as f64).cos();
            let beta = (xi * c.abs()).asin();
            let e = Complex64::from_polar(1.0, beta);
            (e * impedance(nu, e * (2.0 * u.sqrt() * c))).re / beta.cos()
        })
        .sum::<f64>()
        / n as f64
}

/// The supersonic stage's pressure in closed form (`docs/impact.md`, section 6): for a
/// parabola driven at a constant speed V, while the edge outruns the P wave (t < t_s/4,
/// t_s = 2 R V/c1^2) the displacement of the whole surface is known, and the pressure is the
/// double series sum_j zeta_j (t/t_s)^j P_j(x/b) in the impedance's Taylor coefficients, whose
/// sum over j is the integral of [`supersonic_pressure`], wherever the cone of dependence of
/// (x, t) lies inside the contact (|x| < b - c1 t). At the default grid (R/200, three
/// levels, the start on finer grids) every cell inside that bound, at every pressure profile
/// of the stage, matches the closed form's mean over the cell and the step within 1e-4 of
/// rho c1 V (measured 2.6e-5 at nu = 1/4 and 3.0e-5 at nu = 0.2, nearly the same offset in
/// every cell and at every time; about 6e-6 at R/400), where the next term alone,
/// 1 + 2 zeta_1 (t - 3 t_x)/t_s, is off by up to 4.2e-3 and 2.5e-3 at the centre.
#[test]
fn supersonic_pressure_in_closed_form() {
    for nu in [0.25, 0.2] {
        // the integral against the series' first terms (zeta_1 = K3, zeta_2, zeta_3 from the
        // expansion; P_1 = 2 - 6 xi^2, P_2 = 6 - 60 xi^2 + 70 xi^4, P_3(0) = 20)
        let [z1, z2, z3] = impedance_coefficients(nu);
        let u = 1e-3;
        let centre = 1.0 + 2.0 * z1 * u + 6.0 * z2 * u * u + 20.0 * z3 * u.powi(3);
        assert!((supersonic_pressure(nu, u, 0.0) - centre).abs() < 1e-11);
        let xi: f64 = 0.6;
        let off = 1.0
            + z1 * u * (2.0 - 6.0 * xi * xi)
            + z2 * u * u * (6.0 - 60.0 * xi * xi + 70.0 * xi.powi(4));
        assert!((supersonic_pressure(nu, u, xi) - off).abs() < 1e-8);

        let v = 0.1;
        let ts = 2.0 * v;
        let mut case = ImpactCase::new(
            nu,
            Profile::Parabola { radius: 1.0 },
            Drive::Speed(v),
            EdgeLaw::Signorini,
            0.2,
        );
        case.dx = 0.005;
        let sol = case.solve(|_| {}).unwrap();
        let dt = sol.runs[0].dt;
        // Gauss-Legendre, five points on [-1, 1]
        let (gx, gw) = (
            [
                -0.906_179_845_938_664,
                -0.538_469_310_105_683,
                0.0,
                0.538_469_310_105_683,
                0.906_179_845_938_664,
            ],
            [
                0.236_926_885_056_189_1,
                0.478_628_670_499_366_5,
                0.568_888_888_888_888_9,
                0.478_628_670_499_366_5,
                0.236_926_885_056_189_1,
            ],
        );
        let (mut worst, mut next_term_off, mut cells): (f64, f64, usize) = (0.0, 0.0, 0);
        for t in [0.01, 0.02, 0.03, 0.04, 0.05] {
            let prof = sol.pressure_profile(t).unwrap();
            let (t, dx) = (prof.t, prof.x[1] - prof.x[0]);
            // the profile is the finest grid's step about t, its cells' means
            if t + 0.5 * dt > ts / 4.0 + 1e-12 {
                continue;
            }
            let t0 = t - 0.5 * dt;
            let bound = (ts * t0).sqrt() - t0;
            for (j, &p) in prof.p.iter().enumerate() {
                let (lo, hi) = (
                    if j == 0 { 0.0 } else { (j as f64 - 0.5) * dx },
                    (j as f64 + 0.5) * dx,
                );
                if hi > bound {
                    break;
                }
                let mut mean = 0.0;
                for (a, wa) in gx.iter().zip(gw) {
                    let tt = t + 0.5 * a * dt;
                    let b = (ts * tt).sqrt();
                    for (c, wc) in gx.iter().zip(gw) {
                        let x = 0.5 * (lo + hi) + 0.5 * c * (hi - lo);
                        mean += 0.25 * wa * wc * supersonic_pressure(nu, tt / ts, x / b);
                    }
                }
                worst = worst.max((p / v - mean).abs());
                cells += 1;
            }
            next_term_off = next_term_off.max((prof.p[0] / v - 1.0 - 2.0 * z1 * t / ts).abs());
        }
        assert!(cells >= 30, "{cells} cells checked");
        assert!(
            worst < 1e-4,
            "nu = {nu}: the pressure off the closed form by {worst:e} of rho c1 V"
        );
        // the higher terms are resolved: the next term alone is off by more than 1e-3
        assert!(next_term_off > 1e-3, "nu = {nu}: {next_term_off:e}");
    }
}

/// The pressure profiles' error estimates (from the next coarser grid) cover the actual
/// error of the finest grid's cell means, measured against a grid four times finer in space
/// and time (its cell means over the same cells, its steps over the same step): the free
/// cylinder through its force peak, and a wedge driven with a prescribed sub-Rayleigh edge,
/// whose pressure is singular there.
#[test]
fn pressure_profile_estimates_cover_a_finer_grid() {
    let wedge = |dx: f64, levels: usize| {
        let v = 0.3 / 80f64.to_radians().tan();
        let mut c = ImpactCase::new(
            0.25,
            Profile::Wedge { theta_deg: 80.0 },
            Drive::Speed(v),
            EdgeLaw::Kinematic,
            1.52,
        );
        c.dx = dx;
        c.levels = levels;
        c
    };
    // ends that are whole numbers of the coarsest step (0.08), so that both runs take the
    // nominal steps and share their times
    let cylinder = |dx: f64, levels: usize| {
        let mut c = free_parabola(0.25, 10.0, 0.01, 7.04, dx);
        c.levels = levels;
        c
    };
    type Setup = fn(f64, usize) -> ImpactCase;
    let cases: [(&str, Setup, f64, &[f64]); 2] = [
        ("cylinder", cylinder, 0.01, &[1.0, 3.0, 6.8]),
        ("wedge", wedge, 0.01, &[0.5, 1.5]),
    ];
    for (name, setup, dx, times) in cases {
        let sol = setup(dx, 3).solve(|_| {}).unwrap();
        let truth = setup(dx / 4.0, 1).solve(|_| {}).unwrap();
        let tr = &truth.runs[0];
        let mut worst: f64 = 0.0;
        for &t in times {
            let prof = sol.pressure_profile(t).unwrap();
            let err = prof.err.as_ref().expect("three levels give estimates");
            // the four steps of the finer grid that make up the step of the profile
            let n = ((prof.t / sol.runs[0].dt) + 0.5).round() as usize;
            let steps: Vec<&Vec<f64>> = (4 * n - 3..=4 * n)
                .map(|k| &tr.step(k).unwrap().pressure)
                .collect();
            let len = steps.iter().map(|p| p.len()).max().unwrap();
            let mean: Vec<f64> = (0..len)
                .map(|j| {
                    steps
                        .iter()
                        .map(|p| p.get(j).copied().unwrap_or(0.0))
                        .sum::<f64>()
                        / 4.0
                })
                .collect();
            let reference = impact::coarse_means(&mean, 4);
            for (j, (p, e)) in prof.p.iter().zip(err).enumerate() {
                let r = reference.get(j).copied().unwrap_or(0.0);
                let actual = (p - r * truth.m * truth.m).abs();
                worst = worst.max(actual / e);
                assert!(
                    actual <= *e,
                    "{name}, c1 t/R = {t}, cell {j} of {}: error {actual:.3e} against stated {e:.3e} (p = {p:.5})",
                    prof.p.len()
                );
            }
        }
        eprintln!("{name}: largest actual/stated {worst:.3}");
    }
}

/// A very light striker under the kinematic law on a nearly incompressible half-plane: the
/// tensile force of the prescribed edge raises h within the step's fixed point, and the edge
/// with it, past the cells the step had considered (before, an index out of bounds). The step
/// widens its cells (`docs/impact.md`, section 9, the contact's window): the run completes,
/// every value finite, and b is the profile's edge of h, (h/A)^(1/k), at every row in
/// contact. (The kinematic march is unstable on this nearly incompressible half-plane,
/// `docs/impact.md` section 9, the force's bound: the striker is thrown off at 59 times its
/// impact speed on this coarse grid and at 27 times on R/100, and on R/200 the run is refused
/// at c1 t/R = 1.34; here the energy audit reports it, an energy defect far above the
/// kinematic law's few tenths.)
#[test]
fn light_kinematic_striker_keeps_its_edge_inside_the_step() {
    let mut case = ImpactCase::new(
        0.49,
        Profile::Power { a: 1.0, k: 3.0 },
        Drive::Free {
            mass_ratio: 0.01,
            v0_over_c1: 0.01,
        },
        EdgeLaw::Kinematic,
        2.0,
    );
    case.dx = 0.02;
    let sol = case.solve(|_| {}).unwrap();
    let (rows, _) = sol.history();
    assert!(!rows.is_empty());
    for r in &rows {
        assert!(r.h.value.is_finite() && r.force.value.is_finite() && r.b.value.is_finite());
        if r.h.value <= 0.0 {
            continue;
        }
        assert!(
            (r.h.value.cbrt() - r.b.value).abs() < 1e-12,
            "c1 t/R = {}: b {} against h {}",
            r.t,
            r.b.value,
            r.h.value
        );
    }
    assert!(rows.iter().filter(|r| r.h.value > 0.0).count() >= 2);
    let audit = rows
        .iter()
        .filter_map(|r| r.energy_defect.map(|d| d.value.abs()))
        .fold(0.0, f64::max);
    assert!(audit > 1.0, "energy defect {audit}");
}

/// The contact's window (`docs/impact.md`, section 9): a light, fast cylinder on a nearly
/// incompressible half-plane (nu = 0.49) with long steps (kappa = 8). Its free edge runs
/// transonic, captured cell by cell, and the contact grows by more than three cells a step
/// (it outruns the geometric one). The step checks the contact conditions over the reach of
/// one step beyond the last contact, and further while the contact reaches the window's end;
/// when it checked three cells only, cells beyond them interpenetrated unseen, their entry put
/// energy in, and the force grew to 1e5 times its peak (energy defect 1e7) without an error.
/// Checked against two independent quantities: the energy balance (the striker's lost
/// kinetic energy against the work through the kernels), with the edge model and with whole
/// cells, and for whole cells (whose conditions are exact, the edge model's edge cell carries
/// the local solution's gap) the gap of every cell beyond the contact out to the P wave's
/// reach, its displacement summed directly from the tables.
#[test]
fn contact_conditions_hold_beyond_a_fast_edge() {
    let (nu, mass, v0, dx, kappa) = (0.49, 1.0, 0.1, 0.000625, 8.0);
    for edge_model in [true, false] {
        let mut case = free_parabola(nu, mass, v0, 0.64, dx);
        case.kappa = kappa;
        case.levels = 1;
        case.start_halvings = 0;
        case.edge_model = edge_model;
        let sol = case.solve(|_| {}).unwrap();
        let (rows, _) = sol.history();
        let ke0 = 0.5 * mass * v0 * v0;
        let gap = rows
            .iter()
            .map(|r| (ke0 - r.kinetic.unwrap().value - r.work.value).abs() / ke0)
            .fold(0.0, f64::max);
        let steps = &sol.runs[0].steps;
        let growth = steps
            .windows(2)
            .map(|w| w[1].pressure.len().saturating_sub(w[0].pressure.len()))
            .max()
            .unwrap();
        eprintln!("edge model {edge_model}: energy gap {gap:.2e}, growth {growth} cells a step");
        assert!(
            growth > 3,
            "the contact grew by {growth} cells a step at most"
        );
        assert!(gap < 0.1, "energy gap {gap:e} of the impact energy");
        if edge_model {
            continue;
        }
        // the direct sum of the displacements at the step's end over the cells out to the P
        // wave's reach, and the largest interpenetration beyond the contact
        let widest = steps.iter().map(|s| s.pressure.len()).max().unwrap();
        let reach = (((steps.len() + 1) as f64 * kappa).ceil() as usize).min(widest + 64);
        let mut tables =
            impact::tables::Tables::new(lamb::HalfPlane::from_poisson(nu).unwrap(), kappa).unwrap();
        tables.ensure(2 * reach + 2, steps.len() + 1).unwrap();
        let mut worst: f64 = 0.0;
        for n in (7..steps.len()).step_by(8) {
            for i in steps[n].pressure.len()..reach {
                let mut w = 0.0;
                for (m, s) in steps[..=n].iter().enumerate() {
                    let row = tables.row(n - m);
                    for (j, &pj) in s.pressure.iter().enumerate() {
                        let a = row[i.abs_diff(j)] + if j > 0 { row[i + j] } else { 0.0 };
                        w += dx * a * pj;
                    }
                }
                let x = i as f64 * dx;
                let fbar = 0.5 * (x * x + dx * dx / 12.0);
                worst = worst.max(steps[n].h - fbar - w);
            }
        }
        eprintln!("whole cells: interpenetration beyond the contact {worst:.2e} R");
        assert!(
            worst < 1e-12,
            "a cell beyond the contact interpenetrates by {worst:e} R"
        );
    }
}

/// The end of the supersonic stage (`docs/impact.md`, section 4): the parabola driven at
/// V/c1 = 0.05 on R/400 with the start on finer grids hands its first stage (R/25600) over at
/// c1 t/R = 0.03, just after the geometric edge has slowed below c1 (at 0.025), while the free
/// edge, captured cell by cell, still runs at 0.9 c1. The edge model's speed, over the last
/// four reported edges, scatters by several percent there; read above c1 at one step, it had
/// put the edge back on the geometric one, and the next steps' slower edge below it, a cycle
/// every five or six steps whose force oscillated by up to 7e-3 of its peak over
/// [0.035, 0.1). A free edge now returns to the supersonic stage only where the geometric edge
/// itself outruns c1. Against one grid of R/6400 throughout (without a hand-over, its own
/// error about 1e-4 of the peak there), the force at every step of R/400 within 2e-4 of its
/// peak.
#[test]
fn a_handover_just_after_the_supersonic_stage_keeps_the_edge_free() {
    let case = |dx: f64, start: usize| {
        let mut c = ImpactCase::reference(EdgeLaw::Signorini);
        c.drive = Drive::Speed(0.05);
        c.end = 0.1;
        c.dx = dx;
        c.levels = 1;
        c.start_halvings = start;
        c.solve(|_| {}).unwrap().runs[0].clone()
    };
    let (run, reference) = (case(0.0025, 6), case(0.00015625, 0));
    let ratio = 16;
    let peak = (1..=reference.steps.len())
        .filter_map(|n| reference.force_at(n))
        .fold(0.0, f64::max);
    let mut worst = (0.0f64, 0.0);
    for n in 1..=run.steps.len() {
        let t = run.steps[n - 1].t;
        if !(0.035..0.1).contains(&t) {
            continue;
        }
        let m = n * ratio;
        assert!(
            (reference.steps[m - 1].t - t).abs() < 1e-12,
            "the steps pair"
        );
        let err = (run.force_at(n).unwrap() - reference.force_at(m).unwrap()).abs() / peak;
        if err > worst.0 {
            worst = (err, t);
        }
    }
    eprintln!(
        "the force's largest error over [0.035, 0.1): {:.2e} of its peak at c1 t/R = {}",
        worst.0, worst.1
    );
    assert!(worst.0 < 2e-4, "{worst:?}");
}

/// The force's bound (`docs/impact.md`, section 9): on a nearly incompressible half-plane
/// (nu = 0.49) the parabola driven at V/c1 = 0.01 under the kinematic law goes unstable (its
/// force had reached 1.2e8 rho c1^2 R by c1 t/R = 2, returned as a result); a step whose mean
/// contact pressure passes 2 rho c1^2 now ends the run with an error naming the Poisson's
/// ratio. The same case on nu = 0.45 runs to its end, its force far below the bound.
#[test]
fn an_unstable_march_is_refused_not_reported() {
    let case = |nu: f64| {
        let mut c = ImpactCase::new(
            nu,
            Profile::Parabola { radius: 1.0 },
            Drive::Speed(0.01),
            EdgeLaw::Kinematic,
            2.0,
        );
        c.levels = 1;
        c
    };
    match case(0.49).solve(|_| {}) {
        Err(ImpactError::Step { time, reason }) => {
            eprintln!("refused at c1 t/R = {time}: {reason}");
            assert!(
                reason.contains("--poisson") && reason.contains("unstable"),
                "{reason}"
            );
        }
        other => panic!(
            "an unstable march returned {:?}",
            other.map(|s| s.runs.len())
        ),
    }
    let sol = case(0.45).solve(|_| {}).unwrap();
    let (rows, _) = sol.history();
    for r in &rows {
        // |F| <= 4 (b + dx) rho c1^2 R (the history's force is over rho c1^2 R), with a
        // wide margin here
        let force = r.force.value;
        assert!(
            force.abs() < 0.1 * 4.0 * (r.b.value + 0.005),
            "{}: {force}",
            r.t
        );
    }
}
