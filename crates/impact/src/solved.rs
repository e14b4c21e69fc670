//! A solved impact case and what it reports: the history of the finest grid with error
//! estimates from grid refinement (`docs/impact.md`, section 5), the rebound, the pressure
//! profiles and the striker's energies.

use complexfn::{ErrorKind, Real};

use crate::case::{Drive, ImpactCase};
use crate::error::{ImpactError, Result};
use crate::march::EdgeLaw;
use crate::run::Run;
use crate::scalar::Scalar;
use crate::striker::cylinder::DiskModes;
use crate::striker::{shell_energies, Ring, Striker};

/// The safety factor on the grids' differences in the conservative error estimates of a
/// history and a pressure profile (`docs/impact.md`, section 5): the contact set moves cell by
/// cell, so the error is not smooth in dx.
const ESTIMATE_SAFETY: f64 = 4.0;

/// The report times either side of a row over which its level differences are taken (the
/// contact set moves cell by cell, so one difference may happen to be small).
const ESTIMATE_WINDOW: usize = 4;

/// How the estimates of one history were formed (`docs/impact.md`, section 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Estimator {
    /// Richardson's estimate with the observed order credited up to a cap, times a safety
    /// factor measured on the twelve-case sweep: the order is shown on three levels.
    Richardson,
    /// The conservative bound: four times the level differences, no order above one
    /// credited (the order is not shown, or the quantity is outside the sweep).
    Conservative,
}

impl Estimator {
    /// `richardson` or `conservative`.
    pub fn name(self) -> &'static str {
        match self {
            Estimator::Richardson => "richardson",
            Estimator::Conservative => "conservative",
        }
    }
}

/// The estimator of one history and what it credited ([`Orders::models`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorModel {
    /// The estimator of the rows.
    pub estimator: Estimator,
    /// The safety factor on the level differences.
    pub safety: f64,
    /// The order credited in the Richardson factor 1/(2^p - 1) (never above 1 for the
    /// conservative bound, which credits no order above the first).
    pub order_credited: Option<f64>,
    /// The rows that took the conservative bound all the same: the times while the coarsest
    /// grid's contact spans less than one of its cells, and for b and the force the last
    /// report time where their crossing fits are one-sided there (a level that neither
    /// marched past the end, `Run::beyond`, nor left the contact before it).
    pub conservative_rows: usize,
    /// The rows whose estimate is at least half the finest cell (b's, where the free edge is
    /// captured cell by cell: faster than 0.8 c_R, or without the edge model).
    pub cell_floor_rows: usize,
    /// The rows whose estimate is Richardson's at the order every row of their window shows
    /// on its own ([`ORDER_SHOWN_ROW_TOLERANCE`]; h's and b's, `docs/impact.md` section 5), where it
    /// is below the policy's: how many, at what safety and order (`None` where no row took
    /// it).
    pub order_shown: Option<OrderShown>,
}

/// The rows of a history whose estimate took the order their window shows row by row
/// ([`ErrorModel::order_shown`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrderShown {
    /// How many rows.
    pub rows: usize,
    /// The safety factor on their level differences.
    pub safety: f64,
    /// The order credited: the history's observed order taken in [1, 2].
    pub order_credited: f64,
}

impl ErrorModel {
    /// The conservative bound on every one of `rows` rows, crediting no order (the
    /// axisymmetric march's histories).
    pub fn conservative(rows: usize) -> Self {
        ErrorModel {
            estimator: Estimator::Conservative,
            safety: ESTIMATE_SAFETY,
            order_credited: None,
            conservative_rows: rows,
            cell_floor_rows: 0,
            order_shown: None,
        }
    }
}

/// The sharp estimator's safety factor and order cap for one history (`docs/impact.md`,
/// section 5).
#[derive(Clone, Copy, Debug)]
struct SharpPolicy {
    safety: f64,
    order_cap: f64,
    /// The safety factor of Richardson's estimate at the order the rows show one by one
    /// ([`shown_order_estimate`]), where the history takes it.
    shown_safety: Option<f64>,
}

const fn policy(safety: f64, order_cap: f64) -> Option<SharpPolicy> {
    Some(SharpPolicy {
        safety,
        order_cap,
        shown_safety: None,
    })
}

/// h's and b's policy: [`policy`] and, where every row of the window shows the order on its
/// own, Richardson's estimate at that order with the safety [`SHOWN_SAFETY`].
const fn shown_policy(safety: f64, order_cap: f64) -> Option<SharpPolicy> {
    Some(SharpPolicy {
        safety,
        order_cap,
        shown_safety: Some(SHOWN_SAFETY),
    })
}

/// The safety factor on h's and b's Richardson estimate where every row of the window shows
/// the order (`docs/impact.md`, section 5): at 3 the estimate is three times the error of an
/// exactly second-order history; over the twelve-case sweep at R/200 the largest ratios of
/// actual to stated stayed where they were (rows outside the check) and b's median rose from
/// 0.080 to 0.12.
const SHOWN_SAFETY: f64 = 3.0;

/// The scheme's order (cell means in space and time, the midpoint rule in time): the most a
/// row's shown order is credited.
pub const ORDER_SCHEME: f64 = 2.0;

/// How far, in log2, each row's ratio of the level differences, (Q_2 - Q_4)/(Q_1 - Q_2), may
/// lie from 2^p, p the history's observed order taken in [1, [`ORDER_SCHEME`]], for the order
/// to count as shown in that row (`docs/impact.md`, section 5): 0.3, a ratio within a factor
/// 1.23 of 2^p, and of the same sign.
pub const ORDER_SHOWN_ROW_TOLERANCE: f64 = 0.3;

/// Richardson's estimate of a row whose window shows the order row by row: with the level
/// differences `d1[j]` = Q_1 - Q_2 and `d2[j]` = Q_2 - Q_4 over the window's rows and the
/// history's observed order `p`, `None` unless every row's ratio d2/d1 lies within
/// [`ORDER_SHOWN_ROW_TOLERANCE`] (in log2) of 2^p' with p' = p taken in [1, [`ORDER_SCHEME`]];
/// then `safety` times the largest of |d1| and |d2|/2^p' over the window, times
/// 1/(2^p' - 1).
fn shown_order_estimate(
    d1: impl Iterator<Item = f64>,
    d2: impl Iterator<Item = f64>,
    p: f64,
    safety: f64,
) -> Option<f64> {
    let p = p.clamp(1.0, ORDER_SCHEME);
    let scale = 0.5f64.powf(p);
    let mut d: f64 = 0.0;
    for (a, b) in d1.zip(d2) {
        let r = b / a;
        if !(r.is_finite() && r > 0.0 && (r.log2() - p).abs() <= ORDER_SHOWN_ROW_TOLERANCE) {
            return None;
        }
        d = d.max(a.abs()).max(scale * b.abs());
    }
    (d > 0.0).then(|| safety * d * richardson_factor(p))
}

