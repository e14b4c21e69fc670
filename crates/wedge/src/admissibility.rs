//! Physical admissibility of a solved case: the Signorini conditions and the slip direction (8).
//!
//! * Contact compressive: sigma_theta <= 0 on the contact. Every factor of the integrand of
//!   (40) is positive (|Omega| < 1/2), so this holds exactly when Q > 0.
//! * No interpenetration outside the contact: the normal gap
//!   g(x) = -V + x cot Theta - (u_theta + beta u_r) >= 0 for p < x < 1 (x = r/(c1 t)), with
//!   u_theta + beta u_r from (18):
//!   Q Int_x^1 (v - x) (H/v^2) C(v) dv, C = -Y_a + beta T_a on (p, m), Y_b + beta T_b on (m, 1),
//!   plus, for the `paper` variant and x < m_R, the Rayleigh-pole term
//!   -Q (beta + gamma) (m_R - x) delta_R/m_R (see [`crate::matching`]). g(p) = 0 by (53).
//! * Slip direction (8): du_r/dt > 0 on the contact (only meaningful when gamma > 0).

use complexfn::cauchy::principal_value;
use complexfn::quadrature::{tanh_sinh, CachedRules, Point, TsOptions};

use crate::case::Case;
use crate::error::{from_quad, invalid, Result};
use crate::matching::tol_for;
use crate::params::Solution;

/// Admissibility report of one case.
#[derive(Clone, Debug)]
pub struct Admissibility {
    /// sigma_theta <= 0 on the contact (Q > 0).
    pub contact_compressive: bool,
    /// The smallest normal gap found outside the contact, over (c1 t cot Theta); the sample
    /// points are `gap_points`.
    pub min_gap: f64,
    /// min_gap >= -(its error estimate).
    pub no_interpenetration: bool,
    /// du_r/dt > 0 at every sample point of the contact (true when gamma = 0, where (8) does
    /// not apply).
    pub slip_direction_ok: bool,
    /// The smallest du_r/dt/V found on the contact.
    pub min_slip_rate: f64,
}

/// Sample points (as fractions of the contact half-width) of the slip-direction check.
pub const SLIP_SAMPLES: usize = 16;
/// Sample points of the gap check in (p, 1).
pub const GAP_SAMPLES: usize = 12;

impl<T: CachedRules> Case<T> {
    /// The normal gap g(x)/(c1 t cot Theta) outside the contact, p < x < 1.
    pub fn normal_gap(&self, x: &T) -> Result<T> {
        let p = self.p().clone();
        let one = p.one();
        if !(*x > p) || !(*x < one) {
            return Err(invalid(
                "r/(c1 t)",
                x.to_f64(),
                format!("(p, 1) = ({}, 1)", p.to_f64()),
            ));
        }
        let mt = self.matching()?;
        let m = self.m().clone();
        let m_r = self.m_r().clone();
        let m2 = m.clone().sqr();
        let ray = self.rayleigh().clone();
        let beta = self.beta().clone();
        let gamma = self.gamma().clone();
        let bg = beta.clone() * &gamma;
        let tol = tol_for(&p);
        let x_minus_p = x.clone() - &p;
        let mut acc = p.zero();
        if *x < m {
            // (x, m): (v - x) H (-|p2| + beta gamma |p1|)/(m^2 R)
            let core = |pt: &Point<T>| -> (T, T) {
                let v = &pt.v;
                let vmp = pt.from_a.clone() + &x_minus_p;
                let h = self.h_over_v_outside(v, &vmp) * v;
                let s = v.clone().sqr();
                let p1 = (one.clone() - &s).sqrt().recip();
                let p2 = m.clone() / (pt.to_b.clone() * (m.clone() + v)).sqrt();
                let c = pt.from_a.clone() * h * (bg.clone() * p1 - p2) / &m2;
                (c, v.clone())
            };
            if *x < m_r {
                let e = principal_value(x, &m, &m_r, TsOptions::new(tol), |pt: &Point<T>| {
                    let (c, v) = core(pt);
                    c / ray.r_over_xi_minus_root(&v)
                })
                .map_err(|e| from_quad("normal gap", e))?;
                acc += e.estimate.value;
                if self.solution() != Solution::AsPrinted {
                    acc -= (beta.clone() + &gamma) * (m_r.clone() - x) * &mt.pole / &m_r;
                }
            } else {
                let e = tanh_sinh(x, &m, TsOptions::new(tol), |pt: &Point<T>| {
                    let (c, v) = core(pt);
                    let r = ray.r_over_xi_minus_root(&v) * (v - &m_r);
                    c / r
                })
                .map_err(|e| from_quad("normal gap", e))?;
                acc += e.estimate.value;
            }
        }
        let lo = if *x > m { x.clone() } else { m.clone() };
        let lo_minus_m = lo.clone() - &m;
        let e = tanh_sinh(&lo, &one, TsOptions::new(tol), |pt: &Point<T>| {
            let v = &pt.v;
            let h = self.h_over_v_outside(v, &(v.clone() - &p)) * v;
            let s = v.clone().sqr();
            let p1 = (pt.to_b.clone() * (one.clone() + v)).sqrt().recip();
            let vm = pt.from_a.clone() + &lo_minus_m;
            let p2 = m.clone() / (vm * (m.clone() + v)).sqrt();
            let k = one.clone() * 2.0 - s.clone() / &m2;
            let pp = p1.clone() * &p2;
            let den = m2.clone() * (pp.clone().sqr() * k.clone().sqr().sqr() + 16.0);
            let yb = s.clone() * &k * &pp * (k.clone() * &p2 - gamma.clone() * 2.0) / &den;
            let tb = s * &p1 * (gamma.clone() * 2.0 - k * &p2) * 2.0 / den;
            (v.clone() - x) * h / v.clone().sqr() * (yb + beta.clone() * tb)
        })
        .map_err(|e| from_quad("normal gap", e))?;
        acc += e.estimate.value;
        Ok(-mt.v_hat.clone() + x - mt.q_hat.clone() * acc)
    }

    /// The admissibility report (Signorini, slip direction) at fixed sample points.
    pub fn admissibility(&self) -> Result<Admissibility> {
        let mt = self.matching()?;
        let p = self.p().clone();
        let contact_compressive = mt.q_hat > 0.0;
        let mut min_gap = f64::INFINITY;
        let scale = mt.v_hat.to_f64().abs().max(1.0);
        let tol = 1e3 * mt.rel_error.max(p.epsilon().to_f64()) * scale;
        for k in 1..=GAP_SAMPLES {
            let f = (k as f64 / (GAP_SAMPLES as f64 + 1.0)).powi(2);
            let x = p.clone() + (p.one() - &p) * f;
            min_gap = min_gap.min(self.normal_gap(&x)?.to_f64());
        }
        let mut min_slip = f64::INFINITY;
        for k in 0..SLIP_SAMPLES {
            let x = p.clone() * ((k as f64 + 0.5) / SLIP_SAMPLES as f64);
            min_slip = min_slip.min(self.slip_rate_over_speed(&x)?.value.to_f64());
        }
        let slip_direction_ok = *self.gamma() == 0.0 || min_slip > 0.0;
        Ok(Admissibility {
            contact_compressive,
            min_gap,
            no_interpenetration: min_gap >= -tol,
            slip_direction_ok,
            min_slip_rate: min_slip,
        })
    }
}
