//! Pieces the timer tests (TON, TOF) share: the delay limit of every timebase and the walk
//! of one delay to its end.

use safelogic::*;

/// Every fixed timebase with its largest delay: 60,000 steps of it (T1, T3).
pub const BASE_LIMITS: [(u16, u32); 4] = [
    (SL_TIMEBASE_1MS, 60_000),
    (SL_TIMEBASE_10MS, 600_000),
    (SL_TIMEBASE_100MS, 6_000_000),
    (SL_TIMEBASE_1000MS, 60_000_000),
];

/// T1, T3: `check(delay, base)` for every fixed timebase with the delay of one step, one
/// step below the limit and at the limit, and for the automatic timebase at each limit.
pub fn at_and_below_the_limits(mut check: impl FnMut(u32, u16)) {
    for (base, max) in BASE_LIMITS {
        let b = u32::from(base);
        for delay in [b, max - b, max] {
            check(delay, base);
        }
        check(max, SL_TIMEBASE_AUTO);
    }
}

/// From the call at `start` that started the timer: calls in big steps (below 2^31, so that
/// the clock check does not fire) up to one ms before the delay ends, each showing `during`
/// as (state, output); then the call at `start + delay`, showing `after`. A failure names
/// the delay, the timebase and the time.
#[track_caller]
pub fn walk_delay<B: FunctionBlock>(
    f: &mut B,
    st: fn(&B) -> (u8, u8),
    (start, delay, base): (u32, u32, u16),
    during: (u8, u8),
    after: (u8, u8),
) {
    let end = start.wrapping_add(delay - 1);
    let mut t = start;
    while t != end {
        t = t.wrapping_add(end.wrapping_sub(t).min(1 << 30));
        assert_eq!(f.cycle(t), SL_OK, "delay {delay} base {base} at {t}");
        assert_eq!(st(f), during, "delay {delay} base {base} at {t}");
    }
    let t = start.wrapping_add(delay);
    assert_eq!(f.cycle(t), SL_OK, "delay {delay} base {base} at {t}");
    assert_eq!(st(f), after, "delay {delay} base {base} at {t}");
}
