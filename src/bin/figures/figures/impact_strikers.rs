//! `impact_strikers`: rigid, elastic (local model), thin-shell and full elastic cylinder
//! strikers at one impact speed on the same half-plane (`docs/strikers.md`), over whole
//! impacts to their separation: penetration of the mass centre, contact force, contact
//! half-width and the share of the impact energy taken up by the striker.
//!
//! The half-plane is the paper's material (c2/c1 = 1000/1870.83); the strikers are of a steel
//! (c1s = 5900 m/s, c2s = 3200 m/s, three times the half-plane's density): the shell has
//! h_s/R = 0.05, whose mass m0/(rho R^2) = 2 pi 0.05 3 = 0.942 the rigid and the elastic
//! strikers share; the solid cylinder's mass is its own, pi 3 = 9.42, beside a rigid striker of
//! that mass; V0/c1 = 0.01, parabolic profile of radius R, Signorini edge. The elastic
//! striker's local half-plane model holds until c1 t/R = 2 c1/c1s = 0.634, where its curves
//! stop.

use std::path::PathBuf;

use impact::{
    Drive, EdgeLaw, HistoryRow, ImpactCase, Profile, ShellStriker, Striker, StrikerMaterial,
};

use super::output::{Cell, Column, Table};
use super::plot::{save, Axis, Dash, Legend, Page, Panel, Series};
use super::{cycle_color, Ctx, FigError, Result, Summary};

// the half-plane of the benchmark's reference case
const C1: f64 = impact::REFERENCE.c1;
const C2: f64 = impact::REFERENCE.c2;
const STEEL: (f64, f64, f64) = (5900.0, 3200.0, 3.0);
const THICKNESS: f64 = 0.05;
const V0: f64 = 0.01;

/// The thin steel shell; its mass m0/(rho R^2) is the one all three strikers share.
fn shell() -> ShellStriker {
    ShellStriker {
        thickness: THICKNESS,
        material: steel(),
    }
}

fn steel() -> StrikerMaterial {
    StrikerMaterial {
        c1_ratio: STEEL.0 / C1,
        c2_ratio: STEEL.1 / C1,
        density_ratio: STEEL.2,
    }
}

/// Each striker with its mass m0/(rho R^2).
fn strikers() -> Vec<(&'static str, Striker, f64)> {
    let light = shell().mass_ratio();
    let cylinder = Striker::Cylinder(steel());
    let heavy = cylinder.own_mass_ratio().unwrap_or(light);
    vec![
        ("rigid", Striker::Rigid, light),
        ("elastic", Striker::Elastic(steel()), light),
        ("shell", Striker::Shell(shell()), light),
        ("cylinder", cylinder, heavy),
        ("rigid_cylinder_mass", Striker::Rigid, heavy),
    ]
}

/// The history to the separation (at most `end`), or to the elastic striker's model's end.
fn solve(striker: Striker, mass_ratio: f64, end: f64, dx: f64) -> Result<Vec<HistoryRow>> {
    let nu = lamb::poisson_of(&(C2 / C1).powi(2));
    let local_end = striker.validity_end();
    let mut case = ImpactCase::new(
        nu,
        Profile::Parabola { radius: 1.0 },
        Drive::Free {
            mass_ratio,
            v0_over_c1: V0,
        },
        EdgeLaw::Signorini,
        end.min(local_end),
    )
    .with_striker(striker);
    if local_end.is_infinite() {
        case.stop = impact::Stop::AtSeparation;
    }
    case.dx = dx;
    case.levels = 2;
    let sol = case
        .solve(|_| {})
        .map_err(|e| FigError(format!("{} striker: {e}", striker.name())))?;
    Ok(sol.history().0)
}

