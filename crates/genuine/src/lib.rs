//! The genuine frictional wedge-indentation solution (no apex dislocation).
#![warn(missing_docs)]
