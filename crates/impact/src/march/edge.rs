//! The edge model of the march (`docs/impact.md`, section 4): the local solution of
//! `lamb::edge` inside the edge cell ([`EdgeModel`]), the shape defect of the cells behind the
//! edge, the tied solves of the edge cell (its pressure tied to its neighbour's by the local
//! power law, Sherman-Morrison on the factorised system of the cells behind it), the free
//! (Signorini) edge placed inside its cell and the prescribed edge's fit.

use complexfn::quadrature::CachedRules;

use super::*;

/// Source cells at least this many cells from the receiving cell enter the shape defect by
/// their moments (`EdgeModel::shape_defect_with`).
pub(super) const FAR_CELLS: usize = 4;

/// The moments D_1 .. D_MOMENTS of a far cell: kbar's Taylor series about the cell's middle
/// converges like (1/2)/(distance to the receiving cell)^n, under 1e-9 relative at four cells.
pub(super) const MOMENTS: usize = 12;

/// Terms of the binomial series of a far cell's pressure about its middle
/// ([`far_kernel_row`]): (d/m)^lambda in powers of e/m, |e/m| <= 1/7 on the far cells, so
/// 24 terms reach 1e-20 relative.
pub(crate) const FAR_SERIES: usize = 24;

/// The far cells' kernel B_r(d), r = 1..=[`FAR_SERIES`], of a source cell `d` cells beyond
/// the receiving cell (`docs/impact.md`, section 4, the shape defect's far cells): on a cell
/// of middle m the pressure d^lambda less its mean is
/// m^lambda sum_r c_r m^-r (e^r - I_r), c_r = binom(lambda, r), I_r the mean of e^r over
/// e in [-1/2, 1/2], so its moments are D_n = m^lambda sum_r c_r m^-r J_rn with
/// J_rn = I_(r+n) - I_r I_n, and the cell's part of the defect, sum_n K_n(d) D_n with kbar's
/// Taylor coefficients K_n at the cell's middle (which depend on d alone), is
/// m^lambda sum_r c_r m^-r B_r(d), B_r(d) = sum_n J_rn K_n(d). Tabulated once per distance
/// ([`Tables::ensure`]): a far cell then costs one power and a series of [`FAR_SERIES`]
/// terms instead of a quadrature and two logarithms.
pub(crate) fn far_kernel_row<T: Scalar>(d: usize) -> [T; FAR_SERIES] {
    // the receiving cell's ends relative to the source cell's middle, u0 = -(d + 1/2) and
    // u1 = -(d - 1/2); kbar^(n)(m)/n! = K_n
    let df = T::of(d as f64);
    let (u0, u1) = (-(df + 0.5), -(df - 0.5));
    let mut k = [T::of(0.0); MOMENTS];
    k[0] = (df - 0.5).ln() - (df + 0.5).ln();
    let (mut p0, mut p1) = (u0.recip(), u1.recip());
    for (i, kn) in k.iter_mut().enumerate().skip(1) {
        let n = (i + 1) as f64;
        *kn = (p0 - p1) / (n * (n - 1.0));
        p0 /= u0;
        p1 /= u1;
    }
    // I_q over [-1/2, 1/2]: 0 for odd q, (1/2)^q/(q + 1) for even q
    let mean_power = |q: usize| -> T {
        if q % 2 == 1 {
            T::of(0.0)
        } else {
            T::of(0.5).powi(q as i32) / (q as f64 + 1.0)
        }
    };
    let mut row = [T::of(0.0); FAR_SERIES];
    for (ri, b) in row.iter_mut().enumerate() {
        let r = ri + 1;
        for (ni, kn) in k.iter().enumerate() {
            let n = ni + 1;
            let j = mean_power(r + n) - mean_power(r) * mean_power(n);
            *b += j * *kn;
        }
    }
    row
}

/// The cells behind the free edge whose conditions carry the shape correction, besides the
/// edge cell (`docs/impact.md`, section 4): the neighbour. On the reference case 1, 3, 6 and
/// 16 cells give the same errors within 20 percent, one costing least.
pub(super) const ROWS_CORRECTED: usize = 1;

/// The banded contact systems kept on either side of the current width.
pub(super) const SYSTEMS_KEPT: usize = 4;

/// The step's system of the contact cells 0..c - 1 depends on c alone (the current step's
/// coefficients and the striker's coupling are the same at every step): its factorisation,
/// M^-1 u for the column u of cell c and M^-1 e_{c-k} for the corrected cells behind it, kept
/// for the whole march.
#[derive(Debug)]
pub(super) struct CellSystem<T> {
    pub(super) factor: Factor<T>,
    pub(super) z: Vec<T>,
    /// M^-1 e_{c-k}, k = 1 ..= `ROWS_CORRECTED`: the columns of the shape corrections of the
    /// cells behind the edge cell.
    pub(super) behind: Vec<Vec<T>>,
}

