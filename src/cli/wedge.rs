//! The `wedge` program's flags and what they compute: the subcommands `solve`, `stress`,
//! `field` and `curve` parsed by clap, each turned into its typed report
//! ([`crate::report::wedge`]). The binary prints them; other front ends (the Python package)
//! parse the same flags and take the same reports.

use std::ops::ControlFlow;

use clap::{Args, Parser, Subcommand, ValueEnum};
use rayon::prelude::*;
use rug::Float;
use wedge::{Coupling, Indenter, Material, Param, Result, Solution, WedgeError};

use crate::input::wedge::{check_spacing, linspace, parse_params, parse_points, parse_range};
use crate::report::wedge::{FieldReport, StressReport};
use crate::{CaseInput, Selection, SolveReport, Speed, ADMISSIBILITY_KEYS, SIGN_KEYS, VERSION};

/// The self-similar indentation of an elastic half-plane by a rigid wedge (plane strain, the
/// wedge paper), with Coulomb friction and tangential-displacement coupling.
///
/// Conventions: c1, c2 dilatational and shear wave speeds (m/s); Theta the wedge half-angle
/// (degrees); alpha the contact-zone expansion speed (0 < alpha < c_R); V the indenter speed;
/// gamma the friction coefficient; coupling on means beta = -cot Theta in the contact
/// condition u_theta + beta u_r = -V t + r cot Theta. Results are dimensionless: speeds over
/// c1 or V, stresses over mu cot Theta, displacements over c1 t cot Theta or V t.
#[derive(Parser, Debug)]
#[command(name = "wedge", version, arg_required_else_help = true)]
pub struct WedgeCli {
    /// The subcommand.
    #[command(subcommand)]
    pub command: Command,
}

/// The wedge program's subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Solve one case: Q, V (or alpha), force, apex regime, edge velocities, admissibility.
    Solve(SolveArgs),
    /// Contact stress sigma_theta/(mu cot Theta) at r/(alpha t) = the given fractions.
    Stress(StressArgs),
    /// The field inside the half-plane (stresses, particle velocities, displacements, Cartesian,
    /// y out of the body) at points x/(c1 t):y/(c1 t) with y < 0.
    Field(FieldArgs),
    /// The alpha-V relation (and force, Omega0, regime) over evenly spaced alpha.
    Curve(CurveArgs),
}

/// The flags of `wedge solve`.
#[derive(Args, Debug, Clone)]
pub struct SolveArgs {
    #[command(flatten)]
    case: CaseArgs,
    #[command(flatten)]
    speed: SpeedArgs,
    #[command(flatten)]
    out: OutArgs,
    #[command(flatten)]
    select: SelectArgs,
}

/// The flags of `wedge stress`.
#[derive(Args, Debug, Clone)]
pub struct StressArgs {
    #[command(flatten)]
    case: CaseArgs,
    #[command(flatten)]
    speed: SpeedArgs,
    /// Comma-separated fractions r/(alpha t) in (0, 1].
    #[arg(long, allow_hyphen_values = true)]
    at: String,
    #[command(flatten)]
    out: OutArgs,
}

/// The flags of `wedge field`.
#[derive(Args, Debug, Clone)]
pub struct FieldArgs {
    #[command(flatten)]
    case: CaseArgs,
    #[command(flatten)]
    speed: SpeedArgs,
    /// Comma-separated points x:y in units of c1 t, y < 0 (e.g. 0.1:-0.1,0.6:-0.5).
    #[arg(long, allow_hyphen_values = true)]
    at: String,
    #[command(flatten)]
    out: OutArgs,
}

/// The flags of `wedge curve`.
#[derive(Args, Debug, Clone)]
pub struct CurveArgs {
    #[command(flatten)]
    case: CaseArgs,
    /// min,max,steps of alpha in m/s (0 < min < max < c_R).
    #[arg(long = "alpha-range", allow_hyphen_values = true)]
    alpha_range: String,
    /// Digits (omit for the f64 path).
    #[arg(long)]
    digits: Option<u32>,
    /// CSV with '#' header lines (the default); --json for a JSON array instead.
    #[arg(long, conflicts_with = "json")]
    csv: bool,
    /// JSON array of objects.
    #[arg(long)]
    json: bool,
    /// Allow more than 10^4 points.
    #[arg(long)]
    force: bool,
    #[command(flatten)]
    select: SelectArgs,
}

