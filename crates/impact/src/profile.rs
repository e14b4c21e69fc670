//! The striker's profile z = f(x): symmetric, convex, f(0) = 0, in units of the length scale
//! R (the radius for the circle and the parabola; a length the user picks for the others).
//!
//! The profile enters the contact condition w(x, t) = h(t) - f(x) on the contact (the paper's
//! eq (3) with L the distance from the mass centre to the front point) and the kinematic edge
//! law f(b) = L - h (eq (4)), i.e. f(b) = h with h measured from first contact.

use std::sync::Arc;

use crate::error::{invalid, Result};
use crate::scalar::Scalar;

/// A symmetric convex striker profile (dimensionless: x/R, f/R).
#[derive(Clone)]
pub enum Profile {
    /// A circle of radius `radius`: f = radius - sqrt(radius^2 - x^2), |x| < radius.
    Circle {
        /// Radius over R (1 when R is the radius).
        radius: f64,
    },
    /// A parabola f = x^2/(2 radius).
    Parabola {
        /// Radius of curvature at the apex over R.
        radius: f64,
    },
    /// A power law f = a |x|^k, k >= 1.
    Power {
        /// Coefficient (in units R^(1-k)).
        a: f64,
        /// Exponent, >= 1.
        k: f64,
    },
    /// A wedge f = |x| cot theta, theta the half-angle.
    Wedge {
        /// Half-angle in degrees, (0, 90).
        theta_deg: f64,
    },
    /// A flat punch of half-width `half_width`: f = 0 on |x| <= half_width, a wall beyond.
    Flat {
        /// Half-width over R.
        half_width: f64,
    },
    /// A tabulated profile: points (x_i, f_i), x_0 = 0 < x_1 < ..., f_0 = 0, convex and
    /// increasing, linearly interpolated (the table's last x bounds the contact).
    Table(Arc<Vec<(f64, f64)>>),
    /// A user-supplied function (library): f(x) for x >= 0, convex, increasing, f(0) = 0,
    /// defined up to `max_x`.
    Function {
        /// The profile f(x), x >= 0.
        f: Arc<dyn Fn(f64) -> f64 + Send + Sync>,
        /// The largest x where f is defined.
        max_x: f64,
    },
}

impl std::fmt::Debug for Profile {
    fn fmt(&self, fm: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(fm, "{}", self.label())
    }
}

fn positive(name: &'static str, v: f64) -> Result<()> {
    if !(v.is_finite() && v > 0.0) {
        return Err(invalid(name, v, "(0, inf)"));
    }
    Ok(())
}

impl Profile {
    /// A short label, e.g. `parabola:R=1`.
    pub fn label(&self) -> String {
        match self {
            Profile::Circle { radius } => format!("circle:R={radius}"),
            Profile::Parabola { radius } => format!("parabola:R={radius}"),
            Profile::Power { a, k } => format!("power:A={a},k={k}"),
            Profile::Wedge { theta_deg } => format!("wedge:theta_deg={theta_deg}"),
            Profile::Flat { half_width } => format!("flat:a={half_width}"),
            Profile::Table(t) => format!("table({} points)", t.len()),
            Profile::Function { .. } => "function".into(),
        }
    }

    /// Checks the parameters: positive sizes, k >= 1, 0 < theta < 90, a table that starts
    /// at (0, 0) with increasing x and is increasing and convex, a function that is
    /// increasing and convex on a sample.
    pub fn validate(&self) -> Result<()> {
        match self {
            Profile::Circle { radius } | Profile::Parabola { radius } => {
                positive("profile radius R", *radius)
            }
            Profile::Power { a, k } => {
                positive("profile coefficient A", *a)?;
                if !(k.is_finite() && *k >= 1.0) {
                    return Err(invalid("profile exponent k", k, "[1, inf) (convex)"));
                }
                Ok(())
            }
            Profile::Wedge { theta_deg } => {
                if !(theta_deg.is_finite() && *theta_deg > 0.0 && *theta_deg < 90.0) {
                    return Err(invalid("wedge half-angle theta_deg", theta_deg, "(0, 90)"));
                }
                Ok(())
            }
            Profile::Flat { half_width } => positive("flat punch half-width a", *half_width),
            Profile::Table(t) => check_samples(t, "profile table"),
            Profile::Function { f, max_x } => {
                positive("profile function max_x", *max_x)?;
                let pts: Vec<(f64, f64)> = (0..=64)
                    .map(|i| {
                        let x = max_x * i as f64 / 64.0;
                        (x, f(x))
                    })
                    .collect();
                check_samples(&pts, "profile function")
            }
        }
    }

