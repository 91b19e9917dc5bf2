//! The group scenario of the state explorer (docs/testing.md, "State exploration"): a
//! TwinSAFE group with connections assigned (`bConnections`: its `bComErrIn` and
//! `bComStartupIn` inputs stand in for an FSoE connection, semantics GR12), an ESTOP
//! feeding an AND through a link, explored through the real C functions (`sl_group_init`,
//! `sl_group_add_member`, `sl_group_add_link`, `sl_group_cycle`) breadth first over every
//! combination of the group's inputs, the ESTOP's inputs and the AND's other input, with
//! the invalid byte in each, until no new state appears.
//!
//! The whole installation lives in one caller-allocated arena at a fixed address, so a
//! reached state is the arena's bytes: it is restored by copying them back. A second arena
//! runs every transition 2^30 ms later (as the block explorer's copy B) to find the time
//! stamps, which the canonical form keeps relative to tNow; the words that differ between
//! the two arenas from the start are their own addresses (the member pointers), restored
//! per arena and checked unchanged; the schedule check over the tables' addresses (GR15)
//! is arena A's in every copy.

use super::{Figures, NOW_A, SHIFT};
use safelogic::ffi::{
    sl_and_init, sl_estop_init, sl_group_add_link, sl_group_add_member, sl_group_cycle,
    sl_group_init,
};
use safelogic::group::{
    SL_GROUP_DIAG_RESTARTERROR, SL_GROUP_STATE_START, SL_GROUP_STATE_STOPERROR,
};
use safelogic::registry::block_type_named;
use safelogic::*;
use std::collections::{BTreeSet, HashMap, VecDeque};
use std::mem::{offset_of, size_of};
use std::time::Instant;

/// The installation: the group, its tables and its two members, in one block of memory.
#[repr(C, align(8))]
#[derive(Default)]
struct Arena {
    g: SL_GROUP,
    members: [SL_MEMBER; 2],
    links: [SL_LINK; 1],
    estop: FB_ESTOP,
    and: FB_AND,
}

const SIZE: usize = size_of::<Arena>();

/// ESTOP's discrepancy time (ms): two task cycles, so that the discrepancy error (a member
/// error that stops the group) is reached.
pub const DISC_TIME: u32 = 20;
/// The task cycle: every explored call is one cycle later (the scenario replays exactly).
pub const CYCLE: u32 = 10;

/// The driven inputs: process-image name, place in the project, byte offset in the arena,
/// and the value an invalid byte is read as (semantics GR9: Run and ErrAck FALSE, the
/// connection's error and start-up TRUE; a block's input FALSE). `bModuleFault` stays
/// FALSE: it takes the group to ERROR exactly as `bComErrIn` does (GR7), with another
/// diag value, and would double the inputs.
pub const INPUTS: [(&str, &str, usize, u8); 8] = [
    (
        "Run",
        "safety.bRun",
        offset_of!(Arena, g) + offset_of!(SL_GROUP, bRun),
        0,
    ),
    (
        "ErrAck",
        "safety.bErrAck",
        offset_of!(Arena, g) + offset_of!(SL_GROUP, bErrAck),
        0,
    ),
    (
        "ComErr",
        "safety.bComErrIn",
        offset_of!(Arena, g) + offset_of!(SL_GROUP, bComErrIn),
        1,
    ),
    (
        "ComStartup",
        "safety.bComStartupIn",
        offset_of!(Arena, g) + offset_of!(SL_GROUP, bComStartupIn),
        1,
    ),
    (
        "S1",
        "estop.bEStopIn1",
        offset_of!(Arena, estop) + offset_of!(FB_ESTOP, bEStopIn1),
        0,
    ),
    (
        "S2",
        "estop.bEStopIn2",
        offset_of!(Arena, estop) + offset_of!(FB_ESTOP, bEStopIn2),
        0,
    ),
    (
        "Restart",
        "estop.bRestart",
        offset_of!(Arena, estop) + offset_of!(FB_ESTOP, bRestart),
        0,
    ),
    (
        "In2",
        "k1.bAndIn2",
        offset_of!(Arena, and) + offset_of!(FB_AND, bAndIn2),
        0,
    ),
];
const RUN: usize = 0;
const ERRACK: usize = 1;
const COM_ERR: usize = 2;
const IN2: usize = 7;

