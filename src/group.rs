//! The TwinSAFE group — manual §3.1, §3.1.1 (EL6910 group interface §3.1.1.2), §3.2.1.1,
//! §3.2.5 (group states and diagnostics); KL6904 manual §3.1.
//!
//! Blocks are members of a group, executed in the order they were added, all with the same
//! `tNow`; the group drives each member's bRun/bErrAck. When any member is in ERROR, or a
//! connection error or module fault is reported, the group enters ERROR and every member
//! is stopped (bRun FALSE) within the same group cycle — members that already ran in this
//! cycle are run once more with bRun FALSE, so their outputs are FALSE when the call
//! returns. Links copy a member output into a member input just before the destination
//! executes. No heap: member and link storage belong to the caller.
//!
//! FSoE connections (`SL_FSOE_CONN`, ABI-2 §13.5) are members too, before the blocks: they
//! run first in every cycle, their bComErr / bComStartup are ORed into the group's ComErr /
//! ComStartup (with the stand-ins bComErrIn / bComStartupIn), their SafeData bits are linked
//! with `SL_LINK_RXBIT` / `SL_LINK_TXBIT`, and a FB_CONNECTION_SHUTDOWN is wired to the
//! connection(s) with its Connection ID (docs/semantics.md FS17–FS21).

use crate::base::block::{Dir, Field, Kind};
use crate::base::bools::{any_invalid, bit_flags, edge, is_true};
use crate::base::member::*;
// The member interface, public here too: a user of the group implements or names it here.
pub use crate::base::member::{ConnReport, Member, Ran, Wiring, SL_GROUP_CONN_MAX};
use crate::base::types::*;
use core::ffi::c_void;

/// Copies a pending CONNECTION SHUTDOWN request to its connection(s): their
/// bShutdownRequest input (acted on in their next cycle).
#[inline(always)]
fn apply_request<M: Members + ?Sized>(m: &mut M, w: &mut Wiring) {
    if w.has_request() {
        deliver_request(m, w);
    }
}

/// The request of a CONNECTION SHUTDOWN block, to the connection(s) with its Connection ID.
#[inline(never)]
fn deliver_request<M: Members + ?Sized>(m: &mut M, w: &mut Wiring) {
    if let Some((v, idx, k)) = w.take_request() {
        for &i in &idx[..k] {
            m.with(usize::from(i), |b| {
                b.set_input_bits(crate::fsoe::member::OFFSET_SHUTDOWN_REQUEST, u32::from(v))
            });
        }
    }
}

/// The states (value, NUL-terminated name) of a group member type: a block's, or an FSoE
/// connection's (`SL_TYPE_FSOE_CONN`).
pub fn states(tag: u16) -> Option<&'static [(u8, &'static str)]> {
    if tag == crate::fsoe::SL_TYPE_FSOE_CONN {
        return Some(crate::fsoe::STATE_NAMES);
    }
    crate::registry::info(tag).map(|b| b.states)
}

/// Name of state `state` of member type `tag` ("?" for a value the type does not have).
pub fn state_name(tag: u16, state: u8) -> &'static str {
    states(tag)
        .and_then(|s| s.iter().find(|(v, _)| *v == state))
        .map_or("?", |(_, name)| name.trim_end_matches('\0'))
}

/// Link kind: BOOL output to BOOL input.
pub const SL_LINK_BOOL: u8 = 0;
/// Link kind: 16-bit analog output to a 16-bit analog input of the same type (INT or UINT).
pub const SL_LINK_ANALOG16: u8 = 1;
/// Link kind: 32-bit analog output to a 32-bit analog input of the same type (DINT or UDINT).
pub const SL_LINK_ANALOG32: u8 = 2;

/// Link kind (ABI-2 §10.7): bit `nSrcOffset` (byte · 8 + bit) of a connection's received
/// SafeData (`aRxSafeData`) to a BOOL input (0/1).
pub const SL_LINK_RXBIT: u8 = 3;
/// Link kind (ABI-2 §10.7): a BOOL output to bit `nDstOffset` (byte · 8 + bit) of a
/// connection's SafeData to send (`aTxSafeData`).
pub const SL_LINK_TXBIT: u8 = 4;

/// The link kind that carries a field of this type (`None`: not linkable).
pub fn link_kind(k: Kind) -> Option<u8> {
    match k {
        Kind::Bool => Some(SL_LINK_BOOL),
        Kind::I16 | Kind::U16 => Some(SL_LINK_ANALOG16),
        Kind::I32 | Kind::U32 => Some(SL_LINK_ANALOG32),
        Kind::U8 => None,
    }
}

/// The field of `b` at `offset` in direction `dir`.
fn field_at(b: &dyn Member, offset: u16, dir: Dir) -> Option<Field> {
    b.fields()
        .iter()
        .find(|f| f.offset == offset && f.dir == dir)
        .copied()
}

/// Group state START (6): connections still starting up.
pub const SL_GROUP_STATE_START: u8 = 6;
/// Group state STOPERROR (7): started with connections assigned; Run leads to ERROR.
pub const SL_GROUP_STATE_STOPERROR: u8 = 7;

/// Group diag value: no error.
pub const SL_GROUP_DIAG_NONE: u16 = 0;
/// Group diag value FBERROR: at least one member is in ERROR.
pub const SL_GROUP_DIAG_FBERROR: u16 = 1;
/// Group diag value COMERROR: at least one connection is faulty.
pub const SL_GROUP_DIAG_COMERROR: u16 = 2;
/// Group diag value MODULEERROR: the input ModuleFault is TRUE.
pub const SL_GROUP_DIAG_MODULEERROR: u16 = 3;
/// Group diag value RESTARTERROR: the group was started with connections (STOPERROR).
pub const SL_GROUP_DIAG_RESTARTERROR: u16 = 6;

/// No member index.
pub const SL_NO_MEMBER: u16 = 0xFFFF;

/// One member entry in caller storage (written only by `sl_group_add_member`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_MEMBER {
    /// The block instance (`FB_<NAME> *`).
    pub pBlock: *mut c_void,
    /// SL_TYPE_* of the block.
    pub nType: u16,
    /// Private: the group's check of this entry (its block, type, place and the group's
    /// member count and capacity). Never write it: an entry that fails it is a member error.
    pub aReserved: [u8; 6],
}

