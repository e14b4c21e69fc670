//! Typed reports of solved wedge cases: what `solve`, `curve`, `stress` and `field` compute,
//! as values the library returns, with the case's inputs ([`CaseInput`], [`Speed`]) beside
//! them; their JSON, CSV and table forms are written here, from the typed fields.
//!
//! Every number is a [`Quantity`]: its decimal text at the digits asked for and its own
//! absolute error estimate, never optimistic (checked against solves at twice the
//! precision in `tests/suite/error_estimates.rs`). A quantity a case may lack is an [`Entry`]: a
//! value, or the reason it is unavailable. A required quantity that cannot be computed is an
//! error naming it: no report carries a non-finite number.

use complexfn::{Precision, Real};
use serde_json::{Map, Value};
use wedge::{
    ApexRegime, ContactSolution, Indenter, Material, Result, Solution, WedgeError, WithError,
};

use super::{not_finite, num, print_floor, ratio, Entry, Quantity};
use crate::{DOUBLE_DOUBLE_DIGITS, GUARD_BITS};

/// The report keys that other code (the figures, other front ends) names: each spelled
/// once, here; the key lists are made of them.
pub mod keys {
    /// `apex_exponent`.
    pub const APEX_EXPONENT: &str = "apex_exponent";
    /// `coupling`.
    pub const COUPLING: &str = "coupling";
    /// `edge_following_rate_over_speed`.
    pub const EDGE_FOLLOWING_RATE_OVER_SPEED: &str = "edge_following_rate_over_speed";
    /// `edge_slip_velocity_over_speed`.
    pub const EDGE_SLIP_VELOCITY_OVER_SPEED: &str = "edge_slip_velocity_over_speed";
    /// `gamma`.
    pub const GAMMA: &str = "gamma";
    /// `p`.
    pub const P: &str = "p";
    /// `r_over_alpha_t`.
    pub const R_OVER_ALPHA_T: &str = "r_over_alpha_t";
    /// `regime`.
    pub const REGIME: &str = "regime";
    /// `sigma_over_mu_cot_theta`.
    pub const SIGMA_OVER_MU_COT_THETA: &str = "sigma_over_mu_cot_theta";
    /// `solution`.
    pub const SOLUTION: &str = "solution";
    /// `theta_deg`.
    pub const THETA_DEG: &str = "theta_deg";
    /// `v_over_c1_cot_theta`.
    pub const V_OVER_C1_COT_THETA: &str = "v_over_c1_cot_theta";
    /// `x_over_c1_t`.
    pub const X_OVER_C1_T: &str = "x_over_c1_t";
    /// `y_over_c1_t`.
    pub const Y_OVER_C1_T: &str = "y_over_c1_t";
}

/// The contact speed of a case: the contact-zone speed alpha or the indenter speed V (m/s),
/// as decimal text parsed at the working precision (`f64.into()` for a double).
#[derive(Clone, Debug, PartialEq)]
pub enum Speed {
    /// Contact-zone expansion speed alpha, 0 < alpha < c_R.
    Alpha(wedge::Param),
    /// Indenter speed V > 0 (alpha found by the inverse solve).
    Indenter(wedge::Param),
}

/// Everything that defines one case.
#[derive(Clone, Debug)]
pub struct CaseInput {
    /// Material.
    pub material: Material,
    /// Indenter.
    pub indenter: Indenter,
    /// Solution variant.
    pub solution: Solution,
    /// Requested significant digits; `None` for the f64 path.
    pub digits: Option<u32>,
}

impl CaseInput {
    /// The working precision: f64, or enough bits for `digits` plus [`GUARD_BITS`].
    pub fn precision(&self) -> Result<Precision> {
        match self.digits {
            None => Ok(Precision::F64),
            Some(d) if !(1..=crate::MAX_DIGITS).contains(&d) => {
                Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
                    name: "digits",
                    value: d.to_string(),
                    range: format!("1 ..= {}", crate::MAX_DIGITS),
                }))
            }
            Some(d) => Ok(Precision::from_digits(d, GUARD_BITS)?),
        }
    }
    /// Whether the case is computed in double-double arithmetic: `digits` at most
    /// [`DOUBLE_DOUBLE_DIGITS`] (any solution variant).
    pub fn uses_double_double(&self) -> bool {
        self.digits.is_some_and(|d| d <= DOUBLE_DOUBLE_DIGITS)
    }
    /// The arithmetic of the case, for messages: `f64`, `double-double` or `MPFR`.
    pub fn arithmetic(&self) -> &'static str {
        match self.digits {
            None => "f64",
            Some(_) if self.uses_double_double() && self.solution == Solution::Genuine => {
                "double-double, or MPFR where it falls short"
            }
            Some(_) if self.uses_double_double() => "double-double",
            Some(_) => "MPFR",
        }
    }
    /// Digits printed: the requested ones, or 16 for the f64 path.
    pub fn out_digits(&self) -> usize {
        self.digits.map(|d| d as usize).unwrap_or(16)
    }
}

