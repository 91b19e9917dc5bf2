//! The FSoE connection object `SL_FSOE_CONN` (ABI-2 §13.1–§13.5): master and slave state
//! machines as fsoe.md §6 and §7 (mm::etg order of checks: ConnID → echo data → CRC),
//! sequence numbers and CRC chaining as §4.4–§4.5, watchdog as §9, FailSafeData (all
//! zeros) as §10. Readings: docs/semantics.md FS1…
//!
//! One struct serves both roles. A frame is written to the caller's transmit buffer only
//! when the state machine produces one; a received frame is an event only when it differs
//! from the previous one (the frame-received event of ETG.5100).

use super::crc::next_seq;
use super::frame::{decode, encode, frame_len, is_known_cmd, SL_FSOE_FRAME};
use super::*;
use crate::base::bools::{any_invalid, bit_flags, edge};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/fsoe/conn.rs"));

const MAGIC: u16 = 0xF50E;

// Flags (nFlags).
bit_flags!(u8: F_PEER_SEEN, F_COM_ERR, F_COMACK_SEEN, F_REACHED_DATA, F_PEER_FSD, F_PEER_PD, F_SLAVE_ERR, F_HAVE_LAST_RX);
// Flags (nFlags2).
bit_flags!(u8: G_STARTED, G_SHUTDOWN, G_OWN_FSD);
// Edge bits (nEdges).
bit_flags!(u8: E_ACK, E_COMACK, E_SHUT);

const ALL_OPTIONS: u32 =
    SL_FSOE_OPT_COMERRACK | SL_FSOE_OPT_MODULE_ERR_IS_COMERR | SL_FSOE_OPT_PIN_CONNID;

/// Start of SafePara in `aRxItem` (ConnData occupies 0-3).
const PARA_AT: usize = 4;

/// The latched parameters are valid (ABI-2 §13.1).
fn config_valid(c: &SL_FSOE_CONN) -> bool {
    c.nConnectionId != 0
        && (c.nRole == SL_FSOE_ROLE_MASTER || c.nRole == SL_FSOE_ROLE_SLAVE)
        && frame_len(usize::from(c.nTxDataLen)) != 0
        && frame_len(usize::from(c.nRxDataLen)) != 0
        && c.nAppParaLen <= SL_FSOE_APPPARA_MAX
        && (1..=65_535).contains(&c.tWatchdogTime)
        && c.dwOptions & !ALL_OPTIONS == 0
}

fn clear_outputs(c: &mut SL_FSOE_CONN) {
    c.bComErr = 0;
    c.bComStartup = 0;
    c.bDataValid = 0;
    c.bShutdown = 0;
    c.bPeerFailSafe = 0;
    c.aReserved3 = [0; 3];
    c.aRxSafeData = [0; 32];
    c.nResetCode = 0;
    c.nDiag = 0;
}

/// `sl_fsoe_init`: validates and latches the parameters, state 100, nothing sent yet.
/// Never modifies an input or parameter field. `Status::Config` for invalid parameters
/// (the connection then refuses every cycle with `Status::Config`).
pub fn init(c: &mut SL_FSOE_CONN) -> Status {
    clear_outputs(c);
    c.stPrivate = SL_FSOE_CONN_PRIVATE::default();
    c.nState = SL_FSOE_STATE_RESET;
    if !config_valid(c) {
        c.bComStartup = 0;
        return Status::Config;
    }
    let p = &mut c.stPrivate;
    p.wMagic = MAGIC;
    p.nConnId = c.nConnectionId;
    p.nAddress = c.nFsoeAddress;
    p.nWatchdog = c.tWatchdogTime as u16;
    p.nAppLen = c.nAppParaLen;
    p.nRole = c.nRole as u8;
    p.nTxLen = c.nTxDataLen as u8;
    p.nRxLen = c.nRxDataLen as u8;
    p.nOptions = c.dwOptions as u8;
    // SafePara = CommParaLen (2) ‖ watchdog ‖ AppParaLen ‖ AppPara, little endian.
    p.aOwnPara[0..2].copy_from_slice(&2u16.to_le_bytes());
    p.aOwnPara[2..4].copy_from_slice(&p.nWatchdog.to_le_bytes());
    p.aOwnPara[4..6].copy_from_slice(&p.nAppLen.to_le_bytes());
    let n = usize::from(p.nAppLen);
    p.aOwnPara[6..6 + n].copy_from_slice(&c.aAppPara[..n]);
    set_state(c, SL_FSOE_STATE_RESET);
    reset_vars(c);
    outputs(c, false, false);
    Status::Ok
}

fn set_state(c: &mut SL_FSOE_CONN, s: u8) {
    c.nState = s;
    c.stPrivate.nState = s;
    c.stPrivate.nStateInv = !s;
}

fn is_master(c: &SL_FSOE_CONN) -> bool {
    u16::from(c.stPrivate.nRole) == SL_FSOE_ROLE_MASTER
}

/// Handshake chunk: min(Tx, Rx) SafeData bytes (fsoe.md §5).
fn chunk(c: &SL_FSOE_CONN) -> usize {
    usize::from(c.stPrivate.nTxLen.min(c.stPrivate.nRxLen))
}

