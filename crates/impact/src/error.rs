//! Typed errors of the impact engine: each names the offending input, its value and the
//! admissible range, so that the command line prints one clear line.

use thiserror::Error;

/// Errors of the impact engine.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum ImpactError {
    /// A parameter outside its admissible range, or not finite (the shape shared by every
    /// crate, [`complexfn::InvalidParameter`]).
    #[error(transparent)]
    InvalidParameter(#[from] complexfn::InvalidParameter),
    /// The grid cannot represent the run (too few cells across the contact, too many steps).
    #[error("the grid cannot resolve this run: {reason} (input {name})")]
    Grid {
        /// The input to change.
        name: &'static str,
        /// Why.
        reason: String,
    },
    /// The contact set or the linear system of a time step could not be determined.
    #[error("time step at c1 t/R = {time}: {reason}")]
    Step {
        /// The time (dimensionless) of the failing step.
        time: String,
        /// Why.
        reason: String,
    },
    /// The caller stopped the march ([`crate::ImpactCase::solve_reporting`]'s report
    /// answered [`std::ops::ControlFlow::Break`]): no result, by request.
    #[error("stopped at c1 t/R = {time} on request")]
    Stopped {
        /// The time c1 t/R the march had reached.
        time: f64,
    },
    /// An error of the half-plane's response (Lamb crate).
    #[error(transparent)]
    Lamb(#[from] lamb::LambError),
}

/// Result alias of the impact engine.
pub type Result<T> = std::result::Result<T, ImpactError>;

pub(crate) fn invalid(
    name: &'static str,
    value: impl std::fmt::Display,
    range: impl Into<String>,
) -> ImpactError {
    complexfn::InvalidParameter::new(name, value, range).into()
}
