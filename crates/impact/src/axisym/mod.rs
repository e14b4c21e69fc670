//! The axisymmetric impact of a rigid striker on the elastic half-space
//! (`docs/axisymmetric.md`): a sphere, its paraboloid, a cone or a flat cylindrical punch,
//! free (mass m, speed V0) or driven, under Signorini's conditions or the kinematic edge law.
//! The contact condition is marched on rings of width dr whose influence coefficients are the
//! half-space's ring-cell pulses ([`lamb::HalfSpace::ring_pulse`], `docs/half_space.md`); the
//! striker's equation of motion is integrated exactly over each step as in the plane march;
//! the histories are reported with error estimates from grid refinement.
//!
//! Dimensionless variables (R the profile's length scale, the sphere's radius): r/R, c1 t/R,
//! h/R, V0/c1, m/(rho R^3); pressure over rho c1^2, force over rho c1^2 R^2, energies over
//! rho c1^2 R^3. Inside, c1 = mu = 1 and rho = 1/m^2 (m = c2/c1).

pub mod march;
pub mod profile;
pub mod tables;

use std::ops::ControlFlow;

pub use march::AxiStep;
pub use profile::AxiProfile;
use tables::RingTables;

use crate::case::{Drive, Stop};
use crate::error::{invalid, ImpactError, Result};
use crate::march::EdgeLaw;
use crate::solve::Progress;
use crate::solved::{level_estimate, windowed_estimates, Stage};

/// The fewest rings across the largest contact radius of the default grid.
pub const DEFAULT_RINGS: f64 = 30.0;

/// The inputs of an axisymmetric case.
#[derive(Clone, Debug)]
pub struct AxiCase {
    /// Poisson's ratio of the half-space, in (-1, 1/2) (0 and about 0.2631 excluded by the
    /// Lamb crate).
    pub poisson: f64,
    /// The striker's profile.
    pub profile: AxiProfile,
    /// Free flight (`mass_ratio` = m/(rho R^3), V0/c1) or a prescribed penetration.
    pub drive: Drive,
    /// The edge law.
    pub law: EdgeLaw,
    /// The end time c1 t/R (the cap when stopping at separation).
    pub end: f64,
    /// Where the run stops.
    pub stop: Stop,
    /// The finest ring width dr/R; `None`: [`AxiCase::default_dr`].
    pub dr: Option<f64>,
    /// kappa = c1 dt/dr.
    pub kappa: f64,
    /// Grid levels dr, 2 dr, 4 dr, ... (1 to 4).
    pub levels: usize,
}

/// One level's march: its grid and its steps.
#[derive(Clone, Debug)]
pub struct AxiRun {
    /// dr/R.
    pub dr: f64,
    /// c1 dt/R.
    pub dt: f64,
    /// The steps (the end of step n at c1 t/R = n dt).
    pub steps: Vec<AxiStep>,
    /// Times c1 t/R at which a contact ended.
    pub separations: Vec<f64>,
    /// Contacts begun after a separation.
    pub reimpacts: usize,
}

/// A value with its absolute error estimate (`None` with a single level).
pub type AxiValue = crate::solved::Value<f64>;

/// One reported time of a solved case (dimensionless; speeds over c1).
#[derive(Clone, Debug)]
pub struct AxiRow {
    /// c1 t/R.
    pub t: f64,
    /// h/R.
    pub h: AxiValue,
    /// (dh/dt)/c1.
    pub hdot: AxiValue,
    /// a/R.
    pub a: AxiValue,
    /// (da/dt)/c1 of the finest level.
    pub adot: f64,
    /// The contact edge's speed range.
    pub stage: Option<Stage>,
    /// Force over rho c1^2 R^2 (at t, from the steps around it).
    pub force: AxiValue,
    /// The striker's kinetic energy over rho c1^2 R^3 (free striker).
    pub kinetic: Option<AxiValue>,
    /// The work done on the half-space over rho c1^2 R^3.
    pub work: AxiValue,
    /// The energy radiated: the work less what the quasi-static field of the current
    /// pressures would store, over the impact energy (free) or the work (driven);
    /// `None` for a driven striker before it has done work.
    pub radiated_fraction: Option<AxiValue>,
    /// (kinetic + work)/impact energy - 1 (free striker).
    pub energy_defect: Option<AxiValue>,
}

