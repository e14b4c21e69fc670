//! The striker's own surface influence function G0 of the contact equation (7)
//! (`docs/strikers.md`): rigid (G0 = 0), elastic in the local half-plane model, the full
//! elastic cylinder (the free disk's response), or a thin cylindrical shell (Timoshenko ring).
//!
//! The contact condition with a deformable striker reads w(x, t) + w_s(x, t) = h(t) - f(x) on
//! the contact, w the half-plane's normal displacement (into the half-plane) and w_s the
//! striker's surface displacement towards its own interior, both driven by the same contact
//! pressure; h is the approach of the striker's rigid-body reference (its mass centre), which
//! follows the equation of motion (5)/(8) as for the rigid striker. The striker's cell
//! coefficients are added to the half-plane's, so the march and its edge laws are unchanged.
//!
//! Units as in the march: c1 = 1 and mu = 1 of the half-plane, lengths in R.

pub mod cylinder;
pub mod disk;
pub mod green;

use cylinder::CylinderTable;

use std::f64::consts::PI;

use lamb::HalfPlane;

use crate::error::{invalid, ImpactError, Result};
use crate::tables::Tables;

/// An elastic striker's material (speeds over the half-plane's c1, density over the
/// half-plane's rho).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrikerMaterial {
    /// The striker's P-wave speed over the half-plane's c1.
    pub c1_ratio: f64,
    /// The striker's S-wave speed over the half-plane's c1.
    pub c2_ratio: f64,
    /// The striker's density over the half-plane's.
    pub density_ratio: f64,
}

impl StrikerMaterial {
    fn validate(&self) -> Result<()> {
        let c1 = self.c1_ratio;
        let c2 = self.c2_ratio;
        if !(c1.is_finite() && c1 > 0.0) {
            return Err(invalid(
                "striker c1 over the half-plane's c1",
                c1,
                "(0, inf)",
            ));
        }
        if !(c2.is_finite() && c2 > 0.0 && c2 < c1 * 0.75f64.sqrt()) {
            return Err(invalid(
                "striker c2 over the half-plane's c1",
                c2,
                format!(
                    "(0, {:.6}) (c2/c1 of the striker below sqrt(3)/2)",
                    c1 * 0.75f64.sqrt()
                ),
            ));
        }
        let d = self.density_ratio;
        if !(d.is_finite() && d > 0.0) {
            return Err(invalid("striker density ratio rho_s/rho", d, "(0, inf)"));
        }
        Ok(())
    }

    /// The striker's own half-plane (Lamb crate, its c1 = 1): refused, naming the striker's
    /// c2, at the one Poisson's ratio the Lamb crate excludes (0, c2s/c1s = 1/sqrt 2).
    fn half_plane(&self) -> Result<HalfPlane<f64>> {
        HalfPlane::new(self.c2_ratio / self.c1_ratio).map_err(|_| {
            invalid(
                "striker c2 over the half-plane's c1",
                self.c2_ratio,
                format!(
                    "(0, {:.6}) but not {:.6} (the striker's Poisson's ratio 0, c2s/c1s = \
                     1/sqrt 2, where a root of the Rayleigh cubic lies on the P front: move c2 \
                     by a part in a million)",
                    self.c1_ratio * 0.75f64.sqrt(),
                    self.c1_ratio * 0.5f64.sqrt()
                ),
            )
        })
    }

    /// The striker's Poisson's ratio.
    pub fn poisson(&self) -> f64 {
        lamb::poisson_of(&(self.c2_ratio / self.c1_ratio).powi(2))
    }

    /// The striker's shear modulus over the half-plane's: (rho_s/rho) (c2s/c2)^2, with
    /// m = c2/c1 of the half-plane.
    pub fn shear_modulus_ratio(&self, m: f64) -> f64 {
        self.density_ratio * (self.c2_ratio / m).powi(2)
    }
}

/// A thin cylindrical shell striker: mid-surface radius R (the unit of length, also the
/// contact profile's radius), wall thickness h_s, its material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShellStriker {
    /// h_s/R, in (0, 0.3].
    pub thickness: f64,
    /// The shell's material.
    pub material: StrikerMaterial,
}

