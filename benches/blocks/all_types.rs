//! Every registered type (the rows of `safelogic::for_each_block!`), each in a configuration
//! the library accepts and brought to its running state (`setup`: the parameters and steady
//! inputs per type or family, the same values as the hand-written rows of this bench; a
//! PLCopen block without an entry: every BOOL input TRUE, running at DiagCode 0x8000). The
//! bench asserts that `init` accepted the configuration, that every timed steady call
//! returned `SL_OK` and that the instance is in the named state before and after each
//! timing: a row that timed a refused configuration or an error state fails the bench.
//! Three timings of the C cycle function: steady (nothing written between calls), inputs
//! written first (the steady input values stored through the field table right before each
//! call, as a real caller does) and random (fresh input values right before each call: BOOL
//! 0/1, analog the steady value −2 … +2, so that the row mostly stays in range); the share
//! of random calls that return `SL_OK` and end in the running state is printed beside it.

use safelogic::any::FunctionBlock;
use safelogic::blocks::analog::{
    arith::*, compare::*, counter::*, envelope::*, loadsensing::*, scale::*, speed::*,
    violationcounter::*, window::*,
};
use safelogic::blocks::motion::{advposmon::*, cammonitor::*, sbt::*, slp::*};
use safelogic::ffi::*;
use safelogic::registry::{block_type, BlockType, Dir, Kind, Registered};
use safelogic::*;
use std::hint::black_box;
use std::time::Instant;

/// One row of the every-type table.
pub struct TypeRow {
    /// The registry name.
    pub name: &'static str,
    /// The exported cycle function (`sl_estop_cycle`), the callgrind key.
    pub cycle: &'static str,
    /// The state timed (a PLCopen block: its state and DiagCode).
    pub state: String,
    /// Median ns per call: steady, inputs written first, random inputs.
    pub ns: [f64; 3],
    /// Per cent of the random calls that returned `SL_OK` in the running state.
    pub random_running: f64,
}

/// How one type is configured and brought to its running state.
struct Setup {
    /// Written before `init`, besides `bRun`: parameters and the steady input values (the
    /// other inputs 0).
    set: &'static [(&'static str, i64)],
    /// Inputs written over the steady ones for one call each, before the steady calls (a
    /// Restart or Set pulse, buttons released first).
    pulses: &'static [&'static [(&'static str, i64)]],
    /// The state the timed calls must run in.
    state: &'static str,
}

const fn running(set: &'static [(&'static str, i64)]) -> Setup {
    Setup {
        set,
        pulses: &[],
        state: "RUN",
    }
}

/// A PLCopen block (`Activate` TRUE besides `set`, the TIME parameters 100 ms unless set), at
/// DiagCode 8000, as in the steady rows of `tools/plcopen_peer_bench.py`.
const fn plcopen(set: &'static [(&'static str, i64)]) -> Setup {
    Setup {
        set,
        pulses: &[],
        state: "ACTIVE 8000",
    }
}

/// The name without its width suffix (`LIMIT_UDINT` → `LIMIT`).
fn family(name: &str) -> &str {
    for w in ["_INT", "_UINT", "_DINT", "_UDINT"] {
        if let Some(f) = name.strip_suffix(w) {
            return f;
        }
    }
    name
}