/// The rebound of a free striker.
#[derive(Clone, Debug)]
pub struct AxiRebound {
    /// c1 t/R at the last separation.
    pub separation: AxiValue,
    /// The coefficient of restitution -V_final/V0.
    pub restitution: AxiValue,
    /// The share of the impact energy radiated into the half-space (1 - e^2).
    pub radiated_fraction: AxiValue,
    /// Contacts begun after a separation.
    pub reimpacts: usize,
}

/// A solved axisymmetric case: its inputs and every level's march (finest first).
#[derive(Clone, Debug)]
pub struct SolvedAxi {
    /// The inputs.
    pub case: AxiCase,
    /// m = c2/c1.
    pub m: f64,
    /// c_R/c1.
    pub s_r: f64,
    /// The levels' marches, finest first.
    pub runs: Vec<AxiRun>,
    /// The largest error estimate of a ring coefficient (unit dr).
    pub coefficient_error: f64,
}

impl AxiCase {
    /// Checks every input, naming the one out of range.
    pub fn validate(&self) -> Result<()> {
        self.profile.validate()?;
        if !(self.poisson.is_finite() && self.poisson > -1.0 && self.poisson < 0.5) {
            return Err(invalid("poisson", self.poisson, "(-1, 0.5)"));
        }
        match self.drive {
            Drive::Free {
                mass_ratio,
                v0_over_c1,
            } => {
                if !(mass_ratio.is_finite() && mass_ratio > 0.0) {
                    return Err(invalid("mass_ratio (m/(rho R^3))", mass_ratio, "(0, inf)"));
                }
                if !(v0_over_c1.is_finite() && v0_over_c1 > 0.0 && v0_over_c1 < 1.0) {
                    return Err(invalid("v0_over_c1", v0_over_c1, "(0, 1)"));
                }
            }
            Drive::Speed(v) => {
                if !(v.is_finite() && v > 0.0 && v < 1.0) {
                    return Err(invalid("driven V_over_c1", v, "(0, 1)"));
                }
            }
            Drive::Table(ref t) => {
                if t.len() < 2 {
                    return Err(invalid("driven table points", t.len(), "at least 2"));
                }
            }
        }
        if !(self.end.is_finite() && self.end > 0.0) {
            return Err(invalid("end c1t/R", self.end, "(0, inf)"));
        }
        if !(self.kappa.is_finite() && (0.5..=64.0).contains(&self.kappa)) {
            return Err(invalid("kappa", self.kappa, "[0.5, 64]"));
        }
        if !(1..=4).contains(&self.levels) {
            return Err(invalid("levels", self.levels, "1..=4"));
        }
        if let Some(dr) = self.dr {
            if !(dr.is_finite() && dr > 0.0 && dr <= 0.5) {
                return Err(invalid("dr", dr, "(0, 0.5]"));
            }
        }
        if let (AxiProfile::Sphere { radius }, Some(a)) = (&self.profile, self.largest_radius()) {
            if a >= 0.9 * radius {
                return Err(invalid(
                    "the sphere's expected contact radius a/R",
                    a,
                    "(0, 0.9 R): a slower or lighter sphere",
                ));
            }
        }
        Ok(())
    }

