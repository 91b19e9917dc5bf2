/*
 * TwinSAFE group through the C ABI (manual §3.1, §3.1.1.2, §3.2.5; docs/semantics.md GR1-GR11):
 * members in execution order, error propagation in both orders within one group cycle,
 * acknowledgement, links (this cycle's value from an earlier member, last cycle's from a
 * later one), storage limits, Run toggling, invalid input bytes, NULL and corrupt state.
 */
#include "harness.h"

#define G_MAX_MEMBERS 4
#define G_MAX_LINKS 4

typedef struct grp_fixture {
    SL_GROUP g;
    SL_MEMBER members[G_MAX_MEMBERS];
    SL_LINK links[G_MAX_LINKS];
    FB_ESTOP estop;
    FB_MON mon;
    FB_AND and2;
} grp_fixture;

static int32_t grp_cycle(grp_fixture *f, uint32_t t)
{
    return sl_group_cycle(&f->g, f->members, f->links, t);
}

/* ESTOP (1 channel pair, no EDM), MON (pair 1/2, 50 ms, automatic restart), AND(2). */
static void grp_setup(grp_fixture *f, int and_first)
{
    uint16_t idx = 0xFFFF;
    memset(f, 0, sizeof *f);
    f->estop.wInputActive = 0x01;
    f->estop.bEStopIn1 = 1;
    f->mon.wInputActive = 0x03;
    f->mon.tDiscTime12 = 50;
    f->mon.bMonIn1 = 1;
    f->mon.bMonIn2 = 1;
    f->and2.wInputActive = 0x03;
    CHECK_INT(sl_estop_init(&f->estop), SL_OK);
    CHECK_INT(sl_mon_init(&f->mon), SL_OK);
    CHECK_INT(sl_and_init(&f->and2), SL_OK);
    CHECK_INT(sl_group_init(&f->g, f->members, G_MAX_MEMBERS, f->links, G_MAX_LINKS), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_STOP);
    if (and_first) {
        CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_AND, &f->and2, &idx), SL_OK);
        CHECK_INT(idx, 0);
    }
    CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_ESTOP, &f->estop, &idx), SL_OK);
    CHECK_INT(idx, and_first ? 1 : 0);
    CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_MON, &f->mon, &idx), SL_OK);
    CHECK_INT(idx, and_first ? 2 : 1);
    if (!and_first) {
        CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_AND, &f->and2, &idx), SL_OK);
        CHECK_INT(idx, 2);
    }
    {
        uint16_t ie = and_first ? 1 : 0, im = and_first ? 2 : 1, ia = and_first ? 0 : 2;
        CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, ie,
                                    (uint16_t)offsetof(FB_ESTOP, bEStopOut), ia,
                                    (uint16_t)offsetof(FB_AND, bAndIn1)),
                  SL_OK);
        CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, im,
                                    (uint16_t)offsetof(FB_MON, bMonOut), ia,
                                    (uint16_t)offsetof(FB_AND, bAndIn2)),
                  SL_OK);
    }
    CHECK_INT(f->g.nMembers, 3);
    CHECK_INT(f->g.nLinks, 2);
}

/* Run the group up: ESTOP needs its restart sequence, MON restarts by itself. */
static uint32_t grp_to_run(grp_fixture *f, uint32_t t)
{
    f->g.bRun = 1;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_RUN);
    CHECK_INT(f->g.bInRun, 1);
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    f->estop.bRestart = 1;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    f->estop.bRestart = 0;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->estop.nState, SL_STATE_RUN);
    CHECK_INT(f->mon.nState, SL_STATE_RUN);
    CHECK_INT(f->and2.bAndOut, 1);
    CHECK_INT(f->g.bFbRun, 1);
    return t;
}

