//! `impact`: the transient impact of rigid, elastic and thin-shell strikers on an elastic
//! half-plane, from the command line: a thin shell over `dyncontact::impact_api`, which
//! parses the flags and prints the typed reports (`dyncontact::report::impact`).
//!
//! `impact run` marches an impact and prints its histories with their error estimates;
//! `impact green` prints Lamb's surface influence functions of the half-plane (for a line
//! force at x = 0, z into the medium, s = |x|/(c1 t): u = I/(pi mu t) g(s) for an impulse
//! I delta(t) and u = P/(pi mu) W(s) for a step P H(t); keys `g_zz`, `g_xz`, `g_xx`,
//! `W_zz`, `U_xz`, `U_xx`, cell integrals `Ix_*` = Int g ds and `It_*` = Int g/s ds,
//! `--constants` for s_R, r_zz, r_xx and K_R); `impact edge` prints the power law of the
//! pressure at a moving contact edge. Every value comes with its absolute error estimate.
//! Errors: one line on stderr, exit code 2.

use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
use dyncontact::cli::{emit, program, MaterialArgs};
use dyncontact::impact_api::{self, EdgeInput, GreenInput, RunInput};
use dyncontact::Error;

/// The transient impact of strikers on an elastic half-plane (plane strain, the impact
/// paper): rigid, elastic and thin-shell strikers over a whole impact to their rebound,
/// Lamb's surface influence functions, and the pressure at a moving contact edge.
#[derive(Parser, Debug)]
#[command(name = "impact", version, arg_required_else_help = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Lamb's surface influence functions g(s), step responses W(s), cell integrals and the
    /// Rayleigh constants of the half-plane.
    Green(GreenArgs),
    /// The transient impact of a striker on the half-plane, rigid, elastic (the local
    /// half-plane model) or a thin cylindrical shell, free or driven: histories of the
    /// penetration, the contact half-width, the force, energies and pressure profiles, the
    /// rebound, each with an error estimate from grid refinement.
    Run(RunArgs),
    /// The power law p ~ d^lambda of the contact pressure at a contact edge moving at speed
    /// D, for each speed range and edge law (docs/edge.md).
    Edge(EdgeArgs),
}

