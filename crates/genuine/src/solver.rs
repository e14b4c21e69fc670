//! The genuine contact problem and its spectral collocation solve.
//!
//! Units c1 = mu = 1; S = sigma_yy/(mu cot Theta) on the contact |x| < p (even, S(p) = 0),
//! shear sigma_xy = -sgn(x) gamma sigma_yy (eq (4b)), displacements over c1 t cot Theta, and the
//! contact condition (7) on 0 < x < p: U_y + beta U_x = -V_hat + x.
//!
//! With h = dS/dx (odd), integration by parts gives the F-functions of [`crate::kernels`]:
//!
//! ```text
//!   F_y(z) = Int_0^p h(v) 2v/(v^2 - z^2) dv,   F_x(z) = -gamma Int_0^p h(v) 2v^2/(z (v^2 - z^2)) dv.
//! ```
//!
//! The condition is imposed in two parts.
//! 1. Its second derivative, U_y'' + beta U_x'' = 0 on (0, p), is local: U'' = Im Phi''(x + i0)/pi
//!    with Phi'' = -K(1/z) F(z)/z. On the contact xi = 1/x > 1/c_R, a_k = i alpha_k, K_yy and
//!    K_xx are imaginary and K_yx real, F^+ = PV + i pi h, and the condition becomes the
//!    singular integral equation
//!    ```text
//!      H_y/|p1| - gamma beta H_x/|p2| - pi (beta + gamma) c(x) h(x) = 0,
//!      H_y = PV Int_0^p h 2v/(v^2 - x^2) dv,  H_x = PV Int_0^p h 2v^2/(x (v^2 - x^2)) dv,
//!      c(x) = m^2 (L/x^2)/(|p1| |p2|)   (L = 2 - K |p1| |p2| of the paper).
//!    ```
//!    Its characteristic ratio is the paper's tan(pi Omega) (eq (31)), so the local edge
//!    exponent is Omega(x); at the apex it gives the eigen-equation of [`crate::apex`].
//!    It is collocated at Chebyshev points of (0, p), the principal value taken as
//!    Int (f(v) - f(x))/(v - x) dv + f(x) ln((p - x)/x) with tanh-sinh on (0, x) and (x, p).
//! 2. The slope at x* = p/2, U_y'(x*) + beta U_x'(x*) = 1, fixes the scale, and
//!    V_hat = x* - U_y(x*) - beta U_x(x*), both from the contour representation.
//!
//!
//! Discretisation. The basis functions are sampled once on one tanh-sinh rule of (0, p) (step
//! `h_quad`), and every collocation row is a weighted sum over those samples; the collocation
//! points are Chebyshev points moved onto the quarter points of the rule's t-grid, so that no
//! node is closer to a collocation point than a quarter step and the difference quotient
//! (f(v) - f(x))/(v - x) keeps its accuracy. The rows and a normalisation row (the force
//! moment Int_0^p x h dx = 1, heavily weighted) are solved in the least-squares sense by
//! Householder QR with column pivoting ([`crate::lsq`]); the contour functionals of step 2 are
//! then evaluated for the solution only (one column, not one per basis function), and the
//! solution is rescaled so that the slope condition holds. The error estimate is
//! |V_hat(N) - V_hat(N/2)| plus a precision-dependent floor ([`roundoff_floor`]).
//!
//! Precision. Everything is generic over `T: Real` (f64, or `rug::Float` at the precision of
//! the contact speed p passed in). The truncations of every rule follow the working precision
//! and the case's endpoint exponents ([`crate::quad`]); the steps and the basis degree are
//! options, with [`SolveOptions::for_precision`] giving the defaults for a precision.

use std::sync::OnceLock;

use complexfn::quadrature::CachedRules;
use complexfn::{Cx, Rayleigh, Real};
use wedge::{Coupling, Indenter, Material};

use crate::basis::{Basis, Family};
use crate::error::{invalid, GenuineError, Result};
use crate::kernels::{contour_integrand, y_integral_checked, CauchySums, Lamb};
use crate::lsq::{least_squares, Matrix};
use crate::quad::{integrate_vec, tanh_sinh_unit, tanh_sinh_unit_node, UnitNode};

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
/// 120-case comparison of `tests/error_estimates.rs` holds without the probe.
pub const NEAR_RAYLEIGH: f64 = 0.95;

/// The factor of the contour step within [`NEAR_RAYLEIGH`] of the Rayleigh speed.
pub const NEAR_RAYLEIGH_STEP: f64 = 0.75;

/// The margin on the difference between the fine fit and the fit of the same degree on
/// another collocation set (the plateau of the least-squares solve, see
/// [`GenuineCase::error_estimate`]). The difference is a sample of the scatter, not a bound.
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

/// Sample points of the gap check on (p, 1) ([`GenuineCase::no_interpenetration`]).
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
    ///   digits wanted; [`GenuineCase::error_estimate`] says how the error is estimated from
    ///   coarser sizes);
    /// * oversampling 2 up to 64 bits, 1.5 beyond (the rows are then exact to many more
    ///   digits than the discretisation needs).
    ///
    /// Truncations (the reach of every rule into its endpoint tails) are not options: they
    /// follow the precision of the contact speed passed to [`GenuineCase::solve`].
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

/// Everything that defines one case (shared by the two basis sizes).
#[derive(Clone, Debug)]
struct Problem<T> {
    p: T,
    beta: T,
    gamma: T,
    cot_theta: T,
    ray: Rayleigh<T>,
    lamb: Lamb<T>,
    prec: u32,
}

/// One sample of the basis: the abscissa, p - v, the quadrature weight, the family weights
/// and the Chebyshev argument (enough to evaluate the basis at any degree).
#[derive(Clone, Debug)]
struct Sample<T> {
    v: T,
    pv: T,
    w: T,
    fam: Vec<T>,
    t: T,
}

/// The apex coefficient c_j of one family (h ~ c_j x^(-1 - lambda_j)) and the size of the
/// alternating sum that gives it.
struct ApexCoefficient<T> {
    c: T,
    size: f64,
}

/// The apex exponent lambda_j of each family of `basis` (`None` for the logarithmic and the
/// regular families).
fn family_exponents<T: Real>(
    ex: &crate::apex::ApexExponents<T>,
    basis: &Basis<T>,
) -> Vec<Option<T>> {
    basis
        .families()
        .iter()
        .map(|f| match f {
            crate::basis::Family::Root(j) => Some(ex.lambdas[*j].clone()),
            crate::basis::Family::Fixed(l) => Some(basis.rayleigh().m().lit(*l)),
            crate::basis::Family::Log | crate::basis::Family::Regular => None,
        })
        .collect()
}

/// One collocation solve.
#[derive(Clone, Debug)]
struct Fit<T> {
    basis: Basis<T>,
    coef: Vec<T>,
    v_hat: T,
    residual: f64,
}

/// The error of the contour integrals behind the scale of the solution (the slope condition
/// U_y' + beta U_x' = 1 at x*) and V_hat, from the level-doubling probe of their v-rule (the
/// same load summed on the nodes of step 2h) and the y-rule's own estimate.
#[derive(Clone, Copy, Debug)]
struct ContourProbe {
    /// |V_hat(h) - V_hat(2h)|.
    v_diff: f64,
    /// |slope(2h)/slope(h) - 1|.
    scale_diff: f64,
    /// The y-rule's estimated error of the slope and of V_hat, relative to the slope.
    y_rel: f64,
}

/// The margin of the contour probe's extrapolation (the level doubling of the v-rule): the
/// error of the rule of step h is taken as `CONTOUR_MARGIN` d^2/|q| from d = |q(h) - q(2h)|. Measured at
/// 132 bits (Theta 89 deg, gamma 0.6), the actual error was 3.5 (p = 0.3) to 350 (p = 0.45,
/// 0.495, next to the Rayleigh speed) times d^2 (q of order 0.4): the margin keeps the estimate
/// at least 30 times above the error.
pub const CONTOUR_MARGIN: f64 = 1e4;

impl ContourProbe {
    /// The error of a quantity of size `size` whose rules of steps h and 2h differ by `d`:
    /// the rule converges like exp(-c/h), so e(h) ~ e(2h)^2/A; taken as
    /// [`CONTOUR_MARGIN`] d^2/size while that is below d (d < size/[`CONTOUR_MARGIN`]),
    /// otherwise d itself.
    fn extrapolate(d: f64, size: f64) -> f64 {
        if size > 0.0 && d * CONTOUR_MARGIN < size {
            CONTOUR_MARGIN * d * d / size
        } else {
            d
        }
    }

