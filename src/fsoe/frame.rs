//! The FSoE frame codec on caller buffers (ABI-2 §13.6, fsoe.md §2–§4).
//!
//! Layout: `CMD | SafeData[0..1] | CRC_0 | SafeData[2..3] | CRC_1 | … | ConnID`, block k's
//! data at 1 + 4k, CRC_k at 3 + 4k, ConnID at len − 2; one SafeData byte:
//! `CMD | D0 | CRC_0 | ConnID` (6 bytes). Little endian throughout. Pure and total.

use super::crc::{fsoe_crc, next_seq};
use super::*;
use crate::base::types::Status;

/// A decoded frame (`sl_fsoe_frame_decode`). Size: 40 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_FSOE_FRAME {
    /// Offset 0. The command octet.
    pub nCmd: u8,
    /// Offset 1. Reason when rejected (2 unknown command, 4 CRC); else a Reset frame's code (SafeData byte 0), 0 for other commands.
    pub nResetCode: u8,
    /// Offset 2. The ConnID field.
    pub nConnId: u16,
    /// Offset 4. CRC_0 as carried by the frame.
    pub wCrc0: u16,
    /// Offset 6. The sequence number that matched (the last one tried when rejected).
    pub nSeqNo: u16,
    /// Offset 8. SafeData (the first nSafeDataLen bytes; the rest 0).
    pub aSafeData: [u8; 32],
}

/// Frame length for `n` SafeData bytes: 6 for 1, 2n + 3 for even n in 2..=32, else 0.
pub const fn frame_len(n: usize) -> usize {
    if n == 1 {
        6
    } else if n >= 2 && n <= SL_FSOE_DATA_MAX as usize && n % 2 == 0 {
        2 * n + 3
    } else {
        0
    }
}

/// A known command octet.
pub const fn is_known_cmd(cmd: u8) -> bool {
    matches!(
        cmd,
        SL_FSOE_CMD_RESET
            | SL_FSOE_CMD_SESSION
            | SL_FSOE_CMD_CONNECTION
            | SL_FSOE_CMD_PARAMETER
            | SL_FSOE_CMD_PROCESSDATA
            | SL_FSOE_CMD_FAILSAFEDATA
    )
}

/// Data bytes of block `k` (1 or 2) of `data`.
fn block(data: &[u8], k: usize) -> &[u8] {
    if data.len() == 1 {
        &data[..1]
    } else {
        &data[2 * k..2 * k + 2]
    }
}

/// The sequence number whose CRC_0 is used: `seq`, or with the collision rule the first
/// number from `seq` on (65535 → 1) whose CRC_0 differs from `old_crc0`. Bounded: at most
/// 65535 candidates (a CRC_0 equal to `old_crc0` for every number does not occur, and
/// would end with the last candidate).
fn crc0_seq(
    recv_crc0: u16,
    conn_id: u16,
    seq: u16,
    cmd: u8,
    data: &[u8],
    old_crc0: u16,
    collision: bool,
) -> (u16, u16) {
    let mut s = seq;
    let mut c = fsoe_crc(recv_crc0, conn_id, s, cmd, 0, block(data, 0));
    let mut tries = 0u32;
    while collision && c == old_crc0 && tries < 65_535 {
        s = next_seq(s);
        c = fsoe_crc(recv_crc0, conn_id, s, cmd, 0, block(data, 0));
        tries += 1;
    }
    (s, c)
}

