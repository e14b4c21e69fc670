//! Time marching of the contact integral equation on one uniform grid (`docs/impact.md`,
//! sections 2-4): eq (7) imposed on the cell means at the end of each step (the striker's G0
//! added to the half-plane's coefficients, `docs/strikers.md`),
//! the striker's equation of motion (5)/(8) integrated exactly for a force constant over the
//! step, the contact set from the edge law.
//!
//! Units inside: c1 = 1, mu = 1, lengths in R (so rho = 1/m^2, m = c2/c1).

use complexfn::quadrature::CachedRules;

use crate::case::Drive;
use crate::error::{ImpactError, Result};
use crate::history::{HistorySum, KernelRows};
use crate::linalg::{least_index_pivoting, Factor};
use crate::profile::Profile;
use crate::run::{HandoverDefect, Run};
use crate::scalar::Scalar;
use crate::tables::{ShapeRules, Tables};

mod edge;

pub(crate) use edge::{far_kernel_row, FAR_SERIES, FREE_EDGE_SPEED};
use edge::{SystemCache, TiedBasis};

/// The edge law (labelled in every output); shared with the edge analysis of `lamb::edge`.
pub use lamb::edge::EdgeLaw;

/// One time step's solution, at the march's precision T.
#[derive(Clone, Debug)]
pub struct StepState<T = f64> {
    /// Time t_n (units R/c1).
    pub t: T,
    /// Penetration h(t_n) (units R).
    pub h: T,
    /// dh/dt (units c1).
    pub v: T,
    /// Number of contact cells on one side minus one: cells 0..=k carry pressure (none when
    /// `pressure` is empty).
    pub k: usize,
    /// Contact half-width (units R) at the time `edge_time`: f^-1(h) for the kinematic law
    /// and a supersonic edge; for the Signorini law the free edge of the step's pressures
    /// (the local model's edge, or the zero of a square-root fit through the last two cell
    /// pressures where the edge is captured cell by cell).
    pub b: T,
    /// The time b stands for: t_n for a geometric edge, t_n - dt/2 for an edge the step's
    /// pressures set (they stand for the middle of the step, `docs/impact.md`, section 3).
    /// [`crate::run::Run::edge_at`] interpolates the edge to t_n.
    pub edge_time: T,
    /// Force per unit length R(t) (units mu R).
    pub force: T,
    /// Cell pressures p_0..p_k (units mu), constant over the step.
    pub pressure: Vec<T>,
    /// The half-plane's mean normal surface displacement over the cells at x_0, x_1, ... at
    /// t_n (units R), at least over the contact and one cell beyond.
    pub w: Vec<T>,
    /// The striker's mean surface displacement towards its interior over the same cells
    /// (empty for a rigid striker).
    pub ws: Vec<T>,
    /// Work done on the half-plane up to t_n, through the kernels (units mu R^2).
    pub work: T,
    /// Work done on the striker's deformation up to t_n (its strain and vibration energy).
    pub striker_work: T,
    /// For a step marched on a finer grid and merged onto this one (`docs/impact.md`,
    /// section 11): the finer grid's reported edge and force at t_n, which
    /// [`crate::run::Run::edge_at`] and [`crate::run::Run::force_at`] report as they are.
    pub finer: Option<(T, T)>,
}

/// The marching state on one grid, at the precision T (`crate::scalar`).
pub struct March<'a, T: Scalar + CachedRules = f64> {
    tables: &'a mut Tables<T>,
    /// The striker's compliance rows (none for a rigid striker).
    striker: Option<&'a mut dyn KernelRows<T>>,
    profile: &'a Profile,
    drive: &'a Drive,
    law: EdgeLaw,
    dx: T,
    dt: T,
    /// Largest admissible contact index (the profile's extent).
    kcap: usize,
    /// The steps so far.
    pub steps: Vec<StepState<T>>,
    /// The times the contact ended (the striker left the surface), in order: the end of the
    /// last step in contact (`docs/impact.md`, section 9).
    pub separations: Vec<T>,
    /// The times contact began again after a separation (re-impacts), in order.
    pub reimpacts: Vec<T>,
    /// The exact end time and its step: the last step's time is this value, not n dt rounded
    /// (the reported times end at the requested end exactly).
    end: Option<(usize, T)>,
    /// The memory limit (bytes): a march whose history grows beyond it ends with an error
    /// (`crate::cost`).
    memory: Option<f64>,
    /// The widest history width checked against the limit so far.
    checked_width: usize,
    /// The factor of the edge model's gap coefficient for the pair of bodies (1 for a
    /// rigid striker); `None` when the local model does not apply (a striker of other wave
    /// speeds or a shell): the edge is then captured cell by cell.
    edge_gap_scale: Option<T>,
    /// The defect the last hand-over left (`March::seed_handover`, [`HandoverDefect`]).
    pub handover: Option<HandoverDefect<T>>,
    /// The history sums of the half-plane's and the striker's displacements.
    history: HistorySum<T>,
    striker_history: Option<HistorySum<T>>,
    /// The factorised systems by number of contact cells (and the coupling they were built
    /// with).
    systems: std::cell::RefCell<SystemCache<T>>,
}

