//! A rigid-striker impact case: inputs in, solved histories out, every reported quantity with
//! an error estimate from grid refinement (`docs/impact.md`, section 5).
//!
//! Dimensionless throughout (R the profile's length scale): x/R, c1 t/R, h/R, speeds over c1,
//! pressure over rho c1^2, force per unit length over rho c1^2 R, energies over rho c1^2 R^2,
//! the striker's mass per unit length as m0/(rho R^2).

use complexfn::quadrature::CachedRules;
use complexfn::Real;
use lamb::HalfPlane;

use crate::error::{invalid, ImpactError, Result};
use crate::march::{EdgeLaw, March, Motion, StepState};
use crate::profile::Profile;
use crate::scalar::Scalar;
use crate::striker::{shell_energies, Ring, Striker};
use crate::tables::Tables;

/// Smallest admissible kappa = c1 dt/dx. The march is stable for every kappa (the discrete
/// energy input is never negative, `docs/impact.md` section 2); below 1/2 the cost grows as
/// kappa^-2 while the error, dominated by the cells in space, does not fall.
pub const KAPPA_MIN: f64 = 0.5;

/// The parameters of the benchmark's reference case ([`ImpactCase::reference`]).
#[derive(Clone, Copy, Debug)]
pub struct ReferenceCase {
    /// The half-plane's c1 (m/s), the wedge paper's material.
    pub c1: f64,
    /// The half-plane's c2 (m/s).
    pub c2: f64,
    /// m0/(rho R^2).
    pub mass_ratio: f64,
    /// V0/c1.
    pub v0_over_c1: f64,
    /// End time c1 t/R.
    pub end: f64,
}

/// The benchmark's reference case: a free rigid cylinder with the parabolic profile
/// x^2/(2R), m0/(rho R^2) = 10, V0/c1 = 0.01, c1 = 1870.83 m/s, c2 = 1000 m/s, to c1 t/R = 10.
pub const REFERENCE: ReferenceCase = ReferenceCase {
    c1: 1870.83,
    c2: 1000.0,
    mass_ratio: 10.0,
    v0_over_c1: 0.01,
    end: 10.0,
};

/// The striker's motion in dimensionless form.
#[derive(Clone, Debug)]
pub enum Drive {
    /// Free rigid striker: mass ratio m0/(rho R^2) and initial speed V0/c1.
    Free {
        /// m0/(rho R^2) > 0.
        mass_ratio: f64,
        /// V0/c1 in (0, 1).
        v0_over_c1: f64,
    },
    /// Penetration at constant speed V/c1.
    Speed(f64),
    /// Penetration from a table of (c1 t/R, h/R) points, starting at (0, 0), increasing t.
    Table(Vec<(f64, f64)>),
}

/// The largest r = dt rho c1 b/m0 of the finest step admitted for a free striker
/// (`ImpactCase::check_stiffness`, a refusal of the solve): above 1 the trapezoidal factor (1 - r)/(1 + r) of the
/// striker's relaxation changes sign.
pub const STIFF_RATIO: f64 = 1.0;

/// Where a march stands ([`ImpactCase::solve_reporting`]).
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    /// The share of the whole run's estimated work done, in [0, 1] (the levels weighted by
    /// their cost).
    pub fraction: f64,
    /// The refinement level being marched (0 the finest).
    pub level: usize,
    /// Its step.
    pub step: usize,
    /// Its time c1 t/R.
    pub t: f64,
}

/// Where a run stops.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// At the end time [`ImpactCase::end`], the last reported time exactly.
    AtEnd,
    /// Shortly after the striker separates (free striker): the first reported time at least
    /// one reporting interval after the finest grid's separation; [`ImpactCase::end`] is then
    /// the safety cap (a run that has not separated by then ends there, its separation
    /// reported unavailable).
    AtSeparation,
}

/// The inputs of a case.
#[derive(Clone, Debug)]
pub struct ImpactCase {
    /// Poisson's ratio of the half-plane, in (-1, 1/2) (nu = 0 excluded by the Lamb crate).
    pub poisson: f64,
    /// The striker's profile.
    pub profile: Profile,
    /// The striker model (rigid by default).
    pub striker: Striker,
    /// Free or driven.
    pub drive: Drive,
    /// The edge law.
    pub law: EdgeLaw,
    /// End time c1 t/R (the cap with [`Stop::AtSeparation`]).
    pub end: f64,
    /// Where the run stops (default [`Stop::AtEnd`]).
    pub stop: Stop,
    /// The memory limit of the march in bytes (`None`: none): a level whose contact widens
    /// its history beyond it ends the solve with [`ImpactError::Grid`] (`crate::cost`).
    pub memory_limit: Option<f64>,
    /// Cell width dx/R of the finest grid.
    pub dx: f64,
    /// kappa = c1 dt/dx (>= 2).
    pub kappa: f64,
    /// Refinement levels for the error estimate (the finest grid dx and 2, 4, ... times
    /// coarser); 1 gives no estimate, 3 (default) gives the observed order.
    pub levels: usize,
    /// Whether the edge cell carries the local behaviour of the pressure at a moving edge
    /// (`lamb::edge`, `docs/impact.md`, section 4; default): the edge then moves continuously
    /// inside its cell. `false`: whole cells (the edge captured cell by cell).
    pub edge_model: bool,
}

impl ImpactCase {
    /// The case with the defaults dx = 0.01, kappa = 2, three levels.
    pub fn new(poisson: f64, profile: Profile, drive: Drive, law: EdgeLaw, end: f64) -> Self {
        ImpactCase {
            poisson,
            profile,
            striker: Striker::Rigid,
            drive,
            law,
            end,
            stop: Stop::AtEnd,
            memory_limit: None,
            dx: 0.01,
            kappa: 2.0,
            levels: 3,
            edge_model: true,
        }
    }

