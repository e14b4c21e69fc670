//! `impact`: the transient impact of rigid, elastic and thin-shell strikers on an elastic
//! half-plane, from the command line: a thin shell over `dyncontact::impact_api`, which
//! parses the flags (`dyncontact::cli::impact`) and prints the typed reports
//! (`dyncontact::report::impact`).
//!
//! `impact run` marches an impact and prints its histories with their error estimates;
//! `impact green` prints Lamb's surface influence functions of the half-plane (for a line
//! force at x = 0, z into the medium, s = |x|/(c1 t): u = I/(pi mu t) g(s) for an impulse
//! I delta(t) and u = P/(pi mu) W(s) for a step P H(t); keys `g_zz`, `g_xz`, `g_xx`,
//! `W_zz`, `U_xz`, `U_xx`, cell integrals `Ix_*` = Int g ds and `It_*` = Int g/s ds,
//! `--constants` for s_R, r_zz, r_xx and K_R); `impact edge` prints the power law of the
//! pressure at a moving contact edge; `impact striker-green` prints a free elastic cylinder's
//! own influence function (keys `c2t_over_R`, `angle_deg`, `w_over_p0R_mu`,
//! `w_def_over_p0R_mu`, `error_estimate`). Every value comes with its absolute error estimate.
//! Errors: one line on stderr, exit code 2.

use std::ops::ControlFlow;
use std::process::ExitCode;

use dyncontact::cli::impact::{Command, ImpactCli};
use dyncontact::cli::{emit, program};
use dyncontact::impact_api::{self, RunInput};
use dyncontact::Error;

/// Seconds after which a run shows its progress.
const PROGRESS_AFTER_S: f64 = 2.0;

/// Runs `impact run`, its progress on stderr once it has taken a few seconds (hidden by
/// indicatif where stderr is not a terminal).
fn run_with_progress(input: &RunInput) -> Result<impact_api::AnyRunReport, Error> {
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
    let r = impact_api::run_any(input, |p: impact::Progress| {
        if !shown && start.elapsed().as_secs_f64() > PROGRESS_AFTER_S {
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            shown = true;
        }
        bar.set_message(format!(
            "level {} step {} c1t/R {:.3}",
            p.level, p.step, p.t
        ));
        bar.set_position((p.fraction * 1000.0) as u64);
        ControlFlow::Continue(())
    });
    bar.finish_and_clear();
    r
}

fn run(cli: ImpactCli) -> Result<(), Error> {
    match cli.command {
        Command::Green(a) => emit(&impact_api::green(&a.input())?, a.json()),
        Command::Run(a) => emit(&run_with_progress(&a.input()?)?, a.json()),
        Command::Edge(a) => emit(&impact_api::edge(&a.input()?)?, a.json()),
        Command::StrikerGreen(a) => emit(&impact_api::striker_green(&a.input()?)?, a.json()),
    }
    Ok(())
}

fn main() -> ExitCode {
    program("impact", run)
}
