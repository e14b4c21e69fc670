//! The estimate sweep's cases and the comparison of a solved case's estimates with finer
//! grids, shared by `estimate_sweep` and the test `tests/suite/estimates.rs`
//! (`docs/impact.md`, section 5).
#![allow(dead_code)]

use impact::{Drive, EdgeLaw, HistoryRow, ImpactCase, Profile, SolvedImpact, Value};

/// A free striker.
pub fn free(nu: f64, profile: Profile, mass: f64, v0: f64, law: EdgeLaw, end: f64) -> ImpactCase {
    ImpactCase::new(
        nu,
        profile,
        Drive::Free {
            mass_ratio: mass,
            v0_over_c1: v0,
        },
        law,
        end,
    )
}

/// The sweep's cases: (name, case).
pub fn cases() -> Vec<(&'static str, ImpactCase)> {
    let parabola = Profile::Parabola { radius: 1.0 };
    let (sig, kin) = (EdgeLaw::Signorini, EdgeLaw::Kinematic);
    vec![
        ("reference", ImpactCase::reference(sig)),
        ("reference kinematic", ImpactCase::reference(kin)),
        (
            "light fast nu .3",
            free(0.3, parabola.clone(), 1.0, 0.1, sig, 3.2),
        ),
        (
            "heavy slow nu .1",
            free(0.1, parabola.clone(), 1000.0, 0.001, sig, 10.0),
        ),
        ("nu .45", free(0.45, parabola.clone(), 10.0, 0.01, sig, 8.0)),
        (
            "power k 3",
            free(
                0.25,
                Profile::Power { a: 1.0, k: 3.0 },
                10.0,
                0.01,
                sig,
                6.0,
            ),
        ),
        (
            "circle M 100 V .05",
            free(0.25, Profile::Circle { radius: 1.0 }, 100.0, 0.05, sig, 6.0),
        ),
        (
            "wedge 80",
            free(
                0.25,
                Profile::Wedge { theta_deg: 80.0 },
                10.0,
                0.01,
                sig,
                4.0,
            ),
        ),
        (
            "kinematic M 100 V .05",
            free(0.25, parabola.clone(), 100.0, 0.05, kin, 6.0),
        ),
        (
            "kinematic power k 3",
            free(
                0.2,
                Profile::Power { a: 1.0, k: 3.0 },
                30.0,
                0.003,
                kin,
                8.0,
            ),
        ),
        (
            "slow M 300 nu .2",
            free(0.2, parabola.clone(), 300.0, 0.003, sig, 10.0),
        ),
        (
            "kinematic wedge 80",
            free(0.3, Profile::Wedge { theta_deg: 80.0 }, 3.0, 0.03, kin, 3.2),
        ),
    ]
}

/// A reported history's value at a row (`None` where the case has no such history).
pub type Pick = fn(&HistoryRow) -> Option<Value>;

/// The histories compared: h, b and the force (the sharp estimator), then the penetration
/// speed, the striker's kinetic energy, the work on the half-plane and the energy defect
/// (the conservative bound).
pub const PICKS: [(&str, Pick); 7] = [
    ("h", |r| Some(r.h)),
    ("b", |r| Some(r.b)),
    ("force", |r| Some(r.force)),
    ("hdot", |r| Some(r.hdot)),
    ("kinetic", |r| r.kinetic),
    ("work", |r| Some(r.work)),
    ("energy defect", |r| r.energy_defect),
];

pub fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// One report row compared: its index and time, and per quantity of [`PICKS`] the value, the
/// stated error and the values of the grids four and two times finer (both the exact value
/// where one is known: the energy defect under Signorini's law, 0).
pub struct Compared {
    /// The row's index in the history.
    pub i: usize,
    /// c1 t/R.
    pub t: f64,
    /// (value, stated error, four times finer, twice finer) per quantity.
    pub q: [(f64, Option<f64>, f64, f64); PICKS.len()],
}

impl Compared {
    /// The bound of quantity q's actual error, the difference from the grid four times finer
    /// plus that grid's own error (its difference from the grid twice finer).
    pub fn bound(&self, q: usize) -> f64 {
        let (v, _, t4, t2) = self.q[q];
        (v - t4).abs() + (t4 - t2).abs()
    }
}

/// `base` solved with its levels at `dx`, its history, and the rows the grids four and two
/// times finer (one level each) share with it.
pub fn compare(base: &ImpactCase, dx: f64) -> (SolvedImpact, Vec<HistoryRow>, Vec<Compared>) {
    let mut case = base.clone();
    case.dx = dx;
    let sol = case.solve(|_| {}).expect("the case solves");
    let (rows, _) = sol.history();
    let reference = |d: f64| {
        let mut c = base.clone();
        c.dx = d;
        c.levels = 1;
        // refined at every time: the start hands over on the schedule of dx
        c.start_grid = Some(dx);
        c.solve(|_| {}).expect("the reference solves").history().0
    };
    let (r4, r2) = (reference(dx / 4.0), reference(dx / 2.0));
    let find = |rs: &[HistoryRow], t: f64| rs.iter().find(|r| (r.t - t).abs() < 1e-9).cloned();
    let compared = rows
        .iter()
        .enumerate()
        .filter_map(|(i, r)| {
            let (a, b) = (find(&r4, r.t)?, find(&r2, r.t)?);
            let q = PICKS.map(|(key, pick)| match (pick(r), pick(&a), pick(&b)) {
                // under Signorini's law the continuum's energy defect is exactly zero
                // (`docs/impact.md`, section 9): the exact value replaces the finer grids'
                (Some(v), Some(_), Some(_))
                    if key == "energy defect" && base.law == EdgeLaw::Signorini =>
                {
                    (v.value, v.error, 0.0, 0.0)
                }
                (Some(v), Some(x), Some(y)) => (v.value, v.error, x.value, y.value),
                _ => (f64::NAN, None, f64::NAN, f64::NAN),
            });
            Some(Compared { i, t: r.t, q })
        })
        .collect();
    (sol, rows, compared)
}
