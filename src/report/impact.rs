//! Typed reports of the impact engine: [`RunReport`] (`impact run`, a striker's transient
//! impact from crate `impact`), [`GreenReport`] (`impact green`, Lamb's surface influence
//! functions from crate `lamb`) and [`EdgeReport`] (`impact edge`, the pressure's power law at
//! a moving contact edge, `docs/edge.md`).
//!
//! Each report echoes its inputs, carries every number with its error estimate (or the
//! reason it has none, under `unavailable`), and lists its keys in order ([`RUN_KEYS`],
//! [`GREEN_KEYS`], [`EDGE_KEYS`]). JSON and CSV are written here, from the typed fields:
//! [`RunReport::to_json`], [`RunReport::to_csv`], and the same for the other two.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use complexfn::Real;
use impact::scalar::Scalar;
use impact::{Drive, EdgeLaw, ImpactCase, SolvedImpact, Stop, Striker, Value as Est};
use lamb::{Estimate, HalfPlane, Triple};
use serde_json::{json, Map, Value};

use super::{num, Number};

/// The report keys that other code (the figures, other front ends) names: each spelled
/// once, here; the key lists are made of them.
pub mod keys {
    /// `b_over_R`.
    pub const B_OVER_R: &str = "b_over_R";
    /// `bdot_over_c1`.
    pub const BDOT_OVER_C1: &str = "bdot_over_c1";
    /// `c1t_over_R`.
    pub const C1T_OVER_R: &str = "c1t_over_R";
    /// `force_over_rho_c1sq_R`.
    pub const FORCE_OVER_RHO_C1SQ_R: &str = "force_over_rho_c1sq_R";
    /// `h_over_R`.
    pub const H_OVER_R: &str = "h_over_R";
    /// `hdot_over_v0`.
    pub const HDOT_OVER_V0: &str = "hdot_over_v0";
    /// `law`.
    pub const LAW: &str = "law";
    /// `poisson`.
    pub const POISSON: &str = "poisson";
    /// `stage`.
    pub const STAGE: &str = "stage";
    /// `striker`.
    pub const STRIKER: &str = "striker";
    /// `x_over_R`.
    pub const X_OVER_R: &str = "x_over_R";
    /// `p_over_rho_c1sq`.
    pub const P_OVER_RHO_C1SQ: &str = "p_over_rho_c1sq";
    /// `speed_over_c1`.
    pub const SPEED_OVER_C1: &str = "speed_over_c1";
    /// `range`.
    pub const RANGE: &str = "range";
    /// `err_b_over_R`, the error estimates of `b_over_R` in a CSV.
    pub const ERR_B_OVER_R: &str = "err_b_over_R";
    /// `err_force_over_rho_c1sq_R`, the error estimates of `force_over_rho_c1sq_R` in a CSV.
    pub const ERR_FORCE_OVER_RHO_C1SQ_R: &str = "err_force_over_rho_c1sq_R";
    /// `err_h_over_R`, the error estimates of `h_over_R` in a CSV.
    pub const ERR_H_OVER_R: &str = "err_h_over_R";
}

/// Why the edge's speed (`bdot_over_c1`, `adot_over_c1`) carries no estimate.
pub const EDGE_SPEED_WITHOUT_ESTIMATE: &str = "the edge's speed carries no error estimate: it is the centred difference of the finest grid's edge over one report interval either side, and names the stage";

/// The bound of |energy_defect| above which a run's energy audit is flagged.
pub const ENERGY_DEFECT_BOUND: f64 = 1e-2;

/// The fewest cells across the largest contact half-width of the finest grid for a contact
/// not to be flagged as under-resolved.
pub const MIN_CONTACT_CELLS: usize = 10;

/// The keys of a [`RunReport`] as JSON, in order (each present when it applies: see the
/// field of the same name).
pub const RUN_KEYS: &[&str] = &[
    "version",
    keys::LAW,
    keys::STRIKER,
    "striker_model",
    "profile",
    "mass_ratio",
    "v0_over_c1",
    "driven",
    "end",
    keys::POISSON,
    "c2_over_c1",
    "cR_over_c1",
    "precision",
    "grid",
    keys::H_OVER_R,
    keys::HDOT_OVER_V0,
    "hdot_over_c1",
    keys::B_OVER_R,
    keys::FORCE_OVER_RHO_C1SQ_R,
    "kinetic_energy_over_rho_c1sq_Rsq",
    "work_over_rho_c1sq_Rsq",
    "striker_deformation_over_R",
    "striker_energy_over_rho_c1sq_Rsq",
    "energy_defect",
    keys::C1T_OVER_R,
    keys::BDOT_OVER_C1,
    keys::STAGE,
    "peak_force",
    "largest_force",
    "separation_c1t_over_R",
    "restitution",
    "rebound_speed_over_c1",
    "energy_to_half_plane",
    "reimpacts",
    "energy_audit",
    "resolution",
    "error_estimate",
    "observed_order",
    "error_model",
    "edge_without_solution",
    "pressure",
    "unavailable",
    "striker_strain_energy_over_rho_c1sq_Rsq",
    "striker_vibration_energy_over_rho_c1sq_Rsq",
];

/// The columns of a run's CSV table, in order (those the run has; then `err_<key>` for each
/// that carries an error estimate).
pub const RUN_COLUMNS: &[&str] = &[
    keys::C1T_OVER_R,
    keys::H_OVER_R,
    keys::HDOT_OVER_V0,
    "hdot_over_c1",
    keys::B_OVER_R,
    keys::BDOT_OVER_C1,
    keys::STAGE,
    keys::FORCE_OVER_RHO_C1SQ_R,
    "kinetic_energy_over_rho_c1sq_Rsq",
    "work_over_rho_c1sq_Rsq",
    "striker_deformation_over_R",
    "striker_energy_over_rho_c1sq_Rsq",
    "striker_strain_energy_over_rho_c1sq_Rsq",
    "striker_vibration_energy_over_rho_c1sq_Rsq",
    "energy_defect",
];

/// The scalar results a run's CSV lists in its `#` header, in order.
const RUN_SUMMARY_KEYS: &[&str] = &[
    "mass_ratio",
    "v0_over_c1",
    "separation_c1t_over_R",
    "restitution",
    "rebound_speed_over_c1",
    "energy_to_half_plane",
    "reimpacts",
    "peak_force",
    "largest_force",
    "energy_audit",
    "resolution",
];

/// Why a run's report could not be formed.
#[derive(Clone, Debug, PartialEq)]
pub enum ReportError {
    /// A pressure profile asked for at a time outside the run (the message says which).
    PressureTime(String),
    /// A reported value that is not finite (its key).
    NotFinite(String),
}

/// One history column: a value per reported time and, where estimated, an absolute error
/// estimate per value (from the grid levels).
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// The report key (also the CSV column).
    pub key: &'static str,
    /// The finest grid's values.
    pub values: Vec<Number>,
    /// The absolute error estimates, one per value; `None` where the run has none (the
    /// reason is under [`RunReport::unavailable`]).
    pub errors: Option<Vec<f64>>,
}

/// The largest contact force of a run and its time.
#[derive(Clone, Debug, PartialEq)]
pub struct ForcePeak {
    /// R/(rho c1^2 R).
    pub force_over_rho_c1sq_r: Number,
    /// c1 t/R.
    pub c1t_over_r: Number,
    /// Whether the force turned down after it (a peak) or was still rising at the end (the
    /// largest so far).
    pub turned_down: bool,
}

/// A number with its absolute error estimate, `None` where there is none (the reason under
/// [`RunReport::unavailable`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Estimated {
    /// The value.
    pub value: Number,
    /// The absolute error estimate.
    pub error: Option<f64>,
}