/// One entry of a report, as the command line serialises it.
#[derive(Clone, Copy, Debug)]
pub enum Item<'a> {
    /// A number with its estimate.
    Number(&'a Quantity),
    /// A name (solution variant, apex regime).
    Name(&'static str),
    /// A yes/no check.
    Flag(bool),
    /// A relative error estimate.
    Ratio(f64),
    /// A count (the digits printed).
    Count(usize),
    /// Unavailable, with the reason.
    Unavailable(&'a str),
    /// Left out by the selection (not serialised).
    Omitted,
}

impl<'a> From<&'a Entry<Quantity>> for Item<'a> {
    fn from(e: &'a Entry<Quantity>) -> Self {
        match e {
            Entry::Value(q) => Item::Number(q),
            Entry::Unavailable(r) => Item::Unavailable(r),
            Entry::Omitted => Item::Omitted,
        }
    }
}

impl<'a> From<&'a Entry<bool>> for Item<'a> {
    fn from(e: &'a Entry<bool>) -> Self {
        match e {
            Entry::Value(b) => Item::Flag(*b),
            Entry::Unavailable(r) => Item::Unavailable(r),
            Entry::Omitted => Item::Omitted,
        }
    }
}

/// The keys of a `solve` report, in order (also the CSV columns of `curve`); the field of
/// [`SolveReport`] of the same name holds each.
pub const SOLVE_KEYS: &[&str] = &[
    keys::SOLUTION,
    "alpha",
    "speed",
    keys::P,
    "m",
    "m_r",
    "omega0",
    "s0",
    keys::REGIME,
    keys::APEX_EXPONENT,
    "apex_amplitude_over_mu_cot_theta",
    "q_over_c1sq_cot_theta",
    keys::V_OVER_C1_COT_THETA,
    "force_over_a_mu_cot_theta",
    keys::EDGE_SLIP_VELOCITY_OVER_SPEED,
    keys::EDGE_FOLLOWING_RATE_OVER_SPEED,
    "apex_u_r_over_speed_t",
    "slip_direction_ok",
    "contact_compressive",
    "no_interpenetration",
    "speed_positive",
    "force_compressive",
    "error_estimate",
    "digits",
];

/// The numeric quantities of a report, each with its own error estimate (in a CSV the
/// columns `err_<key>`, after the [`SOLVE_KEYS`]).
pub const ESTIMATED_KEYS: &[&str] = &[
    "alpha",
    "speed",
    keys::P,
    "m",
    "m_r",
    "omega0",
    "s0",
    keys::APEX_EXPONENT,
    "apex_amplitude_over_mu_cot_theta",
    "q_over_c1sq_cot_theta",
    keys::V_OVER_C1_COT_THETA,
    "force_over_a_mu_cot_theta",
    keys::EDGE_SLIP_VELOCITY_OVER_SPEED,
    keys::EDGE_FOLLOWING_RATE_OVER_SPEED,
    "apex_u_r_over_speed_t",
];

/// The keys every report carries, whatever the [`Selection`]: the inputs, the solution
/// variant, V (the solve's result), the apex regime and the summary estimate.
pub const ALWAYS_KEYS: &[&str] = &[
    keys::SOLUTION,
    "alpha",
    "speed",
    keys::P,
    "m",
    "m_r",
    keys::REGIME,
    keys::V_OVER_C1_COT_THETA,
    "error_estimate",
    "digits",
];

/// The admissibility flags that sample the contact and its outside (sign checks made on the
/// f64 twin of a case above f64, [`wedge::Admissibility`]).
pub const ADMISSIBILITY_KEYS: &[&str] = &[
    "slip_direction_ok",
    "contact_compressive",
    "no_interpenetration",
];

/// The admissibility flags read off the solve itself, at the working precision: V > 0 and a
/// compressive normal force P > 0, each beyond its own estimate.
pub const SIGN_KEYS: &[&str] = &["speed_positive", "force_compressive"];

/// Which quantities a report computes: every key of [`SOLVE_KEYS`] (the default), or the
/// [`ALWAYS_KEYS`] and the keys selected. What is left out is not computed (each quantity is
/// computed on demand by [`wedge::ContactSolution`]) and not printed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Selection {
    keys: Option<Vec<&'static str>>,
}

impl Selection {
    /// Every quantity.
    pub fn all() -> Self {
        Selection { keys: None }
    }
    /// The [`ALWAYS_KEYS`] and `keys` (each a key of [`SOLVE_KEYS`]; an unknown key is an
    /// error naming it and listing the keys).
    pub fn of<S: AsRef<str>>(keys: &[S]) -> Result<Self> {
        let mut out = Vec::new();
        for k in keys {
            let k = k.as_ref().trim();
            match SOLVE_KEYS.iter().find(|s| **s == k) {
                Some(s) => out.push(*s),
                None => {
                    return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
                        name: "quantities",
                        value: k.to_string(),
                        range: format!("keys of a solve report: {}", SOLVE_KEYS.join(",")),
                    }))
                }
            }
        }
        Ok(Selection { keys: Some(out) })
    }
    /// Every quantity but the admissibility flags.
    pub fn without_admissibility() -> Self {
        Selection {
            keys: Some(
                SOLVE_KEYS
                    .iter()
                    .filter(|k| !ADMISSIBILITY_KEYS.contains(k))
                    .copied()
                    .collect(),
            ),
        }
    }
    /// Whether the report carries `key`.
    pub fn wants(&self, key: &str) -> bool {
        ALWAYS_KEYS.contains(&key) || self.keys.as_ref().is_none_or(|k| k.contains(&key))
    }
    /// Whether any admissibility flag is selected.
    pub fn wants_admissibility(&self) -> bool {
        ADMISSIBILITY_KEYS.iter().any(|k| self.wants(k))
    }
    /// The [`SOLVE_KEYS`] the report carries, in order.
    pub fn solve_keys(&self) -> Vec<&'static str> {
        SOLVE_KEYS
            .iter()
            .copied()
            .filter(|k| self.wants(k))
            .collect()
    }
    /// The [`ESTIMATED_KEYS`] the report carries, in order.
    pub fn estimated_keys(&self) -> Vec<&'static str> {
        ESTIMATED_KEYS
            .iter()
            .copied()
            .filter(|k| self.wants(k))
            .collect()
    }
}

