import assert from 'node:assert/strict';
import { test } from 'node:test';
import { decodeBase64, decodeDocument, f32, u32 } from '../src/decode.js';

test('base64 decodes the RFC 4648 vectors', () => {
  const vectors = [['', ''], ['Zg==', 'f'], ['Zm8=', 'fo'], ['Zm9v', 'foo'], ['Zm9vYg==', 'foob'], ['Zm9vYmE=', 'fooba'], ['Zm9vYmFy', 'foobar']];
  for (const [encoded, plain] of vectors) {
    assert.equal(new TextDecoder().decode(decodeBase64(encoded)), plain);
  }
});

test('f32 and u32 read little-endian words', () => {
  // 1.0 = 00 00 80 3f, -2.5 = 00 00 20 c0; 258 = 02 01 00 00.
  const floats = Buffer.from([0, 0, 0x80, 0x3f, 0, 0, 0x20, 0xc0]).toString('base64');
  assert.deepEqual(Array.from(f32(floats)), [1, -2.5]);
  const ints = Buffer.from([2, 1, 0, 0, 0xff, 0xff, 0xff, 0xff]).toString('base64');
  assert.deepEqual(Array.from(u32(ints)), [258, 4294967295]);
  assert.equal(f32('').length, 0);
});

test('a document has every encoded array decoded', () => {
  const enc = (values) => Buffer.from(new Float32Array(values).buffer).toString('base64');
  const raw = {
    title: 't', subtitle: [], notes: [], kind: 'arm',
    robot: { name: 'r', hand: 0, links: [{ name: 'l', spheres: enc([0, 0, 0, 1]), meshes: [{ positions: enc([0, 0, 0, 1, 0, 0, 0, 1, 0]), indices: Buffer.from(new Uint32Array([0, 1, 2]).buffer).toString('base64'), colour: [1, 0, 0] }] }] },
    scene: { solids: [], clouds: [{ name: 'c', points: enc([1, 2, 3]), radius: 0.1 }], bounds: null },
    motions: [{ label: 'm', joint_names: ['j'], frames: 1, joints: enc([0.5]), poses: enc([0, 0, 0, 0, 0, 0, 1]), times: null, waypoints: [0], colliding: [] }],
    search: { segments: enc([0, 0, 0, 1, 1, 1]), costs: enc([2]), informed: null, label: 's' },
  };
  const doc = decodeDocument(raw);
  assert.deepEqual(Array.from(doc.robot.links[0].meshes[0].indices), [0, 1, 2]);
  assert.deepEqual(Array.from(doc.scene.clouds[0].points), [1, 2, 3]);
  assert.deepEqual(Array.from(doc.motions[0].joints), [0.5]);
  assert.deepEqual(Array.from(doc.search.costs), [2]);
  assert.equal(doc.title, 't');
});
