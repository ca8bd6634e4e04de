//! Counts of the gap evaluations a run makes (cargo feature `count-evaluations`): coarse
//! samples, exact gaps, scans for basins, certificates and the certificate's deep-search
//! cells. They say where a search's work goes in units that do not depend on the machine,
//! beside the instruction counts of callgrind and the medians of `cargo bench`. Without the
//! feature the counting compiles to nothing (the `count!` macro of the crate root).
//!
//! The counts are global, summed over every thread (relaxed atomics): [`take`] them around
//! one call in a process that runs nothing else. `cargo run --release --example
//! evaluation_counts --features count-evaluations` prints them for the paper scene's stages.

use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// What is counted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Event {
    /// A wheel sample's gap against the rail's height table (a coarse sample of a scan).
    CoarseSample,
    /// The exact gap with its derivatives at one wheel coordinate ([`crate::gap::SideGap::at`]).
    ExactGap,
    /// A scan for basins at one pose of one wheel.
    Scan,
    /// A certificate of the global minimum at one pose of one wheel.
    Certificate,
    /// A cell of the certificate's deep search (bounded, split or evaluated at its ends).
    DeepCell,
}

/// One counter per [`Event`], in its order.
static COUNTS: [AtomicU64; 5] = [const { AtomicU64::new(0) }; 5];

/// Adds `n` events.
#[inline]
pub(crate) fn add(event: Event, n: u64) {
    COUNTS[event as usize].fetch_add(n, Relaxed);
}

/// The events counted since the last [`take`] (or the start of the process).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    /// Coarse samples: a wheel sample's gap against the rail's height table.
    pub coarse_samples: u64,
    /// Exact gaps with their derivatives (Newton's steps, the certificate's cell ends,
    /// the quasi-elastic quadrature nodes).
    pub exact_gaps: u64,
    /// Scans for basins (one wheel at one pose).
    pub scans: u64,
    /// Certificates of the global minimum (one wheel at one pose).
    pub certificates: u64,
    /// Cells of the certificate's deep search.
    pub deep_cells: u64,
}

/// The counts since the last call, which restarts them from zero.
pub fn take() -> Counts {
    let [coarse_samples, exact_gaps, scans, certificates, deep_cells] =
        COUNTS.each_ref().map(|c| c.swap(0, Relaxed));
    Counts {
        coarse_samples,
        exact_gaps,
        scans,
        certificates,
        deep_cells,
    }
}
