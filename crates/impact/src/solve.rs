//! Solving an impact case: the march on every refinement level (the finest grid dx and 2, 4,
//! ... times coarser) sharing their time levels, the stiffness check of a free striker, and
//! the progress reported on the way (`docs/impact.md`, section 5).

use std::ops::ControlFlow;

use complexfn::quadrature::CachedRules;
use lamb::HalfPlane;

use crate::case::{Drive, ImpactCase, Stop};
use crate::error::{invalid, ImpactError, Result};
use crate::march::{merge_onto_coarser, recent_edge_speed, EdgeLaw, March, StepState};
use crate::profile::Profile;
use crate::run::{end_margin, window_margin, Run};
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

/// The contact's span, in cells of the next coarser grid, at which a finer start hands over
/// to it ([`ImpactCase::start_halvings`], `docs/impact.md`, section 11).
pub const START_CELLS: usize = 24;

/// The default of [`ImpactCase::start_halvings`]: the first steps of every level on cells 64
/// times finer (`docs/impact.md`, section 11).
pub const START_HALVINGS: usize = 6;

/// The steps of the finest level's grid over which a level lets go of the defect its start's
/// last hand-over leaves ([`crate::run::HandoverDefect`], `docs/impact.md`, section
/// 11). 16 to 128 and no decay at all were compared on the reference case and the parabola
/// driven at V/c1 = 0.05.
pub const HANDOVER_DEFECT_STEPS: usize = 128;

/// The most steps of one finer grid of the start ([`ImpactCase::start_halvings`]): it hands
/// over after as many steps at the latest (a fast edge that does not slow down, a contact
/// that stays narrow), which bounds the start's cost.
pub const START_STEPS: usize = 16 * START_CELLS;

