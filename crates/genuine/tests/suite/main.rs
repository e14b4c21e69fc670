//! The integration tests of `genuine` in one binary, a module for each subject: the generic
//! code they share is instantiated, optimised and linked once rather than once a file.
//! `cargo test --release -p genuine <module>::` runs one subject's tests.

mod genuine;
mod kernels;
mod lamb_step;
mod precision;
