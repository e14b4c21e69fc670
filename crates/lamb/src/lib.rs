//! Lamb's problem for the elastic half-plane in plane strain: the surface response to a line
//! force, in the time domain and in the transform domain, at any precision.
//!
//! * [`half_plane`]: the material, the Rayleigh cubic and its roots, the impulse responses
//!   g_zz, g_xz, g_xx in closed form in every wave region, the Rayleigh constants;
//! * [`half_space`]: the elastic half-space's axisymmetric response (three dimensions): the
//!   step response of a normal point force in closed form and its means over rings;
//! * [`moments`]: the step responses W and the moments Int g s^-n ds in closed form (the
//!   cells of a time-marching solver), principal values and the Rayleigh delta included;
//! * [`cells`]: the displacement due to a load uniform on a strip and piecewise constant or
//!   linear in time, as corner differences of homogeneous primitives;
//! * [`rational`]: closed-form integrals of even rational functions (partial fractions,
//!   principal values, Taylor series near the wavefronts);
//! * [`edge`]: the power law of the contact pressure at a moving contact edge, by edge speed;
//! * [`transform`]: the transform-domain kernels (self-similar surface response), shared with
//!   the genuine wedge solver.
//!
//! Conventions (the second reference paper's surface influence functions, eq (7)): z points
//! into the medium, a normal force F_z > 0 pushes into it, s = |x|/(c1 t); an impulse
//! I delta(t) per unit length gives u = I/(pi mu t) g(s), a step P H(t) gives
//! u = P/(pi mu) W(s); the cross terms are odd in x and given for x > 0. Everything is zero
//! for s >= 1 (causality). Derivations: `docs/lamb.md`.
#![warn(missing_docs)]
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod cells;
pub mod edge;
pub mod error;
pub mod half_plane;
pub mod half_space;
pub mod moments;
pub mod rational;
pub mod transform;

pub use error::{LambError, Result};
pub use half_plane::{poisson_of, Estimate, HalfPlane, RayleighConstants, Region, Triple};
pub use half_space::{Annulus, HalfSpace};
pub use transform::Lamb;
