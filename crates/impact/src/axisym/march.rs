//! One grid level of the axisymmetric march (`docs/axisymmetric.md`, section 3): rings of
//! width dr, steps of dt = kappa dr/c1, the pressure constant on each ring over each step,
//! the contact condition on each contact ring's mean displacement at the end of each step.

use std::cell::RefCell;
use std::collections::hash_map::Entry;
use std::collections::HashMap;

use super::profile::AxiProfile;
use super::tables::{ring_area_over_pi, RingTables};
use crate::case::Drive;
use crate::error::{ImpactError, Result};
use crate::linalg::{least_index_pivoting, Factor};
use crate::march::EdgeLaw;

/// The state at the end of one step (units c1 = mu = 1, lengths in R).
#[derive(Clone, Debug)]
pub struct AxiStep {
    /// c1 t/R at the end of the step.
    pub t: f64,
    /// The penetration h/R at t.
    pub h: f64,
    /// dh/dt over c1 at t.
    pub v: f64,
    /// The force over mu R^2, constant over the step (it stands for the step's middle).
    pub force: f64,
    /// The contact radius a/R at t (geometric under the kinematic law; the zero of the
    /// square-root fit through the last two ring pressures under Signorini's).
    pub a: f64,
    /// The work done on the half-space up to t over mu R^3 (through the ring means).
    pub work: f64,
    /// The energy the quasi-static (Boussinesq) field of the step's pressures would store,
    /// (1/2) sum_i A_i p_i (S p)_i, over mu R^3.
    pub quasi_static: f64,
    /// The ring pressures over mu (rings 0.. in contact).
    pub pressure: Vec<f64>,
}

/// One level's march.
pub(crate) struct AxiMarch<'a> {
    pub(crate) dr: f64,
    pub(crate) dt: f64,
    profile: &'a AxiProfile,
    drive: &'a Drive,
    law: EdgeLaw,
    /// The striker's mass over rho R^3 times rho = mass/m^2 (mu R^3/c1^2 units); None when
    /// driven.
    mass: Option<f64>,
    tables: &'a RingTables,
    /// Ring areas over R^2.
    area: Vec<f64>,
    /// The profile's ring means (None: no striker surface over the ring).
    fbar: Vec<Option<f64>>,
    /// The kept factorisations of the disks 0..c - 1, by c.
    factors: RefCell<HashMap<usize, Factor>>,
    pub(crate) steps: Vec<AxiStep>,
    /// The mean displacements of the last step, rings 0..len.
    last_w: Vec<f64>,
    /// Times c1 t/R at which a contact ended.
    pub(crate) separations: Vec<f64>,
    /// Contacts begun after a separation.
    pub(crate) reimpacts: usize,
}

/// How many rings beyond the geometric contact the march keeps evaluated.
const MARGIN_RINGS: usize = 3;

impl<'a> AxiMarch<'a> {
    pub(crate) fn new(
        dr: f64,
        tables: &'a RingTables,
        profile: &'a AxiProfile,
        drive: &'a Drive,
        law: EdgeLaw,
        m: f64,
    ) -> Self {
        let n = tables.rings();
        let area: Vec<f64> = (0..n)
            .map(|i| std::f64::consts::PI * ring_area_over_pi(i) * dr * dr)
            .collect();
        let fbar = (0..n)
            .map(|i| {
                let r1 = if i == 0 { 0.0 } else { (i as f64 - 0.5) * dr };
                profile.ring_mean(r1, (i as f64 + 0.5) * dr)
            })
            .collect();
        AxiMarch {
            dr,
            dt: tables.kappa() * dr,
            profile,
            drive,
            law,
            mass: drive.mass(m),
            tables,
            area,
            fbar,
            factors: RefCell::new(HashMap::new()),
            steps: Vec::new(),
            last_w: Vec::new(),
            separations: Vec::new(),
            reimpacts: 0,
        }
    }

    /// The rings the table covers.
    fn rings(&self) -> usize {
        self.tables.rings()
    }

    /// The ring pressures of step `n` (1-based; empty before the first).
    fn pressure(&self, n: usize) -> &[f64] {
        if n == 0 {
            &[]
        } else {
            &self.steps[n - 1].pressure
        }
    }

