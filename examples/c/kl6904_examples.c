/*
 * The KL6904 application examples 5.1 (machine with an emergency stop, FB ESTOP) and 5.2
 * (machine with safety door monitoring, FB MON), run against a simulated machine: the C
 * twin of the Rust demo (`cargo run --release --example demo`). It prints the same
 * scenarios in the same table, byte for byte (the test command compares the two outputs).
 *
 *     kl6904_examples            both examples
 *     kl6904_examples 5.1        only the emergency stop
 *     kl6904_examples 5.2        only the safety door
 *
 * The task runs every millisecond on a simulated clock, so every run prints the same
 * timeline. Contactors K1 and K2 are simulated with a pick-up and a release delay and a
 * mechanically linked (mirror) NC auxiliary contact, which is TRUE while the contactor is
 * released; a welded contactor stays picked up when its coil is switched off. One line is
 * printed whenever an input, a contactor, the state, an output, the diagnosis or the
 * returned status changes, and whenever the script does something.
 *
 * Exits 0 when the milestones of each example were seen (RUN reached, the EDM1 error or the
 * discrepancy error reported, RUN again after the repair, no unexpected status); otherwise
 * it says on stderr which one is missing and exits 1.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "safelogic.h"

#define CYCLE_MS 1u   /* task cycle of the simulated safety task */
#define PICKUP_MS 8u  /* contactor pick-up delay (coil on -> contacts closed, mirror open) */
#define RELEASE_MS 5u /* contactor release delay (coil off -> contacts open, mirror closed) */

/* ---- the simulated machine --------------------------------------------------------- */

/* A contactor with forced (mirror) contacts. */
typedef struct {
    int coil;
    uint32_t coil_since;
    int picked;
    int welded;
} contactor;

/* Follows the coil after the pick-up or release delay. A welded contactor cannot release. */
static void contactor_update(contactor *c, int coil, uint32_t now)
{
    uint32_t delay;
    int stuck;
    if (coil != c->coil) {
        c->coil = coil;
        c->coil_since = now;
    }
    delay = coil ? PICKUP_MS : RELEASE_MS;
    stuck = c->welded && c->picked;
    if (c->picked != coil && !stuck && (uint32_t)(now - c->coil_since) >= delay) {
        c->picked = coil;
    }
}

static const char *contactor_label(const contactor *c)
{
    if (c->picked) {
        return c->welded ? "WELD" : "on";
    }
    return "off";
}

/* Signals the operator and the wiring put on the block's inputs (besides EDM1). */
typedef struct {
    int in1, in2, restart, errack, run;
} panel;

typedef enum { SAY, NOTE, IN1, IN2, RESTART, ERRACK, RUN, WELD, REPLACE } act;

typedef struct {
    uint32_t t;
    act a;
    int v; /* the new value, or the contactor (0 = K1, 1 = K2) */
    const char *note;
} step;

/* ---- the two blocks behind one interface --------------------------------------------- */

typedef struct {
    int is_mon;
    FB_ESTOP estop;
    FB_MON mon;
    const char *pairs[4]; /* names of the discrepancy groups, diag bits 0-3 */
} guard;

static int32_t g_init(guard *g) { return g->is_mon ? sl_mon_init(&g->mon) : sl_estop_init(&g->estop); }
static int32_t g_cycle(guard *g, uint32_t now) { return g->is_mon ? sl_mon_cycle(&g->mon, now) : sl_estop_cycle(&g->estop, now); }

static void g_write_inputs(guard *g, const panel *p, int edm1)
{
    if (g->is_mon) {
        g->mon.bMonIn1 = (uint8_t)p->in1;
        g->mon.bMonIn2 = (uint8_t)p->in2;
        g->mon.bRestart = (uint8_t)p->restart;
        g->mon.bErrAck = (uint8_t)p->errack;
        g->mon.bRun = (uint8_t)p->run;
        g->mon.bEDM1 = (uint8_t)edm1;
    } else {
        g->estop.bEStopIn1 = (uint8_t)p->in1;
        g->estop.bEStopIn2 = (uint8_t)p->in2;
        g->estop.bRestart = (uint8_t)p->restart;
        g->estop.bErrAck = (uint8_t)p->errack;
        g->estop.bRun = (uint8_t)p->run;
        g->estop.bEDM1 = (uint8_t)edm1;
    }
}