/// Bytes in a GiB.
const GIB: f64 = 1024.0 * 1024.0 * 1024.0;
/// The error of a step whose contact system is singular (or gives a non-finite solution).
fn singular_system<T: Scalar>(t: T) -> ImpactError {
    ImpactError::Step {
        time: format!("{:.6}", t.to_f64()),
        reason: "singular contact system".into(),
    }
}

/// A step's contact: (last contact cell, edge, cell pressures, force).
type StepSet<T> = (usize, T, Vec<T>, T);

/// Whether an edge is that of the step's middle (set by the step's pressures) rather than
/// of its end (geometric).
type MidStep = bool;

/// What every trial solve of one step shares.
struct StepData<T> {
    /// The half-plane's and the striker's displacements at the cells due to the past steps
    /// (the striker's empty when rigid).
    hist: (Vec<T>, Vec<T>),
    /// The profile's mean over the cells 0..=imax (`None` beyond its extent).
    fbar: Vec<Option<T>>,
    /// The penetration at the step's end before the step's own force.
    h_pred: T,
    /// The step's change of penetration per unit force (free striker; 0 when driven).
    coupling: T,
    /// The step's time.
    t: T,
}

impl<T: Scalar> StepData<T> {
    /// The profile's mean over cell i.
    fn fbar(&self, i: usize) -> Result<T> {
        self.fbar
            .get(i)
            .copied()
            .flatten()
            .ok_or_else(|| ImpactError::Step {
                time: format!("{:.6}", self.t.to_f64()),
                reason: "the contact reaches the end of the profile".into(),
            })
    }

    /// The approach the contact condition asks of cell i, h - mean f_i, less the past
    /// steps' displacements, for a step force `force`.
    fn target(&self, i: usize, force: T) -> Result<T> {
        Ok(self.h_pred - self.coupling * force - self.fbar(i)?)
    }
}

/// The edge's speed (units c1) over the last (up to four) of `steps`, which are at least one,
/// from their reported edges (the edge at t = 0 is 0): the speed the march takes for the edge
/// model of the next step, and the report for its edges without solution.
pub(crate) fn recent_edge_speed<T: Scalar>(steps: &[StepState<T>], dt: T) -> T {
    let n = steps.len();
    let q = n.clamp(1, 4);
    let before = if n > q {
        steps[n - 1 - q].b
    } else {
        T::of(0.0)
    };
    (steps[n - 1].b - before) / (dt * q as f64)
}

/// The most fixed-point iterations of one step on the force (kinematic law), in f64; in
/// proportion to the significand's bits at other precisions.
const ITERATIONS: usize = 50;

/// A relative tolerance stated for f64, scaled to the precision T (the same multiple of its
/// rounding unit).
fn tolerance<T: Scalar>(in_f64: f64) -> f64 {
    in_f64 * (T::of(1.0).epsilon().to_f64() / f64::EPSILON)
}

impl<'a, T: Scalar + CachedRules> March<'a, T> {
    /// A march with cell width dx and time step dt (the tables' kappa is dt/dx), with the
    /// striker's compliance (none for a rigid striker).
    pub(crate) fn new(
        tables: &'a mut Tables<T>,
        striker: Option<&'a mut dyn KernelRows<T>>,
        profile: &'a Profile,
        drive: &'a Drive,
        law: EdgeLaw,
        dx: T,
        dt: T,
    ) -> Self {
        let ext = profile.extent();
        let kcap = if ext.is_finite() {
            ((ext / dx.to_f64() - 0.5).floor().max(0.0)) as usize
        } else {
            usize::MAX / 4
        };
        March {
            tables,
            profile,
            drive,
            law,
            dx,
            dt,
            kcap,
            edge_gap_scale: striker.is_none().then(|| T::of(1.0)),
            history: HistorySum::new(dx, None),
            striker_history: striker.is_some().then(|| HistorySum::new(dx, None)),
            systems: std::cell::RefCell::new((T::of(f64::NAN), Vec::new())),
            striker,
            steps: Vec::new(),
            separations: Vec::new(),
            reimpacts: Vec::new(),
            end: None,
            memory: None,
            checked_width: 0,
            handover: None,
        }
    }

