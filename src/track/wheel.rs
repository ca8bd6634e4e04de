//! A wheel fixed to the wheelset, in its side frame.

use super::{PlacementError, TrackLayout, convex_from_second_derivative};
use crate::profile::bounds::DerivativeBounds;
use crate::profile::{Profile, ProfileKind};
use std::sync::{Arc, OnceLock};

/// A wheel fixed to the wheelset, in the side frame relative to the wheelset centre.
#[derive(Debug, Clone)]
pub struct PlacedWheel {
    profile: Profile,
    taping_line_mm: f64,
    nominal_radius_mm: f64,
    /// [`PlacedWheel::cells`] of the first grid asked for, built on first use and shared by
    /// the wheel's clones and by an equal wheel on the other side of a placement
    /// ([`Placement::new`](super::Placement::new)): a wheelset's two equal wheels build them once.
    cells: Arc<OnceLock<WheelCells>>,
    /// The largest value jump of the profile at a section joint (mm).
    value_jump_mm: f64,
}

/// Bounds of a placed wheel over one cell of a uniform grid of its profile coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct WheelCell {
    /// Ranges of `F'` and `F''` over the cell.
    pub(crate) d: DerivativeBounds,
    /// Range of `Z` (mm, relative to the axle, no roll) over the cell: the ends' heights
    /// widened by the sag `max |F''| h^2 / 8` and by the value and slope jumps at joints
    /// inside (`|jump of F| + |jump of F'| h`).
    pub(crate) z: (f64, f64),
    /// The value and slope jumps at joints inside (`|jump of F| + |jump of F'| h`, mm): what
    /// a bound from the derivatives misses across them.
    pub(crate) jump: f64,
}

/// The [`WheelCell`]s of a uniform grid, with a sparse table of their unions: the bounds
/// over any run of cells in two lookups (two overlapping runs count the joints of their
/// overlap twice in `jump`: an upper bound still).
#[derive(Debug, Clone)]
pub(crate) struct WheelCells {
    /// `levels.level(k)[i]`: the union of the cells `i..i + 2^k` (level 0: the cells), each
    /// level above the cells made on first use.
    levels: super::sparse::LazyLevels<WheelCell>,
}

impl WheelCells {
    fn new(cells: Vec<WheelCell>) -> WheelCells {
        WheelCells {
            levels: super::sparse::LazyLevels::new(cells, WheelCell::union),
        }
    }

    /// The cells, in order.
    pub(crate) fn cells(&self) -> &[WheelCell] {
        self.levels.level(0)
    }

    /// The bounds over the cells `i..j` (`i < j`): the union of theirs. The levels join two
    /// runs of `2^k` cells that cover `i..j`, for one cell the cell with itself, whose
    /// ranges are its own (`min(x, x)` and `max(x, x)` are `x`) and whose joint terms count
    /// twice (`jump + jump`, as the join sums them): one cell is read directly, the same
    /// bits (the certificate asks for single cells most, and reads them without the lookup
    /// through the levels).
    #[inline]
    pub(crate) fn over(&self, i: usize, j: usize) -> WheelCell {
        if j == i + 1 {
            let c = self.cells()[i];
            return WheelCell {
                jump: c.jump + c.jump,
                ..c
            };
        }
        let k = super::sparse::level_of(j - i);
        let level = self.levels.level(k);
        level[i].union(level[j - (1 << k)])
    }
}

impl WheelCell {
    /// The bounds over two runs of cells together.
    #[inline]
    pub(crate) fn union(self, o: WheelCell) -> WheelCell {
        WheelCell {
            d: self.d.union(o.d),
            z: (self.z.0.min(o.z.0), self.z.1.max(o.z.1)),
            jump: self.jump + o.jump,
        }
    }
}

/// A point of a placed wheel relative to the wheelset centre (side frame, no roll), as
/// [`PlacedWheel::at`] gives it and [`crate::gap::GapPoint`] carries it; `Y`, `Z` and their
/// derivatives in mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelPoint {
    /// Lateral `Y` from the wheelset centre (mm).
    pub y: f64,
    /// Vertical `Z` from the axle (mm): `-(r0 + F(s))`.
    pub z: f64,
    /// `dZ/dY` (= `-dF/ds`): tangent of the wheel's contact angle without roll.
    pub slope: f64,
    /// `d2Z/dY2` (= `-d2F/ds2`, 1/mm).
    pub d2: f64,
    /// `dY/ds`: 1 for a profile point; the rate at which a yawed wheel's outline (the
    /// points the rail sees) moves sideways along the profile.
    pub dy_ds: f64,
}

