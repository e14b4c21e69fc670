//! The impact engine's text inputs: the material, the striker, the profile, the drive, the
//! end and the time lists, from the specifications the command line takes
//! (`circle:R=1`, `elastic:c1=..,c2=..,density_ratio=..`, `speed:V_over_c1=..`,
//! `c1t/R=10`, `separation:max=40`), each refused with an [`InputError`] naming its
//! parameter.
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use impact::axisym::AxiProfile;
use impact::{Drive, Profile, ShellStriker, Stop, Striker, StrikerMaterial};

use crate::error::InputError;

type R<T> = std::result::Result<T, InputError>;

/// `key=value` pairs of a specification, each value a finite number.
fn kv(parameter: &'static str, spec: &str, what: &str) -> R<Vec<(String, f64)>> {
    spec.split(',')
        .map(|item| {
            let (k, v) = item.split_once('=').ok_or_else(|| {
                InputError::new(
                    parameter,
                    format!("invalid {what} {spec:?}: write key=value pairs"),
                )
            })?;
            let v: f64 = v.trim().parse().map_err(|_| {
                InputError::new(
                    parameter,
                    format!("invalid {what} value {v:?} for {k}: not a number"),
                )
            })?;
            if !v.is_finite() {
                return Err(InputError::new(
                    parameter,
                    format!("invalid {what} value {v} for {k}: must be finite"),
                ));
            }
            Ok((k.trim().to_string(), v))
        })
        .collect()
}

/// The one pair `key=VALUE` of a specification.
fn one(parameter: &'static str, pairs: &[(String, f64)], key: &str, what: &str) -> R<f64> {
    if pairs.len() != 1 || pairs[0].0 != key {
        return Err(InputError::new(
            parameter,
            format!("invalid {what}: expected exactly {key}=VALUE"),
        ));
    }
    Ok(pairs[0].1)
}

/// A two-column table of numbers from the file `path` (`#` lines and blank lines skipped;
/// commas or white space between the columns).
pub fn read_table(parameter: &'static str, path: &str, what: &str) -> R<Vec<(f64, f64)>> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError::new(parameter, format!("cannot read {what} {path}: {e}")))?;
    let mut rows = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let bad = || {
            InputError::new(
                parameter,
                format!("invalid {what} {path}, line {}: two numbers", i + 1),
            )
        };
        let nums: Vec<f64> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .map(|s| s.parse::<f64>())
            .collect::<std::result::Result<_, _>>()
            .map_err(|_| bad())?;
        if nums.len() != 2 {
            return Err(bad());
        }
        rows.push((nums[0], nums[1]));
    }
    Ok(rows)
}

/// A profile specification's kind and parameters (`kind:parameters`) and the length scale
/// of `--length` (m, default 1), each refused naming its flag; `example` shows the form.
fn kind_and_scale<'s>(
    spec: &'s str,
    length: Option<f64>,
    example: &str,
) -> R<(&'s str, &'s str, f64)> {
    let (kind, rest) = spec.split_once(':').ok_or_else(|| {
        InputError::new(
            "profile",
            format!("invalid --profile {spec:?}: write kind:parameters, e.g. {example}"),
        )
    })?;
    let scale = length.unwrap_or(1.0);
    if !(scale.is_finite() && scale > 0.0) {
        return Err(InputError::new(
            "length",
            format!("invalid --length = {scale}: admissible range is (0, inf) m"),
        ));
    }
    Ok((kind, rest, scale))
}

