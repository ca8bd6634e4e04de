//! The top-level modules of `src/` form no import cycle: each module may use those below it
//! and none above, so that a module can be read (and tested) with only what it stands on.
//!
//! The graph is read from the source text: a module `a` uses `b` where a line of `a`'s
//! files outside comments names `crate::b` (an import or a path in code). Unit-test code is
//! left out (a test may run the whole pipeline): files named `tests.rs` or `*_tests.rs`,
//! and a file's `#[cfg(test)] mod tests { ... }` block, which in this crate closes the
//! file. `crate::Error` is the `error` module's.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The lines of `text` before its unit-test module, each with its number (from 1).
fn code_lines(text: &str) -> Vec<(usize, &str)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let next = lines.get(i + 1).map_or("", |l| l.trim());
        let test_block =
            line.trim() == "#[cfg(test)]" && next.contains("mod tests") && !next.ends_with(';');
        if test_block {
            break;
        }
        if !line.trim_start().starts_with("//") {
            out.push((i + 1, *line));
        }
    }
    out
}

/// The top-level modules named as `crate::NAME` on `line`.
fn crate_paths(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("crate::") {
        let before = rest[..i].chars().next_back();
        rest = &rest[i + "crate::".len()..];
        // `$crate::` (a macro) and `wheelrail_crate::` are not this crate's paths.
        if before.is_some_and(|c| c == '$' || c.is_alphanumeric() || c == '_') {
            continue;
        }
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if !name.is_empty() {
            out.push(if name == "Error" {
                "error".into()
            } else {
                name
            });
        }
    }
    out
}

/// `module -> (used module -> the first file and line that uses it)`.
fn module_graph() -> BTreeMap<String, BTreeMap<String, String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    let mut graph: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    for path in files {
        let rel = path.strip_prefix(&src).unwrap();
        let name = rel.file_name().unwrap().to_string_lossy();
        if rel == Path::new("lib.rs") || rel == Path::new("main.rs") {
            continue;
        }
        if name == "tests.rs" || name.ends_with("_tests.rs") {
            continue;
        }
        let first = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy();
        let module = first.trim_end_matches(".rs").to_string();
        let text = std::fs::read_to_string(&path).unwrap();
        let uses = graph.entry(module.clone()).or_default();
        for (number, line) in code_lines(&text) {
            for used in crate_paths(line) {
                if used != module {
                    uses.entry(used)
                        .or_insert_with(|| format!("src/{}:{number}", rel.display()));
                }
            }
        }
    }
    graph
}

/// A cycle of `graph` as its modules in order, if there is one (depth-first search).
fn find_cycle(graph: &BTreeMap<String, BTreeMap<String, String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeMap<String, String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|n| n == node) {
            return Some(path[at..].to_vec());
        }
        if done.contains(node) {
            return None;
        }
        path.push(node.to_string());
        for next in graph.get(node).into_iter().flat_map(|uses| uses.keys()) {
            if let Some(cycle) = visit(next, graph, path, done) {
                return Some(cycle);
            }
        }
        path.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph
        .keys()
        .find_map(|node| visit(node, graph, &mut Vec::new(), &mut done))
}

#[test]
fn top_level_modules_form_no_cycle() {
    let graph = module_graph();
    // The check reads what it should: the stages are found, with the edges they must have.
    assert!(graph["rigid"].contains_key("gap") && graph["pipeline"].contains_key("rigid"));
    if let Some(cycle) = find_cycle(&graph) {
        let mut steps = String::new();
        for (i, module) in cycle.iter().enumerate() {
            let next = &cycle[(i + 1) % cycle.len()];
            steps += &format!("\n  {module} -> {next} ({})", graph[module][next]);
        }
        panic!("the top-level modules form a cycle:{steps}");
    }
}