/// The policies of the runs outside the start on finer grids (a deformable striker, the flat
/// punch, the kinematic law, or the start turned off): h, b and the force, the smallest round
/// factors that kept the ratio of the actual error to the stated one below 0.8 over the
/// twelve-case sweep at dx = R/100 and R/200 before the start (the force's 3.5 raised to 5
/// once the last reports took whole windows: the kinematic wedge's force at R/100 reached
/// 0.99 at c1 t/R = 1.6, where its coarser levels' windows had been narrowed by the run's
/// end and so had differed more). b's error carries the edge's
/// phase across the cell crossings, which the level differences follow only loosely, so no
/// order above one is credited; h and the force are smooth. The other histories take the
/// conservative bound.
fn plain_policy(q: usize) -> Option<SharpPolicy> {
    match q {
        Q_H => shown_policy(2.0, 1.0),
        Q_B => shown_policy(2.0, 1.0),
        Q_FORCE => policy(5.0, 2.0),
        _ => None,
    }
}

/// The policies of a rigid striker of a curved profile under Signorini's law with the start
/// on finer grids ([`ImpactCase::starts_finer`], at least [`crate::solve::START_HALVINGS`]
/// halvings): measured on the sweep's eight such cases at dx = R/100 and R/200 with the
/// start, the smallest round factors that keep the ratio of actual to stated below 0.7
/// (`docs/impact.md`, section 5). The start removes the early rows where the coarse levels
/// resolved the contact worst, so h and the penetration speed (and with it the kinetic
/// energy) are estimated within a factor two of their actual errors; b and the force keep a
/// spread of about eight (the edge's phase across cell crossings); the work and the energy
/// defect, once conservative, take the observed order too.
fn started_policy(q: usize) -> Option<SharpPolicy> {
    match q {
        Q_H => shown_policy(1.25, 1.5),
        Q_HDOT => policy(1.5, 1.5),
        Q_B => shown_policy(5.5, 2.0),
        Q_FORCE => policy(5.0, 2.0),
        Q_WORK => policy(3.5, 1.5),
        Q_DEFECT => policy(2.0, 1.5),
        _ => None,
    }
}

// the histories' indices in `SolvedImpact::history`'s samples
const Q_H: usize = 0;
const Q_HDOT: usize = 1;
const Q_B: usize = 2;
const Q_FORCE: usize = 3;
const Q_DEFECT: usize = 6;
const Q_WORK: usize = 7;

/// Richardson's factor 1/(2^p - 1) for the order p (at least 1 when p is at most one).
fn richardson_factor(p: f64) -> f64 {
    1.0 / (2f64.powf(p) - 1.0)
}

/// The conservative bound's factor for the observed order `p`: Richardson's where p is
/// positive, never below 1 (no order above the first credited), and at most its value at
/// [`ORDER_SHOWN`], 1/(2^(1/2) - 1) = 2.41 (Richardson's tail sum grows without bound as p
/// goes to 0, where the levels do not converge at all: a bound of 2000 times the value at
/// p = 0.003 said nothing more); 1 without an order.
fn conservative_factor(p: Option<f64>) -> f64 {
    p.filter(|p| *p > 0.0)
        .map_or(1.0, |p| richardson_factor(p.max(ORDER_SHOWN)).max(1.0))
}

/// The lowest observed order at which the sharp estimator is used.
const ORDER_SHOWN: f64 = 0.5;

/// A pressure profile of the finest grid ([`SolvedImpact::pressure_profile`]).
#[derive(Clone, Debug)]
pub struct PressureProfile<T = f64> {
    /// c1 t/R (the middle of the step).
    pub t: T,
    /// The cell centres x/R.
    pub x: Vec<T>,
    /// The cells' mean pressures p/(rho c1^2).
    pub p: Vec<T>,
    /// Their error estimates (`None` with a single grid).
    pub err: Option<Vec<f64>>,
}

/// The mean pressures over the cells of a grid `ratio` times coarser (`ratio` even; the
/// coarse cell k spans [(k ratio - ratio/2) dx, (k ratio + ratio/2) dx], so the fine cells at
/// its two ends count half), from the fine cells' means `p` (cell j spanning
/// [(j - 1/2) dx, (j + 1/2) dx], cell 0 centred on the axis, the profile even).
pub fn coarse_means<T: Scalar>(p: &[T], ratio: usize) -> Vec<T> {
    let half = ratio / 2;
    let zero = T::of(0.0);
    // the even extension p_-j = p_j, and nothing beyond the given cells
    let at = |j: i64| p.get(j.unsigned_abs() as usize).copied().unwrap_or(zero);
    let n = p.len().div_ceil(half) / 2 + 1;
    (0..n)
        .map(|k| {
            let c = (k * ratio) as i64;
            let h = half as i64;
            let inner = (c - h + 1..c + h).map(at).fold(zero, |a, v| a + v);
            (inner + (at(c - h) + at(c + h)) * 0.5) / ratio as f64
        })
        .collect()
}

/// The edge's speed range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// |db/dt| > c1.
    Supersonic,
    /// c2 < |db/dt| < c1.
    Transonic,
    /// c_R < |db/dt| < c2.
    RayleighShear,
    /// |db/dt| < c_R.
    SubRayleigh,
}

impl Stage {
    /// `supersonic`, `transonic`, `rayleigh-shear` or `sub-rayleigh`.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Supersonic => "supersonic",
            Stage::Transonic => "transonic",
            Stage::RayleighShear => "rayleigh-shear",
            Stage::SubRayleigh => "sub-rayleigh",
        }
    }
}

/// The finest grid's value with its absolute error estimate from refinement (kind
/// [`ErrorKind::Refinement`]): the workspace's one value-with-error type,
/// [`complexfn::Estimate`], whose error is here an `Option`, `None` with a single grid level
/// (nothing to refine against), never a zero that would read as exact.
pub type Value<T = f64> = complexfn::Estimate<T, Option<f64>>;

