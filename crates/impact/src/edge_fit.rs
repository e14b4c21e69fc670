//! The local exponent of the contact pressure at a moving edge, fitted to a march's pressures
//! (`docs/impact.md`, section 8): the check of `lamb::edge`'s exponents against the transient
//! solver.
//!
//! Near an edge moving at a steady speed the pressure is p = d^lambda (c_0 + c_1 d + ...)
//! (d the distance from the edge into the contact): the local solutions of `docs/edge.md`
//! carry a regular series behind the leading power, and the two local exponents of one speed
//! differ by one, so the family d^lambda (polynomial) is that of the other exponent as well. A
//! plain log-log line through the pressures would take the series' corrections for a change
//! of slope (of order d/b over the fitted range); the fit therefore takes lambda and a
//! polynomial of degree `degree` together, by least squares on log-spaced bins (each bin one
//! weight: a fit on a log scale), with lambda searched in a bracket narrower than one so that
//! the two exponents of one speed are not confused.

use lamb::edge::{EdgeBehaviour, SpeedRange};
use lamb::HalfPlane;

use crate::error::{invalid, ImpactError, Result};
use crate::march::EdgeLaw;
use crate::run::Run;
use crate::solved::SolvedImpact;
use complexfn::linalg::Lu;

/// The fit's upper end in s = d/b for a driven wedge (its pressure has a logarithmic peak at
/// the apex, s = 1).
const WEDGE_FIT_END: f64 = 0.5;
/// The cells next to the edge left out of the fit (at least; a fast edge leaves out the cells
/// it crosses in two steps).
const EDGE_CELLS_LEFT_OUT: f64 = 4.0;
/// The share of the steps, at the end of the run, whose pressures are fitted.
const LATE_SHARE: f64 = 0.3;

/// The predicted local behaviour at a self-similar run's edge and the exponent fitted to the
/// run's pressures.
#[derive(Clone, Debug)]
pub struct EdgeExponentCheck {
    /// `lamb::edge`'s local behaviour for the edge's measured speed and the run's law.
    pub behaviour: EdgeBehaviour,
    /// The fit.
    pub fit: ExponentFit,
}

/// The fitted local law p = s^lambda (c_0 + c_1 s + ... ), s = d/b.
#[derive(Clone, Debug)]
pub struct ExponentFit {
    /// The fitted exponent.
    pub lambda: f64,
    /// c_0, c_1, ... (units of the samples' pressures).
    pub coefficients: Vec<f64>,
    /// The root-mean-square of the weighted residuals (relative to the bins' pressures).
    pub rms: f64,
    /// The bins that held samples.
    pub bins: usize,
    /// The smallest and the largest mean s of those bins: the range actually fitted.
    pub s_range: (f64, f64),
}

/// The edge exponent of a self-similar solution (a wedge driven at constant speed, whose
/// pressure is a function of x/t) fitted to its finest grid's pressures, against the
/// prediction of `lamb::edge` for the edge's speed over the last 30 percent of the run
/// (`docs/impact.md`, section 8). The fit takes two decades of s = d/b up to s = 0.5, or up
/// to 80 percent of the way to the nearest wave front from the first contact (s = 1 - c/D,
/// c the fastest of c1, c2, c_R below D) when that is nearer, except the Rayleigh point behind
/// a free edge between c_R and c2, where the solution is smooth (its edge term is the one that
/// keeps the face free of a kink there, `docs/edge.md`, section 5); the cells next to the edge are
/// left out (at least four, and the cells the edge crosses in two steps). Errors: a run too
/// short or too coarse for the fit, an edge speed at a range boundary, a failed fit.
pub fn fit_self_similar_edge(sol: &SolvedImpact) -> Result<EdgeExponentCheck> {
    let run = &sol.runs[0];
    let too_short = || ImpactError::Grid {
        name: "end",
        reason: "too few steps for the edge exponent fit".into(),
    };
    let last = run.steps.last().ok_or_else(too_short)?;
    let t_from = (1.0 - LATE_SHARE) * last.t;
    let first = run
        .steps
        .iter()
        .find(|s| s.t >= t_from)
        .filter(|s| s.t < last.t)
        .ok_or_else(too_short)?;
    let speed = (last.b - first.b) / (last.t - first.t);
    let behaviour = HalfPlane::new(sol.m)?.edge_behaviour(speed, sol.case.law)?;
    let front = match behaviour.range {
        SpeedRange::SubRayleigh => None,
        SpeedRange::RayleighShear if sol.case.law == EdgeLaw::Signorini => None,
        SpeedRange::RayleighShear => Some(sol.s_r),
        SpeedRange::Transonic => Some(sol.m),
        SpeedRange::Supersonic => Some(1.0),
    };
    let hi = front.map_or(WEDGE_FIT_END, |c| {
        WEDGE_FIT_END.min(0.8 * (1.0 - c / speed))
    });
    let min_cells = EDGE_CELLS_LEFT_OUT.max(2.0 * speed * sol.case.kappa);
    let samples = run.edge_samples(t_from, min_cells);
    let lambda = behaviour.selected;
    let fit = fit_edge_exponent(
        &samples,
        (hi / 100.0, hi),
        (lambda - 0.45, lambda + 0.45),
        3,
        40,
    )?;
    Ok(EdgeExponentCheck { behaviour, fit })
}

