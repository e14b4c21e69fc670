//! The apex regime of the paper's solution: finite, logarithmic or a power singularity of
//! order 2 Omega0 (eqs (40)-(44)).
//!
//! The regime is the paper's, decided by the sign of Omega0 = (1/pi) atan(m^2 (beta + gamma)/(1 - beta gamma)),
//! i.e. by gamma against cot Theta:
//! * `Finite` (Omega0 < 0, gamma < cot Theta with coupling): sigma_theta(0) is finite;
//! * `Logarithmic` (Omega0 = 0: gamma = cot Theta with coupling, or beta = gamma = 0):
//!   Omega vanishes identically, b = 0 and (41) is exact:
//!   sigma/(mu cot Theta) = -(Q_hat/p) arccosh(p/x);
//! * `Power` (Omega0 > 0): sigma/(mu cot Theta) ~ -Q_hat e^(S0) cos(pi Omega0)/(2 Omega0 p) (p/x)^(2 Omega0), eq (43).
//!
//! The boundary gamma = cot Theta is decided deliberately: it holds when |gamma - cot Theta|
//! <= 8 eps (gamma + cot Theta) at the working precision ([`crate::case::REGIME_BOUNDARY_ULPS`]),
//! and then beta + gamma is set to exactly zero. (The genuine solution has a different apex
//! exponent; see the errata, section 6b.)

use complexfn::quadrature::{tanh_sinh, CachedRules, Point, TsOptions};

use crate::case::Case;
use crate::error::{from_quad, Result};
use crate::matching::tol_for;

/// The paper's apex regime.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ApexRegime {
    /// Finite contact stress at the apex (Omega0 < 0).
    Finite,
    /// Logarithmic singularity (Omega0 = 0), eq (41).
    Logarithmic,
    /// Power singularity of order 2 Omega0 (Omega0 > 0), eq (43).
    Power,
}

impl ApexRegime {
    /// Name used in outputs: `finite`, `logarithmic`, `power`.
    pub fn name(self) -> &'static str {
        match self {
            ApexRegime::Finite => "finite",
            ApexRegime::Logarithmic => "logarithmic",
            ApexRegime::Power => "power",
        }
    }
}

/// The apex behaviour: regime, exponent and the amplitude of the leading term.
#[derive(Clone, Debug)]
pub struct Apex<T> {
    /// The regime.
    pub regime: ApexRegime,
    /// 2 Omega0 for `Power`, else 0.
    pub exponent: T,
    /// `Finite`: sigma(0)/(mu cot Theta); `Logarithmic`: the coefficient c of
    /// sigma/(mu cot Theta) ~ c ln(2 p/x), i.e. -Q_hat/p; `Power`: the coefficient A of
    /// sigma/(mu cot Theta) ~ A (p/x)^(2 Omega0).
    pub amplitude: T,
}

impl<T: CachedRules> Case<T> {
    /// The paper's apex regime (from the sign of Omega0; see the module docs).
    pub fn regime(&self) -> ApexRegime {
        let o0 = self.omega_fn().omega0();
        if self.omega_fn().is_zero() || *o0 == 0.0 {
            ApexRegime::Logarithmic
        } else if *o0 < 0.0 {
            ApexRegime::Finite
        } else {
            ApexRegime::Power
        }
    }

    /// Regime, exponent and amplitude of the leading apex term.
    pub fn apex(&self) -> Result<Apex<T>> {
        let q = self.q_hat()?;
        let p = self.p().clone();
        let o0 = self.omega0();
        let regime = self.regime();
        let (exponent, amplitude) = match regime {
            ApexRegime::Logarithmic => (p.zero(), -(q / &p)),
            ApexRegime::Power => {
                let a =
                    -(q * self.s0().exp() * (o0.clone() * p.pi()).cos()) / (o0.clone() * 2.0 * &p);
                (o0 * 2.0, a)
            }
            ApexRegime::Finite => (p.zero(), self.stress_at_apex()?),
        };
        Ok(Apex {
            regime,
            exponent,
            amplitude,
        })
    }

    /// The leading apex term of sigma_theta/(mu cot Theta) at x = r/(c1 t): (41), (43), or the
    /// finite apex value.
    pub fn apex_leading_term(&self, x: &T) -> Result<T> {
        let a = self.apex()?;
        let p = self.p().clone();
        Ok(match a.regime {
            ApexRegime::Logarithmic => a.amplitude * (p / x).acosh(),
            ApexRegime::Power => a.amplitude * (p / x).powf(&a.exponent),
            ApexRegime::Finite => a.amplitude,
        })
    }

    /// sigma_theta(0)/(mu cot Theta) in the finite regime. The apex part of (40) is
    /// integrated with its leading term c0 v^(-1 - 2 Omega0) subtracted and added back in
    /// closed form (the integrand is only weakly integrable when Omega0 is close to 0).
    fn stress_at_apex(&self) -> Result<T> {
        let p = self.p().clone();
        let o0 = self.omega0();
        let q = self.q_hat()?;
        let tol = tol_for(&p);
        let quarter = p.clone() / 4.0;
        let one = p.one();
        // c0 = e^(S0) cos(pi Omega0) p^(-1 + 2 Omega0)
        let c0 = self.s0().exp()
            * (o0.clone() * p.pi()).cos()
            * p.clone().powf(&(o0.clone() * 2.0 - 1.0));
        let expo = -(one.clone() + o0.clone() * 2.0);
        let g = |v: &T, pv: &T| -> T {
            let (x, om) = self.x_on_contact(v, pv);
            x * (om * v.pi()).cos() / v.clone().sqr()
        };
        let lower = tanh_sinh(&p.zero(), &quarter, TsOptions::new(tol), |pt: &Point<T>| {
            let pv = p.clone() - &pt.v;
            g(&pt.v, &pv) - c0.clone() * pt.v.clone().powf(&expo)
        })
        .map_err(|e| from_quad("apex stress", e))?;
        let upper = tanh_sinh(&quarter, &p, TsOptions::new(tol), |pt: &Point<T>| {
            g(&pt.v, &pt.to_b)
        })
        .map_err(|e| from_quad("apex stress", e))?;
        // Int_0^{p/4} c0 v^(-1 - 2 Omega0) dv = c0 (p/4)^(-2 Omega0)/(-2 Omega0)
        let lead = c0 * quarter.powf(&(o0.clone() * -2.0)) / (o0 * -2.0);
        Ok(-(q * (lower.value + upper.value + lead)))
    }
}
