//! The placed rail against exact inversions and known placements.

use super::*;

fn paper_layout() -> TrackLayout {
    TrackLayout::standard(Inclination::parse("1:40").unwrap())
}

#[test]
fn uic60_at_1_in_40_has_its_top_43_03_mm_field_side_of_the_gauge_point() {
    let rail =
        PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &paper_layout()).unwrap();
    // Gauge point exactly at half the gauge (bisection to 1e-15).
    assert!((rail.gauge_point()[0] - 717.5).abs() < 1e-9);
    assert!((rail.gauge_point()[1] + 14.0).abs() < 1e-9);
    assert!(rail.top()[1].abs() < 1e-12);
    // Reference value (the project's reference notes on the standard-gauge layout,
    // outside this repository): 43.03 mm (2 decimals), so 760.53 from the track centre.
    let offset = rail.top()[0] - rail.gauge_point()[0];
    assert!((offset - 43.03).abs() < 0.005, "{offset}");
}

#[test]
fn top_offsets_for_other_inclinations() {
    // Same reference notes: upright 35.98 mm, 1:20 46.5 mm (as many decimals as given).
    for (incl, expected, tol) in [("vertical", 35.98, 0.005), ("1:20", 46.5, 0.05)] {
        let layout = TrackLayout {
            inclination: Inclination::parse(incl).unwrap(),
            ..paper_layout()
        };
        let rail = PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &layout).unwrap();
        let offset = rail.top()[0] - rail.gauge_point()[0];
        assert!((offset - expected).abs() < tol, "{incl}: {offset}");
    }
}

#[test]
fn rail_inverse_is_exact() {
    let rail =
        PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &paper_layout()).unwrap();
    let (lo, hi) = rail.profile().domain();
    for i in 0..=200 {
        let u = lo + (hi - lo) * f64::from(i) / 200.0;
        let p = rail.point_of(u);
        if let Some(r) = rail.at(p[0]) {
            assert!((r.z - p[1]).abs() < 1e-10, "u = {u}");
        }
    }
}

/// Every 1e-3 mm over `rail`: the quintic pieces against Newton's inversion; the number
/// of points tabulated, of points, and the largest differences in `Z`, the slope and
/// `Z''` (relative).
fn table_against_inversion(rail: &PlacedRail) -> (usize, usize, [f64; 3]) {
    let (lo, hi) = rail.y_range();
    let (mut tabulated, mut worst) = (0, [0.0f64; 3]);
    let n = ((hi - lo) / 1e-3) as usize;
    for i in 0..=n {
        let y = lo + (hi - lo) * i as f64 / n as f64;
        let table = rail.tabulated_at(y).or_else(|| rail.split_at(y));
        let (Some(t), Some(e)) = (table, rail.exact_at(y)) else {
            continue;
        };
        tabulated += 1;
        for (w, d) in worst.iter_mut().zip([
            t.z - e.z,
            t.slope - e.slope,
            (t.d2 - e.d2) / (1.0 + e.d2.abs()),
        ]) {
            *w = w.max(d.abs());
        }
    }
    (tabulated, n, worst)
}

/// UIC60 sampled every 0.25 mm (joints included) and fitted by an interpolating spline.
fn sampled_uic60() -> Profile {
    let points = Profile::uic60e1()
        .sample(0.25)
        .iter()
        .map(|r| [r[0], r[1]])
        .collect();
    let points =
        crate::profile::read::PointProfile::from_points(ProfileKind::Rail, "sampled", points)
            .unwrap();
    Profile::from_points(points, 0.0).unwrap()
}

