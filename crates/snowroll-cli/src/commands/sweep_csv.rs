//! The CSV records of sweep rows, byte for byte what `csv::Writer::serialize`
//! writes for a [`SweepRow`], at a fraction of its cost.
//!
//! Serialising goes through serde and formats every number afresh, but in a
//! sweep most columns (the parameters that are not swept, the model, the
//! stop reason) repeat from one row to the next. [`RowWriter`] keeps the
//! text of each column's last value and formats only what changed, with
//! the same formatters the csv crate uses (`ryu` for floats, `itoa` for
//! integers, the serde name for enums) and writes the record's bytes
//! itself; a row with free text (an error) is left to `csv`, which quotes
//! it. A test checks the bytes against `serialize` on rows of every kind.

use serde::Serialize;
use snowroll::sweep::{AxisParam, SweepRow};

/// The text of one column's last value.
struct Last<K> {
    key: Option<K>,
    text: Vec<u8>,
}

impl<K: PartialEq + Copy> Last<K> {
    fn new() -> Self {
        Last {
            key: None,
            text: Vec::new(),
        }
    }

    /// The text of `key`, from `format` when it differs from the last one.
    fn get(&mut self, key: K, format: impl FnOnce(K, &mut Vec<u8>)) -> &[u8] {
        if self.key != Some(key) {
            self.text.clear();
            format(key, &mut self.text);
            self.key = Some(key);
        }
        &self.text
    }
}

/// The numeric axes of a sweep, each a column of its rows.
const AXES: usize = AxisParam::ALL.len();

/// A float as `csv` serialises it (`ryu`).
fn float(bits: u64, out: &mut Vec<u8>) {
    out.extend_from_slice(ryu::Buffer::new().format(f64::from_bits(bits)).as_bytes());
}

/// An optional float: empty for `None`, as `csv` serialises it.
fn opt_float(bits: Option<u64>, out: &mut Vec<u8>) {
    if let Some(bits) = bits {
        float(bits, out);
    }
}

/// A unit enum variant under its serde name, as `csv` serialises it.
fn variant<T: Serialize>(value: T, out: &mut Vec<u8>) {
    if let Ok(serde_json::Value::String(name)) = serde_json::to_value(value) {
        out.extend_from_slice(name.as_bytes());
    }
}

/// Writes [`SweepRow`]s as CSV records, remembering each column's last text.
pub struct RowWriter {
    floats: [Last<Option<u64>>; AXES + 4],
    model: Last<snowroll::ModelKind>,
    on_hop: Last<snowroll::OnHop>,
    collision: Last<snowroll::CollisionModel>,
    stop: Last<Option<snowroll::StopReason>>,
}

impl RowWriter {
    /// A writer with nothing remembered.
    pub fn new() -> Self {
        RowWriter {
            floats: std::array::from_fn(|_| Last::new()),
            model: Last::new(),
            on_hop: Last::new(),
            collision: Last::new(),
            stop: Last::new(),
        }
    }

