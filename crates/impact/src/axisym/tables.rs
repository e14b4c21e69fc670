//! The ring-cell coefficients of the half-space (`docs/axisymmetric.md`, section 2): the mean
//! displacement over ring i at the end of step n due to a unit pressure on ring j during step
//! m, dr c(i, j, n - m; kappa), from [`lamb::HalfSpace::ring_pulse`] on rings of unit width
//! (the response is homogeneous of degree one in lengths and c1 t together, so one table
//! serves every grid of the same kappa = c1 dt/dr, every refinement level).
//!
//! The half-space's memory is finite: behind the Rayleigh arrival its step response is
//! static, so c(i, j, l) vanishes once s_R l kappa >= i + j + 1 (the two rings' outer radii).
//! The table holds, for each lag l below that bound, the N x N block c(., ., l).

use lamb::{Annulus, HalfSpace};
use rayon::prelude::*;

use crate::error::{invalid, ImpactError, Result};

/// The coefficients of rings 0..n at every lag where any of them is nonzero, and the static
/// (Boussinesq) influence of the same rings, for unit ring width.
pub struct RingTables {
    space: HalfSpace<f64>,
    kappa: f64,
    /// The most lags any run will ask for (its steps).
    lag_cap: usize,
    n: usize,
    /// coef[l][i n + j] = c(i, j, l).
    coef: Vec<Vec<f64>>,
    /// stat[i n + j]: the static mean displacement over ring i due to a unit pressure on j.
    stat: Vec<f64>,
    /// The largest error estimate of any coefficient.
    largest_error: f64,
}

/// The area of ring i of unit width over pi: 1/4 for the central disk, 2 i otherwise.
pub fn ring_area_over_pi(i: usize) -> f64 {
    if i == 0 {
        0.25
    } else {
        2.0 * i as f64
    }
}

impl RingTables {
    /// An empty table for Poisson's ratio `poisson` and kappa = c1 dt/dr, for runs of at most
    /// `steps` steps (no lag beyond is computed).
    pub fn new(poisson: f64, kappa: f64, steps: usize) -> Result<Self> {
        if !(kappa.is_finite() && kappa > 0.0) {
            return Err(invalid("kappa", kappa, "(0, inf)"));
        }
        Ok(RingTables {
            space: HalfSpace::from_poisson(poisson)?,
            kappa,
            lag_cap: steps.max(1),
            n: 0,
            coef: Vec::new(),
            stat: Vec::new(),
            largest_error: 0.0,
        })
    }

    /// The half-space.
    pub fn space(&self) -> &HalfSpace<f64> {
        &self.space
    }

    /// kappa = c1 dt/dr.
    pub fn kappa(&self) -> f64 {
        self.kappa
    }

    /// The rings covered.
    pub fn rings(&self) -> usize {
        self.n
    }

    /// The largest error estimate of a coefficient (unit ring width).
    pub fn largest_error(&self) -> f64 {
        self.largest_error
    }

    /// The number of lags at which c(i, j, .) may be nonzero: the first l with
    /// s_R l kappa >= i + j + 1 (the arithmetic of [`HalfSpace::ring_pulse`]'s own test).
    pub fn lags(&self, i: usize, j: usize) -> usize {
        lags_of(*self.space.s_r(), self.kappa, i, j).min(self.lag_cap)
    }

    /// The number of lags of the table (those of its outermost pair).
    pub fn max_lags(&self) -> usize {
        self.coef.len()
    }

    /// c(i, j, l) (zero beyond the table's lags).
    #[inline]
    pub fn at(&self, l: usize, i: usize, j: usize) -> f64 {
        self.coef.get(l).map_or(0.0, |b| b[i * self.n + j])
    }

    /// The block c(., ., l), row-major with row length [`RingTables::rings`].
    #[inline]
    pub fn block(&self, l: usize) -> Option<&[f64]> {
        self.coef.get(l).map(|b| b.as_slice())
    }

    /// The static mean displacement over ring i due to a unit pressure on ring j.
    #[inline]
    pub fn static_at(&self, i: usize, j: usize) -> f64 {
        self.stat[i * self.n + j]
    }

