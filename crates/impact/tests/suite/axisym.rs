//! The axisymmetric impact (`impact::axisym`, `docs/axisymmetric.md`) against Hertz's
//! quasi-static theory, the one-dimensional start and its next term, the first-order
//! radiation of a point force (two routes), the plane wave under a driven punch, the
//! self-similar cone and the energy balance.

use std::ops::ControlFlow;

use impact::axisym::{AxiCase, AxiProfile, SolvedAxi};
use impact::{Drive, EdgeLaw, Stop};
use lamb::HalfSpace;

const OWN_DENSITY: f64 = 4.0 * std::f64::consts::PI / 3.0;

fn sphere(v0: f64, end: f64, law: EdgeLaw) -> AxiCase {
    AxiCase {
        poisson: 0.25,
        profile: AxiProfile::Sphere { radius: 1.0 },
        drive: Drive::Free {
            mass_ratio: OWN_DENSITY,
            v0_over_c1: v0,
        },
        law,
        end,
        stop: Stop::AtSeparation,
        dr: None,
        kappa: 2.0,
        levels: 3,
    }
}

fn solve(c: &AxiCase) -> SolvedAxi {
    c.solve(|_| ControlFlow::Continue(())).unwrap()
}

/// Hertz's impact of the rigid sphere of mass ratio `mass` on the half-space (nu, E* =
/// 2 mu/(1 - nu), mu = c1 = 1): (peak force over rho c1^2 R^2, contact duration c1 t/R).
fn hertz(nu: f64, mass: f64, v0: f64) -> (f64, f64) {
    let m2 = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let estar = 2.0 / (1.0 - nu);
    let energy = 0.5 * mass / m2 * v0 * v0;
    let h = (15.0 * energy / (8.0 * estar)).powf(0.4);
    // the duration 2 Int_0^1 dx/(1 - x^(5/2))^(1/2) h/V0, computed here by Gauss-Jacobi-free
    // midpoint sums after x = 1 - u^2 (the end's inverse square root removed)
    let n = 200_000;
    let mut q = 0.0;
    for k in 0..n {
        let u = (k as f64 + 0.5) / n as f64;
        let x: f64 = 1.0 - u * u;
        q += 2.0 * u / (1.0 - x.powf(2.5)).sqrt() / n as f64;
    }
    (4.0 / 3.0 * estar * h.powf(1.5) * m2, 2.0 * q * h / v0)
}

fn peak(sol: &SolvedAxi) -> f64 {
    sol.history()
        .0
        .iter()
        .map(|r| r.force.value)
        .fold(0.0, f64::max)
}

/// Hertz's impact with the first-order radiation (Hunter's order; docs/axisymmetric.md,
/// section 5): the displacement under a slowly varying force lags the static one by
/// E_F dF/dt, so to first order in E_F the paraboloid's force is K h^(3/2) plus the damping
/// (3/2) K h^(1/2) E_F d(K h^(3/2))/dt = (9/4) K^2 E_F h dh/dt. In Hertz's units
/// (x = h/h_max, tau = t V0/h_max) m x'' = -(5/4) x^(3/2) - beta x x' with
/// beta = (9/4) K^2 E_F h_max^2/(m V0); integrated here by the classical Runge-Kutta rule
/// until the force vanishes. Returns the relative differences of the peak force and the
/// contact duration from Hertz's.
fn first_order_hertz(nu: f64, mass: f64, v0: f64, ef: f64) -> (f64, f64) {
    let m2 = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let estar = 2.0 / (1.0 - nu);
    let k = 4.0 / 3.0 * estar;
    let m = mass / m2;
    let h_max = (15.0 * 0.5 * m * v0 * v0 / (8.0 * estar)).powf(0.4);
    let beta = 2.25 * k * k * ef * h_max * h_max / (m * v0);
    let force = |x: f64, v: f64| x.max(0.0).powf(1.5) + 0.8 * beta * x.max(0.0) * v;
    let accel = |x: f64, v: f64| -1.25 * force(x, v);
    let n = 400_000;
    let dt = 4.0 / n as f64;
    let (mut x, mut v, mut tau, mut peak) = (0.0f64, 1.0f64, 0.0, 0.0f64);
    let mut f_prev = 0.0;
    for _ in 0..n {
        let (k1x, k1v) = (v, accel(x, v));
        let (k2x, k2v) = (
            v + 0.5 * dt * k1v,
            accel(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v),
        );
        let (k3x, k3v) = (
            v + 0.5 * dt * k2v,
            accel(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v),
        );
        let (k4x, k4v) = (v + dt * k3v, accel(x + dt * k3x, v + dt * k3v));
        x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        tau += dt;
        let f = force(x, v);
        peak = peak.max(f);
        if tau > 0.5 && f <= 0.0 {
            // the force's zero, linear between the last two steps
            let end = tau - dt * f / (f - f_prev);
            return (peak - 1.0, end / HERTZ_DURATION - 1.0);
        }
        f_prev = f;
    }
    panic!("the first-order Hertz impact did not end");
}

