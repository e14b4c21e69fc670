//! `regime_map`: the paper's apex regime over (Theta, gamma), coupled contact.
//!
//! Each grid node is a [`Case`] (p = 0.3, `paper`; Omega0 and the regime do not depend on p),
//! shaded by [`Case::regime`]: finite (Omega0 < 0, gamma < cot Theta), power (Omega0 > 0), with
//! the logarithmic boundary gamma = cot Theta drawn as a curve and contours of the apex
//! exponent 2 Omega0 (from [`Case::omega0`]). A second panel shows the apex exponent lambda of
//! the genuine solution (roots of the eigen-equation, [`genuine::apex::exponents`]): a power
//! singularity wherever gamma > 0.

use rayon::prelude::*;
use wedge::{ApexRegime, Case, Coupling, Indenter, Solution};

use super::contour::{as_polyline, Grid, Segment};
use super::output::{Column, Table};
use super::paper::{genuine_exponent, material_line, write};
use super::plot::{Axis, Cell, Dash, Legend, Note, Page, Panel, Rgb, Series};
use super::{material, palette, Ctx, Result, Summary};

/// Range of the half-angle Theta (degrees).
pub const THETA_RANGE: (f64, f64) = (60.0, 89.9);
/// Range of the friction coefficient.
pub const GAMMA_RANGE: (f64, f64) = (0.0, 1.0);
/// The contact speed p = alpha/c1 at which the cases are built.
pub const MAP_P: f64 = 0.3;
/// Contour levels of 2 Omega0 (the zero level is the boundary curve, drawn apart).
pub const LEVELS: [f64; 13] = [
    -0.10, -0.08, -0.06, -0.04, -0.02, 0.02, 0.04, 0.06, 0.08, 0.10, 0.12, 0.14, 0.16,
];

fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
        .collect()
}

fn shade(r: ApexRegime) -> Rgb {
    match r {
        ApexRegime::Finite => (198, 219, 239),
        ApexRegime::Logarithmic => (200, 200, 200),
        ApexRegime::Power => (253, 208, 162),
    }
}

