//! The rigid-wedge indentation of an elastic half-plane (reference paper, eqs (22)-(57)).
//!
//! A symmetric rigid wedge of half-angle Theta is driven at constant speed V into an elastic
//! half-plane; the contact zone |x| < alpha t grows at a constant sub-Rayleigh speed alpha,
//! with Coulomb friction gamma (reversing at the apex) and the coupling beta = -cot Theta of
//! tangential and normal displacement in the contact condition (7).
//!
//! Build a [`Case`] from a [`Material`], an [`Indenter`] and the contact speed, at the
//! precision of the scalar type (`f64`, or `rug::Float` at any number of bits); ask it for the
//! quantities you need. Everything is dimensionless: speeds over c1, stresses over
//! mu cot Theta, Q over c1^2 cot Theta.
#![warn(missing_docs)]
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod admissibility;
pub mod case;
pub mod error;
pub mod fields;
pub mod inverse;
pub mod matching;
pub mod omega;
pub mod params;
pub mod regime;
pub mod solved;
pub mod stress;

pub use admissibility::Admissibility;
pub use case::Case;
pub use error::{Result, WedgeError};
pub use inverse::{case_for_speed, for_speed};
pub use params::{Coupling, Indenter, Material, Param, Solution};
pub use regime::{Apex, ApexRegime};
pub use solved::{ApexLeading, ContactSolution, PaperSolver, Solver, MAX_REL_ERROR, PAPER_ONLY};
pub use stress::WithError;
