//! Fuzz tests of the inputs a user writes: the profile readers (CSV, SIMPACK, MiniProf through
//! `profile::read::parse_str_with`) and the scene parser (`scene::Scene::from_toml`), as
//! proptest properties that run on the stable toolchain.
//!
//! # Budget
//!
//! `WHEELRAIL_FUZZ_CASES` cases per property (default 256: under 1 s in `cargo test --release
//! --test fuzz` on 2 cores, so the suite runs in CI). For a longer run by hand:
//!
//! ```text
//! WHEELRAIL_FUZZ_CASES=20000 cargo test --release --test fuzz
//! ```
//!
//! Coverage-guided fuzzing of the same two entry points with libFuzzer lives in `fuzz/`
//! (`cargo +nightly fuzz run profile_text -s none`, see `fuzz/README.md`); its findings are
//! regression tests in `tests/regression.rs`.
//!
//! # What the properties guarantee
//!
//! * Nothing panics, whatever the bytes.
//! * A profile the readers accept has at least `MIN_POINTS` finite points with strictly
//!   increasing lateral coordinate, and the spline through it evaluates to finite values; an
//!   error names a line within the text (or none) and displays as a non-empty message.
//! * A scene the parser accepts has a non-empty, increasing, finite sweep within +-100 mm,
//!   nominal radii within 100-1000 mm, a positive load, and an effective quasi-elastic
//!   eps within (0, 1] mm; with the built-in profiles it places, and a rigid search over it
//!   returns finite-or-flagged positions.

use proptest::prelude::*;
use std::path::Path;
use wheelrail::profile::read::{
    PointProfile, ProfileFormat, ReadError, ReadOptions, StepBack, parse_str_with,
};
use wheelrail::profile::{Profile, ProfileKind};
use wheelrail::rigid::{self, Solver, Stop};
use wheelrail::scene::Scene;
use wheelrail::sweep::Sweep;

