//! The fleet's outputs as bytes: `fleet.csv` line by line (its `#` header, then one line
//! per row as rows complete), or its rows as one [`Table`](crate::Table)
//! ([`table`]: the same columns and numbers, for a library user); with the feature `cli`,
//! the fleet charts and the `index.html` page. The command line (`app`) writes them.
//!
//! One file each: the CSV's columns and lines (`schema`), the charts, the page.

mod charts;
mod page;
mod schema;

pub use charts::{conicity_against_nonlinearity, conicity_functions, flange_dimensions, histogram};
pub use schema::{columns, csv_header, csv_line, maintenance_status, table};

use super::{OutputFile, chart_files, figure_entry};
use crate::Error;
use wheelrail::fleet::{Fleet, Row};

/// Name and caption of the flange dimensions figure.
const FLANGE_FIGURE: (&str, &str) = (
    "fleet_flange_dimensions",
    "Each wheel's flange thickness Sd against its flange height Sh (EN 15313: Sh the flange tip above the taping-line point, Sd from the inner face to the flank 10 mm above it), the maintenance limits of the template's wheel as a dashed box ([limits], by default the TSI's for its diameter). Wheels that break a limit, qR included, are named with the limits they break (five: the one furthest beyond a limit of each kind of breach, then the furthest; the table below and fleet.csv's maintenance_status have all). Wheels whose dimensions are undefined are not drawn.",
);

/// Names and captions of the fleet figures.
const FIGURES: [(&str, &str); 3] = [
    (
        "fleet_conicity_histogram",
        "Distribution of the equivalent conicity tan γe(3 mm) over the fleet (bins of equal width; bins at or above the limit in the second colour, the limit [fleet] conicity_limit as a vertical line). Rows that failed or whose tan γe(3 mm) is undefined are not counted.",
    ),
    (
        "fleet_conicity_nonlinearity",
        "Each pair's tan γe(3 mm) against Polach's nonlinearity parameter NP = (tan γe(4 mm) - tan γe(2 mm)) / 2 mm: worn, conformal pairs sit at high conicity and negative NP. Pairs over the limit in the second colour; the worst pair (largest tan γe(3 mm)) named.",
    ),
    (
        "fleet_conicity_functions",
        "The equivalent conicity functions tan γe(ŷ) of all pairs overlaid (the scene's method), the worst pair highlighted and named, the limit dashed. A function ends where the motion would leave the swept Δr.",
    ),
];

/// The fleet's figures in the template's formats and `index.html`.
///
/// # Errors
/// [`Error::Chart`] when a figure cannot be rendered.
pub fn render(
    fleet: &Fleet,
    rows: &[Row],
    template_path: &str,
    reports: bool,
) -> Result<Vec<OutputFile>, Error> {
    let t = fleet.template();
    let limit = t.fleet().conicity_limit();
    let mut charts = vec![
        histogram(rows, limit),
        conicity_against_nonlinearity(rows, limit),
        conicity_functions(rows, limit, t.conicity().method().name()),
    ];
    let mut names = FIGURES.to_vec();
    if fleet.inputs().has_wheels() {
        let limits = wheelrail::maintenance::Limits::with_overrides(
            2.0 * t.nominal_radius_mm()[0],
            t.limits(),
        );
        names.insert(0, FLANGE_FIGURE);
        charts.insert(0, flange_dimensions(rows, fleet.inputs(), &limits));
    }
    let mut files = Vec::new();
    let mut entries = Vec::new();
    for ((name, caption), chart) in names.iter().zip(&charts) {
        files.extend(chart_files(name, chart, t.formats())?);
        entries.push(figure_entry(name, (*caption).to_string(), t.formats()));
    }
    files.push(OutputFile {
        name: "index.html".into(),
        bytes: crate::render_html(&page::page(fleet, rows, template_path, reports, entries))
            .into_bytes(),
    });
    Ok(files)
}
