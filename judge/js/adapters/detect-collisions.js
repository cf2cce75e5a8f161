// detect-collisions (now a re-export of check2d): System.checkCollision(a, b, response) on
// bodies inserted into a System. Read: README.md of check2d (bodies, system.insert, checks),
// dist/system.js (checkCollision: convex pairs go to SAT.js's tests; non-convex bodies are
// decomposed and the pieces' overlapV summed), dist/utils.js (getSATTest maps to SAT.js),
// dist/bodies/polygon.js (isConvex from its decomposition). Touching and the push vector are
// SAT.js's: touching overlaps; subtracting response.overlapV from a's position separates. No
// tolerance documented: the band is the rounding of double arithmetic. Containment: the exported
// pointInPolygon(point, polygon) (dist/intersect.js: SAT.js's pointInPolygon on each convex part,
// a 1e-6 probe box) for polygons; circles have no exported point test (not asked).
'use strict';
const DC = require('detect-collisions');
const { packageVersion, obbCorners, aabbCorners, points, lit, prelude, report, reportContains } = require('../common.js');

const version = packageVersion('detect-collisions');
const check2d = packageVersion('check2d');

function corners(s) {
  if (s.kind === 'aabb') return aabbCorners(s.values);
  if (s.kind === 'obb') return obbCorners(s.values);
  return points(s.values);
}

function build(s) {
  if (s.kind === 'circle') return new DC.Circle({ x: s.values[0], y: s.values[1] }, s.values[2]);
  return new DC.Polygon(
    { x: 0, y: 0 },
    corners(s).map(([x, y]) => ({ x, y })),
  );
}

function stored(s, body) {
  if (s.kind === 'circle') return { kind: 'circle', values: [body.pos.x, body.pos.y, body.r] };
  return { kind: 'polygon', values: body.calcPoints.flatMap((p) => [p.x + body.pos.x, p.y + body.pos.y]) };
}

function answer(a, b) {
  if (a.kind === 'capsule' || b.kind === 'capsule') return { unsupported: true };
  const system = new DC.System();
  const A = build(a);
  const B = build(b);
  system.insert(A);
  system.insert(B);
  const overlap = system.checkCollision(A, B);
  const r = system.response;
  return {
    overlap,
    push: overlap ? [r.overlapV.x, r.overlapV.y] : null,
    storedA: stored(a, A),
    storedB: stored(b, B),
  };
}

function contains(s, p) {
  if (s.kind === 'capsule' || s.kind === 'circle') return { unsupported: true };
  const A = build(s);
  return { inside: DC.pointInPolygon({ x: p[0], y: p[1] }, A), stored: stored(s, A), point: p };
}

function source(s, name) {
  if (s.kind === 'circle') {
    const v = s.values.map(lit);
    return `const ${name} = new Circle({ x: ${v[0]}, y: ${v[1]} }, ${v[2]});\n`;
  }
  const pts = corners(s)
    .map(([x, y]) => `{ x: ${lit(x)}, y: ${lit(y)} }`)
    .join(',\n  ');
  return `const ${name} = new Polygon({ x: 0, y: 0 }, [\n  ${pts},\n]);\n`;
}

function reproducer(a, b, query, exact, p) {
  if (query === 'contains') {
    return (
      prelude('detect-collisions', version, `detect-collisions ${version}: pointInPolygon gives a wrong contains answer.`) +
      "const { Polygon, pointInPolygon } = require('detect-collisions');\n" +
      source(a, 'a') +
      reportContains(`pointInPolygon({ x: ${lit(p[0])}, y: ${lit(p[1])} }, a)`, exact)
    );
  }
  return (
    prelude(
      'detect-collisions',
      version,
      `detect-collisions ${version}: System.checkCollision gives a wrong ${query} answer.`,
    ) +
    "const { System, Circle, Polygon } = require('detect-collisions');\n" +
    'const system = new System();\n' +
    source(a, 'a') +
    source(b, 'b') +
    'system.insert(a);\nsystem.insert(b);\n' +
    '// SAT.js semantics: subtracting response.overlapV from the position of a separates the pair.\n' +
    report('system.checkCollision(a, b)', '[system.response.overlapV.x, system.response.overlapV.y]', exact)
  );
}

module.exports = {
  hello: {
    library: 'detect-collisions',
    version: `${version} (check2d ${check2d})`,
    kinds: ['circle', 'aabb', 'obb', 'polygon'],
    queries: ['overlap', 'push', 'contains'],
    contract: {
      scalar: 'float64',
      touching: 'overlap',
      tol_abs: 0,
      tol_rel: 2 ** -40,
      push_moves: 'b',
      contains: { touching: 'either', tol_abs: 1.5e-6 },
      source:
        "check2d dist/system.js checkCollision (SAT.js's tests and Response: touching overlaps; overlapV subtracted from a separates); dist/intersect.js pointInPolygon (SAT.js pointInPolygon: a 1e-6 probe box, containment band 1.5e-6, boundary either); no tolerance documented (band: double rounding)",
    },
    mapping:
      'circle -> Circle(centre, r); aabb, obb -> Polygon at (0, 0) with the 4 corners (an OBB\'s computed in double); polygon -> Polygon at (0, 0); each inserted into a fresh System; stored: pos + calcPoints',
  },
  answer,
  contains,
  reproducer,
};
