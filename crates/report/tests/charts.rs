//! Chart layout against the pixels actually drawn: every figure of every committed report
//! scene (`reports/*/scene.toml`) is rendered once without its legends and labels (laid out
//! but not drawn) and each legend box and each label box (of marker lines and points) must
//! then hold only background: white or the grey of the grid. Whatever a legend or a label
//! would cover (a curve, a marker, a marker line, an off-chart mark) shows in those pixels,
//! whichever code decided the placement; labels and legends are checked against each
//! other by their boxes.

use std::path::{Path, PathBuf};

use wheelrail::{pipeline, scene::Scene};
use wheelrail_report::chart::{Chart, Figure, LegendPosition, PxBox, Series, layout, render_rgb};
use wheelrail_report::outputs;

/// The lightest ink the charts draw that is not background: the grid is 0xD0 (major) and
/// 0xEE (minor) grey on white, anything else (data colours, black text and frame, the 0x44
/// annotations, their anti-aliased edges darker than the grid) differs from grey or is darker.
const GRID_GREY: u8 = 0xD0;

fn is_background(px: &[u8]) -> bool {
    px[0] == px[1] && px[1] == px[2] && px[0] >= GRID_GREY
}

/// Pixels inside `b` (its one-pixel border excluded: anti-aliased edges of the box's
/// neighbours may touch it) that are not background.
fn ink_inside(pixels: &[u8], width: u32, b: PxBox) -> Vec<(i32, i32)> {
    let mut ink = Vec::new();
    for y in b.top + 1..b.bottom {
        for x in b.left + 1..b.right {
            let i = (y as usize * width as usize + x as usize) * 3;
            if !is_background(&pixels[i..i + 3]) {
                ink.push((x, y));
            }
        }
    }
    ink
}

/// Whether two pixel boxes share a pixel.
fn overlap(a: PxBox, b: PxBox) -> bool {
    a.left <= b.right && b.left <= a.right && a.top <= b.bottom && b.top <= a.bottom
}

/// Legends and labels of `figure` that cover ink or each other, as readable messages.
fn covered_legends(figure: &Figure) -> Vec<String> {
    let bare = render_rgb(figure, false).unwrap();
    let mut problems = Vec::new();
    for (i, panel) in layout(figure).unwrap().iter().enumerate() {
        let boxes = panel
            .legend
            .iter()
            .map(|b| ("legend", *b))
            .chain(panel.labels.iter().map(|b| ("label", *b)));
        for (k, (what, b)) in boxes.clone().enumerate() {
            assert!(b.left >= 0 && b.top >= 0, "{b:?}");
            assert!(
                b.right < figure.width as i32 && b.bottom < figure.height as i32,
                "{b:?}"
            );
            let ink = ink_inside(&bare, figure.width, b);
            if !ink.is_empty() {
                problems.push(format!(
                    "panel {i} {what} {b:?} covers {} drawn pixels, first {:?}",
                    ink.len(),
                    ink[0]
                ));
            }
            for (other, c) in boxes.clone().skip(k + 1) {
                if overlap(b, c) {
                    problems.push(format!("panel {i} {what} {b:?} overlaps {other} {c:?}"));
                }
            }
        }
    }
    problems
}

fn report_scenes() -> Vec<PathBuf> {
    let reports = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).join("reports");
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(&reports)
        .unwrap()
        .map(|e| e.unwrap().path().join("scene.toml"))
        .filter(|p| p.is_file())
        .collect();
    scenes.sort();
    scenes
}

