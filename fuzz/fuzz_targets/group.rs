//! The group API (`sl_group_init`, `sl_group_add_member`, `sl_group_add_link`,
//! `sl_group_cycle`) driven by the fuzzer: four block slots of any registered types at
//! fuzzer-chosen places in one arena (so they may overlap), members added with their own
//! or another tag, links between arbitrary fields, cycles with arbitrary group inputs and
//! time steps, writes to any byte of the blocks, re-inits of blocks and of the group.
//! Invariants after every call: no panic; a documented status; every member's own
//! invariants (tests/conformance.rs); no member output TRUE unless the group is in RUN;
//! the group's outputs are 0/1 and `bInRun` / `bFbRun` only in RUN.
#![no_main]

use libfuzzer_sys::fuzz_target;
use safelogic::registry::{block_type, Dir, BLOCKS};
use safelogic::*;
use std::ffi::c_void;

mod invariants;
use invariants::*;

const SLOTS: usize = 4;
const CAP: u16 = 4;
const LINK_CAP: u16 = 4;

fn max_size() -> usize {
    BLOCKS.iter().map(|b| b.size).max().unwrap()
}

macro_rules! inits {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        fn init_block(tag: u16, p: *mut u8) -> i32 {
            $(if tag == <$ty as safelogic::base::block::Registered>::INFO.tag {
                // SAFETY: `p` is 8-aligned arena memory of at least the type's size.
                return unsafe { safelogic::ffi::$init(p.cast()) };
            })*
            unreachable!()
        }
    };
}
safelogic::for_each_block!(inits);

/// Slot `k` was just initialised as its type: it is one again, and every other slot whose
/// bytes overlap it is not.
fn clobber(slots: &[(u16, usize); SLOTS], clobbered: &mut [bool; SLOTS], k: usize) {
    let span = |(tag, at): (u16, usize)| at..at + block_type(tag).unwrap().size;
    let mine = span(slots[k]);
    for (j, c) in clobbered.iter_mut().enumerate() {
        let other = span(slots[j]);
        if j == k {
            *c = false;
        } else if other.start < mine.end && mine.start < other.end {
            *c = true;
        }
    }
}

