//! The energy ledger of the turn models (issue 11, part 3;
//! `docs/snowball-and-losses.md` §3.2): `kinetic + collision − created −
//! released = initial` at every sample for `turns` and `turns-exact` with
//! each collision rule, on random scenarios; and the energy each collision
//! removes against the closed form of the note's rule (angular momentum about
//! the new contact line conserved, eq. (89)), written out here from the note.

use std::f64::consts::PI;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use snowroll::{
    run_turns, CollisionModel, LedgerRow, Losses, ModelKind, OnHop, ParamError, Scenario,
    ScenarioFile, SimError, SimOptions, Trajectory, TurnMethod, TurnModel, TurnVariant,
};

/// The run's tolerances for the per-turn checks.
const TIGHT: (f64, f64) = (1e-12, 1e-14);
/// Collision loss per turn against its closed form: both use v_end of the
/// same deterministic run, so they differ by the rounding of a difference
/// of kinetic energies up to ~1/(4b/3r) ≈ 300 times larger than the loss
/// (b/r ≥ 1/400 here): 300 × a few ulp.
const LOSS_TOL: f64 = 1e-12;
/// The ledger's residual relative to its largest term: within a turn
/// `I θ̇²/2 + W` is conserved to the integrator's error (rtol 1e-10 on
/// the state [θ, θ̇], a few steps per turn), accumulated over up to 40
/// turns; the largest seen is 2.8e-9 (`pivot`, whose impact and turn end
/// are located events), so 1e-8.
const LEDGER_TOL: f64 = 1e-8;
/// Scenarios per (model, collision) pair; 6 pairs, the issue asks for ≥ 1000.
const CASES: u32 = 200;
const SEED: [u8; 32] = *b"snowroll issue 11 turn ledger 01";

fn ledger_opts(turns: u64, collision: CollisionModel) -> SimOptions {
    let mut opts = SimOptions {
        turns: Some(turns),
        t_end: 1e6,
        collision,
        losses: Losses {
            ledger: true,
            ..Losses::default()
        },
        ..SimOptions::default()
    };
    opts.tolerances.rtol = TIGHT.0;
    opts.tolerances.atol = TIGHT.1;
    opts
}

/// The collision loss of each turn: the jump of `collision_j` between the
/// last sample of turn k and the first of turn k + 1.
fn losses_per_turn(traj: &Trajectory) -> Vec<(u64, f64)> {
    let mut out = Vec::new();
    for i in 1..traj.samples.len() {
        let (before, after) = (traj.turn_states[i - 1].turn, traj.turn_states[i].turn);
        if after == before + 1 {
            out.push((
                before,
                traj.ledger[i].collision_j - traj.ledger[i - 1].collision_j,
            ));
        }
    }
    out
}

/// Eq. (89) with the model's own kinetic energy before the collision: the
/// log of turn k has radius r = r0 + k b, R = r + b after; it rolls about
/// its old contact line at v_end = r θ̇ with I_end, and after the collision
/// about the new one with I_beg = (3/2) m_{k+1} R², angular momentum about
/// that line conserved: θ̇′ = θ̇ I_C,end/I_C,beg with the note's
/// I_C,end = m_{k+1}(R²/2 + r²) (eq. (85)). The loss is
/// `I_end θ̇²/2 − I_beg θ̇′²/2`, with I_end = m_{k+1}(R²/2 + r²) for
/// `turns-exact` and m_k (3r²/2 + 4 b r) for `turns` (eq. (76) at θ = 2π).
fn note_loss(f: &ScenarioFile, exact: bool, k: u64, v_end: f64) -> f64 {
    let (b, rho_l) = (f.snow_depth, f.density * f.length);
    let r = f.r0 + k as f64 * b;
    let big_r = r + b;
    let m_k = PI * rho_l * r * r;
    let m_next = PI * rho_l * big_r * big_r;
    let omega = v_end / r;
    let i_c_end = m_next * (big_r * big_r / 2.0 + r * r);
    let i_beg = 1.5 * m_next * big_r * big_r;
    let omega_after = omega * i_c_end / i_beg;
    let i_end = if exact {
        i_c_end
    } else {
        m_k * (1.5 * r * r + 4.0 * b * r)
    };
    0.5 * i_end * omega * omega - 0.5 * i_beg * omega_after * omega_after
}