/// The check finds a cycle where there is one, and names it in order.
#[test]
fn a_cycle_is_found() {
    let edge = |a: &str, b: &str| {
        (
            a.to_string(),
            BTreeMap::from([(b.to_string(), String::new())]),
        )
    };
    let graph = BTreeMap::from([edge("a", "b"), edge("b", "c"), edge("c", "a")]);
    assert_eq!(find_cycle(&graph).unwrap(), ["a", "b", "c"]);
    let graph = BTreeMap::from([edge("a", "b"), edge("b", "c")]);
    assert_eq!(find_cycle(&graph), None);
    assert_eq!(
        crate_paths("use crate::Error; x = $crate::counters::add"),
        ["error"]
    );
}

/// The functions of `src/` over [`LONG_FUNCTION_LINES`] lines, `(file, line, name, lines)`:
/// from a line declaring `fn name` to the line closing its body (braces counted outside
/// comments, strings and character literals).
fn long_functions() -> Vec<(String, usize, String, usize)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut out = Vec::new();
    for path in files {
        let text = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            let code = line.trim_start();
            let Some(name) = declared_fn(code) else {
                continue;
            };
            let (mut depth, mut opened) = (0i64, false);
            for (j, body) in lines[i..].iter().enumerate() {
                for c in code_chars(body) {
                    match c {
                        '{' => (depth, opened) = (depth + 1, true),
                        '}' => depth -= 1,
                        _ => {}
                    }
                }
                if !opened && body.trim_end().ends_with(';') {
                    break;
                }
                if opened && depth == 0 {
                    if j + 1 > LONG_FUNCTION_LINES {
                        let file = path.strip_prefix(&src).unwrap().display().to_string();
                        out.push((file, i + 1, name.to_string(), j + 1));
                    }
                    break;
                }
            }
        }
    }
    out
}

/// Functions longer than this need a sentence in ARCHITECTURE.md saying why they are whole.
const LONG_FUNCTION_LINES: usize = 80;

/// The name of the function `code` (a trimmed line) declares, if it declares one.
fn declared_fn(code: &str) -> Option<&str> {
    if code.starts_with("//") {
        return None;
    }
    let rest = code.split_once("fn ")?;
    let before = rest.0.trim();
    let modifiers = [
        "",
        "pub",
        "pub(crate)",
        "pub(super)",
        "const",
        "pub const",
        "unsafe",
    ];
    if !modifiers.contains(&before) {
        return None;
    }
    let name: &str = rest
        .1
        .split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .next()?;
    (!name.is_empty()).then_some(name)
}

/// The characters of `line` outside its comment, strings and character literals.
fn code_chars(line: &str) -> Vec<char> {
    let (mut out, mut in_string, mut prev) = (Vec::new(), false, ' ');
    let chars: Vec<char> = line.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if in_string {
            if c == '"' && prev != '\\' {
                in_string = false;
            }
        } else if c == '"' {
            in_string = true;
        } else if c == '/' && chars.get(i + 1) == Some(&'/') {
            break;
        } else if c == '\'' && chars.get(i + 2) == Some(&'\'') {
            i += 2;
        } else {
            out.push(c);
        }
        prev = if prev == '\\' && c == '\\' { ' ' } else { c };
        i += 1;
    }
    out
}

#[test]
fn every_long_function_says_why_in_the_architecture() {
    let architecture =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/ARCHITECTURE.md")).unwrap();
    let long = long_functions();
    eprintln!("{} functions over {LONG_FUNCTION_LINES} lines", long.len());
    // The check reads what it should: the reader's messages are one long match.
    assert!(
        long.iter()
            .any(|(file, _, name, _)| file.ends_with("error.rs") && name == "fmt")
    );
    let unexplained: Vec<String> = long
        .iter()
        .filter(|(_, _, name, _)| !architecture.contains(&format!("`{name}`")))
        .map(|(file, line, name, n)| format!("src/{file}:{line}: {name} ({n} lines)"))
        .collect();
    assert!(
        unexplained.is_empty(),
        "functions over {LONG_FUNCTION_LINES} lines without a sentence in ARCHITECTURE.md \
         (\"Kept whole\") naming them: {unexplained:#?}"
    );
}