/// The Connection ID of the current session: the master's configured one; the slave's as
/// taken from the master (0 before its first Connection frame).
fn session_conn_id(c: &SL_FSOE_CONN) -> u16 {
    if is_master(c) {
        c.stPrivate.nConnId
    } else {
        c.stPrivate.nSessionConnId
    }
}

/// Every transition to Reset: chain, sequence numbers, counters, received data, the
/// slave's session Connection ID (a new session may bring a new one).
fn reset_vars(c: &mut SL_FSOE_CONN) {
    let p = &mut c.stPrivate;
    p.nSessionConnId = 0;
    p.wLastCrc = 0;
    p.wOldMasterCrc = 0;
    p.wOldSlaveCrc = 0;
    p.nMasterSeqNo = 1;
    p.nSlaveSeqNo = 1;
    p.nTxOff = 0;
    p.nRxCount = 0;
    p.aRxItem = [0; 76];
    p.aRxData = [0; 32];
    p.nFlags &= !(F_PEER_FSD | F_PEER_PD);
    p.nFlags2 &= !G_OWN_FSD;
}

/// What one cycle writes to the transmit buffer.
struct Tx<'a> {
    buf: &'a mut [u8],
    len: usize,
    now: u32,
}

/// Sends one frame: `data` zero-filled to nTxDataLen.
fn send(c: &mut SL_FSOE_CONN, tx: &mut Tx, cmd: u8, data: &[u8], collision: bool) {
    let n = usize::from(c.stPrivate.nTxLen);
    let mut sd = [0u8; SL_FSOE_DATA_MAX as usize];
    let k = data.len().min(n);
    sd[..k].copy_from_slice(&data[..k]);
    let master = is_master(c);
    let session_id = session_conn_id(c);
    let p = &mut c.stPrivate;
    let (conn, recv, mut seq, old) = if cmd == SL_FSOE_CMD_RESET {
        (0, 0, 1, 0)
    } else {
        let conn = if cmd == SL_FSOE_CMD_SESSION {
            0
        } else {
            session_id
        };
        if master {
            (conn, p.wLastCrc, p.nMasterSeqNo, p.wOldMasterCrc)
        } else {
            (conn, p.wLastCrc, p.nSlaveSeqNo, p.wOldSlaveCrc)
        }
    };
    let Ok((len, crc0)) = encode(tx.buf, cmd, &sd[..n], conn, recv, &mut seq, old, collision)
    else {
        return;
    };
    tx.len = len;
    p.tWdStart = tx.now;
    if cmd != SL_FSOE_CMD_RESET {
        p.wLastCrc = crc0;
        if master {
            p.wOldMasterCrc = crc0;
            p.nMasterSeqNo = next_seq(seq);
        } else {
            p.wOldSlaveCrc = crc0;
            p.nSlaveSeqNo = next_seq(seq);
        }
    }
}

/// Sends a Reset frame with `code` (no chain, ConnID 0, sequence number 1, no collision rule).
fn send_reset(c: &mut SL_FSOE_CONN, tx: &mut Tx, code: u8) {
    c.nResetCode = code;
    send(c, tx, SL_FSOE_CMD_RESET, &[code], false);
}

/// Enters Reset with `code` after an error this node detected (or 0: local reset).
fn go_reset(c: &mut SL_FSOE_CONN, tx: &mut Tx, code: u8) {
    reset_vars(c);
    set_state(c, SL_FSOE_STATE_RESET);
    if code != 0 {
        error(c, code, !is_master(c));
    }
    send_reset(c, tx, code);
}

/// Latches a communication error with its code (semantics FS6): only once the partner has
/// answered since init (a partner that never started is start-up, diag 15, not an error).
fn error(c: &mut SL_FSOE_CONN, code: u8, by_slave: bool) {
    let p = &mut c.stPrivate;
    if p.nFlags & F_PEER_SEEN == 0 {
        return;
    }
    p.nFlags |= F_COM_ERR;
    p.nFlags &= !F_COMACK_SEEN;
    p.nDiagCode = if code > 11 { 15 } else { code };
    if by_slave {
        p.nFlags |= F_SLAVE_ERR;
    } else {
        p.nFlags &= !F_SLAVE_ERR;
    }
}

/// The handshake item this node sends in state `s`, and its length.
fn item(c: &SL_FSOE_CONN, s: u8) -> ([u8; 72], usize) {
    let p = &c.stPrivate;
    let mut it = [0u8; 72];
    match s {
        SL_FSOE_STATE_SESSION => {
            it[..2].copy_from_slice(&p.wOwnSession.to_le_bytes());
            (it, 2)
        }
        SL_FSOE_STATE_CONNECTION => {
            it[..2].copy_from_slice(&p.nConnId.to_le_bytes());
            it[2..4].copy_from_slice(&p.nAddress.to_le_bytes());
            (it, 4)
        }
        _ => (p.aOwnPara, 6 + usize::from(p.nAppLen)),
    }
}

