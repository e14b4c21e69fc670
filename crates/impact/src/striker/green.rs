//! The free elastic cylinder's own influence function: the inward normal surface
//! displacement of a free disk under a uniform pressure switched on at t = 0 over an arc,
//! averaged over arcs of the same width (`docs/strikers.md`, section 7).
//!
//! Units of [`Disk`]: R = 1, mu_s = 1, rho_s = 1 (c2s = 1), the pressure p0 = 1. With
//! theta0 the arc's half-width, the pressure's harmonics are p_0 = theta0/pi and
//! p_n = 2 sin(n theta0)/(n pi), the receiver's mean multiplies harmonic n by
//! sinc(n theta0), so the response at the arc centred at theta_j is, in the Laplace domain,
//!
//! ```text
//! G(theta_j, s) = sum_n w_n(theta_j) W_n(s)/s,   w_n = p_n sinc(n theta0) cos(n theta_j).
//! ```
//!
//! The series is split into three parts, each in the form where it converges:
//!
//! - the periodised half-plane: F(n, s), the half-plane's transfer function at the
//!   wavenumber n (same material), summed over all n by Poisson's formula, is the
//!   half-plane's strip-on-strip mean response summed over the images theta_j + 2 pi m, in
//!   closed form in the time domain from the Lamb crate ([`HalfPlane::cell_mean_primitive_zz`]);
//! - the rigid translation t^2/2 w_1 (the pole 1/s^2 of W_1) and the half-plane's uniform
//!   mode w_0 t/c1s (its transfer 1/(c1s s) at n = 0), in closed form;
//! - the remainder sum_n w_n [W_n - F(n)]/s (W_0 itself at n = 0, W_1 without its pole),
//!   whose terms fall like n^-2 faster than the series' and whose time function starts
//!   like t^2 (the curvature's correction): inverted by Fourier series along
//!   Re s = sigma (Durbin), with its truncations estimated by halving.

use std::f64::consts::PI;

use lamb::{Estimate, HalfPlane};
use rayon::prelude::*;
use rustfft::num_complex::Complex64;

use super::disk::{ratio_terms, transfer, Disk};
use super::sinc;
use crate::error::{invalid, ImpactError, Result};

/// The admissible arc widths 2 theta0 R (units R).
pub const ARC_RANGE: (f64, f64) = (2e-3, PI);

/// The latest time served, c2s t/R.
pub const LATEST_TIME: f64 = 100.0;

/// The most harmonic evaluations (frequencies times harmonics) one response may take.
pub const WORK_LIMIT: f64 = 2e9;

/// Highest frequency of the inversion, times theta0: the remainder's time structure is that
/// of fronts smeared over an arc, of duration theta0/c.
const OMEGA_THETA: f64 = 24.0;

/// The lowest highest frequency (the structure of the disk's own reflections).
const OMEGA_MIN: f64 = 2000.0;

/// The fewest frequencies of the inversion (for early last times, whose structure is at the
/// scale of the time itself).
const FREQUENCIES_MIN: f64 = 256.0;

/// Harmonics kept per unit of the highest frequency.
const HARMONICS_PER_OMEGA: f64 = 0.8;

/// The half-period T of the inversion over the last time: the errors of the series are
/// amplified by e^(sigma t) <= e^(sigma T/4) at the times asked for.
const PERIOD_OVER_T: f64 = 4.0;

/// sigma T of the inversion: the aliased images weigh e^(-2 sigma T) = 1.5e-8 of the
/// bounded remainder, the latest time's errors are amplified by e^(sigma T/4) = 9.5.
const SIGMA_T: f64 = 9.0;

/// The inversion's parameters on a lattice: the highest frequency's factor, the harmonics per
/// unit of it and the half-period over the last time.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LatticeAccuracy {
    pub(crate) refine: f64,
    pub(crate) harmonics_per_omega: f64,
    pub(crate) period_over_t: f64,
}

impl LatticeAccuracy {
    /// The influence function's own (the arcs' route, 1e-6 of the peak).
    const FULL: LatticeAccuracy = LatticeAccuracy {
        refine: 1.0,
        harmonics_per_omega: HARMONICS_PER_OMEGA,
        period_over_t: PERIOD_OVER_T,
    };

