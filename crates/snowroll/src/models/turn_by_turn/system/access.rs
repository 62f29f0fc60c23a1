//! The run's constants and current turn as the table's observer and the
//! closed path read them (moved from `mod.rs`, not changed).

use super::*;

impl TurnSystem {
    pub(crate) fn turn(&self) -> u64 {
        self.turn
    }

    pub(crate) fn dynamics(&self) -> &TurnDynamics {
        &self.dynamics
    }

    pub(crate) fn turn_start_x(&self) -> Meters {
        self.x_start
    }

    pub(crate) fn snow_depth(&self) -> Meters {
        self.b
    }

    pub(crate) fn rho_l(&self) -> f64 {
        self.rho_l
    }

    pub(crate) fn collision(&self) -> CollisionModel {
        self.collision
    }

    pub(crate) fn start_mass(&self) -> f64 {
        self.mass
    }

    pub(crate) fn pivot_impact(&self) -> &PivotImpact {
        &self.impact
    }
}
