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

use complexfn::Cx;

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
pub struct LocalSolution {
    /// The exponent lambda in (-1, 1).
    pub lambda: f64,
    /// G: the gap outside the contact grows like (c/mu) G x^(lambda + 1) (0 when the relation
    /// is local, D > c1: the gap then opens with the profile's own slope).
    pub gap_coefficient: f64,
    /// Whether a free edge admits it (c > 0 with a non-negative gap: G > 0, or a local
    /// relation).
    pub signorini_admissible: bool,
}

/// The local behaviour of the contact pressure at an edge moving at a given speed.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeBehaviour {
    /// D/c1.
    pub speed_over_c1: f64,
    /// The speed range.
    pub range: SpeedRange,
    /// The slope symbol S+ (units 1/mu), as (re, im).
    pub slope_symbol: (f64, f64),
    /// The admissible local solutions, exponents ascending.
    pub solutions: Vec<LocalSolution>,
    /// The law.
    pub law: EdgeLaw,
    /// The exponent the law selects.
    pub selected: f64,
    /// For D > c1: the edge pressure per unit profile slope at the edge, p(b) = f'(b) times
    /// this (units mu); `None` otherwise.
    pub jump_per_slope: Option<f64>,
}

/// Relative distance from c_R, c2 and c1 below which a speed is refused.
pub const SPEED_GUARD: f64 = 1e-9;

impl HalfPlane<f64> {
    /// The local behaviour of the contact pressure at an edge moving at D = `speed_over_c1`
    /// c1 (an expanding contact, frictionless), with the exponent `law` selects.
    /// `docs/edge.md`; the second paper's eqs (9)-(10).
    ///
    /// Errors: D not finite or D <= 0, and D within a relative 1e-9 of c_R, c2 or c1 (the
    /// exponents jump or the symbol is singular there).
    pub fn edge_behaviour(&self, speed_over_c1: f64, law: EdgeLaw) -> Result<EdgeBehaviour> {
        let d = speed_over_c1;
        let (m, sr) = (*self.m(), *self.s_r());
        let range_text = || {
            format!(
                "(0, inf) except c_R/c1 = {}, c2/c1 = {} and 1",
                short(sr),
                short(m)
            )
        };
        if !(d.is_finite() && d > 0.0) {
            return Err(invalid("speed_over_c1", short(d), range_text()));
        }
        if [sr, m, 1.0]
            .iter()
            .any(|c| (d - c).abs() <= SPEED_GUARD * c)
        {
            return Err(invalid("speed_over_c1", short(d), range_text()));
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
        let xi = Cx::new(1.0 / d, -1e-300);
        let kyy = Lamb::new(m).kernels(&xi)[0][0].clone();
        let s = -(xi * &kyy);
        // parts below rounding of |S+| are the trace of the side chosen, not of the physics
        let size = s.re.hypot(s.im);
        let clean = |v: f64| if v.abs() <= 1e-14 * size { 0.0 } else { v };
        let (re, im) = (clean(s.re), clean(s.im));
        if !(re.is_finite() && im.is_finite()) {
            return Err(invalid("speed_over_c1", short(d), range_text()));
        }
        let pi = std::f64::consts::PI;
        let local = im.abs() <= 1e-12 * re.abs();
        let solutions = if local {
            vec![LocalSolution {
                lambda: 0.0,
                gap_coefficient: 0.0,
                signorini_admissible: true,
            }]
        } else {
            let mut low = -im.atan2(re) / pi;
            while low >= 0.0 {
                low -= 1.0;
            }
            while low <= -1.0 {
                low += 1.0;
            }
            [low, low + 1.0]
                .into_iter()
                .map(|lambda| {
                    let g = im / ((lambda + 1.0) * (pi * lambda).sin());
                    LocalSolution {
                        lambda,
                        gap_coefficient: g,
                        signorini_admissible: g > 0.0,
                    }
                })
                .collect()
        };
        let selected = match law {
            EdgeLaw::Kinematic => solutions[0].lambda,
            EdgeLaw::Signorini => solutions
                .iter()
                .find(|s| s.signorini_admissible)
                .map(|s| s.lambda)
                .ok_or_else(|| invalid("speed_over_c1", short(d), range_text()))?,
        };
        Ok(EdgeBehaviour {
            speed_over_c1: d,
            range,
            slope_symbol: (re, im),
            solutions,
            law,
            selected,
            jump_per_slope: local.then(|| -1.0 / re),
        })
    }
}
