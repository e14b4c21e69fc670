//! Input parameters: material, indenter geometry and friction, solution variant.
//!
//! Inputs are kept as the decimal numbers the caller gave (shortest round-trip form of an
//! `f64`, or a string), and converted to the working precision only when a case is built,
//! so that 1870.83 means the decimal 1870.83 at 300 bits, not its nearest double.

use complexfn::Real;

use crate::error::{invalid, Result};

/// A real input parameter: its decimal text and its nearest double.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    text: String,
    value: f64,
}

impl Param {
    /// From a double (its shortest round-trip decimal is kept as the text).
    pub fn from_f64(x: f64) -> Self {
        Param {
            text: format!("{x}"),
            value: x,
        }
    }
    /// From decimal text; `name` goes into the error message if it does not parse or is not
    /// finite.
    pub fn parse(name: &'static str, s: &str) -> Result<Self> {
        let value: f64 = s
            .trim()
            .parse()
            .map_err(|_| invalid(name, s, "a finite decimal number"))?;
        if !value.is_finite() {
            return Err(invalid(name, s, "a finite decimal number"));
        }
        Ok(Param {
            text: s.trim().to_string(),
            value,
        })
    }
    /// The nearest double.
    pub fn value(&self) -> f64 {
        self.value
    }
    /// The decimal text.
    pub fn text(&self) -> &str {
        &self.text
    }
    /// The value at the precision of `like` (parsed from the decimal text).
    pub fn to_real<T: Real>(&self, like: &T) -> T {
        T::parse_prec(&self.text, like.prec()).unwrap_or_else(|_| like.lit(self.value))
    }
}

/// Digits kept of c1 computed from Poisson's ratio (above the 2000 digits the command line
/// accepts), and the bits they are computed with.
const POISSON_DIGITS: usize = 2100;
const POISSON_BITS: u32 = 7200;

impl From<f64> for Param {
    fn from(x: f64) -> Self {
        Param::from_f64(x)
    }
}

/// Wave speeds of the elastic half-plane (plane strain), in m/s.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    c1: Param,
    c2: Param,
}

impl Material {
    /// Dilatational speed `c1` and shear speed `c2` (m/s): both finite and positive, and
    /// c2 < c1 sqrt(3)/2 (Poisson's ratio above -1).
    pub fn new(c1: impl Into<Param>, c2: impl Into<Param>) -> Result<Self> {
        let (c1, c2) = (c1.into(), c2.into());
        if !(c1.value.is_finite() && c1.value > 0.0) {
            return Err(invalid("c1", c1.text(), "(0, inf) m/s"));
        }
        let lim = c1.value * 0.75_f64.sqrt();
        if !(c2.value.is_finite() && c2.value > 0.0 && c2.value < lim) {
            return Err(invalid(
                "c2",
                c2.text(),
                format!("(0, c1 sqrt(3)/2) = (0, {lim}) m/s"),
            ));
        }
        Ok(Material { c1, c2 })
    }

    /// From Poisson's ratio nu in (-1, 1/2) and the shear speed c2 (m/s):
    /// (c1/c2)^2 = 2 (1 - nu)/(1 - 2 nu).
    pub fn from_poisson(nu: impl Into<Param>, c2: impl Into<Param>) -> Result<Self> {
        let nu: Param = nu.into();
        let v = nu.value;
        if !(v.is_finite() && v > -1.0 && v < 0.5) {
            return Err(invalid("poisson", nu.text(), "(-1, 0.5)"));
        }
        let c2 = c2.into();
        if !(c2.value.is_finite() && c2.value > 0.0) {
            return Err(invalid("c2", c2.text(), "(0, inf) m/s"));
        }
        // c1 = c2 (2 (1 - nu)/(1 - 2 nu))^(1/2) from the decimal texts, kept to
        // POISSON_DIGITS digits (beyond any working precision the library accepts)
        let like = rug::Float::with_val(POISSON_BITS, 0);
        let n: rug::Float = nu.to_real(&like);
        let one = rug::Float::with_val(POISSON_BITS, 1);
        let ratio = rug::Float::with_val(POISSON_BITS, &one - &n) * 2u32
            / rug::Float::with_val(
                POISSON_BITS,
                &one - rug::Float::with_val(POISSON_BITS, &n * 2u32),
            );
        let c1 = c2.to_real(&like) * ratio.sqrt();
        let text = c1.to_string_radix(10, Some(POISSON_DIGITS));
        Material::new(Param::parse("c1", &text)?, c2)
    }

