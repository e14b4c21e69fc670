//! The elastic half-space's axisymmetric surface response (Lamb's problem in three
//! dimensions, Pekeris' problem): the normal displacement of the surface due to a normal point
//! force that is a step in time, and its means over rings (`docs/half_space.md`).
//!
//! Units c1 = 1, mu = 1 as in [`crate::half_plane`]; m = c2/c1, s = rho/(c1 t) with rho the
//! distance from the force. A force P H(t) pushing into the medium gives the normal
//! displacement (into the medium)
//!
//! ```text
//!   u(rho, t) = P/(pi mu rho) V(s),
//!   V(s) = (1 - nu)/2                                             s < s_R (behind Rayleigh),
//!        = (1 - nu)/2 [1 - A_3/sqrt(x_3 - tau^2)]                  s_R < s < m,
//!        = (1 - nu)/4 [1 - sum_{j=1,2} A_j/sqrt(tau^2 - x_j) - A_3/sqrt(x_3 - tau^2)]
//!                                                                   m < s < 1,
//!        = 0                                                       s >= 1 (ahead of P),
//! ```
//!
//! with tau = c2 t/rho = m/s, x_j = 1/y_j the reciprocals of the roots y_j of the Rayleigh
//! cubic of [`HalfPlane`] (x_3 = (c2/c_R)^2 the Rayleigh root) and
//! A_j = (x_j - 1/2)^2 sqrt(a - x_j)/prod_{k != j}(x_j - x_k), a = m^2 (sqrt(x_3 - a) for
//! A_3). Behind the Rayleigh arrival the displacement is Boussinesq's static one; just ahead
//! of it V has an inverse square-root singularity. The derivation (Cagniard-de Hoop through
//! the plane-strain impulse response and an Abel inversion, then partial fractions) and the
//! second route are in `docs/half_space.md`, sections 1 and 2.
//!
//! Ring cells (section 3): the area mean over a receiving annulus of the displacement due to a
//! unit pressure on a source annulus is a single integral over the distance rho,
//!
//! ```text
//!   U(t) = (2/A_rec) Int_0^{min(c1 t, r_out + r'_out)} V(rho/t) L(rho) d rho,
//! ```
//!
//! L(rho) the area of the overlap of the receiving annulus with the source annulus shifted by
//! rho (four lens areas of pairs of disks), A_rec the receiver's area. The integral is split
//! at every point where V or L is not analytic (the three wavefronts rho = s_R t, m t, t and
//! the lens kinks |r - r'|, r + r'), each piece mapped by rho = l + (r - l)(1 - cos pi v)/2,
//! which makes the endpoints' square-root behaviours analytic, and summed by Gauss-Legendre
//! rules of 16 and 32 nodes (more at higher precision), the difference being the error
//! estimate; a piece that does not meet its tolerance is halved.

use complexfn::quadrature::{gauss_legendre_rule, CachedRules};
use complexfn::{Cx, ErrorKind, Estimate, NoConvergence, Real};

use crate::error::{invalid, short, LambError, Result};
use crate::half_plane::{HalfPlane, Spurious};

/// The non-Rayleigh terms of the closed form: (x_j, A_j, a - x_j), a = m^2 (the last formed
/// at the guard precision: near Poisson's ratio 0 a root lies just below a, and
/// tau^2 - x_j = ((a - x_j) + x_j (1 - s^2))/s^2 keeps its relative accuracy there).
#[derive(Clone, Debug)]
enum Terms<T> {
    /// Two real roots.
    Real([(T, T, T); 2]),
    /// A complex-conjugate pair (the member with Im x > 0), whose two terms are conjugate.
    Pair(Cx<T>, Cx<T>, Cx<T>),
}

/// An annulus inner <= r <= outer on the surface (inner = 0: a disk).
#[derive(Clone, Debug, PartialEq)]
pub struct Annulus<T> {
    /// Inner radius (>= 0).
    pub inner: T,
    /// Outer radius (> inner).
    pub outer: T,
}