/* (undelayed output, delayed output, Error) */
static void g_outputs(const guard *g, uint8_t out[3])
{
    out[0] = g->is_mon ? g->mon.bMonOut : g->estop.bEStopOut;
    out[1] = g->is_mon ? g->mon.bMonDelOut : g->estop.bEStopDelOut;
    out[2] = g->is_mon ? g->mon.bError : g->estop.bError;
}

static uint8_t g_state(const guard *g) { return g->is_mon ? g->mon.nState : g->estop.nState; }
static uint16_t g_diag(const guard *g) { return g->is_mon ? g->mon.nDiag : g->estop.nDiag; }

/* "RUN", "SAFE", ... from the library (ESTOP's states are a subset of MON's, same names). */
static const char *state_name(uint8_t state) { return sl_state_str(SL_TYPE_MON, state); }

/* "SL_E_CLOCK" etc. (the part of the status text before the colon). */
static void status_name(int32_t status, char *buf, size_t len)
{
    const char *text = sl_status_str(status);
    size_t n = strcspn(text, ":");
    if (n >= len) {
        n = len - 1;
    }
    memcpy(buf, text, n);
    buf[n] = '\0';
}

static void append(char *buf, size_t len, const char *text)
{
    size_t used = strlen(buf);
    if (used + 1 < len) {
        strncat(buf, text, len - used - 1);
    }
}

/* nDiag as hex and the names of its bits. */
static void diag_text(const guard *g, uint16_t diag, char *buf, size_t len)
{
    static const struct { uint16_t mask; const char *name; } extra[] = {
        {SL_DIAG_EDM1, "EDM1"}, {SL_DIAG_EDM2, "EDM2"}, {SL_DIAG_PARAM_CHANGED, "parameter changed"},
        {SL_DIAG_CLOCK, "clock"}, {SL_DIAG_CORRUPT, "corrupt"},
    };
    int bit, first = 1;
    size_t i;
    if (diag == 0) {
        snprintf(buf, len, "0x0000");
        return;
    }
    snprintf(buf, len, "0x%04X ", (unsigned)diag);
    for (bit = 0; bit < 4; bit++) {
        if (diag & (1u << bit)) {
            if (!first) append(buf, len, ", ");
            append(buf, len, g->pairs[bit]);
            if (diag & (1u << (bit + 8))) append(buf, len, " (safe inputs after disc.)");
            first = 0;
        }
    }
    for (i = 0; i < sizeof extra / sizeof extra[0]; i++) {
        if (diag & extra[i].mask) {
            if (!first) append(buf, len, ", ");
            append(buf, len, extra[i].name);
            first = 0;
        }
    }
}

/* ---- the simulation ---------------------------------------------------------------- */

/* Everything a line of the timeline shows. */
typedef struct {
    panel p;
    int edm1;
    const char *k[2];
    uint8_t state;
    uint8_t out[3];
    uint16_t diag;
    int32_t status;
} snapshot;

static int snap_equal(const snapshot *a, const snapshot *b)
{
    return memcmp(&a->p, &b->p, sizeof a->p) == 0 && a->edm1 == b->edm1 && strcmp(a->k[0], b->k[0]) == 0 &&
           strcmp(a->k[1], b->k[1]) == 0 && a->state == b->state && memcmp(a->out, b->out, 3) == 0 &&
           a->diag == b->diag && a->status == b->status;
}

/* What the example must show (checked at the end). */
typedef struct {
    int run;          /* RUN reached */
    int fault;        /* the scripted fault reported (ERROR with the expected diag bit) */
    int run_after;    /* RUN again after the repair */
    int unexpected;   /* a call returned something other than SL_OK */
} milestones;

