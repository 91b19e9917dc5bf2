//! The state explorer: every block type run through its C functions (`sl_<name>_init`,
//! `sl_<name>_cycle`) from every reachable state under every input combination and every
//! relevant time step, breadth first, until no new state appears (docs/testing.md,
//! "State exploration"). The blocks are driven generically from the registry's field
//! tables; the invariants are in `invariants.rs`, the configurations in `configs.rs`, the
//! scenario writer in `scenario.rs`.

pub mod configs;
pub mod group;
pub mod invariants;
pub mod scenario;

use safelogic::registry::{BlockType, Dir, Field, Kind, Registered};
use safelogic::SL_E_INVALID_BOOL;
use std::collections::{HashMap, VecDeque};
use std::time::Instant;

/// The C entry points of one block type, as a C caller holds them.
#[derive(Clone, Copy)]
pub struct Api {
    pub init: fn(*mut u8) -> i32,
    pub cycle: fn(*mut u8, u32) -> i32,
}

macro_rules! api_table {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// The C functions of the block type with this tag.
        pub fn api(tag: u16) -> Api {
            $(if tag == <$ty as Registered>::INFO.tag {
                return Api {
                    // SAFETY: `p` points to a live, 8-aligned buffer of the type's size
                    // (`Instance`), as the C functions require.
                    init: |p| unsafe { safelogic::ffi::$init(p.cast()) },
                    // SAFETY: as above.
                    cycle: |p, now| unsafe { safelogic::ffi::$cycle(p.cast(), now) },
                };
            })*
            panic!("no block type with tag {tag}")
        }
    };
}
safelogic::for_each_block!(api_table);

/// A block instance in C memory: the struct's bytes in an 8-aligned buffer.
#[derive(Clone)]
pub struct Instance {
    words: Vec<u64>,
    size: usize,
}

impl Instance {
    pub fn new(size: usize) -> Self {
        Instance {
            words: vec![0; size.div_ceil(8)],
            size,
        }
    }
    pub fn bytes(&self) -> &[u8] {
        // SAFETY: the buffer holds at least `size` initialised bytes; u8 has no alignment.
        unsafe { std::slice::from_raw_parts(self.words.as_ptr().cast(), self.size) }
    }
    pub fn bytes_mut(&mut self) -> &mut [u8] {
        // SAFETY: as in `bytes`, uniquely borrowed.
        unsafe { std::slice::from_raw_parts_mut(self.words.as_mut_ptr().cast(), self.size) }
    }
    pub fn from_bytes(b: &[u8]) -> Self {
        let mut i = Instance::new(b.len());
        i.bytes_mut().copy_from_slice(b);
        i
    }
    fn ptr(&mut self) -> *mut u8 {
        self.words.as_mut_ptr().cast()
    }
    pub fn get(&self, f: &Field) -> i64 {
        read(self.bytes(), usize::from(f.offset), f.kind)
    }
    pub fn set(&mut self, f: &Field, v: i64) {
        write(self.bytes_mut(), usize::from(f.offset), f.kind, v)
    }
}

pub fn read(b: &[u8], o: usize, k: Kind) -> i64 {
    match k {
        Kind::Bool | Kind::U8 => i64::from(b[o]),
        Kind::U16 => i64::from(u16::from_le_bytes([b[o], b[o + 1]])),
        Kind::I16 => i64::from(i16::from_le_bytes([b[o], b[o + 1]])),
        Kind::U32 => i64::from(u32::from_le_bytes(b[o..o + 4].try_into().unwrap())),
        Kind::I32 => i64::from(i32::from_le_bytes(b[o..o + 4].try_into().unwrap())),
    }
}

fn write(b: &mut [u8], o: usize, k: Kind, v: i64) {
    match k {
        Kind::Bool | Kind::U8 => b[o] = v as u8,
        Kind::U16 | Kind::I16 => b[o..o + 2].copy_from_slice(&(v as u16).to_le_bytes()),
        Kind::U32 | Kind::I32 => b[o..o + 4].copy_from_slice(&(v as u32).to_le_bytes()),
    }
}

fn word(b: &[u8], o: usize) -> u32 {
    u32::from_le_bytes(b[o..o + 4].try_into().unwrap())
}

