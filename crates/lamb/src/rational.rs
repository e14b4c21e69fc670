//! Closed-form integrals of even rational functions, `Int_0^V N(v^2)/D(v^2) dv`.
//!
//! Every step response and every cell integral of the Lamb crate reduces, after a substitution
//! that removes a square root (`docs/lamb.md`, section 3), to such an integral with D a product
//! of simple linear factors in u = v^2. With the partial fractions
//! N(u)/D(u) = Q(u) + sum_j C_j/(u - a_j), C_j = N(a_j)/D'(a_j),
//!
//! ```text
//!   Int_0^V dv/(v^2 - a) = atan(V/r)/r,            a = -r^2 < 0,
//!                        = -atanh(V/r)/r,          a = r^2 > 0 (principal value past V = r),
//!                        = (i/r) atan(i V/r),      a complex, r = sqrt(a) principal,
//! ```
//!
//! and a complex-conjugate pair of roots contributes twice the real part of one of its terms.
//! Near V = 0 the partial fractions cancel (the integrand of a step response vanishes like a
//! power of v at a wavefront), so there the Taylor series of N/D in u is integrated term by term
//! instead; it is used while V^2 <= |a|_min/4 and converges at least like 4^-k.
//!
//! A real root a = 1 ([`Factor::Unit`]) is the late-time logarithm of a step response; its
//! atanh is formed from the caller's exact `1 - V`, so no digit is lost as V -> 1.

use complexfn::{Cx, Real};

use crate::half_plane::Estimate;

/// One linear factor alpha u + beta of the denominator; a `Pair` stands for the factor and its
/// complex conjugate.
#[derive(Clone, Debug)]
pub enum Factor<T> {
    /// Real alpha u + beta.
    Real(T, T),
    /// (alpha u + beta)(conj(alpha) u + conj(beta)).
    Pair(Cx<T>, Cx<T>),
    /// -u + 1 (the exact unit root), times `scale`: scale (1 - u).
    Unit(T),
    /// A real alpha u + beta whose root is the Rayleigh pole: its atanh is formed from the
    /// caller's exact distance sqrt(a) - V (see [`EvenRational::eval`]).
    Pole(T, T),
}

/// An even rational function c N(u)/prod(factors), u = v^2, before it is put in partial
/// fractions.
#[derive(Clone, Debug)]
pub struct Rational<T> {
    /// Numerator coefficients in u, ascending.
    pub num: Vec<T>,
    /// The denominator's linear factors.
    pub factors: Vec<Factor<T>>,
}

#[derive(Clone, Debug)]
struct RealTerm<T> {
    /// The root a and sqrt(|a|).
    a: T,
    r: T,
    c: T,
    unit: bool,
    pole: bool,
}

#[derive(Clone, Debug)]
struct PairTerm<T> {
    /// sqrt(a) (principal) and C/sqrt(a).
    r: Cx<T>,
    c_over_r: Cx<T>,
    /// sqrt(-a) (principal), for V = infinity.
    r_neg: Cx<T>,
    c: Cx<T>,
}

/// `Int_0^V N(v^2)/D(v^2) dv` for one even rational function, ready to evaluate.
#[derive(Clone, Debug)]
pub struct EvenRational<T> {
    /// Polynomial part Q(u), ascending.
    poly: Vec<T>,
    real: Vec<RealTerm<T>>,
    pairs: Vec<PairTerm<T>>,
    /// Taylor coefficients of N/D in u.
    taylor: Vec<T>,
    /// min |a_j| / 4: the largest V^2 for the Taylor path.
    taylor_v2: T,
}

fn poly_eval<T: Real>(p: &[T], x: &Cx<T>) -> Cx<T> {
    let like = &x.re;
    let mut acc = Cx::real(like.zero());
    for c in p.iter().rev() {
        acc = (acc * x).add_re(c);
    }
    acc
}

fn cpoly_mul<T: Real>(p: &[Cx<T>], q: &[Cx<T>]) -> Vec<Cx<T>> {
    let zero = Cx::real(p[0].re.zero());
    let mut out = vec![zero; p.len() + q.len() - 1];
    for (i, a) in p.iter().enumerate() {
        for (j, b) in q.iter().enumerate() {
            out[i + j] += a.clone() * b;
        }
    }
    out
}

impl<T: Real> Rational<T> {
    /// The same function with every factor as (alpha, beta) in the complex plane, each pair
    /// expanded, for the product polynomial and the roots.
    fn linear_factors(&self) -> Vec<(Cx<T>, Cx<T>)> {
        let mut out = Vec::new();
        for f in &self.factors {
            match f {
                Factor::Real(a, b) | Factor::Pole(a, b) => {
                    out.push((Cx::real(a.clone()), Cx::real(b.clone())))
                }
                Factor::Pair(a, b) => {
                    out.push((a.clone(), b.clone()));
                    out.push((a.clone().conj(), b.clone().conj()));
                }
                Factor::Unit(s) => out.push((Cx::real(-s.clone()), Cx::real(s.clone()))),
            }
        }
        out
    }

