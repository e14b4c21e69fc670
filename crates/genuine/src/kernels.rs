//! Lamb's self-similar surface response of an elastic half-plane y <= 0 (errata, section 6b).
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
//! Degree-0 tractions S_k(x/t) and displacements u_j = t U_j(x/t): with z = 1/xi the traction
//! transform is z^2 F_k(z)/s^2, F_k(z) = Int S_k(w)/(w - z)^2 dw, and the displacement one is
//! -(2 z^3/s^3) Int U_j(w)/(w - z)^3 dw. Hence Phi_j(z) = Int U_j(w)/(w - z) dw satisfies
//! Phi_j'' = -K_jk(1/z) F_k(z)/z; integrating twice from infinity along z = x0 + i y and
//! taking the jump U = Im Phi(x0 + i0)/pi gives the representation used here,
//!
//! ```text
//!   U_j(x0)  = (1/pi) Im Int_0^inf y K_jk(1/z) F_k(z)/z dy,
//!   U_j'(x0) = (1/pi) Re Int_0^inf   K_jk(1/z) F_k(z)/z dy,        z = x0 + i y,
//! ```
//!
//! which needs no principal values and no Rayleigh-pole terms.
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
    b: T,
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

    /// The displacements (U_y, U_x)(x0) and their slopes (U_y', U_x')(x0) produced by degree-0
    /// tractions whose F-functions are given by `f(z) = [F_y(z), F_x(z)]`, from the contour
    /// representation along z = x0 + i y (module docs). `rel_tol` is the tolerance of the
    /// nested tanh-sinh rule in y (mapped by y = Y u/(1 - u), Y = max(|x0|, 0.05); step down
    /// to 2^-8 at 53 bits, one more halving per doubling of the precision). Returns the values
    /// and the estimated absolute error.
    pub fn displacement<F>(&self, x0: T, rel_tol: f64, mut f: F) -> ([T; 4], f64)
    where
        F: FnMut(Cx<T>) -> [Cx<T>; 2],
    {
        let prec = x0.prec();
        let (v, err) = y_integral(&x0, 4, rel_tol, prec, |y, z, jac, out| {
            let fz = f(z.clone());
            let kk = self.kernels(&z.clone().recip());
            let zi = z.clone().recip();
            for j in 0..2 {
                let g = (kk[j][0].clone() * &fz[0] + kk[j][1].clone() * &fz[1]) * &zi;
                out[j] = g.im.clone() * y * jac;
                out[2 + j] = g.re * jac;
            }
        });
        let mut it = v.into_iter();
        let mut next = || it.next().unwrap_or_else(|| x0.zero());
        ([next(), next(), next(), next()], err)
    }
}

/// Smallest step of the nested tanh-sinh rule of the contour integrals at `bits` of precision:
/// 2^-8 at 53 bits, halved once more for every doubling of the precision (the rule converges
/// quadratically once resolved, so the number of correct digits doubles per level).
pub fn contour_h_min(bits: u32) -> f64 {
    let extra = (f64::from(bits.max(53)) / 53.0).log2().ceil() as i32;
    0.5_f64.powi(8 + extra)
}

/// The integral over y in (0, inf) along z = x0 + i y of `g(y, z, jac, out)` (which writes
/// `dim` real components, already multiplied by the Jacobian `jac`), divided by pi; the
/// y-variable is mapped by y = Y u/(1 - u), Y = max(|x0|, 0.05), and the u-integral done by
/// nested tanh-sinh to `rel_tol`.
pub(crate) fn y_integral<T, G>(
    x0: &T,
    dim: usize,
    rel_tol: f64,
    prec: u32,
    mut g: G,
) -> (Vec<T>, f64)
where
    T: Real,
    G: FnMut(&T, Cx<T>, &T, &mut [T]),
{
    let scale = x0.clone().abs().max(x0.lit(0.05));
    let zero = x0.zero();
    let one = x0.one();
    let pi = x0.pi();
    let (mut vals, err) = crate::quad::integrate_vec(
        &zero,
        &one,
        dim,
        rel_tol,
        contour_h_min(prec),
        crate::quad::t_max(prec),
        |nd, out| {
            // y = Y u/(1 - u), dy = Y du/(1 - u)^2
            let one_minus = &nd.to_b;
            let y = scale.clone() * &nd.from_a / one_minus;
            let jac = scale.clone() / one_minus.clone().sqr();
            if !y.is_finite() || !jac.is_finite() || y == 0.0 {
                return;
            }
            let z = Cx::new(x0.clone(), y.clone());
            g(&y, z, &jac, out);
        },
    );
    vals.iter_mut().for_each(|v| *v /= &pi);
    let err = err / pi.to_f64();
    (vals, err)
}

/// F(z) = Int S(w)/(w - z)^2 dw for a point traction S(w) = delta(w) (that is, a line load
/// P t delta(x) growing linearly in time): F = 1/z^2.
pub fn point_load<T: Real>(z: Cx<T>) -> Cx<T> {
    (z.clone() * &z).recip()
}

/// F(z) for a uniform traction S(w) = 1 on |w| < p: F = [-1/(w - z)]_{-p}^{p} = -2p/(p^2 - z^2).
pub fn uniform_load<T: Real>(p: T, z: Cx<T>) -> Cx<T> {
    let d = (-(z.clone() * &z)).add_re(&p.clone().sqr());
    Cx::real(p * -2.0) / &d
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
