//! Two-channel input pairs with discrepancy monitoring and the "Safe Inputs after Disc
//! Error" latch (ABI §7 "Pairs"; manual §4.4.1, §4.5.1). Pair k consists of the inputs
//! with bits 2k and 2k+1 of a logical-value mask.

use super::time;

/// Bit k set: the two channels of pair k have different logical values now.
#[inline]
pub const fn differing(logical: u8) -> u8 {
    let a = logical & 0b0101_0101;
    let b = (logical >> 1) & 0b0101_0101;
    compress_even(a ^ b)
}

/// Bit k set: both channels of pair k request the safe state (logical FALSE) now.
#[inline]
pub const fn both_safe(logical: u8) -> u8 {
    let a = !logical & 0b0101_0101;
    let b = (!logical >> 1) & 0b0101_0101;
    compress_even(a & b)
}

/// Moves bits 0, 2, 4, 6 to bits 0, 1, 2, 3.
#[inline]
const fn compress_even(x: u8) -> u8 {
    (x & 1) | ((x >> 1) & 2) | ((x >> 2) & 4) | ((x >> 3) & 8)
}

/// One cycle of discrepancy monitoring for the pairs in `monitored` (bit k = pair k, at most
/// `starts.len()` pairs). `running` holds bit k while pair k's timer runs, `starts[k]` its
/// start time, `times[k]` its discrepancy time in ms (non-zero for monitored pairs).
/// Returns bit k set when pair k has differed continuously for its full time.
#[inline]
pub fn monitor(
    logical: u8,
    monitored: u8,
    running: &mut u8,
    starts: &mut [u32],
    times: &[impl Copy + Into<u32>],
    now: u32,
) -> u8 {
    let diff = differing(logical) & monitored;
    // Timers of pairs that agree again stop; timers of pairs that start to differ start now.
    let starting = diff & !*running;
    *running = diff;
    if diff == 0 {
        return 0;
    }
    let mut errors = 0u8;
    for (k, (start, &t)) in starts.iter_mut().zip(times).enumerate() {
        let bit = 1u8 << k;
        if starting & bit != 0 {
            *start = now;
        } else if diff & bit != 0 && time::reached(now, *start, t.into()) {
            errors |= bit;
        }
    }
    errors
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differing_and_both_safe() {
        assert_eq!(differing(0b0000_0001), 0b0001);
        assert_eq!(differing(0b1000_0011), 0b1000);
        assert_eq!(both_safe(0b1000_0011), 0b0110);
    }

    #[test]
    fn error_exactly_at_the_limit() {
        let (mut run, mut st) = (0u8, [0u32; 1]);
        assert_eq!(monitor(0b01, 1, &mut run, &mut st, &[100u16], 1000), 0);
        assert_eq!(monitor(0b01, 1, &mut run, &mut st, &[100u16], 1099), 0);
        assert_eq!(monitor(0b01, 1, &mut run, &mut st, &[100u16], 1100), 1);
        // agreeing again stops the timer; a new discrepancy starts from scratch
        assert_eq!(monitor(0b11, 1, &mut run, &mut st, &[100u16], 1101), 0);
        assert_eq!(monitor(0b10, 1, &mut run, &mut st, &[100u16], 1102), 0);
        assert_eq!(monitor(0b10, 1, &mut run, &mut st, &[100u16], 1201), 0);
        assert_eq!(monitor(0b10, 1, &mut run, &mut st, &[100u16], 1202), 1);
    }
}
