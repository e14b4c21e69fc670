//! Displacement matching, eqs (48)-(57): Q and the alpha-V-Theta-gamma relation.
//!
//! With c1 = 1 and H(v)/v = v^(-2 Omega0) (v^2 - p^2)^(-1/2 + Omega0) e^(Lambda0(v)) for v > p,
//! the integrals (54), (55) are
//!
//! ```text
//!   I1, I3 = PV Int_p^m (H/v) Y_a {1, 1/v},   I2, I4 = Int_m^1 (H/v) Y_b {1, 1/v},
//!   I5, I7 = PV Int_p^m (H/v) T_a {1, 1/v},   I6, I8 = Int_m^1 (H/v) T_b {1, 1/v},
//!   Y_a = |p2| v^2/(m^2 R),  T_a = gamma |p1| v^2/(m^2 R)                          on (p, m),
//!   Y_b = v^2 K |p1| |p2| (K |p2| - 2 gamma)/(m^2 (16 + K^4 |p1|^2 |p2|^2)),
//!   T_b = 2 v^2 |p1| (2 gamma - K |p2|)/(m^2 (16 + K^4 |p1|^2 |p2|^2))            on (m, 1),
//! ```
//!
//! with |p2| = (v^2/m^2 - 1)^(-1/2) on (m, 1). Corrections to the OCR text, each re-derived
//! from (18) with the boundary values of p_k (p_k^{+-} = -+|p_k| on the cut, p_2 = -i|p_2| on
//! (m, 1)):
//! * (56b), (57b): the denominators are 16 + K^4 |p1|^2 |p2|^2 and "K p2^2" is K |p2|^2
//!   (read literally, with p2 imaginary there, the denominator has spurious zeros);
//! * (53)-(55) omit the Rayleigh-pole terms. On (p, m), 1/R^+ - 1/R^- = -2 pi i delta(v - m_R)/R'(m_R)
//!   and F = -i Q v H is imaginary, so D(L F/R) has the real part
//!   -2 pi Q m_R H L/R' delta(v - m_R); in (53) this adds, with
//!   delta_R = pi L(m_R) H(m_R)/(m_R R'(m_R)),
//!   I1 += gamma delta_R, I3 += gamma delta_R/m_R, I5 -= delta_R, I7 -= delta_R/m_R.
//!   They enter (53) as (beta + gamma) delta_R, so the classical case is unchanged.
//!
//! The principal values at m_R are taken with the pole subtracted analytically: the
//! integrand is written phi(v)/(v - m_R) with phi built on R/(v - m_R) in its
//! cancellation-free form ([`complexfn::Rayleigh::r_over_xi_minus_root`]).
//!
//! Then (53) gives Q/(c1^2 cot Theta) = 1/[(I3 - I4) - beta (I7 + I8)] and
//! V/(c1 cot Theta) = Q/(c1^2 cot Theta) [(I1 - I2) - beta (I5 + I6)].

use complexfn::cauchy::principal_value;
use complexfn::quadrature::{tanh_sinh, CachedRules, Point, TsOptions};
use complexfn::{Real, Side};

use crate::case::Case;
use crate::error::{from_quad, Result, WedgeError};
use crate::params::{Coupling, Solution};

/// The solved matching: the integrals (54), (55) and the constants they give.
#[derive(Clone, Debug)]
pub struct Matching<T> {
    /// I1 ... I8 as used (including the pole terms for the `paper` variant).
    pub i: [T; 8],
    /// The Rayleigh-pole term delta_R = pi L(m_R) H(m_R)/(m_R R'(m_R)).
    pub pole: T,
    /// Q/(c1^2 cot Theta).
    pub q_hat: T,
    /// V/(c1 cot Theta).
    pub v_hat: T,
    /// Estimated relative error of q_hat and v_hat (from the quadrature estimates).
    pub rel_error: f64,
    /// Estimated absolute error of each of I1 ... I8 (quadrature and inner rule), without
    /// round-off: what a combination of the integrals that cancels, such as I5 + I6, adds
    /// to its relative error ([`Case::edge_slip_velocity_over_speed`]).
    pub abs_error: f64,
    /// Integrand evaluations spent on the eight integrals.
    pub evals: usize,
}

