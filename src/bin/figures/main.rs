//! `figures`: redraws the reference paper's figures, and a map of the apex regimes, from the
//! library.
//!
//! ```text
//! figures                      # every figure, into figures/
//! figures fig5 fig6            # only these
//! figures --out DIR --quick    # into DIR, with fewer points (tests, previews)
//! figures --list               # the figure names
//! ```
//!
//! Each figure writes `<name>.png`, `<name>.svg` and `<name>.csv` (the plotted data, with `#`
//! header lines: library version, parameters, precision, the meaning of each column). Figures
//! are computed in parallel, each computing only what it draws; progress goes to stderr (hidden
//! when stderr is not a terminal), then one line per figure with its wall time.
//!
//! Errors (an unknown figure name, a bad flag) are one line on stderr with exit code 2; a
//! figure that fails to compute or write is reported on one line and the exit code is 1.
//!
//! Adding a figure: a function `fn(&Ctx) -> Result<Summary>` in a module under `src/bin/figures/figures/`
//! (declared in `src/bin/figures/figures/mod.rs`) that builds a `Table` (CSV) and a `Page` (PNG, SVG),
//! and one [`Entry`] in [`FIGURES`]. Adding a solution variant to fig3 and fig5: one entry in
//! `figures::VARIANTS`.

mod figures;

use std::collections::BTreeSet;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::Parser;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

use figures::{field_snapshot, paper, regime_map, Ctx, Result, Summary};

/// One figure of the registry: its name, what it shows, and the function that draws it.
struct Entry {
    name: &'static str,
    about: &'static str,
    draw: fn(&Ctx) -> Result<Summary>,
}

/// Every figure, in drawing order. A figure is added by one entry here.
const FIGURES: &[Entry] = &[
    Entry {
        name: "fig3",
        about: "edge particle velocity and the paper's edge-following rate over V against alpha (Theta 89, gamma 0.6)",
        draw: paper::fig3,
    },
    Entry {
        name: "fig4",
        about: "alpha/c2 against V/(c2 cot Theta), classical (frictionless, uncoupled)",
        draw: paper::fig4,
    },
    Entry {
        name: "fig5",
        about: "alpha/c2 against V/(c2 cot Theta), coupled, gamma 0.4, Theta 86 and 89, with the classical curve",
        draw: paper::fig5,
    },
    Entry {
        name: "fig6",
        about: "contact stress at p = 0.3, Theta 86, gamma 0.001 and 0.6, with the apex behaviour",
        draw: paper::fig6,
    },
    Entry {
        name: "fig7",
        about: "contact stress at p = 0.3, Theta 89, gamma 0.001 and 0.6, with the apex behaviour",
        draw: paper::fig7,
    },
    Entry {
        name: "regime_map",
        about: "apex regime over (Theta, gamma) with contours of 2 Omega0",
        draw: regime_map::regime_map,
    },
    Entry {
        name: "field_snapshot",
        about: "maximum shear stress and sigma_yy over the half-plane at c1 t = 1 with the wave fronts (Theta 89, gamma 0.6, p = 0.3)",
        draw: field_snapshot::field_snapshot,
    },
    Entry {
        name: "error_vs_time",
        about: "relative error against run time, f64 and MPFR paths, against a 400-bit reference",
        draw: figures::error_vs_time::error_vs_time,
    },
    Entry {
        name: "impact_history",
        about: "free rigid cylinder (m0/(rho R^2) = 10, V0/c1 = 0.01): h, dh/dt, b and force against c1 t/R, both edge laws, edge speed ranges marked",
        draw: figures::impact_history::impact_history,
    },
    Entry {
        name: "impact_pressure",
        about: "free rigid cylinder: pressure over (x, t) with the contact edge, and profiles",
        draw: figures::impact_history::impact_pressure,
    },
    Entry {
        name: "edge_exponents",
        about: "power of the contact pressure at a moving edge against its speed, four Poisson's ratios, both edge laws",
        draw: figures::edge_exponents::edge_exponents,
    },
    Entry {
        name: "impact_accuracy",
        about: "reference impact case: error of h, b and the force (actual and stated, over the peak) against the run time of three grids",
        draw: figures::impact_accuracy::impact_accuracy,
    },
    Entry {
        name: "impact_strikers",
        about: "rigid, elastic and thin-shell strikers of equal mass and impact speed: h, force, b and the striker's energy against c1 t/R",
        draw: figures::impact_strikers::impact_strikers,
    },
    Entry {
        name: "sphere_impact",
        about: "rigid sphere on the elastic half-space (own density): restitution and radiated energy against V0/c1 over four decades beside Hertz and Hunter, force histories against Hertz's",
        draw: figures::sphere_impact::sphere_impact,
    },
];

