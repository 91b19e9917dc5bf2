// The public header compiled as C++17 (ABI.md §1: "compiles cleanly ... as C++17"), with
// static_assert on a few published offsets (literal numbers from ABI.md §8/§9 / the manual)
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
static_assert(sizeof(FB_ESTOP) == 152, "sizeof FB_ESTOP");

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
static_assert(sizeof(FB_MON) == 152, "sizeof FB_MON");

// The eleven blocks of ABI §9: standard layout, a few offsets (inputs absolute, outputs at
// output base + the manual's offset), info data, private state and size from the header.
#define SL_CXX_PLAIN(T)                                                              \
    static_assert(std::is_standard_layout<T>::value, #T " is standard-layout");      \
    static_assert(std::is_trivially_copyable<T>::value, #T " is trivially copyable")
SL_CXX_PLAIN(FB_XOR);
SL_CXX_PLAIN(FB_DECOUPLE);
SL_CXX_PLAIN(FB_OPMODE);
SL_CXX_PLAIN(FB_TWOHAND);
SL_CXX_PLAIN(FB_MUTING);
SL_CXX_PLAIN(FB_EDM);
SL_CXX_PLAIN(FB_RS);
SL_CXX_PLAIN(FB_SR);
SL_CXX_PLAIN(FB_TON);
SL_CXX_PLAIN(FB_TON2);
SL_CXX_PLAIN(FB_TOF);

static_assert(offsetof(FB_XOR, bXor1In1) == 0, "FB_XOR.bXor1In1");
static_assert(offsetof(FB_XOR, bXor2In1) == 1, "FB_XOR.bXor2In1");
static_assert(offsetof(FB_XOR, bXor2In8) == 15, "FB_XOR.bXor2In8");
static_assert(offsetof(FB_XOR, bXorOut1) == 24 + 8, "FB_XOR.bXorOut1");
static_assert(offsetof(FB_XOR, bXorOut8) == 24 + 15, "FB_XOR.bXorOut8");
static_assert(offsetof(FB_XOR, nState) == 40 && offsetof(FB_XOR, nDiag) == 42, "FB_XOR info");
static_assert(offsetof(FB_XOR, stPrivate) == 48 && sizeof(FB_XOR) == 112, "FB_XOR size");

static_assert(offsetof(FB_DECOUPLE, bDecIn1) == 8, "FB_DECOUPLE.bDecIn1");
static_assert(offsetof(FB_DECOUPLE, bDecOut8) == 24 + 15, "FB_DECOUPLE.bDecOut8");
static_assert(sizeof(FB_DECOUPLE) == 112, "sizeof FB_DECOUPLE");

static_assert(offsetof(FB_OPMODE, bRestart) == 0, "FB_OPMODE.bRestart");
static_assert(offsetof(FB_OPMODE, bOpIn8) == 15, "FB_OPMODE.bOpIn8");
static_assert(offsetof(FB_OPMODE, tDiscTime) == 20, "FB_OPMODE.tDiscTime");
static_assert(offsetof(FB_OPMODE, bError) == 32 + 0, "FB_OPMODE.bError");
static_assert(offsetof(FB_OPMODE, bOpOut1) == 32 + 8, "FB_OPMODE.bOpOut1");
static_assert(offsetof(FB_OPMODE, nState) == 48 && offsetof(FB_OPMODE, nDiag) == 50,
              "FB_OPMODE info");
static_assert(offsetof(FB_OPMODE, stPrivate) == 56 && sizeof(FB_OPMODE) == 88, "FB_OPMODE");

static_assert(offsetof(FB_TWOHAND, bTwoHand1) == 8, "FB_TWOHAND.bTwoHand1");
static_assert(offsetof(FB_TWOHAND, bTwoHand4) == 11, "FB_TWOHAND.bTwoHand4");
static_assert(offsetof(FB_TWOHAND, tDiscTimePairs) == 28, "FB_TWOHAND.tDiscTimePairs");
static_assert(offsetof(FB_TWOHAND, bTwoHandOut) == 40 + 1, "FB_TWOHAND.bTwoHandOut");
static_assert(sizeof(FB_TWOHAND) == 104, "sizeof FB_TWOHAND");

static_assert(offsetof(FB_MUTING, bMutingEnable) == 0, "FB_MUTING.bMutingEnable");
static_assert(offsetof(FB_MUTING, bOSSDIn1) == 10, "FB_MUTING.bOSSDIn1");
static_assert(offsetof(FB_MUTING, bMutingIn4) == 13, "FB_MUTING.bMutingIn4");
static_assert(offsetof(FB_MUTING, tMaxMutingTime) == 36, "FB_MUTING.tMaxMutingTime");
static_assert(offsetof(FB_MUTING, bMuteDelOut) == 56 + 3, "FB_MUTING.bMuteDelOut");
static_assert(offsetof(FB_MUTING, nState) == 64 && offsetof(FB_MUTING, nDiag) == 66,
              "FB_MUTING info");
static_assert(offsetof(FB_MUTING, stPrivate) == 72 && sizeof(FB_MUTING) == 144, "FB_MUTING");

static_assert(offsetof(FB_EDM, bMon2) == 9, "FB_EDM.bMon2");
static_assert(offsetof(FB_EDM, bError) == 32 + 0, "FB_EDM.bError");
static_assert(sizeof(FB_EDM) == 80, "sizeof FB_EDM");

static_assert(offsetof(FB_RS, bReset) == 8 && offsetof(FB_RS, bSet) == 9, "FB_RS inputs");
static_assert(offsetof(FB_RS, bRsOut) == 24 + 1, "FB_RS.bRsOut");
static_assert(offsetof(FB_SR, bReset) == 8 && offsetof(FB_SR, bSet) == 9, "FB_SR inputs");
static_assert(offsetof(FB_SR, bSrOut) == 24 + 1, "FB_SR.bSrOut");
static_assert(sizeof(FB_RS) == 104 && sizeof(FB_SR) == 104, "sizeof FB_RS / FB_SR");

static_assert(offsetof(FB_TON, bTonIn1) == 8, "FB_TON.bTonIn1");
static_assert(offsetof(FB_TON, bTonOut) == 32 + 1, "FB_TON.bTonOut");
static_assert(sizeof(FB_TON) == 112, "sizeof FB_TON");
static_assert(offsetof(FB_TON2, bEnable) == 9, "FB_TON2.bEnable");
static_assert(offsetof(FB_TON2, dwOptions) == 32, "FB_TON2.dwOptions");
static_assert(offsetof(FB_TON2, bTonOut) == 40 + 1, "FB_TON2.bTonOut");
static_assert(sizeof(FB_TON2) == 120, "sizeof FB_TON2");
static_assert(offsetof(FB_TOF, bTofIn1) == 8, "FB_TOF.bTofIn1");
static_assert(offsetof(FB_TOF, bTofOut) == 32 + 1, "FB_TOF.bTofOut");
static_assert(sizeof(FB_TOF) == 112, "sizeof FB_TOF");

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
    FB_TON2 ton2{};
    std::uint32_t elapsed = 1;
    ton2.wInputActive = 0x01;
    ton2.tDelay = 1000;
    const int32_t rc3 = sl_ton2_init(&ton2);
    const int32_t rc4 = sl_ton2_get_elapsed(&ton2, &elapsed);
    std::printf("C++17: sizeof(FB_MUTING)=%zu, TON2 init %s, elapsed %lu, state %s\n",
                sizeof(FB_MUTING), sl_status_str(rc3), static_cast<unsigned long>(elapsed),
                sl_state_str(SL_TYPE_TON2, ton2.nState));
    if (rc3 != SL_OK || rc4 != SL_OK || elapsed != 0 || ton2.nState != SL_STATE_STOP) {
        return 1;
    }
    return (rc1 == SL_OK && rc2 == SL_OK && es.nState == SL_STATE_STOP &&
            mon.nState == SL_STATE_STOP)
               ? 0
               : 1;
}
