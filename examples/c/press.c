/*
 * An excentric press with an electronic cam controller (FB CAMMONITOR_UINT, manual §4.26),
 * in C: crank encoder (0 .. 8192 = 360 deg), hardware overrun and upward cams, Reset start
 * pulses and Press_Started. The same press and timeline as `cargo run --example press`:
 * the test command diffs the two outputs. Deterministic simulated time (10 ms cycles);
 * exits 0 when both errors (overrun 0x400D, failing upward cam 0x4007) were seen.
 */
#include <stdio.h>
#include <string.h>

#include "safelogic.h"

#define C_POS 8193u

static struct {
    FB_CAMMONITOR_UINT fb;
    uint32_t pos, t;
    int upward_cam_broken;
    char last[160];
    uint16_t seen[8];
    int nseen;
} p;

static void press_init(void)
{
    memset(&p, 0, sizeof p);
    p.fb.wInputActive = SL_CAMMONITOR_ACTIVE_RESET | SL_CAMMONITOR_ACTIVE_POSITION
                        | SL_CAMMONITOR_ACTIVE_PRESSSTARTED | SL_CAMMONITOR_ACTIVE_OVERRUNCAM
                        | SL_CAMMONITOR_ACTIVE_UPWARDCAM;
    p.fb.tStopDetectionTime = 50;
    p.fb.tPressStartDelayTime = 200;
    p.fb.tMoveDetectionTime = 100;
    p.fb.nAllowedPositionJitter = 4;
    p.fb.nMinPositionChange = 20;
    p.fb.nMaxPosition = 8192;
    p.fb.nTDC1LowerLimitFix = 8092;
    p.fb.nTDC1UpperLimitFix = 100;
    p.fb.nBDCLowerLimitFix = 3896;
    p.fb.nBDCUpperLimitFix = 4296;
    p.fb.nOverrunMaxFix = 800;
    p.pos = 50;
    if (sl_cammonitor_uint_init(&p.fb) != SL_OK)
        fprintf(stderr, "init refused\n");
    p.fb.bRun = 1;
}

/* One 10 ms cycle at the current position; prints a line when something changed. */
static void cycle(const char *note)
{
    char key[160];
    FB_CAMMONITOR_UINT *f = &p.fb;
    int32_t rc;
    f->bOverrunCam = (uint8_t)!(p.pos >= 1500 && p.pos < 6000);
    f->bUpwardCam = (uint8_t)(p.pos >= 4000 && !p.upward_cam_broken);
    f->nPosition = (uint16_t)p.pos;
    rc = sl_cammonitor_uint_cycle(f, p.t);
    if (f->nDiagTextId != 0) {
        int known = 0;
        for (int i = 0; i < p.nseen; i++)
            known |= p.seen[i] == f->nDiagTextId;
        if (!known && p.nseen < 8)
            p.seen[p.nseen++] = f->nDiagTextId;
    }
    /* A line when a state, a BOOL output or the message changes (or an event is noted). */
    snprintf(key, sizeof key, "%-26s OK=%u UP=%u TDC=%u BDC=%u ERR=%u text=0x%04x",
             sl_state_str(SL_TYPE_CAMMONITOR_UINT, f->nState), f->bCamMonOK, f->bUpwardsMove,
             f->bTDC, f->bBDC, f->bError, f->nDiagTextId);
    if (strcmp(key, p.last) != 0 || note[0] != '\0' || rc != SL_OK) {
        printf("%6u ms  pos %4u  %s  OverrunTDC %4u  OverrunStop %4u%s%s\n", (unsigned)p.t,
               (unsigned)p.pos, key, f->nOverrunTDC, f->nOverrunStop, note[0] ? "  <- " : "", note);
        strcpy(p.last, key);
    }
    p.t += 10;
}

static void hold(int calls, const char *note)
{
    for (int i = 0; i < calls; i++)
        cycle(i == 0 ? note : "");
}

static void reset_pulse(void)
{
    p.fb.bReset = 1;
    cycle("Reset TRUE");
    p.fb.bReset = 0;
    cycle("Reset FALSE (start released)");
}

/* A stroke: Press_Started on, clockwise at `speed` per cycle; Press_Started off at
 * `brake_at` (the stop command), then the press coasts `coast` increments further at half
 * speed and stands still. */
static void stroke(uint32_t speed, uint32_t brake_at, uint32_t coast)
{
    uint32_t travelled = 0, left;
    int first = 1;
    p.fb.bPressStarted = 1;
    for (;;) {
        uint32_t next = (p.pos + speed) % C_POS;
        if (travelled > C_POS / 2 && brake_at >= p.pos && brake_at < p.pos + speed) {
            p.pos = brake_at;
            break;
        }
        p.pos = next;
        travelled += speed;
        cycle(first ? "Press_Started TRUE, press runs" : "");
        first = 0;
        if (p.fb.nState == SL_STATE_ERROR)
            return;
    }
    p.fb.bPressStarted = 0;
    cycle("Press_Started FALSE (stop command)");
    left = coast;
    while (left > 0 && p.fb.nState != SL_STATE_ERROR) {
        uint32_t s = speed / 2 < left ? speed / 2 : left;
        left -= s;
        p.pos = (p.pos + s) % C_POS;
        cycle("");
    }
    hold(8, "standstill");
}

static void ack(void)
{
    p.fb.bErrAck = 1;
    cycle("ErrAck TRUE");
    p.fb.bErrAck = 0;
    cycle("ErrAck FALSE");
}

int main(void)
{
    printf("Excentric press: CAMMONITOR_UINT, TDC 8092..100, OverrunMax 800, BDC 3896..4296, "
           "cams checked\n\n");
    press_init();
    hold(1, "power on at TDC");
    reset_pulse();
    printf("-- stroke 1: normal\n");
    stroke(64, 8000, 256);
    reset_pulse();
    printf("-- stroke 2: normal\n");
    stroke(64, 8000, 200);
    reset_pulse();
    printf("-- stroke 3: the brake is late, the press overruns TDC past OverrunMax\n");
    stroke(64, 200, 900);
    ack();
    reset_pulse();
    printf("-- stroke 4: the upward cam fails (stuck FALSE)\n");
    p.upward_cam_broken = 1;
    stroke(64, 8000, 256);
    p.upward_cam_broken = 0;
    ack();
    if (p.nseen != 2 || p.seen[0] != SL_TEXT_CAMMONITOR_LEFT_TDC
        || p.seen[1] != SL_TEXT_CAMMONITOR_UPWARDCAM_FALSE_LEFT) {
        fprintf(stderr, "expected the errors 0x400D and 0x4007\n");
        return 1;
    }
    return 0;
}
