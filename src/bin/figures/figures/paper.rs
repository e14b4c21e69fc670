//! The reference paper's Figs 3-7, recomputed with the library (f64 path).
//!
//! * `fig3`: tangential velocity at the contact edge against alpha (Theta = 89 deg, gamma = 0.6,
//!   coupled): the particle velocity du_r/dt at r = alpha t and the paper's edge-following rate
//!   u_r(alpha t, t)/t, both over V, for every variant of [`VARIANTS`].
//! * `fig4`: the classical alpha-V relation (frictionless, uncoupled).
//! * `fig5`: the alpha-V relation with coupling and friction gamma = 0.4 at Theta = 86 and 89 deg,
//!   every variant of the paper's construction and the genuine solution (dotted, on its own
//!   sweep of [`GENUINE_POINTS`] speeds up to [`GENUINE_TOP`] m_R), with the classical curve.
//! * `fig6`, `fig7`: the contact stress at p = 0.3 for gamma = 0.001 and 0.6 (Theta = 86, 89 deg),
//!   along the contact and, log-log, near the apex with the paper's leading apex term; the
//!   genuine stress (dotted) beside the paper's.
//!
//! Speeds on the axes are over c2, as in the paper; the indenter speed is also divided by
//! cot Theta (V is proportional to cot Theta at fixed alpha).

use rayon::prelude::*;
use wedge::{ApexRegime, Case, Coupling, Indenter, Material, Solution};

use super::output::{Cell, Column, Table};
use super::plot::{save, Axis, Dash, Legend, Note, Page, Panel, Series};
use super::{fmt_num, interior, logspace, material, palette, Ctx, FigError, Result, Summary};
use super::{v_hat, VariantStyle, GENUINE, VARIANTS};
use dyncontact::{solve_at, Solved};
use wedge::ContactSolution;

/// The contact speeds p = alpha/c1 of the alpha sweeps: n interior points of (0, m_R),
/// evenly spaced in alpha; with `tail`, followed by p = m_R (1 - 10^(-k/2)), k = 4..8, which
/// approach the Rayleigh speed (the last at 1e-4 below it, where the f64 path still holds
/// about 10 digits).
pub fn alpha_sweep(mat: &Material, n: usize, tail: bool) -> Result<Vec<f64>> {
    let m_r = mat.m_r()?;
    let mut s = interior(n);
    if tail {
        let last = s.last().copied().unwrap_or(0.0);
        s.extend(
            (4..=8)
                .map(|k| 1.0 - 10f64.powf(-(k as f64) / 2.0))
                .filter(|&x| x > last),
        );
    }
    Ok(s.into_iter().map(|s| s * m_r).collect())
}

pub fn material_line(mat: &Material) -> Result<String> {
    Ok(format!(
        "material: c1 = {} m/s, c2 = {} m/s, c_R = {:.6} m/s (Poisson's ratio {:.6})",
        mat.c1().text(),
        mat.c2().text(),
        mat.m_r()? * mat.c1().value(),
        mat.poisson()
    ))
}

pub fn indenter_line(ind: &Indenter) -> String {
    format!(
        "indenter: Theta = {} deg, gamma = {}, coupling {}",
        ind.theta_deg().text(),
        ind.gamma().text(),
        match ind.coupling() {
            Coupling::On => "on (beta = -cot Theta)",
            Coupling::Off => "off (beta = 0)",
        }
    )
}

fn variants_line() -> String {
    let names: Vec<String> = VARIANTS
        .iter()
        .map(|v| format!("{} ({})", v.solution.name(), dash_name(v.dash)))
        .collect();
    format!("solutions: {}", names.join(", "))
}

fn dash_name(d: Dash) -> &'static str {
    match d {
        Dash::Solid => "solid",
        Dash::Dashed => "dashed",
        Dash::Dotted => "dotted",
    }
}

pub fn write(ctx: &Ctx, table: &Table, page: &Page) -> Result<Summary> {
    std::fs::create_dir_all(&ctx.out)
        .map_err(|e| FigError(format!("cannot create {}: {e}", ctx.out.display())))?;
    let mut files = vec![table.write(&ctx.out)?];
    files.extend(save(&ctx.out, page)?);
    Ok(Summary {
        files,
        points: table.rows.len(),
    })
}