/// The reason given for the sampled admissibility checks of a report built without them
/// ([`SolveReport::set_admissibility`] sets them).
pub const ADMISSIBILITY_NOT_COMPUTED: &str =
    "not computed (the sampled sign checks are set by SolveReport::set_admissibility)";

/// The report of one solved case (`wedge solve`, a row of `wedge curve`): every quantity
/// dimensionless, the field names are the report keys ([`SOLVE_KEYS`]).
#[derive(Clone, Debug)]
pub struct SolveReport {
    /// The case's inputs (material, indenter, solution variant, digits asked for).
    pub input: CaseInput,
    /// Contact-zone speed alpha, m/s.
    pub alpha: Quantity,
    /// Indenter speed V, m/s.
    pub speed: Quantity,
    /// p = alpha/c1.
    pub p: Quantity,
    /// m = c2/c1.
    pub m: Quantity,
    /// m_R = c_R/c1.
    pub m_r: Quantity,
    /// Omega0, eq (31) (the paper's construction).
    pub omega0: Entry<Quantity>,
    /// S0, eq (44) (the paper's construction).
    pub s0: Entry<Quantity>,
    /// The apex regime.
    pub regime: ApexRegime,
    /// lambda of sigma ~ (p/x)^lambda at the apex (0 for a finite or logarithmic apex).
    pub apex_exponent: Entry<Quantity>,
    /// The amplitude of the leading apex term over mu cot Theta ([`wedge::solved`]).
    pub apex_amplitude_over_mu_cot_theta: Entry<Quantity>,
    /// Q/(c1^2 cot Theta), eq (53b) (the paper's construction).
    pub q_over_c1sq_cot_theta: Entry<Quantity>,
    /// V/(c1 cot Theta).
    pub v_over_c1_cot_theta: Quantity,
    /// P/(alpha t mu cot Theta), eq (47) (an error when selected and not computable).
    pub force_over_a_mu_cot_theta: Entry<Quantity>,
    /// du_r/dt at the contact edge over V (the paper's construction).
    pub edge_slip_velocity_over_speed: Entry<Quantity>,
    /// The rate of u_r following the edge over V (the paper's construction).
    pub edge_following_rate_over_speed: Entry<Quantity>,
    /// u_r(0+, t)/(V t), the apex dislocation (the paper's construction).
    pub apex_u_r_over_speed_t: Entry<Quantity>,
    /// The slip direction (8) holds on the contact.
    pub slip_direction_ok: Entry<bool>,
    /// The contact stress is compressive.
    pub contact_compressive: Entry<bool>,
    /// No interpenetration outside the contact.
    pub no_interpenetration: Entry<bool>,
    /// The indenter speed V is positive beyond its estimate.
    pub speed_positive: Entry<bool>,
    /// The normal force P is positive (compressive) beyond its estimate.
    pub force_compressive: Entry<bool>,
    /// The relative error estimate of V (the solve's summary accuracy).
    pub error_estimate: f64,
    /// Significant digits printed.
    pub digits: usize,
}

impl SolveReport {
    /// The solution variant.
    pub fn solution(&self) -> Solution {
        self.input.solution
    }

