#!/usr/bin/env bash
# Every speed target of the project measured in one run, the seed's own program (Annex II
# as Java, SeedFrog.java) as the baseline in the same run; prints the targets table of docs/performance.md.
#   bash tests/benchmarks/targets.sh [BUILD_DIR] [PATH/TO/SeedFrog.java]
# Timings are medians of three repetitions (Google Benchmark) on whatever else the machine
# is doing: compare the ratios, not the absolute numbers of two different runs.
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build}"
seed_java="${2:-../shared/reference/SeedFrog.java}"
export QT_QPA_PLATFORM=offscreen

bench() { # filter → median real time in the unit asked for
  "$build/bin/granota-bench" --benchmark_filter="$1" --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true --benchmark_format=json 2>/dev/null |
    python3 -c 'import json,sys; d=json.load(sys.stdin)
scale={"ns":1,"us":1e3,"ms":1e6,"s":1e9}
for b in d["benchmarks"]:
    if b.get("aggregate_name")=="median": print(b["real_time"]*scale[b["time_unit"]]/scale[sys.argv[1]]); break' "$2"
}

mkdir -p "$build/seedfrog"
javac -d "$build/seedfrog" "$seed_java"
java_ns=$(for i in 1 2 3; do java -cp "$build/seedfrog" SeedFrog 2000000; done |
  sed -n 's/.*ns_per_frog_step=\([0-9.]*\).*/\1/p' | sort -n | sed -n 2p)
seed_ns=$(bench 'BM_FrogStep/seed$' ns)
stable_us=$(bench 'BM_FrogStep/stable$' us)
pile_ms=$(bench 'BM_ManyBodiesPile/1000$' ms)
spread_ms=$(bench 'BM_ManyBodiesSpread/1000$' ms)
outline_us=$(bench 'BM_OutlineFit/3$' us)
fit_ms=$(bench 'BM_FitBezier/1000000/10$' ms)
drag_ms=$(bench 'BM_GuiDragDegree30/1$' ms)
overlays_ms=$(bench 'BM_GuiDragDegree30AllOverlays$' ms)
frogs_ms=$(bench 'BM_GuiFrog200$' ms)
length3_us=$(bench 'BM_ArcLength/3$' us)
length10_us=$(bench 'BM_ArcLength/10$' us)
features_us=$(bench 'BM_CurveFeatures/10$' us)
closest_us=$(bench 'BM_ClosestPoint/10$' us)
# Plain and recorded steps in turns of 10 in one run (bench_many_bodies.cpp): their ratio.
overhead=$("$build/bin/granota-bench" --benchmark_filter='BM_RecordingOverhead/1000/' --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true --benchmark_format=json 2>/dev/null |
    python3 -c 'import json,sys; d=json.load(sys.stdin)
for b in d["benchmarks"]:
    if b.get("aggregate_name")=="median": print(b["recorded_ms"], b["plain_ms"]); break')
recorded_ms=${overhead% *}
plain_ms=${overhead#* }
frogs_plots_ms=$(bench 'BM_GuiFrog200Plots$' ms)
scrub_ms=$(bench 'BM_ScrubBack10000$' ms)
closed_ms=$(bench 'BM_ClosedSpline/100000$' ms)
# The peer: scipy's periodic CubicSpline on the same 10⁵ points (Debian's python3-scipy); nan without it.
scipy_ms=$(/usr/bin/python3 tests/benchmarks/peer/scipy_periodic_spline.py 100000 2>/dev/null || echo nan)

python3 - "$java_ns" "$seed_ns" "$stable_us" "$pile_ms" "$spread_ms" "$outline_us" "$fit_ms" "$drag_ms" "$frogs_ms" "$length3_us" "$length10_us" "$features_us" "$closest_us" "$overlays_ms" "$plain_ms" "$recorded_ms" "$frogs_plots_ms" "$scrub_ms" "$closed_ms" "$scipy_ms" <<'PY'
import sys, platform, subprocess
java, seed, stable, pile, spread, outline, fit, drag, frogs, length3, length10, features, closest, overlays, plain, recorded, frogs_plots, scrub, closed, scipy = map(float, sys.argv[1:])
cpu = next((l.split(':',1)[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')), '?')
print(f"Machine: {cpu}, {subprocess.check_output(['nproc']).decode().strip()} cores; release build.\n")
print("| target | measured | goal | met |")
print("|---|---|---|---|")
rows = [
  ("`seed` frog step vs `java SeedFrog` (same run)", f"{seed:.0f} ns vs {java:.0f} ns: **{java/seed:.1f}×**", "≥ 20×", java/seed >= 20),
  ("1000 colliding frogs, `stable`, piled", f"{pile:.1f} ms/step", "≤ 16 ms, one core", pile <= 16),
  ("1000 frogs, `stable`, spread", f"{spread:.1f} ms/step", "≤ 16 ms, one core", spread <= 16),
  ("per-frame least-squares fit of the outline (§4.9)", f"{outline:.2f} µs", "< 5 µs", outline < 5),
  ("degree-10 fit of 10⁶ points", f"{fit:.0f} ms", "< 100 ms", fit < 100),
  ("drag on a degree-30 curve: recompute + repaint", f"{drag:.1f} ms", "< 16.7 ms (one frame)", drag < 16.7),
  ("the same drag with every overlay on (comb, circle, box, inflections, hodograph…)", f"{overlays:.1f} ms", "< 16.7 ms (one frame)", overlays < 16.7),
  ("200 frogs on the canvas: step + paint", f"{frogs:.1f} ms", "< 16.7 ms (60 fps)", frogs < 16.7),
  ("arc length of a cubic to 1e-13 relative", f"{length3:.2f} µs", "< 1 µs", length3 < 1),
  ("arc length of a degree-10 curve to 1e-13 relative", f"{length10:.2f} µs", "< 5 µs", length10 < 5),
  ("extrema, tight box, inflections and cusps of a degree-10 curve", f"{features:.2f} µs", "< 5 µs", features < 5),
  ("global closest point on a degree-10 curve", f"{closest:.2f} µs", "< 5 µs", closest < 5),
  ("recording and the series on 1000 bodies, `stable` (900 steps, in turns with the plain step)", f"{recorded:.0f} ms vs {plain:.0f} ms: **{100*(recorded/plain-1):+.1f} %**", "≤ +5 %", recorded <= 1.05 * plain),
  ("200 frogs with the plots over time open: step + paint + plot", f"{frogs_plots:.1f} ms", "< 16.7 ms (60 fps)", frogs_plots < 16.7),
  ("a scrub 10 000 steps back (the stable frog)", f"{scrub:.1f} ms", "< 100 ms", scrub < 100),
  ("closed C² spline through 10⁵ points, chord parameters, vs scipy `CubicSpline(bc_type='periodic')` (same run)", f"{closed:.1f} ms vs {scipy:.0f} ms: **{scipy/closed:.1f}×**", "< 50 ms", closed < 50),
  ("one `stable` frog step", f"{stable:.1f} µs", "—", True),
]
for name, got, goal, ok in rows:
    print(f"| {name} | {got} | {goal} | {'yes' if ok else 'no'} |")
PY
