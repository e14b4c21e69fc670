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
        a.err += b.err;
    };
    f(&mut acc.zz, t.zz);
    f(&mut acc.xz, t.xz);
    f(&mut acc.xx, t.xx);
}

fn zero_triple<T: Real>(like: &T) -> Triple<Estimate<T>> {
    let z = || Estimate {
        value: like.zero(),
        err: 0.0,
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
        let total = match self.total.get() {
            Some(t) => t.clone(),
            None => {
                let t = self.moment(0, &s.zero())?;
                self.total.get_or_init(|| t).clone()
            }
        };
        let half = if order == 1 { 1.0 } else { 0.5 };
        if *s >= 1.0 {
            return Ok(total.map(|e| Estimate {
                value: e.value * half,
                err: e.err * half,
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
                err: half * (sn.to_f64() * b.err + t.err + a.err + 4.0 * eps * mag),
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
            err: e.err * scale.to_f64(),
        };
        Ok(Triple {
            zz: sc(prof.zz, odd),
            xz: sc(prof.xz, 1.0),
            xx: sc(prof.xx, odd),
        })
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
                    err: (lead.to_f64().abs() * p.err + q.err) / dt.to_f64(),
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
