//! A double-double scalar: the fast extended-precision backend of [`Real`].
//!
//! A value is the unevaluated sum `hi + lo` of two doubles with `|lo| <= ulp(hi)/2`, about
//! 106 bits of mantissa (32 decimal digits) at a few times the cost of `f64` and, unlike
//! MPFR, `Copy` and allocation-free. The arithmetic is the classical one of Dekker and of
//! Hida, Li and Bailey's QD library (error-free `two_sum` and `two_prod`, renormalisation
//! after each operation); the elementary functions are written here for this type, each
//! with its argument reduction and series stated at the function and tested against MPFR
//! at 256 bits (`tests` below and `tests/double_double.rs`). The derivation of the accuracy
//! policy is in `docs/double-double.md`.
//!
//! Accuracy contract: arithmetic and `sqrt` are accurate to a few units of 2^-106; the
//! elementary functions to a relative 2^-100 or better over the arguments the workspace
//! uses (-671 < x < 709.78 for `exp`, results above the normal floor below; any positive
//! finite argument of `ln`; |x| < 2^20 for the trigonometric functions, including their
//! zeros), except `powf` and `powi`, whose relative errors grow like |e ln x| 2^-106 (the
//! error of the exponent handed to `exp`) and |n| 2^-106. [`Real::prec`] reports 104
//! bits, so that [`Real::epsilon`] (2^-103) bounds every one of these with a margin, and the
//! estimates built on it stay on the safe side. The exponent range is that of `f64`, with
//! the low part's precision lost below 2^-969 ([`Real::normal_floor`]).
//!
//! Infinities and NaN follow IEEE arithmetic on the leading part (x/0 is infinite, not NaN,
//! as for `f64`).
//!
//! Conversions from and to MPFR (`from_mpfr`, `to_mpfr`, decimal text) are exact or
//! correctly rounded.

use std::cmp::Ordering;
use std::fmt::{self, Display};
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use rug::Float;

use crate::error::Result;
use crate::scalar::Real;

/// The mantissa length a double-double reports ([`Real::prec`]): 104 of its about 106
/// bits, the margin covering the few units of roundoff of each operation.
pub const DD_BITS: u32 = 104;

/// A double-double number `hi + lo` (`|lo| <= ulp(hi)/2`): see the [module](self) docs.
#[derive(Clone, Copy, Debug, Default)]
pub struct Dd {
    hi: f64,
    lo: f64,
}

// ---- error-free transformations --------------------------------------------------------

/// `a + b = s + e` exactly, `s = fl(a + b)`.
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly when `|a| >= |b|` (or a = 0).
#[inline(always)]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a = hi + lo` with 26-bit halves (Veltkamp), scaled so that the splitter cannot overflow.
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    const THRESH: f64 = 6.696_928_794_914_17e299; // 2^996
    if a.abs() > THRESH {
        let b = a * 3.725_290_298_461_914e-9; // 2^-28
        let t = SPLITTER * b;
        let hi = t - (t - b);
        let lo = b - hi;
        (hi * 268_435_456.0, lo * 268_435_456.0)
    } else {
        let t = SPLITTER * a;
        let hi = t - (t - a);
        (hi, a - hi)
    }
}

/// `a b = p + e` exactly, `p = fl(a b)`.
#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    #[cfg(target_feature = "fma")]
    {
        (p, a.mul_add(b, -p))
    }
    #[cfg(not(target_feature = "fma"))]
    {
        if p.abs() > 1e300 {
            // the halves' products could overflow: the library's fused multiply-add
            return (p, a.mul_add(b, -p));
        }
        let (ah, al) = split(a);
        let (bh, bl) = split(b);
        (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
    }
}

// ---- a loop of products added ----------------------------------------------------------

/// Calls `$body::<true>` compiled for AVX2 and FMA where the processor has them (detected at
/// run time, so the build needs no target flag), `$body::<false>` otherwise: the one dispatch
/// of the slice loops below, with the arguments and the result of `$body`.
macro_rules! with_fma {
    ($body:ident($($arg:ident: $ty:ty),*) -> $ret:ty) => {{
        #[cfg(target_arch = "x86_64")]
        {
            #[target_feature(enable = "avx2,fma")]
            unsafe fn fast($($arg: $ty),*) -> $ret {
                $body::<true>($($arg),*)
            }
            if std::is_x86_feature_detected!("fma") && std::is_x86_feature_detected!("avx2") {
                // SAFETY: the features `fast` is compiled for were detected at run time.
                return unsafe { fast($($arg),*) };
            }
        }
        $body::<false>($($arg),*)
    }};
}

/// `acc[k] += b[k] c` for every k, each step the operations of `acc[k] + b[k] * c` (the
/// product as `mul_dd` forms it, the sum as `add_dd`): the same results, finite or not,
/// without the branches that keep the loop scalar. Where the processor has them (detected at
/// run time, so the build needs no target flag), the loop runs with AVX2 and fused
/// multiply-adds, whose `two_prod` is exact as Dekker's split is.
pub(crate) fn mul_add_slice(acc: &mut [Dd], b: &[Dd], c: Dd) {
    with_fma!(mul_add_slice_body(acc: &mut [Dd], b: &[Dd], c: Dd) -> ())
}

