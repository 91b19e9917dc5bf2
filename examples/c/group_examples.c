/*
 * TwinSAFE groups in C (manual §3.1; KL6904 manual §5.1, §5.2):
 *   1. KL6904 5.1 on a group: FB ESTOP (EStopIn1/2, EDM1 = K1/K2 feedback, restart S2).
 *   2. KL6904 5.2 on a group: FB MON (door switches MonIn1/2, EDM1, manual restart S3).
 *   3. A multi-block group: ESTOP and MON feed an AND that drives one contactor; a
 *      discrepancy error on the MON stops the whole group until ErrAck.
 * Deterministic simulated time (10 ms cycles). Exits 0 when every milestone was seen.
 */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "safelogic.h"

static int failures;

#define EXPECT(cond, what)                                               \
    do {                                                                 \
        if (!(cond)) {                                                   \
            printf("  !! expected: %s\n", what);                         \
            failures++;                                                  \
        }                                                                \
    } while (0)

static const char *group_state(uint8_t s)
{
    switch (s) {
    case SL_STATE_RUN: return "RUN";
    case SL_STATE_STOP: return "STOP";
    case SL_STATE_ERROR: return "ERROR";
    case SL_STATE_RESET: return "RESET";
    case 6: return "START";
    case 7: return "STOPERROR";
    default: return "?";
    }
}

static void show(uint32_t t, const SL_GROUP *g, const char *blocks, const char *what)
{
    printf("%6lu ms | group %-5s FbErr=%u FbRun=%u | %s | %s\n", (unsigned long)t,
           group_state(g->nState), (unsigned)g->bFbErr, (unsigned)g->bFbRun, blocks, what);
}

/* 5.1: machine with an emergency stop, on a group. */
static void example_estop(void)
{
    SL_GROUP g;
    SL_MEMBER members[1];
    FB_ESTOP e;
    char buf[160], diag[96];
    uint32_t t = 0;
    memset(&g, 0, sizeof g);
    memset(&e, 0, sizeof e);
    e.wInputActive = 0x03;
    e.tDiscTime12 = 30;
    e.dwOptions = SL_OPT_EDM1 | SL_OPT_SAFE_INPUTS_AFTER_DISC;
    e.bEStopIn1 = e.bEStopIn2 = 1;
    e.bEDM1 = 1;
    sl_estop_init(&e);
    sl_group_init(&g, members, 1, NULL, 0);
    sl_group_add_member(&g, members, SL_TYPE_ESTOP, &e, NULL);

#define STEP51(what)                                                                     \
    do {                                                                                 \
        sl_group_cycle(&g, members, NULL, t);                                            \
        sl_diag_text(SL_TYPE_ESTOP, e.nDiag, diag, sizeof diag);                         \
        snprintf(buf, sizeof buf, "ESTOP %-5s out=%u del=%u err=%u diag=%s",             \
                 sl_state_str(SL_TYPE_ESTOP, e.nState), (unsigned)e.bEStopOut,           \
                 (unsigned)e.bEStopDelOut, (unsigned)e.bError, diag[0] ? diag : "-");    \
        show(t, &g, buf, what);                                                          \
        t += 10;                                                                         \
    } while (0)

    printf("\nKL6904 5.1 on a group: ESTOP with contactors K1/K2 (EDM1), restart S2\n");
    g.bRun = 1;
    STEP51("group Run: ESTOP SAFE, waiting for S2");
    e.bRestart = 1;
    STEP51("S2 pressed");
    e.bRestart = 0;
    STEP51("S2 released: K1/K2 on");
    EXPECT(e.bEStopOut == 1, "ESTOP on after the restart");
    e.bEDM1 = 0;
    STEP51("K1/K2 picked up (EDM1 FALSE)");
    e.bEStopIn1 = e.bEStopIn2 = 0;
    STEP51("S1 pressed: outputs off at once");
    EXPECT(e.bEStopOut == 0, "ESTOP off on the e-stop");
    STEP51("K1 welded: EDM1 stays FALSE");
    e.bEStopIn1 = e.bEStopIn2 = 1;
    e.bRestart = 1;
    STEP51("S1 released, S2 pressed: EDM1 still FALSE, EDM error stops the group");
    EXPECT(e.nState == SL_STATE_ERROR && (e.nDiag & SL_DIAG_EDM1), "EDM1 error");
    EXPECT(g.nState == SL_STATE_ERROR && g.bFbErr == 1, "group ERROR");
    e.bRestart = 0;
    e.bEDM1 = 1;
    STEP51("K1 replaced (EDM1 TRUE)");
    g.bErrAck = 1;
    STEP51("ErrAck pressed");
    g.bErrAck = 0;
    STEP51("ErrAck released: group RUN, ESTOP waits for S2");
    EXPECT(g.nState == SL_STATE_RUN && e.nState == SL_STATE_SAFE, "acknowledged");
#undef STEP51
}