/// Encodes a frame into `out` (its first `frame_len(data.len())` bytes). `*seq` in: the
/// sequence number to use; out: the one used (the caller continues from its successor).
/// Returns the frame length and CRC_0. `Status::Length` for an invalid SafeData length or a
/// too small buffer (nothing written); `Status::Frame` for an unknown command.
#[allow(clippy::too_many_arguments)]
pub fn encode(
    out: &mut [u8],
    cmd: u8,
    data: &[u8],
    conn_id: u16,
    recv_crc0: u16,
    seq: &mut u16,
    old_crc0: u16,
    collision: bool,
) -> Result<(usize, u16), Status> {
    let len = frame_len(data.len());
    if len == 0 || out.len() < len {
        return Err(Status::Length);
    }
    if !is_known_cmd(cmd) {
        return Err(Status::Frame);
    }
    let (s, crc0) = crc0_seq(recv_crc0, conn_id, *seq, cmd, data, old_crc0, collision);
    let out = &mut out[..len];
    out[0] = cmd;
    if data.len() == 1 {
        out[1] = data[0];
        out[2..4].copy_from_slice(&crc0.to_le_bytes());
    } else {
        for k in 0..data.len() / 2 {
            let crc = if k == 0 {
                crc0
            } else {
                fsoe_crc(recv_crc0, conn_id, s, cmd, k as u16, block(data, k))
            };
            out[1 + 4 * k..3 + 4 * k].copy_from_slice(block(data, k));
            out[3 + 4 * k..5 + 4 * k].copy_from_slice(&crc.to_le_bytes());
        }
    }
    out[len - 2..].copy_from_slice(&conn_id.to_le_bytes());
    *seq = s;
    Ok((len, crc0))
}

/// Decodes and checks a frame of `n` SafeData bytes. `*seq` in: the expected sequence
/// number; out (accepted frames only): the one that matched. `out` is filled in every case
/// but `Status::Length` (the frame's length is not that of `n`). `Status::Frame`: unknown
/// command (`nResetCode` 2) or a CRC mismatch (`nResetCode` 4).
#[allow(clippy::too_many_arguments)]
pub fn decode(
    frame: &[u8],
    n: usize,
    recv_crc0: u16,
    seq: &mut u16,
    old_crc0: u16,
    collision: bool,
    out: &mut SL_FSOE_FRAME,
) -> Status {
    let len = frame_len(n);
    if len == 0 || frame.len() != len {
        return Status::Length;
    }
    let mut data = [0u8; SL_FSOE_DATA_MAX as usize];
    let blocks = if n == 1 { 1 } else { n / 2 };
    let mut wire_crc = [0u16; SL_FSOE_DATA_MAX as usize / 2];
    if n == 1 {
        data[0] = frame[1];
        wire_crc[0] = u16::from_le_bytes([frame[2], frame[3]]);
    } else {
        for k in 0..blocks {
            data[2 * k..2 * k + 2].copy_from_slice(&frame[1 + 4 * k..3 + 4 * k]);
            wire_crc[k] = u16::from_le_bytes([frame[3 + 4 * k], frame[4 + 4 * k]]);
        }
    }
    let cmd = frame[0];
    *out = SL_FSOE_FRAME {
        nCmd: cmd,
        nResetCode: if cmd == SL_FSOE_CMD_RESET { data[0] } else { 0 },
        nConnId: u16::from_le_bytes([frame[len - 2], frame[len - 1]]),
        wCrc0: wire_crc[0],
        nSeqNo: *seq,
        aSafeData: data,
    };
    if !is_known_cmd(cmd) {
        out.nResetCode = SL_FSOE_RESET_UNKNOWN_CMD;
        return Status::Frame;
    }
    let data = &data[..n];
    let (s, crc0) = crc0_seq(recv_crc0, out.nConnId, *seq, cmd, data, old_crc0, collision);
    out.nSeqNo = s;
    let mut ok = crc0 == wire_crc[0];
    for (k, &w) in wire_crc.iter().enumerate().take(blocks).skip(1) {
        ok &= fsoe_crc(recv_crc0, out.nConnId, s, cmd, k as u16, block(data, k)) == w;
    }
    if !ok {
        out.nResetCode = SL_FSOE_RESET_INVALID_CRC;
        return Status::Frame;
    }
    *seq = s;
    Status::Ok
}
