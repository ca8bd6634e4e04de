//! Stage results as CSV tables. Every table states its frame, signs and units in `#`
//! comment lines above the header, and every column name carries its unit.

use crate::{Table, TableBuilder, TableError};
use wheelrail::conicity::ParameterRow;
use wheelrail::gap::ContactPoint;
use wheelrail::hertz::accuracy::HertzAccuracy;
use wheelrail::pipeline::EpsilonSweeps;
use wheelrail::quasi_elastic::QuasiElasticSweep;
use wheelrail::rigid::{ARTEFACT_HOLLOW_MM, JUMP_REFINE_MM, JumpKind, RigidSweep, Stop};
use wheelrail::track::{PlacedRail, PlacedWheel, Side};

/// Sampling step of the profile tables (mm).
pub const PROFILE_TABLE_STEP_MM: f64 = 0.1;

pub(super) const TRACK_FRAME: &str = "frame: track, x forward, y lateral positive to the left, z up, origin on the track centre line at the top of the rails; roll positive lifts the left wheel";
pub(super) const PER_WHEEL: &str = "per wheel: s_mm wheel coordinate from the taping line, positive towards the field side (flange at s < 0); gamma contact angle in the track frame with roll, mirrored per side, positive on tread and flange; curvatures convex positive";

/// What the yaw columns of a yawed sweep mean.
const YAW_COLUMNS: &str = "yaw_rad right-hand about z (up): positive turns the wheelset's forward axis to the left (the left wheel back, the right forward); per wheel: x_mm the contact's position along the track (x forward) from the wheelset centre, lead_mm its distance ahead of the axle along the wheelset's own forward axis; with yaw the rail meets the wheel's outline seen along the track (its points whose normal has no x component), not its profile";

/// The yaw comment of a sweep yawed by `yaw`: the rule and the outline's model.
fn yaw_comment(yaw: &wheelrail::sweep::YawRule) -> String {
    format!(
        "{YAW_COLUMNS}; yaw = {} mrad + {} mrad/mm * y_ws, outline {}",
        wheelrail::message::Number(yaw.yaw_rad() * 1e3),
        wheelrail::message::Number(yaw.yaw_rad_per_mm() * 1e3),
        yaw.model().name()
    )
}

/// The wheel's side frame as the profile tables state it.
const WHEEL_SIDE_FRAME: &str = "s_mm from the taping line, positive towards the field side (flange at s < 0); F_mm radius increase over the nominal radius, positive towards the flange tip";

/// Steepest `|tan_gamma|` a profile table writes as a number. Steeper is a vertical tangent:
/// the profiles evaluate it with a capped root (the S1002 flange back gives `1e6`, see
/// `profile::s1002`), and a finite stand-in for an infinite slope would read as data. No
/// profile face that is not vertical is this steep (89.9994°).
pub const VERTICAL_TAN_GAMMA: f64 = 1e5;

/// The wheel profile: `s_mm, F_mm, tan_gamma, curvature_per_mm, face`.
///
/// Where the profile's tangent is vertical (`|tan_gamma|` beyond [`VERTICAL_TAN_GAMMA`], the
/// flange back of S1002) `tan_gamma` is `NaN` and `face` says `vertical`; elsewhere `face` is
/// `regular`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn wheel_profile(wheel: &PlacedWheel) -> Result<Table, TableError> {
    let rows = wheel.profile().sample(PROFILE_TABLE_STEP_MM);
    let (tan_gamma, face) = slope_and_face(&rows);
    Table::builder()
        .comment(format!("wheel profile {} ({})", wheel.profile().name(), wheel.profile().source()))
        .comment(format!("frame: wheel side frame; {WHEEL_SIDE_FRAME}"))
        .comment("tan_gamma = -dF/ds (positive on the coned tread); curvature_per_mm convex positive; section joints included as extra rows")
        .comment(face_comment())
        .numeric("s_mm", col(&rows, 0))
        .numeric("F_mm", col(&rows, 1))
        .numeric("tan_gamma", tan_gamma)
        .numeric("curvature_per_mm", col(&rows, 3))
        .text("face", face)
        .build()
}

/// The `tan_gamma` and `face` columns of profile samples `[u, v, tan_gamma, curvature]`:
/// `NaN` and `vertical` where the tangent is vertical (see [`VERTICAL_TAN_GAMMA`]), the slope
/// and `regular` elsewhere.
fn slope_and_face(rows: &[[f64; 4]]) -> (Vec<f64>, Vec<&'static str>) {
    rows.iter()
        .map(|r| {
            if r[2].abs() > VERTICAL_TAN_GAMMA {
                (f64::NAN, "vertical")
            } else {
                (r[2], "regular")
            }
        })
        .unzip()
}

/// The `#` header line that explains the `face` column of [`slope_and_face`].
fn face_comment() -> String {
    format!(
        "face: vertical where the tangent is vertical (|tan_gamma| > {VERTICAL_TAN_GAMMA:e}, \
         infinite): tan_gamma NaN there; regular elsewhere"
    )
}

