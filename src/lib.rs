//! Reports of solved cases for the `wedge` command line and the `figures` generator:
//! one place that turns a [`wedge::Case`] into named, dimensionless numbers.
//!
//! Key names (JSON keys and CSV columns) are part of the interface; they spell out the
//! normalisation: `v_over_c1_cot_theta` is V/(c1 cot Theta), `force_over_a_mu_cot_theta` is
//! P/(alpha t mu cot Theta), and so on.
#![warn(missing_docs)]
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accuracy;
pub mod stability;

use complexfn::quadrature::CachedRules;
use complexfn::{Precision, Real};
use rug::Float;
use serde_json::{Map, Number, Value};
use wedge::{Case, Coupling, Indenter, Material, Result, Solution, WedgeError};

/// Library version, written into every output header.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// Guard bits added to the precision that holds the requested digits.
pub const GUARD_BITS: u32 = 32;

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
            Some(d) => Ok(Precision::from_digits(d, GUARD_BITS)?),
        }
    }
    /// Digits printed: the requested ones, or 16 for the f64 path.
    pub fn out_digits(&self) -> usize {
        self.digits.map(|d| d as usize).unwrap_or(16)
    }
    /// Build the case at the precision of `like`.
    pub fn case<T: CachedRules>(&self, speed: &Speed, like: &T) -> Result<Case<T>> {
        match speed {
            Speed::Alpha(a) => Case::with_alpha(
                &self.material,
                &self.indenter,
                a.clone(),
                like,
                self.solution,
            ),
            Speed::Indenter(v) => wedge::case_for_speed(
                &self.material,
                &self.indenter,
                v.clone(),
                like,
                self.solution,
            ),
        }
    }
}

/// A JSON number with exactly the digits given (arbitrary precision).
pub fn num(s: &str) -> Value {
    match s.parse::<Number>() {
        Ok(n) => Value::Number(n),
        Err(_) => Value::Null,
    }
}

fn real<T: Real>(x: &T, digits: usize) -> Value {
    if x.is_finite() {
        num(&x.to_decimal(digits))
    } else {
        Value::Null
    }
}

fn f(x: f64) -> Value {
    if x.is_finite() {
        num(&format!("{x:e}"))
    } else {
        Value::Null
    }
}

/// The keys of a `solve` report, in order (also the CSV columns of `curve`).
pub const SOLVE_KEYS: &[&str] = &[
    "solution",
    "alpha",
    "speed",
    "p",
    "m",
    "m_r",
    "omega0",
    "s0",
    "regime",
    "apex_exponent",
    "apex_amplitude_over_mu_cot_theta",
    "q_over_c1sq_cot_theta",
    "v_over_c1_cot_theta",
    "force_over_a_mu_cot_theta",
    "edge_slip_velocity_over_speed",
    "edge_following_rate_over_speed",
    "apex_u_r_over_speed_t",
    "slip_direction_ok",
    "contact_compressive",
    "no_interpenetration",
    "error_estimate",
    "digits",
];

/// The quantities of a report that may be declared unavailable, with the reason, instead of
/// failing the whole report: the apex expansion, the edge velocities, the apex displacement,
/// the admissibility flags, and the keys a solution variant does not define. Every other
/// quantity is required: a report never carries a non-finite or missing number silently.
pub const OPTIONAL_KEYS: &[&str] = &[
    "omega0",
    "s0",
    "apex_exponent",
    "apex_amplitude_over_mu_cot_theta",
    "q_over_c1sq_cot_theta",
    "edge_slip_velocity_over_speed",
    "edge_following_rate_over_speed",
    "apex_u_r_over_speed_t",
    "slip_direction_ok",
    "contact_compressive",
    "no_interpenetration",
];

/// The numeric quantities of a report that carry their own error estimate, under
/// `error_estimates` (absolute, in the quantity's own units, never optimistic: checked against
/// solves at twice the precision over a grid of cases in `tests/error_estimates.rs`). In a CSV
/// they are the columns `err_<key>`, after the [`SOLVE_KEYS`].
pub const ESTIMATED_KEYS: &[&str] = &[
    "alpha",
    "speed",
    "p",
    "m",
    "m_r",
    "omega0",
    "s0",
    "apex_exponent",
    "apex_amplitude_over_mu_cot_theta",
    "q_over_c1sq_cot_theta",
    "v_over_c1_cot_theta",
    "force_over_a_mu_cot_theta",
    "edge_slip_velocity_over_speed",
    "edge_following_rate_over_speed",
    "apex_u_r_over_speed_t",
];

/// The relative error floor of a value printed to `digits` significant digits and computed
/// at `bits` bits: half a unit in the last printed digit, or 8 units of round-off.
fn print_floor(digits: usize, bits: u32) -> f64 {
    (0.5 * 10f64.powi(1 - digits as i32)).max(8.0 * 2f64.powi(-(bits as i32)))
}

