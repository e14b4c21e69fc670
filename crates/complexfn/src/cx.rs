//! A complex number over any [`Real`]: the one complex type of the workspace.
//!
//! `num_complex::Complex<T>` needs `T: Copy` for its elementary functions, which `rug::Float`
//! is not, so the complex arithmetic is written once here, generic over the precision layer.
//! Elementary functions use the principal branch with the cut on the negative real axis;
//! the branch of a value *on* a cut is decided by the sign bit of the imaginary part
//! (`-0.0` is below the cut). Code that needs boundary values on a cut never relies on that:
//! it asks for a side explicitly (see [`crate::Side`]).

use std::fmt;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

use crate::scalar::Real;

/// `re + i im`.
#[derive(Clone, Debug, PartialEq)]
pub struct Cx<T> {
    /// Real part.
    pub re: T,
    /// Imaginary part.
    pub im: T,
}

impl<T: Real> fmt::Display for Cx<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({} + {}i)", self.re, self.im)
    }
}

impl<T: Real> Cx<T> {
    /// `re + i im`.
    #[inline]
    pub fn new(re: T, im: T) -> Self {
        Cx { re, im }
    }
    /// The real number `re` (imaginary part +0).
    #[inline]
    pub fn real(re: T) -> Self {
        let im = re.zero();
        Cx { re, im }
    }
    /// `i im`.
    #[inline]
    pub fn imag(im: T) -> Self {
        let re = im.zero();
        Cx { re, im }
    }
    /// Mantissa length in bits.
    #[inline]
    pub fn prec(&self) -> u32 {
        self.re.prec()
    }
    /// `re + i im` from f64 parts, at the precision of `like`.
    #[inline]
    pub fn lit(like: &T, re: f64, im: f64) -> Self {
        Cx::new(like.lit(re), like.lit(im))
    }
    /// Complex conjugate.
    #[inline]
    pub fn conj(self) -> Self {
        Cx::new(self.re, -self.im)
    }
    /// `i * self`.
    #[inline]
    pub fn mul_i(self) -> Self {
        Cx::new(-self.im, self.re)
    }
    /// `-i * self`.
    #[inline]
    pub fn mul_neg_i(self) -> Self {
        Cx::new(self.im, -self.re)
    }
    /// |z|^2.
    #[inline]
    pub fn norm_sqr(&self) -> T {
        self.re.clone().sqr() + self.im.clone().sqr()
    }
    /// |z| (overflow-free).
    #[inline]
    pub fn abs(&self) -> T {
        self.re.clone().hypot(&self.im)
    }
    /// Principal argument in (-pi, pi].
    #[inline]
    pub fn arg(&self) -> T {
        self.im.clone().atan2(&self.re)
    }
    /// Multiply by a real.
    #[inline]
    pub fn scale(self, s: &T) -> Self {
        Cx::new(self.re * s, self.im * s)
    }
    /// Add a real.
    #[inline]
    pub fn add_re(self, x: &T) -> Self {
        Cx::new(self.re + x, self.im)
    }
    /// 1/z.
    pub fn recip(self) -> Self {
        let n = self.norm_sqr();
        Cx::new(self.re / &n, -(self.im / &n))
    }
    /// Principal square root (cut along the negative real axis, `Re sqrt >= 0`).
    pub fn sqrt(self) -> Self {
        let zero = self.re.zero();
        if self.re == 0.0 && self.im == 0.0 {
            return Cx::new(zero.clone(), self.im);
        }
        let r = self.abs();
        // t = sqrt((|z| + |re|)/2), computed without cancellation.
        let t = ((r + self.re.clone().abs()) / 2.0).sqrt();
        if !self.re.is_sign_negative() {
            let im = self.im / (t.clone() * 2.0);
            Cx::new(t, im)
        } else {
            let re = self.im.clone().abs() / (t.clone() * 2.0);
            Cx::new(re, t.copysign(&self.im))
        }
    }
    /// Principal logarithm. Near the unit circle (1/2 < |z|^2 < 2) the real part is
    /// ln_1p((x - 1)(x + 1) + y^2)/2, which keeps the relative accuracy of a small ln|z|
    /// (ln of the rounded |z| would lose eps/|ln|z||).
    pub fn ln(self) -> Self {
        let a = self.arg();
        let n = self.norm_sqr();
        let re = if n > 0.5 && n < 2.0 {
            let (x, y) = (self.re, self.im);
            let d = (x.clone() - 1.0) * (x + 1.0) + y.sqr();
            d.ln_1p() / 2.0
        } else {
            self.abs().ln()
        };
        Cx::new(re, a)
    }
    /// Exponential.
    pub fn exp(self) -> Self {
        let e = self.re.exp();
        let (s, c) = self.im.sin_cos();
        Cx::new(e.clone() * c, e * s)
    }
    /// Principal power `z^e` for a real exponent: exp(e ln z).
    pub fn powf(self, e: &T) -> Self {
        if self.re == 0.0 && self.im == 0.0 {
            return self;
        }
        let r = self.abs().powf(e);
        let a = self.arg() * e;
        let (s, c) = a.sin_cos();
        Cx::new(r.clone() * c, r * s)
    }
    /// Principal arctangent, atan z = (i/2) [ln(1 - i z) - ln(1 + i z)], cuts on the imaginary
    /// axis beyond +-i. Evaluated in the cancellation-free form (z = x + i y)
    ///
    /// ```text
    ///   Re atan z = atan2(2x, (1 - y)(1 + y) - x^2)/2,   Im atan z = log1p(4y/(x^2 + (1 - y)^2))/4,
    /// ```
    ///
    /// so that both parts keep full relative accuracy for small |z| (the difference of the two
    /// logarithms loses eps/|z| there).
    pub fn atan(self) -> Self {
        let one = self.re.one();
        let (x, y) = (self.re, self.im);
        let x2 = x.clone().sqr();
        // 1 - x^2 - y^2 with the cancellation near |y| = 1 taken out
        let d = (one.clone() - &y) * (one.clone() + &y) - x2.clone();
        let re = (x.clone() * 2.0).atan2(&d) / 2.0;
        let den = x2 + (one - &y).sqr();
        let im = (y * 4.0 / den).ln_1p() / 4.0;
        Cx::new(re, im)
    }
    /// Both parts finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
    /// Convert to `num_complex::Complex<f64>`.
    pub fn to_c64(&self) -> num_complex::Complex<f64> {
        num_complex::Complex::new(self.re.to_f64(), self.im.to_f64())
    }
}

