//! Cost of the march against the number of time steps N_t and contact cells N_x, with the
//! fitted exponents (least squares on log-log scales), single grid, f64, one thread:
//!
//! - a driven flat punch (fixed contact of N_x = a/dx + 1/2 cells) for several end times at
//!   fixed a (cost against N_t) and several half-widths at a fixed end time (against N_x);
//! - the reference case (free rigid cylinder, m0/(rho R^2) = 10, V0/c1 = 0.01, to
//!   c1 t/R = 10) for several dx (N_t and N_x both grow like 1/dx).
//!
//! `cargo run --release -p impact --features examples --example cost_scaling`
use std::time::Instant;

use impact::cost::fitted_exponent;
use impact::{Drive, EdgeLaw, ImpactCase, Profile};

fn seconds(case: &ImpactCase) -> (f64, usize, usize) {
    // the fastest of three runs
    let mut best = f64::INFINITY;
    let mut sizes = (0, 0);
    for _ in 0..3 {
        let t0 = Instant::now();
        let sol = case.solve(|_| {}).expect("the case solves");
        best = best.min(t0.elapsed().as_secs_f64());
        let run = &sol.runs[0];
        let nx = run
            .steps
            .iter()
            .map(|s| s.pressure.len())
            .max()
            .unwrap_or(0);
        sizes = (run.steps.len(), nx);
    }
    (best, sizes.0, sizes.1)
}

fn punch(a: f64, end: f64) -> ImpactCase {
    let mut c = ImpactCase::new(
        0.3,
        Profile::Flat { half_width: a },
        Drive::Speed(0.01),
        EdgeLaw::Signorini,
        end,
    );
    c.dx = 0.01;
    c.levels = 1;
    c
}

fn main() {
    println!("driven flat punch, dx = R/100, kappa = 2: cost against N_t (a = 0.2 R)");
    let mut pts = Vec::new();
    for end in [1.0, 2.0, 4.0, 8.0, 16.0] {
        let (s, nt, nx) = seconds(&punch(0.2, end));
        println!("  N_t = {nt:5}  N_x = {nx:4}  {s:.4} s");
        pts.push((nt as f64, s));
    }
    println!(
        "  fitted exponent of N_t: {:.2}",
        fitted_exponent(&pts).unwrap_or(f64::NAN)
    );
    println!("driven flat punch, dx = R/100: cost against N_x (c1 t/R = 2)");
    let mut pts = Vec::new();
    for a in [0.1, 0.2, 0.4, 0.8, 1.6] {
        let (s, nt, nx) = seconds(&punch(a, 2.0));
        println!("  N_t = {nt:5}  N_x = {nx:4}  {s:.4} s");
        pts.push((nx as f64, s));
    }
    println!(
        "  fitted exponent of N_x: {:.2}",
        fitted_exponent(&pts).unwrap_or(f64::NAN)
    );
    println!("reference case (free rigid cylinder to c1 t/R = 10), one grid: cost against 1/dx");
    let mut pts = Vec::new();
    for dx in [0.04, 0.02, 0.01, 0.005, 0.0025] {
        let mut c = ImpactCase::reference(EdgeLaw::Signorini);
        c.dx = dx;
        c.levels = 1;
        let (s, nt, nx) = seconds(&c);
        println!(
            "  dx = R/{:<4} N_t = {nt:5}  N_x = {nx:4}  {s:.4} s",
            (1.0 / dx).round()
        );
        pts.push((1.0 / dx, s));
    }
    println!(
        "  fitted exponent of 1/dx: {:.2}",
        fitted_exponent(&pts).unwrap_or(f64::NAN)
    );
}
