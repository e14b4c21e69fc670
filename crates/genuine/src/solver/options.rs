//! The options of the collocation solve and the constants that set its rules and its error
//! estimate.

/// Where (as a fraction of p) the slope U_y' + beta U_x' = 1 and V_hat are taken from the
/// contour representation: an interior point, where the y-integrand is smooth (at the edge it
/// carries y^(-1/2 + Omega) and converges slowly).
pub const NORMALISATION_POINT: f64 = 0.5;

/// Relative floor added to the error estimate at 53 bits: the level to which the collocation
/// rows and the contour integrals are converged (measured residuals of (7) are 1e-15 to
/// 1e-14). [`roundoff_floor`] gives the value for other precisions.
pub const ROUNDOFF_FLOOR: f64 = 1e-13;

/// The relative floor of the error estimate at `bits` of working precision:
/// [`ROUNDOFF_FLOOR`] 2^(53 - bits), i.e. about 900 units in the last place, the level of the
/// rules chosen by [`SolveOptions::for_precision`].
pub fn roundoff_floor(bits: u32) -> f64 {
    ROUNDOFF_FLOOR * 2f64.powi(53 - bits.max(53) as i32)
}

/// The fraction of the Rayleigh speed (p/m_R) above which the solve refines its contour step
/// by [`NEAR_RAYLEIGH_STEP`] and, above f64, adds the plateau probe (a second fit of degree N
/// on another collocation set, [`PLATEAU_MARGIN`]). Measured at 132 bits (Theta 89 deg,
/// gamma 0.6): at p = 0.495 = 0.9986 m_R the contour rule of the plain step left 3.7e-32 and
/// the degrees' extrapolation stated 5e-36 for an actual 9e-34; at p = 0.3 and 0.45 (0.61 and
/// 0.91 m_R) the plain step and the extrapolation were within their estimates, and the
/// 120-case comparison of `tests/suite/error_estimates.rs` holds without the probe.
pub const NEAR_RAYLEIGH: f64 = 0.95;

/// The factor of the contour step within [`NEAR_RAYLEIGH`] of the Rayleigh speed.
pub const NEAR_RAYLEIGH_STEP: f64 = 0.75;

/// The margin on the difference between the fine fit and the fit of the same degree on
/// another collocation set (the plateau of the least-squares solve, see
/// [`GenuineCase::error_estimate`](super::GenuineCase::error_estimate)). The difference is a sample of the scatter, not a bound.
pub const PLATEAU_MARGIN: f64 = 4.0;

/// Up to this working precision (double-double, 104 bits, but not f64) the plateau probe
/// ([`PLATEAU_MARGIN`]) runs at every contact speed, not only within [`NEAR_RAYLEIGH`]: the
/// least-squares solve's round-off (of order its conditioning times 2^-104) can then lie above
/// the degrees' extrapolation anywhere. Measured against MPFR at 200 bits (Theta 30 deg,
/// gamma 0.2, alpha = 93.5 m/s): V off by 7.5e-28 with the fits of degrees N/2, 3N/4 and N
/// differing by 1.6e-25 and 2.6e-28, which extrapolate to 4.1e-29; the probe states 3.1e-27.
pub const PLATEAU_EVERYWHERE_BITS: u32 = 110;

/// Reach of the tanh rule behind the F-functions at 53 bits, in units of its variable
/// (offsets down to e^(-100) of the interval). The rule used now is the mixed map of
/// [`crate::quad::se_de_unit`], whose reach follows the precision ([`v_rule_s_max`]).
pub const V_RULE_S_MAX: f64 = 100.0;

/// Reach of the single-exponential end of the v-rule for `bits` of precision: offsets from the
/// split point down to 2^(-bits - 8) of the interval (the integrand is bounded there, so the
/// lost tail is the offset itself).
pub fn v_rule_s_max(bits: u32) -> f64 {
    (f64::from(bits) + 8.0) * std::f64::consts::LN_2
}

/// Sample points of the gap check on (p, 1) ([`GenuineCase::no_interpenetration`](super::GenuineCase::no_interpenetration)).
pub const GAP_SAMPLES: usize = 12;

/// Options of the solve.
#[derive(Clone, Debug)]
pub struct SolveOptions {
    /// Chebyshev polynomials per basis family (the error estimate uses half as many).
    pub degree: usize,
    /// Add the family without apex factor (default: only when gamma > 0).
    pub regular_family: Option<bool>,
    /// Collocation points per unknown (>= 1).
    pub oversample: f64,
    /// Step of the tanh-sinh rule of the collocation rows.
    pub h_quad: f64,
    /// Relative tolerance of the contour integrals.
    pub contour_tol: f64,
    /// Replace the apex families by fixed exponents (S ~ x^(-lambda)); for diagnostics only
    /// (the default, `None`, uses the roots of the eigen-equation with their x-variation).
    pub apex_lambdas: Option<Vec<f64>>,
    /// Step of the v-rule in the F-functions of the contour integrals (error ~ exp(-pi^2/h)).
    pub h_tanh: f64,
}

impl Default for SolveOptions {
    /// The defaults for f64 ([`SolveOptions::for_precision`] at 53 bits).
    fn default() -> Self {
        SolveOptions::for_precision(53)
    }
}

impl SolveOptions {
    /// The defaults for a working precision of `bits` bits (53 for f64), chosen so that every
    /// discretisation error is of the order of 2^-bits:
    ///
    /// * `h_tanh = pi^2/((bits + 4) ln 2)` (the v-rule's error is exp(-c/h), c = pi^2 for a
    ///   pole above the split point; within [`NEAR_RAYLEIGH`] of the Rayleigh speed c falls to
    ///   about (3/4) pi^2, 3.7e-32 instead of 1e-41 at 132 bits, and the solve takes
    ///   [`NEAR_RAYLEIGH_STEP`] times the step given; the level-doubling probe of the solve
    ///   reports what is left);
    /// * `h_quad = 1/32 * (53/bits)^(1/2)` (the rows' integrands are analytic inside the
    ///   tanh-sinh strip except at the ends, where the rule is double-exponential; measured at
    ///   128 bits, halving `h_quad` from this value changes nothing above 1e-37);
    /// * `contour_tol = 2^-(bits - 7)`;
    /// * `degree = 24 + 20 (bits - 53)/75`, even (the spectral error falls geometrically, by
    ///   about one decade per unit of degree, so the degree grows linearly with the number of
    ///   digits wanted; [`GenuineCase::error_estimate`](super::GenuineCase::error_estimate) says how the error is estimated from
    ///   coarser sizes);
    /// * oversampling 2 up to 64 bits, 1.5 beyond (the rows are then exact to many more
    ///   digits than the discretisation needs).
    ///
    /// Truncations (the reach of every rule into its endpoint tails) are not options: they
    /// follow the precision of the contact speed passed to [`GenuineCase::solve`](super::GenuineCase::solve).
    pub fn for_precision(bits: u32) -> Self {
        let b = f64::from(bits.max(53));
        let degree =
            (((24.0 + 20.0 * (b - 53.0) / 75.0) / 2.0).round() as usize * 2).clamp(24, 200);
        SolveOptions {
            degree,
            regular_family: None,
            oversample: if bits <= 64 { 2.0 } else { 1.5 },
            h_quad: 1.0 / 32.0 * (53.0 / b).sqrt(),
            contour_tol: 2f64.powi(-(b as i32 - 7)),
            h_tanh: std::f64::consts::PI.powi(2) / ((b + 4.0) * std::f64::consts::LN_2),
            apex_lambdas: None,
        }
    }
}
