//! Regimes of a sweep: the outcome of rows on either side of the
//! closed-form borders (fn. 7 stall slope, fn. 10 hop, §5 slip), and the
//! settings axes (mu, on_hop, collision) in grid order.

use snowroll::sweep::{run_point, Axis, AxisParam, Choices, Grid, Method, Outcome, Values};
use snowroll::{CollisionModel, ModelKind, OnHop, Scenario};

/// Degrees either side of a stall or hop slope: far more than the closed
/// forms' error (rounding for the circular models; O((b/r0)²) ≈ 1e-2 of
/// tan α* for the first-turn stall of `turns`, well under 0.2° here).
const MARGIN_DEG: f64 = 0.2;

fn axis(param: AxisParam, values: &[f64]) -> Axis {
    Axis {
        param,
        values: Values::List(values.to_vec()),
    }
}

fn outcomes(model: ModelKind, axes: Vec<Axis>, choices: Choices) -> Vec<Outcome> {
    let grid = Grid::new(vec![model], axes)
        .unwrap()
        .with_choices(choices)
        .unwrap();
    (0..grid.len())
        .map(|i| Outcome::of(&run_point(&grid, i, Method::Auto).unwrap()))
        .collect()
}

#[test]
fn fn7_circular_model_starts_only_above_its_stall_slope() {
    let (b, r0) = (0.05, 0.1);
    let star = ModelKind::Energy
        .stall_threshold(b, r0)
        .unwrap()
        .slope
        .to_degrees();
    let got = outcomes(
        ModelKind::Energy,
        vec![
            axis(
                AxisParam::named("alpha_deg"),
                &[star - MARGIN_DEG, star + MARGIN_DEG],
            ),
            axis(AxisParam::named("snow_depth"), &[b]),
            axis(AxisParam::named("t_end"), &[5.0]),
        ],
        Choices::default(),
    );
    assert_eq!(got, [Outcome::NeverStarts, Outcome::RollsOn]);
}

#[test]
fn fn7_turn_model_stalls_in_turn_0_below_its_threshold() {
    let (b, r0) = (0.02, 0.1);
    let star = ModelKind::Turns
        .stall_threshold(b, r0)
        .unwrap()
        .slope
        .to_degrees();
    let got = outcomes(
        ModelKind::Turns,
        vec![
            axis(
                AxisParam::named("alpha_deg"),
                &[star - MARGIN_DEG, star + MARGIN_DEG],
            ),
            axis(AxisParam::named("snow_depth"), &[b]),
            axis(AxisParam::named("t_end"), &[5.0]),
        ],
        Choices::default(),
    );
    assert_eq!(got, [Outcome::Stalls { turn: 0 }, Outcome::RollsOn]);
}

#[test]
fn fn10_turn_model_hops_at_80_degrees_in_turn_1_unless_told_to_continue() {
    // docs/contact-forces.md §4.4: at 80° (defaults, from rest) the log
    // hops in turn 1; at 30° it never hops. With on_hop = continue nothing
    // stops at N = 0.
    let grid = Grid::new(
        vec![ModelKind::Turns],
        vec![
            axis(AxisParam::named("alpha_deg"), &[30.0, 80.0]),
            axis(AxisParam::named("t_end"), &[3.0]),
        ],
    )
    .unwrap()
    .with_choices(Choices {
        collision: vec![CollisionModel::Note],
        on_hop: vec![OnHop::Stop, OnHop::Continue],
    })
    .unwrap();
    let rows: Vec<_> = (0..grid.len())
        .map(|i| run_point(&grid, i, Method::Auto).unwrap())
        .collect();
    let got: Vec<Outcome> = rows.iter().map(Outcome::of).collect();
    assert_eq!(
        got,
        [
            Outcome::RollsOn,
            Outcome::Hops,
            Outcome::RollsOn,
            Outcome::RollsOn
        ]
    );
    assert_eq!(rows[1].turns, Some(1));
    assert_eq!(rows[2].on_hop, OnHop::Continue);
}

#[test]
fn slip_of_the_snowless_log_at_mu_tan_alpha_over_3() {
    // §5.1: a rolling cylinder needs μ ≥ tan α/3.
    let s = Scenario::default();
    let mu = s.slope_angle().tan() / 3.0;
    let got = outcomes(
        ModelKind::Snowless,
        vec![
            axis(AxisParam::named("mu"), &[0.95 * mu, 1.05 * mu]),
            axis(AxisParam::named("t_end"), &[5.0]),
        ],
        Choices::default(),
    );
    assert_eq!(got, [Outcome::Slips, Outcome::RollsOn]);
}

#[test]
fn settings_axes_follow_the_model_in_grid_order() {
    let grid = Grid::new(
        vec![ModelKind::Turns],
        vec![axis(AxisParam::named("alpha_deg"), &[20.0, 40.0])],
    )
    .unwrap()
    .with_choices(Choices {
        collision: vec![CollisionModel::Note, CollisionModel::Pivot],
        on_hop: vec![OnHop::Stop, OnHop::Continue],
    })
    .unwrap();
    assert_eq!(grid.len(), 8);
    let seen: Vec<(CollisionModel, OnHop, String)> = (0..8)
        .map(|i| {
            let p = grid.point(i).unwrap();
            (
                p.options.collision,
                p.options.on_hop,
                p.scenario.slope_angle().to_degrees().round().to_string(),
            )
        })
        .collect();
    let mut want = Vec::new();
    for c in [CollisionModel::Note, CollisionModel::Pivot] {
        for h in [OnHop::Stop, OnHop::Continue] {
            for a in ["20", "40"] {
                want.push((c, h, a.to_string()));
            }
        }
    }
    assert_eq!(seen, want);
    let e = grid
        .clone()
        .with_choices(Choices {
            collision: vec![CollisionModel::Note, CollisionModel::Note],
            on_hop: vec![OnHop::Stop],
        })
        .unwrap_err();
    assert!(e.to_string().contains("collision"), "{e}");
    let e = grid
        .with_choices(Choices {
            collision: vec![],
            on_hop: vec![OnHop::Stop],
        })
        .unwrap_err();
    assert!(e.to_string().contains("no values"), "{e}");
}
