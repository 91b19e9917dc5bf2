//! FSoE (Safety over EtherCAT, ETG.5100) connection — ABI-2 §13, shared/research/fsoe.md.
//!
//! `crc`: the FSoE CRC (§13.7); `frame`: the frame codec on caller buffers (§13.6);
//! `conn`: the master and slave state machines behind `SL_FSOE_CONN` (§13.1–§13.5).
//! `no_std`, no allocation, every loop bounded by the frame length (at most 67 bytes).

pub mod conn;
pub mod crc;
pub mod frame;

include!(concat!(env!("OUT_DIR"), "/abi/fsoe/mod.rs"));

pub mod member;

/// The connection states with their manual names (§3.2.1.3), NUL-terminated: what
/// `sl_state_str(SL_TYPE_FSOE_CONN, nState)` returns.
pub const STATE_NAMES: &[(u8, &str)] = &[
    (SL_FSOE_STATE_RESET, "RESET\0"),
    (SL_FSOE_STATE_SESSION, "SESSION\0"),
    (SL_FSOE_STATE_CONNECTION, "CONNECTION\0"),
    (SL_FSOE_STATE_PARAMETER, "PARAMETER\0"),
    (SL_FSOE_STATE_DATA, "DATA\0"),
    (SL_FSOE_STATE_SHUTDOWN, "SHUTDOWN\0"),
    (SL_FSOE_STATE_SHUTDOWN_DEACTIVE, "SHUTDOWN-DEACTIVE\0"),
];
