//! FB CAMMONITOR (electronic cam controller of a press) — manual §4.26; layout ABI-2
//! §11.13, rules ABI-2 §12.
//!
//! Watches the crank position of a press (Position, 0 … MaxPosition = 360°, clockwise =
//! increasing) against TDC, BDC and OverrunMax limits, each from its input or its fixed
//! value. Excentric mode (default): one direction of rotation; each stroke is released by
//! a Reset pulse (MOVE-STOP → MOVE-START → MOVE-DOWN), passes BDC into the left half
//! (MOVE-UP, UpwardsMove) and must stop between TDC1_LowerLimit and OverrunMax (MOVE-TDC →
//! MOVE-STOP); OverrunTDC shows the distance from TDC1_LowerLimit, OverrunStop the distance
//! from the position at the falling edge of Press_Started. Hardware cams (OverrunCam,
//! UpwardCam) are checked against the areas. Pendulum mode (`SL_OPT_CAMMONITOR_PENDULUM`):
//! both directions, two upper reversal areas TDC1 (left) and TDC2 (right), any motion
//! after a Reset pulse until BDC is passed, then only upwards to the other TDC area, which
//! is never to be exceeded. Press_Started expects movement. Parameter-only ordering errors
//! are `SL_E_CONFIG` with their Text ID in the info data; limits from live inputs or
//! re-latched in SettingMode are verified every cycle (ERROR with the Text ID) unless
//! Automatic is TRUE ("no parameter verification"), which also switches off the movement
//! and cam checks the manual conditions on "Automatic = FALSE". The area predicates of the
//! missing Fig. 140/143 are derived from the diag message texts: docs/semantics.md CM1–CM20.

#![allow(non_camel_case_types)] // the ABI's names (FB_CAMMONITOR_UINT …)

use crate::base::block::{Private, Registered};
use crate::base::bools::{self, edge, Edge};
use crate::base::envelope::Block;
use crate::base::header::{param_crc, put_crc_words, F_CFG_INVALID, F_RESTART_PREV};
use crate::base::reason::rule;
use crate::base::reason::{when, Hit, Rule, RuleDef, Unit};
use crate::base::time::reached;
use crate::base::types::*;
use crate::blocks::analog::{magic, Unsigned};

include!(concat!(env!("OUT_DIR"), "/abi/blocks/motion/cammonitor.rs"));

const _: () = assert!(core::mem::size_of::<SL_CAMMONITOR_PRIVATE>() == 128);

// The ABI-2 §11.13 numbers of the two layouts (the §10.2 rule itself is checked for every
// registered analog type in registry.rs).
const _: () = {
    use core::mem::{offset_of, size_of};
    type U = FB_CAMMONITOR_UINT;
    type D = FB_CAMMONITOR_UDINT;
    assert!(offset_of!(U, nTDC1LowerLimit) == 26 && offset_of!(D, nTDC1LowerLimit) == 28);
    assert!(offset_of!(U, nOverrunMax) == 38 && offset_of!(D, nOverrunMax) == 52);
    assert!(offset_of!(U, tStopDetectionTime) == 40 && offset_of!(D, tStopDetectionTime) == 56);
    assert!(offset_of!(U, dwOptions) == 52 && offset_of!(D, dwOptions) == 68);
    assert!(
        offset_of!(U, nAllowedPositionJitter) == 56 && offset_of!(D, nAllowedPositionJitter) == 72
    );
    assert!(offset_of!(U, nOverrunMaxFix) == 74 && offset_of!(D, nOverrunMaxFix) == 108);
    assert!(offset_of!(U, wInputActive) == 76 && offset_of!(D, wInputActive) == 112);
    assert!(offset_of!(U, bError) == 80 && offset_of!(D, bError) == 120);
    assert!(offset_of!(U, nOverrunTDC) == 88 && offset_of!(D, nOverrunTDC) == 128);
    assert!(offset_of!(U, nOverrunStop) == 90 && offset_of!(D, nOverrunStop) == 132);
    assert!(offset_of!(U, nState) == 96 && offset_of!(D, nState) == 136);
    assert!(offset_of!(U, stPrivate) == 112 && offset_of!(D, stPrivate) == 152);
    assert!(size_of::<U>() == 112 + size_of::<SL_CAMMONITOR_PRIVATE>());
};

/// The messages (Text ID − 0x4000, the manual's message text), §4.26.7 and §4.26.8.
const DIAG_VALUES: &[(u16, &str)] = &[
    (0, "No diagnostic information"),
    (0x01, "The TDC2UpperLimit is lower or equal than the maximum position jitter"),
    (0x02, "The Position is greater than the maximum position (plus the maximum position jitter)"),
    (0x03, "The OverrunCAM input was FALSE in the top dead center area"),
    (0x04, "The OverrunCAM input changed from FALSE to TRUE outside the area between BDCUpperLimit and TDCLowerLimit"),
    (0x05, "The OverrunCAM input was TRUE in the area between OverrunMax and BDCUpperLimit"),
    (0x06, "The OverrunCAM input changed from TRUE to FALSE outside the area between OverrunMax and BDCLowerLimit"),
    (0x07, "The UpwardsCAM input was FALSE in the area between BDCUpperLimit and TDCLowerLimit"),
    (0x08, "The UpwardsCAM input changed from FALSE to TRUE outside the area between BDCLowerLimit and TDCLowerLimit"),
    (0x09, "The UpwardsCAM input changed from TRUE to FALSE outside the area between TDCLowerLimit and OverrunMax"),
    (0x0A, "The Position was moving while waiting for a rising edge at the Reset input in the MOVE-STOP state"),
    (0x0B, "The Position was moving while waiting for a falling edge at the Reset input in the MOVE-START state"),
    (0x0C, "The Position in the area between OverrunMax and BDCLowerLimit was detected in the MOVE-UP state"),
    (0x0D, "The Position has left the top dead center while waiting for a stop"),
    (0x0E, "The position has been changed negatively"),
    (0x0F, "The UpwardsCAM input was TRUE in the area between OverrunMax and BDCLowerLimit"),
    (0x10, "The Position has a circle overflow in Pendulum Mode"),
    (0x11, "The Position has moved while waiting for a rising edge at the Reset input in Pendulum Mode"),
    (0x12, "The BackwardsMove input is TRUE while the Position is between 180° and 360°"),
    (0x13, "The BackwardsMove input is TRUE while the movement is clockwise"),
    (0x14, "The Position has moved while waiting for a falling edge at the Reset input in Pendulum Mode"),
    (0x15, "The value of TDCLowerLimit (plus maximum position jitter) is greater than or equal to the configured position of 360°"),
    (0x16, "The value of BDCUpperLimit (plus twice the maximum position jitter) is greater than or equal to the value of TDCLowerLimit"),
    (0x17, "The value of BDCUpperLimit is less than or equal to the configured value of 180° (plus maximum position jitter)"),
    (0x18, "The value of BDCLowerLimit (plus maximum position jitter) is greater than or equal to the configured value of 180°"),
    (0x19, "The value of OverrunMax (plus twice the maximum position jitter) is greater than or equal to the value of BDCLowerLimit"),
    (0x1A, "The value of TDCUpperLimit (plus twice the maximum position jitter) is greater than or equal to the value of OverrunMax"),
    (0x1B, "The value of TDC1UpperLimit (plus the maximum position jitter) is greater than or to equal the configured position of 360°"),
    (0x1C, "The value of TDC1LowerLimit (plus twice the maximum position jitter) is greater than or equal to the value of TDC1UpperLimit"),
    (0x1D, "The value of TDC2LowerLimit (plus twice the maximum position jitter) is greater than or equal to the value of BDCLowerLimit"),
    (0x1E, "The value of TDC2UpperLimit (plus twice the maximum position jitter) is greater than or equal to the value of TDC2LowerLimit"),
    (0x1F, "The PressStarted input is TRUE and the position did not move after the PressStartedDelayTime"),
    (0x20, "The PressStarted input is TRUE and the position has stopped after moving before"),
    (0x21, "The PressStarted input is TRUE and the position has not moved enough"),
    (0x22, "The Position has changed counter clockwise while moving up clockwise"),
    (0x23, "The Position has changed clockwise while moving up counter clockwise"),
    (0x24, "The Position was moving while waiting for a falling edge on the Reset input in the WAIT-FOR_RESET state"),
    (0x25, "The TDCUpperLimit is lower or equal than the maximum position jitter"),
];

