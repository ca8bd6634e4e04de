//! The SVG writer of the charts: a plotters backend that writes the same bytes as plotters'
//! own `SVGBackend` (plotters-svg 0.3.7) for every primitive, at a fraction of the cost.
//!
//! plotters' backend builds each attribute value as a `String` with `format!` and then copies
//! it, escaped, into the document; here numbers and colours go straight into the one
//! document string and only text (and the font family) is escaped. On the EN 15302 E1
//! comparison scene's rolling-radius SVG (`../shared/peer/awrcc/compare.sh`) plotters'
//! backend took about 1.25 M instructions of the figure's 3.00 M; with this one the figure
//! takes 1.79 M (callgrind, the whole process 25.21 -> 24.00 M).
//!
//! The output is the other backend's, byte for byte: the same elements with the same
//! attributes in the same order, integers in decimal, colours as `#RRGGBB` in capitals,
//! opacities and font sizes as Rust prints an `f64`, and `<`, `>`, `&`, `"` and `'`
//! escaped. The unit test below draws every primitive through both and compares.

use std::fmt::Write as _;

use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
    FontStyle, FontTransform,
};

/// An SVG document written into a borrowed string (see the module docs).
pub(super) struct SvgWriter<'a> {
    out: &'a mut String,
    size: (u32, u32),
    /// The `<svg>` element is closed (by [`DrawingBackend::present`]).
    closed: bool,
    /// The last font size written and its text: a figure uses a handful of sizes, and
    /// printing an `f64` is the costliest number to write.
    font_size: Option<(u64, String)>,
}

impl<'a> SvgWriter<'a> {
    /// Starts a document of `size` (width, height) pixels in `out`.
    pub(super) fn new(out: &'a mut String, size: (u32, u32)) -> Self {
        out.push_str("<svg width=\"");
        push_u32(out, size.0);
        out.push_str("\" height=\"");
        push_u32(out, size.1);
        out.push_str("\" viewBox=\"0 0 ");
        push_u32(out, size.0);
        out.push(' ');
        push_u32(out, size.1);
        out.push_str("\" xmlns=\"http://www.w3.org/2000/svg\">\n");
        SvgWriter {
            out,
            size,
            closed: false,
            font_size: None,
        }
    }

    /// Writes ` name="` (the attribute's opening).
    fn attr(&mut self, name: &str) {
        self.out.push(' ');
        self.out.push_str(name);
        self.out.push_str("=\"");
    }

    fn attr_i32(&mut self, name: &str, value: i32) {
        self.attr(name);
        push_i32(self.out, value);
        self.out.push('"');
    }

    fn attr_u32(&mut self, name: &str, value: u32) {
        self.attr(name);
        push_u32(self.out, value);
        self.out.push('"');
    }

    fn attr_str(&mut self, name: &str, value: &str) {
        self.attr(name);
        self.out.push_str(value);
        self.out.push('"');
    }

    fn attr_color(&mut self, name: &str, color: BackendColor) {
        self.attr(name);
        push_color(self.out, color);
        self.out.push('"');
    }

    /// `fill` in `color` and no stroke, or the other way round (a filled or an outlined
    /// shape, as plotters writes them).
    fn attr_paint(&mut self, color: BackendColor, fill: bool) {
        if fill {
            self.attr_color("fill", color);
            self.attr_str("stroke", "none");
        } else {
            self.attr_str("fill", "none");
            self.attr_color("stroke", color);
        }
    }

    fn attr_opacity(&mut self, color: BackendColor) {
        self.attr("opacity");
        push_f64(self.out, color.alpha);
        self.out.push('"');
    }

    /// ` points="x,y x,y "`, as plotters writes it (a space after every point).
    fn attr_points(&mut self, points: impl IntoIterator<Item = BackendCoord>) {
        self.attr("points");
        for (x, y) in points {
            push_i32(self.out, x);
            self.out.push(',');
            push_i32(self.out, y);
            self.out.push(' ');
        }
        self.out.push('"');
    }

