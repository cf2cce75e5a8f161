// @dimforge/rapier2d-compat (parry2d compiled to WebAssembly, f32): Shape.intersectsShape and
// Shape.contactShape(..., prediction 0). Read: README.md (await RAPIER.init() first),
// dist/geometry/shape.d.ts (intersectsShape; contactShape returns null when separated by more
// than prediction; positions and rotations per call), dist/geometry/contact.d.ts (ShapeContact:
// distance negative on penetration, normal1 points out of the first shape). No tolerance is
// documented: the band is the rounding of f32 arithmetic (32 ulps of the scale). Values are
// rounded to f32 before they reach the library; the rounded values are the stored geometry.
// Containment: Shape.containsPoint(shapePos, shapeRot, point) (shape.d.ts), the point in f32.
'use strict';
const RAPIER = require('@dimforge/rapier2d-compat');
const { packageVersion, obbCorners, points, lit, prelude, report, reportContains, ccw } = require('../common.js');

const version = packageVersion('@dimforge/rapier2d-compat');
const f = Math.fround;

// Our shape as { shape, pos, stored }, or null when the f32 geometry is not exactly one of ours.
function build(s) {
  const v = s.values.map(f);
  if (s.kind === 'circle') {
    return { shape: new RAPIER.Ball(v[2]), pos: { x: v[0], y: v[1] }, stored: { kind: 'circle', values: v } };
  }
  if (s.kind === 'aabb') {
    // A cuboid centred between the rounded corners; stored exactly only when the centre and half
    // extents rebuild the corners without rounding.
    const cx = f((v[0] + v[2]) / 2), cy = f((v[1] + v[3]) / 2);
    const hx = f((v[2] - v[0]) / 2), hy = f((v[3] - v[1]) / 2);
    const box = [cx - hx, cy - hy, cx + hx, cy + hy];
    if (box.some((x) => !Number.isFinite(x))) return null;
    return { shape: new RAPIER.Cuboid(hx, hy), pos: { x: cx, y: cy }, stored: { kind: 'aabb', values: box }, exact: box.every((x, i) => x - [cx, cy, cx, cy][i] === [-hx, -hy, hx, hy][i]) };
  }
  const pts = ccw((s.kind === 'obb' ? obbCorners(s.values) : points(s.values)).map(([x, y]) => [f(x), f(y)]));
  // With the hull computation skipped the vertices must turn left at every corner; a shape that
  // f32 rounding flattened is not one rapier can be given (its raw shape is undefined).
  for (let i = 0; i < pts.length; i++) {
    const [x0, y0] = pts[i];
    const [x1, y1] = pts[(i + 1) % pts.length];
    const [x2, y2] = pts[(i + 2) % pts.length];
    if ((x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1) <= 0) return null;
  }
  return {
    shape: new RAPIER.ConvexPolygon(new Float32Array(pts.flat()), true),
    pos: { x: 0, y: 0 },
    stored: { kind: 'polygon', values: pts.flat() },
  };
}

function answer(a, b) {
  if (a.kind === 'capsule' || b.kind === 'capsule') return { unsupported: true };
  const A = build(a);
  const B = build(b);
  if (!A || !B || A.exact === false || B.exact === false) return { unsupported: true };
  const overlap = A.shape.intersectsShape(A.pos, 0, B.shape, B.pos, 0);
  let push = null;
  if (overlap) {
    const c = A.shape.contactShape(A.pos, 0, B.shape, B.pos, 0, 0);
    // Moving a by normal1 * distance (distance < 0 on penetration) separates the pair; no
    // contact (touching, say) is no push.
    push = c ? [c.normal1.x * c.distance, c.normal1.y * c.distance] : null;
  }
  return { overlap, push, storedA: A.stored, storedB: B.stored };
}

function contains(s, p) {
  if (s.kind === 'capsule') return { unsupported: true };
  const A = build(s);
  if (!A || A.exact === false) return { unsupported: true };
  const q = { x: f(p[0]), y: f(p[1]) };
  return { inside: A.shape.containsPoint(A.pos, 0, q), stored: A.stored, point: [q.x, q.y] };
}