impl WheelPoint {
    /// Convex-positive curvature (1/mm): the wheel surface is convex towards the rail where
    /// `F'' < 0`, i.e. where `Z'' > 0`.
    #[inline]
    pub fn curvature(&self) -> f64 {
        -convex_from_second_derivative(self.slope, self.d2)
    }
}

/// The nominal wheel radii accepted (mm): from small trolley wheels to the largest
/// locomotive wheels, with margin.
pub(crate) const NOMINAL_RADIUS_RANGE_MM: (f64, f64) = (100.0, 1000.0);

/// `nominal_radius_mm` if it is within [`NOMINAL_RADIUS_RANGE_MM`].
///
/// # Errors
/// [`PlacementError::NominalRadius`] otherwise (and for a non-finite radius).
pub(crate) fn check_nominal_radius(nominal_radius_mm: f64) -> Result<f64, PlacementError> {
    let (lo, hi) = NOMINAL_RADIUS_RANGE_MM;
    if (lo..=hi).contains(&nominal_radius_mm) {
        Ok(nominal_radius_mm)
    } else {
        Err(PlacementError::NominalRadius {
            radius_mm: nominal_radius_mm,
        })
    }
}

impl PlacedWheel {
    /// Fixes `profile` to the wheelset with its taping line at `layout.taping_line_mm()`
    /// and its rolling circle there of radius `nominal_radius_mm`.
    ///
    /// # Errors
    /// [`PlacementError::WrongKind`] when the profile is not a wheel,
    /// [`PlacementError::NominalRadius`] when the radius is outside
    /// `NOMINAL_RADIUS_RANGE_MM`.
    pub fn place(
        profile: Profile,
        nominal_radius_mm: f64,
        layout: &TrackLayout,
    ) -> Result<PlacedWheel, PlacementError> {
        let nominal_radius_mm = check_nominal_radius(nominal_radius_mm)?;
        if profile.kind() != ProfileKind::Wheel {
            return Err(PlacementError::WrongKind {
                profile: profile.name().to_string(),
                expected: ProfileKind::Wheel,
            });
        }
        Ok(PlacedWheel {
            taping_line_mm: layout.taping_line_mm(),
            nominal_radius_mm,
            cells: Arc::default(),
            value_jump_mm: value_jump(&profile),
            profile,
        })
    }

    /// The wheel profile.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// Nominal rolling radius r0 at the taping line (mm).
    pub fn nominal_radius_mm(&self) -> f64 {
        self.nominal_radius_mm
    }

    /// Lateral position of the taping line from the wheelset centre (mm).
    pub fn taping_line_mm(&self) -> f64 {
        self.taping_line_mm
    }

    /// The wheel point at profile coordinate `s` (mm), relative to the wheelset centre.
    #[inline]
    pub fn at(&self, s: f64) -> WheelPoint {
        self.point(s, self.profile.eval(s))
    }

    /// [`PlacedWheel::at`] of four points, to the bit: in SIMD lanes where the profile
    /// allows (see [`Profile::eval_x4`]), else one by one.
    #[inline]
    pub(crate) fn at_x4(&self, s: [f64; 4]) -> [WheelPoint; 4] {
        match self.profile.eval_x4(s) {
            Some(e) => std::array::from_fn(|i| self.point(s[i], e[i])),
            None => s.map(|x| self.at(x)),
        }
    }

    /// The wheel point at `s` from the profile's `[F, F', F'']` there.
    #[inline(always)]
    fn point(&self, s: f64, [f, d1, d2]: [f64; 3]) -> WheelPoint {
        WheelPoint {
            y: self.taping_line_mm + s,
            z: -(self.nominal_radius_mm + f),
            slope: -d1,
            d2: -d2,
            dy_ds: 1.0,
        }
    }

    /// The largest value jump of the profile at a section joint (mm; S1002: 1.2e-4 at
    /// s = -35, 0 for a spline).
    pub(crate) fn value_jump_mm(&self) -> f64 {
        self.value_jump_mm
    }