crate::impl_member!([T: Unsigned, const P1: usize, const P2: usize] FB_CAMMONITOR<T, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "CAMMONITOR", CamMonitorState, DIAG_VALUES;
        UINT = SL_TYPE_CAMMONITOR_UINT, UDINT = SL_TYPE_CAMMONITOR_UDINT),
    state: CamMonitorState,
    private: SL_CAMMONITOR_PRIVATE,
    input: [bAutomatic, bBackwardsMove, bReset, bPressStarted, bOverrunCam, bUpwardCam,
        bSettingMode, nPosition, nTDC1LowerLimit, nTDC1UpperLimit, nTDC2LowerLimit,
        nTDC2UpperLimit, nBDCLowerLimit, nBDCUpperLimit, nOverrunMax],
    param: [tStopDetectionTime, tPressStartDelayTime, tMoveDetectionTime, dwOptions,
        nAllowedPositionJitter, nMinPositionChange, nMaxPosition, nTDC1LowerLimitFix,
        nTDC1UpperLimitFix, nTDC2LowerLimitFix, nTDC2UpperLimitFix, nBDCLowerLimitFix,
        nBDCUpperLimitFix, nOverrunMaxFix, wInputActive],
    output: [bError, bCamMonOK, bUpwardsMove, bTDC, bBDC, nOverrunTDC, nOverrunStop],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

// Indices into `adwValue`.
const JITTER: usize = 0;
const MIN_CHANGE: usize = 1;
const MAX_POS: usize = 2;
/// First of the seven limits (TDC1 LL, TDC1 UL, TDC2 LL, TDC2 UL, BDC LL, BDC UL,
/// OverrunMax), in the order of their inputs and active bits 9–15.
const FIX: usize = 3;
// Indices into the seven limits.
const TDC1_LL: usize = 0;
const TDC1_UL: usize = 1;
const TDC2_LL: usize = 2;
const TDC2_UL: usize = 3;
const BDC_LL: usize = 4;
const BDC_UL: usize = 5;
const OVERRUN: usize = 6;
// Indices into `adwTime`.
const T_STOP: usize = 0;
const T_START_DELAY: usize = 1;
const T_MOVE: usize = 2;

/// The limits SettingMode re-latches (§4.26.6.4), as a mask over the seven limits.
const fn settable(options: u32) -> u8 {
    if options & SL_OPT_CAMMONITOR_PENDULUM != 0 {
        0b011_1111 // TDC1 LL/UL, TDC2 LL/UL, BDC LL/UL
    } else {
        0b111_0011 // TDC1 LL/UL, BDC LL/UL, OverrunMax
    }
}

/// Parameters as the user wrote them, with SettingMode's level: while it is TRUE the
/// settable fixed limits may differ from the latched copy (they are re-latched, not a
/// parameter change; ABI-2 §11.13, semantics CM15).
#[derive(Clone, Copy, Debug)]
pub struct CamParams {
    active: u16,
    options: u32,
    times: [u32; 3],
    values: [u32; 10],
    setting: bool,
}

impl PartialEq for CamParams {
    fn eq(&self, o: &Self) -> bool {
        let free = if self.setting || o.setting {
            settable(self.options)
        } else {
            0
        };
        self.active == o.active
            && self.options == o.options
            && self.times == o.times
            && (0..10)
                .all(|i| (i >= FIX && free >> (i - FIX) & 1 != 0) || self.values[i] == o.values[i])
    }
}

/// One cycle's inputs after BOOL decoding.
#[derive(Clone, Copy, Debug)]
pub struct CamIn {
    automatic: bool,
    backwards: bool,
    reset: Edge,
    /// Press_Started (active; an invalid byte reads TRUE).
    started: Edge,
    overrun_cam: Edge,
    upward_cam: Edge,
    pos: u32,
    /// The seven limit inputs as 32-bit patterns.
    limits: [u32; 7],
}

/// `wAux` bits.
const STOPPED: u16 = 1 << 0;
/// Press_Started: a movement has been detected since its rising edge.
const PS_MOVED: u16 = 1 << 1;
/// Press_Started: the delay timer runs (set on its rising edge).
const PS_ARMED: u16 = 1 << 2;
/// `dwStopLatch` holds the position of the last falling edge of Press_Started.
const LATCHED: u16 = 1 << 3;

/// `nEdges` bits.
const E_STARTED: u8 = 1 << 0;
const E_OVERRUN_CAM: u8 = 1 << 1;
const E_UPWARD_CAM: u8 = 1 << 2;

/// A diag message: Text ID, parameters 2 and 3.
type Msg = (u16, [u32; 2]);

/// The effective geometry of one call: jitter J, MaxPosition M, the circle C = M + 1
/// positions (ABI-2 §14 row 25) and the seven limits, all exact.
#[derive(Clone, Copy, Debug)]
struct Geo {
    pendulum: bool,
    j: u64,
    m: u64,
    c: u64,
    l: [u64; 7],
}

impl Geo {
    fn new(options: u32, values: &[u32; 10], limits: [u32; 7]) -> Self {
        let m = u64::from(values[MAX_POS]);
        Geo {
            pendulum: options & SL_OPT_CAMMONITOR_PENDULUM != 0,
            j: u64::from(values[JITTER]),
            m,
            c: m + 1,
            l: limits.map(u64::from),
        }
    }