/// The magnitude of a report's numeric entry (0 when absent or not a number).
fn magnitude(o: &Map<String, Value>, key: &str) -> Option<f64> {
    o.get(key).and_then(Value::as_f64).map(f64::abs)
}

/// Fills `error_estimates` for every [`ESTIMATED_KEYS`] entry the report holds: the
/// quantity's own absolute estimate where `own` has one, otherwise `rel` |value| (the solve's
/// relative estimate); never below the print floor `floor` |value|.
fn add_estimates(o: &mut Map<String, Value>, rel: f64, floor: f64, own: &[(&str, f64)]) {
    let mut e = Map::new();
    for k in ESTIMATED_KEYS {
        let Some(v) = magnitude(o, k) else { continue };
        let est = match own.iter().find(|(name, _)| name == k) {
            Some((_, a)) => *a,
            None => rel * v,
        };
        e.insert((*k).into(), f(est.max(floor * v)));
    }
    o.insert("error_estimates".into(), Value::Object(e));
}

/// Sets the estimate of `key` to `value` (when the report holds the key).
fn set_estimate(o: &mut Map<String, Value>, key: &str, value: f64) {
    if let Some(Value::Object(e)) = o.get_mut("error_estimates") {
        if e.contains_key(key) {
            e.insert(key.into(), f(value));
        }
    }
}

/// The estimate of `key` (absolute), if the report has one.
pub fn estimate(o: &Map<String, Value>, key: &str) -> Option<f64> {
    o.get("error_estimates")?.get(key)?.as_f64()
}

/// Declares `key` unavailable with `reason` (the report's `unavailable` object).
fn unavailable(o: &mut Map<String, Value>, key: &str, reason: impl Into<String>) {
    o.insert(key.into(), Value::Null);
    let list = o
        .entry("unavailable")
        .or_insert_with(|| Value::Object(Map::new()));
    if let Value::Object(m) = list {
        m.insert(key.into(), Value::String(reason.into()));
    }
}

/// Inserts an optional quantity, or declares it unavailable with the reason (its error, or a
/// non-finite value).
fn optional<T: Real>(o: &mut Map<String, Value>, key: &str, v: Result<T>, digits: usize) {
    match v {
        Ok(x) if x.is_finite() => {
            o.insert(key.into(), real(&x, digits));
        }
        Ok(_) => unavailable(o, key, "not finite at this precision"),
        Err(e) => unavailable(o, key, e.to_string()),
    }
}

/// The report's final check: every key of [`SOLVE_KEYS`] holds a finite number (or a string,
/// a boolean) unless the report declares it unavailable; a missing required quantity is an
/// error naming it.
pub fn check_report(o: &Map<String, Value>) -> Result<()> {
    let declared = o.get("unavailable").and_then(Value::as_object);
    if let Some(k) = declared
        .into_iter()
        .flat_map(|d| d.keys())
        .find(|k| !OPTIONAL_KEYS.contains(&k.as_str()))
    {
        return Err(WedgeError::Unsupported(format!(
            "{k} is a required quantity and cannot be declared unavailable"
        )));
    }
    for k in SOLVE_KEYS {
        let missing = matches!(o.get(*k), None | Some(Value::Null));
        let excused = declared.is_some_and(|d| d.contains_key(*k));
        if missing && !excused {
            return Err(WedgeError::NoConvergence {
                what: format!("{k} (not finite at this precision)"),
                reached: f64::INFINITY,
                asked: 0.0,
            });
        }
    }
    Ok(())
}

/// The case's inputs in one line, for error messages.
pub fn describe(input: &CaseInput, speed: &Speed) -> String {
    let speed = match speed {
        Speed::Alpha(a) => format!("alpha = {} m/s", lamb::error::short(a.value())),
        Speed::Indenter(v) => format!("V = {} m/s", lamb::error::short(v.value())),
    };
    format!(
        "theta_deg = {}, gamma = {}, coupling {}, {speed}, c1 = {} m/s, c2 = {} m/s, solution {}, {}",
        input.indenter.theta_deg().text(),
        input.indenter.gamma().text(),
        match input.indenter.coupling() {
            Coupling::On => "on",
            Coupling::Off => "off",
        },
        input.material.c1().text(),
        input.material.c2().text(),
        input.solution.name(),
        match input.digits {
            None => "f64".to_string(),
            Some(d) => format!("{d} digits"),
        }
    )
}

/// A numerical failure of the case, with its inputs (parameter errors name their parameter
/// already and pass unchanged).
pub fn at_case(input: &CaseInput, speed: &Speed, e: WedgeError) -> WedgeError {
    match e {
        WedgeError::InvalidParameter { .. } | WedgeError::AtCase { .. } => e,
        other => {
            let overflow = matches!(
                &other,
                WedgeError::Complex(complexfn::Error::NonFinite { .. })
            );
            let inputs = describe(input, speed);
            WedgeError::AtCase {
                inputs: if overflow && input.digits.is_none() {
                    format!("{inputs} (the f64 range is exceeded here; try --digits)")
                } else {
                    inputs
                },
                error: Box::new(other),
            }
        }
    }
}