/// Quadrature tolerance for a precision: eps^0.9. The tanh-sinh estimate |S_k - S_(k-1)| is
/// the error of the previous level; once it is below eps^0.9 the last level is accurate to
/// working precision (the rule converges quadratically), so asking for eps itself would only
/// add a level that round-off keeps from confirming.
pub(crate) fn tol_for<T: Real>(like: &T) -> f64 {
    let eps = like.epsilon().to_f64();
    if eps > 0.0 {
        eps.powf(0.9)
    } else {
        // below f64's range: 2^(-0.9 prec)
        2f64.powf(-0.9 * f64::from(like.prec())).max(1e-300)
    }
}

impl<T: CachedRules> Case<T> {
    /// The displacement matching (computed once, then cached).
    pub fn matching(&self) -> Result<&Matching<T>> {
        self.matching
            .get_or_init(|| self.compute_matching())
            .as_ref()
            .map_err(Clone::clone)
    }

    fn compute_matching(&self) -> Result<Matching<T>> {
        let p = self.p.clone();
        let m = self.m().clone();
        let m_r = self.m_r().clone();
        let m2 = m.clone().sqr();
        let one = p.one();
        let ray = self.rayleigh().clone();
        let tol = tol_for(&p);
        let gamma = self.gamma.clone();
        // The T-integrals (I5 ... I8) enter (53) times beta: they are integrated times
        // w = max(1, |beta|), so that the quadratures' estimates (of the largest component)
        // bound the errors of I1 ... I4 and of beta I5 ... beta I8 alike, the terms that
        // (53) sums (for a sharp wedge with coupling they nearly cancel).
        let w = self.beta.clone().abs().max(one.clone());
        let gamma_w = gamma.clone() * &w;

        // (p, m): phi(v) = (H/v) v^2/(m^2 R/(v - m_R)) [|p2|, |p2|/v, gamma|p1|, gamma|p1|/v]
        let phi_a = |pt: &Point<T>| -> [T; 4] {
            let v = &pt.v;
            let hv = self.h_over_v_outside(v, &pt.from_a);
            let s = v.clone().sqr();
            let p1 = (one.clone() - &s).sqrt().recip();
            // |p2| = m/sqrt((m - v)(m + v)), with m - v exact from the endpoint offset
            let p2 = m.clone() / (pt.to_b.clone() * (m.clone() + v)).sqrt();
            let rq = ray.r_over_xi_minus_root(v);
            let c = hv * &s / (m2.clone() * rq);
            let inv_v = v.clone().recip();
            let y = c.clone() * p2;
            let tt = c * p1 * &gamma_w;
            [y.clone(), y * &inv_v, tt.clone(), tt * inv_v]
        };
        let opts_a = TsOptions::new(tol)
            .left_end(self.edge_end)
            .right_singularity(-0.5);
        let ea = principal_value(&p, &m, &m_r, opts_a, phi_a)
            .map_err(|e| from_quad("matching integrals on (p, m)", e))?;

        // (m, 1)
        let phi_b = |pt: &Point<T>| -> [T; 4] {
            let v = &pt.v;
            let v_minus_p = v.clone() - &p;
            let hv = self.h_over_v_outside(v, &v_minus_p);
            let s = v.clone().sqr();
            // |p1| = 1/sqrt((1 - v)(1 + v)), |p2| = m/sqrt((v - m)(v + m))
            let p1 = (pt.to_b.clone() * (one.clone() + v)).sqrt().recip();
            let p2 = m.clone() / (pt.from_a.clone() * (m.clone() + v)).sqrt();
            let k = one.clone() * 2.0 - s.clone() / &m2;
            let pp = p1.clone() * &p2;
            let den = m2.clone() * (pp.clone().sqr() * k.clone().sqr().sqr() + 16.0);
            let yb = s.clone() * &k * &pp * (k.clone() * &p2 - gamma.clone() * 2.0) / &den;
            let tb = s * &p1 * (gamma.clone() * 2.0 - k * &p2) * 2.0 / den * &w;
            let inv_v = v.clone().recip();
            [
                hv.clone() * &yb,
                hv.clone() * yb * &inv_v,
                hv.clone() * &tb,
                hv * tb * inv_v,
            ]
        };
        let eb = tanh_sinh(&m, &one, TsOptions::new(tol), phi_b)
            .map_err(|e| from_quad("matching integrals on (m, 1)", e))?;

        // Rayleigh-pole term
        let mr_minus_p = m_r.clone() - &p;
        let h_mr = self.h_over_v_outside(&m_r, &mr_minus_p) * &m_r;
        let l_mr = ray.at_boundary(&m_r, Side::Lower).l.re;
        let pole = p.pi() * l_mr * &h_mr / (m_r.clone() * ray.r_prime_at_root());

        let [i1, i3, i5, i7] = ea.estimate.value;
        let [i2, i4, i6, i8] = eb.estimate.value;
        let (i5, i7, i6, i8) = (i5 / &w, i7 / &w, i6 / &w, i8 / &w);
        let (i1, i3, i5, i7) = if self.solution == Solution::AsPrinted {
            (i1, i3, i5, i7)
        } else {
            (
                i1 + gamma.clone() * &pole,
                i3 + gamma.clone() * &pole / &m_r,
                i5 - pole.clone(),
                i7 - pole.clone() / &m_r,
            )
        };
        let denom = (i3.clone() - &i4) - self.beta.clone() * (i7.clone() + &i8);
        let numer = (i1.clone() - &i2) - self.beta.clone() * (i5.clone() + &i6);
        let q_hat = denom.clone().recip();
        let v_hat = numer.clone() * &q_hat;
        let scale_d = (i3.clone().abs()
            + i4.clone().abs()
            + (self.beta.clone() * (i7.clone().abs() + i8.clone().abs())).abs())
        .to_f64();
        let scale_n = (i1.clone().abs()
            + i2.clone().abs()
            + (self.beta.clone() * (i5.clone().abs() + i6.clone().abs())).abs())
        .to_f64();
        // the quadratures bound I1 ... I4 and w I5 ... w I8 to ea.error + eb.error each, so
        // each of the two sums of (53) to (1 + |beta|/w) times that; the inner rule's error
        // perturbs every integrand alike (relative to its terms' sizes)
        let quad =
            (ea.estimate.error + eb.estimate.error) * (1.0 + self.beta.to_f64().abs() / w.to_f64());
        let inner = self.inner.error().min(1.0) * (scale_d + scale_n);
        let abs_err = quad + inner;
        let rel_d = abs_err / denom.to_f64().abs().max(1e-300);
        let rel_n = abs_err / numer.to_f64().abs().max(1e-300);
        let cond = (scale_d / denom.to_f64().abs()).max(scale_n / numer.to_f64().abs().max(1e-300));
        // A factor 4 of margin: the level-difference estimates of tanh-sinh are of the
        // right size but not bounds, and the stated error must never be optimistic.
        let rel_error = 4.0 * (rel_d + rel_n + cond * p.epsilon().to_f64() * 8.0);
        if !(rel_error <= crate::solved::MAX_REL_ERROR) {
            return Err(self.undetermined(rel_error));
        }
        Ok(Matching {
            i: [i1, i2, i3, i4, i5, i6, i7, i8],
            pole,
            q_hat,
            v_hat,
            rel_error,
            abs_error: abs_err,
            evals: ea.evals + eb.evals,
        })
    }

