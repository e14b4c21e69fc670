//! Brock's homogeneous-function technique for self-similar elastodynamic fields in a
//! half-plane (reference paper, eqs (9)-(21)).
//!
//! # Units and conventions
//! The core API works in units c1 = 1 (P-wave speed), mu = 1 (shear modulus) and, where a
//! time does not appear explicitly, t = 1: lengths are in units of c1 t, stresses in units of
//! mu, displacements of degree n in units of c1^n t^n (times whatever scale F and G carry),
//! particle velocities in units of c1^(n-1) t^(n-1). The half-plane is y <= 0 with y pointing out
//! of the body; polar angle theta = atan2(y, x) in [-pi, 0], theta = 0 is the face x > 0 and
//! theta = -pi the face x < 0. Polar components follow eq (9):
//! u = u_r + i u_theta, s_r = sigma_r - sigma_theta + 2 i sigma_rtheta,
//! s_theta = sigma_theta - i sigma_rtheta.
//!
//! # Modules
//! * [`zeta_map`]: the maps zeta_k of eq (14a,b), the radicals p_k(v) "in the quadrant of
//!   zeta_k" (eq (12)), h_k and the wave regions (with the corrected h_k).
//! * [`j_operator`]: the operators J_k of eq (13) applied to the kernels of (10), (11).
//! * [`field`]: the interior field (10)-(12) with (16), polar and Cartesian.
//! * [`surface`]: the surface forms (18)-(20) by contour deformation.
//!
//! # Corrections to the OCR text of the paper (each re-derived; the tests decide)
//! 1. **h_k** (below eq (6)): printed `h_k = m_k |cos theta| + (1 - m_k^2)^(1/2) sin theta`. With
//!    sin theta <= 0 in the body this is discontinuous at the edge of the head-wave wedge
//!    (it gives 2 m^2 - 1 instead of 1 at theta = -arccos m). The head-wave front is the line
//!    through (c1 t, 0) tangent to the circle r = c2 t, r cos(theta + arccos m_k) = c_k t, so
//!    `h_k = m_k |cos theta| + (1 - m_k^2)^(1/2) |sin theta|` (continuous, = 1 at the wedge
//!    edge, = m_k on the surface). See [`zeta_map::h_k`].
//! 2. **Eq (11a)**: the sign of the last term. From sigma_r + sigma_theta = 2 (lambda + mu) Delta
//!    and Delta = -(1/2) J_1[v^2 Re(p_1 W_1)] (which follows from (10) and is checked against
//!    finite differences in the tests), the correct form is
//!    `(c1^2/mu) s_r = -(2 c1^2/mu) s_theta - (1 - m^2) J_1[2U(W_1) - V(W_1)]`.
//! 3. **Eq (13)**: the lower limit `r/c1` is read r/(c1 t) (v is dimensionless, (vt - r/c1) is a
//!    time); likewise the lower limits of (18), (19) are r/(c1 t).
//! 4. **Eq (12a)**: `W_k = Omega_k(zeta_k) + conj(omega_k(conj zeta_k))` with omega_k given by the
//!    *same formula* (16) evaluated in the lower half-plane; p_k(v) in U, V is the boundary value
//!    on the side and quadrant of zeta_k, which in the body (Im zeta_k > 0) is
//!    p_k(v) = -|p_k(v)| for v < m_k (`docs/errata.md`, section 1) and, in a head-wave wedge (v > m_k, zeta_k
//!    real), p_k(v) = -i sgn(cos theta) (v^2/m_k^2 - 1)^(-1/2).
//! 5. **Eq (14b)**: printed with `zeta-bar`; it is zeta_k itself, a real number:
//!    zeta_k = m_k sec[arcsec(v/m_k) + |theta|] (|theta| <= pi/2) and m_k sec[arcsec(v/m_k) - |theta|]
//!    (|theta| > pi/2), the continuation of (14a) through v = m_k on the branch that keeps the
//!    field continuous.
//! 6. In (18) the factors p_k and v^2 sit inside D(.), i.e. they are evaluated at zeta = +-v +- i0
//!    together with F, G (v^2 = zeta^2 there); this is how [`surface`] continues them off the axis.
//!
//! Equations (10), (11b), (16), (18), (19), (21) were re-derived and found correct as printed
//! (with the above readings): the surface forms (18), (19) follow from (10), (11b) at theta = 0
//! by the identities given in [`surface`]. The normalisation is confirmed by the closed-form
//! case (s_theta = -(Q mu/(c1 alpha)) arccosh(alpha t/r) for F = -i Q zeta^2 (zeta^2 - p^2)^(-1/2)).
#![warn(missing_docs)]
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod error;
pub mod field;
pub mod j_operator;
pub mod surface;
pub mod zeta_map;