/// 2 Int_0^1 dx/(1 - x^(5/2))^(1/2): Hertz's duration over h_max/V0.
const HERTZ_DURATION: f64 = 2.943_275_184_324_705;

/// The sphere's own quasi-static impact (no waves) against Hertz's, which takes the sphere
/// for its paraboloid: Sneddon's contact of the sphere, approach
/// d(a) = (a/2) ln((R + a)/(R - a)) and force
/// F(a) = (E*/2)((a^2 + R^2) ln((R + a)/(R - a)) - 2 a R), to the contact radius where Int F dd has taken the impact energy. Returns the
/// relative difference of the peak force from Hertz's (R = 1).
fn sphere_quasi_static(nu: f64, mass: f64, v0: f64) -> f64 {
    let m2 = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let estar = 2.0 / (1.0 - nu);
    let e0 = 0.5 * mass / m2 * v0 * v0;
    let log = |a: f64| ((1.0 + a) / (1.0 - a)).ln();
    let force = |a: f64| 0.5 * estar * ((a * a + 1.0) * log(a) - 2.0 * a);
    let dd = |a: f64| 0.5 * log(a) + a / (1.0 - a * a);
    let stored = |a: f64| {
        let n = 2000;
        (0..n)
            .map(|k| {
                let x = (k as f64 + 0.5) / n as f64 * a;
                force(x) * dd(x) * a / n as f64
            })
            .sum::<f64>()
    };
    let (mut lo, mut hi) = (0.0, 0.9);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if stored(mid) < e0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let h_max = (15.0 * e0 / (8.0 * estar)).powf(0.4);
    force(0.5 * (lo + hi)) / (4.0 / 3.0 * estar * h_max.powf(1.5)) - 1.0
}

