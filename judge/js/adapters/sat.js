// SAT.js: testPolygonPolygon, testPolygonCircle, testCirclePolygon, testCircleCircle with a
// Response. Read: README.md (polygons convex and counter-clockwise; "If [overlapV] is
// subtracted from the position of a, a and b will no longer be colliding"), SAT.js
// (isSeparatingAxis separates only when rangeA[0] > rangeB[1] or rangeB[0] > rangeA[1], so
// touching overlaps; testCircleCircle is apart only when distance^2 > (r1 + r2)^2; circle and
// polygon by Voronoi regions, apart only when dist > radius). No tolerance documented: the
// band is the rounding of double arithmetic. Polygons are placed at pos (0, 0) with their
// world points, so SAT.js stores our values as given. Containment: pointInCircle (distance^2 <=
// r^2, closed) and pointInPolygon, which tests a 1e-6 box at the point (TEST_POINT in SAT.js,
// aInB): a point within about 1.5e-6 of an edge may be outside, a boundary point either.
'use strict';
const SAT = require('sat');
const { packageVersion, obbCorners, aabbCorners, points, lit, prelude, report, reportContains, ccw } = require('../common.js');

const version = packageVersion('sat');

function corners(s) {
  if (s.kind === 'aabb') return aabbCorners(s.values);
  if (s.kind === 'obb') return obbCorners(s.values);
  return ccw(points(s.values));
}

function build(s) {
  if (s.kind === 'circle') return new SAT.Circle(new SAT.Vector(s.values[0], s.values[1]), s.values[2]);
  return new SAT.Polygon(
    new SAT.Vector(0, 0),
    corners(s).map(([x, y]) => new SAT.Vector(x, y)),
  );
}

function stored(s, shape) {
  if (s.kind === 'circle') return { kind: 'circle', values: [shape.pos.x, shape.pos.y, shape.r] };
  return { kind: 'polygon', values: shape.calcPoints.flatMap((p) => [p.x + shape.pos.x, p.y + shape.pos.y]) };
}

function test(a, b) {
  const name = (a.kind === 'circle' ? 'Circle' : 'Polygon') + (b.kind === 'circle' ? 'Circle' : 'Polygon');
  return 'test' + name;
}

function answer(a, b) {
  if (a.kind === 'capsule' || b.kind === 'capsule') return { unsupported: true };
  const A = build(a);
  const B = build(b);
  const r = new SAT.Response();
  const overlap = SAT[test(a, b)](A, B, r);
  return {
    overlap,
    push: overlap ? [r.overlapV.x, r.overlapV.y] : null,
    storedA: stored(a, A),
    storedB: stored(b, B),
  };
}

function contains(s, p) {
  if (s.kind === 'capsule') return { unsupported: true };
  const S = build(s);
  const v = new SAT.Vector(p[0], p[1]);
  const inside = s.kind === 'circle' ? SAT.pointInCircle(v, S) : SAT.pointInPolygon(v, S);
  return { inside, stored: stored(s, S), point: p };
}

function source(s, name) {
  if (s.kind === 'circle') {
    const v = s.values.map(lit);
    return `const ${name} = new SAT.Circle(new SAT.Vector(${v[0]}, ${v[1]}), ${v[2]});\n`;
  }
  const pts = corners(s)
    .map(([x, y]) => `new SAT.Vector(${lit(x)}, ${lit(y)})`)
    .join(',\n  ');
  return `const ${name} = new SAT.Polygon(new SAT.Vector(0, 0), [\n  ${pts},\n]);\n`;
}

function reproducer(a, b, query, exact, p) {
  if (query === 'contains') {
    const fn = a.kind === 'circle' ? 'pointInCircle' : 'pointInPolygon';
    return (
      prelude('sat', version, `SAT.js ${version}: SAT.${fn} gives a wrong contains answer.`) +
      "const SAT = require('sat');\n" +
      source(a, 'a') +
      `const p = new SAT.Vector(${lit(p[0])}, ${lit(p[1])});\n` +
      reportContains(`SAT.${fn}(p, a)`, exact)
    );
  }
  return (
    prelude('sat', version, `SAT.js ${version}: SAT.${test(a, b)} gives a wrong ${query} answer.`) +
    "const SAT = require('sat');\n" +
    source(a, 'a') +
    source(b, 'b') +
    '// README: subtracting response.overlapV from the position of a separates the pair.\n' +
    'const r = new SAT.Response();\n' +
    report(`SAT.${test(a, b)}(a, b, r)`, '[r.overlapV.x, r.overlapV.y]', exact)
  );
}

module.exports = {
  hello: {
    library: 'sat',
    version,
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
        'SAT.js pointInPolygon (a 1e-6 box at the point, TEST_POINT: containment band 1.5e-6, boundary either) and pointInCircle (closed); README.md (Response.overlapV: subtracted from the position of a, they no longer collide); SAT.js isSeparatingAxis and testCircleCircle (touching overlaps); no tolerance documented (band: double rounding)',
    },
    mapping:
      'circle -> SAT.Circle(centre, r); aabb, obb -> SAT.Polygon at (0, 0) with the 4 corners (an OBB\'s computed in double), counter-clockwise; polygon -> SAT.Polygon at (0, 0), counter-clockwise; stored: pos + calcPoints',
  },
  answer,
  contains,
  reproducer,
};