// ---------------------------------------------------------------------------------------------
// fig3

/// One point of fig3.
struct EdgePoint {
    variant: VariantStyle,
    p: f64,
    v_hat: f64,
    slip: f64,
    follow: f64,
}

/// The indenter of fig3.
pub fn fig3_indenter() -> Result<Indenter> {
    Ok(Indenter::new(89.0, 0.6, Coupling::On)?)
}

/// fig3: edge particle velocity and edge-following rate over V against alpha/c2.
pub fn fig3(ctx: &Ctx) -> Result<Summary> {
    let mat = material();
    let ind = fig3_indenter()?;
    let m = mat.m(&0.0_f64);
    let c_r_over_c2 = mat.m_r()? / m;
    let ps = alpha_sweep(&mat, ctx.points(100, 6), false)?;
    let jobs: Vec<(VariantStyle, f64)> = VARIANTS
        .iter()
        .flat_map(|v| ps.iter().map(move |&p| (*v, p)))
        .collect();
    ctx.plan(jobs.len());
    let pts: Vec<EdgePoint> = jobs
        .par_iter()
        .map(|&(variant, p)| {
            let case = Case::new(&mat, &ind, p, variant.solution)?;
            let pt = EdgePoint {
                variant,
                p,
                v_hat: case.v_hat()?,
                slip: case.edge_slip_velocity_over_speed()?,
                follow: case.edge_following_rate_over_speed()?,
            };
            ctx.tick();
            Ok(pt)
        })
        .collect::<Result<_>>()?;

    let mut t = Table::new(
        "fig3",
        "tangential velocity at the contact edge r = alpha t against the contact speed alpha",
        vec![
            Column {
                name: dyncontact::report::wedge::keys::SOLUTION,
                meaning: "solution variant",
            },
            Column {
                name: dyncontact::report::wedge::keys::P,
                meaning: "p = alpha/c1 (input of the case)",
            },
            Column {
                name: "alpha_over_c2",
                meaning: "alpha/c2",
            },
            Column {
                name: dyncontact::report::wedge::keys::V_OVER_C1_COT_THETA,
                meaning: "indenter speed V/(c1 cot Theta)",
            },
            Column {
                name: dyncontact::report::wedge::keys::EDGE_SLIP_VELOCITY_OVER_SPEED,
                meaning: "particle velocity (du_r/dt)(r = alpha t)/V (docs/errata.md, section 5)",
            },
            Column {
                name: dyncontact::report::wedge::keys::EDGE_FOLLOWING_RATE_OVER_SPEED,
                meaning: "the paper's Fig. 3 expression: u_r(alpha t, t)/(V t)",
            },
        ],
    );
    t.param(material_line(&mat)?);
    t.param(indenter_line(&ind));
    t.param(variants_line());
    for q in &pts {
        t.push(vec![
            q.variant.solution.name().into(),
            q.p.into(),
            (q.p / m).into(),
            q.v_hat.into(),
            q.slip.into(),
            q.follow.into(),
        ])?;
    }

    let mut panel = Panel::new(
        "Fig. 3: tangential velocity at the contact edge (Θ = 89°, γ = 0.6, coupled)",
        Axis::lin("contact-zone speed α/c₂", 0.0, c_r_over_c2),
        Axis::fit(
            "velocity / V",
            pts.iter().flat_map(|q| [q.slip, q.follow]).chain([0.0]),
            0.06,
        ),
        Legend::UpperLeft,
    );
    panel.series.push(Series {
        label: None,
        points: vec![(0.0, 0.0), (c_r_over_c2, 0.0)],
        color: palette::GREY,
        dash: Dash::Solid,
        width: 1,
    });
    for v in VARIANTS {
        let of = |f: fn(&EdgePoint) -> f64| -> Vec<(f64, f64)> {
            pts.iter()
                .filter(|q| q.variant.solution == v.solution)
                .map(|q| (q.p / m, f(q)))
                .collect()
        };
        let name = v.solution.name();
        panel.series.push(Series::new(
            format!("particle velocity ∂u_r/∂t at r = αt ({name})"),
            of(|q| q.slip),
            palette::BLUE,
            v.dash,
        ));
        panel.series.push(Series::new(
            format!("edge-following rate u_r(αt, t)/t, paper's Fig. 3 ({name})"),
            of(|q| q.follow),
            palette::RED,
            v.dash,
        ));
    }
    let page = Page {
        name: "fig3",
        width: 1100,
        height: 750,
        panels: vec![panel],
        stacked: false,
    };
    write(ctx, &t, &page)
}