    /// The largest contact radius expected: Hertz's quasi-static one (the sphere and its
    /// paraboloid, E* = 2 mu/(1 - nu)), Sneddon's for the cone, from the impact energy (under
    /// the kinematic law the geometric radius of the quasi-static impact with that law); the
    /// geometric one at the end's penetration when driven; the punch's radius.
    pub fn largest_radius(&self) -> Option<f64> {
        let estar = 2.0 / (1.0 - self.poisson);
        let m2 = (1.0 - 2.0 * self.poisson) / (2.0 * (1.0 - self.poisson));
        if let Some(a) = self.profile.flat_radius() {
            return Some(a);
        }
        match self.drive {
            Drive::Free {
                mass_ratio,
                v0_over_c1,
            } => {
                let energy = 0.5 * mass_ratio / m2 * v0_over_c1 * v0_over_c1;
                let pi = std::f64::consts::PI;
                match (&self.profile, self.law) {
                    (
                        AxiProfile::Sphere { radius } | AxiProfile::Paraboloid { radius },
                        EdgeLaw::Signorini,
                    ) => {
                        // (8/15) E* R^(1/2) h^(5/2) = energy, a = (R h)^(1/2)
                        let h = (15.0 * energy / (8.0 * estar * radius.sqrt())).powf(0.4);
                        Some((radius * h).sqrt())
                    }
                    (
                        AxiProfile::Sphere { radius } | AxiProfile::Paraboloid { radius },
                        EdgeLaw::Kinematic,
                    ) => {
                        // the geometric contact a = (2 R h)^(1/2) carries Hertz's pressure for
                        // a plus a punch's of depth -h (docs/axisymmetric.md, section 6):
                        // F = (2^(3/2)/3) E* R^(1/2) h^(3/2), (2^(5/2)/15) E* R^(1/2) h^(5/2)
                        // = energy
                        let h =
                            (15.0 * energy / (2f64.powf(2.5) * estar * radius.sqrt())).powf(0.4);
                        Some((2.0 * radius * h).sqrt())
                    }
                    (AxiProfile::Cone { theta_deg }, EdgeLaw::Signorini) => {
                        // P = (2/pi) E* tan(theta) h^2, a = (2/pi) h tan(theta)
                        let tan = theta_deg.to_radians().tan();
                        let h = (3.0 * pi * energy / (2.0 * estar * tan)).cbrt();
                        Some(2.0 / pi * h * tan)
                    }
                    (AxiProfile::Cone { theta_deg }, EdgeLaw::Kinematic) => {
                        // a = h tan(theta): Sneddon's force (pi/2) E* a^2/tan(theta) plus a
                        // punch's of depth h (1 - pi/2), F = (2 - pi/2) E* tan(theta) h^2
                        let tan = theta_deg.to_radians().tan();
                        let h = (3.0 * energy / ((2.0 - pi / 2.0) * estar * tan)).cbrt();
                        Some(h * tan)
                    }
                    (AxiProfile::Flat { radius }, _) => Some(*radius),
                }
            }
            _ => self
                .drive
                .driven_h(self.end)
                .map(|h| self.profile.contact_radius(h)),
        }
    }

    /// The default ring width: [`DEFAULT_RINGS`] rings across the largest expected contact
    /// radius (for the punch, its radius spans a whole number and a half of rings).
    pub fn default_dr(&self) -> f64 {
        let a = self.largest_radius().unwrap_or(0.1).max(1e-9);
        match self.profile.flat_radius() {
            Some(r) => r / (DEFAULT_RINGS + 0.5),
            None => a / DEFAULT_RINGS,
        }
    }

    /// The finest ring width in use.
    pub fn finest_dr(&self) -> f64 {
        let dr = self.dr.unwrap_or_else(|| self.default_dr());
        match self.profile.flat_radius() {
            // whole rings under the punch on every level: a = (N + 1/2) dr_coarse
            Some(r) => {
                let coarse = dr * (1 << (self.levels - 1)) as f64;
                let n = ((r / coarse) - 0.5).round().max(1.0);
                r / (n + 0.5) / (1 << (self.levels - 1)) as f64
            }
            None => dr,
        }
    }

