// matter-js: Collision.collides(bodyA, bodyB) on bodies from its own factories.
// Read: src/collision/Collision.js (collides, _overlapAxes: SAT over each body's axes, returns
// null when the smallest overlap is <= 0, so touching is apart; penetration = normal * depth,
// the normal's sign chosen by the centres' difference), src/collision/Resolver.js
// (solvePosition moves bodyA along +normal and bodyB along -normal: the penetration is a push
// of a), src/geometry/Axes.js (axes merged
// when their gradients agree to 3 decimals), src/factory/Bodies.js (circle: a polygon of
// ceil(max(10, min(25, r))) sides, its vertices written with toFixed(3) into a path), src/body/Body.js (setVertices recentres on the centroid).
// No tolerance is documented for detection (slop is the resolver's): the band is the rounding
// of double arithmetic. Containment: src/geometry/Vertices.js contains(vertices, point) (outside
// only when a cross product is > 0: the boundary is inside, unlike collides()).
'use strict';
const Matter = require('matter-js');
const { packageVersion, points, lit, prelude, report, reportContains } = require('../common.js');

const version = packageVersion('matter-js');

function build(s) {
  const v = s.values;
  switch (s.kind) {
    case 'circle':
      return Matter.Bodies.circle(v[0], v[1], v[2]);
    case 'aabb':
      return Matter.Bodies.rectangle((v[0] + v[2]) / 2, (v[1] + v[3]) / 2, v[2] - v[0], v[3] - v[1]);
    case 'obb':
      return Matter.Bodies.rectangle(v[0], v[1], 2 * v[2], 2 * v[3], { angle: Math.atan2(v[5], v[4]) });
    case 'polygon': {
      const verts = points(v).map(([x, y]) => ({ x, y }));
      return Matter.Body.create({ vertices: verts, position: Matter.Vertices.centre(verts) });
    }
    default:
      return null;
  }
}

function stored(body) {
  return { kind: 'polygon', values: body.vertices.flatMap((p) => [p.x, p.y]) };
}

function answer(a, b) {
  const A = build(a);
  const B = build(b);
  if (!A || !B) return { unsupported: true };
  const c = Matter.Collision.collides(A, B);
  return {
    overlap: c !== null,
    push: c ? [c.penetration.x, c.penetration.y] : null,
    storedA: stored(A),
    storedB: stored(B),
  };
}

function contains(s, p) {
  const A = build(s);
  if (!A) return { unsupported: true };
  return { inside: Matter.Vertices.contains(A.vertices, { x: p[0], y: p[1] }), stored: stored(A), point: p };
}

function source(s, name) {
  const v = s.values.map(lit);
  switch (s.kind) {
    case 'circle':
      return `const ${name} = Matter.Bodies.circle(${v[0]}, ${v[1]}, ${v[2]});\n`;
    case 'aabb':
      return `const ${name} = Matter.Bodies.rectangle((${v[0]} + ${v[2]}) / 2, (${v[1]} + ${v[3]}) / 2, ${v[2]} - ${v[0]}, ${v[3]} - ${v[1]});\n`;
    case 'obb':
      return `const ${name} = Matter.Bodies.rectangle(${v[0]}, ${v[1]}, 2 * ${v[2]}, 2 * ${v[3]}, { angle: Math.atan2(${v[5]}, ${v[4]}) });\n`;
    default: {
      const pts = points(s.values)
        .map(([x, y]) => `{ x: ${lit(x)}, y: ${lit(y)} }`)
        .join(',\n  ');
      return `const ${name}Vertices = [\n  ${pts},\n];\nconst ${name} = Matter.Body.create({ vertices: ${name}Vertices, position: Matter.Vertices.centre(${name}Vertices) });\n`;
    }
  }
}

function reproducer(a, b, query, exact, p) {
  if (query === 'contains') {
    return (
      prelude('matter-js', version, `matter-js ${version}: Matter.Vertices.contains gives a wrong contains answer.`) +
      "const Matter = require('matter-js');\n" +
      source(a, 'a') +
      reportContains(`Matter.Vertices.contains(a.vertices, { x: ${lit(p[0])}, y: ${lit(p[1])} })`, exact) +
      "console.log('stored a: ' + JSON.stringify(a.vertices.map((q) => [q.x, q.y])));\n"
    );
  }
  return (
    prelude('matter-js', version, `matter-js ${version}: Matter.Collision.collides gives a wrong ${query} answer.`) +
    "const Matter = require('matter-js');\n" +
    source(a, 'a') +
    source(b, 'b') +
    '// Resolver.solvePosition moves a along +normal: moving a by the penetration separates the pair.\n' +
    'const c = Matter.Collision.collides(a, b);\n' +
    report('c !== null', '[c.penetration.x, c.penetration.y]', exact) +
    "console.log('stored a: ' + JSON.stringify(a.vertices.map((p) => [p.x, p.y])));\n" +
    "console.log('stored b: ' + JSON.stringify(b.vertices.map((p) => [p.x, p.y])));\n"
  );
}

module.exports = {
  hello: {
    library: 'matter-js',
    version,
    kinds: ['circle', 'aabb', 'obb', 'polygon'],
    queries: ['overlap', 'push', 'contains'],
    contract: {
      scalar: 'float64',
      touching: 'apart',
      tol_abs: 0,
      tol_rel: 2 ** -40,
      push_moves: 'a',
      contains: { touching: 'overlap' },
      source:
        'src/geometry/Vertices.js contains (the boundary is inside); src/collision/Collision.js: collides() is null when the overlap is <= 0; penetration = normal * depth; src/collision/Resolver.js moves bodyA along +normal; no detection tolerance documented (band: double rounding); min_size 0.01: Bodies.circle writes its vertices with toFixed(3), so shapes under ten times that resolution are below the library\'s own design resolution',
      min_size: 0.01,
    },
    mapping:
      'circle -> Bodies.circle (a polygon of 10..25 sides, vertices rounded to 3 decimals, judged as that polygon); aabb -> Bodies.rectangle; obb -> Bodies.rectangle with angle atan2(uy, ux); polygon -> Body.create({vertices, position: centroid}); stored: body.vertices',
  },
  answer,
  contains,
  reproducer,
};
