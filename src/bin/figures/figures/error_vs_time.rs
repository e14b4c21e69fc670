//! `error_vs_time`: relative error against run time of one full solve (and of one contact
//! stress evaluation), f64 and MPFR paths, against a 400-bit reference
//! ([`dyncontact::accuracy`]). The CSV is the accuracy report's.

use std::path::PathBuf;

use dyncontact::accuracy::{csv, report, QUANTITIES};

use super::plot::{save, Axis, Dash, Legend, Page, Panel, Series};
use super::{cycle_color, Ctx, FigError, Result, Summary};

/// error_vs_time: the accuracy report as a figure.
pub fn error_vs_time(ctx: &Ctx) -> Result<Summary> {
    ctx.plan(1);
    let rows = report(ctx.quick)?;
    ctx.tick();
    std::fs::create_dir_all(&ctx.out)
        .map_err(|e| FigError(format!("cannot create {}: {e}", ctx.out.display())))?;
    let path: PathBuf = ctx.out.join("error_vs_time.csv");
    std::fs::write(
        &path,
        csv(
            &rows,
            if ctx.quick {
                200
            } else {
                dyncontact::accuracy::REFERENCE_BITS
            },
        ),
    )
    .map_err(|e| FigError(format!("cannot write {}: {e}", path.display())))?;
    // log10 of the errors (drawn linearly: the range spans a hundred decades)
    let floor = |e: f64| e.max(1e-120).log10();
    let mut solve = Panel::new(
        "error of each quantity against the time of one full solve",
        Axis::fit_log(
            "seconds per solve (case build + matching)",
            rows.iter().map(|r| r.solve_seconds),
        ),
        Axis::lin(
            "log10 of the relative error against 400 bits",
            -110.0,
            -10.0,
        ),
        Legend::UpperRight,
    );
    for (k, q) in QUANTITIES.iter().enumerate().take(5) {
        let pts = rows
            .iter()
            .map(|r| (r.solve_seconds, floor(r.errors[k])))
            .collect();
        solve
            .series
            .push(Series::new(*q, pts, cycle_color(k), Dash::Solid));
    }
    let pts = rows
        .iter()
        .map(|r| (r.solve_seconds, floor(r.estimate)))
        .collect();
    solve.series.push(Series::new(
        "stated error of V",
        pts,
        cycle_color(5),
        Dash::Dashed,
    ));
    let mut stress = Panel::new(
        "contact stress: error against the time of one evaluation",
        Axis::fit_log(
            "seconds per stress point",
            rows.iter().map(|r| r.stress_seconds),
        ),
        Axis::lin(
            "log10 of the relative error against 400 bits",
            -110.0,
            -10.0,
        ),
        Legend::UpperRight,
    );
    for (k, q) in QUANTITIES.iter().enumerate().skip(5) {
        let pts = rows
            .iter()
            .map(|r| (r.stress_seconds, floor(r.errors[k])))
            .collect();
        stress
            .series
            .push(Series::new(*q, pts, cycle_color(k), Dash::Solid));
    }
    let page = Page {
        name: "error_vs_time",
        width: 1600,
        height: 700,
        panels: vec![solve, stress],
        stacked: false,
    };
    let mut files = vec![path];
    files.extend(save(&ctx.out, &page)?);
    Ok(Summary {
        files,
        points: rows.len(),
    })
}