/// The configuration of a type.
fn setup(name: &str) -> Setup {
    const A16: i64 = ARITH_ACTIVE as i64;
    match family(name) {
        "ESTOP" => Setup {
            set: &[
                ("wInputActive", 0b11),
                ("tDiscTime12", 20),
                ("bEStopIn1", 1),
                ("bEStopIn2", 1),
            ],
            pulses: &[&[], &[("bRestart", 1)]],
            state: "RUN",
        },
        "MON" => running(&[
            ("wInputActive", 0b11),
            ("tDiscTime12", 20),
            ("bMonIn1", 1),
            ("bMonIn2", 1),
        ]),
        "AND" => running(&[("wInputActive", 0b11), ("bAndIn1", 1), ("bAndIn2", 1)]),
        "OR" => running(&[("wInputActive", 0b11), ("bOrIn1", 1)]),
        "XOR" => running(&[("wInputActive", 0b11), ("bXor1In1", 1), ("bXor1In2", 1)]),
        "DECOUPLE" => running(&[("wInputActive", 0xFF), ("bDecIn1", 1), ("bDecIn5", 1)]),
        "OPMODE" => running(&[("wInputActive", 0b11), ("tDiscTime", 100), ("bOpIn1", 1)]),
        "TWOHAND" => Setup {
            set: &[
                ("wInputActive", 0b1111),
                ("tDiscTime12", 100),
                ("tDiscTime34", 100),
                ("bTwoHand1", 1),
                ("bTwoHand2", 1),
                ("bTwoHand3", 1),
                ("bTwoHand4", 1),
            ],
            pulses: &[&[
                ("bTwoHand1", 0),
                ("bTwoHand2", 0),
                ("bTwoHand3", 0),
                ("bTwoHand4", 0),
            ]],
            state: "RUN",
        },
        "MUTING" => running(&[
            ("wInputActive", 0b11_1111),
            ("tDiscTime12", 50),
            ("tDiscTime34", 50),
            ("tDiscTimeOSSD", 50),
            ("bMutingEnable", 1),
            ("bEDM1", 1),
            ("bEDM2", 1),
            ("bOSSDIn1", 1),
            ("bOSSDIn2", 1),
        ]),
        "EDM" => Setup {
            state: "MONON",
            ..running(&[
                ("wInputActive", 0b11),
                ("tSwitchOnTime", 100),
                ("tSwitchOffTime", 100),
                ("bMon1", 1),
            ])
        },
        "RS" | "SR" => Setup {
            set: &[("wInputActive", 0b11)],
            pulses: &[&[("bSet", 1)]],
            state: "SET",
        },
        "TON" => running(&[("wInputActive", 1), ("tDelay", 10), ("bTonIn1", 1)]),
        "TON2" => running(&[
            ("wInputActive", 1),
            ("tDelay", 10),
            ("bTonIn1", 1),
            ("bEnable", 1),
        ]),
        "TOF" => running(&[("wInputActive", 1), ("tDelay", 10), ("bTofIn1", 1)]),
        "ADD" | "SUB" | "MUL" | "DIV" => running(&[
            ("wInputActive", A16),
            ("nAnalogIn1", 1200),
            ("nAnalogIn2", 3),
        ]),
        "LIMIT" => running(&[
            ("wInputActive", 0x100),
            ("nMinimumValue", 0),
            ("nMaximumValue", 1000),
            ("nAnalogIn", 500),
            ("nMinValue", 10),
        ]),
        "COMPARE" => running(&[
            ("nArchitecture", SL_ARCH_3OO5 as i64),
            ("wInputActive", 0x1F00),
            ("nAllowedDeviation", 2),
            ("tToleranceTime", 100),
            ("nCompIn1", 50),
            ("nCompIn2", 10),
            ("nCompIn3", 11),
            ("nCompIn4", 90),
            ("nCompIn5", 12),
        ]),
        "SCALE" => running(&[
            ("wInputActive", SL_SCALE_ACTIVE_ANALOGIN as i64),
            ("nNumerator", 3),
            ("nDenominator", 4),
            ("nOffset", 5),
            ("nRounding", SL_ROUNDING_ROUND as i64),
            ("tWatchdog", 100),
            ("nAnalogIn", 1000),
        ]),
        "SPEED" => running(&[
            ("wInputActive", SL_SPEED_ACTIVE_POSITION as i64),
            ("tTimeInterval", 10),
            ("nPosition", 1000),
        ]),
        "COUNTER" => running(&[
            ("wInputActive", SL_COUNTER_ACTIVE_INPUTS as i64),
            ("nPresetValue", 5),
            ("nCounterLimit", 100),
        ]),
        "VIOLATIONCOUNTER" => running(&[
            ("wInputActive", SL_VIOLATIONCOUNTER_ACTIVE as i64),
            ("nIncrementError", 3),
            ("nDecrementNoError", 1),
            ("nCounterLimit", 10),
            ("bInput", 1),
            ("bEnable", 1),
        ]),
        "SLI" | "SLI2" => running(&[
            ("wInputActive", SL_SLI_ACTIVE as i64),
            ("nLimitPos", 100),
            ("nLimitNeg", 100),
            ("nPosition", 1000),
            ("bSLI", 1),
        ]),
        // The value table (outside the field table) is written by `loadsensing_rows`.
        "LOADSENSING" => running(&[
            (
                "wInputActive",
                (SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY) as i64,
            ),
            ("nRowCount", SL_LOADSENSING_ROWS_MAX as i64),
            ("nAnalogInX", 1000),
            ("nAnalogInY", 2450),
        ]),
        "ENVELOPE" => running(&[
            ("wInputActive", SL_ENVELOPE_ACTIVE as i64),
            ("tTimeAfterInTarget", 100),
            ("tMaxTime", 5000),
            ("nTargetValue", 10),
            ("nOffset", 50),
            ("bSafeFunction", 1),
            ("nInValue", 500),
        ]),
        "CAMMONITOR" => Setup {
            set: &[
                (
                    "wInputActive",
                    (SL_CAMMONITOR_ACTIVE_RESET
                        | SL_CAMMONITOR_ACTIVE_POSITION
                        | SL_CAMMONITOR_ACTIVE_PRESSSTARTED
                        | SL_CAMMONITOR_ACTIVE_OVERRUNCAM
                        | SL_CAMMONITOR_ACTIVE_UPWARDCAM) as i64,
                ),
                ("tStopDetectionTime", 50),
                ("tPressStartDelayTime", 200),
                ("tMoveDetectionTime", 100),
                ("nAllowedPositionJitter", 4),
                ("nMinPositionChange", 20),
                ("nMaxPosition", 8192),
                ("nTDC1LowerLimitFix", 8092),
                ("nTDC1UpperLimitFix", 100),
                ("nBDCLowerLimitFix", 3896),
                ("nBDCUpperLimitFix", 4296),
                ("nOverrunMaxFix", 800),
                ("nPosition", 50),
                ("bOverrunCam", 1),
            ],
            pulses: &[&[], &[("bReset", 1)]],
            state: "RUN",
        },
        "SLP" => running(&[
            (
                "wInputActive",
                (SL_SLP_ACTIVE_SAFEPOSVALID
                    | SL_SLP_ACTIVE_SINGLETURNPOS
                    | SL_SLP_ACTIVE_MULTITURNPOS) as i64,
            ),
            ("nMultiturnPosLLFix", -1),
            ("nMultiturnPosULFix", 1),
            ("bSafePosValid", 1),
            ("nSingleturnPos", 5),
        ]),
        "SBT" => Setup {
            state: "SAFE",
            ..running(&[
                (
                    "wInputActive",
                    (SL_SBT_ACTIVE_SBT
                        | SL_SBT_ACTIVE_SBCIN
                        | SL_SBT_ACTIVE_SINGLETURNPOS
                        | SL_SBT_ACTIVE_ACTCURRENTIQ) as i64,
                ),
                ("tBrakeTestInterval", SL_SBT_TIME_MAX as i64),
                ("tMinDuration", 1000),
                ("tMaxDuration", 20_000),
                ("nMaxPositionDeviation", 10),
            ])
        },
        "ADVPOSMON" => running(&[
            (
                "wInputActive",
                (SL_ADVPOSMON_ACTIVE_ENABLE | SL_ADVPOSMON_ACTIVE_RESTART) as i64,
            ),
            ("bEnable", 1),
            ("bPosRefOk", 1),
            ("bPosCheckOk", 1),
        ]),
        "CONNECTION_SHUTDOWN" => running(&[
            ("wInputActive", 0b01),
            ("nConnectionId", 7),
            ("bDeactivate1", 1),
            ("bConnShutdown", 1),
        ]),
        "SF_EmergencyStop" => plcopen(&[("S_EStopIn", 1), ("S_StartReset", 1), ("S_AutoReset", 1)]),
        "SF_ESPE" => plcopen(&[("S_ESPE_In", 1), ("S_StartReset", 1), ("S_AutoReset", 1)]),
        "SF_PSE" => plcopen(&[("S_PSE_In", 1), ("S_StartReset", 1), ("S_AutoReset", 1)]),
        "SF_Equivalent" => plcopen(&[("S_ChannelA", 1), ("S_ChannelB", 1)]),
        "SF_Antivalent" => plcopen(&[("S_ChannelNC", 1)]),
        "SF_Guard" => plcopen(&[
            ("S_GuardSwitch1", 1),
            ("S_GuardSwitch2", 1),
            ("S_StartReset", 1),
            ("S_AutoReset", 1),
        ]),
        "SF_SafetyRequest" => Setup {
            pulses: &[
                &[("S_OpMode", 1), ("S_Acknowledge", 0)],
                &[("S_OpMode", 1), ("Reset", 1), ("S_Acknowledge", 0)],
                &[("S_OpMode", 1), ("S_Acknowledge", 0)],
                &[("S_Acknowledge", 0)],
            ],
            ..plcopen(&[("S_Acknowledge", 1)])
        },
        // StaticControl: a ProcessControl that is TRUE from the start enables the output.
        "SF_OutControl" => plcopen(&[
            ("S_SafeControl", 1),
            ("ProcessControl", 1),
            ("StaticControl", 1),
            ("S_StartReset", 1),
            ("S_AutoReset", 1),
        ]),
        // Activated (it has no Activate), waiting for a press (8000 lasts one call).
        "SF_ResetButton" => Setup {
            state: "ACTIVE 83E2",
            ..plcopen(&[
                ("ResetRequested", 1),
                ("TrailingMinimum", 100),
                ("TrailingMaximum", 2000),
            ])
        },
        // The contactors released (feedback TRUE) while the output is off and in the call
        // that switches it on, then switched.
        "SF_EDM" => Setup {
            pulses: &[
                &[("S_OutControl", 0), ("EDM1", 1), ("EDM2", 1)],
                &[("S_OutControl", 0), ("EDM1", 1), ("EDM2", 1)],
                &[("EDM1", 1), ("EDM2", 1)],
            ],
            ..plcopen(&[("S_OutControl", 1), ("S_StartReset", 1)])
        },
        // Free, not tested automatically (an automatic test needs the OSSD to follow the
        // test output): the output TRUE.
        "SF_TestableSafetySensor" => Setup {
            state: "ACTIVE 8010",
            ..plcopen(&[
                ("S_OSSD_In", 1),
                ("NoExternalTest", 1),
                ("S_StartReset", 1),
                ("S_AutoReset", 1),
            ])
        },
        "SF_EnableSwitch" => Setup {
            pulses: &[
                &[
                    ("S_SafetyActive", 0),
                    ("S_EnableSwitchCh1", 0),
                    ("S_EnableSwitchCh2", 0),
                ],
                &[("S_EnableSwitchCh1", 0)],
                &[("S_EnableSwitchCh1", 0)],
                &[("S_EnableSwitchCh1", 0)],
            ],
            ..plcopen(&[
                ("S_SafetyActive", 1),
                ("S_EnableSwitchCh1", 1),
                ("S_EnableSwitchCh2", 1),
            ])
        },
        "SF_TwoHandControlTypeII" | "SF_TwoHandControlTypeIII" => Setup {
            pulses: &[
                &[("S_Button1", 0), ("S_Button2", 0)],
                &[("S_Button1", 0), ("S_Button2", 0)],
                &[("S_Button1", 0), ("S_Button2", 0)],
            ],
            ..plcopen(&[("S_Button1", 1), ("S_Button2", 1)])
        },
        "SF_ModeSelector" => plcopen(&[("S_Mode0", 1), ("AutoSetMode", 1), ("S_Unlock", 1)]),
        _ => panic!("{name}: no configuration in the every-type table"),
    }
}