/// The placed rail in its side frame: `u_mm, y_mm, z_mm, tan_gamma, curvature_per_mm, face`.
///
/// `face` is `running` on the running surface (the lateral range of the contact search's
/// `Z(Y)` table) and `flank` beyond it, where `tan_gamma` and `curvature_per_mm` are `NaN`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn rail_profile(rail: &PlacedRail, side: Side) -> Result<Table, TableError> {
    // The rail's own profile is not evaluated: only where it is sampled.
    let us = rail.profile().sample_positions(PROFILE_TABLE_STEP_MM);
    let mut y = Vec::with_capacity(us.len());
    let mut z = Vec::with_capacity(us.len());
    let mut slope = Vec::with_capacity(us.len());
    let mut curvature = Vec::with_capacity(us.len());
    let mut face = Vec::with_capacity(us.len());
    let (y_lo, y_hi) = rail.y_range();
    for (y_side, q) in rail.surface_along(&us) {
        y.push(y_side);
        z.push(q.z);
        // Only the running surface has a slope that Z(Y) can carry; the flanks beyond it
        // are drawn but not used by the contact search.
        if (y_lo..=y_hi).contains(&y_side) {
            slope.push(q.slope);
            curvature.push(q.curvature());
            face.push("running");
        } else {
            slope.push(f64::NAN);
            curvature.push(f64::NAN);
            face.push("flank");
        }
    }
    Table::builder()
        .comment(format!("rail profile {} ({}), {} rail as placed", rail.profile().name(), rail.profile().source(), side.name()))
        .comment("frame: rail side frame = track frame mirrored per side; y_mm = |y| from the track centre (positive towards the field side), z_mm up from the top of rail; u_mm the profile's own lateral coordinate")
        .comment("tan_gamma = dz/dy in the side frame (inclination included); curvature_per_mm convex positive; NaN where the surface is steeper than the running surface")
        .comment("face: running on the running surface; flank beyond it (tan_gamma and curvature_per_mm NaN)")
        .numeric("u_mm", us)
        .numeric("y_mm", y)
        .numeric("z_mm", z)
        .numeric("tan_gamma", slope)
        .numeric("curvature_per_mm", curvature)
        .text("face", face)
        .build()
}

fn col(rows: &[[f64; 4]], k: usize) -> Vec<f64> {
    rows.iter().map(|r| r[k]).collect()
}

/// The status of a converged position of a sweep whose centred wheelset has no contact.
const NO_CENTRED_CONTACT: &str = "; no contact at y_ws = 0: z_ws, epsilon, sigma undefined";

/// Rigid contact over the sweep (`rigid.csv`).
///
/// Wickens' parameters (Fundamentals of Rail Vehicle Dynamics, 2003), with `l0` half the
/// lateral distance between the contact points of the centred wheelset: equivalent
/// conicity `lambda = delta_r / (2 y_ws)`, contact angle parameter
/// `epsilon = l0 (tan gamma_l - tan gamma_r) / (2 y_ws)`, roll angle parameter
/// `sigma = l0 roll / y_ws`; undefined (NaN) at `y_ws = 0`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn rigid(sweep: &RigidSweep) -> Result<Table, TableError> {
    let l0 = sweep.l0_mm();
    // Without a contact on both wheels of the centred wheelset (very unequal radii, say)
    // z_ws and l0 have no reference: their columns are NaN and the status says so.
    let centred_reference = l0.is_finite() && sweep.centre().axle_height.is_finite();
    let mut t = Table::builder()
        .comment(format!("rigid contact, solver {}", sweep.solver().name()))
        .comment(TRACK_FRAME)
        .comment(PER_WHEEL)
        .comment("z_ws_mm relative to the centred wheelset; r_mm rolling radius; second_s_mm a second contact point within 0.01 mm of touching (NaN if none); jump_after 1 where the contact point jumps before the next position, 2 where it hops across a sampling artefact (see rigid_jumps.csv)")
        .comment(format!("Wickens: lambda = delta_r/(2 y_ws), epsilon = l0 (tan gamma_l - tan gamma_r)/(2 y_ws), sigma = l0 roll/y_ws, l0 = {l0:.6} mm; NaN at y_ws = 0"));
    let yawed = sweep.yaw().is_yawed();
    if yawed {
        t = t.comment(yaw_comment(sweep.yaw()));
    }
    t = t.numeric(
        "y_ws_mm",
        sweep.positions().iter().map(|p| p.y_ws).collect::<Vec<_>>(),
    );
    if yawed {
        t = t.numeric(
            "yaw_rad",
            sweep.positions().iter().map(|p| p.yaw).collect::<Vec<_>>(),
        );
    }
    t = t
        .numeric("roll_rad", converged(sweep, |p| p.roll))
        .numeric("z_ws_mm", converged(sweep, |p| sweep.z_ws(p)));
    for side in [Side::Left, Side::Right] {
        t = rigid_side_columns(t, sweep, side);
    }
    let positions = &sweep.positions();
    let wickens: Vec<_> = positions.iter().map(|p| sweep.wickens(p)).collect();
    let column = |f: &dyn Fn(&wheelrail::rigid::RigidPosition) -> f64| -> Vec<f64> {
        positions.iter().map(f).collect()
    };
    t.numeric("delta_r_mm", column(&|p| p.delta_r()))
        .numeric(
            "lambda",
            wickens.iter().map(|w| w.lambda).collect::<Vec<_>>(),
        )
        .numeric(
            "epsilon",
            wickens.iter().map(|w| w.epsilon).collect::<Vec<_>>(),
        )
        .numeric("sigma", wickens.iter().map(|w| w.sigma).collect::<Vec<_>>())
        .numeric("iterations", column(&|p| p.iterations as f64))
        .numeric("residual_mm", column(&|p| p.residual))
        .text(
            "status",
            positions.iter().map(|p| rigid_status(p, centred_reference)),
        )
        .build()
}

