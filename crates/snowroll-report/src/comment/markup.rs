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
    let text = cite_notes(text);
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
            // Unicode's subscript digits: the PDF's text then says r₀, as
            // the page does.
            out.extend(
                chars[i..end]
                    .iter()
                    .filter_map(|d| d.to_digit(10).and_then(|d| char::from_u32(0x2080 + d))),
            );
            i = end;
        } else {
            out.push_str(&esc(&c.to_string()));
            i += 1;
        }
    }
    out
}

/// `text` with each backquoted path of the program's notes (`` `docs/…md` ``)
/// replaced by a citation of the program, whose notes they are.
pub(super) fn cite_notes(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(open) = rest.find('`') {
        let Some(len) = rest[open + 1..].find('`') else {
            break;
        };
        let inner = &rest[open + 1..open + 1 + len];
        out.push_str(&rest[..open]);
        if inner.contains(".md") {
            out.push_str("the program's notes [4]");
        } else {
            out.push_str(inner);
        }
        rest = &rest[open + 2 + len..];
    }
    out.push_str(rest);
    out
}

/// A legend of the report's figures in the note's words: `torque-cm
/// (eq4)` becomes `torque about the centre (4)` (a model's id is replaced
/// where an equation follows it; equations are cited by their number in
/// parentheses, footnotes as `fn. 4`); a program section's citation
/// (`(§4.3)`, of the program's notes) is left out.
pub(super) fn legend(name: &str) -> String {
    const MODELS: [(&str, &str); 11] = [
        ("quasi-circular-lift", "quasi-circular + lift"),
        ("quasi-circular", "quasi-circular"),
        ("lagrangian-printed", "Lagrangian as printed"),
        ("torque-contact", "torque about the contact"),
        ("torque-cm", "torque about the centre"),
        ("energy-thin", "thin-layer energy"),
        ("turns-exact", "turn by turn, exact"),
        ("snowless", "no snow"),
        ("energy", "energy"),
        ("loney", "Loney"),
        ("turns", "turn by turn"),
    ];
    let mut out = String::with_capacity(name.len() + 16);
    let mut rest = name;
    while !rest.is_empty() {
        if let Some((id, words)) = MODELS.iter().find(|(id, _)| {
            rest.strip_prefix(id)
                .is_some_and(|after| after.starts_with(" (eq") || after.starts_with(" (fn"))
        }) {
            out.push_str(words);
            rest = &rest[id.len()..];
        } else if let Some((numbers, after)) = digit_after(rest, "(eq") {
            let cited: Vec<String> = numbers.split('+').map(|n| format!("({n})")).collect();
            out.push_str(&cited.join("+"));
            rest = after;
        } else if let Some((number, after)) = digit_after(rest, "(fn") {
            out.push_str(&format!("fn. {number}"));
            rest = after;
        } else if let Some(section) = rest.strip_prefix(" (§") {
            rest = section.find(')').map_or("", |end| &section[end + 1..]);
        } else {
            let c = rest.chars().next().unwrap_or(' ');
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out.replace(" fn. ", ", fn. ")
}

/// What follows `prefix` in `s` when a digit does: the text up to the
/// closing parenthesis, and the rest after it.
fn digit_after<'a>(s: &'a str, prefix: &str) -> Option<(&'a str, &'a str)> {
    s.strip_prefix(prefix)
        .filter(|r| r.starts_with(|c: char| c.is_ascii_digit()))
        .map(|r| {
            let end = r.find(')').unwrap_or(r.len());
            (&r[..end], &r[(end + 1).min(r.len())..])
        })
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
    fn legends_name_models_and_equations_in_words() {
        assert_eq!(
            legend("torque-cm (eq4) = loney (fn4)"),
            "torque about the centre (4) = Loney, fn. 4"
        );
        assert_eq!(
            legend("energy-thin (eq15) = quasi-circular-lift (eq32+36)"),
            "thin-layer energy (15) = quasi-circular + lift (32)+(36)"
        );
        assert_eq!(
            legend("turns (eq73), mean per turn"),
            "turn by turn (73), mean per turn"
        );
        assert_eq!(
            legend("in turn, mean over turns K/10 … K"),
            "in turn, mean over turns K/10 … K"
        );
        assert_eq!(legend("stall slope (fn. 7)"), "stall slope (fn. 7)");
        assert_eq!(
            legend("hop within the turns reached (§4.3)"),
            "hop within the turns reached"
        );
    }

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
        assert_eq!(notation("br0 and 10⁵"), "br₀ and 10⁵");
        assert_eq!(notation("x^(10/3)]"), r"x#super[10\/3]\]");
        assert_eq!(notation("τ̃_P, `r0`"), "τ̃#sub[P], r₀");
        assert_eq!(
            notation("§2 (`docs/snowball-and-losses.md` §1.3)"),
            r"§2 \(the program's notes \[4\] §1\.3\)"
        );
        assert_eq!(notation("fn. 4 (5)"), r"fn\. 4 \(5\)");
    }
}
