//! The free elastic disk: the full elastic cylinder striker's own response, harmonic by
//! harmonic in the polar angle (`docs/strikers.md`, section 6).
//!
//! Plane strain, radius R = 1, shear modulus mu_s = 1 and density rho_s = 1 (so c2s = 1 and
//! c1s = sqrt(2 (1 - nu)/(1 - 2 nu))), zero initial state, the surface r = 1 free of traction
//! but for a normal pressure p(theta, t) (inward: sigma_rr = -p, sigma_r_theta = 0). For the
//! pressure P(s) cos(n theta) (Laplace transform in time) the inward normal displacement of
//! the surface is W_n(s) P(s) cos(n theta) ([`Disk::harmonic`]); its zeros on the imaginary
//! axis, s = i omega, are the free disk's natural frequencies ([`Disk::frequencies`]).
//!
//! These are the building blocks of the cylinder's influence function G0; the march does not
//! use them yet.

use rustfft::num_complex::Complex64;

use complexfn::roots::illinois;

use crate::error::{invalid, ImpactError, Result};

/// A free elastic disk in its own units (R = 1, mu_s = 1, rho_s = 1, c2s = 1).
#[derive(Clone, Copy, Debug)]
pub struct Disk {
    poisson: f64,
    /// c1s/c2s.
    c1: f64,
}

/// The smallest |s| R/c2s at which [`Disk::harmonic`] is formed: below it the determinant's
/// leading terms cancel (for n >= 2 they vanish like s^2) and the response loses about
/// 2 log10(1/|s|) digits.
pub const SMALLEST_S: f64 = 1e-4;

/// The most terms of the Bessel ratio's continued fraction (it needs about |s| R/c2s).
const CF_TERMS: u32 = 1_000_000;

/// No natural frequency of order n lies below LOWEST_OVER_N n (units c2s/R): the lowest,
/// flexural, ones of the low orders are near 0.65 n, the high orders' near n c_R >= 0.87 n
/// (checked for Poisson's ratios from -0.9 to 0.49 and n <= 40 against a scan from 0 in the
/// tests). The scans start there, where J_n of the low frequencies would underflow.
const LOWEST_OVER_N: f64 = 0.5;

/// The largest circumferential order served.
pub const LARGEST_ORDER: u32 = 100_000;

impl Disk {
    /// The disk of Poisson's ratio `poisson` in (-1, 1/2).
    pub fn new(poisson: f64) -> Result<Self> {
        if !(poisson > -1.0 && poisson < 0.5) {
            return Err(invalid("poisson", poisson, "(-1, 0.5)"));
        }
        Ok(Disk {
            poisson,
            c1: (2.0 * (1.0 - poisson) / (1.0 - 2.0 * poisson)).sqrt(),
        })
    }

    /// Poisson's ratio.
    pub fn poisson(&self) -> f64 {
        self.poisson
    }

    /// c1s/c2s.
    pub fn c1(&self) -> f64 {
        self.c1
    }

    /// W_n(s): the Laplace transform of the inward normal surface displacement (units
    /// P R/mu_s) per unit transformed pressure P(s) cos(n theta), at s (units c2s/R) with
    /// Re s >= 0 and |s| >= [`SMALLEST_S`]. With the potentials phi = A I_n(s r/c1s) cos n theta
    /// and psi = B I_n(s r) sin n theta, x = s/c1s, y = s, f = x I_n'(x)/I_n(x) and
    /// g = y I_n'(y)/I_n(y) (`docs/strikers.md`, section 6):
    ///
    /// ```text
    /// W_n = (f a22 - n a21)/(a11 a22 - a12 a21),
    /// a11 = y^2 + 2 n^2 - 2 f,  a12 = 2 n (g - 1),  a21 = 2 n (1 - f),
    /// a22 = 2 g - y^2 - 2 n^2,
    /// ```
    ///
    /// evaluated in a form free of the cancellation of the determinant's
    /// leading terms.
    pub fn harmonic(&self, n: u32, s: Complex64) -> Result<Complex64> {
        if n > LARGEST_ORDER {
            return Err(invalid("n", n, format!("0..={LARGEST_ORDER}")));
        }
        if !(s.re >= 0.0 && s.norm() >= SMALLEST_S && s.norm().is_finite()) {
            return Err(invalid(
                "s",
                s,
                format!("Re s >= 0 and {SMALLEST_S} <= |s| < inf (units c2s/R)"),
            ));
        }
        let nf = f64::from(n);
        let x = s / self.c1;
        let y = s;
        let unconverged = || ImpactError::Step {
            time: format!("s = {s}"),
            reason: format!("the Bessel ratio's continued fraction of order {n} did not converge"),
        };
        let df = ratio_term(n, x).ok_or_else(unconverged)?;
        let dg = ratio_term(n, y).ok_or_else(unconverged)?;
        let w = transfer(nf, df, dg, y * y);
        if !(w.re.is_finite() && w.im.is_finite()) {
            return Err(ImpactError::Step {
                time: format!("s = {s}"),
                reason: format!("the disk's harmonic n = {n} is singular there"),
            });
        }
        Ok(w)
    }

