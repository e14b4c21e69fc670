//! One interface to a solved case, whichever construction solved it: the paper's
//! ([`Case`], eqs (22)-(57)) or the genuine solution without the apex dislocation (the
//! `genuine` crate). Reports, figures and the inverse solve ask a [`ContactSolution`] for
//! its quantities and never dispatch on the variant.
//!
//! Conventions shared by every implementation (all dimensionless):
//! * x = r/(c1 t), the contact is 0 < x < p with p = alpha/c1;
//! * V/(c1 cot Theta), the force P/(alpha t mu cot Theta), the contact stress
//!   sigma_theta/(mu cot Theta) at x;
//! * the apex behaviour in the paper's normalisation (eqs (41)-(44)): for a power
//!   singularity sigma/(mu cot Theta) ~ A (p/x)^lambda, for a logarithmic apex
//!   sigma/(mu cot Theta) ~ A ln(2 p/x) + O(1), for a finite apex A = sigma(0+).
//!
//! Every value carries its own absolute error estimate ([`WithError`]), never optimistic.

use complexfn::quadrature::CachedRules;
use complexfn::{Rayleigh, Real};

use crate::admissibility::Admissibility;
use crate::case::Case;
use crate::error::{Result, WedgeError};
use crate::params::{Indenter, Material, Param, Solution};
use crate::regime::ApexRegime;
use crate::stress::WithError;

/// The leading apex behaviour of the contact stress, in the normalisation of the module
/// docs.
#[derive(Clone, Debug)]
pub struct ApexLeading<T> {
    /// Finite, logarithmic or power.
    pub regime: ApexRegime,
    /// lambda of sigma ~ (p/x)^lambda for a power singularity, 0 otherwise (a closed form or
    /// a root of the apex eigen-equation).
    pub exponent: T,
    /// The absolute error estimate of the exponent (the forward error of its inputs' rounding).
    pub exponent_error: f64,
    /// The amplitude A with its absolute error estimate.
    pub amplitude: WithError<T>,
}

/// The largest relative error estimate of V that a solved case reports. Beyond it V's
/// leading digits, even its sign, are not determined at the working precision (for a sharp
/// wedge with coupling the two terms of V in eq (53), each of order cot Theta, cancel: their
/// rounding is amplified about cot Theta times, `docs/errata.md` section 11), and the case is
/// refused: [`WedgeError::Undetermined`], or for the paper's construction of a sharp wedge a
/// [`WedgeError::InvalidParameter`] naming theta_deg and the angles the precision resolves.
pub const MAX_REL_ERROR: f64 = 1e-2;

/// The reason given for a quantity that only the paper's construction defines.
pub const PAPER_ONLY: &str =
    "defined by the paper's construction only (solution paper or as-printed)";

fn paper_only<T>() -> Result<T> {
    Err(WedgeError::Unsupported(PAPER_ONLY.into()))
}

