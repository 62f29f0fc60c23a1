//! A measured trajectory read from text: a CSV file with a time and a
//! distance column, or the table the video-analysis tool Tracker (Open
//! Source Physics) exports, whose first line names the tracked mass
//! (`mass A`) above a header (`t`, `x`, `y`, …) and the numbers, separated
//! by tabs, commas, semicolons or spaces.
//!
//! Columns: `t`, `t_s` or `time` for the time and `x`, `x_m` or `distance`
//! for the distance along the slope (any case), or the two names given.
//! Units are seconds and metres unless the header states one, as
//! `t (s)`, `x [cm]` or a suffix `x_cm`: time in s or ms, distance in m, cm
//! or mm. Every error names the line.

use thiserror::Error;

/// A bad measured file: what is wrong and where.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrackError {
    /// A problem on one line (counted from 1).
    #[error("line {line}: {message}")]
    Line {
        /// The line, from 1.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A problem of the whole file.
    #[error("{0}")]
    File(String),
}

/// The file as read: the name on Tracker's first line, if any, the two
/// columns' headers, and the points in seconds and metres with the line
/// each came from.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredTrack {
    /// Tracker's first line (`mass A`), or `None` for a plain CSV file.
    pub name: Option<String>,
    /// The time and distance columns' headers, as written.
    pub columns: (String, String),
    /// Times, s.
    pub t: Vec<f64>,
    /// Distances, m.
    pub x: Vec<f64>,
    /// The line of each point, from 1.
    pub lines: Vec<usize>,
}

/// The names a time column may have, before any unit.
pub const TIME_NAMES: [&str; 2] = ["t", "time"];
/// The names a distance column may have, before any unit.
pub const DISTANCE_NAMES: [&str; 2] = ["x", "distance"];
/// Fewest points a file may have.
pub const MIN_POINTS: usize = snowroll::fit::MIN_POINTS;

/// One header cell: its name (lower case, without the unit) and the factor
/// to SI of its unit, `None` for a unit this reader does not know.
fn header_cell(cell: &str, time: bool) -> (String, Option<f64>, String) {
    let cell = cell.trim().trim_matches('"').trim();
    let (name, unit) = match cell.find(['(', '[']) {
        Some(i) => {
            let unit = cell[i + 1..].trim_end_matches([')', ']']).trim();
            (cell[..i].trim(), Some(unit.to_string()))
        }
        None => match cell.rsplit_once('_') {
            Some((name, unit)) if factor(unit, time).is_some() => (name, Some(unit.to_string())),
            _ => (cell, None),
        },
    };
    let unit = unit.unwrap_or_else(|| if time { "s" } else { "m" }.to_string());
    (name.to_ascii_lowercase(), factor(&unit, time), unit)
}

/// The factor from `unit` to s (time) or m (distance).
fn factor(unit: &str, time: bool) -> Option<f64> {
    match (time, unit.to_ascii_lowercase().as_str()) {
        (true, "s") => Some(1.0),
        (true, "ms") => Some(1e-3),
        (false, "m") => Some(1.0),
        (false, "cm") => Some(1e-2),
        (false, "mm") => Some(1e-3),
        _ => None,
    }
}

/// Splits a line on the file's separator.
fn cells(line: &str, sep: Option<char>) -> Vec<&str> {
    match sep {
        Some(c) => line.split(c).map(str::trim).collect(),
        None => line.split_whitespace().collect(),
    }
}

/// Reads `text`. `columns`, when given, names the time and distance
/// columns (as in the header, without the unit).
///
/// # Errors
/// [`TrackError`] naming the line: no header with a time and a distance
/// column, a cell that is not a finite number, a time not after the one
/// before, fewer than [`MIN_POINTS`] points.
pub fn read_track(text: &str, columns: Option<(&str, &str)>) -> Result<MeasuredTrack, TrackError> {
    let lines: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim_end_matches('\r')))
        .filter(|(_, l)| !l.trim().is_empty())
        .collect();
    if let Some((n, _)) = lines
        .iter()
        .find(|(_, l)| l.trim_start().starts_with("#multi"))
    {
        return Err(TrackError::Line {
            line: *n,
            message: "a Tracker table of several tracks: export one track (one mass) at a time"
                .into(),
        });
    }
    let (k, header_line, sep, heads, ti, xi) = find_header(&lines, columns)?;
    let name = (k == 1).then(|| lines[0].1.trim().to_string());
    let (_, t_factor, t_unit) = header_cell(&heads[ti], true);
    let (_, x_factor, x_unit) = header_cell(&heads[xi], false);
    let t_factor = t_factor.ok_or_else(|| TrackError::Line {
        line: header_line,
        message: format!(
            "column {}: unknown time unit {t_unit:?} (s or ms)",
            heads[ti]
        ),
    })?;
    let x_factor = x_factor.ok_or_else(|| TrackError::Line {
        line: header_line,
        message: format!(
            "column {}: unknown distance unit {x_unit:?} (m, cm or mm)",
            heads[xi]
        ),
    })?;
    let mut track = MeasuredTrack {
        name,
        columns: (heads[ti].clone(), heads[xi].clone()),
        t: Vec::new(),
        x: Vec::new(),
        lines: Vec::new(),
    };
    for &(n, line) in &lines[k + 1..] {
        let row = cells(line, sep);
        let t = number(&row, ti, &heads[ti], n, sep)? * t_factor;
        let x = number(&row, xi, &heads[xi], n, sep)? * x_factor;
        if let (Some(&before), Some(&m)) = (track.t.last(), track.lines.last()) {
            if t <= before {
                return Err(TrackError::Line {
                    line: n,
                    message: format!(
                        "time {} s is not after the time on line {m} ({} s): times must increase",
                        row[ti], before
                    ),
                });
            }
        }
        track.t.push(t);
        track.x.push(x);
        track.lines.push(n);
    }
    if track.t.len() < MIN_POINTS {
        return Err(TrackError::File(format!(
            "{} data lines under the header: a fit needs at least {MIN_POINTS}",
            track.t.len()
        )));
    }
    Ok(track)
}