    fn font_size(&mut self, size: f64) {
        self.attr("font-size");
        let size = size / 1.24;
        match &self.font_size {
            Some((bits, text)) if *bits == size.to_bits() => self.out.push_str(text),
            _ => {
                let mut text = String::new();
                push_f64(&mut text, size);
                self.out.push_str(&text);
                self.font_size = Some((size.to_bits(), text));
            }
        }
        self.out.push('"');
    }
}

impl DrawingBackend for SvgWriter<'_> {
    type ErrorType = std::convert::Infallible;

    fn get_size(&self) -> (u32, u32) {
        self.size
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if !self.closed {
            self.out.push_str("</svg>\n");
            self.closed = true;
        }
        Ok(())
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if color.alpha == 0.0 {
            return Ok(());
        }
        self.out.push_str("<rect");
        self.attr_i32("x", point.0);
        self.attr_i32("y", point.1);
        self.out
            .push_str(" width=\"1\" height=\"1\" stroke=\"none\"");
        self.attr_opacity(color);
        self.attr_color("fill", color);
        self.out.push_str("/>\n");
        Ok(())
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        self.out.push_str("<line");
        self.attr_opacity(color);
        self.attr_color("stroke", color);
        self.attr_u32("stroke-width", style.stroke_width());
        self.attr_i32("x1", from.0);
        self.attr_i32("y1", from.1);
        self.attr_i32("x2", to.0);
        self.attr_i32("y2", to.1);
        self.out.push_str("/>\n");
        Ok(())
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        self.out.push_str("<rect");
        self.attr_i32("x", upper_left.0);
        self.attr_i32("y", upper_left.1);
        self.attr_i32("width", bottom_right.0 - upper_left.0);
        self.attr_i32("height", bottom_right.1 - upper_left.1);
        self.attr_opacity(color);
        self.attr_paint(color, fill);
        self.out.push_str("/>\n");
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        self.out.push_str("<polyline fill=\"none\"");
        self.attr_opacity(color);
        self.attr_color("stroke", color);
        self.attr_u32("stroke-width", style.stroke_width());
        self.attr_points(path);
        self.out.push_str("/>\n");
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        self.out.push_str("<polygon");
        self.attr_opacity(color);
        self.attr_color("fill", color);
        self.attr_points(path);
        self.out.push_str("/>\n");
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        self.out.push_str("<circle");
        self.attr_i32("cx", center.0);
        self.attr_i32("cy", center.1);
        self.attr_u32("r", radius);
        self.attr_opacity(color);
        self.attr_paint(color, fill);
        self.attr_u32("stroke-width", style.stroke_width());
        self.out.push_str("/>\n");
        Ok(())
    }

    fn draw_text<S: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &S,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let anchor = style.anchor();
        self.out.push_str("<text");
        self.attr_i32("x", pos.0);
        self.attr_i32("y", pos.1);
        self.attr_str(
            "dy",
            match anchor.v_pos {
                VPos::Top => "0.76em",
                VPos::Center => "0.5ex",
                VPos::Bottom => "-0.5ex",
            },
        );
        self.attr_str(
            "text-anchor",
            match anchor.h_pos {
                HPos::Left => "start",
                HPos::Right => "end",
                HPos::Center => "middle",
            },
        );
        self.attr("font-family");
        push_escaped(self.out, style.family().as_str());
        self.out.push('"');
        self.font_size(style.size());
        self.attr_opacity(color);
        self.attr_color("fill", color);
        match style.style() {
            FontStyle::Normal => {}
            FontStyle::Bold => self.attr_str("font-weight", "bold"),
            other => self.attr_str("font-style", other.as_str()),
        }
        let angle = match style.transform() {
            FontTransform::Rotate90 => Some("90"),
            FontTransform::Rotate180 => Some("180"),
            FontTransform::Rotate270 => Some("270"),
            _ => None,
        };
        if let Some(angle) = angle {
            self.attr("transform");
            self.out.push_str("rotate(");
            self.out.push_str(angle);
            self.out.push_str(", ");
            push_i32(self.out, pos.0);
            self.out.push_str(", ");
            push_i32(self.out, pos.1);
            self.out.push_str(")\"");
        }
        self.out.push_str(">\n");
        push_escaped(self.out, text);
        self.out.push_str("\n</text>\n");
        Ok(())
    }
}

