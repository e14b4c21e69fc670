//! The solved case: material and indenter in, quantities computed on demand.
//!
//! A [`Case`] is built for one contact-zone speed p = alpha/c1 at the precision of the scalar
//! type `T`. Building it costs one table of Omega on the nodes of the inner rule (see
//! [`crate::omega`]); the displacement matching (Q, V) is computed on first use and cached;
//! the contact stress, the fundamental function and the admissibility checks are computed
//! only when asked for.
//!
//! Units: c1 = 1 and mu = 1 inside; results are returned dimensionless — speeds over c1,
//! Q over c1^2 cot Theta, stresses over mu cot Theta, displacements over c1 t cot Theta.

use std::sync::OnceLock;

use complexfn::quadrature::{CachedRules, EndExponent};
use complexfn::{Cx, Rayleigh, Real};

use crate::error::{invalid, Result, WedgeError};
use crate::omega::{InnerRule, OmegaFn};
use crate::params::{Coupling, Indenter, Material, Solution};

/// X(v), Omega(v) and cos, sin of pi Omega(v) on the contact (see [`Case::x_on_contact`]).
#[derive(Clone, Debug)]
pub struct ContactFactors<T> {
    /// X = v^(1 - 2 Omega) (p^2 - v^2)^(-1/2 + Omega) e^(b(v)).
    pub x: T,
    /// Omega(v).
    pub omega: T,
    /// cos(pi Omega(v)).
    pub cos: T,
    /// sin(pi Omega(v)).
    pub sin: T,
}

/// The indentation problem for one contact speed, at the precision of `T`.
#[derive(Debug)]
pub struct Case<T> {
    pub(crate) material: Material,
    pub(crate) indenter: Indenter,
    pub(crate) solution: Solution,
    pub(crate) p: T,
    pub(crate) beta: T,
    pub(crate) gamma: T,
    pub(crate) cot_theta: T,
    pub(crate) omega: OmegaFn<T>,
    pub(crate) inner: InnerRule<T>,
    pub(crate) on_boundary: bool,
    /// -1/2 + Omega(p): the exponent of the edge singularity of H (declared to the quadrature).
    pub(crate) edge_exponent: f64,
    /// The same exponent with its gap 1/2 + Omega(p) to full relative accuracy: close to -1
    /// (sharp wedges with coupling) the quadrature sums the part of the integrals next to the
    /// edge in closed form from it.
    pub(crate) edge_end: EndExponent,
    pub(crate) matching: OnceLock<std::result::Result<crate::matching::Matching<T>, WedgeError>>,
    pub(crate) apex: OnceLock<std::result::Result<crate::regime::Apex<T>, WedgeError>>,
}

/// Relative tolerance, in units of the working precision's epsilon, within which
/// gamma = cot Theta is taken as exact (the logarithmic regime boundary).
pub const REGIME_BOUNDARY_ULPS: f64 = 8.0;

impl<T: CachedRules> Case<T> {
    /// The case for contact-zone speed `p` = alpha/c1 (0 < p < m_R), given at the working
    /// precision. `Solution::Genuine` is refused here (it has its own solver).
    pub fn new(material: &Material, indenter: &Indenter, p: T, solution: Solution) -> Result<Self> {
        if solution == Solution::Genuine {
            return Err(WedgeError::Unsupported(
                "solution 'genuine' is solved by the genuine crate (genuine::GenuineCase); \
                 Case builds the paper's construction: use 'paper' or 'as-printed'"
                    .into(),
            ));
        }
        let m = material.m(&p);
        let ray = Rayleigh::new(m)?;
        let m_r = ray.m_r().clone();
        if !(p > 0.0) || !(p < m_r) || !p.is_finite() {
            let c1 = material.c1().value();
            return Err(invalid(
                "alpha",
                format!("{} m/s", p.to_f64() * c1),
                format!("(0, c_R) = (0, {}) m/s", m_r.to_f64() * c1),
            ));
        }
        let cot_theta = indenter.cot_theta(&p);
        if !cot_theta.is_finite() {
            // Theta so small that cot Theta exceeds the working precision's range
            return Err(invalid(
                "theta_deg",
                indenter.theta_deg().text(),
                "(0, 90) degrees with cot Theta within the working precision's range \
                 (in f64, Theta above about 3.2e-307 degrees)",
            ));
        }
        let gamma = indenter.gamma().to_real(&p);
        let beta = match indenter.coupling() {
            Coupling::On => -cot_theta.clone(),
            Coupling::Off => p.zero(),
        };
        // beta + gamma: exactly zero on the regime boundary (gamma = cot Theta within a few
        // ulps of the working precision, or the classical beta = gamma = 0).
        let mut bpg = beta.clone() + &gamma;
        let tol = p.epsilon() * REGIME_BOUNDARY_ULPS * (cot_theta.clone() + &gamma);
        let on_boundary = indenter.coupling() == Coupling::On && bpg.clone().abs() <= tol;
        if on_boundary {
            bpg = p.zero();
        }
        let bg = beta.clone() * &gamma;
        let omega = OmegaFn::new(ray, bpg, bg);
        let inner = InnerRule::new(&omega, &p)?;
        let edge_gap = omega.half_plus_omega(&p);
        let edge_end = EndExponent::from_gap(&edge_gap);
        let edge_exponent = edge_end.alpha();
        Ok(Case {
            material: material.clone(),
            indenter: indenter.clone(),
            solution,
            p,
            beta,
            gamma,
            cot_theta,
            omega,
            inner,
            on_boundary,
            edge_exponent,
            edge_end,
            matching: OnceLock::new(),
            apex: OnceLock::new(),
        })
    }

