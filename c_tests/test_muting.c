/*
 * FB_MUTING behaviour scenarios (manual §4.8, EL6910 extensions §4.8.4; ABI.md §2, §4, §5,
 * §7, §9; docs/semantics.md step table and rows M1-M22, C1-C12).
 *
 * Every step calls sl_muting_cycle once and checks the status code, nState, nDiag and all
 * four outputs: bit 0 of the expected set = bMuteOut, bit 1 = bMuteDelOut,
 * bit 2 = bMutingActive, bit 3 = bError. The state outputs are row M19's table.
 */
#include "harness.h"

/* ---- helpers (prefixed mut_) ---- */

#define MUT_OUT 1u
#define MUT_DEL 2u
#define MUT_ACT 4u
#define MUT_ERR 8u
#define MUT_O_RUN (MUT_OUT | MUT_DEL)            /* RUN: 0, 1, 1 */
#define MUT_O_MUTING (MUT_ACT | MUT_OUT | MUT_DEL) /* MUTING1-9: 1, 1, 1 */

/* Pattern bits of the step table: M1, M2, F (field interrupted), M3, M4. */
#define MUT_M1 1u
#define MUT_M2 2u
#define MUT_F 4u
#define MUT_M3 8u
#define MUT_M4 16u

static uint32_t mut_outs(const FB_MUTING *fb)
{
    uint32_t o = 0;
    o = h_pack_bool(o, fb->bMuteOut, 0);
    o = h_pack_bool(o, fb->bMuteDelOut, 1);
    o = h_pack_bool(o, fb->bMutingActive, 2);
    o = h_pack_bool(o, fb->bError, 3);
    return o;
}

static void mut_step(FB_MUTING *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_muting_cycle(fb, t);
    h_check_fb(file, line, "MUTING", SL_TYPE_MUTING, t, rc, fb->nState, fb->nDiag,
               mut_outs(fb), xrc, xst, xdiag, xouts);
}

/* MUT_S(t, rc, state, diag, outputs): one cycle of `fb` at time t. */
#define MUT_S(t_, rc_, st_, diag_, outs_) \
    mut_step(fb, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define MUT_RUN(t_) MUT_S((t_), SL_OK, SL_STATE_RUN, 0, MUT_O_RUN)
#define MUT_STOP(t_) MUT_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define MUT_SAFE(t_) MUT_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define MUT_RESET(t_) MUT_S((t_), SL_OK, SL_STATE_RESET, 0, 0)
#define MUT_DELAYOUT(t_) MUT_S((t_), SL_OK, SL_STATE_DELAYOUT, 0, MUT_DEL)
#define MUT_MUTING(t_, n_) \
    MUT_S((t_), SL_OK, (uint8_t)(SL_STATE_MUTING_MUTING1 + (n_) - 1), 0, MUT_O_MUTING)
#define MUT_ERROR(t_, diag_) MUT_S((t_), SL_OK, SL_STATE_ERROR, (diag_), MUT_ERR)

/* Sets the inputs from a step-table pattern (field clear = both OSSD inputs TRUE). */
static void mut_set(FB_MUTING *fb, unsigned p)
{
    fb->bMutingIn1 = (p & MUT_M1) ? 1 : 0;
    fb->bMutingIn2 = (p & MUT_M2) ? 1 : 0;
    fb->bMutingIn3 = (p & MUT_M3) ? 1 : 0;
    fb->bMutingIn4 = (p & MUT_M4) ? 1 : 0;
    fb->bOSSDIn1 = (p & MUT_F) ? 0 : 1;
    fb->bOSSDIn2 = (p & MUT_F) ? 0 : 1;
}

/* All six inputs active, Enable TRUE, EDM inputs TRUE (inactive unless an option says so),
 * sensors idle, field clear. */
static void mut_setup(FB_MUTING *fb, uint16_t active, uint32_t options)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = active;
    fb->dwOptions = options;
    fb->bMutingEnable = 1;
    fb->bEDM1 = 1;
    fb->bEDM2 = 1;
    mut_set(fb, 0);
}

