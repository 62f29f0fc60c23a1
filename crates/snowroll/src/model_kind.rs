//! The names of the models: one table, [`MODEL_TABLE`], from which the enum
//! [`ModelKind`], its serde and clap spellings, [`ModelKind::id`],
//! [`ModelKind::alias`], [`ModelKind::equation`],
//! [`ModelKind::description`] and [`ModelKind::is_turn_model`] are all
//! generated. The user guide's model table (docs/guide/running.md) is checked against it by a test.
//!
//! This module depends on nothing else in the crate, so the output schema
//! ([`Trajectory`](crate::Trajectory)) can name a model without depending on
//! the models; what each model computes is in [`crate::models`].

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use crate::error::ParamError;

/// One row of [`MODEL_TABLE`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModelInfo {
    /// The model.
    pub kind: ModelKind,
    /// Kebab-case id (`torque-cm`).
    pub id: &'static str,
    /// Equation alias (`eq4`).
    pub alias: &'static str,
    /// Where in the note, in the citation form `eq. (N)` / `fn. N`.
    pub equation: &'static str,
    /// One line for people.
    pub description: &'static str,
    /// Whether the model follows the log turn by turn (§3) rather than
    /// taking it as circular at all times (§2, App. A, fn. 4).
    pub turn_model: bool,
}

macro_rules! model_table {
    ($(
        $(#[$doc:meta])*
        $variant:ident: $id:literal, $alias:literal, $equation:literal, $turn:literal, $description:literal;
    )*) => {
        /// The models of the note, by kebab-case id; each also answers to its
        /// equation alias (`snowroll models` lists both). Generated with
        /// [`MODEL_TABLE`] from one table.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
        #[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
        pub enum ModelKind {
            $(
                $(#[$doc])*
                #[serde(rename = $id, alias = $alias)]
                #[cfg_attr(feature = "clap", value(name = $id, alias = $alias))]
                $variant,
            )*
        }

        /// Every model with its id, alias, equation, description and whether
        /// it is a turn model, in the order of the note.
        pub const MODEL_TABLE: [ModelInfo; [$($id),*].len()] = [$(
            ModelInfo {
                kind: ModelKind::$variant,
                id: $id,
                alias: $alias,
                equation: $equation,
                description: $description,
                turn_model: $turn,
            },
        )*];

        impl ModelKind {
            /// Every model, in the order of the note.
            pub const ALL: [ModelKind; [$($id),*].len()] = [$(ModelKind::$variant),*];
        }
    };
}

model_table! {
    /// App. A: no snow, a = (2/3) g sin α, eq. (95).
    Snowless: "snowless", "eq95", "eq. (95)", false,
        "cylinder on a bare slope (App. A)";
    /// §2.1.1: torque about the centre of mass, eq. (4).
    TorqueCm: "torque-cm", "eq4", "eq. (4)", false,
        "circular log, torque about the centre of mass (§2.1.1)";
    /// §2.1.2: torque about the contact line, eq. (6).
    TorqueContact: "torque-contact", "eq6", "eq. (6)", false,
        "circular log, torque about the contact line (§2.1.2)";
    /// §2.2: energy conservation with the b² terms, eq. (14).
    Energy: "energy", "eq14", "eq. (14)", false,
        "circular log, energy conservation with b² terms (§2.2)";
    /// §2.2: eq. (14) without the b² terms, eq. (15).
    EnergyThin: "energy-thin", "eq15", "eq. (15)", false,
        "circular log, energy conservation to first order in b (§2.2)";
    /// §2.3: the Lagrangian result exactly as printed, eq. (21) (omits ∂T/∂x, `docs/errata.md` (19)–(21)).
    LagrangianPrinted: "lagrangian-printed", "eq21", "eq. (21) as printed", false,
        "circular log, Lagrangian as printed: omits dT/dx (docs/errata.md (19)-(21); corrected = eq. 14)";
    /// §2.4: the approximately circular log, eq. (32).
    QuasiCircular: "quasi-circular", "eq32", "eq. (32)", false,
        "approximately circular log, energy rate (§2.4)";
    /// §2.4: eq. (32) plus the lift term (36).
    QuasiCircularLift: "quasi-circular-lift", "eq32+36", "eqs. (32)+(36)", false,
        "eq. (32) plus the snow-lifting term (36) (§2.4)";
    /// fn. 4: Loney's closed-form solution of eq. (4), no ODE solver.
    Loney: "loney", "fn4", "fn. 4", false,
        "Loney's closed form of eq. (4), no ODE solver (fn. 4)";
    /// §3.4: turn by turn, eqs. (73), (76) to first order in b/r, collision eq. (89).
    Turns: "turns", "eq73", "eqs. (73), (76), (89)", true,
        "turn by turn, first order in b/r, collision at every full turn (§3.4)";
    /// §3.4: turn by turn with the exact mass properties, so that eq. (88) holds.
    TurnsExact: "turns-exact", "eq88", "eqs. (88), (89), exact geometry", true,
        "turn by turn, exact disk + sector mass properties, eq. (88) holds (§3.4)";
}

impl ModelKind {
    /// This model's row of [`MODEL_TABLE`].
    pub fn info(self) -> &'static ModelInfo {
        // The table lists the variants in declaration order.
        &MODEL_TABLE[self as usize]
    }

    /// The kebab-case id.
    pub fn id(self) -> &'static str {
        self.info().id
    }

    /// The equation alias (`eq4`, `fn4`, …).
    pub fn alias(self) -> &'static str {
        self.info().alias
    }

    /// Where in the note, in the citation form `eq. (N)` / `fn. N`.
    pub fn equation(self) -> &'static str {
        self.info().equation
    }

    /// One line for people.
    pub fn description(self) -> &'static str {
        self.info().description
    }

    /// Whether the model follows the log turn by turn (§3).
    pub fn is_turn_model(self) -> bool {
        self.info().turn_model
    }

    /// Whether the model takes the log as circular at all times (§2, App. A
    /// and Loney's fn. 4), as opposed to following it turn by turn (§3).
    pub fn is_circular(self) -> bool {
        !self.is_turn_model()
    }
}

