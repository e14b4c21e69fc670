//! The interior field, eqs (9)-(12) with (16): displacement, stresses, particle velocity,
//! dilatation and rotation at a point of the body, in polar and Cartesian components.
//!
//! Units c1 = 1, mu = 1 (see the crate docs). With the J_k integrals of [`crate::j_operator`]:
//!
//! ```text
//!   u        = (J_1[(vt - r)U_1] - i J_2[(vt - r)U_2]) / (2n)                 (10)
//!   s_theta  = (J_1[V_1] - i J_2[V_2]) / 2                                     (11b)
//!   s_r      = -2 s_theta - ((1 - m^2)/m^2) J_1[v^2 Re(p_1 W_1)]                (11a, corrected sign)
//!   du/dt    = (1/2) [1/(n-1)! Int v^(-n-1) (vt - r)^(n-1) (U_1 - i U_2) dv]    (d/dt of (10))
//!   Delta    = -(1/2) J_1[v^2 Re(p_1 W_1)],   (curl u)_z = (1/(2 m^2)) J_2[v^2 Re(p_2 W_2)]
//! ```
//!
//! Eq (11a) as printed has `+ (1 - m^2) J_1[2U - V]`; since 2U - V = (v^2/m^2) Re(p_1 W_1) and
//! sigma_r + sigma_theta = 2(lambda + mu) Delta = 2 (1/m^2 - 1) Delta, the sign must be minus. The
//! tests confirm it against finite differences of u through Hooke's law.
//!
//! The particle velocity: d/dt of (10) under the integral (the lower-limit term vanishes since
//! (vt - r)^n = 0 there for n >= 1); equivalently n u = r du/dr + t du/dt (Euler) - both checked.

use complexfn::quadrature::{CachedRules, TsOptions};
use complexfn::{Cx, Real};

use crate::error::{invalid, Result};
use crate::j_operator::{default_options, j_terms};
use crate::zeta_map::{region, Region};
use crate::Potentials;

/// The field at one point, polar components (eq (9)), units c1 = mu = 1.
#[derive(Clone, Debug)]
pub struct FieldValues<T> {
    /// r (units c1 t when t = 1).
    pub r: T,
    /// theta in (-pi, 0).
    pub theta: T,
    /// t.
    pub t: T,
    /// Wave region of the point.
    pub region: Region,
    /// u = u_r + i u_theta.
    pub u: Cx<T>,
    /// s_r = sigma_r - sigma_theta + 2 i sigma_rtheta.
    pub s_r: Cx<T>,
    /// s_theta = sigma_theta - i sigma_rtheta.
    pub s_theta: Cx<T>,
    /// du/dt = du_r/dt + i du_theta/dt.
    pub velocity: Cx<T>,
    /// Dilatation Delta = div u (eq (1a)).
    pub dilatation: T,
    /// (curl u)_z = du_y/dx - du_x/dy = 2 omega (eq (1b) defines omega as half of it).
    pub curl: T,
}

/// The field in Cartesian components (x along the surface, y out of the body).
#[derive(Clone, Debug)]
pub struct CartesianValues<T> {
    /// u_x.
    pub ux: T,
    /// u_y.
    pub uy: T,
    /// du_x/dt.
    pub vx: T,
    /// du_y/dt.
    pub vy: T,
    /// sigma_xx.
    pub sxx: T,
    /// sigma_yy.
    pub syy: T,
    /// sigma_xy.
    pub sxy: T,
}

