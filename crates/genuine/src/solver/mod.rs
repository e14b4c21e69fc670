//! The genuine contact problem and its spectral collocation solve.
//!
//! Units c1 = mu = 1; S = sigma_yy/(mu cot Theta) on the contact |x| < p (even, S(p) = 0),
//! shear sigma_xy = -sgn(x) gamma sigma_yy (eq (4b)), displacements over c1 t cot Theta, and the
//! contact condition (7) on 0 < x < p: U_y + beta U_x = -V_hat + x.
//!
//! With h = dS/dx (odd), integration by parts gives the F-functions of [`crate::kernels`]:
//!
//! ```text
//!   F_y(z) = Int_0^p h(v) 2v/(v^2 - z^2) dv,   F_x(z) = -gamma Int_0^p h(v) 2v^2/(z (v^2 - z^2)) dv.
//! ```
//!
//! The condition is imposed in two parts.
//! 1. Its second derivative, U_y'' + beta U_x'' = 0 on (0, p), is local: U'' = Im Phi''(x + i0)/pi
//!    with Phi'' = -K(1/z) F(z)/z. On the contact xi = 1/x > 1/c_R, a_k = i alpha_k, K_yy and
//!    K_xx are imaginary and K_yx real, F^+ = PV + i pi h, and the condition becomes the
//!    singular integral equation
//!    ```text
//!      H_y/|p1| - gamma beta H_x/|p2| - pi (beta + gamma) c(x) h(x) = 0,
//!      H_y = PV Int_0^p h 2v/(v^2 - x^2) dv,  H_x = PV Int_0^p h 2v^2/(x (v^2 - x^2)) dv,
//!      c(x) = m^2 (L/x^2)/(|p1| |p2|)   (L = 2 - K |p1| |p2| of the paper).
//!    ```
//!    Its characteristic ratio is the paper's tan(pi Omega) (eq (31)), so the local edge
//!    exponent is Omega(x); at the apex it gives the eigen-equation of [`crate::apex`].
//!    It is collocated at Chebyshev points of (0, p), the principal value taken as
//!    Int (f(v) - f(x))/(v - x) dv + f(x) ln((p - x)/x) with tanh-sinh on (0, x) and (x, p).
//! 2. The slope at x* = p/2, U_y'(x*) + beta U_x'(x*) = 1, fixes the scale, and
//!    V_hat = x* - U_y(x*) - beta U_x(x*), both from the contour representation.
//!
//!
//! Discretisation. The basis functions are sampled once on one tanh-sinh rule of (0, p) (step
//! `h_quad`), and every collocation row is a weighted sum over those samples; the collocation
//! points are Chebyshev points moved onto the quarter points of the rule's t-grid, so that no
//! node is closer to a collocation point than a quarter step and the difference quotient
//! (f(v) - f(x))/(v - x) keeps its accuracy. The rows and a normalisation row (the force
//! moment Int_0^p x h dx = 1, heavily weighted) are solved in the least-squares sense by
//! Householder QR with column pivoting ([`complexfn::linalg`]); the contour functionals of step 2 are
//! then evaluated for the solution only (one column, not one per basis function), and the
//! solution is rescaled so that the slope condition holds. The error estimate is
//! |V_hat(N) - V_hat(N/2)| plus a precision-dependent floor ([`roundoff_floor`]).
//!
//! Precision. Everything is generic over `T: Real` (f64, or `rug::Float` at the precision of
//! the contact speed p passed in). The truncations of every rule follow the working precision
//! and the case's endpoint exponents ([`crate::quad`]); the steps and the basis degree are
//! options, with [`SolveOptions::for_precision`] giving the defaults for a precision.

mod case;
mod checks;
mod collocation;
mod options;

pub use case::GenuineCase;
pub use case::CONTOUR_MARGIN;
pub use checks::load_through_kernels;
pub use options::*;
