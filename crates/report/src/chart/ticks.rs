//! Tick positions and labels: "nice" steps on linear axes, decades on log axes.

/// "Nice" tick positions and their labels for one axis.
#[derive(Debug, Clone)]
pub(super) struct Ticks {
    pub(super) major: Vec<f64>,
    pub(super) minor: Vec<f64>,
    pub(super) labels: Vec<String>,
}

impl Ticks {
    pub(super) fn label(&self, v: f64) -> String {
        self.major
            .iter()
            .zip(&self.labels)
            .min_by(|a, b| (a.0 - v).abs().total_cmp(&(b.0 - v).abs()))
            .map(|(_, l)| l.clone())
            .unwrap_or_default()
    }

    pub(super) fn linear(lo: f64, hi: f64, max_ticks: usize) -> Ticks {
        let raw = (hi - lo) / max_ticks.max(1) as f64;
        let magnitude = 10f64.powf(raw.log10().floor());
        // (step mantissa, minor divisions per step)
        let (mantissa, minor_div) = [(1.0, 5.0), (2.0, 4.0), (2.5, 5.0), (5.0, 5.0), (10.0, 5.0)]
            .into_iter()
            .find(|(m, _)| m * magnitude >= raw * (1.0 - 1e-9))
            .unwrap_or((10.0, 5.0));
        let step = mantissa * magnitude;
        let first = (lo / step - 1e-9).ceil() as i64;
        let last = (hi / step + 1e-9).floor() as i64;
        let major: Vec<f64> = (first..=last).map(|k| k as f64 * step).collect();
        let minor_step = step / minor_div;
        let first_minor = (lo / minor_step - 1e-9).ceil() as i64;
        let last_minor = (hi / minor_step + 1e-9).floor() as i64;
        let minor = (first_minor..=last_minor)
            .map(|k| k as f64 * minor_step)
            .collect();
        let labels = linear_labels(&major, step, lo.abs().max(hi.abs()));
        Ticks {
            major,
            minor,
            labels,
        }
    }

    /// Ticks for an axis in log10 units; labels show the untransformed values.
    pub(super) fn log(lo: f64, hi: f64, max_ticks: usize) -> Ticks {
        let first = lo.ceil() as i64;
        let last = hi.floor() as i64;
        let in_range = |v: f64| v >= lo - 1e-9 && v <= hi + 1e-9;
        let multiples = |set: &[f64]| -> Vec<f64> {
            ((lo.floor() as i64)..=(hi.ceil() as i64))
                .flat_map(|k| set.iter().map(move |m| m.log10() + k as f64))
                .filter(|&v| in_range(v))
                .collect()
        };
        let (major, minor) = if last - first + 1 >= 2 {
            let decades: Vec<f64> = (first..=last).map(|k| k as f64).collect();
            let stride = decades.len().div_ceil(max_ticks.max(1));
            let major: Vec<f64> = decades.iter().copied().step_by(stride).collect();
            let minor = if stride == 1 && decades.len() <= 8 {
                multiples(&[2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0])
            } else {
                decades
            };
            (major, minor)
        } else {
            let major = multiples(&[1.0, 2.0, 5.0]);
            if major.len() >= 2 {
                (
                    major,
                    multiples(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]),
                )
            } else {
                // Less than a factor of 2.5: label evenly spaced values in log units.
                let lin = Ticks::linear(lo, hi, max_ticks);
                (lin.major, lin.minor)
            }
        };
        let labels = major.iter().map(|&v| plain_number(10f64.powf(v))).collect();
        Ticks {
            major,
            minor,
            labels,
        }
    }
}

/// Labels for tick values `step` apart: all with the same number of decimals (or of mantissa
/// digits in scientific notation, used when the axis reaches beyond [1e-3, 1e6)), the fewest
/// that represent every value to within a thousandth of a step.
fn linear_labels(values: &[f64], step: f64, largest: f64) -> Vec<String> {
    let scientific = !(1e-3..1e6).contains(&largest);
    let format = |v: f64, digits: usize| {
        // Values within rounding noise of zero are zero (and never "-0").
        let v = if v.abs() < step * 1e-6 { 0.0 } else { v };
        match (scientific, v == 0.0) {
            (true, true) => "0".to_owned(),
            (true, false) => format!("{v:.digits$e}"),
            (false, _) => format!("{v:.digits$}"),
        }
    };
    let exact = |labels: &[String]| {
        labels.iter().zip(values).all(|(l, v)| {
            l.parse::<f64>()
                .is_ok_and(|parsed| (parsed - v).abs() <= 1e-3 * step)
        })
    };
    const MAX_DIGITS: usize = 12;
    for digits in 0..MAX_DIGITS {
        let labels: Vec<String> = values.iter().map(|&v| format(v, digits)).collect();
        if exact(&labels) {
            return labels;
        }
    }
    values.iter().map(|&v| format(v, MAX_DIGITS)).collect()
}

/// A short label for a positive number: 4 significant digits, plain between 1e-3 and 1e5.
fn plain_number(x: f64) -> String {
    let rounded: f64 = format!("{x:.3e}").parse().unwrap_or(x);
    if (1e-3..1e5).contains(&rounded) {
        format!("{rounded}")
    } else {
        format!("{rounded:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_use_nice_steps_and_consistent_labels() {
        let t = Ticks::linear(-10.4, 10.4, 9);
        assert_eq!(
            t.labels,
            [
                "-10.0", "-7.5", "-5.0", "-2.5", "0.0", "2.5", "5.0", "7.5", "10.0"
            ]
        );
        let t = Ticks::linear(-0.05, 1.05, 6);
        assert_eq!(t.labels, ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
        let t = Ticks::linear(-1.05e300, 1.05e300, 5);
        assert_eq!(t.labels, ["-1e300", "-5e299", "0", "5e299", "1e300"]);
        let t = Ticks::linear(0.0, 1.0e-9, 4);
        assert_eq!(t.labels, ["0", "2.5e-10", "5.0e-10", "7.5e-10", "1.0e-9"]);
    }

    #[test]
    fn minor_ticks_subdivide_major_steps() {
        let t = Ticks::linear(0.0, 10.0, 5); // step 2 -> minor 0.5
        assert_eq!(t.major.len(), 6);
        assert_eq!(t.minor.len(), 21);
    }

    #[test]
    fn log_ticks_label_decades_or_1_2_5() {
        // Axis in log10 units: 0.5 .. 4.2 is 3.2 .. 15849.
        let t = Ticks::log(0.5, 4.2, 10);
        assert_eq!(t.labels, ["10", "100", "1000", "10000"]);
        assert_eq!(t.minor.len(), 8 * 3 + 6); // 2..9 in three full decades, 4..9 below 10
        let t = Ticks::log(0.2, 0.8, 10); // 1.58 .. 6.3
        assert_eq!(t.labels, ["2", "5"]);
        let t = Ticks::log(-30.0, 30.0, 4); // too many decades: every 16th
        assert_eq!(t.labels, ["1e-30", "1e-14", "100", "1e18"]);
    }
}
