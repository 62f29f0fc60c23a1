//! Issue 36, item 4: no source text anywhere a reader looks. The checks
//! here are applied to the report (HTML as shown, its Markdown, the text of
//! its figures), to `--help` of every command, to the explorer page and the
//! strings its scripts put on it, and to error messages.
//!
//! Source text is: a Rust path (`report::CLAIMS`; an IPv6 address such as
//! `::1` is not one), a test's name (four or more words joined by `_`), a
//! path of the code (`crates/…`, `tests/claims.rs`), an ASCII sub- or
//! superscript (`x_n`, `b^2`, `r_{k}`) in a text that sets others (`rₖ`),
//! and a repository path as the text of a link (a link says what it leads
//! to).

/// Characters that are Unicode sub- or superscripts (a text with one of
/// them "sets" its indices, so an ASCII one beside it is a slip).
fn is_set_index(c: char) -> bool {
    matches!(c, '⁰' | '¹' | '²' | '³' | '⁴'..='⁹' | '⁺' | '⁻' | 'ⁿ' | '₀'..='₎' | 'ₐ'..='ₜ' | 'ᵢ' | 'ⱼ' | 'ᵣ' | 'ᵤ' | 'ᵥ')
}

/// Words that make an identifier a sentence, as a test's name is
/// (`every_row_names_a_claim`); a column such as `a_over_g_sin_alpha` or
/// `v_start_m_s` is a key a user reads, not a test.
const SENTENCE: [&str; 16] = [
    "the", "of", "is", "are", "every", "each", "and", "or", "not", "no", "names", "gives", "has",
    "when", "from", "that",
];

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '.'
}

/// The source text in `text` (what was found, with the words around it);
/// empty when there is none.
pub fn findings(text: &str) -> Vec<String> {
    findings_of(text, true)
}

/// [`findings`] with (`indices`) or without the check of ASCII indices.
pub fn findings_of(text: &str, indices: bool) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let around = |i: usize| -> String {
        chars[i.saturating_sub(40)..(i + 40).min(chars.len())]
            .iter()
            .collect::<String>()
            .replace('\n', " ")
    };
    let mut found = Vec::new();
    // Tokens: the runs of characters between spaces and brackets.
    let mut start = 0;
    for (i, c) in chars.iter().chain(std::iter::once(&' ')).enumerate() {
        if !(c.is_whitespace() || matches!(c, '(' | ')' | '"' | '\'' | '`' | ',' | ';' | '<' | '>'))
        {
            continue;
        }
        let token: String = chars[start..i].iter().collect();
        let token = token.trim_end_matches(['.', ':']);
        let ipv6 = token
            .chars()
            .all(|c| c.is_ascii_hexdigit() || matches!(c, ':' | '[' | ']' | '.' | '/'));
        let words = token.split('_').collect::<Vec<_>>();
        let test_name = words.len() >= 4
            && words.iter().all(|w| {
                !w.is_empty()
                    && w.chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit())
            })
            && words.iter().any(|w| SENTENCE.contains(w));
        let code_path = ["crates/", "src/", "tests/"]
            .iter()
            .any(|p| token.starts_with(p) || token.contains(&format!("/{p}")))
            || (token.ends_with(".rs") && token.len() > 3);
        if token.contains("::") && !ipv6 {
            found.push(format!("a Rust path {token:?}: …{}…", around(start)));
        } else if test_name {
            found.push(format!("a test's name {token:?}: …{}…", around(start)));
        } else if code_path {
            found.push(format!("a path of the code {token:?}: …{}…", around(start)));
        }
        start = i + 1;
    }
    // ASCII indices, where the text sets others.
    if indices && chars.iter().any(|&c| is_set_index(c)) {
        for i in 0..chars.len().saturating_sub(1) {
            let (c, next) = (chars[i], chars[i + 1]);
            let group = matches!(c, '^' | '_') && matches!(next, '(' | '{');
            let power = c == '^' && (next.is_ascii_digit() || matches!(next, '-' | '−'));
            // `x_n`, `ρ_a`, `2πr_k`: a one-letter name (starting a word or
            // after a number or a Greek letter) and a short subscript, as
            // the report's notation sets them; `alpha_deg`, `mass_kg` and
            // `a_over_g` are names a user types, not indices.
            let index = c == '_' && i >= 1 && chars[i - 1].is_alphabetic() && {
                let alone = i == 1 || {
                    let p = chars[i - 2];
                    !is_word(p) || p.is_ascii_digit() || (p.is_alphabetic() && !p.is_ascii())
                };
                let len = chars[i + 1..]
                    .iter()
                    .take_while(|c| c.is_ascii_alphanumeric())
                    .count();
                let ends = chars
                    .get(i + 1 + len)
                    .is_none_or(|&c| !(c.is_alphanumeric() || c == '_'));
                alone && (1..=8).contains(&len) && ends
            };
            if group || power || index {
                found.push(format!("an ASCII index beside set ones: …{}…", around(i)));
            }
        }
    }
    found
}