/// The columns of one wheel in `rigid.csv`: its contact point (with the rail's contact
/// angle), the second contact point and the jump flag.
fn rigid_side_columns(t: TableBuilder, sweep: &RigidSweep, side: Side) -> TableBuilder {
    let name = side.name();
    let contact = |p: &wheelrail::rigid::RigidPosition| match p.side(side) {
        Some(c) if p.stop == Stop::Converged => Some(*c),
        _ => None,
    };
    let points: Vec<ContactPoint> = sweep
        .positions()
        .iter()
        .map(|p| contact(p).map_or(ContactPoint::NAN, |c| c.point()))
        .collect();
    let jump_after = (0..sweep.positions().len()).map(|i| {
        let y0 = sweep.positions()[i].y_ws;
        let y1 = sweep
            .positions()
            .get(i + 1)
            .map_or(f64::INFINITY, |p| p.y_ws);
        // 1 for a jump, 2 for a sampling artefact (a jump wins where a step holds both).
        let within = |kind: JumpKind| {
            sweep
                .jumps()
                .iter()
                .any(|j| j.side == side && j.kind == kind && j.y_from >= y0 && j.y_to <= y1)
        };
        if within(JumpKind::Jump) {
            1.0
        } else if within(JumpKind::Artefact) {
            2.0
        } else {
            0.0
        }
    });
    contact_columns(
        t,
        side,
        &points,
        RailSlopeColumn::Written,
        sweep.yaw().is_yawed(),
    )
    .numeric(
        format!("{name}_second_s_mm"),
        sweep
            .positions()
            .iter()
            .map(|p| contact(p).and_then(|c| c.second).map_or(f64::NAN, |s| s.0))
            .collect::<Vec<_>>(),
    )
    .numeric(format!("{name}_jump_after"), jump_after.collect::<Vec<_>>())
}

/// The `status` of one position in `rigid.csv`: the stop reason in words, two-point
/// contacts, and why Wickens' parameters are undefined where they are.
fn rigid_status(p: &wheelrail::rigid::RigidPosition, centred_reference: bool) -> String {
    let mut s = p.stop.status_text().to_string();
    for (k, side) in ["left", "right"].iter().enumerate() {
        if p.contact[k].is_some_and(|c| c.second.is_some()) {
            s.push_str(&format!("; two-point contact {side}"));
        }
    }
    if p.y_ws.abs() < wheelrail::rigid::WICKENS_CENTRE_MM {
        s.push_str("; y_ws = 0: lambda, epsilon, sigma undefined");
    } else if p.stop == Stop::Converged && !centred_reference {
        s.push_str(NO_CENTRED_CONTACT);
    }
    s
}

/// Whether [`contact_columns`] writes the rail's contact angle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum RailSlopeColumn {
    /// `{side}_rail_tan_gamma` after `gamma_rad` (`rigid.csv`).
    Written,
    /// Not written (`quasi_elastic.csv`).
    Omitted,
}

/// The contact-point columns of one wheel, one row per point (NaN rows where there is no
/// contact): `{side}_s_mm`, with yaw `_x_mm`, then `_y_mm, _z_mm`, with yaw `_lead_mm`,
/// then `_r_mm, _gamma_rad`, `_rail_tan_gamma` where written, and
/// `_wheel_curvature_per_mm, _rail_curvature_per_mm`.
pub(super) fn contact_columns(
    t: TableBuilder,
    side: Side,
    points: &[ContactPoint],
    rail_slope: RailSlopeColumn,
    yawed: bool,
) -> TableBuilder {
    let name = side.name();
    let column = |f: fn(&ContactPoint) -> f64| points.iter().map(f).collect::<Vec<_>>();
    let mut t = t.numeric(format!("{name}_s_mm"), column(|c| c.s));
    if yawed {
        t = t.numeric(format!("{name}_x_mm"), column(|c| c.x));
    }
    t = t
        .numeric(format!("{name}_y_mm"), column(|c| c.y))
        .numeric(format!("{name}_z_mm"), column(|c| c.z));
    if yawed {
        t = t.numeric(format!("{name}_lead_mm"), column(|c| c.lead));
    }
    let mut t = t
        .numeric(format!("{name}_r_mm"), column(|c| c.r))
        .numeric(format!("{name}_gamma_rad"), column(|c| c.gamma));
    if rail_slope == RailSlopeColumn::Written {
        t = t.numeric(
            format!("{name}_rail_tan_gamma"),
            column(|c| c.rail_tan_gamma),
        );
    }
    t.numeric(
        format!("{name}_wheel_curvature_per_mm"),
        column(|c| c.wheel_curvature),
    )
    .numeric(
        format!("{name}_rail_curvature_per_mm"),
        column(|c| c.rail_curvature),
    )
}