impl Default for SL_MEMBER {
    fn default() -> Self {
        Self {
            pBlock: core::ptr::null_mut(),
            nType: 0,
            aReserved: [0; 6],
        }
    }
}

/// One link in caller storage: output byte `nSrcOffset` of member `nSrcMember` is copied
/// to input byte `nDstOffset` of member `nDstMember` just before the destination runs.
/// Size: 12 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_LINK {
    pub nSrcMember: u16,
    pub nSrcOffset: u16,
    pub nDstMember: u16,
    pub nDstOffset: u16,
    /// SL_LINK_BOOL, SL_LINK_ANALOG16 or SL_LINK_ANALOG32 (the type of both fields).
    pub nKind: u8,
    /// Private: the group's check of this link (its fields, place and the link count).
    /// Never write it: a link that fails it is a member error of its destination.
    pub aReserved: [u8; 3],
}

/// One step of the entry checks: a bijection of `h` for a fixed word, so a change of any
/// single word always changes the result.
const fn mix(h: u64, w: u64) -> u64 {
    let h = (h ^ w).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    h ^ (h >> 29)
}

/// [`mix`] of each word in turn into `seed`: each field of a check is its own word.
fn fold(seed: u64, words: &[u64]) -> u64 {
    words.iter().fold(seed, |h, w| mix(h, *w))
}

/// The check a member entry carries in `aReserved` (48 bits): binds the block pointer and
/// type to the group (`group`: its address), the entry's own address (`entry`, so a copied
/// or moved entry fails), its index, and the group's member count, member capacity and link
/// capacity (`shape`: so a forged count or capacity of either table fails every entry, and
/// entry 0 vouches for the link capacity before any link past the count is read).
pub fn member_check(
    group: usize,
    entry: usize,
    index: u16,
    shape: [u16; 3],
    block: usize,
    ty: u16,
) -> [u8; 6] {
    let [count, cap, link_cap] = shape;
    let h = fold(
        0x5AFE_10C1_6A05_0001,
        &[
            group as u64,
            entry as u64,
            u64::from(index),
            u64::from(count),
            u64::from(cap),
            u64::from(link_cap),
            block as u64,
            u64::from(ty),
        ],
    );
    let b = h.to_le_bytes();
    [b[0], b[1], b[2], b[3], b[4], b[5]]
}

/// The sealed schedule's check (docs/performance.md), in steps: where the tables are and
/// how many entries they hold, then every member entry and every link, in order, as their
/// bytes ([`schedule_words`]). One multiply per entry or link, a bijection of its lane's
/// running value: a change of any single entry or link always changes its lane, and the
/// lanes are folded into the check by bijections too ([`schedule_end`]).
pub fn schedule_start(group: usize, members: usize, count: u16, cap: u16, links: usize) -> Lanes {
    // The three sizes side by side in one word (each below 2^16, the links' below 2^32).
    let sizes = u64::from(count) | u64::from(cap) << 16 | (links as u64) << 32;
    let h = fold(
        0x5AFE_10C1_6A05_0003,
        &[group as u64, members as u64, sizes],
    );
    // Every lane starts alike: lanes that traded their whole sequences still differ in
    // the end, where each is rotated by its own amount.
    [h; LANES]
}

/// How many running values the schedule check keeps: entry `i` of a table goes into lane
/// `i % LANES`, so the multiplies of neighbouring entries do not wait for each other (as one
/// chain, the 2,000 multiplies of a 1,000-member group were ~2 µs of latency per cycle).
pub const LANES: usize = 4;

/// The schedule check's running values ([`LANES`]).
pub type Lanes = [u64; LANES];

/// Every entry of a table into the lanes, entry `i` into lane `i % LANES`; `words`: an
/// entry's bytes as two words.
#[inline(always)]
pub fn schedule_table<T>(mut lanes: Lanes, table: &[T], words: impl Fn(&T) -> [u64; 2]) -> Lanes {
    let mut rounds = table.chunks_exact(LANES);
    for round in &mut rounds {
        for (lane, t) in lanes.iter_mut().zip(round) {
            let [w0, w1] = words(t);
            *lane = schedule_words(*lane, w0, w1);
        }
    }
    for (lane, t) in lanes.iter_mut().zip(rounds.remainder()) {
        let [w0, w1] = words(t);
        *lane = schedule_words(*lane, w0, w1);
    }
    lanes
}

/// A member entry's bytes as words for the schedule check (the block's address, then the
/// type and the entry's own check).
#[inline(always)]
pub fn member_words(e: &SL_MEMBER) -> [u64; 2] {
    let [t0, t1] = e.nType.to_le_bytes();
    let [r0, r1, r2, r3, r4, r5] = e.aReserved;
    [
        e.pBlock as usize as u64,
        u64::from_le_bytes([t0, t1, r0, r1, r2, r3, r4, r5]),
    ]
}

/// A link's bytes as words for the schedule check (bytes 0–7, bytes 8–11).
#[inline(always)]
pub fn link_words(l: &SL_LINK) -> [u64; 2] {
    let [a0, a1] = l.nSrcMember.to_le_bytes();
    let [b0, b1] = l.nSrcOffset.to_le_bytes();
    let [c0, c1] = l.nDstMember.to_le_bytes();
    let [d0, d1] = l.nDstOffset.to_le_bytes();
    let [r0, r1, r2] = l.aReserved;
    [
        u64::from_le_bytes([a0, a1, b0, b1, c0, c1, d0, d1]),
        u64::from(u32::from_le_bytes([l.nKind, r0, r1, r2])),
    ]
}

/// One member entry (its two 64-bit words) or one link (its 64-bit and 32-bit words) into
/// a lane of the schedule check: both words folded into one step (a change of either alone
/// always changes it).
#[inline(always)]
pub fn schedule_words(h: u64, w0: u64, w1: u64) -> u64 {
    step(h, w0 ^ w1.rotate_left(32))
}

