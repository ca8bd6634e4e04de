//! A fleet's inputs: its items (a profile file on both wheels or both rails, or a pairs
//! file of wheelsets measured wheel by wheel), their ids, and the shards that split a fleet
//! across machines.

use std::collections::HashSet;
use std::fmt;
use std::path::{Path, PathBuf};
/// One wheelset of the fleet: its id and the files that replace the template's profiles.
#[derive(Debug, Clone, PartialEq)]
pub struct Item {
    /// Unique within the fleet; letters, digits, `.`, `-`, `_` (a folder name for
    /// `--reports`).
    pub id: String,
    /// Left and right wheel profile files; `None`: the template's wheels.
    pub wheels: Option<[PathBuf; 2]>,
    /// Left and right rail profile files; `None`: the template's rails.
    pub rails: Option<[PathBuf; 2]>,
}

/// What the items of a fleet replace in the template: decides the file columns of a row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Inputs {
    /// One wheel profile per item, on both wheels.
    Wheels,
    /// One rail profile per item, on both rails.
    Rails,
    /// Left and right wheels measured separately, and optionally left and right rails.
    Pairs {
        /// Whether the pairs file has rail columns.
        rails: bool,
    },
}

impl Inputs {
    /// The roles of an item's files, in column order (`wheel`, or `left_wheel`,
    /// `right_wheel`, ...): each gives the columns `ROLE_file` and `ROLE_sha256`.
    pub fn roles(self) -> &'static [&'static str] {
        match self {
            Inputs::Wheels => &["wheel"],
            Inputs::Rails => &["rail"],
            Inputs::Pairs { rails: false } => &["left_wheel", "right_wheel"],
            Inputs::Pairs { rails: true } => {
                &["left_wheel", "right_wheel", "left_rail", "right_rail"]
            }
        }
    }

    /// Whether the items replace the rails (whose wear the fleet reports).
    pub fn has_rails(self) -> bool {
        matches!(self, Inputs::Rails | Inputs::Pairs { rails: true })
    }

    /// Whether the items replace the wheels (whose flange dimensions the fleet reports).
    pub fn has_wheels(self) -> bool {
        !matches!(self, Inputs::Rails)
    }

    /// The files of `item` in the order of [`Inputs::roles`] (`None` where the item keeps
    /// the template's profile).
    pub fn files(self, item: &Item) -> Vec<Option<PathBuf>> {
        let w = item.wheels.as_ref();
        let r = item.rails.as_ref();
        match self {
            Inputs::Wheels => vec![w.map(|w| w[0].clone())],
            Inputs::Rails => vec![r.map(|r| r[0].clone())],
            Inputs::Pairs { rails } => {
                let mut v = vec![w.map(|w| w[0].clone()), w.map(|w| w[1].clone())];
                if rails {
                    v.extend([r.map(|r| r[0].clone()), r.map(|r| r[1].clone())]);
                }
                v
            }
        }
    }
}

/// Items for profile files given one by one: each on both wheels (or both rails with
/// `rails`), ids from the file names (see `unique_ids`).
pub fn items_of_files(paths: &[PathBuf], rails: bool) -> Vec<Item> {
    let stems: Vec<String> = paths
        .iter()
        .map(|p| {
            p.file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default()
        })
        .collect();
    unique_ids(&stems)
        .into_iter()
        .zip(paths)
        .map(|(id, p)| {
            let both = Some([p.clone(), p.clone()]);
            if rails {
                Item {
                    id,
                    wheels: None,
                    rails: both,
                }
            } else {
                Item {
                    id,
                    wheels: both,
                    rails: None,
                }
            }
        })
        .collect()
}

/// Ids for names, in order: characters other than letters, digits, `.`, `-` and `_`
/// replaced by `_`, a leading `.` too (ids name folders), empty names `profile`; a name met
/// again gets `-2`, `-3`, ... (the first keeps its name).
pub(crate) fn unique_ids(names: &[String]) -> Vec<String> {
    let mut seen = HashSet::new();
    names
        .iter()
        .map(|name| {
            let mut base: String = name
                .chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '_') {
                        c
                    } else {
                        '_'
                    }
                })
                .collect();
            if base.is_empty() {
                base = "profile".into();
            }
            if base.starts_with('.') {
                base.replace_range(0..1, "_");
            }
            let mut id = base.clone();
            let mut n = 2;
            while !seen.insert(id.clone()) {
                id = format!("{base}-{n}");
                n += 1;
            }
            id
        })
        .collect()
}

