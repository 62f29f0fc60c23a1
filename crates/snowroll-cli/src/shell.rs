//! Command lines written into outputs, quoted so that a shell reads them
//! back word for word.

/// `word` as a shell reads it back as one word, so that the `# command:`
/// line stays one line and can be pasted: unchanged when it is plain (letters,
/// digits, `_./:,+=@%-`), in single quotes when it has other printable
/// characters, in `$'…'` with `\n`, `\t`, `\xNN` escapes when it has control
/// characters (a newline in a file name). Written here: the quoting crates
/// either refuse control characters or quote them raw, which breaks the line.
pub fn shell_word(word: &str) -> std::borrow::Cow<'_, str> {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_./:,+=@%-".contains(c);
    if !word.is_empty() && word.chars().all(plain) {
        return word.into();
    }
    if !word.chars().any(char::is_control) {
        return format!("'{}'", word.replace('\'', r"'\''")).into();
    }
    let mut out = String::from("$'");
    for c in word.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\\' => out.push_str("\\\\"),
            '\'' => out.push_str("\\'"),
            c if c.is_control() => out.push_str(&format!("\\x{:02x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('\'');
    out.into()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_words_stay_and_others_are_quoted() {
        assert_eq!(shell_word("5:60:12"), "5:60:12");
        assert_eq!(shell_word("/tmp/a b.csv"), "'/tmp/a b.csv'");
        assert_eq!(shell_word("it's"), r"'it'\''s'");
        assert_eq!(shell_word("two\nlines"), r"$'two\nlines'");
        assert_eq!(shell_word(""), "''");
    }
}
