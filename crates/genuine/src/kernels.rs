//! The contour representation of the self-similar surface response (Lamb's kernels of
//! [`lamb::transform`]) used by the genuine wedge solver.
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
use complexfn::{Cx, Real};

pub use lamb::transform::{Kernels, Lamb, C64};

/// The contour representation of the displacement on the surface (module docs), for the
/// kernels of [`Lamb`].
pub trait ContourDisplacement<T: Real> {
    /// The displacements (U_y, U_x)(x0) and their slopes (U_y', U_x')(x0) produced by degree-0
    /// tractions whose F-functions are given by `f(z) = [F_y(z), F_x(z)]`, from the contour
    /// representation along z = x0 + i y (module docs). `rel_tol` is the tolerance of the
    /// nested tanh-sinh rule in y (mapped by y = Y u/(1 - u), Y = max(|x0|, 0.05); step down
    /// to 2^-8 at 53 bits, one more halving per doubling of the precision). Returns the values
    /// and the estimated absolute error.
    fn displacement<F>(&self, x0: T, rel_tol: f64, f: F) -> ([T; 4], f64)
    where
        F: FnMut(Cx<T>) -> [Cx<T>; 2];
}

impl<T: Real> ContourDisplacement<T> for Lamb<T> {
    fn displacement<F>(&self, x0: T, rel_tol: f64, mut f: F) -> ([T; 4], f64)
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
pub(crate) fn y_integral<T, G>(x0: &T, dim: usize, rel_tol: f64, prec: u32, g: G) -> (Vec<T>, f64)
where
    T: Real,
    G: FnMut(&T, Cx<T>, &T, &mut [T]),
{
    y_integral_checked(x0, dim, dim, rel_tol, prec, g)
}

/// [`y_integral`] whose convergence test looks at the first `checked` components only
/// ([`crate::quad::integrate_vec_checked`]).
pub(crate) fn y_integral_checked<T, G>(
    x0: &T,
    dim: usize,
    checked: usize,
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
    let (mut vals, err) = crate::quad::integrate_vec_checked(
        &zero,
        &one,
        dim,
        checked,
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