    /// Every entry in [`SOLVE_KEYS`] order.
    pub fn items(&self) -> Vec<(&'static str, Item<'_>)> {
        fn q<'a>(k: &'static str, x: &'a Quantity) -> (&'static str, Item<'a>) {
            (k, Item::Number(x))
        }
        vec![
            ("solution", Item::Name(self.solution().name())),
            q("alpha", &self.alpha),
            q("speed", &self.speed),
            q("p", &self.p),
            q("m", &self.m),
            q("m_r", &self.m_r),
            ("omega0", (&self.omega0).into()),
            ("s0", (&self.s0).into()),
            ("regime", Item::Name(self.regime.name())),
            ("apex_exponent", (&self.apex_exponent).into()),
            (
                "apex_amplitude_over_mu_cot_theta",
                (&self.apex_amplitude_over_mu_cot_theta).into(),
            ),
            (
                "q_over_c1sq_cot_theta",
                (&self.q_over_c1sq_cot_theta).into(),
            ),
            q("v_over_c1_cot_theta", &self.v_over_c1_cot_theta),
            (
                "force_over_a_mu_cot_theta",
                (&self.force_over_a_mu_cot_theta).into(),
            ),
            (
                "edge_slip_velocity_over_speed",
                (&self.edge_slip_velocity_over_speed).into(),
            ),
            (
                "edge_following_rate_over_speed",
                (&self.edge_following_rate_over_speed).into(),
            ),
            (
                "apex_u_r_over_speed_t",
                (&self.apex_u_r_over_speed_t).into(),
            ),
            ("slip_direction_ok", (&self.slip_direction_ok).into()),
            ("contact_compressive", (&self.contact_compressive).into()),
            ("no_interpenetration", (&self.no_interpenetration).into()),
            ("speed_positive", (&self.speed_positive).into()),
            ("force_compressive", (&self.force_compressive).into()),
            ("error_estimate", Item::Ratio(self.error_estimate)),
            ("digits", Item::Count(self.digits)),
        ]
    }

    /// The numeric quantities present, with their keys ([`ESTIMATED_KEYS`] order).
    pub fn quantities(&self) -> Vec<(&'static str, &Quantity)> {
        self.items()
            .into_iter()
            .filter_map(|(k, it)| match it {
                Item::Number(q) => Some((k, q)),
                _ => None,
            })
            .collect()
    }

    /// The quantity of `key`, if the report holds it.
    pub fn quantity(&self, key: &str) -> Option<&Quantity> {
        self.quantities()
            .into_iter()
            .find(|(k, _)| *k == key)
            .map(|(_, q)| q)
    }

    /// Every numeric quantity present, mutable (required ones first).
    #[doc(hidden)]
    pub fn quantities_mut(&mut self) -> Vec<(&'static str, &mut Quantity)> {
        let mut out: Vec<(&'static str, &mut Quantity)> = vec![
            ("alpha", &mut self.alpha),
            ("speed", &mut self.speed),
            ("p", &mut self.p),
            ("m", &mut self.m),
            ("m_r", &mut self.m_r),
            ("v_over_c1_cot_theta", &mut self.v_over_c1_cot_theta),
        ];
        for (k, e) in [
            (
                "force_over_a_mu_cot_theta",
                &mut self.force_over_a_mu_cot_theta,
            ),
            ("omega0", &mut self.omega0),
            ("s0", &mut self.s0),
            ("apex_exponent", &mut self.apex_exponent),
            (
                "apex_amplitude_over_mu_cot_theta",
                &mut self.apex_amplitude_over_mu_cot_theta,
            ),
            ("q_over_c1sq_cot_theta", &mut self.q_over_c1sq_cot_theta),
            (
                "edge_slip_velocity_over_speed",
                &mut self.edge_slip_velocity_over_speed,
            ),
            (
                "edge_following_rate_over_speed",
                &mut self.edge_following_rate_over_speed,
            ),
            ("apex_u_r_over_speed_t", &mut self.apex_u_r_over_speed_t),
        ] {
            if let Entry::Value(q) = e {
                out.push((k, q));
            }
        }
        out
    }

    /// The quantities not available, with the reasons.
    pub fn unavailable(&self) -> Vec<(&'static str, &str)> {
        self.items()
            .into_iter()
            .filter_map(|(k, it)| match it {
                Item::Unavailable(r) => Some((k, r)),
                _ => None,
            })
            .collect()
    }
}

/// Whether `value` is positive beyond its estimate `error`: true above it, false below
/// -error, unavailable (with the reason) in between, where its sign is not determined.
fn sign_flag(what: &str, value: f64, error: f64) -> Entry<bool> {
    if !(value.is_finite() && error.is_finite()) {
        Entry::Unavailable(format!("{what} is not finite"))
    } else if value > error {
        Entry::Value(true)
    } else if value < -error {
        Entry::Value(false)
    } else {
        Entry::Unavailable(format!(
            "the sign of {what} is not determined: {value:e} with the estimate {error:e}"
        ))
    }
}

/// The optional quantity `key`, or the reason it is unavailable (its error, a value that is
/// not finite, or an estimate that is not: [`Quantity::new`]).
fn entry<T: Real>(
    key: &str,
    r: Result<WithError<T>>,
    floor: f64,
    digits: usize,
) -> Entry<Quantity> {
    match r.and_then(|w| Quantity::new(key, &w.value, w.error, floor, digits)) {
        Ok(q) => Entry::Value(q),
        Err(e) => Entry::Unavailable(e.to_string()),
    }
}

impl SolveReport {
    /// The report of the solved case `s` of `input`, printed to `digits` digits, every
    /// quantity but the sampled admissibility checks ([`ADMISSIBILITY_NOT_COMPUTED`]; see
    /// [`Self::set_admissibility`]).
    ///
    /// A V whose relative estimate exceeds [`wedge::MAX_REL_ERROR`] is refused
    /// ([`WedgeError::Undetermined`]): its sign is not determined at the working precision.
    pub fn of<T, S>(s: &S, input: &CaseInput, digits: usize) -> Result<Self>
    where
        T: complexfn::quadrature::CachedRules,
        S: ContactSolution<T> + ?Sized,
    {
        Self::selected(s, input, digits, &Selection::all())
    }