/// The last step: the lanes side by side (each rotated by its own amount, so a change of
/// any one lane changes their sum) into one mixing step; 48 bits, the width stored in the group.
pub fn schedule_end(lanes: Lanes) -> u64 {
    let [a, b, c, d] = lanes;
    mix(
        a ^ b.rotate_left(16) ^ c.rotate_left(32) ^ d.rotate_left(48),
        0,
    ) & 0xFFFF_FFFF_FFFF
}

/// The cheap step per word (xor, multiply by an odd constant: a bijection).
#[inline(always)]
const fn step(h: u64, w: u64) -> u64 {
    (h ^ w).wrapping_mul(0x9E37_79B9_7F4A_7C15)
}

/// The check a link carries in `aReserved` (24 bits): its fields, its index and the
/// group's link count (no address: a Rust caller may move its link array).
pub fn link_check(l: &SL_LINK, index: usize, count: u16) -> [u8; 3] {
    let h = fold(
        0x5AFE_10C1_6A05_0002,
        &[
            u64::from(l.nSrcMember),
            u64::from(l.nSrcOffset),
            u64::from(l.nDstMember),
            u64::from(l.nDstOffset),
            u64::from(l.nKind),
            index as u64,
            u64::from(count),
        ],
    );
    let b = h.to_le_bytes();
    [b[0], b[1], b[2]]
}

/// The group's links in caller storage, read by value (a link array that some member
/// overlaps is then merely corrupt, never aliased).
pub trait Links {
    /// Number of entries.
    fn count(&self) -> usize;
    /// Entry `i`.
    fn get(&self, i: usize) -> Option<SL_LINK>;
    /// Entry `i`'s destination member (what a cycle reads first of every link).
    fn dst(&self, i: usize) -> Option<u16>;
    /// All entries, for a sealed cycle's straight run.
    fn as_slice(&self) -> &[SL_LINK];
    /// Entry `i` (the one after the last link) is unused as far as the group can tell. The
    /// C tables (`ffi`): beyond the capacity, or all zero as `sl_group_init` left it, since a
    /// link count forged lower would otherwise drop the links past it unnoticed when no link
    /// is left to fail its own check (a count of 0). A Rust caller's slice: what follows the
    /// group's links is the caller's (a longer array).
    fn unused(&self, _i: usize) -> bool {
        true
    }
}

impl Links for [SL_LINK] {
    fn count(&self) -> usize {
        self.len()
    }
    fn get(&self, i: usize) -> Option<SL_LINK> {
        <[SL_LINK]>::get(self, i).copied()
    }
    fn dst(&self, i: usize) -> Option<u16> {
        <[SL_LINK]>::get(self, i).map(|l| l.nDstMember)
    }
    fn as_slice(&self) -> &[SL_LINK] {
        self
    }
}

/// Private state of a group (32 bytes): data words and their complements.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_GROUP_PRIVATE {
    /// wMagic | nState << 16 | nFlags << 24.
    pub dwCtrl: u32,
    /// nDiag | nFailed << 16.
    pub dwDiag: u32,
    /// nMembers | nMemberCap << 16.
    pub dwMembers: u32,
    /// nLinks | nLinkCap << 16.
    pub dwLinks: u32,
    /// Complements of the four words above.
    pub adwCheck: [u32; 4],
}

/// A TwinSAFE group with the EL6910 interface (manual §3.1.1.2, §3.2.5).
/// Size: 64 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_GROUP {
    /// Offset 0. Run/Stop: TRUE executes the members.
    pub bRun: SL_BOOL,
    /// Offset 1. Err Ack: FALSE→TRUE→FALSE acknowledges group and member errors.
    pub bErrAck: SL_BOOL,
    /// Offset 2. Module Fault: error output of another module (→ OtherErr, group ERROR).
    pub bModuleFault: SL_BOOL,
    /// Offset 3. A connection of the group reports an error (until connections are members).
    pub bComErrIn: SL_BOOL,
    /// Offset 4. A connection of the group is still starting up.
    pub bComStartupIn: SL_BOOL,
    /// Offset 5. Parameter: TRUE = connections are assigned (start in STOPERROR).
    pub bConnections: SL_BOOL,
    /// Offset 6. Reserved, keep 0.
    pub aReserved0: [u8; 2],
    /// Offset 8. Communication error in at least one connection.
    pub bComErr: SL_BOOL,
    /// Offset 9. Error in at least one member.
    pub bFbErr: SL_BOOL,
    /// Offset 10. Not used (FALSE).
    pub bOutErr: SL_BOOL,
    /// Offset 11. ModuleFault.
    pub bOtherErr: SL_BOOL,
    /// Offset 12. At least one connection is starting up.
    pub bComStartup: SL_BOOL,
    /// Offset 13. The group is deactivated (never: no customizing).
    pub bFbDeactive: SL_BOOL,
    /// Offset 14. All members are in RUN.
    pub bFbRun: SL_BOOL,
    /// Offset 15. The group is in RUN.
    pub bInRun: SL_BOOL,
    /// Offset 16. Group state (1 RUN, 2 STOP, 4 ERROR, 5 RESET, 6 START, 7 STOPERROR).
    pub nState: u8,
    /// Offset 17. Reserved.
    pub aReserved1: [u8; 1],
    /// Offset 18. Group diag value (0 none, 1 FBERROR, 2 COMERROR, 3 MODULEERROR, 6 RESTARTERROR).
    pub nDiag: u16,
    /// Offset 20. Index of the member whose ERROR stopped the group (0xFFFF: none).
    pub nFailedMember: u16,
    /// Offset 22. Number of members.
    pub nMembers: u16,
    /// Offset 24. Number of links.
    pub nLinks: u16,
    /// Offset 26. Private: the check of the member and link tables that the last fully
    /// checked cycle found intact (the sealed schedule, docs/performance.md). Never write it:
    /// a value that does not match only costs one fully checked cycle.
    pub awSchedule: [u16; 3],
    /// Offset 32. Private state, 32 bytes: never write it.
    pub stPrivate: SL_GROUP_PRIVATE,
}

const MAGIC: u32 = 0x6A05;
bit_flags!(u8:
    /// Previous ErrAck level.
    F_ACK_PREV,
    /// Latched error causes (cleared on ERROR → RESET).
    F_FB, F_COM, F_MODULE,
    /// A connection member reported bComStartup in the previous cycle.
    F_CONN_STARTUP,
);

