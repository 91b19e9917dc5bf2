/*
 * Why a block refuses, from C: sl_reason_text (docs/c-integration.md "Reasons": the sentence
 * format, the reason codes, the buffer rules) and the PLCopen defaults functions
 * (docs/semantics.md PO12). The sentences are the documented ones; the TWOHAND limit is the
 * manual's 2500 ms (sec. 4.7), LIMIT's Text ID 0x4090 its sec. 4.21, the LOADSENSING table
 * its Fig. 132.
 */
#include "harness.h"

/* The sentence sl_reason_text writes for a live block (asserting SL_OK). */
static const char *reason(uint16_t type, const void *block)
{
    static char buf[SL_REASON_TEXT_MAX + 1];
    CHECK_INT(sl_reason_text(type, block, buf, sizeof buf), SL_OK);
    return buf;
}

static void reason_refused_parameter(void)
{
    FB_TWOHAND th;
    h_begin("sl_reason_text: a refused TWOHAND names field, limit and reason code");
    memset(&th, 0, sizeof th);
    th.wInputActive = 0x0005;
    th.tDiscTimePairs = 3000;
    CHECK_INT(sl_twohand_init(&th), SL_E_CONFIG);
    CHECK_STR(reason(SL_TYPE_TWOHAND, &th),
              "TWOHAND: tDiscTimePairs (3000 ms) must be <= 2500 ms [reason 0xE001]");
    th.tDiscTimePairs = 2500;
    CHECK_INT(sl_twohand_init(&th), SL_OK);
    CHECK_STR(reason(SL_TYPE_TWOHAND, &th), "TWOHAND: no refusal");
    h_end();
}

static void reason_buffer_rules(void)
{
    FB_TWOHAND th;
    char buf[16];
    h_begin("sl_reason_text: NULL pointers, nLen 0, truncation with the NUL, unknown type");
    memset(&th, 0, sizeof th);
    CHECK_INT(sl_reason_text(SL_TYPE_TWOHAND, &th, NULL, 5), SL_E_NULL);
    CHECK_INT(sl_reason_text(SL_TYPE_TWOHAND, &th, NULL, 0), SL_E_NULL);
    memset(buf, 0xAA, sizeof buf);
    CHECK_INT(sl_reason_text(SL_TYPE_TWOHAND, &th, buf, 0), SL_OK);
    CHECK_INT((unsigned char)buf[0], 0xAA); /* nothing written */
    CHECK_INT(sl_reason_text(SL_TYPE_TWOHAND, &th, buf, 1), SL_OK);
    CHECK_INT(buf[0], 0); /* only the NUL fits */
    memset(buf, 0xAA, sizeof buf);
    CHECK_INT(sl_reason_text(999, &th, buf, sizeof buf), SL_E_CONFIG);
    CHECK_STR(buf, "");
    memset(buf, 0xAA, sizeof buf);
    CHECK_INT(sl_reason_text(SL_TYPE_TWOHAND, NULL, buf, sizeof buf), SL_E_NULL);
    CHECK_STR(buf, "");
    CHECK_INT(sl_reason_text(SL_TYPE_TWOHAND, (const char *)&th + 1, buf, sizeof buf),
              SL_E_ALIGNMENT);
    /* a zeroed TWOHAND breaks its first rule (wInputActive); 15 bytes and the NUL */
    memset(buf, 0xAA, sizeof buf);
    CHECK_INT(sl_reason_text(SL_TYPE_TWOHAND, &th, buf, sizeof buf), SL_OK);
    CHECK_STR(buf, "TWOHAND: wInput");
    h_end();
}

static void reason_text_id_and_error(void)
{
    FB_LIMIT_INT lim;
    h_begin("sl_reason_text: LIMIT Min > Max as parameters (0x4090) and as inputs (ERROR)");
    memset(&lim, 0, sizeof lim);
    lim.wInputActive = SL_LIMIT_ACTIVE_ANALOGIN;
    lim.nMinimumValue = -5;
    lim.nMaximumValue = -7;
    CHECK_INT(sl_limit_int_init(&lim), SL_E_CONFIG);
    CHECK_INT(lim.nDiagTextId, 0x4090);
    CHECK_STR(reason(SL_TYPE_LIMIT_INT, &lim),
              "LIMIT_INT: nMinimumValue (-5) must be <= nMaximumValue (-7) [Text ID 0x4090]");

    /* valid parameters, MinValue from its input above the maximum: the manual's ERROR */
    memset(&lim, 0, sizeof lim);
    lim.wInputActive = SL_LIMIT_ACTIVE_ANALOGIN | SL_LIMIT_ACTIVE_MINVALUE;
    lim.nMinValue = 9;
    lim.nMaximumValue = 3;
    lim.bRun = 1;
    CHECK_INT(sl_limit_int_init(&lim), SL_OK);
    CHECK_INT(sl_limit_int_cycle(&lim, 1), SL_OK);
    CHECK_INT(lim.nState, SL_STATE_ERROR);
    CHECK_STR(reason(SL_TYPE_LIMIT_INT, &lim),
              "LIMIT_INT: ERROR: MinValue is greater than MaxValue [Text ID 0x4090, Par2 9, Par3 3]");
    h_end();
}

