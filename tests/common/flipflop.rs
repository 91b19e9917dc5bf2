//! Tests shared by FB RS and FB SR (manual §4.10, §4.11): everything that does not depend on
//! which input dominates. `tests/rs.rs` and `tests/sr.rs` each instantiate them once.

/// The tests of the common RS/SR behaviour for one block type: `$new(active, negated)`
/// builds an initialised instance, `$set` is the block's SET state.
#[macro_export]
macro_rules! flipflop_shared_tests {
    ($fb:ident, $out:ident, $ty:ident, $set:ident, $init:ident, $cycle:ident, $new:ident) => {
        #[test]
        fn layout_is_the_abi() {
            // ABI §9: bReset (8), bSet (9), $out (+1).
            assert_eq!(offset_of!($fb, bReset), 8);
            assert_eq!(offset_of!($fb, bSet), 9);
            assert_eq!(offset_of!($fb, bRun), 16);
            assert_eq!(offset_of!($fb, bErrAck), 17);
            let base = offset_of!($fb, $out) - 1;
            assert_eq!(base % 8, 0);
            assert!(base >= offset_of!($fb, wInputNegated) + 2);
            assert_eq!(offset_of!($fb, stPrivate) % 8, 0);
            assert_eq!(size_of::<$fb>() % 8, 0);
            assert_eq!($set, 9);
        }

        /// R2: an inactive input reads FALSE (no command); its negation bit is ignored.
        #[test]
        fn inactive_inputs() {
            let mut b = $new(SET, RESET);
            b.bRun = 1;
            let mut t = 0;
            step(&mut b, &mut t, 1, 1);
            assert_eq!(b.$out, 1, "inactive Reset ignored");
            step(&mut b, &mut t, 1, 0);
            assert_eq!(b.$out, 1, "set stays set without an active Reset");
            step(&mut b, &mut t, 0xEE, 0);
            assert_eq!(
                (b.$out, b.cycle(t + 1)),
                (1, SL_OK),
                "inactive byte unread"
            );
            let mut b = $new(RESET, SET);
            b.bRun = 1;
            step(&mut b, &mut t, 0, 1);
            assert_eq!(b.$out, 0, "inactive Set never sets");
            step(&mut b, &mut t, 0, 0);
            assert_eq!(b.$out, 0);
        }

        /// R1, C6.
        #[test]
        fn configuration_errors() {
            for (active, negated) in [
                (0u16, 0u16),
                (0b100, 0),
                (0b111, 0),
                (0b11, 0b100),
                (0, 0b11),
            ] {
                let mut b = $fb {
                    wInputActive: active,
                    wInputNegated: negated,
                    bRun: 1,
                    bSet: 1,
                    ..Default::default()
                };
                assert_eq!(b.init(), SL_E_CONFIG, "{active:#b} {negated:#b}");
                assert_eq!(b.cycle(0), SL_E_CONFIG);
                assert_eq!((b.nState, b.$out), (SL_STATE_STOP, 0));
            }
            for active in [RESET, SET, RESET | SET] {
                assert_eq!($new(active, 0).nState, SL_STATE_STOP);
            }
        }

        /// C5, ABI §5 (no bError: ERROR is nState 4 with the output FALSE) and R4: the memory is
        /// lost through ERROR and RESET.
        #[test]
        fn parameter_change_while_running() {
            let (mut b, mut t) = running();
            step(&mut b, &mut t, 0, 1);
            assert_eq!(b.$out, 1);
            b.wInputNegated = SET;
            assert_eq!(step(&mut b, &mut t, 0, 0), SL_E_PARAM_CHANGED);
            assert_eq!(
                (b.nState, b.$out, b.nDiag),
                (SL_STATE_ERROR, 0, SL_DIAG_PARAM_CHANGED)
            );
            b.bErrAck = 1;
            assert_eq!(step(&mut b, &mut t, 0, 0), SL_E_PARAM_CHANGED);
            assert_eq!(b.nState, SL_STATE_ERROR, "the change remains");
            b.wInputNegated = 0;
            b.bErrAck = 0;
            step(&mut b, &mut t, 0, 0);
            b.bErrAck = 1;
            step(&mut b, &mut t, 0, 0);
            assert_eq!((b.nState, b.$out, b.nDiag), (SL_STATE_RESET, 0, 0));
            b.bErrAck = 0;
            step(&mut b, &mut t, 0, 0);
            assert_eq!((b.nState, b.$out), (SL_STATE_SAFE, 0), "not SET again");
        }

        #[test]
        fn clock_backwards() {
            let (mut b, mut t) = running();
            step(&mut b, &mut t, 0, 1);
            b.bSet = 0;
            assert_eq!(b.cycle(t - 1), SL_E_CLOCK);
            assert_eq!(
                (b.nState, b.$out, b.nDiag),
                (SL_STATE_ERROR, 0, SL_DIAG_CLOCK)
            );
            b.bErrAck = 1;
            b.cycle(t);
            assert_eq!(b.nState, SL_STATE_RESET);
            b.bErrAck = 0;
            b.bSet = 1;
            b.cycle(t + 1);
            assert_eq!(
                (b.nState, b.$out),
                ($set, 1),
                "RESET → start, set by its inputs"
            );
        }

        /// R7, C3: a state value the block never takes, and a corrupted parameter CRC before the
        /// output switches on.
        #[test]
        fn corruption() {
            let (mut b, mut t) = running();
            let h = &mut b.stPrivate.stHeader;
            h.nState = SL_STATE_RUN;
            h.dwCtrlCheck =
                !(u32::from(h.nState) | (u32::from(h.nFlags) << 8) | (u32::from(h.wDiag) << 16));
            assert_eq!(step(&mut b, &mut t, 0, 0), SL_E_CORRUPT);
            assert_eq!((b.nState, b.$out), (SL_STATE_ERROR, 0));
            assert_eq!(b.nDiag & SL_DIAG_CORRUPT, SL_DIAG_CORRUPT);

            let (mut b, mut t) = running();
            b.stPrivate.stHeader.wParamCrc ^= 0x5A5A;
            assert_eq!(step(&mut b, &mut t, 0, 0), SL_OK, "nothing switches on yet");
            assert_eq!(step(&mut b, &mut t, 0, 1), SL_E_CORRUPT);
            assert_eq!((b.nState, b.$out), (SL_STATE_ERROR, 0));

            let (mut b, mut t) = running();
            b.stPrivate.stHeader.dwCtrlCheck ^= 1;
            assert_eq!(step(&mut b, &mut t, 0, 1), SL_E_CORRUPT);
            assert_eq!((b.nState, b.$out), (SL_STATE_ERROR, 0));
        }

        #[test]
        fn c_functions_names_and_group() {
            assert_eq!(unsafe { ffi::$init(std::ptr::null_mut()) }, SL_E_NULL);
            assert_eq!(unsafe { ffi::$cycle(std::ptr::null_mut(), 0) }, SL_E_NULL);
            let mut b = $fb {
                wInputActive: 0b11,
                ..Default::default()
            };
            assert_eq!(unsafe { ffi::$init(&mut b) }, SL_OK);
            assert_eq!(state_name($ty, SL_STATE_STOP), "STOP");
            assert_eq!(state_name($ty, SL_STATE_SAFE), "SAFE");
            assert_eq!(state_name($ty, $set), "SET");
            assert_eq!(state_name($ty, SL_STATE_ERROR), "ERROR");
            assert_eq!(state_name($ty, SL_STATE_RESET), "RESET");
            assert_eq!(state_name($ty, SL_STATE_RUN), "?");

            // An AND feeds Set: the block as a group member through the C API.
            let mut a = common::ready(FB_AND { wInputActive: 0b11, ..Default::default() });
            let mut g = SL_GROUP::default();
            let mut members = [SL_MEMBER::default(); 2];
            let mut links = [SL_LINK::default(); 1];
            common::c_group_init(&mut g, (members.as_mut_ptr(), 2), (links.as_mut_ptr(), 1));
            let null = std::ptr::null_mut();
            let and = std::ptr::addr_of_mut!(a).cast();
            common::c_add_member(&mut g, members.as_mut_ptr(), SL_TYPE_AND, and, null);
            let fb = std::ptr::addr_of_mut!(b).cast();
            common::c_add_member(&mut g, members.as_mut_ptr(), $ty, fb, null);
            let (src, dst) = (offset_of!(FB_AND, bAndOut), offset_of!($fb, bSet));
            common::c_add_link(&mut g, &mut members, &mut links, (0, src), (1, dst));
            g.bRun = 1;
            c_group_cycle!(g, members, links, 0; a, b);
            assert_eq!((b.nState, b.$out), (SL_STATE_SAFE, 0));
            a.bAndIn1 = 1;
            a.bAndIn2 = 1;
            c_group_cycle!(g, members, links, 1; a, b);
            assert_eq!(
                (b.nState, b.$out),
                ($set, 1),
                "the link carries this cycle's value"
            );
            a.bAndIn1 = 0;
            c_group_cycle!(g, members, links, 2; a, b);
            assert_eq!(b.$out, 1, "memory");
            b.bReset = 1;
            c_group_cycle!(g, members, links, 3; a, b);
            assert_eq!(b.$out, 0);
            let mb: &mut dyn Member = &mut b;
            assert!(mb.input_mut(offset_of!($fb, bReset) as u16).is_some());
            assert!(mb.output(offset_of!($fb, $out) as u16).is_some());
        }
    };
}

