//! Small dense and band linear algebra shared by the solvers: the dense column-major
//! [`Matrix`] and linear least squares by Householder QR with column pivoting
//! ([`least_squares`], any precision: the genuine wedge solver's collocation fits), and the LU
//! factorisations with partial pivoting of a row-major dense matrix ([`Lu`]) and of a band
//! matrix ([`BandLu`]), for the fixed-width reals (`f64`, [`crate::Dd`]: the impact march's
//! step systems).
//!
//! Least squares: for an m x n matrix A (m >= n) the columns are reflected one at a time, the
//! next pivot being the remaining column of largest norm (recomputed from the untransformed
//! rows at each step, so the pivoting does not suffer from norm downdating; above f64 from the
//! entries' f64 parts, the chosen column's norm at full precision). Columns whose pivot falls
//! below `rcond` times the first are treated as dependent and get a zero coefficient (the
//! basic solution), which is what a truncated SVD does for the residual, at a fraction of the
//! cost.

use crate::Real;

/// A dense column-major matrix.
#[derive(Clone, Debug)]
pub struct Matrix<T> {
    rows: usize,
    cols: usize,
    data: Vec<T>,
}

impl<T: Real> Matrix<T> {
    /// The zero matrix with `rows` x `cols` entries at the precision of `like`.
    pub fn zeros(rows: usize, cols: usize, like: &T) -> Self {
        Matrix {
            rows,
            cols,
            data: vec![like.zero(); rows * cols],
        }
    }
    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }
    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }
    /// Entry (i, j).
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> &T {
        &self.data[j * self.rows + i]
    }
    /// Mutable entry (i, j).
    #[inline]
    pub fn get_mut(&mut self, i: usize, j: usize) -> &mut T {
        &mut self.data[j * self.rows + i]
    }
    /// Column j.
    pub fn col(&self, j: usize) -> &[T] {
        &self.data[j * self.rows..(j + 1) * self.rows]
    }
    /// Column j, mutable.
    pub fn col_mut(&mut self, j: usize) -> &mut [T] {
        &mut self.data[j * self.rows..(j + 1) * self.rows]
    }
    /// A x.
    pub fn mul_vec(&self, x: &[T]) -> Vec<T> {
        let mut out = vec![x[0].zero(); self.rows];
        for (j, xj) in x.iter().enumerate() {
            for (o, a) in out.iter_mut().zip(self.col(j)) {
                o.mul_add_assign(a, xj);
            }
        }
        out
    }
}

/// The solution of min ||A x - b||_2 (A: m x n, m >= n) and the numerical rank.
///
/// Householder QR with column pivoting; a column whose remaining norm is below `rcond` times
/// the largest pivot is dropped (coefficient zero).
pub fn least_squares<T: Real>(a: &Matrix<T>, b: &[T], rcond: f64) -> (Vec<T>, usize) {
    let (m, n) = (a.rows, a.cols);
    assert!(m >= n && b.len() == m, "least_squares: shape");
    let mut q = a.clone();
    let mut rhs: Vec<T> = b.to_vec();
    let mut perm: Vec<usize> = (0..n).collect();
    let mut diag: Vec<T> = Vec::with_capacity(n);
    let zero = b[0].zero();
    let mut first = zero.clone();
    let mut rank = n;
    // above f64 the pivot is chosen by the norms of the columns' leading f64 parts (the
    // choice differs from the exact one only where two norms agree to f64's rounding, and
    // either is as good a pivot); the pivot's norm itself is summed at full precision
    let approx = zero.prec() > 53;
    for k in 0..n {
        // pivot: the remaining column of largest norm over rows k..m
        let (pj, norm2) = if approx {
            let mut best = (k, 0.0_f64);
            for j in k..n {
                let s = q.col(j)[k..].iter().fold(0.0_f64, |s, x| {
                    let x = x.to_f64();
                    s + x * x
                });
                if s > best.1 {
                    best = (j, s);
                }
            }
            let mut norm2 = zero.clone();
            let x = &q.col(best.0)[k..];
            norm2.dot_add(x, x);
            (best.0, norm2)
        } else {
            let mut best = (k, zero.clone());
            for j in k..n {
                let mut s = zero.clone();
                let x = &q.col(j)[k..];
                s.dot_add(x, x);
                if s > best.1 {
                    best = (j, s);
                }
            }
            best
        };
        if pj != k {
            for i in 0..m {
                q.data.swap(k * m + i, pj * m + i);
            }
            perm.swap(k, pj);
        }
        let alpha = norm2.sqrt();
        if k == 0 {
            first = alpha.clone();
        }
        let threshold = first.clone() * rcond;
        let independent = alpha > threshold && alpha != 0.0;
        if !independent {
            rank = k;
            break;
        }
        // v = x + sign(x_k) |x| e_k, stored in place; H = I - v v^T/(|x| |v_k|)
        let xk = q.get(k, k).clone();
        let r_kk = if xk.is_sign_negative() {
            alpha.clone()
        } else {
            -alpha.clone()
        };
        let vk = xk - &r_kk;
        *q.get_mut(k, k) = vk.clone();
        // v^T v / 2 = alpha (alpha + |x_k|) = -r_kk v_k
        let tau = -(r_kk.clone() * &vk);
        let (head, tail) = q.data.split_at_mut((k + 1) * m);
        let v = &head[k * m + k..(k + 1) * m];
        for j in 0..(n - k - 1) {
            let c = &mut tail[j * m + k..(j + 1) * m];
            let mut dot = zero.clone();
            dot.dot_add(v, c);
            let f = -(dot / &tau);
            T::mul_add_slice(c, v, &f);
        }
        let mut dot = zero.clone();
        dot.dot_add(v, &rhs[k..]);
        let f = -(dot / &tau);
        T::mul_add_slice(&mut rhs[k..], v, &f);
        diag.push(r_kk);
    }
    // back substitution on the leading rank x rank block of R
    let mut y = vec![zero.clone(); rank];
    for i in (0..rank).rev() {
        let mut s = rhs[i].clone();
        for (j, yj) in y.iter().enumerate().skip(i + 1) {
            s.mul_sub_assign(q.get(i, j), yj);
        }
        y[i] = s / &diag[i];
    }
    let mut x = vec![zero; n];
    for (i, yi) in y.into_iter().enumerate() {
        x[perm[i]] = yi;
    }
    (x, rank)
}

