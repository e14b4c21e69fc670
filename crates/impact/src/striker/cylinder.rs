//! The full elastic cylinder striker's cell coefficients: the free disk's deformation step
//! response on the march's lattice ([`Disk::lattice_step_response`]), differenced in time
//! (`docs/strikers.md`, section 8).
//!
//! The march's coefficient c(k, l) is the mean striker displacement over the receiver cell
//! k dx away, at t_{l+1}, due to a unit pressure held on a source cell over one step, over
//! dx (units of the half-plane: c1 = 1, mu = 1, R = 1). The disk's deformation step response
//! S(k, t) (units p0 R/mu_s, time c2s t/R) gives it as
//!
//! ```text
//! c(k, l) = (mu/mu_s) [S(k, t_{l+1}) - S(k, t_l)]/dx,   c2s t_l/R = (c2s/c1) l dt.
//! ```
//!
//! The rigid translation is not in S: it is the striker's mass-centre motion h(t), which the
//! equation of motion carries, with the mass pi R^2 rho_s of the disk.

use super::disk::Disk;
use super::green::LatticeAccuracy;
use super::StrikerMaterial;
use crate::error::{invalid, ImpactError, Result};

/// The first width of the table (offsets): each growth repeats the frequency samples, whose
/// cost is most of a table's, so the first width serves a history 64 cells wide (2 x 64 + 1
/// columns).
const FIRST_WIDTH: usize = 129;

/// The offsets added beyond a request.
const GROWTH_MARGIN: usize = 8;

/// The most rows computed at first: a run to its separation has an open horizon, and its
/// table grows by doubling (each growth repeats the whole table, so at most twice the work).
const MAX_FIRST_ROWS: usize = 2048;

/// Refuses a cell narrower than the disk's response serves ([`super::green::ARC_RANGE`]),
/// naming the march's cell width.
pub(crate) fn check_cell(dx: f64) -> Result<()> {
    if dx < super::green::ARC_RANGE.0 {
        return Err(invalid(
            "cell width dx/R",
            dx,
            format!(
                "[{}, ...) for a cylinder striker (its own response is served for arcs of at \
                 least that width)",
                super::green::ARC_RANGE.0
            ),
        ));
    }
    Ok(())
}

/// The refusal of an end time c1 t/R = `end` past the disk's served response, for c2s/c1 =
/// `c2_ratio`.
fn past_served(end: f64, c2_ratio: f64) -> ImpactError {
    invalid(
        "end time c1 t/R",
        end,
        format!(
            "(0, {:.6}]: the cylinder's own response is served to c2s t/R = {} (c2s/c1 = {:.6})",
            super::green::LATEST_TIME / c2_ratio,
            super::green::LATEST_TIME,
            c2_ratio
        ),
    )
}

/// The cylinder's coefficients c(k, l) (unscaled: without mu/mu_s), grown by columns.
pub(crate) struct CylinderTable {
    disk: Disk,
    /// The cell width (units R), the lattice's arc.
    dx: f64,
    /// The step in the disk's time c2s t/R.
    dt: f64,
    /// The rows served: l = 0 .. rows.
    rows: usize,
    /// The last row the response's latest time allows.
    last_row: usize,
    /// c2s/c1 (the march's step is dt over it), for the messages.
    c2_ratio: f64,
    /// c[l][k].
    c: Vec<Vec<f64>>,
    /// Bound of a coefficient's error (unscaled).
    err: f64,
}

impl CylinderTable {
    /// The table of the cylinder of `material` for cells of width `dx` (units R) and the
    /// march's step `dt` (c1 t/R), serving the steps 0 .. `horizon`.
    pub(crate) fn new(
        material: &StrikerMaterial,
        dx: f64,
        dt: f64,
        horizon: usize,
    ) -> Result<Self> {
        check_cell(dx)?;
        let disk = Disk::new(material.poisson())?;
        let dt_disk = dt * material.c2_ratio;
        // the last row served: the response's latest time
        let last_row = ((super::green::LATEST_TIME / dt_disk).floor() as usize).saturating_sub(1);
        if last_row == 0 || (horizon > last_row && horizon <= MAX_FIRST_ROWS) {
            return Err(past_served(horizon as f64 * dt, material.c2_ratio));
        }
        Ok(CylinderTable {
            disk,
            dx,
            dt: dt_disk,
            rows: horizon.clamp(1, MAX_FIRST_ROWS.min(last_row)),
            last_row,
            c2_ratio: material.c2_ratio,
            c: Vec::new(),
            err: 0.0,
        })
    }

