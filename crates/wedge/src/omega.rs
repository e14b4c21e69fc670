//! Omega (31), Omega0 (37), b (33), Lambda0 (38) and S0 (44).
//!
//! Omega depends on xi through s = xi^2 only, and is analytic in s on [0, m^2):
//!
//! ```text
//!   tan(pi Omega) = -m^2 (beta + gamma) (L/s) / (|p2| - beta gamma |p1|),
//! ```
//!
//! with the cancellation-free L/s of `complexfn::rayleigh` (L < 0 on (0, m), so the sign of
//! Omega is that of beta + gamma = gamma - cot Theta), and |p_k| = (1 - s/m_k^2)^(-1/2). At
//! s = 0 this gives (37), Omega0 = (1/pi) atan(m^2 (beta + gamma)/(1 - beta gamma)).
//!
//! With omega(u) = Omega(sqrt u) - Omega0 (`docs/errata.md`, section 9), eq (38) becomes
//!
//! ```text
//!   Lambda0(zeta) = Int_{-p}^{p} sgn(v) (Omega(v) - Omega0)/(v - zeta) dv = Int_0^{p^2} omega(u)/(u - zeta^2) du,
//! ```
//!
//! and (33), (44) are its regular parts:
//!
//! ```text
//!   b(xi) = Int_0^{p^2} (omega(u) - omega(xi^2))/(u - xi^2) du,   S0 = b(0) = Lambda0(0) = Int_0^{p^2} omega(u)/u du.
//! ```
//!
//! The u-integrand is analytic on [0, p^2] (the nearest singularity of omega is the branch
//! point u = m^2 of |p2|), so one Gauss-Legendre rule, with omega tabulated on its nodes once
//! per case ([`InnerRule`]), serves every evaluation of b, S0 and Lambda0. The rule is
//! Gauss-Legendre in t = ln sqrt(m^2 - u), which sends that branch point to t = -inf and needs
//! a third to a half fewer nodes than a rule in u (`docs/inner-rule.md`).
//! Near the segment, Lambda0 subtracts omega at zeta^2 (continued analytically) and adds
//! omega(zeta^2) ln((p^2 - zeta^2)/(-zeta^2)) in closed form, so its boundary values are
//!
//! ```text
//!   Lambda0^{+-}(xi) = b(xi) + omega(xi^2) ln((p^2 - xi^2)/xi^2) +- i pi omega(xi^2),  0 < xi < p.
//! ```

use complexfn::quadrature::{gauss_legendre_rule, CachedRules};
use std::ops::{Add, Div, Mul, Sub};

use complexfn::{Cx, Rayleigh, Real};

use crate::error::{Result, WedgeError};

/// Omega as a function of s = xi^2, real on [0, m^2) and continued to complex s.
#[derive(Clone, Debug)]
pub struct OmegaFn<T> {
    ray: Rayleigh<T>,
    /// beta + gamma (exactly zero when the case is on the logarithmic boundary).
    beta_plus_gamma: T,
    /// beta * gamma.
    beta_gamma: T,
    omega0: T,
}

impl<T: Real> OmegaFn<T> {
    /// Omega for coupling beta and friction gamma. `beta_plus_gamma` is passed separately so
    /// that a caller can make it exactly zero on the regime boundary gamma = cot Theta.
    pub fn new(ray: Rayleigh<T>, beta_plus_gamma: T, beta_gamma: T) -> Self {
        let m2 = ray.m2().clone();
        let omega0 =
            (m2 * &beta_plus_gamma / (beta_gamma.one() - &beta_gamma)).atan() / beta_gamma.pi();
        OmegaFn {
            ray,
            beta_plus_gamma,
            beta_gamma,
            omega0,
        }
    }

    /// The material's Rayleigh family.
    pub fn rayleigh(&self) -> &Rayleigh<T> {
        &self.ray
    }

    /// Omega0 = Omega(0), eq (37).
    pub fn omega0(&self) -> &T {
        &self.omega0
    }

    /// True when beta + gamma = 0, where Omega vanishes identically.
    pub fn is_zero(&self) -> bool {
        self.beta_plus_gamma == 0.0
    }

    /// Omega(xi) for real 0 <= xi < m, eq (31).
    pub fn omega(&self, xi: &T) -> T {
        if self.is_zero() {
            return xi.zero();
        }
        let (num, den) = self.tan_parts(xi);
        num.atan2(&den) / xi.pi()
    }

    /// 1/2 + Omega(xi) for real 0 <= xi < m, with full relative accuracy as Omega -> -1/2
    /// (a sharp wedge with coupling, where cot Theta is large): with tan(pi Omega) = num/den,
    /// den > 0, pi (1/2 + Omega) = atan2(den, -num), formed without the cancellation of
    /// 1/2 + Omega. It is the gap 1 + alpha of the exponent alpha = -1/2 + Omega(p) of the
    /// fundamental function at the contact edge.
    pub fn half_plus_omega(&self, xi: &T) -> T {
        self.omega_and_gap(xi).1
    }

    /// (Omega(xi), 1/2 + Omega(xi)), each to full relative accuracy, from one evaluation of
    /// tan(pi Omega) (see [`Self::half_plus_omega`]).
    pub fn omega_and_gap(&self, xi: &T) -> (T, T) {
        if self.is_zero() {
            return (xi.zero(), xi.lit(0.5));
        }
        let (num, den) = self.tan_parts(xi);
        let pi = xi.pi();
        let gap = den.clone().atan2(&-num.clone()) / &pi;
        (num.atan2(&den) / pi, gap)
    }

    /// tan(pi Omega) = num/den, eq (31): num = -m^2 (beta + gamma) L/xi^2 and
    /// den = |p2| - beta gamma |p1| > 0 (real arithmetic on the cut).
    fn tan_parts(&self, xi: &T) -> (T, T) {
        let (p1, p2, l_s) = self.ray.cut_values(xi);
        let num = -(self.ray.m2().clone() * &self.beta_plus_gamma * l_s);
        let den = p2 - self.beta_gamma.clone() * p1;
        (num, den)
    }