    /// The march's: a tenth of the frequencies, half the harmonics per frequency and half the
    /// period (the latest time's errors amplified by e^(sigma T/2) = 90 rather than 9.5), for
    /// a four-hundredth of the work. Measured on the reference case at R/200
    /// (`docs/strikers.md`, section 8): the coefficients' error about 2e-3 of the largest, at
    /// the fronts of the waves reflected from the far side, where the truncated series rings;
    /// the march's force, penetration and half-width within 9.5e-6, 1.3e-6 and 9.4e-6 of their
    /// peaks of the same march with a quarter of the frequencies and the full harmonics and
    /// period.
    pub(crate) const MARCH: LatticeAccuracy = LatticeAccuracy {
        refine: 0.1,
        harmonics_per_omega: 0.4,
        period_over_t: 2.0,
    };
}

/// The step response of a free disk to a pressure on an arc, averaged over arcs of the same
/// width: [`Disk::arc_step_response`].
#[derive(Clone, Debug)]
pub struct ArcStepResponse {
    /// The arc's width 2 theta0 (units R).
    pub arc: f64,
    /// The receiver arcs' centres (radians from the loaded arc's centre).
    pub angles: Vec<f64>,
    /// The times c2s t/R.
    pub times: Vec<f64>,
    /// The mean inward normal displacement, units p0 R/mu_s, `[angle][time]`.
    pub total: Vec<Vec<f64>>,
    /// `total` minus the rigid translation's mean over the receiver arc,
    /// X(t) cos(theta_j) sin(theta0)/theta0, X = F t^2/(2 m), F = 2 p0 R sin(theta0),
    /// m = pi R^2 rho_s.
    pub deformation: Vec<Vec<f64>>,
    /// A bound of each value's error (the same for both arrays; the translation is exact).
    pub error: Vec<Vec<f64>>,
    /// The harmonics summed in the remainder.
    pub harmonics: usize,
    /// The frequencies of its inversion.
    pub frequencies: usize,
}

/// The deformation step response of a free disk on a lattice of arcs and times:
/// [`Disk::lattice_step_response`], the building block of a cylinder striker's cell
/// coefficients.
#[derive(Clone, Debug)]
pub struct LatticeStepResponse {
    /// The arcs' width (units R), also the lattice's spacing in angle.
    pub dx: f64,
    /// The time step (units R/c2s).
    pub dt: f64,
    /// The deformation (the total without the rigid translation's mean, as
    /// [`ArcStepResponse::deformation`]) over the receiver arc centred at k dx at the time
    /// l dt, `[k][l]`, l = 0 ..= steps (0 at l = 0).
    pub deformation: Vec<Vec<f64>>,
    /// A bound of each value's error.
    pub error: Vec<Vec<f64>>,
}

/// The half-plane's transfer function at wavenumber n: the Laplace transform of the inward
/// normal surface displacement under the pressure cos(n x) (mu = 1, c2 = 1, c1 = `c1`),
///
/// ```text
/// F = s^2 alpha / ((2 n^2 + s^2)^2 - 4 n^2 alpha beta)
///   = alpha ((2 n^2 + q)^2 + 4 n^2 alpha beta) / P(q),   q = s^2,
/// P = 16 n^6 (1 - 1/c1^2) + n^4 q (24 - 16/c1^2) + 8 n^2 q^2 + q^3,
/// ```
///
/// alpha = sqrt(n^2 + q/c1^2), beta = sqrt(n^2 + q), the second form free of the
/// cancellation of the first at small |s|/n (F -> 1/(c1 s) at n = 0, (1 - nu)/n as s -> 0).
pub(crate) fn half_plane_transfer(c1: f64, n: f64, s: Complex64) -> Complex64 {
    let q = s * s;
    let n2 = n * n;
    let ic2 = 1.0 / (c1 * c1);
    let alpha = principal_sqrt(q * ic2 + n2);
    let beta = principal_sqrt(q + n2);
    let p = ((q + 8.0 * n2) * q + n2 * n2 * (24.0 - 16.0 * ic2)) * q
        + 16.0 * n2 * n2 * n2 * (1.0 - ic2);
    alpha * ((q + 2.0 * n2) * (q + 2.0 * n2) + alpha * beta * (4.0 * n2)) / p
}

/// The principal square root in algebraic form ([`complexfn::Cx::sqrt`]: one real square
/// root of the modulus' half-sum, no trigonometric functions).
fn principal_sqrt(z: Complex64) -> Complex64 {
    let r = complexfn::Cx::new(z.re, z.im).sqrt();
    Complex64::new(r.re, r.im)
}

/// The remainder's transform at one s for every receiver: sum_n w_n E_n(s) over all the
/// harmonics and over the first three quarters of them, and a bound of its rounding.
struct Sample {
    full: Vec<Complex64>,
    half: Vec<Complex64>,
    rounding: f64,
}

