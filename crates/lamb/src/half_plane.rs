//! The half-plane's material, its Rayleigh cubic and the impulse responses g(s) in closed form.
//!
//! Units c1 = 1, mu = 1; m = c2/c1, s = |x|/(c1 t), x = s^2/m^2 (the slowness variable of the
//! Rayleigh cubic), K = 2 - x, v = sqrt(1 - s^2), w = sqrt(1 - x), and the Rayleigh cubic
//!
//! ```text
//!   c(x) = x^3 - 8 x^2 + (24 - 16 m^2) x - 16 (1 - m^2) = (x - x_R) q(x),
//! ```
//!
//! x_R = (c_R/c2)^2. The Cagniard-de Hoop inversion (`docs/lamb.md`, section 2) gives, for an
//! impulsive line force at x = 0 (z into the medium; u = I/(pi mu t) g(s)):
//!
//! ```text
//!   behind S (s < m):    g_zz = -(K^2 v + 4 v^2 w)/c(x),   g_xx = -(K^2 w + 4 v w^2)/c(x),
//!                        g_xz = pi K_R s_R delta(s - s_R),
//!   between P and S:     g_zz = -K^2 v x/E,   g_xx = 4 v x (x - 1)/E,
//!   (m < s < 1)          g_xz = -2 K v x sqrt(x - 1)/E,    E = K^4 + 16 v^2 (x - 1) = x c(x) > 0,
//!   ahead of P (s >= 1): 0,
//! ```
//!
//! with g_zx = -g_xz (reciprocity) and u_x = sign(x) I/(pi mu t) g_xz. The direct terms have a
//! simple pole at s_R (a principal value in every integral), with residues
//! r_zz = -K^2 v m^2/(s_R c'(x_R)), r_xx = -K^2 w m^2/(s_R c'(x_R)) (at x = x_R); the delta
//! weight of the cross term is K_R = -(2 - x_R)^3/(2 x_R c'(x_R)). Every form above is free of
//! cancellation: c(x) is evaluated as (x - x_R) q(x) with x - x_R = (s - s_R)(s + s_R)/m^2,
//! E is a sum of non-negative terms, and g -> 1 - nu as s -> 0 with no difference of large
//! terms (c(0) = -16 (1 - m^2)).

use complexfn::{Cx, Rayleigh, Real};
use std::sync::OnceLock;

use rug::Float;

use crate::error::{invalid, short, LambError, Result};

/// A value for each of the three independent surface responses.
///
/// `zz`: u_z due to a normal force; `xz`: u_x due to a normal force (for x > 0; odd in x);
/// `xx`: u_x due to a tangential force. The fourth, u_z due to a tangential force, is
/// `-xz` (reciprocity), odd in x.
#[derive(Clone, Debug, PartialEq)]
pub struct Triple<T> {
    /// Normal displacement due to a normal force.
    pub zz: T,
    /// Tangential displacement due to a normal force (x > 0).
    pub xz: T,
    /// Tangential displacement due to a tangential force.
    pub xx: T,
}

impl<T> Triple<T> {
    /// Apply `f` to each component.
    pub fn map<U>(self, mut f: impl FnMut(T) -> U) -> Triple<U> {
        Triple {
            zz: f(self.zz),
            xz: f(self.xz),
            xx: f(self.xx),
        }
    }
}

/// A value with its estimated absolute error (never below the rounding of the evaluation):
/// the workspace's one such type, [`complexfn::Estimate`].
pub use complexfn::Estimate;

/// The non-Rayleigh roots of the Rayleigh cubic.
#[derive(Clone, Debug)]
pub(crate) enum Spurious<T> {
    /// Two real roots.
    Real(T, T),
    /// A complex-conjugate pair (the root with Im > 0).
    Pair(Cx<T>),
}

/// Where s lies relative to the wavefronts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Region {
    /// Behind the Rayleigh arrival, 0 <= s < s_R.
    BehindRayleigh,
    /// Between the S and the Rayleigh arrivals, s_R < s < m.
    BetweenSAndRayleigh,
    /// Between the P and S arrivals, m <= s < 1.
    BetweenPAndS,
    /// Ahead of the P wave, s >= 1.
    AheadOfP,
}

/// The Rayleigh constants of the half-plane (units c1 = 1, mu = 1).
#[derive(Clone, Debug)]
pub struct RayleighConstants<T> {
    /// s_R = c_R/c1.
    pub s_r: T,
    /// Residue of g_zz at s_R: g_zz ~ r_zz/(s - s_R).
    pub r_zz: T,
    /// Residue of g_xx at s_R.
    pub r_xx: T,
    /// Weight of the cross term's delta: u_x due to an impulsive normal force contains
    /// (I/mu) K_R sign(x) delta(t - |x|/c_R), i.e. g_xz contains pi K_R s_R delta(s - s_R).
    pub k_r: T,
}