impl ShellStriker {
    /// The shell's mass per unit length over rho R^2: 2 pi (h_s/R) (rho_s/rho).
    pub fn mass_ratio(&self) -> f64 {
        2.0 * PI * self.thickness * self.material.density_ratio
    }
}

/// The striker model.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum Striker {
    /// Absolutely rigid: G0 = 0.
    #[default]
    Rigid,
    /// Elastic, local model: near the contact the striker's surface responds as an elastic
    /// half-plane of its own material (the Lamb crate). Exact until waves reflected from the
    /// striker's far side return: c1 t/R < 2 c1/c1s for a striker of radius (depth 2) R.
    Elastic(StrikerMaterial),
    /// A thin cylindrical shell (Timoshenko ring: membrane, bending, transverse shear, rotary
    /// inertia), empty, valid for all times.
    Shell(ShellStriker),
    /// The full elastic cylinder of radius R (the unit of length) in plane strain: the free
    /// disk's own response ([`green`]), valid for all times; its mass pi R^2 rho_s.
    Cylinder(StrikerMaterial),
}

/// Transverse-shear coefficient of the shell's wall.
pub const SHEAR_COEFFICIENT: f64 = 5.0 / 6.0;

impl Striker {
    /// `rigid`, `elastic` or `shell`.
    pub fn name(&self) -> &'static str {
        match self {
            Striker::Rigid => "rigid",
            Striker::Elastic(_) => "elastic",
            Striker::Shell(_) => "shell",
            Striker::Cylinder(_) => "cylinder",
        }
    }

    /// The mass per unit length over rho R^2 that the striker's geometry fixes: 2 pi (h_s/R)
    /// (rho_s/rho) for the shell, pi rho_s/rho for the cylinder; `None` for the strikers whose
    /// mass is an input (rigid, local elastic model).
    pub fn own_mass_ratio(&self) -> Option<f64> {
        match self {
            Striker::Shell(s) => Some(s.mass_ratio()),
            Striker::Cylinder(mat) => Some(PI * mat.density_ratio),
            Striker::Rigid | Striker::Elastic(_) => None,
        }
    }

    /// Checks the parameters.
    pub fn validate(&self) -> Result<()> {
        match self {
            Striker::Rigid => Ok(()),
            Striker::Elastic(mat) | Striker::Cylinder(mat) => mat.validate(),
            Striker::Shell(s) => {
                s.material.validate()?;
                if !(s.thickness.is_finite() && s.thickness > 0.0 && s.thickness <= 0.3) {
                    return Err(invalid(
                        "shell thickness h_s/R",
                        s.thickness,
                        "(0, 0.3] (a thin shell)",
                    ));
                }
                Ok(())
            }
        }
    }

    /// The last time c1 t/R at which the model holds: 2 c1/c1s for the elastic striker's
    /// local half-plane model (the P wave's return from the far side of a striker of radius
    /// R), unbounded otherwise.
    pub fn validity_end(&self) -> f64 {
        match self {
            Striker::Elastic(mat) => 2.0 / mat.c1_ratio,
            _ => f64::INFINITY,
        }
    }

    /// Builds the striker's compliance for a grid of cell width `dx` and step `kappa dx`, on
    /// the half-plane of speed ratio `m` (its mu = 1), for the steps 0 .. `horizon` (the
    /// cylinder computes them at once). `None` for the rigid striker.
    pub(crate) fn compliance(
        &self,
        m: f64,
        dx: f64,
        kappa: f64,
        horizon: usize,
    ) -> Result<Option<Compliance>> {
        Ok(match self {
            Striker::Rigid => None,
            Striker::Elastic(mat) => {
                let hp = mat.half_plane()?;
                Some(Compliance::Elastic {
                    tables: Box::new(Tables::new(hp, kappa * mat.c1_ratio)?),
                    scale: 1.0 / mat.shear_modulus_ratio(m),
                    omitted: None,
                })
            }
            Striker::Shell(s) => Some(Compliance::Shell(ShellTable::new(
                Ring::new(s, m)?,
                dx,
                kappa * dx,
            )?)),
            Striker::Cylinder(mat) => Some(cylinder_compliance(mat, m, dx, kappa, horizon)?),
        })
    }
}

/// The largest share of a coefficient (mu/mu_s times twice the bound of the deformation
/// response over dx) that a stiff cylinder may leave out: below it the cylinder's table is its
/// local half-plane model's, with that bound in its error (`docs/strikers.md`, section 8).
pub const STIFF_OMISSION: f64 = 1e-4;