    /// The displacement at the end of step n (1-based) over rings 0..k due to the steps
    /// before n.
    fn history(&self, n: usize, k: usize) -> Vec<f64> {
        let nr = self.rings();
        let mut h = vec![0.0; k];
        for l in 1..self.tables.max_lags().min(n) {
            let p = self.pressure(n - l);
            if p.is_empty() {
                continue;
            }
            let Some(block) = self.tables.block(l) else {
                break;
            };
            for (i, hi) in h.iter_mut().enumerate() {
                let row = &block[i * nr..i * nr + p.len()];
                *hi += row.iter().zip(p).map(|(c, q)| c * q).sum::<f64>();
            }
        }
        for hi in &mut h {
            *hi *= self.dr;
        }
        h
    }

    /// The current step's contribution to ring i's displacement.
    fn current(&self, i: usize, p: &[f64]) -> f64 {
        let nr = self.rings();
        let block = self.tables.block(0).unwrap_or(&[]);
        let row = &block[i * nr..i * nr + p.len()];
        self.dr * row.iter().zip(p).map(|(c, q)| c * q).sum::<f64>()
    }

    /// The step's contact system on the rings `rings` (ascending), M = dr C + gamma 1 A^T
    /// (C the current step's ring coefficients, A the rings' areas).
    fn factor(&self, rings: &[usize], t: f64) -> Result<Factor> {
        let gamma = self.mass.map_or(0.0, |m| self.dt * self.dt / (2.0 * m));
        let nr = self.rings();
        let block = self.tables.block(0).unwrap_or(&[]);
        let dr = self.dr;
        Factor::new(
            rings.len(),
            None,
            |i, j| dr * block[rings[i] * nr + rings[j]],
            gamma,
            rings.iter().map(|&j| self.area[j]).collect(),
        )
        .ok_or_else(|| ImpactError::Step {
            time: format!("{t:.6}"),
            reason: format!("the contact system of {} rings is singular", rings.len()),
        })
    }

    /// Solves the step with the contact rings `rings` (ascending) for the right-hand side
    /// `rhs` (one entry a contact ring): the pressures up to the last contact ring (zeros
    /// off the contact) and the force. A disk 0..c - 1 takes the kept factorisation; any
    /// other set is factorised here.
    fn solve_rings(&self, rings: &[usize], rhs: &[f64], t: f64) -> Result<(Vec<f64>, f64)> {
        let Some(&last) = rings.last() else {
            return Ok((Vec::new(), 0.0));
        };
        let disk = rings.len() == last + 1;
        let fresh;
        let mut kept = self.factors.borrow_mut();
        let f: &Factor = if disk {
            match kept.entry(rings.len()) {
                Entry::Occupied(e) => e.into_mut(),
                Entry::Vacant(e) => e.insert(self.factor(rings, t)?),
            }
        } else {
            fresh = self.factor(rings, t)?;
            &fresh
        };
        let pc = f.solve(rhs).ok_or_else(|| ImpactError::Step {
            time: format!("{t:.6}"),
            reason: "the contact system's solution is not finite".into(),
        })?;
        let mut p = vec![0.0; last + 1];
        for (&i, &v) in rings.iter().zip(&pc) {
            p[i] = v;
        }
        let force = p.iter().zip(&self.area).map(|(q, a)| q * a).sum();
        Ok((p, force))
    }

    /// The penetration at the end of the step for the step's force: the predicted one less
    /// the force's dt^2 F/(2 m) (free), or the prescribed one (driven).
    fn penetration(&self, h_pred: f64, force: f64) -> f64 {
        match self.mass {
            Some(m) => h_pred - self.dt * self.dt * force / (2.0 * m),
            None => h_pred,
        }
    }