/* 5.2: machine with safety door monitoring, on a group. */
static void example_mon(void)
{
    SL_GROUP g;
    SL_MEMBER members[1];
    FB_MON m;
    char buf[160];
    uint32_t t = 0;
    memset(&g, 0, sizeof g);
    memset(&m, 0, sizeof m);
    m.wInputActive = 0x03;
    m.tDiscTime12 = 50;
    m.dwOptions = SL_OPT_EDM1 | SL_OPT_MANUAL_RESTART;
    m.bMonIn1 = m.bMonIn2 = 1;
    m.bEDM1 = 1;
    sl_mon_init(&m);
    sl_group_init(&g, members, 1, NULL, 0);
    sl_group_add_member(&g, members, SL_TYPE_MON, &m, NULL);

#define STEP52(what)                                                                     \
    do {                                                                                 \
        sl_group_cycle(&g, members, NULL, t);                                            \
        snprintf(buf, sizeof buf, "MON %-5s out=%u del=%u err=%u diag=0x%04x",           \
                 sl_state_str(SL_TYPE_MON, m.nState), (unsigned)m.bMonOut,               \
                 (unsigned)m.bMonDelOut, (unsigned)m.bError, (unsigned)m.nDiag);         \
        show(t, &g, buf, what);                                                          \
        t += 10;                                                                         \
    } while (0)

    printf("\nKL6904 5.2 on a group: MON safety door S1/S2, EDM1, manual restart S3\n");
    g.bRun = 1;
    STEP52("group Run: MON SAFE, waiting for S3");
    m.bRestart = 1;
    STEP52("S3 pressed");
    m.bRestart = 0;
    STEP52("S3 released: K1/K2 on");
    EXPECT(m.bMonOut == 1, "MON on after the restart");
    m.bEDM1 = 0;
    STEP52("contactors picked up");
    m.bMonIn1 = 0;
    STEP52("door opened (S1): outputs off at once");
    m.bMonIn2 = 0;
    m.bEDM1 = 1;
    STEP52("S2 follows, contactors released");
    m.bMonIn1 = m.bMonIn2 = 1;
    STEP52("door closed: MON stays SAFE until S3");
    EXPECT(m.nState == SL_STATE_SAFE && g.nState == SL_STATE_RUN, "manual restart needed");
    m.bRestart = 1;
    STEP52("S3 pressed");
    m.bRestart = 0;
    STEP52("S3 released: on again");
    EXPECT(m.bMonOut == 1, "MON on again");
#undef STEP52
}

/* 3. ESTOP + MON -> AND -> K1. */
static void example_multi(void)
{
    SL_GROUP g;
    SL_MEMBER members[3];
    SL_LINK links[2];
    FB_ESTOP e;
    FB_MON m;
    FB_AND a;
    char buf[200];
    uint32_t t = 0;
    int i;
    memset(&g, 0, sizeof g);
    memset(&e, 0, sizeof e);
    memset(&m, 0, sizeof m);
    memset(&a, 0, sizeof a);
    e.wInputActive = 0x03;
    e.tDiscTime12 = 30;
    e.bEStopIn1 = e.bEStopIn2 = 1;
    m.wInputActive = 0x03;
    m.tDiscTime12 = 40;
    m.bMonIn1 = m.bMonIn2 = 1;
    a.wInputActive = 0x03;
    sl_estop_init(&e);
    sl_mon_init(&m);
    sl_and_init(&a);
    sl_group_init(&g, members, 3, links, 2);
    sl_group_add_member(&g, members, SL_TYPE_ESTOP, &e, NULL);
    sl_group_add_member(&g, members, SL_TYPE_MON, &m, NULL);
    sl_group_add_member(&g, members, SL_TYPE_AND, &a, NULL);
    sl_group_add_link(&g, members, links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 2,
                      (uint16_t)offsetof(FB_AND, bAndIn1));
    sl_group_add_link(&g, members, links, 1, (uint16_t)offsetof(FB_MON, bMonOut), 2,
                      (uint16_t)offsetof(FB_AND, bAndIn2));

#define STEPM(what)                                                                      \
    do {                                                                                 \
        sl_group_cycle(&g, members, links, t);                                           \
        snprintf(buf, sizeof buf, "ESTOP=%-5s MON=%-5s AND=%-5s K1=%-3s",                \
                 sl_state_str(SL_TYPE_ESTOP, e.nState), sl_state_str(SL_TYPE_MON, m.nState), \
                 sl_state_str(SL_TYPE_AND, a.nState), a.bAndOut ? "on" : "off");         \
        if ((what)[0]) show(t, &g, buf, what);                                           \
        t += 10;                                                                         \
    } while (0)

    printf("\nMulti-block group: ESTOP + MON -> AND -> contactor K1\n");
    g.bRun = 1;
    STEPM("group Run");
    e.bRestart = 1;
    STEPM("S2 pressed");
    e.bRestart = 0;
    STEPM("S2 released: K1 on");
    EXPECT(a.bAndOut == 1, "K1 on");
    m.bMonIn1 = 0;
    STEPM("door switch S1 opens, S2 does not: K1 off, discrepancy running");
    for (i = 0; i < 3; i++) {
        STEPM("");
    }
    STEPM("40 ms: MON ERROR stops the whole group in this cycle");
    EXPECT(g.nState == SL_STATE_ERROR && e.nState == SL_STATE_STOP && a.bAndOut == 0,
           "group stopped");
    m.bMonIn1 = 1;
    STEPM("door closed: still ERROR");
    g.bErrAck = 1;
    STEPM("ErrAck pressed");
    g.bErrAck = 0;
    STEPM("ErrAck released: group RUN, ESTOP needs S2 again");
    STEPM("");
    e.bRestart = 1;
    STEPM("S2 pressed");
    e.bRestart = 0;
    STEPM("S2 released: K1 on again");
    EXPECT(a.bAndOut == 1, "K1 on again after acknowledgement and restart");
#undef STEPM
}

int main(void)
{
    printf("safelogic %s: TwinSAFE groups\n", sl_version());
    example_estop();
    example_mon();
    example_multi();
    printf("\n%s\n", failures == 0 ? "all milestones seen" : "MILESTONES MISSING");
    return failures == 0 ? 0 : 1;
}
