//! From sweep rows to a map's pieces: the axis of each swept parameter, the
//! cell edges around its values, the classes (outcomes or bins of a column)
//! that colour the cells, and one cell per row.

use super::super::ticks::AxisTicks;
use super::super::Axis;
use super::{Cell, Class, ColorBy, MapError};
use snowroll::sweep::{AxisParam, Outcome, SweepRow};

/// Fill colours of the outcomes (colour-blind aware, stalls in shades of
/// one hue by turn).
fn outcome_rgb(o: Outcome) -> (u8, u8, u8) {
    match o {
        Outcome::NeverStarts => (120, 120, 120),
        Outcome::Stalls { turn } => {
            let shade = (turn.min(6) * 22) as u8;
            (200u8.saturating_sub(shade / 2), 150 + shade / 2, 230)
        }
        Outcome::RollsOn => (166, 219, 160),
        Outcome::Hops => (253, 174, 97),
        Outcome::Slips => (215, 48, 39),
        Outcome::Stuck => (118, 42, 131),
        Outcome::Failed => (0, 0, 0),
    }
}

/// Seven steps of a sequential colour scale (viridis), low to high.
const SCALE: [(u8, u8, u8); 7] = [
    (68, 1, 84),
    (68, 57, 131),
    (49, 104, 142),
    (33, 145, 140),
    (53, 183, 121),
    (144, 215, 67),
    (253, 231, 37),
];

/// The axis of a parameter: label and unit of its row in the parameter
/// table (`plot`), logarithmic when
/// its values are positive and span two decades or more.
pub(super) fn param_axis(p: AxisParam, values: &[f64]) -> Axis {
    let (label, unit) = p.spec().plot;
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let axis = if lo > 0.0 && hi / lo >= 100.0 {
        Axis::log(label, unit)
    } else {
        Axis::linear(label, unit)
    };
    axis.column(p.key())
}

/// The edges of the cells around sorted distinct `values`: halfway between
/// neighbours (geometric mean on a log axis), the outer cells as wide as
/// their inner neighbours.
pub(super) fn edges(values: &[f64], log: bool) -> Vec<f64> {
    let mid = |a: f64, b: f64| if log { (a * b).sqrt() } else { 0.5 * (a + b) };
    let mut e = Vec::with_capacity(values.len() + 1);
    let n = values.len();
    let outer = |v: f64, inner: f64| if log { v * v / inner } else { 2.0 * v - inner };
    e.push(outer(values[0], mid(values[0], values[1])));
    for w in values.windows(2) {
        e.push(mid(w[0], w[1]));
    }
    e.push(outer(values[n - 1], mid(values[n - 2], values[n - 1])));
    e
}

/// Sorted distinct values (bit-exact, as the grid produced them).
pub(super) fn distinct(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| a.to_bits() == b.to_bits());
    v
}

/// The classes of the map coloured by `color`, in legend order, and the
/// class of each row.
pub(super) fn classes_of(rows: &[SweepRow], color: ColorBy) -> (Vec<Class>, Vec<usize>) {
    if color == ColorBy::Outcome {
        outcome_classes(rows)
    } else {
        value_classes(rows, color)
    }
}

/// One class per outcome that occurs, in the outcomes' order.
fn outcome_classes(rows: &[SweepRow]) -> (Vec<Class>, Vec<usize>) {
    let mut outcomes: Vec<Outcome> = rows.iter().map(Outcome::of).collect();
    outcomes.sort();
    outcomes.dedup();
    let classes = outcomes
        .iter()
        .map(|o| Class {
            label: o.to_string(),
            rgb: outcome_rgb(*o),
        })
        .collect();
    let mut class_of_row: Vec<usize> = Vec::with_capacity(rows.len());
    for r in rows {
        let o = Outcome::of(r);
        class_of_row.push(outcomes.iter().position(|u| *u == o).unwrap_or(0));
    }
    (classes, class_of_row)
}

/// Up to [`SCALE`]`.len()` equal bins of the column `color` with round
/// edges (a step of 1, 2, 2.5 or 5 times a power of ten) covering its
/// smallest to largest value (one bin when all are equal), and a last class
/// for the rows without a value. Labels name the quantity and its unit.
fn value_classes(rows: &[SweepRow], color: ColorBy) -> (Vec<Class>, Vec<usize>) {
    let mut classes: Vec<Class> = Vec::new();
    let mut class_of_row: Vec<usize> = Vec::with_capacity(rows.len());
    let values: Vec<Option<f64>> = rows.iter().map(|r| color.value(r)).collect();
    let (lo, hi) = values
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let (_, sym, unit) = color.quantity().unwrap_or(("", "value", "1"));
    let unit = if unit == "1" {
        String::new()
    } else {
        format!(" {unit}")
    };
    let (start, width, bins) = round_bins(lo, hi, SCALE.len());
    let edges: Vec<f64> = (0..=bins).map(|k| start + width * k as f64).collect();
    let fmt = AxisTicks::new(&edges, edges[bins] - edges[0], false);
    for (k, rgb) in SCALE.iter().enumerate().take(bins) {
        let label = if lo >= hi {
            format!(
                "{sym} = {}{unit}",
                AxisTicks::new(&[lo], lo.abs(), false).label(lo)
            )
        } else {
            format!(
                "{} ≤ {sym} < {}{unit}",
                fmt.label(edges[k]),
                fmt.label(edges[k + 1])
            )
        };
        classes.push(Class { label, rgb: *rgb });
    }
    let none = classes.len();
    classes.push(Class {
        label: format!("no {sym}"),
        rgb: (200, 200, 200),
    });
    for v in values {
        class_of_row.push(match v {
            Some(v) if bins > 1 => (((v - start) / width).floor().max(0.0) as usize).min(bins - 1),
            Some(_) => 0,
            None => none,
        });
    }
    (classes, class_of_row)
}

