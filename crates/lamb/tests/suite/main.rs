//! The integration tests of `lamb` in one binary, a module for each subject: the generic
//! code they share is instantiated, optimised and linked once rather than once a file.
//! `cargo test --release -p lamb <module>::` runs one subject's tests.

mod common;

mod cells;
mod closed_forms;
mod edge;
mod extreme;
mod half_space;
mod mpmath_reference;