    /// The ordering checks of §4.26.7.1 / §4.26.8.1 in the manual's order; a check is
    /// made only when every limit it reads is in `known` (a mask over the seven limits).
    fn ordering(&self, known: u8) -> Option<Msg> {
        let (j, l, half) = (self.j, &self.l, self.m / 2);
        let p = |v: u64| v as u32;
        // (Text ID, limits read, fails, Par2, Par3)
        let common = [
            (
                SL_TEXT_CAMMONITOR_BDCLL_HALF,
                1 << BDC_LL,
                l[BDC_LL] + j >= half,
                p(l[BDC_LL] + j),
                p(half),
            ),
            (
                SL_TEXT_CAMMONITOR_BDCUL_HALF,
                1 << BDC_UL,
                l[BDC_UL] <= half + j,
                p(l[BDC_UL]),
                p(half + j),
            ),
            (
                SL_TEXT_CAMMONITOR_BDCUL_TDC1LL,
                1 << BDC_UL | 1 << TDC1_LL,
                l[BDC_UL] + 2 * j >= l[TDC1_LL],
                p(l[BDC_UL] + 2 * j),
                p(l[TDC1_LL]),
            ),
        ];
        let checks: [(u16, u8, bool, u32, u32); 8] = if self.pendulum {
            [
                (
                    SL_TEXT_CAMMONITOR_TDC2UL_JITTER,
                    1 << TDC2_UL,
                    l[TDC2_UL] <= j,
                    p(l[TDC2_UL]),
                    p(j),
                ),
                (
                    SL_TEXT_CAMMONITOR_TDC2UL_TDC2LL,
                    1 << TDC2_UL | 1 << TDC2_LL,
                    l[TDC2_UL] + 2 * j >= l[TDC2_LL],
                    p(l[TDC2_UL] + 2 * j),
                    p(l[TDC2_LL]),
                ),
                (
                    SL_TEXT_CAMMONITOR_TDC2LL_BDCLL,
                    1 << TDC2_LL | 1 << BDC_LL,
                    l[TDC2_LL] + 2 * j >= l[BDC_LL],
                    p(l[TDC2_LL] + 2 * j),
                    p(l[BDC_LL]),
                ),
                common[0],
                common[1],
                common[2],
                (
                    SL_TEXT_CAMMONITOR_TDC1LL_TDC1UL,
                    1 << TDC1_LL | 1 << TDC1_UL,
                    l[TDC1_LL] + 2 * j >= l[TDC1_UL],
                    p(l[TDC1_LL] + 2 * j),
                    p(l[TDC1_UL]),
                ),
                (
                    SL_TEXT_CAMMONITOR_TDC1UL_MAX,
                    1 << TDC1_UL,
                    l[TDC1_UL] + j >= self.m,
                    p(l[TDC1_UL] + j),
                    p(self.m),
                ),
            ]
        } else {
            [
                (
                    SL_TEXT_CAMMONITOR_TDC1UL_JITTER,
                    1 << TDC1_UL,
                    l[TDC1_UL] <= j,
                    p(l[TDC1_UL]),
                    p(j),
                ),
                (
                    SL_TEXT_CAMMONITOR_TDC1UL_OVERRUNMAX,
                    1 << TDC1_UL | 1 << OVERRUN,
                    l[TDC1_UL] + 2 * j >= l[OVERRUN],
                    p(l[TDC1_UL] + 2 * j),
                    p(l[OVERRUN]),
                ),
                (
                    SL_TEXT_CAMMONITOR_OVERRUNMAX_BDCLL,
                    1 << OVERRUN | 1 << BDC_LL,
                    l[OVERRUN] + 2 * j >= l[BDC_LL],
                    p(l[OVERRUN] + 2 * j),
                    p(l[BDC_LL]),
                ),
                common[0],
                common[1],
                common[2],
                (
                    SL_TEXT_CAMMONITOR_TDC1LL_MAX,
                    1 << TDC1_LL,
                    l[TDC1_LL] + j > self.m,
                    p(l[TDC1_LL] + j),
                    p(self.m),
                ),
                (0, 0, false, 0, 0),
            ]
        };
        checks
            .iter()
            .find(|(_, reads, fails, _, _)| *fails && reads & !known == 0)
            .map(|&(text, _, _, a, b)| (text, [a, b]))
    }

    /// Position → place on the circle 0 … M (values up to M + J are jitter past 360°).
    fn circle(&self, pos: u64) -> u64 {
        if pos < self.c {
            pos
        } else {
            pos % self.c
        }
    }

    /// Clockwise distance from `from` to `to`, both on the circle.
    fn forward(&self, to: u64, from: u64) -> u64 {
        if to >= from {
            to - from
        } else {
            to + self.c - from
        }
    }

    /// Signed distance from `from` to `to`: excentric the short way round the circle,
    /// pendulum along the line (its wrap is an error of its own).
    fn dist(&self, to: u64, from: u64) -> i64 {
        let (to, from) = (self.circle(to), self.circle(from));
        if self.pendulum {
            to as i64 - from as i64
        } else {
            let d = self.forward(to, from);
            if 2 * d > self.c {
                d as i64 - self.c as i64
            } else {
                d as i64
            }
        }
    }

    /// Excentric: distance clockwise from `from` to `to`; pendulum: the absolute distance.
    fn ahead(&self, to: u64, from: u64) -> u64 {
        let (to, from) = (self.circle(to), self.circle(from));
        if self.pendulum {
            to.abs_diff(from)
        } else {
            self.forward(to, from)
        }
    }

    // Excentric areas (semantics CM2).
    /// LeftArea: BDC_UpperLimit … TDC1_LowerLimit (0x4004, 0x4007).
    fn left(&self, q: u64) -> bool {
        q >= self.l[BDC_UL] && q <= self.l[TDC1_LL]
    }
    /// TDCArea: TDC1_LowerLimit … 360°/0° … TDC1_UpperLimit (output TDC, 0x4003).
    fn tdc(&self, q: u64) -> bool {
        q >= self.l[TDC1_LL] || q <= self.l[TDC1_UL]
    }
    /// TDCAreaMax: TDC1_LowerLimit … 0° … OverrunMax (MOVE-TDC, 0x400D, 0x4009).
    fn tdc_max(&self, q: u64) -> bool {
        q >= self.l[TDC1_LL] || q <= self.l[OVERRUN]
    }
    /// OverrunMaxArea: OverrunMax … BDC_LowerLimit (0x4006).
    fn overrun_area(&self, q: u64) -> bool {
        q >= self.l[OVERRUN] && q <= self.l[BDC_LL]
    }
    /// BDCRightArea: beyond BDC_LowerLimit, before BDC_UpperLimit (0x4005).
    fn bdc_right(&self, q: u64) -> bool {
        q > self.l[BDC_LL] && q < self.l[BDC_UL]
    }
    /// OverrunMaxRightArea: beyond OverrunMax, before BDC_LowerLimit (0x400F).
    fn overrun_right(&self, q: u64) -> bool {
        q > self.l[OVERRUN] && q < self.l[BDC_LL]
    }
    /// BDCArea of 0x4008: BDC_LowerLimit … TDC1_LowerLimit.
    fn upward_rise(&self, q: u64) -> bool {
        q >= self.l[BDC_LL] && q <= self.l[TDC1_LL]
    }
    /// Output BDC: BDC_LowerLimit … BDC_UpperLimit.
    fn bdc(&self, q: u64) -> bool {
        q >= self.l[BDC_LL] && q <= self.l[BDC_UL]
    }