    /// `Int_0^V` of this function, ready to evaluate. Requires a non-zero denominator at u = 0.
    pub fn head(&self) -> EvenRational<T> {
        let like = self.num[0].clone();
        let lin = self.linear_factors();
        // real coefficients of the denominator
        let mut den = vec![Cx::real(like.one())];
        for (a, b) in &lin {
            den = cpoly_mul(&den, &[b.clone(), a.clone()]);
        }
        let den: Vec<T> = den.into_iter().map(|c| c.re).collect();
        let mut den = den;
        while den.len() > 1 && den.last().is_some_and(|c| *c == 0.0) {
            den.pop();
        }
        // polynomial part by long division
        let mut rem = self.num.clone();
        let dd = den.len() - 1;
        let mut poly = Vec::new();
        if rem.len() > dd {
            poly = vec![like.zero(); rem.len() - dd];
            for k in (0..poly.len()).rev() {
                let q = rem[k + dd].clone() / &den[dd];
                for (i, d) in den.iter().enumerate() {
                    rem[k + i] -= q.clone() * d;
                }
                poly[k] = q;
            }
        }
        // roots and partial-fraction coefficients C_j = N(a_j) / prod_{k != j} (alpha_k a_j + beta_k) / alpha_j
        let roots: Vec<Cx<T>> = lin
            .iter()
            .map(|(a, b)| -(b.clone() / a))
            .collect::<Vec<_>>();
        let coef = |j: usize| -> Cx<T> {
            let aj = &roots[j];
            let mut d = lin[j].0.clone();
            for (k, (a, b)) in lin.iter().enumerate() {
                if k != j {
                    d *= &(a.clone() * aj + b);
                }
            }
            poly_eval(&self.num, aj) / &d
        };
        let mut real = Vec::new();
        let mut pairs = Vec::new();
        let mut j = 0;
        for f in &self.factors {
            match f {
                Factor::Real(..) | Factor::Unit(_) | Factor::Pole(..) => {
                    let a = roots[j].re.clone();
                    let c = coef(j).re;
                    let unit = matches!(f, Factor::Unit(_));
                    let pole = matches!(f, Factor::Pole(..));
                    let r = a.clone().abs().sqrt();
                    real.push(RealTerm {
                        a,
                        r,
                        c,
                        unit,
                        pole,
                    });
                    j += 1;
                }
                Factor::Pair(..) => {
                    let (mut k, mut a) = (j, roots[j].clone());
                    if a.im < 0.0 {
                        k = j + 1;
                        a = roots[k].clone();
                    }
                    let c = coef(k);
                    let r = a.clone().sqrt();
                    let c_over_r = c.clone() / &r;
                    let r_neg = (-a).sqrt();
                    pairs.push(PairTerm {
                        r,
                        c_over_r,
                        r_neg,
                        c,
                    });
                    j += 2;
                }
            }
        }
        // Taylor coefficients of N/D: t_k = (n_k - sum_{i>=1} d_i t_{k-i}) / d_0
        let terms = like.prec() as usize + 16;
        let mut taylor: Vec<T> = Vec::with_capacity(terms);
        for k in 0..terms {
            let mut t = self.num.get(k).cloned().unwrap_or_else(|| like.zero());
            for i in 1..=dd.min(k) {
                t -= den[i].clone() * &taylor[k - i];
            }
            taylor.push(t / &den[0]);
        }
        let amin = roots
            .iter()
            .map(|a| a.abs())
            .fold(None::<T>, |m, a| Some(m.map_or(a.clone(), |m| m.min(a))))
            .unwrap_or_else(|| like.lit(f64::INFINITY));
        EvenRational {
            poly,
            real,
            pairs,
            taylor,
            taylor_v2: amin / 4.0,
        }
    }

    /// `Int_T^inf` of this function, as the head integral of the reflected function in
    /// w = 1/v: `Int_T^inf f(v^2) dv = Int_0^{1/T} f(1/w^2)/w^2 dw`. Requires
    /// deg N <= (number of linear factors) - 1, so that the integral converges.
    pub fn tail(&self) -> EvenRational<T> {
        let like = self.num[0].clone();
        let d: usize = self
            .factors
            .iter()
            .map(|f| if matches!(f, Factor::Pair(..)) { 2 } else { 1 })
            .sum();
        let dn = self.num.len() - 1;
        debug_assert!(d > dn, "tail integral of a function that does not decay");
        // u^(d - dn - 1) Nrev(u)
        let mut num = vec![like.zero(); d - dn - 1];
        num.extend(self.num.iter().rev().cloned());
        let mut factors = Vec::new();
        let mut konst = like.one();
        for f in &self.factors {
            match f {
                Factor::Real(a, b) => {
                    if *b == 0.0 {
                        konst *= a;
                    } else {
                        factors.push(Factor::Real(b.clone(), a.clone()));
                    }
                }
                Factor::Unit(s) => factors.push(Factor::Unit(s.clone()).reflect_unit()),
                Factor::Pole(a, b) => factors.push(Factor::Pole(b.clone(), a.clone())),
                Factor::Pair(a, b) => factors.push(Factor::Pair(b.clone(), a.clone())),
            }
        }
        let num = num.into_iter().map(|c| c / &konst).collect();
        Rational { num, factors }.head()
    }
}