#[derive(Args, Debug, Clone)]
struct SelectArgs {
    /// Compute and print only these report keys (comma-separated, e.g.
    /// v_over_c1_cot_theta,force_over_a_mu_cot_theta); the inputs, the solution variant, V,
    /// the regime and the error estimates of what is printed always come along. Default: all.
    #[arg(long)]
    quantities: Option<String>,
}

impl SelectArgs {
    fn selection(&self) -> Result<Selection> {
        match &self.quantities {
            None => Ok(Selection::all()),
            Some(list) => Selection::of(&list.split(',').collect::<Vec<_>>()),
        }
    }
}

/// The largest `curve` grid computed without `--force`.
pub const CURVE_CAP: usize = 10_000;
/// Rows computed in parallel before they are printed (the curve streams in order).
pub const CURVE_CHUNK: usize = 32;

#[derive(Args, Debug, Clone)]
struct CaseArgs {
    /// Dilatational wave speed c1 in m/s.
    #[arg(
        long,
        default_value = "1870.83",
        conflicts_with = "poisson",
        allow_hyphen_values = true
    )]
    c1: String,
    /// Shear wave speed c2 in m/s (must be below c1 sqrt(3)/2).
    #[arg(long, default_value = "1000", allow_hyphen_values = true)]
    c2: String,
    /// Poisson's ratio in (-1, 0.5), instead of --c1 (c1 then follows from c2), as decimal
    /// text kept at the working precision.
    #[arg(long, allow_hyphen_values = true)]
    poisson: Option<String>,
    /// Wedge half-angle Theta in degrees, in (0, 90).
    #[arg(long = "theta-deg", allow_hyphen_values = true)]
    theta_deg: String,
    /// Friction coefficient gamma >= 0, or `cot` for exactly cot Theta (the regime boundary).
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    gamma: String,
    /// Displacement coupling: on (beta = -cot Theta) or off (beta = 0).
    #[arg(long, value_enum, default_value_t = CouplingArg::On)]
    coupling: CouplingArg,
    /// Solution variant: genuine (no apex dislocation), paper (the paper's construction,
    /// consistent matching) or as-printed (the printed matching). Default: genuine when
    /// gamma > 0, paper when gamma = 0 (where the two coincide); `field` computes the paper's
    /// construction only and defaults to paper.
    #[arg(long)]
    solution: Option<String>,
}

#[derive(Args, Debug, Clone)]
#[group(required = true, multiple = false)]
struct SpeedArgs {
    /// Contact-zone expansion speed alpha in m/s, 0 < alpha < c_R (decimal text, kept at the
    /// working precision).
    #[arg(long, allow_hyphen_values = true)]
    alpha: Option<String>,
    /// Indenter speed V in m/s (alpha is then found by a bracketed root solve; decimal text).
    #[arg(long, allow_hyphen_values = true)]
    speed: Option<String>,
}

#[derive(Args, Debug, Clone)]
struct OutArgs {
    /// Significant digits (arbitrary precision); omit for the f64 path.
    #[arg(long)]
    digits: Option<u32>,
    /// Print JSON instead of a table.
    #[arg(long)]
    json: bool,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
enum CouplingArg {
    On,
    Off,
}

/// Which default variant a command uses when `--solution` is absent.
#[derive(Clone, Copy, PartialEq)]
enum Defaults {
    /// `Solution::default_for` the indenter (solve, stress, curve).
    ByFriction,
    /// Always `paper` (field: the paper's construction only).
    Paper,
}

fn input(case: &CaseArgs, digits: Option<u32>, defaults: Defaults) -> Result<CaseInput> {
    let c2 = Param::parse("c2", &case.c2)?;
    let material = match &case.poisson {
        Some(nu) => Material::from_poisson(Param::parse("poisson", nu)?, c2)?,
        None => Material::new(Param::parse("c1", &case.c1)?, c2)?,
    };
    let theta = Param::parse("theta_deg", &case.theta_deg)?;
    let coupling = match case.coupling {
        CouplingArg::On => Coupling::On,
        CouplingArg::Off => Coupling::Off,
    };
    let indenter = if case.gamma.trim() == "cot" {
        let probe = Indenter::new(theta.clone(), 0.0, coupling)?;
        let cot = probe.cot_theta(&Float::with_val(2048, 0));
        let text = cot.to_string_radix(10, Some(600));
        Indenter::new(theta, Param::parse("gamma", &text)?, coupling)?
    } else {
        Indenter::new(theta, Param::parse("gamma", &case.gamma)?, coupling)?
    };
    if let Some(d) = digits {
        if d == 0 || d > crate::MAX_DIGITS {
            return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
                name: "digits",
                value: d.to_string(),
                range: format!("1 ..= {}", crate::MAX_DIGITS),
            }));
        }
    }
    let solution = match (&case.solution, defaults) {
        (Some(name), _) => Solution::parse(name)?,
        (None, Defaults::ByFriction) => Solution::default_for(&indenter),
        (None, Defaults::Paper) => Solution::Paper,
    };
    // the field of the genuine solution is refused by `dyncontact::field`
    Ok(CaseInput {
        material,
        indenter,
        solution,
        digits,
    })
}