impl Drop for SvgWriter<'_> {
    /// Closes the document if [`DrawingBackend::present`] was not called, as plotters'
    /// backend does.
    fn drop(&mut self) {
        let _ = self.present();
    }
}

fn push_u32(out: &mut String, mut value: u32) {
    let mut digits = [0u8; 10];
    let mut start = digits.len();
    loop {
        start -= 1;
        digits[start] = b'0' + (value % 10) as u8;
        value /= 10;
        if value == 0 {
            break;
        }
    }
    for &d in &digits[start..] {
        out.push(char::from(d));
    }
}

fn push_i32(out: &mut String, value: i32) {
    if value < 0 {
        out.push('-');
    }
    push_u32(out, value.unsigned_abs());
}

/// `#RRGGBB` in capitals.
fn push_color(out: &mut String, color: BackendColor) {
    const HEX: &[u8; 16] = b"0123456789ABCDEF";
    let (r, g, b) = color.rgb;
    out.push('#');
    for byte in [r, g, b] {
        out.push(char::from(HEX[usize::from(byte >> 4)]));
        out.push(char::from(HEX[usize::from(byte & 0xF)]));
    }
}

/// An `f64` as Rust's `Display` prints it (opaque, the usual opacity, written directly).
fn push_f64(out: &mut String, value: f64) {
    if value.to_bits() == 1f64.to_bits() {
        out.push('1');
    } else {
        // Writing to a String cannot fail.
        let _ = write!(out, "{value}");
    }
}

/// `text` with the five XML special characters escaped.
fn push_escaped(out: &mut String, text: &str) {
    let special = |c: char| matches!(c, '<' | '>' | '&' | '"' | '\'');
    if !text.contains(special) {
        out.push_str(text);
        return;
    }
    for c in text.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            other => out.push(other),
        }
    }
}

#[cfg(test)]
mod tests {
    use plotters::coord::Shift;
    use plotters::prelude::*;
    use plotters::style::text_anchor::{HPos, Pos, VPos};

    use super::SvgWriter;
    use crate::chart::{FONT_FAMILY, ensure_font};