    /// The benchmark's reference case ([`REFERENCE`]) under `law`, with the default grid.
    pub fn reference(law: EdgeLaw) -> Self {
        let r = REFERENCE;
        ImpactCase::new(
            lamb::poisson_of(&(r.c2 / r.c1).powi(2)),
            Profile::Parabola { radius: 1.0 },
            Drive::Free {
                mass_ratio: r.mass_ratio,
                v0_over_c1: r.v0_over_c1,
            },
            law,
            r.end,
        )
    }

    /// The case with another striker model.
    pub fn with_striker(mut self, striker: Striker) -> Self {
        self.striker = striker;
        self
    }

    fn validate(&self) -> Result<()> {
        self.profile.validate()?;
        self.striker.validate()?;
        if let Striker::Shell(shell) = &self.striker {
            match self.profile {
                Profile::Circle { radius } | Profile::Parabola { radius } if radius == 1.0 => {}
                _ => {
                    return Err(invalid(
                        "profile of a shell striker",
                        self.profile.label(),
                        "circle:R=1 or parabola:R=1 (the shell's radius is the unit R)",
                    ))
                }
            }
            if let Drive::Free { mass_ratio, .. } = self.drive {
                let own = shell.mass_ratio();
                if (mass_ratio - own).abs() > 1e-12 * own {
                    return Err(invalid(
                        "mass ratio m0/(rho R^2) of a shell striker",
                        mass_ratio,
                        format!("its own 2 pi (h_s/R) rho_s/rho = {own:.6}"),
                    ));
                }
            }
        }
        let valid_until = self.striker.validity_end();
        if self.end > valid_until {
            return Err(invalid(
                "end time c1 t/R",
                self.end,
                format!(
                    "(0, {valid_until:.6}]: the elastic striker's local half-plane model holds until \
                     the P wave returns from its far side, c1 t/R = 2 c1/c1s"
                ),
            ));
        }
        match &self.drive {
            Drive::Free {
                mass_ratio,
                v0_over_c1,
            } => {
                if !(mass_ratio.is_finite() && *mass_ratio > 0.0) {
                    return Err(invalid("mass ratio m0/(rho R^2)", mass_ratio, "(0, inf)"));
                }
                if !(v0_over_c1.is_finite() && *v0_over_c1 > 0.0 && *v0_over_c1 < 1.0) {
                    return Err(invalid("V0/c1", v0_over_c1, "(0, 1)"));
                }
            }
            Drive::Speed(v) => {
                if !(v.is_finite() && *v > 0.0 && *v < 1.0) {
                    return Err(invalid("driven speed V/c1", v, "(0, 1)"));
                }
            }
            Drive::Table(t) => {
                if t.len() < 2 || t[0] != (0.0, 0.0) {
                    return Err(invalid(
                        "driven table",
                        format!("{} points", t.len()),
                        "at least 2 points (c1 t/R, h/R) starting at (0, 0)",
                    ));
                }
                for w in t.windows(2) {
                    if !(w[1].0 > w[0].0) || !w[1].1.is_finite() {
                        return Err(invalid(
                            "driven table",
                            format!("t = {}", w[1].0),
                            "strictly increasing finite times, finite h",
                        ));
                    }
                }
                if t.last().map(|p| p.0).unwrap_or(0.0) < self.end {
                    return Err(invalid(
                        "driven table",
                        format!("last time {}", t.last().unwrap().0),
                        format!("a table reaching the end time {}", self.end),
                    ));
                }
            }
        }
        if !(self.end.is_finite() && self.end > 0.0) {
            return Err(invalid("end time c1 t/R", self.end, "(0, inf)"));
        }
        if !(self.dx.is_finite() && self.dx > 0.0) {
            return Err(invalid("cell width dx/R", self.dx, "(0, inf)"));
        }
        if !(self.kappa.is_finite() && (KAPPA_MIN..=64.0).contains(&self.kappa)) {
            return Err(invalid(
                "kappa = c1 dt/dx",
                self.kappa,
                "[0.5, 64] (the march is stable for every kappa; below 1/2 its cost grows as kappa^-2 while its error does not fall)",
            ));
        }
        if !(1..=4).contains(&self.levels) {
            return Err(invalid("refinement levels", self.levels, "1 to 4"));
        }
        let coarse = self.dx * (1 << (self.levels - 1)) as f64;
        let steps = self.end / (self.kappa * self.dx);
        if steps > 2.0e5 {
            return Err(ImpactError::Grid {
                name: "dx",
                reason: format!("{steps:.0} time steps (at most 200000): raise dx or kappa"),
            });
        }
        if self.end < 4.0 * self.kappa * coarse {
            return Err(ImpactError::Grid {
                name: "dx",
                reason: format!(
                    "the coarsest level (dx = {coarse}) takes fewer than 4 steps to c1 t/R = {}",
                    self.end
                ),
            });
        }
        if let Profile::Flat { half_width } = self.profile {
            if half_width < 2.0 * coarse {
                return Err(ImpactError::Grid {
                    name: "dx",
                    reason: format!(
                        "the flat punch (a = {half_width}) spans fewer than 2 cells of the coarsest level"
                    ),
                });
            }
        }
        Ok(())
    }