    /// The bound of a coefficient's error (unscaled).
    pub(crate) fn error(&self) -> f64 {
        self.err
    }

    /// Makes c(k, l) available for k <= kmax and l <= lmax: new columns by doubling, each
    /// computed once; rows past the horizon recompute the table with twice the rows.
    pub(crate) fn ensure(&mut self, kmax: usize, lmax: usize) -> Result<()> {
        let have_k = self.c.first().map_or(0, Vec::len);
        if lmax >= self.rows {
            if lmax > self.last_row {
                return Err(past_served(
                    (lmax + 1) as f64 * self.dt / self.c2_ratio,
                    self.c2_ratio,
                ));
            }
            self.rows = (lmax + 1).max(2 * self.rows).min(self.last_row + 1);
            self.c.clear();
            return self.ensure(kmax.max(have_k.saturating_sub(1)), lmax);
        }
        if kmax < have_k && !self.c.is_empty() {
            return Ok(());
        }
        // a growth repeats the frequency samples (most of a table's cost): at least double,
        // with a margin (the history's requests are 2W + 1 columns, W a power of two)
        let width = if have_k == 0 {
            (kmax + 1 + GROWTH_MARGIN).max(FIRST_WIDTH)
        } else {
            (kmax + 1).max(2 * have_k) + GROWTH_MARGIN
        };
        let dx = self.dx;
        let lattice = self
            .disk
            .lattice_rows(
                dx,
                self.dt,
                have_k..width,
                self.rows,
                LatticeAccuracy::MARCH,
            )
            .map_err(|e| match e {
                // the response's work limit, said of the march's input
                ImpactError::InvalidParameter(p) if p.name == "arc over R" => invalid(
                    "cell width dx/R",
                    dx,
                    format!(
                        "a cylinder striker's response within its work limit: {}",
                        p.range
                    ),
                ),
                other => other,
            })?;
        if self.c.is_empty() {
            self.c = vec![Vec::with_capacity(width); self.rows];
        }
        for (s, e) in lattice.deformation.iter().zip(&lattice.error) {
            for (l, row) in self.c.iter_mut().enumerate() {
                row.push((s[l + 1] - s[l]) / self.dx);
                self.err = self.err.max((e[l + 1] + e[l]) / self.dx);
            }
        }
        Ok(())
    }

    /// The row c(., l).
    pub(crate) fn row(&self, l: usize) -> &[f64] {
        &self.c[l]
    }
}

/// One order's modes: (n, [(omega_k, r_k)]).
pub type OrderModes = (u32, Vec<(f64, f64)>);

/// One order's data for the recursion: c_n, the cells' weights, each mode's (cos, sin of
/// omega dtau, omega, r).
struct Order {
    c_n: f64,
    weights: Vec<f64>,
    modes: Vec<(f64, f64, f64, f64)>,
}

/// The free disk's elastic modes below a frequency, harmonic by harmonic ([`Disk::modes`]):
/// the striker's vibration under a pressure history by an exact modal recursion
/// (`docs/strikers.md`, section 8).
#[derive(Clone, Debug)]
pub struct DiskModes {
    /// The highest frequency kept (units c2s/R).
    pub omega_max: f64,
    /// (n, [(omega_k, r_k)]) for every order with a mode below `omega_max`:
    /// W_n(s) = sum_k r_k/(s^2 + omega_k^2) + (the modes above, and the translation at n = 1).
    pub harmonics: Vec<OrderModes>,
}

