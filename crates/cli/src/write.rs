//! The one layer that writes files. The outputs are made as bytes first; then a report
//! folder shows exactly one run: each new file is staged inside the folder under a hidden
//! name (a folder in the way of its name is an error), and only when all are written are
//! they swapped in, with the replaced files kept aside until the swap is complete (and put
//! back if it fails). A write that fails before the swap removes what it staged.
//!
//! A manifest (`.wheelrail-manifest`, one `group name` line per file) records what wheelrail
//! wrote, per group (`report`, `tradeoff`, `golden`, `fleet`), so that a new run removes the files of
//! its group's earlier run that it does not write again (figures a scene no longer asks for),
//! leaves the other groups' files (a tradeoff study beside a report) and never touches a
//! file it did not write (a user's notes, the scene file itself). A file with the name of one
//! of the run's outputs is replaced whoever wrote it: that name is the report's.
//!
//! A run killed before it finished leaves its staged and set-aside files under hidden names
//! that carry its process id; the next run into the folder clears them up
//! (`recover_leftovers`) once the system shows that process gone.

use crate::Error;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use wheelrail_report::outputs::OutputFile;

/// The manifest's file name.
pub const MANIFEST: &str = ".wheelrail-manifest";
/// A run's new file waiting in the folder: `.wheelrail-new-PID-NAME`.
const STAGED: &str = ".wheelrail-new-";
/// A file a run moved aside until its own is in place: `.wheelrail-old-PID-NAME`.
const ASIDE: &str = ".wheelrail-old-";

/// The command whose files a folder write replaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// `wheelrail report` (and `wheelrail` without arguments).
    Report,
    /// `wheelrail tradeoff`.
    Tradeoff,
    /// `wheelrail check --bless`.
    Golden,
    /// `wheelrail fleet`.
    Fleet,
}

impl Group {
    fn name(self) -> &'static str {
        match self {
            Group::Report => "report",
            Group::Tradeoff => "tradeoff",
            Group::Golden => "golden",
            Group::Fleet => "fleet",
        }
    }
}

/// An error about the folder `dir` (not about the staging folder inside it).
fn folder_error(dir: &Path, what: &str, source: &std::io::Error) -> Error {
    Error::Output {
        path: dir.to_path_buf(),
        problem: format!("cannot {what}: {source}"),
    }
}

/// A file name the manifest may name: one plain component, not hidden (so never the
/// manifest, a staging folder, or anything outside the folder).
fn plain_name(name: &str) -> bool {
    !name.is_empty()
        && !name.starts_with('.')
        && !name.contains(['/', '\\'])
        && Path::new(name).components().count() == 1
}

/// The manifest's entries, `(group, name)`; none when there is no manifest.
fn read_manifest(dir: &Path) -> Result<BTreeSet<(String, String)>, Error> {
    let path = dir.join(MANIFEST);
    let text = match std::fs::read_to_string(&path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(BTreeSet::new()),
        Err(e) => return Err(folder_error(&path, "read wheelrail's manifest", &e)),
    };
    Ok(text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once(' '))
        .filter(|(_, name)| plain_name(name))
        .map(|(g, n)| (g.to_string(), n.to_string()))
        .collect())
}

fn manifest_text(entries: &BTreeSet<(String, String)>) -> String {
    let mut text = String::from(
        "# Files written by wheelrail into this folder (group name); a new run of a group\n# replaces that group's files and removes those it no longer writes.\n",
    );
    for (g, n) in entries {
        text.push_str(&format!("{g} {n}\n"));
    }
    text
}

/// Writes `files` into `dir` as the new output of `group`, all or nothing (see the module
/// docs). `dir` is created if missing.
///
/// # Errors
/// An [`Error`] naming `dir` or the file in the way: `dir` is a file; it cannot be created
/// or written; an output's name is taken by a folder. Before the swap nothing in `dir` has
/// changed; a failure during the swap puts the replaced files back.
pub fn write_folder(dir: &Path, group: Group, files: &[OutputFile]) -> Result<(), Error> {
    let mut staging = Staging::begin(dir, group)?;
    for f in files {
        staging.stage(f)?;
    }
    staging.finish()
}

