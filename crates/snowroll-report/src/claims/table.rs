//! The table of claims, [`CLAIMS`]: each row's tolerances are the constants
//! its check compares with, and each expected verdict that names an erratum
//! uses the same constant as the check.

use super::app_a::{
    app_a_moving_points, snowless_limit, APP_A_APART, APP_A_INTEGRALS, ERRATUM_APP_A,
    SNOWLESS_LIMIT,
};
use super::circular::{
    circular_agree_as_b_vanishes, circular_differ, eq5_contact_torque, lagrangian_vs_energy,
    loney_closed_form, loney_coefficient, loney_limit, stall_threshold, DIFFER,
    DIFFER_COEFFICIENTS, DIFFER_TERMINAL, EQ5_PRINTED_APART, EQ5_TORQUE, ERRATUM_5, ERRATUM_FN4,
    LAGRANGE_APART, LAGRANGE_CORRECTED, LAGRANGE_DIFFERENCE, LONEY_DERIVATIVE, LONEY_LIMIT,
    LONEY_PRINTED_APART, LONEY_SPEED, SPREAD_LINEAR, SPREAD_SMALL, STALL_BISECTION, STALL_MARGIN,
};
use super::contact::{hop_threshold, HOP_LATE_MIN, HOP_MARGIN};
use super::first_turn::{
    eq47_48_angular_momentum, eq51_55_accreting_body, eq54_erratum, eq70_mass,
    first_turn_equivalence, ACCRETING_B3, ACCRETING_ORDER, EQ47_48_APART, EQ47_48_MATCH,
    EQ48_ORDER, EQ54_ORDER, ERRATUM_47_48, ERRATUM_54, ERRATUM_58_69, ERRATUM_70, FIRST_TURN_AGREE,
    FIRST_TURN_APART, MASS_EXACT, MASS_FIRST_ORDER, MASS_PRINTED_APART,
};
use super::losses::{
    drag_terminal_velocity, ledger_balances, DRAG_TERMINAL, LEDGER_BALANCE, LEDGER_CONSERVED,
    LEDGER_W4,
};
use super::multi_turn::{
    collision_loss, collision_potential_jump, eq73_truncates_exact, eq78_speed, eq88_balance,
    mean_four_ninths, never_settles, COLLISION_L, COLLISION_T, EQ88_APART, EQ88_EXACT, ERRATUM_87,
    JUMP_ORDER, LONG_RUN, NOTE_APART, SWING, TRUNCATION_ORDER,
};
use super::regime::{map_borders, MAP_CELL, MAP_HOP_BISECTED, MAP_STALL_BISECTED};
use super::slip::{slip_mu_min, MU_AT_END, MU_AT_REST};
use super::snowball::{
    ball_terminal_fractions, five_sevenths, tpt_letter, BALL_TERMINAL_LIMIT, FIVE_SEVENTHS,
    TPT_CLOSED_FORM, TPT_OTHERS_APART,
};
use super::stall::{
    stall_in_first_turn, TURN_STALL_EXACT, TURN_STALL_FORMULA, TURN_STALL_LIBRARY,
    TURN_STALL_MARGIN, TURN_STALL_ORDER, TURN_START, TURN_START_EXACT,
};
use super::terminal::{
    eq33_35_argument, eq35_third, eq36_slows, terminal_values, APPROACH_POWER, EQ33_DERIVATIVE,
    EQ33_PRINTED_APART, EQ34_LATE, EQ35_LIMIT, EQ35_POSITION, ERRATUM_33_35, TERMINAL_LIMIT,
    TERMINAL_PRINTED,
};
use super::unwinding::{
    unwinding_hollow_roll, unwinding_textbook_speed, HOLLOW_ROLL, UNWINDING_SPEED,
};
use super::ClaimCheck;
use crate::{Claim, ClaimId, Verdict};

