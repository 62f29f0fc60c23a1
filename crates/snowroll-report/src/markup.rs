//! Text into HTML: escaping, and prose in the report's one notation.

use crate::notation;

/// Prose of the report, in its one notation ([`notation::prettify_html`]), escaped.
pub(crate) fn prose(s: &str) -> String {
    notation::prettify_html(s, esc)
}

/// Escapes text for HTML element content and attribute values.
pub(crate) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}