/// The rebound of a free striker after its last separation ([`impact::Rebound`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ReboundReport {
    /// c1 t/R at the last separation.
    pub separation_c1t_over_r: Estimated,
    /// The coefficient of restitution -V_final/V0.
    pub restitution: Estimated,
    /// The rebound speed V_final/c1 (restitution times V0/c1, its estimate likewise).
    pub rebound_speed_over_c1: Estimated,
    /// The share of the impact energy carried off by the half-plane.
    pub energy_to_half_plane: Estimated,
    /// Contacts begun after a separation.
    pub reimpacts: usize,
}

/// The energy audit: the largest |energy_defect| of the history against
/// [`ENERGY_DEFECT_BOUND`].
#[derive(Clone, Debug, PartialEq)]
pub struct EnergyAudit {
    /// The largest |energy_defect|.
    pub largest_defect: f64,
    /// [`ENERGY_DEFECT_BOUND`].
    pub bound: f64,
    /// Whether the largest defect is within the bound.
    pub within_bound: bool,
    /// Why not, when not.
    pub note: Option<&'static str>,
}

/// An interval of time where a prescribed (kinematic) edge ran between c_R and c1
/// (`docs/edge.md`, section 5).
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeWithoutSolution {
    /// c1 t/R at its start.
    pub from_c1t_over_r: Number,
    /// c1 t/R at its end.
    pub to_c1t_over_r: Number,
}

/// The reason reported for an [`EdgeWithoutSolution`] interval.
pub const EDGE_WITHOUT_SOLUTION: &str = "the prescribed (kinematic) edge ran between c_R and c1, where a steadily moving prescribed edge has no solution (docs/edge.md, section 5); the pressure near the edge does not converge there";

/// A pressure profile of the finest grid.
#[derive(Clone, Debug, PartialEq)]
pub struct PressureReport {
    /// c1 t/R.
    pub c1t_over_r: Number,
    /// The cell centres x/R.
    pub x_over_r: Vec<Number>,
    /// The cells' mean pressures p/(rho c1^2).
    pub p_over_rho_c1sq: Vec<Number>,
    /// Their absolute error estimates (`None` with one grid level).
    pub error_estimate: Option<Vec<f64>>,
}

/// The grid of a run, finest level.
#[derive(Clone, Debug, PartialEq)]
pub struct GridReport {
    /// dx/R.
    pub dx_over_r: Number,
    /// c1 dt/R.
    pub c1dt_over_r: Number,
    /// kappa = c1 dt/dx as asked.
    pub kappa: f64,
    /// Grid levels.
    pub levels: usize,
    /// `model` or `whole`.
    pub edge_cell: &'static str,
    /// How many times the grid was halved for the first steps (0: one grid throughout;
    /// `docs/impact.md`, section 11).
    pub start_halvings: usize,
    /// The peak memory the run was estimated to need before it started, GiB
    /// (`impact::cost`, `docs/impact.md`, section 10).
    pub estimated_memory_gib: f64,
}

/// The contact's resolution on the finest grid.
#[derive(Clone, Debug, PartialEq)]
pub struct Resolution {
    /// The largest contact half-width in cells.
    pub largest_contact_cells: usize,
    /// [`MIN_CONTACT_CELLS`].
    pub least_cells: usize,
    /// Whether the contact spans fewer cells than that.
    pub under_resolved: bool,
}

