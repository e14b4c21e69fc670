//! `impact run`: a striker's transient impact on the half-plane (crate `impact`): rigid,
//! elastic (local half-plane model) or a thin cylindrical shell.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use clap::Args;
use complexfn::{Dd, Real};
use impact::scalar::Scalar;
use impact::{
    Drive, EdgeLaw, HistoryRow, ImpactCase, Profile, ShellStriker, SolvedImpact, Stop, Striker,
    StrikerMaterial, Value as Est,
};
use serde_json::{json, Map, Value};

use crate::cli::num;

/// The most digits `--digits` gives: the march runs in double-double (about 32 digits) above
/// f64.
pub const MAX_DIGITS: u32 = 30;

/// Arguments of `impact run`.
#[derive(Args, Debug)]
pub struct RunArgs {
    /// P-wave speed c1 in m/s (with --c2).
    #[arg(long, allow_hyphen_values = true)]
    c1: Option<f64>,
    /// S-wave speed c2 in m/s (with --c1).
    #[arg(long, allow_hyphen_values = true)]
    c2: Option<f64>,
    /// Poisson's ratio nu in (-1, 1/2), nu != 0 (instead of --c1, --c2).
    #[arg(long, allow_hyphen_values = true)]
    poisson: Option<f64>,
    /// The striker: `rigid`; `elastic:c1=..,c2=..,density_ratio=..` (its wave speeds in m/s,
    /// its density over the half-plane's; local half-plane model, valid until c1 t/R =
    /// 2 c1/c1s); `shell:thickness_over_R=..,c1=..,c2=..,density_ratio=..` (a thin
    /// cylindrical shell of radius R, its mass from its geometry). Deformable strikers need
    /// the half-plane's --c1 and --c2.
    #[arg(long, default_value = "rigid")]
    striker: String,
    /// The profile: circle:R=.., parabola:R=.., power:A=..,k=.., wedge:theta_deg=..,
    /// flat:a=.., table:FILE (two columns x f in metres, from x = 0).
    #[arg(long)]
    profile: String,
    /// m0/(rho R^2), the striker's mass per unit length (free striker).
    #[arg(long, allow_hyphen_values = true)]
    mass_ratio: Option<f64>,
    /// V0/c1, the initial speed (free striker).
    #[arg(long, allow_hyphen_values = true)]
    v0_over_c1: Option<f64>,
    /// Prescribed penetration instead of the equation of motion: speed:V_over_c1=.. or
    /// table:FILE (two columns c1 t/R, h/R from (0, 0)).
    #[arg(long)]
    driven: Option<String>,
    /// The edge law: signorini (unilateral conditions) or kinematic (eq (4), f(b) = h).
    #[arg(long, default_value = "signorini")]
    law: String,
    /// End time: c1t/R=VALUE (the last reported time exactly), or `separation` (shortly
    /// after the free striker leaves the surface; at most c1 t/R = 400) or
    /// `separation:max=VALUE` (at most c1 t/R = VALUE).
    #[arg(long)]
    end: String,
    /// The length scale R in metres for the flat punch, the wedge and the power law (the
    /// radius for the circle and the parabola).
    #[arg(long, allow_hyphen_values = true)]
    length: Option<f64>,
    /// Cell width dx/R of the finest grid.
    #[arg(long, default_value_t = 0.005, allow_hyphen_values = true)]
    dx: f64,
    /// kappa = c1 dt/dx, at least 1/2.
    #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
    kappa: f64,
    /// Refinement levels for the error estimates (1 to 4).
    #[arg(long, default_value_t = 3)]
    levels: usize,
    /// The edge cell: `model` (the local behaviour of the pressure at a moving edge, the
    /// edge inside its cell) or `whole` (whole cells, the edge captured cell by cell), for
    /// comparing the two.
    #[arg(long, default_value = "model")]
    edge_cell: String,
    /// Pressure profiles at these times: c1t/R=T1,T2,...
    #[arg(long)]
    pressure_at: Option<String>,
    /// JSON output (default: CSV with `#` headers).
    #[arg(long)]
    json: bool,
    /// Significant digits of the reported values (1 to 30): the march in double-double,
    /// the discrete solution of the same grids to that many digits (regression data for the
    /// scheme; the error estimates stay those of the discretisation). Rigid strikers; the
    /// inputs are taken as their nearest doubles. Omit for f64.
    #[arg(long)]
    digits: Option<u32>,
    /// Run even when the estimated memory exceeds the limit (4 GiB by default, or
    /// --memory-limit-gib).
    #[arg(long)]
    force: bool,
    /// The memory limit in GiB above which a run is refused without --force.
    #[arg(long, default_value_t = impact::cost::DEFAULT_MEMORY_LIMIT_GIB)]
    memory_limit_gib: f64,
}

type R<T> = std::result::Result<T, String>;

