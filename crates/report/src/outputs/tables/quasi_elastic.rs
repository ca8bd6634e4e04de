//! The quasi-elastic sweep's tables: `quasi_elastic.csv` and the eps sensitivity
//! `qe_epsilon.csv`.

use super::rigid::{RailSlopeColumn, contact_columns, converged};
use super::{PER_WHEEL, TRACK_FRAME, yaw_comment};
use crate::{Table, TableBuilder, TableError};
use wheelrail::gap::ContactPoint;
use wheelrail::pipeline::EpsilonSweeps;
use wheelrail::quasi_elastic::QuasiElasticSweep;
use wheelrail::rigid::{RigidSweep, Stop};
use wheelrail::track::Side;

/// Quasi-elastic contact over the sweep (`quasi_elastic.csv`): the heaviest patch per
/// wheel, and the second one where present.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn quasi_elastic(q: &QuasiElasticSweep) -> Result<Table, TableError> {
    let mut t = Table::builder()
        .comment(format!(
            "quasi-elastic contact: weights exp(-(d - d_min)/eps), eps = {} mm, cut-off {} eps, quadrature {}",
            q.settings().epsilon_mm(),
            q.settings().cutoff(),
            q.settings().quadrature().name()
        ))
        .comment(TRACK_FRAME)
        .comment(PER_WHEEL)
        .comment("the heaviest patch (local minimum of the gap) per wheel; second_* the next heaviest (NaN if none); weight_share its share of the wheel's total weight");
    let yaw = q.rigid().yaw();
    if yaw.is_yawed() {
        t = t.comment(yaw_comment(yaw));
    }
    t = t.numeric(
        "y_ws_mm",
        q.positions().iter().map(|p| p.y_ws).collect::<Vec<_>>(),
    );
    if yaw.is_yawed() {
        let yaws = q
            .rigid()
            .positions()
            .iter()
            .map(|p| p.yaw)
            .collect::<Vec<_>>();
        t = t.numeric("yaw_rad", yaws);
    }
    for side in [Side::Left, Side::Right] {
        t = quasi_elastic_side_columns(t, q, side, yaw.is_yawed());
    }
    let r = |p: &wheelrail::quasi_elastic::QuasiElasticPosition, k: usize| {
        p.sides[k].main().map_or(f64::NAN, |c| c.r)
    };
    t.numeric(
        "delta_r_mm",
        q.positions()
            .iter()
            .map(|p| r(p, 0) - r(p, 1))
            .collect::<Vec<_>>(),
    )
    .text("status", q.positions().iter().map(quasi_elastic_status))
    .build()
}

/// The columns of one wheel in `quasi_elastic.csv`: the contact point of its heaviest
/// patch, that patch's weight share, the number of patches and the second patch.
fn quasi_elastic_side_columns(
    t: TableBuilder,
    q: &QuasiElasticSweep,
    side: Side,
    yawed: bool,
) -> TableBuilder {
    let name = side.name();
    let main = |f: &dyn Fn(&wheelrail::quasi_elastic::Patch) -> f64| -> Vec<f64> {
        q.positions()
            .iter()
            .map(|p| p.side(side).main().map_or(f64::NAN, f))
            .collect()
    };
    let second = |f: &dyn Fn(&wheelrail::quasi_elastic::Patch) -> f64| -> Vec<f64> {
        q.positions()
            .iter()
            .map(|p| p.side(side).second().map_or(f64::NAN, f))
            .collect()
    };
    let points: Vec<ContactPoint> = q
        .positions()
        .iter()
        .map(|p| p.side(side).main().map_or(ContactPoint::NAN, |c| c.point()))
        .collect();
    contact_columns(t, side, &points, RailSlopeColumn::Omitted, yawed)
        .numeric(format!("{name}_weight_share"), main(&|c| c.weight_share))
        .numeric(
            format!("{name}_patches"),
            q.positions()
                .iter()
                .map(|p| p.side(side).patches.len() as f64)
                .collect::<Vec<_>>(),
        )
        .numeric(format!("{name}_second_s_mm"), second(&|c| c.s))
        .numeric(
            format!("{name}_second_weight_share"),
            second(&|c| c.weight_share),
        )
}

/// The `status` of one position in `quasi_elastic.csv`: the rigid search's stop where it
/// did not converge, the wheels without a patch, or whether a wheel has two patches.
fn quasi_elastic_status(p: &wheelrail::quasi_elastic::QuasiElasticPosition) -> String {
    let missing: Vec<&str> = [Side::Left, Side::Right]
        .into_iter()
        .filter(|&side| p.side(side).main().is_none_or(|c| !c.is_finite()))
        .map(Side::name)
        .collect();
    if p.rigid_stop != Stop::Converged {
        format!("rigid search: {}", p.rigid_stop.status_text())
    } else if !missing.is_empty() {
        format!(
            "no patch: {} (wheel not above its rail)",
            missing.join(", ")
        )
    } else if p.sides.iter().any(|s| s.patches.len() > 1) {
        "ok; two patches".to_string()
    } else {
        "ok".to_string()
    }
}

/// The quasi-elastic contact location for each sensitivity eps (`qe_epsilon.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn epsilon_sensitivity(rigid: &RigidSweep, e: &EpsilonSweeps) -> Result<Table, TableError> {
    let mut t = Table::builder()
        .comment("quasi-elastic contact location (heaviest patch) against eps; rigid for reference; status: ok, the rigid search's stop where it did not converge, or the sides and eps without a patch (NaN there)")
        .comment(PER_WHEEL)
        .numeric(
            "y_ws_mm",
            rigid.positions().iter().map(|p| p.y_ws).collect::<Vec<_>>(),
        );
    for (k, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        t = t.numeric(
            format!("{}_rigid_s_mm", side.name()),
            converged(rigid, |p| p.contact[k].map_or(f64::NAN, |c| c.s)),
        );
        for (eps, q) in &e.runs {
            t = t.numeric(
                format!("{}_s_mm_eps_{eps}_mm", side.name()),
                q.positions()
                    .iter()
                    .map(|p| p.sides[k].main().map_or(f64::NAN, |c| c.s))
                    .collect::<Vec<_>>(),
            );
        }
    }
    let status = rigid.positions().iter().enumerate().map(|(i, p)| {
        if p.stop != Stop::Converged {
            return format!("rigid search: {}", p.stop.status_text());
        }
        let missing: Vec<String> = e
            .runs
            .iter()
            .flat_map(|(eps, q)| {
                [Side::Left, Side::Right]
                    .into_iter()
                    .enumerate()
                    .filter(move |&(k, _)| {
                        q.positions()[i].sides[k]
                            .main()
                            .is_none_or(|c| !c.s.is_finite())
                    })
                    .map(move |(_, side)| format!("{} at eps {eps} mm", side.name()))
            })
            .collect();
        if missing.is_empty() {
            "ok".to_string()
        } else {
            format!("no patch: {}", missing.join(", "))
        }
    });
    t.text("status", status).build()
}
