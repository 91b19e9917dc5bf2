/*
 * PLCopen Safety SF_ blocks through the C ABI (issue 15; research plcopen_safety.md §3, §4.1,
 * §4.11; docs/semantics.md PO1-PO11, PE1-PE5, PP1-PP4): SF_EmergencyStop walked through every
 * state of its table with the PLCopen names only (v2.01 codes, then the v1.0 profile), the
 * static-reset error, Activate FALSE, a constant changed while activated, sl_diag_text;
 * SF_Equivalent's discrepancy time; an SF_ block as a group member (the group's halt is its
 * idle). Every expected DiagCode is the research table's.
 */
#include "harness.h"

/* One call of `fb` at `t`: the status, the DiagCode and the five outputs as a bit set
 * (Ready, S_EStopOut, SafetyDemand, ResetRequest, Error = bits 0..4). */
#define PO_READY 1u
#define PO_OUT 2u
#define PO_DEMAND 4u
#define PO_RESREQ 8u
#define PO_ERROR 16u

static void po_estop(SF_EmergencyStop *fb, uint32_t t, int32_t xrc, uint16_t xcode,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_sf_emergencystop_cycle(fb, t);
    uint32_t outs = h_pack_bool(0, fb->Ready, 0);
    outs = h_pack_bool(outs, fb->S_EStopOut, 1);
    outs = h_pack_bool(outs, fb->SafetyDemand, 2);
    outs = h_pack_bool(outs, fb->ResetRequest, 3);
    outs = h_pack_bool(outs, fb->Error, 4);
    h_check_int(rc, xrc, file, line, "SF_EmergencyStop status");
    h_check_int(fb->DiagCode, xcode, file, line, "SF_EmergencyStop DiagCode");
    h_check_int(outs, xouts, file, line, "SF_EmergencyStop outputs (Ready, S_EStopOut, SafetyDemand, ResetRequest, Error)");
}

#define PES(t_, code_, outs_) po_estop(fb, (t_), SL_OK, (code_), (outs_), __FILE__, __LINE__)

static void po_estop_table(void)
{
    SF_EmergencyStop e;
    SF_EmergencyStop *fb = &e;
    char text[96];
    h_begin("SF_EmergencyStop: the table of research 4.1 with the PLCopen names (v2.01)");
    memset(&e, 0, sizeof e);
    CHECK_INT(sl_sf_emergencystop_init(fb), SL_OK);
    PES(0, 0x0000, 0);
    fb->Activate = 1;
    PES(10, 0x8001, PO_READY);                    /* IDLE -> INIT, the one transition */
    PES(20, 0x8802, PO_READY | PO_DEMAND);        /* no S_StartReset: wait for the input */
    fb->S_EStopIn = 1;
    PES(30, 0x8402, PO_READY | PO_RESREQ);        /* input TRUE: wait for the Reset edge */
    fb->Reset = 1;
    PES(40, 0x8000, PO_READY | PO_OUT);           /* R_TRIG(Reset): output enabled */
    fb->Reset = 0;
    PES(50, 0x8000, PO_READY | PO_OUT);
    fb->S_EStopIn = 0;
    PES(60, 0x8804, PO_READY | PO_DEMAND);        /* safety demand: output FALSE in this call */
    fb->Reset = 1;
    PES(70, 0x8804, PO_READY | PO_DEMAND);        /* no static-reset check while waiting for the input */
    fb->S_EStopIn = 1;
    PES(80, 0x8404, PO_READY);                    /* ResetRequest FALSE while Reset is held */
    PES(90, 0xC011, PO_READY | PO_ERROR);         /* Reset held into the wait: static reset */
    fb->Reset = 0;
    PES(100, 0x8404, PO_READY | PO_RESREQ);
    fb->Reset = 1;
    PES(110, 0x8000, PO_READY | PO_OUT);
    fb->Activate = 0;
    PES(120, 0x0000, 0);                          /* Activate FALSE: idle, every output FALSE */
    fb->Reset = 0;
    fb->S_StartReset = 1;
    fb->S_AutoReset = 1;
    fb->Activate = 1;
    PES(130, 0x8001, PO_READY);
    PES(140, 0x8000, PO_READY | PO_OUT);          /* S_StartReset: no reset at start-up */
    fb->S_EStopIn = 0;
    PES(150, 0x8804, PO_READY | PO_DEMAND);
    fb->S_EStopIn = 1;
    PES(160, 0x8000, PO_READY | PO_OUT);          /* S_AutoReset after a safety demand */
    CHECK_INT(sl_diag_text(SL_TYPE_SF_EMERGENCYSTOP, 0xC011, text, sizeof text), SL_OK);
    CHECK(strstr(text, "static Reset") != NULL, "sl_diag_text names the static-reset error C011");
    h_end();

    h_begin("SF_EmergencyStop: the v1.0 profile, and a constant changed while activated");
    fb->Activate = 0;
    PES(200, 0x0000, 0);
    fb->nDiagProfile = SL_SF_PROFILE_V10;
    fb->S_StartReset = 0;
    fb->S_AutoReset = 0;
    fb->S_EStopIn = 0;
    fb->Activate = 1;
    PES(210, 0x8001, PO_READY);
    PES(220, 0x8002, PO_READY | PO_DEMAND);       /* v1.0 code of 8802; the outputs are the same */
    fb->S_EStopIn = 1;
    PES(230, 0x8003, PO_READY | PO_RESREQ);       /* v1.0 code of 8402 */
    fb->nDiagProfile = SL_SF_PROFILE_V201;       /* a constant input changed while activated */
    po_estop(fb, 240, SL_E_PARAM_CHANGED, SL_SF_DIAG_CONST_CHANGED, PO_READY | PO_ERROR, __FILE__, __LINE__);
    fb->Reset = 1;
    po_estop(fb, 250, SL_E_PARAM_CHANGED, SL_SF_DIAG_CONST_CHANGED, PO_READY | PO_ERROR, __FILE__, __LINE__);
    fb->Activate = 0;
    PES(260, 0x0000, 0);                          /* only Activate FALSE leaves a library fault */
    CHECK_INT(sl_diag_text(SL_TYPE_SF_EMERGENCYSTOP, SL_SF_DIAG_CONST_CHANGED, text, sizeof text), SL_OK);
    CHECK(strstr(text, "constant") != NULL, "sl_diag_text names the library fault");
    h_end();
}