/// The `solve` report of a case: every quantity of [`SOLVE_KEYS`]; the optional ones
/// ([`OPTIONAL_KEYS`]) that cannot be computed are declared under `unavailable` with the
/// reason, and the rest of the report stands.
pub fn solve_report<T: CachedRules>(
    case: &Case<T>,
    digits: usize,
    full: bool,
) -> Result<Map<String, Value>> {
    let c1 = case.material().c1().to_real(case.p());
    let cot = case.cot_theta().clone();
    let mt = case.matching()?;
    let mut o = Map::new();
    o.insert(
        "solution".into(),
        Value::String(case.solution().name().into()),
    );
    o.insert("alpha".into(), real(&(case.p().clone() * &c1), digits));
    o.insert(
        "speed".into(),
        real(&(mt.v_hat.clone() * &c1 * &cot), digits),
    );
    o.insert("p".into(), real(case.p(), digits));
    o.insert("m".into(), real(case.m(), digits));
    o.insert("m_r".into(), real(case.m_r(), digits));
    optional(&mut o, "omega0", Ok(case.omega0()), digits);
    optional(&mut o, "s0", Ok(case.s0()), digits);
    o.insert("regime".into(), Value::String(case.regime().name().into()));
    match case.apex_leading() {
        Ok((_, exponent, amplitude)) => {
            optional(&mut o, "apex_exponent", Ok(exponent), digits);
            optional(
                &mut o,
                "apex_amplitude_over_mu_cot_theta",
                Ok(amplitude),
                digits,
            );
        }
        Err(e) => {
            let why = format!("apex expansion: {e}");
            unavailable(&mut o, "apex_exponent", why.clone());
            unavailable(&mut o, "apex_amplitude_over_mu_cot_theta", why);
        }
    }
    optional(
        &mut o,
        "q_over_c1sq_cot_theta",
        Ok(mt.q_hat.clone()),
        digits,
    );
    o.insert("v_over_c1_cot_theta".into(), real(&mt.v_hat, digits));
    o.insert(
        "force_over_a_mu_cot_theta".into(),
        real(&case.force_hat()?, digits),
    );
    optional(
        &mut o,
        "edge_slip_velocity_over_speed",
        case.edge_slip_velocity_over_speed(),
        digits,
    );
    optional(
        &mut o,
        "edge_following_rate_over_speed",
        case.edge_following_rate_over_speed(),
        digits,
    );
    let apex_ur = case.apex_u_r_over_speed_t();
    let apex_ur_err = apex_ur.as_ref().ok().map(|a| a.error);
    optional(
        &mut o,
        "apex_u_r_over_speed_t",
        apex_ur.map(|a| a.value),
        digits,
    );
    let err = mt.rel_error;
    let floor = print_floor(digits, case.p().prec());
    // alpha is given (decimal text), p = alpha/c1, m and m_r are the material's: round-off
    // only; the apex displacement carries its own (absolute) quadrature estimate
    let mut own = vec![("alpha", 0.0), ("p", 0.0), ("m", 0.0), ("m_r", 0.0)];
    if let (Some(e), Some(v)) = (apex_ur_err, magnitude(&o, "apex_u_r_over_speed_t")) {
        own.push(("apex_u_r_over_speed_t", e.max(err * v)));
    }
    add_estimates(&mut o, err, floor, &own);
    if full {
        add_admissibility(&mut o, case);
    } else {
        let why = "not computed for curve rows (the sign checks of `solve` sample the contact)";
        unavailable(&mut o, "slip_direction_ok", why);
        o.insert("contact_compressive".into(), Value::Bool(mt.q_hat > 0.0));
        unavailable(&mut o, "no_interpenetration", why);
    }
    o.insert(
        "error_estimate".into(),
        if err.is_finite() { f(err) } else { Value::Null },
    );
    o.insert("digits".into(), Value::Number(digits.into()));
    check_report(&o)?;
    Ok(o)
}

/// Relative difference of two reports' numeric entries (the largest over `keys`).
pub fn report_difference(a: &Map<String, Value>, b: &Map<String, Value>, keys: &[&str]) -> f64 {
    let mut d = 0.0_f64;
    for k in keys {
        let (Some(Value::Number(x)), Some(Value::Number(y))) = (a.get(*k), b.get(*k)) else {
            continue;
        };
        let (Ok(x), Ok(y)) = (Float::parse(x.to_string()), Float::parse(y.to_string())) else {
            continue;
        };
        let x = Float::with_val(2048, x);
        let y = Float::with_val(2048, y);
        let diff = (x - &y).abs();
        let scale = y.abs();
        if scale > 0 {
            d = d.max((diff / scale).to_f64());
        }
    }
    d
}

/// Numeric keys of the solve report whose agreement across two precisions is checked.
pub const CHECKED_KEYS: &[&str] = &[
    "alpha",
    "speed",
    "omega0",
    "s0",
    "q_over_c1sq_cot_theta",
    "v_over_c1_cot_theta",
    "force_over_a_mu_cot_theta",
    "edge_slip_velocity_over_speed",
    "edge_following_rate_over_speed",
];