/// The header found: its index among the non-empty lines (0, or 1 under
/// Tracker's name of the mass), its line, the separator, its cells, and
/// the time and distance columns.
type Header = (usize, usize, Option<char>, Vec<String>, usize, usize);

/// The header: the first of the first two non-empty lines with both
/// columns.
fn find_header(
    lines: &[(usize, &str)],
    columns: Option<(&str, &str)>,
) -> Result<Header, TrackError> {
    let wanted = |name: &str, names: &[&str], given: Option<&str>| match given {
        Some(g) => name == g.to_ascii_lowercase(),
        None => names.contains(&name),
    };
    // The header: the first of the first two lines with both columns
    // (a line above it is Tracker's name of the mass).
    let mut found = None;
    for (k, &(n, line)) in lines.iter().take(2).enumerate() {
        let sep = ['\t', ',', ';'].into_iter().find(|c| line.contains(*c));
        let heads = cells(line, sep);
        let t = heads
            .iter()
            .position(|h| wanted(&header_cell(h, true).0, &TIME_NAMES, columns.map(|c| c.0)));
        let x = heads.iter().position(|h| {
            wanted(
                &header_cell(h, false).0,
                &DISTANCE_NAMES,
                columns.map(|c| c.1),
            )
        });
        if let (Some(t), Some(x)) = (t, x) {
            found = Some((
                k,
                n,
                sep,
                heads.iter().map(|h| h.to_string()).collect::<Vec<_>>(),
                t,
                x,
            ));
            break;
        }
    }
    found.ok_or_else(|| {
        let (t, x) = columns.unwrap_or(("t, t_s or time", "x, x_m or distance"));
        TrackError::File(format!(
            "no header naming a time column ({t}) and a distance column ({x}) on the first line, \
             or on the second under Tracker's name of the mass: add one, or name the columns with \
             --columns TIME,DISTANCE"
        ))
    })
}

/// The number in cell `i` of `row`, finite; a comma as the decimal mark is
/// read where the separator is not a comma (Tracker in some languages).
fn number(
    row: &[&str],
    i: usize,
    head: &str,
    line: usize,
    sep: Option<char>,
) -> Result<f64, TrackError> {
    let err = |message: String| TrackError::Line { line, message };
    let cell = row
        .get(i)
        .map(|c| c.trim().trim_matches('"'))
        .filter(|c| !c.is_empty())
        .ok_or_else(|| {
            err(format!(
                "no value in column {head} (an untracked frame? delete the line)"
            ))
        })?;
    let text = if sep != Some(',') && cell.contains(',') && !cell.contains('.') {
        cell.replace(',', ".")
    } else {
        cell.to_string()
    };
    let v: f64 = text
        .parse()
        .map_err(|_| err(format!("column {head}: {cell:?} is not a number")))?;
    if !v.is_finite() {
        return Err(err(format!("column {head}: {cell} is not a finite number")));
    }
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tracker_s_table_with_the_mass_name_reads() {
        let text = "mass A\nt\tx\ty\n0.000000000E0\t1.2E-1\t0\n3.3E-2\t1.25E-1\t0\n\
                    6.7E-2\t1.3E-1\t0\n1.0E-1\t1.4E-1\t0\n1.33E-1\t1.5E-1\t0\n";
        let t = read_track(text, None).unwrap();
        assert_eq!(t.name.as_deref(), Some("mass A"));
        assert_eq!(t.t.len(), 5);
        assert_eq!(t.lines[0], 3);
        assert!((t.x[4] - 0.15).abs() < 1e-15);
    }

    #[test]
    fn units_in_the_header_are_converted() {
        let text = "time (ms),x [cm]\n0,0\n100,1\n200,4\n300,9\n400,16\n";
        let t = read_track(text, None).unwrap();
        assert!((t.t[1] - 0.1).abs() < 1e-15 && (t.x[4] - 0.16).abs() < 1e-15);
        let t = read_track("t_s;x_mm\n0;0\n1;1\n2;2\n3;3\n4;4\n", None).unwrap();
        assert!((t.x[4] - 0.004).abs() < 1e-15);
        let t = read_track("t\tx\n0\t0\n0,5\t1,5\n1\t2\n1,5\t3\n2\t4\n", None).unwrap();
        assert!((t.x[1] - 1.5).abs() < 1e-15, "decimal comma under tabs");
    }

    #[test]
    fn bad_files_name_the_line() {
        let cases = [
            ("t,x\n0,0\n1,1\n0.5,2\n2,3\n3,4\n", "line 4"),
            ("t,x\n0,0\n1,NaN\n2,2\n3,3\n4,4\n", "line 3"),
            ("t,x\n0,0\n1,abc\n2,2\n3,3\n4,4\n", "line 3"),
            ("t,x\n0,0\n1,\n2,2\n3,3\n4,4\n", "line 3"),
            ("t,x\n0,0\n1,1\n", "at least 5"),
            ("a,b\n0,0\n", "no header"),
            ("t (h),x\n0,0\n", "unknown time unit"),
            ("#multi:\n\tmass A\t\n", "several tracks"),
        ];
        for (text, want) in cases {
            let err = read_track(text, None).unwrap_err().to_string();
            assert!(err.contains(want), "{text:?}: {err}");
        }
        let t = read_track("secs,pos\n0,0\n1,1\n2,2\n3,3\n4,4\n", Some(("secs", "pos"))).unwrap();
        assert_eq!(t.t.len(), 5);
    }
}
