//! The maps zeta_k of eq (14a, b), the radicals p_k(v) of eq (12) and the wave regions.
//!
//! With v = r/(c1 s) (the similarity variable at an earlier time s, the integration variable
//! of the J_k operators (13)) and m_1 = 1, m_2 = m = c2/c1:
//!
//! * **Behind the k-front, v < m_k** (eq (14a)):
//!   `zeta_k = m_k sech[sech^-1(v/m_k) + i theta] = m_k v / (m_k cos theta + i s_k sin theta)`,
//!   `s_k = (m_k^2 - v^2)^(1/2)`. For -pi < theta < 0 this lies in the upper half-plane; it is
//!   v on theta = 0 and -v on theta = -pi, and m_k sec(theta) (real, |.| >= m_k) on the front
//!   v = m_k. The second form needs no transcendental function and takes m_k - v exactly.
//! * **Head-wave wedges, m_k < v < m_k/h_k** (eq (14b), exists only for k = 2):
//!   `zeta_k = m_k sec[arcsec(v/m_k) +- |theta|] = m_k v / (m_k cos theta + sgn(cos theta) q_k sin theta)`,
//!   `q_k = (v^2 - m_k^2)^(1/2)`, a real number in [m/|cos theta|, 1] (in absolute value): the
//!   continuation of (14a) through v = m_k with s_k -> -i sgn(cos theta) q_k, which keeps the
//!   field continuous. Functions of zeta_k there take the boundary value from the side the
//!   continuation comes from: Omega_k from above, omega_k from below.
//! * **p_k(v) "in the quadrant of zeta_k"** (eq (12)): p_k(v) = -m_k/s_k in both cases, i.e.
//!   -|p_k(v)| behind the front (upper side of the cut, `docs/errata.md`, section 1, = `p_same_quadrant`) and
//!   -i sgn(cos theta) (v^2/m_k^2 - 1)^(-1/2) in a head-wave wedge (the value of p_k(+-v) off the
//!   cut). This is r times the radial derivative of the Chaplygin variable sech^-1(v/m_k) + i theta,
//!   which is what makes (10) a gradient (k = 1) or a curl (k = 2).
//!
//! The maps solve (t zeta - x)^2 + y^2 (1 - zeta^2/m_k^2) = 0 (c1 = 1), so analytic functions of
//! zeta_k are homogeneous solutions of degree 0 of the wave equation with speed c_k.
//!
//! **Correction (h_k).** The OCR prints h_k = m_k|cos theta| + (1 - m_k^2)^(1/2) sin theta outside
//! [arccos(m_k) - pi, -arccos(m_k)]; with sin theta < 0 that is discontinuous at the edges of that
//! interval. The head-wave front is the line through (c1 t, 0) tangent to the circle r = c_k t,
//! r cos(|theta| - arccos m_k) = c_k t (and its mirror image), so
//! h_k = m_k|cos theta| + (1 - m_k^2)^(1/2) |sin theta| = cos(|theta| - arccos m_k) there.

use complexfn::{Cx, Real};

/// Wave region of a point (r/(c1 t), theta) of the body.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Region {
    /// r >= c1 t: not yet reached by the P wave; the field vanishes.
    AheadOfP,
    /// c2 t / h_2 <= r < c1 t: reached by the P wave only.
    BetweenPAndS,
    /// c2 t <= r < c2 t / h_2: inside a head-wave wedge (h_2 < 1), zeta_2 real.
    HeadWave,
    /// r < c2 t: behind both cylindrical fronts.
    BehindS,
}

/// h_k(theta) of the wavefront r = c_k t / h_k (eq (5b)), corrected as in the module docs:
/// 1 for arccos(m_k) - pi <= theta <= -arccos(m_k), otherwise
/// m_k |cos theta| + (1 - m_k^2)^(1/2) |sin theta|.
pub fn h_k<T: Real>(theta: &T, mk: &T) -> T {
    let psi = mk.clone().min(mk.one()).acos_like();
    let th = theta.clone();
    let lo = psi.clone() - th.pi();
    if th >= lo && th <= -psi.clone() {
        return th.one();
    }
    let (s, c) = th.sin_cos();
    let sq = (mk.one() - mk.clone().sqr()).max(mk.zero()).sqrt();
    (mk.clone() * c.abs() + sq * s.abs()).min(mk.one())
}

trait AcosLike {
    fn acos_like(self) -> Self;
}
impl<T: Real> AcosLike for T {
    /// arccos x = atan2(sqrt(1 - x^2), x).
    fn acos_like(self) -> Self {
        let s = ((self.one() - &self) * (self.one() + &self))
            .max(self.zero())
            .sqrt();
        s.atan2(&self)
    }
}

/// The wave region of the point r/(c1 t) = `rho`, angle `theta` (material ratio m = c2/c1).
pub fn region<T: Real>(rho: &T, theta: &T, m: &T) -> Region {
    if *rho >= 1.0 {
        Region::AheadOfP
    } else if rho < m {
        Region::BehindS
    } else if rho.clone() < m.clone() / h_k(theta, m) {
        Region::HeadWave
    } else {
        Region::BetweenPAndS
    }
}

/// zeta_k and p_k(v) at one value of v.
#[derive(Clone, Debug)]
pub struct MapPoint<T> {
    /// zeta_k (eq (14)).
    pub zeta: Cx<T>,
    /// p_k(v) evaluated in the quadrant of zeta_k (eq (12)).
    pub p_v: Cx<T>,
    /// Whether zeta_k is real (head-wave wedge, eq (14b)).
    pub on_axis: bool,
}

