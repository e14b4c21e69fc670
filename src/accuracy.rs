//! Error against run time: every reported quantity of one case computed in f64 and at
//! increasing MPFR precision, compared with a 400-bit reference.
//!
//! The case is the paper's Theta = 89 deg, gamma = 0.6, coupled, p = 0.3 (paper variant).
//! Quantities: m_R, Omega0, S0, V/(c1 cot Theta), P/(alpha t mu cot Theta) and the contact
//! stress at r/(alpha t) = 0.05, 0.5, 0.95. Run times are wall-clock for one evaluation from
//! scratch (quadrature rules already cached, as in any run after the first case).

use std::time::Instant;

use complexfn::quadrature::CachedRules;
use rayon::prelude::*;
use rug::Float;
use wedge::{Case, Coupling, Indenter, Material, Result, Solution};

/// Precision of the reference values.
pub const REFERENCE_BITS: u32 = 400;
/// MPFR precisions of the report (bits).
pub const LEVELS_BITS: [u32; 6] = [64, 100, 133, 200, 266, 333];
/// Fractions r/(alpha t) at which the stress is reported.
pub const STRESS_AT: [f64; 3] = [0.05, 0.5, 0.95];

/// Names of the quantities, in the order of [`Row::errors`].
pub const QUANTITIES: [&str; 8] = [
    "m_r",
    "omega0",
    "s0",
    "v_over_c1_cot_theta",
    "force",
    "sigma(0.05)",
    "sigma(0.5)",
    "sigma(0.95)",
];

/// One line of the report.
#[derive(Clone, Debug)]
pub struct Row {
    /// "f64" or "`<bits>` bits".
    pub precision: String,
    /// Mantissa bits.
    pub bits: u32,
    /// Relative error of each quantity against the reference (same order as [`QUANTITIES`]).
    pub errors: Vec<f64>,
    /// The library's own error estimate for V (relative).
    pub estimate: f64,
    /// Seconds for the full solve (case build + matching).
    pub solve_seconds: f64,
    /// Seconds per contact-stress evaluation.
    pub stress_seconds: f64,
    /// Nodes of the inner Gauss-Legendre rule.
    pub inner_nodes: usize,
    /// Integrand evaluations of the matching integrals.
    pub outer_evals: usize,
}

fn case<T: CachedRules>(p: T) -> Result<Case<T>> {
    Case::new(
        &Material::paper(),
        &Indenter::new(89.0, 0.6, Coupling::On)?,
        p,
        Solution::Paper,
    )
}

fn values<T: CachedRules>(like: &T) -> Result<(Vec<Float>, f64, f64, f64, usize, usize)> {
    let p = wedge::Param::from_f64(0.3).to_real(like);
    let t0 = Instant::now();
    let c = case(p.clone())?;
    let v = c.v_hat()?;
    let solve = t0.elapsed().as_secs_f64();
    let mut out: Vec<T> = vec![c.m_r().clone(), c.omega0(), c.s0(), v, c.force_hat()?];
    let t1 = Instant::now();
    for f in STRESS_AT {
        out.push(c.stress_hat(&(p.clone() * like.lit(f)))?.value);
    }
    let stress = t1.elapsed().as_secs_f64() / STRESS_AT.len() as f64;
    let big: Vec<Float> = out
        .iter()
        .map(|x| {
            Float::with_val(
                REFERENCE_BITS,
                Float::parse(x.to_decimal(140)).expect("decimal"),
            )
        })
        .collect();
    let m = c.matching()?;
    Ok((big, m.rel_error, solve, stress, c.inner().len(), m.evals))
}

fn rel(a: &Float, b: &Float) -> f64 {
    let d = Float::with_val(REFERENCE_BITS, a - b).abs();
    if *b == 0 {
        d.to_f64()
    } else {
        (d / b.clone().abs()).to_f64()
    }
}

/// Compute the report (about 10 s on two cores; `quick`: f64, 64 and 100 bits only, against
/// 200 bits, for tests).
pub fn report(quick: bool) -> Result<Vec<Row>> {
    let ref_bits = if quick { 200 } else { REFERENCE_BITS };
    let reference = values(&Float::with_val(ref_bits, 0))?.0;
    let mut rows = Vec::new();
    let mut push = |precision: String, bits: u32, r: (Vec<Float>, f64, f64, f64, usize, usize)| {
        let errors = r.0.iter().zip(&reference).map(|(a, b)| rel(a, b)).collect();
        rows.push(Row {
            precision,
            bits,
            errors,
            estimate: r.1,
            solve_seconds: r.2,
            stress_seconds: r.3,
            inner_nodes: r.4,
            outer_evals: r.5,
        });
    };
    // warm the caches (rules) once, then time
    values(&0.0_f64)?;
    push("f64".into(), 53, values(&0.0_f64)?);
    let levels: &[u32] = if quick {
        &LEVELS_BITS[..2]
    } else {
        &LEVELS_BITS
    };
    for &bits in levels {
        let like = Float::with_val(bits, 0);
        values(&like)?;
        push(format!("{bits} bits"), bits, values(&like)?);
    }
    Ok(rows)
}