/// One row of the reported history (dimensionless).
#[derive(Clone, Debug)]
pub struct HistoryRow<T = f64> {
    /// c1 t/R.
    pub t: T,
    /// h/R.
    pub h: Value<T>,
    /// (dh/dt)/c1.
    pub hdot: Value<T>,
    /// b/R.
    pub b: Value<T>,
    /// (db/dt)/c1 (central difference of b over the reporting interval).
    pub bdot: T,
    /// The edge's speed range.
    pub stage: Stage,
    /// R(t)/(rho c1^2 R).
    pub force: Value<T>,
    /// Striker kinetic energy over rho c1^2 R^2 (free striker).
    pub kinetic: Option<Value<T>>,
    /// Work done on the half-plane over rho c1^2 R^2, through the kernels.
    pub work: Value<T>,
    /// The striker's surface displacement towards its interior at the contact point (mean over
    /// the central cell) over R; `None` for a rigid striker.
    pub striker_deformation: Option<Value<T>>,
    /// Energy taken up by the striker's deformation (its strain and vibration kinetic
    /// energy: the work of the contact pressure on its surface) over rho c1^2 R^2; `None`
    /// for a rigid striker.
    pub striker_energy: Option<Value<T>>,
    /// (kinetic + work on the half-plane + the striker's energy - impact energy)/impact
    /// energy (free striker; `docs/impact.md`, section 9).
    pub energy_defect: Option<Value<T>>,
}

/// The rebound of a free striker, after its last separation ([`SolvedImpact::rebound`]).
#[derive(Clone, Copy, Debug)]
pub struct Rebound<T = f64> {
    /// c1 t/R at which the contact last ended (the end of the last step in contact).
    pub separation: Value<T>,
    /// The coefficient of restitution -V_final/V0, V_final the striker's speed after the
    /// separation (constant in free flight).
    pub restitution: Value<T>,
    /// The work done on the half-plane over the impact energy (1/2) m0 V0^2: the share of
    /// the impact energy carried off by the half-plane's waves (in plane strain no static
    /// field remains).
    pub energy_to_half_plane: Value<T>,
    /// The number of re-impacts (contacts begun after a separation) before the last
    /// separation.
    pub reimpacts: usize,
}

/// The observed convergence order of each quantity, and how each history's estimates were
/// formed.
#[derive(Clone, Debug)]
pub struct Orders {
    /// Order of h.
    pub h: Option<f64>,
    /// Order of b.
    pub b: Option<f64>,
    /// Order of the force.
    pub force: Option<f64>,
    /// The error model of each estimated history ([`Models`]: the sharp estimator or the
    /// conservative bound, `docs/impact.md`, section 5); `None` with one level.
    pub models: Option<Models>,
}

/// The error models of the histories ([`Orders::models`]).
#[derive(Clone, Copy, Debug)]
pub struct Models {
    /// h's.
    pub h: ErrorModel,
    /// The penetration speed's (and the kinetic energy's, formed from it).
    pub hdot: ErrorModel,
    /// b's.
    pub b: ErrorModel,
    /// The force's.
    pub force: ErrorModel,
    /// The work on the half-plane's (never below the kinetic energy's estimate).
    pub work: ErrorModel,
    /// The energy defect's (under Signorini's law never below the defect itself).
    pub energy_defect: ErrorModel,
    /// The other histories' (the striker's deformation and energy).
    pub others: ErrorModel,
}

/// A solved case, at the precision T.
#[derive(Clone, Debug)]
pub struct SolvedImpact<T = f64> {
    /// The inputs.
    pub case: ImpactCase,
    /// c2/c1.
    pub m: T,
    /// c_R/c1.
    pub s_r: T,
    pub(crate) mass: Option<T>,
    /// The runs, finest first.
    pub runs: Vec<Run<T>>,
    /// A cylinder striker's free modes below [`CYLINDER_MODES_BELOW`] (computed beside the
    /// march), `None` for the other strikers.
    pub(crate) disk_modes: Option<Result<DiskModes>>,
}

/// The estimate of a quantity known on every level (finest first) as one number per level:
/// the difference of the two finest levels (or half that of the next pair, if larger),
/// extrapolated with the observed order where three levels show one above 1/2, times the
/// safety factor of the histories; `None` with one level. Shared by the plane and the
/// axisymmetric marches.
pub(crate) fn level_estimate(values: &[f64]) -> Option<f64> {
    if values.len() < 2 || values.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let d1 = (values[0] - values[1]).abs();
    let d2 = values.get(2).map(|c| (values[1] - c).abs());
    let factor = match d2 {
        Some(d2) if d1 > 0.0 && d2 > 0.0 => {
            let p = (d2 / d1).log2();
            if p > ORDER_SHOWN {
                conservative_factor(Some(p))
            } else {
                2.0
            }
        }
        _ => 1.0,
    };
    Some(ESTIMATE_SAFETY * d1.max(0.5 * d2.unwrap_or(0.0)) * factor)
}

/// The estimates of a history known on every level at the same report times (finest first,
/// `levels[q][i]`): at each time the largest of |Q_1 - Q_2| and |Q_2 - Q_4|/2 over the nine
/// report times around it (the contact set moves ring by ring or cell by cell, so one
/// difference may happen to be small), extrapolated with the history's observed order where
/// it is positive, times the safety factor; with the observed order. `None` with one level.
pub(crate) fn windowed_estimates(levels: &[Vec<f64>]) -> (Option<Vec<f64>>, Option<f64>) {
    if levels.len() < 2 {
        return (None, None);
    }
    let n = levels.iter().map(Vec::len).min().unwrap_or(0);
    let ord = if levels.len() >= 3 {
        order(&levels[0][..n], &levels[1][..n], &levels[2][..n])
    } else {
        None
    };
    let factor = conservative_factor(ord);
    let est = (0..n)
        .map(|i| {
            let mut d: f64 = 0.0;
            for j in i.saturating_sub(4)..(i + 5).min(n) {
                d = d.max((levels[0][j] - levels[1][j]).abs());
                if let Some(c) = levels.get(2) {
                    d = d.max(0.5 * (levels[1][j] - c[j]).abs());
                }
            }
            ESTIMATE_SAFETY * d * factor
        })
        .collect();
    (Some(est), ord)
}

fn order(fine: &[f64], mid: &[f64], coarse: &[f64]) -> Option<f64> {
    let d1: f64 = fine.iter().zip(mid).map(|(a, b)| (a - b).abs()).sum();
    let d2: f64 = mid.iter().zip(coarse).map(|(a, b)| (a - b).abs()).sum();
    (d1 > 0.0 && d2 > 0.0).then(|| (d2 / d1).log2())
}

impl<T: Scalar> SolvedImpact<T> {
    /// The reporting interval: the coarsest level's time step (its times are steps of every
    /// level).
    pub fn report_dt(&self) -> T {
        self.runs.last().map(|r| r.dt).unwrap_or(T::of(0.0))
    }

    /// Separation time c1 t/R of the finest grid (the last time the contact ended, the
    /// striker off the surface at the run's end), with its estimate from the levels'
    /// separations (never below the finest step); `None` when the finest grid's striker is
    /// in contact at the end or never separated.
    pub fn separation(&self) -> Option<Value<T>> {
        self.rebound().ok().map(|r| r.separation)
    }

