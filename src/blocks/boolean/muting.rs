//! FB MUTING — manual §4.8 (functional description 4.8.1, signals, states and diag bits
//! 4.8.2, configuration and the two sensor examples 4.8.3, EL6910 extensions 4.8.4). The
//! KL6904 has no MUTING block (manual §4.8.1 notice); its manual has no MUTING text.
//!
//! A protective device (light curtain: OSSDIn1/2, one- or two-channel, discrepancy time)
//! whose interruption switches MuteOut off immediately and MuteDelOut after
//! `tMuteDelOutDelay`, unless a muting sequence of four muting sensors is running (states
//! MUTING1…MUTING9): sequential with four single-channel sensors, or parallel with two
//! two-channel groups MutingIn1/2 and MutingIn3/4. Enable input, filter time of the muting
//! inputs, maximum muting time, EDM1/EDM2 feedback loops, and the EL6910 options backwards
//! mode, OSSD check optional, and MutingIn3/4 left inactive with sequential inputs. The step
//! table and every reading are in docs/semantics.md, rows M1–M22.

use crate::base::block::BlockInfo;
use crate::base::bools::{self, bit_flags};
use crate::base::edm::Edm;
use crate::base::envelope::Block;
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::types::*;
use crate::base::{pair, time};

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/muting.rs"));

/// Type tag, name, states and diag texts (manual §4.8.2, §4.8.4).
const INFO: BlockInfo = BlockInfo::of::<MutingState>(SL_TYPE_MUTING, "MUTING").diag(&[
    (SL_DIAG_DISC1, "discrepancy error in muting input group 1"),
    (SL_DIAG_DISC2, "discrepancy error in the OSSD input group"),
    (SL_DIAG_DISC3, "discrepancy error in muting input group 2"),
    (SL_DIAG_EDM1, "EDM monitoring error EDM1"),
    (SL_DIAG_EDM2, "EDM monitoring error EDM2"),
    (SL_DIAG_MUTING_SEQUENCE, "muting sequence was violated"),
    (SL_DIAG_MUTING_MAX_TIME, "maximum muting time was exceeded"),
    (
        SL_DIAG_SAFE_IN_DISC1,
        "discrepancy error in muting input group 1 was not yet reset",
    ),
    (
        SL_DIAG_SAFE_IN_DISC2,
        "discrepancy error in OSSD input group was not yet reset",
    ),
    (
        SL_DIAG_SAFE_IN_DISC3,
        "discrepancy error in muting input group 2 was not yet reset",
    ),
]);

crate::impl_member!([] FB_MUTING {
    info: INFO,
    state: MutingState,
    private: SL_MUTING_PRIVATE,
    input: [bMutingEnable, bEDM1, bEDM2, bMutingIn1, bMutingIn2, bOSSDIn1, bOSSDIn2, bMutingIn3, bMutingIn4],
    param: [tDiscTime12, tDiscTimeOSSD, tDiscTime34, tFilterTime, tMaxMutingTime, tMuteDelOutDelay, wInputActive, wInputNegated, dwOptions],
    output: [bError, bMutingActive, bMuteOut, bMuteDelOut],
    info_fields: [],
});

/// Bits of the input masks (`wInputActive` order, ABI §9).
const M12: u8 = 0b00_0011;
const OSSD: u8 = 0b00_1100;
const M34: u8 = 0b11_0000;
const MUTING_INPUTS: u8 = M12 | M34;
const INPUTS: u16 = 0x3F;
/// Logical-mask bit of MutingIn1…4, in the order of `atFilterStart`.
const M_BIT: [u8; 4] = [1 << 0, 1 << 1, 1 << 4, 1 << 5];

const OPTIONS: u32 = SL_OPT_EDM1
    | SL_OPT_EDM2
    | SL_OPT_MUTING_SEQUENTIAL
    | SL_OPT_MUTING_BACKWARDS
    | SL_OPT_MUTING_OSSD_CHECK_OPTIONAL;

/// Indices into `awTime`.
const T_FILTER: usize = 3;
const T_DELAY: usize = 4;

/// `wAux` layout.
const AUX_FILTERED: u16 = 0x003F;
const AUX_PENDING_SHIFT: u32 = 6;
const AUX_RUNNING_SHIFT: u32 = 12;
const AUX_BACKWARDS: u16 = 1 << 15;

