//! The bridge to the wedge: a rigid wedge driven into the half-plane at constant speed V with
//! the Signorini edge law settles to the self-similar classical solution of the `wedge` crate
//! (frictionless, uncoupled: the first paper's solution, an independent construction by
//! Brock's technique): the contact edge moves at alpha with V(alpha) from the wedge crate, and
//! the pressure equals the wedge crate's contact stress (40), both converging under refinement.

use impact::{Drive, EdgeLaw, ImpactCase, Profile};

/// (relative error of the fitted edge speed, largest pressure error over the middle of the
/// contact relative to the largest pressure there) for contact speed p = alpha/c1 and dx.
fn bridge(p: f64, dx: f64) -> (f64, f64) {
    let (alpha, pressure, _) = bridge_with(p, dx, true);
    (alpha, pressure)
}

/// As [`bridge`], with or without the edge cell's local model, and the relative error of the
/// edge b(t)/(alpha t) - 1 at the end time.
fn bridge_with(p: f64, dx: f64, edge_model: bool) -> (f64, f64, f64) {
    let mat = wedge::Material::paper();
    let theta = 80.0f64;
    let ind = wedge::Indenter::classical(theta).unwrap();
    let case = wedge::Case::new(&mat, &ind, p, wedge::Solution::Paper).unwrap();
    let cot = 1.0 / theta.to_radians().tan();
    // V/c1 = V/(c1 cot Theta) cot Theta
    let v = case.v_hat().unwrap() * cot;
    let mut c = ImpactCase::new(
        mat.poisson(),
        Profile::Wedge { theta_deg: theta },
        Drive::Speed(v),
        EdgeLaw::Signorini,
        1.0,
    );
    c.dx = dx;
    c.levels = 1;
    c.edge_model = edge_model;
    // the edge model on one grid throughout (a start on finer grids would hand the steps
    // over merged from them)
    c.start_halvings = 0;
    let sol = c.solve(|_| {}).unwrap();
    let run = &sol.runs[0];
    // b = alpha t + const over the second half (the edge moves cell by cell)
    let pts: Vec<(f64, f64)> = run
        .steps
        .iter()
        .filter(|s| s.t >= 0.5)
        .map(|s| (s.t, s.b))
        .collect();
    let n = pts.len() as f64;
    let (sx, sy, sxx, sxy) = pts.iter().fold((0.0, 0.0, 0.0, 0.0), |a, (x, y)| {
        (a.0 + x, a.1 + y, a.2 + x * x, a.3 + x * y)
    });
    let alpha = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    // cell pressures (units mu) against the cell means of the wedge's contact stress
    // -sigma_theta = -mu cot Theta stress_hat(x/(c1 t)), over 0.2 p <= x/(c1 t) <= 0.8 p (the
    // apex is logarithmic, the edge a square root: the cells' means are compared away from both)
    let last = run.steps.last().unwrap();
    let gauss = [
        (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.0, 0.568_888_888_888_888_9),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let (mut err, mut top) = (0.0f64, 0.0f64);
    for (j, pj) in last.pressure.iter().enumerate() {
        let x = j as f64 * run.dx / last.t;
        if !(0.2 * p..=0.8 * p).contains(&x) {
            continue;
        }
        let h = 0.5 * run.dx / last.t;
        let mean: f64 = gauss
            .iter()
            .map(|(u, w)| w * case.stress_hat(&(x + h * u)).unwrap().value)
            .sum::<f64>()
            * 0.5;
        let want = -mean * cot;
        err = err.max((pj - want).abs());
        top = top.max(want.abs());
    }
    (
        alpha / p - 1.0,
        err / top,
        last.b / (p * last.edge_time) - 1.0,
    )
}

#[test]
fn driven_wedge_settles_to_the_self_similar_solution() {
    for p in [0.2, 0.45] {
        // dx = R/100 and R/400 (b/R = p at the end: 20 to 180 cells over the contact)
        let (a1, p1) = bridge(p, 0.01);
        let (a2, p2) = bridge(p, 0.0025);
        assert!(a2.abs() < 5e-4, "p = {p}: alpha off by {a2:e}");
        assert!(
            a2.abs() < 0.5 * a1.abs(),
            "p = {p}: alpha errors {a1:e}, {a2:e}"
        );
        assert!(p2 < 5e-3, "p = {p}: pressure off by {p2:e}");
        assert!(p2 < 0.5 * p1, "p = {p}: pressure errors {p1:e}, {p2:e}");
    }
}

/// The edge cell's local model (`docs/impact.md`, section 4) makes the edge's error a smooth
/// function of the grid: at a sub-Rayleigh edge speed the error of b(t) is first order with a
/// ratio of 2 between successive grids to 2 percent, so one Richardson step removes it to
/// 1e-4; with whole cells the error is first order too but irregular, and the same step
/// leaves an error over 5 times larger.
#[test]
fn edge_model_makes_the_edge_error_smooth() {
    let p = 0.2;
    let errors = |model: bool| -> Vec<f64> {
        [0.01, 0.005, 0.0025]
            .iter()
            .map(|&dx| bridge_with(p, dx, model).2)
            .collect()
    };
    let with = errors(true);
    let without = errors(false);
    let show = |e: &[f64]| {
        e.iter()
            .map(|x| format!("{x:.2e}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    eprintln!(
        "b/(alpha t_b) - 1 at R/100, R/200, R/400: model {}; whole cells {}",
        show(&with),
        show(&without)
    );
    let ratio = |e: &[f64], i: usize| e[i] / e[i + 1];
    let richardson = |e: &[f64], i: usize| (2.0 * e[i + 1] - e[i]).abs();
    for i in 0..2 {
        assert!(
            (ratio(&with, i) - 2.0).abs() < 0.04,
            "with the model: errors {with:?}"
        );
    }
    assert!(richardson(&with, 1) < 1e-4, "with the model: {with:?}");
    assert!(
        richardson(&without, 1) > 5.0 * richardson(&with, 1),
        "whole cells {without:?} against the model {with:?}"
    );
}
