//! Cycle-time benchmark of FB_ESTOP and FB_MON through the C ABI (`sl_estop_cycle`,
//! `sl_mon_cycle`), self-timed with `std::time::Instant` (no criterion).
//!
//! Run with `cargo bench --bench cycle` (about 5 s). Run by `cargo test --all-targets`
//! (no `--bench` argument) it only does a short smoke run of every case.
//!
//! Each case is timed in batches of `CALLS_PER_BATCH` calls; the per-call time of a batch is
//! the batch time divided by the number of calls, and the table shows the median and the
//! 99th percentile of those per-batch figures. The calls go through a function pointer
//! hidden behind `black_box`, so they are real out-of-line calls with the C calling
//! convention, as from a C or PLC host linking `libsafelogic`; nothing is inlined into the
//! timing loop.
//!
//! The figures are reported next to the project's targets; the bench never fails on them.

use safelogic::ffi::{sl_estop_cycle, sl_estop_init, sl_mon_cycle, sl_mon_init};
use safelogic::*;
use std::hint::black_box;
use std::mem::size_of;
use std::time::Instant;

type EstopCycleFn = unsafe extern "C" fn(*mut FB_ESTOP, u32) -> i32;
type MonCycleFn = unsafe extern "C" fn(*mut FB_MON, u32) -> i32;

const CALLS_PER_BATCH: usize = 1000;
/// Length of the pre-generated random input table (a power of two).
const TABLE_LEN: usize = 1 << 14;

const TARGET_STEADY_NS: f64 = 5.0;
const TARGET_RANDOM_NS: f64 = 25.0;
const TARGET_PRIVATE_BYTES: usize = 128;

/// How much work one run does.
#[derive(Clone, Copy)]
struct Plan {
    warmup_batches: usize,
    batches: usize,
}

const FULL: Plan = Plan {
    warmup_batches: 300,
    batches: 5000,
};
const SMOKE: Plan = Plan {
    warmup_batches: 2,
    batches: 20,
};

// ---------------------------------------------------------------------------------------
// Random inputs
// ---------------------------------------------------------------------------------------

/// xorshift64 (Marsaglia); deterministic, so every run uses the same input table.
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }

    /// TRUE with probability 1/n.
    fn one_in(&mut self, n: u64) -> bool {
        self.next() % n == 0
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    /// One step of a two-state Markov chain on a BOOL byte: a TRUE byte falls with
    /// probability 1/`fall`, a FALSE one rises with probability 1/`rise`.
    fn walk(&mut self, b: &mut u8, fall: u64, rise: u64) {
        if *b == 1 {
            if self.one_in(fall) {
                *b = 0;
            }
        } else if self.one_in(rise) {
            *b = 1;
        }
    }
}

/// The input bytes of one cycle and the time step before it.
#[derive(Clone, Copy, Default)]
struct Inputs {
    /// Safety inputs 1-6 (ESTOP: EStopIn1-6; MON: MonIn1-4, Secure1, Secure2).
    safety: [u8; 6],
    restart: u8,
    edm1: u8,
    edm2: u8,
    errack: u8,
    run: u8,
    /// Milliseconds to add to the clock before this cycle.
    dt: u8,
}

