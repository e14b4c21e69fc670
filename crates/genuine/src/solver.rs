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
//! The least-squares solve (SVD) of the collocation rows and the weighted normalisation row
//! gives the coefficients; the error estimate is |V_hat(N) - V_hat(N/2)|.

use complexfn::{Rayleigh, Side};
use nalgebra::{DMatrix, DVector};
use wedge::{Coupling, Indenter, Material};

use crate::basis::Basis;
use crate::error::{invalid, GenuineError, Result};
use crate::kernels::{Lamb, C64};
use crate::quad::{integrate_vec, nodes, tanh_rule};

/// Where (as a fraction of p) the slope U_y' + beta U_x' = 1 and V_hat are taken from the
/// contour representation: an interior point, where the y-integrand is smooth (at the edge it
/// carries y^(-1/2 + Omega) and converges slowly).
pub const NORMALISATION_POINT: f64 = 0.5;

/// Relative floor added to the error estimate: the level to which the collocation rows and the
/// contour integrals are converged (measured residuals of (7) are 1e-15 to 1e-14).
pub const ROUNDOFF_FLOOR: f64 = 1e-13;

/// Truncation of the tanh rule behind the F-functions: offsets down to e^(-100) of the interval.
pub const V_RULE_S_MAX: f64 = 100.0;

/// Options of the solve.
#[derive(Clone, Debug)]
pub struct SolveOptions {
    /// Chebyshev polynomials per basis family (the error estimate uses half as many).
    pub degree: usize,
    /// Add the family without apex factor (default: only when gamma > 0).
    pub regular_family: Option<bool>,
    /// Collocation points per unknown (>= 1).
    pub oversample: f64,
    /// Step of the tanh-sinh rules in the collocation rows and in the F-functions.
    pub h_quad: f64,
    /// Relative tolerance of the contour integrals.
    pub contour_tol: f64,
    /// Replace the apex families by fixed exponents (S ~ x^(-lambda)); for diagnostics only
    /// (the default, `None`, uses the roots of the eigen-equation with their x-variation).
    pub apex_lambdas: Option<Vec<f64>>,
    /// Step of the tanh rule in the F-functions of the contour integrals (error ~ exp(-pi^2/h)).
    pub h_tanh: f64,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions {
            degree: 24,
            regular_family: None,
            oversample: 2.0,
            h_quad: 1.0 / 32.0,
            contour_tol: 1e-14,
            h_tanh: 0.25,
            apex_lambdas: None,
        }
    }
}

/// Everything that defines one case (shared by the two basis sizes).
#[derive(Clone, Debug)]
struct Problem {
    p: f64,
    beta: f64,
    gamma: f64,
    cot_theta: f64,
    ray: Rayleigh<f64>,
    lamb: Lamb,
}

/// One collocation solve.
#[derive(Clone, Debug)]
struct Fit {
    basis: Basis,
    coef: Vec<f64>,
    v_hat: f64,
    residual: f64,
}

/// The solved genuine case.
#[derive(Clone, Debug)]
pub struct GenuineCase {
    prob: Problem,
    fit: Fit,
    coarse_v_hat: f64,
    opts: SolveOptions,
}

impl Problem {
    fn new(material: &Material, indenter: &Indenter, p: f64) -> Result<Self> {
        let m = material.c2().value() / material.c1().value();
        let ray = Rayleigh::new(m)?;
        let m_r = *ray.m_r();
        if !(p.is_finite() && p > 0.0 && p < m_r) {
            return Err(invalid("p = alpha/c1", p, format!("(0, m_R) = (0, {m_r})")));
        }
        let th = indenter.theta_deg().value().to_radians();
        let cot_theta = th.cos() / th.sin();
        let gamma = indenter.gamma().value();
        let beta = match indenter.coupling() {
            Coupling::On => -cot_theta,
            Coupling::Off => 0.0,
        };
        Ok(Problem {
            p,
            beta,
            gamma,
            cot_theta,
            ray,
            lamb: Lamb::new(m),
        })
    }