impl<T: Real> Factor<T> {
    /// s (1 - u) reflected to s (u - 1) = -s (1 - u).
    fn reflect_unit(self) -> Self {
        match self {
            Factor::Unit(s) => Factor::Unit(-s),
            f => f,
        }
    }
}

/// atanh(z) for real z >= 0, as a principal value for z > 1 (the real part), from `1 - z`
/// given exactly by the caller where it is small (the side is decided by its sign, so a z
/// rounded to 1 keeps its logarithm).
fn atanh_pv<T: Real>(z: &T, one_minus_z: &T) -> T {
    let one = z.one();
    if *one_minus_z > 0.0 {
        // 0.5 ln((1 + z)/(1 - z)) = 0.5 ln1p(2z/(1 - z))
        (z.clone() * 2.0 / one_minus_z).ln_1p() / 2.0
    } else {
        // 0.5 ln((z + 1)/(z - 1)) = 0.5 ln1p(2/(z - 1))
        (-(one * 2.0) / one_minus_z).ln_1p() / 2.0
    }
}

impl EvenRational<rug::Float> {
    /// The same function rounded to `bits` bits of `T` (built at a higher precision, used at
    /// the working one); the Taylor series keeps the terms the working precision needs.
    pub fn round_to<T: Real>(&self, bits: u32) -> EvenRational<T> {
        let r = |x: &rug::Float| T::from_mpfr(x, bits);
        let c = |z: &Cx<rug::Float>| Cx::new(r(&z.re), r(&z.im));
        let terms = (bits as usize + 16).min(self.taylor.len());
        EvenRational {
            poly: self.poly.iter().map(r).collect(),
            real: self
                .real
                .iter()
                .map(|t| RealTerm {
                    a: r(&t.a),
                    r: r(&t.r),
                    c: r(&t.c),
                    unit: t.unit,
                    pole: t.pole,
                })
                .collect(),
            pairs: self
                .pairs
                .iter()
                .map(|p| PairTerm {
                    r: c(&p.r),
                    c_over_r: c(&p.c_over_r),
                    r_neg: c(&p.r_neg),
                    c: c(&p.c),
                })
                .collect(),
            taylor: self.taylor[..terms].iter().map(r).collect(),
            taylor_v2: r(&self.taylor_v2),
        }
    }
}

impl<T: Real> EvenRational<T> {
    /// `Int_0^V`, V >= 0 finite. `one_minus_v` is 1 - V and `pole_gap` is sqrt(a_R) - V for
    /// the [`Factor::Pole`] root a_R, each computed without cancellation by the caller (pass
    /// `None` to form them here by subtraction). The principal value is taken past a positive
    /// real root; V at a root is the caller's to refuse (the value is then infinite).
    pub fn eval(&self, v: &T, one_minus_v: Option<&T>, pole_gap: Option<&T>) -> Estimate<T> {
        let eps = v.epsilon().to_f64();
        let v2 = v.clone().sqr();
        if v2 <= self.taylor_v2 {
            return self.taylor(v, &v2, eps);
        }
        let mut sum = v.zero();
        let mut mag = 0.0;
        // polynomial part
        let mut vp = v.clone();
        for (k, q) in self.poly.iter().enumerate() {
            let t = q.clone() * &vp / (2 * k + 1) as f64;
            mag += t.to_f64().abs();
            sum += &t;
            vp *= &v2;
        }
        for t in &self.real {
            let i = if t.a < 0.0 {
                (v.clone() / &t.r).atan() / &t.r
            } else {
                let z = v.clone() / &t.r;
                let omz = match (t.unit, one_minus_v, t.pole, pole_gap) {
                    (true, Some(g), _, _) => g.clone(),
                    (_, _, true, Some(g)) => g.clone() / &t.r,
                    _ => z.one() - &z,
                };
                -(atanh_pv(&z, &omz) / &t.r)
            };
            let term = t.c.clone() * &i;
            mag += term.to_f64().abs();
            sum += &term;
        }
        for p in &self.pairs {
            // (i/r) atan(i V/r) times C, doubled real part
            let iz = (Cx::real(v.clone()) / &p.r).mul_i();
            let at = iz.atan().mul_i();
            let term = (at * &p.c_over_r).re * 2.0;
            mag += term.to_f64().abs();
            sum += &term;
        }
        Estimate {
            value: sum,
            error: 32.0 * eps * mag,
            kind: complexfn::ErrorKind::Rounding,
        }
    }

