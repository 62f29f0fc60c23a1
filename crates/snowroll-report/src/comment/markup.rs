//! Text into typst markup: escaping, and the errata's plain-text
//! notation (`r_k`, `m_{k+1}`, `r0`, `x^(10/3)`) set as sub- and
//! superscripts, so that no ASCII stand-in for a subscript reaches the page.

/// `text` as typst markup that prints exactly `text`: every ASCII
/// punctuation character that markup could read as syntax is escaped
/// (`\` followed by any character prints that character).
pub(super) fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + text.len() / 8);
    for c in text.chars() {
        if c.is_ascii_punctuation() && !matches!(c, ',' | ';' | ':' | '!' | '?' | '\'' | '"') {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// A character of a symbol's name in the errata's notation: a letter, a
/// prime, or a combining accent (θ̇, τ̃).
fn symbol_char(c: char) -> bool {
    c.is_alphabetic() || matches!(c, '′' | '\u{0300}'..='\u{036f}')
}

/// Plain text in the errata's notation as typst markup: `base_x`,
/// `base_{…}` and `base_n,end` get their subscript typeset; a lower-case
/// Latin or Greek letter followed by ASCII digits (`r0`, `m1`, `br0`) gets
/// the digits as a subscript; `^(…)` is a superscript; backquoted
/// spans lose their quotes; everything else is escaped.
pub(super) fn notation(text: &str) -> String {
    let chars: Vec<char> = text.chars().filter(|&c| c != '`').collect();
    let mut out = String::with_capacity(text.len() * 2);
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let after_symbol = i > 0 && symbol_char(chars[i - 1]);
        if c == '_' && after_symbol {
            let (sub, next) = subscript(&chars, i + 1);
            out.push_str(&format!("#sub[{}]", esc(&sub)));
            i = next;
        } else if c == '^' && chars.get(i + 1) == Some(&'(') {
            let end = chars[i + 2..]
                .iter()
                .position(|&c| c == ')')
                .map_or(chars.len(), |p| i + 2 + p);
            let sup: String = chars[i + 2..end].iter().collect();
            out.push_str(&format!("#super[{}]", esc(&sup)));
            i = (end + 1).min(chars.len());
        } else if c.is_ascii_digit() && i > 0 && is_lower_letter(chars[i - 1]) {
            let end = chars[i..]
                .iter()
                .position(|c| !c.is_ascii_digit())
                .map_or(chars.len(), |p| i + p);
            let digits: String = chars[i..end].iter().collect();
            out.push_str(&format!("#sub[{digits}]"));
            i = end;
        } else {
            out.push_str(&esc(&c.to_string()));
            i += 1;
        }
    }
    out
}

/// A lower-case Latin or Greek letter (the symbols that carry a digit
/// subscript in the errata: r0, m0, r1).
fn is_lower_letter(c: char) -> bool {
    c.is_ascii_lowercase() || ('α'..='ω').contains(&c)
}

/// The subscript starting at `chars[start]` and the index after it:
/// `{…}` up to its closing brace, else a run of letters and digits,
/// continued by `,word` (`n,end`).
fn subscript(chars: &[char], start: usize) -> (String, usize) {
    if chars.get(start) == Some(&'{') {
        let end = chars[start..]
            .iter()
            .position(|&c| c == '}')
            .map_or(chars.len(), |p| start + p);
        return (
            chars[start + 1..end].iter().collect(),
            (end + 1).min(chars.len()),
        );
    }
    let run = |from: usize| {
        chars[from..]
            .iter()
            .position(|c| !c.is_alphanumeric())
            .map_or(chars.len(), |p| from + p)
    };
    let mut end = run(start);
    if chars.get(end) == Some(&',') && chars.get(end + 1).is_some_and(|c| c.is_alphabetic()) {
        end = run(end + 1);
    }
    (chars[start..end].iter().collect(), end)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escaping_prints_the_text() {
        assert_eq!(
            esc("a_b #c $d [e] -- 1. f/g"),
            r"a\_b \#c \$d \[e\] \-\- 1\. f\/g"
        );
        assert_eq!(esc("x, y; z: \"q\""), "x, y; z: \"q\"");
    }

    #[test]
    fn errata_subscripts_are_typeset() {
        assert_eq!(notation("r_k"), "r#sub[k]");
        assert_eq!(notation("m_{k+1}²"), r"m#sub[k\+1]²");
        assert_eq!(notation("V_n,end = x"), "V#sub[n,end] \\= x");
        assert_eq!(notation("br0 and 10⁵"), "br#sub[0] and 10⁵");
        assert_eq!(notation("x^(10/3)]"), r"x#super[10\/3]\]");
        assert_eq!(notation("τ̃_P, `r0`"), "τ̃#sub[P], r#sub[0]");
        assert_eq!(notation("fn. 4 (5)"), r"fn\. 4 \(5\)");
    }
}
