//! Fitting a [`SmoothingSpline`]: the banded Reinsch solve for the second derivatives at the
//! knots and the smoothed values they give.

use super::{SmoothingSpline, SplineError, bucket_table};

impl SmoothingSpline {
    /// Fits the smoothing spline to points `(x[i], y[i])`.
    ///
    /// # Units
    ///
    /// x and y in mm; `lambda` in mm^3 (the penalty integral has units mm^2/mm^4 * mm =
    /// 1/mm, the sum of squares mm^2). Use [`default_lambda`](super::default_lambda) for measured profiles, 0 to
    /// interpolate exact points.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] below 2 points, [`SplineError::LengthMismatch`],
    /// [`SplineError::NonFinite`], [`SplineError::NonIncreasing`] unless x increases
    /// strictly, [`SplineError::InvalidLambda`] for negative or non-finite `lambda`, and
    /// [`SplineError::NumericalBreakdown`] if the solve fails.
    pub fn fit(x: &[f64], y: &[f64], lambda: f64) -> Result<Self, SplineError> {
        if x.len() != y.len() {
            return Err(SplineError::LengthMismatch {
                x: x.len(),
                y: y.len(),
            });
        }
        let n = x.len();
        if n < 2 {
            return Err(SplineError::TooFewPoints { found: n });
        }
        if let Some(index) = (0..n).find(|&i| !(x[i].is_finite() && y[i].is_finite())) {
            return Err(SplineError::NonFinite { index });
        }
        if let Some(index) = (1..n).find(|&i| x[i] <= x[i - 1]) {
            return Err(SplineError::NonIncreasing { index });
        }
        if !(lambda >= 0.0 && lambda.is_finite()) {
            return Err(SplineError::InvalidLambda { lambda });
        }
        let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
        let gamma = second_derivatives(&h, y, lambda)?;
        let values = smoothed_values(&h, y, &gamma, lambda);
        let coeffs: Vec<[f64; 4]> = (0..n - 1)
            .map(|i| {
                let (g0, g1, c0, c1, hi) = (values[i], values[i + 1], gamma[i], gamma[i + 1], h[i]);
                [
                    g0,
                    (g1 - g0) / hi - hi * (2.0 * c0 + c1) / 6.0,
                    c0 / 2.0,
                    (c1 - c0) / (6.0 * hi),
                ]
            })
            .collect();
        let last = coeffs[n - 2];
        let h_last = h[n - 2];
        let end_slopes = [
            coeffs[0][1],
            last[1] + h_last * (2.0 * last[2] + 3.0 * h_last * last[3]),
        ];
        let (buckets, bucket_scale) = bucket_table(x);
        Ok(SmoothingSpline {
            knots: x.to_vec(),
            values,
            coeffs,
            buckets,
            bucket_scale,
            end_slopes,
        })
    }
}

/// Second derivatives at all knots (zero at both ends): the Reinsch system
/// `(R + lambda Q^T Q) gamma = Q^T y` (Green & Silverman eq. 2.12 with unit weights).
fn second_derivatives(h: &[f64], y: &[f64], lambda: f64) -> Result<Vec<f64>, SplineError> {
    let n = y.len();
    let mut gamma = vec![0.0; n];
    if n < 3 {
        return Ok(gamma);
    }
    let m = n - 2;
    // The pentadiagonal symmetric matrix (diagonal, first and second off-diagonals; row k
    // is the interior knot j = k + 1) is factored LDL^T, with a unit lower L of bandwidth 2
    // (l1: first, l2: second sub-diagonal), and the forward and diagonal substitutions done
    // row by row as each row is made: the same operations in the same order as building
    // the matrix, factoring it and substituting one after the other (the test
    // `one_pass_solve_is_the_textbook_solve_to_the_bit`), without keeping the matrix: 5
    // vectors of n and 3 passes fewer.
    let mut l1 = vec![0.0; m];
    let mut l2 = vec![0.0; m];
    // The solution in gamma[1..=m]: first the forward substitution's values divided by D.
    let solution = &mut gamma[1..=m];
    // Of the two rows before: D, and the forward substitution's values before division.
    let (mut d1, mut d2) = (0.0, 0.0);
    let (mut f1, mut f2) = (0.0, 0.0);
    for k in 0..m {
        let j = k + 1;
        let (ha, hb) = (h[j - 1], h[j]);
        let (ia, ib) = (1.0 / ha, 1.0 / hb);
        let diag = (ha + hb) / 3.0 + lambda * (ia * ia + (ia + ib) * (ia + ib) + ib * ib);
        let mut off1 = 0.0;
        if k + 1 < m {
            let ic = 1.0 / h[j + 1];
            off1 = hb / 6.0 - lambda * ib * (ia + 2.0 * ib + ic);
        }
        let mut off2 = 0.0;
        if k + 2 < m {
            off2 = lambda * ib / h[j + 1];
        }
        let mut f = (y[j + 1] - y[j]) * ib - (y[j] - y[j - 1]) * ia;
        let mut dk = diag;
        if k >= 1 {
            dk -= l1[k - 1] * l1[k - 1] * d1;
        }
        if k >= 2 {
            dk -= l2[k - 2] * l2[k - 2] * d2;
        }
        if !(dk > 0.0 && dk.is_finite()) {
            return Err(SplineError::NumericalBreakdown { index: k + 1 });
        }
        let mut o1 = off1;
        if k >= 1 {
            o1 -= l2[k - 1] * l1[k - 1] * d1;
        }
        l1[k] = o1 / dk;
        l2[k] = off2 / dk;
        if k >= 1 {
            f -= l1[k - 1] * f1;
        }
        if k >= 2 {
            f -= l2[k - 2] * f2;
        }
        solution[k] = f / dk;
        (d2, d1) = (d1, dk);
        (f2, f1) = (f1, f);
    }
    // Backward substitution, in place.
    for k in (0..m).rev() {
        if k + 1 < m {
            solution[k] -= l1[k] * solution[k + 1];
        }
        if k + 2 < m {
            solution[k] -= l2[k] * solution[k + 2];
        }
    }
    Ok(gamma)
}

