//! Property tests: random valid parameter sets and random input sequences for FB_ESTOP and
//! FB_MON, checked against the manual's state tables (§4.4.2, §4.5.2), ABI.md §2/§5/§7 and
//! docs/semantics.md.
//!
//! Every input byte is random (0/1, and with low probability an invalid 2..=255), including
//! Run, ErrAck, Restart and the EDM inputs; time steps are random (0 included) and start
//! anywhere on the 32-bit clock (so many runs cross the wrap).

mod common;
use common::*;
use proptest::prelude::*;
use safelogic::*;

const CASES: u32 = 400;
const MAX_STEPS: usize = 400;

// ---------------------------------------------------------------------------------------
// Inputs
// ---------------------------------------------------------------------------------------

/// Field indices of one block's inputs: 0 Restart, 1 EDM1, 2 EDM2, 3.. the safety inputs
/// (ESTOP: EStopIn1-8, MON: MonIn1-4, Secure1-2), then Run, ErrAck.
#[derive(Clone, Copy, Debug)]
struct Layout {
    n_in: usize,
}

impl Layout {
    fn run(self) -> usize {
        3 + self.n_in
    }
    fn errack(self) -> usize {
        4 + self.n_in
    }
}

const ESTOP_LAYOUT: Layout = Layout { n_in: 8 };
const MON_LAYOUT: Layout = Layout { n_in: 6 };

/// A BOOL byte: mostly 0/1, sometimes an invalid value (ABI §2).
fn bool_byte() -> impl Strategy<Value = u8> {
    prop_oneof![40 => 0u8..=1, 1 => 2u8..=255]
}

/// A safety input change, given as its *logical* value (0/1, converted to the raw byte with
/// the input's negation bit when applied) and biased towards "no request" so that RUN is
/// reached often; invalid bytes stay raw.
fn input_byte() -> impl Strategy<Value = u8> {
    prop_oneof![30 => Just(1u8), 8 => Just(0u8), 1 => 2u8..=255]
}

/// Run: mostly TRUE.
fn run_byte() -> impl Strategy<Value = u8> {
    prop_oneof![8 => Just(1u8), 3 => Just(0u8), 1 => 2u8..=255]
}

/// EDM feedback: mostly TRUE (contactor released), so restarts succeed often.
fn edm_byte() -> impl Strategy<Value = u8> {
    prop_oneof![24 => Just(1u8), 10 => Just(0u8), 1 => 2u8..=255]
}

/// One change of the inputs: a list of (field, byte). Run changes rarely, safety inputs
/// often — singly, or both channels of a pair together (so pairs also agree).
fn change(l: Layout) -> impl Strategy<Value = Vec<(usize, u8)>> {
    let n = l.n_in;
    prop_oneof![
        8 => (Just(0usize), bool_byte()).prop_map(|c| vec![c]),
        5 => (1usize..=2, edm_byte()).prop_map(|c| vec![c]),
        14 => (3usize..3 + n, input_byte()).prop_map(|c| vec![c]),
        10 => (0..n / 2, input_byte()).prop_map(|(k, v)| vec![(3 + 2 * k, v), (4 + 2 * k, v)]),
        1 => (Just(l.run()), run_byte()).prop_map(|c| vec![c]),
        5 => (Just(l.errack()), bool_byte()).prop_map(|c| vec![c]),
    ]
}

fn time_step() -> impl Strategy<Value = u32> {
    prop_oneof![
        4 => Just(0u32),
        20 => 1u32..=20,
        6 => 21u32..=300,
        1 => 301u32..=5000,
    ]
}

#[derive(Clone, Debug)]
struct Step {
    changes: Vec<(usize, u8)>,
    dt: u32,
}

fn steps(l: Layout) -> impl Strategy<Value = Vec<Step>> {
    let step =
        (prop::collection::vec(change(l), 0..=2), time_step()).prop_map(|(changes, dt)| Step {
            changes: changes.into_iter().flatten().collect(),
            dt,
        });
    prop::collection::vec(step, 1..=MAX_STEPS)
}