/// regime_map: regimes, the boundary gamma = cot Theta and contours of 2 Omega0.
pub fn regime_map(ctx: &Ctx) -> Result<Summary> {
    let mat = material();
    let thetas = linspace(THETA_RANGE.0, THETA_RANGE.1, ctx.points(120, 14));
    let gammas = linspace(GAMMA_RANGE.0, GAMMA_RANGE.1, ctx.points(81, 11));
    ctx.plan(thetas.len() * gammas.len());
    // one column of the grid per Theta
    let m = mat.m(&0.0_f64);
    let columns: Vec<Vec<Cellv>> = thetas
        .par_iter()
        .map(|&theta| {
            gammas
                .iter()
                .map(|&gamma| {
                    let ind = Indenter::new(theta, gamma, Coupling::On)?;
                    let case = Case::new(&mat, &ind, MAP_P, Solution::Paper)?;
                    let g = genuine::apex::exponents(m, *case.beta(), gamma);
                    ctx.tick();
                    Ok((
                        case.regime(),
                        2.0 * case.omega0(),
                        g.kind,
                        genuine_exponent(&g),
                    ))
                })
                .collect::<Result<Vec<_>>>()
        })
        .collect::<Result<_>>()?;

    let mut t = Table::new(
        "regime_map",
        "the paper's apex regime and exponent 2 Omega0 over (Theta, gamma), coupled contact",
        vec![
            Column {
                name: dyncontact::report::wedge::keys::THETA_DEG,
                meaning: "wedge half-angle Theta in degrees",
            },
            Column {
                name: dyncontact::report::wedge::keys::GAMMA,
                meaning: "friction coefficient",
            },
            Column {
                name: dyncontact::report::wedge::keys::REGIME,
                meaning: "finite (gamma < cot Theta), logarithmic (=), power (>)",
            },
            Column {
                name: "two_omega0",
                meaning: "2 Omega0, Omega0 = (1/pi) atan(m^2 (beta + gamma)/(1 - beta gamma))",
            },
            Column {
                name: "genuine_regime",
                meaning: "apex regime of the genuine solution (finite, logarithmic, power)",
            },
            Column {
                name: "genuine_exponent",
                meaning: "lambda of the genuine apex stress sigma ~ r^(-lambda): the largest root of t^2 - m^2 (beta + gamma) t + beta gamma = 0, lambda = (2/pi) atan t (0 when none is positive)",
            },
        ],
    );
    t.param(material_line(&mat)?);
    t.param(format!(
        "grid: Theta {} values in [{}, {}] deg, gamma {} values in [{}, {}]; coupling on (beta = -cot Theta); p = alpha/c1 = {MAP_P} (Omega0 does not depend on p); solution paper",
        thetas.len(), THETA_RANGE.0, THETA_RANGE.1, gammas.len(), GAMMA_RANGE.0, GAMMA_RANGE.1
    ));
    for (theta, col) in thetas.iter().zip(&columns) {
        for (gamma, (r, e, gk, gl)) in gammas.iter().zip(col) {
            t.push(vec![
                (*theta).into(),
                (*gamma).into(),
                r.name().into(),
                (*e).into(),
                gk.name().into(),
                (*gl).into(),
            ])?;
        }
    }

    let mut panel = Panel::new(
        "Apex regime of the paper's solution (coupled, β = −cot Θ)",
        Axis::lin("wedge half-angle Θ (degrees)", THETA_RANGE.0, THETA_RANGE.1),
        Axis::lin("friction coefficient γ", GAMMA_RANGE.0, GAMMA_RANGE.1),
        Legend::UpperLeft,
    );
    // cells centred on the nodes, clipped to the axes; equal neighbours in a column merged
    let half = |v: &[f64], i: usize| -> (f64, f64) {
        let lo = if i == 0 {
            v[0]
        } else {
            (v[i - 1] + v[i]) / 2.0
        };
        let hi = if i + 1 == v.len() {
            v[i]
        } else {
            (v[i] + v[i + 1]) / 2.0
        };
        (lo, hi)
    };
    for (i, col) in columns.iter().enumerate() {
        let (x0, x1) = half(&thetas, i);
        let mut j = 0;
        while j < col.len() {
            let r = col[j].0;
            let k = (j..col.len())
                .take_while(|&k| col[k].0 == r)
                .last()
                .unwrap_or(j);
            panel.cells.push(Cell {
                from: (x0, half(&gammas, j).0),
                to: (x1, half(&gammas, k).1),
                color: shade(r),
            });
            j = k + 1;
        }
    }
    // contours of 2 Omega0
    let z: Vec<Vec<f64>> = columns
        .iter()
        .map(|c| c.iter().map(|v| v.1).collect())
        .collect();
    let grid = Grid {
        xs: &thetas,
        ys: &gammas,
        z: &z,
    };
    let (mut first_neg, mut first_pos) = (true, true);
    for level in LEVELS {
        let mut segs = grid.contour(level);
        if segs.is_empty() {
            continue;
        }
        let (label, dash, first) = if level < 0.0 {
            (
                "contours of 2Ω₀ < 0 (step 0.02)",
                Dash::Dotted,
                &mut first_neg,
            )
        } else {
            (
                "contours of 2Ω₀ > 0 (step 0.02)",
                Dash::Solid,
                &mut first_pos,
            )
        };
        let mut s = Series::new(label, as_polyline(&segs), palette::GREY, dash).width(1);
        if !*first {
            s.label = None;
        }
        *first = false;
        panel.series.push(s);
        label_contour(&mut panel, &mut segs, format!("{level:+.2}"));
    }
    // the logarithmic boundary gamma = cot Theta
    let boundary = cot_theta_curve();
    panel.series.insert(
        0,
        Series::new(
            "logarithmic: γ = cot Θ (2Ω₀ = 0)",
            boundary,
            palette::BLACK,
            Dash::Solid,
        )
        .width(3),
    );
    panel.notes.push(Note {
        at: (60.6, 0.83),
        text: "power singularity: σ ~ r^(−2Ω₀), 2Ω₀ > 0 (γ > cot Θ)".into(),
        color: (140, 60, 0),
        size: 17,
    });
    panel.notes.push(Note {
        at: (61.0, 0.12),
        text: "finite apex stress (γ < cot Θ)".into(),
        color: (0, 60, 120),
        size: 17,
    });
    let gpanel = genuine_panel(&thetas, &gammas, &columns);
    let page = Page {
        name: "regime_map",
        width: 2000,
        height: 800,
        panels: vec![panel, gpanel],
        stacked: false,
    };
    write(ctx, &t, &page)
}