/// A random walk over the input bytes, each BOOL a two-state Markov chain: the channels of
/// a pair usually switch together, but now and then one channel switches alone and comes
/// back later (short ones stay inside the discrepancy time, long ones are discrepancy
/// errors); Restart and ErrAck are short pulses at random times; EDM1/EDM2 are mostly TRUE
/// with short FALSE periods at random times (so restarts sometimes meet a FALSE EDM, and
/// the EDM reset time is sometimes missed); Run drops rarely and briefly; about one cycle in
/// 500 carries an invalid BOOL byte (2..=255) in one field. The clock advances by 0-2 ms per
/// cycle.
fn random_table(seed: u64) -> Vec<Inputs> {
    let mut rng = XorShift(seed);
    let mut cur = Inputs {
        safety: [1; 6],
        edm1: 1,
        edm2: 1,
        run: 1,
        ..Inputs::default()
    };
    let mut table = Vec::with_capacity(TABLE_LEN);
    for _ in 0..TABLE_LEN {
        for pair in 0..3 {
            let (a, b) = (2 * pair, 2 * pair + 1);
            if cur.safety[a] == cur.safety[b] {
                let mut v = cur.safety[a];
                rng.walk(&mut v, 400, 40);
                if v != cur.safety[a] {
                    // Both channels switch; one of them may lag a cycle or two.
                    let lag = rng.below(3);
                    cur.safety[a] = v;
                    if lag == 0 {
                        cur.safety[b] = v;
                    }
                } else if rng.one_in(1500) {
                    let ch = if rng.one_in(2) { a } else { b };
                    cur.safety[ch] = 1 - cur.safety[ch];
                }
            } else if rng.one_in(8) {
                // The other channel follows (usually well inside the discrepancy time).
                cur.safety[a] = cur.safety[b].max(cur.safety[a]);
                cur.safety[b] = cur.safety[a];
            }
        }
        rng.walk(&mut cur.restart, 8, 40);
        rng.walk(&mut cur.edm1, 150, 5);
        rng.walk(&mut cur.edm2, 150, 5);
        rng.walk(&mut cur.errack, 5, 120);
        rng.walk(&mut cur.run, 8000, 20);
        cur.dt = rng.below(3) as u8;
        let mut row = cur;
        if rng.one_in(500) {
            let bad = 2 + rng.below(254) as u8;
            match rng.below(9) {
                k @ 0..=5 => row.safety[k as usize] = bad,
                6 => row.restart = bad,
                7 => row.edm1 = bad,
                _ => row.errack = bad,
            }
        }
        table.push(row);
    }
    table
}

// ---------------------------------------------------------------------------------------
// Block configurations
// ---------------------------------------------------------------------------------------

/// ESTOP with three two-channel pairs (EStopIn1-6), EDM1 and EDM2 (EDM1 with a reset time),
/// a delayed output and "Safe Inputs after Disc Error": most of the machine is in use.
fn estop_config() -> FB_ESTOP {
    FB_ESTOP {
        wInputActive: 0x3F,
        tDiscTime12: 20,
        tDiscTime34: 20,
        tDiscTime56: 20,
        tEDM1ResetTime: 500,
        tEStopDelOutDelay: 10,
        dwOptions: SL_OPT_EDM1 | SL_OPT_EDM2 | SL_OPT_SAFE_INPUTS_AFTER_DISC,
        ..FB_ESTOP::default()
    }
}

/// MON with MonIn1-4 as two pairs, the Secure pair (make contacts, so the mostly-TRUE random
/// bytes rarely bypass the MonIn inputs), manual restart, EDM1 and EDM2, a delayed output (so
/// ERRORDELAY is reachable) and "Safe Inputs after Disc Error".
fn mon_config() -> FB_MON {
    FB_MON {
        wInputActive: 0x3F,
        wInputNegated: 0x30,
        tDiscTime12: 20,
        tDiscTime34: 20,
        tDiscTimeSecure12: 20,
        tEDM1ResetTime: 500,
        tMonDelOutDelay: 10,
        dwOptions: SL_OPT_EDM1
            | SL_OPT_EDM2
            | SL_OPT_SAFE_INPUTS_AFTER_DISC
            | SL_OPT_MANUAL_RESTART,
        ..FB_MON::default()
    }
}

/// Brings a block into RUN with all inputs TRUE: Run, Restart pulse, then the contactors
/// pick up (EDM FALSE). Returns the clock after the last call.
fn estop_to_run(fb: &mut FB_ESTOP) -> u32 {
    assert_eq!(unsafe { sl_estop_init(fb) }, SL_OK);
    fb.bRun = 1;
    fb.bEDM1 = 1;
    fb.bEDM2 = 1;
    fb.bEStopIn1 = 1;
    fb.bEStopIn2 = 1;
    fb.bEStopIn3 = 1;
    fb.bEStopIn4 = 1;
    fb.bEStopIn5 = 1;
    fb.bEStopIn6 = 1;
    let mut t = 0;
    for restart in [0, 1, 0] {
        fb.bRestart = restart;
        t += 1;
        assert_eq!(unsafe { sl_estop_cycle(fb, t) }, SL_OK);
    }
    fb.bEDM1 = 0;
    fb.bEDM2 = 0;
    t += 1;
    assert_eq!(unsafe { sl_estop_cycle(fb, t) }, SL_OK);
    assert_eq!(fb.nState, SL_STATE_RUN, "ESTOP did not reach RUN");
    t
}