    // Pendulum areas (semantics CM3).
    /// TDC1Area or TDC1ExceededArea: from TDC1_LowerLimit upwards.
    fn tdc1_reached(&self, q: u64) -> bool {
        q >= self.l[TDC1_LL]
    }
    /// TDC2Area or TDC2ExceededArea: from TDC2_LowerLimit downwards.
    fn tdc2_reached(&self, q: u64) -> bool {
        q <= self.l[TDC2_LL]
    }
    /// A reversal area exceeded: above TDC1_UpperLimit or below TDC2_UpperLimit.
    fn exceeded(&self, q: u64) -> bool {
        q > self.l[TDC1_UL] || q < self.l[TDC2_UL]
    }
    /// Output TDC in pendulum mode: TDC1Area or TDC2Area.
    fn tdc_pendulum(&self, q: u64) -> bool {
        (q >= self.l[TDC1_LL] && q <= self.l[TDC1_UL])
            || (q >= self.l[TDC2_UL] && q <= self.l[TDC2_LL])
    }
}

/// CamMonOK is TRUE in RUN and the MOVE-* states.
fn cam_ok(state: u8) -> bool {
    state == SL_STATE_RUN || state >= SL_STATE_CAMMONITOR_MOVE_STOP
}

/// The tracking values a call changes besides the state.
#[derive(Clone, Copy, Debug)]
struct Track {
    aux: u16,
    r: u32,
    last: u32,
    t_ref: u32,
    t_ps: u32,
    ps_ref: u32,
    latch: u32,
}

impl Track {
    /// One running call: checks in the order position range, circle overflow, parameter
    /// verification, direction and cams, Press_Started, then the state's transition.
    fn run(
        &mut self,
        state: u8,
        inp: &CamIn,
        geo: &Geo,
        p: &SL_CAMMONITOR_PRIVATE,
        now: u32,
        first: bool,
    ) -> Result<u8, Msg> {
        let pos = u64::from(inp.pos);
        if pos > geo.m + geo.j {
            let limit = (geo.m + geo.j) as u32;
            return Err((SL_TEXT_CAMMONITOR_POSITION_RANGE, [inp.pos, limit]));
        }
        let q = geo.circle(pos);
        if first {
            self.r = q as u32;
            self.last = q as u32;
            self.t_ref = now;
            self.aux = 0;
        }
        let last = u64::from(self.last);
        let (r, j) = (u64::from(self.r), geo.j as i64);
        if geo.pendulum && 2 * q.abs_diff(last) > geo.c {
            return Err((SL_TEXT_CAMMONITOR_CIRCLE_OVERFLOW, [inp.pos, self.last]));
        }
        if !inp.automatic {
            if let Some(m) = geo.ordering(0x7F) {
                return Err(m);
            }
        }
        // Standstill and direction (§4.26.6.1, §4.26.6.3; semantics CM5).
        let (d_ref, d_last) = (geo.dist(q, r), geo.dist(q, last));
        let cw = d_ref > j || d_last > j;
        let ccw = d_ref < -j || d_last < -j;
        let moving = cw || ccw;
        let was_stopped = self.aux & STOPPED != 0;
        if moving {
            (self.r, self.t_ref) = (q as u32, now);
            self.aux &= !STOPPED;
        } else if reached(now, self.t_ref, p.adwTime[T_STOP]) {
            (self.r, self.t_ref) = (q as u32, now);
            self.aux |= STOPPED;
        }
        let stopped = self.aux & STOPPED != 0;
        let stop_rise = stopped && !was_stopped;
        self.last = q as u32;

        if !geo.pendulum && !inp.automatic {
            self.excentric_checks(inp, geo, q, cw, ccw, first, p.wActive)?;
        }
        if p.wActive & SL_CAMMONITOR_ACTIVE_PRESSSTARTED != 0 {
            self.press_started(inp, geo, p, q, moving, stop_rise, now, first)?;
        }

        let rise = !first && inp.reset.rising;
        let fall = !first && inp.reset.falling;
        let (qq, lastq) = (q as u32, last as u32);
        let next = match state {
            SL_STATE_START if moving => {
                let text = if geo.pendulum {
                    SL_TEXT_CAMMONITOR_MOVED_START_TDC
                } else {
                    SL_TEXT_CAMMONITOR_MOVED_MOVE_START
                };
                return Err((text, if geo.pendulum { [qq, lastq] } else { [0; 2] }));
            }
            SL_STATE_START if fall => SL_STATE_RUN,
            SL_STATE_CAMMONITOR_WAIT_FOR_RESET if moving => {
                let par = if geo.pendulum { [inp.pos, 0] } else { [0; 2] };
                return Err((SL_TEXT_CAMMONITOR_MOVED_WAIT_FOR_RESET, par));
            }
            SL_STATE_CAMMONITOR_WAIT_FOR_RESET | SL_STATE_SAFE if rise => SL_STATE_START,
            // Excentric (semantics CM6).
            SL_STATE_RUN if !geo.pendulum && cw => {
                if geo.left(q) && !geo.tdc(q) {
                    SL_STATE_CAMMONITOR_MOVE_UP
                } else {
                    SL_STATE_CAMMONITOR_MOVE_DOWN
                }
            }
            SL_STATE_CAMMONITOR_MOVE_DOWN if geo.left(q) && !geo.tdc(q) => {
                SL_STATE_CAMMONITOR_MOVE_UP
            }
            SL_STATE_CAMMONITOR_MOVE_UP if geo.tdc_max(q) => SL_STATE_CAMMONITOR_MOVE_TDC,
            SL_STATE_CAMMONITOR_MOVE_UP if !geo.left(q) => {
                return Err((SL_TEXT_CAMMONITOR_MOVE_UP_AREA, [inp.pos, 0]));
            }
            SL_STATE_CAMMONITOR_MOVE_DOWN | SL_STATE_CAMMONITOR_MOVE_UP if stop_rise => {
                SL_STATE_SAFE
            }
            SL_STATE_CAMMONITOR_MOVE_TDC if !geo.tdc_max(q) => {
                return Err((SL_TEXT_CAMMONITOR_LEFT_TDC, [inp.pos, 0]));
            }
            SL_STATE_CAMMONITOR_MOVE_TDC if stopped => SL_STATE_CAMMONITOR_MOVE_STOP,
            SL_STATE_CAMMONITOR_MOVE_STOP if moving => {
                return Err((SL_TEXT_CAMMONITOR_MOVED_MOVE_STOP, [0; 2]));
            }
            SL_STATE_CAMMONITOR_MOVE_STOP if rise => SL_STATE_CAMMONITOR_MOVE_START,
            SL_STATE_CAMMONITOR_MOVE_START if moving => {
                return Err((SL_TEXT_CAMMONITOR_MOVED_MOVE_START, [0; 2]));
            }
            SL_STATE_CAMMONITOR_MOVE_START if fall => SL_STATE_CAMMONITOR_MOVE_DOWN,
            // Pendulum (semantics CM7).
            SL_STATE_RUN if geo.pendulum && cw => SL_STATE_CAMMONITOR_MOVE_DOWN_CW,
            SL_STATE_RUN if geo.pendulum && ccw => SL_STATE_CAMMONITOR_MOVE_DOWN_CCW,
            SL_STATE_CAMMONITOR_MOVE_DOWN_CW if ccw => SL_STATE_CAMMONITOR_MOVE_DOWN_CCW,
            SL_STATE_CAMMONITOR_MOVE_DOWN_CCW if cw => SL_STATE_CAMMONITOR_MOVE_DOWN_CW,
            SL_STATE_CAMMONITOR_MOVE_DOWN_CW if geo.tdc1_reached(q) && !geo.tdc1_reached(last) => {
                SL_STATE_CAMMONITOR_MOVE_UP_TDC1
            }
            SL_STATE_CAMMONITOR_MOVE_DOWN_CCW if geo.tdc2_reached(q) && !geo.tdc2_reached(last) => {
                SL_STATE_CAMMONITOR_MOVE_UP_TDC2
            }
            SL_STATE_CAMMONITOR_MOVE_DOWN_CW if q >= geo.l[BDC_UL] && last < geo.l[BDC_UL] => {
                SL_STATE_CAMMONITOR_MOVE_UP_CW
            }
            SL_STATE_CAMMONITOR_MOVE_DOWN_CCW if q <= geo.l[BDC_LL] && last > geo.l[BDC_LL] => {
                SL_STATE_CAMMONITOR_MOVE_UP_CCW
            }
            SL_STATE_CAMMONITOR_MOVE_UP_CW | SL_STATE_CAMMONITOR_MOVE_UP_TDC1 if ccw => {
                return Err((SL_TEXT_CAMMONITOR_CCW_MOVING_UP_CW, [qq, lastq]));
            }
            SL_STATE_CAMMONITOR_MOVE_UP_CCW | SL_STATE_CAMMONITOR_MOVE_UP_TDC2 if cw => {
                return Err((SL_TEXT_CAMMONITOR_CW_MOVING_UP_CCW, [qq, lastq]));
            }
            SL_STATE_CAMMONITOR_MOVE_UP_CW if geo.tdc1_reached(q) => {
                SL_STATE_CAMMONITOR_MOVE_UP_TDC1
            }
            SL_STATE_CAMMONITOR_MOVE_UP_CCW if geo.tdc2_reached(q) => {
                SL_STATE_CAMMONITOR_MOVE_UP_TDC2
            }
            SL_STATE_CAMMONITOR_MOVE_UP_CW | SL_STATE_CAMMONITOR_MOVE_UP_CCW if stop_rise => {
                SL_STATE_SAFE
            }
            SL_STATE_CAMMONITOR_MOVE_UP_TDC1 if stopped => SL_STATE_CAMMONITOR_MOVE_STOP_TDC1,
            SL_STATE_CAMMONITOR_MOVE_UP_TDC2 if stopped => SL_STATE_CAMMONITOR_MOVE_STOP_TDC2,
            SL_STATE_CAMMONITOR_MOVE_STOP_TDC1 | SL_STATE_CAMMONITOR_MOVE_STOP_TDC2 if moving => {
                return Err((SL_TEXT_CAMMONITOR_MOVED_STOP_TDC, [qq, lastq]));
            }
            SL_STATE_CAMMONITOR_MOVE_STOP_TDC1 if rise => SL_STATE_CAMMONITOR_MOVE_START_TDC1,
            SL_STATE_CAMMONITOR_MOVE_STOP_TDC2 if rise => SL_STATE_CAMMONITOR_MOVE_START_TDC2,
            SL_STATE_CAMMONITOR_MOVE_START_TDC1 | SL_STATE_CAMMONITOR_MOVE_START_TDC2 if moving => {
                return Err((SL_TEXT_CAMMONITOR_MOVED_START_TDC, [qq, lastq]));
            }
            SL_STATE_CAMMONITOR_MOVE_START_TDC1 | SL_STATE_CAMMONITOR_MOVE_START_TDC2 if fall => {
                SL_STATE_RUN
            }
            s => s,
        };
        // Pendulum: the upper reversal areas are never exceeded (§4.26.4; semantics CM8).
        Ok(if geo.pendulum && cam_ok(next) && geo.exceeded(q) {
            SL_STATE_SAFE
        } else {
            next
        })
    }