/// The chunk of this node's item at offset nTxOff (zero-filled to the chunk length).
fn own_chunk(c: &SL_FSOE_CONN, s: u8) -> [u8; 32] {
    let (it, len) = item(c, s);
    let off = usize::from(c.stPrivate.nTxOff);
    let mut out = [0u8; 32];
    let ch = chunk(c);
    for i in 0..ch {
        if off + i < len {
            out[i] = it[off + i];
        }
    }
    out
}

/// Master: sends the chunk at nTxOff of the item of state `s` with command `cmd`.
fn send_chunk(c: &mut SL_FSOE_CONN, tx: &mut Tx, s: u8, cmd: u8) {
    let d = own_chunk(c, s);
    let ch = chunk(c);
    // The master's Session frames: no collision rule (fsoe.md §4.5).
    let collision = !(cmd == SL_FSOE_CMD_SESSION && is_master(c));
    send(c, tx, cmd, &d[..ch], collision);
}

/// Sends the Data frame: ProcessData with aTxSafeData when bRun and no bComErr, else
/// FailSafeData (all zeros).
fn send_data(c: &mut SL_FSOE_CONN, tx: &mut Tx, run: bool) {
    let pd = run && c.stPrivate.nFlags & F_COM_ERR == 0;
    if pd {
        c.stPrivate.nFlags2 &= !G_OWN_FSD;
        let d = c.aTxSafeData;
        send(c, tx, SL_FSOE_CMD_PROCESSDATA, &d, true);
    } else {
        c.stPrivate.nFlags2 |= G_OWN_FSD;
        send(c, tx, SL_FSOE_CMD_FAILSAFEDATA, &[], true);
    }
}

/// Master: a new session (new ID from the caller's seed), first Session frame → 101.
fn start_session(c: &mut SL_FSOE_CONN, tx: &mut Tx) {
    reset_vars(c);
    c.stPrivate.wOwnSession = c.nSessionIdSeed;
    set_state(c, SL_FSOE_STATE_SESSION);
    send_chunk(c, tx, SL_FSOE_STATE_SESSION, SL_FSOE_CMD_SESSION);
}

fn enter_data(c: &mut SL_FSOE_CONN) {
    set_state(c, SL_FSOE_STATE_DATA);
    let p = &mut c.stPrivate;
    p.nFlags |= F_REACHED_DATA;
    p.nFlags2 &= !G_SHUTDOWN;
    if p.nFlags & F_COM_ERR == 0 {
        p.nDiagCode = 0;
        p.nFlags &= !F_SLAVE_ERR;
    }
}

/// Decodes the received frame against the chain (does not commit).
fn check(c: &SL_FSOE_CONN, rx: &[u8], fresh: bool) -> (Status, SL_FSOE_FRAME, u16) {
    let p = &c.stPrivate;
    let master = is_master(c);
    let (recv, mut seq, old, collision) = if fresh {
        (0, 1, 0, false)
    } else if master {
        (p.wLastCrc, p.nSlaveSeqNo, p.wOldSlaveCrc, true)
    } else {
        (p.wLastCrc, p.nMasterSeqNo, p.wOldMasterCrc, true)
    };
    let mut f = SL_FSOE_FRAME::default();
    let st = decode(
        rx,
        usize::from(p.nRxLen),
        recv,
        &mut seq,
        old,
        collision,
        &mut f,
    );
    (st, f, seq)
}

/// Commits an accepted frame: chain, the partner's sequence number and old CRC.
/// A Connection or Parameter frame the slave receives (`rx`: the check's status, the
/// frame, its sequence number): accepted, or refused with a Reset when the state does not
/// expect it now (`unexpected`), it is for another connection, or its CRC fails, in this
/// order.
fn take(
    c: &mut SL_FSOE_CONN,
    tx: &mut Tx,
    rx: (Status, &SL_FSOE_FRAME, u16),
    unexpected: bool,
    conn_ok: bool,
) -> bool {
    let (st, f, seq) = rx;
    let refusal = if unexpected {
        SL_FSOE_RESET_INVALID_CMD
    } else if !conn_ok {
        SL_FSOE_RESET_INVALID_CONNID
    } else if st != Status::Ok {
        SL_FSOE_RESET_INVALID_CRC
    } else {
        accept(c, f, seq);
        return true;
    };
    go_reset(c, tx, refusal);
    false
}

fn accept(c: &mut SL_FSOE_CONN, f: &SL_FSOE_FRAME, seq: u16) {
    let master = is_master(c);
    let p = &mut c.stPrivate;
    p.nFlags |= F_PEER_SEEN;
    p.wLastCrc = f.wCrc0;
    if master {
        p.wOldSlaveCrc = f.wCrc0;
        p.nSlaveSeqNo = next_seq(seq);
    } else {
        p.wOldMasterCrc = f.wCrc0;
        p.nMasterSeqNo = next_seq(seq);
    }
}