fn speed_of(s: &SpeedArgs) -> Result<Speed> {
    match (&s.alpha, &s.speed) {
        (Some(a), _) => Ok(Speed::Alpha(Param::parse("alpha", a)?)),
        (None, Some(v)) => Ok(Speed::Indenter(Param::parse("speed", v)?)),
        (None, None) => Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
            name: "alpha",
            value: "none".into(),
            range: "one of --alpha or --speed".into(),
        })),
    }
}

fn header_lines(input: &CaseInput, command_line: &str) -> Vec<String> {
    vec![
        format!("# dyncontact {VERSION}: dynamic wedge indentation of an elastic half-plane"),
        format!("# command: {command_line}"),
        format!(
            "# material: c1 = {} m/s, c2 = {} m/s; theta = {} deg, gamma = {}, coupling = {:?}; solution = {}",
            input.material.c1().text(),
            input.material.c2().text(),
            input.indenter.theta_deg().text(),
            input.indenter.gamma().text(),
            input.indenter.coupling(),
            input.solution.name()
        ),
        format!(
            "# precision: {}; {}",
            match input.digits {
                None => "f64".to_string(),
                Some(d) => format!("{d} digits"),
            },
            if input.solution == Solution::Genuine {
                "spectral collocation of the contact pressure (error estimate from two basis sizes)"
            } else {
                "quadrature: tanh-sinh (outer, tolerance eps^0.9), Gauss-Legendre in u = v^2 (inner, converged by doubling)"
            }
        ),
        "# normalisation: speeds in m/s; v_over_c1_cot_theta = V/(c1 cot Theta); force_over_a_mu_cot_theta = P/(alpha t mu cot Theta); velocities over V".into(),
    ]
}

/// The `#` line of a curve's CSV that says what its admissibility columns hold, when it has
/// any.
fn flags_header(sel: &Selection) -> Option<String> {
    let sign: Vec<&str> = SIGN_KEYS.iter().copied().filter(|k| sel.wants(k)).collect();
    let sampled: Vec<&str> = ADMISSIBILITY_KEYS
        .iter()
        .copied()
        .filter(|k| sel.wants(k))
        .collect();
    if sign.is_empty() && sampled.is_empty() {
        return None;
    }
    let mut parts = Vec::new();
    if !sign.is_empty() {
        parts.push(format!(
            "{} (V > 0 and the normal force P > 0, each beyond its estimate, at the working precision)",
            sign.join(", ")
        ));
    }
    if !sampled.is_empty() {
        parts.push(format!(
            "{} (sign checks sampling the contact and its outside, on each row's case in f64)",
            sampled.join(", ")
        ));
    }
    Some(format!(
        "# admissibility, computed per row: {}; a flag that cannot be computed is an empty cell, its reason on a # line after the row",
        parts.join("; ")
    ))
}

impl SolveArgs {
    /// Whether JSON was asked for (`--json`) instead of a table.
    pub fn json(&self) -> bool {
        self.out.json
    }
    /// The solved case's report ([`crate::solve`]).
    pub fn report(&self) -> Result<SolveReport> {
        let inp = input(&self.case, self.out.digits, Defaults::ByFriction)?;
        crate::solve(&inp, &speed_of(&self.speed)?, &self.select.selection()?)
    }
}

