//! The checks of a solution: the residual of the contact condition, the slip direction, the
//! normal gap and the Signorini conditions of a solved [`GenuineCase`], and the load of an
//! arbitrary contact pressure through Lamb's kernels ([`load_through_kernels`]), which checks
//! any solution independently of how it was obtained.

use complexfn::quadrature::CachedRules;
use complexfn::{Rayleigh, Real};

use super::case::GenuineCase;
use super::collocation::*;
use super::options::*;
use crate::error::{invalid, Result};
use crate::kernels::Lamb;

impl<T: CachedRules> GenuineCase<T> {
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