// ---------------------------------------------------------------------------------------
// Parameters (always valid: C6, C10)
// ---------------------------------------------------------------------------------------

fn opt_time(max: u32) -> impl Strategy<Value = u32> {
    prop_oneof![2 => Just(0u32), 3 => 1u32..=max]
}

fn estop_params() -> impl Strategy<Value = FB_ESTOP> {
    (
        1u16..=0xFF,
        0u16..=0xFF,
        prop::array::uniform4(opt_time(300)),
        (any::<bool>(), any::<bool>(), any::<bool>(), any::<bool>()),
        (opt_time(300), opt_time(300), opt_time(300)),
    )
        .prop_map(
            |(active, negated, disc, (e1, e2, si, man), (r1, r2, delay))| {
                let mut fb = FB_ESTOP {
                    wInputActive: active,
                    wInputNegated: negated,
                    ..Default::default()
                };
                let disc: Vec<u32> = (0..4)
                    .map(|k| {
                        let both = 0b11 << (2 * k);
                        if active & both == both {
                            disc[k]
                        } else {
                            0
                        }
                    })
                    .collect();
                fb.tDiscTime12 = disc[0];
                fb.tDiscTime34 = disc[1];
                fb.tDiscTime56 = disc[2];
                fb.tDiscTime78 = disc[3];
                fb.dwOptions = (if e1 { SL_OPT_EDM1 } else { 0 })
                    | (if e2 { SL_OPT_EDM2 } else { 0 })
                    | (if si { SL_OPT_SAFE_INPUTS_AFTER_DISC } else { 0 })
                    | (if man { SL_OPT_MANUAL_RESTART } else { 0 });
                fb.tEDM1ResetTime = if e1 { r1 } else { 0 };
                fb.tEDM2ResetTime = if e2 { r2 } else { 0 };
                fb.tEStopDelOutDelay = delay;
                fb
            },
        )
}

fn mon_params() -> impl Strategy<Value = FB_MON> {
    (
        (1u16..=0xF, 0u16..=3),
        0u16..=0x3F,
        prop::array::uniform3(opt_time(300)),
        (
            any::<bool>(),
            any::<bool>(),
            any::<bool>(),
            any::<bool>(),
            any::<bool>(),
        ),
        (opt_time(300), opt_time(300), opt_time(300)),
    )
        .prop_map(
            |((mon_in, secure), negated, disc, (e1, e2, si, man, ft), (r1, r2, delay))| {
                let active = mon_in | (secure << 4);
                let mut fb = FB_MON {
                    wInputActive: active,
                    wInputNegated: negated,
                    ..Default::default()
                };
                let d = |k: usize| {
                    let both = 0b11 << (2 * k);
                    if active & both == both {
                        disc[k]
                    } else {
                        0
                    }
                };
                fb.tDiscTime12 = d(0);
                fb.tDiscTime34 = d(1);
                fb.tDiscTimeSecure12 = d(2);
                fb.dwOptions = (if e1 { SL_OPT_EDM1 } else { 0 })
                    | (if e2 { SL_OPT_EDM2 } else { 0 })
                    | (if si { SL_OPT_SAFE_INPUTS_AFTER_DISC } else { 0 })
                    | (if man { SL_OPT_MANUAL_RESTART } else { 0 })
                    | (if ft { SL_OPT_FUNCTION_TEST } else { 0 });
                fb.tEDM1ResetTime = if e1 { r1 } else { 0 };
                fb.tEDM2ResetTime = if e2 { r2 } else { 0 };
                fb.tMonDelOutDelay = delay;
                fb
            },
        )
}

// ---------------------------------------------------------------------------------------
// The model of what the manual / ABI say, per block
// ---------------------------------------------------------------------------------------

