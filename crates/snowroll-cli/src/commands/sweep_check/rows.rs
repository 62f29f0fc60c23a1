//! The rows of a sweep file read back: each parsed against the schema,
//! its spelling held to the one the sweep writes, and its parameters held
//! to the grid point its index names ([`check_rows`]).

use super::*;

/// Checks the column line against [`SweepRow::COLUMNS`].
pub(super) fn check_columns(line: &str, shown: &str) -> Result<()> {
    let names: Vec<&str> = line.split(',').collect();
    let want = &SweepRow::COLUMNS;
    if names.len() < want.len() && want.starts_with(&names) {
        bail!(
            "{shown}: has no column {} (a sweep of an older snowroll, whose rows cannot be \
             checked against this one's): run the sweep again",
            want[names.len()..].join(", ")
        );
    }
    for (k, want) in SweepRow::COLUMNS.iter().enumerate() {
        match names.get(k) {
            Some(name) if name == want => {}
            Some(name) => bail!(
                "{shown}: column {} is {name:?} where a sweep has {want:?}",
                k + 1
            ),
            None => bail!(
                "{shown}: {} columns where a sweep has {}",
                names.len(),
                SweepRow::COLUMNS.len()
            ),
        }
    }
    if names.len() != SweepRow::COLUMNS.len() {
        bail!(
            "{shown}: {} columns where a sweep has {}",
            names.len(),
            SweepRow::COLUMNS.len()
        );
    }
    Ok(())
}

/// Reads the rows from `input` to its end, and checks that they are rows
/// `rows.start`, `rows.start + 1`, ... in order (no gap, no repeat, none
/// past `rows.end`), each a whole line, each cell of its column's type and
/// finite, and each row's parameters those of the grid point its index
/// names. `line` is the file's line number of the first row. Each line is
/// handed to `each` once checked. Returns the index after the last row.
///
/// # Errors
/// The first bad row, with its line number and what is wrong with it.
pub fn check_rows(
    input: &mut impl BufRead,
    grid: &Grid,
    rows: &Range<u64>,
    mut line: u64,
    shown: &str,
    mut each: impl FnMut(&[u8], &SweepRow) -> Result<()>,
) -> Result<u64> {
    let mut next = rows.start;
    let mut buf = Vec::new();
    let mut canonical = Vec::new();
    let mut writer = RowWriter::new();
    loop {
        buf.clear();
        let n = (&mut *input)
            .take(MAX_ROW_LINE + 1)
            .read_until(b'\n', &mut buf)
            .with_context(|| format!("reading {shown}"))?;
        if n == 0 {
            return Ok(next);
        }
        if buf.last() != Some(&b'\n') {
            if n as u64 > MAX_ROW_LINE {
                bail!(
                    "{shown}: line {line} is longer than {} MiB, the most snowroll reads of one sweep row",
                    MAX_ROW_LINE >> 20
                );
            }
            bail!(
                "{shown}: line {line}, its last, is cut short (an interrupted sweep? finish it \
                 with --resume)"
            );
        }
        let row = parse_row(&buf).map_err(|e| anyhow!("{shown}: line {line}: {e}"))?;
        if row.index != next || next >= rows.end {
            let what = if row.index < next {
                "repeats an earlier row"
            } else if next >= rows.end {
                "is past the rows of its shard"
            } else {
                "leaves a gap"
            };
            bail!(
                "{shown}: line {line}: row {} where row {next} of {rows:?} was expected (it {what})",
                row.index
            );
        }
        check_point(&row, grid).map_err(|e| anyhow!("{shown}: line {line}: {e}"))?;
        // The row must be spelt as snowroll writes it: the line is copied
        // as it is, so `1.00` for `1` or a needlessly quoted cell would
        // change the output's bytes (issue 33, item 5).
        canonical.clear();
        writer
            .write(&mut canonical, &row)
            .with_context(|| format!("{shown}: line {line}"))?;
        if canonical != buf {
            bail!(
                "{shown}: line {line}: row {} is not spelt as snowroll writes it ({}): an \
                 edited file is refused, as the edit would pass into the output",
                row.index,
                spelling_difference(&buf, &canonical)
            );
        }
        each(&buf, &row)?;
        next += 1;
        line += 1;
    }
}

/// Where `got` and `want` (two lines) first differ, as the text around it
/// in each: "`,1.00,` where snowroll writes `,1,`".
pub(super) fn spelling_difference(got: &[u8], want: &[u8]) -> String {
    /// Bytes shown on each side of the first difference.
    const AROUND: usize = 16;
    let at = got.iter().zip(want).take_while(|(a, b)| a == b).count();
    let show = |line: &[u8]| {
        let line = line.strip_suffix(b"\n").unwrap_or(line);
        let lo = at.saturating_sub(AROUND).min(line.len());
        let hi = (at + AROUND).min(line.len());
        String::from_utf8_lossy(&line[lo..hi]).into_owned()
    };
    format!("`{}` where snowroll writes `{}`", show(got), show(want))
}