impl<T: Real> Annulus<T> {
    /// The annulus inner <= r <= outer; 0 <= inner < outer, both finite.
    pub fn new(inner: T, outer: T) -> Result<Self> {
        if !inner.is_finite() || inner.is_sign_negative() && !(inner == 0.0) {
            return Err(invalid(
                "annulus inner radius",
                short(inner.to_f64()),
                "[0, outer radius)",
            ));
        }
        if !outer.is_finite() || !(outer > inner) {
            return Err(invalid(
                "annulus outer radius",
                short(outer.to_f64()),
                "(inner radius, infinity)",
            ));
        }
        Ok(Annulus { inner, outer })
    }

    /// The ring cell i of width dr: [(i - 1/2) dr, (i + 1/2) dr], the disk [0, dr/2] for i = 0.
    pub fn ring_cell(i: usize, dr: &T) -> Result<Self> {
        let outer = dr.clone() * (i as f64 + 0.5);
        let inner = if i == 0 {
            dr.zero()
        } else {
            dr.clone() * (i as f64 - 0.5)
        };
        Annulus::new(inner, outer)
    }

    /// The area pi (outer^2 - inner^2).
    pub fn area(&self) -> T {
        (self.outer.clone() - &self.inner) * (self.outer.clone() + &self.inner) * self.outer.pi()
    }
}

/// The area of the intersection of two disks of radii a, c (>= 0) whose centres are d apart,
/// and the size of the terms it is formed from (the scale of its rounding). Written with the
/// triangle's area (Heron) and two angles by atan2, free of the cancellation of arccos near
/// its ends.
fn lens<T: Real>(d: &T, a: &T, c: &T) -> (T, f64) {
    if *a == 0.0 || *c == 0.0 {
        return (d.zero(), 0.0);
    }
    let (small, large) = if a < c { (a, c) } else { (c, a) };
    if *d <= large.clone() - small {
        let v = small.clone().sqr() * d.pi();
        let size = v.to_f64();
        return (v, size);
    }
    if *d >= a.clone() + c {
        return (d.zero(), 0.0);
    }
    // 4 * (area of the triangle with sides a, c, d)
    let (sum, dif) = (a.clone() + c, a.clone() - c);
    let h =
        ((sum.clone() - d) * (d.clone() + &dif) * (d.clone() - &dif) * (d.clone() + &sum)).sqrt();
    // d^2 + a^2 - c^2 with a^2 - c^2 = (a - c)(a + c): for a ring with itself (a = c) d^2
    // is not lost to the rounding of a^2
    let d2 = d.clone().sqr();
    let diff = (a.clone() - c) * (a.clone() + c);
    let alpha = h.clone().atan2(&(d2.clone() + &diff));
    let gamma = h.clone().atan2(&(d2 - diff));
    let (ta, tc, th) = (a.clone().sqr() * alpha, c.clone().sqr() * gamma, h / 2.0);
    let size = ta.to_f64().abs() + tc.to_f64().abs() + th.to_f64().abs();
    (ta + tc - th, size)
}

/// The area of the overlap of annulus `r` with annulus `s` shifted by d, and the sum of the
/// magnitudes of its four lens areas (the scale of its rounding).
fn overlap<T: Real>(d: &T, r: &Annulus<T>, s: &Annulus<T>) -> (T, f64) {
    let parts = [
        lens(d, &r.outer, &s.outer),
        lens(d, &r.inner, &s.outer),
        lens(d, &r.outer, &s.inner),
        lens(d, &r.inner, &s.inner),
    ];
    let size = parts.iter().map(|p| p.1).sum();
    let [(a, _), (b, _), (c, _), (e, _)] = parts;
    (a - b - c + e, size)
}

/// An elastic half-space, units c1 = 1, mu = 1, at the precision of its m.
#[derive(Clone, Debug)]
pub struct HalfSpace<T> {
    plane: HalfPlane<T>,
    /// (1 - nu)/2, V behind the Rayleigh arrival.
    v_static: T,
    /// A_3, the Rayleigh term's coefficient.
    a3: T,
    terms: Terms<T>,
}