    /// The rebound of a free striker ([`Rebound`]), or the reason it is unavailable: a
    /// driven striker, or one still in contact at the end of the run on one of the levels.
    pub fn rebound(&self) -> std::result::Result<Rebound<T>, String> {
        let Drive::Free { v0_over_c1, .. } = self.case.drive else {
            return Err("a driven striker has no rebound".into());
        };
        let fine = &self.runs[0];
        let free_at_end = |r: &Run<T>| {
            !r.separations.is_empty() && r.steps.last().is_some_and(|s| s.pressure.is_empty())
        };
        if !free_at_end(fine) {
            let t = fine.steps.last().map(|s| s.t.to_f64()).unwrap_or(0.0);
            return Err(format!(
                "the striker is in contact at the end of the run (c1 t/R = {t:.4}): run longer, or to --end separation"
            ));
        }
        let mass = self.mass.ok_or("no mass")?;
        let v0 = T::input(v0_over_c1);
        let e0 = mass * v0 * v0 * 0.5;
        let per_level = |r: &Run<T>| -> Option<(T, T, T)> {
            if !free_at_end(r) {
                return None;
            }
            let last = r.steps.last()?;
            Some((*r.separations.last()?, -last.v / v0, last.work / e0))
        };
        let levels: Vec<(T, T, T)> = self.runs.iter().map_while(per_level).collect();
        let (sep, res, work) = levels[0];
        let pick =
            |q: usize| -> Vec<f64> { levels.iter().map(|l| [l.0, l.1, l.2][q].to_f64()).collect() };
        let coarser_in_contact = levels.len() < self.runs.len().min(2);
        let est = |q: usize| -> Option<f64> {
            if coarser_in_contact {
                return None;
            }
            level_estimate(&pick(q))
        };
        Ok(Rebound {
            separation: Value {
                value: sep,
                error: est(0).map(|e| e.max(fine.dt.to_f64())),
                kind: ErrorKind::Refinement,
            },
            restitution: Value {
                value: res,
                error: est(1),
                kind: ErrorKind::Refinement,
            },
            energy_to_half_plane: Value {
                value: work,
                error: est(2),
                kind: ErrorKind::Refinement,
            },
            reimpacts: fine.reimpacts.len(),
        })
    }

    fn kinetic(&self, v: T) -> Option<T> {
        // (1/2) m0 v^2 in units mu R^2 -> over rho c1^2 R^2 = (1/m^2)
        self.mass.map(|mass| mass * v * v * self.m * self.m * 0.5)
    }