    /// [`Self::of`] computing only the quantities `sel` wants; the others are
    /// [`Entry::Omitted`].
    pub fn selected<T, S>(s: &S, input: &CaseInput, digits: usize, sel: &Selection) -> Result<Self>
    where
        T: complexfn::quadrature::CachedRules,
        S: ContactSolution<T> + ?Sized,
    {
        let p = s.p();
        let floor = print_floor(digits, p.prec());
        let c1 = input.material.c1().to_real(&p);
        let cot = input.indenter.cot_theta(&p);
        let exact = |key: &str, x: &T| Quantity::new(key, x, 0.0, floor, digits);
        let optional = |key: &str, f: &dyn Fn() -> Result<WithError<T>>| {
            Entry::when(sel, key, || entry(key, f(), floor, digits))
        };
        let v = s.v_hat()?;
        let v_rel = v.error / v.value.to_f64().abs();
        if !(v_rel <= wedge::MAX_REL_ERROR) {
            return Err(WedgeError::Undetermined {
                what: "v_over_c1_cot_theta".into(),
                reached: v_rel,
                allowed: wedge::MAX_REL_ERROR,
            });
        }
        let speed_scale = (c1.clone() * &cot).to_f64().abs();
        let speed = v.value.clone() * &c1 * &cot;
        let force_key = "force_over_a_mu_cot_theta";
        let force_hat = if sel.wants(force_key) || sel.wants("force_compressive") {
            Some(s.force_hat())
        } else {
            None
        };
        let force = match &force_hat {
            Some(f) if sel.wants(force_key) => {
                let f = f.as_ref().map_err(Clone::clone)?;
                Entry::Value(Quantity::new(force_key, &f.value, f.error, floor, digits)?)
            }
            _ => Entry::Omitted,
        };
        let speed_positive = Entry::when(sel, "speed_positive", || {
            sign_flag("V", v.value.to_f64(), v.error)
        });
        let force_compressive = Entry::when(sel, "force_compressive", || match &force_hat {
            Some(Ok(f)) => sign_flag("the force", f.value.to_f64(), f.error),
            Some(Err(e)) => Entry::Unavailable(format!("the force: {e}")),
            None => Entry::Unavailable("the force was not computed".into()),
        });
        let apex_keys = ["apex_exponent", "apex_amplitude_over_mu_cot_theta"];
        let (regime, apex_exponent, apex_amplitude) = if !apex_keys.iter().any(|k| sel.wants(k)) {
            (s.regime(), Entry::Omitted, Entry::Omitted)
        } else {
            match s.apex_leading() {
                Ok(a) => (
                    a.regime,
                    Entry::when(sel, apex_keys[0], || {
                        entry(
                            apex_keys[0],
                            Ok(WithError {
                                value: a.exponent,
                                error: a.exponent_error,
                                kind: complexfn::ErrorKind::Propagated,
                            }),
                            floor,
                            digits,
                        )
                    }),
                    Entry::when(sel, apex_keys[1], || {
                        entry(apex_keys[1], Ok(a.amplitude), floor, digits)
                    }),
                ),
                Err(e) => {
                    let why = format!("apex expansion: {e}");
                    let un = |k| Entry::when(sel, k, || Entry::Unavailable(why.clone()));
                    (s.regime(), un(apex_keys[0]), un(apex_keys[1]))
                }
            }
        };
        let error_estimate = s.rel_error()?;
        if !error_estimate.is_finite() {
            return Err(not_finite("error_estimate"));
        }
        let ray = s.rayleigh();
        let not_here = |k| {
            Entry::when(sel, k, || {
                Entry::Unavailable(ADMISSIBILITY_NOT_COMPUTED.to_string())
            })
        };
        let mut report = SolveReport {
            input: input.clone(),
            alpha: exact("alpha", &(p.clone() * &c1))?,
            speed: Quantity::new("speed", &speed, v.error * speed_scale, floor, digits)?,
            p: exact("p", &p)?,
            m: exact("m", ray.m())?,
            m_r: exact("m_r", ray.m_r())?,
            omega0: optional("omega0", &|| s.omega0()),
            s0: optional("s0", &|| s.s0()),
            regime,
            apex_exponent,
            apex_amplitude_over_mu_cot_theta: apex_amplitude,
            q_over_c1sq_cot_theta: optional("q_over_c1sq_cot_theta", &|| s.q_hat()),
            v_over_c1_cot_theta: Quantity::new(
                "v_over_c1_cot_theta",
                &v.value,
                v.error,
                floor,
                digits,
            )?,
            force_over_a_mu_cot_theta: force,
            edge_slip_velocity_over_speed: optional("edge_slip_velocity_over_speed", &|| {
                s.edge_slip_velocity_over_speed()
            }),
            edge_following_rate_over_speed: optional("edge_following_rate_over_speed", &|| {
                s.edge_following_rate_over_speed()
            }),
            apex_u_r_over_speed_t: optional("apex_u_r_over_speed_t", &|| s.apex_u_r_over_speed_t()),
            slip_direction_ok: not_here("slip_direction_ok"),
            contact_compressive: not_here("contact_compressive"),
            no_interpenetration: not_here("no_interpenetration"),
            speed_positive,
            force_compressive,
            error_estimate,
            digits,
        };
        report.summarise();
        Ok(report)
    }

    /// Echoes the contact-zone speed alpha as the caller gave it (its decimal text, not
    /// rounded to the digits printed). Its estimate is the working precision's round-off
    /// (the value the case was computed with), not the print floor of the digits asked for.
    pub(crate) fn echo_alpha(&mut self, alpha: &wedge::Param) {
        self.alpha = self.echoed(alpha);
    }