    /// The absolute error of V_hat (of size `v`) from the contour integrals.
    fn v_error(&self, v: f64) -> f64 {
        Self::extrapolate(self.v_diff, v.abs()) + self.y_rel * (1.0 + v.abs())
    }

    /// The relative error of the solution's scale (of every quantity proportional to the
    /// coefficients) from the contour integrals.
    fn scale_error(&self) -> f64 {
        Self::extrapolate(self.scale_diff, 1.0) + self.y_rel
    }

    fn new<T: Real>(
        slope: &T,
        v_hat: &T,
        slope_2h: &T,
        v_hat_2h: &T,
        y_err: f64,
        beta: &T,
    ) -> Self {
        let s = slope.to_f64().abs();
        ContourProbe {
            v_diff: (v_hat.clone() - v_hat_2h).abs().to_f64(),
            scale_diff: (slope_2h.clone() / slope - 1.0).abs().to_f64(),
            y_rel: y_err * (1.0 + beta.to_f64().abs()) / s,
        }
    }
}

/// The row rule's abscissae, weights and doubled abscissae as slices (the operands of the
/// rows' slice operations).
struct RowColumns<T> {
    v: Vec<T>,
    w: Vec<T>,
    v2: Vec<T>,
}

impl<T: Real> RowColumns<T> {
    fn new(samples: &[Sample<T>]) -> Self {
        RowColumns {
            v: samples.iter().map(|s| s.v.clone()).collect(),
            w: samples.iter().map(|s| s.w.clone()).collect(),
            v2: samples.iter().map(|s| s.v.clone() * 2.0).collect(),
        }
    }
}

/// The collocation rows of the fine fit's basis by the grid index of their point (t = k h/4):
/// a fit whose basis is a part of it (the same families, a lower degree) takes its rows at the
/// points it shares from there (the row of a basis function does not depend on the others,
/// so the columns taken are the ones it would compute). With the default options at 104 bits
/// the plateau probe shares 111 of its 214 points with the fine fit, the degrees N/2 and 3N/4
/// 54 of 86 and 86 of 126 with the two. The rows are computed once, for the union of the
/// fine fit's and the plateau probe's points, in parallel (each row is a function of its point
/// alone, so the numbers do not depend on the threads); the fits then only read them.
struct RowCache<T> {
    families: Vec<Family>,
    degree: usize,
    rows: std::collections::HashMap<i64, Vec<T>>,
}

impl<T: Real> RowCache<T> {
    /// The rows of `full` at `points`, computed by `compute` on the available threads.
    fn new(
        full: &Basis<T>,
        points: &[(i64, T, T)],
        compute: impl Fn(&T, &T) -> Vec<T> + Sync,
    ) -> Self {
        use rayon::prelude::*;
        RowCache {
            families: full.families().to_vec(),
            degree: full.degree(),
            rows: points
                .par_iter()
                .map(|(k, x, pmx)| (*k, compute(x, pmx)))
                .collect(),
        }
    }

    /// The row of `basis` at the point of index `k`, from `compute` unless held.
    fn row(&self, basis: &Basis<T>, k: i64, compute: impl FnOnce() -> Vec<T>) -> Vec<T> {
        if basis.families() != self.families.as_slice() || basis.degree() > self.degree {
            return compute();
        }
        match self.rows.get(&k) {
            Some(full) if basis.degree() == self.degree => full.clone(),
            Some(full) => leading_columns(full, self.degree, basis.degree()),
            None => compute(),
        }
    }
}

/// Collocation points as (k, x, p - x), t = k h/4 on the row rule's grid
/// ([`Problem::collocation_points`]).
type CollocationPoints<T> = Vec<(i64, T, T)>;

/// The values of a basis of degree `n` taken from those of a basis of the same families and
/// degree `big` >= n (laid out a family's `big` values after another, per row): each family's
/// first n, the values a fill at degree n gives (the Chebyshev recurrence being the same).
fn leading_columns<T: Clone>(full: &[T], big: usize, n: usize) -> Vec<T> {
    full.chunks_exact(big)
        .flat_map(|f| f[..n].iter().cloned())
        .collect()
}

/// The contour functionals of [`Problem::contour_loads`]: the load's, the coarse level's, the
/// differences' (in f64), and the y-rule's estimated absolute error.
struct ContourLoads<T> {
    fine: [T; 4],
    coarse: Option<[T; 4]>,
    diffs: Vec<[f64; 4]>,
    err: f64,
}

/// The terms of the moment expansion of the Cauchy sums ([`crate::kernels::CauchySums`]) kept
/// at `bits` for `samples` samples: as many as the bits (enough down to |z| = 1.43 max v, where
/// r^M reaches 2^-bits at r = 1/2), but no more than an eighth of the samples (the expansion
/// then costs under a fifth of the term-by-term sums).
fn moment_terms(bits: u32, samples: usize) -> usize {
    (bits as usize).min(samples / 8)
}

/// The solved genuine case, at the precision of the contact speed it was solved for (`f64` by
/// default).
#[derive(Clone, Debug)]
pub struct GenuineCase<T = f64> {
    prob: Problem<T>,
    fit: Fit<T>,
    /// The solve at degree N/2.
    coarse: Fit<T>,
    /// The solve at degree 3N/4.
    middle: Fit<T>,
    /// Above f64 (next to the Rayleigh speed, or at every speed up to
    /// [`PLATEAU_EVERYWHERE_BITS`]): the solve at degree N on another collocation set (a
    /// quarter more points).
    other_points: Option<Fit<T>>,
    /// The error of the contour rule behind the slope and V_hat.
    contour: ContourProbe,
    opts: SolveOptions,
    /// The apex exponents, amplitude and its estimate ([`GenuineCase::apex_with_error`]),
    /// computed once on demand.
    apex: OnceLock<Result<(crate::apex::ApexExponents<T>, T, f64)>>,
    /// The force and its estimate ([`GenuineCase::force_hat_with_error`]), computed once on
    /// demand.
    force: OnceLock<(T, f64)>,
}

impl<T: Real> Problem<T> {
    fn new(material: &Material, indenter: &Indenter, p: T) -> Result<Self> {
        let m = material.m(&p);
        let ray = Rayleigh::new(m.clone())?;
        let m_r = ray.m_r().clone();
        if !(p.is_finite() && p > 0.0 && p < m_r) {
            return Err(invalid(
                "p = alpha/c1",
                p.to_f64(),
                format!("(0, m_R) = (0, {})", m_r.to_f64()),
            ));
        }
        let cot_theta = indenter.cot_theta(&p);
        let gamma = indenter.gamma().to_real(&p);
        let beta = match indenter.coupling() {
            Coupling::On => -cot_theta.clone(),
            Coupling::Off => p.zero(),
        };
        let prec = p.prec();
        Ok(Problem {
            p,
            beta,
            gamma,
            cot_theta,
            ray,
            lamb: Lamb::new(m),
            prec,
        })
    }

    fn basis(&self, degree: usize, opts: &SolveOptions) -> Basis<T> {
        let regular = opts.regular_family.unwrap_or(self.gamma > 0.0);
        Basis::new(
            self.ray.clone(),
            self.p.clone(),
            self.beta.clone(),
            self.gamma.clone(),
            degree,
            regular,
            opts.apex_lambdas.as_deref(),
        )
    }

    /// The weakest endpoint exponent e of the integrands (tails behave like offset^(e - 1)):
    /// 1/2 + Omega(p) at the edge, 1 - lambda_max at the apex, at most 1, at least 0.05.
    fn tail_exponent(&self, basis: &Basis<T>) -> f64 {
        let edge = 0.5 + basis.omega(&self.p).to_f64();
        let ex =
            crate::apex::exponents(self.ray.m().clone(), self.beta.clone(), self.gamma.clone());
        let mut lam_max = 0.0_f64;
        for f in basis.families() {
            match f {
                Family::Root(j) => lam_max = lam_max.max(ex.lambdas[*j].to_f64()),
                Family::Fixed(l) => lam_max = lam_max.max(*l),
                Family::Log | Family::Regular => {}
            }
        }
        edge.min(1.0 - lam_max).clamp(0.05, 1.0)
    }

