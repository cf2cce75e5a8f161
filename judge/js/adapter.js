#!/usr/bin/env node
// The judge's subprocess protocol, version 2 (docs/judge.md), for adapters written in
// JavaScript: `node adapter.js <library>` loads adapters/<library>.js and serves the judge on
// stdin/stdout. Every number crosses as little-endian IEEE-754 binary64 bytes, bit for bit.
//
// An adapter module exports:
//   hello: { library, version, kinds, queries, contract, mapping }   (the handshake's JSON)
//   init(): optional, may be async (rapier's WebAssembly)
//   answer(a, b): a and b are { kind, values } (our stored values); returns
//     { overlap, push: [x, y] or null, storedA: { kind, values }, storedB: { kind, values } },
//     or { unsupported: true }; a throw is reported as the library's exception
//   contains(s, p): optional (with "contains" among its queries): p is [x, y]; returns
//     { inside, stored: { kind, values }, point: [x, y] as the library holds it }, or
//     { unsupported: true }
//   reproducer(a, b, query, exact, p): the source of a standalone program in the library's own
//     API (for "contains", b is null and p the point)
'use strict';

const KINDS = ['circle', 'aabb', 'obb', 'capsule', 'polygon'];
const PROTOCOL = 2;

function frame(type, payload) {
  const head = Buffer.alloc(5);
  head.writeUInt32LE(payload.length + 1, 0);
  head.write(type, 4, 'latin1');
  return Buffer.concat([head, payload]);
}

function readShape(buf, off) {
  const kind = KINDS[buf.readUInt8(off)];
  const n = buf.readUInt16LE(off + 1);
  const values = new Array(n);
  for (let i = 0; i < n; i++) values[i] = buf.readDoubleLE(off + 3 + 8 * i);
  return [{ kind, values }, off + 3 + 8 * n];
}

function shapeBytes(s) {
  const k = KINDS.indexOf(s.kind);
  if (k < 0) throw new Error(`adapter reported a stored shape of unknown kind ${s.kind}`);
  const b = Buffer.alloc(3 + 8 * s.values.length);
  b.writeUInt8(k, 0);
  b.writeUInt16LE(s.values.length, 1);
  s.values.forEach((v, i) => b.writeDoubleLE(v, 3 + 8 * i));
  return b;
}

function answerBatch(adapter, payload) {
  const n = payload.readUInt32LE(0);
  let off = 4;
  const parts = [Buffer.alloc(4)];
  parts[0].writeUInt32LE(n, 0);
  for (let i = 0; i < n; i++) {
    let a, b;
    [a, off] = readShape(payload, off);
    [b, off] = readShape(payload, off);
    let r;
    try {
      r = adapter.answer(a, b);
    } catch (e) {
      const msg = Buffer.from(String(e && e.message ? e.message : e).slice(0, 500), 'utf8');
      const h = Buffer.alloc(3);
      h.writeUInt8(1, 0);
      h.writeUInt16LE(msg.length, 1);
      parts.push(h, msg);
      continue;
    }
    if (r.unsupported) {
      parts.push(Buffer.from([2]));
      continue;
    }
    const h = Buffer.alloc(19);
    h.writeUInt8(0, 0);
    h.writeUInt8(r.overlap ? 1 : 0, 1);
    h.writeUInt8(r.push ? 1 : 0, 2);
    h.writeDoubleLE(r.push ? r.push[0] : 0, 3);
    h.writeDoubleLE(r.push ? r.push[1] : 0, 11);
    parts.push(h, shapeBytes(r.storedA), shapeBytes(r.storedB));
  }
  return Buffer.concat(parts);
}

function errorBytes(e) {
  const msg = Buffer.from(String(e && e.message ? e.message : e).slice(0, 500), 'utf8');
  const h = Buffer.alloc(3);
  h.writeUInt8(1, 0);
  h.writeUInt16LE(msg.length, 1);
  return [h, msg];
}

// A point batch: per input a shape and a point; per result the answer, the stored shape and
// the stored point.
function answerPoints(adapter, payload) {
  const n = payload.readUInt32LE(0);
  let off = 4;
  const parts = [Buffer.alloc(4)];
  parts[0].writeUInt32LE(n, 0);
  for (let i = 0; i < n; i++) {
    let s;
    [s, off] = readShape(payload, off);
    const p = [payload.readDoubleLE(off), payload.readDoubleLE(off + 8)];
    off += 16;
    let r;
    try {
      r = adapter.contains(s, p);
    } catch (e) {
      parts.push(...errorBytes(e));
      continue;
    }
    if (r.unsupported) {
      parts.push(Buffer.from([2]));
      continue;
    }
    const pt = Buffer.alloc(16);
    pt.writeDoubleLE(r.point[0], 0);
    pt.writeDoubleLE(r.point[1], 8);
    parts.push(Buffer.from([0, r.inside ? 1 : 0]), shapeBytes(r.stored), pt);
  }
  return Buffer.concat(parts);
}

function valueOfBits(hex) {
  const b = Buffer.alloc(8);
  b.writeBigUInt64LE(BigInt('0x' + hex), 0);
  return b.readDoubleLE(0);
}

async function main() {
  const name = process.argv[2];
  if (!name || !/^[a-z0-9-]+$/.test(name)) {
    process.stderr.write('usage: node adapter.js <library>\n');
    process.exit(2);
  }
  const adapter = require(`./adapters/${name}.js`);
  if (adapter.init) await adapter.init();
  process.stdout.write(frame('H', Buffer.from(JSON.stringify({ protocol: PROTOCOL, ...adapter.hello }), 'utf8')));
  let pending = Buffer.alloc(0);
  process.stdin.on('data', (chunk) => {
    pending = pending.length ? Buffer.concat([pending, chunk]) : chunk;
    while (pending.length >= 4) {
      const len = pending.readUInt32LE(0);
      if (pending.length < 4 + len) break;
      const type = String.fromCharCode(pending[4]);
      const payload = pending.subarray(5, 4 + len);
      pending = pending.subarray(4 + len);
      if (type === 'B') {
        process.stdout.write(frame('R', answerBatch(adapter, payload)));
      } else if (type === 'C') {
        process.stdout.write(frame('R', answerPoints(adapter, payload)));
      } else if (type === 'P') {
        const req = JSON.parse(payload.toString('utf8'));
        const shape = (s) => ({ kind: s.kind, values: s.bits.map(valueOfBits) });
        const source = req.p
          ? adapter.reproducer(shape(req.a), null, req.query, req.exact, req.p.map(valueOfBits))
          : adapter.reproducer(shape(req.a), shape(req.b), req.query, req.exact);
        process.stdout.write(frame('S', Buffer.from(JSON.stringify({ ext: 'js', source }), 'utf8')));
      } else if (type === 'Q') {
        process.exit(0);
      } else {
        process.stderr.write(`adapter: unknown message type ${type}\n`);
        process.exit(3);
      }
    }
  });
  process.stdin.on('end', () => process.exit(0));
}

main().catch((e) => {
  process.stderr.write(`adapter: ${e && e.stack ? e.stack : e}\n`);
  process.exit(1);
});
