//! SIMPACK `.prw` / `.prr` profiles; format, order of operations and frame mapping in the
//! [parent module docs](super).

use super::error::{Field, ReadError};
use super::fields::{self, RawPoint};
use crate::profile::ProfileKind;

const EXPECTED_POINT: &str = "a number in the file's length unit (units.len.f)";

/// Rotations smaller than this (rad) are taken as "no rotation": files write `0` or
/// `+0.000000000000000e+00`, and anything a user meant as a rotation is far larger.
const ROTATION_ZERO_TOLERANCE_RAD: f64 = 1e-12;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Block {
    Outside,
    Header,
    Spline,
    Points,
}

impl Block {
    fn name(self) -> &'static str {
        match self {
            Block::Outside => "file",
            Block::Header => "header",
            Block::Spline => "spline",
            Block::Points => "point",
        }
    }
}

/// A numeric entry and the line it was on.
#[derive(Debug, Clone, Copy)]
struct Entry {
    value: f64,
    line: usize,
}

/// The processing entries of the spline block, with SIMPACK's defaults.
#[derive(Debug)]
struct Processing {
    point_dist_min: f64,
    shift: [f64; 2],
    rotate: Option<Entry>,
    bound_y: [f64; 2],
    bound_z: [f64; 2],
    mirror_y: bool,
    mirror_z: bool,
    inversion: bool,
    units_len: Entry,
    units_ang: Entry,
}

impl Default for Processing {
    fn default() -> Self {
        Processing {
            point_dist_min: 0.0,
            shift: [0.0; 2],
            rotate: None,
            // min >= max disables a bound, as in the benchmark files.
            bound_y: [1.0, 0.0],
            bound_z: [1.0, 0.0],
            mirror_y: false,
            mirror_z: false,
            inversion: false,
            // SIMPACK works in SI units: without units.len.f the lengths are metres.
            units_len: Entry {
                value: 1.0,
                line: 0,
            },
            units_ang: Entry {
                value: 1.0,
                line: 0,
            },
        }
    }
}

/// Cuts a `!` or `%` comment, except inside a single-quoted string.
fn strip_comment(line: &str) -> &str {
    let mut quoted = false;
    for (i, c) in line.char_indices() {
        match c {
            '\'' => quoted = !quoted,
            '!' | '%' if !quoted => return &line[..i],
            _ => {}
        }
    }
    line
}

/// Parses a SIMPACK profile and returns its points in the side frame of `kind`.
pub(super) fn parse(
    text: &str,
    kind: ProfileKind,
    origin: &str,
) -> Result<Vec<RawPoint>, ReadError> {
    let mut reader = Reader::new(origin);
    let mut saw_content = false;
    let mut last_line = 0;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        last_line = line;
        let content = strip_comment(raw).trim();
        if content.is_empty() {
            continue;
        }
        saw_content = true;
        reader.line(content, line)?;
    }
    if !saw_content {
        return Err(ReadError::Empty {
            origin: origin.to_owned(),
        });
    }
    reader.finish(kind, last_line)
}

/// What a SIMPACK file has said so far, read line by line.
struct Reader<'a> {
    origin: &'a str,
    block: Block,
    saw_points_block: bool,
    /// The header's `type` and its line.
    declared: Option<(ProfileKind, usize)>,
    proc: Processing,
    /// Points in file units and file axes, before processing.
    points: Vec<RawPoint>,
}