    /// Echoes the indenter speed V as the caller gave it: the inverse solve's own estimate
    /// of the speed reached is kept (see [`Self::echo_alpha`]).
    pub(crate) fn echo_speed(&mut self, speed: &wedge::Param) {
        let error = self.speed.error;
        self.speed = Quantity {
            error,
            ..self.echoed(speed)
        };
    }

    /// An input as given, with the working precision's round-off as its estimate.
    fn echoed(&self, x: &wedge::Param) -> Quantity {
        let bits = self.input.precision().map(|p| p.bits()).unwrap_or(53);
        Quantity {
            text: x.text().to_string(),
            error: 8.0 * 2f64.powi(-(bits as i32)) * x.value().abs(),
        }
    }

    /// Sets the three sampled admissibility flags, or declares them unavailable with the
    /// reason.
    pub fn set_admissibility(&mut self, checks: Result<wedge::Admissibility>) {
        let (values, why) = match checks {
            Ok(a) => (
                [
                    a.slip_direction_ok,
                    a.contact_compressive,
                    a.no_interpenetration,
                ],
                String::new(),
            ),
            Err(e) => ([false; 3], format!("admissibility checks: {e}")),
        };
        for (flag, value) in [
            &mut self.slip_direction_ok,
            &mut self.contact_compressive,
            &mut self.no_interpenetration,
        ]
        .into_iter()
        .zip(values)
        {
            // a flag the selection left out stays out
            if *flag != Entry::Omitted {
                *flag = if why.is_empty() {
                    Entry::Value(value)
                } else {
                    Entry::Unavailable(why.clone())
                };
            }
        }
    }

    /// The summary estimate: at least V's own relative estimate.
    fn summarise(&mut self) {
        let v = &self.v_over_c1_cot_theta;
        if v.value() != 0.0 {
            self.error_estimate = self.error_estimate.max(v.error / v.value().abs());
        }
    }

    /// The report printed to `digits` digits, every estimate at least the print floor
    /// `floor` |value|.
    pub(crate) fn rounded(mut self, digits: usize, floor: f64) -> Self {
        for (_, q) in self.quantities_mut() {
            *q = q.rounded(digits, floor);
        }
        self.digits = digits;
        self
    }

    /// Adds `extra(key)` to the estimate of each quantity (the uncertainty of an input
    /// carried through the quantity's slope).
    pub(crate) fn widen(&mut self, extra: impl Fn(&str) -> f64) {
        for (k, q) in self.quantities_mut() {
            q.error += extra(k);
        }
        self.summarise();
    }
}

/// The contact stress of a case at fractions r/(alpha t) of the contact (`wedge stress`).
#[derive(Clone, Debug)]
pub struct StressReport {
    /// The case's inputs, echoed in the JSON (set by [`crate::stress`]).
    pub input: Option<CaseInput>,
    /// The contact speed as given (set by [`crate::stress`]).
    pub speed: Option<Speed>,
    /// The solution variant.
    pub solution: Solution,
    /// The fractions r/(alpha t), as given.
    pub r_over_alpha_t: Vec<wedge::Param>,
    /// sigma_theta/(mu cot Theta) at each fraction, with its estimate.
    pub sigma_over_mu_cot_theta: Vec<Quantity>,
    /// The largest relative estimate over the points.
    pub error_estimate: f64,
    /// Significant digits printed.
    pub digits: usize,
}

impl StressReport {
    /// The stress of the solved case `s` at the fractions `at` (each in (0, 1]).
    pub fn of<T, S>(s: &S, at: &[wedge::Param], digits: usize) -> Result<Self>
    where
        T: complexfn::quadrature::CachedRules,
        S: ContactSolution<T> + ?Sized,
    {
        let p = s.p();
        let floor = print_floor(digits, p.prec());
        let mut out = Vec::with_capacity(at.len());
        let mut worst = 0.0_f64;
        for fp in at {
            let f = fp.value();
            if !(f > 0.0 && f <= 1.0) {
                return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
                    name: "at",
                    value: fp.text().to_string(),
                    range: "(0, 1] (fractions r/(alpha t) of the contact half-width)".into(),
                }));
            }
            let x = p.clone() * fp.to_real(&p);
            let x = if x > p { p.clone() } else { x };
            let point = |e: WedgeError| WedgeError::AtCase {
                inputs: format!("the contact stress at r/(alpha t) = {}", fp.text()),
                error: Box::new(e),
            };
            let w = s.stress_hat(&x).map_err(point)?;
            let q = Quantity::new("the contact stress", &w.value, w.error, floor, digits)
                .map_err(point)?;
            worst = worst.max(q.error / q.value().abs().max(1e-300));
            out.push(q);
        }
        Ok(StressReport {
            input: None,
            speed: None,
            solution: s.solution(),
            r_over_alpha_t: at.to_vec(),
            sigma_over_mu_cot_theta: out,
            error_estimate: worst,
            digits,
        })
    }
}