    /// Limits the memory the march's history holds to `bytes`, checked at every step for its
    /// steps so far and widest contact (`crate::cost::BYTES_PER_CELL_STEP` per step and cell of
    /// the history's width).
    pub(crate) fn with_memory_limit(mut self, bytes: Option<f64>) -> Self {
        self.memory = bytes;
        self
    }

    /// Ends the march's time levels at `end` exactly after `steps` steps (the step's time
    /// there is `end`, not `steps` dt rounded).
    pub(crate) fn with_end(mut self, steps: usize, end: T) -> Self {
        self.end = Some((steps, end));
        self
    }

    /// The time t_n of step n.
    pub fn time(&self, n: usize) -> T {
        match self.end {
            Some((last, end)) if n == last => end,
            _ => self.dt * n as f64,
        }
    }

    /// Whether the striker is off the surface after the last step, having been in contact
    /// before.
    pub fn separated(&self) -> bool {
        !self.separations.is_empty() && self.steps.last().is_some_and(|s| s.pressure.is_empty())
    }

    /// Limits the march to `steps` steps, so that the history sum accumulates nothing for
    /// later steps (a step beyond is refused).
    pub(crate) fn with_horizon(mut self, steps: usize) -> Self {
        self.history.set_horizon(steps);
        if let Some(h) = self.striker_history.as_mut() {
            h.set_horizon(steps);
        }
        self
    }

    /// Sets the factor of the edge model's gap coefficient (`None`: no edge model).
    pub(crate) fn with_edge_gap_scale(mut self, scale: Option<T>) -> Self {
        self.edge_gap_scale = scale;
        self
    }

    /// Time step.
    pub fn dt(&self) -> T {
        self.dt
    }

    /// The half-bandwidth of the current step's coefficients (the kernels are causal: a cell
    /// loaded over one step reaches the cells within c dt of it, c the fastest wave), `None`
    /// when the striker's response is not local (a shell).
    fn reach(&self) -> Option<usize> {
        let hp = self.tables.reach_at(0);
        match self.striker.as_deref() {
            Some(s) => s.reach(0).map(|r| r.max(hp)),
            None => Some(hp),
        }
    }

    fn weight(&self, j: usize) -> T {
        if j == 0 {
            self.dx
        } else {
            self.dx * 2.0
        }
    }

    /// Displacements at t_n (n = steps.len() + 1) at x_0..x_imax due to all past steps: the
    /// half-plane's and the striker's (empty for a rigid striker), from the fast history sums
    /// (`crate::history`).
    fn history(&mut self, n: usize, imax: usize) -> Result<(Vec<T>, Vec<T>)> {
        debug_assert_eq!(self.history.len() + 1, n);
        let kmax = self.steps.iter().map(|s| s.k).max().unwrap_or(0).max(imax);
        // the current step's coefficients (lag 0)
        self.tables.ensure(2 * kmax + 2, 0)?;
        if let Some(s) = self.striker.as_deref_mut() {
            s.ensure_rows(2 * kmax + 2, 0)?;
        }
        let hist = self.history.at(&mut *self.tables, imax)?;
        let hist_s = match (self.striker.as_deref_mut(), self.striker_history.as_mut()) {
            (Some(s), Some(h)) => h.at(s, imax)?,
            _ => Vec::new(),
        };
        Ok((hist, hist_s))
    }

    /// The current step's coefficient of the half-plane and of the striker.
    fn current_parts(&self, i: usize, j: usize) -> (T, T) {
        let pair = |row: &[T]| {
            if j > 0 {
                row[i.abs_diff(j)] + row[i + j]
            } else {
                row[i]
            }
        };
        let hp = pair(self.tables.row(0)) * self.dx;
        let st = match self.striker.as_deref() {
            Some(s) => {
                let (row, scale) = s.scaled_row(0);
                pair(row) * scale * self.dx
            }
            None => T::of(0.0),
        };
        (hp, st)
    }

    fn current(&self, i: usize, j: usize) -> T {
        let (a, b) = self.current_parts(i, j);
        a + b
    }

    /// Solves the step with contact cells 0..=k: returns (pressures, force).
    fn solve_set(&self, d: &StepData<T>, k: usize) -> Result<(Vec<T>, T)> {
        // cell k + 1 tied with a zero ratio carries nothing
        let (mut p, f) = self.solve_tied(d, k + 1, T::of(0.0))?;
        p.pop();
        Ok((p, f))
    }

    /// The half-plane's and the striker's displacement at x_i at t_n from the histories and
    /// the current pressures (the striker's 0 when rigid).
    fn displacements(&self, i: usize, hist: &(Vec<T>, Vec<T>), p: &[T]) -> (T, T) {
        let (mut a, mut b) = (hist.0[i], hist.1.get(i).copied().unwrap_or(T::of(0.0)));
        // the current step's cells reach |i - j| <= reach (the mirror terms i + j <= reach
        // lie inside that range)
        let near = match self.reach() {
            Some(r) => i.saturating_sub(r)..(i + r + 1).min(p.len()),
            None => 0..p.len(),
        };
        for (j, v) in p.iter().enumerate().take(near.end).skip(near.start) {
            let (ca, cb) = self.current_parts(i, j);
            a += ca * *v;
            b += cb * *v;
        }
        (a, b)
    }

