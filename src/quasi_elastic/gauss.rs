//! The Gauss-Legendre integration of the weighted averages over one low region: panels of
//! a few weight widths on the smooth pieces between joints, 8 nodes (4 on short pieces).

use super::{Average, BARRIER_EPS, FIELDS, Pass, Work, barrier_maxima, fields_of};
use crate::gap::{SideGap, SidePose};

/// Nodes of the 8-point Gauss-Legendre rule on [-1, 1] (positive half; symmetric).
const GL8_X: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
/// Weights of the 8-point Gauss-Legendre rule, matching [`GL8_X`].
const GL8_W: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];
/// Nodes of the 4-point Gauss-Legendre rule on [-1, 1] (positive half; symmetric).
const GL4_X: [f64; 2] = [0.339_981_043_584_856_3, 0.861_136_311_594_052_6];
/// Weights of the 4-point Gauss-Legendre rule, matching [`GL4_X`].
const GL4_W: [f64; 2] = [0.652_145_154_862_546_1, 0.347_854_845_137_453_9];
/// Pieces shorter than this fraction of a panel take the 4-point rule. The rule is exact to
/// degree 7; over a twelfth of the default panel (a quarter of a weight width) the weight's
/// Taylor terms beyond that are below `0.25^8 / 8! = 4e-10` of it, and the fields are
/// analytic within a piece. Shorter panels (finer settings) shrink the bound with them.
const SHORT_PIECE: f64 = 1.0 / 12.0;
/// Bounds of the weight width used to size panels (mm): below, the contact is so stiff that
/// micrometre panels are plenty; above (nearly conformal contact, d'' -> 0) the panels
/// follow the profile's own variation instead of the weight. Measured on the paper scene
/// with panels of 3 widths: raising the upper bound to 2 mm saves a fifth of the nodes but
/// errs by 2e-6 in a and b (2.3e-8 at 1 mm).
const WIDTH_BOUNDS_MM: (f64, f64) = (1e-3, 1.0);