fn solver_err(e: genuine::GenuineError) -> WedgeError {
    match e {
        genuine::GenuineError::Wedge(w) => w,
        other => WedgeError::Solver(other.to_string()),
    }
}

/// The genuine solution for a contact speed, at the precision of `like` (the solver's
/// options for that precision, [`genuine::SolveOptions::for_precision`]).
pub fn genuine_case<T: CachedRules>(
    input: &CaseInput,
    speed: &Speed,
    like: &T,
) -> Result<genuine::GenuineCase<T>> {
    let c1 = input.material.c1().value();
    let m_r = complexfn::Rayleigh::new(input.material.m(&0.0_f64))?
        .m_r()
        .to_owned();
    let opts = genuine::SolveOptions::for_precision(like.prec());
    match speed {
        Speed::Alpha(alpha) => {
            let a = alpha.value();
            if !(a.is_finite() && a > 0.0 && a < m_r * c1) {
                return Err(WedgeError::InvalidParameter {
                    name: "alpha",
                    value: format!("{} m/s", alpha.text()),
                    range: format!("(0, c_R) = (0, {:.6}) m/s", m_r * c1),
                });
            }
            let p = alpha.to_real(like) / input.material.c1().to_real(like);
            genuine::GenuineCase::solve(&input.material, &input.indenter, p, opts)
                .map_err(solver_err)
        }
        Speed::Indenter(speed) => {
            let v = speed.value();
            if !(v.is_finite() && v > 0.0) {
                return Err(WedgeError::InvalidParameter {
                    name: "speed",
                    value: format!("{} m/s", speed.text()),
                    range: "(0, inf) m/s".into(),
                });
            }
            let v_hat = speed.to_real(like)
                / (input.material.c1().to_real(like) * input.indenter.cot_theta(like));
            genuine::GenuineCase::for_speed(
                &input.material,
                &input.indenter,
                v_hat,
                like.lit(m_r * 1e-6),
                like.lit(m_r * (1.0 - 1e-6)),
                opts,
            )
            .map_err(solver_err)
        }
    }
}

/// The `solve` report of the genuine solution (keys of [`SOLVE_KEYS`]; quantities that belong
/// to the paper's construction only, such as Omega0, Q and the apex dislocation, are null).
/// `error_estimate` is the relative change of V between the two basis sizes of the solve (plus
/// the precision's round-off floor): it bounds the coarse solve and so over-states the error
/// of the reported one.
pub fn genuine_report<T: CachedRules>(
    input: &CaseInput,
    g: &genuine::GenuineCase<T>,
    full: bool,
) -> Result<Map<String, Value>> {
    let digits = input.out_digits();
    let like = g.p();
    let c1 = input.material.c1().to_real(&like);
    let cot = input.indenter.cot_theta(&like);
    let ray = complexfn::Rayleigh::new(input.material.m(&like))?;
    let (apex, amp, amp_err) = g.apex_with_error().map_err(solver_err)?;
    let (force, force_err) = g.force_hat_with_error();
    let mut o = Map::new();
    for k in SOLVE_KEYS {
        o.insert((*k).into(), Value::Null);
    }
    o.insert(
        "solution".into(),
        Value::String(Solution::Genuine.name().into()),
    );
    o.insert("alpha".into(), real(&(g.p() * c1.clone()), digits));
    o.insert("speed".into(), real(&(g.v_hat() * c1 * cot), digits));
    o.insert("p".into(), real(&g.p(), digits));
    o.insert("m".into(), real(ray.m(), digits));
    o.insert("m_r".into(), real(ray.m_r(), digits));
    o.insert("regime".into(), Value::String(apex.kind.name().into()));
    let lambda = apex.leading().cloned().unwrap_or_else(|| g.p().zero());
    o.insert("apex_exponent".into(), real(&lambda, digits));
    o.insert(
        "apex_amplitude_over_mu_cot_theta".into(),
        real(&amp, digits),
    );
    o.insert("v_over_c1_cot_theta".into(), real(&g.v_hat(), digits));
    o.insert("force_over_a_mu_cot_theta".into(), real(&force, digits));
    if full {
        add_genuine_admissibility(&mut o, g)?;
    }
    let v_abs = g.error_estimate();
    let rel = v_abs / g.v_hat().to_f64().abs();
    o.insert("error_estimate".into(), f(rel));
    o.insert("digits".into(), Value::Number(digits.into()));
    let floor = print_floor(digits, g.precision_bits());
    let own = [
        ("alpha", 0.0),
        ("p", 0.0),
        ("m", 0.0),
        ("m_r", 0.0),
        ("apex_exponent", 0.0),
        ("v_over_c1_cot_theta", v_abs),
        ("force_over_a_mu_cot_theta", force_err),
        ("apex_amplitude_over_mu_cot_theta", amp_err),
    ];
    if !amp_err.is_finite() {
        unavailable(
            &mut o,
            "apex_amplitude_over_mu_cot_theta",
            "no error estimate: the coarser basis sizes give no amplitude",
        );
    }
    add_estimates(&mut o, rel, floor, &own);
    for k in [
        "omega0",
        "s0",
        "q_over_c1sq_cot_theta",
        "edge_slip_velocity_over_speed",
        "edge_following_rate_over_speed",
        "apex_u_r_over_speed_t",
    ] {
        unavailable(
            &mut o,
            k,
            "defined by the paper's construction only (solution paper or as-printed)",
        );
    }
    if !full {
        for k in [
            "slip_direction_ok",
            "contact_compressive",
            "no_interpenetration",
        ] {
            if o.get(k).is_none_or(Value::is_null) {
                unavailable(
                    &mut o,
                    k,
                    "not computed for curve rows (the sign checks of `solve` sample the contact)",
                );
            }
        }
    }
    check_report(&o)?;
    add_inputs(&mut o, input);
    Ok(o)
}