    /// The factor of the edge model's gap coefficient for the pair of bodies
    /// (`docs/impact.md`, section 4): 1 for a rigid striker; 1 + mu/mu_s for an elastic
    /// striker of the half-plane's wave speeds (both local solutions then share the
    /// exponents, and the gaps add); `None` otherwise (the edge is captured cell by cell).
    fn edge_gap_scale(&self, m: f64) -> Option<f64> {
        if !self.edge_model {
            return None;
        }
        match &self.striker {
            Striker::Rigid => Some(1.0),
            Striker::Elastic(s) if s.c1_ratio == 1.0 && (s.c2_ratio - m).abs() <= 1e-12 * m => {
                Some(1.0 + m * m / (s.density_ratio * s.c2_ratio * s.c2_ratio))
            }
            _ => None,
        }
    }

    /// Refuses a free striker whose deceleration the finest time step does not resolve
    /// (`docs/impact.md`, section 9): against the plane-wave impedance rho c1 2b of its
    /// widest contact, its speed relaxes with the time m0/(2 rho c1 b), and the step's
    /// constant force advances it by the trapezoidal factor (1 - r)/(1 + r),
    /// r = dt rho c1 b/m0, which turns negative, a spurious bounce, for r > 1.
    fn check_stiffness<T: Scalar>(&self, fine: &Run<T>) -> Result<()> {
        let Drive::Free { mass_ratio, .. } = self.drive else {
            return Ok(());
        };
        let b = fine.steps.iter().map(|s| s.b.to_f64()).fold(0.0, f64::max);
        let dt = fine.dt.to_f64();
        let r = dt * b / mass_ratio;
        if r > STIFF_RATIO {
            return Err(ImpactError::Grid {
                name: "dx",
                reason: format!(
                    "the striker's deceleration time m0/(2 rho c1 b) = {:.3e} R/c1 is shorter than half the time step c1 dt/R = {dt:.3e}, so the step's constant force would bounce it back: lower --dx or --kappa to c1 dt/R < {:.3e}, or raise --mass-ratio",
                    mass_ratio / (2.0 * b),
                    mass_ratio / b
                ),
            });
        }
        Ok(())
    }

    /// Solves the case on `levels` grids (dx, 2 dx, ...) in f64. `progress` is called with
    /// the fraction done.
    pub fn solve(&self, progress: impl FnMut(f64)) -> Result<Solution> {
        self.solve_at::<f64>(progress)
    }

    /// Solves the case as [`ImpactCase::solve`] at the precision T (`crate::scalar`: f64 or
    /// the double-double, about 32 digits): the discrete solution of the same grids to that
    /// precision (`docs/impact.md`, section 7). Above f64 the striker must be rigid and the
    /// profile one of the closed forms or a table (a user's function is evaluated in f64).
    pub fn solve_at<T: Scalar + CachedRules>(
        &self,
        mut progress: impl FnMut(f64),
    ) -> Result<Solution<T>> {
        self.solve_reporting::<T>(|p| progress(p.fraction))
    }