// ---------------------------------------------------------------------------------------------
// fig4 and fig5: alpha against V

/// One curve of the alpha-V relation.
pub struct SpeedCurve {
    /// Legend label.
    pub label: String,
    /// Indenter.
    pub indenter: Indenter,
    /// Variant.
    pub solution: Solution,
    /// Colour.
    pub color: super::plot::Rgb,
    /// Dash.
    pub dash: Dash,
}

/// The classical curve (frictionless, uncoupled; Theta enters only through V/cot Theta).
pub fn classical_curve() -> Result<SpeedCurve> {
    Ok(SpeedCurve {
        label: "classical (γ = 0, uncoupled)".into(),
        indenter: Indenter::classical(89.0)?,
        solution: Solution::Paper,
        color: palette::BLACK,
        dash: Dash::Solid,
    })
}

/// The curves of fig5: classical, then Theta = 86 and 89 deg with gamma = 0.4 for each variant
/// of the paper's construction and for the genuine solution.
pub fn fig5_curves() -> Result<Vec<SpeedCurve>> {
    let mut c = vec![classical_curve()?];
    for (theta, color) in [(86.0, palette::BLUE), (89.0, palette::RED)] {
        for v in VARIANTS.iter().chain([&GENUINE]) {
            c.push(SpeedCurve {
                label: format!("Θ = {theta}°, γ = 0.4, coupled ({})", v.solution.name()),
                indenter: Indenter::new(theta, 0.4, Coupling::On)?,
                solution: v.solution,
                color,
                dash: v.dash,
            });
        }
    }
    Ok(c)
}

