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
            common::c_add_link(&mut g, members.as_mut_ptr(), links.as_mut_ptr(), (0, src), (1, dst));
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