fn mon_to_run(fb: &mut FB_MON) -> u32 {
    assert_eq!(unsafe { sl_mon_init(fb) }, SL_OK);
    fb.bRun = 1;
    fb.bEDM1 = 1;
    fb.bEDM2 = 1;
    fb.bMonIn1 = 1;
    fb.bMonIn2 = 1;
    fb.bMonIn3 = 1;
    fb.bMonIn4 = 1;
    fb.bSecure1 = 1; // make contacts: raw 1 = logically FALSE, no bypass
    fb.bSecure2 = 1;
    let mut t = 0;
    for restart in [0, 1, 0] {
        fb.bRestart = restart;
        t += 1;
        assert_eq!(unsafe { sl_mon_cycle(fb, t) }, SL_OK);
    }
    fb.bEDM1 = 0;
    fb.bEDM2 = 0;
    t += 1;
    assert_eq!(unsafe { sl_mon_cycle(fb, t) }, SL_OK);
    assert_eq!(fb.nState, SL_STATE_RUN, "MON did not reach RUN");
    t
}

#[inline(always)]
fn apply_estop(fb: &mut FB_ESTOP, i: &Inputs) {
    fb.bEStopIn1 = i.safety[0];
    fb.bEStopIn2 = i.safety[1];
    fb.bEStopIn3 = i.safety[2];
    fb.bEStopIn4 = i.safety[3];
    fb.bEStopIn5 = i.safety[4];
    fb.bEStopIn6 = i.safety[5];
    fb.bRestart = i.restart;
    fb.bEDM1 = i.edm1;
    fb.bEDM2 = i.edm2;
    fb.bErrAck = i.errack;
    fb.bRun = i.run;
}

#[inline(always)]
fn apply_mon(fb: &mut FB_MON, i: &Inputs) {
    fb.bMonIn1 = i.safety[0];
    fb.bMonIn2 = i.safety[1];
    fb.bMonIn3 = i.safety[2];
    fb.bMonIn4 = i.safety[3];
    fb.bSecure1 = i.safety[4];
    fb.bSecure2 = i.safety[5];
    fb.bRestart = i.restart;
    fb.bEDM1 = i.edm1;
    fb.bEDM2 = i.edm2;
    fb.bErrAck = i.errack;
    fb.bRun = i.run;
}

// ---------------------------------------------------------------------------------------
// Timing
// ---------------------------------------------------------------------------------------

/// Per-call times (ns) of `plan.batches` batches; `batch` runs one batch of
/// `CALLS_PER_BATCH` calls.
fn measure(plan: Plan, mut batch: impl FnMut()) -> Vec<f64> {
    for _ in 0..plan.warmup_batches {
        batch();
    }
    let mut per_call = Vec::with_capacity(plan.batches);
    for _ in 0..plan.batches {
        let start = Instant::now();
        batch();
        let ns = start.elapsed().as_nanos() as f64;
        per_call.push(ns / CALLS_PER_BATCH as f64);
    }
    per_call
}

struct Stats {
    median: f64,
    p99: f64,
    min: f64,
}

fn stats(mut v: Vec<f64>) -> Stats {
    v.sort_by(|a, b| a.total_cmp(b));
    let at = |q: f64| v[((v.len() - 1) as f64 * q).round() as usize];
    Stats {
        median: at(0.5),
        p99: at(0.99),
        min: v[0],
    }
}

/// Histogram of the states a block passes through over one pass of the random table.
struct StateMix([u64; 10]);

impl StateMix {
    fn describe(&self) -> String {
        let total: u64 = self.0.iter().sum();
        let mut parts = Vec::new();
        for (state, &n) in self.0.iter().enumerate() {
            if n > 0 {
                parts.push(format!(
                    "{} {:.1}%",
                    state_name(state as u8),
                    100.0 * n as f64 / total as f64
                ));
            }
        }
        parts.join(", ")
    }
}

fn state_name(state: u8) -> String {
    safelogic::state_name(SL_TYPE_MON, state).to_string()
}

fn estop_state_mix(table: &[Inputs]) -> StateMix {
    let mut fb = estop_config();
    let mut t = estop_to_run(&mut fb);
    let mut mix = StateMix([0; 10]);
    for row in table {
        apply_estop(&mut fb, row);
        t = t.wrapping_add(u32::from(row.dt));
        unsafe { sl_estop_cycle(&mut fb, t) };
        mix.0[usize::from(fb.nState).min(9)] += 1;
    }
    mix
}