static void print_header(void)
{
    printf("  %6s | %3s %3s %3s %4s %3s | %-8s %3s %3s %3s | %-25s | %-4s %-4s | event\n", "t [ms]", "In1", "In2",
           "Rst", "EDM1", "Ack", "state", "Out", "Del", "Err", "diag", "K1", "K2");
    printf("  ------%s-+-%s-+-%s-+-%s-+-%s-+-%s\n", "", "--------------------", "--------------------",
           "-------------------------", "---------", "----------------------------------------");
}

static void print_row(const guard *g, const char *time, const snapshot *s, const char *notes)
{
    char event[1024], diag[128], st[64];
    snprintf(event, sizeof event, "%s", notes);
    if (s->status != SL_OK) {
        if (event[0] != '\0') append(event, sizeof event, "; ");
        status_name(s->status, st, sizeof st);
        append(event, sizeof event, "call returned ");
        append(event, sizeof event, st);
    }
    diag_text(g, s->diag, diag, sizeof diag);
    printf("  %6s | %3d %3d %3d %4d %3d | %-8s %3u %3u %3u | %-25s | %-4s %-4s | %s\n", time, s->p.in1, s->p.in2,
           s->p.restart, s->edm1, s->p.errack, state_name(s->state), (unsigned)s->out[0], (unsigned)s->out[1],
           (unsigned)s->out[2], diag, s->k[0], s->k[1], event);
}

static void add_note(char *notes, size_t len, const char *text)
{
    if (notes[0] != '\0') append(notes, len, "; ");
    append(notes, len, text);
}

static void take(snapshot *s, const guard *g, const panel *p, int edm1, const contactor k[2], int32_t status)
{
    s->p = *p;
    s->edm1 = edm1;
    s->k[0] = contactor_label(&k[0]);
    s->k[1] = contactor_label(&k[1]);
    s->state = g_state(g);
    g_outputs(g, s->out);
    s->diag = g_diag(g);
    s->status = status;
}

/* Runs the script against g (parameters set) with K1 and K2 on the undelayed output and
   their mirror contacts in series on EDM1. fault_bit: the diag bit the scripted fault sets. */
