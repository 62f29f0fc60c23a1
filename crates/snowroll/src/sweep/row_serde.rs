//! A sweep row's serde form: a flat record of [`SweepRow::COLUMNS`], the
//! axes' cells named by their keys in the parameter table. Written by hand
//! because the axes' columns come from the table ([`AxisParam::ALL`]), not
//! from fields: the CSV, Parquet and JSON forms are those a struct with one
//! field per column would have (an axis that is not optional in the table
//! is a number, never empty).

use std::fmt;

use serde::de::{self, DeserializeSeed, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde::ser::SerializeStruct;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::axis::{AxisParam, AXES};
use super::row::{AxisValues, SweepRow};
use crate::models::{CollisionModel, ModelKind};
use crate::params::Kind;
use crate::trajectory::{OnHop, StopReason};

impl Serialize for SweepRow {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut s = serializer.serialize_struct("SweepRow", SweepRow::COLUMNS.len())?;
        s.serialize_field("index", &self.index)?;
        s.serialize_field("model", &self.model)?;
        for (p, v) in AxisParam::ALL.iter().zip(&self.params) {
            s.serialize_field(p.key_const(), v)?;
        }
        s.serialize_field("on_hop", &self.on_hop)?;
        s.serialize_field("collision", &self.collision)?;
        s.serialize_field("stop", &self.stop)?;
        s.serialize_field("t_s", &self.t_s)?;
        s.serialize_field("x_m", &self.x_m)?;
        s.serialize_field("v_m_s", &self.v_m_s)?;
        s.serialize_field("a_over_g_sin_alpha", &self.a_over_g_sin_alpha)?;
        s.serialize_field("turns", &self.turns)?;
        s.serialize_field("error", &self.error)?;
        s.serialize_field("warnings", &self.warnings)?;
        s.end()
    }
}

/// A row being read: each column's cell once read.
#[derive(Default)]
struct Cells {
    index: Option<u64>,
    model: Option<ModelKind>,
    /// `None` until read; then the cell (itself `None` when empty).
    params: [Option<Option<f64>>; AXES],
    on_hop: Option<OnHop>,
    collision: Option<CollisionModel>,
    stop: Option<StopReason>,
    t_s: Option<f64>,
    x_m: Option<f64>,
    v_m_s: Option<f64>,
    a_over_g_sin_alpha: Option<f64>,
    turns: Option<u64>,
    error: Option<String>,
    warnings: Option<String>,
}

/// Whether axis `k`'s cell may be empty (an optional number of the table).
fn optional(k: usize) -> bool {
    AxisParam::ALL[k].spec().kind == Kind::OptionalReal
}

/// Reads the cell of column `column` (an index into [`SweepRow::COLUMNS`])
/// from `next`, a reader of one value of a chosen type.
trait Next<'de> {
    type Error: de::Error;
    fn next<T: Deserialize<'de>>(&mut self) -> Result<T, Self::Error>;
}

impl Cells {
    /// Reads column `column` with `next`.
    fn read<'de, N: Next<'de>>(&mut self, column: usize, next: &mut N) -> Result<(), N::Error> {
        match column {
            0 => self.index = Some(next.next()?),
            1 => self.model = Some(next.next()?),
            c if c < 2 + AXES => {
                let k = c - 2;
                self.params[k] = Some(if optional(k) {
                    next.next()?
                } else {
                    Some(next.next::<f64>()?)
                });
            }
            c => match c - 2 - AXES {
                0 => self.on_hop = Some(next.next()?),
                1 => self.collision = Some(next.next()?),
                2 => self.stop = next.next()?,
                3 => self.t_s = next.next()?,
                4 => self.x_m = next.next()?,
                5 => self.v_m_s = next.next()?,
                6 => self.a_over_g_sin_alpha = next.next()?,
                7 => self.turns = next.next()?,
                8 => self.error = next.next()?,
                9 => self.warnings = next.next()?,
                _ => next.next::<IgnoredAny>().map(drop)?,
            },
        }
        Ok(())
    }

    /// The row, or the first required column that was not read.
    fn row<E: de::Error>(self) -> Result<SweepRow, E> {
        let missing = |name: &'static str| E::missing_field(name);
        let mut params: AxisValues = [None; AXES];
        for (k, (slot, cell)) in params.iter_mut().zip(self.params).enumerate() {
            *slot = match cell {
                Some(v) => v,
                None if optional(k) => None,
                None => return Err(missing(AxisParam::ALL[k].key_const())),
            };
        }
        Ok(SweepRow {
            index: self.index.ok_or_else(|| missing("index"))?,
            model: self.model.ok_or_else(|| missing("model"))?,
            params,
            on_hop: self.on_hop.ok_or_else(|| missing("on_hop"))?,
            collision: self.collision.ok_or_else(|| missing("collision"))?,
            stop: self.stop,
            t_s: self.t_s,
            x_m: self.x_m,
            v_m_s: self.v_m_s,
            a_over_g_sin_alpha: self.a_over_g_sin_alpha,
            turns: self.turns,
            error: self.error,
            warnings: self.warnings,
        })
    }
}

/// A sequence's next element (a record without a header: every column, in
/// order).
struct SeqNext<A> {
    seq: A,
    column: usize,
}

impl<'de, A: SeqAccess<'de>> Next<'de> for SeqNext<A> {
    type Error = A::Error;
    fn next<T: Deserialize<'de>>(&mut self) -> Result<T, A::Error> {
        self.seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(self.column, &RowVisitor))
    }
}

/// A map's next value (a record under a header: the columns by name).
struct MapNext<'a, A>(&'a mut A);

