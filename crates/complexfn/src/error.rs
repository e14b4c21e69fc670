//! Typed errors of the complex-function layer.

use thiserror::Error;

/// A parameter outside its admissible range (or not finite): the one shape of this error in
/// every crate of the workspace, each crate's error enum carrying it as its
/// `InvalidParameter` variant. Its message names the parameter, its value and the admissible
/// range on one line: "invalid {name} = {value}: admissible range is {range}".
#[derive(Debug, Clone, Error, PartialEq)]
#[error("invalid {name} = {value}: admissible range is {range}")]
pub struct InvalidParameter {
    /// Parameter name as the documentation and the command line spell it.
    pub name: &'static str,
    /// The offending value, printed.
    pub value: String,
    /// The admissible range, in words or interval notation.
    pub range: String,
}

impl InvalidParameter {
    /// The error for parameter `name` with the value `value` outside `range`.
    pub fn new(
        name: &'static str,
        value: impl std::fmt::Display,
        range: impl Into<String>,
    ) -> Self {
        InvalidParameter {
            name,
            value: value.to_string(),
            range: range.into(),
        }
    }
}

/// A quadrature, root solve or convergence check that did not reach its tolerance: the one
/// shape of this error in every crate of the workspace, each crate's error enum carrying it as
/// its `NoConvergence` variant. Its message is
/// "{what} did not converge: reached {reached:e}, asked {asked:e}" (the wedge crate words its
/// variant's message in terms of relative errors, on the same fields).
#[derive(Debug, Clone, Error, PartialEq)]
#[error("{what} did not converge: reached {reached:e}, asked {asked:e}")]
pub struct NoConvergence {
    /// What was being computed.
    pub what: String,
    /// The (relative) error estimate reached.
    pub reached: f64,
    /// The (relative) tolerance asked for.
    pub asked: f64,
}

/// Errors of the complex-function crate. Each names the offending parameter, its value and the
/// admissible range, so that callers (and the command line) can print one clear line.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum Error {
    /// A parameter outside its admissible range (or not finite).
    #[error(transparent)]
    InvalidParameter(#[from] InvalidParameter),
    /// A decimal string could not be parsed as a number.
    #[error("cannot parse {0:?} as a number")]
    Parse(String),
    /// A quadrature or root solve did not reach the requested tolerance.
    #[error(transparent)]
    NoConvergence(#[from] NoConvergence),
    /// A quadrature or series produced a non-finite value or error (an overflow, or an
    /// integrand not integrable at the precision used): never accepted as a result.
    #[error("{what} is not finite (an overflow or a singularity the rule cannot integrate)")]
    NonFinite {
        /// What was being computed.
        what: &'static str,
    },
}

/// Result alias of this crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Check that `x` is finite and inside the open interval (lo, hi); `name` and `range` go into
/// the error message.
pub fn check_open(
    name: &'static str,
    x: f64,
    lo: f64,
    hi: f64,
    range: &'static str,
) -> Result<f64> {
    if x.is_finite() && x > lo && x < hi {
        Ok(x)
    } else {
        Err(InvalidParameter::new(name, format!("{x}"), range).into())
    }
}
