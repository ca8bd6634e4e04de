//! The content of `index.html`: what ran and what to watch (summary, notes), the scene's
//! parameters, the provenance of its profiles, the pair's key results.

use super::capitalised;
use super::{figures, tables};
use crate::{FigureEntry, ReportPage, TableEntry};
use wheelrail::pipeline::Results;
use wheelrail::profile::Profile;
use wheelrail::profile::read::sha256_hex;
use wheelrail::rigid::JumpKind;
use wheelrail::scene::Scene;

/// The report page of a scene's run, listing `figures` and `tables` (each table's file name
/// and description).
pub(super) fn report_page(
    scene: &Scene,
    results: &Results,
    tables: &[(String, String)],
    figures: Vec<FigureEntry>,
) -> ReportPage {
    let (summary, notes) = summary_and_notes(scene, results);
    ReportPage {
        title: scene.title().to_string(),
        key_results: [maintenance_results(results), key_results(results)].concat(),
        summary,
        parameters: parameters(scene),
        provenance: provenance(results),
        figures,
        tables: tables
            .iter()
            .map(|(file, description)| TableEntry {
                name: file.trim_end_matches(".csv").to_string(),
                file: file.clone(),
                description: description.clone(),
            })
            .collect(),
        data_tables: Vec::new(),
        notes,
    }
}

/// The summary (stages run, how the searches went) and the notes (what did not converge or
/// is flagged) of the page.
fn summary_and_notes(scene: &Scene, results: &Results) -> (Vec<String>, Vec<String>) {
    // The stages, not their times: the page is reproducible (`--timings` prints the times).
    let mut summary = vec![format!(
        "Stages run: {}.",
        results
            .record
            .stages
            .iter()
            .map(|(s, _)| s.name())
            .collect::<Vec<_>>()
            .join(", ")
    )];
    let mut notes = Vec::new();
    if let Some(r) = &results.rigid {
        let bad: Vec<String> = r
            .positions()
            .iter()
            .filter(|p| p.stop != wheelrail::rigid::Stop::Converged)
            .map(|p| format!("{} mm ({})", p.y_ws, p.stop.status_text()))
            .collect();
        let count = |kind: JumpKind| r.jumps().iter().filter(|j| j.kind == kind).count();
        let artefacts = count(JumpKind::Artefact);
        if bad.is_empty() {
            summary.push(format!(
                "Rigid search ({} solver): all {} positions converged; {} contact-point jumps{}.",
                r.solver().name(),
                r.positions().len(),
                count(JumpKind::Jump),
                if artefacts > 0 {
                    format!(" and {artefacts} sampling artefacts (drawn as continuous lines)")
                } else {
                    String::new()
                }
            ));
        } else {
            notes.push(format!(
                "Rigid positions not converged (left out of the figures): {}.",
                bad.join(", ")
            ));
        }
        for (y, label) in figures::flange_onsets(r) {
            // The onset is interpolated between sweep positions or is a jump's bracket: to
            // a hundredth of a millimetre, as the key results give shifts elsewhere.
            summary.push(format!("{} from y_ws = {y:.2} mm.", capitalised(label)));
        }
        if artefacts >= MANY_ARTEFACTS {
            notes.push(smoothing_hint(artefacts, scene.smoothing_wavelength_mm()));
        }
    }
    if let Some(h) = &results.hertz {
        let flagged = h
            .positions()
            .iter()
            .flat_map(|p| p.sides.iter())
            .filter(|s| s.status != "ok")
            .count();
        if flagged > 0 {
            notes.push(format!("{flagged} wheel contacts carry a Hertz status other than ok (see the status columns of hertz.csv)."));
        }
        summary.push(format!(
            "Hertz: {} method, {} contact, normal load {}.",
            scene.hertz().method(),
            scene.hertz_contact().name(),
            scene.hertz().normal_load().name()
        ));
    }
    (summary, notes)
}

/// From this many sampling artefacts on, the page suggests a filter on the profiles.
const MANY_ARTEFACTS: usize = 10;

/// The note of a sweep with `count` sampling artefacts, on profiles filtered with the
/// wavelengths `smoothing` (mm, wheel and rail; 0 for none).
fn smoothing_hint(count: usize, smoothing: [f64; 2]) -> String {
    let filter = if smoothing.iter().all(|&w| w > 0.0) {
        format!(
            "a longer filter than the scene's (`smoothing_wavelength_mm` = {} mm for the wheel, {} mm for the rail)",
            smoothing[0], smoothing[1]
        )
    } else {
        format!(
            "a filter on the profiles, `smoothing_wavelength_mm` under [wheel] and [rail] (it removes the waves shorter than about that length; {} mm is a good start)",
            wheelrail::profile::spline::DEFAULT_FILTER_WAVELENGTH_MM
        )
    };
    format!(
        "{count} sampling artefacts: the contact point of a sampled profile hops between undulations of its data that a hollow of the gap shallower than {} mm separates (rigid_jumps.csv, kind artefact). They are drawn as continuous lines and left out of the jumps; to remove them, {filter}.",
        wheelrail::rigid::ARTEFACT_HOLLOW_MM
    )
}

