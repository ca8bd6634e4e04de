//! The error of the small-angle form of yaw against the wheel's exact outline: S1002 on
//! UIC60 1:40 (the paper's wheelset), fixed yaws of 0 to 30 mrad, shifts of -10 to 10 mm.
//! Prints, per yaw, the largest differences of the rigid contact between the two forms
//! over the positions where both find the contact on the same part of the wheel (within
//! 1 mm), and how many positions jump to another part.
//!
//! Run with `cargo run --release --example yaw_small_angle`.

use wheelrail::pipeline;
use wheelrail::rigid::{self, Solver};
use wheelrail::scene::Scene;
use wheelrail::sweep::{Sweep, YawModel, YawRule};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let scene = Scene::from_toml("", "paper defaults", ".".as_ref())?;
    let placement = pipeline::place(&scene)?;
    println!(
        "yaw_mrad,positions,other_part,lateral_mm,height_mm,contact_angle_rad,lead_mm,roll_rad"
    );
    for yaw_mrad in [0.0, 5.0, 10.0, 20.0, 30.0] {
        let sweep = |model| -> Result<rigid::RigidSweep, Box<dyn std::error::Error>> {
            let shifts = Sweep::range(-10.0, 10.0, 0.5)?.with_yaw(YawRule::new(
                yaw_mrad * 1e-3,
                0.0,
                model,
            ))?;
            Ok(rigid::search(&placement, &shifts, Solver::default()))
        };
        let (exact, small) = (sweep(YawModel::Exact)?, sweep(YawModel::SmallAngle)?);
        let mut worst = [0.0f64; 5];
        let (mut compared, mut other) = (0, 0);
        for (e, s) in exact.positions().iter().zip(small.positions()) {
            worst[4] = worst[4].max((e.roll - s.roll).abs());
            for k in 0..2 {
                let (Some(a), Some(b)) = (e.contact[k], s.contact[k]) else {
                    continue;
                };
                if (a.s - b.s).abs() > 1.0 {
                    other += 1;
                    continue;
                }
                compared += 1;
                let d = [a.y - b.y, a.z - b.z, a.gamma - b.gamma, a.lead - b.lead];
                for (w, d) in worst.iter_mut().zip(d) {
                    *w = w.max(d.abs());
                }
            }
        }
        println!(
            "{yaw_mrad},{compared},{other},{:.3e},{:.3e},{:.3e},{:.3e},{:.3e}",
            worst[0], worst[1], worst[2], worst[3], worst[4]
        );
    }
    Ok(())
}