    /// The refusal of a matching whose relative error estimate `rel` exceeds
    /// [`crate::solved::MAX_REL_ERROR`]. For a sharp wedge with coupling (cot Theta > 1) the
    /// two terms of each sum of (53) are of order cot Theta and cancel to O(1), so the estimate
    /// grows like cot Theta: the error names theta_deg and the smallest angle the working
    /// precision resolves at this contact speed and friction, extrapolated along that growth,
    /// atan(rel/(MAX_REL_ERROR cot Theta)). Otherwise [`WedgeError::Undetermined`].
    fn undetermined(&self, rel: f64) -> WedgeError {
        let cot = self.cot_theta.to_f64();
        let allowed = crate::solved::MAX_REL_ERROR;
        if self.indenter.coupling() == Coupling::On && cot > 1.0 {
            let theta = self.indenter.theta_deg().text();
            // the estimate grows like cot Theta while the sums keep a digit; once they cancel
            // entirely it saturates, and only says that the angle lies well below the limit
            let bound = if rel < 1.0 {
                let min_deg = (rel / (allowed * cot)).atan().to_degrees();
                format!("Theta above about {min_deg:.1e}")
            } else {
                format!("Theta well above {theta}")
            };
            return WedgeError::InvalidParameter(complexfn::InvalidParameter {
                name: "theta_deg",
                value: theta.to_string(),
                range: format!(
                    "{bound} degrees at {} bits for alpha = {} m/s and gamma = {}: below it \
                     the two terms of V in eq (53), each of order cot Theta, cancel beyond the \
                     working precision (relative error estimate {rel:.1e} of V, above \
                     {allowed:e}); more digits resolve smaller angles",
                    self.p.prec(),
                    crate::error::short(self.p.to_f64() * self.material.c1().value()),
                    self.indenter.gamma().text(),
                ),
            });
        }
        WedgeError::Undetermined {
            what: "v_over_c1_cot_theta".into(),
            reached: rel,
            allowed,
        }
    }