    /// Appends `row` as one CSV record to `out`.
    ///
    /// A row without an error has no field that needs quoting (numbers,
    /// enum names, empty fields): its fields are written as they are, with
    /// `,` between them and `\n` after, which is what `csv` writes for
    /// them. A row with an error (free text) is serialised by `csv`.
    ///
    /// # Errors
    /// Only from serialising a row with an error.
    pub fn write(&mut self, out: &mut Vec<u8>, row: &SweepRow) -> csv::Result<()> {
        if row.error.is_some() {
            let mut w = csv::WriterBuilder::new()
                .has_headers(false)
                .from_writer(Vec::new());
            w.serialize(row)?;
            out.extend_from_slice(&w.into_inner().map_err(|e| e.into_error())?);
            return Ok(());
        }
        let opt = |v: Option<f64>| v.map(f64::to_bits);
        // The axes' columns in grid order, then the results.
        let mut floats = [None; AXES + 4];
        for (slot, p) in floats.iter_mut().zip(AxisParam::ALL) {
            *slot = opt(row.param_value(p));
        }
        floats[AXES..].copy_from_slice(&[
            opt(row.t_s),
            opt(row.x_m),
            opt(row.v_m_s),
            opt(row.a_over_g_sin_alpha),
        ]);
        let mut field = |text: &[u8]| {
            out.extend_from_slice(text);
            out.push(b',');
        };
        field(itoa::Buffer::new().format(row.index).as_bytes());
        field(self.model.get(row.model, variant));
        let (params, results) = floats.split_at(AXES);
        let (params_text, results_text) = self.floats.split_at_mut(AXES);
        for (&v, last) in params.iter().zip(params_text) {
            field(last.get(v, opt_float));
        }
        field(self.on_hop.get(row.on_hop, variant));
        field(self.collision.get(row.collision, variant));
        field(self.stop.get(row.stop, |s, out| {
            if let Some(s) = s {
                variant(s, out);
            }
        }));
        for (&v, last) in results.iter().zip(results_text) {
            field(last.get(v, opt_float));
        }
        if let Some(k) = row.turns {
            field(itoa::Buffer::new().format(k).as_bytes());
        } else {
            field(&[]);
        }
        // The error column is empty; the warnings' codes need no quoting
        // (kebab-case words and `;`).
        field(&[]);
        out.extend_from_slice(row.warnings.as_deref().unwrap_or_default().as_bytes());
        out.push(b'\n');
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use snowroll::sweep::{Axis, AxisParam, Grid, Method, Values};
    use snowroll::{CollisionModel, ModelKind, OnHop, StopReason};

    fn serialized(rows: &[SweepRow]) -> Vec<u8> {
        let mut w = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(Vec::new());
        for row in rows {
            w.serialize(row).unwrap();
        }
        w.into_inner().unwrap()
    }

    fn written(rows: &[SweepRow]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut r = RowWriter::new();
        for row in rows {
            r.write(&mut out, row).unwrap();
        }
        out
    }

    /// Rows of a real sweep (every model; runs that end, do not start, hop),
    /// then the same rows with every enum variant, missing values, awkward
    /// floats and errors that need quoting: the bytes are serde's.
    #[test]
    fn rows_are_the_bytes_serialize_writes() {
        let axis = |param, text: &str| Axis {
            param,
            values: Values::parse(param.key(), text).unwrap(),
        };
        let grid = Grid::new(
            ModelKind::ALL.to_vec(),
            vec![
                axis(AxisParam::named("alpha_deg"), "1,30,80"),
                axis(AxisParam::named("v0"), "0,150"),
                axis(AxisParam::named("t_end"), "2"),
            ],
        )
        .unwrap();
        let mut rows: Vec<SweepRow> = (0..grid.len())
            .map(|i| snowroll::sweep::run_point(&grid, i, Method::Auto).unwrap())
            .collect();
        assert_eq!(written(&rows), serialized(&rows));

        let base = rows[0].clone();
        let stops = [
            None,
            Some(StopReason::EndTime),
            Some(StopReason::Distance),
            Some(StopReason::Turns),
            Some(StopReason::Stalled),
            Some(StopReason::DoesNotStart),
            Some(StopReason::Hop),
            Some(StopReason::Slip),
            Some(StopReason::Stuck),
            Some(StopReason::StepLimit),
            Some(StopReason::RowLimit),
            Some(StopReason::Terminal),
        ];
        let floats = [
            0.0,
            -0.0,
            1e-300,
            5e-324,
            f64::MAX,
            f64::NAN,
            f64::INFINITY,
            -f64::INFINITY,
            0.1,
            123456789.0,
            1e21,
            1e-7,
        ];
        for (k, &stop) in stops.iter().enumerate() {
            for (j, &f) in floats.iter().enumerate() {
                let mut r = base.clone();
                r.index = (k * 100 + j) as u64;
                r.stop = stop;
                let mut set = |key: &str, v: Option<f64>| {
                    r.params[AxisParam::named(key).axis_index()] = v;
                };
                set("alpha_deg", Some(f));
                set("snow_depth", Some(-f));
                set("x_end", (j % 2 == 0).then_some(f));
                set("mu", (j % 3 == 0).then_some(f));
                r.t_s = (j % 2 == 1).then_some(f);
                r.a_over_g_sin_alpha = Some(f);
                r.turns = (j % 2 == 0).then_some(j as u64);
                r.on_hop = if j % 2 == 0 {
                    OnHop::Stop
                } else {
                    OnHop::Continue
                };
                r.collision = [
                    CollisionModel::Note,
                    CollisionModel::Charged,
                    CollisionModel::Pivot,
                ][j % 3];
                r.warnings = match j % 3 {
                    0 => None,
                    1 => Some("b-over-r0".into()),
                    _ => Some("b-over-r0;loose-tolerance".into()),
                };
                r.error = match j % 4 {
                    0 => None,
                    1 => Some("plain".into()),
                    2 => Some("with, comma and \"quotes\"".into()),
                    _ => Some("two\nlines".into()),
                };
                rows.push(r);
            }
        }
        assert_eq!(written(&rows), serialized(&rows));
    }
}
