//! Wheel and rail profiles: analytic definitions (S1002, UIC60) and sampled profiles read
//! from files, with their heights, slopes and curvatures.
//!
//! A [`Profile`] is a curve `v(u)` in its own side frame (see the crate docs):
//!
//! * wheel: `u = s` (mm) from the taping line, + towards the field side; `v = F(s)` (mm), the
//!   radius increase, + towards the flange tip;
//! * rail: `u = y` (mm) lateral, + towards the field side; `v = z` (mm) height, + up.
//!
//! In both frames the vertical coordinate grows *towards the other body*'s side of the
//! surface only for the wheel; the functions below hide that: [`Profile::tan_gamma`] is
//! positive on a tread sloping down towards the field side for both, and
//! [`Profile::convex_curvature`] is positive where the surface bulges towards the other body
//! (wheel flange tip, rail crown).

pub(crate) mod bounds;
pub mod read;
mod s1002;
pub mod spline;
mod uic60;

pub use spline::SplineError;

use spline::SmoothingSpline;

/// Whether a profile describes a wheel or a rail; decides its side frame (see the crate docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ProfileKind {
    /// Wheel: lateral `s` from the taping line (+ field side), vertical `F` = radius increase
    /// (+ towards the flange tip).
    Wheel,
    /// Rail: lateral coordinate (+ field side), vertical = height (+ up).
    Rail,
}

impl std::fmt::Display for ProfileKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ProfileKind::Wheel => "wheel",
            ProfileKind::Rail => "rail",
        })
    }
}

/// Where a profile comes from, for the report's provenance table.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// A definition built into wheelrail, described in words.
    Definition(&'static str),
    /// A profile file, with the SHA-256 of its bytes (hex).
    File {
        /// The path as given in the scene.
        path: String,
        /// SHA-256 of the file's bytes, lower-case hex.
        sha256: String,
    },
}

impl std::fmt::Display for Source {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Source::Definition(d) => f.write_str(d),
            Source::File { path, sha256 } => write!(f, "{path} (sha256 {sha256})"),
        }
    }
}

/// The shape of a profile: an analytic definition or a spline through sampled points.
///
/// The spline is shared by the profile's clones (it is never changed once fitted): an equal
/// wheel on the other side, a fleet's pairs and the placement cache clone profiles, and a
/// 1000-point spline is some 56 kB to copy and to fault in.
#[derive(Debug, Clone)]
enum Shape {
    S1002,
    Uic60,
    Sampled(std::sync::Arc<SmoothingSpline>),
}

/// A wheel or rail profile: `v(u)` with exact or spline derivatives, in its side frame.
#[derive(Debug, Clone)]
pub struct Profile {
    kind: ProfileKind,
    name: String,
    source: Source,
    shape: Shape,
    /// The points a sampled profile was read from, as the spline was fitted to them (before
    /// any smoothing); `None` for a built-in definition. Shared by clones, as the spline is.
    points: Option<std::sync::Arc<[[f64; 2]]>>,
}

