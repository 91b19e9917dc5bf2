/*
 * FB_TWOHAND behaviour scenarios (manual §4.7; ABI.md §2, §4, §5, §7, §9;
 * docs/semantics.md rows H1-H14, C1-C12).
 *
 * Every step calls sl_twohand_cycle once and checks the status code, nState, nDiag and both
 * outputs: bit 0 of the expected set (TH_OUT) = bTwoHandOut, bit 1 (TH_ERR) = bError.
 * Group 1 = TwoHand1/2, group 2 = TwoHand3/4 (H1).
 */
#include "harness.h"

/* ---- helpers (prefixed th_) ---- */

#define TH_OUT 1u
#define TH_ERR 2u

static uint32_t th_outs(const FB_TWOHAND *fb)
{
    uint32_t o = 0;
    o = h_pack_bool(o, fb->bTwoHandOut, 0);
    o = h_pack_bool(o, fb->bError, 1);
    return o;
}

static void th_step(FB_TWOHAND *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                    uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_twohand_cycle(fb, t);
    h_check_fb(file, line, "TWOHAND", SL_TYPE_TWOHAND, t, rc, fb->nState, fb->nDiag,
               th_outs(fb), xrc, xst, xdiag, xouts);
}

/* TH_S(t, rc, state, diag, outputs): one cycle of `fb` at time t. */
#define TH_S(t_, rc_, st_, diag_, outs_) \
    th_step(fb, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define TH_RUN(t_) TH_S((t_), SL_OK, SL_STATE_RUN, 0, TH_OUT)
#define TH_STOP(t_) TH_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define TH_SAFE(t_) TH_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define TH_RESET(t_) TH_S((t_), SL_OK, SL_STATE_RESET, 0, 0)
#define TH_1BUTTON(t_) TH_S((t_), SL_OK, SL_STATE_TWOHAND_1BUTTON, 0, 0)
#define TH_2BUTTON(t_) TH_S((t_), SL_OK, SL_STATE_TWOHAND_2BUTTON, 0, 0)
#define TH_RELEASE(t_) TH_S((t_), SL_OK, SL_STATE_TWOHAND_RELEASE, 0, 0)
#define TH_ERROR(t_, diag_) TH_S((t_), SL_OK, SL_STATE_ERROR, (diag_), TH_ERR)

static void th_setup(FB_TWOHAND *fb, uint16_t active, uint32_t disc12, uint32_t disc34,
                     uint32_t pairs)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = active;
    fb->tDiscTime12 = disc12;
    fb->tDiscTime34 = disc34;
    fb->tDiscTimePairs = pairs;
}

static void th_group1(FB_TWOHAND *fb, uint8_t v)
{
    fb->bTwoHand1 = v;
    fb->bTwoHand2 = v;
}

static void th_group2(FB_TWOHAND *fb, uint8_t v)
{
    fb->bTwoHand3 = v;
    fb->bTwoHand4 = v;
}