    fn sample(&self, basis: &Basis<T>, v: T, pv: T, w: T) -> Sample<T> {
        let fam = basis.weights(&v, &pv);
        let t = basis.cheb_arg(&v, &pv);
        Sample { v, pv, w, fam, t }
    }

    /// The tanh-sinh rule of (0, p) behind the collocation rows, sampled.
    fn row_samples(&self, basis: &Basis<T>, h: f64) -> Vec<Sample<T>> {
        let tmax = crate::quad::t_max_for(self.prec, self.tail_exponent(basis));
        tanh_sinh_unit(&self.p, h, tmax)
            .iter()
            .map(|u| {
                let nd = u.on(&self.p.zero(), &self.p);
                self.sample(basis, nd.from_a, nd.to_b, nd.w)
            })
            .collect()
    }

    /// The v-rule of the contour integrals at x0 in (0, p), sampled: the mixed rule of
    /// [`crate::quad::se_de_unit`] on (0, x0) and (x0, p), single-exponential at x0; with, per
    /// sample, whether it is a node of the rule of step 2h (the coarser level of the probe).
    fn contour_samples(&self, basis: &Basis<T>, x0: &T, h: f64) -> (Vec<Sample<T>>, Vec<bool>) {
        let e = self.tail_exponent(basis);
        let unit =
            crate::quad::se_de_unit_indexed(&self.p, h, v_rule_s_max(self.prec), self.prec, e);
        let p = &self.p;
        let left = x0.clone();
        let right = p.clone() - x0;
        let mut out = Vec::with_capacity(2 * unit.len());
        let mut coarse = Vec::with_capacity(2 * unit.len());
        for (k, u) in &unit {
            coarse.extend([k % 2 == 0; 2]);
            // (0, x0): the single-exponential end is x0
            let d_x0 = u.from_a.clone() * &left;
            let d_0 = u.to_b.clone() * &left;
            let v = if d_0 < d_x0 {
                d_0.clone()
            } else {
                x0.clone() - &d_x0
            };
            out.push(self.sample(basis, v, right.clone() + &d_x0, u.w.clone() * &left));
            // (x0, p)
            let d_x0 = u.from_a.clone() * &right;
            let d_p = u.to_b.clone() * &right;
            let v = if d_x0 < d_p {
                x0.clone() + &d_x0
            } else {
                p.clone() - &d_p
            };
            out.push(self.sample(basis, v, d_p, u.w.clone() * &right));
        }
        (out, coarse)
    }

    /// The collocation points: Chebyshev points of (0, p) moved to the nearest quarter point
    /// of the t-grid of the row rule (never onto a node), as (k, x, p - x), t = k h/4.
    fn collocation_points(&self, count: usize, h: f64) -> Vec<(i64, T, T)> {
        // positions in units of h/4
        let mut ks: Vec<i64> = (0..count)
            .map(|i| {
                let th = std::f64::consts::PI * (i as f64 + 0.5) / count as f64;
                let frac = (1.0 - th.cos()) / 2.0;
                // x/p = 1/(1 + e^(-2u)), u = (pi/2) sinh t
                let u = 0.5 * (frac / (1.0 - frac)).ln();
                let t = (2.0 * u / std::f64::consts::PI).asinh();
                let q = t / h;
                let j = q.floor();
                let r = ((q - j) * 4.0).round().clamp(1.0, 3.0);
                4 * (j as i64) + r as i64
            })
            .collect();
        ks.sort_unstable();
        ks.dedup();
        ks.into_iter()
            .filter_map(|k| {
                tanh_sinh_unit_node(&self.p, k, h / 4.0)
                    .map(|u: UnitNode<T>| (k, u.from_a * &self.p, u.to_b * &self.p))
            })
            .collect()
    }

    /// The collocation row of the singular integral equation at x in (0, p), from the sampled
    /// basis values `bv` (row-major, one row of `kk` values per sample).
    fn sie_row(
        &self,
        basis: &Basis<T>,
        x: &T,
        pmx: &T,
        samples: &[Sample<T>],
        cols: &RowColumns<T>,
        bv: &[T],
    ) -> Vec<T> {
        let kk = basis.len();
        let (p1, p2, l_s) = self.ray.cut_values(x);
        let a1 = p1.clone().recip();
        let a2 = self.gamma.clone() * &self.beta / &p2;
        let a2x = a2.clone() / x;
        let c = self.ray.m2().clone() * l_s / (p1 * p2);
        let mut phi_x = vec![x.zero(); kk];
        basis.eval(x, pmx, &mut phi_x);
        let a12 = a1.clone() - &a2;
        let log_term = (pmx.clone() / x).ln();
        let pc = x.pi() * (self.beta.clone() + &self.gamma) * c;
        // Sum_n w_n (f_n - f_x)/(v_n - x) = Sum_n c_n B_n - f_x Sum_n w_n/(v_n - x), with
        // c_n = w_n/(v_n - x) 2v_n/(v_n + x) (a1 - a2 v_n/x): one division per sample, the
        // loops over the samples in the slice operations of the precision layer
        let zero = x.zero();
        let n = samples.len();
        let mut dv = Vec::with_capacity(n);
        let mut vpx = Vec::with_capacity(n);
        for s in samples {
            dv.push(if s.pv < s.v {
                pmx.clone() - &s.pv
            } else {
                s.v.clone() - x
            });
            vpx.push(s.v.clone() + x);
        }
        let mut t = vec![zero.clone(); n];
        T::mul_slice(&mut t, &dv, &vpx);
        // r = w/((v - x)(v + x)); Sum w/(v - x) = Sum r (v + x)
        let mut r = dv;
        T::div_slice(&mut r, &cols.w, &t);
        let mut wsum = zero.clone();
        wsum.dot_add(&r, &vpx);
        let mut g = vec![a1.clone(); n];
        T::mul_add_slice(&mut g, &cols.v, &-a2x);
        T::mul_slice(&mut t, &r, &cols.v2);
        T::mul_slice(&mut r, &t, &g);
        let mut row = vec![zero; kk];
        for (cn, b) in r.iter().zip(bv.chunks_exact(kk)) {
            T::mul_add_slice(&mut row, b, cn);
        }
        let fx_coef = log_term - wsum;
        for (r, ph) in row.iter_mut().zip(&phi_x) {
            *r += ph.clone() * &a12 * &fx_coef - ph.clone() * &pc;
        }
        row
    }

    /// (U_y, U_x, U_y', U_x') at x0 > 0 of the load whose slope h = dS/dx, times the rule's
    /// weight, is `hw[i]` at the contour sample i; with the estimated absolute error.
    fn contour(&self, samples: &[Sample<T>], hw: &[T], x0: &T, tol: f64) -> ([T; 4], f64) {
        let out = self.contour_loads(samples, hw, None, &[], x0, tol);
        (out.fine, out.err)
    }