/// Hertz's quasi-static limit (issue's test): the differences of the peak force and the
/// contact duration from Hertz's shrink at the rate (V0/c1)^(3/5) of the energy the waves
/// carry off, and are below one percent at V0/c1 = 1e-4; the radiated energy approaches its
/// first-order value, E_F Int (dF/dt)^2 dt over Hertz's pulse.
#[test]
fn a_slow_sphere_approaches_hertz() {
    let mut dforce = Vec::new();
    let mut dtime = Vec::new();
    let mut radiated = Vec::new();
    let mut first_order = Vec::new();
    let ef = HalfSpace::from_poisson(0.25f64)
        .unwrap()
        .radiation_constant()
        .unwrap()
        .value;
    for (v0, end) in [(1e-2, 20.0), (1e-3, 30.0), (1e-4, 45.0)] {
        let sol = solve(&sphere(v0, end, EdgeLaw::Signorini));
        let (f_h, t_h) = hertz(0.25, OWN_DENSITY, v0);
        let r = sol.rebound().unwrap();
        let df = peak(&sol) / f_h - 1.0;
        let dt = r.separation.value / t_h - 1.0;
        // the same impact to first order in the radiation, with the sphere's own geometry
        let (model, _) = first_order_hertz(0.25, OWN_DENSITY, v0, ef);
        let geometry = sphere_quasi_static(0.25, OWN_DENSITY, v0);
        eprintln!(
            "V0/c1 = {v0:e}: first-order radiation {model:+.4e}, the sphere's geometry {geometry:+.4e}, the march {df:+.4e}"
        );
        first_order.push(model + geometry);
        // the first-order radiation: E_F F^2/t_c * 4.6851... / E0 (docs/axisymmetric.md, 5)
        let m2 = 1.0 / 3.0;
        let e0 = 0.5 * OWN_DENSITY / m2 * v0 * v0;
        let first = ef * (f_h / m2).powi(2) / t_h * 4.685_148_538_378_613 / e0;
        eprintln!(
            "V0/c1 = {v0:e}: peak force {df:+.4e}, duration {dt:+.4e}, radiated {:.6} (first order {first:.6}), restitution {:.6} +- {:.1e}",
            r.radiated_fraction.value,
            r.restitution.value,
            r.restitution.error.unwrap()
        );
        // the restitution's estimate covers its distance from 1 - radiated
        assert!((r.restitution.value.powi(2) - (1.0 - r.radiated_fraction.value)).abs() < 1e-12);
        dforce.push(df);
        dtime.push(dt);
        radiated.push((r.radiated_fraction.value, first));
    }
    // the waves take energy: the force falls short of Hertz's, the contact lasts longer
    assert!(dforce.iter().all(|d| *d < 0.0) && dtime.iter().all(|d| *d > 0.0));
    // below one percent at 1e-4
    assert!(dforce[2].abs() < 0.01 && dtime[2].abs() < 0.01);
    // the force's difference is the first-order radiation's (with the sphere's own
    // geometry, a small part of the same sign) to 7 percent of itself: the waves, not the
    // grid, make it
    for (d, f) in dforce.iter().zip(&first_order) {
        assert!(
            (d / f - 1.0).abs() < 0.07,
            "the march {d:e}, first order {f:e}"
        );
    }
    // each decade divides them by 10^(3/5) = 3.98 or nearly (the sphere's departure from its
    // paraboloid shrinks like (V0/c1)^(4/5)); the force's ratios approach 3.98 from below,
    // as the first-order model's own do (3.59 and 3.88: the damping's effect on the peak is
    // not linear in the damping), hence the ten percent
    for w in first_order.windows(2) {
        eprintln!("first order: per-decade ratio {:.3}", w[0] / w[1]);
    }
    let rate = 10f64.powf(0.6);
    for d in [&dforce, &dtime] {
        for w in d.windows(2) {
            let ratio = w[0] / w[1];
            assert!(
                ratio > 0.9 * rate,
                "per-decade ratio {ratio} against {rate}"
            );
        }
    }
    // the radiated energy approaches its first order
    let gap: Vec<f64> = radiated.iter().map(|(r, f)| (r / f - 1.0).abs()).collect();
    assert!(
        gap[0] > gap[1] && gap[1] > gap[2] && gap[2] < 0.01,
        "{gap:?}"
    );
}

