//! Placed profiles shared across the scenes of one run: [`PlacementCache`].
//!
//! Reading and fitting a measured profile and placing a rail (its surface, inverse and height
//! tables) is the cold cost of every scene, and the scenes of one run often share them:
//! `wheelrail report a.toml b.toml ...` on one rail, the pairs of a fleet that list the
//! same rail file. A cache hit hands out the rail placed before (`Arc<PlacedRail>`, shared,
//! not copied) or a copy of the profile fitted before; the placement is deterministic, so a
//! hit gives the same numbers to the last digit as placing again.
//!
//! The keys hold everything the result depends on:
//!
//! * a profile: a built-in name (upper case), or a file's path as the scene resolves it (it
//!   is the provenance path the report prints), the SHA-256 of its bytes when looked up, the
//!   reader option (`drop_step_backs`), the smoothing wavelength and wheel or rail. A file
//!   rewritten between two scenes has another hash and is read again;
//! * a placed rail: its profile's key, the inclination the profile data has, and the track
//!   layout (gauge, gauge-point depth, inclination, flange back: every number that
//!   [`PlacedRail::place`] reads).
//!
//! Only successes are kept: an unreadable file or a rail without a gauge point fails again,
//! with the scene's own message. A lookup of a file reads and hashes its bytes before the
//! profile is read on a miss, work without a return where each file is read once, so a run
//! of one scene does not use a cache. The cache holds at most its capacity of each (least
//! recently used dropped first): a fleet of distinct files does not grow it.
//!
//! ```
//! use std::sync::Arc;
//! use wheelrail::{cache::PlacementCache, pipeline, scene::Scene};
//! let scene = Scene::from_toml("", "doc", ".".as_ref()).unwrap();
//! let cache = PlacementCache::new();
//! let a = pipeline::place_cached(&scene, &cache).unwrap();
//! let b = pipeline::place_cached(&scene, &cache).unwrap(); // a hit: nothing placed
//! assert!(Arc::ptr_eq(a.left().shared_rail(), b.left().shared_rail()));
//! ```

use crate::profile::{Profile, ProfileKind};
use crate::scene::{ProfileRef, Scene};
use crate::track::{Inclination, PlacedRail, TrackLayout};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// Entries of each kind a [`PlacementCache::new`] keeps.
pub(crate) const DEFAULT_CAPACITY: usize = 16;

/// Fitted profiles and placed rails of one run, keyed by their inputs (see the [module
/// docs](self)). Shared by reference between threads: lookups lock it briefly; two threads
/// that miss the same key at once both compute it and the first result is kept (the two are
/// equal).
#[derive(Debug)]
pub struct PlacementCache {
    capacity: usize,
    /// Least recently used first.
    profiles: Mutex<Vec<(ProfileKey, Profile)>>,
    /// Least recently used first.
    rails: Mutex<Vec<(RailKey, Arc<PlacedRail>)>>,
}

/// What a profile depends on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum ProfileKey {
    /// A built-in profile, by its name in upper case.
    BuiltIn(String, ProfileKind),
    /// A profile file.
    File {
        path: PathBuf,
        sha256: String,
        kind: ProfileKind,
        drop_step_backs: bool,
        /// The smoothing wavelength's bits (mm).
        smoothing: u64,
    },
}

/// What a placed rail depends on: its profile, the profile data's inclination and the
/// layout's four numbers (as bits: equal keys are equal inputs).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct RailKey {
    profile: ProfileKey,
    profile_inclination: u64,
    layout: [u64; 4],
}

impl ProfileKey {
    /// The key of `scene`'s profile `r` of `kind`; `None` when a file cannot be read (the
    /// load that follows reports it).
    pub(crate) fn of(scene: &Scene, r: &ProfileRef, kind: ProfileKind) -> Option<ProfileKey> {
        let i = match kind {
            ProfileKind::Wheel => 0,
            ProfileKind::Rail => 1,
        };
        Some(match r {
            ProfileRef::BuiltIn(name) => ProfileKey::BuiltIn(name.to_ascii_uppercase(), kind),
            ProfileRef::File(path) => ProfileKey::File {
                path: path.clone(),
                sha256: crate::profile::read::sha256_hex(&std::fs::read(path).ok()?),
                kind,
                drop_step_backs: scene.drop_step_backs[i],
                smoothing: scene.smoothing_wavelength_mm[i].to_bits(),
            },
        })
    }
}