/// The two solutions behind every tied solve of one step and edge cell c: y = M^-1 r and
/// z = M^-1 u, M the system of the cells 0..c - 1 (with the striker's coupling), r the
/// right-hand side and u the edge cell's column. The tied system M + ratio u e^T (e the last
/// cell) then has the solution y - ratio z (e.y)/(1 + ratio e.z) (Sherman-Morrison), so the
/// iterations on the edge's position cost O(c) each instead of a factorisation; M's
/// factorisation and z are the same at every step ([`CellSystem`]), so a step costs O(c^2)
/// when M is dense and O(c) when it is banded (`crate::linalg`).
pub(super) struct TiedBasis<T> {
    pub(super) y: Vec<T>,
    pub(super) system: std::rc::Rc<CellSystem<T>>,
}

/// The factorised systems by number of contact cells and the coupling they were built with.
pub(super) type SystemCache<T> = (T, Vec<Option<std::rc::Rc<CellSystem<T>>>>);

/// The local model of the edge cell (`docs/impact.md`, section 4): inside the contact the
/// pressure is A d^lambda (d the distance from the edge b), outside the gap is A G s^(lambda + 1)
/// (s the distance beyond b), the local solution of `lamb::edge` for the edge's current speed.
#[derive(Clone, Copy, Debug)]
pub(super) struct EdgeModel<T> {
    /// The exponent lambda the edge law selects.
    pub(super) lambda: T,
    /// The gap coefficient G (units 1/mu); unused by the kinematic law.
    pub(super) gap: T,
    /// Supersonic edge: the two laws coincide, the edge is the geometric one.
    pub(super) geometric: bool,
    /// Whether the free edge is placed inside its cell by the model: below
    /// `FREE_EDGE_SPEED` times the Rayleigh speed (nearer c_R the gap coefficient of the
    /// square-root solution vanishes and the edge's position is ill-conditioned).
    pub(super) sub_cell: bool,
    /// (1 - nu)/pi: the static kernel's factor, w = -(1 - nu)/(pi mu) Int p(xi) ln|x - xi| dxi
    /// (units mu = 1), for the shape correction of the free edge's condition; scaled like the
    /// gap for a striker of the half-plane's own wave speeds (the two bodies' compliances add).
    pub(super) static_factor: T,
    /// beta dx, beta the second term of the local expansion p = A d^lambda (1 + beta d):
    /// the factor of the other edge of a symmetric contact, (1 - d/(2b))^lambda, gives
    /// beta = -lambda/(2b) (`docs/impact.md`, section 4).
    pub(super) curvature: T,
}

/// d^e for d >= 0: through the square root and integer powers when 2e is a small integer (the
/// exponents +-1/2 of the edge laws below c2 and their primitives), `powf` otherwise.
pub(super) fn pow<T: Scalar>(d: T, e: T) -> T {
    let twice = e * 2.0;
    let n = twice.to_f64().round();
    if twice == n && n.abs() <= 16.0 {
        let n = n as i32;
        if n % 2 == 0 {
            d.powi(n / 2)
        } else {
            d.sqrt() * d.powi((n - 1) / 2)
        }
    } else {
        d.powf(&e)
    }
}

/// Fraction of the Rayleigh speed below which a free (Signorini) edge is placed inside its
/// cell by the local model; faster free edges are captured cell by cell.
pub(crate) const FREE_EDGE_SPEED: f64 = 0.8;

impl<T: Scalar> EdgeModel<T> {
    /// (1/dx) Int_lo^hi d^lambda dd (0 <= lo <= hi).
    pub(super) fn mean_power(&self, lo: T, hi: T, dx: T) -> T {
        let e = self.lambda + 1.0;
        let beta = self.curvature / dx;
        (pow(hi, e) - pow(lo, e)) / (e * dx)
            + beta * (pow(hi, e + 1.0) - pow(lo, e + 1.0)) / ((e + 1.0) * dx)
    }

