//! Every integration test of `snowroll` in one binary (one link instead of
//! one per file); each file is a module, named as before.

mod chord;
mod circular;
mod collision;
mod contact;
mod event_extrema;
mod fit;
mod integrator;
mod invariants;
mod loney;
mod losses;
mod named_keys;
mod sphere;
mod streaming;
mod support;
mod sweep;
mod sweep_regime;
mod turn_ledger;
mod turns;
mod turns_closed;
mod turns_precision;
mod turns_reference;
mod unwinding;
mod unwinding_core;