    /// Q/(c1^2 cot Theta), from (53b).
    pub fn q_hat(&self) -> Result<T> {
        Ok(self.matching()?.q_hat.clone())
    }

    /// V/(c1 cot Theta), from (53a).
    pub fn v_hat(&self) -> Result<T> {
        Ok(self.matching()?.v_hat.clone())
    }

    /// The normal force per unit half-width and mu cot Theta, P/(alpha t mu cot Theta) =
    /// pi Q/(c1^2 cot Theta)/p, eq (47).
    pub fn force_hat(&self) -> Result<T> {
        Ok(self.q_hat()? * self.p.pi() / &self.p)
    }

    /// The tangential particle velocity du_r/dt at the contact edge r = alpha t, over V:
    /// (Q/c1)(I5 + I6)/V (`docs/errata.md`, section 5; pole term included for the `paper` variant).
    ///
    /// I5 + I6 may cancel: its own absolute error is added by
    /// [`Case::combination_error`].
    pub fn edge_slip_velocity_over_speed(&self) -> Result<T> {
        let mt = self.matching()?;
        Ok(mt.q_hat.clone() * (mt.i[4].clone() + &mt.i[5]) / &mt.v_hat)
    }

    /// The paper's Fig. 3 expression (Q/c1)[(I5 + I6) - (I7 + I8) alpha/c1], over V: this is
    /// u_r(alpha t, t)/t, the rate of u_r following the moving edge (`docs/errata.md`, section 5).
    pub fn edge_following_rate_over_speed(&self) -> Result<T> {
        let mt = self.matching()?;
        let i56 = mt.i[4].clone() + &mt.i[5];
        let i78 = mt.i[6].clone() + &mt.i[7];
        Ok(mt.q_hat.clone() * (i56 - i78 * &self.p) / &mt.v_hat)
    }

    /// The absolute error that a combination sum_k w_k I_k of the matching integrals adds to
    /// a quantity (Q/V) sum_k w_k I_k beyond the matching's relative error: |Q/V| times the
    /// integrals' absolute errors and the round-off of the sum, 8 u sum_k |w_k I_k|. It
    /// matters where the sum cancels (the edge velocities near the regime boundary).
    pub fn combination_error(&self, weights: &[(usize, f64)]) -> Result<f64> {
        let mt = self.matching()?;
        let u = self.p.epsilon().to_f64();
        let mut err = 0.0;
        for &(k, w) in weights {
            err += w.abs() * (mt.abs_error + 8.0 * u * mt.i[k].to_f64().abs());
        }
        Ok((mt.q_hat.to_f64() / mt.v_hat.to_f64()).abs() * err)
    }
}
