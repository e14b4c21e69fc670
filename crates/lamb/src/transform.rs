//! Lamb's self-similar surface response of an elastic half-plane y <= 0 (`docs/lamb.md`, section 1).
//!
//! Units c1 = 1, mu = 1; m = c2/c1. With the two-sided transform f^(xi) = Int f e^{s xi x} dx
//! (so d/dx -> -s xi) and the Laplace transform in t, potentials e^{s a_k y} that decay as
//! y -> -inf give, for surface tractions T_y = sigma_yy, T_x = sigma_xy,
//!
//! ```text
//!   u_y^ = [K_yy T_y + K_yx T_x]/(mu s),   u_x^ = [K_xy T_y + K_xx T_x]/(mu s),
//!   K_yy = a1/(c2^2 R),  K_xx = a2/(c2^2 R),  K_yx = -K_xy = xi (k - 2 a1 a2)/R,
//!   a_k = (1/c_k^2 - xi^2)^(1/2) (Re a_k > 0),  k = 1/c2^2 - 2 xi^2,  R = k^2 + 4 xi^2 a1 a2.
//! ```
//!
//! (Derived from sigma_yy = mu s^2 (k A + 2 xi a2 B), sigma_xy = mu s^2 (-2 xi a1 A + k B) for
//! phi = A e^{s a1 y}, psi = B e^{s a2 y}; the sign of K_yx is fixed by the transform
//! convention and checked by the Cerruti test.) The principal square root gives Re a_k > 0
//! everywhere off the real cuts |xi| > 1/c_k, i.e. on the whole upper half of z = 1/xi.
//!
//! Cancellation: for |xi| >> 1 both R and k - 2 a1 a2 cancel. The products
//! R (k^2 - 4 xi^2 a1 a2) and (k - 2 a1 a2)(k + 2 a1 a2) are polynomials in s = xi^2 (a cubic
//! and a linear function; the s^4 and s^2 terms cancel exactly), so whichever factor is larger
//! is computed directly and the other as polynomial/factor.

use complexfn::{Cx, Real};

/// Complex f64.
pub type C64 = Cx<f64>;

/// The half-plane's surface response for speed ratio m = c2/c1 (c1 = 1, mu = 1), at the
/// precision of `m`.
#[derive(Clone, Debug)]
pub struct Lamb<T = f64> {
    m: T,
    /// 1/c2^2
    pub(crate) b: T,
}

/// The four kernels at one slowness: `[[K_yy, K_yx], [K_xy, K_xx]]`.
pub type Kernels<T = f64> = [[Cx<T>; 2]; 2];

impl<T: Real> Lamb<T> {
    /// The response for m = c2/c1 in (0, sqrt(3)/2).
    pub fn new(m: T) -> Self {
        let b = m.clone().sqr().recip();
        Lamb { m, b }
    }

    /// m = c2/c1.
    pub fn m(&self) -> T {
        self.m.clone()
    }

    /// The kernels K_jk(xi) at a complex slowness xi off the cuts |Re xi| > 1/c_k of the real
    /// axis (units c1 = 1).
    pub fn kernels(&self, xi: &Cx<T>) -> Kernels<T> {
        let b = &self.b;
        let bb = b.clone().sqr();
        let s = xi.clone() * xi;
        let a1 = (-s.clone()).add_re(&b.one()).sqrt();
        let a2 = (-s.clone()).add_re(b).sqrt();
        let k = (s.clone() * -2.0).add_re(b);
        let a12 = a1.clone() * &a2;
        let q = s.clone() * &a12 * 4.0;
        let kk = k.clone() * &k;
        let (r_plus, r_minus) = (kk.clone() + &q, kk - &q);
        // R (k^2 - 4 s a1 a2) = b^4 - 8 b^3 s + (24 b^2 - 16 b) s^2 + 16 (1 - b) s^3
        let c3 = (b.one() - b) * 16.0;
        let c2 = bb.clone() * 24.0 - b.clone() * 16.0;
        let c1 = bb.clone() * b * -8.0;
        let cubic =
            ((s.clone().scale(&c3).add_re(&c2) * &s).add_re(&c1) * &s).add_re(&bb.clone().sqr());
        let r = if r_plus.norm_sqr() >= r_minus.norm_sqr() {
            r_plus
        } else {
            cubic / &r_minus
        };
        let aa = a12 * 2.0;
        let (n_minus, n_plus) = (k.clone() - &aa, k + &aa);
        // (k - 2 a1 a2)(k + 2 a1 a2) = b^2 - 4 b + 4 s
        let lin = (s * 4.0).add_re(&(bb - b.clone() * 4.0));
        let nyx = if n_minus.norm_sqr() >= n_plus.norm_sqr() {
            n_minus
        } else {
            lin / &n_plus
        };
        let rinv = r.recip();
        let kyy = (a1 * &rinv).scale(b);
        let kxx = (a2 * &rinv).scale(b);
        let kyx = xi.clone() * &nyx * &rinv;
        [[kyy, kyx.clone()], [-kyx, kxx]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn direct<T: Real>(l: &Lamb<T>, xi: &Cx<T>) -> (Cx<T>, Cx<T>) {
        let one = xi.re.one();
        let s = xi.clone() * xi;
        let a1 = (-s.clone()).add_re(&one).sqrt();
        let a2 = (-s.clone()).add_re(&l.b).sqrt();
        let k = (s.clone() * -2.0).add_re(&l.b);
        let r = k.clone() * &k + s * &a1 * &a2 * 4.0;
        let kyx = xi.clone() * &(k - a1.clone() * &a2 * 2.0) / &r;
        let kyy = (a1 / &r).scale(&l.b);
        (kyy, kyx)
    }

    #[test]
    fn cancellation_free_forms_agree_with_the_direct_ones() {
        let l = Lamb::new(0.5345);
        for (re, im) in [(0.3, -0.2), (1.5, -0.4), (-0.2, -2.0)] {
            let xi = C64::new(re, im);
            let kk = l.kernels(&xi);
            let (kyy, kyx) = direct(&l, &xi);
            assert!((kk[0][1].clone() - &kyx).abs() < 1e-12 * kyx.abs());
            assert!((kk[0][0].clone() - &kyy).abs() < 1e-12 * kyy.abs());
        }
        // the same at 192 bits, to a tolerance far below f64's
        let like = rug::Float::with_val(192, 0);
        let l = Lamb::new(like.lit(0.5345));
        for (re, im) in [(0.3, -0.2), (1.5, -0.4), (-0.2, -2.0)] {
            let xi = Cx::lit(&like, re, im);
            let kk = l.kernels(&xi);
            let (kyy, kyx) = direct(&l, &xi);
            let e1 = ((kk[0][1].clone() - &kyx).abs() / kyx.abs()).to_f64();
            let e2 = ((kk[0][0].clone() - &kyy).abs() / kyy.abs()).to_f64();
            assert!(e1 < 1e-50 && e2 < 1e-50, "{e1:e} {e2:e}");
        }
    }
}
