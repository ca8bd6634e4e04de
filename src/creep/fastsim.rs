//! Kalker's FASTSIM: the simplified theory of rolling contact (Kalker 1982; Kalker 1990,
//! Ch. 3), with three flexibilities as CONTACT blends them.
//!
//! # The simplified theory
//!
//! The surface of each body moves at a point by `L` times the traction there (Winkler's
//! bedding with flexibility `L`, mm³/N). In steady rolling a particle enters the patch at its
//! leading edge `x = a_j` of strip `y` traction-free and travels to the trailing edge
//! `-a_j`; where it adheres its traction grows with the rigid slip `w` it accumulates,
//! `dp/d(-x) = -w/L` (forces on the rail), with `w = (ξ - φ y, η + φ x)` and one flexibility
//! per creepage:
//!
//! ```text
//! dp_x/d(-x) = -(ξ/L1 - φ y/L3),    dp_y/d(-x) = -(η/L2 + φ x/L3)
//! ```
//!
//! Where `|p|` would exceed the traction bound `μ p_n(x, y)` it is scaled back onto the bound
//! in the same direction (slip). Kalker's flexibilities make the theory reproduce his linear
//! theory at small creepage (Kalker 1990, §3.2):
//!
//! ```text
//! L1 = 8a / (3 G C11),   L2 = 8a / (3 G C22),   L3 = π a √(a/b) / (4 G C23)
//! ```
//!
//! # Flexibilities blended (CONTACT)
//!
//! [`Flexibility::Blended`] (default) follows CONTACT (`simpflex`, `src/m_hertz.f90`): with
//! the creepages that saturate linear theory, `ξ* = μ FN/(c² G C11)`, `η* = μ FN/(c² G C22)`,
//! `φ* = μ FN/(c³ G C23)`, the creepage level `f = √((ξ² + η² + φ²)/(ξ*² + η*² + φ*²))` (as
//! CONTACT forms it, mixing 1/mm with pure numbers) sets the weight
//! `w = clamp((f - 0.1)/(3 - 0.1), 0, 1)` and each `L_k ← (1 - w) L_k + w L_c`, with the
//! combined flexibility `L_c = (ξ² + η² + (k φ)²)/(ξ²/L1 + η²/L2 + (k φ)²/L3)`,
//! `k = (π a²/4)/(8a/3)`. At full sliding the traction then points along one flexibility's
//! slip. The window `[0.1, 3]` reproduces the flexibilities CONTACT prints for its FASTSIM
//! example (commit d431cdb) to 0.03 % (test `flexibilities_match_contacts_fastsim_example`);
//! the copy of `simpflex` read for this (`src/m_hertz.f90` at commit 0ecc556) starts the
//! window at 0, which would make `L1`, `L2` 0.5 % smaller there. [`Flexibility::Three`]
//! keeps Kalker's three at every creepage.
//!
//! # Discretisation
//!
//! `strips` strips of equal width across the ellipse, each divided into `elements` equal
//! cells along its own length `2 a_j` (Kalker's layout); the traction is followed from cell
//! centre to cell centre (a half cell from the leading edge first), the rigid slip integrated
//! exactly over each step, and the forces are the sum of the centre tractions times the cell
//! areas. In full adhesion this integrates the traction exactly along a strip (it is linear
//! in `x` for ξ, η; the spin's is quadratic), and the adhesion fraction is the area of the
//! cells that adhere (1 in full adhesion, 0 in full slip). The pressure of the bound is
//! scaled so that the cells carry exactly `FN` (the analytic pressure's cell sums differ by
//! about `1/(2 n²)`): in full slip the force is `μ FN` to rounding.
//!
//! Where the traction slips, Kalker's rule ([`Scheme::Kalker`]) scales `p + Δ` (`Δ` the
//! step's increment) back onto the bound. Where spin turns the traction along the strip, that
//! turns it by `Δ_⊥/(g_i + Δ_r)` with the bound `g_i` of the cell it comes from: first order
//! in the cell length (the force errs by 1.8 % of `μ FN` at 32 × 32 against the study's
//! reference below, 26 times the default's error). The default [`Scheme::Midpoint`] keeps
//! Kalker's test for slip and his bound, and turns a traction that already slipped towards
//! `(g_mid - Δ_r/2) e + Δ` (`e` its direction, `g_mid` the bound at mid-step, `Δ_r = Δ·e`):
//! by `Δ_⊥/g_mid` to second order, the midpoint rule for the direction's rate `v_⊥/g` along
//! the strip. Both approach the same limit: Kalker's rule, laid out on CONTACT's grid, moves
//! towards the midpoint scheme's converged values as its grid is refined (test
//! `contacts_fastsim_grid_explains_the_difference`).
//!
//! The strips are independent: they are marched four at a time in SIMD lanes, all groups a
//! cell at a time, so a strip count that is a multiple of 4 costs nothing extra.
//!
//! The default grid (`super::DEFAULT_GRID`, 32 × 32) comes from `study`: against a
//! converged FASTSIM (1000 × 1000) over patches of `a/b` = 1.5 and 0.375 and creepages of
//! 0.3, 1 and 3 times saturation in ξ, η, φ and all three at once, it errs by at most
//! 0.07 % of `μ FN` in force and 0.04 % of `μ FN c` in spin moment, at about 6 µs per patch
//! (`cargo bench --bench creep`, on CONTACT's FASTSIM example; record in
//! `docs/2026-11-27-fastsim-grid.md`); `wheelrail tradeoff` times the study's 13 grids (8 to
//! 64 strips and elements) on its cases and charts them beside the numerical settings
//! (`fastsim_tradeoff`). The error does not fall monotonically with the strip count (a strip's adhesion zone vanishes at some `|y|`, a kink the strip sums straddle
//! differently): 24 × 24 errs by 0.27 %, 28 × 28 by 0.12 %, 40 × 40 by 0.04 %.
//!
//! # Accuracy against the exact theory
//!
//! FASTSIM is an approximation of Kalker's exact theory. On CONTACT's FASTSIM example
//! (`a = 8, b = 4` mm, FN = 82 kN, η = -6.25e-4, φ = 6.25e-4 /mm) the parabolic bound gives
//! `Fy` 5.7 % above CONTACT's exact solution in magnitude and the spin moment 22 % below it;
//! the elliptic bound 2.5 % and 7.1 % below (test `fastsim_example` in `crates/cli/tests/creep.rs`).

