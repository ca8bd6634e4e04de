//! A static, self-contained HTML report page.
//!
//! [`render_html`] returns one document with inline CSS, no JavaScript and no external
//! resources: figures and tables are referenced by relative file names, so the page works when
//! the output folder is copied or opened from disk. All text is HTML-escaped; file names are
//! also percent-encoded, so a name can never break out of its attribute or become a
//! `javascript:` link.

use std::fmt::Write as _;

/// One figure on the page: an SVG shown inline as an image, with a link to its PNG.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct FigureEntry {
    /// Short name, used as heading and anchor (`fig2`).
    pub name: String,
    /// Caption text under the figure.
    pub caption: String,
    /// Relative file name of the SVG (`fig2.svg`).
    pub svg: String,
    /// Relative file name of the PNG (`fig2.png`).
    pub png: String,
}

/// One CSV table listed on the page.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct TableEntry {
    /// Short name (`rigid contact points`).
    pub name: String,
    /// Relative file name (`rigid.csv`).
    pub file: String,
    /// What the table holds.
    pub description: String,
}

/// A table of values shown on the page (escaped text cells), under its own heading.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct DataTable {
    /// Heading above the table.
    pub title: String,
    /// Column headings.
    pub header: Vec<String>,
    /// Rows of cells, as many as the header has.
    pub rows: Vec<Vec<String>>,
}

/// The content of a report page.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ReportPage {
    /// Page title and top heading.
    pub title: String,
    /// The key results, shown first as `(name, value, unit, definition)` rows.
    pub key_results: Vec<[String; 4]>,
    /// Summary paragraphs.
    pub summary: Vec<String>,
    /// Run parameters as `(name, value)` rows, e.g. `("gauge_mm", "1435")`.
    pub parameters: Vec<(String, String)>,
    /// Provenance as `(item, value)` rows: program version, scene file hash, profile sources.
    pub provenance: Vec<(String, String)>,
    /// Figures in order.
    pub figures: Vec<FigureEntry>,
    /// CSV tables in order.
    pub tables: Vec<TableEntry>,
    /// Tables of values shown on the page, after the summary (e.g. the pairs of a fleet over
    /// a limit).
    pub data_tables: Vec<DataTable>,
    /// Closing notes, e.g. points that did not converge.
    pub notes: Vec<String>,
}

const STYLE: &str = "\
body{font-family:'DejaVu Sans',Verdana,sans-serif;max-width:70rem;margin:2rem auto;\
padding:0 1rem;color:#222;line-height:1.45}\
h1{font-size:1.7rem;margin-bottom:.5rem}h2{font-size:1.3rem;margin-top:2rem;\
border-bottom:1px solid #ccc;padding-bottom:.2rem}\
table{border-collapse:collapse;margin:.5rem 0}\
th,td{border:1px solid #ccc;padding:.25rem .6rem;text-align:left;vertical-align:top}\
th{background:#f2f2f2}td.v{font-family:'DejaVu Sans Mono',monospace}\
figure{margin:1.5rem 0}figure img{max-width:100%;height:auto;border:1px solid #ddd}\
figcaption{margin-top:.4rem;color:#444}\
";