// The sequence patterns: one bit per sensor and one for "protective field interrupted".
bit_flags!(u8: P_M1, P_M2, P_F, P_M3, P_M4);
const P_ALL: u8 = 0x1F;

/// The forward muting sequence with four single-channel sensors (docs/semantics.md M1):
/// the pattern of sensors actuated and field interrupted at each step. Position 0 is RUN
/// before the sequence, positions 1…9 are MUTING1…MUTING9, position 10 is RUN after it.
const STEPS: [u8; 11] = [
    0,
    P_M1,
    P_M1 | P_M2,
    P_M1 | P_M2 | P_F,
    P_M1 | P_M2 | P_F | P_M3,
    P_M1 | P_M2 | P_F | P_M3 | P_M4,
    P_M2 | P_F | P_M3 | P_M4,
    P_F | P_M3 | P_M4,
    P_M3 | P_M4,
    P_M4,
    0,
];

/// The muting sequence of one configuration: which parts of the pattern are checked and
/// whether the muting inputs are two two-channel groups.
#[derive(Clone, Copy, Debug)]
struct Sequence {
    /// Pattern bits that take part in the check.
    mask: u8,
    /// Parallel muting: a group counts as actuated only with both channels actuated.
    parallel: bool,
}

impl Sequence {
    fn new(active: u8, options: u32) -> Self {
        let mut mask = P_ALL;
        if options & SL_OPT_MUTING_OSSD_CHECK_OPTIONAL != 0 {
            mask &= !P_F;
        }
        if active & M34 == 0 {
            mask &= !(P_M3 | P_M4);
        }
        Self {
            mask,
            parallel: options & SL_OPT_MUTING_SEQUENTIAL == 0,
        }
    }

    /// A pattern as the check sees it: groups merged (parallel), unchecked bits removed.
    fn view(&self, p: u8) -> u8 {
        let p = if self.parallel {
            let group = |g: u8| if p & g == g { g } else { 0 };
            group(P_M1 | P_M2) | group(P_M3 | P_M4) | (p & P_F)
        } else {
            p
        };
        p & self.mask
    }

    /// The checked pattern of step `pos` (0…10).
    fn expected(&self, pos: usize) -> u8 {
        STEPS.get(pos).map_or(0, |&p| self.view(p))
    }

    /// Step `pos` is a state of this configuration's sequence: it changes the checked
    /// pattern and is not the idle pattern (docs/semantics.md M2).
    fn used(&self, pos: usize) -> bool {
        let e = self.expected(pos);
        (1..=9).contains(&pos) && e != 0 && e != self.expected(pos - 1)
    }

    /// The next state after `pos` (None: the sequence ends with the idle pattern).
    fn next(&self, pos: usize) -> Option<usize> {
        (pos + 1..=9).find(|&y| self.used(y))
    }

    /// The step a sequence starts with.
    fn first(&self) -> Option<usize> {
        self.next(0)
    }
}

/// The sensor pattern seen backwards: MutingIn4 plays MutingIn1, MutingIn3 MutingIn2.
const fn mirror(p: u8) -> u8 {
    ((p & P_M1) << 4) | ((p & P_M2) << 2) | (p & P_F) | ((p & P_M3) >> 2) | ((p & P_M4) >> 4)
}

/// At least one active OSSD input requests the safe state: the protective field is
/// interrupted (a single channel is enough, ABI §7 Signals).
const fn field_interrupted(logical: u8, active: u8) -> bool {
    logical & active & OSSD != active & OSSD
}

/// The sequence pattern of the evaluated inputs.
fn pattern(eval: u8, active: u8) -> u8 {
    let bit = |mask: u8, p: u8| if eval & mask != 0 { p } else { 0 };
    bit(1 << 0, P_M1)
        | bit(1 << 1, P_M2)
        | bit(1 << 4, P_M3)
        | bit(1 << 5, P_M4)
        | if field_interrupted(eval, active) {
            P_F
        } else {
            0
        }
}

/// The state of sequence step `pos` (1…9).
const fn muting_state(pos: usize) -> u8 {
    SL_STATE_MUTING_MUTING1 - 1 + pos as u8
}

