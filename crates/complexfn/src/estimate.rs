//! A value with its estimated absolute error, the one such type of the workspace, and what
//! the estimate means ([`ErrorKind`]).

/// What an [`Estimate`]'s error estimates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// A quadrature's error, from its level doubling (the difference of successive rules,
    /// extrapolated where the driver says so).
    Quadrature,
    /// The round-off of the working precision (and, for a series, its truncated tail): the
    /// value is exact in real arithmetic.
    Rounding,
    /// The difference to coarser grid levels of a discretised solution (grid refinement).
    Refinement,
    /// A least-squares or collocation fit's error, from fits of other sizes and the rules
    /// behind them.
    Fit,
    /// Carried through a formula from the estimates of its inputs.
    Propagated,
}

/// A value with its estimated absolute error and what the estimate means.
///
/// The error is an `f64` (`E = f64`) wherever every value carries an estimate. Where a
/// value may have none (the impact history of a single grid level, which has nothing to
/// refine against), `E = Option<f64>` and a missing estimate is `None`, never a zero that
/// would read as an exact value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate<T, E = f64> {
    /// The value.
    pub value: T,
    /// Its estimated absolute error.
    pub error: E,
    /// What the error estimates.
    pub kind: ErrorKind,
}

impl<T, E> Estimate<T, E> {
    /// The value `value` with the error `error` of the kind `kind`.
    pub fn new(value: T, error: E, kind: ErrorKind) -> Self {
        Estimate { value, error, kind }
    }
}