/// Renders `page` as a complete HTML5 document.
///
/// Sections without content (no parameters, no tables, ...) are left out.
///
/// # Examples
///
/// ```
/// use wheelrail_report::html::{render_html, FigureEntry, ReportPage};
///
/// let page = ReportPage {
///     title: "S1002 on UIC60 <1:40>".into(),
///     figures: vec![FigureEntry {
///         name: "fig2".into(),
///         caption: "Contact angle & radius".into(),
///         svg: "fig2.svg".into(),
///         png: "fig2.png".into(),
///     }],
///     ..ReportPage::default()
/// };
/// let html = render_html(&page);
/// assert!(html.contains("<title>S1002 on UIC60 &lt;1:40&gt;</title>"));
/// assert!(html.contains(r#"<img src="fig2.svg""#));
/// assert!(html.contains(r#"<a href="fig2.png">"#));
/// assert!(html.contains("Contact angle &amp; radius"));
/// ```
pub fn render_html(page: &ReportPage) -> String {
    let mut out = String::new();
    let title = escape_html(&page.title);
    // Writing into a String cannot fail.
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n<h1>{title}</h1>\n"
    );
    if !page.key_results.is_empty() {
        out.push_str(
            "<h2 id=\"key-results\">Key results</h2>\n<table>\n<tr><th>Parameter</th>\
             <th>Value</th><th>Unit</th><th>Definition</th></tr>\n",
        );
        for [name, value, unit, definition] in &page.key_results {
            let _ = writeln!(
                out,
                "<tr><td>{}</td><td class=\"v\">{}</td><td>{}</td><td>{}</td></tr>",
                escape_html(name),
                escape_html(value),
                escape_html(unit),
                escape_html(definition)
            );
        }
        out.push_str("</table>\n");
    }
    for paragraph in &page.summary {
        let _ = writeln!(out, "<p>{}</p>", escape_html(paragraph));
    }
    for t in &page.data_tables {
        data_table(&mut out, t);
    }
    if !page.parameters.is_empty() {
        out.push_str("<h2 id=\"parameters\">Parameters</h2>\n");
        key_value_table(&mut out, ("Parameter", "Value"), &page.parameters);
    }
    figures(&mut out, &page.figures);
    if !page.tables.is_empty() {
        out.push_str(
            "<h2 id=\"tables\">Tables</h2>\n<table>\n<tr><th>Table</th><th>File</th>\
             <th>Contents</th></tr>\n",
        );
        for t in &page.tables {
            let _ = writeln!(
                out,
                "<tr><td>{}</td><td><a href=\"{}\">{}</a></td><td>{}</td></tr>",
                escape_html(&t.name),
                escape_html(&encode_path(&t.file)),
                escape_html(&t.file),
                escape_html(&t.description)
            );
        }
        out.push_str("</table>\n");
    }
    if !page.notes.is_empty() {
        out.push_str("<h2 id=\"notes\">Notes</h2>\n<ul>\n");
        for note in &page.notes {
            let _ = writeln!(out, "<li>{}</li>", escape_html(note));
        }
        out.push_str("</ul>\n");
    }
    if !page.provenance.is_empty() {
        out.push_str("<h2 id=\"provenance\">Provenance</h2>\n");
        key_value_table(&mut out, ("Item", "Value"), &page.provenance);
    }
    out.push_str("</body>\n</html>\n");
    out
}

/// A table of text cells under its own heading ("none" when it has no rows).
fn data_table(out: &mut String, t: &DataTable) {
    let _ = writeln!(
        out,
        "<h2 id=\"{}\">{}</h2>\n<table>\n<tr>{}</tr>",
        escape_html(&anchor(&t.title)),
        escape_html(&t.title),
        t.header
            .iter()
            .map(|h| format!("<th>{}</th>", escape_html(h)))
            .collect::<String>()
    );
    if t.rows.is_empty() {
        let _ = writeln!(
            out,
            "<tr><td colspan=\"{}\">none</td></tr>",
            t.header.len().max(1)
        );
    }
    for row in &t.rows {
        let _ = writeln!(
            out,
            "<tr>{}</tr>",
            row.iter()
                .map(|c| format!("<td class=\"v\">{}</td>", escape_html(c)))
                .collect::<String>()
        );
    }
    out.push_str("</table>\n");
}