/// The constants of the closed form at the precision of `hp`: (x_3, A_3, the other terms).
fn closed_form_terms<T: Real>(hp: &HalfPlane<T>) -> (T, T, Terms<T>) {
    let a = hp.m2.clone();
    let half = a.lit(0.5);
    let x3 = hp.x_r.clone().recip();
    match &hp.spurious {
        Spurious::Real(yp, ym) => {
            let x1 = yp.clone().recip();
            let x2 = ym.clone().recip();
            let coef = |xj: &T, xk: &T| {
                (xj.clone() - &half).sqr() * (a.clone() - xj).sqrt()
                    / ((xj.clone() - xk) * (xj.clone() - &x3))
            };
            let a1 = coef(&x1, &x2);
            let a2 = coef(&x2, &x1);
            let a3 = (x3.clone() - &half).sqr() * (x3.clone() - &a).sqrt()
                / ((x3.clone() - &x1) * (x3.clone() - &x2));
            let (d1, d2) = (a.clone() - &x1, a.clone() - &x2);
            (x3, a3, Terms::Real([(x1, a1, d1), (x2, a2, d2)]))
        }
        Spurious::Pair(z) => {
            let w = z.clone().recip();
            let wc = w.clone().conj();
            let one = Cx::real(a.one());
            let sa = (one.clone().scale(&a) - &w).sqrt();
            let h = w.clone() - half.to_f64();
            let a1 =
                h.clone() * &h * &sa / ((w.clone() - &wc) * (w.clone() - Cx::real(x3.clone())));
            let d3 = Cx::real(x3.clone()) - &w;
            let a3 = (x3.clone() - &half).sqr() * (x3.clone() - &a).sqrt() / d3.norm_sqr();
            let d = Cx::real(a.clone()) - &w;
            (x3, a3, Terms::Pair(w, a1, d))
        }
    }
}

impl<T: Real + CachedRules> HalfSpace<T> {
    /// The half-space with speed ratio m = c2/c1 in (0, sqrt(3)/2), excluding the two values
    /// [`HalfPlane::new`] refuses (Poisson's ratio 0 and about 0.2631).
    pub fn new(m: T) -> Result<Self> {
        let plane = HalfPlane::new(m)?;
        let bits = plane.m.prec();
        let (a3, terms) = match &plane.guard {
            Some(g) => {
                let (_, a3, terms) = closed_form_terms(g);
                let r = |x: &rug::Float| T::from_mpfr(x, bits);
                let rc = |z: &Cx<rug::Float>| Cx::new(r(&z.re), r(&z.im));
                let terms = match terms {
                    Terms::Real([(x1, a1, d1), (x2, a2, d2)]) => {
                        Terms::Real([(r(&x1), r(&a1), r(&d1)), (r(&x2), r(&a2), r(&d2))])
                    }
                    Terms::Pair(w, a1, d) => Terms::Pair(rc(&w), rc(&a1), rc(&d)),
                };
                (r(&a3), terms)
            }
            None => {
                let (_, a3, terms) = closed_form_terms(&plane);
                (a3, terms)
            }
        };
        let v_static = (plane.m.one() - plane.poisson()) / 2.0;
        Ok(HalfSpace {
            plane,
            v_static,
            a3,
            terms,
        })
    }

    /// The half-space for Poisson's ratio nu in (-1, 1/2) (except 0 and about 0.2631).
    pub fn from_poisson(nu: T) -> Result<Self> {
        if !nu.is_finite() || !(nu > -1.0) || !(nu < 0.5) {
            return Err(invalid("Poisson's ratio", short(nu.to_f64()), "(-1, 1/2)"));
        }
        let one = nu.one();
        let m2 = (one.clone() - nu.clone() * 2.0) / ((one - &nu) * 2.0);
        HalfSpace::new(m2.sqrt())
    }

    /// The plane-strain half-plane of the same material.
    pub fn plane(&self) -> &HalfPlane<T> {
        &self.plane
    }