    /// Every primitive, in every variant the two backends write differently, on `root`.
    fn draw_everything<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>) {
        let grey = RGBColor(0x44, 0x44, 0x44);
        let blue = RGBColor(0x1f, 0x77, 0xb4);
        root.fill(&WHITE).unwrap();
        root.draw(&PathElement::new(
            vec![(10, 10), (120, -3), (250, 90), (-4, 200)],
            blue.stroke_width(2),
        ))
        .unwrap();
        root.draw(&PathElement::new(vec![(5, 5), (6, 6)], grey.mix(0.9)))
            .unwrap();
        root.draw(&PathElement::new(vec![(5, 5), (6, 6)], grey.mix(0.0)))
            .unwrap();
        root.draw(&PathElement::new(vec![(30, 40), (30, 40), (31, 40)], BLACK))
            .unwrap();
        root.draw(&Rectangle::new([(3, 4), (100, 50)], grey.filled()))
            .unwrap();
        root.draw(&Rectangle::new([(3, 4), (100, 50)], blue.mix(0.25)))
            .unwrap();
        root.draw(&Rectangle::new([(90, 80), (12, 8)], BLACK.stroke_width(3)))
            .unwrap();
        root.draw(&Circle::new((50, 60), 5, blue.filled())).unwrap();
        root.draw(&Circle::new((-50, 600), 7, RED.stroke_width(2)))
            .unwrap();
        root.draw(&Polygon::new(
            vec![(0, 0), (10, 20), (-5, 30)],
            grey.mix(0.3),
        ))
        .unwrap();
        root.draw(&Pixel::new((7, 8), RGBColor(0xab, 0xcd, 0xef)))
            .unwrap();
        root.draw_pixel((9, 9), &RGBColor(1, 2, 3).mix(0.5))
            .unwrap();
        // Grid lines and crosses go through draw_line.
        root.draw(&Cross::new((-3, 100), 4, grey)).unwrap();
        root.draw(&Cross::new((300, 10), 6, blue.mix(0.5).stroke_width(2)))
            .unwrap();
        let sub = root.margin(7, 11, 13, 17);
        sub.draw(&PathElement::new(vec![(0, 0), (20, 30)], BLACK))
            .unwrap();
        draw_texts(root);
    }

    /// Text in every anchor, rotation, style and colour, with characters to escape.
    fn draw_texts<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>) {
        let grey = RGBColor(0x44, 0x44, 0x44);
        let blue = RGBColor(0x1f, 0x77, 0xb4);
        let texts = [
            "plain",
            "lateral shift y_ws (mm)",
            "a<b & c>d \"quoted\" it's",
            "Δr (mm) ±0.5 – µ",
            " ",
        ];
        let sizes = [16.0, 19.0, 28.0, 14.0, 15.0, 22.3];
        let anchors = [HPos::Left, HPos::Center, HPos::Right];
        let vertical = [VPos::Top, VPos::Center, VPos::Bottom];
        let transforms = [
            FontTransform::None,
            FontTransform::Rotate90,
            FontTransform::Rotate180,
            FontTransform::Rotate270,
        ];
        let styles = [FontStyle::Normal, FontStyle::Bold, FontStyle::Italic];
        let mut k = 0usize;
        for text in texts {
            for h in anchors {
                for v in vertical {
                    let font = FontDesc::new(
                        FontFamily::Name(FONT_FAMILY),
                        sizes[k % sizes.len()],
                        styles[k % styles.len()],
                    )
                    .transform(transforms[k % transforms.len()].clone());
                    let style = TextStyle {
                        font,
                        color: if k.is_multiple_of(4) {
                            grey.mix(0.9)
                        } else {
                            blue.into()
                        }
                        .to_backend_color(),
                        pos: Pos::new(h, v),
                    };
                    let at = (k as i32 * 13 - 40, 300 - k as i32 * 7);
                    root.draw(&Text::new(text.to_owned(), at, style)).unwrap();
                    k += 1;
                }
            }
        }
        let other_family = ("serif", 12.0).into_font().color(&RED);
        root.draw(&Text::new("serif & co", (5, 5), other_family))
            .unwrap();
    }

    #[test]
    fn writes_the_bytes_of_plotters_svg_backend() {
        ensure_font().unwrap();
        let size = (640, 480);
        let mut expected = String::new();
        {
            let root = SVGBackend::with_string(&mut expected, size).into_drawing_area();
            draw_everything(&root);
            root.present().unwrap();
        }
        let mut ours = String::new();
        {
            let root = SvgWriter::new(&mut ours, size).into_drawing_area();
            draw_everything(&root);
            root.present().unwrap();
        }
        for element in [
            "<polyline",
            "<line",
            "<rect",
            "<circle",
            "<polygon",
            "<text",
        ] {
            assert!(expected.contains(element), "{element} not drawn");
        }
        assert!(expected.contains("transform=\"rotate(90"));
        assert!(expected.contains("&amp;"));
        assert!(expected.contains("font-weight"));
        assert!(expected.contains("font-style"));
        assert!(expected.contains("opacity=\"0.9\""));
        assert_eq!(ours, expected);
    }

    #[test]
    fn closes_the_document_when_dropped_unpresented() {
        let (mut expected, mut ours) = (String::new(), String::new());
        drop(SVGBackend::with_string(&mut expected, (200, 100)));
        drop(SvgWriter::new(&mut ours, (200, 100)));
        assert_eq!(ours, expected);
    }
}
