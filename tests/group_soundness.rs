//! The group API against callers that get things wrong (issue "Reliability proven"): a
//! refused or premature re-init never detaches the members of a running group, and a
//! member that cannot be reached stops the group instead of being skipped.

use safelogic::ffi;
use safelogic::group;
use safelogic::*;
use std::ffi::c_void;

#[path = "common/invariants.rs"]
mod invariants;

struct Fixture {
    g: SL_GROUP,
    members: [SL_MEMBER; 2],
    links: [SL_LINK; 2],
    estop: FB_ESTOP,
}

/// The fixture is reached only through this raw pointer (as a C caller's memory): a
/// `&mut Fixture` formed after the ESTOP's address went into the member table would, under
/// Stacked Borrows, invalidate that address (a test-side aliasing error Miri reports).
struct Fx(*mut Fixture);

impl Drop for Fx {
    fn drop(&mut self) {
        // SAFETY: from `Box::into_raw` in `running_estop_group`, freed once.
        drop(unsafe { Box::from_raw(self.0) });
    }
}

fn running_estop_group() -> Fx {
    let f = Fx(Box::into_raw(Box::new(Fixture {
        g: SL_GROUP::default(),
        members: [SL_MEMBER::default(); 2],
        links: [SL_LINK::default(); 2],
        estop: FB_ESTOP {
            wInputActive: 0b11,
            tDiscTime12: 50,
            ..Default::default()
        },
    })));
    let p = f.0;
    // SAFETY: every pointer is to a field of the boxed fixture, derived from `p`.
    unsafe {
        assert_eq!((*p).estop.init(), SL_OK);
        assert_eq!(init(p), SL_OK);
        let e: *mut c_void = std::ptr::addr_of_mut!((*p).estop).cast();
        assert_eq!(
            ffi::sl_group_add_member(
                std::ptr::addr_of_mut!((*p).g),
                members(p),
                SL_TYPE_ESTOP,
                e,
                std::ptr::null_mut()
            ),
            SL_OK
        );
        (*p).estop.bEStopIn1 = 1;
        (*p).estop.bEStopIn2 = 1;
        (*p).g.bRun = 1;
        cycle(p, 0);
        (*p).estop.bRestart = 1;
        cycle(p, 10);
        (*p).estop.bRestart = 0;
        cycle(p, 20);
        assert_eq!((*p).g.nState, SL_STATE_RUN);
        assert_eq!((*p).estop.bEStopOut, 1);
    }
    f
}

fn members(f: *mut Fixture) -> *mut SL_MEMBER {
    // SAFETY: a field address of the live fixture.
    unsafe { std::ptr::addr_of_mut!((*f).members).cast() }
}

fn links(f: *mut Fixture) -> *mut SL_LINK {
    // SAFETY: a field address of the live fixture.
    unsafe { std::ptr::addr_of_mut!((*f).links).cast() }
}

fn init(f: *mut Fixture) -> i32 {
    // SAFETY: the fixture's own tables.
    unsafe { ffi::sl_group_init(std::ptr::addr_of_mut!((*f).g), members(f), 2, links(f), 2) }
}

fn cycle(f: *mut Fixture, t: u32) -> i32 {
    // SAFETY: the fixture's own tables, as passed to sl_group_init.
    unsafe { ffi::sl_group_cycle(std::ptr::addr_of_mut!((*f).g), members(f), links(f), t) }
}

fn press_estop_and_cycle(f: *mut Fixture) {
    // SAFETY: fields of the live fixture, no reference kept.
    unsafe {
        (*f).estop.bEStopIn1 = 0;
        (*f).estop.bEStopIn2 = 0;
        cycle(f, 30);
        assert_eq!(
            (*f).estop.bEStopOut,
            0,
            "the E-stop output must follow the E-stop"
        );
    }
}

/// The reproducer of the issue: a refused init (bConnections = 2) must change nothing.
#[test]
fn refused_init_keeps_the_members_of_a_running_group() {
    let fx = running_estop_group();
    let f = fx.0;
    // SAFETY: fields of the live fixture.
    unsafe {
        (*f).g.bConnections = 2;
        let rc = init(f);
        assert_eq!(rc, SL_E_CONFIG);
        assert!(!(*f).members[0].pBlock.is_null(), "member table untouched");
        (*f).g.bConnections = 0;
    }
    press_estop_and_cycle(f);
}

/// A refused init for a NULL table changes nothing either.
#[test]
fn init_with_null_links_keeps_the_members() {
    let fx = running_estop_group();
    let f = fx.0;
    // SAFETY: the fixture's member table; links NULL with a capacity is refused.
    unsafe {
        let rc = ffi::sl_group_init(
            std::ptr::addr_of_mut!((*f).g),
            members(f),
            2,
            std::ptr::null_mut(),
            2,
        );
        assert_eq!(rc, SL_E_NULL);
        assert!(!(*f).members[0].pBlock.is_null());
    }
    press_estop_and_cycle(f);
}

/// A valid init of a group that is still running is refused (semantics GR13).
#[test]
fn init_of_a_running_group_is_refused() {
    let fx = running_estop_group();
    let f = fx.0;
    assert_eq!(init(f), SL_E_CONFIG);
    press_estop_and_cycle(f);
    // SAFETY: fields of the live fixture.
    unsafe {
        // Stopped, the group may be initialised again.
        (*f).g.bRun = 0;
        cycle(f, 40);
        assert_eq!((*f).g.nState, SL_STATE_STOP);
        assert_eq!(init(f), SL_OK);
        assert_eq!((*f).g.nMembers, 0);
    }
}

