//! Typed errors of the Lamb crate.

use thiserror::Error;

/// Errors of the half-plane response. Each names the offending parameter, its value and the
/// admissible range, so that callers (and the command line) can print one clear line.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum LambError {
    /// A parameter outside its admissible range, or not finite (the shape shared by every
    /// crate, [`complexfn::InvalidParameter`]).
    #[error(transparent)]
    InvalidParameter(#[from] complexfn::InvalidParameter),
    /// A pointwise value (or a cell end) exactly at the Rayleigh arrival s = s_R, where the
    /// direct terms have a pole and the cross terms a delta.
    #[error("{quantity} is singular at s = s_R = {s_r} (the Rayleigh arrival): give s != s_R, or a cell that contains s_R in its interior")]
    AtRayleighArrival {
        /// The quantity asked for.
        quantity: &'static str,
        /// s_R, printed.
        s_r: String,
    },
    /// A value that came out non-finite (overflow, or a point within rounding of a
    /// singularity); never returned as a number.
    #[error("{quantity} could not be computed at s = {s}: the result is not finite (a point within rounding of a singularity, or an overflow)")]
    NotFinite {
        /// The quantity asked for.
        quantity: &'static str,
        /// The point, printed.
        s: String,
    },
    /// An error of the complex-function layer.
    #[error(transparent)]
    Complex(#[from] complexfn::Error),
}

/// Result alias of the Lamb crate.
pub type Result<T> = std::result::Result<T, LambError>;

pub(crate) fn invalid(
    name: &'static str,
    value: impl std::fmt::Display,
    range: impl Into<String>,
) -> LambError {
    complexfn::InvalidParameter::new(name, value, range).into()
}

/// A value with about seven significant digits, for messages (plain notation between 1e-4
/// and 1e6, scientific outside).
pub fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if (1e-4..1e6).contains(&a) {
        let digits = (6 - a.log10().floor() as i32).clamp(0, 12) as usize;
        let t = format!("{x:.digits$}");
        let t = if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        };
        t
    } else {
        format!("{x:.6e}")
    }
}