/// impact_strikers: rigid, elastic, shell and cylinder strikers at one speed, to their
/// separation.
pub fn impact_strikers(ctx: &Ctx) -> Result<Summary> {
    let (end, dx) = if ctx.quick {
        (40.0, 0.02)
    } else {
        (40.0, 0.005)
    };
    let list = strikers();
    ctx.plan(list.len());
    let mut runs = Vec::new();
    for (name, s, mass) in &list {
        runs.push((*name, solve(*s, *mass, end, dx)?, 0.5 * mass * V0 * V0));
        ctx.tick();
    }
    let end = runs
        .iter()
        .filter_map(|r| r.1.last().map(|l| l.t))
        .fold(0.0, f64::max);
    let mut table = Table::new(
        "impact_strikers",
        "rigid, elastic (local half-plane model), thin-shell and full elastic cylinder strikers at one impact speed, to their separation",
        vec![
            Column { name: dyncontact::report::impact::keys::STRIKER, meaning: "rigid, elastic, shell, cylinder, or rigid_cylinder_mass (the rigid striker of the cylinder's mass)" },
            Column { name: dyncontact::report::impact::keys::C1T_OVER_R, meaning: "time c1 t/R" },
            Column { name: dyncontact::report::impact::keys::H_OVER_R, meaning: "penetration of the mass centre h/R" },
            Column { name: dyncontact::report::impact::keys::ERR_H_OVER_R, meaning: "its absolute error estimate (two grids)" },
            Column { name: dyncontact::report::impact::keys::B_OVER_R, meaning: "contact half-width b/R" },
            Column { name: dyncontact::report::impact::keys::ERR_B_OVER_R, meaning: "its absolute error estimate" },
            Column { name: dyncontact::report::impact::keys::FORCE_OVER_RHO_C1SQ_R, meaning: "contact force per unit length over rho c1^2 R" },
            Column { name: dyncontact::report::impact::keys::ERR_FORCE_OVER_RHO_C1SQ_R, meaning: "its absolute error estimate" },
            Column { name: "striker_energy_share", meaning: "energy taken up by the striker's deformation over its impact energy (0 for the rigid striker)" },
        ],
    );
    table.param(format!(
        "material: c1 = {C1} m/s, c2 = {C2} m/s (the half-plane)"
    ));
    table.param(format!(
        "half-plane c1 = {C1} m/s, c2 = {C2} m/s; strikers c1s = {} m/s, c2s = {} m/s, rho_s/rho = {}; shell h_s/R = {THICKNESS}; rigid and elastic of the shell's mass m0/(rho R^2) = 2 pi h_s/R rho_s/rho, the cylinder of its own pi rho_s/rho beside a rigid striker of that mass; V0/c1 = {V0}; parabola of radius R; signorini edge; to the separation; dx/R = {dx}, kappa = 2, two grids",
        STEEL.0, STEEL.1, STEEL.2
    ));
    let err = |v: &impact::Value| v.error.map(Cell::Num).unwrap_or(Cell::Empty);
    for (name, rows, ke0) in &runs {
        let ke0 = *ke0;
        for r in rows {
            let share = r.striker_energy.map(|e| e.value / ke0).unwrap_or(0.0);
            table.push(vec![
                Cell::from(*name),
                r.t.into(),
                r.h.value.into(),
                err(&r.h),
                r.b.value.into(),
                err(&r.b),
                r.force.value.into(),
                err(&r.force),
                share.into(),
            ])?;
        }
    }
    let path: PathBuf = table.write(&ctx.out)?;
    let panel = |title: &str,
                 ylabel: &str,
                 get: &dyn Fn(&HistoryRow, f64) -> f64,
                 legend,
                 headroom: f64| {
        // `headroom` above the largest value leaves the legend clear of the curves
        let all = || {
            runs.iter()
                .flat_map(|(_, rows, ke0)| rows.iter().map(|r| get(r, *ke0)))
        };
        let top = all().fold(0.0, f64::max) * headroom;
        let mut p = Panel::new(
            title,
            Axis::lin("c1 t/R", 0.0, end),
            Axis::fit(ylabel, all().chain([0.0, top]), 0.05),
            legend,
        );
        for (name, rows, ke0) in &runs {
            let label = match *name {
                "elastic" => format!(
                    "elastic (local model, to c1 t/R = {:.3})",
                    2.0 * C1 / STEEL.0
                ),
                "rigid" => format!("rigid (mass {:.3})", shell().mass_ratio()),
                "rigid_cylinder_mass" => "rigid (the cylinder's mass)".to_string(),
                "cylinder" => format!("cylinder (mass {:.2})", 2.0 * ke0 / (V0 * V0)),
                other => other.to_string(),
            };
            let pts = rows.iter().map(|r| (r.t, get(r, *ke0))).collect();
            // each striker its own colour; the rigid striker of the cylinder's mass dashed
            // black beside the cylinder
            let (colour, dash) = match *name {
                "rigid" => (1, Dash::Solid),
                "elastic" => (3, Dash::Dashed),
                "shell" => (5, Dash::Dotted),
                "cylinder" => (4, Dash::Solid),
                _ => (0, Dash::Dashed),
            };
            p.series
                .push(Series::new(label, pts, cycle_color(colour), dash).width(3));
        }
        p
    };
    let page = Page {
        name: "impact_strikers",
        width: 1600,
        height: 1200,
        panels: vec![
            panel(
                "penetration of the mass centre",
                "h/R",
                &|r, _| r.h.value,
                Legend::UpperLeft,
                1.0,
            ),
            panel(
                "contact force",
                "force / (rho c1^2 R)",
                &|r, _| r.force.value,
                Legend::UpperRight,
                1.35,
            ),
            panel(
                "contact half-width",
                "b/R",
                &|r, _| r.b.value,
                Legend::LowerRight,
                1.0,
            ),
            panel(
                "energy taken up by the striker",
                "share of the impact energy",
                &|r, ke0| r.striker_energy.map(|e| e.value / ke0).unwrap_or(0.0),
                Legend::UpperLeft,
                1.0,
            ),
        ],
        stacked: false,
    };
    let mut files = vec![path];
    files.extend(save(&ctx.out, &page)?);
    Ok(Summary {
        files,
        points: runs.iter().map(|(_, r, _)| r.len()).sum(),
    })
}