    /// [`Self::contour`] of the load `hw` together with (one y-integral, the kernels shared):
    /// * with `coarse`, the same load on the samples marked there, times 2 (the rule of step
    ///   2h of the level-doubling probe; its terms are the fine load's, summed apart);
    /// * the loads `hw + diffs[j]/v`, given through their differences from `hw` in f64, times
    ///   v (the product, not the factors, in f64: a slope times a weight next to the apex can
    ///   lie beyond f64's range): those differences are what is wanted of them (the degrees'
    ///   and the collocation sets' changes), and f64 carries them to 16 digits of themselves
    ///   (`docs/contour-sums.md`).
    ///
    /// The y-rule's convergence is tested on the load `hw` alone.
    fn contour_loads(
        &self,
        samples: &[Sample<T>],
        hw: &[T],
        coarse: Option<&[bool]>,
        diffs: &[Vec<f64>],
        x0: &T,
        tol: f64,
    ) -> ContourLoads<T> {
        let v: Vec<T> = samples.iter().map(|s| s.v.clone()).collect();
        let (class, classes) = match coarse {
            Some(c) => (c.iter().map(|&c| usize::from(c)).collect(), 2),
            None => (vec![0; v.len()], 1),
        };
        let terms = moment_terms(self.prec, v.len());
        let vhw: Vec<T> = v.iter().zip(hw).map(|(v, h)| v.clone() * h).collect();
        let sums = CauchySums::new(&v, &class, classes, &[&vhw], terms, &self.p);
        let v64: Vec<f64> = v.iter().map(|x| x.to_f64()).collect();
        let d64: Vec<&[f64]> = diffs.iter().map(|d| d.as_slice()).collect();
        let zeros = vec![0; v.len()];
        let sums64 = CauchySums::new(&v64, &zeros, 1, &d64, moment_terms(53, v.len()), &0.0);
        let lamb64 = Lamb::new(self.lamb.m().to_f64());
        let gamma64 = self.gamma.to_f64();
        let nd = diffs.len();
        let x064 = x0.to_f64();
        let y_scale = crate::kernels::y_scale(x0);
        let (y_lo, y_hi) = (y_scale.clone() * 2f64.powi(-60), y_scale * 2f64.powi(60));
        let (vals, err) =
            y_integral_checked(x0, 8 + 4 * nd, 4, tol, self.prec, |y, z, jac, out| {
                let zinv = z.clone().recip();
                let k = self.lamb.kernels(&zinv);
                let a = sums.at(&z);
                // class 0 (or all) and class 1 (the coarse level's nodes)
                let mut all = contour_integrand(&k, &a[0], &zinv, &self.gamma, y, jac);
                if classes == 2 {
                    let c = contour_integrand(&k, &a[1], &zinv, &self.gamma, y, jac);
                    for (j, (o, ci)) in all.iter_mut().zip(c).enumerate() {
                        out[4 + j] = ci.clone() * 2.0;
                        *o += &ci;
                    }
                }
                for (o, x) in out.iter_mut().zip(all) {
                    *o = x;
                }
                // the differences on the nodes within 2^60 of the y-scale (tails below: the
                // u-integrand is bounded, and the nodes beyond carry weights under 2^-60 of
                // the rule's, far under f64's 2^-53, while f64 could not hold their y, jac)
                let inside = *y > y_lo && *y < y_hi;
                if nd > 0 && inside {
                    let (y64, jac64) = (y.to_f64(), jac.to_f64());
                    let z64 = Cx::new(x064, y64);
                    let zinv64 = z64.clone().recip();
                    let k64 = lamb64.kernels(&zinv64);
                    for (j, s) in sums64.at(&z64).iter().enumerate() {
                        let u = contour_integrand(&k64, s, &zinv64, &gamma64, &y64, &jac64);
                        for (o, x) in out[8 + 4 * j..12 + 4 * j].iter_mut().zip(u) {
                            *o = x0.lit(x);
                        }
                    }
                }
            });
        let quad = |o: &[T]| -> [T; 4] { std::array::from_fn(|j| o[j].clone()) };
        ContourLoads {
            fine: quad(&vals[0..4]),
            coarse: coarse.map(|_| quad(&vals[4..8])),
            diffs: (0..nd)
                .map(|j| std::array::from_fn(|i| vals[8 + 4 * j + i].to_f64()))
                .collect(),
            err,
        }
    }

    /// The slope values h(v) w at the samples for coefficients `coef` of `basis`.
    fn weighted_slopes(&self, basis: &Basis<T>, samples: &[Sample<T>], coef: &[T]) -> Vec<T> {
        self.weighted_slopes_many(basis, samples, &[(basis, coef)])
            .pop()
            .unwrap_or_default()
    }

    /// [`Self::weighted_slopes`] for several coefficient sets, each of a basis that is a part of
    /// `full` (the same families, at most its degree): the basis is filled once per sample at
    /// the full degree, and each set sums its own columns (the values a fill at its degree
    /// gives, the Chebyshev recurrence being the same).
    fn weighted_slopes_many(
        &self,
        full: &Basis<T>,
        samples: &[Sample<T>],
        sets: &[(&Basis<T>, &[T])],
    ) -> Vec<Vec<T>> {
        let big = full.degree();
        debug_assert!(sets
            .iter()
            .all(|(b, _)| b.families() == full.families() && b.degree() <= big));
        let zero = self.p.zero();
        let mut buf = vec![zero.clone(); full.len()];
        let mut out = vec![Vec::with_capacity(samples.len()); sets.len()];
        for s in samples {
            full.fill(&s.fam, &s.t, &mut buf);
            for ((b, coef), o) in sets.iter().zip(out.iter_mut()) {
                let n = b.degree();
                let mut acc = zero.clone();
                for (vals, c) in buf.chunks_exact(big).zip(coef.chunks_exact(n)) {
                    acc.dot_add(&vals[..n], c);
                }
                o.push(acc * &s.w);
            }
        }
        out
    }

    /// The values of `basis` at the row samples, one row of `basis.len()` values per sample.
    fn basis_values(&self, basis: &Basis<T>, rows: &[Sample<T>]) -> Vec<T> {
        let kk = basis.len();
        let mut bv = vec![self.p.zero(); rows.len() * kk];
        for (s, out) in rows.iter().zip(bv.chunks_exact_mut(kk)) {
            basis.fill(&s.fam, &s.t, out);
        }
        bv
    }

    /// The collocation points of a fit of `basis` with the options `opts`.
    fn fit_points(&self, basis: &Basis<T>, opts: &SolveOptions) -> CollocationPoints<T> {
        let count = ((basis.len() as f64) * opts.oversample).ceil() as usize;
        self.collocation_points(count, opts.h_quad)
    }

    /// The collocation least-squares solve of `basis` (its values at the row samples `bv`) at
    /// the collocation points `pts` ([`Self::fit_points`]): coefficients normalised by the
    /// force moment, and the max residual of the scaled rows.
    fn fit(
        &self,
        basis: &Basis<T>,
        rows: &[Sample<T>],
        bv: &[T],
        cols: &RowColumns<T>,
        pts: &[(i64, T, T)],
        cache: &RowCache<T>,
    ) -> Result<(Vec<T>, f64)> {
        let kk = basis.len();
        let like = &self.p;
        let mpts = pts.len();
        if mpts < kk {
            return Err(GenuineError::NoConvergence {
                what: "collocation",
                detail: format!("{mpts} distinct points for {kk} unknowns: decrease h_quad"),
            });
        }
        let mut a = Matrix::zeros(mpts + 1, kk, like);
        for (i, (k, x, pmx)) in pts.iter().enumerate() {
            let row = cache.row(basis, *k, || self.sie_row(basis, x, pmx, rows, cols, bv));
            let norm = row
                .iter()
                .fold(like.zero(), |m, v| m.max(v.clone().abs()))
                .max(like.lit(1e-300));
            for (k, r) in row.into_iter().enumerate() {
                *a.get_mut(i, k) = r / &norm;
            }
        }
        // normalisation: the force moment Int_0^p v h dv = 1
        let mut nrow = vec![like.zero(); kk];
        for (s, b) in rows.iter().zip(bv.chunks_exact(kk)) {
            let wv = s.w.clone() * &s.v;
            T::mul_add_slice(&mut nrow, b, &wv);
        }
        let nn = nrow
            .iter()
            .fold(like.zero(), |m, v| m.max(v.clone().abs()))
            .max(like.lit(1e-300));
        let wgt = like.lit(1e3) / &nn;
        for (k, n) in nrow.into_iter().enumerate() {
            *a.get_mut(mpts, k) = n * &wgt;
        }
        let mut rhs = vec![like.zero(); mpts + 1];
        rhs[mpts] = like.lit(1e3);
        // column scaling
        let mut cs = Vec::with_capacity(kk);
        for k in 0..kk {
            let mut s = like.zero();
            for x in a.col(k) {
                s.mul_add_assign(x, x);
            }
            let n = s.sqrt().max(like.lit(1e-300));
            for x in a.col_mut(k) {
                *x /= &n;
            }
            cs.push(n);
        }
        let rcond = like.epsilon().to_f64() * 16.0;
        let (sol, _rank) = least_squares(&a, &rhs, rcond);
        let ax = a.mul_vec(&sol);
        let res = ax
            .iter()
            .zip(&rhs)
            .take(mpts)
            .fold(0.0_f64, |m, (u, v)| m.max((u.clone() - v).to_f64().abs()));
        let coef: Vec<T> = sol.into_iter().zip(&cs).map(|(s, c)| s / c).collect();
        Ok((coef, res))
    }

    /// The slope U_y' + beta U_x' at xs and V_hat = xs - (U_y + beta U_x)/slope, from the
    /// contour functionals `u` of an unscaled solution.
    fn slope_and_v_hat(&self, u: [T; 4], xs: &T) -> Result<(T, T)> {
        let [uy, ux, duy, dux] = u;
        let slope = duy + self.beta.clone() * &dux;
        let value = uy + self.beta.clone() * &ux;
        let usable = slope.clone().abs() > 0.0 && slope.is_finite();
        if !usable {
            return Err(GenuineError::NoConvergence {
                what: "collocation solve",
                detail: format!("degenerate slope at p = {}", self.p.to_f64()),
            });
        }
        let v_hat = xs.clone() - value / &slope;
        if !v_hat.is_finite() {
            return Err(GenuineError::NoConvergence {
                what: "collocation solve",
                detail: format!("non-finite V_hat at p = {}", self.p.to_f64()),
            });
        }
        Ok((slope, v_hat))
    }

