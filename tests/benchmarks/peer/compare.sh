#!/usr/bin/env bash
# Peer comparison: bezier-js (npm, under node) against Granota on the curves of curves.json —
# arc length, tight bounding box, closest point — each against an mpmath reference at 40 digits
# (reference.py), error and time side by side, as a markdown table. Not run by CI.
#
#   tests/benchmarks/peer/compare.sh [path/to/granota-cli]     (default: build/bin/granota-cli)
#   REPS=20000 CLI_REPS=50 tests/benchmarks/peer/compare.sh
#
# Times: bezier-js is timed in-process with performance.now() (mean of REPS calls after a
# warm-up; the Bezier object is built inside each call). Granota is timed as a loop of CLI_REPS
# whole `granota-cli analyze|project --json` processes, nothing subtracted: its time is mostly
# process start and JSON output, not the computation (tests/benchmarks/bench_curves.cpp's
# BM_ArcLength, BM_CurveFeatures and BM_ClosestPoint measure the computation itself: when
# granota-bench is next to granota-cli, their medians for its degree-3 curve are printed under
# the table — a different cubic from these, so a scale, not a row of the table).
# Needs node + npm (npm ci is run if node_modules is missing) and python3 with mpmath.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
cli="${1:-$root/build/bin/granota-cli}"
reps="${REPS:-20000}"
cli_reps="${CLI_REPS:-50}"
[ -x "$cli" ] || { echo "error: no granota-cli at $cli (build it, or pass its path)" >&2; exit 2; }
command -v node >/dev/null || { echo "error: node is not installed" >&2; exit 2; }
python3 -c "import mpmath" 2>/dev/null || { echo "error: python3 mpmath is not installed (pip install mpmath)" >&2; exit 2; }
if [ ! -d "$here/node_modules/bezier-js" ]; then
    (cd "$here" && npm ci --no-audit --no-fund >/dev/null)
fi

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
python3 "$here/reference.py" "$here/curves.json" >"$tmp/reference.json"
node "$here/bezier_js.mjs" "$reps" >"$tmp/bezier_js.json"

# Granota: one analyze per curve, one project per point; each repeated cli_reps times for the time.
now_ns() { date +%s%N; }
python3 - "$here/curves.json" >"$tmp/calls.txt" <<'PY'
import json, sys
for i, c in enumerate(json.load(open(sys.argv[1]))["curves"]):
    pts = ";".join(f"{x},{y}" for x, y in c["points"])
    print(f"{i}\tanalyze\t-\t{pts}")
    for j, (x, y) in enumerate(c["project"]):
        print(f"{i}\tproject\t{j}\t{pts}\t{x},{y}")
PY
: >"$tmp/granota.tsv"
while IFS=$'\t' read -r ci kind pj pts at; do
    if [ "$kind" = analyze ]; then args=(analyze --points "$pts" --json); else args=(project --points "$pts" --at "$at" --json); fi
    out="$("$cli" "${args[@]}")"
    t0="$(now_ns)"
    for ((k = 0; k < cli_reps; ++k)); do "$cli" "${args[@]}" >/dev/null; done
    t1="$(now_ns)"
    printf '%s\t%s\t%s\t%s\t%s\n' "$ci" "$kind" "$pj" "$(( (t1 - t0) / cli_reps / 1000 ))" "$out" >>"$tmp/granota.tsv"
done <"$tmp/calls.txt"

python3 - "$here/curves.json" "$tmp/reference.json" "$tmp/bezier_js.json" "$tmp/granota.tsv" "$reps" "$cli_reps" <<'PY'
import json, sys
from mpmath import mp, mpf
mp.dps = 40
spec = json.load(open(sys.argv[1]))["curves"]
ref = json.load(open(sys.argv[2]))["curves"]
bjs = json.load(open(sys.argv[3]))["curves"]
gra = {}
for line in open(sys.argv[4]):
    ci, kind, pj, us, out = line.rstrip("\n").split("\t", 4)
    gra[(int(ci), kind, pj)] = (int(us), json.loads(out))
