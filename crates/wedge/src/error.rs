//! Typed errors of the wedge crate.

use thiserror::Error;

/// Errors of the wedge solution. Parameter errors name the parameter, the offending value and
/// the admissible range, so that the command line can print them as one line.
#[derive(Debug, Clone, Error, PartialEq)]
pub enum WedgeError {
    /// A parameter outside its admissible range, or not finite (the shape shared by every
    /// crate, [`complexfn::InvalidParameter`]).
    #[error(transparent)]
    InvalidParameter(#[from] complexfn::InvalidParameter),
    /// A quadrature, root solve or convergence check failed to reach its tolerance (the
    /// shape shared by every crate, [`complexfn::NoConvergence`], its `reached` and `asked`
    /// relative errors, which this crate's message names so).
    #[error(
        "{} did not converge: relative error {:e} (asked {:e})",
        .0.what,
        .0.reached,
        .0.asked
    )]
    NoConvergence(complexfn::NoConvergence),
    /// A computed quantity is not finite at the working precision (an overflow, or a
    /// singularity its rule cannot integrate there): never reported as a value.
    #[error("{what} is not finite at this precision (an overflow or a singularity the rule cannot integrate)")]
    NotFinite {
        /// The quantity (its report key).
        what: String,
    },
    /// The requested solution variant or quantity is not available for this case.
    #[error("{0}")]
    Unsupported(String),
    /// An error reported by a companion solver (e.g. the genuine solution's), as its message.
    #[error("{0}")]
    Solver(String),
    /// An error of the complex-function layer.
    #[error(transparent)]
    Complex(#[from] complexfn::Error),
    /// The working arithmetic reaches less than the requested accuracy (a solve in
    /// double-double whose estimate exceeds what the request allows): the caller computes the
    /// case again with more bits.
    #[error("relative error {reached:e} at {bits} bits, above the {asked:e} the request allows")]
    ShortOfPrecision {
        /// The working precision in bits.
        bits: u32,
        /// The relative error reached.
        reached: f64,
        /// The relative error the request allows.
        asked: f64,
    },
    /// A result whose relative error estimate exceeds what a reported value may carry
    /// ([`crate::solved::MAX_REL_ERROR`]): its leading digits, even its sign, are not
    /// determined at the working precision. Never reported as a value.
    #[error("{what} is not determined at this precision: relative error estimate {reached:.1e}, above the {allowed:e} a reported value may carry")]
    Undetermined {
        /// The quantity (its report key).
        what: String,
        /// Its relative error estimate.
        reached: f64,
        /// The largest relative estimate a reported value may carry.
        allowed: f64,
    },
    /// A numerical failure of one case, with the inputs that led to it.
    #[error("{inputs}: {error}")]
    AtCase {
        /// The case's inputs, printed (material, indenter, speed, variant, precision).
        inputs: String,
        /// The failure.
        error: Box<WedgeError>,
    },
}

/// Result alias of the wedge crate.
pub type Result<T> = std::result::Result<T, WedgeError>;

pub(crate) fn invalid(
    name: &'static str,
    value: impl std::fmt::Display,
    range: impl Into<String>,
) -> WedgeError {
    complexfn::InvalidParameter::new(name, value, range).into()
}

pub(crate) fn from_quad(what: &str, e: complexfn::Error) -> WedgeError {
    match e {
        complexfn::Error::NoConvergence(e) => WedgeError::NoConvergence(complexfn::NoConvergence {
            what: what.to_string(),
            ..e
        }),
        other => WedgeError::Complex(other),
    }
}

/// `x` to 7 significant digits for a message (fixed notation between 1e-4 and 1e6, trailing
/// zeros dropped), scientific outside.
pub(crate) fn short(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || !(1e-4..1e6).contains(&a) {
        return format!("{x:.6e}");
    }
    let digits = (6 - a.log10().floor() as i32).clamp(0, 12) as usize;
    let t = format!("{x:.digits$}");
    if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    }
}
