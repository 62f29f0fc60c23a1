//! The report's figure of the snowball (issue 11): a/(g sin α) against time
//! for every circular model run with a ball (I = (2/5) M r², swath 2r) from
//! rest on the lab's slope, with the terminal fractions of
//! `docs/snowball-and-losses.md` §1.3 as reference lines; and the ball's
//! animation. It only reads trajectories.

use super::{Animation, ClaimId, Figure, Lab, ReportError};
use crate::plot::{Axis, Chart, Series, Style};
use snowroll::models::ModelKind;
use snowroll::scenario::{Scenario, ScenarioFile, Shape};
use snowroll::trajectory::{Sampling, SimOptions};

/// Distance the ball's animation rolls, m: its radius doubles on the way
/// (π r² = π r0² + b x: r = 2 r0 at x = 3π r0²/b, 9.4 m with the defaults),
/// in about a dozen turns, enough to see it grow.
const BALL_ANIMATION_X: f64 = 10.0;
/// Sampling interval of the ball's animation run, s (the page shows at most
/// the frames it is given; 5 ms is below one frame of a 60 Hz screen).
const BALL_ANIMATION_DT: f64 = 0.005;

/// The lab's scenario with a ball of natural swath (2r) in place of the log.
fn ball_scenario(lab: &Lab) -> Result<Scenario, ReportError> {
    Ok(Scenario::new(ScenarioFile {
        shape: Shape::Sphere,
        swath_width: None,
        ..ScenarioFile::from(*lab.scenario())
    })
    .map_err(snowroll::error::SimError::from)?)
}

/// The snowball's animation: the ball of eq. (4)'s balance (torque about
/// the centre, the closed form of the TPT letter, §1.4) from rest over
/// [`BALL_ANIMATION_X`], at most `frames` frames.
///
/// # Errors
/// [`ReportError`] when the run fails or cannot be animated.
pub(super) fn ball_animation(lab: &Lab, frames: usize) -> Result<Animation, ReportError> {
    let s = ball_scenario(lab)?;
    let opts = SimOptions {
        t_end: 1e6,
        x_end: Some(BALL_ANIMATION_X),
        sampling: Sampling::Every(BALL_ANIMATION_DT),
        ..SimOptions::default()
    };
    let traj = lab.run(ModelKind::TorqueCm, &s, &opts)?;
    let mut anim = Animation::from_trajectory(&traj, &s, frames)?;
    let r_end = traj.samples.last().map_or(f64::NAN, |p| p.r_m);
    anim.caption = format!(
        "The snowball of the closed form in The Physics Teacher 57, p. 436 (2019): torque about the centre, eq. (4)'s balance for a uniform ball of snow (I = (2/5) M r²), from rest over the first {BALL_ANIMATION_X} m (docs/snowball-and-losses.md §1.4). \
         It picks up the layer over its diameter, so π r² = π r₀² + b x and its radius grows from {} m to {} m; its acceleration falls from (5/7) g sin α towards (1/6) g sin α. \
         Shaded, with no wooden core, to tell it from the log's cross-section; the line on it shows it turning.",
        s.initial_radius(),
        super::notation::fixed(r_end, 3)
    );
    Ok(anim)
}

/// The figure, on times `times` (s, ascending, the last one the end).
///
/// # Errors
/// [`ReportError`] when a run fails.
pub(super) fn snowball_figure(lab: &Lab, times: &[f64]) -> Result<Figure, ReportError> {
    let s = ball_scenario(lab)?;
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
    );
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
            .and_then(snowroll::models::as_fraction)
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
            "The snowball: a/(g sin α) against time for every circular model with --shape sphere (a uniform ball, I = (2/5) M r², picking up the layer over its diameter, so π r² = π r0² + b x as for the log), from rest. All start at the snowless ball's 5/7 and tend to their own terminal fractions ({}; the project's notes on the snowball and the losses §1.3). torque-cm and loney are the closed form of the letter in The Physics Teacher 57, p. 436 (2019): from 5/7 to 1/6. The turn models take the log only.",
            fractions.join(", ")
        ),
    )
    .param("shape", "sphere")
    .param("alpha_deg", ScenarioFile::from(s).alpha_deg)
    .param("snow_depth", ScenarioFile::from(s).snow_depth)
    .param("r0", ScenarioFile::from(s).r0)
    .param("rtol", format!("{:e}", opts.tolerances.rtol))
    .supports(&[
        ClaimId::SnowballFiveSevenths,
        ClaimId::SnowballTerminalFractions,
        ClaimId::TptLetterClosedForm,
    ]))
}