    /// Scale the coefficients so that U_y' + beta U_x' = 1 at xs, from the contour
    /// functionals `u` of the unscaled solution, and return (slope, V_hat).
    fn normalise(&self, coef: &mut [T], u: [T; 4], xs: &T) -> Result<(T, T)> {
        let (slope, v_hat) = self.slope_and_v_hat(u, xs)?;
        coef.iter_mut().for_each(|c| *c /= &slope);
        Ok((slope, v_hat))
    }
}

impl<T: CachedRules> GenuineCase<T> {
    /// Solve the genuine contact problem for contact-zone speed p = alpha/c1 in (0, m_R), at
    /// the precision of `p` (f64, or the precision of a `rug::Float`). Use
    /// [`SolveOptions::for_precision`] for the options that match that precision.
    pub fn solve(
        material: &Material,
        indenter: &Indenter,
        p: T,
        opts: SolveOptions,
    ) -> Result<Self> {
        if opts.degree < 4 || opts.degree > 200 {
            return Err(invalid("degree", opts.degree, "4 ..= 200"));
        }
        if !(opts.oversample >= 1.0 && opts.oversample <= 10.0) {
            return Err(invalid("oversample", opts.oversample, "[1, 10]"));
        }
        if !(opts.h_quad > 0.0 && opts.h_quad <= 0.25) {
            return Err(invalid("h_quad", opts.h_quad, "(0, 0.25]"));
        }
        if !(opts.h_tanh > 0.0 && opts.h_tanh <= 1.0) {
            return Err(invalid("h_tanh", opts.h_tanh, "(0, 1]"));
        }
        let prob = Problem::new(material, indenter, p)?;
        // next to the Rayleigh speed the contour rule converges more slowly and the degrees'
        // convergence flattens into the least-squares plateau: a finer contour step and the
        // plateau probe there (see [`NEAR_RAYLEIGH`])
        let near = (prob.p.clone() / prob.ray.m_r()).to_f64() > NEAR_RAYLEIGH;
        let mut opts = opts;
        if near {
            opts.h_tanh *= NEAR_RAYLEIGH_STEP;
        }
        let basis = prob.basis(opts.degree, &opts);
        // the coarser sizes of the error estimates: N/2 and 3N/4 (see
        // [`GenuineCase::error_estimate`] and [`GenuineCase::apex_with_error`])
        let sizes = [opts.degree / 2, 3 * opts.degree / 4 / 2 * 2];
        let rows = prob.row_samples(&basis, opts.h_quad);
        let xs = prob.p.clone() * NORMALISATION_POINT;
        let (cont, on_coarse) = prob.contour_samples(&basis, &xs, opts.h_tanh);
        // the plateau probe: degree N on another collocation set (above f64, next to the
        // Rayleigh speed, and at every speed at double-double precision)
        let plateau = prob.prec > 64 && (near || prob.prec <= PLATEAU_EVERYWHERE_BITS);
        let other = SolveOptions {
            oversample: opts.oversample * 1.25,
            ..opts.clone()
        };
        let bv = prob.basis_values(&basis, &rows);
        let cols = RowColumns::new(&rows);
        // the fine basis's rows at the fine fit's and the plateau probe's points, computed
        // once on the available threads; the coarser degrees take theirs from there too
        let fine_points = prob.fit_points(&basis, &opts);
        // the fits besides the fine one: the coarser degrees, then the plateau probe
        let mut jobs: Vec<(Basis<T>, CollocationPoints<T>)> = sizes
            .iter()
            .map(|&n| {
                let b = prob.basis(n, &opts);
                let pts = prob.fit_points(&b, &opts);
                (b, pts)
            })
            .collect();
        if plateau {
            jobs.push((basis.clone(), prob.fit_points(&basis, &other)));
        }
        let mut points = fine_points.clone();
        if plateau {
            points.extend(jobs.last().map_or(&[][..], |j| &j.1[..]).iter().cloned());
            points.sort_unstable_by_key(|q| q.0);
            points.dedup_by_key(|q| q.0);
        }
        let cache = RowCache::new(&basis, &points, |x, pmx| {
            prob.sie_row(&basis, x, pmx, &rows, &cols, &bv)
        });
        // the fits are independent given the rows: the fine one, the coarser degrees and the
        // plateau probe's, solved in parallel (the same numbers as one after the other)
        let fine_job = || prob.fit(&basis, &rows, &bv, &cols, &fine_points, &cache);
        let other_jobs = || {
            use rayon::prelude::*;
            jobs.into_par_iter()
                .map(|(b, pts)| {
                    // a coarser basis is a part of the fine one: its values from the fine fill
                    let own;
                    let values = if b.families() != basis.families() {
                        own = prob.basis_values(&b, &rows);
                        &own
                    } else if b.degree() == basis.degree() {
                        &bv
                    } else {
                        own = leading_columns(&bv, basis.degree(), b.degree());
                        &own
                    };
                    let (c, r) = prob.fit(&b, &rows, values, &cols, &pts, &cache)?;
                    Ok((b, c, r))
                })
                .collect::<Result<Vec<_>>>()
        };
        let (fine_fit, fits) = rayon::join(fine_job, other_jobs);
        let (mut coef, residual) = fine_fit?;
        let fits = fits?;
        let mut sets = vec![(&basis, coef.as_slice())];
        sets.extend(fits.iter().map(|(b, c, _)| (b, c.as_slice())));
        let mut slopes = prob.weighted_slopes_many(&basis, &cont, &sets).into_iter();
        let hw = slopes.next().unwrap_or_default();
        // the other fits' loads through their differences from the fine one
        let diffs: Vec<Vec<f64>> = slopes
            .map(|other| {
                other
                    .into_iter()
                    .zip(&hw)
                    .zip(&cont)
                    .map(|((x, f), s)| ((x - f) * &s.v).to_f64())
                    .collect()
            })
            .collect();
        // the level-doubling probe of the v-rule: the fine load on the nodes of step 2h
        let loads = prob.contour_loads(&cont, &hw, Some(&on_coarse), &diffs, &xs, opts.contour_tol);
        let no_value = || GenuineError::NoConvergence {
            what: "contour",
            detail: "no value".into(),
        };
        let fine = loads.fine;
        let with_diff = |d: &[f64; 4]| -> [T; 4] {
            std::array::from_fn(|j| fine[j].clone() + prob.p.lit(d[j]))
        };
        let others: Vec<[T; 4]> = loads.diffs.iter().map(with_diff).collect();
        let (slope, v_hat) = prob.normalise(&mut coef, fine.clone(), &xs)?;
        let mut coarser = Vec::with_capacity(fits.len());
        for ((basis, mut coef, residual), u) in fits.into_iter().zip(others) {
            let (_, v_hat) = prob.normalise(&mut coef, u, &xs)?;
            coarser.push(Fit {
                basis,
                coef,
                v_hat,
                residual,
            });
        }
        let mut coarser = coarser.into_iter();
        let coarse = coarser.next().ok_or_else(no_value)?;
        let middle = coarser.next().ok_or_else(no_value)?;
        let other_points = if plateau {
            Some(coarser.next().ok_or_else(no_value)?)
        } else {
            None
        };
        let (slope_2h, v_hat_2h) = prob.slope_and_v_hat(loads.coarse.ok_or_else(no_value)?, &xs)?;
        let contour =
            ContourProbe::new(&slope, &v_hat, &slope_2h, &v_hat_2h, loads.err, &prob.beta);
        Ok(GenuineCase {
            prob,
            fit: Fit {
                basis,
                coef,
                v_hat,
                residual,
            },
            coarse,
            middle,
            other_points,
            contour,
            opts,
            apex: OnceLock::new(),
            force: OnceLock::new(),
        })
    }

