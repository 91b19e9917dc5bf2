//! FSoE frame codec and CRC (ABI-2 §13.6, §13.7; fsoe.md §12.1, §12.2): every known-answer
//! vector byte for byte, 1-byte and 2…32-byte SafeData, the collision rule on both sides,
//! lengths, and random round trips against an independent bit-wise reference CRC.

use safelogic::fsoe::crc::{fsoe_crc, next_seq};
use safelogic::fsoe::frame::{decode, encode, frame_len};
use safelogic::*;

/// Independent reference: bit-wise CRC-16/0x39B7 over the octets and three zero octets.
fn ref_crc(bytes: &[u8]) -> u16 {
    let mut crc: u16 = 0;
    for &b in bytes.iter().chain([0u8, 0, 0].iter()) {
        crc ^= u16::from(b) << 8;
        for _ in 0..8 {
            crc = if crc & 0x8000 != 0 {
                (crc << 1) ^ 0x39B7
            } else {
                crc << 1
            };
        }
    }
    crc
}

fn ref_block_crc(recv: u16, conn: u16, seq: u16, cmd: u8, k: u16, block: &[u8]) -> u16 {
    let mut v = Vec::new();
    v.extend_from_slice(&recv.to_le_bytes());
    v.extend_from_slice(&conn.to_le_bytes());
    v.extend_from_slice(&seq.to_le_bytes());
    v.push(cmd);
    if k > 0 {
        v.extend_from_slice(&k.to_le_bytes());
    }
    v.extend_from_slice(block);
    ref_crc(&v)
}

/// Independent reference encoder (no collision rule).
fn ref_frame(cmd: u8, data: &[u8], conn: u16, recv: u16, seq: u16) -> Vec<u8> {
    let mut f = vec![cmd];
    if data.len() == 1 {
        f.push(data[0]);
        f.extend_from_slice(&ref_block_crc(recv, conn, seq, cmd, 0, data).to_le_bytes());
    } else {
        for k in 0..data.len() / 2 {
            let b = &data[2 * k..2 * k + 2];
            f.extend_from_slice(b);
            f.extend_from_slice(&ref_block_crc(recv, conn, seq, cmd, k as u16, b).to_le_bytes());
        }
    }
    f.extend_from_slice(&conn.to_le_bytes());
    f
}

fn hex(s: &str) -> Vec<u8> {
    s.split_whitespace()
        .map(|b| u8::from_str_radix(b, 16).unwrap())
        .collect()
}

fn enc(cmd: u8, data: &[u8], conn: u16, recv: u16, seq: u16) -> Vec<u8> {
    let mut out = [0u8; 67];
    let mut s = seq;
    let (len, _) = encode(&mut out, cmd, data, conn, recv, &mut s, 0, false).unwrap();
    out[..len].to_vec()
}

#[test]
fn crc_known_answers_fsoe_md_12_1() {
    assert_eq!(fsoe_crc(0, 0, 1, 0x4E, 0, &[0x12, 0x34]), 0x4D07);
    assert_eq!(fsoe_crc(0, 0, 1, 0x4E, 0, &[0x12]), 0xA176);
    assert_eq!(fsoe_crc(0xABCD, 0x0007, 2, 0x36, 1, &[0xDE, 0xAD]), 0xBC47);
    // The reference agrees, and the CRC without the three zero octets is not the FSoE CRC.
    assert_eq!(ref_block_crc(0, 0, 1, 0x4E, 0, &[0x12, 0x34]), 0x4D07);
    for wrong in [0x9137u16, 0xA973, 0xDA0B] {
        assert_ne!(fsoe_crc(0, 0, 1, 0x4E, 0, &[0x12, 0x34]), wrong);
    }
    let c = crc::Crc::<u16>::new(&safelogic::fsoe::crc::CRC_16_FSOE_BASE);
    assert_eq!(c.checksum(b"123456789"), 0xDDE2);
}

