//! The typed report layer: every report round-trips (typed, then JSON, then parsed back,
//! with the same numbers), its JSON keys follow its one ordered key list, its CSV carries
//! the columns of that list; and every admissible range that a message states is the range
//! the code enforces (probed on both sides of each finite end).

use dyncontact::impact_api::{self, EdgeInput, GreenInput, RunInput};
use dyncontact::report::impact::{
    EDGE_COLUMNS, EDGE_KEYS, EDGE_RECORD_KEYS, GREEN_CELL_KEYS, GREEN_KEYS, GREEN_POINT_KEYS,
    RUN_COLUMNS, RUN_KEYS,
};
use dyncontact::{CaseInput, Selection, Speed, SOLVE_KEYS};
use serde_json::Value;
use wedge::{Coupling, Indenter, Material, Param, Solution};

/// Whether `keys` appear in `list` in its order.
fn in_order(keys: &[String], list: &[&str]) -> bool {
    let mut at = 0;
    for k in keys {
        match list[at..].iter().position(|l| l == k) {
            Some(i) => at += i + 1,
            None => return false,
        }
    }
    true
}

fn keys_of(v: &Value) -> Vec<String> {
    v.as_object().unwrap().keys().cloned().collect()
}

fn run_input(extra: impl FnOnce(&mut RunInput)) -> RunInput {
    let mut r = RunInput {
        c1: Some(1870.83),
        c2: Some(1000.0),
        profile: "parabola:R=1".into(),
        mass_ratio: Some(10.0),
        v0_over_c1: Some(0.01),
        end: "c1t/R=1".into(),
        dx: 0.01,
        pressure_at: Some("c1t/R=0.5,1".into()),
        ..RunInput::default()
    };
    extra(&mut r);
    r
}

/// A run's report: its JSON parsed back holds the typed columns' numbers exactly, its keys
/// follow `RUN_KEYS`, and its CSV table has the columns of `RUN_COLUMNS` (then `err_` of each
/// estimated one) with the same numbers.
#[test]
fn run_report_round_trips() {
    for input in [
        run_input(|_| {}),
        run_input(|r| {
            r.mass_ratio = None;
            r.v0_over_c1 = None;
            r.driven = Some("speed:V_over_c1=0.01".into());
        }),
        // (one grid throughout: the start's finer grids in double-double cost twenty seconds)
        run_input(|r| {
            r.digits = Some(25);
            r.start_halvings = Some(0);
        }),
    ] {
        let report = impact_api::run(&input, |_| std::ops::ControlFlow::Continue(())).unwrap();
        let text = serde_json::to_string_pretty(&report.to_json()).unwrap();
        let back: Value = serde_json::from_str(&text).unwrap();
        assert!(in_order(&keys_of(&back), RUN_KEYS), "{:?}", keys_of(&back));
        assert_eq!(back["mass_ratio"].as_f64(), input.mass_ratio);
        assert_eq!(back["v0_over_c1"].as_f64(), input.v0_over_c1);
        assert!(!report.columns.is_empty());
        for col in &report.columns {
            let values = back[col.key].as_array().unwrap();
            assert_eq!(values.len(), col.values.len(), "{}", col.key);
            for (j, x) in values.iter().zip(&col.values) {
                match &x.text {
                    None => assert_eq!(j.as_f64().unwrap(), x.value, "{}", col.key),
                    // the digits asked for, kept as printed
                    Some(t) => assert_eq!(&j.to_string(), t, "{}", col.key),
                }
            }
            if let Some(errs) = &col.errors {
                let e = back["error_estimate"][col.key].as_array().unwrap();
                let e: Vec<f64> = e.iter().map(|x| x.as_f64().unwrap()).collect();
                assert_eq!(&e, errs, "{}", col.key);
            }
        }
        // the CSV: its header is the key list's columns, its cells the same numbers
        let csv = report.to_csv("test");
        let table: Vec<&str> = csv.lines().filter(|l| !l.starts_with('#')).collect();
        let head: Vec<&str> = table[0].split(',').collect();
        let plain: Vec<String> = head
            .iter()
            .filter(|h| !h.starts_with("err_"))
            .map(|h| h.to_string())
            .collect();
        assert!(in_order(&plain, RUN_COLUMNS), "{head:?}");
        for h in head.iter().filter(|h| h.starts_with("err_")) {
            assert!(RUN_COLUMNS.contains(&&h[4..]), "{h}");
        }
        for (i, h) in head.iter().enumerate() {
            let Some(col) = report.column(h) else {
                continue;
            };
            for (row, x) in table[1..=col.values.len()].iter().zip(&col.values) {
                let cell = row.split(',').nth(i).unwrap();
                assert_eq!(cell.parse::<f64>().unwrap(), x.value, "{h}");
            }
        }
        let p = report.pressure.as_ref().unwrap();
        assert_eq!(back["pressure"].as_array().unwrap().len(), p.len());
    }
}