/// Writes `v` (its low `size` bytes) at `offset` of the instance at `p`, as one store of
/// the field's width (what a caller's typed store is).
///
/// # Safety
/// `offset + size` lies inside the instance; `size` is 1, 2 or 4.
#[inline(always)]
unsafe fn put(p: *mut u8, offset: u16, size: usize, v: u32) {
    // SAFETY: the caller keeps the write inside the instance; integer fields only.
    unsafe {
        let q = p.add(usize::from(offset));
        match size {
            1 => q.write(v as u8),
            2 => q.cast::<u16>().write_unaligned(v as u16),
            _ => q.cast::<u32>().write_unaligned(v),
        }
    }
}

/// The value table of LOADSENSING (a parameter outside the field table, the rows right
/// before `nRowCount`): the hand-written row's 25 rows, X 10·i, Y1..Y2 100·i … 100·i + 90,
/// the warning levels 10 inside.
fn loadsensing_rows(t: &BlockType, p: *mut u8) {
    let (Some(count), Some(x)) = (t.field("nRowCount"), t.field("nAnalogInX")) else {
        return;
    };
    let w = x.kind.size();
    let rows = usize::from(SL_LOADSENSING_ROWS_MAX);
    let base = usize::from(count.offset) - rows * 5 * w;
    for i in 0..rows as u32 {
        let row = [10 * i, 100 * i, 100 * i + 90, 100 * i + 10, 100 * i + 80];
        for (k, v) in row.into_iter().enumerate() {
            let at = (base + (5 * i as usize + k) * w) as u16;
            // SAFETY: the rows lie inside the struct, before `nRowCount`.
            unsafe { put(p, at, w, v) };
        }
    }
}

