//! FSoE connections as members of TwinSAFE groups (ABI-2 §10.7, §11.1, §13.5; manual §3.2.5,
//! §4.15; docs/semantics.md FS17–FS21, CS1–CS8), through the C functions: a master node
//! (connection + ESTOP fed by the received bits, its output sent back) and a slave node
//! ("remote safe I/O": connection + DECOUPLE whose outputs are sent), frames carried between
//! the two mailboxes. ComStartup → group START; ComErr → group ERROR diag 2, outputs FALSE
//! within the watchdog time; recovery through ErrAck; TXBIT reaches the other side;
//! FB_CONNECTION_SHUTDOWN shuts the connection down without a group error.

mod common;

use common::RawBox;
use safelogic::ffi::*;
use safelogic::fsoe::*;
use safelogic::group::{
    SL_GROUP_CONN_MAX, SL_GROUP_DIAG_COMERROR, SL_GROUP_STATE_START, SL_LINK_BOOL, SL_LINK_RXBIT,
    SL_LINK_TXBIT, SL_NO_MEMBER,
};
use safelogic::*;
use std::mem::offset_of;

const WD: u32 = 100;
const STEP: u32 = 10;

#[repr(C)]
#[derive(Default)]
struct Node {
    g: SL_GROUP,
    members: [SL_MEMBER; 4],
    links: [SL_LINK; 8],
    conn: SL_FSOE_CONN,
    estop: FB_ESTOP,
    dec: FB_DECOUPLE,
    shut: FB_CONNECTION_SHUTDOWN,
}

fn conn(role: u16) -> SL_FSOE_CONN {
    SL_FSOE_CONN {
        tWatchdogTime: WD,
        ..common::fsoe::conn(role, 2, 2, 0)
    }
}

/// A node, owned through the raw pointer of its box (freed on drop). The group keeps
/// pointers to the node's blocks across calls, so they are derived from this pointer
/// (`block`), the library calls get pointers derived from it, and no `&mut Node` is held
/// across a call: field access goes through `Deref` / `DerefMut`, a borrow that ends before
/// the next call (under Stacked Borrows, Miri, a `&mut Node` around a call would invalidate
/// the group's pointers).
type NodeRef = RawBox<Node>;

impl NodeRef {
    fn with_role(role: u16) -> NodeRef {
        let n = NodeRef::new(Node::default());
        // SAFETY (all calls of this impl): pointers to fields of a live node,
        // derived from its own raw pointer, with no reference to it alive during the call.
        unsafe {
            (*n.ptr()).conn = conn(role);
            assert_eq!(sl_fsoe_init(n.block(|n| &raw mut (*n).conn)), SL_OK);
            assert_eq!(
                sl_group_init(n.group(), n.members(), 4, n.links(), 8),
                SL_OK
            );
        }
        n
    }