/// The radiated fraction follows (V0/c1)^(3/5) as V0 -> 0: its exponent fitted over the two
/// decades 1e-5 .. 1e-3 is 3/5 to 0.02, and its prefactor approaches the first-order one.
#[test]
fn radiated_energy_follows_three_fifths() {
    let mut pts = Vec::new();
    for (v0, end, kappa) in [(1e-3, 30.0, 2.0), (1e-4, 45.0, 2.0), (1e-5, 70.0, 4.0)] {
        let mut c = sphere(v0, end, EdgeLaw::Signorini);
        c.kappa = kappa;
        let sol = solve(&c);
        let r = sol.rebound().unwrap();
        pts.push((
            v0,
            r.radiated_fraction.value,
            r.radiated_fraction.error.unwrap(),
        ));
    }
    let (x0, y0, _) = pts[0];
    let (x2, y2, _) = pts[2];
    let slope = (y0 / y2).ln() / (x0 / x2).ln();
    let ef = HalfSpace::from_poisson(0.25f64)
        .unwrap()
        .radiation_constant()
        .unwrap()
        .value;
    let (f_h, t_h) = hertz(0.25, OWN_DENSITY, 1.0);
    let m2 = 1.0 / 3.0;
    let prefactor_first =
        ef * (f_h / m2).powi(2) / t_h * 4.685_148_538_378_613 / (0.5 * OWN_DENSITY / m2);
    let prefactor = y2 / x2.powf(0.6);
    eprintln!(
        "radiated fraction exponent {slope:.4}, prefactor at 1e-5 {prefactor:.4} (first order {prefactor_first:.4}); {pts:?}"
    );
    assert!((slope - 0.6).abs() < 0.02, "exponent {slope}");
    assert!((prefactor / prefactor_first - 1.0).abs() < 0.01);
}

/// The point force's radiation constant by the second route: the Laplace-Hankel transform
/// at s -> 0 (docs/axisymmetric.md, section 5): E_F = Lambda/(2 pi mu c2^2),
/// Lambda = Int_0^inf (G_inf - G(q)) dq, G = q eta1/D, against the time-domain constant of
/// `lamb` (the step response's deficit at the loaded point).
#[test]
fn the_point_force_radiation_constant_by_two_routes() {
    for nu in [0.25f64, 0.1, 0.3, 0.45, -0.3] {
        let m2 = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
        let b = 1.0 / m2;
        let g = |q: f64| {
            let q2 = q * q;
            let (e1, e2, k) = ((q2 + 1.0).sqrt(), (q2 + b).sqrt(), 2.0 * q2 + b);
            // D (K^2 + 4 q^2 e1 e2), expanded: free of the cancellation of D at large q
            let num = 16.0 * (b - 1.0) * q2 * q2 * q2
                + 8.0 * b * (3.0 * b - 2.0) * q2 * q2
                + 8.0 * b * b * b * q2
                + b.powi(4);
            q * e1 * (k * k + 4.0 * q2 * e1 * e2) / num
        };
        let ginf = 0.5 / (b - 1.0);
        // Int_0^Q by Gauss-Legendre on dyadic panels, the tail C/Q + D/(3 Q^3) with C, D from
        // the integrand's values at two large q
        let rule = complexfn::quadrature::gauss_legendre_rule::<f64>(40, 53).unwrap();
        let mut lambda = 0.0;
        let mut lo = 0.0;
        let big = 1024.0;
        let mut hi = 1.0 / 64.0;
        while lo < big {
            for (x, w) in rule.iter() {
                let q = lo + (hi - lo) * (x + 1.0) / 2.0;
                lambda += w * (hi - lo) / 2.0 * (ginf - g(q));
            }
            lo = hi;
            hi *= 2.0;
        }
        let (q1, q2) = (big, 2.0 * big);
        let (r1, r2) = ((ginf - g(q1)) * q1 * q1, (ginf - g(q2)) * q2 * q2);
        // r(q) = C + D/q^2
        let d = (r1 - r2) / (1.0 / (q1 * q1) - 1.0 / (q2 * q2));
        let c = r1 - d / (q1 * q1);
        lambda += c / big + d / (3.0 * big.powi(3));
        let transform = lambda / (2.0 * std::f64::consts::PI * m2);
        let time = HalfSpace::from_poisson(nu)
            .unwrap()
            .radiation_constant()
            .unwrap();
        assert!(
            (transform - time.value).abs() < 1e-9 * time.value,
            "nu {nu}: {transform} vs {}",
            time.value
        );
        assert!(time.error < 1e-12);
    }
}

