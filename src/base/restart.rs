//! The restart sequence (ABI §7 "Restart"; manual §4.4.4, §4.5.4): START is entered while
//! Restart is TRUE and nothing requests the safe state; the outputs are enabled on the
//! falling edge of Restart if nothing requests the safe state then.

use super::bools::Edge;

/// What the restart sequence asks for this cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Restart {
    /// Stay in (or fall back to) the waiting state with the outputs safe.
    Wait,
    /// Enter or stay in START.
    Start,
    /// Falling edge in START with nothing requesting the safe state: enable the outputs.
    Enable,
}

/// One step of the sequence. `in_start`: the block is in START now.
#[inline]
pub fn step(in_start: bool, restart: Edge, request: bool) -> Restart {
    if request {
        Restart::Wait
    } else if in_start && restart.falling {
        Restart::Enable
    } else if restart.level {
        Restart::Start
    } else {
        Restart::Wait
    }
}