use super::coefficients::{self, Coefficients};
use super::creepage::Creepages;
use super::tangential::{EllipticPatch, Tangential};
use super::{Bound, Flexibility, Grid, Scheme, Settings};
use std::f64::consts::PI;
use wide::f64x4;

/// Where CONTACT's blending of the flexibilities starts and ends, in units of the creepage
/// that saturates linear theory (module docs).
const BLEND_WINDOW: (f64, f64) = (0.1, 3.0);

/// The flexibilities `[L1, L2, L3]` (mm³/N) FASTSIM uses on `patch` for `creepages`: Kalker's
/// three, blended as the module docs state when the settings ask for it.
///
/// # Units
///
/// mm³/N (`L3` per unit of spin: the same, as φ is per mm).
///
/// # Example
///
/// ```
/// use wheelrail::creep::creepage::Creepages;
/// use wheelrail::creep::fastsim::flexibilities;
/// use wheelrail::creep::tangential::EllipticPatch;
/// use wheelrail::creep::Settings;
/// // No creepage: Kalker's L1 = 8a / (3 G C11), here C11(a/b = 2, ν = 0.28) = 5.2036.
/// let p = EllipticPatch::new(8.0, 4.0, 82_000.0)?;
/// let [l1, _, _] = flexibilities(&p, &Creepages::default(), &Settings::default());
/// assert!((l1 / (64.0 / (3.0 * 82_000.0 * 5.2036)) - 1.0).abs() < 1e-4);
/// # Ok::<(), wheelrail::creep::CreepError>(())
/// ```
pub fn flexibilities(
    patch: &EllipticPatch,
    creepages: &Creepages,
    settings: &Settings,
) -> [f64; 3] {
    let c = coefficients::kalker(patch.a_mm() / patch.b_mm(), settings.poisson());
    flexibilities_with(patch, creepages, &c, settings)
}

