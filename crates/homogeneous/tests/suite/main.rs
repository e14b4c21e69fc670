//! The integration tests of `homogeneous` in one binary, a module for each subject: the generic
//! code they share is instantiated, optimised and linked once rather than once a file.
//! `cargo test --release -p homogeneous <module>::` runs one subject's tests.

mod common;

mod field_tests;