impl Disk {
    /// The inward normal surface displacement of the free disk (R = 1, mu_s = 1, rho_s = 1)
    /// under the pressure p0 = 1 switched on at t = 0 over the arc |theta| <= arc/2, averaged
    /// over the arc of the same width centred at each of `angles` (radians), at each of
    /// `times` (c2s t/R), with a bound of each value's error (module docs; derivation in
    /// `docs/strikers.md`, section 7). `arc` in [`ARC_RANGE`], times in (0, [`LATEST_TIME`]];
    /// the work grows like t_max/arc^2 and is refused above [`WORK_LIMIT`].
    pub fn arc_step_response(
        &self,
        arc: f64,
        angles: &[f64],
        times: &[f64],
    ) -> Result<ArcStepResponse> {
        self.arc_step_response_refined(arc, angles, times, 1.0)
    }

    /// [`Disk::arc_step_response`] with the inversion's highest frequency (and with it the
    /// harmonics kept) multiplied by `refine` in [0.25, 16]: a finer or coarser computation
    /// of the same quantity, to check the error estimates against.
    pub fn arc_step_response_refined(
        &self,
        arc: f64,
        angles: &[f64],
        times: &[f64],
        refine: f64,
    ) -> Result<ArcStepResponse> {
        if !(0.25..=16.0).contains(&refine) {
            return Err(invalid("refinement", refine, "[0.25, 16]"));
        }
        if !(arc >= ARC_RANGE.0 && arc <= ARC_RANGE.1) {
            return Err(invalid("arc over R", arc, format!("[{}, pi]", ARC_RANGE.0)));
        }
        if angles.is_empty() || times.is_empty() {
            return Err(invalid(
                "angles and times",
                format!("{} angles, {} times", angles.len(), times.len()),
                "at least one of each",
            ));
        }
        if let Some(a) = angles.iter().find(|a| !a.is_finite()) {
            return Err(invalid("angle", a, "finite"));
        }
        if let Some(t) = times.iter().find(|t| !(**t > 0.0 && **t <= LATEST_TIME)) {
            return Err(invalid("c2 t/R", t, format!("(0, {LATEST_TIME}]")));
        }
        let c1 = self.c1();
        let theta0 = 0.5 * arc;
        let t_max = times.iter().copied().fold(0.0, f64::max);
        let inv = Inversion::new(
            theta0,
            PERIOD_OVER_T * t_max,
            refine,
            HARMONICS_PER_OMEGA,
            arc,
            t_max,
        )?;
        // the half-plane first: it refuses a Poisson's ratio of 0 before the long part
        let hp = HalfPlane::from_poisson(self.poisson())?;
        let samples = self.remainder_samples(theta0, angles, &inv)?;
        let (kmax, nmax) = (inv.kmax, inv.nmax);
        let mut out = ArcStepResponse {
            arc,
            angles: angles.to_vec(),
            times: times.to_vec(),
            total: Vec::with_capacity(angles.len()),
            deformation: Vec::with_capacity(angles.len()),
            error: Vec::with_capacity(angles.len()),
            harmonics: nmax + 1,
            frequencies: kmax + 1,
        };
        let translation_weight = 2.0 * theta0.sin() / PI * sinc(theta0);
        let round = inv.rounding(&samples);
        for (j, &angle) in angles.iter().enumerate() {
            let mut row_total = Vec::with_capacity(times.len());
            let mut row_def = Vec::with_capacity(times.len());
            let mut row_err = Vec::with_capacity(times.len());
            for &t in times {
                // the remainder by Durbin's series, over all frequencies, up to each mark,
                // and over three quarters of the harmonics
                let (mut all, mut few_harmonics) = (0.0, 0.0);
                // partial sums over the first 1/2, 5/8, 3/4 and 7/8 of the frequencies
                let marks = [kmax / 2, 5 * kmax / 8, 3 * kmax / 4, 7 * kmax / 8];
                let mut partial = [0.0; 4];
                for (k, smp) in samples.iter().enumerate() {
                    let s = inv.s(k);
                    let phase = Complex64::from_polar(1.0, s.im * t) / s;
                    let factor = if k == 0 { 0.5 } else { 1.0 };
                    let v = (smp.full[j] * phase).re * factor;
                    all += v;
                    for (p, m) in partial.iter_mut().zip(marks) {
                        if k <= m {
                            *p += v;
                        }
                    }
                    few_harmonics += (smp.half[j] * phase).re * factor;
                }
                let series = [
                    all,
                    partial[0],
                    partial[1],
                    partial[2],
                    partial[3],
                    few_harmonics,
                ];
                // the periodised half-plane, in its own units (c1 = 1: time c1s t)
                let images = periodised_half_plane(&hp, theta0, angle, c1 * t)?;
                let (deformation, error) =
                    inv.deformation(&series, round, t, theta0, angle, c1, images)?;
                let translation = translation_weight * (angle).cos() * 0.5 * t * t;
                let total = deformation + translation;
                row_total.push(total);
                row_def.push(deformation);
                row_err.push(error);
            }
            out.total.push(row_total);
            out.deformation.push(row_def);
            out.error.push(row_err);
        }
        Ok(out)
    }
}

