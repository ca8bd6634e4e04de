//! The profile readers on arbitrary text: the first byte chooses the format, the kind and the
//! step-back option, the rest is the file. Whatever the text, `parse_str_with` returns, and a
//! profile it accepts satisfies the `PointProfile` invariants and fits a spline that
//! evaluates to finite values.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wheelrail::profile::read::{ProfileFormat, ReadOptions, StepBack, parse_str_with};
use wheelrail::profile::{Profile, ProfileKind};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let format = [
        ProfileFormat::Csv,
        ProfileFormat::Simpack,
        ProfileFormat::MiniProf,
    ][usize::from(selector % 3)];
    let kind = if (selector / 3) % 2 == 0 {
        ProfileKind::Wheel
    } else {
        ProfileKind::Rail
    };
    let step_back = if (selector / 6) % 2 == 0 {
        StepBack::Refuse
    } else {
        StepBack::Drop
    };
    let text = String::from_utf8_lossy(rest);
    let Ok(profile) = parse_str_with(&text, format, kind, "fuzz", &ReadOptions::new(step_back))
    else {
        return;
    };
    assert!(profile.points.len() >= wheelrail::profile::read::PointProfile::MIN_POINTS);
    assert!(profile.points.windows(2).all(|w| w[1][0] > w[0][0]));
    assert!(profile.points.iter().flatten().all(|v| v.is_finite()));
    let smoothing = if (selector / 12) % 2 == 0 { 0.0 } else { 4.0 };
    if let Ok(p) = Profile::from_points(profile, smoothing) {
        let (lo, hi) = p.domain();
        for k in 0..=16 {
            let u = lo + (hi - lo) * f64::from(k) / 16.0;
            assert!(p.eval(u).iter().all(|v| v.is_finite()), "{u}");
        }
    }
});
