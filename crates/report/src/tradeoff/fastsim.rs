//! Run time against error of FASTSIM's discretisation: the grids of the discretisation study
//! ([`wheelrail::creep::fastsim::STUDY_GRIDS`]) with their errors against the converged grid
//! ([`wheelrail::creep::fastsim::study`]), each timed on the study's cases as the scene's
//! settings are timed (a warm-up round, then rounds in random order; median, fastest and
//! slowest), `wheelrail tradeoff`'s second table and chart.

use super::{ChartPoint, StudyCsv, Timing, TradeoffCsvError, timed_rounds};
use wheelrail::creep::fastsim::{self as creep_fastsim, STUDY_REFERENCE};
use wheelrail::creep::{DEFAULT_GRID, Grid, Settings, tangential};

/// Passes over the study's cases in one timed run: 24 cases times 5 passes, so that a run
/// of the coarsest grid (about 0.6 µs a patch) lasts about 0.07 ms, far above the clock's
/// resolution and the cost of reading it, and one of the default grid (about 6 µs) under a
/// millisecond, short enough that most runs on a shared machine are not interrupted (the
/// median then leaves out those that are).
pub const PASSES: usize = 5;

/// The measured cost and errors of one grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridMeasurement {
    /// The grid.
    pub grid: Grid,
    /// Median, fastest and slowest time of one FASTSIM solve (one patch), s.
    pub timing: Timing,
    /// Largest force error over the study's cases, relative to `μ FN`.
    pub force_error: f64,
    /// Largest spin-moment error over the study's cases, relative to `μ FN c`.
    pub moment_error: f64,
}

/// The end of the default grid's label: the chart draws that grid as the default.
pub const DEFAULT_MARK: &str = " (default)";

/// The label of `grid` in the table and the chart: `strips x elements`, the default marked
/// `(default)`.
///
/// # Example
///
/// ```
/// use wheelrail::creep::{DEFAULT_GRID, Grid};
/// use wheelrail_report::tradeoff::fastsim::label;
/// assert_eq!(label(Grid { strips: 8, elements: 16 }), "8x16");
/// assert_eq!(label(DEFAULT_GRID), "32x32 (default)");
/// ```
pub fn label(grid: Grid) -> String {
    let mark = if grid == DEFAULT_GRID {
        DEFAULT_MARK
    } else {
        ""
    };
    format!("{}x{}{mark}", grid.strips, grid.elements)
}

/// Measures `grids` (`wheelrail tradeoff`: [`creep_fastsim::STUDY_GRIDS`]): errors from
/// [`wheelrail::creep::fastsim::study`] against [`STUDY_REFERENCE`], times from a warm-up round
/// and `repeats` timed rounds, each run solving the study's cases [`PASSES`] times with the
/// default settings on the grid (one thread: FASTSIM is not parallel). `progress` as for
/// [`super::study`].
pub fn study(
    grids: &[Grid],
    repeats: usize,
    mut progress: impl FnMut(usize, usize, &str),
) -> Vec<GridMeasurement> {
    let rows = creep_fastsim::study(grids, STUDY_REFERENCE);
    let cases = creep_fastsim::study_cases();
    let settings: Vec<Option<Settings>> = grids
        .iter()
        .map(|&g| Settings::default().with_grid(g).ok())
        .collect();
    let labels: Vec<String> = grids.iter().map(|&g| label(g)).collect();
    let labels: Vec<&str> = labels.iter().map(String::as_str).collect();
    let solves = (PASSES * cases.len()) as f64;
    let timings = timed_rounds(&labels, repeats, &mut progress, |i, _| {
        if let Some(settings) = &settings[i] {
            for _ in 0..PASSES {
                for (patch, creepages) in &cases {
                    std::hint::black_box(tangential::solve(
                        std::hint::black_box(patch),
                        creepages,
                        settings,
                    ));
                }
            }
        }
        Ok::<(), std::convert::Infallible>(())
    });
    let Ok(timings) = timings;
    rows.iter()
        .zip(timings)
        .map(|(row, t)| GridMeasurement {
            grid: row.grid,
            timing: Timing {
                median_s: t.median_s / solves,
                range_s: (t.range_s.0 / solves, t.range_s.1 / solves),
            },
            force_error: row.force_error,
            moment_error: row.moment_error,
        })
        .collect()
}

impl From<&GridMeasurement> for ChartPoint {
    fn from(m: &GridMeasurement) -> ChartPoint {
        ChartPoint {
            label: label(m.grid),
            median: 1e6 * m.timing.median_s,
            errors: [m.force_error, m.moment_error],
        }
    }
}

/// The chart points of a `fastsim_tradeoff.csv` as `wheelrail tradeoff` writes it: median
/// times in µs, errors `[force, moment]`.
///
/// # Errors
/// [`TradeoffCsvError`] naming `origin` when the text is no such table (a column missing,
/// a cell without a number where one is needed).
pub fn chart_points(text: &str, origin: &str) -> Result<Vec<ChartPoint>, TradeoffCsvError> {
    let csv = StudyCsv::parse(text, origin, "fastsim_tradeoff.csv")?;
    let (force, moment) = (csv.numbers("force_error")?, csv.numbers("moment_error")?);
    csv.points("grid", "median_us", |i| [force[i], moment[i]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_grid_is_timed_and_its_errors_are_the_studys() {
        let grids = [
            Grid {
                strips: 8,
                elements: 8,
            },
            DEFAULT_GRID,
        ];
        let mut calls = 0;
        let m = study(&grids, 1, |_, _, _| calls += 1);
        // A warm-up and one timed round of both grids, and the final call.
        assert_eq!(calls, 5);
        let rows = creep_fastsim::study(&grids, STUDY_REFERENCE);
        for (m, row) in m.iter().zip(&rows) {
            assert_eq!(m.grid, row.grid);
            assert_eq!(m.force_error.to_bits(), row.force_error.to_bits());
            assert_eq!(m.moment_error.to_bits(), row.moment_error.to_bits());
            let t = m.timing;
            assert!(t.range_s.0 > 0.0 && t.range_s.0 <= t.median_s && t.median_s <= t.range_s.1);
        }
    }
}