    /// The total approach w + w_s at x_i at t_n.
    fn displacement(&self, i: usize, hist: &(Vec<T>, Vec<T>), p: &[T]) -> T {
        let (a, b) = self.displacements(i, hist, p);
        a + b
    }

    /// The data of step n over the cells 0..=imax: the history sums (less the last
    /// hand-over's defect while it lasts) and the profile's cell means.
    fn step_data(
        &mut self,
        n: usize,
        imax: usize,
        h_pred: T,
        coupling: T,
        t: T,
    ) -> Result<StepData<T>> {
        let mut hist = self.history(n, imax)?;
        if let Some(handover) = &self.handover {
            let weight = handover.weight(n);
            if weight > 0.0 {
                for (i, h) in hist.0.iter_mut().enumerate() {
                    *h -= handover.at(i) * weight;
                }
            }
        }
        Ok(StepData {
            hist,
            fbar: (0..=imax).map(|i| self.profile_mean(i)).collect(),
            h_pred,
            coupling,
            t,
        })
    }

    /// Advances one step. Returns whether the striker is in contact at the step's end. Off
    /// the surface the striker flies free (a free striker keeps its speed) and the march goes
    /// on: the contact conditions are tried at every step, so a re-impact is found
    /// (`docs/impact.md`, section 9).
    pub fn step(&mut self) -> Result<bool> {
        let n = self.steps.len() + 1;
        let t = self.time(n);
        let dt = self.dt;
        let zero = T::of(0.0);
        let (h0, v0, k0) = match self.steps.last() {
            Some(s) => (s.h, s.v, s.k),
            None => match self.drive {
                Drive::Free { v0_over_c1, .. } => (zero, T::input(*v0_over_c1), 0),
                _ => (zero, zero, 0),
            },
        };
        let m = *self.tables.half_plane().m();
        let (h_pred, coupling, mass) = match (self.drive.driven_h(t), self.drive.mass(m)) {
            (Some(h), _) => (h, zero, T::of(f64::INFINITY)),
            (None, Some(mass)) => (h0 + dt * v0, dt * dt / (mass * 2.0), mass),
            (None, None) => unreachable!("a driven striker always gives h"),
        };
        let profile = self.profile;
        let kin = move |h: T| profile.kinematic_edge(h);
        let kin_b = kin(h_pred).ok_or_else(|| ImpactError::Step {
            time: format!("{:.6}", t.to_f64()),
            reason: "the penetration exceeds the profile's extent".into(),
        })?;
        let dxv = self.dx;
        let kin_k = move |b: T| -> usize { ((b / dxv).to_f64().ceil() as usize).saturating_sub(1) };
        // the cell containing an edge b: x_c - dx/2 <= b < x_c + dx/2
        let edge_cell = move |b: T| -> usize { (b / dxv + 0.5).to_f64().floor().max(0.0) as usize };
        let b_prev = self.steps.last().map(|s| s.b).unwrap_or(zero);
        let model = self.edge_model(kin_b)?;
        let signorini = matches!(self.law, EdgeLaw::Signorini);
        // a free edge that has left the supersonic stage returns to it only where the
        // geometric edge itself outruns c1 over the step (`docs/impact.md`, section 4, the
        // supersonic stage's end): the edge model's speed, over the last reported edges,
        // scatters by several percent where the edge is captured cell by cell, and an edge
        // just below c1 read as supersonic at one step and subsonic at the next had locked
        // into a cycle of geometric and free steps
        let left_supersonic = self
            .steps
            .last()
            .is_some_and(|s| !s.pressure.is_empty() && s.edge_time != s.t);
        let outruns = || kin(h0).is_some_and(|b0| kin_b - b0 > dt);
        let geometric = !signorini
            || (matches!(model, Some(m) if m.geometric) && (!left_supersonic || outruns()));
        let sub_cell = matches!(model, Some(m) if m.sub_cell) && edge_cell(b_prev) >= 2;
        // the cells whose contact conditions the step checks (`docs/impact.md`, section 9,
        // the contact's window): the last contact and three cells beyond it, and where the
        // contact is found among whole cells and one step reaches further than three cells
        // (kappa > 3) the reach of one step more (an edge below c1 advances by at most kappa
        // cells a step; the window widens below while the contact reaches its end); the
        // kinematic edge and the last edge's cell with three more
        let reach = self.tables.reach_at(0);
        let ahead = if geometric || sub_cell || reach <= 3 {
            0
        } else {
            reach
        };
        let base = (k0 + 3)
            .max(kin_k(kin_b) + 3)
            .max(edge_cell(b_prev) + 3)
            .min(self.kcap + 2);
        let mut imax = base.max((k0 + 3 + ahead).min(self.kcap + 2));
        if let Some(limit) = self.memory {
            // the memory the history holds at this step, for its widest contact so far
            let width = (imax + 1)
                .next_power_of_two()
                .max(8)
                .max(self.checked_width);
            self.checked_width = width;
            let bytes = crate::cost::BASE_BYTES
                + crate::cost::BYTES_PER_CELL_STEP * n as f64 * width as f64;
            if bytes > limit {
                return Err(ImpactError::Grid {
                    name: "dx",
                    reason: format!(
                        "at c1 t/R = {:.4} (step {n}, the contact over {imax} cells) the history holds about {:.1} GiB, the memory limit (raise --dx, shorten --end, or pass --force)",
                        t.to_f64(),
                        bytes / GIB
                    ),
                });
            }
        }
        let mut data = self.step_data(n, imax, h_pred, coupling, t)?;
        let mut set = None;
        // whether a branch below has settled the step's contact (else: the active set of
        // whole cells, which can shrink the contact to nothing)
        let mut settled = false;
        match (geometric, model) {
            (true, _) => {
                let mut f_est = zero;
                // the tied basis of the edge cell, the same while the edge stays in it
                let mut kept: Option<(usize, TiedBasis<T>)> = None;
                for _ in 0..ITERATIONS * T::BITS as usize / 53 {
                    let h = h_pred - coupling * f_est;
                    let b = kin(h).unwrap_or(zero);
                    if b <= 0.0 {
                        break;
                    }
                    let c = edge_cell(b).min(self.kcap);
                    let (k, p, f) = match model {
                        Some(m) if c >= 2 && c <= imax => {
                            let theta = (b / dxv + (0.5 - c as f64)).max(zero).min(T::of(1.0));
                            let (ratio, _) = m.tie(theta, dxv, c, None);
                            // the cells behind the edge carry the shape correction of
                            // their conditions, as behind a free edge
                            if kept.as_ref().is_none_or(|(kc, _)| *kc != c) {
                                kept = Some((c, self.tied_basis(&data, c)?));
                            }
                            let basis = kept
                                .as_ref()
                                .map(|(_, b)| b)
                                .ok_or_else(|| singular_system(data.t))?;
                            let q = self.behind_corrections(&m, theta, c, basis);
                            let (p, f) =
                                self.tied_solution_with(&data, basis, c, ratio, Some(&q))?;
                            (c, p, f)
                        }
                        _ => {
                            let k = kin_k(b).min(self.kcap);
                            if k + 1 > imax {
                                // a tensile force raised h, and the edge, past the cells
                                // considered (a light striker's fixed point): they widen
                                imax = (k + 4).min(self.kcap + 2);
                                data = self.step_data(n, imax, h_pred, coupling, t)?;
                                kept = None;
                            }
                            let (p, f) = self.solve_set(&data, k)?;
                            (k, p, f)
                        }
                    };
                    let done = (f - f_est).abs() <= f.abs() * tolerance::<T>(1e-14);
                    f_est = f;
                    set = Some(((k, b, p, f), false));
                    if done {
                        break;
                    }
                }
                // the kinematic law imposes its contact whatever the pressure's sign; under
                // Signorini's a geometric (supersonic) edge stands only while every cell
                // pushes
                settled = !signorini
                    || set
                        .as_ref()
                        .is_some_and(|((_, _, p, _), _): &(StepSet<T>, MidStep)| {
                            p.iter().all(|v| *v >= 0.0)
                        });
                if !settled {
                    set = None;
                }
            }
            (false, Some(m)) if sub_cell => {
                if let Some(s) = self.free_edge(&data, m, edge_cell(b_prev))? {
                    set = Some((s, true));
                    settled = true;
                }
            }
            _ => {}
        }
        if !settled {
            // a contact that reaches the window's last cells may go on beyond them (cells
            // the conditions did not see could interpenetrate, and their entry later would
            // put energy in): the window widens by the reach and the contact is found again
            loop {
                let found = self.whole_cells(&data, k0.min(self.kcap), imax)?;
                let top = imax.min(self.kcap).min(data.fbar.len() - 1);
                match found {
                    Some((k, ..)) if ahead > 0 && k + 3 > top && top < self.kcap => {
                        imax = (imax + reach + 3).min(self.kcap + 2);
                        data = self.step_data(n, imax, h_pred, coupling, t)?;
                    }
                    found => {
                        set = found.map(|f| (f, true));
                        break;
                    }
                }
            }
        }
        let hist = &data.hist;
        let in_contact = set.is_some();
        let was_in_contact = self.steps.last().is_some_and(|s| !s.pressure.is_empty());
        if was_in_contact && !in_contact {
            // the contact ended within the step: its pressures vanish from the middle of
            // this step, the last step's stood for the middle of that one
            self.separations.push(t - dt);
        } else if in_contact && !was_in_contact && !self.separations.is_empty() {
            self.reimpacts.push(t - dt);
        }
        let ((k, b, p, f), mid_step): (StepSet<T>, MidStep) =
            set.unwrap_or(((0, zero, Vec::new(), zero), false));
        let (h, v) = match self.drive.driven_h(t) {
            Some(h) => {
                let hp = self.drive.driven_h(t - dt).unwrap_or(zero);
                (h, (h - hp) / dt)
            }
            None => (
                h0 + dt * v0 - dt * dt * f / (mass * 2.0),
                v0 - dt * f / mass,
            ),
        };
        // the displacements kept for the next step (its work and its edge's mid-step gap):
        // over the cells the narrower window would have held, and three beyond the contact
        let kept_to = base.max(p.len() + 2).min(imax);
        let (w, ws): (Vec<T>, Vec<T>) = (0..=kept_to)
            .map(|i| self.displacements(i, hist, &p))
            .unzip();
        let ws = if self.striker.is_some() {
            ws
        } else {
            Vec::new()
        };
        let prev = self.steps.last();
        let prev_w = prev.map(|s| s.w.as_slice()).unwrap_or(&[]);
        let prev_ws = prev.map(|s| s.ws.as_slice()).unwrap_or(&[]);
        let (mut dwork, mut dwork_s) = (zero, zero);
        for (j, &pj) in p.iter().enumerate() {
            let before = prev_w.get(j).copied().unwrap_or(zero);
            dwork += self.weight(j) * pj * (w[j] - before);
            if let Some(&now) = ws.get(j) {
                let before = prev_ws.get(j).copied().unwrap_or(zero);
                dwork_s += self.weight(j) * pj * (now - before);
            }
        }
        let work = prev.map(|s| s.work).unwrap_or(zero) + dwork;
        let striker_work = prev.map(|s| s.striker_work).unwrap_or(zero) + dwork_s;
        if !(h.is_finite() && v.is_finite() && f.is_finite()) {
            return Err(ImpactError::Step {
                time: format!("{:.6}", t.to_f64()),
                reason: "a non-finite penetration or force".into(),
            });
        }
        // a mean contact pressure above 2 rho c1^2 (strains of order one; a plane wave at the
        // speed c1 carries rho c1^2), or above that times twice the profile's mean slope over
        // the contact, h/f^-1(h), where it is steeper than 1/2 (a sharp wedge's static
        // pressure grows with its slope), is a march gone unstable, not a result
        // (`docs/impact.md`, section 9, the force's bound)
        let width = b.max(kin_b).max(zero) + self.dx;
        let slope = if kin_b > 0.0 { h.abs() / kin_b } else { zero };
        // rho c1^2 in the march's units of mu
        let rho_c1sq = T::of(1.0) / (m * m);
        let bound = width * rho_c1sq * 4.0 * (slope * 2.0).max(T::of(1.0));
        if f.abs() > bound {
            return Err(ImpactError::Step {
                time: format!("{:.6}", t.to_f64()),
                reason: format!(
                    "the force reached {:.3e} rho c1^2 R over a contact of half-width {:.3e} R, a mean pressure above 2 rho c1^2 (strains of order one) and the profile's slope allows: the march has gone unstable, as it does on nearly incompressible half-planes (poisson = {:.4}) under the kinematic law or driven (docs/impact.md, section 9): lower --poisson",
                    (f / rho_c1sq).to_f64(),
                    width.to_f64(),
                    self.tables.half_plane().poisson().to_f64()
                ),
            });
        }
        self.history.push(&mut *self.tables, &p)?;
        if let (Some(s), Some(hs)) = (self.striker.as_deref_mut(), self.striker_history.as_mut()) {
            hs.push(s, &p)?;
        }
        self.steps.push(StepState {
            t,
            h,
            v,
            k,
            b,
            edge_time: if mid_step { t - dt * 0.5 } else { t },
            force: f,
            pressure: p,
            w,
            ws,
            work,
            striker_work,
            finer: None,
        });
        Ok(in_contact)
    }

