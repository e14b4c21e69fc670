//! Moments of the impulse responses in closed form: M_n(s) = Int_s^inf g(sigma) sigma^-n dsigma.
//!
//! * n = 1 is the step response: W_zz(s) = M_1^zz(s), U_xz = M_1^xz, U_xx = M_1^xx
//!   (u = P/(pi mu) W for a step force P H(t)); a temporal cell at fixed x is
//!   It = Int_sa^sb g/s ds = M_1(sa) - M_1(sb).
//! * n = 0 is the spatial integral at fixed t: Ix = Int_sa^sb g ds = M_0(sa) - M_0(sb).
//! * n = 2 is the ramp moment of the space-time cells with a load linear in time.
//!
//! Principal values are taken across s_R and the delta of g_xz is counted for s < s_R.
//! Each of g_zz, g_xx is a term in v = sqrt(1 - s^2) (for s < 1) plus a term in
//! w = sqrt(1 - s^2/m^2) (for s < m), each of the form -r P(x)/c(x), r = v or w, P a
//! polynomial in x = s^2/m^2. The substitutions of `docs/lamb.md`, section 3, make every
//! moment an integral of an even rational function ([`crate::rational`]):
//!
//! * odd n = 1: the variable r itself (sigma^2 = 1 - v^2, or m^2 (1 - w^2)),
//!   M = -Int_0^r u P(x)/(lambda x c(x)) dr', x = (1 - u)/lambda, u = r'^2;
//! * even n: T = tan of the angle (sigma = sin phi, v = cos phi; or sigma = m sin psi,
//!   w = cos psi), M = -lambda^3 kappa Int_T^inf P(x) y^(n/2 - 2 + 3)/(u^(n/2) prod lin_j) dT',
//!   y = 1 + u, x = u/(lambda y), lin_j = (1 - lambda x_j) u - lambda x_j;
//!
//! with lambda = m^2, kappa = 1 for the v-terms and lambda = 1, kappa = m^(1 - n) for the
//! w-terms. The cross term between P and S, -2 K v sqrt(x - 1) x/E, carries two square roots;
//! for n = 1 the Euler substitution tau^2 = (1/m^2 - x)/(x - 1) makes it rational, and for
//! n = 0, 2 it is an elliptic integral: in the angle theta of
//! s^2 = (1 + m^2)/2 - (1 - m^2)/2 cos theta the integrand is an analytic function of
//! cos theta, so its cosine series converges geometrically; the series is computed once (by the
//! trapezoidal rule, exact but for aliasing) and integrated term by term,
//! Int_theta^pi f = (c_0/2)(pi - theta) - sin theta sum_k (c_k/k) U_{k-1}(cos theta), after the
//! Rayleigh pole of the integrand in cos theta has been taken out and integrated in closed form.

use std::sync::OnceLock;

use complexfn::quadrature::CachedRules;
use complexfn::{Cx, Real};

use crate::error::{invalid, short, Result};
use crate::half_plane::{Estimate, HalfPlane, Spurious, Triple};
use crate::rational::{EvenRational, Factor, Rational};

/// The partial-fraction data of the moments, built on first use for each n.
#[derive(Clone, Debug)]
pub struct MomentCache<T> {
    by_n: [OnceLock<MomentTerms<T>>; 3],
    /// The v- and w-parts of the first moment of g_zz (order n = -1).
    first_zz: OnceLock<(EvenRational<T>, EvenRational<T>)>,
    /// M_{-1}^zz(0) = Int_0^1 sigma g_zz dsigma.
    pub(crate) first_zz_total: OnceLock<Estimate<T>>,
    /// The Taylor coefficients of g_zz in u = s^2 behind the Rayleigh arrival.
    pub(crate) zz_series: OnceLock<Vec<T>>,
    /// C_1 = lim_{s -> 0} (W_zz(s) + g_zz(0) ln s), the constant of the step response.
    pub(crate) step_constant: OnceLock<Estimate<T>>,
}

impl<T> Default for MomentCache<T> {
    fn default() -> Self {
        MomentCache {
            by_n: [OnceLock::new(), OnceLock::new(), OnceLock::new()],
            first_zz: OnceLock::new(),
            first_zz_total: OnceLock::new(),
            zz_series: OnceLock::new(),
            step_constant: OnceLock::new(),
        }
    }
}

#[derive(Clone, Debug)]
struct MomentTerms<T> {
    zz_v: EvenRational<T>,
    zz_w: EvenRational<T>,
    xx_v: EvenRational<T>,
    xx_w: EvenRational<T>,
    xz: XzTerm<T>,
}

/// A cosine series on [0, pi] with the bound of its truncation.
#[derive(Clone, Debug)]
struct CosineSeries<T> {
    /// c_0 .. c_K of the integrand less its Rayleigh pole.
    coef: Vec<T>,
    /// The pole r_p/(cos theta - zeta_R) taken out (zeta_R > 1): (zeta_R, r_p).
    pole: (T, T),
    /// Bound of the rounding of each coefficient.
    coef_err: f64,
    /// Bound of the aliasing and truncation error of any integral of the series over a part
    /// of [0, pi].
    tail: f64,
}

