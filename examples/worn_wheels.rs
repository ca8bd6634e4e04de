//! Writes generated worn S1002 wheel profiles (`wheelrail::fleet::synthetic`) as CSV files:
//! the generated part of the example fleet (`reports/fleet/`), reproducible from a seed.
//!
//! `cargo run --release --example worn_wheels -- DIR [N] [SEED]` writes
//! `DIR/worn_0000.csv` ... (N files, default 300; seed default 14).

use std::path::PathBuf;
use wheelrail::prelude::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let dir = PathBuf::from(args.next().unwrap_or_else(|| "target/worn_wheels".into()));
    let n: u64 = args.next().map_or(Ok(300), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(14), |a| a.parse())?;
    std::fs::create_dir_all(&dir)?;
    for i in 0..n {
        let (text, _) = fleet::synthetic::csv_text(seed, i);
        std::fs::write(dir.join(format!("worn_{i:04}.csv")), text)?;
    }
    eprintln!("wrote {n} profiles (seed {seed}) to {}", dir.display());
    Ok(())
}
