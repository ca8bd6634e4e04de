//! Declarative charts rendered to SVG text and PNG bytes.
//!
//! A [`Chart`] says *what* to draw: axis labels (with units), series of points, optional fixed
//! ranges, log axes, equal aspect for profile drawings in millimetres, vertical marker lines. A
//! [`Figure`] arranges one or more charts in a grid under a title. [`render_svg`] and
//! [`render_png`] say *how*, with [plotters](https://docs.rs/plotters); neither touches the file
//! system.
//!
//! # Conventions of the drawing
//!
//! * A non-finite point (`NaN`, `±inf`) breaks a line: jumps and points that could not be
//!   computed show as gaps, never as joining lines. On a log axis, non-positive values are
//!   skipped the same way.
//! * Automatic ranges come from the data that matters: isolated extremes (a pole, a vertical
//!   profile face, one wild sample) are left out of the y range. Data outside the y range,
//!   automatic or fixed, is clipped at the frame, where a triangle in the series' colour marks
//!   each place it leaves, and the legend says how far it goes ("off the chart: ▼ down to
//!   -1e6").
//! * Legends never cover what is drawn (see [`LegendPosition`]), and neither do the labels
//!   of marker lines and points ([`PointLabel`]): they go on the same occupancy grid;
//!   [`layout`] tells where they went and [`render_rgb`] can leave them out to check it.
//! * Lines are drawn at the chart's resolution: of the points of a line that fall in one
//!   pixel column only the first, the lowest, the highest and the last are kept, which
//!   draw the same pixels, so a chart's size does not grow with its data (a sweep of
//!   100,001 positions keeps at most four points a column); markers and segments that
//!   fall on the pixels of earlier ones are drawn once.
//! * Colours come from the Okabe–Ito palette ([`PALETTE`]), readable with the common colour
//!   vision deficiencies; each colour has its own marker shape ([`MarkerShape::for_color`]), and
//!   lines can be dashed, so series stay distinguishable in grey-scale print.
//! * Text uses the DejaVu Sans font compiled into the crate, never a system font, so the PNG
//!   bytes are the same on every machine. SVG text names `DejaVu Sans, sans-serif`.
//! * Sizes are in pixels; fonts are sized for the default 1000 × 700 figure.
//!
//! # Examples
//!
//! ```
//! use wheelrail_report::chart::{render_png, render_svg, Chart, Figure, Series};
//!
//! let chart = Chart::new("Rolling radius difference", "y_ws (mm)", "Δr (mm)")
//!     .series(Series::line("rigid", vec![(0.0, 0.0), (5.0, 0.4), (f64::NAN, f64::NAN), (6.0, 3.0)]))
//!     .vline(5.5, "flange contact");
//! let figure = Figure::single(chart);
//! let svg = render_svg(&figure)?;
//! assert!(svg.contains("Rolling radius difference"));
//! let png = render_png(&figure)?;
//! assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
//! # Ok::<(), wheelrail_report::chart::ChartError>(())
//! ```

use std::fmt;
use std::sync::OnceLock;

use plotters::prelude::*;

mod draw;
mod geometry;
mod text;
mod ticks;

use text::TextMode;

/// The Okabe–Ito colour-blind-safe palette, reordered so that the first colours contrast most on
/// white (yellow, the weakest, is last). `Series::color` indexes it modulo its length.
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0x00, 0x72, 0xB2), // blue
    (0xD5, 0x5E, 0x00), // vermillion
    (0x00, 0x9E, 0x73), // bluish green
    (0xCC, 0x79, 0xA7), // reddish purple
    (0xE6, 0x9F, 0x00), // orange
    (0x56, 0xB4, 0xE9), // sky blue
    (0x00, 0x00, 0x00), // black
    (0xF0, 0xE4, 0x42), // yellow
];

/// Default figure width in pixels.
pub const DEFAULT_WIDTH: u32 = 1000;
/// Default figure height in pixels.
pub const DEFAULT_HEIGHT: u32 = 700;

/// Font family name under which the bundled font is registered; also written into SVG, where
/// the generic fallback applies if a viewer lacks DejaVu Sans.
const FONT_FAMILY: &str = "DejaVu Sans, sans-serif";
const FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SeriesStyle {
    /// A polyline through the points, broken at non-finite points.
    #[default]
    Line,
    /// A marker at each finite point.
    Markers,
    /// Points taken in pairs, each pair drawn as its own segment (e.g. linking a wheel contact
    /// point with its rail contact point). A trailing odd point is ignored.
    Segments,
    /// A polyline with a marker at each finite point.
    LineWithMarkers,
}

