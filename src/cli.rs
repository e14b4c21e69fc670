//! What the command-line programs share: parsing of list and range arguments, and the
//! serialisation of the library's typed reports (JSON objects, CSV rows, tables). Each
//! program uses a part of it.
#![allow(dead_code)]
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use dyncontact::{CaseInput, FieldReport, Item, Selection, SolveReport, StressReport, FIELD_KEYS};
use rug::Float;
use serde_json::{Map, Number, Value};
use wedge::{Result, WedgeError};

/// A JSON number with exactly the digits given (arbitrary precision).
pub fn num(s: &str) -> Value {
    match s.parse::<Number>() {
        Ok(n) => Value::Number(n),
        Err(_) => Value::Null,
    }
}

/// An f64 (an error estimate) as a JSON number.
pub fn ratio(x: f64) -> Value {
    num(&format!("{x:e}"))
}

/// The JSON value of an item (`None` for one the selection left out).
fn item(it: &Item) -> Option<Value> {
    Some(match it {
        Item::Number(q) => num(q.text()),
        Item::Name(s) => Value::String((*s).into()),
        Item::Flag(b) => Value::Bool(*b),
        Item::Ratio(x) => ratio(*x),
        Item::Count(n) => Value::Number((*n).into()),
        Item::Unavailable(_) => Value::Null,
        Item::Omitted => return None,
    })
}

fn inputs(o: &mut Map<String, Value>, input: &CaseInput) {
    o.insert("c1".into(), num(input.material.c1().text()));
    o.insert("c2".into(), num(input.material.c2().text()));
    o.insert("theta_deg".into(), num(input.indenter.theta_deg().text()));
    o.insert("gamma".into(), num(input.indenter.gamma().text()));
    o.insert(
        "coupling".into(),
        Value::String(input.indenter.coupling().name().into()),
    );
}

/// A `solve` report as a JSON object: the keys of [`SOLVE_KEYS`] it carries (null where
/// unavailable, absent where the selection left them out), `error_estimates` (absolute, per
/// quantity), `unavailable` (the reasons, when any) and the case's inputs.
pub fn solve_json(r: &SolveReport) -> Value {
    let mut o = Map::new();
    let items = r.items();
    for (k, it) in &items {
        if let Some(v) = item(it) {
            o.insert((*k).into(), v);
        }
    }
    let est: Map<String, Value> = r
        .quantities()
        .into_iter()
        .map(|(k, q)| (k.to_string(), ratio(q.error())))
        .collect();
    o.insert("error_estimates".into(), Value::Object(est));
    let why: Map<String, Value> = r
        .unavailable()
        .into_iter()
        .map(|(k, reason)| (k.to_string(), Value::String(reason.into())))
        .collect();
    if !why.is_empty() {
        o.insert("unavailable".into(), Value::Object(why));
    }
    inputs(&mut o, &r.input);
    Value::Object(o)
}

/// The CSV header of `curve`: the [`SOLVE_KEYS`] of the selection, then `err_<key>` for its
/// [`ESTIMATED_KEYS`].
pub fn solve_csv_header(sel: &Selection) -> String {
    sel.solve_keys()
        .iter()
        .map(|k| k.to_string())
        .chain(sel.estimated_keys().iter().map(|k| format!("err_{k}")))
        .collect::<Vec<_>>()
        .join(",")
}

/// One CSV row of `curve`, the columns of [`solve_csv_header`] (empty cells where
/// unavailable).
pub fn solve_csv_row(r: &SolveReport, sel: &Selection) -> String {
    let cell = |v: Option<Value>| match v {
        Some(Value::String(s)) => s,
        Some(Value::Null) | None => String::new(),
        Some(v) => v.to_string(),
    };
    let keys = sel.solve_keys();
    let values = r
        .items()
        .into_iter()
        .filter(|(k, _)| keys.contains(k))
        .map(|(_, it)| cell(item(&it)));
    let errs = sel
        .estimated_keys()
        .into_iter()
        .map(|k| match r.quantity(k) {
            Some(q) => cell(Some(ratio(q.error()))),
            None => String::new(),
        });
    values.chain(errs).collect::<Vec<_>>().join(",")
}

