// The public header compiled as C++17 (ABI.md §1: "compiles cleanly ... as C++17"), with
// static_assert on a few published offsets (literal numbers from ABI.md §8 / the manual)
// and a call through the extern "C" declarations.
#include "safelogic.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <type_traits>

static_assert(std::is_standard_layout<FB_ESTOP>::value, "FB_ESTOP is standard-layout");
static_assert(std::is_trivially_copyable<FB_ESTOP>::value, "FB_ESTOP is trivially copyable");
static_assert(std::is_standard_layout<FB_MON>::value, "FB_MON is standard-layout");
static_assert(std::is_trivially_copyable<FB_MON>::value, "FB_MON is trivially copyable");
static_assert(std::is_same<SL_BOOL, std::uint8_t>::value, "SL_BOOL is uint8_t");

static_assert(offsetof(FB_ESTOP, bRestart) == 0, "FB_ESTOP.bRestart");
static_assert(offsetof(FB_ESTOP, bEDM2) == 2, "FB_ESTOP.bEDM2");
static_assert(offsetof(FB_ESTOP, bEStopIn1) == 8, "FB_ESTOP.bEStopIn1");
static_assert(offsetof(FB_ESTOP, bEStopIn8) == 15, "FB_ESTOP.bEStopIn8");
static_assert(offsetof(FB_ESTOP, bRun) == 16, "FB_ESTOP.bRun");
static_assert(offsetof(FB_ESTOP, bErrAck) == 17, "FB_ESTOP.bErrAck");
static_assert(offsetof(FB_ESTOP, tEStopDelOutDelay) == 44, "FB_ESTOP.tEStopDelOutDelay");
static_assert(offsetof(FB_ESTOP, bError) == 56, "FB_ESTOP.bError");
static_assert(offsetof(FB_ESTOP, bEStopOut) == 57, "FB_ESTOP.bEStopOut");
static_assert(offsetof(FB_ESTOP, bEStopDelOut) == 58, "FB_ESTOP.bEStopDelOut");
static_assert(offsetof(FB_ESTOP, nState) == 64, "FB_ESTOP.nState");
static_assert(offsetof(FB_ESTOP, nDiag) == 66, "FB_ESTOP.nDiag");
static_assert(offsetof(FB_ESTOP, stPrivate) == 72, "FB_ESTOP.stPrivate");
static_assert(sizeof(FB_ESTOP) == 136, "sizeof FB_ESTOP");

static_assert(offsetof(FB_MON, bMonIn1) == 8, "FB_MON.bMonIn1");
static_assert(offsetof(FB_MON, bSecure1) == 12, "FB_MON.bSecure1");
static_assert(offsetof(FB_MON, bSecure2) == 13, "FB_MON.bSecure2");
static_assert(offsetof(FB_MON, bRun) == 16, "FB_MON.bRun");
static_assert(offsetof(FB_MON, bErrAck) == 17, "FB_MON.bErrAck");
static_assert(offsetof(FB_MON, tMonDelOutDelay) == 40, "FB_MON.tMonDelOutDelay");
static_assert(offsetof(FB_MON, dwOptions) == 48, "FB_MON.dwOptions");
static_assert(offsetof(FB_MON, bError) == 56, "FB_MON.bError");
static_assert(offsetof(FB_MON, bMonOut) == 57, "FB_MON.bMonOut");
static_assert(offsetof(FB_MON, bMonDelOut) == 58, "FB_MON.bMonDelOut");
static_assert(offsetof(FB_MON, nState) == 64, "FB_MON.nState");
static_assert(offsetof(FB_MON, nDiag) == 66, "FB_MON.nDiag");
static_assert(offsetof(FB_MON, stPrivate) == 72, "FB_MON.stPrivate");
static_assert(sizeof(FB_MON) == 136, "sizeof FB_MON");

int main()
{
    FB_ESTOP es{};
    FB_MON mon{};
    es.wInputActive = 0x03;
    mon.wInputActive = 0x03;
    const int32_t rc1 = sl_estop_init(&es);
    const int32_t rc2 = sl_mon_init(&mon);
    std::printf("C++17: safelogic %s, sizeof(FB_ESTOP)=%zu sizeof(FB_MON)=%zu, init %s / %s, "
                "state %s / %s\n",
                sl_version(), sizeof(FB_ESTOP), sizeof(FB_MON), sl_status_str(rc1),
                sl_status_str(rc2), sl_state_str(SL_TYPE_ESTOP, es.nState), sl_state_str(SL_TYPE_MON, mon.nState));
    return (rc1 == SL_OK && rc2 == SL_OK && es.nState == SL_STATE_STOP &&
            mon.nState == SL_STATE_STOP)
               ? 0
               : 1;
}
