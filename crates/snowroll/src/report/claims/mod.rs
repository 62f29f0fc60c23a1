//! The claims of the note and the computations that judge them: one table,
//! [`CLAIMS`], read by the `paper` report and by `tests/claims.rs`, so the
//! two cannot disagree.
//!
//! Each check runs the models (or evaluates the note's formulae) on the
//! scenario of a [`Lab`] and returns a [`Finding`]: the numbers, the
//! verdict, and the evidence. Tolerances are stated in each [`Claim`].

//! The checks live by part of the note: [`circular`] (§2, App. A),
//! [`first_turn`] (§3.1–3.3 and its errata), [`multi_turn`] (§3.4).

mod circular;
mod first_turn;
mod multi_turn;

use std::sync::OnceLock;

use super::{Claim, ClaimResult, Tolerance, Verdict};
use crate::error::SimError;
use crate::models::{run_turns, ModelKind, TurnTable};
use crate::scenario::{Scenario, ScenarioFile};
use crate::trajectory::{Sampling, SimOptions, Trajectory};

use circular::{
    circular_agree_as_b_vanishes, circular_differ, eq35_third, eq36_slows, lagrangian_vs_energy,
    loney_closed_form, loney_coefficient, loney_limit, snowless, stall_threshold, terminal_values,
};
use first_turn::{eq54_erratum, eq70_mass, first_turn_equivalence};
use multi_turn::{collision_loss, eq78_speed, eq88_balance, mean_four_ninths, never_settles};

/// The set-up every check runs on, with the long multi-turn runs computed
/// once and shared by the claims that read them.
#[derive(Debug, Default)]
pub struct Lab {
    scenario: Scenario,
    turns: u64,
    long_run: OnceLock<Result<TurnTable, SimError>>,
    long_run_exact: OnceLock<Result<TurnTable, SimError>>,
}

impl Lab {
    /// A lab on `scenario` whose multi-turn claims run `turns` turns (the
    /// report uses 10^5; fewer turns give looser long-run means).
    pub fn new(scenario: Scenario, turns: u64) -> Self {
        Self {
            scenario,
            turns: turns.max(10),
            long_run: OnceLock::new(),
            long_run_exact: OnceLock::new(),
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

    /// The long run of `turns` (eq. (73)) or `turns-exact`, computed on first use.
    ///
    /// # Errors
    /// [`SimError`] if the run fails (the error is kept and returned again).
    pub fn long_run(&self, exact: bool) -> Result<&TurnTable, SimError> {
        let (cell, kind) = if exact {
            (&self.long_run_exact, ModelKind::TurnsExact)
        } else {
            (&self.long_run, ModelKind::Turns)
        };
        let opts = SimOptions {
            t_end: 1e9,
            turns: Some(self.turns),
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        cell.get_or_init(|| run_turns(kind, &self.scenario, &opts))
            .as_ref()
            .map_err(Clone::clone)
    }
}

/// What a check found.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
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
            measured: f.measured,
            verdict: f.verdict,
            evidence: f.evidence,
        })
    }
}

pub(super) fn with(
    s: &Scenario,
    edit: impl FnOnce(&mut ScenarioFile),
) -> Result<Scenario, SimError> {
    let mut f = ScenarioFile::from(*s);
    edit(&mut f);
    Ok(Scenario::new(f)?)
}

pub(super) fn run(
    kind: ModelKind,
    s: &Scenario,
    opts: &SimOptions,
) -> Result<Trajectory, SimError> {
    kind.build().simulate(s, opts)
}

pub(super) fn last_a_over_g(
    kind: ModelKind,
    s: &Scenario,
    opts: &SimOptions,
) -> Result<f64, SimError> {
    let traj = run(kind, s, opts)?;
    Ok(traj
        .samples
        .last()
        .map_or(f64::NAN, |p| p.a_m_s2 / s.g_along()))
}

pub(super) fn holds_if(ok: bool, otherwise: Verdict) -> Verdict {
    if ok {
        Verdict::Holds
    } else {
        otherwise
    }
}

