//! The captions of the report's model figures: each chart with the numbers
//! its caption quotes, its scenario and the claims it supports.

use super::charts::{Charts, CircularRuns};
use super::looks::{circular_models, same_equation_groups};
use super::APPROACH_FLOOR;
use crate::notation;
use crate::{ClaimId, Figure, Lab, TurnDigest};
use snowroll::scenario::{Scenario, ScenarioFile};
use snowroll::trajectory::SimOptions;

/// What the long run of `paper` means physically: its last radius and the
/// distance rolled, m (rₖ = r₀ + k b; x = Σ 2π rₖ over the turns).
fn long_run_extent(paper: &TurnDigest, s: &Scenario) -> (f64, f64) {
    let k = paper.turns as f64;
    let (r0, b) = (s.initial_radius(), s.snow_depth());
    (
        r0 + k * b,
        std::f64::consts::TAU * (k * r0 + b * k * (k - 1.0) / 2.0),
    )
}

/// The figures of the report, each with its caption and the claims it
/// supports, in the order they are shown.
pub(super) fn figures(
    charts: Charts,
    runs: &CircularRuns,
    paper: &TurnDigest,
    lab: &Lab,
    opts: &SimOptions,
) -> Vec<Figure> {
    let file = ScenarioFile::from(*lab.scenario());
    // Each figure's footer names the scenario; the full list is in the metadata.
    let short = |f: Figure| {
        f.param("alpha_deg", file.alpha_deg)
            .param("snow_depth", file.snow_depth)
            .param("r0", file.r0)
            .param("v0", file.v0)
            .param("rtol", format!("{:e}", opts.tolerances.rtol))
    };
    // The terminal values in the caption come from the library's coefficients.
    let terminal_values = same_equation_groups(&circular_models())
        .iter()
        .filter_map(|group| {
            group[0].terminal_fraction().map(|f| {
                let eqs = group.iter().map(|k| k.equation()).collect::<Vec<_>>();
                format!("{} for {}", notation::fixed(f, 4), eqs.join(" = "))
            })
        })
        .collect::<Vec<_>>()
        .join(", ");
    let overall = paper.summary.overall();
    let in_turn_mean = overall.map_or(f64::NAN, |c| c.window_mean_a_turn_over_g);
    let with_collisions = overall.map_or(f64::NAN, |c| c.window_mean_a_with_collision_over_g);
    let same = runs.caption();
    let extent = long_run_extent(paper, lab.scenario());
    let kinetic_share = paper
        .ledger
        .last()
        .map_or(f64::NAN, |p| p.kinetic_j / p.released_j);
    let Charts {
        accel,
        speed,
        radius,
        approach,
        in_turn,
        means,
        ledger,
    } = charts;
    vec![
        Figure::new(accel, &format!("a/(g sin α) against time for every model from rest on the default slope. The circular models of §2 each tend to their own terminal value ({terminal_values}); the turn-by-turn models (markers: the mean over each turn) settle near {} within a turn over the last decade of the long run. {same} Curves that lie close differ in dash pattern and markers as well as colour.", notation::fixed(in_turn_mean, 4))).supports(&[ClaimId::CircularAnalysesDiffer, ClaimId::TerminalAccelerations, ClaimId::Eq35TerminalThird, ClaimId::LoneyLimitFifth, ClaimId::MultiTurnNeverSettles]),
        Figure::new(speed, &format!("Speed against time. After the first seconds every model's speed grows linearly, at its terminal acceleration. {same}")).supports(&[ClaimId::TerminalAccelerations]),
        Figure::new(radius, "Radius against time: π r² = π r₀² + b x (eq. (8)); the turn models grow by b per full turn.").supports(&[ClaimId::Eq70MassAfterFirstTurn]),
        Figure::new(approach, &format!("How fast each circular model approaches its terminal acceleration: |a − a∞| against x, one curve per equation (eq. (4) stands for Loney's fn. 4, its closed form). Models with only the v² term approach as a power, ∝ r⁻ᵖ with p = 2(1 + 2cᵥ) (x{} for eq. (4), fn. 4); the snow-lifting term of eqs. (14), (15), (21), (36) slows this to 1/r. The dips near x = 10 m are where a − a∞ changes sign; curves stop at {}, the accuracy of the integration.", notation::superscript("-10/3"), notation::number(APPROACH_FLOOR, 1))).supports(&[ClaimId::Eq36SlowsApproach, ClaimId::Eq33_35TerminalArgument, ClaimId::LoneyLimitFifth]),
        Figure::new(in_turn, "The acceleration of the turn-by-turn model over its first turns: it starts each turn near 2G/3, dips within the turn, and the speed drops at each collision (eq. (89)). eq. (73) is the note's O(b/r) equation, exact geometry the full mass properties.").supports(&[ClaimId::MultiTurnNeverSettles, ClaimId::FirstTurn58_64_69, ClaimId::Eq89Collision, ClaimId::Eq73TruncatesExact]),
        Figure::new(means, &format!("Mean acceleration over many turns, against the number of turns K: over the last decade of {} turns it is {} G within turns and {} G including the collisions, not the note's 4G/9 (eq. (79)).", paper.summary.turns, notation::fixed(in_turn_mean, 4), notation::fixed(with_collisions, 4))).supports(&[ClaimId::MultiTurnMeanFourNinths, ClaimId::MultiTurnNeverSettles]),
        Figure::new(ledger, &format!("Where the energy goes in the turn-by-turn model (eq. (73)), as shares of the energy released within the turns: the kinetic energy after each collision and what the collisions removed add up to 1 (squares). After {} turns the log keeps a share of {} as kinetic energy; the collisions took the rest. The long run is a mathematical limit, not a hill: after {} turns the log has r = {} m and has rolled x = {} m.", paper.summary.turns, notation::fixed(kinetic_share, 3), paper.summary.turns, notation::number(extent.0, 2), notation::number(extent.1, 2))).supports(&[ClaimId::Eq88EnergyBalance, ClaimId::Eq89Collision, ClaimId::CollisionPotentialJump]),
    ]
    .into_iter()
    .map(short)
    .collect()
}