/// Integrates one low region by Gauss-Legendre panels on the smooth pieces between the
/// wheel's section joints, the rail's section joints (mapped onto the wheel) and the
/// barriers that separate patches; pushes one [`Average`] per patch.
///
/// The barriers are found from the gaps at the quadrature nodes themselves (8 per panel of
/// 3 weight widths by default): most regions have none, and are integrated once. A region with a barrier
/// is integrated again with the refined barriers as patch boundaries.
pub(super) fn gauss_region(
    pass: &Pass,
    panel_widths: f64,
    (lo, hi): (f64, f64),
    work: &mut Work,
    patches: &mut Vec<Average<FIELDS>>,
) {
    let Pass {
        side,
        pose,
        axle_height,
        d_min,
        width,
        settings,
    } = *pass;
    let pose = &pose;
    let eps = settings.epsilon_mm;
    let width = width.clamp(WIDTH_BOUNDS_MM.0, WIDTH_BOUNDS_MM.1);
    // Breaks: (s, separates patches).
    let breaks = &mut work.breaks;
    breaks.clear();
    breaks.push((lo, true));
    breaks.push((hi, true));
    // The wheel's breaks inside the region.
    let wheel = side.wheel_breaks();
    let from = wheel.partition_point(|&j| j <= lo);
    let to = wheel.partition_point(|&j| j < hi);
    breaks.extend(wheel[from..to].iter().map(|&j| (j, false)));
    // The rail's breaks under the region: the wheel coordinate whose point lies above each,
    // Y(s) = Y_break (Newton: dY/ds = cos + sin F', close to 1, so Y grows with s).
    let y_of = |s: f64| {
        let w = side.wheel_point(s)?;
        let [y, _] = pose.apply(w.y, w.z);
        Some((y, (pose.cos - pose.sin * w.slope) * w.dy_ds))
    };
    let rail = side.rail_break_ys();
    // (With yaw, a region's end may lie just beyond the part of the wheel that takes part:
    // its nodes there are not over the rail, and no rail break is mapped.)
    if let (Some((y_lo, _)), Some((y_hi, _))) = (y_of(lo), y_of(hi)) {
        let from = rail.partition_point(|&y| y < y_lo.min(y_hi) - 1.0);
        let to = rail.partition_point(|&y| y <= y_lo.max(y_hi) + 1.0);
        let mut s = lo;
        for &target in &rail[from..to] {
            // From the previous break's wheel coordinate (the targets increase).
            for _ in 0..20 {
                let Some((y, dy)) = y_of(s) else {
                    break;
                };
                let step = (y - target) / dy;
                s -= step;
                if step.abs() < 1e-12 || !(s > lo - 1.0 && s < hi + 1.0) {
                    break;
                }
            }
            if s > lo && s < hi {
                breaks.push((s, false));
            } else {
                s = s.clamp(lo, hi);
            }
        }
    }
    breaks.sort_by(|x, y| x.0.total_cmp(&y.0));
    let first_patch = patches.len();
    let gauss = Gauss {
        side,
        pose,
        offset: axle_height - d_min,
        eps,
        cutoff: settings.cutoff,
        panel: panel_widths * width,
    };
    gauss.integrate(&work.breaks, &mut work.nodes, &mut work.gaps, patches);

    // Barriers: local maxima of the gap at the nodes that rise more than BARRIER_EPS * eps
    // above both neighbouring minima, refined on the sign of dg/ds.
    let barriers = barrier_maxima(&work.gaps, BARRIER_EPS * eps);
    if barriers.is_empty() {
        return;
    }
    for i in barriers {
        let (mut a, mut b) = (work.nodes[i - 1], work.nodes[i + 1]);
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            // Once the midpoint rounds onto an end, further halvings keep it there (or
            // collapse the bracket onto it): the refined barrier is `m` itself.
            if !(a < m && m < b) {
                break;
            }
            match side.at(m, pose) {
                Some(p) if p.dg < 0.0 => b = m,
                _ => a = m,
            }
        }
        work.breaks.push((0.5 * (a + b), true));
    }
    work.breaks.sort_by(|x, y| x.0.total_cmp(&y.0));
    patches.truncate(first_patch);
    gauss.integrate(&work.breaks, &mut work.nodes, &mut work.gaps, patches);
}

/// The Gauss-Legendre integration of one wheel at one pose.
struct Gauss<'a, 'b> {
    side: &'a SideGap<'b>,
    pose: &'a SidePose,
    /// Added to [`GapPoint::g`](crate::gap::GapPoint) to measure gaps from the
    /// wheel's minimum (mm).
    offset: f64,
    eps: f64,
    cutoff: f64,
    /// Panel length (mm).
    panel: f64,
}