/// The text of every link (`<a …>text</a>`) of `html`, tags taken out.
pub fn link_texts(html: &str) -> Vec<String> {
    html.split("<a ")
        .skip(1)
        .filter_map(|s| s.split_once('>').map(|(_, rest)| rest))
        .filter_map(|s| s.split_once("</a>").map(|(text, _)| strip_tags(text)))
        .collect()
}

/// The text of every Markdown link (`[text](target)`) of `md`.
pub fn markdown_link_texts(md: &str) -> Vec<String> {
    md.match_indices("](")
        .filter_map(|(i, _)| md[..i].rfind('[').map(|j| md[j + 1..i].to_string()))
        .collect()
}

/// Whether a link's text is a repository path (`docs/errata.md`,
/// `data/claims.csv`, `src/x.rs`) rather than words saying where it leads.
pub fn is_path(text: &str) -> bool {
    let t = text.trim().trim_matches('`');
    let pathlike = t.contains('/')
        && !t.contains(' ')
        && t.chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '/' | '.' | '-' | '_'));
    pathlike || t.ends_with(".md") || t.ends_with(".rs")
}

/// `html` without its tags.
pub fn strip_tags(html: &str) -> String {
    let mut out = String::with_capacity(html.len());
    let mut in_tag = false;
    for c in html.chars() {
        match c {
            '<' => in_tag = true,
            '>' if in_tag => in_tag = false,
            _ if !in_tag => out.push(c),
            _ => {}
        }
    }
    out
}

/// `html` without its `<script>` and `<style>` elements (whatever else it
/// holds is shown, `<code>` included).
pub fn without_scripts(html: &str) -> String {
    let mut text = html.to_string();
    for element in ["script", "style"] {
        let (open, close) = (format!("<{element}"), format!("</{element}>"));
        while let Some(start) = text.find(&open) {
            let end = text[start..]
                .find(&close)
                .map_or(text.len(), |e| start + e + close.len());
            text.replace_range(start..end, " ");
        }
    }
    text
}

/// Every finding of [`findings`] in `text`, and every link of `links` whose
/// text is a path, named by `what`.
pub fn assert_clean(what: &str, text: &str, links: &[String]) {
    assert_clean_of(what, text, links, true);
}

/// [`assert_clean`] with (`indices`) or without the check of ASCII indices.
pub fn assert_clean_of(what: &str, text: &str, links: &[String], indices: bool) {
    let mut found = findings_of(text, indices);
    found.extend(
        links
            .iter()
            .filter(|l| is_path(l))
            .map(|l| format!("a path as a link's text: {l:?}")),
    );
    assert!(
        found.is_empty(),
        "source text in {what}:\n{}",
        found.join("\n")
    );
}

