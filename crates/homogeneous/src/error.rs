//! Typed errors of the homogeneous-function crate.

use thiserror::Error;

/// Errors of this crate. Each names the offending parameter, its value and the admissible range.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum Error {
    /// A parameter outside its admissible range, or not finite (the shape shared by every
    /// crate, [`complexfn::InvalidParameter`]).
    #[error(transparent)]
    InvalidParameter(#[from] complexfn::InvalidParameter),
    /// An error of the complex-function layer (typically a quadrature that did not converge).
    #[error(transparent)]
    Complexfn(#[from] complexfn::Error),
}

/// Result alias of this crate.
pub type Result<T> = std::result::Result<T, Error>;

pub(crate) fn invalid<T>(name: &'static str, value: f64, range: &'static str) -> Result<T> {
    Err(complexfn::InvalidParameter::new(name, format!("{value}"), range).into())
}
