//! The stiff and extreme grid: p near 0 and near the Rayleigh speed, Theta near 90 degrees,
//! gamma at and around cot Theta, huge gamma, Poisson's ratio near its limits; each case
//! solved in f64 and compared with 256 bits against the accuracy the library states.

use complexfn::quadrature::CachedRules;
use complexfn::Real;
use rug::Float;
use wedge::{Case, Coupling, Indenter, Material, Result, Solution};

/// Smallest relative accuracy claimed for an f64 result.
pub const F64_FLOOR: f64 = 1e-13;

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
            "nu {} theta {} gamma {:e} p {}",
            self.nu, self.theta, self.gamma, self.p_label
        )
    }
}

/// The grid of the stability suite: 5 Poisson ratios x 5 angles x 8 friction coefficients x
/// 5 contact speeds, coupled.
pub fn grid() -> Vec<GridPoint> {
    let mut v = Vec::new();
    for nu in [-0.9, 0.0, 0.3, 0.49, 0.4999] {
        for theta in [30.0, 60.0, 86.0, 89.0, 90.0 - 1e-6] {
            let cot = Indenter::new(theta, 0.0, Coupling::On)
                .expect("angle")
                .cot_theta(&0.0_f64);
            for gamma in [
                0.0,
                1e-12,
                cot * (1.0 - 1e-12),
                cot,
                cot * (1.0 + 1e-12),
                0.6,
                10.0,
                1e6,
            ] {
                for (p_label, p_spec) in [
                    ("1e-8", -1e-8),
                    ("1e-4", -1e-4),
                    ("0.3", -0.3),
                    ("mR(1-1e-6)", 1e-6),
                    ("mR(1-1e-12)", 1e-12),
                ] {
                    v.push(GridPoint {
                        nu,
                        theta,
                        gamma,
                        p_label,
                        p_spec,
                    });
                }
            }
        }
    }
    v
}

/// Q, V, the stress at p/2, the apex displacement and S0, with the largest stated relative
/// error among them.
pub fn values<T: CachedRules>(c: &Case<T>) -> Result<(Vec<T>, f64)> {
    let m = c.matching()?;
    let x = c.p().clone() / 2.0;
    let s = c.stress_hat(&x)?;
    let a = c.apex_u_r_over_speed_t()?;
    let scale_a = m.v_hat.clone().abs().max(a.value.clone().abs());
    let err = m
        .rel_error
        .max(s.error / s.value.to_f64().abs())
        .max(a.error / scale_a.to_f64());
    Ok((
        vec![m.q_hat.clone(), m.v_hat.clone(), s.value, a.value, c.s0()],
        err,
    ))
}

/// The outcome of one grid point.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// Refused with a typed error (the message).
    Refused(String),
    /// Solved in f64 with this stated relative error; with `Some((actual, stated))` when
    /// compared at 256 bits (the largest actual relative error over the quantities, on the
    /// scale of V for the apex displacement and S0, which may vanish).
    Solved {
        /// Stated relative error of the f64 result.
        stated: f64,
        /// Actual error against 256 bits, if compared.
        actual: Option<f64>,
    },
}

/// Solve one grid point in f64, and at 256 bits when `compare`.
pub fn check(pt: &GridPoint, compare: bool) -> std::result::Result<Outcome, String> {
    let mat = Material::from_poisson(pt.nu, 1000.0).map_err(|e| e.to_string())?;
    let ind = Indenter::new(pt.theta, pt.gamma, Coupling::On).map_err(|e| e.to_string())?;
    let m_r = complexfn::Rayleigh::new(mat.m(&0.0_f64))
        .map_err(|e| e.to_string())?
        .m_r()
        .to_owned();
    let p = pt.p(m_r);
    let (v64, err64) = match Case::new(&mat, &ind, p, Solution::Paper).and_then(|c| values(&c)) {
        Ok(x) => x,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    if v64.iter().any(|v| !v.is_finite()) || !err64.is_finite() {
        return Err(format!(
            "{}: non-finite result {v64:?}, error {err64}",
            pt.label()
        ));
    }
    let stated = err64.max(F64_FLOOR);
    if !compare {
        return Ok(Outcome::Solved {
            stated,
            actual: None,
        });
    }
    let (vb, errb) = Case::new(&mat, &ind, Float::with_val(256, p), Solution::Paper)
        .and_then(|c| values(&c))
        .map_err(|e| format!("{}: f64 solved but 256 bits failed: {e}", pt.label()))?;
    if errb > 1e-20 {
        return Err(format!("{}: 256-bit error estimate {errb:e}", pt.label()));
    }
    let scale = vb[1].clone().abs().to_f64();
    let mut actual = 0.0_f64;
    for (k, (a, b)) in v64.iter().zip(vb.iter()).enumerate() {
        let bb = b.to_f64();
        let d = if k >= 3 {
            (a - bb).abs() / scale.max(bb.abs())
        } else {
            ((a - bb) / bb).abs()
        };
        actual = actual.max(d);
    }
    Ok(Outcome::Solved {
        stated,
        actual: Some(actual),
    })
}