    /// Bounds of the wheel over the `n` cells of the uniform grid
    /// `s_i = lo + (hi - lo) i / n` of its domain `(lo, hi)`: built once for the first `n`
    /// asked for, computed afresh for another.
    pub(crate) fn cells(&self, n: usize) -> std::borrow::Cow<'_, WheelCells> {
        let cells = self.cells.get_or_init(|| self.build_cells(n));
        if cells.cells().len() == n {
            std::borrow::Cow::Borrowed(cells)
        } else {
            std::borrow::Cow::Owned(self.build_cells(n))
        }
    }

    /// Bounds of the wheel over `[a, b]`; `joints` are the profile's
    /// [`joints`](Profile::joints). A joint at `a` is no jump inside (the profile is
    /// evaluated on its field side there, as inside); one at `b` is.
    pub(crate) fn cell(&self, a: f64, b: f64, joints: &[f64]) -> WheelCell {
        self.cell_between(a, b, [self.at(a).z, self.at(b).z], joints)
    }

    /// [`PlacedWheel::cell`] from the heights `Z` of its ends (`self.at(a).z`, `self.at(b).z`).
    #[inline]
    fn cell_between(&self, a: f64, b: f64, [za, zb]: [f64; 2], joints: &[f64]) -> WheelCell {
        let d = self.profile.derivative_bounds(a, b);
        let jump: f64 = joints
            .iter()
            .copied()
            .filter(|&j| a < j && j <= b)
            .map(|j| {
                let (p, q) = (self.profile.eval(j), self.profile.eval(j - 1e-12));
                (p[0] - q[0]).abs() + (p[1] - q[1]).abs() * (b - a)
            })
            .sum();
        let sag = d.d2_abs() * (b - a) * (b - a) / 8.0 + jump;
        let pad = 1e-12 * za.abs().max(zb.abs());
        WheelCell {
            d,
            z: (za.min(zb) - sag - pad, za.max(zb) + sag + pad),
            jump,
        }
    }

    /// Whether `other` is this wheel to the bit: the same profile data at the same radius
    /// and taping line (its cell bounds, built from these, are then the same too).
    pub(crate) fn same_as(&self, other: &PlacedWheel) -> bool {
        let bits = |a: f64, b: f64| a.to_bits() == b.to_bits();
        self.profile.same_data(&other.profile)
            && bits(self.nominal_radius_mm, other.nominal_radius_mm)
            && bits(self.taping_line_mm, other.taping_line_mm)
    }

    /// Shares the cell bounds of `other`, a wheel [the same as this one](Self::same_as):
    /// built once for both (a wheelset's two equal wheels).
    pub(crate) fn share_cells_with(&mut self, other: &PlacedWheel) {
        debug_assert!(self.same_as(other));
        self.cells = Arc::clone(&other.cells);
    }

    /// Whether `other` shares this wheel's cell bounds (a test of the sharing, which
    /// decides nothing).
    #[cfg(test)]
    pub(crate) fn shares_cells_with(&self, other: &PlacedWheel) -> bool {
        Arc::ptr_eq(&self.cells, &other.cells)
    }

    fn build_cells(&self, n: usize) -> WheelCells {
        let (lo, hi) = self.profile.domain();
        let s = |i: usize| lo + (hi - lo) * i as f64 / n as f64;
        let joints = self.profile.joints();
        // The height of each grid point evaluated once (the end of one cell and the start
        // of the next), the value only, by a scan: the `z` of `at` to the bit.
        let mut scan = self.profile.scan();
        let mut z_of = |s: f64| -(self.nominal_radius_mm + scan.eval_slope(s)[0]);
        let mut z_a = z_of(s(0));
        WheelCells::new(
            (0..n)
                .map(|i| {
                    let z_b = z_of(s(i + 1));
                    let cell = self.cell_between(s(i), s(i + 1), [z_a, z_b], &joints);
                    z_a = z_b;
                    cell
                })
                .collect(),
        )
    }
}

/// The largest value jump of `profile` at a section joint (mm).
pub(crate) fn value_jump(profile: &Profile) -> f64 {
    profile
        .joints()
        .into_iter()
        .map(|j| (profile.eval(j)[0] - profile.eval(j - 1e-12)[0]).abs())
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::track::{Inclination, TrackLayout};

    /// `at_x4` is `at` to the bit over the whole S1002 domain and beyond, for groups of
    /// four inside one section (lanes) and across joints (the scalar fallback).
    #[test]
    fn four_at_once_are_at_to_the_bit() {
        let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
        let pair = crate::track::SidePair::place(
            Profile::s1002(),
            460.0,
            Profile::uic60e1(),
            Inclination::VERTICAL,
            &layout,
        )
        .unwrap();
        let wheel = &pair.wheel;
        for i in 0..20_000 {
            let s0 = -75.0 + 0.007 * f64::from(i);
            for spread in [1e-3, 0.05, 0.7] {
                let s = [0.0, 1.0, 2.0, 3.0].map(|k| s0 + spread * k);
                for (lane, &si) in wheel.at_x4(s).iter().zip(&s) {
                    let one = wheel.at(si);
                    let bits = |p: &WheelPoint| [p.y, p.z, p.slope, p.d2].map(f64::to_bits);
                    assert_eq!(bits(lane), bits(&one), "s = {si}");
                }
            }
        }
    }
}