/// A solved wedge-indentation case at the working precision `T` (f64 or `rug::Float`).
///
/// The quantities of the paper's construction that the genuine solution does not have
/// (Omega0, S0, Q, the edge velocities of section 5 of `docs/errata.md`, the apex
/// dislocation) return [`WedgeError::Unsupported`] with [`PAPER_ONLY`] by default.
pub trait ContactSolution<T: CachedRules>: Send + Sync {
    /// The solution variant.
    fn solution(&self) -> Solution;
    /// p = alpha/c1.
    fn p(&self) -> T;
    /// The material's Rayleigh function at the working precision (m = c2/c1, m_R = c_R/c1).
    fn rayleigh(&self) -> &Rayleigh<T>;
    /// V/(c1 cot Theta), eq (53a) for the paper's construction.
    fn v_hat(&self) -> Result<WithError<T>>;
    /// The normal force P/(alpha t mu cot Theta), eq (47).
    fn force_hat(&self) -> Result<WithError<T>>;
    /// The contact stress sigma_theta/(mu cot Theta) at x = r/(c1 t) in (0, p], eq (40).
    fn stress_hat(&self, x: &T) -> Result<WithError<T>>;
    /// The apex regime (decided without computing the apex amplitude).
    fn regime(&self) -> ApexRegime;
    /// The leading apex behaviour (regime, exponent, amplitude), eqs (41)-(44).
    fn apex_leading(&self) -> Result<ApexLeading<T>>;
    /// The apex expansion of sigma_theta/(mu cot Theta) at x (for plotting against the
    /// stress near the apex).
    fn apex_leading_term(&self, x: &T) -> Result<T>;
    /// The admissibility checks: compressive contact, no interpenetration outside it, slip
    /// direction (8).
    fn admissibility(&self) -> Result<Admissibility>;
    /// The relative error estimate of V, the solve's summary accuracy.
    fn rel_error(&self) -> Result<f64> {
        let v = self.v_hat()?;
        Ok(v.error / v.value.to_f64().abs())
    }
    /// Omega0 of eq (31).
    fn omega0(&self) -> Result<WithError<T>> {
        paper_only()
    }
    /// S0 of eq (44).
    fn s0(&self) -> Result<WithError<T>> {
        paper_only()
    }
    /// Q/(c1^2 cot Theta), eq (53b).
    fn q_hat(&self) -> Result<WithError<T>> {
        paper_only()
    }
    /// du_r/dt at the contact edge over V (`docs/errata.md`, section 5).
    fn edge_slip_velocity_over_speed(&self) -> Result<WithError<T>> {
        paper_only()
    }
    /// The rate of u_r following the moving edge over V (`docs/errata.md`, section 5).
    fn edge_following_rate_over_speed(&self) -> Result<WithError<T>> {
        paper_only()
    }
    /// u_r(0+, t)/(V t), the apex dislocation of the construction (`docs/errata.md`,
    /// section 6).
    fn apex_u_r_over_speed_t(&self) -> Result<WithError<T>> {
        paper_only()
    }
}

/// `value` with the relative error `rel` of the matching (absolute: rel |value|).
fn with_rel<T: Real>(value: T, rel: f64) -> WithError<T> {
    let error = rel * value.to_f64().abs();
    WithError {
        value,
        error,
        kind: complexfn::ErrorKind::Propagated,
    }
}

/// The relative forward error that the rounding of p = alpha/c1 (and of m_R) to the working
/// precision causes in a quantity that grows like a power (at most the first) of
/// 1/(m_R - p) near the Rayleigh speed: 2 u p/(m_R - p), u the unit round-off. Negligible
/// except within a few thousand ulps of m_R, where it dominates (`docs/errata.md`,
/// section 10).
pub fn rayleigh_conditioning<T: Real>(p: &T, m_r: &T) -> f64 {
    let u = p.epsilon().to_f64();
    let gap = (m_r.clone() - p).to_f64();
    if gap > 0.0 {
        2.0 * u * p.to_f64() / gap
    } else {
        f64::INFINITY
    }
}

impl<T: CachedRules> Case<T> {
    /// The absolute forward error of Omega0 from the rounding of beta + gamma, which cancels
    /// near the regime boundary gamma = cot Theta: beta + gamma is uncertain by 4 u (|beta| +
    /// |gamma|), or by the snapping tolerance when the boundary is taken as exact
    /// ([`crate::case::REGIME_BOUNDARY_ULPS`]), and dOmega0/d(beta + gamma) =
    /// m^2/((1 - beta gamma) pi (1 + x^2)), x = m^2 (beta + gamma)/(1 - beta gamma)
    /// (`docs/errata.md`, section 10).
    fn omega0_conditioning(&self) -> f64 {
        let d_bpg = self.bpg_rounding();
        let (b, g) = (self.beta().to_f64(), self.gamma().to_f64());
        let m2 = self.rayleigh().m().to_f64().powi(2);
        let den = 1.0 - b * g;
        let x = m2 * (b + g) / den;
        m2 / (den.abs() * std::f64::consts::PI * (1.0 + x * x)) * d_bpg
    }

    /// The absolute rounding error of beta + gamma (see [`Self::omega0_conditioning`]).
    fn bpg_rounding(&self) -> f64 {
        let u = self.p().epsilon().to_f64();
        let (b, g) = (self.beta().to_f64(), self.gamma().to_f64());
        let size = b.abs() + g.abs();
        if self.on_regime_boundary() {
            crate::case::REGIME_BOUNDARY_ULPS * u * size.max(self.cot_theta().to_f64() + g)
        } else {
            4.0 * u * size
        }
    }