fn flexibilities_with(
    patch: &EllipticPatch,
    creepages: &Creepages,
    c: &Coefficients,
    settings: &Settings,
) -> [f64; 3] {
    let (a, b) = (patch.a_mm(), patch.b_mm());
    let g = settings.shear_modulus_mpa();
    let kalker = [
        8.0 * a / (3.0 * g * c.c11),
        8.0 * a / (3.0 * g * c.c22),
        PI * a * (a / b).sqrt() / (4.0 * g * c.c23),
    ];
    if settings.flexibility() == Flexibility::Three {
        return kalker;
    }
    let Creepages {
        xi,
        eta,
        phi_per_mm: phi,
    } = *creepages;
    let cc = patch.c_mm();
    let traction = settings.friction() * patch.normal_force_n() / g;
    let saturating = [
        traction / (cc * cc * c.c11),
        traction / (cc * cc * c.c22),
        traction / (cc * cc * cc * c.c23),
    ];
    let level =
        ((xi * xi + eta * eta + phi * phi) / saturating.iter().map(|s| s * s).sum::<f64>()).sqrt();
    let weight = ((level - BLEND_WINDOW.0) / (BLEND_WINDOW.1 - BLEND_WINDOW.0)).clamp(0.0, 1.0);
    if weight == 0.0 {
        return kalker;
    }
    // The spin's slip over the patch is of the order φ a: weighted by (π a²/4)/(8a/3).
    let k_phi = phi * (PI * a * a / 4.0) / (8.0 * a / 3.0);
    let combined = (xi * xi + eta * eta + k_phi * k_phi)
        / (xi * xi / kalker[0] + eta * eta / kalker[1] + k_phi * k_phi / kalker[2]);
    kalker.map(|l| (1.0 - weight) * l + weight * combined)
}

/// FASTSIM on `patch` (module docs).
pub(super) fn solve(
    patch: &EllipticPatch,
    creepages: &Creepages,
    coefficients: &Coefficients,
    settings: &Settings,
) -> Tangential {
    let [l1, l2, l3] = flexibilities_with(patch, creepages, coefficients, settings);
    let (fx_n, fy_n, mz_nmm, adhesion_fraction) = march(
        patch,
        [
            creepages.xi / l1,
            creepages.eta / l2,
            creepages.phi_per_mm / l3,
        ],
        settings.friction(),
        settings.bound(),
        settings.grid(),
        settings.scheme() == Scheme::Midpoint,
    );
    Tangential {
        fx_n,
        fy_n,
        mz_nmm,
        adhesion_fraction,
        coefficients: *coefficients,
    }
}

/// The strips of FASTSIM, four at a time in SIMD lanes (a last group is filled with strips
/// of zero length, which add nothing), all groups a cell at a time so that their
/// independent dependency chains overlap: `slopes = [ξ/L1, η/L2, φ/L3]`; returns
/// `(Fx, Fy, Mz, adhesion fraction)`.
fn march(
    patch: &EllipticPatch,
    [sx, sy, sphi]: [f64; 3],
    friction: f64,
    bound: Bound,
    grid: Grid,
    second_order: bool,
) -> (f64, f64, f64, f64) {
    let layout = Layout::new(patch, grid);
    let bound = TractionBound::new(&layout, bound, friction * patch.normal_force_n());
    let (sy, sphi) = (f64x4::splat(sy), f64x4::splat(sphi));
    let mut groups = layout.groups(sx, sphi);
    for i in 0..layout.elements {
        let centre = f64x4::splat(i as f64 + 0.5);
        for s in &mut groups {
            s.step(centre, sy, sphi, &bound, second_order);
        }
    }
    layout.forces(&groups)
}

/// The strips and cells of [`march`] on a patch (module docs, Discretisation).
struct Layout {
    /// The patch's semi-axes, mm.
    a: f64,
    b: f64,
    strips: usize,
    /// Cells per strip.
    elements: usize,
    /// The strips' width, mm.
    dy: f64,
}

impl Layout {
    fn new(patch: &EllipticPatch, grid: Grid) -> Self {
        let b = patch.b_mm();
        let strips = grid.strips as usize;
        Layout {
            a: patch.a_mm(),
            b,
            strips,
            elements: grid.elements as usize,
            dy: 2.0 * b / strips as f64,
        }
    }

