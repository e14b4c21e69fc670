//! Space-time cells: the surface displacement at (x, t) due to a load uniform on a strip
//! [x_a, x_b] and constant (or linear) in time on [t_a, t_b], as corner differences of
//! primitives homogeneous in (X, T) (`docs/lamb.md`, section 4).
//!
//! Units c1 = 1, mu = 1 and a load of unit intensity (force per unit area). With
//! G(X, T) = g(|X|/T)/(pi T) the impulse response, the double primitives
//!
//! ```text
//!   Phi(X, T) = Int_0^X Int_0^T G dT' dX' = (T/pi) phi(s),   phi(s) = s M_1(s) + M_0(0) - M_0(s),
//!   Psi(X, T) = Int_0^X Int_0^T T' G dT' dX' = (T^2/pi) psi(s), psi(s) = [s^2 M_2(s) + M_0(0) - M_0(s)]/2,
//! ```
//!
//! s = |X|/T, follow from integrating by parts ([`crate::moments`] gives M_n); both vanish for
//! T <= 0 (causality), are odd in X for the direct terms and even for the cross term. A load
//! constant on the cell gives the four-corner difference of Phi at X = x - x_{a,b},
//! T = t - t_{a,b}; a load rising linearly from 0 at t_a to 1 at t_b gives
//! [(t - t_a) dPhi - dPsi]/(t_b - t_a). The corner differences lose digits in proportion to
//! t/(t_b - t_a) and |x|/(x_b - x_a): the absolute error estimate carries that loss.

use complexfn::quadrature::CachedRules;
use complexfn::Real;

use crate::error::{invalid, short, Result};
use crate::half_plane::{Estimate, HalfPlane, Triple};

/// A rectangle of the surface-time plane carrying a uniform load: [xa, xb] x [ta, tb].
#[derive(Clone, Debug)]
pub struct Cell<T> {
    /// Left end of the strip (units c1 = 1: lengths in c1 times the time unit).
    pub xa: T,
    /// Right end of the strip.
    pub xb: T,
    /// Start of the load.
    pub ta: T,
    /// End of the load.
    pub tb: T,
}

/// How the load varies in time over its cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimeShape {
    /// Constant (1) on [ta, tb].
    Constant,
    /// Rising linearly from 0 at ta to 1 at tb.
    Linear,
}

fn add<T: Real>(acc: &mut Triple<Estimate<T>>, t: Triple<Estimate<T>>, sign: f64) {
    let f = |a: &mut Estimate<T>, b: Estimate<T>| {
        a.value += b.value * sign;
        a.error += b.error;
    };
    f(&mut acc.zz, t.zz);
    f(&mut acc.xz, t.xz);
    f(&mut acc.xx, t.xx);
}

fn zero_triple<T: Real>(like: &T) -> Triple<Estimate<T>> {
    let z = || Estimate {
        value: like.zero(),
        error: 0.0,
        kind: complexfn::ErrorKind::Propagated,
    };
    Triple {
        zz: z(),
        xz: z(),
        xx: z(),
    }
}

impl<T: CachedRules> HalfPlane<T> {
    /// phi(s) (order 1) or psi(s) (order 2) of the module docs, s >= 0, s != s_R.
    fn corner_profile(&self, order: usize, s: &T) -> Result<Triple<Estimate<T>>> {
        if *s == 0.0 {
            return Ok(zero_triple(s));
        }
        let eps = s.epsilon().to_f64();
        let total = self.total_moment(s)?;
        let half = if order == 1 { 1.0 } else { 0.5 };
        if *s >= 1.0 {
            return Ok(total.map(|e| Estimate {
                value: e.value * half,
                error: e.error * half,
                kind: complexfn::ErrorKind::Propagated,
            }));
        }
        let m0 = self.moment(0, s)?;
        let mn = self.moment(order, s)?;
        let sn = s.clone().powi(order as i32);
        let comb = |t: Estimate<T>, a: Estimate<T>, b: Estimate<T>| {
            let p = sn.clone() * &b.value;
            let mag = p.to_f64().abs() + t.value.to_f64().abs() + a.value.to_f64().abs();
            Estimate {
                value: (p + &t.value - &a.value) * half,
                error: half * (sn.to_f64() * b.error + t.error + a.error + 4.0 * eps * mag),
                kind: complexfn::ErrorKind::Propagated,
            }
        };
        Ok(Triple {
            zz: comb(total.zz, m0.zz, mn.zz),
            xz: comb(total.xz, m0.xz, mn.xz),
            xx: comb(total.xx, m0.xx, mn.xx),
        })
    }