    /// m = c2/c1.
    pub fn m(&self) -> &T {
        &self.plane.m
    }

    /// s_R = c_R/c1.
    pub fn s_r(&self) -> &T {
        &self.plane.s_r
    }

    /// (1 - nu)/2: V behind the Rayleigh arrival (Boussinesq's static displacement,
    /// u = (1 - nu) P/(2 pi mu rho)).
    pub fn static_value(&self) -> &T {
        &self.v_static
    }

    /// V(s) of the point force's step response, u = P/(pi mu rho) V(s), s = rho/(c1 t) > 0
    /// (docs/half_space.md, eq (2.3)); an error at s = s_R, where V is singular.
    pub fn point_step(&self, s: &T) -> Result<T> {
        if !s.is_finite() || !(*s > 0.0) {
            return Err(invalid(
                "s = rho/(c1 t)",
                short(s.to_f64()),
                "(0, infinity)",
            ));
        }
        if *s == self.plane.s_r {
            return Err(self.plane.at_rayleigh("the half-space's point response V"));
        }
        let (v, _) = self.v_unchecked(s, None);
        if !v.is_finite() {
            return Err(LambError::NotFinite {
                quantity: "the half-space's point response V",
                s: short(s.to_f64()),
            });
        }
        Ok(v)
    }

    /// V(s) without the checks (s > 0, s != s_R), and the size of the terms it cancelled (the
    /// scale of its rounding); `past_rayleigh`, when given, is s - s_R known to full
    /// relative accuracy (a quadrature node's distance from the Rayleigh arrival, which
    /// s - s_R would lose to rounding).
    fn v_unchecked(&self, s: &T, past_rayleigh: Option<&T>) -> (T, f64) {
        if *s >= 1.0 {
            return (s.zero(), 0.0);
        }
        let sr = &self.plane.s_r;
        let v0 = self.v_static.to_f64();
        if s < sr || past_rayleigh.is_none() && s == sr {
            return (self.v_static.clone(), v0);
        }
        let m2 = &self.plane.m2;
        // x_3 - tau^2 = m^2 (s - s_R)(s + s_R)/(s_R^2 s^2), free of cancellation at s_R
        let s2 = s.clone().sqr();
        let ds = match past_rayleigh {
            Some(d) => d.clone(),
            None => s.clone() - sr,
        };
        let gap3 = m2.clone() * ds * (s.clone() + sr) / (sr.clone().sqr() * &s2);
        let rayleigh = self.a3.clone() / gap3.sqrt();
        let size = v0 * (1.0 + rayleigh.to_f64().abs());
        if *s < self.plane.m {
            return (self.v_static.clone() * (s.one() - rayleigh), size);
        }
        // tau^2 - x_j = ((a - x_j) + x_j (1 - s)(1 + s))/s^2
        let q = (s.one() - s) * (s.clone() + 1.0);
        let (others, osize) = match &self.terms {
            Terms::Real(t) => t.iter().fold((s.zero(), 0.0), |(acc, sz), (x, a, d)| {
                let term = a.clone() * s / (d.clone() + x.clone() * &q).sqrt();
                let tf = term.to_f64().abs();
                (acc + term, sz + tf)
            }),
            Terms::Pair(w, a1, d) => {
                let g = (d.clone() + w.clone().scale(&q)).sqrt();
                let term = (a1.clone() / g).scale(s);
                let tf = term.abs().to_f64() * 2.0;
                (term.re * 2.0, tf)
            }
        };
        let value = self.v_static.clone() * (s.one() - others - rayleigh) / 2.0;
        (value, (size + v0 * osize) / 2.0)
    }