/// The profile of `--profile` (`circle:R=..`, `parabola:R=..`, `power:A=..,k=..`,
/// `wedge:theta_deg=..`, `flat:a=..`, `table:FILE`), in units of R: the radius for the
/// circle and the parabola, `length` (m, default 1) for the others.
pub fn profile(spec: &str, length: Option<f64>) -> R<Profile> {
    let p = "profile";
    let (kind, rest, scale) = kind_and_scale(spec, length, "circle:R=1")?;
    let radius_only = |what: &str| -> R<()> {
        if length.is_some() {
            return Err(InputError::new(
                "length",
                format!("contradictory flags: --length with --profile {what} (R is the radius)"),
            ));
        }
        Ok(())
    };
    Ok(match kind {
        "circle" | "parabola" => {
            radius_only(kind)?;
            let r = one(p, &kv(p, rest, "--profile")?, "R", "--profile")?;
            if !(r > 0.0) {
                return Err(InputError::new(
                    p,
                    format!("invalid profile radius R = {r}: admissible range is (0, inf) m"),
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
            let pairs = kv(p, rest, "--profile")?;
            let get = |k: &str| {
                pairs.iter().find(|(n, _)| n == k).map(|x| x.1).ok_or_else(|| {
                    InputError::new(
                        p,
                        format!("invalid --profile {spec:?}: power needs A=..,k=.."),
                    )
                })
            };
            let (a, k) = (get("A")?, get("k")?);
            // f/R = A R^(k-1) (x/R)^k
            Profile::Power {
                a: a * scale.powf(k - 1.0),
                k,
            }
        }
        "wedge" => Profile::Wedge {
            theta_deg: one(p, &kv(p, rest, "--profile")?, "theta_deg", "--profile")?,
        },
        "flat" => Profile::Flat {
            half_width: one(p, &kv(p, rest, "--profile")?, "a", "--profile")? / scale,
        },
        "table" => {
            let t = read_table(p, rest, "profile table")?;
            Profile::Table(std::sync::Arc::new(
                t.into_iter().map(|(x, f)| (x / scale, f / scale)).collect(),
            ))
        }
        other => {
            return Err(InputError::new(
                p,
                format!(
                    "invalid --profile kind {other:?}: one of circle, parabola, power, wedge, flat, table"
                ),
            ))
        }
    })
}

/// The axisymmetric profile of `--profile` in `--geometry axisymmetric` runs:
/// `sphere:R=..`, `paraboloid:R=..` (or `parabola:R=..`), `cone:theta_deg=..` (the half-angle
/// at the apex), `flat:a=..` (a cylindrical punch of radius a), in units of R: the radius for
/// the sphere and the paraboloid, `length` (m, default 1) for the punch.
pub fn axi_profile(spec: &str, length: Option<f64>) -> R<AxiProfile> {
    let p = "profile";
    let (kind, rest, scale) = kind_and_scale(spec, length, "sphere:R=1")?;
    let pairs = kv(p, rest, "--profile")?;
    Ok(match kind {
        "sphere" | "paraboloid" | "parabola" => {
            if length.is_some() {
                return Err(InputError::new(
                    "length",
                    format!("contradictory flags: --length with --profile {kind} (R is the radius)"),
                ));
            }
            let r = one(p, &pairs, "R", "--profile")?;
            if !(r > 0.0) {
                return Err(InputError::new(
                    p,
                    format!("invalid profile radius R = {r}: admissible range is (0, inf) m"),
                ));
            }
            if kind == "sphere" {
                AxiProfile::Sphere { radius: 1.0 }
            } else {
                AxiProfile::Paraboloid { radius: 1.0 }
            }
        }
        "cone" => AxiProfile::Cone {
            theta_deg: one(p, &pairs, "theta_deg", "--profile")?,
        },
        "flat" => AxiProfile::Flat {
            radius: one(p, &pairs, "a", "--profile")? / scale,
        },
        other => {
            return Err(InputError::new(
                p,
                format!(
                    "invalid --profile kind {other:?} for --geometry axisymmetric: one of sphere, paraboloid, cone, flat"
                ),
            ))
        }
    })
}

/// Poisson's ratio from `--c1`, `--c2` (m/s) or `--poisson`: one of the two, whole.
pub fn poisson(c1: Option<f64>, c2: Option<f64>, nu: Option<f64>) -> R<f64> {
    match (c1, c2, nu) {
        (None, None, Some(nu)) => Ok(nu),
        (Some(c1), Some(c2), None) => {
            if !(c1 > 0.0 && c2 > 0.0 && c1.is_finite() && c2.is_finite()) {
                return Err(InputError::new(
                    "c1",
                    format!("invalid --c1, --c2 = {c1}, {c2}: wave speeds must be > 0 m/s"),
                ));
            }
            let m2 = (c2 / c1).powi(2);
            if !(m2 < 0.75) {
                return Err(InputError::new(
                    "c2",
                    format!(
                        "invalid c2/c1 = {}: admissible range is (0, sqrt(3)/2)",
                        c2 / c1
                    ),
                ));
            }
            Ok(lamb::poisson_of(&m2))
        }
        (None, None, None) => Err(InputError::new(
            "poisson",
            "missing material: give --poisson NU, or --c1 and --c2 (m/s)",
        )),
        (_, _, Some(_)) => Err(InputError::new(
            "poisson",
            "contradictory material: give either --poisson or --c1 and --c2, not both",
        )),
        (Some(_), None, None) => Err(InputError::new(
            "c2",
            "incomplete material: --c1 and --c2 go together (m/s)",
        )),
        (None, Some(_), None) => Err(InputError::new(
            "c1",
            "incomplete material: --c1 and --c2 go together (m/s)",
        )),
    }
}

/// The times of `c1t/R=T1,T2,...` (each finite).
pub fn time_list(parameter: &'static str, spec: &str, flag: &str) -> R<Vec<f64>> {
    scaled_time_list(parameter, spec, flag, "c1t/R")
}

/// The times of `SCALE=T1,T2,...` (each finite), `scale` naming the time's unit (`c1t/R`,
/// `c2t/R`).
pub fn scaled_time_list(
    parameter: &'static str,
    spec: &str,
    flag: &str,
    scale: &str,
) -> R<Vec<f64>> {
    let rest = spec
        .strip_prefix(scale)
        .and_then(|r| r.strip_prefix('='))
        .ok_or_else(|| {
            InputError::new(
                parameter,
                format!("invalid {flag} {spec:?}: write {scale}=VALUE[,VALUE...]"),
            )
        })?;
    rest.split(',')
        .map(|s| {
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    InputError::new(
                        parameter,
                        format!("invalid {flag} value {s:?}: not a finite number"),
                    )
                })
        })
        .collect()
}

/// The default cap of `--end separation`, c1 t/R.
pub const SEPARATION_CAP: f64 = 400.0;

/// `--end`: an end time `c1t/R=VALUE`, or the separation (`separation`, capped at
/// [`SEPARATION_CAP`], or `separation:max=VALUE`).
pub fn end(spec: &str) -> R<(f64, Stop)> {
    let bad = || {
        InputError::new(
            "end",
            format!("invalid --end {spec:?}: c1t/R=VALUE, separation or separation:max=VALUE"),
        )
    };
    if let Some(rest) = spec.strip_prefix("separation") {
        let cap = match rest.strip_prefix(':') {
            None if rest.is_empty() => SEPARATION_CAP,
            Some(kvs) => one(
                "end",
                &kv("end", kvs, "--end")?,
                "max",
                "--end separation:max=VALUE",
            )?,
            None => return Err(bad()),
        };
        return Ok((cap, Stop::AtSeparation));
    }
    let end = time_list("end", spec, "--end").map_err(|_| bad())?;
    if end.len() != 1 {
        return Err(InputError::new(
            "end",
            "invalid --end: one time, c1t/R=VALUE",
        ));
    }
    Ok((end[0], Stop::AtEnd))
}

/// The striker of `--striker`: `rigid`, `elastic:c1=..,c2=..,density_ratio=..`,
/// `cylinder:c1=..,c2=..,density_ratio=..` or
/// `shell:thickness_over_R=..,c1=..,c2=..,density_ratio=..`, its wave speeds in m/s over the
/// half-plane's `c1` (m/s; a deformable striker needs it).
pub fn striker(spec: &str, c1: Option<f64>) -> R<Striker> {
    let p = "striker";
    if spec == "rigid" {
        return Ok(Striker::Rigid);
    }
    let (kind, rest) = spec.split_once(':').ok_or_else(|| {
        InputError::new(
            p,
            format!(
                "invalid --striker {spec:?}: rigid, elastic:c1=..,c2=..,density_ratio=.., \
                 cylinder:c1=..,c2=..,density_ratio=.. or \
                 shell:thickness_over_R=..,c1=..,c2=..,density_ratio=.."
            ),
        )
    })?;
    let keys: &[&str] = match kind {
        "elastic" | "cylinder" => &["c1", "c2", "density_ratio"],
        "shell" => &["thickness_over_R", "c1", "c2", "density_ratio"],
        other => {
            return Err(InputError::new(
                p,
                format!("invalid --striker kind {other:?}: one of rigid, elastic, cylinder, shell"),
            ))
        }
    };
    let pairs = kv(p, rest, "--striker")?;
    let get = |k: &str| -> R<f64> {
        let mut found = pairs.iter().filter(|(n, _)| n == k);
        match (found.next(), found.next()) {
            (Some(x), None) => Ok(x.1),
            _ => Err(InputError::new(
                p,
                format!(
                    "invalid --striker {spec:?}: {kind} needs {} (each once)",
                    keys.iter()
                        .map(|k| format!("{k}=.."))
                        .collect::<Vec<_>>()
                        .join(",")
                ),
            )),
        }
    };
    if let Some((k, _)) = pairs.iter().find(|(n, _)| !keys.contains(&n.as_str())) {
        return Err(InputError::new(
            p,
            format!(
                "invalid --striker {spec:?}: unknown key {k:?} (keys: {})",
                keys.join(", ")
            ),
        ));
    }
    let Some(c1) = c1 else {
        return Err(InputError::new(
            "c1",
            format!(
                "--striker {kind} gives its wave speeds in m/s: give the half-plane's --c1 and --c2 (m/s) instead of --poisson"
            ),
        ));
    };
    let material = StrikerMaterial {
        c1_ratio: get("c1")? / c1,
        c2_ratio: get("c2")? / c1,
        density_ratio: get("density_ratio")?,
    };
    Ok(match kind {
        "elastic" => Striker::Elastic(material),
        "cylinder" => Striker::Cylinder(material),
        _ => Striker::Shell(ShellStriker {
            thickness: get("thickness_over_R")?,
            material,
        }),
    })
}

/// The drive: a free striker (`mass_ratio` m0/(rho R^2) and `v0_over_c1`; a shell's mass
/// follows from its geometry) or a prescribed penetration (`driven`: `speed:V_over_c1=..` or
/// `table:FILE`). Each combination is refused with the flags it lacks or contradicts.
pub fn drive(
    driven: Option<&str>,
    mass_ratio: Option<f64>,
    v0_over_c1: Option<f64>,
    striker: &Striker,
) -> R<Drive> {
    Ok(match (driven, mass_ratio, v0_over_c1) {
        (Some(_), Some(_), _) | (Some(_), _, Some(_)) => {
            return Err(InputError::new(
                "driven",
                "contradictory flags: --driven replaces --mass-ratio and --v0-over-c1",
            ))
        }
        (Some(d), None, None) => {
            if let Some(rest) = d.strip_prefix("speed:") {
                Drive::Speed(one(
                    "driven",
                    &kv("driven", rest, "--driven")?,
                    "V_over_c1",
                    "--driven",
                )?)
            } else if let Some(path) = d.strip_prefix("table:") {
                Drive::Table(read_table("driven", path, "driven table")?)
            } else {
                return Err(InputError::new(
                    "driven",
                    format!("invalid --driven {d:?}: speed:V_over_c1=.. or table:FILE"),
                ));
            }
        }
        (None, Some(_), _) if striker.own_mass_ratio().is_some() => {
            return Err(InputError::new(
                "mass_ratio",
                format!(
                    "contradictory flags: --mass-ratio with --striker {} (its mass follows from its geometry and density)",
                    striker.name()
                ),
            ))
        }
        (None, None, Some(v)) => match striker.own_mass_ratio() {
            Some(mass_ratio) => Drive::Free {
                mass_ratio,
                v0_over_c1: v,
            },
            None => {
                return Err(InputError::new(
                    "mass_ratio",
                    "missing --mass-ratio (or --driven)",
                ))
            }
        },
        (None, Some(m), Some(v)) => Drive::Free {
            mass_ratio: m,
            v0_over_c1: v,
        },
        (None, None, None) => {
            return Err(InputError::new(
                "mass_ratio",
                "missing --mass-ratio and --v0-over-c1 (or --driven)",
            ))
        }
        (None, Some(_), None) => {
            return Err(InputError::new(
                "v0_over_c1",
                "missing --v0-over-c1 (or --driven)",
            ))
        }
    })
}
