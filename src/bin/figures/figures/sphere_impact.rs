//! `sphere_impact`: a rigid sphere of the half-space's own density (m/(rho R^3) = 4 pi/3,
//! nu = 1/4) dropped on the elastic half-space at V0/c1 over four decades
//! (`docs/axisymmetric.md`): the coefficient of restitution and the share of the impact
//! energy radiated into the half-space, beside Hertz (no loss), Hunter's estimate and the
//! first-order radiation of Hertz's force; and force histories against Hertz's.

use std::ops::ControlFlow;
use std::path::PathBuf;

use dyncontact::report::axisym::{hertz, HERTZ_PULSE_SLOPE};
use impact::axisym::{AxiCase, AxiProfile};
use impact::{Drive, EdgeLaw, Stop};

use super::output::{Cell, Column, Table};
use super::plot::{save, Axis, Dash, Legend, Page, Panel, Series};
use super::{cycle_color, Ctx, FigError, Result, Summary};

const NU: f64 = 0.25;
const MASS: f64 = 4.0 * std::f64::consts::PI / 3.0;

/// One impact: its speed, restitution (with estimate), radiated share (with estimate), and
/// its force history normalised by Hertz's (t/t_c, F/F_max).
struct Point {
    v0: f64,
    restitution: (f64, f64),
    radiated: (f64, f64),
    force: Vec<(f64, f64)>,
}

/// Hertz's force pulse F/F_max against t/t_c: x'' = -(5/4) x^(3/2) in units of h_max/V0
/// (x = h/h_max, x(0) = 0, x'(0) = 1), F/F_max = x^(3/2), by RK4.
fn hertz_pulse() -> Vec<(f64, f64)> {
    let dt = 1e-4;
    let (mut x, mut v, mut t): (f64, f64, f64) = (0.0, 1.0, 0.0);
    let acc = |x: f64| -1.25 * x.max(0.0).powf(1.5);
    let mut pts = vec![(0.0, 0.0)];
    while x >= 0.0 {
        let (k1x, k1v) = (v, acc(x));
        let (k2x, k2v) = (v + 0.5 * dt * k1v, acc(x + 0.5 * dt * k1x));
        let (k3x, k3v) = (v + 0.5 * dt * k2v, acc(x + 0.5 * dt * k2x));
        let (k4x, k4v) = (v + dt * k3v, acc(x + dt * k3x));
        x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        t += dt;
        pts.push((t, x.max(0.0).powf(1.5)));
    }
    let end = t;
    pts.into_iter()
        .step_by(100)
        .map(|(t, f)| (t / end, f))
        .collect()
}

fn impact(v0: f64, quick: bool) -> Result<Point> {
    let h = hertz(NU, 1.0, MASS, v0);
    let mut case = AxiCase {
        poisson: NU,
        profile: AxiProfile::Sphere { radius: 1.0 },
        drive: Drive::Free {
            mass_ratio: MASS,
            v0_over_c1: v0,
        },
        law: EdgeLaw::Signorini,
        end: 1.5 * h.contact_c1t_over_r,
        stop: Stop::AtSeparation,
        dr: None,
        kappa: if v0 < 3e-5 { 4.0 } else { 2.0 },
        levels: if quick { 2 } else { 3 },
    };
    if quick {
        case.dr = Some(case.default_dr() * 2.0);
    }
    let sol = case
        .solve(|_| ControlFlow::Continue(()))
        .map_err(|e| FigError(format!("sphere at V0/c1 = {v0}: {e}")))?;
    let r = sol
        .rebound()
        .map_err(|e| FigError(format!("sphere at V0/c1 = {v0}: {e}")))?;
    let rows = sol.history().0;
    let force = rows
        .iter()
        .map(|row| {
            (
                row.t / h.contact_c1t_over_r,
                row.force.value / h.peak_force_over_rho_c1sq_rsq,
            )
        })
        .collect();
    Ok(Point {
        v0,
        restitution: (r.restitution.value, r.restitution.error.unwrap_or(0.0)),
        radiated: (
            r.radiated_fraction.value,
            r.radiated_fraction.error.unwrap_or(0.0),
        ),
        force,
    })
}