    /// The centre line of strip `j`, mm.
    fn centre(&self, j: usize) -> f64 {
        -self.b + (j as f64 + 0.5) * self.dy
    }

    /// Half the length `a_j` of strip `j`, mm.
    fn half_length(&self, j: usize) -> f64 {
        let across = self.centre(j) / self.b;
        self.a * ((1.0 - across) * (1.0 + across)).sqrt()
    }

    /// The strips in groups of [`LANES`], traction-free at their leading edges, with the
    /// slopes `sx = ξ/L1` and `sphi = φ/L3` (in every lane).
    fn groups(&self, sx: f64, sphi: f64x4) -> Vec<Strips> {
        let zero = f64x4::ZERO;
        (0..self.strips.div_ceil(LANES))
            .map(|g| {
                let lanes: [(f64, f64); LANES] = std::array::from_fn(|k| {
                    let j = g * LANES + k;
                    if j >= self.strips {
                        return (0.0, 0.0);
                    }
                    (self.centre(j), self.half_length(j))
                });
                let y = f64x4::from(lanes.map(|l| l.0));
                let half = f64x4::from(lanes.map(|l| l.1));
                Strips {
                    y,
                    half,
                    dx: half * f64x4::splat(2.0 / self.elements as f64),
                    // Along a strip p_x changes at the constant rate -(ξ/L1 - φ y/L3).
                    rate_x: -(f64x4::splat(sx) - sphi * y),
                    px: zero,
                    py: zero,
                    x_prev: half,
                    g_prev: zero,
                    slipped: zero.simd_gt(zero),
                    sum_x: zero,
                    sum_y: zero,
                    sum_m: zero,
                    sticking: zero,
                }
            })
            .collect()
    }

    /// `(Fx, Fy, Mz, adhesion fraction)` of the marched `groups`: their centre tractions
    /// and moments times the cell areas, and the share of the area whose cells adhere.
    fn forces(&self, groups: &[Strips]) -> (f64, f64, f64, f64) {
        let zero = f64x4::ZERO;
        let (mut fx, mut fy, mut mz, mut adhering, mut total) = (zero, zero, zero, zero, zero);
        for s in groups {
            let cell = s.dx * f64x4::splat(self.dy);
            fx += s.sum_x * cell;
            fy += s.sum_y * cell;
            mz += s.sum_m * cell;
            adhering += s.sticking * cell;
            total += f64x4::splat(self.elements as f64) * cell;
        }
        (
            fx.reduce_add(),
            fy.reduce_add(),
            mz.reduce_add(),
            adhering.reduce_add() / total.reduce_add(),
        )
    }
}

/// The traction bound `μ p_n` of [`march`]: `peak (a_j² - x²)` (parabolic) or
/// `peak √(a_j² - x²)` (elliptic).
struct TractionBound {
    /// In every lane.
    peak: f64x4,
    parabolic: bool,
}

impl TractionBound {
    /// The bound of `μ FN = traction_n` on `layout`. The pressure is `k (a_j² - x²)` or
    /// `k √(a_j² - x²)`, with `k` such that the cells carry exactly FN: on every strip the
    /// cell centres sit at the same fractions u of a_j, so a strip carries `k a_j³ P`
    /// (`k a_j² P`) with one sum P over u. (The analytic k, `2 FN/(π a³ b)` or
    /// `3 FN/(2 π a² b)`, is larger by about `1/(2 n²)` and the strips' error: a full slip
    /// would then exceed μ FN.)
    fn new(layout: &Layout, bound: Bound, traction_n: f64) -> Self {
        let parabolic = bound == Bound::Parabolic;
        let elements = layout.elements;
        let per_strip: f64 = (0..elements)
            .map(|i| {
                let u = 1.0 - (2 * i + 1) as f64 / elements as f64;
                let room = (1.0 - u) * (1.0 + u);
                if parabolic { room } else { room.sqrt() }
            })
            .sum::<f64>()
            * (2.0 / elements as f64);
        let carried: f64 = (0..layout.strips)
            .map(|j| {
                let h = layout.half_length(j);
                if parabolic { h * h * h } else { h * h }
            })
            .sum::<f64>()
            * per_strip
            * layout.dy;
        TractionBound {
            peak: f64x4::splat(traction_n / carried),
            parabolic,
        }
    }

