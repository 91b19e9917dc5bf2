//! Analog blocks chained to Boolean ones in one group (issue 9 item 3): a speed from
//! FB SPEED, checked by FB LIMIT, gates an E-stop shutdown through FB AND. Every switch-off
//! happens in the cycle of its cause (members run in order, links are copied just before
//! their destination runs); an analog range error stops the whole group.

use safelogic::blocks::analog::limit::SL_LIMIT_ACTIVE_ANALOGIN;
use safelogic::blocks::analog::speed::SL_SPEED_ACTIVE_POSITION;
use safelogic::group::{self, Member, SL_LINK_ANALOG16, SL_LINK_BOOL};
use safelogic::*;
use std::mem::offset_of;

struct Blocks {
    estop: FB_ESTOP,
    speed: FB_SPEED_INT,
    limit: FB_LIMIT_INT,
    and: FB_AND,
}

impl Blocks {
    fn members(&mut self) -> [&mut dyn Member; 4] {
        [
            &mut self.estop,
            &mut self.speed,
            &mut self.limit,
            &mut self.and,
        ]
    }
}

struct Plant {
    g: SL_GROUP,
    links: [SL_LINK; 3],
    b: Blocks,
    t: u32,
}

impl Plant {
    fn new() -> Self {
        let mut b = Blocks {
            estop: FB_ESTOP {
                wInputActive: 0b11,
                tDiscTime12: 30,
                ..Default::default()
            },
            speed: FB_SPEED_INT {
                wInputActive: SL_SPEED_ACTIVE_POSITION,
                tTimeInterval: 20,
                ..Default::default()
            },
            limit: FB_LIMIT_INT {
                wInputActive: SL_LIMIT_ACTIVE_ANALOGIN,
                nMinimumValue: -100,
                nMaximumValue: 100,
                ..Default::default()
            },
            and: FB_AND {
                wInputActive: 0b11,
                ..Default::default()
            },
        };
        let inits = [b.estop.init(), b.speed.init(), b.limit.init(), b.and.init()];
        assert_eq!(inits, [SL_OK; 4]);
        (b.estop.bEStopIn1, b.estop.bEStopIn2) = (1, 1);
        let mut p = Plant {
            g: SL_GROUP::default(),
            links: [SL_LINK::default(); 3],
            b,
            t: 0,
        };
        assert_eq!(group::init(&mut p.g, 4, 3), SL_OK);
        for _ in 0..4 {
            group::reserve_member(&mut p.g).unwrap();
        }
        let link = |s: u16, so: usize, d: u16, dof: usize, kind: u8| SL_LINK {
            nSrcMember: s,
            nSrcOffset: so as u16,
            nDstMember: d,
            nDstOffset: dof as u16,
            nKind: kind,
            ..Default::default()
        };
        for l in [
            link(
                0,
                offset_of!(FB_ESTOP, bEStopOut),
                3,
                offset_of!(FB_AND, bAndIn1),
                SL_LINK_BOOL,
            ),
            link(
                1,
                offset_of!(FB_SPEED_INT, nSpeed),
                2,
                offset_of!(FB_LIMIT_INT, nAnalogIn),
                SL_LINK_ANALOG16,
            ),
            link(
                2,
                offset_of!(FB_LIMIT_INT, bInLimit),
                3,
                offset_of!(FB_AND, bAndIn2),
                SL_LINK_BOOL,
            ),
        ] {
            assert_eq!(
                group::add_link(&mut p.g, &mut p.b.members()[..], &mut p.links, l),
                SL_OK
            );
        }
        p.g.bRun = 1;
        p
    }

    /// One 10 ms cycle with the axis at `position`.
    fn cycle(&mut self, position: i16) -> i32 {
        self.b.speed.nPosition = position;
        let rc = group::cycle(&mut self.g, &mut self.b.members()[..], &self.links, self.t);
        self.t += 10;
        rc
    }

    fn restart(&mut self, position: i16) {
        self.b.estop.bRestart = 1;
        self.cycle(position);
        self.b.estop.bRestart = 0;
        self.cycle(position);
    }
}

