//! A group driven through the C API (`sl_group_*`), its members in [`RawBox`]es so that the
//! pointers the group keeps stay valid while the test reads and writes the blocks between
//! calls.

use super::RawBox;
use safelogic::ffi::*;
use safelogic::*;

/// An `SL_GROUP` with its member and link tables and a clock. The group is boxed: it must
/// not move after `sl_group_init`.
pub struct CGroup {
    pub g: RawBox<SL_GROUP>,
    members: Vec<SL_MEMBER>,
    links: Vec<SL_LINK>,
    pub now: u32,
}

/// Offset of the field `name` of block type `ty` as the registry lists it.
pub fn field(ty: u16, name: &str) -> u16 {
    registry::block_type(ty)
        .and_then(|t| t.field(name))
        .unwrap_or_else(|| panic!("type {ty} has no field {name}"))
        .offset
}

impl CGroup {
    /// `sl_group_init` with tables of `members` and `links` entries (must return SL_OK).
    #[track_caller]
    pub fn new(members: u16, links: u16) -> Self {
        let mut s = CGroup {
            g: RawBox::new(SL_GROUP::default()),
            members: vec![SL_MEMBER::default(); members.into()],
            links: vec![SL_LINK::default(); links.into()],
            now: 0,
        };
        // SAFETY: the tables are live for the group's life and hold the stated counts.
        let rc = unsafe {
            sl_group_init(
                s.g.ptr(),
                s.members.as_mut_ptr(),
                members,
                s.links.as_mut_ptr(),
                links,
            )
        };
        assert_eq!(rc, SL_OK, "sl_group_init");
        s
    }

    /// `sl_group_add_member` of the block in `b` as type `ty`: its status.
    pub fn add<T>(&mut self, ty: u16, b: &RawBox<T>) -> i32 {
        // SAFETY: `b` owns a live block that outlives the group's use in the test.
        unsafe {
            sl_group_add_member(
                self.g.ptr(),
                self.members.as_mut_ptr(),
                ty,
                b.ptr().cast(),
                std::ptr::null_mut(),
            )
        }
    }

    /// `init` (the block's C init) on `b`, then adds it as type `ty`; both must return SL_OK.
    #[track_caller]
    pub fn add_init<T>(
        &mut self,
        ty: u16,
        b: &RawBox<T>,
        init: unsafe extern "C" fn(*mut T) -> i32,
    ) {
        // SAFETY: a live block, no borrow of it alive.
        assert_eq!(unsafe { init(b.ptr()) }, SL_OK, "init of type {ty}");
        assert_eq!(self.add(ty, b), SL_OK, "sl_group_add_member type {ty}");
    }

    /// Adds the SF_EmergencyStop in `es` after its C init (both must return SL_OK).
    #[track_caller]
    pub fn add_estop(&mut self, es: &RawBox<SF_EmergencyStop>) {
        self.add_init(SL_TYPE_SF_EMERGENCYSTOP, es, sl_sf_emergencystop_init);
    }

    /// `sl_group_add_link` from member `src` at `src_off` to member `dst` at `dst_off`
    /// (must return SL_OK).
    #[track_caller]
    pub fn link(&mut self, src: u16, src_off: u16, dst: u16, dst_off: u16) {
        // SAFETY: the group's own tables.
        let rc = unsafe {
            sl_group_add_link(
                self.g.ptr(),
                self.members.as_mut_ptr(),
                self.links.as_mut_ptr(),
                src,
                src_off,
                dst,
                dst_off,
            )
        };
        assert_eq!(rc, SL_OK, "link {src}@{src_off} -> {dst}@{dst_off}");
    }

    /// One `sl_group_cycle`, `dt` ms after the last.
    pub fn cycle(&mut self, dt: u32) -> i32 {
        self.now = self.now.wrapping_add(dt);
        // SAFETY: the group's own tables; the members' boxes are alive and not borrowed.
        unsafe {
            sl_group_cycle(
                self.g.ptr(),
                self.members.as_mut_ptr(),
                self.links.as_mut_ptr(),
                self.now,
            )
        }
    }
}

/// An FB_AND with inputs 1 and 2 active and `bAndIn2` TRUE: its output follows `bAndIn1`.
pub fn and_following_in1() -> RawBox<FB_AND> {
    RawBox::new(FB_AND {
        wInputActive: 0x3,
        bAndIn2: 1,
        ..Default::default()
    })
}