/// A Reset frame from the partner (no CRC check, fsoe.md §6 RESET_OK). Returns false when
/// it was the shutdown code (the connection is now in 105).
fn peer_reset(c: &mut SL_FSOE_CONN, tx: &mut Tx, code: u8) -> bool {
    c.stPrivate.nFlags |= F_PEER_SEEN;
    let state = c.nState;
    reset_vars(c);
    c.nResetCode = code;
    if code == SL_FSOE_RESET_SHUTDOWN {
        set_state(c, SL_FSOE_STATE_SHUTDOWN);
        c.stPrivate.nFlags2 |= G_SHUTDOWN;
        if is_master(c) {
            // A master in 105 keeps offering Reset frames (ABI-2 §13.5).
            send_reset(c, tx, 0);
        }
        c.nResetCode = code;
        return false;
    }
    set_state(c, SL_FSOE_STATE_RESET);
    if code != 0 {
        error(c, code, is_master(c));
    } else if !is_master(c)
        && c.stPrivate.nFlags & F_REACHED_DATA != 0
        && state != SL_FSOE_STATE_RESET
        && c.stPrivate.nFlags & F_COM_ERR == 0
    {
        c.stPrivate.nDiagCode = SL_FSOE_DIAG_MASTER_RESET as u8;
        c.stPrivate.nFlags &= !(F_SLAVE_ERR | F_REACHED_DATA);
    }
    true
}

/// Master: one received frame in state 100–105.
fn master_rx(c: &mut SL_FSOE_CONN, tx: &mut Tx, rx: &[u8], run: bool) {
    let s = c.nState;
    let (st, f, seq) = check(c, rx, false);
    let cmd = f.nCmd;
    if s == SL_FSOE_STATE_RESET || s == SL_FSOE_STATE_SHUTDOWN {
        if cmd == SL_FSOE_CMD_RESET {
            // RESET_OK: the partner's code is kept; a new session.
            if peer_reset(c, tx, f.aSafeData[0]) {
                start_session(c, tx);
            }
        } else if s == SL_FSOE_STATE_RESET {
            // RESET_STAY1.
            send_reset(c, tx, 0);
        }
        return;
    }
    if !is_known_cmd(cmd) {
        return go_reset(c, tx, SL_FSOE_RESET_UNKNOWN_CMD);
    }
    if cmd == SL_FSOE_CMD_RESET {
        if peer_reset(c, tx, f.aSafeData[0]) {
            start_session(c, tx);
        }
        return;
    }
    match s {
        SL_FSOE_STATE_SESSION => {
            if cmd != SL_FSOE_CMD_SESSION {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CMD);
            }
            let ch = chunk(c);
            let off = usize::from(c.stPrivate.nTxOff);
            let second_sent = off > 0;
            if st != Status::Ok {
                // SESSION_STAY2: tolerated until the second Session frame was sent.
                if second_sent {
                    go_reset(c, tx, SL_FSOE_RESET_INVALID_CRC);
                }
                return;
            }
            accept(c, &f, seq);
            store_peer_session(c, &f, ch);
            if off + ch < 2 {
                c.stPrivate.nTxOff = (off + ch) as u16;
                send_chunk(c, tx, SL_FSOE_STATE_SESSION, SL_FSOE_CMD_SESSION);
            } else {
                c.stPrivate.nTxOff = 0;
                set_state(c, SL_FSOE_STATE_CONNECTION);
                send_chunk(c, tx, SL_FSOE_STATE_CONNECTION, SL_FSOE_CMD_CONNECTION);
            }
        }
        SL_FSOE_STATE_CONNECTION | SL_FSOE_STATE_PARAMETER => {
            let want = if s == SL_FSOE_STATE_CONNECTION {
                SL_FSOE_CMD_CONNECTION
            } else {
                SL_FSOE_CMD_PARAMETER
            };
            if cmd != want {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CMD);
            }
            if f.nConnId != c.stPrivate.nConnId {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CONNID);
            }
            let ch = chunk(c);
            if f.aSafeData[..ch] != own_chunk(c, s)[..ch] {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_DATA);
            }
            if st != Status::Ok {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CRC);
            }
            accept(c, &f, seq);
            let off = usize::from(c.stPrivate.nTxOff) + ch;
            if off < item(c, s).1 {
                c.stPrivate.nTxOff = off as u16;
                send_chunk(c, tx, s, want);
            } else if s == SL_FSOE_STATE_CONNECTION {
                c.stPrivate.nTxOff = 0;
                set_state(c, SL_FSOE_STATE_PARAMETER);
                send_chunk(c, tx, SL_FSOE_STATE_PARAMETER, SL_FSOE_CMD_PARAMETER);
            } else {
                c.stPrivate.nTxOff = 0;
                enter_data(c);
                send_data(c, tx, run);
            }
        }
        _ => data_rx(c, tx, &f, st, seq, run),
    }
}

/// Both roles in DATA: a ProcessData / FailSafeData frame.
fn data_rx(c: &mut SL_FSOE_CONN, tx: &mut Tx, f: &SL_FSOE_FRAME, st: Status, seq: u16, run: bool) {
    let cmd = f.nCmd;
    if cmd != SL_FSOE_CMD_PROCESSDATA && cmd != SL_FSOE_CMD_FAILSAFEDATA {
        return go_reset(c, tx, SL_FSOE_RESET_INVALID_CMD);
    }
    if f.nConnId != session_conn_id(c) {
        return go_reset(c, tx, SL_FSOE_RESET_INVALID_CONNID);
    }
    if st != Status::Ok {
        return go_reset(c, tx, SL_FSOE_RESET_INVALID_CRC);
    }
    accept(c, f, seq);
    apply_data(c, f);
    send_data(c, tx, run);
}

