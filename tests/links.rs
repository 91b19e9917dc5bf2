//! Typed links (ABI-2 §10.7): an analog chain ADD → MUL → DIV beside a Boolean chain
//! ESTOP → AND in one group through the C API, and every refused link.

mod common;

use common::RawBox;
use safelogic::blocks::analog::arith::ARITH_ACTIVE;
use safelogic::ffi;
use safelogic::group::{self, SL_LINK_ANALOG16, SL_LINK_ANALOG32, SL_LINK_BOOL};
use safelogic::*;
use std::ffi::c_void;
use std::mem::offset_of;
use std::ptr::addr_of_mut;

struct Plant {
    g: SL_GROUP,
    members: [SL_MEMBER; 8],
    links: [SL_LINK; 8],
    estop: FB_ESTOP,
    and: FB_AND,
    add: FB_ADD_INT,
    mul: FB_MUL_INT,
    div: FB_DIV_INT,
    uadd: FB_ADD_UINT,
    dadd: FB_ADD_DINT,
    dmul: FB_MUL_DINT,
}

/// The plant behind one raw pointer (`common::RawBox`).
type Fixture = RawBox<Plant>;

impl Plant {
    fn boxed() -> Fixture {
        let f = Fixture::new(Plant {
            g: SL_GROUP::default(),
            members: [SL_MEMBER::default(); 8],
            links: [SL_LINK::default(); 8],
            estop: FB_ESTOP {
                wInputActive: 0b11,
                ..Default::default()
            },
            and: FB_AND {
                wInputActive: 0b11,
                ..Default::default()
            },
            add: FB_ADD_INT {
                wInputActive: ARITH_ACTIVE,
                ..Default::default()
            },
            mul: FB_MUL_INT {
                wInputActive: ARITH_ACTIVE,
                ..Default::default()
            },
            div: FB_DIV_INT {
                wInputActive: ARITH_ACTIVE,
                ..Default::default()
            },
            uadd: FB_ADD_UINT {
                wInputActive: ARITH_ACTIVE,
                ..Default::default()
            },
            dadd: FB_ADD_DINT {
                wInputActive: ARITH_ACTIVE,
                ..Default::default()
            },
            dmul: FB_MUL_DINT {
                wInputActive: ARITH_ACTIVE,
                ..Default::default()
            },
        });
        let q = f.ptr();
        // SAFETY: every pointer is to a field of the boxed plant, derived from `q`, alive
        // for the test.
        unsafe {
            assert_eq!(
                ffi::sl_group_init(
                    addr_of_mut!((*q).g),
                    addr_of_mut!((*q).members).cast(),
                    8,
                    addr_of_mut!((*q).links).cast(),
                    8
                ),
                SL_OK
            );
            let blocks: [(u16, *mut c_void); 8] = [
                (SL_TYPE_ESTOP, addr_of_mut!((*q).estop).cast()),
                (SL_TYPE_AND, addr_of_mut!((*q).and).cast()),
                (
                    safelogic::blocks::analog::arith::SL_TYPE_ADD_INT,
                    addr_of_mut!((*q).add).cast(),
                ),
                (
                    safelogic::blocks::analog::arith::SL_TYPE_MUL_INT,
                    addr_of_mut!((*q).mul).cast(),
                ),
                (
                    safelogic::blocks::analog::arith::SL_TYPE_DIV_INT,
                    addr_of_mut!((*q).div).cast(),
                ),
                (
                    safelogic::blocks::analog::arith::SL_TYPE_ADD_UINT,
                    addr_of_mut!((*q).uadd).cast(),
                ),
                (
                    safelogic::blocks::analog::arith::SL_TYPE_ADD_DINT,
                    addr_of_mut!((*q).dadd).cast(),
                ),
                (
                    safelogic::blocks::analog::arith::SL_TYPE_MUL_DINT,
                    addr_of_mut!((*q).dmul).cast(),
                ),
            ];
            for (ty, b) in blocks {
                assert_eq!(
                    ffi::sl_group_add_member(
                        addr_of_mut!((*q).g),
                        addr_of_mut!((*q).members).cast(),
                        ty,
                        b,
                        std::ptr::null_mut()
                    ),
                    SL_OK
                );
            }
        }
        f
    }
}

impl Fixture {
    /// The group and its two tables, derived from the fixture's pointer.
    fn tables(&self) -> (*mut SL_GROUP, *mut SL_MEMBER, *mut SL_LINK) {
        let q = self.ptr();
        // SAFETY: field places of the live plant; no reference is formed.
        unsafe {
            (
                addr_of_mut!((*q).g),
                addr_of_mut!((*q).members).cast(),
                addr_of_mut!((*q).links).cast(),
            )
        }
    }