/// The edge speed, in Rayleigh speeds, below which a finer grid of the start hands over
/// ([`ImpactCase::start_halvings`]): under it the coarser grid's edge model is accurate from
/// the first step (between it and the sub-cell model's limit
/// `FREE_EDGE_SPEED` the edge's error on a coarse grid is several times larger, section 11).
pub const START_EDGE_SPEED: f64 = 0.5;

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
    /// Whether the levels start on finer grids ([`ImpactCase::start_halvings`]): for a rigid
    /// striker of a curved profile under Signorini's law (`docs/impact.md`, section 11).
    pub fn starts_finer(&self) -> bool {
        self.start_halvings > 0
            && matches!(self.striker, Striker::Rigid)
            && matches!(self.law, EdgeLaw::Signorini)
            && !matches!(self.profile, Profile::Flat { .. })
    }

    /// The first steps of a level's march on (dx, dt), marched on grids 2, 4, ..., 2^depth
    /// times finer and merged onto it (`docs/impact.md`, section 11). The grid of stage j
    /// (dx/2^j) hands over to stage j - 1 once its edge is slower than [`START_EDGE_SPEED`]
    /// c_R and the contact spans [`START_CELLS`] cells of the finest level's grid of stage
    /// j - 1 (`finest`: that level's dx and dt, or [`ImpactCase::start_grid`]'s), or at the
    /// latest after [`START_STEPS`] of that grid's steps, or after `most` steps of this level,
    /// or when the striker has left; not within [`crate::run::FORCE_WINDOW_STEPS`] steps of
    /// the finest level's grid of stage j before the level's end (it then goes on to the
    /// end). The hand-over times are the same for every level, so that at every time the
    /// levels' grids stand in the ratio of their dx (the levels' differences keep measuring
    /// the error). A stage marches half a report window past its hand-over, and past the
    /// level's end where it goes on to the end and `past_end` allows it (the drive and the
    /// striker's model go on there), so that its reports of the steps it hands over take
    /// whole windows.
    #[allow(clippy::too_many_arguments)]
    fn fine_start<T: Scalar + CachedRules>(
        &self,
        tables: &mut Tables<T>,
        (dx, dt): (T, T),
        finest: (f64, f64),
        stage: usize,
        depth: usize,
        most: usize,
        gap_scale: Option<T>,
        past_end: bool,
    ) -> Result<Vec<StepState<T>>> {
        if stage > depth || most == 0 {
            return Ok(Vec::new());
        }
        let (fdx, fdt) = (dx * 0.5, dt * 0.5);
        let seeds = self.fine_start(
            &mut *tables,
            (fdx, fdt),
            finest,
            stage + 1,
            depth,
            2 * most,
            gap_scale,
            past_end,
        )?;
        let slow_below = *tables.half_plane().s_r() * START_EDGE_SPEED;
        let scale = 0.5f64.powi(stage as i32);
        let mut march = March::new(
            &mut *tables,
            None,
            &self.profile,
            &self.drive,
            self.law,
            fdx,
            fdt,
        )
        .with_edge_gap_scale(gap_scale)
        .with_memory_limit(self.memory_limit);
        for s in seeds {
            march.seed(s)?;
        }
        let wide = finest.0 * START_CELLS as f64 * scale * 2.0;
        let until = finest.1 * START_STEPS as f64 * scale;
        // the report window of the finest level's grid of this stage, in time (the same on
        // every level), and this level's end
        let room_after = finest.1 * crate::run::FORCE_WINDOW_STEPS as f64 * scale;
        let end = dt.to_f64() * most as f64 * (1.0 - 1e-9);
        loop {
            let n = march.steps.len();
            if n > 0 && n % 2 == 0 {
                let last = &march.steps[n - 1];
                // the edge slow enough for the coarser grid's edge model, and wide
                let slow = crate::march::recent_edge_speed(&march.steps, fdt) < slow_below;
                let spans = slow && last.b.to_f64() >= wide;
                let late = last.t.to_f64() >= until * (1.0 - 1e-9);
                // not within a report window of the level's end (the coarser grid's first
                // steps would set the last reports alone): this grid goes on to the end
                let room = last.t.to_f64() + room_after <= end;
                if (room && (spans || late)) || n >= 2 * most || march.separated() {
                    break;
                }
            }
            march.step()?;
        }
        // a few steps past the hand-over, so that the finer run's reports of the steps handed
        // over take their whole windows (`Run::force_at`: half of EDGE_CROSSINGS cell
        // crossings of the edge, at most half of FORCE_WINDOW_STEPS, after the step), not the
        // one-sided fits of a run's end
        // (at the level's end too, where the run goes on past it: `Run::beyond`)
        let handed = march.steps.len();
        let at_end = handed >= 2 * most;
        if (!at_end || past_end) && !march.separated() {
            let speed = recent_edge_speed(&march.steps, fdt).to_f64();
            let most_past = if at_end {
                end_margin(handed)
            } else {
                usize::MAX
            };
            for _ in 0..window_margin(speed, fdx.to_f64(), fdt.to_f64()).min(most_past) {
                match march.step() {
                    Ok(_) => {}
                    Err(e) if !at_end => return Err(e),
                    // past the end the margin only smooths the last reports
                    Err(_) => break,
                }
            }
        }
        let run = Run {
            dx: fdx,
            dt: fdt,
            steps: std::mem::take(&mut march.steps),
            beyond: Vec::new(),
            handover: None,
            separations: Vec::new(),
            reimpacts: Vec::new(),
            coefficient_error: 0.0,
        };
        Ok(merge_onto_coarser(&run, handed, dt))
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
            // to an end time, the march goes on past it for the smoothing windows of the last
            // reports (`Run::beyond`), where the drive and the striker's model go on too, and
            // no further than the history's squares reach (`run::end_margin`)
            let margin = match (self.stop, target) {
                (Stop::AtEnd, Some((n, _))) => {
                    let room = end_margin(n);
                    let t_more = dt.to_f64() * (n + room) as f64;
                    let drive_on = match &self.drive {
                        Drive::Table(tab) => tab.last().is_some_and(|p| p.0 >= t_more),
                        _ => true,
                    };
                    if drive_on && t_more <= valid_end {
                        room
                    } else {
                        0
                    }
                }
                _ => 0,
            };
            let margin_room = margin > 0;
            let horizon = horizon + margin;
            let mut own = match (&self.striker, shared_kappa) {
                (Striker::Shell(_) | Striker::Cylinder(_), _) | (Striker::Elastic(_), false) => {
                    self.striker
                        .compliance(m64, dx, kappa.to_f64(), horizon + 1)?
                }
                _ => None,
            };
            // the start on finer grids, merged onto this one (`docs/impact.md`, section 11)
            let seeds = if self.starts_finer() {
                let most = target.map_or(cap_steps, |(n, _)| n.min(cap_steps));
                self.fine_start(
                    &mut *tables,
                    (grid_dx, dt),
                    match self.start_grid {
                        Some(g) => (g, g * self.kappa),
                        None => (level_dx(0).to_f64(), level_dt(0).to_f64()),
                    },
                    1,
                    self.start_halvings,
                    most,
                    self.edge_gap_scale(m64).map(T::of),
                    margin_room,
                )?
            } else {
                Vec::new()
            };
            let slow_edge = !seeds.is_empty()
                && recent_edge_speed(&seeds, dt).abs()
                    < *tables.half_plane().s_r() * START_EDGE_SPEED;
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
            let mut n = seeds.len();
            // the defect of the last hand-over, onto this level's own grid, let go over
            // HANDOVER_DEFECT_STEPS steps of the finest level's grid (the same time on every
            // level), only behind an edge slower than START_EDGE_SPEED c_R (a fast edge's
            // cells near it carry the singular law's shape, which the defect would move)
            let decay = if slow_edge {
                HANDOVER_DEFECT_STEPS as f64 * (level_dt(0) / dt).to_f64()
            } else {
                0.0
            };
            let last = seeds.len();
            for (i, s) in seeds.into_iter().enumerate() {
                if i + 1 == last {
                    march.seed_handover(s, decay)?;
                } else {
                    march.seed(s)?;
                }
            }
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
            // past the end, while in contact there (`Run::beyond`)
            let beyond = match (margin_room, target) {
                (true, Some((g, end)))
                    if n == g && march.steps.last().is_some_and(|s| !s.pressure.is_empty()) =>
                {
                    let speed = recent_edge_speed(&march.steps, dt).to_f64();
                    for _ in 0..window_margin(speed, dx, dt.to_f64()).min(margin) {
                        // the margin only smooths the last reports: a step that cannot be
                        // marched ends it
                        if march.step().is_err() {
                            break;
                        }
                    }
                    march.separations.retain(|&t| t <= end);
                    march.reimpacts.retain(|&t| t <= end);
                    march.steps.split_off(g.min(march.steps.len()))
                }
                _ => Vec::new(),
            };
            let (steps, separations, reimpacts, handover) = (
                std::mem::take(&mut march.steps),
                std::mem::take(&mut march.separations),
                std::mem::take(&mut march.reimpacts),
                march.handover.take(),
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
                beyond,
                handover,
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