function source(s, name) {
  const v = s.values.map((x) => `Math.fround(${lit(x)})`);
  if (s.kind === 'circle') return `const ${name} = new RAPIER.Ball(${v[2]});\nconst ${name}Pos = { x: ${v[0]}, y: ${v[1]} };\n`;
  if (s.kind === 'aabb')
    return `const ${name}Min = [${v[0]}, ${v[1]}], ${name}Max = [${v[2]}, ${v[3]}];\nconst ${name} = new RAPIER.Cuboid(Math.fround((${name}Max[0] - ${name}Min[0]) / 2), Math.fround((${name}Max[1] - ${name}Min[1]) / 2));\nconst ${name}Pos = { x: Math.fround((${name}Min[0] + ${name}Max[0]) / 2), y: Math.fround((${name}Min[1] + ${name}Max[1]) / 2) };\n`;
  const built = build(s).stored.values;
  return `const ${name} = new RAPIER.ConvexPolygon(new Float32Array([\n  ${built.map(lit).join(',\n  ')},\n]), true);\nconst ${name}Pos = { x: 0, y: 0 };\n`;
}

function reproducer(a, b, query, exact, p) {
  if (query === 'contains') {
    return (
      prelude('@dimforge/rapier2d-compat', version, `rapier2d ${version}: Shape.containsPoint gives a wrong contains answer.`) +
      "const RAPIER = require('@dimforge/rapier2d-compat');\n" +
      'globalThis.rapierReady = globalThis.rapierReady || RAPIER.init();\n' +
      'globalThis.rapierReady.then(() => {\n' +
      source(a, 'a') +
      `const p = { x: Math.fround(${lit(p[0])}), y: Math.fround(${lit(p[1])}) };\n` +
      reportContains('a.containsPoint(aPos, 0, p)', exact) +
      '});\n'
    );
  }
  return (
    prelude('@dimforge/rapier2d-compat', version, `rapier2d ${version}: Shape.intersectsShape / contactShape give a wrong ${query} answer.`) +
    "const RAPIER = require('@dimforge/rapier2d-compat');\n" +
    '// One initialisation shared by every part of the file, so the parts print in order.\n' +
    'globalThis.rapierReady = globalThis.rapierReady || RAPIER.init();\n' +
    'globalThis.rapierReady.then(() => {\n' +
    source(a, 'a') +
    source(b, 'b') +
    '// contactShape: distance < 0 on penetration, normal1 out of a: moving a by normal1 * distance separates.\n' +
    'function pushOf(c) {\n  return c ? [c.normal1.x * c.distance, c.normal1.y * c.distance] : null;\n}\n' +
    report('a.intersectsShape(aPos, 0, b, bPos, 0)', 'pushOf(a.contactShape(aPos, 0, b, bPos, 0, 0))', exact) +
    '});\n'
  );
}

module.exports = {
  hello: {
    library: 'rapier2d',
    version,
    kinds: ['circle', 'aabb', 'obb', 'polygon'],
    queries: ['overlap', 'push', 'contains'],
    contract: {
      scalar: 'float32',
      touching: 'either',
      tol_abs: 0,
      tol_rel: 2 ** -18,
      push_moves: 'a',
      source:
        'dist/geometry/shape.d.ts (intersectsShape, contactShape, containsPoint), dist/geometry/contact.d.ts (distance < 0 on penetration, normal1 out of the first shape); f32; no tolerance documented (band: 32 f32 ulps of the scale); min_size 1e-3: parry works with absolute epsilons (concentric boxes of 2^-13 get a push a third of the exact one, of 1 the exact one), an undocumented design for metre-scale scenes, so smaller shapes are a convention here',
      min_size: 1e-3,
    },
    mapping:
      'every value rounded to f32 first; circle -> Ball(r) at its centre; aabb -> Cuboid(half extents) at its centre (when that rebuilds the corners exactly); obb -> ConvexPolygon of its 4 corners (computed in double, rounded to f32); polygon -> ConvexPolygon (counter-clockwise, hull computation skipped); rotations 0',
  },
  init: () => RAPIER.init(),
  answer,
  contains,
  reproducer,
};
