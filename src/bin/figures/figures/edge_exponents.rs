//! `edge_exponents`: the power lambda of the contact pressure p ~ d^lambda at an edge moving at
//! D along the surface, against D/c1, for four Poisson's ratios (`lamb::edge`,
//! `docs/edge.md`): the admissible pair of local solutions and the exponent each edge law
//! selects, the speed ranges shaded.

use std::path::PathBuf;

use lamb::edge::{EdgeLaw, SpeedRange};
use lamb::HalfPlane;

use super::output::{Cell as CsvCell, Column, Table};
use super::plot::{save, Axis, Cell, Dash, Legend, Note, Page, Panel, Series};
use super::{palette, Ctx, FigError, Result, Summary};

/// Poisson's ratios of the four panels.
const POISSON: [f64; 4] = [0.1, 0.25, 0.35, 0.45];
/// The largest D/c1 drawn.
const D_MAX: f64 = 1.5;

fn range_color(r: SpeedRange) -> (u8, u8, u8) {
    match r {
        SpeedRange::SubRayleigh => (235, 242, 250),
        SpeedRange::RayleighShear => (252, 236, 222),
        SpeedRange::Transonic => (232, 245, 235),
        SpeedRange::Supersonic => (242, 242, 242),
    }
}

/// The rows of one speed range: (low, high, signorini, kinematic) exponents and the speeds.
type Segment = (SpeedRange, Vec<[Option<f64>; 4]>, Vec<f64>);

/// edge_exponents: the exponent against the edge speed.
pub fn edge_exponents(ctx: &Ctx) -> Result<Summary> {
    let n = ctx.points(600, 120);
    ctx.plan(POISSON.len());
    let mut table = Table::new(
        "edge_exponents",
        "power lambda of the contact pressure p ~ d^lambda at an edge moving at D (d the distance from the edge into the contact)",
        vec![
            Column { name: dyncontact::report::impact::keys::POISSON, meaning: "Poisson's ratio nu" },
            Column { name: dyncontact::report::impact::keys::SPEED_OVER_C1, meaning: "edge speed D/c1" },
            Column { name: dyncontact::report::impact::keys::RANGE, meaning: "sub-rayleigh, rayleigh-shear, transonic or supersonic" },
            Column { name: "exponent_low", meaning: "the lower admissible exponent" },
            Column { name: "exponent_high", meaning: "the upper admissible exponent (empty where a single local solution exists)" },
            Column { name: "selected_signorini", meaning: "the exponent a free edge selects (signorini law)" },
            Column { name: "selected_kinematic", meaning: "the exponent a prescribed edge selects (kinematic law, eq (4))" },
        ],
    );
    table.param("material: Poisson's ratios 0.1, 0.25, 0.35, 0.45 (only c2/c1 enters)");
    table.param(format!(
        "{n} speeds per panel, evenly spaced in (0, {D_MAX}], speeds within 1e-6 of c_R, c2, c1 left out (the exponents jump there)"
    ));
    let mut panels = Vec::new();
    let mut points = 0;
    for &nu in POISSON.iter() {
        let hp = HalfPlane::from_poisson(nu).map_err(|e| FigError(e.to_string()))?;
        let (m, sr) = (*hp.m(), *hp.s_r());
        let mut panel = Panel::new(
            format!("nu = {nu}: c_R/c1 = {sr:.4}, c2/c1 = {m:.4} (rayleigh-shear band between)"),
            Axis::lin("edge speed D/c1", 0.0, D_MAX),
            Axis::lin("exponent lambda (p ~ d^lambda)", -1.05, 1.05),
            Legend::LowerRight,
        );
        for (x, text) in [
            (0.5 * sr, "sub-Rayleigh"),
            (0.5 * (m + 1.0), "transonic"),
            (0.5 * (1.0 + D_MAX), "supersonic"),
        ] {
            panel.notes.push(Note {
                at: (x - 0.06, 0.97),
                text: text.into(),
                color: palette::BLACK,
                size: 18,
            });
        }
        for (lo, hi, r) in [
            (0.0, sr, SpeedRange::SubRayleigh),
            (sr, m, SpeedRange::RayleighShear),
            (m, 1.0, SpeedRange::Transonic),
            (1.0, D_MAX, SpeedRange::Supersonic),
        ] {
            panel.cells.push(Cell {
                from: (lo, -1.05),
                to: (hi, 1.05),
                color: range_color(r),
            });
        }
        // one segment per speed range, so that no line joins across a jump
        let mut segs: Vec<Segment> = Vec::new();
        for i in 1..=n {
            let d = D_MAX * i as f64 / n as f64;
            if [sr, m, 1.0].iter().any(|c| (d - c).abs() <= 1e-6 * c) {
                continue;
            }
            let sig = hp
                .edge_behaviour(d, EdgeLaw::Signorini)
                .map_err(|e| FigError(format!("nu = {nu}, D/c1 = {d}: {e}")))?;
            let kin = hp
                .edge_behaviour(d, EdgeLaw::Kinematic)
                .map_err(|e| FigError(format!("nu = {nu}, D/c1 = {d}: {e}")))?;
            let low = sig.solutions.first().map(|s| s.lambda);
            let high = sig.solutions.get(1).map(|s| s.lambda);
            table.push(vec![
                nu.into(),
                d.into(),
                sig.range.name().into(),
                low.map(CsvCell::Num).unwrap_or(CsvCell::Empty),
                high.map(CsvCell::Num).unwrap_or(CsvCell::Empty),
                sig.selected.into(),
                kin.selected.into(),
            ])?;
            points += 1;
            let row = [low, high, Some(sig.selected), Some(kin.selected)];
            match segs.last_mut() {
                Some((r, rows, ds)) if *r == sig.range => {
                    rows.push(row);
                    ds.push(d);
                }
                _ => segs.push((sig.range, vec![row], vec![d])),
            }
        }
        for (si, (_, rows, ds)) in segs.iter().enumerate() {
            let curve = |q: usize| -> Vec<(f64, f64)> {
                ds.iter()
                    .zip(rows)
                    .filter_map(|(d, r)| r[q].map(|v| (*d, v)))
                    .collect()
            };
            let label = |s: &str| if si == 0 { Some(s.to_string()) } else { None };
            for (q, name, color, dash, width) in [
                (0, "admissible exponents", palette::GREY, Dash::Solid, 6),
                (1, "admissible exponents", palette::GREY, Dash::Solid, 6),
                (
                    2,
                    "selected, signorini (free edge)",
                    palette::BLUE,
                    Dash::Solid,
                    3,
                ),
                (
                    3,
                    "selected, kinematic (prescribed edge)",
                    palette::RED,
                    Dash::Dashed,
                    3,
                ),
            ] {
                let pts = curve(q);
                if pts.is_empty() {
                    continue;
                }
                let mut s = Series::new(name, pts, color, dash).width(width);
                s.label = if q == 1 { None } else { label(name) };
                panel.series.push(s);
            }
        }
        panels.push(panel);
        ctx.tick();
    }
    let path: PathBuf = table.write(&ctx.out)?;
    let page = Page {
        name: "edge_exponents",
        width: 1600,
        height: 1200,
        panels,
        stacked: false,
    };
    let mut files = vec![path];
    files.extend(save(&ctx.out, &page)?);
    Ok(Summary { files, points })
}
