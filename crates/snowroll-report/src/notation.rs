//! One notation for numbers and symbols in the report: Unicode superscripts
//! and subscripts (`10⁻¹²`, `r₀`, `s^−7/3` as `s⁻⁷ᐟ³`), no negative zero, no
//! ASCII `^(…)` or LaTeX `_{…}`; in HTML, a group with no Unicode form
//! (`r_(K−1)`) is set in `<sub>`/`<sup>`.

/// The Unicode superscript of `c`, for digits, signs and `/`, `(`, `)`.
fn superscript_char(c: char) -> Option<char> {
    Some(match c {
        '0' => '⁰',
        '1' => '¹',
        '2' => '²',
        '3' => '³',
        '4' => '⁴',
        '5' => '⁵',
        '6' => '⁶',
        '7' => '⁷',
        '8' => '⁸',
        '9' => '⁹',
        '-' | '−' => '⁻',
        '+' => '⁺',
        '/' => 'ᐟ',
        '(' => '⁽',
        ')' => '⁾',
        'i' => 'ⁱ',
        'k' => 'ᵏ',
        'n' => 'ⁿ',
        'p' => 'ᵖ',
        'x' => 'ˣ',
        _ => return None,
    })
}

/// `text` in superscript: digits, signs, `/` and parentheses (other
/// characters are kept as they are).
pub fn superscript(text: &str) -> String {
    text.chars()
        .map(|c| superscript_char(c).unwrap_or(c))
        .collect()
}

/// `x` with `digits` significant figures: plain between 10⁻³ and 10⁵,
/// else `m×10ᵉ` (`3.2×10⁻¹²`, `10⁻¹⁰` for a mantissa of 1). Never `-0`.
pub fn number(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let digits = digits.max(1);
    let text = format!("{:.*e}", digits - 1, x);
    let Some((mantissa, exp)) = text.split_once('e') else {
        return text;
    };
    let exp: i32 = exp.parse().unwrap_or(0);
    let sign = if x < 0.0 { "−" } else { "" };
    let mantissa = mantissa.trim_start_matches('-');
    if (-3..5).contains(&exp) {
        let decimals = (digits as i32 - 1 - exp).max(0) as usize;
        let plain = format!("{:.*}", decimals, x.abs());
        return format!("{sign}{plain}");
    }
    let mantissa = if mantissa.contains('.') {
        mantissa.trim_end_matches('0').trim_end_matches('.')
    } else {
        mantissa
    };
    let power = format!("10{}", superscript(&exp.to_string()));
    if mantissa == "1" {
        format!("{sign}{power}")
    } else {
        format!("{sign}{mantissa}×{power}")
    }
}

/// `x` in its shortest round-trip digits: plain between 10⁻² and 10⁴
/// (`0.01`, `2.5`), else `m×10ᵉ` (`10⁻³`, `5×10⁻⁴`): for tolerances and
/// other numbers people typed.
pub fn compact(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return number(x, 1);
    }
    let text = format!("{:e}", x.abs());
    let Some((mantissa, exp)) = text.split_once('e') else {
        return text;
    };
    let exp: i32 = exp.parse().unwrap_or(0);
    let sign = if x < 0.0 { "−" } else { "" };
    if (-2..4).contains(&exp) {
        return format!("{sign}{}", x.abs());
    }
    let power = format!("10{}", superscript(&exp.to_string()));
    if mantissa == "1" {
        format!("{sign}{power}")
    } else {
        format!("{sign}{mantissa}×{power}")
    }
}

/// `x` with `decimals` decimals and a Unicode minus, never `−0.000`: a value
/// that rounds to zero prints as zero.
pub fn fixed(x: f64, decimals: usize) -> String {
    let text = format!("{:.*}", decimals, x);
    match text.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        Some(rest) => format!("−{rest}"),
        None => text,
    }
}

/// The Unicode subscript of `c`, where there is one.
fn subscript_char(c: char) -> Option<char> {
    Some(match c {
        '0'..='9' => char::from_u32(0x2080 + (c as u32 - '0' as u32))?,
        '+' => '₊',
        '-' | '−' => '₋',
        '(' => '₍',
        ')' => '₎',
        'a' => 'ₐ',
        'e' => 'ₑ',
        'h' => 'ₕ',
        'i' => 'ᵢ',
        'j' => 'ⱼ',
        'k' => 'ₖ',
        'l' => 'ₗ',
        'm' => 'ₘ',
        'n' => 'ₙ',
        'o' => 'ₒ',
        'p' => 'ₚ',
        'r' => 'ᵣ',
        's' => 'ₛ',
        't' => 'ₜ',
        'u' => 'ᵤ',
        'v' => 'ᵥ',
        'x' => 'ₓ',
        _ => return None,
    })
}

