//! Checks of the first turn, §3.1–3.3, and of the errata (`docs/errata.md`) a computation shows there.
//!
//! The note's formulae are typed here as printed (and as corrected), not taken
//! from [`snowroll::models::InTurnCoefficients`]; the body's masses, centres and
//! moments come from integrals over its elements ([`super::quadrature`]).
//!
//! One file per group of claims: [`equivalence`] (eqs. (58), (64), (69)),
//! [`angular_momentum`] (eqs. (47), (48), (54)), [`accreting`] (eqs.
//! (51)–(55)) and [`mass`] (eq. (70)).

mod accreting;
mod angular_momentum;
mod equivalence;
mod mass;

pub(super) use accreting::{eq51_55_accreting_body, ACCRETING_B3, ACCRETING_ORDER};
pub(super) use angular_momentum::{
    eq47_48_angular_momentum, eq54_erratum, EQ47_48_APART, EQ47_48_MATCH, EQ48_ORDER, EQ54_ORDER,
    ERRATUM_47_48, ERRATUM_54,
};
pub(super) use equivalence::{
    first_turn_equivalence, ERRATUM_58_69, FIRST_TURN_AGREE, FIRST_TURN_APART,
};
pub(super) use mass::{eq70_mass, ERRATUM_70, MASS_EXACT, MASS_FIRST_ORDER, MASS_PRINTED_APART};