#[test]
fn each_kind_of_source_text_is_found_and_prose_is_not() {
    for bad in [
        "the table report::CLAIMS",
        "a test (every_errata_row_names_a_claim in it)",
        "see tests/claims.rs",
        "in crates/snowroll/src/losses.rs",
        "rₖ beside 2πr_k",
        "rₖ beside ρlb x_n/2",
        "r² and tan α_K",
        "r² and b^2",
        "r² and r_{k+1}",
    ] {
        assert!(!findings(bad).is_empty(), "{bad:?} passed");
    }
    for good in [
        "listen on ::1 or [::1]:8080, or ::",
        "rₖ = r0 + kb, alpha_deg = 30, snow_depth = 0.01, a_over_g_sin_alpha, v_start_m_s",
        "without set indices x_n may stay",
        "the ratio 2/3 and the page docs at 10:30",
    ] {
        assert!(findings(good).is_empty(), "{good:?}: {:?}", findings(good));
    }
    assert!(is_path("docs/errata.md") && is_path("data/claims.csv") && is_path("errata.md"));
    assert!(!is_path("erratum") && !is_path("data (CSV)") && !is_path("a/G = 1/6 of the ball"));
    assert_eq!(
        link_texts("<a href=\"#e\">docs/errata.md</a> and <a href=x><code>id</code></a>"),
        ["docs/errata.md", "id"]
    );
    assert_eq!(
        markdown_link_texts("[Figure 1](#f) and [x.md](x.md)"),
        ["Figure 1", "x.md"]
    );
}

/// The string literals of JavaScript `src` ('…', "…" and `…` without their
/// `${…}` parts): what a script can put on the page.
fn js_strings(src: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut chars = src.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '/' if chars.peek() == Some(&'/') => {
                // A comment to the end of the line.
                for d in chars.by_ref() {
                    if d == '\n' {
                        break;
                    }
                }
            }
            '\'' | '"' | '`' => {
                let mut s = String::new();
                let mut depth = 0;
                while let Some(d) = chars.next() {
                    match d {
                        '\\' => {
                            chars.next();
                        }
                        '$' if c == '`' && chars.peek() == Some(&'{') => {
                            depth += 1;
                            s.push(' ');
                        }
                        '}' if depth > 0 => depth -= 1,
                        _ if depth > 0 => {}
                        _ if d == c => break,
                        _ => s.push(d),
                    }
                }
                out.push(s);
            }
            _ => {}
        }
    }
    out
}

/// The explorer page (`serve`'s, built into the program): its visible text,
/// its links, and every string its scripts hold.
#[test]
fn the_explorer_page_shows_no_source_text() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/serve/assets");
    let page = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let shown = without_scripts(&page);
    assert_clean(
        "the explorer page",
        &strip_tags(&shown),
        &link_texts(&shown),
    );
    let mut scripts = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "js") {
            scripts += 1;
            let src = std::fs::read_to_string(&path).unwrap();
            for s in js_strings(&src) {
                assert_clean(&format!("a string of {}", path.display()), &s, &[]);
            }
        }
    }
    assert!(scripts >= 3, "the explorer's scripts were not found");
}

/// Error messages of the program for bad input: one line, in words.
#[test]
fn error_messages_show_no_source_text() {
    let cases: &[&[&str]] = &[
        &["simulate"],
        &["simulate", "--model", "eq99"],
        &["simulate", "--model", "eq4", "--snow-depth", "-1"],
        &["simulate", "--model", "eq4", "--alpha-deg", "90"],
        &["simulate", "--model", "eq4", "--t-end", "nan"],
        &["turns", "--turns", "0"],
        &["turns", "--collision", "bogus"],
        &["sweep", "--alpha-deg", "1:2:0"],
        &["merge"],
        &["fit"],
        &["fit", "/nonexistent/track.csv"],
        &["fit", "/dev/null"],
        &["fit", "/dev/null", "--free", "bogus"],
        &["paper", "--turns", "3"],
        &[
            "simulate",
            "--model",
            "eq4",
            "--config",
            "/nonexistent/x.toml",
        ],
        &["bogus"],
    ];
    for args in cases {
        let out = assert_cmd::cargo::cargo_bin_cmd!("snowroll")
            .args(*args)
            .output()
            .unwrap();
        assert!(!out.status.success(), "{args:?} succeeded");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(!err.trim().is_empty(), "{args:?}: no message");
        assert_clean(&format!("the error of {args:?}"), &err, &[]);
    }
}
