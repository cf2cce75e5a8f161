// Shared helpers for the JavaScript adapters: our shapes' corners, and the pieces every
// reproducer is made of (values written as their exact bits, the answer line the judge reads).
'use strict';

// The four corners of an OBB (cx cy hx hy ux uy), counter-clockwise, computed in double.
function obbCorners(v) {
  const [cx, cy, hx, hy, ux, uy] = v;
  const ex = [ux * hx, uy * hx];
  const ey = [-uy * hy, ux * hy];
  return [
    [cx - ex[0] - ey[0], cy - ex[1] - ey[1]],
    [cx + ex[0] - ey[0], cy + ex[1] - ey[1]],
    [cx + ex[0] + ey[0], cy + ex[1] + ey[1]],
    [cx - ex[0] + ey[0], cy - ex[1] + ey[1]],
  ];
}

// The corners of an AABB (minx miny maxx maxy), counter-clockwise: exact.
function aabbCorners(v) {
  const [x0, y0, x1, y1] = v;
  return [
    [x0, y0],
    [x1, y0],
    [x1, y1],
    [x0, y1],
  ];
}

// A polygon's values as points.
function points(values) {
  const out = [];
  for (let i = 0; i + 1 < values.length; i += 2) out.push([values[i], values[i + 1]]);
  return out;
}

function polygonOf(pts) {
  return { kind: 'polygon', values: pts.flat() };
}

// The exact bits of a double, as 16 hex digits.
function bitsOf(x) {
  const b = Buffer.alloc(8);
  b.writeDoubleLE(x, 0);
  return b.readBigUInt64LE(0).toString(16).padStart(16, '0');
}

// `v('3ff8000000000000') /* 1.5 */`: the value, exactly, in a reproducer's source.
function lit(x) {
  return `v('${bitsOf(x)}') /* ${x} */`;
}

// The head of every JavaScript reproducer: what it shows, how to run it, and v().
function prelude(library, version, what) {
  return `// ${what}
// Standalone: npm install ${library}@${version}, then node this-file.js
// Prints the library's answer (first line) beside the exact one, computed in exact rational
// arithmetic on the geometry the library stores.
'use strict';
function v(bits) {
  const b = Buffer.alloc(8);
  b.writeBigUInt64LE(BigInt('0x' + bits), 0);
  return b.readDoubleLE(0);
}
`;
}

// The closing lines: print the library's answer and the exact one.
function report(overlapExpr, pushExpr, exact) {
  return `try {
  const overlap = ${overlapExpr};
  const push = overlap ? ${pushExpr || 'null'} : null;
  console.log('library: overlap ' + overlap + (push ? ' push ' + push[0] + ' ' + push[1] : ''));
} catch (e) {
  console.log('library: threw ' + (e && e.message ? e.message : e));
}
console.log('exact:   ' + ${JSON.stringify(exact)});
`;
}

// The closing lines of a containment reproducer: the library's answer and the exact one.
function reportContains(insideExpr, exact) {
  return `try {
  console.log('library: contains ' + (${insideExpr}));
} catch (e) {
  console.log('library: threw ' + (e && e.message ? e.message : e));
}
console.log('exact:   ' + ${JSON.stringify(exact)});
`;
}

// The installed version of a package (read from its package.json, which some packages do not
// export to require()).
function packageVersion(name) {
  const fs = require('fs');
  const path = require('path');
  let dir = path.dirname(require.resolve(name));
  while (!fs.existsSync(path.join(dir, 'package.json')) || path.basename(dir) === 'dist') dir = path.dirname(dir);
  return JSON.parse(fs.readFileSync(path.join(dir, 'package.json'), 'utf8')).version;
}

// The points in counter-clockwise order (reversed when their signed area is negative).
function ccw(pts) {
  let area = 0;
  for (let i = 0; i < pts.length; i++) {
    const [x0, y0] = pts[i];
    const [x1, y1] = pts[(i + 1) % pts.length];
    area += x0 * y1 - x1 * y0;
  }
  return area < 0 ? pts.slice().reverse() : pts;
}

module.exports = { packageVersion, obbCorners, aabbCorners, points, polygonOf, lit, prelude, report, reportContains, ccw };