/// What the properties need to know about a block and its parameters.
trait Subject: Guard {
    const LAYOUT: Layout;
    fn states() -> &'static [u8];
    fn active(&self) -> u16;
    fn negated(&self) -> u16;
    fn options(&self) -> u32;
    fn delay(&self) -> u32;
    /// Pairs with a non-zero discrepancy time (bit k = diag bit k).
    fn monitored_pairs(&self) -> u16;
    fn manual_restart(&self) -> bool;
    /// The bytes of the current inputs in layout order.
    fn bytes(&self) -> Vec<u8>;
    fn set_byte(&mut self, i: usize, v: u8);
    /// Logical value of active safety input i (ABI §7 Signals; invalid byte = FALSE, C7).
    fn logical(&self, i: usize) -> bool {
        let b = self.get_in(i);
        b <= 1 && ((b == 1) != (self.negated() & (1 << i) != 0))
    }
    /// An input requesting the safe state that must switch the undelayed output off.
    fn switch_off_request(&self) -> bool;
}

fn set_common<B: Guard>(fb: &mut B, l: Layout, i: usize, v: u8) {
    match i {
        0 => fb.set_restart(v),
        1 => fb.set_edm(1, v),
        2 => fb.set_edm(2, v),
        _ if i == l.run() => fb.set_run(v),
        _ if i == l.errack() => fb.set_errack(v),
        _ => fb.set_in(i - 3, v),
    }
}

impl Subject for FB_ESTOP {
    const LAYOUT: Layout = ESTOP_LAYOUT;
    fn states() -> &'static [u8] {
        &ESTOP_STATES
    }
    fn active(&self) -> u16 {
        self.wInputActive
    }
    fn negated(&self) -> u16 {
        self.wInputNegated
    }
    fn options(&self) -> u32 {
        self.dwOptions
    }
    fn delay(&self) -> u32 {
        self.tEStopDelOutDelay
    }
    fn monitored_pairs(&self) -> u16 {
        [
            self.tDiscTime12,
            self.tDiscTime34,
            self.tDiscTime56,
            self.tDiscTime78,
        ]
        .iter()
        .enumerate()
        .fold(0, |m, (k, &t)| m | (u16::from(t != 0) << k))
    }
    fn manual_restart(&self) -> bool {
        true // §4.4.1: ESTOP always restarts via the Restart input
    }
    fn bytes(&self) -> Vec<u8> {
        let mut v = vec![self.bRestart, self.bEDM1, self.bEDM2];
        v.extend((0..8).map(|i| self.get_in(i)));
        v.extend([self.bRun, self.bErrAck]);
        v
    }
    fn set_byte(&mut self, i: usize, v: u8) {
        set_common(self, Self::LAYOUT, i, v);
    }
    /// §4.4.1 "The first output (EStopOut) goes immediately ... into the safe state once an
    /// input requests the safe state".
    fn switch_off_request(&self) -> bool {
        (0..8).any(|i| self.wInputActive & (1 << i) != 0 && !self.logical(i))
    }
}