    /// A field of the node, derived from the node's raw pointer (see [`NodeRef`]).
    fn block<T>(&self, field: impl FnOnce(*mut Node) -> *mut T) -> *mut T {
        field(self.ptr())
    }
    fn group(&self) -> *mut SL_GROUP {
        // SAFETY: a field place of the live node; no reference is formed.
        unsafe { &raw mut (*self.ptr()).g }
    }
    fn members(&self) -> *mut SL_MEMBER {
        // SAFETY: as in `group`.
        unsafe { &raw mut (*self.ptr()).members }.cast()
    }
    fn links(&self) -> *mut SL_LINK {
        // SAFETY: as in `group`.
        unsafe { &raw mut (*self.ptr()).links }.cast()
    }
    fn add(&self, ty: u16, p: *mut core::ffi::c_void) -> i32 {
        let mut idx = 0u16;
        // SAFETY: see `NodeRef::with_role`.
        let rc = unsafe { sl_group_add_member(self.group(), self.members(), ty, p, &mut idx) };
        if rc == SL_OK {
            assert_eq!(idx + 1, self.g.nMembers);
        }
        rc
    }
    /// `init` (the block's C init) on the node's block at `field`, then adds it as type
    /// `ty`; both must return SL_OK.
    #[track_caller]
    fn add_init<T>(
        &self,
        ty: u16,
        field: impl FnOnce(*mut Node) -> *mut T,
        init: unsafe extern "C" fn(*mut T) -> i32,
    ) {
        let p = self.block(field);
        // SAFETY: a block of the live node, no borrow of it alive.
        assert_eq!(unsafe { init(p) }, SL_OK, "init of type {ty}");
        assert_eq!(self.add(ty, p.cast()), SL_OK, "add type {ty}");
    }
    /// [`Self::with_role`] with its connection added as member 0.
    #[track_caller]
    fn with_conn(role: u16) -> NodeRef {
        let n = NodeRef::with_role(role);
        assert_eq!(n.add_conn(), SL_OK);
        n
    }
    fn add_conn(&self) -> i32 {
        // SAFETY: a field place of the live node.
        let p = self.block(|n| unsafe { &raw mut (*n).conn });
        self.add(SL_TYPE_FSOE_CONN, p.cast())
    }
    fn link(&self, kind: u8, src: u16, so: usize, dst: u16, d: usize) -> i32 {
        // SAFETY: see `NodeRef::with_role`.
        unsafe {
            sl_group_add_link_kind(
                self.group(),
                self.members(),
                self.links(),
                kind,
                src,
                so as u16,
                dst,
                d as u16,
            )
        }
    }
    /// The next cycle runs the sealed schedule (docs/performance.md): the scenarios below
    /// then exercise its hand-backs (a connection member, RXBIT/TXBIT links, a shutdown
    /// request) as well as the checked cycle.
    fn sealed(&self) -> bool {
        // SAFETY: see `NodeRef::with_role`.
        unsafe {
            safelogic::ffi::sl_group_schedule_sealed(self.group(), self.members(), self.links())
        }
    }
    fn cycle(&mut self, now: u32) -> i32 {
        self.conn.nSessionIdSeed = (now.wrapping_mul(2_654_435_761) >> 16) as u16 | 1;
        // SAFETY: see `NodeRef::with_role`.
        unsafe { sl_group_cycle(self.group(), self.members(), self.links(), now) }
    }
}

/// The node's FB_CONNECTION_SHUTDOWN (Connection ID 7, inputs `active`), initialised and
/// added as the next member.
fn add_shutdown(n: &mut NodeRef, active: u16) {
    n.shut = FB_CONNECTION_SHUTDOWN {
        nConnectionId: 7,
        wInputActive: active,
        ..Default::default()
    };
    let init = sl_connection_shutdown_init;
    // SAFETY: a field place of the live node.
    n.add_init(
        SL_TYPE_CONNECTION_SHUTDOWN,
        |n| unsafe { &raw mut (*n).shut },
        init,
    );
}

/// Master node: connection (member 0), ESTOP (member 1) with its two channels from received
/// bits 0 and 1, its EStopOut sent as bit 0; FB_CONNECTION_SHUTDOWN (member 2).
fn master() -> NodeRef {
    let mut n = NodeRef::with_conn(SL_FSOE_ROLE_MASTER);
    n.estop = FB_ESTOP {
        wInputActive: 0b11,
        ..Default::default()
    };
    // SAFETY: a field place of the live node.
    n.add_init(
        SL_TYPE_ESTOP,
        |n| unsafe { &raw mut (*n).estop },
        sl_estop_init,
    );
    add_shutdown(&mut n, 0b01);
    let in1 = offset_of!(FB_ESTOP, bEStopIn1);
    let in2 = offset_of!(FB_ESTOP, bEStopIn2);
    assert_eq!(n.link(SL_LINK_RXBIT, 0, 0, 1, in1), SL_OK);
    assert_eq!(n.link(SL_LINK_RXBIT, 0, 1, 1, in2), SL_OK);
    let out = offset_of!(FB_ESTOP, bEStopOut);
    assert_eq!(n.link(SL_LINK_TXBIT, 1, out, 0, 0), SL_OK);
    n.g.bRun = 1;
    n
}

/// Slave node ("remote safe I/O"): connection (member 0), DECOUPLE (member 1): inputs 1 and
/// 2 are the hardware e-stop channels, sent as bits 0 and 1; input 3 is received bit 0
/// (the master's EStopOut), shown at output 3. FB_CONNECTION_SHUTDOWN with no active input
/// (member 2): the partner's shutdown only.
fn slave() -> NodeRef {
    slave_with(0b111)
}