/// The group's private data, unpacked.
#[derive(Clone, Copy, Debug, Default)]
struct Core {
    state: u8,
    flags: u8,
    diag: u16,
    failed: u16,
    members: u16,
    member_cap: u16,
    links: u16,
    link_cap: u16,
}

impl SL_GROUP_PRIVATE {
    fn words(&self) -> [u32; 4] {
        [self.dwCtrl, self.dwDiag, self.dwMembers, self.dwLinks]
    }

    fn load(&self) -> Option<Core> {
        let w = self.words();
        let intact = w.iter().zip(&self.adwCheck).all(|(&d, &c)| c == !d) && w[0] & 0xFFFF == MAGIC;
        let c = Core {
            state: (w[0] >> 16) as u8,
            flags: (w[0] >> 24) as u8,
            diag: w[1] as u16,
            failed: (w[1] >> 16) as u16,
            members: w[2] as u16,
            member_cap: (w[2] >> 16) as u16,
            links: w[3] as u16,
            link_cap: (w[3] >> 16) as u16,
        };
        (intact && c.members <= c.member_cap && c.links <= c.link_cap).then_some(c)
    }

    fn store(&mut self, c: &Core) {
        self.dwCtrl = MAGIC | (u32::from(c.state) << 16) | (u32::from(c.flags) << 24);
        self.dwDiag = u32::from(c.diag) | (u32::from(c.failed) << 16);
        self.dwMembers = u32::from(c.members) | (u32::from(c.member_cap) << 16);
        self.dwLinks = u32::from(c.links) | (u32::from(c.link_cap) << 16);
        let w = self.words();
        self.adwCheck = [!w[0], !w[1], !w[2], !w[3]];
    }
}

/// Access to the members of a group by index, in execution order.
pub trait Members {
    /// Runs `f` on member `i`; `None` when the entry does not hold a usable block.
    fn with<R>(&mut self, i: usize, f: impl FnOnce(&mut dyn Member) -> R) -> Option<R>;

    /// The check of the member and link tables as they are now (48 bits), for storage
    /// whose entries carry checks of their own (the C tables); `None`: no sealed schedule.
    fn schedule_check<L: Links + ?Sized>(&self, _links: &L) -> Option<u64> {
        None
    }

    /// Member `i` in a sealed cycle: its entry is one that a fully checked cycle found
    /// intact, so its own check is not repeated.
    fn run_sealed(&mut self, i: usize, run: u8, ack: u8, now: u32, w: &mut Wiring) -> Option<Ran> {
        self.with(i, |b| b.run_in_group(run, ack, now, w))
    }

    /// A sealed cycle's straight run from member `at.0` and link `at.1` up to member
    /// `members` ([`Straight`]), the members' bRun and bErrAck as one word (`drive`:
    /// `run | ack << 8`); storage without runners runs nothing straight.
    #[allow(clippy::too_many_arguments)]
    fn run_straight<L: Links + ?Sized>(
        &mut self,
        _links: &L,
        _link_count: usize,
        at: (usize, usize),
        _members: usize,
        _drive: u16,
        _now: u32,
        _w: &mut Wiring,
    ) -> Straight {
        Straight::at(at)
    }

    /// A BOOL or analog link in a sealed cycle (both ends checked when it was added).
    fn copy_sealed(&mut self, l: &SL_LINK) {
        copy_link(self, l, usize::from(l.nDstMember));
    }
}

impl Members for [&mut dyn Member] {
    fn with<R>(&mut self, i: usize, f: impl FnOnce(&mut dyn Member) -> R) -> Option<R> {
        self.get_mut(i).map(|m| f(&mut **m))
    }
}

/// The next cycle over these tables runs the sealed schedule.
pub fn is_sealed<M: Members + ?Sized, L: Links + ?Sized>(g: &SL_GROUP, m: &M, links: &L) -> bool {
    m.schedule_check(links)
        .is_some_and(|s| s == stored_schedule(g))
}

/// The schedule check stored in the group.
fn stored_schedule(g: &SL_GROUP) -> u64 {
    let [[a0, a1], [b0, b1], [c0, c1]] = g.awSchedule.map(u16::to_le_bytes);
    u64::from_le_bytes([a0, a1, b0, b1, c0, c1, 0, 0])
}

fn store_schedule(g: &mut SL_GROUP, check: u64) {
    g.awSchedule = [check as u16, (check >> 16) as u16, (check >> 32) as u16];
}

fn initial_state(g: &SL_GROUP) -> u8 {
    if g.bConnections == 1 {
        SL_GROUP_STATE_STOPERROR
    } else {
        SL_STATE_STOP
    }
}

fn write_info(g: &mut SL_GROUP, c: &Core) {
    g.nState = c.state;
    g.nDiag = c.diag;
    g.nFailedMember = c.failed;
    g.nMembers = c.members;
    g.nLinks = c.links;
    g.stPrivate.store(c);
}

/// Resets a group to power-up with room for `member_cap` members and `link_cap` links in
/// the caller's storage. Does not modify the input fields.
pub fn init(g: &mut SL_GROUP, member_cap: u16, link_cap: u16) -> i32 {
    if !init_valid(g) {
        return SL_E_CONFIG;
    }
    let c = Core {
        state: initial_state(g),
        failed: SL_NO_MEMBER,
        member_cap,
        link_cap,
        ..Core::default()
    };
    set_outputs(g, &c, false, false, Conns::default());
    write_info(g, &c);
    SL_OK
}

/// The group's parameters allow an init (checked before anything is changed).
/// A group that is running (RUN, START) refuses a re-init: its members would be detached
/// with their outputs as they are (docs/semantics.md GR13). Stop it first (bRun FALSE).
pub fn init_valid(g: &SL_GROUP) -> bool {
    let running = g
        .stPrivate
        .load()
        .is_some_and(|c| matches!(c.state, SL_STATE_RUN | SL_GROUP_STATE_START));
    g.bConnections <= 1 && !running
}

/// Member count and capacity (`None`: the private state is corrupt).
pub fn member_counts(g: &SL_GROUP) -> Option<(u16, u16)> {
    g.stPrivate.load().map(|c| (c.members, c.member_cap))
}