static void grp_propagation(int and_first)
{
    grp_fixture fx;
    grp_fixture *f = &fx;
    uint32_t t = 100, t_err;
    h_begin(and_first ? "GROUP discrepancy in MON stops all members (AND executes first)"
                      : "GROUP discrepancy in MON stops all members (AND executes last)");
    grp_setup(f, and_first);
    t = grp_to_run(f, t);
    f->mon.bMonIn2 = 0;
    t_err = t + 50;
    for (; t < t_err; t++) {
        CHECK_INT(grp_cycle(f, t), SL_OK);
        CHECK_INT(f->g.nState, SL_STATE_RUN);
        CHECK_INT(f->estop.bEStopOut, 1);
    }
    CHECK_INT(grp_cycle(f, t), SL_OK);     /* 50 ms of discrepancy reached */
    CHECK_INT(f->g.nState, SL_STATE_ERROR);
    CHECK_INT(f->g.nDiag, 1);              /* FBERROR */
    CHECK_INT(f->g.nFailedMember, and_first ? 2 : 1);
    CHECK_INT(f->g.bFbErr, 1);
    CHECK_INT(f->g.bInRun, 0);
    CHECK_INT(f->mon.nState, SL_STATE_ERROR);
    CHECK_INT(f->mon.bError, 1);
    CHECK_INT(f->estop.nState, SL_STATE_STOP);   /* ran earlier in the cycle, stopped again */
    CHECK_INT(f->estop.bEStopOut, 0);
    CHECK_INT(f->estop.bEStopDelOut, 0);
    CHECK_INT(f->and2.nState, SL_STATE_STOP);
    CHECK_INT(f->and2.bAndOut, 0);
    /* ErrAck while the pair still differs: nothing. */
    f->g.bErrAck = 1;
    CHECK_INT(grp_cycle(f, ++t), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_ERROR);
    f->g.bErrAck = 0;
    CHECK_INT(grp_cycle(f, ++t), SL_OK);
    f->mon.bMonIn2 = 1;
    CHECK_INT(grp_cycle(f, ++t), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_ERROR);   /* needs a new edge */
    f->g.bErrAck = 1;
    CHECK_INT(grp_cycle(f, ++t), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_RESET);
    CHECK_INT(f->mon.nState, SL_STATE_RESET);
    CHECK_INT(f->g.bFbErr, 0);
    CHECK_INT(f->g.nDiag, 0);
    f->g.bErrAck = 0;
    CHECK_INT(grp_cycle(f, ++t), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_RUN);
    CHECK_INT(grp_cycle(f, ++t), SL_OK);
    CHECK_INT(grp_cycle(f, ++t), SL_OK);
    CHECK_INT(f->mon.nState, SL_STATE_RUN);
    CHECK_INT(f->estop.nState, SL_STATE_SAFE);    /* ESTOP needs its restart again */
    CHECK_INT(f->and2.bAndOut, 0);
    h_end();
}

static void grp_links_and_order(void)
{
    grp_fixture fx;
    grp_fixture *f = &fx;
    uint32_t t = 10;
    h_begin("GROUP link from an earlier member: same cycle; from a later member: next cycle");
    grp_setup(f, 0);
    t = grp_to_run(f, t);
    f->estop.bEStopIn1 = 0;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->estop.bEStopOut, 0);
    CHECK_INT(f->and2.bAndOut, 0);     /* AND runs after ESTOP: same cycle */
    h_end();

    h_begin("GROUP link order with AND first: the ESTOP value arrives one cycle later");
    grp_setup(f, 1);
    t = grp_to_run(f, 10);
    f->estop.bEStopIn1 = 0;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->estop.bEStopOut, 0);
    CHECK_INT(f->and2.bAndOut, 1);     /* still last cycle's ESTOP output */
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->and2.bAndOut, 0);
    h_end();
}

static void grp_rejects(void)
{
    grp_fixture fx;
    grp_fixture *f = &fx;
    FB_OR extra;
    uint16_t idx = 7;
    h_begin("GROUP rejects bad members and links, full storage, NULL");
    grp_setup(f, 0);
    /* a link to an output, from an input, to bRun, to a member outside, to a taken input */
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopIn1), 2,
                                (uint16_t)offsetof(FB_AND, bAndIn3)), SL_E_CONFIG);
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 2,
                                (uint16_t)offsetof(FB_AND, bAndOut)), SL_E_CONFIG);
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 2,
                                (uint16_t)offsetof(FB_AND, bRun)), SL_E_CONFIG);
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 3,
                                (uint16_t)offsetof(FB_AND, bAndIn3)), SL_E_CONFIG);
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 2,
                                (uint16_t)offsetof(FB_AND, bAndIn1)), SL_E_CONFIG);
    /* the same block twice, an unknown type, a NULL block */
    CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_AND, &f->and2, &idx), SL_E_CONFIG);
    CHECK_INT(sl_group_add_member(&f->g, f->members, 999, &extra, &idx), SL_E_CONFIG);
    CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_OR, NULL, &idx), SL_E_NULL);
    CHECK_INT(idx, 7);
    memset(&extra, 0, sizeof extra);
    extra.wInputActive = 0x01;
    CHECK_INT(sl_or_init(&extra), SL_OK);
    CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_OR, &extra, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_OR, &f->estop, NULL), SL_E_CONFIG);
    {
        FB_OR more;
        memset(&more, 0, sizeof more);
        CHECK_INT(sl_group_add_member(&f->g, f->members, SL_TYPE_OR, &more, NULL), SL_E_FULL);
    }
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 3,
                                (uint16_t)offsetof(FB_OR, bOrIn1)), SL_OK);
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 3,
                                (uint16_t)offsetof(FB_OR, bOrIn2)), SL_OK);
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 3,
                                (uint16_t)offsetof(FB_OR, bOrIn3)), SL_E_FULL);
    /* no members or links while running */
    f->g.bRun = 1;
    CHECK_INT(grp_cycle(f, 1), SL_OK);
    CHECK_INT(sl_group_add_link(&f->g, f->members, f->links, 0, (uint16_t)offsetof(FB_ESTOP, bEStopOut), 3,
                                (uint16_t)offsetof(FB_OR, bOrIn4)), SL_E_CONFIG);
    CHECK_INT(sl_group_cycle(NULL, f->members, f->links, 2), SL_E_NULL);
    CHECK_INT(sl_group_init(NULL, f->members, 1, f->links, 1), SL_E_NULL);
    CHECK_INT(sl_group_init(&f->g, NULL, 1, f->links, 1), SL_E_NULL);
    CHECK_INT(sl_group_add_member(NULL, f->members, SL_TYPE_OR, &extra, NULL), SL_E_NULL);
    h_end();
}

