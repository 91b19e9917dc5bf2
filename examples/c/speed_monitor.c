/*
 * A two-channel speed monitor in one TwinSAFE group, in C (manual §4.20, §4.21, §4.24,
 * §4.27): two encoders -> SPEED_DINT x2 -> COMPARE_DINT 1oo2 -> LIMIT_DINT -> AND (drive
 * enable), and SLI_DINT as a standstill window on encoder 1 (door release).
 * The same machine and timeline as `cargo run --example speed_monitor`: the test command
 * diffs the two outputs. Deterministic simulated time (10 ms cycles); exits 0 when every
 * milestone was seen.
 */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "safelogic.h"

static int failures;

#define EXPECT(cond, what)                                               \
    do {                                                                 \
        if (!(cond)) {                                                   \
            fprintf(stderr, "  !! expected: %s\n", what);                \
            failures++;                                                  \
        }                                                                \
    } while (0)

enum { SPEED1, SPEED2, COMPARE, LIMIT, SLI, ENABLE, MEMBERS };

/* The machine: two encoders and one group of six blocks with five links. */
static struct {
    SL_GROUP g;
    SL_MEMBER members[MEMBERS];
    SL_LINK links[5];
    FB_SPEED_DINT speed1, speed2;
    FB_COMPARE_DINT compare;
    FB_LIMIT_DINT limit;
    FB_SLI_DINT sli;
    FB_AND enable;
    int32_t pos[2], step[2]; /* encoder positions, movement per 10 ms cycle */
    uint32_t t;
} d;

static const char *group_state(uint8_t s)
{
    switch (s) {
    case SL_STATE_RUN: return "RUN";
    case SL_STATE_STOP: return "STOP";
    case SL_STATE_ERROR: return "ERROR";
    case SL_STATE_RESET: return "RESET";
    case SL_GROUP_STATE_START: return "START";
    case SL_GROUP_STATE_STOPERROR: return "STOPERROR";
    default: return "?";
    }
}

static void build(void)
{
    int ok = 1;
    memset(&d, 0, sizeof d);
    d.speed1.wInputActive = SL_SPEED_ACTIVE_POSITION;
    d.speed1.tTimeInterval = 50;
    d.speed2 = d.speed1;
    d.compare.wInputActive = 0x0300; /* CompIn1, CompIn2 */
    d.compare.nArchitecture = SL_ARCH_1OO2;
    d.compare.nAllowedDeviation = 50;
    d.compare.tToleranceTime = 100;
    d.limit.wInputActive = SL_LIMIT_ACTIVE_ANALOGIN;
    d.limit.nMinimumValue = -1000;
    d.limit.nMaximumValue = 1000;
    d.sli.wInputActive = SL_SLI_ACTIVE;
    d.sli.nLimitPos = 30;
    d.sli.nLimitNeg = 30;
    d.enable.wInputActive = 0x03;
    ok &= sl_speed_dint_init(&d.speed1) == SL_OK;
    ok &= sl_speed_dint_init(&d.speed2) == SL_OK;
    ok &= sl_compare_dint_init(&d.compare) == SL_OK;
    ok &= sl_limit_dint_init(&d.limit) == SL_OK;
    ok &= sl_sli_dint_init(&d.sli) == SL_OK;
    ok &= sl_and_init(&d.enable) == SL_OK;
    ok &= sl_group_init(&d.g, d.members, MEMBERS, d.links, 5) == SL_OK;
    /* members in execution order */
    ok &= sl_group_add_member(&d.g, d.members, SL_TYPE_SPEED_DINT, &d.speed1, NULL) == SL_OK;
    ok &= sl_group_add_member(&d.g, d.members, SL_TYPE_SPEED_DINT, &d.speed2, NULL) == SL_OK;
    ok &= sl_group_add_member(&d.g, d.members, SL_TYPE_COMPARE_DINT, &d.compare, NULL) == SL_OK;
    ok &= sl_group_add_member(&d.g, d.members, SL_TYPE_LIMIT_DINT, &d.limit, NULL) == SL_OK;
    ok &= sl_group_add_member(&d.g, d.members, SL_TYPE_SLI_DINT, &d.sli, NULL) == SL_OK;
    ok &= sl_group_add_member(&d.g, d.members, SL_TYPE_AND, &d.enable, NULL) == SL_OK;
    /* analog links: the link kind follows from the source field (DINT: SL_LINK_ANALOG32) */
    ok &= sl_group_add_link(&d.g, d.members, d.links, SPEED1, offsetof(FB_SPEED_DINT, nSpeed),
                            COMPARE, offsetof(FB_COMPARE_DINT, nCompIn1)) == SL_OK;
    ok &= sl_group_add_link(&d.g, d.members, d.links, SPEED2, offsetof(FB_SPEED_DINT, nSpeed),
                            COMPARE, offsetof(FB_COMPARE_DINT, nCompIn2)) == SL_OK;
    ok &= sl_group_add_link(&d.g, d.members, d.links, COMPARE, offsetof(FB_COMPARE_DINT, nCompOut),
                            LIMIT, offsetof(FB_LIMIT_DINT, nAnalogIn)) == SL_OK;
    ok &= sl_group_add_link(&d.g, d.members, d.links, LIMIT, offsetof(FB_LIMIT_DINT, bInLimit),
                            ENABLE, offsetof(FB_AND, bAndIn1)) == SL_OK;
    ok &= sl_group_add_link(&d.g, d.members, d.links, COMPARE, offsetof(FB_COMPARE_DINT, bIsValid),
                            ENABLE, offsetof(FB_AND, bAndIn2)) == SL_OK;
    EXPECT(ok, "the group is built");
    d.g.bRun = 1;
}

