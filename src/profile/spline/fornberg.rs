//! Finite-difference weights on arbitrary nodes: the paper's alternative to the spline.

/// Finite-difference weights on arbitrary nodes (Fornberg 1988, "Generation of finite
/// difference formulas on arbitrarily spaced grids", Math. Comp. 51, 699-706; the paper's
/// ref. 12).
///
/// Returns `w` with `w[k][j]` the weight of `f(xs[j])` in the approximation of the k-th
/// derivative at `x0`, for `k = 0..=max_order`: `f^(k)(x0) ~ sum_j w[k][j] f(xs[j])`. The
/// formula is exact for polynomials of degree below `xs.len()`. Nodes must be distinct
/// (repeated nodes give non-finite weights); no order of the nodes is required. Orders at or
/// above `xs.len()` get zero weights (no such formula exists on so few nodes).
///
/// ```
/// use wheelrail::profile::spline::fornberg_weights;
/// // The classic central second difference on a uniform grid: (1, -2, 1) / h^2.
/// let w = fornberg_weights(0.0, &[-0.5, 0.0, 0.5], 2);
/// for (got, want) in w[2].iter().zip([4.0, -8.0, 4.0]) {
///     assert!((got - want).abs() < 1e-12);
/// }
/// ```
pub fn fornberg_weights(x0: f64, xs: &[f64], max_order: usize) -> Vec<Vec<f64>> {
    let n = xs.len();
    let mut w = vec![vec![0.0; n]; max_order + 1];
    if n == 0 {
        return w;
    }
    w[0][0] = 1.0;
    let mut c1 = 1.0;
    let mut c4 = xs[0] - x0;
    for i in 1..n {
        let orders = i.min(max_order);
        let mut c2 = 1.0;
        let c5 = c4;
        c4 = xs[i] - x0;
        for j in 0..i {
            let c3 = xs[i] - xs[j];
            c2 *= c3;
            if j == i - 1 {
                for k in (1..=orders).rev() {
                    w[k][i] = c1 * (k as f64 * w[k - 1][i - 1] - c5 * w[k][i - 1]) / c2;
                }
                w[0][i] = -c1 * c5 * w[0][i - 1] / c2;
            }
            for k in (1..=orders).rev() {
                w[k][j] = (c4 * w[k][j] - k as f64 * w[k - 1][j]) / c3;
            }
            w[0][j] = c4 * w[0][j] / c3;
        }
        c1 = c2;
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fornberg_is_exact_for_polynomials_on_random_nodes() {
        let xs = [-0.31, -0.12, 0.0, 0.07, 0.33, 0.52];
        let x0 = 0.05;
        let w = fornberg_weights(x0, &xs, 4);
        // p(x) = sum c_m x^m, degree 5 = nodes - 1.
        let c = [0.4, -1.3, 2.1, 0.7, -0.9, 1.6];
        let deriv = |k: usize, x: f64| -> f64 {
            (k..c.len())
                .map(|m| {
                    let falling: f64 = (0..k).map(|r| (m - r) as f64).product();
                    c[m] * falling * x.powi((m - k) as i32)
                })
                .sum()
        };
        for (k, wk) in w.iter().enumerate() {
            let approx: f64 = wk.iter().zip(&xs).map(|(wj, xj)| wj * deriv(0, *xj)).sum();
            let exact = deriv(k, x0);
            // Measured at most 1.6e-13 (the weights' rounding, larger for higher orders).
            assert!(
                (approx - exact).abs() < 4e-13 * (1.0 + exact.abs()),
                "order {k}: {approx} vs {exact}"
            );
        }
        assert!(fornberg_weights(0.0, &[], 2).iter().all(Vec::is_empty));
    }
}