fn kv(spec: &str, what: &str) -> R<Vec<(String, f64)>> {
    spec.split(',')
        .map(|item| {
            let (k, v) = item
                .split_once('=')
                .ok_or_else(|| format!("invalid {what} {spec:?}: write key=value pairs"))?;
            let v: f64 = v
                .trim()
                .parse()
                .map_err(|_| format!("invalid {what} value {v:?} for {k}: not a number"))?;
            if !v.is_finite() {
                return Err(format!("invalid {what} value {v} for {k}: must be finite"));
            }
            Ok((k.trim().to_string(), v))
        })
        .collect()
}

fn one(pairs: &[(String, f64)], key: &str, what: &str) -> R<f64> {
    if pairs.len() != 1 || pairs[0].0 != key {
        return Err(format!("invalid {what}: expected exactly {key}=VALUE"));
    }
    Ok(pairs[0].1)
}

fn read_table(path: &str, what: &str) -> R<Vec<(f64, f64)>> {
    let text =
        std::fs::read_to_string(path).map_err(|e| format!("cannot read {what} {path}: {e}"))?;
    let mut rows = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let nums: Vec<f64> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .map(|s| s.parse::<f64>())
            .collect::<std::result::Result<_, _>>()
            .map_err(|_| format!("invalid {what} {path}, line {}: two numbers", i + 1))?;
        if nums.len() != 2 {
            return Err(format!(
                "invalid {what} {path}, line {}: two numbers",
                i + 1
            ));
        }
        rows.push((nums[0], nums[1]));
    }
    Ok(rows)
}

fn profile(spec: &str, length: Option<f64>) -> R<Profile> {
    let (kind, rest) = spec.split_once(':').ok_or_else(|| {
        format!("invalid --profile {spec:?}: write kind:parameters, e.g. circle:R=1")
    })?;
    let scale = length.unwrap_or(1.0);
    if !(scale.is_finite() && scale > 0.0) {
        return Err(format!(
            "invalid --length = {scale}: admissible range is (0, inf) m"
        ));
    }
    let radius_only = |what: &str| -> R<()> {
        if length.is_some() {
            return Err(format!(
                "contradictory flags: --length with --profile {what} (R is the radius)"
            ));
        }
        Ok(())
    };
    Ok(match kind {
        "circle" | "parabola" => {
            radius_only(kind)?;
            let r = one(&kv(rest, "--profile")?, "R", "--profile")?;
            if !(r > 0.0) {
                return Err(format!(
                    "invalid profile radius R = {r}: admissible range is (0, inf) m"
                ));
            }
            // R is the unit of length
            if kind == "circle" {
                Profile::Circle { radius: 1.0 }
            } else {
                Profile::Parabola { radius: 1.0 }
            }
        }
        "power" => {
            let p = kv(rest, "--profile")?;
            let get = |k: &str| {
                p.iter()
                    .find(|(n, _)| n == k)
                    .map(|x| x.1)
                    .ok_or_else(|| format!("invalid --profile {spec:?}: power needs A=..,k=.."))
            };
            let (a, k) = (get("A")?, get("k")?);
            // f/R = A R^(k-1) (x/R)^k
            Profile::Power {
                a: a * scale.powf(k - 1.0),
                k,
            }
        }
        "wedge" => Profile::Wedge {
            theta_deg: one(&kv(rest, "--profile")?, "theta_deg", "--profile")?,
        },
        "flat" => Profile::Flat {
            half_width: one(&kv(rest, "--profile")?, "a", "--profile")? / scale,
        },
        "table" => {
            let t = read_table(rest, "profile table")?;
            Profile::Table(std::sync::Arc::new(
                t.into_iter().map(|(x, f)| (x / scale, f / scale)).collect(),
            ))
        }
        other => {
            return Err(format!(
            "invalid --profile kind {other:?}: one of circle, parabola, power, wedge, flat, table"
        ))
        }
    })
}

fn poisson(a: &RunArgs) -> R<f64> {
    material(a.c1, a.c2, a.poisson)
}

/// Poisson's ratio from `--c1`, `--c2` (m/s) or `--poisson`, with one-line errors.
pub fn material(c1: Option<f64>, c2: Option<f64>, nu: Option<f64>) -> R<f64> {
    match (c1, c2, nu) {
        (None, None, Some(nu)) => Ok(nu),
        (Some(c1), Some(c2), None) => {
            if !(c1 > 0.0 && c2 > 0.0 && c1.is_finite() && c2.is_finite()) {
                return Err(format!(
                    "invalid --c1, --c2 = {c1}, {c2}: wave speeds must be > 0 m/s"
                ));
            }
            let m2 = (c2 / c1).powi(2);
            if !(m2 < 0.75) {
                return Err(format!(
                    "invalid c2/c1 = {}: admissible range is (0, sqrt(3)/2)",
                    c2 / c1
                ));
            }
            Ok(lamb::poisson_of(&m2))
        }
        (None, None, None) => {
            Err("missing material: give --poisson NU, or --c1 and --c2 (m/s)".into())
        }
        (_, _, Some(_)) => {
            Err("contradictory material: give either --poisson or --c1 and --c2, not both".into())
        }
        _ => Err("incomplete material: --c1 and --c2 go together (m/s)".into()),
    }
}

