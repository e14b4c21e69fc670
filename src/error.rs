//! The errors of the library's front: a bad input that names its parameter
//! ([`InputError`]), and the engines' own errors ([`Error`]).
//!
//! A parameter is named as the command-line flag names it, without the dashes (`mass_ratio`
//! for `--mass-ratio`): the same name a keyword argument of another front end carries.

use thiserror::Error as ThisError;

/// A bad input: malformed, out of its admissible range, missing, or contradicting another.
/// The message says which and what would do; `parameter` names the input responsible.
#[derive(Clone, Debug, PartialEq, ThisError)]
#[error("{message}")]
pub struct InputError {
    /// The parameter responsible (the flag's name, underscores for dashes).
    pub parameter: &'static str,
    /// The one-line message.
    pub message: String,
}

impl InputError {
    /// A bad `parameter`, with its message.
    pub fn new(parameter: &'static str, message: impl Into<String>) -> Self {
        InputError {
            parameter,
            message: message.into(),
        }
    }
}

/// Any failure of a library call: a bad input, or a numerical failure of an engine with the
/// case's inputs.
#[derive(Clone, Debug, PartialEq, ThisError)]
pub enum Error {
    /// A bad input, naming its parameter.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A failure of the wedge engine (its `InvalidParameter` is a bad input too).
    #[error(transparent)]
    Wedge(#[from] wedge::WedgeError),
    /// A failure of the impact engine (its `InvalidParameter` is a bad input too).
    #[error(transparent)]
    Impact(#[from] impact::ImpactError),
    /// A failure of the half-plane's response functions (its `InvalidParameter` is a bad
    /// input too).
    #[error(transparent)]
    Lamb(#[from] lamb::LambError),
}

impl Error {
    /// The parameter a bad input names, or `None` for a numerical failure.
    pub fn parameter(&self) -> Option<&'static str> {
        match self {
            Error::Input(e) => Some(e.parameter),
            Error::Wedge(wedge::WedgeError::InvalidParameter(p)) => Some(p.name),
            Error::Impact(impact::ImpactError::InvalidParameter(p)) => Some(p.name),
            Error::Lamb(lamb::LambError::InvalidParameter(p)) => Some(p.name),
            _ => None,
        }
    }
    /// Whether the error is a bad input (else a numerical failure).
    pub fn is_input(&self) -> bool {
        self.parameter().is_some()
    }
}
