//! Tick positions and labels: "nice" steps on linear axes, decades on log axes.

/// "Nice" tick positions and their labels for one axis.
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
        // (step mantissa, minor divisions, extra label digit: 2.5 needs one more than 1, 2, 5)
        let (mantissa, minor_div, extra_digit) = [
            (1.0, 5.0, 0),
            (2.0, 4.0, 0),
            (2.5, 5.0, 1),
            (5.0, 5.0, 0),
            (10.0, 5.0, 0),
        ]
        .into_iter()
        .find(|(m, _, _)| m * magnitude >= raw * (1.0 - 1e-9))
        .unwrap_or((10.0, 5.0, 0));
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
        let largest = lo.abs().max(hi.abs());
        let scientific = !(1e-3..1e6).contains(&largest);
        let labels = major
            .iter()
            .map(|&v| {
                let v = if v.abs() < step * 1e-6 { 0.0 } else { v };
                if scientific {
                    let digits = ((v.abs().max(step)).log10().floor() - step.log10().floor())
                        .clamp(0.0, 6.0) as usize
                        + extra_digit;
                    if v == 0.0 {
                        "0".to_owned()
                    } else {
                        format!("{v:.digits$e}")
                    }
                } else {
                    let decimals = (-step.log10().floor()).max(0.0) as usize
                        + usize::from(step < 10.0) * extra_digit;
                    format!("{v:.decimals$}")
                }
            })
            .collect();
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

/// A short label for a positive number: 4 significant digits, plain between 1e-3 and 1e5.
fn plain_number(x: f64) -> String {
    let rounded: f64 = format!("{x:.3e}").parse().unwrap_or(x);
    if (1e-3..1e5).contains(&rounded) {
        format!("{rounded}")
    } else {
        format!("{rounded:e}")
    }
}
