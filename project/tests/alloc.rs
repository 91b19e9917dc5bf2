//! Loading a project may allocate; cycling it may not. A counting global allocator counts
//! the heap operations of this thread between the reads around the cycles.

use safelogic_project::{Project, Runtime};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static HEAP_OPS: Cell<usize> = const { Cell::new(0) };
}

struct CountingAlloc;

impl CountingAlloc {
    fn note(&self) {
        if COUNTING.try_with(Cell::get).unwrap_or(false) {
            let _ = HEAP_OPS.try_with(|n| n.set(n.get() + 1));
        }
    }
}

// SAFETY: every call is forwarded unchanged to the system allocator; counting touches only
// const-initialised thread-locals (no allocation, no recursion).
unsafe impl GlobalAlloc for CountingAlloc {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        self.note();
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        self.note();
        // SAFETY: `p` came from `alloc` above with this layout.
        unsafe { System.dealloc(p, layout) }
    }
    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        self.note();
        // SAFETY: forwarded unchanged.
        unsafe { System.realloc(p, layout, new_size) }
    }
}

#[global_allocator]
static ALLOC: CountingAlloc = CountingAlloc;

fn counted<R>(f: impl FnOnce() -> R) -> (R, usize) {
    HEAP_OPS.with(|n| n.set(0));
    COUNTING.with(|c| c.set(true));
    let r = f();
    COUNTING.with(|c| c.set(false));
    (r, HEAP_OPS.with(Cell::get))
}

#[test]
fn the_counter_sees_an_allocation() {
    let (v, ops) = counted(|| vec![1u8; 64]);
    assert_eq!(v.len(), 64);
    assert!(ops >= 1);
}

#[test]
fn a_loaded_project_cycles_without_allocating() {
    let text = include_str!("../../examples/projects/kl6904_5_1.toml");
    let p = Project::parse("kl6904_5_1.toml", text).unwrap();
    let (rt, ops) = counted(|| Runtime::load(&p).unwrap());
    assert!(ops > 0, "loading allocates (Vecs)");
    let mut rt = rt;
    let places: Vec<_> = p.inputs.iter().map(|s| s.places[0]).collect();
    let outs: Vec<_> = p.outputs.iter().map(|s| s.places[0]).collect();
    let ((), ops) = counted(|| {
        let mut sum = 0i64;
        for t in 0..20_000u32 {
            // inputs toggling through every state: e-stop, restart, feedback, ErrAck
            for (i, pl) in places.iter().enumerate() {
                rt.write(pl, i64::from((t >> (i + 3)) & 1));
            }
            rt.cycle(t * 10);
            for pl in &outs {
                sum += rt.read(pl);
            }
            sum += i64::from(rt.member_state(0, 0).len() as u8);
            sum += rt.group_state(0).len() as i64;
        }
        std::hint::black_box(sum);
    });
    assert_eq!(ops, 0, "cycling a loaded project allocated {ops} times");
}
