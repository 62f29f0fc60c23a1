//! The last guard before a number is written: every `f64` of a record is
//! visited through its `Serialize` implementation (the same one the CSV and
//! JSON writers use), and the first NaN or infinity is reported with the
//! field that holds it. Validation ([`snowroll::Scenario::new`]) keeps the
//! derived quantities in range; this guard catches whatever a run still
//! manages to push out of range, so that no output ever carries `inf`,
//! `NaN` or a JSON `null` standing for one. (A quantity that is undefined
//! rather than overflowed, such as the friction ratio |F|/N where N ≤ 0, is
//! an `Option` and is written as an empty CSV cell or a JSON `null`.)

use std::fmt;

use serde::ser::{self, Serialize};

/// A non-finite number found in a record about to be written.
#[derive(Debug, Clone, PartialEq)]
pub struct NonFinite {
    /// Where: the column (CSV) or the key path (JSON, `samples[3].mass_kg`).
    pub field: String,
    /// The data row, counted from 1 (CSV rows; `None` for header values).
    pub row: Option<u64>,
    /// The number itself (NaN or ±inf).
    pub value: f64,
}

impl fmt::Display for NonFinite {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "refusing to write the non-finite {} = {}",
            self.field, self.value
        )?;
        if let Some(row) = self.row {
            write!(f, " in data row {row}")?;
        }
        write!(
            f,
            " (a quantity overflowed: the scenario is out of the range this program computes in)"
        )
    }
}

impl std::error::Error for NonFinite {}

/// Checks every number of `record`; `row` is the data row it will become
/// (CSV), or `None` for a whole document or a header.
///
/// # Errors
/// [`NonFinite`] naming the first field that holds NaN or ±inf.
pub fn check_finite<T: Serialize + ?Sized>(record: &T, row: Option<u64>) -> Result<(), NonFinite> {
    let mut scan = Scan {
        path: String::new(),
    };
    match record.serialize(&mut scan) {
        Ok(()) => Ok(()),
        Err(Found { field, value }) => Err(NonFinite { field, row, value }),
    }
}

/// The scanner's "error": the first non-finite number and where it was.
#[derive(Debug)]
struct Found {
    field: String,
    value: f64,
}

impl fmt::Display for Found {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}", self.field, self.value)
    }
}

impl std::error::Error for Found {}

impl ser::Error for Found {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        // A record that cannot serialise at all fails in the real writer
        // too, with its own message; the scan reports nothing for it.
        Found {
            field: msg.to_string(),
            value: 0.0,
        }
    }
}

/// Walks a value, keeping the key path of the field being visited.
struct Scan {
    path: String,
}

impl Scan {
    /// Visits `value` under the path extended by `step`, then restores it.
    fn visit<T: Serialize + ?Sized>(
        &mut self,
        step: fmt::Arguments<'_>,
        value: &T,
    ) -> Result<(), Found> {
        let len = self.path.len();
        self.path.push_str(&step.to_string());
        let out = value.serialize(&mut *self);
        self.path.truncate(len);
        out
    }

    fn dot(&self) -> &'static str {
        if self.path.is_empty() {
            ""
        } else {
            "."
        }
    }

    fn number(&self, value: f64) -> Result<(), Found> {
        if value.is_finite() {
            Ok(())
        } else {
            Err(Found {
                field: if self.path.is_empty() {
                    "value".to_string()
                } else {
                    self.path.clone()
                },
                value,
            })
        }
    }
}

/// Compound values: sequences count their items, structs and maps name
/// their keys (map keys are not numbers in any of our records).
struct Compound<'a> {
    scan: &'a mut Scan,
    index: usize,
}

impl Compound<'_> {
    fn item<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        let i = self.index;
        self.index += 1;
        self.scan.visit(format_args!("[{i}]"), value)
    }

    fn field<T: Serialize + ?Sized>(&mut self, key: &str, value: &T) -> Result<(), Found> {
        let dot = self.scan.dot();
        self.scan.visit(format_args!("{dot}{key}"), value)
    }
}

macro_rules! ok_scalars {
    ($($method:ident: $ty:ty),* $(,)?) => {
        $(fn $method(self, _: $ty) -> Result<(), Found> { Ok(()) })*
    };
}

impl<'a> ser::Serializer for &'a mut Scan {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = MapScan<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    ok_scalars!(
        serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_i128: i128, serialize_u8: u8, serialize_u16: u16,
        serialize_u32: u32, serialize_u64: u64, serialize_u128: u128, serialize_char: char,
        serialize_str: &str, serialize_bytes: &[u8],
    );

