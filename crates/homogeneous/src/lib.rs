//! Brock's homogeneous-function technique for self-similar elastodynamic fields in a
//! half-plane (reference paper, eqs (9)-(21)).
#![warn(missing_docs)]

use complexfn::{Cx, Rayleigh, Real};

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
}
