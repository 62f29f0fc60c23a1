//! The project's errata (`docs/errata.md`) as the report's last section, so
//! that the report stays self-contained and every verdict that names an
//! erratum links to its row.
//!
//! `docs/errata.md` is a plain document of headings, paragraphs and pipe
//! tables; the few rules it uses are rendered here by hand (a Markdown crate
//! would be a dependency for ~60 lines of known input). Its tables' first
//! column, "Where", is the key a verdict cites (`docs/errata.md (5): …`).

use std::fmt::Write as _;

use super::markup::esc;

/// The errata, compiled in.
const ERRATA_MD: &str = include_str!("../../../docs/errata.md");

/// The text that names the errata in verdicts and evidence.
const CITE: &str = "docs/errata.md";

/// The anchor of the row whose "Where" cell is `place`.
fn anchor(place: &str) -> String {
    let slug: String = place
        .chars()
        .map(|c| if c.is_alphanumeric() { c } else { '-' })
        .collect();
    let slug = slug
        .split('-')
        .filter(|p| !p.is_empty())
        .collect::<Vec<_>>()
        .join("-");
    format!("erratum-{slug}")
}

/// The "Where" cells of every table row of the errata, longest first (so
/// that `(66), (67), (68)` is matched before `(66)`).
fn places() -> Vec<&'static str> {
    let mut places: Vec<&str> = ERRATA_MD
        .lines()
        .filter(|l| !is_separator(l))
        .filter_map(|l| l.strip_prefix("| "))
        .filter_map(|l| l.split(" | ").next())
        .map(str::trim)
        .filter(|p| *p != "Where")
        .collect();
    places.sort_by_key(|p| std::cmp::Reverse(p.len()));
    places
}

/// `text` (already HTML-escaped) with each mention of `docs/errata.md`
/// turned into a link: "erratum" to the row it names when the words after it
/// start with a row's "Where" (`docs/errata.md (5): …`), else "errata" to the
/// section.
pub(super) fn link_citations(escaped: &str) -> String {
    let places = places();
    let mut out = String::with_capacity(escaped.len());
    let mut rest = escaped;
    while let Some(i) = rest.find(CITE) {
        out.push_str(&rest[..i]);
        let after = &rest[i + CITE.len()..];
        let tail = after.trim_start_matches([',', ' ']);
        // The link says what it leads to: the erratum of the row it names,
        // or the errata section; the file's path is no text for a reader.
        let (target, text) = places
            .iter()
            .find(|p| tail.starts_with(&esc(p)))
            .map_or_else(
                || ("errata".to_string(), "errata"),
                |p| (anchor(p), "erratum"),
            );
        let _ = write!(out, "<a href=\"#{target}\">{text}</a>");
        rest = after;
    }
    out.push_str(rest);
    out
}

/// Inline markup of the errata: the report's prose ([`crate::markup::prose`]).
fn inline(text: &str) -> String {
    crate::markup::prose(text)
}

/// Whether `line` is a pipe table's separator row (`|---|:--:|`): only
/// pipes, dashes, colons and spaces. Its cells are not split by ` | `, so it
/// is recognised as a whole line.
fn is_separator(line: &str) -> bool {
    let line = line.trim();
    line.starts_with('|')
        && line.contains('-')
        && line.chars().all(|c| matches!(c, '|' | '-' | ':' | ' '))
}

/// The cells of a pipe-table row.
fn cells(line: &str) -> Vec<&str> {
    line.trim()
        .trim_start_matches('|')
        .trim_end_matches('|')
        .split(" | ")
        .map(str::trim)
        .collect()
}

