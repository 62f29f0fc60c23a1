//! The data behind the report's animation: the log's cross-section rolling
//! down the slope, with the snow it has picked up drawn layer by layer.
//!
//! Frames are read from a [`Trajectory`]; nothing is simulated here. The
//! total angle rolled is
//! * for the circular models (§2), `θ = ∫ dx / r` along the samples
//!   (rolling without slipping on the contact line, radius from eq. (8));
//! * for the turn models (§3), `θ = 2πk + θ_k` from the turn state.
//!
//! Turn k starts when `θ = 2πk`; the radius there is where the k-th layer
//! begins (for a circular log, eq. (8) gives `r0 + k b` exactly, since
//! `θ = 2π (r − r0)/b` when `π r² = π r0² + b x`).

use std::f64::consts::TAU;

use serde::Serialize;

use snowroll::scenario::{Scenario, Shape};
use snowroll::trajectory::Trajectory;

use super::ReportError;
use snowroll_io::CsvTable;

/// Significant digits kept in the animation data embedded in the page.
const DIGITS: usize = 6;

/// One frame of the animation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Frame {
    /// Time, s.
    pub t_s: f64,
    /// Distance rolled, m.
    pub x_m: f64,
    /// Speed, m/s.
    pub v_m_s: f64,
    /// Total angle rolled since the start, rad.
    pub theta_rad: f64,
    /// Radius (nominal radius for the turn models), m.
    pub r_m: f64,
    /// Turn number k, 0-based: `θ ∈ [2πk, 2π(k+1))`.
    pub turn: u64,
}

/// The animation: frames, the geometry it needs, and labels.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Animation {
    /// Heading above the animation.
    pub title: String,
    /// Sentence under it.
    pub caption: String,
    /// Model id (`energy`, `turns`, …).
    pub model: String,
    /// Where the model is in the note.
    pub equation: String,
    /// Slope angle α, degrees.
    pub alpha_deg: f64,
    /// Snow depth b, m.
    pub snow_depth: f64,
    /// Initial radius r0, m.
    pub r0: f64,
    /// `true` for the circular models (the log stays round: the accreted
    /// snow is spread evenly), `false` for the turn models (the snow of the
    /// current turn is an arc of depth b on a round log of the turn's radius).
    pub circular: bool,
    /// The body: `cylinder` (a log, drawn as its cross-section with a wooden
    /// core) or `sphere` (a snowball, drawn as a shaded ball of snow whose
    /// radius grows), issue 11.
    pub shape: Shape,
    /// Radius at the start of turn k, m, for k = 0, 1, … up to the last frame's turn.
    pub turn_start_radius_m: Vec<f64>,
    /// Frames in time order.
    pub frames: Vec<Frame>,
}