    /// The reported history with error estimates, and the observed orders.
    pub fn history(&self) -> (Vec<HistoryRow<T>>, Orders) {
        let m2 = self.m * self.m;
        let dtr = self.report_dt();
        let fine = &self.runs[0];
        let zero = T::of(0.0);
        let last_t = fine.steps.last().map(|s| s.t).unwrap_or(zero);
        let nrep = ((last_t / dtr).to_f64() + 1e-9).floor() as usize;
        // the levels share their time levels: report time i is step i dtr/dt of each level,
        // at the time the finest level gives it (the end exactly at the last)
        let per = |r: &Run<T>| (dtr / r.dt).to_f64().round().max(1.0) as usize;
        let times: Vec<T> = (1..=nrep)
            .map(|i| fine.step(i * per(fine)).map_or(dtr * i as f64, |s| s.t))
            .collect();
        // the step of a run at a report time
        let step_at = |r: &Run<T>, i: usize| (i + 1) * per(r);
        // each quantity at step n (time t_n)
        type Getter<'g, T> = Box<dyn Fn(&Run<T>, usize) -> Option<T> + 'g>;
        // the energy defect (kinetic + work + striker's - impact energy)/impact energy of a
        // free striker (`docs/impact.md`, section 9)
        let energy = match (self.mass, &self.case.drive) {
            (Some(mass), Drive::Free { v0_over_c1, .. }) => {
                let v0 = T::input(*v0_over_c1);
                Some((mass, mass * v0 * v0 * 0.5))
            }
            _ => None,
        };
        let getters: [Getter<'_, T>; 8] = [
            Box::new(|r, n| r.step(n).map(|s| s.h)),
            Box::new(|r, n| r.step(n).map(|s| s.v)),
            Box::new(|r, n| r.edge_at(n)),
            Box::new(|r, n| r.force_at(n)),
            Box::new(|r, n| {
                r.step(n)
                    .map(|s| s.ws.first().copied().unwrap_or(T::of(0.0)))
            }),
            Box::new(|r, n| r.step(n).map(|s| s.striker_work)),
            Box::new(move |r, n| {
                let (mass, e0) = energy?;
                r.step(n)
                    .map(|s| (mass * s.v * s.v * 0.5 + s.work + s.striker_work - e0) / e0)
            }),
            Box::new(|r, n| r.step(n).map(|s| s.work)),
        ];
        // samples[q][level][i] (NaN where a level has no value)
        let samples: Vec<Vec<Vec<T>>> = getters
            .iter()
            .map(|g| {
                self.runs
                    .iter()
                    .map(|r| {
                        times
                            .iter()
                            .enumerate()
                            .map(|(i, _)| g(r, step_at(r, i)).unwrap_or(T::of(f64::NAN)))
                            .collect()
                    })
                    .collect()
            })
            .collect();
        // their f64 values, for the orders and the estimates
        let low: Vec<Vec<Vec<f64>>> = samples
            .iter()
            .map(|q| {
                q.iter()
                    .map(|l| l.iter().map(|v| v.to_f64()).collect())
                    .collect()
            })
            .collect();
        let usable = |q: usize| -> usize {
            // times where every level has a value
            low[q]
                .iter()
                .map(|l| l.iter().take_while(|v| v.is_finite()).count())
                .min()
                .unwrap_or(0)
        };
        let nuse = usable(0);
        let ords: Vec<Option<f64>> = (0..getters.len())
            .map(|q| {
                if self.runs.len() < 3 {
                    return None;
                }
                let s = &low[q];
                order(&s[0][..nuse], &s[1][..nuse], &s[2][..nuse])
            })
            .collect();
        // the rows that take the conservative bound whatever the model: those while the
        // coarsest grid's contact spans less than one of its cells, and the last report time
        // (h, a step's own value, excepted; b and the force too where their crossing fits
        // there take whole windows)
        let coarsest = &self.runs[self.runs.len() - 1];
        let coarse_contact: Vec<bool> = (0..times.len())
            .map(|i| {
                coarsest
                    .edge_at(step_at(coarsest, i))
                    .is_none_or(|b| b < coarsest.dx)
            })
            .collect();
        // with the start on finer grids every level resolves the early contact on the start's
        // cells, so the coarse contact's rows keep the sharp estimate; there the work and the
        // energy defect take the conservative bound at the first report time (the start's
        // own first steps, whose defect the coarser levels see only merged)
        let started =
            self.case.starts_finer() && self.case.start_halvings >= crate::solve::START_HALVINGS;
        // b's and the force's last rows are one-sided crossing fits unless every level
        // marched past the end (`Run::beyond`) or left the contact before it
        let whole_windows_at_end = self.runs.iter().all(Run::last_reports_centred);
        let last_conservative = |q: usize, i: usize| {
            i + 1 == times.len()
                && q != Q_H
                && !(whole_windows_at_end && (q == Q_B || q == Q_FORCE))
        };
        let conservative_row = |q: usize, i: usize| {
            if started {
                (i == 0 && (q == Q_WORK || q == Q_DEFECT)) || last_conservative(q, i)
            } else {
                coarse_contact[i] || last_conservative(q, i)
            }
        };
        // the rows whose free edge is captured cell by cell (`docs/impact.md`, section 4):
        // faster than FREE_EDGE_SPEED c_R (below c1), or everywhere without the edge model;
        // there the levels may agree on an edge a fraction of a cell off, and b's estimate
        // is at least half the finest cell
        // the finest grid's edge speed at each report time: the centred difference over one
        // report interval either side (the reported bdot)
        let bdot: Vec<T> = (0..times.len())
            .map(|i| {
                let b = &samples[2][0];
                let (a, c) = (i.saturating_sub(1), (i + 1).min(times.len() - 1));
                if c > a {
                    (b[c] - b[a]) / (times[c] - times[a])
                } else {
                    zero
                }
            })
            .collect();
        let whole_cell_edge: Vec<bool> = {
            let free = self.case.law == EdgeLaw::Signorini
                && !matches!(self.case.profile, crate::profile::Profile::Flat { .. });
            let modelled = self.case.edge_gap_scale(self.m.to_f64()).is_some();
            let fast = crate::march::FREE_EDGE_SPEED * self.s_r.to_f64();
            bdot.iter()
                .map(|v| {
                    let speed = v.abs().to_f64();
                    free && (!modelled || (speed > fast && speed < 1.0))
                })
                .collect()
        };
        let half_cell = 0.5 * fine.dx.to_f64();
        // the sharp estimator where three levels show an order and the sweep measured it
        let sharp = |q: usize| -> Option<(SharpPolicy, f64)> {
            let policy = if started {
                started_policy(q)
            } else {
                plain_policy(q)
            }?;
            let p = ords[q].filter(|p| *p > ORDER_SHOWN)?;
            Some((policy, p.min(policy.order_cap)))
        };
        // the estimate of history q at row i, and whether it took the order the window's
        // rows show one by one
        let est_with = |q: usize, i: usize| -> Option<(f64, bool)> {
            if self.runs.len() < 2 {
                return None;
            }
            // the level differences over the neighbouring report times, and the coarser
            // pair scaled down by the order credited
            let credited = sharp(q).filter(|_| !conservative_row(q, i));
            let coarse_scale = credited.map_or(0.5, |(_, p)| 0.5f64.powf(p.max(1.0)));
            let window =
                i.saturating_sub(ESTIMATE_WINDOW)..(i + ESTIMATE_WINDOW + 1).min(nuse.max(i + 1));
            // the differences in T, then rounded
            let d1 = |j: usize| (samples[q][0][j] - samples[q][1][j]).to_f64();
            let d2 = |j: usize| {
                samples[q]
                    .get(2)
                    .map(|c| (samples[q][1][j] - c[j]).to_f64())
            };
            let mut d: f64 = 0.0;
            for j in window.clone() {
                d = d.max(d1(j).abs());
                if let Some(d2) = d2(j) {
                    d = d.max(coarse_scale * d2.abs());
                }
            }
            if !d.is_finite() {
                return None;
            }
            let floor = if q == Q_B && whole_cell_edge[i] {
                half_cell
            } else {
                0.0
            };
            let policy_estimate = match credited {
                // Richardson with the observed order up to the cap
                Some((policy, p)) => policy.safety * d * richardson_factor(p),
                // the conservative bound: no order above one credited
                None => ESTIMATE_SAFETY * d * conservative_factor(ords[q]),
            };
            // Richardson at the order the rows show one by one, where the policy takes it
            let shown = credited
                .and_then(|(policy, _)| policy.shown_safety)
                .zip(ords[q])
                .filter(|_| samples[q].len() >= 3)
                .and_then(|(safety, p)| {
                    shown_order_estimate(
                        window.clone().map(d1),
                        window.clone().map(|j| d2(j).unwrap_or(f64::NAN)),
                        p,
                        safety,
                    )
                })
                .filter(|e| *e < policy_estimate);
            Some(match shown {
                Some(e) => (floor.max(e), true),
                None => (floor.max(policy_estimate), false),
            })
        };
        // every history's estimates, formed once: the rows and the error models read them
        let estimates: Vec<Vec<Option<(f64, bool)>>> = (0..getters.len())
            .map(|q| (0..times.len()).map(|i| est_with(q, i)).collect())
            .collect();
        let est = |q: usize, i: usize| estimates[q][i].map(|(e, _)| e);
        let order_shown = |q: usize, policy: SharpPolicy| {
            let rows = estimates[q][..nuse.min(times.len())]
                .iter()
                .filter(|e| e.is_some_and(|(_, shown)| shown))
                .count();
            let (safety, p) = policy.shown_safety.zip(ords[q])?;
            (rows > 0).then(|| OrderShown {
                rows,
                safety,
                order_credited: p.clamp(1.0, ORDER_SCHEME),
            })
        };
        let conservative_rows =
            |q: usize| (0..times.len()).filter(|&i| conservative_row(q, i)).count();
        let cell_floor_rows = whole_cell_edge.iter().filter(|c| **c).count();
        let model = |q: usize| -> ErrorModel {
            let cell_floor_rows = if q == Q_B { cell_floor_rows } else { 0 };
            // the sharp estimator where at least one row took it
            let conservative = conservative_rows(q);
            match sharp(q).filter(|_| conservative < times.len()) {
                Some((policy, p)) => ErrorModel {
                    estimator: Estimator::Richardson,
                    safety: policy.safety,
                    order_credited: Some(p),
                    conservative_rows: conservative,
                    cell_floor_rows,
                    order_shown: order_shown(q, policy),
                },
                None => ErrorModel {
                    estimator: Estimator::Conservative,
                    safety: ESTIMATE_SAFETY,
                    order_credited: ords[q].filter(|p| *p > 0.0).map(|p| p.min(1.0)),
                    conservative_rows: times.len(),
                    cell_floor_rows,
                    order_shown: None,
                },
            }
        };
        let models = (self.runs.len() >= 2).then(|| Models {
            h: model(Q_H),
            hdot: model(Q_HDOT),
            b: model(Q_B),
            force: model(Q_FORCE),
            work: model(Q_WORK),
            energy_defect: model(Q_DEFECT),
            others: ErrorModel::conservative(times.len()),
        });
        let mut rows = Vec::with_capacity(times.len());
        for (i, &t) in times.iter().enumerate() {
            let st = &fine.steps[step_at(fine, i) - 1];
            let val = |q: usize, scale: T| Value {
                value: samples[q][0][i] * scale,
                error: if i < nuse {
                    est(q, i).map(|e| e * scale.to_f64().abs())
                } else {
                    None
                },
                kind: ErrorKind::Refinement,
            };
            let bdot = bdot[i];
            let speed = bdot.abs();
            let stage = if speed > 1.0 {
                Stage::Supersonic
            } else if speed > self.m {
                Stage::Transonic
            } else if speed > self.s_r {
                Stage::RayleighShear
            } else {
                Stage::SubRayleigh
            };
            let one = T::of(1.0);
            let hdot_scale = match self.case.drive {
                Drive::Free { v0_over_c1, .. } => one / v0_over_c1,
                _ => one,
            };
            let kinetic = self.kinetic(st.v).map(|k| {
                let e = match (est(1, i), self.mass) {
                    (Some(dv), Some(mass)) => Some((mass * st.v.abs() * m2).to_f64() * dv),
                    _ => None,
                };
                Value {
                    value: k,
                    error: if i < nuse { e } else { None },
                    kind: ErrorKind::Refinement,
                }
            });
            // the work's own level differences, and never below the kinetic energy's
            // estimate (what the striker loses, the half-plane takes up)
            let work = {
                let own = val(7, m2).error;
                let lost = kinetic.and_then(|k| k.error);
                Value {
                    value: st.work * m2,
                    error: match (own, lost) {
                        (Some(a), Some(b)) => Some(a.max(b)),
                        (a, b) => a.or(b),
                    },
                    kind: ErrorKind::Refinement,
                }
            };
            let deformable = !matches!(self.case.striker, Striker::Rigid);
            // under Signorini's law the continuum's defect is exactly 0, so the defect is its
            // own error and its estimate is never below it (`docs/impact.md`, section 9)
            let defect = energy.map(|_| {
                let mut d = val(6, one);
                if self.case.law == EdgeLaw::Signorini {
                    let own = d.value.to_f64().abs();
                    d.error = Some(d.error.map_or(own, |e| e.max(own)));
                }
                d
            });
            rows.push(HistoryRow {
                energy_defect: defect,
                striker_deformation: deformable.then(|| val(4, one)),
                striker_energy: deformable.then(|| val(5, m2)),
                t,
                h: val(0, one),
                hdot: val(1, hdot_scale),
                b: val(2, one),
                bdot,
                stage,
                force: {
                    // under Signorini's law the force pushes: a fit through the steps'
                    // forces (all >= 0) may dip below zero where the contact ends
                    let mut f = val(3, m2);
                    if self.case.law == EdgeLaw::Signorini && f.value < 0.0 {
                        f.value = T::of(0.0);
                    }
                    f
                },
                kinetic,
                work,
            });
        }
        (
            rows,
            Orders {
                h: ords[0],
                b: ords[2],
                force: ords[3],
                models,
            },
        )
    }

