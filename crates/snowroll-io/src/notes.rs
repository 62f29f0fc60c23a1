//! The notes a run's output ends with (after its stop): why it ended before
//! its end time, requested times it never reached, turns short of those
//! asked for. One sentence each, written by `snowroll simulate` and
//! `snowroll turns` and by the explorer's WebAssembly build alike, so that
//! their outputs are the same bytes.

use snowroll::trajectory::{HopDoubt, SimOptions, Stop, StopReason, TurnState};
use snowroll::{format_number, ModelKind, Sampling, Scenario, TurnRunEnd};

/// How many requested times were not written because the run stopped
/// before them (times after `t_end` are refused before the run).
pub fn times_note(rows: u64, stop: Stop, opts: &SimOptions) -> Option<String> {
    let Sampling::Times(times) = &opts.sampling else {
        return None;
    };
    let missing = times.len().saturating_sub(rows as usize);
    (missing > 0).then(|| {
        format!(
            "{missing} of the {} requested times are after the stop at t = {} s and were not written",
            times.len(),
            format_number(stop.t_s)
        )
    })
}

/// The note of a trajectory (`simulate`) when the run ended before its end
/// time, or reached it short of the turns asked for.
pub fn stop_note(
    model: ModelKind,
    stop: Stop,
    last_turn: Option<TurnState>,
    scenario: &Scenario,
    opts: &SimOptions,
) -> Option<String> {
    if stop.reason == StopReason::EndTime {
        let (wanted, last) = (opts.turns?, last_turn?);
        return Some(format!(
            "reached t_end = {} s in turn {} (0-based) of the {wanted} asked for; \
             raise --t-end for more",
            format_number(opts.t_end),
            last.turn
        ));
    }
    let mut note = format!(
        "run stopped at {}: {}",
        stop.place(),
        stop.reason.describe()
    );
    if stop.reason == StopReason::DoesNotStart {
        // The run's own body, swath and losses set the threshold.
        let threshold = model.stall_threshold_in(scenario, &opts.losses);
        match threshold.map(|t| t.slope.to_degrees()) {
            Some(deg) if deg < 89.9999 => note.push_str(&format!(
                "; from rest this model needs alpha > {deg:.4} degrees"
            )),
            Some(_) => {
                note.push_str("; with this snow, radius and losses it cannot start on any slope")
            }
            None => {}
        }
    }
    match stop.reason {
        StopReason::StepLimit => {
            note.push_str("; a looser --rtol or a shorter --t-end needs fewer steps");
        }
        StopReason::RowLimit => note.push_str(&format!(
            " ({}); raise --max-rows, or sample with {}",
            opts.max_rows,
            // A grid run can only coarsen its grid; a step-by-step run can take one.
            if matches!(opts.sampling, Sampling::Every(_)) {
                "a coarser --dt"
            } else {
                "--dt"
            }
        )),
        _ => {}
    }
    Some(note)
}

/// The note of a turn table (`turns`) when the run ended before the
/// `wanted` turns.
pub fn turns_stop_note(end: &TurnRunEnd, wanted: u64, t_end: f64) -> Option<String> {
    let stop = end.stop;
    if stop.reason == StopReason::Turns {
        return None;
    }
    let mut note = format!(
        "run stopped at {}: {}, after {} of the {wanted} turns asked for",
        stop.place(),
        stop.reason.describe(),
        end.summary.turns
    );
    if stop.reason == StopReason::EndTime {
        note.push_str(&format!(
            " (t_end = {} s; raise --t-end for more)",
            format_number(t_end)
        ));
    }
    Some(note)
}

/// The note of a turn run whose first hop the integrator's error could
/// decide ([`TurnRunEnd::hop_doubt`], [`RunEnd::hop_doubt`](snowroll::trajectory::RunEnd::hop_doubt) of `simulate`):
/// the turn, its least N and the error.
pub fn hop_doubt_note(doubt: Option<HopDoubt>) -> Option<String> {
    let d = doubt?;
    Some(format!(
        "the first hop may depend on the tolerance: turn {} keeps least N/(m_k g) = {}, within the \
         integrator's estimated error {} of 0 (no closed form of the turns confirms it here, \
         docs/contact-forces.md); rerun at a tighter --rtol to see whether the hop moves",
        d.turn,
        format_number(d.least_normal_over_mkg),
        format_number(d.error_over_mkg)
    ))
}

/// The notes a turn table ends with: why it stopped short of the `wanted`
/// turns ([`turns_stop_note`]), then a first hop that may depend on the
/// tolerance ([`hop_doubt_note`]).
pub fn turns_notes(end: &TurnRunEnd, wanted: u64, t_end: f64) -> Vec<String> {
    turns_stop_note(end, wanted, t_end)
        .into_iter()
        .chain(hop_doubt_note(end.hop_doubt))
        .collect()
}