    /// For the edge b in cell c (theta = (b - x_c + dx/2)/dx in [0, 1]): the ratio of the
    /// edge cell's mean pressure to the mean pressure of cell c - 1, and the mean gap over the
    /// edge cell per unit mean pressure of cell c - 1 that the cells' constant pressures must
    /// leave there: the model's gap less the shape correction of the c + 1 cells 0..=c
    /// (`docs/impact.md`, section 4; the correction only for a free edge, given its rules).
    pub(super) fn tie(&self, theta: T, dx: T, c: usize, shape: Option<ShapeRules<T>>) -> (T, T) {
        let outside = (T::of(1.0) - theta) * dx;
        let neighbour = self.neighbour_mean(theta, dx);
        let load = self.mean_power(T::of(0.0), theta * dx, dx);
        let e = self.lambda + 2.0;
        // the gap of A d^lambda (1 + beta d): A G s^(lambda + 1) (1 + beta_g s) with
        // beta_g = -beta (lambda + 1)/(lambda + 2) (the kernel of a steadily moving edge is
        // the static one times a constant, and the static pair of p = d^mu has the gap's
        // slope s^mu/sin(pi mu))
        let beta_g = -self.curvature / dx * (self.lambda + 1.0) / e;
        let mut gap =
            self.gap * (pow(outside, e) / e + beta_g * pow(outside, e + 1.0) / (e + 1.0)) / dx;
        if let Some(rules) = shape {
            gap -= self.shape_term(theta, dx, c, 0, rules);
        }
        (load / neighbour, gap / neighbour)
    }

    /// The mean of d^lambda over cell c - 1 (the amplitude's reference), edge at theta.
    pub(super) fn neighbour_mean(&self, theta: T, dx: T) -> T {
        self.mean_power(theta * dx, theta * dx + dx, dx)
    }

    /// The displacement the cells' constant pressures miss over the cell `k` behind the edge
    /// cell, per unit amplitude A: (1 - nu)/pi dx^(lambda + 1) times the shape defect.
    pub(super) fn shape_term(
        &self,
        theta: T,
        dx: T,
        c: usize,
        k: usize,
        rules: ShapeRules<T>,
    ) -> T {
        self.static_factor * pow(dx, self.lambda + 1.0) * self.shape_defect_at(theta, c, k, rules)
    }

    /// The shape defect (`docs/impact.md`, section 4), dx = 1: with d the distance from the
    /// edge into the contact, the edge cell d in [theta - 1, theta] and its neighbours
    /// j = 1..=cells behind it, the mean over the receiving cell, `k` cells behind the edge
    /// cell (0: the edge cell), of -Int (p - pbar) ln|d - xi| dxi for p = d^lambda (d > 0) and
    /// pbar its mean on each cell: the part of the local solution's displacement there that
    /// the cells' constant pressures miss (the static kernel without its factor).
    pub(super) fn shape_defect_at(
        &self,
        theta: T,
        cells: usize,
        k: usize,
        rules: ShapeRules<T>,
    ) -> T {
        self.shape_defect_with(theta, cells, k, rules, FAR_CELLS)
    }