    /// Direction (§4.26.7.2) and hardware cams (§4.26.7.3, §4.26.7.4), Automatic FALSE.
    #[allow(clippy::too_many_arguments)]
    fn excentric_checks(
        &self,
        inp: &CamIn,
        geo: &Geo,
        q: u64,
        cw: bool,
        ccw: bool,
        first: bool,
        active: u16,
    ) -> Result<(), Msg> {
        let pos = inp.pos;
        if ccw && !inp.backwards {
            return Err((SL_TEXT_CAMMONITOR_BACKWARDS, [0; 2]));
        }
        if cw && inp.backwards {
            return Err((SL_TEXT_CAMMONITOR_BACKWARDS_CLOCKWISE, [0; 2]));
        }
        if inp.backwards && q >= geo.l[BDC_UL] {
            return Err((SL_TEXT_CAMMONITOR_BACKWARDS_AREA, [pos, 0]));
        }
        if active & SL_CAMMONITOR_ACTIVE_OVERRUNCAM != 0 {
            let cam = inp.overrun_cam;
            let fail = if cam.level && geo.bdc_right(q) {
                SL_TEXT_CAMMONITOR_OVERRUNCAM_TRUE_BDC
            } else if !cam.level && geo.tdc(q) {
                SL_TEXT_CAMMONITOR_OVERRUNCAM_FALSE_TDC
            } else if !first && cam.rising && !geo.left(q) {
                SL_TEXT_CAMMONITOR_OVERRUNCAM_RISE
            } else if !first && cam.falling && !geo.overrun_area(q) {
                SL_TEXT_CAMMONITOR_OVERRUNCAM_FALL
            } else {
                0
            };
            if fail != 0 {
                return Err((fail, [pos, 0]));
            }
        }
        if active & SL_CAMMONITOR_ACTIVE_UPWARDCAM != 0 {
            let cam = inp.upward_cam;
            let fail = if cam.level && geo.overrun_right(q) {
                SL_TEXT_CAMMONITOR_UPWARDCAM_TRUE_RIGHT
            } else if !cam.level && geo.left(q) {
                SL_TEXT_CAMMONITOR_UPWARDCAM_FALSE_LEFT
            } else if !first && cam.rising && !geo.upward_rise(q) {
                SL_TEXT_CAMMONITOR_UPWARDCAM_RISE
            } else if !first && cam.falling && !geo.tdc_max(q) {
                SL_TEXT_CAMMONITOR_UPWARDCAM_FALL
            } else {
                0
            };
            if fail != 0 {
                return Err((fail, [pos, 0]));
            }
        }
        Ok(())
    }

    /// Press_Started (§4.26.6.2, §4.26.7.6; semantics CM10) and OverrunStop's latch.
    #[allow(clippy::too_many_arguments)]
    fn press_started(
        &mut self,
        inp: &CamIn,
        geo: &Geo,
        p: &SL_CAMMONITOR_PRIVATE,
        q: u64,
        moving: bool,
        stop_rise: bool,
        now: u32,
        first: bool,
    ) -> Result<(), Msg> {
        let ps = inp.started;
        if ps.rising || (first && ps.level) {
            self.aux = (self.aux | PS_ARMED) & !(PS_MOVED | LATCHED);
            self.t_ps = now;
        }
        if ps.falling {
            self.aux = (self.aux | LATCHED) & !(PS_ARMED | PS_MOVED);
            self.latch = q as u32;
        }
        if !ps.level || self.aux & PS_ARMED == 0 {
            return Ok(());
        }
        if self.aux & PS_MOVED == 0 {
            if moving {
                self.aux |= PS_MOVED;
                (self.t_ps, self.ps_ref) = (now, q as u32);
            } else if reached(now, self.t_ps, p.adwTime[T_START_DELAY]) {
                return Err((SL_TEXT_CAMMONITOR_NOT_STARTED, [0; 2]));
            }
        } else if stop_rise {
            return Err((SL_TEXT_CAMMONITOR_STOPPED, [0; 2]));
        } else if reached(now, self.t_ps, p.adwTime[T_MOVE]) {
            // Forward only (excentric): a step back within the jitter is no progress.
            let change = if geo.pendulum {
                q.abs_diff(u64::from(self.ps_ref))
            } else {
                geo.dist(q, u64::from(self.ps_ref)).max(0) as u64
            };
            if change < u64::from(p.adwValue[MIN_CHANGE]) {
                return Err((SL_TEXT_CAMMONITOR_TOO_SLOW, [inp.pos, self.ps_ref]));
            }
            (self.t_ps, self.ps_ref) = (now, q as u32);
        }
        Ok(())
    }
}

