//! The typed report of an axisymmetric impact run (`impact run --geometry axisymmetric`,
//! crate `impact`'s [`impact::axisym`], `docs/axisymmetric.md`): the inputs echoed, the
//! histories with their estimates, the rebound, the energy audit, Hertz's quasi-static
//! values and the first-order radiation beside them. Keys as the plane run's where they
//! apply ([`AXI_KEYS`]); written as JSON and CSV here.

use impact::axisym::{AxiCase, AxiProfile, AxiRow, SolvedAxi};
use impact::{Drive, Stop};
use serde_json::{json, Map, Value};

use super::impact::{keys, Column, EnergyAudit, ENERGY_DEFECT_BOUND};
use super::Number;

/// The keys of an [`AxiReport`] as JSON, in order (each present when it applies).
pub const AXI_KEYS: &[&str] = &[
    "version",
    "geometry",
    keys::LAW,
    keys::STRIKER,
    "profile",
    "mass_ratio",
    "v0_over_c1",
    "driven",
    "end",
    keys::POISSON,
    "c2_over_c1",
    "cR_over_c1",
    "grid",
    keys::H_OVER_R,
    keys::HDOT_OVER_V0,
    "hdot_over_c1",
    A_OVER_R,
    FORCE_OVER_RHO_C1SQ_RSQ,
    "kinetic_energy_over_rho_c1sq_Rcu",
    "work_over_rho_c1sq_Rcu",
    RADIATED_ENERGY_FRACTION,
    "energy_defect",
    keys::C1T_OVER_R,
    "adot_over_c1",
    keys::STAGE,
    "peak_force",
    "separation_c1t_over_R",
    "restitution",
    "rebound_speed_over_c1",
    "energy_to_half_space",
    "reimpacts",
    "energy_audit",
    "resolution",
    "hertz",
    "first_order_radiation",
    "error_estimate",
    "observed_order",
    "error_model",
    "pressure",
    "unavailable",
];

/// `a_over_R`, the contact radius.
pub const A_OVER_R: &str = "a_over_R";
/// `force_over_rho_c1sq_Rsq`, the force over rho c1^2 R^2.
pub const FORCE_OVER_RHO_C1SQ_RSQ: &str = "force_over_rho_c1sq_Rsq";
/// `radiated_energy_fraction`, the energy radiated into the half-space.
pub const RADIATED_ENERGY_FRACTION: &str = "radiated_energy_fraction";

/// The columns of the CSV table, in order (those the run has; then `err_<key>`).
pub const AXI_COLUMNS: &[&str] = &[
    keys::C1T_OVER_R,
    keys::H_OVER_R,
    keys::HDOT_OVER_V0,
    "hdot_over_c1",
    A_OVER_R,
    "adot_over_c1",
    keys::STAGE,
    FORCE_OVER_RHO_C1SQ_RSQ,
    "kinetic_energy_over_rho_c1sq_Rcu",
    "work_over_rho_c1sq_Rcu",
    RADIATED_ENERGY_FRACTION,
    "energy_defect",
];

/// The fewest rings across the largest contact radius of the finest grid for the contact not
/// to be flagged as under-resolved.
pub const MIN_CONTACT_RINGS: usize = 10;

/// A value with its absolute error estimate.
#[derive(Clone, Debug, PartialEq)]
pub struct AxiEstimated {
    /// The value.
    pub value: f64,
    /// Its absolute error estimate (`None` with one level).
    pub error: Option<f64>,
}

/// The rebound of a free striker.
#[derive(Clone, Debug, PartialEq)]
pub struct AxiReboundReport {
    /// c1 t/R at the last separation.
    pub separation_c1t_over_r: AxiEstimated,
    /// The coefficient of restitution.
    pub restitution: AxiEstimated,
    /// V_final/c1.
    pub rebound_speed_over_c1: AxiEstimated,
    /// 1 - e^2, the share of the impact energy radiated into the half-space.
    pub energy_to_half_space: AxiEstimated,
    /// Contacts begun after a separation.
    pub reimpacts: usize,
}

