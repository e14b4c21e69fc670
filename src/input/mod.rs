//! Text inputs into typed cases: the decimal texts and specifications (`circle:R=1`,
//! `c1t/R=10`, `x:y` points, alpha ranges) that the command lines take as flags and other
//! front ends as keyword arguments, each refused with an error naming its parameter.

pub mod impact;
pub mod wedge;
