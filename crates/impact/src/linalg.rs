//! The step's linear systems (`docs/impact.md`, section 7): LU factorisations with partial
//! pivoting, dense and banded, and the contact system M = B + gamma 1 w^T (B the current
//! step's coefficients, banded when the kernels are causal with a finite reach in one step;
//! gamma 1 w^T the rigid striker's coupling through its equation of motion, every row the
//! same) solved with the Sherman-Morrison formula on B's factorisation.

use crate::scalar::Scalar;

/// The LU factorisation with partial pivoting of a row-major n x n matrix.
#[derive(Debug)]
pub(crate) struct Lu<T = f64> {
    n: usize,
    /// U on and above the diagonal, the multipliers of L below it.
    a: Vec<T>,
    /// The row swapped into place at each column.
    piv: Vec<usize>,
}

impl<T: Scalar> Lu<T> {
    /// Factorises `a`; `None` when a pivot vanishes.
    pub(crate) fn new(mut a: Vec<T>, n: usize) -> Option<Self> {
        let mut piv = Vec::with_capacity(n);
        for c in 0..n {
            let mut p = c;
            for i in c + 1..n {
                if a[i * n + c].abs() > a[p * n + c].abs() {
                    p = i;
                }
            }
            if !(a[p * n + c].abs() > 0.0) {
                return None;
            }
            if p != c {
                for j in 0..n {
                    a.swap(c * n + j, p * n + j);
                }
            }
            piv.push(p);
            let d = a[c * n + c];
            for i in c + 1..n {
                let f = a[i * n + c] / d;
                a[i * n + c] = f;
                if f != 0.0 {
                    for j in c + 1..n {
                        let acj = a[c * n + j];
                        a[i * n + j] -= f * acj;
                    }
                }
            }
        }
        Some(Lu { n, a, piv })
    }