    /// Pressure profile p/(rho c1^2) of the finest grid's step whose middle is nearest to
    /// c1 t/R = `t` (a step's pressures stand for the middle of the step, `docs/impact.md`,
    /// section 3): (that time, the cell centres x/R, the pressures).
    pub fn pressure_at(&self, t: f64) -> Option<(T, Vec<T>, Vec<T>)> {
        self.pressure_profile(t).map(|p| (p.t, p.x, p.p))
    }

    /// The pressure profile of [`SolvedImpact::pressure_at`] with an error estimate per cell
    /// (`docs/impact.md`, section 5), from the next coarser grid (none with one level). The
    /// finest grid's two steps that make up the coarser grid's step (the same middle time)
    /// are averaged and taken to the coarser cells ([`coarse_means`]); e_j is four times the
    /// largest difference |coarse - fine| over the coarser cells within one cell of cell j,
    /// plus what that comparison cannot see: the cell's second difference
    /// |p_j - (p_{j-1} + p_{j+1})/2| (a cell-to-cell oscillation, which the coarser cells
    /// average out) and its difference from the two steps' mean (a step-to-step one).
    pub fn pressure_profile(&self, t: f64) -> Option<PressureProfile<T>> {
        let fine = &self.runs[0];
        let n = ((t / fine.dt.to_f64() + 0.5).round() as usize).clamp(1, fine.steps.len());
        let st = fine.steps.get(n - 1)?;
        let m2 = self.m * self.m;
        let x = (0..st.pressure.len()).map(|j| fine.dx * j as f64).collect();
        let p: Vec<T> = st.pressure.iter().map(|&v| v * m2).collect();
        let zero = T::of(0.0);
        let err = self.runs.get(1).and_then(|coarse| {
            // the coarse step m spans the fine steps 2m - 1 and 2m (at the end of a run with
            // an odd number of fine steps, the last whole pair: the difference of
            // step n from that pair then holds the change over one step)
            let m = n
                .div_ceil(2)
                .min(coarse.steps.len())
                .min(fine.steps.len() / 2);
            let cs = coarse.step(m)?;
            let (a, b) = (fine.step(2 * m - 1)?, fine.step(2 * m)?);
            let len = a.pressure.len().max(b.pressure.len()).max(p.len());
            let at = |v: &[T], j: usize| v.get(j).copied().unwrap_or(zero);
            let pair: Vec<T> = (0..len)
                .map(|j| (at(&a.pressure, j) + at(&b.pressure, j)) * 0.5)
                .collect();
            let agg = coarse_means(&pair, 2);
            let nc = agg.len().max(cs.pressure.len());
            let diff: Vec<f64> = (0..nc)
                .map(|k| ((at(&cs.pressure, k) - at(&agg, k)).abs() * m2).to_f64())
                .collect();
            Some(
                (0..p.len())
                    .map(|j| {
                        // the coarse cells overlapping fine cell j, and their neighbours
                        let lo = (j / 2).saturating_sub(1);
                        let hi = (j.div_ceil(2) + 1).min(nc - 1);
                        let d = diff[lo..=hi].iter().fold(0.0, |a: f64, v| a.max(*v));
                        let left = if j == 0 { at(&p, 1) } else { p[j - 1] };
                        let rough = (p[j] - (left + at(&p, j + 1)) * 0.5).abs();
                        let step = (p[j] - pair[j] * m2).abs();
                        ESTIMATE_SAFETY * d + (rough + step).to_f64()
                    })
                    .collect(),
            )
        });
        Some(PressureProfile {
            t: st.t - fine.dt * 0.5,
            x,
            p,
            err,
        })
    }
}