    fn link(&mut self, src: u16, so: usize, dst: u16, dof: usize) -> i32 {
        let (g, m, l) = self.tables();
        // SAFETY: the plant's own tables, reached through the fixture's pointer.
        unsafe { ffi::sl_group_add_link(g, m, l, src, so as u16, dst, dof as u16) }
    }

    /// The next cycle runs the sealed schedule (links as plain copies of their width).
    fn sealed(&self) -> bool {
        let (g, m, l) = self.tables();
        // SAFETY: as in `link`.
        unsafe { ffi::sl_group_schedule_sealed(g, m, l) }
    }

    fn cycle(&mut self, t: u32) -> i32 {
        let (g, m, l) = self.tables();
        // SAFETY: as in `link`.
        unsafe { ffi::sl_group_cycle(g, m, l, t) }
    }
}

const ADD_OUT: usize = offset_of!(FB_ADD_INT, nAnalogOut);
const MUL_IN1: usize = offset_of!(FB_MUL_INT, nAnalogIn1);
const MUL_OUT: usize = offset_of!(FB_MUL_INT, nAnalogOut);
const DIV_IN1: usize = offset_of!(FB_DIV_INT, nAnalogIn1);

#[test]
fn analog_chain_beside_a_boolean_chain() {
    let mut p = Plant::boxed();
    assert_eq!(
        p.link(
            0,
            offset_of!(FB_ESTOP, bEStopOut),
            1,
            offset_of!(FB_AND, bAndIn1)
        ),
        SL_OK
    );
    assert_eq!(p.link(2, ADD_OUT, 3, MUL_IN1), SL_OK);
    assert_eq!(p.link(3, MUL_OUT, 4, DIV_IN1), SL_OK);
    let kinds: Vec<u8> = p.links[..3].iter().map(|l| l.nKind).collect();
    assert_eq!(kinds, [SL_LINK_BOOL, SL_LINK_ANALOG16, SL_LINK_ANALOG16]);

    (p.add.nAnalogIn1, p.add.nAnalogIn2) = (20, 30); // 50
    p.mul.nAnalogIn2 = -3; // -150
    (p.div.nAnalogIn2, p.div.nRounding) = (7, 2); // -21.43 → -21
    (p.estop.bEStopIn1, p.estop.bEStopIn2, p.and.bAndIn2) = (1, 1, 1);
    (p.uadd.nAnalogIn1, p.uadd.nAnalogIn2) = (1, 2);
    p.g.bRun = 1;
    assert_eq!(p.cycle(0), SL_OK);
    assert_eq!(
        (p.add.nAnalogOut, p.mul.nAnalogOut, p.div.nAnalogOut),
        (50, -150, -21)
    );
    assert_eq!(p.mul.nAnalogIn1, 50, "link copied before MUL ran");
    p.estop.bRestart = 1;
    p.cycle(10);
    p.estop.bRestart = 0;
    p.cycle(20);
    assert_eq!((p.estop.bEStopOut, p.and.bAndOut), (1, 1));
    assert_eq!(p.g.nState, SL_STATE_RUN);
    assert_eq!(p.g.bFbRun, 1);
    // Sealed cycles copy each analog link as its width, no more: the second inputs right
    // after the linked ones stay the caller's.
    assert!(p.sealed());
    p.cycle(25);
    assert_eq!(
        (p.add.nAnalogOut, p.mul.nAnalogOut, p.div.nAnalogOut),
        (50, -150, -21)
    );
    assert_eq!((p.mul.nAnalogIn2, p.div.nAnalogIn2), (-3, 7));

    // An overflow in the chain stops the whole group, the Boolean outputs included.
    p.add.nAnalogIn1 = i16::MAX;
    p.cycle(30);
    assert_eq!(p.add.nState, SL_STATE_ERROR);
    assert_eq!((p.g.nState, p.g.nFailedMember), (SL_STATE_ERROR, 2));
    assert_eq!(
        (p.estop.bEStopOut, p.and.bAndOut, p.mul.nAnalogOut),
        (0, 0, 0)
    );
}

