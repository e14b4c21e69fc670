//! The rigid striker's impact (`docs/impact.md`): `impact_history` draws h, dh/dt, b and the
//! force against time for both edge laws, with the times where the edge falls below c1, c2 and
//! c_R marked; `impact_pressure` draws the pressure over (x, t) as a colour map with the
//! contact edge, and pressure profiles at several times.
//!
//! The reference case: a free rigid cylinder (parabolic profile of radius R),
//! m0/(rho R^2) = 10, V0/c1 = 0.01, c1 = 1870.83 m/s, c2 = 1000 m/s, to c1 t/R = 10.

use std::path::PathBuf;

use impact::{EdgeLaw, HistoryRow, ImpactCase, SolvedImpact, REFERENCE};

use super::field_snapshot::{colormap, VIRIDIS};
use super::output::{Cell as CsvCell, Column, Table};
use super::plot::{save, Axis, Cell, ColorBar, Dash, Legend, Note, Page, Panel, Series};
use super::{cycle_color, palette, Ctx, FigError, Result, Summary};

const C1: f64 = REFERENCE.c1;
const C2: f64 = REFERENCE.c2;
const MASS_RATIO: f64 = REFERENCE.mass_ratio;
const V0: f64 = REFERENCE.v0_over_c1;
const END: f64 = REFERENCE.end;

/// The reference case with `law` on the grid of the figure's mode.
fn solve(ctx: &Ctx, law: EdgeLaw) -> Result<SolvedImpact> {
    let mut case = ImpactCase::reference(law);
    case.dx = if ctx.quick { 0.02 } else { 0.005 };
    case.levels = 3;
    case.solve(|_| {})
        .map_err(|e| FigError(format!("impact, {} law: {e}", law.name())))
}

fn case_param(table: &mut Table, sol: &SolvedImpact) {
    table.param(format!(
        "material: c1 = {C1} m/s, c2 = {C2} m/s (the half-plane)"
    ));
    table.param(format!(
        "rigid cylinder, parabolic profile of radius R, m0/(rho R^2) = {MASS_RATIO}, V0/c1 = {V0}; grid dx/R = {}, c1 dt/R = {}, {} levels for the error estimates",
        sol.runs[0].dx,
        sol.runs[0].dt,
        sol.runs.len()
    ));
}

const LAWS: [EdgeLaw; 2] = [EdgeLaw::Signorini, EdgeLaw::Kinematic];

