//! Dynamic contact mechanics of an elastic half-plane, as a library: the self-similar
//! indentation by a rigid wedge (crates `wedge`, `genuine`) and the transient impact of
//! strikers (crates `lamb`, `impact`), each case returned as a typed report
//! ([`report`]) whose numbers carry their error estimates. The command lines `wedge` and
//! `impact`, the `figures` generator and other front ends parse their inputs with
//! [`input`] and print the reports; they compute nothing themselves.
//!
//! For the wedge, one constructor, [`build`], solves any solution variant (the paper's construction or the
//! genuine solution) from the material, the indenter, the contact speed (alpha or V) and the
//! precision, behind one interface, [`wedge::ContactSolution`]. The report builders
//! ([`solve`], [`curve_row`], [`stress`], [`field`]) return typed reports
//! ([`report::wedge::SolveReport`], ...) whose numbers carry their own error estimates; the command
//! line serialises them. Field names are the report keys, which spell out the normalisation:
//! `v_over_c1_cot_theta` is V/(c1 cot Theta), `force_over_a_mu_cot_theta` is
//! P/(alpha t mu cot Theta), and so on.
#![warn(missing_docs)]
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accuracy;
pub mod cli;
pub mod error;
pub mod impact_api;
pub mod input;
pub mod report;
pub mod stability;

use complexfn::quadrature::CachedRules;
use complexfn::{Dd, Precision};
use genuine::GenuineSolver;
use rug::Float;
use wedge::{
    ContactSolution, Indenter, Material, PaperSolver, Result, Solution, Solver, WedgeError,
};

pub use error::{Error, InputError};
pub use report::wedge::{
    CaseInput, FieldReport, Item, Selection, SolveReport, Speed, StressReport, ADMISSIBILITY_KEYS,
    ADMISSIBILITY_NOT_COMPUTED, ALWAYS_KEYS, ESTIMATED_KEYS, FIELD_KEYS, SIGN_KEYS, SOLVE_KEYS,
};
pub use report::{print_floor, Entry, Quantity};

/// Library version, written into every output header.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The most significant digits a case is computed with (MPFR): `wedge --digits`, `impact
/// green --digits`.
pub const MAX_DIGITS: u32 = 2000;

/// Guard bits added to the precision that holds the requested digits.
pub const GUARD_BITS: u32 = 32;

/// Requests of at most this many digits are computed in double-double arithmetic
/// ([`complexfn::Dd`], 104 bits, no allocation), one solve per case, instead of MPFR: 5 to
/// 100 times faster. Each quantity's estimate is then that of 104-bit arithmetic (on the
/// paper's construction typically 1e-29 to 1e-28 relative, larger near the Rayleigh speed;
/// on the genuine solution 1e-28 to 1e-24, its least-squares solve losing more), a bound that
/// measured errors stay below (`tests/suite/double_double.rs`, `tests/suite/genuine_double_double.rs`).
/// Larger requests use MPFR (`docs/double-double.md`).
pub const DOUBLE_DOUBLE_DIGITS: u32 = 30;

/// The genuine solution's least-squares fit can leave fewer correct digits in double-double
/// than a request of up to [`DOUBLE_DOUBLE_DIGITS`] asks for (V to 1e-25 relative at
/// Theta 30 deg, to 4e-22 at Theta 5 deg; 1e-28 to 6e-28 at Theta 89 deg): a request of d
/// digits is answered in double-double only when V's relative estimate is at most
/// 10^(DOUBLE_DOUBLE_SLACK - d), and otherwise computed again on MPFR at d digits plus
/// [`GUARD_BITS`] (`docs/double-double.md`).
pub const DOUBLE_DOUBLE_SLACK: i32 = 3;

/// A solved case of any solution variant at precision `T`.
pub type Solved<T> = Box<dyn ContactSolution<T>>;

/// The solution variant of a [`CaseInput`] as a [`Solver`]: the one place that maps the
/// variant to its construction.
struct Variant<'a>(&'a CaseInput);

