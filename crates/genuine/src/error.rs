//! Typed errors of the genuine solver.

use thiserror::Error;

/// Errors of the genuine solution; parameter errors name the parameter, its value and range.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum GenuineError {
    /// A parameter outside its admissible range, or not finite (the shape shared by every
    /// crate, [`complexfn::InvalidParameter`]).
    #[error(transparent)]
    InvalidParameter(#[from] complexfn::InvalidParameter),
    /// A step of the solve that gave no usable result (too few distinct collocation points, a
    /// degenerate slope condition, a non-finite value, an apex exponent of the wrong sign):
    /// not a tolerance missed, so it carries a description rather than the reached and asked
    /// errors of [`complexfn::NoConvergence`]. The message keeps the command line's wording,
    /// "{what} did not converge: {detail}".
    #[error("{what} did not converge: {detail}")]
    SolveFailed {
        /// What was being computed.
        what: &'static str,
        /// Details.
        detail: String,
    },
    /// An error of the wedge crate (material, Omega).
    #[error(transparent)]
    Wedge(#[from] wedge::WedgeError),
    /// An error of the complex-function layer.
    #[error(transparent)]
    Complex(#[from] complexfn::Error),
}

/// Result alias of the genuine crate.
pub type Result<T> = std::result::Result<T, GenuineError>;

pub(crate) fn invalid(
    name: &'static str,
    value: impl std::fmt::Display,
    range: impl Into<String>,
) -> GenuineError {
    complexfn::InvalidParameter::new(name, value, range).into()
}

/// The genuine solver's errors as the wedge crate's (for [`wedge::ContactSolution`]): a
/// wedge error passes unchanged, the solver's own become [`wedge::WedgeError::Solver`].
impl From<GenuineError> for wedge::WedgeError {
    fn from(e: GenuineError) -> Self {
        match e {
            GenuineError::Wedge(w) => w,
            other => wedge::WedgeError::Solver(other.to_string()),
        }
    }
}