/// Filter of the muting inputs (manual §4.8.1 "filter time up to 500 ms"): a changed
/// logical value is taken over once it has stood unchanged for `t` ms (docs M9).
fn filter(raw: u8, filtered: &mut u8, pending: &mut u8, starts: &mut [u32; 4], t: u32, now: u32) {
    for (&bit, start) in M_BIT.iter().zip(starts.iter_mut()) {
        if (raw ^ *filtered) & bit == 0 {
            *pending &= !bit;
            continue;
        }
        if *pending & bit == 0 {
            *pending |= bit;
            *start = now;
        }
        if time::reached(now, *start, t) {
            *filtered ^= bit;
            *pending &= !bit;
        }
    }
}

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MutingParams {
    pub disc: [u32; 3],
    pub filter: u32,
    pub max_muting: u32,
    pub delay: u32,
    pub active: u16,
    pub negated: u16,
    pub options: u32,
}

/// Decoded inputs of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct MutingIn {
    /// Logical values of the active inputs (wInputActive bit order), unfiltered.
    pub logical: u8,
    /// MutingEnable reads TRUE.
    pub enable: bool,
    pub edm: Edm,
}

impl SL_MUTING_PRIVATE {
    /// CRC of the latched parameters (seeded with the block's magic).
    fn latched_crc(&self) -> u16 {
        let h = &self.stHeader;
        let [a, b, c, d, e, f] = self.awTime;
        let max = self.tMaxMutingTime;
        param_crc(
            FB_MUTING::MAGIC,
            h.nActive,
            h.nNegated,
            h.wOptions,
            &crc_words![u16 a, u16 b, u16 c, u16 d, u16 e, u16 f, u32 max],
        )
    }

    /// Before the outputs switch on or muting starts, the latched parameters must still be
    /// intact (ABI §3.6, docs/semantics.md C3, M21).
    fn intact(&self) -> bool {
        self.latched_crc() == self.stHeader.wParamCrc
    }

    /// The field is interrupted without muting: MuteOut off now, MuteDelOut after the delay.
    fn switch_off(&mut self, now: u32) -> u8 {
        if self.awTime[T_DELAY] != 0 {
            self.stHeader.tPhase = now;
            SL_STATE_DELAYOUT
        } else {
            SL_STATE_SAFE
        }
    }
}

impl Block for FB_MUTING {
    const MAGIC: u16 = 0x3A7E;
    type Params = MutingParams;
    type In = MutingIn;

    fn live_params(&self) -> MutingParams {
        MutingParams {
            disc: [self.tDiscTime12, self.tDiscTimeOSSD, self.tDiscTime34],
            filter: self.tFilterTime,
            max_muting: self.tMaxMutingTime,
            delay: self.tMuteDelOutDelay,
            active: self.wInputActive,
            negated: self.wInputNegated,
            options: self.dwOptions,
        }
    }

    fn latched_params(&self) -> MutingParams {
        let p = &self.stPrivate;
        let t = |i: usize| p.awTime.get(i).map_or(0, |&v| u32::from(v));
        MutingParams {
            disc: [t(0), t(1), t(2)],
            filter: t(T_FILTER),
            max_muting: p.tMaxMutingTime,
            delay: t(T_DELAY),
            active: u16::from(p.stHeader.nActive),
            negated: u16::from(p.stHeader.nNegated),
            options: u32::from(p.stHeader.wOptions),
        }
    }