/// The seven effective limits: the input where its active bit is set, else the latched
/// fixed value.
fn effective(active: u16, values: &[u32; 10], inputs: [u32; 7]) -> [u32; 7] {
    core::array::from_fn(|i| {
        if active & (SL_CAMMONITOR_ACTIVE_TDC1LOWERLIMIT << i) != 0 {
            inputs[i]
        } else {
            values[FIX + i]
        }
    })
}

/// The limits that come from the fixed values (mask over the seven).
fn from_params(active: u16) -> u8 {
    !(active >> 9) as u8 & 0x7F
}

/// The parameter-only ordering error of a configuration (ABI-2 §12.8), if any.
fn config_error(p: &CamParams) -> Option<Msg> {
    let fix: [u32; 7] = core::array::from_fn(|i| p.values[FIX + i]);
    Geo::new(p.options, &p.values, fix).ordering(from_params(p.active))
}

/// The texts of the ordering errors (they remain while their check fails, ABI-2 §12.5).
fn is_ordering(text: u16) -> bool {
    matches!(text, 0x4001 | 0x4015..=0x401E | 0x4025)
}

impl<T: Unsigned, const P1: usize, const P2: usize> FB_CAMMONITOR<T, P1, P2> {
    fn geometry(&self, inp: &CamIn) -> Geo {
        let p = self.private();
        Geo::new(
            p.dwOptions,
            &p.adwValue,
            effective(p.wActive, &p.adwValue, inp.limits),
        )
    }

    fn limit_inputs(&self) -> [u32; 7] {
        [
            self.nTDC1LowerLimit.to_bits(),
            self.nTDC1UpperLimit.to_bits(),
            self.nTDC2LowerLimit.to_bits(),
            self.nTDC2UpperLimit.to_bits(),
            self.nBDCLowerLimit.to_bits(),
            self.nBDCUpperLimit.to_bits(),
            self.nOverrunMax.to_bits(),
        ]
    }

    /// One running call (`first`: the call that enters the start state).
    fn advance(&mut self, inp: &CamIn, now: u32, first: bool) -> Status {
        let p = *self.private();
        let h = p.stHeader;
        let geo = self.geometry(inp);
        let mut t = Track {
            aux: h.wAux,
            r: p.dwRef,
            last: p.dwLast,
            t_ref: p.tRef,
            t_ps: p.tPs,
            ps_ref: p.dwPsRef,
            latch: p.dwStopLatch,
        };
        let result = t.run(h.nState, inp, &geo, &p, now, first);
        let next = match result {
            Ok(next) => next,
            Err((text, par)) => {
                let q = self.private_mut();
                q.wText = text;
                q.adwPar = par;
                q.stHeader.enter_error(text - SL_CAMMONITOR_DIAG_TEXT_BASE);
                return Status::Ok;
            }
        };
        // CamMonOK switching on is where the latched parameters are verified (C3).
        if self.corrupt_at_switch_on(cam_ok(next) && !cam_ok(h.nState)) {
            return Status::Corrupt;
        }
        let q = self.private_mut();
        q.stHeader.nState = next;
        q.stHeader.wAux = t.aux;
        q.dwRef = t.r;
        q.dwLast = t.last;
        q.tRef = t.t_ref;
        q.tPs = t.t_ps;
        q.dwPsRef = t.ps_ref;
        q.dwStopLatch = t.latch;
        Status::Ok
    }
}

