//! Every registered type (the rows of `safelogic::for_each_block!`), driven from the
//! registry's field tables rather than written out per type: a configuration the library
//! accepts (zero parameters, else the first of a fixed pseudo-random series of small
//! parameter values that `init` accepts), bRun TRUE, every BOOL input TRUE and every analog
//! input 0, brought to the state those inputs lead to; then three timings of the C cycle
//! function: steady (nothing written between calls), inputs written first (the same input
//! values written through the field table right before each call, as a real caller does)
//! and random (fresh random input values written right before each call: BOOL 0/1,
//! analog any value). Both writing columns pay the same generic byte writes.

use safelogic::any::FunctionBlock;
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
    /// What `init` returned for the configuration used.
    pub init: i32,
    /// The block's state after the warm-up, with the steady inputs.
    pub state: &'static str,
    /// Median ns per call: steady, inputs written first, random inputs.
    pub ns: [f64; 3],
}

/// Writes `v` (little-endian, `size` bytes) at `offset` of the instance at `p`.
///
/// # Safety
/// `offset + size` lies inside the instance.
unsafe fn put(p: *mut u8, offset: u16, size: usize, v: u32) {
    let bytes = v.to_le_bytes();
    // SAFETY: the caller keeps the write inside the instance; integer fields only.
    unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), p.add(usize::from(offset)), size) };
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
/// steady one, the others random.
fn inputs(t: &BlockType, n: usize) -> (Vec<(u16, usize)>, Vec<Vec<u32>>) {
    let fields: Vec<_> = t.fields.iter().filter(|f| f.dir == Dir::Input).collect();
    let mut rng = Rng(0x5EED_0000 ^ u64::from(t.info.tag) | 1);
    let patterns = (0..n)
        .map(|i| {
            fields
                .iter()
                .map(|f| match (f.kind, i) {
                    (Kind::Bool, 0) => 1,
                    (_, 0) => 0,
                    (Kind::Bool, _) => (rng.next() & 1) as u32,
                    _ => rng.next() as u32,
                })
                .collect()
        })
        .collect();
    (
        fields.iter().map(|f| (f.offset, f.kind.size())).collect(),
        patterns,
    )
}

/// Sets up one instance and times it (`batches` batches of `calls`), or in the callgrind
/// child (`steady_only`) makes only the warm-up and the steady calls.
fn one<T: Copy + FunctionBlock>(
    cycle_name: &'static str,
    tag: u16,
    init: unsafe extern "C" fn(*mut T) -> i32,
    cycle: unsafe extern "C" fn(*mut T, u32) -> i32,
    (warmup, batches, calls): (u32, usize, u32),
    steady_only: bool,
) -> TypeRow {
    let t = block_type(tag).expect("a registered row");
    assert_eq!(t.size, std::mem::size_of::<T>());
    let (fields, patterns) = inputs(t, 257);
    let write = |fb: &mut T, pattern: &[u32]| {
        let p = (fb as *mut T).cast::<u8>();
        for (&(offset, size), &v) in fields.iter().zip(pattern) {
            // SAFETY: the field table's offsets and sizes lie inside the struct.
            unsafe { put(p, offset, size, v) };
        }
    };
    // A configuration init accepts: zero parameters first, then small pseudo-random ones.
    let mut rng = Rng(0xC0F1_6000 ^ u64::from(tag) | 1);
    let mut status = i32::MIN;
    // SAFETY: every block struct holds only integer fields (and zero-sized markers), so the
    // zero pattern is a valid value.
    let mut fb: T = unsafe { std::mem::zeroed() };
    for attempt in 0..20_000 {
        // SAFETY: as above.
        fb = unsafe { std::mem::zeroed() };
        let p = (&mut fb as *mut T).cast::<u8>();
        for f in t.fields.iter() {
            let v = match f.dir {
                Dir::Control if f.name == "bRun" => 1,
                Dir::Param if attempt > 0 => {
                    let r = rng.next();
                    [0, 1, 2, 3, 5, 10, 100, 1000, 0xFF, 0xFFFF][(r % 10) as usize]
                }
                _ => continue,
            };
            // SAFETY: the field table's offsets and sizes lie inside the struct.
            unsafe { put(p, f.offset, f.kind.size(), v) };
        }
        write(&mut fb, &patterns[0]);
        // SAFETY: `fb` is a valid instance of the type the function belongs to.
        status = unsafe { init(&mut fb) };
        if status == SL_OK {
            break;
        }
    }
    let f = black_box(cycle);
    let mut now = 0u32;
    for _ in 0..warmup {
        now += 1;
        // SAFETY: as above.
        unsafe { f(&mut fb, now) };
    }
    let state = fb.state_name();
    let mut ns = [0.0; 3];
    let mut timed = |column: usize, fb: &mut T, now: &mut u32| {
        let mut per_call = Vec::with_capacity(batches);
        let mut k = 0usize;
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
                black_box(unsafe { f(black_box(&mut *fb), *now) });
            }
            per_call.push(start.elapsed().as_nanos() as f64 / f64::from(calls));
        }
        per_call.sort_by(f64::total_cmp);
        ns[column] = per_call[per_call.len() / 2];
    };
    timed(0, &mut fb, &mut now);
    if !steady_only {
        timed(1, &mut fb, &mut now);
        // Random inputs on a copy, so the steady instance stays as it was.
        let mut r = fb;
        timed(2, &mut r, &mut now);
    }
    TypeRow {
        name: t.info.name,
        cycle: cycle_name,
        init: status,
        state,
        ns,
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