    /// Makes the table cover rings 0..n (the pairs not yet computed, in parallel).
    pub fn ensure(&mut self, n: usize) -> Result<()> {
        if n <= self.n {
            return Ok(());
        }
        let old = self.n;
        let sr = *self.space.s_r();
        let kappa = self.kappa;
        let cap = self.lag_cap;
        let lmax = lags_of(sr, kappa, n - 1, n - 1).min(cap);
        // the pairs i <= j with j >= old, computed in parallel
        let pairs: Vec<(usize, usize)> = (0..n)
            .flat_map(|j| (0..=j).map(move |i| (i, j)))
            .filter(|&(_, j)| j >= old)
            .collect();
        let space = &self.space;
        let computed: Vec<PairResult> = pairs
            .par_iter()
            .map(|&(i, j)| {
                let r = Annulus::ring_cell(i, &1.0)?;
                let s = Annulus::ring_cell(j, &1.0)?;
                let mut err: f64 = 0.0;
                let lags = lags_of(sr, kappa, i, j).min(cap);
                let mut row = Vec::with_capacity(lags);
                for l in 0..lags {
                    let p =
                        space.ring_pulse(&r, &s, &(l as f64 * kappa), &((l + 1) as f64 * kappa))?;
                    err = err.max(p.error);
                    row.push(p.value);
                }
                let st = space.ring_static(&r, &s)?;
                Ok((row, st.value, err.max(st.error)))
            })
            .collect();
        let mut coef = vec![vec![0.0; n * n]; lmax];
        let mut stat = vec![0.0; n * n];
        for l in 0..self.coef.len().min(lmax) {
            for i in 0..old {
                coef[l][i * n..i * n + old].copy_from_slice(&self.coef[l][i * old..(i + 1) * old]);
            }
        }
        for i in 0..old {
            stat[i * n..i * n + old].copy_from_slice(&self.stat[i * old..(i + 1) * old]);
        }
        for (&(i, j), res) in pairs.iter().zip(computed) {
            let (row, st, err) = res.map_err(ImpactError::from)?;
            self.largest_error = self.largest_error.max(err);
            // reciprocity of the area-weighted form: A_i c(i, j) = A_j c(j, i)
            let ratio = ring_area_over_pi(i) / ring_area_over_pi(j);
            for (l, v) in row.into_iter().enumerate() {
                coef[l][i * n + j] = v;
                coef[l][j * n + i] = v * ratio;
            }
            stat[i * n + j] = st;
            stat[j * n + i] = st * ratio;
        }
        self.coef = coef;
        self.stat = stat;
        self.n = n;
        Ok(())
    }
}

/// A pair's pulses by lag, its static coefficient and their largest error estimate.
type PairResult = std::result::Result<(Vec<f64>, f64, f64), lamb::LambError>;

fn lags_of(s_r: f64, kappa: f64, i: usize, j: usize) -> usize {
    let reach = (i as f64 + 0.5) + (j as f64 + 0.5);
    let mut l = ((reach / (s_r * kappa)).floor() as usize).saturating_sub(1);
    while s_r * (l as f64 * kappa) < reach {
        l += 1;
    }
    l
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_holds_the_pulses_and_their_reciprocal_pairs() {
        let mut t = RingTables::new(0.3, 2.0, 1000).unwrap();
        t.ensure(3).unwrap();
        t.ensure(6).unwrap();
        let hs = HalfSpace::from_poisson(0.3f64).unwrap();
        for (i, j, l) in [(0, 0, 0), (2, 5, 1), (5, 2, 3), (4, 4, 2), (1, 3, 0)] {
            let r = Annulus::ring_cell(i, &1.0).unwrap();
            let s = Annulus::ring_cell(j, &1.0).unwrap();
            let want = hs
                .ring_pulse(&r, &s, &(l as f64 * 2.0), &((l + 1) as f64 * 2.0))
                .unwrap()
                .value;
            assert!((t.at(l, i, j) - want).abs() < 1e-13, "({i},{j},{l})");
        }
        // beyond its lags a pair's pulse vanishes, within them it does not
        let sr = *hs.s_r();
        for (i, j) in [(0, 0), (2, 5), (5, 5)] {
            let l = t.lags(i, j);
            assert!(sr * l as f64 * 2.0 >= (i + j + 1) as f64);
            assert!(sr * (l - 1) as f64 * 2.0 < (i + j + 1) as f64);
            assert_eq!(t.at(l, i, j), 0.0);
        }
    }
}
