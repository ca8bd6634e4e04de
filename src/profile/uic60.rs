//! The UIC60 (60E1, EN 13674-1) rail head from its drawing: arcs R300, R80 and R13, tangent
//! to each other, and a straight 1:20 flank, with exact derivatives.
//!
//! Coordinates are the rail side frame of the crate docs for an **upright** rail: `y` (mm)
//! lateral from the rail's vertical axis (the head is symmetric, so the sign does not matter
//! here), `z` (mm) height, up positive, zero at the top of the rail. Inclination and placement
//! are applied by [`crate::track`].
//!
//! The flank is continued down to [`FLANK_DEPTH_MM`] below the top; the fillets under the
//! head are not modelled (no wheel reaches them).

/// Depth below the top of rail to which the 1:20 flank is drawn (mm). The head's underside
/// fillets begin about here on the 60E1 drawing.
pub const FLANK_DEPTH_MM: f64 = 37.5;

use super::bounds::{DerivativeBounds, arc_bounds};

const R_CROWN: f64 = 300.0;
const R_SHOULDER: f64 = 80.0;
const R_CORNER: f64 = 13.0;
/// Centres of the arcs as (lateral, depth below the top), mm.
const C_SHOULDER: (f64, f64) = (7.500533, 80.127896);
const C_CORNER: (f64, f64) = (23.016030, 14.949147);
/// Lateral positions of the crown/shoulder and shoulder/corner joints (mm).
const Y_CROWN_END: f64 = 20.456 / 2.0;
const Y_SHOULDER_END: f64 = 52.053 / 2.0;
/// Flank slope: 1 mm outwards for every 20 mm down.
const FLANK_OUTWARD_PER_DEPTH: f64 = 1.0 / 20.0;

/// Where the R13 corner arc meets the flank tangentially: the point of the arc whose outward
/// normal is perpendicular to the flank direction (1/20, 1) in (lateral, depth).
fn corner_flank_joint() -> (f64, f64) {
    // sqrt(1 + 20^2), written out so that the hot path does no square root for it.
    let norm = 20.024_984_394_500_787;
    // Outward normal (20, -1)/sqrt(401): lateral outwards, depth upwards.
    (
        C_CORNER.0 + R_CORNER * 20.0 / norm,
        C_CORNER.1 - R_CORNER / norm,
    )
}

/// Half-width of the modelled head at its lowest point (mm).
pub fn half_width() -> f64 {
    let (y, d) = corner_flank_joint();
    y + (FLANK_DEPTH_MM - d) * FLANK_OUTWARD_PER_DEPTH
}

/// Section joints in `y` (mm), both sides of the symmetric head, increasing.
pub fn joints() -> [f64; 6] {
    let y3 = corner_flank_joint().0;
    [
        -y3,
        -Y_SHOULDER_END,
        -Y_CROWN_END,
        Y_CROWN_END,
        Y_SHOULDER_END,
        y3,
    ]
}

/// `[z, dz/dy, d2z/dy2]` of the upright UIC60 head at lateral `y` (mm), height up positive.
///
/// `y` is clamped to `[-half_width(), half_width()]`.
#[inline]
pub fn eval(y: f64) -> [f64; 3] {
    let w = half_width();
    let (u, sign) = if y < 0.0 { (-y, -1.0) } else { (y, 1.0) };
    let u = u.min(w);
    let [depth, d1, d2] = depth_of_half(u);
    // z = -depth(|y|): dz/dy = -sign depth', d2z/dy2 = -depth''.
    [-depth, -sign * d1, -d2]
}

/// Depth below the top and its derivatives for `0 <= u <= half_width()`.
fn depth_of_half(u: f64) -> [f64; 3] {
    if u <= Y_CROWN_END {
        arc_below_centre((0.0, R_CROWN), R_CROWN, u)
    } else if u <= Y_SHOULDER_END {
        arc_below_centre(C_SHOULDER, R_SHOULDER, u)
    } else if u <= corner_flank_joint().0 {
        arc_below_centre(C_CORNER, R_CORNER, u)
    } else {
        let (y3, d3) = corner_flank_joint();
        let slope = 1.0 / FLANK_OUTWARD_PER_DEPTH;
        [d3 + (u - y3) * slope, slope, 0.0]
    }
}