impl Subject for FB_MON {
    const LAYOUT: Layout = MON_LAYOUT;
    fn states() -> &'static [u8] {
        &MON_STATES
    }
    fn active(&self) -> u16 {
        self.wInputActive
    }
    fn negated(&self) -> u16 {
        self.wInputNegated
    }
    fn options(&self) -> u32 {
        self.dwOptions
    }
    fn delay(&self) -> u32 {
        self.tMonDelOutDelay
    }
    fn monitored_pairs(&self) -> u16 {
        [self.tDiscTime12, self.tDiscTime34, self.tDiscTimeSecure12]
            .iter()
            .enumerate()
            .fold(0, |m, (k, &t)| m | (u16::from(t != 0) << k))
    }
    fn manual_restart(&self) -> bool {
        self.dwOptions & SL_OPT_MANUAL_RESTART != 0
    }
    fn bytes(&self) -> Vec<u8> {
        let mut v = vec![self.bRestart, self.bEDM1, self.bEDM2];
        v.extend((0..6).map(|i| self.get_in(i)));
        v.extend([self.bRun, self.bErrAck]);
        v
    }
    fn set_byte(&mut self, i: usize, v: u8) {
        set_common(self, Self::LAYOUT, i, v);
    }
    /// §4.5.1 "When an input requests the safe state, the MonOut output immediately switches
    /// to the safe state" — unless the Secure inputs bypass the MonIn inputs (G8/ABI §8: at
    /// least one Secure input active and every active Secure input logically TRUE).
    fn switch_off_request(&self) -> bool {
        let a = self.wInputActive;
        let mon_req = (0..4).any(|i| a & (1 << i) != 0 && !self.logical(i));
        let secure_active: Vec<usize> = (4..6).filter(|&i| a & (1 << i) != 0).collect();
        let bypass = !secure_active.is_empty() && secure_active.iter().all(|&i| self.logical(i));
        mon_req && !bypass
    }
}

/// Bytes the block reads (C7): active inputs, active EDMs, Restart where a manual restart
/// uses it, Run, ErrAck.
fn read_bytes_invalid<B: Subject>(fb: &B) -> bool {
    let l = B::LAYOUT;
    let b = fb.bytes();
    let inputs = (0..l.n_in).any(|i| fb.active() & (1 << i) != 0 && b[3 + i] > 1);
    let edm1 = fb.options() & SL_OPT_EDM1 != 0 && b[1] > 1;
    let edm2 = fb.options() & SL_OPT_EDM2 != 0 && b[2] > 1;
    let restart = fb.manual_restart() && b[0] > 1;
    inputs || edm1 || edm2 || restart || b[l.run()] > 1 || b[l.errack()] > 1
}

/// Diag bits the manual allows for this parameter set (§4.4.2 / §4.5.2 diag tables).
fn allowed_diag<B: Subject>(fb: &B) -> u16 {
    let pairs = fb.monitored_pairs();
    let mut d = pairs;
    if fb.options() & SL_OPT_SAFE_INPUTS_AFTER_DISC != 0 {
        d |= pairs << 8;
    }
    if fb.options() & SL_OPT_EDM1 != 0 {
        d |= SL_DIAG_EDM1;
    }
    if fb.options() & SL_OPT_EDM2 != 0 {
        d |= SL_DIAG_EDM2;
    }
    d
}

/// Converts a generated change to the raw byte: safety inputs are generated as logical
/// values (see [`input_byte`]).
fn to_raw<B: Subject>(fb: &B, i: usize, v: u8) -> u8 {
    let n = B::LAYOUT.n_in;
    if (3..3 + n).contains(&i) && v <= 1 {
        v ^ u8::from(fb.negated() & (1 << (i - 3)) != 0)
    } else {
        v
    }
}