    /// (Omega(xi), cos(pi Omega), sin(pi Omega)) for real 0 <= xi < m. The cosine and sine
    /// are formed from tan(pi Omega) = num/den directly (den/hypot, num/hypot), so cos(pi Omega)
    /// keeps full relative accuracy when Omega is close to 1/2 (large friction).
    pub fn omega_cos_sin(&self, xi: &T) -> (T, T, T) {
        if self.is_zero() {
            return (xi.zero(), xi.one(), xi.zero());
        }
        let (num, den) = self.tan_parts(xi);
        let h = num.clone().hypot(&den);
        let om = num.clone().atan2(&den) / xi.pi();
        (om, den / &h, num / h)
    }

    /// (Omega(xi), 1/2 + Omega(xi), cos(pi Omega), sin(pi Omega)): [`Self::omega_cos_sin`]
    /// with the gap of [`Self::half_plus_omega`].
    pub fn omega_gap_cos_sin(&self, xi: &T) -> (T, T, T, T) {
        if self.is_zero() {
            return (xi.zero(), xi.lit(0.5), xi.one(), xi.zero());
        }
        let (num, den) = self.tan_parts(xi);
        let h = num.clone().hypot(&den);
        let pi = xi.pi();
        let om = num.clone().atan2(&den) / &pi;
        let gap = den.clone().atan2(&-num.clone()) / pi;
        (om, gap, den / &h, num / h)
    }

    /// 1 - 2 Omega0 with full relative accuracy as Omega0 -> 1/2 (strong friction):
    /// (2/pi) atan((1 - beta gamma)/(m^2 (beta + gamma))) for beta + gamma > 0.
    pub fn one_minus_two_omega0(&self) -> T {
        let num = self.ray.m2().clone() * &self.beta_plus_gamma;
        let den = self.beta_gamma.one() - &self.beta_gamma;
        if num > 0.0 {
            (den / num).atan() * 2.0 / self.beta_gamma.pi()
        } else {
            self.beta_gamma.one() - self.omega0.clone() * 2.0
        }
    }

    /// (cos(pi Omega0), sin(pi Omega0)) from tan(pi Omega0) = m^2 (beta + gamma)/(1 - beta gamma).
    pub fn omega0_cos_sin(&self) -> (T, T) {
        let num = self.ray.m2().clone() * &self.beta_plus_gamma;
        let den = self.beta_gamma.one() - &self.beta_gamma;
        let h = num.clone().hypot(&den);
        (den / &h, num / h)
    }

    /// omega(s) = Omega(sqrt s) - Omega0 for complex s near [0, m^2), free of cancellation as
    /// s -> 0 (where omega = O(s)), so that omega(u)/u in S0 keeps full relative accuracy.
    ///
    /// With tan(pi Omega) = A = m^2 (beta+gamma) N/D, N = -L/s, D = |p2| - beta gamma |p1| and
    /// A0 = m^2 (beta+gamma)/(1 - beta gamma), atan A - atan A0 = atan((A - A0)/(1 + A A0))
    /// (A A0 >= 0), and A - A0 is formed from N - 1, |p1| - 1, |p2| - 1, each written with an
    /// explicit factor s:
    /// |p_k| - 1 = (s/m_k^2)/(r_k (1 + r_k)), r_k = sqrt(1 - s/m_k^2), and with w = r_1 r_2,
    /// N - 1 = s [(1 + 1/m^2)(1 + 1/m^2 - s/m^2)/(1 + w) + 1 - 1/m^2 - s/m^2]/((1 + w) w).
    pub fn omega_rel(&self, s: &Cx<T>) -> Cx<T> {
        if self.is_zero() {
            return Cx::real(s.re.zero());
        }
        let one = s.re.one();
        let inv_m2 = self.ray.inv_m2().clone();
        let sm = s.clone().scale(&inv_m2);
        let r1 = (-s.clone()).add_re(&one).sqrt();
        let r2 = (-sm.clone()).add_re(&one).sqrt();
        let d1 = s.clone() / (r1.clone() * r1.clone().add_re(&one));
        let d2 = sm.clone() / (r2.clone() * r2.clone().add_re(&one));
        let w = r1 * &r2;
        let w1 = w.clone().add_re(&one);
        let a = (-sm.clone()).add_re(&(one.clone() + &inv_m2));
        let bracket =
            (a.scale(&(one.clone() + &inv_m2)) / &w1).add_re(&(one.clone() - &inv_m2)) - sm;
        let n1 = s.clone() * bracket / (w1 * &w);
        let bg = &self.beta_gamma;
        let one_bg = one.clone() - bg;
        let num = n1.clone().scale(&one_bg) - d2.clone() + d1.clone().scale(bg);
        let n = n1.add_re(&one);
        let d = d2.add_re(&one) - d1.add_re(&one).scale(bg);
        let k = self.ray.m2().clone() * &self.beta_plus_gamma;
        let den = d.scale(&one_bg) + n.scale(&(k.clone() * &k));
        let arg = num.scale(&k) / &den;
        arg.atan().scale(&s.re.pi().recip())
    }

    /// The parts of tan(pi Omega) at s = xi^2 (real on the cut, or complex near it) in the
    /// form used by [`Self::divided_difference`].
    pub(crate) fn tan_form<F: Field<T>>(&self, s: &F) -> TanForm<F> {
        let inv_m2 = self.ray.inv_m2().clone();
        // 1 - c s
        let one_minus = |c: &T| s.clone().rmul(c) * -1.0 + 1.0;
        let r1 = one_minus(&inv_m2.one()).sqrt_f();
        let r2 = one_minus(&inv_m2).sqrt_f();
        let w = r1.clone() * &r2;
        let k = one_minus(&inv_m2) + 1.0;
        let q = w.clone() * (k.clone() + w.clone() * 2.0);
        // P = 4 + s (1/m^4 - 4/m^2)
        let pp = s
            .clone()
            .rmul(&(inv_m2.clone().sqr() - inv_m2.clone() * 4.0))
            + 4.0;
        let n = pp.clone() / &q;
        let d = r2.clone().recip_f() - r1.clone().recip_f().rmul(&self.beta_gamma);
        let a = (n.clone() / &d).rmul(&(self.ray.m2().clone() * &self.beta_plus_gamma));
        TanForm {
            s: s.clone(),
            r1,
            r2,
            w,
            k,
            q,
            pp,
            n,
            d,
            a,
        }
    }