    /// Takes the last step a finer grid hands over ([`March::seed`]) with the defect of this
    /// grid's displacements there (`docs/impact.md`, section 11): this grid's kernels applied
    /// to the merged pressures miss the merged displacements, which meet the contact
    /// conditions, by its own discretisation error, which its next steps would otherwise
    /// take up at once, a jump of the pressures. The defect of each cell inside the step's
    /// contact (behind its last contact cell's neighbour), and beyond them the last one's, is
    /// taken off this grid's history sums at the next steps with the weight (1 - m/K)^2 at
    /// the m-th, K = `decay_steps` (none below one step).
    pub(crate) fn seed_handover(&mut self, s: StepState<T>, decay_steps: f64) -> Result<()> {
        let inside = s.k.saturating_sub(1).min(s.w.len());
        if inside > 0 && decay_steps >= 1.0 {
            let n = self.steps.len() + 1;
            let imax = s.w.len().max(s.pressure.len()) - 1;
            let hist = self.history(n, imax)?;
            let defect = (0..inside)
                .map(|i| self.displacements(i, &hist, &s.pressure).0 - s.w[i])
                .collect();
            self.handover = Some(HandoverDefect {
                step: n,
                defect,
                decay_steps,
            });
        }
        self.seed(s)
    }

    /// Takes step n + 1 as solved on a finer grid and merged onto this one
    /// ([`merge_onto_coarser`], `docs/impact.md`, section 11): its pressures enter the history
    /// sums as if marched, its state is the next step's start.
    pub(crate) fn seed(&mut self, s: StepState<T>) -> Result<()> {
        self.tables.ensure(2 * s.pressure.len() + 2, 0)?;
        self.history.push(&mut *self.tables, &s.pressure)?;
        if let (Some(k), Some(hs)) = (self.striker.as_deref_mut(), self.striker_history.as_mut()) {
            hs.push(k, &s.pressure)?;
        }
        if s.pressure.is_empty() && self.steps.last().is_some_and(|p| !p.pressure.is_empty()) {
            self.separations.push(s.t - self.dt);
        }
        self.steps.push(s);
        Ok(())
    }