/// Runs one random case and checks every property after every call.
fn check<B: Subject>(params: B, t0: u32, steps: &[Step]) -> Result<(), TestCaseError> {
    let l = B::LAYOUT;
    let mut fb = params;
    // start with nothing requesting: each active input at its non-requesting level
    for i in 0..l.n_in {
        let neg = fb.negated() & (1 << i) != 0;
        fb.set_byte(3 + i, u8::from(!neg));
    }
    fb.set_byte(1, 1);
    fb.set_byte(2, 1);
    fb.set_byte(l.run(), 1);
    prop_assert_eq!(fb.init(), SL_OK, "valid parameters rejected: {:?}", fb);
    prop_assert_eq!(fb.state(), SL_STATE_STOP);
    prop_assert_eq!(fb.outs(), [0, 0, 0]);

    let delay = fb.delay();
    let options = fb.options();
    let manual = fb.manual_restart();
    let allowed = allowed_diag(&fb);
    let safe_inputs = options & SL_OPT_SAFE_INPUTS_AFTER_DISC != 0;
    let mut t = t0;

    for (n, st) in steps.iter().enumerate() {
        let prev = fb.clone();
        let prev_bytes = fb.bytes();
        for &(i, v) in &st.changes {
            fb.set_byte(i, to_raw(&fb, i, v));
        }
        let bytes = fb.bytes();
        t = t.wrapping_add(st.dt);
        let rc = fb.cycle(t);
        let state = fb.state();
        common::saw(state);
        // ABI §3/§4: the cycle writes outputs, info data and private state only — the
        // inputs and parameters it was given are unchanged
        prop_assert_eq!(fb.bytes(), bytes.clone(), "cycle changed an input");
        prop_assert_eq!(
            (fb.active(), fb.negated(), fb.options(), fb.delay()),
            (prev.active(), prev.negated(), prev.options(), prev.delay())
        );
        let ctx = || format!("step {n} t={t} prev={prev:?} now={fb:?}");

        // every call returns a documented status code (ABI §5, C11) — here, with valid
        // parameters, an intact private state and a forward clock: SL_OK, or
        // SL_E_INVALID_BOOL exactly when a byte the block reads is invalid (ABI §2, C7)
        prop_assert!(DOCUMENTED_STATUS.contains(&rc), "status {} {}", rc, ctx());
        let want = if read_bytes_invalid(&fb) {
            SL_E_INVALID_BOOL
        } else {
            SL_OK
        };
        prop_assert_eq!(rc, want, "status {}", ctx());

        // nState is one of the block's states (§4.4.2 / §4.5.2), and only those the
        // configuration allows: START "only if manual restart is active", ERRORDELAY and
        // DELAYOUT "only if the Output Delay time ... is not equal to 0", FUNCTEST "only if
        // the manual function test is active"
        prop_assert!(B::states().contains(&state), "state {} {}", state, ctx());
        if state == SL_STATE_START {
            prop_assert!(manual, "START without manual restart {}", ctx());
        }
        if state == SL_STATE_DELAYOUT || state == SL_STATE_ERRORDELAY {
            prop_assert!(delay != 0, "state {} without delay {}", state, ctx());
        }
        if state == SL_STATE_FUNCTEST {
            prop_assert!(options & SL_OPT_FUNCTION_TEST != 0, "{}", ctx());
        }

        // outputs exactly as the state table lists them: FALSE in STOP, ERROR, RESET,
        // SAFE, START, FUNCTEST; bError TRUE exactly in ERROR (nState == 4)
        prop_assert_eq!(fb.outs(), table(state), "outputs {}", ctx());
        prop_assert_eq!(fb.outs()[0] == 1, state == SL_STATE_ERROR, "{}", ctx());

        // an active input requesting the safe state clears EStopOut / MonOut in the same
        // cycle (MON: unless the Secure inputs bypass)
        if fb.switch_off_request() {
            prop_assert_eq!(fb.outs()[1], 0, "Out with a request {}", ctx());
        }

        // manual restart: no output FALSE → TRUE without a Restart falling edge (byte 1 in
        // the previous call, byte 0 now) in this cycle (§4.4.1, §4.5.1, ABI §7, C7)
        if manual {
            let switched_on = prev
                .outs()
                .into_iter()
                .zip(fb.outs())
                .map(|(p, n)| p == 0 && n == 1);
            for (k, on) in switched_on.enumerate().skip(1) {
                if on {
                    prop_assert!(
                        prev_bytes[0] == 1 && bytes[0] == 0,
                        "output {} switched on without a Restart falling edge {}",
                        k,
                        ctx()
                    );
                }
            }
        }

        // diag (G15, §4.4.2/§4.5.2 diag tables): 0 outside ERROR/ERRORDELAY; in ERROR some
        // bit; only bits this configuration can produce; bit 8+k only with bit k and the
        // option
        let diag = fb.diag();
        if state == SL_STATE_ERROR || state == SL_STATE_ERRORDELAY {
            prop_assert!(diag != 0, "error without diag {}", ctx());
        } else {
            prop_assert_eq!(diag, 0, "diag outside ERROR {}", ctx());
        }
        prop_assert_eq!(
            diag & !allowed,
            0,
            "diag {:#06x} not allowed {}",
            diag,
            ctx()
        );
        if safe_inputs {
            prop_assert_eq!(diag & 0xF, (diag >> 8) & 0xF, "bits 8-11 {}", ctx());
        }
        if state == SL_STATE_ERRORDELAY {
            // G7: only a discrepancy error delays
            prop_assert_eq!(diag & (SL_DIAG_EDM1 | SL_DIAG_EDM2), 0, "{}", ctx());
        }

        // ABI §7 Run: bRun FALSE → STOP, except ERROR (stays until acknowledged: ERROR or,
        // on the acknowledgement, RESET — C9), RESET (left by the ErrAck falling edge) and
        // ERRORDELAY (→ ERROR, G7)
        let ps = prev.state();
        if bytes[l.run()] != 1 {
            match ps {
                SL_STATE_ERROR => prop_assert!(
                    state == SL_STATE_ERROR || state == SL_STATE_RESET,
                    "{}",
                    ctx()
                ),
                SL_STATE_ERRORDELAY => prop_assert_eq!(state, SL_STATE_ERROR, "{}", ctx()),
                SL_STATE_RESET => prop_assert!(
                    state == SL_STATE_RESET || state == SL_STATE_STOP,
                    "{}",
                    ctx()
                ),
                _ => prop_assert_eq!(state, SL_STATE_STOP, "{}", ctx()),
            }
        }
        // ABI §7 Errors: ERROR is left only through RESET, on an ErrAck rising edge
        if ps == SL_STATE_ERROR {
            prop_assert!(
                state == SL_STATE_ERROR || state == SL_STATE_RESET,
                "{}",
                ctx()
            );
            if state == SL_STATE_RESET {
                prop_assert!(
                    prev_bytes[l.errack()] != 1 && bytes[l.errack()] == 1,
                    "ERROR left without an ErrAck rising edge {}",
                    ctx()
                );
            }
        }
        if state == SL_STATE_RESET {
            prop_assert!(ps == SL_STATE_ERROR || ps == SL_STATE_RESET, "{}", ctx());
        }
        // RESET is left on the falling edge of ErrAck: to STOP with bRun FALSE, else the
        // start state (ABI §7, G9, G12)
        if ps == SL_STATE_RESET && state != SL_STATE_RESET {
            prop_assert!(
                prev_bytes[l.errack()] == 1 && bytes[l.errack()] == 0,
                "RESET left without an ErrAck falling edge {}",
                ctx()
            );
            let start = if options & SL_OPT_FUNCTION_TEST != 0 {
                SL_STATE_FUNCTEST
            } else {
                SL_STATE_SAFE
            };
            let want = if bytes[l.run()] == 1 {
                start
            } else {
                SL_STATE_STOP
            };
            prop_assert_eq!(state, want, "{}", ctx());
        }
        // STOP → run goes to the start state (G12)
        if ps == SL_STATE_STOP && state != SL_STATE_STOP {
            prop_assert_eq!(bytes[l.run()], 1, "{}", ctx());
            let start = if options & SL_OPT_FUNCTION_TEST != 0 {
                SL_STATE_FUNCTEST
            } else {
                SL_STATE_SAFE
            };
            prop_assert_eq!(state, start, "{}", ctx());
        }
    }
    Ok(())
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_SAFE, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET];
    /// All properties for FB_ESTOP over random valid parameters and input sequences.
    fn estop_random_sequences(
        params in estop_params(),
        t0 in prop_oneof![any::<u32>(), (u32::MAX - 3000)..=u32::MAX],
        steps in steps(ESTOP_LAYOUT),
    ) {
        check(params, t0, &steps)?;
    }
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_SAFE, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET];
    /// All properties for FB_MON over random valid parameters and input sequences.
    fn mon_random_sequences(
        params in mon_params(),
        t0 in prop_oneof![any::<u32>(), (u32::MAX - 3000)..=u32::MAX],
        steps in steps(MON_LAYOUT),
    ) {
        check(params, t0, &steps)?;
    }
}