/// The admissibility checks of a genuine solve: contact compressive, no interpenetration
/// outside the contact, slip direction (8).
fn add_genuine_admissibility<T: CachedRules>(
    o: &mut Map<String, Value>,
    g: &genuine::GenuineCase<T>,
) -> Result<()> {
    o.insert(
        "slip_direction_ok".into(),
        Value::Bool(g.slip_direction_ok().map_err(solver_err)?),
    );
    o.insert(
        "contact_compressive".into(),
        Value::Bool(g.contact_compressive().map_err(solver_err)?),
    );
    o.insert(
        "no_interpenetration".into(),
        Value::Bool(g.no_interpenetration().map_err(solver_err)?.0),
    );
    Ok(())
}

/// The genuine `solve` report at the requested precision. With `digits`, the admissibility
/// checks (sign checks over some 50 sample points) are made on the f64 twin of the case.
fn genuine_solve(input: &CaseInput, speed: &Speed, full: bool) -> Result<Map<String, Value>> {
    match input.precision()? {
        Precision::F64 => genuine_report(input, &genuine_case(input, speed, &0.0_f64)?, full),
        Precision::Bits(b) => {
            let g = genuine_case(input, speed, &Float::with_val(b, 0))?;
            let mut o = genuine_report(input, &g, false)?;
            if full {
                let alpha = g.p().to_f64() * input.material.c1().value();
                let twin = genuine_case(input, &Speed::Alpha(alpha.into()), &0.0_f64)?;
                add_genuine_admissibility(&mut o, &twin)?;
            }
            Ok(o)
        }
    }
}

/// Solve a case and report it, at the requested precision. With `digits`, the case is solved
/// at two precisions (bits(digits) + 32 and + 64) and the error estimate is the larger of the
/// quadrature estimate and the difference between the two: never optimistic.
///
/// Every quantity of [`ESTIMATED_KEYS`] carries its own absolute estimate under
/// `error_estimates`. When the indenter speed is given, the inverse solve's uncertainty in
/// alpha is carried into every quantity through its slope (two f64 rows at nearby alpha).
pub fn solve(input: &CaseInput, speed: &Speed, full: bool) -> Result<Map<String, Value>> {
    let mut o = solve_unlabelled(input, speed, full).map_err(|e| at_case(input, speed, e))?;
    if let Speed::Indenter(_) = speed {
        inverse_estimates(input, &mut o).map_err(|e| at_case(input, speed, e))?;
    }
    Ok(o)
}

/// With V given, alpha is found by the inverse solve, which stops once |V(alpha) - V| is
/// within V's own estimate: alpha is uncertain by delta alpha = 2 delta V/(dV/d alpha), and
/// every quantity Q(alpha) by |dQ/d alpha| delta alpha more. The slopes are central
/// differences of two f64 rows at alpha (1 +- 1e-5) (they are needed to a few percent; a
/// margin of 10 percent is added).
fn inverse_estimates(input: &CaseInput, o: &mut Map<String, Value>) -> Result<()> {
    let alpha = magnitude(o, "alpha").unwrap_or(0.0);
    let h = 1e-5;
    let f64_input = CaseInput {
        digits: None,
        ..input.clone()
    };
    let row = |a: f64| curve_row_unlabelled(&f64_input, &a.into());
    let (lo, hi) = (row(alpha * (1.0 - h))?, row(alpha * (1.0 + h))?);
    let slope = |k: &str| -> Option<f64> {
        let (a, b) = (lo.get(k)?.as_f64()?, hi.get(k)?.as_f64()?);
        Some((b - a) / (2.0 * h * alpha))
    };
    let dv = slope("v_over_c1_cot_theta").unwrap_or(0.0).abs();
    let v_err = estimate(o, "v_over_c1_cot_theta").unwrap_or(f64::INFINITY);
    if !(dv.is_finite() && dv > 0.0) {
        return Err(WedgeError::NoConvergence {
            what: "slope of the alpha-V relation".into(),
            reached: dv,
            asked: 0.0,
        });
    }
    let d_alpha = 2.0 * v_err / dv;
    let c1 = input.material.c1().value();
    for k in ESTIMATED_KEYS {
        let Some(own) = estimate(o, k) else { continue };
        let add = match *k {
            "alpha" => d_alpha,
            "p" => d_alpha / c1,
            "m" | "m_r" | "speed" | "v_over_c1_cot_theta" => 0.0,
            _ => slope(k).map(f64::abs).unwrap_or(0.0) * d_alpha,
        };
        set_estimate(o, k, own + 1.1 * add);
    }
    Ok(())
}