    /// The contact among whole cells (`docs/impact.md`, section 9): the linear
    /// complementarity problem of the step's cells 0..=min(imax, kcap), p >= 0 on the contact
    /// cells, mean gap >= 0 on the others, one of the two zero on each, solved by Murty's
    /// least-index principal pivoting from the previous step's contact 0..=k0: the first cell
    /// that pulls or interpenetrates changes side, until none does. The contact need not be
    /// one interval (the middle of a flat punch may lift off while its edges push). Returns
    /// (last contact cell, edge, pressures with zeros off the contact, force), or `None`
    /// without contact.
    fn whole_cells(&self, d: &StepData<T>, k0: usize, imax: usize) -> Result<Option<StepSet<T>>> {
        let top = imax.min(self.kcap).min(d.fbar.len() - 1);
        let zero = T::of(0.0);
        let start = Some(k0.min(top));
        let settled = least_index_pivoting(
            top,
            start,
            |cells: &[usize]| match cells.last() {
                Some(_) => self.solve_cells(d, cells),
                None => Ok((Vec::new(), zero)),
            },
            |(p, f): &(Vec<T>, T), i, inside| {
                if inside {
                    p[i] < 0.0
                } else {
                    match d.target(i, *f) {
                        Ok(target) => self.displacement(i, &d.hist, p) - target < 0.0,
                        // beyond the profile's extent the gap is open
                        Err(_) => false,
                    }
                }
            },
        )?;
        match settled {
            Some((cells, (p, f))) => Ok(cells.last().map(|&k| {
                let b = self.edge_fit(k, &p);
                (k, b, p, f)
            })),
            None => Err(ImpactError::Step {
                time: format!("{:.6}", d.t.to_f64()),
                reason: "the contact among whole cells did not settle (least-index pivoting)"
                    .into(),
            }),
        }
    }