/// The times at which the edge's speed falls below c1, c2 and c_R on the early geometric law
/// b = (2 R h)^(1/2), h = V0 t (exact while the edge is supersonic, the same for both laws):
/// db/dt = c at c1 t/R = (V0/c1)/(2 (c/c1)^2).
fn stage_times(m: f64, s_r: f64) -> [(f64, &'static str); 3] {
    let at = |c: f64| V0 / (2.0 * c * c);
    [(at(1.0), "c1"), (at(m), "c2"), (at(s_r), "c_R")]
}

/// impact_history: h, dh/dt, b and the force for both edge laws.
pub fn impact_history(ctx: &Ctx) -> Result<Summary> {
    ctx.plan(LAWS.len());
    let mut runs = Vec::new();
    for law in LAWS {
        let sol = solve(ctx, law)?;
        let rows = sol.history().0;
        runs.push((law, sol, rows));
        ctx.tick();
    }
    let mut table = Table::new(
        "impact_history",
        "a free rigid cylinder on the half-plane: penetration, its rate, contact half-width and force against time, both edge laws",
        vec![
            Column { name: dyncontact::report::impact::keys::LAW, meaning: "signorini (free edge) or kinematic (eq (4), f(b) = h)" },
            Column { name: dyncontact::report::impact::keys::C1T_OVER_R, meaning: "time c1 t/R" },
            Column { name: dyncontact::report::impact::keys::H_OVER_R, meaning: "penetration h/R" },
            Column { name: dyncontact::report::impact::keys::HDOT_OVER_V0, meaning: "(dh/dt)/V0" },
            Column { name: dyncontact::report::impact::keys::B_OVER_R, meaning: "contact half-width b/R" },
            Column { name: dyncontact::report::impact::keys::BDOT_OVER_C1, meaning: "(db/dt)/c1" },
            Column { name: dyncontact::report::impact::keys::STAGE, meaning: "the edge's speed range" },
            Column { name: dyncontact::report::impact::keys::FORCE_OVER_RHO_C1SQ_R, meaning: "contact force per unit length over rho c1^2 R" },
            Column { name: dyncontact::report::impact::keys::ERR_H_OVER_R, meaning: "absolute error estimate of h/R (refinement)" },
            Column { name: dyncontact::report::impact::keys::ERR_B_OVER_R, meaning: "absolute error estimate of b/R" },
            Column { name: dyncontact::report::impact::keys::ERR_FORCE_OVER_RHO_C1SQ_R, meaning: "absolute error estimate of the force" },
        ],
    );
    case_param(&mut table, &runs[0].1);
    let err = |v: &impact::Value| v.error.map(CsvCell::Num).unwrap_or(CsvCell::Empty);
    for (law, _, rows) in &runs {
        for r in rows {
            table.push(vec![
                law.name().into(),
                r.t.into(),
                r.h.value.into(),
                r.hdot.value.into(),
                r.b.value.into(),
                r.bdot.into(),
                r.stage.name().into(),
                r.force.value.into(),
                err(&r.h),
                err(&r.b),
                err(&r.force),
            ])?;
        }
    }
    let path: PathBuf = table.write(&ctx.out)?;
    type Get = fn(&HistoryRow) -> f64;
    let quantities: [(&str, &str, Get, Legend); 4] = [
        ("penetration", "h/R", |r| r.h.value, Legend::LowerRight),
        (
            "penetration rate",
            "(dh/dt)/V0",
            |r| r.hdot.value,
            Legend::UpperRight,
        ),
        (
            "contact half-width (log time; the edge's speed falls below c1, c2, c_R at the lines)",
            "b/R",
            |r| r.b.value,
            Legend::LowerRight,
        ),
        (
            "contact force",
            "force/(rho c1^2 R)",
            |r| r.force.value,
            Legend::UpperRight,
        ),
    ];
    let mut panels = Vec::new();
    for (qi, (title, ylabel, get, legend)) in quantities.into_iter().enumerate() {
        let all = runs.iter().flat_map(|(_, _, rows)| rows.iter().map(get));
        let y = Axis::fit(ylabel, all.chain([0.0]), 0.05);
        let (ylo, yhi) = (y.lo, y.hi);
        // the edge's early stages last until c1 t/R ~ V0/c1: the half-width on a log time axis
        let x = if qi == 2 {
            Axis::log("c1 t/R", 1e-3, END)
        } else {
            Axis::lin("c1 t/R", 0.0, END)
        };
        let mut p = Panel::new(title, x, y, legend);
        for (k, (law, _, rows)) in runs.iter().enumerate() {
            let color = cycle_color(5 + 4 * k);
            let dash = if k == 0 { Dash::Solid } else { Dash::Dashed };
            // on the log axis every step of the finest grid, from its first
            let pts: Vec<(f64, f64)> = if qi == 2 {
                sol_steps(&runs[k].1)
            } else {
                rows.iter().map(|r| (r.t, get(r))).collect()
            };
            p.series
                .push(Series::new(law.name(), pts, color, dash).width(3));
        }
        if qi == 2 {
            let sol = &runs[0].1;
            for (k, (t, name)) in stage_times(sol.m, sol.s_r).into_iter().enumerate() {
                let mut s = Series::new("", vec![(t, ylo), (t, yhi)], palette::GREY, Dash::Dotted);
                s.label = None;
                p.series.push(s);
                p.notes.push(Note {
                    at: (t * 1.05, yhi - (0.05 + 0.06 * k as f64) * (yhi - ylo)),
                    text: format!("< {name}"),
                    color: palette::BLACK,
                    size: 16,
                });
            }
            // the geometric law b = (2 R V0 t)^(1/2) of the supersonic stage
            let geo = (0..=60)
                .map(|i| 1e-3 * (END / 1e-3f64).powf(i as f64 / 60.0))
                .map(|t| (t, (2.0 * V0 * t).sqrt()))
                .filter(|(_, b)| *b <= yhi)
                .collect();
            let mut g = Series::new("(2 R V0 t)^(1/2)", geo, palette::GREY, Dash::Dashed);
            g.width = 1;
            p.series.push(g);
        }
        panels.push(p);
    }
    let page = Page {
        name: "impact_history",
        width: 1600,
        height: 1200,
        panels,
        stacked: false,
    };
    let mut files = vec![path];
    files.extend(save(&ctx.out, &page)?);
    Ok(Summary {
        files,
        points: runs.iter().map(|r| r.2.len()).sum(),
    })
}

/// (c1 t/R, b/R) at every step of the finest grid.
fn sol_steps(sol: &SolvedImpact) -> Vec<(f64, f64)> {
    sol.runs[0].steps.iter().map(|s| (s.t, s.b)).collect()
}

/// impact_pressure: p(x, t) as a colour map with the contact edge, and profiles.
pub fn impact_pressure(ctx: &Ctx) -> Result<Summary> {
    ctx.plan(1);
    let sol = solve(ctx, EdgeLaw::Signorini)?;
    ctx.tick();
    let m2 = (C2 / C1).powi(2);
    let run = &sol.runs[0];
    // at most 300 time rows
    let every = run.steps.len().div_ceil(300).max(1);
    let rows: Vec<&impact::march::StepState> =
        run.steps.iter().skip(every - 1).step_by(every).collect();
    let pmax = rows
        .iter()
        .flat_map(|s| s.pressure.iter())
        .fold(0.0f64, |a, p| a.max(p * m2));
    let bmax = rows.iter().fold(0.0f64, |a, s| a.max(s.b));
    let mut table = Table::new(
        "impact_pressure",
        "contact pressure of a free rigid cylinder over space and time (signorini edge)",
        vec![
            Column {
                name: dyncontact::report::impact::keys::C1T_OVER_R,
                meaning:
                    "time c1 t/R (every step of the finest grid, thinned to at most 300 times)",
            },
            Column {
                name: dyncontact::report::impact::keys::X_OVER_R,
                meaning: "cell centre x/R",
            },
            Column {
                name: dyncontact::report::impact::keys::P_OVER_RHO_C1SQ,
                meaning: "cell pressure over rho c1^2 (constant over the cell and the step; it stands for the middle of the step)",
            },
            Column {
                name: dyncontact::report::impact::keys::B_OVER_R,
                meaning: "the contact half-width at that time",
            },
        ],
    );
    case_param(&mut table, &sol);
    for s in &rows {
        for (j, p) in s.pressure.iter().enumerate() {
            table.push(vec![
                s.t.into(),
                (j as f64 * run.dx).into(),
                (p * m2).into(),
                s.b.into(),
            ])?;
        }
    }
    let path: PathBuf = table.write(&ctx.out)?;
    let xmax = 1.1 * bmax;
    let mut map = Panel::new(
        "pressure p/(rho c1^2) over (x, t) with the contact edge",
        Axis::lin("x/R", 0.0, xmax),
        Axis::lin("c1 t/R", 0.0, END),
        Legend::LowerRight,
    );
    let dt_row = run.dt * every as f64;
    for s in &rows {
        for (j, p) in s.pressure.iter().enumerate() {
            let x = j as f64 * run.dx;
            let lo = if j == 0 { 0.0 } else { x - 0.5 * run.dx };
            map.cells.push(Cell {
                from: (lo, s.t - dt_row),
                to: (x + 0.5 * run.dx, s.t),
                color: colormap(&VIRIDIS, (p * m2 / pmax).max(0.0)),
            });
        }
    }
    map.series.push(
        Series::new(
            "contact edge b(t)",
            rows.iter().map(|s| (s.b, s.t)).collect(),
            palette::RED,
            Dash::Solid,
        )
        .width(3),
    );
    let n = 128;
    map.colorbar = Some(ColorBar {
        label: "p/(ρ c1²)".into(),
        colors: (0..n)
            .map(|k| colormap(&VIRIDIS, (k as f64 + 0.5) / n as f64))
            .collect(),
        ticks: (0..=4)
            .map(|k| {
                let f = k as f64 / 4.0;
                (f, format!("{:.4}", f * pmax))
            })
            .collect(),
    });
    let mut profiles = Panel::new(
        "pressure profiles",
        Axis::lin("x/R", 0.0, xmax),
        Axis::lin("p/(rho c1^2)", 0.0, 1.1 * pmax),
        Legend::UpperRight,
    );
    for (k, t) in [0.5, 1.0, 2.0, 4.0, 6.8, 9.0].iter().enumerate() {
        if let Some((ts, x, p)) = sol.pressure_at(*t) {
            // cell values drawn as steps
            let mut pts = Vec::with_capacity(2 * x.len());
            for (xi, pi) in x.iter().zip(&p) {
                pts.push(((xi - 0.5 * run.dx).max(0.0), *pi));
                pts.push((xi + 0.5 * run.dx, *pi));
            }
            profiles.series.push(
                Series::new(
                    format!("c1 t/R = {ts:.2}"),
                    pts,
                    cycle_color(k + 1),
                    Dash::Solid,
                )
                .width(2),
            );
        }
    }
    let page = Page {
        name: "impact_pressure",
        width: 1600,
        height: 700,
        panels: vec![map, profiles],
        stacked: false,
    };
    let mut files = vec![path];
    files.extend(save(&ctx.out, &page)?);
    Ok(Summary {
        files,
        points: table_len(&rows),
    })
}

fn table_len(rows: &[&impact::march::StepState]) -> usize {
    rows.iter().map(|s| s.pressure.len()).sum()
}