    /// The point force's radiation constant E_F (docs/half_space.md, section 5): a normal
    /// force F(t) on the surface, slow against the waves' transit over its footprint,
    /// radiates the energy E_F Int (dF/dt)^2 dt (the first order of Miller and Pursey's
    /// radiation), E_F = (1/(pi mu c1)) [V_static + Int_{s_R}^1 (V_static - V(s))/s^2 ds],
    /// the time integral of the static displacement's excess over the step response at the
    /// loaded point. Units mu = c1 = 1.
    pub fn radiation_constant(&self) -> Result<Estimate<T>> {
        let sr = &self.plane.s_r;
        let one = sr.one();
        let cuts = vec![sr.clone(), self.plane.m.clone(), one.clone()];
        let (j, err) = integrate(cuts, &one, |s, left| {
            let past = match left {
                Some((l, off)) if *l == *sr => Some(off),
                _ => None,
            };
            let (v, size) = self.v_unchecked(s, past);
            let s2 = s.clone().sqr();
            let d = (self.v_static.clone() - v) / &s2;
            let sz = (size + self.v_static.to_f64()) / s2.to_f64();
            (d, sz)
        })?;
        let pi = one.pi();
        let value = (j + &self.v_static) / &pi;
        let error = err / pi.to_f64();
        if !value.is_finite() {
            return Err(LambError::NotFinite {
                quantity: "the point force's radiation constant",
                s: short(sr.to_f64()),
            });
        }
        Ok(Estimate::new(value, error, ErrorKind::Quadrature))
    }

    /// The static (Boussinesq) ring response, the limit of [`HalfSpace::ring_step`] for
    /// t -> infinity, reached exactly once s_R t >= receiver.outer + source.outer
    /// (docs/half_space.md, eq (3.3)).
    pub fn ring_static(&self, receiver: &Annulus<T>, source: &Annulus<T>) -> Result<Estimate<T>> {
        let like = &receiver.outer;
        let reach = receiver.outer.clone() + &source.outer;
        let mut cuts = lens_cuts(receiver, source, &like.one());
        cuts.push(like.zero());
        cuts.push(reach.clone());
        let q = integrate(cuts, &reach, |rho, _| {
            let (l, size) = overlap(rho, receiver, source);
            (l * &self.v_static, size * self.v_static.to_f64())
        })?;
        self.to_mean(q, receiver)
    }

    /// The area mean over `receiver` at time t (c1 t, in the annuli's length unit) of the
    /// displacement due to a unit pressure on `source` applied as a step at time 0
    /// (docs/half_space.md, eq (3.2)); mu = 1.
    pub fn ring_step(
        &self,
        receiver: &Annulus<T>,
        source: &Annulus<T>,
        t: &T,
    ) -> Result<Estimate<T>> {
        if !t.is_finite() || t.is_sign_negative() {
            return Err(invalid("c1 t", short(t.to_f64()), "[0, infinity)"));
        }
        if *t == 0.0 {
            return Ok(Estimate::new(t.zero(), 0.0, ErrorKind::Rounding));
        }
        let q = self.at_time(receiver, source, t, &t.zero())?;
        self.to_mean(q, receiver)
    }

    /// U(t1) - U(t0) of [`HalfSpace::ring_step`] (0 <= t0 < t1): the displacement at t1 due to
    /// a unit pressure on `source` during (0, t1 - t0], the pulse of a time-marching solver's
    /// cell. The distances behind the Rayleigh arrival of t0, where both responses are
    /// static, are left out of both integrals; the pulse is exactly zero once
    /// s_R t0 >= receiver.outer + source.outer.
    pub fn ring_pulse(
        &self,
        receiver: &Annulus<T>,
        source: &Annulus<T>,
        t0: &T,
        t1: &T,
    ) -> Result<Estimate<T>> {
        if !t0.is_finite() || t0.is_sign_negative() {
            return Err(invalid("c1 t0", short(t0.to_f64()), "[0, c1 t1)"));
        }
        if !t1.is_finite() || !(t1 > t0) {
            return Err(invalid("c1 t1", short(t1.to_f64()), "(c1 t0, infinity)"));
        }
        let reach = receiver.outer.clone() + &source.outer;
        let from = self.plane.s_r.clone() * t0;
        if from >= reach {
            return Ok(Estimate::new(t0.zero(), 0.0, ErrorKind::Rounding));
        }
        let late = self.at_time(receiver, source, t1, &from)?;
        if *t0 == 0.0 {
            return self.to_mean(late, receiver);
        }
        let early = self.at_time(receiver, source, t0, &from)?;
        self.to_mean((late.0 - early.0, late.1 + early.1), receiver)
    }