    /// [`EdgeModel::shape_defect_at`] with the source cells at least `far` cells from the
    /// receiving cell (and from the edge) taken by their moments: on such a cell kbar is
    /// smooth, and Int (p - pbar) kbar = sum_n kbar^(n)(m) D_n/n! with
    /// D_n = Int (p - pbar) (x - m)^n (m the cell's middle, D_0 = 0), to n = `MOMENTS`; D_n on the
    /// smooth rule's nodes, kbar's derivatives in closed form: two logarithms a cell instead
    /// of fourteen (`far_cells_by_moments_agree_with_the_quadrature`).
    pub(super) fn shape_defect_with(
        &self,
        theta: T,
        cells: usize,
        k: usize,
        rules: ShapeRules<T>,
        far: usize,
    ) -> T {
        let lam = self.lambda;
        let kf = k as f64;
        let zero = T::of(0.0);
        // primitive of ln|u|
        let f = |u: T| if u == 0.0 { zero } else { u * u.abs().ln() - u };
        // minus the mean over the receiving cell of ln|d - xi|
        let kbar = |xi: T| f(theta + (kf - 1.0) - xi) - f(theta + kf - xi);
        let power = |d: T| if d > 0.0 { pow(d, lam) } else { zero };
        let prim = |d: T| {
            if d > 0.0 {
                pow(d, lam + 1.0) / (lam + 1.0)
            } else {
                zero
            }
        };
        let (clustered_rule, smooth_rule, far_kernel) = rules;
        // the binomial coefficients c_r = binom(lambda, r), r = 1..=FAR_SERIES
        let mut binom = [zero; FAR_SERIES];
        let mut c = T::of(1.0);
        for (r, b) in binom.iter_mut().enumerate() {
            c = c * (lam - r as f64) / (r + 1) as f64;
            *b = c;
        }
        // a far cell of middle m, d >= FAR_CELLS cells beyond the receiving cell, by the
        // tabulated kernel (`far_kernel_row`)
        let tabulated = |m: T, d: usize| -> Option<T> {
            let row = far_kernel.get(d)?;
            let x = m.recip();
            let mut s = zero;
            for (b, c) in row.iter().zip(&binom).rev() {
                s = (s + *b * *c) * x;
            }
            Some(pow(m, lam) * s)
        };
        // Int_a^b (p - pbar) kbar, clustered at both ends (x = end + (mid - end) u^2): the
        // pieces touching the edge cell's ends (kinks of kbar) or the edge (d^lambda)
        let clustered = |a: T, b: T, pbar: T| -> T {
            let mid = (a + b) * 0.5;
            let mut s = zero;
            for (end, dir) in [(a, mid - a), (b, mid - b)] {
                for &(u, w) in clustered_rule {
                    // u on [0, 1], weight w/2
                    let u = (u + 1.0) * 0.5;
                    let x = end + dir * u * u;
                    s += (power(x) - pbar) * kbar(x) * w * dir.abs() * u;
                }
            }
            s
        };
        let smooth = |a: T, b: T, pbar: T| -> T {
            smooth_rule.iter().fold(zero, |s, &(u, w)| {
                let x = a + (b - a) * (u + 1.0) * 0.5;
                s + (power(x) - pbar) * kbar(x) * w * (b - a) * 0.5
            })
        };
        // the receiving cell's ends, where kbar's derivatives are singular
        let (r0, r1) = (theta + (kf - 1.0), theta + kf);
        let moments = |a: T, b: T, pbar: T| -> T {
            let m = (a + b) * 0.5;
            let h = (b - a) * 0.5;
            // D_1 .. D_MOMENTS on the smooth rule's nodes (p is smooth away from the edge)
            let mut dn = [zero; MOMENTS];
            for &(u, w) in smooth_rule {
                let e = h * u;
                let mut q = (power(m + e) - pbar) * w * h;
                for d in dn.iter_mut() {
                    q *= e;
                    *d += q;
                }
            }
            let (u0, u1) = (r0 - m, r1 - m);
            // kbar = f(r0 - x) - f(r1 - x): kbar' = ln|r1 - x| - ln|r0 - x| and, for n >= 2,
            // kbar^(n)(m)/n! = (u0^(1-n) - u1^(1-n))/(n (n - 1)), u = r - m
            let mut sum = (u1.abs().ln() - u0.abs().ln()) * dn[0];
            let (mut p0, mut p1) = (u0.recip(), u1.recip());
            for (i, d) in dn.iter().enumerate().skip(1) {
                let n = (i + 1) as f64;
                sum += (p0 - p1) * *d / (n * (n - 1.0));
                p0 /= u0;
                p1 /= u1;
            }
            sum
        };
        let mut total = zero;
        for j in 0..=cells {
            let (a, b) = (theta + (j as f64 - 1.0), theta + j as f64);
            let pbar = prim(b) - prim(a);
            total += match j {
                0 if theta > 0.0 => clustered(a, zero, pbar) + clustered(zero, b, pbar),
                0 => clustered(a, b, pbar),
                // the cells touching the edge cell or the receiving cell (kinks of kbar)
                _ if j <= 1 || j + 1 >= k && j <= k + 1 => clustered(a, b, pbar),
                _ if j >= 2 && j.abs_diff(k) >= far => (j >= k)
                    .then(|| tabulated((a + b) * 0.5, j - k))
                    .flatten()
                    .unwrap_or_else(|| moments(a, b, pbar)),
                _ => smooth(a, b, pbar),
            };
        }
        total
    }
}

impl<'a, T: Scalar + CachedRules> March<'a, T> {
    /// The edge's speed (units c1) over the last steps (up to four), from the reported edges
    /// (the edge at t = 0 is 0); over the first step, from the geometric edge `kin_b` at its
    /// end.
    pub(super) fn edge_speed(&self, kin_b: T) -> T {
        if self.steps.is_empty() {
            return kin_b / self.dt;
        }
        recent_edge_speed(&self.steps, self.dt)
    }

    /// The local model of the edge cell for the current edge speed and law (`lamb::edge`);
    /// `None` for the flat punch (its edges sit on cell boundaries).
    pub(super) fn edge_model(&self, kin_b: T) -> Result<Option<EdgeModel<T>>> {
        let Some(scale) = self.edge_gap_scale else {
            return Ok(None);
        };
        if matches!(self.profile, Profile::Flat { .. }) {
            return Ok(None);
        }
        let hp = self.tables.half_plane();
        let (sr, m) = (*hp.s_r(), *hp.m());
        let d = self.edge_speed(kin_b);
        // a receding or resting edge takes the model of a slowly advancing one (the
        // static limit), below the Rayleigh speed
        let mut speed = if d > 0.0 { d } else { d.abs().min(sr * 0.5) };
        speed = speed.max(T::of(1e-6));
        // off the speeds where the local solutions jump (refused by `lamb::edge`)
        let guard = 10.0 * lamb::edge::SPEED_GUARD;
        for c in [sr, m, T::of(1.0)] {
            if (speed - c).abs() <= c * guard {
                speed = c * (1.0 - guard);
            }
        }
        let eb = hp.edge_behaviour(speed, self.law)?;
        let gap = eb
            .solutions
            .iter()
            .find(|s| s.lambda == eb.selected)
            .map_or(T::of(0.0), |s| s.gap_coefficient);
        let pi = speed.pi();
        Ok(Some(EdgeModel {
            lambda: eb.selected,
            gap: gap * scale,
            geometric: eb.range == lamb::edge::SpeedRange::Supersonic,
            sub_cell: speed < sr * FREE_EDGE_SPEED,
            static_factor: scale * (T::of(1.0) - hp.poisson()) / pi,
            curvature: match self.steps.last() {
                Some(s) if s.b > 0.0 => -eb.selected * self.dx / (s.b * 2.0),
                _ => T::of(0.0),
            },
        }))
    }

