//! Why an iterative solver stopped: one type for the roll solvers of [`crate::rigid`] and the
//! ellipse-shape solvers of [`crate::hertz`] (`wheelrail::Stop`, also as `rigid::Stop` and `hertz::Stop`).
//!
//! Anything but [`Stop::Converged`] means the numbers did not meet the solver's own tolerance:
//! the outputs flag such a result instead of plotting it as valid.

use std::fmt;

/// Why an iterative solve stopped.
///
/// # Texts
///
/// The reason appears in two families of outputs, each with its own spelling, kept as they
/// were before the two solvers shared this type:
///
/// | variant        | [`Display`](std::fmt::Display) | [`Stop::status_text`] |
/// |----------------|-------------------|-------------------|
/// | `Converged`    | `converged`       | `converged`       |
/// | `IterationCap` | `iteration_cap`   | `iteration cap`   |
/// | `LeftDomain`   | `left_domain`     | `left domain`     |
/// | `NoContact`    | `no_contact`      | `no contact`      |
/// | `Stalled`      | `stalled`         | `stalled`         |
///
/// `Display` is an identifier: the `stop` column of `wheelrail hertz` and the `ellipse: ...`
/// status of `hertz.csv`. [`Stop::status_text`] is words: the `status` column of
/// `rigid.csv` and the `rigid search: ...` status of the tables built on a rigid sweep.
///
/// # Example
/// ```
/// use wheelrail::Stop;
/// assert_eq!(Stop::IterationCap.to_string(), "iteration_cap");
/// assert_eq!(Stop::IterationCap.status_text(), "iteration cap");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Stop {
    /// The residual or step fell below the solver's tolerance (or no iteration was needed:
    /// the circular Hertz contact).
    Converged,
    /// The iteration cap was reached first; the result is flagged and not plotted.
    IterationCap,
    /// The paper's Hertz fixed-point update would have left `0 < e < 1` or produced a
    /// non-finite value; the last valid iterate is reported. Happens near the circle with
    /// the paper's truncated series.
    LeftDomain,
    /// Rigid search: a wheel is nowhere above its rail (shift beyond the rail head).
    NoContact,
    /// Rigid search: the bracket on the roll collapsed without the residual falling below
    /// the tolerance (the gap minima were not found consistently); flagged, not plotted.
    Stalled,
}

impl Stop {
    /// The reason in words, for `status` columns (see [`Stop`] for the mapping to the
    /// identifier of [`Display`](fmt::Display)).
    pub fn status_text(self) -> &'static str {
        match self {
            Stop::Converged => "converged",
            Stop::IterationCap => "iteration cap",
            Stop::LeftDomain => "left domain",
            Stop::NoContact => "no contact",
            Stop::Stalled => "stalled",
        }
    }
}

impl fmt::Display for Stop {
    /// The reason as an identifier (`iteration_cap`), for machine-read columns.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Stop::Converged => "converged",
            Stop::IterationCap => "iteration_cap",
            Stop::LeftDomain => "left_domain",
            Stop::NoContact => "no_contact",
            Stop::Stalled => "stalled",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::Stop;

    /// The texts are in committed reports and documented CLI output: they must not change.
    #[test]
    fn texts_are_those_of_the_outputs() {
        let all = [
            Stop::Converged,
            Stop::IterationCap,
            Stop::LeftDomain,
            Stop::NoContact,
            Stop::Stalled,
        ];
        let shown: Vec<String> = all.iter().map(Stop::to_string).collect();
        let words: Vec<&str> = all.iter().map(|s| s.status_text()).collect();
        assert_eq!(
            shown,
            [
                "converged",
                "iteration_cap",
                "left_domain",
                "no_contact",
                "stalled"
            ]
        );
        assert_eq!(
            words,
            [
                "converged",
                "iteration cap",
                "left domain",
                "no contact",
                "stalled"
            ]
        );
    }
}
