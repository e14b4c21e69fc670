//! `impact`: transient contact of strikers with an elastic half-plane, from the command line.
//!
//! `impact green` prints Lamb's surface influence functions of the half-plane (crate `lamb`):
//! for a line force at x = 0, z into the medium, s = |x|/(c1 t),
//! u = I/(pi mu t) g(s) for an impulse I delta(t) and u = P/(pi mu) W(s) for a step P H(t).
//! Keys: `g_zz`, `g_xz`, `g_xx` (u_z from a normal force, u_x from a normal force for x > 0,
//! u_x from a tangential force; u_z from a tangential force is -g_xz), `W_zz`, `U_xz`, `U_xx`
//! (the step responses); for cells [sa, sb], `Ix_*` = Int g ds (a spatial cell at fixed t) and
//! `It_*` = Int g/s ds = W(sa) - W(sb) (a temporal cell at fixed x), principal values across
//! s_R and the Rayleigh delta of the cross terms counted inside; `--constants` adds s_R, the
//! residues r_zz, r_xx of g at s_R and the delta weight K_R. Every value comes with its
//! absolute error estimate under `error_estimate`. Errors: one line on stderr, exit code 2.

use std::io::Write;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
use cli::num;
use complexfn::quadrature::CachedRules;
use complexfn::{Precision, Real};
use dyncontact::VERSION;
use lamb::{Estimate, HalfPlane, LambError, Triple};
use rug::Float;
use serde_json::{Map, Value};

/// Transient contact of strikers with an elastic half-plane (plane strain): Lamb's surface
/// influence functions and their cell integrals.
#[derive(Parser, Debug)]
#[command(name = "impact", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Lamb's surface influence functions g(s), step responses W(s), cell integrals and the
    /// Rayleigh constants of the half-plane.
    Green(GreenArgs),
    /// Transient impact of a rigid striker on the half-plane: histories of the penetration,
    /// the contact half-width, the force, energies and pressure profiles, each with an error
    /// estimate from grid refinement.
    Run(impact_run::RunArgs),
    /// The power law p ~ d^lambda of the contact pressure at a contact edge moving at speed
    /// D, for each speed range and edge law (docs/edge.md).
    Edge(impact_edge::EdgeArgs),
}

#[path = "../cli.rs"]
mod cli;

#[path = "../impact_run.rs"]
mod impact_run;

#[path = "../impact_edge.rs"]
mod impact_edge;

#[derive(Args, Debug)]
struct GreenArgs {
    /// P-wave speed c1 in m/s (with --c2).
    #[arg(long, allow_hyphen_values = true)]
    c1: Option<String>,
    /// S-wave speed c2 in m/s (with --c1).
    #[arg(long, allow_hyphen_values = true)]
    c2: Option<String>,
    /// Poisson's ratio nu in (-1, 1/2) (instead of --c1, --c2).
    #[arg(long, allow_hyphen_values = true)]
    poisson: Option<String>,
    /// Comma-separated points s = |x|/(c1 t) >= 0 (not s_R) for pointwise values.
    #[arg(long, allow_hyphen_values = true)]
    at: Option<String>,
    /// Comma-separated cells sa:sb with 0 <= sa <= sb (for sa = 0, It diverges and is reported
    /// unavailable with the reason).
    #[arg(long, allow_hyphen_values = true)]
    cells: Option<String>,
    /// Print the Rayleigh constants s_R, r_zz, r_xx, K_R.
    #[arg(long)]
    constants: bool,
    /// Significant decimal digits (arbitrary precision); omit for f64.
    #[arg(long)]
    digits: Option<u32>,
    /// JSON output (default: CSV with a `#` header).
    #[arg(long)]
    json: bool,
}

#[derive(Debug)]
struct CliError(String);

impl From<LambError> for CliError {
    fn from(e: LambError) -> Self {
        CliError(e.to_string())
    }
}

impl From<complexfn::Error> for CliError {
    fn from(e: complexfn::Error) -> Self {
        CliError(e.to_string())
    }
}

type CliResult<T> = std::result::Result<T, CliError>;

fn parse_num<T: Real>(name: &str, text: &str, bits: u32) -> CliResult<T> {
    let v = T::parse_prec(text, bits)
        .map_err(|_| CliError(format!("invalid {name} = {text:?}: not a number")))?;
    if !v.is_finite() {
        return Err(CliError(format!("invalid {name} = {text}: must be finite")));
    }
    Ok(v)
}

fn split_list(name: &str, text: &str) -> CliResult<Vec<String>> {
    let items: Vec<String> = text.split(',').map(|s| s.trim().to_string()).collect();
    if items.iter().any(|s| s.is_empty()) {
        return Err(CliError(format!(
            "invalid {name} = {text:?}: a comma-separated list of numbers"
        )));
    }
    Ok(items)
}