impl<T: Real> CosineSeries<T> {
    /// sum_{k>=1} (c_k/k) U_{k-1}(x) by Clenshaw's recurrence, with the sum of |c_k/k|.
    fn sine_sum(&self, x: &T) -> (T, f64) {
        let two_x = x.clone() * 2.0;
        let (mut b1, mut b2) = (x.zero(), x.zero());
        let mut mag = 0.0;
        for k in (1..self.coef.len()).rev() {
            let bk = self.coef[k].clone() / k as f64;
            mag += bk.to_f64().abs();
            let b0 = bk + two_x.clone() * &b1 - &b2;
            b2 = b1;
            b1 = b0;
        }
        (b1, mag)
    }
}

/// The head variables of the odd moments ([`HalfPlane::odd_heads`]): (1 - r, the distance
/// from the Rayleigh pole, r) for r = v and, behind S, r = w.
struct OddHeads<T> {
    v: (T, T, T),
    w: Option<(T, T, T)>,
}

#[derive(Clone, Debug)]
enum XzTerm<T> {
    /// n = 1: Euler substitution, rational in tau.
    Euler(EvenRational<T>),
    /// n = 0, 2: the cosine series of the integrand in theta, integrated term by term.
    Cosine(CosineSeries<T>),
}

/// P(c0 + c1 u) for P with ascending coefficients.
fn compose_affine<T: Real>(p: &[T], c0: &T, c1: &T) -> Vec<T> {
    let mut out: Vec<T> = vec![c0.zero()];
    for c in p.iter().rev() {
        // out = out * (c0 + c1 u) + c
        let mut next = vec![c0.zero(); out.len() + 1];
        for (i, o) in out.iter().enumerate() {
            next[i] += o.clone() * c0;
            next[i + 1] += o.clone() * c1;
        }
        next[0] += c;
        out = next;
    }
    while out.len() > 1 && out.last().is_some_and(|c| *c == 0.0) {
        out.pop();
    }
    out
}

fn poly_mul<T: Real>(p: &[T], q: &[T]) -> Vec<T> {
    let mut out = vec![p[0].zero(); p.len() + q.len() - 1];
    for (i, a) in p.iter().enumerate() {
        for (j, b) in q.iter().enumerate() {
            out[i + j] += a.clone() * b;
        }
    }
    out
}

fn poly_add<T: Real>(p: &mut Vec<T>, q: &[T]) {
    if p.len() < q.len() {
        p.resize(q.len(), q[0].zero());
    }
    for (a, b) in p.iter_mut().zip(q) {
        *a += b;
    }
}

impl<T: CachedRules> HalfPlane<T> {
    /// The factor alpha u + beta for each root of the Rayleigh cubic, from the map
    /// x_j -> (alpha, beta).
    fn cubic_factors(&self, f: impl Fn(&Cx<T>) -> (Cx<T>, Cx<T>)) -> Vec<Factor<T>> {
        let real = |x: &T| {
            let (a, b) = f(&Cx::real(x.clone()));
            Factor::Real(a.re, b.re)
        };
        let (a, b) = f(&Cx::real(self.x_r.clone()));
        let mut out = vec![Factor::Pole(a.re, b.re)];
        match &self.spurious {
            Spurious::Real(x1, x2) => {
                out.push(real(x1));
                out.push(real(x2));
            }
            Spurious::Pair(z) => {
                let (a, b) = f(z);
                out.push(Factor::Pair(a, b));
            }
        }
        out
    }

    /// -Int_0^r u P(x)/(lambda x c(x)) dr', x = (1 - u)/lambda (the step response, n = 1).
    fn odd_form(&self, p: &[T], lambda: &T) -> EvenRational<T> {
        let inv = lambda.clone().recip();
        self.odd_rational(p, lambda, &inv, true)
    }

    /// The first moment's form (order n = -1): -mu Int_0^r u P(x)/c(x) dr', x = (1 - u)/lambda,
    /// mu = 1 for the v-terms (lambda = m^2) and m^2 for the w-terms (lambda = 1): with
    /// sigma^2 = m^2 x, d sigma = -mu r dr/sigma and the factor sigma^-(n + 1) = 1.
    fn first_moment_form(&self, p: &[T], lambda: &T, mu: &T) -> EvenRational<T> {
        self.odd_rational(p, lambda, mu, false)
    }

    /// -scale Int_0^r u P(x)/c(x) dr' (times 1/x when `over_x`: the factor lambda x = 1 - u
    /// of the step response), x = (1 - u)/lambda, as an even rational function of r.
    fn odd_rational(&self, p: &[T], lambda: &T, scale: &T, over_x: bool) -> EvenRational<T> {
        let inv = lambda.clone().recip();
        let px = compose_affine(p, &inv, &(-inv.clone()));
        let mut num = vec![lambda.zero()];
        num.extend(px.into_iter().map(|c| -(c * scale)));
        let mut factors = if over_x {
            vec![Factor::Unit(inv.clone())]
        } else {
            Vec::new()
        };
        factors.extend(self.cubic_factors(|x| {
            (
                Cx::real(-inv.clone()),
                (-(x.clone().scale(lambda)))
                    .add_re(&lambda.one())
                    .scale(&inv),
            )
        }));
        Rational { num, factors }.head()
    }

