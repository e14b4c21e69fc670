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
//! With omega(u) = Omega(sqrt u) - Omega0 (errata, section 9), eq (38) becomes
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
//! point u = m^2 of |p2|), so one Gauss-Legendre rule in u, with omega tabulated on its nodes
//! once per case ([`InnerRule`]), serves every evaluation of b, S0 and Lambda0.
//! Near the segment, Lambda0 subtracts omega at zeta^2 (continued analytically) and adds
//! omega(zeta^2) ln((p^2 - zeta^2)/(-zeta^2)) in closed form, so its boundary values are
//!
//! ```text
//!   Lambda0^{+-}(xi) = b(xi) + omega(xi^2) ln((p^2 - xi^2)/xi^2) +- i pi omega(xi^2),  0 < xi < p.
//! ```

use complexfn::quadrature::{gauss_legendre_rule, CachedRules};
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
        let inv_m2 = self.ray.m2().clone().recip();
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

/// Omega - Omega0 tabulated on a Gauss-Legendre rule in u over [0, p^2]: the one table behind
/// b, S0 and Lambda0.
#[derive(Clone, Debug)]
pub struct InnerRule<T> {
    p2: T,
    /// (u_j, w_j, omega(u_j)) with omega = Omega - Omega0.
    nodes: Vec<(T, T, T)>,
    /// |S0(n) - S0(n/2)|, the convergence estimate of the rule (absolute).
    error: f64,
}

impl<T: CachedRules> InnerRule<T> {
    /// Build the rule for contact speed p, doubling the number of nodes until S0 and b at
    /// two interior points agree between n and 2n to the working precision.
    pub fn new(omega: &OmegaFn<T>, p: &T) -> Result<Self> {
        let prec = p.prec();
        let p2 = p.clone().sqr();
        let mut n = ((f64::from(prec) * 0.45) as usize).max(24);
        let mut prev: Option<Self> = None;
        let mut last_d: Option<f64> = None;
        let eps = p.epsilon().to_f64().max(1e-300);
        for _ in 0..6 {
            let mut rule = Self::with_nodes(omega, &p2, n)?;
            if omega.is_zero() {
                // Omega = 0: b, S0 and Lambda0 vanish identically, nothing to converge.
                rule.error = 0.0;
                return Ok(rule);
            }
            if let Some(pr) = &prev {
                let mut d = 0.0_f64;
                let mut scale = 1e-300_f64;
                let probes = [p.zero(), p.clone() * 0.5, p.clone() * 0.97];
                for xi in &probes {
                    let a = rule.b(omega, xi);
                    let b = pr.b(omega, xi);
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
                    return Ok(r);
                }
            }
            prev = Some(rule);
            n *= 2;
        }
        Err(WedgeError::NoConvergence {
            what: "Gauss-Legendre rule for Lambda0".into(),
            reached: prev.map(|r| r.error).unwrap_or(f64::INFINITY),
            asked: eps,
        })
    }

    fn with_nodes(omega: &OmegaFn<T>, p2: &T, n: usize) -> Result<Self> {
        let rule = gauss_legendre_rule::<T>(n, p2.prec())?;
        let half = p2.clone() / 2.0;
        let nodes = rule
            .iter()
            .map(|(x, w)| {
                let u = half.clone() * (x.clone() + 1.0);
                let om = omega.omega_rel(&Cx::real(u.clone())).re;
                (u, w.clone() * &half, om)
            })
            .collect();
        Ok(InnerRule {
            p2: p2.clone(),
            nodes,
            error: f64::INFINITY,
        })
    }
}

impl<T: Real> InnerRule<T> {
    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }
    /// Whether the rule is empty (never, once built).
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
        self.b_with(&s, &om_s)
    }

    /// b at s = xi^2 given omega(s) = Omega(xi) - Omega0 (saves an evaluation of Omega).
    pub fn b_with(&self, s: &T, om_s: &T) -> T {
        let mut acc = s.zero();
        for (u, w, om) in &self.nodes {
            let d = u.clone() - s;
            if d == 0.0 {
                continue;
            }
            acc += (om.clone() - om_s) * w / d;
        }
        acc
    }

    /// S0 = b(0), eq (44).
    pub fn s0(&self) -> T {
        let mut acc = self.p2.zero();
        for (u, w, om) in &self.nodes {
            acc += om.clone() * w / u;
        }
        acc
    }

    /// Lambda0 at a real s = v^2 > p^2 (no subtraction; used for v >= m).
    pub fn lambda0_real_outside(&self, s: &T) -> T {
        let mut acc = s.zero();
        for (u, w, om) in &self.nodes {
            acc += om.clone() * w / (u.clone() - s);
        }
        acc
    }

    /// Lambda0(zeta) of eq (38) off the segment [-p, p] of the real axis.
    pub fn lambda0(&self, omega: &OmegaFn<T>, zeta: &Cx<T>) -> Cx<T> {
        if omega.is_zero() {
            return Cx::real(zeta.re.zero());
        }
        let s = zeta.clone() * zeta;
        // Semi-major axis (in units of p^2/2) of the ellipse with foci 0, p^2 through s.
        let d0 = s.abs();
        let d1 = s.clone().add_re(&(-self.p2.clone())).abs();
        let a = (d0 + d1) / &self.p2;
        let m2 = omega.rayleigh().m2().clone();
        let limit = (m2 * 2.0 / &self.p2 - 1.01).min(s.re.lit(1.25));
        if a < limit {
            let om_s = omega.omega_rel(&s);
            let mut acc = Cx::real(s.re.zero());
            for (u, w, om) in &self.nodes {
                let num = (-om_s.clone()).add_re(om).scale(w);
                let den = (-s.clone()).add_re(u);
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

    fn rd(a: &Float, b: &Float) -> f64 {
        complexfn::scalar::rel_diff(a, b)
    }
}