impl Profile {
    /// The names of the built-in profiles, as scenes, `wheelrail profile` and
    /// [`Profile::built_in`] accept them (which also reads `UIC60` and `60E1`, any case).
    pub const BUILT_IN: [&'static str; 2] = ["S1002", "UIC60E1"];

    /// The S1002 wheel (EN 13715, 28 mm flange height, 32.5 mm flange thickness).
    pub fn s1002() -> Profile {
        Profile {
            kind: ProfileKind::Wheel,
            name: "S1002".into(),
            source: Source::Definition(
                "S1002 (EN 13715, flange 28 / 32.5 mm), piecewise analytic definition (DLR, H. Netter)",
            ),
            shape: Shape::S1002,
            points: None,
        }
    }

    /// The UIC60 (60E1) rail head, upright (EN 13674-1: R300, R80, R13, 1:20 flank).
    pub fn uic60e1() -> Profile {
        Profile {
            kind: ProfileKind::Rail,
            name: "UIC60E1".into(),
            source: Source::Definition(
                "UIC60 / 60E1 head (EN 13674-1): arcs R300, R80, R13 and 1:20 flank, upright",
            ),
            shape: Shape::Uic60,
            points: None,
        }
    }

    /// A built-in profile by name (case-insensitive: `S1002`, `UIC60E1`, also `UIC60`, `60E1`).
    pub fn built_in(name: &str) -> Option<Profile> {
        match name.to_ascii_uppercase().as_str() {
            "S1002" => Some(Profile::s1002()),
            "UIC60E1" | "UIC60" | "60E1" => Some(Profile::uic60e1()),
            _ => None,
        }
    }

    /// A profile through sampled points: a cubic spline that filters out waves shorter than
    /// about `smoothing_wavelength_mm` (0 interpolates the points; see
    /// `spline::lambda_for_wavelength`).
    ///
    /// # Errors
    /// [`spline::SplineError`] when the spline cannot be fitted to the points.
    pub fn from_points(
        points: read::PointProfile,
        smoothing_wavelength_mm: f64,
    ) -> Result<Profile, spline::SplineError> {
        let (x, y) = points.columns();
        let lambda = match (x.first(), x.last()) {
            (Some(a), Some(b)) if x.len() > 1 && smoothing_wavelength_mm > 0.0 => {
                spline::lambda_for_wavelength(
                    smoothing_wavelength_mm,
                    (b - a) / (x.len() - 1) as f64,
                )
            }
            _ => 0.0,
        };
        let spline = SmoothingSpline::fit(&x, &y, lambda)?;
        let name = std::path::Path::new(&points.source.path)
            .file_name()
            .map_or_else(
                || points.source.path.clone(),
                |n| n.to_string_lossy().into_owned(),
            );
        Ok(Profile {
            kind: points.kind,
            name,
            source: Source::File {
                path: points.source.path.clone(),
                sha256: points.source.sha256.clone(),
            },
            shape: Shape::Sampled(std::sync::Arc::new(spline)),
            points: Some(points.points.into()),
        })
    }

    /// Whether `other` has this profile's data to the bit (the same definition, or a spline
    /// through the same points with the same filter): its numbers are the same everywhere.
    /// The name and source, which only label it, may differ.
    pub(crate) fn same_data(&self, other: &Profile) -> bool {
        self.kind == other.kind
            && match (&self.shape, &other.shape) {
                (Shape::S1002, Shape::S1002) | (Shape::Uic60, Shape::Uic60) => true,
                (Shape::Sampled(a), Shape::Sampled(b)) => {
                    std::sync::Arc::ptr_eq(a, b) || a.same_data(b)
                }
                _ => false,
            }
            && match (&self.points, &other.points) {
                (Some(a), Some(b)) => {
                    std::sync::Arc::ptr_eq(a, b)
                        || a.as_flattened()
                            .iter()
                            .map(|v| v.to_bits())
                            .eq(b.as_flattened().iter().map(|v| v.to_bits()))
                }
                (a, b) => a.is_none() && b.is_none(),
            }
    }

    /// The points a sampled profile was read from (`[u, v]` in mm, side frame, strictly
    /// increasing `u`), as the reader kept them and before the spline's smoothing; `None`
    /// for a built-in definition. What a gauge measured, for dimensions that must not
    /// depend on the filter chosen for the contact (`maintenance::flange_dimensions`).
    pub fn points(&self) -> Option<&[[f64; 2]]> {
        self.points.as_deref()
    }

    /// Wheel or rail.
    pub fn kind(&self) -> ProfileKind {
        self.kind
    }

    /// A short name (built-in name or file name).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Where the profile comes from.
    pub fn source(&self) -> &Source {
        &self.source
    }

    /// The lateral extent `(u_min, u_max)` of the definition (mm).
    pub fn domain(&self) -> (f64, f64) {
        match &self.shape {
            Shape::S1002 => (s1002::S_MIN, s1002::S_MAX),
            Shape::Uic60 => (-uic60::half_width(), uic60::half_width()),
            Shape::Sampled(sp) => sp.domain(),
        }
    }

    /// `[v, dv/du, d2v/du2]` at `u` (mm), `u` clamped to the domain.
    ///
    /// # Units
    /// mm, dimensionless, 1/mm.
    #[inline]
    pub fn eval(&self, u: f64) -> [f64; 3] {
        match &self.shape {
            Shape::S1002 => s1002::eval(u),
            Shape::Uic60 => uic60::eval(u),
            Shape::Sampled(sp) => {
                let (lo, hi) = sp.domain();
                sp.eval_inside(u.clamp(lo, hi))
            }
        }
    }

    /// [`Profile::eval`] of four points at once in SIMD lanes, to the bit, where the profile
    /// has a lane form and the four share one section (S1002's polynomials); `None` otherwise.
    #[inline]
    pub(crate) fn eval_x4(&self, u: [f64; 4]) -> Option<[[f64; 3]; 4]> {
        match &self.shape {
            Shape::S1002 => s1002::eval_x4(u),
            _ => None,
        }
    }

    /// A scan of the profile at increasing `u` ([`ProfileScan`]): [`Profile::eval`] to the
    /// bit.
    pub(crate) fn scan(&self) -> ProfileScan<'_> {
        match &self.shape {
            Shape::Sampled(sp) => ProfileScan::Walk(sp.walk_from_start(), sp.domain()),
            // Through `eval`, not its arms: a second caller of `s1002::eval` would keep it
            // from being inlined into `eval`, which the gap calls most.
            _ => ProfileScan::Eval(self),
        }
    }