fn converged(sweep: &RigidSweep, f: impl Fn(&wheelrail::rigid::RigidPosition) -> f64) -> Vec<f64> {
    sweep
        .positions()
        .iter()
        .map(|p| {
            if p.stop == Stop::Converged {
                f(p)
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// The contact-point jumps of a rigid sweep (`rigid_jumps.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn rigid_jumps(sweep: &RigidSweep) -> Result<Table, TableError> {
    let j = &sweep.jumps();
    Table::builder()
        .comment(format!("intervals of y_ws across which a rigid contact point jumps; kind jump: refined to {JUMP_REFINE_MM} mm; kind artefact: a sampled profile's contact point hopping between two minima of the gap that a hollow shallower than {ARTEFACT_HOLLOW_MM} mm separates, over the sweep step that holds it (not refined; continuous in delta_r and in the charts)"))
        .comment("hollow_mm: how far the gap rises between the two contact points above the higher of them, where they exchange (NaN, with the reason in hollow_status, where they could not be followed to one pose)")
        .comment(PER_WHEEL)
        .text("side", j.iter().map(|j| j.side.name()))
        .numeric("y_from_mm", j.iter().map(|j| j.y_from).collect::<Vec<_>>())
        .numeric("y_to_mm", j.iter().map(|j| j.y_to).collect::<Vec<_>>())
        .numeric("s_from_mm", j.iter().map(|j| j.s_from).collect::<Vec<_>>())
        .numeric("s_to_mm", j.iter().map(|j| j.s_to).collect::<Vec<_>>())
        .text("kind", j.iter().map(|j| j.kind.name()))
        .numeric("hollow_mm", j.iter().map(|j| j.hollow_mm).collect::<Vec<_>>())
        .text(
            "hollow_status",
            j.iter().map(|j| {
                if j.hollow_mm.is_finite() {
                    "ok"
                } else {
                    "not measured: the two contacts could not be followed to one pose (kind jump)"
                }
            }),
        )
        .build()
}

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

/// Hertz ellipses over the sweep (`hertz.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn hertz(
    sweep: &wheelrail::hertz::HertzSweep,
    settings: &wheelrail::hertz::HertzSettings,
) -> Result<Table, TableError> {
    let h = sweep.positions();
    let mut t = Table::builder()
        .comment(format!(
            "Hertz contact ellipses, method {}, contact {}, normal load {}",
            settings.method(), sweep.source().name(), settings.normal_load().name()
        ))
        .comment("a_mm semi-axis along the rolling direction, b_mm lateral; p0_MPa maximum pressure; A, B relative curvatures (1/mm) in the rolling and lateral directions")
        .numeric("y_ws_mm", h.iter().map(|p| p.y_ws).collect::<Vec<_>>());
    for (k, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let name = side.name();
        let ell = |f: &dyn Fn(&wheelrail::hertz::Ellipse) -> f64| -> Vec<f64> {
            h.iter()
                .map(|p| p.sides[k].ellipse().map_or(f64::NAN, f))
                .collect()
        };
        t = t
            .numeric(format!("{name}_a_mm"), ell(&|e| e.a_mm))
            .numeric(format!("{name}_b_mm"), ell(&|e| e.b_mm))
            .numeric(format!("{name}_p0_MPa"), ell(&|e| e.p0_mpa))
            .numeric(format!("{name}_approach_mm"), ell(&|e| e.approach_mm))
            .numeric(
                format!("{name}_normal_load_N"),
                h.iter()
                    .map(|p| p.sides[k].normal_load_n)
                    .collect::<Vec<_>>(),
            )
            .numeric(
                format!("{name}_A_per_mm"),
                h.iter().map(|p| p.sides[k].a_curvature).collect::<Vec<_>>(),
            )
            .numeric(
                format!("{name}_B_per_mm"),
                h.iter().map(|p| p.sides[k].b_curvature).collect::<Vec<_>>(),
            )
            .text(
                format!("{name}_status"),
                h.iter().map(|p| p.sides[k].status.clone()),
            );
    }
    t.build()
}

/// Errors of the paper's Hertz numerics (`hertz_accuracy_series.csv`,
/// `hertz_accuracy_ratio.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn hertz_accuracy(a: &HertzAccuracy) -> Result<(Table, Table), TableError> {
    let series = Table::builder()
        .comment("relative error of the paper's truncated series (its Eqs. 15-18, terms summed until below 1e-3) against K and E by the AGM")
        .numeric("e", a.series.iter().map(|r| r.0).collect::<Vec<_>>())
        .numeric("K_rel_error", a.series.iter().map(|r| r.1).collect::<Vec<_>>())
        .numeric("E_rel_error", a.series.iter().map(|r| r.2).collect::<Vec<_>>())
        .build()?;
    let ratio = Table::builder()
        .comment("relative error of b/a from the paper's fixed-point iteration (from e = 0.5, |de| <= 1e-3) against the exact inversion")
        .numeric("A_over_B", a.ratio.iter().map(|r| r.0).collect::<Vec<_>>())
        .numeric("b_over_a_rel_error", a.ratio.iter().map(|r| r.1).collect::<Vec<_>>())
        .numeric("iterations", a.ratio.iter().map(|r| f64::from(r.2)).collect::<Vec<_>>())
        .build()?;
    Ok((series, ratio))
}

/// The run time against error study (`tradeoff.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn tradeoff(m: &[crate::tradeoff::Measurement]) -> Result<Table, TableError> {
    let col =
        |f: &dyn Fn(&crate::tradeoff::Measurement) -> f64| m.iter().map(f).collect::<Vec<_>>();
    Table::builder()
        .comment("run time against error: the scene's pipeline (placement, rigid, quasi-elastic, Hertz; no rendering) per setting, single-threaded")
        .comment("errors against the reference (analytic profiles, default solver, Gauss-Legendre panels of half a weight width, cut-off exp(-60), exact Hertz), max over the sweep and both wheels; contact_mm excludes positions within one step of a reference jump; qe_location_mm is weight-averaged over the patches")
        .comment("median_ms, min_ms, max_ms over the timed rounds: after an untimed warm-up round, each round runs every setting once in its own random order")
        .comment("times are machine-dependent: compare settings as ratios within one run")
        .text("setting", m.iter().map(|x| x.setting.label.clone()))
        .numeric("profile_step_mm", col(&|x| x.setting.profile_step_mm.unwrap_or(f64::NAN)))
        .text("rigid_solver", m.iter().map(|x| x.setting.solver.name()))
        .text("qe_quadrature", m.iter().map(|x| x.setting.quasi_elastic.quadrature().name()))
        .numeric("qe_cutoff", col(&|x| x.setting.quasi_elastic.cutoff()))
        .text("hertz_method", m.iter().map(|x| x.setting.hertz.to_string()))
        .numeric("median_ms", col(&|x| 1e3 * x.median_s))
        .numeric("min_ms", col(&|x| 1e3 * x.range_s.0))
        .numeric("max_ms", col(&|x| 1e3 * x.range_s.1))
        .numeric("contact_error_mm", col(&|x| x.errors.contact_mm))
        .numeric("qe_location_error_mm", col(&|x| x.errors.qe_location_mm))
        .numeric("roll_error_rad", col(&|x| x.errors.roll_rad))
        .numeric("a_rel_error", col(&|x| x.errors.a_rel))
        .numeric("b_rel_error", col(&|x| x.errors.b_rel))
        .numeric("p0_rel_error", col(&|x| x.errors.p0_rel))
        .text(
            "status",
            m.iter().map(|x| match x.setting.profile_step_mm {
                Some(_) => "ok",
                None => "analytic profiles: no profile_step_mm (NaN)",
            }),
        )
        .build()
}