/// Bins of a round width covering `lo..=hi`: `(start, width, count)` with
/// `start` a multiple of `width`, `width` 1, 2, 2.5 or 5 times a power of
/// ten, and at most `most` bins, as many as that allows; one bin when
/// `lo >= hi` (or either is not finite).
pub(super) fn round_bins(lo: f64, hi: f64, most: usize) -> (f64, f64, usize) {
    if !lo.is_finite() || !hi.is_finite() || lo >= hi || most < 2 {
        return (lo, 1.0, 1);
    }
    let raw = (hi - lo) / most as f64;
    let mut decade = 10_f64.powf(raw.log10().floor());
    loop {
        for m in [1.0, 2.0, 2.5, 5.0] {
            let width = m * decade;
            if width < raw * (1.0 - 1e-12) {
                continue;
            }
            let start = (lo / width).floor() * width;
            // The largest value falls in the last bin: it needs hi < end.
            let count = ((hi - start) / width).floor() as usize + 1;
            if count <= most {
                return (start, width, count);
            }
        }
        decade *= 10.0;
    }
}

/// One cell per row, of the row's class, between the `edges` around its
/// values of the two parameters (each axis given as parameter, sorted
/// distinct values, edges).
///
/// # Errors
/// [`MapError::SharedCell`] when two rows fall in one cell.
pub(super) fn place_cells(
    rows: &[SweepRow],
    class_of_row: Vec<usize>,
    (x, xs, xe): (AxisParam, &[f64], &[f64]),
    (y, ys, ye): (AxisParam, &[f64], &[f64]),
) -> Result<Vec<Cell>, MapError> {
    let find = |v: &[f64], t: f64| v.iter().position(|u| u.to_bits() == t.to_bits());
    let mut owner: Vec<Option<u64>> = vec![None; xs.len() * ys.len()];
    let mut cells = Vec::with_capacity(rows.len());
    for (r, class) in rows.iter().zip(class_of_row) {
        let (Some(i), Some(j)) = (find(xs, r.param(x)), find(ys, r.param(y))) else {
            continue;
        };
        let slot = &mut owner[j * xs.len() + i];
        if let Some(first) = *slot {
            return Err(MapError::SharedCell {
                first,
                second: r.index,
            });
        }
        *slot = Some(r.index);
        cells.push(Cell {
            x: (xe[i], xe[i + 1]),
            y: (ye[j], ye[j + 1]),
            class,
        });
    }
    Ok(cells)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bins_have_round_edges_and_cover_every_value() {
        // 0.13 … 29.7 in at most 7 bins: width 5 from 0 (raw width 4.2).
        assert_eq!(round_bins(0.13, 29.7, 7), (0.0, 5.0, 6));
        // Negative values: the start is a multiple of the width below lo.
        assert_eq!(round_bins(-0.3, 0.9, 7), (-0.4, 0.2, 7));
        for (lo, hi) in [
            (0.13, 29.7),
            (-0.3, 0.9),
            (1.7e-3, 2.03e-2),
            (3.0, 3.5),
            (0.0, 7.0),
        ] {
            let (start, width, n) = round_bins(lo, hi, 7);
            assert!(
                n <= 7 && start <= lo && hi < start + width * n as f64,
                "{lo}..{hi}"
            );
            // The width is 1, 2, 2.5 or 5 times a power of ten (to round-off).
            let m = width / 10_f64.powf(width.log10().floor());
            assert!(
                [1.0, 2.0, 2.5, 5.0].iter().any(|r| (m - r).abs() < 1e-9),
                "width {width}"
            );
            // The start is a whole number of widths (to round-off).
            assert!(((start / width).round() - start / width).abs() < 1e-9);
        }
        // One value: one bin.
        assert_eq!(round_bins(2.0, 2.0, 7), (2.0, 1.0, 1));
    }

    #[test]
    fn cell_edges_lie_halfway_and_outer_cells_match_their_neighbours() {
        let e = edges(&[1.0, 2.0, 4.0], false);
        assert_eq!(format!("{e:?}"), "[0.5, 1.5, 3.0, 5.0]");
        // Log axis: geometric means, 1 → 10 → 100 gives edges √10 apart.
        let e = edges(&[1.0, 10.0, 100.0], true);
        for (got, want) in e.iter().zip([
            10f64.powf(-0.5),
            10f64.powf(0.5),
            10f64.powf(1.5),
            10f64.powf(2.5),
        ]) {
            assert!((got / want - 1.0).abs() < 1e-14, "{got} {want}");
        }
    }
}