/// Whether `id` may name a pair: letters, digits, `.`, `-`, `_`, not starting with `.`.
fn valid_id(id: &str) -> bool {
    !id.is_empty()
        && !id.starts_with('.')
        && id
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '_'))
}

/// The columns of a pairs file.
const PAIR_COLUMNS: [&str; 5] = ["id", "left_wheel", "right_wheel", "left_rail", "right_rail"];

/// Why the inputs of a fleet cannot be used.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum FleetError {
    /// A pairs file that is not one: the file, the line where known, what is wrong.
    Pairs {
        /// The pairs file (as named by the caller).
        origin: String,
        /// The 1-based line, where the problem has one.
        line: Option<u64>,
        /// What is wrong.
        problem: PairsProblem,
    },
    /// A shard that is not `K/N` with `1 <= K <= N` (the text given).
    Shard(String),
    /// No profiles or pairs to assess.
    NoItems,
    /// A pairs file that cannot be read: the file, and the system's reason.
    Unreadable(std::path::PathBuf, String),
}

/// What is wrong with a pairs file.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum PairsProblem {
    /// Not CSV (the parser's message).
    Csv(String),
    /// A column that is not one of the pairs file's.
    UnknownColumn(String),
    /// A column given twice.
    RepeatedColumn(String),
    /// One of `id`, `left_wheel`, `right_wheel` is missing.
    MissingColumn(&'static str),
    /// Only one of the two rail columns.
    OneRailColumn,
    /// An id that cannot name a folder.
    BadId(String),
    /// An id given twice.
    RepeatedId(String),
    /// An empty cell (the pair's id, the column).
    EmptyCell(String, &'static str),
    /// A header and no pairs.
    NoPairs,
}

impl fmt::Display for FleetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (origin, line, problem) = match self {
            FleetError::Pairs {
                origin,
                line,
                problem,
            } => (origin, line, problem),
            FleetError::Shard(text) => {
                return write!(
                    f,
                    "--shard {text:?}: expected K/N with 1 <= K <= N, e.g. 3/8"
                );
            }
            FleetError::NoItems => return f.write_str("no profiles to assess"),
            FleetError::Unreadable(path, reason) => {
                return write!(f, "{}: {reason}", path.display());
            }
        };
        match line {
            Some(line) => write!(f, "{origin}:{line}: ")?,
            None => write!(f, "{origin}: ")?,
        }
        match problem {
            PairsProblem::Csv(message) => f.write_str(message),
            PairsProblem::UnknownColumn(name) => {
                write!(
                    f,
                    "unknown column {name:?}; expected {}",
                    PAIR_COLUMNS.join(",")
                )
            }
            PairsProblem::RepeatedColumn(name) => write!(f, "column {name:?} appears twice"),
            PairsProblem::MissingColumn(name) => write!(
                f,
                "missing column {name:?}; expected id,left_wheel,right_wheel and optionally left_rail,right_rail"
            ),
            PairsProblem::OneRailColumn => {
                f.write_str("give both left_rail and right_rail, or neither")
            }
            PairsProblem::BadId(id) => write!(
                f,
                "id {id:?}: expected letters, digits, '.', '-' and '_', not starting with '.' (it names the pair's report folder)"
            ),
            PairsProblem::RepeatedId(id) => write!(f, "id {id:?} appears twice"),
            PairsProblem::EmptyCell(id, column) => write!(f, "pair {id:?}: empty {column} cell"),
            PairsProblem::NoPairs => f.write_str("no pairs (only a header)"),
        }
    }
}

impl std::error::Error for FleetError {}

