//! One Hertz contact ellipse from the principal curvatures of wheel and rail.
//!
//! Run with `cargo run --release --example hertz_ellipse`.

use wheelrail::hertz::{Contact, PrincipalCurvatures};
use wheelrail::prelude::*;

fn main() -> Result<(), Error> {
    // A 460 mm wheel with a straight (conical) tread on a rail head of 300 mm crown radius:
    // principal curvatures in 1/mm, convex positive, principal directions aligned (ψ = 0).
    let k = PrincipalCurvatures {
        wheel_rolling: 1.0 / 460.0,
        wheel_lateral: 0.0,
        rail_rolling: 0.0,
        rail_lateral: 1.0 / 300.0,
    };
    let (a, b) = hertz::relative_curvatures(&k, 0.0);
    let steel = Material::new(210e3, 0.3)?; // Young's modulus in MPa
    let e_star = hertz::effective_modulus(&steel, &steel);
    match hertz::ellipse(a, b, 70e3, e_star, EllipseMethod::Exact)? {
        Contact::Hertzian(e) => println!(
            "A = {a:.6} 1/mm, B = {b:.6} 1/mm, 70 kN: a = {:.3} mm (rolling), b = {:.3} mm, p0 = {:.0} MPa",
            e.a_mm, e.b_mm, e.p0_mpa
        ),
        Contact::NotHertzian(reason) => println!("no Hertz ellipse: {reason}"),
    }
    Ok(())
}