common::property! {
    cases: CASES / 4, reach: [SL_STATE_ERROR];
    /// C4/ABI §5: any backwards step (wrapping difference ≥ 2^31) in any state is
    /// SL_E_CLOCK, ERROR, bError TRUE, diag bit 14.
    fn backwards_clock_is_always_a_clock_error(
        params in estop_params(),
        steps in steps(ESTOP_LAYOUT),
        back in 0x8000_0000u32..=u32::MAX,
    ) {
        let mut fb = params;
        for i in 0..8 {
            let neg = fb.wInputNegated & (1 << i) != 0;
            fb.set_byte(3 + i, u8::from(!neg));
        }
        fb.bRun = 1;
        prop_assert_eq!(fb.init(), SL_OK);
        let mut t = T0;
        for st in &steps {
            for &(i, v) in &st.changes {
                fb.set_byte(i, to_raw(&fb, i, v));
            }
            t = t.wrapping_add(st.dt);
            fb.cycle(t);
        }
        let rc = fb.cycle(t.wrapping_add(back));
        common::saw(fb.nState);
        prop_assert_eq!(rc, SL_E_CLOCK);
        prop_assert_eq!(fb.nState, SL_STATE_ERROR);
        prop_assert_eq!(fb.outs(), [1, 0, 0]);
        prop_assert!(fb.nDiag & SL_DIAG_CLOCK != 0);
    }
}

