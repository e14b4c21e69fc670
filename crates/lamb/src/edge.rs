//! The contact pressure at a contact edge moving along the surface: its local power law
//! p ~ c d^lambda (d the distance from the edge into the contact) against the edge speed D,
//! for a frictionless contact (the second reference paper's eqs (9)-(10); derivation and
//! literature in `docs/edge.md`).
//!
//! In the frame of an edge moving steadily at speed D > 0 with the contact behind it (an
//! expanding contact), a pressure p(x - D t) gives the surface slope w' (w the normal
//! displacement, into the medium) through a symbol homogeneous of degree 0:
//! (w')^ = S(kappa) p^, S = S+ for kappa > 0, S- = conj(S+) for kappa < 0, with
//! S+ = -xi K_yy(xi - i0)/mu at the slowness xi = c1/D ([`crate::transform`], units c1 = 1).
//! In x: `w' = Re(S+) p - Im(S+) H[p]`, H the Hilbert transform. A local solution c d^lambda
//! keeps the slope smooth inside the contact exactly when e^{2 pi i lambda} = S-/S+, i.e.
//! lambda = -arg(S+)/pi (mod 1): two exponents in (-1, 1) while Im S+ != 0, the single
//! exponent 0 (a finite jump) when the relation is local (D > c1). Outside the contact the
//! gap between the striker and the surface then grows like (c/mu) G x^(lambda + 1),
//! G = Im(S+)/((lambda + 1) sin(pi lambda)); a free edge under the Signorini conditions
//! (c > 0, gap >= 0) admits exactly the exponent with G > 0, a prescribed edge (the paper's
//! eq (4)) the lower one.
//!
//! These are local laws. Whether a whole contact with such an edge exists is a global
//! question: between c_R and c1 the Rayleigh points lie inside the contact, and a prescribed
//! edge moving steadily there has no solution (the self-similar wedge, `docs/edge.md`,
//! section 5), while a free edge does.

use complexfn::{Cx, Real};

use crate::error::{invalid, short, Result};
use crate::half_plane::HalfPlane;
use crate::transform::Lamb;

/// Where the edge speed lies among the wave speeds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpeedRange {
    /// 0 < D < c_R.
    SubRayleigh,
    /// c_R < D < c2.
    RayleighShear,
    /// c2 < D < c1.
    Transonic,
    /// D > c1.
    Supersonic,
}

impl SpeedRange {
    /// `sub-rayleigh`, `rayleigh-shear`, `transonic` or `supersonic`.
    pub fn name(self) -> &'static str {
        match self {
            SpeedRange::SubRayleigh => "sub-rayleigh",
            SpeedRange::RayleighShear => "rayleigh-shear",
            SpeedRange::Transonic => "transonic",
            SpeedRange::Supersonic => "supersonic",
        }
    }
}

/// The law that fixes the contact edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EdgeLaw {
    /// The second paper's eq (4): the edge where the undeformed profile meets the undeformed
    /// surface, f(b) = h (a prescribed edge).
    Kinematic,
    /// The unilateral conditions: pressure >= 0 on the contact, no interpenetration outside
    /// it (a free edge).
    Signorini,
}

impl EdgeLaw {
    /// `kinematic` or `signorini`.
    pub fn name(self) -> &'static str {
        match self {
            EdgeLaw::Kinematic => "kinematic",
            EdgeLaw::Signorini => "signorini",
        }
    }
}

/// One local solution p ~ c d^lambda at the edge.
#[derive(Clone, Debug, PartialEq)]
pub struct LocalSolution<T = f64> {
    /// The exponent lambda in (-1, 1).
    pub lambda: T,
    /// G: the gap outside the contact grows like (c/mu) G x^(lambda + 1) (0 when the relation
    /// is local, D > c1: the gap then opens with the profile's own slope).
    pub gap_coefficient: T,
    /// Whether a free edge admits it (c > 0 with a non-negative gap: G > 0, or a local
    /// relation).
    pub signorini_admissible: bool,
}

/// The local behaviour of the contact pressure at an edge moving at a given speed.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeBehaviour<T = f64> {
    /// D/c1.
    pub speed_over_c1: T,
    /// The speed range.
    pub range: SpeedRange,
    /// The slope symbol S+ (units 1/mu), as (re, im).
    pub slope_symbol: (T, T),
    /// The admissible local solutions, exponents ascending.
    pub solutions: Vec<LocalSolution<T>>,
    /// The law.
    pub law: EdgeLaw,
    /// The exponent the law selects.
    pub selected: T,
    /// For D > c1: the edge pressure per unit profile slope at the edge, p(b) = f'(b) times
    /// this (units mu); `None` otherwise.
    pub jump_per_slope: Option<T>,
}

