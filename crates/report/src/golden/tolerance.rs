//! What a golden comparison accepts: the tolerance of a value and the policy that gives
//! every column its tolerance.

use std::fmt;

/// How far an actual value may be from the expected one: `|actual - expected| <= abs + rel *
/// |expected|`.
///
/// `NaN` equals `NaN` (a point that could not be computed must stay so) and differs from every
/// number; an infinity equals only the same infinity.
///
/// # Examples
///
/// ```
/// use wheelrail_report::golden::Tolerance;
///
/// let tol = Tolerance { abs: 1e-6, rel: 1e-9 };
/// assert!(tol.accepts(1000.0, 1000.0 + 1.9e-6)); // allowance 1e-6 + 1e-9 * 1000 = 2e-6
/// assert!(!tol.accepts(1000.0, 1000.0 + 2.1e-6));
/// assert!(tol.accepts(f64::NAN, f64::NAN));
/// assert!(!tol.accepts(f64::NAN, 0.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Absolute allowance, in the column's unit.
    pub abs: f64,
    /// Relative allowance, as a fraction of `|expected|`.
    pub rel: f64,
}

impl Tolerance {
    /// Only identical values pass.
    pub const EXACT: Tolerance = Tolerance { abs: 0.0, rel: 0.0 };

    /// Absolute tolerance only.
    pub const fn abs(abs: f64) -> Self {
        Tolerance { abs, rel: 0.0 }
    }

    /// Relative tolerance only.
    pub const fn rel(rel: f64) -> Self {
        Tolerance { abs: 0.0, rel }
    }

    /// The largest difference accepted around `expected`: `abs + rel * |expected|`.
    pub fn allowance(&self, expected: f64) -> f64 {
        self.abs + self.rel * expected.abs()
    }

    /// Whether `actual` is within tolerance of `expected`.
    pub fn accepts(&self, expected: f64, actual: f64) -> bool {
        match (expected.is_nan(), actual.is_nan()) {
            (true, true) => return true,
            (true, false) | (false, true) => return false,
            (false, false) => {}
        }
        if expected.is_infinite() || actual.is_infinite() {
            return expected.is_infinite()
                && actual.is_infinite()
                && expected.is_sign_positive() == actual.is_sign_positive();
        }
        (actual - expected).abs() <= self.allowance(expected)
    }
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "abs {:e} + rel {:e}", self.abs, self.rel)
    }
}

/// Which tolerance applies to which column: exact names first, then the longest matching
/// name suffix, then the default.
///
/// It may also name a key column (such as `y_ws_mm`) whose value is printed next to each failing
/// row, so a reader sees *where* a curve differs, not only in which row.
///
/// # Examples
///
/// ```
/// use wheelrail_report::golden::{Tolerance, TolerancePolicy};
///
/// let policy = TolerancePolicy::new(Tolerance::rel(1e-9))
///     .suffix("_mm", Tolerance::abs(1e-6))
///     .suffix("_rad", Tolerance::abs(1e-9))
///     .suffix("p0_MPa", Tolerance::rel(1e-6))
///     .column("roll_rad", Tolerance::abs(1e-12));
/// assert_eq!(policy.tolerance_for("y_ws_mm"), Tolerance::abs(1e-6));
/// assert_eq!(policy.tolerance_for("roll_rad"), Tolerance::abs(1e-12));
/// assert_eq!(policy.tolerance_for("left_gamma_rad"), Tolerance::abs(1e-9));
/// assert_eq!(policy.tolerance_for("left_p0_MPa"), Tolerance::rel(1e-6));
/// assert_eq!(policy.tolerance_for("count"), Tolerance::rel(1e-9));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct TolerancePolicy {
    default: Tolerance,
    columns: Vec<(String, Tolerance)>,
    suffixes: Vec<(String, Tolerance)>,
    pub(super) key_column: Option<String>,
    /// Rows whose key lies in `[from, to]`, with the rules that hold there instead.
    regions: Vec<Region>,
}

/// Rows of a key range with rules of their own (see [`TolerancePolicy::region`]).
#[derive(Debug, Clone, PartialEq)]
struct Region {
    from: f64,
    to: f64,
    why: String,
    policy: TolerancePolicy,
}

impl TolerancePolicy {
    /// A policy applying `default` to every column.
    pub fn new(default: Tolerance) -> Self {
        TolerancePolicy {
            default,
            columns: Vec::new(),
            suffixes: Vec::new(),
            key_column: None,
            regions: Vec::new(),
        }
    }

    /// Applies `tol` to the column named exactly `name` (replacing an earlier rule for it).
    pub fn column(mut self, name: impl Into<String>, tol: Tolerance) -> Self {
        let name = name.into();
        self.columns.retain(|(n, _)| *n != name);
        self.columns.push((name, tol));
        self
    }

    /// Applies `tol` to columns whose name ends with `suffix` (replacing an earlier rule for it).
    pub fn suffix(mut self, suffix: impl Into<String>, tol: Tolerance) -> Self {
        let suffix = suffix.into();
        self.suffixes.retain(|(s, _)| *s != suffix);
        self.suffixes.push((suffix, tol));
        self
    }