/// The observed outputs: process-image name, place, byte offset.
pub const OUTPUTS: [(&str, &str, usize); 3] = [
    (
        "EStopOut",
        "estop.bEStopOut",
        offset_of!(Arena, estop) + offset_of!(FB_ESTOP, bEStopOut),
    ),
    (
        "EStopDelOut",
        "estop.bEStopDelOut",
        offset_of!(Arena, estop) + offset_of!(FB_ESTOP, bEStopDelOut),
    ),
    (
        "K1",
        "k1.bAndOut",
        offset_of!(Arena, and) + offset_of!(FB_AND, bAndOut),
    ),
];
const ESTOP_OUT: usize = 0;
const K1: usize = 2;

const G_STATE: usize = offset_of!(Arena, g) + offset_of!(SL_GROUP, nState);
const G_DIAG: usize = offset_of!(Arena, g) + offset_of!(SL_GROUP, nDiag);
const SCHEDULE: usize = offset_of!(Arena, g) + offset_of!(SL_GROUP, awSchedule);
const ESTOP_STATE: usize = offset_of!(Arena, estop) + offset_of!(FB_ESTOP, nState);

/// The group's states (manual §3.2.5, semantics GR1): DEACTIVE and WAITCOMERROR belong to
/// EL6910 customizing, which the library does not have.
pub const GROUP_STATES: [(u8, &str); 6] = [
    (SL_STATE_RUN, "RUN"),
    (SL_STATE_STOP, "STOP"),
    (SL_STATE_ERROR, "ERROR"),
    (SL_STATE_RESET, "RESET"),
    (SL_GROUP_STATE_START, "START"),
    (SL_GROUP_STATE_STOPERROR, "STOPERROR"),
];

pub fn group_state_name(v: u8) -> &'static str {
    GROUP_STATES
        .iter()
        .find(|(s, _)| *s == v)
        .map_or("?", |(_, n)| n)
}

fn estop_state_name(v: u8) -> &'static str {
    safelogic::group::state_name(SL_TYPE_ESTOP, v)
}

impl Arena {
    /// A new installation, every call checked: ESTOP (inputs 1 and 2 active, discrepancy
    /// time `DISC_TIME`), AND (both inputs active), the link ESTOP.bEStopOut → AND.bAndIn1,
    /// and a group with connections assigned.
    fn install() -> Box<Arena> {
        let mut a = Box::<Arena>::default();
        a.estop.wInputActive = 0b11;
        a.estop.tDiscTime12 = DISC_TIME;
        a.and.wInputActive = 0b11;
        a.g.bConnections = 1;
        let p: *mut Arena = &mut *a;
        // SAFETY: `p` points to the boxed arena, which stays in place for the whole
        // exploration; every table and block is a field of it (disjoint, aligned).
        unsafe {
            assert_eq!(sl_estop_init(&raw mut (*p).estop), SL_OK);
            assert_eq!(sl_and_init(&raw mut (*p).and), SL_OK);
            let members = (&raw mut (*p).members).cast::<SL_MEMBER>();
            let links = (&raw mut (*p).links).cast::<SL_LINK>();
            assert_eq!(sl_group_init(&raw mut (*p).g, members, 2, links, 1), SL_OK);
            let mut idx = 0u16;
            let estop = (&raw mut (*p).estop).cast();
            assert_eq!(
                sl_group_add_member(&raw mut (*p).g, members, SL_TYPE_ESTOP, estop, &mut idx),
                SL_OK
            );
            let and = (&raw mut (*p).and).cast();
            assert_eq!(
                sl_group_add_member(&raw mut (*p).g, members, SL_TYPE_AND, and, &mut idx),
                SL_OK
            );
            let (so, d) = (offset_of!(FB_ESTOP, bEStopOut), offset_of!(FB_AND, bAndIn1));
            assert_eq!(
                sl_group_add_link(&raw mut (*p).g, members, links, 0, so as u16, 1, d as u16),
                SL_OK
            );
        }
        a
    }

