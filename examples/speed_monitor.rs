//! A two-channel speed monitor in one TwinSAFE group (manual §4.20, §4.21, §4.24, §4.27):
//!
//! ```text
//!   encoder 1 ─ SPEED_DINT ─┐                             ┌─ LIMIT_DINT.InLimit ─┐
//!                           ├─ COMPARE_DINT 1oo2 ─ CompOut┤                      ├─ AND ─ drive enable
//!   encoder 2 ─ SPEED_DINT ─┘                             └─ COMPARE.IsValid ────┘
//!   encoder 1 ─ SLI_DINT (standstill window while the operator asks for it) ─ door release
//! ```
//!
//! The drive may run while both speed channels agree (COMPARE 1oo2, ±50 increments, 100 ms
//! tolerance) and the agreed speed stays within ±1,000 increments per 50 ms (LIMIT). When
//! the operator asks for a safe standstill, SLI latches encoder 1's position and allows the
//! door to open while the axis stays within ±30 increments of it; a larger creep is an
//! SLI error that stops the whole group until it is acknowledged.
//!
//! Prints a timeline (10 ms cycle); `cargo run --example speed_monitor`. The C example
//! `examples/c/speed_monitor.c` prints the same lines (the test command diffs them).

use safelogic::blocks::analog::compare::{SL_ARCH_1OO2, SL_TYPE_COMPARE_DINT};
use safelogic::blocks::analog::limit::{SL_LIMIT_ACTIVE_ANALOGIN, SL_TYPE_LIMIT_DINT};
use safelogic::blocks::analog::sli::{SL_SLI_ACTIVE, SL_TYPE_SLI_DINT};
use safelogic::blocks::analog::speed::SL_SPEED_ACTIVE_POSITION;
use safelogic::group::{self, Member, SL_LINK_ANALOG32, SL_LINK_BOOL};
use safelogic::*;
use std::mem::offset_of;

/// The six blocks of the group.
struct Blocks {
    speed1: FB_SPEED_DINT,
    speed2: FB_SPEED_DINT,
    compare: FB_COMPARE_DINT,
    limit: FB_LIMIT_DINT,
    sli: FB_SLI_DINT,
    enable: FB_AND,
}

impl Blocks {
    /// The members in execution order.
    fn members(&mut self) -> [&mut dyn Member; 6] {
        [
            &mut self.speed1,
            &mut self.speed2,
            &mut self.compare,
            &mut self.limit,
            &mut self.sli,
            &mut self.enable,
        ]
    }
}

/// The machine: two encoders and one group of six blocks with five links.
struct Drive {
    g: SL_GROUP,
    links: [SL_LINK; 5],
    b: Blocks,
    /// Encoder positions (increments) and their movement per 10 ms cycle.
    pos: [i32; 2],
    step: [i32; 2],
    t: u32,
}

/// Member indices = execution order.
const SPEED1: u16 = 0;
const SPEED2: u16 = 1;
const COMPARE: u16 = 2;
const LIMIT: u16 = 3;
const ENABLE: u16 = 5;