    /// Solves the case as [`ImpactCase::solve_at`], reporting every 64 steps where the march
    /// stands ([`Progress`]).
    pub fn solve_reporting<T: Scalar + CachedRules>(
        &self,
        mut report: impl FnMut(Progress),
    ) -> Result<Solution<T>> {
        self.validate()?;
        let extended = T::BITS > 53;
        if extended && !matches!(self.striker, Striker::Rigid) {
            return Err(invalid(
                "striker",
                self.striker.name(),
                "rigid: above f64 precision only the rigid striker is solved (the elastic and shell strikers' coefficients are f64)",
            ));
        }
        if extended && !self.profile.exact_at_every_precision() {
            return Err(invalid(
                "profile",
                self.profile.label(),
                "a closed form or a table: above f64 precision a user's function would be evaluated in f64",
            ));
        }
        let hp = HalfPlane::from_poisson(T::input(self.poisson))?;
        let m = *hp.m();
        let s_r = *hp.s_r();
        let m64 = m.to_f64();
        let motion = match &self.drive {
            Drive::Free {
                mass_ratio,
                v0_over_c1,
            } => Motion::Free {
                mass_ratio: *mass_ratio,
                v0: *v0_over_c1,
            },
            Drive::Speed(v) => Motion::DrivenSpeed(*v),
            Drive::Table(t) => Motion::DrivenTable(t.clone()),
        };
        // The levels share their time levels (`docs/impact.md`, section 5): the coarsest
        // step dt_c, and dt_c/2, dt_c/4, ... below it, so that every level has a value at
        // every reported time. To an end time, dt_c = end/N_c exactly (kappa then differs from
        // the request by under 1/(2 N_c) relative); to the separation, dt_c = kappa dx_c.
        let top = self.levels - 1;
        let coarse_nominal = self.kappa * self.dx * (1u64 << top) as f64;
        let (dt_coarse, coarse_steps): (T, Option<usize>) = match self.stop {
            Stop::AtEnd => {
                let n = (self.end / coarse_nominal).round().max(1.0) as usize;
                (T::input(self.end) / n as f64, Some(n))
            }
            Stop::AtSeparation => (
                T::input(self.kappa) * T::input(self.dx) * (1u64 << top) as f64,
                None,
            ),
        };
        // each level's cell width: the input dx times 2^level, the flat punch's adjusted so
        // that its cells exactly cover [0, a]
        let level_dx = |level: usize| -> T {
            let grid_dx = T::input(self.dx) * (1u64 << level) as f64;
            match self.profile {
                Profile::Flat { half_width } => {
                    let cells = (half_width / grid_dx.to_f64() - 0.5).round().max(1.0);
                    T::input(half_width) / (cells + 0.5)
                }
                _ => grid_dx,
            }
        };
        let level_dt = |level: usize| dt_coarse / (1u64 << (top - level)) as f64;
        // the tables by kappa = dt/dx: one set for every level, except the flat punch's
        let shared_kappa = !matches!(self.profile, Profile::Flat { .. });
        let mut shared_tables = if shared_kappa {
            Some(Tables::new(hp.clone(), level_dt(0) / level_dx(0))?)
        } else {
            None
        };
        let mut shared = match (&self.striker, shared_kappa) {
            (Striker::Elastic(_), true) => {
                self.striker
                    .compliance(m64, self.dx, (level_dt(0) / level_dx(0)).to_f64())?
            }
            _ => None,
        };
        let valid_end = self.striker.validity_end();
        let mut runs: Vec<Option<Run<T>>> = (0..self.levels).map(|_| None).collect();
        // to an end time: coarse first (cost ~ steps^2, the finest level dominates); to the
        // separation: the finest first, which sets the common end
        let order: Vec<usize> = match self.stop {
            Stop::AtEnd => (0..self.levels).rev().collect(),
            Stop::AtSeparation => (0..self.levels).collect(),
        };
        let total: f64 = (0..self.levels).map(|l| 0.25f64.powi(l as i32)).sum();
        let mut done = 0.0;
        let mut common_end: Option<(usize, T)> = coarse_steps.map(|n| (n, T::input(self.end)));
        for level in order {
            let grid_dx = level_dx(level);
            let dt = level_dt(level);
            let kappa = dt / grid_dx;
            let dx = grid_dx.to_f64();
            let mut own_tables = match shared_tables {
                Some(_) => None,
                None => Some(Tables::new(hp.clone(), kappa)?),
            };
            let tables = match (own_tables.as_mut(), shared_tables.as_mut()) {
                (Some(t), _) | (None, Some(t)) => t,
                (None, None) => unreachable!("one set of tables exists"),
            };
            let mut own = match (&self.striker, shared_kappa) {
                (Striker::Shell(_), _) | (Striker::Elastic(_), false) => {
                    self.striker.compliance(m64, dx, kappa.to_f64())?
                }
                _ => None,
            };
            let scale = 1u64 << (top - level);
            // the steps of this level to the common end, if known, and the cap
            let cap_steps = ((self.end.min(valid_end) / dt.to_f64()) + 1e-9).floor() as usize;
            let target = common_end.map(|(n, end)| (n * scale as usize, end));
            let horizon = match self.stop {
                Stop::AtEnd => target.map_or(cap_steps, |(n, _)| n),
                Stop::AtSeparation => cap_steps,
            };
            let mut march = March::new(
                &mut *tables,
                own.as_mut()
                    .or(shared.as_mut())
                    .and_then(|c| T::striker_rows(c)),
                &self.profile,
                &motion,
                self.law,
                grid_dx,
                dt,
            )
            .with_edge_gap_scale(self.edge_gap_scale(m64).map(T::of))
            .with_horizon(horizon)
            .with_memory_limit(self.memory_limit);
            if let Some((n, end)) = target {
                march = march.with_end(n, end);
            }
            let weight = 0.25f64.powi(level as i32) / total;
            let mut goal = target.map(|(n, _)| n);
            let mut n = 0usize;
            loop {
                match goal {
                    Some(g) if n >= g => {
                        // to the separation, a coarser level still in contact at the common
                        // end goes on to its own separation (its restitution is its own)
                        let on =
                            self.stop == Stop::AtSeparation && !march.separated() && n < cap_steps;
                        if !on {
                            break;
                        }
                    }
                    None if march.separated() || n >= cap_steps => {
                        // the finest level sets the common end: the first coarse step at
                        // least one coarse step after its separation (or the cap)
                        let t_stop = match march.separations.last() {
                            Some(&ts) if march.separated() => ts,
                            _ => march.time(n),
                        };
                        let nc = ((t_stop / dt_coarse).to_f64() + 1e-9).floor() as usize + 2;
                        let nc = nc.min(cap_steps / scale as usize).max(1);
                        let end = dt_coarse * nc as f64;
                        common_end = Some((nc, end));
                        let g = nc * scale as usize;
                        goal = Some(g);
                        if g > n {
                            march = march.with_end(g, end);
                        }
                        continue;
                    }
                    _ => {}
                }
                if n >= cap_steps {
                    break;
                }
                march.step()?;
                n += 1;
                if n % 64 == 0 {
                    let frac = n as f64 / goal.unwrap_or(cap_steps).max(1) as f64;
                    report(Progress {
                        fraction: done + weight * frac.min(1.0),
                        level,
                        step: n,
                        t: march.time(n).to_f64(),
                    });
                }
            }
            done += weight;
            let (steps, separations, reimpacts) = (
                std::mem::take(&mut march.steps),
                std::mem::take(&mut march.separations),
                std::mem::take(&mut march.reimpacts),
            );
            drop(march);
            let striker_err = own
                .as_ref()
                .or(shared.as_ref())
                .map(|c| c.error())
                .unwrap_or(0.0);
            let coefficient_error = tables.error() + striker_err;
            runs[level] = Some(Run {
                dx: grid_dx,
                dt,
                steps,
                separations,
                reimpacts,
                coefficient_error,
            });
        }
        let runs: Vec<Run<T>> = runs.into_iter().flatten().collect();
        self.check_stiffness(&runs[0])?;
        report(Progress {
            fraction: 1.0,
            level: 0,
            step: runs.first().map_or(0, |r| r.steps.len()),
            t: runs
                .first()
                .and_then(|r| r.steps.last())
                .map_or(0.0, |s| s.t.to_f64()),
        });
        Ok(Solution {
            case: self.clone(),
            m,
            s_r,
            mass: match motion {
                Motion::Free { mass_ratio, .. } => Some(T::input(mass_ratio) / (m * m)),
                _ => None,
            },
            runs,
        })
    }
}