/// The cylinder's compliance: a stiff one's local half-plane tables with the bound of what
/// they leave out (the response beyond the local model, D, within twice the quasi-static
/// compliance plus the local response itself), when that bound is below [`STIFF_OMISSION`] at
/// the horizon; the free disk's lattice response otherwise.
fn cylinder_compliance(
    mat: &StrikerMaterial,
    m: f64,
    dx: f64,
    kappa: f64,
    horizon: usize,
) -> Result<Compliance> {
    cylinder::check_cell(dx)?;
    let scale = 1.0 / mat.shear_modulus_ratio(m);
    let quasi_static = disk::Disk::new(mat.poisson())?.inertia_relief_compliance(dx)?;
    let hp = mat.half_plane()?;
    // the local response's size at the horizon (the striker's units: c1s = 1, mu_s = 1)
    let t_end = (horizon.max(1) as f64 * kappa * dx) * mat.c1_ratio;
    let (local, local_err) = green::half_plane_strip(&hp, 0.5 * dx, 0.0, t_end)?;
    let estimate = scale * 2.0 * (2.0 * quasi_static + 2.0 * (local.abs() + local_err)) / dx;
    if estimate <= STIFF_OMISSION {
        return Ok(Compliance::Elastic {
            tables: Box::new(Tables::new(hp, kappa * mat.c1_ratio)?),
            scale,
            omitted: Some(Omitted { quasi_static, dx }),
        });
    }
    Ok(Compliance::Cylinder {
        table: CylinderTable::new(mat, dx, kappa * dx, horizon)?,
        scale,
    })
}

/// What a stiff cylinder's local tables leave out: its deformation response beyond the local
/// model, bounded by twice the quasi-static compliance `quasi_static` (units p0 R/mu_s, arcs
/// of width `dx`) plus the local response itself.
pub(crate) struct Omitted {
    quasi_static: f64,
    dx: f64,
}

/// The striker's cell coefficients, in the normalisation of [`Tables`]: the mean striker
/// displacement over receiver cell i at t_n due to a unit pressure on source cell j over
/// step m is dx c(|i - j|, n - m) (mu = 1 of the half-plane).
pub(crate) enum Compliance {
    /// The striker's own half-plane tables (its c1 = 1, mu = 1, kappa_s = kappa c1s/c1),
    /// times `scale` = mu/mu_s.
    Elastic {
        /// Tables in the striker's own units.
        tables: Box<Tables>,
        /// mu/mu_s.
        scale: f64,
        /// For a stiff cylinder, the bound of the response the local model leaves out.
        omitted: Option<Omitted>,
    },
    /// The shell's modal sums.
    Shell(ShellTable),
    /// The free disk's lattice response, times `scale` = mu/mu_s.
    Cylinder {
        /// The coefficients in the disk's units (mu_s = 1).
        table: CylinderTable,
        /// mu/mu_s.
        scale: f64,
    },
}

impl Compliance {
    /// Makes c(k, l) available for k <= kmax, l <= lmax.
    pub(crate) fn ensure(&mut self, kmax: usize, lmax: usize) -> Result<()> {
        match self {
            Compliance::Elastic { tables, .. } => tables.ensure(kmax, lmax),
            Compliance::Shell(t) => t.ensure(kmax, lmax),
            Compliance::Cylinder { table, .. } => table.ensure(kmax, lmax),
        }
    }

    /// A bound of a coefficient's error in the half-plane's normalisation (the tables' error
    /// estimate so far, or the shell's truncation bound).
    pub(crate) fn error(&self) -> f64 {
        match self {
            Compliance::Elastic {
                tables,
                scale,
                omitted,
            } => {
                let mut e = tables.error() * scale;
                if let Some(o) = omitted {
                    // |D| <= 2 quasi-static + |local|, the local step response from the rows
                    // computed (dx = 1 normalisation: S = dx sum_l a); a coefficient is a
                    // difference of two values of D, over dx
                    let width = (0..tables.rows()).map(|l| tables.row(l).len()).min();
                    let mut largest: f64 = 0.0;
                    if let Some(width) = width {
                        let mut sums = vec![0.0; width];
                        for l in 0..tables.rows() {
                            for (acc, a) in sums.iter_mut().zip(tables.row(l)) {
                                *acc += a;
                                largest = largest.max(acc.abs());
                            }
                        }
                    }
                    let bound = 2.0 * o.quasi_static + o.dx * largest;
                    e += scale * 2.0 * bound / o.dx;
                }
                e
            }
            Compliance::Shell(t) => t.error(),
            Compliance::Cylinder { table, scale } => table.error() * scale,
        }
    }