static milestones simulate(guard *g, const char *title, const char *const *legend, const step *script, size_t n,
                           uint16_t fault_bit)
{
    milestones m = {0, 0, 0, 0};
    panel p = {1, 1, 0, 0, 0};
    contactor k[2];
    snapshot last, now;
    uint32_t t, end;
    size_t i, len = strlen(title);
    int32_t status;

    printf("\n%s\n", title);
    for (i = 0; i < len; i++) putchar('=');
    putchar('\n');
    for (; *legend != NULL; legend++) printf("  %s\n", *legend);
    printf("\n");
    print_header();

    memset(k, 0, sizeof k);
    g_write_inputs(g, &p, 1);
    status = g_init(g);
    take(&last, g, &p, 1, k, status);
    print_row(g, "init", &last, "power-up: init() latches the parameters");

    end = script[n - 1].t + 300u;
    for (t = 0; t <= end; t += CYCLE_MS) {
        char notes[1024] = "";
        uint8_t out[3];
        int before[2], edm1, coil, up;
        /* 1. What the operator, the machine and the maintenance staff do now. */
        for (i = 0; i < n; i++) {
            const step *s = &script[i];
            if (s->t != t) continue;
            switch (s->a) {
            case SAY: printf("  %6s |  --- %s\n", "", s->note); continue;
            case NOTE: break;
            case IN1: p.in1 = s->v; break;
            case IN2: p.in2 = s->v; break;
            case RESTART: p.restart = s->v; break;
            case ERRACK: p.errack = s->v; break;
            case RUN: p.run = s->v; break;
            case WELD: k[s->v].welded = 1; break;
            case REPLACE:
                memset(&k[s->v], 0, sizeof k[s->v]);
                g_outputs(g, out);
                k[s->v].coil = out[0] == 1;
                break;
            }
            if (s->note[0] != '\0') add_note(notes, sizeof notes, s->note);
        }
        /* 2. The contactors follow the output the block wrote in the previous cycle. */
        g_outputs(g, out);
        coil = out[0] == 1;
        before[0] = k[0].picked;
        before[1] = k[1].picked;
        contactor_update(&k[0], coil, t);
        contactor_update(&k[1], coil, t);
        edm1 = !k[0].picked && !k[1].picked;
        for (up = 1; up >= 0; up--) {
            const char *names[2];
            int moved = 0, c;
            char text[64];
            for (c = 0; c < 2; c++) {
                if (before[c] != k[c].picked && k[c].picked == up) names[moved++] = c == 0 ? "K1" : "K2";
            }
            if (moved == 0) continue;
            snprintf(text, sizeof text, "%s%s%s %s", names[0], moved == 2 ? " and " : "", moved == 2 ? names[1] : "",
                     up ? "picked up" : "released");
            add_note(notes, sizeof notes, text);
        }
        if (before[0] != k[0].picked || before[1] != k[1].picked) {
            add_note(notes, sizeof notes, edm1 ? "EDM1 = 1" : "EDM1 = 0");
        }
        /* 3. One task cycle of the block through the C ABI. */
        g_write_inputs(g, &p, edm1);
        status = g_cycle(g, t);
        /* 4. Print what changed. */
        take(&now, g, &p, edm1, k, status);
        if (now.state != last.state) {
            char text[128];
            if (now.state == SL_STATE_ERROR) {
                int b, bits = 0;
                char list[64] = "";
                for (b = 0; b < 16; b++) {
                    if (now.diag & (1u << b)) {
                        char num[8];
                        snprintf(num, sizeof num, "%s%d", bits ? ", " : "", b);
                        append(list, sizeof list, num);
                        bits++;
                    }
                }
                snprintf(text, sizeof text, "=> %s, Error TRUE, diag bit%s %s", state_name(now.state),
                         bits == 1 ? "" : "s", list);
            } else {
                snprintf(text, sizeof text, "=> %s", state_name(now.state));
            }
            add_note(notes, sizeof notes, text);
        }
        if (!snap_equal(&now, &last) || notes[0] != '\0') {
            char time[16];
            snprintf(time, sizeof time, "%u", (unsigned)t);
            print_row(g, time, &now, notes);
        }
        /* milestones */
        if (status != SL_OK) m.unexpected = 1;
        if (now.state == SL_STATE_RUN && now.out[0] == 1) {
            if (m.fault) m.run_after = 1;
            else m.run = 1;
        }
        if (now.state == SL_STATE_ERROR && (now.diag & fault_bit) && now.out[2] == 1) m.fault = 1;
        last = now;
    }
    return m;
}

static int report(const char *name, milestones m)
{
    int ok = m.run && m.fault && m.run_after && !m.unexpected;
    if (!ok) {
        fprintf(stderr, "%s: milestone missing:%s%s%s%s\n", name, m.run ? "" : " RUN", m.fault ? "" : " fault reported",
                m.run_after ? "" : " RUN after repair", m.unexpected ? " (unexpected status)" : "");
    }
    return ok;
}

/* ---- KL6904 application example 5.1: machine with an emergency stop ------------------- */