    /// Nodes of the tanh rule on (0, p), split at x0 (if inside), as (v, p - v, weight).
    fn v_nodes(&self, x0: f64, h: f64) -> Vec<(f64, f64, f64)> {
        let p = self.p;
        let smax = V_RULE_S_MAX;
        if x0 > 0.0 && x0 < p {
            let mut out: Vec<(f64, f64, f64)> = tanh_rule(0.0, x0, h, smax)
                .into_iter()
                .map(|n| (n.v, (p - x0) + n.to_b, n.w))
                .collect();
            out.extend(
                tanh_rule(x0, p, h, smax)
                    .into_iter()
                    .map(|n| (x0 + n.from_a, n.to_b, n.w)),
            );
            out
        } else {
            tanh_rule(0.0, p, h, smax)
                .into_iter()
                .map(|n| (n.v, n.to_b, n.w))
                .collect()
        }
    }

    /// The collocation row of the singular integral equation at x in (0, p).
    fn sie_row(&self, basis: &Basis, x: f64, h: f64) -> Vec<f64> {
        let p = self.p;
        let kk = basis.len();
        let vals = self.ray.at_boundary(&x, Side::Lower);
        let (p1, p2, l_s) = (vals.p1.re, vals.p2.re, vals.l_over_s.re);
        let m2 = *self.ray.m2();
        let a1 = 1.0 / p1;
        let a2 = self.gamma * self.beta / p2;
        let c = m2 * l_s / (p1 * p2);
        let mut phi_x = vec![0.0; kk];
        basis.eval(x, p - x, &mut phi_x);
        let fx: Vec<f64> = phi_x.iter().map(|v| v * (a1 - a2)).collect();
        let mut row: Vec<f64> = (0..kk)
            .map(|k| {
                fx[k] * ((p - x) / x).ln()
                    - std::f64::consts::PI * (self.beta + self.gamma) * c * phi_x[k]
            })
            .collect();
        let mut buf = vec![0.0; kk];
        let mut add = |v: f64, pv: f64, dv: f64, w: f64| {
            // dv = v - x, exact
            basis.eval(v, pv, &mut buf);
            let fac = 2.0 * v / (v + x) * (a1 - a2 * v / x);
            for k in 0..kk {
                let f = buf[k] * fac;
                row[k] += w * (f - fx[k]) / dv;
            }
        };
        for n in nodes(0.0, x, h) {
            add(n.v, (p - x) + n.to_b, -n.to_b, n.w);
        }
        for n in nodes(x, p, h) {
            add(x + n.from_a, n.to_b, n.from_a, n.w);
        }
        row
    }

    /// For every basis function: (U_y, U_x, U_y', U_x') at x0 > 0 from the contour
    /// representation, with the estimated absolute error of the y-integral.
    fn contour_rows(&self, basis: &Basis, x0: f64, h_tanh: f64, tol: f64) -> (Vec<[f64; 4]>, f64) {
        let vn = self.v_nodes(x0, h_tanh);
        contour_rows_with(
            &self.lamb,
            self.gamma,
            &vn,
            basis.len(),
            x0,
            tol,
            |v, pv, out| basis.eval(v, pv, out),
        )
    }