    /// The reference paper's material: c1 = 1870.83 m/s, c2 = 1000 m/s (c_R = 927.41 m/s).
    pub fn paper() -> Self {
        Material::new(1870.83, 1000.0).expect("valid")
    }
    /// c1 in m/s.
    pub fn c1(&self) -> &Param {
        &self.c1
    }
    /// c2 in m/s.
    pub fn c2(&self) -> &Param {
        &self.c2
    }
    /// p = alpha/c1 at the precision of `like` for a contact-zone speed `alpha` (m/s, decimal
    /// text parsed at that precision): the one check of the admissible range 0 < alpha < c_R
    /// (decided in f64; the construction at the working precision checks p < m_R again).
    pub fn p_of_alpha<T: Real>(&self, alpha: &Param, like: &T) -> Result<T> {
        let c_r = self.m_r()? * self.c1.value;
        let av = alpha.value;
        if !(av.is_finite() && av > 0.0 && av < c_r) {
            return Err(invalid(
                "alpha",
                format!("{} m/s", alpha.text()),
                format!("(0, c_R) = (0, {c_r:.6}) m/s"),
            ));
        }
        Ok(alpha.to_real(like) / self.c1.to_real(like))
    }

    /// m = c2/c1 at the precision of `like`.
    pub fn m<T: Real>(&self, like: &T) -> T {
        self.c2.to_real(like) / self.c1.to_real(like)
    }
    /// m_R = c_R/c1 in f64 (the Rayleigh root of m = c2/c1; [`complexfn::Rayleigh`] gives it
    /// at any precision).
    pub fn m_r(&self) -> Result<f64> {
        Ok(*complexfn::Rayleigh::new(self.m(&0.0_f64))?.m_r())
    }
    /// Poisson's ratio nu = (1 - 2 m^2)/(2 (1 - m^2)).
    pub fn poisson(&self) -> f64 {
        let m2 = (self.c2.value / self.c1.value).powi(2);
        (1.0 - 2.0 * m2) / (2.0 * (1.0 - m2))
    }
}

/// Whether the tangential surface displacement enters the contact condition (7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Coupling {
    /// beta = -cot Theta (the paper's coupled formulation).
    On,
    /// beta = 0 (the classical formulation).
    Off,
}

impl Coupling {
    /// The name the command line and the outputs use: `on` or `off`.
    pub fn name(self) -> &'static str {
        match self {
            Coupling::On => "on",
            Coupling::Off => "off",
        }
    }
}

/// The rigid wedge: half-angle Theta (degrees, in (0, 90)), Coulomb friction gamma >= 0,
/// and the coupling of eq (7).
#[derive(Clone, Debug, PartialEq)]
pub struct Indenter {
    theta_deg: Param,
    gamma: Param,
    coupling: Coupling,
    /// cot Theta correctly rounded to f64 (formed once: the f64 path asks for it per case).
    cot_f64: f64,
}