fn time_list(spec: &str, flag: &str) -> R<Vec<f64>> {
    let rest = spec
        .strip_prefix("c1t/R=")
        .ok_or_else(|| format!("invalid {flag} {spec:?}: write c1t/R=VALUE[,VALUE...]"))?;
    rest.split(',')
        .map(|s| {
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("invalid {flag} value {s:?}: not a finite number"))
        })
        .collect()
}

/// The default cap of `--end separation`, c1 t/R.
pub const SEPARATION_CAP: f64 = 400.0;

/// `--end`: an end time, or the separation with its cap.
fn end_spec(spec: &str) -> R<(f64, Stop)> {
    if let Some(rest) = spec.strip_prefix("separation") {
        let cap = match rest.strip_prefix(':') {
            None if rest.is_empty() => SEPARATION_CAP,
            Some(kvs) => one(&kv(kvs, "--end")?, "max", "--end separation:max=VALUE")?,
            None => {
                return Err(format!(
                    "invalid --end {spec:?}: c1t/R=VALUE, separation or separation:max=VALUE"
                ))
            }
        };
        return Ok((cap, Stop::AtSeparation));
    }
    let end = time_list(spec, "--end").map_err(|_| {
        format!("invalid --end {spec:?}: c1t/R=VALUE, separation or separation:max=VALUE")
    })?;
    if end.len() != 1 {
        return Err("invalid --end: one time, c1t/R=VALUE".into());
    }
    Ok((end[0], Stop::AtEnd))
}

/// The striker from `--striker` (speeds in m/s over the half-plane's c1 in m/s).
fn striker(a: &RunArgs) -> R<Striker> {
    let spec = a.striker.as_str();
    if spec == "rigid" {
        return Ok(Striker::Rigid);
    }
    let (kind, rest) = spec.split_once(':').ok_or_else(|| {
        format!(
            "invalid --striker {spec:?}: rigid, elastic:c1=..,c2=..,density_ratio=.. or \
             shell:thickness_over_R=..,c1=..,c2=..,density_ratio=.."
        )
    })?;
    let keys: &[&str] = match kind {
        "elastic" => &["c1", "c2", "density_ratio"],
        "shell" => &["thickness_over_R", "c1", "c2", "density_ratio"],
        other => {
            return Err(format!(
                "invalid --striker kind {other:?}: one of rigid, elastic, shell"
            ))
        }
    };
    let pairs = kv(rest, "--striker")?;
    let get = |k: &str| -> R<f64> {
        let mut found = pairs.iter().filter(|(n, _)| n == k);
        match (found.next(), found.next()) {
            (Some(p), None) => Ok(p.1),
            _ => Err(format!(
                "invalid --striker {spec:?}: {kind} needs {} (each once)",
                keys.iter()
                    .map(|k| format!("{k}=.."))
                    .collect::<Vec<_>>()
                    .join(",")
            )),
        }
    };
    if let Some((k, _)) = pairs.iter().find(|(n, _)| !keys.contains(&n.as_str())) {
        return Err(format!(
            "invalid --striker {spec:?}: unknown key {k:?} (keys: {})",
            keys.join(", ")
        ));
    }
    let c1 = match (a.c1, a.c2, a.poisson) {
        (Some(c1), Some(_), None) => c1,
        _ => {
            return Err(format!(
                "--striker {kind} gives its wave speeds in m/s: give the half-plane's --c1 and --c2 (m/s) instead of --poisson"
            ))
        }
    };
    let material = StrikerMaterial {
        c1_ratio: get("c1")? / c1,
        c2_ratio: get("c2")? / c1,
        density_ratio: get("density_ratio")?,
    };
    Ok(match kind {
        "elastic" => Striker::Elastic(material),
        _ => Striker::Shell(ShellStriker {
            thickness: get("thickness_over_R")?,
            material,
        }),
    })
}

