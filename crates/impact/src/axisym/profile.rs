//! The axisymmetric striker's profile z = f(r): f(0) = 0, increasing, convex, in units of the
//! length scale R (the sphere's radius; a length the user picks for the cone and the punch).

use crate::error::{invalid, Result};

/// An axisymmetric rigid striker's profile (dimensionless: r/R, f/R).
#[derive(Clone, Debug, PartialEq)]
pub enum AxiProfile {
    /// A sphere of radius `radius`: f = radius - sqrt(radius^2 - r^2), r < radius.
    Sphere {
        /// Radius over R (1 when R is the radius).
        radius: f64,
    },
    /// Its paraboloid f = r^2/(2 radius) (Hertz's approximation of the sphere).
    Paraboloid {
        /// Radius of curvature at the apex over R.
        radius: f64,
    },
    /// A cone f = r cot theta, theta the half-angle at the apex.
    Cone {
        /// Half-angle in degrees, (0, 90).
        theta_deg: f64,
    },
    /// A flat cylindrical punch of radius `radius`: f = 0 on r <= radius, a wall beyond.
    Flat {
        /// Radius over R.
        radius: f64,
    },
}

impl AxiProfile {
    /// A short label, e.g. `sphere:R=1`.
    pub fn label(&self) -> String {
        match self {
            AxiProfile::Sphere { radius } => format!("sphere:R={radius}"),
            AxiProfile::Paraboloid { radius } => format!("paraboloid:R={radius}"),
            AxiProfile::Cone { theta_deg } => format!("cone:theta_deg={theta_deg}"),
            AxiProfile::Flat { radius } => format!("flat:a={radius}"),
        }
    }

    /// Checks the parameter.
    pub fn validate(&self) -> Result<()> {
        match *self {
            AxiProfile::Sphere { radius } | AxiProfile::Paraboloid { radius } => {
                if !(radius.is_finite() && radius > 0.0) {
                    return Err(invalid("profile radius R", radius, "(0, inf)"));
                }
            }
            AxiProfile::Cone { theta_deg } => {
                if !(theta_deg.is_finite() && theta_deg > 0.0 && theta_deg < 90.0) {
                    return Err(invalid("cone half-angle theta_deg", theta_deg, "(0, 90)"));
                }
            }
            AxiProfile::Flat { radius } => {
                if !(radius.is_finite() && radius > 0.0) {
                    return Err(invalid("flat punch radius a", radius, "(0, inf)"));
                }
            }
        }
        Ok(())
    }

    /// The punch's radius, if a flat punch.
    pub fn flat_radius(&self) -> Option<f64> {
        match *self {
            AxiProfile::Flat { radius } => Some(radius),
            _ => None,
        }
    }

    /// The mean of f over the annulus r1 <= r <= r2 (area-weighted); `None` where the
    /// striker has no surface there (beyond a sphere's radius, beyond a punch's edge).
    pub fn ring_mean(&self, r1: f64, r2: f64) -> Option<f64> {
        // primitive P(r) = Int_0^r f(r') r' dr'; the mean is 2 (P(r2) - P(r1))/(r2^2 - r1^2)
        let mean = |p: &dyn Fn(f64) -> f64| 2.0 * (p(r2) - p(r1)) / ((r2 - r1) * (r2 + r1));
        match *self {
            AxiProfile::Sphere { radius } => {
                if r2 > radius {
                    return None;
                }
                // P = R r^2/2 + ((R^2 - r^2)^(3/2) - R^3)/3, written without cancellation as
                // Int f r dr with f = r^2/(R + sqrt(R^2 - r^2))
                let p = |r: f64| {
                    let q = ((radius - r) * (radius + r)).sqrt();
                    // R r^2/2 - (R^3 - q^3)/3, R^3 - q^3 = r^2 (R^2 + R q + q^2)/(R + q)
                    r * r
                        * (radius / 2.0
                            - (radius * radius + radius * q + q * q) / (3.0 * (radius + q)))
                };
                Some(mean(&p))
            }
            AxiProfile::Paraboloid { radius } => Some(mean(&|r: f64| r.powi(4) / (8.0 * radius))),
            AxiProfile::Cone { theta_deg } => {
                let cot = 1.0 / theta_deg.to_radians().tan();
                Some(mean(&|r: f64| r.powi(3) * cot / 3.0))
            }
            AxiProfile::Flat { radius } => (r2 <= radius * (1.0 + 1e-12)).then_some(0.0),
        }
    }

    /// The geometric contact radius for a penetration h > 0: f(a) = h (the punch's radius).
    pub fn contact_radius(&self, h: f64) -> f64 {
        if !(h > 0.0) {
            return 0.0;
        }
        match *self {
            AxiProfile::Sphere { radius } => (h * (2.0 * radius - h)).max(0.0).sqrt(),
            AxiProfile::Paraboloid { radius } => (2.0 * radius * h).sqrt(),
            AxiProfile::Cone { theta_deg } => h * theta_deg.to_radians().tan(),
            AxiProfile::Flat { radius } => radius,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ring_means_are_the_area_means() {
        for p in [
            AxiProfile::Sphere { radius: 1.0 },
            AxiProfile::Paraboloid { radius: 2.0 },
            AxiProfile::Cone { theta_deg: 70.0 },
        ] {
            let f = |r: f64| match p {
                AxiProfile::Sphere { radius } => radius - (radius * radius - r * r).sqrt(),
                AxiProfile::Paraboloid { radius } => r * r / (2.0 * radius),
                AxiProfile::Cone { theta_deg } => r / theta_deg.to_radians().tan(),
                _ => 0.0,
            };
            for (r1, r2) in [(0.0, 0.01), (0.3, 0.31), (0.05, 0.4)] {
                // midpoint rule on a fine partition of the ring
                let n = 20000;
                let (mut num, mut den) = (0.0, 0.0);
                for k in 0..n {
                    let r = r1 + (r2 - r1) * (k as f64 + 0.5) / n as f64;
                    num += f(r) * r;
                    den += r;
                }
                let want = num / den;
                let got = p.ring_mean(r1, r2).unwrap();
                assert!(
                    (got - want).abs() < 1e-8 * want.abs().max(1e-6),
                    "{p:?} {r1} {r2}"
                );
            }
            let h = 0.01;
            assert!((f(p.contact_radius(h)) - h).abs() < 1e-14);
        }
        assert_eq!(AxiProfile::Sphere { radius: 1.0 }.ring_mean(0.9, 1.1), None);
        assert_eq!(
            AxiProfile::Flat { radius: 0.5 }.ring_mean(0.4, 0.5),
            Some(0.0)
        );
        assert_eq!(AxiProfile::Flat { radius: 0.5 }.ring_mean(0.5, 0.6), None);
    }
}
