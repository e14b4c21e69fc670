//! `wedge`: the self-similar indentation of an elastic half-plane by a rigid wedge, from the
//! command line: a thin shell over the `dyncontact` library, which parses the flags
//! (`dyncontact::cli::wedge`) and prints the typed reports (`dyncontact::report::wedge`).
//!
//! Units: speeds in m/s, the half-angle in degrees. Outputs are dimensionless and their names
//! say how: `v_over_c1_cot_theta` = V/(c1 cot Theta), `force_over_a_mu_cot_theta` =
//! P/(alpha t mu cot Theta), `sigma_over_mu_cot_theta`, `r_over_alpha_t`, ...
//! Every output names its solution variant. Errors: one line on stderr, exit code 2.

use std::io::Write;
use std::ops::ControlFlow;
use std::process::ExitCode;

use dyncontact::cli::wedge::{Command, CurveArgs, WedgeCli};
use dyncontact::cli::{command_line, emit, program};
use dyncontact::{SolveReport, ADMISSIBILITY_KEYS, SIGN_KEYS};
use indicatif::{ProgressBar, ProgressStyle};
use wedge::Result;

/// Prints a curve as its rows are computed: CSV with `#` header lines, or a JSON array.
fn curve(args: &CurveArgs) -> Result<()> {
    let plan = args.plan()?;
    let json = args.json();
    let sel = &plan.selection;
    let bar = ProgressBar::new(plan.alphas.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} alpha values")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let stdout = std::io::stdout();
    let mut lock = stdout.lock();
    if json {
        write!(lock, "[").ok();
    } else {
        for l in plan.header_lines(&command_line()) {
            writeln!(lock, "{l}").ok();
        }
        writeln!(lock, "{}", SolveReport::csv_header(sel)).ok();
    }
    let mut first = true;
    let done = plan.rows(
        || {
            bar.inc(1);
            ControlFlow::Continue(())
        },
        |rows| {
            for r in rows {
                if json {
                    let sep = if first { "" } else { "," };
                    write!(lock, "{sep}{}", r.to_json()).ok();
                } else {
                    writeln!(lock, "{}", r.csv_row(sel)).ok();
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
            // the reader has gone (a closed pipe): stop quietly
            match lock.flush() {
                Ok(()) => ControlFlow::Continue(()),
                Err(_) => ControlFlow::Break(()),
            }
        },
    );
    bar.finish_and_clear();
    // close what was printed, also before a row's error
    if json {
        writeln!(lock, "]").ok();
    }
    lock.flush().ok();
    done.map(|_| ())
}

fn run(cli: WedgeCli) -> Result<()> {
    match cli.command {
        Command::Solve(a) => emit(&a.report()?, a.json()),
        Command::Stress(a) => emit(&a.report()?, a.json()),
        Command::Field(a) => emit(&a.report()?, a.json()),
        Command::Curve(a) => curve(&a)?,
    }
    Ok(())
}

fn main() -> ExitCode {
    program("wedge", run)
}