/// Builds the case from the arguments.
pub fn case(a: &RunArgs) -> R<ImpactCase> {
    let nu = poisson(a)?;
    let striker = striker(a)?;
    let prof = profile(&a.profile, a.length)?;
    let law = match a.law.as_str() {
        "signorini" => EdgeLaw::Signorini,
        "kinematic" => EdgeLaw::Kinematic,
        other => return Err(format!("invalid --law {other:?}: signorini or kinematic")),
    };
    let (end, stop) = end_spec(&a.end)?;
    let drive = match (&a.driven, a.mass_ratio, a.v0_over_c1) {
        (Some(_), Some(_), _) | (Some(_), _, Some(_)) => {
            return Err(
                "contradictory flags: --driven replaces --mass-ratio and --v0-over-c1".into(),
            )
        }
        (Some(d), None, None) => {
            if let Some(rest) = d.strip_prefix("speed:") {
                Drive::Speed(one(&kv(rest, "--driven")?, "V_over_c1", "--driven")?)
            } else if let Some(path) = d.strip_prefix("table:") {
                Drive::Table(read_table(path, "driven table")?)
            } else {
                return Err(format!(
                    "invalid --driven {d:?}: speed:V_over_c1=.. or table:FILE"
                ));
            }
        }
        (None, Some(_), _) if matches!(striker, Striker::Shell(_)) => {
            return Err(
                "contradictory flags: --mass-ratio with --striker shell (the shell's mass follows from its thickness and density)"
                    .into(),
            )
        }
        (None, None, Some(v)) if matches!(striker, Striker::Shell(_)) => {
            let Striker::Shell(s) = striker else {
                unreachable!()
            };
            Drive::Free {
                mass_ratio: s.mass_ratio(),
                v0_over_c1: v,
            }
        }
        (None, Some(m), Some(v)) => Drive::Free {
            mass_ratio: m,
            v0_over_c1: v,
        },
        (None, None, _) => return Err("missing --mass-ratio (or --driven)".into()),
        (None, _, None) => return Err("missing --v0-over-c1 (or --driven)".into()),
    };
    if stop == Stop::AtSeparation && !matches!(drive, Drive::Free { .. }) {
        return Err(
            "invalid --end separation: only a free striker separates (give --mass-ratio and --v0-over-c1, or an end time c1t/R=VALUE)"
                .into(),
        );
    }
    let mut c = ImpactCase::new(nu, prof, drive, law, end).with_striker(striker);
    c.stop = stop;
    c.dx = a.dx;
    c.kappa = a.kappa;
    c.levels = a.levels;
    c.edge_model = match a.edge_cell.as_str() {
        "model" => true,
        "whole" => false,
        other => {
            return Err(format!(
                "invalid --edge-cell {other}: admissible values are model, whole"
            ))
        }
    };
    Ok(c)
}

/// The bound of |energy_defect| above which a run's energy audit is flagged.
pub const ENERGY_DEFECT_BOUND: f64 = 1e-2;

/// The fewest cells across the largest contact half-width of the finest grid for a contact
/// not to be flagged as under-resolved.
pub const MIN_CONTACT_CELLS: usize = 10;

/// V0/c1 of a free striker (0 when driven).
fn v0_of(c: &ImpactCase) -> f64 {
    match c.drive {
        Drive::Free { v0_over_c1, .. } => v0_over_c1,
        _ => 0.0,
    }
}

/// How the report writes a value: f64 as it is, or to a number of significant digits.
#[derive(Clone, Copy)]
struct Digits(Option<usize>);

impl Digits {
    fn of<T: Scalar>(self, x: T) -> Value {
        match self.0 {
            None => json!(x.to_f64()),
            Some(d) => num(&x.to_decimal(d)),
        }
    }
    fn all<T: Scalar>(self, xs: &[T]) -> Value {
        Value::Array(xs.iter().map(|&x| self.of(x)).collect())
    }
    fn est<T: Scalar>(self, v: &Est<T>) -> (Value, Value) {
        (
            self.of(v.value),
            v.error.map(|e| json!(e)).unwrap_or(Value::Null),
        )
    }
}

