//! The scalars the march is generic over (`docs/impact.md`, section 7): the fixed-width
//! implementations of the precision trait [`Real`], `f64` and the double-double [`Dd`]
//! (about 32 digits), both `Copy` and free of allocation, so the march's arithmetic reads as
//! in f64 and costs no allocation at either precision.

use complexfn::{Dd, Real};

use crate::history::KernelRows;

/// A fixed-width real of the precision layer: `f64` or [`Dd`].
pub trait Scalar: Real + Copy {
    /// Whether the history sum may run through the f64 FFT (exact only in f64: the FFT's
    /// rounding is that of f64, `crate::history`).
    const FFT: bool;

    /// The value of an f64 (exact).
    fn of(x: f64) -> Self {
        Self::from_f64_prec(x, Self::BITS)
    }

    /// The significand's bits (53 for f64, 106 for double-double).
    const BITS: u32;

    /// An input (a case's parameter): the decimal number of the f64's shortest
    /// representation, which is what was written (0.02 is 0.02, not the double nearest to
    /// it), at this precision; the f64 itself in f64.
    fn input(x: f64) -> Self;

    /// A deformable striker's compliance rows at this precision: the striker models
    /// (`crate::striker`) are built in f64, so `None` at any other precision.
    fn striker_rows(rows: &mut dyn KernelRows<f64>) -> Option<&mut dyn KernelRows<Self>>;

    /// The sum of the products a_i b_i.
    fn dot(a: &[Self], b: &[Self]) -> Self {
        a.iter().zip(b).fold(Self::of(0.0), |s, (x, y)| s + *x * *y)
    }
}

impl Scalar for f64 {
    const FFT: bool = true;
    const BITS: u32 = 53;
    fn input(x: f64) -> Self {
        x
    }
    fn striker_rows(rows: &mut dyn KernelRows<f64>) -> Option<&mut dyn KernelRows<Self>> {
        Some(rows)
    }
}

impl Scalar for Dd {
    const FFT: bool = false;
    const BITS: u32 = 106;
    fn input(x: f64) -> Self {
        Dd::parse_prec(&x.to_string(), Self::BITS).unwrap_or(Dd::from_f64(x))
    }
    fn striker_rows(_: &mut dyn KernelRows<f64>) -> Option<&mut dyn KernelRows<Self>> {
        None
    }
}
