//! The integration tests of `impact` in one binary, a module for each subject: the generic
//! code they share is instantiated, optimised and linked once rather than once a file.
//! `cargo test --release -p impact <module>::` runs one subject's tests.

mod common;

mod axisym;
mod bridge;
mod cylinder;
mod disk;
mod edge_exponents;
mod estimates;
mod green;
mod physics;
mod precision;
mod rebound;
mod selfsimilar;
mod strikers;