impl Solver for Variant<'_> {
    type Solved<T: CachedRules> = Solved<T>;
    fn material(&self) -> &Material {
        &self.0.material
    }
    fn indenter(&self) -> &Indenter {
        &self.0.indenter
    }
    fn solve<T: CachedRules>(&self, p: T) -> Result<Solved<T>> {
        let bits = p.prec();
        let s = solve_at(&self.0.material, &self.0.indenter, self.0.solution, p)?;
        let double_double = bits == complexfn::double_double::DD_BITS;
        if let (Solution::Genuine, Some(d), true) = (self.0.solution, self.0.digits, double_double)
        {
            let v = s.v_hat()?;
            let reached = v.error / v.value.to_f64().abs();
            let asked = 10f64.powi(DOUBLE_DOUBLE_SLACK - d as i32);
            if !(reached <= asked) {
                return Err(WedgeError::ShortOfPrecision {
                    bits,
                    reached,
                    asked,
                });
            }
        }
        Ok(s)
    }
}

/// The case of `solution` for contact speed p = alpha/c1 in (0, m_R), at the precision of
/// `p`: the paper's construction ([`wedge::Case`]) or the genuine solution
/// ([`genuine::GenuineCase`], with the solver options of that precision).
pub fn solve_at<T: CachedRules>(
    material: &Material,
    indenter: &Indenter,
    solution: Solution,
    p: T,
) -> Result<Solved<T>> {
    Ok(match solution {
        Solution::Genuine => Box::new(GenuineSolver::new(material, indenter).solve(p)?),
        s => Box::new(PaperSolver::new(material, indenter, s).solve(p)?),
    })
}

/// The case of `solver` for a contact speed, alpha given or V given (the inverse solve,
/// [`wedge::for_speed`]), at the precision of `like`.
fn solve_speed<S: Solver, T: CachedRules>(
    solver: &S,
    speed: &Speed,
    like: &T,
) -> Result<S::Solved<T>> {
    match speed {
        Speed::Alpha(a) => solver.solve_alpha(a, like),
        Speed::Indenter(v) => wedge::for_speed(solver, v, like),
    }
}

/// The one constructor of a solved case: material, indenter and solution variant from
/// `input`, the contact speed (alpha, or V through the inverse solve), at the precision of
/// `like`.
pub fn build<T: CachedRules>(input: &CaseInput, speed: &Speed, like: &T) -> Result<Solved<T>> {
    solve_speed(&Variant(input), speed, like)
}

/// [`build`] in double-double arithmetic ([`complexfn::Dd`]), compiled once, here: a caller
/// gets the solved case behind its trait object without instantiating the solvers at `Dd`
/// itself (release builds share no generic code between crates; the library's tests save
/// minutes of compile time this way). A genuine case with `digits` set is refused with
/// [`WedgeError::ShortOfPrecision`] where double-double falls short of them, as in
/// [`build`]; with `digits: None` it is the plain double-double solve.
pub fn build_dd(input: &CaseInput, speed: &Speed) -> Result<Solved<Dd>> {
    build(input, speed, &Dd::from_f64(0.0))
}

/// [`build`] on MPFR at `bits`, compiled once, here (as [`build_dd`]).
pub fn build_mpfr(input: &CaseInput, speed: &Speed, bits: u32) -> Result<Solved<Float>> {
    build(input, speed, &Float::with_val(bits, 0))
}

/// The genuine solution with the solver `options` at the contact speed `alpha` (m/s), on MPFR
/// at `bits`, compiled once, here (as [`build_dd`]): a reference computed with other rules
/// than those of its precision.
pub fn genuine_mpfr(
    material: &Material,
    indenter: &Indenter,
    options: genuine::SolveOptions,
    alpha: &wedge::Param,
    bits: u32,
) -> Result<Solved<Float>> {
    let solver = GenuineSolver::with_options(material, indenter, options);
    Ok(Box::new(
        solver.solve_alpha(alpha, &Float::with_val(bits, 0))?,
    ))
}