/// The report of one impact run (`impact run`): the inputs echoed, the histories with their
/// estimates, the rebound, the audits. Dimensionless: x/R, c1 t/R, h/R, speeds over c1 (the
/// penetration speed over V0 for a free striker), force over rho c1^2 R, energies over
/// rho c1^2 R^2.
#[derive(Clone, Debug)]
pub struct RunReport {
    /// The library version.
    pub version: String,
    /// The inputs of the run.
    pub case: ImpactCase,
    /// c2/c1.
    pub c2_over_c1: Number,
    /// c_R/c1.
    pub cr_over_c1: Number,
    /// The significant digits of a double-double run (`None` for f64).
    pub digits: Option<usize>,
    /// The finest grid.
    pub grid: GridReport,
    /// The reported times c1 t/R.
    pub c1t_over_r: Vec<Number>,
    /// The history columns with their estimates ([`RUN_KEYS`] order).
    pub columns: Vec<Column>,
    /// (db/dt)/c1 at each reported time.
    pub bdot_over_c1: Vec<Number>,
    /// The edge's speed range at each reported time.
    pub stage: Vec<&'static str>,
    /// The largest force and whether it is a peak.
    pub peak: Option<ForcePeak>,
    /// The rebound of a free striker that separated.
    pub rebound: Option<ReboundReport>,
    /// The energy audit of a free striker.
    pub energy_audit: Option<EnergyAudit>,
    /// The contact's resolution.
    pub resolution: Resolution,
    /// The observed convergence orders (key, order).
    pub observed_order: Vec<(&'static str, f64)>,
    /// How each estimated history's estimates were formed (key, model; `docs/impact.md`,
    /// section 5).
    pub error_model: Vec<(&'static str, impact::ErrorModel)>,
    /// Where a prescribed edge ran between c_R and c1.
    pub edge_without_solution: Vec<EdgeWithoutSolution>,
    /// The pressure profiles asked for.
    pub pressure: Option<Vec<PressureReport>>,
    /// A shell's or a cylinder's strain and vibration energies (f64 runs).
    pub striker_energy_parts: Vec<Column>,
    /// The quantities without a value or an estimate, with the reasons (key, reason).
    pub unavailable: Vec<(String, String)>,
}

fn number<T: Scalar>(x: T, digits: Option<usize>) -> Number {
    Number {
        value: x.to_f64(),
        text: digits.map(|d| x.to_decimal(d)),
    }
}

fn estimated<T: Scalar>(v: &Est<T>, digits: Option<usize>) -> Estimated {
    Estimated {
        value: number(v.value, digits),
        error: v.error,
    }
}

/// V0/c1 of a free striker (0 when driven).
fn v0_of(c: &ImpactCase) -> f64 {
    match c.drive {
        Drive::Free { v0_over_c1, .. } => v0_over_c1,
        _ => 0.0,
    }
}

impl RunReport {
    /// The report of the solved run `sol` at `digits` significant digits (`None` for f64),
    /// with the pressure profiles at the times `pressure_at` (c1 t/R, each within the run).
    pub fn of<T: Scalar>(
        sol: &SolvedImpact<T>,
        version: &str,
        digits: Option<usize>,
        pressure_at: &[f64],
    ) -> Result<(Self, Vec<impact::HistoryRow<T>>), ReportError> {
        let dg = |x: T| number(x, digits);
        let (rows, orders) = sol.history();
        let driven = !matches!(sol.case.drive, Drive::Free { .. });
        let levels = sol.runs.len();
        let mut why: Vec<(String, String)> = vec![(
            keys::BDOT_OVER_C1.into(),
            EDGE_SPEED_WITHOUT_ESTIMATE.into(),
        )];
        if levels < 2 {
            why.push((
                "error_estimate".into(),
                "one grid level (--levels 1): no refinement estimate".into(),
            ));
        }
        let mut columns = Vec::new();
        let mut col = |key: &'static str, vals: Vec<&Est<T>>, why: &mut Vec<(String, String)>| {
            let values = vals.iter().map(|v| dg(v.value)).collect();
            let errors = if levels < 2 {
                None
            } else if vals.iter().all(|v| v.error.is_some()) {
                Some(vals.iter().map(|v| v.error.unwrap_or(0.0)).collect())
            } else {
                why.push((
                    format!("error_estimate.{key}"),
                    "a coarser level has no value at some reported time".into(),
                ));
                None
            };
            columns.push(Column {
                key,
                values,
                errors,
            });
        };
        let hdot_key = if driven {
            "hdot_over_c1"
        } else {
            "hdot_over_v0"
        };
        col("h_over_R", rows.iter().map(|r| &r.h).collect(), &mut why);
        col(hdot_key, rows.iter().map(|r| &r.hdot).collect(), &mut why);
        col("b_over_R", rows.iter().map(|r| &r.b).collect(), &mut why);
        col(
            "force_over_rho_c1sq_R",
            rows.iter().map(|r| &r.force).collect(),
            &mut why,
        );
        if !driven {
            col(
                "kinetic_energy_over_rho_c1sq_Rsq",
                rows.iter().filter_map(|r| r.kinetic.as_ref()).collect(),
                &mut why,
            );
        }
        col(
            "work_over_rho_c1sq_Rsq",
            rows.iter().map(|r| &r.work).collect(),
            &mut why,
        );
        if !matches!(sol.case.striker, Striker::Rigid) {
            col(
                "striker_deformation_over_R",
                rows.iter()
                    .filter_map(|r| r.striker_deformation.as_ref())
                    .collect(),
                &mut why,
            );
            col(
                "striker_energy_over_rho_c1sq_Rsq",
                rows.iter()
                    .filter_map(|r| r.striker_energy.as_ref())
                    .collect(),
                &mut why,
            );
        }
        if !driven {
            col(
                "energy_defect",
                rows.iter()
                    .filter_map(|r| r.energy_defect.as_ref())
                    .collect(),
                &mut why,
            );
        } else {
            why.push((
                "energy_defect".into(),
                "a driven striker has no impact energy to audit".into(),
            ));
        }
        // the estimator of each estimated column
        let error_model: Vec<(&'static str, impact::ErrorModel)> = match orders.models {
            Some(m) => columns
                .iter()
                .filter(|c| c.errors.is_some())
                .map(|c| {
                    let model = match c.key {
                        "h_over_R" => m.h,
                        "hdot_over_v0" | "hdot_over_c1" | "kinetic_energy_over_rho_c1sq_Rsq" => {
                            m.hdot
                        }
                        "b_over_R" => m.b,
                        "force_over_rho_c1sq_R" => m.force,
                        "work_over_rho_c1sq_Rsq" => m.work,
                        "energy_defect" => m.energy_defect,
                        _ => m.others,
                    };
                    (c.key, model)
                })
                .collect(),
            None => Vec::new(),
        };
        // the observed orders: a negative order (the level differences grow) is no order
        let mut observed_order = Vec::new();
        for (key, o) in [
            ("h_over_R", orders.h),
            ("b_over_R", orders.b),
            ("force_over_rho_c1sq_R", orders.force),
        ] {
            match o {
                Some(p) if p > 0.0 => observed_order.push((key, p)),
                Some(p) => why.push((
                    format!("observed_order.{key}"),
                    format!(
                        "not converging: the level differences grow from the finest pair to the coarsest (order {p:.2})"
                    ),
                )),
                None if levels < 3 => why.push((
                    format!("observed_order.{key}"),
                    "fewer than three grid levels".into(),
                )),
                None => why.push((
                    format!("observed_order.{key}"),
                    "the levels agree exactly: no order to observe".into(),
                )),
            }
        }
        let peak = match sol.peak_force() {
            Some((f, t, turned_down)) => {
                if !turned_down {
                    why.push((
                        "peak_force".into(),
                        "the force had not turned down by the end of the run: largest_force is the largest so far, not a peak".into(),
                    ));
                }
                Some(ForcePeak {
                    force_over_rho_c1sq_r: dg(f),
                    c1t_over_r: dg(t),
                    turned_down,
                })
            }
            None => {
                why.push(("peak_force".into(), "no contact force in the run".into()));
                None
            }
        };
        // the rebound of a free striker
        let rebound = match sol.rebound() {
            Ok(r) => {
                let v0 = v0_of(&sol.case);
                let rebound = ReboundReport {
                    separation_c1t_over_r: estimated(&r.separation, digits),
                    restitution: estimated(&r.restitution, digits),
                    rebound_speed_over_c1: Estimated {
                        value: dg(r.restitution.value * T::input(v0)),
                        error: r.restitution.error.map(|e| e * v0),
                    },
                    energy_to_half_plane: estimated(&r.energy_to_half_plane, digits),
                    reimpacts: r.reimpacts,
                };
                for (key, e) in [
                    ("restitution", &rebound.restitution),
                    ("rebound_speed_over_c1", &rebound.rebound_speed_over_c1),
                    ("energy_to_half_plane", &rebound.energy_to_half_plane),
                ] {
                    if e.error.is_none() {
                        why.push((
                            format!("error_estimate.{key}"),
                            "one grid level, or a coarser level still in contact at the end".into(),
                        ));
                    }
                }
                Some(rebound)
            }
            Err(reason) => {
                for key in [
                    "separation_c1t_over_R",
                    "restitution",
                    "rebound_speed_over_c1",
                    "energy_to_half_plane",
                ] {
                    why.push((key.into(), reason.clone()));
                }
                None
            }
        };
        // the energy audit: the largest |energy_defect| against its bound
        let energy_audit = rows
            .iter()
            .filter_map(|r| r.energy_defect.as_ref())
            .map(|d| d.value.to_f64().abs())
            // a NaN defect propagates (and is refused by the finiteness check)
            .reduce(|a, d| if a.is_nan() || d.is_nan() { f64::NAN } else { a.max(d) })
            .map(|worst| {
                let within = worst <= ENERGY_DEFECT_BOUND;
                EnergyAudit {
                    largest_defect: worst,
                    bound: ENERGY_DEFECT_BOUND,
                    within_bound: within,
                    note: (!within).then_some(if sol.case.law == EdgeLaw::Kinematic {
                        "the kinematic law's prescribed edge carries a finite energy flux (its pressure ~ d^(-1/2), its gap ~ s^(1/2)): the energy defect converges to that flux's work, not to 0 (docs/impact.md, section 9)"
                    } else {
                        "the energy does not close to the bound: refine the grid (--dx)"
                    }),
                }
            });
        // the contact's resolution: the largest contact half-width in cells of the finest grid
        let widest = sol.runs[0]
            .steps
            .iter()
            .map(|s| s.pressure.len())
            .max()
            .unwrap_or(0);
        if widest < MIN_CONTACT_CELLS {
            why.push((
                "resolution".into(),
                format!(
                    "under-resolved: the contact spans at most {widest} cells of the finest grid (at least {MIN_CONTACT_CELLS} wanted): refine --dx"
                ),
            ));
        }
        let pressure = if pressure_at.is_empty() {
            None
        } else {
            let last = sol.runs[0].steps.last().map_or(0.0, |s| s.t.to_f64());
            let mut list = Vec::new();
            for &t in pressure_at {
                if !(t > 0.0 && t <= last * (1.0 + 1e-12)) {
                    return Err(ReportError::PressureTime(format!(
                        "invalid --pressure-at time {t}: admissible range is (0, {last}], the run's times"
                    )));
                }
                if let Some(prof) = sol.pressure_profile(t) {
                    list.push(PressureReport {
                        c1t_over_r: dg(prof.t),
                        x_over_r: prof.x.iter().map(|&x| dg(x)).collect(),
                        p_over_rho_c1sq: prof.p.iter().map(|&p| dg(p)).collect(),
                        error_estimate: prof.err.clone(),
                    });
                }
            }
            Some(list)
        };
        let report = RunReport {
            version: version.to_string(),
            case: sol.case.clone(),
            c2_over_c1: dg(sol.m),
            cr_over_c1: dg(sol.s_r),
            digits,
            grid: GridReport {
                dx_over_r: dg(sol.runs[0].dx),
                c1dt_over_r: dg(sol.runs[0].dt),
                kappa: sol.case.kappa,
                levels,
                edge_cell: if sol.case.edge_model {
                    "model"
                } else {
                    "whole"
                },
                start_halvings: if sol.case.starts_finer() {
                    sol.case.start_halvings
                } else {
                    0
                },
                estimated_memory_gib: sol.case.cost_estimate().gib(),
            },
            c1t_over_r: rows.iter().map(|r| dg(r.t)).collect(),
            columns,
            bdot_over_c1: rows.iter().map(|r| dg(r.bdot)).collect(),
            stage: rows.iter().map(|r| r.stage.name()).collect(),
            peak,
            rebound,
            energy_audit,
            resolution: Resolution {
                largest_contact_cells: widest,
                least_cells: MIN_CONTACT_CELLS,
                under_resolved: widest < MIN_CONTACT_CELLS,
            },
            observed_order,
            error_model,
            edge_without_solution: sol
                .edge_without_solution()
                .into_iter()
                .map(|(from, to)| EdgeWithoutSolution {
                    from_c1t_over_r: dg(from),
                    to_c1t_over_r: dg(to),
                })
                .collect(),
            pressure,
            striker_energy_parts: Vec::new(),
            unavailable: why,
        };
        report.check_finite()?;
        Ok((report, rows))
    }

    /// Every reported number finite, or the key of the first that is not.
    fn check_finite(&self) -> Result<(), ReportError> {
        let bad = |key: &str| Err(ReportError::NotFinite(key.to_string()));
        let all = |xs: &[Number]| xs.iter().all(|x| x.value.is_finite());
        for col in self.columns.iter().chain(&self.striker_energy_parts) {
            if !all(&col.values) {
                return bad(col.key);
            }
            if col.errors.iter().flatten().any(|e| !e.is_finite()) {
                return bad(&format!("the error estimate of {}", col.key));
            }
        }
        if !all(&self.c1t_over_r) || !all(&self.bdot_over_c1) {
            return bad("c1t_over_R or bdot_over_c1");
        }
        if let Some(p) = &self.peak {
            if !all(&[p.force_over_rho_c1sq_r.clone(), p.c1t_over_r.clone()]) {
                return bad("peak_force");
            }
        }
        if let Some(r) = &self.rebound {
            for (k, e) in [
                ("separation_c1t_over_R", &r.separation_c1t_over_r),
                ("restitution", &r.restitution),
                ("rebound_speed_over_c1", &r.rebound_speed_over_c1),
                ("energy_to_half_plane", &r.energy_to_half_plane),
            ] {
                if !e.value.value.is_finite() || e.error.is_some_and(|x| !x.is_finite()) {
                    return bad(k);
                }
            }
        }
        if self
            .energy_audit
            .as_ref()
            .is_some_and(|a| !a.largest_defect.is_finite())
        {
            return bad("energy_defect");
        }
        for p in self.pressure.iter().flatten() {
            if !all(&p.x_over_r)
                || !all(&p.p_over_rho_c1sq)
                || p.error_estimate.iter().flatten().any(|e| !e.is_finite())
            {
                return bad("pressure");
            }
        }
        Ok(())
    }

    /// Adds a shell's or a cylinder's strain and vibration energies with their estimates
    /// (f64: those strikers run in f64 only).
    pub fn add_striker_energy(
        &mut self,
        sol: &SolvedImpact,
        rows: &[impact::HistoryRow],
    ) -> Result<(), impact::ImpactError> {
        let Some(parts) = sol.striker_energy_history(rows) else {
            return Ok(());
        };
        let parts = parts?;
        for (key, pick) in [
            ("striker_strain_energy_over_rho_c1sq_Rsq", 0),
            ("striker_vibration_energy_over_rho_c1sq_Rsq", 1),
        ] {
            let vals: Vec<&Est> = parts
                .iter()
                .map(|p| if pick == 0 { &p.0 } else { &p.1 })
                .collect();
            if vals
                .iter()
                .any(|v| !v.value.is_finite() || v.error.is_some_and(|e| !e.is_finite()))
            {
                return Err(impact::ImpactError::Step {
                    time: "the report".into(),
                    reason: format!("{key} is not finite"),
                });
            }
            self.striker_energy_parts.push(Column {
                key,
                values: vals.iter().map(|v| number(v.value, None)).collect(),
                // every value's estimate, or none (one grid level)
                errors: vals.iter().map(|v| v.error).collect(),
            });
        }
        Ok(())
    }

    /// The history column of `key`, if the run has it.
    pub fn column(&self, key: &str) -> Option<&Column> {
        self.columns
            .iter()
            .chain(&self.striker_energy_parts)
            .find(|c| c.key == key)
    }

    /// The report's entries as JSON values, in [`RUN_KEYS`] order (those the run has).
    pub fn entries(&self) -> Vec<(&'static str, Value)> {
        let c = &self.case;
        let mut out: Vec<(&'static str, Value)> = vec![
            ("version", json!(self.version)),
            ("law", json!(c.law.name())),
            ("striker", json!(c.striker.name())),
        ];
        if let Some(m) = self.striker_model_json() {
            out.push(("striker_model", m));
        }
        out.push(("profile", json!(c.profile.label())));
        self.push_summary(&mut out, &["mass_ratio", "v0_over_c1"]);
        match &c.drive {
            Drive::Free { .. } => {}
            Drive::Speed(v) => out.push(("driven", json!({"V_over_c1": v}))),
            Drive::Table(t) => out.push(("driven", json!({"table_points": t.len()}))),
        }
        out.push((
            "end",
            match c.stop {
                Stop::AtEnd => json!({"c1t_over_R": c.end}),
                Stop::AtSeparation => json!({"separation": true, "max_c1t_over_R": c.end}),
            },
        ));
        out.push(("poisson", json!(c.poisson)));
        out.push(("c2_over_c1", self.c2_over_c1.json()));
        out.push(("cR_over_c1", self.cr_over_c1.json()));
        if let Some(d) = self.digits {
            out.push((
                "precision",
                json!({"digits": d, "arithmetic": "double-double"}),
            ));
        }
        out.push(("grid", self.grid_json()));
        for col in &self.columns {
            out.push((col.key, numbers(&col.values)));
        }
        out.push(("c1t_over_R", numbers(&self.c1t_over_r)));
        out.push(("bdot_over_c1", numbers(&self.bdot_over_c1)));
        out.push(("stage", json!(self.stage)));
        self.push_summary(
            &mut out,
            &[
                "peak_force",
                "largest_force",
                "separation_c1t_over_R",
                "restitution",
                "rebound_speed_over_c1",
                "energy_to_half_plane",
                "reimpacts",
                "energy_audit",
                "resolution",
            ],
        );
        out.push(("error_estimate", Value::Object(self.errors_json())));
        let ords: Map<String, Value> = self
            .observed_order
            .iter()
            .map(|(k, p)| (k.to_string(), json!(p)))
            .collect();
        out.push(("observed_order", Value::Object(ords)));
        if !self.error_model.is_empty() {
            out.push(("error_model", Value::Object(self.error_model_json())));
        }
        out.push((
            "edge_without_solution",
            Value::Array(
                self.edge_without_solution
                    .iter()
                    .map(|e| {
                        json!({
                            "from_c1t_over_R": e.from_c1t_over_r.json(),
                            "to_c1t_over_R": e.to_c1t_over_r.json(),
                            "reason": EDGE_WITHOUT_SOLUTION,
                        })
                    })
                    .collect(),
            ),
        ));
        if let Some(list) = &self.pressure {
            out.push((
                "pressure",
                Value::Array(
                    list.iter()
                        .map(|p| {
                            json!({
                                "c1t_over_R": p.c1t_over_r.json(),
                                "x_over_R": numbers(&p.x_over_r),
                                "p_over_rho_c1sq": numbers(&p.p_over_rho_c1sq),
                                "error_estimate": p.error_estimate,
                            })
                        })
                        .collect(),
                ),
            ));
        }
        if !self.unavailable.is_empty() {
            let why: Map<String, Value> = self
                .unavailable
                .iter()
                .map(|(k, r)| (k.clone(), json!(r)))
                .collect();
            out.push(("unavailable", Value::Object(why)));
        }
        for col in &self.striker_energy_parts {
            out.push((col.key, numbers(&col.values)));
        }
        out
    }

    /// The striker's model, for a deformable striker.
    fn striker_model_json(&self) -> Option<Value> {
        let c = &self.case;
        match &c.striker {
            Striker::Rigid => None,
            Striker::Elastic(mat) => Some(
                json!({"c1_over_c1": mat.c1_ratio, "c2_over_c1": mat.c2_ratio, "density_ratio": mat.density_ratio,
                       "model": "local half-plane", "valid_until_c1t_over_R": c.striker.validity_end()}),
            ),
            Striker::Shell(s) => Some(
                json!({"thickness_over_R": s.thickness, "c1_over_c1": s.material.c1_ratio, "c2_over_c1": s.material.c2_ratio,
                       "density_ratio": s.material.density_ratio, "mass_ratio": s.mass_ratio(),
                       "model": "Timoshenko ring (membrane, bending, transverse shear, rotary inertia)"}),
            ),
            Striker::Cylinder(mat) => Some(
                json!({"c1_over_c1": mat.c1_ratio, "c2_over_c1": mat.c2_ratio, "density_ratio": mat.density_ratio,
                       "mass_ratio": c.striker.own_mass_ratio(),
                       "model": "free elastic disk (plane strain), its deformation by harmonics in the polar angle"}),
            ),
        }
    }

    /// A scalar result of the run ([`RUN_SUMMARY_KEYS`]) as JSON with its absolute estimate
    /// where it has one, or `None` when the run does not have it.
    fn summary(&self, key: &str) -> Option<(Value, Option<f64>)> {
        let rebound = self.rebound.as_ref();
        let peak = |down: bool| {
            self.peak
                .as_ref()
                .filter(|p| p.turned_down == down)
                .map(|p| (self.peak_json(p), None))
        };
        match key {
            "mass_ratio" | "v0_over_c1" => match self.case.drive {
                Drive::Free {
                    mass_ratio,
                    v0_over_c1,
                } => Some((
                    json!(if key == "mass_ratio" {
                        mass_ratio
                    } else {
                        v0_over_c1
                    }),
                    None,
                )),
                _ => None,
            },
            "separation_c1t_over_R" => rebound.map(|r| {
                let s = &r.separation_c1t_over_r;
                (
                    json!({"value": s.value.json(), "error_estimate": s.error}),
                    None,
                )
            }),
            "restitution" => rebound.map(|r| (r.restitution.value.json(), r.restitution.error)),
            "rebound_speed_over_c1" => rebound.map(|r| {
                (
                    r.rebound_speed_over_c1.value.json(),
                    r.rebound_speed_over_c1.error,
                )
            }),
            "energy_to_half_plane" => rebound.map(|r| {
                (
                    r.energy_to_half_plane.value.json(),
                    r.energy_to_half_plane.error,
                )
            }),
            "reimpacts" => rebound.map(|r| (json!(r.reimpacts), None)),
            "peak_force" => peak(true),
            "largest_force" => peak(false),
            "energy_audit" => self.energy_audit.as_ref().map(|a| {
                let mut audit = Map::new();
                audit.insert("largest_defect".into(), json!(a.largest_defect));
                audit.insert("bound".into(), json!(a.bound));
                audit.insert("within_bound".into(), json!(a.within_bound));
                if let Some(note) = a.note {
                    audit.insert("note".into(), json!(note));
                }
                (Value::Object(audit), None)
            }),
            "resolution" => {
                let r = &self.resolution;
                Some((
                    json!({
                        "largest_contact_cells": r.largest_contact_cells,
                        "least_cells": r.least_cells,
                        "under_resolved": r.under_resolved,
                    }),
                    None,
                ))
            }
            _ => None,
        }
    }

    /// Appends the summary entries of `keys` the run has.
    fn push_summary(&self, out: &mut Vec<(&'static str, Value)>, keys: &[&'static str]) {
        for k in keys {
            if let Some((v, _)) = self.summary(k) {
                out.push((k, v));
            }
        }
    }

    fn grid_json(&self) -> Value {
        let g = &self.grid;
        json!({
            "dx_over_R": g.dx_over_r.json(),
            "c1dt_over_R": g.c1dt_over_r.json(),
            "kappa": g.kappa,
            "levels": g.levels,
            "edge_cell": g.edge_cell,
            "start_halvings": g.start_halvings,
            "estimated_memory_gib": g.estimated_memory_gib,
        })
    }

    fn peak_json(&self, p: &ForcePeak) -> Value {
        json!({"force_over_rho_c1sq_R": p.force_over_rho_c1sq_r.json(), "c1t_over_R": p.c1t_over_r.json()})
    }

    /// The `error_model` object: per estimated column its estimator, the safety factor, the
    /// order credited and the rows that took the conservative bound.
    fn error_model_json(&self) -> Map<String, Value> {
        self.error_model
            .iter()
            .map(|(key, m)| (key.to_string(), super::error_model_json(m)))
            .collect()
    }

    /// The `error_estimate` object: per column an array, per rebound quantity a number
    fn errors_json(&self) -> Map<String, Value> {
        let mut errs = Map::new();
        for col in &self.columns {
            if let Some(e) = &col.errors {
                errs.insert(col.key.into(), json!(e));
            }
        }
        // the scalar results' estimates, as the CSV header gives them
        for key in RUN_SUMMARY_KEYS {
            if let Some((_, Some(e))) = self.summary(key) {
                errs.insert(key.to_string(), json!(e));
            }
        }
        for col in &self.striker_energy_parts {
            if let Some(e) = &col.errors {
                errs.insert(col.key.into(), json!(e));
            }
        }
        errs
    }

    /// The report as one JSON object ([`RUN_KEYS`] order).
    pub fn to_json(&self) -> Value {
        Value::Object(
            self.entries()
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect(),
        )
    }

    /// The report as CSV with `#` header lines (the inputs, the scalar results, the reasons
    /// of what is unavailable), one row per reported time ([`RUN_COLUMNS`]), then the
    /// pressure profiles. `cmdline` is written into the header.
    pub fn to_csv(&self, cmdline: &str) -> String {
        let c = &self.case;
        let mut s = String::new();
        s.push_str(&format!("# impact run {}\n", self.version));
        s.push_str(&format!("# command: {cmdline}\n"));
        s.push_str(&format!(
            "# striker: {}{}; law: {}; profile: {}; poisson: {}; grid: {}\n",
            c.striker.name(),
            self.striker_model_json()
                .map(|m| format!(" {m}"))
                .unwrap_or_default(),
            c.law.name(),
            c.profile.label(),
            json!(c.poisson),
            self.grid_json()
        ));
        s.push_str("# dimensionless: x/R, c1 t/R, h/R, speeds over c1 (hdot over V0 for a free striker), force over rho c1^2 R, energies over rho c1^2 R^2; err_* are absolute error estimates\n");
        for e in &self.edge_without_solution {
            s.push_str(&format!(
                "# edge without solution: c1 t/R from {} to {}: {}\n",
                e.from_c1t_over_r.json(),
                e.to_c1t_over_r.json(),
                EDGE_WITHOUT_SOLUTION
            ));
        }
        for key in RUN_SUMMARY_KEYS {
            if let Some((x, e)) = self.summary(key) {
                let err = e
                    .map(|e| format!(" (error estimate {})", json!(e)))
                    .unwrap_or_default();
                s.push_str(&format!("# {key}: {x}{err}\n"));
            }
        }
        for (key, m) in &self.error_model {
            let order = m
                .order_credited
                .map(|p| format!(", order credited {p:.3}"))
                .unwrap_or_default();
            let floor = if m.cell_floor_rows > 0 {
                format!("; at least half a cell at {} rows", m.cell_floor_rows)
            } else {
                String::new()
            };
            let shown = m
                .order_shown
                .map(|o| {
                    format!(
                        "; order {:.3} shown row by row, safety {}, at {} rows",
                        o.order_credited, o.safety, o.rows
                    )
                })
                .unwrap_or_default();
            s.push_str(&format!(
                "# error_model: {key}: {} (safety {}{order}; conservative rows: {}{floor}{shown})\n",
                m.estimator.name(),
                m.safety,
                m.conservative_rows,
            ));
        }
        for (key, reason) in &self.unavailable {
            s.push_str(&format!("# unavailable: {key}: {reason}\n"));
        }
        // the table: each column's cells as text, then the estimates of those that have them
        let cells = |key: &str| -> Option<Vec<String>> {
            match key {
                "c1t_over_R" => Some(self.c1t_over_r.iter().map(Number::cell).collect()),
                "bdot_over_c1" => Some(self.bdot_over_c1.iter().map(Number::cell).collect()),
                "stage" => Some(self.stage.iter().map(|s| s.to_string()).collect()),
                k => self
                    .column(k)
                    .map(|c| c.values.iter().map(Number::cell).collect()),
            }
        };
        let keys: Vec<(&str, Vec<String>)> = RUN_COLUMNS
            .iter()
            .filter_map(|k| cells(k).map(|v| (*k, v)))
            .collect();
        let errs: Vec<(&str, Vec<String>)> = keys
            .iter()
            .filter_map(|(k, _)| {
                let col = self.column(k)?;
                let e = col.errors.as_ref()?;
                Some((*k, e.iter().map(|&x| float_cell(x)).collect()))
            })
            .collect();
        let mut head: Vec<String> = keys.iter().map(|(k, _)| k.to_string()).collect();
        head.extend(errs.iter().map(|(k, _)| format!("err_{k}")));
        s.push_str(&head.join(","));
        s.push('\n');
        let cell = |v: &[String], i: usize| v.get(i).cloned().unwrap_or_default();
        for i in 0..self.c1t_over_r.len() {
            let mut line: Vec<String> = keys.iter().map(|(_, v)| cell(v, i)).collect();
            line.extend(errs.iter().map(|(_, v)| cell(v, i)));
            s.push_str(&line.join(","));
            s.push('\n');
        }
        for p in self.pressure.iter().flatten() {
            s.push_str(&format!(
                "# pressure at c1t/R = {}\nx_over_R,p_over_rho_c1sq,error_estimate\n",
                p.c1t_over_r.json()
            ));
            for (i, (x, q)) in p.x_over_r.iter().zip(&p.p_over_rho_c1sq).enumerate() {
                let e = p
                    .error_estimate
                    .as_ref()
                    .and_then(|e| e.get(i))
                    .map(|&e| float_cell(e))
                    .unwrap_or_default();
                s.push_str(&format!("{},{},{e}\n", x.json(), q.json()));
            }
        }
        s
    }
}

fn numbers(xs: &[Number]) -> Value {
    Value::Array(xs.iter().map(Number::json).collect())
}

/// An f64 estimate as a CSV cell (empty when absent).
fn float_cell(x: f64) -> String {
    if x.is_finite() {
        json!(x).to_string()
    } else {
        String::new()
    }
}

// ---------------------------------------------------------------------------------------
// impact green

/// The keys of a [`GreenReport`] as JSON, in order.
pub const GREEN_KEYS: &[&str] = &[
    "version",
    keys::POISSON,
    "c2_over_c1",
    "precision_bits",
    "points",
    "cells",
    "constants",
];

/// The columns of a point of `impact green` (its CSV table, then `err_` of each but `s`).
pub const GREEN_POINT_KEYS: &[&str] = &["s", "g_zz", "g_xz", "g_xx", "W_zz", "U_xz", "U_xx"];

/// The columns of a cell of `impact green` (then `err_` of each but `sa`, `sb`).
pub const GREEN_CELL_KEYS: &[&str] = &[
    "sa", "sb", "Ix_zz", "Ix_xz", "Ix_xx", "It_zz", "It_xz", "It_xx",
];

/// A number of `impact green`: its decimal text at the digits asked for and its absolute
/// error estimate (printed to three digits).
#[derive(Clone, Debug, PartialEq)]
pub struct GreenValue {
    /// The value's decimal text.
    pub text: String,
    /// The absolute error estimate.
    pub error: f64,
}

impl GreenValue {
    /// The value and its estimate, each finite (else the lamb crate's refusal, naming it).
    fn of<T: Real>(e: &Estimate<T>, digits: usize) -> lamb::Result<Self> {
        if !(e.value.is_finite() && e.error.is_finite()) {
            return Err(lamb::LambError::NotFinite {
                quantity: "a value of impact green or its estimate",
                s: e.value.to_f64().to_string(),
            });
        }
        Ok(GreenValue {
            text: e.value.to_decimal(digits),
            error: e.error,
        })
    }
    fn error_json(&self) -> Value {
        num(&format!("{:.2e}", self.error.max(0.0)))
    }
}

/// The pointwise values at s = |x|/(c1 t): the impulse responses g and the step responses
/// W (zz, xz, xx).
#[derive(Clone, Debug, PartialEq)]
pub struct GreenPoint {
    /// s, as computed.
    pub s: String,
    /// g_zz, g_xz, g_xx.
    pub g: [GreenValue; 3],
    /// W_zz, U_xz, U_xx.
    pub w: [GreenValue; 3],
}

/// The cell integrals over [sa, sb]: Ix = Int g ds, It = Int g/s ds (unavailable for
/// sa = 0, with the reason).
#[derive(Clone, Debug, PartialEq)]
pub struct GreenCell {
    /// sa.
    pub sa: String,
    /// sb.
    pub sb: String,
    /// Ix_zz, Ix_xz, Ix_xx.
    pub ix: [GreenValue; 3],
    /// It_zz, It_xz, It_xx, or why not.
    pub it: Result<[GreenValue; 3], String>,
}

/// The reason `It` is unavailable on a cell from sa = 0.
pub const IT_AT_ZERO: &str =
    "diverges for sa = 0: the step response grows like (1 - nu) ln(1/s) as s -> 0";

/// The Rayleigh constants of the half-plane, as decimal text.
#[derive(Clone, Debug, PartialEq)]
pub struct GreenConstants {
    /// s_R = c_R/c1.
    pub s_r: String,
    /// The residue of g_zz at s_R.
    pub r_zz: String,
    /// The residue of g_xx at s_R.
    pub r_xx: String,
    /// The Rayleigh delta's weight K_R.
    pub k_r: String,
}

/// The report of `impact green` (units c1 = 1, mu = 1).
#[derive(Clone, Debug, PartialEq)]
pub struct GreenReport {
    /// The library version.
    pub version: String,
    /// Poisson's ratio.
    pub poisson: String,
    /// c2/c1.
    pub c2_over_c1: String,
    /// The working precision in bits.
    pub precision_bits: u32,
    /// The points asked for.
    pub points: Option<Vec<GreenPoint>>,
    /// The cells asked for.
    pub cells: Option<Vec<GreenCell>>,
    /// The Rayleigh constants, when asked for.
    pub constants: Option<GreenConstants>,
}

fn triple<T: Real>(t: Triple<Estimate<T>>, digits: usize) -> lamb::Result<[GreenValue; 3]> {
    Ok([
        GreenValue::of(&t.zz, digits)?,
        GreenValue::of(&t.xz, digits)?,
        GreenValue::of(&t.xx, digits)?,
    ])
}

impl GreenReport {
    /// The report of the half-plane `hp` at precision `bits`, printed to `digits` digits: the
    /// pointwise values at `at`, the cell integrals over `cells`, the Rayleigh constants when
    /// `constants`.
    pub fn of<T: complexfn::quadrature::CachedRules>(
        hp: &HalfPlane<T>,
        bits: u32,
        digits: usize,
        at: Option<&[T]>,
        cells: Option<&[(T, T)]>,
        constants: bool,
        version: &str,
    ) -> lamb::Result<Self> {
        let points = match at {
            None => None,
            Some(at) => Some(
                at.iter()
                    .map(|s| {
                        Ok(GreenPoint {
                            s: s.to_decimal(digits),
                            g: triple(hp.impulse(s)?, digits)?,
                            w: triple(hp.step(s)?, digits)?,
                        })
                    })
                    .collect::<lamb::Result<Vec<_>>>()?,
            ),
        };
        let cells = match cells {
            None => None,
            Some(cells) => Some(
                cells
                    .iter()
                    .map(|(sa, sb)| {
                        Ok(GreenCell {
                            sa: sa.to_decimal(digits),
                            sb: sb.to_decimal(digits),
                            ix: triple(hp.cell(0, sa, sb)?, digits)?,
                            it: if *sa == 0.0 {
                                Err(IT_AT_ZERO.to_string())
                            } else {
                                triple(hp.cell(1, sa, sb)?, digits).map(Ok)?
                            },
                        })
                    })
                    .collect::<lamb::Result<Vec<_>>>()?,
            ),
        };
        let constants = constants.then(|| {
            let c = hp.rayleigh_constants();
            GreenConstants {
                s_r: c.s_r.to_decimal(digits),
                r_zz: c.r_zz.to_decimal(digits),
                r_xx: c.r_xx.to_decimal(digits),
                k_r: c.k_r.to_decimal(digits),
            }
        });
        Ok(GreenReport {
            version: version.to_string(),
            poisson: hp.poisson().to_decimal(digits),
            c2_over_c1: hp.m().to_decimal(digits),
            precision_bits: bits,
            points,
            cells,
            constants,
        })
    }