    /// p = alpha/c1.
    pub fn p(&self) -> T {
        self.prob.p.clone()
    }
    /// The coupling beta (-cot Theta or 0).
    pub fn beta(&self) -> T {
        self.prob.beta.clone()
    }
    /// The friction coefficient gamma.
    pub fn gamma(&self) -> T {
        self.prob.gamma.clone()
    }
    /// cot Theta.
    pub fn cot_theta(&self) -> T {
        self.prob.cot_theta.clone()
    }
    /// The working precision in bits (53 for f64).
    pub fn precision_bits(&self) -> u32 {
        self.prob.prec
    }
    /// The options used.
    pub fn options(&self) -> &SolveOptions {
        &self.opts
    }
    /// The basis of the fine solve.
    pub fn basis(&self) -> &Basis<T> {
        &self.fit.basis
    }
    /// The coefficients of the fine solve (h = Sum_k c_k h_k, basis order of [`Basis::eval`]).
    pub fn coefficients(&self) -> &[T] {
        &self.fit.coef
    }
    /// Max residual of the scaled collocation rows.
    pub fn collocation_residual(&self) -> f64 {
        self.fit.residual
    }

    /// The contour probe's raw differences: |V_hat(h) - V_hat(2h)| and |slope(2h)/slope(h) - 1|
    /// of the v-rule of step h = `h_tanh` against its nodes of step 2h, and the y-rule's
    /// relative estimate.
    pub fn contour_probe(&self) -> (f64, f64, f64) {
        (
            self.contour.v_diff,
            self.contour.scale_diff,
            self.contour.y_rel,
        )
    }

    /// The differences between the degrees: |V_hat(N) - V_hat(3N/4)| and
    /// |V_hat(N) - V_hat(N/2)|,
    /// and, above f64, the difference from the fit of degree N on another collocation set.
    pub fn degree_differences(&self) -> (f64, f64, Option<f64>) {
        let d = |f: &Fit<T>| (self.fit.v_hat.clone() - &f.v_hat).abs().to_f64();
        (
            d(&self.middle),
            d(&self.coarse),
            self.other_points.as_ref().map(d),
        )
    }

    /// V/(c1 cot Theta).
    pub fn v_hat(&self) -> T {
        self.fit.v_hat.clone()
    }

    /// The (absolute) error estimate of V_hat, plus [`roundoff_floor`] |V_hat| of the working
    /// precision.
    ///
    /// In f64 it is d2 = |V_hat(N) - V_hat(N/2)|, which bounds the coarse solve. Above f64,
    /// where that bound can stay many digits above the error reached (1e-19 for an actual
    /// 2e-37 at 128 bits, gamma = 0), the geometric convergence in the degree is extrapolated
    /// from a third size: with d4 = |V_hat(N) - V_hat(3N/4)|, e(N) ~ d4^2/d2 (e(k) = C rho^(-k)
    /// through N/2 and 3N/4), taken with a factor 100 of margin, and only when the sizes
    /// converge (d4 <= d2/4); otherwise d2. Where the convergence flattens into the plateau
    /// of the least-squares solve's conditioning (next to the Rayleigh speed: at 128 bits,
    /// Theta 89 deg, gamma 0.6, p = 0.495, d2 = 1.9e-28, d4 = 3.1e-33 extrapolate to 5e-36
    /// for an actual 9e-34), the extrapolation is optimistic; above f64 a second fit of
    /// degree N on another collocation set (a quarter more points) measures that plateau:
    /// [`PLATEAU_MARGIN`] times the difference is added. The contour integrals' share comes
    /// from their own level-doubling probe and is added too.
    pub fn error_estimate(&self) -> f64 {
        let contour = self.contour.v_error(self.fit.v_hat.to_f64());
        self.estimate_of(true, contour, &self.fit.v_hat, |f| Ok(f.v_hat.clone()))
            .unwrap_or(f64::INFINITY)
    }

    /// The absolute error estimate of a quantity `fine` = q(fit of degree N), by the rule of
    /// [`Self::error_estimate`] applied to its values at degrees N, N/2 and 3N/4,
    /// plus the round-off floor times its magnitude. Without `extrapolate` the estimate above
    /// f64 is d4 = |q(N) - q(3N/4)| itself (it bounds the 3N/4 solve), and in f64 the larger
    /// of d2 and d4, both doubled: quantities taken at the ends of the contact (the apex
    /// amplitude) converge more slowly and less regularly in the degree than V, the
    /// extrapolation tuned on V can be optimistic for them, and in f64 the sizes stall near
    /// round-off, where one difference may happen to be small.
    fn estimate_of(
        &self,
        extrapolate: bool,
        contour: f64,
        fine: &T,
        q: impl Fn(&Fit<T>) -> Result<T>,
    ) -> Result<f64> {
        let d2 = (fine.clone() - q(&self.coarse)?).abs().to_f64();
        let floor = roundoff_floor(self.prob.prec) * fine.to_f64().abs();
        let high = self.prob.prec > 64;
        let d4 = (fine.clone() - q(&self.middle)?).abs().to_f64();
        let d = match (extrapolate, high) {
            (true, true) if d4 <= d2 / 4.0 && d2 > 0.0 => (100.0 * d4 * (d4 / d2)).min(d2),
            (true, _) => d2,
            (false, true) => 10.0 * d4.min(d2),
            (false, false) => 3.0 * d4.max(d2),
        };
        let plateau = match &self.other_points {
            Some(f) => PLATEAU_MARGIN * (fine.clone() - q(f)?).abs().to_f64(),
            None => 0.0,
        };
        Ok(d + floor + contour + plateau)
    }

    /// The relative error of the solution's scale from the contour integrals (every quantity
    /// proportional to the coefficients carries it).
    pub(crate) fn contour_scale_error(&self) -> f64 {
        self.contour.scale_error()
    }

    /// The contour integrals' share of the error of a quantity proportional to the solution's
    /// coefficients (their scale comes from the slope condition).
    fn scaled_contour_error(&self, q: &T) -> f64 {
        self.contour_scale_error() * q.to_f64().abs()
    }

    /// [`Self::force_hat`] with its absolute error estimate (the rule of
    /// [`Self::error_estimate`] applied to the force of each degree, extrapolated as V's).
    /// Computed once per case, then cached.
    pub fn force_hat_with_error(&self) -> (T, f64) {
        self.force
            .get_or_init(|| self.compute_force_with_error())
            .clone()
    }

    fn compute_force_with_error(&self) -> (T, f64) {
        let fine = self.force_hat();
        let err = self
            .estimate_of(true, self.scaled_contour_error(&fine), &fine, |f| {
                Ok(self.force_of(f))
            })
            .unwrap_or(f64::INFINITY);
        (fine, err)
    }

    /// [`Self::apex`] with the absolute error estimate of the amplitude (infinite when a
    /// coarser basis size gives no amplitude): the differences
    /// between the amplitudes of the degrees (not extrapolated), plus the round-off of the
    /// alternating sums that give the apex coefficients (the Chebyshev polynomials are (-1)^k
    /// at the apex): 8 units of the working precision times the amplitude built from |c_k|.
    /// Computed once per case, then cached.
    pub fn apex_with_error(&self) -> Result<(crate::apex::ApexExponents<T>, T, f64)> {
        self.apex
            .get_or_init(|| self.compute_apex_with_error())
            .clone()
    }

    fn compute_apex_with_error(&self) -> Result<(crate::apex::ApexExponents<T>, T, f64)> {
        let ex = self.exponents();
        let apex = self.apex_coefficients(&self.fit);
        let amp = self.amplitude_from(&ex, &self.fit, &apex)?;
        // a coarser size whose amplitude cannot be computed leaves no estimate (infinite)
        let degrees = self
            .estimate_of(false, self.scaled_contour_error(&amp), &amp, |f| {
                self.amplitude_from(&ex, f, &self.apex_coefficients(f))
            })
            .unwrap_or(f64::INFINITY);
        let lams = family_exponents(&ex, &self.fit.basis);
        let pf = self.prob.p.to_f64();
        let size: f64 = apex
            .iter()
            .zip(&lams)
            .enumerate()
            .map(|(fi, (ac, lam))| {
                let lam = lam.as_ref().map_or(1.0, |l| l.to_f64());
                let scale = match ex.kind {
                    wedge::ApexRegime::Power if fi == 0 => pf.powf(-lam) / lam.abs(),
                    wedge::ApexRegime::Logarithmic if fi == 0 => 1.0,
                    wedge::ApexRegime::Finite => pf.powf(-lam) / lam.abs(),
                    _ => 0.0,
                };
                ac.size * scale
            })
            .sum();
        let roundoff = 8.0 * 2f64.powi(-(self.prob.prec as i32)) * size;
        Ok((ex, amp, degrees + roundoff))
    }