/// The table of claims: each row is judged by its check.
pub static CLAIMS: &[ClaimCheck] = &[
    ClaimCheck {
        claim: Claim {
            id: ClaimId::CircularAnalysesDiffer,
            paper_ref: "§2.1–2.3, eqs. (4), (6), (14), (21)",
            statement: "The four analyses of the always-circular log give four different equations of motion.",
            method: "read the coefficients c_v of b v²/(πr²) and λ of the lift C(3br + b²)/(3πr²) off each model's acceleration at rest and at b v²/(πr²) = G, at r = r0, 3r0, 10r0, against the printed 7/6, 3/2, 1/2, 1 and 0, 0, 1, 1; the terminal fractions (2/3)/(1 + 2c_v) they imply (1/5, 1/6, 1/3, 2/9) must be apart; and each integrated from rest, a/(g sin α) at t = 10 s",
            tolerances: &[DIFFER_COEFFICIENTS, DIFFER_TERMINAL, DIFFER],
            expected: Verdict::Holds,
        },
        check: circular_differ,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::CircularAgreeAsBVanishes,
            paper_ref: "§2.1.3, §2.3, App. A",
            statement: "All four agree with the snowless (2/3) g sin α as b → 0.",
            method: "largest |a/G − 2/3| over 5 s for b = 1e-6, 1e-8, 1e-10 m; must fall like b",
            tolerances: &[SPREAD_LINEAR, SPREAD_SMALL],
            expected: Verdict::Holds,
        },
        check: circular_agree_as_b_vanishes,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::LagrangianDiffersFromEnergy,
            paper_ref: "§2.3, eqs. (19)–(21)",
            statement: "The Lagrangian equation of motion (21) differs slightly from the energy equation (14).",
            method: "on a grid of states (r, v): the models' accelerations (first sample of a run started there) against (21) with ∂T/∂x restored and against the derived difference −(bv²/2πr²)/(1 + b²/6π²r²)",
            tolerances: &[LAGRANGE_CORRECTED, LAGRANGE_DIFFERENCE, LAGRANGE_APART],
            expected: Verdict::Refuted,
        },
        check: lagrangian_vs_energy,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq5ContactTorque,
            paper_ref: "§2.1.2, eq. (5)",
            statement: "The torque about the contact line equals d(3mr²/2)/dt, which gives eq. (6).",
            method: "along the integrated eq. (6): d(3mrv/2)/dt and d(3mr²/2)/dt by central differences of the samples, against r m g sin α",
            tolerances: &[EQ5_TORQUE, EQ5_PRINTED_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_5),
        },
        check: eq5_contact_torque,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::LoneySolvesEq4,
            paper_ref: "fn. 4",
            statement: "Loney's closed form v² = 2G s/(5b) + K/s^(7/3) solves eq. (4).",
            method: "integrate eq. (4) to x = 10 km for three scenarios and compare v(x) with fn. 4's u(x), typed here",
            tolerances: &[LONEY_SPEED],
            expected: Verdict::Holds,
        },
        check: loney_closed_form,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::LoneyAccelerationCoefficient,
            paper_ref: "fn. 4",
            statement: "The acceleration is a = (g/5) sin α − 7bK/[3 (π r0² + b x)^(10/3)].",
            method: "compare with ½ du/dx of fn. 4's u(x) (central difference)",
            tolerances: &[LONEY_DERIVATIVE, LONEY_PRINTED_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_FN4),
        },
        check: loney_coefficient,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::LoneyLimitFifth,
            paper_ref: "fn. 4",
            statement: "Under eq. (4) the acceleration tends to (g/5) sin α.",
            method: "fn. 4's u(x) differentiated and eq. (4) integrated, at x = 10⁷ r0",
            tolerances: &[LONEY_LIMIT],
            expected: Verdict::Holds,
        },
        check: loney_limit,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::TerminalAccelerations,
            paper_ref: "§2.4, eqs. (4), (6), (14), (15), (21), (32), (36)",
            statement: "Each circular equation of motion has a terminal acceleration (the note gives G/5 for (4) and G/3 for (32)).",
            method: "integrate each to x = 10⁷ r0; compare a/G with the limit (2/3)/(1 + 2c) derived here from the drag coefficient c of the printed equation (plus its derived 1/r term where there is lift), and with the note's G/5, G/3; the measured power of r in |a − a∞| against the derived one",
            tolerances: &[TERMINAL_LIMIT, TERMINAL_PRINTED, APPROACH_POWER],
            expected: Verdict::Holds,
        },
        check: terminal_values,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq35TerminalThird,
            paper_ref: "eq. (35)",
            statement: "Under eq. (32) the acceleration tends to g sin α / 3.",
            method: "integrate eq. (32) to x = 1000 km",
            tolerances: &[EQ35_LIMIT],
            expected: Verdict::Holds,
        },
        check: eq35_third,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq33_35TerminalArgument,
            paper_ref: "§2.4, eqs. (33)–(35)",
            statement: "Differentiating (32) gives v̈ ≈ (b/2πr²)(bv²/(2πr³) − v̇), so a∞ ≈ bv²/(2πr³); late on x ≈ a_cm t²/2 and, from (31), πr² ≈ bx.",
            method: "along the integrated eq. (32): v̈ by central differences of a against (33); at x = 1000 km, a against (34), x against a t²/2, πr² against bx",
            tolerances: &[EQ33_DERIVATIVE, EQ34_LATE, EQ35_POSITION, EQ33_PRINTED_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_33_35),
        },
        check: eq33_35_argument,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq36SlowsApproach,
            paper_ref: "§2.4, term (36)",
            statement: "A lift term −g b cos α/(π r) does not change the terminal value but slows the approach to it.",
            method: "log-slope of |a − G/3| against r for (32) and for (32)+(36), against the derived powers",
            tolerances: &[APPROACH_POWER],
            expected: Verdict::Holds,
        },
        check: eq36_slows,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Fn7StallThreshold,
            paper_ref: "fn. 7, eqs. (14), (15)",
            statement: "A log too light for the snow does not start: it must lift the snow it collects.",
            method: "closed-form critical slope from a(0) = 0 in the printed eqs. (14), (15), against bisection on the simulated models; runs just below (must not start) and just above (must keep rolling)",
            tolerances: &[STALL_BISECTION, STALL_MARGIN],
            expected: Verdict::Holds,
        },
        check: stall_threshold,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Fn7StallInFirstTurn,
            paper_ref: "fn. 7, §3, eqs. (62), (73)",
            statement: "In the setting of §3 a log that is too light for the snow starts (a(0) = 2G/3) but stalls inside its first turn.",
            method: "bisection in α on the simulated turns and turns-exact (stall inside turn 0 or not), against the closed form max ε(θ − sin θ)/(θ + ε(θ²/2 − 1 + cos θ)) typed from (62) (turns), the maximum of Q/P of the exact disk and layer integrated element by element (turns-exact), the library's threshold (shown by `snowroll models`), and the leading-order forms in ε = b/(πr0); runs just below these independent thresholds (must start, then stall in turn 0) and just above (must roll on)",
            tolerances: &[
                TURN_START,
                TURN_START_EXACT,
                TURN_STALL_FORMULA,
                TURN_STALL_EXACT,
                TURN_STALL_LIBRARY,
                TURN_STALL_ORDER,
                TURN_STALL_MARGIN,
            ],
            expected: Verdict::Holds,
        },
        check: stall_in_first_turn,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::SnowlessLimit,
            paper_ref: "App. A, eqs. (95)–(130)",
            statement: "Without snow a rolling cylinder accelerates at (2/3) g sin α, whichever way it is derived; every model tends to it as b → 0.",
            method: "every model with snow at b = 1e-7 and 1e-8 m: a and x at t = 2 s extrapolated linearly to b = 0, against 2G/3 and G t²/3",
            tolerances: &[SNOWLESS_LIMIT],
            expected: Verdict::Holds,
        },
        check: snowless_limit,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::AppAMovingPoints,
            paper_ref: "App. A.3.2, A.4.1, A.5.2, eqs. (111), (115), (127), (128)",
            statement: "About the moving contact line L′_P = I_cm ω = mr²v/2 (111); F_y − mg = 0 (115); about the point P of A.5.2, τ′_P = τ_P + rma and L′_P = L_cm.",
            method: "a rolling disk integrated element by element: L′_P and τ′_P from eqs. (105), (106) for P on the contact line, for P the geometric point (x, 2r) and for the material point at the top; the normal force the snowless model reports against m g cos α (Newton's law normal to the slope, m(ÿ − g_y), says the same for a centre at constant height: one check)",
            tolerances: &[APP_A_INTEGRALS, APP_A_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_APP_A),
        },
        check: app_a_moving_points,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::FirstTurn58_64_69,
            paper_ref: "§3.1–3.3, eqs. (58), (63), (64), (68), (69)",
            statement: "Torque (58), energy (64) and Lagrangian (69) analyses of the first turn give the same equation of motion.",
            method: "evaluate each for θ over a turn and three speeds, (64) and (69) from V of eq. (62) differentiated numerically",
            tolerances: &[FIRST_TURN_AGREE, FIRST_TURN_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_58_69),
        },
        check: first_turn_equivalence,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq47_48AngularMomentum,
            paper_ref: "§3, eqs. (47), (48)",
            statement: "An element moves with ẋ′ = ẋ − r′θ̇′ cos θ, and L_cm = −ρlθ̇ ∫{r0r′(1 − cos θ′) + …} ≈ −(m0r0²/2 + m0br0θ/π)θ̇.",
            method: "ẋ′ by central differences of the element's position; the integrand of (48) against ∫ dm (x′ − x_cm) × v′ of the disk and layer; the final line against the exact L_cm for two depths",
            tolerances: &[EQ47_48_MATCH, EQ48_ORDER, EQ47_48_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_47_48),
        },
        check: eq47_48_angular_momentum,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq54CrossProduct,
            paper_ref: "eq. (54)",
            statement: "(x_cm − x_C) × m a_cm = −m0[r0² θ̈ + (b r/π)(θθ̈ − 2θ̇ sin θ − θ̇² cos θ)] to O(b).",
            method: "compare with the cross product of (43) and (45) evaluated exactly, at two b: the residual must be O(b²)",
            tolerances: &[EQ54_ORDER],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_54),
        },
        check: eq54_erratum,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq51_55AccretingBody,
            paper_ref: "§3.1, eqs. (51)–(55)",
            statement: "The torque analysis about the contact line, eqs. (51)–(55), gives the first-turn equation of motion to first order in b.",
            method: "the rigorous angular-momentum balance of the accreting body and the energy equation, both from element integrals of the disk and layer, against each other (their derived O(b³) difference) and against (55) for two depths",
            tolerances: &[ACCRETING_B3, ACCRETING_ORDER],
            expected: Verdict::Holds,
        },
        check: eq51_55_accreting_body,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq70MassAfterFirstTurn,
            paper_ref: "eq. (70)",
            statement: "After the first turn the log has mass m1 = 2πρ l r1².",
            method: "the disk plus the layer integrated element by element, against the printed and corrected (70) and the masses turns-exact and turns report at θ = 2π",
            tolerances: &[MASS_EXACT, MASS_FIRST_ORDER, MASS_PRINTED_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_70),
        },
        check: eq70_mass,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::MultiTurnNeverSettles,
            paper_ref: "§3.4, eqs. (77)–(79)",
            statement: "The acceleration of the log turn by turn never settles: it oscillates within every turn.",
            method: "simulate both turn models for many turns (10⁵ in the report); the range of a/G within the turns of the last decade against the derived [0, 2/3]",
            tolerances: &[SWING],
            expected: Verdict::Holds,
        },
        check: never_settles,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::MultiTurnMeanFourNinths,
            paper_ref: "eq. (79)",
            statement: "On average the multi-turn log accelerates at 4 g sin α / 9.",
            method: "mean of a over the turns of the last decade of a long run, within turns and including the collisions, for both turn models, against 4/9 and against the long-run means derived from eqs. (76), (89)",
            tolerances: &[LONG_RUN, NOTE_APART],
            expected: Verdict::Refuted,
        },
        check: mean_four_ninths,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq78SpeedInTurnN,
            paper_ref: "eq. (78)",
            statement: "In the n-th turn v² ≈ π g n² b sin α / 3.",
            method: "v²/(π g n² b sin α) at the start of the last turn of a long run of both turn models, against 1/3 (and 2/3) and against the derived limit",
            tolerances: &[LONG_RUN, NOTE_APART],
            expected: Verdict::Refuted,
        },
        check: eq78_speed,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq89Collision,
            paper_ref: "eq. (89)",
            statement: "In the collision at the end of a turn the angular momentum about the contact line is conserved.",
            method: "for the first 200 and the last collision of both long runs: the speed after it predicted from the impact's geometry (the impact point where the new rim meets the slope; L about it, I_cm ω + M (c − P) × v_c, with the centres and I_cm of the disk and layer integrated element by element, the same before and after), against the run's; and the kinetic energy kept",
            tolerances: &[COLLISION_L, COLLISION_T],
            expected: Verdict::Holds,
        },
        check: collision_loss,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::CollisionPotentialJump,
            paper_ref: "§3.4, eqs. (70), (89)",
            statement: "At the collision the centre of the log rises by b; neglecting the potential energy this takes costs only a relative O(b/r) per turn.",
            method: "the rise m g b cos α from the element integrals, divided by the energy each turn releases (the kinetic energy T_end − T_beg the long run of `turns` gains over the turn, I_C of eq. (76)); that ratio times rₖ/b against the derived C/(2πG)",
            tolerances: &[JUMP_ORDER],
            expected: Verdict::Holds,
        },
        check: collision_potential_jump,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq88EnergyBalance,
            paper_ref: "eqs. (80)–(88)",
            statement: "Energy conservation within a turn, T_beg = T_end + V_end with V_end of (87), gives v at the end of the turn.",
            method: "v_end from (88) against the integrated turns, exact geometry and eq. (73); (87) corrected and printed; the turn index of (80)–(88) and of (73)",
            tolerances: &[EQ88_EXACT, EQ88_APART],
            expected: Verdict::HoldsAfterCorrection(ERRATUM_87),
        },
        check: eq88_balance,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Eq73TruncatesExact,
            paper_ref: "§3.4, eqs. (73), (76), (88)",
            statement: "The turn equation (73) holds to first order in b/r: with exact mass properties the motion differs only at second order.",
            method: "v at the end of turn 0 from rest of turns and turns-exact for b/r0 = 0.02 and 0.01",
            tolerances: &[TRUNCATION_ORDER],
            expected: Verdict::Holds,
        },
        check: eq73_truncates_exact,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::Fn10HopThreshold,
            paper_ref: "fn. 10",
            statement: "The note leaves open whether the turn-by-turn log hops (fn. 10). Answer: in late turns the smallest normal force of a turn tends to M g (cos α − ½ sin α), so the log hops iff tan α > 2 (α* = 63.435°).",
            method: "turns and turns-exact from rest for 2000 turns at α* ± 1° with the hop event on: above, it must hop; below, it must complete every turn, and the smallest N/(M g) of its last turn (2000 samples) must match cos α − ½ sin α",
            tolerances: &[HOP_MARGIN, HOP_LATE_MIN],
            expected: Verdict::Holds,
        },
        check: hop_threshold,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::SlipMuMin,
            paper_ref: "beyond the note: App. A, §2.4, fn. 4",
            statement: "The smallest coefficient of static friction that keeps a model rolling over the default run is tan α/3 for the snowless cylinder, tan α/(3 + b tan α/(π r0)) for eq. (32) and (G − a₀)/(C + b a₀/(2π r0)) for the lift models (needed at rest), and for eqs. (4), (6) the closed-form F/N at the end of the run (it grows towards (2/5) tan α and (1/2) tan α).",
            method: "max over every step of the default run (from rest, 100 s) of |F|/N, F and N from the momentum balance; against the closed forms of `docs/contact-forces.md` §5.1–§5.2 (u = v² from fn. 4's solution at the run's final radius)",
            tolerances: &[MU_AT_REST, MU_AT_END],
            expected: Verdict::Holds,
        },
        check: slip_mu_min,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::SnowballFiveSevenths,
            paper_ref: "beyond the note: App. A for a ball",
            statement: "A uniform ball (I = (2/5) M r²) rolling without slipping on a bare slope accelerates at (5/7) g sin α.",
            method: "the snowless model with shape = sphere on the default slope: a/G at every sample and x(10 s) against 5Gt²/14",
            tolerances: &[FIVE_SEVENTHS],
            expected: Verdict::Holds,
        },
        check: five_sevenths,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::SnowballTerminalFractions,
            paper_ref: "beyond the note: §2 for a ball (`docs/snowball-and-losses.md` §1.3)",
            statement: "The always-round snowball (swath 2r) tends to a/(g sin α) = 1/6 (torque about the centre, eq. (4)'s balance), 1/7 (contact line, eq. (6)), 2/7 (energy, eqs. (14), (15), (32), (32)+(36)), 5/28 (eq. (21) as printed).",
            method: "each circular model with shape = sphere from rest to x = 5e5 m; a/G against the derived fraction plus the derived 1/r approach of the models with the lift term",
            tolerances: &[BALL_TERMINAL_LIMIT],
            expected: Verdict::Holds,
        },
        check: ball_terminal_fractions,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::TptLetterClosedForm,
            paper_ref: "The Physics Teacher 57, p. 436 (2019), on S. Rubin, TPT 57 (2019); §2.1.1 (eq. (4)) for a ball",
            statement: "A snowball rolling down a snowy incline has a closed-form motion whose acceleration starts at (5/7) g sin α and tends to (1/6) g sin α (the letter's C − 60V² = 14 r A, V = dr/dt, dr/dφ = k/2π).",
            method: "the ball's torque-cm (swath 2r, so b = k) from rest for 100 s against v² = (G s/(3b))(1 − (s0/s)^{30/7}) and a = (G/6)(1 + (23/7)(s0/s)^{30/7}), s = π r² (docs/snowball-and-losses.md §1.4); the ball's other derivations at 100 s against the same v²",
            tolerances: &[TPT_CLOSED_FORM, TPT_OTHERS_APART],
            expected: Verdict::Holds,
        },
        check: tpt_letter,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::RegimeMapBorders,
            paper_ref: "fn. 7, fn. 10",
            statement: "Over slope × snow depth the turn-by-turn log started from rest stalls in its first turn below the fn. 7 slope, hops within K turns above tan α_K = (1 + ε c_C)/(½ − ε c_G) (ε = b/r_(K−1)) and rolls on between: the closed forms are the borders of the regime map.",
            method: "turns from rest for 200 turns on 48 slopes (0.5°–6° by 0.5°, 8°–56° by 4°, 58°–80° by 1°) × 7 depths (b/r0 = 0.05–0.2): in each row, the midpoint between the last stalling and first rolling slope, and between the last rolling and first hopping slope, against the closed forms typed in the check (not the library's functions); then each border bisected inside its cell, on runs of turns from rest (the stall: does the log get past turn 0; the hop: does it hop within 200 turns), against the same forms",
            tolerances: &[MAP_CELL, MAP_STALL_BISECTED, MAP_HOP_BISECTED],
            expected: Verdict::Holds,
        },
        check: map_borders,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::SnowlessDragTerminalVelocity,
            paper_ref: "fn. 5",
            statement: "The note sets dissipation aside (fn. 5). With air drag and no snow the rolling log has a terminal velocity v_t² = M g sin α/(½ ρ_a C_d A), A = 2 r0 l (docs/snowball-and-losses.md §2.2); with snow it has none (v grows like t^(1/3)).",
            method: "snowless with C_d = 1, ρ_a = 1.2 kg/m³ from rest until |a| ≤ 1e-10 g sin α/(1 + k) (stop `terminal`); its speed there against the closed form",
            tolerances: &[DRAG_TERMINAL],
            expected: Verdict::Holds,
        },
        check: drag_terminal_velocity,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::EnergyLedgerBalances,
            paper_ref: "fn. 5; eqs. (7), (10)",
            statement: "With the losses fn. 5 sets aside (air drag, rolling resistance, compaction of the snow picked up), the energy is still accounted for: the kinetic energy, the work of each loss and the energy the model's own equation destroys (W_model) add up to the potential energy released plus the initial kinetic energy (docs/snowball-and-losses.md §3).",
            method: "every circular model on 12 scenarios each, logs and balls (swath 2r) alternately, drawn from a fixed seed with all three losses; at 17 samples of each run, K from eq. (7) and the energy released from eq. (10) (their ball forms, docs/snowball-and-losses.md §1.2) computed from (x, r, v), D_comp = e_c (M − M0), the works D_drag, D_rr and W_model read from the run's ledger; W_model of energy and snowless against 0, and W_model of torque-cm from rest without losses against Loney's closed form W_4 (docs/snowball-and-losses.md §3.1)",
            tolerances: &[LEDGER_BALANCE, LEDGER_CONSERVED, LEDGER_W4],
            expected: Verdict::Holds,
        },
        check: ledger_balances,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::UnwindingTextbookSpeed,
            paper_ref: "eqs. (4), (6), (15) with b < 0",
            statement: "A roll that lays its layer down instead of picking it up (b < 0 in eq. (8), docs/unwinding.md) and starts from rest on a level floor moves, under eq. (15), as the textbook energy balance of an unrolling carpet says: v² = 4g(R³ − r³)/(3r²), √(14gR/3) at r = R/2; the torque analyses, eqs. (4) and (6), do not start it.",
            method: "energy-thin with R = 0.1 m, b = −1e-4 m, core 0.02 m, α = 0, from rest, stopped at r = 0.09, 0.07, 0.05 and 0.03 m (x_end = π(r² − R²)/b); its speed against the textbook v², typed in the check; torque-cm and torque-contact from rest on the same floor",
            tolerances: &[UNWINDING_SPEED],
            expected: Verdict::Holds,
        },
        check: unwinding_textbook_speed,
    },
    ClaimCheck {
        claim: Claim {
            id: ClaimId::UnwindingHollowRoll,
            paper_ref: "eq. (15) with b < 0",
            statement: "A real roll is hollow: its layer lies on a cardboard tube of its own mass, so M and I are not those of the uniform roll of the textbook (docs/unwinding.md, 'The core'). Eq. (15) written with the roll's and the tube's M(r) and I(r) keeps its energy integral, v² = 2g (M(R) R − M(r) r)/(M(r) + I(r)/r²) on a level floor from rest, and a light tube makes the roll faster than the textbook's.",
            method: "energy-thin with R = 0.06 m, b = −1e-4 m, paper of 700 kg/m³ 0.1 m wide on a tube of 5 g at 0.02 m (--core-mass), α = 0, from rest, stopped at r = 0.055, 0.045, 0.03 and 0.025 m; its speed against the energy integral with the tube, M and I typed in the check",
            tolerances: &[HOLLOW_ROLL],
            expected: Verdict::Holds,
        },
        check: unwinding_hollow_roll,
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The method of `snowless-limit` quotes the depths its check runs.
    #[test]
    fn the_snowless_limit_method_quotes_the_depths_it_uses() {
        let row = CLAIMS
            .iter()
            .find(|c| c.claim.id == ClaimId::SnowlessLimit)
            .map(|c| c.claim.method)
            .unwrap_or_default();
        let [b1, b2] = super::super::app_a::SNOWLESS_B;
        let quoted = format!("b = {b1:e} and {b2:e} m");
        assert!(row.contains(&quoted), "{quoted} not in {row}");
    }

    #[test]
    fn every_claim_id_has_one_row_in_the_order_of_all() {
        let rows: Vec<ClaimId> = CLAIMS.iter().map(|c| c.claim.id).collect();
        assert_eq!(rows, ClaimId::ALL, "CLAIMS and ClaimId::ALL differ");
        for id in ClaimId::ALL {
            let n = CLAIMS.iter().filter(|c| c.claim.id == id).count();
            assert_eq!(n, 1, "{id} has {n} rows");
        }
    }
}