impl<T: Unsigned, const P1: usize, const P2: usize> Block for FB_CAMMONITOR<T, P1, P2> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    type Params = CamParams;
    type In = CamIn;

    #[inline(always)]
    fn live_params(&self) -> CamParams {
        let setting = self.private().wActive & SL_CAMMONITOR_ACTIVE_SETTINGMODE != 0
            && self.bSettingMode == 1;
        CamParams {
            active: self.wInputActive,
            options: self.dwOptions,
            times: [
                self.tStopDetectionTime,
                self.tPressStartDelayTime,
                self.tMoveDetectionTime,
            ],
            values: [
                self.nAllowedPositionJitter.to_bits(),
                self.nMinPositionChange.to_bits(),
                self.nMaxPosition.to_bits(),
                self.nTDC1LowerLimitFix.to_bits(),
                self.nTDC1UpperLimitFix.to_bits(),
                self.nTDC2LowerLimitFix.to_bits(),
                self.nTDC2UpperLimitFix.to_bits(),
                self.nBDCLowerLimitFix.to_bits(),
                self.nBDCUpperLimitFix.to_bits(),
                self.nOverrunMaxFix.to_bits(),
            ],
            setting,
        }
    }
    #[inline(always)]
    fn latched_params(&self) -> CamParams {
        let p = self.private();
        CamParams {
            active: p.wActive,
            options: p.dwOptions,
            times: p.adwTime,
            values: p.adwValue,
            setting: false,
        }
    }
    /// ABI-2 §11.13: Reset and Position active, bits 0–6 and 8–15 only, the mode's unused
    /// inputs inactive and their fixed values 0, the times ≤ 65,535 ms, StopDetectionTime
    /// ≥ 1, with Press_Started active its times and MinPositionChange ≥ 1, and no failing
    /// parameter-only ordering check, each with the manual's Text ID (semantics CM11, CM12).
    const RULES: &'static [RuleDef<CamParams>] = &[
        RuleDef::new("wInputActive", Rule::BitsClear, Unit::Hex, |p| {
            when(p.active & 0x0080 != 0, p.active, 0x0080)
        }),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            let need = SL_CAMMONITOR_ACTIVE_RESET | SL_CAMMONITOR_ACTIVE_POSITION;
            when(p.active & need != need, p.active, need)
        }),
        rule!(no_bits_outside "dwOptions", |p| p.options, SL_OPT_CAMMONITOR_PENDULUM),
        RuleDef::new("wInputActive", Rule::BitsClear, Unit::Hex, |p| {
            let unused = SL_CAMMONITOR_ACTIVE_BACKWARDSMOVE
                | SL_CAMMONITOR_ACTIVE_OVERRUNCAM
                | SL_CAMMONITOR_ACTIVE_UPWARDCAM
                | SL_CAMMONITOR_ACTIVE_OVERRUNMAX;
            when(pendulum(p) && p.active & unused != 0, p.active, unused)
        }),
        RuleDef::new(
            "nOverrunMaxFix",
            Rule::ZeroUnless("the mode is excentric"),
            Unit::Plain,
            |p| {
                let v = p.values[FIX + OVERRUN];
                when(pendulum(p) && v != 0, v, 0)
            },
        ),
        RuleDef::new("wInputActive", Rule::BitsClear, Unit::Hex, |p| {
            let unused = SL_CAMMONITOR_ACTIVE_TDC2LOWERLIMIT | SL_CAMMONITOR_ACTIVE_TDC2UPPERLIMIT;
            when(!pendulum(p) && p.active & unused != 0, p.active, unused)
        }),
        RuleDef::new(
            "nTDC2LowerLimitFix",
            Rule::ZeroUnless("the mode is pendulum"),
            Unit::Plain,
            |p| {
                let v = p.values[FIX + TDC2_LL];
                when(!pendulum(p) && v != 0, v, 0)
            },
        ),
        RuleDef::new(
            "nTDC2UpperLimitFix",
            Rule::ZeroUnless("the mode is pendulum"),
            Unit::Plain,
            |p| {
                let v = p.values[FIX + TDC2_UL];
                when(!pendulum(p) && v != 0, v, 0)
            },
        ),
        RuleDef::new("tStopDetectionTime", Rule::AtMost, Unit::Ms, |p| {
            let t = p.times[T_STOP];
            when(t > SL_CAMMONITOR_TIME_MAX, t, SL_CAMMONITOR_TIME_MAX)
        }),
        RuleDef::new("tPressStartDelayTime", Rule::AtMost, Unit::Ms, |p| {
            let t = p.times[T_START_DELAY];
            when(t > SL_CAMMONITOR_TIME_MAX, t, SL_CAMMONITOR_TIME_MAX)
        }),
        RuleDef::new("tMoveDetectionTime", Rule::AtMost, Unit::Ms, |p| {
            let t = p.times[T_MOVE];
            when(t > SL_CAMMONITOR_TIME_MAX, t, SL_CAMMONITOR_TIME_MAX)
        }),
        rule!(not_zero "tStopDetectionTime" in Ms, |p| p.times[T_STOP]),
        RuleDef::new(
            "tPressStartDelayTime",
            Rule::NotZeroWhen(STARTED),
            Unit::Ms,
            |p| when(started(p) && p.times[T_START_DELAY] == 0, 0, 0),
        ),
        RuleDef::new(
            "tMoveDetectionTime",
            Rule::NotZeroWhen(STARTED),
            Unit::Ms,
            |p| when(started(p) && p.times[T_MOVE] == 0, 0, 0),
        ),
        RuleDef::new(
            "nMinPositionChange",
            Rule::NotZeroWhen(STARTED),
            Unit::Plain,
            |p| when(started(p) && p.values[MIN_CHANGE] == 0, 0, 0),
        ),
        RuleDef::new(
            "nTDC2UpperLimitFix",
            Rule::Message("TDC2UpperLimit must be > AllowedPositionJitter"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC2UL_JITTER),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC2UL_JITTER),
        RuleDef::new(
            "nTDC2UpperLimitFix",
            Rule::Message("TDC2UpperLimit + 2 x AllowedPositionJitter must be < TDC2LowerLimit"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC2UL_TDC2LL),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC2UL_TDC2LL),
        RuleDef::new(
            "nTDC2LowerLimitFix",
            Rule::Message("TDC2LowerLimit + 2 x AllowedPositionJitter must be < BDCLowerLimit"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC2LL_BDCLL),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC2LL_BDCLL),
        RuleDef::new(
            "nBDCLowerLimitFix",
            Rule::Message("BDCLowerLimit + AllowedPositionJitter must be < MaxPosition / 2"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_BDCLL_HALF),
        )
        .text_id(SL_TEXT_CAMMONITOR_BDCLL_HALF),
        RuleDef::new(
            "nBDCUpperLimitFix",
            Rule::Message("BDCUpperLimit must be > MaxPosition / 2 + AllowedPositionJitter"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_BDCUL_HALF),
        )
        .text_id(SL_TEXT_CAMMONITOR_BDCUL_HALF),
        RuleDef::new(
            "nBDCUpperLimitFix",
            Rule::Message("BDCUpperLimit + 2 x AllowedPositionJitter must be < TDC1LowerLimit"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_BDCUL_TDC1LL),
        )
        .text_id(SL_TEXT_CAMMONITOR_BDCUL_TDC1LL),
        RuleDef::new(
            "nTDC1LowerLimitFix",
            Rule::Message("TDC1LowerLimit + 2 x AllowedPositionJitter must be < TDC1UpperLimit"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC1LL_TDC1UL),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC1LL_TDC1UL),
        RuleDef::new(
            "nTDC1UpperLimitFix",
            Rule::Message("TDC1UpperLimit + AllowedPositionJitter must be < MaxPosition"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC1UL_MAX),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC1UL_MAX),
        RuleDef::new(
            "nTDC1UpperLimitFix",
            Rule::Message("TDC1UpperLimit must be > AllowedPositionJitter"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC1UL_JITTER),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC1UL_JITTER),
        RuleDef::new(
            "nTDC1UpperLimitFix",
            Rule::Message("TDC1UpperLimit + 2 x AllowedPositionJitter must be < OverrunMax"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC1UL_OVERRUNMAX),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC1UL_OVERRUNMAX),
        RuleDef::new(
            "nOverrunMaxFix",
            Rule::Message("OverrunMax + 2 x AllowedPositionJitter must be < BDCLowerLimit"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_OVERRUNMAX_BDCLL),
        )
        .text_id(SL_TEXT_CAMMONITOR_OVERRUNMAX_BDCLL),
        RuleDef::new(
            "nTDC1LowerLimitFix",
            Rule::Message("TDC1LowerLimit + AllowedPositionJitter must be <= MaxPosition"),
            Unit::Plain,
            |p| ordering_hit(p, SL_TEXT_CAMMONITOR_TDC1LL_MAX),
        )
        .text_id(SL_TEXT_CAMMONITOR_TDC1LL_MAX),
    ];
    fn store_params(&mut self, p: &CamParams) {
        let q = self.private_mut();
        q.wActive = p.active;
        q.dwOptions = p.options;
        q.adwTime = p.times;
        q.adwValue = p.values;
    }
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let mut words = [0u16; 29];
        let options = [p.dwOptions];
        let all = options
            .iter()
            .chain(p.adwTime.iter())
            .chain(p.adwValue.iter());
        put_crc_words(&mut words[1..], all.copied());
        words[0] = p.wActive;
        param_crc(Self::MAGIC, 0, 0, 0, &words)
    }
    /// Inactive optional BOOLs read FALSE; invalid bytes read FALSE without an edge, but
    /// Press_Started reads TRUE (ABI-2 §12.7). SettingMode TRUE outside STOP re-latches
    /// the settable fixed limits (semantics CM15).
    #[inline(always)]
    fn decode(&mut self) -> (CamIn, bool) {
        let a = self.private().wActive;
        let raw = bools::pack([
            self.bAutomatic,
            self.bBackwardsMove,
            self.bReset,
            self.bPressStarted,
            self.bOverrunCam,
            self.bUpwardCam,
            self.bSettingMode,
        ]);
        let on = |bit: u16, i: u8| a & bit != 0 && raw.ones >> i & 1 != 0;
        let gated = |bit: u16, b: u8| if a & bit != 0 { b } else { 0 };
        let started_raw = match gated(SL_CAMMONITOR_ACTIVE_PRESSSTARTED, self.bPressStarted) {
            0 => 0,
            _ => 1,
        };
        let ocam_raw = gated(SL_CAMMONITOR_ACTIVE_OVERRUNCAM, self.bOverrunCam);
        let ucam_raw = gated(SL_CAMMONITOR_ACTIVE_UPWARDCAM, self.bUpwardCam);
        let reset_raw = self.bReset;
        let limits = self.limit_inputs();
        let pos = self.nPosition.to_bits();
        let setting = on(SL_CAMMONITOR_ACTIVE_SETTINGMODE, 6);
        let q = self.private_mut();
        let reset = edge(reset_raw, &mut q.stHeader.nFlags, F_RESTART_PREV);
        let started = edge(started_raw, &mut q.nEdges, E_STARTED);
        let overrun_cam = edge(ocam_raw, &mut q.nEdges, E_OVERRUN_CAM);
        let upward_cam = edge(ucam_raw, &mut q.nEdges, E_UPWARD_CAM);
        if setting && self.private().stHeader.nState != SL_STATE_STOP {
            self.relatch_settable();
        }
        (
            CamIn {
                automatic: on(SL_CAMMONITOR_ACTIVE_AUTOMATIC, 0),
                backwards: on(SL_CAMMONITOR_ACTIVE_BACKWARDSMOVE, 1),
                reset,
                started,
                overrun_cam,
                upward_cam,
                pos,
                limits,
            },
            raw.invalid != 0,
        )
    }
    /// STOP → run and RESET → run: START with Reset TRUE, else WAIT-FOR-RESET (§4.26.9),
    /// then this call's checks (semantics CM4).
    fn start(&mut self, inp: &CamIn, now: u32) {
        let q = self.private_mut();
        q.stHeader.nState = if inp.reset.level {
            SL_STATE_START
        } else {
            SL_STATE_CAMMONITOR_WAIT_FOR_RESET
        };
        q.stHeader.wAux = 0;
        q.wText = 0;
        q.adwPar = [0; 2];
        self.advance(inp, now, true);
    }
    #[inline(always)]
    fn step(&mut self, inp: &CamIn, now: u32) -> Status {
        self.advance(inp, now, false)
    }
    /// A parameter error remains while its check fails, a position out of range while it
    /// is out of range; movement and cam errors are events (ABI-2 §12.5).
    fn error_remains(&mut self, inp: &CamIn) -> bool {
        let text = self.private().wText;
        let geo = self.geometry(inp);
        if u64::from(inp.pos) > geo.m + geo.j {
            return true;
        }
        is_ordering(text) && !inp.automatic && geo.ordering(0x7F).is_some()
    }
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let state = h.nState;
        let ok = cam_ok(state);
        let (mut upwards, mut tdc, mut bdc, mut overrun_tdc, mut overrun_stop) =
            (false, false, false, 0u64, 0u64);
        if ok {
            let a = p.wActive;
            let geo = Geo::new(
                p.dwOptions,
                &p.adwValue,
                effective(a, &p.adwValue, self.limit_inputs()),
            );
            let q = u64::from(p.dwLast);
            bdc = geo.bdc(q);
            if geo.pendulum {
                tdc = geo.tdc_pendulum(q);
                upwards = matches!(
                    state,
                    SL_STATE_CAMMONITOR_MOVE_UP_CW
                        | SL_STATE_CAMMONITOR_MOVE_UP_TDC1
                        | SL_STATE_CAMMONITOR_MOVE_UP_CCW
                        | SL_STATE_CAMMONITOR_MOVE_UP_TDC2
                );
            } else {
                tdc = geo.tdc(q);
                upwards = matches!(
                    state,
                    SL_STATE_CAMMONITOR_MOVE_UP | SL_STATE_CAMMONITOR_MOVE_TDC
                ) && q >= geo.l[BDC_UL];
                if geo.tdc_max(q) {
                    overrun_tdc = geo.ahead(q, geo.l[TDC1_LL]);
                }
            }
            if h.wAux & LATCHED != 0 {
                overrun_stop = geo.ahead(q, u64::from(p.dwStopLatch));
                // Within the jitter behind the latch is no overrun (excentric).
                if !geo.pendulum && geo.c - overrun_stop <= geo.j {
                    overrun_stop = 0;
                }
            }
        }
        let t = |v: u64| T::from_bits(v.min(T::MAX as u64) as u32);
        self.bError = u8::from(state == SL_STATE_ERROR);
        self.bCamMonOK = u8::from(ok);
        self.bUpwardsMove = u8::from(upwards);
        self.bTDC = u8::from(tdc);
        self.bBDC = u8::from(bdc);
        self.nOverrunTDC = t(overrun_tdc);
        self.nOverrunStop = t(overrun_stop);
        self.nState = state;
        self.nDiag = h.wDiag;
        let value = h.wDiag & !LIBRARY_DIAG_BITS;
        let shown = state == SL_STATE_ERROR
            && p.wText != 0
            && value == p.wText.wrapping_sub(SL_CAMMONITOR_DIAG_TEXT_BASE);
        let refused = state == SL_STATE_STOP && h.flag(F_CFG_INVALID);
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = if shown {
            (p.wText, p.adwPar[0], p.adwPar[1])
        } else if refused {
            match config_error(&self.latched_params()) {
                Some((text, [a, b])) => {
                    // The diag value of the same message, as in ERROR (semantics C15).
                    self.nDiag = h.wDiag | (text - SL_CAMMONITOR_DIAG_TEXT_BASE);
                    (text, a, b)
                }
                None => (0, 0, 0),
            }
        } else {
            (0, 0, 0)
        };
    }
}

