//! Complex-function layer of the dynamic wedge-indentation engine.
//!
//! Everything here is independent of the wedge problem: the precision layer ([`scalar`],
//! [`double_double`], [`cx`]), the radicals p_k with the cuts of the reference paper ([`branch`]), the Rayleigh
//! family K, L, R and the Rayleigh root ([`rayleigh`]), Plemelj boundary values and the
//! operator D ([`plemelj`]), Cauchy integrals and principal values ([`cauchy`]), the
//! quadrature rules they rest on ([`quadrature`]), small dense and band linear algebra
//! ([`linalg`]) and the scalar root finders of the inverse
//! solves ([`roots`]).
//!
//! Reference: "Dynamic indentation of an elastic half-plane by a rigid wedge: frictional and
//! tangential-displacement effects", eqs (12)-(21). Every function is generic over
//! [`scalar::Real`], implemented for `f64`, the double-double [`Dd`] and `rug::Float`.
#![warn(missing_docs)]
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod branch;
pub mod cauchy;
pub mod cx;
pub mod double_double;
pub mod error;
pub mod estimate;
pub mod linalg;
pub mod plemelj;
pub mod quadrature;
pub mod rayleigh;
pub mod roots;
pub mod scalar;

pub use branch::{p_boundary, p_k, Side};
pub use cx::Cx;
pub use double_double::Dd;
pub use error::{Error, InvalidParameter, NoConvergence, Result};
pub use estimate::{ErrorKind, Estimate};
pub use rayleigh::{Rayleigh, RayleighValues};
pub use scalar::{Precision, Real};