    /// Solves the step with full contact cells 0..c-1 and the edge cell c, whose mean
    /// pressure is `ratio` times that of cell c - 1: returns (pressures 0..=c, force).
    pub(super) fn solve_tied(&self, d: &StepData<T>, c: usize, ratio: T) -> Result<(Vec<T>, T)> {
        let basis = self.tied_basis(d, c)?;
        self.tied_solution(d, &basis, c, ratio)
    }

    /// The factorised system of the cells 0..c - 1 and M^-1 u ([`CellSystem`]), built once
    /// per march.
    pub(super) fn cell_system(
        &self,
        d: &StepData<T>,
        c: usize,
    ) -> Result<std::rc::Rc<CellSystem<T>>> {
        {
            let cache = self.systems.borrow();
            if cache.0 == d.coupling {
                if let Some(Some(sys)) = cache.1.get(c) {
                    return Ok(sys.clone());
                }
            }
        }
        let n = c;
        let w: Vec<T> = (0..n).map(|j| self.weight(j)).collect();
        let u: Vec<T> = (0..n)
            .map(|i| self.current(i, c) + d.coupling * self.weight(c))
            .collect();
        let singular = || singular_system(d.t);
        let factor = Factor::new(n, self.reach(), |i, j| self.current(i, j), d.coupling, w)
            .ok_or_else(singular)?;
        let z = factor.solve(&u).ok_or_else(singular)?;
        // M^-1 e_{c-k} for the cells behind the edge cell whose conditions carry the shape
        // correction (the same at every step, like z)
        let behind = (1..=ROWS_CORRECTED.min(n))
            .map(|k| {
                let mut e = vec![T::of(0.0); n];
                e[n - k] = T::of(1.0);
                factor.solve(&e).ok_or_else(singular)
            })
            .collect::<Result<Vec<_>>>()?;
        let sys = std::rc::Rc::new(CellSystem { factor, z, behind });
        let mut cache = self.systems.borrow_mut();
        if cache.0 != d.coupling {
            *cache = (d.coupling, Vec::new());
        }
        if cache.1.len() <= c {
            cache.1.resize_with(c + 1, || None);
        }
        cache.1[c] = Some(sys.clone());
        // banded systems cost O(c) to rebuild: keep only the widths near the current one
        // (the contact grows or shrinks a cell at a time), so memory stays O(c)
        if matches!(sys.factor, Factor::Band { .. }) {
            for (k, slot) in cache.1.iter_mut().enumerate() {
                if k.abs_diff(c) > SYSTEMS_KEPT {
                    *slot = None;
                }
            }
        }
        Ok(sys)
    }

    /// The two solutions behind the tied solves of cell c at this step ([`TiedBasis`]).
    pub(super) fn tied_basis(&self, d: &StepData<T>, c: usize) -> Result<TiedBasis<T>> {
        let sys = self.cell_system(d, c)?;
        let zero = T::of(0.0);
        let mut r = vec![zero; c];
        for (i, ri) in r.iter_mut().enumerate() {
            *ri = d.target(i, zero)? - d.hist.0[i] - d.hist.1.get(i).copied().unwrap_or(zero);
        }
        let y = sys.factor.solve(&r).ok_or_else(|| singular_system(d.t))?;
        Ok(TiedBasis { y, system: sys })
    }

    /// The pressures of cells 0..=c and the force when cell c carries `ratio` times the
    /// pressure of cell c - 1, from the step's [`TiedBasis`] of cell c.
    pub(super) fn tied_solution(
        &self,
        d: &StepData<T>,
        basis: &TiedBasis<T>,
        c: usize,
        ratio: T,
    ) -> Result<(Vec<T>, T)> {
        self.tied_solution_with(d, basis, c, ratio, None)
    }