/// `inner` wholly in super- or subscript, if every character has one.
fn all_in(inner: &str, map: fn(char) -> Option<char>) -> Option<String> {
    inner.chars().map(map).collect()
}

/// Report prose in the report's one notation: `1.5e-7` → `1.5×10⁻⁷`,
/// `s^(−7/3)` → `s⁻⁷ᐟ³`, `r_{k+1}` → `rₖ₊₁`, and a negative zero such as
/// `-0.0000` → `0.0000`. Text between backticks is left alone (commands and
/// identifiers), and so are tokens that are part of a word (`eq32+36`,
/// `x_m`).
pub fn prettify(text: &str) -> String {
    prettify_with(text, false)
}

/// Marks (private-use characters) around a group that has no Unicode
/// super- or subscript form, such as `r_(K−1)`: [`prettify_html`] turns them
/// into `<sub>`/`<sup>` elements after escaping.
const SUB_OPEN: char = '\u{E000}';
const SUB_CLOSE: char = '\u{E001}';
const SUP_OPEN: char = '\u{E002}';
const SUP_CLOSE: char = '\u{E003}';

/// Report prose as HTML element content: [`prettify`], escaped with
/// `escape`, and a group with no Unicode form (`r_(K−1)`, `x^{a+b}`) set
/// in `<sub>`/`<sup>`, so that no `_{`, `^(` … is left in the page.
pub fn prettify_html(text: &str, escape: impl Fn(&str) -> String) -> String {
    escape(&prettify_with(text, true))
        .replace(SUB_OPEN, "<sub>")
        .replace(SUB_CLOSE, "</sub>")
        .replace(SUP_OPEN, "<sup>")
        .replace(SUP_CLOSE, "</sup>")
}

fn prettify_with(text: &str, marks: bool) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    for (i, part) in text.split('`').enumerate() {
        if i > 0 {
            out.push('`');
        }
        if i % 2 == 1 {
            out.push_str(part);
        } else {
            out.push_str(&prettify_plain(part, marks));
        }
    }
    out
}

/// `text` (outside code spans) in the report's notation: groups and runs
/// after `^` or `_` in super/subscript, numbers at the start of a token in
/// scientific form or with a Unicode minus; the rest as it is.
fn prettify_plain(text: &str, marks: bool) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len() + 16);
    let mut i = 0;
    while i < chars.len() {
        let found = group_at(&chars, i, marks)
            .or_else(|| subscript_name_at(&chars, i, marks))
            .or_else(|| superscript_run_at(&chars, i))
            .or_else(|| number_at(&chars, i));
        if let Some((pretty, next)) = found {
            out.push_str(&pretty);
            i = next;
            continue;
        }
        out.push(chars[i]);
        i += 1;
    }
    out
}

/// A character of a word: a number or a name with its subscripts.
fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '.'
}

/// ^(…), ^{…}, _{…}, _(…) at `i`: the whole group in super/subscript; else,
/// with `marks`, the group between marks (for <sup>/<sub>); else `None`
/// (untouched). With the text, the index just past the group.
fn group_at(chars: &[char], i: usize, marks: bool) -> Option<(String, usize)> {
    let c = chars[i];
    let open = chars.get(i + 1).copied();
    if !((c == '^' || c == '_') && matches!(open, Some('(' | '{'))) {
        return None;
    }
    let close = if open == Some('(') { ')' } else { '}' };
    let len = chars[i + 2..].iter().position(|&d| d == close)?;
    let inner: String = chars[i + 2..i + 2 + len].iter().collect();
    let (map, left, right) = if c == '^' {
        (
            superscript_char as fn(char) -> Option<char>,
            SUP_OPEN,
            SUP_CLOSE,
        )
    } else {
        (
            subscript_char as fn(char) -> Option<char>,
            SUB_OPEN,
            SUB_CLOSE,
        )
    };
    if let Some(mapped) = all_in(&inner, map) {
        return Some((mapped, i + len + 3));
    }
    if marks {
        let mut out = String::new();
        out.push(left);
        out.push_str(&prettify_plain(&inner, marks));
        out.push(right);
        return Some((out, i + len + 3));
    }
    None
}

/// The longest subscript written without braces: `I_C`, `x_cm`, `v_Loney`,
/// `E_released`.
const NAME_SUBSCRIPT_MAX: usize = 8;

