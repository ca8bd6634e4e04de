//! Adversarial scenes: random but syntactically valid scenes over the whole key space (every
//! numeric key pushed to 0, ±1e-300, ±1e300, subnormals, the largest double, NaN and
//! infinities as well as to plausible values; every profile file of the test data, good and
//! bad), each run through the `wheelrail` binary as a user runs it.
//!
//! # What every scene must show
//!
//! * exit code 0 or 2: never a panic (no "panicked" on stderr), never an abort or a signal;
//! * an accepted scene (exit 0) is within the work budget (`cost::estimate` of the same
//!   scene), and a refused one over the budget says so (`--allow-long`);
//! * every non-finite number of every CSV is flagged (`common::unflagged_non_finite`);
//! * `y_ws_mm`, where a table has it, strictly increases.
//!
//! # Budget
//!
//! `WHEELRAIL_ADVERSARIAL_CASES` scenes (default 150, 4 to 11 s in `cargo test --release
//! --test adversarial` on 2 cores). CI fixes `PROPTEST_RNG_SEED`. For a long run by hand,
//! with one line per scene (exit code, seconds, estimated work) appended to a log:
//!
//! ```text
//! WHEELRAIL_ADVERSARIAL_CASES=20000 WHEELRAIL_ADVERSARIAL_LOG=/tmp/adversarial.log \
//!     cargo test --release --test adversarial
//! ```

mod common;

use common::root;
use proptest::prelude::*;
use std::io::Write;
use std::path::PathBuf;
use std::process::Command;
use std::time::Instant;

fn cases() -> u32 {
    std::env::var("WHEELRAIL_ADVERSARIAL_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(150)
}

/// A float as TOML writes it (`nan`, `inf`; Rust's `{:?}` otherwise: `1e300`, `5e-324`).
fn toml_float(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{v:?}")
    }
}

/// Values no key should meet unprepared.
const EXTREMES: [f64; 24] = [
    0.0,
    -0.0,
    1e-300,
    -1e-300,
    1e300,
    -1e300,
    5e-324,
    -5e-324,
    2.2250738585072014e-308,
    f64::MAX,
    f64::MIN,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e-9,
    1e-6,
    1e-3,
    0.5,
    1.0,
    -1.0,
    100.0,
    -100.0,
    1000.0,
    1e6,
];

/// A numeric key: absent, plausible (in `range`), or extreme.
fn number(range: std::ops::Range<f64>, x: u32) -> BoxedStrategy<Option<String>> {
    if x == 0 {
        return prop_oneof![Just(None), range.prop_map(|v| Some(toml_float(v)))].boxed();
    }
    prop_oneof![
        10 => Just(None),
        9 => range.prop_map(|v| Some(toml_float(v))),
        x => prop::sample::select(EXTREMES.to_vec()).prop_map(|v| Some(toml_float(v))),
    ]
    .boxed()
}

/// A number on a log scale from `10^lo` to `10^hi`, or an extreme, or absent.
fn log_number(lo: f64, hi: f64, x: u32) -> BoxedStrategy<Option<String>> {
    if x == 0 {
        return prop_oneof![
            Just(None),
            (lo..hi).prop_map(|e| Some(toml_float(10f64.powf(e))))
        ]
        .boxed();
    }
    prop_oneof![
        10 => Just(None),
        9 => (lo..hi).prop_map(|e| Some(toml_float(10f64.powf(e)))),
        x => prop::sample::select(EXTREMES.to_vec()).prop_map(|v| Some(toml_float(v))),
    ]
    .boxed()
}

/// A string key: absent, one of `valid`, or (rarely) one of `invalid`.
fn choice(valid: &[&str], invalid: &[&str], x: u32) -> BoxedStrategy<Option<String>> {
    let quoted =
        |v: &[&str]| -> Vec<Option<String>> { v.iter().map(|s| Some(format!("{s:?}"))).collect() };
    let valid = quoted(valid);
    let invalid = quoted(invalid);
    if x == 0 {
        return prop_oneof![Just(None), prop::sample::select(valid)].boxed();
    }
    prop_oneof![
        10 => Just(None),
        9 => prop::sample::select(valid),
        x => prop::sample::select(invalid),
    ]
    .boxed()
}