    /// The case for a contact-zone speed `alpha` in m/s, at the precision of `like` (a
    /// decimal [`crate::Param`] is parsed at that precision: its digits are kept).
    pub fn with_alpha(
        material: &Material,
        indenter: &Indenter,
        alpha: impl Into<crate::params::Param>,
        like: &T,
        solution: Solution,
    ) -> Result<Self> {
        let p = material.p_of_alpha(&alpha.into(), like)?;
        Case::new(material, indenter, p, solution)
    }
}

impl<T: Real> Case<T> {
    /// p = alpha/c1.
    pub fn p(&self) -> &T {
        &self.p
    }
    /// m = c2/c1.
    pub fn m(&self) -> &T {
        self.omega.rayleigh().m()
    }
    /// m_R = c_R/c1.
    pub fn m_r(&self) -> &T {
        self.omega.rayleigh().m_r()
    }
    /// The coupling constant beta (-cot Theta, or 0 when uncoupled).
    pub fn beta(&self) -> &T {
        &self.beta
    }
    /// The friction coefficient gamma.
    pub fn gamma(&self) -> &T {
        &self.gamma
    }
    /// cot Theta.
    pub fn cot_theta(&self) -> &T {
        &self.cot_theta
    }
    /// The solution variant.
    pub fn solution(&self) -> Solution {
        self.solution
    }
    /// The material.
    pub fn material(&self) -> &Material {
        &self.material
    }
    /// The indenter.
    pub fn indenter(&self) -> &Indenter {
        &self.indenter
    }
    /// Omega as a function (eq (31)).
    pub fn omega_fn(&self) -> &OmegaFn<T> {
        &self.omega
    }
    /// The inner rule behind b, S0, Lambda0.
    pub fn inner(&self) -> &InnerRule<T> {
        &self.inner
    }
    /// The exponent -1/2 + Omega(p) of (v^2 - p^2) in H at the contact edge.
    pub fn edge_exponent(&self) -> f64 {
        self.edge_exponent
    }
    /// The edge exponent with its gap 1/2 + Omega(p) (its distance from -1) to full relative
    /// accuracy, as the quadrature takes it.
    pub fn edge_end(&self) -> EndExponent {
        self.edge_end
    }
    /// Whether gamma = cot Theta was detected (coupled case), where Omega = 0 identically.
    pub fn on_regime_boundary(&self) -> bool {
        self.on_boundary
    }
    /// Omega(xi), eq (31), for 0 <= xi < m.
    pub fn omega(&self, xi: &T) -> T {
        self.omega.omega(xi)
    }
    /// Omega0, eq (37).
    pub fn omega0(&self) -> T {
        self.omega.omega0().clone()
    }
    /// b(xi), eq (33), for 0 <= xi < m (continued analytically past p).
    pub fn b(&self, xi: &T) -> T {
        self.inner.b(&self.omega, xi)
    }
    /// S0 = b(0), eq (44).
    pub fn s0(&self) -> T {
        self.inner.s0()
    }
    /// Lambda0(zeta), eq (38), off the segment [-p, p].
    pub fn lambda0(&self, zeta: &Cx<T>) -> Cx<T> {
        self.inner.lambda0(&self.omega, zeta)
    }