/// Spline values at the knots: `g = y - lambda Q gamma` (Green & Silverman eq. 2.11).
fn smoothed_values(h: &[f64], y: &[f64], gamma: &[f64], lambda: f64) -> Vec<f64> {
    let n = y.len();
    (0..n)
        .map(|i| {
            let mut q_gamma = 0.0;
            if i >= 1 {
                q_gamma += (gamma[i - 1] - gamma[i]) / h[i - 1];
            }
            if i + 1 < n {
                q_gamma += (gamma[i + 1] - gamma[i]) / h[i];
            }
            y[i] - lambda * q_gamma
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Reinsch system solved the textbook way: the matrix built, factored LDL^T and
    /// substituted forward, diagonally and backward, each in its own pass.
    fn second_derivatives_in_passes(h: &[f64], y: &[f64], lambda: f64) -> Option<Vec<f64>> {
        let n = y.len();
        let m = n - 2;
        let (mut diag, mut off1, mut off2, mut rhs) =
            (vec![0.0; m], vec![0.0; m], vec![0.0; m], vec![0.0; m]);
        for k in 0..m {
            let j = k + 1;
            let (ha, hb) = (h[j - 1], h[j]);
            let (ia, ib) = (1.0 / ha, 1.0 / hb);
            diag[k] = (ha + hb) / 3.0 + lambda * (ia * ia + (ia + ib) * (ia + ib) + ib * ib);
            if k + 1 < m {
                let ic = 1.0 / h[j + 1];
                off1[k] = hb / 6.0 - lambda * ib * (ia + 2.0 * ib + ic);
            }
            if k + 2 < m {
                off2[k] = lambda * ib / h[j + 1];
            }
            rhs[k] = (y[j + 1] - y[j]) * ib - (y[j] - y[j - 1]) * ia;
        }
        let (mut d, mut l1, mut l2) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
        for k in 0..m {
            let mut dk = diag[k];
            if k >= 1 {
                dk -= l1[k - 1] * l1[k - 1] * d[k - 1];
            }
            if k >= 2 {
                dk -= l2[k - 2] * l2[k - 2] * d[k - 2];
            }
            if !(dk > 0.0 && dk.is_finite()) {
                return None;
            }
            d[k] = dk;
            let mut o1 = off1[k];
            if k >= 1 {
                o1 -= l2[k - 1] * l1[k - 1] * d[k - 1];
            }
            l1[k] = o1 / dk;
            l2[k] = off2[k] / dk;
        }
        for k in 0..m {
            if k >= 1 {
                rhs[k] -= l1[k - 1] * rhs[k - 1];
            }
            if k >= 2 {
                rhs[k] -= l2[k - 2] * rhs[k - 2];
            }
        }
        for k in 0..m {
            rhs[k] /= d[k];
        }
        for k in (0..m).rev() {
            if k + 1 < m {
                rhs[k] -= l1[k] * rhs[k + 1];
            }
            if k + 2 < m {
                rhs[k] -= l2[k] * rhs[k + 2];
            }
        }
        let mut gamma = vec![0.0; n];
        gamma[1..=m].copy_from_slice(&rhs);
        Some(gamma)
    }

    /// The one-pass solve gives the textbook passes' second derivatives to the bit, on
    /// uneven knots, noisy values and penalties from interpolation (0) to heavy smoothing.
    #[test]
    fn one_pass_solve_is_the_textbook_solve_to_the_bit() {
        let mut rng = crate::rng::SplitMix64::new(7);
        for n in [3, 4, 5, 6, 17, 1001] {
            for lambda in [0.0, 1e-4, 0.3, 50.0, 1e6] {
                let h: Vec<f64> = (1..n).map(|_| 0.05 + rng.uniform()).collect();
                let y: Vec<f64> = (0..n).map(|_| 10.0 * rng.normal()).collect();
                let bits = |g: Vec<f64>| g.into_iter().map(f64::to_bits).collect::<Vec<_>>();
                let got = second_derivatives(&h, &y, lambda).ok().map(bits);
                let want = second_derivatives_in_passes(&h, &y, lambda).map(bits);
                assert!(want.is_some(), "n = {n}, lambda = {lambda}");
                assert_eq!(got, want, "n = {n}, lambda = {lambda}");
            }
        }
    }
}
