//! The genuine solution behind the one interface of solved cases,
//! [`wedge::ContactSolution`]: V, the force, the stress, the apex behaviour (in the paper's
//! normalisation) and the admissibility checks, each with its own error estimate. The
//! quantities of the paper's construction only (Omega0, S0, Q, edge velocities, apex
//! dislocation) keep the trait's default: unavailable, with the reason.

use complexfn::quadrature::CachedRules;
use complexfn::Rayleigh;
use wedge::{
    Admissibility, ApexLeading, ApexRegime, ContactSolution, Indenter, Material, Solution, Solver,
    WithError,
};

use crate::solver::{GenuineCase, SolveOptions};

type WResult<T> = wedge::Result<T>;

impl<T: CachedRules> GenuineCase<T> {
    /// The forward error of `value` from the rounding of p near the Rayleigh speed
    /// ([`wedge::solved::rayleigh_conditioning`]).
    fn rayleigh_error(&self, value: &T) -> f64 {
        let ray = self.basis().rayleigh();
        wedge::solved::rayleigh_conditioning(&GenuineCase::p(self), ray.m_r())
            * value.to_f64().abs()
    }
}

impl<T: CachedRules> ContactSolution<T> for GenuineCase<T> {
    fn solution(&self) -> Solution {
        Solution::Genuine
    }
    fn p(&self) -> T {
        GenuineCase::p(self)
    }
    fn rayleigh(&self) -> &Rayleigh<T> {
        self.basis().rayleigh()
    }
    fn v_hat(&self) -> WResult<WithError<T>> {
        let value = GenuineCase::v_hat(self);
        let error = self.error_estimate() + self.rayleigh_error(&value);
        Ok(WithError {
            value,
            error,
            kind: complexfn::ErrorKind::Fit,
        })
    }
    fn force_hat(&self) -> WResult<WithError<T>> {
        let (value, error) = self.force_hat_with_error();
        let error = error + self.rayleigh_error(&value);
        Ok(WithError {
            value,
            error,
            kind: complexfn::ErrorKind::Fit,
        })
    }
    /// The larger of V's and the force's relative estimates, plus the contour integrals'
    /// error of the solution's scale (the stress is proportional to the coefficients, V is
    /// not). The force, an integral of the stress, stands for the stress's own convergence:
    /// V alone can be optimistic for it (double-double, Theta 30 deg, gamma 0.2,
    /// alpha = 927 m/s: S(0.7 p) off by 1.3 times V's relative estimate).
    fn rel_error(&self) -> WResult<f64> {
        let v = ContactSolution::v_hat(self)?;
        let f = ContactSolution::force_hat(self)?;
        let rel = |q: &WithError<T>| q.error / q.value.to_f64().abs();
        Ok(rel(&v).max(rel(&f)) + self.contour_scale_error())
    }
    /// The stress with the relative estimate of [`ContactSolution::rel_error`] (V and the
    /// stress come from the same basis).
    fn stress_hat(&self, x: &T) -> WResult<WithError<T>> {
        let value = GenuineCase::stress_hat(self, x.clone())?;
        let rel = ContactSolution::rel_error(self)?;
        let error = rel * value.to_f64().abs();
        Ok(WithError {
            value,
            error,
            kind: complexfn::ErrorKind::Fit,
        })
    }
    fn regime(&self) -> ApexRegime {
        self.exponents().kind
    }
    fn apex_leading(&self) -> WResult<ApexLeading<T>> {
        let (ex, value, error) = self.apex_with_error()?;
        let error = error + self.rayleigh_error(&value);
        let exponent = ex.leading().cloned().unwrap_or_else(|| value.zero());
        Ok(ApexLeading {
            regime: ex.kind,
            exponent,
            // a root of the eigen-equation in closed form
            exponent_error: 0.0,
            amplitude: WithError {
                value,
                error,
                kind: complexfn::ErrorKind::Fit,
            },
        })
    }
    /// A (p/x)^lambda, A arccosh(p/x) (the classical case, where the genuine solution is the
    /// paper's and (41) is exact) or the finite limit A.
    fn apex_leading_term(&self, x: &T) -> WResult<T> {
        let lead = ContactSolution::apex_leading(self)?;
        let a = lead.amplitude.value;
        let ratio = GenuineCase::p(self) / x;
        Ok(match lead.regime {
            ApexRegime::Power => a * ratio.powf(&lead.exponent),
            ApexRegime::Logarithmic => a * ratio.acosh(),
            ApexRegime::Finite => a,
        })
    }
    fn admissibility(&self) -> WResult<Admissibility> {
        let (no_interpenetration, min_gap) = self.no_interpenetration()?;
        let (slip_direction_ok, min_slip_rate) = self.slip_check()?;
        Ok(Admissibility {
            contact_compressive: self.contact_compressive()?,
            min_gap: min_gap.to_f64(),
            no_interpenetration,
            slip_direction_ok,
            min_slip_rate,
        })
    }
}

/// The genuine solution as a [`wedge::Solver`]: the solve for a contact speed at any
/// precision, with the options of that precision ([`SolveOptions::for_precision`]) unless
/// given; the inverse solve for an indenter speed is [`wedge::for_speed`] with this solver.
#[derive(Clone, Debug)]
pub struct GenuineSolver<'a> {
    material: &'a Material,
    indenter: &'a Indenter,
    options: Option<SolveOptions>,
}

impl<'a> GenuineSolver<'a> {
    /// The solver with the options of each precision.
    pub fn new(material: &'a Material, indenter: &'a Indenter) -> Self {
        GenuineSolver {
            material,
            indenter,
            options: None,
        }
    }
    /// The solver with fixed options (whatever the precision).
    pub fn with_options(
        material: &'a Material,
        indenter: &'a Indenter,
        opts: SolveOptions,
    ) -> Self {
        GenuineSolver {
            material,
            indenter,
            options: Some(opts),
        }
    }
}

impl Solver for GenuineSolver<'_> {
    type Solved<T: CachedRules> = GenuineCase<T>;
    fn material(&self) -> &Material {
        self.material
    }
    fn indenter(&self) -> &Indenter {
        self.indenter
    }
    fn solve<T: CachedRules>(&self, p: T) -> WResult<GenuineCase<T>> {
        let opts = self
            .options
            .clone()
            .unwrap_or_else(|| SolveOptions::for_precision(p.prec()));
        Ok(GenuineCase::solve(self.material, self.indenter, p, opts)?)
    }
}