/// The wedge's solve report: every quantity parsed back from the JSON is its text, every
/// estimate its error; the keys follow `SOLVE_KEYS`, then the estimates and the inputs.
#[test]
fn solve_report_round_trips() {
    let input = CaseInput {
        material: Material::paper(),
        indenter: Indenter::new(86.0, 0.6, Coupling::On).unwrap(),
        solution: Solution::Genuine,
        digits: Some(40),
    };
    let speed = Speed::Alpha(Param::parse("alpha", "561.249").unwrap());
    let r = dyncontact::solve(&input, &speed, &Selection::all()).unwrap();
    let back: Value = serde_json::from_str(&r.to_json().to_string()).unwrap();
    let mut list: Vec<&str> = SOLVE_KEYS.to_vec();
    list.extend([
        "error_estimates",
        "unavailable",
        "c1",
        "c2",
        "theta_deg",
        "gamma",
        "coupling",
    ]);
    assert!(in_order(&keys_of(&back), &list), "{:?}", keys_of(&back));
    for (k, q) in r.quantities() {
        assert_eq!(back[k].to_string(), q.text(), "{k}");
        assert_eq!(
            back["error_estimates"][k].as_f64().unwrap(),
            q.error(),
            "{k}"
        );
    }
    let sel = Selection::all();
    let head = dyncontact::SolveReport::csv_header(&sel);
    let row = r.csv_row(&sel);
    assert_eq!(head.split(',').count(), row.split(',').count());
    for (h, cell) in head.split(',').zip(row.split(',')) {
        if let Some(q) = r.quantity(h) {
            assert_eq!(cell, q.text(), "{h}");
        }
    }
}