    /// Solves the step with the contact cells `cells` (ascending, not empty): the pressures
    /// over 0..=max (zeros off the contact) and the force. A contact 0..=k takes the kept
    /// factorisation of [`March::solve_set`]; any other is factorised here.
    fn solve_cells(&self, d: &StepData<T>, cells: &[usize]) -> Result<(Vec<T>, T)> {
        let k = cells[cells.len() - 1];
        if cells.len() == k + 1 {
            return self.solve_set(d, k);
        }
        let zero = T::of(0.0);
        let w: Vec<T> = cells.iter().map(|&j| self.weight(j)).collect();
        // the band of the cells' local indices is no wider than that of the cells
        let factor = Factor::new(
            cells.len(),
            self.reach(),
            |i, j| self.current(cells[i], cells[j]),
            d.coupling,
            w,
        )
        .ok_or_else(|| singular_system(d.t))?;
        let mut r = Vec::with_capacity(cells.len());
        for &i in cells {
            r.push(d.target(i, zero)? - d.hist.0[i] - d.hist.1.get(i).copied().unwrap_or(zero));
        }
        let pc = factor.solve(&r).ok_or_else(|| singular_system(d.t))?;
        let mut p = vec![zero; k + 1];
        for (&i, &v) in cells.iter().zip(&pc) {
            p[i] = v;
        }
        let force = p
            .iter()
            .enumerate()
            .fold(zero, |s, (j, &v)| s + self.weight(j) * v);
        Ok((p, force))
    }

