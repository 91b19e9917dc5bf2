//! Shared pieces of the FSoE connection tests.

use safelogic::*;

/// A connection's parameters: Connection ID 7, FSoE address 3, `role`, SafeData lengths
/// `tx` / `rx`, watchdog 100 ms, session ID seed `seed`; everything else zero.
pub fn conn(role: u16, tx: u16, rx: u16, seed: u16) -> SL_FSOE_CONN {
    SL_FSOE_CONN {
        nConnectionId: 7,
        nFsoeAddress: 3,
        nRole: role,
        nTxDataLen: tx,
        nRxDataLen: rx,
        tWatchdogTime: 100,
        nSessionIdSeed: seed,
        ..Default::default()
    }
}

/// The connection's BOOL outputs are 0 or 1 (ABI-2 §13.1).
#[track_caller]
pub fn assert_bool_outputs(c: &SL_FSOE_CONN) {
    for b in [
        c.bComErr,
        c.bComStartup,
        c.bDataValid,
        c.bShutdown,
        c.bPeerFailSafe,
    ] {
        assert!(b <= 1, "a BOOL output reads {b}");
    }
}
