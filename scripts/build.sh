#!/usr/bin/env bash
# Configure and build (Release) into build/. Binaries land in build/bin/.
#   scripts/build.sh --sanitize   the sanitizer build instead, into build-san/:
#                                 clang, ASan + UBSan (-fno-sanitize-recover),
#                                 the libFuzzer harnesses, the CLI and the
#                                 benches on the uninstrumented Verilated RTL
#                                 (docs/verification.md "Sanitizers")
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh"
jobs=$(nproc)
if [ "${1:-}" = "--sanitize" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S "$here" -B "$here/build-san" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DSC_SANITIZE=ON -DSC_FUZZ=ON \
    -DSCURVE_HOST_EXECUTABLE=ON >/dev/null
  # Only what its tests run (not the benchmarks or the nightly-size tests).
  cmake --build "$here/build-san" -j"$jobs" --target scurve_host_tests scurve_board_link_tests scurve_host_main plan_digest san_model_tests \
    parser_tests tools_tests scurve sc_bench fuzz_scenario_json fuzz_stream_json fuzz_regress_list fuzz_regress_results fuzz_kin_trace fuzz_fst_trace \
    fuzz_uart_response
  exit 0
fi
cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$here/build" -j"$jobs"