    /// The free disk's natural angular frequencies (units c2s/R) of order n whose motion has a
    /// radial displacement ~ cos(n theta), the lowest `count` above zero (the rigid
    /// translation, n = 1, omega = 0, excluded; for n = 0 the breathing modes only, the
    /// torsional ones having no radial motion). They are the zeros of the pole-free frequency
    /// function [`Disk::frequency_function`], bracketed on a grid of 1/200 of the shear
    /// wavelength's scale and refined by `complexfn::roots::illinois` to the rounding of omega.
    pub fn frequencies(&self, n: u32, count: usize) -> Result<Vec<f64>> {
        if n > 1000 {
            return Err(invalid("n", n, "0..=1000"));
        }
        let out = self.scan(n, LOWEST_OVER_N * f64::from(n), 1e4, count)?;
        if out.len() < count {
            return Err(ImpactError::Step {
                time: "omega = 1e4".into(),
                reason: format!("fewer than {count} frequencies of order {n} found"),
            });
        }
        Ok(out)
    }

    /// The natural frequencies of order n below `omega_max` (as [`Disk::frequencies`]), each
    /// with its residue r in W_n(s) = sum_k r_k/(s^2 + omega_k^2) (+ the rigid translation's
    /// 1/s^2 at n = 1): the mode's share of the surface response, positive. r is the limit of
    /// (omega^2 - w^2) W_n(i w) as w -> omega, taken as the mean of the two sides
    /// w = omega (1 +- 1e-6), whose first-order terms cancel (relative error ~1e-11).
    pub fn modes_below(&self, n: u32, omega_max: f64) -> Result<Vec<(f64, f64)>> {
        if n > 1000 {
            return Err(invalid("n", n, "0..=1000"));
        }
        if !(omega_max > 0.0 && omega_max <= 1e4) {
            return Err(invalid("omega_max", omega_max, "(0, 1e4]"));
        }
        let h = 1e-6;
        self.scan(n, LOWEST_OVER_N * f64::from(n), omega_max, usize::MAX)?
            .into_iter()
            .map(|omega| {
                let side = |w: f64| -> Result<f64> {
                    let v = self.harmonic(n, Complex64::new(0.0, w))?;
                    Ok((omega * omega - w * w) * v.re)
                };
                let r = 0.5 * (side(omega * (1.0 - h))? + side(omega * (1.0 + h))?);
                if !(r.is_finite() && r > 0.0) {
                    return Err(ImpactError::Step {
                        time: format!("omega = {omega}"),
                        reason: format!("the residue of the disk's mode of order {n} is {r}"),
                    });
                }
                Ok((omega, r))
            })
            .collect()
    }

    /// The zeros of [`Disk::frequency_function`] of order n in (`from`, omega_max], at most
    /// `count` of them: bracketed on a grid of 1/200 of the shear wavelength's scale and
    /// refined by `complexfn::roots::illinois` to the rounding of omega.
    fn scan(&self, n: u32, from: f64, omega_max: f64, count: usize) -> Result<Vec<f64>> {
        let step = 0.005;
        let f = |omega: &f64| Ok::<f64, ImpactError>(self.frequency_function(n, *omega));
        let mut out = Vec::new();
        // below `from` J_n may underflow: start where the function is not 0
        let mut lo = from.max(1e-3);
        let mut flo = self.frequency_function(n, lo);
        while flo == 0.0 && lo < omega_max {
            lo += step;
            flo = self.frequency_function(n, lo);
        }
        while out.len() < count && lo < omega_max {
            let hi = (lo + step).min(omega_max);
            let fhi = self.frequency_function(n, hi);
            if flo == 0.0 {
                out.push(lo);
            } else if flo.signum() != fhi.signum() {
                out.push(illinois(lo, flo, hi, fhi, &f64::EPSILON, f)?);
            }
            lo = hi;
            flo = fhi;
        }
        Ok(out)
    }