#[inline(always)]
fn mul_add_slice_body<const FMA: bool>(acc: &mut [Dd], b: &[Dd], c: Dd) {
    for (a, x) in acc.iter_mut().zip(b) {
        *a = mul_add_step::<FMA>(*a, *x, c);
    }
}

/// `a + x c` with the operations of `add_dd(a, mul_dd(x, c))` and their results, finite or
/// not, without branches (the tests of non-finite values and zero low parts compile to
/// selects).
#[inline(always)]
fn mul_add_step<const FMA: bool>(a: Dd, x: Dd, c: Dd) -> Dd {
    let p = x.hi * c.hi;
    let m = mul_nb::<FMA>(x, c);
    // a non-finite product is `mul_dd`'s result, and a non-finite leading sum `add_dd`'s
    let s = a.hi + if p.is_finite() { m.hi } else { p };
    if s.is_finite() {
        add_nb(a, m)
    } else {
        Dd { hi: s, lo: 0.0 }
    }
}

/// `two_prod` as the loops compile it: the fused multiply-add where enabled.
#[inline(always)]
fn two_prod_nb<const FMA: bool>(a: f64, b: f64) -> (f64, f64) {
    if FMA {
        let p = a * b;
        (p, a.mul_add(b, -p))
    } else {
        two_prod(a, b)
    }
}

/// `mul_dd` for a finite product, without branches (the renormalisations' tests of a zero
/// low part compile to selects).
#[inline(always)]
fn mul_nb<const FMA: bool>(x: Dd, c: Dd) -> Dd {
    let (p, e) = two_prod_nb::<FMA>(x.hi, c.hi);
    Dd::quick(p, e + (x.hi * c.lo + x.lo * c.hi))
}

/// `mul_f64` for a finite product, without branches.
#[inline(always)]
fn mul_f64_nb<const FMA: bool>(x: Dd, c: f64) -> Dd {
    let (p, e) = two_prod_nb::<FMA>(x.hi, c);
    Dd::quick(p, e + x.lo * c)
}

/// `add_dd` for a finite sum, without branches.
#[inline(always)]
fn add_nb(a: Dd, b: Dd) -> Dd {
    let (s, e) = two_sum(a.hi, b.hi);
    let (t, f) = two_sum(a.lo, b.lo);
    let e = e + t;
    let (s, e) = if e == 0.0 {
        (s, e)
    } else {
        quick_two_sum(s, e)
    };
    Dd::quick(s, e + f)
}

/// `div_dd` for a finite quotient whose numerator is at most 1e307, without branches.
#[inline(always)]
fn div_nb<const FMA: bool>(a: Dd, b: Dd) -> Dd {
    let q1 = a.hi / b.hi;
    let r = add_nb(a, -mul_f64_nb::<FMA>(b, q1));
    let q2 = r.hi / b.hi;
    let r = add_nb(r, -mul_f64_nb::<FMA>(b, q2));
    let q3 = r.hi / b.hi;
    let q = Dd::quick(q1, q2);
    let (s, e) = two_sum(q.hi, q3);
    Dd::quick(s, e + q.lo)
}

/// `out[i] = a[i] b[i]`, each the result of `mul_dd`, on AVX2/FMA where detected (as
/// [`mul_add_slice`]).
pub(crate) fn mul_slice(out: &mut [Dd], a: &[Dd], b: &[Dd]) {
    with_fma!(mul_slice_body(out: &mut [Dd], a: &[Dd], b: &[Dd]) -> ())
}

#[inline(always)]
fn mul_slice_body<const FMA: bool>(out: &mut [Dd], a: &[Dd], b: &[Dd]) {
    for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
        let p = x.hi * y.hi;
        let m = mul_nb::<FMA>(*x, *y);
        // a non-finite product is `mul_dd`'s result
        *o = if p.is_finite() {
            m
        } else {
            Dd { hi: p, lo: 0.0 }
        };
    }
}

/// `out[i] = a[i]/b[i]`, each the result of `div_dd`, on AVX2/FMA where detected (as
/// [`mul_add_slice`]). A numerator above 1e307 (which `div_dd` scales first) sends the slice
/// to `div_dd` itself.
pub(crate) fn div_slice(out: &mut [Dd], a: &[Dd], b: &[Dd]) {
    if a.iter().any(|x| x.hi.abs() > 1e307) {
        for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
            *o = *x / *y;
        }
        return;
    }
    with_fma!(div_slice_body(out: &mut [Dd], a: &[Dd], b: &[Dd]) -> ())
}

#[inline(always)]
fn div_slice_body<const FMA: bool>(out: &mut [Dd], a: &[Dd], b: &[Dd]) {
    for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
        let q = div_nb::<FMA>(*x, *y);
        // `div_dd`'s early return: a non-finite first digit, or an infinite divisor
        let q1 = x.hi / y.hi;
        *o = if q1.is_finite() && y.hi.is_finite() && q.hi.is_finite() {
            q
        } else {
            Dd { hi: q1, lo: 0.0 }
        };
    }
}