    /// The polynomials P(x) of the direct terms (module docs): K^2 = (2 - x)^2 (v-part of zz,
    /// w-part of xx), 4 (1 - m^2 x) (w-part of zz) and 4 (1 - x) (v-part of xx), ascending.
    fn direct_polynomials(&self) -> [Vec<T>; 3] {
        let one = self.m.one();
        let four = one.lit(4.0);
        [
            vec![four.clone(), -four.clone(), one],
            vec![four.clone(), -(self.m2.clone() * 4.0)],
            vec![four.clone(), -four],
        ]
    }

    /// The v- and w-parts of the first moment of g_zz at this precision.
    fn first_zz_rationals(&self) -> (EvenRational<T>, EvenRational<T>) {
        let [k2, p_zz_w, _] = self.direct_polynomials();
        (
            self.first_moment_form(&k2, &self.m2, &self.m.one()),
            self.first_moment_form(&p_zz_w, &self.m.one(), &self.m2),
        )
    }

    /// -lambda^3 kappa Int_T^inf [sum_k p_k lambda^-k u^k y^(1 + n/2 - k + e)] /
    /// (y^e u^(n/2) prod_j lin_j(u)) dT'.
    fn even_form(&self, p: &[T], lambda: &T, kappa: &T, n: usize) -> EvenRational<T> {
        let half = n / 2;
        let deg = p.len() - 1;
        let e = deg.saturating_sub(1 + half);
        let one = lambda.one();
        let y = [one.clone(), one.clone()];
        let pre = -(lambda.clone().sqr() * lambda * kappa);
        let mut num = vec![lambda.zero()];
        let mut lam_k = one.clone();
        for (k, pk) in p.iter().enumerate() {
            let mut term = vec![lambda.zero(); k];
            term.push(pk.clone() * &pre / &lam_k);
            for _ in 0..(1 + half + e - k) {
                term = poly_mul(&term, &y);
            }
            poly_add(&mut num, &term);
            lam_k *= lambda;
        }
        let mut factors = Vec::new();
        for _ in 0..e {
            factors.push(Factor::Real(one.clone(), one.clone()));
        }
        for _ in 0..half {
            factors.push(Factor::Real(one.clone(), one.zero()));
        }
        factors.extend(self.cubic_factors(|x| {
            let lx = x.clone().scale(lambda);
            ((-lx.clone()).add_re(&one), -lx)
        }));
        Rational { num, factors }.tail()
    }

    /// The moment terms of order n: the partial fractions from the guard copy, rounded once;
    /// the cosine series of the cross term at the working precision.
    fn build_moment(&self, n: usize) -> MomentTerms<T> {
        let bits = self.m.prec();
        let (zz_v, zz_w, xx_v, xx_w, euler) = match &self.guard {
            Some(g) => {
                let (a, b, c, d, e) = g.rationals(n);
                (
                    a.round_to(bits),
                    b.round_to(bits),
                    c.round_to(bits),
                    d.round_to(bits),
                    e.map(|e| e.round_to(bits)),
                )
            }
            // the guard copy itself: T is rug::Float here
            None => self.rationals(n),
        };
        let xz = match euler {
            Some(r) => XzTerm::Euler(r),
            None => self.cosine_xz(n),
        };
        MomentTerms {
            zz_v,
            zz_w,
            xx_v,
            xx_w,
            xz,
        }
    }

    /// The even rational functions of the moment of order n (module docs): the v- and w-parts
    /// of zz and xx, and for n = 1 the cross term's Euler form.
    #[allow(clippy::type_complexity)]
    fn rationals(
        &self,
        n: usize,
    ) -> (
        EvenRational<T>,
        EvenRational<T>,
        EvenRational<T>,
        EvenRational<T>,
        Option<EvenRational<T>>,
    ) {
        let one = self.m.one();
        let [k2, p_zz_w, p_xx_v] = self.direct_polynomials();
        let kappa_w = self.m.clone().powi(1 - n as i32);
        let (zz_v, zz_w, xx_v, xx_w) = if n % 2 == 1 {
            (
                self.odd_form(&k2, &self.m2),
                self.odd_form(&p_zz_w, &one),
                self.odd_form(&p_xx_v, &self.m2),
                self.odd_form(&k2, &one),
            )
        } else {
            (
                self.even_form(&k2, &self.m2, &one, n),
                self.even_form(&p_zz_w, &one, &kappa_w, n),
                self.even_form(&p_xx_v, &self.m2, &one, n),
                self.even_form(&k2, &one, &kappa_w, n),
            )
        };
        let xz = if n == 1 {
            let a = &self.a;
            let am1 = a.clone() - 1.0;
            let pre = -(self.m.clone() * am1.sqr() * 2.0);
            let num = vec![one.zero(), pre.clone() * (one.lit(2.0) - a), pre];
            let mut factors = vec![Factor::Real(one.clone(), a.clone())];
            factors.extend(
                self.cubic_factors(|x| ((-x.clone()).add_re(&one), (-x.clone()).add_re(a))),
            );
            Some(Rational { num, factors }.head())
        } else {
            None
        };
        (zz_v, zz_w, xx_v, xx_w, xz)
    }