fn solve_unlabelled(input: &CaseInput, speed: &Speed, full: bool) -> Result<Map<String, Value>> {
    if input.solution == Solution::Genuine {
        return genuine_solve(input, speed, full);
    }
    let digits = input.out_digits();
    match input.precision()? {
        Precision::F64 => {
            let case = input.case(speed, &0.0_f64)?;
            let mut r = solve_report(&case, digits, full)?;
            add_inputs(&mut r, input);
            Ok(r)
        }
        Precision::Bits(bits) => {
            let hi = Float::with_val(bits + GUARD_BITS, 0);
            let lo = Float::with_val(bits, 0);
            let case_hi = input.case(speed, &hi)?;
            let case_lo = input.case(speed, &lo)?;
            let r_lo = solve_report(&case_lo, digits + 10, false)?;
            let r_hi = solve_report(&case_hi, digits + 10, false)?;
            let diff = report_difference(&r_lo, &r_hi, CHECKED_KEYS);
            let err = diff.max(case_hi.matching()?.rel_error);
            let estimates = merged_estimates(&r_lo, &r_hi, print_floor(digits, bits));
            let mut out = round_report(r_hi, digits);
            out.insert("error_estimates".into(), estimates);
            if full {
                // The admissibility checks are sign checks: done on the f64 twin of the case.
                let twin = input.case(
                    &Speed::Alpha((case_hi.p().to_f64() * input.material.c1().value()).into()),
                    &0.0_f64,
                )?;
                add_admissibility(&mut out, &twin);
            }
            out.insert("error_estimate".into(), f(err));
            add_inputs(&mut out, input);
            Ok(out)
        }
    }
}

/// The estimates of a report solved at two precisions (`hi` reported): for each quantity the
/// larger of `hi`'s own estimate and the difference between the two, not below the print
/// floor `floor` |value| of the digits finally printed.
fn merged_estimates(lo: &Map<String, Value>, hi: &Map<String, Value>, floor: f64) -> Value {
    let mut e = Map::new();
    for k in ESTIMATED_KEYS {
        let (Some(own), Some(v)) = (estimate(hi, k), hi.get(*k)) else {
            continue;
        };
        let scale = v.as_f64().map(f64::abs).unwrap_or(0.0);
        // report_difference is relative to |hi|; for a zero value take the absolute one
        let diff = if scale > 0.0 {
            report_difference(lo, hi, &[k]) * scale
        } else {
            lo.get(*k).and_then(Value::as_f64).unwrap_or(0.0).abs()
        };
        e.insert((*k).into(), f(own.max(diff).max(floor * scale)));
    }
    Value::Object(e)
}

/// The admissibility flags, or all three declared unavailable with the reason.
fn add_admissibility<T: CachedRules>(r: &mut Map<String, Value>, case: &Case<T>) {
    let adm = match case.admissibility() {
        Ok(a) => a,
        Err(e) => {
            let why = format!("admissibility checks: {e}");
            for k in [
                "slip_direction_ok",
                "contact_compressive",
                "no_interpenetration",
            ] {
                unavailable(r, k, why.clone());
            }
            return;
        }
    };
    r.insert(
        "slip_direction_ok".into(),
        Value::Bool(adm.slip_direction_ok),
    );
    r.insert(
        "contact_compressive".into(),
        Value::Bool(adm.contact_compressive),
    );
    r.insert(
        "no_interpenetration".into(),
        Value::Bool(adm.no_interpenetration),
    );
}

/// Round every arbitrary-precision number of a report to `digits` significant digits
/// (booleans, strings and the integer `digits` entry are left as they are).
pub fn round_report(r: Map<String, Value>, digits: usize) -> Map<String, Value> {
    r.into_iter()
        .map(|(k, v)| {
            let v = match (&v, k.as_str()) {
                (_, "digits") => Value::Number(digits.into()),
                (Value::Number(n), _) => match Float::parse(n.to_string()) {
                    Ok(x) => real(&Float::with_val(4096, x), digits),
                    Err(_) => v,
                },
                _ => v,
            };
            (k, v)
        })
        .collect()
}

fn add_inputs(r: &mut Map<String, Value>, input: &CaseInput) {
    r.insert("c1".into(), num(input.material.c1().text()));
    r.insert("c2".into(), num(input.material.c2().text()));
    r.insert("theta_deg".into(), num(input.indenter.theta_deg().text()));
    r.insert("gamma".into(), num(input.indenter.gamma().text()));
    r.insert(
        "coupling".into(),
        Value::String(
            match input.indenter.coupling() {
                Coupling::On => "on",
                Coupling::Off => "off",
            }
            .into(),
        ),
    );
}