/// The report as a Markdown table.
pub fn markdown(rows: &[Row]) -> String {
    let mut s = String::from("| precision | ");
    s += &QUANTITIES.join(" | ");
    s += " | estimate (V) | solve | stress/point | inner nodes | outer evals |\n|---|";
    s += &"---|".repeat(QUANTITIES.len() + 5);
    s.push('\n');
    for r in rows {
        s += &format!("| {} | ", r.precision);
        s += &r
            .errors
            .iter()
            .map(|e| format!("{e:.1e}"))
            .collect::<Vec<_>>()
            .join(" | ");
        s += &format!(
            " | {:.1e} | {} | {} | {} | {} |\n",
            r.estimate,
            seconds(r.solve_seconds),
            seconds(r.stress_seconds),
            r.inner_nodes,
            r.outer_evals
        );
    }
    s
}

fn seconds(t: f64) -> String {
    if t < 1e-3 {
        format!("{:.0} us", t * 1e6)
    } else if t < 1.0 {
        format!("{:.1} ms", t * 1e3)
    } else {
        format!("{t:.2} s")
    }
}

/// The report as CSV with '#' header lines (`ref_bits`: precision of the reference).
pub fn csv(rows: &[Row], ref_bits: u32) -> String {
    let mut s = format!(
        "# dyncontact {} figures: error_vs_time\n# error against run time; case Theta = 89 deg, gamma = 0.6, coupled, p = 0.3, solution = paper; material c1 = 1870.83 m/s, c2 = 1000 m/s\n# precision: per row (f64, or MPFR bits); errors: relative, against a {ref_bits}-bit reference; times in seconds (one evaluation, rules cached)\n",
        crate::VERSION
    );
    s += "precision,bits,";
    s += &QUANTITIES.map(|q| format!("err_{q}")).join(",");
    s += ",estimate_v,solve_seconds,stress_seconds,inner_nodes,outer_evals\n";
    for r in rows {
        s += &format!("{},{},", r.precision, r.bits);
        s += &r
            .errors
            .iter()
            .map(|e| format!("{e:e}"))
            .collect::<Vec<_>>()
            .join(",");
        s += &format!(
            ",{:e},{:e},{:e},{},{}\n",
            r.estimate, r.solve_seconds, r.stress_seconds, r.inner_nodes, r.outer_evals
        );
    }
    s
}

/// The accuracy of an f64 alpha-V curve against a high-precision reference.
#[derive(Clone, Debug)]
pub struct CurveCheck {
    /// Number of points.
    pub points: usize,
    /// Largest relative error of V/(c1 cot Theta) over the curve.
    pub max_error: f64,
    /// Largest ratio of actual to stated error (<= 1 when the estimates hold).
    pub worst_ratio: f64,
    /// Largest stated relative error.
    pub max_stated: f64,
    /// Seconds for the whole f64 curve on one thread.
    pub seconds: f64,
}

/// The contact speeds p = alpha/c1 of the benchmark curve: `n` points evenly spread over
/// (0, 0.49), midpoints of n equal cells (the last one at 0.98 m_R for the paper's material).
pub fn curve_speeds(n: usize) -> Vec<f64> {
    (0..n).map(|k| 0.49 * (k as f64 + 0.5) / n as f64).collect()
}

/// The coupled frictional alpha-V curve of the benchmarks (Theta = 89 deg, gamma = 0.6,
/// `paper`) in f64 on one thread, timed, and each point against `ref_bits` bits (computed in
/// parallel).
pub fn curve_check(n: usize, ref_bits: u32) -> Result<CurveCheck> {
    let mat = Material::paper();
    let ind = Indenter::new(89.0, 0.6, Coupling::On)?;
    let ps = curve_speeds(n);
    let t0 = Instant::now();
    let f64s: Vec<(f64, f64)> = ps
        .iter()
        .map(|&p| {
            let c = Case::new(&mat, &ind, p, Solution::Paper)?;
            let m = c.matching()?;
            Ok((m.v_hat, m.rel_error))
        })
        .collect::<Result<_>>()?;
    let seconds = t0.elapsed().as_secs_f64();
    let refs: Vec<Float> = ps
        .par_iter()
        .map(|&p| {
            let like = Float::with_val(ref_bits, 0);
            let pb = wedge::Param::from_f64(p).to_real(&like);
            Case::new(&mat, &ind, pb, Solution::Paper)?.v_hat()
        })
        .collect::<Result<_>>()?;
    let mut out = CurveCheck {
        points: n,
        max_error: 0.0,
        worst_ratio: 0.0,
        max_stated: 0.0,
        seconds,
    };
    for ((v, stated), r) in f64s.iter().zip(&refs) {
        let err = rel(&Float::with_val(ref_bits, *v), r);
        out.max_error = out.max_error.max(err);
        out.max_stated = out.max_stated.max(*stated);
        out.worst_ratio = out.worst_ratio.max(err / stated);
    }
    Ok(out)
}
