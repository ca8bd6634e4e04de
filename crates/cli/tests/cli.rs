//! The `wheelrail` binary run as a user runs it: reports, golden checks, bad input, exit
//! codes, and outputs that are written all or nothing.

mod common;

use common::{assert_clean_failure, bin, root, scratch, stderr};
use std::path::{Path, PathBuf};

/// Runs `wheelrail report SCENE --timings` and returns its standard error (the stages run).
fn report_timings(scene: &Path) -> String {
    let o = bin()
        .arg("report")
        .arg(scene)
        .arg("--timings")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    stderr(&o)
}

/// Writes a scene into `dir` with the given extra TOML (profile-only outputs by default).
fn scene(dir: &Path, body: &str) -> PathBuf {
    let path = dir.join("scene.toml");
    std::fs::write(&path, format!("name = \"t\"\n{body}\n")).unwrap();
    path
}

#[test]
fn paper_report_writes_every_figure_in_both_formats() {
    let out = scratch("paper");
    let o = bin()
        .args(["report", "reports/paper/scene.toml", "--out"])
        .arg(&out)
        .arg("--timings")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    for fig in [
        "profiles",
        "conicity",
        "contact_points",
        "contact_map",
        "qe_contact_points",
        "semi_axes",
        "hertz_accuracy",
    ] {
        assert!(
            out.join(format!("{fig}.svg")).exists() && out.join(format!("{fig}.png")).exists(),
            "{fig}"
        );
        assert!(
            html.contains(&format!("{fig}.svg")),
            "{fig} not in index.html"
        );
    }
    let png = std::fs::read(out.join("profiles.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    for table in [
        "rigid.csv",
        "quasi_elastic.csv",
        "hertz.csv",
        "wheel_profile.csv",
        "rail_profile.csv",
    ] {
        let text = std::fs::read_to_string(out.join(table)).unwrap();
        assert!(text.starts_with('#'), "{table} has no frame/unit header");
    }
    // Settings appear as the scene spells them, not as Rust names them.
    let hertz = std::fs::read_to_string(out.join("hertz.csv")).unwrap();
    for text in [&html, &hertz] {
        assert!(
            text.contains("quasi_elastic contact, normal load projected")
                || text.contains("contact quasi_elastic, normal load projected"),
            "scene values missing"
        );
        assert!(!text.contains("QuasiElastic") && !text.contains("Projected"));
    }
    // Every stage ran, and --timings said so.
    let err = stderr(&o);
    assert!(
        err.contains(&format!("files to {} (open ", out.display())),
        "{err}"
    );
    for stage in ["profiles", "rigid", "quasi_elastic", "hertz"] {
        assert!(err.contains(stage), "{err}");
    }
}

#[test]
fn a_profile_only_scene_runs_no_contact_search() {
    let dir = scratch("profile_only");
    let s = scene(
        &dir,
        "[outputs]\nfigures = [\"profiles\", \"conicity\"]\nformats = [\"svg\"]",
    );
    let err = report_timings(&s);
    // The stages run: the first word of each timing line (`name  0.5 ms`). The last line
    // names the output folder, which may contain any word.
    let stages: Vec<&str> = err
        .lines()
        .filter(|l| l.ends_with(" ms"))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert!(stages.contains(&"profiles"), "{err}");
    for stage in ["rigid", "quasi_elastic", "hertz"] {
        assert!(
            !stages.contains(&stage),
            "stage {stage} ran for a profile-only scene: {err}"
        );
    }
    assert!(dir.join("profiles.svg").exists() && !dir.join("profiles.png").exists());
    assert!(!dir.join("rigid.csv").exists());
}

#[test]
fn golden_check_passes_and_fails_beyond_tolerance() {
    let o = bin()
        .args([
            "check",
            "reports/paper/scene.toml",
            "--golden",
            "golden/paper",
        ])
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}{}",
        stderr(&o),
        String::from_utf8_lossy(&o.stdout)
    );

    // Perturb one roll angle by twice its tolerance: the check fails and names it.
    let dir = scratch("golden_perturbed");
    for e in std::fs::read_dir(root().join("golden/paper"))
        .unwrap()
        .flatten()
    {
        std::fs::copy(e.path(), dir.join(e.file_name())).unwrap();
    }
    let rigid = std::fs::read_to_string(dir.join("rigid.csv")).unwrap();
    let mut lines: Vec<String> = rigid.lines().map(String::from).collect();
    let header = lines.iter().position(|l| !l.starts_with('#')).unwrap();
    let roll_col = lines[header]
        .split(',')
        .position(|c| c == "roll_rad")
        .unwrap();
    let row = header + 250;
    let mut cells: Vec<String> = lines[row].split(',').map(String::from).collect();
    let roll: f64 = cells[roll_col].parse().unwrap();
    let y_ws: f64 = cells[0].parse().unwrap();
    let allowed = wheelrail_cli::golden_policy()
        .tolerance_at("roll_rad", Some(y_ws))
        .allowance(roll);
    // Twice the allowance fails.
    cells[roll_col] = format!("{:.12e}", roll + 2.0 * allowed);
    lines[row] = cells.join(",");
    std::fs::write(dir.join("rigid.csv"), lines.join("\n") + "\n").unwrap();
    let o = bin()
        .args(["check", "reports/paper/scene.toml", "--golden"])
        .arg(&dir)
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(
        out.contains("rigid.csv") && out.contains("roll_rad"),
        "{out}"
    );

    // Within tolerance (half the allowance) it passes.
    cells[roll_col] = format!("{:.12e}", roll + 0.5 * allowed);
    lines[row] = cells.join(",");
    std::fs::write(dir.join("rigid.csv"), lines.join("\n") + "\n").unwrap();
    let o = bin()
        .args(["check", "reports/paper/scene.toml", "--golden"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
}

#[test]
fn bad_scenes_name_the_key_and_exit_2() {
    let dir = scratch("bad_scenes");
    let cases: &[(&str, &[&str])] = &[
        ("[track]\ngauge = 1435.0", &["gauge", "unknown field"]),
        ("[track]\ngauge_mm = -1435.0", &["track.gauge_mm"]),
        ("[material]\npoisson = 0.5", &["poisson"]),
        ("[sweep]\nstep_mm = 0.0", &["sweep.step_mm"]),
        (
            "[sweep]\nstep_mm = 0.000001",
            &["sweep.step_mm", "positions"],
        ),
        ("[load]\nwheel_load_kN = -70.0", &["load.wheel_load_kN"]),
        (
            "[wheel]\nprofile = \"no_such_file.prw\"",
            &["key `wheel.profile`", "no_such_file.prw"],
        ),
        (
            "[rail]\nprofile = \"S1002\"",
            &["key `rail.profile`", "wheel profile"],
        ),
        ("[rigid]\nsolver = \"fast\"", &["rigid.solver"]),
        ("[load]\nwheel_load_kN = 1e306", &["load.wheel_load_kN"]),
        (
            "[quasi_elastic]\nepsilon_mm = 0.0",
            &["quasi_elastic.epsilon_mm"],
        ),
    ];
    for (body, expected) in cases {
        let s = scene(&dir, body);
        let o = bin().arg("report").arg(&s).output().unwrap();
        assert_clean_failure(&o, 2, expected);
        assert!(
            !dir.join("index.html").exists(),
            "{body}: output written despite the error"
        );
    }
    let o = bin()
        .args(["report", "no/such/scene.toml"])
        .output()
        .unwrap();
    assert_clean_failure(&o, 2, &["no/such/scene.toml"]);
}

#[test]
fn bad_profile_files_name_the_file_and_line() {
    let dir = scratch("bad_profiles");
    let bad = root().join("tests/data/profiles/bad");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "rail",
            "non_numeric.csv",
            &["non_numeric.csv:", "non-numeric"],
        ),
        ("rail", "not_finite.csv", &["not_finite.csv:"]),
        ("rail", "empty.csv", &["empty.csv"]),
        ("rail", "header_only.csv", &["header_only.csv"]),
        ("rail", "duplicate_point.csv", &["duplicate_point.csv:"]),
        ("rail", "zig_zag.csv", &["zig_zag.csv:"]),
        ("rail", "metres_values.csv", &["metres_values.csv"]),
        ("rail", "metres_header.csv", &["metres_header.csv"]),
        ("wheel", "rail_type_in.prw", &["rail_type_in.prw"]),
        // A rail file given as the wheel.
        (
            "wheel",
            "../MBench_UIC60_v3.prr",
            &["MBench_UIC60_v3.prr", "rail"],
        ),
    ];
    for (body, file, expected) in cases {
        let s = scene(
            &dir,
            &format!("[{body}]\nprofile = \"{}\"", bad.join(file).display()),
        );
        let o = bin().arg("report").arg(&s).output().unwrap();
        assert_clean_failure(&o, 2, expected);
    }
}