fn boolean() -> BoxedStrategy<Option<String>> {
    prop::sample::select(vec![
        None,
        Some("true".to_string()),
        Some("false".to_string()),
    ])
    .boxed()
}

/// Every file under the test data's profile folders, and the built-in names.
fn profiles() -> Vec<String> {
    let mut out = vec![
        "S1002".to_string(),
        "UIC60E1".to_string(),
        "s1002".to_string(),
        "no_such_profile.csv".to_string(),
    ];
    for dir in [
        "tests/data/profiles",
        "tests/data/profiles/bad",
        "tests/data/en15302",
        "profiles",
    ] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root().join(dir))
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .filter(|p| {
                p.is_file()
                    && !p.extension().is_some_and(|e| e == "md" || e == "txt")
                    && p.file_name().is_none_or(|n| n != "cases.csv")
                    && !p.to_string_lossy().contains("annexF")
            })
            .collect();
        files.sort();
        out.extend(files.iter().map(|p| p.display().to_string()));
    }
    out
}

/// A profile key: absent, a good profile of the right kind (its name matches `kind`), or
/// (rarely) any file of the test data, bad ones and the other kind included.
fn profile(kind: &[&str], x: u32) -> BoxedStrategy<Option<String>> {
    let all = profiles();
    let good: Vec<String> = all
        .iter()
        .filter(|p| !p.contains("/bad/") && kind.iter().any(|k| p.contains(k)))
        .cloned()
        .collect();
    if x == 0 {
        return prop_oneof![
            1 => Just(None),
            2 => prop::sample::select(good).prop_map(|s| Some(format!("{s:?}"))),
        ]
        .boxed();
    }
    prop_oneof![
        3 => Just(None),
        6 => prop::sample::select(good).prop_map(|s| Some(format!("{s:?}"))),
        1 => prop::sample::select(all).prop_map(|s| Some(format!("{s:?}"))),
    ]
    .boxed()
}

/// Names of good wheel profiles (built-in, `.prw`, `.whl`, EN 15302 `R-*` (Rad), `s1002.csv`).
const WHEELS: [&str; 6] = ["S1002", ".prw", ".whl", "R-UIC", "s1002.csv", "s1002"];
/// Names of good rail profiles (EN 15302 `S-*`: Schiene).
const RAILS: [&str; 6] = ["UIC60E1", ".prr", ".ban", ".BAN", "S-UIC", "uic60e1.csv"];

fn inclination(x: u32) -> BoxedStrategy<Option<String>> {
    if x == 0 {
        return prop_oneof![
            choice(
                &[
                    "1:40", "1:20", "1:30", "vertical", "1:1e300", "0.2", "upright"
                ],
                &[],
                0
            ),
            (0.0..0.2_f64).prop_map(|v| Some(format!("\"{v}\""))),
        ]
        .boxed();
    }
    prop_oneof![
        4 => choice(
            &["1:40", "1:20", "1:30", "vertical", "1:1e300", "1:5e-324", "0.2", "1e-300", "upright"],
            &["1:0", "0:1", "0.2000001", "-0.01", "nan", "inf", "1:-40", "1:x"],
            x,
        ),
        1 => (0.0..0.25_f64).prop_map(|v| Some(format!("\"{v}\""))),
        1 => (1.0..100.0_f64).prop_map(|n| Some(format!("\"1:{n}\""))),
    ]
    .boxed()
}

const FIGURES: [&str; 17] = [
    "profiles",
    "conicity",
    "curvature",
    "contact_points",
    "rolling_radius",
    "equivalent_conicity",
    "delta_r_linearised",
    "contact_angles",
    "roll",
    "contact_angle_parameter",
    "contact_map",
    "qe_contact_points",
    "qe_contact_map",
    "qe_epsilon",
    "semi_axes",
    "pressure",
    "hertz_accuracy",
];