fn mon_state_mix(table: &[Inputs]) -> StateMix {
    let mut fb = mon_config();
    let mut t = mon_to_run(&mut fb);
    let mut mix = StateMix([0; 10]);
    for row in table {
        apply_mon(&mut fb, row);
        t = t.wrapping_add(u32::from(row.dt));
        unsafe { sl_mon_cycle(&mut fb, t) };
        mix.0[usize::from(fb.nState).min(9)] += 1;
    }
    mix
}

fn bench_estop_steady(plan: Plan) -> Stats {
    let f: EstopCycleFn = black_box(sl_estop_cycle);
    let mut fb = estop_config();
    let mut t = estop_to_run(&mut fb);
    let mut bad = 0u32;
    let v = measure(plan, || {
        let p: *mut FB_ESTOP = black_box(&mut fb);
        for _ in 0..CALLS_PER_BATCH {
            t = t.wrapping_add(1);
            bad |= black_box(unsafe { f(p, t) }) as u32;
        }
    });
    assert_eq!(bad, 0, "steady ESTOP returned a non-OK status");
    assert_eq!(fb.nState, SL_STATE_RUN, "steady ESTOP left RUN");
    stats(v)
}

fn bench_mon_steady(plan: Plan) -> Stats {
    let f: MonCycleFn = black_box(sl_mon_cycle);
    let mut fb = mon_config();
    let mut t = mon_to_run(&mut fb);
    let mut bad = 0u32;
    let v = measure(plan, || {
        let p: *mut FB_MON = black_box(&mut fb);
        for _ in 0..CALLS_PER_BATCH {
            t = t.wrapping_add(1);
            bad |= black_box(unsafe { f(p, t) }) as u32;
        }
    });
    assert_eq!(bad, 0, "steady MON returned a non-OK status");
    assert_eq!(fb.nState, SL_STATE_RUN, "steady MON left RUN");
    stats(v)
}

fn bench_estop_random(plan: Plan, table: &[Inputs]) -> Stats {
    let f: EstopCycleFn = black_box(sl_estop_cycle);
    let mut fb = estop_config();
    let mut t = estop_to_run(&mut fb);
    let mut k = 0usize;
    let v = measure(plan, || {
        let fb: &mut FB_ESTOP = black_box(&mut fb);
        for _ in 0..CALLS_PER_BATCH {
            let row = &table[k & (TABLE_LEN - 1)];
            k = k.wrapping_add(1);
            apply_estop(fb, row);
            t = t.wrapping_add(u32::from(row.dt));
            black_box(unsafe { f(fb, t) });
        }
    });
    stats(v)
}

fn bench_mon_random(plan: Plan, table: &[Inputs]) -> Stats {
    let f: MonCycleFn = black_box(sl_mon_cycle);
    let mut fb = mon_config();
    let mut t = mon_to_run(&mut fb);
    let mut k = 0usize;
    let v = measure(plan, || {
        let fb: &mut FB_MON = black_box(&mut fb);
        for _ in 0..CALLS_PER_BATCH {
            let row = &table[k & (TABLE_LEN - 1)];
            k = k.wrapping_add(1);
            apply_mon(fb, row);
            t = t.wrapping_add(u32::from(row.dt));
            black_box(unsafe { f(fb, t) });
        }
    });
    stats(v)
}

/// Reference: the random-input loop without the block call (table read, input copy, clock),
/// so the cost of the call itself can be told from the loop around it.
fn bench_loop_only(plan: Plan, table: &[Inputs]) -> Stats {
    let mut fb = estop_config();
    let mut t = 0u32;
    let mut k = 0usize;
    let v = measure(plan, || {
        let fb: &mut FB_ESTOP = black_box(&mut fb);
        for _ in 0..CALLS_PER_BATCH {
            let row = &table[k & (TABLE_LEN - 1)];
            k = k.wrapping_add(1);
            apply_estop(fb, row);
            t = t.wrapping_add(u32::from(row.dt));
            black_box(t);
            black_box(&mut *fb);
        }
    });
    stats(v)
}

// ---------------------------------------------------------------------------------------
// Report
// ---------------------------------------------------------------------------------------

fn cpu_model() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name") || l.starts_with("Model"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.trim().to_string())
        })
        .unwrap_or_else(|| "unknown (no /proc/cpuinfo)".to_string());
    let cpus = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(0);
    format!("{model} ({cpus} logical CPUs available)")
}