/// FASTSIM's discretisation study (`fastsim_tradeoff.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn fastsim_tradeoff(
    m: &[crate::tradeoff::fastsim::GridMeasurement],
) -> Result<Table, TableError> {
    use crate::tradeoff::fastsim::{PASSES, label};
    use wheelrail::creep::fastsim::{STUDY_REFERENCE, study_cases};
    let col = |f: &dyn Fn(&crate::tradeoff::fastsim::GridMeasurement) -> f64| {
        m.iter().map(f).collect::<Vec<_>>()
    };
    let cases = study_cases();
    let mut patches: Vec<String> = Vec::new();
    for (p, _) in &cases {
        let text = format!(
            "a = {}, b = {} mm at FN = {} kN",
            p.a_mm(),
            p.b_mm(),
            1e-3 * p.normal_force_n()
        );
        if !patches.contains(&text) {
            patches.push(text);
        }
    }
    let defaults = wheelrail::creep::Settings::default();
    let cases = cases.len();
    Table::builder()
        .comment("run time against error of FASTSIM's discretisation: grid = strips across the patch (lateral) x elements along each strip (rolling direction); the default grid is marked (default)")
        .comment(format!(
            "errors against the reference grid {}x{} with the same settings otherwise (the default: parabolic bound, blended flexibilities, midpoint scheme, mu = {}, G = {} GPa, nu = {}), the largest over the {cases} cases of creep::fastsim::study_cases: patches {}; creepages of 0.3, 1 and 3 times the creepage that saturates linear theory in xi, eta, phi alone and all three at once",
            STUDY_REFERENCE.strips,
            STUDY_REFERENCE.elements,
            defaults.friction(),
            1e-3 * defaults.shear_modulus_mpa(),
            defaults.poisson(),
            patches.join(" and ")
        ))
        .comment("force_error = max(|dFx|, |dFy|) / (mu FN); moment_error = |dMz| / (mu FN c), c = sqrt(a b): both dimensionless")
        .comment(format!(
            "median_us, min_us, max_us: one patch's FASTSIM solve (microseconds), single-threaded; each timed run solves the {cases} cases {PASSES} times; after an untimed warm-up round, each round runs every grid once in its own random order"
        ))
        .comment("times are machine-dependent: compare grids as ratios within one run")
        .text("grid", m.iter().map(|x| label(x.grid)))
        .numeric("strips", col(&|x| f64::from(x.grid.strips)))
        .numeric("elements", col(&|x| f64::from(x.grid.elements)))
        .numeric("median_us", col(&|x| 1e6 * x.timing.median_s))
        .numeric("min_us", col(&|x| 1e6 * x.timing.range_s.0))
        .numeric("max_us", col(&|x| 1e6 * x.timing.range_s.1))
        .numeric("force_error", col(&|x| x.force_error))
        .numeric("moment_error", col(&|x| x.moment_error))
        .text(
            "status",
            m.iter().map(|x| {
                if x.force_error.is_finite() && x.moment_error.is_finite() {
                    "ok"
                } else {
                    "grid out of range: not solved (NaN)"
                }
            }),
        )
        .build()
}