impl<T: Real> FieldValues<T> {
    /// sigma_r.
    pub fn sigma_r(&self) -> T {
        self.s_r.re.clone() + self.sigma_theta()
    }
    /// sigma_theta.
    pub fn sigma_theta(&self) -> T {
        self.s_theta.re.clone()
    }
    /// sigma_rtheta.
    pub fn sigma_rtheta(&self) -> T {
        -self.s_theta.im.clone()
    }
    /// The rotation omega of eq (1b) (half the curl).
    pub fn rotation(&self) -> T {
        self.curl.clone() / 2.0
    }
    /// Cartesian components.
    pub fn cartesian(&self) -> CartesianValues<T> {
        let (s, c) = self.theta.clone().sin_cos();
        let rot = |a: &Cx<T>| -> (T, T) {
            (
                a.re.clone() * &c - a.im.clone() * &s,
                a.re.clone() * &s + a.im.clone() * &c,
            )
        };
        let (ux, uy) = rot(&self.u);
        let (vx, vy) = rot(&self.velocity);
        let (sr, st, srt) = (self.sigma_r(), self.sigma_theta(), self.sigma_rtheta());
        let (c2, s2, sc) = (c.clone().sqr(), s.clone().sqr(), s.clone() * &c);
        let sxx = sr.clone() * &c2 + st.clone() * &s2 - srt.clone() * &sc * 2.0;
        let syy = sr.clone() * &s2 + st.clone() * &c2 + srt.clone() * &sc * 2.0;
        let sxy = (sr - st) * &sc + srt * (c2 - s2);
        CartesianValues {
            ux,
            uy,
            vx,
            vy,
            sxx,
            syy,
            sxy,
        }
    }
}

/// The field at polar point (r, theta) and time t (c1 = mu = 1), -pi < theta < 0, r > 0, t > 0,
/// with quadrature options `opts` (see [`crate::j_operator::default_options`]).
/// Points with r >= t (ahead of the P front) give zero.
pub fn at_polar<T, P>(pot: &P, r: &T, theta: &T, t: &T, opts: TsOptions) -> Result<FieldValues<T>>
where
    T: CachedRules,
    P: Potentials<T> + ?Sized,
{
    let n = pot.degree();
    if n == 0 {
        return invalid("degree n", 0.0, ">= 1");
    }
    if !(r.is_finite() && *r > 0.0) {
        return invalid("r", r.to_f64(), "(0, inf)");
    }
    if !(t.is_finite() && *t > 0.0) {
        return invalid("t", t.to_f64(), "(0, inf)");
    }
    let pi = r.pi();
    if !(theta.is_finite() && *theta < 0.0 && theta.clone() > -pi) {
        return invalid(
            "theta",
            theta.to_f64(),
            "(-pi, 0) (use surface:: on the faces)",
        );
    }
    let ray = pot.rayleigh();
    let reg = region(&(r.clone() / t), theta, ray.m());
    let j1 = j_terms(pot, 1, r, theta, t, opts)?;
    let j2 = j_terms(pot, 2, r, theta, t, opts)?;
    let m2 = ray.m2().clone();
    let nn = r.lit(f64::from(n));
    let u = (j1.ju.clone() - j2.ju.clone().mul_i()).scale(&(nn * 2.0).recip());
    let s_theta = (j1.jv.clone() - j2.jv.clone().mul_i()) / 2.0;
    let coef = (r.one() - &m2) / &m2;
    let s_r = -(s_theta.clone() * 2.0) - Cx::real(coef * &j1.jp);
    let velocity = (j1.jdt.clone() - j2.jdt.clone().mul_i()) / 2.0;
    let dilatation = -(j1.jp.clone() / 2.0);
    let curl = j2.jp.clone() / (m2 * 2.0);
    Ok(FieldValues {
        r: r.clone(),
        theta: theta.clone(),
        t: t.clone(),
        region: reg,
        u,
        s_r,
        s_theta,
        velocity,
        dilatation,
        curl,
    })
}

/// The field at Cartesian point (x, y), y < 0, and time t (c1 = mu = 1), default tolerance.
pub fn at_time<T, P>(pot: &P, x: &T, y: &T, t: &T) -> Result<FieldValues<T>>
where
    T: CachedRules,
    P: Potentials<T> + ?Sized,
{
    if !(x.is_finite() && y.is_finite() && *y < 0.0) {
        return invalid(
            "y",
            y.to_f64(),
            "(-inf, 0) with x, y finite (use surface:: on y = 0)",
        );
    }
    let r = x.clone().hypot(y);
    let theta = y.clone().atan2(x);
    at_polar(pot, &r, &theta, t, default_options(x.prec()))
}

/// The field at Cartesian point (x, y), y < 0, at t = 1: x, y in units of c1 t.
pub fn at<T, P>(pot: &P, x: &T, y: &T) -> Result<FieldValues<T>>
where
    T: CachedRules,
    P: Potentials<T> + ?Sized,
{
    at_time(pot, x, y, &x.one())
}