    /// The bound at `x` on strips of half lengths `half`, MPa.
    #[inline(always)]
    fn at(&self, half: f64x4, x: f64x4) -> f64x4 {
        let room = (half - x) * (half + x);
        if self.parabolic {
            self.peak * room
        } else {
            self.peak * room.max(f64x4::ZERO).sqrt()
        }
    }
}

/// The state of four strips of [`march`] (one per SIMD lane).
struct Strips {
    /// The strips' centre lines, mm.
    y: f64x4,
    /// Half their lengths `a_j`, mm.
    half: f64x4,
    /// Their cell lengths, mm.
    dx: f64x4,
    /// `dp_x/dx` along each strip.
    rate_x: f64x4,
    /// The traction at the last cell centre, MPa.
    px: f64x4,
    py: f64x4,
    /// The last cell centre, mm.
    x_prev: f64x4,
    /// The bound there, MPa.
    g_prev: f64x4,
    /// A lane mask: the last cell slipped (its traction lies on the bound).
    slipped: f64x4,
    /// Sums of the centre tractions and moments, and the count of adhering cells.
    sum_x: f64x4,
    sum_y: f64x4,
    sum_m: f64x4,
    sticking: f64x4,
}

impl Strips {
    /// One step of the four strips to the cell centre `centre` (in cells from the leading
    /// edge): the rigid slip integrated over the step (`sy = η/L2`, `sphi = φ/L3`), the
    /// traction scaled back onto `bound` where it slips, and the sums.
    // Inlined always (and `TractionBound::at`): the march of four strips is the innermost
    // loop of every FASTSIM patch, and a plain `#[inline]` left the call in Kalker's
    // scheme (`cargo bench --bench creep -- fastsim_kalker_scheme` compares the two).
    #[inline(always)]
    fn step(
        &mut self,
        centre: f64x4,
        sy: f64x4,
        sphi: f64x4,
        bound: &TractionBound,
        second_order: bool,
    ) {
        let (zero, one, one_half) = (f64x4::ZERO, f64x4::splat(1.0), f64x4::splat(0.5));
        let x = self.half - self.dx * centre;
        let step = self.x_prev - x;
        let middle = one_half * (self.x_prev + x);
        let (dpx, dpy) = (self.rate_x * step, -(sy + sphi * middle) * step);
        let limit = bound.at(self.half, x);
        let (qx, qy) = (self.px + dpx, self.py + dpy);
        let slip = (qx * qx + qy * qy).simd_gt(limit * limit);
        // Slip: the traction on the bound. Kalker turns it towards p + Δ; the midpoint
        // scheme turns a traction that already slipped by the step's tangential part
        // over the bound at mid-step (module docs).
        let (mut tx, mut ty) = (qx, qy);
        if second_order {
            // The direction of (g_mid - (Δ·p)/(2 g)) p/g + Δ with |p| = g, times g²
            // (only its direction is used): no division.
            let g = self.g_prev;
            let k = bound.at(self.half, middle) * g - one_half * (dpx * self.px + dpy * self.py);
            let g2 = g * g;
            tx = self.slipped.select(k * self.px + g2 * dpx, qx);
            ty = self.slipped.select(k * self.py + g2 * dpy, qy);
        }
        let scale = limit / (tx * tx + ty * ty).sqrt();
        self.px = slip.select(tx * scale, qx);
        self.py = slip.select(ty * scale, qy);
        self.slipped = slip;
        self.g_prev = limit;
        self.x_prev = x;
        self.sticking += slip.select(zero, one);
        self.sum_x += self.px;
        self.sum_y += self.py;
        self.sum_m += x * self.py - self.y * self.px;
    }
}

/// Strips marched at once (SIMD lanes of `wide::f64x4`).
const LANES: usize = 4;

/// One row of the discretisation study: a grid's largest error over the study's cases
/// against a converged FASTSIM.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyRow {
    /// The grid.
    pub grid: Grid,
    /// Largest `|ΔFx|`, `|ΔFy|` over all cases, relative to `μ FN`.
    pub force_error: f64,
    /// Largest `|ΔMz|` over all cases, relative to `μ FN c`.
    pub moment_error: f64,
}

