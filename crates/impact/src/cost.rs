//! What a run will cost, known before it is paid (`docs/impact.md`, section 10): the memory
//! of its history and the work of its march, estimated from the grid and a bound of the
//! contact's width, and the one limit a run is held to.
//!
//! The march keeps, per level, every step's pressures and displacements over the contact
//! (about three vectors of the history's width W, a power of two above the widest contact in
//! cells), the history sum's accumulators of pending targets and the kernels' transforms by
//! level (4W complex numbers for each time lag up to the run's length), and the influence
//! tables (one row per lag, as wide as the kernel's reach). All of it is proportional to
//! N_t W, N_t the number of steps; [`BYTES_PER_CELL_STEP`] is the constant measured on the
//! reference case (peak resident memory over N_t W on five runs: 520 to 1040 bytes).
//!
//! The estimate before the march bounds the contact's width by the kinematic edge of the
//! largest penetration the motion allows; the march itself checks, at every step, the memory
//! its history holds for the widest contact so far against the limit
//! ([`crate::case::ImpactCase::memory_limit`]), so a run to the separation, whose length is not
//! known in advance, is held to the limit too.

use crate::case::{Drive, ImpactCase};
use crate::solve::START_STEPS;

/// The default memory limit of a run, GiB.
pub const DEFAULT_MEMORY_LIMIT_GIB: f64 = 4.0;

/// Bytes of peak memory per step and cell of the history's width, over all that a level
/// keeps (measured, `docs/impact.md`, section 10).
pub const BYTES_PER_CELL_STEP: f64 = 1000.0;

/// Memory besides the history: the process, the tables' fixed part, the rules (bytes).
pub const BASE_BYTES: f64 = 64.0 * 1024.0 * 1024.0;

/// A run's estimated cost.
#[derive(Clone, Copy, Debug)]
pub struct CostEstimate {
    /// Peak memory, bytes (every level's history is released before the next is built, so
    /// the finest level's).
    pub bytes: f64,
    /// Time steps of the finest level (to the end, or to the cap when running to the
    /// separation).
    pub steps: usize,
    /// The history's width W of the finest level, in cells (a bound: the widest contact the
    /// striker's motion allows).
    pub width: usize,
    /// Space-time cells of all levels, sum of N_t W: the measure of the march's work (the
    /// fast history sum costs about that times log^2 N_t log W).
    pub cell_steps: f64,
}

impl CostEstimate {
    /// The estimated peak memory in GiB.
    pub fn gib(&self) -> f64 {
        self.bytes / (1024.0 * 1024.0 * 1024.0)
    }
}

impl ImpactCase {
    /// The run's estimated cost ([`CostEstimate`]): the finest level's steps to the end
    /// (or the cap), and its width from the widest contact the motion allows: the kinematic
    /// edge of the largest penetration, V0 t for a free striker (it never moves in faster
    /// than it started), V t or the table's largest h when driven, within the profile's
    /// extent; with the start on finer grids ([`ImpactCase::start_halvings`]) the largest of
    /// its grids' marches too (each to its latest hand-over).
    pub fn cost_estimate(&self) -> CostEstimate {
        // the widest contact by time t: the kinematic edge of the largest penetration
        let edge_by = |t: f64| {
            let h_max = match &self.drive {
                Drive::Free { v0_over_c1, .. } => v0_over_c1 * t,
                Drive::Speed(v) => v * t,
                Drive::Table(tab) => tab.iter().map(|p| p.1).fold(0.0, f64::max),
            };
            self.profile
                .kinematic_edge::<f64>(h_max.max(0.0))
                .unwrap_or(f64::INFINITY)
                .min(self.profile.extent())
        };
        // one march of `steps` steps over a contact of `b` on cells dx: its history's bytes
        // and space-time cells
        let march = |dx: f64, steps: f64, b: f64| {
            let cells = (b / dx).ceil().max(0.0) + 4.0;
            let width = if cells.is_finite() && cells < 1e12 {
                (cells as usize).next_power_of_two().max(8)
            } else {
                usize::MAX / 2
            };
            let w = width as f64;
            (
                BASE_BYTES + BYTES_PER_CELL_STEP * steps * w,
                steps * w,
                width,
            )
        };
        let b = edge_by(self.end);
        let mut bytes = 0.0f64;
        let mut cell_steps = 0.0;
        let (mut steps0, mut width0) = (0, 0);
        for level in 0..self.levels.max(1) {
            let dx = self.dx * (1u64 << level) as f64;
            let steps = (self.end / (self.kappa * dx)).ceil().max(1.0);
            let (need, cells, width) = march(dx, steps, b);
            bytes = bytes.max(need);
            cell_steps += cells;
            if level == 0 {
                steps0 = steps as usize;
                width0 = width;
            }
            // the start's grids (`docs/impact.md`, section 11): grid j runs at most to the
            // finest level's START_STEPS steps of that grid
            if self.starts_finer() {
                let dt0 = self.kappa * self.start_grid.unwrap_or(self.dx);
                for j in 1..=self.start_halvings.min(40) {
                    let scale = 0.5f64.powi(j as i32);
                    let until = (dt0 * START_STEPS as f64 * scale).min(self.end);
                    let (dxj, dtj) = (dx * scale, self.kappa * dx * scale);
                    let (need, cells, _) =
                        march(dxj, (until / dtj).ceil().max(1.0), edge_by(until));
                    bytes = bytes.max(need);
                    cell_steps += cells;
                }
            }
        }
        CostEstimate {
            bytes,
            steps: steps0,
            width: width0,
            cell_steps,
        }
    }
}

/// The exponent of a cost's growth: the least-squares slope of ln y against ln x over the
/// points (x, y); `None` unless there are two points of different x, all x and y positive.
pub fn fitted_exponent(pts: &[(f64, f64)]) -> Option<f64> {
    if pts.len() < 2
        || pts
            .iter()
            .any(|&(x, y)| !(x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite()))
    {
        return None;
    }
    let n = pts.len() as f64;
    let (mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0);
    for (x, y) in pts {
        let (lx, ly) = (x.ln(), y.ln());
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    let slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    slope.is_finite().then_some(slope)
}

#[cfg(test)]
mod tests {
    use super::fitted_exponent;

    /// A power law's exponent is recovered exactly, and N ln N over 2e3..1.2e5 fits about 1.1.
    #[test]
    fn fitted_exponent_recovers_power_laws() {
        let pts: Vec<(f64, f64)> = [1.0, 2.0, 5.0, 11.0_f64]
            .iter()
            .map(|&x| (x, 3.0 * x.powf(1.7)))
            .collect();
        assert!((fitted_exponent(&pts).unwrap() - 1.7).abs() < 1e-12);
        assert_eq!(fitted_exponent(&[(2.0, 1.0), (2.0, 3.0)]), None);
        assert_eq!(fitted_exponent(&[(2.0, 1.0)]), None);
        let nlogn: Vec<(f64, f64)> = [2250.0, 8000.0, 31000.0, 122000.0_f64]
            .iter()
            .map(|&n| (n, n * n.ln()))
            .collect();
        let p = fitted_exponent(&nlogn).unwrap();
        assert!((1.08..1.12).contains(&p), "{p}");
    }
}