/// A deformable striker's energies after one step ([`SolvedImpact::striker_energies`]), over
/// rho c1^2 R^2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrikerEnergyStep {
    /// c1 t/R.
    pub t: f64,
    /// The strain energy.
    pub strain: f64,
    /// The vibration kinetic energy (in the frame of the mass centre).
    pub kinetic: f64,
    /// The estimate of the modal truncation's error (both energies).
    pub truncation: f64,
}

/// The highest frequency (units c2s/R) of the free disk's modes that carry a cylinder
/// striker's vibration energy: the kinetic energy converges like about 1/omega_max (its change
/// per doubling falls by 2.3 to 2.8 on the reference case; 0.8 percent of it from 16 to 32,
/// `docs/strikers.md` section 8), and the report adds twice the change from the modes below
/// half this frequency to its estimate.
pub const CYLINDER_MODES_BELOW: f64 = 24.0;

impl SolvedImpact<f64> {
    /// A deformable striker's strain and vibration kinetic energy over rho c1^2 R^2 after
    /// each step of the finest grid: the shell's by the
    /// modal recursion of [`shell_energies`] (independent of the coefficient tables; its
    /// truncation is in the coefficients' bound, so 0 here); the cylinder's vibration by the
    /// free disk's modes below [`CYLINDER_MODES_BELOW`] ([`DiskModes::energies`]), its strain
    /// the work done on its deformation less the vibration, and the truncation's estimate
    /// twice the change from the modes below half that frequency (`docs/strikers.md`, section
    /// 8). `None` for the other strikers.
    pub fn striker_energies(&self) -> Option<Result<Vec<StrikerEnergyStep>>> {
        let modes = match self.cylinder_modes() {
            Ok(m) => m,
            Err(e) => return Some(Err(e)),
        };
        self.run_striker_energies(&self.runs[0], modes)
    }

    /// The free disk's modes of a cylinder striker ([`CYLINDER_MODES_BELOW`]), once for
    /// every level; `None` for the other strikers.
    fn cylinder_modes(&self) -> Result<Option<&DiskModes>> {
        self.disk_modes
            .as_ref()
            .map(|r| r.as_ref().map_err(Clone::clone))
            .transpose()
    }

    fn run_striker_energies(
        &self,
        run: &Run,
        modes: Option<&DiskModes>,
    ) -> Option<Result<Vec<StrikerEnergyStep>>> {
        let m2 = self.m * self.m;
        let pressures =
            || -> Vec<Vec<f64>> { run.steps.iter().map(|s| s.pressure.clone()).collect() };
        match &self.case.striker {
            Striker::Shell(shell) => Some((|| {
                let ring = Ring::new(shell, self.m)?;
                let e = shell_energies(&ring, run.dx, run.dt, &pressures())?;
                Ok(run
                    .steps
                    .iter()
                    .zip(e)
                    .map(|(s, (u, k))| StrikerEnergyStep {
                        t: s.t,
                        strain: u * m2,
                        kinetic: k * m2,
                        truncation: 0.0,
                    })
                    .collect())
            })()),
            Striker::Cylinder(mat) => Some((|| {
                // the disk's units: pressures over mu_s, time c2s t/R, energies mu_s R^2
                let g = mat.shear_modulus_ratio(self.m);
                let scaled: Vec<Vec<f64>> = pressures()
                    .into_iter()
                    .map(|p| p.into_iter().map(|v| v / g).collect())
                    .collect();
                let modes = modes.ok_or_else(|| ImpactError::Step {
                    time: "0".into(),
                    reason: "the cylinder's modes were not computed".into(),
                })?;
                let dtau = run.dt * mat.c2_ratio;
                let all = modes.energies(run.dx, dtau, &scaled);
                let half = modes
                    .below(0.5 * CYLINDER_MODES_BELOW)
                    .energies(run.dx, dtau, &scaled);
                Ok(run
                    .steps
                    .iter()
                    .zip(all.iter().zip(&half))
                    .map(|(s, (e, h))| {
                        let kinetic = e.0 * g * m2;
                        let trunc = 2.0 * (e.0 - h.0).abs() * g * m2;
                        StrikerEnergyStep {
                            t: s.t,
                            strain: s.striker_work * m2 - kinetic,
                            kinetic,
                            truncation: trunc,
                        }
                    })
                    .collect())
            })()),
            _ => None,
        }
    }

    /// A deformable striker's (strain, vibration kinetic) energy over rho c1^2 R^2 at the
    /// times of `rows` (from [`SolvedImpact::history`]), each with an error estimate: four
    /// times the difference between the two finest levels (the factor of the history's
    /// estimates), plus the coefficients' bound and the modal truncation's estimate
    /// ([`SolvedImpact::striker_energies`]). `None` for the strikers without them.
    pub fn striker_energy_history(
        &self,
        rows: &[HistoryRow],
    ) -> Option<Result<Vec<(Value, Value)>>> {
        let modes = match self.cylinder_modes() {
            Ok(m) => m,
            Err(e) => return Some(Err(e)),
        };
        let fine = match self.run_striker_energies(&self.runs[0], modes)? {
            Ok(v) => v,
            Err(e) => return Some(Err(e)),
        };
        let coarse = match self
            .runs
            .get(1)
            .map(|r| self.run_striker_energies(r, modes))
        {
            Some(Some(Ok(v))) => Some(v),
            Some(Some(Err(e))) => return Some(Err(e)),
            _ => None,
        };
        let at = |list: &[StrikerEnergyStep], dt: f64, t: f64| -> Option<(f64, f64, f64)> {
            let n = (t / dt).round() as usize;
            (n >= 1)
                .then(|| list.get(n - 1).map(|e| (e.strain, e.kinetic, e.truncation)))
                .flatten()
        };
        let mut out = Vec::with_capacity(rows.len());
        for r in rows {
            let (u, k, trunc) = match at(&fine, self.runs[0].dt, r.t) {
                Some(v) => v,
                None => {
                    return Some(Err(ImpactError::Step {
                        time: format!("{:.6}", r.t),
                        reason: "no step of the finest grid at this report time".into(),
                    }))
                }
            };
            let floor = self.runs[0].coefficient_error * (u + k).abs() + trunc;
            let err = coarse.as_ref().and_then(|c| {
                at(c, self.runs[1].dt, r.t)
                    .map(|(uc, kc, _)| (4.0 * (u - uc).abs() + floor, 4.0 * (k - kc).abs() + floor))
            });
            out.push((
                Value {
                    value: u,
                    error: err.map(|e| e.0),
                    kind: ErrorKind::Refinement,
                },
                Value {
                    value: k,
                    error: err.map(|e| e.1),
                    kind: ErrorKind::Refinement,
                },
            ));
        }
        Some(Ok(out))
    }
}

