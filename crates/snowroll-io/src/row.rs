//! One row type for every trajectory output, and column names spelled once.
//!
//! A row is a [`Sample`] followed by what the run adds: a turn model's
//! [`TurnState`], or the energy [`LedgerRow`] of a run that records one
//! ([`Row`]). Each of those types names its fields once, in its serde
//! derive; the header of a CSV ([`Row::columns`], [`field_names`]) and each
//! row (CSV record or JSON object) are both read from there, so they cannot
//! drift apart.
//!
//! The csv crate cannot write `#[serde(flatten)]` (it turns the struct
//! into a map), so [`Row`] flattens by hand: its `Serialize` opens one
//! struct and lets each part write its fields into it through [`Fields`].

use serde::de::{self, Deserialize, Deserializer, Visitor};
use serde::ser::{self, Impossible, Serialize, SerializeStruct, Serializer};

use snowroll::models::TurnRow;
use snowroll::trajectory::{LedgerRow, Sample, TurnState};

/// What a row adds after the sample's columns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Extra<'a> {
    /// Nothing: a circular model without a ledger.
    None,
    /// The turn state of a turn model.
    Turn(&'a TurnState),
    /// The energy ledger (`docs/snowball-and-losses.md` §3).
    Ledger(&'a LedgerRow),
    /// A turn model's state and its ledger (§3.2), in that order.
    TurnLedger(&'a TurnState, &'a LedgerRow),
}

/// Which columns a run's rows carry (the [`Extra`] variant, without data).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum RowKind {
    /// [`Sample`]'s columns only.
    Plain,
    /// [`Sample`] then [`TurnState`].
    Turn,
    /// [`Sample`] then [`LedgerRow`].
    Ledger,
    /// [`Sample`], [`TurnState`], then [`LedgerRow`].
    TurnLedger,
}

/// One output row: a sample and what its run adds, written as one flat
/// CSV record or JSON object (the sample's fields first).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Row<'a> {
    /// The sample.
    pub sample: &'a Sample,
    /// What follows it.
    pub extra: Extra<'a>,
}

impl Row<'_> {
    /// The kind of this row (the writers know it from the run; the tests
    /// take it from a row).
    #[cfg(test)]
    pub fn kind(&self) -> RowKind {
        match self.extra {
            Extra::None => RowKind::Plain,
            Extra::Turn(_) => RowKind::Turn,
            Extra::Ledger(_) => RowKind::Ledger,
            Extra::TurnLedger(..) => RowKind::TurnLedger,
        }
    }

    /// The column names of rows of `kind`, in the order they are written.
    pub fn columns(kind: RowKind) -> Vec<&'static str> {
        let sample = field_names::<Sample>();
        sample.iter().copied().chain(kind.extra_columns()).collect()
    }
}

impl RowKind {
    /// The columns this kind adds after the sample's.
    fn extra_columns(self) -> Vec<&'static str> {
        let (turn, ledger) = match self {
            RowKind::Plain => (false, false),
            RowKind::Turn => (true, false),
            RowKind::Ledger => (false, true),
            RowKind::TurnLedger => (true, true),
        };
        let turn = turn.then(field_names::<TurnState>).unwrap_or_default();
        let ledger = ledger.then(field_names::<LedgerRow>).unwrap_or_default();
        turn.iter().chain(ledger).copied().collect()
    }
}

impl Serialize for Row<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        // The field count, without building the column list (this runs for
        // every row written, twice with the finiteness check).
        let (turn, ledger) = match self.extra {
            Extra::None => (0, 0),
            Extra::Turn(_) => (field_names::<TurnState>().len(), 0),
            Extra::Ledger(_) => (0, field_names::<LedgerRow>().len()),
            Extra::TurnLedger(..) => (
                field_names::<TurnState>().len(),
                field_names::<LedgerRow>().len(),
            ),
        };
        let len = field_names::<Sample>().len() + turn + ledger;
        let mut out = serializer.serialize_struct("Row", len)?;
        self.sample.serialize(Fields(&mut out))?;
        match self.extra {
            Extra::None => {}
            Extra::Turn(k) => k.serialize(Fields(&mut out))?,
            Extra::Ledger(l) => l.serialize(Fields(&mut out))?,
            Extra::TurnLedger(k, l) => {
                k.serialize(Fields(&mut out))?;
                l.serialize(Fields(&mut out))?;
            }
        }
        out.end()
    }
}

