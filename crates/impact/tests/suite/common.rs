//! Shared setup of the impact engine's integration tests.
#![allow(dead_code)]

use impact::{Drive, EdgeLaw, HistoryRow, ImpactCase, Profile, Striker};

/// (c2/c1)^2 of Poisson's ratio nu: rho c1^2 = mu/m^2, so a pressure over mu times m^2 is the
/// pressure over rho c1^2.
pub fn m2(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))
}

/// A free striker with the parabolic profile of radius R, Signorini edge, cell width `dx`
/// (three refinement levels, the default).
pub fn free_parabola(nu: f64, mass_ratio: f64, v0: f64, end: f64, dx: f64) -> ImpactCase {
    let mut case = ImpactCase::new(
        nu,
        Profile::Parabola { radius: 1.0 },
        Drive::Free {
            mass_ratio,
            v0_over_c1: v0,
        },
        EdgeLaw::Signorini,
        end,
    );
    case.dx = dx;
    case
}

/// The reported history of `case` with `striker`.
pub fn history(case: ImpactCase, striker: Striker) -> Vec<HistoryRow> {
    case.with_striker(striker)
        .solve(|_| {})
        .expect("the case solves")
        .history()
        .0
}