impl Indenter {
    /// Half-angle in degrees (0 < Theta < 90), friction coefficient gamma (finite, >= 0).
    pub fn new(
        theta_deg: impl Into<Param>,
        gamma: impl Into<Param>,
        coupling: Coupling,
    ) -> Result<Self> {
        let (theta_deg, gamma) = (theta_deg.into(), gamma.into());
        if !(theta_deg.value.is_finite() && theta_deg.value > 0.0 && theta_deg.value < 90.0) {
            return Err(invalid("theta_deg", theta_deg.text(), "(0, 90) degrees"));
        }
        if !(gamma.value.is_finite() && gamma.value >= 0.0) {
            return Err(invalid("gamma", gamma.text(), "[0, inf)"));
        }
        let cot_f64 = cot_theta_mpfr(&theta_deg, 53).to_f64();
        Ok(Indenter {
            theta_deg,
            gamma,
            coupling,
            cot_f64,
        })
    }
    /// The classical indenter: frictionless and uncoupled (Theta enters only through the
    /// normalisation by cot Theta).
    pub fn classical(theta_deg: impl Into<Param>) -> Result<Self> {
        Indenter::new(theta_deg, 0.0, Coupling::Off)
    }
    /// Half-angle in degrees.
    pub fn theta_deg(&self) -> &Param {
        &self.theta_deg
    }
    /// Friction coefficient.
    pub fn gamma(&self) -> &Param {
        &self.gamma
    }
    /// Coupling.
    pub fn coupling(&self) -> Coupling {
        self.coupling
    }
    /// cot Theta at the precision of `like`, correctly rounded for the decimal angle given:
    /// computed from the decimal text with 64 extra bits, as tan((90 - Theta) pi/180) for
    /// Theta >= 45 degrees, so that Theta close to 90 degrees (cot Theta -> 0) keeps full
    /// relative accuracy in f64 too, and as 1/tan(Theta pi/180) below, so that a sharp wedge
    /// (cot Theta -> inf) does too: 90 - Theta would lose the digits of a small Theta.
    pub fn cot_theta<T: Real>(&self, like: &T) -> T {
        if like.prec() <= 53 {
            return T::from_f64_prec(self.cot_f64, like.prec());
        }
        T::from_mpfr(&cot_theta_mpfr(&self.theta_deg, like.prec()), like.prec())
    }
}

/// cot Theta from the decimal angle, with 64 bits beyond `bits`: tan((90 - Theta) pi/180)
/// for Theta >= 45 degrees, 1/tan(Theta pi/180) below (each argument without cancellation).
fn cot_theta_mpfr(theta_deg: &Param, bits: u32) -> rug::Float {
    let bits = bits.max(53) + 64;
    let th = theta_deg.to_real(&rug::Float::with_val(bits, 0));
    let pi = rug::Float::with_val(bits, rug::float::Constant::Pi);
    if th >= 45 {
        let comp: rug::Float = (rug::Float::with_val(bits, 90) - th) * pi / 180.0;
        comp.tan()
    } else {
        let rad: rug::Float = th * pi / 180.0;
        rad.tan().recip()
    }
}

/// Which solution of the problem a result belongs to; named in every output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Solution {
    /// The paper's construction (23), (39) with the displacement matching (53)-(57) taken
    /// exactly as printed: principal values only (no Rayleigh-pole terms), |p_k| read in
    /// (56b), (57b). Reproduces the printed curves.
    AsPrinted,
    /// The paper's construction made consistent: the matching includes the Rayleigh-pole
    /// terms, so (7) holds in the paper's representation (18). Genuine when gamma = 0; carries
    /// a tangential dislocation at the apex when gamma > 0.
    Paper,
    /// The genuine half-plane solution (no apex dislocation).
    Genuine,
}

impl Solution {
    /// Whether this variant is the paper's construction (`paper`, `as-printed`), whose
    /// estimates are the quadratures' own; not the genuine solution, whose estimates come
    /// from its basis sizes.
    pub fn is_paper_construction(self) -> bool {
        self != Solution::Genuine
    }

    /// The name used in outputs and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Solution::AsPrinted => "as-printed",
            Solution::Paper => "paper",
            Solution::Genuine => "genuine",
        }
    }
    /// The default variant for an indenter: `genuine` when gamma > 0 (the paper's construction
    /// then carries an apex dislocation), `paper` for gamma = 0, where the two coincide and the
    /// paper's closed form is the faster and more precise route.
    pub fn default_for(indenter: &Indenter) -> Self {
        if indenter.gamma().value() > 0.0 {
            Solution::Genuine
        } else {
            Solution::Paper
        }
    }

    /// Parse a command-line name.
    pub fn parse(s: &str) -> Result<Self> {
        match s {
            "as-printed" => Ok(Solution::AsPrinted),
            "paper" => Ok(Solution::Paper),
            "genuine" => Ok(Solution::Genuine),
            _ => Err(invalid("solution", s, "paper | as-printed | genuine")),
        }
    }
}