    /// The mean of the profile over cell i (3-point Gauss-Legendre; cell 0 through its
    /// right half, the profile being even); `None` beyond the profile's extent.
    fn profile_mean(&self, i: usize) -> Option<T> {
        let half_cell = self.dx * 0.5;
        let (lo, hi) = if i == 0 {
            (T::of(0.0), half_cell)
        } else {
            let x = self.dx * i as f64;
            (x - half_cell, x + half_cell)
        };
        let (mid, half) = ((lo + hi) * 0.5, (hi - lo) * 0.5);
        let u = (T::of(3.0) / 5.0).sqrt();
        let ninth = T::of(1.0) / 9.0;
        let mut s = T::of(0.0);
        for (node, w) in [
            (-u, ninth * 5.0),
            (T::of(0.0), ninth * 8.0),
            (u, ninth * 5.0),
        ] {
            s += w * self.profile.height(mid + half * node)?;
        }
        Some(s * 0.5)
    }
}

/// The means over `len` cells of a grid twice as coarse of a field given by its means over
/// the cells of width dx/2 (cell 0 centred on x = 0, the field even, zero beyond `fine`):
/// the coarse cell J covers the fine cell 2J and the halves of 2J - 1 and 2J + 1.
fn coarse_means<T: Scalar>(fine: &[T], len: usize) -> Vec<T> {
    let at = |i: usize| fine.get(i).copied().unwrap_or(T::of(0.0));
    (0..len)
        .map(|j| {
            if j == 0 {
                (at(0) + at(1)) * 0.5
            } else {
                (at(2 * j - 1) * 0.5 + at(2 * j) + at(2 * j + 1) * 0.5) * 0.5
            }
        })
        .collect()
}

/// The first `handed` steps (an even number) of a march on cells dx/2 and steps dt/2 merged
/// onto the grid dx, dt (`docs/impact.md`, section 11): coarse step n holds the means of the fine
/// pressures over its cells and over the fine steps 2n - 1 and 2n (the impulse of every cell
/// and step kept exactly), the displacements of fine step 2n over its cells, and fine step
/// 2n's penetration, speed and work. Its edge is the fine run's at the middle of the step
/// (so that the edge reports of the coarse steps marched after it fit through it), and it
/// keeps the fine run's reports at t_n ([`StepState::finer`]).
pub(crate) fn merge_onto_coarser<T: Scalar>(
    fine: &Run<T>,
    handed: usize,
    dt: T,
) -> Vec<StepState<T>> {
    let edge = |n: usize| fine.edge_at(n).unwrap_or(fine.steps[n - 1].b);
    let force = |n: usize| fine.force_at(n).unwrap_or(fine.steps[n - 1].force);
    let fine = &fine.steps;
    let zero = T::of(0.0);
    (1..=handed.min(fine.len()) / 2)
        .map(|n| {
            let (a, b) = (&fine[2 * n - 2], &fine[2 * n - 1]);
            let cells = a.pressure.len().max(b.pressure.len());
            // coarse cells reaching the last fine contact cell
            let len = if cells == 0 { 0 } else { cells / 2 + 1 };
            let pa = coarse_means(&a.pressure, len);
            let pb = coarse_means(&b.pressure, len);
            let mut pressure: Vec<T> = pa.iter().zip(&pb).map(|(x, y)| (*x + *y) * 0.5).collect();
            // the displacements at t_n: they meet the contact conditions, so that the work
            // of the steps marched after them balances the striker's energy
            let w = coarse_means(&b.w, b.w.len().saturating_sub(1) / 2);
            let ws = coarse_means(&b.ws, b.ws.len().saturating_sub(1) / 2);
            while pressure.last().is_some_and(|v| *v == 0.0) {
                pressure.pop();
            }
            let t = dt * n as f64;
            let in_contact = !pressure.is_empty();
            StepState {
                t,
                h: b.h,
                v: b.v,
                k: pressure.len().saturating_sub(1),
                b: if in_contact { edge(2 * n - 1) } else { zero },
                edge_time: t - dt * 0.5,
                force: (a.force + b.force) * 0.5,
                pressure,
                w,
                ws,
                work: b.work,
                striker_work: b.striker_work,
                finer: Some((if in_contact { edge(2 * n) } else { zero }, force(2 * n))),
            }
        })
        .collect()
}
