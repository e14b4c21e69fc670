//! Contact stress (40), its apex behaviour (41), (43), and the tangential slip rate on the
//! contact.
//!
//! With c1 = 1 and the corrected boundary values H^{+-} = -+ i X e^(+- i pi Omega) (eq (32)),
//! (19) gives on 0 < x = r/(c1 t) < p
//!
//! ```text
//!   sigma_theta/(mu cot Theta) = -Q_hat Int_x^p g(v) dv,
//!   g(v) = e^(b(v)) cos(pi Omega(v)) v^(-1 - 2 Omega(v)) (p^2 - v^2)^(-1/2 + Omega(v)),
//! ```
//!
//! Q_hat = Q/(c1^2 cot Theta). Near the apex g ~ v^(-1 - 2 Omega0): the stress is finite for
//! Omega0 < 0, logarithmic for Omega0 = 0 and a power x^(-2 Omega0) for Omega0 > 0. Below
//! x = p/4 the integral is taken in the variable ln v, which resolves every scale down to the
//! apex; above, the edge singularity (p - v)^(-1/2 + Omega(p)) is handed to the rule as an exact
//! offset.
//!
//! The tangential slip rate du_r/dt on the contact follows from (18): with
//! A = D(L F/R - i p1 v^2 G/(m^2 R)) = (2 Q v X/R) [-L cos(pi Omega) + gamma |p1| v^2 sin(pi Omega)/m^2]
//! on (0, p), du_r/dt(x) = Q [(I5 + I6) + J(x)] with
//! J(x) = Int_x^p (X/v)/(R/v^2) [-(L/v^2) cos(pi Omega) + gamma |p1| sin(pi Omega)/m^2] dv.

use complexfn::quadrature::{tanh_sinh, CachedRules, Point, TsOptions};
use complexfn::Side;

use crate::case::Case;
use crate::error::{from_quad, invalid, Result};
use crate::matching::tol_for;

/// A value with its estimated absolute error: the workspace's one such type,
/// [`complexfn::Estimate`], under the name this crate's interface has used.
pub use complexfn::Estimate as WithError;

impl<T: CachedRules> Case<T> {
    /// The integrand g(v) of (40) at v in (0, p), with p - v given exactly.
    fn stress_integrand(&self, v: &T, p_minus_v: &T) -> T {
        let f = self.x_on_contact(v, p_minus_v);
        f.x * f.cos / v.clone().sqr()
    }

    /// Int_x^p of an integrand f(v, p - v) on the contact, split at p/4 with the lower part in
    /// the variable y = ln v (so that the apex scale is resolved however small x is).
    fn contact_integral<F>(&self, x: &T, mut f: F) -> Result<WithError<T>>
    where
        F: FnMut(&T, &T) -> T,
    {
        let p = &self.p;
        let tol = tol_for(p);
        let quarter = p.clone() / 4.0;
        let mut value = p.zero();
        let mut error = 0.0;
        let upper_start = if *x < quarter {
            quarter.clone()
        } else {
            x.clone()
        };
        let e = tanh_sinh(
            &upper_start,
            p,
            TsOptions::new(tol).right_end(self.edge_end),
            |pt: &Point<T>| f(&pt.v, &pt.to_b),
        )
        .map_err(|e| from_quad("contact integral", e))?;
        value += e.estimate.value;
        error += e.estimate.error;
        if *x < quarter {
            let y0 = x.clone().ln();
            let y1 = quarter.ln();
            let e = tanh_sinh(&y0, &y1, TsOptions::new(tol), |pt: &Point<T>| {
                let v = pt.v.clone().exp();
                let pv = p.clone() - &v;
                f(&v, &pv) * v
            })
            .map_err(|e| from_quad("contact integral (apex part)", e))?;
            value += e.estimate.value;
            error += e.estimate.error;
        }
        Ok(WithError {
            value,
            error,
            kind: complexfn::ErrorKind::Quadrature,
        })
    }

    /// Contact stress sigma_theta(r, 0, t)/(mu cot Theta) at x = r/(c1 t) in (0, p], eq (40).
    /// Equal on theta = -pi by symmetry. Errors if x is outside (0, p].
    pub fn stress_hat(&self, x: &T) -> Result<WithError<T>> {
        if !(*x > 0.0) || *x > self.p || !x.is_finite() {
            return Err(invalid(
                "r/(c1 t)",
                x.to_f64(),
                format!("(0, p] = (0, {}]", self.p.to_f64()),
            ));
        }
        let q = self.q_hat()?;
        if *x == self.p {
            return Ok(WithError {
                value: x.zero(),
                error: 0.0,
                kind: complexfn::ErrorKind::Quadrature,
            });
        }
        let e = self.contact_integral(x, |v, pv| self.stress_integrand(v, pv))?;
        let rel = self.matching()?.rel_error;
        let q_abs = q.to_f64().abs();
        let value = -(q * e.value);
        let error = 4.0 * e.error * q_abs + rel * value.to_f64().abs();
        Ok(WithError {
            value,
            error,
            kind: complexfn::ErrorKind::Quadrature,
        })
    }