/// The cases of `study`: two patches (`a/b = 1.5` and `0.375`, 50 kN), each with creepages
/// of 0.3, 1 and 3 times the creepage that saturates linear theory, in ξ alone, η alone, φ
/// alone and all three at once (with signs mixed).
pub fn study_cases() -> Vec<(EllipticPatch, Creepages)> {
    let settings = Settings::default();
    let mut cases = Vec::new();
    for (a, b) in [(6.0, 4.0), (3.0, 8.0)] {
        // Valid by construction: positive semi-axes and force.
        let Ok(patch) = EllipticPatch::new(a, b, 50_000.0) else {
            continue;
        };
        let c = coefficients::kalker(a / b, settings.poisson());
        let cc = patch.c_mm();
        let t = settings.friction() * patch.normal_force_n() / settings.shear_modulus_mpa();
        let (xi, eta, phi) = (
            t / (cc * cc * c.c11),
            t / (cc * cc * c.c22),
            t / (cc * cc * cc * c.c23),
        );
        for level in [0.3, 1.0, 3.0] {
            for (x, e, p) in [
                (xi, 0.0, 0.0),
                (0.0, eta, 0.0),
                (0.0, 0.0, phi),
                (0.5 * xi, -0.5 * eta, 0.5 * phi),
            ] {
                cases.push((
                    patch,
                    Creepages {
                        xi: level * x,
                        eta: level * e,
                        phi_per_mm: level * p,
                    },
                ));
            }
        }
    }
    cases
}

/// The grids of the discretisation study as `wheelrail tradeoff` measures them: square grids
/// of 8 to 64 strips and elements around the default, and the default's strips or elements
/// halved or doubled.
pub const STUDY_GRIDS: [Grid; 13] = [
    square(8),
    square(12),
    square(16),
    square(20),
    square(24),
    square(28),
    square(32),
    square(40),
    square(48),
    square(64),
    Grid {
        strips: 16,
        elements: 32,
    },
    Grid {
        strips: 32,
        elements: 16,
    },
    Grid {
        strips: 32,
        elements: 64,
    },
];

/// The converged grid the discretisation study compares with: 1000 × 1000 cells, a thousand
/// times the default's.
pub const STUDY_REFERENCE: Grid = square(1000);

/// `n` strips of `n` elements.
const fn square(n: u32) -> Grid {
    Grid {
        strips: n,
        elements: n,
    }
}

/// The discretisation study: for each grid, the largest error of FASTSIM over
/// [`study_cases`] against the same FASTSIM on `reference` (default settings otherwise).
/// Run times are measured separately (`cargo bench --bench creep`).
///
/// # Example
///
/// ```
/// use wheelrail::creep::Grid;
/// use wheelrail::creep::fastsim::study;
/// let g = |n| Grid { strips: n, elements: n };
/// let rows = study(&[g(5), g(20)], g(200));
/// assert!(rows[1].force_error < rows[0].force_error);
/// ```
pub fn study(grids: &[Grid], reference: Grid) -> Vec<StudyRow> {
    let cases = study_cases();
    let solve_on = |grid: Grid| -> Vec<Tangential> {
        let Ok(settings) = Settings::default().with_grid(grid) else {
            return Vec::new();
        };
        cases
            .iter()
            .map(|(p, c)| super::tangential::solve(p, c, &settings))
            .collect()
    };
    let exact = solve_on(reference);
    grids
        .iter()
        .map(|&grid| {
            let mut row = StudyRow {
                grid,
                force_error: f64::NAN,
                moment_error: f64::NAN,
            };
            let got = solve_on(grid);
            if got.len() == exact.len() {
                let (mut force, mut moment) = (0.0f64, 0.0f64);
                for ((p, _), (g, e)) in cases.iter().zip(got.iter().zip(&exact)) {
                    let scale = Settings::default().friction() * p.normal_force_n();
                    force = force.max((g.fx_n - e.fx_n).abs().max((g.fy_n - e.fy_n).abs()) / scale);
                    moment = moment.max((g.mz_nmm - e.mz_nmm).abs() / (scale * p.c_mm()));
                }
                row.force_error = force;
                row.moment_error = moment;
            }
            row
        })
        .collect()
}