    fn bytes(&self) -> &[u8] {
        // SAFETY: the arena is plain integer fields and pointers, SIZE initialised bytes.
        unsafe { std::slice::from_raw_parts((self as *const Arena).cast(), SIZE) }
    }

    fn load(&mut self, b: &[u8]) {
        // SAFETY: `b` holds SIZE bytes taken from an arena; its pointer words are this
        // arena's own (restored by the caller), so every pointer stays valid.
        unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), (self as *mut Arena).cast(), SIZE) }
    }

    /// Writes the input byte at offset `o` (one of `INPUTS`).
    fn set(&mut self, o: usize, v: u8) {
        assert!(o < SIZE);
        // SAFETY: `o` lies within the arena, whose every byte is an integer field's.
        unsafe { *(self as *mut Arena).cast::<u8>().add(o) = v }
    }

    fn cycle(&mut self, now: u32) -> i32 {
        let p: *mut Arena = self;
        // SAFETY: the tables and blocks are this arena's fields, installed by `install`.
        unsafe {
            sl_group_cycle(
                &raw mut (*p).g,
                (&raw mut (*p).members).cast(),
                (&raw mut (*p).links).cast(),
                now,
            )
        }
    }
}

fn word(b: &[u8], o: usize) -> u32 {
    u32::from_le_bytes(b[o..o + 4].try_into().unwrap())
}

/// One explored call: the driven inputs' bytes (2 = the invalid byte).
pub type Step = [u8; INPUTS.len()];

