//! JSON documents written whole (`snowroll models --format json`, the
//! report's `claims.json`): pretty-printed, ending in a newline. A run's and
//! a turn table's JSON are streamed by their writers (`trajectory.rs`,
//! `turns.rs`).

use serde::Serialize;

use crate::OutputError;

/// `value` as one pretty-printed JSON document ending in a newline.
///
/// # Errors
/// [`OutputError::Json`] when `value` cannot be serialised.
pub fn json_document<T: Serialize + ?Sized>(value: &T) -> Result<String, OutputError> {
    let mut text = serde_json::to_string_pretty(value)?;
    text.push('\n');
    Ok(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two-space indentation, keys in field order, one newline at the end.
    #[test]
    fn pretty_with_a_final_newline() {
        #[derive(Serialize)]
        struct Doc {
            b: u8,
            a: [f64; 1],
        }
        assert_eq!(
            json_document(&Doc { b: 1, a: [0.5] }).unwrap(),
            "{\n  \"b\": 1,\n  \"a\": [\n    0.5\n  ]\n}\n"
        );
    }
}