    /// As [`March::tied_solution`], with `q` = M^-1 delta when the conditions of the cells
    /// behind the edge carry terms delta p_{c-1} (their shape corrections): the system
    /// M + (ratio u + delta) e_{c-1}^T, by Sherman-Morrison on z ratio + q.
    pub(super) fn tied_solution_with(
        &self,
        d: &StepData<T>,
        basis: &TiedBasis<T>,
        c: usize,
        ratio: T,
        q: Option<&[T]>,
    ) -> Result<(Vec<T>, T)> {
        let last = c - 1;
        let z = &basis.system.z;
        let zw: Vec<T> = match q {
            Some(q) => z.iter().zip(q).map(|(&z, &q)| ratio * z + q).collect(),
            None => z.iter().map(|&z| ratio * z).collect(),
        };
        let den = zw[last] + 1.0;
        if !(den.abs() > 1e-300) || !den.is_finite() {
            return Err(singular_system(d.t));
        }
        let k = basis.y[last] / den;
        let mut p: Vec<T> = basis.y.iter().zip(&zw).map(|(&y, &z)| y - k * z).collect();
        p.push(ratio * p[last]);
        let force = p
            .iter()
            .enumerate()
            .fold(T::of(0.0), |s, (j, &v)| s + self.weight(j) * v);
        Ok((p, force))
    }

    /// The shape correction of the conditions of the cells just behind the edge cell c (edge
    /// at theta), proportional to p_{c-1} like the edge cell's own (`docs/impact.md`, section
    /// 4): q = M^-1 delta from the kept columns M^-1 e_{c-k} of `basis`, for
    /// [`March::tied_solution_with`].
    pub(super) fn behind_corrections(
        &self,
        model: &EdgeModel<T>,
        theta: T,
        c: usize,
        basis: &TiedBasis<T>,
    ) -> Vec<T> {
        let rules = self.tables.shape_rules();
        let neighbour = model.neighbour_mean(theta, self.dx);
        let mut q = vec![T::of(0.0); c];
        for (k, col) in (1..).zip(&basis.system.behind) {
            let coef = model.shape_term(theta, self.dx, c, k, rules) / neighbour;
            for (qi, &v) in q.iter_mut().zip(col) {
                *qi += coef * v;
            }
        }
        q
    }

