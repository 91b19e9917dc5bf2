//! The group API against callers that get things wrong (issue "Reliability proven"): a
//! refused or premature re-init never detaches the members of a running group, and a
//! member that cannot be reached stops the group instead of being skipped.

use safelogic::ffi;
use safelogic::*;
use std::ffi::c_void;

struct Fixture {
    g: SL_GROUP,
    members: [SL_MEMBER; 2],
    links: [SL_LINK; 2],
    estop: FB_ESTOP,
}

fn running_estop_group() -> Box<Fixture> {
    let mut f = Box::new(Fixture {
        g: SL_GROUP::default(),
        members: [SL_MEMBER::default(); 2],
        links: [SL_LINK::default(); 2],
        estop: FB_ESTOP {
            wInputActive: 0b11,
            tDiscTime12: 50,
            ..Default::default()
        },
    });
    assert_eq!(f.estop.init(), SL_OK);
    let f_ptr: *mut Fixture = &mut *f;
    // SAFETY: every pointer is to a live field of the boxed fixture.
    unsafe {
        let f = &mut *f_ptr;
        assert_eq!(
            ffi::sl_group_init(&mut f.g, f.members.as_mut_ptr(), 2, f.links.as_mut_ptr(), 2),
            SL_OK
        );
        let e: *mut c_void = (&mut f.estop as *mut FB_ESTOP).cast();
        assert_eq!(
            ffi::sl_group_add_member(
                &mut f.g,
                f.members.as_mut_ptr(),
                SL_TYPE_ESTOP,
                e,
                std::ptr::null_mut()
            ),
            SL_OK
        );
    }
    f.estop.bEStopIn1 = 1;
    f.estop.bEStopIn2 = 1;
    f.g.bRun = 1;
    cycle(&mut f, 0);
    f.estop.bRestart = 1;
    cycle(&mut f, 10);
    f.estop.bRestart = 0;
    cycle(&mut f, 20);
    assert_eq!(f.g.nState, SL_STATE_RUN);
    assert_eq!(f.estop.bEStopOut, 1);
    f
}

fn cycle(f: &mut Fixture, t: u32) -> i32 {
    // SAFETY: the fixture's own tables, as passed to sl_group_init.
    unsafe { ffi::sl_group_cycle(&mut f.g, f.members.as_mut_ptr(), f.links.as_mut_ptr(), t) }
}

fn press_estop_and_cycle(f: &mut Fixture) {
    f.estop.bEStopIn1 = 0;
    f.estop.bEStopIn2 = 0;
    cycle(f, 30);
    assert_eq!(
        f.estop.bEStopOut, 0,
        "the E-stop output must follow the E-stop"
    );
}

/// The reproducer of the issue: a refused init (bConnections = 2) must change nothing.
#[test]
fn refused_init_keeps_the_members_of_a_running_group() {
    let mut f = running_estop_group();
    f.g.bConnections = 2;
    // SAFETY: the fixture's own tables.
    let rc =
        unsafe { ffi::sl_group_init(&mut f.g, f.members.as_mut_ptr(), 2, f.links.as_mut_ptr(), 2) };
    assert_eq!(rc, SL_E_CONFIG);
    assert!(!f.members[0].pBlock.is_null(), "member table untouched");
    f.g.bConnections = 0;
    press_estop_and_cycle(&mut f);
}

/// A refused init for a NULL table changes nothing either.
#[test]
fn init_with_null_links_keeps_the_members() {
    let mut f = running_estop_group();
    // SAFETY: the fixture's member table; links NULL with a capacity is refused.
    let rc =
        unsafe { ffi::sl_group_init(&mut f.g, f.members.as_mut_ptr(), 2, std::ptr::null_mut(), 2) };
    assert_eq!(rc, SL_E_NULL);
    assert!(!f.members[0].pBlock.is_null());
    press_estop_and_cycle(&mut f);
}

/// A valid init of a group that is still running is refused (semantics GR13).
#[test]
fn init_of_a_running_group_is_refused() {
    let mut f = running_estop_group();
    // SAFETY: the fixture's own tables.
    let rc =
        unsafe { ffi::sl_group_init(&mut f.g, f.members.as_mut_ptr(), 2, f.links.as_mut_ptr(), 2) };
    assert_eq!(rc, SL_E_CONFIG);
    press_estop_and_cycle(&mut f);
    // Stopped, the group may be initialised again.
    f.g.bRun = 0;
    cycle(&mut f, 40);
    assert_eq!(f.g.nState, SL_STATE_STOP);
    // SAFETY: the fixture's own tables.
    let rc =
        unsafe { ffi::sl_group_init(&mut f.g, f.members.as_mut_ptr(), 2, f.links.as_mut_ptr(), 2) };
    assert_eq!(rc, SL_OK);
    assert_eq!(f.g.nMembers, 0);
}

/// A member entry that no longer reaches a block puts the group into ERROR.
#[test]
fn unreachable_member_is_a_group_error() {
    let mut f = running_estop_group();
    f.members[0].pBlock = std::ptr::null_mut();
    assert_eq!(cycle(&mut f, 30), SL_E_CORRUPT);
    assert_eq!(f.g.nState, SL_STATE_ERROR);
    assert_eq!(f.g.bFbErr, 1);
    assert_eq!(f.g.bInRun, 0);
    assert_eq!(f.g.bFbRun, 0);
    assert_eq!(f.g.nFailedMember, 0);
}