/// A `stress` report as a JSON object.
pub fn stress_json(r: &StressReport) -> Value {
    let mut m = Map::new();
    m.insert("solution".into(), Value::String(r.solution.name().into()));
    m.insert(
        "r_over_alpha_t".into(),
        Value::Array(r.r_over_alpha_t.iter().map(|x| num(x.text())).collect()),
    );
    m.insert(
        "sigma_over_mu_cot_theta".into(),
        Value::Array(
            r.sigma_over_mu_cot_theta
                .iter()
                .map(|q| num(q.text()))
                .collect(),
        ),
    );
    m.insert(
        "sigma_error_estimates".into(),
        Value::Array(
            r.sigma_over_mu_cot_theta
                .iter()
                .map(|q| ratio(q.error()))
                .collect(),
        ),
    );
    m.insert("error_estimate".into(), ratio(r.error_estimate));
    m.insert("digits".into(), Value::Number(r.digits.into()));
    Value::Object(m)
}

/// A `field` report as a JSON object: an array over the points for each of [`FIELD_KEYS`].
pub fn field_json(r: &FieldReport) -> Value {
    let mut o = Map::new();
    o.insert("solution".into(), Value::String(r.solution.name().into()));
    for (i, k) in FIELD_KEYS.iter().enumerate() {
        let col = r.points.iter().map(|pt| num(&pt[i])).collect();
        o.insert((*k).into(), Value::Array(col));
    }
    o.insert("digits".into(), Value::Number(r.digits.into()));
    Value::Object(o)
}

/// Parse points "x:y,x:y" (x/(c1 t), y/(c1 t)) into pairs; `name` goes into the error.
pub fn parse_points(name: &'static str, s: &str) -> Result<Vec<(wedge::Param, wedge::Param)>> {
    let bad = || {
        WedgeError::InvalidParameter(complexfn::InvalidParameter {
            name,
            value: s.to_string(),
            range: "comma-separated x:y pairs (x/(c1 t), y/(c1 t)) with y < 0 and x^2 + y^2 < 1"
                .into(),
        })
    };
    s.split(',')
        .map(|t| {
            let (a, b) = t.split_once(':').ok_or_else(bad)?;
            let x = wedge::Param::parse(name, a).map_err(|_| bad())?;
            let y = wedge::Param::parse(name, b).map_err(|_| bad())?;
            if !(y.value() < 0.0) {
                return Err(bad());
            }
            Ok((x, y))
        })
        .collect()
}

/// Parse "a,b,c" into decimal parameters (kept as text for arbitrary precision).
pub fn parse_params(name: &'static str, s: &str) -> Result<Vec<wedge::Param>> {
    s.split(',').map(|t| wedge::Param::parse(name, t)).collect()
}

/// Parse a range "min,max,steps" (steps >= 2, min < max).
pub fn parse_range(name: &'static str, s: &str) -> Result<(wedge::Param, wedge::Param, usize)> {
    let bad = || {
        WedgeError::InvalidParameter(complexfn::InvalidParameter {
            name,
            value: s.to_string(),
            range: "min,max,steps with min < max and an integer steps >= 2".into(),
        })
    };
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(bad());
    }
    let (lo, hi) = (
        wedge::Param::parse(name, parts[0])?,
        wedge::Param::parse(name, parts[1])?,
    );
    let n: f64 = parts[2].parse().map_err(|_| bad())?;
    if !(lo.value() < hi.value()) || n < 2.0 || n.fract() != 0.0 || n > 1e6 {
        return Err(bad());
    }
    Ok((lo, hi, n as usize))
}

/// The resolution of f64 at |x|: the spacing of the doubles just above |x| (the smallest
/// positive normal double at 0).
pub fn f64_resolution(x: f64) -> f64 {
    let a = x.abs();
    if a == 0.0 || !a.is_finite() {
        return f64::MIN_POSITIVE;
    }
    f64::from_bits(a.to_bits() + 1) - a
}

