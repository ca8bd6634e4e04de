//! `wheelrail fleet` with pairs files and rails: rows against single reports of the same
//! wheel and rail, a bad path in a pairs file, a rail fleet's wear against the template's rail.

mod common;

use common::fleet::{assert_row_is_report, fleet, generated, read, rows, single_report};
use common::{assert_clean_failure, bin, root, scratch, stderr};
use std::collections::HashMap;

#[test]
fn pairs_and_rails_match_single_reports_and_a_bad_path_is_a_row() {
    let dir = scratch("fleet-pairs");
    let files = generated(&dir, 2);
    let pairs = dir.join("pairs.csv");
    std::fs::write(
        &pairs,
        "# two wheelsets measured wheel by wheel\nid,left_wheel,right_wheel\nws1,worn_0000.csv,worn_0001.csv\nws2,worn_0001.csv,missing.csv\n",
    )
    .unwrap();
    let scene = root().join("reports/fleet/scene.toml");
    let out = dir.join("out");
    let o = bin()
        .arg("fleet")
        .arg(&scene)
        .arg("--pairs")
        .arg(&pairs)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_clean_failure(&o, 3, &[]);
    let got = rows(&read(&out.join("fleet.csv")));
    assert_eq!(got.len(), 2);
    assert_eq!(got[0]["status"], "ok");
    assert!(
        got[1]["status"].contains("missing.csv"),
        "{}",
        got[1]["status"]
    );
    assert!(got[1]["right_wheel_sha256"].is_empty());
    // Each wheel's flange dimensions: the generated wheels are within the limits.
    for c in [
        "left_sh_mm",
        "left_sd_mm",
        "left_qr_mm",
        "right_sh_mm",
        "right_sd_mm",
        "right_qr_mm",
    ] {
        let v: f64 = got[0][c].parse().unwrap();
        assert!((5.0..40.0).contains(&v), "{c} = {v}");
    }
    assert_eq!(got[0]["maintenance_status"], "ok");
    assert_eq!(got[1]["left_sd_mm"], "NaN");
    // ws1 against a report with the two wheels.
    let base = read(&scene);
    let template = base.replace(
        "profile = \"S1002\"",
        &format!(
            "left_profile = \"{}\"\nright_profile = \"{}\"",
            files[0].display(),
            files[1].display()
        ),
    );
    let report = single_report(&dir, "single-ws1", &template);
    assert_row_is_report(&got[0], &report);
    // Asymmetric wheels give an asymmetric pair.
    assert_ne!(
        got[0]["flange_contact_left_y_mm"].trim_start_matches('-'),
        got[0]["flange_contact_right_y_mm"].trim_start_matches('-')
    );

    // --rail: a measured rail under the template's S1002 wheels, against a report.
    let rail = root().join("tests/data/profiles/MBench_UIC60_v3.ban");
    let rail_scene = dir.join("rail.toml");
    let rail_template = base.replace(
        "inclination = \"1:40\"",
        "inclination = \"1:40\"\nprofile_inclination = \"1:40\"",
    );
    std::fs::write(&rail_scene, &rail_template).unwrap();
    let out = dir.join("rails");
    let o = fleet(&rail_scene, &[&rail], &out, &["--rail"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let got = rows(&read(&out.join("fleet.csv")));
    assert_eq!(got[0]["rail_file"], rail.display().to_string());
    let report = single_report(
        &dir,
        "single-rail",
        &rail_template.replace(
            "profile = \"UIC60E1\"",
            &format!("profile = \"{}\"", rail.display()),
        ),
    );
    assert_row_is_report(&got[0], &report);

    // A pairs file with rail columns: both wheels and both rails replaced.
    let pairs = dir.join("pairs_rails.csv");
    std::fs::write(
        &pairs,
        format!(
            "id,left_wheel,right_wheel,left_rail,right_rail\nws1,worn_0000.csv,worn_0001.csv,{0},{0}\n",
            rail.display()
        ),
    )
    .unwrap();
    let out = dir.join("pairs-rails");
    let o = bin()
        .arg("fleet")
        .arg(&rail_scene)
        .arg("--pairs")
        .arg(&pairs)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let got = rows(&read(&out.join("fleet.csv")));
    assert_eq!(got[0]["left_rail_file"], rail.display().to_string());
    let report = single_report(
        &dir,
        "single-ws1-rails",
        &template
            .replace(
                "inclination = \"1:40\"",
                "inclination = \"1:40\"\nprofile_inclination = \"1:40\"",
            )
            .replace(
                "profile = \"UIC60E1\"",
                &format!("profile = \"{}\"", rail.display()),
            ),
    );
    assert_row_is_report(&got[0], &report);
}

/// `fleet --rail`: each rail's wear against the template's rail (60E1): the nominal head
/// sampled every 0.1 mm (no wear), and the same planed flat 1.2 mm below its top (vertical
/// wear 1.2 mm; the gauge face at 14 mm depth untouched). On the crown the spline through
/// the samples is the head within 1e-6 mm; the gauge point lies 0.3 mm above the joint of
/// the R13 arc and the 1:20 flank, where the spline through samples 0.1 mm apart in `y` on
/// a face this steep errs by about 1e-3 mm in `y` (measured 1.06e-3): 2e-3 mm allowed there. The rows
/// carry no flange dimensions (the wheels are the template's), and a rail's wear is a
/// result: exit 0.
#[test]
fn a_rail_fleet_reports_the_wear_against_the_template_rail() {
    let dir = scratch("fleet-rail-wear");
    let nominal = wheelrail::profile::Profile::uic60e1();
    let write = |name: &str, planed_mm: f64| {
        let mut text =
            String::from("# 60E1 upright, origin on the top of the rail axis\ny_mm,z_mm\n");
        for r in nominal.sample(0.1) {
            text.push_str(&format!("{},{}\n", r[0], r[1].min(-planed_mm)));
        }
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path
    };
    let new = write("new.csv", 0.0);
    let planed = write("planed.csv", 1.2);
    let out = dir.join("out");
    let scene = root().join("reports/fleet/scene.toml");
    let o = fleet(&scene, &[&new, &planed], &out, &["--rail"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = read(&out.join("fleet.csv"));
    assert!(
        text.contains("# vertical_wear_mm, gauge_face_wear_mm"),
        "{text}"
    );
    let got = rows(&text);
    let value = |r: &HashMap<String, String>, c: &str| -> f64 { r[c].parse().unwrap() };
    assert!(!got[0].contains_key("sh_mm") && !got[0].contains_key("maintenance_status"));
    for (row, vertical) in got.iter().zip([0.0, 1.2]) {
        assert_eq!(row["status"], "ok");
        assert!(
            (value(row, "vertical_wear_mm") - vertical).abs() < 1e-5,
            "{row:?}"
        );
        assert!(value(row, "gauge_face_wear_mm").abs() < 2e-3, "{row:?}");
    }
}