    /// `Int_0^inf` (requires a proper rational function, deg N <= deg D - 1).
    pub fn eval_infinite(&self, like: &T) -> Estimate<T> {
        let eps = like.epsilon().to_f64();
        let half_pi = like.pi() / 2.0;
        let mut sum = like.zero();
        let mut mag = 0.0;
        for t in &self.real {
            if t.a < 0.0 {
                let term = t.c.clone() * &half_pi / &t.r;
                mag += term.to_f64().abs();
                sum += &term;
            }
        }
        for p in &self.pairs {
            let term = (p.c.clone() / &p.r_neg).re * &half_pi * 2.0;
            mag += term.to_f64().abs();
            sum += &term;
        }
        Estimate {
            value: sum,
            error: 32.0 * eps * mag,
            kind: complexfn::ErrorKind::Rounding,
        }
    }

    fn taylor(&self, v: &T, v2: &T, eps: f64) -> Estimate<T> {
        let mut sum = v.zero();
        let mut mag = 0.0;
        let mut vp = v.clone();
        let mut last = 0.0;
        for (k, t) in self.taylor.iter().enumerate() {
            let term = t.clone() * &vp / (2 * k + 1) as f64;
            let a = term.to_f64().abs();
            mag += a;
            sum += &term;
            last = a;
            if k > 3 && a <= eps * 1e-2 * sum.to_f64().abs() {
                break;
            }
            vp *= v2;
        }
        Estimate {
            value: sum,
            error: 8.0 * eps * mag + 2.0 * last,
            kind: complexfn::ErrorKind::Rounding,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Int_a^b f by composite Simpson (smooth test integrands only).
    fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
        let h = (b - a) / n as f64;
        let mut s = f(a) + f(b);
        for i in 1..n {
            let x = a + h * i as f64;
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(x);
        }
        s * h / 3.0
    }

    #[test]
    fn head_and_tail_agree_with_direct_quadrature() {
        // N = 1 + 2u, D = (u + 2)(3u - 1 + ... ) with a complex pair and a negative real root
        let pair_a = Cx::new(0.5, 1.5); // factor alpha u + beta with root -beta/alpha
        let pair_b = Cx::new(-1.0, 0.25);
        let r = Rational {
            num: vec![1.0, 2.0],
            factors: vec![
                Factor::Real(1.0, 2.0),
                Factor::Pair(pair_a.clone(), pair_b.clone()),
            ],
        };
        let f = |v: f64| {
            let u = v * v;
            let num = 1.0 + 2.0 * u;
            let q = (pair_a.clone() * &Cx::real(u) + &pair_b).norm_sqr();
            num / ((u + 2.0) * q)
        };
        let h = r.head();
        for v in [0.05, 0.3, 1.0, 2.5] {
            let got = h.eval(&v, None, None).value;
            let want = simpson(f, 0.0, v, 4000);
            assert!((got - want).abs() < 1e-11, "{v}: {got} {want}");
        }
        let t = r.tail();
        for tt in [0.5, 2.0, 9.0] {
            let got = t.eval(&(1.0 / tt), None, None).value;
            // Int_T^inf f = Int_0^{1/T} f(1/w^2)/w^2 dw
            let want = simpson(
                |w| if w == 0.0 { 0.0 } else { f(1.0 / w) / (w * w) },
                0.0,
                1.0 / tt,
                4000,
            );
            assert!((got - want).abs() < 1e-11, "{tt}: {got} {want}");
        }
    }

    #[test]
    fn principal_value_past_a_positive_root() {
        // Int_0^V dv/(v^2 - 1/4) = -2 atanh(2V) -> PV past V = 1/2: ln|(1 - 2V)/(1 + 2V)|
        let r = Rational {
            num: vec![1.0],
            factors: vec![Factor::Real(1.0, -0.25)],
        };
        let h = r.head();
        for v in [0.1, 0.45, 0.55, 3.0] {
            let want = ((1.0 - 2.0 * v) / (1.0 + 2.0 * v)).abs().ln();
            let got = h.eval(&v, None, None).value;
            assert!((got - want).abs() < 1e-14 * want.abs().max(1.0), "{v}");
        }
        // the Taylor path near 0 keeps relative accuracy
        let v = 1e-3;
        let want = ((1.0 - 2.0 * v) / (1.0 + 2.0 * v)).ln();
        let got = h.eval(&v, None, None).value;
        assert!(((got - want) / want).abs() < 1e-13);
    }
}