/// alpha/c2 against V/(c2 cot Theta) for the given curves.
fn speed_figure(
    ctx: &Ctx,
    name: &'static str,
    title: &str,
    curves: &[SpeedCurve],
    n: usize,
) -> Result<Summary> {
    let mat = material();
    let m = mat.m(&0.0_f64);
    let c_r_over_c2 = mat.m_r()? / m;
    let ps = alpha_sweep(&mat, n, true)?;
    let gps = genuine_sweep(&mat, ctx.points(GENUINE_POINTS, 3))?;
    let jobs: Vec<(usize, f64)> = (0..curves.len())
        .flat_map(|k| {
            let sweep = if curves[k].solution == Solution::Genuine {
                &gps
            } else {
                &ps
            };
            sweep.iter().map(move |&p| (k, p))
        })
        .collect();
    ctx.plan(jobs.len());
    let vs: Vec<f64> = jobs
        .par_iter()
        .map(|&(k, p)| {
            let c = &curves[k];
            let v = v_hat(&mat, &c.indenter, p, c.solution)?;
            ctx.tick();
            Ok(v)
        })
        .collect::<Result<_>>()?;

    let mut t = Table::new(
        name,
        "contact-zone speed alpha against indenter speed V",
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
                name: dyncontact::report::wedge::keys::COUPLING,
                meaning: "on: beta = -cot Theta; off: beta = 0",
            },
            Column {
                name: dyncontact::report::wedge::keys::SOLUTION,
                meaning: "solution variant",
            },
            Column {
                name: dyncontact::report::wedge::keys::P,
                meaning: "p = alpha/c1 (input of the case)",
            },
            Column {
                name: "alpha_over_c2",
                meaning: "alpha/c2",
            },
            Column {
                name: dyncontact::report::wedge::keys::V_OVER_C1_COT_THETA,
                meaning: "V/(c1 cot Theta)",
            },
            Column {
                name: "v_over_c2_cot_theta",
                meaning: "V/(c2 cot Theta)",
            },
        ],
    );
    t.param(material_line(&mat)?);
    for c in curves {
        t.param(format!(
            "curve '{}': {}",
            c.label,
            indenter_line(&c.indenter)
        ));
    }
    for (&(k, p), &v) in jobs.iter().zip(&vs) {
        let c = &curves[k];
        t.push(vec![
            c.indenter.theta_deg().value().into(),
            c.indenter.gamma().value().into(),
            c.indenter.coupling().name().into(),
            c.solution.name().into(),
            p.into(),
            (p / m).into(),
            v.into(),
            (v / m).into(),
        ])?;
    }

    // the x range: all the data, but at most 1.5 times the end of the `paper` curves (the
    // as-printed curves fold back near the Rayleigh speed and run off to large V there); the
    // lines are cut at the axis, the CSV keeps every point
    let data_max = vs.iter().fold(0.0_f64, |a, &v| a.max(v / m));
    let paper_max = jobs
        .iter()
        .zip(&vs)
        .filter(|((k, _), _)| curves[*k].solution == Solution::Paper)
        .fold(0.0_f64, |a, (_, &v)| a.max(v / m));
    let x_hi = if paper_max > 0.0 {
        (data_max * 1.04).min(paper_max * 1.5)
    } else {
        data_max * 1.04
    };
    let mut panel = Panel::new(
        title,
        Axis::lin("indenter speed V/(c₂ cot Θ)", 0.0, x_hi),
        Axis::lin("contact-zone speed α/c₂", 0.0, c_r_over_c2 * 1.08),
        Legend::LowerRight,
    );
    panel.series.push(
        Series::new(
            format!("Rayleigh speed c_R/c₂ = {c_r_over_c2:.4}"),
            vec![(0.0, c_r_over_c2), (x_hi, c_r_over_c2)],
            palette::GREY,
            Dash::Dashed,
        )
        .width(1),
    );
    for (k, c) in curves.iter().enumerate() {
        let pts: Vec<(f64, f64)> = jobs
            .iter()
            .zip(&vs)
            .filter(|((j, _), _)| *j == k)
            .map(|(&(_, p), &v)| (v / m, p / m))
            .collect();
        panel.series.push(Series::new(
            c.label.clone(),
            clip_right(&pts, x_hi),
            c.color,
            c.dash,
        ));
    }
    if data_max > x_hi {
        let names: Vec<&str> = curves
            .iter()
            .enumerate()
            .filter(|(k, _)| {
                jobs.iter()
                    .zip(&vs)
                    .any(|((j, _), &v)| j == k && v / m > x_hi)
            })
            .map(|(_, c)| c.solution.name())
            .fold(Vec::new(), |mut a, n| {
                if !a.contains(&n) {
                    a.push(n);
                }
                a
            });
        panel.notes.push(Note {
            at: (x_hi * 0.02, c_r_over_c2 * 1.075),
            text: format!(
                "near c_R the {} curves fold back and run off to V/(c₂ cot Θ) = {data_max:.2}, beyond this axis (cut here; the CSV has every point)",
                names.join(", ")
            ),
            color: palette::GREY,
            size: 15,
        });
    }
    let page = Page {
        name,
        width: 1100,
        height: 750,
        panels: vec![panel],
        stacked: false,
    };
    write(ctx, &t, &page)
}

/// Points of the genuine alpha-V curves in fig5 (each a spectral solve of about 0.1-0.3 s).
pub const GENUINE_POINTS: usize = 40;

/// Upper end of the genuine curves, as a fraction of m_R: the spectral solver's validated
/// range ends at p = 0.45 (0.91 m_R for the paper's material); beyond, toward the Rayleigh
/// speed, the contact pressure steepens and the default basis loses digits.
pub const GENUINE_TOP: f64 = 0.95;

/// The contact speeds of the genuine curves: n points evenly spaced in alpha on
/// (0, GENUINE_TOP m_R].
pub fn genuine_sweep(mat: &Material, n: usize) -> Result<Vec<f64>> {
    let top = GENUINE_TOP * mat.m_r()?;
    Ok((1..=n).map(|k| top * k as f64 / n as f64).collect())
}