/// Link count and capacity (`None`: the private state is corrupt).
pub fn link_counts(g: &SL_GROUP) -> Option<(u16, u16)> {
    g.stPrivate.load().map(|c| (c.links, c.link_cap))
}

/// Members may be added or linked now (STOP or STOPERROR); `Err` is the refusal.
pub fn configurable(g: &SL_GROUP) -> Result<(), i32> {
    let c = g.stPrivate.load().ok_or(SL_E_CORRUPT)?;
    if c.state != SL_STATE_STOP && c.state != SL_GROUP_STATE_STOPERROR {
        return Err(SL_E_CONFIG);
    }
    Ok(())
}

/// Reserves the next member index (execution order). The caller stores the entry.
pub fn reserve_member(g: &mut SL_GROUP) -> Result<u16, i32> {
    let mut c = g.stPrivate.load().ok_or(SL_E_CORRUPT)?;
    if c.state != SL_STATE_STOP && c.state != SL_GROUP_STATE_STOPERROR {
        return Err(SL_E_CONFIG);
    }
    if c.members >= c.member_cap {
        return Err(SL_E_FULL);
    }
    let index = c.members;
    c.members += 1;
    write_info(g, &c);
    Ok(index)
}

/// Adds a BOOL link, keeping the link storage sorted by destination member (stable), so
/// that one pass over the members copies every link just before its destination runs.
pub fn add_link<M: Members + ?Sized>(
    g: &mut SL_GROUP,
    m: &mut M,
    links: &mut [SL_LINK],
    link: SL_LINK,
) -> i32 {
    let Some(mut c) = g.stPrivate.load() else {
        return SL_E_CORRUPT;
    };
    if c.state != SL_STATE_STOP && c.state != SL_GROUP_STATE_STOPERROR {
        return SL_E_CONFIG;
    }
    if c.links >= c.link_cap || usize::from(c.links) >= links.len() {
        return SL_E_FULL;
    }
    let n = usize::from(c.links);
    let in_group = |i: u16| i < c.members;
    // The field of a member in the group at an offset, in one direction.
    let mut field = |member: u16, offset: u16, dir: Dir| {
        in_group(member)
            .then(|| m.with(usize::from(member), |b| field_at(b, offset, dir)))
            .flatten()
            .flatten()
    };
    let src = field(link.nSrcMember, link.nSrcOffset, Dir::Output);
    let dst = field(link.nDstMember, link.nDstOffset, Dir::Input);
    // SafeData bits (ABI-2 §10.7): the bit must lie in the connection's latched length.
    let src_bits = in_group(link.nSrcMember)
        .then(|| m.with(usize::from(link.nSrcMember), |b| b.safe_data_bits()))
        .flatten();
    let dst_bits = in_group(link.nDstMember)
        .then(|| m.with(usize::from(link.nDstMember), |b| b.safe_data_bits()))
        .flatten();
    let typed = match link.nKind {
        SL_LINK_RXBIT => {
            let dst_bool = dst.is_some_and(|f| f.kind == Kind::Bool);
            dst_bool && src_bits.is_some_and(|(rx, _)| link.nSrcOffset < rx)
        }
        SL_LINK_TXBIT => {
            let src_bool = src.is_some_and(|f| f.kind == Kind::Bool);
            src_bool && dst_bits.is_some_and(|(_, tx)| link.nDstOffset < tx)
        }
        // Same IEC type on both ends (width and signedness), carried by the stated kind.
        _ => match (src, dst) {
            (Some(s), Some(d)) => s.kind == d.kind && link_kind(s.kind) == Some(link.nKind),
            _ => false,
        },
    };
    // A TXBIT destination is a bit number, every other one a byte offset.
    let tx = link.nKind == SL_LINK_TXBIT;
    let taken = links[..n].iter().any(|l| {
        l.nDstMember == link.nDstMember
            && l.nDstOffset == link.nDstOffset
            && (l.nKind == SL_LINK_TXBIT) == tx
    });
    if !typed || taken {
        return SL_E_CONFIG;
    }
    let at = links[..n].partition_point(|l| l.nDstMember <= link.nDstMember);
    links.copy_within(at..n, at + 1);
    links[at] = link;
    c.links += 1;
    for (i, l) in links[..=n].iter_mut().enumerate() {
        l.aReserved = link_check(l, i, c.links);
    }
    write_info(g, &c);
    SL_OK
}

/// The connections' bComErr / bComStartup of this cycle (ORed into the group's).
#[derive(Clone, Copy, Debug, Default)]
struct Conns {
    com_err: bool,
    startup: bool,
}

fn set_outputs(g: &mut SL_GROUP, c: &Core, member_error: bool, all_run: bool, k: Conns) {
    g.bComErr = u8::from(c.flags & F_COM != 0 || g.bComErrIn != 0 || k.com_err);
    g.bFbErr = u8::from(c.flags & F_FB != 0 || member_error);
    g.bOutErr = 0;
    g.bOtherErr = u8::from(c.flags & F_MODULE != 0 || g.bModuleFault != 0);
    g.bComStartup = u8::from(g.bComStartupIn != 0 || k.startup);
    g.bFbDeactive = 0;
    g.bInRun = u8::from(c.state == SL_STATE_RUN);
    g.bFbRun = u8::from(c.state == SL_STATE_RUN && all_run);
}

/// Enters ERROR with a cause; the first cause is the diag value.
fn enter_error(c: &mut Core, flag: u8, diag: u16) {
    if c.state != SL_STATE_ERROR {
        c.diag = diag;
    }
    c.state = SL_STATE_ERROR;
    c.flags |= flag;
}

/// One group cycle: group state, then every member in order with its links.
/// Returns the group's status, or the worst status a member returned.
pub fn cycle<M: Members + ?Sized>(g: &mut SL_GROUP, m: &mut M, links: &[SL_LINK], now: u32) -> i32 {
    cycle_with(g, m, links, now)
}

/// [`cycle`] over any link storage.
pub fn cycle_with<M: Members + ?Sized, L: Links + ?Sized>(
    g: &mut SL_GROUP,
    m: &mut M,
    links: &L,
    now: u32,
) -> i32 {
    cycle_traced(g, m, links, now, &mut 0)
}