impl<T: Unsigned, const P1: usize, const P2: usize> FB_CAMMONITOR<T, P1, P2> {
    /// SettingMode: the live settable fixed limits become the latched ones, with a new CRC
    /// (only when one differs).
    fn relatch_settable(&mut self) {
        let live = self.live_params();
        let mask = settable(self.private().dwOptions);
        let q = self.private_mut();
        let mut changed = false;
        for i in 0..7 {
            if mask >> i & 1 != 0 && q.adwValue[FIX + i] != live.values[FIX + i] {
                q.adwValue[FIX + i] = live.values[FIX + i];
                changed = true;
            }
        }
        if changed {
            let crc = self.latched_crc();
            self.private_mut().stHeader.wParamCrc = crc;
        }
    }
}

/// The condition of the Press_Started rules.
const STARTED: &str = "wInputActive has Press_Started";

fn pendulum(p: &CamParams) -> bool {
    p.options & SL_OPT_CAMMONITOR_PENDULUM != 0
}

fn started(p: &CamParams) -> bool {
    p.active & SL_CAMMONITOR_ACTIVE_PRESSSTARTED != 0
}

/// The parameter-only ordering error `text`, when it is the one the configuration has.
fn ordering_hit(p: &CamParams, text: u16) -> Option<Hit> {
    match config_error(p) {
        Some((t, [a, b])) if t == text => when(true, a, b),
        _ => None,
    }
}
