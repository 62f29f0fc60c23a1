//! The claims of the note and the computations that judge them: one table,
//! [`CLAIMS`], read by the `paper` report and by `tests/claims.rs`, so the
//! two cannot disagree.
//!
//! Each check observes the models through a [`Lab`]: the scenario, the runs
//! of the models, and the long multi-turn runs. The checks never read the
//! coefficients the models run with; they type the note's equations (as
//! printed and as corrected in `docs/errata.md`) and compare the models'
//! output with what those equations imply. A lab can be given a deliberately
//! wrong model ([`Lab::with_coefficients`], [`Lab::with_runner`],
//! [`Lab::with_long_run`]); the tests do so once per strengthened check and
//! see its verdict change.
//!
//! Every tolerance is a [`Criterion`] constant that the table lists and the
//! check calls. A refutation is reached only when the check has also
//! measured what holds instead; otherwise the verdict is
//! [`Verdict::Inconclusive`].
//!
//! The checks live by part of the note: [`circular`] (§2, fn. 4, fn. 7),
//! [`terminal`] (§2.4), [`app_a`] (App. A), [`first_turn`] (§3.1–3.3),
//! [`stall`] (fn. 7 in §3), [`multi_turn`] (§3.4), [`contact`] (fn. 10),
//! [`slip`] (issue 10: the smallest μ),
//! [`snowball`] (issue 11: the ball, and The Physics Teacher 57 (2019)),
//! [`losses`] (fn. 5).

mod app_a;
mod circular;
mod contact;
mod first_turn;
mod losses;
mod multi_turn;
mod quadrature;
mod regime;
mod slip;
mod snowball;
mod stall;
mod table;
mod terminal;
mod unwinding;

use std::fmt;
use std::sync::OnceLock;

use super::turn_digest::{DigestSink, TurnDigest};
use super::{Claim, ClaimResult, Criterion, Verdict};
use snowroll::error::SimError;
use snowroll::models::{
    run_turns_into, CircularModel, Coefficients, Derivation, ModelKind, TurnTable,
};
use snowroll::scenario::{Scenario, ScenarioFile};
use snowroll::trajectory::{Sampling, SimOptions, Trajectory};

pub(crate) use regime::regime_figure;
pub(crate) use slip::mu_min_rows;
pub use table::CLAIMS;

/// A replacement for the runs of some models: returns `Some` for the
/// models it replaces, `None` to run the library's model.
pub type Runner =
    dyn Fn(ModelKind, &Scenario, &SimOptions) -> Option<Result<Trajectory, SimError>> + Send + Sync;

/// Why the check of claim `id` is judged on the default scenario when the
/// report runs another (`snowroll paper --alpha-deg ...`), or `None` when it
/// adapts to any scenario. An exhaustive match: a new claim must decide.
pub fn tuned_to_default(id: crate::ClaimId) -> Option<&'static str> {
    use crate::ClaimId::*;
    match id {
        SnowlessLimit | CircularAgreeAsBVanishes => {
            Some("its b → 0 extrapolation and absolute tolerance are set for the default run's growth x/r0")
        }
        SlipMuMin => Some("its closed forms are for a start from rest on a slope where no model hops"),
        UnwindingTextbookSpeed | UnwindingHollowRoll => {
            Some("it runs its own roll of paper on a level floor, whatever the report's scenario")
        }
        SnowballFiveSevenths | TptLetterClosedForm | SnowballTerminalFractions => {
            Some("the ball's closed forms start from rest and its runs are as long as the default b/r0 needs")
        }
        TerminalAccelerations | Eq35TerminalThird | Eq33_35TerminalArgument | Eq36SlowsApproach => {
            Some("the run must reach the terminal regime, whose distance grows like r0/b")
        }
        MultiTurnNeverSettles | MultiTurnMeanFourNinths | Eq78SpeedInTurnN | CollisionPotentialJump
        | Eq88EnergyBalance | Eq51_55AccretingBody => Some(
            "the turn-model checks need a log that rolls on without hopping, with tolerances set for b/r0 = 0.1",
        ),
        Fn7StallInFirstTurn | Fn10HopThreshold => {
            Some("it brackets the slope 0.01° to 1° either side, on the default body")
        }
        AppAMovingPoints => Some("its derivatives are sampled at the default slope's speeds"),
        CircularAnalysesDiffer | LagrangianDiffersFromEnergy | Eq5ContactTorque | LoneySolvesEq4
        | LoneyAccelerationCoefficient | LoneyLimitFifth | Fn7StallThreshold | FirstTurn58_64_69
        | Eq47_48AngularMomentum | Eq54CrossProduct | Eq70MassAfterFirstTurn | Eq89Collision
        | Eq73TruncatesExact | RegimeMapBorders | SnowlessDragTerminalVelocity
        | EnergyLedgerBalances => None,
    }
}