/// Arguments of `impact green`.
#[derive(Args, Debug)]
struct GreenArgs {
    #[command(flatten)]
    material: MaterialArgs,
    /// Comma-separated points s = |x|/(c1 t) > 0 (not s_R) for pointwise values.
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

/// Arguments of `impact run`.
#[derive(Args, Debug)]
struct RunArgs {
    #[command(flatten)]
    material: MaterialArgs,
    /// The striker: `rigid`; `elastic:c1=..,c2=..,density_ratio=..` (its wave speeds in m/s,
    /// its density over the half-plane's; local half-plane model, valid until c1 t/R =
    /// 2 c1/c1s); `shell:thickness_over_R=..,c1=..,c2=..,density_ratio=..` (a thin
    /// cylindrical shell of radius R, its mass from its geometry). Deformable strikers need
    /// the half-plane's --c1 and --c2.
    #[arg(long, default_value = "rigid")]
    striker: String,
    /// The profile: circle:R=.., parabola:R=.., power:A=..,k=.., wedge:theta_deg=..,
    /// flat:a=.., table:FILE (two columns x f in metres, from x = 0).
    #[arg(long)]
    profile: Option<String>,
    /// m0/(rho R^2), the striker's mass per unit length (free striker; a shell's follows
    /// from its geometry).
    #[arg(long, allow_hyphen_values = true)]
    mass_ratio: Option<f64>,
    /// V0/c1, the initial speed (free striker).
    #[arg(long, allow_hyphen_values = true)]
    v0_over_c1: Option<f64>,
    /// Prescribed penetration instead of the equation of motion: speed:V_over_c1=.. or
    /// table:FILE (two columns c1 t/R, h/R from (0, 0)).
    #[arg(long)]
    driven: Option<String>,
    /// The edge law: signorini (unilateral conditions) or kinematic (eq (4), f(b) = h).
    #[arg(long, default_value = "signorini")]
    law: String,
    /// End time: c1t/R=VALUE (the last reported time exactly), or `separation` (shortly
    /// after the free striker leaves the surface; at most c1 t/R = 400) or
    /// `separation:max=VALUE` (at most c1 t/R = VALUE).
    #[arg(long)]
    end: Option<String>,
    /// The length scale R in metres for the flat punch, the wedge and the power law (the
    /// radius for the circle and the parabola).
    #[arg(long, allow_hyphen_values = true)]
    length: Option<f64>,
    /// Cell width dx/R of the finest grid.
    #[arg(long, default_value_t = 0.005, allow_hyphen_values = true)]
    dx: f64,
    /// kappa = c1 dt/dx, in [0.5, 64].
    #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
    kappa: f64,
    /// Refinement levels for the error estimates (1 to 4).
    #[arg(long, default_value_t = 3)]
    levels: usize,
    /// The edge cell: `model` (the local behaviour of the pressure at a moving edge, the
    /// edge inside its cell) or `whole` (whole cells, the edge captured cell by cell), for
    /// comparing the two.
    #[arg(long, default_value = "model")]
    edge_cell: String,
    /// Pressure profiles at these times: c1t/R=T1,T2,...
    #[arg(long)]
    pressure_at: Option<String>,
    /// JSON output (default: CSV with `#` headers).
    #[arg(long)]
    json: bool,
    /// Significant digits of the reported values (1 to 30): the march in double-double,
    /// the discrete solution of the same grids to that many digits (regression data for the
    /// scheme; the error estimates stay those of the discretisation). Rigid strikers; the
    /// inputs are taken as their nearest doubles. Omit for f64.
    #[arg(long)]
    digits: Option<u32>,
    /// Run even when the estimated memory exceeds the limit (4 GiB by default, or
    /// --memory-limit-gib).
    #[arg(long)]
    force: bool,
    /// The memory limit in GiB above which a run is refused without --force.
    #[arg(long, default_value_t = impact::cost::DEFAULT_MEMORY_LIMIT_GIB)]
    memory_limit_gib: f64,
}

/// Arguments of `impact edge`.
#[derive(Args, Debug)]
struct EdgeArgs {
    #[command(flatten)]
    material: MaterialArgs,
    /// Comma-separated edge speeds D/c1 > 0 (not c_R/c1, c2/c1 or 1).
    #[arg(long, allow_hyphen_values = true)]
    speed_over_c1: Option<String>,
    /// The edge law: `signorini` (a free edge) or `kinematic` (a prescribed edge, f(b) = h).
    #[arg(long, default_value = "signorini")]
    law: String,
    /// JSON output (default: CSV with `#` header lines).
    #[arg(long)]
    json: bool,
}

/// Seconds after which a run shows its progress.
const PROGRESS_AFTER_S: f64 = 2.0;

/// Runs `impact run`, its progress on stderr once it has taken a few seconds (hidden by
/// indicatif where stderr is not a terminal).
fn run_with_progress(input: &RunInput) -> Result<dyncontact::report::impact::RunReport, Error> {
    let bar = indicatif::ProgressBar::with_draw_target(
        Some(1000),
        indicatif::ProgressDrawTarget::hidden(),
    );
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{bar:40} {percent}% {msg} elapsed {elapsed} remaining ~{eta}",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let start = std::time::Instant::now();
    let mut shown = false;
    let r = impact_api::run(input, |p: impact::Progress| {
        if !shown && start.elapsed().as_secs_f64() > PROGRESS_AFTER_S {
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            shown = true;
        }
        bar.set_message(format!(
            "level {} step {} c1t/R {:.3}",
            p.level, p.step, p.t
        ));
        bar.set_position((p.fraction * 1000.0) as u64);
    });
    bar.finish_and_clear();
    r
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Green(a) => {
            let input = GreenInput {
                c1: a.material.c1,
                c2: a.material.c2,
                poisson: a.material.poisson,
                at: a.at,
                cells: a.cells,
                constants: a.constants,
                digits: a.digits,
            };
            emit(&impact_api::green(&input)?, a.json);
        }
        Command::Run(a) => {
            let (c1, c2, poisson) = a.material.numbers()?;
            let input = RunInput {
                c1,
                c2,
                poisson,
                striker: a.striker,
                profile: a.profile.unwrap_or_default(),
                mass_ratio: a.mass_ratio,
                v0_over_c1: a.v0_over_c1,
                driven: a.driven,
                law: a.law,
                end: a.end.unwrap_or_default(),
                length: a.length,
                dx: a.dx,
                kappa: a.kappa,
                levels: a.levels,
                edge_cell: a.edge_cell,
                pressure_at: a.pressure_at,
                digits: a.digits,
                force: a.force,
                memory_limit_gib: a.memory_limit_gib,
            };
            emit(&run_with_progress(&input)?, a.json);
        }
        Command::Edge(a) => {
            let (c1, c2, poisson) = a.material.numbers()?;
            let input = EdgeInput {
                c1,
                c2,
                poisson,
                speed_over_c1: a.speed_over_c1,
                law: a.law,
            };
            emit(&impact_api::edge(&input)?, a.json);
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    program("impact", run)
}