/// [`slave`] with the DECOUPLE's inputs `active`.
fn slave_with(active: u16) -> NodeRef {
    let mut n = NodeRef::with_conn(SL_FSOE_ROLE_SLAVE);
    n.dec = FB_DECOUPLE {
        wInputActive: active,
        ..Default::default()
    };
    // SAFETY: a field place of the live node.
    n.add_init(
        SL_TYPE_DECOUPLE,
        |n| unsafe { &raw mut (*n).dec },
        sl_decouple_init,
    );
    add_shutdown(&mut n, 0);
    assert_eq!(
        n.link(SL_LINK_TXBIT, 1, offset_of!(FB_DECOUPLE, bDecOut1), 0, 0),
        SL_OK
    );
    assert_eq!(
        n.link(SL_LINK_TXBIT, 1, offset_of!(FB_DECOUPLE, bDecOut2), 0, 1),
        SL_OK
    );
    assert_eq!(
        n.link(SL_LINK_RXBIT, 0, 0, 1, offset_of!(FB_DECOUPLE, bDecIn3)),
        SL_OK
    );
    n.g.bRun = 1;
    n
}

/// A connection's pointer for one call.
fn conn_ptr(c: &mut SL_FSOE_CONN) -> *mut core::ffi::c_void {
    (c as *mut SL_FSOE_CONN).cast()
}

/// The black channel: the frame in `from`'s transmit mailbox into `to`'s receive mailbox.
fn carry(from: &SL_FSOE_CONN, to: &mut SL_FSOE_CONN) {
    to.aRxFrame = from.aTxFrame;
    to.nRxFrameLen = from.nTxFrameLen;
}

struct Pair {
    m: NodeRef,
    s: NodeRef,
    t: u32,
    /// The slave process runs and its frames reach the master.
    slave_alive: bool,
}

impl Pair {
    fn new() -> Pair {
        Pair {
            m: master(),
            s: slave(),
            t: 0,
            slave_alive: true,
        }
    }
    /// One bus cycle: slave's frame → master group cycle → master's frame → slave group cycle.
    fn step(&mut self) {
        if self.slave_alive {
            carry(&self.s.conn, &mut self.m.conn);
        }
        assert_eq!(self.m.cycle(self.t), SL_OK);
        check(&self.m);
        if self.slave_alive {
            carry(&self.m.conn, &mut self.s.conn);
            assert_eq!(self.s.cycle(self.t), SL_OK);
            check(&self.s);
        }
        self.t += STEP;
    }
    fn run(&mut self, cycles: u32) {
        for _ in 0..cycles {
            self.step();
        }
    }
    /// Runs until `f` holds (at most `max` cycles); returns the cycles taken.
    fn until(&mut self, max: u32, f: impl Fn(&Pair) -> bool) -> u32 {
        for k in 0..max {
            if f(self) {
                return k;
            }
            self.step();
        }
        panic!("condition not reached in {max} cycles (t = {})", self.t);
    }
    /// The master's ESTOP restart: a pulse (falling edge enables).
    fn restart(&mut self) {
        self.m.estop.bRestart = 1;
        self.step();
        self.m.estop.bRestart = 0;
        self.step();
    }
    fn ack(n: &mut NodeRef) {
        n.g.bErrAck = 1;
    }
}

/// Invariants of a node after every cycle: the group's ComErr / ComStartup include the
/// connection's; in ERROR / STOP / START no block is in RUN and its outputs are FALSE; the
/// connection presents SafeData only when valid.
fn check(n: &Node) {
    let c = &n.conn;
    assert!(c.bComErr == 0 || n.g.bComErr == 1);
    assert!(c.bComStartup == 0 || n.g.bComStartup == 1);
    if c.bDataValid == 0 {
        assert_eq!(c.aRxSafeData, [0; 32]);
    }
    if n.g.nState != SL_STATE_RUN {
        assert_eq!((n.estop.bEStopOut, n.estop.bEStopDelOut), (0, 0));
        assert_eq!(n.dec.bDecOut3, 0);
        assert_ne!(n.estop.nState, SL_STATE_RUN);
    }
    assert_eq!(c.bRun, u8::from(n.g.nState == SL_STATE_RUN));
}

/// Brings the pair to DATA / group RUN with the e-stop released and the master's output on.
fn running() -> Pair {
    running_from(Pair::new())
}

