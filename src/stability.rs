//! The stiff and extreme grid: sharp and blunt wedges (Theta from 1 to 90 - 1e-6 degrees),
//! friction from 0 through cot Theta to 10 and 1e6, p near 0 and near the Rayleigh speed,
//! Poisson's ratio near its limits; both solution variants. Each case is reported in f64 as
//! the command line reports it (every quantity of [`crate::SolveReport`], the admissibility
//! checks, the contact stress at two points), and compared, quantity by quantity, with the
//! same case solved at a high precision: the actual error of every number must stay within
//! the estimate the report states for it.

use complexfn::Precision;
use rug::Float;
use wedge::{Coupling, Indenter, Material, Param, Solution};

use crate::{build, solve, CaseInput, Quantity, Speed, StressReport};

/// Bits of the reference solve of the paper's construction.
pub const PAPER_REFERENCE_BITS: u32 = 256;
/// Digits of the reference solve of the genuine solution (its cost grows fast with the
/// digits: about 6 s at 30).
pub const GENUINE_REFERENCE_DIGITS: u32 = 30;
/// Fractions r/(alpha t) at which the contact stress is compared.
pub const STRESS_FRACTIONS: [&str; 2] = ["0.01", "0.5"];

/// One point of the grid.
#[derive(Clone, Debug)]
pub struct GridPoint {
    /// Poisson's ratio.
    pub nu: f64,
    /// Half-angle, degrees.
    pub theta: f64,
    /// Friction coefficient.
    pub gamma: f64,
    /// Label of the contact speed.
    pub p_label: &'static str,
    /// p itself when negative (as -p, capped at 0.9 m_R), else the gap 1 - p/m_R.
    pub p_spec: f64,
    /// The solution variant.
    pub solution: Solution,
}

impl GridPoint {
    /// p = alpha/c1 for this point, given m_R.
    pub fn p(&self, m_r: f64) -> f64 {
        if self.p_spec < 0.0 {
            (-self.p_spec).min(0.9 * m_r)
        } else {
            m_r * (1.0 - self.p_spec)
        }
    }
    /// A one-line description.
    pub fn label(&self) -> String {
        format!(
            "{} nu {} theta {} gamma {:e} p {}",
            self.solution.name(),
            self.nu,
            self.theta,
            self.gamma,
            self.p_label
        )
    }
    /// The corner of the parameter space the point belongs to (for the summary).
    pub fn corner(&self) -> &'static str {
        if self.theta <= 10.0 {
            "sharp wedge (Theta <= 10 deg)"
        } else if self.gamma >= 10.0 {
            "strong friction (gamma >= 10)"
        } else if self.p_spec >= 0.0 {
            "near the Rayleigh speed"
        } else if self.p_spec > -1e-3 {
            "slow contact (p <= 1e-4)"
        } else if self.theta >= 89.0 {
            "blunt wedge (Theta >= 89 deg)"
        } else if !(0.0..=0.49).contains(&self.nu) {
            "extreme Poisson ratio"
        } else {
            "ordinary"
        }
    }
}

const SPEEDS: [(&str, f64); 5] = [
    ("1e-8", -1e-8),
    ("1e-4", -1e-4),
    ("0.3", -0.3),
    ("mR(1-1e-6)", 1e-6),
    ("mR(1-1e-12)", 1e-12),
];