/* sl_muting_init: status, power-up image (C1), VAR_INPUT bytes 0..55 untouched (ABI §4). */
static void mut_init_check(FB_MUTING *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[56];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_muting_init(fb);
    h_check_int(rc, xrc, file, line, "sl_muting_init");
    h_check_fb(file, line, "MUTING(init)", SL_TYPE_MUTING, 0, rc, fb->nState, fb->nDiag,
               mut_outs(fb), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_muting_init modified a VAR_INPUT byte (ABI §4)");
}
#define MUT_INIT(rc_) mut_init_check(fb, (rc_), __FILE__, __LINE__)

/* STOP -> SAFE -> RUN (M11: automatic start, one transition per call). */
static void mut_start(FB_MUTING *fb, uint32_t *t, const char *file, int line)
{
    fb->bRun = 1;
    mut_step(fb, *t += 10, SL_OK, SL_STATE_SAFE, 0, 0, file, line);
    mut_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, MUT_O_RUN, file, line);
}
#define MUT_START() mut_start(fb, &t, __FILE__, __LINE__)

/* ERROR -> RESET -> SAFE -> RUN (M11), with the muting area clear (M15). */
static void mut_ack(FB_MUTING *fb, uint32_t *t, const char *file, int line)
{
    fb->bErrAck = 1;
    mut_step(fb, *t += 10, SL_OK, SL_STATE_RESET, 0, 0, file, line);
    fb->bErrAck = 0;
    mut_step(fb, *t += 10, SL_OK, SL_STATE_SAFE, 0, 0, file, line);
    mut_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, MUT_O_RUN, file, line);
}
#define MUT_ACK() mut_ack(fb, &t, __FILE__, __LINE__)

/* The sequential forward step table (docs/semantics.md): the pattern of MUTING1..MUTING9. */
static const unsigned mut_table[9] = {
    MUT_M1,
    MUT_M1 | MUT_M2,
    MUT_M1 | MUT_M2 | MUT_F,
    MUT_M1 | MUT_M2 | MUT_F | MUT_M3,
    MUT_M1 | MUT_M2 | MUT_F | MUT_M3 | MUT_M4,
    MUT_M2 | MUT_F | MUT_M3 | MUT_M4,
    MUT_F | MUT_M3 | MUT_M4,
    MUT_M3 | MUT_M4,
    MUT_M4,
};

/* ---- sequences ---- */

static void mut_sequential(void)
{
    FB_MUTING inst;
    FB_MUTING *fb = &inst;
    uint32_t t = 1000;
    int i;
    h_begin("MUTING sequential, 4 sensors: full forward sequence MUTING1..9 -> RUN (M1, M3)");
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    MUT_INIT(SL_OK);
    MUT_STOP(t += 10);
    MUT_START();
    for (i = 0; i < 9; i++) {
        mut_set(fb, mut_table[i]);
        MUT_MUTING(t += 10, i + 1);
        MUT_MUTING(t += 10, i + 1);     /* the same pattern stays */
    }
    mut_set(fb, 0);
    MUT_RUN(t += 10);                   /* M4 released: sequence complete, MutingActive 0 */
    MUT_RUN(t += 10);
    /* a second sequence may start after the first completed (M5) */
    mut_set(fb, mut_table[0]);
    MUT_MUTING(t += 10, 1);
    mut_set(fb, mut_table[1]);
    MUT_MUTING(t += 10, 2);
    fb->bRun = 0;
    MUT_STOP(t += 10);                  /* bRun FALSE: STOP, all outputs 0 */
    mut_set(fb, 0);
    MUT_STOP(t += 10);
    MUT_START();
    h_end();
}