/// The set-up every check observes: the scenario, the models (the library's
/// own unless replaced by a deliberately wrong one), and the long
/// multi-turn runs, computed once and shared by the claims that read them.
#[derive(Default)]
pub struct Lab {
    scenario: Scenario,
    turns: u64,
    long_run: OnceLock<Result<TurnDigest, SimError>>,
    long_run_exact: OnceLock<Result<TurnDigest, SimError>>,
    /// The regime map's grid and rows (read by a claim and a figure).
    regime_map: OnceLock<Result<regime::MapRows, SimError>>,
    coefficients: Vec<(Derivation, Coefficients)>,
    runner: Option<Box<Runner>>,
}

impl fmt::Debug for Lab {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Lab")
            .field("scenario", &self.scenario)
            .field("turns", &self.turns)
            .field("coefficients", &self.coefficients)
            .field("runner", &self.runner.as_ref().map(|_| "replaced"))
            .finish_non_exhaustive()
    }
}

impl Lab {
    /// A lab on `scenario` whose multi-turn claims run `turns` turns (the
    /// report uses 10^5; fewer turns give looser long-run means).
    pub fn new(scenario: Scenario, turns: u64) -> Self {
        Self {
            scenario,
            turns: turns.max(10),
            ..Self::default()
        }
    }

    /// A deliberately wrong model: the circular model of `derivation` runs
    /// with `coefficients` (for the tests that see a verdict change).
    pub fn with_coefficients(mut self, derivation: Derivation, coefficients: Coefficients) -> Self {
        self.coefficients.retain(|(d, _)| *d != derivation);
        self.coefficients.push((derivation, coefficients));
        self
    }

    /// A deliberately wrong model: `runner` replaces the run of every model
    /// for which it returns `Some`.
    pub fn with_runner(
        mut self,
        runner: impl Fn(ModelKind, &Scenario, &SimOptions) -> Option<Result<Trajectory, SimError>>
            + Send
            + Sync
            + 'static,
    ) -> Self {
        self.runner = Some(Box::new(runner));
        self
    }

    /// A deliberately wrong long run: `table` replaces the long run of
    /// `turns-exact` (`exact`) or `turns`.
    pub fn with_long_run(self, exact: bool, table: TurnTable) -> Self {
        let cell = OnceLock::new();
        let _ = cell.set(Ok(TurnDigest::from_table(&table, &self.scenario)));
        if exact {
            Self {
                long_run_exact: cell,
                ..self
            }
        } else {
            Self {
                long_run: cell,
                ..self
            }
        }
    }