    /// The cross term's integrand in theta between P and S (module docs), for moment n.
    fn xz_theta(&self, theta: &T, n: usize) -> (T, f64) {
        let (sin, cos) = theta.clone().sin_cos();
        self.xz_sin_cos(&sin, &cos, n)
    }

    /// The same integrand from sin theta and cos theta, with the magnitude that bounds its
    /// rounding (|f| and the effect of rounding K = 2 - x, which vanishes at x = 2).
    fn xz_sin_cos(&self, sin: &T, cos: &T, n: usize) -> (T, f64) {
        let one = self.m.one();
        let om = one.clone() - &self.m2;
        // 1 +- cos theta without cancellation at either end
        let sin2 = sin.clone().sqr();
        let (opc, omc) = if *cos < 0.0 {
            let omc = one.clone() - cos;
            (sin2.clone() / &omc, omc)
        } else {
            let opc = one.clone() + cos;
            (opc.clone(), sin2.clone() / &opc)
        };
        // 1 - s^2 = (1 - m^2)(1 + cos)/2, s^2 - m^2 = (1 - m^2)(1 - cos)/2
        let v2 = om.clone() * opc / 2.0;
        let ym = om.clone() * omc / 2.0;
        let y = ym.clone() + &self.m2;
        let x = y.clone() * &self.a;
        let xm1 = ym * &self.a;
        let k = one.lit(2.0) - &x;
        let e = k.clone().sqr().sqr() + v2 * &xm1 * 16.0;
        let sigma = y.clone().sqrt();
        // f = -K C/E; the rounding of K (absolute eps x) moves f by at most
        // eps x |C|/E (1 + 4 K^4/E)
        let k4_e = (k.clone().sqr().sqr() / &e).to_f64();
        let c_e = om.sqr() * sin2 * &x / (self.m.clone() * e * sigma.powi(n as i32 + 1) * 4.0);
        let f = -(k * &c_e);
        let dev = f.to_f64().abs() + 4.0 * x.to_f64() * c_e.to_f64().abs() * (1.0 + 4.0 * k4_e);
        (f, dev)
    }

