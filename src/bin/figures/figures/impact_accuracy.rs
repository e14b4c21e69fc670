//! `impact_accuracy`: the accuracy of the impact engine against its run time, on the
//! benchmark's reference case (free rigid cylinder, m0/(rho R^2) = 10, V0/c1 = 0.01, Signorini
//! edge, to c1 t/R = 10): for each cell width, three grids (dx, 2 dx, 4 dx, the reported values
//! and their stated errors) timed together; the actual error of h, b and the force is the
//! largest difference over the report times from c1 t/R = 0.02 on from one grid four times
//! finer than the finest shown at every time (its start on the finest's hand-over schedule),
//! relative to the quantity's peak, next to the largest stated error.

use std::path::PathBuf;
use std::time::Instant;

use impact::{EdgeLaw, HistoryRow, ImpactCase};

use super::output::{Cell, Column, Table};
use super::plot::{save, Axis, Dash, Legend, Page, Panel, Series};
use super::{cycle_color, Ctx, FigError, Result, Summary};

const C1: f64 = impact::REFERENCE.c1;
const C2: f64 = impact::REFERENCE.c2;

type Pick = fn(&HistoryRow) -> impact::Value;

/// The errors are taken from c1 t/R = 0.02 on, the range of the accuracy targets
/// (`docs/impact.md`, section 11: the start on finer grids resolves the first steps).
const FROM: f64 = 0.02;

const QUANTITIES: [(&str, Pick); 3] = [("h", |r| r.h), ("b", |r| r.b), ("force", |r| r.force)];

/// The reference case at `dx` with `levels` grids; `schedule`: the start's hand-over
/// schedule of another grid (the reference run, refined at every time).
fn solve(dx: f64, levels: usize, schedule: Option<f64>) -> Result<(Vec<HistoryRow>, f64)> {
    let mut case = ImpactCase::reference(EdgeLaw::Signorini);
    case.dx = dx;
    case.levels = levels;
    case.start_grid = schedule;
    let t0 = Instant::now();
    let sol = case
        .solve(|_| {})
        .map_err(|e| FigError(format!("reference case at dx = {dx}: {e}")))?;
    let secs = t0.elapsed().as_secs_f64();
    Ok((sol.history().0, secs))
}

/// impact_accuracy: error of h, b and the force against run time.
pub fn impact_accuracy(ctx: &Ctx) -> Result<Summary> {
    let cells: &[f64] = if ctx.quick {
        // (below R/100 the reference case's contact never spans the start's hand-over width:
        // R/25 and R/50 run on about the grids of R/100)
        &[100.0, 200.0]
    } else {
        &[25.0, 50.0, 100.0, 200.0]
    };
    let finest = cells[cells.len() - 1];
    ctx.plan(cells.len() + 1);
    let (truth, _) = solve(1.0 / (4.0 * finest), 1, Some(1.0 / finest))?;
    ctx.tick();
    // each quantity's peak over the reference run, the errors' scale
    let peaks: Vec<f64> = QUANTITIES
        .iter()
        .map(|(_, pick)| {
            truth
                .iter()
                .map(|r| pick(r).value.abs())
                .fold(0.0, f64::max)
        })
        .collect();
    let mut table = Table::new(
        "impact_accuracy",
        "accuracy of h, b and the force against run time (reference case, three grids per point)",
        vec![
            Column { name: "dx_over_R", meaning: "cell width of the finest of the three grids" },
            Column { name: "seconds", meaning: "run time of the three grids together (this run, one thread)" },
            Column { name: "quantity", meaning: "h, b or force" },
            Column { name: "actual_error", meaning: "largest |value - reference| over the report times from c1 t/R = 0.02, over the quantity's peak (the reference: one grid four times finer than the finest shown at every time, its start on the finest's hand-over schedule)" },
            Column { name: "stated_error", meaning: "largest stated error over the same times, over the quantity's peak" },
        ],
    );
    table.param(format!(
        "material: c1 = {C1} m/s, c2 = {C2} m/s (the half-plane)"
    ));
    table.param(format!(
        "reference case: parabola of radius R, m0/(rho R^2) = {}, V0/c1 = {}, signorini edge, to c1 t/R = {}; kappa = 2; three grids dx, 2 dx, 4 dx per point; reference dx = R/{}",
        impact::REFERENCE.mass_ratio,
        impact::REFERENCE.v0_over_c1,
        impact::REFERENCE.end,
        4.0 * finest
    ));
    // (quantity, [(seconds, actual, stated)])
    let mut curves: Vec<Vec<(f64, f64, f64)>> = vec![Vec::new(); QUANTITIES.len()];
    for &n in cells {
        let dx = 1.0 / n;
        let (rows, secs) = solve(dx, 3, None)?;
        ctx.tick();
        for (q, ((name, pick), scale)) in QUANTITIES.iter().zip(&peaks).enumerate() {
            let (mut actual, mut stated) = (0.0f64, 0.0f64);
            for r in rows.iter().filter(|r| r.t >= FROM) {
                let Some(t) = truth.iter().find(|x| (x.t - r.t).abs() < 1e-9) else {
                    continue;
                };
                let v = pick(r);
                actual = actual.max((v.value - pick(t).value).abs());
                if let Some(e) = v.error {
                    stated = stated.max(e);
                }
            }
            let (actual, stated) = (actual / scale, stated / scale);
            curves[q].push((secs, actual, stated));
            table.push(vec![
                dx.into(),
                secs.into(),
                Cell::from(*name),
                actual.into(),
                stated.into(),
            ])?;
        }
    }
    let path: PathBuf = table.write(&ctx.out)?;
    let all = || {
        curves
            .iter()
            .flat_map(|c| c.iter().flat_map(|p| [p.1, p.2]))
            .chain([1e-5])
    };
    let mut panel = Panel::new(
        "reference case: error (over the peak) against run time of three grids",
        Axis::fit_log(
            "seconds (three grids, one thread)",
            curves.iter().flat_map(|c| c.iter().map(|p| p.0)),
        ),
        Axis::fit_log("largest error over the run / peak value", all()),
        Legend::UpperRight,
    );
    for (q, (name, _)) in QUANTITIES.iter().enumerate() {
        let color = cycle_color(2 * q + 1);
        panel.series.push(
            Series::new(
                format!("{name}: actual"),
                curves[q].iter().map(|p| (p.0, p.1)).collect(),
                color,
                Dash::Solid,
            )
            .width(3),
        );
        panel.series.push(
            Series::new(
                format!("{name}: stated"),
                curves[q].iter().map(|p| (p.0, p.2)).collect(),
                color,
                Dash::Dashed,
            )
            .width(3),
        );
    }
    let (x0, x1) = (panel.x.lo, panel.x.hi);
    panel.series.push(Series::new(
        "1e-4 target",
        vec![(x0, 1e-4), (x1, 1e-4)],
        (0, 0, 0),
        Dash::Dotted,
    ));
    let page = Page {
        name: "impact_accuracy",
        width: 1100,
        height: 750,
        panels: vec![panel],
        stacked: false,
    };
    let mut files = vec![path];
    files.extend(save(&ctx.out, &page)?);
    Ok(Summary {
        files,
        points: cells.len() * QUANTITIES.len(),
    })
}
