# QUADCOVER_SANITIZE: build everything of ours (Core, the VTK modules, the Python wrapping, the
# command line, the tests, the benchmarks) with GCC's AddressSanitizer and/or
# UndefinedBehaviorSanitizer, e.g.
#   cmake -S . -B build-asan -DQUADCOVER_SANITIZE=address,undefined
# VTK, CHOLMOD, BLAS and Python stay as Debian built them. Our programs need no environment (the
# sanitizers' defaults: a report ends the program with an error, leaks are checked at exit); set
# UBSAN_OPTIONS=print_stacktrace=1 for whole stacks in UBSan's reports.
# Sets QUADCOVER_SANITIZER_PYTHON_ENV, the environment of a test that imports our Python modules
# into the uninstrumented /usr/bin/python3 (empty without ASan).
set(QUADCOVER_SANITIZE "" CACHE STRING
  "Sanitizers to build with: address, undefined or address,undefined (empty: none)")
set(QUADCOVER_SANITIZER_PYTHON_ENV "")
if (NOT QUADCOVER_SANITIZE)
  return ()
endif ()

string(REPLACE "," ";" qc_sanitizers "${QUADCOVER_SANITIZE}")
list(REMOVE_DUPLICATES qc_sanitizers)
foreach (qc_s IN LISTS qc_sanitizers)
  if (NOT qc_s MATCHES "^(address|undefined)$")
    message(FATAL_ERROR "QUADCOVER_SANITIZE: '${qc_s}' is not one of address, undefined")
  endif ()
endforeach ()
# The runtime the Python tests preload and the flags below are GCC's; Clang links its runtimes
# differently (statically into executables only), which the test environment does not handle.
if (NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU" OR NOT CMAKE_C_COMPILER_ID STREQUAL "GNU")
  message(FATAL_ERROR "QUADCOVER_SANITIZE is set up for GCC, not ${CMAKE_CXX_COMPILER_ID}")
endif ()
list(JOIN qc_sanitizers "," qc_list)

# Frame pointers give the reports whole stacks at little cost. Undefined behaviour stops the
# program (as an address error does) so that a test cannot pass over a report.
set(qc_flags "-fsanitize=${qc_list}" -fno-omit-frame-pointer)
if ("undefined" IN_LIST qc_sanitizers)
  list(APPEND qc_flags -fno-sanitize-recover=undefined)
endif ()
# Directory-wide, before any of our targets exists: every target below this folder gets them,
# the VTK modules' and the wrapping's included.
add_compile_options(${qc_flags})
add_link_options("-fsanitize=${qc_list}")

if ("address" IN_LIST qc_sanitizers)
  # An instrumented library loaded into an uninstrumented program needs the ASan runtime loaded
  # first, before libc's malloc is in use: the Python tests preload it. libstdc++ is preloaded
  # with it because python3 does not link it: ASan looks up the real __cxa_throw when it starts,
  # and without libstdc++ loaded by then the first C++ exception aborts the interpreter ("CHECK
  # failed: ... real___cxa_throw"). CPython and VTK's wrapping keep objects alive until exit by
  # design, so leak checking is off inside the interpreter only; our programs (the tests, the
  # command line, also when Python starts them) keep the default, leak checking on.
  set(qc_preload "")
  foreach (qc_lib libasan.so libstdc++.so)
    execute_process(COMMAND "${CMAKE_CXX_COMPILER}" "-print-file-name=${qc_lib}"
      OUTPUT_VARIABLE qc_path OUTPUT_STRIP_TRAILING_WHITESPACE)
    if (NOT IS_ABSOLUTE "${qc_path}" OR NOT EXISTS "${qc_path}")
      message(FATAL_ERROR "QUADCOVER_SANITIZE: ${CMAKE_CXX_COMPILER} has no ${qc_lib}")
    endif ()
    list(APPEND qc_preload "${qc_path}")
  endforeach ()
  list(JOIN qc_preload ":" qc_preload)
  set(QUADCOVER_SANITIZER_PYTHON_ENV "LD_PRELOAD=${qc_preload}" "ASAN_OPTIONS=detect_leaks=0")
endif ()
message(STATUS "QuadCover: sanitizers ${qc_list} (${qc_flags})")
