//! How many gap evaluations each stage of a scene makes: the machine-independent side of
//! the speed measurements (docs/performance.md). Counts coarse samples (a wheel sample
//! against the rail's height table), exact gaps (with derivatives: Newton's steps, the
//! certificate's cell ends, quadrature nodes), scans for basins, certificates and
//! deep-search cells.
//!
//! Run with `cargo run --release --example evaluation_counts --features count-evaluations`
//! (the counting is compiled in only with that feature). Without arguments: the paper
//! scene and the EN 15302 reference pair of `benches/data`; or give scene files.

use std::path::{Path, PathBuf};
use wheelrail::counters::{self, Counts};
use wheelrail::pipeline::Stage;
use wheelrail::prelude::*;

/// The EN 15302 reference pair's benchmark scene (R-UIC519A on S-UIC519A, 141 positions).
const EN_PAIR: &str = "benches/data/en15302_e1_delta_r.toml";

fn main() -> Result<(), Error> {
    let args: Vec<PathBuf> = std::env::args_os().skip(1).map(PathBuf::from).collect();
    let scenes: Vec<(String, Scene)> = if args.is_empty() {
        let paper = Scene::from_toml("", "paper", Path::new("."))?;
        let en_pair = Scene::load(Path::new(EN_PAIR))?;
        vec![("the paper scene".into(), paper), (EN_PAIR.into(), en_pair)]
    } else {
        args.iter()
            .map(|p| Ok((p.display().to_string(), Scene::load(p)?)))
            .collect::<Result<_, Error>>()?
    };
    for (label, scene) in &scenes {
        let placement = pipeline::place(scene)?;
        counters::take(); // placing evaluates no gap
        let rigid = rigid::search(&placement, scene.sweep(), scene.rigid_solver());
        let searched = counters::take();
        // The quasi-elastic pass only where the scene's outputs need it, as a report runs.
        let needs_quasi = pipeline::needed_stages(scene).contains(&Stage::QuasiElastic);
        if needs_quasi {
            quasi_elastic::search(&placement, rigid.clone(), scene.quasi_elastic());
        }
        let averaged = counters::take();
        let n = rigid.positions().len();
        println!("{label}: {n} positions, both wheels");
        println!(
            "  {:<14} {:>10} {:>10} {:>8} {:>8} {:>8}   per position: coarse, exact",
            "stage", "coarse", "exact", "scans", "certif.", "cells"
        );
        print_row("rigid", &searched, n);
        if needs_quasi {
            print_row("quasi-elastic", &averaged, n);
        }
    }
    Ok(())
}

/// One stage's counts, with the two evaluation counts per position.
fn print_row(stage: &str, c: &Counts, positions: usize) {
    let per = |v: u64| v as f64 / positions as f64;
    println!(
        "  {stage:<14} {:>10} {:>10} {:>8} {:>8} {:>8}   {:>8.1} {:>8.1}",
        c.coarse_samples,
        c.exact_gaps,
        c.scans,
        c.certificates,
        c.deep_cells,
        per(c.coarse_samples),
        per(c.exact_gaps),
    );
}