/// Hertz's quasi-static impact of the same sphere (or paraboloid): no waves, no loss.
#[derive(Clone, Debug, PartialEq)]
pub struct HertzReport {
    /// The peak force over rho c1^2 R^2.
    pub peak_force_over_rho_c1sq_rsq: f64,
    /// The contact duration c1 t/R.
    pub contact_c1t_over_r: f64,
    /// The largest contact radius a/R.
    pub largest_a_over_r: f64,
    /// The largest penetration h/R.
    pub largest_h_over_r: f64,
}

/// The first-order radiation of a free sphere (`docs/axisymmetric.md`, section 5): Hertz's
/// force history radiating as a point force, E = E_F Int (dF/dt)^2 dt, and Hunter's estimate
/// (the same with Hertz's force approximated by a half-sine).
#[derive(Clone, Debug, PartialEq)]
pub struct FirstOrderReport {
    /// The radiated share of the impact energy, first order.
    pub radiated_fraction: f64,
    /// Hunter's estimate of it.
    pub hunter_fraction: f64,
    /// The prefactor C of fraction = C (V0/c1)^(3/5) (first order).
    pub prefactor: f64,
    /// Hunter's prefactor.
    pub hunter_prefactor: f64,
    /// E_F mu c1: the point force's radiation constant (Miller and Pursey).
    pub point_force_constant: f64,
}

/// A pressure profile of the finest grid.
#[derive(Clone, Debug, PartialEq)]
pub struct AxiPressure {
    /// c1 t/R (the middle of the step).
    pub c1t_over_r: f64,
    /// The ring centres r/R.
    pub r_over_r: Vec<f64>,
    /// The rings' mean pressures over rho c1^2.
    pub p_over_rho_c1sq: Vec<f64>,
    /// Their absolute error estimates (`None` with one level).
    pub error_estimate: Option<Vec<f64>>,
}