/// The grid: the paper's construction over 5 Poisson ratios x 8 angles x 8 friction
/// coefficients x 5 contact speeds (coupled), then the genuine solution over 3 x 5 x 3 x 3.
pub fn grid() -> Vec<GridPoint> {
    // every combination of the given Poisson ratios, angles, friction coefficients (as a
    // function of cot Theta) and speeds, for one solution variant
    fn product(
        v: &mut Vec<GridPoint>,
        solution: Solution,
        nus: &[f64],
        thetas: &[f64],
        gammas: impl Fn(f64) -> Vec<f64>,
        speeds: &[(&'static str, f64)],
    ) {
        for &nu in nus {
            for &theta in thetas {
                let cot = Indenter::new(theta, 0.0, Coupling::On)
                    .expect("angle")
                    .cot_theta(&0.0_f64);
                for gamma in gammas(cot) {
                    for &(p_label, p_spec) in speeds {
                        v.push(GridPoint {
                            nu,
                            theta,
                            gamma,
                            p_label,
                            p_spec,
                            solution,
                        });
                    }
                }
            }
        }
    }
    let mut v = Vec::new();
    product(
        &mut v,
        Solution::Paper,
        &[-0.9, 0.0, 0.3, 0.49, 0.4999],
        &[1.0, 5.0, 10.0, 30.0, 60.0, 86.0, 89.0, 90.0 - 1e-6],
        |cot| {
            vec![
                0.0,
                1e-12,
                cot * (1.0 - 1e-12),
                cot,
                cot * (1.0 + 1e-12),
                0.6,
                10.0,
                1e6,
            ]
        },
        &SPEEDS,
    );
    product(
        &mut v,
        Solution::Genuine,
        &[0.0, 0.3, 0.49],
        &[1.0, 10.0, 60.0, 86.0, 89.0],
        |_| vec![0.3, 1.0, 10.0],
        &SPEEDS[1..4],
    );
    v
}

/// The outcome of one grid point.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// Refused with a typed error (the message).
    Refused(String),
    /// Reported in f64.
    Solved {
        /// V's stated relative error (the report's `error_estimate`).
        stated: f64,
        /// The quantities declared unavailable, with the reasons.
        unavailable: Vec<(String, String)>,
        /// When compared: the largest ratio actual/stated error over the quantities, with
        /// the quantity's key.
        worst: Option<(f64, String)>,
        /// Quantities whose actual error exceeds the stated one: (key, actual, stated).
        optimistic: Vec<(String, f64, f64)>,
    },
}

/// Every number of the report and of the stress at [`STRESS_FRACTIONS`], with keys.
fn numbers(r: &crate::SolveReport, s: &StressReport) -> Vec<(String, Quantity)> {
    let mut out: Vec<(String, Quantity)> = r
        .quantities()
        .into_iter()
        .map(|(k, q)| (k.to_string(), q.clone()))
        .collect();
    for (f, q) in STRESS_FRACTIONS.iter().zip(&s.sigma_over_mu_cot_theta) {
        out.push((format!("sigma at r/(alpha t) = {f}"), q.clone()));
    }
    out
}

/// The case of a grid point: its input at `digits` and its contact speed.
fn case_of(pt: &GridPoint, digits: Option<u32>) -> Result<(CaseInput, Speed), String> {
    let material = Material::from_poisson(pt.nu, 1000.0).map_err(|e| e.to_string())?;
    let indenter = Indenter::new(pt.theta, pt.gamma, Coupling::On).map_err(|e| e.to_string())?;
    let m_r = material.m_r().map_err(|e| e.to_string())?;
    let alpha = pt.p(m_r) * material.c1().value();
    let input = CaseInput {
        material,
        indenter,
        solution: pt.solution,
        digits,
    };
    Ok((input, Speed::Alpha(alpha.into())))
}

/// Report one grid point in f64 (every quantity, the admissibility checks, the stress) and,
/// when `compare`, check every number against the reference precision. `Err` is a defect: a
/// reference that fails or is not accurate enough to judge the f64 numbers.
pub fn check(pt: &GridPoint, compare: bool) -> Result<Outcome, String> {
    let (input, speed) = case_of(pt, None)?;
    let at: Vec<Param> = STRESS_FRACTIONS
        .iter()
        .map(|f| Param::parse("at", f).expect("fraction"))
        .collect();
    let tested = solve(&input, &speed, &crate::Selection::all())
        .and_then(|r| Ok((crate::stress(&input, &speed, &at)?, r)));
    let (stress, report) = match tested {
        Ok(x) => x,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let unavailable = report
        .unavailable()
        .into_iter()
        .map(|(k, r)| (k.to_string(), r.to_string()))
        .collect();
    let mine = numbers(&report, &stress);
    let mut outcome = Outcome::Solved {
        stated: report.error_estimate,
        unavailable,
        worst: None,
        optimistic: Vec::new(),
    };
    if !compare {
        return Ok(outcome);
    }
    let bits = match pt.solution {
        Solution::Genuine => Precision::from_digits(GENUINE_REFERENCE_DIGITS, crate::GUARD_BITS)
            .map_err(|e| format!("{}: no reference precision: {e}", pt.label()))?
            .bits(),
        _ => PAPER_REFERENCE_BITS,
    };
    let like = Float::with_val(bits, 0);
    let digits = (bits as f64 * std::f64::consts::LOG10_2) as usize;
    let reference = build(&input, &speed, &like)
        .and_then(|s| {
            let r = crate::SolveReport::of(&s, &input, digits)?;
            Ok((StressReport::of(&s, &at, digits)?, r))
        })
        .map_err(|e| format!("{}: f64 solved but {bits} bits failed: {e}", pt.label()))?;
    let mut theirs = numbers(&reference.1, &reference.0);
    if reference.1.regime != report.regime {
        // gamma within a few ulps of cot Theta: the regime boundary is taken as exact at the
        // working precision, and the apex amplitude is then a different quantity (the
        // logarithm's coefficient) from the reference's (a power's)
        // (and S0, identically zero on the boundary, is the reference's small nonzero one)
        theirs.retain(|(k, _)| k != "apex_amplitude_over_mu_cot_theta" && k != "s0");
    }
    let (mut worst, mut optimistic) = ((0.0_f64, String::new()), Vec::new());
    for (k, q) in &mine {
        let Some((_, y)) = theirs.iter().find(|(kk, _)| kk == k) else {
            continue;
        };
        let stated = q.error();
        // the reference must be good enough to judge the f64 number
        if y.error() > 1e-3 * stated.max(1e-300) && y.error() > 1e-25 * y.value().abs() {
            return Err(format!(
                "{}: {k}: reference estimate {:e} does not resolve the stated {stated:e}",
                pt.label(),
                y.error()
            ));
        }
        let actual = (q.to_float(bits + 64) - y.to_float(bits + 64))
            .abs()
            .to_f64();
        if actual > stated {
            optimistic.push((k.clone(), actual, stated));
        }
        let ratio = if stated > 0.0 {
            actual / stated
        } else if actual > 0.0 {
            f64::INFINITY
        } else {
            0.0
        };
        if ratio > worst.0 || worst.1.is_empty() {
            worst = (ratio, k.clone());
        }
    }
    if let Outcome::Solved {
        worst: w,
        optimistic: o,
        ..
    } = &mut outcome
    {
        *w = Some(worst);
        *o = optimistic;
    }
    Ok(outcome)
}
