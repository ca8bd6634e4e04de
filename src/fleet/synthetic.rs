//! Worn S1002 wheel profiles, generated: the fleet of the tests, the benchmark and the
//! example report. Deterministic from a seed and an index, so a fleet can be regenerated
//! instead of committed.
//!
//! A profile is the analytic S1002 sampled every `STEP_MM` with three defects of varying
//! depth ([`Wear::of`]):
//!
//! * **tread hollow wear**: the radius reduced by `hollow_mm · cos²(π (s - c) / (2 W))` over
//!   `|s - c| < W` (`HOLLOW_HALF_WIDTH_MM`), `c` near the taping line: the running band
//!   worn into a groove, leaving a false flange on the field side (conicity rises);
//! * **flange wear**: the flange face thinned laterally by `flange_mm`: the radius
//!   reduced by `flange_mm · |dF/ds| · cos²` over the flank (a lateral shift of the face by
//!   about `flange_mm` where it is steep);
//! * **measurement noise**: independent normal errors of standard deviation `noise_mm` on
//!   every radius, as a gauge's repeatability.
//!
//! [`csv_text`] writes the points as a wheel profile CSV file that the readers accept.

use crate::profile::Profile;
use crate::rng::SplitMix64;

/// Lateral spacing of the generated points (mm): a MiniProf-like density.
pub(crate) const STEP_MM: f64 = 0.25;
/// The generated profile starts here (mm): 1 mm into the flange back from its vertical face
/// at -70 mm, where measured profiles begin too.
pub(crate) const S_FROM_MM: f64 = -69.0;
/// Half width of the hollow-worn band (mm).
pub(crate) const HOLLOW_HALF_WIDTH_MM: f64 = 22.0;
/// Centre and half width of the worn flange face (mm).
pub(crate) const FLANGE_WEAR_BAND_MM: (f64, f64) = (-40.0, 12.0);

/// The defects of one generated profile (mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wear {
    /// Depth of the hollow at its centre (mm, 0 to 2.5).
    pub hollow_mm: f64,
    /// Lateral position of the hollow's centre (mm, -3 to 5).
    pub hollow_centre_mm: f64,
    /// Lateral thinning of the flange face (mm, 0 to 2).
    pub flange_mm: f64,
    /// Standard deviation of the measurement noise (mm, 0.001 to 0.02).
    pub noise_mm: f64,
}

impl Wear {
    /// The wear of profile `index` of the fleet `seed`: depths drawn uniformly (the hollow
    /// skewed to shallow, as most wheels in service are), reproducible on every machine.
    pub fn of(seed: u64, index: u64) -> Wear {
        let mut rng = SplitMix64::new(seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15));
        let u = [rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform()];
        Wear {
            hollow_mm: 2.5 * u[0] * u[0],
            hollow_centre_mm: -3.0 + 8.0 * u[1],
            flange_mm: 2.0 * u[2],
            noise_mm: 0.001 + 0.019 * u[3],
        }
    }
}

/// The points `[s, F]` (mm, wheel side frame) of S1002 with `wear`, noise drawn from
/// `noise_seed`.
///
/// ```
/// use wheelrail::fleet::synthetic::{worn_s1002, Wear};
/// let new = Wear { hollow_mm: 0.0, hollow_centre_mm: 0.0, flange_mm: 0.0, noise_mm: 0.0 };
/// let points = worn_s1002(&new, 1);
/// // The taping line of a new S1002 is at F = 0.
/// let taping = points.iter().find(|p| p[0] == 0.0).unwrap();
/// assert!(taping[1].abs() < 1e-12);
/// let worn = worn_s1002(&Wear { hollow_mm: 1.0, ..new }, 1);
/// let taping = worn.iter().find(|p| p[0] == 0.0).unwrap();
/// assert!((taping[1] + 1.0).abs() < 1e-12);
/// ```
pub fn worn_s1002(wear: &Wear, noise_seed: u64) -> Vec<[f64; 2]> {
    let s1002 = Profile::s1002();
    let (_, s_max) = s1002.domain();
    let n = ((s_max - S_FROM_MM) / STEP_MM).floor() as usize;
    let mut rng = SplitMix64::new(noise_seed);
    (0..=n)
        .map(|i| {
            let s = S_FROM_MM + i as f64 * STEP_MM;
            let [f, slope, _] = s1002.eval(s);
            let hollow = wear.hollow_mm * bump(s, wear.hollow_centre_mm, HOLLOW_HALF_WIDTH_MM);
            let (c, w) = FLANGE_WEAR_BAND_MM;
            let flange = wear.flange_mm * slope.abs() * bump(s, c, w);
            let noise = if wear.noise_mm > 0.0 {
                wear.noise_mm * rng.normal()
            } else {
                0.0
            };
            [s, f - hollow - flange + noise]
        })
        .collect()
}