    /// Marches one step.
    pub(crate) fn step(&mut self) -> Result<()> {
        let n = self.steps.len() + 1;
        let t = n as f64 * self.dt;
        let (h0, v0) = match self.steps.last() {
            Some(s) => (s.h, s.v),
            None => (0.0, self.initial_speed()),
        };
        // the penetration before the step's force, and the driven one
        let h_pred = match self.drive.driven_h(t) {
            Some(h) => h,
            None => h0 + self.dt * v0,
        };
        let nr = self.rings();
        let reach = self.profile.contact_radius(h_pred.max(h0));
        let prev_c = self.steps.last().map_or(0, |s| s.pressure.len());
        let geometric = (((reach / self.dr) + 0.5).ceil() as usize + MARGIN_RINGS)
            .max(2)
            .max(prev_c + MARGIN_RINGS);
        // the kinematic contact is the geometric one; Signorini's lies well inside it (the
        // geometric radius is 2^(1/2) Hertz's for the paraboloid, pi/2 Sneddon's for the
        // cone), so it may take fewer rings than that, as long as it keeps MARGIN_RINGS
        // evaluated rings beyond its last one (checked below)
        let k = match self.law {
            EdgeLaw::Signorini => geometric.min(nr),
            EdgeLaw::Kinematic => geometric,
        };
        let outgrown = || ImpactError::Grid {
            name: "dr",
            reason: format!(
                "the contact reached the {nr} rings the march was sized for at c1 t/R = {t:.4}"
            ),
        };
        if k > nr || prev_c + MARGIN_RINGS > k {
            return Err(outgrown());
        }
        let mut k = k;
        let mut hist = self.history(n, k);
        let dt = self.dt;
        let rings_of = |k: usize| self.fbar.iter().take_while(|f| f.is_some()).count().min(k);
        let mut max_rings = rings_of(k);
        let (p, force) = match self.law {
            EdgeLaw::Kinematic => {
                // the geometric contact for the step's own penetration (a fixed point: the
                // force lowers h): the rings inside it whole, the ring holding the edge tied
                // to its neighbour by the local behaviour of the pressure at the edge
                let speed = self.edge_speed(h_pred);
                let lambda = self.edge_exponent(speed)?;
                let mut h = h_pred;
                let mut sol = (Vec::new(), 0.0);
                for _ in 0..8 {
                    let a = self.profile.contact_radius(h);
                    sol = self.kinematic_solve(a, lambda, max_rings, &hist, h_pred, t)?;
                    // the step's system holds the force's coupling exactly; h moves the edge
                    // only by dt^2 F/(2 m) a step, which changes the tie's ratio negligibly
                    // unless the edge changes ring: iterate until it stays in its ring
                    let h2 = self.penetration(h_pred, sol.1);
                    let same_ring = rings_within(self.profile.contact_radius(h2), self.dr)
                        == rings_within(a, self.dr);
                    h = h2;
                    if same_ring {
                        break;
                    }
                }
                sol
            }
            EdgeLaw::Signorini => loop {
                // a contact that reaches the evaluated rings' last MARGIN_RINGS may go on
                // beyond them (rings the conditions did not see could interpenetrate): the
                // rings widen, up to those the march was sized for, and the contact is found
                // again
                let sol = self.active_set(prev_c, max_rings, &hist, h_pred, t)?;
                if sol.0.len() + MARGIN_RINGS > k && max_rings == k && k < nr {
                    k = (k + 2 * MARGIN_RINGS).min(nr);
                    hist = self.history(n, k);
                    max_rings = rings_of(k);
                    continue;
                }
                break sol;
            },
        };
        if p.len() + MARGIN_RINGS > k && max_rings == k {
            return Err(outgrown());
        }
        let h = self.penetration(h_pred, force);
        let v = match (self.mass, self.drive.driven_h(t)) {
            (Some(m), _) => v0 - dt * force / m,
            (None, Some(_)) => (h - h0) / dt,
            (None, None) => v0,
        };
        // mean displacements at the end of the step, the work through them
        let w: Vec<f64> = (0..k).map(|i| hist[i] + self.current(i, &p)).collect();
        let mut work = self.steps.last().map_or(0.0, |s| s.work);
        for (j, q) in p.iter().enumerate() {
            let before = match self.last_w.get(j) {
                Some(&x) => x,
                None => self.history(n - 1, j + 1)[j] + self.previous_current(n, j),
            };
            work += q * self.area[j] * (w[j] - before);
        }
        let mut quasi_static = 0.0;
        for (i, qi) in p.iter().enumerate() {
            let sp: f64 = p
                .iter()
                .enumerate()
                .map(|(j, qj)| self.tables.static_at(i, j) * qj)
                .sum();
            quasi_static += 0.5 * self.area[i] * qi * sp * self.dr;
        }
        let a = self.report_radius(&p, h);
        if p.is_empty() && prev_c > 0 {
            self.separations.push(t);
        }
        if !p.is_empty() && prev_c == 0 && !self.separations.is_empty() {
            self.reimpacts += 1;
        }
        self.last_w = w;
        self.steps.push(AxiStep {
            t,
            h,
            v,
            force,
            a,
            work,
            quasi_static,
            pressure: p,
        });
        Ok(())
    }