/// A write of a folder's new output under way ([`write_folder`]): each file is staged
/// (written under a hidden name in the folder), and [`Staging::finish`] swaps them all in.
/// Dropped unfinished (an error on the way), it removes what it staged, and the folder too
/// if it made it: the folder is as it was.
#[derive(Debug)]
struct Staging<'a> {
    dir: &'a Path,
    group: Group,
    /// Whether this write made the folder (so that it held nothing).
    fresh: bool,
    /// The manifest's entries before this write.
    old: BTreeSet<(String, String)>,
    /// The names staged so far.
    names: BTreeSet<String>,
    finished: bool,
}

impl<'a> Staging<'a> {
    /// Makes `dir` if it is missing and clears up after a run killed in it.
    ///
    /// # Errors
    /// As [`write_folder`].
    fn begin(dir: &'a Path, group: Group) -> Result<Staging<'a>, Error> {
        // A folder this run has just made holds nothing: no leftovers, manifest, obstacles
        // or files to set aside are looked for in it.
        let fresh = make_folder(dir)?;
        let old = if fresh {
            BTreeSet::new()
        } else {
            recover_leftovers(dir);
            read_manifest(dir)?
        };
        let staging = Staging {
            dir,
            group,
            fresh,
            old,
            names: BTreeSet::new(),
            finished: false,
        };
        staging.check_not_a_folder(MANIFEST)?;
        Ok(staging)
    }

    /// Stages `file` (a second file of the same name replaces the first).
    ///
    /// # Errors
    /// As [`write_folder`].
    fn stage(&mut self, file: &OutputFile) -> Result<(), Error> {
        self.check_not_a_folder(&file.name)?;
        // Recorded first: a file written in part is removed with the others.
        self.names.insert(file.name.clone());
        std::fs::write(staged(self.dir, &file.name), &file.bytes)
            .map_err(|e| folder_error(self.dir, "write into the folder", &e))
    }

    /// An obstacle: an output's name taken by a folder (or anything but a file).
    fn check_not_a_folder(&self, name: &str) -> Result<(), Error> {
        let path = self.dir.join(name);
        if !self.fresh
            && let Ok(meta) = std::fs::symlink_metadata(&path)
            && meta.is_dir()
        {
            return Err(Error::Output {
                path,
                problem: "is a folder, not a file; wheelrail writes a file of that name: move the folder away or choose another output folder".into(),
            });
        }
        Ok(())
    }

    /// Writes the manifest and swaps the staged files in, moving aside the files they
    /// replace and the group's earlier files that this write does not write again.
    ///
    /// # Errors
    /// As [`write_folder`].
    fn finish(mut self) -> Result<(), Error> {
        let (dir, group) = (self.dir, self.group);
        // The group's earlier files that this run does not write again (only plain files).
        let stale: Vec<&str> = self
            .old
            .iter()
            .filter(|(g, n)| g == group.name() && !self.names.contains(n))
            .map(|(_, n)| n.as_str())
            .filter(|n| std::fs::symlink_metadata(dir.join(n)).is_ok_and(|m| m.is_file()))
            .collect();
        let mut manifest: BTreeSet<(String, String)> = self
            .old
            .iter()
            .filter(|(g, _)| g != group.name())
            .cloned()
            .collect();
        manifest.extend(
            self.names
                .iter()
                .map(|n| (group.name().to_string(), n.clone())),
        );
        // The new files are staged and the replaced ones kept aside under hidden names in
        // the folder itself: a rename within one folder cannot cross file systems.
        let aside = |name: &str| dir.join(format!("{ASIDE}{}-{name}", std::process::id()));
        let incoming: Vec<&str> = self
            .names
            .iter()
            .map(String::as_str)
            .chain([MANIFEST])
            .collect();
        // The names that may hold a file to set aside.
        let present: Vec<&str> = if self.fresh {
            Vec::new()
        } else {
            incoming.iter().chain(&stale).copied().collect()
        };
        let moved_aside = std::fs::write(staged(dir, MANIFEST), manifest_text(&manifest))
            .map_err(|e| folder_error(dir, "write into the folder", &e))
            .and_then(|()| swap(dir, &incoming, &present, |n| staged(dir, n), aside))?;
        self.finished = true;
        for name in moved_aside {
            let _ = std::fs::remove_file(aside(name));
        }
        Ok(())
    }
}

impl Drop for Staging<'_> {
    fn drop(&mut self) {
        if self.finished {
            return;
        }
        // The staged files not placed; a replaced file that could not be put back stays
        // aside, not deleted (see `swap`).
        let manifest = [MANIFEST.to_string()];
        for name in self.names.iter().chain(&manifest) {
            let _ = std::fs::remove_file(staged(self.dir, name));
        }
        if self.fresh {
            // Empty again: removed only if so.
            let _ = std::fs::remove_dir(self.dir);
        }
    }
}