/// An elastic half-plane in plane strain, units c1 = 1, mu = 1, at the precision of its m.
///
/// Physical values: u = I/(pi mu t) g(s) for an impulse I delta(t) per unit length,
/// u = P/(pi mu) W(s) for a step P H(t), s = |x|/(c1 t).
#[derive(Clone, Debug)]
pub struct HalfPlane<T> {
    pub(crate) m: T,
    pub(crate) m2: T,
    /// 1/m^2
    pub(crate) a: T,
    pub(crate) x_r: T,
    pub(crate) s_r: T,
    /// q(x) = x^2 + (x_R - 8) x + q0, q0 = 16 (1 - m^2)/x_R
    pub(crate) q0: T,
    pub(crate) spurious: Spurious<T>,
    pub(crate) moments: crate::moments::MomentCache<T>,
    /// The same half-plane with [`GUARD_BITS`] more bits, where the partial fractions are
    /// built (absent on the guard copy itself).
    pub(crate) guard: Option<Box<HalfPlane<Float>>>,
    /// The Rayleigh constants, formed on first use.
    pub(crate) constants: OnceLock<RayleighConstants<T>>,
    /// M_0(0) = Int_0^1 g ds, formed on first use (every space-time corner needs it).
    pub(crate) total: OnceLock<Triple<Estimate<T>>>,
}

/// Extra bits of the precision at which roots and partial fractions are formed.
pub const GUARD_BITS: u32 = 64;

impl<T: Real> HalfPlane<T> {
    /// The half-plane with speed ratio m = c2/c1 in (0, sqrt(3)/2) (Poisson's ratio in
    /// (-1, 1/2)); m's precision is the working precision.
    pub fn new(m: T) -> Result<Self> {
        let mf = m.to_f64();
        if !m.is_finite() || !(m > 0.0) || !(m.clone().sqr() < 0.75) {
            return Err(invalid(
                "c2/c1",
                short(mf),
                "(0, sqrt(3)/2), i.e. Poisson's ratio in (-1, 1/2)",
            ));
        }
        // The roots of the Rayleigh cubic and every coefficient built on them are computed
        // with 64 guard bits and rounded once (the spurious roots are ill-conditioned in the
        // cubic's coefficients, and 1 - m^2 x_j cancels near the P front).
        let bits = m.prec();
        let guard = HalfPlane::<Float>::unguarded(m.to_mpfr(bits + GUARD_BITS))?;
        let r = |x: &Float| T::from_mpfr(x, bits);
        let spurious = match &guard.spurious {
            Spurious::Real(a, b) => Spurious::Real(r(a), r(b)),
            Spurious::Pair(z) => Spurious::Pair(Cx::new(r(&z.re), r(&z.im))),
        };
        let m2 = m.clone().sqr();
        Ok(HalfPlane {
            a: m2.clone().recip(),
            m2,
            x_r: r(&guard.x_r),
            s_r: r(&guard.s_r),
            q0: r(&guard.q0),
            m,
            spurious,
            moments: Default::default(),
            guard: Some(Box::new(guard)),
            constants: OnceLock::new(),
            total: OnceLock::new(),
        })
    }

    /// The constants at the precision of `m` itself, without a guard copy.
    fn unguarded(m: T) -> Result<Self> {
        let mf = m.to_f64();
        let ray = Rayleigh::new(m.clone())?;
        let m2 = m.clone().sqr();
        let a = m2.clone().recip();
        let s_r = ray.m_r().clone();
        let x_r = s_r.clone().sqr() * &a;
        let q0 = (m.one() - &m2) * 16.0 / &x_r;
        let b = x_r.clone() - 8.0;
        let disc = b.clone().sqr() - q0.clone() * 4.0;
        let spurious = if disc > 0.0 {
            let xp = (-b.clone() + disc.sqrt()) / 2.0;
            let xm = q0.clone() / &xp;
            Spurious::Real(xp, xm)
        } else if disc < 0.0 {
            Spurious::Pair(Cx::new(-b / 2.0, (-disc).sqrt() / 2.0))
        } else {
            return Err(invalid(
                "c2/c1",
                short(mf),
                "(0, sqrt(3)/2) except the value where the two non-Rayleigh roots of the Rayleigh cubic coincide (Poisson's ratio about 0.2631)",
            ));
        };
        // A real root at x = 1/m^2 (Poisson's ratio 0) sits on the P front, where the
        // substitutions of the step responses put their expansion point.
        if let Spurious::Real(xp, xm) = &spurious {
            let tol = m.epsilon() * 64.0;
            for x in [xp, xm] {
                if ((x.clone() * &m2) - 1.0).abs() <= tol {
                    return Err(invalid(
                        "Poisson's ratio",
                        short(poisson_of(&m2).to_f64()),
                        "(-1, 1/2) except 0 (there a root of the Rayleigh cubic lies on the P front; use e.g. nu = 1e-6)",
                    ));
                }
            }
        }
        Ok(HalfPlane {
            m,
            m2,
            a,
            x_r,
            s_r,
            q0,
            spurious,
            moments: Default::default(),
            guard: None,
            constants: OnceLock::new(),
            total: OnceLock::new(),
        })
    }

