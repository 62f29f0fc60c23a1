//! The long-run statistics of a turn run's rows: the means of the
//! acceleration that eqs. (77)–(79) leave open (`docs/errata.md`, (78)–(79)),
//! at checkpoints K = 1, 2, 5, 10, …, computed from all the rows
//! ([`TurnSummary::new`]) or row by row ([`SummaryBuilder`]).
//!
//! What to expect (leading order in 1/k, checked in `tests/turns.rs`): with
//! r_k ≈ kb, the energy over a turn gives `(3/4 + 2b/r) v_end² ≈ (3/4) v_beg² + 2πG r`
//! and the collision `v_after² ≈ v_end²(1 − 2b/3r)`, so `v_beg² → (πGb/2) k²`
//! and each turn lasts `2πr/v`: the mean acceleration tends to G/3 within a
//! turn and to G/4 with the collisions (not the 4G/9 of eq. (79)), while
//! `a(θ) ≈ (2/3)G − (G/3)(1 − cos θ)` keeps ranging over [0, 2G/3] (eq. (77)).

use serde::{Deserialize, Serialize};

use super::TurnRow;

/// Means of the acceleration up to turn K, as fractions of G = g sin α.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TurnCheckpoint {
    /// K: the statistics cover completed turns k < K.
    pub turns: u64,
    /// Time-weighted mean of a within turns, over all turns k < K,
    /// `Σ(v_end − v_start)/Σ(t_end − t_start)`, over G.
    pub mean_a_turn_over_g: f64,
    /// Mean of a including the collisions, over all turns k < K,
    /// `(v_after(K−1) − v_start(0))/t_end(K−1)`, over G.
    pub mean_a_with_collision_over_g: f64,
    /// First turn of the last decade, ⌊K/10⌋.
    pub window_first_turn: u64,
    /// Time-weighted mean of a within turns over the last decade ⌊K/10⌋ ≤ k < K, over G.
    pub window_mean_a_turn_over_g: f64,
    /// Mean of a including collisions over the last decade, over G.
    pub window_mean_a_with_collision_over_g: f64,
    /// Smallest a within a turn over the last decade, over G.
    pub window_min_a_over_g: f64,
    /// Largest a within a turn over the last decade, over G.
    pub window_max_a_over_g: f64,
}

/// Long-run statistics of a run: checkpoints at K = 1, 2, 5, 10, 20, 50, …
/// and at the last completed turn.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TurnSummary {
    /// G = g sin α, the unit of every `_over_g` value, m/s².
    pub g_along_m_s2: f64,
    /// Number of completed turns.
    pub turns: u64,
    /// How the means converge with K; the last entry covers every turn.
    pub checkpoints: Vec<TurnCheckpoint>,
}

impl TurnSummary {
    /// The statistics of `rows` (consecutive turns from k = 0).
    pub fn new(rows: &[TurnRow], g_along: f64) -> Self {
        // Prefix sums of the in-turn velocity gain, so that any window costs O(1).
        let mut gain = Vec::with_capacity(rows.len() + 1);
        gain.push(0.0);
        let mut sum = 0.0;
        for row in rows {
            sum += row.v_end_m_s - row.v_start_m_s;
            gain.push(sum);
        }
        let window = |from: usize, to: usize| {
            let (first, last) = (&rows[from], &rows[to - 1]);
            let dt = last.t_end_s - first.t_start_s;
            let in_turn = (gain[to] - gain[from]) / dt / g_along;
            let with = (last.v_after_m_s - first.v_start_m_s) / dt / g_along;
            (in_turn, with)
        };
        let checkpoints = checkpoint_turns(rows.len())
            .into_iter()
            .map(|k| {
                let first = k / 10;
                let (mean_turn, mean_with) = window(0, k);
                let (w_turn, w_with) = window(first, k);
                let (lo, hi) = rows[first..k]
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| {
                        (lo.min(r.min_a_m_s2), hi.max(r.max_a_m_s2))
                    });
                TurnCheckpoint {
                    turns: k as u64,
                    mean_a_turn_over_g: mean_turn,
                    mean_a_with_collision_over_g: mean_with,
                    window_first_turn: first as u64,
                    window_mean_a_turn_over_g: w_turn,
                    window_mean_a_with_collision_over_g: w_with,
                    window_min_a_over_g: lo / g_along,
                    window_max_a_over_g: hi / g_along,
                }
            })
            .collect();
        Self {
            g_along_m_s2: g_along,
            turns: rows.len() as u64,
            checkpoints,
        }
    }

    /// The checkpoint covering every turn, if any turn was completed.
    pub fn overall(&self) -> Option<&TurnCheckpoint> {
        self.checkpoints.last()
    }
}