    /// The divided difference (Omega(sqrt u) - Omega(sqrt s))/(u - s) for u, s in [0, m^2)
    /// or complex near it, free of cancellation however close u is to s (the limit u = s is
    /// Omega'(s)).
    ///
    /// With A = tan(pi Omega) = m^2 (beta + gamma) N/D, N = -L/s = P/(w (K + 2 w)),
    /// P = 4 + s (1/m^4 - 4/m^2) (from K^2 - 4 w^2 = s P), w = r1 r2, r_k = (1 - s/m_k^2)^(1/2),
    /// K = 2 - s/m^2 and D = 1/r2 - beta gamma/r1, every difference between u and s carries
    /// the factor u - s explicitly:
    ///
    /// ```text
    ///   w_u^2 - w_s^2 = (u - s)((u + s)/m^2 - 1 - 1/m^2),   1/r_u - 1/r_s = (u - s)/(m_k^2 r_u r_s (r_u + r_s)),
    /// ```
    ///
    /// and pi (Omega_u - Omega_s) = atan((A_u - A_s)/(1 + A_u A_s)) (A_u A_s >= 0 on the cut,
    /// so no branch of the arctangent is crossed near it).
    pub(crate) fn divided_difference<F: Field<T>>(&self, u: &TanForm<F>, s: &TanForm<F>) -> F {
        let inv_m2 = self.ray.inv_m2().clone();
        let one = inv_m2.one();
        let dw2 = (u.s.clone() + &s.s)
            .rmul(&inv_m2)
            .radd(&-(one.clone() + &inv_m2));
        let dw = dw2.clone() / &(u.w.clone() + &s.w);
        // Q = w K + 2 w^2: Q_u - Q_s = (u - s) dq
        let dq = dw * &u.k - s.w.clone().rmul(&inv_m2) + dw2 * 2.0;
        let dp = inv_m2.clone().sqr() - inv_m2.clone() * 4.0;
        let dn = (s.q.clone().rmul(&dp) - s.pp.clone() * &dq) / &(u.q.clone() * &s.q);
        let dinv = |ru: &F, rs: &F, inv_mk2: &T| {
            (ru.clone() * rs * &(ru.clone() + rs))
                .recip_f()
                .rmul(inv_mk2)
        };
        let dd = dinv(&u.r2, &s.r2, &inv_m2) - dinv(&u.r1, &s.r1, &one).rmul(&self.beta_gamma);
        let da = ((dn * &s.d - s.n.clone() * &dd) / &(u.d.clone() * &s.d))
            .rmul(&(self.ray.m2().clone() * &self.beta_plus_gamma));
        let y = da / &(u.a.clone() * &s.a + 1.0);
        let z = y.clone() * &(u.s.clone() - &s.s);
        let atan_ratio = if z.is_zero_f() {
            z.clone() * 0.0 + 1.0
        } else {
            z.clone().atan_f() / &z
        };
        (y * &atan_ratio).rmul(&one.pi().recip())
    }

    /// Omega continued analytically to complex s = zeta^2 (agrees with [`Self::omega`] for
    /// real 0 <= s < m^2).
    pub fn omega_continued(&self, s: &Cx<T>) -> Cx<T> {
        if self.is_zero() {
            return Cx::real(s.re.zero());
        }
        let v = self.ray.continued(s);
        let num = -(v
            .l_over_s
            .scale(&(self.ray.m2().clone() * &self.beta_plus_gamma)));
        let den = v.p2 - v.p1.scale(&self.beta_gamma);
        let arg = num / &den;
        arg.atan().scale(&s.re.pi().recip())
    }
}

/// The arithmetic that [`TanForm`] and [`OmegaFn::divided_difference`] need, shared by real
/// s on the cut and complex s near it (one formula for both).
pub(crate) trait Field<T: Real>:
    Clone
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
    + Add<f64, Output = Self>
    + Sub<f64, Output = Self>
    + Mul<f64, Output = Self>
{
    /// Times a real.
    fn rmul(self, r: &T) -> Self;
    /// Plus a real.
    fn radd(self, r: &T) -> Self;
    /// Principal square root.
    fn sqrt_f(self) -> Self;
    /// 1/self.
    fn recip_f(self) -> Self;
    /// Principal arctangent.
    fn atan_f(self) -> Self;
    /// Exactly zero.
    fn is_zero_f(&self) -> bool;
}

impl<T: Real> Field<T> for T {
    fn rmul(self, r: &T) -> Self {
        self * r
    }
    fn radd(self, r: &T) -> Self {
        self + r
    }
    fn sqrt_f(self) -> Self {
        self.sqrt()
    }
    fn recip_f(self) -> Self {
        self.recip()
    }
    fn atan_f(self) -> Self {
        self.atan()
    }
    fn is_zero_f(&self) -> bool {
        *self == 0.0
    }
}

impl<T: Real> Field<T> for Cx<T> {
    fn rmul(self, r: &T) -> Self {
        self.scale(r)
    }
    fn radd(self, r: &T) -> Self {
        self.add_re(r)
    }
    fn sqrt_f(self) -> Self {
        self.sqrt()
    }
    fn recip_f(self) -> Self {
        self.recip()
    }
    fn atan_f(self) -> Self {
        self.atan()
    }
    fn is_zero_f(&self) -> bool {
        self.re == 0.0 && self.im == 0.0
    }
}