/// [`cycle_with`], also adding to `straight` the members the sealed schedule ran straight
/// (`run_straight`), for the tests that pin it (the count is not observable otherwise: the
/// member loop gives the same results, only slower).
#[doc(hidden)]
pub fn cycle_traced<M: Members + ?Sized, L: Links + ?Sized>(
    g: &mut SL_GROUP,
    m: &mut M,
    links: &L,
    now: u32,
    straight: &mut usize,
) -> i32 {
    let Some(mut c) = g.stPrivate.load() else {
        // Member count and storage size are unknown: no member can be reached safely.
        g.bInRun = 0;
        g.bFbRun = 0;
        g.nState = SL_STATE_ERROR;
        return SL_E_CORRUPT;
    };
    let inputs = [
        g.bRun,
        g.bErrAck,
        g.bModuleFault,
        g.bComErrIn,
        g.bComStartupIn,
    ];
    let mut status = Status::Ok;
    if any_invalid(&inputs) {
        status = Status::InvalidBool;
    }
    // Invalid bytes: Run and ErrAck read FALSE, the fault inputs read TRUE (ABI §2).
    let run = is_true(g.bRun);
    let ack = edge(g.bErrAck, &mut c.flags, F_ACK_PREV);
    let module_fault = g.bModuleFault != 0;
    let com_err = g.bComErrIn != 0;
    // The connections' start-up as of their last cycle (they run again below).
    let startup = g.bComStartupIn != 0 || c.flags & F_CONN_STARTUP != 0;
    let was_error = c.state == SL_STATE_ERROR;

    // Transitions driven by the group's own inputs.
    c.state = match c.state {
        SL_STATE_STOP if run => {
            if startup {
                SL_GROUP_STATE_START
            } else {
                SL_STATE_RUN
            }
        }
        SL_GROUP_STATE_STOPERROR if run => {
            enter_error(&mut c, 0, SL_GROUP_DIAG_RESTARTERROR);
            SL_STATE_ERROR
        }
        SL_STATE_RUN | SL_GROUP_STATE_START if !run => SL_STATE_STOP,
        SL_STATE_RESET if ack.falling => {
            if !run {
                SL_STATE_STOP
            } else if startup {
                SL_GROUP_STATE_START
            } else {
                SL_STATE_RUN
            }
        }
        SL_GROUP_STATE_START if !startup => SL_STATE_RUN,
        SL_STATE_RUN if startup => SL_GROUP_STATE_START,
        s => s,
    };
    if matches!(c.state, SL_STATE_RUN | SL_GROUP_STATE_START) {
        if module_fault {
            enter_error(&mut c, F_MODULE, SL_GROUP_DIAG_MODULEERROR);
        }
        if com_err {
            enter_error(&mut c, F_COM, SL_GROUP_DIAG_COMERROR);
        }
    }

    // The members, in order, each right after its incoming links. Connections are the
    // first members (sl_group_add_member), so their bComErr / bComStartup of this cycle
    // reach the group before any block runs.
    let ack_level = u8::from(ack.level);
    let mut member_run = u8::from(c.state == SL_STATE_RUN);
    let mut member_error = false;
    let mut all_run = c.members > 0;
    let mut conns = Conns::default();
    let mut w = Wiring::default();
    let mut next_link = 0usize;
    let link_count = links.count().min(usize::from(c.links));
    // The sealed schedule (docs/performance.md): tables equal to those a fully checked
    // cycle found intact need no check per entry and link; any other cycle checks every
    // one, and seals the tables when it found them all intact.
    let schedule = m.schedule_check(links);
    let sealed = schedule.is_some_and(|s| s == stored_schedule(g));
    // A checked cycle also finds the C link table's tail as sl_group_init left it: else
    // every member counts as having a link that failed its check (stopped, ERROR).
    let tail_intact = sealed || links.unused(usize::from(c.links));
    let mut all_intact = true;
    let members = usize::from(c.members);
    let mut i = 0;
    while i < members {
        // A sealed cycle runs the plain stretches of the schedule straight; the member that
        // needs more (or every member, otherwise) takes the steps below.
        let mut ran_straight = None;
        if sealed {
            let s = m.run_straight(
                links,
                link_count,
                (i, next_link),
                members,
                u16::from_le_bytes([member_run, ack_level]),
                now,
                &mut w,
            );
            all_run &= s.all_run;
            let (member, link) = (s.member as usize, s.link as usize);
            *straight += member - i;
            (i, next_link, ran_straight) = (member, link, s.ran());
            if i == members {
                break;
            }
        }
        let outcome = if let Some(outcome) = ran_straight {
            outcome
        } else {
            let mut links_intact = tail_intact;
            while next_link < link_count
                && links.dst(next_link).is_some_and(|d| usize::from(d) == i)
            {
                let Some(l) = links.get(next_link) else { break };
                next_link += 1;
                if sealed && l.nKind <= SL_LINK_ANALOG32 {
                    m.copy_sealed(&l);
                    continue;
                }
                // A link that fails its check is not copied: its destination is stopped.
                links_intact &= sealed || l.aReserved == link_check(&l, next_link - 1, c.links);
                if !links_intact {
                    continue;
                }
                copy_link(m, &l, i);
            }
            all_intact &= links_intact;
            if sealed {
                m.run_sealed(i, member_run, ack_level, now, &mut w)
            } else if links_intact {
                m.with(i, |b| b.run_in_group(member_run, ack_level, now, &mut w))
            } else {
                m.with(i, |b| b.run_in_group(0, ack_level, now, &mut w));
                None
            }
        };
        all_intact &= outcome.is_some();
        apply_request(m, &mut w);
        // A member that cannot be reached is a member error of the group, never a skip.
        let ran = outcome.unwrap_or(Ran {
            status: Status::Corrupt,
            state: SL_STATE_ERROR,
            conn: None,
        });
        status = status.worst(ran.status);
        let mut stop_earlier = false;
        if let Some(r) = ran.conn {
            // An FSoE connection: its errors are the group's ComErr, never a member error.
            w.connection(i as u16, &r);
            conns.com_err |= r.com_err;
            conns.startup |= r.startup;
            if r.com_err && matches!(c.state, SL_STATE_RUN | SL_GROUP_STATE_START) {
                enter_error(&mut c, F_COM, SL_GROUP_DIAG_COMERROR);
                stop_earlier = member_run != 0;
            } else if r.startup && c.state == SL_STATE_RUN {
                c.state = SL_GROUP_STATE_START;
                stop_earlier = true;
            }
        } else {
            all_run &= ran.state == SL_STATE_RUN;
            if ran.state == SL_STATE_ERROR {
                member_error = true;
                if c.state == SL_STATE_RUN || c.state == SL_GROUP_STATE_START {
                    enter_error(&mut c, F_FB, SL_GROUP_DIAG_FBERROR);
                    c.failed = i as u16;
                    stop_earlier = true;
                }
            }
        }
        if stop_earlier {
            // Members that already ran with bRun TRUE stop within this same cycle (this
            // one too when it is a connection: it presents no SafeData).
            member_run = 0;
            let last = if ran.conn.is_some() { i + 1 } else { i };
            for j in 0..last {
                if sealed {
                    m.run_sealed(j, 0, ack_level, now, &mut w);
                } else {
                    m.with(j, |b| b.run_in_group(0, ack_level, now, &mut w));
                }
                apply_request(m, &mut w);
            }
        }
        member_run &= u8::from(c.state == SL_STATE_RUN);
        i += 1;
    }

    // A link that no member consumed (forged destination or order) was not applied: the
    // group stops every member, as for a member error.
    if next_link < link_count {
        status = status.worst(Status::Corrupt);
        member_error = true;
        all_run = false;
        if c.state == SL_STATE_RUN || c.state == SL_GROUP_STATE_START {
            enter_error(&mut c, F_FB, SL_GROUP_DIAG_FBERROR);
            for j in 0..usize::from(c.members) {
                m.with(j, |b| b.run_in_group(0, ack_level, now, &mut w));
                apply_request(m, &mut w);
            }
        }
    }
    if let Some(check) = schedule.filter(|_| !sealed && all_intact && next_link == link_count) {
        store_schedule(g, check);
    }
    if conns.startup {
        c.flags |= F_CONN_STARTUP;
    } else {
        c.flags &= !F_CONN_STARTUP;
    }

    // Acknowledgement, after the members saw the same ErrAck edge.
    if c.state == SL_STATE_ERROR
        && was_error
        && ack.rising
        && !member_error
        && !module_fault
        && !com_err
        && !conns.com_err
    {
        c.state = SL_STATE_RESET;
        c.diag = SL_GROUP_DIAG_NONE;
        c.failed = SL_NO_MEMBER;
        c.flags &= !(F_FB | F_COM | F_MODULE);
    }
    set_outputs(g, &c, member_error, all_run, conns);
    write_info(g, &c);
    status.code()
}