/// Whether `k` is one of 1, 2, 5, 10, 20, 50, …
#[cfg(test)]
fn is_decade_checkpoint(k: u64) -> bool {
    let mut decade = 1u64;
    loop {
        if [1, 2, 5].iter().any(|&m| decade.checked_mul(m) == Some(k)) {
            return true;
        }
        match decade.checked_mul(10) {
            Some(d) if d <= k => decade = d,
            _ => return false,
        }
    }
}

/// The smallest turn count 1, 2, 5, 10, 20, … not below `k` (`u64::MAX`
/// past the last one that fits).
fn next_decade_checkpoint(k: u64) -> u64 {
    let mut decade = 1u64;
    loop {
        for m in [1, 2, 5] {
            match decade.checked_mul(m) {
                Some(c) if c >= k => return c,
                Some(_) => {}
                None => return u64::MAX,
            }
        }
        match decade.checked_mul(10) {
            Some(d) => decade = d,
            None => return u64::MAX,
        }
    }
}

/// The state of the run where a window starts (turn `first`), and the
/// extremes of a over its segment: the turns from `first` to the next
/// window's start (a window's extremes are those of its segment and of
/// every later one, folded at a checkpoint, so a row updates one segment).
#[derive(Debug, Clone, Copy)]
struct WindowStart {
    first: u64,
    /// Σ(v_end − v_start) over the turns before `first`, m/s.
    gain_before: f64,
    t_start: f64,
    v_start: f64,
    min_a: f64,
    max_a: f64,
}

/// [`TurnSummary`] computed row by row in memory O(log n): running sums,
/// and one [`WindowStart`] per turn where a checkpoint's window may start
/// (0, 1, 2, 5, 10, …, and ⌊N/10⌋ for the N turns asked for).
///
/// For a run that completes the turns it was asked for, the result is that
/// of [`TurnSummary::new`] on all the rows, bit for bit (the same sums in
/// the same order). After an early stop at n turns, the window of the
/// last checkpoint starts at the largest of those turns not past ⌊n/10⌋
/// (its `window_first_turn` says which).
#[derive(Debug, Clone)]
pub(crate) struct SummaryBuilder {
    g_along: f64,
    wanted: Option<u64>,
    turns: u64,
    gain: f64,
    starts: Vec<WindowStart>,
    last: Option<TurnRow>,
    checkpoints: Vec<TurnCheckpoint>,
    /// The smallest checkpoint turn count (1, 2, 5, 10, …) not below
    /// `turns` ([`next_decade_checkpoint`]), kept so that a row costs O(1).
    next_check: u64,
}

impl SummaryBuilder {
    pub(crate) fn new(g_along: f64, wanted: Option<u64>) -> Self {
        Self {
            g_along,
            wanted,
            turns: 0,
            gain: 0.0,
            starts: Vec::new(),
            last: None,
            checkpoints: Vec::new(),
            next_check: 1,
        }
    }

