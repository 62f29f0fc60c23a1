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

/// The words of a command line written with [`shell_word`], as a shell
/// splits and unquotes them: words separated by spaces or tabs, each made of
/// plain characters, `'…'` (taken as is), `$'…'` (with the escapes
/// [`shell_word`] writes: `\n`, `\t`, `\\`, `\'`, `\xNN`) and `\c` (the
/// character c).
///
/// # Errors
/// An unterminated quote, a trailing `\`, or an escape other than those,
/// named with its position.
pub fn shell_words(line: &str) -> Result<Vec<String>, String> {
    let mut words = Vec::new();
    let mut word: Option<String> = None;
    let mut chars = line.char_indices().peekable();
    while let Some((at, c)) = chars.next() {
        match c {
            ' ' | '\t' => words.extend(word.take()),
            '\'' => {
                let w = word.get_or_insert_with(String::new);
                loop {
                    match chars.next() {
                        Some((_, '\'')) => break,
                        Some((_, c)) => w.push(c),
                        None => return Err(format!("unterminated ' at byte {at}")),
                    }
                }
            }
            '$' if chars.peek().is_some_and(|&(_, c)| c == '\'') => {
                chars.next();
                let w = word.get_or_insert_with(String::new);
                loop {
                    match chars.next() {
                        Some((_, '\'')) => break,
                        Some((_, '\\')) => w.push(escape(&mut chars, at)?),
                        Some((_, c)) => w.push(c),
                        None => return Err(format!("unterminated $' at byte {at}")),
                    }
                }
            }
            '\\' => match chars.next() {
                Some((_, c)) => word.get_or_insert_with(String::new).push(c),
                None => return Err(format!("a \\ ends the line (byte {at})")),
            },
            c => word.get_or_insert_with(String::new).push(c),
        }
    }
    words.extend(word);
    Ok(words)
}

/// The character of the escape after a `\` in `$'…'` (begun at byte `at`).
fn escape(
    chars: &mut std::iter::Peekable<std::str::CharIndices<'_>>,
    at: usize,
) -> Result<char, String> {
    match chars.next().map(|(_, c)| c) {
        Some('n') => Ok('\n'),
        Some('t') => Ok('\t'),
        Some('\\') => Ok('\\'),
        Some('\'') => Ok('\''),
        Some('x') => {
            let hex: String = (0..2)
                .filter_map(|_| chars.next().map(|(_, c)| c))
                .collect();
            u32::from_str_radix(&hex, 16)
                .ok()
                .filter(|_| hex.len() == 2)
                .and_then(char::from_u32)
                .ok_or_else(|| format!("bad escape \\x{hex} in the $' at byte {at}"))
        }
        Some(c) => Err(format!(
            "unknown escape \\{c} in the $' at byte {at} (expected \\n, \\t, \\\\, \\' or \\xNN)"
        )),
        None => Err(format!("unterminated $' at byte {at}")),
    }
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

    /// `shell_words` reads back what `shell_word` wrote, word for word, for
    /// words with spaces, quotes, backslashes, control characters and none.
    #[test]
    fn words_read_back_as_written() {
        let words = [
            "snowroll",
            "/tmp/a b.csv",
            "it's",
            "two\nlines\tand\\ a 'quote'",
            "",
            "bell\u{7}",
            "-5:5:3",
            "\u{e9}t\u{e9}",
        ];
        let line: Vec<String> = words.iter().map(|w| shell_word(w).into_owned()).collect();
        assert_eq!(shell_words(&line.join(" ")).unwrap(), words);
        // What a shell makes of hand-written words too: runs of blanks, \c.
        assert_eq!(
            shell_words("  a\\ b  'c'd\t$'e\\x41' ").unwrap(),
            ["a b", "cd", "eA"]
        );
    }

    #[test]
    fn broken_quoting_is_refused_and_placed() {
        for (line, says) in [
            ("a 'b", "unterminated ' at byte 2"),
            ("a $'b", "unterminated $' at byte 2"),
            ("a\\", "ends the line (byte 1)"),
            ("$'\\q'", "unknown escape \\q"),
            ("$'\\x4'", "bad escape \\x4'"),
        ] {
            let e = shell_words(line).unwrap_err();
            assert!(e.contains(says), "{line:?}: {e}");
        }
    }
}
