//! A measured MiniProf wheel through the whole pipeline from Rust: read and smooth the file,
//! place it on 60E1 rails at 1:40, rigid and quasi-elastic contact search, Hertz ellipses.
//!
//! Run with `cargo run --release --example measured_wheel [FILE.whl]` (default: the worn
//! wheel Car7216 of the test data).

use wheelrail::prelude::*;

fn main() -> Result<(), Error> {
    let path = std::env::args().nth(1).unwrap_or_else(|| {
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/data/profiles/Car7216_0001r.whl"
        )
        .into()
    });
    // Measured flanges fold back at their vertical faces: drop those points (the reader
    // lists them), then smooth the measurement with a 4 mm filter.
    let options = ReadOptions::new(StepBack::Drop);
    let points = read_profile_with(path.as_ref(), ProfileKind::Wheel, &options)?;
    println!(
        "{}: {} points ({} dropped), sha256 {}",
        points.source.path,
        points.points.len(),
        points.dropped_step_backs.len(),
        &points.source.sha256[..12]
    );
    let wheel = Profile::from_points(points, 4.0)?;

    let layout = TrackLayout::standard(Inclination::parse("1:40")?);
    let rail = Profile::uic60e1();
    let placement = Placement::symmetric(wheel, 460.0, rail, Inclination::VERTICAL, layout)?;
    let rigid = rigid::search(
        &placement,
        &Sweep::range(-8.0, 8.0, 1.0)?,
        Solver::default(),
    );
    // The quasi-elastic sweep keeps the rigid sweep it averaged around.
    let qe = quasi_elastic::search(&placement, rigid, &QuasiElasticSettings::default());

    // Hertz on the heaviest quasi-elastic patch, 70 kN per wheel, steel on steel.
    let steel = Material::new(210e3, 0.3)?;
    let e_star = hertz::effective_modulus(&steel, &steel);
    let settings = HertzSettings::default();
    let ellipses = hertz::sweep(Contacts::QuasiElastic(&qe), 70e3, e_star, &settings);

    println!("y_ws_mm  delta_r_mm  left: a_mm  b_mm  p0_MPa");
    for (position, hertz) in qe.rigid().positions().iter().zip(ellipses.positions()) {
        let left = hertz.side(Side::Left);
        match left.ellipse() {
            Some(e) => println!(
                "{:6.1}  {:9.4}  {:9.3}  {:5.3}  {:6.0}",
                position.y_ws,
                position.delta_r(),
                e.a_mm,
                e.b_mm,
                e.p0_mpa
            ),
            None => println!(
                "{:6.1}  {:9.4}  no ellipse: {}",
                position.y_ws,
                position.delta_r(),
                left.status
            ),
        }
    }
    Ok(())
}