    /// The cosine series f(theta) = c_0/2 + sum_k c_k cos(k theta) of the cross term's
    /// integrand (module docs) from the trapezoidal rule on [0, pi] (exact to the aliasing of
    /// the coefficients beyond the last one kept), the number of samples doubled until the
    /// coefficients have decayed below the working precision.
    fn cosine_xz(&self, n: usize) -> XzTerm<T> {
        let pi = self.m.pi();
        let one = self.m.one();
        let eps = self.m.epsilon().to_f64();
        // the Rayleigh pole in cos theta: f ~ r_p/(cos theta - zeta_R) (docs/lamb.md, section 3)
        let om = one.clone() - &self.m2;
        let zeta = ((one.clone() + &self.m2) - self.s_r.clone().sqr() * 2.0) / &om;
        let k = one.lit(2.0) - &self.x_r;
        let r_p = k * &om * (one.clone() - zeta.clone().sqr()) * &self.m
            / (self.dc_r() * self.s_r.clone().powi(n as i32 + 1) * 2.0);
        let mut samples = 32usize;
        loop {
            let mm = samples;
            // cos(pi j/mm), j = 0 .. 2 mm - 1
            let table: Vec<T> = (0..2 * mm)
                .map(|j| (pi.clone() * (j as f64) / (mm as f64)).cos())
                .collect();
            let mut mag = 0.0;
            let f: Vec<T> = (0..=mm)
                .map(|i| {
                    let w = if i == 0 || i == mm { 0.5 } else { 1.0 };
                    let (full, dev) = self.xz_theta(&(pi.clone() * (i as f64) / (mm as f64)), n);
                    let pole = r_p.clone() / (table[i].clone() - &zeta);
                    mag += w * (dev + pole.to_f64().abs());
                    (full - pole) * w
                })
                .collect();
            let mut c = Vec::with_capacity(mm + 1);
            for k in 0..=mm {
                let mut acc = self.m.zero();
                for (i, fi) in f.iter().enumerate() {
                    acc.mul_add_assign(fi, &table[(k * i) % (2 * mm)]);
                }
                c.push(acc * 2.0 / (mm as f64));
            }
            let cmax = c.iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max);
            let tail = c[3 * mm / 4..]
                .iter()
                .map(|x| x.to_f64().abs())
                .fold(0.0, f64::max);
            let coef_err = 8.0 * eps * mag * 2.0 / (mm as f64);
            if tail <= (eps * cmax * 0.01).max(coef_err) || samples >= 1 << 12 {
                // keep the coefficients above the rounding level
                let mut keep = mm;
                while keep > 1 && c[keep].to_f64().abs() <= eps * cmax * 0.01 {
                    keep -= 1;
                }
                c.truncate(keep + 1);
                return XzTerm::Cosine(CosineSeries {
                    coef: c,
                    pole: (zeta, r_p),
                    coef_err,
                    tail: tail * (mm as f64) / 4.0,
                });
            }
            samples *= 2;
        }
    }

    /// Int_theta^pi of the cross term's integrand for phi = pi - theta < 3/4 by Gauss-Legendre
    /// in phi (the integrand is analytic there; sin and cos of theta are formed from phi, so
    /// nothing is lost as phi -> 0), with the difference of two rule sizes as the error.
    fn near_front_xz(&self, n: usize, phi: &T, s: &T) -> Estimate<T> {
        let bits = s.prec();
        let big = ((f64::from(bits) / 2.5) as usize).max(20);
        let small = big * 2 / 3;
        let eps = s.epsilon().to_f64();
        let sum = |nodes: usize| -> Option<(T, f64)> {
            let rule = complexfn::quadrature::gauss_legendre_rule::<T>(nodes, bits).ok()?;
            let half = phi.clone() / 2.0;
            let mut acc = s.zero();
            let mut mag = 0.0;
            for (x, w) in rule.iter() {
                let (sp, cp) = (half.clone() + half.clone() * x).sin_cos();
                let (f, dev) = self.xz_sin_cos(&sp, &(-cp), n);
                mag += w.to_f64().abs() * dev;
                acc.mul_add_assign(w, &f);
            }
            let h = half.to_f64();
            Some((acc * half, mag * h))
        };
        // double the rules until two sizes agree to the working precision (the integrand can
        // have a complex singularity near the P front when K(1/m^2) is small, nu near 0)
        let (mut big, mut small) = (big, small);
        let mut best = Estimate {
            value: s.zero(),
            error: f64::INFINITY,
            kind: complexfn::ErrorKind::Rounding,
        };
        for _ in 0..6 {
            let (Some((a, mag)), Some((b, _))) = (sum(big), sum(small)) else {
                break;
            };
            let diff = (a.clone() - &b).abs().to_f64();
            let err = diff + 16.0 * eps * mag;
            if err < best.error {
                best = Estimate {
                    value: a,
                    error: err,
                    kind: complexfn::ErrorKind::Rounding,
                };
            }
            if diff <= 64.0 * eps * mag {
                break;
            }
            small = big;
            big *= 2;
        }
        best
    }

    fn terms(&self, n: usize) -> &MomentTerms<T> {
        self.moments.by_n[n].get_or_init(|| self.build_moment(n))
    }

    /// The head variables of the odd moments at s < 1 (`docs/lamb.md`, section 3): v with
    /// 1 - v and its distance from the Rayleigh pole, and behind S (s < m) the same for w,
    /// each formed without cancellation.
    fn odd_heads(&self, s: &T) -> OddHeads<T> {
        let one = s.one();
        let v = ((one.clone() - s) * (one.clone() + s)).sqrt();
        // s^2 - s_R^2 exactly (up to rounding of the product)
        let d2 = (s.clone() - &self.s_r) * (s.clone() + &self.s_r);
        let v_r = (one.clone() - self.s_r.clone().sqr()).sqrt();
        let v_part = (
            s.clone().sqr() / (one.clone() + &v),
            d2.clone() / (v_r + &v),
            v,
        );
        let w_part = (*s < self.m).then(|| {
            let w = ((self.m.clone() - s) * (self.m.clone() + s)).sqrt() / &self.m;
            let w_r = (one.clone() - &self.x_r).sqrt();
            let x = s.clone().sqr() * &self.a;
            (x / (one + &w), d2 * &self.a / (w_r + &w), w)
        });
        OddHeads {
            v: v_part,
            w: w_part,
        }
    }

    /// The Taylor coefficients g_k of g_zz(s) = sum_k g_k u^k, u = s^2, at this precision
    /// (`terms` of them): behind the S arrival g_zz = -(K^2 + 4 v w) v/c(x) with x = u/m^2,
    /// K = 2 - x, v = (1 - u)^(1/2), w = (1 - x)^(1/2), all power series in u; the division by
    /// the cubic c(x) is the recurrence of its coefficients. The series converges for
    /// u < s_R^2 (the Rayleigh pole is the nearest singularity), its terms falling like
    /// (u/s_R^2)^k.
    fn zz_series_at(&self, terms: usize) -> Vec<T> {
        let one = self.m.one();
        // a = 1/m^2; v = sqrt(1 - u) and w = sqrt(1 - a u)
        let a = self.a.clone();
        let mut v = vec![one.clone()];
        for k in 1..terms {
            // (k - 3/2)/k, formed in T from exact integers
            let c = v[k - 1].clone() * (2.0 * k as f64 - 3.0) / (2.0 * k as f64);
            v.push(c);
        }
        let mut w = Vec::with_capacity(terms);
        let mut ak = one.clone();
        for c in &v {
            w.push(c.clone() * &ak);
            ak *= &a;
        }
        let mul = |p: &[T], q: &[T]| -> Vec<T> {
            (0..terms)
                .map(|k| {
                    let mut acc = one.zero();
                    for i in 0..=k.min(p.len() - 1) {
                        if k - i < q.len() {
                            acc += p[i].clone() * &q[k - i];
                        }
                    }
                    acc
                })
                .collect()
        };
        // K^2 + 4 v w = 4 - 4 a u + a^2 u^2 + 4 v w
        let mut num = mul(&v, &w);
        for c in num.iter_mut() {
            *c *= 4.0;
        }
        num[0] += one.lit(4.0);
        if terms > 1 {
            num[1] -= a.clone() * 4.0;
        }
        if terms > 2 {
            num[2] += a.clone().sqr();
        }
        let num = mul(&num, &v);
        // c(x) = x^3 - 8 x^2 + (24 - 16 m^2) x - 16 (1 - m^2), x = a u
        let cpoly = [
            -((one.clone() - &self.m2) * 16.0),
            (one.lit(24.0) - self.m2.clone() * 16.0) * &a,
            -(a.clone().sqr() * 8.0),
            a.clone().sqr() * &a,
        ];
        let mut g: Vec<T> = Vec::with_capacity(terms);
        for k in 0..terms {
            // sum_i c_i g_{k-i} = -num_k
            let mut acc = -num[k].clone();
            for i in 1..cpoly.len().min(k + 1) {
                acc -= cpoly[i].clone() * &g[k - i];
            }
            g.push(acc / &cpoly[0]);
        }
        g
    }

    /// The Taylor coefficients of g_zz in u = s^2 (see [`HalfPlane::zz_series_at`]), formed
    /// on the guard copy and rounded once; enough terms for s <= s_R/2 at this precision.
    pub(crate) fn zz_series(&self) -> &[T] {
        self.moments.zz_series.get_or_init(|| {
            let bits = self.m.prec();
            // terms fall like 4^-k at s = s_R/2
            let terms = (f64::from(bits) / 2.0).ceil() as usize + 8;
            match &self.guard {
                Some(g) => g
                    .zz_series_at(terms)
                    .iter()
                    .map(|c| T::from_mpfr(c, bits))
                    .collect(),
                None => self.zz_series_at(terms),
            }
        })
    }

    /// The first moment's partial fractions, from the guard copy and rounded once.
    fn first_zz_terms(&self) -> &(EvenRational<T>, EvenRational<T>) {
        self.moments.first_zz.get_or_init(|| match &self.guard {
            Some(g) => {
                let bits = self.m.prec();
                let (a, b) = g.first_zz_rationals();
                (a.round_to(bits), b.round_to(bits))
            }
            None => self.first_zz_rationals(),
        })
    }

    /// The first moment of the normal response, M_{-1}^zz(s) = Int_s^inf sigma g_zz(sigma)
    /// dsigma (principal value across s_R), with its absolute error estimate: the odd
    /// substitution of the step response without its factor 1/sigma^2 (`docs/lamb.md`,
    /// section 3), an even rational function of v (and w behind S) with no logarithm at
    /// s = 0. It enters the cell means of the space-time cells
    /// ([`HalfPlane::cell_mean_primitive_zz`]). Errors: s < 0 or not finite, s = s_R.
    pub fn first_moment_zz(&self, s: &T) -> Result<Estimate<T>> {
        self.first_moment_zz_with(s, true)
    }

    /// [`HalfPlane::first_moment_zz`] with or without the rounding of s_R (see
    /// [`HalfPlane::moment_with`]).
    pub(crate) fn first_moment_zz_with(&self, s: &T, rounding_of_s_r: bool) -> Result<Estimate<T>> {
        self.check_s("s", s)?;
        if *s == self.s_r {
            return Err(self.at_rayleigh("the first moment M_-1(s)"));
        }
        if *s >= 1.0 {
            return Ok(Estimate {
                value: s.zero(),
                error: 0.0,
                kind: complexfn::ErrorKind::Rounding,
            });
        }
        let (tv, tw) = self.first_zz_terms();
        let heads = self.odd_heads(s);
        let (_, gap, v) = &heads.v;
        let mut out = tv.eval(v, None, Some(gap));
        if let Some((_, gap, w)) = &heads.w {
            let b = tw.eval(w, None, Some(gap));
            out.value += &b.value;
            out.error += b.error;
        }
        // rounding of s_R moves the logarithm r s_R ln|s - s_R|
        if rounding_of_s_r {
            let eps = s.epsilon().to_f64();
            let c = self.rayleigh_constants();
            out.error += self.pole_conditioning(s) * eps * c.r_zz.to_f64().abs() * c.s_r.to_f64();
        }
        if !out.value.is_finite() {
            return Err(invalid(
                "s",
                short(s.to_f64()),
                "a point where M_-1(s) is finite",
            ));
        }
        Ok(out)
    }

    /// M_n(s) = Int_s^inf g(sigma) sigma^-n dsigma for n = 0, 1, 2 (module docs), each
    /// component with its absolute error estimate. Errors: s < 0 or not finite, s = s_R
    /// (logarithmic singularity of the direct terms, the delta of the cross term), s = 0 for
    /// n >= 1 (M_1 grows like (1 - nu) ln(1/s), M_2 like 1/s), n > 2.
    pub fn moment(&self, n: usize, s: &T) -> Result<Triple<Estimate<T>>> {
        self.moment_with(n, s, true)
    }

    /// [`HalfPlane::moment`], with (`rounding_of_s_r`) or without the error that the rounding
    /// of s_R causes in the logarithm at the Rayleigh arrival (a combination of moments in
    /// which the logarithms cancel accounts for it itself).
    pub(crate) fn moment_with(
        &self,
        n: usize,
        s: &T,
        rounding_of_s_r: bool,
    ) -> Result<Triple<Estimate<T>>> {
        if n > 2 {
            return Err(invalid("moment order n", n, "0, 1 or 2"));
        }
        self.check_s("s", s)?;
        if *s == self.s_r {
            return Err(self.at_rayleigh(match n {
                0 => "the spatial moment M_0(s)",
                1 => "the step response W(s)",
                _ => "the ramp moment M_2(s)",
            }));
        }
        if n >= 1 && *s == 0.0 {
            return Err(invalid(
                "s",
                0,
                "(0, inf) for the step response and the ramp moment (they diverge at s = 0, i.e. at x = 0 or t -> inf)",
            ));
        }
        let zero = s.zero();
        let est = |v: T| Estimate {
            value: v,
            error: 0.0,
            kind: complexfn::ErrorKind::Rounding,
        };
        if *s >= 1.0 {
            return Ok(Triple {
                zz: est(zero.clone()),
                xz: est(zero.clone()),
                xx: est(zero),
            });
        }
        let t = self.terms(n);
        let one = s.one();
        let v = ((one.clone() - s) * (one.clone() + s)).sqrt();
        // s^2 - s_R^2 exactly (up to rounding of the product), for the distance of each head
        // variable from the Rayleigh pole (docs/lamb.md, section 3)
        let d2 = (s.clone() - &self.s_r) * (s.clone() + &self.s_r);
        let v_r = (one.clone() - self.s_r.clone().sqr()).sqrt();
        let heads = (n == 1).then(|| self.odd_heads(s));
        let (mut zz, mut xx) = if let Some(OddHeads {
            v: (omv, gap, v), ..
        }) = &heads
        {
            (
                t.zz_v.eval(v, Some(omv), Some(gap)),
                t.xx_v.eval(v, Some(omv), Some(gap)),
            )
        } else if *s == 0.0 {
            (t.zz_v.eval_infinite(s), t.xx_v.eval_infinite(s))
        } else {
            let h = v.clone() / s;
            let gap =
                d2.clone() / (s.clone() * &self.s_r * (v_r.clone() * s + v.clone() * &self.s_r));
            (
                t.zz_v.eval(&h, None, Some(&gap)),
                t.xx_v.eval(&h, None, Some(&gap)),
            )
        };
        if *s < self.m {
            let w = ((self.m.clone() - s) * (self.m.clone() + s)).sqrt() / &self.m;
            let w_r = (one.clone() - &self.x_r).sqrt();
            let (a, b) = if let Some(OddHeads {
                w: Some((omw, gap, w)),
                ..
            }) = &heads
            {
                (
                    t.zz_w.eval(w, Some(omw), Some(gap)),
                    t.xx_w.eval(w, Some(omw), Some(gap)),
                )
            } else if *s == 0.0 {
                (t.zz_w.eval_infinite(s), t.xx_w.eval_infinite(s))
            } else {
                let h = w.clone() * &self.m / s;
                let gap = d2.clone() * &self.m
                    / (s.clone() * &self.s_r * (w_r.clone() * s + w.clone() * &self.s_r));
                (
                    t.zz_w.eval(&h, None, Some(&gap)),
                    t.xx_w.eval(&h, None, Some(&gap)),
                )
            };
            zz.value += &a.value;
            zz.error += a.error;
            xx.value += &b.value;
            xx.error += b.error;
        }
        let mut xz = self.xz_moment(t, n, s);
        // rounding of s_R: the logarithm r s_R^-n ln|s - s_R| of the direct terms moves by
        // r s_R^-n (d s_R)/|s - s_R|; the cross term's delta changes side within an ulp of s_R
        if rounding_of_s_r && *s < 1.0 {
            let eps = s.epsilon().to_f64();
            let c = self.rayleigh_constants();
            let srn = c.s_r.to_f64().powi(-(n as i32));
            let cond = self.pole_conditioning(s);
            zz.error += cond * eps * c.r_zz.to_f64().abs() * srn;
            xx.error += cond * eps * c.r_xx.to_f64().abs() * srn;
            if cond > 0.25 / eps {
                xz.error += std::f64::consts::PI * c.k_r.to_f64().abs() * c.s_r.to_f64() * srn;
            }
        }
        self.finite("the moment M_n(s)", s, Triple { zz, xz, xx })
    }

    fn xz_moment(&self, t: &MomentTerms<T>, n: usize, s: &T) -> Estimate<T> {
        let one = s.one();
        let mut out = match &t.xz {
            XzTerm::Euler(r) => {
                if *s > self.m {
                    let tau = ((one.clone() - s) * (one.clone() + s)
                        / ((s.clone() - &self.m) * (s.clone() + &self.m)))
                        .sqrt();
                    r.eval(&tau, None, None)
                } else {
                    r.eval_infinite(s)
                }
            }
            XzTerm::Cosine(series) => {
                // Int_theta^pi f = (c_0/2)(pi - theta) - sin(theta) sum_k (c_k/k) U_{k-1}(cos theta)
                // + r_p Int_theta^pi dtheta/(cos theta - zeta_R), the last
                // = -(2 r_p/sqrt(zeta^2 - 1)) atan(sqrt((zeta - 1)/(zeta + 1)) (1 + cos)/sin)
                let eps = s.epsilon().to_f64();
                let (zeta, r_p) = &series.pole;
                let root = (zeta.clone().sqr() - 1.0).sqrt();
                let kk = series.coef.len() as f64;
                let rounding = series.coef_err * (s.pi().to_f64() + 1.0 + kk.ln());
                if *s > self.m {
                    let om = one.clone() - &self.m2;
                    let s2 = s.clone().sqr();
                    let sin = ((one.clone() - s)
                        * (one.clone() + s)
                        * (s.clone() - &self.m)
                        * (s.clone() + &self.m))
                        .sqrt()
                        * 2.0
                        / &om;
                    let cos = ((one.clone() + &self.m2) - s2 * 2.0) / &om;
                    let theta = sin.clone().atan2(&cos);
                    // phi = pi - theta, formed without cancellation
                    let phi = sin.clone().atan2(&(-cos.clone()));
                    if phi < 0.75 {
                        // next to the P front the value vanishes like phi^3 and the series
                        // would lose it to cancellation: integrate directly
                        return self.near_front_xz(n, &phi, s);
                    }
                    let (sum, mag) = series.sine_sum(&cos);
                    let head = series.coef[0].clone() / 2.0 * (s.pi() - &theta);
                    let ratio = ((zeta.clone() - 1.0) / (zeta.clone() + 1.0)).sqrt()
                        * (cos.clone() + 1.0)
                        / &sin;
                    let pole = -(r_p.clone() * 2.0 / &root * ratio.atan());
                    let value = head.clone() - sin * sum + &pole;
                    Estimate {
                        error: series.tail
                            + rounding
                            + 16.0 * eps * (head.to_f64().abs() + kk * mag + pole.to_f64().abs()),
                        value,
                        kind: complexfn::ErrorKind::Rounding,
                    }
                } else {
                    let pole = -(r_p.clone() * s.pi() / &root);
                    let value = series.coef[0].clone() / 2.0 * s.pi() + &pole;
                    Estimate {
                        error: series.tail
                            + rounding
                            + 16.0 * eps * (value.to_f64().abs() + pole.to_f64().abs()),
                        value,
                        kind: complexfn::ErrorKind::Rounding,
                    }
                }
            }
        };
        if *s < self.s_r {
            let c = self.rayleigh_constants();
            let delta = s.pi() * &c.k_r * c.s_r.clone().powi(1 - n as i32);
            out.error += 16.0 * s.epsilon().to_f64() * delta.to_f64().abs();
            out.value += &delta;
        }
        out
    }

    /// The step responses W_zz(s), U_xz(s), U_xx(s) = M_1(s): u = P/(pi mu) W for a step
    /// force P H(t) (u_x of the normal force odd in x). s > 0, s != s_R.
    pub fn step(&self, s: &T) -> Result<Triple<Estimate<T>>> {
        self.moment(1, s)
    }

    /// Int_sa^sb g(s) s^-n ds over a cell 0 <= sa <= sb (principal value across s_R, the delta
    /// of the cross term counted when s_R is inside): n = 0 is the spatial cell Ix at fixed t,
    /// n = 1 the temporal cell It at fixed x (= W(sa) - W(sb)). Ends may not be s_R; sa = 0 only
    /// for n = 0.
    pub fn cell(&self, n: usize, sa: &T, sb: &T) -> Result<Triple<Estimate<T>>> {
        self.check_s("sa", sa)?;
        self.check_s("sb", sb)?;
        if sa > sb {
            return Err(invalid(
                "cell [sa, sb]",
                format!("[{}, {}]", short(sa.to_f64()), short(sb.to_f64())),
                "0 <= sa <= sb",
            ));
        }
        let a = self.moment(n, sa)?;
        let b = self.moment(n, sb)?;
        let diff = |p: Estimate<T>, q: Estimate<T>| Estimate {
            value: p.value - &q.value,
            error: p.error + q.error,
            kind: complexfn::ErrorKind::Rounding,
        };
        Ok(Triple {
            zz: diff(a.zz, b.zz),
            xz: diff(a.xz, b.xz),
            xx: diff(a.xx, b.xx),
        })
    }
}
