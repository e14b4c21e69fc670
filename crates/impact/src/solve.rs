//! Solving an impact case: the march on every refinement level (the finest grid dx and 2, 4,
//! ... times coarser) sharing their time levels, the stiffness check of a free striker, and
//! the progress reported on the way (`docs/impact.md`, section 5).

use std::ops::ControlFlow;

use complexfn::quadrature::CachedRules;
use lamb::HalfPlane;

use crate::case::{Drive, ImpactCase, Stop};
use crate::error::{invalid, ImpactError, Result};
use crate::march::March;
use crate::profile::Profile;
use crate::run::Run;
use crate::scalar::Scalar;
use crate::solved::SolvedImpact;
use crate::solved::CYLINDER_MODES_BELOW;
use crate::striker::disk::Disk;
use crate::striker::Striker;
use crate::tables::Tables;

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

/// The precisions a case is solved at, f64 and the double-double [`complexfn::Dd`]: each
/// solves through one non-generic entry compiled in this crate, so that a caller's crate does
/// not compile the march again.
pub trait Solvable: Scalar + CachedRules {
    /// Solves `case` at this precision ([`ImpactCase::solve_reporting`]).
    fn solve_case(
        case: &ImpactCase,
        report: &mut dyn FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<SolvedImpact<Self>>;
}

/// The entry of each precision, compiled here.
macro_rules! solvable {
    ($($t:ty),*) => {$(
        impl Solvable for $t {
            #[inline(never)]
            fn solve_case(
                case: &ImpactCase,
                report: &mut dyn FnMut(Progress) -> ControlFlow<()>,
            ) -> Result<SolvedImpact<Self>> {
                case.solve_dyn(report)
            }
        }
    )*};
}

solvable!(f64, complexfn::Dd);

impl ImpactCase {
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
    pub fn solve(&self, progress: impl FnMut(f64)) -> Result<SolvedImpact> {
        self.solve_at::<f64>(progress)
    }

    /// Solves the case as [`ImpactCase::solve`] at the precision T (`crate::scalar`: f64 or
    /// the double-double, about 32 digits): the discrete solution of the same grids to that
    /// precision (`docs/impact.md`, section 7). Above f64 the striker must be rigid and the
    /// profile one of the closed forms or a table (a user's function is evaluated in f64).
    pub fn solve_at<T: Solvable>(&self, mut progress: impl FnMut(f64)) -> Result<SolvedImpact<T>> {
        self.solve_reporting::<T>(|p| {
            progress(p.fraction);
            ControlFlow::Continue(())
        })
    }

    /// Solves the case as [`ImpactCase::solve_at`], reporting every 64 steps where the march
    /// stands ([`Progress`]). When `report` answers [`ControlFlow::Break`], the march stops
    /// there and the solve ends with [`ImpactError::Stopped`] (a caller's interrupt).
    pub fn solve_reporting<T: Solvable>(
        &self,
        mut report: impl FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<SolvedImpact<T>> {
        T::solve_case(self, &mut report)
    }

    /// [`ImpactCase::solve_reporting`] behind its generic shim and [`Solvable`]: one copy per
    /// precision, compiled in this crate, not one per caller's closure and crate.
    fn solve_dyn<T: Scalar + CachedRules>(
        &self,
        report: &mut dyn FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<SolvedImpact<T>> {
        self.validate()?;
        let extended = T::BITS > 53;
        if extended && !matches!(self.striker, Striker::Rigid) {
            return Err(invalid(
                "striker",
                self.striker.name(),
                "rigid: above f64 precision only the rigid striker is solved (the elastic and shell strikers' coefficients are f64)",
            ));
        }
        // a cylinder's modes (for its energies) on another thread while the march goes on
        let modes_job = match self.striker {
            Striker::Cylinder(mat) => Some(std::thread::spawn(move || {
                Disk::new(mat.poisson()).and_then(|d| d.modes(CYLINDER_MODES_BELOW))
            })),
            _ => None,
        };
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
                    .compliance(m64, self.dx, (level_dt(0) / level_dx(0)).to_f64(), 0)?
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
            let scale = 1u64 << (top - level);
            // the steps of this level to the common end, if known, and the cap
            let cap_steps = ((self.end.min(valid_end) / dt.to_f64()) + 1e-9).floor() as usize;
            let target = common_end.map(|(n, end)| (n * scale as usize, end));
            let horizon = match self.stop {
                Stop::AtEnd => target.map_or(cap_steps, |(n, _)| n),
                Stop::AtSeparation => cap_steps,
            };
            let mut own = match (&self.striker, shared_kappa) {
                (Striker::Shell(_) | Striker::Cylinder(_), _) | (Striker::Elastic(_), false) => {
                    self.striker
                        .compliance(m64, dx, kappa.to_f64(), horizon + 1)?
                }
                _ => None,
            };
            let mut march = March::new(
                &mut *tables,
                own.as_mut()
                    .or(shared.as_mut())
                    .and_then(|c| T::striker_rows(c)),
                &self.profile,
                &self.drive,
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
                    let answer = report(Progress {
                        fraction: done + weight * frac.min(1.0),
                        level,
                        step: n,
                        t: march.time(n).to_f64(),
                    });
                    if answer.is_break() {
                        return Err(ImpactError::Stopped {
                            time: march.time(n).to_f64(),
                        });
                    }
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
        let _ = report(Progress {
            fraction: 1.0,
            level: 0,
            step: runs.first().map_or(0, |r| r.steps.len()),
            t: runs
                .first()
                .and_then(|r| r.steps.last())
                .map_or(0.0, |s| s.t.to_f64()),
        });
        let disk_modes = modes_job.map(|job| {
            job.join().unwrap_or_else(|_| {
                Err(ImpactError::Step {
                    time: "0".into(),
                    reason: "the cylinder's modes could not be computed".into(),
                })
            })
        });
        Ok(SolvedImpact {
            case: self.clone(),
            m,
            s_r,
            mass: self.drive.mass(m),
            runs,
            disk_modes,
        })
    }
}