#[test]
fn crc_via_c_function() {
    // SAFETY: valid buffers of the given lengths.
    unsafe {
        assert_eq!(
            safelogic::ffi::sl_fsoe_crc(0xABCD, 7, 2, 0x36, 1, [0xDE, 0xAD].as_ptr(), 2),
            0xBC47
        );
        assert_eq!(
            safelogic::ffi::sl_fsoe_crc(0, 0, 1, 0x4E, 0, [0x12].as_ptr(), 1),
            0xA176
        );
        assert_eq!(
            safelogic::ffi::sl_fsoe_crc(0, 0, 1, 0x4E, 0, core::ptr::null(), 1),
            0
        );
        assert_eq!(
            safelogic::ffi::sl_fsoe_crc(0, 0, 1, 0x4E, 0, [1, 2, 3].as_ptr(), 3),
            0
        );
    }
}

#[test]
fn single_frames_fsoe_md_12_2() {
    let rows: [(&[u8], u8, &str); 8] = [
        (&[0], 0x2A, "2A 00 86 F8 00 00"),
        (&[4], 0x2A, "2A 04 11 18 00 00"),
        (&[5], 0x2A, "2A 05 59 6E 00 00"),
        (&[0x12], 0x4E, "4E 12 76 A1 00 00"),
        (&[0, 0], 0x2A, "2A 00 00 C4 2D 00 00"),
        (&[4, 0], 0x2A, "2A 04 00 A6 34 00 00"),
        (&[5, 0], 0x2A, "2A 05 00 25 AE 00 00"),
        (&[0x12, 0x34], 0x4E, "4E 12 34 07 4D 00 00"),
    ];
    for (data, cmd, want) in rows {
        assert_eq!(enc(cmd, data, 0, 0, 1), hex(want), "{want}");
    }
    assert_eq!(
        enc(0x2A, &[0, 0, 0, 0], 0, 0, 1),
        hex("2A 00 00 C4 2D 00 00 B9 14 00 00")
    );
}