/// The figures, each as its SVG with a caption and links to both formats.
fn figures(out: &mut String, figures: &[FigureEntry]) {
    if !figures.is_empty() {
        out.push_str("<h2 id=\"figures\">Figures</h2>\n");
        for fig in figures {
            let _ = write!(
                out,
                "<figure id=\"{id}\">\n<img src=\"{svg}\" alt=\"{alt}\">\n\
                 <figcaption><strong>{name}.</strong> {caption} \
                 (<a href=\"{png}\">PNG</a>, <a href=\"{svg}\">SVG</a>)</figcaption>\n</figure>\n",
                id = escape_html(&anchor(&fig.name)),
                svg = escape_html(&encode_path(&fig.svg)),
                png = escape_html(&encode_path(&fig.png)),
                alt = escape_html(&fig.caption),
                name = escape_html(&fig.name),
                caption = escape_html(&fig.caption),
            );
        }
    }
}

fn key_value_table(out: &mut String, (key, value): (&str, &str), rows: &[(String, String)]) {
    let _ = writeln!(out, "<table>\n<tr><th>{key}</th><th>{value}</th></tr>");
    for (k, v) in rows {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td class=\"v\">{}</td></tr>",
            escape_html(k),
            escape_html(v)
        );
    }
    out.push_str("</table>\n");
}

/// Escapes `&`, `<`, `>`, `"` and `'` so that `text` is safe in element content and in quoted
/// attribute values.
fn escape_html(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    // The five are ASCII: found as bytes, they end runs at character boundaries, and each
    // run between them is copied whole.
    while let Some(i) = rest
        .bytes()
        .position(|b| matches!(b, b'&' | b'<' | b'>' | b'"' | b'\''))
    {
        out.push_str(&rest[..i]);
        out.push_str(match rest.as_bytes()[i] {
            b'&' => "&amp;",
            b'<' => "&lt;",
            b'>' => "&gt;",
            b'"' => "&quot;",
            _ => "&#39;",
        });
        rest = &rest[i + 1..];
    }
    out.push_str(rest);
    out
}

/// Percent-encodes a relative file path for `href`/`src`: every byte except ASCII letters,
/// digits, `-._~` and `/` is encoded, so spaces, `#`, `?` and `:` (no `javascript:` scheme)
/// stay part of the file name.
fn encode_path(path: &str) -> String {
    let mut out = String::with_capacity(path.len());
    for b in path.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            out.push(char::from(b));
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

/// An `id` attribute value from a name: ASCII letters and digits kept, runs of anything else
/// turned into `-`.
fn anchor(name: &str) -> String {
    let mut out = String::new();
    for c in name.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') {
            out.push('-');
        }
    }
    let trimmed = out.trim_matches('-');
    if trimmed.is_empty() {
        "figure".to_owned()
    } else {
        trimmed.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_percent_encoded() {
        assert_eq!(encode_path("fig 2#a?.svg"), "fig%202%23a%3F.svg");
        assert_eq!(
            encode_path("javascript:alert(1)"),
            "javascript%3Aalert%281%29"
        );
        assert_eq!(encode_path("sub/dir/é.png"), "sub/dir/%C3%A9.png");
    }

    #[test]
    fn markup_characters_are_escaped() {
        assert_eq!(
            escape_html(r#"<a href="x">'&'</a>"#),
            "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;"
        );
        // Characters of several bytes next to the escaped ones, at both ends and alone.
        assert_eq!(escape_html("Δr<γ>&µ"), "Δr&lt;γ&gt;&amp;µ");
        assert_eq!(escape_html("&é"), "&amp;é");
        assert_eq!(escape_html("é\""), "é&quot;");
        assert_eq!(escape_html("Δ"), "Δ");
        assert_eq!(escape_html(""), "");
    }

    #[test]
    fn anchors_are_plain() {
        assert_eq!(anchor("Fig. 2 (a)"), "fig-2-a");
        assert_eq!(anchor("<>"), "figure");
    }

    #[test]
    fn empty_sections_are_omitted() {
        let html = render_html(&ReportPage {
            title: "t".into(),
            ..ReportPage::default()
        });
        for id in ["parameters", "figures", "tables", "notes", "provenance"] {
            assert!(!html.contains(&format!("id=\"{id}\"")), "{id}");
        }
    }
}
