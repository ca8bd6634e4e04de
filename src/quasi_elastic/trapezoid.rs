//! The trapezoid variant of the quasi-elastic averages
//! ([`Quadrature::Trapezoid`](super::Quadrature::Trapezoid)): nodes on a fixed grid over
//! each low region, averaged by [`average`]. Only first order across a section joint; the
//! Gauss-Legendre panels (`gauss.rs`) are the default.

use super::{Average, BARRIER_EPS, FIELDS, Pass, Work, barrier_maxima, fields_of};

/// Trapezoid steps per weight width `sqrt(eps / d'')` at the rigid contact point.
pub(crate) const TRAPEZOID_STEPS_PER_WIDTH: f64 = 8.0;
/// Smallest quadrature step wanted (mm): bounds the cost where `eps / d''` is tiny.
pub(crate) const MIN_STEP_MM: f64 = 1e-4;

/// The trapezoid variant on one region `(lo, hi)`: nodes on a fixed grid, averaged by
/// `average`.
pub(super) fn trapezoid_region(
    pass: &Pass,
    max_step_mm: f64,
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
    let domain = side.wheel().profile().domain();
    // The step is the largest step halved until it resolves the width, and the nodes are
    // its multiples: a fixed grid, the same on both sides of a symmetric wheelset.
    let wanted = (width / TRAPEZOID_STEPS_PER_WIDTH).max(MIN_STEP_MM);
    let halvings = (max_step_mm / wanted).log2().ceil().max(0.0);
    let step = max_step_mm / halvings.exp2();
    // Above about 5e307 mm the halvings overflow 2^1023 and the step would be 0 (an endless
    // grid); the scene refuses such steps, library callers get the wanted step itself.
    let step = if step.is_normal() { step } else { wanted };
    work.nodes.clear();
    work.gaps.clear();
    work.fields.clear();
    let k_lo = (lo / step).floor() as i64;
    let k_hi = (hi / step).ceil() as i64;
    for k in k_lo..=k_hi {
        let s = k as f64 * step;
        // The grid is rounded outwards; beyond its domain the profile is clamped and a node
        // there would be a phantom point of the wheel.
        if !(domain.0..=domain.1).contains(&s) {
            continue;
        }
        let Some(p) = side.at(s, &pose) else { continue };
        work.nodes.push(s);
        work.gaps.push(p.g + axle_height - d_min);
        work.fields.push(fields_of(side, &p));
    }
    patches.extend(average(
        &work.nodes,
        &work.gaps,
        &work.fields,
        settings.epsilon_mm,
        settings.cutoff,
    ));
}

/// Weighted averages of `fields` over `nodes` (increasing, possibly uneven) with weights
/// `exp(-gap / eps)` and trapezoid quadrature, one [`Average`] per patch: the nodes are
/// split into patches at every local maximum of the gap that rises more than `eps` above
/// both neighbouring minima. Gaps are measured from the wheel's minimum gap (the caller
/// subtracts it, the same for every region of a wheel, so that weights compare across
/// regions). Nodes where `gap / eps > cutoff` weigh 0.
///
/// # Example
/// ```
/// use wheelrail::quasi_elastic::average;
/// // Gap kappa s^2 / 2 on an even grid: the averaged location is 0.
/// let s: Vec<f64> = (-200..=200).map(|i| f64::from(i) * 0.01).collect();
/// let gap: Vec<f64> = s.iter().map(|s| 0.05 * s * s).collect();
/// let fields: Vec<[f64; 1]> = s.iter().map(|&s| [s]).collect();
/// let a = average(&s, &gap, &fields, 0.01, 37.0);
/// assert_eq!(a.len(), 1);
/// assert!(a[0].mean[0].abs() < 1e-15);
/// ```
pub fn average<const N: usize>(
    nodes: &[f64],
    gaps: &[f64],
    fields: &[[f64; N]],
    eps: f64,
    cutoff: f64,
) -> Vec<Average<N>> {
    let n = nodes.len();
    if n == 0 {
        return Vec::new();
    }
    // Split points: local maxima with a barrier above both neighbouring minima.
    let mut bounds = vec![0];
    bounds.extend(barrier_maxima(gaps, BARRIER_EPS * eps));
    bounds.push(n - 1);
    bounds
        .windows(2)
        .filter_map(|b| {
            let (first, last) = (b[0], b[1]);
            let mut sum_w = 0.0;
            let mut sum = [0.0; N];
            let mut min_gap = f64::INFINITY;
            for k in first..=last {
                min_gap = min_gap.min(gaps[k]);
                let x = gaps[k] / eps;
                if x > cutoff {
                    continue;
                }
                // Trapezoid weight of node k within [first, last]; a split node is shared.
                let left = if k > first {
                    nodes[k] - nodes[k - 1]
                } else {
                    0.0
                };
                let right = if k < last {
                    nodes[k + 1] - nodes[k]
                } else {
                    0.0
                };
                let w = 0.5 * (left + right) * (-x).exp();
                sum_w += w;
                for (acc, f) in sum.iter_mut().zip(fields[k]) {
                    *acc += w * f;
                }
            }
            (sum_w > 0.0).then(|| Average {
                mean: sum.map(|v| v / sum_w),
                weight: sum_w,
                min_gap,
            })
        })
        .collect()
}