/// Definition lines shared by the conicity tables.
const CONICITY_FRAME: &str = "y lateral displacement of the wheelset, positive to the left (track frame); delta_r = r_left - r_right; amplitude = half the peak-to-peak motion; centre_mm = middle of the motion (the equilibrium for a symmetric pair)";

/// The equivalent conicity of one method over its amplitudes, as printed by `wheelrail
/// conicity` (`source` names the Δr table).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn conicity_points(
    c: &wheelrail::conicity::EquivalentConicity,
    source: &str,
) -> Result<Table, TableError> {
    let p = &c.points;
    Table::builder()
        .comment(format!(
            "equivalent conicity tan_gamma_e (EN 15302), method {}, from {source}",
            conicity_method_text(c.method)
        ))
        .comment(CONICITY_FRAME)
        .comment(format!(
            "equilibrium (delta_r = 0) at y = {:.6} mm; largest amplitude the delta_r function supports: {:.6} mm",
            c.equilibrium_mm, c.max_amplitude_mm
        ))
        .numeric("amplitude_mm", p.iter().map(|p| p.amplitude_mm).collect::<Vec<_>>())
        .numeric("tan_gamma_e", p.iter().map(|p| p.tan_gamma_e).collect::<Vec<_>>())
        .numeric("centre_mm", p.iter().map(|p| p.centre_mm).collect::<Vec<_>>())
        .text("status", p.iter().map(|p| p.status.name()))
        .build()
}

/// What each method is, for table headers.
pub fn conicity_method_text(m: wheelrail::conicity::ConicityMethod) -> &'static str {
    match m {
        wheelrail::conicity::ConicityMethod::Klingel => {
            "klingel (EN 15302 Annex B: wavelength of the nonlinear kinematic motion, closed-form integral)"
        }
        wheelrail::conicity::ConicityMethod::Regression => {
            "regression (EN 15302 Annex C: least-squares line through delta_r over the motion, weighted as a harmonic motion)"
        }
    }
}

/// The equivalent conicity function of a pair by both methods (`equivalent_conicity.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn equivalent_conicity(c: &wheelrail::conicity::PairConicity) -> Result<Table, TableError> {
    use wheelrail::conicity::ConicityMethod;
    let k = &c.klingel.points;
    let r = &c.regression.points;
    Table::builder()
        .comment("equivalent conicity tan_gamma_e (EN 15302) of the rigid delta_r function, by both methods; NaN with a status where not computable")
        .comment(format!("tan_gamma_e_klingel: {}", conicity_method_text(ConicityMethod::Klingel)))
        .comment(format!("tan_gamma_e_regression: {}", conicity_method_text(ConicityMethod::Regression)))
        .comment(CONICITY_FRAME)
        .comment(format!(
            "equilibrium (delta_r = 0) at y = {:.6} mm; largest amplitude supported: {:.6} mm (klingel), {:.6} mm (regression)",
            c.klingel.equilibrium_mm, c.klingel.max_amplitude_mm, c.regression.max_amplitude_mm
        ))
        .numeric("amplitude_mm", k.iter().map(|p| p.amplitude_mm).collect::<Vec<_>>())
        .numeric("tan_gamma_e_klingel", k.iter().map(|p| p.tan_gamma_e).collect::<Vec<_>>())
        .numeric("tan_gamma_e_regression", r.iter().map(|p| p.tan_gamma_e).collect::<Vec<_>>())
        .numeric("centre_mm", k.iter().map(|p| p.centre_mm).collect::<Vec<_>>())
        .text("status_klingel", k.iter().map(|p| p.status.name()))
        .text("status_regression", r.iter().map(|p| p.status.name()))
        .build()
}

