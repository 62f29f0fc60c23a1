//! How the models look in the figures: which circular models share one
//! equation (and so one curve), their legend entries, line styles and markers.

use crate::plot::{Marker, Series, Style};
use snowroll::models::{Coefficients, Derivation, ModelKind};

/// The equation a circular model integrates, as its coefficients: Loney's
/// closed form (fn. 4) solves eq. (4), so it has eq. (4)'s.
fn equation_of(kind: ModelKind) -> Option<Coefficients> {
    match kind {
        ModelKind::Loney => Some(Derivation::TorqueAboutCentre.coefficients()),
        _ => kind.derivation().map(Derivation::coefficients),
    }
}

/// The circular models grouped by equation, in the order of the note: models
/// with the same equation of motion (eq. (15) and eqs. (32)+(36); eq. (4) and
/// Loney's fn. 4) draw one curve under one legend entry.
pub(super) fn same_equation_groups(kinds: &[ModelKind]) -> Vec<Vec<ModelKind>> {
    let mut groups: Vec<Vec<ModelKind>> = Vec::new();
    for &k in kinds {
        let eq = equation_of(k);
        match groups
            .iter_mut()
            .find(|g| eq.is_some() && equation_of(g[0]) == eq)
        {
            Some(group) => group.push(k),
            None => groups.push(vec![k]),
        }
    }
    groups
}

/// Legend entry of a model: its id and equation alias.
pub(super) fn label(k: ModelKind) -> String {
    format!("{} ({})", k.id(), k.alias())
}

/// Legend entry of a group of models with one equation: `a (eq15) = b (eq32+36)`.
pub(super) fn group_label(group: &[ModelKind]) -> String {
    group
        .iter()
        .map(|&k| label(k))
        .collect::<Vec<_>>()
        .join(" = ")
}

/// Line style and marker of each model: every group of models with one
/// equation looks different apart from colour, so that curves that lie
/// close (all start near 2G/3; three tend to G/3; G/5, 2G/9 and G/6 are
/// near each other) stay apart for readers who cannot tell the colours apart.
pub(super) fn look(k: ModelKind) -> (Style, Option<Marker>) {
    match k {
        ModelKind::TorqueCm | ModelKind::Loney => (Style::Line, Some(Marker::Circle)),
        ModelKind::TorqueContact => (Style::Dashed, None),
        ModelKind::Energy => (Style::Dashed, Some(Marker::Circle)),
        ModelKind::EnergyThin | ModelKind::QuasiCircularLift => {
            (Style::LongDashed, Some(Marker::Triangle))
        }
        ModelKind::LagrangianPrinted => (Style::Dotted, None),
        ModelKind::QuasiCircular => (Style::Dotted, Some(Marker::Square)),
        ModelKind::Turns => (Style::LongDashed, None),
        ModelKind::TurnsExact => (Style::LongDashed, Some(Marker::Square)),
        ModelKind::Snowless => (Style::Line, None),
    }
}

/// `series` drawn in the look of `k`.
pub(super) fn styled(series: Series, k: ModelKind) -> Series {
    let (style, marker) = look(k);
    let series = series.style(style);
    match marker {
        Some(m) => series.marker(m),
        None => series,
    }
}

/// The circular models (§2, App. A, fn. 4), in the order of the note.
pub(super) fn circular_models() -> Vec<ModelKind> {
    ModelKind::ALL
        .into_iter()
        .filter(|k| k.is_circular())
        .collect()
}