    /// The double primitive Phi(X, T) (order 1) or Psi(X, T) (order 2) of the module docs.
    /// Zero for T <= 0. Errors on the Rayleigh ray |X| = s_R T.
    pub fn space_time_primitive(&self, order: usize, x: &T, t: &T) -> Result<Triple<Estimate<T>>> {
        if order != 1 && order != 2 {
            return Err(invalid("primitive order", order, "1 (Phi) or 2 (Psi)"));
        }
        if !x.is_finite() {
            return Err(invalid("X", short(x.to_f64()), "finite"));
        }
        if !t.is_finite() {
            return Err(invalid("T", short(t.to_f64()), "finite"));
        }
        if *t <= 0.0 {
            return Ok(zero_triple(t));
        }
        let s = x.clone().abs() / t;
        if s == self.s_r {
            return Err(self.at_rayleigh("a cell corner on the Rayleigh ray |X| = c_R T"));
        }
        let prof = self.corner_profile(order, &s)?;
        let prof = self.finite("a cell corner primitive", &s, prof)?;
        let scale = t.clone().powi(order as i32) / t.pi();
        let odd = if x.is_sign_negative() { -1.0 } else { 1.0 };
        let sc = |e: Estimate<T>, sign: f64| Estimate {
            value: e.value * &scale * sign,
            error: e.error * scale.to_f64(),
            kind: complexfn::ErrorKind::Propagated,
        };
        Ok(Triple {
            zz: sc(prof.zz, odd),
            xz: sc(prof.xz, 1.0),
            xx: sc(prof.xx, odd),
        })
    }

    /// The triple primitive of the normal response to a normal load,
    /// Xi(X, T) = Int_0^X Phi_zz(X', T) dX' (even in X, zero for T <= 0), with its absolute
    /// error estimate. Its second difference in X over three cell boundaries is the mean over
    /// a receiver cell of the displacement due to a source cell (the influence coefficients of
    /// a Galerkin grid); with s = |X|/T,
    ///
    /// ```text
    ///   Xi = (T^2/pi) xi(s),
    ///   xi(s) = (s^2/2) M_1(s) + s [M_0(0) - M_0(s)] - [M_{-1}(0) - M_{-1}(s)]/2
    /// ```
    ///
    /// (`docs/lamb.md`, section 4; integrate phi by parts twice). Each moment is in closed
    /// form, so no quadrature crosses the Rayleigh ray or a front. The three logarithms of
    /// the Rayleigh arrival cancel to (s - s_R)^2 ln|s - s_R|, so Xi is continuously
    /// differentiable across the ray; a corner exactly on it takes the mean of its two
    /// neighbouring floating-point values of s, their difference added to the estimate.
    pub fn cell_mean_primitive_zz(&self, x: &T, t: &T) -> Result<Estimate<T>> {
        if !x.is_finite() {
            return Err(invalid("X", short(x.to_f64()), "finite"));
        }
        if !t.is_finite() {
            return Err(invalid("T", short(t.to_f64()), "finite"));
        }
        if *t <= 0.0 || *x == 0.0 {
            return Ok(Estimate {
                value: t.zero(),
                error: 0.0,
                kind: complexfn::ErrorKind::Propagated,
            });
        }
        let s = x.clone().abs() / t;
        let scale = t.clone().sqr() / t.pi();
        let xi = if s == self.s_r {
            let eps = s.epsilon();
            let lo = self.xi_zz(&(s.clone() * (s.one() - eps.clone() * 4.0)))?;
            let hi = self.xi_zz(&(s.clone() * (s.one() + eps * 4.0)))?;
            let spread = (hi.value.clone() - &lo.value).abs().to_f64();
            Estimate {
                value: (lo.value + &hi.value) / 2.0,
                error: lo.error.max(hi.error) + spread,
                kind: complexfn::ErrorKind::Propagated,
            }
        } else {
            self.xi_zz(&s)?
        };
        Ok(Estimate {
            error: xi.error * scale.to_f64(),
            value: xi.value * &scale,
            kind: complexfn::ErrorKind::Propagated,
        })
    }