/// Contact stress sigma_theta/(mu cot Theta) at the given r/(alpha t), with its largest
/// relative error estimate.
pub fn stress_profile<T: CachedRules>(
    case: &Case<T>,
    at: &[wedge::Param],
    digits: usize,
) -> Result<(Vec<Value>, f64)> {
    let mut out = Vec::with_capacity(at.len());
    let mut err = 0.0_f64;
    for fp in at {
        let f = fp.value();
        if !(f > 0.0 && f <= 1.0) {
            return Err(WedgeError::InvalidParameter {
                name: "at",
                value: format!("{f}"),
                range: "(0, 1] (fractions r/(alpha t) of the contact half-width)".into(),
            });
        }
        let x = case.p().clone() * fp.to_real(case.p());
        let x = if x > *case.p() { case.p().clone() } else { x };
        let point = |e: WedgeError| WedgeError::AtCase {
            inputs: format!("the contact stress at r/(alpha t) = {}", fp.text()),
            error: Box::new(e),
        };
        let s = case.stress_hat(&x).map_err(point)?;
        if !(s.value.is_finite() && s.error.is_finite()) {
            return Err(point(WedgeError::NoConvergence {
                what: "the contact stress (not finite at this precision)".into(),
                reached: f64::INFINITY,
                asked: 0.0,
            }));
        }
        err = err.max(s.error / s.value.to_f64().abs().max(1e-300));
        out.push(real(&s.value, digits));
    }
    Ok((out, err))
}

/// Contact stress of the case at fractions r/(alpha t), in any solution variant, with its
/// largest relative error estimate.
pub fn stress_values(
    input: &CaseInput,
    speed: &Speed,
    at: &[wedge::Param],
) -> Result<(Vec<Value>, f64)> {
    stress_unlabelled(input, speed, at).map_err(|e| at_case(input, speed, e))
}

fn stress_unlabelled(
    input: &CaseInput,
    speed: &Speed,
    at: &[wedge::Param],
) -> Result<(Vec<Value>, f64)> {
    let digits = input.out_digits();
    if input.solution == Solution::Genuine {
        return match input.precision()? {
            Precision::F64 => genuine_stress(&genuine_case(input, speed, &0.0_f64)?, at, digits),
            Precision::Bits(b) => genuine_stress(
                &genuine_case(input, speed, &Float::with_val(b, 0))?,
                at,
                digits,
            ),
        };
    }
    match input.precision()? {
        Precision::F64 => stress_profile(&input.case(speed, &0.0_f64)?, at, digits),
        Precision::Bits(b) => {
            stress_profile(&input.case(speed, &Float::with_val(b, 0))?, at, digits)
        }
    }
}

/// Genuine contact stress at fractions r/(alpha t), with the solve's relative error estimate.
fn genuine_stress<T: CachedRules>(
    g: &genuine::GenuineCase<T>,
    at: &[wedge::Param],
    digits: usize,
) -> Result<(Vec<Value>, f64)> {
    let mut out = Vec::with_capacity(at.len());
    for fp in at {
        let fr = fp.value();
        if !(fr > 0.0 && fr <= 1.0) {
            return Err(WedgeError::InvalidParameter {
                name: "at",
                value: fp.text().to_string(),
                range: "(0, 1] (fractions r/(alpha t) of the contact half-width)".into(),
            });
        }
        let x = g.p() * fp.to_real(&g.p());
        out.push(real(&g.stress_hat(x).map_err(solver_err)?, digits));
    }
    Ok((out, g.error_estimate() / g.v_hat().to_f64().abs()))
}

/// One row of an alpha-V curve (the `solve` keys without the admissibility sweep).
pub fn curve_row(input: &CaseInput, alpha: &wedge::Param) -> Result<Map<String, Value>> {
    curve_row_unlabelled(input, alpha).map_err(|e| at_case(input, &Speed::Alpha(alpha.clone()), e))
}

fn curve_row_unlabelled(input: &CaseInput, alpha: &wedge::Param) -> Result<Map<String, Value>> {
    let alpha = alpha.clone();
    if input.solution == Solution::Genuine {
        return genuine_solve(input, &Speed::Alpha(alpha), false);
    }
    match input.precision()? {
        Precision::F64 => solve_report(
            &input.case(&Speed::Alpha(alpha), &0.0_f64)?,
            input.out_digits(),
            false,
        ),
        Precision::Bits(b) => solve_report(
            &input.case(&Speed::Alpha(alpha), &Float::with_val(b, 0))?,
            input.out_digits(),
            false,
        ),
    }
}