/// The parameters of the remainder's Fourier inversion (module docs): the half-period T,
/// sigma = SIGMA_T/T, the frequencies k pi/T for k = 0..=kmax, the harmonics 0..=nmax.
struct Inversion {
    period_half: f64,
    sigma: f64,
    kmax: usize,
    nmax: usize,
}

impl Inversion {
    /// For arcs of half-width `theta0` and the half-period `period_half`, the highest
    /// frequency multiplied by `refine`, `harmonics_per_omega` harmonics per unit of it;
    /// refused (naming the arc) above [`WORK_LIMIT`].
    fn new(
        theta0: f64,
        period_half: f64,
        refine: f64,
        harmonics_per_omega: f64,
        arc: f64,
        t_max: f64,
    ) -> Result<Self> {
        let omega = refine
            * (OMEGA_THETA / theta0)
                .max(OMEGA_MIN)
                .max(FREQUENCIES_MIN * PI / period_half);
        let nmax = (harmonics_per_omega * omega).ceil() as usize;
        let kmax = (omega * period_half / PI).ceil() as usize;
        let work = (kmax + 1) as f64 * (nmax as f64 + 2.0 * omega);
        if work > WORK_LIMIT {
            return Err(invalid(
                "arc over R",
                arc,
                format!(
                    "[{}, pi] with t_max/arc^2 small enough: {work:.2e} harmonic evaluations \
                     needed to c2 t/R = {t_max}, above the limit {WORK_LIMIT:.0e} (a wider arc \
                     or an earlier last time)",
                    ARC_RANGE.0
                ),
            ));
        }
        Ok(Inversion {
            period_half,
            sigma: SIGMA_T / period_half,
            kmax,
            nmax,
        })
    }

    /// The k-th frequency's s.
    fn s(&self, k: usize) -> Complex64 {
        Complex64::new(self.sigma, k as f64 * PI / self.period_half)
    }

    /// The series' rounding bound (without the factor e^(sigma t)/T), the same at every time.
    fn rounding(&self, samples: &[Sample]) -> f64 {
        samples
            .iter()
            .enumerate()
            .map(|(k, smp)| smp.rounding * if k == 0 { 0.5 } else { 1.0 } / self.s(k).norm())
            .sum()
    }

    /// The deformation at time `t` over the receiver arc centred at `angle` and its error
    /// bound, from the remainder's series `series` at t (without the factor
    /// e^(sigma t)/T): over all frequencies, up to the four marks 1/2, 5/8, 3/4, 7/8 of
    /// them, and over three quarters of the harmonics; `round` the series' rounding bound.
    /// The periodised half-plane `images` (value, error bound) and the uniform mode are
    /// added here.
    #[allow(clippy::too_many_arguments)]
    fn deformation(
        &self,
        series: &[f64; 6],
        round: f64,
        t: f64,
        theta0: f64,
        angle: f64,
        c1: f64,
        images: (f64, f64),
    ) -> Result<(f64, f64)> {
        let scale = (self.sigma * t).exp() / self.period_half;
        let all = series[0];
        let remainder = scale * all;
        // the truncation in frequency: twice the largest change over the last half of the
        // frequencies (the series converges like K^-1.5 or faster, so this bounds the rest
        // unless the partial sums happen to cross: four marks guard that)
        let err_frequencies = 2.0
            * scale
            * series[1..5]
                .iter()
                .map(|p| (all - p).abs())
                .fold(0.0, f64::max);
        let err_harmonics = scale * (all - series[5]).abs();
        let err_alias = (-2.0 * SIGMA_T).exp() * 10.0 * remainder.abs().max(theta0);
        let (images, err_images) = images;
        let value = images + remainder - theta0 / PI * t / c1;
        let error = err_frequencies + err_harmonics + scale * round + err_alias + err_images;
        if !(value.is_finite() && error.is_finite()) {
            return Err(ImpactError::Step {
                time: format!("{t}"),
                reason: format!("the disk's response is not finite at angle {angle} rad"),
            });
        }
        Ok((value, error))
    }
}