/// Where a sealed cycle's straight run handed back to the member loop.
///
/// The straight run (docs/performance.md, [`Members::run_straight`]): for a member whose
/// incoming links are all BOOL or analog copies and which ends its cycle as a block (not a
/// connection, not a CONNECTION SHUTDOWN block) outside ERROR with SL_OK, all the member
/// loop does is copy the links, run it, and fold its state into the group's — so that is
/// all the straight run does, with no per-member bookkeeping beyond it. It hands back at the
/// first member that needs more: before an FSoE bit link, or after a run whose outcome the
/// loop must see (a member that cannot be reached, ERROR, another status, a connection, a
/// CONNECTION SHUTDOWN block, which may leave a request). The group's state does not change
/// while it runs, so `run` holds throughout.
///
/// Sixteen bytes, so that it comes back in two registers (the indices fit: counts are 16-bit).
pub struct Straight {
    /// The member the loop goes on with (the member count: all ran).
    pub member: u32,
    /// The next link.
    pub link: u32,
    /// The word of `member`'s outcome when it already ran (it goes through the loop's
    /// steps, [`Straight::ran`]); [`RAN_NOT_RUN`]: it did not run yet, its links from `link`
    /// on not copied.
    pub word: RanWord,
    /// Every member that ran straight ended its cycle in RUN.
    pub all_run: bool,
}

impl Straight {
    /// Nothing ran straight: the loop goes on at member `at.0`, link `at.1`.
    pub fn at(at: (usize, usize)) -> Self {
        Straight {
            member: at.0 as u32,
            link: at.1 as u32,
            word: RAN_NOT_RUN,
            all_run: true,
        }
    }

    /// `Some(outcome)`: `member` already ran (`None` inside: it could not be reached);
    /// `None`: it did not run yet.
    pub fn ran(&self) -> Option<Option<Ran>> {
        (self.word & RAN_NOT_RUN == 0).then(|| Ran::of_word(self.word))
    }
}

