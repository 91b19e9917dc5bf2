//! The FSoE frame decoder through its C function (`sl_fsoe_frame_decode`), on arbitrary
//! bytes with arbitrary SafeData length, CRC_0 of the last received frame, expected sequence
//! number, old CRC_0 and collision flag. After every call: a documented status; the frame
//! length rule (SL_E_LENGTH exactly when the length is not that of the SafeData length, and
//! then nothing written); and what makes the decoder safe: a frame it accepts is authentic,
//! i.e. encoding its decoded command, SafeData and ConnID with the same CRC_0 and the
//! sequence number it matched (no collision search) gives back the received bytes exactly.
//! Half of the inputs (first byte odd) start from a frame the encoder built from the
//! input's own fields and flip the bits of the rest of the input into it, so the accept
//! path is reached: an accepted mutated frame must still be authentic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use safelogic::ffi::{sl_fsoe_frame_decode, sl_fsoe_frame_encode};
use safelogic::*;

/// Frame length of `n` SafeData bytes (ABI-2 §13.6), 0 for an invalid `n`.
fn frame_len(n: usize) -> usize {
    match n {
        1 => 6,
        2..=32 if n % 2 == 0 => 3 + 2 * n,
        _ => 0,
    }
}

fuzz_target!(|input: &[u8]| {
    if input.len() < 8 {
        return;
    }
    let n = usize::from(input[0] % 36);
    let crc0 = u16::from_le_bytes([input[1], input[2]]);
    let seq_in = u16::from_le_bytes([input[3], input[4]]);
    let old = u16::from_le_bytes([input[5], input[6]]);
    let collision = input[7] % 3; // 2: an invalid BOOL
    let mut built = [0u8; 80];
    let frame: &[u8] = if input[0] & 1 == 1 && frame_len(n) != 0 {
        let len = frame_len(n);
        let tail = &input[8..];
        let mut data = [0u8; 32];
        for (k, d) in data.iter_mut().take(n).enumerate() {
            *d = tail.get(k).copied().unwrap_or(0);
        }
        let (mut blen, mut s) = (0usize, seq_in);
        let cmd = [0x36u8, 0x2A, 0x4E, 0x64, 0x52, 0x08][usize::from(input[0] >> 1) % 6];
        let rc = unsafe {
            sl_fsoe_frame_encode(
                built.as_mut_ptr(),
                built.len(),
                &mut blen,
                cmd,
                data.as_ptr(),
                n,
                u16::from(input[3]) | 1,
                crc0,
                &mut s,
                old,
                collision.min(1),
            )
        };
        assert_eq!((rc, blen), (SL_OK, len));
        // flip: the input after the SafeData bytes, as an XOR mask
        for (k, m) in tail.iter().skip(n).enumerate() {
            built[k % len] ^= m;
        }
        &built[..len]
    } else {
        &input[8..]
    };
    let mut seq = seq_in;
    let mut out = SL_FSOE_FRAME {
        nCmd: 0xAA,
        ..Default::default()
    };
    let st = unsafe {
        sl_fsoe_frame_decode(
            frame.as_ptr(),
            frame.len(),
            n,
            crc0,
            &mut seq,
            old,
            collision,
            &mut out,
        )
    };
    assert!(
        [SL_OK, SL_E_LENGTH, SL_E_FRAME, SL_E_INVALID_BOOL].contains(&st),
        "undocumented status {st}"
    );
    if collision > 1 {
        assert_eq!(st, SL_E_INVALID_BOOL);
        return;
    }
    let len = frame_len(n);
    assert_eq!(
        st == SL_E_LENGTH,
        len == 0 || frame.len() != len,
        "length rule"
    );
    if st == SL_E_LENGTH {
        assert_eq!((out.nCmd, seq), (0xAA, seq_in), "written on SL_E_LENGTH");
        return;
    }
    if st != SL_OK {
        assert_eq!(
            seq, seq_in,
            "the expected sequence number moved on a refused frame"
        );
        return;
    }
    // Accepted: re-encode what was decoded with the sequence number that matched.
    let mut again = [0u8; 80];
    let mut again_len = 0usize;
    let mut s = out.nSeqNo;
    let data = &out.aSafeData[..n];
    let rc = unsafe {
        sl_fsoe_frame_encode(
            again.as_mut_ptr(),
            again.len(),
            &mut again_len,
            out.nCmd,
            data.as_ptr(),
            n,
            out.nConnId,
            crc0,
            &mut s,
            old,
            0,
        )
    };
    assert_eq!(rc, SL_OK);
    assert_eq!(
        &again[..again_len],
        frame,
        "an accepted frame is not what the sender's encoder gives"
    );
    assert_eq!(seq, out.nSeqNo);
});