fn verdict(ok: bool) -> &'static str {
    if ok {
        "PASS"
    } else {
        "MISS"
    }
}

fn row(case: &str, s: &Stats, target: Option<f64>, full: bool) {
    let (t, v) = match target {
        Some(t) if full => (format!("<= {t:.0} ns"), verdict(s.median <= t)),
        Some(t) => (format!("<= {t:.0} ns"), "(smoke run)"),
        None => ("-".to_string(), ""),
    };
    println!(
        "  {case:<36} {:>8.2} {:>8.2} {:>8.2}   {t:<10} {v}",
        s.median, s.p99, s.min
    );
}

fn main() {
    let full = std::env::args().any(|a| a == "--bench");
    let plan = if full { FULL } else { SMOKE };

    println!("safelogic cycle benchmark: sl_estop_cycle / sl_mon_cycle through the C ABI");
    println!("  CPU      : {}", cpu_model());
    println!(
        "  method   : {} batches x {} calls per case after {} warm-up batches; per-call time = \
         batch time / {}",
        plan.batches, CALLS_PER_BATCH, plan.warmup_batches, CALLS_PER_BATCH
    );
    println!(
        "             calls through an opaque extern \"C\" fn pointer (out-of-line, as from C)"
    );
    if !full {
        println!(
            "  SMOKE RUN (not started by `cargo bench`, debug build?): the figures mean nothing"
        );
    }

    let private = size_of::<SL_GUARD_PRIVATE>();
    println!(
        "  sizes    : sizeof(FB_ESTOP) = {} B, sizeof(FB_MON) = {} B, private state \
         SL_GUARD_PRIVATE = {} B (target <= {} B: {})",
        size_of::<FB_ESTOP>(),
        size_of::<FB_MON>(),
        private,
        TARGET_PRIVATE_BYTES,
        verdict(private <= TARGET_PRIVATE_BYTES)
    );
    println!("  config   : ESTOP EStopIn1-6 (3 pairs, disc 20 ms), EDM1 (reset time 500 ms) + EDM2, delay 10 ms;");
    println!("             MON MonIn1-4 (2 pairs) + Secure1/2 pair (make contacts; disc 20 ms), manual restart, EDM1 (500 ms) + EDM2, delay 10 ms");

    let table = random_table(0x5AFE_1061_C0DE_2024);
    let estop_mix = estop_state_mix(&table);
    let mon_mix = mon_state_mix(&table);

    let es = bench_estop_steady(plan);
    let ms = bench_mon_steady(plan);
    let er = bench_estop_random(plan, &table);
    let mr = bench_mon_random(plan, &table);
    let lo = bench_loop_only(plan, &table);

    println!();
    println!(
        "  {:<36} {:>8} {:>8} {:>8}   {:<10} result",
        "case", "median", "p99", "min", "target"
    );
    println!(
        "  {:<36} {:>8} {:>8} {:>8}",
        "", "ns/call", "ns/call", "ns/call"
    );
    println!("  {}", "-".repeat(84));
    row(
        "FB_ESTOP steady (RUN, no change)",
        &es,
        Some(TARGET_STEADY_NS),
        full,
    );
    row(
        "FB_MON   steady (RUN, no change)",
        &ms,
        Some(TARGET_STEADY_NS),
        full,
    );
    row("FB_ESTOP random inputs", &er, Some(TARGET_RANDOM_NS), full);
    row("FB_MON   random inputs", &mr, Some(TARGET_RANDOM_NS), full);
    row("(ref.) random-input loop, no call", &lo, None, full);
    println!("  {}", "-".repeat(84));
    println!(
        "  random input table: {TABLE_LEN} cycles (random walk incl. Restart, ErrAck, EDM1/2, \
         Run, ~0.2% invalid BOOL bytes, 0-2 ms per cycle), replayed cyclically"
    );
    println!("  states visited, ESTOP: {}", estop_mix.describe());
    println!("  states visited, MON  : {}", mon_mix.describe());
    println!(
        "  The random rows include the loop around the call (table read, 11 input byte \
         writes, clock), shown alone in the (ref.) row."
    );
    println!(
        "  p99 is the 99th percentile of per-batch averages (one batch = {CALLS_PER_BATCH} calls), \
         not of single calls."
    );
    println!("  Targets are reported, not enforced: this bench always exits 0.");
}
