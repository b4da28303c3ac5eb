#!/usr/bin/env bash
# Peer comparison for B-splines: Granota (`granota-cli bspline --u … --json`), scipy's
# BSpline (python3-scipy) and verb-nurbs (npm, under node) on the same random floating-point
# curves (bspline_cases.py: seeded; degrees 1–5, clamped and unclamped, polynomial and rational),
# each against exact values (bspline_reference.py: de Boor in Python fractions). Prints one
# markdown table: the largest error of each library and the largest differences between them.
# Not run by CI (tests/test_bspline_peers.cpp is the test against scipy).
#
#   tests/benchmarks/peer/bspline_compare.sh [path/to/granota-cli] [SEED]
#
# Needs node + npm (npm ci is run if node_modules is missing) and a python3 with scipy.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
cli="${1:-$root/build/bin/granota-cli}"
seed="${2:-36}"
[ -x "$cli" ] || { echo "error: no granota-cli at $cli (build it, or pass its path)" >&2; exit 2; }
command -v node >/dev/null || { echo "error: node is not installed" >&2; exit 2; }
py=""
for candidate in python3 /usr/bin/python3; do
    if "$candidate" -c "import scipy" 2>/dev/null; then py="$candidate"; break; fi
done
[ -n "$py" ] || { echo "error: no python3 with scipy (apt-get install python3-scipy)" >&2; exit 2; }
if [ ! -d "$here/node_modules/verb-nurbs" ]; then
    (cd "$here" && npm ci --no-audit --no-fund >/dev/null)
fi

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$py" "$here/bspline_cases.py" "$seed" >"$tmp/cases.json"
"$py" "$here/bspline_reference.py" "$tmp/cases.json" >"$tmp/reference.json"
"$py" "$here/scipy_bspline_eval.py" "$tmp/cases.json" >"$tmp/scipy.json"
(cd "$here" && node verb_nurbs.mjs "$tmp/cases.json" "$tmp/verb.json" >/dev/null)

# Granota: one granota-cli process per case and parameter (the doubles written shortest, so
# that they read back as themselves).
"$py" - "$tmp/cases.json" >"$tmp/calls.txt" <<'PY'
import json, sys
for i, c in enumerate(json.load(open(sys.argv[1]))["cases"]):
    pts = ";".join(f"{x!r},{y!r}" for x, y in c["points"])
    knots = ",".join(repr(k) for k in c["knots"])
    weights = ",".join(repr(w) for w in c.get("weights", [])) or "-"  # no empty field: read would merge the tabs
    for j, u in enumerate(c["u"]):
        print("\t".join([str(i), str(j), str(c["degree"]), pts, knots, weights, repr(u)]))
PY
: >"$tmp/granota.tsv"
while IFS=$'\t' read -r ci uj degree pts knots weights u; do
    args=(bspline --points "$pts" --degree "$degree" --knots "$knots" --u "$u" --json)
    [ "$weights" = - ] || args+=(--weights "$weights")
    printf '%s\t%s\t%s\n' "$ci" "$uj" "$("$cli" "${args[@]}" | tr -d '\n')" >>"$tmp/granota.tsv"
done <"$tmp/calls.txt"

"$py" - "$tmp" "$seed" <<'PY'
import json, subprocess, sys
from fractions import Fraction
tmp, seed = sys.argv[1], sys.argv[2]
cases = json.load(open(f"{tmp}/cases.json"))["cases"]
exact = json.load(open(f"{tmp}/reference.json"))["values"]
scipy = json.load(open(f"{tmp}/scipy.json"))
verb = json.load(open(f"{tmp}/verb.json"))
granota = [[None] * len(c["u"]) for c in cases]
for line in open(f"{tmp}/granota.tsv"):
    ci, uj, out = line.rstrip("\n").split("\t", 2)
    granota[int(ci)][int(uj)] = json.loads(out)["point"]

def err(a, b):
    """Largest coordinate difference over the parameters; None when a library has no value."""
    if any(x is None for x in a) or any(y is None for y in b):
        return None
    return max(abs(Fraction(p) - Fraction(q)) for xa, xb in zip(a, b) for p, q in zip(xa, xb))

def fmt(e):
    return "—" if e is None else ("0" if e == 0 else f"{float(e):.1e}")

print("| case | control points | parameters | Granota error | scipy error | verb error | Granota − scipy | Granota − verb |")
print("|---|---|---|---|---|---|---|---|")
worst = {}
for i, c in enumerate(cases):
    ex = [[Fraction(v) for v in p] for p in exact[i]]
    g, s, v = granota[i], scipy["values"][i], verb["values"][i]
    row = {"Granota": err(g, ex), "scipy": err(s, ex), "verb": err(v, ex),
           "Granota − scipy": err(g, s), "Granota − verb": err(g, v)}
    for k, e in row.items():
        if e is not None:
            worst[k] = max(worst.get(k, 0), e)
    print(f"| {c['name']} | {len(c['points'])} | {len(c['u'])} | " + " | ".join(fmt(e) for e in row.values()) + " |")
print(f"| **largest** | | | " + " | ".join(fmt(worst.get(k)) for k in
      ["Granota", "scipy", "verb", "Granota − scipy", "Granota − verb"]) + " |")
node = subprocess.run(["node", "--version"], capture_output=True, text=True).stdout.strip()
print()
print(f"Seed {seed}. Errors: the largest coordinate difference from the exact value (de Boor in "
      f"Python fractions on the doubles' exact values), over the case's parameters (random ones, "
      f"both ends and every interior knot); control points in [−1, 1]². scipy {scipy['scipy']} "
      f"(a rational curve as its homogeneous B-spline divided by w); verb-nurbs {verb['verb']} "
      f"(node {node}), which accepts clamped knot vectors only (— for the others).")
PY
