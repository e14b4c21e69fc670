//! Influence coefficients of the uniform space-time grid (`docs/impact.md`, section 2).
//!
//! Cells [x_j - dx/2, x_j + dx/2] x [t_{m-1}, t_m], x_j = j dx, t_m = m dt, kappa = c1 dt/dx,
//! a unit pressure constant on a cell; the normal surface displacement at the collocation
//! point (x_i, t_n) is A(i - j, n - m), a four-corner difference of the Lamb crate's space-time
//! primitive Phi(X, T) (`lamb::cells`, closed form, singular parts integrated exactly).
//! Phi is homogeneous of degree 1, so A = dx a(k, l) with a depending on kappa and the
//! material only: one table serves every grid of the same kappa (the refinement levels).
//! Units c1 = 1, mu = 1.

use lamb::HalfPlane;

use crate::error::Result;

/// The normalised coefficients a(k, l) (dx = 1), grown on demand in k and l.
pub struct Tables {
    kappa: f64,
    half_plane: HalfPlane<f64>,
    /// phi[l][k] = Phi(k + 1/2, l kappa), the primitive at the cell corners (dx = 1).
    phi: Vec<Vec<f64>>,
    /// a[l][k] for l = 0 .. phi.len() - 2.
    a: Vec<Vec<f64>>,
    /// Largest rounding-error estimate of a coefficient so far.
    err: f64,
}

impl Tables {
    /// Tables for the half-plane `half_plane` (units c1 = 1) and kappa = c1 dt/dx.
    pub fn new(half_plane: HalfPlane<f64>, kappa: f64) -> Self {
        Tables {
            kappa,
            half_plane,
            phi: vec![Vec::new()],
            a: Vec::new(),
            err: 0.0,
        }
    }

    /// The half-plane.
    pub fn half_plane(&self) -> &HalfPlane<f64> {
        &self.half_plane
    }

    /// The largest absolute error estimate of a normalised coefficient computed so far.
    pub fn error(&self) -> f64 {
        self.err
    }

    /// Makes a(k, l) available for k <= kmax and l <= lmax.
    pub fn ensure(&mut self, kmax: usize, lmax: usize) -> Result<()> {
        let width = kmax + 2;
        // rows of phi: l = 0 .. lmax + 1, each of `width` corners
        while self.phi.len() < lmax + 2 {
            self.phi.push(Vec::new());
        }
        for l in 0..self.phi.len() {
            let have = self.phi[l].len();
            if have >= width {
                continue;
            }
            let t = l as f64 * self.kappa;
            for k in have..width {
                let v = if l == 0 {
                    0.0
                } else {
                    let e = self
                        .half_plane
                        .space_time_primitive(1, &(k as f64 + 0.5), &t)?
                        .zz;
                    self.err = self.err.max(e.err);
                    e.value
                };
                self.phi[l].push(v);
            }
        }
        while self.a.len() < lmax + 1 {
            self.a.push(Vec::new());
        }
        for l in 0..self.a.len() {
            let have = self.a[l].len();
            for k in have..=kmax.max(have.saturating_sub(1)) {
                if k < have {
                    continue;
                }
                let corner = |row: &Vec<f64>, k: usize| -> f64 {
                    // Phi(k + 1/2) - Phi(k - 1/2); Phi is odd in X
                    let left = if k == 0 { -row[0] } else { row[k - 1] };
                    row[k] - left
                };
                let v = corner(&self.phi[l + 1], k) - corner(&self.phi[l], k);
                self.a[l].push(v);
            }
        }
        Ok(())
    }

    /// The row a(., l) (dx = 1), available up to the k given to [`Tables::ensure`].
    pub fn row(&self, l: usize) -> &[f64] {
        &self.a[l]
    }
}
