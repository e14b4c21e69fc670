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
use super::StrikerMaterial;
use crate::error::{invalid, Result};

/// The cylinder's coefficients c(k, l) (unscaled: without mu/mu_s), grown by columns.
pub(crate) struct CylinderTable {
    disk: Disk,
    /// The cell width (units R), the lattice's arc.
    dx: f64,
    /// The step in the disk's time c2s t/R.
    dt: f64,
    /// The rows served: l = 0 .. rows.
    rows: usize,
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
        let disk = Disk::new(material.poisson())?;
        let dt_disk = dt * material.c2_ratio;
        let rows = horizon.max(1);
        let last = (rows + 1) as f64 * dt_disk;
        if last > super::green::LATEST_TIME {
            return Err(invalid(
                "end time c1 t/R",
                (rows + 1) as f64 * dt,
                format!(
                    "(0, {:.6}]: the cylinder's own response is served to c2s t/R = {} \
                     (c2s/c1 = {:.6})",
                    super::green::LATEST_TIME / material.c2_ratio,
                    super::green::LATEST_TIME,
                    material.c2_ratio
                ),
            ));
        }
        Ok(CylinderTable {
            disk,
            dx,
            dt: dt_disk,
            rows,
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
            self.rows = (lmax + 1).max(2 * self.rows);
            self.c.clear();
            return self.ensure(kmax.max(have_k.saturating_sub(1)), lmax);
        }
        if kmax < have_k && !self.c.is_empty() {
            return Ok(());
        }
        let width = (kmax + 1).max(2 * have_k).max(16);
        let lattice = self
            .disk
            .lattice_rows(self.dx, self.dt, have_k..width, self.rows)?;
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
