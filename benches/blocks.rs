//! Per-block benchmark (issue 3): every block called through its C function with steady
//! inputs, in the steady state the inputs lead to (RUN where the block has one). Prints the
//! median and p99 per call, the struct and private-state sizes, and each target.
//! `cargo bench --bench blocks`. Reports, never asserts timing. With `--bench` and valgrind
//! on the machine it also runs its own smoke mode under callgrind and prints the
//! instructions per steady call of every row (repeatable where times are not), and those
//! per call with random inputs of the random-against-steady rows (a second child that runs
//! only their random calls); `tools/callgrind_blocks.sh` prints only the steady ones.

use safelogic::ffi::*;
use safelogic::*;
use std::collections::HashMap;
use std::hint::black_box;
use std::mem::size_of_val;
use std::process::Command;
use std::time::Instant;

#[path = "blocks/all_types.rs"]
mod all_types;

/// The callgrind child that makes only the steady calls of the every-type table.
const ALL_CHILD: &str = "--callgrind-all";

const CALLS_PER_BATCH: u32 = 1000;
const WARMUP_CALLS: u32 = 200;
const SMOKE_BATCHES: usize = 20;

/// The callgrind child that runs only the random-input rows, random inputs only.
const RANDOM_CHILD: &str = "--callgrind-random";

/// Instructions per call of every exported `sl_*_cycle` in one callgrind run of this bench's
/// smoke mode (inclusive counts of the functions, divided by the calls each row makes), or
/// why there are none.
fn instructions_per_call() -> Result<HashMap<String, f64>, String> {
    let calls = f64::from(WARMUP_CALLS) + (SMOKE_BATCHES as f64) * f64::from(CALLS_PER_BATCH);
    callgrind_per_call("--callgrind-child", calls)
}

/// Instructions per call with random inputs (the random half of `cliff_row`, which makes
/// `SMOKE_BATCHES + 1` batches of calls in the child).
fn random_instructions_per_call() -> Result<HashMap<String, f64>, String> {
    let calls = ((SMOKE_BATCHES + 1) as f64) * f64::from(CALLS_PER_BATCH);
    callgrind_per_call(RANDOM_CHILD, calls)
}

/// Runs this bench as `child` under callgrind, collecting inside the `sl_*_cycle` functions
/// only, and divides each one's inclusive count by `calls`.
fn callgrind_per_call(child: &str, calls: f64) -> Result<HashMap<String, f64>, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = std::env::temp_dir().join(format!("sl-blocks-{}.callgrind", std::process::id()));
    let run = Command::new("valgrind")
        .arg("--tool=callgrind")
        .arg(format!("--callgrind-out-file={}", out.display()))
        .arg("--toggle-collect=sl_*_cycle")
        .arg(&exe)
        .arg(child)
        .output()
        .map_err(|_| "valgrind is not installed".to_string())?;
    if !run.status.success() {
        return Err("valgrind failed".into());
    }
    let ann = Command::new("callgrind_annotate")
        .arg("--inclusive=yes")
        // Every function: the default threshold drops the cheap ones.
        .arg("--threshold=100")
        .arg(&out)
        .output()
        .map_err(|_| "callgrind_annotate is not installed".to_string())?;
    let _ = std::fs::remove_file(&out);
    let mut per_call = HashMap::new();
    for line in String::from_utf8_lossy(&ann.stdout).lines() {
        let mut words = line.split_whitespace();
        let (Some(count), Some(_)) = (words.next(), words.next()) else {
            continue;
        };
        let Ok(count) = count.replace(',', "").parse::<f64>() else {
            continue;
        };
        let Some(name) = line
            .split(':')
            .nth(1)
            .and_then(|f| f.split_whitespace().next())
        else {
            continue;
        };
        if name.starts_with("sl_") && name.ends_with("_cycle") {
            per_call.entry(name.to_string()).or_insert(count / calls);
        }
    }
    Ok(per_call)
}

struct Row {
    name: &'static str,
    state: u8,
    ty: u16,
    median: f64,
    p99: f64,
    size: usize,
    private: usize,
    target: f64,
}

