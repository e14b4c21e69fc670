//! The integration tests of `dyncontact` in one binary, a module for each subject: the generic
//! code they share is instantiated, optimised and linked once rather than once a file.
//! `cargo test --release -p dyncontact <module>::` runs one subject's tests.

mod common;

mod accuracy;
mod cli;
mod complex_functions;
mod double_double;
mod edge_exponents;
mod error_estimates;
mod figures;
mod genuine_double_double;
mod golden;
mod hundred_digits;
mod impact_cli;
mod messages;
mod no_silent_numbers;
mod report_layer;
mod selection;
mod stability;
mod tiny_theta;
mod wedge_reference;
mod wedge_solution;