/// One grid's history, at the precision T.
#[derive(Clone, Debug)]
pub struct Run<T = f64> {
    /// Cell width (units R).
    pub dx: T,
    /// Time step (units R/c1).
    pub dt: T,
    /// The steps.
    pub steps: Vec<StepState<T>>,
    /// The times the contact ended, in order (the end of the last step in contact).
    pub separations: Vec<T>,
    /// The times contact began again after a separation.
    pub reimpacts: Vec<T>,
    /// A bound of the error of the normalised influence coefficients used (quadrature of the
    /// half-plane's and an elastic striker's tables, truncation of a shell's modal sums).
    pub coefficient_error: f64,
}

/// The reported edge's smoothing window, in cell crossings (`Run::edge_at`).
pub const EDGE_CROSSINGS: f64 = 3.0;

/// The largest window of the reported edge's smoothing, in steps (`Run::edge_at`).
pub const EDGE_WINDOW_STEPS: usize = 40;

/// The largest window of the reported force's smoothing, in steps (`Run::force_at`): one
/// crossing takes 1/(kappa |db/dt|) steps on every grid (37 near the reference case's peak
/// force), and three of them are needed to average the force's sawtooth out
/// (`docs/impact.md`, section 4).
pub const FORCE_WINDOW_STEPS: usize = 120;

impl<T: Scalar> Run<T> {
    /// Step n (time t_n = n dt, n >= 1), if the march reached it.
    pub fn step(&self, n: usize) -> Option<&StepState<T>> {
        n.checked_sub(1).and_then(|i| self.steps.get(i))
    }

    /// The contact half-width at t_n (`docs/impact.md`, section 4, the edge's report): the
    /// edge of step n where it stands for t_n (geometric); otherwise the value at t_n of the
    /// least-squares quadratic through the steps' edges (at the times they stand for) over a
    /// window of [`EDGE_CROSSINGS`] cell crossings centred on t_n (at most
    /// [`EDGE_WINDOW_STEPS`] steps, narrowed to stay symmetric within the steps whose edges
    /// the pressures set), which averages out the edge's phase error within its cell; where
    /// the window holds fewer than five edges, the edges of the two steps around t_n
    /// interpolated.
    pub fn edge_at(&self, n: usize) -> Option<T> {
        let s = self.step(n)?;
        if s.edge_time == s.t {
            return Some(s.b);
        }
        let mid = |x: &StepState<T>| x.edge_time != x.t && x.b > 0.0;
        self.crossing_fit(n, EDGE_WINDOW_STEPS, mid, |x| (x.edge_time, x.b))
            .or_else(|| self.edge_interpolated(n))
    }

    /// The value at t_n of the least-squares quadratic through `value` (time, value) of the
    /// steps in a window of [`EDGE_CROSSINGS`] cell crossings of the edge centred on step n,
    /// at most `cap` steps and narrowed to stay symmetric within the block of steps around n
    /// that satisfy `eligible` (n among them); `None` where the window holds fewer than five
    /// steps (`docs/impact.md`, section 4: the edge's phase within its cell leaves a sawtooth
    /// of one crossing's period in the per-step values, which the fit averages out).
    fn crossing_fit(
        &self,
        n: usize,
        cap: usize,
        eligible: impl Fn(&StepState<T>) -> bool,
        value: impl Fn(&StepState<T>) -> (T, T),
    ) -> Option<T> {
        let s = self.step(n)?;
        let ok = |m: usize| self.step(m).is_some_and(&eligible);
        if !ok(n) {
            return None;
        }
        // the block of eligible steps around n
        let (mut first, mut last) = (n, n);
        while first > 1 && ok(first - 1) && n - first < cap {
            first -= 1;
        }
        while ok(last + 1) && last - n < cap {
            last += 1;
        }
        // the window (a choice of steps, taken in f64)
        let (dx, dt) = (self.dx.to_f64(), self.dt.to_f64());
        let b = |m: usize| self.step(m).map_or(0.0, |x| x.b.to_f64());
        let k = (n - first).min(last - n).min(5);
        let speed = if k > 0 {
            ((b(n + k) - b(n - k)) / (2.0 * k as f64 * dt)).abs()
        } else {
            0.0
        };
        let steps = (EDGE_CROSSINGS * dx / (speed * dt)).min(cap as f64);
        let half = ((0.5 * steps) as usize).min(n - first).min(last - n);
        if half < 2 {
            return None;
        }
        // normal equations of a + c1 x + c2 x^2, x = (time - t_n)/width
        let width = self.dt * (half as f64 + 0.5);
        let zero = T::of(0.0);
        let (mut m, mut r) = (vec![zero; 9], [zero; 3]);
        for j in n - half..=n + half {
            let (time, v) = value(self.step(j)?);
            let x = (time - s.t) / width;
            let phi = [T::of(1.0), x, x * x];
            for i in 0..3 {
                for (mij, &pj) in m[3 * i..3 * i + 3].iter_mut().zip(&phi) {
                    *mij += phi[i] * pj;
                }
                r[i] += phi[i] * v;
            }
        }
        crate::linalg::Lu::new(m, 3)
            .and_then(|lu| lu.solve(&r))
            .map(|c| c[0])
    }