/// [`running`] from a pair built otherwise.
fn running_from(mut p: Pair) -> Pair {
    p.s.dec.bDecIn1 = 1;
    p.s.dec.bDecIn2 = 1;
    p.step();
    // ComStartup: the groups are in START while the connections start up.
    assert_eq!(p.m.g.nState, SL_GROUP_STATE_START);
    assert_eq!((p.m.g.bComStartup, p.m.g.bComErr), (1, 0));
    assert_eq!(p.m.conn.bRun, 0);
    p.until(50, |p| {
        p.m.g.nState == SL_STATE_RUN && p.s.g.nState == SL_STATE_RUN
    });
    assert_eq!(p.m.conn.nState, SL_FSOE_STATE_DATA);
    assert_eq!(p.s.conn.nState, SL_FSOE_STATE_DATA);
    assert_eq!((p.m.g.bComStartup, p.m.g.nDiag), (0, 0));
    // The hardware channels arrive at the master's ESTOP inputs.
    p.until(5, |p| p.m.estop.bEStopIn1 == 1 && p.m.estop.bEStopIn2 == 1);
    p.restart();
    p.run(2);
    assert_eq!(p.m.estop.bEStopOut, 1, "state {}", p.m.estop.nState);
    assert!(
        p.m.sealed() && p.s.sealed(),
        "both groups run sealed from here on"
    );
    p
}

/// A BOOL link that follows an FSoE bit link into the same member: the sealed cycle's
/// straight run hands that member back to the member loop at the bit link, and the loop
/// copies the BOOL link after it too (here DECOUPLE's output 1 back into its input 4: last
/// cycle's value).
#[test]
fn a_bool_link_after_a_bit_link_into_one_member_is_copied_in_a_sealed_cycle() {
    let s = slave_with(0b1111);
    let (out1, in4) = (
        offset_of!(FB_DECOUPLE, bDecOut1),
        offset_of!(FB_DECOUPLE, bDecIn4),
    );
    assert_eq!(s.link(SL_LINK_BOOL, 1, out1, 1, in4), SL_OK);
    let kinds: Vec<(u16, u8)> = s.links[..4]
        .iter()
        .map(|l| (l.nDstMember, l.nKind))
        .collect();
    assert_eq!(
        kinds[2..],
        [(1, SL_LINK_RXBIT), (1, SL_LINK_BOOL)],
        "the BOOL link follows the bit link into DECOUPLE"
    );
    let mut p = running_from(Pair {
        m: master(),
        s,
        t: 0,
        slave_alive: true,
    });
    for v in [0, 1, 0, 1] {
        (p.s.dec.bDecIn1, p.s.dec.bDecIn2) = (v, v);
        p.run(2);
        assert!(p.s.sealed());
        assert_eq!(p.s.g.nState, SL_STATE_RUN);
        assert_eq!(
            (p.s.dec.bDecOut1, p.s.dec.bDecIn4, p.s.dec.bDecOut4),
            (v, v, v)
        );
    }
}

#[test]
fn a_signal_arrives_through_master_and_slave_into_a_block_input_and_back() {
    let mut p = running();
    // TXBIT: the master's EStopOut reached the slave's DECOUPLE input 3.
    p.until(5, |p| p.s.dec.bDecOut3 == 1);
    assert_eq!(p.m.g.bFbRun, 0, "CONNECTION_SHUTDOWN is in SAFE, not RUN");
    // The e-stop pressed on the slave side: the master's output falls.
    p.s.dec.bDecIn1 = 0;
    p.s.dec.bDecIn2 = 0;
    // Three cycles: the slave's DECOUPLE output of cycle 1 is sent by its connection in
    // cycle 2 (a TXBIT carries the value of the previous group cycle: connections run
    // first), the master receives it in cycle 3 and its ESTOP switches off in that cycle.
    let k = p.until(5, |p| p.m.estop.bEStopOut == 0);
    assert_eq!(k, 3);
    assert_eq!(p.m.estop.nState, SL_STATE_SAFE);
    p.until(5, |p| p.s.dec.bDecOut3 == 0);
    assert_eq!((p.m.g.nState, p.m.g.bComErr), (SL_STATE_RUN, 0));
}