/// Where a run stages the file `name` in `dir` (see [`STAGED`]).
fn staged(dir: &Path, name: &str) -> PathBuf {
    dir.join(format!("{STAGED}{}-{name}", std::process::id()))
}

/// Makes the folder `dir` if it is missing; `true` when this call made it (so that it is
/// empty), `false` when it was there (or its parents had to be made too).
fn make_folder(dir: &Path) -> Result<bool, Error> {
    match std::fs::create_dir(dir) {
        Ok(()) => return Ok(true),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && dir.is_dir() => {
            return Ok(false);
        }
        Err(_) => {}
    }
    if dir.exists() && !dir.is_dir() {
        return Err(Error::Output {
            path: dir.to_path_buf(),
            problem:
                "is a file, not a folder (the output goes into a folder; choose another --out)"
                    .into(),
        });
    }
    std::fs::create_dir_all(dir).map_err(|e| folder_error(dir, "create the folder", &e))?;
    Ok(false)
}

/// Clears up after a run into `dir` that was killed before it finished (its process is
/// gone): a file it had moved aside goes back where no other file took its place, and is
/// removed where one did; a file it had staged is removed. Files of a run still going (a
/// process writing the same folder now) are left alone, and so is everything where the
/// system cannot tell whether a process runs. Best effort: what cannot be moved or removed
/// stays as it was.
fn recover_leftovers(dir: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let file_name = entry.file_name();
        let Some((aside, pid, name)) = file_name.to_str().and_then(leftover) else {
            continue;
        };
        if pid == std::process::id() || may_be_running(pid) {
            continue;
        }
        let target = dir.join(name);
        if aside && std::fs::symlink_metadata(&target).is_err() {
            let _ = std::fs::rename(entry.path(), target);
        } else {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// `(aside, pid, name)` of a file a run staged (`aside` false) or moved aside, from its
/// name; `None` for any other file, and for a name the manifest could not hold.
fn leftover(file_name: &str) -> Option<(bool, u32, &str)> {
    let (aside, rest) = match file_name.strip_prefix(ASIDE) {
        Some(rest) => (true, rest),
        None => (false, file_name.strip_prefix(STAGED)?),
    };
    let (pid, name) = rest.split_once('-')?;
    let pid = pid.parse().ok()?;
    (plain_name(name) || name == MANIFEST).then_some((aside, pid, name))
}

/// Whether process `pid` may still be running. Only Linux's `/proc` tells (and only where it
/// is mounted); elsewhere every process may be.
fn may_be_running(pid: u32) -> bool {
    let proc = Path::new("/proc");
    !cfg!(target_os = "linux") || !proc.join("self").exists() || proc.join(pid.to_string()).exists()
}

/// Moves the files in `dir` under the names `present` (those replaced and the stale ones)
/// aside (to `aside(name)`), then the staged files (and manifest) `incoming` from
/// `staged(name)` into place; on any failure undoes what was done, in reverse. The names
/// moved aside, for the caller to delete.
fn swap<'a>(
    dir: &Path,
    incoming: &[&'a str],
    present: &[&'a str],
    staged: impl Fn(&str) -> PathBuf,
    aside: impl Fn(&str) -> PathBuf,
) -> Result<Vec<&'a str>, Error> {
    let mut moved_aside: Vec<&str> = Vec::new();
    let mut placed: Vec<&str> = Vec::new();
    let attempt = (|| -> Result<(), (PathBuf, std::io::Error)> {
        for &name in present {
            // A name with nothing under it is told by the rename itself (one system call
            // instead of a look-up and the rename).
            let from = dir.join(name);
            match std::fs::rename(&from, aside(name)) {
                Ok(()) => moved_aside.push(name),
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
                Err(e) => return Err((from, e)),
            }
        }
        for &name in incoming {
            let to = dir.join(name);
            std::fs::rename(staged(name), &to).map_err(|e| (to.clone(), e))?;
            placed.push(name);
        }
        Ok(())
    })();
    match attempt {
        Ok(()) => Ok(moved_aside),
        Err((path, source)) => {
            for name in placed.iter().rev() {
                let _ = std::fs::remove_file(dir.join(name));
            }
            for name in moved_aside.iter().rev() {
                let _ = std::fs::rename(aside(name), dir.join(name));
            }
            Err(Error::Io { path, source })
        }
    }
}

/// Writes one file atomically (a temporary file beside it, then a rename): `path` either
/// keeps its old contents or gets all of the new ones.
///
/// # Errors
/// An [`Error`] naming `path` or its folder.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    if path.is_dir() {
        return Err(Error::Output {
            path: path.to_path_buf(),
            problem: "is a folder, not a file (give a file name)".into(),
        });
    }
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path.file_name().ok_or_else(|| Error::Output {
        path: path.to_path_buf(),
        problem: "not a file name".into(),
    })?;
    std::fs::create_dir_all(dir).map_err(|e| folder_error(dir, "create the folder", &e))?;
    let tmp = dir.join(format!(
        ".{}.wheelrail-{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = std::fs::write(&tmp, bytes)
        .map_err(|e| folder_error(dir, "write into the folder", &e))
        .and_then(|()| {
            std::fs::rename(&tmp, path).map_err(|source| Error::Io {
                path: path.to_path_buf(),
                source,
            })
        });
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("wheelrail-write-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn files(names: &[&str], tag: &str) -> Vec<OutputFile> {
        names
            .iter()
            .map(|n| OutputFile {
                name: (*n).to_string(),
                bytes: format!("{n} {tag}").into_bytes(),
            })
            .collect()
    }

    fn listing(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn a_group_replaces_its_own_files_and_nothing_else() {
        let dir = scratch("groups");
        std::fs::write(dir.join("notes.txt"), "mine").unwrap();
        write_folder(&dir, Group::Report, &files(&["a.csv", "b.svg"], "1")).unwrap();
        write_folder(&dir, Group::Tradeoff, &files(&["t.csv"], "1")).unwrap();
        write_folder(&dir, Group::Report, &files(&["a.csv", "c.svg"], "2")).unwrap();
        assert_eq!(
            listing(&dir),
            [MANIFEST, "a.csv", "c.svg", "notes.txt", "t.csv"]
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("a.csv")).unwrap(),
            "a.csv 2"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("t.csv")).unwrap(),
            "t.csv 1"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
            "mine"
        );
        let manifest = std::fs::read_to_string(dir.join(MANIFEST)).unwrap();
        assert!(manifest.ends_with("report a.csv\nreport c.svg\ntradeoff t.csv\n"));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_new_folder_and_new_parents_get_the_same_files() {
        // The run makes the folder (nothing looked for in it), or its parents too (the
        // folder then gets the checks of an existing one).
        let root = scratch("fresh");
        for dir in [root.join("new"), root.join("a/b/new")] {
            write_folder(&dir, Group::Report, &files(&["a.csv", "b.svg"], "1")).unwrap();
            assert_eq!(listing(&dir), [MANIFEST, "a.csv", "b.svg"]);
            assert_eq!(
                std::fs::read_to_string(dir.join("b.svg")).unwrap(),
                "b.svg 1"
            );
            let manifest = std::fs::read_to_string(dir.join(MANIFEST)).unwrap();
            assert!(
                manifest.ends_with("report a.csv\nreport b.svg\n"),
                "{manifest}"
            );
        }
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn a_folder_in_the_way_changes_nothing() {
        let dir = scratch("obstacle");
        write_folder(&dir, Group::Report, &files(&["a.csv", "b.svg"], "1")).unwrap();
        std::fs::remove_file(dir.join("b.svg")).unwrap();
        std::fs::create_dir(dir.join("b.svg")).unwrap();
        let before = listing(&dir);
        let a_before = std::fs::read(dir.join("a.csv")).unwrap();
        let err = write_folder(&dir, Group::Report, &files(&["a.csv", "b.svg"], "2"))
            .unwrap_err()
            .to_string();
        assert!(err.contains("b.svg: is a folder, not a file"), "{err}");
        assert_eq!(listing(&dir), before);
        assert_eq!(std::fs::read(dir.join("a.csv")).unwrap(), a_before);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_failed_swap_puts_the_replaced_files_back() {
        let dir = scratch("rollback");
        write_folder(&dir, Group::Report, &files(&["a.csv", "b.svg"], "1")).unwrap();
        let before = listing(&dir);
        // a.csv is staged, b.svg is not: its move into place fails after a.csv's.
        let staged = |name: &str| dir.join(format!(".staged-{name}"));
        let aside = |name: &str| dir.join(format!(".aside-{name}"));
        std::fs::write(staged("a.csv"), "a.csv 2").unwrap();
        let names = ["a.csv", "b.svg"];
        let err = swap(&dir, &names, &names, staged, aside)
            .unwrap_err()
            .to_string();
        assert!(err.contains("b.svg"), "{err}");
        assert_eq!(listing(&dir), before);
        assert_eq!(
            std::fs::read_to_string(dir.join("a.csv")).unwrap(),
            "a.csv 1"
        );
        // A successful run leaves nothing staged or aside.
        write_folder(&dir, Group::Report, &files(&["a.csv"], "3")).unwrap();
        assert_eq!(listing(&dir), [MANIFEST, "a.csv"]);
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// The id of a process that has ended.
    #[cfg(target_os = "linux")]
    fn ended_process() -> u32 {
        let mut child = std::process::Command::new("true").spawn().unwrap();
        let pid = child.id();
        child.wait().unwrap();
        pid
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn a_killed_runs_leftovers_are_put_back_or_removed() {
        let dir = scratch("killed");
        write_folder(&dir, Group::Report, &files(&["a.csv", "b.svg"], "1")).unwrap();
        // A run killed during its swap: b.svg moved aside and not replaced, a.csv replaced
        // with its old copy still aside, c.csv staged; and a live process's staged file
        // (pid 1 runs as long as the system does).
        let gone = ended_process();
        let name = |kind: &str, pid: u32, file: &str| dir.join(format!("{kind}{pid}-{file}"));
        std::fs::rename(dir.join("b.svg"), name(ASIDE, gone, "b.svg")).unwrap();
        std::fs::write(name(ASIDE, gone, "a.csv"), "a.csv 0").unwrap();
        std::fs::write(name(STAGED, gone, "c.csv"), "half").unwrap();
        std::fs::write(name(STAGED, 1, "d.csv"), "live").unwrap();
        write_folder(&dir, Group::Tradeoff, &files(&["t.csv"], "1")).unwrap();
        let live = format!("{STAGED}1-d.csv");
        assert_eq!(
            listing(&dir),
            [MANIFEST, live.as_str(), "a.csv", "b.svg", "t.csv"]
        );
        for file in ["a.csv", "b.svg"] {
            let text = std::fs::read_to_string(dir.join(file)).unwrap();
            assert_eq!(text, format!("{file} 1"));
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn only_a_runs_own_hidden_names_are_leftovers() {
        assert_eq!(
            leftover(".wheelrail-old-12-a.csv"),
            Some((true, 12, "a.csv"))
        );
        assert_eq!(
            leftover(".wheelrail-old-12-.wheelrail-manifest"),
            Some((true, 12, MANIFEST))
        );
        assert_eq!(
            leftover(".wheelrail-new-7-b-c.svg"),
            Some((false, 7, "b-c.svg"))
        );
        for other in [
            "a.csv",
            MANIFEST,
            ".wheelrail-new-x-a.csv",
            ".wheelrail-new-12",
            ".wheelrail-old-12-.hidden",
            ".wheelrail-old-12-../a.csv",
        ] {
            assert_eq!(leftover(other), None, "{other}");
        }
    }

    #[test]
    fn a_manifest_never_reaches_outside_the_folder() {
        let dir = scratch("hostile");
        let outside = scratch("hostile-outside");
        std::fs::write(outside.join("keep.txt"), "keep").unwrap();
        std::fs::write(
            dir.join(MANIFEST),
            format!(
                "report ../{}/keep.txt\nreport .hidden\nreport /etc/passwd\n",
                outside.file_name().unwrap().to_string_lossy()
            ),
        )
        .unwrap();
        write_folder(&dir, Group::Report, &files(&["a.csv"], "1")).unwrap();
        assert!(outside.join("keep.txt").exists());
        assert_eq!(listing(&dir), [MANIFEST, "a.csv"]);
        let _ = std::fs::remove_dir_all(&dir);
        let _ = std::fs::remove_dir_all(&outside);
    }

    #[test]
    fn a_file_given_as_the_folder_is_refused() {
        let dir = scratch("file");
        let file = dir.join("report.txt");
        std::fs::write(&file, "x").unwrap();
        let err = write_folder(&file, Group::Report, &files(&["a.csv"], "1"))
            .unwrap_err()
            .to_string();
        assert!(err.contains("is a file, not a folder"), "{err}");
        assert_eq!(std::fs::read_to_string(&file).unwrap(), "x");
        let err = write_file(&dir, b"x").unwrap_err().to_string();
        assert!(err.contains("is a folder, not a file"), "{err}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_staging_dropped_unfinished_leaves_the_folder_as_it_was() {
        // An error between two files (a figure that cannot be rendered): the files staged
        // so far go, the folder's own stay, and a folder the staging made goes too.
        let dir = scratch("unfinished");
        write_folder(&dir, Group::Report, &files(&["a.csv"], "1")).unwrap();
        let before = listing(&dir);
        let mut staging = Staging::begin(&dir, Group::Report).unwrap();
        for f in files(&["a.csv", "b.svg"], "2") {
            staging.stage(&f).unwrap();
        }
        drop(staging);
        assert_eq!(listing(&dir), before);
        assert_eq!(
            std::fs::read_to_string(dir.join("a.csv")).unwrap(),
            "a.csv 1"
        );
        let new = dir.join("new");
        let mut staging = Staging::begin(&new, Group::Report).unwrap();
        staging.stage(&files(&["a.csv"], "1")[0]).unwrap();
        drop(staging);
        assert!(!new.exists());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_folder_in_the_way_of_a_later_file_undoes_the_earlier_ones() {
        let dir = scratch("later");
        write_folder(&dir, Group::Report, &files(&["a.csv"], "1")).unwrap();
        std::fs::create_dir(dir.join("b.svg")).unwrap();
        let before = listing(&dir);
        let err = write_folder(&dir, Group::Report, &files(&["a.csv", "b.svg"], "2"))
            .unwrap_err()
            .to_string();
        assert!(err.contains("is a folder, not a file"), "{err}");
        assert_eq!(listing(&dir), before);
        assert_eq!(
            std::fs::read_to_string(dir.join("a.csv")).unwrap(),
            "a.csv 1"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
