//! Wrapping millisecond time (ABI §4, §7): `tNow` may wrap at 2^32; every difference is
//! taken modulo 2^32, so a timer keeps working across the wrap.

/// Milliseconds from `start` to `now`, modulo 2^32.
#[inline]
pub const fn elapsed(now: u32, start: u32) -> u32 {
    now.wrapping_sub(start)
}

/// A time `t` started at `start` is reached at the first cycle with `now - start >= t`.
#[inline]
pub const fn reached(now: u32, start: u32, t: u32) -> bool {
    elapsed(now, start) >= t
}

/// The clock went backwards: the wrapping difference to the previous call is >= 2^31.
#[inline]
pub const fn went_backwards(now: u32, last: u32) -> bool {
    elapsed(now, last) >= 0x8000_0000
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wraps_across_2_pow_32() {
        assert_eq!(elapsed(5, u32::MAX - 4), 10);
        assert!(reached(5, u32::MAX - 4, 10));
        assert!(!reached(4, u32::MAX - 4, 10));
    }

    #[test]
    fn backwards_is_half_the_circle() {
        assert!(!went_backwards(100, 100));
        assert!(!went_backwards(100 + 0x7FFF_FFFF, 100));
        assert!(went_backwards(99, 100));
        assert!(went_backwards(100u32.wrapping_add(0x8000_0000), 100));
    }
}