/// The errata section of `report.html`.
pub(super) fn errata_section(h: &mut String) {
    h.push_str(
        "<section id=\"errata\">\n<details class=\"fold\"><summary><h2>Errata of the note</h2></summary>\n",
    );
    let _ = writeln!(
        h,
        "<p class=\"source\">The project's list of the note's errata, as compiled into this program.</p>"
    );
    let mut paragraph: Vec<&str> = Vec::new();
    let mut in_table = false;
    // The header of the table being written: each cell's label on a phone.
    let mut header: Vec<String> = Vec::new();
    let flush = |h: &mut String, paragraph: &mut Vec<&str>| {
        if !paragraph.is_empty() {
            let _ = writeln!(h, "<p>{}</p>", inline(&paragraph.join(" ")));
            paragraph.clear();
        }
    };
    for line in ERRATA_MD.lines() {
        let trimmed = line.trim();
        if let Some(title) = trimmed.strip_prefix("## ") {
            flush(h, &mut paragraph);
            let _ = writeln!(h, "<h3>{}</h3>", inline(title));
        } else if trimmed.starts_with("# ") {
            // The document's own title: the section heading replaces it.
        } else if trimmed.starts_with('|') {
            flush(h, &mut paragraph);
            let row = cells(trimmed);
            if !in_table {
                h.push_str("<div class=\"table-wrap\"><table class=\"parting errata\"><thead><tr>");
                for c in &row {
                    let _ = write!(h, "<th scope=\"col\">{}</th>", inline(c));
                }
                header = row.iter().map(|c| esc(&c.replace('`', ""))).collect();
                h.push_str("</tr></thead><tbody>\n");
                in_table = true;
            } else if is_separator(trimmed) {
                // The header/body separator: no row of its own.
            } else {
                let _ = write!(h, "<tr id=\"{}\">", anchor(row[0]));
                for (k, c) in row.iter().enumerate() {
                    let label = header.get(k).map_or("", String::as_str);
                    let _ = write!(h, "<td data-label=\"{label}\">{}</td>", inline(c));
                }
                h.push_str("</tr>\n");
            }
        } else {
            if in_table {
                h.push_str("</tbody></table></div>\n");
                in_table = false;
            }
            if trimmed.is_empty() {
                flush(h, &mut paragraph);
            } else {
                paragraph.push(trimmed);
            }
        }
    }
    if in_table {
        h.push_str("</tbody></table></div>\n");
    }
    flush(h, &mut paragraph);
    h.push_str("</details>\n</section>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_citation_links_to_the_row_it_names() {
        let text = esc("holds after correction (docs/errata.md (5): dL_C/dt = d(3mrv/2)/dt)");
        let html = link_citations(&text);
        assert!(
            html.contains("<a href=\"#erratum-5\">erratum</a> (5)"),
            "{html}"
        );
        assert!(!html.contains("docs/"), "a path as link text: {html}");
        let fn4 = link_citations(&esc("docs/errata.md fn. 4: 7bK/6, not 7bK/3"));
        assert!(fn4.contains("href=\"#erratum-fn-4\""), "{fn4}");
        let general = link_citations("see docs/errata.md for all");
        assert!(
            general.contains("<a href=\"#errata\">errata</a>"),
            "{general}"
        );
    }

    #[test]
    fn every_row_of_the_errata_gets_an_anchor_a_citation_can_reach() {
        let mut h = String::new();
        errata_section(&mut h);
        for place in places() {
            assert!(
                h.contains(&format!("<tr id=\"{}\">", anchor(place))),
                "no row for {place}"
            );
        }
        assert!(places().len() >= 20, "the errata tables were not found");
        assert_eq!(h.matches("<table").count(), h.matches("</table>").count());
    }

    #[test]
    fn no_row_is_a_separator_and_every_row_id_is_non_empty_and_unique() {
        let mut h = String::new();
        errata_section(&mut h);
        let ids: Vec<&str> = h
            .split("<tr id=\"")
            .skip(1)
            .filter_map(|s| s.split('"').next())
            .collect();
        assert_eq!(
            ids.len(),
            places().len(),
            "one row per table row of the errata"
        );
        let mut seen = std::collections::HashSet::new();
        for id in &ids {
            assert!(id.len() > "erratum-".len(), "empty id {id:?}");
            assert!(seen.insert(*id), "id {id} twice");
        }
        for cell in h.split("<td>").skip(1) {
            let text = cell.split("</td>").next().unwrap_or_default();
            assert!(
                !text.is_empty() && !text.chars().all(|c| matches!(c, '-' | '|' | ':' | ' ')),
                "a separator or empty cell in the errata: {text:?}"
            );
        }
        assert!(is_separator("|---|:--:| --- |"));
        assert!(!is_separator("| fn. 3 | a − b |"));
    }
}
