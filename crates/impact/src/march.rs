//! Time marching of the contact integral equation on one uniform grid (`docs/impact.md`,
//! sections 2-4): eq (7) imposed on the cell means at the end of each step (the striker's G0
//! added to the half-plane's coefficients, `docs/strikers.md`),
//! the striker's equation of motion (5)/(8) integrated exactly for a force constant over the
//! step, the contact set from the edge law.
//!
//! Units inside: c1 = 1, mu = 1, lengths in R (so rho = 1/m^2, m = c2/c1).

use crate::error::{ImpactError, Result};
use crate::profile::Profile;
use crate::striker::Compliance;
use crate::tables::Tables;

/// How the penetration evolves.
#[derive(Clone, Debug)]
pub enum Motion {
    /// A free rigid striker: mass per unit length m0 (units rho R^2 = R^2/m^2 here) and
    /// initial speed v0 (units c1).
    Free {
        /// m0 in units mu R^2/c1^2.
        mass: f64,
        /// Initial speed over c1.
        v0: f64,
    },
    /// Penetration prescribed at constant speed (units c1).
    DrivenSpeed(f64),
    /// Penetration prescribed by a table (c1 t/R, h/R), linear between points, h(0) = 0.
    DrivenTable(Vec<(f64, f64)>),
}

impl Motion {
    fn driven_h(&self, t: f64) -> Option<f64> {
        match self {
            Motion::Free { .. } => None,
            Motion::DrivenSpeed(v) => Some(v * t),
            Motion::DrivenTable(tab) => {
                let i = tab.partition_point(|p| p.0 <= t).clamp(1, tab.len() - 1);
                let (a, b) = (tab[i - 1], tab[i]);
                Some(a.1 + (b.1 - a.1) * (t - a.0) / (b.0 - a.0))
            }
        }
    }
}

/// The edge law (labelled in every output); shared with the edge analysis of `lamb::edge`.
pub use lamb::edge::EdgeLaw;

/// One time step's solution.
#[derive(Clone, Debug)]
pub struct StepState {
    /// Time t_n (units R/c1).
    pub t: f64,
    /// Penetration h(t_n) (units R).
    pub h: f64,
    /// dh/dt (units c1).
    pub v: f64,
    /// Number of contact cells on one side minus one: cells 0..=k carry pressure (none when
    /// `pressure` is empty).
    pub k: usize,
    /// Contact half-width estimate (units R): the zero of a square-root fit through the
    /// last two cell pressures for the Signorini law, f^-1(h) for the kinematic law.
    pub b: f64,
    /// Force per unit length R(t) (units mu R).
    pub force: f64,
    /// Cell pressures p_0..p_k (units mu), constant over the step.
    pub pressure: Vec<f64>,
    /// The half-plane's mean normal surface displacement over the cells at x_0, x_1, ... at
    /// t_n (units R), at least over the contact and one cell beyond.
    pub w: Vec<f64>,
    /// The striker's mean surface displacement towards its interior over the same cells
    /// (empty for a rigid striker).
    pub ws: Vec<f64>,
    /// Work done on the half-plane up to t_n, through the kernels (units mu R^2).
    pub work: f64,
    /// Work done on the striker's deformation up to t_n (its strain and vibration energy).
    pub striker_work: f64,
}

/// The marching state on one grid.
pub struct March<'a> {
    tables: &'a mut Tables,
    striker: Option<&'a mut Compliance>,
    profile: &'a Profile,
    motion: &'a Motion,
    law: EdgeLaw,
    dx: f64,
    dt: f64,
    /// Largest admissible contact index (the profile's extent).
    kcap: usize,
    /// The steps so far.
    pub steps: Vec<StepState>,
    /// Time of separation (free striker), if it happened.
    pub separation: Option<f64>,
}

