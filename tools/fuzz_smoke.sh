#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) in build-fuzz/ and
# runs each for FUZZ_SECONDS (default 20) from its seed corpus. Skips when
# clang or its fuzzer runtime is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang++ >/dev/null || ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, long){return 0;}' |
     clang++ -x c++ -fsanitize=fuzzer - -o /dev/null 2>/dev/null; then
  echo "fuzz smoke: skipped (clang with libFuzzer not available)"
  exit 0
fi
SECONDS_PER_TARGET=${FUZZ_SECONDS:-20}
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLINEMAP_FUZZ=ON -DLINEMAP_BUILD_TOOLS=OFF >/dev/null
targets=$(cd tests/fuzz && ls fuzz_*.cc | sed 's/\.cc$//')
cmake --build build-fuzz -j"$(nproc)" --target $targets
for t in $targets; do
  name=${t#fuzz_}
  work=build-fuzz/corpus-$name
  mkdir -p "$work"
  echo "== $t for ${SECONDS_PER_TARGET}s"
  build-fuzz/tests/fuzz/$t -max_total_time="$SECONDS_PER_TARGET" -rss_limit_mb=2048 \
    -print_final_stats=1 "$work" tests/fuzz/corpus/$name 2>&1 | grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)|ERROR|SUMMARY" || true
  test "${PIPESTATUS[0]}" -eq 0
done
