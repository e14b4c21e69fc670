//! Typed errors of the homogeneous-function crate.

use thiserror::Error;

/// Errors of this crate. Each names the offending parameter, its value and the admissible range.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum Error {
    /// A parameter outside its admissible range (or not finite).
    #[error("invalid {name} = {value}: admissible range is {range}")]
    InvalidParameter {
        /// Parameter name as the documentation spells it.
        name: &'static str,
        /// The offending value, printed.
        value: String,
        /// The admissible range.
        range: &'static str,
    },
    /// An error of the complex-function layer (typically a quadrature that did not converge).
    #[error(transparent)]
    Complexfn(#[from] complexfn::Error),
}

/// Result alias of this crate.
pub type Result<T> = std::result::Result<T, Error>;

pub(crate) fn invalid<T>(name: &'static str, value: f64, range: &'static str) -> Result<T> {
    Err(Error::InvalidParameter {
        name,
        value: format!("{value}"),
        range,
    })
}
