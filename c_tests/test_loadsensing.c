/*
 * FB_LOADSENSING through the C ABI (manual §4.25, ABI-2 §11.8, §12; docs/semantics.md
 * LS1-LS6): the value table `aRow` of SL_LOADSENSING_ROW_<type> written by the caller, the
 * row search (X strictly below AnalogInX), RUN / WARNING / SAFE, INACTIVE (an invalid byte
 * reads TRUE), Outside, the table checks at init (SL_E_CONFIG) and a changed row while
 * running (SL_E_PARAM_CHANGED); Valid gating a Boolean AND in a group.
 */
#include "harness.h"

/* Rows 2-5 of the manual's example table (Fig. 132): X, Y1, Y2, WY1, WY2. */
static const int16_t loadsensing_rows[4][5] = {
    {-25, -100, -50, -90, -60},
    {-20, -50, 0, -40, -10},
    {-15, 0, 100, 10, 90},
    {-10, 100, 200, 110, 190},
};

static void loadsensing_fill_int(FB_LOADSENSING_INT *fb)
{
    int i;
    for (i = 0; i < 4; i++) {
        fb->aRow[i].nX = loadsensing_rows[i][0];
        fb->aRow[i].nY1 = loadsensing_rows[i][1];
        fb->aRow[i].nY2 = loadsensing_rows[i][2];
        fb->aRow[i].nWY1 = loadsensing_rows[i][3];
        fb->aRow[i].nWY2 = loadsensing_rows[i][4];
    }
    fb->nRowCount = 4;
}

static void loadsensing_int_table(void)
{
    FB_LOADSENSING_INT ls;
    memset(&ls, 0, sizeof ls);
    h_begin("LOADSENSING_INT: row search, RUN / WARNING / SAFE, INACTIVE (LS1-LS4)");
    CHECK_INT(sizeof(SL_LOADSENSING_ROW_INT), 10);
    CHECK_INT(offsetof(FB_LOADSENSING_INT, aRow), 32);
    CHECK_INT(offsetof(FB_LOADSENSING_INT, nRowCount), 282);
    ls.wInputActive = SL_LOADSENSING_ACTIVE_INACTIVE | SL_LOADSENSING_ACTIVE_ANALOGINX |
                      SL_LOADSENSING_ACTIVE_ANALOGINY;
    loadsensing_fill_int(&ls);
    CHECK_INT(sl_loadsensing_int_init(&ls), SL_OK);
    ls.bRun = 1;
    ls.nAnalogInX = -14; /* row X -15 */
    ls.nAnalogInY = 50;
    CHECK_INT(sl_loadsensing_int_cycle(&ls, 0), SL_OK);
    CHECK_INT(ls.nState, SL_STATE_RUN);
    CHECK_INT(ls.bValid, 1);
    CHECK_INT(ls.bWarning, 0);
    ls.nAnalogInY = 95; /* between WY2 90 and Y2 100 */
    sl_loadsensing_int_cycle(&ls, 1);
    CHECK_INT(ls.nState, SL_STATE_LOADSENSING_WARNING);
    CHECK_INT(ls.bValid, 1);
    CHECK_INT(ls.bWarning, 1);
    CHECK_STR(sl_state_str(SL_TYPE_LOADSENSING_INT, ls.nState), "WARNING");
    ls.nAnalogInY = 101;
    sl_loadsensing_int_cycle(&ls, 2);
    CHECK_INT(ls.nState, SL_STATE_SAFE);
    CHECK_INT(ls.bValid, 0);
    ls.nAnalogInX = -15; /* X -15 is not below -15: row X -20 applies (WY -40 … -10) */
    ls.nAnalogInY = -20;
    sl_loadsensing_int_cycle(&ls, 3);
    CHECK_INT(ls.nState, SL_STATE_RUN);
    ls.nAnalogInX = -25; /* no row below: SAFE */
    sl_loadsensing_int_cycle(&ls, 4);
    CHECK_INT(ls.nState, SL_STATE_SAFE);
    ls.nAnalogInX = -14;
    ls.nAnalogInY = 50;
    ls.bInactive = 2; /* invalid byte: reads TRUE */
    CHECK_INT(sl_loadsensing_int_cycle(&ls, 5), SL_E_INVALID_BOOL);
    CHECK_INT(ls.nState, SL_STATE_LOADSENSING_INACTIVE);
    CHECK_INT(ls.bValid, 0);
    CHECK_STR(sl_state_str(SL_TYPE_LOADSENSING_INT, ls.nState), "INACTIVE");
    ls.bInactive = 0;
    sl_loadsensing_int_cycle(&ls, 6);
    CHECK_INT(ls.nState, SL_STATE_RUN);
    CHECK_INT(ls.nDiag, 0);
    CHECK_INT(ls.nDiagTextId, 0);
    h_end();
}