/// Work done at the working precision of a case ([`at_precision`]).
trait Job<R> {
    fn run<T: CachedRules>(&self, like: &T) -> Result<R>;
}

/// Runs `job` at the working precision of `input`: f64, double-double
/// ([`CaseInput::uses_double_double`]), or a `rug::Float` of its bits.
fn at_precision<R>(input: &CaseInput, job: &impl Job<R>) -> Result<R> {
    match input.precision()? {
        Precision::F64 => job.run(&0.0_f64),
        Precision::Bits(b) if input.uses_double_double() => {
            match job.run(&Dd::from_f64(0.0)) {
                // the genuine solution short of the request in double-double: on MPFR
                Err(WedgeError::ShortOfPrecision { .. }) => job.run(&Float::with_val(b, 0)),
                r => r,
            }
        }
        Precision::Bits(b) => job.run(&Float::with_val(b, 0)),
    }
}

/// The case's inputs in one line, for error messages (numbers to 7 significant digits).
pub fn describe(input: &CaseInput, speed: &Speed) -> String {
    let speed = match speed {
        Speed::Alpha(a) => format!("alpha = {} m/s", lamb::error::short(a.value())),
        Speed::Indenter(v) => format!("V = {} m/s", lamb::error::short(v.value())),
    };
    let short = |p: &wedge::Param| lamb::error::short(p.value());
    format!(
        "theta_deg = {}, gamma = {}, coupling {}, {speed}, c1 = {} m/s, c2 = {} m/s, solution {}, {}",
        short(input.indenter.theta_deg()),
        short(input.indenter.gamma()),
        input.indenter.coupling().name(),
        short(input.material.c1()),
        short(input.material.c2()),
        input.solution.name(),
        match input.digits {
            None => "f64".to_string(),
            Some(d) => format!("{d} digits ({})", input.arithmetic()),
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
                    | WedgeError::NotFinite { .. }
            );
            let undetermined = matches!(&other, WedgeError::Undetermined { .. });
            let inputs = describe(input, speed);
            WedgeError::AtCase {
                inputs: if overflow && input.digits.is_none() {
                    format!("{inputs} (the f64 range is exceeded here; try --digits)")
                } else if undetermined && input.digits.is_none() {
                    format!("{inputs} (try --digits)")
                } else {
                    inputs
                },
                error: Box::new(other),
            }
        }
    }
}

/// Solve a case and report the quantities `sel` wants, at the requested precision (the
/// admissibility checks, when selected, are sign checks made on the f64 twin of the case at
/// high precision). What the selection leaves out is not computed.
///
/// Every numeric quantity carries its own absolute estimate, from one solve: with `digits`
/// above [`DOUBLE_DOUBLE_DIGITS`] at the MPFR precision of `digits` plus [`GUARD_BITS`], up to
/// that many digits in double-double arithmetic. The estimates are the quadratures' own (level doubling,
/// round-off floors), never optimistic without a second solve (`docs/estimates.md`).
/// When the indenter speed is given, the inverse solve's uncertainty in alpha is carried
/// into every quantity through its slope (two f64 rows at nearby alpha).
///
/// The given speed (alpha or V) is echoed as its decimal text, whatever the digits printed.
pub fn solve(input: &CaseInput, speed: &Speed, sel: &Selection) -> Result<SolveReport> {
    let mut r = solve_unlabelled(input, speed, sel).map_err(|e| at_case(input, speed, e))?;
    match speed {
        Speed::Indenter(v) => {
            inverse_estimates(input, &mut r, sel).map_err(|e| at_case(input, speed, e))?;
            r.echo_speed(v);
        }
        Speed::Alpha(a) => r.echo_alpha(a),
    }
    Ok(r)
}