static void reason_table_row(void)
{
    /* Fig. 132: X, Y1, Y2, WY1, WY2 */
    static const int16_t fig132[25][5] = {
        {-30, -200, -100, -180, -80},  {-25, -100, -50, -90, -60},   {-20, -50, 0, -40, -10},
        {-15, 0, 100, 10, 90},         {-10, 100, 200, 110, 190},    {-5, 200, 300, 210, 290},
        {0, 300, 400, 310, 390},       {5, 400, 500, 410, 490},      {10, 500, 600, 510, 590},
        {15, 600, 700, 610, 690},      {20, 700, 800, 710, 790},     {25, 800, 900, 810, 890},
        {30, 900, 1000, 910, 990},     {35, 1000, 1100, 1010, 1090}, {40, 1100, 1200, 1110, 1190},
        {45, 1200, 1300, 1210, 1290},  {50, 1300, 1400, 1310, 1390}, {60, 1400, 1500, 1410, 1490},
        {80, 1500, 1600, 1510, 1590},  {100, 1600, 1700, 1610, 1690}, {140, 1700, 1800, 1710, 1790},
        {180, 1800, 2000, 1810, 1990}, {250, 2000, 3000, 2010, 2990}, {500, 3000, 4000, 3010, 3990},
        {1000, 4000, 5000, 4010, 4990},
    };
    FB_LOADSENSING_INT ls;
    size_t i;
    h_begin("sl_reason_text: LOADSENSING names the table row and its rule (Fig. 132, row 1)");
    memset(&ls, 0, sizeof ls);
    ls.wInputActive = SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY;
    ls.nRowCount = 25;
    for (i = 0; i < 25; i++) {
        ls.aRow[i].nX = fig132[i][0];
        ls.aRow[i].nY1 = fig132[i][1];
        ls.aRow[i].nY2 = fig132[i][2];
        ls.aRow[i].nWY1 = fig132[i][3];
        ls.aRow[i].nWY2 = fig132[i][4];
    }
    CHECK_INT(sl_loadsensing_int_init(&ls), SL_E_CONFIG);
    CHECK_STR(reason(SL_TYPE_LOADSENSING_INT, &ls),
              "LOADSENSING_INT row 1: nWY2 (-80) must be <= nY2 (-100) [reason 0xE00B]");
    ls.aRow[0].nWY2 = -120; /* 20 inside Y2, as WY1 is inside Y1 */
    CHECK_INT(sl_loadsensing_int_init(&ls), SL_OK);
    CHECK_STR(reason(SL_TYPE_LOADSENSING_INT, &ls), "LOADSENSING_INT: no refusal");
    h_end();
}

static void plcopen_defaults(void)
{
    SF_ResetButton rb;
    SF_Antivalent av;
    h_begin("sl_sf_resetbutton_defaults / sl_sf_antivalent_defaults: the PLCopen initial values");
    memset(&rb, 0, sizeof rb);
    rb.DiagCode = 7; /* left over: overwritten */
    CHECK_INT(sl_sf_resetbutton_defaults(&rb), SL_OK);
    CHECK_INT(rb.ResetRequested, 1);
    CHECK_INT(rb.TrailingMinimum, 350);
    CHECK_INT(rb.TrailingMaximum, 2000);
    CHECK_INT(rb.DiagCode, 0);
    CHECK_INT(sl_sf_resetbutton_init(&rb), SL_OK);
    CHECK_INT(sl_sf_resetbutton_cycle(&rb, 1), SL_OK);
    CHECK_INT(rb.DiagCode, 0x83E2); /* activated by ResetRequested, waiting for the button */
    CHECK_INT(rb.Error, 0);
    CHECK_INT(sl_sf_resetbutton_defaults(NULL), SL_E_NULL);

    /* zero stays "not configured": TrailingMinimum 0 is the block's parameter error */
    memset(&rb, 0, sizeof rb);
    CHECK_INT(sl_sf_resetbutton_init(&rb), SL_OK);
    rb.ResetRequested = 1;
    (void)sl_sf_resetbutton_cycle(&rb, 1);
    CHECK_INT(rb.DiagCode, 0xC000);
    CHECK_STR(reason(SL_TYPE_SF_RESETBUTTON, &rb),
              "SF_ResetButton: TrailingMinimum (0 ms) must be >= 100 ms [reason 0xE002]");

    memset(&av, 0, sizeof av);
    CHECK_INT(sl_sf_antivalent_defaults(&av), SL_OK);
    CHECK_INT(av.S_ChannelNO, 1);
    CHECK_INT(av.S_ChannelNC, 0);
    CHECK_INT(av.Activate, 0);
    CHECK_INT(sl_sf_antivalent_init(&av), SL_OK);
    av.Activate = 1;
    CHECK_INT(sl_sf_antivalent_cycle(&av, 1), SL_OK);
    CHECK_INT(av.Error, 0);
    CHECK_INT(sl_sf_antivalent_defaults(NULL), SL_E_NULL);
    h_end();
}

void run_reason_scenarios(void)
{
    reason_refused_parameter();
    reason_buffer_rules();
    reason_text_id_and_error();
    reason_table_row();
    plcopen_defaults();
}