/// The LU factorisation with partial pivoting of a row-major n x n matrix.
#[derive(Debug)]
pub struct Lu<T = f64> {
    n: usize,
    /// U on and above the diagonal, the multipliers of L below it.
    a: Vec<T>,
    /// The row swapped into place at each column.
    piv: Vec<usize>,
}

impl<T: Real + Copy> Lu<T> {
    /// Factorises `a`; `None` when a pivot vanishes.
    pub fn new(mut a: Vec<T>, n: usize) -> Option<Self> {
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
    pub fn solve(&self, r: &[T]) -> Option<Vec<T>> {
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
pub struct BandLu<T = f64> {
    n: usize,
    kl: usize,
    ku: usize,
    /// Column j holds rows j - kl - ku ..= j + kl at offsets 0 ..= 2 kl + ku.
    ab: Vec<T>,
    /// The row swapped into place at each column.
    piv: Vec<usize>,
}

impl<T: Real + Copy> BandLu<T> {
    fn at(&self, i: usize, j: usize) -> usize {
        j * (2 * self.kl + self.ku + 1) + self.kl + self.ku + i - j
    }

    /// Factorises the matrix whose entries in the band (i - kl <= j <= i + ku)
    /// are `entry(i, j)`; `None` when a pivot vanishes.
    pub fn new(n: usize, kl: usize, ku: usize, entry: impl Fn(usize, usize) -> T) -> Option<Self> {
        let ld = 2 * kl + ku + 1;
        let mut lu = BandLu {
            n,
            kl,
            ku,
            ab: vec![T::from_f64_prec(0.0, 53); n * ld],
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
    pub fn solve(&self, r: &[T]) -> Option<Vec<T>> {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn check<T: Real>(like: &T, tol: f64) {
        // overdetermined, consistent system with a known solution
        let (m, n) = (9, 5);
        let mut a = Matrix::zeros(m, n, like);
        for i in 0..m {
            for j in 0..n {
                let x = like.lit((i as f64 + 0.5) / m as f64);
                *a.get_mut(i, j) = x.powi(j as i32) + like.lit(0.1 * (i * j) as f64).sin();
            }
        }
        let xs: Vec<T> = (0..n).map(|j| like.lit(1.0 + j as f64) / 3.0).collect();
        let b = a.mul_vec(&xs);
        let (x, rank) = least_squares(&a, &b, 1e-30);
        assert_eq!(rank, n);
        for (u, v) in x.iter().zip(&xs) {
            let e = (u.clone() - v).abs().to_f64();
            assert!(e < tol, "{e:e}");
        }
        // least-squares residual is orthogonal to the columns
        let mut b2 = b.clone();
        b2[3] += 1.0;
        let (x2, _) = least_squares(&a, &b2, 1e-30);
        let r: Vec<T> = a
            .mul_vec(&x2)
            .into_iter()
            .zip(&b2)
            .map(|(u, v)| u - v)
            .collect();
        for j in 0..n {
            let mut d = like.zero();
            for (ai, ri) in a.col(j).iter().zip(&r) {
                d += ai.clone() * ri;
            }
            assert!(d.abs().to_f64() < tol, "normal equations");
        }
    }

    #[test]
    fn solves_least_squares_in_f64_and_at_160_bits() {
        check(&0.0_f64, 1e-11);
        check(&rug::Float::with_val(160, 0), 1e-40);
    }

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
    fn band_lu_pivots_to_a_rounding_level_residual() {
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
        // a singular band matrix is refused
        assert!(BandLu::new(n, kl, ku, |i, j| if j == 5 { 0.0 } else { a(i, j) }).is_none());
    }
}
