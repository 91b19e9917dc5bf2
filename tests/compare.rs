//! FB COMPARE (manual §4.20, ABI-2 §11.3, §12; docs/semantics.md CP1–CP4) in all four
//! integer variants: one test per statement of the manual section, then random sequences
//! against a small model of the block (≥ 10,000 per variant, with an independent brute-force
//! majority) that assert what they reached.

mod common;

use common::Rng;
use safelogic::blocks::analog::Analog;
use safelogic::*;

fn active(arch: u16) -> u16 {
    ((1 << arch) - 1) << 8
}

/// Brute force: the smallest input index that belongs to some `k`-subset of the values whose
/// members pairwise differ by at most `dev`.
fn majority(values: &[i128], k: usize, dev: i128) -> Option<usize> {
    let n = values.len();
    let mut best: Option<usize> = None;
    for mask in 0u32..1 << n {
        if mask.count_ones() as usize != k {
            continue;
        }
        let members: Vec<usize> = (0..n).filter(|i| mask >> i & 1 == 1).collect();
        let close = members.iter().all(|&a| {
            members
                .iter()
                .all(|&b| (values[a] - values[b]).abs() <= dev)
        });
        if close {
            best = Some(best.map_or(members[0], |b| b.min(members[0])));
        }
    }
    best
}