/// Parse points "x:y,x:y" (x/(c1 t), y/(c1 t)) into pairs; `name` goes into the error.
pub fn parse_points(name: &'static str, s: &str) -> Result<Vec<(wedge::Param, wedge::Param)>> {
    let bad = || WedgeError::InvalidParameter {
        name,
        value: s.to_string(),
        range: "comma-separated x:y pairs (x/(c1 t), y/(c1 t)) with y < 0 and x^2 + y^2 < 1".into(),
    };
    s.split(',')
        .map(|t| {
            let (a, b) = t.split_once(':').ok_or_else(bad)?;
            let x = wedge::Param::parse(name, a).map_err(|_| bad())?;
            let y = wedge::Param::parse(name, b).map_err(|_| bad())?;
            if !(y.value() < 0.0) {
                return Err(bad());
            }
            Ok((x, y))
        })
        .collect()
}

/// Keys of the `field` report, in order (arrays over the points).
pub const FIELD_KEYS: &[&str] = &[
    "x_over_c1_t",
    "y_over_c1_t",
    "sigma_xx_over_mu_cot_theta",
    "sigma_yy_over_mu_cot_theta",
    "sigma_xy_over_mu_cot_theta",
    "v_x_over_c1_cot_theta",
    "v_y_over_c1_cot_theta",
    "u_x_over_c1_t_cot_theta",
    "u_y_over_c1_t_cot_theta",
];

/// The field inside the half-plane at points (x/(c1 t), y/(c1 t)), y < 0, from the
/// homogeneous-function crate (eqs (10)-(12) with (16)); Cartesian components, y out of the
/// body. Points ahead of the P front (x^2 + y^2 >= 1) are at rest and give zeros.
pub fn field_report<T: CachedRules>(
    case: &Case<T>,
    pts: &[(wedge::Param, wedge::Param)],
    digits: usize,
) -> Result<Map<String, Value>> {
    let pot = case.potentials()?;
    let mut cols: Vec<Vec<Value>> = vec![Vec::new(); FIELD_KEYS.len()];
    for (x, y) in pts {
        let (xt, yt) = (x.to_real(case.p()), y.to_real(case.p()));
        let fv =
            homogeneous::field::at(&pot, &xt, &yt).map_err(|e| WedgeError::InvalidParameter {
                name: "at",
                value: format!("{}:{}", x.text(), y.text()),
                range: format!("a point of the half-plane y < 0 ({e})"),
            })?;
        let c = fv.cartesian();
        let vals = [xt, yt, c.sxx, c.syy, c.sxy, c.vx, c.vy, c.ux, c.uy];
        for (col, v) in cols.iter_mut().zip(vals.iter()) {
            col.push(real(v, digits));
        }
    }
    let mut o = Map::new();
    o.insert(
        "solution".into(),
        Value::String(case.solution().name().into()),
    );
    for (k, col) in FIELD_KEYS.iter().zip(cols) {
        o.insert((*k).into(), Value::Array(col));
    }
    o.insert("digits".into(), Value::Number(digits.into()));
    Ok(o)
}

/// Parse "a,b,c" into decimal parameters (kept as text for arbitrary precision).
pub fn parse_params(name: &'static str, s: &str) -> Result<Vec<wedge::Param>> {
    s.split(',').map(|t| wedge::Param::parse(name, t)).collect()
}

/// Parse a range "min,max,steps" (steps >= 2, min < max).
pub fn parse_range(name: &'static str, s: &str) -> Result<(wedge::Param, wedge::Param, usize)> {
    let bad = || WedgeError::InvalidParameter {
        name,
        value: s.to_string(),
        range: "min,max,steps with min < max and an integer steps >= 2".into(),
    };
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(bad());
    }
    let (lo, hi) = (
        wedge::Param::parse(name, parts[0])?,
        wedge::Param::parse(name, parts[1])?,
    );
    let n: f64 = parts[2].parse().map_err(|_| bad())?;
    if !(lo.value() < hi.value()) || n < 2.0 || n.fract() != 0.0 || n > 1e6 {
        return Err(bad());
    }
    Ok((lo, hi, n as usize))
}

/// `n` evenly spaced values from `lo` to `hi` (decimal texts), spaced at `bits` of precision
/// (at least 128) and kept as decimal text with the digits of that precision plus ten: each
/// grid point is parsed at the working precision exactly as the spacing computed it.
pub fn linspace(lo: &wedge::Param, hi: &wedge::Param, n: usize, bits: u32) -> Vec<wedge::Param> {
    let bits = bits.max(128) + 32;
    let like = Float::with_val(bits, 0);
    let (a, b): (Float, Float) = (lo.to_real(&like), hi.to_real(&like));
    let digits = (bits as f64 * std::f64::consts::LOG10_2).ceil() as usize + 10;
    (0..n)
        .map(|i| {
            if i == 0 {
                return lo.clone();
            }
            if i + 1 == n {
                return hi.clone();
            }
            let x = Float::with_val(bits, &b - &a) * (i as u32) / ((n - 1) as u32) + &a;
            let text = x.to_string_radix(10, Some(digits));
            wedge::Param::parse("alpha", &text).unwrap_or_else(|_| x.to_f64().into())
        })
        .collect()
}