/// The half-plane from --c1/--c2 or --poisson at the precision of `bits`.
fn half_plane<T: CachedRules>(a: &GreenArgs, bits: u32) -> CliResult<HalfPlane<T>> {
    match (&a.c1, &a.c2, &a.poisson) {
        (None, None, Some(nu)) => {
            let nu: T = parse_num("--poisson", nu, bits)?;
            Ok(HalfPlane::from_poisson(nu)?)
        }
        (Some(c1), Some(c2), None) => {
            let c1: T = parse_num("--c1", c1, bits)?;
            let c2: T = parse_num("--c2", c2, bits)?;
            if c1.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
                || c2.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
            {
                return Err(CliError(format!(
                    "invalid --c1, --c2 = {}, {}: wave speeds must be > 0 m/s",
                    c1.to_f64(),
                    c2.to_f64()
                )));
            }
            Ok(HalfPlane::new(c2 / &c1)?)
        }
        (None, None, None) => Err(CliError(
            "missing material: give --poisson NU, or --c1 and --c2 (m/s)".into(),
        )),
        (_, _, Some(_)) => Err(CliError(
            "contradictory material: give either --poisson or --c1 and --c2, not both".into(),
        )),
        _ => Err(CliError(
            "incomplete material: --c1 and --c2 go together (m/s)".into(),
        )),
    }
}

struct Out {
    digits: usize,
}

impl Out {
    fn real<T: Real>(&self, x: &T) -> Value {
        num(&x.to_decimal(self.digits))
    }
    fn err(&self, e: f64) -> Value {
        num(&format!("{:.2e}", e.max(0.0)))
    }
}

fn triple_into(
    out: &Out,
    rec: &mut Map<String, Value>,
    errs: &mut Map<String, Value>,
    pre: &str,
    t: Triple<Estimate<impl Real>>,
) {
    for (k, e) in [("zz", t.zz), ("xz", t.xz), ("xx", t.xx)] {
        let key = match pre {
            "W" if k == "zz" => "W_zz".to_string(),
            "W" => format!("U_{k}"),
            p => format!("{p}_{k}"),
        };
        rec.insert(key.clone(), out.real(&e.value));
        errs.insert(key, out.err(e.error));
    }
}

fn green<T: CachedRules>(a: &GreenArgs, bits: u32, digits: usize) -> CliResult<Value> {
    let hp: HalfPlane<T> = half_plane(a, bits)?;
    let out = Out { digits };
    let mut report = Map::new();
    report.insert("version".into(), Value::String(VERSION.into()));
    report.insert("poisson".into(), out.real(&hp.poisson()));
    report.insert("c2_over_c1".into(), out.real(hp.m()));
    report.insert("precision_bits".into(), Value::Number(bits.into()));
    if a.at.is_none() && a.cells.is_none() && !a.constants {
        return Err(CliError(
            "nothing asked: give --at s1,s2,..., --cells sa:sb,... or --constants".into(),
        ));
    }
    if let Some(at) = &a.at {
        let mut points = Vec::new();
        for text in split_list("--at", at)? {
            let s: T = parse_num("s", &text, bits)?;
            if s == 0.0 {
                return Err(CliError(
                    "invalid s = 0: admissible range is (0, inf) for pointwise values (the step responses diverge at s = 0, i.e. at x = 0 or t -> inf)".into(),
                ));
            }
            let mut rec = Map::new();
            let mut errs = Map::new();
            rec.insert("s".into(), out.real(&s));
            triple_into(&out, &mut rec, &mut errs, "g", hp.impulse(&s)?);
            triple_into(&out, &mut rec, &mut errs, "W", hp.step(&s)?);
            rec.insert("error_estimate".into(), Value::Object(errs));
            points.push(Value::Object(rec));
        }
        report.insert("points".into(), Value::Array(points));
    }
    if let Some(cells) = &a.cells {
        let mut list = Vec::new();
        for text in split_list("--cells", cells)? {
            let (sa, sb) = text.split_once(':').ok_or_else(|| {
                CliError(format!(
                    "invalid cell {text:?}: write sa:sb with 0 <= sa <= sb"
                ))
            })?;
            let sa: T = parse_num("sa", sa, bits)?;
            let sb: T = parse_num("sb", sb, bits)?;
            if sa > sb {
                return Err(CliError(format!(
                    "invalid cell {text}: admissible range is 0 <= sa <= sb"
                )));
            }
            let mut rec = Map::new();
            let mut errs = Map::new();
            rec.insert("sa".into(), out.real(&sa));
            rec.insert("sb".into(), out.real(&sb));
            triple_into(&out, &mut rec, &mut errs, "Ix", hp.cell(0, &sa, &sb)?);
            if sa == 0.0 {
                // It = W(0) - W(sb) diverges (W grows like (1 - nu) ln(1/s)): unavailable
                for k in ["It_zz", "It_xz", "It_xx"] {
                    rec.insert(k.into(), Value::Null);
                }
                let mut why = Map::new();
                why.insert(
                    "It".into(),
                    Value::String(
                        "diverges for sa = 0: the step response grows like (1 - nu) ln(1/s) as s -> 0"
                            .into(),
                    ),
                );
                rec.insert("unavailable".into(), Value::Object(why));
            } else {
                triple_into(&out, &mut rec, &mut errs, "It", hp.cell(1, &sa, &sb)?);
            }
            rec.insert("error_estimate".into(), Value::Object(errs));
            list.push(Value::Object(rec));
        }
        report.insert("cells".into(), Value::Array(list));
    }
    if a.constants {
        let c = hp.rayleigh_constants();
        let mut rec = Map::new();
        rec.insert("s_R".into(), out.real(&c.s_r));
        rec.insert("r_zz".into(), out.real(&c.r_zz));
        rec.insert("r_xx".into(), out.real(&c.r_xx));
        rec.insert("K_R".into(), out.real(&c.k_r));
        report.insert("constants".into(), Value::Object(rec));
    }
    Ok(Value::Object(report))
}