#[test]
fn wheel_and_rail_that_never_overlap_are_an_error() {
    // Placement puts any rail's gauge point at half the gauge, so the head is always where a
    // rail belongs; a wheel profile that covers only its flange back (s from -70 to -65 mm)
    // lies inside the gauge, over no rail: placement refuses it, naming the profiles.
    let dir = scratch("no_overlap");
    let mut csv = String::from("y_mm,z_mm\n");
    for i in 0..=60 {
        let y = 2000.0 + 0.1 * f64::from(i);
        csv.push_str(&format!("{y},{}\n", -0.01 * (y - 2003.0) * (y - 2003.0)));
    }
    std::fs::write(dir.join("rail.csv"), csv).unwrap();
    let mut wheel = String::from("s_mm,F_mm\n");
    for i in 0..=20 {
        let s = -70.0 + 0.25 * f64::from(i);
        wheel.push_str(&format!("{s},{}\n", 10.0 + 0.1 * f64::from(i)));
    }
    std::fs::write(dir.join("wheel.csv"), wheel).unwrap();
    let s = scene(
        &dir,
        "[wheel]\nprofile = \"wheel.csv\"\n[rail]\nprofile = \"rail.csv\"",
    );
    let o = bin().arg("report").arg(&s).output().unwrap();
    assert_clean_failure(&o, 2, &["do not overlap"]);
    assert!(!dir.join("index.html").exists());
}