impl RailKey {
    /// The key of a rail of profile `profile` given with `profile_inclination`, placed for
    /// `layout`.
    pub(crate) fn of(
        profile: ProfileKey,
        profile_inclination: Inclination,
        layout: &TrackLayout,
    ) -> RailKey {
        RailKey {
            profile,
            profile_inclination: profile_inclination.0.to_bits(),
            layout: [
                layout.gauge_mm.to_bits(),
                layout.gauge_point_depth_mm.to_bits(),
                layout.inclination.0.to_bits(),
                layout.flange_back_mm.to_bits(),
            ],
        }
    }
}

impl Default for PlacementCache {
    fn default() -> Self {
        PlacementCache::new()
    }
}

/// The value of `key` in `entries` (marked most recently used), or `make`'s, kept when it
/// succeeds (the least recently used entry dropped beyond `capacity`). No lock is held
/// while `make` runs.
fn get_or_make<K: PartialEq, V: Clone, E>(
    entries: &Mutex<Vec<(K, V)>>,
    capacity: usize,
    key: Option<K>,
    make: impl FnOnce() -> Result<V, E>,
) -> Result<V, E> {
    let Some(key) = key else {
        return make();
    };
    // A panic elsewhere while holding the lock leaves the entries valid: use them.
    let lock = || {
        entries
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    };
    {
        let mut entries = lock();
        if let Some(i) = entries.iter().position(|(k, _)| *k == key) {
            let entry = entries.remove(i);
            let value = entry.1.clone();
            entries.push(entry);
            return Ok(value);
        }
    }
    let value = make()?;
    let mut entries = lock();
    if !entries.iter().any(|(k, _)| *k == key) && capacity > 0 {
        if entries.len() >= capacity {
            entries.remove(0);
        }
        entries.push((key, value.clone()));
    }
    Ok(value)
}

impl PlacementCache {
    /// An empty cache that keeps at most 16 profiles and 16 rails.
    pub fn new() -> PlacementCache {
        PlacementCache::with_capacity(DEFAULT_CAPACITY)
    }

    /// An empty cache that keeps at most `capacity` profiles and `capacity` rails (0: none).
    pub fn with_capacity(capacity: usize) -> PlacementCache {
        PlacementCache {
            capacity,
            profiles: Mutex::new(Vec::new()),
            rails: Mutex::new(Vec::new()),
        }
    }

    /// How many fitted profiles and placed rails it holds.
    pub fn len(&self) -> (usize, usize) {
        use std::sync::PoisonError;
        (
            self.profiles
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .len(),
            self.rails
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .len(),
        )
    }

    /// Whether it holds nothing.
    pub fn is_empty(&self) -> bool {
        self.len() == (0, 0)
    }

    /// The profile of `key`, from the cache or from `load` (kept when it succeeds); `load`
    /// alone when there is no key.
    pub(crate) fn profile<E>(
        &self,
        key: Option<ProfileKey>,
        load: impl FnOnce() -> Result<Profile, E>,
    ) -> Result<Profile, E> {
        get_or_make(&self.profiles, self.capacity, key, load)
    }

    /// The placed rail of `key`, from the cache or from `place` (kept when it succeeds);
    /// `place` alone when there is no key.
    pub(crate) fn rail<E>(
        &self,
        key: Option<RailKey>,
        place: impl FnOnce() -> Result<PlacedRail, E>,
    ) -> Result<Arc<PlacedRail>, E> {
        get_or_make(&self.rails, self.capacity, key, || place().map(Arc::new))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline;
    use std::path::Path;

    /// A scene on the EN 15302 rail, copied into `dir` as `rail.csv`, inclined by `incl`.
    fn scene_on_a_rail_file(dir: &Path, incl: &str) -> Scene {
        let toml = format!(
            "[rail]\nprofile = \"rail.csv\"\ninclination = \"{incl}\"\nprofile_inclination = \"1:20\"\n[track]\ngauge_point_depth_mm = 14.4918\n[sweep]\nfrom_mm = 0.0\nto_mm = 1.0\nstep_mm = 1.0"
        );
        Scene::from_toml(&toml, "cache test", dir).unwrap()
    }

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("wheelrail-cache-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let rail = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/en15302/S-UIC519A.csv");
        std::fs::copy(rail, dir.join("rail.csv")).unwrap();
        dir
    }