    /// The frequency function of order n at the real angular frequency omega: the determinant
    /// of [`Disk::harmonic`] at s = i omega times J_n(omega/c1s) J_n(omega), free of poles
    /// (z1 = omega/c1s, z2 = omega, j_k = J_n(z_k), d_k = z_k J_n'(z_k)):
    ///
    /// ```text
    /// E = ((2 n^2 - z2^2) j1 - 2 d1)((z2^2 - 2 n^2) j2 + 2 d2) - 4 n^2 (d2 - j2)(j1 - d1),
    /// ```
    ///
    /// and for n = 0 its first factor alone (the second is the torsional modes').
    pub fn frequency_function(&self, n: u32, omega: f64) -> f64 {
        let nf = f64::from(n);
        let (z1, z2) = (omega / self.c1, omega);
        let (j1, d1) = bessel_j(n, z1);
        let (j2, d2) = bessel_j(n, z2);
        let first = (2.0 * nf * nf - z2 * z2) * j1 - 2.0 * d1;
        if n == 0 {
            return first;
        }
        first * ((z2 * z2 - 2.0 * nf * nf) * j2 + 2.0 * d2) - 4.0 * nf * nf * (d2 - j2) * (j1 - d1)
    }
}

/// W_n from the Bessel ratio terms df = x I_(n+1)(x)/I_n(x) (x = s/c1s) and
/// dg = y I_(n+1)(y)/I_n(y) (y = s), so that f = n + df and g = n + dg
/// (`docs/strikers.md`, section 6). With A = 2 n (n - 1), u = y^2 - 2 df and v = 2 dg - y^2 the
/// matrix is a11 = A + u, a22 = v - A, a12 = A + 2 n dg, a21 = -A - 2 n df, and
///
/// ```text
/// det = A (2 (n + 1) (df + dg) - 2 y^2) + u v + 4 n^2 df dg,
/// W_n = (n v + df (v + 2 n))/det,
/// ```
///
/// the terms A^2 of a11 a22 and a12 a21 (of order n^4 against the determinant's n^2 s^2)
/// cancelled by hand, so no digits are lost at small |s|/n.
pub(crate) fn transfer(n: f64, df: Complex64, dg: Complex64, y2: Complex64) -> Complex64 {
    let a = 2.0 * n * (n - 1.0);
    let u = y2 - df * 2.0;
    let v = dg * 2.0 - y2;
    let det = ((df + dg) * (2.0 * (n + 1.0)) - y2 * 2.0) * a + u * v + df * dg * (4.0 * n * n);
    (v * n + df * (v + 2.0 * n)) / det
}

/// The ratio terms rho_n = z I_(n+1)(z)/I_n(z) for n = 0, ..., out.len() - 1 at once, by
/// the backward recurrence rho_(n-1) = z^2/(2 n + rho_n) of the minimal solution, started
/// from 0 above both the last order and 1.1 |z| by 50 orders: above |z| a starting error is
/// damped by |rho_n/(2 n)|^2 <= 1/4 per step. Re z >= 0, z != 0.
pub(crate) fn ratio_terms(z: Complex64, out: &mut [Complex64]) {
    let Some(last) = out.len().checked_sub(1) else {
        return;
    };
    let start = last.max((1.1 * z.norm()) as usize) + 50;
    let z2 = z * z;
    let mut rho = Complex64::new(0.0, 0.0);
    for n in (1..=start).rev() {
        rho = z2 / (rho + 2.0 * n as f64);
        if n - 1 <= last {
            out[n - 1] = rho;
        }
    }
}

/// z I_n'(z)/I_n(z) = n + [`ratio_term`].
#[cfg(test)]
fn log_derivative_i(n: u32, z: Complex64) -> Option<Complex64> {
    ratio_term(n, z).map(|r| r + f64::from(n))
}

/// z I_(n+1)(z)/I_n(z) for Re z >= 0, z != 0 (so that z I_n'(z)/I_n(z) is n plus it): the
/// ratio I_(n+1)/I_n = 1/(2 (n + 1)/z + 1/(2 (n + 2)/z + ...)) by the modified Lentz method
/// (the continued fraction of the minimal solution of the recurrence, convergent for every z;
/// it takes about |z| terms). `None` if it has not converged after [`CF_TERMS`] terms.
fn ratio_term(n: u32, z: Complex64) -> Option<Complex64> {
    let tiny = Complex64::new(1e-150, 0.0);
    let inv = z.inv();
    let b = |k: u32| inv * (2.0 * (f64::from(n) + f64::from(k)));
    // Lentz on f = 0 + 1/(b1 + 1/(b2 + ...)), the ratio itself
    let mut f = tiny;
    let mut c = f;
    let mut d = Complex64::new(0.0, 0.0);
    for k in 1..=CF_TERMS {
        let bk = b(k);
        d = bk + d;
        if d.norm() < 1e-150 {
            d = tiny;
        }
        c = bk + c.inv();
        if c.norm() < 1e-150 {
            c = tiny;
        }
        d = d.inv();
        let delta = c * d;
        f *= delta;
        if (delta - 1.0).norm() < 1e-16 {
            return Some(z * f);
        }
    }
    None
}

