//! The tabulated wheel and rail of the paper's solver (its "tabular data").

use super::{SideGap, SidePose};
use crate::track::HeightTable;

/// Tabulated wheel `(s, Yw, Zw)` and rail, for the paper's solver.
#[derive(Debug, Clone)]
pub(super) struct Tables {
    wheel: Vec<[f64; 3]>,
    rail: HeightTable,
}
impl<'a> SideGap<'a> {
    /// Adds the tables the paper's solver searches: wheel and rail tabulated every
    /// `step_mm`, the rail height between its table points interpolated linearly.
    pub(crate) fn with_tables(mut self, step_mm: f64) -> SideGap<'a> {
        let (lo, hi) = self.pair.wheel.profile().domain();
        let n = ((hi - lo) / step_mm).round().max(1.0) as usize;
        let wheel = (0..=n)
            .map(|i| {
                let s = lo + (hi - lo) * i as f64 / n as f64;
                let p = self.pair.wheel.at(s);
                [s, p.y, p.z]
            })
            .collect();
        self.tabulated = Some(Tables {
            wheel,
            rail: HeightTable::new(&self.pair.rail, step_mm),
        });
        self
    }

    /// The lowest gap over the tabulated wheel points with the tabulated rail (the paper's
    /// discrete minimum): `(s, g, Y)` of the table point, or `None` without tables or
    /// without a wheel point above the rail.
    pub(crate) fn tabulated_minimum(&self, pose: &SidePose) -> Option<(f64, f64, f64)> {
        let t = self.tabulated.as_ref()?;
        let mut best: Option<(f64, f64, f64)> = None;
        for &[s, yw, zw] in &t.wheel {
            let [y, z] = pose.apply(yw, zw);
            if let Some(zr) = t.rail.height(y) {
                let g = z - zr;
                if best.is_none_or(|b| g < b.1) {
                    best = Some((s, g, y));
                }
            }
        }
        best
    }
}