/// One row of the per-turn table (`snowroll turns`): a [`TurnRow`] and,
/// for a run that records one, the ledger at the end of that turn
/// (`docs/snowball-and-losses.md` §3.2), written as one flat record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TableRow<'a> {
    /// The turn.
    pub turn: &'a TurnRow,
    /// Its ledger.
    pub ledger: Option<&'a LedgerRow>,
}

impl TableRow<'_> {
    /// The column names, with or without the ledger's.
    pub fn columns(ledger: bool) -> Vec<&'static str> {
        let extra = ledger.then(field_names::<LedgerRow>).unwrap_or_default();
        field_names::<TurnRow>()
            .iter()
            .chain(extra)
            .copied()
            .collect()
    }
}

impl Serialize for TableRow<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        // The field count, without building the column list (per row).
        let len = field_names::<TurnRow>().len()
            + self.ledger.map_or(0, |_| field_names::<LedgerRow>().len());
        let mut out = serializer.serialize_struct("TableRow", len)?;
        self.turn.serialize(Fields(&mut out))?;
        if let Some(l) = self.ledger {
            l.serialize(Fields(&mut out))?;
        }
        out.end()
    }
}

/// The serde field names of the struct `T`, in declaration order: the
/// names its derived `Serialize` writes (`T` derives both, from the same
/// field list; none of the row types skips or renames a field one way
/// only).
///
/// `Deserialize` hands the list to [`Deserializer::deserialize_struct`];
/// a deserializer that records it and stops is all it takes, without a
/// value of `T`.
pub(crate) fn field_names<T: for<'de> Deserialize<'de>>() -> &'static [&'static str] {
    let mut names: &'static [&'static str] = &[];
    // The error is the recorder stopping once it has the names.
    let _ = T::deserialize(FieldNames(&mut names));
    names
}

/// A serializer that writes the fields of one struct into a struct being
/// written (`M`), so that several structs make one flat record.
struct Fields<'m, M>(&'m mut M);

/// Why [`Fields`] refused a value: it takes structs only.
const NOT_A_STRUCT: &str = "a row part must be a struct with named fields";

impl<M: SerializeStruct> SerializeStruct for Fields<'_, M> {
    type Ok = ();
    type Error = M::Error;

    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), M::Error> {
        self.0.serialize_field(key, value)
    }

    fn skip_field(&mut self, key: &'static str) -> Result<(), M::Error> {
        self.0.skip_field(key)
    }

    fn end(self) -> Result<(), M::Error> {
        Ok(())
    }
}

/// The methods of [`Fields`] that refuse their value.
macro_rules! refuse {
    ($($method:ident($($arg:ty),*) -> $ret:ty;)*) => {
        $(fn $method(self, $(_: $arg),*) -> Result<$ret, M::Error> {
            Err(ser::Error::custom(NOT_A_STRUCT))
        })*
    };
}

impl<'m, M: SerializeStruct> Serializer for Fields<'m, M> {
    type Ok = ();
    type Error = M::Error;
    type SerializeSeq = Impossible<(), M::Error>;
    type SerializeTuple = Impossible<(), M::Error>;
    type SerializeTupleStruct = Impossible<(), M::Error>;
    type SerializeTupleVariant = Impossible<(), M::Error>;
    type SerializeMap = Impossible<(), M::Error>;
    type SerializeStruct = Self;
    type SerializeStructVariant = Impossible<(), M::Error>;

    fn serialize_struct(self, _name: &'static str, _len: usize) -> Result<Self, M::Error> {
        Ok(self)
    }