    /// The half-plane for Poisson's ratio nu in (-1, 1/2): m^2 = (1 - 2 nu)/(2 (1 - nu)).
    pub fn from_poisson(nu: T) -> Result<Self> {
        if !nu.is_finite() || !(nu > -1.0) || !(nu < 0.5) {
            return Err(invalid("Poisson's ratio", short(nu.to_f64()), "(-1, 1/2)"));
        }
        let one = nu.one();
        let m2 = (one.clone() - nu.clone() * 2.0) / ((one - &nu) * 2.0);
        HalfPlane::new(m2.sqrt())
    }

    /// m = c2/c1.
    pub fn m(&self) -> &T {
        &self.m
    }

    /// Poisson's ratio, nu = (1 - 2 m^2)/(2 (1 - m^2)).
    pub fn poisson(&self) -> T {
        poisson_of(&self.m2)
    }

    /// s_R = c_R/c1.
    pub fn s_r(&self) -> &T {
        &self.s_r
    }

    /// The wave region of s >= 0.
    pub fn region(&self, s: &T) -> Region {
        if *s >= 1.0 {
            Region::AheadOfP
        } else if *s >= self.m {
            Region::BetweenPAndS
        } else if *s > self.s_r {
            Region::BetweenSAndRayleigh
        } else {
            Region::BehindRayleigh
        }
    }

    /// q(x), the Rayleigh cubic with its Rayleigh root divided out (positive on [0, 1/m^2]).
    pub(crate) fn q(&self, x: &T) -> T {
        (x.clone() + &self.x_r - 8.0) * x + &self.q0
    }

    /// c'(x_R) = q(x_R).
    pub(crate) fn dc_r(&self) -> T {
        self.q(&self.x_r)
    }

    /// The Rayleigh constants: s_R, the residues of g_zz and g_xx, and the delta weight K_R.
    pub fn rayleigh_constants(&self) -> &RayleighConstants<T> {
        self.constants
            .get_or_init(|| self.compute_rayleigh_constants())
    }

    fn compute_rayleigh_constants(&self) -> RayleighConstants<T> {
        let one = self.m.one();
        let dc = self.dc_r();
        let k = one.lit(2.0) - &self.x_r;
        let v = (one.clone() - self.s_r.clone().sqr()).sqrt();
        let w = (one - &self.x_r).sqrt();
        let pre = -(k.clone().sqr() * &self.m2 / (self.s_r.clone() * &dc));
        RayleighConstants {
            s_r: self.s_r.clone(),
            r_zz: pre.clone() * &v,
            r_xx: pre * &w,
            k_r: -(k.clone().sqr() * &k / (self.x_r.clone() * &dc * 2.0)),
        }
    }

    /// 16 s_R/|s - s_R|: the amplification, near the Rayleigh pole, of the rounding of s_R at the
    /// working precision (the values are exact functions of the given s, but s_R itself is a
    /// rounded root).
    pub(crate) fn pole_conditioning(&self, s: &T) -> f64 {
        let d = (s.clone() - &self.s_r).abs().to_f64();
        16.0 * self.s_r.to_f64() / d.max(f64::MIN_POSITIVE)
    }

    /// Check a point s: finite, >= 0; `quantity` names what is asked for in the error.
    pub(crate) fn check_s(&self, name: &'static str, s: &T) -> Result<()> {
        if !s.is_finite() || *s < 0.0 {
            return Err(invalid(name, short(s.to_f64()), "[0, inf)"));
        }
        Ok(())
    }

    /// `t` unchanged if every value and error estimate is finite, else [`LambError::NotFinite`].
    pub(crate) fn finite(
        &self,
        quantity: &'static str,
        s: &T,
        t: Triple<Estimate<T>>,
    ) -> Result<Triple<Estimate<T>>> {
        let ok = |e: &Estimate<T>| e.value.is_finite() && e.error.is_finite();
        if ok(&t.zz) && ok(&t.xz) && ok(&t.xx) {
            Ok(t)
        } else {
            Err(LambError::NotFinite {
                quantity,
                s: short(s.to_f64()),
            })
        }
    }

