/*
 * FB_SBT through the C ABI (manual §4.30, ABI-2 §11.15; docs/semantics.md BT1-BT8): a brake
 * test that passes (TEST-OK, RUN with BrakeValid), one that fails by a slipping position
 * (TEST-FAILED 0x40DA), and the interval expiring (MONS-ERROR 0x40D9).
 */
#include "harness.h"

static FB_SBT sbt_config(void)
{
    FB_SBT b;
    memset(&b, 0, sizeof b);
    b.wInputActive = SL_SBT_ACTIVE_SBT | SL_SBT_ACTIVE_SBCIN | SL_SBT_ACTIVE_SINGLETURNPOS |
                     SL_SBT_ACTIVE_ACTCURRENTIQ | SL_SBT_ACTIVE_MINCURRENTIQ;
    b.tBrakeTestInterval = 5000;
    b.tMinDuration = 500;
    b.tMaxDuration = 2000;
    b.nMaxPositionDeviation = 4;
    return b;
}

static void sbt_pass_then_expire(void)
{
    FB_SBT b = sbt_config();
    h_begin("SBT: test passes after MinDuration (TEST-OK, RUN), interval expires (MONS-ERROR 0x40D9) (BT3, BT6)");
    CHECK_INT(sl_sbt_init(&b), SL_OK);
    b.bRun = 1;
    b.nMinCurrentIq = 300;
    CHECK_INT(sl_sbt_cycle(&b, 0), SL_OK);
    CHECK_INT(b.nState, SL_STATE_SAFE);
    CHECK_INT(b.nRemainingTime, 5);
    b.bSBT = 1;
    b.nActCurrentIq = 300;
    b.nSingleturnPos = 1000;
    sl_sbt_cycle(&b, 1000);
    CHECK_INT(b.nState, SL_STATE_SBT_TESTING);
    CHECK_INT(b.bBrakeValid, 0);
    sl_sbt_cycle(&b, 1500);
    CHECK_INT(b.nState, SL_STATE_SBT_TEST_OK);
    CHECK_INT(b.bBrakeValid, 1);
    CHECK_INT(b.nRemainingTime, 5);
    CHECK_STR(sl_state_str(SL_TYPE_SBT, b.nState), "TEST-OK");
    b.bSBT = 0;
    sl_sbt_cycle(&b, 1600);
    CHECK_INT(b.nState, SL_STATE_RUN);
    CHECK_INT(b.bBrakeValid, 1);
    sl_sbt_cycle(&b, 6500);
    CHECK_INT(b.nState, SL_STATE_SBT_MONS_ERROR);
    CHECK_INT(b.bTestError, 1);
    CHECK_INT(b.bBrakeValid, 0);
    CHECK_INT(b.nRemainingTime, 0);
    CHECK_INT(b.nDiagTextId, SL_TEXT_SBT_INTERVAL_EXPIRED);
    CHECK_INT(b.nDiag, 0xD9);
    CHECK_INT(b.dwDiagPar2, 0x14);
    CHECK_INT(b.dwDiagPar3, 1000);
    h_end();
}

static void sbt_slipping_brake(void)
{
    FB_SBT b = sbt_config();
    h_begin("SBT: the position slips by 5 > 4 -> TEST-FAILED 0x40DA, SBT falls -> SAFE (BT5)");
    CHECK_INT(sl_sbt_init(&b), SL_OK);
    b.bRun = 1;
    sl_sbt_cycle(&b, 0);
    b.bSBT = 1;
    b.nSingleturnPos = 2;
    sl_sbt_cycle(&b, 10);
    b.nSingleturnPos = 0xFFFFFFFDu;
    sl_sbt_cycle(&b, 20);
    CHECK_INT(b.nState, SL_STATE_SBT_TEST_FAILED);
    CHECK_INT(b.bTestError, 1);
    CHECK_INT(b.nDiagTextId, SL_TEXT_SBT_POSITION_DEVIATION);
    CHECK_INT(b.dwDiagPar2, 5);
    CHECK_INT(b.dwDiagPar3, 4);
    CHECK_DIAG_TEXT(SL_TYPE_SBT, 0xDA, "The single-turn position exceeds the maximum position deviation.");
    b.bSBT = 0;
    sl_sbt_cycle(&b, 30);
    CHECK_INT(b.nState, SL_STATE_SAFE);
    CHECK_INT(b.bTestError, 0);
    CHECK_INT(b.nDiagTextId, 0);
    b.tMinDuration = 2100;
    CHECK_INT(sl_sbt_init(&b), SL_E_CONFIG);
    h_end();
}

void run_sbt_scenarios(void)
{
    sbt_pass_then_expire();
    sbt_slipping_brake();
}
