//! The inputs of an impact case: the half-plane, the striker and its profile, its drive, the
//! edge law, the grid and where the run stops, with their validation. Solving a case is
//! [`crate::solve`]; the solved case and its reported history are [`crate::solved`].
//!
//! Dimensionless throughout (R the profile's length scale): x/R, c1 t/R, h/R, speeds over c1,
//! pressure over rho c1^2, force per unit length over rho c1^2 R, energies over rho c1^2 R^2,
//! the striker's mass per unit length as m0/(rho R^2).

use crate::error::{invalid, ImpactError, Result};
use crate::march::EdgeLaw;
use crate::profile::Profile;
use crate::scalar::Scalar;
use crate::striker::Striker;

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

impl Drive {
    /// The free striker's mass per unit length m0 in the march's units mu R^2/c1^2 (c1 = mu = 1,
    /// lengths in R, so rho = 1/m^2): `mass_ratio`/m^2, at the precision of `m` = c2/c1;
    /// `None` for a driven striker. The one conversion of the mass ratio: the march and the
    /// solved case both take m0 from here.
    pub fn mass<T: Scalar>(&self, m: T) -> Option<T> {
        match self {
            Drive::Free { mass_ratio, .. } => Some(T::input(*mass_ratio) / (m * m)),
            Drive::Speed(_) | Drive::Table(_) => None,
        }
    }

    /// The prescribed penetration h/R at time c1 t/R = `t`, at the precision of t (`None` for
    /// a free striker): V t for [`Drive::Speed`], linear between the points of a
    /// [`Drive::Table`].
    pub fn driven_h<T: Scalar>(&self, t: T) -> Option<T> {
        match self {
            Drive::Free { .. } => None,
            Drive::Speed(v) => Some(t * T::input(*v)),
            Drive::Table(tab) => {
                let i = tab.partition_point(|p| t >= p.0).clamp(1, tab.len() - 1);
                let (a, b) = (tab[i - 1], tab[i]);
                let (ax, ay, bx, by) = (T::input(a.0), T::input(a.1), T::input(b.0), T::input(b.1));
                Some((t - ax) * (by - ay) / (bx - ax) + ay)
            }
        }
    }
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

/// The largest [`ImpactCase::start_halvings`]: cells 4096 times finer.
pub const START_HALVINGS_MAX: usize = 12;

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
    /// How many times the grid is halved at the start (`docs/impact.md`, section 11): the
    /// first steps of every level are marched on cells 2, 4, ..., 2^start_halvings times
    /// finer, each handing over (its steps merged by their means) once the contact spans
    /// [`crate::solve::START_CELLS`] cells of the next coarser grid. 0: one grid throughout.
    pub start_halvings: usize,
    /// The cell width dx/R whose hand-over schedule the start follows (`None`: [`Self::dx`]):
    /// a finer grid given a coarser one's schedule is that run refined at every time, the
    /// reference of a refinement study (with its own schedule a finer grid's start would
    /// hand over at narrower contacts, on the same grids as the coarser run).
    pub start_grid: Option<f64>,
}

impl ImpactCase {
    /// The case with the defaults of `impact run`: dx = 0.005 (R/200), kappa = 2, three
    /// levels, the start on cells 64 times finer ([`crate::solve::START_HALVINGS`]).
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
            dx: 0.005,
            kappa: 2.0,
            levels: 3,
            edge_model: true,
            start_grid: None,
            start_halvings: crate::solve::START_HALVINGS,
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

    /// Checks every input against its admissible range (the profile, the striker, the
    /// drive, the end, the grid), as the solve does first: an error naming the first input out
    /// of range.
    pub fn validate(&self) -> Result<()> {
        self.profile.validate()?;
        self.striker.validate()?;
        if let Some(own) = self.striker.own_mass_ratio() {
            // the shell and the cylinder: their radius is the profile's, their mass their own
            let (profile_name, mass_name, mass_of) = match self.striker {
                Striker::Shell(_) => (
                    "profile of a shell striker",
                    "mass ratio m0/(rho R^2) of a shell striker",
                    "2 pi (h_s/R) rho_s/rho",
                ),
                _ => (
                    "profile of a cylinder striker",
                    "mass ratio m0/(rho R^2) of a cylinder striker",
                    "pi rho_s/rho",
                ),
            };
            match self.profile {
                Profile::Circle { radius } | Profile::Parabola { radius } if radius == 1.0 => {}
                _ => {
                    return Err(invalid(
                        profile_name,
                        self.profile.label(),
                        format!(
                            "circle:R=1 or parabola:R=1 (the {}'s radius is the unit R)",
                            self.striker.name()
                        ),
                    ))
                }
            }
            if let Drive::Free { mass_ratio, .. } = self.drive {
                if (mass_ratio - own).abs() > 1e-12 * own {
                    return Err(invalid(
                        mass_name,
                        mass_ratio,
                        format!("its own {mass_of} = {own:.6}"),
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
        if self.start_halvings > START_HALVINGS_MAX {
            return Err(invalid(
                "start halvings",
                self.start_halvings,
                format!("0 to {START_HALVINGS_MAX} (the start's finest cells dx/2^K)"),
            ));
        }
        if let Some(g) = self.start_grid {
            if !(g.is_finite() && g > 0.0) {
                return Err(invalid("start grid dx/R", g, "(0, inf)"));
            }
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
    /// striker of the half-plane's wave speeds, local model or full cylinder (both local
    /// solutions then share the exponents, and the gaps add: near the edge the cylinder is
    /// its own half-plane, `docs/strikers.md` section 8); `None` otherwise (the edge is
    /// captured cell by cell).
    pub(crate) fn edge_gap_scale(&self, m: f64) -> Option<f64> {
        if !self.edge_model {
            return None;
        }
        match &self.striker {
            Striker::Rigid => Some(1.0),
            Striker::Elastic(s) | Striker::Cylinder(s)
                if s.c1_ratio == 1.0 && (s.c2_ratio - m).abs() <= 1e-12 * m =>
            {
                Some(1.0 + m * m / (s.density_ratio * s.c2_ratio * s.c2_ratio))
            }
            _ => None,
        }
    }
}