    fn fit(&self, degree: usize, opts: &SolveOptions) -> Result<Fit> {
        let regular = opts.regular_family.unwrap_or(self.gamma > 0.0);
        let basis = Basis::new(
            self.ray.clone(),
            self.p,
            self.beta,
            self.gamma,
            degree,
            regular,
            opts.apex_lambdas.as_deref(),
        );
        let kk = basis.len();
        let mpts = ((kk as f64) * opts.oversample).ceil() as usize;
        let mut a = DMatrix::<f64>::zeros(mpts + 1, kk);
        for i in 0..mpts {
            let th = std::f64::consts::PI * (i as f64 + 0.5) / mpts as f64;
            let x = self.p * (1.0 - th.cos()) / 2.0;
            let row = self.sie_row(&basis, x, opts.h_quad);
            let norm = row.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(1e-300);
            for k in 0..kk {
                a[(i, k)] = row[k] / norm;
            }
        }
        let xs = NORMALISATION_POINT * self.p;
        let (edge, _) = self.contour_rows(&basis, xs, opts.h_tanh, opts.contour_tol);
        let nrow: Vec<f64> = edge.iter().map(|r| r[2] + self.beta * r[3]).collect();
        let nn = nrow.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(1e-300);
        let wgt = 1e3 / nn;
        for k in 0..kk {
            a[(mpts, k)] = nrow[k] * wgt;
        }
        let mut rhs = DVector::<f64>::zeros(mpts + 1);
        rhs[mpts] = wgt;
        // column scaling
        let mut cs = vec![0.0; kk];
        for k in 0..kk {
            let n = a.column(k).norm().max(1e-300);
            cs[k] = n;
            for i in 0..=mpts {
                a[(i, k)] /= n;
            }
        }
        let svd = a.clone().svd(true, true);
        let smax = svd.singular_values.max();
        let sol = svd
            .solve(&rhs, smax * 1e-15)
            .map_err(|e| GenuineError::NoConvergence {
                what: "collocation least squares",
                detail: e.to_string(),
            })?;
        let res = (&a * &sol - &rhs).rows(0, mpts).amax();
        let coef: Vec<f64> = (0..kk).map(|k| sol[k] / cs[k]).collect();
        let uy: f64 = edge.iter().zip(&coef).map(|(r, c)| r[0] * c).sum();
        let ux: f64 = edge.iter().zip(&coef).map(|(r, c)| r[1] * c).sum();
        let v_hat = xs - uy - self.beta * ux;
        if !v_hat.is_finite() {
            return Err(GenuineError::NoConvergence {
                what: "collocation solve",
                detail: format!("non-finite V_hat at p = {}", self.p),
            });
        }
        Ok(Fit {
            basis,
            coef,
            v_hat,
            residual: res,
        })
    }
}

impl GenuineCase {
    /// Solve the genuine contact problem for contact-zone speed p = alpha/c1 in (0, m_R).
    pub fn solve(
        material: &Material,
        indenter: &Indenter,
        p: f64,
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
        let prob = Problem::new(material, indenter, p)?;
        let fit = prob.fit(opts.degree, &opts)?;
        let coarse = prob.fit(opts.degree / 2, &opts)?;
        Ok(GenuineCase {
            prob,
            fit,
            coarse_v_hat: coarse.v_hat,
            opts,
        })
    }

    /// p = alpha/c1.
    pub fn p(&self) -> f64 {
        self.prob.p
    }
    /// The coupling beta (-cot Theta or 0).
    pub fn beta(&self) -> f64 {
        self.prob.beta
    }
    /// The friction coefficient gamma.
    pub fn gamma(&self) -> f64 {
        self.prob.gamma
    }
    /// cot Theta.
    pub fn cot_theta(&self) -> f64 {
        self.prob.cot_theta
    }
    /// The options used.
    pub fn options(&self) -> &SolveOptions {
        &self.opts
    }
    /// The basis of the fine solve.
    pub fn basis(&self) -> &Basis {
        &self.fit.basis
    }
    /// Max residual of the scaled collocation rows.
    pub fn collocation_residual(&self) -> f64 {
        self.fit.residual
    }

    /// V/(c1 cot Theta).
    pub fn v_hat(&self) -> f64 {
        self.fit.v_hat
    }

    /// |V_hat(N) - V_hat(N/2)| + [`ROUNDOFF_FLOOR`] |V_hat|, the error estimate of V_hat from two
    /// basis sizes.
    pub fn error_estimate(&self) -> f64 {
        (self.fit.v_hat - self.coarse_v_hat).abs() + ROUNDOFF_FLOOR * self.fit.v_hat.abs()
    }