/// The scene's keys shown on the page, as `(name, value)`.
fn parameters(scene: &Scene) -> Vec<(String, String)> {
    let l = &scene.layout();
    vec![
        ("scene".into(), scene.path().to_string()),
        ("gauge_mm".into(), l.gauge_mm().to_string()),
        (
            "gauge_point_depth_mm".into(),
            l.gauge_point_depth_mm().to_string(),
        ),
        (
            "rail inclination (rad)".into(),
            format!("{:.7}", l.inclination().radians()),
        ),
        ("flange_back_mm".into(), l.flange_back_mm().to_string()),
        (
            "nominal_radius_mm (left, right)".into(),
            format!(
                "{}, {}",
                scene.nominal_radius_mm()[0],
                scene.nominal_radius_mm()[1]
            ),
        ),
        (
            "wheel_load_kN".into(),
            (scene.wheel_load_n() / 1000.0).to_string(),
        ),
        (
            "E (GPa) and nu, wheel".into(),
            format!(
                "{}, {}",
                scene.wheel_material().young_mpa() / 1000.0,
                scene.wheel_material().poisson()
            ),
        ),
        (
            "E (GPa) and nu, rail".into(),
            format!(
                "{}, {}",
                scene.rail_material().young_mpa() / 1000.0,
                scene.rail_material().poisson()
            ),
        ),
        (
            "sweep (mm)".into(),
            format!(
                "{} to {}, {} positions",
                scene
                    .sweep()
                    .shifts_mm()
                    .first()
                    .copied()
                    .unwrap_or(f64::NAN),
                scene
                    .sweep()
                    .shifts_mm()
                    .last()
                    .copied()
                    .unwrap_or(f64::NAN),
                scene.sweep().len()
            ),
        ),
        ("rigid solver".into(), scene.rigid_solver().name().into()),
        (
            "quasi-elastic eps (mm)".into(),
            scene.quasi_elastic().epsilon_mm().to_string(),
        ),
    ]
}

/// The program's version and where each profile came from, with the sha256 of its file (or
/// of the sampled table of a built-in profile), once, as `(name, value)`. File paths are
/// written without `.` and `..` segments (`reports/x/../../tests/a.csv` is
/// `tests/a.csv`).
fn provenance(results: &Results) -> Vec<(String, String)> {
    let p = &results.placement;
    let profile_row = |label: &str, profile: &Profile| -> (String, String) {
        let value = match profile.source() {
            wheelrail::profile::Source::File { path, sha256 } => {
                format!("{} — sha256 {sha256}", lexically_normal(path))
            }
            wheelrail::profile::Source::Definition(definition) => {
                // Built-in: the hash of its sampled table, which changes with the definition.
                let rows = profile.sample(tables::PROFILE_TABLE_STEP_MM);
                let text: String = rows
                    .iter()
                    .map(|r| format!("{:.12e},{:.12e}\n", r[0], r[1]))
                    .collect();
                format!(
                    "{definition} — sha256 {} (of the sampled profile)",
                    sha256_hex(text.as_bytes())
                )
            }
        };
        (label.to_string(), value)
    };
    vec![
        (
            "wheelrail".into(),
            format!("version {}", env!("CARGO_PKG_VERSION")),
        ),
        profile_row("left wheel", p.left().wheel().profile()),
        profile_row("right wheel", p.right().wheel().profile()),
        profile_row("left rail", p.left().rail().profile()),
        profile_row("right rail", p.right().rail().profile()),
        (
            "conventions".into(),
            "mm, N, MPa, rad; track frame y left, z up; see every CSV header".into(),
        ),
    ]
}

/// `path` with its `.` segments dropped and each `..` taking away the folder before it
/// (where there is one to take: a leading `..` stays), as text with `/`. Lexical only: for
/// display, where the path's folders are those of the checkout.
fn lexically_normal(path: &str) -> String {
    use std::path::Component;
    let mut parts: Vec<String> = Vec::new();
    for c in std::path::Path::new(path).components() {
        match c {
            Component::CurDir => {}
            // Above the root is the root.
            Component::ParentDir if parts.last().is_some_and(String::is_empty) => {}
            Component::ParentDir if parts.last().is_some_and(|l| l != "..") => {
                parts.pop();
            }
            Component::RootDir => parts.push(String::new()),
            c => parts.push(c.as_os_str().to_string_lossy().into_owned()),
        }
    }
    if parts == [String::new()] {
        return "/".into();
    }
    parts.join("/")
}