    /// The reach of the coefficients c(., l) (`Tables::reach_at`, the striker's own); `None`
    /// for the shell and the cylinder, whose modes respond everywhere at once.
    pub(crate) fn reach_at(&self, l: usize) -> Option<usize> {
        match self {
            Compliance::Elastic { tables, .. } => Some(tables.reach_at(l)),
            Compliance::Shell(_) | Compliance::Cylinder { .. } => None,
        }
    }

    /// The unscaled row c(., l) and its scale.
    pub(crate) fn row(&self, l: usize) -> (&[f64], f64) {
        match self {
            Compliance::Elastic { tables, scale, .. } => (tables.row(l), *scale),
            Compliance::Shell(t) => (t.row(l), 1.0),
            Compliance::Cylinder { table, scale } => (table.row(l), *scale),
        }
    }
}

/// The modes of one Fourier harmonic cos(n theta) of the ring's radial displacement: for each
/// mode with a non-zero frequency, (omega, phi_W^2) with phi mass-normalised.
#[derive(Clone, Debug)]
pub struct Harmonic {
    /// n.
    pub n: usize,
    /// (omega R/c1, phi_W^2 of the mass-normalised mode) for each elastic mode, ascending in
    /// omega (the rigid translation of n = 1 left out; n = 0 has the breathing mode alone,
    /// the torsional pair carries no radial load).
    pub modes: Vec<(f64, f64)>,
    /// The modal mass factor c_n = pi (n >= 1) or 2 pi (n = 0): a radial load q_n cos(n theta)
    /// has the generalised force c_n R q_n.
    pub c_n: f64,
}

/// The Timoshenko ring (`docs/strikers.md`, section 3), in the march's units.
#[derive(Clone, Debug)]
pub struct Ring {
    /// h_s/R.
    pub thickness: f64,
    /// Density (units mu/c1^2 of the half-plane).
    pub rho: f64,
    /// Plane-strain modulus E' = E/(1 - nu^2) = 4 rho c2s^2 (1 - c2s^2/c1s^2).
    pub e_plane: f64,
    /// Shear modulus G = rho c2s^2.
    pub shear: f64,
}

impl Ring {
    /// The ring of a shell striker on a half-plane of speed ratio m (rho = 1/m^2).
    pub fn new(s: &ShellStriker, m: f64) -> Result<Self> {
        Striker::Shell(*s).validate()?;
        let rho = s.material.density_ratio / (m * m);
        let c2 = s.material.c2_ratio;
        let ms2 = (c2 / s.material.c1_ratio).powi(2);
        Ok(Ring {
            thickness: s.thickness,
            rho,
            e_plane: 4.0 * rho * c2 * c2 * (1.0 - ms2),
            shear: rho * c2 * c2,
        })
    }