    /// Int_from^{min(reach, t)} V(rho/t) L(rho) d rho, integrated in s = rho/t (so that the
    /// wavefronts s_R, m, 1 are exact cuts and the Rayleigh singularity is met with the
    /// nodes' exact distances from it); `from` is 0 or s_R t0 <= s_R t.
    fn at_time(
        &self,
        receiver: &Annulus<T>,
        source: &Annulus<T>,
        t: &T,
        from: &T,
    ) -> Result<(T, f64)> {
        let reach = receiver.outer.clone() + &source.outer;
        let sr = &self.plane.s_r;
        let end = (reach / t).min(t.one());
        // from = s_R t exactly when it is t0's own Rayleigh distance
        let start = if *from == sr.clone() * t {
            sr.clone()
        } else {
            from.clone() / t
        };
        if !(end > start) {
            return Ok((t.zero(), 0.0));
        }
        let mut cuts = lens_cuts(receiver, source, t);
        cuts.extend([start.clone(), end.clone(), sr.clone(), self.plane.m.clone()]);
        cuts.retain(|c| *c >= start);
        let q = integrate(cuts, &end, |s, left| {
            let past = match left {
                Some((l, off)) if *l == *sr => Some(off),
                _ => None,
            };
            let (v, vsize) = self.v_unchecked(s, past);
            if v == 0.0 {
                return (v, 0.0);
            }
            let (l, lsize) = overlap(&(s.clone() * t), receiver, source);
            let tf = t.to_f64();
            let sz = (lsize * v.to_f64().abs() + l.to_f64().abs() * vsize) * tf;
            (l * v * t, sz)
        })?;
        Ok(q)
    }

    /// (2/A_rec) times an integral with its error.
    fn to_mean(&self, q: (T, f64), receiver: &Annulus<T>) -> Result<Estimate<T>> {
        let scale = receiver.outer.lit(2.0) / receiver.area();
        let value = q.0 * &scale;
        let error = q.1 * scale.to_f64();
        if !value.is_finite() || !error.is_finite() {
            return Err(LambError::NotFinite {
                quantity: "the half-space's ring response",
                s: short(receiver.outer.to_f64()),
            });
        }
        Ok(Estimate::new(value, error, ErrorKind::Quadrature))
    }
}

/// The distances |r - r'| and r + r' (over `unit`) of the pairs of nonzero radii, where the
/// overlap of the two annuli is not analytic.
fn lens_cuts<T: Real>(receiver: &Annulus<T>, source: &Annulus<T>, unit: &T) -> Vec<T> {
    let mut cuts = Vec::with_capacity(10);
    for r in [&receiver.inner, &receiver.outer] {
        for s in [&source.inner, &source.outer] {
            if *r == 0.0 || *s == 0.0 {
                continue;
            }
            cuts.push((r.clone() - s).abs() / unit);
            cuts.push((r.clone() + s) / unit);
        }
    }
    cuts
}

/// The sum of [`piece`] over the intervals between the sorted `cuts` up to `end`.
fn integrate<T: Real + CachedRules>(
    mut cuts: Vec<T>,
    end: &T,
    f: impl Fn(&T, Option<(&T, &T)>) -> (T, f64),
) -> Result<(T, f64)> {
    cuts.retain(|c| c <= end);
    cuts.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    cuts.dedup_by(|a, b| *a == *b);
    let bits = end.prec();
    let tol = (f64::from(bits) * -std::f64::consts::LN_2).exp() * 64.0;
    let mut value = end.zero();
    let mut error = 0.0;
    for w in cuts.windows(2) {
        let (q, e) = piece(&w[0], &w[1], tol, &f)?;
        value += q;
        error += e;
    }
    Ok((value, error))
}