#[test]
fn a_failed_run_leaves_the_previous_report_intact() {
    let dir = scratch("atomic");
    let good = scene(
        &dir,
        "[outputs]\nfigures = [\"profiles\"]\nformats = [\"svg\"]",
    );
    assert!(
        bin()
            .arg("report")
            .arg(&good)
            .output()
            .unwrap()
            .status
            .success()
    );
    let before = std::fs::read(dir.join("profiles.svg")).unwrap();
    // Same outputs, but a rail file that fails to read: nothing may change.
    let bad = root().join("tests/data/profiles/bad/non_numeric.csv");
    std::fs::write(
        &good,
        format!("name = \"t\"\n[rail]\nprofile = \"{}\"\n[outputs]\nfigures = [\"profiles\"]\nformats = [\"svg\"]\n", bad.display()),
    )
    .unwrap();
    let o = bin().arg("report").arg(&good).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read(dir.join("profiles.svg")).unwrap(), before);
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .filter(|e| {
            e.file_name()
                .to_string_lossy()
                .starts_with(".wheelrail-new")
        })
        .collect();
    assert!(leftovers.is_empty());
}

#[test]
fn hertz_command_prints_a_csv_row_and_rejects_bad_input() {
    // Sphere on plane, R = 300 mm, P = 1 kN, E* = 210000 / (2 (1 - 0.09)) MPa:
    // a = (3 P R / (4 E*))^(1/3) (Johnson 1985, Sect. 4.2).
    let o = bin()
        .args([
            "hertz",
            "--A",
            "0.0016666666666666667",
            "--B",
            "0.0016666666666666667",
            "--load",
            "1000",
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    let mut lines = text.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .starts_with("a_mm,b_mm,p0_MPa,approach_mm,e,method")
    );
    let a: f64 = lines
        .next()
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let e_star: f64 = 210_000.0 / (2.0 * (1.0 - 0.09));
    let exact = (3.0 * 1000.0 * 300.0 / (4.0 * e_star)).powf(1.0 / 3.0);
    assert!((a - exact).abs() < 1e-12 * exact, "{a} vs {exact}");

    let o = bin()
        .args(["hertz", "--A", "0.001", "--B", "0.002", "--load", "-5"])
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(!stderr(&o).contains("panicked"));
    let o = bin()
        .args([
            "hertz",
            "--A",
            "0.001",
            "--B",
            "0.002",
            "--load",
            "100",
            "--poisson",
            "0.5",
        ])
        .output()
        .unwrap();
    assert_clean_failure(&o, 2, &["oisson"]);
}

#[test]
fn profile_export_round_trips_and_rejects_unknown_names() {
    let dir = scratch("export");
    let out = dir.join("w.csv");
    let o = bin()
        .args(["profile", "s1002", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let p = wheelrail::profile::read::read_profile(&out, wheelrail::profile::ProfileKind::Wheel)
        .unwrap();
    assert!(p.points.len() > 1300);
    let o = bin()
        .args(["profile", "s1003", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert_clean_failure(&o, 2, &["s1003"]);
}

#[test]
fn conicity_command_reads_a_delta_r_table_and_rejects_bad_ones() {
    let dir = scratch("conicity");
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    // A cone of 0.15 with a comment and an extra column.
    let mut text = String::from("# a cone\ny_mm,delta_r_mm,note\n");
    for i in -60..=60 {
        let y = f64::from(i) * 0.1;
        text += &format!("{y},{},x\n", 0.3 * y);
    }
    let good = write("cone.csv", &text);
    let o = bin()
        .arg("conicity")
        .arg(&good)
        .args(["--amplitudes-mm", "1:7:2", "--method", "regression"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let rows: Vec<&str> = out.lines().filter(|l| !l.starts_with('#')).collect();
    assert!(rows[0].starts_with("amplitude_mm,tan_gamma_e,") && rows[0].ends_with("status"));
    assert_eq!(rows.len(), 5, "{out}");
    for r in &rows[1..4] {
        let t: f64 = r.split(',').nth(1).unwrap().parse().unwrap();
        assert!((t - 0.15).abs() < 1e-10 && r.ends_with(",ok"), "{r}");
    }
    assert!(
        rows[4].starts_with("7")
            && rows[4].contains("NaN")
            && rows[4].ends_with("beyond delta_r range")
    );
    // Default amplitudes: clipped to the table (0.5 to 6.0 mm).
    let o = bin().arg("conicity").arg(&good).output().unwrap();
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(
        out.lines().filter(|l| !l.starts_with('#')).count(),
        1 + 56,
        "{out}"
    );

    let cases = [
        (
            "nan.csv",
            "y_mm,delta_r_mm\n-1,-0.2\n0,NaN\n1,0.2\n",
            "nan.csv:3",
        ),
        (
            "order.csv",
            "y_mm,delta_r_mm\n-1,-0.2\n1,0.2\n0.5,0.1\n",
            "order.csv:4",
        ),
        ("short.csv", "y_mm,delta_r_mm\n-1,-0.2\n1,0.2\n", "2 points"),
        (
            "sign.csv",
            "y_mm,delta_r_mm\n-1,0.2\n0,0.3\n1,0.4\n",
            "never changes sign",
        ),
        ("header.csv", "y,dr\n-1,-0.2\n0,0\n1,0.2\n", "header.csv:1"),
        (
            "text.csv",
            "y_mm,delta_r_mm\n-1,-0.2\n0,abc\n1,0.2\n",
            "text.csv:3",
        ),
    ];
    for (name, text, expected) in cases {
        let p = write(name, text);
        let o = bin().arg("conicity").arg(&p).output().unwrap();
        assert_clean_failure(&o, 2, &[name, expected]);
        assert!(o.stdout.is_empty());
    }
    for bad in ["0:3:0.1", "1:3", "1:3:-1", "a:3:1"] {
        let o = bin()
            .arg("conicity")
            .arg(&good)
            .args(["--amplitudes-mm", bad])
            .output()
            .unwrap();
        assert_clean_failure(&o, 2, &["--amplitudes-mm"]);
    }
    let o = bin()
        .arg("conicity")
        .arg(&good)
        .args(["--method", "harmonic"])
        .output()
        .unwrap();
    assert_clean_failure(&o, 2, &["--method", "klingel"]);
}

#[test]
fn a_conicity_only_scene_runs_the_rigid_search_and_nothing_after_it() {
    let dir = scratch("conicity_only");
    let s = scene(
        &dir,
        "[outputs]\nfigures = [\"equivalent_conicity\"]\nformats = [\"svg\"]",
    );
    let err = report_timings(&s);
    for stage in ["profiles", "rigid", "equivalent_conicity"] {
        assert!(err.contains(stage), "{stage} did not run: {err}");
    }
    for stage in ["quasi_elastic", "epsilon_sensitivity", "hertz"] {
        assert!(!err.contains(stage), "{stage} ran: {err}");
    }
    for file in [
        "equivalent_conicity.svg",
        "equivalent_conicity.csv",
        "parameters.csv",
    ] {
        assert!(dir.join(file).exists(), "{file}");
    }
    assert!(!dir.join("quasi_elastic.csv").exists());
}

#[test]
fn paper_conicity_agrees_with_the_cli_on_its_rigid_table() {
    // The stage's tan γe (Δr with its jumps located to 1e-4 mm) against `wheelrail
    // conicity` on the y_ws_mm and delta_r_mm columns of rigid.csv (0.1 mm grid, jumps
    // smeared over a grid step): they differ by the table's resolution, at most 5e-3.
    let out = scratch("paper_conicity");
    let o = bin()
        .args(["report", "reports/paper/scene.toml", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let params = std::fs::read_to_string(out.join("parameters.csv")).unwrap();
    let value = |name: &str| -> f64 {
        let row = params.lines().find(|l| l.starts_with(name)).unwrap();
        row.split(',').nth(1).unwrap().parse().unwrap()
    };
    let o = bin()
        .arg("conicity")
        .arg(out.join("rigid.csv"))
        .args(["--amplitudes-mm", "2:4:1"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let cli: Vec<f64> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("amplitude"))
        .map(|l| l.split(',').nth(1).unwrap().parse().unwrap())
        .collect();
    for (i, name) in ["tan_gamma_e_2mm", "tan_gamma_e_3mm", "tan_gamma_e_4mm"]
        .into_iter()
        .enumerate()
    {
        let stage = value(name);
        assert!(
            (stage - cli[i]).abs() <= 5e-3,
            "{name}: stage {stage}, cli on rigid.csv {}",
            cli[i]
        );
        println!("{name}: stage {stage:.5}, cli on rigid.csv {:.5}", cli[i]);
    }
}

/// A report's `profile_dimensions.csv`: the wheels' Sh, Sd, qR against their limits (a
/// `[limits]` override taking the place of the TSI's and breaking S1002's Sd, which the
/// report states and exits 0 on), and with `rail.nominal_profile` the rails' wear: 60E1
/// planed flat 0.8 mm below its top (a CSV in the rail's frame), vertical wear 0.8 mm.
#[test]
fn a_report_has_the_profile_dimensions_and_the_rail_wear() {
    let dir = common::scratch("report-dimensions");
    let mut rail = String::from("y_mm,z_mm\n");
    for r in wheelrail::profile::Profile::uic60e1().sample(0.1) {
        rail.push_str(&format!("{},{}\n", r[0], r[1].min(-0.8)));
    }
    std::fs::write(dir.join("planed.csv"), rail).unwrap();
    let o = common::report_scene(
        &dir,
        "[rail]\nprofile = \"planed.csv\"\nnominal_profile = \"UIC60E1\"\n[limits]\nsd_max_mm = 32.0\n[outputs]\nfigures = [\"profiles\"]\nformats = [\"svg\"]\n",
    );
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let text = std::fs::read_to_string(dir.join("out/profile_dimensions.csv")).unwrap();
    assert!(
        text.contains("sd_max_mm = 32 (scene key limits.sd_max_mm)"),
        "{text}"
    );
    let line = |side: &str, dimension: &str| -> Vec<String> {
        text.lines()
            .find(|l| l.starts_with(&format!("{side},")) && l.contains(&format!(",{dimension},")))
            .unwrap_or_else(|| panic!("no {side} {dimension} row in {text}"))
            .split(',')
            .map(str::to_string)
            .collect()
    };
    let sd = line("left", "Sd");
    assert!(
        (sd[4].parse::<f64>().unwrap() - 32.5).abs() < 1e-4,
        "{sd:?}"
    );
    assert_eq!(sd[7], "above the maximum");
    assert_eq!(line("right", "qR")[7], "ok; no maximum limit");
    for side in ["left", "right"] {
        let v = line(side, "vertical_wear");
        assert!((v[4].parse::<f64>().unwrap() - 0.8).abs() < 1e-5, "{v:?}");
        assert_eq!(v[7], "no limit");
    }
    let page = std::fs::read_to_string(dir.join("out/index.html")).unwrap();
    assert!(page.contains("Sd 32.50 &gt; 32 mm") || page.contains("Sd 32.50 > 32 mm"));
    assert!(page.contains("vertical wear (left rail)"));
}
