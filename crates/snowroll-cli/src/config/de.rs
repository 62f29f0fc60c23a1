//! Reading a config file's keys with serde: each key looked up in the
//! parameter table, its value parsed as the table's kind says, a key given
//! twice refused, and names compared without regard to case.

use super::*;

impl<'de> Deserialize<'de> for ConfigFile {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_map(ConfigVisitor)
    }
}

/// A key of a config file.
enum Key {
    Model,
    Format,
    Output,
    Plot,
    Method,
    Param(&'static Param),
}

/// Reads a key and names an unknown one while the reader is on it, so
/// that the message gives the key's own line and column.
struct KeySeed;

impl<'de> DeserializeSeed<'de> for KeySeed {
    type Value = Key;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Key, D::Error> {
        let key = String::deserialize(d)?;
        Ok(match key.as_str() {
            "model" => Key::Model,
            "format" => Key::Format,
            "output" => Key::Output,
            "plot" => Key::Plot,
            "method" => Key::Method,
            k => Key::Param(
                Param::find(k)
                    .filter(|p| p.settable())
                    .ok_or_else(|| D::Error::unknown_field(k, known_keys()))?,
            ),
        })
    }
}

/// Reads the value of a parameter as its kind, and refuses a word outside
/// a choice while the reader is on it (the message gives its place).
struct ValueSeed(&'static Param);

impl<'de> DeserializeSeed<'de> for ValueSeed {
    type Value = Value;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        let value = match self.0.kind {
            Kind::Real | Kind::OptionalReal => Value::Real(f64::deserialize(d)?),
            Kind::Count | Kind::OptionalCount => Value::Count(u64::deserialize(d)?),
            Kind::Flag => Value::Flag(bool::deserialize(d)?),
            Kind::Choice(_) | Kind::Text => Value::Word(String::deserialize(d)?),
            Kind::Reals => Value::Reals(Vec::deserialize(d)?),
            Kind::OptionalRealOr(_) => RealOrWord::deserialize(d)?.into(),
        };
        self.0
            .set(&mut Settings::default(), value.clone())
            .map_err(D::Error::custom)?;
        Ok(value)
    }
}

/// Reads a config file's keys one by one, each value as its parameter's kind.
struct ConfigVisitor;

impl<'de> Visitor<'de> for ConfigVisitor {
    type Value = ConfigFile;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a table of settings, one key per long flag")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<ConfigFile, A::Error> {
        let mut file = ConfigFile::default();
        while let Some(key) = map.next_key_seed(KeySeed)? {
            match key {
                Key::Model if file.model.is_some() => {
                    return Err(A::Error::duplicate_field("model"))
                }
                Key::Model => file.model = Some(map.next_value::<AnyCase<ModelKind>>()?.0),
                Key::Format => file.format = Some(map.next_value::<AnyCase<Format>>()?.0),
                Key::Output => file.output = Some(map.next_value()?),
                Key::Plot => file.plot = Some(map.next_value()?),
                Key::Method => file.method = Some(map.next_value::<AnyCase<TurnMethod>>()?.0),
                Key::Param(p) if file.given.get(p).is_some() => {
                    return Err(A::Error::duplicate_field(p.key))
                }
                Key::Param(p) => {
                    let value = map.next_value_seed(ValueSeed(p))?;
                    file.given.insert(p, value);
                }
            }
        }
        Ok(file)
    }
}

/// A model id or alias, or an output format, in any case, as the command
/// line takes them.
struct AnyCase<T>(T);

impl<'de> Deserialize<'de> for AnyCase<ModelKind> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        name.parse().map(AnyCase).map_err(D::Error::custom)
    }
}

impl<'de> Deserialize<'de> for AnyCase<TurnMethod> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        TurnMethod::ALL
            .into_iter()
            .find(|m| m.id().eq_ignore_ascii_case(name.trim()))
            .map(AnyCase)
            .ok_or_else(|| {
                let ids: Vec<String> = TurnMethod::ALL
                    .iter()
                    .map(|m| format!("`{}`", m.id()))
                    .collect();
                D::Error::custom(format!(
                    "unknown method `{name}`, expected {}",
                    ids.join(" or ")
                ))
            })
    }
}

impl<'de> Deserialize<'de> for AnyCase<Format> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        format_any_case(&name)
            .map(AnyCase)
            .map_err(D::Error::custom)
    }
}