/// `_C`, `_cm`, `_end` at `i` after a one-letter name (`I_C`, `v_end`, and
/// `dI_C` for a derivative): the subscript in Unicode where every character
/// has a form, else (with `marks`) between marks for `<sub>`; else `None`.
/// A name of more letters (`mass_kg`), a longer subscript or a second
/// underscore (`v_m_s`, `a_over_g`) is an identifier, left as it is; write
/// identifiers in backticks.
fn subscript_name_at(chars: &[char], i: usize, marks: bool) -> Option<(String, usize)> {
    if chars[i] != '_' || i == 0 || !chars[i - 1].is_alphabetic() {
        return None;
    }
    // A name starts a word, or follows a number or a Greek letter of a
    // product (`2πr_k`, `3m_n`); after an ASCII letter it is part of an
    // identifier (`mass_kg`).
    let starts_word = |j: usize| {
        j == 0 || {
            let c = chars[j - 1];
            !is_word(c) || c.is_ascii_digit() || (c.is_alphabetic() && !c.is_ascii())
        }
    };
    let name_alone = starts_word(i - 1) || (i >= 2 && chars[i - 2] == 'd' && starts_word(i - 2));
    let len = chars[i + 1..]
        .iter()
        .take_while(|c| c.is_ascii_alphanumeric())
        .count();
    let end = i + 1 + len;
    let ends_word = match chars.get(end) {
        None => true,
        Some('_') => false,
        Some('.') => !chars
            .get(end + 1)
            .is_some_and(|c| c.is_ascii_alphanumeric()),
        Some(c) => !c.is_ascii_alphanumeric(),
    };
    if !name_alone || len == 0 || len > NAME_SUBSCRIPT_MAX || !ends_word {
        return None;
    }
    let inner: String = chars[i + 1..end].iter().collect();
    if let Some(mapped) = all_in(&inner, subscript_char) {
        return Some((mapped, end));
    }
    marks.then(|| (format!("{SUB_OPEN}{inner}{SUB_CLOSE}"), end))
}

/// ^−7/3, ^2, ^−p at `i`: the run of characters that have a superscript, in
/// superscript, and the index just past it; `None` when no such run follows.
fn superscript_run_at(chars: &[char], i: usize) -> Option<(String, usize)> {
    let open = chars.get(i + 1).copied();
    if chars[i] != '^' || matches!(open, Some('(' | '{')) {
        return None;
    }
    let run = chars[i + 1..]
        .iter()
        .take_while(|&&d| superscript_char(d).is_some())
        .count();
    if run == 0 {
        return None;
    }
    let inner: String = chars[i + 1..i + 1 + run].iter().collect();
    Some((superscript(&inner), i + run + 1))
}

/// A number at the start of a token at `i`, in scientific form (`2.5×10⁷`)
/// or with a Unicode minus (none for negative zero), and the index just past
/// it; `None` when no number starts there, or one runs into a word or ends
/// in a point.
fn number_at(chars: &[char], i: usize) -> Option<(String, usize)> {
    let c = chars[i];
    let starts_token = i == 0 || !is_word(chars[i - 1]);
    let minus = c == '-' || c == '−';
    let digit_at = if minus { i + 1 } else { i };
    if !(starts_token && chars.get(digit_at).is_some_and(char::is_ascii_digit)) {
        return None;
    }
    let mut j = digit_at;
    while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.') {
        j += 1;
    }
    let mantissa: String = chars[digit_at..j].iter().collect();
    let (exponent, end) = exponent_at(chars, j);
    let followed_by_word = chars
        .get(end)
        .is_some_and(|&d| d.is_alphabetic() || d == '_');
    let is_zero = mantissa.chars().all(|d| d == '0' || d == '.');
    if followed_by_word || mantissa.ends_with('.') {
        return None;
    }
    let sign = if minus && !is_zero { "−" } else { "" };
    let pretty = match exponent {
        Some(e) => {
            let m = mantissa.as_str();
            let power = format!("10{}", superscript(&e.to_string()));
            if m == "1" {
                format!("{sign}{power}")
            } else {
                format!("{sign}{m}×{power}")
            }
        }
        None => format!("{sign}{mantissa}"),
    };
    Some((pretty, end))
}

