/* One ESTOP: two-channel switch S1, contactor K1 with feedback (EDM1), restart button S2 */
#include <stdint.h>
#include <stdio.h>
#include "safelogic.h"

static FB_ESTOP estop;                           /* caller-allocated, zeroed */

int main(void) {
    uint8_t k1 = 0, s1_pressed, was_on = 0;
    uint32_t t;
    estop.wInputActive = 0x03;                   /* EStopIn1, EStopIn2: one pair */
    estop.tDiscTime12 = 100;                     /* discrepancy time 100 ms */
    estop.dwOptions = SL_OPT_EDM1 | SL_OPT_SAFE_INPUTS_AFTER_DISC;
    if (sl_estop_init(&estop) != SL_OK) return 1; /* SL_E_CONFIG: fix the parameters */
    for (t = 0; t <= 250; t += 50) {             /* one call per task cycle; tNow in ms */
        s1_pressed = t >= 200;
        estop.bEStopIn1 = estop.bEStopIn2 = !s1_pressed; /* TRUE: no demand */
        estop.bEDM1 = !k1;                       /* TRUE while K1 is released */
        estop.bRestart = t == 50;                /* S2: its falling edge restarts */
        estop.bRun = 1;
        int32_t rc = sl_estop_cycle(&estop, t);  /* SL_OK, or a status code below */
        if (rc != SL_OK) { fprintf(stderr, "ESTOP: %s\n", sl_status_str(rc)); return 1; }
        k1 = estop.bEStopOut;                    /* FALSE in every state but RUN */
        was_on |= k1;
        printf("%3u ms  S1 %-8s K1 %-3s %s\n", (unsigned)t, s1_pressed ? "pressed" : "released",
               k1 ? "on" : "off", sl_state_str(SL_TYPE_ESTOP, estop.nState));
        if (s1_pressed && k1) return 1;          /* S1 pressed: K1 off in that very cycle */
    }
    return !was_on;                              /* 0: K1 was on before S1 was pressed */
}
