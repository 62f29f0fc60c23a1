//! `snowroll models`: every model with its equation, its late-time
//! acceleration as a fraction of g sin alpha, the slope below which it does
//! not roll on from rest (fn. 7: the circular models with a lift term do not
//! start; the turn models start but stall inside their first turn), and its
//! range of validity. Every number is computed by the library
//! ([`ModelKind::terminal_fraction`], [`ModelKind::stall_threshold`],
//! [`ModelKind::validity`]).

use std::io::Write;

use anyhow::{Context, Result};
use serde::Serialize;
use snowroll::models::{StallKind, Validity};
use snowroll::params::Settings;
use snowroll::{ModelKind, Scenario, ScenarioFile, Shape};

use crate::args::{BodyArgs, ModelsArgs, ModelsFormat};
use crate::sink::Sink;
use snowroll::as_fraction;

/// One model, as listed.
#[derive(Debug, Serialize)]
struct Row {
    id: &'static str,
    alias: &'static str,
    equation: &'static str,
    description: &'static str,
    /// Late-time acceleration over g sin alpha.
    terminal_fraction: Option<f64>,
    /// The same as a fraction `p/q`, when it is one.
    terminal_fraction_exact: Option<String>,
    /// The shapes the model takes (`cylinder`, `sphere`; issue 11).
    shapes: Vec<&'static str>,
    /// Late-time acceleration over g sin alpha of the ball (swath 2r), where the model takes one.
    sphere_terminal_fraction: Option<f64>,
    /// The same as a fraction `p/q`.
    sphere_terminal_fraction_exact: Option<String>,
    /// Below this slope the model does not roll on from rest, for the default b and r0 (fn. 7).
    stall_slope_deg: Option<f64>,
    /// What happens below `stall_slope_deg`.
    stall_kind: Option<StallKind>,
    /// The order in b/r the model keeps and where it is used without a warning.
    validity: Validity,
}

/// The listing.
#[derive(Debug, Serialize)]
struct Listing {
    snowroll_version: &'static str,
    /// Snow depth b used for `stall_slope_deg`, m.
    snow_depth: f64,
    /// Initial radius r0 used for `stall_slope_deg`, m.
    r0: f64,
    models: Vec<Row>,
    /// The flags the listing was computed for, when any was given (else
    /// the default log without losses).
    #[serde(skip_serializing_if = "Option::is_none")]
    flags_given: Option<String>,
}

/// The listing for the scenario and losses of `args` (the defaults where
/// no flag is given): the stall slopes on that body with those losses, the
/// ball's column on the same slope and snow.
fn listing(args: &ModelsArgs) -> Result<Listing> {
    let settings = args.body.given.apply(Settings::default())?;
    let (file, losses) = (settings.scenario, settings.options.losses);
    losses.validate()?;
    let scenario = Scenario::new(file)?;
    let ball = Scenario::new(ScenarioFile {
        shape: Shape::Sphere,
        ..file
    });
    let (b, r0) = (file.snow_depth, file.r0);
    let models = ModelKind::ALL
        .into_iter()
        .map(|kind| {
            let terminal = kind.terminal_fraction();
            let shapes = kind.shapes();
            let sphere = match &ball {
                Ok(s) if shapes.contains(&Shape::Sphere) => kind.terminal_fraction_on(s),
                _ => None,
            };
            // None for a body or losses the model does not take.
            let stall = kind.stall_threshold_listed(&scenario, &losses);
            Row {
                id: kind.id(),
                alias: kind.alias(),
                equation: kind.equation(),
                description: kind.description(),
                terminal_fraction: terminal,
                terminal_fraction_exact: terminal
                    .and_then(as_fraction)
                    .map(|(p, q)| format!("{p}/{q}")),
                shapes: shapes.iter().map(|s| s.id()).collect(),
                sphere_terminal_fraction: sphere,
                sphere_terminal_fraction_exact: sphere
                    .and_then(as_fraction)
                    .map(|(p, q)| format!("{p}/{q}")),
                stall_slope_deg: stall.map(|t| t.slope.to_degrees()),
                stall_kind: stall.map(|t| t.kind),
                validity: kind.validity(),
            }
        })
        .collect();
    Ok(Listing {
        snowroll_version: snowroll_io::VERSION,
        snow_depth: b,
        r0,
        models,
        flags_given: assumptions(&args.body),
    })
}

/// The flags given, as typed on a command line in table order (`None`
/// when there are none: the default log without losses).
fn assumptions(body: &BodyArgs) -> Option<String> {
    let flags: Vec<String> = body
        .given
        .iter()
        .map(|(p, v)| format!("--{} {}", p.flag(), p.text(v)))
        .collect();
    (!flags.is_empty()).then(|| flags.join(" "))
}