/// (J_n(x), x J_n'(x)) for real x >= 0 by Miller's backward recurrence, normalised by
/// J_0 + 2 (J_2 + J_4 + ...) = 1.
fn bessel_j(n: u32, x: f64) -> (f64, f64) {
    if x == 0.0 {
        return (if n == 0 { 1.0 } else { 0.0 }, 0.0);
    }
    let nf = n as usize;
    // start well above both n and x: the recurrence's growing solution is J's dominant
    // partner Y, so backward from there J emerges to the working precision
    let start = (nf.max(x as usize) + 30 + (x.sqrt() * 10.0) as usize) | 1;
    let start = start + 1; // even
    let (mut jp1, mut j) = (0.0f64, 1e-300f64);
    let mut norm = 0.0;
    let (mut jn, mut jn1) = (0.0, 0.0); // J_n and J_(n+1), unnormalised
    for k in (1..=start).rev() {
        // j = J_k, jp1 = J_(k+1): J_(k-1) = (2 k/x) J_k - J_(k+1)
        let jm1 = (2.0 * k as f64 / x) * j - jp1;
        jp1 = j;
        j = jm1;
        let km1 = k - 1;
        if km1 == nf {
            jn = j;
            jn1 = jp1;
        }
        if km1 % 2 == 0 {
            norm += if km1 == 0 { j } else { 2.0 * j };
        }
        if j.abs() > 1e250 {
            // rescale everything carried
            let sc = 1e-250;
            j *= sc;
            jp1 *= sc;
            norm *= sc;
            jn *= sc;
            jn1 *= sc;
        }
    }
    let (jn, jn1) = (jn / norm, jn1 / norm);
    // x J_n' = n J_n - x J_(n+1)
    (jn, f64::from(n) * jn - x * jn1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scans' start: no frequency of order n below LOWEST_OVER_N n, by a scan from 0
    /// (where J_n does not underflow: 1 <= n <= 40).
    #[test]
    fn no_frequency_below_the_scans_start() {
        for nu in [-0.9, -0.5, 0.0, 0.25, 0.45, 0.49] {
            let disk = Disk::new(nu).unwrap();
            for n in 1..=40u32 {
                let top = LOWEST_OVER_N * f64::from(n) + 0.5;
                let found = disk.scan(n, 1e-3, top, 1).unwrap();
                if let Some(w) = found.first() {
                    assert!(
                        *w > LOWEST_OVER_N * f64::from(n),
                        "nu {nu}, n {n}: a frequency at {w}"
                    );
                }
            }
        }
    }

    /// J_0, J_1, J_5 at a few points against their tabulated values (Abramowitz and Stegun,
    /// table 9.1).
    #[test]
    fn bessel_j_matches_tables() {
        let cases = [
            (0, 1.0, 0.765_197_686_557_966_6),
            (1, 1.0, 0.440_050_585_744_933_5),
            (0, 10.0, -0.245_935_764_451_348_3),
            (1, 10.0, 0.043_472_746_168_861_44),
            (5, 10.0, -0.234_061_528_186_793_7),
        ];
        for (n, x, want) in cases {
            let (j, _) = bessel_j(n, x);
            assert!((j - want).abs() < 1e-14, "J_{n}({x}) = {j}, want {want}");
        }
        // x J_1'(x) = x J_0 - J_1
        let (j1, d1) = bessel_j(1, 10.0);
        let (j0, _) = bessel_j(0, 10.0);
        assert!((d1 - (10.0 * j0 - j1)).abs() < 1e-14);
    }

    /// The modified Bessel functions' log-derivative at small z, from their power series:
    /// n + z^2/(2 (n + 1)) - z^4/(8 (n + 1)^2 (n + 2)) + O(z^6) (z^6/96 = 1e-14 at z = 0.01); and at z = i t, where
    /// z I_n'(z)/I_n(z) = t J_n'(t)/J_n(t) (I_n(i t) = i^n J_n(t)), against Miller's J.
    #[test]
    fn log_derivative_small_argument_and_imaginary_axis() {
        for n in [0u32, 1, 3] {
            let z = 1e-2;
            let f = log_derivative_i(n, Complex64::new(z, 0.0)).unwrap();
            let m = f64::from(n);
            let want =
                m + z * z / (2.0 * (m + 1.0)) - z.powi(4) / (8.0 * (m + 1.0).powi(2) * (m + 2.0));
            assert!((f.re - want).abs() < 2e-14 && f.im == 0.0, "{n}: {f}");
            for t in [0.7, 3.0, 12.5] {
                let f = log_derivative_i(n, Complex64::new(0.0, t)).unwrap();
                let (j, d) = bessel_j(n, t);
                let want = d / j;
                assert!(
                    (f - want).norm() < 1e-12 * want.abs().max(1.0),
                    "{n} {t}: {f} vs {want}"
                );
            }
        }
    }
}