/// `impact green` and `impact edge`: keys in their lists' order, numbers parsed back equal.
#[test]
fn green_and_edge_reports_round_trip() {
    let g = impact_api::green(&GreenInput {
        poisson: Some("0.25".into()),
        at: Some("0.3,0.8".into()),
        cells: Some("0:0.4,0.5:0.9".into()),
        constants: true,
        digits: Some(30),
        ..GreenInput::default()
    })
    .unwrap();
    let back: Value = serde_json::from_str(&g.to_json().to_string()).unwrap();
    assert!(in_order(&keys_of(&back), GREEN_KEYS));
    let points = g.points.as_ref().unwrap();
    for (p, j) in points.iter().zip(back["points"].as_array().unwrap()) {
        let vals: Vec<&str> = p.g.iter().chain(&p.w).map(|v| v.text.as_str()).collect();
        for (k, v) in GREEN_POINT_KEYS[1..].iter().zip(vals) {
            assert_eq!(j[*k].to_string(), v, "{k}");
        }
    }
    let cells = back["cells"].as_array().unwrap();
    assert!(cells[0]["It_zz"].is_null() && cells[0]["unavailable"]["It"].is_string());
    let csv = g.to_csv("test");
    assert!(csv.contains(&GREEN_CELL_KEYS.join(",")));
    let e = impact_api::edge(&EdgeInput {
        poisson: Some(0.25),
        speed_over_c1: Some("0.3,0.7,1.2".into()),
        ..EdgeInput::default()
    })
    .unwrap();
    let back: Value = serde_json::from_str(&e.to_json().to_string()).unwrap();
    assert!(in_order(&keys_of(&back), EDGE_KEYS));
    for (rec, j) in e.records.iter().zip(back["records"].as_array().unwrap()) {
        assert!(in_order(&keys_of(j), EDGE_RECORD_KEYS), "{:?}", keys_of(j));
        assert_eq!(j["selected"].as_f64().unwrap(), rec.selected);
        let ex: Vec<f64> = j["exponents"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        let typed: Vec<f64> = rec.solutions.iter().map(|s| s.lambda).collect();
        assert_eq!(ex, typed);
    }
    assert!(e.to_csv("x").contains(&EDGE_COLUMNS.join(",")));
}

/// The interval a message states after "admissible range is": its ends (None for inf) and
/// whether each is closed.
fn stated_range(msg: &str) -> Option<(Option<f64>, bool, Option<f64>, bool)> {
    let rest = &msg[msg.find("admissible range is ")? + "admissible range is ".len()..];
    let num = |s: &str| -> Option<f64> {
        match s.trim() {
            "inf" => None,
            t => t.parse().ok(),
        }
    };
    if let Some(body) = rest.strip_prefix(['[', '(']) {
        let open_lo = rest.starts_with('(');
        let close = body.find([']', ')'])?;
        let (lo, hi) = body[..close].split_once(',')?;
        let closed_hi = body[close..].starts_with(']');
        return Some((num(lo), !open_lo, num(hi), closed_hi));
    }
    // "1 to 4", "1..=30"
    let word: String = rest
        .chars()
        .take_while(|c| c.is_ascii_digit() || " to.=".contains(*c))
        .collect();
    let (lo, hi) = word.split_once(" to ").or_else(|| word.split_once("..="))?;
    Some((num(lo), true, num(hi), true))
}

/// Whether `message` refuses the parameter whose refusal began with `prefix`.
fn refuses(result: &Result<(), String>, prefix: &str) -> bool {
    matches!(result, Err(m) if m.starts_with(prefix))
}

/// Probes a stated range: each finite end and a point just beyond it, inside and out, give
/// the refusal exactly where the message says.
/// (`unit`: the step of an integer parameter; `None` for a real one.)
fn probe(what: &str, bad: f64, unit: Option<f64>, check: &dyn Fn(f64) -> Result<(), String>) {
    let msg = check(bad).expect_err(what);
    // the refusal's first two words name the parameter: "invalid kappa", "invalid --digits"
    let prefix: String = msg.split_whitespace().take(2).collect::<Vec<_>>().join(" ");
    let (lo, lo_closed, hi, hi_closed) =
        stated_range(&msg).unwrap_or_else(|| panic!("{what}: no range in {msg:?}"));
    for (end, closed, inward) in [(lo, lo_closed, 1.0), (hi, hi_closed, -1.0)] {
        let Some(e) = end else { continue };
        let step = unit.unwrap_or(1e-9 * e.abs().max(1.0));
        assert_eq!(
            refuses(&check(e), &prefix),
            !closed,
            "{what}: at the end {e} of {msg:?}"
        );
        assert!(
            !refuses(&check(e + inward * step), &prefix),
            "{what}: just inside {e} of {msg:?}"
        );
        assert!(
            refuses(&check(e - inward * step), &prefix),
            "{what}: just outside {e} of {msg:?}"
        );
    }
}

#[test]
fn stated_ranges_are_the_enforced_ranges() {
    let run = |f: &dyn Fn(&mut RunInput)| -> Result<(), String> {
        let mut input = run_input(|_| {});
        input.pressure_at = None;
        input.end = "c1t/R=1".into();
        input.dx = 0.02;
        // one grid throughout: what is probed is the input's admission, and the start on
        // finer grids would multiply the cost of the ranges' ends (kappa 1/2, 30 digits)
        input.start_halvings = Some(0);
        f(&mut input);
        impact_api::run(&input, |_| std::ops::ControlFlow::Continue(()))
            .map(|_| ())
            .map_err(|e| e.to_string())
    };
    probe("kappa", 0.4, None, &|x| run(&|r| r.kappa = x));
    probe("v0_over_c1", 1.5, None, &|x| {
        run(&|r| r.v0_over_c1 = Some(x))
    });
    probe("mass_ratio", -1.0, None, &|x| {
        run(&|r| r.mass_ratio = Some(x))
    });
    probe("levels", 5.0, Some(1.0), &|x| {
        run(&|r| r.levels = x as usize)
    });
    probe("digits", 31.0, Some(1.0), &|x| {
        run(&|r| r.digits = Some(x as u32))
    });
    probe("dx", 0.0, None, &|x| run(&|r| r.dx = x));
    let edge = |nu: f64| -> Result<(), String> {
        impact_api::edge(&EdgeInput {
            poisson: Some(nu),
            speed_over_c1: Some("0.3".into()),
            ..EdgeInput::default()
        })
        .map(|_| ())
        .map_err(|e| e.to_string())
    };
    probe("poisson", 0.7, None, &edge);
    let wedge = |theta: f64| -> Result<(), String> {
        Indenter::new(theta, 0.5, Coupling::On)
            .map(|_| ())
            .map_err(|e| e.to_string())
    };
    probe("theta_deg", 95.0, None, &wedge);
}

/// A bad input names its parameter as the flag is named, underscores for dashes: the name a
/// keyword argument of another front end carries.
#[test]
fn bad_inputs_name_their_flag() {
    let run = |f: &dyn Fn(&mut RunInput)| {
        let mut input = run_input(|_| {});
        f(&mut input);
        impact_api::run(&input, |_| std::ops::ControlFlow::Continue(()))
            .err()
            .and_then(|e| e.parameter())
    };
    assert_eq!(run(&|r| r.kappa = 0.4), Some("kappa"));
    assert_eq!(run(&|r| r.levels = 5), Some("levels"));
    assert_eq!(run(&|r| r.v0_over_c1 = Some(1.5)), Some("v0_over_c1"));
    assert_eq!(run(&|r| r.mass_ratio = Some(-1.0)), Some("mass_ratio"));
    assert_eq!(run(&|r| r.dx = 0.0), Some("dx"));
    assert_eq!(run(&|r| r.digits = Some(31)), Some("digits"));
    assert_eq!(run(&|r| r.end = "t=1".into()), Some("end"));
    assert_eq!(run(&|r| r.profile = "circle".into()), Some("profile"));
    assert_eq!(
        run(&|r| r.profile = "wedge:theta_deg=120".into()),
        Some("profile")
    );
    assert_eq!(run(&|r| r.striker = "x:y".into()), Some("striker"));
    assert_eq!(
        run(&|r| r.pressure_at = Some("c1t/R=5".into())),
        Some("pressure_at")
    );
    assert_eq!(run(&|r| r.end = "c1t/R=0.01".into()), Some("dx"));
    let edge = impact_api::edge(&EdgeInput {
        poisson: Some(0.7),
        speed_over_c1: Some("0.3".into()),
        ..EdgeInput::default()
    });
    assert_eq!(edge.err().and_then(|e| e.parameter()), Some("poisson"));
    for (input, flag) in [
        (
            GreenInput {
                poisson: Some("0.25".into()),
                at: Some("-1".into()),
                ..GreenInput::default()
            },
            "at",
        ),
        (
            GreenInput {
                poisson: Some("0.25".into()),
                at: Some("0.5".into()),
                digits: Some(3000),
                ..GreenInput::default()
            },
            "digits",
        ),
        (
            GreenInput {
                poisson: Some("0.25".into()),
                cells: Some("0.5:0.2".into()),
                ..GreenInput::default()
            },
            "cells",
        ),
    ] {
        let e = impact_api::green(&input).unwrap_err();
        assert_eq!(e.parameter(), Some(flag), "{e}");
    }
}

/// The key lists, `items`, `quantities` and the mutable list the merges use name the same
/// entries in the same order: a field added to the report and forgotten in one of them
/// fails here.
#[test]
fn key_lists_match_the_report_fields() {
    let input = CaseInput {
        material: Material::paper(),
        indenter: Indenter::new(86.0, 0.5, Coupling::On).unwrap(),
        solution: Solution::Paper,
        digits: None,
    };
    let speed = Speed::Alpha(Param::parse("alpha", "500").unwrap());
    let mut r = dyncontact::solve(&input, &speed, &Selection::without_admissibility()).unwrap();
    let items: Vec<&str> = r.items().into_iter().map(|(k, _)| k).collect();
    assert_eq!(items, SOLVE_KEYS);
    let numbers: Vec<&str> = r.quantities().into_iter().map(|(k, _)| k).collect();
    assert_eq!(numbers, dyncontact::ESTIMATED_KEYS);
    let mut mutable: Vec<&str> = r.quantities_mut().into_iter().map(|(k, _)| k).collect();
    mutable.sort_unstable();
    let mut expected = dyncontact::ESTIMATED_KEYS.to_vec();
    expected.sort_unstable();
    assert_eq!(mutable, expected);
}

/// Decimal text in any form the inputs accept is written as a JSON number.
#[test]
fn decimal_text_in_any_accepted_form_is_a_json_number() {
    use dyncontact::report::num;
    for (text, json) in [
        ("+86", "86"),
        (".5", "0.5"),
        ("-.5", "-0.5"),
        ("500.", "500.0"),
        ("086", "86"),
        ("0.001", "0.001"),
        ("1e-3", "1e-3"),
        ("561.249", "561.249"),
    ] {
        assert_eq!(num(text).to_string(), json, "{text}");
    }
    assert_eq!(num("2E+5").as_f64(), Some(2e5));
    assert!(num("abc").is_null());
}

/// A curve's points are plain, trimmed decimal text.
#[test]
fn decimal_text_is_plain_and_trimmed() {
    use dyncontact::input::wedge::decimal_text;
    use rug::Float;
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

/// Numbers longer than a message can show are cut, short ones kept.
#[test]
fn long_numbers_are_cut_and_short_ones_kept() {
    use dyncontact::cli::shorten_numbers;
    let long = format!(
        "invalid gamma = 0.{}: out of range",
        "1234567890".repeat(60)
    );
    let s = shorten_numbers(&long);
    assert!(s.len() < 80, "{s}");
    assert!(s.contains("0.12345678901234567..."), "{s}");
    assert!(s.contains("(601 digits)"), "{s}");
    let short = "invalid kappa = 0.4: admissible range is [0.5, 64] and 1e-300";
    assert_eq!(shorten_numbers(short), short);
}
