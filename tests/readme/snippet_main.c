/* Driver for the C snippet of docs/c-integration.md ("A task"), which tools/check_readme_snippet.sh
 * extracts to build/readme/snippet.c. Valid C11 and C++17: both builds link the snippet with
 * this file and run it. It plays the machine: emergency-stop switch S1 (two channels),
 * contactor K with feedback (EDM1: TRUE while K is released), restart button S2. */
#include <stdint.h>
#include <stdio.h>

int32_t task_init(void);
void task_cycle(uint8_t s1a, uint8_t s1b, uint8_t k_fb, uint8_t s2, uint8_t run, uint8_t ack);
void set_contactors(uint8_t on);

static uint8_t k_on;
static unsigned cycles_on;

void set_contactors(uint8_t on)
{
    k_on = on;
    if (on) {
        cycles_on++;
    }
}

int main(void)
{
    int k;
    unsigned on_before_press;
    if (task_init() != 0) {
        printf("task_init failed\n");
        return 1;
    }
    /* S1 released, restart pressed and released: the outputs switch on */
    for (k = 0; k < 20; k++) {
        uint8_t s2 = (uint8_t)(k >= 5 && k < 8);
        task_cycle(1, 1, (uint8_t)!k_on, s2, 1, 0);
    }
    if (cycles_on == 0) {
        printf("the outputs never switched on\n");
        return 1;
    }
    /* S1 pressed: off at once */
    task_cycle(0, 0, (uint8_t)!k_on, 0, 1, 0);
    on_before_press = cycles_on;
    for (k = 0; k < 5; k++) {
        task_cycle(0, 0, (uint8_t)!k_on, 0, 1, 0);
    }
    if (k_on || cycles_on != on_before_press) {
        printf("the outputs stayed on with S1 pressed\n");
        return 1;
    }
    printf("README snippet: outputs on for %u cycles, off with S1 pressed\n", cycles_on);
    return 0;
}