/// The one-dimensional start: at first contact the pressure is the plane wave's rho c1 V0;
/// while the edge outruns the P wave the contact is the geometric one ring by ring; and the
/// mean pressure over the inner half of the contact grows with the next term of the
/// supersonic start, 4 (K3/c1^3)(t/t_s) (docs/axisymmetric.md, section 4: the plane's 2
/// becomes 4, the paraboloid's Laplacian being 2/R).
#[test]
fn the_start_is_one_dimensional() {
    let v0 = 0.1;
    let c = AxiCase {
        poisson: 0.25,
        profile: AxiProfile::Paraboloid { radius: 1.0 },
        drive: Drive::Free {
            mass_ratio: 1000.0,
            v0_over_c1: v0,
        },
        law: EdgeLaw::Signorini,
        end: 0.048,
        stop: Stop::AtEnd,
        dr: Some(0.001),
        kappa: 1.0,
        levels: 1,
    };
    let sol = solve(&c);
    let run = &sol.runs[0];
    let m: f64 = (1.0f64 / 3.0).sqrt();
    let k3 = 4.0 * m * m - 4.0 * m * m * m - 0.5;
    let ts = 2.0 * v0;
    let rho = 1.0 / (m * m);
    // the first step: the plane wave
    let p0 = run.steps[0].pressure[0];
    assert!((p0 / (rho * v0) - 1.0).abs() < 0.01, "{p0}");
    let mut pts = Vec::new();
    for (n, s) in run.steps.iter().enumerate() {
        // the supersonic stage ends at t_s/4 = 0.05: the contact is the geometric one
        let geometric = (((2.0 * s.h).sqrt() / run.dr).floor() as usize) + 1;
        let rings = s.pressure.len();
        assert!(
            rings + 1 >= geometric && rings <= geometric,
            "step {n}: {rings} rings, {geometric} geometric"
        );
        // the inner half's mean pressure (area-weighted) at the step's middle
        let half = rings / 2;
        let (mut num, mut den) = (0.0, 0.0);
        for (i, p) in s.pressure.iter().take(half).enumerate() {
            let w = if i == 0 { 0.25 } else { 2.0 * i as f64 };
            num += w * p;
            den += w;
        }
        let tm = s.t - 0.5 * run.dt;
        if tm / ts > 0.02 {
            pts.push((tm / ts, num / den / (rho * v0)));
        }
    }
    // the slope of the least-squares line through (t/t_s, p/(rho c1 V0))
    let n = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
    let (mx, my) = (sx / n, sy / n);
    let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |a, p| {
        (a.0 + (p.0 - mx) * (p.1 - my), a.1 + (p.0 - mx).powi(2))
    });
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    eprintln!(
        "inner half's pressure: 1 + {slope:.4} t/t_s (intercept {intercept:.5}); next term {:.4}",
        4.0 * k3
    );
    assert!((intercept - 1.0).abs() < 0.002, "{intercept}");
    assert!((slope / (4.0 * k3) - 1.0).abs() < 0.2, "{slope}");
}

/// A flat punch of radius R under Signorini's conditions on one grid whose rings 0..=n lie
/// under it ((n + 1/2) dr = R).
fn punch(poisson: f64, drive: Drive, end: f64, stop: Stop, n: usize) -> AxiCase {
    AxiCase {
        poisson,
        profile: AxiProfile::Flat { radius: 1.0 },
        drive,
        law: EdgeLaw::Signorini,
        end,
        stop,
        dr: Some(1.0 / (n as f64 + 0.5)),
        kappa: 2.0,
        levels: 1,
    }
}

