//! The tabulated wheel and rail of the paper's solver (its "tabular data").

use super::{SideGap, SidePose};
use crate::track::HeightTable;

/// Tabulated wheel `(s, Yw, Zw)` and rail, for the paper's solver.
#[derive(Debug, Clone)]
pub(super) struct Tables {
    step_mm: f64,
    wheel: Vec<[f64; 3]>,
    rail: HeightTable,
}
impl<'a> SideGap<'a> {
    /// Adds the tables the paper's solver searches: wheel and rail tabulated every
    /// `step_mm`, the rail height between its table points interpolated linearly.
    pub(crate) fn with_tables(mut self, step_mm: f64) -> SideGap<'a> {
        self.tabulated = Some(Tables {
            step_mm,
            wheel: Vec::new(),
            rail: HeightTable::new(&self.pair.rail, step_mm),
        });
        self.tabulate_wheel();
        self
    }

    /// Tabulates the wheel (the points the rail sees, at the side's yaw) every step of the
    /// tables over the profile's domain.
    pub(super) fn tabulate_wheel(&mut self) {
        let Some(step_mm) = self.tabulated.as_ref().map(|t| t.step_mm) else {
            return;
        };
        let (lo, hi) = self.pair.wheel.profile().domain();
        let n = ((hi - lo) / step_mm).round().max(1.0) as usize;
        let wheel = (0..=n)
            .filter_map(|i| {
                let s = lo + (hi - lo) * i as f64 / n as f64;
                let p = self.wheel_point(s)?;
                Some([s, p.y, p.z])
            })
            .collect();
        if let Some(t) = &mut self.tabulated {
            t.wheel = wheel;
        }
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