/// A small xorshift generator (the bench must not depend on a crate for this).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

/// The input fields as (offset, size), and `n` patterns of their values: pattern 0 the
/// steady one, the others random around it.
fn inputs(t: &BlockType, steady: &[u32], n: usize) -> (Vec<(u16, usize)>, Vec<Vec<u32>>) {
    let fields: Vec<_> = t.fields.iter().filter(|f| f.dir == Dir::Input).collect();
    let mut rng = Rng(0x5EED_0000 ^ u64::from(t.info.tag) | 1);
    let patterns = (0..n)
        .map(|i| {
            fields
                .iter()
                .zip(steady)
                .map(|(f, &s)| match (f.kind, i) {
                    (_, 0) => s,
                    (Kind::Bool, _) => (rng.next() & 1) as u32,
                    _ => s.wrapping_add((rng.next() % 5) as u32).wrapping_sub(2),
                })
                .collect()
        })
        .collect();
    (
        fields.iter().map(|f| (f.offset, f.kind.size())).collect(),
        patterns,
    )
}

/// The state column: the state's name, and a PLCopen block's DiagCode.
fn state_of<T: FunctionBlock>(fb: &T) -> String {
    match fb.get("DiagCode") {
        Some(d) => format!("{} {d:04X}", fb.state_name()),
        None => fb.state_name().to_string(),
    }
}

