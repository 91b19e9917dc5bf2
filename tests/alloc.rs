//! ABI.md §4: "A call is total: no input, pointer or parameter value may cause undefined
//! behaviour, a panic, an abort or an allocation."
//!
//! This test installs a counting global allocator and proves that `sl_estop_init`,
//! `sl_estop_cycle`, `sl_mon_init` and `sl_mon_cycle` (called through the C ABI functions)
//! never allocate, over many cycles with varying inputs and through every error path:
//! invalid BOOL bytes, corrupted private state, the clock going backwards, changed and
//! invalid parameters, NULL and misaligned instance pointers.
//!
//! Only the allocations made by the thread that runs the calls, and only between the
//! reads of the counter right before and right after each call, are attributed to that
//! call: the test harness runs tests in parallel threads, and their allocations must not
//! count. The first test shows that the counter does see an allocation.

use safelogic::ffi::{
    sl_estop_cycle, sl_estop_init, sl_mon_cycle, sl_mon_init, sl_state_str, sl_status_str,
};
use safelogic::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;
use std::ptr;

// ---------------------------------------------------------------------------------------
// Counting allocator
// ---------------------------------------------------------------------------------------

thread_local! {
    // Const-initialised Cells need no lazy initialisation and no destructor, so touching
    // them inside the allocator cannot itself allocate or recurse. Both are per thread: the
    // test harness runs tests in parallel, and another test's allocations must not count.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    /// Heap operations (alloc, alloc_zeroed, realloc, dealloc) of this thread while counting.
    static HEAP_OPS: Cell<usize> = const { Cell::new(0) };
}

struct CountingAlloc;

impl CountingAlloc {
    #[inline]
    fn note(&self) {
        if COUNTING.try_with(Cell::get).unwrap_or(false) {
            let _ = HEAP_OPS.try_with(|n| n.set(n.get() + 1));
        }
    }
}

unsafe impl GlobalAlloc for CountingAlloc {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        self.note();
        System.alloc(layout)
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        self.note();
        System.alloc_zeroed(layout)
    }
    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        self.note();
        System.realloc(p, layout, new_size)
    }
    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        self.note();
        System.dealloc(p, layout)
    }
}

#[global_allocator]
static GLOBAL: CountingAlloc = CountingAlloc;

/// Switches counting on for the current thread while alive.
struct Counting;

impl Counting {
    fn on() -> Self {
        COUNTING.with(|c| c.set(true));
        Counting
    }
}

impl Drop for Counting {
    fn drop(&mut self) {
        COUNTING.with(|c| c.set(false));
    }
}

/// Runs `f` and returns its result with the number of heap operations it made.
#[inline(always)]
fn heap_ops<R>(f: impl FnOnce() -> R) -> (R, usize) {
    let before = HEAP_OPS.with(Cell::get);
    let r = f();
    let after = HEAP_OPS.with(Cell::get);
    (r, after - before)
}

// ---------------------------------------------------------------------------------------
// The counter works
// ---------------------------------------------------------------------------------------

#[test]
fn counter_sees_an_allocation() {
    let _on = Counting::on();
    let (v, n) = heap_ops(|| black_box(Vec::<u64>::with_capacity(16)));
    assert_eq!(n, 1, "Vec::with_capacity(16) must count as one allocation");
    let (_, n) = heap_ops(|| drop(v));
    assert_eq!(n, 1, "dropping the Vec must count as one deallocation");
    let (b, n) = heap_ops(|| black_box(Box::new([0u8; 64])));
    assert_eq!(n, 1);
    drop(b);
    // And the same closure shape as the block calls below counts nothing when nothing
    // allocates.
    let (_, n) = heap_ops(|| black_box(1u32) + 1);
    assert_eq!(n, 0);
}

// ---------------------------------------------------------------------------------------
// The block calls
// ---------------------------------------------------------------------------------------

/// xorshift64: deterministic varying inputs.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }
    fn one_in(&mut self, n: u64) -> bool {
        self.next() % n == 0
    }
    /// Random-walk step of a BOOL byte (falls with 1/`fall`, rises with 1/`rise`).
    fn walk(&mut self, b: &mut u8, fall: u64, rise: u64) {
        let flip = if *b == 1 {
            self.one_in(fall)
        } else {
            self.one_in(rise)
        };
        if flip {
            *b = u8::from(*b != 1);
        }
    }
}