    pub(crate) fn at_rayleigh(&self, quantity: &'static str) -> LambError {
        LambError::AtRayleighArrival {
            quantity,
            s_r: short(self.s_r.to_f64()),
        }
    }

    /// The impulse responses g_zz, g_xz, g_xx at s = |x|/(c1 t) >= 0 (module docs), their
    /// regular parts: the delta of g_xz at s_R is not a pointwise value (see
    /// [`HalfPlane::rayleigh_constants`]). Errors for s < 0 or non-finite, and at s = s_R
    /// exactly. Each value is correct to a few units of the working precision for the given s.
    pub fn impulse(&self, s: &T) -> Result<Triple<Estimate<T>>> {
        self.check_s("s", s)?;
        if *s == self.s_r {
            return Err(self.at_rayleigh("the impulse response g(s)"));
        }
        let one = s.one();
        let zero = s.zero();
        let eps = s.epsilon().to_f64();
        let mut k_dev = Triple {
            zz: 0.0,
            xz: 0.0,
            xx: 0.0,
        };
        let value = match self.region(s) {
            Region::AheadOfP => Triple {
                zz: zero.clone(),
                xz: zero.clone(),
                xx: zero,
            },
            Region::BetweenPAndS => {
                let x = s.clone().sqr() * &self.a;
                let v = ((one.clone() - s) * (one.clone() + s)).sqrt();
                let xm1 = (s.clone() - &self.m) * (s.clone() + &self.m) * &self.a;
                let k = one.lit(2.0) - &x;
                let k2 = k.clone().sqr();
                let e = k2.clone().sqr() + v.clone().sqr() * &xm1 * 16.0;
                let k4_e = (k2.clone().sqr() / &e).to_f64();
                let ef = e.to_f64();
                let vx_e = v * &x / e;
                // K = 2 - x vanishes at x = 2 (next to the P front for Poisson's ratio near 0):
                // its absolute rounding eps x moves each g by eps x |dg/dK|
                let (kf, xf, r) = (k.to_f64().abs(), x.to_f64(), vx_e.to_f64().abs());
                let sq = xm1.to_f64().abs().sqrt();
                k_dev = Triple {
                    zz: 2.0 * kf * r * (1.0 + 2.0 * k4_e) * xf,
                    xz: 2.0 * sq * r * (1.0 + 4.0 * k4_e) * xf,
                    xx: 16.0 * xm1.to_f64().abs() * r * kf.powi(3) / ef * xf,
                };
                Triple {
                    zz: -(k2 * &vx_e),
                    xz: -(k * xm1.clone().sqrt() * &vx_e * 2.0),
                    xx: xm1 * vx_e * 4.0,
                }
            }
            _ => {
                let x = s.clone().sqr() * &self.a;
                let v = ((one.clone() - s) * (one.clone() + s)).sqrt();
                let w = ((self.m.clone() - s) * (self.m.clone() + s)).sqrt() / &self.m;
                let k2 = (one.lit(2.0) - &x).sqr();
                let xmr = (s.clone() - &self.s_r) * (s.clone() + &self.s_r) * &self.a;
                let c = xmr * self.q(&x);
                let vw4 = v.clone() * &w * 4.0;
                Triple {
                    zz: -((k2.clone() + &vw4) * v / &c),
                    xz: zero,
                    xx: -((k2 + vw4) * w / c),
                }
            }
        };
        // s_R and m are rounded: near the pole and the S front the value moves with them
        let near_s = (s.clone() - &self.m).abs().to_f64().max(f64::MIN_POSITIVE);
        let cond = self.pole_conditioning(s) + 2.0 * self.m.to_f64() / near_s;
        let dev = [k_dev.zz, k_dev.xz, k_dev.xx];
        let mut i = 0;
        let out = value.map(|v| {
            let err = (16.0 + cond) * eps * v.to_f64().abs() + 4.0 * eps * dev[i];
            i += 1;
            Estimate {
                value: v,
                error: err,
                kind: complexfn::ErrorKind::Rounding,
            }
        });
        self.finite("the impulse response g(s)", s, out)
    }
}

/// Poisson's ratio from m^2 = (c2/c1)^2: nu = (1 - 2 m^2)/(2 (1 - m^2)).
pub fn poisson_of<T: Real>(m2: &T) -> T {
    let one = m2.one();
    (one.clone() - m2.clone() * 2.0) / ((one - m2) * 2.0)
}
