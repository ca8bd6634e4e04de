//! Reports: turning results into bytes.
//!
//! Nothing here touches the file system: every function returns a `String` or `Vec<u8>` and the
//! caller (the pipeline's outer layer) writes the files. The module knows no physics; it offers
//!
//! * [`table`]: named numeric/text columns and their CSV form ([`Table`]);
//! * [`golden`]: column-by-column comparison of tables with stated tolerances ([`compare`]);
//! * [`chart`]: a declarative chart model rendered to SVG and PNG ([`render_svg`],
//!   [`render_png`]);
//! * [`html`]: a static, self-contained report page ([`render_html`]).

pub mod chart;
pub mod golden;
pub mod table;

pub use golden::{
    ColumnDiff, Comparison, FileOutcome, FilesComparison, Tolerance, TolerancePolicy, compare,
    compare_files,
};
pub use table::{Column, ColumnData, NumberFormat, Table, TableBuilder, TableError};