/// The lanes of [`dot_add`] (a loop the compiler vectorises).
const DOT_LANES: usize = 16;

/// `acc + Sum_i a_i b_i`, the products and sums those of `mul_add_assign`, summed in
/// [`DOT_LANES`] interleaved partial sums (i mod 16) added pairwise at the end: the error
/// bound of a sum in any order (each addition within a few units of 2^-106 of its result),
/// with the lanes in the vector registers where the processor has AVX2 and FMA (as
/// [`mul_add_slice`]).
pub(crate) fn dot_add(acc: Dd, a: &[Dd], b: &[Dd]) -> Dd {
    with_fma!(dot_add_body(acc: Dd, a: &[Dd], b: &[Dd]) -> Dd)
}

#[inline(always)]
fn dot_add_body<const FMA: bool>(acc: Dd, a: &[Dd], b: &[Dd]) -> Dd {
    let n = a.len().min(b.len());
    let mut lanes = [Dd::from_f64(0.0); DOT_LANES];
    let (ca, ra) = a[..n].split_at(n / DOT_LANES * DOT_LANES);
    let (cb, rb) = b[..n].split_at(n / DOT_LANES * DOT_LANES);
    for (xa, xb) in ca.chunks_exact(DOT_LANES).zip(cb.chunks_exact(DOT_LANES)) {
        for ((l, x), y) in lanes.iter_mut().zip(xa).zip(xb) {
            *l = mul_add_step::<FMA>(*l, *x, *y);
        }
    }
    for ((l, x), y) in lanes.iter_mut().zip(ra).zip(rb) {
        *l = mul_add_step::<FMA>(*l, *x, *y);
    }
    let mut w = DOT_LANES;
    while w > 1 {
        w /= 2;
        for j in 0..w {
            lanes[j] += lanes[j + w];
        }
    }
    acc + lanes[0]
}

// ---- constants -------------------------------------------------------------------------

/// pi as three doubles (the first two are [`Real::pi`]).
const PI: [f64; 3] = [
    std::f64::consts::PI,
    1.224_646_799_147_353_2e-16,
    -2.994_769_809_718_339_7e-33,
];
/// pi/2 as five doubles (argument reduction of the trigonometric functions).
const PI_2: [f64; 5] = [
    std::f64::consts::FRAC_PI_2,
    6.123_233_995_736_766e-17,
    -1.497_384_904_859_169_8e-33,
    5.562_271_104_316_826e-50,
    2.836_115_989_820_158e-66,
];
/// ln 2 as three doubles (argument reduction of `exp` and `ln`).
const LN2: [f64; 3] = [
    std::f64::consts::LN_2,
    2.319_046_813_846_299_6e-17,
    5.707_708_438_416_212e-34,
];

/// Terms of the series below this relative size are dropped (well under 2^-106).
const SERIES_TOL: f64 = 1e-34;

impl Dd {
    /// The double-double `hi + lo`, renormalised.
    #[inline]
    pub fn new(hi: f64, lo: f64) -> Self {
        if lo == 0.0 {
            // keeps the sign of a zero hi (-0 + 0 would round to +0)
            return Dd { hi, lo: 0.0 };
        }
        let (h, l) = two_sum(hi, lo);
        Dd { hi: h, lo: l }
    }
    /// The double `x` exactly.
    #[inline]
    pub const fn from_f64(x: f64) -> Self {
        Dd { hi: x, lo: 0.0 }
    }
    /// The leading double (the value rounded to `f64`).
    #[inline]
    pub fn hi(&self) -> f64 {
        self.hi
    }
    /// The trailing double.
    #[inline]
    pub fn lo(&self) -> f64 {
        self.lo
    }