/// The parameters of the pair (`parameters.csv`): one row each, with unit and definition.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn parameters(p: &wheelrail::conicity::Parameters) -> Result<Table, TableError> {
    let rows = p.rows();
    Table::builder()
        .comment("parameters of the wheel/rail pair from its rigid sweep; NaN where undefined (e.g. flange contact beyond the sweep), with the reason in status")
        .comment(CONICITY_FRAME)
        .text("parameter", rows.iter().map(|r| r.name))
        .numeric("value", rows.iter().map(|r| r.value).collect::<Vec<_>>())
        .text("unit", rows.iter().map(|r| r.unit))
        .text("definition", rows.iter().map(|r| r.definition.clone()))
        .text("status", rows.iter().map(ParameterRow::status))
        .build()
}

/// A built-in profile in its own frame as a point table readable by the CSV reader.
///
/// # Errors
/// Only internal inconsistencies.
pub fn profile_points(
    profile: &wheelrail::profile::Profile,
    step_mm: f64,
) -> Result<Table, TableError> {
    let rows = profile.sample(step_mm);
    let col = |k: usize| rows.iter().map(|r| r[k]).collect::<Vec<f64>>();
    let (tan_gamma, face) = slope_and_face(&rows);
    let (u, v, frame) = match profile.kind() {
        wheelrail::profile::ProfileKind::Wheel => (
            "s_mm",
            "F_mm",
            format!("wheel side frame: {WHEEL_SIDE_FRAME}"),
        ),
        wheelrail::profile::ProfileKind::Rail => (
            "y_mm",
            "z_mm",
            "rail side frame, upright rail: y_mm lateral from the rail axis, positive towards the field side; z_mm height, up positive, 0 at the top of rail".to_string(),
        ),
    };
    Table::builder()
        .comment(format!("{} generated by wheelrail {} from its definition: {}", profile.name(), env!("CARGO_PKG_VERSION"), profile.source()))
        .comment(format!("frame: {frame}"))
        .comment("tan_gamma positive on the coned tread; curvature_per_mm convex positive; section joints included as extra rows")
        .comment(face_comment())
        .comment(format!("regenerate: wheelrail profile {} --out FILE --step-mm {step_mm}", profile.name().to_ascii_lowercase()))
        .numeric(u, col(0))
        .numeric(v, col(1))
        .numeric("tan_gamma", tan_gamma)
        .numeric("curvature_per_mm", col(3))
        .text("face", face)
        .build()
}

/// The definitions of the flange dimensions, as the tables and pages state them.
pub const FLANGE_DIMENSIONS_TEXT: &str = "flange dimensions (EN 15313, UIC 510-2; TSI WAG Regulation (EU) No 321/2013 4.2.3.6.2 Figure 1): Sh flange height, the flange tip above the profile's point on the taping line (70 mm from the inner face, s = 0); Sd flange thickness, from the inner face (s = -70 mm) to the flank 10 mm above the taping-line point; qR, from the Sd point to the flank 2 mm below the tip; measured on the wheel's points joined by straight lines (a built-in profile on its definition), whatever smoothing_wavelength_mm filters for the contact";

/// The definitions of the rail wear, as the tables and pages state them.
pub const RAIL_WEAR_TEXT: &str = "rail wear against the nominal rail, both upright (profile_inclination taken out) in the frame their files give (no fitting): vertical_wear, nominal minus measured height on the centre line (halfway between the nominal head's faces at the gauge-point depth); gauge_face_wear, how far the gauge face lies towards the field side of the nominal's at the gauge-point depth below the nominal top; positive where material is gone";

