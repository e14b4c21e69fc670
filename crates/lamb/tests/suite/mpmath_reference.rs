//! A third route: the values of an independent mpmath implementation
//! (`tests/reference/lamb_mpmath.py`, its own derivation from the potentials and plain
//! quadrature for the step responses and moments, two precisions agreeing to the digits kept),
//! stored in `tests/reference/lamb_reference.json`.

use lamb::HalfPlane;
use rug::Float;
use serde_json::Value;

const BITS: u32 = 200;

fn parse(v: &Value) -> Option<Float> {
    // a value is a decimal string, or an object {"value": "...", "rel_err"/"abs_err": ...}
    let v = if v.is_object() { &v["value"] } else { v };
    let s = v
        .as_str()
        .map(str::to_string)
        .or_else(|| v.as_number().map(|n| n.to_string()))?;
    Float::parse(s.trim())
        .ok()
        .map(|p| Float::with_val(BITS, p))
}

fn check(what: &str, got: &Float, want: &Float, f64_got: Option<f64>) {
    let scale = want.to_f64().abs().max(1e-3);
    let d = Float::with_val(BITS, got - want).abs().to_f64() / scale;
    assert!(
        d < 1e-35,
        "{what}: {} vs {} ({d:e})",
        got.to_f64(),
        want.to_f64()
    );
    if let Some(x) = f64_got {
        let d = (x - want.to_f64()).abs() / scale;
        assert!(d < 1e-12, "{what} (f64): {x} vs {} ({d:e})", want.to_f64());
    }
}

#[test]
fn closed_forms_agree_with_the_independent_mpmath_values() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/reference/lamb_reference.json"
    );
    let text = std::fs::read_to_string(path).expect("reference file");
    let v: Value = serde_json::from_str(&text).unwrap();
    let cases = v["cases"].as_array().unwrap();
    assert!(!cases.is_empty());
    let mut compared = 0;
    for case in cases {
        let m = parse(&case["m"]).unwrap();
        let hp = HalfPlane::new(m.clone()).unwrap();
        let hp64 = HalfPlane::new(m.to_f64()).unwrap();
        let nu = case["nu"].to_string();
        let c = hp.rayleigh_constants();
        for (k, got) in [
            ("s_R", &c.s_r),
            ("r_zz", &c.r_zz),
            ("r_xx", &c.r_xx),
            ("K_R", &c.k_r),
        ] {
            if let Some(want) = parse(&case[k]) {
                check(&format!("nu {nu} {k}"), got, &want, None);
                compared += 1;
            }
        }
        for p in case["points"].as_array().into_iter().flatten() {
            let Some(s) = parse(&p["s"]) else { continue };
            // the f64 point is the rounded s, and g moves with it next to s_R, m and 1: there
            // the f64 values are checked elsewhere against the same rounded point
            let near = (s.to_f64() - c.s_r.to_f64()).abs() < 1e-3
                || (s.to_f64() - hp.m().to_f64()).abs() < 1e-3
                || (s.to_f64() - 1.0).abs() < 1e-3;
            let s64 = s.to_f64();
            let g = hp.impulse(&s).unwrap();
            let g64 = hp64.impulse(&s64).ok();
            for (k, got, x) in [
                ("g_zz", &g.zz.value, g64.as_ref().map(|t| t.zz.value)),
                ("g_xz", &g.xz.value, g64.as_ref().map(|t| t.xz.value)),
                ("g_xx", &g.xx.value, g64.as_ref().map(|t| t.xx.value)),
            ] {
                if let Some(want) = parse(&p[k]) {
                    check(
                        &format!("nu {nu} s {s64} {k}"),
                        got,
                        &want,
                        if near { None } else { x },
                    );
                    compared += 1;
                }
            }
            if s64 > 0.0 && s64 < 1.0 {
                let w = hp.step(&s).unwrap();
                for (k, got) in [
                    ("W_zz", &w.zz.value),
                    ("U_xz", &w.xz.value),
                    ("U_xx", &w.xx.value),
                ] {
                    if let Some(want) = parse(&p[k]) {
                        check(&format!("nu {nu} s {s64} {k}"), got, &want, None);
                        compared += 1;
                    }
                }
            }
        }
        for cell in case["cells"].as_array().into_iter().flatten() {
            let (Some(sa), Some(sb)) = (parse(&cell["sa"]), parse(&cell["sb"])) else {
                continue;
            };
            for (n, pre) in [(0usize, "Ix"), (1, "It"), (2, "I2")] {
                if n > 0 && sa == 0.0 {
                    continue;
                }
                let Ok(t) = hp.cell(n, &sa, &sb) else {
                    continue;
                };
                for (k, got) in [
                    ("zz", &t.zz.value),
                    ("xz", &t.xz.value),
                    ("xx", &t.xx.value),
                ] {
                    let key = format!("{pre}_{k}");
                    if let Some(want) = parse(&cell[key.as_str()]) {
                        check(
                            &format!("nu {nu} cell [{}, {}] {key}", sa.to_f64(), sb.to_f64()),
                            got,
                            &want,
                            None,
                        );
                        compared += 1;
                    }
                }
            }
        }
    }
    assert!(compared > 100, "only {compared} values compared");
}