    /// h(x) = dS/dx at 0 < x < p (p - x given exactly by the caller when known).
    pub fn h(&self, x: f64, p_minus_x: f64) -> f64 {
        let mut buf = vec![0.0; self.fit.basis.len()];
        self.fit.basis.eval(x, p_minus_x, &mut buf);
        buf.iter().zip(&self.fit.coef).map(|(a, b)| a * b).sum()
    }

    /// sigma_yy/(mu cot Theta) at x = r/(c1 t) in (0, p]: S(x) = -Int_x^p h.
    pub fn stress_hat(&self, x: f64) -> Result<f64> {
        let p = self.prob.p;
        if !(x > 0.0 && x <= p) {
            return Err(invalid("x = r/(c1 t)", x, format!("(0, p] = (0, {p}]")));
        }
        if x == p {
            return Ok(0.0);
        }
        let (v, _) = integrate_vec(x, p, 1, 1e-15, 1.0 / 256.0, |n, out| {
            out[0] = self.h(x + n.from_a, n.to_b);
        });
        Ok(-v[0])
    }

    /// P/(alpha t mu cot Theta) = -(2/p) Int_0^p S dx = (2/p) Int_0^p x h(x) dx.
    pub fn force_hat(&self) -> f64 {
        let p = self.prob.p;
        let (v, _) = integrate_vec(0.0, p, 1, 1e-15, 1.0 / 256.0, |n, out| {
            out[0] = n.from_a * self.h(n.from_a, n.to_b);
        });
        2.0 * v[0] / p
    }

    /// (U_y, U_x, U_y', U_x') of the solution at x0 > 0, loaded through Lamb's kernels, with
    /// the estimated absolute quadrature error.
    pub fn displacement(&self, x0: f64) -> Result<([f64; 4], f64)> {
        if !(x0 > 0.0 && x0.is_finite()) {
            return Err(invalid("x0", x0, "(0, inf)"));
        }
        let (rows, err) =
            self.prob
                .contour_rows(&self.fit.basis, x0, self.opts.h_tanh, self.opts.contour_tol);
        let mut u = [0.0; 4];
        for (r, c) in rows.iter().zip(&self.fit.coef) {
            for j in 0..4 {
                u[j] += r[j] * c;
            }
        }
        let cmax = self.fit.coef.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
        Ok((u, err * cmax))
    }

    /// The residual of (7), U_y + beta U_x + V_hat - x, at 0 < x0 < p, over V_hat.
    pub fn contact_residual(&self, x0: f64) -> Result<f64> {
        let (u, _) = self.displacement(x0)?;
        Ok((u[0] + self.prob.beta * u[1] + self.fit.v_hat - x0) / self.fit.v_hat)
    }

    /// The tangential particle velocity du_x/dt on the contact, over V, at 0 < x < p:
    /// (U_x - x U_x')/V_hat.
    pub fn slip_rate(&self, x: f64) -> Result<f64> {
        let p = self.prob.p;
        if !(x > 0.0 && x < p) {
            return Err(invalid("x = r/(c1 t)", x, format!("(0, p) = (0, {p})")));
        }
        let (u, _) = self.displacement(x)?;
        Ok((u[1] - x * u[3]) / self.fit.v_hat)
    }