static void grp_run_toggle_and_faults(void)
{
    grp_fixture fx;
    grp_fixture *f = &fx;
    uint32_t t;
    h_begin("GROUP Run FALSE stops every member; ModuleFault and ComErr; invalid bytes; corrupt");
    grp_setup(f, 0);
    t = grp_to_run(f, 10);
    f->g.bRun = 0;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_STOP);
    CHECK_INT(f->estop.nState, SL_STATE_STOP);
    CHECK_INT(f->mon.nState, SL_STATE_STOP);
    CHECK_INT(f->and2.bAndOut, 0);
    CHECK_INT(f->g.bInRun, 0);
    f->g.bRun = 1;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_RUN);
    f->g.bModuleFault = 1;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_ERROR);
    CHECK_INT(f->g.nDiag, 3);              /* MODULEERROR */
    CHECK_INT(f->g.bOtherErr, 1);
    CHECK_INT(f->mon.bMonOut, 0);
    f->g.bModuleFault = 0;
    f->g.bComErrIn = 1;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.bComErr, 1);
    CHECK_INT(f->g.bOutErr, 0);
    CHECK_INT(f->g.bFbDeactive, 0);
    f->g.bComErrIn = 0;
    f->g.bErrAck = 1;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_RESET);
    f->g.bErrAck = 0;
    f->g.bComStartupIn = 1;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.nState, 6);             /* START: a connection starts up */
    CHECK_INT(f->g.bComStartup, 1);
    CHECK_INT(f->mon.bMonOut, 0);
    f->g.bComStartupIn = 0;
    CHECK_INT(grp_cycle(f, t++), SL_OK);
    CHECK_INT(f->g.nState, SL_STATE_RUN);
    f->g.bRun = 3;                         /* invalid: reads FALSE */
    CHECK_INT(grp_cycle(f, t++), SL_E_INVALID_BOOL);
    CHECK_INT(f->g.nState, SL_STATE_STOP);
    f->g.bRun = 1;
    f->g.stPrivate.dwLinks ^= 0x1;         /* scribble on the private state */
    CHECK_INT(grp_cycle(f, t++), SL_E_CORRUPT);
    CHECK_INT(f->g.nState, SL_STATE_ERROR);
    CHECK_INT(f->g.bInRun, 0);
    h_end();
}

static void grp_stoperror(void)
{
    SL_GROUP g;
    h_begin("GROUP with connections starts in STOPERROR, Run leads to ERROR (diag 6)");
    memset(&g, 0, sizeof g);
    g.bConnections = 1;
    CHECK_INT(sl_group_init(&g, NULL, 0, NULL, 0), SL_OK);
    CHECK_INT(g.nState, 7);
    g.bRun = 1;
    CHECK_INT(sl_group_cycle(&g, NULL, NULL, 1), SL_OK);
    CHECK_INT(g.nState, SL_STATE_ERROR);
    CHECK_INT(g.nDiag, 6);
    g.bErrAck = 1;
    CHECK_INT(sl_group_cycle(&g, NULL, NULL, 2), SL_OK);
    CHECK_INT(g.nState, SL_STATE_RESET);
    g.bErrAck = 0;
    CHECK_INT(sl_group_cycle(&g, NULL, NULL, 3), SL_OK);
    CHECK_INT(g.nState, SL_STATE_RUN);
    CHECK_INT(g.bFbRun, 0);                /* no members: none in RUN */
    h_end();
}

void run_group_scenarios(void)
{
    grp_propagation(0);
    grp_propagation(1);
    grp_links_and_order();
    grp_rejects();
    grp_run_toggle_and_faults();
    grp_stoperror();
}