/// One grid node: the paper's regime and 2 Omega0, the genuine regime and exponent.
type Cellv = (ApexRegime, f64, wedge::ApexRegime, f64);

/// Contour levels of the genuine apex exponent lambda.
pub const GENUINE_LEVELS: [f64; 8] = [0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4];

/// The right panel: contours of the genuine apex exponent (a power singularity wherever
/// gamma > 0, including below gamma = cot Theta where the paper's apex stress is finite).
fn genuine_panel(thetas: &[f64], gammas: &[f64], columns: &[Vec<Cellv>]) -> Panel {
    let mut panel = Panel::new(
        "Apex exponent λ of the genuine solution, σ ~ r^(−λ)",
        Axis::lin("wedge half-angle Θ (degrees)", THETA_RANGE.0, THETA_RANGE.1),
        Axis::lin("friction coefficient γ", GAMMA_RANGE.0, GAMMA_RANGE.1),
        Legend::UpperLeft,
    );
    let z: Vec<Vec<f64>> = columns
        .iter()
        .map(|c| c.iter().map(|v| v.3).collect())
        .collect();
    let grid = Grid {
        xs: thetas,
        ys: gammas,
        z: &z,
    };
    let mut first = true;
    for level in GENUINE_LEVELS {
        let mut segs = grid.contour(level);
        if segs.is_empty() {
            continue;
        }
        let mut s = Series::new(
            "contours of λ (step 0.05)",
            as_polyline(&segs),
            (140, 60, 0),
            Dash::Solid,
        )
        .width(1);
        if !first {
            s.label = None;
        }
        first = false;
        panel.series.push(s);
        label_contour(&mut panel, &mut segs, format!("{level:.2}"));
    }
    // the paper's boundary, for comparison
    let boundary = cot_theta_curve();
    panel.series.insert(
        0,
        Series::new(
            "γ = cot Θ (the paper's regime boundary)",
            boundary,
            palette::BLACK,
            Dash::Dashed,
        )
        .width(2),
    );
    panel.notes.push(Note {
        at: (60.6, 0.05),
        text: "power singularity for every γ > 0; finite only at γ = 0".into(),
        color: (140, 60, 0),
        size: 17,
    });
    panel
}

/// The label `text` at the middle of a contour (its segments ordered by Theta).
fn label_contour(panel: &mut Panel, segs: &mut [Segment], text: String) {
    segs.sort_by(|a, b| (a.0 .0 + a.1 .0).total_cmp(&(b.0 .0 + b.1 .0)));
    let ((xa, ya), (xb, yb)) = segs[segs.len() / 2];
    panel.notes.push(Note {
        at: ((xa + xb) / 2.0, (ya + yb) / 2.0),
        text,
        color: (60, 60, 60),
        size: 14,
    });
}

/// The curve gamma = cot Theta over the Theta range of the map.
fn cot_theta_curve() -> Vec<(f64, f64)> {
    linspace(THETA_RANGE.0, THETA_RANGE.1, 300)
        .into_iter()
        .map(|th| (th, 1.0 / th.to_radians().tan()))
        .collect()
}