fn apply_data(c: &mut SL_FSOE_CONN, f: &SL_FSOE_FRAME) {
    let p = &mut c.stPrivate;
    if f.nCmd == SL_FSOE_CMD_PROCESSDATA {
        p.aRxData = [0; 32];
        let n = usize::from(p.nRxLen);
        p.aRxData[..n].copy_from_slice(&f.aSafeData[..n]);
        p.nFlags = (p.nFlags | F_PEER_PD) & !F_PEER_FSD;
    } else {
        p.aRxData = [0; 32];
        p.nFlags = (p.nFlags | F_PEER_FSD) & !F_PEER_PD;
    }
}

fn store_peer_session(c: &mut SL_FSOE_CONN, f: &SL_FSOE_FRAME, ch: usize) {
    let p = &mut c.stPrivate;
    let at = usize::from(p.nRxCount);
    let mut b = p.wPeerSession.to_le_bytes();
    for i in 0..ch.min(2) {
        if at + i < 2 {
            b[at + i] = f.aSafeData[i];
        }
    }
    p.wPeerSession = u16::from_le_bytes(b);
    p.nRxCount = (at + ch).min(2) as u16;
}

/// Slave: echoes the first chunk of the received SafeData.
fn echo(c: &mut SL_FSOE_CONN, tx: &mut Tx, f: &SL_FSOE_FRAME) {
    let ch = chunk(c);
    let mut d = [0u8; 32];
    d[..ch].copy_from_slice(&f.aSafeData[..ch]);
    send(c, tx, f.nCmd, &d[..ch], true);
}

/// Slave: a master Session frame checked as the first frame of a session; on success the
/// slave starts its session (own ID from the seed) and answers.
fn slave_session_start(c: &mut SL_FSOE_CONN, tx: &mut Tx, rx: &[u8]) {
    reset_vars(c);
    let (st, f, seq) = check(c, rx, true);
    if st != Status::Ok {
        return go_reset(c, tx, SL_FSOE_RESET_INVALID_CRC);
    }
    accept(c, &f, seq);
    let ch = chunk(c);
    store_peer_session(c, &f, ch);
    c.stPrivate.wOwnSession = c.nSessionIdSeed;
    set_state(c, SL_FSOE_STATE_SESSION);
    let d = own_chunk(c, SL_FSOE_STATE_SESSION);
    // The slave's Session reply: collision rule on (ETG.5100 errata, fsoe.md §4.5).
    send(c, tx, SL_FSOE_CMD_SESSION, &d[..ch], true);
}

/// Expected SafePara length from the received header (u32::MAX until it is complete).
fn expected_para(c: &SL_FSOE_CONN) -> u32 {
    let p = &c.stPrivate;
    if p.nRxCount < 6 {
        return u32::MAX;
    }
    let a = &p.aRxItem[PARA_AT..];
    6 + u32::from(u16::from_le_bytes([a[4], a[5]]))
}

/// Slave: stores a SafePara chunk.
fn store_para(c: &mut SL_FSOE_CONN, f: &SL_FSOE_FRAME) {
    let ch = chunk(c);
    let p = &mut c.stPrivate;
    let at = usize::from(p.nRxCount);
    for i in 0..ch {
        if let Some(b) = p.aRxItem.get_mut(PARA_AT + at + i) {
            *b = f.aSafeData[i];
        }
    }
    p.nRxCount = p.nRxCount.saturating_add(ch as u16);
}

/// Slave: the SafePara check at the first Data frame (fsoe.md §7): 8, 9, 10, 11 or 0.
fn para_code(c: &SL_FSOE_CONN) -> u8 {
    let p = &c.stPrivate;
    let a = &p.aRxItem[PARA_AT..];
    let own = &p.aOwnPara;
    if a[0..2] != own[0..2] {
        SL_FSOE_RESET_INVALID_COMMPARALEN
    } else if a[2..4] != own[2..4] {
        SL_FSOE_RESET_INVALID_COMMPARA
    } else if a[4..6] != own[4..6] {
        SL_FSOE_RESET_INVALID_USERPARALEN
    } else {
        let n = 6 + usize::from(p.nAppLen);
        if a[6..n] != own[6..n] {
            SL_FSOE_RESET_INVALID_USERPARA
        } else {
            0
        }
    }
}

