//! A long turn run (§3.4) kept in memory that does not grow with the
//! number of turns: what the claims and the figures of the report read.
//!
//! The rows of [`TurnModel::run_table_into`](snowroll::TurnModel::run_table_into)
//! go by once; [`TurnDigest`] keeps the first [`HEAD_ROWS`] of them (the
//! claims check the first turns, the figures show the first 100 s), the
//! last, the long-run statistics, and the energy ledger at about
//! [`LEDGER_POINTS`] turns spread evenly in log k.

use snowroll::error::SinkError;
use snowroll::integrate::Stats;
use snowroll::models::{
    kinetic_energy_at_turn_end, kinetic_energy_at_turn_start, ModelKind, TurnRow, TurnRunEnd,
    TurnSink, TurnSummary, TurnTable,
};
use snowroll::scenario::Scenario;
use snowroll::trajectory::Stop;

/// Rows kept from the start of a run: 10^4 rows, about 1 MB, far past the
/// ~130 turns of the default scenario's first 100 s.
pub const HEAD_ROWS: usize = 10_000;

/// About this many points of the energy ledger, spread in log k.
pub const LEDGER_POINTS: usize = 200;

/// The energy account after turn k, summed over turns 0..=k.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LedgerPoint {
    /// Completed turns, k + 1.
    pub turns: u64,
    /// Potential energy released within the turns, Σ(T_end − T_beg): energy
    /// is conserved within a turn (eqs. (82), (85), (86)), J.
    pub released_j: f64,
    /// Kinetic energy removed by the collisions, Σ collision_loss_j, J.
    pub lost_j: f64,
    /// Kinetic energy just after the collision of turn k, eq. (82) with
    /// r_{k+1} and v_after, J.
    pub kinetic_j: f64,
}

/// A long turn run in bounded memory (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct TurnDigest {
    /// Which model ran.
    pub model: ModelKind,
    /// The first rows, up to [`HEAD_ROWS`], in order.
    pub head: Vec<TurnRow>,
    /// The last row, if any turn was completed.
    pub last: Option<TurnRow>,
    /// Completed turns.
    pub turns: u64,
    /// How the run ended.
    pub stop: Stop,
    /// Long-run statistics over every row.
    pub summary: TurnSummary,
    /// Integrator counts.
    pub stats: Stats,
    /// The energy ledger at about [`LEDGER_POINTS`] turns spread in log k.
    pub ledger: Vec<LedgerPoint>,
}

impl TurnDigest {
    /// The digest of a whole table (the rows go through the same sink as a
    /// streamed run's).
    pub fn from_table(table: &TurnTable, scenario: &Scenario) -> Self {
        let mut sink = DigestSink::new(scenario, table.rows.len() as u64);
        for row in &table.rows {
            sink.keep(row);
        }
        sink.finish(TurnRunEnd {
            model: table.model,
            stop: table.stop,
            summary: table.summary.clone(),
            stats: table.stats,
            hop_doubt: table.hop_doubt,
        })
    }
}

/// The [`TurnSink`] that makes a [`TurnDigest`].
#[derive(Debug, Clone)]
pub(crate) struct DigestSink {
    r0: f64,
    b: f64,
    rho_l: f64,
    head: Vec<TurnRow>,
    last: Option<TurnRow>,
    turns: u64,
    released: f64,
    lost: f64,
    /// Turns whose ledger point is kept, in order; `next` indexes it.
    keep: Vec<u64>,
    next: usize,
    ledger: Vec<LedgerPoint>,
}

impl DigestSink {
    /// For a run of `s` asked for `turns` turns (the ledger's spread).
    pub(crate) fn new(s: &Scenario, turns: u64) -> Self {
        Self {
            r0: s.initial_radius(),
            b: s.snow_depth(),
            rho_l: s.density() * s.length(),
            head: Vec::new(),
            last: None,
            turns: 0,
            released: 0.0,
            lost: 0.0,
            keep: super::log_spread(turns, LEDGER_POINTS),
            next: 0,
            ledger: Vec::new(),
        }
    }

    fn keep(&mut self, row: &TurnRow) {
        if self.head.len() < HEAD_ROWS {
            self.head.push(*row);
        }
        let (r0, b, rho_l) = (self.r0, self.b, self.rho_l);
        let k = row.turn as f64;
        let (r, r1) = (r0 + k * b, r0 + (k + 1.0) * b);
        self.released += kinetic_energy_at_turn_end(rho_l, r, b, row.v_end_m_s)
            - kinetic_energy_at_turn_start(rho_l, r, row.v_start_m_s);
        self.lost += row.collision_loss_j;
        if self.keep.get(self.next) == Some(&row.turn) {
            self.next += 1;
            self.ledger.push(LedgerPoint {
                turns: row.turn + 1,
                released_j: self.released,
                lost_j: self.lost,
                kinetic_j: kinetic_energy_at_turn_start(rho_l, r1, row.v_after_m_s),
            });
        }
        self.last = Some(*row);
        self.turns += 1;
    }

    pub(crate) fn finish(self, end: TurnRunEnd) -> TurnDigest {
        TurnDigest {
            model: end.model,
            head: self.head,
            last: self.last,
            turns: self.turns,
            stop: end.stop,
            summary: end.summary,
            stats: end.stats,
            ledger: self.ledger,
        }
    }
}

impl TurnSink for DigestSink {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        self.keep(row);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use snowroll::models::run_turns;
    use snowroll::trajectory::SimOptions;

    #[test]
    fn the_digest_keeps_the_head_the_last_row_and_sums_over_every_row() {
        let s = Scenario::default();
        let opts = SimOptions {
            turns: Some(300),
            t_end: 1e9,
            ..SimOptions::default()
        };
        let table = run_turns(ModelKind::Turns, &s, &opts).unwrap();
        let digest = TurnDigest::from_table(&table, &s);
        assert_eq!(digest.head, table.rows);
        assert_eq!(digest.last, table.rows.last().copied());
        assert_eq!(digest.turns, 300);
        // The last ledger point is the last turn; its loss is the plain sum.
        let end = digest.ledger.last().unwrap();
        assert_eq!(end.turns, 300);
        let lost: f64 = table.rows.iter().map(|r| r.collision_loss_j).sum();
        // Same terms in the same order: the same sum.
        assert_eq!(end.lost_j.to_bits(), lost.to_bits());
        assert!(digest.ledger.len() > 50 && digest.ledger.len() <= LEDGER_POINTS);
        // Energy: from rest, the kinetic energy after turn k is what the
        // turns released less what the collisions took (eqs. (82), (85),
        // (86), (89) telescope). Tolerance: rounding of 300 sums of terms
        // up to ~1e3 J.
        for p in &digest.ledger {
            approx::assert_relative_eq!(p.kinetic_j, p.released_j - p.lost_j, max_relative = 1e-11);
        }
    }
}