/// The halving depth after which a piece is accepted at [`STAGNANT_UNITS`] (its difference
/// its error).
const STAGNANT_DEPTH: usize = 12;

/// The relative difference of the two rules accepted on a piece halved [`STAGNANT_DEPTH`]
/// times, in units of the working precision (counted in the error estimate).
const STAGNANT_UNITS: f64 = 1e4;

/// Int_l^r f by Gauss-Legendre rules in v, x = l + (r - l)(1 - cos pi v)/2 (square-root
/// behaviours at the ends become analytic), n and 2n nodes, halving the piece until
/// |Q_2n - Q_n| <= tol Int |f| or the rounding of the terms. f gets the node and, on the
/// piece that starts at l, (l, x - l) with x - l to full relative accuracy; it returns its
/// value and the magnitude of the terms it cancelled. Returns (Q_2n, its error: the
/// differences and the rounding).
fn piece<T: Real + CachedRules>(
    l: &T,
    r: &T,
    tol: f64,
    f: &impl Fn(&T, Option<(&T, &T)>) -> (T, f64),
) -> Result<(T, f64)> {
    let bits = l.prec();
    let n = if bits <= 53 {
        16
    } else {
        8 * (bits as usize / 26).max(4)
    };
    let lo = gauss_legendre_rule::<T>(n, bits)?;
    let hi = gauss_legendre_rule::<T>(2 * n, bits)?;
    let mut stack = vec![(l.clone(), r.clone(), 0usize)];
    let mut total = l.zero();
    let mut error = 0.0;
    let quarter_pi = l.pi() / 4.0;
    let unit = f64::EPSILON.max((f64::from(bits) * -std::f64::consts::LN_2).exp());
    while let Some((a, b, depth)) = stack.pop() {
        if !(b > a) {
            continue;
        }
        let width = b.clone() - &a;
        let at_start = a == *l;
        let rule = |nodes: &[(T, T)]| -> (T, f64, f64) {
            let mut q = a.zero();
            let mut abs = 0.0;
            let mut size = 0.0;
            for (x, w) in nodes {
                // v = (x + 1)/2; x - a = width sin^2(pi v/2), dx/dv = width pi sin(pi v)/2
                let (sh, ch) = (quarter_pi.clone() * (x.clone() + 1.0)).sin_cos();
                let off = width.clone() * sh.clone().sqr();
                let node = a.clone() + &off;
                let scale = width.clone() * &quarter_pi * (sh * ch) * 2.0 * w;
                let (v, sz) = if at_start {
                    f(&node, Some((&a, &off)))
                } else {
                    f(&node, None)
                };
                let term = v * &scale;
                let scale = scale.to_f64().abs();
                abs += term.to_f64().abs();
                size += sz * scale;
                q += term;
            }
            (q, abs, size)
        };
        let (q1, _, _) = rule(&lo);
        let (q2, abs, size) = rule(&hi);
        let diff = (q2.clone() - q1).abs().to_f64();
        let floor = 16.0 * unit * size;
        let ok = diff <= (tol * abs).max(floor) || diff <= f64::MIN_POSITIVE;
        // a piece whose rules stop agreeing better under halving is at the rounding of its
        // node positions (a lens kink far out, where rho = s t carries rho's rounding): its
        // difference is then its honest error, accepted below STAGNANT_UNITS
        let stagnant = depth >= STAGNANT_DEPTH && diff <= STAGNANT_UNITS * unit * abs;
        if ok || stagnant || depth >= 40 {
            if !ok && !stagnant {
                return Err(LambError::Complex(
                    NoConvergence {
                        what: "the half-space's ring response (a piece of the distance integral)"
                            .into(),
                        reached: diff / abs.max(f64::MIN_POSITIVE),
                        asked: tol,
                    }
                    .into(),
                ));
            }
            total += q2;
            error += diff + floor;
            continue;
        }
        let mid = a.clone() + width / 2.0;
        stack.push((a, mid.clone(), depth + 1));
        stack.push((mid, b, depth + 1));
    }
    Ok((total, error))
}