static void loadsensing_udint_checks(void)
{
    FB_LOADSENSING_UDINT ls;
    memset(&ls, 0, sizeof ls);
    h_begin("LOADSENSING_UDINT: Outside, table checks, a changed row (LS4-LS6)");
    CHECK_INT(sizeof(SL_LOADSENSING_ROW_UDINT), 20);
    CHECK_INT(offsetof(FB_LOADSENSING_UDINT, aRow), 36);
    CHECK_INT(offsetof(FB_LOADSENSING_UDINT, nRowCount), 536);
    ls.wInputActive = SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY;
    ls.dwOptions = SL_OPT_LOADSENSING_OUTSIDE;
    ls.nRowCount = 1;
    ls.aRow[0].nX = 0;
    ls.aRow[0].nY1 = 1000;
    ls.aRow[0].nY2 = 2000;
    ls.aRow[0].nWY1 = 1100; /* Outside needs WY1 <= Y1 */
    ls.aRow[0].nWY2 = 2100;
    CHECK_INT(sl_loadsensing_udint_init(&ls), SL_E_CONFIG);
    ls.aRow[0].nWY1 = 900;
    CHECK_INT(sl_loadsensing_udint_init(&ls), SL_OK);
    ls.nRowCount = 26;
    CHECK_INT(sl_loadsensing_udint_init(&ls), SL_E_CONFIG);
    ls.nRowCount = 1;
    CHECK_INT(sl_loadsensing_udint_init(&ls), SL_OK);
    ls.bRun = 1;
    ls.nAnalogInX = 1;
    ls.nAnalogInY = 1500; /* inside Y1..Y2: not valid with Outside */
    sl_loadsensing_udint_cycle(&ls, 0);
    CHECK_INT(ls.nState, SL_STATE_SAFE);
    ls.nAnalogInY = 950; /* between WY1 and Y1 */
    sl_loadsensing_udint_cycle(&ls, 1);
    CHECK_INT(ls.nState, SL_STATE_LOADSENSING_WARNING);
    ls.nAnalogInY = 4000000000u;
    sl_loadsensing_udint_cycle(&ls, 2);
    CHECK_INT(ls.nState, SL_STATE_RUN);
    ls.aRow[7].nY1 = 1; /* an unused row is a parameter too */
    CHECK_INT(sl_loadsensing_udint_cycle(&ls, 3), SL_E_PARAM_CHANGED);
    CHECK_INT(ls.nState, SL_STATE_ERROR);
    CHECK_INT(ls.bValid, 0);
    CHECK_INT(ls.nDiag, SL_DIAG_PARAM_CHANGED);
    h_end();
}

static void loadsensing_gates_an_and_in_a_group(void)
{
    SL_GROUP g;
    SL_MEMBER members[2];
    SL_LINK links[1];
    FB_LOADSENSING_DINT ls;
    FB_AND and_;
    memset(&g, 0, sizeof g);
    memset(&ls, 0, sizeof ls);
    memset(&and_, 0, sizeof and_);
    h_begin("group: LOADSENSING_DINT Valid -> AND (Boolean link)");
    ls.wInputActive = SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY;
    ls.nRowCount = 2;
    ls.aRow[0].nX = -1000000;
    ls.aRow[0].nY1 = 0;
    ls.aRow[0].nY2 = 500000;
    ls.aRow[0].nWY1 = 10000;
    ls.aRow[0].nWY2 = 490000;
    ls.aRow[1].nX = 0;
    ls.aRow[1].nY1 = 400000;
    ls.aRow[1].nY2 = 900000;
    ls.aRow[1].nWY1 = 410000;
    ls.aRow[1].nWY2 = 890000;
    and_.wInputActive = 0x3;
    CHECK_INT(sl_group_init(&g, members, 2, links, 1), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_LOADSENSING_DINT, &ls, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_AND, &and_, NULL), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 0, offsetof(FB_LOADSENSING_DINT, bValid), 1,
                                offsetof(FB_AND, bAndIn1)), SL_OK);
    and_.bAndIn2 = 1;
    ls.nAnalogInX = -5;
    ls.nAnalogInY = 20000;
    g.bRun = 1;
    CHECK_INT(sl_group_cycle(&g, members, links, 0), SL_OK);
    CHECK_INT(ls.bValid, 1);
    CHECK_INT(and_.bAndOut, 1);
    ls.nAnalogInX = 5; /* the second row: 20000 is below its Y1 */
    CHECK_INT(sl_group_cycle(&g, members, links, 10), SL_OK);
    CHECK_INT(ls.nState, SL_STATE_SAFE);
    CHECK_INT(and_.bAndOut, 0);
    CHECK_INT(g.nState, SL_STATE_RUN);
    h_end();
}

void run_loadsensing_scenarios(void)
{
    loadsensing_int_table();
    loadsensing_udint_checks();
    loadsensing_gates_an_and_in_a_group();
}