/// The fixtures of one flip-flop type: `$new(active, negated)` (initialised), `running()`
/// (both inputs active, running in SAFE, with the next time), `step` (Reset and Set written,
/// the call 10 ms later) and `io` (the [`Io`] of a step table).
#[macro_export]
macro_rules! flipflop_fixtures {
    ($fb:ident, $out:ident, $new:ident) => {
        fn $new(active: u16, negated: u16) -> $fb {
            common::ready($fb {
                wInputActive: active,
                wInputNegated: negated,
                ..Default::default()
            })
        }

        /// A running block with both inputs active (break contacts).
        fn running() -> ($fb, u32) {
            let mut b = $new(RESET | SET, 0);
            b.bRun = 1;
            assert_eq!(b.cycle(0), SL_OK);
            assert_eq!(b.nState, SL_STATE_SAFE);
            (b, 1)
        }

        fn step(b: &mut $fb, t: &mut u32, reset: u8, set: u8) -> i32 {
            b.bReset = reset;
            b.bSet = set;
            *t += 10;
            b.cycle(*t)
        }

        /// One call of a step table: (Run, Reset, Set) written, the call at `t`, its status
        /// with (state, output).
        fn io(b: &mut $fb, [run, reset, set]: [u8; 3], t: u32) -> (i32, u8, u8) {
            (b.bRun, b.bReset, b.bSet) = (run, reset, set);
            let rc = b.cycle(t);
            (rc, b.nState, b.$out)
        }

        /// From [`running`]: the rows both flip-flops share, then the block's own.
        #[track_caller]
        fn walk_running(shared: &[flipflop::Step], own: &[flipflop::Step]) -> $fb {
            let (mut b, mut t) = running();
            flipflop::walk(&mut b, &mut t, io, shared);
            flipflop::walk(&mut b, &mut t, io, own);
            b
        }
    };
}