    const RULES: &'static [RuleDef<MutingParams>] = &[
        rule!(no_bits_outside "wInputActive", |p| p.active, INPUTS),
        rule!(no_bits_outside "wInputNegated", |p| p.negated, INPUTS),
        rule!(no_bits_outside "dwOptions", |p| p.options, OPTIONS),
        rule!(at_most "tDiscTime12" in Ms, |p| p.disc[0], SL_TIME_PARAM_MAX),
        rule!(at_most "tDiscTimeOSSD" in Ms, |p| p.disc[1], SL_TIME_PARAM_MAX),
        rule!(at_most "tDiscTime34" in Ms, |p| p.disc[2], SL_TIME_PARAM_MAX),
        rule!(at_most "tFilterTime" in Ms, |p| p.filter, SL_MUTING_FILTER_TIME_MAX),
        rule!(at_most "tMaxMutingTime" in Ms, |p| p.max_muting, SL_MUTING_MAX_MUTING_TIME_MAX),
        rule!(at_most "tMuteDelOutDelay" in Ms, |p| p.delay, SL_MUTING_DELOUT_DELAY_MAX),
        // A discrepancy time belongs to a pair with both inputs active.
        RuleDef::new("tDiscTime12", Rule::Needs("wInputActive"), Unit::Ms, |p| {
            let both = u16::from(M12);
            when(p.disc[0] != 0 && p.active & both != both, p.disc[0], both)
        }),
        RuleDef::new(
            "tDiscTimeOSSD",
            Rule::Needs("wInputActive"),
            Unit::Ms,
            |p| {
                let both = u16::from(OSSD);
                when(p.disc[1] != 0 && p.active & both != both, p.disc[1], both)
            },
        ),
        RuleDef::new("tDiscTime34", Rule::Needs("wInputActive"), Unit::Ms, |p| {
            let both = u16::from(M34);
            when(p.disc[2] != 0 && p.active & both != both, p.disc[2], both)
        }),
        // Sequential: single-channel sensors only, MutingIn3/4 both or neither (EL6910).
        // Parallel: two two-channel groups.
        RuleDef::new(
            "tDiscTime12",
            Rule::ZeroUnless("muting is parallel"),
            Unit::Ms,
            |p| when(sequential(p) && p.disc[0] != 0, p.disc[0], 0),
        ),
        RuleDef::new(
            "tDiscTime34",
            Rule::ZeroUnless("muting is parallel"),
            Unit::Ms,
            |p| when(sequential(p) && p.disc[2] != 0, p.disc[2], 0),
        ),
        RuleDef::new("wInputActive", Rule::BothOrNeither, Unit::Hex, |p| {
            let m = u16::from(M34);
            let some = p.active & m;
            when(sequential(p) && some != 0 && some != m, p.active, m)
        }),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            let m = u16::from(MUTING_INPUTS);
            when(!sequential(p) && p.active & m != m, p.active, m)
        }),
        // Backwards starts at MutingIn4.
        RuleDef::new("dwOptions", Rule::Needs("wInputActive"), Unit::Hex, |p| {
            let m = u16::from(M34);
            let backwards = p.options & SL_OPT_MUTING_BACKWARDS != 0;
            when(backwards && p.active & m != m, p.options, m)
        }),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            let m = u16::from(M12);
            when(p.active & m != m, p.active, m)
        }),
        RuleDef::new("wInputActive", Rule::AnyBitOf, Unit::Hex, |p| {
            let m = u16::from(OSSD);
            when(p.active & m == 0, p.active, m)
        }),
    ];

    fn store_params(&mut self, p: &MutingParams) {
        let q = &mut self.stPrivate;
        // Narrowing is exact for valid parameters; an invalid set is stored truncated and
        // never runs (F_CFG_INVALID).
        let n = |t: u32| t as u16;
        q.awTime = [
            n(p.disc[0]),
            n(p.disc[1]),
            n(p.disc[2]),
            n(p.filter),
            n(p.delay),
            0,
        ];
        q.tMaxMutingTime = p.max_muting;
        q.stHeader.nActive = p.active as u8;
        q.stHeader.nNegated = p.negated as u8;
        q.stHeader.wOptions = p.options as u16;
    }

    fn latched_crc(&self) -> u16 {
        self.stPrivate.latched_crc()
    }

    fn decode(&mut self) -> (MutingIn, bool) {
        let h = &self.stPrivate.stHeader;
        let packed = bools::pack([
            self.bMutingIn1,
            self.bMutingIn2,
            self.bOSSDIn1,
            self.bOSSDIn2,
            self.bMutingIn3,
            self.bMutingIn4,
        ]);
        let active = h.nActive;
        let options = u32::from(h.wOptions);
        let edm = Edm {
            active: [options & SL_OPT_EDM1 != 0, options & SL_OPT_EDM2 != 0],
            is_true: [bools::is_true(self.bEDM1), bools::is_true(self.bEDM2)],
            is_false: [bools::is_false(self.bEDM1), bools::is_false(self.bEDM2)],
        };
        // Only bytes the block reads count: active inputs, active EDMs, and MutingEnable.
        let invalid = packed.invalid & active != 0
            || (edm.active[0] && self.bEDM1 > 1)
            || (edm.active[1] && self.bEDM2 > 1)
            || self.bMutingEnable > 1;
        let inp = MutingIn {
            logical: bools::logical(packed, active, h.nNegated),
            enable: bools::is_true(self.bMutingEnable),
            edm,
        };
        (inp, invalid)
    }

    fn start(&mut self, inp: &MutingIn, now: u32) {
        let h = &mut self.stPrivate.stHeader;
        // The filter starts from the present values; no timer runs, no direction is set.
        h.wAux = u16::from(inp.logical & MUTING_INPUTS);
        h.tPhase = now;
        h.nState = SL_STATE_SAFE;
    }

    fn step(&mut self, inp: &MutingIn, now: u32) -> Status {
        let p = &mut self.stPrivate;
        let state = p.stHeader.nState;
        let active = p.stHeader.nActive;
        let options = u32::from(p.stHeader.wOptions);
        let aux = p.stHeader.wAux;

        // Muting inputs through the filter, OSSD inputs as they are (docs M9).
        let mut filtered = (aux & AUX_FILTERED) as u8 & MUTING_INPUTS;
        let mut pending = (aux >> AUX_PENDING_SHIFT) as u8 & MUTING_INPUTS;
        let [d12, d_ossd, d34, filter_time, delay, _] = p.awTime;
        filter(
            inp.logical & MUTING_INPUTS,
            &mut filtered,
            &mut pending,
            &mut p.atFilterStart,
            u32::from(filter_time),
            now,
        );
        let eval = filtered | (inp.logical & OSSD);

        // Discrepancy monitoring of the three pairs runs in every running state.
        let disc_times = [d12, d_ossd, d34];
        let monitored = disc_times
            .iter()
            .enumerate()
            .fold(0u8, |m, (k, &t)| m | (u8::from(t != 0) << k));
        let mut running = (aux >> AUX_RUNNING_SHIFT) as u8 & 0b111;
        let disc = pair::monitor(
            eval,
            monitored,
            &mut running,
            &mut p.atDiscStart,
            &disc_times,
            now,
        );
        p.stHeader.wAux = (aux & AUX_BACKWARDS)
            | u16::from(filtered)
            | (u16::from(pending) << AUX_PENDING_SHIFT)
            | (u16::from(running) << AUX_RUNNING_SHIFT);
        // Bit k: discrepancy error of group k; bit 8+k: not yet reset (docs M14).
        let err = u16::from(disc) | (u16::from(disc) << 8);

        let seq = Sequence::new(active, options);
        let pat = pattern(eval, active);
        let field = field_interrupted(eval, active);
        let backwards = p.stHeader.wAux & AUX_BACKWARDS != 0;
        let max_time = p.tMaxMutingTime;
        let violation = SL_DIAG_MUTING_SEQUENCE;

        let mut status = Status::Ok;
        // The next state; `Err(diag)` enters ERROR with these bits.
        let next: Result<u8, u16> = match state {
            SL_STATE_DELAYOUT => {
                // A discrepancy error waits for the end of the delay (manual §4.8.2, docs M16).
                p.stHeader.wDiag |= err;
                if !time::reached(now, p.stHeader.tPhase, u32::from(delay)) {
                    Ok(SL_STATE_DELAYOUT)
                } else if p.stHeader.wDiag != 0 {
                    Err(0)
                } else {
                    Ok(SL_STATE_SAFE)
                }
            }
            _ if err != 0 => Err(err),
            SL_STATE_SAFE => {
                if field || !inp.edm.all_released() {
                    Ok(SL_STATE_SAFE)
                } else if p.intact() {
                    Ok(SL_STATE_RUN)
                } else {
                    status = Status::Corrupt;
                    Err(SL_DIAG_CORRUPT)
                }
            }
            SL_STATE_RUN if !inp.enable => {
                if field {
                    Ok(p.switch_off(now))
                } else {
                    Ok(SL_STATE_RUN)
                }
            }
            SL_STATE_RUN => {
                let forward = seq.view(pat);
                let dir = match seq.first() {
                    Some(f) if forward == seq.expected(f) => Some((f, false)),
                    Some(f)
                        if options & SL_OPT_MUTING_BACKWARDS != 0
                            && seq.view(mirror(pat)) == seq.expected(f) =>
                    {
                        Some((f, true))
                    }
                    _ => None,
                };
                match dir {
                    Some((f, back)) if p.intact() => {
                        let h = &mut p.stHeader;
                        h.wAux = (h.wAux & !AUX_BACKWARDS) | if back { AUX_BACKWARDS } else { 0 };
                        h.tPhase = now;
                        Ok(muting_state(f))
                    }
                    Some(_) => {
                        status = Status::Corrupt;
                        Err(SL_DIAG_CORRUPT)
                    }
                    // With Enable TRUE every shutdown is a sequence violation (docs M6).
                    None if field || forward != 0 => Err(violation),
                    None => Ok(SL_STATE_RUN),
                }
            }
            SL_STATE_MUTING_MUTING1..=SL_STATE_MUTING_MUTING9 => {
                let pos = usize::from(state - SL_STATE_MUTING_MUTING1) + 1;
                let seen = seq.view(if backwards { mirror(pat) } else { pat });
                if !seq.used(pos) {
                    // A step this configuration never takes: the private state is corrupt.
                    status = Status::Corrupt;
                    Err(SL_DIAG_CORRUPT)
                } else if !inp.enable {
                    // Enable FALSE ends muting: the field decides alone (docs M7).
                    if field {
                        Ok(p.switch_off(now))
                    } else {
                        Ok(SL_STATE_RUN)
                    }
                } else if max_time != 0 && time::reached(now, p.stHeader.tPhase, max_time) {
                    Err(SL_DIAG_MUTING_MAX_TIME)
                } else if seen == seq.expected(pos) {
                    Ok(state)
                } else {
                    match seq.next(pos) {
                        Some(y) if seen == seq.expected(y) => Ok(muting_state(y)),
                        None if seen == 0 && !field => Ok(SL_STATE_RUN),
                        _ => Err(violation),
                    }
                }
            }
            _ => {
                // A state value this block never takes: the private state cannot be trusted.
                status = Status::Corrupt;
                Err(SL_DIAG_CORRUPT)
            }
        };
        match next {
            Ok(s) => p.stHeader.nState = s,
            Err(diag) => p.stHeader.enter_error(diag),
        }
        status
    }

    fn stop(&mut self) {
        let h = &mut self.stPrivate.stHeader;
        // A discrepancy error waiting in DELAYOUT stays an error; every other state stops.
        if h.nState == SL_STATE_DELAYOUT && h.wDiag != 0 {
            h.enter_error(0);
        } else {
            h.nState = SL_STATE_STOP;
        }
    }

    fn error_remains(&mut self, inp: &MutingIn) -> bool {
        let h = &mut self.stPrivate.stHeader;
        let active = h.nActive;
        // "Not yet reset" (bits 8-10) clears once both channels of the group requested the
        // safe state in the same cycle (docs M14).
        let both_safe = u16::from(pair::both_safe(inp.logical) & 0b111);
        h.wDiag &= !(both_safe << 8);
        let failed = (h.wDiag & 0b111) as u8;
        let disc_remains = failed & pair::differing(inp.logical) != 0 || h.wDiag & 0x0700 != 0;
        // The muting area must be clear: no muting sensor actuated, the field clear (docs M15).
        let area_busy = h.wDiag & 0x00FF != 0
            && (inp.logical & MUTING_INPUTS != 0 || field_interrupted(inp.logical, active));
        disc_remains || area_busy
    }

    fn write_outputs(&mut self) {
        let h = self.stPrivate.stHeader;
        let (error, muting, out, del_out) = match h.nState {
            SL_STATE_RUN => (false, false, true, true),
            SL_STATE_MUTING_MUTING1..=SL_STATE_MUTING_MUTING9 => (false, true, true, true),
            SL_STATE_DELAYOUT => (false, false, false, true),
            SL_STATE_ERROR => (true, false, false, false),
            _ => (false, false, false, false),
        };
        self.bError = u8::from(error);
        self.bMutingActive = u8::from(muting);
        self.bMuteOut = u8::from(out);
        self.bMuteDelOut = u8::from(del_out);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
    }
}

/// The muting sensors are sequential (`SL_OPT_MUTING_SEQUENTIAL`).
fn sequential(p: &MutingParams) -> bool {
    p.options & SL_OPT_MUTING_SEQUENTIAL != 0
}