static int example_5_1(void)
{
    static const char *const legend[] = {
        "In1/In2 = EStopIn1/EStopIn2: the two NC channels of e-stop S1 (1 = not pressed),",
        "          one pair, discrepancy time 100 ms",
        "Rst     = Restart: push button S2 (1 = pressed); Ack = ErrAck of the TwinSAFE group",
        "EDM1    = mirror contacts of K1 and K2 in series (1 = both released), EDM1 active",
        "Out/Del/Err = EStopOut / EStopDelOut (delay 0 ms) / Error; K1 and K2 are switched by",
        "          EStopOut (pick-up 8 ms, release 5 ms); FbRun TRUE from t = 0; task cycle 1 ms",
        "K1/K2   = off / on / WELD (main contacts welded: stays on with the coil off)",
        NULL};
    static const step script[] = {
        {0, SAY, 0, "power-up: the group starts; the outputs stay off until S2 is operated"},
        {0, RUN, 1, "FbRun TRUE"},
        {200, RESTART, 1, "S2 pressed, S1 and EDM1 are TRUE"},
        {400, RESTART, 0, "S2 released (falling edge): outputs on"},
        {1000, SAY, 0, "emergency stop"},
        {1000, IN1, 0, "S1 pressed: channel 1 opens, EStopOut off at once"},
        {1003, IN2, 0, "channel 2 opens 3 ms later (inside the discrepancy time)"},
        {1500, IN1, 1, "S1 unlatched: channel 1 closes"},
        {1502, IN2, 1, "channel 2 closes; the outputs stay off until a restart"},
        {2000, RESTART, 1, "S2 pressed"},
        {2150, RESTART, 0, "S2 released: outputs on"},
        {2800, SAY, 0, "welded contactor: the EDM1 check prevents the restart"},
        {2800, WELD, 0, "the main contacts of K1 weld (not visible yet: K1 is on)"},
        {3200, IN1, 0, "S1 pressed: EStopOut off"},
        {3202, IN2, 0, "channel 2 opens"},
        {3700, IN1, 1, "S1 unlatched"},
        {3702, IN2, 1, "channel 2 closes"},
        {4000, RESTART, 1, "S2 pressed while EDM1 = 0 (K1 welded)"},
        {4150, RESTART, 0, "S2 released: no effect in ERROR"},
        {4500, ERRACK, 1, "ErrAck refused: the EDM1 fault remains (K1 still welded)"},
        {4600, ERRACK, 0, "ErrAck released"},
        {5000, REPLACE, 0, "maintenance replaces K1: its mirror contact closes"},
        {5500, ERRACK, 1, "ErrAck rising edge, no fault left"},
        {5600, ERRACK, 0, "ErrAck falling edge; a restart is still required"},
        {6000, RESTART, 1, "S2 pressed"},
        {6150, RESTART, 0, "S2 released: outputs on"},
        {6800, SAY, 0, "discrepancy error: a defective contact block on channel 2"},
        {6800, IN1, 0, "S1 pressed, channel 2 stays closed: the discrepancy timer runs"},
        {6900, NOTE, 0, "channel 1 and 2 differed for 100 ms"},
        {7300, IN1, 1, "S1 unlatched: both channels agree again"},
        {7400, SAY, 0, "the contact block of channel 2 is replaced"},
        {7500, ERRACK, 1, "ErrAck rising edge"},
        {7600, ERRACK, 0, "ErrAck falling edge"},
        {8000, RESTART, 1, "S2 pressed"},
        {8150, RESTART, 0, "S2 released: outputs on"},
    };
    static guard g;
    memset(&g, 0, sizeof g);
    /* EStopIn1/EStopIn2 = the two NC channels of e-stop S1, a pair with a discrepancy time
       of 100 ms; EDM1 active; no delay for EStopDelOut. */
    g.estop.wInputActive = 0x03;
    g.estop.tDiscTime12 = 100;
    g.estop.dwOptions = SL_OPT_EDM1;
    g.pairs[0] = "disc. EStopIn1/2";
    g.pairs[1] = "disc. EStopIn3/4";
    g.pairs[2] = "disc. EStopIn5/6";
    g.pairs[3] = "disc. EStopIn7/8";
    return report("5.1", simulate(&g, "KL6904 application example 5.1: machine with an emergency stop (FB ESTOP)",
                                  legend, script, sizeof script / sizeof script[0], SL_DIAG_EDM1));
}

/* ---- KL6904 application example 5.2: machine with safety door monitoring ------------- */