/// Slave: one received frame in state 100–105.
fn slave_rx(c: &mut SL_FSOE_CONN, tx: &mut Tx, rx: &[u8], run: bool) {
    let s = c.nState;
    let (st, f, seq) = check(c, rx, false);
    let cmd = f.nCmd;
    if s == SL_FSOE_STATE_SHUTDOWN {
        if cmd == SL_FSOE_CMD_RESET && peer_reset(c, tx, f.aSafeData[0]) {
            send_reset(c, tx, 0);
        }
        return;
    }
    if !is_known_cmd(cmd) {
        return go_reset(c, tx, SL_FSOE_RESET_UNKNOWN_CMD);
    }
    if cmd == SL_FSOE_CMD_RESET {
        // Acknowledged with Reset(0).
        if peer_reset(c, tx, f.aSafeData[0]) {
            send_reset(c, tx, 0);
            c.nResetCode = f.aSafeData[0];
        }
        return;
    }
    let ch = chunk(c);
    // The master's first Connection frame brings the session's Connection ID: any non-zero
    // one, or only the configured one with SL_FSOE_OPT_PIN_CONNID (semantics FS11). Every
    // later frame, and ConnData's ConnID, must carry that one.
    let conn_ok = if s == SL_FSOE_STATE_SESSION {
        let pinned = u32::from(c.stPrivate.nOptions) & SL_FSOE_OPT_PIN_CONNID != 0;
        f.nConnId != 0 && (!pinned || f.nConnId == c.stPrivate.nConnId)
    } else {
        f.nConnId == c.stPrivate.nSessionConnId
    };
    match (s, cmd) {
        (SL_FSOE_STATE_RESET, SL_FSOE_CMD_SESSION) => slave_session_start(c, tx, rx),
        (SL_FSOE_STATE_SESSION, SL_FSOE_CMD_SESSION) => {
            if c.stPrivate.nRxCount < 2 && st == Status::Ok {
                // The master's second Session frame (1-byte chunks).
                accept(c, &f, seq);
                store_peer_session(c, &f, ch);
                c.stPrivate.nTxOff = 1;
                let d = own_chunk(c, SL_FSOE_STATE_SESSION);
                send(c, tx, SL_FSOE_CMD_SESSION, &d[..ch], true);
            } else {
                // The master restarts the session.
                slave_session_start(c, tx, rx);
            }
        }
        (SL_FSOE_STATE_SESSION, SL_FSOE_CMD_CONNECTION)
        | (SL_FSOE_STATE_CONNECTION, SL_FSOE_CMD_CONNECTION) => {
            let first = s == SL_FSOE_STATE_SESSION;
            let done = if first {
                c.stPrivate.nRxCount < 2
            } else {
                c.stPrivate.nRxCount >= 4
            };
            if !take(c, tx, (st, &f, seq), done, conn_ok) {
                return;
            }
            if first {
                c.stPrivate.nRxCount = 0;
                c.stPrivate.nSessionConnId = f.nConnId;
                set_state(c, SL_FSOE_STATE_CONNECTION);
            }
            let p = &mut c.stPrivate;
            let at = usize::from(p.nRxCount);
            for i in 0..ch {
                if at + i < 4 {
                    p.aRxItem[at + i] = f.aSafeData[i];
                }
            }
            p.nRxCount = (at + ch).min(4) as u16;
            echo(c, tx, &f);
        }
        (SL_FSOE_STATE_CONNECTION, SL_FSOE_CMD_PARAMETER) => {
            if c.stPrivate.nRxCount < 4 {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CMD);
            }
            let p = &c.stPrivate;
            let cd_conn = u16::from_le_bytes([p.aRxItem[0], p.aRxItem[1]]);
            let cd_addr = u16::from_le_bytes([p.aRxItem[2], p.aRxItem[3]]);
            if !conn_ok || cd_conn != p.nSessionConnId {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CONNID);
            }
            if cd_addr != p.nAddress {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_ADDRESS);
            }
            if st != Status::Ok {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CRC);
            }
            accept(c, &f, seq);
            c.stPrivate.nRxCount = 0;
            set_state(c, SL_FSOE_STATE_PARAMETER);
            store_para(c, &f);
            echo(c, tx, &f);
        }
        (SL_FSOE_STATE_PARAMETER, SL_FSOE_CMD_PARAMETER) => {
            let all_in = u32::from(c.stPrivate.nRxCount) >= expected_para(c);
            if !take(c, tx, (st, &f, seq), all_in, conn_ok) {
                return;
            }
            store_para(c, &f);
            echo(c, tx, &f);
        }
        (SL_FSOE_STATE_PARAMETER, SL_FSOE_CMD_PROCESSDATA)
        | (SL_FSOE_STATE_PARAMETER, SL_FSOE_CMD_FAILSAFEDATA) => {
            if u32::from(c.stPrivate.nRxCount) < expected_para(c) {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CMD);
            }
            if !conn_ok {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CONNID);
            }
            let code = para_code(c);
            if code != 0 {
                return go_reset(c, tx, code);
            }
            if st != Status::Ok {
                return go_reset(c, tx, SL_FSOE_RESET_INVALID_CRC);
            }
            accept(c, &f, seq);
            enter_data(c);
            apply_data(c, &f);
            send_data(c, tx, run);
        }
        (SL_FSOE_STATE_DATA, _) => data_rx(c, tx, &f, st, seq, run),
        _ => go_reset(c, tx, SL_FSOE_RESET_INVALID_CMD),
    }
}