/// The reference-model property of one flip-flop type (manual §4.10.1 / §4.11.1, R2–R5):
/// the output is TRUE only in SET; in the running states it follows the inputs in the same
/// call, and with both inputs logically TRUE the block is SET exactly when `$both` (RS:
/// Reset dominant, false; SR: Set dominant, true).
#[macro_export]
macro_rules! flipflop_model {
    ($out:ident, $set:ident, $new:ident, $both:expr) => {
        common::property! {
            cases: common::depth_cases(10_000), reach: [$set, SL_STATE_SAFE, SL_STATE_STOP];
            /// The block against the reference model, any activation and negation.
            fn follows_the_manual_model(
                active in 1u16..=3,
                negated in 0u16..=3,
                steps in proptest::collection::vec((0u8..4, 0u8..3, 0u8..3, 0u8..3, 0u32..20, 0u8..30), 1..80)
            ) {
                let mut b = $new(active, negated);
                let mut t = 0u32;
                let mut model_set = false;
                for (run, ack, reset, set, dt, mode) in steps {
                    b.bRun = u8::from(run != 0);
                    b.bErrAck = u8::from(ack == 1);
                    b.bReset = reset;
                    b.bSet = set;
                    t = if mode == 0 { t.wrapping_sub(1) } else { t.wrapping_add(dt) };
                    let before = b.nState;
                    b.cycle(t);
                    common::saw(b.nState);
                    prop_assert!([SL_STATE_STOP, SL_STATE_SAFE, $set, SL_STATE_ERROR, SL_STATE_RESET].contains(&b.nState));
                    prop_assert_eq!(b.$out, u8::from(b.nState == $set));
                    if matches!(b.nState, SL_STATE_SAFE | $set) {
                        // Logical values: inactive → FALSE; invalid Reset → TRUE; invalid Set → FALSE.
                        let logical = |raw: u8, bit: u16, invalid_reads: bool| {
                            if active & bit == 0 { false }
                            else if raw > 1 { invalid_reads }
                            else { (raw == 1) != (negated & bit != 0) }
                        };
                        let r = logical(reset, RESET, true);
                        let s = logical(set, SET, false);
                        let was_set = before == $set && model_set;
                        model_set = match (r, s) {
                            (true, true) => $both,
                            (true, false) => false,
                            (false, true) => true,
                            (false, false) => was_set,
                        };
                        prop_assert_eq!(b.nState == $set, model_set);
                    } else {
                        model_set = false;
                    }
                }
            }
        }
    };
}

