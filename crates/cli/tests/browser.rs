//! The committed reports in a real browser: every `reports/*/index.html` opened in headless
//! Chromium at a width of 1280 pixels must show every image, log no error and need no
//! horizontal scrolling; every file it links must exist. A page broken on purpose (an
//! image removed, an error logged, an element too wide) must fail each check.
//!
//! The page is opened as a copy in a scratch folder beside copies of its files, with a
//! small script first in its head that records failed loads, errors and `console.error`
//! calls and, once the page has loaded, checks its images and width and writes the
//! findings into the page, which `--dump-dom` prints. The browser is `WHEELRAIL_BROWSER`
//! or the first of `chromium`, `chromium-browser`, `google-chrome` on the `PATH` (`.ci/run`
//! installs Debian's `chromium`); without one the tests say so and pass, unless
//! `WHEELRAIL_REQUIRE_BROWSER` is set (as `.ci/run` sets it once the browser is there).

mod common;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Width of the browser window in pixels.
const WIDTH_PX: u32 = 1280;
/// The longest a page may take in the browser before the test gives up on it.
const PAGE_TIMEOUT: Duration = Duration::from_secs(60);

/// The check, first in the page's head: see the module docs. Its findings, one a line:
/// `viewport W`, `images N`, then one line per problem.
const CHECK: &str = r#"<script>
(function () {
  var problems = [];
  window.addEventListener('error', function (e) {
    var t = e.target, src = t && t.getAttribute && t.getAttribute('src');
    problems.push(src ? 'failed to load ' + src : 'error: ' + e.message);
  }, true);
  var original = console.error;
  console.error = function () {
    problems.push('console.error: ' + Array.prototype.join.call(arguments, ' '));
    original.apply(console, arguments);
  };
  window.addEventListener('load', function () {
    var images = document.images, shown = 0;
    for (var i = 0; i < images.length; i++) {
      var im = images[i];
      if (im.complete && im.naturalWidth > 0) { shown++; }
      else { problems.push('image not shown: ' + im.getAttribute('src')); }
    }
    var d = document.documentElement;
    if (d.scrollWidth > d.clientWidth) {
      problems.push('horizontal overflow: ' + d.scrollWidth + ' px wide in ' + d.clientWidth);
    }
    var out = document.createElement('pre');
    out.id = 'wheelrail-check';
    out.textContent = ['viewport ' + window.innerWidth, 'images ' + shown].concat(problems).join('\n');
    document.body.appendChild(out);
  });
})();
</script>"#;

/// The browser to run, or `None` (with the reason printed) where there is none.
fn browser() -> Option<PathBuf> {
    if let Some(path) = std::env::var_os("WHEELRAIL_BROWSER") {
        return Some(PathBuf::from(path));
    }
    let found = ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .find_map(|name| {
            std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default())
                .map(|dir| dir.join(name))
                .find(|p| p.is_file())
        });
    if found.is_none() {
        assert!(
            std::env::var_os("WHEELRAIL_REQUIRE_BROWSER").is_none(),
            "WHEELRAIL_REQUIRE_BROWSER is set but no browser was found"
        );
        // Straight to standard error: the test harness keeps what `eprintln!` prints of a
        // passing test to itself, and this must be seen.
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED: no browser to check the report pages in (install Debian's chromium, or set WHEELRAIL_BROWSER)"
        );
    }
    found
}

/// What the browser found on a page.
#[derive(Debug)]
struct Findings {
    viewport: u32,
    images: usize,
    problems: Vec<String>,
}