/// The watchdog (fsoe.md §9): restarted by every frame sent, checked before the input.
/// Returns true when it expired (the received frame of this cycle is then not processed).
fn watchdog(c: &mut SL_FSOE_CONN, tx: &mut Tx) -> bool {
    let p = &c.stPrivate;
    let elapsed = tx.now.wrapping_sub(p.tWdStart);
    if elapsed < u32::from(p.nWatchdog) {
        return false;
    }
    let master = is_master(c);
    match c.nState {
        SL_FSOE_STATE_RESET if master && p.nFlags2 & G_STARTED != 0 => {
            // RESET_WD (mm::etg): offer a session anyway.
            start_session(c, tx);
            true
        }
        SL_FSOE_STATE_SESSION..=SL_FSOE_STATE_DATA => {
            go_reset(c, tx, SL_FSOE_RESET_WD_EXPIRED);
            true
        }
        SL_FSOE_STATE_SHUTDOWN if master => {
            // Keeps offering Reset frames; the partner's Reset of this cycle still counts.
            send_reset(c, tx, 0);
            false
        }
        _ => false,
    }
}

/// The outputs from the state (ABI-2 §13.1, §13.3).
fn outputs(c: &mut SL_FSOE_CONN, run: bool, module: bool) {
    let p = c.stPrivate;
    let s = c.nState;
    let master = u16::from(p.nRole) == SL_FSOE_ROLE_MASTER;
    let com_err = p.nFlags & F_COM_ERR != 0;
    let shut = p.nFlags2 & G_SHUTDOWN != 0;
    let data = s == SL_FSOE_STATE_DATA;
    let valid = data && p.nFlags & F_PEER_PD != 0 && run && !com_err;
    c.bComErr = u8::from(com_err);
    c.bComStartup = u8::from(s <= SL_FSOE_STATE_PARAMETER && !shut);
    c.bDataValid = u8::from(valid);
    c.bShutdown = u8::from(shut);
    let peer_fsd = data && p.nFlags & F_PEER_FSD != 0;
    let own_fsd = data && p.nFlags2 & G_OWN_FSD != 0;
    c.bPeerFailSafe = u8::from(peer_fsd);
    c.aRxSafeData = if valid { p.aRxData } else { [0; 32] };
    let mut code = u16::from(p.nDiagCode);
    if code == 0 && master && p.nFlags & F_PEER_SEEN == 0 && s <= SL_FSOE_STATE_SESSION {
        code = SL_FSOE_DIAG_NOT_STARTED;
    }
    if module && u32::from(p.nOptions) & SL_FSOE_OPT_MODULE_ERR_IS_COMERR != 0 {
        code = SL_FSOE_DIAG_MODULE_ERROR;
    }
    let mut d = code & 0x0F;
    if p.nFlags & F_SLAVE_ERR != 0 && (1..=11).contains(&code) {
        d |= SL_FSOE_DIAG_SLAVE_ERROR;
    }
    if (master && peer_fsd) || (!master && own_fsd) {
        d |= SL_FSOE_DIAG_SLAVE_FAILSAFE;
    }
    if s <= SL_FSOE_STATE_PARAMETER && !shut {
        d |= SL_FSOE_DIAG_STARTUP;
    }
    if (master && own_fsd) || (!master && peer_fsd) {
        d |= SL_FSOE_DIAG_MASTER_FAILSAFE;
    }
    c.nDiag = d;
}

/// The private state's check: `None` for a connection whose init was refused or never
/// done, `Some(false)` for one that fails its check (corrupt), `Some(true)` when intact.
pub fn integrity(c: &SL_FSOE_CONN) -> Option<bool> {
    let p = &c.stPrivate;
    if p.wMagic == 0 && p.nState == 0 {
        return None;
    }
    Some(
        p.wMagic == MAGIC
            && p.nState == !p.nStateInv
            && p.nState == c.nState
            && (SL_FSOE_STATE_RESET..=SL_FSOE_STATE_SHUTDOWN_DEACTIVE).contains(&p.nState)
            && frame_len(usize::from(p.nTxLen)) != 0
            && frame_len(usize::from(p.nRxLen)) != 0,
    )
}

/// Latched SafeData lengths in bytes (received, sent); `None` unless intact.
pub fn data_lens(c: &SL_FSOE_CONN) -> Option<(u8, u8)> {
    (integrity(c) == Some(true)).then_some((c.stPrivate.nRxLen, c.stPrivate.nTxLen))
}

/// Latched Connection ID (0 unless initialised).
pub fn conn_id(c: &SL_FSOE_CONN) -> u16 {
    c.stPrivate.nConnId
}

/// One cycle as a group member: the received frame from the mailbox (`nRxFrameLen` > 0),
/// a new frame into the mailbox (`aTxFrame`, `nTxFrameLen`, `nTxCount` + 1).
/// `nRxFrameLen` above the mailbox: `Status::Length`, the frame is ignored.
pub fn cycle_mailbox(c: &mut SL_FSOE_CONN, now: u32) -> Status {
    let n = usize::from(c.nRxFrameLen);
    let rx_buf = c.aRxFrame;
    let (rx, too_long) = match n {
        0 => (None, false),
        n if n > rx_buf.len() => (None, true),
        n => (Some(&rx_buf[..n]), false),
    };
    let mut tx = [0u8; 68];
    let (mut status, len) = cycle(c, now, rx, &mut tx);
    if len > 0 {
        c.aTxFrame = tx;
        c.nTxFrameLen = len as u16;
        c.nTxCount = c.nTxCount.wrapping_add(1);
    }
    if too_long {
        status = status.worst(Status::Length);
    }
    status
}

