/*
 * KL6904 application examples 5.1 and 5.2 (shared/spec/kl6904-logic-manual.txt, chapter 5)
 * run on the safelogic C ABI with a simulated plant.
 *
 *   5.1 Machine with an emergency stop switch: FB_ESTOP.
 *       EStopIn1/EStopIn2 = the two break contacts of e-stop S1 (a two-channel pair),
 *       Restart = push button S2, EDM1 = feedback contacts of K1 and K2 in series.
 *       EStopOut drives contactor K1, EStopDelOut drives contactor K2.
 *   5.2 Machine with safety door monitoring: FB_MON with manual restart.
 *       MonIn1/MonIn2 = door switches S1 and S2, Restart = push button S3,
 *       EDM1 = feedback contacts of K1 and K2 in series.
 *       MonOut drives K1, MonDelOut drives K2.
 *
 * The contactors have forced (mirror) feedback contacts: the feedback is TRUE while the
 * contactor is released. A contactor picks up 30 ms after its coil is energised and drops
 * out 20 ms after the coil is switched off -- unless its contacts are welded, in which
 * case it stays closed. Each example includes a welded-contactor episode: the feedback
 * stays FALSE after the safe state, and the next restart attempt is refused with the EDM1
 * error (Error output TRUE, diag bit 4), as the manual's examples describe ("The sticking of
 * contacts on contactors K1 and K2 is detected at the EDM1 input and prevents switching on
 * of the block again. The block reports this error by setting the output error to TRUE").
 *
 * Simulated time only (10 ms task cycle from t = 0), so the output is deterministic.
 * Prints a timeline line whenever an input, the state, an output or the diag changes.
 * Exits 0 when the expected milestones were seen (RUN reached, EDM1 error reported while
 * a contactor was welded, RUN again after repair, acknowledgement and restart).
 *
 * Build: cc -std=c11 -I include examples/c/kl6904_examples.c target/release/libsafelogic.a \
 *           -lpthread -ldl -lm
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "safelogic.h"

#define CYCLE_MS 10u
#define PICKUP_MS 30u
#define DROPOUT_MS 20u

/* ---- plant: a contactor with a forced feedback (mirror) contact ---- */

typedef struct {
    const char *name;
    int coil;        /* coil energised by the safe output */
    int closed;      /* main contacts closed */
    int welded;      /* main contacts welded: stay closed whatever the coil does */
    uint32_t since;  /* time of the last coil change */
} contactor;

static void contactor_drive(contactor *k, int coil, uint32_t t)
{
    if (coil != k->coil) {
        k->coil = coil;
        k->since = t;
    }
}

static void contactor_update(contactor *k, uint32_t t)
{
    uint32_t dt = t - k->since;
    if (k->coil && !k->closed && dt >= PICKUP_MS) {
        k->closed = 1;
    } else if (!k->coil && k->closed && !k->welded && dt >= DROPOUT_MS) {
        k->closed = 0;
    }
}

/* Feedback contact: TRUE while released. */
static int contactor_feedback(const contactor *k)
{
    return !k->closed;
}

/* ---- timeline printing ---- */

typedef struct {
    uint8_t in1, in2, restart, edm1, errack;
    uint8_t state, err, out, del;
    uint16_t diag;
    int k1, k2;
    int32_t rc;
} snapshot;

static void diag_text(uint16_t diag, char *buf, size_t n)
{
    static const struct {
        uint16_t bit;
        const char *name;
    } names[] = {{SL_DIAG_DISC1, "DISC1"}, {SL_DIAG_DISC2, "DISC2"},
                 {SL_DIAG_DISC3, "DISC3"}, {SL_DIAG_DISC4, "DISC4"},
                 {SL_DIAG_EDM1, "EDM1"},   {SL_DIAG_EDM2, "EDM2"},
                 {SL_DIAG_PARAM_CHANGED, "PARAM"}, {SL_DIAG_CLOCK, "CLOCK"},
                 {SL_DIAG_CORRUPT, "CORRUPT"}};
    size_t i;
    int w = snprintf(buf, n, "0x%04x", (unsigned)diag);
    for (i = 0; i < sizeof names / sizeof names[0] && w > 0 && (size_t)w < n; i++) {
        if (diag & names[i].bit) {
            w += snprintf(buf + w, n - (size_t)w, " %s", names[i].name);
        }
    }
}

static void print_header(const char *in1, const char *in2, const char *restart,
                         const char *out, const char *del)
{
    printf("  %7s | %-4s %-4s %-4s %-4s %-6s | %-10s | %-5s %-9s %-9s | %-12s | %-2s %-2s | %s\n",
           "t [ms]", in1, in2, restart, "EDM1", "ErrAck", "state", "Error", out, del, "diag",
           "K1", "K2", "event");
    printf("  --------+-----------------------------+------------+---------------------------+"
           "--------------+-------+------\n");
}

