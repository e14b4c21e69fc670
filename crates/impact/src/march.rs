//! Time marching of the contact integral equation on one uniform grid (`docs/impact.md`,
//! sections 2-4): eq (7) imposed on the cell means at the end of each step (the striker's G0
//! added to the half-plane's coefficients, `docs/strikers.md`),
//! the striker's equation of motion (5)/(8) integrated exactly for a force constant over the
//! step, the contact set from the edge law.
//!
//! Units inside: c1 = 1, mu = 1, lengths in R (so rho = 1/m^2, m = c2/c1).

use complexfn::quadrature::CachedRules;

use crate::error::{ImpactError, Result};
use crate::history::{HistorySum, KernelRows};
use crate::linalg::Factor;
use crate::profile::Profile;
use crate::scalar::Scalar;
use crate::tables::{ShapeRules, Tables};

/// How the penetration evolves.
#[derive(Clone, Debug)]
pub enum Motion {
    /// A free rigid striker: mass per unit length m0 and initial speed v0 (units c1).
    Free {
        /// m0/(rho R^2); the march takes m0 = mass_ratio/m^2 in its units mu R^2/c1^2 at its
        /// own precision.
        mass_ratio: f64,
        /// Initial speed over c1.
        v0: f64,
    },
    /// Penetration prescribed at constant speed (units c1).
    DrivenSpeed(f64),
    /// Penetration prescribed by a table (c1 t/R, h/R), linear between points, h(0) = 0.
    DrivenTable(Vec<(f64, f64)>),
}

impl Motion {
    /// The prescribed penetration at time t, at the precision of t (`None` for a free
    /// striker).
    fn driven_h<T: Scalar>(&self, t: T) -> Option<T> {
        match self {
            Motion::Free { .. } => None,
            Motion::DrivenSpeed(v) => Some(t * T::input(*v)),
            Motion::DrivenTable(tab) => {
                let i = tab.partition_point(|p| t >= p.0).clamp(1, tab.len() - 1);
                let (a, b) = (tab[i - 1], tab[i]);
                let (ax, ay, bx, by) = (T::input(a.0), T::input(a.1), T::input(b.0), T::input(b.1));
                Some((t - ax) * (by - ay) / (bx - ax) + ay)
            }
        }
    }
}

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
    /// [`crate::case::Run::edge_at`] interpolates the edge to t_n.
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
}

/// The marching state on one grid, at the precision T (`crate::scalar`).
pub struct March<'a, T: Scalar + CachedRules = f64> {
    tables: &'a mut Tables<T>,
    /// The striker's compliance rows (none for a rigid striker).
    striker: Option<&'a mut dyn KernelRows<T>>,
    profile: &'a Profile,
    motion: &'a Motion,
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
    /// The history sums of the half-plane's and the striker's displacements.
    history: HistorySum<T>,
    striker_history: Option<HistorySum<T>>,
    /// The factorised systems by number of contact cells (and the coupling they were built
    /// with).
    systems: std::cell::RefCell<SystemCache<T>>,
}

/// Bytes in a GiB.
const GIB: f64 = 1024.0 * 1024.0 * 1024.0;

/// Source cells at least this many cells from the receiving cell enter the shape defect by
/// their moments (`EdgeModel::shape_defect_with`).
const FAR_CELLS: usize = 4;

/// The moments D_1 .. D_MOMENTS of a far cell: kbar's Taylor series about the cell's middle
/// converges like (1/2)/(distance to the receiving cell)^n, under 1e-9 relative at four cells.
const MOMENTS: usize = 12;

/// The cells behind the free edge whose conditions carry the shape correction, besides the
/// edge cell (`docs/impact.md`, section 4): the neighbour. On the reference case 1, 3, 6 and
/// 16 cells give the same errors within 20 percent, one costing least.
const ROWS_CORRECTED: usize = 1;

/// The banded contact systems kept on either side of the current width.
const SYSTEMS_KEPT: usize = 4;

/// The step's system of the contact cells 0..c - 1 depends on c alone (the current step's
/// coefficients and the striker's coupling are the same at every step): its factorisation,
/// M^-1 u for the column u of cell c and M^-1 e_{c-k} for the corrected cells behind it, kept
/// for the whole march.
#[derive(Debug)]
struct CellSystem<T> {
    factor: Factor<T>,
    z: Vec<T>,
    /// M^-1 e_{c-k}, k = 1 ..= `ROWS_CORRECTED`: the columns of the shape corrections of the
    /// cells behind the edge cell.
    behind: Vec<Vec<T>>,
}