/// The polyline `pts` cut at x = `hi`: the parts beyond are dropped, each crossing is
/// interpolated, and a NaN point breaks the line where it leaves the range.
pub fn clip_right(pts: &[(f64, f64)], hi: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for (k, &(x, y)) in pts.iter().enumerate() {
        if k > 0 {
            let (x0, y0) = pts[k - 1];
            if (x0 <= hi) != (x <= hi) {
                let yc = y0 + (y - y0) * (hi - x0) / (x - x0);
                if x0 <= hi {
                    out.push((hi, yc));
                    out.push((f64::NAN, f64::NAN));
                } else {
                    out.push((hi, yc));
                }
            }
        }
        if x <= hi {
            out.push((x, y));
        }
    }
    out
}

/// fig4: the classical alpha-V relation.
pub fn fig4(ctx: &Ctx) -> Result<Summary> {
    speed_figure(
        ctx,
        "fig4",
        "Fig. 4: α against V, classical problem (frictionless, uncoupled)",
        &[classical_curve()?],
        ctx.points(150, 12),
    )
}

/// fig5: the coupled frictional alpha-V relation with the classical curve.
pub fn fig5(ctx: &Ctx) -> Result<Summary> {
    speed_figure(
        ctx,
        "fig5",
        "Fig. 5: α against V, coupled and frictional (γ = 0.4)",
        &fig5_curves()?,
        ctx.points(100, 6),
    )
}

// ---------------------------------------------------------------------------------------------
// fig6 and fig7: contact stress

/// The contact speed p = alpha/c1 of figs 6 and 7.
pub const STRESS_P: f64 = 0.3;
/// The friction coefficients of figs 6 and 7.
pub const STRESS_GAMMAS: [f64; 2] = [0.001, 0.6];
/// The variant of figs 6 and 7.
pub const STRESS_SOLUTION: Solution = Solution::Paper;

/// Fractions r/(alpha t) of the contact panel: Chebyshev-like points of (0, 1], dense at the
/// apex and at the edge.
pub fn contact_fractions(n: usize) -> Vec<f64> {
    (1..=n)
        .map(|k| (1.0 - (std::f64::consts::PI * k as f64 / n as f64).cos()) / 2.0)
        .collect()
}

/// One stress point.
struct StressPoint {
    gamma_index: usize,
    genuine: bool,
    apex_panel: bool,
    frac: f64,
    sigma: f64,
    lead: Option<f64>,
}

fn regime_text(r: ApexRegime) -> &'static str {
    match r {
        ApexRegime::Finite => "finite",
        ApexRegime::Logarithmic => "logarithmic",
        ApexRegime::Power => "power singularity",
    }
}