#[test]
fn no_legend_or_label_of_a_committed_report_covers_data_or_labels() {
    let scenes = report_scenes();
    assert!(scenes.len() >= 7, "{scenes:?}");
    let (mut legends, mut labels) = (0, 0);
    let mut problems = Vec::new();
    for path in &scenes {
        let scene = Scene::load(path).unwrap();
        let results = pipeline::run(&scene).unwrap();
        for &fig in scene.figures() {
            let figure = outputs::figure(fig, &results).unwrap();
            for panel in layout(&figure).unwrap() {
                legends += usize::from(panel.legend.is_some());
                labels += panel.labels.len();
            }
            for p in covered_legends(&figure) {
                problems.push(format!("{} {}: {p}", path.display(), fig.name()));
            }
        }
    }
    // The committed tradeoff charts, drawn from their tables: a numbered label per point.
    for study in outputs::Study::ALL {
        let csv = root_file(&format!("reports/paper/{}.csv", study.name()));
        let points = study.points(&csv, study.name()).unwrap();
        let chart = study.chart(&points);
        for panel in layout(&chart).unwrap() {
            assert_eq!(panel.labels.len(), points.len(), "a label per point");
            labels += panel.labels.len();
        }
        problems.extend(
            covered_legends(&chart)
                .into_iter()
                .map(|p| format!("{}: {p}", study.name())),
        );
    }
    assert!(legends >= 50, "only {legends} legends checked");
    assert!(labels >= 60, "only {labels} labels checked");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

fn root_file(path: &str) -> String {
    std::fs::read_to_string(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).join(path))
        .unwrap()
}

/// Labels of points find a free place near their point, and those of marker lines beside
/// their line, where curves pass right where the first choice would put them: each label
/// covers nothing, and the check sees ink where a label is drawn.
#[test]
fn labels_move_off_curves_and_the_check_sees_them() {
    // A curve through the top of the marker line (where its label went before) and a
    // cluster of points on one row.
    let curve: Vec<(f64, f64)> = (0..=200)
        .map(|i| {
            let x = f64::from(i) / 20.0;
            (x, 9.6 - 0.02 * (x - 3.0).powi(2))
        })
        .collect();
    let cluster: Vec<(f64, f64)> = (0..8).map(|i| (6.0 + 0.08 * f64::from(i), 2.0)).collect();
    let mut chart = Chart::new("t", "x (mm)", "y (mm)")
        .series(Series::line("curve", curve))
        .series(Series::markers("cluster", cluster.clone()))
        .y_range(0.0, 10.0)
        .vline(3.0, "marker line");
    for (i, &(x, y)) in cluster.iter().enumerate() {
        chart = chart.label(x, y, format!("{}", i + 1));
    }
    let figure = Figure::single(chart);
    let panel = &layout(&figure).unwrap()[0];
    assert_eq!(panel.labels.len(), 9);
    assert_eq!(covered_legends(&figure), Vec::<String>::new());
    let drawn = render_rgb(&figure, true).unwrap();
    for b in &panel.labels {
        assert!(!ink_inside(&drawn, figure.width, *b).is_empty(), "{b:?}");
    }
}

/// The check sees ink: drawn with its legends, a figure's legend boxes are not blank.
#[test]
fn the_pixel_check_sees_a_drawn_legend() {
    let chart = Chart::new("t", "x (mm)", "y (mm)")
        .series(Series::line("a curve", vec![(0.0, 0.0), (1.0, 1.0)]));
    let figure = Figure::single(chart);
    let drawn = render_rgb(&figure, true).unwrap();
    let b = layout(&figure).unwrap()[0].legend.unwrap();
    assert!(ink_inside(&drawn, figure.width, b).len() > 100);
}

/// Data in every part of the plot leaves no free place inside: the legend goes outside the
/// plot, and still covers nothing. A grid of markers 40 px apart: no legend fits between them.
#[test]
fn a_full_plot_puts_the_legend_outside() {
    let points: Vec<(f64, f64)> = (0..=25)
        .flat_map(|i| (0..=16).map(move |j| (f64::from(i), f64::from(j))))
        .collect();
    for position in [LegendPosition::Auto, LegendPosition::LowerLeft] {
        let chart = Chart::new("full", "x (mm)", "y (mm)")
            .series(Series::markers("everywhere", points.clone()))
            .legend(position);
        let figure = Figure::single(chart);
        let panel = &layout(&figure).unwrap()[0];
        assert!(panel.legend_outside, "{panel:?}");
        let (b, plot) = (panel.legend.unwrap(), panel.plot);
        assert!(b.left > plot.right || b.top > plot.bottom, "{panel:?}");
        assert_eq!(covered_legends(&figure), Vec::<String>::new());
    }
}

