//! FSoE (Safety over EtherCAT, ETG.5100) connection — ABI-2 §13, shared/research/fsoe.md.
//!
//! `crc`: the FSoE CRC (§13.7); `frame`: the frame codec on caller buffers (§13.6);
//! `conn`: the master and slave state machines behind `SL_FSOE_CONN` (§13.1–§13.5).
//! `no_std`, no allocation, every loop bounded by the frame length (at most 67 bytes).

pub mod conn;
pub mod crc;
pub mod frame;

/// Largest SafeData length per direction (bytes).
pub const SL_FSOE_DATA_MAX: u16 = 32;
/// Largest number of application parameter bytes.
pub const SL_FSOE_APPPARA_MAX: u16 = 64;
/// Largest frame (2 * SL_FSOE_DATA_MAX + 3 bytes).
pub const SL_FSOE_FRAME_MAX: u16 = 67;

/// Command Reset.
pub const SL_FSOE_CMD_RESET: u8 = 0x2A;
/// Command Session.
pub const SL_FSOE_CMD_SESSION: u8 = 0x4E;
/// Command Connection.
pub const SL_FSOE_CMD_CONNECTION: u8 = 0x64;
/// Command Parameter.
pub const SL_FSOE_CMD_PARAMETER: u8 = 0x52;
/// Command ProcessData.
pub const SL_FSOE_CMD_PROCESSDATA: u8 = 0x36;
/// Command FailSafeData.
pub const SL_FSOE_CMD_FAILSAFEDATA: u8 = 0x08;

/// Role: FSoE master.
pub const SL_FSOE_ROLE_MASTER: u16 = 1;
/// Role: FSoE slave.
pub const SL_FSOE_ROLE_SLAVE: u16 = 2;

/// Option: a communication error is acknowledged by bComErrAck and then bErrAck.
pub const SL_FSOE_OPT_COMERRACK: u32 = 1 << 0;
/// Option "Module error is ComError": bModuleFault sets bComErr (diag 13).
pub const SL_FSOE_OPT_MODULE_ERR_IS_COMERR: u32 = 1 << 1;
/// Option (slave): accept only the configured `nConnectionId`; without it the slave takes
/// the non-zero Connection ID the master sends (fsoe.md §7, §11; semantics FS11).
pub const SL_FSOE_OPT_PIN_CONNID: u32 = 1 << 2;

/// Connection state Reset (manual §3.2.1.3).
pub const SL_FSOE_STATE_RESET: u8 = 100;
/// Connection state Session.
pub const SL_FSOE_STATE_SESSION: u8 = 101;
/// Connection state Connection.
pub const SL_FSOE_STATE_CONNECTION: u8 = 102;
/// Connection state Parameter.
pub const SL_FSOE_STATE_PARAMETER: u8 = 103;
/// Connection state Data.
pub const SL_FSOE_STATE_DATA: u8 = 104;
/// Connection state Shutdown (shut down by the partner).
pub const SL_FSOE_STATE_SHUTDOWN: u8 = 105;
/// Connection state Shutdown-Deactive (shut down by bShutdownRequest).
pub const SL_FSOE_STATE_SHUTDOWN_DEACTIVE: u8 = 106;

/// Reset code 0: local reset / acknowledgement.
pub const SL_FSOE_RESET_LOCAL: u8 = 0;
/// Reset code 1: invalid (unexpected) command.
pub const SL_FSOE_RESET_INVALID_CMD: u8 = 1;
/// Reset code 2: unknown command.
pub const SL_FSOE_RESET_UNKNOWN_CMD: u8 = 2;
/// Reset code 3: invalid connection ID.
pub const SL_FSOE_RESET_INVALID_CONNID: u8 = 3;
/// Reset code 4: invalid CRC.
pub const SL_FSOE_RESET_INVALID_CRC: u8 = 4;
/// Reset code 5: watchdog expired.
pub const SL_FSOE_RESET_WD_EXPIRED: u8 = 5;
/// Reset code 6: invalid FSoE address (slave only).
pub const SL_FSOE_RESET_INVALID_ADDRESS: u8 = 6;
/// Reset code 7: invalid data (echo mismatch, master only).
pub const SL_FSOE_RESET_INVALID_DATA: u8 = 7;
/// Reset code 8: invalid communication parameter length (slave only).
pub const SL_FSOE_RESET_INVALID_COMMPARALEN: u8 = 8;
/// Reset code 9: invalid communication parameters (watchdog; slave only).
pub const SL_FSOE_RESET_INVALID_COMMPARA: u8 = 9;
/// Reset code 10: invalid application parameter length (slave only).
pub const SL_FSOE_RESET_INVALID_USERPARALEN: u8 = 10;
/// Reset code 11: invalid application parameters (slave only).
pub const SL_FSOE_RESET_INVALID_USERPARA: u8 = 11;
/// Library proposal (ABI-2 §13.5, semantics FS9): a Reset frame with this code shuts the
/// connection down between two safelogic nodes (not interoperable with an EL6910).
pub const SL_FSOE_RESET_SHUTDOWN: u8 = 0xFE;

/// nDiag bit 4: the error code was detected by the slave.
pub const SL_FSOE_DIAG_SLAVE_ERROR: u16 = 1 << 4;
/// nDiag bit 5: the slave sends FailSafeData.
pub const SL_FSOE_DIAG_SLAVE_FAILSAFE: u16 = 1 << 5;
/// nDiag bit 6: start-up (state 100–103).
pub const SL_FSOE_DIAG_STARTUP: u16 = 1 << 6;
/// nDiag bit 7: the master sends FailSafeData.
pub const SL_FSOE_DIAG_MASTER_FAILSAFE: u16 = 1 << 7;
/// nDiag low nibble 12: FSoE master reset (slave role, Reset code 0 after DATA).
pub const SL_FSOE_DIAG_MASTER_RESET: u16 = 12;
/// nDiag low nibble 13: module error with "Module error is ComError".
pub const SL_FSOE_DIAG_MODULE_ERROR: u16 = 13;
/// nDiag low nibble 15: slave not yet started, or a received code above 11.
pub const SL_FSOE_DIAG_NOT_STARTED: u16 = 15;

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

/// Type tag of an FSoE connection as a group member (`SL_MEMBER.nType`): not a function
/// block, so outside the registry's block tags.
pub const SL_TYPE_FSOE_CONN: u16 = 256;