    /// f(x) (symmetric), `None` beyond the profile's extent (the circle's radius, a flat
    /// punch's edge, a table's last point), at the precision of x (a user's function is
    /// evaluated in f64: [`Profile::exact_at_every_precision`]).
    pub fn height<T: Scalar>(&self, x: T) -> Option<T> {
        let x = x.abs();
        match self {
            Profile::Circle { radius } => {
                let r = T::input(*radius);
                (x < r).then(|| x * x / (r + (r * r - x * x).sqrt()))
            }
            Profile::Parabola { radius } => Some(x * x / (T::input(*radius) * 2.0)),
            Profile::Power { a, k } => Some(x.powf(&T::input(*k)) * T::input(*a)),
            Profile::Wedge { theta_deg } => Some(x / tan_deg::<T>(*theta_deg)),
            Profile::Flat { half_width } => (x <= T::input(*half_width)).then(|| T::of(0.0)),
            Profile::Table(t) => interpolate(t, x),
            Profile::Function { f, max_x } => (x <= *max_x).then(|| T::of(f(x.to_f64()))),
        }
    }

    /// Whether [`Profile::height`] is exact at every precision: all but a user's function,
    /// which is evaluated in f64.
    pub fn exact_at_every_precision(&self) -> bool {
        !matches!(self, Profile::Function { .. })
    }

    /// The extent of the profile: the largest contact half-width it admits.
    pub fn extent(&self) -> f64 {
        match self {
            Profile::Circle { radius } => *radius,
            Profile::Flat { half_width } => *half_width,
            Profile::Table(t) => t.last().map(|p| p.0).unwrap_or(0.0),
            Profile::Function { max_x, .. } => *max_x,
            _ => f64::INFINITY,
        }
    }

    /// The kinematic edge (eq (4)): the half-width b with f(b) = h for a penetration h >= 0
    /// (the flat punch's edge for every h > 0), at the precision of h. `None` when h exceeds
    /// the profile's extent.
    pub fn kinematic_edge<T: Scalar>(&self, h: T) -> Option<T> {
        let zero = T::of(0.0);
        if h <= 0.0 {
            return Some(zero);
        }
        match self {
            Profile::Circle { radius } => {
                let r = T::input(*radius);
                (h < r).then(|| (h * (r * 2.0 - h)).sqrt())
            }
            Profile::Parabola { radius } => Some((h * T::input(*radius) * 2.0).sqrt()),
            Profile::Power { a, k } => Some((h / T::input(*a)).powf(&(T::of(1.0) / T::input(*k)))),
            Profile::Wedge { theta_deg } => Some(h * tan_deg::<T>(*theta_deg)),
            Profile::Flat { half_width } => Some(T::input(*half_width)),
            _ => {
                // bisection on the increasing profile, to the precision's last bit
                let top = T::of(self.extent());
                if self.height(top)? < h {
                    return None;
                }
                let (mut lo, mut hi) = (zero, top);
                for _ in 0..(T::BITS + 60) {
                    let mid = (lo + hi) * 0.5;
                    if self.height(mid)? < h {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                Some((lo + hi) * 0.5)
            }
        }
    }
}

/// tan(theta) for theta in degrees, at the precision T (the wedge's cot of its half-angle
/// inverted).
fn tan_deg<T: Scalar>(theta_deg: f64) -> T {
    let one = T::of(1.0);
    (T::input(theta_deg) * one.pi() / 180.0).tan()
}

fn interpolate<T: Scalar>(t: &[(f64, f64)], x: T) -> Option<T> {
    let last = t.last()?;
    if x > last.0 {
        return None;
    }
    let i = t.partition_point(|p| x >= p.0).clamp(1, t.len() - 1);
    let (a, b) = (t[i - 1], t[i]);
    let (ax, ay, bx, by) = (T::input(a.0), T::input(a.1), T::input(b.0), T::input(b.1));
    Some((x - ax) * (by - ay) / (bx - ax) + ay)
}

fn check_samples(t: &[(f64, f64)], what: &'static str) -> Result<()> {
    if t.len() < 2 {
        return Err(invalid(
            what,
            format!("{} points", t.len()),
            "at least 2 points",
        ));
    }
    if t.iter().any(|p| !p.0.is_finite() || !p.1.is_finite()) {
        return Err(invalid(what, "a non-finite value", "finite points"));
    }
    if t[0].0 != 0.0 || t[0].1 != 0.0 {
        return Err(invalid(
            what,
            format!("first point ({}, {})", t[0].0, t[0].1),
            "(0, 0): the profile is symmetric about x = 0 and touches first there",
        ));
    }
    let mut prev_slope = 0.0;
    for w in t.windows(2) {
        let dx = w[1].0 - w[0].0;
        if !(dx > 0.0) {
            return Err(invalid(
                what,
                format!("x = {}", w[1].0),
                "strictly increasing x",
            ));
        }
        let slope = (w[1].1 - w[0].1) / dx;
        let tol = 1e-12 * (1.0 + slope.abs());
        if slope < -tol || slope < prev_slope - tol {
            return Err(invalid(
                what,
                format!("slope {slope} after {prev_slope} at x = {}", w[0].0),
                "increasing slopes >= 0 (a convex profile rising from its apex)",
            ));
        }
        prev_slope = slope;
    }
    Ok(())
}