    /// xi(s) of [`HalfPlane::cell_mean_primitive_zz`], s > 0, s != s_R.
    fn xi_zz(&self, s: &T) -> Result<Estimate<T>> {
        let eps = s.epsilon().to_f64();
        let total0 = self.total_moment(s)?.zz;
        let total1 = self.first_zz_total(s)?;
        if *s >= 1.0 {
            // beyond the P front every moment of s vanishes
            let a = s.clone() * &total0.value;
            let b = total1.value.clone() / 2.0;
            let mag = a.to_f64().abs() + b.to_f64().abs();
            return Ok(Estimate {
                value: a - b,
                error: s.to_f64() * total0.error + total1.error / 2.0 + 4.0 * eps * mag,
                kind: complexfn::ErrorKind::Propagated,
            });
        }
        // behind the Rayleigh arrival g_zz is analytic: its Taylor series, free of the
        // cancellation of the differences of moments
        if *s <= self.s_r.clone() / 2.0 {
            return self.xi_zz_series(s);
        }
        // the logarithms r s_R^-n ln|s - s_R| of the three moments cancel to
        // (r/(2 s_R)) (s - s_R)^2 ln|s - s_R|: the rounding of s_R moves xi by
        // r |s - s_R|/(2 s_R) d s_R only
        let m1 = self.moment_with(1, s, false)?.zz;
        let m0 = self.moment_with(0, s, false)?.zz;
        let mm = self.first_moment_zz_with(s, false)?;
        let c = self.rayleigh_constants();
        let sr = c.s_r.to_f64();
        let rounding = 16.0 * eps * c.r_zz.to_f64().abs() * (s.to_f64() - sr).abs() / sr;
        let a = s.clone().sqr() / 2.0 * &m1.value;
        let b = s.clone() * (total0.value.clone() - &m0.value);
        let c = (total1.value.clone() - &mm.value) / 2.0;
        let sf = s.to_f64();
        let mag = a.to_f64().abs()
            + sf * (total0.value.to_f64().abs() + m0.value.to_f64().abs())
            + 0.5 * (total1.value.to_f64().abs() + mm.value.to_f64().abs());
        let err = 0.5 * sf * sf * m1.error
            + sf * (total0.error + m0.error)
            + 0.5 * (total1.error + mm.error)
            + 4.0 * eps * mag
            + rounding;
        let value = a + b - c;
        if !value.is_finite() {
            return Err(self.at_rayleigh("the cell-mean primitive Xi(X, T)"));
        }
        Ok(Estimate {
            value,
            error: err,
            kind: complexfn::ErrorKind::Propagated,
        })
    }

    /// xi(s) for 0 < s <= s_R/2 from the Taylor series of g_zz in u = s^2
    /// ([`HalfPlane::zz_series`]): with g_zz = sum_k g_k u^k,
    ///
    /// ```text
    ///   M_1(s) = -g_0 ln s + C_1 - sum_{k>=1} g_k u^k/(2k),
    ///   Int_0^s (s - sigma/2) g_zz dsigma = sum_k g_k u^(k+1) [1/(2k + 1) - 1/(4k + 4)],
    ///   xi(s) = u [(C_1 - g_0 ln s)/2 + sum_k g_k e_k u^k],
    ///   e_0 = 3/4,  e_k = 1/(2k + 1) - 1/(4k + 4) - 1/(4k) = -1/(4k(k + 1)(2k + 1)),
    /// ```
    ///
    /// C_1 fixed once by the closed-form step response at s_R/2. No difference of moments
    /// is formed (they would lose 1/s^2 to cancellation, 1e-11 at s = 1/200 in f64), and a
    /// value costs one logarithm and a short polynomial.
    fn xi_zz_series(&self, s: &T) -> Result<Estimate<T>> {
        let eps = s.epsilon().to_f64();
        let g = self.zz_series();
        let c1 = self.step_constant(g)?;
        let u = s.clone().sqr();
        // Horner in u over sum_k g_k e_k u^k
        let mut poly = s.zero();
        let mut mag = 0.0;
        for (k, gk) in g.iter().enumerate().rev() {
            // e_k = 1/(2k + 1) - 1/(4k + 4) - 1/(4k) = -1/(4k(k + 1)(2k + 1)), e_0 = 3/4:
            // exact integers, divided in T
            let kf = k as f64;
            let (num, den) = if k == 0 {
                (3.0, 4.0)
            } else {
                (-1.0, 4.0 * kf * (kf + 1.0) * (2.0 * kf + 1.0))
            };
            let term = gk.clone() * num / den;
            mag = mag * u.to_f64() + term.to_f64().abs();
            poly = poly * &u + &term;
        }
        let log = (c1.value.clone() - g[0].clone() * s.clone().ln()) / 2.0;
        let inner = log.clone() + &poly;
        let uf = u.to_f64();
        let err =
            uf * (c1.error / 2.0 + 8.0 * eps * (log.to_f64().abs() + mag) + series_tail(g, &u));
        Ok(Estimate {
            value: inner * &u,
            error: err,
            kind: complexfn::ErrorKind::Propagated,
        })
    }

    /// M_0(0) = Int_0^1 g ds, formed on first use (every corner and cell mean needs it).
    fn total_moment(&self, like: &T) -> Result<Triple<Estimate<T>>> {
        if let Some(t) = self.total.get() {
            return Ok(t.clone());
        }
        let t = self.moment(0, &like.zero())?;
        Ok(self.total.get_or_init(|| t).clone())
    }

