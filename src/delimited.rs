//! Delimited text as spreadsheets export it: the field separator of a file (comma, semicolon
//! or tab) taken from its header line, and the decimal commas that go with semicolons and
//! tabs in European locales (`s_mm;F_mm` then `-12,5;3,25`).
//!
//! Every CSV reader of the crate (profiles, `wheelrail conicity`'s Δr table, a fleet's pairs
//! file) finds its separator here, so that they read the same files alike and name the
//! separator when a line does not follow its header.
//!
//! For example, the header `s_mm;F_mm` gives [`Separator::Semicolon`], with which the field
//! `-12,5` reads as `-12.5`; with [`Separator::Comma`] it stays `-12,5` (the tests below).

use std::borrow::Cow;
use std::fmt;

/// The character between the fields of a line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Separator {
    /// `,`: numbers take a decimal point.
    Comma,
    /// `;`: numbers take a decimal comma or point.
    Semicolon,
    /// A tab: numbers take a decimal comma or point.
    Tab,
}

impl Separator {
    /// The separators tried, in order.
    pub const ALL: [Separator; 3] = [Separator::Comma, Separator::Semicolon, Separator::Tab];

    /// The separator of a file whose header (its first line that is neither blank nor a
    /// comment) is `line`: the first of comma, semicolon and tab that it holds (a header
    /// names its columns, so none of them is a decimal comma); a comma when it holds none
    /// (a header of one column, which the reader refuses as such).
    pub fn of_header(line: &str) -> Separator {
        Separator::ALL
            .into_iter()
            .find(|s| line.contains(s.char()))
            .unwrap_or(Separator::Comma)
    }

    /// The separator of the header of `text`: its first line (ended by `\n`, `\r\n` or a
    /// lone `\r`) that is neither empty nor a `#` comment, after a byte-order mark; see
    /// [`Separator::of_header`].
    pub fn of_text(text: &str) -> Separator {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        Separator::of_header(
            text.split(['\n', '\r'])
                .find(|l| !l.is_empty() && !l.starts_with('#'))
                .unwrap_or(""),
        )
    }

    /// The character.
    pub fn char(self) -> char {
        match self {
            Separator::Comma => ',',
            Separator::Semicolon => ';',
            Separator::Tab => '\t',
        }
    }

    /// The byte (ASCII), for the `csv` crate.
    pub fn byte(self) -> u8 {
        self.char() as u8
    }

    /// The separator named in messages: `commas`, `semicolons`, `tabs`.
    pub fn plural(self) -> &'static str {
        match self {
            Separator::Comma => "commas",
            Separator::Semicolon => "semicolons",
            Separator::Tab => "tabs",
        }
    }

    /// The text of a number field as Rust's parser reads it: with semicolons and tabs a
    /// comma is the decimal mark (`-12,5` is -12.5); a field with more than one comma, or
    /// with a comma and a point, is left as it is (and so is not a number).
    pub fn number_text(self, field: &str) -> Cow<'_, str> {
        let decimal_comma = self != Separator::Comma
            && field.bytes().filter(|&b| b == b',').count() == 1
            && !field.contains('.');
        if decimal_comma {
            Cow::Owned(field.replacen(',', ".", 1))
        } else {
            Cow::Borrowed(field)
        }
    }

    /// Another separator than `self` that `line` holds, where a line that did not read
    /// under `self` was likely written with it: a semicolon or a tab in a file of commas, a
    /// comma or the other one in a file of semicolons or tabs. A comma counts in a file of
    /// semicolons or tabs only where it cannot be a decimal comma (the line has no
    /// `self` at all).
    pub fn other_in(self, line: &str) -> Option<Separator> {
        Separator::ALL.into_iter().find(|&s| {
            s != self
                && line.contains(s.char())
                && (s != Separator::Comma || !line.contains(self.char()))
        })
    }
}

impl fmt::Display for Separator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Separator::Comma => "','",
            Separator::Semicolon => "';'",
            Separator::Tab => "tab",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_header_decides() {
        assert_eq!(Separator::of_header("s_mm,F_mm"), Separator::Comma);
        assert_eq!(Separator::of_header("s_mm;F_mm"), Separator::Semicolon);
        assert_eq!(Separator::of_header("s_mm\tF_mm"), Separator::Tab);
        // A tab beside a comma is white space around a field.
        assert_eq!(Separator::of_header("s_mm,\tF_mm"), Separator::Comma);
        assert_eq!(Separator::of_header("s_mm"), Separator::Comma);
        assert_eq!(
            Separator::of_text("# a, b\r\n\r\ns_mm;F_mm\r\n1,5;2\r\n"),
            Separator::Semicolon
        );
    }

    #[test]
    fn decimal_commas_only_where_the_separator_allows_them() {
        for sep in [Separator::Semicolon, Separator::Tab] {
            assert_eq!(sep.number_text("3,25"), "3.25");
            assert_eq!(sep.number_text("3.25"), "3.25");
            assert_eq!(sep.number_text("-1,5e-3"), "-1.5e-3");
            // Thousands marks are not guessed at: the field stays as written.
            assert_eq!(sep.number_text("1.234,5"), "1.234,5");
            assert_eq!(sep.number_text("1,234,5"), "1,234,5");
        }
        assert_eq!(Separator::Comma.number_text("3,25"), "3,25");
    }

    #[test]
    fn another_separator_is_found_where_it_cannot_be_a_decimal_comma() {
        assert_eq!(
            Separator::Comma.other_in("1,5;2,5"),
            Some(Separator::Semicolon)
        );
        assert_eq!(Separator::Comma.other_in("1\t2"), Some(Separator::Tab));
        assert_eq!(
            Separator::Semicolon.other_in("1.5,2.5"),
            Some(Separator::Comma)
        );
        // Decimal commas in a line of semicolons are not separators.
        assert_eq!(Separator::Semicolon.other_in("1,5;2,5"), None);
        assert_eq!(Separator::Comma.other_in("1,2"), None);
    }
}