/// A member entry that no longer reaches a block puts the group into ERROR.
#[test]
fn unreachable_member_is_a_group_error() {
    let fx = running_estop_group();
    let f = fx.0;
    // SAFETY: fields of the live fixture.
    unsafe {
        (*f).members[0].pBlock = std::ptr::null_mut();
        assert_eq!(cycle(f, 30), SL_E_CORRUPT);
        assert_eq!((*f).g.nState, SL_STATE_ERROR);
        assert_eq!((*f).g.bFbErr, 1);
        assert_eq!((*f).g.bInRun, 0);
        assert_eq!((*f).g.bFbRun, 0);
        assert_eq!((*f).g.nFailedMember, 0);
    }
}

// ---------------------------------------------------------------------------------------
// Adversarial callers (issue 16 item 1). Every object lives in one 8-aligned arena and is
// reached only through raw pointers derived from the arena's base, as a C caller's memory
// would be: the abuses below place blocks and tables so that they overlap, forge the
// group's private state and the entries, and pass other tables. Miri runs this file.
// ---------------------------------------------------------------------------------------

use std::mem::{offset_of, size_of};

const ARENA: usize = 4096;

#[repr(C, align(8))]
struct Arena([u8; ARENA]);

struct Mem {
    base: *mut u8,
}

impl Drop for Mem {
    fn drop(&mut self) {
        // SAFETY: `base` came from `Box::into_raw` in `new` and is freed once.
        drop(unsafe { Box::from_raw(self.base.cast::<Arena>()) });
    }
}

impl Mem {
    fn new() -> Mem {
        // Only raw pointers from here on, as a C caller's memory (no Box is moved or
        // retagged while the library holds pointers into it).
        let raw = Box::into_raw(Box::new(Arena([0; ARENA])));
        Mem { base: raw.cast() }
    }

    /// A pointer `off` bytes into the arena.
    fn at<T>(&self, off: usize) -> *mut T {
        assert!(off < ARENA);
        self.base.wrapping_add(off).cast()
    }
}

/// A group at arena offset 0 with its member table at 64 (cap 4) and link table at 128
/// (cap 4); blocks go from 512 on.
const G: usize = 0;
const MT: usize = 64;
const LT: usize = 128;
const CAP: u16 = 4;

fn group_in(mem: &Mem) -> (*mut SL_GROUP, *mut SL_MEMBER, *mut SL_LINK) {
    let (g, m, l) = (mem.at::<SL_GROUP>(G), mem.at(MT), mem.at(LT));
    // SAFETY: arena memory, 8-aligned, disjoint ranges (64 + 4 * 16 = 128, 128 + 48 < 512).
    assert_eq!(unsafe { ffi::sl_group_init(g, m, CAP, l, CAP) }, SL_OK);
    (g, m, l)
}

fn add(g: *mut SL_GROUP, m: *mut SL_MEMBER, ty: u16, b: *mut c_void) -> i32 {
    // SAFETY: arena pointers; the functions check everything they can.
    unsafe { ffi::sl_group_add_member(g, m, ty, b, std::ptr::null_mut()) }
}

fn gcycle(g: *mut SL_GROUP, m: *mut SL_MEMBER, l: *mut SL_LINK, t: u32) -> i32 {
    // SAFETY: as above.
    unsafe { ffi::sl_group_cycle(g, m, l, t) }
}

/// An initialised two-channel ESTOP at arena offset `off`, inputs TRUE.
fn estop_at(mem: &Mem, off: usize) -> *mut FB_ESTOP {
    let p = mem.at::<FB_ESTOP>(off);
    // SAFETY: arena memory large enough for the block.
    unsafe {
        p.write(FB_ESTOP {
            wInputActive: 0b11,
            bEStopIn1: 1,
            bEStopIn2: 1,
            ..Default::default()
        });
        assert_eq!(ffi::sl_estop_init(p), SL_OK);
    }
    p
}

fn and_at(mem: &Mem, off: usize) -> *mut FB_AND {
    let p = mem.at::<FB_AND>(off);
    // SAFETY: arena memory large enough for the block.
    unsafe {
        p.write(FB_AND {
            wInputActive: 0b11,
            ..Default::default()
        });
        assert_eq!(ffi::sl_and_init(p), SL_OK);
    }
    p
}

fn state(g: *mut SL_GROUP) -> SL_GROUP {
    // SAFETY: arena memory, read by value.
    unsafe { g.read() }
}

/// Brings the group with an ESTOP as member 0 to RUN with the E-stop output TRUE.
fn to_run(g: *mut SL_GROUP, m: *mut SL_MEMBER, l: *mut SL_LINK, e: *mut FB_ESTOP) {
    // SAFETY: arena pointers; no reference outlives a statement.
    unsafe {
        (*g).bRun = 1;
        gcycle(g, m, l, 0);
        (*e).bRestart = 1;
        gcycle(g, m, l, 10);
        (*e).bRestart = 0;
        assert_eq!(gcycle(g, m, l, 20), SL_OK);
        assert_eq!((*g).nState, SL_STATE_RUN);
        assert_eq!((*e).bEStopOut, 1);
    }
}

/// The group is in ERROR with its outputs safe and SL_E_CORRUPT. `reachable`: the ESTOP's
/// entry is intact, so the group stopped it in the same cycle (an entry that fails its
/// check cannot be reached: GR14 makes its outputs the caller's to treat as FALSE).
fn assert_stopped_with_corrupt(rc: i32, g: *mut SL_GROUP, e: *mut FB_ESTOP, reachable: bool) {
    assert_eq!(rc, SL_E_CORRUPT);
    let gs = state(g);
    assert_eq!(gs.nState, SL_STATE_ERROR);
    assert_eq!((gs.bInRun, gs.bFbRun, gs.bFbErr), (0, 0, 1));
    assert_eq!(gs.nDiag, group::SL_GROUP_DIAG_FBERROR);
    if reachable {
        // SAFETY: arena memory, read by value.
        assert_eq!(unsafe { (*e).bEStopOut }, 0, "the E-stop output is FALSE");
    }
}