/// The maintenance view of a placement's profiles: `side, body, profile, dimension,
/// value_mm, limit_min_mm, limit_max_mm, status`, one row per wheel dimension (Sh, Sd, qR)
/// and, when the scene names nominal rails, per rail wear (vertical, gauge face).
///
/// `status` is `ok` (`ok; no maximum limit` for qR, whose maximum is `NaN`), `below the
/// minimum`, `above the maximum`, `no limit` (rail wear) or `undefined: ` and why; a limit
/// that does not exist is `NaN`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn profile_dimensions(
    placement: &wheelrail::track::Placement,
    assessment: &wheelrail::maintenance::Assessment,
) -> Result<Table, TableError> {
    let sides = [
        (Side::Left, &placement.left()),
        (Side::Right, &placement.right()),
    ];
    let mut rows: Vec<DimensionRow> = Vec::new();
    let mut builder = Table::builder()
        .comment(FLANGE_DIMENSIONS_TEXT)
        .comment(format!(
            "frame: wheel side frame; {WHEEL_SIDE_FRAME}; every value in mm"
        ));
    for (k, (side, pair)) in sides.iter().enumerate() {
        let w = &assessment.wheels[k];
        builder = builder.comment(format!(
            "limits of the {} wheel (nominal diameter {} mm): {}",
            side.name(),
            2.0 * pair.wheel().nominal_radius_mm(),
            w.limits.describe()
        ));
        rows.extend(wheel_dimension_rows(
            *side,
            pair.wheel().profile().name(),
            w,
        ));
    }
    if let Some(rails) = &assessment.rails {
        builder = builder.comment(RAIL_WEAR_TEXT);
        for (k, (side, pair)) in sides.iter().enumerate() {
            rows.extend(rail_wear_rows(
                *side,
                pair.rail().profile().name(),
                &rails[k],
            ));
        }
    }
    let text = |f: fn(&DimensionRow) -> String| rows.iter().map(f).collect::<Vec<_>>();
    let number = |f: fn(&DimensionRow) -> f64| rows.iter().map(f).collect::<Vec<_>>();
    builder
        .comment("status: ok (qR: ok; no maximum limit), below the minimum, above the maximum (a limit broken is a result, not an error), no limit (rail wear), or undefined and why (value NaN); a limit that does not exist is NaN")
        .text("side", text(|r| r.side.name().to_string()))
        .text("body", text(|r| r.body.to_string()))
        .text("profile", text(|r| r.profile.clone()))
        .text("dimension", text(|r| r.dimension.to_string()))
        .numeric("value_mm", number(|r| r.value))
        .numeric("limit_min_mm", number(|r| r.limits.0))
        .numeric("limit_max_mm", number(|r| r.limits.1))
        .text("status", text(|r| r.status.clone()))
        .build()
}

/// One row of `profile_dimensions.csv`.
struct DimensionRow {
    side: Side,
    body: &'static str,
    profile: String,
    dimension: &'static str,
    /// The value (mm), NaN where undefined.
    value: f64,
    /// The limits (mm), NaN where there is none.
    limits: (f64, f64),
    status: String,
}

/// The rows of one wheel's flange dimensions Sh, Sd and qR against its limits.
fn wheel_dimension_rows(
    side: Side,
    profile: &str,
    w: &wheelrail::maintenance::WheelAssessment,
) -> Vec<DimensionRow> {
    use wheelrail::maintenance::limits::{Bound, Dimension};
    let l = &w.limits;
    let d = w.dimensions.as_ref();
    [
        (
            Dimension::Sh,
            d.map(|d| d.sh_mm),
            l.sh_min.value_mm,
            l.sh_max.value_mm,
        ),
        (
            Dimension::Sd,
            d.map(|d| d.sd_mm),
            l.sd_min.value_mm,
            l.sd_max.value_mm,
        ),
        (
            Dimension::QR,
            d.map(|d| d.qr_mm),
            l.qr_min.value_mm,
            f64::NAN,
        ),
    ]
    .into_iter()
    .map(|(dim, v, min, max)| {
        let (value, status) = match v {
            Ok(v) => {
                let broken = w.breaches.iter().find(|b| b.dimension == dim);
                let status = match broken.map(|b| b.bound) {
                    // The NaN maximum of qR is explained in the row, as every NaN is.
                    None if max.is_nan() => "ok; no maximum limit".into(),
                    None => "ok".into(),
                    Some(Bound::Min) => "below the minimum".into(),
                    Some(Bound::Max) => "above the maximum".into(),
                };
                (v, status)
            }
            Err(e) => (f64::NAN, format!("undefined: {e}")),
        };
        DimensionRow {
            side,
            body: "wheel",
            profile: profile.to_string(),
            dimension: dim.symbol(),
            value,
            limits: (min, max),
            status,
        }
    })
    .collect()
}

/// The rows of one rail's wear (no limits).
fn rail_wear_rows(
    side: Side,
    profile: &str,
    wear: &Result<wheelrail::maintenance::RailWear, wheelrail::maintenance::WearError>,
) -> Vec<DimensionRow> {
    [
        ("vertical_wear", wear.as_ref().map(|w| w.vertical_mm)),
        ("gauge_face_wear", wear.as_ref().map(|w| w.gauge_face_mm)),
    ]
    .into_iter()
    .map(|(name, v)| {
        let (value, status) = match v {
            Ok(v) => (v, "no limit".to_string()),
            Err(e) => (f64::NAN, format!("undefined: {e}")),
        };
        DimensionRow {
            side,
            body: "rail",
            profile: profile.to_string(),
            dimension: name,
            value,
            limits: (f64::NAN, f64::NAN),
            status,
        }
    })
    .collect()
}