/// CSV with a `#` header: the material, then one table per section.
fn csv(v: &Value, cmdline: &str) -> String {
    let mut out = String::new();
    let mut println = |line: String| {
        out.push_str(&line);
        out.push('\n');
    };
    println(format!("# impact {VERSION}: Lamb's surface influence functions (units c1 = 1, mu = 1; u = I/(pi mu t) g(s), u = P/(pi mu) W(s), s = |x|/(c1 t))"));
    println(format!("# command: {cmdline}"));
    for key in ["poisson", "c2_over_c1", "precision_bits"] {
        println(format!("# {key} = {}", v[key]));
    }
    if let Some(c) = v.get("constants").and_then(Value::as_object) {
        for (k, x) in c {
            println(format!("# {k} = {x}"));
        }
    }
    for (section, cols) in [
        (
            "points",
            &["s", "g_zz", "g_xz", "g_xx", "W_zz", "U_xz", "U_xx"][..],
        ),
        (
            "cells",
            &[
                "sa", "sb", "Ix_zz", "Ix_xz", "Ix_xx", "It_zz", "It_xz", "It_xx",
            ][..],
        ),
    ] {
        let Some(rows) = v.get(section).and_then(Value::as_array) else {
            continue;
        };
        let errs: Vec<String> = cols
            .iter()
            .filter(|c| !c.starts_with('s'))
            .map(|c| format!("err_{c}"))
            .collect();
        println(format!("{},{}", cols.join(","), errs.join(",")));
        for r in rows {
            // an unavailable value (see the JSON's `unavailable`) is an empty field
            let field = |v: &Value| {
                if v.is_null() {
                    String::new()
                } else {
                    v.to_string()
                }
            };
            let mut line: Vec<String> = cols.iter().map(|c| field(&r[*c])).collect();
            for c in cols.iter().filter(|c| !c.starts_with('s')) {
                line.push(field(&r["error_estimate"][*c]));
            }
            println(line.join(","));
        }
    }
    out
}

/// Prints a report as JSON or as CSV with `#` headers (the full command line in them).
fn emit(v: &Value, json: bool, to_csv: impl Fn(&Value, &str) -> String) {
    let text = if json {
        serde_json::to_string_pretty(v).unwrap_or_default() + "\n"
    } else {
        let cmdline: Vec<String> = std::env::args().collect();
        to_csv(v, &cmdline.join(" "))
    };
    // a closed pipe (e.g. `| head`) ends the output quietly
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}

fn run(cli: Cli) -> CliResult<()> {
    match cli.command {
        Command::Green(a) => {
            let v = match a.digits {
                None => green::<f64>(&a, 53, 17)?,
                Some(d) => {
                    let p = Precision::from_digits(d, 24)?;
                    green::<Float>(&a, p.bits(), d as usize)?
                }
            };
            emit(&v, a.json, csv);
            Ok(())
        }
        Command::Run(a) => {
            let v = impact_run::run(&a, VERSION).map_err(CliError)?;
            emit(&v, impact_run::wants_json(&a), impact_run::csv);
            Ok(())
        }
        Command::Edge(a) => {
            let v = impact_edge::run(&a, VERSION).map_err(CliError)?;
            emit(&v, a.json, impact_edge::csv);
            Ok(())
        }
    }
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            if !e.use_stderr() {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            // one line: clap's first line, without the usage block
            let text = e.to_string();
            let first = text.lines().next().unwrap_or("invalid arguments");
            eprintln!("impact: {}", first.trim_start_matches("error: "));
            return ExitCode::from(2);
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(CliError(msg)) => {
            eprintln!("impact: {msg}");
            ExitCode::from(2)
        }
    }
}