fn solve_dense(mut a: Vec<f64>, mut r: Vec<f64>, n: usize) -> Option<Vec<f64>> {
    for c in 0..n {
        let mut piv = c;
        for i in c + 1..n {
            if a[i * n + c].abs() > a[piv * n + c].abs() {
                piv = i;
            }
        }
        if !(a[piv * n + c].abs() > 0.0) {
            return None;
        }
        if piv != c {
            for j in 0..n {
                a.swap(c * n + j, piv * n + j);
            }
            r.swap(c, piv);
        }
        let d = a[c * n + c];
        for i in c + 1..n {
            let f = a[i * n + c] / d;
            if f != 0.0 {
                for j in c..n {
                    a[i * n + j] -= f * a[c * n + j];
                }
                r[i] -= f * r[c];
            }
        }
    }
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let mut s = r[i];
        for j in i + 1..n {
            s -= a[i * n + j] * x[j];
        }
        x[i] = s / a[i * n + i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

impl<'a> March<'a> {
    /// A march with cell width dx and time step kappa dx (kappa from the tables), with the
    /// striker's compliance (none for a rigid striker).
    pub(crate) fn new(
        tables: &'a mut Tables,
        striker: Option<&'a mut Compliance>,
        profile: &'a Profile,
        motion: &'a Motion,
        law: EdgeLaw,
        dx: f64,
        kappa: f64,
    ) -> Self {
        let ext = profile.extent();
        let kcap = if ext.is_finite() {
            ((ext / dx - 0.5).floor().max(0.0)) as usize
        } else {
            usize::MAX / 4
        };
        March {
            tables,
            striker,
            profile,
            motion,
            law,
            dx,
            dt: kappa * dx,
            kcap,
            steps: Vec::new(),
            separation: None,
        }
    }

    /// Time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    fn weight(&self, j: usize) -> f64 {
        if j == 0 {
            self.dx
        } else {
            2.0 * self.dx
        }
    }

    /// Displacements at t_n (n = steps.len() + 1) at x_0..x_imax due to all past steps: the
    /// half-plane's and the striker's (empty for a rigid striker).
    fn history(&mut self, n: usize, imax: usize) -> Result<(Vec<f64>, Vec<f64>)> {
        let kmax = self.steps.iter().map(|s| s.k).max().unwrap_or(0).max(imax);
        self.tables.ensure(2 * kmax + 2, n)?;
        if let Some(s) = self.striker.as_deref_mut() {
            s.ensure(2 * kmax + 2, n)?;
        }
        let add = |row: &[f64], scale: f64, p: &[f64], hist: &mut [f64]| {
            for (j, &pj) in p.iter().enumerate() {
                let pj = pj * scale;
                if j == 0 {
                    for (i, hv) in hist.iter_mut().enumerate() {
                        *hv += row[i] * pj;
                    }
                } else {
                    for (i, hv) in hist.iter_mut().enumerate() {
                        *hv += (row[i.abs_diff(j)] + row[i + j]) * pj;
                    }
                }
            }
        };
        let mut hist = vec![0.0; imax + 1];
        let mut hist_s = if self.striker.is_some() {
            vec![0.0; imax + 1]
        } else {
            Vec::new()
        };
        for (mi, st) in self.steps.iter().enumerate() {
            if st.pressure.is_empty() {
                continue;
            }
            let l = n - (mi + 1);
            add(self.tables.row(l), self.dx, &st.pressure, &mut hist);
            if let Some(s) = self.striker.as_deref() {
                let (row, scale) = s.row(l);
                add(row, self.dx * scale, &st.pressure, &mut hist_s);
            }
        }
        Ok((hist, hist_s))
    }

    /// The current step's coefficient of the half-plane and of the striker.
    fn current_parts(&self, i: usize, j: usize) -> (f64, f64) {
        let pair = |row: &[f64]| row[i.abs_diff(j)] + if j > 0 { row[i + j] } else { 0.0 };
        let hp = pair(self.tables.row(0)) * self.dx;
        let st = match self.striker.as_deref() {
            Some(s) => {
                let (row, scale) = s.row(0);
                pair(row) * scale * self.dx
            }
            None => 0.0,
        };
        (hp, st)
    }

    fn current(&self, i: usize, j: usize) -> f64 {
        let (a, b) = self.current_parts(i, j);
        a + b
    }

    /// Solves the step with contact cells 0..=k: returns (pressures, force).
    fn solve_set(
        &self,
        k: usize,
        hist: &(Vec<f64>, Vec<f64>),
        h_pred: f64,
        coupling: f64,
        time: f64,
    ) -> Result<(Vec<f64>, f64)> {
        let n = k + 1;
        let mut a = vec![0.0; n * n];
        let mut r = vec![0.0; n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] = self.current(i, j) + coupling * self.weight(j);
            }
            let f = self
                .profile
                .height(i as f64 * self.dx)
                .ok_or_else(|| ImpactError::Step {
                    time: format!("{time:.6}"),
                    reason: "the contact reaches the end of the profile".into(),
                })?;
            r[i] = h_pred - f - hist.0[i] - hist.1.get(i).copied().unwrap_or(0.0);
        }
        let p = solve_dense(a, r, n).ok_or_else(|| ImpactError::Step {
            time: format!("{time:.6}"),
            reason: "singular contact system".into(),
        })?;
        let force = p.iter().enumerate().map(|(j, v)| self.weight(j) * v).sum();
        Ok((p, force))
    }

    /// The half-plane's and the striker's displacement at x_i at t_n from the histories and
    /// the current pressures (the striker's 0 when rigid).
    fn displacements(&self, i: usize, hist: &(Vec<f64>, Vec<f64>), p: &[f64]) -> (f64, f64) {
        let (mut a, mut b) = (hist.0[i], hist.1.get(i).copied().unwrap_or(0.0));
        for (j, v) in p.iter().enumerate() {
            let (ca, cb) = self.current_parts(i, j);
            a += ca * v;
            b += cb * v;
        }
        (a, b)
    }

    /// The total approach w + w_s at x_i at t_n.
    fn displacement(&self, i: usize, hist: &(Vec<f64>, Vec<f64>), p: &[f64]) -> f64 {
        let (a, b) = self.displacements(i, hist, p);
        a + b
    }

    /// Advances one step. Returns false when the striker has separated (free motion) and
    /// the march is over.
    pub fn step(&mut self) -> Result<bool> {
        let n = self.steps.len() + 1;
        let t = n as f64 * self.dt;
        let dt = self.dt;
        let (h0, v0, k0) = match self.steps.last() {
            Some(s) => (s.h, s.v, s.k),
            None => match self.motion {
                Motion::Free { v0, .. } => (0.0, *v0, 0),
                _ => (0.0, 0.0, 0),
            },
        };
        let (h_pred, coupling, mass) = match (self.motion.driven_h(t), self.motion) {
            (Some(h), _) => (h, 0.0, f64::INFINITY),
            (None, Motion::Free { mass, .. }) => (h0 + dt * v0, dt * dt / (2.0 * mass), *mass),
            _ => unreachable!("a driven motion always gives h"),
        };
        let profile = self.profile;
        let kin = move |h: f64| profile.kinematic_edge(h);
        let kin_b = kin(h_pred).ok_or_else(|| ImpactError::Step {
            time: format!("{t:.6}"),
            reason: "the penetration exceeds the profile's extent".into(),
        })?;
        let dxv = self.dx;
        let kin_k = move |b: f64| -> usize { ((b / dxv).ceil() as usize).saturating_sub(1) };
        let imax = (k0 + 3).max(kin_k(kin_b) + 3).min(self.kcap + 2);
        let hist = self.history(n, imax)?;
        let mut set = None;
        match self.law {
            EdgeLaw::Kinematic => {
                let mut f_est = 0.0;
                for _ in 0..50 {
                    let h = h_pred - coupling * f_est;
                    let b = kin(h).unwrap_or(0.0);
                    if b <= 0.0 {
                        break;
                    }
                    let k = kin_k(b).min(self.kcap);
                    let (p, f) = self.solve_set(k, &hist, h_pred, coupling, t)?;
                    let done = (f - f_est).abs() <= 1e-14 * f.abs();
                    f_est = f;
                    set = Some((k, b, p, f));
                    if done {
                        break;
                    }
                }
            }
            EdgeLaw::Signorini => {
                // active set of whole cells 0..=k, started from the previous step's
                let mut k = k0.min(self.kcap);
                let mut tried = vec![false; self.kcap.min(imax) + 2];
                loop {
                    tried[k] = true;
                    let (p, f) = self.solve_set(k, &hist, h_pred, coupling, t)?;
                    if p[k] < 0.0 {
                        if k == 0 {
                            break; // no contact at all
                        }
                        if !tried[k - 1] {
                            k -= 1;
                            continue;
                        }
                    }
                    let i = k + 1;
                    if i <= imax.min(self.kcap) {
                        let gap = self.displacement(i, &hist, &p)
                            - (h_pred
                                - coupling * f
                                - self
                                    .profile
                                    .height(i as f64 * self.dx)
                                    .unwrap_or(f64::INFINITY));
                        if gap < 0.0 && !tried[i] {
                            k = i;
                            continue;
                        }
                    }
                    let b = self.edge_fit(k, &p);
                    set = Some((k, b, p, f));
                    break;
                }
            }
        }
        let (k, b, p, f) = match set {
            Some(s) => s,
            None => {
                // no contact: the striker has left the surface (or never touched it)
                if let Motion::Free { .. } = self.motion {
                    if v0 < 0.0 || n > 1 {
                        self.separation = Some(t - dt);
                        return Ok(false);
                    }
                }
                (0, 0.0, Vec::new(), 0.0)
            }
        };
        let (h, v) = match self.motion.driven_h(t) {
            Some(h) => {
                let hp = self.motion.driven_h(t - dt).unwrap_or(0.0);
                (h, (h - hp) / dt)
            }
            None => (
                h0 + dt * v0 - dt * dt * f / (2.0 * mass),
                v0 - dt * f / mass,
            ),
        };
        let (w, ws): (Vec<f64>, Vec<f64>) =
            (0..=imax).map(|i| self.displacements(i, &hist, &p)).unzip();
        let ws = if self.striker.is_some() {
            ws
        } else {
            Vec::new()
        };
        let prev = self.steps.last();
        let prev_w = prev.map(|s| s.w.as_slice()).unwrap_or(&[]);
        let prev_ws = prev.map(|s| s.ws.as_slice()).unwrap_or(&[]);
        let (mut dwork, mut dwork_s) = (0.0, 0.0);
        for (j, pj) in p.iter().enumerate() {
            let before = prev_w.get(j).copied().unwrap_or(0.0);
            dwork += self.weight(j) * pj * (w[j] - before);
            if let Some(now) = ws.get(j) {
                let before = prev_ws.get(j).copied().unwrap_or(0.0);
                dwork_s += self.weight(j) * pj * (now - before);
            }
        }
        let work = prev.map(|s| s.work).unwrap_or(0.0) + dwork;
        let striker_work = prev.map(|s| s.striker_work).unwrap_or(0.0) + dwork_s;
        if !(h.is_finite() && v.is_finite() && f.is_finite()) {
            return Err(ImpactError::Step {
                time: format!("{t:.6}"),
                reason: "a non-finite penetration or force".into(),
            });
        }
        self.steps.push(StepState {
            t,
            h,
            v,
            k,
            b,
            force: f,
            pressure: p,
            w,
            ws,
            work,
            striker_work,
        });
        Ok(true)
    }

    /// The Signorini edge inside the last cell: the zero of C (b - x)^(1/2) through the last
    /// two cell pressures, kept within the last cell.
    fn edge_fit(&self, k: usize, p: &[f64]) -> f64 {
        let dx = self.dx;
        let xk = k as f64 * dx;
        if k == 0 || p.len() < 2 {
            return xk + 0.5 * dx;
        }
        let (a, c) = (p[k - 1].max(0.0).powi(2), p[k].max(0.0).powi(2));
        let b = if a > c {
            (xk * a - (xk - dx) * c) / (a - c)
        } else {
            xk + 0.5 * dx
        };
        b.clamp(xk, xk + dx)
    }
}