static void po_equivalent_time(void)
{
    SF_Equivalent q;
    h_begin("SF_Equivalent: DiscrepancyTime runs from the entry into the waiting state");
    memset(&q, 0, sizeof q);
    CHECK_INT(sl_sf_equivalent_init(&q), SL_OK);
    q.DiscrepancyTime = 50;
    q.Activate = 1;
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1000), SL_OK);
    CHECK_INT(q.DiagCode, 0x8801);
    q.S_ChannelA = 1;
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1010), SL_OK);
    CHECK_INT(q.DiagCode, 0x8802);               /* A active: waiting for B, timer from 1010 */
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1059), SL_OK);
    CHECK_INT(q.DiagCode, 0x8802);               /* 49 ms: not yet */
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1060), SL_OK);
    CHECK_INT(q.DiagCode, 0xC010);               /* 50 ms: discrepancy error */
    CHECK_INT(q.S_EquivalentOut, 0);
    CHECK_INT(q.Error, 1);
    q.S_ChannelA = 0;
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1070), SL_OK);
    CHECK_INT(q.DiagCode, 0x8801);               /* both inactive: the error is left */
    q.S_ChannelA = 1;
    q.S_ChannelB = 1;
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1080), SL_OK);
    CHECK_INT(q.DiagCode, 0x8000);
    CHECK_INT(q.S_EquivalentOut, 1);
    q.DiscrepancyTime = 0x80000000u;             /* changed while activated, and out of range */
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1090), SL_E_PARAM_CHANGED);
    CHECK_INT(q.S_EquivalentOut, 0);
    q.Activate = 0;
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1100), SL_OK);
    q.Activate = 1;                              /* latched at activation: refused */
    CHECK_INT(sl_sf_equivalent_cycle(&q, 1110), SL_E_CONFIG);
    CHECK_INT(q.DiagCode, SL_SF_DIAG_CONFIG);
    CHECK_INT(q.S_EquivalentOut, 0);
    h_end();
}

static void po_group(void)
{
    SL_GROUP g;
    SL_MEMBER members[2];
    SL_LINK links[1];
    SF_EmergencyStop e;
    uint16_t idx = 0;
    h_begin("SF_EmergencyStop as a group member: the group's halt is its idle");
    memset(&g, 0, sizeof g);
    memset(&e, 0, sizeof e);
    CHECK_INT(sl_group_init(&g, members, 2, links, 1), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_SF_EMERGENCYSTOP, &e, &idx),
              SL_E_CONFIG);                       /* never initialised: refused (PO8) */
    CHECK_INT(sl_sf_emergencystop_init(&e), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_SF_EMERGENCYSTOP, &e, &idx), SL_OK);
    e.Activate = 1;
    e.S_StartReset = 1;
    e.S_EStopIn = 1;
    g.bRun = 1;
    CHECK_INT(sl_group_cycle(&g, members, links, 10), SL_OK);
    CHECK_INT(sl_group_cycle(&g, members, links, 20), SL_OK);
    CHECK_INT(e.DiagCode, 0x8000);
    CHECK_INT(e.S_EStopOut, 1);
    CHECK_INT(g.nState, SL_STATE_RUN);
    g.bRun = 0;                                   /* the group stops: the block goes idle */
    CHECK_INT(sl_group_cycle(&g, members, links, 30), SL_OK);
    CHECK_INT(e.DiagCode, 0x0000);
    CHECK_INT(e.S_EStopOut, 0);
    CHECK_INT(e.Ready, 0);
    h_end();
}

void run_plcopen_scenarios(void)
{
    po_estop_table();
    po_equivalent_time();
    po_group();
}