#[test]
fn sampled_surface_table_matches_the_exact_inversion() {
    // UIC60 sampled every 0.25 mm (joints included) and fitted by an interpolating spline,
    // as the tradeoff study's sampled setting: the pieces that hold a knot are split there.
    let profile = sampled_uic60();
    let rail = PlacedRail::place(profile, Inclination::VERTICAL, &paper_layout()).unwrap();
    let splits = rail.splits.len();
    let (tabulated, n, worst) = table_against_inversion(&rail);
    println!(
        "tabulated {tabulated} of {n} ({splits} split pieces); max |dz| {:.1e}, |dslope| {:.1e}, |dZ''| rel {:.1e}",
        worst[0], worst[1], worst[2]
    );
    // One piece in 12.5 holds a knot (0.25 mm / 0.02 mm); as much of the head as on the
    // analytic rail is tabulated.
    assert!(splits > 200, "{splits}");
    assert!(tabulated > n * 3 / 4, "{tabulated} of {n}");
    // Measured: 2.0e-13 mm, 5.1e-11 and 7.8e-9 (the analytic rail: 8.5e-13, 1.5e-10,
    // 1.5e-8); the analytic rail's limits.
    assert!(worst[0] < 4e-12, "z {:e}", worst[0]);
    assert!(worst[1] < 6e-10, "slope {:e}", worst[1]);
    assert!(worst[2] < 6e-8, "second derivative {:e}", worst[2]);
}

#[test]
fn surface_table_matches_the_exact_inversion() {
    // Every 1e-3 mm over the placed UIC60 at 1:40: the quintic pieces against Newton's
    // inversion of the analytic head.
    let rail =
        PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &paper_layout()).unwrap();
    let (tabulated, n, worst) = table_against_inversion(&rail);
    println!(
        "tabulated {tabulated} of {n}; max |dz| {:.1e}, |dslope| {:.1e}, |dZ''| rel {:.1e}",
        worst[0], worst[1], worst[2]
    );
    // Most of the head is tabulated (the steep gauge face and the pieces at joints not).
    assert!(tabulated > n * 3 / 4, "{tabulated} of {n}");
    // Measured: 8.5e-13 mm, 1.5e-10 and 1.5e-8, all on the R13 corners at slopes 1.5 to
    // 3, where the derivatives of Z(Y) are largest; limits 4 times that.
    assert!(worst[0] < 4e-12, "z {:e}", worst[0]);
    assert!(worst[1] < 6e-10, "slope {:e}", worst[1]);
    assert!(worst[2] < 6e-8, "second derivative {:e}", worst[2]);
}

/// The heights the height table is filled with are the surface's heights to the bit, on
/// tabulated, split and inverted pieces alike (analytic and sampled UIC60).
#[test]
fn heights_are_the_surface_heights_to_the_bit() {
    let sampled = sampled_uic60();
    for profile in [Profile::uic60e1(), sampled] {
        let rail = PlacedRail::place(profile, Inclination::VERTICAL, &paper_layout()).unwrap();
        let (lo, hi) = rail.y_range();
        let n = 20_000;
        // At increasing `y` from one scan, as the table is filled.
        let mut scan = rail.profile().scan();
        for i in 0..=n {
            let y = lo + (hi - lo) * f64::from(i) / f64::from(n);
            let z = rail.at(y).map(|p| p.z.to_bits());
            let height = rail.height_from(&mut scan, y);
            assert_eq!(height.map(f64::to_bits), z, "y = {y}");
        }
        let height_at = |y| rail.height_from(&mut rail.profile().scan(), y);
        assert_eq!(height_at(lo - 1e-9), None);
        assert_eq!(height_at(hi + 1e-9), None);
    }
}