    #[inline(always)]
    fn quick(hi: f64, lo: f64) -> Self {
        if lo == 0.0 {
            return Dd { hi, lo: 0.0 };
        }
        let (h, l) = quick_two_sum(hi, lo);
        Dd { hi: h, lo: l }
    }
    #[inline(always)]
    fn add_dd(self, b: Dd) -> Dd {
        let s = self.hi + b.hi;
        if !s.is_finite() {
            return Dd::from_f64(s);
        }
        add_nb(self, b)
    }
    #[inline(always)]
    fn add_f64(self, b: f64) -> Dd {
        let (s, e) = two_sum(self.hi, b);
        if !s.is_finite() {
            return Dd::from_f64(s);
        }
        Dd::quick(s, e + self.lo)
    }
    #[inline(always)]
    fn mul_dd(self, b: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, b.hi);
        if !p.is_finite() {
            return Dd::from_f64(p);
        }
        Dd::quick(p, e + (self.hi * b.lo + self.lo * b.hi))
    }
    #[inline(always)]
    fn mul_f64(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi, b);
        if !p.is_finite() {
            return Dd::from_f64(p);
        }
        Dd::quick(p, e + self.lo * b)
    }
    #[inline(always)]
    fn div_dd(self, b: Dd) -> Dd {
        let q1 = self.hi / b.hi;
        if !q1.is_finite() || b.hi.is_infinite() {
            return Dd::from_f64(q1);
        }
        if self.hi.abs() > 1e307 {
            // b q1 could round past the largest double
            return (self.ldexp(-3) / b).ldexp(3);
        }
        let r = self - b.mul_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi / b.hi;
        Dd::quick(q1, q2).add_f64(q3)
    }
    #[inline(always)]
    fn div_f64(self, b: f64) -> Dd {
        let q1 = self.hi / b;
        if !q1.is_finite() || b.is_infinite() {
            return Dd::from_f64(q1);
        }
        if self.hi.abs() > 1e307 {
            return (self.ldexp(-3) / b).ldexp(3);
        }
        let (p1, p2) = two_prod(q1, b);
        let (s, e) = two_sum(self.hi, -p1);
        let e = e + self.lo - p2;
        Dd::quick(q1, (s + e) / b)
    }
    /// `self * 2^k` exactly (barring overflow and underflow).
    #[inline]
    fn ldexp(self, k: i32) -> Dd {
        if !(-1022..=1023).contains(&k) {
            let h = k / 2;
            return self.ldexp(h).ldexp(k - h);
        }
        let s = pow2(k);
        Dd {
            hi: self.hi * s,
            lo: self.lo * s,
        }
    }
    fn nan() -> Dd {
        Dd::from_f64(f64::NAN)
    }
    fn dd_const<const N: usize>(c: &[f64; N]) -> Dd {
        Dd { hi: c[0], lo: c[1] }
    }
    /// `self - k c` for a constant `c` given as N doubles and a small integer `k`, every
    /// product but the last exact: the argument reduction of `exp` (ln 2 to three doubles,
    /// about 2^-106 |r| + 2^-160 |k|) and of the trigonometric functions (pi/2 to five
    /// doubles, 2^-106 |r| + 2^-260 |k|: relative accuracy kept at the zeros of sin and cos
    /// up to |x| = 2^20 and beyond).
    fn reduce<const N: usize>(self, k: f64, c: &[f64; N]) -> Dd {
        let mut r = self;
        for ci in &c[..N - 1] {
            let (p, e) = two_prod(k, *ci);
            r -= Dd::new(p, e);
        }
        r - k * c[N - 1]
    }

    /// ln(1 + t) = 2 atanh(u), u = t/(2 + t), by its series (|t| <= 1/2, so |u| <= 1/3):
    /// relative accuracy for every small t.
    fn ln1p_series(t: Dd) -> Dd {
        let u = t / (t + 2.0);
        let u2 = u * u;
        let mut term = u;
        let mut sum = u;
        let mut n = 1.0_f64;
        loop {
            term *= u2;
            n += 2.0;
            let add = term.div_f64(n);
            sum += add;
            if !(add.hi.abs() > SERIES_TOL * sum.hi.abs()) {
                break;
            }
        }
        sum.mul_f64(2.0)
    }

    /// The sum of `first` and the terms t_k = next(t_(k-1), k), k = 1, 2, ..., up to the
    /// first below [`SERIES_TOL`] relative to the sum (a NaN stops it too).
    fn series(first: Dd, mut next: impl FnMut(Dd, f64) -> Dd) -> Dd {
        let (mut term, mut sum) = (first, first);
        let mut k = 1.0_f64;
        loop {
            term = next(term, k);
            sum += term;
            if !(term.hi.abs() > SERIES_TOL * sum.hi.abs()) {
                return sum;
            }
            k += 1.0;
        }
    }

    /// exp(r) - 1 for |r| <= ln(2)/2: r/1024 by its Taylor series, then ten squarings
    /// (1 + s)^2 - 1 = s (2 + s), which keep the relative accuracy of small results.
    fn expm1_reduced(r: Dd) -> Dd {
        let x = r.ldexp(-10);
        let mut s = Dd::series(x, |t, k| (t * x).div_f64(k + 1.0));
        for _ in 0..10 {
            s = s * (s + 2.0);
        }
        s
    }

    /// exp(self) 2^j, without overflow where only the product is in range (sinh and cosh
    /// of large arguments take j = -1).
    fn exp_times_pow2(self, j: i32) -> Dd {
        // ln of the largest double
        const LN_MAX: f64 = 709.782_712_893_384;
        if self.hi.is_nan() {
            return self;
        }
        if self.hi > LN_MAX - f64::from(j) * LN2[0] {
            return Dd::from_f64(f64::INFINITY);
        }
        if self.hi < -746.0 - f64::from(j) * LN2[0] {
            return Dd::from_f64(0.0);
        }
        let k = (self.hi / LN2[0]).round();
        let r = self.reduce(k, &LN2);
        let s = Dd::expm1_reduced(r) + 1.0;
        s.ldexp(k as i32 + j)
    }

    /// sin r and cos r for |r| <= pi/4 by their Taylor series.
    fn sin_cos_reduced(r: Dd) -> (Dd, Dd) {
        if r.hi == 0.0 {
            return (r, Dd::from_f64(1.0));
        }
        let r2 = r * r;
        // r - r^3/3! + ... and 1 - r^2/2! + ...
        let s = Dd::series(r, |t, k| -(t * r2).div_f64((2.0 * k) * (2.0 * k + 1.0)));
        let c = Dd::series(Dd::from_f64(1.0), |t, k| {
            -(t * r2).div_f64((2.0 * k - 1.0) * (2.0 * k))
        });
        (s, c)
    }
}