/// The pair's parameters (from the conicity stage) as rows `[name, value, unit, definition]`;
/// none when that stage did not run.
fn key_results(results: &Results) -> Vec<[String; 4]> {
    results.conicity.as_ref().map_or_else(Vec::new, |c| {
        c.parameters
            .rows()
            .into_iter()
            .map(|r| {
                let value = if r.value.is_nan() {
                    "—".to_string()
                } else if r.unit == "count" {
                    format!("{}", r.value)
                } else {
                    format!("{:.4}", r.value)
                };
                [r.name.to_string(), value, r.unit.to_string(), r.definition]
            })
            .collect()
    })
}

/// The wheels' flange dimensions with their limits and the rails' wear, as key-result rows
/// `[name, value, unit, definition]`: once for a wheelset of equal wheels, per wheel
/// otherwise.
fn maintenance_results(results: &Results) -> Vec<[String; 4]> {
    let m = &results.maintenance;
    let p = &results.placement;
    let equal = m.wheels[0] == m.wheels[1];
    let mut rows = Vec::new();
    for (k, side) in ["left", "right"].into_iter().enumerate() {
        if equal && k == 1 {
            break;
        }
        let whose = if equal {
            "both wheels".to_string()
        } else {
            format!("{side} wheel")
        };
        let wheel = if k == 0 {
            &p.left().wheel()
        } else {
            &p.right().wheel()
        };
        rows.extend(wheel_rows(&m.wheels[k], &whose, wheel.profile().name()));
    }
    if let Some(rails) = &m.rails {
        for (k, side) in ["left", "right"].into_iter().enumerate() {
            let (vertical, face) = match &rails[k] {
                Ok(w) => (three_places(w.vertical_mm), three_places(w.gauge_face_mm)),
                Err(e) => (format!("— ({e})"), "—".into()),
            };
            rows.push([
                format!("vertical wear ({side} rail)"),
                vertical,
                "mm".into(),
                tables::RAIL_WEAR_TEXT.into(),
            ]);
            rows.push([
                format!("gauge-face wear ({side} rail)"),
                face,
                "mm".into(),
                "see vertical wear".into(),
            ]);
        }
    }
    rows
}

/// A length in mm to three decimals.
fn three_places(v: f64) -> String {
    format!("{v:.3}")
}

/// The key-result rows of one wheel's flange dimensions (`whose`: which wheels they are,
/// `profile` its name) and its limits' status.
fn wheel_rows(
    w: &wheelrail::maintenance::WheelAssessment,
    whose: &str,
    profile: &str,
) -> Vec<[String; 4]> {
    let l = &w.limits;
    let defined = w.dimensions.as_ref().ok();
    let mut rows: Vec<[String; 4]> = [
        (
            "Sh",
            defined.map(|d| d.sh_mm),
            format!(
                "flange height: the tip above the taping-line point; limits {} to {} mm",
                l.sh_min.value_mm, l.sh_max.value_mm
            ),
        ),
        (
            "Sd",
            defined.map(|d| d.sd_mm),
            format!(
                "flange thickness: inner face to the flank 10 mm above the taping-line point; limits {} to {} mm",
                l.sd_min.value_mm, l.sd_max.value_mm
            ),
        ),
        (
            "qR",
            defined.map(|d| d.qr_mm),
            format!(
                "Sd point to the flank 2 mm below the tip; at least {} mm",
                l.qr_min.value_mm
            ),
        ),
    ]
    .into_iter()
    .map(|(name, value, definition)| {
        [
            format!("{name} ({whose}, {profile})"),
            value.map_or("—".into(), three_places),
            "mm".into(),
            definition,
        ]
    })
    .collect();
    rows.push([
        format!("maintenance limits ({whose})"),
        w.status(),
        String::new(),
        format!(
            "{} (sources: profile_dimensions.csv)",
            tables::FLANGE_DIMENSIONS_TEXT
        ),
    ]);
    rows
}

#[cfg(test)]
mod tests {
    use super::lexically_normal;

    #[test]
    fn paths_lose_their_dot_segments() {
        for (path, normal) in [
            (
                "reports/en15302_e1/../../tests/data/en15302/R-UIC519A.csv",
                "tests/data/en15302/R-UIC519A.csv",
            ),
            ("./a/./b.csv", "a/b.csv"),
            ("../a/../../b.csv", "../../b.csv"),
            ("/x/../y.csv", "/y.csv"),
            ("/../y.csv", "/y.csv"),
        ] {
            assert_eq!(lexically_normal(path), normal, "{path}");
        }
    }
}
