// Evaluates B-spline curves with verb-nurbs (npm, pinned in package.json), under node.
//   node verb_nurbs.mjs CASES.json OUT.json
// Reads {"cases": [{"degree", "knots", "points", "weights"?, "u"}]} and writes
// {"verb": version, "values": [[[x, y] | null for each u] for each case]} to OUT.json (verb
// prints its version on stdout when loaded, so the results go to a file). verb accepts only
// clamped knot vectors (p + 1 equal knots at each end): an unclamped case gets null values
// and its "error".
// The ES build: verb.js (the package's "main") reads `window`, which node does not have.
import verb from "verb-nurbs/build/js/verb.es.js";
import { readFileSync, writeFileSync } from "node:fs";

const [casesPath, outPath] = process.argv.slice(2);
const { cases } = JSON.parse(readFileSync(casesPath, "utf8"));
const results = cases.map((c) => {
    const weights = c.weights ?? c.points.map(() => 1);
    try {
        const curve = verb.geom.NurbsCurve.byKnotsControlPointsWeights(c.degree, c.knots, c.points, weights);
        return { values: c.u.map((u) => curve.point(u)) };
    } catch (e) {
        return { values: c.u.map(() => null), error: String(e.value ?? e) };
    }
});
writeFileSync(outPath, JSON.stringify({ verb: "3.0.3", values: results.map((r) => r.values), errors: results.map((r) => r.error ?? null) }));
