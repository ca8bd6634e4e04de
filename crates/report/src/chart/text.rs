//! Text drawing with the bundled font, placed by us rather than by plotters' layout.
//!
//! plotters 0.3.7 rasterises ab_glyph glyphs without their left side bearing, so in bitmaps a
//! narrow glyph such as `1` sits too far left and words look unevenly spaced ("S1 002"). For
//! bitmaps we therefore draw glyph by glyph: each at its pen position from the font's advances
//! (kerning included) plus an estimate of its side bearing, namely half the space its advance
//! leaves around its ink. For SVG we write plain `<text>` and the viewer lays it out.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{ChartError, FONT_FAMILY, drawing_error, ensure_font};

/// Alignment along or across a line of text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Align {
    /// Left (along) or top (across).
    Start,
    /// Centre.
    Middle,
    /// Right (along) or bottom (across).
    End,
}

impl Align {
    fn fraction(self) -> f64 {
        match self {
            Align::Start => 0.0,
            Align::Middle => 0.5,
            Align::End => 1.0,
        }
    }
}

/// How text reaches the backend; see the module docs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum TextMode {
    /// One `<text>` element per string (SVG).
    Whole,
    /// One glyph at a time with side-bearing correction (bitmaps).
    PerGlyph,
}

/// One text style: size in pixels (the font's ascent-to-descent height) and colour.
#[derive(Debug, Clone, Copy)]
pub(super) struct TextSpec {
    pub(super) px: f64,
    pub(super) color: RGBColor,
}

impl TextSpec {
    pub(super) fn new(px: f64) -> Self {
        TextSpec { px, color: BLACK }
    }

    pub(super) fn color(self, color: RGBColor) -> Self {
        TextSpec { color, ..self }
    }

    fn font(&self) -> FontDesc<'static> {
        self.with_font(FontDesc::clone)
    }

    /// Calls `f` with the font of this size, made once per size: making one looks the family
    /// up in plotters' font table and copies the font's parsed tables. `f` must not make
    /// fonts itself.
    fn with_font<T>(&self, f: impl FnOnce(&FontDesc<'static>) -> T) -> T {
        let key = self.px.to_bits();
        FONTS.with(|fonts| {
            if let Some((_, font)) = fonts.borrow().iter().find(|(k, _)| *k == key) {
                return f(font);
            }
            let font = FontDesc::new(FontFamily::Name(FONT_FAMILY), self.px, FontStyle::Normal);
            // Keep only a font that found the bundled font file (made before it was
            // registered, it would fail for good).
            if ensure_font().is_err() {
                return f(&font);
            }
            let mut kept = fonts.borrow_mut();
            if kept.len() >= FONTS_CAPACITY {
                kept.clear();
            }
            kept.push((key, font));
            drop(kept);
            let kept = fonts.borrow();
            let (_, font) = kept.last().expect("just pushed");
            f(font)
        })
    }

    /// Advance width and line height in pixels (memoised: charts measure the same labels
    /// many times, and the layout engine is the costliest part of drawing text).
    pub(super) fn size(&self, text: &str) -> (i32, i32) {
        memo(&SIZES, text, self.px, || {
            self.with_font(|font| font.box_size(text))
                .map(|(w, h)| (w as i32, h as i32))
                .unwrap_or((0, 0))
        })
    }
}

/// A text placement: the anchor point in pixels of the root area, alignment along and across
/// the line, and whether the line runs upwards (rotated by 270°, as y-axis titles).
#[derive(Debug, Clone, Copy)]
pub(super) struct Place {
    pub(super) at: (i32, i32),
    pub(super) along: Align,
    pub(super) across: Align,
    pub(super) upwards: bool,
}

impl Place {
    pub(super) fn new(at: (i32, i32), along: Align, across: Align) -> Self {
        Place {
            at,
            along,
            across,
            upwards: false,
        }
    }

    pub(super) fn upwards(self) -> Self {
        Place {
            upwards: true,
            ..self
        }
    }
}