/// A violated group invariant with the shortest trace to it.
pub struct GroupViolation {
    pub what: String,
    pub trace: Vec<Step>,
    pub group_state: &'static str,
    pub estop_state: &'static str,
    pub outputs: Vec<(&'static str, u8)>,
}

/// Every input combination: all valid ones, and for each input the invalid byte with every
/// other input FALSE and with every other input TRUE.
fn combos() -> Vec<Step> {
    let mut out: Vec<Step> = (0..1u32 << INPUTS.len())
        .map(|m| std::array::from_fn(|i| u8::from(m & (1 << i) != 0)))
        .collect();
    for i in 0..INPUTS.len() {
        for other in [0, 1] {
            let mut s = [other; INPUTS.len()];
            s[i] = 2;
            out.push(s);
        }
    }
    out
}

/// The group invariants over one call: `b` before (with the previous call's inputs), `a`
/// after, `safe` the same call with each invalid byte replaced by its documented reading.
fn check(
    b: &[u8],
    a: &[u8],
    prev_ack: u8,
    step: &Step,
    rc: i32,
    safe: Option<&[u8]>,
) -> Option<String> {
    let invalid = step.iter().any(|&x| x > 1);
    if !(rc == SL_OK || invalid && rc == SL_E_INVALID_BOOL) {
        return Some(format!("status {rc} is not documented for this call"));
    }
    let (gb, ga) = (b[G_STATE], a[G_STATE]);
    let out = |i: usize| a[OUTPUTS[i].2];
    // Outputs TRUE only while the group runs its members (GR4: a stopped or failed group
    // leaves every member in STOP, outputs FALSE, by the end of the same cycle).
    if ga != SL_STATE_RUN {
        if let Some((n, ..)) = OUTPUTS.iter().find(|o| a[o.2] != 0) {
            return Some(format!(
                "{n} TRUE with the group in {}",
                group_state_name(ga)
            ));
        }
    }
    // K1 needs both of its inputs: the ESTOP's output of this cycle (the link from an
    // earlier member carries this cycle's value, GR8) and In2 TRUE.
    if out(K1) != 0 && (out(ESTOP_OUT) != 1 || step[IN2] != 1) {
        return Some("K1 TRUE without EStopOut and In2 both TRUE".into());
    }
    // A connection error (or the invalid byte, read TRUE) never leaves the group in RUN.
    if ga == SL_STATE_RUN && step[COM_ERR] != 0 {
        return Some("the group is in RUN with ComErrIn TRUE".into());
    }
    // A member in ERROR stops a running group in the same cycle (GR4).
    if a[ESTOP_STATE] == SL_STATE_ERROR
        && matches!(gb, SL_STATE_RUN | SL_GROUP_STATE_START)
        && ga != SL_STATE_ERROR
    {
        return Some(format!(
            "ESTOP in ERROR, the group left RUN for {}",
            group_state_name(ga)
        ));
    }
    // ERROR is left only to RESET, on a rising ErrAck edge (GR3).
    if gb == SL_STATE_ERROR && ga != SL_STATE_ERROR {
        let rising = prev_ack == 0 && step[ERRACK] == 1;
        if ga != SL_STATE_RESET || !rising {
            return Some(format!(
                "the group left ERROR for {} without a rising ErrAck edge",
                group_state_name(ga)
            ));
        }
    }
    // Power-up with connections: STOPERROR is left only into ERROR with diag 6 (GR2).
    if gb == SL_GROUP_STATE_STOPERROR && ga != gb {
        let diag = u16::from_le_bytes([a[G_DIAG], a[G_DIAG + 1]]);
        if ga != SL_STATE_ERROR || diag != SL_GROUP_DIAG_RESTARTERROR {
            return Some(format!(
                "STOPERROR left for {} with diag {diag}",
                group_state_name(ga)
            ));
        }
        if step[RUN] != 1 {
            return Some("STOPERROR left without Run TRUE".into());
        }
    }
    // An invalid byte never makes an output TRUE that its documented reading leaves FALSE.
    if let Some(s) = safe {
        if let Some((n, ..)) = OUTPUTS.iter().find(|o| a[o.2] > s[o.2]) {
            return Some(format!(
                "{n} TRUE with an invalid input byte, FALSE with its reading"
            ));
        }
    }
    None
}

/// Explores the group scenario. Returns the figures, the group and ESTOP states reached,
/// and the first violation (breadth first: a shortest trace).
pub fn explore() -> (Figures, BTreeSet<u8>, BTreeSet<u8>, Option<GroupViolation>) {
    let t0 = Instant::now();
    let mut a = Arena::install();
    let mut b = Arena::install();
    let mut c = Arena::install();
    // The words that differ between two installations are addresses: restored per arena.
    let own_a = a.bytes().to_vec();
    let own_b = b.bytes().to_vec();
    let own_c = c.bytes().to_vec();
    let addr: Vec<bool> = (0..SIZE / 4)
        .map(|w| own_a[w * 4..w * 4 + 4] != own_b[w * 4..w * 4 + 4])
        .collect();
    let with_own = |bytes: &[u8], own: &[u8]| -> Vec<u8> {
        let mut v = bytes.to_vec();
        for (w, &is_addr) in addr.iter().enumerate() {
            if is_addr {
                v[w * 4..w * 4 + 4].copy_from_slice(&own[w * 4..w * 4 + 4]);
            }
        }
        v
    };
    let is_input: Vec<bool> = (0..SIZE).map(|o| INPUTS.iter().any(|i| i.2 == o)).collect();
    let clamp = DISC_TIME + CYCLE;
    // A state: the canonical bytes (inputs zeroed, time stamps relative, addresses those
    // of arena A), its stamp words, and the previous call's ErrAck level (for the edge).
    type Key = (Vec<u8>, Vec<(usize, bool)>, u8);
    let materialize = |k: &Key, own: &[u8], now: u32| -> Vec<u8> {
        let mut v = with_own(&k.0, own);
        for &(o, complement) in &k.1 {
            let abs = now.wrapping_sub(word(&v, o));
            v[o..o + 4].copy_from_slice(&(if complement { !abs } else { abs }).to_le_bytes());
        }
        v
    };
    let start: Key = (own_a.clone(), vec![], 0);
    let mut index: HashMap<Key, usize> = HashMap::from([(start.clone(), 0)]);
    // (state, parent and the step from it, depth)
    type Node = (Key, Option<(usize, Step)>, usize);
    let mut nodes: Vec<Node> = vec![(start, None, 0)];
    let mut queue = VecDeque::from([0usize]);
    let mut fig = Figures {
        configs: 1,
        ..Default::default()
    };
    let mut group_seen = BTreeSet::from([own_a[G_STATE]]);
    let mut estop_seen = BTreeSet::from([own_a[ESTOP_STATE]]);
    let all = combos();
    while let Some(n) = queue.pop_front() {
        let (key, _, depth) = nodes[n].clone();
        let before_a = materialize(&key, &own_a, NOW_A);
        let before_b = materialize(&key, &own_b, NOW_A.wrapping_add(SHIFT));
        for step in &all {
            let now = NOW_A.wrapping_add(CYCLE);
            a.load(&before_a);
            b.load(&before_b);
            for (inp, &x) in INPUTS.iter().zip(step) {
                a.set(inp.2, x);
                b.set(inp.2, x);
            }
            let rc = a.cycle(now);
            let rc_b = b.cycle(now.wrapping_add(SHIFT));
            fig.transitions += 1;
            let (ba, bb) = (a.bytes().to_vec(), b.bytes().to_vec());
            let safe = step.iter().any(|&x| x > 1).then(|| {
                c.load(&materialize(&key, &own_c, NOW_A));
                for (inp, &x) in INPUTS.iter().zip(step) {
                    c.set(inp.2, if x > 1 { inp.3 } else { x });
                }
                c.cycle(now);
                c.bytes().to_vec()
            });
            let mut what = check(&before_a, &ba, key.2, step, rc, safe.as_deref());
            // Copy A against copy B: equal, or a time stamp 2^30 ms apart (or its complement).
            let mut stamps = Vec::new();
            if what.is_none() && rc != rc_b {
                what = Some(format!("status {rc} at the wrap, {rc_b} 2^30 ms later"));
            }
            for (w, &is_addr) in addr.iter().enumerate() {
                if what.is_some() {
                    break;
                }
                let o = w * 4;
                // The schedule check (GR15) hashes the tables' addresses: arena B is given
                // arena A's, fails it and runs the checked path, so the two arenas also
                // compare the sealed and the checked cycle; only the hash itself differs.
                if (SCHEDULE..SCHEDULE + 6).any(|x| x / 4 == w) {
                    continue;
                }
                if is_addr {
                    if ba[o..o + 4] != own_a[o..o + 4] || bb[o..o + 4] != own_b[o..o + 4] {
                        what = Some(format!("the address word at {o} changed"));
                    }
                    continue;
                }
                if ba[o..o + 4] == bb[o..o + 4] {
                    continue;
                }
                let d = word(&bb, o).wrapping_sub(word(&ba, o));
                if d == SHIFT {
                    stamps.push((o, false));
                } else if d == SHIFT.wrapping_neg() {
                    stamps.push((o, true));
                } else {
                    what = Some(format!(
                        "word at {o}: {:#010x} at the wrap, {:#010x} 2^30 ms later",
                        word(&ba, o),
                        word(&bb, o)
                    ));
                }
            }
            group_seen.insert(ba[G_STATE]);
            estop_seen.insert(ba[ESTOP_STATE]);
            if let Some(what) = what {
                let mut trace = vec![*step];
                let mut p = n;
                while let Some((parent, s)) = nodes[p].1 {
                    trace.push(s);
                    p = parent;
                }
                trace.reverse();
                fig.secs = t0.elapsed().as_secs_f64();
                fig.states = nodes.len();
                let v = GroupViolation {
                    what,
                    trace,
                    group_state: group_state_name(ba[G_STATE]),
                    estop_state: estop_state_name(ba[ESTOP_STATE]),
                    outputs: OUTPUTS.iter().map(|o| (o.0, ba[o.2])).collect(),
                };
                return (fig, group_seen, estop_seen, Some(v));
            }
            let mut canon = ba.clone();
            for (o, &inp) in is_input.iter().enumerate() {
                if inp {
                    canon[o] = 0;
                }
            }
            for &(o, complement) in &stamps {
                let w = if complement {
                    !word(&canon, o)
                } else {
                    word(&canon, o)
                };
                let rel = (now.wrapping_sub(w) as i32).clamp(-(clamp as i32), clamp as i32);
                canon[o..o + 4].copy_from_slice(&(rel as u32).to_le_bytes());
            }
            let next: Key = (canon, stamps, u8::from(step[ERRACK] == 1));
            if !index.contains_key(&next) {
                let k = nodes.len();
                index.insert(next.clone(), k);
                nodes.push((next, Some((n, *step)), depth + 1));
                fig.depth = fig.depth.max(depth + 1);
                queue.push_back(k);
            }
        }
    }
    fig.states = nodes.len();
    fig.secs = t0.elapsed().as_secs_f64();
    (fig, group_seen, estop_seen, None)
}

/// (project file, scenario file) of a group violation: the installation as a project,
/// one 10 ms task cycle per explored call, the offending call's states and outputs as the
/// last step's expectations.
pub fn files(v: &GroupViolation) -> (String, String) {
    assert!(block_type_named("ESTOP").is_some());
    let mut p = String::from(
        "# The explorer's group scenario: ESTOP -> AND, connections assigned (ComErrIn and\n\
         # ComStartupIn stand in for an FSoE connection).\n",
    );
    p += &format!("[project]\nname = \"explore group\"\ncycle = \"{CYCLE} ms\"\n\n");
    p += "[[group]]\nname = \"safety\"\nconnections = true\n";
    p += "links = [\"estop.bEStopOut -> k1.bAndIn1\"]\n\n";
    p += &format!(
        "[[group.member]]\nname = \"estop\"\ntype = \"ESTOP\"\nactive = [\"bEStopIn1\", \"bEStopIn2\"]\ntDiscTime12 = \"{DISC_TIME} ms\"\n\n"
    );
    p += "[[group.member]]\nname = \"k1\"\ntype = \"AND\"\nactive = [\"bAndIn1\", \"bAndIn2\"]\n\n[inputs]\n";
    for (n, place, ..) in INPUTS {
        p += &format!("{n} = \"{place}\"\n");
    }
    p += "\n[outputs]\n";
    for (n, place, _) in OUTPUTS {
        p += &format!("{n} = \"{place}\"\n");
    }
    let mut s = format!(
        "# The explorer's shortest trace to: {}\n[scenario]\nname = \"group: {}\"\n",
        v.what,
        v.what.replace('"', "'")
    );
    for (k, step) in v.trace.iter().enumerate() {
        // The first explored call is the first task cycle after power-up.
        let t = k as u32 * CYCLE;
        let sets: Vec<String> = INPUTS
            .iter()
            .zip(step)
            .map(|((n, ..), &x)| format!("{n} = {}", x != 0))
            .collect();
        s += &format!(
            "\n[[step]]\nat = \"{t} ms\"\nset = {{ {} }}\n",
            sets.join(", ")
        );
        if k + 1 == v.trace.len() {
            let mut ex = vec![
                format!("\"safety.state\" = \"{}\"", v.group_state),
                format!("\"estop.state\" = \"{}\"", v.estop_state),
            ];
            ex.extend(v.outputs.iter().map(|(n, x)| format!("{n} = {}", *x == 1)));
            s += &format!("expect = {{ {} }}\n", ex.join(", "));
        }
        if step.iter().any(|&x| x > 1) {
            s += "note = \"invalid BOOL byte 2 replayed as TRUE\"\n";
        }
    }
    (p, s)
}