/* sl_twohand_init: status, power-up image (C1), VAR_INPUT bytes 0..39 untouched (ABI §4). */
static void th_init_check(FB_TWOHAND *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[40];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_twohand_init(fb);
    h_check_int(rc, xrc, file, line, "sl_twohand_init");
    h_check_fb(file, line, "TWOHAND(init)", SL_TYPE_TWOHAND, 0, rc, fb->nState, fb->nDiag,
               th_outs(fb), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_twohand_init modified a VAR_INPUT byte (ABI §4)");
}
#define TH_INIT(rc_) th_init_check(fb, (rc_), __FILE__, __LINE__)

/* ERROR -> RESET -> start state (H5: SAFE when all released, else RELEASE). */
static void th_ack(FB_TWOHAND *fb, uint32_t *t, uint8_t start_state, const char *file, int line)
{
    fb->bErrAck = 1;
    th_step(fb, *t += 10, SL_OK, SL_STATE_RESET, 0, 0, file, line);
    fb->bErrAck = 0;
    th_step(fb, *t += 10, SL_OK, start_state, 0, 0, file, line);
}
#define TH_ACK(st_) th_ack(fb, &t, (st_), __FILE__, __LINE__)

/* ---- scenarios ---- */

static void th_both_groups(void)
{
    FB_TWOHAND inst;
    FB_TWOHAND *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("TWOHAND §4.7.1: both groups within the window -> RUN; re-trigger (H8, H11, H12)");
    th_setup(fb, 0x0F, 50, 50, 500);
    TH_INIT(SL_OK);
    TH_STOP(t += 10);
    fb->bRun = 1;
    TH_SAFE(t += 10);                   /* start state: every input released (H5) */
    d = t += 10;
    th_group1(fb, 1);
    TH_1BUTTON(d);
    TH_1BUTTON(d + 250);
    th_group2(fb, 1);
    TH_RUN(d + 499);                    /* second group 499 ms after the first */
    TH_RUN(d + 509);
    fb->bTwoHand1 = 0;                  /* one channel of group 1 released */
    TH_RELEASE(d + 519);                /* output off in that call (H12) */
    fb->bTwoHand2 = 0;
    TH_RELEASE(d + 529);                /* group 2 still actuated */
    th_group1(fb, 1);                   /* both groups actuated again: no new output */
    TH_RELEASE(d + 539);
    TH_RELEASE(d + 1500);
    th_group1(fb, 0);
    th_group2(fb, 0);
    TH_SAFE(d + 1510);                  /* every input released: SAFE */
    t = d + 1510;
    th_group1(fb, 1);
    th_group2(fb, 1);
    TH_1BUTTON(t += 10);                /* both in the same call: 1BUTTON (H8) ... */
    TH_RUN(t += 10);                    /* ... and RUN in the next one */
    th_group2(fb, 0);
    TH_RELEASE(t += 10);
    th_group1(fb, 0);
    TH_SAFE(t += 10);
    th_group2(fb, 1);
    TH_2BUTTON(t += 10);                /* group 2 first */
    th_group1(fb, 1);
    TH_RUN(t += 10);
    fb->bRun = 0;
    TH_STOP(t += 10);                   /* bRun FALSE: STOP, output 0 */
    fb->bRun = 1;
    TH_RELEASE(t += 10);                /* buttons held through start-up (H5) */
    th_group1(fb, 0);
    th_group2(fb, 0);
    TH_SAFE(t += 10);
    h_end();
}

static void th_window(void)
{
    FB_TWOHAND inst;
    FB_TWOHAND *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("TWOHAND window between the groups: at the limit -> ERROR bit 2 (H11, H13)");
    th_setup(fb, 0x0F, 50, 50, 500);
    TH_INIT(SL_OK);
    fb->bRun = 1;
    TH_SAFE(t += 10);
    d = t += 10;
    th_group2(fb, 1);
    TH_2BUTTON(d);
    TH_2BUTTON(d + 499);
    TH_ERROR(d + 500, SL_DIAG_TWOHAND_PAIRS);
    t = d + 500;
    th_group2(fb, 0);
    TH_ERROR(t += 10, SL_DIAG_TWOHAND_PAIRS);
    TH_ACK(SL_STATE_SAFE);
    /* the second group in the very call the window is reached: RUN (H11) */
    d = t += 10;
    th_group1(fb, 1);
    TH_1BUTTON(d);
    th_group2(fb, 1);
    TH_RUN(d + 500);
    t = d + 500;
    th_group1(fb, 0);
    th_group2(fb, 0);
    TH_RELEASE(t += 10);
    TH_SAFE(t += 10);
    /* acknowledged while the first group is still held: start state RELEASE (H5, H13) */
    d = t += 10;
    th_group1(fb, 1);
    TH_1BUTTON(d);
    TH_ERROR(d + 500, SL_DIAG_TWOHAND_PAIRS);
    t = d + 500;
    TH_ACK(SL_STATE_TWOHAND_RELEASE);
    th_group2(fb, 1);
    TH_RELEASE(t += 10);                /* no output from RELEASE */
    th_group1(fb, 0);
    th_group2(fb, 0);
    TH_SAFE(t += 10);
    h_end();

    h_begin("TWOHAND tDiscTimePairs 0: no window (H3)");
    th_setup(fb, 0x0F, 0, 0, 0);
    TH_INIT(SL_OK);
    fb->bRun = 1;
    TH_SAFE(t += 10);
    th_group1(fb, 1);
    TH_1BUTTON(t += 10);
    TH_1BUTTON(t += 60000);
    th_group2(fb, 1);
    TH_RUN(t += 10);
    h_end();
}

static void th_twohand_error(void)
{
    FB_TWOHAND inst;
    FB_TWOHAND *fb = &inst;
    uint32_t t = 1000;
    h_begin("TWOHAND two-hand error bit 6 (H10); 1BUTTON left without the second group (H9)");
    th_setup(fb, 0x0F, 50, 50, 500);
    TH_INIT(SL_OK);
    fb->bRun = 1;
    TH_SAFE(t += 10);
    th_group1(fb, 1);
    TH_1BUTTON(t += 10);
    th_group1(fb, 0);                   /* first released and second actuated in one call */
    th_group2(fb, 1);
    TH_ERROR(t += 10, SL_DIAG_TWOHAND_ERROR);
    th_group2(fb, 0);
    TH_ERROR(t += 10, SL_DIAG_TWOHAND_ERROR);
    TH_ACK(SL_STATE_SAFE);
    th_group1(fb, 1);
    TH_1BUTTON(t += 10);
    th_group1(fb, 0);
    TH_SAFE(t += 10);                   /* let go, nothing else actuated: SAFE (H9) */
    th_group2(fb, 1);
    TH_2BUTTON(t += 10);                /* a new attempt, no error (H10) */
    th_group2(fb, 0);
    TH_SAFE(t += 10);
    th_group1(fb, 1);
    TH_1BUTTON(t += 10);
    fb->bTwoHand3 = 1;                  /* second group partly pressed: keeps 1BUTTON */
    TH_1BUTTON(t += 10);
    th_group1(fb, 0);
    TH_RELEASE(t += 10);                /* TwoHand3 still pressed: RELEASE (H9) */
    fb->bTwoHand3 = 0;
    TH_SAFE(t += 10);
    h_end();
}

static void th_pair_disc(void)
{
    FB_TWOHAND inst;
    FB_TWOHAND *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("TWOHAND discrepancy inside a group: below / at the limit (H7, H13)");
    th_setup(fb, 0x0F, 50, 80, 0);
    TH_INIT(SL_OK);
    fb->bRun = 1;
    TH_SAFE(t += 10);
    d = t += 10;
    fb->bTwoHand1 = 1;                  /* group 1 channels differ */
    TH_SAFE(d);
    fb->bTwoHand2 = 1;
    TH_1BUTTON(d + 49);                 /* agree after 49 ms */
    th_group1(fb, 0);
    TH_SAFE(d + 59);
    d += 69;
    fb->bTwoHand2 = 1;
    TH_SAFE(d);
    TH_SAFE(d + 49);
    TH_ERROR(d + 50, SL_DIAG_DISC1);
    t = d + 50;
    fb->bErrAck = 1;                    /* channels still differ: consumed */
    TH_ERROR(t += 10, SL_DIAG_DISC1);
    fb->bErrAck = 0;
    fb->bTwoHand2 = 0;
    TH_ERROR(t += 10, SL_DIAG_DISC1);
    TH_ACK(SL_STATE_SAFE);
    d = t += 10;
    fb->bTwoHand4 = 1;                  /* group 2, its own time 80 ms */
    TH_SAFE(d);
    TH_SAFE(d + 79);
    TH_ERROR(d + 80, SL_DIAG_DISC2);
    t = d + 80;
    fb->bTwoHand4 = 0;
    TH_ACK(SL_STATE_SAFE);
    h_end();

    h_begin("TWOHAND Safe Inputs after Disc Error: bits 1 + 9, both FALSE first (H4, H13)");
    th_setup(fb, 0x0F, 50, 50, 0);
    fb->dwOptions = SL_OPT_SAFE_INPUTS_AFTER_DISC;
    TH_INIT(SL_OK);
    fb->bRun = 1;
    TH_SAFE(t += 10);
    d = t += 10;
    fb->bTwoHand3 = 1;
    TH_SAFE(d);
    TH_ERROR(d + 50, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);
    t = d + 50;
    fb->bTwoHand4 = 1;                  /* channels agree (TRUE) but never both FALSE */
    TH_ERROR(t += 10, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);
    fb->bErrAck = 1;
    TH_ERROR(t += 10, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);
    fb->bErrAck = 0;
    th_group2(fb, 0);                   /* both FALSE in one call */
    TH_ERROR(t += 10, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);
    TH_ACK(SL_STATE_SAFE);
    h_end();
}

static void th_single_channel_and_invalid(void)
{
    FB_TWOHAND inst;
    FB_TWOHAND *fb = &inst;
    uint32_t t = 1000;
    h_begin("TWOHAND single-channel groups, make contact (H1)");
    th_setup(fb, 0x05, 0, 0, 0);        /* TwoHand1 and TwoHand3 */
    fb->wInputNegated = 0x01;           /* TwoHand1 negated: logical = raw XOR 1 */
    fb->bTwoHand1 = 1;                  /* logical FALSE: released */
    fb->bTwoHand2 = 9;                  /* inactive: not read */
    fb->bTwoHand4 = 9;
    TH_INIT(SL_OK);
    fb->bRun = 1;
    TH_SAFE(t += 10);
    fb->bTwoHand1 = 0;                  /* logical TRUE: group 1 actuated */
    TH_1BUTTON(t += 10);
    fb->bTwoHand3 = 1;
    TH_RUN(t += 10);
    fb->bTwoHand1 = 1;
    TH_RELEASE(t += 10);
    fb->bTwoHand3 = 0;
    TH_SAFE(t += 10);
    h_end();

    h_begin("TWOHAND invalid BOOL: never actuates, never counts as released (H6, ABI §2)");
    th_setup(fb, 0x0F, 50, 50, 0);
    TH_INIT(SL_OK);
    fb->bRun = 1;
    TH_SAFE(t += 10);
    th_group1(fb, 1);
    TH_1BUTTON(t += 10);
    fb->bTwoHand3 = 1;
    fb->bTwoHand4 = 2;                  /* group 2 not actuated */
    TH_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_TWOHAND_1BUTTON, 0, 0);
    fb->bTwoHand4 = 1;
    TH_RUN(t += 10);
    th_group1(fb, 0);
    th_group2(fb, 0);
    fb->bTwoHand2 = 2;
    TH_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_TWOHAND_RELEASE, 0, 0);
    TH_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_TWOHAND_RELEASE, 0, 0); /* not released */
    fb->bTwoHand2 = 0;
    TH_SAFE(t += 10);
    fb->bRun = 3;                       /* invalid Run reads FALSE */
    TH_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_STOP, 0, 0);
    h_end();
}