/// Draws `text` on `root` (pixel coordinates of the whole figure).
pub(super) fn draw_text<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    mode: TextMode,
    text: &str,
    spec: TextSpec,
    place: Place,
) -> Result<(), ChartError> {
    if text.is_empty() {
        return Ok(());
    }
    let (w, h) = spec.size(text);
    let along = (place.along.fraction() * f64::from(w)).round() as i32;
    let across = (place.across.fraction() * f64::from(h)).round() as i32;
    // Start of the line (left end, or bottom end when upwards) and its top (left) edge.
    let (x0, y0) = if place.upwards {
        (place.at.0 - across, place.at.1 + along)
    } else {
        (place.at.0 - along, place.at.1 - across)
    };
    // The style made in one piece: each of plotters' builder steps (`color`, `pos`,
    // `transform`) clones the font, and a clone copies the font's parsed tables.
    let font = if place.upwards {
        spec.with_font(|font| font.transform(FontTransform::Rotate270))
    } else {
        spec.font()
    };
    let style = move |h, v| TextStyle {
        font,
        color: spec.color.to_backend_color(),
        pos: Pos::new(h, v),
    };
    match mode {
        // Let the viewer align the text, so it stays aligned with whatever font it substitutes.
        TextMode::Whole => {
            let h = match place.along {
                Align::Start => HPos::Left,
                Align::Middle => HPos::Center,
                Align::End => HPos::Right,
            };
            let v = match place.across {
                Align::Start => VPos::Top,
                Align::Middle => VPos::Center,
                Align::End => VPos::Bottom,
            };
            root.draw(&Text::new(text.to_owned(), place.at, style(h, v)))
                .map_err(drawing_error)
        }
        TextMode::PerGlyph => {
            // plotters puts the bitmap baseline at half the size below the top; SVG puts it at
            // about 0.61 of the size. Shift bitmaps down so both outputs agree.
            let baseline = (0.11 * spec.px).round() as i32;
            let style = style(HPos::Left, VPos::Top);
            for (glyph, offset) in glyph_offsets(text, spec) {
                let at = if place.upwards {
                    (x0 + baseline, y0 - offset)
                } else {
                    (x0 + offset, y0 + baseline)
                };
                root.draw(&Text::new(glyph, at, style.clone()))
                    .map_err(drawing_error)?;
            }
            Ok(())
        }
    }
}

/// The glyphs of `text` that draw ink, each with its offset in pixels from the start of the
/// line: the pen position from the font's advances (kerning included) plus half the space
/// the glyph's advance leaves around its ink. Memoised like [`TextSpec::size`].
fn glyph_offsets(text: &str, spec: TextSpec) -> Vec<(String, i32)> {
    memo(&GLYPHS, text, spec.px, || {
        let font = spec.font();
        let mut glyph = [0u8; 4];
        let mut out = Vec::new();
        for (i, c) in text.char_indices() {
            let c: &str = c.encode_utf8(&mut glyph);
            let pen = spec.size(&text[..i]).0;
            let advance = spec.size(c).0;
            let Some(ink) = ink_width(&font, c) else {
                continue; // blank glyph such as a space
            };
            out.push((c.to_owned(), pen + (advance - ink).max(0) / 2));
        }
        out
    })
}

type Memo<T> = std::cell::RefCell<std::collections::HashMap<(String, u64), T>>;

thread_local! {
    static FONTS: std::cell::RefCell<Vec<(u64, FontDesc<'static>)>> =
        const { std::cell::RefCell::new(Vec::new()) };
    static SIZES: Memo<(i32, i32)> = Memo::default();
    static GLYPHS: Memo<Vec<(String, i32)>> = Memo::default();
}

/// Fonts (sizes) kept at once: a figure uses a handful.
const FONTS_CAPACITY: usize = 16;

/// Entries a memo holds before it starts afresh (a few figures' worth of labels).
const MEMO_CAPACITY: usize = 4096;

fn memo<T: Clone>(
    table: &'static std::thread::LocalKey<Memo<T>>,
    text: &str,
    px: f64,
    compute: impl FnOnce() -> T,
) -> T {
    let key = (text.to_owned(), px.to_bits());
    if let Some(hit) = table.with(|m| m.borrow().get(&key).cloned()) {
        return hit;
    }
    let value = compute();
    table.with(|m| {
        let mut m = m.borrow_mut();
        if m.len() >= MEMO_CAPACITY {
            m.clear();
        }
        m.insert(key, value.clone());
    });
    value
}

/// Width in pixels of the glyph's rasterised ink, `None` if it draws nothing.
fn ink_width(font: &FontDesc<'_>, glyph: &str) -> Option<i32> {
    let mut max_x: Option<i32> = None;
    let drawn = font.draw(glyph, (0, 0), |x, _y, _alpha| {
        max_x = Some(max_x.map_or(x, |m| m.max(x)));
        Ok::<(), ()>(())
    });
    match drawn {
        Ok(Ok(())) => max_x.map(|m| m + 1),
        _ => None,
    }
}