    /// h(x) = dS/dx at 0 < x < p (p - x given exactly by the caller when known).
    pub fn h(&self, x: T, p_minus_x: T) -> T {
        Self::h_of(&self.fit, x, p_minus_x)
    }

    fn h_of(fit: &Fit<T>, x: T, p_minus_x: T) -> T {
        let mut buf = vec![x.zero(); fit.basis.len()];
        fit.basis.eval(&x, &p_minus_x, &mut buf);
        let mut acc = x.zero();
        for (a, b) in buf.iter().zip(&fit.coef) {
            acc.mul_add_assign(a, b);
        }
        acc
    }

    /// Tolerance and smallest step of the nested tanh-sinh rules of [`Self::stress_hat`] and
    /// [`Self::force_hat`]: 8 units in the last place; 2^-8 at 53 bits, halved once more per
    /// doubling of the precision.
    fn profile_rule(&self) -> (f64, f64, f64) {
        let prec = self.prob.prec;
        let tol = 8.0 * 2f64.powi(-(prec as i32));
        let e = self.prob.tail_exponent(&self.fit.basis);
        (
            tol,
            crate::kernels::contour_h_min(prec),
            crate::quad::t_max_for(prec, e),
        )
    }

    /// sigma_yy/(mu cot Theta) at x = r/(c1 t) in (0, p]: S(x) = -Int_x^p h.
    pub fn stress_hat(&self, x: T) -> Result<T> {
        let p = &self.prob.p;
        if !(x > 0.0 && x <= *p) {
            return Err(invalid(
                "x = r/(c1 t)",
                x.to_f64(),
                format!("(0, p] = (0, {}]", p.to_f64()),
            ));
        }
        if x == *p {
            return Ok(x.zero());
        }
        let (tol, hmin, tmax) = self.profile_rule();
        let (v, _) = integrate_vec(&x, p, 1, tol, hmin, tmax, |n, out| {
            out[0] = self.h(x.clone() + &n.from_a, n.to_b.clone());
        });
        Ok(-v[0].clone())
    }

    /// P/(alpha t mu cot Theta) = -(2/p) Int_0^p S dx = (2/p) Int_0^p x h(x) dx.
    pub fn force_hat(&self) -> T {
        self.force_of(&self.fit)
    }

    fn force_of(&self, fit: &Fit<T>) -> T {
        let p = &self.prob.p;
        let (tol, hmin, tmax) = self.profile_rule();
        let (v, _) = integrate_vec(&p.zero(), p, 1, tol, hmin, tmax, |n, out| {
            out[0] = n.from_a.clone() * Self::h_of(fit, n.from_a.clone(), n.to_b.clone());
        });
        v[0].clone() * 2.0 / p
    }

    /// (U_y, U_x, U_y', U_x') of the solution at x0 > 0, loaded through Lamb's kernels, with
    /// the estimated absolute quadrature error.
    pub fn displacement(&self, x0: T) -> Result<([T; 4], f64)> {
        self.displacement_with_step(x0, self.opts.h_tanh)
    }

    /// [`Self::displacement`] with the step `h` of the contour rule.
    fn displacement_with_step(&self, x0: T, h: f64) -> Result<([T; 4], f64)> {
        if !(x0 > 0.0 && x0.is_finite()) {
            return Err(invalid("x0", x0.to_f64(), "(0, inf)"));
        }
        let prob = &self.prob;
        let samples = if x0 < prob.p {
            prob.contour_samples(&self.fit.basis, &x0, h).0
        } else {
            // Outside the contact the v-integrand has no singularity at x0; the rule is split
            // at p/2, so that the edge singularity h ~ (p - v)^(-1/2 + Omega) keeps the
            // double-exponential end of the rule (a split at p would put the truncated
            // single-exponential end there and lose about delta^(1/2), 1e-10 in f64).
            prob.contour_samples(&self.fit.basis, &(prob.p.clone() / 2.0), h)
                .0
        };
        let hw = prob.weighted_slopes(&self.fit.basis, &samples, &self.fit.coef);
        Ok(prob.contour(&samples, &hw, &x0, self.opts.contour_tol))
    }

    /// The residual of (7), U_y + beta U_x + V_hat - x, at 0 < x0 < p, over V_hat.
    pub fn contact_residual(&self, x0: T) -> Result<T> {
        let (u, _) = self.displacement(x0.clone())?;
        let [uy, ux, _, _] = u;
        Ok((uy + self.prob.beta.clone() * ux + &self.fit.v_hat - x0) / &self.fit.v_hat)
    }

    /// The tangential particle velocity du_x/dt on the contact, over V, at 0 < x < p:
    /// (U_x - x U_x')/V_hat.
    pub fn slip_rate(&self, x: T) -> Result<T> {
        let p = &self.prob.p;
        if !(x > 0.0 && x < *p) {
            return Err(invalid(
                "x = r/(c1 t)",
                x.to_f64(),
                format!("(0, p) = (0, {})", p.to_f64()),
            ));
        }
        let (u, _) = self.displacement(x.clone())?;
        let [_, ux, _, dux] = u;
        Ok((ux - x * dux) / &self.fit.v_hat)
    }

    /// The slip direction (8) as the wedge crate states it (du_r/dt > 0, u_r = u_x on x > 0)
    /// at 8 sample points of the contact, with the smallest slip rate found there
    /// (infinite when gamma = 0, where (8) does not apply and nothing is sampled).
    pub fn slip_check(&self) -> Result<(bool, f64)> {
        if self.prob.gamma == 0.0 {
            return Ok((true, f64::INFINITY));
        }
        let mut min = f64::INFINITY;
        for i in 1..=8 {
            let x = self.prob.p.clone() * (i as f64) / 9.0;
            min = min.min(self.slip_rate(x)?.to_f64());
        }
        Ok((min > 0.0, min))
    }

    /// The normal gap outside the contact, g(x) = -V_hat + x - (U_y + beta U_x) at x0 > p (over
    /// c1 t cot Theta; the wedge crate's `Case::normal_gap` for the paper's construction),
    /// with its estimated absolute error (the contour quadrature's estimate, the change
    /// between the contour steps h and h/2, and the round-off floor times V_hat). g(p) = 0
    /// by (7).
    pub fn normal_gap(&self, x0: T) -> Result<(T, f64)> {
        let p = &self.prob.p;
        if !(x0 > *p && x0.is_finite()) {
            return Err(invalid(
                "x = r/(c1 t)",
                x0.to_f64(),
                format!("(p, inf) = ({}, inf)", p.to_f64()),
            ));
        }
        // Just outside the edge the kernels' pole at x0 sits next to the end p of the
        // v-rule: the gap is taken with the contour step halved, and the change from the
        // default step is added to its error estimate.
        let h = self.opts.h_tanh;
        let gap_at = |h: f64| -> Result<(T, f64)> {
            let (u, err) = self.displacement_with_step(x0.clone(), h)?;
            let [uy, ux, _, _] = u;
            let gap = x0.clone() - &self.fit.v_hat - uy - self.prob.beta.clone() * ux;
            Ok((gap, err * (1.0 + self.prob.beta.to_f64().abs())))
        };
        let (fine, err) = gap_at(h / 2.0)?;
        let (coarse, _) = gap_at(h)?;
        let change = (fine.clone() - coarse).abs().to_f64();
        let floor = roundoff_floor(self.prob.prec) * self.fit.v_hat.to_f64().abs();
        Ok((fine, err + change + floor))
    }

    /// Signorini outside the contact: the smallest normal gap at [`GAP_SAMPLES`] points of
    /// (p, 1) (evenly spread, p excluded), and whether it is >= -(its error estimate) there,
    /// i.e. no interpenetration.
    pub fn no_interpenetration(&self) -> Result<(bool, T)> {
        let p = self.prob.p.clone();
        let mut ok = true;
        let mut min_gap: Option<T> = None;
        for i in 1..=GAP_SAMPLES {
            let x = p.clone() + (p.one() - &p) * (i as f64) / (GAP_SAMPLES as f64 + 1.0);
            let (g, err) = self.normal_gap(x)?;
            ok &= g.to_f64() >= -err - self.error_estimate();
            min_gap = Some(match min_gap {
                Some(m) if m < g => m,
                _ => g,
            });
        }
        Ok((ok, min_gap.unwrap_or_else(|| p.zero())))
    }

