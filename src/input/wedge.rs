//! The wedge's text inputs: lists of fractions and points, and alpha ranges, parsed as
//! decimal text kept at the working precision (`wedge stress --at`, `wedge field --at`,
//! `wedge curve --alpha-range`).
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use rug::Float;
use wedge::{Result, WedgeError};

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
pub fn decimal_text(x: &Float, digits: usize) -> String {
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
