//! K, L and the Rayleigh function R of the paper (eqs (12b), (16c), (21)) and the Rayleigh root.
//!
//! With s = zeta^2, m = c2/c1 and the radicals p_k of [`crate::branch`],
//!
//! ```text
//!   K = 2 - s/m^2,   L = 2 - K p1 p2,   R = 4 - K^2 p1 p2.
//! ```
//!
//! R has a double zero at zeta = 0 and simple zeros at +-m_R = +-c_R/c1; L has a double zero
//! at 0. On (-m, m) both p_k flip sign across the axis, so p1 p2, L and R are continuous there
//! (R > 0 on (0, m_R), L < 0 on (0, m)).
//!
//! Near zeta = 0 both L and R cancel to O(s). With q = p1 p2 and w = 1/q, w^2 = (1-s)(1-s/m^2)
//! exactly, so w - 1 = (w^2 - 1)/(w + 1) with w^2 - 1 = -s(1 + 1/m^2 - s/m^2) a polynomial:
//!
//! ```text
//!   R/s = q [ -4 (1 + 1/m^2 - s/m^2)/(w + 1) + 4/m^2 - s/m^4 ],
//!   L/s = q [ -2 (1 + 1/m^2 - s/m^2)/(w + 1) + 1/m^2 ],
//! ```
//!
//! which are free of cancellation; [`RayleighValues::r_over_s`] and
//! [`RayleighValues::l_over_s`] use them for |s| < m^2 (the direct forms elsewhere).
//!
//! The Rayleigh root: R(zeta) = 0 with x = s/m^2 = (c_R/c2)^2 is the classical cubic
//! x^3 - 8x^2 + (24 - 16 m^2) x - 16 (1 - m^2) = 0 (after dividing out the root x = 0),
//! which has exactly one root in (0, 1) for 0 < m^2 < 3/4 (f(0) < 0 < f(1) = 1).

use crate::branch::{p_boundary, p_k, Side};
use crate::cx::Cx;
use crate::error::{Error, Result};
use crate::scalar::Real;

/// The speed ratio m = c2/c1 with its Rayleigh root m_R = c_R/c1: the functions K, L, R and
/// p_k for one material, at the precision of `m`.
#[derive(Clone, Debug)]
pub struct Rayleigh<T> {
    m: T,
    m2: T,
    inv_m2: T,
    m_r: T,
    /// x_R = (m_R/m)^2, the root of the Rayleigh cubic.
    x_r: T,
}

/// p1, p2, K, L, R (and the cancellation-free L/s, R/s) at one point.
#[derive(Clone, Debug)]
pub struct RayleighValues<T> {
    /// p_1 = (1 - zeta^2)^(-1/2).
    pub p1: Cx<T>,
    /// p_2 = (1 - zeta^2/m^2)^(-1/2).
    pub p2: Cx<T>,
    /// K = 2 - zeta^2/m^2.
    pub k: Cx<T>,
    /// L = 2 - K p1 p2 (eq (21)).
    pub l: Cx<T>,
    /// R = 4 - K^2 p1 p2 (eq (16c)).
    pub r: Cx<T>,
    /// L / zeta^2, free of cancellation near 0.
    pub l_over_s: Cx<T>,
    /// R / zeta^2, free of cancellation near 0.
    pub r_over_s: Cx<T>,
}

impl<T: Real> Rayleigh<T> {
    /// The family for speed ratio `m` = c2/c1, which must satisfy 0 < m < sqrt(3)/2
    /// (Poisson's ratio in (-1, 1/2)).
    pub fn new(m: T) -> Result<Self> {
        let mf = m.to_f64();
        if !m.is_finite() || !(m > 0.0) || !(m.clone().sqr() < 0.75) {
            return Err(Error::InvalidParameter(crate::error::InvalidParameter {
                name: "m = c2/c1",
                value: format!("{mf}"),
                range: "(0, sqrt(3)/2)".into(),
            }));
        }
        let m2 = m.clone().sqr();
        let inv_m2 = m2.clone().recip();
        let x = rayleigh_cubic_root(&m2)?;
        let m_r = m.clone() * x.clone().sqrt();
        Ok(Rayleigh {
            m,
            m2,
            inv_m2,
            m_r,
            x_r: x,
        })
    }

