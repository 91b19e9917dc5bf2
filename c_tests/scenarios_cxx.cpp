// The C scenario sources compiled as C++17 (-std=c++17 -Wall -Wextra -Werror -pedantic):
// one translation unit that includes every scenario file, so the header and the harness
// are exercised through a C++ compiler and C++ name lookup, linked against the C ABI.
#include "test_api.c"  // first: it sets _POSIX_C_SOURCE before any system header
#include "test_main.c"
#include "test_estop.c"
#include "test_mon.c"
#include "test_group.c"
#include "test_logic.c"
#include "test_opmode.c"
#include "test_twohand.c"
#include "test_muting.c"
#include "test_edm.c"
#include "test_flipflop.c"
#include "test_timers.c"
#include "test_arith.c"
#include "test_scale_speed.c"
#include "test_sli.c"
#include "test_loadsensing.c"
#include "test_envelope.c"
#include "test_fsoe.c"
#include "test_slp.c"
#include "test_sbt.c"
#include "test_advposmon.c"
