//! `field_snapshot`: the stress field over the half-plane at one instant, from the
//! homogeneous-function interior field ([`homogeneous::field::at`]) of the paper's wedge
//! potentials (Theta = 89 deg, gamma = 0.6, coupled, p = alpha/c1 = 0.3, `paper`).
//!
//! The fields of the self-similar problem depend on x/(c1 t) and y/(c1 t) only, so one snapshot
//! (c1 t = 1) shows them at every time. Two stacked panels over x in [-1.1, 1.1],
//! y in [-1.1, 0]: the maximum shear stress tau_max = ((sigma_xx - sigma_yy)^2/4 +
//! sigma_xy^2)^(1/2) on a logarithmic colour scale, and sigma_yy on a signed-logarithmic one,
//! both clipped (the stresses are singular, weakly, at the apex: gamma > cot Theta here; the
//! contact stress falls to zero at the contact edges x = +-p). Drawn over them: the P front r = c1 t, the S front r = c2 t, the head
//! waves (from (+-c1 t, 0) tangent to the S circle), the Rayleigh-wave positions x = +-c_R t
//! and the contact zone |x| < alpha t. Points ahead of the P front are at rest (light grey).
//! Each grid cell is computed at its centre (never on y = 0 or on x = +-p).

use homogeneous::Region;
use rayon::prelude::*;
use wedge::{Case, Coupling, Indenter, Solution};

use super::output::{Column, Table};
use super::paper::{indenter_line, material_line, write};
use super::plot::{Axis, Cell, ColorBar, Dash, Legend, Note, Page, Panel, Rgb, Series};
use super::{material, Ctx, FigError, Result, Summary};

/// Half-angle Theta (degrees) of the snapshot.
pub const THETA: f64 = 89.0;
/// Friction coefficient of the snapshot.
pub const GAMMA: f64 = 0.6;
/// Contact speed p = alpha/c1 of the snapshot.
pub const P: f64 = 0.3;
/// Solution variant of the snapshot.
pub const SOLUTION: Solution = Solution::Paper;
/// x range (units c1 t).
pub const X_RANGE: (f64, f64) = (-1.1, 1.1);
/// y range (units c1 t).
pub const Y_RANGE: (f64, f64) = (-1.1, 0.0);
/// Grid (cells in x, cells in y) in full mode.
pub const GRID_FULL: (usize, usize) = (144, 72);
/// Grid in quick mode.
pub const GRID_QUICK: (usize, usize) = (24, 12);
/// Colour range of tau_max/(mu cot Theta), logarithmic; values outside are clipped.
pub const TAU_CLIP: (f64, f64) = (1e-2, 3.0);
/// sigma_yy/(mu cot Theta): linear within +-SIGMA_LIN, logarithmic beyond, clipped at
/// +-SIGMA_MAX.
pub const SIGMA_LIN: f64 = 0.01;
/// See [`SIGMA_LIN`].
pub const SIGMA_MAX: f64 = 5.0;

/// Colour of the points at rest (ahead of the P front).
const AT_REST: Rgb = (235, 235, 235);

/// Cell centres of `n` equal cells covering [lo, hi].
pub fn centres(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo + (hi - lo) * (i as f64 + 0.5) / n as f64)
        .collect()
}

/// The CSV name of a wave region.
pub fn region_name(r: Region) -> &'static str {
    match r {
        Region::AheadOfP => "ahead_of_p",
        Region::BetweenPAndS => "between_p_and_s",
        Region::HeadWave => "head_wave",
        Region::BehindS => "behind_s",
    }
}

/// The maximum shear stress of a plane stress state.
pub fn tau_max(sxx: f64, syy: f64, sxy: f64) -> f64 {
    ((sxx - syy) / 2.0).hypot(sxy)
}

/// One grid point.
struct Point {
    x: f64,
    y: f64,
    region: Region,
    sxx: f64,
    syy: f64,
    sxy: f64,
}

impl Point {
    fn tau(&self) -> f64 {
        tau_max(self.sxx, self.syy, self.sxy)
    }
}