/// Which function a heap operation would be attributed to.
#[derive(Clone, Copy)]
enum Func {
    EstopInit,
    EstopCycle,
    MonInit,
    MonCycle,
    StatusStr,
    StateStr,
}

const FUNC_NAMES: [&str; 6] = [
    "sl_estop_init",
    "sl_estop_cycle",
    "sl_mon_init",
    "sl_mon_cycle",
    "sl_status_str",
    "sl_state_str",
];

/// Statistics kept in fixed arrays (no allocation inside the counting window).
struct Tally {
    /// Heap operations per function.
    ops: [usize; 6],
    /// Calls per function.
    calls: [u64; 6],
    /// Status codes seen per block (index = -status, 0..=8).
    status: [[u64; 9]; 2],
    /// States seen per block (index = nState, 0..=9).
    states: [[u64; 10]; 2],
}

impl Tally {
    fn call(&mut self, f: Func, g: impl FnOnce() -> i32) -> i32 {
        let (rc, n) = heap_ops(g);
        self.ops[f as usize] += n;
        self.calls[f as usize] += 1;
        let block = match f {
            Func::EstopInit | Func::EstopCycle => 0,
            _ => 1,
        };
        let idx = usize::try_from(-i64::from(rc)).unwrap_or(usize::MAX);
        assert!(idx < 9, "unexpected status {rc}");
        self.status[block][idx] += 1;
        rc
    }

    fn texts(&mut self, rc: i32, state: u8) {
        let (p, n) = heap_ops(|| sl_status_str(rc));
        assert!(!p.is_null());
        self.ops[Func::StatusStr as usize] += n;
        self.calls[Func::StatusStr as usize] += 1;
        let (p, n) = heap_ops(|| sl_state_str(SL_TYPE_MON, state));
        assert!(!p.is_null());
        self.ops[Func::StateStr as usize] += n;
        self.calls[Func::StateStr as usize] += 1;
    }
}

fn estop_params() -> FB_ESTOP {
    FB_ESTOP {
        wInputActive: 0x0F,
        tDiscTime12: 20,
        tDiscTime34: 20,
        tEDM1ResetTime: 200,
        tEStopDelOutDelay: 10,
        dwOptions: SL_OPT_EDM1 | SL_OPT_EDM2 | SL_OPT_SAFE_INPUTS_AFTER_DISC,
        ..FB_ESTOP::default()
    }
}

fn mon_params() -> FB_MON {
    FB_MON {
        wInputActive: 0x3F,
        wInputNegated: 0x30,
        tDiscTime12: 20,
        tDiscTime34: 20,
        tDiscTimeSecure12: 20,
        tEDM1ResetTime: 200,
        tMonDelOutDelay: 10,
        dwOptions: SL_OPT_EDM1
            | SL_OPT_EDM2
            | SL_OPT_SAFE_INPUTS_AFTER_DISC
            | SL_OPT_MANUAL_RESTART,
        ..FB_MON::default()
    }
}

/// Input bytes of one cycle; `inputs` are the safety inputs (ESTOP: EStopIn1-4;
/// MON: MonIn1-4, Secure1-2 as make contacts).
#[derive(Clone, Copy)]
struct Plant {
    inputs: [u8; 6],
    restart: u8,
    edm: [u8; 2],
    errack: u8,
    run: u8,
}

impl Plant {
    fn step(&mut self, rng: &mut Rng) {
        for pair in 0..3 {
            let (a, b) = (2 * pair, 2 * pair + 1);
            if self.inputs[a] == self.inputs[b] {
                let mut v = self.inputs[a];
                rng.walk(&mut v, 300, 30);
                self.inputs[a] = v;
                if !rng.one_in(3) {
                    self.inputs[b] = v;
                } else if rng.one_in(500) {
                    self.inputs[b] ^= 1;
                }
            } else if rng.one_in(6) {
                self.inputs[b] = self.inputs[a];
            }
        }
        rng.walk(&mut self.restart, 8, 40);
        rng.walk(&mut self.edm[0], 150, 5);
        rng.walk(&mut self.edm[1], 150, 5);
        rng.walk(&mut self.errack, 5, 100);
        rng.walk(&mut self.run, 5000, 20);
    }
}

/// One random invalid BOOL byte (2..=255) in one of the input fields, or none.
fn corrupt_bool(rng: &mut Rng, bytes: &mut [&mut u8]) {
    if rng.one_in(50) {
        let k = (rng.next() % bytes.len() as u64) as usize;
        *bytes[k] = 2 + (rng.next() % 254) as u8;
    }
}