/// Keys of the `field` report, in order (arrays over the points).
pub const FIELD_KEYS: &[&str] = &[
    keys::X_OVER_C1_T,
    keys::Y_OVER_C1_T,
    "sigma_xx_over_mu_cot_theta",
    "sigma_yy_over_mu_cot_theta",
    "sigma_xy_over_mu_cot_theta",
    "v_x_over_c1_cot_theta",
    "v_y_over_c1_cot_theta",
    "u_x_over_c1_t_cot_theta",
    "u_y_over_c1_t_cot_theta",
];

/// The field inside the half-plane at points (x/(c1 t), y/(c1 t)) (`wedge field`): for each
/// point the values of [`FIELD_KEYS`] as decimal text.
#[derive(Clone, Debug)]
pub struct FieldReport {
    /// The case's inputs, echoed in the JSON (set by [`crate::field`]).
    pub input: Option<CaseInput>,
    /// The contact speed as given (set by [`crate::field`]).
    pub speed: Option<Speed>,
    /// The solution variant (the paper's construction).
    pub solution: Solution,
    /// Per point, the values in [`FIELD_KEYS`] order.
    pub points: Vec<[String; 9]>,
    /// Significant digits printed.
    pub digits: usize,
}

impl FieldReport {
    /// The field of the paper's construction `case` at the points `pts` (y < 0), from the
    /// homogeneous-function crate (eqs (10)-(12) with (16)); Cartesian components, y out of
    /// the body. Points ahead of the P front (x^2 + y^2 >= 1) are at rest and give zeros.
    pub fn of<T: complexfn::quadrature::CachedRules>(
        case: &wedge::Case<T>,
        pts: &[(wedge::Param, wedge::Param)],
        digits: usize,
    ) -> Result<Self> {
        let pot = case.potentials()?;
        let mut points = Vec::with_capacity(pts.len());
        for (x, y) in pts {
            let (xt, yt) = (x.to_real(case.p()), y.to_real(case.p()));
            let fv = homogeneous::field::at(&pot, &xt, &yt).map_err(|e| {
                WedgeError::InvalidParameter(complexfn::InvalidParameter {
                    name: "at",
                    value: format!("{}:{}", x.text(), y.text()),
                    range: format!("a point of the half-plane y < 0 ({e})"),
                })
            })?;
            let c = fv.cartesian();
            let vals = [xt, yt, c.sxx, c.syy, c.sxy, c.vx, c.vy, c.ux, c.uy];
            if let Some(k) = vals.iter().position(|v| !v.is_finite()) {
                return Err(not_finite(FIELD_KEYS[k]));
            }
            points.push(vals.map(|v| v.to_decimal(digits)));
        }
        Ok(FieldReport {
            input: None,
            speed: None,
            solution: case.solution(),
            points,
            digits,
        })
    }
}

// ---------------------------------------------------------------------------------------
// JSON, CSV and tables

/// The JSON value of an item (`None` for one the selection left out).
fn item_json(it: &Item) -> Option<Value> {
    Some(match it {
        Item::Number(q) => num(q.text()),
        Item::Name(s) => Value::String((*s).into()),
        Item::Flag(b) => Value::Bool(*b),
        Item::Ratio(x) => ratio(*x),
        Item::Count(n) => Value::Number((*n).into()),
        Item::Unavailable(_) => Value::Null,
        Item::Omitted => return None,
    })
}

/// The keys echoing a case's inputs, in order (after a report's own keys).
pub const INPUT_KEYS: &[&str] = &["c1", "c2", keys::THETA_DEG, keys::GAMMA, keys::COUPLING];

/// The keys echoing the contact speed as given (one of them).
pub const SPEED_KEYS: &[&str] = &["alpha", "speed"];

fn inputs_json(o: &mut Map<String, Value>, input: &CaseInput) {
    o.insert("c1".into(), num(input.material.c1().text()));
    o.insert("c2".into(), num(input.material.c2().text()));
    o.insert("theta_deg".into(), num(input.indenter.theta_deg().text()));
    o.insert("gamma".into(), num(input.indenter.gamma().text()));
    o.insert(
        "coupling".into(),
        Value::String(input.indenter.coupling().name().into()),
    );
}

fn echo_json(o: &mut Map<String, Value>, input: &Option<CaseInput>, speed: &Option<Speed>) {
    if let Some(input) = input {
        inputs_json(o, input);
    }
    match speed {
        Some(Speed::Alpha(a)) => {
            o.insert("alpha".into(), num(a.text()));
        }
        Some(Speed::Indenter(v)) => {
            o.insert("speed".into(), num(v.text()));
        }
        None => {}
    }
}

impl SolveReport {
    /// The report as a JSON object: the keys of [`SOLVE_KEYS`] it carries (null where
    /// unavailable, absent where the selection left them out), `error_estimates`
    /// (absolute, per quantity), `unavailable` (the reasons, when any) and the case's inputs
    /// ([`INPUT_KEYS`]).
    pub fn to_json(&self) -> Value {
        let mut o = Map::new();
        for (k, it) in &self.items() {
            if let Some(v) = item_json(it) {
                o.insert((*k).into(), v);
            }
        }
        let est: Map<String, Value> = self
            .quantities()
            .into_iter()
            .map(|(k, q)| (k.to_string(), ratio(q.error())))
            .collect();
        o.insert("error_estimates".into(), Value::Object(est));
        let why: Map<String, Value> = self
            .unavailable()
            .into_iter()
            .map(|(k, reason)| (k.to_string(), Value::String(reason.into())))
            .collect();
        if !why.is_empty() {
            o.insert("unavailable".into(), Value::Object(why));
        }
        inputs_json(&mut o, &self.input);
        Value::Object(o)
    }