reps, cli_reps = sys.argv[5], sys.argv[6]

def g(x):
    return f"{float(x):.10g}"

def err(x):
    x = abs(x)
    return "0" if x == 0 else f"{float(x):.1e}"

def box(b):
    return f"[{g(b[0][0])}, {g(b[0][1])}]–[{g(b[1][0])}, {g(b[1][1])}]"

def box_err(b, r):
    return max(abs(mpf(repr(b[i][j])) - mpf(r[i][j])) for i in range(2) for j in range(2))

print("| curve | quantity | reference (mpmath) | bezier-js | error | Granota | error | bezier-js time | Granota time (whole process) |")
print("|---|---|---|---|---|---|---|---|---|")
for i, c in enumerate(spec):
    r, b = ref[i], bjs[i]
    us, a = gra[(i, "analyze", "-")]
    pts = " ".join(f"({x},{y})" for x, y in c["points"])
    name = f"{c['name']} {pts}"
    L = mpf(r["length"])
    print(f"| {name} | length | {g(L)} | {g(b['length'])} | {err((mpf(repr(b['length'])) - L) / L)} rel | "
          f"{g(a['length'])} | {err((mpf(repr(a['length'])) - L) / L)} rel | {b['length_us']:.2f} µs | {us} µs |")
    print(f"| | bbox | {box(r['bbox'])} | {box(b['bbox'])} | {err(box_err(b['bbox'], r['bbox']))} | "
          f"{box(a['bbox'])} | {err(box_err(a['bbox'], r['bbox']))} | {b['bbox_us']:.2f} µs | (same call) |")
    for j, (x, y) in enumerate(c["project"]):
        pr, pb = r["project"][j], b["project"][j]
        us, pg = gra[(i, "project", str(j))]
        t = mpf(pr["t"])
        print(f"| | closest t to ({x}, {y}) | {g(t)} | {g(pb['t'])} | {err(mpf(repr(pb['t'])) - t)} | "
              f"{g(pg['t'])} | {err(mpf(repr(pg['t'])) - t)} | {pb['us']:.2f} µs | {us} µs |")
print()
print(f"Errors: length relative; bbox the largest coordinate error; closest point |t − t*|. "
      f"bezier-js: mean of {reps} in-process calls (node {__import__('subprocess').run(['node', '--version'], capture_output=True, text=True).stdout.strip()}); "
      f"Granota: mean of {cli_reps} whole granota-cli processes (analyze gives length and box in one call), "
      f"so its time is mostly process start.")
PY

bench="$(dirname "$cli")/granota-bench"
if [ -x "$bench" ]; then
    QT_QPA_PLATFORM=offscreen "$bench" --benchmark_filter='BM_(ArcLength|CurveFeatures|ClosestPoint)/3$' \
        --benchmark_repetitions=3 --benchmark_report_aggregates_only=true --benchmark_format=json \
        >"$tmp/bench.json" 2>/dev/null
    python3 - "$tmp/bench.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
scale = {"ns": 1e-3, "us": 1, "ms": 1e3, "s": 1e6}
m = {b["run_name"].split("/")[0]: b["real_time"] * scale[b["time_unit"]]
     for b in d["benchmarks"] if b.get("aggregate_name") == "median"}
def us(name):
    return f"{m[name]:.2f} µs" if name in m else "not measured"
print()
print("Granota in-process (granota-bench, bench_curves.cpp's own wavy cubic, median of 3): "
      f"length {us('BM_ArcLength')} (BM_ArcLength/3), extrema + box + inflections + cusps "
      f"{us('BM_CurveFeatures')} (BM_CurveFeatures/3), closest point {us('BM_ClosestPoint')} "
      "(BM_ClosestPoint/3).")
PY
fi