    /// Tangent of the profile's own contact angle at `u` (no inclination, no roll): positive
    /// where the surface falls towards the field side as a coned tread does
    /// (`-dF/ds` for a wheel; for a rail `dz/dy`, which is positive where the rail surface
    /// rises towards the field side, matching a wheel tread that touches it there).
    ///
    /// # Example
    /// ```
    /// let w = wheelrail::profile::Profile::s1002();
    /// assert!((w.tan_gamma(0.0) - 0.03359).abs() < 1e-5);
    /// ```
    pub fn tan_gamma(&self, u: f64) -> f64 {
        let d1 = self.eval(u)[1];
        match self.kind {
            ProfileKind::Wheel => -d1,
            ProfileKind::Rail => d1,
        }
    }

    /// Curvature of the profile curve at `u` (1/mm), positive where the surface is convex
    /// towards the other body (S1002 flange tip +1/12, UIC60 crown +1/300).
    pub fn convex_curvature(&self, u: f64) -> f64 {
        let [_, d1, d2] = self.eval(u);
        convex_curvature(d1, d2)
    }

    /// Where the profile's second derivative may jump or kink (increasing): the section
    /// joints of a built-in profile, the interior knots of a spline. Between two of them the
    /// profile is analytic, so quadratures that break there converge fast.
    pub fn breaks(&self) -> Vec<f64> {
        match &self.shape {
            Shape::Sampled(sp) => {
                let k = sp.knots();
                k[1..k.len().saturating_sub(1)].to_vec()
            }
            _ => self.joints(),
        }
    }

    /// Whether the profile is a spline through points (its smoothness between
    /// [`Profile::joints`] is that of a cubic spline, not of an analytic definition).
    pub fn is_sampled(&self) -> bool {
        matches!(self.shape, Shape::Sampled(_))
    }

    /// Section joints or spline knots that lie inside the domain (mm), increasing. Analytic
    /// profiles give their section joints; sampled ones give nothing (their knots are
    /// everywhere).
    pub fn joints(&self) -> Vec<f64> {
        match &self.shape {
            Shape::S1002 => {
                let mut j = s1002::JOINTS.to_vec();
                j.reverse();
                j
            }
            Shape::Uic60 => uic60::joints().to_vec(),
            Shape::Sampled(_) => Vec::new(),
        }
    }

    /// Samples the profile every `step_mm` over its domain (both ends included), plus the
    /// section joints, as `[u, v, tan_gamma, convex_curvature]` rows.
    pub fn sample(&self, step_mm: f64) -> Vec<[f64; 4]> {
        // The positions increase: a scan (the same values as `eval`).
        let mut scan = self.scan();
        self.sample_positions(step_mm)
            .into_iter()
            .map(|u| {
                let [v, d1, d2] = scan.eval(u);
                // `tan_gamma(u)` from the slope just evaluated (the same number).
                let tan_gamma = match self.kind {
                    ProfileKind::Wheel => -d1,
                    ProfileKind::Rail => d1,
                };
                [u, v, tan_gamma, convex_curvature(d1, d2)]
            })
            .collect()
    }

    /// The positions `u` (mm) that [`Profile::sample`] evaluates the profile at: every
    /// `step_mm` over the domain (both ends included) and the section joints, increasing.
    pub fn sample_positions(&self, step_mm: f64) -> Vec<f64> {
        let (lo, hi) = self.domain();
        let n = ((hi - lo) / step_mm).ceil().max(1.0) as usize;
        let mut us: Vec<f64> = (0..=n).map(|i| (lo + i as f64 * step_mm).min(hi)).collect();
        us.extend(self.joints());
        us.sort_by(f64::total_cmp);
        us.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
        us
    }
}

/// A scan of a profile at increasing `u` ([`Profile::scan`]): a sampled profile's spline
/// walked forward from its last interval ([`spline::Walk`]: the same interval as the lookup
/// of `eval`, found in about half its work, the spline's slices held by the scan, which a
/// loop keeps in registers), another profile evaluated. Any `u` is allowed; one below the
/// previous takes the lookup.
#[derive(Debug, Clone, Copy)]
pub(crate) enum ProfileScan<'a> {
    /// The spline's walk and its domain.
    Walk(spline::Walk<'a>, (f64, f64)),
    /// The profile itself.
    Eval(&'a Profile),
}

impl ProfileScan<'_> {
    /// `[v, v']` at `u`: the first two numbers of [`Profile::eval`] to the bit, without the
    /// second derivative.
    #[inline(always)]
    pub(crate) fn eval_slope(&mut self, u: f64) -> [f64; 2] {
        match self {
            ProfileScan::Walk(walk, (lo, hi)) => walk.eval_slope(u.clamp(*lo, *hi)),
            ProfileScan::Eval(p) => {
                let [v, d1, _] = p.eval(u);
                [v, d1]
            }
        }
    }

    /// `[v, v', v'']` at `u`: [`Profile::eval`] to the bit.
    #[inline(always)]
    pub(crate) fn eval(&mut self, u: f64) -> [f64; 3] {
        match self {
            ProfileScan::Walk(walk, (lo, hi)) => walk.eval(u.clamp(*lo, *hi)),
            ProfileScan::Eval(p) => p.eval(u),
        }
    }
}