/// Marker shapes; see [`MarkerShape::for_color`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MarkerShape {
    /// Filled circle.
    Circle,
    /// Filled square.
    Square,
    /// Filled upward triangle.
    Triangle,
    /// Filled diamond.
    Diamond,
    /// Diagonal cross.
    Cross,
    /// Open circle.
    OpenCircle,
    /// Open square.
    OpenSquare,
    /// Upright cross (plus sign).
    Plus,
}

impl MarkerShape {
    /// The shape paired with palette colour `index` (modulo 8), so that colour and shape
    /// together identify a series.
    pub fn for_color(index: usize) -> MarkerShape {
        const SHAPES: [MarkerShape; 8] = [
            MarkerShape::Circle,
            MarkerShape::Square,
            MarkerShape::Triangle,
            MarkerShape::Diamond,
            MarkerShape::Cross,
            MarkerShape::OpenCircle,
            MarkerShape::OpenSquare,
            MarkerShape::Plus,
        ];
        SHAPES[index % SHAPES.len()]
    }
}

/// One labelled set of points.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Series {
    /// Legend text; an empty label keeps the series out of the legend.
    pub label: String,
    /// How the points are drawn.
    pub style: SeriesStyle,
    /// Index into [`PALETTE`] (modulo its length); `None` uses the series' position in the chart.
    pub color: Option<usize>,
    /// Draw lines dashed (e.g. right wheel dashed, left solid).
    pub dashed: bool,
    /// The points `(x, y)` in axis units; non-finite points make gaps.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A [`SeriesStyle::Line`] series.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            style: SeriesStyle::Line,
            points,
            ..Series::default()
        }
    }

    /// A [`SeriesStyle::Markers`] series.
    pub fn markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            style: SeriesStyle::Markers,
            ..Series::line(label, points)
        }
    }

    /// A [`SeriesStyle::LineWithMarkers`] series.
    pub fn line_with_markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            style: SeriesStyle::LineWithMarkers,
            ..Series::line(label, points)
        }
    }

    /// A [`SeriesStyle::Segments`] series from `[start, end]` pairs.
    pub fn segments(label: impl Into<String>, segments: &[[(f64, f64); 2]]) -> Self {
        Series {
            style: SeriesStyle::Segments,
            ..Series::line(label, segments.iter().flatten().copied().collect())
        }
    }

    /// Sets the palette colour index.
    pub fn color(mut self, index: usize) -> Self {
        self.color = Some(index);
        self
    }

    /// Draws the lines dashed.
    pub fn dashed(mut self) -> Self {
        self.dashed = true;
        self
    }
}

/// A vertical marker line across the plot, e.g. the onset of flange contact.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VLine {
    /// Position on the x axis, in axis units.
    pub x: f64,
    /// Text written beside the line near the top; may be empty.
    pub label: String,
}

/// A text beside one point of the plot (the setting a marker stands for, say), placed like
/// a legend where it covers nothing drawn, nearest its point; a thin leader line joins the
/// two when the text had to move away.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PointLabel {
    /// Position on the x axis, in axis units.
    pub x: f64,
    /// Position on the y axis, in axis units.
    pub y: f64,
    /// The text.
    pub text: String,
}

/// A shaded horizontal band across the plot, named at the y axis in place of the tick
/// labels within it: where values off the axis's scale are drawn at a stand-in value, such
/// as the exact zeros of a logarithmic axis ("exact").
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HBand {
    /// Lower edge on the y axis, in axis units.
    pub from: f64,
    /// Upper edge on the y axis, in axis units.
    pub to: f64,
    /// The band's name, written at the y axis level with its middle.
    pub label: String,
}

/// Where the legend goes. Whatever the choice, a legend never covers data, marker lines or
/// labels: if the requested corner is not free the legend moves to the free place nearest a
/// corner, and if no place inside the plot is free, outside it (right of the plot or below
/// the x-axis title, whichever takes less room from the plot).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LegendPosition {
    /// The free inside corner, in the order upper right, upper left, lower right, lower left.
    #[default]
    Auto,
    /// Inside, upper left corner.
    UpperLeft,
    /// Inside, upper right corner.
    UpperRight,
    /// Inside, lower left corner.
    LowerLeft,
    /// Inside, lower right corner.
    LowerRight,
    /// No legend.
    Hidden,
}