/// The group functions' statuses: a block's documented ones, and the table faults.
fn group_status(rc: i32) -> bool {
    DOCUMENTED.contains(&rc) || rc == SL_E_FULL || rc == SL_E_NULL
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input(data);
    let max = max_size();
    let arena_len = 64 * 8 + max;
    let mut arena = aligned(arena_len);
    let base = arena.as_mut_ptr().cast::<u8>();
    // Slots: a type and a place (8-aligned offset) each.
    let mut slots = [(0u16, 0usize); SLOTS];
    let mut written = [false; SLOTS];
    for (s, w) in slots.iter_mut().zip(written.iter_mut()) {
        let t = &BLOCKS[usize::from(inp.u8()) % BLOCKS.len()];
        *s = (t.info.tag, usize::from(inp.u8() % 64) * 8);
        let p = base.wrapping_add(s.1);
        if inp.u8() & 1 == 1 {
            for i in 0..t.size {
                // SAFETY: inside the arena (offset <= 504, size <= max).
                unsafe { *p.add(i) = inp.u8() };
            }
            *w = true;
        }
        if inp.u8() & 1 == 1 {
            init_block(t.info.tag, p);
            *w = true;
        }
    }
    // A slot whose bytes another slot's init has since overwritten (slots may overlap) is no
    // instance of its type any more: the group refuses it as corrupt (the tag inside the
    // private header differs) and cannot write it, so its own invariants are not asked.
    let mut clobbered = [false; SLOTS];
    for k in (0..SLOTS).filter(|&k| written[k]) {
        clobber(&slots, &mut clobbered, k);
    }
    let mut g = Box::new(SL_GROUP::default());
    let mut members = vec![SL_MEMBER::default(); usize::from(CAP)];
    let mut links = vec![SL_LINK::default(); usize::from(LINK_CAP)];
    let gp: *mut SL_GROUP = &mut *g;
    let mp = members.as_mut_ptr();
    let lp = links.as_mut_ptr();
    // SAFETY: live, separate allocations.
    assert_eq!(
        unsafe { ffi::sl_group_init(gp, mp, CAP, lp, LINK_CAP) },
        SL_OK
    );
    // (slot, tag it was accepted with) of the current members, in order.
    let mut in_group: Vec<(usize, u16)> = Vec::new();
    let mut now = inp.u32();
    while !inp.is_empty() {
        let op = inp.u8();
        match op % 8 {
            0 if op & 0xE0 == 0xE0 => {
                // SAFETY: as above.
                unsafe { (*gp).bConnections = inp.u8() % 3 };
                // SAFETY: as above.
                let rc = unsafe { ffi::sl_group_init(gp, mp, CAP, lp, LINK_CAP) };
                assert!(group_status(rc), "init: {rc}");
                if rc == SL_OK {
                    in_group.clear();
                }
            }
            1 => {
                let k = usize::from(inp.u8()) % SLOTS;
                let tag = if op & 0x80 == 0 {
                    slots[k].0
                } else {
                    BLOCKS[usize::from(inp.u8()) % BLOCKS.len()].info.tag
                };
                let p = base.wrapping_add(slots[k].1).cast::<c_void>();
                // SAFETY: arena memory of at least the largest block's size.
                let rc = unsafe { ffi::sl_group_add_member(gp, mp, tag, p, std::ptr::null_mut()) };
                assert!(group_status(rc), "add: {rc}");
                if rc == SL_OK {
                    slots[k].0 = tag;
                    in_group.push((k, tag));
                }
            }
            2 if !in_group.is_empty() => {
                let s = usize::from(inp.u8()) % in_group.len();
                let d = usize::from(inp.u8()) % in_group.len();
                let ts = block_type(in_group[s].1).unwrap();
                let td = block_type(in_group[d].1).unwrap();
                let outs: Vec<_> = ts.fields.iter().filter(|f| f.dir == Dir::Output).collect();
                let ins: Vec<_> = td.fields.iter().filter(|f| f.dir == Dir::Input).collect();
                let so = if outs.is_empty() || op & 0x80 != 0 {
                    inp.u16() % 256
                } else {
                    outs[usize::from(inp.u8()) % outs.len()].offset
                };
                let dof = if ins.is_empty() || op & 0x40 != 0 {
                    inp.u16() % 256
                } else {
                    ins[usize::from(inp.u8()) % ins.len()].offset
                };
                // SAFETY: as above.
                let rc = unsafe { ffi::sl_group_add_link(gp, mp, lp, s as u16, so, d as u16, dof) };
                assert!(group_status(rc), "link: {rc}");
            }
            3 => {
                let k = usize::from(inp.u8()) % SLOTS;
                let t = block_type(slots[k].0).unwrap();
                let ins: Vec<_> = t
                    .fields
                    .iter()
                    .filter(|f| matches!(f.dir, Dir::Input | Dir::Param))
                    .collect();
                if !ins.is_empty() {
                    let f = ins[usize::from(inp.u8()) % ins.len()];
                    let v = inp.u8();
                    let v = if op & 0x80 == 0 { v & 1 } else { v };
                    // SAFETY: inside the arena.
                    unsafe { *base.add(slots[k].1 + usize::from(f.offset)) = v };
                }
            }
            4 if op & 0xC0 == 0xC0 => {
                let k = usize::from(inp.u8()) % SLOTS;
                let i = usize::from(inp.u16()) % block_type(slots[k].0).unwrap().size;
                // SAFETY: inside the arena.
                unsafe { *base.add(slots[k].1 + i) = inp.u8() };
            }
            5 if op & 0xC0 == 0xC0 => {
                let k = usize::from(inp.u8()) % SLOTS;
                init_block(slots[k].0, base.wrapping_add(slots[k].1));
                clobber(&slots, &mut clobbered, k);
            }
            _ => {
                let mut bytes = [0u8; 5];
                for b in bytes.iter_mut() {
                    let v = inp.u8();
                    *b = if op & 0x80 == 0 { v & 1 } else { v };
                }
                // SAFETY: as above.
                unsafe {
                    (*gp).bRun = bytes[0];
                    (*gp).bErrAck = bytes[1];
                    (*gp).bModuleFault = bytes[2] & u8::from(op & 0x20 != 0);
                    (*gp).bComErrIn = bytes[3] & u8::from(op & 0x10 != 0);
                    (*gp).bComStartupIn = bytes[4] & u8::from(op & 0x08 != 0);
                }
                now = now.wrapping_add(u32::from(inp.u16() % 1024));
                // SAFETY: as above.
                let rc = unsafe { ffi::sl_group_cycle(gp, mp, lp, now) };
                assert!(
                    group_status(rc) && rc != SL_E_NULL && rc != SL_E_FULL,
                    "cycle: {rc}"
                );
                // SAFETY: read by value.
                let gs = unsafe { gp.read() };
                for b in [
                    gs.bComErr,
                    gs.bFbErr,
                    gs.bOutErr,
                    gs.bOtherErr,
                    gs.bComStartup,
                    gs.bFbDeactive,
                    gs.bFbRun,
                    gs.bInRun,
                ] {
                    assert!(b <= 1);
                }
                let run = gs.nState == SL_STATE_RUN;
                assert_eq!(gs.bInRun == 1, run);
                assert!(gs.bFbRun == 0 || run);
                for &(k, tag) in in_group.iter().filter(|&&(k, _)| !clobbered[k]) {
                    let t = block_type(tag).unwrap();
                    // SAFETY: the member's bytes in the arena.
                    let bytes = unsafe { std::slice::from_raw_parts(base.add(slots[k].1), t.size) }
                        .to_vec();
                    check_block(t, &bytes, SL_OK);
                    if !run {
                        check_outputs_false(t, &bytes, "the group is not in RUN");
                    }
                }
            }
        }
    }
    drop((g, members, links, arena));
});