/// The report as JSON (the values to `digits` significant digits, or as f64) and the history
/// rows it was made from.
fn report<T: Scalar>(
    a: &RunArgs,
    sol: &SolvedImpact<T>,
    version: &str,
    digits: Option<usize>,
) -> R<(Value, Vec<HistoryRow<T>>)> {
    let dg = Digits(digits);
    let est = |v: &Est<T>| dg.est(v);
    let (rows, orders) = sol.history();
    let driven = !matches!(sol.case.drive, Drive::Free { .. });
    let hdot_key = if driven {
        "hdot_over_c1"
    } else {
        "hdot_over_v0"
    };
    let mut out = Map::new();
    out.insert("version".into(), json!(version));
    out.insert("law".into(), json!(sol.case.law.name()));
    out.insert("striker".into(), json!(sol.case.striker.name()));
    match &sol.case.striker {
        Striker::Rigid => {}
        Striker::Elastic(mat) => {
            out.insert(
                "striker_model".into(),
                json!({"c1_over_c1": mat.c1_ratio, "c2_over_c1": mat.c2_ratio, "density_ratio": mat.density_ratio,
                       "model": "local half-plane", "valid_until_c1t_over_R": sol.case.striker.validity_end()}),
            );
        }
        Striker::Shell(s) => {
            out.insert(
                "striker_model".into(),
                json!({"thickness_over_R": s.thickness, "c1_over_c1": s.material.c1_ratio, "c2_over_c1": s.material.c2_ratio,
                       "density_ratio": s.material.density_ratio, "mass_ratio": s.mass_ratio(),
                       "model": "Timoshenko ring (membrane, bending, transverse shear, rotary inertia)"}),
            );
        }
    }
    out.insert("profile".into(), json!(sol.case.profile.label()));
    match &sol.case.drive {
        Drive::Free {
            mass_ratio,
            v0_over_c1,
        } => {
            out.insert("mass_ratio".into(), json!(mass_ratio));
            out.insert("v0_over_c1".into(), json!(v0_over_c1));
        }
        Drive::Speed(v) => {
            out.insert("driven".into(), json!({"V_over_c1": v}));
        }
        Drive::Table(t) => {
            out.insert("driven".into(), json!({"table_points": t.len()}));
        }
    }
    out.insert(
        "end".into(),
        match sol.case.stop {
            Stop::AtEnd => json!({"c1t_over_R": sol.case.end}),
            Stop::AtSeparation => json!({"separation": true, "max_c1t_over_R": sol.case.end}),
        },
    );
    out.insert("poisson".into(), json!(sol.case.poisson));
    out.insert("c2_over_c1".into(), dg.of(sol.m));
    out.insert("cR_over_c1".into(), dg.of(sol.s_r));
    if let Some(d) = digits {
        out.insert(
            "precision".into(),
            json!({"digits": d, "arithmetic": "double-double"}),
        );
    }
    out.insert(
        "grid".into(),
        json!({
            "dx_over_R": dg.of(sol.runs[0].dx),
            "c1dt_over_R": dg.of(sol.runs[0].dt),
            "kappa": sol.case.kappa,
            "levels": sol.runs.len(),
            "edge_cell": if sol.case.edge_model { "model" } else { "whole" },
        }),
    );
    let mut errs = Map::new();
    let mut why = Map::new();
    let levels = sol.runs.len();
    if levels < 2 {
        why.insert(
            "error_estimate".into(),
            json!("one grid level (--levels 1): no refinement estimate"),
        );
    }
    let mut col = |key: &str, vals: Vec<(Value, Value)>| {
        let (v, e): (Vec<Value>, Vec<Value>) = vals.into_iter().unzip();
        out.insert(key.into(), Value::Array(v));
        if levels >= 2 {
            if e.iter().all(|x| !x.is_null()) {
                errs.insert(key.into(), Value::Array(e));
            } else {
                why.insert(
                    format!("error_estimate.{key}"),
                    json!("a coarser level has no value at some reported time"),
                );
            }
        }
    };
    col("h_over_R", rows.iter().map(|r| est(&r.h)).collect());
    col(hdot_key, rows.iter().map(|r| est(&r.hdot)).collect());
    col("b_over_R", rows.iter().map(|r| est(&r.b)).collect());
    col(
        "force_over_rho_c1sq_R",
        rows.iter().map(|r| est(&r.force)).collect(),
    );
    if !driven {
        col(
            "kinetic_energy_over_rho_c1sq_Rsq",
            rows.iter()
                .filter_map(|r| r.kinetic.as_ref().map(est))
                .collect(),
        );
    }
    col(
        "work_over_rho_c1sq_Rsq",
        rows.iter().map(|r| est(&r.work)).collect(),
    );
    if !matches!(sol.case.striker, Striker::Rigid) {
        col(
            "striker_deformation_over_R",
            rows.iter()
                .filter_map(|r| r.striker_deformation.as_ref().map(est))
                .collect(),
        );
        col(
            "striker_energy_over_rho_c1sq_Rsq",
            rows.iter()
                .filter_map(|r| r.striker_energy.as_ref().map(est))
                .collect(),
        );
    }
    if !driven {
        col(
            "energy_defect",
            rows.iter()
                .filter_map(|r| r.energy_defect.as_ref().map(est))
                .collect(),
        );
    } else {
        why.insert(
            "energy_defect".into(),
            json!("a driven striker has no impact energy to audit"),
        );
    }
    out.insert(
        "c1t_over_R".into(),
        Value::Array(rows.iter().map(|r| dg.of(r.t)).collect()),
    );
    out.insert(
        "bdot_over_c1".into(),
        Value::Array(rows.iter().map(|r| dg.of(r.bdot)).collect()),
    );
    out.insert(
        "stage".into(),
        Value::Array(rows.iter().map(|r| json!(r.stage.name())).collect()),
    );
    // the observed orders: a negative order (the level differences grow) is no order
    let mut ords = Map::new();
    for (key, o) in [
        ("h_over_R", orders.h),
        ("b_over_R", orders.b),
        ("force_over_rho_c1sq_R", orders.force),
    ] {
        match o {
            Some(p) if p > 0.0 => {
                ords.insert(key.into(), json!(p));
            }
            Some(p) => {
                why.insert(
                    format!("observed_order.{key}"),
                    json!(format!(
                        "not converging: the level differences grow from the finest pair to the coarsest (order {p:.2})"
                    )),
                );
            }
            None if levels < 3 => {
                why.insert(
                    format!("observed_order.{key}"),
                    json!("fewer than three grid levels"),
                );
            }
            None => {
                why.insert(
                    format!("observed_order.{key}"),
                    json!("the levels agree exactly: no order to observe"),
                );
            }
        }
    }
    match sol.peak_force() {
        Some((f, t, true)) => {
            out.insert(
                "peak_force".into(),
                json!({"force_over_rho_c1sq_R": dg.of(f), "c1t_over_R": dg.of(t)}),
            );
        }
        Some((f, t, false)) => {
            out.insert(
                "largest_force".into(),
                json!({"force_over_rho_c1sq_R": dg.of(f), "c1t_over_R": dg.of(t)}),
            );
            why.insert(
                "peak_force".into(),
                json!("the force had not turned down by the end of the run: largest_force is the largest so far, not a peak"),
            );
        }
        None => {
            why.insert("peak_force".into(), json!("no contact force in the run"));
        }
    }
    // the rebound of a free striker
    match sol.rebound() {
        Ok(r) => {
            let v0 = v0_of(&sol.case);
            out.insert(
                "separation_c1t_over_R".into(),
                json!({"value": dg.of(r.separation.value), "error_estimate": r.separation.error}),
            );
            out.insert("restitution".into(), dg.of(r.restitution.value));
            out.insert(
                "rebound_speed_over_c1".into(),
                dg.of(r.restitution.value * T::input(v0)),
            );
            out.insert(
                "energy_to_half_plane".into(),
                dg.of(r.energy_to_half_plane.value),
            );
            out.insert("reimpacts".into(), json!(r.reimpacts));
            for (key, e) in [
                ("restitution", r.restitution.error),
                ("rebound_speed_over_c1", r.restitution.error.map(|e| e * v0)),
                ("energy_to_half_plane", r.energy_to_half_plane.error),
            ] {
                match e {
                    Some(e) => {
                        errs.insert(key.into(), json!(e));
                    }
                    None => {
                        why.insert(
                            format!("error_estimate.{key}"),
                            json!("one grid level, or a coarser level still in contact at the end"),
                        );
                    }
                }
            }
        }
        Err(reason) => {
            for key in [
                "separation_c1t_over_R",
                "restitution",
                "rebound_speed_over_c1",
                "energy_to_half_plane",
            ] {
                why.insert(key.into(), json!(reason.clone()));
            }
        }
    }
    // the energy audit: the largest |energy_defect| against its bound
    if let Some(worst) = rows
        .iter()
        .filter_map(|r| r.energy_defect.as_ref())
        .map(|d| d.value.to_f64().abs())
        .reduce(f64::max)
    {
        let within = worst <= ENERGY_DEFECT_BOUND;
        let mut audit = Map::new();
        audit.insert("largest_defect".into(), json!(worst));
        audit.insert("bound".into(), json!(ENERGY_DEFECT_BOUND));
        audit.insert("within_bound".into(), json!(within));
        if !within {
            audit.insert(
                "note".into(),
                json!(if sol.case.law == EdgeLaw::Kinematic {
                    "the kinematic law's prescribed edge carries a finite energy flux (its pressure ~ d^(-1/2), its gap ~ s^(1/2)): the energy defect converges to that flux's work, not to 0 (docs/impact.md, section 9)"
                } else {
                    "the energy does not close to the bound: refine the grid (--dx)"
                }),
            );
        }
        out.insert("energy_audit".into(), Value::Object(audit));
    }
    // the contact's resolution: the largest contact half-width in cells of the finest grid
    let widest = sol.runs[0]
        .steps
        .iter()
        .map(|s| s.pressure.len())
        .max()
        .unwrap_or(0);
    out.insert(
        "resolution".into(),
        json!({
            "largest_contact_cells": widest,
            "least_cells": MIN_CONTACT_CELLS,
            "under_resolved": widest < MIN_CONTACT_CELLS,
        }),
    );
    if widest < MIN_CONTACT_CELLS {
        why.insert(
            "resolution".into(),
            json!(format!(
                "under-resolved: the contact spans at most {widest} cells of the finest grid (at least {MIN_CONTACT_CELLS} wanted): refine --dx"
            )),
        );
    }
    out.insert("error_estimate".into(), Value::Object(errs));
    out.insert("observed_order".into(), Value::Object(ords));
    // where a prescribed edge ran between c_R and c1 (no solution there, docs/edge.md
    // section 5): the intervals, always present ([] when none)
    out.insert(
        "edge_without_solution".into(),
        Value::Array(
            sol.edge_without_solution()
                .into_iter()
                .map(|(from, to)| {
                    json!({
                        "from_c1t_over_R": dg.of(from),
                        "to_c1t_over_R": dg.of(to),
                        "reason": "the prescribed (kinematic) edge ran between c_R and c1, where a steadily moving prescribed edge has no solution (docs/edge.md, section 5); the pressure near the edge does not converge there"
                    })
                })
                .collect(),
        ),
    );
    if let Some(spec) = &a.pressure_at {
        let mut list = Vec::new();
        let last = sol.runs[0].steps.last().map_or(0.0, |s| s.t.to_f64());
        for t in time_list(spec, "--pressure-at")? {
            if !(t > 0.0 && t <= last * (1.0 + 1e-12)) {
                return Err(format!(
                    "invalid --pressure-at time {t}: admissible range is (0, {last}], the run's times"
                ));
            }
            if let Some(prof) = sol.pressure_profile(t) {
                list.push(json!({
                    "c1t_over_R": dg.of(prof.t),
                    "x_over_R": dg.all(&prof.x),
                    "p_over_rho_c1sq": dg.all(&prof.p),
                    "error_estimate": prof.err,
                }));
            }
        }
        out.insert("pressure".into(), Value::Array(list));
    }
    if !why.is_empty() {
        out.insert("unavailable".into(), Value::Object(why));
    }
    Ok((Value::Object(out), rows))
}