    /// The relative error of a quantity that scales like 1/Omega0 (the apex amplitude near
    /// the regime boundary): the conditioning of Omega0 over |Omega0| (0 when Omega0 = 0).
    fn inverse_omega0_conditioning(&self) -> f64 {
        let o0 = Case::omega0(self).to_f64().abs();
        if o0 > 0.0 {
            self.omega0_conditioning() / o0
        } else {
            0.0
        }
    }

    /// The absolute forward error of S0 from the rounding of beta + gamma: S0 integrates
    /// Omega - Omega0, which for small beta + gamma is proportional to it, so S0 carries
    /// the relative error of beta + gamma; at least the error of Omega0; both times 16 (the
    /// sensitivity of Omega grows toward the Rayleigh speed).
    fn s0_conditioning(&self) -> f64 {
        let bpg = (self.beta().clone() + self.gamma()).to_f64().abs();
        let relative = if bpg > 0.0 {
            Case::s0(self).to_f64().abs() * self.bpg_rounding() / bpg
        } else {
            0.0
        };
        16.0 * self.omega0_conditioning().max(relative)
    }

    /// `value` with the matching's relative error and the Rayleigh conditioning.
    fn estimated(&self, value: T) -> Result<WithError<T>> {
        let rel = self.matching()?.rel_error + rayleigh_conditioning(self.p(), self.m_r());
        Ok(with_rel(value, rel))
    }
}

impl<T: CachedRules> ContactSolution<T> for Case<T> {
    fn solution(&self) -> Solution {
        Case::solution(self)
    }
    fn p(&self) -> T {
        Case::p(self).clone()
    }
    fn rayleigh(&self) -> &Rayleigh<T> {
        Case::rayleigh(self)
    }
    fn v_hat(&self) -> Result<WithError<T>> {
        self.estimated(self.matching()?.v_hat.clone())
    }
    fn force_hat(&self) -> Result<WithError<T>> {
        self.estimated(Case::force_hat(self)?)
    }
    fn stress_hat(&self, x: &T) -> Result<WithError<T>> {
        Case::stress_hat(self, x)
    }
    fn regime(&self) -> ApexRegime {
        Case::regime(self)
    }
    fn apex_leading(&self) -> Result<ApexLeading<T>> {
        let (regime, exponent, amplitude) = Case::apex_leading(self)?;
        // the amplitude scales like 1/Omega0 near the regime boundary; S0 enters through e^S0
        let mut a = self.estimated(amplitude)?;
        let rel = self.inverse_omega0_conditioning() + self.s0_conditioning();
        a.error += 2.0 * rel * a.value.to_f64().abs();
        if regime == ApexRegime::Finite {
            // the finite amplitude is the apex constant, a sum of quadratures
            a.error += Case::apex(self)?.constant_error;
        }
        Ok(ApexLeading {
            regime,
            exponent,
            exponent_error: 2.0 * self.omega0_conditioning(),
            amplitude: a,
        })
    }
    fn apex_leading_term(&self, x: &T) -> Result<T> {
        Case::apex_leading_term(self, x)
    }
    fn admissibility(&self) -> Result<Admissibility> {
        Case::admissibility(self)
    }
    // Omega0 is a closed form and S0 a converged Gauss-Legendre sum: both are stated with the
    // matching's relative accuracy, which bounds their own, plus the conditioning of
    // beta + gamma near the regime boundary
    fn omega0(&self) -> Result<WithError<T>> {
        let mut w = self.estimated(Case::omega0(self))?;
        w.error += self.omega0_conditioning();
        Ok(w)
    }
    fn s0(&self) -> Result<WithError<T>> {
        let mut w = self.estimated(Case::s0(self))?;
        w.error += self.inner().error() + self.s0_conditioning();
        Ok(w)
    }
    fn q_hat(&self) -> Result<WithError<T>> {
        self.estimated(self.matching()?.q_hat.clone())
    }
    // the edge velocities are (Q/V) times sums of integrals that may cancel
    fn edge_slip_velocity_over_speed(&self) -> Result<WithError<T>> {
        let mut w = self.estimated(Case::edge_slip_velocity_over_speed(self)?)?;
        w.error += self.combination_error(&[(4, 1.0), (5, 1.0)])?;
        Ok(w)
    }
    fn edge_following_rate_over_speed(&self) -> Result<WithError<T>> {
        let mut w = self.estimated(Case::edge_following_rate_over_speed(self)?)?;
        let p = self.p().to_f64();
        w.error += self.combination_error(&[(4, 1.0), (5, 1.0), (6, p), (7, p)])?;
        Ok(w)
    }
    fn apex_u_r_over_speed_t(&self) -> Result<WithError<T>> {
        let a = Case::apex_u_r_over_speed_t(self)?;
        let own = self.estimated(a.value.clone())?.error;
        let error = a.error.max(own);
        Ok(WithError {
            value: a.value,
            error,
            kind: complexfn::ErrorKind::Propagated,
        })
    }
}