impl Run {
    /// The pressures of the steps at times t >= `from` as samples (s, p) in the edge's own
    /// scale, s = (b - x_j)/b (b the step's contact half-width, x_j the cell centre), for the
    /// cells at least `min_cells` cells behind the edge: for a self-similar case (a driven
    /// wedge, whose pressure is a function of x/t) every step adds points of the same curve.
    pub fn edge_samples(&self, from: f64, min_cells: f64) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        for st in self.steps.iter().filter(|s| s.t >= from && s.b > 0.0) {
            for (j, &p) in st.pressure.iter().enumerate() {
                let d = st.b - j as f64 * self.dx;
                if d >= min_cells * self.dx {
                    out.push((d / st.b, p));
                }
            }
        }
        out
    }
}

/// The exponent lambda in `bracket` and the coefficients of degree `degree` that fit
/// p = s^lambda sum_k c_k s^k to the samples (s, p) with s in `range`, on `bins` log-spaced
/// bins (bin means; weights 1/max(|p|, max|p|/20), so the residual is relative where the
/// pressure is not near a zero). Errors: a range or bracket that is empty or not finite,
/// fewer bins with samples than degree + 3, or a minimum on the bracket's ends (the data
/// prefer an exponent outside it).
pub fn fit_edge_exponent(
    samples: &[(f64, f64)],
    range: (f64, f64),
    bracket: (f64, f64),
    degree: usize,
    bins: usize,
) -> Result<ExponentFit> {
    if !(range.0 > 0.0 && range.1 > range.0 && range.1.is_finite()) {
        return Err(invalid(
            "fit range s",
            format!("({}, {})", range.0, range.1),
            "0 < s_lo < s_hi",
        ));
    }
    if !(bracket.1 > bracket.0 && bracket.1 - bracket.0 < 1.0 && bracket.0 > -1.0) {
        return Err(invalid(
            "exponent bracket",
            format!("({}, {})", bracket.0, bracket.1),
            "an interval in (-1, inf) shorter than 1",
        ));
    }
    let ratio = (range.1 / range.0).ln();
    let mut acc = vec![(0.0, 0.0, 0usize); bins];
    for &(s, p) in samples {
        if s >= range.0 && s < range.1 && p.is_finite() {
            let k = (((s / range.0).ln() / ratio) * bins as f64) as usize;
            let a = &mut acc[k.min(bins - 1)];
            *a = (a.0 + s, a.1 + p, a.2 + 1);
        }
    }
    let pts: Vec<(f64, f64)> = acc
        .iter()
        .filter(|a| a.2 > 0)
        .map(|a| (a.0 / a.2 as f64, a.1 / a.2 as f64))
        .collect();
    if pts.len() < degree + 3 {
        return Err(ImpactError::Grid {
            name: "dx",
            reason: format!(
                "{} bins with pressures in s = ({}, {}), at least {} needed for the exponent fit",
                pts.len(),
                range.0,
                range.1,
                degree + 3
            ),
        });
    }
    let pmax = pts.iter().map(|p| p.1.abs()).fold(0.0, f64::max);
    let weights: Vec<f64> = pts
        .iter()
        .map(|p| 1.0 / p.1.abs().max(0.05 * pmax))
        .collect();
    // weighted linear least squares for a given lambda (normal equations on unit columns)
    let solve = |lambda: f64| -> Option<(Vec<f64>, f64)> {
        let nc = degree + 1;
        let cols: Vec<Vec<f64>> = (0..nc)
            .map(|k| {
                pts.iter()
                    .zip(&weights)
                    .map(|((s, _), w)| w * s.powf(lambda + k as f64))
                    .collect()
            })
            .collect();
        let norms: Vec<f64> = cols
            .iter()
            .map(|c| c.iter().map(|v| v * v).sum::<f64>().sqrt())
            .collect();
        let rhs: Vec<f64> = pts.iter().zip(&weights).map(|((_, p), w)| w * p).collect();
        let mut a = vec![0.0; nc * nc];
        let mut r = vec![0.0; nc];
        for i in 0..nc {
            for j in 0..nc {
                a[i * nc + j] = cols[i]
                    .iter()
                    .zip(&cols[j])
                    .map(|(u, v)| u * v)
                    .sum::<f64>()
                    / (norms[i] * norms[j]);
            }
            r[i] = cols[i].iter().zip(&rhs).map(|(u, v)| u * v).sum::<f64>() / norms[i];
        }
        let y = Lu::new(a, nc)?.solve(&r)?;
        let c: Vec<f64> = y.iter().zip(&norms).map(|(v, n)| v / n).collect();
        let res = (0..pts.len())
            .map(|i| {
                let fit: f64 = (0..nc).map(|k| c[k] * cols[k][i]).sum();
                (fit - rhs[i]).powi(2)
            })
            .sum::<f64>();
        Some((c, res))
    };
    let cost = |lambda: f64| solve(lambda).map(|v| v.1).unwrap_or(f64::INFINITY);
    // golden-section search
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = bracket;
    let (mut x1, mut x2) = (b - g * (b - a), a + g * (b - a));
    let (mut f1, mut f2) = (cost(x1), cost(x2));
    while b - a > 1e-9 {
        if f1 < f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = cost(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = cost(x2);
        }
    }
    let lambda = 0.5 * (a + b);
    let edge = 1e-6 * (bracket.1 - bracket.0);
    if lambda - bracket.0 < edge || bracket.1 - lambda < edge {
        return Err(ImpactError::Grid {
            name: "exponent bracket",
            reason: format!(
                "the fitted exponent sits on the bracket's end ({lambda:.6}): the pressures \
                 do not follow s^lambda times a polynomial of degree {degree} there"
            ),
        });
    }
    let (coefficients, res) = solve(lambda).ok_or_else(|| ImpactError::Grid {
        name: "fit range s",
        reason: "singular least-squares system of the exponent fit".into(),
    })?;
    Ok(ExponentFit {
        lambda,
        coefficients,
        rms: (res / pts.len() as f64).sqrt(),
        bins: pts.len(),
        s_range: (pts[0].0, pts[pts.len() - 1].0),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Samples of an exact s^lambda (c_0 + c_1 s + c_2 s^2) with a sign change give back
    /// lambda to the search's tolerance, and a bracket that excludes it is refused.
    #[test]
    fn fit_recovers_an_exact_local_law() {
        for lambda in [-0.5, -0.15, 0.0, 0.5] {
            let samples: Vec<(f64, f64)> = (0..4000)
                .map(|i| {
                    let s = 1e-3 * (1000f64).powf(i as f64 / 3999.0);
                    (s, s.powf(lambda) * (-0.04 + 0.3 * s + 0.1 * s * s))
                })
                .collect();
            let fit = fit_edge_exponent(
                &samples,
                (0.005, 0.75),
                (lambda - 0.45, lambda + 0.45),
                3,
                40,
            )
            .unwrap();
            // the bins' means of s^lambda differ from s^lambda at the bins' mean s by the
            // bin width's curvature: far below 1e-3 on 40 bins
            assert!((fit.lambda - lambda).abs() < 1e-3, "{lambda}: {fit:?}");
            let e = fit_edge_exponent(&samples, (0.005, 0.75), (lambda + 0.2, lambda + 0.6), 3, 40);
            assert!(e.is_err(), "{lambda}: {e:?}");
        }
    }
}