    /// The edge at t_n interpolated between the edges of the steps around it by the times
    /// they stand for (`StepState::edge_time`; the last step's extrapolated from the two
    /// before).
    pub fn edge_interpolated(&self, n: usize) -> Option<T> {
        let s = self.step(n)?;
        let (a, b) = match (
            self.step(n + 1),
            n.checked_sub(1).and_then(|m| self.step(m)),
        ) {
            (Some(next), _) => (s, next),
            (None, Some(before)) => (before, s),
            (None, None) => return Some(s.b),
        };
        let span = b.edge_time - a.edge_time;
        if !(span > 0.0) {
            return Some(s.b);
        }
        Some(a.b + (b.b - a.b) * (s.t - a.edge_time) / span)
    }

    /// The force at t_n (`docs/impact.md`, sections 3 and 4): a step's force stands for the
    /// middle of the step, and it carries the sawtooth of the edge's cell crossings (large
    /// under the kinematic law, whose edge cell has no condition of its own), so the value at
    /// t_n of the least-squares quadratic through the steps' forces over a window of
    /// [`EDGE_CROSSINGS`] cell crossings (at most [`FORCE_WINDOW_STEPS`] steps, symmetric
    /// within the steps in contact); where that window holds fewer than five steps,
    /// [`Run::force_interpolated`].
    pub fn force_at(&self, n: usize) -> Option<T> {
        let dt = self.dt;
        self.crossing_fit(
            n,
            FORCE_WINDOW_STEPS,
            |x| !x.pressure.is_empty(),
            |x| (x.t - dt * 0.5, x.force),
        )
        .or_else(|| self.force_interpolated(n))
    }

    /// The force at t_n from the two steps around it (their forces stand for the middles of
    /// the steps): their mean, the last step's extrapolated from the two before it.
    pub fn force_interpolated(&self, n: usize) -> Option<T> {
        let f = |n: usize| self.step(n).map(|s| s.force);
        match (f(n), f(n + 1)) {
            (Some(a), Some(b)) => Some((a + b) * 0.5),
            (Some(a), None) if n >= 2 => f(n - 1).map(|z| a * 1.5 - z * 0.5),
            (a, _) => a,
        }
    }
}

/// The safety factor on the grids' differences in every error estimate of a history and a
/// pressure profile (`docs/impact.md`, section 5): the contact set moves cell by cell, so the
/// error is not smooth in dx.
const ESTIMATE_SAFETY: f64 = 4.0;

/// A pressure profile of the finest grid ([`Solution::pressure_profile`]).
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

/// A value with its absolute error estimate (from refinement; `None` with one level).
#[derive(Clone, Copy, Debug)]
pub struct Value<T = f64> {
    /// The finest grid's value.
    pub value: T,
    /// Absolute error estimate.
    pub err: Option<f64>,
}

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

/// The rebound of a free striker, after its last separation ([`Solution::rebound`]).
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

/// The observed convergence order of each quantity.
#[derive(Clone, Debug)]
pub struct Orders {
    /// Order of h.
    pub h: Option<f64>,
    /// Order of b.
    pub b: Option<f64>,
    /// Order of the force.
    pub force: Option<f64>,
}

/// A solved case, at the precision T.
#[derive(Clone, Debug)]
pub struct Solution<T = f64> {
    /// The inputs.
    pub case: ImpactCase,
    /// c2/c1.
    pub m: T,
    /// c_R/c1.
    pub s_r: T,
    mass: Option<T>,
    /// The runs, finest first.
    pub runs: Vec<Run<T>>,
}

fn order(fine: &[f64], mid: &[f64], coarse: &[f64]) -> Option<f64> {
    let d1: f64 = fine.iter().zip(mid).map(|(a, b)| (a - b).abs()).sum();
    let d2: f64 = mid.iter().zip(coarse).map(|(a, b)| (a - b).abs()).sum();
    (d1 > 0.0 && d2 > 0.0).then(|| (d2 / d1).log2())
}

impl<T: Scalar> Solution<T> {
    /// The reporting interval: the coarsest level's time step (its times are steps of every
    /// level).
    pub fn report_dt(&self) -> T {
        self.runs.last().map(|r| r.dt).unwrap_or(T::of(0.0))
    }