impl<T: Real> TanForm<T> {
    /// The same parts as complex numbers.
    fn complex(&self) -> TanForm<Cx<T>> {
        let c = |x: &T| Cx::real(x.clone());
        TanForm {
            s: c(&self.s),
            r1: c(&self.r1),
            r2: c(&self.r2),
            w: c(&self.w),
            k: c(&self.k),
            q: c(&self.q),
            pp: c(&self.pp),
            n: c(&self.n),
            d: c(&self.d),
            a: c(&self.a),
        }
    }
}

/// tan(pi Omega) and its parts at one s = xi^2 on the cut or near it (see
/// [`OmegaFn::divided_difference`]).
#[derive(Clone, Debug)]
pub(crate) struct TanForm<T> {
    s: T,
    r1: T,
    r2: T,
    w: T,
    k: T,
    q: T,
    pp: T,
    n: T,
    d: T,
    a: T,
}

/// The interval of the inner rule's variable t = ln sqrt(m^2 - u), [ln sqrt(m^2 - p^2), ln m],
/// as (centre, half-width) in f64: the half-width is -(1/4) ln(1 - p^2/m^2).
fn log_interval(m: f64, p: f64) -> (f64, f64) {
    let half = -0.25 * (-(p / m).powi(2)).ln_1p();
    (m.ln() - half, half)
}

/// The Bernstein-ellipse parameter of a point z of the complex t-plane with respect to the
/// t-interval (centre, half-width): the rule's error for a pole or branch point at z falls
/// like rho^(-2n). Infinite (or NaN) for points at infinity.
fn ellipse_parameter(z: num_complex::Complex<f64>, centre: f64, half: f64) -> f64 {
    let zeta = (z - centre) / half;
    let w = zeta + (zeta - 1.0).sqrt() * (zeta + 1.0).sqrt();
    let r = w.norm();
    r.max(1.0 / r)
}

/// First guess of the Gauss-Legendre degree of the inner rule at `prec` bits.
///
/// The rule is Gauss-Legendre in t = ln x, x = sqrt(m^2 - u) (`docs/inner-rule.md`): the
/// branch point u = m^2 of omega goes to t = -inf, and the nearest singularities left are
/// those of Lambda0(s) for s in (m^2, 1), whose poles u = s lie at t = ln sqrt(s - m^2) +- i pi/2,
/// at worst straight above the centre of the interval: rho = b + sqrt(b^2 + 1),
/// b = (pi/2)/half-width (the branch point u = 1 of |p1|, at the same height and further out,
/// is no nearer). The rule's error then falls like rho^(-2n), so n = prec ln 2/(2 ln rho) nodes
/// reach the working precision. A margin of 5 percent plus 2 nodes covers the prefactor (the
/// rule of that size passes the doubling test of [`InnerRule::new`] from f64 to 365 bits and
/// p from 0.02 to 0.99 m_R, see the test `predicted_rule_is_accepted`); the doubling test
/// confirms it in every case (and doubles if a complex singularity of the arctangent lies
/// closer).
pub fn predicted_nodes(m: f64, p: f64, prec: u32) -> usize {
    let (_, half) = log_interval(m, p);
    let b = std::f64::consts::FRAC_PI_2 / half.max(1e-300);
    let rho = b + b.hypot(1.0);
    let n = f64::from(prec) * std::f64::consts::LN_2 / (2.0 * rho.ln().max(1e-3));
    ((1.05 * n).ceil() as usize + 2).clamp(16, 4096)
}

/// First guess of the degree of the fallback rule in u itself ([`InnerRule::new`]): the
/// branch point u = m^2 lies on the Bernstein ellipse of [0, p^2] of parameter
/// rho = a + sqrt(a^2 - 1), a = 2 m^2/p^2 - 1, with a margin of 10 percent plus 4 nodes.
fn predicted_nodes_u(m: f64, p: f64, prec: u32) -> usize {
    let a = 2.0 * (m / p).powi(2) - 1.0;
    let rho = a + (a * a - 1.0).max(0.0).sqrt();
    let n = f64::from(prec) * std::f64::consts::LN_2 / (2.0 * rho.ln().max(1e-3));
    ((1.1 * n).ceil() as usize + 4).clamp(16, 4096)
}

/// Omega - Omega0 tabulated on a Gauss-Legendre rule over [0, p^2]: the one table behind
/// b, S0 and Lambda0. The rule is Gauss-Legendre in t = ln sqrt(m^2 - u) (see
/// [`predicted_nodes`] and `docs/inner-rule.md`), carried back to nodes u_j and weights w_j in u.
#[derive(Clone, Debug)]
pub struct InnerRule<T> {
    p2: T,
    /// Whether the rule is Gauss-Legendre in t (otherwise in u: the fallback of
    /// [`InnerRule::new`]).
    log_var: bool,
    /// Centre and half-width of the t-interval (f64: they decide the form of a Lambda0 sum).
    log_centre: f64,
    log_half: f64,
    /// (u_j, w_j, omega(u_j)) with omega = Omega - Omega0.
    nodes: Vec<(T, T, T)>,
    /// w_j omega(u_j), the numerators of the unsubtracted sums.
    w_om: Vec<T>,
    /// w_j Omega(u_j) = w_j (omega(u_j) + Omega0), the numerators of
    /// [`InnerRule::omega_cauchy_outside`].
    w_big_om: Vec<T>,
    /// w_j in f64: the node spacing that decides where a divided difference is needed.
    w_f64: Vec<f64>,
    /// tan(pi Omega) in parts at each node, for the divided differences of nodes close to the
    /// evaluation point (empty when Omega = 0).
    forms: Vec<TanForm<T>>,
    /// |S0(n) - S0(n/2)|, the convergence estimate of the rule (absolute).
    error: f64,
}