/// Bounds of `dz/dy` and `d2z/dy2` over `[lo, hi]` (inside the domain): each arc and the
/// flank on its part of each half of the head, from its own formula (both one-sided limits
/// at a joint).
pub(super) fn derivative_bounds(lo: f64, hi: f64) -> DerivativeBounds {
    let (y3, d3) = corner_flank_joint();
    let w = half_width();
    let slope = 1.0 / FLANK_OUTWARD_PER_DEPTH;
    // Sections of the half head in u = |y|: depth formula and the u of its vertex.
    type Section = (f64, f64, (f64, f64), f64);
    let arcs: [Section; 3] = [
        (0.0, Y_CROWN_END, (0.0, R_CROWN), R_CROWN),
        (Y_CROWN_END, Y_SHOULDER_END, C_SHOULDER, R_SHOULDER),
        (Y_SHOULDER_END, y3, C_CORNER, R_CORNER),
    ];
    let mut b = DerivativeBounds::EMPTY;
    // y = sign * u: z = -depth(u), dz/dy = -sign depth', d2z/dy2 = -depth''.
    for sign in [-1.0, 1.0] {
        // The part of [lo, hi] on this half, in u.
        let (u_lo, u_hi) = if sign > 0.0 {
            (lo.max(0.0), hi)
        } else {
            (-hi.min(0.0), -lo)
        };
        if u_lo > u_hi {
            continue;
        }
        let to_y = |[d, d1, d2]: [f64; 3]| [-d, -sign * d1, -d2];
        for &(start, end, centre, r) in &arcs {
            let (a, c) = (u_lo.max(start), u_hi.min(end));
            if a <= c {
                let f = |u: f64| to_y(arc_below_centre(centre, r, u));
                b = b.union(arc_bounds(f, centre.0, a, c));
            }
        }
        if u_hi >= y3 && u_lo <= w {
            b.include(to_y([d3, slope, 0.0]));
        }
    }
    b
}

/// Depth of the upper part of a circle (centre below the surface): depth = c_d - sqrt(r^2 - (u - c_y)^2).
fn arc_below_centre((cy, cd): (f64, f64), r: f64, u: f64) -> [f64; 3] {
    let v = u - cy;
    let root = (r * r - v * v).max(0.0).sqrt();
    // One division: the derivatives share 1 / root.
    let inv = 1.0 / root;
    [cd - root, v * inv, r * r * inv * inv * inv]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The drawing's check values are given to 6 decimals; the arc centres to 6 decimals.
    const DRAWING_TOL_MM: f64 = 2e-6;

    #[test]
    fn joints_and_width_match_the_drawing() {
        assert!((20.024_984_394_500_787_f64 - 401f64.sqrt()).abs() < 1e-14);
        assert!((eval(Y_CROWN_END)[0] + 0.174404).abs() < DRAWING_TOL_MM);
        assert!((eval(Y_SHOULDER_END)[0] + 2.302524).abs() < DRAWING_TOL_MM);
        let (y3, d3) = corner_flank_joint();
        assert!((y3 - 35.9998).abs() < 1e-4 && (d3 - 14.3000).abs() < 1e-4);
        // Half-width 14 mm below the top: 35.9813 mm (reference, 4 decimals).
        let y14 = bisect_depth(14.0);
        assert!((y14 - 35.9813).abs() < 1e-4, "{y14}");
    }

    #[test]
    fn arcs_are_tangent() {
        // Value continuity to the drawing's 6 decimals (measured 2.6e-7 mm), slope
        // continuity measured 6.2e-7 (the arcs' centres are drawn to 6 decimals).
        for j in joints() {
            let a = eval(j - 1e-9);
            let b = eval(j + 1e-9);
            assert!((a[0] - b[0]).abs() < DRAWING_TOL_MM, "value at {j}");
            assert!(
                (a[1] - b[1]).abs() < 1.5e-6,
                "slope at {j}: {} {}",
                a[1],
                b[1]
            );
        }
    }

    fn bisect_depth(depth: f64) -> f64 {
        let (mut lo, mut hi) = (0.0, half_width());
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if -eval(mid)[0] < depth {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// A known value of `eval`.
    #[test]
    fn eval_example() {
        use crate::profile::uic60;
        // The crown/shoulder joint lies 0.174404 mm below the top (EN 13674-1 drawing).
        let [z, _, _] = uic60::eval(10.228);
        assert!((z + 0.174404).abs() < 1e-6);
    }
}
