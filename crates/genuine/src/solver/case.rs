//! The solved case [`GenuineCase`]: the solve at the fine and the coarser degrees, the
//! solution's values (V_hat, the stress, the force, the apex behaviour) and their error
//! estimates.

use std::sync::OnceLock;

use complexfn::quadrature::CachedRules;
use complexfn::Real;
use wedge::{Indenter, Material};

use super::collocation::*;
use super::options::*;
use crate::basis::Basis;
use crate::error::{invalid, GenuineError, Result};
use crate::quad::integrate_vec;

/// The apex coefficient c_j of one family (h ~ c_j x^(-1 - lambda_j)) and the size of the
/// alternating sum that gives it.
pub(super) struct ApexCoefficient<T> {
    pub(super) c: T,
    pub(super) size: f64,
}

/// The apex exponent lambda_j of each family of `basis` (`None` for the logarithmic and the
/// regular families).
pub(super) fn family_exponents<T: Real>(
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

/// The error of the contour integrals behind the scale of the solution (the slope condition
/// U_y' + beta U_x' = 1 at x*) and V_hat, from the level-doubling probe of their v-rule (the
/// same load summed on the nodes of step 2h) and the y-rule's own estimate.
#[derive(Clone, Copy, Debug)]
pub(super) struct ContourProbe {
    /// |V_hat(h) - V_hat(2h)|.
    pub(super) v_diff: f64,
    /// |slope(2h)/slope(h) - 1|.
    pub(super) scale_diff: f64,
    /// The y-rule's estimated error of the slope and of V_hat, relative to the slope.
    pub(super) y_rel: f64,
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
    pub(super) fn extrapolate(d: f64, size: f64) -> f64 {
        if size > 0.0 && d * CONTOUR_MARGIN < size {
            CONTOUR_MARGIN * d * d / size
        } else {
            d
        }
    }

    /// The absolute error of V_hat (of size `v`) from the contour integrals.
    pub(super) fn v_error(&self, v: f64) -> f64 {
        Self::extrapolate(self.v_diff, v.abs()) + self.y_rel * (1.0 + v.abs())
    }

    /// The relative error of the solution's scale (of every quantity proportional to the
    /// coefficients) from the contour integrals.
    pub(super) fn scale_error(&self) -> f64 {
        Self::extrapolate(self.scale_diff, 1.0) + self.y_rel
    }

    pub(super) fn new<T: Real>(
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

/// The solved genuine case, at the precision of the contact speed it was solved for (`f64` by
/// default).
#[derive(Clone, Debug)]
pub struct GenuineCase<T = f64> {
    pub(super) prob: Problem<T>,
    pub(super) fit: Fit<T>,
    /// The solve at degree N/2.
    pub(super) coarse: Fit<T>,
    /// The solve at degree 3N/4.
    pub(super) middle: Fit<T>,
    /// Above f64 (next to the Rayleigh speed, or at every speed up to
    /// [`PLATEAU_EVERYWHERE_BITS`]): the solve at degree N on another collocation set (a
    /// quarter more points).
    pub(super) other_points: Option<Fit<T>>,
    /// The error of the contour rule behind the slope and V_hat.
    pub(super) contour: ContourProbe,
    pub(super) opts: SolveOptions,
    /// The apex exponents, amplitude and its estimate ([`GenuineCase::apex_with_error`]),
    /// computed once on demand.
    pub(super) apex: OnceLock<Result<(crate::apex::ApexExponents<T>, T, f64)>>,
    /// The force and its estimate ([`GenuineCase::force_hat_with_error`]), computed once on
    /// demand.
    pub(super) force: OnceLock<(T, f64)>,
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
        let no_value = || GenuineError::SolveFailed {
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
    pub(super) fn estimate_of(
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
    pub(super) fn scaled_contour_error(&self, q: &T) -> f64 {
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

    pub(super) fn compute_force_with_error(&self) -> (T, f64) {
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

    pub(super) fn compute_apex_with_error(
        &self,
    ) -> Result<(crate::apex::ApexExponents<T>, T, f64)> {
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

    pub(super) fn h_of(fit: &Fit<T>, x: T, p_minus_x: T) -> T {
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
    pub(super) fn profile_rule(&self) -> (f64, f64, f64) {
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

    pub(super) fn force_of(&self, fit: &Fit<T>) -> T {
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
    pub(super) fn displacement_with_step(&self, x0: T, h: f64) -> Result<([T; 4], f64)> {
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
    pub(super) fn apex_coefficients(&self, fit: &Fit<T>) -> Vec<ApexCoefficient<T>> {
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

    pub(super) fn amplitude_from(
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

    pub(super) fn finite_apex_limit_of(
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
            return Err(GenuineError::SolveFailed {
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
            return Err(GenuineError::SolveFailed {
                what: "finite apex limit",
                detail: format!("not finite at p = {}", p.to_f64()),
            });
        }
        Ok(s)
    }
}
