//! The local exponent of the contact pressure at a moving edge (`lamb::edge`, derived in
//! `docs/edge.md`) against the transient solver: a rigid wedge driven at constant speed is
//! self-similar, and its pressures near the edge, fitted over two decades of the distance
//! from the edge by s^lambda times a cubic (`impact::edge_fit`), give the predicted exponent to
//! 1e-2 (`docs/impact.md`, section 8, which also records the two ranges where the march does
//! not converge near the edge).

use impact::edge_fit::fit_self_similar_edge;
use impact::{Drive, EdgeLaw, ImpactCase, Profile};
use lamb::edge::SpeedRange;

const THETA: f64 = 80.0;

/// The driven wedge at V/c1 = `v` up to `end`, one grid of cell width `dx`.
fn driven_wedge(v: f64, law: EdgeLaw, end: f64, dx: f64) -> impact::Solution {
    let mut case = ImpactCase::new(
        0.25,
        Profile::Wedge { theta_deg: THETA },
        Drive::Speed(v),
        law,
        end,
    );
    case.dx = dx;
    case.levels = 1;
    case.solve(|_| {}).expect("the driven wedge solves")
}

/// The free (Signorini) edge of the driven wedge moves at its own sub-Rayleigh speed with the
/// square-root detachment, +1/2.
#[test]
fn free_sub_rayleigh_edge_has_the_square_root_exponent() {
    // V = 0.0529 c1: the edge runs at 0.212 c1, b = R at c1 t/R = 4.71; 800 cells
    let v = 0.3 / THETA.to_radians().tan();
    let sol = driven_wedge(v, EdgeLaw::Signorini, 4.71, 1.0 / 800.0);
    let check = fit_self_similar_edge(&sol).unwrap();
    assert_eq!(check.behaviour.range, SpeedRange::SubRayleigh);
    assert_eq!(check.behaviour.selected, 0.5);
    let (lo, hi) = check.fit.s_range;
    assert!((hi / lo).log10() > 1.9, "decades fitted: {lo} .. {hi}");
    assert!(
        (check.fit.lambda - 0.5).abs() < 1e-2,
        "fitted {} against +1/2",
        check.fit.lambda
    );
}

/// The prescribed (kinematic) edge at 2 c1: the pressure behind a supersonic edge is the
/// local one-dimensional response, a finite jump (exponent 0), up to the P-wave front from the
/// first contact (s = 1/2).
#[test]
fn supersonic_edge_has_a_finite_jump() {
    let d = 2.0;
    let v = d / THETA.to_radians().tan();
    let sol = driven_wedge(v, EdgeLaw::Kinematic, 1.0 / d, 1.0 / 2000.0);
    let check = fit_self_similar_edge(&sol).unwrap();
    assert_eq!(check.behaviour.range, SpeedRange::Supersonic);
    assert!((check.behaviour.speed_over_c1 - d).abs() < 1e-3);
    let (lo, hi) = check.fit.s_range;
    assert!((hi / lo).log10() > 1.9, "decades fitted: {lo} .. {hi}");
    assert!(
        check.fit.lambda.abs() < 1e-2,
        "fitted {} against 0",
        check.fit.lambda
    );
}