static void th_config_null_names(void)
{
    FB_TWOHAND inst;
    FB_TWOHAND *fb = &inst;
    uint32_t t = 1000;
    h_begin("TWOHAND configuration errors (SL_E_CONFIG, H2, H3, C6), NULL, names");
    th_setup(fb, 0x03, 0, 0, 0);        /* group 2 without an active input */
    TH_INIT(SL_E_CONFIG);
    fb->bRun = 1;
    th_group1(fb, 1);
    TH_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    TH_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    th_setup(fb, 0x0C, 0, 0, 0);
    TH_INIT(SL_E_CONFIG);
    th_setup(fb, 0x1F, 0, 0, 0);        /* bit 4: no TwoHand5 */
    TH_INIT(SL_E_CONFIG);
    th_setup(fb, 0x0F, 0, 0, SL_TWOHAND_PAIRS_TIME_MAX + 1u); /* > 2500 ms */
    TH_INIT(SL_E_CONFIG);
    th_setup(fb, 0x0D, 50, 0, 0);       /* tDiscTime12 with TwoHand2 inactive */
    TH_INIT(SL_E_CONFIG);
    th_setup(fb, 0x0F, SL_TIME_PARAM_MAX + 1u, 0, 0);
    TH_INIT(SL_E_CONFIG);
    th_setup(fb, 0x0F, 0, 0, 0);
    fb->dwOptions = SL_OPT_EDM1;
    TH_INIT(SL_E_CONFIG);
    th_setup(fb, 0x0F, 0, 0, 0);
    fb->wInputNegated = 0x10;
    TH_INIT(SL_E_CONFIG);
    th_setup(fb, 0x0F, SL_TIME_PARAM_MAX, 1, 2500);
    fb->dwOptions = SL_OPT_SAFE_INPUTS_AFTER_DISC;
    TH_INIT(SL_OK);
    th_setup(fb, 0x0A, 0, 0, 0);        /* TwoHand2 and TwoHand4 single-channel */
    TH_INIT(SL_OK);
    CHECK_INT(sl_twohand_init(NULL), SL_E_NULL);
    CHECK_INT(sl_twohand_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_TWOHAND, SL_STATE_TWOHAND_1BUTTON), "1BUTTON");
    CHECK_STR(sl_state_str(SL_TYPE_TWOHAND, SL_STATE_TWOHAND_2BUTTON), "2BUTTON");
    CHECK_STR(sl_state_str(SL_TYPE_TWOHAND, SL_STATE_TWOHAND_RELEASE), "RELEASE");
    CHECK_STR(sl_state_str(SL_TYPE_TWOHAND, SL_STATE_START), "?");
    CHECK_DIAG_TEXT(SL_TYPE_TWOHAND, SL_DIAG_TWOHAND_PAIRS,
                    "Discrepancy error between the two input pairs");
    CHECK_DIAG_TEXT(SL_TYPE_TWOHAND, SL_DIAG_DISC1, "Discrepancy error input pair 1");
    h_end();
}

void run_twohand_scenarios(void)
{
    th_both_groups();
    th_window();
    th_twohand_error();
    th_pair_disc();
    th_single_channel_and_invalid();
    th_config_null_names();
}
