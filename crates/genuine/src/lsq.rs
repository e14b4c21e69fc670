//! Linear least squares by Householder QR with column pivoting, generic over the precision
//! layer (the same code in f64 and in MPFR arithmetic).
//!
//! For an m x n matrix A (m >= n) the columns are reflected one at a time, the next pivot
//! being the remaining column of largest norm (recomputed from the untransformed rows at each
//! step, so the pivoting does not suffer from norm downdating; above f64 from the entries' f64
//! parts, the chosen column's norm at full precision). Columns whose pivot falls below
//! `rcond` times the first are treated as dependent and get a zero coefficient (the basic
//! solution), which is what a truncated SVD does for the residual, at a fraction of the cost.

use complexfn::Real;

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
}