    fn point_json(p: &GreenPoint) -> Value {
        let mut rec = Map::new();
        let mut errs = Map::new();
        rec.insert("s".into(), num(&p.s));
        for (k, v) in GREEN_POINT_KEYS[1..].iter().zip(p.g.iter().chain(&p.w)) {
            rec.insert(k.to_string(), num(&v.text));
            errs.insert(k.to_string(), v.error_json());
        }
        rec.insert("error_estimate".into(), Value::Object(errs));
        Value::Object(rec)
    }

    fn cell_json(c: &GreenCell) -> Value {
        let mut rec = Map::new();
        let mut errs = Map::new();
        rec.insert("sa".into(), num(&c.sa));
        rec.insert("sb".into(), num(&c.sb));
        for (k, v) in GREEN_CELL_KEYS[2..5].iter().zip(&c.ix) {
            rec.insert(k.to_string(), num(&v.text));
            errs.insert(k.to_string(), v.error_json());
        }
        match &c.it {
            Ok(it) => {
                for (k, v) in GREEN_CELL_KEYS[5..].iter().zip(it) {
                    rec.insert(k.to_string(), num(&v.text));
                    errs.insert(k.to_string(), v.error_json());
                }
            }
            Err(why) => {
                for k in &GREEN_CELL_KEYS[5..] {
                    rec.insert(k.to_string(), Value::Null);
                }
                rec.insert("unavailable".into(), json!({"It": why}));
            }
        }
        rec.insert("error_estimate".into(), Value::Object(errs));
        Value::Object(rec)
    }

