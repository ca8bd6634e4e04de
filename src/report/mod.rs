//! Reports: turning results into bytes.
//!
//! Nothing here touches the file system: every function returns a `String` or `Vec<u8>` and the
//! caller (the pipeline's outer layer) writes the files. The module knows no physics; it offers
//!
//! * [`table`]: named numeric/text columns and their CSV form ([`Table`]);
//!
//! and with the feature `cli` (default):
//!
//! * `golden`: column-by-column comparison of tables with stated tolerances (`compare`,
//!   `compare_files`);
//! * `chart`: a declarative chart model rendered to SVG and PNG (`render_svg`,
//!   `render_png`);
//! * `html`: a static, self-contained report page (`render_html`).
//!
//! # Examples
//!
//! ```
//! use wheelrail::report::Table;
//!
//! let y = vec![0.0, 1.0, 2.0];
//! let dr = vec![0.0, 0.06, f64::NAN];
//! let table = Table::builder()
//!     .comment("delta_r_mm = r_left - r_right")
//!     .numeric("y_ws_mm", y.clone())
//!     .numeric("delta_r_mm", dr.clone())
//!     .text("status", ["ok", "ok", "no contact"])
//!     .build()?;
//! let csv = table.to_csv();
//! assert!(csv.contains("2,NaN,no contact"));
//!
//! # #[cfg(feature = "cli")] {
//! // Charts come with the `cli` feature (plotters).
//! use wheelrail::report::{Chart, Figure, Series, render_svg};
//! let points = y.into_iter().zip(dr).collect();
//! let chart = Chart::new("Δr", "y_ws (mm)", "Δr (mm)").series(Series::line("rigid", points));
//! let svg = render_svg(&Figure::single(chart))?;
//! assert!(svg.starts_with("<svg"));
//! # }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#[cfg(feature = "cli")]
pub mod chart;
#[cfg(feature = "cli")]
pub mod golden;
#[cfg(feature = "cli")]
pub mod html;
pub mod table;

#[cfg(feature = "cli")]
pub use chart::{
    Chart, ChartError, Figure, HBand, LegendPosition, PointLabel, Series, SeriesStyle, VLine,
    render_png, render_svg,
};
#[cfg(feature = "cli")]
pub use golden::{
    ColumnDiff, Comparison, FileOutcome, FilesComparison, Tolerance, TolerancePolicy, compare,
    compare_files,
};
#[cfg(feature = "cli")]
pub use html::{DataTable, FigureEntry, ReportPage, TableEntry, render_html};
pub use table::{Column, ColumnData, NumberFormat, Table, TableBuilder, TableError};