/* One 10 ms task cycle: the encoders move, the host writes their positions, the group runs;
 * prints a line when `what` is not empty. */
static void cycle(const char *what)
{
    int32_t rc;
    int k;
    for (k = 0; k < 2; k++)
        d.pos[k] = (int32_t)((uint32_t)d.pos[k] + (uint32_t)d.step[k]);
    d.speed1.nPosition = d.pos[0];
    d.speed2.nPosition = d.pos[1];
    d.sli.nPosition = d.pos[0];
    rc = sl_group_cycle(&d.g, d.members, d.links, d.t);
    if (what[0] != '\0') {
        printf("%5lu ms | %6ld %6ld | speed %5ld %5ld | COMPARE %-8s out %5ld | LIMIT %-5s | "
               "SLI %-5s diff %4d | group %-5s | drive %-3s door %-6s | %s",
               (unsigned long)d.t, (long)d.pos[0], (long)d.pos[1], (long)d.speed1.nSpeed,
               (long)d.speed2.nSpeed, sl_state_str(SL_TYPE_COMPARE_DINT, d.compare.nState),
               (long)d.compare.nCompOut, sl_state_str(SL_TYPE_LIMIT_DINT, d.limit.nState),
               sl_state_str(SL_TYPE_SLI_DINT, d.sli.nState), (int)d.sli.nPositionDiff,
               group_state(d.g.nState), d.enable.bAndOut == 1 ? "on" : "off",
               d.sli.bSLIActive == 1 ? "open" : "locked", what);
        if (rc != SL_OK)
            printf(" [%s]", sl_status_str(rc));
        printf("\n");
    }
    d.t += 10;
}

/* One speed interval (50 ms): four cycles without a line, then one with `what`. */
static void interval(const char *what)
{
    int k;
    for (k = 0; k < 4; k++)
        cycle("");
    cycle(what);
}

static void set_step(int32_t s1, int32_t s2)
{
    d.step[0] = s1;
    d.step[1] = s2;
}

int main(void)
{
    int k;
    printf("Two-channel speed monitor: encoders -> SPEED x2 -> COMPARE 1oo2 -> LIMIT -> AND, "
           "SLI standstill window\n\n");
    build();
    cycle("group Run: both channels at 0 agree, COMPARE RUN, drive enabled");
    EXPECT(d.enable.bAndOut == 1, "drive enabled at start");
    set_step(100, 100);
    interval("drive runs at 100 increments per cycle: 500 per 50 ms on both channels");
    set_step(240, 240);
    interval("overspeed: 1,200 per 50 ms > 1,000, LIMIT SAFE (AboveMax), drive off at once");
    EXPECT(d.limit.bAboveMax == 1 && d.enable.bAndOut == 0, "overspeed switches off");
    set_step(100, 100);
    interval("back to 500: LIMIT RUN by itself, drive enabled again");
    EXPECT(d.enable.bAndOut == 1, "drive enabled after the overspeed");
    set_step(100, 60);
    interval("encoder 2's coupling slips: 500 vs 300, COMPARE DELAYOUT (tolerance 100 ms)");
    interval("50 ms later, still within the tolerance: CompOut held, drive enabled");
    EXPECT(d.enable.bAndOut == 1, "drive enabled within the tolerance");
    interval("tolerance over: COMPARE SAFE, IsValid FALSE, drive off");
    EXPECT(d.compare.bIsValid == 0 && d.enable.bAndOut == 0, "COMPARE SAFE switches off");
    set_step(100, 100);
    interval("coupling repaired: the channels agree, COMPARE RUN, drive enabled");
    EXPECT(d.enable.bAndOut == 1, "drive enabled after the repair");
    set_step(0, 0);
    interval("drive stopped: speed 0");
    d.sli.bSLI = 1;
    cycle("operator asks for standstill: SLI latches encoder 1's position, door released");
    EXPECT(d.sli.bSLIActive == 1, "SLI active");
    set_step(3, 3);
    for (k = 0; k < 8; k++)
        cycle("");
    cycle("the axis creeps 3 increments per cycle: 27 within the window of +-30");
    EXPECT(d.sli.nPositionDiff == 27 && d.sli.bSLIActive == 1, "creep within the window");
    set_step(40, 40);
    cycle("a jolt of 40: 67 > 30, SLI ERROR 0x40C1 (4267 vs latch 4200), group stops every block");
    EXPECT(d.sli.nDiagTextId == 0x40C1 && d.g.nState == SL_STATE_ERROR, "SLI error stops the group");
    EXPECT(d.sli.dwDiagPar2 == 4267 && d.sli.dwDiagPar3 == 4200, "message parameters");
    set_step(0, 0);
    d.sli.bSLI = 0;
    cycle("axis held, standstill request withdrawn: ERROR until acknowledged");
    d.g.bErrAck = 1;
    cycle("ErrAck pressed: group RESET");
    d.g.bErrAck = 0;
    cycle("ErrAck released: group RUN, every block starts again, drive enabled");
    EXPECT(d.enable.bAndOut == 1, "drive enabled after the acknowledgement");
    return failures == 0 ? 0 : 1;
}