    /// Names the column whose value identifies a row in diff reports.
    pub fn key_column(mut self, name: impl Into<String>) -> Self {
        self.key_column = Some(name.into());
        self
    }

    /// Applies `policy` instead of this one to the rows whose key column (see
    /// [`TolerancePolicy::key_column`]) lies in `[from, to]`: a region where the results are
    /// known to be less well determined, named by `why` in [`TolerancePolicy::markdown`].
    /// Tables without the key column are compared with this policy's own rules. A region
    /// on both sides of zero is two calls with the same `why`, listed once.
    pub fn region(
        mut self,
        from: f64,
        to: f64,
        why: impl Into<String>,
        policy: TolerancePolicy,
    ) -> Self {
        self.regions.push(Region {
            from,
            to,
            why: why.into(),
            policy,
        });
        self
    }

    /// The tolerance for column `name` in a row whose key is `key` (`None`: a table without
    /// the key column).
    pub fn tolerance_at(&self, name: &str, key: Option<f64>) -> Tolerance {
        key.and_then(|k| self.regions.iter().find(|r| (r.from..=r.to).contains(&k)))
            .map_or_else(
                || self.tolerance_for(name),
                |r| r.policy.tolerance_for(name),
            )
    }

    /// The tolerance for column `name` (outside any region).
    pub fn tolerance_for(&self, name: &str) -> Tolerance {
        if let Some((_, tol)) = self.columns.iter().find(|(n, _)| n == name) {
            return *tol;
        }
        self.suffixes
            .iter()
            .filter(|(s, _)| name.ends_with(s.as_str()))
            .max_by_key(|(s, _)| s.len())
            .map_or(self.default, |(_, tol)| *tol)
    }
}

impl TolerancePolicy {
    /// The policy as Markdown tables (rule, absolute, relative), exact columns first, then
    /// suffixes from the longest (the most specific), then the default; then each region's
    /// rules under a line naming it: what the README quotes, so that a test can hold the two
    /// together.
    pub fn markdown(&self) -> String {
        let mut out = self.rules_markdown(None);
        let key = self.key_column.as_deref().unwrap_or("key");
        let mut listed: Vec<&str> = Vec::new();
        for r in &self.regions {
            if listed.contains(&r.why.as_str()) {
                continue;
            }
            listed.push(&r.why);
            let ranges: Vec<String> = self
                .regions
                .iter()
                .filter(|o| o.why == r.why)
                .map(|o| format!("{} <= {key} <= {}", o.from, o.to))
                .collect();
            out.push_str(&format!(
                "\nWhere {} ({}), the rules that differ:\n\n",
                ranges.join(" or "),
                r.why
            ));
            out.push_str(&r.policy.rules_markdown(Some(self)));
        }
        out
    }

    /// The rules as (rule, tolerance) rows: exact columns, suffixes from the longest, the
    /// default.
    fn rows(&self) -> Vec<(String, Tolerance)> {
        let mut suffixes = self.suffixes.clone();
        suffixes.sort_by(|a, b| b.0.len().cmp(&a.0.len()).then(a.0.cmp(&b.0)));
        self.columns
            .iter()
            .map(|(n, t)| (format!("column `{n}`"), *t))
            .chain(
                suffixes
                    .iter()
                    .map(|(s, t)| (format!("columns ending `{s}`"), *t)),
            )
            .chain(std::iter::once((
                "any other column".to_string(),
                self.default,
            )))
            .collect()
    }

    /// The rules as a Markdown table, leaving out those `outside` has the same.
    fn rules_markdown(&self, outside: Option<&TolerancePolicy>) -> String {
        let number = |x: f64| {
            if x.fract() == 0.0 && x.abs() < 1e6 {
                format!("{x}")
            } else {
                format!("{x:e}")
            }
        };
        let same = outside.map(TolerancePolicy::rows).unwrap_or_default();
        let mut out = String::from("| columns | absolute | relative |\n|---|---|---|\n");
        for (rule, t) in self.rows().into_iter().filter(|row| !same.contains(row)) {
            out.push_str(&format!(
                "| {rule} | {} | {} |\n",
                number(t.abs),
                number(t.rel)
            ));
        }
        out
    }
}

impl Default for TolerancePolicy {
    /// Exact comparison of every column.
    fn default() -> Self {
        TolerancePolicy::new(Tolerance::EXACT)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn infinities_equal_only_themselves() {
        let tol = Tolerance::abs(1.0);
        assert!(tol.accepts(f64::INFINITY, f64::INFINITY));
        assert!(!tol.accepts(f64::INFINITY, f64::NEG_INFINITY));
        assert!(!tol.accepts(f64::INFINITY, 1e308));
        assert!(!tol.accepts(0.0, f64::INFINITY));
    }

    #[test]
    fn suffix_rules_longest_wins_and_later_rule_replaces() {
        let p = TolerancePolicy::new(Tolerance::EXACT)
            .suffix("_mm", Tolerance::abs(1.0))
            .suffix("radius_mm", Tolerance::abs(2.0))
            .suffix("_mm", Tolerance::abs(3.0));
        assert_eq!(p.tolerance_for("left_radius_mm"), Tolerance::abs(2.0));
        assert_eq!(p.tolerance_for("y_mm"), Tolerance::abs(3.0));
    }
}