#[test]
fn block_reaching_into_the_group_from_below_is_refused() {
    let mem = Mem::new();
    // The group at 1024 this time, a block starting 32 bytes below it.
    let g = mem.at::<SL_GROUP>(1024);
    let (m, l) = (mem.at::<SL_MEMBER>(MT), mem.at::<SL_LINK>(LT));
    // SAFETY: arena memory.
    assert_eq!(unsafe { ffi::sl_group_init(g, m, CAP, l, CAP) }, SL_OK);
    // (Nothing is written there: the range alone is refused, before the block is read.)
    assert_eq!(add(g, m, SL_TYPE_ESTOP, mem.at(1024 - 32)), SL_E_CONFIG);
    // ... and one starting inside it.
    assert_eq!(add(g, m, SL_TYPE_ESTOP, mem.at(1024 + 8)), SL_E_CONFIG);
    assert_eq!(state(g).nMembers, 0);
}

#[test]
fn block_overlapping_the_member_table_or_the_link_table_is_refused() {
    let mem = Mem::new();
    let (g, m, l) = group_in(&mem);
    // Over the member table (starting below it, inside it).
    assert_eq!(add(g, m, SL_TYPE_AND, mem.at(MT - 8)), SL_E_CONFIG);
    assert_eq!(add(g, m, SL_TYPE_AND, mem.at(MT + 16)), SL_E_CONFIG);
    // A member over the link table is refused when a link is added ...
    let e = estop_at(&mem, 512);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
    let a = and_at(&mem, LT);
    assert_eq!(add(g, m, SL_TYPE_AND, a.cast()), SL_OK);
    // SAFETY: arena pointers.
    let rc = unsafe {
        ffi::sl_group_add_link(
            g,
            m,
            l,
            0,
            offset_of!(FB_ESTOP, bEStopOut) as u16,
            1,
            offset_of!(FB_AND, bAndIn1) as u16,
        )
    };
    assert_eq!(rc, SL_E_CONFIG);
    assert_eq!(state(g).nLinks, 0);
}

#[test]
fn member_over_a_link_table_in_use_stops_the_group() {
    let mem = Mem::new();
    let (g, m, l) = group_in(&mem);
    let e = estop_at(&mem, 512);
    let a = and_at(&mem, 1024);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
    assert_eq!(add(g, m, SL_TYPE_AND, a.cast()), SL_OK);
    // SAFETY: arena pointers.
    let rc = unsafe {
        ffi::sl_group_add_link(
            g,
            m,
            l,
            0,
            offset_of!(FB_ESTOP, bEStopOut) as u16,
            1,
            offset_of!(FB_AND, bAndIn1) as u16,
        )
    };
    assert_eq!(rc, SL_OK);
    // A third member placed over the link table (add_member cannot see the link table):
    // its own cycle writes over the link, which then fails its check.
    let b = mem.at::<FB_OR>(LT + 8);
    // SAFETY: arena memory.
    unsafe {
        b.write(FB_OR {
            wInputActive: 1,
            bOrIn1: 1,
            ..Default::default()
        });
        assert_eq!(ffi::sl_or_init(b), SL_OK);
    }
    assert_eq!(add(g, m, SL_TYPE_OR, b.cast()), SL_OK);
    // SAFETY: arena memory.
    unsafe { (*g).bRun = 1 };
    let mut rcs = Vec::new();
    for t in 0..4 {
        rcs.push(gcycle(g, m, l, t));
    }
    assert!(rcs.contains(&SL_E_CORRUPT), "{rcs:?}");
    assert_eq!(state(g).nState, SL_STATE_ERROR);
}

#[test]
fn overlapping_members_and_duplicates_are_refused() {
    let mem = Mem::new();
    let (g, m, _) = group_in(&mem);
    let e = estop_at(&mem, 512);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_E_CONFIG, "twice");
    // An AND whose bytes start inside the ESTOP, and one that ends inside it.
    let inside = and_at(&mem, 512 + 64);
    assert_eq!(add(g, m, SL_TYPE_AND, inside.cast()), SL_E_CONFIG);
    let below = 512 - size_of::<FB_AND>() + 8;
    assert_eq!(add(g, m, SL_TYPE_AND, mem.at(below)), SL_E_CONFIG);
    let next = and_at(&mem, 512 + size_of::<FB_ESTOP>());
    assert_eq!(
        add(g, m, SL_TYPE_AND, next.cast()),
        SL_OK,
        "adjacent is fine"
    );
    assert_eq!(state(g).nMembers, 2);
}

#[test]
fn tables_overlapping_each_other_or_the_group_are_refused_at_init() {
    let mem = Mem::new();
    let g = mem.at::<SL_GROUP>(G);
    // SAFETY: arena memory.
    unsafe {
        assert_eq!(
            ffi::sl_group_init(g, mem.at(32), CAP, mem.at(LT), CAP),
            SL_E_CONFIG
        );
        assert_eq!(
            ffi::sl_group_init(g, mem.at(MT), CAP, mem.at(MT + 48), CAP),
            SL_E_CONFIG
        );
        assert_eq!(
            ffi::sl_group_init(g, mem.at(MT), CAP, mem.at(8), CAP),
            SL_E_CONFIG
        );
    }
}