#[test]
fn speed_limit_and_estop_gate_one_output() {
    let mut p = Plant::new();
    assert_eq!(p.cycle(0), SL_OK);
    assert_eq!(p.b.and.bAndOut, 0, "ESTOP waits for its restart");
    assert_eq!(p.b.limit.bInLimit, 1, "speed 0 is within ±100");
    p.restart(0);
    assert_eq!(p.b.and.bAndOut, 1);

    // 60 increments per 10 ms: 120 per 20 ms interval > 100. The update happens in the cycle
    // at 20 ms after the latch, and the AND is off in that very cycle.
    let mut pos = 0i16;
    let mut off_at = None;
    for _ in 0..4 {
        pos += 60;
        p.cycle(pos);
        if p.b.speed.nSpeed > 100 {
            off_at = Some(p.t);
            assert_eq!(p.b.limit.bAboveMax, 1);
            assert_eq!(
                p.b.and.bAndOut, 0,
                "overspeed switches off in the same cycle"
            );
            break;
        }
        assert_eq!(p.b.and.bAndOut, 1, "no interval completed yet");
    }
    assert!(off_at.is_some(), "the overspeed was seen");

    // Slower again: LIMIT returns to RUN by itself, the ESTOP was never touched.
    for _ in 0..4 {
        pos += 2;
        p.cycle(pos);
    }
    assert_eq!((p.b.speed.nSpeed, p.b.limit.bInLimit), (4, 1));
    assert_eq!(p.b.and.bAndOut, 1, "automatic return through LIMIT");

    // E-stop pressed: off in the same cycle, whatever the speed.
    (p.b.estop.bEStopIn1, p.b.estop.bEStopIn2) = (0, 0);
    p.cycle(pos);
    assert_eq!((p.b.estop.bEStopOut, p.b.and.bAndOut), (0, 0));
    (p.b.estop.bEStopIn1, p.b.estop.bEStopIn2) = (1, 1);
    p.cycle(pos);
    assert_eq!(p.b.and.bAndOut, 0, "released E-stop needs its restart");
    p.restart(pos);
    assert_eq!(p.b.and.bAndOut, 1);
}

#[test]
fn an_analog_range_error_stops_the_whole_group_until_acknowledged() {
    let mut p = Plant::new();
    p.cycle(i16::MIN);
    p.restart(i16::MIN);
    assert_eq!(p.b.and.bAndOut, 1);
    // From -32768 to 32767 within one interval: 65,535 does not fit INT (no overflow
    // check): SPEED ERROR 0x4089 at the interval's end, the group stops every member there.
    p.cycle(i16::MAX);
    assert_eq!(p.g.nState, SL_STATE_RUN, "the interval is not over yet");
    assert_eq!(p.b.and.bAndOut, 1);
    p.cycle(i16::MAX);
    assert_eq!(
        p.g.nState, SL_STATE_ERROR,
        "SPEED's range error stops the group"
    );
    assert_eq!(p.b.speed.nState, SL_STATE_ERROR);
    assert_eq!(
        p.b.speed.nDiagTextId,
        safelogic::blocks::analog::speed::SL_TEXT_SPEED_OVERFLOW
    );
    assert_eq!(
        (p.b.speed.dwDiagPar2, p.b.speed.dwDiagPar3),
        (32767, 0xFFFF_8000)
    );
    assert_eq!(
        (p.b.and.bAndOut, p.b.estop.bEStopOut, p.b.speed.nSpeed),
        (0, 0, 0)
    );
    assert_eq!(p.g.bFbErr, 1);
    p.g.bErrAck = 1;
    p.cycle(i16::MAX);
    p.g.bErrAck = 0;
    p.cycle(i16::MAX);
    assert_eq!(p.g.nState, SL_STATE_RUN);
    assert_eq!(
        p.b.speed.nState, SL_STATE_RUN,
        "SPEED restarts with a new latch"
    );
    assert_eq!(
        p.b.and.bAndOut, 0,
        "the ESTOP needs its restart after the group error"
    );
    p.restart(i16::MAX);
    assert_eq!(p.b.and.bAndOut, 1);
}