impl<T: Real> Neg for Cx<T> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Cx::new(-self.re, -self.im)
    }
}
impl<T: Real> Add for Cx<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Cx::new(self.re + o.re, self.im + o.im)
    }
}
impl<'a, T: Real> Add<&'a Cx<T>> for Cx<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: &'a Cx<T>) -> Self {
        Cx::new(self.re + &o.re, self.im + &o.im)
    }
}
impl<T: Real> Sub for Cx<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Cx::new(self.re - o.re, self.im - o.im)
    }
}
impl<'a, T: Real> Sub<&'a Cx<T>> for Cx<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: &'a Cx<T>) -> Self {
        Cx::new(self.re - &o.re, self.im - &o.im)
    }
}
impl<'a, T: Real> Mul<&'a Cx<T>> for Cx<T> {
    type Output = Self;
    #[inline]
    fn mul(self, o: &'a Cx<T>) -> Self {
        let re = self.re.clone() * &o.re - self.im.clone() * &o.im;
        let im = self.re * &o.im + self.im * &o.re;
        Cx::new(re, im)
    }
}
impl<T: Real> Mul for Cx<T> {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        self * &o
    }
}
impl<'a, T: Real> Div<&'a Cx<T>> for Cx<T> {
    type Output = Self;
    fn div(self, o: &'a Cx<T>) -> Self {
        // Smith's algorithm: no overflow for large |o|.
        if o.re.clone().abs() >= o.im.clone().abs() {
            let r = o.im.clone() / &o.re;
            let d = o.re.clone() + o.im.clone() * &r;
            let re = (self.re.clone() + self.im.clone() * &r) / &d;
            let im = (self.im - self.re * &r) / &d;
            Cx::new(re, im)
        } else {
            let r = o.re.clone() / &o.im;
            let d = o.re.clone() * &r + &o.im;
            let re = (self.re.clone() * &r + &self.im) / &d;
            let im = (self.im * &r - self.re) / &d;
            Cx::new(re, im)
        }
    }
}
impl<T: Real> Div for Cx<T> {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        self / &o
    }
}
impl<T: Real> Add<f64> for Cx<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: f64) -> Self {
        Cx::new(self.re + o, self.im)
    }
}
impl<T: Real> Sub<f64> for Cx<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: f64) -> Self {
        Cx::new(self.re - o, self.im)
    }
}
impl<T: Real> Mul<f64> for Cx<T> {
    type Output = Self;
    #[inline]
    fn mul(self, o: f64) -> Self {
        Cx::new(self.re * o, self.im * o)
    }
}
impl<T: Real> Div<f64> for Cx<T> {
    type Output = Self;
    #[inline]
    fn div(self, o: f64) -> Self {
        Cx::new(self.re / o, self.im / o)
    }
}
impl<T: Real> AddAssign for Cx<T> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        self.re += o.re;
        self.im += o.im;
    }
}
impl<'a, T: Real> AddAssign<&'a Cx<T>> for Cx<T> {
    #[inline]
    fn add_assign(&mut self, o: &'a Cx<T>) {
        self.re += &o.re;
        self.im += &o.im;
    }
}
impl<T: Real> SubAssign for Cx<T> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        self.re -= o.re;
        self.im -= o.im;
    }
}
impl<T: Real> MulAssign<&Cx<T>> for Cx<T> {
    #[inline]
    fn mul_assign(&mut self, o: &Cx<T>) {
        let v = self.clone() * o;
        *self = v;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_complex::Complex64;
    use rug::Float;

    fn close(a: Cx<f64>, b: Complex64) -> bool {
        (a.to_c64() - b).norm() <= 1e-15 * b.norm().max(1.0)
    }

    #[test]
    fn elementary_functions_match_num_complex() {
        let pts = [
            (0.3, 0.7),
            (-2.0, 0.5),
            (-2.0, -0.5),
            (1e-3, -4.0),
            (-1.0, 1e-12),
        ];
        for &(x, y) in &pts {
            let z = Cx::new(x, y);
            let c = Complex64::new(x, y);
            assert!(close(z.clone().sqrt(), c.sqrt()), "sqrt {z}");
            assert!(close(z.clone().ln(), c.ln()), "ln {z}");
            assert!(close(z.clone().exp(), c.exp()), "exp {z}");
            assert!(close(z.clone().powf(&0.37), c.powf(0.37)), "pow {z}");
            assert!(close(z.clone().atan(), c.atan()), "atan {z}");
            let w = Cx::new(0.4, -1.3);
            assert!(
                close(z.clone() / &w, c / Complex64::new(0.4, -1.3)),
                "div {z}"
            );
        }
    }

    #[test]
    fn atan_keeps_relative_accuracy_for_small_arguments() {
        // against 256 bits, where the cancellation of the logarithmic form costs nothing
        // visible; and tan(atan z) = z
        for &(x, y) in &[(1e-14, 1e-14), (0.0, 1e-15), (3e-9, -2e-12), (0.3, 1e-13)] {
            let z = Cx::new(x, y);
            let big = Cx::new(Float::with_val(256, x), Float::with_val(256, y));
            let a = z.atan();
            let b = big.clone().atan();
            for (got, exact) in [(a.re, &b.re), (a.im, &b.im)] {
                let e = exact.to_f64();
                let err = (got - e).abs() / e.abs().max(1e-300);
                assert!(
                    exact.is_zero() || err < 1e-15,
                    "atan({x}, {y}): {got} vs {e}"
                );
            }
            // tan w = sin w/cos w = -i (e^{2iw} - 1)/(e^{2iw} + 1)
            let e2 = b.mul_i().scale(&Float::with_val(256, 2)).exp();
            let t = (e2.clone().add_re(&Float::with_val(256, -1))
                / &e2.add_re(&Float::with_val(256, 1)))
                .mul_neg_i();
            let d = (t - &big).abs() / big.abs();
            // (e^{2iw} - 1 itself loses 1e-77/|w| at 256 bits)
            assert!(d.to_f64() < 1e-55, "tan(atan z) at ({x}, {y})");
        }
    }

    #[test]
    fn sqrt_respects_the_sign_of_zero_on_the_cut() {
        assert_eq!(Cx::new(-4.0, 0.0).sqrt().im, 2.0);
        assert_eq!(Cx::new(-4.0, -0.0).sqrt().im, -2.0);
    }
}