    /// The scenario.
    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }

    /// Number of turns of the long runs.
    pub fn turns(&self) -> u64 {
        self.turns
    }

    /// Runs `kind` on `scenario`: the library's model, unless this lab
    /// replaces it.
    ///
    /// # Errors
    /// [`SimError`] from the run.
    pub fn run(
        &self,
        kind: ModelKind,
        scenario: &Scenario,
        opts: &SimOptions,
    ) -> Result<Trajectory, SimError> {
        if let Some(result) = self.runner.as_ref().and_then(|r| r(kind, scenario, opts)) {
            return result;
        }
        match kind.derivation() {
            Some(d) => {
                // The library's model takes its coefficients from the
                // scenario's shape; a replacement runs as given.
                let model = self
                    .coefficients
                    .iter()
                    .find(|(dd, _)| *dd == d)
                    .map_or_else(
                        || CircularModel::new(d),
                        |(_, c)| CircularModel::with_coefficients(d, *c),
                    );
                snowroll::models::Model::simulate(&model, scenario, opts)
            }
            None => kind.build().simulate(scenario, opts),
        }
    }

    /// The long run of `turns` (eq. (73)) or `turns-exact`, computed on first use.
    ///
    /// # Errors
    /// [`SimError`] if the run fails (the error is kept and returned again).
    pub fn long_run(&self, exact: bool) -> Result<&TurnDigest, SimError> {
        let (cell, kind) = if exact {
            (&self.long_run_exact, ModelKind::TurnsExact)
        } else {
            (&self.long_run, ModelKind::Turns)
        };
        let opts = SimOptions {
            t_end: 1e9,
            turns: Some(self.turns),
            sampling: Sampling::Ends,
            // The digest keeps a bounded part of the rows, so their number
            // is no limit.
            max_rows: u64::MAX,
            ..SimOptions::default()
        };
        cell.get_or_init(|| {
            // The rows go by once; memory does not grow with the turns.
            let mut sink = DigestSink::new(&self.scenario, self.turns);
            let end = run_turns_into(kind, &self.scenario, &opts, &mut sink)?;
            Ok(sink.finish(end))
        })
        .as_ref()
        .map_err(Clone::clone)
    }

    /// The regime map's grid and one row per point ([`regime::map_rows`]),
    /// computed on first use and shared by the claim and the figure.
    ///
    /// # Errors
    /// [`SimError`] if the grid cannot be made (kept and returned again).
    pub(crate) fn regime_map(&self) -> Result<&regime::MapRows, SimError> {
        self.regime_map
            .get_or_init(|| regime::map_rows(self))
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The acceleration of `kind` at the state (radius `r`, speed `v`), m/s²:
    /// the first sample of a run started there (`r0 = r`, `v0 = v`). A
    /// circular model's state enters its equation only through r and v.
    ///
    /// # Errors
    /// [`SimError`] from the run.
    pub fn acceleration_at(&self, kind: ModelKind, r: f64, v: f64) -> Result<f64, SimError> {
        let s = edited(
            &self.scenario,
            Edit {
                r0: Some(r),
                v0: Some(v),
                ..Edit::default()
            },
        )?;
        let opts = SimOptions {
            t_end: 1e-9,
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        let traj = self.run(kind, &s, &opts)?;
        Ok(traj.samples.first().map_or(f64::NAN, |p| p.a_m_s2))
    }
}

/// What a check found.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// The finding in one sentence, composed from the numbers the check
    /// measured, where it has such numbers; `None` for the table's sentence
    /// of the verdict reached ([`crate::headline`]). A headline is printed
    /// only beside the verdict its check expects: any other verdict gets a
    /// sentence that says so instead.
    pub headline: Option<String>,
    /// The measured numbers, with units.
    pub measured: String,
    /// The verdict reached.
    pub verdict: Verdict,
    /// The comparison behind the verdict.
    pub evidence: String,
}

/// A claim with the computation that judges it.
#[derive(Debug, Clone, Copy)]
pub struct ClaimCheck {
    /// The claim.
    pub claim: Claim,
    /// The computation.
    pub check: fn(&Lab) -> Result<Finding, SimError>,
}

impl ClaimCheck {
    /// Runs the check.
    ///
    /// # Errors
    /// [`SimError`] if a simulation fails.
    pub fn run(&'static self, lab: &Lab) -> Result<ClaimResult, SimError> {
        let f = (self.check)(lab)?;
        Ok(ClaimResult {
            claim: &self.claim,
            headline: f.headline,
            measured: f.measured,
            verdict: f.verdict,
            evidence: f.evidence,
        })
    }
}

/// Scenario parameters a check changes; the rest stay the lab's.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Edit {
    /// Slope, degrees.
    pub alpha_deg: Option<f64>,
    /// Snow depth b, m.
    pub snow_depth: Option<f64>,
    /// Initial radius r0, m.
    pub r0: Option<f64>,
    /// Initial speed v0, m/s.
    pub v0: Option<f64>,
    /// Gravitational acceleration g, m/s².
    pub g: Option<f64>,
    /// The body's shape (a ball takes its natural swath 2r).
    pub shape: Option<snowroll::scenario::Shape>,
}