#[test]
fn com_error_stops_the_group_within_the_watchdog_and_errack_recovers() {
    let mut p = running();
    p.slave_alive = false;
    let t_kill = p.t;
    let k = p.until(50, |p| p.m.g.nState == SL_STATE_ERROR);
    let t_err = p.t - STEP;
    assert!(
        t_err - t_kill <= WD + STEP,
        "ERROR after {} ms",
        t_err - t_kill
    );
    assert_eq!(k * STEP, t_err - t_kill + STEP);
    assert_eq!(p.m.g.nDiag, SL_GROUP_DIAG_COMERROR);
    assert_eq!((p.m.g.bComErr, p.m.g.bFbErr), (1, 0));
    assert_eq!(p.m.conn.bComErr, 1);
    assert_eq!(p.m.conn.nDiag & 0x0F, u16::from(SL_FSOE_RESET_WD_EXPIRED));
    assert_eq!((p.m.estop.bEStopOut, p.m.estop.bEStopIn1), (0, 0));
    assert_eq!(p.m.g.nFailedMember, SL_NO_MEMBER);
    // ErrAck while the slave is still gone: nothing is acknowledged.
    Pair::ack(&mut p.m);
    p.run(2);
    p.m.g.bErrAck = 0;
    p.run(2);
    assert_eq!(p.m.g.nState, SL_STATE_ERROR);
    // The slave process comes back: the connection starts up again, ComErr stays latched.
    p.slave_alive = true;
    p.until(50, |p| p.m.conn.nState == SL_FSOE_STATE_DATA);
    p.run(3);
    assert_eq!((p.m.g.nState, p.m.conn.bComErr), (SL_STATE_ERROR, 1));
    assert_eq!(p.m.conn.bDataValid, 0);
    // ErrAck on both nodes (the slave's watchdog expired too while it was gone).
    assert_eq!(p.s.g.nState, SL_STATE_ERROR);
    Pair::ack(&mut p.m);
    Pair::ack(&mut p.s);
    p.step();
    assert_eq!((p.m.g.nState, p.m.g.bComErr), (SL_STATE_RESET, 0));
    assert_eq!(p.m.conn.bComErr, 0);
    p.m.g.bErrAck = 0;
    p.s.g.bErrAck = 0;
    p.step();
    assert_eq!(p.m.g.nState, SL_STATE_RUN);
    p.until(5, |p| p.m.estop.bEStopIn1 == 1);
    p.restart();
    p.run(1);
    assert_eq!(p.m.estop.bEStopOut, 1);
    p.until(5, |p| p.s.dec.bDecOut3 == 1);
}

#[test]
fn com_error_while_starting_up_and_group_stop() {
    let mut p = Pair::new();
    // A slave that never answers: start-up, not an error (diag 15), the group stays START.
    p.slave_alive = false;
    p.run(30);
    assert_eq!(p.m.g.nState, SL_GROUP_STATE_START);
    assert_eq!((p.m.g.bComStartup, p.m.g.bComErr), (1, 0));
    assert_eq!(p.m.conn.nDiag & 0x0F, SL_FSOE_DIAG_NOT_STARTED);
    // Group STOP: a connection error is no group error there.
    p.slave_alive = true;
    p.until(50, |p| p.m.g.nState == SL_STATE_RUN);
    p.m.g.bRun = 0;
    p.s.g.bRun = 0;
    p.run(2);
    assert_eq!(p.m.g.nState, SL_STATE_STOP);
    p.slave_alive = false;
    p.run(15);
    assert_eq!(
        (p.m.g.nState, p.m.g.bComErr, p.m.conn.bComErr),
        (SL_STATE_STOP, 1, 1)
    );
    // Run again with the error latched: ERROR diag 2 at once, before any block runs.
    p.m.g.bRun = 1;
    p.step();
    assert_eq!(
        (p.m.g.nState, p.m.g.nDiag),
        (SL_STATE_ERROR, SL_GROUP_DIAG_COMERROR)
    );
    assert_eq!(p.m.estop.nState, SL_STATE_STOP);
}