/// Sets up one instance and times it (`batches` batches of `calls`), or in the callgrind
/// child (`steady_only`) makes only the warm-up and the steady calls. Panics when the
/// configuration is refused or a timed steady call leaves the running state or returns
/// another status than `SL_OK`.
fn one<T: Copy + FunctionBlock>(
    cycle_name: &'static str,
    tag: u16,
    init: unsafe extern "C" fn(*mut T) -> i32,
    cycle: unsafe extern "C" fn(*mut T, u32) -> i32,
    (warmup, batches, calls): (u32, usize, u32),
    steady_only: bool,
) -> TypeRow {
    let t = block_type(tag).expect("a registered row");
    let name = t.info.name;
    assert_eq!(t.size, std::mem::size_of::<T>());
    let how = setup(name);
    let field = |n: &str| {
        t.field(n)
            .unwrap_or_else(|| panic!("{name}: no field {n} in the field table"))
    };
    // SAFETY: every block struct holds only integer fields (and zero-sized markers), so the
    // zero pattern is a valid value.
    let mut fb: T = unsafe { std::mem::zeroed() };
    let p = (&mut fb as *mut T).cast::<u8>();
    let plcopen = name.starts_with("SF_");
    for f in t.fields.iter() {
        let v = match (f.dir, f.kind) {
            (Dir::Control, _) if f.name == "bRun" => 1,
            (Dir::Input, Kind::Bool) if plcopen && f.name == "Activate" => 1,
            (Dir::Param, Kind::U32) if plcopen && f.name.ends_with("Time") => 100,
            _ => continue,
        };
        // SAFETY: the field table's offsets and sizes lie inside the struct.
        unsafe { put(p, f.offset, f.kind.size(), v) };
    }
    for &(n, v) in how.set {
        let f = field(n);
        // SAFETY: as above.
        unsafe { put(p, f.offset, f.kind.size(), v as u32) };
    }
    if name.starts_with("LOADSENSING") {
        loadsensing_rows(t, p);
    }
    // The steady input values, as configured.
    let steady: Vec<u32> = t
        .fields
        .iter()
        .filter(|f| f.dir == Dir::Input)
        .map(|f| fb.get(f.name).expect("a field of the table"))
        .collect();
    let (fields, patterns) = inputs(t, &steady, 257);
    let write = |fb: &mut T, pattern: &[u32]| {
        let p = (fb as *mut T).cast::<u8>();
        for (&(offset, size), &v) in fields.iter().zip(pattern) {
            // SAFETY: the field table's offsets and sizes lie inside the struct.
            unsafe { put(p, offset, size, v) };
        }
    };
    // SAFETY: `fb` is a valid instance of the type the function belongs to.
    let status = unsafe { init(&mut fb) };
    assert_eq!(status, SL_OK, "{name}: init refused the configuration");
    let f = black_box(cycle);
    let mut now = 0u32;
    for pulse in how.pulses {
        now += 1;
        write(&mut fb, &patterns[0]);
        for &(n, v) in *pulse {
            let f = field(n);
            // SAFETY: as above.
            unsafe {
                put(
                    (&mut fb as *mut T).cast(),
                    f.offset,
                    f.kind.size(),
                    v as u32,
                )
            };
        }
        // SAFETY: as above.
        unsafe { f(&mut fb, now) };
    }
    write(&mut fb, &patterns[0]);
    for _ in 0..warmup {
        now += 1;
        // SAFETY: as above.
        unsafe { f(&mut fb, now) };
    }
    let state = state_of(&fb);
    let expected = how.state.to_string();
    assert_eq!(
        state, expected,
        "{name}: not in its running state after the warm-up"
    );
    let mut ns = [0.0; 3];
    let mut timed = |column: usize, fb: &mut T, now: &mut u32| {
        let mut per_call = Vec::with_capacity(batches);
        let mut k = 0usize;
        let mut refused = 0u32;
        for _ in 0..batches {
            let start = Instant::now();
            for _ in 0..calls {
                *now = now.wrapping_add(1);
                match column {
                    0 => {}
                    1 => write(black_box(&mut *fb), &patterns[0]),
                    _ => {
                        k = k % 256 + 1;
                        write(black_box(&mut *fb), &patterns[k]);
                    }
                }
                // SAFETY: as above.
                let rc = unsafe { f(black_box(&mut *fb), *now) };
                refused += u32::from(black_box(rc) != SL_OK);
            }
            per_call.push(start.elapsed().as_nanos() as f64 / f64::from(calls));
        }
        per_call.sort_by(f64::total_cmp);
        ns[column] = per_call[per_call.len() / 2];
        refused
    };
    for column in 0..if steady_only { 1 } else { 2 } {
        let refused = timed(column, &mut fb, &mut now);
        assert_eq!(
            refused, 0,
            "{name}: a timed call (column {column}) was refused"
        );
        assert_eq!(
            state_of(&fb),
            expected,
            "{name}: left its running state while timed (column {column})"
        );
    }
    let mut random_running = 0.0;
    if !steady_only {
        // Random inputs on a copy, so the steady instance stays as it was; then the same
        // random series once more, untimed, counting the calls that stay running.
        let start = now;
        let mut r = fb;
        timed(2, &mut r, &mut now);
        let mut r = fb;
        let mut running = 0u32;
        let mut t = start;
        for k in 0..4096usize {
            t = t.wrapping_add(1);
            write(&mut r, &patterns[k % 256 + 1]);
            // SAFETY: as above.
            let rc = unsafe { f(&mut r, t) };
            running += u32::from(rc == SL_OK && state_of(&r) == expected);
        }
        random_running = f64::from(running) * 100.0 / 4096.0;
    }
    TypeRow {
        name,
        cycle: cycle_name,
        state,
        ns,
        random_running,
    }
}

macro_rules! all_types {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// Every registered type, in registry order.
        pub fn run(shape: (u32, usize, u32), steady_only: bool) -> Vec<TypeRow> {
            vec![$(one::<$ty>(
                stringify!($cycle),
                <$ty as Registered>::INFO.tag,
                $init,
                $cycle,
                shape,
                steady_only,
            ),)*]
        }
    };
}
safelogic::for_each_block!(all_types);