/// CSV with `#` headers: one row per reported time, then the pressure profiles.
pub fn csv(v: &Value, cmdline: &str) -> String {
    let mut s = String::new();
    s.push_str(&format!(
        "# impact run {}\n",
        v["version"].as_str().unwrap_or("")
    ));
    s.push_str(&format!("# command: {cmdline}\n"));
    s.push_str(&format!(
        "# striker: {}{}; law: {}; profile: {}; poisson: {}; grid: {}\n",
        v["striker"].as_str().unwrap_or(""),
        v.get("striker_model")
            .map(|m| format!(" {m}"))
            .unwrap_or_default(),
        v["law"].as_str().unwrap_or(""),
        v["profile"].as_str().unwrap_or(""),
        v["poisson"],
        v["grid"]
    ));
    s.push_str("# dimensionless: x/R, c1 t/R, h/R, speeds over c1 (hdot over V0 for a free striker), force over rho c1^2 R, energies over rho c1^2 R^2; err_* are absolute error estimates\n");
    if let Some(list) = v["edge_without_solution"].as_array() {
        for e in list {
            s.push_str(&format!(
                "# edge without solution: c1 t/R from {} to {}: {}\n",
                e["from_c1t_over_R"],
                e["to_c1t_over_R"],
                e["reason"].as_str().unwrap_or("")
            ));
        }
    }
    for key in [
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
    ] {
        if let Some(x) = v.get(key) {
            let err = v["error_estimate"]
                .get(key)
                .map(|e| format!(" (error estimate {e})"))
                .unwrap_or_default();
            s.push_str(&format!("# {key}: {x}{err}\n"));
        }
    }
    if let Some(Value::Object(why)) = v.get("unavailable") {
        for (key, reason) in why {
            s.push_str(&format!(
                "# unavailable: {key}: {}\n",
                reason.as_str().unwrap_or("")
            ));
        }
    }
    let keys: Vec<&str> = [
        "c1t_over_R",
        "h_over_R",
        "hdot_over_v0",
        "hdot_over_c1",
        "b_over_R",
        "bdot_over_c1",
        "stage",
        "force_over_rho_c1sq_R",
        "kinetic_energy_over_rho_c1sq_Rsq",
        "work_over_rho_c1sq_Rsq",
        "striker_deformation_over_R",
        "striker_energy_over_rho_c1sq_Rsq",
        "striker_strain_energy_over_rho_c1sq_Rsq",
        "striker_vibration_energy_over_rho_c1sq_Rsq",
        "energy_defect",
    ]
    .into_iter()
    .filter(|k| v.get(*k).is_some())
    .collect();
    let err_keys: Vec<&str> = keys
        .iter()
        .copied()
        .filter(|k| v["error_estimate"].get(*k).is_some())
        .collect();
    let mut head: Vec<String> = keys.iter().map(|k| k.to_string()).collect();
    head.extend(err_keys.iter().map(|k| format!("err_{k}")));
    s.push_str(&head.join(","));
    s.push('\n');
    let n = v["c1t_over_R"].as_array().map(|a| a.len()).unwrap_or(0);
    let field = |x: &Value| match x {
        Value::Null => String::new(),
        Value::String(t) => t.clone(),
        other => other.to_string(),
    };
    for i in 0..n {
        let mut line: Vec<String> = keys.iter().map(|k| field(&v[*k][i])).collect();
        line.extend(err_keys.iter().map(|k| field(&v["error_estimate"][*k][i])));
        s.push_str(&line.join(","));
        s.push('\n');
    }
    if let Some(list) = v["pressure"].as_array() {
        for p in list {
            s.push_str(&format!(
                "# pressure at c1t/R = {}\nx_over_R,p_over_rho_c1sq,error_estimate\n",
                p["c1t_over_R"]
            ));
            let xs = p["x_over_R"].as_array().cloned().unwrap_or_default();
            let ps = p["p_over_rho_c1sq"].as_array().cloned().unwrap_or_default();
            for (i, (x, q)) in xs.iter().zip(&ps).enumerate() {
                let e = field(&p["error_estimate"][i]);
                s.push_str(&format!("{x},{q},{e}\n"));
            }
        }
    }
    s
}