    /// The free (Signorini) edge inside a cell: the edge cell c carries the local model's
    /// pressure, and its mean displacement leaves the model's gap over the part beyond the
    /// edge; the edge is the root of that condition in the cell (a secant from the edge the
    /// previous steps' speed predicts, safeguarded by the bracket and bisection), the cell
    /// moving outwards or inwards when the root lies beyond it. Returns (c, b, pressures,
    /// force), or `None` where the model cannot stand: the edge recedes into the first two
    /// cells, or a cell's pressure would pull (the contact is then found among whole cells,
    /// which can shrink it to nothing).
    pub(super) fn free_edge(
        &self,
        d: &StepData<T>,
        model: EdgeModel<T>,
        start: usize,
    ) -> Result<Option<StepSet<T>>> {
        let dx = self.dx;
        let top = (d.fbar.len() - 1).min(self.kcap);
        // one factorisation per edge cell tried, shared by the iterations on theta
        let mut bases: Vec<Option<TiedBasis<T>>> = Vec::new();
        let mut residual = |c: usize, theta: T| -> Result<(T, Vec<T>, T)> {
            let (ratio, gap) = model.tie(theta, dx, c, Some(self.tables.shape_rules()));
            if bases.len() <= c {
                bases.resize_with(c + 1, || None);
            }
            if bases[c].is_none() {
                bases[c] = Some(self.tied_basis(d, c)?);
            }
            let basis = bases[c].as_ref().ok_or_else(|| ImpactError::Step {
                time: format!("{:.6}", d.t.to_f64()),
                reason: "no factorisation of the edge cell's system".into(),
            })?;
            let q = self.behind_corrections(&model, theta, c, basis);
            let (p, f) = self.tied_solution_with(d, basis, c, ratio, Some(&q))?;
            // the edge cell's mean gap at the step's end, and at its middle, where the
            // step's pressures (and so the model's edge and gap) stand: the mean of the
            // gaps at the step's two ends
            let end_gap = self.displacement(c, &d.hist, &p) - d.target(c, f)?;
            let gap_now = match self.gap_before(c) {
                Some(before) => (end_gap + before) * 0.5,
                None => end_gap,
            };
            Ok((gap_now - gap * p[c - 1], p, f))
        };
        let mut c = start.clamp(2, top.max(2));
        let mut tried = vec![false; top + 2];
        let (zero, one) = (T::of(0.0), T::of(1.0));
        let pushes = |p: &[T]| p.iter().all(|v| *v >= 0.0);
        loop {
            tried[c] = true;
            let (r1, p1, f1) = residual(c, one)?;
            if r1 < 0.0 && c < top && !tried[c + 1] {
                c += 1;
                continue;
            }
            let (r0, p0, f0) = residual(c, zero)?;
            if r0 > 0.0 && c > 2 && !tried[c - 1] {
                c -= 1;
                continue;
            }
            if r0 > 0.0 && c == 2 {
                // the edge recedes into the first two cells
                return Ok(None);
            }
            let edge = |theta: T| (theta + (c as f64 - 0.5)) * dx;
            if r1 <= 0.0 {
                return Ok(pushes(&p1).then(|| (c, edge(one), p1, f1)));
            }
            if r0 >= 0.0 {
                return Ok(pushes(&p0).then(|| (c, edge(zero), p0, f0)));
            }
            // a safeguarded secant on theta in (0, 1), from the edge the previous steps'
            // speed predicts: secant steps through the last two iterates while they fall
            // inside the bracket, bisection otherwise
            let (mut a, mut fa, mut b, mut fb) = (zero, r0, one, r1);
            let mut best = (p0, f0, zero);
            let predicted = self.steps.last().map(|s| {
                let b = s.b + recent_edge_speed(&self.steps, self.dt) * self.dt;
                b / dx - (c as f64 - 0.5)
            });
            let mut x = match predicted {
                Some(t) if t > 1e-3 && t < 1.0 - 1e-3 => t,
                _ => (a * fb - b * fa) / (fb - fa),
            };
            let mut last: Option<(T, T)> = None;
            for _ in 0..ITERATIONS * T::BITS as usize / 53 + 10 {
                let (rx, px, fx) = residual(c, x)?;
                best = (px, fx, x);
                if rx.abs() <= (d.h_pred.abs() + dx) * tolerance::<T>(1e-15)
                    || (b - a) <= tolerance::<T>(1e-13)
                {
                    break;
                }
                if (rx > 0.0) == (fb > 0.0) {
                    b = x;
                    fb = rx;
                } else {
                    a = x;
                    fa = rx;
                }
                let next = match last {
                    Some((xl, rl)) if rl != rx => x - rx * (x - xl) / (rx - rl),
                    _ => (a * fb - b * fa) / (fb - fa),
                };
                last = Some((x, rx));
                x = if next > a && next < b {
                    next
                } else {
                    (a + b) * 0.5
                };
            }
            let (p, f, theta) = best;
            return Ok(pushes(&p).then(|| (c, edge(theta), p, f)));
        }
    }

    /// The mean gap over cell i at the end of the previous step, w_i - (h - mean f_i), if
    /// that step has the cell's displacement.
    pub(super) fn gap_before(&self, i: usize) -> Option<T> {
        let s = self.steps.last()?;
        let w = *s.w.get(i)? + s.ws.get(i).copied().unwrap_or(T::of(0.0));
        Some(w - (s.h - self.profile_mean(i)?))
    }