/// Redraw the reference paper's figures (and a regime map) from the library.
///
/// Each figure is written as PNG, SVG and CSV (the plotted data with a '#' header).
#[derive(Parser, Debug)]
#[command(
    name = "figures",
    version,
    about = "Redraw the reference paper's figures (and a regime map) from the library",
    long_about = None
)]
struct Cli {
    /// Figures to draw (default: all). Names: fig3 fig4 fig5 fig6 fig7 regime_map
    /// field_snapshot error_vs_time impact_history impact_pressure edge_exponents
    /// impact_accuracy impact_strikers sphere_impact.
    names: Vec<String>,
    /// Output directory (created if missing).
    #[arg(long, default_value = "figures")]
    out: PathBuf,
    /// Fewer points per figure (for tests and previews); every point is computed as in full mode.
    #[arg(long)]
    quick: bool,
    /// List the figures and exit.
    #[arg(long)]
    list: bool,
}

fn fail(msg: impl std::fmt::Display) -> ExitCode {
    eprintln!("figures: {msg}");
    ExitCode::from(2)
}

/// The registry entries named (all when none), in registry order, or the first unknown name.
fn select(names: &[String]) -> std::result::Result<Vec<&'static Entry>, String> {
    let mut wanted = BTreeSet::new();
    for n in names {
        match FIGURES.iter().position(|e| e.name == n.as_str()) {
            Some(i) => {
                wanted.insert(i);
            }
            None => {
                let known: Vec<&str> = FIGURES.iter().map(|e| e.name).collect();
                return Err(format!(
                    "unknown figure '{n}' (known: {})",
                    known.join(", ")
                ));
            }
        }
    }
    Ok(if wanted.is_empty() {
        FIGURES.iter().collect()
    } else {
        wanted.into_iter().map(|i| &FIGURES[i]).collect()
    })
}

fn progress_bar() -> ProgressBar {
    let pb = ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("{elapsed:>4} [{bar:40}] {pos}/{len} points {msg}")
    {
        pb.set_style(style.progress_chars("=> "));
    }
    pb.enable_steady_tick(Duration::from_millis(200));
    pb
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                print!("{e}");
                return ExitCode::SUCCESS;
            }
            let text = e.to_string();
            let first = text.lines().next().unwrap_or("invalid arguments");
            return fail(first.trim_start_matches("error: "));
        }
    };
    if cli.list {
        for e in FIGURES {
            println!("{:<12} {}", e.name, e.about);
        }
        return ExitCode::SUCCESS;
    }
    let selected = match select(&cli.names) {
        Ok(s) => s,
        Err(msg) => return fail(msg),
    };
    if let Err(e) = std::fs::create_dir_all(&cli.out) {
        return fail(format!("cannot create {}: {e}", cli.out.display()));
    }

    let ctx = Ctx {
        out: cli.out.clone(),
        quick: cli.quick,
        progress: progress_bar(),
    };
    let start = Instant::now();
    let results: Vec<(&'static str, Result<Summary>, Duration)> = selected
        .par_iter()
        .map(|e| {
            let t0 = Instant::now();
            let r = (e.draw)(&ctx);
            ctx.progress.set_message(format!("{} done", e.name));
            (e.name, r, t0.elapsed())
        })
        .collect();
    let total = start.elapsed();
    ctx.progress.finish_and_clear();

    let mut failed = false;
    for (name, r, dt) in &results {
        match r {
            Ok(s) => {
                let files: Vec<String> = s.files.iter().map(|f| f.display().to_string()).collect();
                eprintln!(
                    "{name:<14} {:>7.2} s  {:>6} points  {}",
                    dt.as_secs_f64(),
                    s.points,
                    files.join(" ")
                );
            }
            Err(e) => {
                failed = true;
                eprintln!("figures: {name}: {e}");
            }
        }
    }
    eprintln!(
        "total          {:>7.2} s  ({} figures, {} threads{})",
        total.as_secs_f64(),
        results.len(),
        rayon::current_num_threads(),
        if cli.quick { ", quick" } else { "" }
    );
    if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