    /// The fundamental function H(zeta) of eq (36) off the segment [-p, p]:
    /// zeta^(1 - 2 Omega0) (zeta - p)^a (zeta + p)^a exp(Lambda0(zeta)), a = -1/2 + Omega0,
    /// each power principal, so that H is analytic off [-p, p] (the jumps of the three
    /// powers cancel on (-inf, -p)) and H(v) > 0 for v > p.
    pub fn h(&self, zeta: &Cx<T>) -> Cx<T> {
        let o0 = self.omega0();
        let one = o0.one();
        let e1 = one.clone() - o0.clone() * 2.0;
        let a = o0.clone() - 0.5;
        let zp = zeta.clone().add_re(&(-self.p.clone()));
        let zm = zeta.clone().add_re(&self.p);
        let pow = zeta.clone().powf(&e1) * zp.powf(&a) * zm.powf(&a);
        pow * self.lambda0(zeta).exp()
    }

    /// H(v)/v for real v in (p, 1), where H is real and positive.
    ///
    /// For p < v < m, Lambda0(v) = b(v) + omega(v^2) ln((v^2 - p^2)/v^2) with b and Omega
    /// continued analytically (no near-singular inner integral), so
    /// H(v) = v^(1 - 2 Omega(v)) (v^2 - p^2)^(-1/2 + Omega(v)) e^(b(v)).
    /// For v >= m the integral form of Lambda0 is used. `v_minus_p` is v - p to full
    /// relative accuracy.
    ///
    /// With q = v^2 - p^2, both are evaluated from exp(c)/sqrt(q). For v < m,
    /// c = Omega(v) ln(q/v^2) + b(v): one logarithm, of q/v^2 = 1 - p^2/v^2 in (0, 1), which
    /// keeps its relative accuracy however close v is to p; with Omega = -1/2 + g
    /// (g = 1/2 + Omega to full relative accuracy, [`OmegaFn::omega_and_gap`]) this is
    /// H/v = (v/q) exp(g ln(q/v^2) + b(v)), whose exponent stays small next to the edge when
    /// Omega is close to -1/2 (sharp wedges with coupling), so that H/v keeps its relative
    /// accuracy at distances from the edge far below the f64 range of (v - p)^(-1/2).
    /// For v >= m, c = Omega0 ln(q/v^2) + Lambda0(v) = Int_0^{p^2} Omega(u)/(u - v^2) du, one
    /// sum over the inner rule without a logarithm ([`InnerRule::omega_cauchy_outside`]).
    pub fn h_over_v_outside(&self, v: &T, v_minus_p: &T) -> T {
        let s = v.clone().sqr();
        let vp = v_minus_p.clone() * (v.clone() + &self.p);
        if v < self.m() {
            let log = (vp.clone() / &s).ln();
            let (om, gap) = self.omega.omega_and_gap(v);
            let om_rel = om - self.omega.omega0();
            let b = self.inner.b_with(&self.omega, &s, &om_rel);
            (log * gap + b).exp() * v / vp
        } else {
            self.inner.omega_cauchy_outside(&s).exp() / vp.sqrt()
        }
    }

    /// X(v) = v^(1 - 2 Omega) (p^2 - v^2)^(-1/2 + Omega) e^(b(v)) on the contact 0 < v < p, the
    /// modulus of H^{+-}(v) (corrected eq (32): H^{+-} = -+ i X e^(+- i pi Omega)), together with
    /// Omega(v). `p_minus_v` is p - v to full relative accuracy.
    ///
    /// With Omega = -1/2 + g (g = 1/2 + Omega to full relative accuracy) and
    /// w = p^2 - v^2, X = exp((2 - 2 g) ln v + g ln w + b(v))/w: the exponent stays small next
    /// to the edge when Omega is close to -1/2 (see [`Case::h_over_v_outside`]).
    pub fn x_on_contact(&self, v: &T, p_minus_v: &T) -> ContactFactors<T> {
        let (om, gap, cos, sin) = self.omega.omega_gap_cos_sin(v);
        let s = v.clone().sqr();
        let om_rel = om.clone() - self.omega.omega0();
        let b = self.inner.b_with(&self.omega, &s, &om_rel);
        let pv = p_minus_v.clone() * (v.clone() + &self.p);
        let two = om.lit(2.0);
        let x = (v.clone().ln() * (two - gap.clone() * 2.0) + pv.clone().ln() * gap + b).exp() / pv;
        ContactFactors {
            x,
            omega: om,
            cos,
            sin,
        }
    }

    /// The material's Rayleigh family.
    pub fn rayleigh(&self) -> &Rayleigh<T> {
        self.omega.rayleigh()
    }
}