/// Mostly a few figures in no image format (tables only: fast); sometimes SVG or PNG, all
/// figures (the key absent), or an unknown name.
fn outputs() -> BoxedStrategy<Vec<(String, String)>> {
    let figures = prop_oneof![
        1 => Just(None),
        12 => prop::sample::subsequence(FIGURES.to_vec(), 1..=4)
            .prop_map(|f| Some(format!("{f:?}"))),
        1 => Just(Some("[\"nope\"]".to_string())),
    ];
    let formats = prop_oneof![
        1 => Just(None),
        8 => Just(Some("[]".to_string())),
        3 => Just(Some("[\"svg\"]".to_string())),
        1 => Just(Some("[\"png\"]".to_string())),
    ];
    (figures, formats)
        .prop_map(|(f, g)| {
            let mut out = Vec::new();
            if let Some(f) = f {
                out.push(("figures".to_string(), f));
            }
            // Without a formats key all figures render as SVG and PNG: only with few figures.
            out.push((
                "formats".to_string(),
                g.unwrap_or_else(|| "[\"svg\"]".into()),
            ));
            out
        })
        .boxed()
}

/// A list of floats: a few plausible increasing values, repeats, or extremes.
fn float_list(lo: f64, hi: f64, x: u32) -> BoxedStrategy<Option<String>> {
    if x == 0 {
        return prop_oneof![
            Just(None),
            prop::collection::vec(lo..hi, 1..4).prop_map(|mut v| {
                v.sort_by(f64::total_cmp);
                v.dedup_by(|a, b| a.to_bits() == b.to_bits());
                Some(format!(
                    "[{}]",
                    v.iter()
                        .map(|x| toml_float(*x))
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
            }),
        ]
        .boxed();
    }
    prop_oneof![
        6 => Just(None),
        6 => prop::collection::vec(lo..hi, 1..4).prop_map(|mut v| {
            v.sort_by(f64::total_cmp);
            Some(format!("[{}]", v.iter().map(|x| toml_float(*x)).collect::<Vec<_>>().join(", ")))
        }),
        1 => (lo..hi).prop_map(|v| Some(format!("[{0}, {0}]", toml_float(v)))),
        1 => prop::collection::vec(prop::sample::select(EXTREMES.to_vec()), 0..3).prop_map(|v| {
            Some(format!("[{}]", v.iter().map(|x| toml_float(*x)).collect::<Vec<_>>().join(", ")))
        }),
    ]
    .boxed()
}

type Section = (&'static str, Vec<(&'static str, Option<String>)>);

fn wheel(x: u32) -> impl Strategy<Value = Section> {
    (
        (
            profile(&WHEELS, x),
            profile(&WHEELS, x),
            profile(&WHEELS, x),
        ),
        (
            number(300.0..700.0, x),
            number(300.0..700.0, x),
            number(300.0..700.0, x),
        ),
        number(0.0..10.0, x),
        boolean(),
    )
        .prop_map(|((p, l, r), (r0, rl, rr), sm, d)| {
            (
                "wheel",
                vec![
                    ("profile", p),
                    ("left_profile", l.filter(|_| rl.is_some())),
                    ("right_profile", r.filter(|_| rr.is_some())),
                    ("nominal_radius_mm", r0),
                    ("left_nominal_radius_mm", rl),
                    ("right_nominal_radius_mm", rr),
                    ("smoothing_wavelength_mm", sm),
                    ("drop_step_backs", d),
                ],
            )
        })
}

fn rail(x: u32) -> impl Strategy<Value = Section> {
    (
        (profile(&RAILS, x), profile(&RAILS, x), profile(&RAILS, x)),
        inclination(x),
        inclination(x),
        number(0.0..10.0, x),
        boolean(),
        any::<bool>(),
    )
        .prop_map(|((p, l, r), i, pi, sm, d, per_side)| {
            (
                "rail",
                vec![
                    ("profile", p),
                    ("left_profile", l.filter(|_| per_side)),
                    ("right_profile", r.filter(|_| per_side)),
                    ("inclination", i),
                    ("profile_inclination", pi.filter(|_| !per_side)),
                    ("smoothing_wavelength_mm", sm),
                    ("drop_step_backs", d),
                ],
            )
        })
}

fn geometry(x: u32) -> impl Strategy<Value = Vec<Section>> {
    (
        number(1400.0..1470.0, x),
        number(5.0..20.0, x),
        number(1340.0..1380.0, x),
        log_number(0.0, 2.5, x),
        (
            number(50.0..400.0, x),
            number(0.0..0.5, x),
            number(50.0..400.0, x),
            number(0.0..0.5, x),
        ),
    )
        .prop_map(|(gauge, depth, back, load, (e, nu, we, rnu))| {
            vec![
                (
                    "track",
                    vec![("gauge_mm", gauge), ("gauge_point_depth_mm", depth)],
                ),
                ("wheelset", vec![("flange_back_mm", back)]),
                ("load", vec![("wheel_load_kN", load)]),
                (
                    "material",
                    vec![
                        ("young_GPa", e),
                        ("poisson", nu),
                        ("wheel_young_GPa", we),
                        ("rail_poisson", rnu),
                    ],
                ),
            ]
        })
}

fn solvers(x: u32) -> impl Strategy<Value = Vec<Section>> {
    (
        (
            number(-40.0..0.0, x),
            number(0.0..40.0, x),
            log_number(-2.0, 0.5, x),
        ),
        choice(&["default", "paper"], &["exact"], x),
        choice(&["solved", "none"], &["free"], x),
        (
            log_number(-5.0, 0.0, x),
            float_list(1e-4, 0.1, x),
            number(2.0..80.0, x),
            choice(&["gauss_legendre", "trapezoid"], &["simpson"], x),
            log_number(-3.5, 0.5, x),
            number(0.05..8.0, x),
        ),
        (
            choice(&["exact", "paper"], &["approximate"], x),
            choice(&["quasi_elastic", "rigid"], &["elastic"], x),
            choice(&["projected", "vertical"], &["normal"], x),
        ),
        (
            choice(&["klingel", "regression"], &["harmonic"], x),
            float_list(0.1, 12.0, x),
        ),
    )
        .prop_map(
            |(
                (from, to, step),
                solver,
                roll,
                (eps, sens, cutoff, quad, max_step, panel),
                (hm, hc, hn),
                (cm, amps),
            )| {
                // Each quadrature takes its own step key; a mismatch is an error worth
                // drawing too, but rarely.
                let trapezoid = quad.as_deref() == Some("\"trapezoid\"");
                vec![
                    (
                        "sweep",
                        vec![("from_mm", from), ("to_mm", to), ("step_mm", step)],
                    ),
                    ("rigid", vec![("solver", solver), ("roll", roll)]),
                    (
                        "quasi_elastic",
                        vec![
                            ("epsilon_mm", eps),
                            ("sensitivity_epsilon_mm", sens),
                            ("cutoff", cutoff),
                            ("quadrature", quad),
                            ("max_step_mm", max_step.filter(|_| trapezoid)),
                            ("panel_widths", panel.filter(|_| !trapezoid)),
                        ],
                    ),
                    (
                        "hertz",
                        vec![("method", hm), ("contact", hc), ("normal_load", hn)],
                    ),
                    ("conicity", vec![("method", cm), ("amplitudes_mm", amps)]),
                ]
            },
        )
}

/// A whole scene as TOML text: half the scenes with plausible values only (they mostly
/// run, and probe the numerics), half with extremes and invalid choices mixed in (`x`, the
/// weight of an extreme against 19 for the other draws of a key).
fn scene() -> impl Strategy<Value = String> {
    prop_oneof![scene_with(0), scene_with(1)]
}

fn scene_with(x: u32) -> impl Strategy<Value = String> {
    (wheel(x), rail(x), geometry(x), solvers(x), outputs()).prop_map(|(w, r, g, s, o)| {
        let mut text = String::from("name = \"adversarial\"\n");
        let mut sections = vec![w, r];
        sections.extend(g);
        sections.extend(s);
        for (name, keys) in sections {
            text.push_str(&format!("[{name}]\n"));
            for (k, v) in keys {
                if let Some(v) = v {
                    text.push_str(&format!("{k} = {v}\n"));
                }
            }
        }
        text.push_str("[outputs]\n");
        for (k, v) in o {
            text.push_str(&format!("{k} = {v}\n"));
        }
        text
    })
}

/// The scratch folder of this test process.
fn scratch() -> PathBuf {
    let dir = root()
        .join("target/test-scratch/adversarial")
        .join(std::process::id().to_string());
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn log_line(line: &str) {
    if let Ok(path) = std::env::var("WHEELRAIL_ADVERSARIAL_LOG") {
        let mut f = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)
            .unwrap();
        writeln!(f, "{line}").unwrap();
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: cases(),
        failure_persistence: None,
        max_shrink_iters: 64,
        ..ProptestConfig::default()
    })]

    #[test]
    fn adversarial_scenes_exit_cleanly_within_budget_and_flag_non_finite_numbers(text in scene()) {
        let dir = scratch();
        let scene_path = dir.join("scene.toml");
        let out = dir.join("out");
        let _ = std::fs::remove_dir_all(&out);
        std::fs::write(&scene_path, &text).unwrap();
        let start = Instant::now();
        let o = Command::new(env!("CARGO_BIN_EXE_wheelrail"))
            .arg("report")
            .arg(&scene_path)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        let seconds = start.elapsed().as_secs_f64();
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        // The same scene through the library: its estimated work.
        let estimate = wheelrail::scene::Scene::from_toml(&text, "scene.toml", &dir)
            .ok()
            .and_then(|s| {
                let placement = wheelrail::pipeline::place(&s).ok()?;
                Some(wheelrail::cost::estimate(&s, &placement))
            });
        let code = o.status.code();
        log_line(&format!(
            "{} {seconds:.3} {:.3e} {}",
            code.map_or("signal".to_string(), |c| c.to_string()),
            estimate.as_ref().map_or(f64::NAN, |e| e.evaluations),
            err.lines().next().unwrap_or("").replace(&*dir.display().to_string(), "")
        ));
        prop_assert!(!err.contains("panicked"), "panic:\n{}\n{}", err, text);
        prop_assert!(code == Some(0) || code == Some(2), "exit {:?}:\n{}\n{}", o.status, err, text);
        if code == Some(2) {
            prop_assert!(err.starts_with("error: "), "{}\n{}", err, text);
            prop_assert!(!err.contains("internal error"), "{}\n{}", err, text);
            if let Some(e) = estimate.as_ref().filter(|e| !e.within_budget()) {
                prop_assert!(err.contains("--allow-long"), "{}: {}\n{}", e.describe(), err, text);
            }
            return Ok(());
        }
        let e = estimate.expect("an accepted scene parses in the library too");
        prop_assert!(e.within_budget(), "accepted over budget: {}\n{}", e.describe(), text);
        let unflagged = common::unflagged_in_folder(&out);
        prop_assert!(unflagged.is_empty(), "{:#?}\n{}", unflagged, text);
        for entry in std::fs::read_dir(&out).unwrap().flatten() {
            let path = entry.path();
            if path.extension().is_some_and(|x| x == "csv") {
                let csv = std::fs::read_to_string(&path).unwrap();
                if let Some(y) = common::y_ws_column(&csv) {
                    prop_assert!(
                        common::strictly_increasing(&y),
                        "{}: y_ws_mm not strictly increasing: {:?}\n{}",
                        path.display(), &y[..y.len().min(20)], text
                    );
                }
            }
        }
    }
}