/// Reads a pairs file: CSV with the columns `id,left_wheel,right_wheel` and optionally
/// `left_rail,right_rail` (both or neither), `#` comment lines allowed; paths relative to
/// `dir` (the file's folder). Fields are separated by commas, semicolons or tabs, as the
/// header's are (the crate's `delimited` module). A row with both rail cells empty keeps
/// the template's rails. `origin` names the file in messages.
///
/// # Errors
/// [`FleetError::Pairs`] naming `origin` and the line: malformed CSV, a missing or unknown
/// column, an empty cell, an id that is repeated or not a folder name, one rail cell of
/// two, no rows.
pub(crate) fn parse_pairs(
    text: &str,
    origin: &str,
    dir: &Path,
) -> Result<(Vec<Item>, Inputs), FleetError> {
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .delimiter(crate::delimited::Separator::of_text(text).byte())
        .trim(csv::Trim::All)
        .flexible(false)
        .from_reader(text.as_bytes());
    let at = |line: Option<u64>, problem| FleetError::Pairs {
        origin: origin.to_string(),
        line,
        problem,
    };
    let csv_error = |e: csv::Error| {
        at(
            e.position().map(csv::Position::line),
            PairsProblem::Csv(e.to_string()),
        )
    };
    let header = reader.headers().map_err(csv_error)?.clone();
    let header_line = Some(header.position().map_or(1, csv::Position::line));
    let mut column = [None; 5];
    for (i, name) in header.iter().enumerate() {
        let Some(k) = PAIR_COLUMNS.iter().position(|c| *c == name) else {
            return Err(at(header_line, PairsProblem::UnknownColumn(name.into())));
        };
        if column[k].replace(i).is_some() {
            return Err(at(header_line, PairsProblem::RepeatedColumn(name.into())));
        }
    }
    if let Some(k) = (0..3).find(|&k| column[k].is_none()) {
        return Err(at(
            header_line,
            PairsProblem::MissingColumn(PAIR_COLUMNS[k]),
        ));
    }
    let rails = match (column[3], column[4]) {
        (None, None) => false,
        (Some(_), Some(_)) => true,
        _ => return Err(at(header_line, PairsProblem::OneRailColumn)),
    };
    let mut items = Vec::new();
    let mut ids = HashSet::new();
    for record in reader.records() {
        let record = record.map_err(csv_error)?;
        let line = Some(record.position().map_or(0, csv::Position::line));
        let cell = |k: usize| column[k].and_then(|i| record.get(i)).unwrap_or("");
        let id = cell(0).to_string();
        if !valid_id(&id) {
            return Err(at(line, PairsProblem::BadId(id)));
        }
        if !ids.insert(id.clone()) {
            return Err(at(line, PairsProblem::RepeatedId(id)));
        }
        let path = |k: usize| match cell(k) {
            "" => Err(at(
                line,
                PairsProblem::EmptyCell(id.clone(), PAIR_COLUMNS[k]),
            )),
            p => Ok(dir.join(p)),
        };
        let wheels = Some([path(1)?, path(2)?]);
        let rails = match (rails, cell(3), cell(4)) {
            (false, _, _) | (true, "", "") => None,
            _ => Some([path(3)?, path(4)?]),
        };
        items.push(Item { id, wheels, rails });
    }
    if items.is_empty() {
        return Err(at(None, PairsProblem::NoPairs));
    }
    Ok((items, Inputs::Pairs { rails }))
}

/// One part of a fleet split across machines: the `k`-th (from 1) of `n` parts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which part, 1 to `n`.
    pub k: usize,
    /// How many parts.
    pub n: usize,
}