    /// Signorini on the contact: S <= 0 at 32 sample points.
    pub fn contact_compressive(&self) -> Result<bool> {
        for i in 1..=32 {
            let x = self.prob.p.clone() * (i as f64) / 33.0;
            if self.stress_hat(x)? > 0.0 {
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// The apex exponents (eigen-equation roots) and the leading amplitude A in the paper's
    /// normalisation (eqs (41)-(43)): S ~ A (p/x)^(lambda_max) for a power singularity,
    /// S ~ A ln(2 p/x) + O(1) for a logarithmic apex, and for a finite apex the limit S(0+)
    /// ([`Self::finite_apex_limit`]).
    pub fn apex(&self) -> Result<(crate::apex::ApexExponents<T>, T)> {
        let ex = self.exponents();
        let amp = self.amplitude_from(&ex, &self.fit, &self.apex_coefficients(&self.fit))?;
        Ok((ex, amp))
    }

    pub(crate) fn exponents(&self) -> crate::apex::ApexExponents<T> {
        let prob = &self.prob;
        crate::apex::exponents(prob.ray.m().clone(), prob.beta.clone(), prob.gamma.clone())
    }

    /// The coefficients c_j of the apex behaviour h ~ c_j x^(-1 - lambda_j) of each family
    /// of `fit` (lambda_j the apex exponents at x = 0; the Chebyshev polynomials are
    /// (-1)^k at x = 0 and the edge factor is p^(Omega(0) - 1/2)), each with the size of its
    /// alternating sum (Sum |c_k| times the edge factor, for the round-off).
    fn apex_coefficients(&self, fit: &Fit<T>) -> Vec<ApexCoefficient<T>> {
        let p = &self.prob.p;
        let n = fit.basis.degree();
        let edge = p.clone().powf(&(fit.basis.omega(&p.zero()) - 0.5));
        fit.coef
            .chunks(n)
            .map(|family| {
                let mut c = p.zero();
                let mut size = 0.0;
                for (k, ck) in family.iter().enumerate() {
                    if k % 2 == 0 {
                        c += ck;
                    } else {
                        c -= ck;
                    }
                    size += ck.to_f64().abs();
                }
                ApexCoefficient {
                    c: c * &edge,
                    size: size * edge.to_f64().abs(),
                }
            })
            .collect()
    }

    fn amplitude_from(
        &self,
        ex: &crate::apex::ApexExponents<T>,
        fit: &Fit<T>,
        apex: &[ApexCoefficient<T>],
    ) -> Result<T> {
        Ok(match ex.kind {
            // S ~ -(c/lambda) x^(-lambda) = A (p/x)^lambda
            wedge::ApexRegime::Power => {
                let lam = &ex.lambdas[0];
                -(apex[0].c.clone() / lam) * self.prob.p.clone().powf(&-lam.clone())
            }
            // S ~ c ln x + const = -c ln(2 p/x) + const
            wedge::ApexRegime::Logarithmic => -apex[0].c.clone(),
            wedge::ApexRegime::Finite => self.finite_apex_limit_of(ex, fit, apex)?,
        })
    }

    /// For a finite apex (every lambda_j < 0), the limit S(0+) = -Int_0^p h dx, integrated
    /// with the apex behaviour of each family subtracted and added back in closed form:
    /// S(0+) = -Int_0^p (h - Sum_j c_j x^(-1 - lambda_j)) dx - Sum_j c_j p^(-lambda_j)/(-lambda_j)
    /// (`docs/errata.md`, section 9: the stress approaches its limit like x^(-lambda_j),
    /// which for lambda_j near 0 is far from the limit at any sampled x).
    pub fn finite_apex_limit(&self) -> Result<T> {
        let ex = self.exponents();
        let apex = self.apex_coefficients(&self.fit);
        self.finite_apex_limit_of(&ex, &self.fit, &apex)
    }

    fn finite_apex_limit_of(
        &self,
        ex: &crate::apex::ApexExponents<T>,
        fit: &Fit<T>,
        apex: &[ApexCoefficient<T>],
    ) -> Result<T> {
        let p = &self.prob.p;
        let lams = family_exponents(ex, &fit.basis);
        let c: Vec<&T> = apex.iter().map(|a| &a.c).collect();
        if let Some(bad) = lams
            .iter()
            .flatten()
            .find(|l| l.to_f64().is_nan() || l.to_f64() >= 0.0)
        {
            return Err(GenuineError::NoConvergence {
                what: "finite apex limit",
                detail: format!("an apex exponent {} is not negative", bad.to_f64()),
            });
        }
        let (tol, hmin, tmax) = self.profile_rule();
        let (v, _) = integrate_vec(&p.zero(), p, 1, tol, hmin, tmax, |n, out| {
            let x = &n.from_a;
            let mut r = Self::h_of(fit, x.clone(), n.to_b.clone());
            for (cj, lj) in c.iter().zip(&lams) {
                if let Some(l) = lj {
                    r -= (*cj).clone() * x.clone().powf(&(-(l.clone() + 1.0)));
                }
            }
            out[0] = r;
        });
        let mut s = -v[0].clone();
        for (cj, lj) in c.iter().zip(&lams) {
            if let Some(l) = lj {
                s -= (*cj).clone() * p.clone().powf(&(-l.clone())) / (-l.clone());
            }
        }
        if !s.is_finite() {
            return Err(GenuineError::NoConvergence {
                what: "finite apex limit",
                detail: format!("not finite at p = {}", p.to_f64()),
            });
        }
        Ok(s)
    }
}

/// Load a half-plane with an arbitrary even contact pressure S on |x| < p (given through its
/// slope h = dS/dx on (0, p), a function of (x, p - x)) and the shear -sgn(x) gamma S, and
/// return (U_y, U_x, U_y', U_x') at x0 > 0 through Lamb's kernels (units c1 = mu = 1, m = c2/c1),
/// at the precision of `p`. The v-rule is the mixed rule of the solver with the default step
/// for that precision, reaching offsets of 2^(-3 bits) at the ends 0 and p (endpoint powers
/// down to -2/3). Used to check any solution of the contact problem, the paper's included,
/// independently of how it was obtained.
pub fn load_through_kernels<T, H>(m: T, p: T, gamma: T, x0: T, h: H) -> Result<[T; 4]>
where
    T: Real,
    H: Fn(T, T) -> T,
{
    if !(p > 0.0 && p.is_finite()) {
        return Err(invalid("p", p.to_f64(), "(0, inf)"));
    }
    if !(x0 > 0.0 && x0.is_finite()) {
        return Err(invalid("x0", x0.to_f64(), "(0, inf)"));
    }
    let prec = p.prec();
    let opts = SolveOptions::for_precision(prec);
    let split = if x0 < p { x0.clone() } else { p.clone() };
    let unit = crate::quad::se_de_unit(&p, opts.h_tanh, v_rule_s_max(prec), prec, 1.0 / 3.0);
    let mut samples = Vec::with_capacity(2 * unit.len());
    let mut hw = Vec::with_capacity(2 * unit.len());
    let left = split.clone();
    let right = p.clone() - &split;
    for u in &unit {
        let d_x0 = u.from_a.clone() * &left;
        let d_0 = u.to_b.clone() * &left;
        let v = if d_0 < d_x0 {
            d_0
        } else {
            split.clone() - &d_x0
        };
        let pv = right.clone() + &d_x0;
        let w = u.w.clone() * &left;
        hw.push(h(v.clone(), pv.clone()) * &w);
        samples.push(Sample {
            v,
            pv,
            w,
            fam: vec![],
            t: p.zero(),
        });
        if right > 0.0 {
            let d_x0 = u.from_a.clone() * &right;
            let d_p = u.to_b.clone() * &right;
            let v = if d_x0 < d_p {
                split.clone() + &d_x0
            } else {
                p.clone() - &d_p
            };
            let w = u.w.clone() * &right;
            hw.push(h(v.clone(), d_p.clone()) * &w);
            samples.push(Sample {
                v,
                pv: d_p,
                w,
                fam: vec![],
                t: p.zero(),
            });
        }
    }
    let prob = Problem {
        beta: p.zero(),
        gamma,
        cot_theta: p.zero(),
        ray: Rayleigh::new(m.clone())?,
        lamb: Lamb::new(m),
        prec,
        p,
    };
    let (u, _) = prob.contour(&samples, &hw, &x0, opts.contour_tol);
    Ok(u)
}
