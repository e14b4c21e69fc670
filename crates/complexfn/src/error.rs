//! Typed errors of the complex-function layer.

use thiserror::Error;

/// Errors of the complex-function crate. Each names the offending parameter, its value and the
/// admissible range, so that callers (and the command line) can print one clear line.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum Error {
    /// A parameter outside its admissible range (or not finite).
    #[error("invalid {name} = {value}: admissible range is {range}")]
    InvalidParameter {
        /// Parameter name as the documentation spells it.
        name: &'static str,
        /// The offending value, printed.
        value: String,
        /// The admissible range, in words or interval notation.
        range: &'static str,
    },
    /// A decimal string could not be parsed as a number.
    #[error("cannot parse {0:?} as a number")]
    Parse(String),
    /// A quadrature or root solve did not reach the requested tolerance.
    #[error("{what} did not converge: reached {reached:e}, asked {asked:e}")]
    NoConvergence {
        /// What was being computed.
        what: &'static str,
        /// Relative error estimate reached.
        reached: f64,
        /// Relative tolerance asked for.
        asked: f64,
    },
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
        Err(Error::InvalidParameter {
            name,
            value: format!("{x}"),
            range,
        })
    }
}