#[test]
fn full_group_refuses_without_touching_past_the_table() {
    // The member table is exactly `cap` entries at the end of its own allocation, so a
    // slice or write one past it is an out-of-bounds access (Miri reports it).
    let mem = Mem::new();
    let g = mem.at::<SL_GROUP>(G);
    let mut table = vec![SL_MEMBER::default(); 1];
    let m = table.as_mut_ptr();
    // SAFETY: the group in the arena, the table in its own allocation.
    assert_eq!(
        unsafe { ffi::sl_group_init(g, m, 1, std::ptr::null_mut(), 0) },
        SL_OK
    );
    let e = estop_at(&mem, 512);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
    let a = and_at(&mem, 1024);
    assert_eq!(add(g, m, SL_TYPE_AND, a.cast()), SL_E_FULL);
    assert_eq!(state(g).nMembers, 1);
    // The never-initialised block offered to a full group stays untouched.
    let zero = mem.at::<FB_AND>(2048);
    assert_eq!(add(g, m, SL_TYPE_AND, zero.cast()), SL_E_FULL);
    // SAFETY: arena memory.
    assert_eq!(unsafe { (*zero).stPrivate.stHeader.wMagic }, 0);
    drop(table);
}

#[test]
fn wrong_type_tags_are_refused() {
    let mem = Mem::new();
    let (g, m, _) = group_in(&mem);
    // An AND (72 bytes) added as MUTING (larger) and as ESTOP; an ESTOP added as AND.
    let a = and_at(&mem, 2048 - size_of::<FB_AND>());
    assert_eq!(add(g, m, SL_TYPE_MUTING, a.cast()), SL_E_CONFIG);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, a.cast()), SL_E_CONFIG);
    let e = estop_at(&mem, 512);
    assert_eq!(add(g, m, SL_TYPE_AND, e.cast()), SL_E_CONFIG);
    assert_eq!(add(g, m, SL_TYPE_OR, e.cast()), SL_E_CONFIG);
    assert_eq!(state(g).nMembers, 0);
    // Right tags are accepted.
    assert_eq!(add(g, m, SL_TYPE_AND, a.cast()), SL_OK);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
}

#[test]
fn every_registered_type_refuses_every_other_tag() {
    // Each initialised block of each type, offered under each other tag: refused, and
    // nothing written. Under its own tag: accepted.
    let types: Vec<_> = safelogic::registry::BLOCKS.iter().collect();
    let (mut undetectable, mut pairs) = (0, 0);
    // Blocks with a parameter table (LOADSENSING: 25 rows, private header at 312 / 568) hide
    // their header beyond nearly every other type's size, and their zero-parameter table
    // reads as a zero header: GR14's limit by construction. Their pairs keep the exact
    // per-pair checks below but are counted apart from the rarity bound.
    const TABLE_BLOCK_PRIVATE: usize = 256;
    // Under Miri (tools/deep-check.sh) every 11th pair plus each type under its own tag:
    // every type is still offered as some other type and claimed by some other type, in
    // minutes instead of hours. The stable test command checks all pairs.
    let stride = if cfg!(miri) { 11 } else { 1 };
    for (i, own) in types.iter().enumerate() {
        let sampled = types
            .iter()
            .enumerate()
            .filter(|(j, _)| *j == i || (i + j) % stride == 0);
        for (_, claimed) in sampled {
            let mem = Mem::new();
            let (g, m, _) = group_in(&mem);
            let p = mem.at::<c_void>(1024);
            let init = init_fn(own.info.tag);
            assert!(matches!(init(p), SL_OK | SL_E_CONFIG));
            // SAFETY: arena memory, read by value.
            let before: Arena = unsafe { mem.at::<Arena>(0).read() };
            let table_block = private_offset(own.info.tag) > TABLE_BLOCK_PRIVATE;
            if !table_block {
                pairs += 1;
            }
            // A PLCopen type is never accepted never-initialised (semantics PO8): the
            // limit applies to TwinSAFE types only.
            let hidden = looks_never_initialised(&mem, own, claimed)
                && safelogic::base::block::family(claimed.info.tag)
                    == safelogic::base::block::Family::TwinSafe;
            let rc = add(g, m, claimed.info.tag, p);
            if own.info.tag == claimed.info.tag {
                assert_eq!(rc, SL_OK, "{}", own.info.name);
            } else if hidden {
                // GR14: the block's own header lies beyond the claimed size and the claimed
                // type's header bytes are zero: a never-initialised block of the claimed
                // type as far as the claimed size shows; accepted and initialised.
                assert_eq!(rc, SL_OK, "{} as {}", own.info.name, claimed.info.name);
                if !table_block {
                    undetectable += 1;
                }
            } else {
                assert_eq!(
                    rc, SL_E_CONFIG,
                    "{} as {}",
                    own.info.name, claimed.info.name
                );
                // SAFETY: as above.
                let after: Arena = unsafe { mem.at::<Arena>(0).read() };
                assert!(before.0 == after.0, "nothing written");
            }
        }
    }
    // The exception is rare: nearly every wrong tag is refused.
    assert!(
        undetectable * 20 < pairs,
        "{undetectable} of {pairs} pairs undetectable"
    );
}

/// GR14's limit: `own`'s header lies beyond `claimed`'s size, and the bytes where `claimed`
/// has its private header are all zero (the block at offset 1024 of the arena).
fn looks_never_initialised(
    mem: &Mem,
    own: &safelogic::registry::BlockType,
    claimed: &safelogic::registry::BlockType,
) -> bool {
    const HEADER: usize = size_of::<SL_PRIVATE_HEADER>();
    let end = private_offset(own.info.tag) + HEADER;
    let at = private_offset(claimed.info.tag);
    // SAFETY: arena memory, read by value.
    let bytes: [u8; HEADER] = unsafe { mem.at::<[u8; HEADER]>(1024 + at).read_unaligned() };
    end > claimed.size && bytes.iter().all(|b| *b == 0)
}

