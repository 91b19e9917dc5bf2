//! BOOL decoding (ABI §2): 0 = FALSE, 1 = TRUE, anything else is an invalid BOOL that reads
//! as the value demanding the safe state. Edges of control inputs (ABI §7).

/// Whether any of the BOOL bytes is invalid (neither 0 nor 1).
#[inline(always)]
pub fn any_invalid(raw: &[u8]) -> bool {
    raw.iter().any(|&b| b > 1)
}

/// A set of BOOL input bytes packed into bit masks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Packed {
    /// Bit i set: byte i is exactly 1.
    pub ones: u8,
    /// Bit i set: byte i is neither 0 nor 1.
    pub invalid: u8,
}

/// Packs up to eight BOOL bytes into masks (bit i = byte i), all bytes at once.
#[inline]
pub fn pack<const N: usize>(input: [u8; N]) -> Packed {
    const { assert!(N <= 8) };
    let mut bytes = [0u8; 8];
    for (b, i) in bytes.iter_mut().zip(input) {
        *b = i;
    }
    const LSB: u64 = 0x0101_0101_0101_0101;
    // Multiplying a value whose bytes are 0 or 1 by this gathers byte i's bit into bit 56+i.
    const GATHER: u64 = 0x0102_0408_1020_4080;
    let v = u64::from_le_bytes(bytes);
    let high = v & !LSB;
    // Byte-wise "high != 0": adding 0x7F to the low seven bits carries into bit 7.
    let nonzero = (((high & (LSB * 0x7F)) + LSB * 0x7F) | high) >> 7 & LSB;
    Packed {
        ones: ((v & LSB & !nonzero).wrapping_mul(GATHER) >> 56) as u8,
        invalid: (nonzero.wrapping_mul(GATHER) >> 56) as u8,
    }
}

/// The fast-path key of up to sixteen BOOL bytes (bit i = byte i), or `None` when a byte
/// is neither 0 nor 1 (such a call always takes the full cycle).
#[inline(always)]
pub fn key<const N: usize>(input: [u8; N]) -> Option<u16> {
    const { assert!(N <= 16) };
    let mut bytes = [0u8; 16];
    for (b, i) in bytes.iter_mut().zip(input) {
        *b = i;
    }
    const LSB: u64 = 0x0101_0101_0101_0101;
    const GATHER: u64 = 0x0102_0408_1020_4080;
    let [a0, a1, a2, a3, a4, a5, a6, a7, b0, b1, b2, b3, b4, b5, b6, b7] = bytes;
    let lo = u64::from_le_bytes([a0, a1, a2, a3, a4, a5, a6, a7]);
    let hi = u64::from_le_bytes([b0, b1, b2, b3, b4, b5, b6, b7]);
    if (lo | hi) & !LSB != 0 {
        return None;
    }
    let gather = |v: u64| (v.wrapping_mul(GATHER) >> 56) as u16;
    Some(gather(lo) | gather(hi) << 8)
}

/// Logical values of safety inputs: raw XOR negation for active inputs; an invalid byte
/// reads as logical FALSE (the safe-state request) whatever its negation. Inactive
/// inputs read FALSE here; callers mask with the active set.
#[inline]
pub const fn logical(p: Packed, active: u8, negated: u8) -> u8 {
    ((p.ones ^ negated) & !p.invalid) & active
}

/// A control input (Restart, ErrAck, Run, EDM...): TRUE only for the byte 1.
#[inline]
pub const fn is_true(raw: u8) -> bool {
    raw == 1
}

/// A control input that reads FALSE: only the byte 0 (an invalid byte is neither).
#[inline]
pub const fn is_false(raw: u8) -> bool {
    raw == 0
}

/// Edges of a control input whose previous level is kept in one bit of a flag byte.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Edge {
    /// Level this cycle (invalid bytes read FALSE).
    pub level: bool,
    pub rising: bool,
    pub falling: bool,
}

/// Updates the edge memory `bit` in `flags` from the raw byte. An invalid byte reads FALSE
/// and produces no edge, so a corrupted Restart or ErrAck never completes a sequence.
#[inline]
pub fn edge(raw: u8, flags: &mut u8, bit: u8) -> Edge {
    let prev = *flags & bit != 0;
    let level = raw == 1;
    let valid = raw <= 1;
    if level {
        *flags |= bit;
    } else {
        *flags &= !bit;
    }
    Edge {
        level,
        rising: level && !prev,
        falling: valid && prev && !level,
    }
}

/// Declares private flag constants of type `$t`, one bit each from bit 0 in the order
/// named (each may carry its doc): `bit_flags!(u8: F_A, F_B);` is
/// `const F_A: u8 = 1 << 0; const F_B: u8 = 1 << 1;`.
macro_rules! bit_flags {
    ($t:ty: $($(#[$m:meta])* $name:ident),+ $(,)?) => {
        $crate::base::bools::bit_flags!(@ $t, 0, $($(#[$m])* $name),+);
    };
    (@ $t:ty, $n:expr, $(#[$m:meta])* $name:ident $(, $($(#[$rm:meta])* $rest:ident),+)?) => {
        $(#[$m])*
        const $name: $t = 1 << ($n);
        $($crate::base::bools::bit_flags!(@ $t, $n + 1, $($(#[$rm])* $rest),+);)?
    };
}
pub(crate) use bit_flags;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pack_and_logical() {
        let p = pack([1, 0, 2, 1, 0, 0xFF, 1, 0]);
        assert_eq!(p.ones, 0b0100_1001);
        assert_eq!(p.invalid, 0b0010_0100);
        // input 1 negated (make contact): raw 0 -> logical TRUE; invalid input 5 negated -> FALSE
        assert_eq!(logical(p, 0xFF, 0b0010_0010), 0b0100_1011);
    }

    #[test]
    fn pack_matches_a_byte_by_byte_reading() {
        let samples = [0u8, 1, 2, 3, 0x7F, 0x80, 0x81, 0xFE, 0xFF];
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..20_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let bytes: [u8; 8] =
                core::array::from_fn(|i| samples[((seed >> (i * 7)) % 9) as usize]);
            let p = pack(bytes);
            for (i, &b) in bytes.iter().enumerate() {
                assert_eq!(p.ones >> i & 1 == 1, b == 1, "{bytes:?}");
                assert_eq!(p.invalid >> i & 1 == 1, b > 1, "{bytes:?}");
            }
        }
    }

    #[test]
    fn key_is_one_bit_per_byte_and_refuses_other_bytes() {
        assert_eq!(key([1u8, 0, 1]), Some(0b101));
        let mut sixteen = [0u8; 16];
        sixteen[15] = 1;
        sixteen[8] = 1;
        assert_eq!(key(sixteen), Some(0x8100));
        for bad in [2u8, 0x80, 0xFF] {
            for at in 0..16 {
                let mut b = [1u8; 16];
                b[at] = bad;
                assert_eq!(key(b), None, "{b:?}");
            }
            // The same bad byte in both halves (bytes i and i + 8) must not cancel out.
            for at in 0..8 {
                let mut b = [0u8; 16];
                (b[at], b[at + 8]) = (bad, bad);
                assert_eq!(key(b), None, "{b:?}");
            }
        }
    }

    #[test]
    fn invalid_control_byte_gives_no_edge() {
        let mut f = 0u8;
        assert!(edge(1, &mut f, 1).rising);
        let e = edge(7, &mut f, 1);
        assert!(!e.level && !e.falling && !e.rising);
        assert!(!edge(0, &mut f, 1).falling);
        assert!(edge(1, &mut f, 1).rising);
        assert!(edge(0, &mut f, 1).falling);
    }
}