fn cases() -> u32 {
    std::env::var("WHEELRAIL_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(256)
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: cases(),
        // Shrinking a 40 kB file byte by byte takes long; a few hundred steps find the line.
        max_shrink_iters: 512,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

const FORMATS: [ProfileFormat; 3] = [
    ProfileFormat::Csv,
    ProfileFormat::Simpack,
    ProfileFormat::MiniProf,
];
const OPTIONS: [StepBack; 2] = [StepBack::Refuse, StepBack::Drop];

/// The readers' contract on one text, for one format, kind and option.
fn check_parse(text: &str, format: ProfileFormat, kind: ProfileKind, step_back: StepBack) {
    let lines = line_count(text);
    match parse_str_with(text, format, kind, "fuzz", &ReadOptions::new(step_back)) {
        Ok(p) => {
            assert!(p.points.len() >= PointProfile::MIN_POINTS);
            assert!(p.points.windows(2).all(|w| w[1][0] > w[0][0]));
            assert!(p.points.iter().flatten().all(|v| v.is_finite()));
            assert!(p.dropped_step_backs.iter().all(|&l| l >= 1 && l <= lines));
            if step_back == StepBack::Refuse {
                assert!(p.dropped_step_backs.is_empty());
            }
            for smoothing in [0.0, 4.0] {
                if let Ok(profile) = Profile::from_points(p.clone(), smoothing) {
                    let (lo, hi) = profile.domain();
                    for k in 0..=8 {
                        let u = lo + (hi - lo) * f64::from(k) / 8.0;
                        assert!(profile.eval(u).iter().all(|v| v.is_finite()), "at {u}");
                    }
                }
            }
        }
        Err(e) => check_error(&e, lines),
    }
}

/// The lines of `text` as the readers count them: each ended by `\n`, `\r\n` or a lone
/// `\r` (`str::lines` does not end one at a lone `\r`), the last possibly unended.
fn line_count(text: &str) -> usize {
    let b = text.as_bytes();
    let ends = (0..b.len())
        .filter(|&i| b[i] == b'\n' || (b[i] == b'\r' && b.get(i + 1) != Some(&b'\n')))
        .count();
    ends + usize::from(!matches!(b.last(), None | Some(b'\n' | b'\r')))
}

fn check_error(e: &ReadError, lines: usize) {
    assert!(!e.to_string().is_empty());
    if let Some(line) = e.line() {
        assert!(
            line >= 1 && line <= lines.max(1),
            "{e} (text has {lines} lines)"
        );
    }
}

fn parse_everything(text: &str) {
    for format in FORMATS {
        for kind in [ProfileKind::Wheel, ProfileKind::Rail] {
            for step_back in OPTIONS {
                check_parse(text, format, kind, step_back);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Mutated real files
// ---------------------------------------------------------------------------------------

/// The real profile files, their format and kind.
fn real_files() -> Vec<(String, ProfileFormat, ProfileKind)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/profiles");
    let mut files = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("tests/data/profiles") {
        let path = entry.expect("dir entry").path();
        let Some(ext) = path.extension().map(|e| e.to_string_lossy().into_owned()) else {
            continue;
        };
        let Some((format, implied)) = ProfileFormat::from_extension(&ext) else {
            continue;
        };
        let bytes = std::fs::read(&path).expect("readable");
        let text = String::from_utf8_lossy(&bytes).into_owned();
        files.push((text, format, implied.unwrap_or(ProfileKind::Rail)));
    }
    files.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(files.len() >= 10, "{} files", files.len());
    files
}

/// Values that stress number parsing and the conversions after it.
const NASTY_NUMBERS: [&str; 20] = [
    "0",
    "-0",
    "1e308",
    "-1e308",
    "1e-320",
    "NaN",
    "inf",
    "-inf",
    "1.0D+400",
    "1e",
    "--1",
    "0x10",
    "1,5",
    "",
    "9999999999999999999999",
    "4.9e-324",
    "1.7976931348623157e308",
    "+.5",
    ".",
    "1e-7",
];

#[derive(Debug, Clone)]
enum Mutation {
    /// Flip one byte (at a fraction of the length) to a value.
    Byte(f64, u8),
    /// Delete the line at a fraction of the line count.
    DeleteLine(f64),
    /// Duplicate a line.
    DuplicateLine(f64),
    /// Swap two lines.
    SwapLines(f64, f64),
    /// Replace the n-th whitespace-separated token of a line by a nasty number.
    Token(f64, usize, usize),
    /// Insert a line of text.
    InsertLine(f64, String),
    /// Cut the text at a fraction of its length.
    Truncate(f64),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let frac = 0.0..1.0_f64;
    let inserted = prop_oneof![
        Just("header.begin".to_owned()),
        Just("point.end".to_owned()),
        Just("spline.begin".to_owned()),
        Just("units.len.f = 0".to_owned()),
        Just("mirror.y = 1".to_owned()),
        Just("rotate = 1".to_owned()),
        Just("ColumnDef=Y,X".to_owned()),
        Just("XOffset=1e308".to_owned()),
        Just("#MINIWHEELPROF".to_owned()),
        Just(String::new()),
        Just("y_mm,z_mm".to_owned()),
        "[ -~]{0,40}",
        (-100.0..100.0_f64, -50.0..50.0_f64).prop_map(|(a, b)| format!("{a} {b}")),
    ];
    prop_oneof![
        (frac.clone(), any::<u8>()).prop_map(|(f, b)| Mutation::Byte(f, b)),
        frac.clone().prop_map(Mutation::DeleteLine),
        frac.clone().prop_map(Mutation::DuplicateLine),
        (frac.clone(), frac.clone()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        (frac.clone(), 0..3usize, 0..NASTY_NUMBERS.len())
            .prop_map(|(f, t, n)| Mutation::Token(f, t, n)),
        (frac.clone(), inserted).prop_map(|(f, l)| Mutation::InsertLine(f, l)),
        frac.prop_map(Mutation::Truncate),
    ]
}

fn index(frac: f64, len: usize) -> usize {
    ((frac * len as f64) as usize).min(len.saturating_sub(1))
}

fn apply(text: &str, mutations: &[Mutation]) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let mut tail_cut: Option<f64> = None;
    for m in mutations {
        if lines.is_empty() {
            lines.push(String::new());
        }
        let n = lines.len();
        match m {
            Mutation::Byte(f, b) => {
                let i = index(*f, n);
                let mut bytes = lines[i].clone().into_bytes();
                if !bytes.is_empty() {
                    let j = index(*f * 7.0 % 1.0, bytes.len());
                    bytes[j] = *b;
                }
                lines[i] = String::from_utf8_lossy(&bytes).into_owned();
            }
            Mutation::DeleteLine(f) => {
                lines.remove(index(*f, n));
            }
            Mutation::DuplicateLine(f) => {
                let i = index(*f, n);
                lines.insert(i, lines[i].clone());
            }
            Mutation::SwapLines(a, b) => lines.swap(index(*a, n), index(*b, n)),
            Mutation::Token(f, t, k) => {
                let i = index(*f, n);
                let mut tokens: Vec<String> =
                    lines[i].split_whitespace().map(str::to_owned).collect();
                if let Some(tok) = tokens.get_mut(*t) {
                    *tok = NASTY_NUMBERS[*k].to_owned();
                }
                lines[i] = tokens.join(" ");
            }
            Mutation::InsertLine(f, l) => lines.insert(index(*f, n + 1), l.clone()),
            Mutation::Truncate(f) => tail_cut = Some(*f),
        }
    }
    let mut out = lines.join("\n");
    if let Some(f) = tail_cut {
        let mut cut = index(f, out.len() + 1);
        while !out.is_char_boundary(cut) {
            cut -= 1;
        }
        out.truncate(cut);
    }
    out
}

// ---------------------------------------------------------------------------------------
// Scenes with random keys and values
// ---------------------------------------------------------------------------------------

/// Every key of the scene format, by section (`""` for the top level), and a few that do not
/// exist.
const KEYS: [(&str, &str); 38] = [
    ("", "name"),
    ("", "title"),
    ("wheel", "profile"),
    ("wheel", "left_profile"),
    ("wheel", "nominal_radius_mm"),
    ("wheel", "left_nominal_radius_mm"),
    ("wheel", "right_nominal_radius_mm"),
    ("wheel", "smoothing_wavelength_mm"),
    ("rail", "profile"),
    ("rail", "right_profile"),
    ("rail", "inclination"),
    ("rail", "profile_inclination"),
    ("rail", "smoothing_wavelength_mm"),
    ("track", "gauge_mm"),
    ("track", "gauge_point_depth_mm"),
    ("wheelset", "flange_back_mm"),
    ("load", "wheel_load_kN"),
    ("material", "young_GPa"),
    ("material", "poisson"),
    ("material", "wheel_young_GPa"),
    ("material", "rail_poisson"),
    ("sweep", "from_mm"),
    ("sweep", "to_mm"),
    ("sweep", "step_mm"),
    ("outputs", "figures"),
    ("outputs", "formats"),
    ("rigid", "solver"),
    ("quasi_elastic", "epsilon_mm"),
    ("quasi_elastic", "sensitivity_epsilon_mm"),
    ("quasi_elastic", "cutoff"),
    ("quasi_elastic", "max_step_mm"),
    ("quasi_elastic", "quadrature"),
    ("quasi_elastic", "panel_widths"),
    ("hertz", "method"),
    ("hertz", "contact"),
    ("hertz", "normal_load"),
    ("track", "gauge"),
    ("colour", "red"),
];

fn toml_value() -> impl Strategy<Value = String> {
    let float = prop_oneof![
        any::<f64>().prop_map(|v| format!("{v:?}")),
        (-2000.0..2000.0_f64).prop_map(|v| format!("{v:?}")),
        (0.0..1.0_f64).prop_map(|v| format!("{v:?}")),
        prop::sample::select(vec![
            "nan",
            "inf",
            "-inf",
            "0.0",
            "-0.0",
            "1e-300",
            "1e300",
            "1435.0",
            "0.5",
            "0.49999",
            "1360.0",
            "460.0",
            "14.0",
            "1e-5",
            "100.0",
            "-100.0",
            "100.00000001",
        ])
        .prop_map(str::to_owned),
    ];
    let string = prop_oneof![
        prop::sample::select(vec![
            "S1002",
            "UIC60E1",
            "uic60",
            "60E1",
            "1:40",
            "1:20",
            "1:0",
            "0:1",
            "1:-40",
            "vertical",
            "0.2",
            "0.2000001",
            "-0.0",
            "nan",
            "inf",
            "default",
            "paper",
            "exact",
            "rigid",
            "quasi_elastic",
            "projected",
            "vertical",
            "svg",
            "png",
            "roll",
            "profiles",
            "",
            "../../etc/passwd",
            "no_such_file.csv",
        ])
        .prop_map(str::to_owned),
        "[ -~&&[^\"\\\\]]{0,20}",
    ]
    .prop_map(|s| format!("{s:?}"));
    prop_oneof![
        3 => float,
        2 => string.clone(),
        1 => any::<i64>().prop_map(|v| v.to_string()),
        1 => any::<bool>().prop_map(|v| v.to_string()),
        1 => prop::collection::vec(string, 0..4).prop_map(|v| format!("[{}]", v.join(", "))),
        1 => prop::collection::vec(0.0..2.0_f64, 0..4).prop_map(|v| format!("{v:?}")),
        1 => Just("{ a = 1 }".to_owned()),
    ]
}

/// A scene text: some of the keys, each with a random value, grouped into their sections.
fn scene_text() -> impl Strategy<Value = String> {
    prop::collection::vec((0..KEYS.len(), toml_value()), 0..14).prop_map(|entries| {
        let mut top = String::new();
        let mut sections: Vec<(&str, String)> = Vec::new();
        for (k, value) in entries {
            let (section, key) = KEYS[k];
            let line = format!("{key} = {value}\n");
            if section.is_empty() {
                top += &line;
            } else if let Some(s) = sections.iter_mut().find(|s| s.0 == section) {
                s.1 += &line;
            } else {
                sections.push((section, line));
            }
        }
        for (section, body) in sections {
            top += &format!("[{section}]\n{body}");
        }
        top
    })
}

/// The scene parser's contract; returns the scene when accepted.
fn check_scene(text: &str) -> Option<Scene> {
    let scene = Scene::from_toml(text, "fuzz.toml", Path::new(".")).ok()?;
    assert!(!scene.sweep().shifts_mm().is_empty());
    assert!(
        scene
            .sweep()
            .shifts_mm()
            .iter()
            .all(|y| y.is_finite() && y.abs() <= 100.0)
    );
    assert!(scene.sweep().shifts_mm().windows(2).all(|w| w[1] > w[0]));
    assert!(
        scene
            .nominal_radius_mm()
            .iter()
            .all(|r| (100.0..=1000.0).contains(r))
    );
    assert!(scene.wheel_load_n().is_finite() && scene.wheel_load_n() > 0.0);
    let qe = scene.quasi_elastic();
    assert!(qe.epsilon_mm() > 0.0 && qe.epsilon_mm() <= 1.0);
    assert!(qe.cutoff().is_finite() && qe.cutoff() > 0.0);
    match qe.quadrature() {
        wheelrail::quasi_elastic::Quadrature::Trapezoid { max_step_mm } => {
            assert!(max_step_mm.is_finite() && max_step_mm >= 1e-4);
        }
        wheelrail::quasi_elastic::Quadrature::GaussLegendre { panel_widths } => {
            assert!((0.05..=8.0).contains(&panel_widths));
        }
    }
    let layout = &scene.layout();
    assert!(layout.gauge_mm().is_finite() && layout.flange_back_mm() < layout.gauge_mm());
    assert!((0.0..=0.2).contains(&layout.inclination().radians()));
    Some(scene)
}

/// An accepted scene with built-in profiles places, and a rigid search at three of its
/// positions is finite or flagged.
fn run_scene(scene: &Scene) {
    let built_in =
        |r: &wheelrail::scene::ProfileRef| matches!(r, wheelrail::scene::ProfileRef::BuiltIn(_));
    if !(scene.wheel_profiles().iter().all(built_in) && scene.rail_profiles().iter().all(built_in))
    {
        return;
    }
    let Ok(placement) = wheelrail::pipeline::place(scene) else {
        return;
    };
    let n = scene.sweep().shifts_mm().len();
    let ys = [
        scene.sweep().shifts_mm()[0],
        scene.sweep().shifts_mm()[n / 2],
        scene.sweep().shifts_mm()[n - 1],
    ];
    let mut ys = ys.to_vec();
    ys.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    let sweep = rigid::search(
        &placement,
        &Sweep::from_slice(&ys).unwrap(),
        scene.rigid_solver(),
    );
    for p in sweep.positions() {
        if p.stop == Stop::Converged {
            assert!(p.roll.is_finite() && p.axle_height.is_finite(), "{p:?}");
            assert!(
                p.contact
                    .iter()
                    .flatten()
                    .all(|c| c.s.is_finite() && c.r.is_finite())
            );
        }
    }
    let _ = Solver::default();
}

const VALID_SCENE: &str = r#"name = "fuzz"
title = "A scene with every key"

[wheel]
profile = "S1002"
nominal_radius_mm = 460.0
left_nominal_radius_mm = 455.0
smoothing_wavelength_mm = 4.0

[rail]
profile = "UIC60E1"
inclination = "1:40"
profile_inclination = "vertical"

[track]
gauge_mm = 1435.0
gauge_point_depth_mm = 14.0

[wheelset]
flange_back_mm = 1360.0

[load]
wheel_load_kN = 70.0

[material]
young_GPa = 210.0
poisson = 0.3

[sweep]
from_mm = -10.0
to_mm = 10.0
step_mm = 0.5

[outputs]
figures = ["roll", "profiles"]
formats = ["svg"]

[rigid]
solver = "default"

[quasi_elastic]
epsilon_mm = 0.01
sensitivity_epsilon_mm = [0.001, 0.01]
cutoff = 37.0
quadrature = "trapezoid"
max_step_mm = 0.05

[hertz]
method = "exact"
contact = "quasi_elastic"
normal_load = "projected"
"#;

// ---------------------------------------------------------------------------------------
// The properties
// ---------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(config())]

    /// Arbitrary bytes (lossy UTF-8) in every format, kind and option.
    #[test]
    fn readers_take_arbitrary_bytes(bytes in prop::collection::vec(any::<u8>(), 0..2000)) {
        parse_everything(&String::from_utf8_lossy(&bytes));
    }

    /// Real profile files with 1-8 mutations, read in their own format and kind (and in
    /// every other, which must fail cleanly).
    #[test]
    fn readers_take_mutated_real_files(
        file in any::<prop::sample::Index>(),
        mutations in prop::collection::vec(mutation(), 1..8),
        other_format in 0..3usize,
    ) {
        let files = real_files();
        let (text, format, kind) = &files[file.index(files.len())];
        let mutated = apply(text, &mutations);
        for step_back in OPTIONS {
            check_parse(&mutated, *format, *kind, step_back);
        }
        check_parse(&mutated, FORMATS[other_format], *kind, StepBack::Drop);
    }

    /// Scenes of random keys and values (known, unknown, wrong types, extreme numbers).
    #[test]
    fn scene_parser_takes_random_keys_and_values(text in scene_text()) {
        if let Some(scene) = check_scene(&text) {
            run_scene(&scene);
        }
    }

    /// A scene with every key, mutated line by line and byte by byte.
    #[test]
    fn scene_parser_takes_mutated_scenes(mutations in prop::collection::vec(mutation(), 1..6)) {
        let text = apply(VALID_SCENE, &mutations);
        if let Some(scene) = check_scene(&text) {
            run_scene(&scene);
        }
    }
}

#[test]
fn the_unmutated_inputs_are_accepted() {
    // The mutation properties would test little if the originals were refused.
    let scene = check_scene(VALID_SCENE).expect("the full scene is valid");
    run_scene(&scene);
    let accepted = real_files()
        .iter()
        .filter(|(text, format, kind)| {
            parse_str_with(
                text,
                *format,
                *kind,
                "real",
                &ReadOptions::new(StepBack::Drop),
            )
            .is_ok()
        })
        .count();
    // Every real file reads with StepBack::Drop (three of them only so).
    assert_eq!(accepted, real_files().len());
}