    /// The report as one JSON object ([`GREEN_KEYS`] order).
    pub fn to_json(&self) -> Value {
        let mut o = Map::new();
        o.insert("version".into(), json!(self.version));
        o.insert("poisson".into(), num(&self.poisson));
        o.insert("c2_over_c1".into(), num(&self.c2_over_c1));
        o.insert("precision_bits".into(), json!(self.precision_bits));
        if let Some(p) = &self.points {
            o.insert(
                "points".into(),
                Value::Array(p.iter().map(Self::point_json).collect()),
            );
        }
        if let Some(c) = &self.cells {
            o.insert(
                "cells".into(),
                Value::Array(c.iter().map(Self::cell_json).collect()),
            );
        }
        if let Some(c) = &self.constants {
            o.insert(
                "constants".into(),
                json!({"s_R": num(&c.s_r), "r_zz": num(&c.r_zz), "r_xx": num(&c.r_xx), "K_R": num(&c.k_r)}),
            );
        }
        Value::Object(o)
    }

    /// CSV with a `#` header: the material, then one table per section (an unavailable
    /// value is an empty field).
    pub fn to_csv(&self, cmdline: &str) -> String {
        let mut out = String::new();
        let mut line = |l: String| {
            out.push_str(&l);
            out.push('\n');
        };
        line(format!("# impact {}: Lamb's surface influence functions (units c1 = 1, mu = 1; u = I/(pi mu t) g(s), u = P/(pi mu) W(s), s = |x|/(c1 t))", self.version));
        line(format!("# command: {cmdline}"));
        line(format!("# poisson = {}", num(&self.poisson)));
        line(format!("# c2_over_c1 = {}", num(&self.c2_over_c1)));
        line(format!("# precision_bits = {}", self.precision_bits));
        if let Some(c) = &self.constants {
            for (k, x) in [
                ("s_R", &c.s_r),
                ("r_zz", &c.r_zz),
                ("r_xx", &c.r_xx),
                ("K_R", &c.k_r),
            ] {
                line(format!("# {k} = {}", num(x)));
            }
        }
        let errs_head = |cols: &[&str]| -> String {
            cols.iter()
                .filter(|c| !c.starts_with('s'))
                .map(|c| format!("err_{c}"))
                .collect::<Vec<_>>()
                .join(",")
        };
        if let Some(points) = &self.points {
            line(format!(
                "{},{}",
                GREEN_POINT_KEYS.join(","),
                errs_head(GREEN_POINT_KEYS)
            ));
            for p in points {
                let vals = p.g.iter().chain(&p.w);
                let mut cells = vec![num(&p.s).to_string()];
                cells.extend(vals.clone().map(|v| num(&v.text).to_string()));
                cells.extend(vals.map(|v| v.error_json().to_string()));
                line(cells.join(","));
            }
        }
        if let Some(list) = &self.cells {
            line(format!(
                "{},{}",
                GREEN_CELL_KEYS.join(","),
                errs_head(GREEN_CELL_KEYS)
            ));
            for c in list {
                let it: Vec<Option<&GreenValue>> = match &c.it {
                    Ok(it) => it.iter().map(Some).collect(),
                    Err(_) => vec![None; 3],
                };
                let vals: Vec<Option<&GreenValue>> = c.ix.iter().map(Some).chain(it).collect();
                let mut cells = vec![num(&c.sa).to_string(), num(&c.sb).to_string()];
                cells.extend(
                    vals.iter()
                        .map(|v| v.map(|v| num(&v.text).to_string()).unwrap_or_default()),
                );
                cells.extend(
                    vals.iter()
                        .map(|v| v.map(|v| v.error_json().to_string()).unwrap_or_default()),
                );
                line(cells.join(","));
            }
        }
        out
    }
}

// ---------------------------------------------------------------------------------------
// impact edge

/// The keys of an [`EdgeReport`] as JSON, in order.
pub const EDGE_KEYS: &[&str] = &[
    "version",
    "poisson",
    "c2_over_c1",
    "cR_over_c1",
    "law",
    "convention",
    "records",
];

/// The keys of one record of an [`EdgeReport`], in order.
pub const EDGE_RECORD_KEYS: &[&str] = &[
    keys::SPEED_OVER_C1,
    keys::RANGE,
    "exponents",
    "gap_coefficients",
    "signorini_admissible",
    "selected",
    keys::LAW,
    "slope_symbol",
    "edge_pressure_per_profile_slope",
    "unavailable",
];

/// The columns of an edge report's CSV table.
pub const EDGE_COLUMNS: &[&str] = &[
    keys::SPEED_OVER_C1,
    keys::RANGE,
    "exponent",
    "gap_coefficient",
    "signorini_admissible",
    "selected",
];

/// The conventions of an edge report.
pub const EDGE_CONVENTION: &str = "p ~ c d^lambda, d the distance from the edge into the contact; gap ~ (c/mu) G x^(lambda+1) outside; slope symbol S+ in units 1/mu (docs/edge.md)";

/// Why the edge pressure per unit slope is unavailable below c1.
pub const EDGE_PRESSURE_BELOW_C1: &str = "only a supersonic edge (speed above c1) has a finite edge pressure proportional to the profile's slope; below c1 the pressure at the edge is zero or singular (the selected exponent)";

/// The report of `impact edge`: the local behaviour of the contact pressure at an edge moving
/// at each speed asked for (`lamb::edge`).
#[derive(Clone, Debug)]
pub struct EdgeReport {
    /// The library version.
    pub version: String,
    /// Poisson's ratio.
    pub poisson: f64,
    /// c2/c1.
    pub c2_over_c1: f64,
    /// c_R/c1.
    pub cr_over_c1: f64,
    /// The edge law.
    pub law: lamb::edge::EdgeLaw,
    /// One record per speed.
    pub records: Vec<lamb::edge::EdgeBehaviour>,
}

impl EdgeReport {
    /// The records of the half-plane `hp` for the edge speeds `speeds` (D/c1) under `law`.
    pub fn of(
        hp: &HalfPlane<f64>,
        law: lamb::edge::EdgeLaw,
        speeds: &[f64],
        version: &str,
    ) -> lamb::Result<Self> {
        Ok(EdgeReport {
            version: version.to_string(),
            poisson: hp.poisson(),
            c2_over_c1: *hp.m(),
            cr_over_c1: *hp.s_r(),
            law,
            records: speeds
                .iter()
                .map(|&d| hp.edge_behaviour(d, law))
                .collect::<lamb::Result<_>>()?,
        })
    }