impl Disk {
    /// The remainder's transform sum_n w_n E_n(s) (over all the harmonics and over three
    /// quarters of them) at every frequency of `inv`, for the receiver arcs centred at
    /// `angles` (module docs), in parallel over the frequencies.
    fn remainder_samples(
        &self,
        theta0: f64,
        angles: &[f64],
        inv: &Inversion,
    ) -> Result<Vec<Sample>> {
        let c1 = self.c1();
        let nmax = inv.nmax;
        // the harmonics' weights p_n sinc(n theta0) (times 2 for n >= 1: cos n theta pairs
        // the orders n and -n) and each receiver's cosines
        let base: Vec<f64> = (0..=nmax)
            .map(|n| {
                let nf = n as f64;
                if n == 0 {
                    theta0 / PI
                } else {
                    2.0 * (nf * theta0).sin() / (nf * PI) * sinc(nf * theta0)
                }
            })
            .collect();
        // each harmonic's weights at every receiver, [n][j] (contiguous in j: the sum over
        // the receivers is the inner loop)
        let nj = angles.len();
        let weights: Vec<f64> = base
            .iter()
            .enumerate()
            .flat_map(|(n, b)| angles.iter().map(move |a| b * (n as f64 * a).cos()))
            .collect();
        // the harmonics' terms fall like n^-4: the last quarter changes the sum by about 1.4
        // times what the harmonics beyond N would
        let half_n = 3 * nmax / 4;
        let sample = |k: usize| -> Sample {
            let s = inv.s(k);
            let mut df = vec![Complex64::new(0.0, 0.0); nmax + 1];
            let mut dg = vec![Complex64::new(0.0, 0.0); nmax + 1];
            ratio_terms(s / c1, &mut df);
            ratio_terms(s, &mut dg);
            let y2 = s * s;
            let pole = y2.inv();
            let mut rounding = 0.0;
            // the remainder's terms E_n, then their sums at every receiver
            let terms: Vec<Complex64> = (0..=nmax)
                .map(|n| {
                    let nf = n as f64;
                    let w = transfer(nf, df[n], dg[n], y2);
                    let e = match n {
                        0 => w,
                        1 => w - half_plane_transfer(c1, nf, s) - pole,
                        _ => w - half_plane_transfer(c1, nf, s),
                    };
                    rounding += base[n].abs() * (w.l1_norm() + e.l1_norm()); // bounds the moduli
                    e
                })
                .collect();
            let (mut re, mut im) = (vec![0.0; nj], vec![0.0; nj]);
            let mut half = Vec::new();
            let accumulate = |range: std::ops::Range<usize>, re: &mut [f64], im: &mut [f64]| {
                for n in range {
                    let (er, ei) = (terms[n].re, terms[n].im);
                    let row = &weights[n * nj..(n + 1) * nj];
                    for ((r, i), w) in re.iter_mut().zip(im.iter_mut()).zip(row) {
                        *r += er * w;
                        *i += ei * w;
                    }
                }
            };
            accumulate(0..half_n + 1, &mut re, &mut im);
            half.extend(re.iter().zip(&im).map(|(r, i)| Complex64::new(*r, *i)));
            accumulate(half_n + 1..nmax + 1, &mut re, &mut im);
            let full = re
                .iter()
                .zip(&im)
                .map(|(r, i)| Complex64::new(*r, *i))
                .collect();
            Sample {
                full,
                half,
                rounding: 64.0 * f64::EPSILON * rounding,
            }
        };
        let samples: Vec<Sample> = (0..=inv.kmax).into_par_iter().map(sample).collect();
        if samples.iter().any(|s| {
            s.full
                .iter()
                .chain(&s.half)
                .any(|v| !(v.re.is_finite() && v.im.is_finite()))
        }) {
            return Err(ImpactError::Step {
                time: "0".into(),
                reason: format!(
                    "the disk's remainder transform is not finite at some frequency \
                     (arc {}, half-period {})",
                    2.0 * theta0,
                    inv.period_half
                ),
            });
        }
        Ok(samples)
    }
}