static void print_line(uint32_t t, const snapshot *s, const char *event)
{
    char diag[64];
    diag_text(s->diag, diag, sizeof diag);
    printf("  %7lu | %-4u %-4u %-4u %-4u %-6u | %-10s | %-5u %-9u %-9u | %-12s | %-2s %-2s |",
           (unsigned long)t, (unsigned)s->in1, (unsigned)s->in2, (unsigned)s->restart,
           (unsigned)s->edm1, (unsigned)s->errack, sl_state_str(SL_TYPE_MON, s->state), (unsigned)s->err,
           (unsigned)s->out, (unsigned)s->del, diag, s->k1 ? "on" : "-", s->k2 ? "on" : "-");
    if (event != NULL) {
        printf(" %s", event);
    }
    if (s->rc != SL_OK) {
        printf(" [%s]", sl_status_str(s->rc));
    }
    printf("\n");
}

/* Milestones a correct run must show. */
typedef struct {
    int run_before_fault;    /* RUN reached before the welded episode */
    int edm_error_reported;  /* ERROR with diag EDM1 and Error TRUE while welded */
    int run_after_repair;    /* RUN again at the end */
    int unexpected_status;   /* a call returned something else than SL_OK */
} milestones;

/* ---- 5.1: machine with an emergency stop (FB_ESTOP) ---- */

typedef struct {
    uint8_t s1_ch1, s1_ch2; /* e-stop S1 break contacts: 1 = closed (not pressed) */
    uint8_t s2;             /* restart push button S2 (make contact) */
    uint8_t errack;         /* ErrAck of the TwinSAFE group */
} operator_5_1;

static const char *events_5_1(uint32_t t, operator_5_1 *op, contactor *k1, contactor *k2)
{
    (void)k2;
    switch (t) {
    case 0: return "power on: TwinSAFE group runs, outputs off";
    case 100: op->s2 = 1; return "S2 (restart) pressed";
    case 300: op->s2 = 0; return "S2 released: falling edge enables EStopOut/EStopDelOut";
    case 1000: op->s1_ch1 = 0; return "S1 (e-stop) pressed: channel 1 opens";
    case 1010: op->s1_ch2 = 0; return "channel 2 opens 10 ms later (< discrepancy time)";
    case 1500: op->s1_ch1 = 1; op->s1_ch2 = 1; return "S1 released";
    case 2000: op->s2 = 1; return "S2 pressed";
    case 2200: op->s2 = 0; return "S2 released: machine runs again";
    case 3000: k1->welded = 1; return "FAULT: main contacts of K1 weld";
    case 3500: op->s1_ch1 = 0; op->s1_ch2 = 0; return "S1 pressed";
    case 4000: op->s1_ch1 = 1; op->s1_ch2 = 1; return "S1 released";
    case 4500: op->s2 = 1; return "S2 pressed: K1 still closed -> EDM1 FALSE";
    case 4700: op->s2 = 0; return "S2 released";
    case 5000: k1->welded = 0; k1->closed = 0; return "K1 replaced";
    case 5500: op->errack = 1; return "ErrAck pressed";
    case 5700: op->errack = 0; return "ErrAck released";
    case 6000: op->s2 = 1; return "S2 pressed";
    case 6200: op->s2 = 0; return "S2 released";
    default: return NULL;
    }
}