/// Offset of `stPrivate` (its header comes first) in a registered type.
fn private_offset(tag: u16) -> usize {
    macro_rules! pick {
        ($($ty:ty => $init:ident, $cycle:ident;)*) => {{
            $(if tag == <$ty as safelogic::base::block::Registered>::INFO.tag {
                return offset_of!($ty, stPrivate);
            })*
            unreachable!()
        }};
    }
    safelogic::for_each_block!(pick)
}

/// `sl_<name>_init` of a registered tag, as a function of an untyped pointer.
fn init_fn(tag: u16) -> fn(*mut c_void) -> i32 {
    macro_rules! pick {
        ($($ty:ty => $init:ident, $cycle:ident;)*) => {{
            $(if tag == <$ty as safelogic::base::block::Registered>::INFO.tag {
                return |p| {
                    // SAFETY: arena memory large enough for any block.
                    unsafe { ffi::$init(p.cast()) }
                };
            })*
            unreachable!()
        }};
    }
    safelogic::for_each_block!(pick)
}

#[test]
fn never_initialised_block_is_initialised_when_added() {
    let mem = Mem::new();
    let (g, m, _) = group_in(&mem);
    let a = mem.at::<FB_AND>(1024);
    // SAFETY: arena memory.
    unsafe {
        a.write(FB_AND {
            wInputActive: 0b11,
            ..Default::default()
        })
    };
    assert_eq!(add(g, m, SL_TYPE_AND, a.cast()), SL_OK);
    // SAFETY: arena memory, read by value.
    let h = unsafe { (*a).stPrivate.stHeader };
    assert_ne!(h.wMagic, 0);
    assert_eq!(h.nState, SL_STATE_STOP);
}

#[test]
fn corrupt_block_of_the_right_type_is_refused() {
    let mem = Mem::new();
    let (g, m, _) = group_in(&mem);
    let e = estop_at(&mem, 512);
    // SAFETY: arena memory.
    unsafe { (*e).stPrivate.stHeader.nState ^= 0x40 };
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_E_CORRUPT);
    assert_eq!(state(g).nMembers, 0);
}

/// A running group with an ESTOP (member 0) and an AND (member 1) linked from it.
fn running_pair(mem: &Mem) -> (*mut SL_GROUP, *mut SL_MEMBER, *mut SL_LINK, *mut FB_ESTOP) {
    let (g, m, l) = group_in(mem);
    let e = estop_at(mem, 512);
    let a = and_at(mem, 1024);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
    assert_eq!(add(g, m, SL_TYPE_AND, a.cast()), SL_OK);
    // SAFETY: arena pointers.
    let rc = unsafe {
        ffi::sl_group_add_link(
            g,
            m,
            l,
            0,
            offset_of!(FB_ESTOP, bEStopOut) as u16,
            1,
            offset_of!(FB_AND, bAndIn1) as u16,
        )
    };
    assert_eq!(rc, SL_OK);
    to_run(g, m, l, e);
    (g, m, l, e)
}

/// Writes the group's private member word and its complement consistently (a forgery
/// that passes the group's own integrity check).
fn forge_members(g: *mut SL_GROUP, count: u16, cap: u16) {
    let w = u32::from(count) | u32::from(cap) << 16;
    // SAFETY: arena memory.
    unsafe {
        (*g).stPrivate.dwMembers = w;
        (*g).stPrivate.adwCheck[2] = !w;
    }
}

#[test]
fn forged_member_count_or_capacity_stops_the_group() {
    for (count, cap) in [(1, CAP), (3, CAP), (2, CAP - 1), (2, CAP + 1)] {
        let mem = Mem::new();
        let (g, m, l, e) = running_pair(&mem);
        forge_members(g, count, cap);
        // SAFETY: arena memory.
        unsafe {
            (*e).bEStopIn1 = 0;
            (*e).bEStopIn2 = 0;
        }
        assert_stopped_with_corrupt(gcycle(g, m, l, 30), g, e, false);
    }
}

/// A table of exactly `n` entries in an allocation of its own (nothing mapped after it that
/// belongs to the test), as raw pointer; freed by the caller with `free_table`.
fn own_table<T: Default + Clone>(n: usize) -> *mut T {
    Box::into_raw(vec![T::default(); n].into_boxed_slice()).cast()
}

fn free_table<T>(p: *mut T, n: usize) {
    // SAFETY: `p` came from `own_table(n)` and is freed once.
    drop(unsafe { Box::from_raw(std::ptr::slice_from_raw_parts_mut(p, n)) });
}

#[test]
fn forged_capacity_over_a_one_entry_table_is_found_before_any_other_entry_is_read() {
    // The member table has one entry, in an allocation of its own (the link table too); the
    // group's private state is forged to claim a capacity of 4,000, and a count of 4,000
    // (with matching complements). Nothing past the one entry may be read (Miri: a read or a slice beyond
    // the allocation is undefined behaviour); the group stops with SL_E_CORRUPT.
    for forged in [(1, 4000), (4000, 4000)] {
        let mem = Mem::new();
        let g = mem.at::<SL_GROUP>(G);
        let m = own_table::<SL_MEMBER>(1);
        let l = own_table::<SL_LINK>(1);
        // SAFETY: the group in the arena, each table in its own allocation of one entry.
        assert_eq!(unsafe { ffi::sl_group_init(g, m, 1, l, 1) }, SL_OK);
        let e = estop_at(&mem, 512);
        assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
        to_run(g, m, l, e);
        // twice: the sealed schedule is in place after a fully checked cycle
        assert_eq!(gcycle(g, m, l, 25), SL_OK);
        forge_members(g, forged.0, forged.1);
        assert_stopped_with_corrupt(gcycle(g, m, l, 30), g, e, false);
        free_table(m, 1);
        free_table(l, 1);
    }
}