/// The half-plane's mean displacement over the strip of half-width theta0 centred at
/// `angle` (arc length), due to the unit pressure on the strip |x| <= theta0 switched on at
/// time 0, summed over the images angle + 2 pi m, at `time` in the Lamb crate's units
/// (c1 = 1, mu = 1): each image is [`half_plane_strip`]; images beyond the P front give 0
/// exactly. Returns the value and its error bound.
fn periodised_half_plane(
    hp: &HalfPlane<f64>,
    theta0: f64,
    angle: f64,
    time: f64,
) -> Result<(f64, f64)> {
    let centred = angle - 2.0 * PI * (angle / (2.0 * PI)).round();
    let reach = time + 2.0 * theta0;
    let mmax = ((reach + PI) / (2.0 * PI)).ceil() as i64;
    let (mut value, mut error) = (0.0, 0.0);
    for m in -mmax..=mmax {
        let d = centred + 2.0 * PI * m as f64;
        if d.abs() >= reach {
            continue;
        }
        let (v, e) = half_plane_strip(hp, theta0, d, time)?;
        value += v;
        error += e;
    }
    Ok((value, error))
}

/// [`periodised_half_plane`] for the arcs of width `dx` centred at k dx for every k in
/// `offsets` (theta0 = dx/2), at `time` (c1 = 1): the second differences of one row of
/// primitives Xi(j dx + 2 pi m) per image, shared by neighbouring offsets (an image whose
/// every offset lies beyond the P front is skipped; Xi is even). Returns (value, error) per
/// offset.
fn periodised_row(
    hp: &HalfPlane<f64>,
    dx: f64,
    offsets: std::ops::Range<usize>,
    time: f64,
) -> Result<Vec<(f64, f64)>> {
    let reach = time + dx;
    let mut out = vec![(0.0, 0.0); offsets.len()];
    let far = (offsets.end as f64 * dx + reach + PI) / (2.0 * PI);
    let mmax = far.ceil() as i64;
    // the row's first index: the primitives at (k - 1) dx .. (k + 1) dx
    let first = offsets.start as i64 - 1;
    for m in -mmax..=mmax {
        let shift = 2.0 * PI * m as f64;
        let near = |k: usize| (k as f64 * dx + shift).abs() < reach;
        if !offsets.clone().any(near) {
            continue;
        }
        let row: Vec<Estimate<f64>> = (first..=offsets.end as i64)
            .map(|j| {
                let x = (j as f64 * dx + shift).abs();
                hp.cell_mean_primitive_zz(&x, &time)
            })
            .collect::<std::result::Result<_, _>>()?;
        for (i, k) in offsets.clone().enumerate() {
            if !near(k) {
                continue;
            }
            let (a, b, c) = (&row[i], &row[i + 1], &row[i + 2]);
            out[i].0 += (a.value - 2.0 * b.value + c.value) / dx;
            out[i].1 += (a.error + 2.0 * b.error + c.error) / dx;
        }
    }
    Ok(out)
}

/// The half-plane's mean displacement over the strip of half-width theta0 at the distance
/// `d`, due to the unit pressure on the strip |x| <= theta0 switched on at time 0, at `time`
/// (the Lamb crate's units, c1 = 1, mu = 1): with Xi the triple primitive,
/// [Xi(d + 2 theta0) - 2 Xi(d) + Xi(d - 2 theta0)]/(2 theta0), with its error bound.
pub(crate) fn half_plane_strip(
    hp: &HalfPlane<f64>,
    theta0: f64,
    d: f64,
    time: f64,
) -> Result<(f64, f64)> {
    let (mut value, mut error) = (0.0, 0.0);
    for (x, c) in [(d + 2.0 * theta0, 1.0), (d, -2.0), (d - 2.0 * theta0, 1.0)] {
        let xi = hp.cell_mean_primitive_zz(&x, &time)?;
        value += c * xi.value;
        error += c.abs() * xi.error;
    }
    Ok((value / (2.0 * theta0), error / (2.0 * theta0)))
}

