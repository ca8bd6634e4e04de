//! The legend box: one row per labelled series, then the note on values off the chart.

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::super::geometry::AxisMap;
use super::super::text::{Align, Place, TextMode, TextSpec, draw_text};
use super::super::{Chart, ChartError, LegendPosition, SeriesStyle, drawing_error};
use super::annotations::{OffChart, off_chart_note};
use super::series::Look;
use super::{ANNOTATION, PxRect};

const LEGEND_PX: f64 = 16.0;
/// Legend: length of the line sample, inner padding, row height factor.
const LEGEND_GLYPH_PX: i32 = 30;
const LEGEND_PAD_PX: i32 = 8;
const LEGEND_ROW: f64 = 1.35;

/// Legend entries: series with a label; a series with nothing to draw says so.
fn legend_entries(chart: &Chart, xmap: AxisMap, ymap: AxisMap) -> Vec<(usize, String)> {
    chart
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.label.is_empty())
        .map(|(i, s)| {
            let any = s
                .points
                .iter()
                .any(|&(x, y)| xmap.forward(x).is_finite() && ymap.forward(y).is_finite());
            let label = if any {
                s.label.clone()
            } else {
                format!("{} (no data)", s.label)
            };
            (i, label)
        })
        .collect()
}

/// The legend's content: one row per labelled series, then the note on values off the chart.
pub(super) struct LegendBox {
    entries: Vec<(usize, String)>,
    note: Option<String>,
    hidden: bool,
}

impl LegendBox {
    pub(super) fn of(
        chart: &Chart,
        xmap: AxisMap,
        ymap: AxisMap,
        off_chart: &[OffChart],
    ) -> LegendBox {
        LegendBox {
            entries: legend_entries(chart, xmap, ymap),
            note: off_chart_note(off_chart, ymap),
            hidden: chart.legend == LegendPosition::Hidden,
        }
    }

    fn rows(&self) -> usize {
        if self.hidden {
            usize::from(self.note.is_some())
        } else {
            self.entries.len() + usize::from(self.note.is_some())
        }
    }

    /// Width and height in pixels; `None` when there is nothing to show.
    pub(super) fn size(&self) -> Option<(i32, i32)> {
        if self.rows() == 0 {
            return None;
        }
        let spec = TextSpec::new(LEGEND_PX);
        let row_h = (LEGEND_PX * LEGEND_ROW).round() as i32;
        let widest_entry = if self.hidden {
            0
        } else {
            self.entries
                .iter()
                .map(|(_, l)| LEGEND_GLYPH_PX + LEGEND_PAD_PX + spec.size(l).0)
                .max()
                .unwrap_or(0)
        };
        let note = self.note.as_deref().map_or(0, |n| spec.size(n).0);
        let w = 2 * LEGEND_PAD_PX + widest_entry.max(note);
        let h = 2 * LEGEND_PAD_PX + row_h * self.rows() as i32;
        Some((w, h))
    }

    pub(super) fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &Chart,
        (left, top, right, bottom): PxRect,
        mode: TextMode,
    ) -> Result<(), ChartError> {
        let spec = TextSpec::new(LEGEND_PX);
        let row_h = (LEGEND_PX * LEGEND_ROW).round() as i32;
        root.draw(&Rectangle::new(
            [(left, top), (right, bottom)],
            WHITE.mix(0.9).filled(),
        ))
        .map_err(drawing_error)?;
        root.draw(&Rectangle::new(
            [(left, top), (right, bottom)],
            RGBColor(0x99, 0x99, 0x99).stroke_width(1),
        ))
        .map_err(drawing_error)?;
        let entries: &[(usize, String)] = if self.hidden { &[] } else { &self.entries };
        let row_y = |row: usize| top + LEGEND_PAD_PX + row_h * row as i32 + row_h / 2;
        for (row, (index, label)) in entries.iter().enumerate() {
            let series = &chart.series[*index];
            let y = row_y(row);
            let x = left + LEGEND_PAD_PX;
            let look = Look::of(series, *index);
            if !matches!(series.style, SeriesStyle::Markers) {
                let path = vec![(x, y), (x + LEGEND_GLYPH_PX, y)];
                if series.dashed {
                    root.draw(&DashedPathElement::new(path, 8, 4, look.line))
                } else {
                    root.draw(&PathElement::new(path, look.line))
                }
                .map_err(drawing_error)?;
            }
            if matches!(
                series.style,
                SeriesStyle::Markers | SeriesStyle::LineWithMarkers
            ) {
                root.draw(&(EmptyElement::at((x + LEGEND_GLYPH_PX / 2, y)) + look.marker::<DB>()))
                    .map_err(drawing_error)?;
            }
            let place = Place::new(
                (x + LEGEND_GLYPH_PX + LEGEND_PAD_PX, y),
                Align::Start,
                Align::Middle,
            );
            draw_text(root, mode, label, spec, place)?;
        }
        if let Some(note) = &self.note {
            let place = Place::new(
                (left + LEGEND_PAD_PX, row_y(entries.len())),
                Align::Start,
                Align::Middle,
            );
            draw_text(root, mode, note, spec.color(ANNOTATION), place)?;
        }
        Ok(())
    }
}
