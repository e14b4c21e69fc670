//! The rigid-wedge indentation problem (reference paper, eqs (22)-(57)).
#![warn(missing_docs)]