impl fmt::Display for ModelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.id())
    }
}

impl FromStr for ModelKind {
    type Err = ParamError;

    /// Accepts the id or the equation alias, case-insensitively.
    fn from_str(s: &str) -> Result<Self, ParamError> {
        let wanted = s.trim().to_ascii_lowercase();
        MODEL_TABLE
            .iter()
            .find(|m| m.id == wanted || m.alias == wanted)
            .map(|m| m.kind)
            .ok_or_else(|| ParamError::UnknownModel {
                given: s.to_string(),
                expected: MODEL_TABLE
                    .iter()
                    .map(|m| format!("{} ({})", m.id, m.alias))
                    .collect::<Vec<_>>()
                    .join(", "),
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_rows_are_in_variant_order_and_names_are_unique() {
        for (i, row) in MODEL_TABLE.iter().enumerate() {
            assert_eq!(row.kind as usize, i, "{}", row.id);
            assert_eq!(row.kind, ModelKind::ALL[i]);
        }
        let mut names: Vec<&str> = MODEL_TABLE.iter().flat_map(|m| [m.id, m.alias]).collect();
        names.sort_unstable();
        let before = names.len();
        names.dedup();
        assert_eq!(names.len(), before, "an id or alias is used twice");
    }

    #[test]
    fn serde_and_from_str_read_the_same_names_as_the_table() {
        for m in &MODEL_TABLE {
            for name in [m.id, m.alias] {
                let json = format!("\"{name}\"");
                let kind: ModelKind = serde_json::from_str(&json).unwrap();
                assert_eq!(kind, m.kind, "serde {name}");
                assert_eq!(name.parse::<ModelKind>().unwrap(), m.kind, "FromStr {name}");
            }
            assert_eq!(
                serde_json::to_string(&m.kind).unwrap(),
                format!("\"{}\"", m.id)
            );
        }
    }

    #[cfg(feature = "clap")]
    #[test]
    fn clap_reads_the_same_names_as_the_table() {
        use clap::ValueEnum;
        for m in &MODEL_TABLE {
            for name in [m.id, m.alias] {
                assert_eq!(
                    <ModelKind as ValueEnum>::from_str(name, false).unwrap(),
                    m.kind,
                    "clap {name}"
                );
            }
        }
    }

    #[test]
    fn user_guide_lists_every_model_as_the_table_does() {
        let readme = include_str!("../../../docs/guide/running.md");
        let rows: Vec<(&str, &str)> = readme
            .lines()
            .filter_map(|l| {
                let cells: Vec<&str> = l.split('|').map(str::trim).collect();
                fn code(c: &str) -> Option<&str> {
                    c.strip_prefix('`')?.strip_suffix('`')
                }
                Some((code(cells.get(1)?)?, code(cells.get(2)?)?))
            })
            .filter(|(id, _)| id.parse::<ModelKind>().is_ok())
            .collect();
        let want: Vec<(&str, &str)> = MODEL_TABLE.iter().map(|m| (m.id, m.alias)).collect();
        assert_eq!(
            rows, want,
            "the user guide's model table (docs/guide/running.md: id | alias) differs from MODEL_TABLE"
        );
    }
}