const CYCLES: u32 = 200_000;

#[test]
fn no_allocation_in_init_and_cycle() {
    let mut rng = Rng(0x0A11_0C47_10D5_EED5);
    let mut tally = Tally {
        ops: [0; 6],
        calls: [0; 6],
        status: [[0; 9]; 2],
        states: [[0; 10]; 2],
    };
    let mut estop = estop_params();
    let mut mon = mon_params();
    let mut plant = Plant {
        inputs: [1, 1, 1, 1, 1, 1],
        restart: 0,
        edm: [1, 1],
        errack: 0,
        run: 1,
    };
    // Storage for a misaligned instance pointer (never dereferenced by the library).
    let mut raw = [0u64; 40];
    let misaligned_estop = raw
        .as_mut_ptr()
        .cast::<u8>()
        .wrapping_add(1)
        .cast::<FB_ESTOP>();
    let misaligned_mon = raw
        .as_mut_ptr()
        .cast::<u8>()
        .wrapping_add(3)
        .cast::<FB_MON>();

    let on = Counting::on();

    tally.call(Func::EstopInit, || unsafe { sl_estop_init(&mut estop) });
    tally.call(Func::MonInit, || unsafe { sl_mon_init(&mut mon) });

    let mut t: u32 = u32::MAX - 50_000; // the clock wraps during the run
    for i in 0..CYCLES {
        t = t.wrapping_add((rng.next() % 3) as u32);
        plant.step(&mut rng);

        // ---- inputs, with an occasional invalid BOOL byte
        estop.bEStopIn1 = plant.inputs[0];
        estop.bEStopIn2 = plant.inputs[1];
        estop.bEStopIn3 = plant.inputs[2];
        estop.bEStopIn4 = plant.inputs[3];
        estop.bRestart = plant.restart;
        estop.bEDM1 = plant.edm[0];
        estop.bEDM2 = plant.edm[1];
        estop.bErrAck = plant.errack;
        estop.bRun = plant.run;
        mon.bMonIn1 = plant.inputs[0];
        mon.bMonIn2 = plant.inputs[1];
        mon.bMonIn3 = plant.inputs[2];
        mon.bMonIn4 = plant.inputs[3];
        mon.bSecure1 = plant.inputs[4];
        mon.bSecure2 = plant.inputs[5];
        mon.bRestart = plant.restart;
        mon.bEDM1 = plant.edm[0];
        mon.bEDM2 = plant.edm[1];
        mon.bErrAck = plant.errack;
        mon.bRun = plant.run;
        corrupt_bool(
            &mut rng,
            &mut [
                &mut estop.bEStopIn1,
                &mut estop.bEStopIn4,
                &mut estop.bRestart,
                &mut estop.bEDM1,
                &mut estop.bErrAck,
                &mut estop.bRun,
            ],
        );
        corrupt_bool(
            &mut rng,
            &mut [
                &mut mon.bMonIn2,
                &mut mon.bSecure1,
                &mut mon.bRestart,
                &mut mon.bEDM2,
                &mut mon.bErrAck,
                &mut mon.bRun,
            ],
        );

        // ---- fault injection
        let mut tn = t;
        match i % 1000 {
            // corrupted private state (a header byte, then a latched time)
            101 => estop.stPrivate.stHeader.nState ^= 0x5A,
            102 => mon.stPrivate.stHeader.nFlags ^= 0x81,
            303 => estop.stPrivate.adwTime[0] ^= 0x0100,
            304 => mon.stPrivate.stHeader.wAux ^= 0x0010,
            // clock backwards (only for this call; the next call is forwards again)
            505 => tn = t.wrapping_sub(1000),
            // a parameter changed while running, restored two cycles later
            707 => {
                estop.tDiscTime12 += 5;
                mon.tMonDelOutDelay += 5;
            }
            709 => {
                estop.tDiscTime12 -= 5;
                mon.tMonDelOutDelay -= 5;
            }
            // invalid parameters: init refuses them (SL_E_CONFIG), cycles report it, then
            // the valid set is restored and latched again
            850 => {
                estop.wInputActive = 0;
                mon.tDiscTime34 = 70_000;
                tally.call(Func::EstopInit, || unsafe { sl_estop_init(&mut estop) });
                tally.call(Func::MonInit, || unsafe { sl_mon_init(&mut mon) });
            }
            860 => {
                estop.wInputActive = estop_params().wInputActive;
                mon.tDiscTime34 = mon_params().tDiscTime34;
                tally.call(Func::EstopInit, || unsafe { sl_estop_init(&mut estop) });
                tally.call(Func::MonInit, || unsafe { sl_mon_init(&mut mon) });
            }
            // a never-initialised instance (all-zero private state) mid-run
            920 => {
                estop.stPrivate = SL_GUARD_PRIVATE::default();
                mon.stPrivate = SL_GUARD_PRIVATE::default();
            }
            _ => {}
        }

        // ---- the calls
        let rc = tally.call(Func::EstopCycle, || unsafe {
            sl_estop_cycle(&mut estop, tn)
        });
        tally.texts(rc, estop.nState);
        let rc = tally.call(Func::MonCycle, || unsafe { sl_mon_cycle(&mut mon, tn) });
        tally.texts(rc, mon.nState);
        tally.states[0][usize::from(estop.nState).min(9)] += 1;
        tally.states[1][usize::from(mon.nState).min(9)] += 1;

        // ---- NULL and misaligned instance pointers
        if i % 97 == 0 {
            tally.call(Func::EstopInit, || unsafe {
                sl_estop_init(ptr::null_mut())
            });
            tally.call(Func::EstopCycle, || unsafe {
                sl_estop_cycle(ptr::null_mut(), tn)
            });
            tally.call(Func::MonInit, || unsafe { sl_mon_init(ptr::null_mut()) });
            tally.call(Func::MonCycle, || unsafe {
                sl_mon_cycle(ptr::null_mut(), tn)
            });
            tally.call(Func::EstopInit, || unsafe {
                sl_estop_init(misaligned_estop)
            });
            tally.call(Func::EstopCycle, || unsafe {
                sl_estop_cycle(misaligned_estop, tn)
            });
            tally.call(Func::MonInit, || unsafe { sl_mon_init(misaligned_mon) });
            tally.call(Func::MonCycle, || unsafe {
                sl_mon_cycle(misaligned_mon, tn)
            });
        }
        // ---- a re-initialisation now and then
        if i % 4099 == 0 {
            tally.call(Func::EstopInit, || unsafe { sl_estop_init(&mut estop) });
            tally.call(Func::MonInit, || unsafe { sl_mon_init(&mut mon) });
        }
    }
    drop(on);

    // ---- no heap operation in any call
    let mut report = String::new();
    for (k, name) in FUNC_NAMES.iter().enumerate() {
        report += &format!(
            "  {name:<15} {:>8} calls, {} heap operations\n",
            tally.calls[k], tally.ops[k]
        );
    }
    println!("{report}");
    assert!(
        tally.ops.iter().all(|&n| n == 0),
        "the C ABI functions allocated:\n{report}"
    );

    // ---- the run really went through the paths it claims to cover
    let codes = [
        (SL_OK, "SL_OK"),
        (SL_E_NULL, "SL_E_NULL"),
        (SL_E_CONFIG, "SL_E_CONFIG"),
        (SL_E_PARAM_CHANGED, "SL_E_PARAM_CHANGED"),
        (SL_E_CORRUPT, "SL_E_CORRUPT"),
        (SL_E_INVALID_BOOL, "SL_E_INVALID_BOOL"),
        (SL_E_CLOCK, "SL_E_CLOCK"),
        (SL_E_ALIGNMENT, "SL_E_ALIGNMENT"),
    ];
    for (block, name) in ["FB_ESTOP", "FB_MON"].iter().enumerate() {
        for (code, code_name) in codes {
            let n = tally.status[block][usize::try_from(-code).unwrap()];
            println!("  {name:<8} {code_name:<20} {n:>8}");
            assert!(n > 0, "{name}: status {code_name} never returned");
        }
        let states = [
            (SL_STATE_RUN, "RUN"),
            (SL_STATE_STOP, "STOP"),
            (SL_STATE_SAFE, "SAFE"),
            (SL_STATE_ERROR, "ERROR"),
            (SL_STATE_RESET, "RESET"),
            (SL_STATE_START, "START"),
            (SL_STATE_DELAYOUT, "DELAYOUT"),
        ];
        for (s, s_name) in states {
            let n = tally.states[block][usize::from(s)];
            println!("  {name:<8} state {s_name:<14} {n:>8} cycles");
            assert!(n > 0, "{name}: state {s_name} never reached");
        }
    }
}
