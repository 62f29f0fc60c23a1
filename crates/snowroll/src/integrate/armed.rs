//! Which event functions can fire in a run ([`OdeSystem::event_armed`]):
//! the step loop evaluates only those.

use super::{OdeSystem, MAX_EVENTS};

/// The event functions that can fire in this run ([`OdeSystem::event_armed`]),
/// in index order: the step loop keeps their values in slots `0..len`, slot
/// `j` holding event `index[j]`, and never evaluates the others.
#[derive(Debug, Clone, Copy)]
pub(super) struct Armed {
    index: [usize; MAX_EVENTS],
    len: usize,
}

impl Armed {
    /// The armed events among the first `n_events` (at most [`MAX_EVENTS`]) of `system`.
    pub fn new<S: OdeSystem<N>, const N: usize>(system: &S, n_events: usize) -> Self {
        let mut armed = Self {
            index: [0; MAX_EVENTS],
            len: 0,
        };
        for i in (0..n_events).filter(|&i| system.event_armed(i)) {
            armed.index[armed.len] = i;
            armed.len += 1;
        }
        armed
    }

    /// How many events are armed.
    pub fn len(&self) -> usize {
        self.len
    }

    /// The event index of each slot, in slot order.
    pub fn indices(&self) -> &[usize] {
        &self.index[..self.len]
    }
}