/// The report of one axisymmetric run.
#[derive(Clone, Debug)]
pub struct AxiReport {
    /// The library version.
    pub version: String,
    /// The inputs.
    pub case: AxiCase,
    /// c2/c1.
    pub c2_over_c1: f64,
    /// c_R/c1.
    pub cr_over_c1: f64,
    /// dr/R of the finest level.
    pub dr_over_r: f64,
    /// c1 dt/R of the finest level.
    pub c1dt_over_r: f64,
    /// kappa = c1 dt/dr used (the request adjusted so that the end is a whole step).
    pub kappa: f64,
    /// The reported times c1 t/R.
    pub c1t_over_r: Vec<f64>,
    /// The history columns with their estimates.
    pub columns: Vec<Column>,
    /// (da/dt)/c1.
    pub adot_over_c1: Vec<f64>,
    /// The edge's speed range at each time ("" out of contact).
    pub stage: Vec<&'static str>,
    /// The largest force and its time.
    pub peak_force: Option<(f64, f64)>,
    /// The rebound of a free striker.
    pub rebound: Option<AxiReboundReport>,
    /// The energy audit of a free striker.
    pub energy_audit: Option<EnergyAudit>,
    /// The rings across the largest contact radius (finest grid).
    pub largest_contact_rings: usize,
    /// Hertz's values (free sphere or paraboloid).
    pub hertz: Option<HertzReport>,
    /// The first-order radiation (free sphere or paraboloid).
    pub first_order: Option<FirstOrderReport>,
    /// The observed orders (key, order).
    pub observed_order: Vec<(&'static str, f64)>,
    /// The pressure profiles asked for.
    pub pressure: Option<Vec<AxiPressure>>,
    /// The quantities without a value or estimate, with the reasons.
    pub unavailable: Vec<(String, String)>,
}

/// Hertz's impact of a rigid sphere (paraboloid of radius R) of mass M = mass_ratio rho R^3
/// at V0 on the half-space (E* = 2 mu/(1 - nu)), in the report's units: the peak force, the
/// contact duration (2.94324 h_max/V0), the largest contact radius and penetration.
pub fn hertz(poisson: f64, radius: f64, mass_ratio: f64, v0_over_c1: f64) -> HertzReport {
    let m2 = (1.0 - 2.0 * poisson) / (2.0 * (1.0 - poisson));
    let estar = 2.0 / (1.0 - poisson);
    let mass = mass_ratio / m2;
    let energy = 0.5 * mass * v0_over_c1 * v0_over_c1;
    let h = (15.0 * energy / (8.0 * estar * radius.sqrt())).powf(0.4);
    let force = 4.0 / 3.0 * estar * radius.sqrt() * h.powf(1.5);
    HertzReport {
        peak_force_over_rho_c1sq_rsq: force * m2,
        contact_c1t_over_r: HERTZ_DURATION * h / v0_over_c1,
        largest_a_over_r: (radius * h).sqrt(),
        largest_h_over_r: h,
    }
}

/// Hertz's contact duration over h_max/V0: 2 Int_0^1 dx/(1 - x^(5/2))^(1/2).
pub const HERTZ_DURATION: f64 = 2.943_275_184_324_705;

/// Int over Hertz's normalised force pulse of (d phi/d tau)^2, phi = F/F_max,
/// tau = t/t_c (the pulse from first contact to separation).
pub const HERTZ_PULSE_SLOPE: f64 = 4.685_148_538_378_613;

impl AxiReport {
    /// The report of the solved run `sol`, with the pressure profiles at the times
    /// `pressure_at` (c1 t/R, each within the run).
    pub fn of(sol: &SolvedAxi, version: &str, pressure_at: &[f64]) -> Result<Self, String> {
        let (rows, orders) = sol.history();
        let levels = sol.runs.len();
        let mut why: Vec<(String, String)> = vec![(
            "adot_over_c1".into(),
            super::impact::EDGE_SPEED_WITHOUT_ESTIMATE.into(),
        )];
        if levels < 2 {
            why.push((
                "error_estimate".into(),
                "one grid level (--levels 1): no refinement estimate".into(),
            ));
        }
        let free = matches!(sol.case.drive, Drive::Free { .. });
        let mut columns = Vec::new();
        let mut col = |key: &'static str, vals: Vec<Option<&impact::axisym::AxiValue>>| {
            if vals.iter().any(Option::is_none) {
                return;
            }
            let vals: Vec<&impact::axisym::AxiValue> = vals.into_iter().flatten().collect();
            columns.push(Column {
                key,
                values: vals
                    .iter()
                    .map(|v| Number {
                        value: v.value,
                        text: None,
                    })
                    .collect(),
                errors: if vals.iter().all(|v| v.error.is_some()) {
                    Some(vals.iter().map(|v| v.error.unwrap_or(0.0)).collect())
                } else {
                    None
                },
            });
        };
        let each = |f: &dyn Fn(&AxiRow) -> Option<&impact::axisym::AxiValue>| {
            rows.iter().map(f).collect::<Vec<_>>()
        };
        col(keys::H_OVER_R, each(&|r| Some(&r.h)));
        col(
            if free {
                keys::HDOT_OVER_V0
            } else {
                "hdot_over_c1"
            },
            each(&|r| Some(&r.hdot)),
        );
        col(A_OVER_R, each(&|r| Some(&r.a)));
        col(FORCE_OVER_RHO_C1SQ_RSQ, each(&|r| Some(&r.force)));
        if free {
            col(
                "kinetic_energy_over_rho_c1sq_Rcu",
                each(&|r| r.kinetic.as_ref()),
            );
        }
        col("work_over_rho_c1sq_Rcu", each(&|r| Some(&r.work)));
        if free {
            col("energy_defect", each(&|r| r.energy_defect.as_ref()));
        }
        if rows.iter().all(|r| r.radiated_fraction.is_some()) {
            col(
                RADIATED_ENERGY_FRACTION,
                each(&|r| r.radiated_fraction.as_ref()),
            );
        } else {
            // a driven striker before it has done work: the fraction of zero work
            let mut values = Vec::new();
            let mut errors = Vec::new();
            for r in &rows {
                let v = r.radiated_fraction.as_ref();
                values.push(Number {
                    value: v.map_or(0.0, |v| v.value),
                    text: None,
                });
                errors.push(v.and_then(|v| v.error).unwrap_or(0.0));
            }
            why.push((
                RADIATED_ENERGY_FRACTION.into(),
                "a driven striker's fraction is of the work done so far: 0 (with estimate 0) before the first work".into(),
            ));
            columns.push(Column {
                key: RADIATED_ENERGY_FRACTION,
                values,
                errors: (levels >= 2).then_some(errors),
            });
        }
        let rebound = match sol.rebound() {
            Ok(r) => {
                let v0 = match sol.case.drive {
                    Drive::Free { v0_over_c1, .. } => v0_over_c1,
                    _ => 0.0,
                };
                let est = |v: &impact::axisym::AxiValue, s: f64| AxiEstimated {
                    value: v.value * s,
                    error: v.error.map(|e| e * s),
                };
                Some(AxiReboundReport {
                    separation_c1t_over_r: est(&r.separation, 1.0),
                    restitution: est(&r.restitution, 1.0),
                    rebound_speed_over_c1: est(&r.restitution, v0),
                    energy_to_half_space: est(&r.radiated_fraction, 1.0),
                    reimpacts: r.reimpacts,
                })
            }
            Err(reason) => {
                if free {
                    for k in [
                        "restitution",
                        "separation_c1t_over_R",
                        "energy_to_half_space",
                    ] {
                        why.push((k.into(), reason.clone()));
                    }
                }
                None
            }
        };
        let energy_audit = free.then(|| {
            let largest = rows
                .iter()
                .filter_map(|r| r.energy_defect.as_ref())
                .fold(0.0f64, |a, d| a.max(d.value.abs()));
            EnergyAudit {
                largest_defect: largest,
                bound: ENERGY_DEFECT_BOUND,
                within_bound: largest <= ENERGY_DEFECT_BOUND,
                note: (largest > ENERGY_DEFECT_BOUND).then_some(match sol.case.law {
                    impact::EdgeLaw::Kinematic => "the kinematic law's contact is wider than Hertz's and its edge pulls (p ~ d^(-1/2)): the edge releases energy as it advances and takes it back as it recedes, as an adhesive contact's does; the defect is that energy, not an error of the march (docs/axisymmetric.md, section 6)",
                    impact::EdgeLaw::Signorini => "kinetic energy plus the work on the half-space drifted from the impact energy: refine the grid",
                }),
            }
        });
        let peak_force =
            rows.iter()
                .map(|r| (r.force.value, r.t))
                .fold(None, |acc: Option<(f64, f64)>, x| match acc {
                    Some(a) if a.0 >= x.0 => Some(a),
                    _ => Some(x),
                });
        let fine = &sol.runs[0];
        let largest_a = fine.steps.iter().map(|s| s.a).fold(0.0, f64::max);
        let largest_contact_rings = (largest_a / fine.dr).round() as usize;
        if largest_contact_rings < MIN_CONTACT_RINGS {
            why.push((
                "resolution".into(),
                format!(
                    "the largest contact radius spans {largest_contact_rings} rings of the finest grid, fewer than {MIN_CONTACT_RINGS}: the estimates may not hold; refine --dr"
                ),
            ));
        }
        let (hertz_r, first_order) = match (&sol.case.profile, &sol.case.drive) {
            (
                AxiProfile::Sphere { radius } | AxiProfile::Paraboloid { radius },
                Drive::Free {
                    mass_ratio,
                    v0_over_c1,
                },
            ) => {
                let hz = hertz(sol.case.poisson, *radius, *mass_ratio, *v0_over_c1);
                let fo = first_order(sol, &hz, *mass_ratio, *v0_over_c1);
                (Some(hz), fo)
            }
            _ => (None, None),
        };
        let mut pressure = None;
        if !pressure_at.is_empty() {
            let mut list = Vec::new();
            for &t in pressure_at {
                list.push(profile_at(sol, t)?);
            }
            pressure = Some(list);
        }
        let c1t_over_r = rows.iter().map(|r| r.t).collect();
        let adot_over_c1 = rows.iter().map(|r| r.adot).collect();
        let stage = rows
            .iter()
            .map(|r| r.stage.map_or("", |s| s.name()))
            .collect();
        let kappa = fine.dt / fine.dr;
        for c in &columns {
            if c.values.iter().any(|v| !v.value.is_finite())
                || c.errors.iter().flatten().any(|e| !e.is_finite())
            {
                return Err(format!("{} is not finite", c.key));
            }
        }
        Ok(AxiReport {
            version: version.to_string(),
            case: sol.case.clone(),
            c2_over_c1: sol.m,
            cr_over_c1: sol.s_r,
            dr_over_r: fine.dr,
            c1dt_over_r: fine.dt,
            kappa,
            c1t_over_r,
            columns,
            adot_over_c1,
            stage,
            peak_force,
            rebound,
            energy_audit,
            largest_contact_rings,
            hertz: hertz_r,
            first_order,
            observed_order: orders,
            pressure,
            unavailable: why,
        })
    }