impl<T: CachedRules> InnerRule<T> {
    /// Build the rule for contact speed p, doubling the number of nodes until S0 and b at
    /// two interior points agree between n and 2n to the working precision.
    ///
    /// Should the rule in t not converge within six doublings (an arctangent branch point close
    /// to u = 0, where t compresses [0, p^2] the most: nu = 0.4999 with gamma = 1e6), the same
    /// doubling runs on a rule in u itself.
    pub fn new(omega: &OmegaFn<T>, p: &T) -> Result<Self> {
        let prec = p.prec();
        let p2 = p.clone().sqr();
        let eps = p.epsilon().to_f64().max(1e-300);
        if omega.is_zero() {
            // Omega = 0 (beta + gamma = 0): b, S0 and Lambda0 vanish identically. No rule is
            // built and every sum over the (empty) nodes is an exact zero.
            return Ok(InnerRule {
                p2,
                log_var: true,
                log_centre: 0.0,
                log_half: 1.0,
                nodes: Vec::new(),
                w_om: Vec::new(),
                w_big_om: Vec::new(),
                w_f64: Vec::new(),
                forms: Vec::new(),
                error: 0.0,
            });
        }
        let (m, pf) = (omega.rayleigh().m().to_f64(), p.to_f64());
        let mut reached = f64::INFINITY;
        for log_var in [true, false] {
            let n = if log_var {
                predicted_nodes(m, pf, prec)
            } else {
                predicted_nodes_u(m, pf, prec)
            };
            match Self::doubled(omega, p, n, log_var)? {
                Ok(rule) => return Ok(rule),
                Err(d) => reached = d,
            }
        }
        Err(WedgeError::NoConvergence(complexfn::NoConvergence {
            what: "Gauss-Legendre rule for Lambda0".into(),
            reached,
            asked: eps,
        }))
    }

    /// The doubling test from n nodes in t (`log_var`) or in u: the accepted rule, or the
    /// last difference found.
    fn doubled(
        omega: &OmegaFn<T>,
        p: &T,
        mut n: usize,
        log_var: bool,
    ) -> Result<std::result::Result<Self, f64>> {
        let p2 = p.clone().sqr();
        let eps = p.epsilon().to_f64().max(1e-300);
        let mut prev: Option<Self> = None;
        let mut last_d: Option<f64> = None;
        for _ in 0..6 {
            let rule = Self::with_nodes(omega, &p2, n, log_var)?;
            if let Some(pr) = &prev {
                let mut d = 0.0_f64;
                let mut scale = 1e-300_f64;
                // b on the contact and between p and m, and Lambda0 at the worst real point
                // of (m^2, 1): u = s at t = centre +- i pi/2 (see `predicted_nodes`)
                let m = omega.rayleigh().m();
                let probes = [
                    p.zero(),
                    p.clone() * 0.5,
                    p.clone() * 0.97,
                    (p.clone() + m) / 2.0,
                ];
                let x_c = p.lit(2.0 * rule.log_centre).exp();
                let s_c = omega.rayleigh().m2().clone() + x_c;
                let values = probes
                    .iter()
                    .map(|xi| (rule.b(omega, xi), pr.b(omega, xi)))
                    .chain([
                        (
                            rule.lambda0_real_outside(&s_c),
                            pr.lambda0_real_outside(&s_c),
                        ),
                        (
                            rule.omega_cauchy_outside(&s_c),
                            pr.omega_cauchy_outside(&s_c),
                        ),
                    ]);
                for (a, b) in values {
                    d = d.max((a.clone() - &b).abs().to_f64());
                    scale = scale.max(a.abs().to_f64()).max(1.0);
                }
                // converged, or stuck at the round-off floor (no longer decreasing)
                let floor = last_d.is_some_and(|l: f64| d > l / 4.0) && d < 1e3 * eps * scale;
                last_d = Some(d);
                if d <= 16.0 * eps * scale || floor {
                    // n/2 nodes already agree with n to working precision: keep the smaller
                    // rule, with the difference as its error estimate.
                    let mut r = prev.take().expect("previous rule");
                    r.error = d;
                    return Ok(Ok(r));
                }
            }
            prev = Some(rule);
            n *= 2;
        }
        Ok(Err(last_d.unwrap_or(f64::INFINITY)))
    }

    /// The rule of n nodes in t = ln x, x = sqrt(m^2 - u), t in [t_p, t_m] = [ln sqrt(m^2 - p^2), ln m]:
    /// with h = (t_m - t_p)/2 = -(1/4) ln(1 - p^2/m^2) and tau_j the Gauss-Legendre nodes on
    /// [-1, 1], x_j^2 = m^2 exp(-2 h (1 - tau_j)), u_j = -m^2 expm1(-2 h (1 - tau_j)) (full
    /// relative accuracy as u_j -> 0) and w_j = 2 h x_j^2 w_tau_j (du = -2 x^2 dt).
    ///
    /// Without `log_var` the rule is Gauss-Legendre in u itself: u_j = (p^2/2)(1 + tau_j),
    /// w_j = (p^2/2) w_tau_j.
    fn with_nodes(omega: &OmegaFn<T>, p2: &T, n: usize, log_var: bool) -> Result<Self> {
        let rule = gauss_legendre_rule::<T>(n, p2.prec())?;
        let m2 = omega.rayleigh().m2().clone();
        let half = -(-(p2.clone() / &m2)).ln_1p() / 4.0;
        let half_u = p2.clone() / 2.0;
        let (log_centre, log_half) =
            log_interval(omega.rayleigh().m().to_f64(), p2.to_f64().sqrt());
        let form0 = omega.tan_form(&p2.zero());
        let mut forms = Vec::with_capacity(n);
        let nodes: Vec<(T, T, T)> = rule
            .iter()
            .map(|(tau, w)| {
                let (u, wu) = if log_var {
                    let e = ((p2.one() - tau) * &half * -2.0).exp_m1();
                    let u = -(m2.clone() * &e);
                    let x2 = m2.clone() - &u;
                    (u, w.clone() * &half * x2 * 2.0)
                } else {
                    (half_u.clone() * (tau.clone() + 1.0), w.clone() * &half_u)
                };
                // omega(u) = u (Omega(u) - Omega(0))/(u - 0), free of cancellation
                let f = omega.tan_form(&u);
                let om = omega.divided_difference(&f, &form0) * &u;
                forms.push(f);
                (u, wu, om)
            })
            .collect();
        let w_om: Vec<T> = nodes.iter().map(|(_, w, om)| om.clone() * w).collect();
        let w_big_om = nodes
            .iter()
            .zip(&w_om)
            .map(|((_, w, _), w_om)| {
                let mut t = w_om.clone();
                t.mul_add_assign(w, omega.omega0());
                t
            })
            .collect();
        let w_f64 = nodes.iter().map(|(_, w, _)| w.to_f64()).collect();
        Ok(InnerRule {
            p2: p2.clone(),
            log_var,
            log_centre,
            log_half,
            nodes,
            w_om,
            w_big_om,
            w_f64,
            forms,
            error: f64::INFINITY,
        })
    }
}