impl Dd {
    #[inline(always)]
    fn sub_dd(self, b: Dd) -> Dd {
        self.add_dd(-b)
    }
    #[inline(always)]
    fn sub_f64(self, b: f64) -> Dd {
        self.add_f64(-b)
    }
    /// self^n by binary powering.
    fn powi_unsigned(self, n: u32) -> Dd {
        let mut base = self;
        let mut k = n;
        let mut acc = Dd::from_f64(1.0);
        while k > 0 {
            if k & 1 == 1 {
                acc *= base;
            }
            k >>= 1;
            if k > 0 {
                base *= base;
            }
        }
        acc
    }
}

/// 2^k as a double, for |k| within the normal range or just below it.
#[inline]
fn pow2(k: i32) -> f64 {
    if (-1022..=1023).contains(&k) {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        2f64.powi(k)
    }
}

// ---- operators -------------------------------------------------------------------------

impl Neg for Dd {
    type Output = Dd;
    #[inline]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

macro_rules! binary_ops {
    ($tr:ident, $m:ident, $atr:ident, $am:ident, $dd:ident, $f:ident) => {
        impl $tr for Dd {
            type Output = Dd;
            #[inline]
            fn $m(self, b: Dd) -> Dd {
                self.$dd(b)
            }
        }
        impl<'a> $tr<&'a Dd> for Dd {
            type Output = Dd;
            #[inline]
            fn $m(self, b: &'a Dd) -> Dd {
                self.$dd(*b)
            }
        }
        impl $tr<f64> for Dd {
            type Output = Dd;
            #[inline]
            fn $m(self, b: f64) -> Dd {
                self.$f(b)
            }
        }
        impl $atr for Dd {
            #[inline]
            fn $am(&mut self, b: Dd) {
                *self = self.$dd(b);
            }
        }
        impl<'a> $atr<&'a Dd> for Dd {
            #[inline]
            fn $am(&mut self, b: &'a Dd) {
                *self = self.$dd(*b);
            }
        }
        impl $atr<f64> for Dd {
            #[inline]
            fn $am(&mut self, b: f64) {
                *self = self.$f(b);
            }
        }
    };
}

binary_ops!(Add, add, AddAssign, add_assign, add_dd, add_f64);
binary_ops!(Sub, sub, SubAssign, sub_assign, sub_dd, sub_f64);
binary_ops!(Mul, mul, MulAssign, mul_assign, mul_dd, mul_f64);
binary_ops!(Div, div, DivAssign, div_assign, div_dd, div_f64);

impl PartialEq for Dd {
    #[inline]
    fn eq(&self, o: &Dd) -> bool {
        self.hi == o.hi && self.lo == o.lo
    }
}

impl PartialOrd for Dd {
    #[inline]
    fn partial_cmp(&self, o: &Dd) -> Option<Ordering> {
        match self.hi.partial_cmp(&o.hi)? {
            Ordering::Equal => self.lo.partial_cmp(&o.lo),
            ord => Some(ord),
        }
    }
}

impl PartialEq<f64> for Dd {
    #[inline]
    fn eq(&self, o: &f64) -> bool {
        self.hi == *o && self.lo == 0.0
    }
}

impl PartialOrd<f64> for Dd {
    #[inline]
    fn partial_cmp(&self, o: &f64) -> Option<Ordering> {
        self.partial_cmp(&Dd::from_f64(*o))
    }
}

impl Display for Dd {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_decimal(32))
    }
}

// ---- the Real backend ------------------------------------------------------------------

impl Real for Dd {
    #[inline]
    fn mul_add_slice(acc: &mut [Self], b: &[Self], c: &Self) {
        mul_add_slice(acc, b, *c);
    }
    #[inline]
    fn dot_add(&mut self, a: &[Self], b: &[Self]) {
        *self = dot_add(*self, a, b);
    }
    #[inline]
    fn mul_slice(out: &mut [Self], a: &[Self], b: &[Self]) {
        mul_slice(out, a, b);
    }
    #[inline]
    fn div_slice(out: &mut [Self], a: &[Self], b: &[Self]) {
        div_slice(out, a, b);
    }
    #[inline]
    fn from_f64_prec(x: f64, _bits: u32) -> Self {
        Dd::from_f64(x)
    }
    fn parse_prec(s: &str, _bits: u32) -> Result<Self> {
        let f = <Float as Real>::parse_prec(s, 256)?;
        Ok(Dd::from_mpfr(&f, DD_BITS))
    }
    fn from_mpfr(x: &Float, _bits: u32) -> Self {
        let hi = x.to_f64();
        if !hi.is_finite() {
            return Dd::from_f64(hi);
        }
        let rest = Float::with_val(x.prec().max(64), x - hi);
        Dd::quick(hi, rest.to_f64())
    }
    fn to_mpfr(&self, bits: u32) -> Float {
        // hi + lo rounded once to `bits`
        let mut exact = Float::with_val(2200, self.hi);
        exact += self.lo;
        Float::with_val(bits, &exact)
    }
    #[inline]
    fn prec(&self) -> u32 {
        DD_BITS
    }
    #[inline]
    fn to_f64(&self) -> f64 {
        self.hi
    }
    fn to_decimal(&self, digits: usize) -> String {
        // from the exact sum, rounded once
        Real::to_decimal(&self.to_mpfr(2200), digits)
    }
    #[inline]
    fn pi(&self) -> Self {
        Dd::dd_const(&PI)
    }
    #[inline]
    fn epsilon(&self) -> Self {
        Dd::from_f64(pow2(1 - DD_BITS as i32))
    }