/// The sampled admissibility checks of `input` at the contact speed `alpha` made on its f64
/// twin (they are sign checks); a twin that f64 cannot solve is the checks' failure, with its
/// reason.
fn twin_admissibility(input: &CaseInput, alpha: &Speed) -> Result<wedge::Admissibility> {
    let f64_input = CaseInput {
        digits: None,
        ..input.clone()
    };
    build(&f64_input, alpha, &0.0_f64)
        .and_then(|twin| twin.admissibility())
        .map_err(|e| WedgeError::AtCase {
            inputs: "made on the case in f64".into(),
            error: Box::new(e),
        })
}

fn solve_unlabelled(input: &CaseInput, speed: &Speed, sel: &Selection) -> Result<SolveReport> {
    let digits = input.out_digits();
    let full = sel.wants_admissibility();
    let Precision::Bits(_) = input.precision()? else {
        let s = build(input, speed, &0.0_f64)?;
        let mut r = SolveReport::selected(&s, input, digits, sel)?;
        if full {
            r.set_admissibility(s.admissibility());
        }
        return Ok(r);
    };
    // one solve at the working precision (double-double where it reaches the request), whose
    // estimates bound its errors on their own
    let (mut r, p) = at_precision(input, &Rounded(input, speed, sel))?;
    if full {
        // the admissibility checks are sign checks: made on the f64 twin of the case
        let alpha = p * input.material.c1().value();
        r.set_admissibility(twin_admissibility(input, &Speed::Alpha(alpha.into())));
    }
    Ok(r)
}

/// A solve report with `digits + 10` digits rounded to the request, printed no finer than the
/// working precision allows, and the case's contact speed p.
struct Rounded<'a>(&'a CaseInput, &'a Speed, &'a Selection);

impl Job<(SolveReport, f64)> for Rounded<'_> {
    fn run<T: CachedRules>(&self, like: &T) -> Result<(SolveReport, f64)> {
        let digits = self.0.out_digits();
        let s = build(self.0, self.1, like)?;
        let r = SolveReport::selected(&s, self.0, digits + 10, self.2)?;
        Ok((
            r.rounded(digits, print_floor(digits, like.prec())),
            s.p().to_f64(),
        ))
    }
}

/// With V given, alpha is found by the inverse solve, which stops once |V(alpha) - V| is
/// within V's own estimate: alpha is uncertain by delta alpha = 2 delta V/(dV/d alpha), and
/// every quantity Q(alpha) by |dQ/d alpha| delta alpha more (with a margin of 10 percent).
/// The slopes are central differences of two f64 rows at alpha (1 +- 1e-5).
fn inverse_estimates(input: &CaseInput, r: &mut SolveReport, sel: &Selection) -> Result<()> {
    let alpha = r.alpha.value();
    let h = 1e-5;
    let f64_input = CaseInput {
        digits: None,
        ..input.clone()
    };
    let row = |a: f64| curve_row_unlabelled(&f64_input, &a.into(), sel, false);
    let (lo, hi) = (row(alpha * (1.0 - h))?, row(alpha * (1.0 + h))?);
    let slope = |k: &str| -> Option<f64> {
        let (a, b) = (lo.quantity(k)?.value(), hi.quantity(k)?.value());
        Some((b - a) / (2.0 * h * alpha))
    };
    let dv = slope("v_over_c1_cot_theta").unwrap_or(0.0).abs();
    if !(dv.is_finite() && dv > 0.0) {
        return Err(WedgeError::NoConvergence(complexfn::NoConvergence {
            what: "slope of the alpha-V relation".into(),
            reached: dv,
            asked: 0.0,
        }));
    }
    let d_alpha = 2.0 * r.v_over_c1_cot_theta.error() / dv;
    let c1 = input.material.c1().value();
    r.widen(|k| {
        1.1 * match k {
            "alpha" => d_alpha,
            "p" => d_alpha / c1,
            "m" | "m_r" | "speed" | "v_over_c1_cot_theta" => 0.0,
            _ => slope(k).map(f64::abs).unwrap_or(0.0) * d_alpha,
        }
    });
    Ok(())
}

