//! The genuine frictional wedge-indentation solution (no apex dislocation).
//!
//! * [`kernels`]: Lamb's self-similar surface response and its contour representation;
//! * [`apex`]: the Mellin eigen-equation at the apex and its exponents;
//! * [`basis`]: the spectral basis carrying the edge and apex exponents;
//! * [`quad`]: the quadrature rules (fixed-step, exact endpoint offsets, any precision);
//! * [`solver`]: the singular integral equation, its collocation solve and the solved case
//!   [`GenuineCase`];
//! * [`solution`]: [`GenuineCase`] behind the one interface of solved cases,
//!   [`wedge::ContactSolution`].
#![warn(missing_docs)]

pub mod apex;
pub mod basis;
pub mod error;
pub mod kernels;
pub mod quad;
pub mod solution;
pub mod solver;

pub use apex::ApexExponents;
pub use error::{GenuineError, Result};
pub use kernels::{ContourDisplacement, Lamb};
pub use solution::GenuineSolver;
pub use solver::{
    load_through_kernels, roundoff_floor, GenuineCase, SolveOptions, NEAR_RAYLEIGH,
    NEAR_RAYLEIGH_STEP,
};