common::property! {
    cases: CASES / 4, reach: [SL_STATE_ERROR];
    /// ABI §4 "A call is total": whole instances of random bytes (parameters, inputs,
    /// private state) through the C functions return a documented status and leave a
    /// state of the block with the state table's outputs.
    fn random_instance_bytes_are_handled(
        estop_bytes in prop::collection::vec(any::<u8>(), std::mem::size_of::<FB_ESTOP>()),
        mon_bytes in prop::collection::vec(any::<u8>(), std::mem::size_of::<FB_MON>()),
        times in prop::collection::vec(any::<u32>(), 1..8),
    ) {
        let mut e = FB_ESTOP::default();
        let mut m = FB_MON::default();
        // SAFETY: both are repr(C) structs of plain integers (ABI §3: no pointers); any
        // byte pattern is a valid value. Sizes match by construction.
        unsafe {
            std::ptr::copy_nonoverlapping(
                estop_bytes.as_ptr(), (&mut e as *mut FB_ESTOP).cast::<u8>(), estop_bytes.len());
            std::ptr::copy_nonoverlapping(
                mon_bytes.as_ptr(), (&mut m as *mut FB_MON).cast::<u8>(), mon_bytes.len());
        }
        for &t in &times {
            let rc = unsafe { safelogic::ffi::sl_estop_cycle(&mut e, t) };
            common::saw(e.nState);
            prop_assert!(DOCUMENTED_STATUS.contains(&rc), "ESTOP status {}", rc);
            prop_assert!(ESTOP_STATES.contains(&e.nState), "ESTOP state {}", e.nState);
            prop_assert_eq!(e.outs(), table(e.nState));
            let rc = unsafe { safelogic::ffi::sl_mon_cycle(&mut m, t) };
            prop_assert!(DOCUMENTED_STATUS.contains(&rc), "MON status {}", rc);
            prop_assert!(MON_STATES.contains(&m.nState), "MON state {}", m.nState);
            prop_assert_eq!(m.outs(), table(m.nState));
        }
    }
}