    fn record_json(&self, e: &lamb::edge::EdgeBehaviour) -> Value {
        let mut rec = json!({
            "speed_over_c1": e.speed_over_c1,
            "range": e.range.name(),
            "exponents": e.solutions.iter().map(|s| s.lambda).collect::<Vec<_>>(),
            "gap_coefficients": e.solutions.iter().map(|s| s.gap_coefficient).collect::<Vec<_>>(),
            "signorini_admissible": e.solutions.iter().map(|s| s.signorini_admissible).collect::<Vec<_>>(),
            "selected": e.selected,
            "law": self.law.name(),
            "slope_symbol": [e.slope_symbol.0, e.slope_symbol.1],
        });
        if let Value::Object(o) = &mut rec {
            match e.jump_per_slope {
                Some(j) => {
                    o.insert("edge_pressure_per_profile_slope".into(), json!(j));
                }
                None => {
                    o.insert(
                        "unavailable".into(),
                        json!({ "edge_pressure_per_profile_slope": EDGE_PRESSURE_BELOW_C1 }),
                    );
                }
            }
        }
        rec
    }

    /// The report as one JSON object ([`EDGE_KEYS`] order).
    pub fn to_json(&self) -> Value {
        json!({
            "version": self.version,
            "poisson": self.poisson,
            "c2_over_c1": self.c2_over_c1,
            "cR_over_c1": self.cr_over_c1,
            "law": self.law.name(),
            "convention": EDGE_CONVENTION,
            "records": self.records.iter().map(|e| self.record_json(e)).collect::<Vec<_>>(),
        })
    }