    refuse! {
        serialize_bool(bool) -> ();
        serialize_i8(i8) -> ();
        serialize_i16(i16) -> ();
        serialize_i32(i32) -> ();
        serialize_i64(i64) -> ();
        serialize_u8(u8) -> ();
        serialize_u16(u16) -> ();
        serialize_u32(u32) -> ();
        serialize_u64(u64) -> ();
        serialize_f32(f32) -> ();
        serialize_f64(f64) -> ();
        serialize_char(char) -> ();
        serialize_str(&str) -> ();
        serialize_bytes(&[u8]) -> ();
        serialize_none() -> ();
        serialize_unit() -> ();
        serialize_unit_struct(&'static str) -> ();
        serialize_unit_variant(&'static str, u32, &'static str) -> ();
        serialize_seq(Option<usize>) -> Self::SerializeSeq;
        serialize_tuple(usize) -> Self::SerializeTuple;
        serialize_tuple_struct(&'static str, usize) -> Self::SerializeTupleStruct;
        serialize_tuple_variant(&'static str, u32, &'static str, usize) -> Self::SerializeTupleVariant;
        serialize_map(Option<usize>) -> Self::SerializeMap;
        serialize_struct_variant(&'static str, u32, &'static str, usize) -> Self::SerializeStructVariant;
    }

    fn serialize_some<T: ?Sized + Serialize>(self, _: &T) -> Result<(), M::Error> {
        Err(ser::Error::custom(NOT_A_STRUCT))
    }

    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: &T,
    ) -> Result<(), M::Error> {
        Err(ser::Error::custom(NOT_A_STRUCT))
    }

    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<(), M::Error> {
        Err(ser::Error::custom(NOT_A_STRUCT))
    }
}

/// A deserializer that records the field names a struct asks for and
/// stops there ([`field_names`]).
struct FieldNames<'a>(&'a mut &'static [&'static str]);

/// [`FieldNames`] stopping: not an error anyone sees.
#[derive(Debug)]
struct Recorded;

impl std::fmt::Display for Recorded {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("field names recorded")
    }
}

impl std::error::Error for Recorded {}

impl de::Error for Recorded {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        Recorded
    }
}

