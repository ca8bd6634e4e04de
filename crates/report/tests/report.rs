//! Integration tests of the report writers: CSV tables, golden comparison, charts and HTML.
//!
//! `cargo test --test report -- --ignored preview` writes example figures to
//! `target/tmp/report-preview/` for a person to look at; the other tests assert properties
//! (round trips, diff contents, determinism), never pixels.

use wheelrail_report::chart::{
    Chart, ChartError, Figure, LegendPosition, Series, render_png, render_svg,
};
use wheelrail_report::golden::{
    ColumnDiff, FileOutcome, Tolerance, TolerancePolicy, compare, compare_files,
};
use wheelrail_report::html::{FigureEntry, ReportPage, TableEntry, render_html};
use wheelrail_report::table::{ColumnData, NumberFormat, Table};

// ---------------------------------------------------------------- tables

fn contact_table() -> Table {
    Table::builder()
        .comment("frame: track, y positive to the left, z up")
        .comment("units: mm, rad")
        .numeric("y_ws_mm", vec![-1.0, 0.0, 0.5, 6.5])
        .numeric("left_gamma_rad", vec![0.0249, 0.0313, 0.0341, f64::NAN])
        .numeric("roll_rad", vec![-1.2e-5, 0.0, 6.1e-6, f64::INFINITY])
        .text(
            "status",
            ["ok", "ok", "ok, \"quoted\", with comma", "no contact"],
        )
        .build()
        .expect("valid table")
}

#[test]
fn csv_round_trip_keeps_numbers_bits_nan_text_and_comments() {
    let table = contact_table();
    let text = table.to_csv();
    let back = Table::parse_csv(&text).unwrap();
    assert_eq!(back.comments(), table.comments());
    assert_eq!(
        back.column_names().collect::<Vec<_>>(),
        table.column_names().collect::<Vec<_>>()
    );
    for (a, b) in table.columns().iter().zip(back.columns()) {
        match (&a.data, &b.data) {
            (ColumnData::Numeric(x), ColumnData::Numeric(y)) => {
                let bits = |v: &[f64]| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
                // NaN payloads are not preserved by text; compare NaN-ness, other values bitwise.
                assert_eq!(x.len(), y.len());
                for (p, q) in x.iter().zip(y) {
                    if p.is_nan() {
                        assert!(q.is_nan());
                    } else {
                        assert_eq!(bits(&[*p]), bits(&[*q]), "{} {p} vs {q}", a.name);
                    }
                }
            }
            (ColumnData::Text(x), ColumnData::Text(y)) => assert_eq!(x, y),
            _ => panic!("column {} changed kind", a.name),
        }
    }
    // The written text is stable: writing the parsed table gives the same bytes.
    assert_eq!(back.to_csv(), text);
}

#[test]
fn csv_layout_is_as_documented() {
    let text = contact_table().to_csv();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "# frame: track, y positive to the left, z up");
    assert_eq!(lines[2], "y_ws_mm,left_gamma_rad,roll_rad,status");
    assert_eq!(lines[3], "-1,0.0249,-1.2e-5,ok");
    assert_eq!(
        lines[5],
        "0.5,0.0341,6.1e-6,\"ok, \"\"quoted\"\", with comma\""
    );
    assert_eq!(lines[6], "6.5,NaN,inf,no contact");
}

#[test]
fn significant_digit_format_rounds() {
    let t = Table::builder()
        .numeric("x_mm", vec![760.530_000_1, f64::NAN])
        .build()
        .unwrap();
    assert_eq!(
        t.to_csv_with(NumberFormat::Significant(6)),
        "x_mm\n7.60530e2\nNaN\n"
    );
}

#[test]
fn column_of_nan_and_numbers_is_numeric_and_mixed_is_text() {
    let t = Table::parse_csv("a_mm,b,c\nNaN,1,x\n2.5,NaN,3\n").unwrap();
    assert!(t.numeric("a_mm").is_some());
    assert!(t.numeric("b").is_some());
    assert_eq!(t.text("c").unwrap(), ["x", "3"]);
}

// ---------------------------------------------------------------- golden comparison

fn policy() -> TolerancePolicy {
    TolerancePolicy::new(Tolerance::rel(1e-9))
        .suffix("_mm", Tolerance::abs(1e-6))
        .suffix("_rad", Tolerance::abs(1e-9))
        .key_column("y_ws_mm")
}