impl Drive {
    fn new() -> Self {
        let speed = FB_SPEED_DINT {
            wInputActive: SL_SPEED_ACTIVE_POSITION,
            tTimeInterval: 50,
            ..Default::default()
        };
        let mut b = Blocks {
            speed1: speed,
            speed2: speed,
            compare: FB_COMPARE_DINT {
                wInputActive: 0x0300, // CompIn1, CompIn2
                nArchitecture: SL_ARCH_1OO2,
                nAllowedDeviation: 50,
                tToleranceTime: 100,
                ..Default::default()
            },
            limit: FB_LIMIT_DINT {
                wInputActive: SL_LIMIT_ACTIVE_ANALOGIN,
                nMinimumValue: -1000,
                nMaximumValue: 1000,
                ..Default::default()
            },
            sli: FB_SLI_DINT {
                wInputActive: SL_SLI_ACTIVE,
                nLimitPos: 30,
                nLimitNeg: 30,
                ..Default::default()
            },
            enable: FB_AND {
                wInputActive: 0b11,
                ..Default::default()
            },
        };
        let inits = [
            b.speed1.init(),
            b.speed2.init(),
            b.compare.init(),
            b.limit.init(),
            b.sli.init(),
            b.enable.init(),
        ];
        assert_eq!(inits, [SL_OK; 6]);
        let mut d = Drive {
            g: SL_GROUP::default(),
            links: [SL_LINK::default(); 5],
            b,
            pos: [0; 2],
            step: [0; 2],
            t: 0,
        };
        assert_eq!(group::init(&mut d.g, 6, 5), SL_OK);
        for _ in 0..6 {
            group::reserve_member(&mut d.g).expect("room for six members");
        }
        let link = |src: u16, so: usize, dst: u16, d: usize, kind: u8| SL_LINK {
            nSrcMember: src,
            nSrcOffset: so as u16,
            nDstMember: dst,
            nDstOffset: d as u16,
            nKind: kind,
            ..Default::default()
        };
        let speed_out = offset_of!(FB_SPEED_DINT, nSpeed);
        let wiring = [
            link(
                SPEED1,
                speed_out,
                COMPARE,
                offset_of!(FB_COMPARE_DINT, nCompIn1),
                SL_LINK_ANALOG32,
            ),
            link(
                SPEED2,
                speed_out,
                COMPARE,
                offset_of!(FB_COMPARE_DINT, nCompIn2),
                SL_LINK_ANALOG32,
            ),
            link(
                COMPARE,
                offset_of!(FB_COMPARE_DINT, nCompOut),
                LIMIT,
                offset_of!(FB_LIMIT_DINT, nAnalogIn),
                SL_LINK_ANALOG32,
            ),
            link(
                LIMIT,
                offset_of!(FB_LIMIT_DINT, bInLimit),
                ENABLE,
                offset_of!(FB_AND, bAndIn1),
                SL_LINK_BOOL,
            ),
            link(
                COMPARE,
                offset_of!(FB_COMPARE_DINT, bIsValid),
                ENABLE,
                offset_of!(FB_AND, bAndIn2),
                SL_LINK_BOOL,
            ),
        ];
        for l in wiring {
            let mut ms = d.b.members();
            assert_eq!(
                group::add_link(&mut d.g, &mut ms[..], &mut d.links, l),
                SL_OK
            );
        }
        d.g.bRun = 1;
        d
    }

    /// One 10 ms task cycle: the encoders move, the host writes their positions, the group
    /// runs; prints a line when `what` is not empty.
    fn cycle(&mut self, what: &str) {
        for k in 0..2 {
            self.pos[k] = self.pos[k].wrapping_add(self.step[k]);
        }
        self.b.speed1.nPosition = self.pos[0];
        self.b.speed2.nPosition = self.pos[1];
        self.b.sli.nPosition = self.pos[0];
        let rc = group::cycle(&mut self.g, &mut self.b.members()[..], &self.links, self.t);
        if !what.is_empty() {
            self.print(rc, what);
        }
        self.t += 10;
    }

    fn print(&self, rc: i32, what: &str) {
        let b = &self.b;
        println!(
            "{:>5} ms | {:>6} {:>6} | speed {:>5} {:>5} | COMPARE {:<8} out {:>5} | LIMIT {:<5} | SLI {:<5} diff {:>4} | group {:<5} | drive {:<3} door {:<6} | {}{}",
            self.t,
            self.pos[0],
            self.pos[1],
            b.speed1.nSpeed,
            b.speed2.nSpeed,
            state_name(SL_TYPE_COMPARE_DINT, b.compare.nState),
            b.compare.nCompOut,
            state_name(SL_TYPE_LIMIT_DINT, b.limit.nState),
            state_name(SL_TYPE_SLI_DINT, b.sli.nState),
            b.sli.nPositionDiff,
            group_state(self.g.nState),
            if b.enable.bAndOut == 1 { "on" } else { "off" },
            if b.sli.bSLIActive == 1 { "open" } else { "locked" },
            what,
            if rc == SL_OK {
                String::new()
            } else {
                format!(" [{}]", safelogic::base::types::status_str(rc))
            }
        );
    }