    /// Mass and stiffness matrices of harmonic n >= 1 in (W, V, Psi) for w = W cos n theta,
    /// v = V sin n theta, psi = Psi sin n theta (R = 1): M = pi rho diag(h, h, h^3/12);
    /// K from the membrane strain (W + n V), the bending strain n Psi and the shear strain
    /// Psi - n W - V.
    pub fn matrices(&self, n: usize) -> ([f64; 3], [[f64; 3]; 3]) {
        let h = self.thickness;
        let nf = n as f64;
        let a = PI * self.e_plane * h;
        let d = PI * self.e_plane * h * h * h / 12.0 * nf * nf;
        let s = PI * SHEAR_COEFFICIENT * self.shear * h;
        let g = [-nf, -1.0, 1.0];
        let mem = [1.0, nf, 0.0];
        let mut k = [[0.0; 3]; 3];
        for (i, row) in k.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = a * mem[i] * mem[j] + s * g[i] * g[j];
            }
        }
        k[2][2] += d;
        let mass = [
            PI * self.rho * h,
            PI * self.rho * h,
            PI * self.rho * h.powi(3) / 12.0,
        ];
        (mass, k)
    }

    /// The harmonics 0..=N kept for cells of width `dx`: N = 16/dx (each cell resolved 16
    /// times over), at least 64. The coefficient tables and the energy recursion use the same.
    pub fn harmonics(&self, dx: f64) -> Result<Vec<Harmonic>> {
        let nmax = ((16.0 / dx).ceil() as usize).max(64);
        (0..=nmax).map(|n| self.harmonic(n)).collect()
    }

    /// The modes of harmonic n (radial components only).
    pub fn harmonic(&self, n: usize) -> Result<Harmonic> {
        if n == 0 {
            // breathing: membrane alone, M = 2 pi rho h, K = 2 pi E' h
            let mass = 2.0 * PI * self.rho * self.thickness;
            let k = 2.0 * PI * self.e_plane * self.thickness;
            return Ok(Harmonic {
                n,
                modes: vec![((k / mass).sqrt(), 1.0 / mass)],
                c_n: 2.0 * PI,
            });
        }
        let (mass, k) = self.matrices(n);
        // symmetric form M^-1/2 K M^-1/2
        let sq: Vec<f64> = mass.iter().map(|v| v.sqrt()).collect();
        let mut a = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] = k[i][j] / (sq[i] * sq[j]);
            }
        }
        let (vals, vecs) = jacobi3(a);
        let top = vals.iter().fold(0.0f64, |x, v| x.max(v.abs()));
        let mut modes = Vec::with_capacity(3);
        for q in 0..3 {
            let lam = vals[q];
            if n == 1 && lam.abs() <= 1e-9 * top {
                continue; // the rigid translation: carried by the equation of motion
            }
            if !(lam > 0.0) {
                return Err(ImpactError::Step {
                    time: "0".into(),
                    reason: format!("the shell's harmonic {n} has a non-positive stiffness"),
                });
            }
            // mass-normalised phi = M^-1/2 y, y the unit eigenvector
            let phi_w = vecs[0][q] / sq[0];
            modes.push((lam.sqrt(), phi_w * phi_w));
        }
        if n == 1 && modes.len() != 2 {
            return Err(ImpactError::Step {
                time: "0".into(),
                reason: "the shell's rigid translation was not found among its n = 1 modes".into(),
            });
        }
        modes.sort_by(|x, y| x.0.total_cmp(&y.0));
        Ok(Harmonic { n, modes, c_n: PI })
    }
}

/// Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations: the eigenvalues
/// and the eigenvectors as the columns of the second array.
fn jacobi3(mut a: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..60 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        let diag = a[0][0].abs() + a[1][1].abs() + a[2][2].abs();
        if off <= 1e-300 || off <= 1e-18 * diag {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            // A <- J^T A J
            for row in a.iter_mut() {
                let (arp, arq) = (row[p], row[q]);
                row[p] = c * arp - s * arq;
                row[q] = s * arp + c * arq;
            }
            let (rp, rq) = (a[p], a[q]);
            for r in 0..3 {
                a[p][r] = c * rp[r] - s * rq[r];
                a[q][r] = s * rp[r] + c * rq[r];
            }
            for row in v.iter_mut() {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

/// sin(x)/x (its series below 1e-4).
pub(crate) fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// The shell's cell coefficients by modal superposition, truncated at harmonic N with the
/// tail bounded (`docs/strikers.md`, section 3).
///
/// With the arc length R theta taken for x along the contact (b << R), a unit pressure on the
/// cell |x| < dx/2 has the radial harmonics c_n q_n = dx sinc(n dx/2) (n >= 1; dx for n = 0),
/// and the mean inward displacement over the cell centred at k dx, t after the load is
/// switched on, is
/// S(k, t) = dx sum_n sinc^2(n dx/2) cos(n k dx) sum_modes phi_W^2 (1 - cos omega t)/omega^2;
/// the coefficient of a pressure held over one step is [S(k, t_{l+1}) - S(k, t_l)]/dx.
pub(crate) struct ShellTable {
    harmonics: Vec<Harmonic>,
    /// The frequencies of every mode, in the harmonics' order.
    omegas: Vec<f64>,
    dx: f64,
    dt: f64,
    /// cos(n k dx) sinc^2(n dx/2), [n][k], grown with k.
    space: Vec<Vec<f64>>,
    /// s[l][k] = S(k, t_l)/dx.
    s: Vec<Vec<f64>>,
    /// c[l][k].
    c: Vec<Vec<f64>>,
    /// Bound of the truncated tail of a coefficient.
    err: f64,
}

impl ShellTable {
    fn new(ring: Ring, dx: f64, dt: f64) -> Result<Self> {
        let harmonics = ring.harmonics(dx)?;
        let nmax = harmonics.len() - 1;
        // tail bound: beyond N each term is at most sinc^2 * 2 * sum phi^2/omega^2, with
        // sinc^2 <= (2/(n dx))^2 and the static compliance falling like n^-2
        let last = &harmonics[nmax];
        let comp: f64 = last.modes.iter().map(|(w, p)| p / (w * w)).sum();
        let c = comp * (nmax * nmax) as f64;
        let tail = 2.0 * 4.0 * c / (3.0 * (nmax as f64).powi(3) * dx * dx);
        let omegas = harmonics
            .iter()
            .flat_map(|h| h.modes.iter().map(|m| m.0))
            .collect();
        Ok(ShellTable {
            harmonics,
            omegas,
            dx,
            dt,
            space: Vec::new(),
            s: Vec::new(),
            c: Vec::new(),
            // a coefficient is a difference of two S values
            err: 4.0 * tail,
        })
    }

    /// The bound of a coefficient's truncation error.
    pub(crate) fn error(&self) -> f64 {
        self.err
    }

    /// The temporal factor sum_modes phi_W^2 (1 - cos omega t)/omega^2 of every harmonic at
    /// t, from the cosines `cosines` of the modes (in the harmonics' order).
    fn temporal(&self, cosines: &[f64]) -> Vec<f64> {
        let mut it = cosines.iter();
        self.harmonics
            .iter()
            .map(|h| {
                h.modes
                    .iter()
                    .map(|(w, p)| p * (1.0 - it.next().copied().unwrap_or(1.0)) / (w * w))
                    .sum::<f64>()
            })
            .collect()
    }

    /// Adds sum_n temporal_n space[n][k] for k in `cols` to `row`.
    fn fill(&self, temporal: &[f64], cols: std::ops::Range<usize>, row: &mut Vec<f64>) {
        let start = row.len();
        row.resize(start + cols.len(), 0.0);
        let out = &mut row[start..];
        for (tf, sp) in temporal.iter().zip(&self.space) {
            for (r, v) in out.iter_mut().zip(&sp[cols.clone()]) {
                *r += tf * v;
            }
        }
    }

    fn ensure(&mut self, kmax: usize, lmax: usize) -> Result<()> {
        let have_k = self.space.first().map(|r| r.len()).unwrap_or(0);
        // columns grow by doubling: each growth revisits every row
        let width = if kmax < have_k {
            have_k
        } else {
            (kmax + 1).max(2 * have_k).max(16)
        };
        if have_k < width {
            if self.space.is_empty() {
                self.space = vec![Vec::new(); self.harmonics.len()];
            }
            for (h, row) in self.harmonics.iter().zip(self.space.iter_mut()) {
                let nf = h.n as f64;
                let w = sinc(0.5 * nf * self.dx).powi(2);
                for k in row.len()..width {
                    row.push((nf * k as f64 * self.dx).cos() * w);
                }
            }
        }
        let omegas = &self.omegas;
        // new columns of the existing rows: the cosines by rotation, reset every 64 steps
        let old_rows = self.s.len();
        if have_k < width && old_rows > 0 {
            let rot: Vec<(f64, f64)> = omegas
                .iter()
                .map(|w| ((w * self.dt).cos(), (w * self.dt).sin()))
                .collect();
            let mut z: Vec<(f64, f64)> = vec![(1.0, 0.0); omegas.len()];
            for l in 0..old_rows {
                if l % 64 == 0 {
                    let t = l as f64 * self.dt;
                    for (zi, w) in z.iter_mut().zip(omegas) {
                        *zi = ((w * t).cos(), (w * t).sin());
                    }
                } else {
                    for (zi, r) in z.iter_mut().zip(&rot) {
                        *zi = (zi.0 * r.0 - zi.1 * r.1, zi.0 * r.1 + zi.1 * r.0);
                    }
                }
                let cosines: Vec<f64> = z.iter().map(|v| v.0).collect();
                let temporal = self.temporal(&cosines);
                let mut row = std::mem::take(&mut self.s[l]);
                let from = row.len();
                self.fill(&temporal, from..width, &mut row);
                self.s[l] = row;
            }
        }
        // new rows: S at t_0 .. t_{lmax + 1}
        for l in old_rows..lmax + 2 {
            let t = l as f64 * self.dt;
            let cosines: Vec<f64> = omegas.iter().map(|w| (w * t).cos()).collect();
            let temporal = self.temporal(&cosines);
            let mut row = Vec::with_capacity(width);
            self.fill(&temporal, 0..width, &mut row);
            self.s.push(row);
        }
        while self.c.len() < lmax + 1 {
            self.c.push(Vec::new());
        }
        for l in 0..self.c.len() {
            let have = self.c[l].len();
            for k in have..width {
                let v = self.s[l + 1][k] - self.s[l][k];
                if !v.is_finite() {
                    return Err(ImpactError::Step {
                        time: format!("{:.6}", l as f64 * self.dt),
                        reason: "a non-finite shell coefficient".into(),
                    });
                }
                self.c[l].push(v);
            }
        }
        Ok(())
    }

    fn row(&self, l: usize) -> &[f64] {
        &self.c[l]
    }
}

/// One step of the oscillator y'' + w^2 (y - ye) = 0 (its equilibrium ye constant over the
/// step) from (y, y'), exactly, with c = cos(w dt) and s = sin(w dt): the modal recursion
/// of the shell's and the cylinder's energies.
pub(crate) fn oscillator_step(y: f64, v: f64, ye: f64, w: f64, c: f64, s: f64) -> (f64, f64) {
    (ye + (y - ye) * c + v / w * s, -(y - ye) * w * s + v * c)
}

/// The shell's strain and vibration kinetic energy after each step of a pressure history,
/// by an exact modal recursion (each mode a harmonic oscillator under a force constant over
/// the step), independent of the coefficient tables: `pressures[n][j]` is the pressure on
/// cell j (j > 0 standing for the cell and its mirror) over step n + 1. Returns (strain,
/// kinetic) per step, units mu R^2 of the half-plane.
pub fn shell_energies(
    ring: &Ring,
    dx: f64,
    dt: f64,
    pressures: &[Vec<f64>],
) -> Result<Vec<(f64, f64)>> {
    let harmonics = ring.harmonics(dx)?;
    // modal coordinates (q, qdot) per harmonic and mode
    let mut state: Vec<Vec<(f64, f64)>> = harmonics
        .iter()
        .map(|h| vec![(0.0, 0.0); h.modes.len()])
        .collect();
    let mut out = Vec::with_capacity(pressures.len());
    for p in pressures {
        let (mut strain, mut kinetic) = (0.0, 0.0);
        for (h, st) in harmonics.iter().zip(state.iter_mut()) {
            let nf = h.n as f64;
            // generalised radial force of the step's pressure (inward): the mode's coordinate
            // sees phi_W times it with the sign of an inward load on an outward W
            let sc = sinc(0.5 * nf * dx);
            let mut force = 0.0;
            for (j, pj) in p.iter().enumerate() {
                let weight = if j == 0 { dx } else { 2.0 * dx };
                force += weight * pj * (nf * j as f64 * dx).cos() * sc;
            }
            for ((w, phi2), (q, v)) in h.modes.iter().zip(st.iter_mut()) {
                // the mode's force: phi_W (-force); with phi_W^2 only the product q phi_W
                // matters, so carry the coordinate scaled by phi_W: f = -phi_W^2 force
                let f = -phi2 * force;
                let (c, s) = ((w * dt).cos(), (w * dt).sin());
                let (q1, v1) = oscillator_step(*q, *v, f / (w * w), *w, c, s);
                *q = q1;
                *v = v1;
                // energies of the true coordinate (scaled by 1/phi_W^2 in squares)
                if *phi2 > 0.0 {
                    strain += 0.5 * w * w * q1 * q1 / phi2;
                    kinetic += 0.5 * v1 * v1 / phi2;
                }
            }
        }
        out.push((strain, kinetic));
    }
    Ok(out)
}