    fn column(&self, key: &str) -> Option<&Column> {
        self.columns.iter().find(|c| c.key == key)
    }

    fn est_json(e: &AxiEstimated) -> Value {
        match e.error {
            Some(err) => json!({"value": e.value, "error_estimate": err}),
            None => json!({"value": e.value}),
        }
    }

    /// The report as one JSON object, keys in [`AXI_KEYS`] order.
    pub fn to_json(&self) -> Value {
        let c = &self.case;
        let mut o = Map::new();
        o.insert("version".into(), json!(self.version));
        o.insert("geometry".into(), json!("axisymmetric"));
        o.insert("law".into(), json!(c.law.name()));
        o.insert("striker".into(), json!("rigid"));
        o.insert("profile".into(), json!(c.profile.label()));
        match &c.drive {
            Drive::Free {
                mass_ratio,
                v0_over_c1,
            } => {
                o.insert("mass_ratio".into(), json!(mass_ratio));
                o.insert("v0_over_c1".into(), json!(v0_over_c1));
            }
            Drive::Speed(v) => {
                o.insert("driven".into(), json!({"V_over_c1": v}));
            }
            Drive::Table(t) => {
                o.insert("driven".into(), json!({"table_points": t.len()}));
            }
        }
        o.insert(
            "end".into(),
            match c.stop {
                Stop::AtEnd => json!({"c1t_over_R": c.end}),
                Stop::AtSeparation => json!({"separation": true, "max_c1t_over_R": c.end}),
            },
        );
        o.insert("poisson".into(), json!(c.poisson));
        o.insert("c2_over_c1".into(), json!(self.c2_over_c1));
        o.insert("cR_over_c1".into(), json!(self.cr_over_c1));
        o.insert(
            "grid".into(),
            json!({
                "dr_over_R": self.dr_over_r,
                "c1dt_over_R": self.c1dt_over_r,
                "kappa": self.kappa,
                "levels": c.levels,
            }),
        );
        for col in &self.columns {
            o.insert(
                col.key.into(),
                Value::Array(col.values.iter().map(Number::json).collect()),
            );
        }
        o.insert("c1t_over_R".into(), json!(self.c1t_over_r));
        o.insert("adot_over_c1".into(), json!(self.adot_over_c1));
        o.insert("stage".into(), json!(self.stage));
        let mut errors = Map::new();
        for col in &self.columns {
            if let Some(e) = &col.errors {
                errors.insert(col.key.into(), json!(e));
            }
        }
        if let Some((f, t)) = self.peak_force {
            o.insert(
                "peak_force".into(),
                json!({"force_over_rho_c1sq_Rsq": f, "c1t_over_R": t}),
            );
        }
        if let Some(r) = &self.rebound {
            o.insert(
                "separation_c1t_over_R".into(),
                Self::est_json(&r.separation_c1t_over_r),
            );
            o.insert("restitution".into(), json!(r.restitution.value));
            o.insert(
                "rebound_speed_over_c1".into(),
                json!(r.rebound_speed_over_c1.value),
            );
            o.insert(
                "energy_to_half_space".into(),
                json!(r.energy_to_half_space.value),
            );
            o.insert("reimpacts".into(), json!(r.reimpacts));
            for (k, e) in [
                ("restitution", r.restitution.error),
                ("rebound_speed_over_c1", r.rebound_speed_over_c1.error),
                ("energy_to_half_space", r.energy_to_half_space.error),
            ] {
                if let Some(e) = e {
                    errors.insert(k.into(), json!(e));
                }
            }
        }
        if let Some(a) = &self.energy_audit {
            let mut audit = json!({"largest_defect": a.largest_defect, "bound": a.bound, "within_bound": a.within_bound});
            if let Some(note) = a.note {
                audit["note"] = json!(note);
            }
            o.insert("energy_audit".into(), audit);
        }
        o.insert(
            "resolution".into(),
            json!({
                "largest_contact_rings": self.largest_contact_rings,
                "least_rings": MIN_CONTACT_RINGS,
                "under_resolved": self.largest_contact_rings < MIN_CONTACT_RINGS,
            }),
        );
        if let Some(h) = &self.hertz {
            o.insert(
                "hertz".into(),
                json!({
                    "peak_force_over_rho_c1sq_Rsq": h.peak_force_over_rho_c1sq_rsq,
                    "contact_c1t_over_R": h.contact_c1t_over_r,
                    "largest_a_over_R": h.largest_a_over_r,
                    "largest_h_over_R": h.largest_h_over_r,
                }),
            );
        }
        if let Some(f) = &self.first_order {
            o.insert(
                "first_order_radiation".into(),
                json!({
                    "radiated_energy_fraction": f.radiated_fraction,
                    "prefactor": f.prefactor,
                    "hunter_radiated_energy_fraction": f.hunter_fraction,
                    "hunter_prefactor": f.hunter_prefactor,
                    "point_force_constant_mu_c1": f.point_force_constant,
                }),
            );
        }
        // every history's estimates are the conservative bound
        let models: serde_json::Map<String, Value> = errors
            .iter()
            .filter_map(|(k, v)| {
                let rows = v.as_array()?.len();
                Some((
                    k.clone(),
                    super::error_model_json(&impact::ErrorModel::conservative(rows)),
                ))
            })
            .collect();
        o.insert("error_estimate".into(), Value::Object(errors));
        o.insert(
            "observed_order".into(),
            Value::Object(
                self.observed_order
                    .iter()
                    .map(|(k, p)| (k.to_string(), json!(p)))
                    .collect(),
            ),
        );
        if !models.is_empty() {
            o.insert("error_model".into(), Value::Object(models));
        }
        if let Some(list) = &self.pressure {
            o.insert(
                "pressure".into(),
                Value::Array(
                    list.iter()
                        .map(|p| {
                            let mut q = json!({
                                "c1t_over_R": p.c1t_over_r,
                                "r_over_R": p.r_over_r,
                                "p_over_rho_c1sq": p.p_over_rho_c1sq,
                            });
                            if let Some(e) = &p.error_estimate {
                                q["error_estimate"] = json!(e);
                            }
                            q
                        })
                        .collect(),
                ),
            );
        }
        o.insert(
            "unavailable".into(),
            Value::Object(
                self.unavailable
                    .iter()
                    .map(|(k, r)| (k.clone(), json!(r)))
                    .collect(),
            ),
        );
        Value::Object(o)
    }

