//! The inverse problem: the contact-zone speed alpha for a given indenter speed V.
//!
//! V/(c1 cot Theta) is an increasing function of p = alpha/c1 on (0, m_R) (it is checked at
//! the bracket ends, and the solve fails with a clear error if the target is outside the
//! range reached). One search serves every solution variant ([`for_speed`] over a
//! [`Solver`]). The root is bracketed in f64 first (Illinois regula falsi with bisection
//! safeguard), then polished at the working precision by the same iteration started from a
//! narrow bracket around the f64 root.

use complexfn::quadrature::CachedRules;
use complexfn::roots::{illinois, secant_polish};

use crate::case::Case;
use crate::error::{invalid, Result, WedgeError};
use crate::params::{Indenter, Material, Param, Solution};
use crate::solved::{ContactSolution, PaperSolver, Solver};

/// Smallest and largest p = alpha/c1 used to bracket the inverse solve, as fractions of m_R.
pub const BRACKET: (f64, f64) = (1e-6, 1.0 - 1e-6);

/// The case whose indenter speed is `speed` (m/s), at the precision of `like`: the paper's
/// construction ([`for_speed`] with a [`PaperSolver`]).
pub fn case_for_speed<T: CachedRules>(
    material: &Material,
    indenter: &Indenter,
    speed: impl Into<Param>,
    like: &T,
    solution: Solution,
) -> Result<Case<T>> {
    for_speed(
        &PaperSolver::new(material, indenter, solution),
        &speed.into(),
        like,
    )
}

/// The case of `solver`'s variant whose indenter speed is `speed` (m/s, decimal text parsed
/// at the precision of `like`), for every solution variant: p is bracketed on
/// [`BRACKET`] m_R in f64 (Illinois), then, above f64, polished at the working precision by
/// a Newton step with the f64 slope and secant steps that stop as soon as |V(p) - V| is
/// within the solve's own error estimate of V (about two or three solves); a bracketed search
/// at the working precision is the fallback. A speed outside the range reached for
/// 0 < alpha < c_R is refused with that range.
pub fn for_speed<S: Solver, T: CachedRules>(
    solver: &S,
    speed_param: &Param,
    like: &T,
) -> Result<S::Solved<T>> {
    let (material, indenter) = (solver.material(), solver.indenter());
    let speed = speed_param.value();
    if !(speed.is_finite() && speed > 0.0) {
        return Err(invalid("speed", speed_param.text(), "(0, inf) m/s"));
    }
    // f64 solve
    let m_r = material.m_r()?;
    let c = material.c1().value() * indenter.cot_theta(&0.0_f64);
    let target64 = speed / c;
    let v64 = |p: f64| -> Result<f64> { Ok(solver.solve(p)?.v_hat()?.value) };
    let g64 = |p: &f64| -> Result<f64> { Ok(v64(*p)? - target64) };
    let (lo, hi) = (m_r * BRACKET.0, m_r * BRACKET.1);
    let (flo, fhi) = (g64(&lo)?, g64(&hi)?);
    if !(flo < 0.0 && fhi > 0.0) {
        // the speeds at the bracket's ends, computed afresh (flo + target cancels for a
        // target far outside)
        let sig = |x: f64| format!("{x:.4e}");
        return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
            name: "speed",
            value: format!("{} m/s", sig(speed)),
            range: format!(
                "({}, {}) m/s, the indenter speeds reached for alpha in (0, c_R)",
                sig(v64(lo)? * c),
                sig(v64(hi)? * c)
            ),
        }));
    }
    let p64 = illinois(lo, flo, hi, fhi, &1e-16, g64)?;
    if like.prec() <= 53 {
        return solver.solve(like.lit(p64));
    }
    // polish at the working precision
    let c1 = material.c1().to_real(like);
    let target = speed_param.to_real(like) / (c1 * indenter.cot_theta(like));
    let dp = 1e-7 * p64;
    let slope = (g64(&(p64 + dp))? - g64(&p64)?) / dp;
    let solve_at = |p: &T| -> Result<(T, S::Solved<T>)> {
        let c = solver.solve(p.clone())?;
        let f = c.v_hat()?.value - &target;
        Ok((f, c))
    };
    let floor = 4.0 * like.epsilon().to_f64() * target.to_f64().abs();
    let settled = |f: &T, c: &S::Solved<T>| -> Result<bool> {
        Ok(f.clone().abs().to_f64() <= c.v_hat()?.error.max(floor))
    };
    if let Some(case) = secant_polish(like.lit(p64), slope, (lo, hi), 8, &solve_at, &settled)? {
        return Ok(case);
    }
    let g = |p: &T| -> Result<T> { Ok(solver.solve(p.clone())?.v_hat()?.value - &target) };
    let mut w = 1e-13;
    let (mut lo, mut hi);
    loop {
        lo = like.lit(p64 * (1.0 - w));
        hi = like.lit(p64 * (1.0 + w)).min(like.lit(m_r * BRACKET.1));
        let (a, b) = (g(&lo)?, g(&hi)?);
        if a < 0.0 && b > 0.0 {
            let p = illinois(lo, a, hi, b, &like.epsilon(), g)?;
            return solver.solve(p);
        }
        w *= 100.0;
        if w > 0.1 {
            return Err(WedgeError::NoConvergence(complexfn::NoConvergence {
                what: "inverse solve for alpha".into(),
                reached: w,
                asked: like.epsilon().to_f64(),
            }));
        }
    }
}