    /// M_{-1}^zz(0) = Int_0^1 s g_zz ds, formed on first use.
    fn first_zz_total(&self, like: &T) -> Result<Estimate<T>> {
        if let Some(t) = self.moments.first_zz_total.get() {
            return Ok(t.clone());
        }
        let t = self.first_moment_zz(&like.zero())?;
        Ok(self.moments.first_zz_total.get_or_init(|| t).clone())
    }

    /// C_1 = lim_{s -> 0} (W_zz(s) + g_0 ln s), from the closed-form step response at s_R/2
    /// less the series' other terms there, formed on first use (`g` the Taylor coefficients
    /// of g_zz in s^2).
    fn step_constant(&self, g: &[T]) -> Result<Estimate<T>> {
        if let Some(c) = self.moments.step_constant.get() {
            return Ok(c.clone());
        }
        let at = self.s_r.clone() / 2.0;
        let eps = at.epsilon().to_f64();
        let w = self.moment(1, &at)?.zz;
        let u = at.clone().sqr();
        let mut sum = w.value.clone() + g[0].clone() * at.ln();
        let mut mag = sum.to_f64().abs();
        let mut uk = u.clone();
        for (k, gk) in g.iter().enumerate().skip(1) {
            let t = gk.clone() * &uk / (2 * k) as f64;
            mag += t.to_f64().abs();
            sum += &t;
            uk *= &u;
        }
        let c = Estimate {
            error: w.error + 8.0 * eps * mag + series_tail(g, &u),
            value: sum,
            kind: complexfn::ErrorKind::Propagated,
        };
        Ok(self.moments.step_constant.get_or_init(|| c).clone())
    }

    /// The displacement at (x, t) due to a unit load on `cell` with the given time shape
    /// (units c1 = 1, mu = 1): u_z from a normal load (`zz`), u_x from a normal load (`xz`),
    /// u_x from a tangential load (`xx`); u_z from a tangential load is `-xz`. Errors for an
    /// empty or reversed cell and for a corner on the Rayleigh ray.
    pub fn cell_response(
        &self,
        cell: &Cell<T>,
        shape: TimeShape,
        x: &T,
        t: &T,
    ) -> Result<Triple<Estimate<T>>> {
        let Cell { xa, xb, ta, tb } = cell;
        for (name, v) in [
            ("xa", xa),
            ("xb", xb),
            ("ta", ta),
            ("tb", tb),
            ("x", x),
            ("t", t),
        ] {
            if !v.is_finite() {
                return Err(invalid(name, short(v.to_f64()), "finite"));
            }
        }
        if !(xa < xb) {
            return Err(invalid(
                "strip [xa, xb]",
                format!("[{}, {}]", short(xa.to_f64()), short(xb.to_f64())),
                "xa < xb",
            ));
        }
        if !(ta < tb) {
            return Err(invalid(
                "load interval [ta, tb]",
                format!("[{}, {}]", short(ta.to_f64()), short(tb.to_f64())),
                "ta < tb",
            ));
        }
        let xs = [x.clone() - xb, x.clone() - xa];
        let ts = [t.clone() - tb, t.clone() - ta];
        let corners = |order: usize| -> Result<Triple<Estimate<T>>> {
            let mut acc = zero_triple(x);
            for (i, tt) in ts.iter().enumerate() {
                for (j, xx) in xs.iter().enumerate() {
                    let sign = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
                    add(&mut acc, self.space_time_primitive(order, xx, tt)?, sign);
                }
            }
            Ok(acc)
        };
        // corners (i, j): i = 1 is T = t - ta (upper), j = 1 is X = x - xa (upper):
        // Phi(X2, T2) - Phi(X1, T2) - Phi(X2, T1) + Phi(X1, T1): + for i + j even
        let phi = corners(1)?;
        match shape {
            TimeShape::Constant => Ok(phi),
            TimeShape::Linear => {
                let psi = corners(2)?;
                let lead = ts[1].clone();
                let dt = tb.clone() - ta;
                let comb = |p: Estimate<T>, q: Estimate<T>| Estimate {
                    value: (lead.clone() * &p.value - &q.value) / &dt,
                    error: (lead.to_f64().abs() * p.error + q.error) / dt.to_f64(),
                    kind: complexfn::ErrorKind::Propagated,
                };
                Ok(Triple {
                    zz: comb(phi.zz, psi.zz),
                    xz: comb(phi.xz, psi.xz),
                    xx: comb(phi.xx, psi.xx),
                })
            }
        }
    }
}

/// A bound of the truncation of the Taylor series of g_zz (coefficients `g`) at u
/// (<= s_R^2/4): the last term kept, times the geometric factor of terms falling at least like
/// 4^-k, times 2.
fn series_tail<T: Real>(g: &[T], u: &T) -> f64 {
    let last = g.len() - 1;
    4.0 * g[last].to_f64().abs() * u.to_f64().powi(last as i32)
}