    /// The report as a two-column table, one key a line (the JSON's keys and values).
    pub fn to_table(&self) -> String {
        let Value::Object(map) = self.to_json() else {
            return String::new();
        };
        let w = map.keys().map(|k| k.len()).max().unwrap_or(0);
        let mut out = String::new();
        for (k, v) in &map {
            let s = match v {
                Value::String(s) => s.clone(),
                other => other.to_string(),
            };
            out.push_str(&format!("{k:<w$}  {s}\n"));
        }
        out
    }

    /// The CSV header of a curve: the [`SOLVE_KEYS`] of the selection, then `err_<key>` for
    /// its [`ESTIMATED_KEYS`].
    pub fn csv_header(sel: &Selection) -> String {
        sel.solve_keys()
            .iter()
            .map(|k| k.to_string())
            .chain(sel.estimated_keys().iter().map(|k| format!("err_{k}")))
            .collect::<Vec<_>>()
            .join(",")
    }

    /// One CSV row of a curve, the columns of [`Self::csv_header`] (empty cells where
    /// unavailable).
    pub fn csv_row(&self, sel: &Selection) -> String {
        let cell = |v: Option<Value>| match v {
            Some(Value::String(s)) => s,
            Some(Value::Null) | None => String::new(),
            Some(v) => v.to_string(),
        };
        let keys = sel.solve_keys();
        let values = self
            .items()
            .into_iter()
            .filter(|(k, _)| keys.contains(k))
            .map(|(_, it)| cell(item_json(&it)));
        let errs = sel
            .estimated_keys()
            .into_iter()
            .map(|k| match self.quantity(k) {
                Some(q) => cell(Some(ratio(q.error()))),
                None => String::new(),
            });
        values.chain(errs).collect::<Vec<_>>().join(",")
    }
}

/// The keys of a `stress` report as JSON, in order (then the inputs echoed).
pub const STRESS_KEYS: &[&str] = &[
    keys::SOLUTION,
    keys::R_OVER_ALPHA_T,
    keys::SIGMA_OVER_MU_COT_THETA,
    "sigma_error_estimates",
    "error_estimate",
    "digits",
];

impl StressReport {
    /// The report as a JSON object ([`STRESS_KEYS`], then the inputs echoed).
    pub fn to_json(&self) -> Value {
        let mut m = Map::new();
        m.insert(
            "solution".into(),
            Value::String(self.solution.name().into()),
        );
        m.insert(
            "r_over_alpha_t".into(),
            Value::Array(self.r_over_alpha_t.iter().map(|x| num(x.text())).collect()),
        );
        m.insert(
            "sigma_over_mu_cot_theta".into(),
            Value::Array(
                self.sigma_over_mu_cot_theta
                    .iter()
                    .map(|q| num(q.text()))
                    .collect(),
            ),
        );
        m.insert(
            "sigma_error_estimates".into(),
            Value::Array(
                self.sigma_over_mu_cot_theta
                    .iter()
                    .map(|q| ratio(q.error()))
                    .collect(),
            ),
        );
        m.insert("error_estimate".into(), ratio(self.error_estimate));
        m.insert("digits".into(), Value::Number(self.digits.into()));
        echo_json(&mut m, &self.input, &self.speed);
        Value::Object(m)
    }

    /// The report as a table: a line per fraction, the value and its estimate.
    pub fn to_table(&self) -> String {
        let mut out = format!("solution: {}\n", self.solution.name());
        out.push_str(&format!("{:>16}  sigma/(mu cot Theta)\n", "r/(alpha t)"));
        for (x, y) in self
            .r_over_alpha_t
            .iter()
            .zip(&self.sigma_over_mu_cot_theta)
        {
            out.push_str(&format!(
                "{:>16}  {}  (+- {:.1e})\n",
                x.text(),
                y.text(),
                y.error()
            ));
        }
        out.push_str(&format!(
            "relative error estimate: {:.1e}\n",
            self.error_estimate
        ));
        out
    }
}

impl FieldReport {
    /// The report as a JSON object: an array over the points for each of [`FIELD_KEYS`],
    /// then the inputs echoed.
    pub fn to_json(&self) -> Value {
        let mut o = Map::new();
        o.insert(
            "solution".into(),
            Value::String(self.solution.name().into()),
        );
        for (i, k) in FIELD_KEYS.iter().enumerate() {
            let col = self.points.iter().map(|pt| num(&pt[i])).collect();
            o.insert((*k).into(), Value::Array(col));
        }
        o.insert("digits".into(), Value::Number(self.digits.into()));
        echo_json(&mut o, &self.input, &self.speed);
        Value::Object(o)
    }

    /// The report as a table: the keys, then a line per point.
    pub fn to_table(&self) -> String {
        let mut out = format!(
            "solution: {}\n{}\n",
            self.solution.name(),
            FIELD_KEYS.join("  ")
        );
        for pt in &self.points {
            out.push_str(&pt.join("  "));
            out.push('\n');
        }
        out
    }
}