/// A flat punch driven at constant speed: under its middle, until the edge's waves arrive,
/// the pressure is the plane wave's rho c1 V exactly (the ring coefficients' sum rule).
#[test]
fn a_driven_punch_carries_the_plane_wave() {
    let v = 0.01;
    let c = punch(0.3, Drive::Speed(v), 0.5, Stop::AtEnd, 40);
    let sol = solve(&c);
    let run = &sol.runs[0];
    let m2 = (1.0 - 0.6) / (2.0 * 0.7);
    for s in &run.steps {
        // rings whose outer edge is farther than c1 t (+ the implicit coupling's few rings)
        // from the punch's edge
        let reach = s.t + 12.0 * run.dr;
        for (i, p) in s.pressure.iter().enumerate() {
            if (i as f64 + 0.5) * run.dr < 1.0 - reach {
                assert!(
                    (p * m2 / v - 1.0).abs() < 1e-9,
                    "t {}, ring {i}: {}",
                    s.t,
                    p * m2 / v
                );
            }
        }
    }
}

/// Signorini's conditions on every ring of a light punch, checked with the displacements
/// recomputed here from `lamb::HalfSpace::ring_step` (not the march's tables): at the end of
/// every step each ring under the punch either pushes (p > 0) and sits on the punch, or
/// carries nothing and is not penetrated. The punch stops in its plane-wave stage and its
/// middle lifts off while its rim still pushes: the contact is not a disk, which an active
/// set of whole disks could not find (it held the middle in tension, down to -7e-3 mu, and
/// the punch in contact until c1 t/R = 2.95 instead of 0.86).
#[test]
fn a_light_punch_keeps_signorini_on_every_ring() {
    let drive = Drive::Free {
        mass_ratio: 0.3,
        v0_over_c1: 0.01,
    };
    let c = punch(0.25, drive, 20.0, Stop::AtSeparation, 20);
    let sol = solve(&c);
    let run = &sol.runs[0];
    let space = HalfSpace::from_poisson(0.25).unwrap();
    let kappa = run.dt / run.dr;
    let under = 21; // rings 0..=20 under the punch: (20 + 1/2) dr = R
    let steps = &run.steps;
    // U_ij(l kappa), unit ring width, cached
    let mut u = std::collections::HashMap::new();
    let mut step_u = |i: usize, j: usize, l: usize| -> f64 {
        *u.entry((i, j, l)).or_insert_with(|| {
            let r = lamb::Annulus::ring_cell(i, &1.0).unwrap();
            let s = lamb::Annulus::ring_cell(j, &1.0).unwrap();
            space.ring_step(&r, &s, &(l as f64 * kappa)).unwrap().value
        })
    };
    let mut holes = 0;
    for (n, st) in steps.iter().enumerate() {
        assert!(
            st.pressure.iter().all(|&p| p >= 0.0),
            "step {n}: {:?}",
            st.pressure
        );
        let contact: Vec<bool> = (0..under)
            .map(|i| st.pressure.get(i).is_some_and(|&p| p > 0.0))
            .collect();
        // not a disk: a ring off inside a ring on
        let last_on = contact.iter().rposition(|&c| c);
        if last_on.is_some_and(|k| contact[..k].iter().any(|&c| !c)) {
            holes += 1;
        }
        for (i, &touching) in contact.iter().enumerate() {
            let mut w = 0.0;
            for (m, past) in steps[..=n].iter().enumerate() {
                let lag = n - m;
                for (j, &p) in past.pressure.iter().enumerate() {
                    if p != 0.0 {
                        w += run.dr * p * (step_u(i, j, lag + 1) - step_u(i, j, lag));
                    }
                }
            }
            let gap = w - st.h;
            if touching {
                assert!(
                    gap.abs() < 1e-9 * st.h.abs().max(1e-6),
                    "step {n}, ring {i}: gap {gap:e}"
                );
            } else {
                assert!(
                    gap > -1e-9 * st.h.abs().max(1e-6),
                    "step {n}, ring {i} penetrated: {gap:e}"
                );
            }
        }
    }
    eprintln!(
        "light punch: {} steps, {holes} with the middle off, separation {:?}",
        steps.len(),
        run.separations
    );
    assert!(holes > 0);
    let sep = run.separations[0];
    assert!(sep < 1.5, "{sep}");
}