    /// Every 0.01 mm of the rail's range, bit for bit.
    fn same_rail(a: &PlacedRail, b: &PlacedRail) -> bool {
        let (lo, hi) = a.y_range();
        a.y_range() == b.y_range()
            && (0..=((hi - lo) / 0.01) as usize).all(|i| {
                let y = lo + 0.01 * i as f64;
                a.at(y) == b.at(y)
            })
    }

    #[test]
    fn a_hit_shares_the_rail_placed_before_and_equals_a_cold_placement() {
        let scene = Scene::from_toml("", "cache test", Path::new(".")).unwrap();
        let cache = PlacementCache::new();
        let first = pipeline::place_cached(&scene, &cache).unwrap();
        let hit = pipeline::place_cached(&scene, &cache).unwrap();
        let cold = pipeline::place(&scene).unwrap();
        // The built-in wheel and rail profiles kept, one rail placed and shared by both
        // sides.
        assert_eq!(cache.len(), (2, 1));
        assert!(Arc::ptr_eq(
            first.left().shared_rail(),
            hit.left().shared_rail()
        ));
        assert!(Arc::ptr_eq(
            hit.left().shared_rail(),
            hit.right().shared_rail()
        ));
        assert!(same_rail(hit.left().rail(), cold.left().rail()));
        assert!(same_rail(hit.right().rail(), cold.right().rail()));
    }

    #[test]
    fn a_rewritten_file_and_another_inclination_are_placed_again() {
        let dir = scratch("rewritten");
        let cache = PlacementCache::new();
        let place =
            |incl| pipeline::place_rails_cached(&scene_on_a_rail_file(&dir, incl), &cache).unwrap();
        let [a, _] = place("1:20");
        let [b, _] = place("1:20");
        assert!(Arc::ptr_eq(&a, &b));
        // The same profile at 1:40 is another rail (the fitted profile is shared).
        let [c, _] = place("1:40");
        assert!(!Arc::ptr_eq(&a, &c));
        assert_eq!(cache.len(), (1, 2));
        // Rewritten (a comment added): another hash, read and placed again, to the same
        // surface.
        let text = std::fs::read_to_string(dir.join("rail.csv")).unwrap();
        std::fs::write(dir.join("rail.csv"), format!("{text}\n# rewritten\n")).unwrap();
        let [d, _] = place("1:20");
        assert!(!Arc::ptr_eq(&a, &d));
        assert_ne!(a.profile().source(), d.profile().source());
        assert!(same_rail(&a, &d));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn the_least_recently_used_entry_goes_first() {
        let entries = Mutex::new(Vec::new());
        let get = |k: u32| get_or_make::<_, _, ()>(&entries, 2, Some(k), || Ok(k * 10));
        assert_eq!(get(1), Ok(10));
        assert_eq!(get(2), Ok(20));
        assert_eq!(get(1), Ok(10)); // a hit: 1 is now the most recent
        assert_eq!(get(3), Ok(30)); // 2 goes
        let keys: Vec<u32> = entries.lock().unwrap().iter().map(|e| e.0).collect();
        assert_eq!(keys, [1, 3]);
    }

    #[test]
    fn failures_and_keyless_lookups_are_not_kept() {
        let entries = Mutex::new(Vec::new());
        assert_eq!(
            get_or_make(&entries, 4, Some(1), || Err::<u32, _>("no")),
            Err("no")
        );
        assert_eq!(
            get_or_make::<u32, _, ()>(&entries, 4, None, || Ok(5)),
            Ok(5)
        );
        assert!(entries.lock().unwrap().is_empty());
        // A hit never calls make.
        assert_eq!(
            get_or_make::<_, _, ()>(&entries, 4, Some(2), || Ok(7)),
            Ok(7)
        );
        assert_eq!(get_or_make(&entries, 4, Some(2), || Err("called")), Ok(7));
    }
}