/// One plot: axes, series and annotations.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Chart {
    /// Title above the plot; may be empty.
    pub title: String,
    /// x-axis label, unit included (`"y_ws (mm)"`).
    pub x_label: String,
    /// y-axis label, unit included.
    pub y_label: String,
    /// The data, drawn in order (later series on top).
    pub series: Vec<Series>,
    /// Fixed x range `(min, max)`; `None` fits the data with a small margin.
    pub x_range: Option<(f64, f64)>,
    /// Fixed y range `(min, max)`; `None` fits the data with a small margin.
    pub y_range: Option<(f64, f64)>,
    /// One x unit as long as one y unit on screen (for profiles in mm). The ranges are widened
    /// about their centres to achieve it; ignored when either axis is logarithmic.
    pub equal_aspect: bool,
    /// Logarithmic x axis (non-positive x values are skipped).
    pub x_log: bool,
    /// Logarithmic y axis (non-positive y values are skipped).
    pub y_log: bool,
    /// Vertical marker lines.
    pub vlines: Vec<VLine>,
    /// Texts beside points.
    pub labels: Vec<PointLabel>,
    /// Shaded horizontal bands.
    pub hbands: Vec<HBand>,
    /// Legend placement.
    pub legend: LegendPosition,
}

impl Chart {
    /// A chart with a title and axis labels, no data.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Chart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            ..Chart::default()
        }
    }

    /// Adds a series.
    pub fn series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Fixes the x range.
    pub fn x_range(mut self, min: f64, max: f64) -> Self {
        self.x_range = Some((min, max));
        self
    }

    /// Fixes the y range.
    pub fn y_range(mut self, min: f64, max: f64) -> Self {
        self.y_range = Some((min, max));
        self
    }

    /// Requests equal scales on both axes.
    pub fn equal_aspect(mut self) -> Self {
        self.equal_aspect = true;
        self
    }

    /// Makes the x axis logarithmic.
    pub fn x_log(mut self) -> Self {
        self.x_log = true;
        self
    }

    /// Makes the y axis logarithmic.
    pub fn y_log(mut self) -> Self {
        self.y_log = true;
        self
    }

    /// Adds a vertical marker line.
    pub fn vline(mut self, x: f64, label: impl Into<String>) -> Self {
        self.vlines.push(VLine {
            x,
            label: label.into(),
        });
        self
    }

    /// Adds a text beside the point `(x, y)`.
    pub fn label(mut self, x: f64, y: f64, text: impl Into<String>) -> Self {
        self.labels.push(PointLabel {
            x,
            y,
            text: text.into(),
        });
        self
    }

    /// Adds a shaded band from `from` to `to` on the y axis, named `label` at the axis.
    pub fn hband(mut self, from: f64, to: f64, label: impl Into<String>) -> Self {
        self.hbands.push(HBand {
            from,
            to,
            label: label.into(),
        });
        self
    }

    /// Sets the legend position.
    pub fn legend(mut self, position: LegendPosition) -> Self {
        self.legend = position;
        self
    }
}

/// One or more charts in a grid of `columns` columns, filled row by row, under a title.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Title above all panels; may be empty.
    pub title: String,
    /// The panels, row by row.
    pub panels: Vec<Chart>,
    /// Number of grid columns (at least 1).
    pub columns: usize,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// A key below the panels: short entries (`"3  profiles sampled 0.05 mm"`) set in
    /// columns, read downwards; the panels give up the height it takes.
    pub key: Vec<String>,
}

impl Figure {
    /// A one-panel figure of the default size, without a figure title (the chart has its own).
    pub fn single(chart: Chart) -> Self {
        Figure {
            title: String::new(),
            panels: vec![chart],
            columns: 1,
            width: DEFAULT_WIDTH,
            height: DEFAULT_HEIGHT,
            key: Vec::new(),
        }
    }