/// A preferred corner that holds data is not used: the legend moves to a free place.
#[test]
fn a_requested_corner_with_data_is_left_free() {
    let line: Vec<(f64, f64)> = (0..=100).map(|i| (f64::from(i), f64::from(i))).collect();
    let chart = Chart::new("diagonal", "x (mm)", "y (mm)")
        .series(Series::line("y = x", line))
        .legend(LegendPosition::UpperRight);
    let figure = Figure::single(chart);
    let panel = &layout(&figure).unwrap()[0];
    let b = panel.legend.unwrap();
    assert!(!panel.legend_outside);
    // The diagonal runs through the upper right corner: the legend sits elsewhere.
    assert!(
        b.right < panel.plot.right - 20 || b.top > panel.plot.top + 20,
        "{panel:?}"
    );
    assert_eq!(covered_legends(&figure), Vec::<String>::new());
}

/// One extreme sample does not set the range: it is left off the chart and counted.
#[test]
fn one_extreme_sample_does_not_set_the_range() {
    let mut points: Vec<(f64, f64)> = (0..200).map(|i| (f64::from(i), f64::from(i % 7))).collect();
    points[0].1 = -1e6;
    let figure =
        Figure::single(Chart::new("t", "x (mm)", "y (mm)").series(Series::line("s", points)));
    let svg = wheelrail_report::render_svg(&figure).unwrap();
    let panel = &layout(&figure).unwrap()[0];
    assert_eq!(panel.off_chart, 1, "{panel:?}");
    assert!(
        svg.contains("off the chart: ▼ down to -1e6"),
        "the legend says how far"
    );
    assert!(
        !svg.contains("-1e6<") && !svg.contains(">-1e6"),
        "no tick label at -1e6"
    );
}

/// The fleet report's charts (issue 14), on 60 generated profiles and the measured CONTACT
/// wheels with a limit: no legend covers data, the limit line or its label.
#[test]
fn no_legend_of_the_fleet_charts_covers_data_or_labels() {
    use wheelrail::fleet::{self, Fleet, Inputs, synthetic};
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let dir = root.join("target/test-scratch/charts-fleet");
    std::fs::create_dir_all(&dir).unwrap();
    let mut files: Vec<PathBuf> = (0..60)
        .map(|i| {
            let p = dir.join(format!("worn_{i:04}.csv"));
            std::fs::write(&p, synthetic::csv_text(14, i).0).unwrap();
            p
        })
        .collect();
    for name in ["Car7216_0001r.whl", "Car7358_0001r.whl", "avg_wheel.whl"] {
        files.push(root.join("tests/data/profiles").join(name));
    }
    let template = Scene::load(&root.join("reports/fleet/scene.toml")).unwrap();
    let limit = template.fleet().conicity_limit();
    assert!(limit.is_some(), "the default fleet scene sets a limit");
    let items = fleet::items_of_files(&files, false);
    let fleet = Fleet::new(template, Inputs::Wheels, &items, false).unwrap();
    let rows: Vec<_> = items.iter().map(|i| fleet.assess(i)).collect();
    let figures = [
        outputs::fleet::histogram(&rows, limit),
        outputs::fleet::conicity_against_nonlinearity(&rows, limit),
        outputs::fleet::conicity_functions(&rows, limit, "klingel"),
    ];
    let mut problems = Vec::new();
    for (i, figure) in figures.iter().enumerate() {
        assert!(layout(figure).unwrap()[0].legend.is_some(), "figure {i}");
        problems.extend(
            covered_legends(figure)
                .into_iter()
                .map(|p| format!("fleet figure {i}: {p}")),
        );
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