/// A cone driven at constant speed is self-similar: its force grows like t^2.
#[test]
fn a_driven_cone_is_self_similar() {
    let c = AxiCase {
        poisson: 0.25,
        profile: AxiProfile::Cone { theta_deg: 70.0 },
        drive: Drive::Speed(0.05),
        law: EdgeLaw::Signorini,
        end: 1.0,
        stop: Stop::AtEnd,
        dr: None,
        kappa: 2.0,
        levels: 3,
    };
    let sol = solve(&c);
    let rows = sol.history().0;
    let late: Vec<(f64, f64, f64)> = rows
        .iter()
        .filter(|r| r.t > 0.5)
        .map(|r| (r.t, r.force.value, r.force.error.unwrap()))
        .collect();
    let (t1, f1, e1) = late[0];
    let (t2, f2, e2) = *late.last().unwrap();
    let k1 = f1 / (t1 * t1);
    let k2 = f2 / (t2 * t2);
    let bound = e1 / (t1 * t1) + e2 / (t2 * t2);
    assert!(
        (k1 - k2).abs() <= bound.max(1e-3 * k2),
        "F/t^2 {k1} at {t1}, {k2} at {t2}, estimates {bound}"
    );
}

/// Energy balance: kinetic energy plus the work on the half-space stay the impact energy to
/// 1e-4 over a whole impact under Signorini's conditions (the kinematic law's edge exchanges
/// energy with the half-space, the next tests).
#[test]
fn the_energy_balance_closes() {
    for (v0, end, law) in [
        (1e-2, 20.0, EdgeLaw::Signorini),
        (1e-3, 30.0, EdgeLaw::Signorini),
    ] {
        let sol = solve(&sphere(v0, end, law));
        let rows = sol.history().0;
        let worst = rows
            .iter()
            .filter_map(|r| r.energy_defect.as_ref())
            .fold(0.0f64, |a, d| a.max(d.value.abs()));
        eprintln!("V0/c1 = {v0:e}, {law:?}: largest energy defect {worst:.3e}");
        assert!(worst < 1e-4, "{worst}");
        // after the separation all the lost energy is in the half-space, none of it static
        let last = rows.last().unwrap();
        let rad = last.radiated_fraction.as_ref().unwrap().value;
        let r = sol.rebound().unwrap();
        assert!(
            (rad - r.radiated_fraction.value).abs() < 1e-3,
            "{rad} vs {}",
            r.radiated_fraction.value
        );
    }
}

/// The energy the kinematic law's edge releases, quasi-statically, over E0: the geometric
/// contact radius a of the sphere at penetration h_g(a) = R - (R^2 - a^2)^(1/2) carries the
/// pressure of the contact without edge stress for a (Sneddon's sphere, approach
/// d0(a) = (a/2) ln((R + a)/(R - a))) plus a flat punch's of depth h_g - d0 < 0, whose
/// edge's energy release rate is E* (h_g - d0)^2/(2 pi a) (the adhesive contact's). Integrated
/// over the contact area, E* Int_0^a (h_g - d0)^2 da'.
fn kinematic_edge_release(a: f64, v0: f64) -> f64 {
    let nu = 0.25;
    let estar = 2.0 / (1.0 - nu);
    let m2 = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let e0 = 0.5 * OWN_DENSITY / m2 * v0 * v0;
    let n = 4000;
    let mut sum = 0.0;
    for k in 0..n {
        let x = (k as f64 + 0.5) / n as f64 * a;
        let hg = 1.0 - (1.0 - x * x).sqrt();
        let d0 = 0.5 * x * ((1.0 + x) / (1.0 - x)).ln();
        sum += estar * (hg - d0).powi(2) * a / n as f64;
    }
    sum / e0
}