/// Each collision removes what eq. (89) says, for both variants and for the
/// `note` and `charged` rules (`charged` pays the lift m_{k+1} g b cos α
/// from the kinetic energy after the same angular-momentum step, so its loss
/// is the note's for its own v_end, and it creates nothing); the note's
/// rule creates exactly m_{k+1} g b cos α per turn.
#[test]
fn collision_loss_per_turn_is_the_closed_form_of_the_rule() {
    for (alpha, b) in [(30.0, 0.01), (15.0, 0.0025), (50.0, 0.03)] {
        let f = ScenarioFile {
            alpha_deg: alpha,
            snow_depth: b,
            ..ScenarioFile::default()
        };
        let s = Scenario::new(f).unwrap();
        for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
            for collision in [CollisionModel::Note, CollisionModel::Charged] {
                let opts = ledger_opts(12, collision);
                let traj = kind.build().simulate(&s, &opts).unwrap();
                // The table of the same integration as the trajectory's (the
                // closed form's v_end differs from it by the integrator's error).
                let table = TurnModel::new(TurnVariant::of(kind).unwrap())
                    .with_method(TurnMethod::Ode)
                    .run_table(&s, &opts)
                    .unwrap();
                let losses = losses_per_turn(&traj);
                assert_eq!(losses.len(), 11, "{kind} {collision}");
                for (k, loss) in losses {
                    let row = &table.rows[k as usize];
                    let want = note_loss(&f, kind == ModelKind::TurnsExact, k, row.v_end_m_s);
                    assert!(
                        (loss - want).abs() <= LOSS_TOL * want,
                        "{kind} {collision} turn {k}: {loss} vs {want}"
                    );
                    assert!(loss > 0.0);
                }
                let created = traj.ledger.last().unwrap().created_j;
                let want: f64 = match collision {
                    CollisionModel::Note => (1..12)
                        .map(|k| {
                            let r = f.r0 + k as f64 * b;
                            PI * f.density * f.length * r * r * s.g_normal() * b
                        })
                        .sum(),
                    _ => 0.0,
                };
                assert!(
                    (created - want).abs() <= 1e-14 * want.max(1.0),
                    "{kind} {collision}: created {created} vs {want}"
                );
            }
        }
    }
}

fn random_case() -> impl Strategy<Value = (Scenario, u64)> {
    (
        -2.0..0.5f64,
        -2.6..-1.0f64,
        10.0..70.0f64,
        prop_oneof![Just(0.0), 0.0..3.0f64],
        1u64..40,
    )
        .prop_map(|(lr0, lratio, alpha, v0, turns)| {
            let r0 = 10f64.powf(lr0);
            let s = Scenario::new(ScenarioFile {
                alpha_deg: alpha,
                snow_depth: r0 * 10f64.powf(lratio),
                r0,
                v0,
                ..ScenarioFile::default()
            })
            .expect("valid scenario");
            (s, turns)
        })
}

fn ledger_scale(row: &LedgerRow, initial: f64) -> f64 {
    [
        row.kinetic_j,
        row.released_j.abs(),
        row.collision_j,
        row.created_j,
        initial,
    ]
    .into_iter()
    .fold(f64::MIN_POSITIVE, f64::max)
}