impl<'a> Reader<'a> {
    fn new(origin: &'a str) -> Reader<'a> {
        Reader {
            origin,
            block: Block::Outside,
            saw_points_block: false,
            declared: None,
            proc: Processing::default(),
            points: Vec::new(),
        }
    }

    fn malformed(&self, line: usize, problem: String) -> ReadError {
        malformed(self.origin, line, problem)
    }

    /// Reads one line's content (comment cut, trimmed, not empty).
    fn line(&mut self, content: &str, line: usize) -> Result<(), ReadError> {
        if self.block_marker(content, line)? {
            return Ok(());
        }
        match self.block {
            Block::Outside => Err(self.malformed(
                line,
                format!("unexpected text outside the header and spline blocks: `{content}`"),
            )),
            Block::Points => {
                self.points.push(point_row(content, self.origin, line)?);
                Ok(())
            }
            Block::Header | Block::Spline => {
                let Some((key, value)) = content.split_once('=') else {
                    return Err(self.malformed(
                        line,
                        format!("expected `key = value` in the {} block", self.block.name()),
                    ));
                };
                let (key, value) = (key.trim(), value.trim());
                if self.block == Block::Header {
                    self.header_entry(key, value, line)
                } else {
                    self.spline_entry(key, value, line)
                }
            }
        }
    }

    /// Enters or leaves a block if `content` is a block marker; whether it was one.
    fn block_marker(&mut self, content: &str, line: usize) -> Result<bool, ReadError> {
        let next = match content {
            "header.begin" => Some((Block::Outside, Block::Header)),
            "header.end" => Some((Block::Header, Block::Outside)),
            "spline.begin" => Some((Block::Outside, Block::Spline)),
            "spline.end" => Some((Block::Spline, Block::Outside)),
            "point.begin" => Some((Block::Spline, Block::Points)),
            "point.end" => Some((Block::Points, Block::Spline)),
            _ => None,
        };
        let Some((required, entered)) = next else {
            return Ok(false);
        };
        if self.block != required {
            return Err(self.malformed(
                line,
                format!(
                    "`{content}` inside the {} block (misnested or missing block markers)",
                    self.block.name()
                ),
            ));
        }
        if entered == Block::Points {
            if self.saw_points_block {
                return Err(self.malformed(line, "a second point block".to_owned()));
            }
            self.saw_points_block = true;
        }
        self.block = entered;
        Ok(true)
    }

    /// A `key = value` of the header: only `type` (0 rail, 1 wheel) matters.
    fn header_entry(&mut self, key: &str, value: &str, line: usize) -> Result<(), ReadError> {
        if key == "type" {
            let found = match number(self.origin, key, value, line)? {
                t if t.abs() < 0.5 => ProfileKind::Rail,
                t if (t - 1.0).abs() < 0.5 => ProfileKind::Wheel,
                _ => {
                    return Err(self.malformed(
                        line,
                        format!("type = {value}: expected 0 (rail) or 1 (wheel)"),
                    ));
                }
            };
            self.declared = Some((found, line));
        }
        Ok(())
    }

    /// A `key = value` of the spline block: the processing of the points.
    fn spline_entry(&mut self, key: &str, value: &str, line: usize) -> Result<(), ReadError> {
        let origin = self.origin;
        let num = |key: &str| number(origin, key, value, line);
        let flag = |key: &str| -> Result<bool, ReadError> {
            match num(key)? {
                v if v.abs() < 0.5 => Ok(false),
                v if (v - 1.0).abs() < 0.5 => Ok(true),
                _ => Err(malformed(
                    origin,
                    line,
                    format!("{key} = {value}: expected 0 or 1"),
                )),
            }
        };
        let entry = |key: &str| num(key).map(|value| Entry { value, line });
        let proc = &mut self.proc;
        match key {
            "point.dist.min" => proc.point_dist_min = num(key)?,
            "shift.y" => proc.shift[0] = num(key)?,
            "shift.z" => proc.shift[1] = num(key)?,
            "rotate" => proc.rotate = Some(entry(key)?),
            "bound.y.min" => proc.bound_y[0] = num(key)?,
            "bound.y.max" => proc.bound_y[1] = num(key)?,
            "bound.z.min" => proc.bound_z[0] = num(key)?,
            "bound.z.max" => proc.bound_z[1] = num(key)?,
            "mirror.y" => proc.mirror_y = flag(key)?,
            "mirror.z" => proc.mirror_z = flag(key)?,
            "inversion" => proc.inversion = flag(key)?,
            "units.len.f" => proc.units_len = entry(key)?,
            "units.ang.f" => proc.units_ang = entry(key)?,
            // approx.smooth (SIMPACK's own smoothing), file, comment, type, ... do not
            // change the points.
            _ => {}
        }
        Ok(())
    }

    /// Checks the file as a whole and returns its points processed, in the side frame of
    /// `kind`.
    fn finish(self, kind: ProfileKind, last_line: usize) -> Result<Vec<RawPoint>, ReadError> {
        let origin = self.origin;
        if self.block != Block::Outside {
            return Err(self.malformed(
                last_line,
                format!(
                    "the file ends inside the {0} block (missing `{0}.end`): truncated?",
                    self.block.name()
                ),
            ));
        }
        if !self.saw_points_block {
            return Err(self.malformed(
                last_line,
                "no `point.begin ... point.end` block in the file".to_owned(),
            ));
        }
        let declared = self.declared.map(|(k, line)| (k, Some(line)));
        super::validate::check_kind(declared, kind, origin)?;
        let proc = self.proc;
        for (key, unit) in [
            ("units.len.f", proc.units_len),
            ("units.ang.f", proc.units_ang),
        ] {
            if unit.value <= 0.0 {
                return Err(ReadError::BadUnitFactor {
                    origin: origin.to_owned(),
                    line: unit.line,
                    key,
                    value: unit.value,
                });
            }
        }
        let mut points = self.points;
        apply_processing(&mut points, &proc, origin)?;
        // SIMPACK frame -> side frame: wheels are (s, F) = (y, z) already; rail z points down.
        if kind == ProfileKind::Rail {
            for p in &mut points {
                p.vert = -p.vert;
            }
        }
        Ok(points)
    }
}

fn malformed(origin: &str, line: usize, problem: String) -> ReadError {
    ReadError::Malformed {
        origin: origin.to_owned(),
        line,
        problem,
    }
}

/// The number of `key = value`, an error naming the key otherwise.
fn number(origin: &str, key: &str, value: &str, line: usize) -> Result<f64, ReadError> {
    fields::number(value, origin, line, Field::Key(key.to_owned()), "a number")
}

fn point_row(content: &str, origin: &str, line: usize) -> Result<RawPoint, ReadError> {
    let mut values = [0.0; 2];
    let mut count = 0;
    for (i, token) in fields::tokens(content).enumerate() {
        match i {
            0 | 1 => {
                values[i] =
                    fields::number(token, origin, line, Field::Column(i + 1), EXPECTED_POINT)?;
            }
            // The optional weight (SIMPACK's approximation weight) does not change the points
            // but must still be a number.
            2 => {
                fields::number(token, origin, line, Field::Column(3), "a weight (number)")?;
            }
            _ => {
                return Err(ReadError::Malformed {
                    origin: origin.to_owned(),
                    line,
                    problem: "more than three values on a point row (expected `y z [weight]`)"
                        .to_owned(),
                });
            }
        }
        count = i + 1;
    }
    if count < 2 {
        return Err(ReadError::MissingField {
            origin: origin.to_owned(),
            line,
            column: count + 1,
        });
    }
    Ok(RawPoint {
        lat: values[0],
        vert: values[1],
        line,
    })
}

/// Applies SIMPACK's processing steps 1-7 in order (see the parent module docs).
fn apply_processing(
    points: &mut Vec<RawPoint>,
    proc: &Processing,
    origin: &str,
) -> Result<(), ReadError> {
    // 1: minimum point distance, in file units, against the last kept point.
    if proc.point_dist_min > 0.0 {
        let mut kept: Vec<RawPoint> = Vec::with_capacity(points.len());
        for p in points.drain(..) {
            let far = kept
                .last()
                .is_none_or(|q| (p.lat - q.lat).hypot(p.vert - q.vert) >= proc.point_dist_min);
            if far {
                kept.push(p);
            }
        }
        *points = kept;
    }
    // 2: shift.
    for p in points.iter_mut() {
        p.lat += proc.shift[0];
        p.vert += proc.shift[1];
    }
    // 3: rotation, refused unless zero.
    if let Some(rotate) = proc.rotate {
        let angle_rad = rotate.value / proc.units_ang.value;
        if angle_rad.abs() >= ROTATION_ZERO_TOLERANCE_RAD {
            return Err(ReadError::UnsupportedRotation {
                origin: origin.to_owned(),
                line: rotate.line,
                angle_rad,
            });
        }
    }
    // 4: bounds: y drops points, z clips.
    let [y_min, y_max] = proc.bound_y;
    if y_min < y_max {
        points.retain(|p| (y_min..=y_max).contains(&p.lat));
    }
    let [z_min, z_max] = proc.bound_z;
    if z_min < z_max {
        for p in points.iter_mut() {
            p.vert = p.vert.clamp(z_min, z_max);
        }
    }
    // 5: mirroring.
    for p in points.iter_mut() {
        if proc.mirror_y {
            p.lat = -p.lat;
        }
        if proc.mirror_z {
            p.vert = -p.vert;
        }
    }
    // 6: inversion of the point order.
    if proc.inversion {
        points.reverse();
    }
    // 7: units: units.len.f is the length unit per metre, so 1000 / f converts to mm.
    let to_mm = 1000.0 / proc.units_len.value;
    for p in points.iter_mut() {
        p.lat *= to_mm;
        p.vert *= to_mm;
        // A huge file value times a large factor could overflow; report it like a bad value.
        if !(p.lat.is_finite() && p.vert.is_finite()) {
            return Err(ReadError::NonFinite {
                origin: origin.to_owned(),
                line: p.line,
                field: Field::Column(if p.lat.is_finite() { 2 } else { 1 }),
                value: "(overflows after unit conversion)".to_owned(),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_respect_quotes() {
        assert_eq!(strip_comment("comment = 'a!b' ! note"), "comment = 'a!b' ");
        assert_eq!(strip_comment("!7.0 9.5"), "");
        assert_eq!(strip_comment("%   -299.7  286.5"), "");
    }
}