/// Copies the report folder `dir` into the scratch folder `name`, with the check in its
/// page, and `edit` applied to the copy; opens it in `browser` and reads the findings.
fn open(browser: &Path, dir: &Path, name: &str, edit: impl Fn(&Path)) -> Findings {
    let copy = common::scratch(&format!("browser/{name}"));
    for file in std::fs::read_dir(dir).unwrap() {
        let path = file.unwrap().path();
        if path.is_file() {
            std::fs::copy(&path, copy.join(path.file_name().unwrap())).unwrap();
        }
    }
    let page = copy.join("index.html");
    let html = std::fs::read_to_string(&page).unwrap();
    let checked = html.replacen("<head>", &format!("<head>\n{CHECK}"), 1);
    assert_ne!(checked, html, "{}: no <head>", dir.display());
    std::fs::write(&page, checked).unwrap();
    edit(&copy);
    let profile = copy.join(".browser-profile");
    let mut child = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--window-size={WIDTH_PX},1000"))
        .arg("--virtual-time-budget=10000")
        .arg("--dump-dom")
        .arg(format!("file://{}", page.display()))
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("the browser starts");
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > PAGE_TIMEOUT {
            let _ = child.kill();
            panic!("{}: the browser took over {PAGE_TIMEOUT:?}", dir.display());
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let out = child.wait_with_output().unwrap();
    let dom = String::from_utf8_lossy(&out.stdout);
    let marker = "<pre id=\"wheelrail-check\">";
    let at = dom
        .find(marker)
        .unwrap_or_else(|| panic!("{}: no findings in the page: {dom:.400}", dir.display()));
    let text = &dom[at + marker.len()..];
    let text = &text[..text.find("</pre>").unwrap()];
    let lines: Vec<String> = text
        .lines()
        .map(|l| {
            l.replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&quot;", "\"")
                .replace("&amp;", "&")
        })
        .collect();
    let number = |line: &str, key: &str| -> usize {
        line.strip_prefix(key)
            .and_then(|v| v.trim().parse().ok())
            .unwrap_or_else(|| panic!("{}: {line:?}", dir.display()))
    };
    Findings {
        viewport: number(&lines[0], "viewport") as u32,
        images: number(&lines[1], "images"),
        problems: lines[2..].to_vec(),
    }
}

/// The committed report folders with a page.
fn report_folders() -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(common::root().join("reports"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|d| d.join("index.html").is_file())
        .collect();
    dirs.sort();
    dirs
}

/// The targets of a page's `src` and `href` attributes that are files beside it.
fn local_links(html: &str) -> Vec<String> {
    let mut links = Vec::new();
    for attribute in ["src=\"", "href=\""] {
        for (at, _) in html.match_indices(attribute) {
            let rest = &html[at + attribute.len()..];
            let target = &rest[..rest.find('"').unwrap_or(0)];
            if !(target.is_empty() || target.starts_with('#') || target.contains("://")) {
                links.push(target.to_string());
            }
        }
    }
    links
}

#[test]
fn every_committed_report_page_shows_its_images_without_errors_at_1280_px() {
    let folders = report_folders();
    assert!(folders.len() >= 8, "{folders:?}");
    // Every file a page links is there (the browser checks what it shows: the images).
    for dir in &folders {
        let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
        let links = local_links(&html);
        assert!(links.len() > 3, "{}: {links:?}", dir.display());
        for link in links {
            assert!(
                dir.join(&link).is_file(),
                "{}: broken link {link}",
                dir.display()
            );
        }
    }
    let Some(browser) = browser() else { return };
    for dir in &folders {
        let name = dir.file_name().unwrap().to_string_lossy().into_owned();
        let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
        let found = open(&browser, dir, &name, |_| {});
        assert_eq!(found.viewport, WIDTH_PX, "reports/{name}");
        assert_eq!(
            found.images,
            html.matches("<img ").count(),
            "reports/{name}: {found:?}"
        );
        assert!(found.images > 0, "reports/{name}");
        assert!(
            found.problems.is_empty(),
            "reports/{name}: {:?}",
            found.problems
        );
    }
}

/// The checks can fail: a page with an image removed, an error logged and an element
/// wider than the window reports each.
#[test]
fn a_page_broken_on_purpose_fails_each_check() {
    let dir = common::root().join("reports/en15302_e1");
    // Links first: the page's own link check sees a removed file.
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    assert!(local_links(&html).contains(&"profiles.svg".to_string()));
    let Some(browser) = browser() else { return };
    let found = open(&browser, &dir, "broken", |copy| {
        std::fs::remove_file(copy.join("profiles.svg")).unwrap();
        let page = copy.join("index.html");
        let html = std::fs::read_to_string(&page).unwrap();
        let broken = html.replacen(
            "<body>",
            "<body>\n<div style=\"width:2000px\">too wide</div>\n<script>console.error('on purpose')</script>",
            1,
        );
        std::fs::write(&page, broken).unwrap();
    });
    let has = |text: &str| found.problems.iter().any(|p| p.contains(text));
    assert!(has("image not shown: profiles.svg"), "{found:?}");
    assert!(has("failed to load profiles.svg"), "{found:?}");
    assert!(has("console.error: on purpose"), "{found:?}");
    assert!(has("horizontal overflow"), "{found:?}");
    assert_eq!(found.images, html.matches("<img ").count() - 1);
}