/// The manual statements RS and SR share (§4.10.1 / §4.11.1), from SAFE; `set` is the
/// block's SET state.
#[rustfmt::skip]
pub fn set_and_reset_rows(set: u8) -> [Step; 4] {
    use safelogic::*;
    [
        // "Logic 1 at input Set and logic 0 at input Reset leads to logic 1 at the output."
        (1, 0, 1, SL_OK, Some(set), Some(1), "Set alone"),
        // "If both inputs are logic 0, the output remains in its current state." (1)
        (1, 0, 0, SL_OK, Some(set), Some(1), "remains 1"),
        // "Logic 0 at input Set and logic 1 at input Reset leads to logic 0 at the output."
        (1, 1, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), "Reset alone"),
        // ... remains (0).
        (1, 0, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), "remains 0"),
    ]
}

/// STOP and start-up as RS and SR share them (R4), from SAFE: the memory does not survive
/// STOP, the output starts FALSE, and Set held through a start-up sets in the call Run rises.
#[rustfmt::skip]
pub fn stop_and_start_rows(set: u8) -> [Step; 5] {
    use safelogic::*;
    [
        (1, 0, 1, SL_OK, None, Some(1), ""),
        (0, 0, 0, SL_OK, Some(SL_STATE_STOP), Some(0), ""),
        (1, 0, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), "starts FALSE"),
        (0, 0, 1, SL_OK, None, Some(0), ""),
        (1, 0, 1, SL_OK, Some(set), Some(1), "Set held through start-up"),
    ]
}

/// Both inputs negated (make contacts), running from SAFE: raw Reset 1 = logical 0, raw Set
/// 0 = logical 1, so the block sets; then remains; then resets.
#[rustfmt::skip]
pub const BOTH_NEGATED_ROWS: [Step; 3] = [
    (1, 1, 0, safelogic::SL_OK, None, Some(1), "logical Set 1"),
    (1, 1, 1, safelogic::SL_OK, None, Some(1), "both logical 0: remains"),
    (1, 0, 1, safelogic::SL_OK, None, Some(0), "logical Reset 1"),
];

/// A row of a flip-flop step table: the Run, Reset and Set bytes, the status, the state and
/// the output (`None`: not checked in this row), and what the row shows.
pub type Step = (u8, u8, u8, i32, Option<u8>, Option<u8>, &'static str);

/// One call of a step table: (Run, Reset, Set) written, the call at a time, and its status
/// with (state, output).
pub type Io<B> = fn(&mut B, [u8; 3], u32) -> (i32, u8, u8);

/// Runs a flip-flop step table, each call 10 ms after the last: `io` writes (Run, Reset,
/// Set) into the block and returns its (state, output) after the call at `t`. A failure
/// names the row and its note.
#[track_caller]
pub fn walk<B>(b: &mut B, t: &mut u32, io: Io<B>, rows: &[Step]) {
    for (k, &(run, reset, set, rc, state, out, note)) in rows.iter().enumerate() {
        *t += 10;
        let (got, s, o) = io(b, [run, reset, set], *t);
        assert_eq!(got, rc, "row {k} (t {t}): status; {note}");
        if let Some(state) = state {
            assert_eq!(s, state, "row {k} (t {t}): state; {note}");
        }
        if let Some(out) = out {
            assert_eq!(o, out, "row {k} (t {t}): output; {note}");
        }
    }
}