    /// m = c2/c1.
    pub fn m(&self) -> &T {
        &self.m
    }
    /// m^2.
    pub fn m2(&self) -> &T {
        &self.m2
    }
    /// 1/m^2.
    pub fn inv_m2(&self) -> &T {
        &self.inv_m2
    }
    /// m_R = c_R/c1, the positive simple zero of R.
    pub fn m_r(&self) -> &T {
        &self.m_r
    }

    /// p1, p2, K, L, R at a point zeta off the real axis (or on it outside (-m, m), or in
    /// (-m, m) with the side given by the sign bit of `Im zeta`).
    pub fn at(&self, zeta: &Cx<T>) -> RayleighValues<T> {
        let one = self.m.one();
        let p1 = p_k(zeta, &one);
        let p2 = p_k(zeta, &self.m);
        self.with_radicals(zeta.clone() * zeta, p1, p2)
    }

    /// Boundary values f(xi +- i0) of p1, p2, K, L, R on the real axis.
    pub fn at_boundary(&self, xi: &T, side: Side) -> RayleighValues<T> {
        let one = self.m.one();
        let p1 = p_boundary(xi, &one, side);
        let p2 = p_boundary(xi, &self.m, side);
        let s = xi.clone().sqr();
        self.with_radicals(Cx::real(s), p1, p2)
    }

    /// (|p1|, |p2|, L/xi^2) on the cut 0 <= xi < m, in real arithmetic (the lower boundary
    /// values; L/xi^2 in the cancellation-free form of the module docs). The fast path of the
    /// functions of xi^2 that only need these three.
    pub fn cut_values(&self, xi: &T) -> (T, T, T) {
        let s = xi.clone().sqr();
        let one = s.one();
        let sm = s.clone() * &self.inv_m2;
        let p1 = (one.clone() - &s).sqrt().recip();
        let p2 = (one.clone() - &sm).sqrt().recip();
        let q = p1.clone() * &p2;
        let w1 = q.clone().recip() + 1.0;
        let a = one + &self.inv_m2 - sm;
        let l_s = q * (self.inv_m2.clone() - a * 2.0 / w1);
        (p1, p2, l_s)
    }

    /// The analytic continuation, in s = zeta^2, of the lower boundary values on (0, m):
    /// p_k = (1 - s/m_k^2)^(-1/2) with the principal power (real positive for s < m_k^2), so
    /// that functions of xi^2 built from |p1|, |p2|, L and R on (0, m) extend to complex s.
    pub fn continued(&self, s: &Cx<T>) -> RayleighValues<T> {
        let one = s.re.one();
        let minus_half = s.re.lit(-0.5);
        let p1 = (-s.clone()).add_re(&one).powf(&minus_half);
        let p2 = (-s.clone().scale(&self.inv_m2))
            .add_re(&one)
            .powf(&minus_half);
        self.with_radicals(s.clone(), p1, p2)
    }

    /// R(xi)/(xi - m_R) for real 0 <= xi < m, free of cancellation at the Rayleigh root.
    ///
    /// With x = xi^2/m^2 and w = sqrt((1 - xi^2)(1 - x)), 16 w^2 - K^4 = -x c(x) where
    /// c(x) = (x - x_R)(x^2 + (x_R - 8) x + 24 - 16 m^2 + x_R (x_R - 8)) is the Rayleigh cubic,
    /// and R = (4w - K^2)/w on (0, m), so
    /// R/(xi - m_R) = -x (xi + m_R) q(x) / (m^2 w (4w + K^2)), q the deflated quadratic.
    pub fn r_over_xi_minus_root(&self, xi: &T) -> T {
        let s = xi.clone().sqr();
        let x = s.clone() * &self.inv_m2;
        let one = s.one();
        let w = ((one.clone() - &s) * (one - &x)).sqrt();
        let k = s.lit(2.0) - &x;
        let a = self.x_r.clone() - 8.0;
        let c1 = s.lit(24.0) - self.m2.clone() * 16.0;
        let quad = (x.clone() + &a) * &x + c1 + self.x_r.clone() * &a;
        let den = self.m2.clone() * &w * (w.clone() * 4.0 + k.sqr());
        -(x * (xi.clone() + &self.m_r) * quad) / den
    }