#[test]
fn stand_in_inputs_still_feed_the_group_beside_connections() {
    let mut p = running();
    p.m.g.bComErrIn = 1;
    p.step();
    assert_eq!(
        (p.m.g.nState, p.m.g.nDiag),
        (SL_STATE_ERROR, SL_GROUP_DIAG_COMERROR)
    );
    assert_eq!(p.m.conn.bComErr, 0, "the connection itself is fine");
    // The group's FbRun FALSE makes the connection send FailSafeData: the slave sees zeros.
    p.until(5, |p| p.s.conn.bPeerFailSafe == 1);
    assert_eq!(p.s.dec.bDecOut3, 0);
    assert_eq!(p.s.conn.bComErr, 0);
    p.m.g.bComErrIn = 0;
    Pair::ack(&mut p.m);
    p.step();
    p.m.g.bErrAck = 0;
    p.step();
    assert_eq!(p.m.g.nState, SL_STATE_RUN);
    // ComStartup stand-in: START, then RUN again.
    p.m.g.bComStartupIn = 1;
    p.step();
    assert_eq!(p.m.g.nState, SL_GROUP_STATE_START);
    p.m.g.bComStartupIn = 0;
    p.step();
    assert_eq!(p.m.g.nState, SL_STATE_RUN);
}

#[test]
fn connection_shutdown_shuts_down_and_reports_without_a_group_error() {
    let mut p = running();
    assert_eq!(p.m.shut.nState, SL_STATE_SAFE);
    assert_eq!(p.s.shut.nState, SL_STATE_SAFE);
    p.m.shut.bDeactivate1 = 1;
    p.step();
    assert_eq!(p.m.shut.bShutdownRequest, 1);
    // The request reaches the connection in the next cycle: 106, Reset 0xFE sent.
    p.step();
    assert_eq!(p.m.conn.nState, SL_FSOE_STATE_SHUTDOWN_DEACTIVE);
    assert_eq!(p.m.conn.bShutdown, 1);
    p.until(3, |p| p.m.shut.nState == SL_STATE_RUN);
    assert_eq!((p.m.shut.bDeactivated, p.m.shut.bError), (1, 0));
    // The partner: 105, its FB_CONNECTION_SHUTDOWN (no active input) in RUN.
    p.until(3, |p| p.s.conn.nState == SL_FSOE_STATE_SHUTDOWN);
    p.until(3, |p| p.s.shut.nState == SL_STATE_RUN);
    p.run(30);
    for n in [&*p.m, &*p.s] {
        assert_eq!(
            (n.g.nState, n.g.bComErr, n.g.bComStartup),
            (SL_STATE_RUN, 0, 0)
        );
        assert_eq!(n.conn.bComErr, 0);
        assert_eq!(n.conn.aRxSafeData, [0; 32]);
    }
    assert_eq!(
        p.m.estop.bEStopOut, 0,
        "no SafeData: the e-stop inputs read FALSE"
    );
    assert_eq!(p.s.dec.bDecOut3, 0);
    // Deactivate released: the master re-establishes the connection; RUN until DATA.
    p.m.shut.bDeactivate1 = 0;
    p.step();
    assert_eq!(p.m.shut.bShutdownRequest, 0);
    assert_eq!(
        p.m.shut.nState, SL_STATE_RUN,
        "held until the connection is in DATA"
    );
    p.until(60, |p| p.m.conn.nState == SL_FSOE_STATE_DATA);
    p.until(3, |p| p.m.shut.nState == SL_STATE_SAFE);
    p.until(60, |p| p.s.shut.nState == SL_STATE_SAFE);
    assert_eq!(p.m.g.nState, SL_STATE_RUN);
    assert_eq!(p.m.conn.bComErr, 0);
    p.until(5, |p| p.m.estop.bEStopIn1 == 1);
}

#[test]
fn shutdown_request_outside_data_is_not_honoured() {
    let mut p = Pair::new();
    p.m.shut.bDeactivate1 = 1;
    p.run(3);
    // The group is in START: the block is stopped, its request FALSE.
    assert_eq!(p.m.shut.bShutdownRequest, 0);
    p.until(50, |p| p.m.g.nState == SL_STATE_RUN);
    // RUN: the request goes out and the connection (now in DATA) shuts down.
    p.until(3, |p| p.m.conn.nState == SL_FSOE_STATE_SHUTDOWN_DEACTIVE);
}

