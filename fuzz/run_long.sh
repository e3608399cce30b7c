#!/bin/bash
# Runs every libFuzzer target of a -DSPIRA_FUZZ=ON build (docs/fuzzing.md) for EXECUTIONS inputs each
# and prints one line per target. Usage: fuzz/run_long.sh BUILD_DIR [EXECUTIONS] [TARGET...]
set -u
build=${1:?usage: fuzz/run_long.sh BUILD_DIR [EXECUTIONS] [TARGET...]}
runs=${2:-1000000}
shift $(( $# >= 2 ? 2 : 1 ))
here=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=($(ls "$here/targets" | sed -n 's/\.cpp$//p'))
fi
work=${FUZZ_WORK:-$(mktemp -d)}
status=0
for t in "${targets[@]}"; do
  bin="$build/fuzz/fuzz_$t"
  [ -x "$bin" ] || { echo "$t: no $bin (build the 'fuzz' target with -DSPIRA_FUZZ=ON)"; status=1; continue; }
  mkdir -p "$work/$t/corpus" "$work/$t/findings"
  inputs=("$here/corpus/$t")
  [ -d "$here/regressions/$t" ] && inputs+=("$here/regressions/$t")
  [ "$t" = ply ] || [ "$t" = obj ] && inputs+=("$here/../tests/data/hostile/$t")
  [ "$t" = step_front ] && inputs+=("$here/../tests/data/hostile/step")
  start=$(date +%s)
  (cd "$work/$t/findings" && "$bin" -runs="$runs" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
      -print_final_stats=1 "$work/$t/corpus" "${inputs[@]}") > "$work/$t/log" 2>&1
  rc=$?
  seconds=$(( $(date +%s) - start ))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t/log")
  cov=$(grep -o 'cov: [0-9]*' "$work/$t/log" | tail -1)
  ft=$(grep -o 'ft: [0-9]*' "$work/$t/log" | tail -1)
  corp=$(grep -o 'corp: [0-9]*/[0-9a-zA-Z]*' "$work/$t/log" | tail -1)
  findings=$(ls "$work/$t/findings" | wc -l)
  echo "$t: exit $rc, ${execs:-?} executions in ${seconds} s, ${cov:-cov: ?}, ${ft:-ft: ?}, ${corp:-corp: ?}, $findings finding(s) (log: $work/$t/log)"
  [ $rc -eq 0 ] && [ "$findings" -eq 0 ] || status=1
done
exit $status