/// Eq (14a) for v <= m_k, with `mk_minus_v` = m_k - v given exactly (it fixes s_k near the
/// front). `cos`, `sin` are cos theta, sin theta.
pub fn map_behind<T: Real>(v: &T, mk_minus_v: &T, mk: &T, cos: &T, sin: &T) -> MapPoint<T> {
    let s = (mk_minus_v.clone() * (mk.clone() + v)).sqrt();
    let den = Cx::new(mk.clone() * cos, s.clone() * sin);
    let zeta = Cx::real(mk.clone() * v) / &den;
    let p_v = Cx::real(-(mk.clone() / &s));
    MapPoint {
        zeta,
        p_v,
        on_axis: false,
    }
}

/// Eq (14b) for m_k <= v <= m_k/h_k, with `v_minus_mk` = v - m_k given exactly.
pub fn map_head<T: Real>(v: &T, v_minus_mk: &T, mk: &T, cos: &T, sin: &T) -> MapPoint<T> {
    let q = (v_minus_mk.clone() * (mk.clone() + v)).sqrt();
    let sg = if cos.is_sign_negative() { -1.0 } else { 1.0 };
    let den = mk.clone() * cos + q.clone() * sin * sg;
    let zeta = Cx::real(mk.clone() * v / den);
    // p_k(v) = -m_k / s_k with s_k = -i sgn(cos) q  =>  -i sgn(cos) m_k / q
    let p_v = Cx::imag(-(mk.clone() / &q) * sg);
    MapPoint {
        zeta,
        p_v,
        on_axis: true,
    }
}

/// zeta_k(v, theta) and p_k(v) for any 0 < v <= m_k/h_k (dispatches to [`map_behind`] or
/// [`map_head`]; m_k -+ v computed by subtraction).
pub fn zeta_k<T: Real>(v: &T, theta: &T, mk: &T) -> MapPoint<T> {
    let (s, c) = theta.clone().sin_cos();
    if v <= mk {
        map_behind(v, &(mk.clone() - v), mk, &c, &s)
    } else {
        map_head(v, &(v.clone() - mk), mk, &c, &s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn map_agrees_with_the_sech_form_and_solves_the_characteristic_equation() {
        let m = 0.55_f64;
        for mk in [1.0, m] {
            for &th in &[-0.2, -1.0, -1.5, -2.0, -3.0] {
                for &v in &[0.05, 0.3, 0.5, 0.54] {
                    if v >= mk {
                        continue;
                    }
                    let mp = zeta_k(&v, &th, &mk);
                    // (14a) literally: m sech(acosh(m/v) + i theta)
                    let a = (mk / v).acosh();
                    let w = num_complex::Complex::new(a, th);
                    let z14 = mk / w.cosh();
                    let z = mp.zeta.to_c64();
                    assert!((z - z14).norm() < 1e-13, "{z} {z14}");
                    assert!(z.im > 0.0);
                    // (t zeta - x)^2 + y^2 (1 - zeta^2/m^2) = 0 at x = v cos, y = v sin, t = 1
                    let (x, y) = (v * th.cos(), v * th.sin());
                    let e = (z - x).powi(2) + y * y * (1.0 - z * z / (mk * mk));
                    assert!(e.norm() < 1e-13);
                    assert!((mp.p_v.re + 1.0 / (1.0 - v * v / (mk * mk)).sqrt()).abs() < 1e-12);
                }
            }
        }
    }

    #[test]
    fn head_wave_map_is_real_continuous_and_ends_at_one() {
        let m = 0.55_f64;
        for &th in &[-0.3_f64, -0.1, -3.0, -2.9] {
            let h = h_k(&th, &m);
            assert!(h < 1.0 && h > m - 1e-12);
            let (s, c) = th.sin_cos();
            // continuity at v = m
            let a = map_behind(&m, &1e-14, &m, &c, &s).zeta.to_c64();
            let b = map_head(&m, &1e-14, &m, &c, &s).zeta.to_c64();
            assert!((a - b).norm() < 1e-6);
            // at the head front v = m/h, |zeta_2| = 1 (the branch point of p_1)
            let e = map_head(&(m / h), &(m / h - m), &m, &c, &s).zeta;
            assert!((e.re.abs() - 1.0).abs() < 1e-12, "{e}");
            // the head front is the tangent line from (1,0) or (-1,0) to the circle r = m
            let r = m / h;
            let (x, y) = (r * c, r * s);
            let psi = m.acos();
            let nx = if c > 0.0 { psi.cos() } else { -psi.cos() };
            assert!((x * nx - y * psi.sin() - m).abs() < 1e-12);
        }
        // continuity of h at the edges of the h = 1 sector
        let psi = m.acos();
        assert!((h_k(&(-psi + 1e-9), &m) - 1.0).abs() < 1e-8);
        assert!((h_k(&(psi - std::f64::consts::PI - 1e-9), &m) - 1.0).abs() < 1e-8);
        assert_eq!(h_k(&-0.0_f64, &1.0), 1.0);
    }

    #[test]
    fn regions() {
        let m = 0.55_f64;
        assert_eq!(region(&1.2, &-1.0, &m), Region::AheadOfP);
        assert_eq!(region(&0.3, &-1.0, &m), Region::BehindS);
        assert_eq!(region(&0.8, &-1.5, &m), Region::BetweenPAndS);
        assert_eq!(region(&0.6, &-0.1, &m), Region::HeadWave);
        assert_eq!(region(&0.6, &-3.1, &m), Region::HeadWave);
    }
}
