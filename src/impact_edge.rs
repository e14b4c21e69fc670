//! `impact edge`: the power law of the contact pressure at a moving contact edge (crate
//! `lamb`, module `edge`; `docs/edge.md`).

use clap::Args;
use lamb::edge::EdgeLaw;
use lamb::HalfPlane;
use serde_json::{json, Value};

use crate::impact_run::material;

/// Arguments of `impact edge`.
#[derive(Args, Debug)]
pub struct EdgeArgs {
    /// P-wave speed c1 in m/s (with --c2).
    #[arg(long, allow_hyphen_values = true)]
    c1: Option<f64>,
    /// S-wave speed c2 in m/s (with --c1).
    #[arg(long, allow_hyphen_values = true)]
    c2: Option<f64>,
    /// Poisson's ratio nu in (-1, 1/2) (instead of --c1, --c2).
    #[arg(long, allow_hyphen_values = true)]
    poisson: Option<f64>,
    /// Comma-separated edge speeds D/c1 > 0 (not c_R/c1, c2/c1 or 1).
    #[arg(long, allow_hyphen_values = true)]
    speed_over_c1: Option<String>,
    /// The edge law: `signorini` (a free edge) or `kinematic` (a prescribed edge, f(b) = h).
    #[arg(long, default_value = "signorini")]
    law: String,
    /// JSON output (default: CSV with `#` header lines).
    #[arg(long)]
    pub json: bool,
}

type R<T> = std::result::Result<T, String>;

/// The records for every speed, as JSON.
pub fn run(a: &EdgeArgs, version: &str) -> R<Value> {
    let nu = material(a.c1, a.c2, a.poisson)?;
    let hp = HalfPlane::from_poisson(nu).map_err(|e| e.to_string())?;
    let law = match a.law.as_str() {
        "signorini" => EdgeLaw::Signorini,
        "kinematic" => EdgeLaw::Kinematic,
        other => {
            return Err(format!(
                "invalid --law = {other}: admissible values are signorini, kinematic"
            ))
        }
    };
    let spec = a
        .speed_over_c1
        .as_deref()
        .ok_or("missing --speed-over-c1 D1,D2,... (edge speeds over c1)")?;
    let mut records = Vec::new();
    for item in spec.split(',') {
        let d: f64 = item
            .trim()
            .parse()
            .map_err(|_| format!("invalid --speed-over-c1 entry '{item}': not a number"))?;
        let e = hp.edge_behaviour(d, law).map_err(|e| e.to_string())?;
        let mut rec = json!({
            "speed_over_c1": e.speed_over_c1,
            "range": e.range.name(),
            "exponents": e.solutions.iter().map(|s| s.lambda).collect::<Vec<_>>(),
            "gap_coefficients": e.solutions.iter().map(|s| s.gap_coefficient).collect::<Vec<_>>(),
            "signorini_admissible": e.solutions.iter().map(|s| s.signorini_admissible).collect::<Vec<_>>(),
            "selected": e.selected,
            "law": law.name(),
            "slope_symbol": [e.slope_symbol.0, e.slope_symbol.1],
        });
        // the edge's pressure is a finite jump (per unit profile slope) only above c1; below,
        // the pressure at the edge is zero or singular: declared unavailable with the reason
        if let Value::Object(o) = &mut rec {
            match e.jump_per_slope {
                Some(j) => {
                    o.insert("edge_pressure_per_profile_slope".into(), json!(j));
                }
                None => {
                    o.insert(
                        "unavailable".into(),
                        json!({"edge_pressure_per_profile_slope": "only a supersonic edge (speed above c1) has a finite edge pressure proportional to the profile's slope; below c1 the pressure at the edge is zero or singular (the selected exponent)"}),
                    );
                }
            }
        }
        records.push(rec);
    }
    Ok(json!({
        "version": version,
        "poisson": nu,
        "c2_over_c1": *hp.m(),
        "cR_over_c1": *hp.s_r(),
        "law": law.name(),
        "convention": "p ~ c d^lambda, d the distance from the edge into the contact; gap ~ (c/mu) G x^(lambda+1) outside; slope symbol S+ in units 1/mu (docs/edge.md)",
        "records": records,
    }))
}

/// CSV with `#` header lines: one row per speed and local solution.
pub fn csv(v: &Value, cmdline: &str) -> String {
    let mut out = format!(
        "# {cmdline}\n# impact edge {}: poisson {}, c2/c1 {}, cR/c1 {}, law {}\n# {}\n",
        v["version"].as_str().unwrap_or(""),
        v["poisson"],
        v["c2_over_c1"],
        v["cR_over_c1"],
        v["law"].as_str().unwrap_or(""),
        v["convention"].as_str().unwrap_or("")
    );
    out.push_str("speed_over_c1,range,exponent,gap_coefficient,signorini_admissible,selected\n");
    for r in v["records"].as_array().into_iter().flatten() {
        let n = r["exponents"].as_array().map(|a| a.len()).unwrap_or(0);
        for i in 0..n {
            out.push_str(&format!(
                "{},{},{},{},{},{}\n",
                r["speed_over_c1"],
                r["range"].as_str().unwrap_or(""),
                r["exponents"][i],
                r["gap_coefficients"][i],
                r["signorini_admissible"][i],
                r["exponents"][i] == r["selected"]
            ));
        }
    }
    out
}