/// The height table interpolates its entries linearly, `z_i + f (z_i+1 - z_i)` with the
/// entries the rail's heights on its grid, bit for bit (the table stores the differences
/// with the heights: the same numbers), and reads `None` outside the running surface.
#[test]
fn the_height_table_interpolates_the_rail_heights_bit_for_bit() {
    let sampled = sampled_uic60();
    for profile in [Profile::uic60e1(), sampled] {
        let rail = PlacedRail::place(profile, Inclination::VERTICAL, &paper_layout()).unwrap();
        let table = rail.heights();
        let (lo, hi) = rail.y_range();
        // The grid `HeightTable::new` makes.
        let n = ((hi - lo) / HEIGHT_TABLE_STEP_MM).ceil().max(1.0) as usize;
        let step = (hi - lo) / n as f64;
        let entry = |i: usize| {
            let y = (lo + i.min(n) as f64 * step).min(hi);
            rail.height_from(&mut rail.profile().scan(), y).unwrap()
        };
        let m = 50_000;
        for k in 0..=m {
            let y = lo + (hi - lo) * f64::from(k) / f64::from(m);
            let t = (y - lo) * (1.0 / step);
            if t > n as f64 {
                // `hi` itself can round past the last entry: off the table.
                assert_eq!(table.height(y), None, "y = {y}");
                continue;
            }
            let i = t as usize;
            let (a, b) = (entry(i), entry(i + 1));
            let expected = a + (t - i as f64) * (b - a);
            assert_eq!(
                table.height(y).map(f64::to_bits),
                Some(expected.to_bits()),
                "y = {y}"
            );
        }
        assert_eq!(table.height(lo - 1e-6), None);
        assert_eq!(table.height(hi + 1e-6), None);
    }
}

/// The height table read four positions at a time in SIMD lanes is `height` to the bit,
/// and its mask is `height`'s `Some`: groups of four at irregular spacing from 2 mm before
/// the table to 2 mm past it (lanes on and off the table in one group), the grid points
/// themselves (integer table coordinates, where the lanes' integer part must not round
/// up), and NaN and infinite positions; analytic and sampled UIC60.
#[test]
fn four_heights_at_once_are_height_to_the_bit() {
    for profile in [Profile::uic60e1(), sampled_uic60()] {
        let rail = PlacedRail::place(profile, Inclination::VERTICAL, &paper_layout()).unwrap();
        let table = rail.heights();
        let lanes = table.lanes();
        let (lo, hi) = rail.y_range();
        let n = ((hi - lo) / HEIGHT_TABLE_STEP_MM).ceil().max(1.0) as usize;
        let step = (hi - lo) / n as f64;
        let check = |y: [f64; 4]| {
            let (h, on) = lanes.height(wide::f64x4::from(y));
            let (h, on) = (h.to_array(), on.to_array());
            for i in 0..4 {
                let expected = table.height(y[i]);
                assert_eq!(on[i].to_bits() != 0, expected.is_some(), "y = {}", y[i]);
                if let Some(e) = expected {
                    assert_eq!(h[i].to_bits(), e.to_bits(), "y = {}", y[i]);
                }
            }
        };
        let (a, b) = (lo - 2.0, hi + 2.0);
        for k in 0..50_000 {
            let x = |j: f64| a + (b - a) * ((f64::from(k) * 0.618_034 + j * 0.173) % 1.0);
            check([x(0.0), x(1.0), x(2.0), x(3.0)]);
        }
        for i in (0..=n + 3).step_by(4) {
            check(std::array::from_fn(|j| lo + (i + j) as f64 * step));
        }
        check([f64::NAN, lo, f64::INFINITY, f64::NEG_INFINITY]);
    }
}