impl Gauss<'_, '_> {
    /// Integrates between consecutive `breaks` (sorted), one patch ending at every
    /// separating break; pushes the patches with weight, and leaves the nodes evaluated and
    /// their gaps in `nodes` and `gaps` (increasing `s`).
    fn integrate(
        &self,
        breaks: &[(f64, bool)],
        nodes: &mut Vec<f64>,
        gaps: &mut Vec<f64>,
        patches: &mut Vec<Average<FIELDS>>,
    ) {
        nodes.clear();
        gaps.clear();
        let mut current = Accumulator::default();
        for k in 0..breaks.len() - 1 {
            let (a, b) = (breaks[k].0, breaks[k + 1].0);
            if b - a > 1e-12 {
                let panels = ((b - a) / self.panel).ceil().max(1.0) as usize;
                let h = (b - a) / panels as f64;
                // A piece much shorter than a panel (between close joints, or between the
                // knots of a spline) takes the 4-point rule: see SHORT_PIECE.
                let (xs, ws): (&[f64], &[f64]) = if b - a <= SHORT_PIECE * self.panel {
                    (&GL4_X, &GL4_W)
                } else {
                    (&GL8_X, &GL8_W)
                };
                for j in 0..panels {
                    let mid = a + (j as f64 + 0.5) * h;
                    // The panel's `m` nodes and gaps, appended at once.
                    let (mut s_of, mut d_of, mut m) = ([0.0; 8], [0.0; 8], 0);
                    // Nodes in increasing `s`: the lower half from the panel's start inwards.
                    let lower = xs.iter().zip(ws).rev().map(|(x, w)| (-x, *w));
                    let upper = xs.iter().zip(ws).map(|(x, w)| (*x, *w));
                    // The panel's nodes and their wheel points, four at a time (SIMD lanes
                    // where the profile has them: one section per panel, see gauss_region).
                    let mut panel = [(0.0, 0.0); 8];
                    let n = xs.len() * 2;
                    for (slot, (x, w)) in panel.iter_mut().zip(lower.chain(upper)) {
                        *slot = (mid + 0.5 * h * x, w);
                    }
                    for quad in panel[..n].chunks_exact(4) {
                        self.add_quad(quad, 0.5 * h, &mut current, |s, d| {
                            (s_of[m], d_of[m]) = (s, d);
                            m += 1;
                        });
                    }
                    nodes.extend_from_slice(&s_of[..m]);
                    gaps.extend_from_slice(&d_of[..m]);
                }
            }
            if breaks[k + 1].1 {
                if let Some(avg) = current.finish() {
                    patches.push(avg);
                }
                current = Accumulator::default();
            }
        }
    }

    /// Four nodes `quad` (`(s, Gauss weight)`) of a panel of half-length `half_h`: their
    /// wheel points and gaps in SIMD lanes, then the weights of those within the cut-off four
    /// at once, added to `current` in node order; `record(s, d)` for every node over the
    /// rail, in order.
    #[inline(always)]
    fn add_quad(
        &self,
        quad: &[(f64, f64)],
        half_h: f64,
        current: &mut Accumulator,
        mut record: impl FnMut(f64, f64),
    ) {
        let s4 = [quad[0].0, quad[1].0, quad[2].0, quad[3].0];
        let wheel = self.side.wheel().at_x4(s4);
        // A dummy `z` of 0 in the lanes of nodes without weight.
        let (mut z4, mut fields) = ([0.0; 4], [[0.0; FIELDS]; 4]);
        let mut weighted = [false; 4];
        self.side.each_x4(s4, wheel, self.pose, |i, p| {
            let d = p.g + self.offset;
            record(quad[i].0, d);
            // f64::min without its NaN handling: the minimum is never NaN, and a NaN gap
            // compares false as f64::min ignores it.
            if d < current.min_gap {
                current.min_gap = d;
            }
            let z = d / self.eps;
            if z <= self.cutoff {
                (z4[i], fields[i], weighted[i]) = (z, fields_of(self.side, &p), true);
            }
        });
        let weights = z4.map(|z| (-z).exp());
        for i in 0..4 {
            if weighted[i] {
                current.add(half_h * quad[i].1 * weights[i], &fields[i]);
            }
        }
    }
}

/// Running weighted sums of one patch.
#[derive(Debug, Clone, Copy)]
struct Accumulator {
    weight: f64,
    sum: [f64; FIELDS],
    min_gap: f64,
}

impl Default for Accumulator {
    fn default() -> Accumulator {
        Accumulator {
            weight: 0.0,
            sum: [0.0; FIELDS],
            min_gap: f64::INFINITY,
        }
    }
}

impl Accumulator {
    #[inline]
    fn add(&mut self, w: f64, f: &[f64; FIELDS]) {
        self.weight += w;
        for (acc, v) in self.sum.iter_mut().zip(f) {
            *acc += w * v;
        }
    }

    fn finish(&self) -> Option<Average<FIELDS>> {
        (self.weight > 0.0).then(|| Average {
            mean: self.sum.map(|v| v / self.weight),
            weight: self.weight,
            min_gap: self.min_gap,
        })
    }
}
