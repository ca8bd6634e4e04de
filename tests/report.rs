//! Integration tests of the report writers: CSV tables, golden comparison, charts and HTML.

use wheelrail::report::chart::{Chart, Figure, LegendPosition, Series, render_png, render_svg};

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