    /// CSV with `#` header lines: one row per speed and local solution ([`EDGE_COLUMNS`]).
    pub fn to_csv(&self, cmdline: &str) -> String {
        let mut out = format!(
            "# {cmdline}\n# impact edge {}: poisson {}, c2/c1 {}, cR/c1 {}, law {}\n# {}\n",
            self.version,
            json!(self.poisson),
            json!(self.c2_over_c1),
            json!(self.cr_over_c1),
            self.law.name(),
            EDGE_CONVENTION
        );
        out.push_str(&EDGE_COLUMNS.join(","));
        out.push('\n');
        for e in &self.records {
            for s in &e.solutions {
                out.push_str(&format!(
                    "{},{},{},{},{},{}\n",
                    json!(e.speed_over_c1),
                    e.range.name(),
                    json!(s.lambda),
                    json!(s.gap_coefficient),
                    json!(s.signorini_admissible),
                    json!(s.lambda) == json!(e.selected)
                ));
            }
        }
        out
    }
}

/// The keys of a [`StrikerGreenReport`] as JSON, in order.
pub const STRIKER_GREEN_KEYS: &[&str] = &[
    "version",
    "striker",
    "poisson",
    "arc_over_R",
    "convention",
    "c2t_over_R",
    "angle_deg",
    "w_over_p0R_mu",
    "w_def_over_p0R_mu",
    "error_estimate",
    "method",
];

/// The conventions of a striker-green report.
pub const STRIKER_GREEN_CONVENTION: &str = "free elastic cylinder in plane strain, R = 1, mu_s = 1, rho_s = 1; unit pressure p0 switched on at t = 0 over |theta| <= theta0, 2 theta0 R = arc; w: inward normal displacement averaged over the arc of the same width centred at each angle, arrays [angle][time]; w_def = w - X(t) cos(theta) sin(theta0)/theta0, X = F t^2/(2 m), F = 2 p0 R sin(theta0), m = pi R^2 rho_s (docs/strikers.md, section 7)";

/// The columns of a striker-green report's CSV table.
pub const STRIKER_GREEN_COLUMNS: &[&str] = &[
    "angle_deg",
    "c2t_over_R",
    "w_over_p0R_mu",
    "w_def_over_p0R_mu",
    "error_estimate",
];

/// The report of `impact striker-green`: a free elastic cylinder's own influence function
/// ([`impact::striker::green`]).
#[derive(Clone, Debug)]
pub struct StrikerGreenReport {
    /// The library version.
    pub version: String,
    /// The striker's Poisson's ratio.
    pub poisson: f64,
    /// The receiver arcs' centres as asked for, degrees.
    pub angle_deg: Vec<f64>,
    /// The response.
    pub response: impact::striker::green::ArcStepResponse,
}

impl StrikerGreenReport {
    /// The report of `response` (a disk of Poisson's ratio `poisson`), its angles as given in
    /// degrees.
    pub fn of(
        poisson: f64,
        angle_deg: &[f64],
        response: impact::striker::green::ArcStepResponse,
        version: &str,
    ) -> Self {
        StrikerGreenReport {
            version: version.to_string(),
            poisson,
            angle_deg: angle_deg.to_vec(),
            response,
        }
    }