/// Writes the group's private link word and its complement consistently.
fn forge_links(g: *mut SL_GROUP, count: u16, cap: u16) {
    let w = u32::from(count) | u32::from(cap) << 16;
    // SAFETY: arena memory.
    unsafe {
        (*g).stPrivate.dwLinks = w;
        (*g).stPrivate.adwCheck[3] = !w;
    }
}

#[test]
fn forged_link_capacity_over_a_small_link_table_is_found_before_a_link_past_it_is_read() {
    // The link table is in an allocation of its own with room for `real` links (none used;
    // for 0 the pointer is a dangling, never-readable one); the private state is forged to
    // claim `forged` (count, capacity) with matching complements. The checked cycle reads
    // the slot after the last link: with the forged capacity that slot is past the table
    // (Miri: undefined behaviour), so the capacity must be found forged first.
    for (real, forged) in [
        (1, (0, 4000)),
        (1, (3999, 4000)),
        (1, (1, 4000)),
        (0, (0, 5)),
    ] {
        let mem = Mem::new();
        let g = mem.at::<SL_GROUP>(G);
        let m = own_table::<SL_MEMBER>(1);
        let l = own_table::<SL_LINK>(real);
        // SAFETY: the group in the arena, each table in its own allocation.
        assert_eq!(
            unsafe { ffi::sl_group_init(g, m, 1, l, real as u16) },
            SL_OK
        );
        let e = estop_at(&mem, 512);
        assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
        to_run(g, m, l, e);
        forge_links(g, forged.0, forged.1);
        assert_stopped_with_corrupt(gcycle(g, m, l, 30), g, e, false);
        free_table(m, 1);
        free_table(l, real);
    }
}

#[test]
fn forged_count_that_drops_the_estop_stops_the_group() {
    // Member 0 is an AND, member 1 the ESTOP; the count forged to 1 would drop the ESTOP.
    let mem = Mem::new();
    let (g, m, l) = group_in(&mem);
    let a = and_at(&mem, 1024);
    let e = estop_at(&mem, 512);
    assert_eq!(add(g, m, SL_TYPE_AND, a.cast()), SL_OK);
    assert_eq!(add(g, m, SL_TYPE_ESTOP, e.cast()), SL_OK);
    to_run(g, m, l, e);
    forge_members(g, 1, CAP);
    let rc = gcycle(g, m, l, 30);
    assert_eq!(rc, SL_E_CORRUPT);
    assert_eq!(state(g).nState, SL_STATE_ERROR);
    assert_eq!((state(g).bInRun, state(g).bFbRun), (0, 0));
}

#[test]
fn forged_member_entries_stop_the_group() {
    type Forge = fn(*mut SL_MEMBER, &Mem);
    let forgeries: [(&str, Forge); 4] = [
        ("pointer to another block", |m, mem| unsafe {
            (*m.add(1)).pBlock = estop_at(mem, 2048).cast();
        }),
        ("type tag", |m, _| unsafe { (*m.add(1)).nType = SL_TYPE_OR }),
        ("entries swapped", |m, _| unsafe {
            let (a, b) = (m.read(), m.add(1).read());
            m.write(b);
            m.add(1).write(a);
        }),
        ("check bytes", |m, _| unsafe {
            (*m.add(1)).aReserved[5] ^= 1
        }),
    ];
    for (what, forge) in forgeries {
        let mem = Mem::new();
        let (g, m, l, e) = running_pair(&mem);
        forge(m, &mem);
        // SAFETY: arena memory.
        unsafe {
            (*e).bEStopIn1 = 0;
            (*e).bEStopIn2 = 0;
        }
        let rc = gcycle(g, m, l, 30);
        assert_eq!(rc, SL_E_CORRUPT, "{what}");
        assert_eq!(state(g).nState, SL_STATE_ERROR, "{what}");
        assert_eq!((state(g).bInRun, state(g).bFbRun), (0, 0), "{what}");
    }
}

#[test]
fn a_copy_of_the_member_table_is_not_the_table() {
    let mem = Mem::new();
    let (g, m, l, e) = running_pair(&mem);
    let copy = mem.at::<SL_MEMBER>(3072);
    // SAFETY: arena memory.
    unsafe { std::ptr::copy_nonoverlapping(m, copy, usize::from(CAP)) };
    assert_stopped_with_corrupt(gcycle(g, copy, l, 30), g, e, false);
}

/// A NULL member or link table is the caller's NULL, not corrupt memory (ABI §5:
/// SL_E_NULL), and the group still takes its safe state (semantics GR16): ERROR, outputs
/// FALSE, FBERROR, acknowledged like any error once the tables are passed again.
#[test]
fn missing_member_table_stops_the_group() {
    let mem = Mem::new();
    let (g, m, l, e) = running_pair(&mem);
    let rc = gcycle(g, std::ptr::null_mut(), l, 30);
    assert_eq!(rc, SL_E_NULL);
    let gs = state(g);
    assert_eq!(gs.nState, SL_STATE_ERROR);
    assert_eq!((gs.bInRun, gs.bFbRun, gs.bFbErr), (0, 0, 1));
    assert_eq!(gs.nDiag, group::SL_GROUP_DIAG_FBERROR);
    // With the table again, the group runs its members (stopped) and is acknowledged.
    assert_eq!(gcycle(g, m, l, 40), SL_OK);
    // SAFETY: arena memory, read by value.
    assert_eq!(unsafe { (*e).bEStopOut }, 0);
    assert_eq!(state(g).nState, SL_STATE_ERROR);
    // A NULL link table for a group that has links: the same.
    let mem = Mem::new();
    let (g, m, _, _) = running_pair(&mem);
    assert_eq!(gcycle(g, m, std::ptr::null_mut(), 30), SL_E_NULL);
    assert_eq!(state(g).nState, SL_STATE_ERROR);
    assert_eq!((state(g).bInRun, state(g).bFbRun), (0, 0));
    // A stopped group stays stopped (GR7), still told SL_E_NULL.
    let mem = Mem::new();
    let (g, m, l) = group_in(&mem);
    assert_eq!(add(g, m, SL_TYPE_AND, and_at(&mem, 1024).cast()), SL_OK);
    assert_eq!(gcycle(g, std::ptr::null_mut(), l, 30), SL_E_NULL);
    assert_eq!(state(g).nState, SL_STATE_STOP);
    assert_eq!(state(g).bInRun, 0);
    // A member table inside the group is never read.
    let mem = Mem::new();
    let (g, _, l, _) = running_pair(&mem);
    assert_eq!(gcycle(g, mem.at(G + 8), l, 30), SL_E_CORRUPT);
    assert_eq!(state(g).nState, SL_STATE_ERROR);
}

