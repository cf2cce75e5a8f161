// planck (a JavaScript port of Box2D): testOverlap(shapeA, 0, shapeB, 0, xfA, xfB).
// Read: src/collision/Distance.ts (testOverlap: GJK distance with useRadii, overlap when the
// distance after subtracting both radii is < 10 * EPSILON, so touching overlaps), src/Settings.ts
// (linearSlop 0.005, polygonRadius = 2 * linearSlop = 0.01), src/collision/shape/PolygonShape.ts
// (every polygon carries the 0.01 skin m_radius; vertices closer than linearSlop / 2 are welded;
// the convex hull is taken), BoxShape.ts (box by half extents, centre and angle). The skin is the
// declared tolerance: up to 0.02 for two polygons, plus the rounding of double arithmetic.
// Containment: Shape.testPoint(xf, p) (PolygonShape.ts: outside when dot(normal, p - vertex) > 0,
// the sharp polygon closed, skin excluded; CircleShape.ts: distance^2 <= r^2).
'use strict';
const planck = require('planck');
const { packageVersion, aabbCorners, points, lit, prelude, report, reportContains } = require('../common.js');

const version = packageVersion('planck');

function build(s) {
  const v = s.values;
  switch (s.kind) {
    case 'circle':
      return new planck.CircleShape(planck.Vec2(v[0], v[1]), v[2]);
    case 'aabb':
      return new planck.PolygonShape(aabbCorners(v).map(([x, y]) => planck.Vec2(x, y)));
    case 'obb':
      return new planck.BoxShape(v[2], v[3], planck.Vec2(v[0], v[1]), Math.atan2(v[5], v[4]));
    case 'polygon':
      return new planck.PolygonShape(points(v).map(([x, y]) => planck.Vec2(x, y)));
    default:
      return null;
  }
}

function stored(shape) {
  if (shape.getType() === 'circle') {
    const c = shape.getCenter();
    return { kind: 'circle', values: [c.x, c.y, shape.getRadius()] };
  }
  return { kind: 'polygon', values: shape.m_vertices.flatMap((p) => [p.x, p.y]) };
}

function answer(a, b) {
  const A = build(a);
  const B = build(b);
  if (!A || !B) return { unsupported: true };
  const id = planck.Transform.identity();
  return {
    overlap: planck.testOverlap(A, 0, B, 0, id, id),
    push: null,
    storedA: stored(A),
    storedB: stored(B),
  };
}

function contains(s, p) {
  const A = build(s);
  if (!A) return { unsupported: true };
  return { inside: A.testPoint(planck.Transform.identity(), planck.Vec2(p[0], p[1])), stored: stored(A), point: p };
}

function source(s, name) {
  const v = s.values.map(lit);
  const vec = ([x, y]) => `planck.Vec2(${lit(x)}, ${lit(y)})`;
  switch (s.kind) {
    case 'circle':
      return `const ${name} = new planck.CircleShape(planck.Vec2(${v[0]}, ${v[1]}), ${v[2]});\n`;
    case 'aabb':
      return `const ${name} = new planck.PolygonShape([\n  ${aabbCorners(s.values).map(vec).join(',\n  ')},\n]);\n`;
    case 'obb':
      return `const ${name} = new planck.BoxShape(${v[2]}, ${v[3]}, planck.Vec2(${v[0]}, ${v[1]}), Math.atan2(${v[5]}, ${v[4]}));\n`;
    default:
      return `const ${name} = new planck.PolygonShape([\n  ${points(s.values).map(vec).join(',\n  ')},\n]);\n`;
  }
}

function reproducer(a, b, query, exact, p) {
  if (query === 'contains') {
    return (
      prelude('planck', version, `planck ${version}: Shape.testPoint gives a wrong contains answer.`) +
      "const planck = require('planck');\n" +
      source(a, 'a') +
      reportContains(`a.testPoint(planck.Transform.identity(), planck.Vec2(${lit(p[0])}, ${lit(p[1])}))`, exact)
    );
  }
  return (
    prelude('planck', version, `planck ${version}: planck.testOverlap gives a wrong ${query} answer.`) +
    "const planck = require('planck');\n" +
    source(a, 'a') +
    source(b, 'b') +
    'const id = planck.Transform.identity();\n' +
    '// Polygons carry a skin of Settings.polygonRadius (0.01): overlaps within it are planck\'s convention.\n' +
    report('planck.testOverlap(a, 0, b, 0, id, id)', null, exact)
  );
}

module.exports = {
  hello: {
    library: 'planck',
    version,
    kinds: ['circle', 'aabb', 'obb', 'polygon'],
    queries: ['overlap', 'contains'],
    contract: {
      scalar: 'float64',
      touching: 'overlap',
      tol_abs: 0.02 + 10 * Number.EPSILON,
      tol_rel: 2 ** -40,
      push_moves: 'a',
      source:
        'src/collision/Distance.ts testOverlap (distance minus radii < 10 EPSILON); shape testPoint (closed); src/Settings.ts polygonRadius 0.01 (each polygon\'s skin); docs/pages/api-conventions/units.md: moving shapes 0.1 to 10 m, static shapes up to 50 m (min_size 0.1, max_size 50)',
      min_size: 0.1,
      max_size: 50,
    },
    mapping:
      'circle -> CircleShape(centre, r); aabb -> PolygonShape(4 corners); obb -> BoxShape(hx, hy, centre, atan2(uy, ux)); polygon -> PolygonShape(vertices); identity transforms; stored: m_vertices (the sharp polygon; its 0.01 skin is the declared tolerance), a circle\'s centre and radius',
  },
  answer,
  contains,
  reproducer,
};