impl<'de, A: MapAccess<'de>> Next<'de> for MapNext<'_, A> {
    type Error = A::Error;
    fn next<T: Deserialize<'de>>(&mut self) -> Result<T, A::Error> {
        self.0.next_value()
    }
}

/// A column's name, read as its index in [`SweepRow::COLUMNS`] (`None`
/// for a name that is not a column, whose cell is skipped).
struct ColumnName;

impl<'de> DeserializeSeed<'de> for ColumnName {
    type Value = Option<usize>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Option<usize>, D::Error> {
        d.deserialize_str(self)
    }
}

impl Visitor<'_> for ColumnName {
    type Value = Option<usize>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a column name")
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<Option<usize>, E> {
        Ok(SweepRow::COLUMNS.iter().position(|c| *c == v))
    }
    fn visit_bytes<E: de::Error>(self, v: &[u8]) -> Result<Option<usize>, E> {
        Ok(SweepRow::COLUMNS.iter().position(|c| c.as_bytes() == v))
    }
}

/// Reads a [`SweepRow`] from a sequence or a map.
struct RowVisitor;

impl<'de> Visitor<'de> for RowVisitor {
    type Value = SweepRow;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "a sweep row of {} columns", SweepRow::COLUMNS.len())
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<SweepRow, A::Error> {
        let mut cells = Cells::default();
        let mut next = SeqNext { seq, column: 0 };
        for column in 0..SweepRow::COLUMNS.len() {
            next.column = column;
            cells.read(column, &mut next)?;
        }
        cells.row()
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<SweepRow, A::Error> {
        let mut cells = Cells::default();
        while let Some(column) = map.next_key_seed(ColumnName)? {
            let mut next = MapNext(&mut map);
            match column {
                Some(c) => cells.read(c, &mut next)?,
                None => next.next::<IgnoredAny>().map(drop)?,
            }
        }
        cells.row()
    }
}

impl<'de> Deserialize<'de> for SweepRow {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<SweepRow, D::Error> {
        d.deserialize_struct("SweepRow", &SweepRow::COLUMNS, RowVisitor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::{Axis, Grid, Values};

    /// The rows of a small grid with both optional axes set and unset.
    fn rows() -> Vec<SweepRow> {
        let axis = |key: &str, text: &str| Axis {
            param: AxisParam::from_key(key).unwrap(),
            values: Values::parse(key, text).unwrap(),
        };
        let grid = Grid::new(
            vec![ModelKind::Energy],
            vec![axis("alpha_deg", "10,20"), axis("mu", "0.5")],
        )
        .unwrap();
        let mut rows: Vec<SweepRow> = (0..grid.len())
            .map(|i| SweepRow::parameters(&grid.point(i).unwrap()))
            .collect();
        rows[0].t_s = Some(1.5);
        rows[0].stop = Some(StopReason::EndTime);
        rows[1].error = Some("a \"quoted\", error".into());
        rows[1].params[AxisParam::from_key("mu").unwrap().axis_index()] = None;
        rows
    }

    /// The header is the table's keys in place; rows read back equal, with
    /// and without a header (a map, a sequence), and JSON too.
    #[test]
    fn rows_read_back_under_the_table_s_column_names() {
        let rows = rows();
        let mut w = csv::Writer::from_writer(Vec::new());
        for row in &rows {
            w.serialize(row).unwrap();
        }
        let bytes = w.into_inner().unwrap();
        let text = String::from_utf8(bytes.clone()).unwrap();
        assert_eq!(text.lines().next().unwrap(), SweepRow::COLUMNS.join(","));
        assert!(SweepRow::COLUMNS[2..].starts_with(&["alpha_deg", "snow_depth"]));
        let back: Vec<SweepRow> = csv::Reader::from_reader(&bytes[..])
            .deserialize()
            .collect::<Result<_, _>>()
            .unwrap();
        assert_eq!(back, rows);
        let back: Vec<SweepRow> = csv::ReaderBuilder::new()
            .has_headers(false)
            .from_reader(text.split_once('\n').unwrap().1.as_bytes())
            .deserialize()
            .collect::<Result<_, _>>()
            .unwrap();
        assert_eq!(back, rows);
        let json = serde_json::to_string(&rows).unwrap();
        assert!(json.contains("\"alpha_deg\":10.0"), "{json}");
        assert_eq!(serde_json::from_str::<Vec<SweepRow>>(&json).unwrap(), rows);
    }

    /// An axis that is not optional in the table cannot be empty, and a
    /// required column cannot be missing.
    #[test]
    fn a_required_cell_cannot_be_empty_or_missing() {
        let rows = rows();
        let mut w = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(Vec::new());
        w.serialize(&rows[0]).unwrap();
        let line = String::from_utf8(w.into_inner().unwrap()).unwrap();
        let cells: Vec<&str> = line.trim_end().split(',').collect();
        let mut blank = cells.clone();
        blank[2] = "";
        let read = |cells: &[&str]| {
            csv::ReaderBuilder::new()
                .has_headers(false)
                .from_reader(cells.join(",").as_bytes())
                .deserialize::<SweepRow>()
                .next()
                .unwrap()
        };
        assert!(read(&cells).is_ok());
        let e = read(&blank).unwrap_err().to_string();
        assert!(e.contains("field 2"), "{e}");
        let json = r#"{"index": 0, "model": "energy"}"#;
        let e = serde_json::from_str::<SweepRow>(json)
            .unwrap_err()
            .to_string();
        assert!(e.contains("missing field `alpha_deg`"), "{e}");
    }
}
