//! # wheelrail-report
//!
//! wheelrail's results as reports: the bytes of tables, charts and pages. Nothing here
//! touches the file system: every function returns a `String` or `Vec<u8>` and the caller
//! (the command line) writes the files. Generic parts that know no physics:
//!
//! * [`table`]: named numeric/text columns and their CSV form ([`Table`]);
//! * `golden`: column-by-column comparison of tables with stated tolerances (`compare`,
//!   `compare_files`);
//! * `chart`: a declarative chart model rendered to SVG and PNG (`render_svg`,
//!   `render_png`);
//! * `html`: a static, self-contained report page (`render_html`).
//!
//! and what wheelrail's results become:
//!
//! * [`outputs`]: every stage's tables (named as their CSV files), figures and the report
//!   page of a scene; a fleet's rows, charts and page;
//! * [`tradeoff`]: run time against error of numerical settings.
//!
//! # Examples
//!
//! ```
//! use wheelrail_report::Table;
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
//! use wheelrail_report::{Chart, Figure, Series, render_svg};
//! let points = y.into_iter().zip(dr).collect();
//! let chart = Chart::new("Δr", "y_ws (mm)", "Δr (mm)").series(Series::line("rigid", points));
//! let svg = render_svg(&Figure::single(chart))?;
//! assert!(svg.starts_with("<svg"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod chart;
mod error;
pub mod golden;
pub mod html;
pub mod outputs;
pub mod table;
pub mod tradeoff;

pub use chart::{
    Chart, ChartError, Figure, HBand, LegendPosition, PointLabel, Series, SeriesStyle, VLine,
    render_png, render_svg,
};
pub use error::Error;
pub use golden::{
    ColumnDiff, Comparison, FileOutcome, FilesComparison, Tolerance, TolerancePolicy, compare,
    compare_files,
};
pub use html::{DataTable, FigureEntry, ReportPage, TableEntry, render_html};
pub use table::{Column, ColumnData, NumberFormat, Table, TableBuilder, TableError};