/// One row of an alpha-V curve: the quantities `sel` wants of the `solve` report at the
/// requested precision (one solve, the estimates the solve's own), the admissibility flags
/// among them as in [`solve`] (the sampled ones on the f64 twin above f64), and alpha echoed
/// as given.
pub fn curve_row(input: &CaseInput, alpha: &wedge::Param, sel: &Selection) -> Result<SolveReport> {
    let speed = Speed::Alpha(alpha.clone());
    let checks = sel.wants_admissibility();
    let f64_path = input.digits.is_none();
    let mut r = curve_row_unlabelled(input, alpha, sel, checks && f64_path)
        .map_err(|e| at_case(input, &speed, e))?;
    if checks && !f64_path {
        r.set_admissibility(twin_admissibility(input, &speed));
    }
    r.echo_alpha(alpha);
    Ok(r)
}

/// A row at the working precision, with the sampled admissibility checks on the same solved
/// case when the last field is set.
struct Row<'a>(&'a CaseInput, Speed, &'a Selection, bool);

impl Job<SolveReport> for Row<'_> {
    fn run<T: CachedRules>(&self, like: &T) -> Result<SolveReport> {
        let s = build(self.0, &self.1, like)?;
        let mut r = SolveReport::selected(&s, self.0, self.0.out_digits(), self.2)?;
        if self.3 {
            r.set_admissibility(s.admissibility());
        }
        Ok(r)
    }
}

fn curve_row_unlabelled(
    input: &CaseInput,
    alpha: &wedge::Param,
    sel: &Selection,
    checks: bool,
) -> Result<SolveReport> {
    at_precision(input, &Row(input, Speed::Alpha(alpha.clone()), sel, checks))
}

struct Stress<'a>(&'a CaseInput, &'a Speed, &'a [wedge::Param]);

impl Job<StressReport> for Stress<'_> {
    fn run<T: CachedRules>(&self, like: &T) -> Result<StressReport> {
        StressReport::of(&build(self.0, self.1, like)?, self.2, self.0.out_digits())
    }
}

/// The contact stress of a case at fractions r/(alpha t) of the contact, in any solution
/// variant, each value with its estimate.
pub fn stress(input: &CaseInput, speed: &Speed, at: &[wedge::Param]) -> Result<StressReport> {
    let mut r =
        at_precision(input, &Stress(input, speed, at)).map_err(|e| at_case(input, speed, e))?;
    r.input = Some(input.clone());
    r.speed = Some(speed.clone());
    Ok(r)
}

struct Field<'a>(&'a CaseInput, &'a Speed, &'a [(wedge::Param, wedge::Param)]);

impl Job<FieldReport> for Field<'_> {
    fn run<T: CachedRules>(&self, like: &T) -> Result<FieldReport> {
        let inp = self.0;
        let solver = PaperSolver::new(&inp.material, &inp.indenter, inp.solution);
        FieldReport::of(
            &solve_speed(&solver, self.1, like)?,
            self.2,
            inp.out_digits(),
        )
    }
}

/// The field inside the half-plane at points (x/(c1 t), y/(c1 t)), y < 0: the paper's
/// construction only (the genuine solution is refused with the reason).
pub fn field(
    input: &CaseInput,
    speed: &Speed,
    pts: &[(wedge::Param, wedge::Param)],
) -> Result<FieldReport> {
    if input.solution == Solution::Genuine {
        return Err(WedgeError::Unsupported(
            "the field over the half-plane is computed for the paper's construction only: \
             use --solution paper or as-printed (solve, stress and curve take genuine)"
                .into(),
        ));
    }
    let mut r =
        at_precision(input, &Field(input, speed, pts)).map_err(|e| at_case(input, speed, e))?;
    r.input = Some(input.clone());
    r.speed = Some(speed.clone());
    Ok(r)
}