/// The table of claims: each row is judged by its check.
pub static CLAIMS: &[ClaimCheck] = &[
    ClaimCheck {
        claim: Claim {
            id: "circular-analyses-differ",
            paper_ref: "§2.1–2.3, eqs. (4), (6), (14), (21)",
            statement: "The four analyses of the always-circular log give four different equations of motion.",
            method: "integrate each from rest (default scenario) and compare a/(g sin α) at t = 10 s",
            tolerance: Tolerance::Absolute { value: 1e-3, unit: "1" },
            expected: Verdict::Holds,
        },
        check: circular_differ,
    },
    ClaimCheck {
        claim: Claim {
            id: "circular-agree-as-b-vanishes",
            paper_ref: "§2.1.3, §2.3, App. A",
            statement: "All four agree with the snowless (2/3) g sin α as b → 0.",
            method: "largest |a/G − 2/3| over 5 s for b = 1e-6, 1e-8, 1e-10 m; must fall like b",
            tolerance: Tolerance::Relative { value: 0.1 },
            expected: Verdict::Holds,
        },
        check: circular_agree_as_b_vanishes,
    },
    ClaimCheck {
        claim: Claim {
            id: "lagrangian-differs-from-energy",
            paper_ref: "§2.3, eqs. (19)–(21)",
            statement: "The Lagrangian equation of motion (21) differs slightly from the energy equation (14).",
            method: "restore ∂T/∂x in (19) and compare the resulting acceleration with (14) on a grid of (x, v); compare terminal values",
            tolerance: Tolerance::Absolute { value: 1e-14, unit: "g sin α" },
            expected: Verdict::Refuted,
        },
        check: lagrangian_vs_energy,
    },
    ClaimCheck {
        claim: Claim {
            id: "loney-solves-eq4",
            paper_ref: "fn. 4",
            statement: "Loney's closed form v² = 2G s/(5b) + K/s^(7/3) solves eq. (4).",
            method: "integrate eq. (4) to x = 10 km for three scenarios and compare v(x)",
            tolerance: Tolerance::Relative { value: 1e-9 },
            expected: Verdict::Holds,
        },
        check: loney_closed_form,
    },
    ClaimCheck {
        claim: Claim {
            id: "loney-acceleration-coefficient",
            paper_ref: "fn. 4",
            statement: "The acceleration is a = (g/5) sin α − 7bC/[3 (π r0² + b x)^(10/3)].",
            method: "compare with ½ du/dx of the closed form (central difference)",
            tolerance: Tolerance::Relative { value: 1e-6 },
            expected: Verdict::HoldsAfterCorrection("errata fn. 4: 7bC/6"),
        },
        check: loney_coefficient,
    },
    ClaimCheck {
        claim: Claim {
            id: "loney-limit-fifth",
            paper_ref: "fn. 4",
            statement: "Under eq. (4) the acceleration tends to (g/5) sin α.",
            method: "closed form and integration at x = 10⁷ r0",
            tolerance: Tolerance::Absolute { value: 1e-6, unit: "g sin α" },
            expected: Verdict::Holds,
        },
        check: loney_limit,
    },
    ClaimCheck {
        claim: Claim {
            id: "terminal-accelerations",
            paper_ref: "§2.4, eqs. (4), (6), (14), (15), (21), (32), (36)",
            statement: "Each circular equation of motion has a terminal acceleration (the note gives G/5 for (4) and G/3 for (32)).",
            method: "integrate each to x = 10⁷ r0 and compare with a∞ = (2G/3)/(1 + 2c_v) derived from its coefficients; measure the power of r in |a − a∞| and compare with the derived rate (2 %)",
            tolerance: Tolerance::Relative { value: 1e-3 },
            expected: Verdict::Holds,
        },
        check: terminal_values,
    },
    ClaimCheck {
        claim: Claim {
            id: "eq35-terminal-third",
            paper_ref: "eq. (35)",
            statement: "Under eq. (32) the acceleration tends to g sin α / 3.",
            method: "integrate eq. (32) to x = 1000 km",
            tolerance: Tolerance::Absolute { value: 1e-6, unit: "g sin α" },
            expected: Verdict::Holds,
        },
        check: eq35_third,
    },
    ClaimCheck {
        claim: Claim {
            id: "eq36-slows-approach",
            paper_ref: "§2.4, term (36)",
            statement: "A lift term −g b cos α/(π r) does not change the terminal value but slows the approach to it.",
            method: "log-slope of |a − G/3| against r for (32) and for (32)+(36)",
            tolerance: Tolerance::Absolute { value: 0.05, unit: "power of r" },
            expected: Verdict::Holds,
        },
        check: eq36_slows,
    },
    ClaimCheck {
        claim: Claim {
            id: "fn7-stall-threshold",
            paper_ref: "fn. 7",
            statement: "A log too light for the snow does not start: it must lift the snow it collects.",
            method: "closed-form critical slope of eq. (14); simulate 0.01° below and above it",
            tolerance: Tolerance::Absolute { value: 0.01, unit: "degree" },
            expected: Verdict::Holds,
        },
        check: stall_threshold,
    },
    ClaimCheck {
        claim: Claim {
            id: "snowless-two-thirds",
            paper_ref: "App. A, eqs. (95)–(130)",
            statement: "Without snow a rolling cylinder accelerates at (2/3) g sin α, whichever way it is derived.",
            method: "every model at b = 0: a(t) and x(t) = G t²/3",
            tolerance: Tolerance::Relative { value: 1e-12 },
            expected: Verdict::Holds,
        },
        check: snowless,
    },
    ClaimCheck {
        claim: Claim {
            id: "first-turn-58-64-69",
            paper_ref: "§3.1–3.3, eqs. (58), (63), (64), (68), (69)",
            statement: "Torque (58), energy (64) and Lagrangian (69) analyses of the first turn give the same equation of motion.",
            method: "evaluate each for θ over a turn and three speeds, (64) and (69) from V of eq. (62) differentiated numerically",
            tolerance: Tolerance::Absolute { value: 1e-8, unit: "g sin α" },
            expected: Verdict::HoldsAfterCorrection("errata (58) m→m0, (63) θ/π→bθ/π, (68)–(69) b/π→bθ/π"),
        },
        check: first_turn_equivalence,
    },
    ClaimCheck {
        claim: Claim {
            id: "eq54-cross-product",
            paper_ref: "eq. (54)",
            statement: "(x_cm − x_C) × m a_cm = −m0[r0² θ̈ + (b r/π)(θθ̈ − 2θ̇ sin θ − θ̇² cos θ)] to O(b).",
            method: "compare with the cross product of (43) and (45) evaluated exactly, at two b: the residual must be O(b²)",
            tolerance: Tolerance::Relative { value: 0.05 },
            expected: Verdict::HoldsAfterCorrection("errata (54): θ̈ for θ̇, r0 for r"),
        },
        check: eq54_erratum,
    },
    ClaimCheck {
        claim: Claim {
            id: "eq70-mass-after-first-turn",
            paper_ref: "eq. (70)",
            statement: "After the first turn the log has mass m1 = 2πρ l r1².",
            method: "exact mass of disk plus full annulus of depth b",
            tolerance: Tolerance::Relative { value: 1e-14 },
            expected: Verdict::HoldsAfterCorrection("errata (70): m1 = πρl r1²"),
        },
        check: eq70_mass,
    },
    ClaimCheck {
        claim: Claim {
            id: "multi-turn-never-settles",
            paper_ref: "§3.4, eqs. (77)–(79)",
            statement: "The acceleration of the log turn by turn never settles: it oscillates within every turn.",
            method: "simulate eq. (73) for many turns (10⁵ in the report); range of a/G within the turns of the last decade",
            tolerance: Tolerance::Absolute { value: 0.5, unit: "g sin α (smallest swing)" },
            expected: Verdict::Holds,
        },
        check: never_settles,
    },
    ClaimCheck {
        claim: Claim {
            id: "multi-turn-mean-four-ninths",
            paper_ref: "eq. (79)",
            statement: "On average the multi-turn log accelerates at 4 g sin α / 9.",
            method: "mean of a over the turns of the last decade of a long run, within turns and including the collisions, for eq. (73) and exact geometry",
            tolerance: Tolerance::Absolute { value: 0.01, unit: "g sin α" },
            expected: Verdict::Refuted,
        },
        check: mean_four_ninths,
    },
    ClaimCheck {
        claim: Claim {
            id: "eq78-speed-in-turn-n",
            paper_ref: "eq. (78)",
            statement: "In the n-th turn v² ≈ π g n² b sin α / 3.",
            method: "v²/(π g n² b sin α) at the start of the last turn of a long run",
            tolerance: Tolerance::Absolute { value: 0.02, unit: "1" },
            expected: Verdict::Refuted,
        },
        check: eq78_speed,
    },
    ClaimCheck {
        claim: Claim {
            id: "eq89-collision",
            paper_ref: "eq. (89)",
            statement: "In the collision at the end of a turn the angular momentum about the contact line is conserved.",
            method: "L_C and T before/after each of the first 1000 collisions of eq. (73), against the closed-form ratio",
            tolerance: Tolerance::Relative { value: 1e-12 },
            expected: Verdict::Holds,
        },
        check: collision_loss,
    },
    ClaimCheck {
        claim: Claim {
            id: "eq88-energy-balance",
            paper_ref: "eqs. (86)–(88)",
            statement: "Energy conservation within a turn, T_beg = T_end + V_end with V_end of (87), gives v at the end of the turn.",
            method: "v_end from (88) against the integrated turns, exact geometry and eq. (73), corrected and printed (87)",
            tolerance: Tolerance::Relative { value: 1e-9 },
            expected: Verdict::HoldsAfterCorrection("errata (87): V = Δm g (r + b/2) cos α − (m − Δm/2) g 2πr sin α"),
        },
        check: eq88_balance,
    },
];
