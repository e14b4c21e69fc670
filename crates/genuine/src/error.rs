//! Typed errors of the genuine solver.

use thiserror::Error;

/// Errors of the genuine solution; parameter errors name the parameter, its value and range.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum GenuineError {
    /// A parameter outside its admissible range, or not finite.
    #[error("invalid {name} = {value}: admissible range is {range}")]
    InvalidParameter {
        /// Parameter name.
        name: &'static str,
        /// The offending value.
        value: String,
        /// The admissible range.
        range: String,
    },
    /// The linear solve or a root search failed.
    #[error("{what} did not converge: {detail}")]
    NoConvergence {
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
    GenuineError::InvalidParameter {
        name,
        value: value.to_string(),
        range: range.into(),
    }
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