/// A PLCopen block whose safety output (at `out`) is linked to `bAndIn1` of an FB_AND with
/// inputs 1 and 2 active and `bAndIn2` TRUE: members 0 (the block) and 1 (the AND).
pub struct WithAnd<T> {
    pub grp: CGroup,
    pub fb: RawBox<T>,
    pub and: RawBox<FB_AND>,
}

impl<T> WithAnd<T> {
    /// Builds the group around `fb` of type `ty`, running (bRun): the group refuses the
    /// block before `init` (semantics PO8) and accepts it after.
    #[track_caller]
    pub fn new(ty: u16, fb: T, init: unsafe extern "C" fn(*mut T) -> i32, out: usize) -> Self {
        let mut grp = CGroup::new(2, 1);
        let fb = RawBox::new(fb);
        assert_eq!(grp.add(ty, &fb), SL_E_CONFIG, "never initialised");
        let and = and_following_in1();
        grp.add_init(ty, &fb, init);
        grp.add_init(SL_TYPE_AND, &and, sl_and_init);
        grp.link(0, out as u16, 1, field(SL_TYPE_AND, "bAndIn1"));
        grp.g.bRun = 1;
        WithAnd { grp, fb, and }
    }

    /// `n` group calls 10 ms apart, each SL_OK.
    #[track_caller]
    pub fn run(&mut self, n: usize) {
        for k in 0..n {
            assert_eq!(self.grp.cycle(10), SL_OK, "group call {k}");
        }
    }
}

/// A PLCopen block's type code, C init and the outputs every PLCopen block has, for
/// [`WithAnd`].
pub trait SfMember: Sized {
    const TYPE: u16;
    const INIT: unsafe extern "C" fn(*mut Self) -> i32;
    fn diag_code(&self) -> u16;
    fn ready(&self) -> u8;
}

macro_rules! sf_member {
    ($($t:ident = $ty:ident, $init:ident;)*) => {
        $(impl SfMember for $t {
            const TYPE: u16 = $ty;
            const INIT: unsafe extern "C" fn(*mut Self) -> i32 = $init;
            fn diag_code(&self) -> u16 {
                self.DiagCode
            }
            fn ready(&self) -> u8 {
                self.Ready
            }
        })*
    };
}

sf_member! {
    SF_EmergencyStop = SL_TYPE_SF_EMERGENCYSTOP, sl_sf_emergencystop_init;
    SF_EnableSwitch = SL_TYPE_SF_ENABLESWITCH, sl_sf_enableswitch_init;
    SF_Guard = SL_TYPE_SF_GUARD, sl_sf_guard_init;
    SF_ModeSelector = SL_TYPE_SF_MODESELECTOR, sl_sf_modeselector_init;
    SF_SafetyRequest = SL_TYPE_SF_SAFETYREQUEST, sl_sf_safetyrequest_init;
    SF_TestableSafetySensor = SL_TYPE_SF_TESTABLESAFETYSENSOR, sl_sf_testablesafetysensor_init;
    SF_TwoHandControlTypeIII = SL_TYPE_SF_TWOHANDCONTROLTYPEIII, sl_sf_twohandcontroltypeiii_init;
}

impl<T: SfMember> WithAnd<T> {
    /// [`Self::new`] with the block's type code and C init; `out` names its safety output
    /// as the registry lists it.
    #[track_caller]
    pub fn of(fb: T, out: &str) -> Self {
        Self::new(T::TYPE, fb, T::INIT, field(T::TYPE, out).into())
    }

    /// The block's DiagCode and the AND's output (the value the link carried).
    #[track_caller]
    pub fn expect(&self, code: u16, and_out: u8) {
        assert_eq!(
            (self.fb.diag_code(), self.and.bAndOut),
            (code, and_out),
            "(DiagCode, AND output)"
        );
    }

    /// As [`Self::expect`], and the group's state: a PLCopen error leaves the group running.
    #[track_caller]
    pub fn expect_group(&self, code: u16, and_out: u8, group: u8) {
        assert_eq!(
            (self.fb.diag_code(), self.and.bAndOut, self.grp.g.nState),
            (code, and_out, group),
            "(DiagCode, AND output, group state)"
        );
    }

    /// Group STOP (its FbRun FALSE): the call returns SL_OK and halts the block, DiagCode
    /// 0000 and Ready FALSE.
    #[track_caller]
    pub fn stop_group(&mut self) {
        self.grp.g.bRun = 0;
        assert_eq!(self.grp.cycle(10), SL_OK, "group STOP");
        assert_eq!(
            (self.fb.diag_code(), self.fb.ready()),
            (0, 0),
            "(DiagCode, Ready) after the group's STOP"
        );
    }
}