impl Animation {
    /// Builds the animation of `traj` (run on `scenario`), keeping at most
    /// `max_frames` frames evenly spread in time (each one a real sample).
    ///
    /// # Errors
    /// [`ReportError::InvalidAnimation`] for fewer than two samples,
    /// non-finite values, or turn states that do not match the samples.
    pub fn from_trajectory(
        traj: &Trajectory,
        scenario: &Scenario,
        max_frames: usize,
    ) -> Result<Self, ReportError> {
        let samples = &traj.samples;
        if samples.len() < 2 || max_frames < 2 {
            return Err(ReportError::InvalidAnimation {
                reason: "need at least two samples and two frames",
            });
        }
        let circular = traj.turn_states.is_empty();
        if !circular && traj.turn_states.len() != samples.len() {
            return Err(ReportError::InvalidAnimation {
                reason: "one turn state per sample is needed",
            });
        }
        let mut all = Vec::with_capacity(samples.len());
        let mut theta = 0.0;
        for (i, s) in samples.iter().enumerate() {
            let (theta_total, turn) = if circular {
                if i > 0 {
                    let p = &samples[i - 1];
                    theta += (s.x_m - p.x_m) * 0.5 * (1.0 / s.r_m + 1.0 / p.r_m);
                }
                (theta, (theta / TAU).floor().max(0.0) as u64)
            } else {
                let k = traj.turn_states[i];
                (TAU * k.turn as f64 + k.theta_rad, k.turn)
            };
            all.push(Frame {
                t_s: s.t_s,
                x_m: s.x_m,
                v_m_s: s.v_m_s,
                theta_rad: theta_total,
                r_m: s.r_m,
                turn,
            });
        }
        let turn_start_radius_m = turn_start_radii(&all, circular);
        let shape = scenario.shape();
        let (title, caption) = match shape {
            Shape::Cylinder => (
                format!("The log rolling down the slope ({})", traj.model.id()),
                format!(
                    "Cross-section of the log, {}: {}. Snow picked up in each turn is drawn as a layer.",
                    traj.model.equation(),
                    traj.model.description()
                ),
            ),
            Shape::Sphere => (
                format!("The snowball rolling down the slope ({})", traj.model.id()),
                format!(
                    "The snowball (a uniform ball of snow, shaded to tell it from the log's cross-section), {} for a ball: its radius grows as it picks up the layer over its {}; the line on it shows it turning.",
                    traj.model.equation(),
                    match scenario.swath_width() {
                        None => "diameter (π r² = π r0² + b x)".to_string(),
                        Some(w) => format!("swath of {w} m"),
                    }
                ),
            ),
        };
        let anim = Self {
            title,
            caption,
            model: traj.model.id().to_string(),
            equation: traj.model.equation().to_string(),
            alpha_deg: snowroll::scenario::ScenarioFile::from(*scenario).alpha_deg,
            snow_depth: scenario.snow_depth(),
            r0: scenario.initial_radius(),
            circular,
            shape,
            turn_start_radius_m,
            frames: thin(&all, max_frames),
        };
        anim.validate()?;
        Ok(anim)
    }

    /// Prefix of the page elements of this animation (`PREFIX-canvas`,
    /// `PREFIX-status`, …): `anim` for the log, `ball-anim` for the
    /// snowball. A report shows at most one animation of each shape.
    pub fn prefix(&self) -> &'static str {
        match self.shape {
            Shape::Cylinder => "anim",
            Shape::Sphere => "ball-anim",
        }
    }

    /// Name of this animation's section in the page and of its frames'
    /// file (`data/NAME.csv`): `animation` for the log, `ball-animation`
    /// for the snowball.
    pub fn name(&self) -> &'static str {
        match self.shape {
            Shape::Cylinder => "animation",
            Shape::Sphere => "ball-animation",
        }
    }

    /// Checks that the animation can be played.
    ///
    /// # Errors
    /// [`ReportError::InvalidAnimation`] naming the problem.
    pub fn validate(&self) -> Result<(), ReportError> {
        let bad = |reason| Err(ReportError::InvalidAnimation { reason });
        if self.frames.len() < 2 {
            return bad("need at least two frames");
        }
        let finite = self.frames.iter().all(|f| {
            [f.t_s, f.x_m, f.v_m_s, f.theta_rad, f.r_m]
                .iter()
                .all(|v| v.is_finite())
        });
        if !finite {
            return bad("a frame holds a non-finite value");
        }
        if self.frames.windows(2).any(|w| w[1].t_s < w[0].t_s) {
            return bad("frame times must not decrease");
        }
        if self.frames.iter().any(|f| f.r_m <= 0.0) || self.r0 <= 0.0 {
            return bad("radii must be positive");
        }
        let last_turn = self.frames.iter().map(|f| f.turn).max().unwrap_or(0);
        if self.turn_start_radius_m.len() as u64 <= last_turn {
            return bad("every turn needs its starting radius");
        }
        Ok(())
    }

    /// The JSON the page's script plays: metadata and one array per column,
    /// rounded to six significant digits.
    ///
    /// # Errors
    /// [`ReportError::Json`] if serialisation fails.
    pub fn to_json(&self) -> Result<String, ReportError> {
        let col = |f: fn(&Frame) -> f64| -> Vec<f64> {
            self.frames.iter().map(|fr| round_sig(f(fr))).collect()
        };
        let doc = serde_json::json!({
            "title": self.title,
            "model": self.model,
            "equation": self.equation,
            "alpha_deg": self.alpha_deg,
            "snow_depth": self.snow_depth,
            "r0": self.r0,
            "circular": self.circular,
            "shape": self.shape,
            "ring_r": self.turn_start_radius_m.iter().map(|&r| round_sig(r)).collect::<Vec<_>>(),
            "t": col(|f| f.t_s),
            "x": col(|f| f.x_m),
            "v": col(|f| f.v_m_s),
            "theta": col(|f| f.theta_rad),
            "r": col(|f| f.r_m),
            "turn": self.frames.iter().map(|f| f.turn).collect::<Vec<_>>(),
        });
        Ok(serde_json::to_string(&doc)?)
    }

    /// The frames as CSV, with `#` lines recording version and geometry.
    ///
    /// # Errors
    /// [`ReportError::Output`] if serialisation fails.
    pub fn to_csv(&self, software: &str) -> Result<String, ReportError> {
        let lines = vec![
            ("animation".to_string(), self.title.clone()),
            (
                "model".to_string(),
                format!("{} ({})", self.model, self.equation),
            ),
            ("alpha_deg".to_string(), self.alpha_deg.to_string()),
            ("snow_depth".to_string(), self.snow_depth.to_string()),
            ("r0".to_string(), self.r0.to_string()),
            ("shape".to_string(), self.shape.to_string()),
            (
                "turn_start_radius_m".to_string(),
                self.turn_start_radius_m
                    .iter()
                    .map(|r| r.to_string())
                    .collect::<Vec<_>>()
                    .join(" "),
            ),
        ];
        let mut w = CsvTable::new(software, &lines);
        {
            for (row, f) in (1..).zip(&self.frames) {
                snowroll_io::check_finite(f, Some(row)).map_err(|source| {
                    ReportError::NonFinite {
                        figure: "animation".to_string(),
                        source,
                    }
                })?;
                w.row(f)?;
            }
        }
        Ok(w.finish()?)
    }
}

