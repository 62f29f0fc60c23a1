//! The report's figure of the snowball (issue 11): a/(g sin α) against time
//! for every circular model run with a ball (I = (2/5) M r², swath 2r) from
//! rest on the lab's slope, with the terminal fractions of
//! `docs/snowball-and-losses.md` §1.3 as reference lines. It only reads
//! trajectories.

use super::{Figure, Lab, ReportError};
use crate::models::ModelKind;
use crate::plot::{Axis, Chart, Legend, Series, Style};
use crate::scenario::{Scenario, ScenarioFile, Shape};
use crate::trajectory::{Sampling, SimOptions};

/// The figure, on times `times` (s, ascending, the last one the end).
///
/// # Errors
/// [`ReportError`] when a run fails.
pub(super) fn snowball_figure(lab: &Lab, times: &[f64]) -> Result<Figure, ReportError> {
    let s = Scenario::new(ScenarioFile {
        shape: Shape::Sphere,
        swath_width: None,
        ..ScenarioFile::from(*lab.scenario())
    })
    .map_err(crate::error::SimError::from)?;
    let g = s.g_along();
    let t_end = times.last().copied().unwrap_or(100.0);
    let opts = SimOptions {
        t_end,
        sampling: Sampling::Times(times.to_vec()),
        ..SimOptions::default()
    };
    let mut chart = Chart::new(
        "snowball-acceleration",
        "Acceleration of the snowball in every circular model",
        Axis::log("time t", "s").column("t_s"),
        Axis::linear("a / (g sin α)", "1").column("a_over_g_sin_alpha"),
    )
    .with_legend(Legend::LowerLeft);
    let mut fractions = Vec::new();
    for kind in ModelKind::ALL
        .into_iter()
        .filter(|k| k.shapes().contains(&Shape::Sphere))
    {
        let traj = lab.run(kind, &s, &opts)?;
        let style = match kind {
            ModelKind::Loney | ModelKind::QuasiCircular | ModelKind::EnergyThin => Style::Dashed,
            _ => Style::Line,
        };
        let name = format!("{} ({})", kind.id(), kind.alias());
        chart = chart.with_series(
            Series::from_samples(&name, &traj.samples, |p| p.t_s, |p| p.a_m_s2 / g).style(style),
        );
        if let Some((p, q)) = kind
            .terminal_fraction_on(&s)
            .and_then(crate::models::as_fraction)
        {
            let text = format!("{p}/{q}");
            if !fractions.contains(&text) {
                fractions.push(text);
            }
        }
    }
    Ok(Figure::new(
        chart,
        &format!(
            "The snowball: a/(g sin α) against time for every circular model with --shape sphere (a uniform ball, I = (2/5) M r², picking up the layer over its diameter, so π r² = π r0² + b x as for the log), from rest. All start at the snowless ball's 5/7 and tend to their own terminal fractions ({}; docs/snowball-and-losses.md §1.3). torque-cm and loney are the closed form of the letter in The Physics Teacher 57, p. 436 (2019): from 5/7 to 1/6. The turn models take the log only.",
            fractions.join(", ")
        ),
    )
    .param("shape", "sphere")
    .param("alpha_deg", ScenarioFile::from(s).alpha_deg)
    .param("snow_depth", ScenarioFile::from(s).snow_depth)
    .param("r0", ScenarioFile::from(s).r0)
    .param("rtol", format!("{:e}", opts.tolerances.rtol))
    .supports(&[
        "snowball-five-sevenths",
        "snowball-terminal-fractions",
        "tpt-letter-closed-form",
    ]))
}
