# Checks on built test binaries, run by ctest as `cmake -DMODE=... -DBINARY=... -P this`.
#
#   MODE=asan           the binary is instrumented: `nm` lists __asan_init and UBSan handlers
#   MODE=shared         the binary needs libsafelogic.so.0 (the SONAME) at run time (DT_NEEDED),
#                       with an RPATH/RUNPATH to RPATH_DIR
#   MODE=static         the binary contains the library (defines sl_estop_cycle) and does
#                       not need libsafelogic.so
#   MODE=deterministic  two runs exit 0 and print exactly the same output
cmake_minimum_required(VERSION 3.16)

if(NOT DEFINED BINARY OR NOT EXISTS "${BINARY}")
  message(FATAL_ERROR "BINARY not set or missing: '${BINARY}'")
endif()

if(MODE STREQUAL "asan")
  if(NOT NM)
    find_program(NM nm REQUIRED)
  endif()
  execute_process(COMMAND "${NM}" "${BINARY}" OUTPUT_VARIABLE syms RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${BINARY}: ${rc}")
  endif()
  if(NOT syms MATCHES "__asan_init")
    message(FATAL_ERROR "${BINARY} is not built with AddressSanitizer (no __asan_init)")
  endif()
  if(NOT syms MATCHES "__ubsan_handle_")
    message(FATAL_ERROR "${BINARY} is not built with UndefinedBehaviorSanitizer")
  endif()
  message(STATUS "${BINARY}: __asan_init and __ubsan_handle_* present")

elseif(MODE STREQUAL "shared" OR MODE STREQUAL "static")
  if(NOT READELF)
    find_program(READELF readelf REQUIRED)
  endif()
  execute_process(COMMAND "${READELF}" -d "${BINARY}" OUTPUT_VARIABLE dyn RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${READELF} -d failed on ${BINARY}: ${rc}")
  endif()
  if(MODE STREQUAL "shared")
    # the library's SONAME: NEEDED is libsafelogic.so.0, not the unversioned dev name
    if(NOT dyn MATCHES "NEEDED[^\n]*\\[libsafelogic\\.so\\.0\\]")
      message(FATAL_ERROR "${BINARY} does not need libsafelogic.so.0:\n${dyn}")
    endif()
    if(NOT dyn MATCHES "(RPATH|RUNPATH)[^\n]*${RPATH_DIR}")
      message(FATAL_ERROR "${BINARY} has no RPATH/RUNPATH to ${RPATH_DIR}:\n${dyn}")
    endif()
    message(STATUS "${BINARY}: NEEDED libsafelogic.so.0, RPATH set")
  else()
    if(dyn MATCHES "libsafelogic")
      message(FATAL_ERROR "${BINARY} should link libsafelogic statically:\n${dyn}")
    endif()
    execute_process(COMMAND "${READELF}" -sW "${BINARY}" OUTPUT_VARIABLE syms)
    if(NOT syms MATCHES "FUNC[^\n]* sl_estop_cycle\n")
      message(FATAL_ERROR "${BINARY} does not define sl_estop_cycle")
    endif()
    message(STATUS "${BINARY}: library linked in statically")
  endif()

elseif(MODE STREQUAL "deterministic")
  execute_process(COMMAND "${BINARY}" OUTPUT_VARIABLE out1 RESULT_VARIABLE rc1)
  execute_process(COMMAND "${BINARY}" OUTPUT_VARIABLE out2 RESULT_VARIABLE rc2)
  if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0)
    message(FATAL_ERROR "${BINARY} exited with ${rc1} / ${rc2}")
  endif()
  if(NOT out1 STREQUAL out2)
    message(FATAL_ERROR "${BINARY}: two runs printed different output")
  endif()
  string(LENGTH "${out1}" n)
  message(STATUS "${BINARY}: two runs, identical output (${n} bytes)")

else()
  message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()
