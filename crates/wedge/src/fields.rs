//! The wedge solution as a pair of potentials F, G for the homogeneous-function crate:
//! F(zeta) = -i Q zeta H(zeta) (39) and G(zeta) = sgn(Re zeta) gamma F(zeta) (23), with Q in
//! units of c1^2 cot Theta, so that fields come out over cot Theta.

use complexfn::quadrature::CachedRules;
use complexfn::{Cx, Rayleigh, Real};
use homogeneous::Potentials;

use crate::case::Case;
use crate::error::Result;

/// F and G of a solved case (borrowing it).
#[derive(Debug)]
pub struct WedgePotentials<'a, T> {
    case: &'a Case<T>,
    q_hat: T,
}

impl<T: CachedRules> Case<T> {
    /// The potentials F, G of this case (solves the matching for Q first).
    pub fn potentials(&self) -> Result<WedgePotentials<'_, T>> {
        Ok(WedgePotentials {
            case: self,
            q_hat: self.q_hat()?,
        })
    }
}

impl<T: Real> WedgePotentials<'_, T> {
    /// Q/(c1^2 cot Theta).
    pub fn q_hat(&self) -> &T {
        &self.q_hat
    }
}

impl<T: CachedRules> Potentials<T> for WedgePotentials<'_, T> {
    fn degree(&self) -> u32 {
        1
    }
    fn rayleigh(&self) -> &Rayleigh<T> {
        self.case.rayleigh()
    }
    fn f(&self, zeta: &Cx<T>) -> Cx<T> {
        // -i Q zeta H
        (zeta.clone() * self.case.h(zeta))
            .mul_neg_i()
            .scale(&self.q_hat)
    }
    fn g(&self, zeta: &Cx<T>) -> Cx<T> {
        let f = self.f(zeta).scale(self.case.gamma());
        if zeta.re.is_sign_negative() {
            -f
        } else {
            f
        }
    }
    fn breakpoints(&self) -> Vec<T> {
        vec![self.case.p().clone()]
    }
    /// On the real axis outside [-p, p], H is real, positive and even (the phases of the three
    /// principal powers cancel for xi < -p), so F(xi) = -i Q xi H(|xi|) is odd and
    /// G = sgn(xi) gamma F.
    fn fg_real(&self, xi: &T) -> (Cx<T>, Cx<T>) {
        let a = xi.clone().abs();
        let h = self.case.h_over_v_outside(&a, &(a.clone() - self.case.p())) * &a;
        let f = Cx::imag(-(self.q_hat.clone() * xi * h));
        let g = f.clone().scale(self.case.gamma());
        let g = if xi.is_sign_negative() { -g } else { g };
        (f, g)
    }
}