    /// The previous step's own contribution to ring j (for a ring not evaluated then).
    fn previous_current(&self, n: usize, j: usize) -> f64 {
        if n < 2 {
            return 0.0;
        }
        let p = self.pressure(n - 1);
        self.current(j, p)
    }

    fn initial_speed(&self) -> f64 {
        match self.drive {
            Drive::Free { v0_over_c1, .. } => *v0_over_c1,
            _ => 0.0,
        }
    }

    /// The geometric edge's speed da/dt over c1 from the last step to the predicted
    /// penetration (infinite at first contact).
    fn edge_speed(&self, h_pred: f64) -> f64 {
        let a_now = self.profile.contact_radius(h_pred);
        match self.steps.last() {
            Some(s) if s.a > 0.0 => ((a_now - s.a) / self.dt).abs(),
            _ => f64::INFINITY,
        }
    }

    /// The exponent of the pressure d^lambda at a prescribed edge moving at `speed` (over
    /// c1): the plane local solution (`lamb::edge`, the edge is locally straight), 0 above
    /// c1, -1/2 for a slow or receding edge.
    fn edge_exponent(&self, speed: f64) -> Result<f64> {
        if speed >= 1.0 {
            return Ok(0.0);
        }
        let plane = self.tables.space().plane();
        let sr = *plane.s_r();
        let m = *plane.m();
        // off the three speeds where the local solution changes form
        let mut d = speed.max(1e-6);
        for c in [sr, m, 1.0] {
            if (d - c).abs() < 1e-6 {
                d = c - 1e-6;
            }
        }
        if d < sr {
            return Ok(-0.5);
        }
        Ok(plane.edge_behaviour(d, EdgeLaw::Kinematic)?.selected)
    }

    /// The kinematic step for the contact radius a: rings 0..c - 1 whole, ring c (holding
    /// the edge) carrying p_c = ratio p_{c-1}, the ratio of the means of (a - r)^lambda over
    /// the part of ring c inside a and over ring c - 1 (area-weighted). Returns the
    /// pressures of rings 0..=c and the force.
    fn kinematic_solve(
        &self,
        a: f64,
        lambda: f64,
        max_rings: usize,
        hist: &[f64],
        h_pred: f64,
        t: f64,
    ) -> Result<(Vec<f64>, f64)> {
        if !(a > 0.0) {
            return Ok((Vec::new(), 0.0));
        }
        let dr = self.dr;
        let c = ((a / dr) + 0.5).floor() as usize;
        if c == 0 || c >= max_rings {
            // the edge in the central disk (or beyond the striker's rings): whole rings
            let n = rings_within(a, dr).min(max_rings).max(1);
            let rhs: Vec<f64> = (0..n)
                .map(|i| h_pred - self.fbar[i].unwrap_or(0.0) - hist[i])
                .collect();
            let rings: Vec<usize> = (0..n).collect();
            return self.solve_rings(&rings, &rhs, t);
        }
        // Int_{r1}^{r2} (a - r)^lambda r dr, u = a - r
        let moment = |r1: f64, r2: f64| -> f64 {
            let prim = |u: f64| {
                if u <= 0.0 {
                    0.0
                } else {
                    a * u.powf(lambda + 1.0) / (lambda + 1.0)
                        - u.powf(lambda + 2.0) / (lambda + 2.0)
                }
            };
            prim(a - r1) - prim(a - r2)
        };
        let r_in = (c as f64 - 0.5) * dr;
        let own = moment(r_in, a) / ((c as f64) * dr * dr); // over ring c's area / (2 pi)
        let nb = moment((r_in - dr).max(0.0), r_in)
            / if c == 1 {
                dr * dr / 8.0
            } else {
                (c as f64 - 1.0) * dr * dr
            };
        let ratio = if nb > 0.0 { own / nb } else { 0.0 };
        // the system on rings 0..c - 1 with ring c's column folded into ring c - 1's
        let nr = self.rings();
        let block = self.tables.block(0).unwrap_or(&[]);
        let gamma = self.mass.map_or(0.0, |m| self.dt * self.dt / (2.0 * m));
        let mut w: Vec<f64> = self.area[..c].to_vec();
        w[c - 1] += ratio * self.area[c];
        let entry = |i: usize, j: usize| {
            let mut e = dr * block[i * nr + j];
            if j == c - 1 {
                e += ratio * dr * block[i * nr + c];
            }
            e
        };
        let f = Factor::new(c, None, entry, gamma, w).ok_or_else(|| ImpactError::Step {
            time: format!("{t:.6}"),
            reason: format!("the kinematic contact system of {c} rings is singular"),
        })?;
        let rhs: Vec<f64> = (0..c)
            .map(|i| h_pred - self.fbar[i].unwrap_or(0.0) - hist[i])
            .collect();
        let mut p = f.solve(&rhs).ok_or_else(|| ImpactError::Step {
            time: format!("{t:.6}"),
            reason: "the kinematic contact system's solution is not finite".into(),
        })?;
        p.push(ratio * p[c - 1]);
        let force = p.iter().zip(&self.area).map(|(q, a)| q * a).sum();
        Ok((p, force))
    }