    fn with_radicals(&self, s: Cx<T>, p1: Cx<T>, p2: Cx<T>) -> RayleighValues<T> {
        let q = p1.clone() * &p2;
        let k = Cx::real(s.re.lit(2.0)) - s.clone().scale(&self.inv_m2);
        let w = q.clone().recip();
        // The cancellation-free form needs w + 1 away from 0 (w = -1 at s = 1 + m^2, on the
        // far side of the branch points); it covers the whole cut (0, m^2) where 0 < w <= 1.
        let small = s.abs() < self.m2 && w.clone().add_re(&s.re.one()).abs() > 0.5;
        let (l, r, l_over_s, r_over_s) = if small {
            let a = Cx::real(s.re.one() + &self.inv_m2) - s.clone().scale(&self.inv_m2);
            let inv_w1 = w.add_re(&s.re.one()).recip();
            let inv_m4 = self.inv_m2.clone().sqr();
            let rho_r = Cx::real(self.inv_m2.clone() * 4.0)
                - a.clone() * &inv_w1 * 4.0
                - s.clone().scale(&inv_m4);
            let rho_l = Cx::real(self.inv_m2.clone()) - a * &inv_w1 * 2.0;
            let r_over_s = q.clone() * &rho_r;
            let l_over_s = q.clone() * &rho_l;
            (
                l_over_s.clone() * &s,
                r_over_s.clone() * &s,
                l_over_s,
                r_over_s,
            )
        } else {
            let kq = k.clone() * &q;
            let l = Cx::real(s.re.lit(2.0)) - kq.clone();
            let r = Cx::real(s.re.lit(4.0)) - kq * &k;
            (l.clone(), r.clone(), l / &s, r / &s)
        };
        RayleighValues {
            p1,
            p2,
            k,
            l,
            r,
            l_over_s,
            r_over_s,
        }
    }

    /// dR/dxi for real 0 < xi < m (where R is real and analytic):
    /// with w = sqrt((1-s)(1-s/m^2)), R = 4 - K^2/w and
    /// dR/ds = 2K/(m^2 w) + K^2 w'(s)/w^2, w'(s) = -[(1 - s/m^2) + (1 - s)/m^2]/(2w).
    pub fn r_prime(&self, xi: &T) -> T {
        let s = xi.clone().sqr();
        let one = s.one();
        let a = one.clone() - &s;
        let b = one - s.clone() * &self.inv_m2;
        let w = (a.clone() * &b).sqrt();
        let k = s.lit(2.0) - s.clone() * &self.inv_m2;
        let dw = -(b + a * &self.inv_m2) / (w.clone() * 2.0);
        let dr_ds = k.clone() * &self.inv_m2 * 2.0 / &w + k.sqr() * dw / w.sqr();
        dr_ds * xi * 2.0
    }

    /// R'(m_R), the derivative at the Rayleigh root (negative).
    pub fn r_prime_at_root(&self) -> T {
        self.r_prime(&self.m_r)
    }
}

