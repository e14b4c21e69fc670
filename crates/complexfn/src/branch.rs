//! The radicals p_k(zeta) = (1 - zeta^2/m_k^2)^(-1/2) with the paper's cuts (eq (15), Fig. 2).
//!
//! p_k is analytic in the zeta-plane cut along the segment |Re zeta| < m_k of the real axis
//! (not the principal branch, whose cuts would run along |Re zeta| > m_k). The branch is fixed
//! by the sign on the cut (`docs/errata.md`, section 1): the paper's eqs (26b), (27b) and (31) need
//!
//! ```text
//!   p_k(xi - i0) = +|p_k(xi)|,   p_k(xi + i0) = -|p_k(xi)|        for |xi| < m_k,
//! ```
//!
//! so that, in closed form with principal square roots,
//!
//! ```text
//!   p_k(zeta) = -i m_k / ( sqrt(zeta - m_k) sqrt(zeta + m_k) ),
//! ```
//!
//! an odd function, continuous across the real axis for |xi| > m_k where
//! p_k(xi) = -i sgn(xi) (xi^2/m_k^2 - 1)^(-1/2), with p_k(i y) < 0 for y > 0 and
//! p_k(zeta) ~ -i m_k / zeta at infinity. (The OCR of the paper writes p_k where |p_k| is meant
//! in (56)-(57); see the wedge crate.)

use crate::cx::Cx;
use crate::scalar::Real;

/// Side of the real axis on which a boundary value f(xi +- i0) is taken (eq (20)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// f^+(xi) = f(xi + i0).
    Upper,
    /// f^-(xi) = f(xi - i0).
    Lower,
}

impl Side {
    /// +1 for `Upper`, -1 for `Lower`.
    #[inline]
    pub fn sign(self) -> f64 {
        match self {
            Side::Upper => 1.0,
            Side::Lower => -1.0,
        }
    }
    /// The other side.
    #[inline]
    pub fn flip(self) -> Side {
        match self {
            Side::Upper => Side::Lower,
            Side::Lower => Side::Upper,
        }
    }
    /// The side of the real axis a point lies on; a point with `Im z == +0` counts as upper,
    /// `-0` as lower.
    #[inline]
    pub fn of<T: Real>(z: &Cx<T>) -> Side {
        if z.im.is_sign_negative() {
            Side::Lower
        } else {
            Side::Upper
        }
    }
}

/// p_k(zeta) off the real axis (or on it outside the cut), eq (15) with the branch above.
///
/// `mk` is m_1 = 1 or m_2 = m. For a point on the cut the side is taken from the sign bit of
/// `Im zeta`; prefer [`p_boundary`] there.
pub fn p_k<T: Real>(zeta: &Cx<T>, mk: &T) -> Cx<T> {
    let a = zeta.clone().add_re(&-mk.clone()).sqrt();
    let b = zeta.clone().add_re(mk).sqrt();
    // -i m_k / (a b)
    let d = a * &b;
    Cx::imag(-mk.clone()) / &d
}

/// Boundary value p_k(xi +- i0) on the real axis.
///
/// * |xi| < m_k: `Upper` gives -|p_k|, `Lower` gives +|p_k| with |p_k| = (1 - xi^2/m_k^2)^(-1/2);
/// * |xi| > m_k: both sides give -i sgn(xi) (xi^2/m_k^2 - 1)^(-1/2).
///
/// The factors (1 -+ xi/m_k) are formed separately so the value stays accurate near the
/// branch points.
pub fn p_boundary<T: Real>(xi: &T, mk: &T, side: Side) -> Cx<T> {
    let x = xi.clone() / mk;
    let ax = x.clone().abs();
    if ax < 1.0 {
        let one = x.one();
        let mag = ((one.clone() - &x) * (one + &x)).sqrt().recip();
        match side {
            Side::Upper => Cx::real(-mag),
            Side::Lower => Cx::real(mag),
        }
    } else {
        let mag = ((ax.clone() - 1.0) * (ax + 1.0)).sqrt().recip();
        if xi.is_sign_negative() {
            Cx::imag(mag)
        } else {
            Cx::imag(-mag)
        }
    }
}

/// p_k evaluated "in the same quadrant as zeta_k", as eq (12) requires: the real argument `v`
/// takes the sign of `Re zeta_k` and, on the cut, the side of `Im zeta_k`.
pub fn p_same_quadrant<T: Real>(v: &T, mk: &T, zeta_k: &Cx<T>) -> Cx<T> {
    let av = v.clone().abs();
    let x = if zeta_k.re.is_sign_negative() {
        -av
    } else {
        av
    };
    p_boundary(&x, mk, Side::of(zeta_k))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_form_is_a_branch_of_the_radical() {
        // p^2 (1 - z^2/m^2) = 1 everywhere off the cut.
        let m = 0.534_f64;
        for &(x, y) in &[
            (0.2, 0.3),
            (-0.7, -0.1),
            (1.5, 2.0),
            (-3.0, 0.01),
            (0.1, -5.0),
        ] {
            let z = Cx::new(x, y);
            let p = p_k(&z, &m);
            let one_minus = Cx::new(1.0, 0.0) - z.clone() * &z / (m * m);
            let e = p.clone() * &p * &one_minus - Cx::new(1.0, 0.0);
            assert!(e.abs() < 1e-14, "{z}: {e}");
        }
    }

    #[test]
    fn sign_conventions_of_the_errata() {
        let m = 1.0_f64;
        // p(iy) < 0 for y > 0
        let p = p_k(&Cx::new(0.0, 0.5), &m);
        assert!(p.re < 0.0 && p.im.abs() < 1e-16);
        // odd
        let z = Cx::new(0.3, 0.2);
        let s = p_k(&z, &m) + p_k(&(-z), &m);
        assert!(s.abs() < 1e-15);
        // ~ -i m/zeta at infinity
        let big = Cx::new(1e6, 3e5);
        let r = p_k(&big, &m) * &big;
        assert!((r - Cx::new(0.0, -1.0)).abs() < 1e-11);
    }

    #[test]
    fn boundary_values_are_limits_from_each_side() {
        let m = 0.534_f64;
        for mk in [1.0, m] {
            for &xi in &[-1.7, -0.9, -0.3, 0.0, 0.25, 0.5, 0.8, 1.4] {
                for side in [Side::Upper, Side::Lower] {
                    let eps = 1e-10 * side.sign();
                    let off = p_k(&Cx::new(xi, eps), &mk);
                    let on = p_boundary(&xi, &mk, side);
                    let d = (off - &on).abs() / on.abs();
                    assert!(d < 1e-8, "xi {xi} mk {mk} {side:?}: {d}");
                }
            }
        }
    }
}
