//! The inverse problem: the contact-zone speed alpha for a given indenter speed V.
//!
//! V/(c1 cot Theta) is an increasing function of p = alpha/c1 on (0, m_R) (it is checked at
//! the bracket ends, and the solve fails with a clear error if the target is outside the
//! range reached). The root is bracketed in f64 first (Illinois regula falsi with bisection
//! safeguard), then polished at the working precision by the same iteration started from a
//! narrow bracket around the f64 root.

use complexfn::quadrature::CachedRules;
use complexfn::Real;

use crate::case::Case;
use crate::error::{invalid, Result, WedgeError};
use crate::params::{Indenter, Material, Param, Solution};

/// Smallest and largest p = alpha/c1 used to bracket the inverse solve, as fractions of m_R.
pub const BRACKET: (f64, f64) = (1e-6, 1.0 - 1e-6);

fn illinois<T: Real, F: FnMut(&T) -> Result<T>>(
    mut lo: T,
    mut flo: T,
    mut hi: T,
    mut fhi: T,
    tol: &T,
    mut f: F,
) -> Result<T> {
    let mut side = 0i32;
    for _ in 0..200 {
        let width = hi.clone() - &lo;
        if width <= tol.clone() * (lo.clone().abs() + hi.clone().abs()) {
            break;
        }
        let mut x = (lo.clone() * &fhi - hi.clone() * &flo) / (fhi.clone() - &flo);
        if !(x > lo && x < hi) {
            x = (lo.clone() + &hi) / 2.0;
        }
        let fx = f(&x)?;
        if fx == 0.0 {
            return Ok(x);
        }
        if (fx < 0.0) == (flo < 0.0) {
            lo = x;
            flo = fx;
            if side == -1 {
                fhi /= 2.0;
            }
            side = -1;
        } else {
            hi = x;
            fhi = fx;
            if side == 1 {
                flo /= 2.0;
            }
            side = 1;
        }
    }
    Ok((lo.clone() * &fhi - hi * &flo) / (fhi - flo))
}

/// The case whose indenter speed is `speed` (m/s), at the precision of `like`.
pub fn case_for_speed<T: CachedRules>(
    material: &Material,
    indenter: &Indenter,
    speed: impl Into<Param>,
    like: &T,
    solution: Solution,
) -> Result<Case<T>> {
    let speed_param: Param = speed.into();
    let speed = speed_param.value();
    if !(speed.is_finite() && speed > 0.0) {
        return Err(invalid("speed", speed_param.text(), "(0, inf) m/s"));
    }
    // f64 solve
    let m_r = complexfn::Rayleigh::new(material.m(&0.0_f64))?
        .m_r()
        .to_owned();
    let target64 = speed / (material.c1().value() * indenter.cot_theta(&0.0_f64));
    let g64 = |p: &f64| -> Result<f64> {
        Ok(Case::new(material, indenter, *p, solution)?.v_hat()? - target64)
    };
    let (lo, hi) = (m_r * BRACKET.0, m_r * BRACKET.1);
    let (flo, fhi) = (g64(&lo)?, g64(&hi)?);
    if !(flo < 0.0 && fhi > 0.0) {
        let c = material.c1().value() * indenter.cot_theta(&0.0_f64);
        // the speeds at the bracket's ends, computed afresh (flo + target cancels for a
        // target far outside)
        let v_at = |p: f64| -> Result<f64> {
            Ok(Case::new(material, indenter, p, solution)?.v_hat()? * c)
        };
        let sig = |x: f64| format!("{x:.4e}");
        return Err(WedgeError::InvalidParameter {
            name: "speed",
            value: format!("{} m/s", sig(speed)),
            range: format!(
                "({}, {}) m/s, the indenter speeds reached for alpha in (0, c_R)",
                sig(v_at(lo)?),
                sig(v_at(hi)?)
            ),
        });
    }
    let p64 = illinois(lo, flo, hi, fhi, &1e-16, g64)?;
    if like.prec() <= 53 {
        return Case::with_alpha(
            material,
            indenter,
            p64 * material.c1().value(),
            like,
            solution,
        )
        .or_else(|_| Case::new(material, indenter, like.lit(p64), solution));
    }
    // polish at the working precision: a Newton step with the f64 slope, then secant steps,
    // stopping as soon as |V(p) - V| is within the matching's own error estimate (about two
    // or three solves); the bracketed search below is the fallback
    let c1 = material.c1().to_real(like);
    let target = speed_param.to_real(like) / (c1 * indenter.cot_theta(like));
    let dp = 1e-7 * p64;
    let slope = (g64(&(p64 + dp))? - g64(&p64)?) / dp;
    let solve_at = |p: &T| -> Result<(T, Case<T>)> {
        let c = Case::new(material, indenter, p.clone(), solution)?;
        let f = c.v_hat()? - &target;
        Ok((f, c))
    };
    let floor = 4.0 * like.epsilon().to_f64() * target.to_f64().abs();
    let settled =
        |f: &T, c: &Case<T>| -> Result<bool> {
            Ok(f.clone().abs().to_f64()
                <= (c.matching()?.rel_error * target.to_f64().abs()).max(floor))
        };
    if slope.is_finite() && slope != 0.0 {
        let mut x0 = like.lit(p64);
        let (mut f0, c0) = solve_at(&x0)?;
        if settled(&f0, &c0)? {
            return Ok(c0);
        }
        let mut x1 = x0.clone() - f0.clone() / slope;
        for _ in 0..8 {
            if !(x1 > lo && x1 < hi) {
                break;
            }
            let (f1, c1_case) = solve_at(&x1)?;
            if settled(&f1, &c1_case)? {
                return Ok(c1_case);
            }
            let denom = f1.clone() - &f0;
            if denom.to_f64() == 0.0 {
                break;
            }
            let x2 = x1.clone() - f1.clone() * (x1.clone() - &x0) / denom;
            x0 = x1;
            f0 = f1;
            x1 = x2;
        }
    }
    let g = |p: &T| -> Result<T> {
        Ok(Case::new(material, indenter, p.clone(), solution)?.v_hat()? - &target)
    };
    let mut w = 1e-13;
    let (mut lo, mut hi);
    loop {
        lo = like.lit(p64 * (1.0 - w));
        hi = like.lit(p64 * (1.0 + w)).min(like.lit(m_r * BRACKET.1));
        let (a, b) = (g(&lo)?, g(&hi)?);
        if a < 0.0 && b > 0.0 {
            let p = illinois(lo, a, hi, b, &like.epsilon(), g)?;
            return Case::new(material, indenter, p, solution);
        }
        w *= 100.0;
        if w > 0.1 {
            return Err(WedgeError::NoConvergence {
                what: "inverse solve for alpha".into(),
                reached: w,
                asked: like.epsilon().to_f64(),
            });
        }
    }
}