    /// A grid figure sized 620 × 440 pixels per panel (plus the title band).
    pub fn grid(title: impl Into<String>, panels: Vec<Chart>, columns: usize) -> Self {
        let columns = columns.max(1);
        let rows = panels.len().div_ceil(columns).max(1);
        let title = title.into();
        let title_band = if title.is_empty() { 0 } else { 50 };
        Figure {
            width: 620 * columns as u32,
            height: 440 * rows as u32 + title_band,
            title,
            panels,
            columns,
            key: Vec::new(),
        }
    }

    /// Sets the key below the panels (see [`Figure::key`]); the figure grows by the
    /// height it takes ([`Figure::key_height`]).
    pub fn with_key(mut self, key: Vec<String>) -> Self {
        self.key = key;
        self.height += self.key_height();
        self
    }

    /// The height in pixels of the key below the panels at the figure's width (0 without
    /// one).
    pub fn key_height(&self) -> u32 {
        draw::key_height(self)
    }

    /// Sets the size in pixels.
    pub fn size(mut self, width: u32, height: u32) -> Self {
        self.width = width;
        self.height = height;
        self
    }
}

/// Which axis a [`ChartError`] is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// The horizontal axis.
    X,
    /// The vertical axis.
    Y,
}

/// Why a figure could not be rendered.
#[derive(Debug, Clone, PartialEq)]
pub enum ChartError {
    /// Width or height is zero, or the panels would be too small to draw.
    InvalidSize {
        /// Requested width in pixels.
        width: u32,
        /// Requested height in pixels.
        height: u32,
    },
    /// `Figure::columns` is zero.
    ZeroColumns,
    /// A fixed range is not finite, empty or reversed, or not positive on a log axis.
    InvalidRange {
        /// Index of the panel in `Figure::panels`.
        panel: usize,
        /// The axis.
        axis: Axis,
        /// The range given.
        range: (f64, f64),
    },
    /// The bundled font could not be loaded.
    Font,
    /// The drawing library reported an error.
    Drawing(String),
    /// PNG encoding failed.
    Png(String),
}

impl fmt::Display for ChartError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ChartError::InvalidSize { width, height } => {
                write!(f, "figure size {width}x{height} px is too small to draw")
            }
            ChartError::ZeroColumns => f.write_str("figure has zero columns"),
            ChartError::InvalidRange { panel, axis, range } => write!(
                f,
                "panel {panel}: {axis:?} range ({}, {}) must be finite and increasing (and \
                 positive on a log axis)",
                range.0, range.1
            ),
            ChartError::Font => f.write_str("the bundled font could not be loaded"),
            ChartError::Drawing(msg) => write!(f, "drawing failed: {msg}"),
            ChartError::Png(msg) => write!(f, "PNG encoding failed: {msg}"),
        }
    }
}

impl std::error::Error for ChartError {}

/// Renders `figure` as an SVG document.
///
/// # Errors
///
/// [`ChartError::InvalidSize`], [`ChartError::ZeroColumns`], [`ChartError::InvalidRange`] for
/// bad input; [`ChartError::Font`] or [`ChartError::Drawing`] if the drawing library fails.
pub fn render_svg(figure: &Figure) -> Result<String, ChartError> {
    check_figure(figure)?;
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (figure.width, figure.height)).into_drawing_area();
        draw::draw_figure(&root, figure, DrawOptions::svg())?;
        root.present().map_err(drawing_error)?;
    }
    Ok(svg)
}

/// Renders `figure` as PNG bytes (8-bit RGB, no metadata), identical on every machine for the
/// same input.
///
/// # Errors
///
/// As [`render_svg`], plus [`ChartError::Png`] if encoding fails.
pub fn render_png(figure: &Figure) -> Result<Vec<u8>, ChartError> {
    let pixels = render_rgb(figure, true)?;
    let (w, h) = (figure.width, figure.height);
    let mut bytes = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut bytes, w, h);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        // Fast deflate (fdeflate) after the Paeth filter: the best zlib level spent 3/4 of the
        // report's time here (perf) for files 1.8 times smaller; lossless either way.
        encoder.set_compression(png::Compression::Fast);
        encoder.set_filter(png::FilterType::Paeth);
        let png_error = |e: png::EncodingError| ChartError::Png(e.to_string());
        let mut writer = encoder.write_header().map_err(png_error)?;
        writer.write_image_data(&pixels).map_err(png_error)?;
        writer.finish().map_err(png_error)?;
    }
    Ok(bytes)
}