    /// The integrand of J(x) (tangential slip rate on the contact) at v in (0, p). R/v^2 is
    /// formed as (v - m_R) [R/(v - m_R)]/v^2 with v - m_R = -((p - v) + (m_R - p)) from the
    /// exact offset, so the integrand stays accurate when p is close to m_R.
    fn slip_integrand(&self, v: &T, p_minus_v: &T) -> T {
        let f = self.x_on_contact(v, p_minus_v);
        let ray = self.rayleigh();
        let vals = ray.at_boundary(v, Side::Lower);
        let (p1, l_s) = (vals.p1.re, vals.l_over_s.re);
        let v_minus_root = -(p_minus_v.clone() + &(self.m_r().clone() - self.p()));
        let s = v.clone().sqr();
        let r_s = if s < ray.m2().clone() / 16.0 {
            vals.r_over_s.re
        } else {
            v_minus_root * ray.r_over_xi_minus_root(v) / &s
        };
        let m2 = ray.m2().clone();
        let bracket = -(l_s * f.cos) + self.gamma.clone() * p1 * f.sin / m2;
        f.x / v / r_s * bracket
    }

    /// J(0) = Int_0^p of the slip integrand, with its apex term c v^(-2 Omega0) subtracted and
    /// integrated in closed form (2 Omega0 may be close to 1 for strong friction):
    /// c = p^(-1 + 2 Omega0) e^(S0) (cos(pi Omega0) + gamma sin(pi Omega0)/m^2)/(2/m^2 - 2).
    fn slip_integral_from_apex(&self) -> Result<WithError<T>> {
        let p = self.p().clone();
        let tol = tol_for(&p);
        let o0 = self.omega0();
        let m2 = self.rayleigh().m2().clone();
        let one = p.one();
        let (cs, sn) = self.omega_fn().omega0_cos_sin();
        let c = p.clone().powf(&(o0.clone() * 2.0 - 1.0))
            * self.s0().exp()
            * (cs + self.gamma.clone() * sn / &m2)
            / ((one.clone() / &m2 - 1.0) * 2.0);
        let e = -(o0.clone() * 2.0);
        let quarter = p.clone() / 4.0;
        let lower = tanh_sinh(&p.zero(), &quarter, TsOptions::new(tol), |pt: &Point<T>| {
            let pv = p.clone() - &pt.v;
            self.slip_integrand(&pt.v, &pv) - c.clone() * pt.v.clone().powf(&e)
        })
        .map_err(|e| from_quad("apex slip integral", e))?;
        let opts = TsOptions::new(tol).right_end(self.edge_end);
        let upper = tanh_sinh(&quarter, &p, opts, |pt: &Point<T>| {
            self.slip_integrand(&pt.v, &pt.to_b)
        })
        .map_err(|e| from_quad("apex slip integral", e))?;
        let e1 = self.omega_fn().one_minus_two_omega0();
        let lead = c * quarter.powf(&e1) / e1;
        Ok(WithError {
            value: lower.estimate.value + upper.estimate.value + lead,
            error: lower.estimate.error + upper.estimate.error,
            kind: complexfn::ErrorKind::Quadrature,
        })
    }

    /// The tangential particle velocity du_r/dt on the contact at x = r/(c1 t) in [0, p), over
    /// V (eq (18) differentiated in t). At x -> 0 it equals u_r(0+, t)/(V t).
    pub fn slip_rate_over_speed(&self, x: &T) -> Result<WithError<T>> {
        if x.is_sign_negative() || !(*x < self.p) || !x.is_finite() {
            return Err(invalid(
                "r/(c1 t)",
                x.to_f64(),
                format!("[0, p) = [0, {})", self.p.to_f64()),
            ));
        }
        let mt = self.matching()?;
        let (q, vh) = (mt.q_hat.clone(), mt.v_hat.clone());
        let i56 = mt.i[4].clone() + &mt.i[5];
        let j = if *x == 0.0 {
            self.slip_integral_from_apex()?
        } else {
            self.contact_integral(x, |v, pv| self.slip_integrand(v, pv))?
        };
        // (I5 + I6) + J cancels where u_r vanishes (gamma = 0 at the apex): the error of the
        // sum is that of its terms, (I5 + I6) with the matching's relative error and both
        // with their round-off
        let terms = i56.to_f64().abs() + j.value.to_f64().abs();
        let cancel = (mt.rel_error * i56.to_f64().abs() + 8.0 * self.p.epsilon().to_f64() * terms)
            * (q.clone() / &vh).to_f64().abs();
        let value = q.clone() * (i56 + &j.value) / &vh;
        let error = 4.0 * j.error * (q / vh).to_f64().abs()
            + mt.rel_error * 2.0 * value.to_f64().abs()
            + cancel;
        Ok(WithError {
            value,
            error,
            kind: complexfn::ErrorKind::Quadrature,
        })
    }

    /// u_r(0+, t)/(V t): the tangential displacement at the apex. Non-zero means the
    /// construction (23) leaves a tangential dislocation 2 u_r(0+) at the apex
    /// (`docs/errata.md`, section 6); it vanishes for gamma = 0.
    pub fn apex_u_r_over_speed_t(&self) -> Result<WithError<T>> {
        self.slip_rate_over_speed(&self.p.zero())
    }
}