fn with_column(table: &Table, name: &str, f: impl Fn(usize, f64) -> f64) -> Table {
    let mut b = Table::builder();
    for c in table.comments() {
        b = b.comment(c);
    }
    for col in table.columns() {
        b = match &col.data {
            ColumnData::Numeric(v) if col.name == name => b.numeric(
                &col.name,
                v.iter()
                    .enumerate()
                    .map(|(i, &x)| f(i, x))
                    .collect::<Vec<_>>(),
            ),
            ColumnData::Numeric(v) => b.numeric(&col.name, v.clone()),
            ColumnData::Text(v) => b.text(&col.name, v.clone()),
        };
    }
    b.build().unwrap()
}

#[test]
fn golden_identical_tables_match_and_comments_are_ignored() {
    let golden = contact_table();
    let mut actual = Table::parse_csv(&golden.to_csv()).unwrap();
    actual.add_comment("generated 2030-01-01 by someone else");
    let c = compare(&golden, &actual, &policy());
    assert!(c.is_match(), "{c}");
}

#[test]
fn golden_perturbation_within_tolerance_passes_and_beyond_fails() {
    let golden = contact_table();
    // left_gamma_rad: abs 1e-9 by the `_rad` suffix rule.
    let within = with_column(&golden, "left_gamma_rad", |_, x| x + 0.9e-9);
    let beyond = with_column(&golden, "left_gamma_rad", |i, x| {
        if i == 2 { x + 1.1e-9 } else { x }
    });
    assert!(compare(&golden, &within, &policy()).is_match());
    let c = compare(&golden, &beyond, &policy());
    assert!(!c.is_match());
    let text = c.to_string();
    assert!(
        text.contains("left_gamma_rad: 1 of 4 rows outside tolerance"),
        "{text}"
    );
    assert!(text.contains("worst row 2 (y_ws_mm = 0.5)"), "{text}");
}

#[test]
fn golden_reports_missing_and_extra_columns() {
    let golden = contact_table();
    let actual = Table::builder()
        .numeric("y_ws_mm", vec![-1.0, 0.0, 0.5, 6.5])
        .numeric("left_gamma_rad", vec![0.0249, 0.0313, 0.0341, f64::NAN])
        .numeric("roll_rad", vec![-1.2e-5, 0.0, 6.1e-6, f64::INFINITY])
        .numeric("z_ws_mm", vec![0.0; 4])
        .build()
        .unwrap();
    let c = compare(&golden, &actual, &policy());
    assert_eq!(c.missing_columns, ["status"]);
    assert_eq!(c.extra_columns, ["z_ws_mm"]);
    let text = c.to_string();
    assert!(text.contains("missing columns: status"), "{text}");
    assert!(text.contains("extra columns: z_ws_mm"), "{text}");
}

#[test]
fn golden_reports_row_count_and_still_compares_common_rows() {
    let golden = Table::builder()
        .numeric("x_mm", vec![1.0, 2.0, 3.0])
        .build()
        .unwrap();
    let actual = Table::builder()
        .numeric("x_mm", vec![1.0, 2.5])
        .build()
        .unwrap();
    let c = compare(&golden, &actual, &policy());
    assert_eq!(c.row_counts, Some((3, 2)));
    assert_eq!(c.columns.len(), 1, "row 1 differs in the common rows");
    assert!(c.to_string().contains("row count: expected 3, actual 2"));
}

