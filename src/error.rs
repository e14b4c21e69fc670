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

/// The flag (underscores for dashes) of an engine's parameter name: the engines name their
/// inputs in words ("kappa = c1 dt/dx", "refinement levels"); a front end names the flag.
pub fn flag_of(name: &'static str) -> &'static str {
    match name {
        "kappa = c1 dt/dx" => "kappa",
        "refinement levels" => "levels",
        "cell width dx/R" => "dx",
        "V0/c1" => "v0_over_c1",
        "mass ratio m0/(rho R^2)" => "mass_ratio",
        "mass ratio m0/(rho R^2) of a shell striker"
        | "mass ratio m0/(rho R^2) of a cylinder striker" => "mass_ratio",
        "end time c1 t/R" => "end",
        "driven table" | "driven speed V/c1" => "driven",
        "Poisson's ratio" => "poisson",
        "c2/c1" => "c2",
        "s" => "at",
        "sa" | "sb" | "cell [sa, sb]" => "cells",
        "speed_over_c1" => "speed_over_c1",
        "arc over R" => "arc_over_R",
        "angle" | "angles and times" => "at_deg",
        "c2 t/R" => "times",
        "profile"
        | "profile of a shell striker"
        | "profile of a cylinder striker"
        | "profile exponent k"
        | "wedge half-angle theta_deg" => "profile",
        "striker"
        | "shell thickness h_s/R"
        | "striker density ratio rho_s/rho"
        | "striker c1 over the half-plane's c1"
        | "striker c2 over the half-plane's c1" => "striker",
        other => other,
    }
}

impl Error {
    /// The parameter a bad input names (the flag's name, underscores for dashes), or `None`
    /// for a numerical failure.
    pub fn parameter(&self) -> Option<&'static str> {
        use impact::ImpactError as I;
        use lamb::LambError as L;
        match self {
            Error::Input(e) => Some(e.parameter),
            Error::Wedge(wedge::WedgeError::InvalidParameter(p)) => Some(p.name),
            Error::Impact(I::InvalidParameter(p))
            | Error::Impact(I::Lamb(L::InvalidParameter(p)))
            | Error::Lamb(L::InvalidParameter(p)) => Some(flag_of(p.name)),
            Error::Impact(I::Grid { name, .. }) => Some(flag_of(name)),
            _ => None,
        }
    }
    /// Whether the error is a bad input (else a numerical failure).
    pub fn is_input(&self) -> bool {
        self.parameter().is_some()
    }
}
