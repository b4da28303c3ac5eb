# Sourced by .ci/setup and .ci/run: named stages that each run to their end, whatever the
# ones before them did, and one summary line per stage with its time (docs/ci.md).
#   stage NAME [--needs OTHER] -- COMMAND…   runs COMMAND (in `bash -eo pipefail -c` when it
#                                            is one string); with --needs, only if OTHER passed
#   stage_summary                            prints every stage's line, then "stages: N passed,
#                                            N failed, N skipped"; non-zero if any failed or
#                                            was skipped
# The lines are kept in $GRANOTA_STAGE_SUMMARY, so that .ci/run can add its own stages to
# those of .ci/setup and print them all at the end.
: "${GRANOTA_STAGE_SUMMARY:=$(mktemp "${TMPDIR:-/tmp}/granota-stages.XXXXXX")}"
export GRANOTA_STAGE_SUMMARY

stage() {
  local name="$1" needs=""
  shift
  if [ "${1:-}" = "--needs" ]; then needs="$2"; shift 2; fi
  [ "${1:-}" = "--" ] && shift
  if [ -n "$needs" ] && ! grep -qxF "$needs" "$GRANOTA_STAGE_SUMMARY.passed" 2>/dev/null; then
    printf '%-7s %6s  %s\n' skipped "-" "$name (needs: $needs)" >>"$GRANOTA_STAGE_SUMMARY"
    echo "=== $name: skipped, '$needs' did not pass"
    return 0
  fi
  echo "=== $name"
  local start status=0
  start=$(date +%s)
  if [ $# -eq 1 ]; then
    bash -eo pipefail -c "$1" || status=$?
  else
    "$@" || status=$?
  fi
  local took=$(($(date +%s) - start)) word=ok
  if [ "$status" -ne 0 ]; then word=FAILED; else echo "$name" >>"$GRANOTA_STAGE_SUMMARY.passed"; fi
  printf '%-7s %5ds  %s\n' "$word" "$took" "$name" >>"$GRANOTA_STAGE_SUMMARY"
  echo "=== $name: $word (exit $status) in $took s"
  return 0
}

stage_summary() {
  local passed failed skipped
  passed=$(grep -c '^ok ' "$GRANOTA_STAGE_SUMMARY" || true)
  failed=$(grep -c '^FAILED ' "$GRANOTA_STAGE_SUMMARY" || true)
  skipped=$(grep -c '^skipped ' "$GRANOTA_STAGE_SUMMARY" || true)
  echo
  echo "=== stages (status, time, stage)"
  cat "$GRANOTA_STAGE_SUMMARY"
  echo "stages: $passed passed, $failed failed, $skipped skipped"
  [ "$failed" -eq 0 ] && [ "$skipped" -eq 0 ]
}