static int example_5_1(void)
{
    FB_ESTOP fb;
    operator_5_1 op;
    contactor k1, k2;
    snapshot prev, cur;
    milestones m;
    uint32_t t;
    int32_t rc;

    printf("\nKL6904 example 5.1: machine with an emergency stop switch (FB_ESTOP)\n");
    printf("  EStopIn1/EStopIn2 = S1 (two break contacts, pair, discrepancy 100 ms),\n"
           "  Restart = S2, EDM1 = feedback K1+K2 in series, EStopOut -> K1, EStopDelOut -> K2\n\n");

    memset(&fb, 0, sizeof fb);
    fb.wInputActive = 0x0003;               /* EStopIn1, EStopIn2 */
    fb.wInputNegated = 0;                   /* break contacts */
    fb.tDiscTime12 = 100;
    fb.tEStopDelOutDelay = 0;
    fb.dwOptions = SL_OPT_EDM1;
    fb.bRun = 1;
    rc = sl_estop_init(&fb);
    if (rc != SL_OK) {
        printf("sl_estop_init: %s\n", sl_status_str(rc));
        return 1;
    }

    memset(&op, 0, sizeof op);
    op.s1_ch1 = 1;
    op.s1_ch2 = 1;
    memset(&k1, 0, sizeof k1);
    memset(&k2, 0, sizeof k2);
    k1.name = "K1";
    k2.name = "K2";
    memset(&prev, 0xFF, sizeof prev);
    memset(&m, 0, sizeof m);

    print_header("S1.1", "S1.2", "S2", "EStopOut", "EStopDel");
    for (t = 0; t <= 7000; t += CYCLE_MS) {
        const char *event = events_5_1(t, &op, &k1, &k2);
        contactor_update(&k1, t);
        contactor_update(&k2, t);

        fb.bEStopIn1 = op.s1_ch1;
        fb.bEStopIn2 = op.s1_ch2;
        fb.bRestart = op.s2;
        fb.bErrAck = op.errack;
        fb.bEDM1 = (uint8_t)(contactor_feedback(&k1) && contactor_feedback(&k2));
        rc = sl_estop_cycle(&fb, t);

        contactor_drive(&k1, fb.bEStopOut, t);
        contactor_drive(&k2, fb.bEStopDelOut, t);

        memset(&cur, 0, sizeof cur); /* padding too: snapshots are compared with memcmp */
        cur.in1 = fb.bEStopIn1;
        cur.in2 = fb.bEStopIn2;
        cur.restart = fb.bRestart;
        cur.edm1 = fb.bEDM1;
        cur.errack = fb.bErrAck;
        cur.state = fb.nState;
        cur.err = fb.bError;
        cur.out = fb.bEStopOut;
        cur.del = fb.bEStopDelOut;
        cur.diag = fb.nDiag;
        cur.k1 = k1.closed;
        cur.k2 = k2.closed;
        cur.rc = rc;
        if (event != NULL || memcmp(&cur, &prev, sizeof cur) != 0) {
            print_line(t, &cur, event);
            memcpy(&prev, &cur, sizeof prev);
        }

        if (rc != SL_OK) {
            m.unexpected_status = 1;
        }
        if (t < 3000 && fb.nState == SL_STATE_RUN) {
            m.run_before_fault = 1;
        }
        if (k1.welded && fb.nState == SL_STATE_ERROR && fb.bError && !fb.bEStopOut &&
            !fb.bEStopDelOut && (fb.nDiag & SL_DIAG_EDM1)) {
            m.edm_error_reported = 1;
        }
        m.run_after_repair = t > 6200 && fb.nState == SL_STATE_RUN && fb.bEStopOut &&
                             fb.bEStopDelOut;
    }
    printf("  => 5.1: RUN %s, welded K1 %s, RUN after repair %s\n",
           m.run_before_fault ? "reached" : "NOT reached",
           m.edm_error_reported ? "reported as EDM1 error (Error TRUE)" : "NOT reported",
           m.run_after_repair ? "reached" : "NOT reached");
    return (m.run_before_fault && m.edm_error_reported && m.run_after_repair &&
            !m.unexpected_status)
               ? 0
               : 1;
}

/* ---- 5.2: machine with safety door monitoring (FB_MON, manual restart) ---- */

typedef struct {
    uint8_t s1, s2;  /* door switches: 1 = door closed */
    uint8_t s3;      /* restart push button S3 */
    uint8_t errack;
} operator_5_2;

static const char *events_5_2(uint32_t t, operator_5_2 *op, contactor *k1, contactor *k2)
{
    (void)k1;
    switch (t) {
    case 0: return "power on: TwinSAFE group runs, outputs off";
    case 100: op->s3 = 1; return "S3 (restart) pressed";
    case 300: op->s3 = 0; return "S3 released: falling edge enables MonOut/MonDelOut";
    case 1000: op->s1 = 0; return "door opened: S1 opens";
    case 1030: op->s2 = 0; return "S2 opens 30 ms later (< discrepancy time)";
    case 1500: op->s2 = 1; return "door closed: S2 closes";
    case 1520: op->s1 = 1; return "S1 closes";
    case 1800: return "door closed, manual restart required";
    case 2000: op->s3 = 1; return "S3 pressed";
    case 2200: op->s3 = 0; return "S3 released: machine runs again";
    case 3000: k2->welded = 1; return "FAULT: main contacts of K2 weld";
    case 3500: op->s1 = 0; op->s2 = 0; return "door opened";
    case 4000: op->s1 = 1; op->s2 = 1; return "door closed";
    case 4500: op->s3 = 1; return "S3 pressed: K2 still closed -> EDM1 FALSE";
    case 4700: op->s3 = 0; return "S3 released";
    case 5000: k2->welded = 0; k2->closed = 0; return "K2 replaced";
    case 5500: op->errack = 1; return "ErrAck pressed";
    case 5700: op->errack = 0; return "ErrAck released";
    case 6000: op->s3 = 1; return "S3 pressed";
    case 6200: op->s3 = 0; return "S3 released";
    default: return NULL;
    }
}