macro_rules! compare_tests {
    ($modname:ident, $ty:ty, $t:ty) => {
        mod $modname {
            use super::*;

            type Fb = $ty;
            crate::common::analog_bounds!($t);

            fn new(arch: u16, dev: u32, tol: u32) -> Fb {
                let mut fb = Fb::default();
                fb.nArchitecture = arch;
                fb.wInputActive = active(arch);
                fb.nAllowedDeviation = dev;
                fb.tToleranceTime = tol;
                fb
            }

            fn running(arch: u16, dev: u32, tol: u32) -> Fb {
                let mut fb = new(arch, dev, tol);
                assert_eq!(fb.init(), SL_OK);
                fb.bRun = 1;
                fb
            }

            /// (IsValid, CompOut, nState) after a call with these inputs at `now`.
            fn call(fb: &mut Fb, now: u32, v: [i128; 5]) -> (u8, i128, u8) {
                (
                    fb.nCompIn1,
                    fb.nCompIn2,
                    fb.nCompIn3,
                    fb.nCompIn4,
                    fb.nCompIn5,
                ) = (t(v[0]), t(v[1]), t(v[2]), t(v[3]), t(v[4]));
                assert_eq!(fb.cycle(now), SL_OK);
                assert_eq!(fb.bError, 0);
                (fb.bIsValid, fb.nCompOut.wide(), fb.nState)
            }

            /// §4.20.1 1oo2 "The two input values are compared for equality" within the
            /// Allowed Deviation (inclusive); RUN: IsValid=1 CompOut=CompInX. The first call
            /// already decides (semantics CP2).
            #[test]
            fn one_out_of_two() {
                let mut fb = running(SL_ARCH_1OO2, 5, 100);
                assert_eq!(call(&mut fb, 0, [20, 25, 0, 0, 0]), (1, 20, SL_STATE_RUN));
                assert_eq!(
                    call(&mut fb, 1, [26, 21, 0, 0, 0]),
                    (1, 26, SL_STATE_RUN),
                    "CompIn1 is X"
                );
                assert_eq!(
                    call(&mut fb, 2, [20, 26, 0, 0, 0]),
                    (1, 26, SL_STATE_DELAYOUT),
                    "6 > 5"
                );
                assert_eq!(fb.state_name(), "DELAYOUT");
            }

            /// §4.20.1 2oo3 "the majority result is used (2 out of 3)"; X is the smallest input
            /// that does not deviate (§4.20.2 RUN).
            #[test]
            fn two_out_of_three() {
                let mut fb = running(SL_ARCH_2OO3, 3, 0);
                assert_eq!(
                    call(&mut fb, 0, [100, 500, 102, 9, 9]),
                    (1, 100, SL_STATE_RUN)
                );
                assert_eq!(
                    call(&mut fb, 1, [500, 100, 102, 9, 9]),
                    (1, 100, SL_STATE_RUN),
                    "X = 2"
                );
                assert_eq!(
                    call(&mut fb, 2, [500, 200, 202, 9, 9]),
                    (1, 200, SL_STATE_RUN)
                );
                // "If all values outside the defined limits are different, … CompOut … 0 and
                // the IsValid output is reset" (Tolerance 0: at once).
                assert_eq!(
                    call(&mut fb, 3, [100, 200, 300, 100, 100]),
                    (0, 0, SL_STATE_SAFE)
                );
            }

            /// §4.20.1 3oo5 "If fewer than 3 values within the defined limits are equal, …
            /// CompOut … 0 and the output IsValid is reset".
            #[test]
            fn three_out_of_five() {
                let mut fb = running(SL_ARCH_3OO5, 2, 0);
                assert_eq!(
                    call(&mut fb, 0, [50, 10, 11, 90, 12]),
                    (1, 10, SL_STATE_RUN),
                    "2, 3, 5"
                );
                assert_eq!(
                    call(&mut fb, 1, [50, 10, 11, 90, 13]),
                    (0, 0, SL_STATE_SAFE),
                    "10..13 > 2"
                );
                assert_eq!(
                    call(&mut fb, 2, [12, 10, 11, 90, 13]),
                    (1, 12, SL_STATE_RUN),
                    "1, 2, 3 (or 1, 3, 5)"
                );
            }

            /// §4.20.2 DELAYOUT: "the DelayOutTimer is started with the ToleranceTime. As long
            /// as [it] has not expired …: IsValid=1 CompOut=unchanged"; SAFE once it has; RUN
            /// again as soon as the values agree (no acknowledgement).
            #[test]
            fn tolerance_time() {
                let mut fb = running(SL_ARCH_1OO2, 0, 50);
                assert_eq!(call(&mut fb, 1000, [7, 7, 0, 0, 0]), (1, 7, SL_STATE_RUN));
                assert_eq!(
                    call(&mut fb, 1010, [8, 9, 0, 0, 0]),
                    (1, 7, SL_STATE_DELAYOUT)
                );
                assert_eq!(
                    call(&mut fb, 1059, [8, 9, 0, 0, 0]),
                    (1, 7, SL_STATE_DELAYOUT),
                    "49 ms"
                );
                assert_eq!(
                    call(&mut fb, 1060, [8, 9, 0, 0, 0]),
                    (0, 0, SL_STATE_SAFE),
                    "50 ms"
                );
                assert_eq!(
                    call(&mut fb, 1061, [9, 9, 0, 0, 0]),
                    (1, 9, SL_STATE_RUN),
                    "automatic"
                );
                // Agreement within the tolerance returns to RUN; the timer restarts later.
                assert_eq!(
                    call(&mut fb, 1070, [1, 9, 0, 0, 0]),
                    (1, 9, SL_STATE_DELAYOUT)
                );
                assert_eq!(call(&mut fb, 1110, [3, 3, 0, 0, 0]), (1, 3, SL_STATE_RUN));
                assert_eq!(
                    call(&mut fb, 1120, [1, 9, 0, 0, 0]),
                    (1, 3, SL_STATE_DELAYOUT)
                );
                assert_eq!(call(&mut fb, 1169, [1, 9, 0, 0, 0]).2, SL_STATE_DELAYOUT);
                // Tolerance 0: SAFE at once.
                let mut fb = running(SL_ARCH_1OO2, 0, 0);
                call(&mut fb, 0, [7, 7, 0, 0, 0]);
                assert_eq!(call(&mut fb, 1, [7, 8, 0, 0, 0]), (0, 0, SL_STATE_SAFE));
            }

            /// §4.20.2 STOP: "Error=0 IsValid=0 CompOut=0".
            #[test]
            fn stop() {
                let mut fb = running(SL_ARCH_2OO3, 0, 10);
                call(&mut fb, 0, [4, 4, 4, 0, 0]);
                fb.bRun = 0;
                assert_eq!(call(&mut fb, 1, [4, 4, 4, 0, 0]), (0, 0, SL_STATE_STOP));
            }

            /// Differences are exact: MIN and MAX of the type differ by at most 2^32 − 1, the
            /// largest deviation; one less and they deviate.
            #[test]
            fn exact_differences_at_the_extremes() {
                let span = HI - LO;
                let mut fb = running(SL_ARCH_1OO2, span as u32, 0);
                assert_eq!(call(&mut fb, 0, [LO, HI, 0, 0, 0]), (1, LO, SL_STATE_RUN));
                let mut fb = running(SL_ARCH_1OO2, (span - 1) as u32, 0);
                assert_eq!(call(&mut fb, 0, [HI, LO, 0, 0, 0]), (0, 0, SL_STATE_SAFE));
            }

            /// ABI-2 §11.3: architecture 2, 3 or 5 with exactly its active bits; Tolerance
            /// Time at most 65,535 ms (ABI-2 §12.9).
            #[test]
            fn configuration() {
                for (arch, act, tol) in [
                    (1, active(1), 0),
                    (4, active(4), 0),
                    (0, 0, 0),
                    (2, active(3), 0),
                    (3, active(2), 0),
                    (5, active(5) | 1, 0),
                    (2, active(2), 65_536),
                ] {
                    let mut fb = new(arch, 0, tol);
                    fb.wInputActive = act;
                    assert_eq!(fb.init(), SL_E_CONFIG, "{arch} {act:#x} {tol}");
                    fb.bRun = 1;
                    assert_eq!(fb.cycle(0), SL_E_CONFIG);
                    assert_eq!((fb.bIsValid, fb.nState), (0, SL_STATE_STOP));
                }
                let mut fb = new(5, u32::MAX, 65_535);
                assert_eq!(fb.init(), SL_OK);
            }

            /// ≥ 10,000 random sequences against the model (brute-force majority, the state
            /// machine of §4.20.2, the DelayOutTimer over random time steps).
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0xC0_4DA8E ^ (HI as u64));
                let mut reached = 0u32;
                const SEQUENCES: u32 = 12_000;
                for _ in 0..SEQUENCES {
                    let arch =
                        [SL_ARCH_1OO2, SL_ARCH_2OO3, SL_ARCH_3OO5][(rng.next() % 3) as usize];
                    let n = usize::from(arch);
                    let k = if n == 5 { 3 } else { 2 };
                    let dev = [0u32, 1, 5, 100, u32::MAX][(rng.next() % 5) as usize];
                    let tol = (rng.next() % 60) as u32;
                    let mut fb = running(arch, dev, tol);
                    let centre = [LO, HI, 0.max(LO), (LO + HI) / 2][(rng.next() % 4) as usize];
                    let (mut state, mut out, mut phase) = (SL_STATE_STOP, 0i128, 0u32);
                    let mut now = (rng.next() % 1000) as u32;
                    for _ in 0..20 {
                        let spread = [0i128, 3, 10, 1000][(rng.next() % 4) as usize];
                        let v: [i128; 5] = core::array::from_fn(|_| {
                            (centre + (rng.next() % (2 * spread as u64 + 1)) as i128 - spread)
                                .clamp(LO, HI)
                        });
                        let run = rng.next() % 16 != 0;
                        now = now.wrapping_add((rng.next() % 20) as u32);
                        fb.bRun = u8::from(run);
                        let got = call(&mut fb, now, v);
                        // The model.
                        if !run {
                            state = SL_STATE_STOP;
                        } else {
                            if state == SL_STATE_STOP {
                                state = SL_STATE_SAFE;
                            }
                            match majority(&v[..n], k, i128::from(dev)) {
                                Some(x) => {
                                    state = SL_STATE_RUN;
                                    out = v[x];
                                }
                                None => {
                                    if state == SL_STATE_RUN {
                                        state = SL_STATE_DELAYOUT;
                                        phase = now;
                                    }
                                    if state == SL_STATE_DELAYOUT && now.wrapping_sub(phase) >= tol
                                    {
                                        state = SL_STATE_SAFE;
                                    }
                                }
                            }
                        }
                        let valid = state == SL_STATE_RUN || state == SL_STATE_DELAYOUT;
                        assert_eq!(
                            got,
                            (u8::from(valid), if valid { out } else { 0 }, state),
                            "v {v:?} arch {arch} dev {dev} tol {tol}"
                        );
                        reached |= 1 << state;
                    }
                }
                crate::common::assert_reached(
                    reached.into(),
                    [
                        SL_STATE_RUN,
                        SL_STATE_STOP,
                        SL_STATE_SAFE,
                        SL_STATE_DELAYOUT,
                    ],
                );
            }
        }
    };
}

compare_tests!(int, FB_COMPARE_INT, i16);
compare_tests!(uint, FB_COMPARE_UINT, u16);
compare_tests!(dint, FB_COMPARE_DINT, i32);
compare_tests!(udint, FB_COMPARE_UDINT, u32);