impl Disk {
    /// Every elastic mode of the free disk with a radial surface motion and a frequency below
    /// `omega_max` (units c2s/R, in (0, 200]), with its residue ([`Disk::modes_below`]). The
    /// lowest frequency of order n grows like n c_R, so the orders are taken up to the first
    /// above 2 `omega_max` + 4 (the lowest, flexural, frequencies of the low orders lie below
    /// n c_R, none below n/2).
    pub fn modes(&self, omega_max: f64) -> Result<DiskModes> {
        use rayon::prelude::*;
        if !(omega_max > 0.0 && omega_max <= 200.0) {
            return Err(invalid("omega_max", omega_max, "(0, 200]"));
        }
        let top = (2.0 * omega_max) as u32 + 4;
        let harmonics = (0..=top)
            .into_par_iter()
            .map(|n| Ok((n, self.modes_below(n, omega_max)?)))
            .collect::<Result<Vec<OrderModes>>>()?
            .into_iter()
            .filter(|(_, m)| !m.is_empty())
            .collect();
        Ok(DiskModes {
            omega_max,
            harmonics,
        })
    }
}

impl DiskModes {
    /// The number of modes kept.
    pub fn count(&self) -> usize {
        self.harmonics.iter().map(|(_, m)| m.len()).sum()
    }

    /// The modes below `omega_max` alone (a subset, for the truncation's estimate).
    pub fn below(&self, omega_max: f64) -> DiskModes {
        DiskModes {
            omega_max: omega_max.min(self.omega_max),
            harmonics: self
                .harmonics
                .iter()
                .map(|(n, m)| (*n, m.iter().copied().filter(|w| w.0 < omega_max).collect()))
                .filter(|(_, m): &OrderModes| !m.is_empty())
                .collect(),
        }
    }

    /// The kinetic and the strain energy of the kept modes (units mu_s R^2 per unit length)
    /// after each step of a pressure history: `pressures[l][j]` is the inward pressure
    /// (units mu_s) held over the step l + 1 of length `dtau` (units R/c2s) on the arc
    /// |theta - j dx| < dx/2 (and on its mirror for j > 0). Each mode is an oscillator
    /// y'' + omega^2 y = r P_n(t), y its share of the surface displacement's harmonic and P_n
    /// the pressure's, with the energy c_n (y'^2 + omega^2 y^2)/(2 r), c_n = 2 pi at n = 0 and
    /// pi above; a pressure constant over a step is integrated exactly.
    pub fn energies(&self, dx: f64, dtau: f64, pressures: &[Vec<f64>]) -> Vec<(f64, f64)> {
        use std::f64::consts::PI;
        // per order: c_n, the cells' weights m_j dx sinc(n dx/2) cos(n j dx)/c_n, and the
        // modes' rotation over a step
        let width = pressures.iter().map(Vec::len).max().unwrap_or(0);
        let orders: Vec<Order> = self
            .harmonics
            .iter()
            .map(|(n, modes)| {
                let nf = f64::from(*n);
                let c_n = if *n == 0 { 2.0 * PI } else { PI };
                let sc = super::sinc(0.5 * nf * dx);
                let weights = (0..width)
                    .map(|j| {
                        let m = if j == 0 { 1.0 } else { 2.0 };
                        m * dx * sc * (nf * j as f64 * dx).cos() / c_n
                    })
                    .collect();
                let modes = modes
                    .iter()
                    .map(|&(w, r)| ((w * dtau).cos(), (w * dtau).sin(), w, r))
                    .collect();
                Order {
                    c_n,
                    weights,
                    modes,
                }
            })
            .collect();
        let mut state: Vec<Vec<(f64, f64)>> = orders
            .iter()
            .map(|o| vec![(0.0, 0.0); o.modes.len()])
            .collect();
        let mut out = Vec::with_capacity(pressures.len());
        for p in pressures {
            let (mut kinetic, mut strain) = (0.0, 0.0);
            for (o, st) in orders.iter().zip(state.iter_mut()) {
                let c_n = o.c_n;
                let force: f64 = p.iter().zip(&o.weights).map(|(a, b)| a * b).sum();
                for (&(c, s, w, r), (y, v)) in o.modes.iter().zip(st.iter_mut()) {
                    let (y1, v1) = super::oscillator_step(*y, *v, r * force / (w * w), w, c, s);
                    *y = y1;
                    *v = v1;
                    kinetic += 0.5 * c_n * v1 * v1 / r;
                    strain += 0.5 * c_n * w * w * y1 * y1 / r;
                }
            }
            out.push((kinetic, strain));
        }
        out
    }
}