/// (cmd, SafeData, ConnID, recvCrc0, SeqNo, bytes).
type TraceRow = (u8, [u8; 4], u16, u16, u16, &'static str);

#[test]
fn trace_frames_fsoe_md_12_2_encode_and_decode() {
    // (cmd, data, conn, recv, seq, bytes) of the 13-frame trace.
    let rows: [TraceRow; 13] = [
        (
            0x2A,
            [0, 0, 0, 0],
            0,
            0,
            1,
            "2A 00 00 C4 2D 00 00 B9 14 00 00",
        ),
        (
            0x2A,
            [0, 0, 0, 0],
            0,
            0,
            1,
            "2A 00 00 C4 2D 00 00 B9 14 00 00",
        ),
        (
            0x4E,
            [0x12, 0x34, 0, 0],
            0,
            0,
            1,
            "4E 12 34 07 4D 00 00 43 4E 00 00",
        ),
        (
            0x4E,
            [0x78, 0x56, 0, 0],
            0,
            0x4D07,
            1,
            "4E 78 56 D3 B9 00 00 38 73 00 00",
        ),
        (
            0x64,
            [7, 0, 3, 0],
            7,
            0xB9D3,
            2,
            "64 07 00 9F 29 03 00 F0 07 07 00",
        ),
        (
            0x64,
            [7, 0, 3, 0],
            7,
            0x299F,
            2,
            "64 07 00 5B 5D 03 00 03 A3 07 00",
        ),
        (
            0x52,
            [2, 0, 0x64, 0],
            7,
            0x5D5B,
            3,
            "52 02 00 A1 A5 64 00 D8 52 07 00",
        ),
        (
            0x52,
            [2, 0, 0x64, 0],
            7,
            0xA5A1,
            3,
            "52 02 00 97 D1 64 00 8E DA 07 00",
        ),
        (
            0x52,
            [0, 0, 0, 0],
            7,
            0xD197,
            4,
            "52 00 00 39 A6 00 00 BB 5B 07 00",
        ),
        (
            0x52,
            [0, 0, 0, 0],
            7,
            0xA639,
            4,
            "52 00 00 AD 00 00 00 98 A4 07 00",
        ),
        (
            0x08,
            [0, 0, 0, 0],
            7,
            0x00AD,
            5,
            "08 00 00 A6 00 00 00 4E 1A 07 00",
        ),
        (
            0x36,
            [1, 2, 3, 4],
            7,
            0x00A6,
            5,
            "36 01 02 C1 8B 03 04 EB C3 07 00",
        ),
        (
            0x36,
            [0xAA, 0x55, 0, 0xFF],
            7,
            0x8BC1,
            6,
            "36 AA 55 A0 38 00 FF 07 36 07 00",
        ),
    ];
    for (i, (cmd, data, conn, recv, seq, want)) in rows.iter().enumerate() {
        let w = hex(want);
        assert_eq!(enc(*cmd, data, *conn, *recv, *seq), w, "row {}", i + 1);
        assert_eq!(
            ref_frame(*cmd, data, *conn, *recv, *seq),
            w,
            "reference row {}",
            i + 1
        );
        let mut s = *seq;
        let mut f = SL_FSOE_FRAME::default();
        assert_eq!(
            decode(&w, 4, *recv, &mut s, 0, true, &mut f),
            Status::Ok,
            "row {}",
            i + 1
        );
        assert_eq!(
            (f.nCmd, f.nConnId, f.nSeqNo, &f.aSafeData[..4]),
            (*cmd, *conn, *seq, &data[..])
        );
    }
    assert_eq!(hex("02 00 64 00 00 00"), [2, 0, 100, 0, 0, 0]);
}

#[test]
fn frame_lengths_and_offsets() {
    assert_eq!(frame_len(1), 6);
    for (n, l) in [(2, 7), (4, 11), (6, 15), (8, 19), (12, 27), (32, 67)] {
        assert_eq!(frame_len(n), l);
        assert_eq!(safelogic::ffi::sl_fsoe_frame_len(n), l);
    }
    for n in [0usize, 3, 5, 31, 33, 34, 126, usize::MAX] {
        assert_eq!(frame_len(n), 0, "{n}");
    }
    // Block k data at 1 + 4k, CRC_k at 3 + 4k, ConnID at len - 2 (n = 8).
    let data: Vec<u8> = (1..=8).collect();
    let f = enc(0x36, &data, 0x1234, 0x5555, 9);
    for k in 0..4 {
        assert_eq!(&f[1 + 4 * k..3 + 4 * k], &data[2 * k..2 * k + 2]);
        let crc = u16::from_le_bytes([f[3 + 4 * k], f[4 + 4 * k]]);
        assert_eq!(
            crc,
            ref_block_crc(0x5555, 0x1234, 9, 0x36, k as u16, &data[2 * k..2 * k + 2])
        );
    }
    assert_eq!(&f[17..19], &[0x34, 0x12]);
}

#[test]
fn lengths_and_unknown_commands_are_refused() {
    let mut out = [0u8; 67];
    let mut s = 1;
    assert_eq!(
        encode(&mut out[..10], 0x36, &[0; 4], 1, 0, &mut s, 0, true),
        Err(Status::Length)
    );
    assert_eq!(
        encode(&mut out, 0x36, &[0; 3], 1, 0, &mut s, 0, true),
        Err(Status::Length)
    );
    assert_eq!(
        encode(&mut out, 0x99, &[0; 4], 1, 0, &mut s, 0, true),
        Err(Status::Frame)
    );
    assert_eq!(out, [0u8; 67]);
    let good = enc(0x36, &[1, 2, 3, 4], 1, 0, 1);
    let mut f = SL_FSOE_FRAME::default();
    assert_eq!(
        decode(&good[..10], 4, 0, &mut s, 0, true, &mut f),
        Status::Length
    );
    assert_eq!(decode(&good, 2, 0, &mut s, 0, true, &mut f), Status::Length);
    let mut bad = good.clone();
    bad[0] = 0x99;
    assert_eq!(decode(&bad, 4, 0, &mut s, 0, true, &mut f), Status::Frame);
    assert_eq!(f.nResetCode, 2);
    assert_eq!(SL_E_LENGTH, -11);
    assert_eq!(SL_E_FRAME, -12);
    assert_eq!(Status::from_code(SL_E_LENGTH), Status::Length);
    assert_eq!(Status::from_code(SL_E_FRAME), Status::Frame);
}

/// Every single-bit flip of a frame is detected (CRC or command or length-preserving
/// ConnID change seen by the CRC), for 1-byte and all even lengths.
#[test]
fn every_bit_flip_is_rejected() {
    for n in [1usize, 2, 4, 6, 8, 16, 32] {
        let data: Vec<u8> = (0..n as u8)
            .map(|i| i.wrapping_mul(37).wrapping_add(5))
            .collect();
        let good = enc(0x36, &data, 0x0102, 0xBEEF, 77);
        for bit in 0..good.len() * 8 {
            let mut bad = good.clone();
            bad[bit / 8] ^= 1 << (bit % 8);
            let mut s = 77;
            let mut f = SL_FSOE_FRAME::default();
            let st = decode(&bad, n, 0xBEEF, &mut s, 0, true, &mut f);
            assert_eq!(st, Status::Frame, "n {n} bit {bit}");
            assert!(f.nResetCode == 2 || f.nResetCode == 4);
        }
    }
}

#[test]
fn collision_rule_both_sides() {
    // Find a case where CRC_0 with seq equals `old`: use old = CRC_0 at seq itself.
    let mut hits = 0;
    for seq in [1u16, 2, 100, 65535] {
        for n in [1usize, 2, 4] {
            let data = vec![0x5Au8; n];
            let old = fsoe_crc(0x1111, 3, seq, 0x36, 0, &data[..n.min(2)]);
            let mut out = [0u8; 67];
            let mut s = seq;
            let (len, crc0) = encode(&mut out, 0x36, &data, 3, 0x1111, &mut s, old, true).unwrap();
            assert_ne!(crc0, old);
            assert_eq!(s, next_seq(seq), "65535 wraps to 1, never 0");
            assert_ne!(s, 0);
            assert_eq!(out[..len].to_vec(), ref_frame(0x36, &data, 3, 0x1111, s));
            // The receiver with the same old CRC finds the same number.
            let mut r = seq;
            let mut f = SL_FSOE_FRAME::default();
            assert_eq!(
                decode(&out[..len], n, 0x1111, &mut r, old, true, &mut f),
                Status::Ok
            );
            assert_eq!(r, s);
            // Without the collision check the receiver expects `seq` and rejects it.
            let mut r = seq;
            assert_eq!(
                decode(&out[..len], n, 0x1111, &mut r, old, false, &mut f),
                Status::Frame
            );
            // Without the check the sender keeps `seq`.
            let mut s2 = seq;
            let (_, c2) = encode(&mut out, 0x36, &data, 3, 0x1111, &mut s2, old, false).unwrap();
            assert_eq!((s2, c2), (seq, old));
            hits += 1;
        }
    }
    assert_eq!(hits, 12);
}

/// 10,000 random frames: encode equals the reference encoder; decode accepts them and
/// returns the fields; a wrong sequence number or chain value is refused.
#[test]
fn random_round_trips_against_the_reference() {
    let mut x = 0x2545_F491_4F6C_DD1Du64;
    let mut rnd = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let cmds = [0x2A, 0x4E, 0x64, 0x52, 0x36, 0x08];
    for _ in 0..10_000 {
        let r = rnd();
        let n = if r % 17 == 0 {
            1
        } else {
            2 * (1 + (r >> 8) as usize % 16)
        };
        let data: Vec<u8> = (0..n).map(|_| rnd() as u8).collect();
        let cmd = cmds[(r >> 20) as usize % 6];
        let conn = (r >> 24) as u16;
        let recv = (r >> 40) as u16;
        let seq = ((r >> 56) as u16).max(1);
        let f = enc(cmd, &data, conn, recv, seq);
        assert_eq!(f, ref_frame(cmd, &data, conn, recv, seq));
        let mut s = seq;
        let mut out = SL_FSOE_FRAME::default();
        assert_eq!(decode(&f, n, recv, &mut s, 0, false, &mut out), Status::Ok);
        assert_eq!(
            (out.nCmd, out.nConnId, &out.aSafeData[..n]),
            (cmd, conn, &data[..])
        );
        let mut s = next_seq(seq);
        assert_eq!(
            decode(&f, n, recv, &mut s, 0, false, &mut out),
            Status::Frame
        );
        let mut s = seq;
        assert_eq!(
            decode(&f, n, recv ^ 1, &mut s, 0, false, &mut out),
            Status::Frame
        );
    }
}