/// `cos²(π (s - c) / (2 w))` inside `|s - c| < w`, 0 outside: a smooth bump of height 1.
fn bump(s: f64, c: f64, w: f64) -> f64 {
    let x = (s - c) / w;
    if x.abs() >= 1.0 {
        0.0
    } else {
        (std::f64::consts::FRAC_PI_2 * x).cos().powi(2)
    }
}

/// Profile `index` of the fleet `seed` as a wheel profile CSV file (`# ` comment lines
/// naming the wear, then `s_mm,F_mm`), with its [`Wear`].
///
/// ```
/// use wheelrail::fleet::synthetic::csv_text;
/// use wheelrail::profile::{ProfileKind, read::{parse_str, ProfileFormat}};
/// let (text, _) = csv_text(7, 3);
/// let points = parse_str(&text, ProfileFormat::Csv, ProfileKind::Wheel, "w.csv").unwrap();
/// assert!(points.points.len() > 500);
/// assert_eq!(csv_text(7, 3).0, text); // deterministic
/// ```
pub fn csv_text(seed: u64, index: u64) -> (String, Wear) {
    let wear = Wear::of(seed, index);
    let points = worn_s1002(
        &wear,
        seed.wrapping_add(index).wrapping_mul(0xD1B5_4A32_D192_ED03),
    );
    let mut text = format!(
        "# worn S1002 generated by wheelrail {} (fleet::synthetic, seed {seed}, index {index})\n\
         # hollow_mm {:.4} centred at s = {:.3} mm, flange_mm {:.4}, noise_mm {:.4}\n\
         # frame: wheel side frame: s_mm from the taping line, positive towards the field side (flange at s < 0); F_mm radius increase over the nominal radius\n\
         s_mm,F_mm\n",
        env!("CARGO_PKG_VERSION"),
        wear.hollow_mm,
        wear.hollow_centre_mm,
        wear.flange_mm,
        wear.noise_mm
    );
    for [s, f] in points {
        text.push_str(&format!("{s:.3},{f:.6}\n"));
    }
    (text, wear)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wear_varies_within_its_documented_ranges() {
        let wears: Vec<Wear> = (0..200).map(|i| Wear::of(1, i)).collect();
        for w in &wears {
            assert!((0.0..=2.5).contains(&w.hollow_mm));
            assert!((-3.0..=5.0).contains(&w.hollow_centre_mm));
            assert!((0.0..=2.0).contains(&w.flange_mm));
            assert!((0.001..=0.02).contains(&w.noise_mm));
        }
        let deep = wears.iter().filter(|w| w.hollow_mm > 1.5).count();
        assert!(deep > 10 && deep < 100, "{deep} deep hollows of 200");
    }

    #[test]
    fn noise_has_the_requested_spread() {
        let clean = Wear {
            hollow_mm: 0.0,
            hollow_centre_mm: 0.0,
            flange_mm: 0.0,
            noise_mm: 0.0,
        };
        let noisy = Wear {
            noise_mm: 0.01,
            ..clean
        };
        let a = worn_s1002(&clean, 3);
        let b = worn_s1002(&noisy, 3);
        let n = a.len() as f64;
        let rms = (a
            .iter()
            .zip(&b)
            .map(|(p, q)| (p[1] - q[1]).powi(2))
            .sum::<f64>()
            / n)
            .sqrt();
        // 521 samples: the sample deviation is within 10 % of sigma with overwhelming odds.
        assert!((rms - 0.01).abs() < 1e-3, "rms {rms}");
    }
}