use complexfn::{Cx, Rayleigh, Real};

pub use error::{Error, Result};
pub use field::{CartesianValues, FieldValues};
pub use zeta_map::Region;

/// The pair of sectionally analytic functions F, G of eq (16) that define a self-similar
/// field of degree n, with the surface traction-free outside the loaded segment.
///
/// F and G are evaluated only off the real axis (`Im zeta != 0`); boundary values on the real
/// axis are obtained as limits along deformed contours. G may be non-analytic across the
/// imaginary axis (the paper's friction construction (23)); no path crosses it.
pub trait Potentials<T: Real>: Sync {
    /// Degree n >= 1 of the homogeneous displacement (n = 1 for the wedge).
    fn degree(&self) -> u32;
    /// The material's Rayleigh family (speed ratio m = c2/c1, functions K, L, R, p_k).
    fn rayleigh(&self) -> &Rayleigh<T>;
    /// F(zeta), Im zeta != 0.
    fn f(&self, zeta: &Cx<T>) -> Cx<T>;
    /// G(zeta), Im zeta != 0.
    fn g(&self, zeta: &Cx<T>) -> Cx<T>;

    /// Positive real points (other than m_R, m, 1, which are always used) where F or G is
    /// singular, typically the end p of the loaded segment. Used only as quadrature breakpoints,
    /// so the integrals stay accurate close to the surface. Default: none.
    fn breakpoints(&self) -> Vec<T> {
        Vec::new()
    }

    /// (F(xi), G(xi)) at a real point with m <= |xi| <= 1, where F and G are analytic (the
    /// loaded segment lies inside (-m_R, m_R)). Needed only in the head-wave wedges, where
    /// zeta_2 is real (eq (14b)).
    ///
    /// The default uses the mean-value property on a circle of radius (|xi| - m_R)/4 around xi
    /// with nodes off the real axis (trapezoidal rule, error about 4^-N); implementors with a
    /// closed form may override it.
    fn fg_real(&self, xi: &T) -> (Cx<T>, Cx<T>) {
        circle_mean(xi, self.rayleigh().m_r(), |z| (self.f(z), self.g(z)))
    }
}

/// Value at a real point `xi` of an analytic pair, by the mean over a circle of radius
/// (|xi| - m_R)/4 (trapezoidal rule on nodes off the real axis).
pub fn circle_mean<T: Real, H: Fn(&Cx<T>) -> (Cx<T>, Cx<T>)>(
    xi: &T,
    m_r: &T,
    h: H,
) -> (Cx<T>, Cx<T>) {
    let rho = (xi.clone().abs() - m_r) / 4.0;
    let nodes = (xi.prec() / 2 + 8) as usize;
    let zero = Cx::real(xi.zero());
    let (mut sf, mut sg) = (zero.clone(), zero);
    let two_pi = xi.pi() * 2.0;
    for j in 0..nodes {
        let phi = two_pi.clone() * xi.lit((j as f64 + 0.5) / nodes as f64);
        let (s, c) = phi.sin_cos();
        let z = Cx::new(xi.clone() + rho.clone() * c, rho.clone() * s);
        let (a, b) = h(&z);
        sf += a;
        sg += b;
    }
    let inv = xi.lit(nodes as f64).recip();
    (sf.scale(&inv), sg.scale(&inv))
}

/// The functions Omega_1, Omega_2 of eq (16a, b) at a point off the real axis (or at a real
/// point with the boundary values of p_k, K, L, R supplied in `rv`):
/// R Omega_1 = -K p_2 F - 2i G, R Omega_2 = K p_1 G - 2i F.
pub fn omegas<T: Real>(rv: &complexfn::RayleighValues<T>, f: &Cx<T>, g: &Cx<T>) -> (Cx<T>, Cx<T>) {
    let kp2f = rv.k.clone() * &rv.p2 * f;
    let o1 = (-kp2f - g.clone().mul_i() * 2.0) / &rv.r;
    let kp1g = rv.k.clone() * &rv.p1 * g;
    let o2 = (kp1g - f.clone().mul_i() * 2.0) / &rv.r;
    (o1, o2)
}