impl<'de> Deserializer<'de> for FieldNames<'_> {
    type Error = Recorded;

    fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Recorded> {
        Err(Recorded)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        _: V,
    ) -> Result<V::Value, Recorded> {
        *self.0 = fields;
        Err(Recorded)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map enum identifier ignored_any
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check_finite;

    /// A sample with every field distinct and not round in binary, so that
    /// a column read back under the wrong name, or a digit lost, shows.
    fn sample(friction_ratio: Option<f64>) -> Sample {
        Sample {
            t_s: 0.1 + 0.2,
            x_m: 1.0 / 3.0,
            v_m_s: 2.0_f64.sqrt(),
            a_m_s2: -std::f64::consts::E,
            r_m: 0.123_456_789,
            mass_kg: 12.566_370_614_359_174,
            normal_n: 107.414_230_578_826_09,
            friction_n: 1e-300,
            friction_ratio,
        }
    }

    const TURN: TurnState = TurnState {
        turn: 7,
        theta_rad: 5.5,
        omega_rad_s: 17.25,
    };

    fn ledger() -> LedgerRow {
        LedgerRow {
            kinetic_j: 1.5,
            released_j: 2.25,
            drag_j: 0.1,
            rolling_j: 0.2,
            compaction_j: 0.3,
            model_j: 0.4,
            collision_j: 0.5,
            created_j: 0.6,
            residual_j: -1e-17,
        }
    }

    /// Every kind of row, with and without the optional friction ratio.
    fn rows<'a>(samples: &'a [Sample; 2], l: &'a LedgerRow) -> Vec<Row<'a>> {
        samples
            .iter()
            .flat_map(|sample| {
                [
                    Extra::None,
                    Extra::Turn(&TURN),
                    Extra::Ledger(l),
                    Extra::TurnLedger(&TURN, l),
                ]
                .map(|extra| Row { sample, extra })
            })
            .collect()
    }

    /// Reads the part `T` of a row back from its fields by column name.
    fn by_name<T: for<'de> Deserialize<'de>>(
        header: &csv::StringRecord,
        r: &csv::StringRecord,
    ) -> T {
        r.deserialize(Some(header)).unwrap()
    }

    #[test]
    fn columns_are_the_serde_field_names_without_repeats() {
        let plain = Row::columns(RowKind::Plain);
        assert_eq!(plain, field_names::<Sample>());
        assert_eq!(plain.len(), 9);
        assert_eq!(plain[0], "t_s");
        for kind in [RowKind::Turn, RowKind::Ledger, RowKind::TurnLedger] {
            let cols = Row::columns(kind);
            assert_eq!(cols[..9], plain[..]);
            assert_eq!(&cols[9..], kind.extra_columns());
            // Reading back by name needs each name once.
            let mut sorted = cols.clone();
            sorted.sort_unstable();
            sorted.dedup();
            assert_eq!(sorted.len(), cols.len(), "{cols:?}");
        }
        assert_eq!(
            RowKind::Turn.extra_columns(),
            ["turn", "theta_rad", "omega_rad_s"]
        );
        assert_eq!(RowKind::Ledger.extra_columns().len(), 9);
        assert_eq!(RowKind::TurnLedger.extra_columns().len(), 12);
        let table = TableRow::columns(true);
        assert_eq!(table[..15], TableRow::columns(false)[..]);
        assert_eq!(table[15], "kinetic_j");
    }

    #[test]
    fn a_csv_row_has_the_header_width_and_reads_back_by_name() {
        let samples = [sample(Some(0.191_278_342_206_245_43)), sample(None)];
        let l = ledger();
        for row in rows(&samples, &l) {
            let header = Row::columns(row.kind());
            let mut w = csv::WriterBuilder::new()
                .has_headers(false)
                .from_writer(Vec::new());
            w.write_record(&header).unwrap();
            w.serialize(row).unwrap();
            let text = w.into_inner().unwrap();
            let mut r = csv::Reader::from_reader(text.as_slice());
            let names = r.headers().unwrap().clone();
            let records: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
            assert_eq!(records.len(), 1);
            assert_eq!(records[0].len(), names.len(), "{row:?}");
            // The numbers are written as their shortest round-trip digits,
            // so they read back exactly.
            assert_eq!(by_name::<Sample>(&names, &records[0]), *row.sample);
            match row.extra {
                Extra::None => {}
                Extra::Turn(k) => assert_eq!(by_name::<TurnState>(&names, &records[0]), *k),
                Extra::Ledger(l) => assert_eq!(by_name::<LedgerRow>(&names, &records[0]), *l),
                Extra::TurnLedger(k, l) => {
                    assert_eq!(by_name::<TurnState>(&names, &records[0]), *k);
                    assert_eq!(by_name::<LedgerRow>(&names, &records[0]), *l);
                }
            }
        }
    }

    #[test]
    fn a_json_row_has_one_key_per_column_and_reads_back_by_name() {
        let samples = [sample(Some(0.25)), sample(None)];
        let l = ledger();
        for row in rows(&samples, &l) {
            let value = serde_json::to_value(row).unwrap();
            let object = value.as_object().unwrap();
            let header = Row::columns(row.kind());
            assert_eq!(object.len(), header.len());
            assert!(header.iter().all(|c| object.contains_key(*c)), "{object:?}");
            let back: Sample = serde_json::from_value(value.clone()).unwrap();
            assert_eq!(back, *row.sample);
            match row.extra {
                Extra::None => {}
                Extra::Turn(k) => {
                    assert_eq!(serde_json::from_value::<TurnState>(value).unwrap(), *k);
                }
                Extra::Ledger(l) => {
                    assert_eq!(serde_json::from_value::<LedgerRow>(value).unwrap(), *l);
                }
                Extra::TurnLedger(k, l) => {
                    assert_eq!(
                        serde_json::from_value::<TurnState>(value.clone()).unwrap(),
                        *k
                    );
                    assert_eq!(serde_json::from_value::<LedgerRow>(value).unwrap(), *l);
                }
            }
        }
    }

    #[test]
    fn a_non_finite_number_is_named_by_its_column() {
        let s = sample(None);
        let l = LedgerRow {
            residual_j: f64::NAN,
            ..ledger()
        };
        let row = Row {
            sample: &s,
            extra: Extra::Ledger(&l),
        };
        let err = check_finite(&row, Some(4)).unwrap_err();
        assert!(err.to_string().contains("residual_j"), "{err}");
    }
}