    /// Solves the case on its levels, calling `progress` now and then (a `Break` stops the
    /// march with [`ImpactError::Stopped`]).
    pub fn solve(
        &self,
        mut progress: impl FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<SolvedAxi> {
        self.validate()?;
        let levels = self.levels;
        let dr_f = self.finest_dr();
        let coarse = (1 << (levels - 1)) as f64;
        // the coarsest step divides the end: kappa adjusted by under 1/(2 N_c)
        let dt_c = self.kappa * dr_f * coarse;
        let n_c = (self.end / dt_c).round().max(1.0) as usize;
        let kappa = self.end / n_c as f64 / (dr_f * coarse);
        let mut tables = RingTables::new(self.poisson, kappa, n_c << (levels - 1))?;
        let m = ((1.0 - 2.0 * self.poisson) / (2.0 * (1.0 - self.poisson))).sqrt();
        let s_r = *tables.space().s_r();
        // the contact cannot outgrow the geometric one at the largest penetration the run can
        // reach (V0 times the end for a free striker)
        let deepest = match self.drive {
            Drive::Free { v0_over_c1, .. } => v0_over_c1 * self.end,
            _ => self.drive.driven_h(self.end).unwrap_or(0.0),
        };
        let reach = self
            .largest_radius()
            .map(|a| a * 1.3)
            .unwrap_or(0.1)
            .min(self.profile.contact_radius(deepest) * 1.05);
        let mut rings = ((reach / dr_f).ceil() as usize + 8).max(8);
        if let Some(r) = self.profile.flat_radius() {
            rings = ((r / dr_f).round() as usize + 3).max(4);
        }
        let mut runs: Vec<AxiRun> = Vec::with_capacity(levels);
        let mut end_steps_c = n_c;
        for q in 0..levels {
            let dr = dr_f * (1 << q) as f64;
            let ratio = 1usize << (levels - 1 - q);
            loop {
                let need = if q == 0 { rings } else { tables.rings() };
                tables.ensure(need)?;
                let mut mar =
                    march::AxiMarch::new(dr, &tables, &self.profile, &self.drive, self.law, m);
                let steps = end_steps_c * ratio;
                let mut outcome = Ok(());
                let mut stop_at = steps;
                for n in 1..=steps {
                    if let Err(e) = mar.step() {
                        outcome = Err(e);
                        break;
                    }
                    if n % 64 == 0 {
                        let done = (q as f64 + n as f64 / steps as f64) / levels as f64;
                        if progress(Progress {
                            fraction: done,
                            level: q,
                            step: n,
                            t: n as f64 * mar.dt,
                        })
                        .is_break()
                        {
                            return Err(ImpactError::Stopped {
                                time: n as f64 * mar.dt,
                            });
                        }
                    }
                    // a free striker's run stops one report interval after its separation
                    if q == 0
                        && self.stop == Stop::AtSeparation
                        && n % ratio == 0
                        && mar.steps.last().is_some_and(|s| s.pressure.is_empty())
                        && mar
                            .separations
                            .last()
                            .is_some_and(|&ts| n as f64 * mar.dt >= ts + dt_c * 0.999)
                    {
                        stop_at = n;
                        break;
                    }
                }
                match outcome {
                    Err(ImpactError::Grid { .. }) if q == 0 && rings < 4096 => {
                        rings *= 2;
                        continue;
                    }
                    Err(e) => return Err(e),
                    Ok(()) => {}
                }
                if q == 0 {
                    end_steps_c = stop_at / ratio;
                    self.check_stiffness(&mar.steps, mar.dt)?;
                }
                runs.push(AxiRun {
                    dr,
                    dt: mar.dt,
                    steps: std::mem::take(&mut mar.steps),
                    separations: mar.separations.clone(),
                    reimpacts: mar.reimpacts,
                });
                break;
            }
        }
        Ok(SolvedAxi {
            case: self.clone(),
            m,
            s_r,
            runs,
            coefficient_error: tables.largest_error(),
        })
    }
}

impl AxiCase {
    /// Refuses a free striker too light for the finest step (`docs/axisymmetric.md`,
    /// section 3; the plane march's check, `docs/impact.md` section 9): against the plane-wave
    /// impedance rho c1 pi a^2 of its widest contact the striker's speed relaxes in
    /// tau = m/(rho c1 pi a^2), and a step's constant force advances it by the factor
    /// (1 - r)/(1 + r), r = dt/(2 tau) = c1 dt pi a^2/(2 R^3 m/(rho R^3)), which is negative
    /// above r = 1: the striker would bounce back from one step to the next.
    fn check_stiffness(&self, steps: &[march::AxiStep], dt: f64) -> Result<()> {
        let Drive::Free { mass_ratio, .. } = self.drive else {
            return Ok(());
        };
        let a = steps.iter().map(|s| s.a).fold(0.0, f64::max);
        let r = dt * std::f64::consts::PI * a * a / (2.0 * mass_ratio);
        if r > crate::solve::STIFF_RATIO {
            let tau = dt / (2.0 * r);
            return Err(ImpactError::Grid {
                name: "dr",
                reason: format!(
                    "the striker's deceleration time m/(rho c1 pi a^2) = {tau:.3e} R/c1 at its widest contact a/R = {a:.4} is shorter than half the time step c1 dt/R = {dt:.3e}, so the step's constant force would bounce it back: lower --dr or --kappa to c1 dt/R < {:.3e}, or raise --mass-ratio",
                    2.0 * tau
                ),
            });
        }
        Ok(())
    }
}

impl SolvedAxi {
    /// The impact energy (1/2) m V0^2 over mu R^3 (free striker).
    fn impact_energy(&self) -> Option<f64> {
        match self.case.drive {
            Drive::Free {
                mass_ratio,
                v0_over_c1,
            } => Some(0.5 * mass_ratio / (self.m * self.m) * v0_over_c1 * v0_over_c1),
            _ => None,
        }
    }

    /// The reporting interval: the coarsest level's step.
    pub fn report_dt(&self) -> f64 {
        self.runs.last().map_or(0.0, |r| r.dt)
    }

