#!/usr/bin/env bash
# Runs every fuzz target (or those named) for SECONDS each, two at a time on two cores; `make fuzz` calls it.
#   tests/fuzz/run-fuzzers.sh SECONDS [replies json tbl csv gcode job emulator lines rows frames beacon]
# SECONDS 0 runs each target over its folder once and stops: a check, the same every time, that CI runs.
# Each target starts from its seeds in tests/fuzz/<name>/ and grows a working corpus in build-fuzz/corpus/.
# Whatever breaks a target is left in build-fuzz/artifacts/<name>/: copy it into tests/fuzz/<name>/ (it then
# replays in `make test`), fix the code, run again.
set -uo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:?usage: run-fuzzers.sh SECONDS [TARGET...]}
shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(replies json tbl csv gcode job emulator lines rows frames beacon)
build=build-fuzz
jobs=$(nproc)

run_one() {
    local name=$1 seconds=$2 build=$3
    mkdir -p "$build/corpus/$name" "$build/artifacts/$name" "$build/logs"
    # Leak checks off: Qt keeps caches for the life of the process, which LeakSanitizer would report on
    # every input. A hang of more than 10 s on one input counts as a failure.
    local how=(-max_total_time="$seconds")
    [ "$seconds" != 0 ] || how=(-runs=0) # libFuzzer's -max_total_time=0 would mean "for ever"
    ASAN_OPTIONS=detect_leaks=0 "$build/fuzz/fuzz-$name" "$build/corpus/$name" "tests/fuzz/$name" \
        -dict="tests/fuzz/$name.dict" "${how[@]}" -timeout=10 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$build/artifacts/$name/" > "$build/logs/$name.log" 2>&1
    echo "$name $?"
}
export -f run_one

if [ "$seconds" = 0 ]; then
    echo "running ${targets[*]} once over their corpora; logs in $build/logs/"
else
    echo "fuzzing ${targets[*]} for $seconds s each, $jobs at a time; logs in $build/logs/"
fi
results=$(printf '%s\n' "${targets[@]}" | xargs -P "$jobs" -I{} bash -c "run_one {} $seconds $build")

status=0
printf '%-8s %12s %10s %8s %10s  %s\n' target runs 'runs/s' edges corpus result
for name in "${targets[@]}"; do
    log=$build/logs/$name.log
    code=$(awk -v n="$name" '$1 == n { print $2 }' <<< "$results")
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    edges=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
    corpus=$(grep -o 'corp: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2) # inputs that each add coverage
    found=$(find "$build/artifacts/$name" -type f | sort)
    if [ "$code" = 0 ] && [ -z "$found" ]; then
        result=clean
    else
        result="FAILED (exit $code): ${found:-see $log}"
        status=1
    fi
    printf '%-8s %12s %10s %8s %10s  %s\n' "$name" "${runs:-?}" "${rate:-?}" "${edges:-?}" "$corpus" "$result"
done
if [ $status != 0 ]; then
    echo "A target broke. Copy each input named above into tests/fuzz/<target>/, fix the code, run again."
fi
exit $status