    /// The Signorini edge inside the last cell: the zero of C (b - x)^(1/2) through the last
    /// two cell pressures, kept within the last cell.
    pub(super) fn edge_fit(&self, k: usize, p: &[T]) -> T {
        let dx = self.dx;
        let xk = dx * k as f64;
        if k == 0 || p.len() < 2 {
            return xk + dx * 0.5;
        }
        let zero = T::of(0.0);
        let (a, c) = (p[k - 1].max(zero).powi(2), p[k].max(zero).powi(2));
        let b = if a > c {
            (xk * a - (xk - dx) * c) / (a - c)
        } else {
            xk + dx * 0.5
        };
        b.max(xk).min(xk + dx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The static half-plane's displacement under a uniform load: the mean over [xa, xb] of
    /// -Int_sa^sb ln|x - xi| dxi in closed form (the second primitive of ln|u| at the corners),
    /// for the test of the shape defect.
    fn static_cell_mean(xa: f64, xb: f64, sa: f64, sb: f64) -> f64 {
        let g = |u: f64| {
            if u == 0.0 {
                0.0
            } else {
                0.5 * u * u * u.abs().ln() - 0.75 * u * u
            }
        };
        -(g(xb - sa) - g(xa - sa) - g(xb - sb) + g(xa - sb)) / (xb - xa)
    }

    /// Tables whose rules the march passes to the shape correction.
    fn tables() -> Tables {
        Tables::new(lamb::HalfPlane::from_poisson(0.25).unwrap(), 2.0).unwrap()
    }

    /// The shape defect for lambda = 0 (a uniform pressure behind the edge), where only the
    /// edge cell's constant misses anything, against the closed-form static cell means.
    #[test]
    fn shape_defect_of_a_uniform_pressure_is_the_closed_form() {
        let model = EdgeModel {
            lambda: 0.0,
            gap: 0.0,
            geometric: false,
            sub_cell: true,
            static_factor: 1.0,
            curvature: 0.0,
        };
        let tables = tables();
        let rules = tables.shape_rules();
        for theta in [0.05, 0.37, 0.5, 0.8, 0.999] {
            let (a, b) = (theta - 1.0, theta);
            let want = -theta * static_cell_mean(a, b, a, 0.0)
                + (1.0 - theta) * static_cell_mean(a, b, 0.0, b);
            for cells in [0, 3, 20] {
                let got = model.shape_defect_at(theta, cells, 0, rules);
                assert!(
                    (got - want).abs() <= 1e-9 * want.abs().max(1e-3),
                    "theta = {theta}, cells = {cells}: {got} against {want}"
                );
            }
        }
    }

    /// The far source cells by their moments agree with the quadrature of every cell, for
    /// the edge cell and its neighbour receiving, both square-root exponents.
    #[test]
    fn far_cells_by_moments_agree_with_the_quadrature() {
        // without the far kernel (the moments on the smooth rule) and with it (the tabulated
        // binomial series, `far_kernel_row`), against the quadrature of every cell
        let bare = tables();
        let mut grown = tables();
        grown.ensure(320, 0).unwrap();
        let mut worst: f64 = 0.0;
        for lambda in [0.5, -0.5, 0.3, -0.85] {
            let model = EdgeModel {
                lambda,
                gap: 0.0,
                geometric: false,
                sub_cell: true,
                static_factor: 1.0,
                curvature: 0.0,
            };
            for theta in [0.05, 0.5, 0.95] {
                for cells in [6, 40, 300] {
                    for k in [0, 1, 9] {
                        let all = model.shape_defect_with(
                            theta,
                            cells,
                            k,
                            bare.shape_rules(),
                            usize::MAX,
                        );
                        for rules in [bare.shape_rules(), grown.shape_rules()] {
                            let fast = model.shape_defect_with(theta, cells, k, rules, FAR_CELLS);
                            // relative to the defect, or to the edge cell's (about 0.1) where
                            // the neighbour's nearly cancels
                            let rel = (fast - all).abs() / all.abs().max(1e-2);
                            worst = worst.max(rel);
                            assert!(
                                rel < 1e-9,
                                "lambda {lambda}, theta {theta}, {cells} cells, k {k}, {} far rows: {fast} vs {all}",
                                rules.2.len()
                            );
                        }
                    }
                }
            }
        }
        eprintln!("largest relative difference {worst:.2e}");
    }

    /// For the square-root edge the defect converges in the number of cells behind the edge
    /// (the cells' dipoles decay like d^(lambda - 2)), and its quadrature agrees with a
    /// brute-force midpoint rule.
    #[test]
    fn shape_defect_of_the_square_root_edge() {
        let model = EdgeModel {
            lambda: 0.5,
            gap: 0.0,
            geometric: false,
            sub_cell: true,
            static_factor: 1.0,
            curvature: 0.0,
        };
        let tables = tables();
        let rules = tables.shape_rules();
        let theta = 0.3;
        // brute force over the edge cell and two cells behind it
        let n = 20000;
        let kbar = |xi: f64| {
            let m = 400;
            -(0..m)
                .map(|q| {
                    let d = theta - 1.0 + (q as f64 + 0.5) / m as f64;
                    (d - xi).abs().ln()
                })
                .sum::<f64>()
                / m as f64
        };
        let mut want = 0.0;
        for j in 0..3 {
            let (a, b) = (theta + j as f64 - 1.0, theta + j as f64);
            let prim = |d: f64| if d > 0.0 { d.powf(1.5) / 1.5 } else { 0.0 };
            let pbar = prim(b) - prim(a);
            for q in 0..n {
                let xi = a + (q as f64 + 0.5) / n as f64;
                let p = if xi > 0.0 { xi.sqrt() } else { 0.0 };
                want += (p - pbar) * kbar(xi) / n as f64;
            }
        }
        let got = model.shape_defect_at(theta, 2, 0, rules);
        assert!(
            (got - want).abs() < 2e-5 * want.abs(),
            "{got} against {want}"
        );
        let (d20, d40, d80) = (
            model.shape_defect_at(theta, 20, 0, rules),
            model.shape_defect_at(theta, 40, 0, rules),
            model.shape_defect_at(theta, 80, 0, rules),
        );
        // tail ~ cells^(-1/2): differences shrink by about sqrt 2
        let ratio = (d40 - d20) / (d80 - d40);
        assert!((ratio - 2f64.sqrt()).abs() < 0.1, "tail ratio {ratio}");
    }
}