impl StressArgs {
    /// Whether JSON was asked for (`--json`) instead of a table.
    pub fn json(&self) -> bool {
        self.out.json
    }
    /// The contact stress's report ([`crate::stress`]).
    pub fn report(&self) -> Result<StressReport> {
        let inp = input(&self.case, self.out.digits, Defaults::ByFriction)?;
        let at = parse_params("at", &self.at)?;
        crate::stress(&inp, &speed_of(&self.speed)?, &at)
    }
}

impl FieldArgs {
    /// Whether JSON was asked for (`--json`) instead of a table.
    pub fn json(&self) -> bool {
        self.out.json
    }
    /// The field's report ([`crate::field`]).
    pub fn report(&self) -> Result<FieldReport> {
        let inp = input(&self.case, self.out.digits, Defaults::Paper)?;
        let pts = parse_points("at", &self.at)?;
        crate::field(&inp, &speed_of(&self.speed)?, &pts)
    }
}

impl CurveArgs {
    /// Whether JSON was asked for (`--json`) instead of CSV.
    pub fn json(&self) -> bool {
        self.json
    }
    /// The curve's case, selection and alpha grid, checked: at most [`CURVE_CAP`] points
    /// without `--force`, the points distinct at the working precision.
    pub fn plan(&self) -> Result<CurvePlan> {
        let input = input(&self.case, self.digits, Defaults::ByFriction)?;
        let selection = self.select.selection()?;
        let (lo, hi, n) = parse_range("alpha_range", &self.alpha_range)?;
        check_spacing("alpha_range", &self.alpha_range, &lo, &hi, n)?;
        // the bits the rows are computed with (double-double up to 30 digits)
        let bits = if input.uses_double_double() {
            input
                .precision()?
                .bits()
                .max(complexfn::double_double::DD_BITS)
        } else {
            input.precision()?.bits()
        };
        if n > CURVE_CAP && !self.force {
            return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
                name: "alpha_range steps",
                value: n.to_string(),
                range: format!("1 ..= {CURVE_CAP} (or add --force)"),
            }));
        }
        Ok(CurvePlan {
            alphas: linspace(&lo, &hi, n, bits),
            input,
            selection,
        })
    }
}

/// An alpha-V curve to compute: its case, the quantities of each row, and alpha's values.
#[derive(Clone, Debug)]
pub struct CurvePlan {
    /// The case (all but alpha).
    pub input: CaseInput,
    /// The quantities of each row.
    pub selection: Selection,
    /// alpha's values in m/s, in order.
    pub alphas: Vec<Param>,
}

impl CurvePlan {
    /// Computes the rows in order, [`CURVE_CHUNK`] at a time in parallel (rayon), handing
    /// each chunk to `rows` as soon as it is done. `before_row` is asked before each row is
    /// computed. When either answers [`ControlFlow::Break`], no further row is computed and
    /// the call returns `Ok(false)` (a chunk stopped part-way is not handed on); `Ok(true)`
    /// when every row was handed on. A row that fails ends the curve with its error, after
    /// the rows before it were handed on.
    pub fn rows(
        &self,
        before_row: impl Fn() -> ControlFlow<()> + Sync,
        mut rows: impl FnMut(Vec<SolveReport>) -> ControlFlow<()>,
    ) -> Result<bool> {
        for chunk in self.alphas.chunks(CURVE_CHUNK) {
            let done: Vec<Option<Result<SolveReport>>> = chunk
                .par_iter()
                .map(|a| {
                    before_row()
                        .is_continue()
                        .then(|| crate::curve_row(&self.input, a, &self.selection))
                })
                .collect();
            let Some(done) = done.into_iter().collect::<Option<Vec<_>>>() else {
                return Ok(false);
            };
            let mut ok = Vec::with_capacity(done.len());
            let mut failed = None;
            for r in done {
                match r {
                    Ok(r) => ok.push(r),
                    Err(e) => {
                        failed = Some(e);
                        break;
                    }
                }
            }
            let answer = rows(ok);
            if let Some(e) = failed {
                return Err(e);
            }
            if answer.is_break() {
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// The `#` lines that open the curve's CSV: the program, `command_line`, the case, the
    /// precision, the normalisation, and what the admissibility columns hold.
    pub fn header_lines(&self, command_line: &str) -> Vec<String> {
        let mut lines = header_lines(&self.input, command_line);
        lines.extend(flags_header(&self.selection));
        lines
    }
}