/// Prints the listing.
pub fn run(args: &ModelsArgs) -> Result<()> {
    let listing = listing(args)?;
    let text = match args.format {
        ModelsFormat::Json => snowroll_io::json_document(&listing)?,
        ModelsFormat::Table => table(&listing),
    };
    let mut out = Sink::stdout();
    out.write_all(text.as_bytes())
        .and_then(|()| out.commit())
        .context("writing to stdout")
}

/// The table's column headers.
const HEADER: [&str; 7] = [
    "id",
    "alias",
    "equation",
    "a_inf / (g sin alpha)",
    "shapes",
    "ball a_inf",
    "description",
];

/// An aligned text table, then the stall and validity notes.
fn table(listing: &Listing) -> String {
    let rows: Vec<[String; 7]> = listing.models.iter().map(row).collect();
    let mut widths = HEADER.map(|h| h.chars().count());
    for row in &rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut text = aligned(HEADER, &widths);
    for row in &rows {
        text.push_str(&aligned(row.each_ref().map(String::as_str), &widths));
    }
    text.push_str(
        "\na_inf: late-time acceleration with snow (b > 0), from the model's coefficients; \
         ball a_inf: the same for --shape sphere (swath 2r, docs/snowball-and-losses.md §1.3). \
         The turn models take the log only.\n",
    );
    text.push_str(&stall_notes(listing, widths[0]));
    text.push_str(&validity_notes(listing, widths[0]));
    text
}

/// One model's cells.
fn row(m: &Row) -> [String; 7] {
    let fraction = |exact: &Option<String>, f: Option<f64>| match (exact, f) {
        (Some(exact), Some(f)) => format!("{exact} = {f:.4}"),
        (None, Some(f)) => format!("{f:.4}"),
        (_, None) => "none".to_string(),
    };
    [
        m.id.to_string(),
        m.alias.to_string(),
        m.equation.to_string(),
        fraction(&m.terminal_fraction_exact, m.terminal_fraction),
        m.shapes.join(","),
        fraction(
            &m.sphere_terminal_fraction_exact,
            m.sphere_terminal_fraction,
        ),
        m.description.to_string(),
    ]
}

/// One line of the table: each cell padded to its column's width but the
/// last.
fn aligned(cells: [&str; 7], widths: &[usize; 7]) -> String {
    let mut s = String::new();
    for (i, (cell, w)) in cells.iter().zip(widths).enumerate() {
        if i + 1 == cells.len() {
            s.push_str(cell);
        } else {
            s.push_str(&format!("{cell:<w$}  "));
        }
    }
    s.push('\n');
    s
}

/// The stall slopes of fn. 7, by kind of stall, ids padded to `width`.
fn stall_notes(listing: &Listing, width: usize) -> String {
    let mut text = String::new();
    for (kind, what) in [
        (StallKind::DoesNotStart, "do not start from rest"),
        (
            StallKind::StallsInFirstTurn,
            "start from rest (a = 2G/3) but stall inside their first turn",
        ),
    ] {
        let list: Vec<(&str, f64)> = listing
            .models
            .iter()
            .filter(|m| m.stall_kind == Some(kind))
            .filter_map(|m| m.stall_slope_deg.map(|s| (m.id, s)))
            .collect();
        if list.is_empty() {
            continue;
        }
        text.push_str(&format!(
            "Stall (fn. 7): with b = {} m, r0 = {} m{} these models {what} unless alpha exceeds:\n",
            listing.snow_depth,
            listing.r0,
            listing
                .flags_given
                .as_ref()
                .map_or_else(String::new, |a| format!(" ({a})")),
        ));
        for (id, slope) in list {
            text.push_str(&format!("  {id:<width$}  {slope:.4} degrees\n"));
        }
    }
    text
}

/// Each model's range of validity, ids padded to `width`.
fn validity_notes(listing: &Listing, width: usize) -> String {
    let mut text = "Validity (order in b/r kept; largest b/r0 used without a warning on stderr):\n"
        .to_string();
    for m in &listing.models {
        let order = match m.validity.order_in_b_over_r {
            Some(0) => "b = 0".to_string(),
            Some(n) => format!("order {n}"),
            None => "no term dropped".to_string(),
        };
        let max = m
            .validity
            .max_b_over_r0
            .map_or_else(|| "any".to_string(), |x| x.to_string());
        text.push_str(&format!(
            "  {:<width$}  {order:<15}  b/r0 <= {max:<4}  {}\n",
            m.id, m.validity.statement,
        ));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fractions_are_recognised_and_decimals_are_not() {
        assert_eq!(
            as_fraction((2.0 / 3.0) / (1.0 + 2.0 * 7.0 / 6.0)),
            Some((1, 5))
        );
        assert_eq!(as_fraction(2.0 / 9.0), Some((2, 9)));
        assert_eq!(as_fraction(1.0), Some((1, 1)));
        assert_eq!(as_fraction(std::f64::consts::FRAC_1_PI), None);
        assert_eq!(as_fraction(f64::NAN), None);
    }
}
