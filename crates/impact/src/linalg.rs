//! The contact system of the march's steps (`docs/impact.md`, section 7):
//! M = B + gamma 1 w^T (B the current step's coefficients, banded when the kernels are causal
//! with a finite reach in one step; gamma 1 w^T the rigid striker's coupling through its
//! equation of motion, every row the same), solved with the Sherman-Morrison formula on B's
//! factorisation. The factorisations themselves (dense and band LU with partial pivoting) are
//! the shared ones of [`complexfn::linalg`]; this rank-one coupling stays here because it is
//! the march's own (the striker's equation of motion), not a general solver.

use complexfn::linalg::{BandLu, Lu};

use crate::scalar::Scalar;

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

/// Murty's least-index principal pivoting for the step's linear complementarity problem
/// (`docs/impact.md`, section 9): over the cells (or rings) 0..=top, p >= 0 on the contact,
/// gap >= 0 off it, one of the two zero on each. Started from the contact 0..=k0 (none when
/// `k0` is `None`); `solve` gives the step's solution for an ascending contact set (the
/// empty set included), `wrong(solution, i, inside)` tells whether cell i is on the wrong
/// side (pulling inside, interpenetrating outside). The first wrong cell changes side until
/// none is. The rule ends for a P-matrix (the step's matrix, positive definite up to the
/// striker's rank-one coupling); `None` when it has not settled within a bound that guards
/// against a matrix that is not. Returns the contact set and its solution.
pub(crate) fn least_index_pivoting<S, E>(
    top: usize,
    k0: Option<usize>,
    mut solve: impl FnMut(&[usize]) -> Result<S, E>,
    mut wrong: impl FnMut(&S, usize, bool) -> bool,
) -> Result<Option<(Vec<usize>, S)>, E> {
    let mut inside = vec![false; top + 1];
    if let Some(k0) = k0 {
        for c in inside.iter_mut().take(k0.min(top) + 1) {
            *c = true;
        }
    }
    let limit = 8 * (top + 1) + 16;
    for _ in 0..limit {
        let cells: Vec<usize> = (0..=top).filter(|&i| inside[i]).collect();
        let s = solve(&cells)?;
        match (0..=top).find(|&i| wrong(&s, i, inside[i])) {
            Some(i) => inside[i] = !inside[i],
            None => return Ok(Some((cells, s))),
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn residual(a: &dyn Fn(usize, usize) -> f64, n: usize, x: &[f64], r: &[f64]) -> f64 {
        (0..n)
            .map(|i| ((0..n).map(|j| a(i, j) * x[j]).sum::<f64>() - r[i]).abs())
            .fold(0.0, f64::max)
    }

    /// Least-index pivoting solves small complementarity problems w = M z + q >= 0, z >= 0,
    /// z.w = 0 (M positive definite) whose solutions are known by hand, from any start, and
    /// returns a contact that is not a leading block when the solution has one.
    #[test]
    fn least_index_pivoting_solves_small_complementarity_problems() {
        let m = [[2.0, 1.0, 0.5], [1.0, 2.0, 1.0], [0.5, 1.0, 2.0]];
        let solve = |q: [f64; 3], set: &[usize]| -> Result<Vec<f64>, ()> {
            let n = set.len();
            let f = Factor::new(n, None, |i, j| m[set[i]][set[j]], 0.0, vec![1.0; n]).ok_or(())?;
            let r: Vec<f64> = set.iter().map(|&i| -q[i]).collect();
            let zs = f.solve(&r).ok_or(())?;
            let mut z = vec![0.0; 3];
            for (&i, v) in set.iter().zip(zs) {
                z[i] = v;
            }
            Ok(z)
        };
        let w = |q: [f64; 3], z: &[f64], i: usize| -> f64 {
            (0..3).map(|j| m[i][j] * z[j]).sum::<f64>() + q[i]
        };
        // (q, the contact, z on it)
        let cases: [([f64; 3], Vec<usize>, Vec<f64>); 4] = [
            ([1.0, 1.0, 1.0], vec![], vec![0.0, 0.0, 0.0]),
            ([-2.0, 1.0, 1.0], vec![0], vec![1.0, 0.0, 0.0]),
            ([-1.0, 2.0, -1.0], vec![0, 2], vec![0.4, 0.0, 0.4]),
            ([-3.5, -4.0, -3.5], vec![0, 1, 2], vec![1.0, 1.0, 1.0]),
        ];
        for (q, contact, z0) in cases {
            for start in [None, Some(0), Some(2)] {
                let (set, z) = least_index_pivoting(
                    2,
                    start,
                    |set: &[usize]| solve(q, set),
                    |z: &Vec<f64>, i, inside| if inside { z[i] < 0.0 } else { w(q, z, i) < 0.0 },
                )
                .unwrap()
                .unwrap();
                assert_eq!(set, contact, "q {q:?} from {start:?}");
                for i in 0..3 {
                    assert!((z[i] - z0[i]).abs() < 1e-14, "q {q:?}: z {z:?}");
                }
            }
        }
    }

    /// The rank-one coupling of a band matrix whose pivots need row swaps, through
    /// Sherman-Morrison, equals the dense solve of the coupled matrix.
    #[test]
    fn the_coupled_band_system_matches_the_dense_one() {
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
        let r: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
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
