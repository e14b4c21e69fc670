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
//! exponent; see `docs/errata.md`, section 6b.)

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
    /// Two-term apex expansion sigma/(mu cot Theta) ~ `constant` + `coefficient` (p/x)^(2 Omega0)
    /// for Omega0 != 0 (for Omega0 < 0 the second term vanishes at the apex and `constant` is
    /// sigma(0)); for Omega0 = 0, `coefficient` multiplies arccosh(p/x) and `constant` is 0.
    pub constant: T,
    /// See `constant`.
    pub coefficient: T,
    /// Estimated absolute error of `constant` from its quadratures and the round-off of the
    /// sum that forms it (0 where it is exact: Omega0 = 0); the matching's relative error
    /// comes on top.
    pub constant_error: f64,
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

    /// Regime, exponent and amplitude of the leading apex term, and the two-term expansion
    /// (computed once per case, then cached: the finite-regime constant is a quadrature).
    pub fn apex(&self) -> Result<Apex<T>> {
        self.apex.get_or_init(|| self.compute_apex()).clone()
    }

    /// The leading apex term alone, (regime, exponent, amplitude): in the power and the
    /// logarithmic regimes in closed form (eq (43), (41)), without the finite-regime constant
    /// (a quadrature) that [`Case::apex`] also computes; in the finite regime the constant is
    /// the amplitude.
    pub fn apex_leading(&self) -> Result<(ApexRegime, T, T)> {
        let regime = self.regime();
        if let Some(Ok(a)) = self.apex.get() {
            return Ok((a.regime, a.exponent.clone(), a.amplitude.clone()));
        }
        let p = self.p().clone();
        match regime {
            ApexRegime::Logarithmic => Ok((regime, p.zero(), -(self.q_hat()? / &p))),
            ApexRegime::Power => Ok((regime, self.omega0() * 2.0, self.power_coefficient()?)),
            ApexRegime::Finite => {
                let a = self.apex()?;
                Ok((a.regime, a.exponent, a.amplitude))
            }
        }
    }

    /// A = -Q e^(S0) cos(pi Omega0)/(2 Omega0 p), eq (43): the coefficient of the power term
    /// (p/x)^(2 Omega0) of the apex expansion.
    fn power_coefficient(&self) -> Result<T> {
        let q = self.q_hat()?;
        Ok(-(q * self.s0().exp() * self.omega_fn().omega0_cos_sin().0)
            / (self.omega0() * 2.0 * self.p()))
    }

    fn compute_apex(&self) -> Result<Apex<T>> {
        let q = self.q_hat()?;
        let p = self.p().clone();
        let o0 = self.omega0();
        let regime = self.regime();
        if regime == ApexRegime::Logarithmic {
            let c = -(q / &p);
            return Ok(Apex {
                regime,
                exponent: p.zero(),
                amplitude: c.clone(),
                constant: p.zero(),
                coefficient: c,
                constant_error: 0.0,
            });
        }
        let a = self.power_coefficient()?;
        let (c, constant_error) = self.apex_constant()?;
        let (exponent, amplitude) = match regime {
            ApexRegime::Power => (o0 * 2.0, a.clone()),
            _ => (p.zero(), c.clone()),
        };
        Ok(Apex {
            regime,
            exponent,
            amplitude,
            constant: c,
            coefficient: a,
            constant_error,
        })
    }

    /// The apex expansion of sigma_theta/(mu cot Theta) at x = r/(c1 t): (41) (exact when
    /// Omega = 0) or C + A (p/x)^(2 Omega0) with (43)'s A and the constant C (for Omega0 < 0,
    /// C = sigma(0) and the power term is the approach to it).
    pub fn apex_leading_term(&self, x: &T) -> Result<T> {
        let a = self.apex()?;
        let p = self.p().clone();
        Ok(match a.regime {
            ApexRegime::Logarithmic => a.coefficient * (p / x).acosh(),
            _ => a.constant + a.coefficient * (p / x).powf(&(self.omega0() * 2.0)),
        })
    }

    /// The constant C of the apex expansion sigma ~ C + A (p/x)^(2 Omega0) (Omega0 != 0):
    /// C = -Q [Int_0^p (g - c0 v^(-1 - 2 Omega0)) dv - c0 p^(-2 Omega0)/(2 Omega0)],
    /// c0 = e^(S0) cos(pi Omega0) p^(-1 + 2 Omega0); the apex part is integrated with the
    /// leading term subtracted (the integrand is only weakly integrable for Omega0 near 0, and
    /// not integrable for Omega0 > 0). For Omega0 < 0, C = sigma(0).
    fn apex_constant(&self) -> Result<(T, f64)> {
        let p = self.p().clone();
        let o0 = self.omega0();
        let q = self.q_hat()?;
        let tol = tol_for(&p);
        let quarter = p.clone() / 4.0;
        let one = p.one();
        // c0 = e^(S0) cos(pi Omega0) p^(-1 + 2 Omega0)
        let c0 = self.s0().exp()
            * self.omega_fn().omega0_cos_sin().0
            * p.clone().powf(&(o0.clone() * 2.0 - 1.0));
        let expo = -(one.clone() + o0.clone() * 2.0);
        let g = |v: &T, pv: &T| -> T {
            let f = self.x_on_contact(v, pv);
            f.x * f.cos / v.clone().sqr()
        };
        let lower = tanh_sinh(&p.zero(), &quarter, TsOptions::new(tol), |pt: &Point<T>| {
            let pv = p.clone() - &pt.v;
            g(&pt.v, &pv) - c0.clone() * pt.v.clone().powf(&expo)
        })
        .map_err(|e| from_quad("apex stress", e))?;
        let upper = tanh_sinh(
            &quarter,
            &p,
            TsOptions::new(tol).right_end(self.edge_end()),
            |pt: &Point<T>| g(&pt.v, &pt.to_b),
        )
        .map_err(|e| from_quad("apex stress", e))?;
        // Int_0^p (g - c0 v^e) = lower + upper - c0 Int_{p/4}^p v^e, which with the
        // -c0 p^(-2 Omega0)/(2 Omega0) of C leaves -c0 (p/4)^(-2 Omega0)/(2 Omega0):
        let lead = c0 * quarter.powf(&(o0.clone() * -2.0)) / (o0 * -2.0);
        // the three parts may cancel: their quadrature errors (with the margin of 4 the
        // matching uses) and 16 eps of their magnitudes
        let size =
            (lower.value.clone().abs() + upper.value.clone().abs() + lead.clone().abs()).to_f64();
        let q_abs = q.to_f64().abs();
        let error =
            q_abs * (4.0 * (lower.error + upper.error) + 16.0 * p.epsilon().to_f64() * size);
        Ok((
            -(q * (lower.estimate.value + upper.estimate.value + lead)),
            error,
        ))
    }
}