impl<T: Scalar> SolvedImpact<T> {
    /// The intervals of c1 t/R over which a prescribed (kinematic) edge advanced faster than
    /// the Rayleigh wave and slower than c1, on the finest grid (the edge's speed over the last
    /// four steps, as the march takes it); empty under Signorini's law. A prescribed edge
    /// moving steadily at such speeds has no solution (`docs/edge.md`, section 5: the Rayleigh
    /// points inside the contact ask a second condition of the edge's one free amplitude), and
    /// the march's pressure near the edge does not converge there (`docs/impact.md`, section
    /// 8); the free edge has a solution at every speed.
    pub fn edge_without_solution(&self) -> Vec<(T, T)> {
        let mut out: Vec<(T, T)> = Vec::new();
        if self.case.law != EdgeLaw::Kinematic {
            return out;
        }
        let Some(run) = self.runs.first() else {
            return out;
        };
        let steps = &run.steps;
        let mut open: Option<T> = None;
        for n in 0..steps.len() {
            let t = steps[n].t;
            let speed = crate::march::recent_edge_speed(&steps[..=n], run.dt);
            let inside = speed > self.s_r && speed < 1.0;
            match (inside, open) {
                (true, None) => open = Some(t),
                (false, Some(from)) => {
                    out.push((from, steps[n - 1].t));
                    open = None;
                }
                _ => {}
            }
        }
        if let (Some(from), Some(last)) = (open, steps.last()) {
            out.push((from, last.t));
        }
        out
    }

    /// The largest force over rho c1^2 R on the finest grid, its time, and whether it is a
    /// peak: whether the force has turned down after it (the run's last force below
    /// [`PEAK_DROP`] times the largest, or the contact over). A largest force that is not a
    /// peak is the value at the end of a run whose force still rises.
    pub fn peak_force(&self) -> Option<(T, T, bool)> {
        let m2 = self.m * self.m;
        let run = &self.runs[0];
        let (f, t) = (1..=run.steps.len())
            .filter_map(|n| run.force_at(n).map(|f| (f * m2, run.steps[n - 1].t)))
            .max_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal))?;
        let last = run.force_at(run.steps.len()).map(|f| f * m2)?;
        let turned_down = last < f * PEAK_DROP || run.steps.last()?.pressure.is_empty();
        Some((f, t, turned_down))
    }
}

/// The share of the largest force the run's last force must fall below for the largest to
/// be reported as a peak ([`SolvedImpact::peak_force`]).
pub const PEAK_DROP: f64 = 0.99;

#[cfg(test)]
mod tests {
    use super::*;

    /// Three levels of a history Q(dx) = Q* + C dx^p + D dx^3 at dx = 1, 2, 4 over a
    /// window of report times (C varying slowly from row to row): (Q_1 - Q_2, Q_2 - Q_4)
    /// per row and the finest level's actual error.
    fn levels(p: f64, d: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let (mut d1, mut d2, mut err) = (Vec::new(), Vec::new(), Vec::new());
        for j in 0..9 {
            let c = 1e-5 * (1.0 + 0.05 * j as f64);
            let q = |dx: f64| c * dx.powf(p) + d * dx.powi(3);
            d1.push(q(1.0) - q(2.0));
            d2.push(q(2.0) - q(4.0));
            err.push(q(1.0).abs());
        }
        (d1, d2, err)
    }

    #[test]
    fn the_shown_order_estimate_is_safety_times_the_error_of_an_exact_order() {
        // an exactly second-order history: the estimate is the safety times the error
        let (d1, d2, err) = levels(2.0, 0.0);
        let e = shown_order_estimate(d1.iter().copied(), d2.iter().copied(), 2.0, 3.0)
            .expect("the rows show order 2");
        let worst = err.iter().copied().fold(0.0, f64::max);
        assert!((e / worst - 3.0).abs() < 1e-12, "{e} against {worst}");
        // an observed order above the scheme's is credited at 2 only
        let e3 = shown_order_estimate(d1.iter().copied(), d2.iter().copied(), 2.2, 3.0)
            .expect("the rows show order 2 within the tolerance");
        assert_eq!(e3, e);
        // first order: the rows' ratios are 2; an observed order below 1 is credited at 1
        let (d1, d2, err) = levels(1.0, 0.0);
        let e = shown_order_estimate(d1.iter().copied(), d2.iter().copied(), 0.8, 3.0)
            .expect("the rows show order 1");
        let worst = err.iter().copied().fold(0.0, f64::max);
        assert!((e / worst - 3.0).abs() < 1e-12, "{e} against {worst}");
    }

    #[test]
    fn the_shown_order_estimate_is_refused_where_a_row_does_not_show_it() {
        // the history's order is 2 but one row's ratio is 2^2.5 (a third-order part there)
        let (d1, mut d2, _) = levels(2.0, 0.0);
        d2[4] = d1[4] * 2f64.powf(2.5);
        assert!(shown_order_estimate(d1.iter().copied(), d2.iter().copied(), 2.0, 3.0).is_none());
        // one row's differences of opposite signs (the finest pair crossing zero)
        let (mut d1, d2, _) = levels(2.0, 0.0);
        d1[7] = -d1[7];
        assert!(shown_order_estimate(d1.iter().copied(), d2.iter().copied(), 2.0, 3.0).is_none());
        // a row where the finest pair agrees exactly
        let (mut d1, d2, _) = levels(2.0, 0.0);
        d1[0] = 0.0;
        assert!(shown_order_estimate(d1.iter().copied(), d2.iter().copied(), 2.0, 3.0).is_none());
        // a mixed history whose rows' ratio drifts from 4 towards 8 (the second-order part
        // no longer dominant on the coarse pair): refused
        let (d1, d2, _) = levels(2.0, 1e-5);
        assert!(shown_order_estimate(d1.iter().copied(), d2.iter().copied(), 2.0, 3.0).is_none());
        // a missing coarsest level (NaN)
        let (d1, _, _) = levels(2.0, 0.0);
        assert!(
            shown_order_estimate(d1.iter().copied(), d1.iter().map(|_| f64::NAN), 2.0, 3.0)
                .is_none()
        );
    }
}