/// Radius at the start of each turn: where θ crosses 2πk (linear
/// interpolation between samples for the circular models; the turn's
/// nominal radius for the turn models).
fn turn_start_radii(frames: &[Frame], circular: bool) -> Vec<f64> {
    let Some(first) = frames.first() else {
        return Vec::new();
    };
    let last_turn = frames.iter().map(|f| f.turn).max().unwrap_or(0);
    let mut radii = vec![first.r_m];
    for k in 1..=last_turn {
        let target = TAU * k as f64;
        let r = if circular {
            frames
                .windows(2)
                .find(|w| w[0].theta_rad <= target && target <= w[1].theta_rad)
                .map(|w| {
                    let span = w[1].theta_rad - w[0].theta_rad;
                    let s = if span > 0.0 {
                        (target - w[0].theta_rad) / span
                    } else {
                        0.0
                    };
                    w[0].r_m + s * (w[1].r_m - w[0].r_m)
                })
        } else {
            frames.iter().find(|f| f.turn == k).map(|f| f.r_m)
        };
        radii.push(r.unwrap_or(first.r_m));
    }
    radii
}

/// At most `max` frames, the last sample at or before each of `max` evenly
/// spaced times (first and last always kept).
fn thin(frames: &[Frame], max: usize) -> Vec<Frame> {
    let (Some(first), Some(last)) = (frames.first(), frames.last()) else {
        return Vec::new();
    };
    if frames.len() <= max {
        return frames.to_vec();
    }
    let span = last.t_s - first.t_s;
    let mut out: Vec<Frame> = Vec::with_capacity(max);
    let mut i = 0;
    for j in 0..max {
        let target = first.t_s + span * j as f64 / (max - 1) as f64;
        while i + 1 < frames.len() && frames[i + 1].t_s <= target {
            i += 1;
        }
        if out.last().is_none_or(|f| f.t_s < frames[i].t_s) {
            out.push(frames[i]);
        }
    }
    out
}

/// `v` rounded to [`DIGITS`] significant digits.
fn round_sig(v: f64) -> f64 {
    format!("{v:.prec$e}", prec = DIGITS - 1)
        .parse()
        .unwrap_or(v)
}
