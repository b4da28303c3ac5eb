// The peer side of the comparison (compare.sh): bezier-js's length(), bbox() and project()
// on the curves of curves.json, each timed over many repetitions with performance.now().
// Prints one line of JSON. Not run by CI.
import { Bezier } from "bezier-js";
import { readFileSync } from "node:fs";
import { performance } from "node:perf_hooks";

const here = new URL(".", import.meta.url);
const spec = JSON.parse(readFileSync(new URL("curves.json", here), "utf8"));
const reps = Number(process.argv[2] ?? 20000);

// Mean time of one call in microseconds; a warm-up run first so the JIT has compiled f.
function time(f) {
  let sink = 0;
  for (let i = 0; i < 1000; ++i) sink += f() ? 1 : 0;
  const t0 = performance.now();
  for (let i = 0; i < reps; ++i) sink += f() ? 1 : 0;
  const t1 = performance.now();
  if (sink < 0) console.error(sink);
  return ((t1 - t0) * 1000) / reps;
}

const out = [];
for (const c of spec.curves) {
  const pts = c.points.map(([x, y]) => ({ x, y }));
  const make = () => new Bezier(pts);
  const b = make();
  const box = b.bbox();
  const r = {
    name: c.name,
    length: b.length(),
    length_us: time(() => make().length()),
    bbox: [[box.x.min, box.y.min], [box.x.max, box.y.max]],
    bbox_us: time(() => make().bbox()),
    project: [],
  };
  for (const [x, y] of c.project) {
    const p = b.project({ x, y });
    r.project.push({ at: [x, y], t: p.t, point: [p.x, p.y], distance: p.d,
                     us: time(() => make().project({ x, y })) });
  }
  out.push(r);
}
console.log(JSON.stringify({ library: "bezier-js", reps, curves: out }));