/// Brings `fb` to its steady state (a few 1 ms cycles), then times batches of calls of
/// `cycle` through an opaque function pointer, as from C.
fn measure<T>(
    (name, ty, target): (&'static str, u16, f64),
    batches: usize,
    mut fb: T,
    private: usize,
    cycle: unsafe extern "C" fn(*mut T, u32) -> i32,
    state: fn(&T) -> u8,
) -> Row {
    let f: unsafe extern "C" fn(*mut T, u32) -> i32 = black_box(cycle);
    let mut t = 0u32;
    for _ in 0..WARMUP_CALLS {
        t += 1;
        unsafe { f(&mut fb, t) };
    }
    let mut per_call = Vec::with_capacity(batches);
    for _ in 0..batches {
        let start = Instant::now();
        for _ in 0..CALLS_PER_BATCH {
            t = t.wrapping_add(1);
            black_box(unsafe { f(black_box(&mut fb), t) });
        }
        per_call.push(start.elapsed().as_nanos() as f64 / f64::from(CALLS_PER_BATCH));
    }
    per_call.sort_by(f64::total_cmp);
    let at = |q: f64| per_call[((per_call.len() - 1) as f64 * q).round() as usize];
    Row {
        name,
        state: state(&fb),
        ty,
        median: at(0.5),
        p99: at(0.99),
        size: size_of_val(&fb),
        private,
        target,
    }
}

fn main() {
    let quick = !std::env::args().any(|a| a == "--bench");
    let only_instructions = std::env::args().any(|a| a == "--instructions");
    // The run under callgrind: the steady rows only, so each function's calls are its row's.
    let child = std::env::args().any(|a| a == "--callgrind-child");
    if std::env::args().any(|a| a == RANDOM_CHILD) {
        cliff_rows(SMOKE_BATCHES);
        return;
    }
    if std::env::args().any(|a| a == ALL_CHILD) {
        all_types::run((WARMUP_CALLS, SMOKE_BATCHES, CALLS_PER_BATCH), true);
        return;
    }
    let instructions = (!child && (!quick || only_instructions)).then(instructions_per_call);
    let random_instructions = (!quick && !only_instructions).then(random_instructions_per_call);
    let batches = if quick || only_instructions {
        SMOKE_BATCHES
    } else {
        3000
    };
    // The virtual CPUs here run slower for the first few hundred ms of a busy process: spin
    // first, so the first rows are not penalised.
    let spin = Instant::now();
    while spin.elapsed().as_millis() < if quick { 10 } else { 1500 } {
        black_box(spin.elapsed());
    }
    let logic = 5.0;
    let timer = 50.0;
    let mut rows = Vec::new();

    let mut e = FB_ESTOP {
        wInputActive: 0b11,
        tDiscTime12: 20,
        bRun: 1,
        ..Default::default()
    };
    (e.bEStopIn1, e.bEStopIn2) = (1, 1);
    e.init();
    e.cycle(0);
    e.bRestart = 1;
    e.cycle(0);
    e.bRestart = 0;
    let private = size_of_val(&e.stPrivate);
    rows.push(measure(
        ("ESTOP", SL_TYPE_ESTOP, logic),
        batches,
        e,
        private,
        sl_estop_cycle,
        |f| f.nState,
    ));

    let mut m = FB_MON {
        wInputActive: 0b11,
        tDiscTime12: 20,
        bRun: 1,
        ..Default::default()
    };
    (m.bMonIn1, m.bMonIn2) = (1, 1);
    m.init();
    let private = size_of_val(&m.stPrivate);
    rows.push(measure(
        ("MON", SL_TYPE_MON, logic),
        batches,
        m,
        private,
        sl_mon_cycle,
        |f| f.nState,
    ));

    let mut a = FB_AND {
        wInputActive: 0b11,
        bRun: 1,
        ..Default::default()
    };
    (a.bAndIn1, a.bAndIn2) = (1, 1);
    a.init();
    let private = size_of_val(&a.stPrivate);
    rows.push(measure(
        ("AND", SL_TYPE_AND, logic),
        batches,
        a,
        private,
        sl_and_cycle,
        |f| f.nState,
    ));

    let mut o = FB_OR {
        wInputActive: 0b11,
        bRun: 1,
        ..Default::default()
    };
    o.bOrIn1 = 1;
    o.init();
    let private = size_of_val(&o.stPrivate);
    rows.push(measure(
        ("OR", SL_TYPE_OR, logic),
        batches,
        o,
        private,
        sl_or_cycle,
        |f| f.nState,
    ));

    let mut x = FB_XOR {
        wInputActive: 0b11,
        bRun: 1,
        ..Default::default()
    };
    (x.bXor1In1, x.bXor1In2) = (1, 1);
    x.init();
    let private = size_of_val(&x.stPrivate);
    rows.push(measure(
        ("XOR", SL_TYPE_XOR, logic),
        batches,
        x,
        private,
        sl_xor_cycle,
        |f| f.nState,
    ));

    let mut d = FB_DECOUPLE {
        wInputActive: 0xFF,
        bRun: 1,
        ..Default::default()
    };
    (d.bDecIn1, d.bDecIn5) = (1, 1);
    d.init();
    let private = size_of_val(&d.stPrivate);
    rows.push(measure(
        ("DECOUPLE", SL_TYPE_DECOUPLE, logic),
        batches,
        d,
        private,
        sl_decouple_cycle,
        |f| f.nState,
    ));

    let mut op = FB_OPMODE {
        wInputActive: 0b11,
        tDiscTime: 100,
        bRun: 1,
        ..Default::default()
    };
    op.bOpIn1 = 1;
    op.init();
    let private = size_of_val(&op.stPrivate);
    rows.push(measure(
        ("OPMODE", SL_TYPE_OPMODE, logic),
        batches,
        op,
        private,
        sl_opmode_cycle,
        |f| f.nState,
    ));

    let mut th = FB_TWOHAND {
        wInputActive: 0b1111,
        tDiscTime12: 100,
        tDiscTime34: 100,
        bRun: 1,
        ..Default::default()
    };
    th.init();
    th.cycle(0);
    (th.bTwoHand1, th.bTwoHand2, th.bTwoHand3, th.bTwoHand4) = (1, 1, 1, 1);
    let private = size_of_val(&th.stPrivate);
    rows.push(measure(
        ("TWOHAND", SL_TYPE_TWOHAND, logic),
        batches,
        th,
        private,
        sl_twohand_cycle,
        |f| f.nState,
    ));

    let mut mu = FB_MUTING {
        wInputActive: 0b11_1111,
        tDiscTime12: 50,
        tDiscTime34: 50,
        tDiscTimeOSSD: 50,
        bRun: 1,
        ..Default::default()
    };
    (
        mu.bMutingEnable,
        mu.bEDM1,
        mu.bEDM2,
        mu.bOSSDIn1,
        mu.bOSSDIn2,
    ) = (1, 1, 1, 1, 1);
    mu.init();
    let private = size_of_val(&mu.stPrivate);
    rows.push(measure(
        ("MUTING", SL_TYPE_MUTING, timer),
        batches,
        mu,
        private,
        sl_muting_cycle,
        |f| f.nState,
    ));

    let mut ed = FB_EDM {
        wInputActive: 0b11,
        tSwitchOnTime: 100,
        tSwitchOffTime: 100,
        bRun: 1,
        ..Default::default()
    };
    (ed.bMon1, ed.bMon2) = (1, 0);
    ed.init();
    let private = size_of_val(&ed.stPrivate);
    rows.push(measure(
        ("EDM", SL_TYPE_EDM, logic),
        batches,
        ed,
        private,
        sl_edm_cycle,
        |f| f.nState,
    ));

    let mut rs = FB_RS {
        wInputActive: 0b11,
        bRun: 1,
        ..Default::default()
    };
    rs.init();
    rs.bSet = 1;
    rs.cycle(0);
    rs.bSet = 0;
    let private = size_of_val(&rs.stPrivate);
    rows.push(measure(
        ("RS", SL_TYPE_RS, logic),
        batches,
        rs,
        private,
        sl_rs_cycle,
        |f| f.nState,
    ));

    let mut sr = FB_SR {
        wInputActive: 0b11,
        bRun: 1,
        ..Default::default()
    };
    sr.init();
    sr.bSet = 1;
    sr.cycle(0);
    sr.bSet = 0;
    let private = size_of_val(&sr.stPrivate);
    rows.push(measure(
        ("SR", SL_TYPE_SR, logic),
        batches,
        sr,
        private,
        sl_sr_cycle,
        |f| f.nState,
    ));

    let mut ton = FB_TON {
        wInputActive: 1,
        tDelay: 10,
        bRun: 1,
        ..Default::default()
    };
    ton.bTonIn1 = 1;
    ton.init();
    let private = size_of_val(&ton.stPrivate);
    rows.push(measure(
        ("TON", SL_TYPE_TON, timer),
        batches,
        ton,
        private,
        sl_ton_cycle,
        |f| f.nState,
    ));

    let mut ton2 = FB_TON2 {
        wInputActive: 1,
        tDelay: 10,
        bRun: 1,
        ..Default::default()
    };
    (ton2.bTonIn1, ton2.bEnable) = (1, 1);
    ton2.init();
    let private = size_of_val(&ton2.stPrivate);
    rows.push(measure(
        ("TON2", SL_TYPE_TON2, timer),
        batches,
        ton2,
        private,
        sl_ton2_cycle,
        |f| f.nState,
    ));

    let mut tof = FB_TOF {
        wInputActive: 1,
        tDelay: 10,
        bRun: 1,
        ..Default::default()
    };
    tof.bTofIn1 = 1;
    tof.init();
    let private = size_of_val(&tof.stPrivate);
    rows.push(measure(
        ("TOF", SL_TYPE_TOF, timer),
        batches,
        tof,
        private,
        sl_tof_cycle,
        |f| f.nState,
    ));

    // The arithmetic blocks, one variant per width and operation (no target in the issue:
    // reported against the logic target).
    macro_rules! arith_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident, $a:expr, $b:expr;)*) => {$(
            let mut fb = <$ty>::default();
            fb.wInputActive = safelogic::blocks::analog::arith::ARITH_ACTIVE;
            (fb.nAnalogIn1, fb.nAnalogIn2, fb.bRun) = ($a, $b, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::arith::*;
    arith_row! {
        "ADD_INT", FB_ADD_INT, SL_TYPE_ADD_INT, sl_add_int_cycle, 1200, -34;
        "SUB_UDINT", FB_SUB_UDINT, SL_TYPE_SUB_UDINT, sl_sub_udint_cycle, 70_000, 3;
        "MUL_DINT", FB_MUL_DINT, SL_TYPE_MUL_DINT, sl_mul_dint_cycle, 4_000, -300;
        "DIV_INT", FB_DIV_INT, SL_TYPE_DIV_INT, sl_div_int_cycle, -7_001, 3;
        "DIV_UDINT", FB_DIV_UDINT, SL_TYPE_DIV_UDINT, sl_div_udint_cycle, 4_000_000_000, 7;
    }

    // LIMIT, one row per width: AnalogIn inside parameter limits (RUN), and INT with the
    // minimum from its input.
    macro_rules! limit_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident, $active:expr, $v:expr;)*) => {$(
            let mut fb = <$ty>::default();
            fb.wInputActive = $active;
            (fb.nMinimumValue, fb.nMaximumValue) = (0, 1_000);
            (fb.nAnalogIn, fb.nMinValue, fb.bRun) = ($v, 10, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::limit::*;
    limit_row! {
        "LIMIT_INT", FB_LIMIT_INT, SL_TYPE_LIMIT_INT, sl_limit_int_cycle, 0x300, 500;
        "LIMIT_UDINT", FB_LIMIT_UDINT, SL_TYPE_LIMIT_UDINT, sl_limit_udint_cycle, 0x100, 500;
    }

    // COMPARE 3oo5, one row per width: five inputs, three agreeing (RUN).
    macro_rules! compare_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident;)*) => {$(
            let mut fb = <$ty>::default();
            (fb.nArchitecture, fb.wInputActive) = (SL_ARCH_3OO5, 0x1F00);
            (fb.nAllowedDeviation, fb.tToleranceTime, fb.bRun) = (2, 100, 1);
            (fb.nCompIn1, fb.nCompIn2, fb.nCompIn3, fb.nCompIn4, fb.nCompIn5) = (50, 10, 11, 90, 12);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::compare::*;
    compare_row! {
        "COMPARE_INT", FB_COMPARE_INT, SL_TYPE_COMPARE_INT, sl_compare_int_cycle;
        "COMPARE_UDINT", FB_COMPARE_UDINT, SL_TYPE_COMPARE_UDINT, sl_compare_udint_cycle;
    }

    // SCALE, one row per width: x · 3 ÷ 4 + 5 with rounding and the StuckAt watchdog on
    // (steady input: the watchdog expires and holds), DINT dividing first with negation.
    macro_rules! scale_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident, $negated:expr, $options:expr;)*) => {$(
            let mut fb = <$ty>::default();
            (fb.wInputActive, fb.wInputNegated, fb.dwOptions) = (SL_SCALE_ACTIVE_ANALOGIN, $negated, $options);
            (fb.nNumerator, fb.nDenominator, fb.nOffset) = (3, 4, 5);
            (fb.nRounding, fb.tWatchdog, fb.nAnalogIn, fb.bRun) = (SL_ROUNDING_ROUND, 100, 1_000, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::scale::*;
    scale_row! {
        "SCALE_INT", FB_SCALE_INT, SL_TYPE_SCALE_INT, sl_scale_int_cycle, 0, 0;
        "SCALE_DINT", FB_SCALE_DINT, SL_TYPE_SCALE_DINT, sl_scale_dint_cycle, SL_SCALE_NEGATE_ANALOGIN, SL_OPT_SCALE_DIVISION_FIRST;
    }

    // SPEED, one row per width: a standing position, a 10 ms interval (an update every tenth
    // call), UDINT with the overflow check.
    macro_rules! speed_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident, $options:expr;)*) => {$(
            let mut fb = <$ty>::default();
            (fb.wInputActive, fb.tTimeInterval, fb.dwOptions) = (SL_SPEED_ACTIVE_POSITION, 10, $options);
            (fb.nPosition, fb.bRun) = (1_000, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::speed::*;
    speed_row! {
        "SPEED_INT", FB_SPEED_INT, SL_TYPE_SPEED_INT, sl_speed_int_cycle, 0;
        "SPEED_UDINT", FB_SPEED_UDINT, SL_TYPE_SPEED_UDINT, sl_speed_udint_cycle, SL_OPT_SPEED_OVERFLOW_CHECK;
    }

    // COUNTER, one row per width: all inputs active, steady (no edge), counting from 0.
    macro_rules! counter_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident;)*) => {$(
            let mut fb = <$ty>::default();
            fb.wInputActive = SL_COUNTER_ACTIVE_INPUTS;
            (fb.nPresetValue, fb.nCounterLimit, fb.bRun) = (5, 100, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::counter::*;
    counter_row! {
        "COUNTER_INT", FB_COUNTER_INT, SL_TYPE_COUNTER_INT, sl_counter_int_cycle;
        "COUNTER_UDINT", FB_COUNTER_UDINT, SL_TYPE_COUNTER_UDINT, sl_counter_udint_cycle;
    }

    // VIOLATIONCOUNTER, both widths: enabled, a good input every call (counter at 0, RUN).
    macro_rules! violation_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident;)*) => {$(
            let mut fb = <$ty>::default();
            fb.wInputActive = SL_VIOLATIONCOUNTER_ACTIVE;
            (fb.nIncrementError, fb.nDecrementNoError, fb.nCounterLimit) = (3, 1, 10);
            (fb.bInput, fb.bEnable, fb.bRun) = (1, 1, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::violationcounter::*;
    violation_row! {
        "VIOLATIONCOUNTER_UINT", FB_VIOLATIONCOUNTER_UINT, SL_TYPE_VIOLATIONCOUNTER_UINT, sl_violationcounter_uint_cycle;
        "VIOLATIONCOUNTER_UDINT", FB_VIOLATIONCOUNTER_UDINT, SL_TYPE_VIOLATIONCOUNTER_UDINT, sl_violationcounter_udint_cycle;
    }

    // SLI and SLI2, one row per width: SLI TRUE since the first call (latched), the
    // position inside the window (RUN); SLI2 with both options.
    macro_rules! sli_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident $(, $options:expr)?;)*) => {$(
            let mut fb = <$ty>::default();
            (fb.wInputActive, fb.nLimitPos, fb.nLimitNeg) = (SL_SLI_ACTIVE, 100, 100);
            $(fb.dwOptions = $options;)?
            (fb.nPosition, fb.bSLI, fb.bRun) = (1_000, 1, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::{sli::*, sli2::*};
    sli_row! {
        "SLI_INT", FB_SLI_INT, SL_TYPE_SLI_INT, sl_sli_int_cycle;
        "SLI_UDINT", FB_SLI_UDINT, SL_TYPE_SLI_UDINT, sl_sli_udint_cycle;
        "SLI2_UINT", FB_SLI2_UINT, SL_TYPE_SLI2_UINT, sl_sli2_uint_cycle,
            SL_OPT_SLI2_OVERFLOW_ALLOWED | SL_OPT_SLI2_EXCEEDED_SUPPORT;
    }

    // LOADSENSING, one row per width: a full table of 25 rows, AnalogInX above the last X
    // (the longest row search), AnalogInY inside the warning level (RUN).
    macro_rules! loadsensing_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident;)*) => {$(
            let mut fb = <$ty>::default();
            fb.wInputActive = SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY;
            fb.nRowCount = SL_LOADSENSING_ROWS_MAX;
            for (i, r) in (0..).zip(fb.aRow.iter_mut()) {
                (r.nX, r.nY1, r.nY2, r.nWY1, r.nWY2) = (10 * i, 100 * i, 100 * i + 90, 100 * i + 10, 100 * i + 80);
            }
            (fb.nAnalogInX, fb.nAnalogInY, fb.bRun) = (1_000, 2_450, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, logic), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::loadsensing::*;
    loadsensing_row! {
        "LOADSENSING_INT", FB_LOADSENSING_INT, SL_TYPE_LOADSENSING_INT, sl_loadsensing_int_cycle;
        "LOADSENSING_UDINT", FB_LOADSENSING_UDINT, SL_TYPE_LOADSENSING_UDINT, sl_loadsensing_udint_cycle;
    }

    // ENVELOPE, one row per width: SafeFunction TRUE (RUN; MONITOR ends at MaxTime ≤ 65 s,
    // shorter than a measurement).
    macro_rules! envelope_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:ident;)*) => {$(
            let mut fb = <$ty>::default();
            fb.wInputActive = SL_ENVELOPE_ACTIVE;
            (fb.tTimeAfterInTarget, fb.tMaxTime, fb.nTargetValue, fb.nOffset) = (100, 5_000, 10, 50);
            (fb.bSafeFunction, fb.nInValue, fb.bRun) = (1, 500, 1);
            fb.init();
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, timer), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::analog::envelope::*;
    envelope_row! {
        "ENVELOPE_INT", FB_ENVELOPE_INT, SL_TYPE_ENVELOPE_INT, sl_envelope_int_cycle;
        "ENVELOPE_UDINT", FB_ENVELOPE_UDINT, SL_TYPE_ENVELOPE_UDINT, sl_envelope_udint_cycle;
    }

    // CAMMONITOR: excentric, both hardware cams and Press_Started monitored, released by a
    // Reset pulse and standing at TDC (RUN: standstill window, ordering check of the
    // limits, cam checks every call).
    macro_rules! cammonitor_row {
        ($($name:literal, $ty:ty, $tag:expr, $cycle:expr;)*) => {$(
            let mut fb = <$ty>::default();
            fb.wInputActive = SL_CAMMONITOR_ACTIVE_RESET
                | SL_CAMMONITOR_ACTIVE_POSITION
                | SL_CAMMONITOR_ACTIVE_PRESSSTARTED
                | SL_CAMMONITOR_ACTIVE_OVERRUNCAM
                | SL_CAMMONITOR_ACTIVE_UPWARDCAM;
            (fb.tStopDetectionTime, fb.tPressStartDelayTime, fb.tMoveDetectionTime) = (50, 200, 100);
            (fb.nAllowedPositionJitter, fb.nMinPositionChange, fb.nMaxPosition) = (4, 20, 8192);
            (fb.nTDC1LowerLimitFix, fb.nTDC1UpperLimitFix) = (8092, 100);
            (fb.nBDCLowerLimitFix, fb.nBDCUpperLimitFix, fb.nOverrunMaxFix) = (3896, 4296, 800);
            (fb.nPosition, fb.bOverrunCam, fb.bRun) = (50, 1, 1);
            fb.init();
            // The Reset pulse just before the measurement's clock starts at 1.
            for (t, reset) in [(u32::MAX - 2, 0), (u32::MAX - 1, 1), (u32::MAX, 0)] {
                fb.bReset = reset;
                fb.cycle(t);
            }
            assert_eq!(fb.nState, SL_STATE_RUN);
            let private = size_of_val(&fb.stPrivate);
            rows.push(measure(($name, $tag, timer), batches, fb, private, $cycle, |f| f.nState));
        )*};
    }
    use safelogic::blocks::motion::cammonitor::*;
    cammonitor_row! {
        "CAMMONITOR_UINT", FB_CAMMONITOR_UINT, SL_TYPE_CAMMONITOR_UINT, sl_cammonitor_uint_cycle;
        "CAMMONITOR_UDINT", FB_CAMMONITOR_UDINT, SL_TYPE_CAMMONITOR_UDINT, sl_cammonitor_udint_cycle;
    }

    // SLP: multi-turn, limits from the parameters, the position inside them (RUN).
    {
        use safelogic::blocks::motion::slp::*;
        let mut fb = FB_SLP {
            wInputActive: SL_SLP_ACTIVE_SAFEPOSVALID
                | SL_SLP_ACTIVE_SINGLETURNPOS
                | SL_SLP_ACTIVE_MULTITURNPOS,
            nMultiturnPosLLFix: -1,
            nMultiturnPosULFix: 1,
            ..Default::default()
        };
        (fb.bSafePosValid, fb.nSingleturnPos, fb.bRun) = (1, 5, 1);
        fb.init();
        let private = size_of_val(&fb.stPrivate);
        rows.push(measure(
            ("SLP", SL_TYPE_SLP, logic),
            batches,
            fb,
            private,
            sl_slp_cycle,
            |f| f.nState,
        ));
    }

    // SBT: no test requested, the longest interval counting down (SAFE; RemainingTime
    // updated every call).
    {
        use safelogic::blocks::motion::sbt::*;
        let mut fb = FB_SBT {
            wInputActive: SL_SBT_ACTIVE_SBT
                | SL_SBT_ACTIVE_SBCIN
                | SL_SBT_ACTIVE_SINGLETURNPOS
                | SL_SBT_ACTIVE_ACTCURRENTIQ,
            tBrakeTestInterval: SL_SBT_TIME_MAX,
            tMinDuration: 1_000,
            tMaxDuration: 20_000,
            nMaxPositionDeviation: 10,
            ..Default::default()
        };
        fb.bRun = 1;
        fb.init();
        let private = size_of_val(&fb.stPrivate);
        rows.push(measure(
            ("SBT", SL_TYPE_SBT, timer),
            batches,
            fb,
            private,
            sl_sbt_cycle,
            |f| f.nState,
        ));
    }

    // ADVPOSMON: enabled, referenced, coverage good (RUN, Active), restart sequence active.
    {
        use safelogic::blocks::motion::advposmon::*;
        let mut fb = FB_ADVPOSMON {
            wInputActive: SL_ADVPOSMON_ACTIVE_ENABLE | SL_ADVPOSMON_ACTIVE_RESTART,
            ..Default::default()
        };
        (fb.bEnable, fb.bPosRefOk, fb.bPosCheckOk, fb.bRun) = (1, 1, 1, 1);
        fb.init();
        let private = size_of_val(&fb.stPrivate);
        rows.push(measure(
            ("ADVPOSMON", SL_TYPE_ADVPOSMON, logic),
            batches,
            fb,
            private,
            sl_advposmon_cycle,
            |f| f.nState,
        ));
    }

    // CONNECTION_SHUTDOWN: Deactivate1 requests, the connection reports its shutdown (RUN).
    {
        let mut fb = FB_CONNECTION_SHUTDOWN {
            wInputActive: 0b01,
            nConnectionId: 7,
            ..Default::default()
        };
        (fb.bDeactivate1, fb.bConnShutdown, fb.bRun) = (1, 1, 1);
        fb.init();
        let private = size_of_val(&fb.stPrivate);
        rows.push(measure(
            ("CONNECTION_SHUTDOWN", SL_TYPE_CONNECTION_SHUTDOWN, logic),
            batches,
            fb,
            private,
            sl_connection_shutdown_cycle,
            |f| f.nState,
        ));
    }

    // Random inputs against steady ones (issue 13: no cliff off the fast path): the same
    // block timed with inputs drawn afresh before every call and with the same inputs
    // written before every call (so both time the writes), and the full cycle alone with
    // the steady inputs (what a random call costs without its randomness).
    // TON and TOF while their timer runs (a delay of 60,000 s outlasts every run): the
    // fast path serves a running timer until the call that reaches it.
    let timing = if only_instructions || child {
        Vec::new()
    } else {
        // Input active, the longest delay, running; two calls with the input TRUE (the
        // start-up call enters SAFE, the next one RUN or Timing), then the input at the
        // level the timer runs with, and the row.
        macro_rules! timing_row {
            ($name:literal, $ty:ty, $tag:expr, $input:ident = $level:expr, $cycle:ident) => {{
                let mut b = <$ty>::default();
                (b.wInputActive, b.tDelay, b.bRun, b.$input) = (1, SL_TIMER_DELAY_MAX, 1, 1);
                b.init();
                for t in 0..2 {
                    unsafe { $cycle(&mut b, t) };
                }
                b.$input = $level;
                let private = size_of_val(&b.stPrivate);
                measure(($name, $tag, timer), batches, b, private, $cycle, |f| {
                    f.nState
                })
            }};
        }
        vec![
            timing_row!("TON", FB_TON, SL_TYPE_TON, bTonIn1 = 1, sl_ton_cycle),
            timing_row!("TOF", FB_TOF, SL_TYPE_TOF, bTofIn1 = 0, sl_tof_cycle),
        ]
    };
    let cliff = if only_instructions || child {
        Vec::new()
    } else {
        cliff_rows(batches)
    };

    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into());
    println!(
        "safelogic per-block benchmark{}",
        if quick {
            " (smoke run: pass --bench for figures)"
        } else {
            ""
        }
    );
    println!("  CPU: {cpu}; {batches} batches x {CALLS_PER_BATCH} calls, steady inputs, 1 ms per call, through the C functions");
    let instr = |name: &str| match &instructions {
        Some(Ok(m)) => m
            .get(&format!("sl_{}_cycle", name.to_ascii_lowercase()))
            .map_or("-".to_string(), |n| format!("{n:.0}")),
        _ => "-".to_string(),
    };
    if let Some(Err(why)) = &instructions {
        println!("  instructions per call: not counted ({why})");
    }
    if only_instructions {
        println!("  {:<22} {:>10}", "block", "instr/call");
        let mut missing = Vec::new();
        for r in &rows {
            let n = instr(r.name);
            if n == "-" {
                missing.push(r.name);
            }
            println!("  {:<22} {:>10}", r.name, n);
        }
        // A row whose C function was not found in the profile is a fault of this bench
        // (a row name that is not the function's), not a figure.
        if !missing.is_empty() {
            eprintln!("no instruction count for: {}", missing.join(", "));
            std::process::exit(1);
        }
        every_type(SMOKE_BATCHES, true, true);
        return;
    }
    println!(
        "  {:<22} {:<10} {:>10} {:>10} {:>10} {:>7} {:>8} {:>9}  result",
        "block", "state", "median ns", "p99 ns", "instr/call", "size B", "priv. B", "target ns"
    );
    let line = |r: &Row, instr: String| {
        println!(
            "  {:<22} {:<10} {:>10.2} {:>10.2} {:>10} {:>7} {:>8} {:>9}  {}",
            r.name,
            state_name(r.ty, r.state),
            r.median,
            r.p99,
            instr,
            r.size,
            r.private,
            r.target,
            if r.median <= r.target { "PASS" } else { "MISS" }
        )
    };
    for r in &rows {
        line(r, instr(r.name));
    }
    if !timing.is_empty() {
        // The callgrind run counts per C function: these calls would mix with the steady
        // rows' calls of the same function, so they have no instruction count.
        println!(
            "  timers while timing (steady inputs, the delay not reached; no instruction count):"
        );
        for r in &timing {
            line(r, "-".into());
        }
    }
    if !cliff.is_empty() {
        println!("  random inputs against steady ones (inputs written before every call in both; \"full, steady\": the full cycle alone, never the fast path, with the steady inputs — what a random call costs without the randomness):");
        if let Some(Err(why)) = &random_instructions {
            println!("  instructions per random call: not counted ({why})");
        }
        println!(
            "  {:<9} {:>14} {:>14} {:>14} {:>14} {:>7} {:>14} {:>12}  result",
            "block",
            "steady median",
            "steady p99",
            "random median",
            "random p99",
            "ratio",
            "instr rnd (st)",
            "full, steady"
        );
        for c in &cliff {
            let ratio = c.random.0 / c.steady.0;
            // Per random call, and the steady row's count beside it.
            let random_instr = match &random_instructions {
                Some(Ok(m)) => m
                    .get(&format!("sl_{}_cycle", c.name.to_ascii_lowercase()))
                    .map_or("-".to_string(), |n| format!("{n:.0} ({})", instr(c.name))),
                _ => "-".to_string(),
            };
            println!(
                "  {:<9} {:>14.2} {:>14.2} {:>14.2} {:>14.2} {:>6.2}x {:>14} {:>12.2}  {} (target <= 2x)",
                c.name,
                c.steady.0,
                c.steady.1,
                c.random.0,
                c.random.1,
                ratio,
                random_instr,
                c.full,
                if ratio <= 2.0 { "PASS" } else { "MISS" }
            );
        }
    }
    if !child {
        every_type(batches, false, !quick);
    }
}

/// The every-type table (`all_types`): the instructions per steady call of every registered
/// type (callgrind, a child that makes only the steady calls) and, unless `only_instructions`,
/// the three timings, random against steady ("rnd/st") and against the same inputs written
/// first ("rnd/wr": both pay the stores), and the per cent of random calls that stay in the
/// running state; `count`: run callgrind (not in the smoke run). Exits non-zero when a
/// counted type's cycle function has no count.
fn every_type(batches: usize, only_instructions: bool, count: bool) {
    let calls = f64::from(WARMUP_CALLS) + (SMOKE_BATCHES as f64) * f64::from(CALLS_PER_BATCH);
    let instructions = if count {
        callgrind_per_call(ALL_CHILD, calls)
    } else {
        Err("smoke run".to_string())
    };
    let rows = all_types::run(
        (
            WARMUP_CALLS,
            if only_instructions { 1 } else { batches },
            CALLS_PER_BATCH,
        ),
        only_instructions,
    );
    println!(
        "every registered type ({}): each configured and brought to its running state (asserted: init SL_OK, every timed steady call SL_OK in that state)",
        rows.len()
    );
    if let Err(why) = &instructions {
        println!("  instructions per call: not counted ({why})");
    }
    if only_instructions {
        println!("  {:<24} {:<12} {:>10}", "block", "state", "instr/call");
    } else {
        println!(
            "  {:<24} {:<12} {:>9} {:>10} {:>9} {:>7} {:>7} {:>9} {:>10}",
            "block",
            "state",
            "steady ns",
            "written ns",
            "random ns",
            "rnd/st",
            "rnd/wr",
            "rnd run %",
            "instr/call"
        );
    }
    let mut missing = Vec::new();
    for r in &rows {
        let n = match &instructions {
            Ok(m) => m.get(r.cycle).map(|n| format!("{n:.0}")),
            Err(_) => Some("-".to_string()),
        };
        let n = n.unwrap_or_else(|| {
            missing.push(r.cycle);
            "-".to_string()
        });
        if only_instructions {
            println!("  {:<24} {:<12} {:>10}", r.name, r.state, n);
        } else {
            println!(
                "  {:<24} {:<12} {:>9.2} {:>10.2} {:>9.2} {:>6.2}x {:>6.2}x {:>9.0} {:>10}",
                r.name,
                r.state,
                r.ns[0],
                r.ns[1],
                r.ns[2],
                r.ns[2] / r.ns[0],
                r.ns[2] / r.ns[1],
                r.random_running,
                n
            );
        }
    }
    if !missing.is_empty() {
        eprintln!("no instruction count for: {}", missing.join(", "));
        std::process::exit(1);
    }
}

/// The blocks of the random-against-steady rows (`cliff_row`), each timed both ways, or only
/// with random inputs in the callgrind child that counts their instructions.
fn cliff_rows(batches: usize) -> Vec<Cliff> {
    // A row: the block with these parameters, bRun TRUE, initialised; a random word sets
    // the listed BOOL inputs from its bits 0, 1, … in order.
    macro_rules! row {
        ($name:literal, $ty:ident { $($p:ident: $v:expr),* }, $cycle:ident, [$($f:ident),+]) => {{
            let mut b = $ty {
                $($p: $v,)*
                bRun: 1,
                ..Default::default()
            };
            b.init();
            cliff_row($name, batches, b, $cycle, |f: &mut $ty, r: u64| {
                let mut bit = 0;
                $(
                    f.$f = (r >> bit & 1) as u8;
                    bit += 1;
                )+
                let _ = bit;
            })
        }};
    }
    vec![
        row!(
            "ESTOP",
            FB_ESTOP {
                wInputActive: 0b11,
                tDiscTime12: 20
            },
            sl_estop_cycle,
            [bEStopIn1, bEStopIn2, bRestart, bErrAck]
        ),
        row!(
            "MON",
            FB_MON {
                wInputActive: 0b11,
                tDiscTime12: 20
            },
            sl_mon_cycle,
            [bMonIn1, bMonIn2, bRestart, bErrAck]
        ),
        row!(
            "AND",
            FB_AND { wInputActive: 0b11 },
            sl_and_cycle,
            [bAndIn1, bAndIn2]
        ),
        row!(
            "OR",
            FB_OR { wInputActive: 0b11 },
            sl_or_cycle,
            [bOrIn1, bOrIn2]
        ),
        row!(
            "RS",
            FB_RS { wInputActive: 0b11 },
            sl_rs_cycle,
            [bReset, bSet]
        ),
        row!(
            "SR",
            FB_SR { wInputActive: 0b11 },
            sl_sr_cycle,
            [bReset, bSet]
        ),
        row!(
            "TON",
            FB_TON {
                wInputActive: 1,
                tDelay: 3
            },
            sl_ton_cycle,
            [bTonIn1]
        ),
        row!(
            "TOF",
            FB_TOF {
                wInputActive: 1,
                tDelay: 3
            },
            sl_tof_cycle,
            [bTofIn1]
        ),
    ]
}

/// Steady and random (median, p99) and full-cycle (median) ns per call of one block.
struct Cliff {
    name: &'static str,
    steady: (f64, f64),
    random: (f64, f64),
    /// The full cycle alone with the steady inputs (`envelope::cycle_full`: never the fast
    /// path), what a random call is measured against in docs/performance.md.
    full: f64,
}

/// What a timed batch of `cliff_row` calls.
#[derive(Clone, Copy, PartialEq)]
enum Calls {
    Steady,
    Random,
    Full,
}

/// Times `set` + `cycle` with a fixed input word (steady: the word that keeps the inputs
/// TRUE, Restart and ErrAck FALSE) and with a fresh random word before every call, and
/// `set` + the full cycle alone with the fixed word.
fn cliff_row<T: Copy + safelogic::base::envelope::Block>(
    name: &'static str,
    batches: usize,
    fb: T,
    cycle: unsafe extern "C" fn(*mut T, u32) -> i32,
    set: fn(&mut T, u64),
) -> Cliff {
    let f: unsafe extern "C" fn(*mut T, u32) -> i32 = black_box(cycle);
    let full: fn(&mut T, u32) -> Status = black_box(safelogic::base::envelope::cycle_full::<T>);
    let mut words = [0u64; 4096];
    let mut x = 0x9E37_79B9_7F4A_7C15u64;
    for w in words.iter_mut() {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        *w = x;
    }
    let run = |calls: Calls| {
        let mut fb = fb;
        let mut t = 0u32;
        let mut per_call = Vec::with_capacity(batches);
        let mut k = 0usize;
        for b in 0..batches + 1 {
            let start = Instant::now();
            for _ in 0..CALLS_PER_BATCH {
                t = t.wrapping_add(1);
                k = (k + 1) & 4095;
                let w = if calls == Calls::Random {
                    words[k]
                } else {
                    0b11
                };
                set(black_box(&mut fb), w);
                if calls == Calls::Full {
                    black_box(full(black_box(&mut fb), t));
                } else {
                    black_box(unsafe { f(black_box(&mut fb), t) });
                }
            }
            if b > 0 {
                per_call.push(start.elapsed().as_nanos() as f64 / f64::from(CALLS_PER_BATCH));
            }
        }
        per_call.sort_by(f64::total_cmp);
        let at = |q: f64| per_call[((per_call.len() - 1) as f64 * q).round() as usize];
        (at(0.5), at(0.99))
    };
    // The callgrind child counts the random calls alone.
    let (steady, full) = if std::env::args().any(|a| a == RANDOM_CHILD) {
        ((f64::NAN, f64::NAN), f64::NAN)
    } else {
        (run(Calls::Steady), run(Calls::Full).0)
    };
    let random = run(Calls::Random);
    Cliff {
        name,
        steady,
        random,
        full,
    }
}