/// The table's lower bound over an interval lies below every interpolated height in it
/// (random intervals of 1e-4 to 30 mm over the head, analytic and sampled UIC60), is
/// `None` for an interval reaching past the table, and is close: within the height
/// variation of the blocks it reads.
#[test]
fn height_table_minimum_lies_below_every_height_of_the_interval() {
    let mut rng = crate::rng::SplitMix64::new(5);
    for profile in [Profile::uic60e1(), sampled_uic60()] {
        let rail = PlacedRail::place(profile, Inclination::VERTICAL, &paper_layout()).unwrap();
        let (lo, hi) = rail.y_range();
        let table = rail.heights();
        let mut bounded = 0;
        for _ in 0..4000 {
            let len = 10f64.powf(-4.0 + 5.5 * rng.uniform());
            let y_lo = lo - 1.0 + (hi - lo + 2.0) * rng.uniform();
            let y_hi = y_lo + len;
            let Some(min) = table.min_over(y_lo, y_hi) else {
                assert!(y_lo < lo || y_hi > hi || table.height(y_lo).is_none());
                continue;
            };
            assert!(y_lo >= lo && y_hi <= hi, "{y_lo} {y_hi}");
            bounded += 1;
            let lowest = (0..=200)
                .map(|i| table.height(y_lo + len * f64::from(i) / 200.0).unwrap())
                .fold(f64::INFINITY, f64::min);
            assert!(min <= lowest, "{min} above {lowest} on [{y_lo}, {y_hi}]");
            // 16 entries each side of 0.02 mm at slopes up to 50 (the steep end).
            assert!(lowest - min < 2.0 * 16.0 * 0.02 * 50.0, "{min} {lowest}");
        }
        assert!(bounded > 2000, "{bounded}");
    }
}

/// The placement of a sampled rail, whose scan and tables read the profile by a walk along its spline,
/// is the placement from `Profile::eval` at every point, to the bit: the same top, gauge
/// point, inverse table, quintic pieces, split pieces and heights.
#[test]
fn sampled_placement_from_a_walk_is_the_placement_from_eval() {
    let layout = paper_layout();
    let fast = PlacedRail::place(sampled_uic60(), Inclination::VERTICAL, &layout).unwrap();
    let slow =
        PlacedRail::place_with(sampled_uic60(), Inclination::VERTICAL, &layout, Direct).unwrap();
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&fast.top()), bits(&slow.top()));
    assert_eq!(bits(&fast.gauge_point()), bits(&slow.gauge_point()));
    assert_eq!(fast.y_range(), slow.y_range());
    assert_eq!(
        bits(fast.inverse.as_flattened()),
        bits(slow.inverse.as_flattened())
    );
    // Debug prints every f64 to its shortest round trip: equal text, equal bits.
    let text = |r: &PlacedRail| format!("{:?} {:?}", r.surface_table, r.splits);
    assert!(!fast.splits.is_empty());
    assert_eq!(text(&fast), text(&slow));
    let (lo, hi) = fast.y_range();
    for k in 0..=10_000 {
        let y = lo + (hi - lo) * f64::from(k) / 10_000.0;
        let (p, q) = (fast.heights().height(y), slow.heights().height(y));
        assert_eq!(p.map(f64::to_bits), q.map(f64::to_bits), "{y}");
    }
}

/// `at_x4` is `at` to the bit, `None` lanes included: every 1e-3 mm from 1 mm before the
/// running surface to 1 mm after it (outside `y_range`, tabulated, split and inverted
/// pieces), in groups of four at spreads from within one piece to across several pieces
/// and the surface's ends (analytic and sampled UIC60).
#[test]
fn four_at_once_are_at_to_the_bit() {
    for profile in [Profile::uic60e1(), sampled_uic60()] {
        let rail = PlacedRail::place(profile, Inclination::VERTICAL, &paper_layout()).unwrap();
        let (lo, hi) = rail.y_range();
        let n = ((hi - lo + 2.0) / 1e-3) as i32;
        let bits = |p: Option<RailPoint>| p.map(|p| [p.z, p.slope, p.d2].map(f64::to_bits));
        let mut nones = 0;
        for i in 0..=n {
            let y0 = lo - 1.0 + 1e-3 * f64::from(i);
            for spread in [3e-3, 0.05, 0.7] {
                let y = [0.0, 1.0, 3.0, 2.0].map(|k| y0 + spread * k);
                for (lane, &yi) in rail.at_x4(y).into_iter().zip(&y) {
                    nones += usize::from(lane.is_none());
                    assert_eq!(bits(lane), bits(rail.at(yi)), "y = {yi}");
                }
            }
        }
        assert!(nones > 0, "lanes outside the running surface were tried");
    }
}