#[test]
fn golden_reports_text_mismatch() {
    let golden = contact_table();
    let actual = Table::parse_csv(&golden.to_csv().replace("no contact", "not converged")).unwrap();
    let c = compare(&golden, &actual, &policy());
    assert!(matches!(
        c.columns[0].1,
        ColumnDiff::Text { failing: 1, .. }
    ));
    let text = c.to_string();
    assert!(
        text.contains(r#"row 3: expected "no contact", actual "not converged""#),
        "{text}"
    );
}

#[test]
fn golden_nan_must_stay_nan_and_number_must_not_become_nan() {
    let golden = contact_table();
    let filled = with_column(
        &golden,
        "left_gamma_rad",
        |_, x| if x.is_nan() { 1.2 } else { x },
    );
    let lost = with_column(
        &golden,
        "left_gamma_rad",
        |i, x| if i == 0 { f64::NAN } else { x },
    );
    for actual in [filled, lost] {
        let c = compare(&golden, &actual, &policy());
        assert!(!c.is_match());
        assert!(c.to_string().contains("|diff| NaN"), "{c}");
    }
}

#[test]
fn golden_kind_mismatch_is_reported() {
    let golden = Table::parse_csv("status\nok\n").unwrap();
    let actual = Table::parse_csv("status\n1\n").unwrap();
    let c = compare(&golden, &actual, &policy());
    assert!(
        c.to_string()
            .contains("status: expected a text column, found numeric"),
        "{c}"
    );
}

#[test]
fn golden_files_outcomes() {
    let golden = contact_table().to_csv();
    let changed = golden.replace("0.0341", "0.0342");
    let files = [
        ("same.csv", Some(golden.as_str()), Some(golden.as_str())),
        ("changed.csv", Some(golden.as_str()), Some(changed.as_str())),
        ("new.csv", None, Some(golden.as_str())),
        ("gone.csv", Some(golden.as_str()), None),
        ("broken.csv", Some(golden.as_str()), Some("a,b\n1\n")),
    ];
    let result = compare_files(&files, &policy());
    assert!(!result.is_match());
    assert_eq!(
        result.failing().collect::<Vec<_>>(),
        ["changed.csv", "new.csv", "gone.csv", "broken.csv"]
    );
    assert_eq!(result.files[0].1, FileOutcome::Match);
    assert!(matches!(result.files[4].1, FileOutcome::InvalidActual(_)));
    let text = result.to_string();
    assert!(text.starts_with("4 of 5 files differ"), "{text}");
    assert!(text.contains("--- changed.csv"), "{text}");
}

// ---------------------------------------------------------------- charts
/// Smooth synthetic curves shaped like the paper's Fig. 2 (a tread region, then a jump to the
/// flange at y_ws = 6.5 mm); only their shape matters here.
fn fake_delta_r(y: f64) -> f64 {
    if y < 6.5 {
        0.06 * y + 0.004 * y.powi(3)
    } else {
        6.0 + 1.5 * (y - 6.5)
    }
}

fn sample_chart() -> Chart {
    let ys: Vec<f64> = (-100..=100).map(|i| f64::from(i) * 0.1).collect();
    let rigid: Vec<(f64, f64)> = ys
        .iter()
        .map(|&y| {
            // A NaN between the two branches makes the jump a gap.
            if (6.5..6.6).contains(&y) {
                (y, f64::NAN)
            } else {
                (y, fake_delta_r(y.abs()) * y.signum())
            }
        })
        .collect();
    let quasi: Vec<(f64, f64)> = ys
        .iter()
        .map(|&y| (y, 0.9 * fake_delta_r(y.abs()) * y.signum()))
        .collect();
    Chart::new(
        "Rolling radius difference",
        "lateral shift y_ws (mm)",
        "Δr = r_left − r_right (mm)",
    )
    .series(Series::line("rigid", rigid))
    .series(Series::line("quasi-elastic, ε = 0.1 mm", quasi).dashed())
    .vline(6.5, "flange contact (left)")
    .vline(-6.5, "flange contact (right)")
}

#[test]
fn png_is_deterministic_and_plausible() {
    let figure = Figure::single(sample_chart());
    let a = render_png(&figure).unwrap();
    let b = render_png(&figure).unwrap();
    assert_eq!(a, b, "same figure, same bytes");
    assert_eq!(&a[..8], b"\x89PNG\r\n\x1a\n");
    // IHDR: width and height as big-endian u32 at bytes 16..24.
    assert_eq!(u32::from_be_bytes(a[16..20].try_into().unwrap()), 1000);
    assert_eq!(u32::from_be_bytes(a[20..24].try_into().unwrap()), 700);
    // A drawn chart compresses to tens of kB; a blank or broken one would be far smaller.
    assert!((10_000..2_000_000).contains(&a.len()), "{} bytes", a.len());
    let blank = render_png(&Figure::single(Chart::default())).unwrap();
    assert!(blank.len() < a.len());
}

#[test]
fn svg_contains_title_axis_labels_legend_and_escapes_text() {
    let chart = sample_chart().series(Series::line("a < b & c", vec![(0.0, 0.0), (1.0, 1.0)]));
    let svg = render_svg(&Figure::grid("Fig. 2", vec![chart], 1)).unwrap();
    for text in [
        "Fig. 2",
        "Rolling radius difference",
        "lateral shift y_ws (mm)",
        "Δr = r_left − r_right (mm)",
        "quasi-elastic, ε = 0.1 mm",
        "flange contact (left)",
        "a &lt; b &amp; c",
    ] {
        assert!(svg.contains(text), "{text} missing");
    }
    assert!(svg.contains("DejaVu Sans"));
}

#[test]
fn nan_gaps_log_axes_empty_and_degenerate_data_render() {
    let figure = edge_case_figure();
    render_svg(&figure).unwrap();
    render_png(&figure).unwrap();
}

fn edge_case_figure() -> Figure {
    let nan = f64::NAN;
    let charts = vec![
        Chart::new("gaps", "x (mm)", "y (mm)").series(Series::line(
            "gappy",
            vec![
                (0.0, 1.0),
                (nan, 2.0),
                (2.0, nan),
                (3.0, 1.0),
                (4.0, 2.0),
                (nan, nan),
                (5.0, 0.0),
            ],
        )),
        Chart::new("log", "x (-)", "y (-)")
            .series(Series::line_with_markers(
                "mixed signs",
                vec![
                    (-1.0, 1.0),
                    (0.0, 10.0),
                    (1.0, 100.0),
                    (10.0, -5.0),
                    (100.0, 1e4),
                ],
            ))
            .x_log()
            .y_log(),
        Chart::new("log, nothing positive", "x (-)", "y (-)")
            .series(Series::markers("negative", vec![(-1.0, -1.0)]))
            .y_log(),
        Chart::new("empty", "x", "y").series(Series::line("none", vec![])),
        Chart::new("all NaN", "x", "y").series(Series::markers("nan", vec![(nan, nan); 3])),
        Chart::new("one point", "x", "y").series(Series::markers("p", vec![(2.0, 3.0)])),
        Chart::new("zero range", "x", "y")
            .series(Series::line("flat", vec![(0.0, 0.0), (0.0, 0.0)])),
        Chart::new("huge", "x", "y").series(Series::line("big", vec![(0.0, -1e300), (1.0, 1e300)])),
        Chart::new("tiny", "x", "y")
            .series(Series::line("small", vec![(0.0, 1e-12), (1e-9, 3e-12)])),
        Chart::new("clipped", "x", "y")
            .series(Series::line(
                "out",
                vec![(-10.0, -10.0), (10.0, 10.0), (20.0, -5.0)],
            ))
            .series(Series::segments(
                "links",
                &[[(-5.0, 0.0), (5.0, 0.0)], [(nan, 0.0), (1.0, 1.0)]],
            ))
            .x_range(0.0, 5.0)
            .y_range(0.0, 5.0)
            .vline(100.0, "outside"),
        Chart::new("equal, log ignored", "x", "y")
            .series(Series::line("l", vec![(1.0, 1.0), (10.0, 2.0)]))
            .equal_aspect()
            .x_log(),
        Chart::new("all styles and colours", "x", "y")
            .series(Series::line("s", vec![]))
            .legend(LegendPosition::Hidden),
    ];
    let mut charts = charts;
    for i in 0..9 {
        let f = f64::from(i);
        charts.last_mut().unwrap().series.push(
            Series::line_with_markers(format!("c{i}"), vec![(f, f), (f + 1.0, f)])
                .color(i as usize),
        );
    }
    Figure::grid("edge cases", charts, 4)
}

#[test]
fn invalid_figures_are_errors_not_panics() {
    let chart = || Chart::new("t", "x", "y");
    let bad_range = Figure::single(chart().x_range(1.0, 1.0));
    assert!(matches!(
        render_png(&bad_range),
        Err(ChartError::InvalidRange { panel: 0, .. })
    ));
    let bad_log = Figure::single(chart().y_log().y_range(0.0, 10.0));
    assert!(matches!(
        render_svg(&bad_log),
        Err(ChartError::InvalidRange { .. })
    ));
    let nan_range = Figure::single(chart().x_range(f64::NAN, 1.0));
    assert!(render_svg(&nan_range).is_err());
    let zero = Figure::single(chart()).size(0, 0);
    assert!(matches!(
        render_png(&zero),
        Err(ChartError::InvalidSize { .. })
    ));
    let mut no_columns = Figure::single(chart());
    no_columns.columns = 0;
    assert_eq!(render_svg(&no_columns), Err(ChartError::ZeroColumns));
    // No panels at all: just the title.
    let empty = Figure::grid("nothing yet", vec![], 2);
    assert!(render_svg(&empty).unwrap().contains("nothing yet"));
}

// ---------------------------------------------------------------- HTML

#[test]
fn html_page_escapes_everything_and_links_files() {
    let page = ReportPage {
        title: "Report <script>alert(1)</script>".into(),
        key_results: vec![[
            "tan_gamma_e_3mm".into(),
            "0.1771".into(),
            "1".into(),
            "at amplitude 3 mm <Annex B> & more".into(),
        ]],
        summary: vec!["Jump at y_ws > 6.5 mm & more".into()],
        parameters: vec![
            ("gauge_mm".into(), "1435".into()),
            ("profile".into(), "S1002 \"new\"".into()),
        ],
        provenance: vec![("wheelrail".into(), "0.1.0".into())],
        figures: vec![FigureEntry {
            name: "Fig. 2".into(),
            caption: "Contact angle 'left' & right".into(),
            svg: "fig 2.svg".into(),
            png: "fig2.png\" onerror=\"x".into(),
        }],
        tables: vec![TableEntry {
            name: "rigid".into(),
            file: "rigid.csv".into(),
            description: "contact points <per y_ws>".into(),
        }],
        data_tables: vec![wheelrail_report::DataTable {
            title: "Pairs over <limit>".into(),
            header: vec!["id & name".into()],
            rows: vec![vec!["<b>ws1</b>".into()]],
        }],
        notes: vec!["3 points did not converge".into()],
    };
    let html = render_html(&page);
    assert!(html.contains("Pairs over &lt;limit&gt;</h2>"));
    assert!(html.contains("<th>id &amp; name</th>"));
    assert!(html.contains("&lt;b&gt;ws1&lt;/b&gt;"));
    assert!(!html.contains("<script>"));
    assert!(html.contains("Report &lt;script&gt;alert(1)&lt;/script&gt;"));
    assert!(html.contains("Jump at y_ws &gt; 6.5 mm &amp; more"));
    assert!(html.contains("S1002 &quot;new&quot;"));
    assert!(html.contains("Contact angle &#39;left&#39; &amp; right"));
    assert!(html.contains(r#"<img src="fig%202.svg""#));
    assert!(html.contains(r#"href="fig2.png%22%20onerror%3D%22x""#));
    assert!(html.contains(r#"<a href="rigid.csv">rigid.csv</a>"#));
    assert!(html.contains("contact points &lt;per y_ws&gt;"));
    assert!(html.contains("3 points did not converge"));
    // Key results come first, before the summary, escaped.
    let key = html.find("id=\"key-results\"").expect("key results table");
    assert!(key < html.find("Jump at y_ws").unwrap());
    assert!(html.contains("<td class=\"v\">0.1771</td>"));
    assert!(html.contains("at amplitude 3 mm &lt;Annex B&gt; &amp; more"));
    // Self-contained: no scripts, no external resources.
    assert!(!html.contains("<script") && !html.contains("http://") && !html.contains("https://"));
    assert!(html.starts_with("<!DOCTYPE html>") && html.ends_with("</html>\n"));
}

#[test]
#[ignore = "writes preview images to target/tmp/report-preview for a person to look at"]
fn preview_figures() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-preview");
    std::fs::create_dir_all(&dir).unwrap();
    let single = Figure::single(sample_chart());
    std::fs::write(dir.join("single.png"), render_png(&single).unwrap()).unwrap();
    std::fs::write(dir.join("single.svg"), render_svg(&single).unwrap()).unwrap();

    // Profile drawing in mm with equal aspect and contact-point links.
    let wheel: Vec<(f64, f64)> = (-40..=70)
        .map(|i| {
            let s = f64::from(i);
            let f = if s < -10.0 {
                28.0 - 0.02 * (s + 40.0).powi(2)
            } else {
                -0.025 * s
            };
            (s, 12.0 + f.max(-0.025 * s))
        })
        .collect();
    let rail: Vec<(f64, f64)> = (-36..=36)
        .map(|i| {
            let y = f64::from(i);
            (y, -(y * y) / 300.0)
        })
        .collect();
    let profile = Chart::new(
        "Wheel and rail profiles",
        "lateral y (mm)",
        "vertical z (mm)",
    )
    .series(Series::line("wheel S1002", wheel))
    .series(Series::line("rail UIC60 1:40", rail))
    .series(
        Series::segments(
            "contact",
            &[[(-2.0, 12.05), (-2.0, -0.01)], [(20.0, 11.5), (20.0, -1.3)]],
        )
        .color(6),
    )
    .equal_aspect()
    .legend(LegendPosition::Auto);
    let fig = Figure::single(profile);
    std::fs::write(dir.join("profile.png"), render_png(&fig).unwrap()).unwrap();

    // Six panels as in Fig. 2, including a log axis, markers, an empty and an all-NaN series.
    let ys: Vec<f64> = (0..=100).map(|i| f64::from(i) * 0.1).collect();
    let gamma = |y: f64| if y < 6.5 { 0.03 + 0.002 * y * y } else { 1.2 };
    let panels = vec![
        sample_chart().legend(LegendPosition::UpperLeft),
        Chart::new("Contact angle", "y_ws (mm)", "γ (rad)")
            .series(Series::line(
                "left",
                ys.iter().map(|&y| (y, gamma(y))).collect(),
            ))
            .series(
                Series::line("right", ys.iter().map(|&y| (y, 0.03 - 0.001 * y)).collect()).dashed(),
            ),
        Chart::new("Roll angle", "y_ws (mm)", "roll (rad)").series(Series::line_with_markers(
            "rigid",
            ys.iter().step_by(5).map(|&y| (y, 1e-4 * y)).collect(),
        )),
        Chart::new("Semi-axis a", "y_ws (mm)", "a (mm)")
            .series(Series::markers(
                "a",
                ys.iter().map(|&y| (y, 2.0 + 10.0 * (-y).exp())).collect(),
            ))
            .y_log(),
        Chart::new("No data yet", "y_ws (mm)", "p0 (MPa)")
            .series(Series::line("not computed", vec![(f64::NAN, f64::NAN)]))
            .series(Series::line("empty", vec![])),
        Chart::new("Constant", "y_ws (mm)", "z_ws (mm)")
            .series(Series::line("flat", ys.iter().map(|&y| (y, 0.5)).collect())),
    ];
    let grid = Figure::grid("Fig. 2 (synthetic data)", panels, 2);
    std::fs::write(dir.join("grid.png"), render_png(&grid).unwrap()).unwrap();
    std::fs::write(dir.join("grid.svg"), render_svg(&grid).unwrap()).unwrap();
    let edge = edge_case_figure();
    std::fs::write(dir.join("edge.png"), render_png(&edge).unwrap()).unwrap();
    println!("previews in {}", dir.display());
}

/// Crops a PNG and scales it up `k` times (nearest neighbour), for looking at text rendering.
#[allow(dead_code)]
fn zoom(png_bytes: &[u8], (x0, y0, w, h): (u32, u32, u32, u32), k: u32) -> Vec<u8> {
    let decoder = png::Decoder::new(png_bytes);
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    let mut out = Vec::with_capacity((w * h * k * k * 3) as usize);
    for y in 0..h * k {
        for x in 0..w * k {
            let (sx, sy) = (x0 + x / k, y0 + y / k);
            let i = ((sy * info.width + sx) * 3) as usize;
            out.extend_from_slice(&buf[i..i + 3]);
        }
    }
    let mut bytes = Vec::new();
    let mut enc = png::Encoder::new(&mut bytes, w * k, h * k);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut wr = enc.write_header().unwrap();
    wr.write_image_data(&out).unwrap();
    wr.finish().unwrap();
    bytes
}

#[test]
#[ignore = "writes a zoomed crop of the legend and tick labels"]
fn preview_zoom() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-preview");
    std::fs::create_dir_all(&dir).unwrap();
    let png = std::fs::read(dir.join("profile.png")).unwrap();
    std::fs::write(
        dir.join("zoom-legend.png"),
        zoom(&png, (800, 40, 180, 80), 4),
    )
    .unwrap();
    std::fs::write(
        dir.join("zoom-ticks.png"),
        zoom(&png, (30, 560, 300, 100), 3),
    )
    .unwrap();
}