/// The ledger sums to the initial energy at every sample, for both turn
/// models and every collision rule, on ≥ 1000 random scenarios (a stall, a
/// stuck step or a refused scale ends a run early; its rows still count).
#[test]
fn turn_ledger_sums_to_the_initial_energy_on_random_scenarios() {
    let mut total = 0;
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        for collision in CollisionModel::ALL {
            let mut runner = TestRunner::new_with_rng(
                Config {
                    cases: CASES,
                    failure_persistence: None,
                    ..Config::default()
                },
                TestRng::from_seed(RngAlgorithm::ChaCha, &SEED),
            );
            runner
                .run(&random_case(), |(s, turns)| {
                    let mut opts = ledger_opts(turns, collision);
                    opts.tolerances.rtol = 1e-10;
                    opts.tolerances.atol = 1e-12;
                    // The pivot leaves the edge at the first step above
                    // 11.5° (`docs/contact-forces.md` §6.3): go on as if in
                    // contact, so that its impacts and notches are booked.
                    if collision == CollisionModel::Pivot {
                        opts.on_hop = OnHop::Continue;
                    }
                    let traj = match kind.build().simulate(&s, &opts) {
                        Ok(t) => t,
                        Err(SimError::Param(_)) => return Ok(()),
                        Err(e) => return Err(TestCaseError::fail(format!("{kind}: {e}"))),
                    };
                    prop_assert_eq!(traj.ledger.len(), traj.samples.len());
                    let first = traj.ledger[0];
                    let initial = first.kinetic_j - first.released_j;
                    for row in &traj.ledger {
                        let scale = ledger_scale(row, initial);
                        prop_assert!(
                            row.residual_j.abs() <= LEDGER_TOL * scale,
                            "{} {}: residual {} of {} ({:?})",
                            kind,
                            collision,
                            row.residual_j,
                            scale,
                            row
                        );
                        prop_assert!(row.collision_j >= 0.0 && row.created_j >= 0.0);
                        prop_assert!(row.drag_j == 0.0 && row.model_j == 0.0);
                    }
                    Ok(())
                })
                .unwrap();
            total += CASES;
        }
    }
    assert!(total >= 1000);
}

/// The turn models take `--ledger` but refuse the losses, naming the flag
/// and the reason (the energy integral of a turn).
#[test]
fn turn_models_refuse_losses_but_keep_a_ledger() {
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let opts = SimOptions {
            losses: Losses {
                rolling_resistance: 0.1,
                ledger: true,
                ..Losses::default()
            },
            turns: Some(3),
            ..SimOptions::default()
        };
        let err = kind
            .build()
            .simulate(&Scenario::default(), &opts)
            .unwrap_err();
        assert!(
            matches!(
                err,
                SimError::Param(ParamError::Unsupported {
                    what: "rolling_resistance",
                    ..
                })
            ),
            "{err}"
        );
        assert!(err.to_string().contains("energy integral"), "{err}");
        let plain = SimOptions {
            turns: Some(3),
            ..SimOptions::default()
        };
        let with = ledger_opts(3, CollisionModel::Note);
        let a = kind.build().simulate(&Scenario::default(), &plain).unwrap();
        let mut b_opts = with;
        b_opts.tolerances = plain.tolerances;
        let b = kind
            .build()
            .simulate(&Scenario::default(), &b_opts)
            .unwrap();
        // Recording the ledger does not change the trajectory.
        assert_eq!(a.samples, b.samples, "{kind}");
        assert!(a.ledger.is_empty() && b.ledger.len() == b.samples.len());
    }
}

/// The per-turn table (`snowroll turns`, Python `turns()`) carries the
/// ledger at the end of each turn, before its collision: it closes like the
/// trajectory's, and for `turns-exact` with the note's rule its collision
/// column grows by the table's own `collision_loss_j` (eqs. (85), (86),
/// (89), computed there from v_end) from one turn to the next.
#[test]
fn the_turn_table_carries_the_ledger_at_each_turn_end() {
    let s = Scenario::default();
    let opts = ledger_opts(30, CollisionModel::Note);
    let table = run_turns(ModelKind::TurnsExact, &s, &opts).unwrap();
    assert_eq!(table.ledger.len(), table.rows.len());
    assert_eq!(table.rows.len(), 30);
    let initial = table.ledger[0].kinetic_j - table.ledger[0].released_j;
    for pair in table.ledger.windows(2).zip(&table.rows) {
        let ([before, after], row) = pair else {
            unreachable!()
        };
        let grown = after.collision_j - before.collision_j;
        assert!(
            (grown - row.collision_loss_j).abs() <= LOSS_TOL * row.collision_loss_j,
            "turn {}: {grown} vs {}",
            row.turn,
            row.collision_loss_j
        );
    }
    for l in &table.ledger {
        assert!(
            l.residual_j.abs() <= LEDGER_TOL * ledger_scale(l, initial),
            "{l:?}"
        );
    }
    // Without `ledger` the table has none.
    let plain = SimOptions {
        turns: Some(3),
        ..SimOptions::default()
    };
    assert!(run_turns(ModelKind::Turns, &s, &plain)
        .unwrap()
        .ledger
        .is_empty());
}