    /// Signorini's conditions on whole rings: the step's linear complementarity problem over
    /// rings 0..max_rings - 1 (p >= 0 on the contact, no interpenetration of a ring's mean
    /// off it), by the plane march's least-index pivoting started from the previous step's
    /// rings 0..prev_c - 1. The contact need not be a disk: a light punch's middle may lift
    /// off while its rim still pushes. Returns the pressures (zeros off the contact, up to
    /// its last ring) and the force.
    fn active_set(
        &self,
        prev_c: usize,
        max_rings: usize,
        hist: &[f64],
        h_pred: f64,
        t: f64,
    ) -> Result<(Vec<f64>, f64)> {
        let Some(top) = max_rings.checked_sub(1) else {
            return Ok((Vec::new(), 0.0));
        };
        let settled = least_index_pivoting(
            top,
            prev_c.checked_sub(1),
            |rings: &[usize]| {
                let rhs: Vec<f64> = rings
                    .iter()
                    .map(|&i| h_pred - self.fbar[i].unwrap_or(0.0) - hist[i])
                    .collect();
                self.solve_rings(rings, &rhs, t)
            },
            |(p, force): &(Vec<f64>, f64), i, inside| {
                if inside {
                    return p[i] < 0.0;
                }
                // beyond the striker's surface the gap is open
                let Some(f) = self.fbar[i] else {
                    return false;
                };
                self.penetration(h_pred, *force) - f - hist[i] - self.current(i, p) > 0.0
            },
        )?;
        settled.map(|(_, s)| s).ok_or_else(|| ImpactError::Step {
            time: format!("{t:.6}"),
            reason: "the contact among whole rings did not settle (least-index pivoting)".into(),
        })
    }

    /// The reported contact radius: geometric under the kinematic law; under Signorini's the
    /// zero of p^2 linear in r through the last two ring pressures (the square-root edge),
    /// kept within the last ring's outer half and never beyond the geometric radius.
    fn report_radius(&self, p: &[f64], h: f64) -> f64 {
        let geo = self.profile.contact_radius(h);
        if let Some(a) = self.profile.flat_radius() {
            return if p.is_empty() { 0.0 } else { a };
        }
        match self.law {
            EdgeLaw::Kinematic => geo,
            EdgeLaw::Signorini => {
                let c = p.len();
                if c == 0 {
                    return 0.0;
                }
                let rc = (c - 1) as f64 * self.dr;
                let edge = if c >= 2 && p[c - 2] > p[c - 1] && p[c - 1] > 0.0 {
                    let (q1, q2) = (p[c - 2] * p[c - 2], p[c - 1] * p[c - 1]);
                    rc + q2 * self.dr / (q1 - q2)
                } else {
                    rc + 0.5 * self.dr
                };
                edge.clamp(rc, rc + 0.5 * self.dr).min(geo.max(rc))
            }
        }
    }
}

/// The rings whose centres lie within radius a (ring 0 as soon as a > 0).
fn rings_within(a: f64, dr: f64) -> usize {
    if !(a > 0.0) {
        0
    } else {
        (a / dr).floor() as usize + 1
    }
}