    /// One speed interval (50 ms): four cycles without a line, then one with `what`.
    fn interval(&mut self, what: &str) {
        for _ in 0..4 {
            self.cycle("");
        }
        self.cycle(what);
    }
}

fn group_state(s: u8) -> &'static str {
    match s {
        SL_STATE_RUN => "RUN",
        SL_STATE_STOP => "STOP",
        SL_STATE_ERROR => "ERROR",
        SL_STATE_RESET => "RESET",
        group::SL_GROUP_STATE_START => "START",
        group::SL_GROUP_STATE_STOPERROR => "STOPERROR",
        _ => "?",
    }
}

fn main() {
    println!("Two-channel speed monitor: encoders -> SPEED x2 -> COMPARE 1oo2 -> LIMIT -> AND, SLI standstill window\n");
    let mut d = Drive::new();
    d.cycle("group Run: both channels at 0 agree, COMPARE RUN, drive enabled");
    assert_eq!(d.b.enable.bAndOut, 1);
    d.step = [100, 100];
    d.interval("drive runs at 100 increments per cycle: 500 per 50 ms on both channels");
    d.step = [240, 240];
    d.interval("overspeed: 1,200 per 50 ms > 1,000, LIMIT SAFE (AboveMax), drive off at once");
    assert_eq!((d.b.limit.bAboveMax, d.b.enable.bAndOut), (1, 0));
    d.step = [100, 100];
    d.interval("back to 500: LIMIT RUN by itself, drive enabled again");
    assert_eq!(d.b.enable.bAndOut, 1);
    d.step = [100, 60];
    d.interval("encoder 2's coupling slips: 500 vs 300, COMPARE DELAYOUT (tolerance 100 ms)");
    d.interval("50 ms later, still within the tolerance: CompOut held, drive enabled");
    assert_eq!(d.b.enable.bAndOut, 1);
    d.interval("tolerance over: COMPARE SAFE, IsValid FALSE, drive off");
    assert_eq!((d.b.compare.bIsValid, d.b.enable.bAndOut), (0, 0));
    d.step = [100, 100];
    d.interval("coupling repaired: the channels agree, COMPARE RUN, drive enabled");
    assert_eq!(d.b.enable.bAndOut, 1);
    d.step = [0, 0];
    d.interval("drive stopped: speed 0");
    d.b.sli.bSLI = 1;
    d.cycle("operator asks for standstill: SLI latches encoder 1's position, door released");
    assert_eq!(d.b.sli.bSLIActive, 1);
    d.step = [3, 3];
    for _ in 0..8 {
        d.cycle("");
    }
    d.cycle("the axis creeps 3 increments per cycle: 27 within the window of +-30");
    assert_eq!((d.b.sli.nPositionDiff, d.b.sli.bSLIActive), (27, 1));
    d.step = [40, 40];
    d.cycle(
        "a jolt of 40: 67 > 30, SLI ERROR 0x40C1 (4267 vs latch 4200), group stops every block",
    );
    assert_eq!((d.b.sli.nDiagTextId, d.g.nState), (0x40C1, SL_STATE_ERROR));
    assert_eq!((d.b.sli.dwDiagPar2, d.b.sli.dwDiagPar3), (4267, 4200));
    d.step = [0, 0];
    d.b.sli.bSLI = 0;
    d.cycle("axis held, standstill request withdrawn: ERROR until acknowledged");
    d.g.bErrAck = 1;
    d.cycle("ErrAck pressed: group RESET");
    d.g.bErrAck = 0;
    d.cycle("ErrAck released: group RUN, every block starts again, drive enabled");
    assert_eq!(d.b.enable.bAndOut, 1);
}