/// Piecewise-linear colour map through evenly spaced `stops`, at `s` in [0, 1].
pub fn colormap(stops: &[Rgb], s: f64) -> Rgb {
    let s = if s.is_finite() {
        s.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let f = s * (stops.len() - 1) as f64;
    let k = (f.floor() as usize).min(stops.len() - 2);
    let w = f - k as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + (f64::from(b) - f64::from(a)) * w).round() as u8;
    let (a, b) = (stops[k], stops[k + 1]);
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Viridis (sampled).
pub const VIRIDIS: [Rgb; 9] = [
    (68, 1, 84),
    (71, 44, 122),
    (59, 81, 139),
    (44, 113, 142),
    (33, 144, 141),
    (39, 173, 129),
    (92, 200, 99),
    (170, 220, 50),
    (253, 231, 37),
];

/// Red-blue diverging map, negative (blue) to positive (red).
const RDBU: [Rgb; 11] = [
    (5, 48, 97),
    (33, 102, 172),
    (67, 147, 195),
    (146, 197, 222),
    (209, 229, 240),
    (247, 247, 247),
    (253, 219, 199),
    (244, 165, 130),
    (214, 96, 77),
    (178, 24, 43),
    (103, 0, 31),
];

/// Position of tau in [0, 1] on the logarithmic colour scale.
fn tau_pos(v: f64) -> f64 {
    let (lo, hi) = (TAU_CLIP.0.log10(), TAU_CLIP.1.log10());
    if v > 0.0 {
        ((v.log10() - lo) / (hi - lo)).clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// Position of sigma in [0, 1] on the signed-logarithmic scale (0.5 at zero).
fn sigma_pos(v: f64) -> f64 {
    let g = |a: f64| (1.0 + a / SIGMA_LIN).ln();
    let s = v.signum() * g(v.abs().min(SIGMA_MAX)) / g(SIGMA_MAX);
    if s.is_finite() {
        (0.5 + s / 2.0).clamp(0.0, 1.0)
    } else {
        0.5
    }
}

fn num_text(v: f64) -> String {
    let a = v.abs();
    let t = if a >= 1.0 || a == 0.0 {
        format!("{a}")
    } else {
        format!("{a:e}")
    };
    if v < 0.0 {
        format!("−{t}")
    } else {
        t
    }
}

fn tau_bar() -> ColorBar {
    let n = 128;
    let (lo, hi) = (
        TAU_CLIP.0.log10().ceil() as i32,
        TAU_CLIP.1.log10().floor() as i32,
    );
    let mut ticks: Vec<(f64, String)> = (lo..=hi)
        .map(|e| 10f64.powi(e))
        .map(|v| (tau_pos(v), num_text(v)))
        .collect();
    if tau_pos(10f64.powi(hi)) < 0.95 {
        ticks.push((1.0, format!("≥ {}", num_text(TAU_CLIP.1))));
    }
    ColorBar {
        label: "τ_max/(μ cot Θ)".into(),
        colors: (0..n)
            .map(|k| colormap(&VIRIDIS, (k as f64 + 0.5) / n as f64))
            .collect(),
        ticks,
    }
}

fn sigma_bar() -> ColorBar {
    let n = 128;
    // decades from 10 SIGMA_LIN (closer ticks would crowd the zero), then the clip values
    let mut ticks = vec![(0.5, "0".to_string())];
    let mut v = 10.0 * SIGMA_LIN;
    while v < SIGMA_MAX * 0.6 {
        ticks.push((sigma_pos(v), num_text(v)));
        ticks.push((sigma_pos(-v), num_text(-v)));
        v *= 10.0;
    }
    ticks.push((1.0, format!("≥ {}", num_text(SIGMA_MAX))));
    ticks.push((0.0, format!("≤ {}", num_text(-SIGMA_MAX))));
    ColorBar {
        label: "σ_yy/(μ cot Θ)".into(),
        colors: (0..n)
            .map(|k| colormap(&RDBU, (k as f64 + 0.5) / n as f64))
            .collect(),
        ticks,
    }
}

/// An unlabelled polyline.
fn line(points: Vec<(f64, f64)>, color: Rgb, dash: Dash, width: u32) -> Series {
    Series {
        label: None,
        points,
        color,
        dash,
        width,
    }
}

/// The wave fronts, the Rayleigh-wave positions and the contact zone, labelled in place (a
/// legend would hide the field), in `color`.
fn overlay(panel: &mut Panel, m: f64, m_r: f64, color: Rgb) {
    let arc = |r: f64| -> Vec<(f64, f64)> {
        (0..=360)
            .map(|k| {
                let a = -std::f64::consts::PI * k as f64 / 360.0;
                (r * a.cos(), r * a.sin())
            })
            .collect()
    };
    let note = |at: (f64, f64), text: &str, color: Rgb| Note {
        at,
        text: text.into(),
        color,
        size: 16,
    };
    let grey = (60, 60, 60);
    panel.series.push(line(arc(1.0), color, Dash::Solid, 2));
    panel.series.push(line(arc(m), color, Dash::Dashed, 2));
    // head waves: from (+-1, 0) to the tangent points (+-m^2, -m (1 - m^2)^(1/2))
    let tan_y = -m * (1.0 - m * m).sqrt();
    for s in [-1.0, 1.0] {
        panel.series.push(line(
            vec![(s, 0.0), (s * m * m, tan_y)],
            color,
            Dash::Dotted,
            2,
        ));
    }
    // Rayleigh-wave positions: ticks down from the surface
    for s in [-1.0, 1.0] {
        panel.series.push(line(
            vec![(s * m_r, 0.0), (s * m_r, -0.07)],
            color,
            Dash::Solid,
            3,
        ));
        panel.notes.push(note((s * m_r - 0.015, -0.08), "R", color));
    }
    // the contact zone |x| < alpha t on the surface
    panel.series.push(line(
        vec![(-P, -0.004), (P, -0.004)],
        (0, 0, 0),
        Dash::Solid,
        6,
    ));
    panel.notes.push(note((-0.1, -0.02), "contact", color));
    panel
        .notes
        .push(note((0.66, -0.86), "P front r = c₁t", grey));
    panel
        .notes
        .push(note((-0.1, -0.56), "S front r = c₂t", color));
    panel.notes.push(note((0.74, -0.17), "head wave", color));
    panel.notes.push(note((-1.08, -0.95), "at rest", grey));
    panel.notes.push(note(
        (-1.08, -1.03),
        &format!(
            "Θ = {THETA}°, γ = {GAMMA}, coupled, α/c₁ = {P}, solution {}",
            SOLUTION.name()
        ),
        grey,
    ));
}

/// field_snapshot: tau_max and sigma_yy over the half-plane at c1 t = 1.
pub fn field_snapshot(ctx: &Ctx) -> Result<Summary> {
    let mat = material();
    let ind = Indenter::new(THETA, GAMMA, Coupling::On)?;
    let case = Case::new(&mat, &ind, P, SOLUTION)?;
    let pot = case.potentials()?;
    let (m, m_r) = (*case.m(), *case.m_r());
    let (nx, ny) = if ctx.quick { GRID_QUICK } else { GRID_FULL };
    let xs = centres(X_RANGE.0, X_RANGE.1, nx);
    let ys = centres(Y_RANGE.0, Y_RANGE.1, ny);
    ctx.plan(nx * ny);
    let pts: Vec<Point> = (0..nx * ny)
        .into_par_iter()
        .map(|k| {
            let (x, y) = (xs[k % nx], ys[k / nx]);
            let fv = homogeneous::field::at(&pot, &x, &y)
                .map_err(|e| FigError(format!("field at ({x}, {y}): {e}")))?;
            let c = fv.cartesian();
            ctx.tick();
            Ok(Point {
                x,
                y,
                region: fv.region,
                sxx: c.sxx,
                syy: c.syy,
                sxy: c.sxy,
            })
        })
        .collect::<Result<_>>()?;

    let clip_line = format!(
        "colour scales clipped: tau_max/(mu cot Theta) logarithmic in [{}, {}]; sigma_yy/(mu cot Theta) signed-logarithmic (linear within +-{SIGMA_LIN}) clipped at +-{SIGMA_MAX}; the stresses are singular at the apex (weakly, ~ r^(-2 Omega0), 2 Omega0 = {:.4}), while the contact stress falls to zero at the contact edges x = +-p; the CSV holds the unclipped values",
        TAU_CLIP.0,
        TAU_CLIP.1,
        2.0 * case.omega0()
    );
    let mut t = Table::new(
        "field_snapshot",
        "interior stresses over the half-plane at c1 t = 1 (fields depend on x/(c1 t), y/(c1 t) only)",
        vec![
            Column {
                name: dyncontact::report::wedge::keys::X_OVER_C1_T,
                meaning: "x/(c1 t), along the surface (cell centre)",
            },
            Column {
                name: dyncontact::report::wedge::keys::Y_OVER_C1_T,
                meaning: "y/(c1 t), out of the body (y < 0 in the body; cell centre)",
            },
            Column {
                name: "region",
                meaning: "wave region: ahead_of_p (at rest), between_p_and_s, head_wave, behind_s",
            },
            Column {
                name: "sxx_over_mu_cot_theta",
                meaning: "sigma_xx/(mu cot Theta)",
            },
            Column {
                name: "syy_over_mu_cot_theta",
                meaning: "sigma_yy/(mu cot Theta)",
            },
            Column {
                name: "sxy_over_mu_cot_theta",
                meaning: "sigma_xy/(mu cot Theta)",
            },
            Column {
                name: "tau_max_over_mu_cot_theta",
                meaning: "maximum shear stress ((sigma_xx - sigma_yy)^2/4 + sigma_xy^2)^(1/2)/(mu cot Theta)",
            },
        ],
    );
    t.param(material_line(&mat)?);
    t.param(format!(
        "{}; p = alpha/c1 = {P}; solution {}; fields from homogeneous::field::at (default tolerance)",
        indenter_line(&ind),
        SOLUTION.name()
    ));
    t.param(format!(
        "grid: {nx} x {ny} cells over x/(c1 t) in [{}, {}], y/(c1 t) in [{}, {}], values at the cell centres; m = c2/c1 = {m}, m_R = c_R/c1 = {m_r}",
        X_RANGE.0, X_RANGE.1, Y_RANGE.0, Y_RANGE.1
    ));
    t.param(clip_line);
    for q in &pts {
        t.push(vec![
            q.x.into(),
            q.y.into(),
            region_name(q.region).into(),
            q.sxx.into(),
            q.syy.into(),
            q.sxy.into(),
            q.tau().into(),
        ])?;
    }

    let (dx, dy) = (
        (X_RANGE.1 - X_RANGE.0) / nx as f64,
        (Y_RANGE.1 - Y_RANGE.0) / ny as f64,
    );
    // cells centred on the grid points; runs of equal colour along a row merged
    let cells = |color: &dyn Fn(&Point) -> Rgb| -> Vec<Cell> {
        let mut out: Vec<Cell> = Vec::new();
        for (k, q) in pts.iter().enumerate() {
            let c = if q.region == Region::AheadOfP {
                AT_REST
            } else {
                color(q)
            };
            let (x0, x1) = (q.x - dx / 2.0, q.x + dx / 2.0);
            match out.last_mut() {
                Some(last) if k % nx != 0 && last.color == c => last.to.0 = x1,
                _ => out.push(Cell {
                    from: (x0, q.y - dy / 2.0),
                    to: (x1, q.y + dy / 2.0),
                    color: c,
                }),
            }
        }
        out
    };
    let axes = || {
        (
            Axis::lin("x/(c₁t)", X_RANGE.0, X_RANGE.1),
            Axis::lin("y/(c₁t)", Y_RANGE.0, Y_RANGE.1),
        )
    };
    let (ax, ay) = axes();
    let mut tau = Panel::new(
        format!(
            "Maximum shear stress at c₁t = 1: log scale, clipped to [{}, {}]",
            TAU_CLIP.0, TAU_CLIP.1
        ),
        ax,
        ay,
        Legend::UpperRight,
    );
    tau.cells = cells(&|q| colormap(&VIRIDIS, tau_pos(q.tau())));
    tau.colorbar = Some(tau_bar());
    overlay(&mut tau, m, m_r, (255, 255, 255));
    let (ax, ay) = axes();
    let mut syy = Panel::new(
        format!(
            "σ_yy at c₁t = 1: signed log scale (linear within ±{SIGMA_LIN}), clipped at ±{SIGMA_MAX}"
        ),
        ax,
        ay,
        Legend::UpperRight,
    );
    syy.cells = cells(&|q| colormap(&RDBU, sigma_pos(q.syy)));
    syy.colorbar = Some(sigma_bar());
    overlay(&mut syy, m, m_r, (0, 0, 0));
    let page = Page {
        name: "field_snapshot",
        width: 1200,
        height: 1166,
        panels: vec![tau, syy],
        stacked: true,
    };
    write(ctx, &t, &page)
}