    /// The reported history: at every step of the coarsest level, the finest level's values
    /// with their estimates from the levels, and the observed orders (quantity, order).
    pub fn history(&self) -> (Vec<AxiRow>, Vec<(&'static str, f64)>) {
        let m2 = self.m * self.m;
        let e0 = self.impact_energy();
        let coarse = self.runs.last().expect("at least one level");
        let n_rep = coarse.steps.len();
        // the value of quantity `f` at report time k on level q
        let at = |q: usize, k: usize, f: &dyn Fn(&[AxiStep], usize) -> f64| -> f64 {
            let run = &self.runs[q];
            let ratio = (coarse.dt / run.dt).round() as usize;
            let n = (k + 1) * ratio; // 1-based step
            f(&run.steps, n - 1)
        };
        let force_at = |steps: &[AxiStep], i: usize| -> f64 {
            // the steps' forces stand for their middles: the mean of the two around t_i
            let next = match steps.get(i + 1) {
                Some(s) => s.force,
                None if i >= 1 => 2.0 * steps[i].force - steps[i - 1].force,
                None => steps[i].force,
            };
            0.5 * (steps[i].force + next) * m2
        };
        type Getter<'g> = Box<dyn Fn(&[AxiStep], usize) -> f64 + 'g>;
        let mut quantities: Vec<(&'static str, Getter)> = vec![
            ("h_over_R", Box::new(|s: &[AxiStep], i: usize| s[i].h)),
            ("hdot", Box::new(|s: &[AxiStep], i: usize| s[i].v)),
            ("a_over_R", Box::new(|s: &[AxiStep], i: usize| s[i].a)),
            ("force_over_rho_c1sq_Rsq", Box::new(force_at)),
            (
                "work",
                Box::new(move |s: &[AxiStep], i: usize| s[i].work * m2),
            ),
            (
                "radiated",
                Box::new(move |s: &[AxiStep], i: usize| (s[i].work - s[i].quasi_static) * m2),
            ),
        ];
        if e0.is_some() {
            let mass = match self.case.drive {
                Drive::Free { mass_ratio, .. } => mass_ratio / m2,
                _ => 0.0,
            };
            quantities.push((
                "kinetic",
                Box::new(move |s: &[AxiStep], i: usize| 0.5 * mass * s[i].v * s[i].v * m2),
            ));
        }
        let mut values: Vec<Vec<Vec<f64>>> = Vec::new();
        let mut ests: Vec<Option<Vec<f64>>> = Vec::new();
        let mut orders = Vec::new();
        for (name, f) in &quantities {
            let lv: Vec<Vec<f64>> = (0..self.runs.len())
                .map(|q| (0..n_rep).map(|k| at(q, k, f.as_ref())).collect())
                .collect();
            let (e, o) = windowed_estimates(&lv);
            if let Some(o) = o {
                orders.push((*name, o));
            }
            values.push(lv);
            ests.push(e);
        }
        // (kinetic energy + work)/E0 - 1 on each level, from the two (indices 6 and 4)
        if let Some(e) = e0 {
            let lv: Vec<Vec<f64>> = values[6]
                .iter()
                .zip(&values[4])
                .map(|(kin, work)| {
                    kin.iter()
                        .zip(work)
                        .map(|(k, w)| (k + w) / (e * m2) - 1.0)
                        .collect()
                })
                .collect();
            let (est, o) = windowed_estimates(&lv);
            if let Some(o) = o {
                orders.push(("energy_defect", o));
            }
            values.push(lv);
            ests.push(est);
        }
        let val = |qi: usize, k: usize, scale: f64| AxiValue {
            value: values[qi][0][k] * scale,
            error: ests[qi].as_ref().map(|e| e[k] * scale.abs()),
            kind: complexfn::ErrorKind::Refinement,
        };
        let v_scale = match self.case.drive {
            Drive::Free { v0_over_c1, .. } => 1.0 / v0_over_c1,
            _ => 1.0,
        };
        let e0_scaled = e0.map(|e| e * m2);
        let fine = &self.runs[0];
        let ratio_f = (coarse.dt / fine.dt).round() as usize;
        let rows = (0..n_rep)
            .map(|k| {
                let t = (k + 1) as f64 * coarse.dt;
                let i = (k + 1) * ratio_f - 1;
                let adot = {
                    let (lo, hi) = (
                        i.saturating_sub(ratio_f),
                        (i + ratio_f).min(fine.steps.len() - 1),
                    );
                    if hi > lo {
                        (fine.steps[hi].a - fine.steps[lo].a) / ((hi - lo) as f64 * fine.dt)
                    } else {
                        0.0
                    }
                };
                let stage = (fine.steps[i].a > 0.0).then(|| {
                    let s = adot.abs();
                    if s > 1.0 {
                        Stage::Supersonic
                    } else if s > self.m {
                        Stage::Transonic
                    } else if s > self.s_r {
                        Stage::RayleighShear
                    } else {
                        Stage::SubRayleigh
                    }
                });
                let kinetic = e0.map(|_| val(6, k, 1.0));
                let work = val(4, k, 1.0);
                let radiated_fraction = match e0_scaled {
                    Some(e) => Some(val(5, k, 1.0 / e)),
                    None => (work.value > 0.0).then(|| val(5, k, 1.0 / work.value)),
                };
                // under Signorini's law the defect's exact value is 0, so the defect is its
                // own error too (docs/impact.md, section 9); the kinematic law's edge
                // exchanges energy (docs/axisymmetric.md, section 6): the levels' estimate
                let energy_defect = e0.map(|_| {
                    let mut d = val(7, k, 1.0);
                    if self.case.law == EdgeLaw::Signorini {
                        d.error = Some(d.error.unwrap_or(0.0).max(d.value.abs()));
                    }
                    d
                });
                AxiRow {
                    t,
                    h: val(0, k, 1.0),
                    hdot: val(1, k, v_scale),
                    a: val(2, k, 1.0),
                    adot,
                    stage,
                    force: val(3, k, 1.0),
                    kinetic,
                    work,
                    radiated_fraction,
                    energy_defect,
                }
            })
            .collect();
        let orders = orders
            .into_iter()
            .map(|(k, o)| {
                let key = match k {
                    "hdot" => {
                        if e0.is_some() {
                            "hdot_over_v0"
                        } else {
                            "hdot_over_c1"
                        }
                    }
                    "work" => "work_over_rho_c1sq_Rcu",
                    "kinetic" => "kinetic_energy_over_rho_c1sq_Rcu",
                    "radiated" => "radiated_energy_fraction",
                    other => other,
                };
                (key, o)
            })
            .collect();
        (rows, orders)
    }

    /// The rebound of a free striker, or why there is none: driven, or in contact at the end
    /// of the run on some level.
    pub fn rebound(&self) -> std::result::Result<AxiRebound, String> {
        let Drive::Free { v0_over_c1, .. } = self.case.drive else {
            return Err("a driven striker has no rebound".into());
        };
        let mut sep = Vec::new();
        let mut rest = Vec::new();
        for r in &self.runs {
            let last = r.steps.last().ok_or("no steps")?;
            if !last.pressure.is_empty() || r.separations.is_empty() {
                return Err(format!(
                    "the striker is in contact at the end of the run (c1 t/R = {:.4}) on the grid dr/R = {:.4e}: run longer, or to --end separation",
                    last.t, r.dr
                ));
            }
            sep.push(*r.separations.last().unwrap_or(&last.t));
            rest.push(-last.v / v0_over_c1);
        }
        let dt = self.runs[0].dt;
        let e_sep = level_estimate(&sep).map(|e| e.max(dt));
        let e_rest = level_estimate(&rest);
        let radiated: Vec<f64> = rest.iter().map(|e| 1.0 - e * e).collect();
        let e_rad = level_estimate(&radiated);
        Ok(AxiRebound {
            separation: AxiValue {
                value: sep[0],
                error: e_sep,
                kind: complexfn::ErrorKind::Refinement,
            },
            restitution: AxiValue {
                value: rest[0],
                error: e_rest,
                kind: complexfn::ErrorKind::Refinement,
            },
            radiated_fraction: AxiValue {
                value: radiated[0],
                error: e_rad,
                kind: complexfn::ErrorKind::Refinement,
            },
            reimpacts: self.runs[0].reimpacts,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_grid_resolves_the_hertz_radius() {
        let c = AxiCase {
            poisson: 0.25,
            profile: AxiProfile::Sphere { radius: 1.0 },
            drive: Drive::Free {
                mass_ratio: 4.0 * std::f64::consts::PI / 3.0,
                v0_over_c1: 1e-3,
            },
            law: EdgeLaw::Signorini,
            end: 1.0,
            stop: Stop::AtEnd,
            dr: None,
            kappa: 2.0,
            levels: 3,
        };
        let a = c.largest_radius().unwrap();
        assert!((c.default_dr() * DEFAULT_RINGS - a).abs() < 1e-15);
        assert!(a > 0.01 && a < 0.2, "{a}");
    }
}