static int example_5_2(void)
{
    FB_MON fb;
    operator_5_2 op;
    contactor k1, k2;
    snapshot prev, cur;
    milestones m;
    uint32_t t;
    int32_t rc;

    printf("\nKL6904 example 5.2: machine with safety door monitoring (FB_MON)\n");
    printf("  MonIn1 = S1, MonIn2 = S2 (door switches, pair, discrepancy 200 ms),\n"
           "  Restart = S3 (manual restart), EDM1 = feedback K1+K2 in series,\n"
           "  MonOut -> K1, MonDelOut -> K2\n\n");

    memset(&fb, 0, sizeof fb);
    fb.wInputActive = 0x0003;               /* MonIn1, MonIn2 */
    fb.tDiscTime12 = 200;
    fb.tMonDelOutDelay = 0;
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_MANUAL_RESTART;
    fb.bRun = 1;
    rc = sl_mon_init(&fb);
    if (rc != SL_OK) {
        printf("sl_mon_init: %s\n", sl_status_str(rc));
        return 1;
    }

    memset(&op, 0, sizeof op);
    op.s1 = 1;
    op.s2 = 1;
    memset(&k1, 0, sizeof k1);
    memset(&k2, 0, sizeof k2);
    k1.name = "K1";
    k2.name = "K2";
    memset(&prev, 0xFF, sizeof prev);
    memset(&m, 0, sizeof m);

    print_header("S1", "S2", "S3", "MonOut", "MonDelOut");
    for (t = 0; t <= 7000; t += CYCLE_MS) {
        const char *event = events_5_2(t, &op, &k1, &k2);
        contactor_update(&k1, t);
        contactor_update(&k2, t);

        fb.bMonIn1 = op.s1;
        fb.bMonIn2 = op.s2;
        fb.bRestart = op.s3;
        fb.bErrAck = op.errack;
        fb.bEDM1 = (uint8_t)(contactor_feedback(&k1) && contactor_feedback(&k2));
        rc = sl_mon_cycle(&fb, t);

        contactor_drive(&k1, fb.bMonOut, t);
        contactor_drive(&k2, fb.bMonDelOut, t);

        memset(&cur, 0, sizeof cur);
        cur.in1 = fb.bMonIn1;
        cur.in2 = fb.bMonIn2;
        cur.restart = fb.bRestart;
        cur.edm1 = fb.bEDM1;
        cur.errack = fb.bErrAck;
        cur.state = fb.nState;
        cur.err = fb.bError;
        cur.out = fb.bMonOut;
        cur.del = fb.bMonDelOut;
        cur.diag = fb.nDiag;
        cur.k1 = k1.closed;
        cur.k2 = k2.closed;
        cur.rc = rc;
        if (event != NULL || memcmp(&cur, &prev, sizeof cur) != 0) {
            print_line(t, &cur, event);
            memcpy(&prev, &cur, sizeof prev);
        }

        if (rc != SL_OK) {
            m.unexpected_status = 1;
        }
        if (t < 3000 && fb.nState == SL_STATE_RUN) {
            m.run_before_fault = 1;
        }
        if (k2.welded && fb.nState == SL_STATE_ERROR && fb.bError && !fb.bMonOut &&
            !fb.bMonDelOut && (fb.nDiag & SL_DIAG_EDM1)) {
            m.edm_error_reported = 1;
        }
        m.run_after_repair = t > 6200 && fb.nState == SL_STATE_RUN && fb.bMonOut &&
                             fb.bMonDelOut;
    }
    printf("  => 5.2: RUN %s, welded K2 %s, RUN after repair %s\n",
           m.run_before_fault ? "reached" : "NOT reached",
           m.edm_error_reported ? "reported as EDM1 error (Error TRUE)" : "NOT reported",
           m.run_after_repair ? "reached" : "NOT reached");
    return (m.run_before_fault && m.edm_error_reported && m.run_after_repair &&
            !m.unexpected_status)
               ? 0
               : 1;
}

int main(void)
{
    int failed = 0;
    printf("safelogic %s -- KL6904 application examples (simulated, %u ms task cycle)\n",
           sl_version(), (unsigned)CYCLE_MS);
    failed |= example_5_1();
    failed |= example_5_2();
    printf("\n%s\n", failed ? "EXAMPLES FAILED: a milestone was not reached"
                            : "both examples behaved as described in the KL6904 manual");
    return failed;
}