static int example_5_2(void)
{
    static const char *const legend[] = {
        "In1/In2 = MonIn1/MonIn2: door switches S1/S2, NC (1 = door closed), one pair,",
        "          discrepancy time 200 ms",
        "Rst     = Restart: push button S3, manual restart active; Ack = ErrAck of the group",
        "EDM1    = mirror contacts of K1 and K2 in series (1 = both released), EDM1 active",
        "Out/Del/Err = MonOut / MonDelOut (delay 0 ms) / Error; K1 and K2 are switched by",
        "          MonOut (pick-up 8 ms, release 5 ms); FbRun TRUE from t = 0; task cycle 1 ms",
        "K1/K2   = off / on (contactor state)",
        NULL};
    static const step script[] = {
        {0, SAY, 0, "power-up: door closed; the outputs stay off until S3 is operated"},
        {0, RUN, 1, "FbRun TRUE"},
        {200, RESTART, 1, "S3 pressed, S1, S2 and EDM1 are TRUE"},
        {350, RESTART, 0, "S3 released (falling edge): outputs on"},
        {1000, SAY, 0, "the door is opened and closed again"},
        {1000, IN1, 0, "door opened: S1 opens, MonOut off at once"},
        {1040, IN2, 0, "S2 opens 40 ms later (inside the discrepancy time)"},
        {2000, IN2, 1, "door closed: S2 closes"},
        {2025, IN1, 1, "S1 closes; the outputs stay off (manual restart)"},
        {2500, RESTART, 1, "S3 pressed"},
        {2650, RESTART, 0, "S3 released: outputs on"},
        {3200, SAY, 0, "S3 held while the door opens (manual 4.5.4, sample 3)"},
        {3200, RESTART, 1, "S3 pressed while running: no effect in RUN"},
        {3400, IN1, 0, "door opened while S3 is held"},
        {3401, NOTE, 0, "Restart TRUE in SAFE: EDM1 is checked at once, K1/K2 have not released yet"},
        {3440, IN2, 0, "S2 opens"},
        {3600, RESTART, 0, "S3 released"},
        {4000, IN2, 1, "door closed"},
        {4020, IN1, 1, "S1 closes"},
        {4300, ERRACK, 1, "ErrAck rising edge: K1/K2 have released, EDM1 = 1"},
        {4400, ERRACK, 0, "ErrAck falling edge"},
        {4700, RESTART, 1, "S3 pressed"},
        {4850, RESTART, 0, "S3 released: outputs on"},
        {5500, SAY, 0, "door switch S2 misaligned: it does not open with the door"},
        {5500, IN1, 0, "door opened: S1 opens, S2 stays closed"},
        {5700, NOTE, 0, "S1 and S2 differed for 200 ms"},
        {6500, IN1, 1, "door closed: S1 and S2 agree again, Error stays until ErrAck"},
        {6600, SAY, 0, "the actuator of S2 is realigned"},
        {6800, ERRACK, 1, "ErrAck rising edge"},
        {6900, ERRACK, 0, "ErrAck falling edge"},
        {7200, RESTART, 1, "S3 pressed"},
        {7350, RESTART, 0, "S3 released: outputs on"},
    };
    static guard g;
    memset(&g, 0, sizeof g);
    /* MonIn1/MonIn2 = door switches S1/S2 (NC, closed while the door is closed), a pair with a
       discrepancy time of 200 ms; EDM1 active; manual restart with S3; no delay for MonDelOut;
       no Secure inputs, no function test. */
    g.is_mon = 1;
    g.mon.wInputActive = 0x03;
    g.mon.tDiscTime12 = 200;
    g.mon.dwOptions = SL_OPT_EDM1 | SL_OPT_MANUAL_RESTART;
    g.pairs[0] = "disc. MonIn1/2";
    g.pairs[1] = "disc. MonIn3/4";
    g.pairs[2] = "disc. Secure1/2";
    g.pairs[3] = "disc. group 4";
    /* the scripted faults: the EDM1 check (S3 held while the door opens), then the discrepancy */
    return report("5.2", simulate(&g, "KL6904 application example 5.2: machine with safety door monitoring (FB MON)",
                                  legend, script, sizeof script / sizeof script[0], SL_DIAG_EDM1 | SL_DIAG_DISC1));
}

int main(int argc, char **argv)
{
    int want51 = argc < 2, want52 = argc < 2, ok = 1, i;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "5.1") == 0) want51 = 1;
        if (strcmp(argv[i], "5.2") == 0) want52 = 1;
    }
    printf("safelogic demo: the KL6904 application examples on a simulated machine\n");
    printf("(safelogic is not a certified safety component; see README.md)\n");
    if (want51) ok &= example_5_1();
    if (want52) ok &= example_5_2();
    if (!want51 && !want52) {
        fprintf(stderr, "usage: kl6904_examples [5.1|5.2]\n");
        return 2;
    }
    return ok ? 0 : 1;
}