impl Disk {
    /// The quasi-static deformation of the free disk (units p0 R/mu_s) under the unit
    /// pressure on the arc |theta| <= arc/2, balanced by its own uniform inertia (the rigid
    /// translation's pole taken out), averaged over the same arc:
    /// sum_n p_n sinc(n theta0) lim_(s -> 0) [W_n(s) - (1/s^2 at n = 1)], summed to
    /// n = 100/theta0 with a bound of the rest added, and evaluated at s =
    /// [`super::disk::SMALLEST_S`] (relative error about 1e-8). It is the sum over the elastic modes of r/omega^2, so the deformation step
    /// response over any arc of the same width stays within twice it at all times (each mode
    /// within twice its static part, the cross terms by Cauchy-Schwarz): the bound of a stiff
    /// cylinder's omitted response (`docs/strikers.md`, section 8).
    pub fn inertia_relief_compliance(&self, arc: f64) -> Result<f64> {
        if !(arc >= ARC_RANGE.0 && arc <= ARC_RANGE.1) {
            return Err(invalid("arc over R", arc, format!("[{}, pi]", ARC_RANGE.0)));
        }
        let theta0 = 0.5 * arc;
        let s = super::disk::SMALLEST_S;
        let sc = Complex64::new(s, 0.0);
        let top = (100.0 / theta0).ceil() as u32;
        let (mut sum, mut last) = (0.0, 0.0);
        for n in 0..=top {
            let nf = f64::from(n);
            let w = if n == 0 {
                theta0 / PI
            } else {
                2.0 * (nf * theta0).sin() / (nf * PI) * sinc(nf * theta0)
            };
            let mut v = self.harmonic(n, sc)?.re;
            if n == 1 {
                v -= 1.0 / (s * s);
            }
            sum += w * v;
            last = nf * v.abs();
        }
        // beyond, |w_n| <= 2/(pi theta0 n^2) and |W_n| ~ C/n with C the last n |W_n|: the
        // tail is within C/(pi theta0 N^2), added (twice) to make the value a bound
        let n = f64::from(top);
        let sum = sum + 2.0 * last / (PI * theta0 * n * n);
        if !sum.is_finite() {
            return Err(ImpactError::Step {
                time: "0".into(),
                reason: format!(
                    "the disk's quasi-static compliance over the arc {arc} is not finite"
                ),
            });
        }
        Ok(sum)
    }
}

impl Disk {
    /// The deformation step response ([`ArcStepResponse::deformation`]) for arcs of width `dx`
    /// centred at the offsets k dx, k = 0 ..= `offsets`, at the times l dt, l = 0 ..= `steps`
    /// (units of [`Disk`]): the march's lattice. The same construction as
    /// [`Disk::arc_step_response`], its Fourier series summed at every time at once: the
    /// half-period is chosen as M dt/2 with M an integer, so the series at t_l is the inverse
    /// discrete Fourier transform of length M of the frequency samples folded modulo M.
    pub fn lattice_step_response(
        &self,
        dx: f64,
        dt: f64,
        offsets: usize,
        steps: usize,
    ) -> Result<LatticeStepResponse> {
        self.lattice_rows(dx, dt, 0..offsets + 1, steps, LatticeAccuracy::FULL)
    }

    /// [`Disk::lattice_step_response`] with the inversion's highest frequency (and with it
    /// the harmonics kept) multiplied by `refine` in [0.1, 16], as
    /// [`Disk::arc_step_response_refined`].
    pub fn lattice_step_response_refined(
        &self,
        dx: f64,
        dt: f64,
        offsets: usize,
        steps: usize,
        refine: f64,
    ) -> Result<LatticeStepResponse> {
        self.lattice_rows(
            dx,
            dt,
            0..offsets + 1,
            steps,
            LatticeAccuracy {
                refine,
                ..LatticeAccuracy::FULL
            },
        )
    }

