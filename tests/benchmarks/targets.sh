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
# B-splines (bench_bsplines.cpp): a cubic with 10⁴ control points at 10⁶ parameters, Granota
# and Eigen's Splines module in the same binary (in turns), scipy's BSpline on the same data in the same
# run (peer/scipy_bspline.py, median of 3; "nan" when no python3 has scipy): another process, so
# compared in CPU time, which the load of a shared machine changes far less than real time; exact
# de Boor at degree 10.
# bsplinePoint, Eigen and bsplinePoints in turns of 10⁴ parameters in one benchmark, so that the load falls on all three.
turns=$("$build/bin/granota-bench" --benchmark_filter='BM_BSplineEvaluateInTurns$' --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true --benchmark_format=json 2>/dev/null |
    python3 -c 'import json,sys; d=json.load(sys.stdin)
for b in d["benchmarks"]:
    if b.get("aggregate_name")=="median": print(b["granota_ms"], b["eigen_ms"], b["sampled_ms"]); break')
read -r bspline_ms eigen_ms sampled_ms <<<"$turns"
bspline_cpu_ms=$("$build/bin/granota-bench" --benchmark_filter='BM_BSplineEvaluateGranota$' --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true --benchmark_format=json 2>/dev/null |
    python3 -c 'import json,sys; d=json.load(sys.stdin)
scale={"ns":1e-6,"us":1e-3,"ms":1,"s":1e3}
for b in d["benchmarks"]:
    if b.get("aggregate_name")=="median": print(b["cpu_time"]*scale[b["time_unit"]]); break')
scipy_ms=nan
scipy_cpu_ms=nan
for py in python3 /usr/bin/python3; do
  if "$py" -c 'import scipy' 2>/dev/null; then
    read -r scipy_ms scipy_cpu_ms < <("$py" tests/benchmarks/peer/scipy_bspline.py |
      python3 -c 'import json,sys; d=json.load(sys.stdin); print(d["median_ms"], d["median_cpu_ms"])')
    break
  fi
done
exact10_ms=$(bench 'BM_DeBoorExact/10$' ms)
bspline_drag_ms=$(bench 'BM_GuiBSplineDrag1000$' ms)

closed_ms=$(bench 'BM_ClosedSpline/100000$' ms)
# The peer: scipy's periodic CubicSpline on the same 10⁵ points (Debian's python3-scipy); nan without it.
scipy_closed_ms=$(/usr/bin/python3 tests/benchmarks/peer/scipy_periodic_spline.py 100000 2>/dev/null || echo nan)

python3 - "$java_ns" "$seed_ns" "$stable_us" "$pile_ms" "$spread_ms" "$outline_us" "$fit_ms" "$drag_ms" "$frogs_ms" "$length3_us" "$length10_us" "$features_us" "$closest_us" "$overlays_ms" "$plain_ms" "$recorded_ms" "$frogs_plots_ms" "$scrub_ms" "$bspline_ms" "$eigen_ms" "$scipy_ms" "$exact10_ms" "$sampled_ms" "$bspline_cpu_ms" "$scipy_cpu_ms" "$closed_ms" "$scipy_closed_ms" "$bspline_drag_ms" <<'PY'
import math, sys, platform, subprocess
java, seed, stable, pile, spread, outline, fit, drag, frogs, length3, length10, features, closest, overlays, plain, recorded, frogs_plots, scrub, bspline, eigen, scipy, exact10, sampled, bspline_cpu, scipy_cpu, closed, scipy_closed, bspline_drag = map(float, sys.argv[1:])
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
  ("cubic B-spline, 10⁴ control points, at 10⁶ parameters: `bsplinePoint` vs Eigen's Splines (same binary, in turns)", f"{bspline:.0f} ms vs {eigen:.0f} ms: Granota / Eigen **{bspline/eigen:.2f}**", "< 1", bspline < eigen),
  ("the same sampled by `bsplinePoints` (the span carried from one parameter to the next) vs Eigen (in turns)", f"{sampled:.0f} ms vs {eigen:.0f} ms: Granota / Eigen **{sampled/eigen:.2f}**", "< 1", sampled < eigen),
  ("`bsplinePoint` against scipy's `BSpline.__call__` (same run, CPU time; real time in brackets)", f"{bspline_cpu:.0f} ms vs {scipy_cpu:.0f} ms ({bspline:.0f} vs {scipy:.0f} ms): Granota / scipy **{bspline_cpu/scipy_cpu:.2f}**" if not math.isnan(scipy) else "scipy not installed", "< 1", bspline_cpu < scipy_cpu if not math.isnan(scipy) else None),
  ("exact de Boor (rationals), degree 10: every level of the net", f"{exact10:.3f} ms", "< 5 ms", exact10 < 5),
  ("drag on a 1000-point cubic B-spline, net and basis plot shown: recompute + repaint of canvas and plot", f"{bspline_drag:.1f} ms", "< 16.7 ms (one frame)", bspline_drag < 16.7),
  ("closed C² spline through 10⁵ points, chord parameters, vs scipy `CubicSpline(bc_type='periodic')` (same run)", f"{closed:.1f} ms vs {scipy_closed:.0f} ms: **{scipy_closed/closed:.1f}×**" if not math.isnan(scipy_closed) else f"{closed:.1f} ms (scipy not installed)", "< 50 ms", closed < 50),
  ("one `stable` frog step", f"{stable:.1f} µs", "—", True),
]
for name, got, goal, ok in rows:
    print(f"| {name} | {got} | {goal} | {'—' if ok is None else 'yes' if ok else 'no'} |")
PY
