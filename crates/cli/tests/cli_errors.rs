//! Errors a user can act on: each case names the key the user wrote, prints numbers as the
//! input had them and names the fix where there is one; exit code 2 and no panic.

mod common;

use common::{assert_clean_failure, bin, report_scene, root, scratch, stderr};

/// Runs `wheelrail report` on a scene with `body`, into a fresh folder, and expects exit 2
/// with every piece of `must` in the message (and none of `must_not`).
fn refused(name: &str, body: &str, must: &[&str], must_not: &[&str]) {
    let dir = scratch(name);
    let o = report_scene(&dir, &format!("name = \"t\"\n{body}\n"));
    assert_clean_failure(&o, 2, must);
    let err = stderr(&o);
    for m in must_not {
        assert!(!err.contains(m), "unexpected {m:?} in: {err}");
    }
    assert!(!dir.join("out").join("index.html").exists());
}

#[test]
fn a_folding_miniprof_file_names_its_line_and_the_option_that_fixes_it() {
    let file = root().join("tests/data/profiles/Car7216_0001r.whl");
    refused(
        "fold-back",
        &format!("[wheel]\nprofile = \"{}\"", file.display()),
        &[
            "key `wheel.profile`",
            "Car7216_0001r.whl:223",
            "-54.105 mm on line 222",
            "`drop_step_backs = true` under [wheel]",
        ],
        &["left_profile", "54.10500000"],
    );
}

#[test]
fn a_side_key_is_named_when_the_scene_used_it() {
    refused(
        "side-key",
        "[rail]\nright_profile = \"missing.csv\"",
        &["key `rail.right_profile`", "missing.csv"],
        &[],
    );
}

#[test]
fn a_huge_load_is_printed_as_written() {
    refused(
        "huge-load",
        "[load]\nwheel_load_kN = 1e308",
        &["key `load.wheel_load_kN`", "1e308 kN is not a wheel load"],
        &["inf", "00000000"],
    );
}

#[test]
fn a_mirrored_wheel_profile_says_so() {
    // S1002 exported and mirrored: the flange on the field side.
    let dir = scratch("mirrored");
    let csv = dir.join("s1002.csv");
    let o = bin()
        .args(["profile", "s1002", "--step-mm", "0.5", "--out"])
        .arg(&csv)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines: Vec<String> = Vec::new();
    let mut rows: Vec<String> = Vec::new();
    for line in text.lines() {
        if line.starts_with('#') || line.starts_with("s_mm") {
            lines.push(line.to_string());
        } else {
            let (s, rest) = line.split_once(',').unwrap();
            rows.push(format!("{},{rest}", -s.parse::<f64>().unwrap()));
        }
    }
    rows.reverse();
    lines.extend(rows);
    let mirrored = dir.join("mirrored.csv");
    std::fs::write(&mirrored, lines.join("\n")).unwrap();
    refused(
        "mirrored-scene",
        &format!("[wheel]\nprofile = \"{}\"", mirrored.display()),
        &["key `wheel.profile`", "looks mirrored", "mirror.y"],
        &[],
    );
}

#[test]
#[cfg(target_os = "linux")]
fn an_unwritable_folder_is_named_not_a_temporary_one() {
    // /proc/self exists and takes no new files, even for root.
    let dir = scratch("unwritable");
    let scene = dir.join("scene.toml");
    std::fs::write(
        &scene,
        "name = \"t\"\n[outputs]\nfigures = [\"profiles\"]\nformats = [\"svg\"]\n",
    )
    .unwrap();
    let o = bin()
        .arg("report")
        .arg(&scene)
        .args(["--out", "/proc/self"])
        .output()
        .unwrap();
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("/proc/self: cannot write into the folder"),
        "{err}"
    );
    assert!(!err.contains("wheelrail-new"), "{err}");
}

#[test]
fn hertz_takes_negative_exponents_and_explains_a_non_hertzian_case() {
    let o = bin()
        .args(["hertz", "--A", "-1e-3", "--B", "2e-3", "--load", "1000"])
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        out.lines()
            .nth(1)
            .unwrap()
            .ends_with(",exact,0,not_hertzian"),
        "{out}"
    );
    assert!(
        stderr(&o).contains("A = -0.001 1/mm") && stderr(&o).contains("A <= 0"),
        "{}",
        stderr(&o)
    );
    assert!(!out.contains("not Hertzian"), "{out}");
}

/// The inputs of issue 32 that `wheelrail hertz` took: radii in metres, a modulus in MPa,
/// an auxetic and an incompressible Poisson's ratio. Each is refused (exit 2, nothing on
/// standard output) naming the flag, the range of the scene's key and the likely unit.
#[test]
fn hertz_refuses_what_no_wheel_and_rail_can_be_naming_the_unit() {
    let flat_a_b = ["--A", "0.001", "--B", "0.002", "--load", "70000"];
    let cases: [(Vec<&str>, &[&str]); 5] = [
        (
            vec![
                "--r1x", "0.46", "--r1y", "inf", "--r2x", "inf", "--r2y", "0.3", "--load", "70",
            ],
            &[
                "--r1x: 0.46 mm is not a principal radius",
                "expected |r| >= 1 mm",
                "likely a unit mistake: 0.46 m = 460 mm",
            ],
        ),
        (
            [&flat_a_b[..], &["--young-gpa", "210000"]].concat(),
            &[
                "--young-gpa: 210000 GPa",
                "expected 1 to 1000 GPa",
                "likely a unit mistake: 210000 MPa = 210 GPa",
            ],
        ),
        (
            [&flat_a_b[..], &["--poisson", "-0.5"]].concat(),
            &["--poisson: -0.5", "expected 0 <= poisson < 0.5"],
        ),
        (
            [&flat_a_b[..], &["--poisson", "0.5"]].concat(),
            &["--poisson: 0.5", "expected 0 <= poisson < 0.5"],
        ),
        (
            vec!["--A", "1.087", "--B", "1.667", "--load", "70000"],
            &[
                "--A: 1.087 1/mm",
                "likely a unit mistake: 1.087 1/m = 0.001087 1/mm",
            ],
        ),
    ];
    for (args, must) in cases {
        let o = bin().arg("hertz").args(&args).output().unwrap();
        assert_clean_failure(&o, 2, must);
        assert!(o.stdout.is_empty(), "{args:?} printed a row");
        assert!(!stderr(&o).contains("(-1, 0.5)"), "{}", stderr(&o));
    }
}

#[test]
fn help_texts_read_as_text() {
    let o = bin().args(["hertz", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(o.status.success());
    assert!(!help.contains("[`"), "raw doc link in: {help}");
    let o = bin().arg("--help").output().unwrap();
    let help = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        help.contains("Without a command, wheelrail regenerates the paper's report"),
        "{help}"
    );
}