/// Copies one link's value to its destination, member `dst` (ABI-2 §10.7 for the bits).
fn copy_link<M: Members + ?Sized>(m: &mut M, l: &SL_LINK, dst: usize) {
    let src = usize::from(l.nSrcMember);
    let (off, to) = (l.nSrcOffset, l.nDstOffset);
    match l.nKind {
        SL_LINK_RXBIT => {
            if let Some(Some(v)) = m.with(src, |b| b.rx_bit(off)) {
                m.with(dst, |b| b.set_input_bits(to, u32::from(v)));
            }
        }
        SL_LINK_TXBIT => {
            if let Some(Some(v)) = m.with(src, |b| b.output(off)) {
                m.with(dst, |b| b.set_tx_bit(to, v));
            }
        }
        _ => {
            if let Some(Some(v)) = m.with(src, |b| b.output_bits(off)) {
                m.with(dst, |b| b.set_input_bits(to, v));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const K: u64 = 0x9E37_79B9_7F4A_7C15;

    /// The inverse of the odd multiplier modulo 2^64 (Newton's iteration).
    fn k_inverse() -> u64 {
        let mut inv = K;
        for _ in 0..6 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(K.wrapping_mul(inv)));
        }
        inv
    }

    /// The inverse of `x ↦ x ^ (x >> 29)`.
    fn unshift(y: u64) -> u64 {
        let mut x = y;
        for _ in 0..3 {
            x = y ^ (x >> 29);
        }
        x
    }

    fn words(n: usize) -> impl Iterator<Item = (u64, u64)> {
        let mut r = 0x5AFE_10C1_u64;
        let mut next = move || {
            r ^= r << 13;
            r ^= r >> 7;
            r ^= r << 17;
            r
        };
        (0..n).map(move |_| (next(), next()))
    }

    /// `mix` and `step` are bijections of the running value for a fixed word (what makes a
    /// change of any single word change every check): each is undone exactly.
    #[test]
    fn mix_and_step_are_bijections() {
        let inv = k_inverse();
        assert_eq!(K.wrapping_mul(inv), 1);
        for (h, w) in words(10_000) {
            assert_eq!(unshift(mix(h, w)).wrapping_mul(inv) ^ w, h);
            assert_eq!(step(h, w).wrapping_mul(inv) ^ w, h);
        }
    }

    /// A block's outcome survives its word for every status and every state, and no such
    /// word has a flag bit set; the flags read as they should.
    #[test]
    fn ran_word_gives_back_every_block_outcome() {
        for code in -12..=0 {
            let status = Status::from_code(code);
            assert_eq!(status.code(), code, "every code in the range is a status");
            for state in 0..=u8::MAX {
                let word = Ran::word(status, state);
                assert!(word < RAN_UNREACHABLE);
                let ran = Ran::of_word(word);
                assert_eq!(
                    ran,
                    Some(Ran {
                        status,
                        state,
                        conn: None
                    })
                );
            }
        }
        assert_eq!(Ran::of_word(RAN_UNREACHABLE), None);
    }

    /// Every connection of a cycle is kept: each one's shutdown is found by its own
    /// Connection ID, and a request reaches exactly the connections with its ID.
    #[test]
    fn wiring_keeps_every_connection() {
        let mut w = Wiring::default();
        for (i, id) in [(0u16, 7u16), (1, 8), (2, 9), (3, 7)] {
            let r = ConnReport {
                id,
                shutdown: i == 0 || i == 2,
                ..ConnReport::default()
            };
            w.connection(i, &r);
        }
        assert_eq!([7, 8, 9].map(|id| w.conn_shutdown(id)), [1, 0, 1]);
        w.request(7, 1);
        let (v, idx, k) = w.take_request().unwrap();
        assert_eq!((v, &idx[..k]), (1, &[0u16, 3][..]));
        assert!(w.take_request().is_none());
    }

    /// The whole check over tables of every length up to three rounds of lanes (the whole
    /// rounds and every remainder): a single-bit change of any word of any entry, or two
    /// different entries trading places, changes it.
    #[test]
    fn schedule_check_sees_every_entry_at_every_length() {
        for n in 0..12 {
            let table: Vec<[u64; 2]> = words(n).map(|(a, b)| [a, b]).collect();
            let check = |t: &[[u64; 2]]| {
                let lanes = schedule_start(0x1000, 0x2000, n as u16, 16, 3);
                Some(schedule_end(schedule_table(lanes, t, |w| *w)))
            };
            let base = check(&table).unwrap();
            for i in 0..n {
                for (word, bit) in (0..2).flat_map(|w| (0..64).map(move |b| (w, b))) {
                    let mut t = table.clone();
                    t[i][word] ^= 1 << bit;
                    assert_ne!(
                        check(&t),
                        Some(base),
                        "entry {i} of {n}, word {word}, bit {bit}"
                    );
                }
                for j in i + 1..n {
                    let mut t = table.clone();
                    t.swap(i, j);
                    assert_ne!(check(&t), Some(base), "entries {i} and {j} of {n}");
                }
            }
            // Two lanes that trade their whole sequences (every entry of lane 0 with the one
            // after it, in lane 1).
            if n >= 2 {
                let mut t = table.clone();
                for i in (0..n - 1).step_by(LANES) {
                    t.swap(i, i + 1);
                }
                assert_ne!(check(&t), Some(base), "lanes 0 and 1 of {n} traded");
            }
        }
    }

    /// A single-bit change of any word the check starts from (the group's and the member
    /// table's addresses, the count, the capacity, the link count) changes the check, with
    /// or without entries after it.
    #[test]
    fn schedule_check_sees_every_bit_of_where_and_how_many() {
        let start = (
            0x7F00_1234_5670usize,
            0x7F00_8765_4320usize,
            5u16,
            9u16,
            7usize,
        );
        for n in [0, 1, 5] {
            let table: Vec<[u64; 2]> = words(n).map(|(a, b)| [a, b]).collect();
            let check = |(g, m, count, cap, links): (usize, usize, u16, u16, usize)| {
                schedule_end(schedule_table(
                    schedule_start(g, m, count, cap, links),
                    &table,
                    |w| *w,
                ))
            };
            let base = check(start);
            let (g, m, count, cap, links) = start;
            for bit in 0..usize::BITS {
                assert_ne!(
                    check((g ^ 1 << bit, m, count, cap, links)),
                    base,
                    "group {bit}"
                );
                assert_ne!(
                    check((g, m ^ 1 << bit, count, cap, links)),
                    base,
                    "table {bit}"
                );
                if bit < 16 {
                    let b = 1u16 << bit;
                    assert_ne!(check((g, m, count ^ b, cap, links)), base, "count {bit}");
                    assert_ne!(check((g, m, count, cap ^ b, links)), base, "cap {bit}");
                }
                if bit < 32 {
                    let b = 1usize << bit;
                    assert_ne!(check((g, m, count, cap, links ^ b)), base, "links {bit}");
                }
            }
        }
    }

    /// A single-bit change of either word of an entry or link changes its schedule step.
    #[test]
    fn schedule_words_sees_every_bit_of_both_words() {
        for (h, w) in words(200) {
            let base = schedule_words(h, w, w.rotate_left(7));
            for bit in 0..64 {
                assert_ne!(schedule_words(h, w ^ 1 << bit, w.rotate_left(7)), base);
                assert_ne!(schedule_words(h, w, w.rotate_left(7) ^ 1 << bit), base);
            }
        }
    }
}
