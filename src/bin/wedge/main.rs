//! `wedge`: the self-similar indentation of an elastic half-plane by a rigid wedge, from the
//! command line: a thin shell over the `dyncontact` library, which parses the flags and
//! prints the typed reports (`dyncontact::report::wedge`).
//!
//! Units: speeds in m/s, the half-angle in degrees. Outputs are dimensionless and their names
//! say how: `v_over_c1_cot_theta` = V/(c1 cot Theta), `force_over_a_mu_cot_theta` =
//! P/(alpha t mu cot Theta), `sigma_over_mu_cot_theta`, `r_over_alpha_t`, ...
//! Every output names its solution variant. Errors: one line on stderr, exit code 2.

use std::io::Write;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use dyncontact::cli::{emit, program};
use dyncontact::input::wedge::{check_spacing, linspace, parse_params, parse_points, parse_range};
use dyncontact::{
    solve, CaseInput, Selection, SolveReport, Speed, ADMISSIBILITY_KEYS, SIGN_KEYS, VERSION,
};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use rug::Float;
use wedge::{Coupling, Indenter, Material, Param, Result, Solution, WedgeError};

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
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Solve one case: Q, V (or alpha), force, apex regime, edge velocities, admissibility.
    Solve {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        speed: SpeedArgs,
        #[command(flatten)]
        out: OutArgs,
        #[command(flatten)]
        select: SelectArgs,
    },
    /// Contact stress sigma_theta/(mu cot Theta) at r/(alpha t) = the given fractions.
    Stress {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        speed: SpeedArgs,
        /// Comma-separated fractions r/(alpha t) in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        at: String,
        #[command(flatten)]
        out: OutArgs,
    },
    /// The field inside the half-plane (stresses, particle velocities, displacements, Cartesian,
    /// y out of the body) at points x/(c1 t):y/(c1 t) with y < 0.
    Field {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        speed: SpeedArgs,
        /// Comma-separated points x:y in units of c1 t, y < 0 (e.g. 0.1:-0.1,0.6:-0.5).
        #[arg(long, allow_hyphen_values = true)]
        at: String,
        #[command(flatten)]
        out: OutArgs,
    },
    /// The alpha-V relation (and force, Omega0, regime) over evenly spaced alpha.
    Curve {
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
    },
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
const CURVE_CAP: usize = 10_000;
/// Rows computed in parallel before they are printed (the curve streams in order).
const CURVE_CHUNK: usize = 32;

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
        if d == 0 || d > dyncontact::MAX_DIGITS {
            return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
                name: "digits",
                value: d.to_string(),
                range: format!("1 ..= {}", dyncontact::MAX_DIGITS),
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
        (None, None) => unreachable!("clap requires one of --alpha, --speed"),
    }
}

fn header_lines(input: &CaseInput) -> Vec<String> {
    let args: Vec<String> = std::env::args().collect();
    vec![
        format!("# dyncontact {VERSION}: dynamic wedge indentation of an elastic half-plane"),
        format!("# command: {}", args.join(" ")),
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

fn run(cli: Cli) -> Result<()> {
    let stdout = std::io::stdout();
    match cli.command {
        Command::Solve {
            case,
            speed,
            out,
            select,
        } => {
            let inp = input(&case, out.digits, Defaults::ByFriction)?;
            emit(
                &solve(&inp, &speed_of(&speed)?, &select.selection()?)?,
                out.json,
            );
        }
        Command::Stress {
            case,
            speed,
            at,
            out,
        } => {
            let inp = input(&case, out.digits, Defaults::ByFriction)?;
            let at = parse_params("at", &at)?;
            emit(
                &dyncontact::stress(&inp, &speed_of(&speed)?, &at)?,
                out.json,
            );
        }
        Command::Field {
            case,
            speed,
            at,
            out,
        } => {
            let inp = input(&case, out.digits, Defaults::Paper)?;
            let pts = parse_points("at", &at)?;
            emit(
                &dyncontact::field(&inp, &speed_of(&speed)?, &pts)?,
                out.json,
            );
        }
        Command::Curve {
            case,
            alpha_range,
            digits,
            csv: _,
            json,
            force,
            select,
        } => {
            let inp = input(&case, digits, Defaults::ByFriction)?;
            let sel = select.selection()?;
            let (lo, hi, n) = parse_range("alpha_range", &alpha_range)?;
            check_spacing("alpha_range", &alpha_range, &lo, &hi, n)?;
            // the bits the rows are computed with (double-double up to 30 digits)
            let bits = if inp.uses_double_double() {
                inp.precision()?
                    .bits()
                    .max(complexfn::double_double::DD_BITS)
            } else {
                inp.precision()?.bits()
            };
            if n > CURVE_CAP && !force {
                return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
                    name: "alpha_range steps",
                    value: n.to_string(),
                    range: format!("1 ..= {CURVE_CAP} (or add --force)"),
                }));
            }
            let alphas = linspace(&lo, &hi, n, bits);
            let bar = ProgressBar::new(n as u64);
            bar.set_style(
                ProgressStyle::with_template("{bar:40} {pos}/{len} alpha values")
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            // rows stream out in order, a chunk at a time (computed in parallel)
            let mut lock = stdout.lock();
            if json {
                write!(lock, "[").ok();
            } else {
                for l in header_lines(&inp) {
                    writeln!(lock, "{l}").ok();
                }
                if let Some(l) = flags_header(&sel) {
                    writeln!(lock, "{l}").ok();
                }
                writeln!(lock, "{}", SolveReport::csv_header(&sel)).ok();
            }
            let mut first = true;
            for chunk in alphas.chunks(CURVE_CHUNK) {
                let rows: Vec<Result<SolveReport>> = chunk
                    .par_iter()
                    .map(|a| {
                        let r = dyncontact::curve_row(&inp, a, &sel);
                        bar.inc(1);
                        r
                    })
                    .collect();
                for r in rows {
                    let r = match r {
                        Ok(r) => r,
                        Err(e) => {
                            bar.finish_and_clear();
                            // close what was printed, then fail with the row's error
                            if json {
                                writeln!(lock, "]").ok();
                            }
                            lock.flush().ok();
                            return Err(e);
                        }
                    };
                    if json {
                        let sep = if first { "" } else { "," };
                        write!(lock, "{sep}{}", r.to_json()).ok();
                    } else {
                        writeln!(lock, "{}", r.csv_row(&sel)).ok();
                        // a flag that could not be computed: why, after its row
                        for (k, why) in r.unavailable() {
                            if ADMISSIBILITY_KEYS.contains(&k) || SIGN_KEYS.contains(&k) {
                                writeln!(
                                    lock,
                                    "# alpha = {} m/s: {k} unavailable: {why}",
                                    r.alpha.text()
                                )
                                .ok();
                            }
                        }
                    }
                    first = false;
                }
                if lock.flush().is_err() {
                    // the reader has gone (a closed pipe): stop quietly
                    bar.finish_and_clear();
                    return Ok(());
                }
            }
            if json {
                writeln!(lock, "]").ok();
            }
            bar.finish_and_clear();
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    program("wedge", run)
}