    /// CSV with `#` header lines (the inputs, the scalar results, the reasons of what is
    /// unavailable), one row per reported time ([`AXI_COLUMNS`]), then the pressure profiles.
    pub fn to_csv(&self, cmdline: &str) -> String {
        let c = &self.case;
        let mut s = String::new();
        s.push_str(&format!("# impact run {} (axisymmetric)\n", self.version));
        s.push_str(&format!("# command: {cmdline}\n"));
        s.push_str(&format!(
            "# striker: rigid; law: {}; profile: {}; poisson: {}; dr/R: {}; c1 dt/R: {}; levels: {}\n",
            c.law.name(),
            c.profile.label(),
            json!(c.poisson),
            json!(self.dr_over_r),
            json!(self.c1dt_over_r),
            c.levels
        ));
        s.push_str("# dimensionless: r/R, c1 t/R, h/R, speeds over c1 (hdot over V0 for a free striker), force over rho c1^2 R^2, energies over rho c1^2 R^3; err_* are absolute error estimates\n");
        if let Some(r) = &self.rebound {
            for (k, v) in [
                ("separation_c1t_over_R", &r.separation_c1t_over_r),
                ("restitution", &r.restitution),
                ("rebound_speed_over_c1", &r.rebound_speed_over_c1),
                ("energy_to_half_space", &r.energy_to_half_space),
            ] {
                let err = v
                    .error
                    .map(|e| format!(" (error estimate {})", json!(e)))
                    .unwrap_or_default();
                s.push_str(&format!("# {k}: {}{err}\n", json!(v.value)));
            }
        }
        if let Some(h) = &self.hertz {
            s.push_str(&format!(
                "# hertz: peak force {} at a contact duration {}, largest a/R {}\n",
                json!(h.peak_force_over_rho_c1sq_rsq),
                json!(h.contact_c1t_over_r),
                json!(h.largest_a_over_r)
            ));
        }
        for (key, reason) in &self.unavailable {
            s.push_str(&format!("# unavailable: {key}: {reason}\n"));
        }
        let cells = |key: &str| -> Option<Vec<String>> {
            match key {
                "c1t_over_R" => Some(
                    self.c1t_over_r
                        .iter()
                        .map(|x| json!(x).to_string())
                        .collect(),
                ),
                "adot_over_c1" => Some(
                    self.adot_over_c1
                        .iter()
                        .map(|x| json!(x).to_string())
                        .collect(),
                ),
                "stage" => Some(self.stage.iter().map(|s| s.to_string()).collect()),
                k => self
                    .column(k)
                    .map(|c| c.values.iter().map(Number::cell).collect()),
            }
        };
        let cols: Vec<(&str, Vec<String>)> = AXI_COLUMNS
            .iter()
            .filter_map(|k| cells(k).map(|v| (*k, v)))
            .collect();
        let errs: Vec<(String, Vec<String>)> = cols
            .iter()
            .filter_map(|(k, _)| {
                let e = self.column(k)?.errors.as_ref()?;
                Some((
                    format!("err_{k}"),
                    e.iter().map(|x| json!(x).to_string()).collect(),
                ))
            })
            .collect();
        let mut head: Vec<String> = cols.iter().map(|(k, _)| k.to_string()).collect();
        head.extend(errs.iter().map(|(k, _)| k.clone()));
        s.push_str(&head.join(","));
        s.push('\n');
        for i in 0..self.c1t_over_r.len() {
            let mut line: Vec<String> = cols.iter().map(|(_, v)| v[i].clone()).collect();
            line.extend(errs.iter().map(|(_, v)| v[i].clone()));
            s.push_str(&line.join(","));
            s.push('\n');
        }
        for p in self.pressure.iter().flatten() {
            s.push_str(&format!(
                "# pressure at c1t/R = {}\nr_over_R,p_over_rho_c1sq,error_estimate\n",
                json!(p.c1t_over_r)
            ));
            for (i, (r, q)) in p.r_over_r.iter().zip(&p.p_over_rho_c1sq).enumerate() {
                let e = p
                    .error_estimate
                    .as_ref()
                    .and_then(|e| e.get(i))
                    .map(|x| json!(x).to_string())
                    .unwrap_or_default();
                s.push_str(&format!("{},{},{e}\n", json!(r), json!(q)));
            }
        }
        s
    }
}

