//! Checks of §2 (the circular log): the four analyses, the Lagrangian's
//! omission, eq. (5), Loney's closed form (fn. 4), and the threshold slope
//! of fn. 7.
//!
//! Each equation the checks compare with is typed here from the note (as
//! printed, and as corrected in `docs/errata.md`); the models are observed
//! only through their runs ([`Lab::run`](super::Lab::run),
//! [`Lab::acceleration_at`](super::Lab::acceleration_at)).
//!
//! One file per group of claims: [`analyses`] (§2.1–2.3), [`loney`]
//! (fn. 4), [`contact_torque`] (eq. (5)) and [`threshold`] (fn. 7).

mod analyses;
mod contact_torque;
mod loney;
mod threshold;

pub(super) use analyses::{
    circular_agree_as_b_vanishes, circular_differ, lagrangian_vs_energy, DIFFER,
    DIFFER_COEFFICIENTS, DIFFER_TERMINAL, LAGRANGE_APART, LAGRANGE_CORRECTED, LAGRANGE_DIFFERENCE,
    SPREAD_LINEAR, SPREAD_SMALL,
};
pub(super) use contact_torque::{eq5_contact_torque, EQ5_PRINTED_APART, EQ5_TORQUE, ERRATUM_5};
pub(super) use loney::{
    loney_closed_form, loney_coefficient, loney_limit, ERRATUM_FN4, LONEY_DERIVATIVE, LONEY_LIMIT,
    LONEY_PRINTED_APART, LONEY_SPEED,
};
#[cfg(test)]
pub(super) use threshold::STALL_TOL_DEG;
pub(super) use threshold::{bisect, stall_threshold, STALL_BISECTION, STALL_MARGIN};
