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

use nalgebra::Complex;

/// Complex f64.
pub type C64 = Complex<f64>;

/// The half-plane's surface response for speed ratio m = c2/c1 (c1 = 1, mu = 1).
#[derive(Clone, Copy, Debug)]
pub struct Lamb {
    m: f64,
    /// 1/c2^2
    b: f64,
}

/// The four kernels at one slowness: `[[K_yy, K_yx], [K_xy, K_xx]]`.
pub type Kernels = [[C64; 2]; 2];

impl Lamb {
    /// The response for m = c2/c1 in (0, sqrt(3)/2).
    pub fn new(m: f64) -> Self {
        Lamb {
            m,
            b: 1.0 / (m * m),
        }
    }

    /// m = c2/c1.
    pub fn m(&self) -> f64 {
        self.m
    }

    /// The kernels K_jk(xi) at a complex slowness xi off the cuts |Re xi| > 1/c_k of the real
    /// axis (units c1 = 1).
    pub fn kernels(&self, xi: C64) -> Kernels {
        let one = C64::new(1.0, 0.0);
        let b = self.b;
        let s = xi * xi;
        let a1 = (one - s).sqrt();
        let a2 = (C64::new(b, 0.0) - s).sqrt();
        let k = C64::new(b, 0.0) - s * 2.0;
        let q = s * a1 * a2 * 4.0;
        let (r_plus, r_minus) = (k * k + q, k * k - q);
        // R (k^2 - 4 s a1 a2) = b^4 - 8 b^3 s + (24 b^2 - 16 b) s^2 + 16 (1 - b) s^3
        let cubic = ((s * (16.0 * (1.0 - b)) + (24.0 * b * b - 16.0 * b)) * s - 8.0 * b * b * b)
            * s
            + b * b * b * b;
        let r = if r_plus.norm() >= r_minus.norm() {
            r_plus
        } else {
            cubic / r_minus
        };
        let aa = a1 * a2 * 2.0;
        let (n_minus, n_plus) = (k - aa, k + aa);
        // (k - 2 a1 a2)(k + 2 a1 a2) = b^2 - 4 b + 4 s
        let lin = s * 4.0 + (b * b - 4.0 * b);
        let nyx = if n_minus.norm() >= n_plus.norm() {
            n_minus
        } else {
            lin / n_plus
        };
        let kyy = a1 * b / r;
        let kxx = a2 * b / r;
        let kyx = xi * nyx / r;
        [[kyy, kyx], [-kyx, kxx]]
    }

    /// The displacements (U_y, U_x)(x0) and their slopes (U_y', U_x')(x0) produced by degree-0
    /// tractions whose F-functions are given by `f(z) = [F_y(z), F_x(z)]`, from the contour
    /// representation along z = x0 + i y (module docs). `rel_tol` is the tolerance of the
    /// tanh-sinh rule in y (mapped by y = Y u/(1 - u), Y = max(|x0|, 0.05)). Returns the values and
    /// the estimated absolute error.
    pub fn displacement<F>(&self, x0: f64, rel_tol: f64, mut f: F) -> ([f64; 4], f64)
    where
        F: FnMut(C64) -> [C64; 2],
    {
        let scale = x0.abs().max(0.05);
        let (v, err) = crate::quad::integrate_vec(0.0, 1.0, 4, rel_tol, 1.0 / 512.0, |nd, out| {
            // y = Y u/(1 - u), dy = Y du/(1 - u)^2
            let u = nd.v;
            let one_minus = nd.to_b;
            let y = scale * nd.from_a / one_minus;
            let jac = scale / (one_minus * one_minus);
            if !y.is_finite() || !jac.is_finite() {
                return;
            }
            let _ = u;
            let z = C64::new(x0, y);
            let fz = f(z);
            let kk = self.kernels(z.inv());
            for j in 0..2 {
                let g = (kk[j][0] * fz[0] + kk[j][1] * fz[1]) / z;
                out[j] = (g * y).im * jac / std::f64::consts::PI;
                out[2 + j] = g.re * jac / std::f64::consts::PI;
            }
        });
        ([v[0], v[1], v[2], v[3]], err)
    }
}

/// F(z) = Int S(w)/(w - z)^2 dw for a point traction S(w) = delta(w) (that is, a line load
/// P t delta(x) growing linearly in time): F = 1/z^2.
pub fn point_load(z: C64) -> C64 {
    (z * z).inv()
}

/// F(z) for a uniform traction S(w) = 1 on |w| < p: F = [-1/(w - z)]_{-p}^{p} = -2p/(p^2 - z^2).
pub fn uniform_load(p: f64, z: C64) -> C64 {
    C64::new(-2.0 * p, 0.0) / (C64::new(p * p, 0.0) - z * z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cancellation_free_forms_agree_with_the_direct_ones() {
        let l = Lamb::new(0.5345);
        for xi in [
            C64::new(0.3, -0.2),
            C64::new(1.5, -0.4),
            C64::new(-0.2, -2.0),
        ] {
            let kk = l.kernels(xi);
            let s = xi * xi;
            let a1 = (C64::new(1.0, 0.0) - s).sqrt();
            let a2 = (C64::new(l.b, 0.0) - s).sqrt();
            let k = C64::new(l.b, 0.0) - s * 2.0;
            let r = k * k + s * a1 * a2 * 4.0;
            let kyx = xi * (k - a1 * a2 * 2.0) / r;
            assert!((kk[0][1] - kyx).norm() < 1e-12 * kyx.norm());
            assert!((kk[0][0] - a1 * l.b / r).norm() < 1e-12 * kk[0][0].norm());
        }
    }
}