/// The first-order radiation of the free sphere: E_F Int (dF/dt)^2 dt over Hertz's pulse
/// (docs/axisymmetric.md, section 5), and Hunter's half-sine version.
fn first_order(
    sol: &SolvedAxi,
    hz: &HertzReport,
    mass_ratio: f64,
    v0: f64,
) -> Option<FirstOrderReport> {
    let ef = lamb::HalfSpace::from_poisson(sol.case.poisson)
        .ok()?
        .radiation_constant()
        .ok()?
        .value;
    let m2 = sol.m * sol.m;
    // in the march's units (mu = c1 = 1): force F = report/m^2, energy (1/2) M V0^2
    let f = hz.peak_force_over_rho_c1sq_rsq / m2;
    let tc = hz.contact_c1t_over_r;
    let e0 = 0.5 * mass_ratio / m2 * v0 * v0;
    let frac = ef * f * f / tc * HERTZ_PULSE_SLOPE / e0;
    let hunter = ef * f * f / tc * std::f64::consts::PI.powi(2) / 2.0 / e0;
    let scale = v0.powf(0.6);
    Some(FirstOrderReport {
        radiated_fraction: frac,
        hunter_fraction: hunter,
        prefactor: frac / scale,
        hunter_prefactor: hunter / scale,
        point_force_constant: ef,
    })
}