    fn sqrt(self) -> Self {
        if self.hi <= 0.0 {
            return if self.hi == 0.0 { self } else { Dd::nan() };
        }
        if !self.hi.is_finite() {
            return self;
        }
        // far from 1, scaled by an even power of two: the low part and the correction stay
        // in the normal range
        if !(1e-250..=1e250).contains(&self.hi) {
            let k = exponent(self.hi) & !1;
            return self.ldexp(-k).sqrt().ldexp(k / 2);
        }
        // Karp and Markstein: one correction of the double square root
        let x = 1.0 / self.hi.sqrt();
        let ax = self.hi * x;
        let (p, e) = two_prod(ax, ax);
        let d = (self - Dd { hi: p, lo: e }).hi * (x * 0.5);
        Dd::new(ax, d)
    }

    /// ln a = e ln 2 + ln m with a = 2^e m, m in [3/4, 3/2], and ln m by
    /// `ln1p_series`.
    fn ln(self) -> Self {
        if !(self.hi > 0.0) {
            return if self.hi == 0.0 {
                Dd::from_f64(f64::NEG_INFINITY)
            } else {
                Dd::nan()
            };
        }
        if self.hi == f64::INFINITY {
            return self;
        }
        let mut e = exponent(self.hi);
        let mut m = self.ldexp(-e);
        if m.hi > 1.5 {
            m = m.ldexp(-1);
            e += 1;
        }
        let lnm = Dd::ln1p_series(m - 1.0);
        if e == 0 {
            return lnm;
        }
        // ln m + e ln 2, the products exact as in exp's reduction
        lnm.reduce(-f64::from(e), &LN2)
    }
    fn ln_1p(self) -> Self {
        if self.hi == 0.0 {
            return self; // the sign of a zero kept
        }
        if self.hi.abs() <= 0.5 {
            Dd::ln1p_series(self)
        } else {
            (self + 1.0).ln()
        }
    }
    /// exp x = 2^k exp(r), r = x - k ln 2 (|r| <= ln(2)/2), exp(r) - 1 by
    /// `expm1_reduced`.
    fn exp(self) -> Self {
        self.exp_times_pow2(0)
    }
    fn exp_m1(self) -> Self {
        if self.hi == 0.0 {
            return self; // the sign of a zero kept
        }
        if self.hi.abs() <= 0.5 * LN2[0] {
            Dd::expm1_reduced(self)
        } else {
            self.exp() - 1.0
        }
    }
    fn sin(self) -> Self {
        self.sin_cos().0
    }
    fn cos(self) -> Self {
        self.sin_cos().1
    }
    /// x = k pi/2 + r (|r| <= pi/4, pi/2 to five doubles), then the Taylor series of r
    /// (`sin_cos_reduced`) and the quadrant of k.
    fn sin_cos(self) -> (Self, Self) {
        if !self.hi.is_finite() {
            return (Dd::nan(), Dd::nan());
        }
        let k = (self.hi / PI_2[0]).round();
        let r = if k == 0.0 {
            self
        } else {
            self.reduce(k, &PI_2)
        };
        let (s, c) = Dd::sin_cos_reduced(r);
        match (k.rem_euclid(4.0)) as u8 {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }
    fn tan(self) -> Self {
        let (s, c) = self.sin_cos();
        s / c
    }
    fn atan(self) -> Self {
        self.atan2(&Dd::from_f64(1.0))
    }
    /// The double atan2 corrected by one Newton step on sin z / cos z = y / x (quadratic
    /// convergence: 53 bits become 106).
    fn atan2(self, x: &Self) -> Self {
        let (y, x) = (self, *x);
        if (x.hi == 0.0 && y.hi == 0.0) || !(x.hi.is_finite() && y.hi.is_finite()) {
            // the exact multiples of pi/4 of the special cases, as double-doubles
            let z = y.hi.atan2(x.hi);
            let k = (z / std::f64::consts::FRAC_PI_4).round();
            return if z.is_nan() || k == 0.0 {
                Dd::from_f64(z)
            } else {
                Dd::dd_const(&PI_2) * (0.5 * k)
            };
        }
        if y.hi == 0.0 {
            return if x.hi > 0.0 {
                y
            } else {
                Dd::dd_const(&PI).copysign(&y)
            };
        }
        if x.hi == 0.0 {
            let h = Dd::dd_const(&PI_2);
            return if y.hi > 0.0 { h } else { -h };
        }
        // scaled by a power of two near 1/max(|x|, |y|): hypot neither overflows nor
        // underflows, and the angle is unchanged
        let e = exponent(x.hi.abs().max(y.hi.abs()));
        let (x, y) = (x.ldexp(-e), y.ldexp(-e));
        let r = x.hypot(&y);
        let (xx, yy) = (x / r, y / r);
        let z = Dd::from_f64(y.hi.atan2(x.hi));
        let (s, c) = z.sin_cos();
        if xx.hi.abs() > yy.hi.abs() {
            z + (yy - s) / c
        } else {
            z - (xx - c) / s
        }
    }
    /// From exp_m1 for |x| <= 1/2 (no cancellation), from exp(|x|) otherwise (the
    /// reciprocal of a small exp would lose its low part), halved inside exp for |x| > 40.
    fn sinh(self) -> Self {
        let a = self.abs();
        let r = if a.hi <= 0.5 {
            let e = a.exp_m1();
            (e + e / (e + 1.0)).ldexp(-1)
        } else if a.hi > 40.0 {
            a.exp_times_pow2(-1)
        } else {
            let e = a.exp();
            (e - e.recip()).ldexp(-1)
        };
        r.copysign(&self)
    }
    /// From exp(|x|), halved inside exp for |x| > 40.
    fn cosh(self) -> Self {
        let a = self.abs();
        if a.hi > 40.0 {
            return a.exp_times_pow2(-1);
        }
        let e = a.exp();
        (e + e.recip()).ldexp(-1)
    }
    fn tanh(self) -> Self {
        let a = self.abs();
        if a.hi > 40.0 {
            return Dd::from_f64(1.0).copysign(&self);
        }
        let e = a.ldexp(1).exp_m1();
        (e / (e + 2.0)).copysign(&self)
    }
    fn acosh(self) -> Self {
        if self.hi < 1.0 {
            return Dd::nan();
        }
        if self.hi > 4.5e15 {
            // acosh x = ln(2x) - 1/(4x^2) - ..., the correction below 2^-106
            return self.ln() + Dd::dd_const(&LN2);
        }
        let t = self - 1.0;
        (t + (t * (t + 2.0)).sqrt()).ln_1p()
    }
    fn hypot(self, y: &Self) -> Self {
        let (mut a, mut b) = (self.abs(), y.abs());
        if a.hi.is_infinite() || b.hi.is_infinite() {
            return Dd::from_f64(f64::INFINITY);
        }
        if a < b {
            std::mem::swap(&mut a, &mut b);
        }
        if a.hi == 0.0 || !a.hi.is_finite() || b.hi.is_nan() {
            return if b.hi.is_nan() { b } else { a };
        }
        let r = b / a;
        a * (r * r + 1.0).sqrt()
    }
    #[inline]
    fn abs(self) -> Self {
        if self.hi.is_sign_negative() {
            -self
        } else {
            self
        }
    }
    /// exp(e ln x); the special values of IEEE `pow` (through the double `powf` on the
    /// leading parts), and a negative base with an integral exponent.
    fn powf(self, e: &Self) -> Self {
        if *e == 0.0 || self == 1.0 {
            return Dd::from_f64(1.0);
        }
        if self.hi == 0.0 || !self.is_finite() || !e.is_finite() {
            return Dd::from_f64(self.hi.powf(e.hi));
        }
        if self.hi < 0.0 {
            // an integral exponent of a negative base; otherwise NaN
            if e.hi.fract() != 0.0 || e.lo.fract() != 0.0 {
                return Dd::nan();
            }
            let odd = (e.hi % 2.0 + e.lo % 2.0) % 2.0 != 0.0;
            let m = (-self).powf(e);
            return if odd { -m } else { m };
        }
        (*e * self.ln()).exp()
    }
    /// Binary powering; for n < 0 of the reciprocal (the intermediates then stay between 1
    /// and the result, in range whenever the result is). The error grows like |n| 2^-106.
    fn powi(self, n: i32) -> Self {
        if n < 0 {
            self.recip().powi_unsigned(n.unsigned_abs())
        } else {
            self.powi_unsigned(n.unsigned_abs())
        }
    }

    #[inline]
    fn is_sign_negative(&self) -> bool {
        self.hi.is_sign_negative()
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }
    /// Below 2^-969 the low part is subnormal and the precision falls away.
    #[inline]
    fn normal_floor(&self) -> Option<f64> {
        Some(pow2(-969))
    }
    #[inline]
    fn recip(self) -> Self {
        Dd::from_f64(1.0) / self
    }
    #[inline]
    fn sqr(self) -> Self {
        let (p, e) = two_prod(self.hi, self.hi);
        if !p.is_finite() {
            return Dd::from_f64(p);
        }
        Dd::quick(p, e + 2.0 * self.hi * self.lo)
    }
}

/// The binary exponent e of a finite nonzero double, |x| = 2^e m with m in [1, 2).
#[inline]
fn exponent(x: f64) -> i32 {
    let bits = (x.to_bits() >> 52) & 0x7ff;
    if bits == 0 {
        // subnormal: scale into the normal range first
        exponent(x * pow2(64)) - 64
    } else {
        bits as i32 - 1023
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slice loops give the scalar operations' results bit for bit (zeros, infinities,
    /// overflow, NaN and numerators beyond 1e307 included), and the dot product's lanes agree
    /// with the sum in order to its rounding.
    #[test]
    fn slice_loops_equal_the_scalar_operations() {
        let mut vals = vec![
            Dd::from_f64(0.0),
            Dd::from_f64(-0.0),
            Dd::from_f64(f64::INFINITY),
            Dd::from_f64(f64::NAN),
            Dd::from_f64(1e300),
            Dd::from_f64(-3e-300),
            Dd::from_f64(1.5e308),
        ];
        let mut x = 0.123_456_789_f64;
        for _ in 0..200 {
            x = (x * 3.987_654_321 + 0.1).fract();
            let e = ((x * 1000.0) as i32 % 60) - 30;
            let hi = (x - 0.5) * pow2(e);
            vals.push(Dd::new(hi, hi * (x - 0.3) * 1e-17));
        }
        let n = vals.len();
        let b: Vec<Dd> = (0..n).map(|i| vals[(i * 7 + 3) % n]).collect();
        let same = |u: &Dd, v: &Dd| {
            (u.hi.to_bits() == v.hi.to_bits() || (u.hi.is_nan() && v.hi.is_nan()))
                && (u.lo == v.lo || (u.lo.is_nan() && v.lo.is_nan()))
        };
        for c in [vals[9], vals[4], vals[2], vals[0]] {
            let mut acc = b.clone();
            Real::mul_add_slice(&mut acc, &vals, &c);
            for i in 0..n {
                let mut want = b[i];
                want.mul_add_assign(&vals[i], &c);
                assert!(same(&acc[i], &want), "mul_add {i}: {:?} {want:?}", acc[i]);
            }
        }
        let mut out = vec![Dd::from_f64(0.0); n];
        Real::mul_slice(&mut out, &vals, &b);
        for i in 0..n {
            assert!(same(&out[i], &(vals[i] * b[i])), "mul {i}");
        }
        Real::div_slice(&mut out, &vals, &b);
        for i in 0..n {
            assert!(same(&out[i], &(vals[i] / b[i])), "div {i}: {:?}", out[i]);
        }
        let finite = &vals[7..];
        Real::div_slice(&mut out[7..], finite, &b[7..]);
        for i in 7..n {
            assert!(same(&out[i], &(vals[i] / b[i])), "div {i}: {:?}", out[i]);
        }
        let bf: Vec<Dd> = (0..finite.len())
            .map(|i| finite[(i * 7 + 3) % finite.len()])
            .collect();
        let mut dot = Dd::from_f64(0.25);
        dot.dot_add(finite, &bf);
        let mut want = Dd::from_f64(0.25);
        let mut size = 0.25;
        for (x, y) in finite.iter().zip(&bf) {
            want.mul_add_assign(x, y);
            size += (x.hi * y.hi).abs();
        }
        assert!(((dot - want).hi.abs()) <= 64.0 * pow2(-106) * size);
    }

    fn rel(a: Dd, b: &Float) -> f64 {
        let d = Float::with_val(256, a.to_mpfr(256) - b);
        (d / b.clone().abs()).to_f64().abs()
    }

    #[test]
    fn arithmetic_is_accurate_to_the_last_bits() {
        let third = Dd::from_f64(1.0) / 3.0;
        let back = third * 3.0 - 1.0;
        assert!(back.hi.abs() < 1e-32, "{back:?}");
        let x = Dd::parse_prec("1.234567890123456789012345678901234", 0).unwrap();
        let y = Dd::parse_prec("-0.987654321098765432109876543210987", 0).unwrap();
        let (xm, ym) = (x.to_mpfr(256), y.to_mpfr(256));
        let u = pow2(-106);
        for (got, want) in [
            (x + y, Float::with_val(256, &xm + &ym)),
            (x - y, Float::with_val(256, &xm - &ym)),
            (x * y, Float::with_val(256, &xm * &ym)),
            (x / y, Float::with_val(256, &xm / &ym)),
            (x.sqrt(), Float::with_val(256, xm.sqrt_ref())),
            (x.sqr(), Float::with_val(256, xm.square_ref())),
        ] {
            assert!(rel(got, &want) < 4.0 * u, "{got} vs {want}");
        }
    }

    #[test]
    fn decimal_round_trip_and_conversions() {
        let s = "3.1415926535897932384626433832795029";
        let x = Dd::parse_prec(s, 0).unwrap();
        assert!(rel(x, &Float::with_val(256, Float::parse(s).unwrap())) < pow2(-105));
        assert_eq!(x.to_decimal(20), "3.1415926535897932385");
        assert_eq!(Dd::from_f64(0.0).to_decimal(5), "0");
        assert!((x - x.pi()).abs() < 1e-31);
    }
}
