//! Scalar root finding shared by the inverse solves (indenter speed to contact speed).
//!
//! Two contracts:
//! - [`illinois`]: a bracketed search (regula falsi with the Illinois modification and a
//!   bisection safeguard) that keeps the bracket and stops once it is `tol` wide relative to
//!   its ends;
//! - [`secant_polish`]: from a good first guess (typically the f64 root) and an f64 slope, a
//!   Newton step then secant steps at the working precision, each evaluation returning a
//!   value and the object it was computed from, stopping as soon as the caller's own
//!   accuracy test accepts one. It gives up (returns `None`) rather than wander: the caller
//!   falls back to a bracketed search.

use crate::scalar::Real;

/// The root of `f` in the bracket `[lo, hi]` (with `f(lo) = flo` and `f(hi) = fhi` of
/// opposite signs), to a relative width `tol`, by Illinois regula falsi with a bisection
/// safeguard; at most 200 evaluations.
pub fn illinois<T: Real, E, F: FnMut(&T) -> Result<T, E>>(
    mut lo: T,
    mut flo: T,
    mut hi: T,
    mut fhi: T,
    tol: &T,
    mut f: F,
) -> Result<T, E> {
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

/// Polish a root from the first guess `x0` with a Newton step of slope `slope` (usually
/// measured in f64), then at most `steps` secant steps, all at the precision of `x0`.
///
/// `eval(x)` returns `(f(x), c)` where `c` is whatever the evaluation built (a solved case);
/// `settled(f(x), &c)` says whether `x` is accurate enough (the caller compares `|f|` with
/// the case's own error estimate). Returns the first accepted `c`, or `None` when the slope
/// is not finite and non-zero, an iterate leaves the open interval `bracket` (tested in
/// f64), two values coincide, or the steps run out.
pub fn secant_polish<T, C, E>(
    x0: T,
    slope: f64,
    bracket: (f64, f64),
    steps: usize,
    mut eval: impl FnMut(&T) -> Result<(T, C), E>,
    mut settled: impl FnMut(&T, &C) -> Result<bool, E>,
) -> Result<Option<C>, E>
where
    T: Real,
{
    if !(slope.is_finite() && slope != 0.0) {
        return Ok(None);
    }
    let inside = |x: &T| {
        let xf = x.to_f64();
        xf > bracket.0 && xf < bracket.1
    };
    let mut x0 = x0;
    let (mut f0, c0) = eval(&x0)?;
    if settled(&f0, &c0)? {
        return Ok(Some(c0));
    }
    let mut x1 = x0.clone() - f0.clone() / slope;
    for _ in 0..steps {
        if !inside(&x1) {
            return Ok(None);
        }
        let (f1, c1) = eval(&x1)?;
        if settled(&f1, &c1)? {
            return Ok(Some(c1));
        }
        let denom = f1.clone() - &f0;
        if denom.to_f64() == 0.0 {
            return Ok(None);
        }
        let x2 = x1.clone() - f1.clone() * (x1.clone() - &x0) / denom;
        x0 = x1;
        f0 = f1;
        x1 = x2;
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn illinois_finds_a_cube_root() {
        let f = |x: &f64| -> Result<f64, ()> { Ok(x * x * x - 2.0) };
        let r = illinois(1.0, -1.0, 2.0, 6.0, &1e-15, f).unwrap();
        assert!((r - 2f64.cbrt()).abs() < 1e-14, "{r}");
    }

    #[test]
    fn secant_polish_reaches_the_working_precision() {
        let prec = 200;
        let two = rug::Float::with_val(prec, 2);
        let exact = two.clone().sqrt();
        let eval = |x: &rug::Float| -> Result<(rug::Float, rug::Float), ()> {
            Ok((x.clone() * x - &two, x.clone()))
        };
        let tol = rug::Float::with_val(prec, 1e-55);
        let settled = |f: &rug::Float, _: &rug::Float| Ok(f.clone().abs() < tol);
        let x0 = rug::Float::with_val(prec, 2f64.sqrt());
        let root = secant_polish(x0, 2.0 * 2f64.sqrt(), (1.0, 2.0), 8, eval, settled)
            .unwrap()
            .expect("settles");
        assert!((root - exact).abs() < 1e-54);
    }

    #[test]
    fn secant_polish_gives_up_outside_the_bracket() {
        let eval = |x: &f64| -> Result<(f64, f64), ()> { Ok((x - 10.0, *x)) };
        let settled = |f: &f64, _: &f64| Ok(f.abs() < 1e-12);
        assert_eq!(
            secant_polish(1.5, 1.0, (1.0, 2.0), 8, eval, settled),
            Ok(None)
        );
        let settled = |f: &f64, _: &f64| Ok(f.abs() < 1e-12);
        assert_eq!(
            secant_polish(1.5, f64::NAN, (1.0, 2.0), 8, eval, settled),
            Ok(None)
        );
    }
}