/// The finest grid's ring pressures at the report time nearest to `t`, with estimates from
/// the next level: its ring means against the fine rings' area means over its rings, over the
/// same time (the fine level's two last steps), plus the ring-to-ring and step-to-step
/// oscillations the comparison cannot see.
fn profile_at(sol: &SolvedAxi, t: f64) -> Result<AxiPressure, String> {
    let dt_c = sol.report_dt();
    let n_rep = sol.runs.last().map_or(0, |r| r.steps.len());
    if !(t > 0.0 && t <= n_rep as f64 * dt_c * (1.0 + 1e-12)) {
        return Err(format!(
            "invalid --pressure-at time {t}: admissible range is (0, {}], the run's times",
            n_rep as f64 * dt_c
        ));
    }
    let k = ((t / dt_c).round() as usize).clamp(1, n_rep);
    let fine = &sol.runs[0];
    let ratio = (dt_c / fine.dt).round() as usize;
    let n = k * ratio; // 1-based
    let m2 = sol.m * sol.m;
    let s = &fine.steps[n - 1];
    let p: Vec<f64> = s.pressure.iter().map(|x| x * m2).collect();
    let r = (0..p.len()).map(|i| i as f64 * fine.dr).collect();
    let error_estimate = sol.runs.get(1).map(|mid| {
        let prev = if n >= 2 {
            &fine.steps[n - 2].pressure
        } else {
            &s.pressure
        };
        let at = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(0.0) * m2;
        let pair: Vec<f64> = (0..p.len().max(prev.len()))
            .map(|i| 0.5 * (at(&s.pressure, i) + at(prev, i)))
            .collect();
        // the fine pair's area means over the coarse rings: coarse ring c spans fine rings
        // 2c - 1 (outer half), 2c, 2c + 1 (inner half)
        let half_area = |i: usize, outer: bool| -> f64 {
            // the area over pi of the outer or inner half of fine ring i (unit dr)
            let (a, b) = if outer {
                (i as f64, i as f64 + 0.5)
            } else {
                ((i as f64 - 0.5).max(0.0), i as f64)
            };
            b * b - a * a
        };
        let mid_step = &mid.steps[n / 2 - 1].pressure;
        let nc = mid_step.len().max(pair.len().div_ceil(2) + 1);
        let d: Vec<f64> = (0..nc)
            .map(|c| {
                let mut num = 0.0;
                let mut den = 0.0;
                let mut add = |i: usize, w: f64| {
                    num += w * pair.get(i).copied().unwrap_or(0.0);
                    den += w;
                };
                if c == 0 {
                    add(0, 0.25);
                    add(1, half_area(1, false));
                } else {
                    add(2 * c - 1, half_area(2 * c - 1, true));
                    add(2 * c, half_area(2 * c, true) + half_area(2 * c, false));
                    add(2 * c + 1, half_area(2 * c + 1, false));
                }
                (num / den - at(mid_step, c)).abs()
            })
            .collect();
        (0..p.len())
            .map(|j| {
                let c = j.div_ceil(2);
                let near = d[c.saturating_sub(1)..(c + 2).min(d.len())]
                    .iter()
                    .fold(0.0f64, |a, &x| a.max(x));
                let left = if j == 0 {
                    p[1.min(p.len() - 1)]
                } else {
                    p[j - 1]
                };
                let right = p.get(j + 1).copied().unwrap_or(0.0);
                4.0 * near + (p[j] - 0.5 * (left + right)).abs() + (p[j] - pair[j]).abs()
            })
            .collect()
    });
    Ok(AxiPressure {
        c1t_over_r: s.t - 0.5 * fine.dt,
        r_over_r: r,
        p_over_rho_c1sq: p,
        error_estimate,
    })
}