    /// [`Disk::lattice_step_response`] for the receiver offsets `offsets` alone (rows
    /// `[k - offsets.start]`): a table grown by columns computes only the new ones.
    pub(crate) fn lattice_rows(
        &self,
        dx: f64,
        dt: f64,
        offsets: std::ops::Range<usize>,
        steps: usize,
        accuracy: LatticeAccuracy,
    ) -> Result<LatticeStepResponse> {
        let refine = accuracy.refine;
        if !(0.1..=16.0).contains(&refine) {
            return Err(invalid("refinement", refine, "[0.1, 16]"));
        }
        if !(dx >= ARC_RANGE.0 && dx <= ARC_RANGE.1) {
            return Err(invalid("arc over R", dx, format!("[{}, pi]", ARC_RANGE.0)));
        }
        if !(dt > 0.0 && dt.is_finite() && steps >= 1 && steps as f64 * dt <= LATEST_TIME) {
            return Err(invalid(
                "c2 t/R",
                steps as f64 * dt,
                format!("(0, {LATEST_TIME}] (steps times dt)"),
            ));
        }
        if offsets.end > 100_001 || offsets.is_empty() {
            return Err(invalid(
                "angle",
                format!("offsets {offsets:?}"),
                "a non-empty range within 0..=100000",
            ));
        }
        let c1 = self.c1();
        let theta0 = 0.5 * dx;
        let t_max = steps as f64 * dt;
        let m = (2.0 * accuracy.period_over_t * steps as f64).ceil() as usize;
        let inv = Inversion::new(
            theta0,
            0.5 * m as f64 * dt,
            refine,
            accuracy.harmonics_per_omega,
            dx,
            t_max,
        )?;
        let angles: Vec<f64> = offsets.clone().map(|k| k as f64 * dx).collect();
        let hp = HalfPlane::from_poisson(self.poisson())?;
        let samples = self.remainder_samples(theta0, &angles, &inv)?;
        let kmax = inv.kmax;
        let marks = [kmax / 2, 5 * kmax / 8, 3 * kmax / 4, 7 * kmax / 8];
        let round = inv.rounding(&samples);
        // the periodised half-plane at every step and offset, the primitives shared by
        // neighbouring offsets, in parallel over the steps
        let images: Vec<Vec<(f64, f64)>> = (1..=steps)
            .into_par_iter()
            .map(|l| periodised_row(&hp, dx, offsets.clone(), c1 * l as f64 * dt))
            .collect::<Result<_>>()?;
        let (_, inverse) = crate::history::Planner::new().plans(m);
        let zero = Complex64::new(0.0, 0.0);
        // each receiver's folded series and inverse transforms, in parallel over the receivers
        let per_angle = |(j, &angle): (usize, &f64)| -> Result<(Vec<f64>, Vec<f64>)> {
            // folded series: all frequencies, the four partial sums, three quarters of the
            // harmonics
            let mut series = vec![vec![zero; m]; 6];
            for (k, smp) in samples.iter().enumerate() {
                let f = if k == 0 { 0.5 } else { 1.0 } / inv.s(k);
                let (full, few) = (smp.full[j] * f, smp.half[j] * f);
                let r = k % m;
                series[0][r] += full;
                for (i, mark) in marks.iter().enumerate() {
                    if k <= *mark {
                        series[1 + i][r] += full;
                    }
                }
                series[5][r] += few;
            }
            for s in series.iter_mut() {
                inverse.process(s);
            }
            let mut row = Vec::with_capacity(steps + 1);
            let mut err = Vec::with_capacity(steps + 1);
            row.push(0.0);
            err.push(0.0);
            for l in 1..=steps {
                let at: [f64; 6] = std::array::from_fn(|i| series[i][l].re);
                let t = l as f64 * dt;
                let (value, e) =
                    inv.deformation(&at, round, t, theta0, angle, c1, images[l - 1][j])?;
                row.push(value);
                err.push(e);
            }
            Ok((row, err))
        };
        let rows: Vec<(Vec<f64>, Vec<f64>)> = angles
            .par_iter()
            .enumerate()
            .map(per_angle)
            .collect::<Result<_>>()?;
        let (deformation, error) = rows.into_iter().unzip();
        let out = LatticeStepResponse {
            dx,
            dt,
            deformation,
            error,
        };
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The march's lattice accuracy against the full one (R/50, nu = 0.25, to c2s t/R = 4.6):
    /// the largest difference within the largest stated error (the table's bound is the largest
    /// over all its values: pointwise, the reduced series rings and its estimate with it), and
    /// the stated errors small beside the values.
    #[test]
    fn march_lattice_is_within_its_stated_error_of_the_full_one() {
        let disk = Disk::new(0.25).unwrap();
        let (dx, dt, steps) = (0.02, 0.04 * (1.0f64 / 3.0).sqrt(), 200);
        let march = disk
            .lattice_rows(dx, dt, 0..6, steps, LatticeAccuracy::MARCH)
            .unwrap();
        let full = disk
            .lattice_rows(dx, dt, 0..6, steps, LatticeAccuracy::FULL)
            .unwrap();
        let largest = |rows: &[Vec<f64>]| rows.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
        let peak = largest(&full.deformation);
        let mut diff: f64 = 0.0;
        for (m, f) in march.deformation.iter().zip(&full.deformation) {
            for (a, b) in m.iter().zip(f) {
                diff = diff.max((a - b).abs());
            }
        }
        let stated = largest(&march.error) + largest(&full.error);
        assert!(diff <= stated, "{diff:e} against {stated:e}");
        assert!(
            diff > 0.1 * stated,
            "{diff:e} against {stated:e}: not sharp"
        );
        assert!(stated < 1e-2 * peak, "stated {stated:e}, peak {peak:e}");
    }
}