#[test]
fn forged_links_stop_the_group() {
    type Forge = fn(*mut SL_LINK);
    let forgeries: [(&str, Forge); 4] = [
        ("destination offset", |l| unsafe {
            (*l).nDstOffset = offset_of!(FB_AND, bAndIn2) as u16
        }),
        ("source member", |l| unsafe { (*l).nSrcMember = 1 }),
        ("destination beyond the members", |l| unsafe {
            (*l).nDstMember = 7
        }),
        ("check bytes", |l| unsafe { (*l).aReserved[0] ^= 0x80 }),
    ];
    for (what, forge) in forgeries {
        let mem = Mem::new();
        let (g, m, l, e) = running_pair(&mem);
        forge(l);
        let rc = gcycle(g, m, l, 30);
        assert_eq!(rc, SL_E_CORRUPT, "{what}");
        assert_eq!(state(g).nState, SL_STATE_ERROR, "{what}");
        // SAFETY: arena memory, read by value.
        assert_eq!(unsafe { (*e).bEStopOut }, 0, "{what}");
        assert_eq!((state(g).bInRun, state(g).bFbRun), (0, 0), "{what}");
    }
}

/// Every single-bit change of a link (its fields or its check bytes) in a running, sealed
/// group is found in the next cycle: the link check and the schedule check bind every bit of
/// every field (a mutation-testing finding: a shift or an `&` in either check left bits
/// unbound, unnoticed by the hand-picked forgeries above).
#[test]
fn every_single_bit_forgery_of_a_link_stops_the_group() {
    for byte in 0..size_of::<SL_LINK>() {
        for bit in 0..8 {
            let mem = Mem::new();
            let (g, m, l, e) = running_pair(&mem);
            // SAFETY: arena memory; the link's bytes.
            unsafe { *l.cast::<u8>().add(byte) ^= 1 << bit };
            let rc = gcycle(g, m, l, 30);
            assert_eq!(rc, SL_E_CORRUPT, "byte {byte} bit {bit}");
            assert_stopped_with_corrupt(rc, g, e, true);
        }
    }
}

/// The same for every single-bit change of a member entry (block pointer, type tag, check
/// bytes), of the ESTOP's entry (member 0: it cannot be reached) and of the AND's (member
/// 1: the ESTOP that ran before it is stopped in the same cycle).
#[test]
fn every_single_bit_forgery_of_a_member_entry_stops_the_group() {
    for (entry, reachable) in [(0, false), (1, true)] {
        for byte in 0..size_of::<SL_MEMBER>() {
            for bit in 0..8 {
                let mem = Mem::new();
                let (g, m, l, e) = running_pair(&mem);
                // SAFETY: arena memory; the entry's bytes.
                unsafe { *m.add(entry).cast::<u8>().add(byte) ^= 1 << bit };
                let rc = gcycle(g, m, l, 30);
                assert_eq!(rc, SL_E_CORRUPT, "entry {entry} byte {byte} bit {bit}");
                assert_stopped_with_corrupt(rc, g, e, reachable);
            }
        }
    }
}

#[test]
fn forged_link_count_stops_the_group() {
    let mem = Mem::new();
    let (g, m, l, e) = running_pair(&mem);
    // A link count of 2 with one link: the second entry (zero) fails its check.
    let w = 2u32 | u32::from(CAP) << 16;
    // SAFETY: arena memory.
    unsafe {
        (*g).stPrivate.dwLinks = w;
        (*g).stPrivate.adwCheck[3] = !w;
    }
    assert_stopped_with_corrupt(gcycle(g, m, l, 30), g, e, true);
}

#[test]
fn ton2_elapsed_into_its_own_block_is_no_aliasing() {
    let mem = Mem::new();
    let t = mem.at::<FB_TON2>(512);
    // SAFETY: arena memory; the output lies inside the block (at tDelay), which the
    // function must only write through the raw pointer after reading the block.
    unsafe {
        t.write(FB_TON2 {
            tDelay: 100,
            ..Default::default()
        });
        ffi::sl_ton2_init(t);
        let out = std::ptr::addr_of_mut!((*t).tDelay);
        assert_eq!(ffi::sl_ton2_get_elapsed(t, out), SL_OK);
        assert_eq!((*t).tDelay, 0);
    }
}