/// Sealed cycles copy the source's value of this cycle through a link of every width: a
/// 16-bit and a 32-bit value (above 16 bits) that change in every cycle reach their
/// destinations before those run.
#[test]
fn sealed_cycles_copy_every_width_as_the_source_changes() {
    let mut p = Plant::boxed();
    assert_eq!(p.link(2, ADD_OUT, 3, MUL_IN1), SL_OK);
    assert_eq!(
        p.link(
            6,
            offset_of!(FB_ADD_DINT, nAnalogOut),
            7,
            offset_of!(FB_MUL_DINT, nAnalogIn1)
        ),
        SL_OK
    );
    let kinds: Vec<u8> = p.links[..2].iter().map(|l| l.nKind).collect();
    assert_eq!(kinds, [SL_LINK_ANALOG16, SL_LINK_ANALOG32]);
    (p.mul.nAnalogIn2, p.dmul.nAnalogIn2) = (2, 2);
    p.g.bRun = 1;
    assert_eq!(p.cycle(0), SL_OK);
    for k in 1..6 {
        assert!(p.sealed(), "cycle {k}");
        (p.add.nAnalogIn1, p.add.nAnalogIn2) = (k as i16, 1);
        (p.dadd.nAnalogIn1, p.dadd.nAnalogIn2) = (100_000 * k, 1);
        assert_eq!(p.cycle(10 * k as u32), SL_OK);
        assert_eq!(
            (p.mul.nAnalogIn1, p.mul.nAnalogOut),
            (k as i16 + 1, 2 * (k as i16 + 1)),
            "cycle {k}"
        );
        assert_eq!(
            (p.dmul.nAnalogIn1, p.dmul.nAnalogOut),
            (100_000 * k + 1, 2 * (100_000 * k + 1)),
            "cycle {k}"
        );
    }
}

#[test]
fn links_between_different_types_are_refused() {
    let mut p = Plant::boxed();
    // INT → UINT (signedness), INT → BOOL, BOOL → INT.
    assert_eq!(
        p.link(2, ADD_OUT, 5, offset_of!(FB_ADD_UINT, nAnalogIn1)),
        SL_E_CONFIG
    );
    assert_eq!(
        p.link(2, ADD_OUT, 1, offset_of!(FB_AND, bAndIn1)),
        SL_E_CONFIG
    );
    assert_eq!(
        p.link(0, offset_of!(FB_ESTOP, bEStopOut), 3, MUL_IN1),
        SL_E_CONFIG
    );
    // From an input, to an output, to a parameter, to bRun, to info data.
    assert_eq!(p.link(3, MUL_IN1, 4, DIV_IN1), SL_E_CONFIG);
    assert_eq!(p.link(2, ADD_OUT, 3, MUL_OUT), SL_E_CONFIG);
    assert_eq!(
        p.link(2, ADD_OUT, 4, offset_of!(FB_DIV_INT, nRounding)),
        SL_E_CONFIG
    );
    assert_eq!(
        p.link(
            0,
            offset_of!(FB_ESTOP, bEStopOut),
            1,
            offset_of!(FB_AND, bRun)
        ),
        SL_E_CONFIG
    );
    assert_eq!(
        p.link(2, offset_of!(FB_ADD_INT, nDiag), 3, MUL_IN1),
        SL_E_CONFIG
    );
    // A misaligned offset inside a field.
    assert_eq!(p.link(2, ADD_OUT + 1, 3, MUL_IN1), SL_E_CONFIG);
    assert_eq!(p.g.nLinks, 0);
}

/// The Rust API states the kind; a kind that does not match the fields is refused.
#[test]
fn stated_kind_must_match() {
    let mut g = SL_GROUP::default();
    assert_eq!(group::init(&mut g, 2, 2), SL_OK);
    let mut a = FB_ADD_DINT::default();
    let mut m = FB_MUL_DINT::default();
    let mut members: [&mut dyn group::Member; 2] = [&mut a, &mut m];
    for _ in 0..2 {
        group::reserve_member(&mut g).unwrap();
    }
    let mut links = [SL_LINK::default(); 2];
    let link = |kind| SL_LINK {
        nSrcMember: 0,
        nSrcOffset: offset_of!(FB_ADD_DINT, nAnalogOut) as u16,
        nDstMember: 1,
        nDstOffset: offset_of!(FB_MUL_DINT, nAnalogIn2) as u16,
        nKind: kind,
        aReserved: [0; 3],
    };
    assert_eq!(
        group::add_link(&mut g, &mut members[..], &mut links, link(SL_LINK_ANALOG16)),
        SL_E_CONFIG
    );
    assert_eq!(
        group::add_link(&mut g, &mut members[..], &mut links, link(SL_LINK_BOOL)),
        SL_E_CONFIG
    );
    assert_eq!(
        group::add_link(&mut g, &mut members[..], &mut links, link(SL_LINK_ANALOG32)),
        SL_OK
    );
}
