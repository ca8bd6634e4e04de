//! Your own wheel and rail profiles, held in memory, through a rigid contact sweep to the
//! rolling radius difference Δr and the equivalent conicity tan γe (EN 15302).
//!
//! Run with `cargo run --release --example own_profiles`.

use wheelrail::prelude::*;

fn main() -> Result<(), Error> {
    // Stand-ins for your measured or designed points, in each profile's side frame (mm):
    // the wheel as [s, F] (s from the taping line, flange at s < 0), the rail as [y, z]
    // (upright, y towards the field side, z up from the top of rail). Here: S1002 and 60E1
    // sampled every 0.2 mm.
    let points = |p: Profile| p.sample(0.2).iter().map(|r| [r[0], r[1]]).collect();
    let wheel =
        PointProfile::from_points(ProfileKind::Wheel, "my wheel", points(Profile::s1002()))?;
    let rail = PointProfile::from_points(ProfileKind::Rail, "my rail", points(Profile::uic60e1()))?;
    let wheel = Profile::from_points(wheel, 0.0)?; // 0: interpolate, no smoothing
    let rail = Profile::from_points(rail, 0.0)?;

    // Standard gauge and wheelset, rails inclined 1:40; the rail points are upright. One
    // wheel and one rail on both sides: a mirror-symmetric wheelset.
    let layout = TrackLayout::standard(Inclination::parse("1:40")?);
    let placement = Placement::symmetric(wheel, 460.0, rail, Inclination::VERTICAL, layout)?;

    // Lateral shifts of the wheelset from -10 to 10 mm every 0.1 mm, roll solved.
    let shifts = Sweep::range(-10.0, 10.0, 0.1)?;
    let sweep = rigid::search(&placement, &shifts, Solver::default());
    let pair = conicity::assess(&sweep, &ConicitySettings::default());

    println!("y_ws_mm, delta_r_mm (every 2 mm)");
    for (y, dr) in pair
        .delta_r
        .points()
        .filter(|(y, _)| (y / 2.0).fract().abs() < 1e-9)
    {
        println!("{y:6.1}, {dr:9.5}");
    }
    let p = &pair.parameters;
    println!(
        "tan γe ({}) at 2, 3, 4 mm: {:.4}, {:.4}, {:.4}",
        p.method.name(),
        p.tan_gamma_e_2mm,
        p.tan_gamma_e_3mm,
        p.tan_gamma_e_4mm
    );
    println!(
        "flange contact from {:.2} mm (left) and {:.2} mm (right); {} contact-point jumps",
        p.flange_contact_left_mm, p.flange_contact_right_mm, p.contact_point_jumps
    );
    Ok(())
}