/// Fuzz regression (target `group`, 2026-11-26): a member whose bytes the caller
/// re-initialises as another type (one whose private state lies where the member's does).
/// The tag inside the private header no longer matches, so
/// the member's own integrity check takes it for a corrupt instance of the member's type:
/// SL_E_CORRUPT for the cycle, and the member's invariants hold read as its own type (no
/// safety output TRUE after SL_E_CORRUPT). A TwinSAFE member enters ERROR and stops the
/// group; an `SF_` member with Activate FALSE returns to IDLE (semantics PO7), which the
/// group reads as STOP.
#[test]
fn member_reinitialised_as_another_type_is_corrupt() {
    for (member, other) in [
        (SL_TYPE_SF_GUARD, SL_TYPE_SF_ENABLESWITCH),
        (SL_TYPE_SF_EMERGENCYSTOP, SL_TYPE_SF_ESPE),
        (SL_TYPE_ESTOP, SL_TYPE_MON),
        (SL_TYPE_AND, SL_TYPE_OR),
    ] {
        let t = safelogic::registry::block_type(member).unwrap();
        let mem = Mem::new();
        let (g, m, l) = group_in(&mem);
        let b: *mut c_void = match member {
            SL_TYPE_ESTOP => estop_at(&mem, 1024).cast(),
            SL_TYPE_AND => and_at(&mem, 1024).cast(),
            _ => mem.at(1024),
        };
        if invariants::is_sf(t) {
            assert_eq!(init_fn(member)(b), SL_OK, "{member}");
        }
        assert_eq!(add(g, m, member, b), SL_OK, "{member}");
        // SAFETY: arena memory; no reference outlives a statement.
        unsafe { (*g).bRun = 1 };
        assert_eq!(gcycle(g, m, l, 0), SL_OK, "{member}");
        assert_eq!(state(g).nState, SL_STATE_RUN, "{member}");
        init_fn(other)(b);
        let rc = gcycle(g, m, l, 10);
        assert_eq!(rc, SL_E_CORRUPT, "{member} over {other}");
        // SAFETY: `t.size` bytes of arena memory from 1024, read by value.
        let bytes = unsafe { std::slice::from_raw_parts(mem.at::<u8>(1024), t.size) }.to_vec();
        invariants::check_any(t, &bytes, rc, "re-initialised as another type");
        if !invariants::is_sf(t) {
            let gs = state(g);
            assert_eq!(gs.nState, SL_STATE_ERROR, "{member} over {other}");
            assert_eq!((gs.bInRun, gs.bFbRun), (0, 0), "{member} over {other}");
        }
    }
}

/// A link count forged to 0 (with valid complements) leaves no link to fail its own check;
/// the entry after the count is then not as sl_group_init left it, which stops the group
/// like a link that failed its check (every member stopped in the same cycle, ERROR).
#[test]
fn link_count_forged_to_zero_stops_the_group() {
    let mem = Mem::new();
    let (g, m, l, e) = running_pair(&mem);
    let w = u32::from(CAP) << 16;
    // SAFETY: arena memory.
    unsafe {
        (*g).stPrivate.dwLinks = w;
        (*g).stPrivate.adwCheck[3] = !w;
    }
    assert_stopped_with_corrupt(gcycle(g, m, l, 30), g, e, true);
}

/// A running group takes no member, and refuses before it touches anything: a
/// never-initialised block stays all zero (it would be initialised first otherwise; a
/// mutation-testing finding).
#[test]
fn a_running_group_refuses_a_member_before_touching_it() {
    let mem = Mem::new();
    let (g, m, _, _) = running_pair(&mem);
    let b = mem.at::<FB_AND>(2048);
    assert_eq!(add(g, m, SL_TYPE_AND, b.cast()), SL_E_CONFIG);
    // SAFETY: arena memory, read by value.
    let bytes = unsafe { std::slice::from_raw_parts(b.cast::<u8>(), size_of::<FB_AND>()) };
    assert!(bytes.iter().all(|&x| x == 0), "the block was written");
    assert_eq!(state(g).nMembers, 2);
}

/// Fuzz regression (target `group`, 2026-11-26): an `SF_` member whose library fault stops
/// the group reports it in that cycle (its DiagCode, Ready and Error TRUE, its safety output
/// FALSE); from the next cycle on the group halts it (DiagCode 0000, semantics PO8).
#[test]
fn sf_member_library_fault_stops_the_group_and_is_halted_next() {
    let mem = Mem::new();
    let (g, m, l) = group_in(&mem);
    let b = mem.at::<SF_Equivalent>(1024);
    // SAFETY: arena memory; no reference outlives a statement.
    unsafe {
        b.write(SF_Equivalent {
            Activate: 1,
            DiscrepancyTime: 100,
            ..Default::default()
        });
        assert_eq!(ffi::sl_sf_equivalent_init(b), SL_OK);
        assert_eq!(add(g, m, SL_TYPE_SF_EQUIVALENT, b.cast()), SL_OK);
        (*g).bRun = 1;
        assert_eq!(gcycle(g, m, l, 0), SL_OK);
        ((*b).S_ChannelA, (*b).S_ChannelB) = (1, 1);
        assert_eq!(gcycle(g, m, l, 5), SL_OK);
        assert_eq!(((*b).DiagCode, (*b).S_EquivalentOut), (0x8000, 1));
        (*b).DiscrepancyTime = 200;
        assert_eq!(gcycle(g, m, l, 10), SL_E_PARAM_CHANGED);
        let gs = state(g);
        assert_eq!((gs.nState, gs.bFbRun), (SL_STATE_ERROR, 0));
        let e = b.read();
        assert_eq!(
            (e.DiagCode, e.Ready, e.Error, e.S_EquivalentOut),
            (SL_SF_DIAG_CONST_CHANGED, 1, 1, 0)
        );
        gcycle(g, m, l, 20);
        let e = b.read();
        assert_eq!((e.DiagCode, e.Ready, e.Error), (0, 0, 0));
    }
}
