//! Text into HTML and Markdown: escaping, and prose in the report's one
//! notation.

use crate::notation;

/// Prose of the report, escaped: `code` spans as `<code>` elements (no
/// backtick reaches the page), the rest in the report's one notation
/// ([`notation::prettify_html`]).
pub(crate) fn prose(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 16);
    for (i, piece) in s.split('`').enumerate() {
        if i % 2 == 1 {
            out.push_str("<code>");
            out.push_str(&esc(piece));
            out.push_str("</code>");
        } else {
            out.push_str(&notation::prettify_html(piece, esc));
        }
    }
    out
}

/// Markdown prose outside a table: the notation of the Markdown report's
/// table cells, `<sub>`/`<sup>` for a group with no Unicode form
/// (`C<sub>d</sub>`, `α<sub>K</sub>`), so that no ASCII index stands beside
/// the set ones; `&`, `<`, `>` escaped, backticks kept (Markdown's code).
pub(crate) fn markdown_prose(s: &str) -> String {
    notation::prettify_html(s, |t| {
        t.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prose_sets_code_spans_and_notation() {
        assert_eq!(
            prose("run `snowroll models` for I_C < 1e-3"),
            "run <code>snowroll models</code> for I<sub>C</sub> &lt; 10⁻³"
        );
    }
}