/// Relative distance from c_R, c2 and c1 below which a speed is refused.
pub const SPEED_GUARD: f64 = 1e-9;

impl<T: Real> HalfPlane<T> {
    /// The local behaviour of the contact pressure at an edge moving at D = `speed_over_c1`
    /// c1 (an expanding contact, frictionless), with the exponent `law` selects, at the
    /// half-plane's precision. `docs/edge.md`; the second paper's eqs (9)-(10).
    ///
    /// Errors: D not finite or D <= 0, and D within a relative 1e-9 of c_R, c2 or c1 (the
    /// exponents jump or the symbol is singular there).
    pub fn edge_behaviour(&self, speed_over_c1: T, law: EdgeLaw) -> Result<EdgeBehaviour<T>> {
        let d = speed_over_c1;
        let (m, sr) = (self.m().clone(), self.s_r().clone());
        let range_text = || {
            format!(
                "(0, inf) except c_R/c1 = {}, c2/c1 = {} and 1",
                short(sr.to_f64()),
                short(m.to_f64())
            )
        };
        let refuse = |d: &T| invalid("speed_over_c1", short(d.to_f64()), range_text());
        if !(d.is_finite() && d > 0.0) {
            return Err(refuse(&d));
        }
        let one = d.one();
        if [&sr, &m, &one]
            .iter()
            .any(|c| (d.clone() - *c).abs() <= (*c).clone() * SPEED_GUARD)
        {
            return Err(refuse(&d));
        }
        let range = if d < sr {
            SpeedRange::SubRayleigh
        } else if d < m {
            SpeedRange::RayleighShear
        } else if d < 1.0 {
            SpeedRange::Transonic
        } else {
            SpeedRange::Supersonic
        };
        // S+ = -xi K_yy(xi - i0): the imaginary part of xi only picks the side of the cuts
        let xi = Cx::new(one.clone() / &d, d.lit(-1e-300));
        let kyy = Lamb::new(m.clone()).kernels(&xi)[0][0].clone();
        let s = -(xi * &kyy);
        // parts below rounding of |S+| are the trace of the side chosen, not of the physics
        // (the thresholds relative to the precision: 1e-14 and 1e-12 in f64)
        let rel = d.epsilon().to_f64() / f64::EPSILON;
        let size = s.re.clone().hypot(&s.im);
        let clean = |v: T| {
            if v.clone().abs() <= size.clone() * (1e-14 * rel) {
                v.zero()
            } else {
                v
            }
        };
        let (re, im) = (clean(s.re.clone()), clean(s.im.clone()));
        if !(re.is_finite() && im.is_finite()) {
            return Err(refuse(&d));
        }
        let pi = d.pi();
        let local = im.clone().abs() <= re.clone().abs() * (1e-12 * rel);
        let solutions = if local {
            vec![LocalSolution {
                lambda: d.zero(),
                gap_coefficient: d.zero(),
                signorini_admissible: true,
            }]
        } else {
            let mut low = -(im.clone().atan2(&re) / &pi);
            while low >= 0.0 {
                low -= 1.0;
            }
            while low <= -1.0 {
                low += 1.0;
            }
            [low.clone(), low + 1.0]
                .into_iter()
                .map(|lambda| {
                    let g = im.clone() / ((lambda.clone() + 1.0) * (pi.clone() * &lambda).sin());
                    LocalSolution {
                        signorini_admissible: g > 0.0,
                        lambda,
                        gap_coefficient: g,
                    }
                })
                .collect::<Vec<_>>()
        };
        let selected = match law {
            EdgeLaw::Kinematic => solutions[0].lambda.clone(),
            EdgeLaw::Signorini => solutions
                .iter()
                .find(|s| s.signorini_admissible)
                .map(|s| s.lambda.clone())
                .ok_or_else(|| refuse(&d))?,
        };
        Ok(EdgeBehaviour {
            range,
            slope_symbol: (re.clone(), im),
            solutions,
            law,
            selected,
            jump_per_slope: local.then(|| -(one / &re)),
            speed_over_c1: d,
        })
    }
}