/// The two solutions behind every tied solve of one step and edge cell c: y = M^-1 r and
/// z = M^-1 u, M the system of the cells 0..c - 1 (with the striker's coupling), r the
/// right-hand side and u the edge cell's column. The tied system M + ratio u e^T (e the last
/// cell) then has the solution y - ratio z (e.y)/(1 + ratio e.z) (Sherman-Morrison), so the
/// iterations on the edge's position cost O(c) each instead of a factorisation; M's
/// factorisation and z are the same at every step ([`CellSystem`]), so a step costs O(c^2)
/// when M is dense and O(c) when it is banded (`crate::linalg`).
struct TiedBasis<T> {
    y: Vec<T>,
    system: std::rc::Rc<CellSystem<T>>,
}

/// The factorised systems by number of contact cells and the coupling they were built with.
type SystemCache<T> = (T, Vec<Option<std::rc::Rc<CellSystem<T>>>>);

/// The local model of the edge cell (`docs/impact.md`, section 4): inside the contact the
/// pressure is A d^lambda (d the distance from the edge b), outside the gap is A G s^(lambda + 1)
/// (s the distance beyond b), the local solution of `lamb::edge` for the edge's current speed.
#[derive(Clone, Copy, Debug)]
struct EdgeModel<T> {
    /// The exponent lambda the edge law selects.
    lambda: T,
    /// The gap coefficient G (units 1/mu); unused by the kinematic law.
    gap: T,
    /// Supersonic edge: the two laws coincide, the edge is the geometric one.
    geometric: bool,
    /// Whether the free edge is placed inside its cell by the model: below
    /// `FREE_EDGE_SPEED` times the Rayleigh speed (nearer c_R the gap coefficient of the
    /// square-root solution vanishes and the edge's position is ill-conditioned).
    sub_cell: bool,
    /// (1 - nu)/pi: the static kernel's factor, w = -(1 - nu)/(pi mu) Int p(xi) ln|x - xi| dxi
    /// (units mu = 1), for the shape correction of the free edge's condition; scaled like the
    /// gap for a striker of the half-plane's own wave speeds (the two bodies' compliances add).
    static_factor: T,
    /// beta dx, beta the second term of the local expansion p = A d^lambda (1 + beta d):
    /// the factor of the other edge of a symmetric contact, (1 - d/(2b))^lambda, gives
    /// beta = -lambda/(2b) (`docs/impact.md`, section 4).
    curvature: T,
}

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

