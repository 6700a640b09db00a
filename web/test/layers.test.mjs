// Unit checks of the page's decoding (no browser): base64 arrays, map blocks, scans, the robot.
//   node --test web/test/layers.test.mjs

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { base64ToInt16, base64ToUint16 } from '../src/util/base64.js';
import { MapLayer } from '../src/scene/map.js';
import { ScanLayer } from '../src/scene/scan.js';
import { RobotLayer } from '../src/scene/robot.js';

const b64 = (typed) => Buffer.from(typed.buffer, typed.byteOffset, typed.byteLength).toString('base64');

test('base64 little-endian arrays decode', () => {
  assert.deepEqual([...base64ToUint16(b64(Uint16Array.from([0, 1, 4095, 65535])))], [0, 1, 4095, 65535]);
  assert.deepEqual([...base64ToInt16(b64(Int16Array.from([-32768, -1, 0, 32767])))], [-32768, -1, 0, 32767]);
  assert.equal(base64ToUint16('').length, 0);
});

test('map blocks: voxel centres, empty block removes, reset drops all', () => {
  const map = new MapLayer();
  const header = { map_seq: 1, t: 0, resolution_m: 0.1, origin_W_m: [-1, -2, 0], dims: [64, 64, 32], block_edge: 16 };
  // Block (1, 0, 2): local (3, 4, 5) -> voxel (19, 4, 37).
  const local = 3 + 16 * (4 + 16 * 5);
  map.apply({ ...header, reset: true, occupied_total: 2,
    blocks: [{ key: [1, 0, 2], occupied: b64(Uint16Array.from([local])) },
      { key: [0, 0, 0], occupied: b64(Uint16Array.from([0])) }] });
  assert.equal(map.update(), true);
  assert.equal(map.update(), false);
  assert.equal(map.blockCount, 2);
  assert.equal(map.voxels, 2);
  const p = map.buffer.positions;
  const centres = [[p[0], p[1], p[2]], [p[3], p[4], p[5]]].map((c) => c.map((x) => +x.toFixed(4)));
  assert.deepEqual(centres.sort(), [[-0.95, -1.95, 0.05], [0.95, -1.55, 3.75]].sort());
  map.apply({ ...header, reset: false, occupied_total: 1, blocks: [{ key: [0, 0, 0], occupied: '' }] });
  map.update();
  assert.equal(map.blockCount, 1);
  assert.equal(map.voxels, 1);
  map.apply({ ...header, reset: true, occupied_total: 0, blocks: [] });
  map.update();
  assert.equal(map.voxels, 0);
});

test('scan: centimetres from p_WS', () => {
  const scan = new ScanLayer();
  scan.apply({ t: 0, p_WS_m: [1, 2, 3], count: 2, points_total: 2, points_cm: b64(Int16Array.from([100, -50, 0, 0, 0, 25])) });
  scan.update();
  assert.equal(scan.count, 2);
  assert.deepEqual([...scan.buffer.positions.slice(0, 6)].map((x) => +x.toFixed(4)), [2, 1.5, 3, 1, 2, 3.25]);
});

test('robot: one mesh per visual, cylinders turned to z, links posed by the state', () => {
  const robot = new RobotLayer();
  robot.setDescription({ name: 'r', joint_names: [], links: [
    { name: 'a', visuals: [{ shape: 'cylinder', size_m: [0.2, 0.2, 1], p_LV_m: [0, 0, 0.5], quat_LV: [1, 0, 0, 0], rgba: [1, 0, 0, 1] }] },
    { name: 'b', visuals: [{ shape: 'box', size_m: [1, 1, 1], p_LV_m: [0, 0, 0], quat_LV: [1, 0, 0, 0], rgba: [0, 1, 0, 0.5] },
      { shape: 'sphere', size_m: [0.2, 0.2, 0.2], p_LV_m: [0, 0, 0], quat_LV: [1, 0, 0, 0], rgba: [0, 0, 1, 1] },
      { shape: 'mesh', size_m: [1, 1, 1], p_LV_m: [0, 0, 0], quat_LV: [1, 0, 0, 0], rgba: [0, 0, 1, 1] }] },
  ] });
  assert.equal(robot.meshes, 3);
  assert.equal(robot.object.visible, false);
  const cylinder = robot.links[0].children[0];
  cylinder.geometry.computeBoundingBox();
  const box = cylinder.geometry.boundingBox;
  assert.ok(Math.abs(box.max.z - 0.5) < 1e-6 && Math.abs(box.max.y - 0.1) < 1e-3, 'axis along z');
  robot.setState({ links: [{ p_WL_m: [1, 2, 3], quat_WL: [0, 0, 0, 1] }, { p_WL_m: [0, 0, 0], quat_WL: [1, 0, 0, 0] }] });
  assert.equal(robot.object.visible, true);
  assert.deepEqual(robot.links[0].position.toArray(), [1, 2, 3]);
  assert.deepEqual(robot.links[0].quaternion.toArray(), [0, 0, 1, 0]);
});