impl<T: CachedRules, S: ContactSolution<T> + ?Sized> ContactSolution<T> for Box<S> {
    fn solution(&self) -> Solution {
        (**self).solution()
    }
    fn p(&self) -> T {
        (**self).p()
    }
    fn rayleigh(&self) -> &Rayleigh<T> {
        (**self).rayleigh()
    }
    fn v_hat(&self) -> Result<WithError<T>> {
        (**self).v_hat()
    }
    fn force_hat(&self) -> Result<WithError<T>> {
        (**self).force_hat()
    }
    fn stress_hat(&self, x: &T) -> Result<WithError<T>> {
        (**self).stress_hat(x)
    }
    fn regime(&self) -> ApexRegime {
        (**self).regime()
    }
    fn apex_leading(&self) -> Result<ApexLeading<T>> {
        (**self).apex_leading()
    }
    fn apex_leading_term(&self, x: &T) -> Result<T> {
        (**self).apex_leading_term(x)
    }
    fn admissibility(&self) -> Result<Admissibility> {
        (**self).admissibility()
    }
    fn rel_error(&self) -> Result<f64> {
        (**self).rel_error()
    }
    fn omega0(&self) -> Result<WithError<T>> {
        (**self).omega0()
    }
    fn s0(&self) -> Result<WithError<T>> {
        (**self).s0()
    }
    fn q_hat(&self) -> Result<WithError<T>> {
        (**self).q_hat()
    }
    fn edge_slip_velocity_over_speed(&self) -> Result<WithError<T>> {
        (**self).edge_slip_velocity_over_speed()
    }
    fn edge_following_rate_over_speed(&self) -> Result<WithError<T>> {
        (**self).edge_following_rate_over_speed()
    }
    fn apex_u_r_over_speed_t(&self) -> Result<WithError<T>> {
        (**self).apex_u_r_over_speed_t()
    }
}

/// Solves one solution variant for a material and an indenter, at any precision: the one
/// constructor behind the contact-speed inputs (alpha given, [`Solver::solve_alpha`]; V given,
/// [`crate::inverse::for_speed`]).
pub trait Solver: Sync {
    /// The solved case at precision `T`.
    type Solved<T: CachedRules>: ContactSolution<T>;
    /// The material.
    fn material(&self) -> &Material;
    /// The indenter.
    fn indenter(&self) -> &Indenter;
    /// The case for contact speed p = alpha/c1 in (0, m_R), at the precision of `p`.
    fn solve<T: CachedRules>(&self, p: T) -> Result<Self::Solved<T>>;
    /// The case for a contact-zone speed alpha in m/s (decimal text parsed at the precision
    /// of `like`; the range 0 < alpha < c_R is checked by [`Material::p_of_alpha`]).
    fn solve_alpha<T: CachedRules>(&self, alpha: &Param, like: &T) -> Result<Self::Solved<T>> {
        self.solve(self.material().p_of_alpha(alpha, like)?)
    }
}

/// The paper's construction ([`Case`], variant `paper` or `as-printed`) as a [`Solver`].
#[derive(Clone, Debug)]
pub struct PaperSolver<'a> {
    material: &'a Material,
    indenter: &'a Indenter,
    solution: Solution,
}

impl<'a> PaperSolver<'a> {
    /// The solver of `solution` (`paper` or `as-printed`; `genuine` is refused by
    /// [`Case::new`] when solving).
    pub fn new(material: &'a Material, indenter: &'a Indenter, solution: Solution) -> Self {
        PaperSolver {
            material,
            indenter,
            solution,
        }
    }
}

impl Solver for PaperSolver<'_> {
    type Solved<T: CachedRules> = Case<T>;
    fn material(&self) -> &Material {
        self.material
    }
    fn indenter(&self) -> &Indenter {
        self.indenter
    }
    fn solve<T: CachedRules>(&self, p: T) -> Result<Case<T>> {
        Case::new(self.material, self.indenter, p, self.solution)
    }
}