/// d^e for d >= 0: through the square root and integer powers when 2e is a small integer (the
/// exponents +-1/2 of the edge laws below c2 and their primitives), `powf` otherwise.
fn pow<T: Scalar>(d: T, e: T) -> T {
    let twice = e * 2.0;
    let n = twice.to_f64().round();
    if twice == n && n.abs() <= 16.0 {
        let n = n as i32;
        if n % 2 == 0 {
            d.powi(n / 2)
        } else {
            d.sqrt() * d.powi((n - 1) / 2)
        }
    } else {
        d.powf(&e)
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

/// Fraction of the Rayleigh speed below which a free (Signorini) edge is placed inside its
/// cell by the local model; faster free edges are captured cell by cell.
const FREE_EDGE_SPEED: f64 = 0.8;

impl<T: Scalar> EdgeModel<T> {
    /// (1/dx) Int_lo^hi d^lambda dd (0 <= lo <= hi).
    fn mean_power(&self, lo: T, hi: T, dx: T) -> T {
        let e = self.lambda + 1.0;
        let beta = self.curvature / dx;
        (pow(hi, e) - pow(lo, e)) / (e * dx)
            + beta * (pow(hi, e + 1.0) - pow(lo, e + 1.0)) / ((e + 1.0) * dx)
    }

    /// For the edge b in cell c (theta = (b - x_c + dx/2)/dx in [0, 1]): the ratio of the
    /// edge cell's mean pressure to the mean pressure of cell c - 1, and the mean gap over the
    /// edge cell per unit mean pressure of cell c - 1 that the cells' constant pressures must
    /// leave there: the model's gap less the shape correction of the c + 1 cells 0..=c
    /// (`docs/impact.md`, section 4; the correction only for a free edge, given its rules).
    fn tie(&self, theta: T, dx: T, c: usize, shape: Option<ShapeRules<T>>) -> (T, T) {
        let outside = (T::of(1.0) - theta) * dx;
        let neighbour = self.neighbour_mean(theta, dx);
        let load = self.mean_power(T::of(0.0), theta * dx, dx);
        let e = self.lambda + 2.0;
        // the gap of A d^lambda (1 + beta d): A G s^(lambda + 1) (1 + beta_g s) with
        // beta_g = -beta (lambda + 1)/(lambda + 2) (the kernel of a steadily moving edge is
        // the static one times a constant, and the static pair of p = d^mu has the gap's
        // slope s^mu/sin(pi mu))
        let beta_g = -self.curvature / dx * (self.lambda + 1.0) / e;
        let mut gap =
            self.gap * (pow(outside, e) / e + beta_g * pow(outside, e + 1.0) / (e + 1.0)) / dx;
        if let Some(rules) = shape {
            gap -= self.shape_term(theta, dx, c, 0, rules);
        }
        (load / neighbour, gap / neighbour)
    }

    /// The mean of d^lambda over cell c - 1 (the amplitude's reference), edge at theta.
    fn neighbour_mean(&self, theta: T, dx: T) -> T {
        self.mean_power(theta * dx, theta * dx + dx, dx)
    }

    /// The displacement the cells' constant pressures miss over the cell `k` behind the edge
    /// cell, per unit amplitude A: (1 - nu)/pi dx^(lambda + 1) times the shape defect.
    fn shape_term(&self, theta: T, dx: T, c: usize, k: usize, rules: ShapeRules<T>) -> T {
        self.static_factor * pow(dx, self.lambda + 1.0) * self.shape_defect_at(theta, c, k, rules)
    }

    /// The shape defect (`docs/impact.md`, section 4), dx = 1: with d the distance from the
    /// edge into the contact, the edge cell d in [theta - 1, theta] and its neighbours
    /// j = 1..=cells behind it, the mean over the receiving cell, `k` cells behind the edge
    /// cell (0: the edge cell), of -Int (p - pbar) ln|d - xi| dxi for p = d^lambda (d > 0) and
    /// pbar its mean on each cell: the part of the local solution's displacement there that
    /// the cells' constant pressures miss (the static kernel without its factor).
    fn shape_defect_at(&self, theta: T, cells: usize, k: usize, rules: ShapeRules<T>) -> T {
        self.shape_defect_with(theta, cells, k, rules, FAR_CELLS)
    }

    /// [`EdgeModel::shape_defect_at`] with the source cells at least `far` cells from the
    /// receiving cell (and from the edge) taken by their moments: on such a cell kbar is
    /// smooth, and Int (p - pbar) kbar = sum_n kbar^(n)(m) D_n/n! with
    /// D_n = Int (p - pbar) (x - m)^n (m the cell's middle, D_0 = 0), to n = `MOMENTS`; D_n on the
    /// smooth rule's nodes, kbar's derivatives in closed form: two logarithms a cell instead
    /// of fourteen (`far_cells_by_moments_agree_with_the_quadrature`).
    fn shape_defect_with(
        &self,
        theta: T,
        cells: usize,
        k: usize,
        rules: ShapeRules<T>,
        far: usize,
    ) -> T {
        let lam = self.lambda;
        let kf = k as f64;
        let zero = T::of(0.0);
        // primitive of ln|u|
        let f = |u: T| if u == 0.0 { zero } else { u * u.abs().ln() - u };
        // minus the mean over the receiving cell of ln|d - xi|
        let kbar = |xi: T| f(theta + (kf - 1.0) - xi) - f(theta + kf - xi);
        let power = |d: T| if d > 0.0 { pow(d, lam) } else { zero };
        let prim = |d: T| {
            if d > 0.0 {
                pow(d, lam + 1.0) / (lam + 1.0)
            } else {
                zero
            }
        };
        let (clustered_rule, smooth_rule) = rules;
        // Int_a^b (p - pbar) kbar, clustered at both ends (x = end + (mid - end) u^2): the
        // pieces touching the edge cell's ends (kinks of kbar) or the edge (d^lambda)
        let clustered = |a: T, b: T, pbar: T| -> T {
            let mid = (a + b) * 0.5;
            let mut s = zero;
            for (end, dir) in [(a, mid - a), (b, mid - b)] {
                for &(u, w) in clustered_rule {
                    // u on [0, 1], weight w/2
                    let u = (u + 1.0) * 0.5;
                    let x = end + dir * u * u;
                    s += (power(x) - pbar) * kbar(x) * w * dir.abs() * u;
                }
            }
            s
        };
        let smooth = |a: T, b: T, pbar: T| -> T {
            smooth_rule.iter().fold(zero, |s, &(u, w)| {
                let x = a + (b - a) * (u + 1.0) * 0.5;
                s + (power(x) - pbar) * kbar(x) * w * (b - a) * 0.5
            })
        };
        // the receiving cell's ends, where kbar's derivatives are singular
        let (r0, r1) = (theta + (kf - 1.0), theta + kf);
        let moments = |a: T, b: T, pbar: T| -> T {
            let m = (a + b) * 0.5;
            let h = (b - a) * 0.5;
            // D_1 .. D_MOMENTS on the smooth rule's nodes (p is smooth away from the edge)
            let mut dn = [zero; MOMENTS];
            for &(u, w) in smooth_rule {
                let e = h * u;
                let mut q = (power(m + e) - pbar) * w * h;
                for d in dn.iter_mut() {
                    q *= e;
                    *d += q;
                }
            }
            let (u0, u1) = (r0 - m, r1 - m);
            // kbar = f(r0 - x) - f(r1 - x): kbar' = ln|r1 - x| - ln|r0 - x| and, for n >= 2,
            // kbar^(n)(m)/n! = (u0^(1-n) - u1^(1-n))/(n (n - 1)), u = r - m
            let mut sum = (u1.abs().ln() - u0.abs().ln()) * dn[0];
            let (mut p0, mut p1) = (u0.recip(), u1.recip());
            for (i, d) in dn.iter().enumerate().skip(1) {
                let n = (i + 1) as f64;
                sum += (p0 - p1) * *d / (n * (n - 1.0));
                p0 /= u0;
                p1 /= u1;
            }
            sum
        };
        let mut total = zero;
        for j in 0..=cells {
            let (a, b) = (theta + (j as f64 - 1.0), theta + j as f64);
            let pbar = prim(b) - prim(a);
            total += match j {
                0 if theta > 0.0 => clustered(a, zero, pbar) + clustered(zero, b, pbar),
                0 => clustered(a, b, pbar),
                // the cells touching the edge cell or the receiving cell (kinks of kbar)
                _ if j <= 1 || j + 1 >= k && j <= k + 1 => clustered(a, b, pbar),
                _ if j >= 2 && j.abs_diff(k) >= far => moments(a, b, pbar),
                _ => smooth(a, b, pbar),
            };
        }
        total
    }
}

impl<'a, T: Scalar + CachedRules> March<'a, T> {
    /// A march with cell width dx and time step dt (the tables' kappa is dt/dx), with the
    /// striker's compliance (none for a rigid striker).
    pub(crate) fn new(
        tables: &'a mut Tables<T>,
        striker: Option<&'a mut dyn KernelRows<T>>,
        profile: &'a Profile,
        motion: &'a Motion,
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
            motion,
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
            None => match self.motion {
                Motion::Free { v0, .. } => (zero, T::input(*v0), 0),
                _ => (zero, zero, 0),
            },
        };
        let (h_pred, coupling, mass) = match (self.motion.driven_h(t), self.motion) {
            (Some(h), _) => (h, zero, T::of(f64::INFINITY)),
            (None, Motion::Free { mass_ratio, .. }) => {
                let m = *self.tables.half_plane().m();
                let mass = T::input(*mass_ratio) / (m * m);
                (h0 + dt * v0, dt * dt / (mass * 2.0), mass)
            }
            _ => unreachable!("a driven motion always gives h"),
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
        let imax = (k0 + 3)
            .max(kin_k(kin_b) + 3)
            .max(edge_cell(b_prev) + 3)
            .min(self.kcap + 2);
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
        let data = StepData {
            hist: self.history(n, imax)?,
            fbar: (0..=imax).map(|i| self.profile_mean(i)).collect(),
            h_pred,
            coupling,
            t,
        };
        let hist = &data.hist;
        let model = self.edge_model(kin_b)?;
        let mut set = None;
        let signorini = matches!(self.law, EdgeLaw::Signorini);
        let geometric = !signorini || matches!(model, Some(m) if m.geometric);
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
            (false, Some(m)) if m.sub_cell && edge_cell(b_prev) >= 2 => {
                if let Some(s) = self.free_edge(&data, m, edge_cell(b_prev))? {
                    set = Some((s, true));
                    settled = true;
                }
            }
            _ => {}
        }
        if !settled {
            if let Some(found) = self.whole_cells(&data, k0.min(self.kcap), imax)? {
                set = Some((found, true));
            }
        }
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
        let (h, v) = match self.motion.driven_h(t) {
            Some(h) => {
                let hp = self.motion.driven_h(t - dt).unwrap_or(zero);
                (h, (h - hp) / dt)
            }
            None => (
                h0 + dt * v0 - dt * dt * f / (mass * 2.0),
                v0 - dt * f / mass,
            ),
        };
        let (w, ws): (Vec<T>, Vec<T>) = (0..=imax).map(|i| self.displacements(i, hist, &p)).unzip();
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
        });
        Ok(in_contact)
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
        let mut inside = vec![false; top + 1];
        for c in inside.iter_mut().take(k0.min(top) + 1) {
            *c = true;
        }
        // Murty's rule ends for a P-matrix; the bound only guards against a matrix that is not
        let limit = 8 * (top + 1) + 16;
        for _ in 0..limit {
            let cells: Vec<usize> = (0..=top).filter(|&i| inside[i]).collect();
            let (p, f) = match cells.last() {
                Some(_) => self.solve_cells(d, &cells)?,
                None => (Vec::new(), zero),
            };
            // the first cell on the wrong side
            let mut flip = None;
            for i in 0..=top {
                let wrong = if inside[i] {
                    p[i] < 0.0
                } else {
                    match d.target(i, f) {
                        Ok(target) => self.displacement(i, &d.hist, &p) - target < 0.0,
                        // beyond the profile's extent the gap is open
                        Err(_) => false,
                    }
                };
                if wrong {
                    flip = Some(i);
                    break;
                }
            }
            match flip {
                Some(i) => inside[i] = !inside[i],
                None => {
                    return Ok(cells.last().map(|&k| {
                        let b = self.edge_fit(k, &p);
                        (k, b, p, f)
                    }))
                }
            }
        }
        Err(ImpactError::Step {
            time: format!("{:.6}", d.t.to_f64()),
            reason: "the contact among whole cells did not settle (least-index pivoting)".into(),
        })
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

    /// The edge's speed (units c1) over the last steps (up to four), from the reported edges
    /// (the edge at t = 0 is 0); over the first step, from the geometric edge `kin_b` at its
    /// end.
    fn edge_speed(&self, kin_b: T) -> T {
        if self.steps.is_empty() {
            return kin_b / self.dt;
        }
        recent_edge_speed(&self.steps, self.dt)
    }

    /// The local model of the edge cell for the current edge speed and law (`lamb::edge`);
    /// `None` for the flat punch (its edges sit on cell boundaries).
    fn edge_model(&self, kin_b: T) -> Result<Option<EdgeModel<T>>> {
        let Some(scale) = self.edge_gap_scale else {
            return Ok(None);
        };
        if matches!(self.profile, Profile::Flat { .. }) {
            return Ok(None);
        }
        let hp = self.tables.half_plane();
        let (sr, m) = (*hp.s_r(), *hp.m());
        let d = self.edge_speed(kin_b);
        // a receding or resting edge takes the model of a slowly advancing one (the
        // static limit), below the Rayleigh speed
        let mut speed = if d > 0.0 { d } else { d.abs().min(sr * 0.5) };
        speed = speed.max(T::of(1e-6));
        // off the speeds where the local solutions jump (refused by `lamb::edge`)
        let guard = 10.0 * lamb::edge::SPEED_GUARD;
        for c in [sr, m, T::of(1.0)] {
            if (speed - c).abs() <= c * guard {
                speed = c * (1.0 - guard);
            }
        }
        let eb = hp.edge_behaviour(speed, self.law)?;
        let gap = eb
            .solutions
            .iter()
            .find(|s| s.lambda == eb.selected)
            .map_or(T::of(0.0), |s| s.gap_coefficient);
        let pi = speed.pi();
        Ok(Some(EdgeModel {
            lambda: eb.selected,
            gap: gap * scale,
            geometric: eb.range == lamb::edge::SpeedRange::Supersonic,
            sub_cell: speed < sr * FREE_EDGE_SPEED,
            static_factor: scale * (T::of(1.0) - hp.poisson()) / pi,
            curvature: match self.steps.last() {
                Some(s) if s.b > 0.0 => -eb.selected * self.dx / (s.b * 2.0),
                _ => T::of(0.0),
            },
        }))
    }

    /// Solves the step with full contact cells 0..c-1 and the edge cell c, whose mean
    /// pressure is `ratio` times that of cell c - 1: returns (pressures 0..=c, force).
    fn solve_tied(&self, d: &StepData<T>, c: usize, ratio: T) -> Result<(Vec<T>, T)> {
        let basis = self.tied_basis(d, c)?;
        self.tied_solution(d, &basis, c, ratio)
    }

    /// The factorised system of the cells 0..c - 1 and M^-1 u ([`CellSystem`]), built once
    /// per march.
    fn cell_system(&self, d: &StepData<T>, c: usize) -> Result<std::rc::Rc<CellSystem<T>>> {
        {
            let cache = self.systems.borrow();
            if cache.0 == d.coupling {
                if let Some(Some(sys)) = cache.1.get(c) {
                    return Ok(sys.clone());
                }
            }
        }
        let n = c;
        let w: Vec<T> = (0..n).map(|j| self.weight(j)).collect();
        let u: Vec<T> = (0..n)
            .map(|i| self.current(i, c) + d.coupling * self.weight(c))
            .collect();
        let singular = || singular_system(d.t);
        let factor = Factor::new(n, self.reach(), |i, j| self.current(i, j), d.coupling, w)
            .ok_or_else(singular)?;
        let z = factor.solve(&u).ok_or_else(singular)?;
        // M^-1 e_{c-k} for the cells behind the edge cell whose conditions carry the shape
        // correction (the same at every step, like z)
        let behind = (1..=ROWS_CORRECTED.min(n))
            .map(|k| {
                let mut e = vec![T::of(0.0); n];
                e[n - k] = T::of(1.0);
                factor.solve(&e).ok_or_else(singular)
            })
            .collect::<Result<Vec<_>>>()?;
        let sys = std::rc::Rc::new(CellSystem { factor, z, behind });
        let mut cache = self.systems.borrow_mut();
        if cache.0 != d.coupling {
            *cache = (d.coupling, Vec::new());
        }
        if cache.1.len() <= c {
            cache.1.resize_with(c + 1, || None);
        }
        cache.1[c] = Some(sys.clone());
        // banded systems cost O(c) to rebuild: keep only the widths near the current one
        // (the contact grows or shrinks a cell at a time), so memory stays O(c)
        if matches!(sys.factor, Factor::Band { .. }) {
            for (k, slot) in cache.1.iter_mut().enumerate() {
                if k.abs_diff(c) > SYSTEMS_KEPT {
                    *slot = None;
                }
            }
        }
        Ok(sys)
    }

    /// The two solutions behind the tied solves of cell c at this step ([`TiedBasis`]).
    fn tied_basis(&self, d: &StepData<T>, c: usize) -> Result<TiedBasis<T>> {
        let sys = self.cell_system(d, c)?;
        let zero = T::of(0.0);
        let mut r = vec![zero; c];
        for (i, ri) in r.iter_mut().enumerate() {
            *ri = d.target(i, zero)? - d.hist.0[i] - d.hist.1.get(i).copied().unwrap_or(zero);
        }
        let y = sys.factor.solve(&r).ok_or_else(|| singular_system(d.t))?;
        Ok(TiedBasis { y, system: sys })
    }

    /// The pressures of cells 0..=c and the force when cell c carries `ratio` times the
    /// pressure of cell c - 1, from the step's [`TiedBasis`] of cell c.
    fn tied_solution(
        &self,
        d: &StepData<T>,
        basis: &TiedBasis<T>,
        c: usize,
        ratio: T,
    ) -> Result<(Vec<T>, T)> {
        self.tied_solution_with(d, basis, c, ratio, None)
    }

    /// As [`March::tied_solution`], with `q` = M^-1 delta when the conditions of the cells
    /// behind the edge carry terms delta p_{c-1} (their shape corrections): the system
    /// M + (ratio u + delta) e_{c-1}^T, by Sherman-Morrison on z ratio + q.
    fn tied_solution_with(
        &self,
        d: &StepData<T>,
        basis: &TiedBasis<T>,
        c: usize,
        ratio: T,
        q: Option<&[T]>,
    ) -> Result<(Vec<T>, T)> {
        let last = c - 1;
        let z = &basis.system.z;
        let zw: Vec<T> = match q {
            Some(q) => z.iter().zip(q).map(|(&z, &q)| ratio * z + q).collect(),
            None => z.iter().map(|&z| ratio * z).collect(),
        };
        let den = zw[last] + 1.0;
        if !(den.abs() > 1e-300) || !den.is_finite() {
            return Err(singular_system(d.t));
        }
        let k = basis.y[last] / den;
        let mut p: Vec<T> = basis.y.iter().zip(&zw).map(|(&y, &z)| y - k * z).collect();
        p.push(ratio * p[last]);
        let force = p
            .iter()
            .enumerate()
            .fold(T::of(0.0), |s, (j, &v)| s + self.weight(j) * v);
        Ok((p, force))
    }

    /// The shape correction of the conditions of the cells just behind the edge cell c (edge
    /// at theta), proportional to p_{c-1} like the edge cell's own (`docs/impact.md`, section
    /// 4): q = M^-1 delta from the kept columns M^-1 e_{c-k} of `basis`, for
    /// [`March::tied_solution_with`].
    fn behind_corrections(
        &self,
        model: &EdgeModel<T>,
        theta: T,
        c: usize,
        basis: &TiedBasis<T>,
    ) -> Vec<T> {
        let rules = self.tables.shape_rules();
        let neighbour = model.neighbour_mean(theta, self.dx);
        let mut q = vec![T::of(0.0); c];
        for (k, col) in (1..).zip(&basis.system.behind) {
            let coef = model.shape_term(theta, self.dx, c, k, rules) / neighbour;
            for (qi, &v) in q.iter_mut().zip(col) {
                *qi += coef * v;
            }
        }
        q
    }

    /// The free (Signorini) edge inside a cell: the edge cell c carries the local model's
    /// pressure, and its mean displacement leaves the model's gap over the part beyond the
    /// edge; the edge is the root of that condition in the cell (regula falsi), the cell
    /// moving outwards or inwards when the root lies beyond it. Returns (c, b, pressures,
    /// force), or `None` where the model cannot stand: the edge recedes into the first two
    /// cells, or a cell's pressure would pull (the contact is then found among whole cells,
    /// which can shrink it to nothing).
    fn free_edge(
        &self,
        d: &StepData<T>,
        model: EdgeModel<T>,
        start: usize,
    ) -> Result<Option<StepSet<T>>> {
        let dx = self.dx;
        let top = (d.fbar.len() - 1).min(self.kcap);
        // one factorisation per edge cell tried, shared by the iterations on theta
        let mut bases: Vec<Option<TiedBasis<T>>> = Vec::new();
        let mut residual = |c: usize, theta: T| -> Result<(T, Vec<T>, T)> {
            let (ratio, gap) = model.tie(theta, dx, c, Some(self.tables.shape_rules()));
            if bases.len() <= c {
                bases.resize_with(c + 1, || None);
            }
            if bases[c].is_none() {
                bases[c] = Some(self.tied_basis(d, c)?);
            }
            let basis = bases[c].as_ref().ok_or_else(|| ImpactError::Step {
                time: format!("{:.6}", d.t.to_f64()),
                reason: "no factorisation of the edge cell's system".into(),
            })?;
            let q = self.behind_corrections(&model, theta, c, basis);
            let (p, f) = self.tied_solution_with(d, basis, c, ratio, Some(&q))?;
            // the edge cell's mean gap at the step's end, and at its middle, where the
            // step's pressures (and so the model's edge and gap) stand: the mean of the
            // gaps at the step's two ends
            let end_gap = self.displacement(c, &d.hist, &p) - d.target(c, f)?;
            let gap_now = match self.gap_before(c) {
                Some(before) => (end_gap + before) * 0.5,
                None => end_gap,
            };
            Ok((gap_now - gap * p[c - 1], p, f))
        };
        let mut c = start.clamp(2, top.max(2));
        let mut tried = vec![false; top + 2];
        let (zero, one) = (T::of(0.0), T::of(1.0));
        let pushes = |p: &[T]| p.iter().all(|v| *v >= 0.0);
        loop {
            tried[c] = true;
            let (r1, p1, f1) = residual(c, one)?;
            if r1 < 0.0 && c < top && !tried[c + 1] {
                c += 1;
                continue;
            }
            let (r0, p0, f0) = residual(c, zero)?;
            if r0 > 0.0 && c > 2 && !tried[c - 1] {
                c -= 1;
                continue;
            }
            if r0 > 0.0 && c == 2 {
                // the edge recedes into the first two cells
                return Ok(None);
            }
            let edge = |theta: T| (theta + (c as f64 - 0.5)) * dx;
            if r1 <= 0.0 {
                return Ok(pushes(&p1).then(|| (c, edge(one), p1, f1)));
            }
            if r0 >= 0.0 {
                return Ok(pushes(&p0).then(|| (c, edge(zero), p0, f0)));
            }
            // regula falsi (Illinois) on theta in (0, 1)
            let (mut a, mut fa, mut b, mut fb) = (zero, r0, one, r1);
            let mut best = (p0, f0, zero);
            let mut side = 0;
            for _ in 0..ITERATIONS * T::BITS as usize / 53 + 10 {
                let x = (a * fb - b * fa) / (fb - fa);
                let (rx, px, fx) = residual(c, x)?;
                best = (px, fx, x);
                if rx.abs() <= (d.h_pred.abs() + dx) * tolerance::<T>(1e-15)
                    || (b - a) <= tolerance::<T>(1e-13)
                {
                    break;
                }
                if (rx > 0.0) == (fb > 0.0) {
                    b = x;
                    fb = rx;
                    if side == -1 {
                        fa *= 0.5;
                    }
                    side = -1;
                } else {
                    a = x;
                    fa = rx;
                    if side == 1 {
                        fb *= 0.5;
                    }
                    side = 1;
                }
            }
            let (p, f, theta) = best;
            return Ok(pushes(&p).then(|| (c, edge(theta), p, f)));
        }
    }

    /// The mean gap over cell i at the end of the previous step, w_i - (h - mean f_i), if
    /// that step has the cell's displacement.
    fn gap_before(&self, i: usize) -> Option<T> {
        let s = self.steps.last()?;
        let w = *s.w.get(i)? + s.ws.get(i).copied().unwrap_or(T::of(0.0));
        Some(w - (s.h - self.profile_mean(i)?))
    }

    /// The Signorini edge inside the last cell: the zero of C (b - x)^(1/2) through the last
    /// two cell pressures, kept within the last cell.
    fn edge_fit(&self, k: usize, p: &[T]) -> T {
        let dx = self.dx;
        let xk = dx * k as f64;
        if k == 0 || p.len() < 2 {
            return xk + dx * 0.5;
        }
        let zero = T::of(0.0);
        let (a, c) = (p[k - 1].max(zero).powi(2), p[k].max(zero).powi(2));
        let b = if a > c {
            (xk * a - (xk - dx) * c) / (a - c)
        } else {
            xk + dx * 0.5
        };
        b.max(xk).min(xk + dx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The static half-plane's displacement under a uniform load: the mean over [xa, xb] of
    /// -Int_sa^sb ln|x - xi| dxi in closed form (the second primitive of ln|u| at the corners),
    /// for the test of the shape defect.
    fn static_cell_mean(xa: f64, xb: f64, sa: f64, sb: f64) -> f64 {
        let g = |u: f64| {
            if u == 0.0 {
                0.0
            } else {
                0.5 * u * u * u.abs().ln() - 0.75 * u * u
            }
        };
        -(g(xb - sa) - g(xa - sa) - g(xb - sb) + g(xa - sb)) / (xb - xa)
    }

    /// Tables whose rules the march passes to the shape correction.
    fn tables() -> Tables {
        Tables::new(lamb::HalfPlane::from_poisson(0.25).unwrap(), 2.0).unwrap()
    }

    /// The shape defect for lambda = 0 (a uniform pressure behind the edge), where only the
    /// edge cell's constant misses anything, against the closed-form static cell means.
    #[test]
    fn shape_defect_of_a_uniform_pressure_is_the_closed_form() {
        let model = EdgeModel {
            lambda: 0.0,
            gap: 0.0,
            geometric: false,
            sub_cell: true,
            static_factor: 1.0,
            curvature: 0.0,
        };
        let tables = tables();
        let rules = tables.shape_rules();
        for theta in [0.05, 0.37, 0.5, 0.8, 0.999] {
            let (a, b) = (theta - 1.0, theta);
            let want = -theta * static_cell_mean(a, b, a, 0.0)
                + (1.0 - theta) * static_cell_mean(a, b, 0.0, b);
            for cells in [0, 3, 20] {
                let got = model.shape_defect_at(theta, cells, 0, rules);
                assert!(
                    (got - want).abs() <= 1e-9 * want.abs().max(1e-3),
                    "theta = {theta}, cells = {cells}: {got} against {want}"
                );
            }
        }
    }

    /// The far source cells by their moments agree with the quadrature of every cell, for
    /// the edge cell and its neighbour receiving, both square-root exponents.
    #[test]
    fn far_cells_by_moments_agree_with_the_quadrature() {
        let tables = tables();
        let rules = tables.shape_rules();
        let mut worst: f64 = 0.0;
        for lambda in [0.5, -0.5] {
            let model = EdgeModel {
                lambda,
                gap: 0.0,
                geometric: false,
                sub_cell: true,
                static_factor: 1.0,
                curvature: 0.0,
            };
            for theta in [0.05, 0.5, 0.95] {
                for cells in [6, 40, 300] {
                    for k in [0, 1] {
                        let fast = model.shape_defect_with(theta, cells, k, rules, FAR_CELLS);
                        let all = model.shape_defect_with(theta, cells, k, rules, usize::MAX);
                        // relative to the defect, or to the edge cell's (about 0.1) where
                        // the neighbour's nearly cancels
                        let rel = (fast - all).abs() / all.abs().max(1e-2);
                        worst = worst.max(rel);
                        assert!(
                            rel < 1e-9,
                            "lambda {lambda}, theta {theta}, {cells} cells, k {k}: {fast} vs {all}"
                        );
                    }
                }
            }
        }
        eprintln!("largest relative difference {worst:.2e}");
    }

    /// For the square-root edge the defect converges in the number of cells behind the edge
    /// (the cells' dipoles decay like d^(lambda - 2)), and its quadrature agrees with a
    /// brute-force midpoint rule.
    #[test]
    fn shape_defect_of_the_square_root_edge() {
        let model = EdgeModel {
            lambda: 0.5,
            gap: 0.0,
            geometric: false,
            sub_cell: true,
            static_factor: 1.0,
            curvature: 0.0,
        };
        let tables = tables();
        let rules = tables.shape_rules();
        let theta = 0.3;
        // brute force over the edge cell and two cells behind it
        let n = 20000;
        let kbar = |xi: f64| {
            let m = 400;
            -(0..m)
                .map(|q| {
                    let d = theta - 1.0 + (q as f64 + 0.5) / m as f64;
                    (d - xi).abs().ln()
                })
                .sum::<f64>()
                / m as f64
        };
        let mut want = 0.0;
        for j in 0..3 {
            let (a, b) = (theta + j as f64 - 1.0, theta + j as f64);
            let prim = |d: f64| if d > 0.0 { d.powf(1.5) / 1.5 } else { 0.0 };
            let pbar = prim(b) - prim(a);
            for q in 0..n {
                let xi = a + (q as f64 + 0.5) / n as f64;
                let p = if xi > 0.0 { xi.sqrt() } else { 0.0 };
                want += (p - pbar) * kbar(xi) / n as f64;
            }
        }
        let got = model.shape_defect_at(theta, 2, 0, rules);
        assert!(
            (got - want).abs() < 2e-5 * want.abs(),
            "{got} against {want}"
        );
        let (d20, d40, d80) = (
            model.shape_defect_at(theta, 20, 0, rules),
            model.shape_defect_at(theta, 40, 0, rules),
            model.shape_defect_at(theta, 80, 0, rules),
        );
        // tail ~ cells^(-1/2): differences shrink by about sqrt 2
        let ratio = (d40 - d20) / (d80 - d40);
        assert!((ratio - 2f64.sqrt()).abs() < 0.1, "tail ratio {ratio}");
    }
}