/// Refuses a range `lo`..`hi` in `n` steps whose spacing (hi - lo)/(n - 1) is below the f64
/// resolution of its larger end (two of its points would be the same double, and the f64
/// checks made on each point, the admissibility flags among them, could not tell them
/// apart); `name` and the range's text `s` go into the error.
pub fn check_spacing(
    name: &'static str,
    s: &str,
    lo: &wedge::Param,
    hi: &wedge::Param,
    n: usize,
) -> Result<()> {
    let like = Float::with_val(256, 0);
    let (a, b): (Float, Float) = (lo.to_real(&like), hi.to_real(&like));
    let step = (Float::with_val(256, &b - &a) / ((n - 1) as u32)).to_f64();
    let resolution = f64_resolution(lo.value().abs().max(hi.value().abs()));
    if step < resolution {
        return Err(WedgeError::InvalidParameter(complexfn::InvalidParameter {
            name,
            value: s.to_string(),
            range: format!(
                "min,max,steps spaced at least the f64 resolution of its values: \
                 (max - min)/(steps - 1) = {step:.3e} is below {resolution:.3e}"
            ),
        }));
    }
    Ok(())
}

/// `x` as plain decimal text with at most `digits` significant digits, trailing zeros
/// dropped (scientific notation outside 1e-6 .. 1e21).
fn decimal_text(x: &Float, digits: usize) -> String {
    let (negative, mantissa, exp) = x.to_sign_string_exp(10, Some(digits));
    let Some(exp) = exp else {
        // zero (or not finite, which a grid of finite ends never holds)
        return mantissa;
    };
    let m = mantissa.trim_end_matches('0');
    let m = if m.is_empty() { "0" } else { m };
    let sign = if negative { "-" } else { "" };
    // the value is 0.m x 10^exp
    let body = if (-5..=21).contains(&exp) {
        let len = m.len() as i32;
        if exp <= 0 {
            format!("0.{}{m}", "0".repeat((-exp) as usize))
        } else if exp >= len {
            format!("{m}{}", "0".repeat((exp - len) as usize))
        } else {
            let (int, frac) = m.split_at(exp as usize);
            format!("{int}.{frac}")
        }
    } else {
        let (first, rest) = m.split_at(1);
        let dot = if rest.is_empty() { "" } else { "." };
        format!("{first}{dot}{rest}e{}", exp - 1)
    };
    format!("{sign}{body}")
}

/// `n` evenly spaced values from `lo` to `hi` (decimal texts) for a working precision of
/// `bits`: the ends as given, and each point in between computed at `bits` plus guard bits
/// (at least 160) and kept as the shortest decimal text that holds the working precision
/// (enough digits to round-trip a value of `bits` bits), so that each point is parsed at the
/// working precision as the spacing computed it and is printed at that precision whatever
/// digits the report prints.
pub fn linspace(lo: &wedge::Param, hi: &wedge::Param, n: usize, bits: u32) -> Vec<wedge::Param> {
    let wide = bits.max(128) + 32;
    let like = Float::with_val(wide, 0);
    let (a, b): (Float, Float) = (lo.to_real(&like), hi.to_real(&like));
    // digits that round-trip a value of `bits` bits (17 for f64)
    let digits = (f64::from(bits) * std::f64::consts::LOG10_2).ceil() as usize + 1;
    (0..n)
        .map(|i| {
            if i == 0 {
                return lo.clone();
            }
            if i + 1 == n {
                return hi.clone();
            }
            let x = Float::with_val(wide, &b - &a) * (i as u32) / ((n - 1) as u32) + &a;
            let text = decimal_text(&x, digits);
            wedge::Param::parse("alpha", &text).unwrap_or_else(|_| x.to_f64().into())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_text_is_plain_and_trimmed() {
        let f = |s: &str, d| decimal_text(&Float::with_val(200, Float::parse(s).unwrap()), d);
        assert_eq!(f("200", 17), "200");
        assert_eq!(f("427.0", 17), "427");
        assert_eq!(f("177.18", 17), "177.18");
        assert_eq!(f("0.000123", 17), "0.000123");
        assert_eq!(f("1e-9", 17), "1e-9");
        assert_eq!(f("-2.5", 17), "-2.5");
        assert_eq!(f("1234.5678", 6), "1234.57");
        assert_eq!(f("0.1", 40), "0.1");
    }
}