/// At most 120 characters of `text`, for messages.
pub(super) fn cut(text: &str) -> String {
    /// Characters of a line shown in a message.
    const SHOWN: usize = 120;
    match text.char_indices().nth(SHOWN) {
        Some((i, _)) => format!("{}...", &text[..i]),
        None => text.to_string(),
    }
}

/// One line parsed as a [`SweepRow`]: the column count, each cell by its
/// column's type, every number finite.
pub(super) fn parse_row(line: &[u8]) -> Result<SweepRow, String> {
    let line = line.strip_suffix(b"\n").unwrap_or(line);
    if line.last() == Some(&b'\r') {
        return Err("the line ends in a carriage return: not a line of a sweep file".to_string());
    }
    let record = if line.contains(&b'"') {
        // Quoting (an error message): the csv crate's parser. Building one
        // costs as much as a hundred rows, so plain rows are split here.
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .from_reader(line);
        let mut record = csv::ByteRecord::new();
        match reader.read_byte_record(&mut record) {
            Ok(true) if reader.position().byte() == line.len() as u64 => record,
            Ok(true) => return Err("more than one record on the line".to_string()),
            Ok(false) => return Err("an empty line where a row was expected".to_string()),
            Err(e) => return Err(format!("not a CSV record: {e}")),
        }
    } else {
        csv::ByteRecord::from(line.split(|&c| c == b',').collect::<Vec<_>>())
    };
    let columns = &SweepRow::COLUMNS;
    if record.len() != columns.len() {
        return Err(format!(
            "{} cells where a row has {}",
            record.len(),
            columns.len()
        ));
    }
    let row: SweepRow = record.deserialize(None).map_err(|e| match e.kind() {
        csv::ErrorKind::Deserialize { err, .. } => {
            let column = err.field().and_then(|k| columns.get(k as usize));
            let cell = err
                .field()
                .and_then(|k| record.get(k as usize))
                .map(String::from_utf8_lossy)
                .unwrap_or_default();
            format!(
                "column {}: cannot read {cell:?}: {}",
                column.unwrap_or(&"?"),
                err.kind()
            )
        }
        _ => e.to_string(),
    })?;
    snowroll_io::check_finite(&row, None)
        .map_err(|e| format!("column {}: {} is not a finite number", e.field, e.value))?;
    // A run that ended has every result and no error; one that failed has
    // an error and no result (`SweepRow::new`).
    let results = row.results();
    // On a level floor (α = 0, the unwinding roll) a/(g sin α) is empty.
    let level = row.param_value(const { AxisParam::named("alpha_deg") }) == Some(0.0);
    let ended = row.stop.is_some()
        && row.turns.is_some()
        && results
            .iter()
            .all(|(name, v)| v.is_some() || (level && *name == "a_over_g_sin_alpha"));
    let failed = row.stop.is_none() && row.turns.is_none() && results.iter().all(|r| r.1.is_none());
    match (row.error.is_some(), ended, failed) {
        (false, true, _) | (true, _, true) => Ok(row),
        (false, ..) => Err("a result cell is empty, and the error cell too".to_string()),
        (true, ..) => Err("an error cell with results: a failed run has none".to_string()),
    }
}

/// Checks that `row`'s model, choices and parameters are those of the grid
/// point its index names.
pub(super) fn check_point(row: &SweepRow, grid: &Grid) -> Result<(), String> {
    let point = grid.point(row.index).map_err(|e| {
        format!(
            "row {} is not a point of the grid ({} points): {e}",
            row.index,
            grid.len()
        )
    })?;
    let want = SweepRow::parameters(&point);
    let differs = |what: String, have: String, want: String| {
        format!(
            "row {} has {what} = {have} where point {} of the grid has {want}",
            row.index, row.index
        )
    };
    if row.model != want.model {
        return Err(differs(
            "model".into(),
            row.model.id().into(),
            want.model.id().into(),
        ));
    }
    if row.collision != want.collision {
        let (a, b) = (row.collision.id(), want.collision.id());
        return Err(differs("collision".into(), a.into(), b.into()));
    }
    if row.on_hop != want.on_hop {
        let (a, b) = (row.on_hop.id(), want.on_hop.id());
        return Err(differs("on_hop".into(), a.into(), b.into()));
    }
    if row.warnings != want.warnings {
        let text = |w: &Option<String>| w.clone().unwrap_or_else(|| "none".to_string());
        return Err(differs(
            "warnings".into(),
            text(&row.warnings),
            text(&want.warnings),
        ));
    }
    for p in AxisParam::ALL {
        let (a, b) = (row.param_value(p), want.param_value(p));
        if a.map(f64::to_bits) != b.map(f64::to_bits) {
            let text = |v: Option<f64>| v.map_or("none".to_string(), |x| x.to_string());
            return Err(differs(p.key().into(), text(a), text(b)));
        }
    }
    Ok(())
}