/// Over the reported times up to the largest contact: the largest distance of the energy
/// defect from the quasi-static edge release, and that release at the largest contact.
fn growing_contact_against_release(sol: &SolvedAxi, v0: f64) -> (f64, f64) {
    let rows = sol.history().0;
    let top = rows
        .iter()
        .enumerate()
        .max_by(|x, y| x.1.a.value.total_cmp(&y.1.a.value))
        .unwrap()
        .0;
    let worst = rows[..=top]
        .iter()
        .map(|r| {
            (r.energy_defect.as_ref().unwrap().value - kinematic_edge_release(r.a.value, v0)).abs()
        })
        .fold(0.0, f64::max);
    (worst, kinematic_edge_release(rows[top].a.value, v0))
}

/// The kinematic law's energy audit is its edge's energy (`docs/axisymmetric.md`, section
/// 6): while the geometric contact grows, kinetic energy plus the work on the half-space
/// exceed the impact energy by the energy an adhesive edge of that pull releases, seven
/// tenths of the impact energy at the largest contact of this slow impact. The march follows
/// that closed form within 0.05 of the impact energy at its default grid.
#[test]
fn the_kinematic_edge_releases_an_adhesive_contacts_energy() {
    let v0 = 1e-3;
    let sol = solve(&sphere(v0, 40.0, EdgeLaw::Kinematic));
    let (worst, peak_release) = growing_contact_against_release(&sol, v0);
    eprintln!("kinematic, V0/c1 = 1e-3: release at the largest contact {peak_release:.4}, largest difference of the defect from it {worst:.3e}");
    assert!(peak_release > 0.6, "{peak_release}");
    assert!(worst < 0.05, "{worst}");
}

/// What the kinematic edge released it takes back as the contact shrinks (the quasi-static
/// release is reversible): the defect left at the separation goes to zero with the ring
/// width (0.14 at the default grid, 0.05 at half of it, V0/c1 = 1e-2), and the growing
/// contact follows the release closer on the finer grid.
#[test]
#[ignore = "two kinematic runs, one at half the default ring width: about 40 s"]
fn the_kinematic_edge_gives_its_energy_back() {
    let v0 = 1e-2;
    let mut ends = Vec::new();
    for halve in [false, true] {
        let mut c = sphere(v0, 20.0, EdgeLaw::Kinematic);
        c.levels = 1;
        if halve {
            c.dr = Some(0.5 * c.default_dr());
        }
        let sol = solve(&c);
        let end = sol
            .history()
            .0
            .last()
            .unwrap()
            .energy_defect
            .as_ref()
            .unwrap()
            .value;
        let (worst, _) = growing_contact_against_release(&sol, v0);
        eprintln!("dr = {:.5}: defect at the separation {end:.4}, growing contact against the release {worst:.3e}", c.finest_dr());
        assert!(sol.rebound().is_ok());
        assert!(worst < 0.05, "{worst}");
        ends.push(end);
    }
    assert!(ends[1].abs() < 0.5 * ends[0].abs(), "{ends:?}");
    assert!(ends[1].abs() < 0.08, "{ends:?}");
}

#[test]
fn bad_input_is_refused_with_the_parameter_named() {
    let mut c = sphere(1e-3, 10.0, EdgeLaw::Signorini);
    c.kappa = 0.1;
    assert!(c.validate().unwrap_err().to_string().contains("kappa"));
    let mut c = sphere(1e-3, 10.0, EdgeLaw::Signorini);
    c.profile = AxiProfile::Cone { theta_deg: 95.0 };
    assert!(c.validate().unwrap_err().to_string().contains("theta_deg"));
    let mut c = sphere(0.5, 10.0, EdgeLaw::Signorini);
    c.drive = Drive::Free {
        mass_ratio: 1000.0,
        v0_over_c1: 0.5,
    };
    assert!(c
        .validate()
        .unwrap_err()
        .to_string()
        .contains("contact radius"));
    let mut c = sphere(1e-3, 10.0, EdgeLaw::Signorini);
    c.dr = Some(-1.0);
    assert!(c.validate().unwrap_err().to_string().contains("dr"));
}