/// The exponent `e±N` of a number whose mantissa ends at `j`, if one follows
/// and ends the word, and the index just past the number.
fn exponent_at(chars: &[char], j: usize) -> (Option<i32>, usize) {
    if chars.get(j) != Some(&'e') {
        return (None, j);
    }
    let mut k = j + 1;
    if matches!(chars.get(k), Some('-' | '+')) {
        k += 1;
    }
    let digits_start = k;
    while k < chars.len() && chars[k].is_ascii_digit() {
        k += 1;
    }
    if k > digits_start && !chars.get(k).is_some_and(|&d| is_word(d)) {
        let e: String = chars[j + 1..k].iter().collect();
        (e.trim_start_matches('+').parse::<i32>().ok(), k)
    } else {
        (None, j)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn superscripts_cover_digits_signs_and_fractions() {
        assert_eq!(superscript("-7/3"), "⁻⁷ᐟ³");
        assert_eq!(superscript("(12)"), "⁽¹²⁾");
    }

    #[test]
    fn numbers_use_powers_of_ten_outside_the_plain_range() {
        assert_eq!(number(1e-10, 2), "10⁻¹⁰");
        assert_eq!(number(3.24e-12, 2), "3.2×10⁻¹²");
        assert_eq!(number(-2.5e7, 3), "−2.5×10⁷");
        assert_eq!(number(0.0123, 2), "0.012");
        assert_eq!(number(1234.0, 2), "1234");
        assert_eq!(number(0.0, 3), "0");
    }

    #[test]
    fn compact_keeps_the_digits_people_typed() {
        assert_eq!(compact(1e-3), "10⁻³");
        assert_eq!(compact(5e-4), "5×10⁻⁴");
        assert_eq!(compact(2.5e-12), "2.5×10⁻¹²");
        assert_eq!(compact(0.01), "0.01");
        assert_eq!(compact(0.5), "0.5");
        assert_eq!(compact(1e6), "10⁶");
    }

    #[test]
    fn prose_gets_one_notation() {
        assert_eq!(
            prettify("measured 1.2e-5 relative"),
            "measured 1.2×10⁻⁵ relative"
        );
        assert_eq!(prettify("within 1e-10"), "within 10⁻¹⁰");
        assert_eq!(prettify("K s^(−7/3), r_{k+1}²"), "K s⁻⁷ᐟ³, rₖ₊₁²");
        assert_eq!(prettify("∝ r^−p, b^2 terms"), "∝ r⁻ᵖ, b² terms");
        assert_eq!(prettify("over [-0.0000, 0.6667]"), "over [0.0000, 0.6667]");
        assert_eq!(prettify("a = -0.25 G"), "a = −0.25 G");
        // A one-letter name's subscript is notation; words, identifiers
        // (more letters, a second underscore) and code stay as they are.
        assert_eq!(prettify("r_k and x_n."), "rₖ and xₙ.");
        assert_eq!(
            prettify("eq32+36 and mass_kg, v_m_s, a_over_g, v2e3"),
            "eq32+36 and mass_kg, v_m_s, a_over_g, v2e3"
        );
        assert_eq!(prettify("`x_m` and x_m"), "`x_m` and xₘ");
        assert_eq!(
            prettify("run `--rtol 1e-10` then"),
            "run `--rtol 1e-10` then"
        );
        assert_eq!(prettify("3 turns, 2.5 m/s"), "3 turns, 2.5 m/s");
    }

    /// Issue 36, item 4: a name's subscript after a number or a Greek
    /// letter of a product, and a Greek name's, are set like any other.
    #[test]
    fn subscripts_in_products_and_on_greek_names_are_set() {
        assert_eq!(
            prettify("one circumference 2πr_k"),
            "one circumference 2πrₖ"
        );
        assert_eq!(prettify("3m_n v²/2, 2r_k²"), "3mₙ v²/2, 2rₖ²");
        assert_eq!(prettify("ρ_a = 1.2 kg/m³"), "ρₐ = 1.2 kg/m³");
        let html = |s: &str| prettify_html(s, |t| t.to_string());
        assert_eq!(html("tan α_K"), "tan α<sub>K</sub>");
        assert_eq!(html("E_released + K0"), "E<sub>released</sub> + K0");
        // Identifiers stay: letters before the name, a second underscore.
        assert_eq!(prettify("alpha_deg, snow_depth"), "alpha_deg, snow_depth");
    }

    #[test]
    fn html_prose_leaves_no_latex_groups() {
        let esc = |s: &str| s.replace('<', "&lt;");
        assert_eq!(prettify_html("(s0/s)^{30/7}", esc), "(s0/s)³⁰ᐟ⁷");
        assert_eq!(prettify_html("r_(k+1) < m_{n−1}", esc), "rₖ₊₁ &lt; mₙ₋₁");
        // K has no Unicode subscript: the group is set in <sub>, text escaped.
        assert_eq!(prettify_html("r_(K−1) < r", esc), "r<sub>K−1</sub> &lt; r");
        assert_eq!(prettify_html("e^{a<b}", esc), "e<sup>a&lt;b</sup>");
        assert_eq!(
            prettify_html("dI_C/dt, x_cm, v_end, c_rr", esc),
            "dI<sub>C</sub>/dt, x<sub>cm</sub>, v<sub>end</sub>, cᵣᵣ"
        );
        // Plain prettify leaves what it cannot map as it was.
        assert_eq!(prettify("I_C"), "I_C");
        assert_eq!(prettify("r_(K−1)"), "r_(K−1)");
        assert_eq!(prettify_html("`x_{k}` stays", esc), "`x_{k}` stays");
    }

    #[test]
    fn fixed_never_prints_negative_zero() {
        assert_eq!(fixed(-0.0, 4), "0.0000");
        assert_eq!(fixed(-1e-9, 4), "0.0000");
        assert_eq!(fixed(-0.25, 2), "−0.25");
        assert_eq!(fixed(2.0 / 3.0, 4), "0.6667");
    }
}