/// One configuration of a block type: its parameters, the inputs the explorer drives
/// (with the values each takes) and the inputs held constant.
#[derive(Clone, Debug)]
pub struct Config {
    pub label: String,
    pub params: Vec<(&'static Field, i64)>,
    /// Driven inputs and their values. BOOL inputs: 0, 1 and the invalid byte 2 (in at
    /// most one input per combination, see `inputs`).
    pub driven: Vec<(&'static Field, Vec<i64>)>,
    /// Fixed times of the block that are not parameters (ms): SF_TwoHandControlTypeIII's
    /// 500 ms synchronism time.
    pub fixed_limits: Vec<u32>,
}

/// How a 4-byte word of the struct relates to the clock (found by running every
/// transition twice, 2^30 ms apart).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Stamp {
    /// A time stamp: stored relative to tNow (`tNow - w`, clamped).
    Time,
    /// The complement of a time stamp (TON/TOF/TON2 keep one).
    Complement,
}

/// A state as the explorer keeps it: the struct's bytes with the driven inputs zeroed and
/// every time word relative to tNow (clamped), the words' roles, and the levels of the
/// edge inputs (ErrAck, Run, Reset, Activate) of the previous call.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct State {
    bytes: Vec<u8>,
    stamps: Vec<(u16, Stamp)>,
    pub prev_edges: Vec<u8>,
}

/// The clock of copy A before a step: 2 ms before the 32-bit wrap, so every step of 2 ms
/// or more crosses it. Copy B runs the same transition `SHIFT` later, far from the wrap.
pub const NOW_A: u32 = u32::MAX - 1;
pub const SHIFT: u32 = 1 << 30;

impl State {
    /// The concrete struct at clock `now`.
    fn materialize(&self, now: u32) -> Instance {
        let mut b = self.bytes.clone();
        for &(o, s) in &self.stamps {
            let o = usize::from(o);
            let rel = word(&b, o);
            let abs = now.wrapping_sub(rel);
            let v = match s {
                Stamp::Time => abs,
                Stamp::Complement => !abs,
            };
            b[o..o + 4].copy_from_slice(&v.to_le_bytes());
        }
        Instance::from_bytes(&b)
    }
}

/// One step of a trace: the driven inputs' values and the time since the previous call.
#[derive(Clone, Debug)]
pub struct Step {
    pub inputs: Vec<i64>,
    pub dt: u32,
}

/// What a transition looked like, for the invariants.
pub struct Transition<'a> {
    pub ty: &'static BlockType,
    pub cfg: &'a Config,
    pub before: &'a Instance,
    pub after: &'a Instance,
    pub prev_edges: &'a [u8],
    pub step: &'a Step,
    pub rc: i32,
    /// Copy B's observation differs from copy A's (time-shift / wrap).
    pub shift_mismatch: Option<String>,
    /// With an invalid input byte: the same call with that byte FALSE (its safe reading).
    pub safe_reading: Option<Instance>,
}