    /// The report as one JSON object ([`STRIKER_GREEN_KEYS`] order).
    pub fn to_json(&self) -> Value {
        let r = &self.response;
        json!({
            "version": self.version,
            "striker": "cylinder",
            "poisson": self.poisson,
            "arc_over_R": r.arc,
            "convention": STRIKER_GREEN_CONVENTION,
            "c2t_over_R": r.times,
            "angle_deg": self.angle_deg,
            "w_over_p0R_mu": r.total,
            "w_def_over_p0R_mu": r.deformation,
            "error_estimate": {
                "w_over_p0R_mu": r.error,
                "w_def_over_p0R_mu": r.error,
            },
            "method": {
                "harmonics": r.harmonics,
                "frequencies": r.frequencies,
                "description": "periodised half-plane (Lamb, closed form) + rigid translation + harmonic remainder inverted by Fourier series (docs/strikers.md, section 7)",
            },
        })
    }

    /// CSV with `#` header lines: one row per angle and time ([`STRIKER_GREEN_COLUMNS`]).
    pub fn to_csv(&self, cmdline: &str) -> String {
        let r = &self.response;
        let mut out = format!(
            "# {cmdline}\n# impact striker-green {}: cylinder, poisson {}, arc_over_R {}\n# {}\n",
            self.version,
            json!(self.poisson),
            json!(r.arc),
            STRIKER_GREEN_CONVENTION
        );
        out.push_str(&STRIKER_GREEN_COLUMNS.join(","));
        out.push('\n');
        for (j, a) in self.angle_deg.iter().enumerate() {
            for (i, t) in r.times.iter().enumerate() {
                out.push_str(&format!(
                    "{},{},{},{},{}\n",
                    json!(a),
                    json!(t),
                    json!(r.total[j][i]),
                    json!(r.deformation[j][i]),
                    json!(r.error[j][i])
                ));
            }
        }
        out
    }
}