/// The pixels of [`render_png`]: 8-bit RGB, row by row from the top, `width × height × 3`
/// bytes. With `legends` false the legends and the labels placed like them (of marker
/// lines and points, with their leader lines) are laid out (the plot keeps its size and
/// the data its place) but not drawn, so that one can see what they would cover.
///
/// # Errors
///
/// As [`render_svg`].
pub fn render_rgb(figure: &Figure, legends: bool) -> Result<Vec<u8>, ChartError> {
    check_figure(figure)?;
    let (w, h) = (figure.width, figure.height);
    let mut pixels = vec![0u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, (w, h)).into_drawing_area();
        let options = DrawOptions {
            mode: TextMode::PerGlyph,
            legends,
        };
        draw::draw_figure(&root, figure, options)?;
        root.present().map_err(drawing_error)?;
    }
    Ok(pixels)
}

/// A rectangle of pixels of the rendered image, edges included, `(0, 0)` at the top left.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PxBox {
    /// Leftmost column.
    pub left: i32,
    /// Top row.
    pub top: i32,
    /// Rightmost column.
    pub right: i32,
    /// Bottom row.
    pub bottom: i32,
}

/// Where the parts of one panel landed on the image (the same in SVG and PNG).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PanelLayout {
    /// The plot area (the frame around the data).
    pub plot: PxBox,
    /// The legend box, `None` when the panel has no legend.
    pub legend: Option<PxBox>,
    /// The legend sits outside the plot (right of it, or below the x-axis title) because no
    /// place inside it was free.
    pub legend_outside: bool,
    /// Number of places where a series leaves the chart above or below (each marked by a
    /// triangle at the frame and summed up in the legend).
    pub off_chart: usize,
    /// The boxes of the labels placed in the plot like the legend (of marker lines and
    /// points), in the order of [`Chart::vlines`] then [`Chart::labels`].
    pub labels: Vec<PxBox>,
}

/// The layout of every panel of `figure`, in panel order.
///
/// # Errors
///
/// As [`render_svg`].
pub fn layout(figure: &Figure) -> Result<Vec<PanelLayout>, ChartError> {
    check_figure(figure)?;
    let mut svg = String::new();
    let root = SVGBackend::with_string(&mut svg, (figure.width, figure.height)).into_drawing_area();
    draw::draw_figure(&root, figure, DrawOptions::svg())
}

/// How [`draw::draw_figure`] draws.
#[derive(Debug, Clone, Copy)]
struct DrawOptions {
    mode: TextMode,
    legends: bool,
}

impl DrawOptions {
    fn svg() -> Self {
        DrawOptions {
            mode: TextMode::Whole,
            legends: true,
        }
    }
}

fn check_figure(figure: &Figure) -> Result<(), ChartError> {
    if figure.columns == 0 {
        return Err(ChartError::ZeroColumns);
    }
    let rows = figure.panels.len().div_ceil(figure.columns).max(1) as u32;
    let cols = figure.columns.min(figure.panels.len().max(1)) as u32;
    // Below this a panel cannot hold its labels and a plot area.
    const MIN_PANEL_PX: u32 = 160;
    if figure.width / cols < MIN_PANEL_PX || figure.height / rows < MIN_PANEL_PX {
        return Err(ChartError::InvalidSize {
            width: figure.width,
            height: figure.height,
        });
    }
    for (panel, chart) in figure.panels.iter().enumerate() {
        for (axis, range, log) in [
            (Axis::X, chart.x_range, chart.x_log),
            (Axis::Y, chart.y_range, chart.y_log),
        ] {
            if let Some((lo, hi)) = range
                && !(lo.is_finite() && hi.is_finite() && lo < hi && (!log || lo > 0.0))
            {
                return Err(ChartError::InvalidRange {
                    panel,
                    axis,
                    range: (lo, hi),
                });
            }
        }
    }
    Ok(())
}

fn drawing_error<E: std::error::Error + Send + Sync>(
    e: plotters::drawing::DrawingAreaErrorKind<E>,
) -> ChartError {
    ChartError::Drawing(e.to_string())
}

fn ensure_font() -> Result<(), ChartError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT_FAMILY, FontStyle::Normal, FONT_BYTES).is_ok()
    });
    if ok { Ok(()) } else { Err(ChartError::Font) }
}