impl Shard {
    /// Parses `K/N` (1 ≤ K ≤ N).
    ///
    /// # Errors
    /// [`FleetError::Shard`].
    ///
    /// ```
    /// use wheelrail::fleet::Shard;
    /// assert_eq!(Shard::parse("2/3"), Ok(Shard { k: 2, n: 3 }));
    /// assert!(Shard::parse("0/3").is_err() && Shard::parse("4/3").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Shard, FleetError> {
        let bad = || FleetError::Shard(text.to_string());
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let k: usize = k.trim().parse().map_err(|_| bad())?;
        let n: usize = n.trim().parse().map_err(|_| bad())?;
        if k == 0 || k > n {
            return Err(bad());
        }
        Ok(Shard { k, n })
    }

    /// The index range of this part of `len` items: consecutive parts whose sizes differ by
    /// at most one, so that the parts' rows concatenated in part order are the whole
    /// fleet's rows in input order.
    ///
    /// ```
    /// use wheelrail::fleet::Shard;
    /// let parts: Vec<_> = (1..=3).map(|k| Shard { k, n: 3 }.range(7)).collect();
    /// assert_eq!(parts, [0..3, 3..5, 5..7]);
    /// ```
    pub fn range(self, len: usize) -> std::ops::Range<usize> {
        let start = |k: usize| k * (len / self.n) + (k).min(len % self.n);
        start(self.k - 1)..start(self.k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Malformed pairs files are errors naming the file and line, never panics.
    #[test]
    fn bad_pairs_files_name_file_and_line() {
        let cases = [
            ("", "p.csv"),
            (
                "id,left_wheel\nws1,a.csv\n",
                "p.csv:1: missing column \"right_wheel\"",
            ),
            (
                "id,left_wheel,right_wheel,left_rail\nws1,a,b,c\n",
                "p.csv:1: give both",
            ),
            ("id,left_wheel,right_wheel\nws1,a.csv\n", "p.csv:2"),
            (
                "id,left_wheel,right_wheel\nws1,a.csv,\n",
                "p.csv:2: pair \"ws1\": empty right_wheel",
            ),
            (
                "id,left_wheel,right_wheel\n../x,a.csv,b.csv\n",
                "p.csv:2: id \"../x\"",
            ),
            ("id,left_wheel,right_wheel\n\"ws1,a.csv,b.csv\n", "p.csv"),
            ("# only a comment\n", "p.csv"),
            (
                "id,id,right_wheel\n",
                "p.csv:1: column \"id\" appears twice",
            ),
        ];
        for (text, expected) in cases {
            let e = parse_pairs(text, "p.csv", Path::new(".")).unwrap_err();
            assert!(e.to_string().contains(expected), "{text:?}: {e}");
        }
        // A repeated id names the line that repeats it and the id.
        let e = parse_pairs(
            "id,left_wheel,right_wheel\nws1,a.whl,b.whl\nws1,c.whl,d.whl\n",
            "p.csv",
            Path::new("."),
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("p.csv:3") && e.contains("ws1"), "{e}");
        let (items, inputs) = parse_pairs(
            "\u{feff}# measured 2026-11-23\nid,left_wheel,right_wheel,left_rail,right_rail\nws1,a.whl,b.whl,,\nws2,a.whl,b.whl,r.ban,s.ban\n",
            "p.csv",
            Path::new("d"),
        )
        .unwrap();
        assert_eq!(inputs, Inputs::Pairs { rails: true });
        assert_eq!(items[0].rails, None);
        assert_eq!(
            items[0].wheels,
            Some([PathBuf::from("d/a.whl"), PathBuf::from("d/b.whl")])
        );
        assert_eq!(
            items[1].rails,
            Some([PathBuf::from("d/r.ban"), PathBuf::from("d/s.ban")])
        );
    }

    /// A spreadsheet's export with semicolons or tabs reads as one with commas.
    #[test]
    fn pairs_files_take_semicolons_and_tabs() {
        let commas = parse_pairs(
            "id,left_wheel,right_wheel\nws1,a.whl,b.whl\n",
            "p.csv",
            Path::new("d"),
        );
        for sep in [";", "\t"] {
            let text = format!(
                "# export\nid{sep}left_wheel{sep}right_wheel\r\nws1{sep}a.whl{sep}b.whl\r\n"
            );
            let other = parse_pairs(&text, "p.csv", Path::new("d"));
            assert_eq!(other, commas, "{text:?}");
        }
    }

    #[test]
    fn shards_cover_the_list_once_in_order() {
        for len in 0..20 {
            for n in 1..7 {
                let parts: Vec<usize> = (1..=n).flat_map(|k| Shard { k, n }.range(len)).collect();
                assert_eq!(parts, (0..len).collect::<Vec<_>>(), "{len} in {n}");
            }
        }
    }

    /// A known value of `unique_ids`.
    #[test]
    fn unique_ids_example() {
        let ids = super::unique_ids(&["w 1".into(), "w_1".into(), "".into(), ".x".into()]);
        assert_eq!(ids, ["w_1", "w_1-2", "profile", "_x"]);
    }
}
