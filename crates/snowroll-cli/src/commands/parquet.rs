//! Parquet output of `snowroll sweep` (cargo feature `parquet`): the rows of
//! the finished partial CSV file, read back a batch at a time (memory stays
//! bounded), as one Arrow column per [`SweepRow`] field, with the CSV
//! header's `# key: value` lines as key-value metadata (`snowroll.key`).

use std::io::{Read, Write};
use std::sync::Arc;

use anyhow::{Context, Result};
use arrow_array::{ArrayRef, Float64Array, RecordBatch, StringArray, UInt64Array};
use arrow_schema::{DataType, Field, Schema};
use parquet::arrow::ArrowWriter;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use snowroll::params::Kind;
use snowroll::sweep::{AxisParam, SweepRow};

/// Rows per record batch (and per read of the CSV).
const BATCH_ROWS: usize = 65_536;

/// The Arrow schema: [`SweepRow::COLUMNS`] in order; results nullable.
pub fn schema() -> Schema {
    let required = |name: &str, t: DataType| Field::new(name, t, false);
    let nullable = |name: &str, t: DataType| Field::new(name, t, true);
    let mut fields = vec![
        required("index", DataType::UInt64),
        required("model", DataType::Utf8),
    ];
    // The numeric axes, in grid order; those a run may leave unset
    // (optional in the parameter table: `x_end`, `mu`) nullable.
    for p in AxisParam::ALL {
        fields.push(Field::new(p.key(), DataType::Float64, is_optional(p)));
    }
    fields.push(required("on_hop", DataType::Utf8));
    fields.push(required("collision", DataType::Utf8));
    fields.push(nullable("stop", DataType::Utf8));
    for name in ["t_s", "x_m", "v_m_s", "a_over_g_sin_alpha"] {
        fields.push(nullable(name, DataType::Float64));
    }
    fields.push(nullable("turns", DataType::UInt64));
    fields.push(nullable("error", DataType::Utf8));
    fields.push(nullable("warnings", DataType::Utf8));
    Schema::new(fields)
}

/// Whether a run may leave axis `p` unset (an optional number of the
/// parameter table: `x_end`, `mu`), so that its column is nullable.
fn is_optional(p: AxisParam) -> bool {
    snowroll::Param::of_key(p.key()).is_some_and(|q| q.kind == Kind::OptionalReal)
}

/// The header's `# key: value` lines as metadata: the first line
/// (`# snowroll sweep, version V`) as `snowroll.version = V`.
fn metadata(header: &str) -> Vec<KeyValue> {
    header
        .lines()
        .filter_map(|l| l.strip_prefix("# "))
        .filter_map(|l| {
            if let Some(v) = l.strip_prefix("snowroll sweep, version ") {
                return Some(("version", v));
            }
            l.split_once(": ")
        })
        .map(|(k, v)| KeyValue::new(format!("snowroll.{k}"), v.to_string()))
        .collect()
}

/// The kebab-case name of a serde unit variant (a stop reason).
fn name(v: &impl serde::Serialize) -> Option<String> {
    match serde_json::to_value(v).ok()? {
        serde_json::Value::String(s) => Some(s),
        _ => None,
    }
}

/// One record batch of `rows`.
fn batch(schema: &Arc<Schema>, rows: &[SweepRow]) -> Result<RecordBatch> {
    let opt = |get: fn(&SweepRow) -> Option<f64>| -> ArrayRef {
        Arc::new(Float64Array::from(rows.iter().map(get).collect::<Vec<_>>()))
    };
    let mut columns: Vec<ArrayRef> = vec![
        Arc::new(UInt64Array::from(
            rows.iter().map(|r| r.index).collect::<Vec<_>>(),
        )),
        Arc::new(StringArray::from(
            rows.iter().map(|r| r.model.id()).collect::<Vec<_>>(),
        )),
    ];
    for p in AxisParam::ALL {
        let column: ArrayRef = if is_optional(p) {
            Arc::new(Float64Array::from(
                rows.iter().map(|r| r.param_value(p)).collect::<Vec<_>>(),
            ))
        } else {
            Arc::new(Float64Array::from(
                rows.iter().map(|r| r.param(p)).collect::<Vec<_>>(),
            ))
        };
        columns.push(column);
    }
    let rest: [ArrayRef; 10] = [
        Arc::new(StringArray::from(
            rows.iter().map(|r| r.on_hop.id()).collect::<Vec<_>>(),
        )),
        Arc::new(StringArray::from(
            rows.iter().map(|r| r.collision.id()).collect::<Vec<_>>(),
        )),
        Arc::new(StringArray::from(
            rows.iter()
                .map(|r| r.stop.as_ref().and_then(name))
                .collect::<Vec<_>>(),
        )),
        opt(|r| r.t_s),
        opt(|r| r.x_m),
        opt(|r| r.v_m_s),
        opt(|r| r.a_over_g_sin_alpha),
        Arc::new(UInt64Array::from(
            rows.iter().map(|r| r.turns).collect::<Vec<_>>(),
        )),
        Arc::new(StringArray::from(
            rows.iter().map(|r| r.error.clone()).collect::<Vec<_>>(),
        )),
        Arc::new(StringArray::from(
            rows.iter().map(|r| r.warnings.clone()).collect::<Vec<_>>(),
        )),
    ];
    columns.extend(rest);
    Ok(RecordBatch::try_new(Arc::clone(schema), columns)?)
}

/// Writes the rows of the sweep CSV `csv` (header included) as Parquet to
/// `out`, and returns `out` (to be committed).
pub fn write<W: Write + Send>(csv: impl Read, header: &str, out: W) -> Result<W> {
    let schema = Arc::new(schema());
    let props = WriterProperties::builder()
        .set_key_value_metadata(Some(metadata(header)))
        .build();
    let mut writer = ArrowWriter::try_new(out, Arc::clone(&schema), Some(props))?;
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(csv);
    let mut rows = Vec::with_capacity(BATCH_ROWS);
    for row in reader.deserialize::<SweepRow>() {
        rows.push(row.context("reading back the rows")?);
        if rows.len() == BATCH_ROWS {
            writer.write(&batch(&schema, &rows)?)?;
            rows.clear();
        }
    }
    if !rows.is_empty() {
        writer.write(&batch(&schema, &rows)?)?;
    }
    // Flushes the last row group and writes the footer.
    Ok(writer.into_inner()?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schema_has_the_csv_columns_in_order() {
        let names: Vec<String> = schema().fields().iter().map(|f| f.name().clone()).collect();
        assert_eq!(names, SweepRow::COLUMNS);
    }

    #[test]
    fn header_lines_become_metadata() {
        let kv = metadata("# snowroll sweep, version 1.2.3\n# command: snowroll sweep --x 1\n# alpha_deg: 5:60:12\nindex,model\n");
        let pairs: Vec<(String, Option<String>)> =
            kv.into_iter().map(|k| (k.key, k.value)).collect();
        assert_eq!(
            pairs,
            [
                ("snowroll.version", "1.2.3"),
                ("snowroll.command", "snowroll sweep --x 1"),
                ("snowroll.alpha_deg", "5:60:12"),
            ]
            .map(|(k, v)| (k.to_string(), Some(v.to_string())))
        );
    }
}