/// `s` with the parameters of `edit` changed (the one place that names the
/// scenario's fields).
pub(super) fn edited(s: &Scenario, edit: Edit) -> Result<Scenario, SimError> {
    let mut f = ScenarioFile::from(*s);
    if let Some(v) = edit.alpha_deg {
        f.alpha_deg = v;
    }
    if let Some(v) = edit.snow_depth {
        f.snow_depth = v;
    }
    if let Some(v) = edit.r0 {
        f.r0 = v;
    }
    if let Some(v) = edit.v0 {
        f.v0 = v;
    }
    if let Some(v) = edit.g {
        f.g = v;
    }
    if let Some(v) = edit.shape {
        f.shape = v;
        f.swath_width = None;
    }
    Ok(Scenario::new(f)?)
}

/// The scenario in the note's symbols.
#[derive(Debug, Clone, Copy)]
pub(super) struct Symbols {
    /// Snow depth b, m.
    pub b: f64,
    /// Initial radius r0, m.
    pub r0: f64,
    /// G = g sin α, m/s².
    pub gs: f64,
    /// C = g cos α, m/s².
    pub gc: f64,
    /// ρl, kg/m.
    pub rho_l: f64,
}

/// `s` in the note's symbols.
pub(super) fn symbols(s: &Scenario) -> Symbols {
    Symbols {
        b: s.snow_depth(),
        r0: s.initial_radius(),
        gs: s.g_along(),
        gc: s.g_normal(),
        rho_l: s.density() * s.length(),
    }
}

/// The scenario's slope, degrees.
pub(super) fn alpha_deg(s: &Scenario) -> f64 {
    s.slope_angle().to_degrees()
}

/// a/G at the last sample of a run (NaN if there is none).
pub(super) fn last_a_over_g(
    lab: &Lab,
    kind: ModelKind,
    s: &Scenario,
    opts: &SimOptions,
) -> Result<f64, SimError> {
    let traj = lab.run(kind, s, opts)?;
    Ok(traj
        .samples
        .last()
        .map_or(f64::NAN, |p| p.a_m_s2 / s.g_along()))
}

/// Whether every number is finite.
pub(super) fn finite(numbers: &[f64]) -> bool {
    numbers.iter().all(|x| x.is_finite())
}

/// Holds when `ok`; inconclusive when a number behind it is not finite;
/// refuted otherwise.
pub(super) fn holds_if(ok: bool, numbers: &[f64]) -> Verdict {
    if !finite(numbers) {
        Verdict::Inconclusive
    } else if ok {
        Verdict::Holds
    } else {
        Verdict::Refuted
    }
}

/// For a claim printed with an erratum: holds as printed when the printed
/// form passes; after correction when the corrected form passes and the
/// printed one is shown apart; inconclusive on non-finite numbers; refuted
/// otherwise.
pub(super) fn corrected_if(
    printed_ok: bool,
    corrected_ok: bool,
    printed_apart: bool,
    erratum: &'static str,
    numbers: &[f64],
) -> Verdict {
    if !finite(numbers) {
        Verdict::Inconclusive
    } else if printed_ok {
        Verdict::Holds
    } else if corrected_ok && printed_apart {
        Verdict::HoldsAfterCorrection(erratum)
    } else {
        Verdict::Refuted
    }
}

/// A refutation: refuted when the claim fails *and* the check measured
/// what holds instead; holds when the claim does not fail; inconclusive
/// when it fails but what holds instead was not established.
pub(super) fn refuted_if(claim_fails: bool, truth_holds: bool) -> Verdict {
    match (claim_fails, truth_holds) {
        (true, true) => Verdict::Refuted,
        (false, _) => Verdict::Holds,
        (true, false) => Verdict::Inconclusive,
    }
}

/// "within" or "OUTSIDE", for evidence text followed by the bound.
pub(super) fn pass(ok: bool) -> &'static str {
    if ok {
        "within"
    } else {
        "OUTSIDE"
    }
}

/// "within relative 1e-6" or "OUTSIDE relative 1e-6": a criterion's outcome
/// with its bound, for evidence text.
pub(super) fn bound(criterion: &Criterion, ok: bool) -> String {
    format!("{} {}", pass(ok), criterion.tolerance)
}