static void mut_parallel(void)
{
    FB_MUTING inst;
    FB_MUTING *fb = &inst;
    uint32_t t = 1000;
    h_begin("MUTING parallel, groups A = MutingIn1/2, B = MutingIn3/4: full sequence (M2, M4)");
    mut_setup(fb, 0x3F, 0);
    fb->tDiscTime12 = 100;
    fb->tDiscTime34 = 100;
    fb->tDiscTimeOSSD = 100;
    MUT_INIT(SL_OK);
    MUT_START();
    fb->bMutingIn1 = 1;                 /* one channel of A: A not actuated yet */
    MUT_RUN(t += 10);
    fb->bMutingIn2 = 1;
    MUT_MUTING(t += 10, 2);             /* A actuated (both channels) */
    fb->bOSSDIn1 = 0;
    fb->bOSSDIn2 = 0;
    MUT_MUTING(t += 10, 3);             /* field interrupted */
    fb->bMutingIn3 = 1;
    MUT_MUTING(t += 10, 3);             /* B not actuated yet */
    fb->bMutingIn4 = 1;
    MUT_MUTING(t += 10, 5);             /* B actuated */
    fb->bMutingIn1 = 0;
    MUT_MUTING(t += 10, 6);             /* A released (first channel) */
    fb->bMutingIn2 = 0;
    MUT_MUTING(t += 10, 6);             /* MUTING6 lasts until the field clears */
    fb->bOSSDIn1 = 1;
    fb->bOSSDIn2 = 1;
    MUT_MUTING(t += 10, 8);             /* field clear */
    fb->bMutingIn3 = 0;
    MUT_RUN(t += 10);                   /* B released (first channel): complete */
    fb->bMutingIn4 = 0;
    MUT_RUN(t += 10);
    h_end();

    h_begin("MUTING parallel: channels of a group differing for tDiscTime12 -> ERROR bit 0 + 8");
    fb->bMutingIn1 = 1;
    MUT_RUN(t += 10);
    MUT_RUN(t + 89);
    MUT_ERROR(t + 100, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    t += 100;
    fb->bMutingIn1 = 0;                 /* both channels FALSE together: bit 8 cleared (M14) */
    MUT_ERROR(t += 10, SL_DIAG_DISC1);
    MUT_ACK();
    h_end();
}

/* ---- violations, maximum muting time ---- */

static void mut_violation(void)
{
    FB_MUTING inst;
    FB_MUTING *fb = &inst;
    uint32_t t = 1000;
    h_begin("MUTING sequence violations -> ERROR bit 6; ack needs the area clear (M3, M6, M15)");
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    MUT_INIT(SL_OK);
    MUT_START();
    mut_set(fb, MUT_M2);                /* M2 first: not the first step */
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    fb->bErrAck = 1;                    /* M2 still actuated: no acknowledgement */
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    fb->bErrAck = 0;
    mut_set(fb, 0);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    MUT_ACK();
    /* a step skipped in the middle: MUTING2 -> M3 without the field interrupted */
    mut_set(fb, mut_table[0]);
    MUT_MUTING(t += 10, 1);
    mut_set(fb, mut_table[1]);
    MUT_MUTING(t += 10, 2);
    mut_set(fb, mut_table[1] | MUT_M3);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    mut_set(fb, 0);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    MUT_ACK();
    /* a step undone: MUTING1 -> idle */
    mut_set(fb, mut_table[0]);
    MUT_MUTING(t += 10, 1);
    mut_set(fb, 0);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    MUT_ACK();
    /* two changes in one call */
    mut_set(fb, mut_table[1]);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    mut_set(fb, 0);
    MUT_ACK();
    /* Enable TRUE, no sequence, field interrupted: violation (M6) */
    mut_set(fb, MUT_F);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    fb->bErrAck = 1;                    /* field still interrupted: no acknowledgement */
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    fb->bErrAck = 0;
    mut_set(fb, 0);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    MUT_ACK();
    /* backwards start without SL_OPT_MUTING_BACKWARDS (M5) */
    mut_set(fb, MUT_M4);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_SEQUENCE);
    mut_set(fb, 0);
    MUT_ACK();
    h_end();
}

