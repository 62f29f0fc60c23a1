//! Outputs of snowroll read back as `--config` files (`simulate` and
//! `turns`): the settings recorded in their header, read within the limits
//! of [`crate::bounded`] and never their rows. A CSV output gives its
//! `# key = value` lines, a JSON output its `model` and `params` (streamed:
//! the reader stops there).
//!
//! A JSON output is read with serde_json's streaming deserializer, stopped
//! once it has `model` and `params` (which every output writes before its
//! rows), rather than parsed from a bounded prefix: a prefix cut at a byte
//! count is not valid JSON, while the streaming reader ends exactly after
//! `params`, whatever their length, holds nothing of what it skips, and
//! the limit of [`crate::bounded`] still caps what it reads before them.

use std::io::{self, Read};

use anyhow::{anyhow, bail, Result};
use serde::de::{DeserializeSeed, Error as _, IgnoredAny, MapAccess, Visitor};
use serde::Deserializer;
use serde_json::Map;
use snowroll::{Param, RecordedSampling};

use super::{ConfigFile, Origin};

/// The keys an output records that are not settings of a run: they are
/// read back as the output's provenance, not as config keys.
const RECORD_ONLY: [&str; 5] = ["sampling", "warnings", "warning", "notes", "note"];

/// Whether a recorded `sampling` is that of a turn table (`snowroll turns`).
fn is_turn_table(sampling: &str) -> bool {
    sampling.parse() == Ok(RecordedSampling::PerTurn)
}

/// The `model` and `params` of a JSON output, as read so far.
#[derive(Debug, Default)]
struct JsonHead {
    model: Option<serde_json::Value>,
    params: Option<Map<String, serde_json::Value>>,
    /// Whether the reading stopped after both, with the error [`HEAD_READ`].
    stopped: bool,
}

/// Reads the keys of a JSON output into a [`JsonHead`] and stops (with an
/// error the caller ignores) once it has both: the rows that follow are
/// never read, so their size costs nothing and an endless file after the
/// header ends the reading. Keys before them are skipped without being
/// kept ([`IgnoredAny`]).
struct JsonHeadSeed<'a>(&'a mut JsonHead);

/// The message of the early stop; never shown.
const HEAD_READ: &str = "the header is read";

impl<'de> DeserializeSeed<'de> for JsonHeadSeed<'_> {
    type Value = ();

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for JsonHeadSeed<'_> {
    type Value = ();

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("an output of snowroll (an object with `model` and `params`)")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        let mut seen = std::collections::HashSet::new();
        while let Some(key) = map.next_key::<String>()? {
            if !seen.insert(key.clone()) {
                return Err(A::Error::custom(duplicate(&key)));
            }
            match key.as_str() {
                "model" => self.0.model = Some(map.next_value_seed(Unique)?),
                "params" => match map.next_value_seed(Unique)? {
                    serde_json::Value::Object(params) => self.0.params = Some(params),
                    _ => return Err(A::Error::custom("`params` is not an object")),
                },
                _ => {
                    map.next_value::<IgnoredAny>()?;
                }
            }
            if self.0.model.is_some() && self.0.params.is_some() {
                self.0.stopped = true;
                return Err(A::Error::custom(HEAD_READ));
            }
        }
        Ok(())
    }
}

/// The message for a key given twice in one JSON object.
fn duplicate(key: &str) -> String {
    format!(
        "the key `{key}` is given twice in one object: a config file sets each key once \
         (TOML refuses this too)"
    )
}

/// A JSON value read with every object's keys checked to be distinct
/// (issue 33, item 5): serde_json keeps the last of two equal keys, so a
/// `model` or a parameter given twice would silently take the second.
struct Unique;

impl<'de> DeserializeSeed<'de> for Unique {
    type Value = serde_json::Value;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Unique {
    type Value = serde_json::Value;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_bool<E>(self, v: bool) -> Result<Self::Value, E> {
        Ok(v.into())
    }

    fn visit_i64<E>(self, v: i64) -> Result<Self::Value, E> {
        Ok(v.into())
    }

    fn visit_u64<E>(self, v: u64) -> Result<Self::Value, E> {
        Ok(v.into())
    }

    fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Self::Value, E> {
        serde_json::Number::from_f64(v)
            .map(serde_json::Value::Number)
            .ok_or_else(|| E::custom("a number that is not finite"))
    }

    fn visit_str<E>(self, v: &str) -> Result<Self::Value, E> {
        Ok(v.into())
    }

    fn visit_string<E>(self, v: String) -> Result<Self::Value, E> {
        Ok(v.into())
    }

    fn visit_unit<E>(self) -> Result<Self::Value, E> {
        Ok(serde_json::Value::Null)
    }

    fn visit_none<E>(self) -> Result<Self::Value, E> {
        Ok(serde_json::Value::Null)
    }

    fn visit_some<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(self)
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut items = Vec::new();
        while let Some(item) = seq.next_element_seed(Unique)? {
            items.push(item);
        }
        Ok(serde_json::Value::Array(items))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            if out.contains_key(&key) {
                return Err(A::Error::custom(duplicate(&key)));
            }
            let value = map.next_value_seed(Unique)?;
            out.insert(key, value);
        }
        Ok(serde_json::Value::Object(out))
    }
}