impl<T: Real> InnerRule<T> {
    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }
    /// Whether the rule is empty (when Omega vanishes identically, and only then).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }
    /// Convergence estimate (absolute, from n and n/2 nodes).
    pub fn error(&self) -> f64 {
        self.error
    }

    /// b(xi) of eq (33) for real 0 <= xi < m (continued analytically for p < xi < m).
    pub fn b(&self, omega: &OmegaFn<T>, xi: &T) -> T {
        if omega.is_zero() {
            return xi.zero();
        }
        let s = xi.clone().sqr();
        let om_s = omega.omega(xi) - omega.omega0();
        self.b_with(omega, &s, &om_s)
    }

    /// b at s = xi^2 (0 <= s < m^2) given omega(s) = Omega(xi) - Omega0 (saves an evaluation
    /// of Omega).
    ///
    /// Each term is w_j (omega(u_j) - omega(s))/(u_j - s). Where |u_j - s| < w_j (the node
    /// spacing), the rounding of the two values of omega would be amplified by w_j/|u_j - s|
    /// (up to 1e-10 in f64 without care); there the divided difference is formed without
    /// cancellation (`OmegaFn::divided_difference`), so every term keeps the working
    /// precision.
    ///
    /// The sum runs in place (two temporaries for all terms); which form a term takes is
    /// decided in f64 (|u_j - s| against w_j), as either form is exact there.
    pub fn b_with(&self, omega: &OmegaFn<T>, s: &T, om_s: &T) -> T {
        let mut acc = s.zero();
        let mut s_form: Option<TanForm<T>> = None;
        let mut d = s.zero();
        let mut t = s.zero();
        for (j, ((u, w, _), (w_om, &w_f))) in self
            .nodes
            .iter()
            .zip(self.w_om.iter().zip(&self.w_f64))
            .enumerate()
        {
            d.clone_from(u);
            d -= s;
            if d.to_f64().abs() < w_f {
                let sf = s_form.get_or_insert_with(|| omega.tan_form(s));
                acc += omega.divided_difference(&self.forms[j], sf) * w;
                continue;
            }
            // w_j omega_j - omega(s) w_j, one fused rounding
            t.clone_from(w_om);
            t.mul_sub_assign(om_s, w);
            t /= &d;
            acc += &t;
        }
        acc
    }

    /// S0 = b(0), eq (44).
    pub fn s0(&self) -> T {
        let mut acc = self.p2.zero();
        for ((u, _, _), w_om) in self.nodes.iter().zip(&self.w_om) {
            acc += w_om.clone() / u;
        }
        acc
    }

    /// Int_0^{p^2} Omega(u)/(u - s) du = Omega0 ln(1 - p^2/s) + Lambda0(s) at a real s >= m^2
    /// (v >= m): the exponent of H(v)/v sqrt(v^2 - p^2) there, summed in place without a
    /// logarithm.
    ///
    /// The rule resolves the pole u = s for s >= m^2 whatever the numerator's constant part
    /// (its nodes are placed for the pole, see [`predicted_nodes`]; the doubling test of
    /// [`InnerRule::new`] checks this sum), so the closed-form Omega0 ln(1 - p^2/s) is not
    /// needed: the terms w_j Omega(u_j)/(u_j - s) have one sign and no cancellation.
    pub fn omega_cauchy_outside(&self, s: &T) -> T {
        let mut acc = s.zero();
        let mut d = s.zero();
        let mut t = s.zero();
        for ((u, _, _), w_big_om) in self.nodes.iter().zip(&self.w_big_om) {
            d.clone_from(u);
            d -= s;
            t.clone_from(w_big_om);
            t /= &d;
            acc += &t;
        }
        acc
    }

    /// Lambda0 at a real s = v^2 > p^2 (no subtraction), summed in place.
    pub fn lambda0_real_outside(&self, s: &T) -> T {
        let mut acc = s.zero();
        let mut d = s.zero();
        let mut t = s.zero();
        for ((u, _, _), w_om) in self.nodes.iter().zip(&self.w_om) {
            d.clone_from(u);
            d -= s;
            t.clone_from(w_om);
            t /= &d;
            acc += &t;
        }
        acc
    }

    /// Lambda0(zeta) of eq (38) off the segment [-p, p] of the real axis.
    pub fn lambda0(&self, omega: &OmegaFn<T>, zeta: &Cx<T>) -> Cx<T> {
        if omega.is_zero() {
            return Cx::real(zeta.re.zero());
        }
        let s = zeta.clone() * zeta;
        // The plain sum of omega(u)/(u - s) converges like rho_s^(-2n), rho_s the ellipse
        // parameter of the pole t_s = ln sqrt(m^2 - s) (principal; its images t_s +- i pi are
        // further away) in the rule's variable t: it is used only where that reaches the working
        // precision (with a factor 4 of margin in the exponent). Closer to the segment the
        // subtracted form is summed: omega(s) (principal square roots, which continue omega(u)
        // in x = sqrt(m^2 - u)) removes the pole at t_s, and the poles left, t_s +- i pi, are
        // never nearer than the singularities the rule is built for.
        let n = self.nodes.len().max(1) as f64;
        let rho = 2f64.powf(1.25 * f64::from(s.re.prec()) / (2.0 * n));
        let m2 = omega.rayleigh().m2().to_f64();
        let t_s = (num_complex::Complex::new(m2, 0.0) - s.to_c64())
            .sqrt()
            .ln();
        let rho_s = ellipse_parameter(t_s, self.log_centre, self.log_half);
        // NaN (s = m^2, t_s = -inf) is far from the segment: the plain sum
        let subtract = if self.log_var {
            rho_s < rho
        } else {
            // the rule in u: the ellipse of s about [0, p^2] (semi-major axis a in units of
            // p^2/2), the subtracted form inside the ellipse through the branch point u = m^2
            let a = (s.abs() + s.clone().add_re(&(-self.p2.clone())).abs()) / &self.p2;
            let a_plain = s.re.lit(0.5 * (rho + 1.0 / rho));
            let limit = (omega.rayleigh().m2().clone() * 2.0 / &self.p2 - 1.01).min(a_plain);
            a < limit
        };
        if subtract {
            let om_s = omega.omega_rel(&s);
            let mut acc = Cx::real(s.re.zero());
            let mut s_form: Option<TanForm<Cx<T>>> = None;
            for (j, (u, w, om)) in self.nodes.iter().enumerate() {
                let den = (-s.clone()).add_re(u);
                if den.abs() < *w {
                    // next to a node: the divided difference without cancellation (as in b)
                    let sf = s_form.get_or_insert_with(|| omega.tan_form(&s));
                    acc += omega
                        .divided_difference(&self.forms[j].complex(), sf)
                        .scale(w);
                    continue;
                }
                let num = (-om_s.clone()).add_re(om).scale(w);
                acc += num / &den;
            }
            let log = (-s.clone()).add_re(&self.p2).ln() - (-s).ln();
            acc + om_s * &log
        } else {
            let mut acc = Cx::real(s.re.zero());
            for (u, w, om) in &self.nodes {
                let den = (-s.clone()).add_re(u);
                acc += Cx::real(om.clone() * w) / &den;
            }
            acc
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    fn omega_fn<T: Real>(like: &T, beta: f64, gamma: f64) -> OmegaFn<T> {
        let m = like.lit(1000.0) / like.lit(1870.83);
        let ray = Rayleigh::new(m).unwrap();
        let (b, g) = (like.lit(beta), like.lit(gamma));
        OmegaFn::new(ray, b.clone() + &g, b * g)
    }

    #[test]
    fn omega_rel_is_omega_minus_omega0_without_cancellation() {
        // against Omega - Omega0 at 256 bits (where the cancellation costs nothing visible)
        let big = omega_fn(&Float::with_val(256, 0), -0.0175, 0.6);
        let small = omega_fn(&0.0_f64, -0.0175, 0.6);
        for u in [1e-12, 1e-6, 0.01, 0.2, 0.27] {
            let ub = Float::with_val(256, u);
            let exact = big.omega(&ub.clone().sqrt()) - big.omega0();
            let got = small.omega_rel(&Cx::real(u)).re;
            let rel = ((got - exact.to_f64()) / exact.to_f64()).abs();
            assert!(rel < 1e-14, "u {u}: {got} {exact}");
            let gb = big.omega_rel(&Cx::real(ub)).re;
            assert!(crate::omega::tests::rd(&gb, &exact) < 1e-60);
        }
        // continuation: complex s agrees with Omega_continued - Omega0
        let s = Cx::new(0.05, 0.02);
        let a = small.omega_rel(&s);
        let b = small.omega_continued(&s).add_re(&-small.omega0());
        assert!((a - b).abs() < 1e-15);
    }

    #[test]
    fn divided_difference_matches_the_difference_quotient() {
        // at 256 bits the plain quotient loses at most ~1e-60 for |u - s| >= 1e-15
        let big = omega_fn(&Float::with_val(256, 0), -0.0175, 0.6);
        let small = omega_fn(&0.0_f64, -0.0175, 0.6);
        for (u, s) in [
            (0.01, 0.0100001),
            (0.2, 0.2 + 1e-13),
            (0.05, 0.27),
            (1e-9, 0.0),
        ] {
            let (ub, sb) = (Float::with_val(256, u), Float::with_val(256, s));
            let exact = (big.omega(&ub.clone().sqrt()) - big.omega(&sb.clone().sqrt()))
                / (ub.clone() - &sb);
            let got_b = big.divided_difference(&big.tan_form(&ub), &big.tan_form(&sb));
            assert!(rd(&got_b, &exact) < 1e-55, "{u} {s}");
            let got = small.divided_difference(&small.tan_form(&u), &small.tan_form(&s));
            let rel = ((got - exact.to_f64()) / exact.to_f64()).abs();
            assert!(rel < 1e-14, "f64 {u} {s}: {got} vs {exact}");
        }
        // u = s: the derivative, against a central difference at 256 bits
        let s = Float::with_val(256, 0.15);
        let h = Float::with_val(256, 1e-25);
        let deriv =
            (big.omega(&(s.clone() + &h).sqrt()) - big.omega(&(s.clone() - &h).sqrt())) / (h * 2.0);
        let f = big.tan_form(&s);
        assert!(rd(&big.divided_difference(&f, &f), &deriv) < 1e-45);
    }

    #[test]
    fn b_keeps_full_precision_next_to_the_nodes() {
        // b at points within a hair of every node of the f64 rule, against 256 bits
        let p = 0.3;
        let small = omega_fn(&0.0_f64, -0.0175, 0.6);
        let big = omega_fn(&Float::with_val(256, 0), -0.0175, 0.6);
        let rule = InnerRule::new(&small, &p).unwrap();
        let rule_b = InnerRule::new(&big, &Float::with_val(256, p)).unwrap();
        for (u, _, _) in &rule.nodes {
            for off in [0.0, 1e-15, -3e-12, 1e-9, 2e-7] {
                let xi = (u + off).max(0.0).sqrt();
                let got = rule.b(&small, &xi);
                let exact = rule_b.b(&big, &Float::with_val(256, xi));
                // absolute: the terms of the sum are O(1), b itself may be small
                let err = (got - exact.to_f64()).abs();
                assert!(err < 1e-14, "xi {xi}: {got} vs {exact}");
            }
        }
    }

    #[test]
    fn lambda0_keeps_full_precision_next_to_the_segment() {
        // zeta^2 within 1e-14 .. 1e-4 of every node of the f64 rule (the field near the
        // contact surface), against 256 bits
        let p = 0.3;
        let small = omega_fn(&0.0_f64, -0.0175, 0.6);
        let big = omega_fn(&Float::with_val(256, 0), -0.0175, 0.6);
        let rule = InnerRule::new(&small, &p).unwrap();
        let rule_b = InnerRule::new(&big, &Float::with_val(256, p)).unwrap();
        for (u, _, _) in &rule.nodes {
            for dy in [1e-14, 1e-10, 1e-7, 1e-4] {
                for dx in [0.0, 1e-12] {
                    let z = Cx::new(u + dx, dy).sqrt();
                    let got = rule.lambda0(&small, &z);
                    let zb = Cx::new(Float::with_val(256, z.re), Float::with_val(256, z.im));
                    let exact = rule_b.lambda0(&big, &zb);
                    let err = (got.re - exact.re.to_f64()).hypot(got.im - exact.im.to_f64());
                    assert!(err < 2e-15, "s = {u} + {dx} + i {dy}: error {err:e}");
                }
            }
        }
    }

    #[test]
    fn inner_sums_match_an_independent_quadrature() {
        // S0, b (on the contact and between p and m) and Lambda0 (real s in (m^2, 1) above the
        // rule's worst point, complex s near the segment) from the rule in t = ln sqrt(m^2 - u),
        // against tanh-sinh in u at 256 bits: the benchmark case, close to the Rayleigh speed,
        // strong friction
        use complexfn::quadrature::{tanh_sinh, Point, TsOptions};
        let like = Float::with_val(256, 0);
        for (beta, gamma, p) in [(-0.0175, 0.6, 0.3), (-0.0175, 0.6, 0.49), (-1.0, 3.0, 0.25)] {
            let om = omega_fn(&like, beta, gamma);
            let pb = like.lit(p);
            let rule = InnerRule::new(&om, &pb).unwrap();
            let p2 = pb.clone().sqr();
            let m = om.rayleigh().m().clone();
            let w = |u: &Float| om.omega_rel(&Cx::real(u.clone())).re;
            let quad = |f: &dyn Fn(&Float) -> Cx<Float>| {
                tanh_sinh(
                    &like.zero(),
                    &p2,
                    TsOptions::new(1e-72),
                    |pt: &Point<Float>| f(&pt.v),
                )
                .unwrap()
                .estimate
                .value
            };
            let close = |got: Cx<Float>, exact: Cx<Float>, what: &str| {
                let err = (got - exact.clone()).abs().to_f64();
                assert!(err < 1e-66, "p {p}, gamma {gamma}, {what}: error {err:e}");
            };
            let s0 = quad(&|u: &Float| Cx::real(w(u) / u));
            close(Cx::real(rule.s0()), s0, "S0");
            let probes: [Float; 2] = [pb.clone() * 0.5, (pb.clone() + &m) / 2.0];
            for xi in probes {
                let s = xi.clone().sqr();
                let ws = om.omega(&xi) - om.omega0();
                let b = quad(&|u: &Float| Cx::real((w(u) - &ws) / (u.clone() - &s)));
                close(Cx::real(rule.b(&om, &xi)), b, "b");
            }
            let s_c = m.clone().sqr() + like.lit(2.0 * rule.log_centre).exp();
            let lam = quad(&|u: &Float| Cx::real(w(u) / (u.clone() - &s_c)));
            close(
                Cx::real(rule.lambda0_real_outside(&s_c)),
                lam,
                "Lambda0 real",
            );
            // Int Omega/(u - s) for s in [m^2, 1), without the closed-form logarithm
            let om0 = om.omega0().clone();
            let m2 = m.clone().sqr();
            for s in [s_c.clone(), m2.clone() * 1.001, like.lit(0.999), m2 * 1.5] {
                let exact = quad(&|u: &Float| Cx::real((w(u) + &om0) / (u.clone() - &s)));
                close(
                    Cx::real(rule.omega_cauchy_outside(&s)),
                    exact,
                    "Int Omega/(u - s)",
                );
            }
            for s in [
                Cx::new(p2.clone() * 0.4, like.lit(0.01)),
                Cx::new(-(p2.clone()) * 0.3, like.lit(0.02)),
                Cx::new(m.clone().sqr() * 1.5, like.lit(0.05)),
            ] {
                let lam = quad(&|u: &Float| Cx::real(w(u)) / &(Cx::real(u.clone()) - s.clone()));
                close(rule.lambda0(&om, &s.clone().sqrt()), lam, "Lambda0 complex");
            }
        }
    }

    #[test]
    fn predicted_rule_is_accepted() {
        // the first guess passes the doubling test (no rule twice the size is kept): f64,
        // double-double and MPFR at 133 and 365 bits, slow to close to the Rayleigh speed,
        // weak and strong friction
        fn check<T: CachedRules>(like: &T) {
            for (beta, gamma) in [(-0.0175, 0.6), (-1.0, 3.0), (-0.1, 0.05)] {
                let om = omega_fn(like, beta, gamma);
                let m = om.rayleigh().m().to_f64();
                let m_r = om.rayleigh().m_r().to_f64();
                for frac in [0.02, 0.3, 0.6, 0.9, 0.99] {
                    let p = m_r * frac;
                    let rule = InnerRule::new(&om, &like.lit(p)).unwrap();
                    let n = predicted_nodes(m, p, like.prec());
                    assert_eq!(rule.len(), n, "{} bits, gamma {gamma}, p {p}", like.prec());
                }
            }
        }
        check(&0.0_f64);
        check(&complexfn::Dd::from_f64(0.0));
        check(&Float::with_val(133, 0));
        check(&Float::with_val(365, 0));
    }

    fn rd(a: &Float, b: &Float) -> f64 {
        complexfn::scalar::rel_diff(a, b)
    }
}