static void mut_max_time(void)
{
    FB_MUTING inst;
    FB_MUTING *fb = &inst;
    uint32_t t = 1000, d;
    int i;
    h_begin("MUTING max muting time: sequence done at 990 ms ok, at 1000 ms ERROR bit 7 (M10)");
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    fb->tMaxMutingTime = 1000;
    MUT_INIT(SL_OK);
    MUT_START();
    d = t + 10;                         /* first step recognised here: muting time starts */
    for (i = 0; i < 9; i++) {
        mut_set(fb, mut_table[i]);
        MUT_MUTING(d + (uint32_t)i * 110u, i + 1);
    }
    mut_set(fb, 0);
    MUT_RUN(d + 990);                   /* complete below the limit */
    t = d + 990;
    d = t + 10;
    for (i = 0; i < 9; i++) {
        mut_set(fb, mut_table[i]);
        MUT_MUTING(d + (uint32_t)i * 111u, i + 1);
    }
    MUT_MUTING(d + 999, 9);
    mut_set(fb, 0);
    MUT_ERROR(d + 1000, SL_DIAG_MUTING_MAX_TIME); /* the error wins the tie (M10) */
    t = d + 1000;
    MUT_ACK();
    /* the limit reached while waiting in MUTING2 */
    d = t + 10;
    mut_set(fb, mut_table[0]);
    MUT_MUTING(d, 1);
    mut_set(fb, mut_table[1]);
    MUT_MUTING(d + 500, 2);
    MUT_MUTING(d + 999, 2);
    MUT_ERROR(d + 1000, SL_DIAG_MUTING_MAX_TIME);
    t = d + 1000;
    fb->bErrAck = 1;                    /* M1/M2 still actuated (M15) */
    MUT_ERROR(t += 10, SL_DIAG_MUTING_MAX_TIME);
    fb->bErrAck = 0;
    mut_set(fb, 0);
    MUT_ERROR(t += 10, SL_DIAG_MUTING_MAX_TIME);
    MUT_ACK();
    h_end();
}

/* ---- Enable FALSE, DELAYOUT, EDM, invalid BOOL ---- */

static void mut_enable_delayout(void)
{
    FB_MUTING inst;
    FB_MUTING *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("MUTING Enable FALSE: interruption -> DELAYOUT to the end of the delay (M7, M13)");
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    fb->tMuteDelOutDelay = 200;
    MUT_INIT(SL_OK);
    fb->bMutingEnable = 0;
    MUT_START();
    mut_set(fb, MUT_M1);                /* Enable FALSE: muting inputs ignored */
    MUT_RUN(t += 10);
    mut_set(fb, 0);
    d = t += 10;
    fb->bOSSDIn2 = 0;                   /* one channel interrupts the field (M8) */
    MUT_DELAYOUT(d);
    fb->bOSSDIn2 = 1;
    MUT_DELAYOUT(d + 50);               /* clear again: the delay still runs out */
    MUT_DELAYOUT(d + 199);
    MUT_SAFE(d + 200);
    MUT_RUN(d + 210);                   /* field clear: RUN (M11) */
    t = d + 210;
    /* Enable going FALSE during a sequence with the field interrupted (M7) */
    fb->bMutingEnable = 1;
    mut_set(fb, mut_table[0]);
    MUT_MUTING(t += 10, 1);
    mut_set(fb, mut_table[1]);
    MUT_MUTING(t += 10, 2);
    mut_set(fb, mut_table[2]);
    MUT_MUTING(t += 10, 3);             /* field interrupted, muted */
    d = t += 10;
    fb->bMutingEnable = 0;
    MUT_DELAYOUT(d);                    /* sequence ended, no muting */
    MUT_DELAYOUT(d + 199);
    MUT_SAFE(d + 200);
    MUT_SAFE(d + 300);
    mut_set(fb, 0);
    MUT_RUN(d + 310);
    t = d + 310;
    /* Enable FALSE during a sequence with the field clear: RUN, MutingActive off */
    fb->bMutingEnable = 1;
    mut_set(fb, mut_table[0]);
    MUT_MUTING(t += 10, 1);
    fb->bMutingEnable = 0;
    MUT_RUN(t += 10);
    mut_set(fb, 0);
    MUT_RUN(t += 10);
    /* invalid OSSD byte: field interrupted (M20) */
    fb->bOSSDIn1 = 2;
    MUT_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_DELAYOUT, 0, MUT_DEL);
    fb->bOSSDIn1 = 1;
    MUT_DELAYOUT(t += 10);
    h_end();

    h_begin("MUTING Enable FALSE, delay 0: interruption -> SAFE at once (M13)");
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    MUT_INIT(SL_OK);
    fb->bMutingEnable = 0;
    MUT_START();
    mut_set(fb, MUT_F);
    MUT_SAFE(t += 10);
    MUT_SAFE(t += 1000);
    mut_set(fb, 0);
    MUT_RUN(t += 10);
    fb->bMutingEnable = 5;              /* invalid Enable reads FALSE (M7, M20) */
    mut_set(fb, MUT_M1);
    MUT_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_RUN, 0, MUT_O_RUN);
    h_end();
}