    /// The estimate of a quantity known on every level (finest first) as one number per
    /// level: the difference of the two finest levels (or half that of the next pair, if
    /// larger), extrapolated with the observed order where three levels show one above 1/2,
    /// times the safety factor of the histories; `None` with one level.
    fn level_estimate(values: &[f64]) -> Option<f64> {
        if values.len() < 2 || values.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let d1 = (values[0] - values[1]).abs();
        let d2 = values.get(2).map(|c| (values[1] - c).abs());
        let factor = match d2 {
            Some(d2) if d1 > 0.0 && d2 > 0.0 => {
                let p = (d2 / d1).log2();
                if p > 0.5 {
                    (1.0 / (2f64.powf(p) - 1.0)).max(1.0)
                } else {
                    2.0
                }
            }
            _ => 1.0,
        };
        Some(ESTIMATE_SAFETY * d1.max(0.5 * d2.unwrap_or(0.0)) * factor)
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
            Self::level_estimate(&pick(q))
        };
        Ok(Rebound {
            separation: Value {
                value: sep,
                err: est(0).map(|e| e.max(fine.dt.to_f64())),
            },
            restitution: Value {
                value: res,
                err: est(1),
            },
            energy_to_half_plane: Value {
                value: work,
                err: est(2),
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
        let getters: [Getter<'_, T>; 7] = [
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
        let ords: Vec<Option<f64>> = (0..7)
            .map(|q| {
                if self.runs.len() < 3 {
                    return None;
                }
                let s = &low[q];
                order(&s[0][..nuse], &s[1][..nuse], &s[2][..nuse])
            })
            .collect();
        let est = |q: usize, i: usize| -> Option<f64> {
            if self.runs.len() < 2 {
                return None;
            }
            // the level differences over the neighbouring report times, and the coarser
            // pair scaled down by first order: the contact set moves cell by cell, so a
            // difference may happen to be small at one time
            let mut d: f64 = 0.0;
            for j in i.saturating_sub(4)..(i + 5).min(nuse.max(i + 1)) {
                // the differences in T, then rounded
                d = d.max((samples[q][0][j] - samples[q][1][j]).abs().to_f64());
                if let Some(c) = samples[q].get(2) {
                    d = d.max(0.5 * (samples[q][1][j] - c[j]).abs().to_f64());
                }
            }
            if !d.is_finite() {
                return None;
            }
            // Richardson with the observed order, never below the last difference
            let factor = ords[q]
                .filter(|p| *p > 0.0)
                .map(|p| (1.0 / (2f64.powf(p) - 1.0)).max(1.0))
                .unwrap_or(1.0);
            Some(ESTIMATE_SAFETY * d * factor)
        };
        let mut rows = Vec::with_capacity(times.len());
        for (i, &t) in times.iter().enumerate() {
            let st = &fine.steps[step_at(fine, i) - 1];
            let val = |q: usize, scale: T| Value {
                value: samples[q][0][i] * scale,
                err: if i < nuse {
                    est(q, i).map(|e| e * scale.to_f64().abs())
                } else {
                    None
                },
            };
            let bdot = {
                let b = |j: usize| samples[2][0][j];
                let (a, c) = (i.saturating_sub(1), (i + 1).min(times.len() - 1));
                if c > a {
                    (b(c) - b(a)) / (times[c] - times[a])
                } else {
                    zero
                }
            };
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
                    err: if i < nuse { e } else { None },
                }
            });
            let work = Value {
                value: st.work * m2,
                err: kinetic.and_then(|k| k.err),
            };
            let deformable = !matches!(self.case.striker, Striker::Rigid);
            // under Signorini's law the continuum's defect is exactly 0, so the defect is its
            // own error and its estimate is never below it (`docs/impact.md`, section 9)
            let defect = energy.map(|_| {
                let mut d = val(6, one);
                if self.case.law == EdgeLaw::Signorini {
                    let own = d.value.to_f64().abs();
                    d.err = Some(d.err.map_or(own, |e| e.max(own)));
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
            },
        )
    }

    /// Pressure profile p/(rho c1^2) of the finest grid's step whose middle is nearest to
    /// c1 t/R = `t` (a step's pressures stand for the middle of the step, `docs/impact.md`,
    /// section 3): (that time, the cell centres x/R, the pressures).
    pub fn pressure_at(&self, t: f64) -> Option<(T, Vec<T>, Vec<T>)> {
        self.pressure_profile(t).map(|p| (p.t, p.x, p.p))
    }

    /// The pressure profile of [`Solution::pressure_at`] with an error estimate per cell
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

impl Solution<f64> {
    /// The shell striker's strain and vibration kinetic energy over rho c1^2 R^2 after each
    /// step of the finest grid, (c1 t/R, strain, kinetic), by the modal recursion of
    /// [`shell_energies`] (independent of the coefficient tables); `None` for other strikers.
    pub fn shell_energies(&self) -> Option<Result<Vec<(f64, f64, f64)>>> {
        self.run_shell_energies(&self.runs[0])
    }

    fn run_shell_energies(&self, run: &Run) -> Option<Result<Vec<(f64, f64, f64)>>> {
        let Striker::Shell(shell) = &self.case.striker else {
            return None;
        };
        let m2 = self.m * self.m;
        Some((|| {
            let ring = Ring::new(shell, self.m)?;
            let pressures: Vec<Vec<f64>> = run.steps.iter().map(|s| s.pressure.clone()).collect();
            let e = shell_energies(&ring, run.dx, run.dt, &pressures)?;
            Ok(run
                .steps
                .iter()
                .zip(e)
                .map(|(s, (u, k))| (s.t, u * m2, k * m2))
                .collect())
        })())
    }

    /// The shell striker's (strain, vibration kinetic) energy over rho c1^2 R^2 at the times
    /// of `rows` (from [`Solution::history`]), each with an error estimate: four times the
    /// difference between the two finest levels (the factor of the history's estimates),
    /// plus the modal truncation bound. `None` for other strikers.
    pub fn shell_energy_history(&self, rows: &[HistoryRow]) -> Option<Result<Vec<(Value, Value)>>> {
        let fine = match self.run_shell_energies(&self.runs[0])? {
            Ok(v) => v,
            Err(e) => return Some(Err(e)),
        };
        let coarse = match self.runs.get(1).map(|r| self.run_shell_energies(r)) {
            Some(Some(Ok(v))) => Some(v),
            Some(Some(Err(e))) => return Some(Err(e)),
            _ => None,
        };
        let at = |list: &[(f64, f64, f64)], dt: f64, t: f64| -> Option<(f64, f64)> {
            let n = (t / dt).round() as usize;
            (n >= 1)
                .then(|| list.get(n - 1).map(|e| (e.1, e.2)))
                .flatten()
        };
        let mut out = Vec::with_capacity(rows.len());
        for r in rows {
            let (u, k) = match at(&fine, self.runs[0].dt, r.t) {
                Some(v) => v,
                None => {
                    return Some(Err(ImpactError::Step {
                        time: format!("{:.6}", r.t),
                        reason: "no step of the finest grid at this report time".into(),
                    }))
                }
            };
            let floor = self.runs[0].coefficient_error * (u + k).abs();
            let err = coarse.as_ref().and_then(|c| {
                at(c, self.runs[1].dt, r.t)
                    .map(|(uc, kc)| (4.0 * (u - uc).abs() + floor, 4.0 * (k - kc).abs() + floor))
            });
            out.push((
                Value {
                    value: u,
                    err: err.map(|e| e.0),
                },
                Value {
                    value: k,
                    err: err.map(|e| e.1),
                },
            ));
        }
        Some(Ok(out))
    }
}

impl<T: Scalar> Solution<T> {
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
/// be reported as a peak ([`Solution::peak_force`]).
pub const PEAK_DROP: f64 = 0.99;

#[cfg(test)]
mod tests {
    use super::*;

    /// A run whose edges follow a smooth b(t) plus a sawtooth of one cell crossing's period
    /// and zero mean (the phase error of the edge cell), at the middle of each step.
    fn sawtooth_run(amplitude: f64) -> (Run, impl Fn(f64) -> f64) {
        let (dx, dt) = (0.01, 0.02);
        let truth = |t: f64| 0.05 + 0.05 * t - 0.002 * t * t;
        let steps = (1..=400)
            .map(|n| {
                let t = n as f64 * dt;
                let tau = t - 0.5 * dt;
                let phase = (truth(tau) / dx).fract();
                StepState {
                    t,
                    h: 0.0,
                    v: 0.0,
                    k: 0,
                    b: truth(tau) + amplitude * dx * (phase - 0.5),
                    edge_time: tau,
                    force: 0.0,
                    pressure: Vec::new(),
                    w: Vec::new(),
                    ws: Vec::new(),
                    work: 0.0,
                    striker_work: 0.0,
                }
            })
            .collect();
        let run = Run {
            dx,
            dt,
            steps,
            separations: Vec::new(),
            reimpacts: Vec::new(),
            coefficient_error: 0.0,
        };
        (run, truth)
    }

    #[test]
    fn the_reported_edge_averages_out_the_phase_sawtooth() {
        let (run, truth) = sawtooth_run(0.02);
        let (mut smooth, mut raw) = (0.0f64, 0.0f64);
        // away from the run's ends, where the window is whole
        for n in 60..=340 {
            let t = n as f64 * run.dt;
            smooth = smooth.max((run.edge_at(n).unwrap() - truth(t)).abs() / run.dx);
            raw = raw.max((run.edge_interpolated(n).unwrap() - truth(t)).abs() / run.dx);
        }
        // the sawtooth's amplitude is 0.01 cells
        assert!(raw > 0.008, "raw edge error {raw} cells");
        assert!(
            smooth < 0.002,
            "smoothed edge error {smooth} cells (raw {raw})"
        );
        // a smooth quadratic history is reproduced to rounding, up to two steps from the
        // run's ends (where the edges are interpolated)
        let (run, truth) = sawtooth_run(0.0);
        for n in 3..=398 {
            let t = n as f64 * run.dt;
            let e = (run.edge_at(n).unwrap() - truth(t)).abs();
            assert!(e < 1e-12, "step {n}: {e}");
        }
        for n in [1, 2, 399, 400] {
            let t = n as f64 * run.dt;
            let e = (run.edge_at(n).unwrap() - truth(t)).abs();
            assert!(e < 1e-3 * run.dx, "step {n}: {e}");
        }
    }

    /// The force of a smooth history plus the sawtooth of the edge's crossings (a drop at
    /// each cell's entry, then a rise through the crossing, zero mean), as under the
    /// kinematic law: the report removes the sawtooth and reproduces a quadratic history.
    #[test]
    fn the_reported_force_averages_out_the_crossing_sawtooth() {
        let force = |t: f64| 1.0 + 0.3 * t - 0.02 * t * t;
        let with_sawtooth = |amplitude: f64| {
            let (mut run, _) = sawtooth_run(0.0);
            let dx = run.dx;
            for s in run.steps.iter_mut() {
                let tau = s.t - 0.5 * run.dt;
                let phase = (s.b / dx).fract();
                s.force = force(tau) + amplitude * (phase - 0.5);
                s.pressure = vec![s.force];
            }
            run
        };
        let run = with_sawtooth(0.03);
        let (mut smooth, mut raw) = (0.0f64, 0.0f64);
        for n in 100..=300 {
            let t = n as f64 * run.dt;
            smooth = smooth.max((run.force_at(n).unwrap() - force(t)).abs());
            raw = raw.max((run.force_interpolated(n).unwrap() - force(t)).abs());
        }
        // the sawtooth's amplitude is 0.015
        assert!(raw > 0.012, "raw force error {raw}");
        assert!(smooth < 0.003, "smoothed force error {smooth} (raw {raw})");
        let run = with_sawtooth(0.0);
        for n in 3..=398 {
            let t = n as f64 * run.dt;
            let e = (run.force_at(n).unwrap() - force(t)).abs();
            assert!(e < 1e-12, "step {n}: {e}");
        }
        // a step out of contact (205, given a wild force here) bounds the windows: it
        // enters no fit on either side
        let mut run = with_sawtooth(0.0);
        run.steps[204].pressure.clear();
        run.steps[204].force = 1e3;
        for n in [200, 210] {
            let t = n as f64 * run.dt;
            let e = (run.force_at(n).unwrap() - force(t)).abs();
            assert!(e < 1e-9, "step {n}: {e}");
        }
    }

    #[test]
    fn a_geometric_edge_is_reported_as_it_is() {
        let (mut run, _) = sawtooth_run(0.02);
        let s = &mut run.steps[199];
        s.edge_time = s.t;
        assert_eq!(run.edge_at(200), Some(run.steps[199].b));
    }
}