/// Runs the subcommand: the report as JSON (the caller prints it, or its CSV form).
pub fn run(a: &RunArgs, version: &str) -> R<Value> {
    let c = case(a)?;
    if !(a.memory_limit_gib.is_finite() && a.memory_limit_gib > 0.0) {
        return Err(format!(
            "invalid --memory-limit-gib {}: admissible range is (0, inf)",
            a.memory_limit_gib
        ));
    }
    if let Some(spec) = &a.pressure_at {
        for t in time_list(spec, "--pressure-at")? {
            if !(t > 0.0 && t <= c.end) {
                return Err(format!(
                    "invalid --pressure-at time {t}: admissible range is (0, {}], the run's times",
                    c.end
                ));
            }
        }
    }
    let mut c = c;
    if !a.force {
        c.memory_limit = Some(a.memory_limit_gib * 1024.0 * 1024.0 * 1024.0);
    }
    let cost = c.cost_estimate();
    // to an end time the estimate bounds the run; to the separation its cap does, and the
    // march checks the width the contact reaches
    if cost.gib() > a.memory_limit_gib && !a.force && c.stop == Stop::AtEnd {
        return Err(format!(
            "the run would take about {:.1} GiB ({} steps by {} cells on the finest grid), above the limit of {} GiB: raise --dx, shorten --end, or pass --force (or --memory-limit-gib)",
            cost.gib(),
            cost.steps,
            cost.width,
            a.memory_limit_gib
        ));
    }
    // progress on stderr, shown once a run has taken a few seconds (and hidden by
    // indicatif where stderr is not a terminal)
    let bar = indicatif::ProgressBar::with_draw_target(
        Some(1000),
        indicatif::ProgressDrawTarget::hidden(),
    );
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{bar:40} {percent}% {msg} elapsed {elapsed} remaining ~{eta}",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let start = std::time::Instant::now();
    let shown = std::cell::Cell::new(false);
    let progress = |p: impact::Progress| {
        if !shown.get() && start.elapsed().as_secs_f64() > PROGRESS_AFTER_S {
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            shown.set(true);
        }
        bar.set_message(format!(
            "level {} step {} c1t/R {:.3}",
            p.level, p.step, p.t
        ));
        bar.set_position((p.fraction * 1000.0) as u64);
    };
    let v = match a.digits {
        None => {
            let sol = c.solve_reporting::<f64>(progress).map_err(|e| e.to_string())?;
            let (mut v, rows) = report(a, &sol, version, None)?;
            shell_energy_columns(&sol, &rows, &mut v)?;
            v
        }
        Some(d) if (1..=MAX_DIGITS).contains(&d) => {
            let sol = c.solve_reporting::<Dd>(progress).map_err(|e| e.to_string())?;
            report(a, &sol, version, Some(d as usize))?.0
        }
        Some(d) => {
            return Err(format!(
                "invalid --digits {d}: admissible range is 1..={MAX_DIGITS} (the march runs in double-double above f64)"
            ))
        }
    };
    bar.finish_and_clear();
    Ok(v)
}