    /// The solution of a x = r; `None` when it is not finite.
    pub(crate) fn solve(&self, r: &[T]) -> Option<Vec<T>> {
        let (n, a) = (self.n, &self.a);
        let mut x = r.to_vec();
        // the rows were swapped whole (multipliers included): all swaps first, then L
        for (c, &p) in self.piv.iter().enumerate() {
            x.swap(c, p);
        }
        for c in 0..n {
            let xc = x[c];
            if xc != 0.0 {
                for i in c + 1..n {
                    x[i] -= a[i * n + c] * xc;
                }
            }
        }
        for i in (0..n).rev() {
            let mut s = x[i];
            for j in i + 1..n {
                s -= a[i * n + j] * x[j];
            }
            x[i] = s / a[i * n + i];
        }
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

/// The LU factorisation with partial pivoting of an n x n band matrix with `kl` sub- and
/// `ku` super-diagonals, in column-major band storage (LAPACK's `gbtrf` layout: the row swaps
/// widen U to kl + ku super-diagonals). O(n kl (kl + ku)) to factorise, O(n (2 kl + ku)) to
/// solve.
#[derive(Debug)]
pub(crate) struct BandLu<T = f64> {
    n: usize,
    kl: usize,
    ku: usize,
    /// Column j holds rows j - kl - ku ..= j + kl at offsets 0 ..= 2 kl + ku.
    ab: Vec<T>,
    /// The row swapped into place at each column.
    piv: Vec<usize>,
}

impl<T: Scalar> BandLu<T> {
    fn at(&self, i: usize, j: usize) -> usize {
        j * (2 * self.kl + self.ku + 1) + self.kl + self.ku + i - j
    }

    /// Factorises the matrix whose entries in the band (i - kl <= j <= i + ku)
    /// are `entry(i, j)`; `None` when a pivot vanishes.
    pub(crate) fn new(
        n: usize,
        kl: usize,
        ku: usize,
        entry: impl Fn(usize, usize) -> T,
    ) -> Option<Self> {
        let ld = 2 * kl + ku + 1;
        let mut lu = BandLu {
            n,
            kl,
            ku,
            ab: vec![T::of(0.0); n * ld],
            piv: Vec::with_capacity(n),
        };
        for j in 0..n {
            for i in j.saturating_sub(ku)..(j + kl + 1).min(n) {
                let k = lu.at(i, j);
                lu.ab[k] = entry(i, j);
            }
        }
        for c in 0..n {
            let last = (c + kl).min(n - 1);
            let right = (c + kl + ku).min(n - 1);
            let mut p = c;
            for i in c + 1..=last {
                if lu.ab[lu.at(i, c)].abs() > lu.ab[lu.at(p, c)].abs() {
                    p = i;
                }
            }
            if !(lu.ab[lu.at(p, c)].abs() > 0.0) {
                return None;
            }
            lu.piv.push(p);
            if p != c {
                // U's part of the two rows (the multipliers stay: L is applied with the swaps
                // interleaved)
                for j in c..=right {
                    let (a, b) = (lu.at(c, j), lu.at(p, j));
                    lu.ab.swap(a, b);
                }
            }
            let d = lu.ab[lu.at(c, c)];
            for i in c + 1..=last {
                let ic = lu.at(i, c);
                let f = lu.ab[ic] / d;
                lu.ab[ic] = f;
                if f != 0.0 {
                    for j in c + 1..=right {
                        let (ij, cj) = (lu.at(i, j), lu.at(c, j));
                        let acj = lu.ab[cj];
                        lu.ab[ij] -= f * acj;
                    }
                }
            }
        }
        Some(lu)
    }

    /// The solution of a x = r; `None` when it is not finite.
    pub(crate) fn solve(&self, r: &[T]) -> Option<Vec<T>> {
        let n = self.n;
        let ld = 2 * self.kl + self.ku + 1;
        let mut x = r.to_vec();
        for c in 0..n {
            x.swap(c, self.piv[c]);
            let xc = x[c];
            let last = (c + self.kl).min(n - 1);
            if xc != 0.0 && last > c {
                // column c's multipliers lie contiguously below its diagonal
                let l = &self.ab[self.at(c + 1, c)..=self.at(last, c)];
                for (xi, m) in x[c + 1..=last].iter_mut().zip(l) {
                    *xi -= *m * xc;
                }
            }
        }
        for i in (0..n).rev() {
            let end = (i + self.kl + self.ku).min(n - 1);
            let mut s = x[i];
            if end > i {
                // row i of U steps by ld - 1 through the band storage
                let u = self.ab[self.at(i, i + 1)..].iter().step_by(ld - 1);
                for (uij, xj) in u.zip(&x[i + 1..=end]) {
                    s -= *uij * *xj;
                }
            }
            x[i] = s / self.ab[self.at(i, i)];
        }
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

/// A factorised contact system M.
#[derive(Debug)]
pub(crate) enum Factor<T = f64> {
    /// M factorised whole.
    Dense(Lu<T>),
    /// M = B + gamma 1 w^T with B banded: B's factorisation, q = B^-1 1 and gamma/(1 + gamma
    /// w.q) (Sherman-Morrison: M^-1 r = y - q gamma (w.y)/(1 + gamma w.q), y = B^-1 r).
    Band {
        /// B's factorisation.
        lu: BandLu<T>,
        /// The column weights w.
        w: Vec<T>,
        /// B^-1 1 (empty when gamma = 0).
        q: Vec<T>,
        /// gamma/(1 + gamma w.q).
        scale: T,
    },
}

impl<T: Scalar> Factor<T> {
    /// M = B + gamma 1 w^T with B of half-bandwidth `band` given by `entry`, factorised
    /// banded when the band is narrow against n, whole otherwise; `None` when M is singular.
    pub(crate) fn new(
        n: usize,
        band: Option<usize>,
        entry: impl Fn(usize, usize) -> T,
        gamma: T,
        w: Vec<T>,
    ) -> Option<Self> {
        match band {
            Some(s) if 4 * s + 8 < n => {
                let lu = BandLu::new(n, s, s, entry)?;
                let (q, scale) = if gamma != 0.0 {
                    let q = lu.solve(&vec![T::of(1.0); n])?;
                    let den = gamma * T::dot(&w, &q) + 1.0;
                    if !(den.abs() > 1e-300) {
                        return None;
                    }
                    (q, gamma / den)
                } else {
                    (Vec::new(), T::of(0.0))
                };
                Some(Factor::Band { lu, w, q, scale })
            }
            _ => {
                let mut a = vec![T::of(0.0); n * n];
                for i in 0..n {
                    for j in 0..n {
                        a[i * n + j] = entry(i, j) + gamma * w[j];
                    }
                }
                Lu::new(a, n).map(Factor::Dense)
            }
        }
    }

    /// The solution of M x = r; `None` when it is not finite.
    pub(crate) fn solve(&self, r: &[T]) -> Option<Vec<T>> {
        match self {
            Factor::Dense(lu) => lu.solve(r),
            Factor::Band { lu, w, q, scale } => {
                let mut y = lu.solve(r)?;
                if !q.is_empty() {
                    let k = *scale * T::dot(w, &y);
                    for (yi, qi) in y.iter_mut().zip(q) {
                        *yi -= k * *qi;
                    }
                }
                y.iter().all(|v| v.is_finite()).then_some(y)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn residual(a: &dyn Fn(usize, usize) -> f64, n: usize, x: &[f64], r: &[f64]) -> f64 {
        (0..n)
            .map(|i| ((0..n).map(|j| a(i, j) * x[j]).sum::<f64>() - r[i]).abs())
            .fold(0.0, f64::max)
    }

    /// The LU factorisation solves a system that needs pivoting (a zero leading entry) to its
    /// residual's rounding, for several right-hand sides, and refuses a singular matrix.
    #[test]
    fn lu_solves_with_pivoting_and_refuses_a_singular_matrix() {
        let n = 7;
        let a: Vec<f64> = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                if i == 0 && j == 0 {
                    0.0
                } else {
                    1.0 / (1.0 + (i as f64 - j as f64).abs()) + ((i * 7 + j * 3) % 5) as f64 * 0.1
                }
            })
            .collect();
        let lu = Lu::new(a.clone(), n).unwrap();
        for r in [vec![1.0; n], (0..n).map(|i| i as f64 - 3.0).collect()] {
            let x = lu.solve(&r).unwrap();
            assert!(residual(&|i, j| a[i * n + j], n, &x, &r) < 1e-12);
        }
        // a column of zeros: no pivot
        let mut sing = a;
        for i in 0..n {
            sing[i * n + 3] = 0.0;
        }
        assert!(Lu::new(sing, n).is_none());
    }

    /// A band matrix whose pivots need row swaps (small diagonal, larger sub-diagonals):
    /// the banded factorisation's solution has a rounding-level residual, and the rank-one
    /// coupling through Sherman-Morrison equals the dense solve of the coupled matrix.
    #[test]
    fn band_lu_pivots_and_the_coupled_system_matches_the_dense_one() {
        let (n, kl, ku) = (40, 3, 2);
        let a = move |i: usize, j: usize| -> f64 {
            let d = j as i64 - i as i64;
            if d < -(kl as i64) || d > ku as i64 {
                0.0
            } else if d == 0 {
                0.01 * (1.0 + (i % 3) as f64)
            } else {
                1.0 / (1.0 + d.abs() as f64) + ((i * 5 + j * 3) % 7) as f64 * 0.05
            }
        };
        let lu = BandLu::new(n, kl, ku, a).unwrap();
        assert!(lu.piv.iter().enumerate().any(|(c, &p)| p != c));
        let r: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let x = lu.solve(&r).unwrap();
        assert!(
            residual(&a, n, &x, &r) < 1e-11,
            "{}",
            residual(&a, n, &x, &r)
        );

        let gamma = 0.37;
        let w: Vec<f64> = (0..n).map(|j| 1.0 + 0.1 * j as f64).collect();
        let wc = w.clone();
        let coupled = move |i: usize, j: usize| a(i, j) + gamma * wc[j];
        let band = Factor::new(n, Some(kl.max(ku)), a, gamma, w.clone()).unwrap();
        assert!(matches!(band, Factor::Band { .. }));
        let dense = Factor::new(n, None, a, gamma, w).unwrap();
        let (xb, xd) = (band.solve(&r).unwrap(), dense.solve(&r).unwrap());
        assert!(residual(&coupled, n, &xb, &r) < 1e-10);
        for (u, v) in xb.iter().zip(&xd) {
            assert!((u - v).abs() < 1e-10 * (1.0 + v.abs()), "{u} vs {v}");
        }
        // a singular band matrix is refused
        assert!(BandLu::new(n, kl, ku, |i, j| if j == 5 { 0.0 } else { a(i, j) }).is_none());
    }

    /// The same factorisations in double-double: the residuals fall to that precision's
    /// rounding (computed in double-double), and the f64 solutions agree to theirs.
    #[test]
    fn double_double_systems_reach_their_rounding() {
        use complexfn::{Dd, Real};
        let (n, kl) = (30, 3);
        let entry = |i: usize, j: usize| -> f64 {
            let d = i.abs_diff(j);
            if d > kl {
                0.0
            } else {
                1.0 / (1.0 + d as f64) + ((i * 5 + j * 3) % 7) as f64 * 0.05
            }
        };
        let dd = |i: usize, j: usize| Dd::of(entry(i, j)) / Dd::of(3.0);
        let gamma = Dd::of(0.37);
        let w: Vec<Dd> = (0..n).map(|j| Dd::of(1.0 + 0.1 * j as f64)).collect();
        let r: Vec<Dd> = (0..n).map(|i| Dd::of(i as f64 * 0.7).sin()).collect();
        for band in [Some(kl), None] {
            let m = Factor::new(n, band, dd, gamma, w.clone()).unwrap();
            let x = m.solve(&r).unwrap();
            let wx = Dd::dot(&w, &x);
            let worst = (0..n)
                .map(|i| {
                    let row: Vec<Dd> = (0..n).map(|j| dd(i, j)).collect();
                    (Dd::dot(&row, &x) + gamma * wx - r[i]).abs().to_f64()
                })
                .fold(0.0, f64::max);
            assert!(worst < 1e-29, "{band:?}: residual {worst:e}");
            // the f64 solve of the same matrix (rounded) agrees to f64's rounding
            let m64 = Factor::new(
                n,
                band,
                |i, j| dd(i, j).to_f64(),
                0.37,
                w.iter().map(|v| v.to_f64()).collect(),
            )
            .unwrap();
            let x64 = m64
                .solve(&r.iter().map(|v| v.to_f64()).collect::<Vec<_>>())
                .unwrap();
            for (a, b) in x.iter().zip(&x64) {
                assert!((a.to_f64() - b).abs() < 1e-12 * (1.0 + b.abs()));
            }
        }
    }
}
