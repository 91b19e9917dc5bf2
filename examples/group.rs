//! A TwinSAFE group in Rust (manual §3.1): ESTOP and MON feed an AND that drives one
//! contactor K1. A discrepancy error on the MON stops the whole group in the same cycle
//! until ErrAck is given; afterwards each block restarts by its own rules (MON by itself,
//! ESTOP with its restart button). Prints a timeline; `cargo run --example group`.

use safelogic::group::{self, Member};
use safelogic::*;
use std::mem::offset_of;

/// The machine: one group, three blocks, two links.
struct Machine {
    g: SL_GROUP,
    links: [SL_LINK; 2],
    estop: FB_ESTOP,
    mon: FB_MON,
    and: FB_AND,
    t: u32,
}

const NAMES: [(&str, u16); 3] = [
    ("ESTOP", SL_TYPE_ESTOP),
    ("MON", SL_TYPE_MON),
    ("AND", SL_TYPE_AND),
];

impl Machine {
    fn new() -> Self {
        // ESTOP: EStopIn1/2 two-channel (e-stop S1), EDM1 = K1 feedback, restart S2.
        let mut estop = FB_ESTOP {
            wInputActive: 0b11,
            tDiscTime12: 30,
            dwOptions: SL_OPT_EDM1,
            ..Default::default()
        };
        // MON: door switches MonIn1/2, automatic restart.
        let mut mon = FB_MON {
            wInputActive: 0b11,
            tDiscTime12: 40,
            ..Default::default()
        };
        // AND: K1 runs only with the e-stop released AND the door closed.
        let mut and = FB_AND {
            wInputActive: 0b11,
            ..Default::default()
        };
        assert_eq!(estop.init(), SL_OK);
        assert_eq!(mon.init(), SL_OK);
        assert_eq!(and.init(), SL_OK);
        (estop.bEStopIn1, estop.bEStopIn2, estop.bEDM1) = (1, 1, 1);
        (mon.bMonIn1, mon.bMonIn2) = (1, 1);
        let mut m = Machine {
            g: SL_GROUP::default(),
            links: [SL_LINK::default(); 2],
            estop,
            mon,
            and,
            t: 0,
        };
        assert_eq!(group::init(&mut m.g, 3, 2), SL_OK);
        for _ in 0..3 {
            group::reserve_member(&mut m.g).expect("room for three members");
        }
        let wire = |src: u16, so: usize, dst: u16, d: usize| SL_LINK {
            nSrcMember: src,
            nSrcOffset: so as u16,
            nDstMember: dst,
            nDstOffset: d as u16,
            ..Default::default()
        };
        let l1 = wire(
            0,
            offset_of!(FB_ESTOP, bEStopOut),
            2,
            offset_of!(FB_AND, bAndIn1),
        );
        let l2 = wire(
            1,
            offset_of!(FB_MON, bMonOut),
            2,
            offset_of!(FB_AND, bAndIn2),
        );
        let mut ms: [&mut dyn Member; 3] = [&mut m.estop, &mut m.mon, &mut m.and];
        assert_eq!(
            group::add_link(&mut m.g, &mut ms[..], &mut m.links, l1),
            SL_OK
        );
        assert_eq!(
            group::add_link(&mut m.g, &mut ms[..], &mut m.links, l2),
            SL_OK
        );
        m
    }

    /// One 10 ms task cycle; prints a line when `what` is not empty.
    fn cycle(&mut self, what: &str) {
        let mut ms: [&mut dyn Member; 3] = [&mut self.estop, &mut self.mon, &mut self.and];
        let rc = group::cycle(&mut self.g, &mut ms[..], &self.links, self.t);
        if !what.is_empty() {
            let states: Vec<String> = ms
                .iter()
                .zip(NAMES)
                .map(|(m, (n, ty))| format!("{n}={:<5}", state_name(ty, m.state())))
                .collect();
            println!(
                "{:>5} ms | group {:<5} FbErr={} FbRun={} | {} | K1={:<3} | {}{}",
                self.t,
                group_state(self.g.nState),
                self.g.bFbErr,
                self.g.bFbRun,
                states.join(" "),
                if self.and.bAndOut == 1 { "on" } else { "off" },
                what,
                if rc == SL_OK {
                    String::new()
                } else {
                    format!(" [{}]", safelogic::types::status_str(rc))
                }
            );
        }
        self.t += 10;
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
    println!("Group: ESTOP + MON -> AND -> contactor K1 (EDM1 = K1 feedback), 10 ms cycle\n");
    let mut m = Machine::new();
    m.cycle("power-up, Run FALSE: every block in STOP");
    m.g.bRun = 1;
    m.cycle("Run TRUE: group RUN, ESTOP waits for its restart");
    m.cycle("MON restarts automatically");
    m.estop.bRestart = 1;
    m.cycle("S2 pressed: ESTOP START");
    m.estop.bRestart = 0;
    m.cycle("S2 released: ESTOP RUN; the AND runs after it, K1 on in the same cycle");
    m.estop.bEDM1 = 0;
    m.cycle("K1 picked up: its feedback EDM1 reads FALSE");
    m.mon.bMonIn1 = 0;
    m.cycle("door switch S1 opens, S2 does not: discrepancy starts, MonOut off");
    for _ in 0..3 {
        m.cycle("");
    }
    m.cycle("40 ms discrepancy: MON ERROR, the group stops every block in this cycle");
    (m.estop.bEDM1, m.mon.bMonIn1) = (1, 1);
    m.cycle("door closed, K1 released: still ERROR until acknowledged");
    m.g.bErrAck = 1;
    m.cycle("ErrAck pressed: group and MON RESET");
    m.g.bErrAck = 0;
    m.cycle("ErrAck released: group RUN");
    m.cycle("MON runs again by itself; ESTOP needs S2 again");
    m.estop.bRestart = 1;
    m.cycle("S2 pressed");
    m.estop.bRestart = 0;
    m.cycle("S2 released: K1 on again");
}