static void mut_edm(void)
{
    FB_MUTING inst;
    FB_MUTING *fb = &inst;
    uint32_t t = 1000;
    h_begin("MUTING EDM1 active: SAFE until EDM1 TRUE, no error (M12, M20)");
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL | SL_OPT_EDM1);
    fb->bEDM1 = 0;
    fb->bEDM2 = 7;                      /* EDM2 inactive: not read */
    MUT_INIT(SL_OK);
    fb->bRun = 1;
    MUT_SAFE(t += 10);
    MUT_SAFE(t += 10);
    MUT_SAFE(t += 5000);
    fb->bEDM1 = 3;                      /* invalid: not TRUE */
    MUT_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    fb->bEDM1 = 1;
    MUT_RUN(t += 10);
    fb->bEDM1 = 0;                      /* outputs on: EDM not looked at */
    MUT_RUN(t += 10);
    h_end();
}

static void mut_config_null_names(void)
{
    FB_MUTING inst;
    FB_MUTING *fb = &inst;
    uint32_t t = 1000;
    h_begin("MUTING configuration errors (SL_E_CONFIG, M17, C6), NULL, names");
    mut_setup(fb, 0x3E, SL_OPT_MUTING_SEQUENTIAL); /* MutingIn1 inactive */
    MUT_INIT(SL_E_CONFIG);
    fb->bRun = 1;
    MUT_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    MUT_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    mut_setup(fb, 0x33, SL_OPT_MUTING_SEQUENTIAL); /* no OSSD input */
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x7F, SL_OPT_MUTING_SEQUENTIAL); /* bit 6: no such input */
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x0F, 0);             /* parallel without MutingIn3/4 */
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x0F, SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_BACKWARDS);
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    fb->tDiscTime12 = 10;               /* sequential: single-channel only */
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    fb->tFilterTime = SL_MUTING_FILTER_TIME_MAX + 1u;
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    fb->tMaxMutingTime = 600001u;
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL);
    fb->tMuteDelOutDelay = 30001u;
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL | (1u << 11));
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL | SL_OPT_FUNCTION_TEST);
    MUT_INIT(SL_E_CONFIG);
    mut_setup(fb, 0x3F, SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_BACKWARDS |
                            SL_OPT_MUTING_OSSD_CHECK_OPTIONAL | SL_OPT_EDM1 | SL_OPT_EDM2);
    fb->tFilterTime = 500;
    fb->tMaxMutingTime = 600000u;
    fb->tMuteDelOutDelay = 30000u;
    MUT_INIT(SL_OK);
    mut_setup(fb, 0x0F, SL_OPT_MUTING_SEQUENTIAL); /* MutingIn3/4 inactive (§4.8.4) */
    MUT_INIT(SL_OK);
    CHECK_INT(sl_muting_init(NULL), SL_E_NULL);
    CHECK_INT(sl_muting_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_MUTING, SL_STATE_MUTING_MUTING1), "MUTING1");
    CHECK_STR(sl_state_str(SL_TYPE_MUTING, SL_STATE_MUTING_MUTING9), "MUTING9");
    CHECK_STR(sl_state_str(SL_TYPE_MUTING, SL_STATE_DELAYOUT), "DELAYOUT");
    CHECK_STR(sl_state_str(SL_TYPE_MUTING, SL_STATE_START), "?");
    CHECK_DIAG_TEXT(SL_TYPE_MUTING, SL_DIAG_MUTING_SEQUENCE, "Muting sequence was violated");
    CHECK_DIAG_TEXT(SL_TYPE_MUTING, SL_DIAG_MUTING_MAX_TIME,
                    "Maximum muting time was exceeded");
    h_end();
}

void run_muting_scenarios(void)
{
    mut_sequential();
    mut_parallel();
    mut_violation();
    mut_max_time();
    mut_enable_delayout();
    mut_edm();
    mut_config_null_names();
}