#[test]
fn links_and_members_are_checked() {
    let mut n = NodeRef::with_role(SL_FSOE_ROLE_MASTER);
    n.estop = FB_ESTOP {
        wInputActive: 0b11,
        ..Default::default()
    };
    // SAFETY: see `NodeRef::with_role`.
    unsafe { assert_eq!(sl_estop_init(&mut n.estop), SL_OK) };
    // An uninitialised connection is refused; so is one whose init was refused. (Its
    // pointer is taken anew for every call: a write to the box invalidates an older one.)
    let mut raw = Box::new(conn(SL_FSOE_ROLE_MASTER));
    assert_eq!(n.add(SL_TYPE_FSOE_CONN, conn_ptr(&mut raw)), SL_E_CONFIG);
    raw.nConnectionId = 0;
    // SAFETY: a live boxed connection.
    unsafe { assert_eq!(sl_fsoe_init(&mut *raw), SL_E_CONFIG) };
    assert_eq!(n.add(SL_TYPE_FSOE_CONN, conn_ptr(&mut raw)), SL_E_CONFIG);
    // A corrupt one.
    raw.nConnectionId = 9;
    // SAFETY: as above.
    unsafe { assert_eq!(sl_fsoe_init(&mut *raw), SL_OK) };
    raw.stPrivate.nStateInv ^= 1;
    assert_eq!(n.add(SL_TYPE_FSOE_CONN, conn_ptr(&mut raw)), SL_E_CORRUPT);
    assert_eq!(n.g.nMembers, 0);
    assert_eq!(n.add_conn(), SL_OK);
    // SAFETY: a field place of the live node.
    let p = n.block(|n| unsafe { &raw mut (*n).estop }).cast();
    assert_eq!(n.add(SL_TYPE_ESTOP, p), SL_OK);
    // A connection after a block: refused (connections run first).
    raw.stPrivate.nStateInv ^= 1;
    assert_eq!(n.add(SL_TYPE_FSOE_CONN, conn_ptr(&mut raw)), SL_E_CONFIG);
    // The same connection twice: refused (it shares bytes with a member).
    let n2 = NodeRef::with_conn(SL_FSOE_ROLE_MASTER);
    // SAFETY: a field place of the live node.
    let cp = n2.block(|n| unsafe { &raw mut (*n).conn }).cast();
    assert_eq!(n2.add(SL_TYPE_FSOE_CONN, cp), SL_E_CONFIG);

    let in1 = offset_of!(FB_ESTOP, bEStopIn1);
    let out = offset_of!(FB_ESTOP, bEStopOut);
    let t1 = offset_of!(FB_ESTOP, tDiscTime12);
    // RXBIT: bits 0..15 of a 2-byte SafeData; into a BOOL input only; from a connection only.
    assert_eq!(n.link(SL_LINK_RXBIT, 0, 16, 1, in1), SL_E_CONFIG);
    assert_eq!(n.link(SL_LINK_RXBIT, 0, 0, 1, t1), SL_E_CONFIG);
    assert_eq!(n.link(SL_LINK_RXBIT, 0, 0, 1, out), SL_E_CONFIG);
    assert_eq!(n.link(SL_LINK_RXBIT, 1, out, 1, in1), SL_E_CONFIG);
    assert_eq!(n.link(SL_LINK_RXBIT, 0, 15, 1, in1), SL_OK);
    assert_eq!(
        n.link(SL_LINK_RXBIT, 0, 3, 1, in1),
        SL_E_CONFIG,
        "already linked"
    );
    // TXBIT: from a BOOL output to a bit of a connection.
    assert_eq!(n.link(SL_LINK_TXBIT, 1, out, 0, 16), SL_E_CONFIG);
    assert_eq!(n.link(SL_LINK_TXBIT, 1, in1, 0, 0), SL_E_CONFIG);
    assert_eq!(n.link(SL_LINK_TXBIT, 1, out, 1, 0), SL_E_CONFIG);
    assert_eq!(n.link(SL_LINK_TXBIT, 1, out, 0, 3), SL_OK);
    assert_eq!(
        n.link(SL_LINK_TXBIT, 1, out, 0, 3),
        SL_E_CONFIG,
        "already linked"
    );
    // Bit 3 of the SafeData and the connection's input byte 3 (bShutdownRequest) differ.
    let sr = offset_of!(SL_FSOE_CONN, bShutdownRequest);
    assert_eq!(sr, 3);
    assert_eq!(n.link(SL_LINK_BOOL, 1, out, 0, sr), SL_OK);
    // A BOOL link from a connection output to a block input.
    let in2 = offset_of!(FB_ESTOP, bEStopIn2);
    let ce = offset_of!(SL_FSOE_CONN, bDataValid);
    assert_eq!(n.link(SL_LINK_BOOL, 0, ce, 1, in2), SL_OK);
    assert_eq!(
        n.link(5, 0, 0, 1, offset_of!(FB_ESTOP, bRestart)),
        SL_E_CONFIG
    );
}

