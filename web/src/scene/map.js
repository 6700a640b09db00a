// The occupancy map from /map/blocks: every occupied voxel is one point at its centre, coloured by
// height. Blocks are kept decoded (positions + colours); the single merged point buffer is rebuilt
// at most once per frame and only after a message changed a block.

import * as THREE from 'three';
import { base64ToUint16 } from '../util/base64.js';
import { turboTable } from '../util/colormap.js';
import { PointsBuffer } from './points-buffer.js';

const FOV_DEG = 50;  // the viewer's camera; a point of size res / tan(fov/2) spans one voxel on screen
const POINT_SCALE = 1 / Math.tan((FOV_DEG / 2) * Math.PI / 180);
const COLORS = turboTable(256);  // raw sRGB: the map is in the cached static pass (static-cache.js)

export class MapLayer {
  constructor() {
    this.material = new THREE.PointsMaterial({ size: 0.05, sizeAttenuation: true, vertexColors: true });
    this.buffer = new PointsBuffer(this.material);
    this.object = this.buffer.points;
    this.blocks = new Map();   // "bi,bj,bk" -> { positions: Float32Array, colors: Float32Array }
    this.voxels = 0;
    this.dirty = false;
    this.info = null;          // the last message's header (map_seq, resolution, occupied_total, ...)
  }

  /** Applies one MapBlocks message. */
  apply(message) {
    if (message.reset) this.blocks.clear();
    const res = message.resolution_m;
    const origin = message.origin_W_m || [0, 0, 0];
    const dims = message.dims || [0, 0, 0];
    const edge = message.block_edge || 16;
    const zMin = origin[2];
    const zSpan = Math.max(res, Math.min(dims[2] * res, 3.0));  // colour over the lowest 3 m
    this.material.size = res * POINT_SCALE;
    for (const block of message.blocks || []) {
      const key = block.key.join(',');
      if (!block.occupied) {
        this.blocks.delete(key);
        continue;
      }
      const indices = base64ToUint16(block.occupied);
      const n = indices.length;
      const positions = new Float32Array(3 * n);
      const colors = new Float32Array(3 * n);
      const i0 = block.key[0] * edge, j0 = block.key[1] * edge, k0 = block.key[2] * edge;
      const area = edge * edge;
      for (let p = 0; p < n; p++) {
        const local = indices[p];
        const li = local % edge;
        const lj = Math.floor(local / edge) % edge;
        const lk = Math.floor(local / area);
        const z = origin[2] + (k0 + lk + 0.5) * res;
        positions[3 * p] = origin[0] + (i0 + li + 0.5) * res;
        positions[3 * p + 1] = origin[1] + (j0 + lj + 0.5) * res;
        positions[3 * p + 2] = z;
        const c = 3 * Math.min(255, Math.max(0, Math.round(((z - zMin) / zSpan) * 255)));
        colors[3 * p] = COLORS[c];
        colors[3 * p + 1] = COLORS[c + 1];
        colors[3 * p + 2] = COLORS[c + 2];
      }
      this.blocks.set(key, { positions, colors });
    }
    this.info = {
      map_seq: message.map_seq, t: message.t, resolution_m: res, dims, origin_W_m: origin,
      occupied_total: message.occupied_total,
    };
    this.dirty = true;
  }

  /** Drops every block (a seek to a time before the first map). */
  clear() {
    this.blocks.clear();
    this.info = null;
    this.dirty = true;
  }

  /** Rebuilds the merged buffer if a message changed it (call once per frame); true if it did. */
  update() {
    if (!this.dirty) return false;
    this.dirty = false;
    let total = 0;
    for (const block of this.blocks.values()) total += block.positions.length / 3;
    this.buffer.reserve(total);
    let offset = 0;
    for (const block of this.blocks.values()) {
      this.buffer.positions.set(block.positions, offset);
      this.buffer.colors.set(block.colors, offset);
      offset += block.positions.length;
    }
    this.voxels = total;
    this.buffer.commit(total);
    return true;
  }

  get blockCount() {
    return this.blocks.size;
  }
}