    /// Adds turn `self.turns` (rows come in order from k = 0).
    pub(crate) fn push(&mut self, row: &TurnRow) {
        let k = self.turns;
        if k == 0 || k == self.next_check || self.wanted.is_some_and(|n| n / 10 == k) {
            self.starts.push(WindowStart {
                first: k,
                gain_before: self.gain,
                t_start: row.t_start_s,
                v_start: row.v_start_m_s,
                min_a: f64::INFINITY,
                max_a: f64::NEG_INFINITY,
            });
        }
        if let Some(w) = self.starts.last_mut() {
            w.min_a = w.min_a.min(row.min_a_m_s2);
            w.max_a = w.max_a.max(row.max_a_m_s2);
        }
        self.gain += row.v_end_m_s - row.v_start_m_s;
        self.turns = k + 1;
        self.last = Some(*row);
        if self.turns > self.next_check {
            self.next_check = next_decade_checkpoint(self.turns);
        }
        if self.turns == self.next_check {
            self.checkpoint();
        }
    }

    /// The checkpoint over the `self.turns` turns seen.
    fn checkpoint(&mut self) {
        let (Some(last), Some(all)) = (self.last, self.starts.first()) else {
            return;
        };
        let g = self.g_along;
        let window = |w: &WindowStart| {
            let dt = last.t_end_s - w.t_start;
            (
                (self.gain - w.gain_before) / dt / g,
                (last.v_after_m_s - w.v_start) / dt / g,
            )
        };
        let wanted_first = self.turns / 10;
        let decade = self
            .starts
            .iter()
            .rev()
            .find(|w| w.first <= wanted_first)
            .unwrap_or(all);
        let (mean_turn, mean_with) = window(all);
        let (w_turn, w_with) = window(decade);
        // The decade window's extremes: its segment's and every later one's.
        let (min_a, max_a) = self
            .starts
            .iter()
            .filter(|w| w.first >= decade.first)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), w| {
                (lo.min(w.min_a), hi.max(w.max_a))
            });
        self.checkpoints.push(TurnCheckpoint {
            turns: self.turns,
            mean_a_turn_over_g: mean_turn,
            mean_a_with_collision_over_g: mean_with,
            window_first_turn: decade.first,
            window_mean_a_turn_over_g: w_turn,
            window_mean_a_with_collision_over_g: w_with,
            window_min_a_over_g: min_a / g,
            window_max_a_over_g: max_a / g,
        });
    }

    /// The summary of the turns seen, with the last checkpoint at the last turn.
    pub(crate) fn finish(mut self) -> TurnSummary {
        if self.checkpoints.last().map(|c| c.turns) != Some(self.turns) {
            self.checkpoint();
        }
        TurnSummary {
            g_along_m_s2: self.g_along,
            turns: self.turns,
            checkpoints: self.checkpoints,
        }
    }
}

/// 1, 2, 5, 10, 20, 50, … below `n`, then `n` (empty when n = 0).
fn checkpoint_turns(n: usize) -> Vec<usize> {
    let mut out = Vec::new();
    let mut decade = 1usize;
    'outer: loop {
        for m in [1, 2, 5] {
            let k = m * decade;
            if k >= n {
                break 'outer;
            }
            out.push(k);
        }
        decade = match decade.checked_mul(10) {
            Some(d) => d,
            None => break,
        };
    }
    if n > 0 {
        out.push(n);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decade_checkpoints_are_recognised() {
        for k in 0..=100_000 {
            let next = next_decade_checkpoint(k);
            assert!(next >= k && is_decade_checkpoint(next), "{k}: {next}");
            assert!((k..next).all(|j| !is_decade_checkpoint(j)), "{k}: {next}");
        }
        assert_eq!(next_decade_checkpoint(u64::MAX), u64::MAX);
        let found: Vec<u64> = (0..=1000).filter(|&k| is_decade_checkpoint(k)).collect();
        assert_eq!(found, [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000]);
        assert!(is_decade_checkpoint(5_000_000_000_000_000_000));
        assert!(!is_decade_checkpoint(u64::MAX));
    }

    #[test]
    fn checkpoints_are_1_2_5_per_decade_then_the_end() {
        assert!(checkpoint_turns(0).is_empty());
        assert_eq!(checkpoint_turns(1), vec![1]);
        assert_eq!(checkpoint_turns(7), vec![1, 2, 5, 7]);
        assert_eq!(checkpoint_turns(100), vec![1, 2, 5, 10, 20, 50, 100]);
    }
}