    /// The slip direction (8) as the wedge crate states it (du_r/dt > 0, u_r = u_x on x > 0)
    /// at 8 sample points of the contact; true when gamma = 0.
    pub fn slip_direction_ok(&self) -> Result<bool> {
        if self.prob.gamma == 0.0 {
            return Ok(true);
        }
        for i in 1..=8 {
            if self.slip_rate(self.prob.p * i as f64 / 9.0)? <= 0.0 {
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// Signorini on the contact: S <= 0 at 32 sample points.
    pub fn contact_compressive(&self) -> Result<bool> {
        for i in 1..=32 {
            if self.stress_hat(self.prob.p * i as f64 / 33.0)? > 0.0 {
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// The apex exponents (eigen-equation roots) and the leading amplitude A of
    /// S ~ A x^(-lambda_max) (for the logarithmic case S ~ A ln x; for a finite apex the
    /// limit S(0+), estimated from S at x = 1e-8 p).
    pub fn apex(&self) -> (crate::apex::ApexExponents, f64) {
        let ex = crate::apex::exponents(*self.prob.ray.m(), self.prob.beta, self.prob.gamma);
        let p = self.prob.p;
        let n = self.fit.basis.degree();
        // amplitude of h ~ C x^(-1-lambda) of the first family at x -> 0
        let omega0 = self.fit.basis.omega(0.0);
        let c: f64 = (0..n)
            .map(|k| self.fit.coef[k] * if k % 2 == 0 { 1.0 } else { -1.0 })
            .sum::<f64>()
            * p.powf(-0.5 + omega0);
        let amp = match ex.kind {
            crate::apex::ApexKind::Power => -c / ex.lambdas[0],
            crate::apex::ApexKind::Logarithmic => c,
            crate::apex::ApexKind::Finite => self.stress_hat(1e-8 * p).unwrap_or(f64::NAN),
        };
        (ex, amp)
    }

    /// The contact speed p whose genuine V/(c1 cot Theta) equals `v_hat`, searched in
    /// [p_lo, p_hi] (inside (0, m_R)) by secant steps safeguarded by bisection.
    pub fn for_speed(
        material: &Material,
        indenter: &Indenter,
        v_hat: f64,
        p_lo: f64,
        p_hi: f64,
        opts: SolveOptions,
    ) -> Result<Self> {
        let f = |p: f64| -> Result<(f64, GenuineCase)> {
            let c = GenuineCase::solve(material, indenter, p, opts.clone())?;
            Ok((c.v_hat() - v_hat, c))
        };
        let (mut a, mut b) = (p_lo, p_hi);
        let (mut fa, _) = f(a)?;
        let (mut fb, mut cb) = f(b)?;
        if fa.signum() == fb.signum() {
            return Err(invalid(
                "v_hat",
                v_hat,
                format!(
                    "between V_hat(p_lo) = {} and V_hat(p_hi) = {}",
                    fa + v_hat,
                    fb + v_hat
                ),
            ));
        }
        for _ in 0..60 {
            let mut x = b - fb * (b - a) / (fb - fa);
            if !(x > a.min(b) && x < a.max(b)) {
                x = 0.5 * (a + b);
            }
            let (fx, cx) = f(x)?;
            if fx.abs() <= 1e-13 * v_hat.abs() || (b - a).abs() < 1e-15 {
                return Ok(cx);
            }
            if fx.signum() == fa.signum() {
                a = x;
                fa = fx;
            } else {
                b = x;
                fb = fx;
                cb = cx;
            }
            // keep the secant well-conditioned: Illinois step
            if fx.signum() == fb.signum() {
                fa *= 0.5;
            }
        }
        let _ = cb;
        Err(GenuineError::NoConvergence {
            what: "inverse p(V)",
            detail: format!("no root for v_hat = {v_hat} in [{p_lo}, {p_hi}]"),
        })
    }
}

/// (U_y, U_x, U_y', U_x') at x0 for each of `kk` slopes h_k(v) = dS_k/dx on (0, p) (S_k even,
/// shear -sgn(x) gamma S_k), given the v-nodes (v, p - v, weight); the y-integral by
/// tanh-sinh to `tol`. Returns the rows and the estimated absolute error.
fn contour_rows_with<E>(
    lamb: &Lamb,
    gamma: f64,
    vn: &[(f64, f64, f64)],
    kk: usize,
    x0: f64,
    tol: f64,
    eval: E,
) -> (Vec<[f64; 4]>, f64)
where
    E: Fn(f64, f64, &mut [f64]),
{
    let mut hv = vec![0.0; kk * vn.len()];
    for (i, &(v, pv, w)) in vn.iter().enumerate() {
        eval(v, pv, &mut hv[i * kk..(i + 1) * kk]);
        hv[i * kk..(i + 1) * kk].iter_mut().for_each(|x| *x *= w);
    }
    let scale = x0.abs().max(0.05);
    let mut fy = vec![C64::new(0.0, 0.0); kk];
    let mut fxv = vec![C64::new(0.0, 0.0); kk];
    let (vals, err) = integrate_vec(0.0, 1.0, 4 * kk, tol, 1.0 / 256.0, |nd, out| {
        let one_minus = nd.to_b;
        let y = scale * nd.from_a / one_minus;
        let jac = scale / (one_minus * one_minus);
        if !y.is_finite() || !jac.is_finite() || y == 0.0 {
            return;
        }
        let z = C64::new(x0, y);
        let z2 = z * z;
        fy.iter_mut().for_each(|c| *c = C64::new(0.0, 0.0));
        fxv.iter_mut().for_each(|c| *c = C64::new(0.0, 0.0));
        for (i, &(v, _, _)) in vn.iter().enumerate() {
            let d = (C64::new(v * v, 0.0) - z2).inv();
            let ky = d * (2.0 * v);
            let kx = ky * v;
            let row = &hv[i * kk..(i + 1) * kk];
            for k in 0..kk {
                fy[k] += ky * row[k];
                fxv[k] += kx * row[k];
            }
        }
        let zi = z.inv();
        let kmat = lamb.kernels(zi);
        for k in 0..kk {
            let fx = -fxv[k] * zi * gamma;
            for j in 0..2 {
                let g = (kmat[j][0] * fy[k] + kmat[j][1] * fx) * zi;
                out[4 * k + j] = (g * y).im * jac / std::f64::consts::PI;
                out[4 * k + 2 + j] = g.re * jac / std::f64::consts::PI;
            }
        }
    });
    let rows = (0..kk)
        .map(|k| {
            [
                vals[4 * k],
                vals[4 * k + 1],
                vals[4 * k + 2],
                vals[4 * k + 3],
            ]
        })
        .collect();
    (rows, err)
}

/// Load a half-plane with an arbitrary even contact pressure S on |x| < p (given through its
/// slope h = dS/dx on (0, p), a function of (x, p - x)) and the shear -sgn(x) gamma S, and
/// return (U_y, U_x, U_y', U_x') at x0 > 0 through Lamb's kernels (units c1 = mu = 1, m = c2/c1).
/// Used to check any solution of the contact problem, the paper's included, independently of
/// how it was obtained.
pub fn load_through_kernels<H>(m: f64, p: f64, gamma: f64, x0: f64, h: H) -> Result<[f64; 4]>
where
    H: Fn(f64, f64) -> f64,
{
    if !(p > 0.0 && p.is_finite()) {
        return Err(invalid("p", p, "(0, inf)"));
    }
    if !(x0 > 0.0 && x0.is_finite()) {
        return Err(invalid("x0", x0, "(0, inf)"));
    }
    let prob_nodes = {
        let smax = V_RULE_S_MAX;
        let hs = SolveOptions::default().h_tanh;
        if x0 < p {
            let mut out: Vec<(f64, f64, f64)> = tanh_rule(0.0, x0, hs, smax)
                .into_iter()
                .map(|n| (n.v, (p - x0) + n.to_b, n.w))
                .collect();
            out.extend(
                tanh_rule(x0, p, hs, smax)
                    .into_iter()
                    .map(|n| (x0 + n.from_a, n.to_b, n.w)),
            );
            out
        } else {
            tanh_rule(0.0, p, hs, smax)
                .into_iter()
                .map(|n| (n.v, n.to_b, n.w))
                .collect()
        }
    };
    let (rows, _) = contour_rows_with(
        &Lamb::new(m),
        gamma,
        &prob_nodes,
        1,
        x0,
        1e-14,
        |v, pv, out| out[0] = h(v, pv),
    );
    Ok(rows[0])
}