fn stress_figure(ctx: &Ctx, name: &'static str, fig: u32, theta: f64) -> Result<Summary> {
    let mat = material();
    let p = STRESS_P;
    let cases: Vec<Case<f64>> = STRESS_GAMMAS
        .iter()
        .map(|&g| {
            Case::new(
                &mat,
                &Indenter::new(theta, g, Coupling::On)?,
                p,
                STRESS_SOLUTION,
            )
        })
        .collect::<std::result::Result<_, _>>()?;
    let apexes: Vec<wedge::Apex<f64>> = cases
        .iter()
        .map(|c| c.apex())
        .collect::<std::result::Result<_, _>>()?;
    // the genuine solution of each friction coefficient, and its apex exponent
    let gcases: Vec<Solved<f64>> = STRESS_GAMMAS
        .par_iter()
        .map(|&g| {
            let ind = Indenter::new(theta, g, Coupling::On)?;
            Ok(solve_at(&mat, &ind, Solution::Genuine, p)?)
        })
        .collect::<Result<_>>()?;
    let gapex: Vec<wedge::ApexLeading<f64>> = gcases
        .iter()
        .map(|g| g.apex_leading())
        .collect::<std::result::Result<_, _>>()?;
    let along = contact_fractions(ctx.points(200, 8));
    let near = logspace(1e-6, 1e-1, ctx.points(51, 6));
    let jobs: Vec<(usize, bool, bool, f64)> = (0..cases.len())
        .flat_map(|g| [false, true].map(|gen| (g, gen)))
        .flat_map(|(g, gen)| {
            along
                .iter()
                .map(move |&f| (g, gen, false, f))
                .chain(near.iter().map(move |&f| (g, gen, true, f)))
        })
        .collect();
    ctx.plan(jobs.len());
    let pts: Vec<StressPoint> = jobs
        .par_iter()
        .map(|&(g, genuine, apex_panel, frac)| {
            let x = p * frac;
            let solved: &dyn ContactSolution<f64> = if genuine { &gcases[g] } else { &cases[g] };
            let sigma = solved.stress_hat(&x)?.value;
            let lead = if apex_panel {
                Some(solved.apex_leading_term(&x)?)
            } else {
                None
            };
            ctx.tick();
            Ok(StressPoint {
                gamma_index: g,
                genuine,
                apex_panel,
                frac,
                sigma,
                lead,
            })
        })
        .collect::<Result<_>>()?;

    let mut t = Table::new(
        name,
        "contact stress sigma_theta along the contact zone (theta = 0) and near the apex",
        vec![
            Column {
                name: "panel",
                meaning: "contact (along the contact) or apex (log-log, near the apex)",
            },
            Column {
                name: dyncontact::report::wedge::keys::GAMMA,
                meaning: "friction coefficient",
            },
            Column {
                name: dyncontact::report::wedge::keys::SOLUTION,
                meaning: "solution variant (paper or genuine)",
            },
            Column {
                name: dyncontact::report::wedge::keys::REGIME,
                meaning: "the apex regime of this row's solution",
            },
            Column {
                name: "two_omega0",
                meaning: "2 Omega0, the apex exponent of the paper's solution",
            },
            Column {
                name: dyncontact::report::wedge::keys::APEX_EXPONENT,
                meaning: "lambda of sigma ~ r^(-lambda) at the apex for this row's solution (2 Omega0 for paper; the largest eigen-equation root for genuine)",
            },
            Column {
                name: dyncontact::report::wedge::keys::R_OVER_ALPHA_T,
                meaning: "r/(alpha t)",
            },
            Column {
                name: "r_over_c1_t",
                meaning: "x = r/(c1 t) = p r/(alpha t) (input of stress_hat)",
            },
            Column {
                name: dyncontact::report::wedge::keys::SIGMA_OVER_MU_COT_THETA,
                meaning: "sigma_theta/(mu cot Theta)",
            },
            Column {
                name: "leading_term_over_mu_cot_theta",
                meaning: "leading apex term of sigma_theta/(mu cot Theta) (apex panel only)",
            },
        ],
    );
    t.param(material_line(&mat)?);
    t.param(format!(
        "indenter: Theta = {theta} deg, gamma = {}, coupling on (beta = -cot Theta); p = alpha/c1 = {p}; solutions {} and genuine",
        STRESS_GAMMAS.map(fmt_num).join(" and "),
        STRESS_SOLUTION.name()
    ));
    for q in &pts {
        let a = &apexes[q.gamma_index];
        let two_o0 = 2.0 * cases[q.gamma_index].omega0();
        let (solution, regime, exponent) = if q.genuine {
            let ex = &gapex[q.gamma_index];
            (Solution::Genuine, ex.regime.name(), ex.exponent)
        } else {
            (STRESS_SOLUTION, a.regime.name(), two_o0)
        };
        t.push(vec![
            if q.apex_panel { "apex" } else { "contact" }.into(),
            STRESS_GAMMAS[q.gamma_index].into(),
            solution.name().into(),
            regime.into(),
            two_o0.into(),
            exponent.into(),
            q.frac.into(),
            (p * q.frac).into(),
            q.sigma.into(),
            q.lead.map(Cell::Num).unwrap_or(Cell::Empty),
        ])?;
    }

    let colors = [palette::BLUE, palette::RED];
    let cot = 1.0 / theta.to_radians().tan();
    let mut contact = Panel::new(
        format!("Fig. {fig}: contact stress, Θ = {theta}°, p = α/c₁ = {p}"),
        Axis::lin("r/(c₁t)", 0.0, p),
        Axis::fit(
            "σ_θ/(μ cot Θ)",
            pts.iter()
                .filter(|q| !q.apex_panel)
                .map(|q| q.sigma)
                .chain([0.0]),
            0.05,
        ),
        Legend::LowerRight,
    );
    let mut apex = Panel::new(
        "near the apex (log-log)",
        Axis::log("r/(αt)", 1e-6, 1e-1),
        Axis::fit_log(
            "|σ_θ|/(μ cot Θ)",
            pts.iter()
                .filter(|q| q.apex_panel)
                .flat_map(|q| [q.sigma.abs(), q.lead.unwrap_or(f64::NAN).abs()]),
        ),
        Legend::UpperRight,
    );
    for (g, gamma) in STRESS_GAMMAS.iter().enumerate() {
        let a = &apexes[g];
        let two_o0 = 2.0 * cases[g].omega0();
        let cmp = if *gamma < cot { "<" } else { ">" };
        let mine = |apex_panel: bool| {
            pts.iter()
                .filter(move |q| q.gamma_index == g && q.apex_panel == apex_panel && !q.genuine)
        };
        let genuine_pts = |apex_panel: bool| {
            pts.iter()
                .filter(move |q| q.gamma_index == g && q.apex_panel == apex_panel && q.genuine)
        };
        let lambda = gapex[g].exponent;
        contact.series.push(Series::new(
            format!("γ = {gamma}, genuine: apex stress ∝ (r/αt)^(−{lambda:.4})"),
            genuine_pts(false).map(|q| (p * q.frac, q.sigma)).collect(),
            colors[g],
            GENUINE.dash,
        ));
        apex.series.push(Series::new(
            format!("γ = {gamma}, genuine: |σ_θ| (λ = {lambda:.4})"),
            genuine_pts(true).map(|q| (q.frac, q.sigma.abs())).collect(),
            colors[g],
            GENUINE.dash,
        ));
        let along_pts: Vec<(f64, f64)> = mine(false).map(|q| (p * q.frac, q.sigma)).collect();
        contact.series.push(Series::new(
            format!(
                "γ = {gamma} {cmp} cot Θ = {cot:.4}: {} apex stress",
                regime_text(a.regime)
            ),
            along_pts,
            colors[g],
            Dash::Solid,
        ));
        apex.series.push(Series::new(
            format!(
                "γ = {gamma}: |σ_θ| ({}, 2Ω₀ = {two_o0:.4})",
                a.regime.name()
            ),
            mine(true).map(|q| (q.frac, q.sigma.abs())).collect(),
            colors[g],
            Dash::Solid,
        ));
        let lead_label = match a.regime {
            ApexRegime::Power => format!("γ = {gamma}: leading term ∝ (r/αt)^(−2Ω₀)"),
            ApexRegime::Logarithmic => format!("γ = {gamma}: leading term ∝ arccosh(αt/r)"),
            ApexRegime::Finite => {
                format!("γ = {gamma}: leading term σ_θ(0) = {:.1}", a.amplitude)
            }
        };
        apex.series.push(
            Series::new(
                lead_label,
                mine(true)
                    .filter_map(|q| q.lead.map(|l| (q.frac, l.abs())))
                    .collect(),
                colors[g],
                Dash::Dashed,
            )
            .width(1),
        );
    }
    apex.notes.push(Note {
        at: (2e-6, apex.y.lo * 1.6),
        text: format!(
            "solid: {}; dotted: genuine; thin dashed: the paper's leading apex term",
            STRESS_SOLUTION.name()
        ),
        color: palette::GREY,
        size: 15,
    });
    let page = Page {
        name,
        width: 1600,
        height: 700,
        panels: vec![contact, apex],
        stacked: false,
    };
    write(ctx, &t, &page)
}

/// The apex exponent lambda of the genuine stress (sigma ~ x^(-lambda)), 0 for a finite or
/// logarithmic apex.
pub fn genuine_exponent(ex: &genuine::ApexExponents) -> f64 {
    ex.leading().copied().unwrap_or(0.0)
}

/// fig6: contact stress, Theta = 86 deg.
pub fn fig6(ctx: &Ctx) -> Result<Summary> {
    stress_figure(ctx, "fig6", 6, 86.0)
}

/// fig7: contact stress, Theta = 89 deg.
pub fn fig7(ctx: &Ctx) -> Result<Summary> {
    stress_figure(ctx, "fig7", 7, 89.0)
}