/// `sl_fsoe_cycle`: one cycle at `now` with the received frame `rx` (None: nothing new on
/// the wire). Returns the status and the length of the frame written to `tx` (0: none).
/// `Status::Length` when `tx` is too small (nothing done) or `rx` has the wrong length (the
/// frame is ignored, the rest of the cycle runs). `Status::InvalidBool` when an input byte
/// was neither 0 nor 1 (read as ABI-2 §13.1 says). `Status::Config` for a connection whose
/// init was refused or never done, `Status::Corrupt` for a failed private state check.
pub fn cycle(c: &mut SL_FSOE_CONN, now: u32, rx: Option<&[u8]>, tx: &mut [u8]) -> (Status, usize) {
    match integrity(c) {
        None => return (Status::Config, 0),
        Some(false) => {
            clear_outputs(c);
            c.bComErr = 1;
            c.nDiag = SL_DIAG_CORRUPT;
            return (Status::Corrupt, 0);
        }
        Some(true) => {}
    }
    let p = &c.stPrivate;
    if tx.len() < frame_len(usize::from(p.nTxLen)) {
        return (Status::Length, 0);
    }
    let inputs = [
        c.bRun,
        c.bErrAck,
        c.bComErrAck,
        c.bShutdownRequest,
        c.bModuleFault,
    ];
    let mut status = Status::Ok;
    if any_invalid(&inputs) {
        status = Status::InvalidBool;
    }
    let run = c.bRun == 1;
    let module = c.bModuleFault != 0;
    let mut edges = c.stPrivate.nEdges;
    let ack = edge(c.bErrAck, &mut edges, E_ACK);
    let comack = edge(c.bComErrAck, &mut edges, E_COMACK);
    let shut = edge(c.bShutdownRequest, &mut edges, E_SHUT);
    c.stPrivate.nEdges = edges;

    // The frame-received event: a frame that differs from the previous one.
    let mut event: Option<&[u8]> = None;
    if let Some(frame) = rx {
        let n = frame_len(usize::from(c.stPrivate.nRxLen));
        if frame.len() != n {
            status = status.worst(Status::Length);
        } else {
            let p = &mut c.stPrivate;
            let same = p.nFlags & F_HAVE_LAST_RX != 0
                && usize::from(p.nLastRxLen) == n
                && p.aLastRx[..n] == *frame;
            if !same {
                p.aLastRx[..n].copy_from_slice(frame);
                p.nLastRxLen = n as u8;
                p.nFlags |= F_HAVE_LAST_RX;
                event = Some(frame);
            }
        }
    }

    let mut t = Tx {
        buf: tx,
        len: 0,
        now,
    };
    let master = is_master(c);
    if master && c.stPrivate.nFlags2 & G_STARTED == 0 {
        // Power-on: the Reset Connection event.
        c.stPrivate.nFlags2 |= G_STARTED;
        send_reset(c, &mut t, 0);
        event = None;
    }
    let s = c.nState;
    if s == SL_FSOE_STATE_DATA && shut.level {
        // FB_CONNECTION_SHUTDOWN: honoured only in DATA.
        reset_vars(c);
        set_state(c, SL_FSOE_STATE_SHUTDOWN_DEACTIVE);
        c.stPrivate.nFlags2 |= G_SHUTDOWN;
        send_reset(c, &mut t, SL_FSOE_RESET_SHUTDOWN);
        event = None;
    } else if s == SL_FSOE_STATE_SHUTDOWN_DEACTIVE {
        if !shut.level {
            // The master re-establishes the connection, the slave answers again.
            reset_vars(c);
            set_state(c, SL_FSOE_STATE_RESET);
            send_reset(c, &mut t, 0);
        }
        event = None;
    } else if watchdog(c, &mut t) {
        event = None;
    }
    if let Some(frame) = event {
        if master {
            master_rx(c, &mut t, frame, run);
        } else {
            slave_rx(c, &mut t, frame, run);
        }
    }

    let opt = u32::from(c.stPrivate.nOptions);
    let module_err = module && opt & SL_FSOE_OPT_MODULE_ERR_IS_COMERR != 0;
    let p = &mut c.stPrivate;
    if module_err {
        p.nFlags |= F_COM_ERR;
        p.nDiagCode = SL_FSOE_DIAG_MODULE_ERROR as u8;
        p.nFlags &= !F_SLAVE_ERR;
    }
    if p.nFlags & F_COM_ERR != 0 {
        if comack.rising {
            p.nFlags |= F_COMACK_SEEN;
        }
        let acked = opt & SL_FSOE_OPT_COMERRACK == 0 || p.nFlags & F_COMACK_SEEN != 0;
        if ack.rising && acked && c.nState == SL_FSOE_STATE_DATA && !module_err {
            p.nFlags &= !(F_COM_ERR | F_COMACK_SEEN | F_SLAVE_ERR);
            p.nDiagCode = 0;
        }
    }
    outputs(c, run, module);
    (status, t.len)
}