/// The root x = (c_R/c2)^2 in (0, 1) of x^3 - 8x^2 + (24 - 16 m^2) x - 16 (1 - m^2),
/// by Newton's method safeguarded with bisection, to the precision of `m2`.
fn rayleigh_cubic_root<T: Real>(m2: &T) -> Result<T> {
    let c1 = m2.lit(24.0) - m2.clone() * 16.0;
    let c0 = (m2.lit(1.0) - m2) * 16.0;
    let f = |x: &T| -> (T, T) {
        let v = ((x.clone() - 8.0) * x + &c1) * x - &c0;
        let d = (x.clone() * 3.0 - 16.0) * x + &c1;
        (v, d)
    };
    let mut lo = m2.zero();
    let mut hi = m2.one();
    let mut x = m2.lit(0.85);
    let eps = m2.epsilon();
    for _ in 0..(200 + m2.prec()) {
        let (v, d) = f(&x);
        if v == 0.0 {
            return Ok(x);
        }
        if v < 0.0 {
            lo = x.clone();
        } else {
            hi = x.clone();
        }
        let step = v / d;
        let mut nx = x.clone() - &step;
        if !(nx > lo && nx < hi && nx.is_finite()) {
            nx = (lo.clone() + &hi) / 2.0;
        }
        let dx = (nx.clone() - &x).abs();
        x = nx;
        if dx <= eps.clone() * &x * 0.5 {
            // one more Newton step polishes the last bit
            let (v, d) = f(&x);
            return Ok(x - v / d);
        }
        if (hi.clone() - &lo) <= eps.clone() * &x * 0.25 {
            return Ok(x);
        }
    }
    Err(Error::NoConvergence(crate::error::NoConvergence {
        what: "Rayleigh root".into(),
        reached: (hi - lo).to_f64(),
        asked: eps.to_f64(),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    #[test]
    fn cancellation_free_forms_agree_with_the_direct_ones_away_from_zero() {
        let ray = Rayleigh::new(0.534_f64).unwrap();
        for &(x, y) in &[(0.13, 0.01), (0.1, -0.2), (-0.2, 0.12)] {
            let z = Cx::new(x, y);
            let v = ray.at(&z);
            let s = z.clone() * &z;
            let q = v.p1.clone() * &v.p2;
            let r_direct = Cx::new(4.0, 0.0) - v.k.clone() * &v.k * &q;
            let l_direct = Cx::new(2.0, 0.0) - v.k.clone() * &q;
            assert!((v.r.clone() - &r_direct).abs() < 1e-13 * r_direct.abs().max(1e-3));
            assert!((v.l.clone() - &l_direct).abs() < 1e-13 * l_direct.abs().max(1e-3));
            assert!((v.r_over_s.clone() * &s - &v.r).abs() < 1e-14);
        }
    }

    #[test]
    fn r_over_s_at_zero_is_two_over_m2_minus_two() {
        // R/s -> 2/m^2 - 2 and L/s -> -1 as zeta -> 0 (from the expansion in the module docs).
        let m = 0.534_f64;
        let ray = Rayleigh::new(m).unwrap();
        let v = ray.at_boundary(&1e-9, Side::Lower);
        assert!((v.r_over_s.re - (2.0 / (m * m) - 2.0)).abs() < 1e-12);
        assert!((v.l_over_s.re + 1.0).abs() < 1e-12);
    }

    #[test]
    fn r_prime_matches_a_difference_quotient_at_256_bits() {
        let m = Float::with_val(256, 0.534);
        let ray = Rayleigh::new(m).unwrap();
        let x = Float::with_val(256, 0.31);
        let h = Float::with_val(256, 1e-26);
        let rp = ray.at_boundary(&(x.clone() + &h), Side::Lower).r.re;
        let rm = ray.at_boundary(&(x.clone() - &h), Side::Lower).r.re;
        let fd = (rp - rm) / (h * 2.0);
        let d = ray.r_prime(&x);
        assert!(crate::scalar::rel_diff(&fd, &d) < 1e-45);
    }

    #[test]
    fn deflated_rayleigh_function_matches_r_away_from_the_root() {
        let ray = Rayleigh::new(0.534_f64).unwrap();
        for xi in [0.05, 0.2, 0.45, 0.52] {
            let r = ray.at_boundary(&xi, Side::Lower).r.re;
            let d = ray.r_over_xi_minus_root(&xi) * (xi - ray.m_r());
            assert!((r - d).abs() < 1e-14 * r.abs().max(1e-3), "{xi}: {r} {d}");
        }
        // at the root it is R'(m_R)
        let mr = *ray.m_r();
        assert!((ray.r_over_xi_minus_root(&mr) - ray.r_prime_at_root()).abs() < 1e-13);
    }

    #[test]
    fn continuation_in_s_matches_the_lower_boundary_values() {
        let ray = Rayleigh::new(0.534_f64).unwrap();
        for xi in [0.1, 0.4, 0.5] {
            let b = ray.at_boundary(&xi, Side::Lower);
            let c = ray.continued(&Cx::new(xi * xi, 0.0));
            assert!((b.l_over_s.clone() - &c.l_over_s).abs() < 1e-14);
            assert!((b.p2.clone() - &c.p2).abs() < 1e-14);
        }
    }

    #[test]
    fn cut_values_match_the_boundary_values() {
        let ray = Rayleigh::new(0.534_f64).unwrap();
        for xi in [0.0, 1e-5, 0.2, 0.49, 0.53] {
            let b = ray.at_boundary(&xi, Side::Lower);
            let (p1, p2, l_s) = ray.cut_values(&xi);
            assert!((p1 - b.p1.re).abs() < 1e-15 * p1 && (p2 - b.p2.re).abs() < 1e-14 * p2);
            assert!(
                (l_s - b.l_over_s.re).abs() < 1e-14 * l_s.abs(),
                "{xi}: {l_s} {}",
                b.l_over_s.re
            );
        }
    }

    #[test]
    fn bad_m_is_refused_with_its_range() {
        for m in [0.0, -0.1, 0.9, f64::NAN, f64::INFINITY] {
            let e = Rayleigh::new(m).unwrap_err();
            assert!(e.to_string().contains("(0, sqrt(3)/2)"), "{e}");
        }
    }
}