/// Curvature of a graph `v(u)` from its derivatives, positive where the surface is convex
/// towards the other body (`-v'' / (1 + v'^2)^(3/2)`; both side frames have `v''` < 0 on a
/// convex bump).
#[inline]
pub(crate) fn convex_curvature(d1: f64, d2: f64) -> f64 {
    -d2 / (1.0 + d1 * d1).powf(1.5)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every listed built-in name reads as the profile of that name; the aliases and any
    /// case read too, an unknown name does not.
    #[test]
    fn the_built_in_names_are_the_profiles_names() {
        for name in Profile::BUILT_IN {
            assert_eq!(
                Profile::built_in(name)
                    .map(|p| p.name().to_string())
                    .as_deref(),
                Some(name)
            );
        }
        for alias in ["uic60", "60e1", "s1002"] {
            assert!(Profile::built_in(alias).is_some(), "{alias}");
        }
        assert!(Profile::built_in("S1003").is_none());
    }

    /// S1002 and UIC60, and both sampled every 0.25 mm (joints included) and fitted by an
    /// interpolating spline.
    fn built_in_and_sampled() -> [Profile; 4] {
        let sampled = |p: Profile| {
            let points = p.sample(0.25).iter().map(|r| [r[0], r[1]]).collect();
            let points = read::PointProfile::from_points(p.kind(), "sampled", points).unwrap();
            Profile::from_points(points, 0.0).unwrap()
        };
        [
            Profile::s1002(),
            Profile::uic60e1(),
            sampled(Profile::s1002()),
            sampled(Profile::uic60e1()),
        ]
    }

    #[test]
    fn samples_are_the_profile_at_the_sample_positions() {
        // The same numbers as evaluating each column on its own, to the bit (a sampled
        // profile's rows come from a scan).
        for p in built_in_and_sampled() {
            let rows = p.sample(0.7);
            let us = p.sample_positions(0.7);
            assert_eq!(rows.len(), us.len());
            for (r, u) in rows.iter().zip(us) {
                assert_eq!(r[0].to_bits(), u.to_bits());
                assert_eq!(r[1].to_bits(), p.eval(u)[0].to_bits());
                assert_eq!(r[2].to_bits(), p.tan_gamma(u).to_bits());
                assert_eq!(r[3].to_bits(), p.convex_curvature(u).to_bits());
            }
            assert!(
                p.joints()
                    .iter()
                    .all(|j| rows.iter().any(|r| (r[0] - *j).abs() < 1e-9))
            );
        }
    }

    /// A scan is `eval` to the bit (and its value and slope the first two numbers of
    /// `eval`), built-in and sampled profiles alike, over and beyond the domain (clamped),
    /// at increasing `u` and stepping back.
    #[test]
    fn a_scan_is_eval_to_the_bit() {
        for p in built_in_and_sampled() {
            let (lo, hi) = p.domain();
            let n = 20_000;
            let us = (0..=n).map(|k| lo - 1.0 + (hi - lo + 2.0) * f64::from(k) / f64::from(n));
            let back = (0..=n / 10).map(|k| hi - (hi - lo) * f64::from(k) / f64::from(n / 10));
            let (mut scan, mut slopes) = (p.scan(), p.scan());
            for u in us.chain(back) {
                let (got, want) = (scan.eval(u), p.eval(u));
                assert_eq!(
                    got.map(f64::to_bits),
                    want.map(f64::to_bits),
                    "{} {u}",
                    p.name()
                );
                let [v, d1] = slopes.eval_slope(u);
                assert_eq!(
                    [v, d1].map(f64::to_bits),
                    [want[0], want[1]].map(f64::to_bits)
                );
            }
        }
    }

    #[test]
    fn convex_curvatures_have_the_documented_signs() {
        let w = Profile::s1002();
        // Flange tip arc R12: +1/12 at its apex (exact arc). Measured exact, exact and one
        // ulp; bounds two ulps.
        assert!((w.convex_curvature(-55.0) - 1.0 / 12.0).abs() < 3e-17);
        let r = Profile::uic60e1();
        assert!((r.convex_curvature(0.0) - 1.0 / 300.0).abs() < 1e-18);
        assert!((r.convex_curvature(30.0) - 1.0 / 13.0).abs() < 3e-17);
    }
}