/// Seconds after which a run shows its progress.
const PROGRESS_AFTER_S: f64 = 2.0;

/// The shell striker's strain and vibration energies with their estimates, added to the
/// report's columns (f64: the shell runs in f64 only).
fn shell_energy_columns(sol: &SolvedImpact, rows: &[HistoryRow], v: &mut Value) -> R<()> {
    let Some(parts) = sol.shell_energy_history(rows) else {
        return Ok(());
    };
    let parts = parts.map_err(|e| e.to_string())?;
    let Value::Object(out) = v else {
        return Ok(());
    };
    for (key, pick) in [
        ("striker_strain_energy_over_rho_c1sq_Rsq", 0),
        ("striker_vibration_energy_over_rho_c1sq_Rsq", 1),
    ] {
        let vals: Vec<&Est> = parts
            .iter()
            .map(|p| if pick == 0 { &p.0 } else { &p.1 })
            .collect();
        let (v, e): (Vec<Value>, Vec<Value>) = vals.iter().map(|x| Digits(None).est(*x)).unzip();
        out.insert(key.into(), Value::Array(v));
        if let Some(Value::Object(errs)) = out.get_mut("error_estimate") {
            errs.insert(key.into(), Value::Array(e));
        }
    }
    Ok(())
}

/// Whether JSON output was asked for.
pub fn wants_json(a: &RunArgs) -> bool {
    a.json
}