/// A violated invariant with the shortest trace that reaches it.
#[derive(Clone, Debug)]
pub struct Violation {
    pub block: &'static str,
    pub config: Config,
    pub what: String,
    pub trace: Vec<Step>,
    /// The offending call's observations: state name and BOOL outputs after it.
    pub state_after: String,
    pub outputs_after: Vec<(&'static str, i64)>,
    /// A PLCopen block's DiagCode after it.
    pub diag_after: Option<i64>,
}

/// The figures of one block type (all its configurations).
#[derive(Clone, Debug, Default)]
pub struct Figures {
    pub configs: usize,
    pub states: usize,
    pub transitions: u64,
    pub depth: usize,
    pub secs: f64,
    pub state_values: Vec<u16>,
}

/// PLCopen inputs that are constants, latched at activation.
pub const CONSTANT_INPUTS: &[&str] = &["S_StartReset", "S_AutoReset", "NoExternalTest"];

/// The edge inputs whose previous level the invariants need.
pub const EDGE_INPUTS: &[&str] = &["bErrAck", "bRun", "Reset", "Activate", "S_Reset"];

/// The time steps of a configuration: 0, 1 and each time parameter's limit -1, =, +1.
pub fn time_steps(cfg: &Config) -> (Vec<u32>, u32) {
    let mut dts = vec![0u32, 1];
    let mut max_t = 0u32;
    for (f, v) in &cfg.params {
        if is_time(f) && *v > 0 {
            let l = *v as u32;
            max_t = max_t.max(l);
            dts.extend([l - 1, l, l + 1]);
        }
    }
    for &l in &cfg.fixed_limits {
        max_t = max_t.max(l);
        dts.extend([l - 1, l, l + 1]);
    }
    dts.sort_unstable();
    dts.dedup();
    (dts, max_t + 1)
}

/// A time parameter (ms): a UDINT whose name begins with `t` (tDiscTime12, tDelay, T_…),
/// or a PLCopen TIME (DiscrepancyTime, MonitoringTime, TestTime, ModeMonitorTime,
/// TrailingMinimum, TrailingMaximum).
pub fn is_time(f: &Field) -> bool {
    f.dir == Dir::Param
        && f.kind == Kind::U32
        && (f.name.starts_with('t')
            || f.name.starts_with("T_")
            || f.name.ends_with("Time")
            || f.name.starts_with("Trailing"))
}

/// Every input combination: the product of the driven inputs' valid values, plus, for
/// each BOOL input, the invalid byte in it with every other input FALSE (its lowest value)
/// and with every other input TRUE (its highest).
pub fn inputs(cfg: &Config) -> Vec<Vec<i64>> {
    let valid: Vec<Vec<i64>> = cfg
        .driven
        .iter()
        .map(|(f, vs)| {
            vs.iter()
                .copied()
                .filter(|&v| f.kind != Kind::Bool || v != 2)
                .collect()
        })
        .collect();
    let mut out = vec![vec![]];
    for vs in &valid {
        out = out
            .into_iter()
            .flat_map(|p| {
                vs.iter().map(move |&v| {
                    let mut q = p.clone();
                    q.push(v);
                    q
                })
            })
            .collect();
    }
    let n = cfg.driven.len();
    for (i, (f, vs)) in cfg.driven.iter().enumerate() {
        if f.kind == Kind::Bool && vs.contains(&2) {
            for other in [0, 1] {
                let q: Vec<i64> = (0..n)
                    .map(|j| {
                        if j == i {
                            2
                        } else {
                            first_or_last(&valid[j], other)
                        }
                    })
                    .collect();
                out.push(q);
            }
        }
    }
    out
}

fn first_or_last(vs: &[i64], last: i64) -> i64 {
    if last == 1 {
        *vs.last().unwrap()
    } else {
        vs[0]
    }
}

/// A reached state, the step from its parent (none for the state after init) and its depth.
type Node = (State, Option<(usize, Step)>, usize);

/// Explores one configuration. Returns the figures and the first violation found (the
/// search is breadth first, so its trace is a shortest one).
pub fn explore(
    ty: &'static BlockType,
    cfg: &Config,
    max_depth: Option<usize>,
) -> Result<(Figures, Option<Violation>), String> {
    let t0 = Instant::now();
    let api = api(ty.info.tag);
    let mut inst = Instance::new(ty.size);
    for (f, v) in &cfg.params {
        inst.set(f, *v);
    }
    let rc = (api.init)(inst.ptr());
    if rc != 0 {
        return Err(format!(
            "{} {}: init returned {rc}",
            ty.info.name, cfg.label
        ));
    }
    let (dts, clamp) = time_steps(cfg);
    let combos = inputs(cfg);
    let edge_idx: Vec<Option<usize>> = EDGE_INPUTS
        .iter()
        .map(|n| cfg.driven.iter().position(|(f, _)| f.name == *n))
        .collect();
    // Bytes that are not state: the driven inputs (rewritten before every call).
    let mut input_bytes = vec![false; ty.size];
    for (f, _) in &cfg.driven {
        for b in input_bytes
            .iter_mut()
            .skip(usize::from(f.offset))
            .take(f.kind.size())
        {
            *b = true;
        }
    }
    let init_state = State {
        bytes: inst.bytes().to_vec(),
        stamps: vec![],
        prev_edges: vec![0; EDGE_INPUTS.len()],
    };
    let mut index: HashMap<State, usize> = HashMap::new();
    // (state, parent index, step from the parent, depth)
    let mut nodes: Vec<Node> = Vec::new();
    index.insert(init_state.clone(), 0);
    nodes.push((init_state, None, 0));
    let mut queue = VecDeque::from([0usize]);
    let mut fig = Figures {
        configs: 1,
        ..Default::default()
    };
    let mut state_values = std::collections::BTreeSet::new();
    state_values.insert(invariants::state_value(ty, &inst));
    while let Some(n) = queue.pop_front() {
        let (state, _, depth) = nodes[n].clone();
        if max_depth.is_some_and(|m| depth >= m) {
            continue;
        }
        let before = state.materialize(NOW_A);
        let before_b = state.materialize(NOW_A.wrapping_add(SHIFT));
        for combo in &combos {
            for &dt in &dts {
                let step = Step {
                    inputs: combo.clone(),
                    dt,
                };
                let mut a = before.clone();
                let mut b = before_b.clone();
                for ((f, _), &v) in cfg.driven.iter().zip(combo) {
                    a.set(f, v);
                    b.set(f, v);
                }
                let now_a = NOW_A.wrapping_add(dt);
                let rc = (api.cycle)(a.ptr(), now_a);
                let rc_b = (api.cycle)(b.ptr(), now_a.wrapping_add(SHIFT));
                fig.transitions += 1;
                // Copy A against copy B: equal bytes, or a word 2^30 apart (a time stamp)
                // or its complement.
                let mut stamps = Vec::new();
                let mut mismatch = (rc != rc_b).then(|| format!("status {rc} vs {rc_b}"));
                let (ba, bb) = (a.bytes(), b.bytes());
                let mut o = 0;
                while o < ty.size && mismatch.is_none() {
                    if o % 4 == 0 && o + 4 <= ty.size && ba[o..o + 4] != bb[o..o + 4] {
                        let d = word(bb, o).wrapping_sub(word(ba, o));
                        if input_bytes[o..o + 4].iter().any(|&x| x) {
                            mismatch = Some(format!("input word at {o}"));
                        } else if d == SHIFT {
                            stamps.push((o as u16, Stamp::Time));
                        } else if d == SHIFT.wrapping_neg() {
                            stamps.push((o as u16, Stamp::Complement));
                        } else {
                            mismatch = Some(format!(
                                "byte offset {o}: {:#010x} at the wrap, {:#010x} 2^30 ms later",
                                word(ba, o),
                                word(bb, o)
                            ));
                        }
                        o += 4;
                        continue;
                    }
                    if ba[o] != bb[o] {
                        mismatch = Some(format!("byte offset {o}: {} vs {}", ba[o], bb[o]));
                    }
                    o += 1;
                }
                // The invalid byte's safe reading: FALSE. A PLCopen constant input is latched
                // at activation (an invalid byte there keeps the latched value, a changed
                // valid one is SL_E_PARAM_CHANGED), so it has no FALSE to compare with.
                let invalid_in_signal = cfg.driven.iter().zip(combo).any(|((f, _), &v)| {
                    f.kind == Kind::Bool && v == 2 && !CONSTANT_INPUTS.contains(&f.name)
                });
                let safe_reading = invalid_in_signal.then(|| {
                    let mut c = before.clone();
                    for ((f, _), &v) in cfg.driven.iter().zip(combo) {
                        c.set(f, if f.kind == Kind::Bool && v == 2 { 0 } else { v });
                    }
                    (api.cycle)(c.ptr(), now_a);
                    c
                });
                let tr = Transition {
                    ty,
                    cfg,
                    before: &before,
                    after: &a,
                    prev_edges: &state.prev_edges,
                    step: &step,
                    rc,
                    shift_mismatch: mismatch,
                    safe_reading,
                };
                state_values.insert(invariants::state_value(ty, &a));
                if let Some(what) = invariants::check(&tr) {
                    let mut trace = vec![step.clone()];
                    let mut p = n;
                    while let Some((parent, s)) = nodes[p].1.clone() {
                        trace.push(s);
                        p = parent;
                    }
                    trace.reverse();
                    fig.secs = t0.elapsed().as_secs_f64();
                    return Ok((
                        fig,
                        Some(Violation {
                            block: ty.info.name,
                            config: cfg.clone(),
                            what,
                            trace,
                            state_after: invariants::state_name(ty, &a),
                            outputs_after: invariants::bool_outputs(ty, &a),
                            diag_after: ty.field("DiagCode").map(|f| a.get(f)),
                        }),
                    ));
                }
                // The canonical form.
                let mut bytes = a.bytes().to_vec();
                for (i, &is_in) in input_bytes.iter().enumerate() {
                    if is_in {
                        bytes[i] = 0;
                    }
                }
                for &(o, s) in &stamps {
                    let o = usize::from(o);
                    let w = match s {
                        Stamp::Time => word(&bytes, o),
                        Stamp::Complement => !word(&bytes, o),
                    };
                    let rel = (now_a.wrapping_sub(w) as i32).clamp(-(clamp as i32), clamp as i32);
                    bytes[o..o + 4].copy_from_slice(&(rel as u32).to_le_bytes());
                }
                let prev_edges = edge_idx
                    .iter()
                    .map(|i| i.map_or(0, |i| u8::from(combo[i] == 1)))
                    .collect();
                let next = State {
                    bytes,
                    stamps,
                    prev_edges,
                };
                if !index.contains_key(&next) {
                    let k = nodes.len();
                    index.insert(next.clone(), k);
                    nodes.push((next, Some((n, step)), depth + 1));
                    fig.depth = fig.depth.max(depth + 1);
                    queue.push_back(k);
                }
            }
        }
    }
    fig.states = nodes.len();
    fig.secs = t0.elapsed().as_secs_f64();
    fig.state_values = state_values.into_iter().collect();
    Ok((fig, None))
}

/// The status a cycle may return: SL_OK, or SL_E_INVALID_BOOL when an input byte is
/// neither 0 nor 1 (ABI §2).
pub fn documented_status(rc: i32, invalid_input: bool) -> bool {
    rc == 0 || (invalid_input && rc == SL_E_INVALID_BOOL)
}