#[test]
fn at_most_sl_group_conn_max_connections() {
    let cap = SL_GROUP_CONN_MAX + 1;
    let mut group = Box::<SL_GROUP>::default();
    let mut members = vec![SL_MEMBER::default(); usize::from(cap)];
    let mut conns = vec![conn(SL_FSOE_ROLE_MASTER); usize::from(cap)];
    let (g, mt, cs) = (
        &mut *group as *mut SL_GROUP,
        members.as_mut_ptr(),
        conns.as_mut_ptr(),
    );
    // SAFETY: live storage, reached only through these pointers while the group holds them.
    unsafe {
        assert_eq!(sl_group_init(g, mt, cap, std::ptr::null_mut(), 0), SL_OK);
        for k in 0..usize::from(cap) {
            let c = cs.add(k);
            (*c).nConnectionId = 1 + k as u16;
            assert_eq!(sl_fsoe_init(c), SL_OK);
            let rc = sl_group_add_member(g, mt, SL_TYPE_FSOE_CONN, c.cast(), std::ptr::null_mut());
            let want = if k < usize::from(SL_GROUP_CONN_MAX) {
                SL_OK
            } else {
                SL_E_FULL
            };
            assert_eq!(rc, want, "connection {k}");
        }
    }
}

#[test]
fn a_corrupt_connection_is_a_com_error_of_the_group() {
    let mut p = running();
    p.m.conn.stPrivate.nStateInv ^= 0x10;
    carry(&p.s.conn, &mut p.m.conn);
    assert_eq!(p.m.cycle(p.t), SL_E_CORRUPT);
    assert_eq!(
        (p.m.g.nState, p.m.g.nDiag),
        (SL_STATE_ERROR, SL_GROUP_DIAG_COMERROR)
    );
    assert_eq!(p.m.estop.bEStopOut, 0);
    assert_eq!(p.m.conn.aRxSafeData, [0; 32]);
}

#[test]
fn rust_members_slice_with_a_connection() {
    use safelogic::group::{self, Member};
    let mut m = conn(SL_FSOE_ROLE_MASTER);
    assert_eq!(fsoe::conn::init(&mut m), Status::Ok);
    let mut e = common::ready(FB_ESTOP {
        wInputActive: 0b11,
        ..Default::default()
    });
    let mut g = SL_GROUP {
        bRun: 1,
        ..Default::default()
    };
    assert_eq!(group::init(&mut g, 2, 1), SL_OK);
    group::reserve_member(&mut g).unwrap();
    group::reserve_member(&mut g).unwrap();
    let mut links = [SL_LINK::default(); 1];
    {
        let mut members: [&mut dyn Member; 2] = [&mut m, &mut e];
        let l = SL_LINK {
            nSrcMember: 0,
            nSrcOffset: 0,
            nDstMember: 1,
            nDstOffset: offset_of!(FB_ESTOP, bEStopIn1) as u16,
            nKind: SL_LINK_RXBIT,
            aReserved: [0; 3],
        };
        assert_eq!(
            group::add_link(&mut g, &mut members[..], &mut links, l),
            SL_OK
        );
        assert_eq!(group::cycle(&mut g, &mut members[..], &links, 0), SL_OK);
    }
    // The master sent its first Reset frame into the mailbox; the group is in START.
    assert_eq!((m.nTxFrameLen, m.nTxCount), (7, 1));
    assert_eq!(m.aTxFrame[0], SL_FSOE_CMD_RESET);
    assert_eq!(g.nState, SL_GROUP_STATE_START);
    // A received length beyond the mailbox: SL_E_LENGTH, the frame ignored.
    m.nRxFrameLen = 200;
    let mut members: [&mut dyn Member; 2] = [&mut m, &mut e];
    assert_eq!(
        group::cycle(&mut g, &mut members[..], &links, 1),
        SL_E_LENGTH
    );
}