/// sphere_impact: restitution and radiated energy over four decades of V0/c1, force
/// histories against Hertz's.
pub fn sphere_impact(ctx: &Ctx) -> Result<Summary> {
    let speeds: Vec<f64> = if ctx.quick {
        vec![1e-4, 1e-3, 1e-2, 1e-1]
    } else {
        vec![1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1]
    };
    ctx.plan(speeds.len());
    let mut pts = Vec::new();
    for &v in &speeds {
        pts.push(impact(v, ctx.quick)?);
        ctx.tick();
    }
    // the first order: E_F F_max^2/t_c times Hertz's pulse integral (or Hunter's half-sine,
    // pi^2/2), over the impact energy; both scale as (V0/c1)^(3/5)
    let ef = lamb::HalfSpace::from_poisson(NU)
        .and_then(|h| h.radiation_constant())
        .map_err(|e| FigError(format!("radiation constant: {e}")))?
        .value;
    let m2 = (1.0 - 2.0 * NU) / (2.0 * (1.0 - NU));
    let first = |v0: f64, slope: f64| {
        let h = hertz(NU, 1.0, MASS, v0);
        let f = h.peak_force_over_rho_c1sq_rsq / m2;
        ef * f * f / h.contact_c1t_over_r * slope / (0.5 * MASS / m2 * v0 * v0)
    };
    let mut table = Table::new(
        "sphere_impact",
        "rigid sphere of the half-space's own density on the elastic half-space: restitution and radiated energy against V0/c1, with Hertz and Hunter",
        vec![
            Column { name: "v0_over_c1", meaning: "impact speed V0/c1" },
            Column { name: "restitution", meaning: "coefficient of restitution (the march)" },
            Column { name: "err_restitution", meaning: "its absolute error estimate" },
            Column { name: "radiated_energy_fraction", meaning: "share of the impact energy radiated into the half-space (1 - e^2)" },
            Column { name: "err_radiated_energy_fraction", meaning: "its absolute error estimate" },
            Column { name: "first_order_fraction", meaning: "the first-order radiation of Hertz's force, E_F Int (dF/dt)^2 dt over the impact energy" },
            Column { name: "hunter_fraction", meaning: "Hunter's estimate: the same with Hertz's force a half-sine" },
        ],
    );
    table.param(format!(
        "nu = {NU}; m/(rho R^3) = 4 pi/3; sphere of radius R; Signorini; default grid (about 30 rings across the largest contact radius), kappa = 2 (4 below V0/c1 = 3e-5), {} levels",
        if ctx.quick { 2 } else { 3 }
    ));
    for p in &pts {
        table.push(vec![
            Cell::Num(p.v0),
            Cell::Num(p.restitution.0),
            Cell::Num(p.restitution.1),
            Cell::Num(p.radiated.0),
            Cell::Num(p.radiated.1),
            Cell::Num(first(p.v0, HERTZ_PULSE_SLOPE)),
            Cell::Num(first(p.v0, std::f64::consts::PI.powi(2) / 2.0)),
        ])?;
    }
    let path: PathBuf = table.write(&ctx.out)?;
    let (lo, hi) = (speeds[0], *speeds.last().unwrap_or(&1e-1));
    let dense: Vec<f64> = (0..=40)
        .map(|k| lo * (hi / lo).powf(k as f64 / 40.0))
        .collect();
    let mut rest = Panel::new(
        "coefficient of restitution",
        Axis::log("V0/c1", lo, hi),
        Axis::fit(
            "e",
            pts.iter().map(|p| p.restitution.0).chain([1.0, 0.75]),
            0.05,
        ),
        Legend::LowerRight,
    );
    rest.series.push(
        Series::new(
            "this engine (the half-space's waves)",
            pts.iter().map(|p| (p.v0, p.restitution.0)).collect(),
            cycle_color(1),
            Dash::Solid,
        )
        .width(3),
    );
    rest.series.push(Series::new(
        "Hertz (quasi-static, no loss)",
        vec![(lo, 1.0), (hi, 1.0)],
        cycle_color(0),
        Dash::Dashed,
    ));
    rest.series.push(Series::new(
        "Hunter's estimate",
        dense
            .iter()
            .map(|&v| {
                (
                    v,
                    (1.0 - first(v, std::f64::consts::PI.powi(2) / 2.0))
                        .max(0.0)
                        .sqrt(),
                )
            })
            .collect(),
        cycle_color(3),
        Dash::Dotted,
    ));
    let mut rad = Panel::new(
        "energy radiated into the half-space",
        Axis::log("V0/c1", lo, hi),
        Axis::fit_log(
            "share of the impact energy",
            pts.iter()
                .map(|p| p.radiated.0)
                .chain(dense.iter().map(|&v| first(v, HERTZ_PULSE_SLOPE))),
        ),
        Legend::UpperLeft,
    );
    rad.series.push(
        Series::new(
            "this engine",
            pts.iter().map(|p| (p.v0, p.radiated.0)).collect(),
            cycle_color(1),
            Dash::Solid,
        )
        .width(3),
    );
    rad.series.push(Series::new(
        "first order (Hertz's force radiating as a point force)",
        dense
            .iter()
            .map(|&v| (v, first(v, HERTZ_PULSE_SLOPE)))
            .collect(),
        cycle_color(4),
        Dash::Dashed,
    ));
    rad.series.push(Series::new(
        "Hunter's estimate (half-sine force)",
        dense
            .iter()
            .map(|&v| (v, first(v, std::f64::consts::PI.powi(2) / 2.0)))
            .collect(),
        cycle_color(3),
        Dash::Dotted,
    ));
    let mut force = Panel::new(
        "force against Hertz's",
        Axis::lin("t / t_Hertz", 0.0, 1.1),
        Axis::lin("F / F_Hertz,max", 0.0, 1.1),
        Legend::UpperRight,
    );
    force.series.push(Series::new(
        "Hertz",
        hertz_pulse(),
        cycle_color(0),
        Dash::Dashed,
    ));
    // one history per decade, each its own colour
    let decades = pts.iter().filter(|p| {
        let f = p.v0.log10().fract().abs();
        f < 1e-9 || (1.0 - f) < 1e-9
    });
    for (k, p) in decades.enumerate() {
        force.series.push(
            Series::new(
                format!("V0/c1 = {:e}", p.v0),
                p.force.clone(),
                cycle_color(k + 1),
                Dash::Solid,
            )
            .width(2),
        );
    }
    let page = Page {
        name: "sphere_impact",
        width: 1800,
        height: 600,
        panels: vec![rest, rad, force],
        stacked: false,
    };
    let mut files = vec![path];
    files.extend(save(&ctx.out, &page)?);
    Ok(Summary {
        files,
        points: pts.len(),
    })
}