/// The settings of a JSON output of snowroll (`simulate` or `turns`), read
/// from `reader` up to its `model` and `params` (streamed: the rows after
/// them are not read, see [`JsonHeadSeed`]). Numbers are read exactly
/// (serde_json's `float_roundtrip`), so a run read back is the same run.
pub fn from_json_output(reader: impl Read) -> Result<(ConfigFile, Origin)> {
    use serde_json::Value;
    let mut head = JsonHead::default();
    let mut de = serde_json::Deserializer::from_reader(reader);
    let read = JsonHeadSeed(&mut head).deserialize(&mut de);
    if !head.stopped {
        // Read to its end without both keys: it must be valid JSON.
        read.and_then(|()| de.end())
            .map_err(|e| match e.io_error_kind() {
                // A bounded reader's error says what the limit is.
                Some(_) => anyhow!("{}", io::Error::from(e)),
                None => anyhow!("not valid JSON: {e}"),
            })?;
    }
    let Some(params) = head.params else {
        bail!("a JSON config file must be an output of snowroll (with `params` and `model`)");
    };
    let mut keys = Map::new();
    if let Some(id) = head.model.as_ref().and_then(|m| m.pointer("/id")?.as_str()) {
        keys.insert("model".into(), Value::String(id.to_string()));
    }
    let sampling = params.get("sampling").and_then(Value::as_str);
    let origin = if sampling.is_some_and(is_turn_table) {
        Origin::Turns
    } else {
        Origin::Simulate
    };
    for (k, v) in params {
        if !RECORD_ONLY.contains(&k.as_str()) && !v.is_null() {
            keys.insert(k, v);
        }
    }
    keys.insert("format".into(), Value::String("json".into()));
    let file = serde_json::from_value(Value::Object(keys)).map_err(|e| anyhow!("{e}"))?;
    Ok((file, origin))
}

/// The settings of a CSV output of snowroll: its `# key = value` lines
/// before the column header. `# model = torque-cm (eq. (4))` gives the id;
/// `none` means not set; `times` is a comma-separated list.
pub fn from_csv_output(text: &str) -> Result<(ConfigFile, Origin)> {
    let mut keys = Map::new();
    let mut origin = Origin::Simulate;
    // Every setting's line, by key: a key given twice is refused, as TOML
    // and JSON refuse it, instead of the last line winning (issue 33, item 5).
    let mut seen: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for (line_no, line) in (1..).zip(text.lines()) {
        let Some(comment) = line.strip_prefix('#') else {
            // The column header: several models' output leads with `model`.
            if line.starts_with("model,") {
                bail!(
                    "it is the output of several models (`--model a,b,...`, a leading `model` \
                     column), which reads back as no one run; give one model's output, or its \
                     settings as flags"
                );
            }
            break;
        };
        let Some((key, value)) = comment.split_once(" = ") else {
            continue;
        };
        let (key, value) = (key.trim(), value.trim());
        if !key
            .bytes()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_')
        {
            continue; // a sentence (the turn table's summary), not a setting
        }
        if !RECORD_ONLY.contains(&key) {
            if let Some(first) = seen.insert(key.to_string(), line_no) {
                bail!(
                    "line {line_no}: the key `{key}` is given twice (`# {key} = ...` on lines \
                     {first} and {line_no}): a config file sets each key once"
                );
            }
        }
        let value = match key {
            "model" => {
                serde_json::Value::String(value.split_whitespace().next().unwrap_or("").into())
            }
            "sampling" => {
                if is_turn_table(value) {
                    origin = Origin::Turns;
                }
                continue;
            }
            k if RECORD_ONLY.contains(&k) || k == "stop" => continue,
            // How a turn table was computed: read back as `--method`.
            "method" => serde_json::Value::String(value.into()),
            _ if value == "none" => continue,
            // A key of the table, read as its kind; any other key goes on as
            // a number, for the config reader to name as unknown.
            k => match Param::of_key(k) {
                Some(p) => serde_json::to_value(p.parse_text(value).map_err(|e| anyhow!(e))?)?,
                None => number(key, value)?,
            },
        };
        keys.insert(key.to_string(), value);
    }
    if !keys.contains_key("model") {
        bail!(
            "a CSV config file must be an output of snowroll (its `# model = ...` line is missing)"
        );
    }
    keys.insert("format".into(), serde_json::Value::String("csv".into()));
    let file =
        serde_json::from_value(serde_json::Value::Object(keys)).map_err(|e| anyhow!("{e}"))?;
    Ok((file, origin))
}

/// A number of a CSV header line, as JSON.
fn number(key: &str, value: &str) -> Result<serde_json::Value> {
    let x: f64 = value
        .parse()
        .map_err(|_| anyhow!("`{key} = {value}` is not a number"))?;
    serde_json::Number::from_f64(x)
        .map(serde_json::Value::Number)
        .ok_or_else(|| anyhow!("`{key} = {value}` is not a finite number"))
}