    fn serialize_f32(self, v: f32) -> Result<(), Found> {
        self.number(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), Found> {
        self.number(v)
    }
    fn serialize_none(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Found> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        value.serialize(self)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Found> {
        Ok(Compound {
            scan: self,
            index: 0,
        })
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, Found> {
        Ok(Compound {
            scan: self,
            index: 0,
        })
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        Ok(Compound {
            scan: self,
            index: 0,
        })
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        Ok(Compound {
            scan: self,
            index: 0,
        })
    }
    fn serialize_map(self, _: Option<usize>) -> Result<MapScan<'a>, Found> {
        Ok(MapScan {
            scan: self,
            key: String::new(),
        })
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        Ok(Compound {
            scan: self,
            index: 0,
        })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        Ok(Compound {
            scan: self,
            index: 0,
        })
    }
}

impl ser::SerializeSeq for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        self.item(value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

impl ser::SerializeTuple for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        self.item(value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

impl ser::SerializeTupleStruct for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        self.item(value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

impl ser::SerializeTupleVariant for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        self.item(value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

impl ser::SerializeStruct for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        self.field(key, value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

impl ser::SerializeStructVariant for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        self.field(key, value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

/// A map: its keys are rendered as text (they name the field of the value
/// that follows); a flattened struct arrives this way too.
struct MapScan<'a> {
    scan: &'a mut Scan,
    key: String,
}

impl ser::SerializeMap for MapScan<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Found> {
        self.key = serde_json::to_value(key)
            .ok()
            .map(|k| match k {
                serde_json::Value::String(s) => s,
                other => other.to_string(),
            })
            .unwrap_or_default();
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        let key = std::mem::take(&mut self.key);
        let dot = self.scan.dot();
        self.scan.visit(format_args!("{dot}{key}"), value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Serialize)]
    struct Row {
        t_s: f64,
        turn: u64,
        mass_kg: f64,
    }

    #[derive(serde::Serialize)]
    struct Doc {
        params: Option<f64>,
        samples: Vec<Row>,
    }

    #[test]
    fn finite_records_pass() {
        let row = Row {
            t_s: 1.0,
            turn: 3,
            mass_kg: 1e300,
        };
        assert_eq!(check_finite(&row, Some(1)), Ok(()));
        assert_eq!(check_finite(&(1.0, -0.0, f64::MAX), None), Ok(()));
    }

    #[test]
    fn names_the_column_and_row_of_a_non_finite_number() {
        let row = Row {
            t_s: 0.5,
            turn: 0,
            mass_kg: f64::INFINITY,
        };
        let err = check_finite(&row, Some(7)).unwrap_err();
        assert_eq!(err.field, "mass_kg");
        assert_eq!(err.row, Some(7));
        let text = err.to_string();
        assert!(
            text.contains("mass_kg = inf") && text.contains("row 7"),
            "{text}"
        );
    }

    #[test]
    fn names_the_key_path_inside_a_document() {
        let doc = Doc {
            params: Some(2.0),
            samples: vec![
                Row {
                    t_s: 0.0,
                    turn: 0,
                    mass_kg: 1.0,
                },
                Row {
                    t_s: f64::NAN,
                    turn: 1,
                    mass_kg: 1.0,
                },
            ],
        };
        let err = check_finite(&doc, None).unwrap_err();
        assert_eq!(err.field, "samples[1].t_s");
        assert!(err.value.is_nan());
        let doc = Doc {
            params: Some(f64::NEG_INFINITY),
            samples: vec![],
        };
        assert_eq!(check_finite(&doc, None).unwrap_err().field, "params");
    }

    /// The friction ratio has no exception: where it is undefined (N ≤ 0)
    /// it is an `Option` left empty, so an infinity there is an overflow.
    #[test]
    fn an_infinite_friction_ratio_is_refused_and_an_undefined_one_passes() {
        #[derive(serde::Serialize)]
        struct Contact {
            normal_n: f64,
            friction_ratio: Option<f64>,
        }
        let inf = Contact {
            normal_n: 0.0,
            friction_ratio: Some(f64::INFINITY),
        };
        assert_eq!(
            check_finite(&inf, Some(1)).unwrap_err().field,
            "friction_ratio"
        );
        let undefined = Contact {
            normal_n: -1.0,
            friction_ratio: None,
        };
        assert_eq!(check_finite(&undefined, Some(1)), Ok(()));
    }

    #[test]
    fn flattened_maps_and_tuples_are_visited() {
        let mut map = std::collections::BTreeMap::new();
        map.insert("r0_m", f64::INFINITY);
        assert_eq!(check_finite(&map, None).unwrap_err().field, "r0_m");
        let err = check_finite(&("series", 1.0, f64::NAN), Some(2)).unwrap_err();
        assert_eq!(err.field, "[2]");
    }
}
