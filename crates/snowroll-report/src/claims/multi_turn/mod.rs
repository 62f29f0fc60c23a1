//! Checks of the turn-by-turn model of §3.4 over many turns.
//!
//! The long-run values the checks compare with are derived in [`long_run`]
//! (`docs/turn-model.md`, "Long run") from two numbers typed from the note;
//! the collision is checked against angular momenta computed element by
//! element ([`super::quadrature`]) in [`collision`]; the energy balance of a
//! turn, eq. (88), and the truncation of eq. (73) are in [`energy_balance`].

mod collision;
mod energy_balance;
mod long_run;

pub(super) use collision::{
    collision_loss, collision_potential_jump, COLLISION_L, COLLISION_T, JUMP_ORDER,
};
pub(super) use energy_balance::{
    eq73_truncates_exact, eq88_balance, EQ88_APART, EQ88_EXACT, ERRATUM_87, TRUNCATION_ORDER,
};
pub(super) use long_run::{
    eq78_speed, mean_four_ninths, never_settles, LONG_RUN, NOTE_APART, SWING,
};
