// The latest LiDAR scan from /lidar/scan: int16 centimetre offsets from p_WS, drawn as small white
// points of constant screen size.

import * as THREE from 'three';
import { base64ToInt16 } from '../util/base64.js';
import { PointsBuffer } from './points-buffer.js';

export class ScanLayer {
  constructor() {
    const material = new THREE.PointsMaterial({ color: 0xffffff, size: 2.5, sizeAttenuation: false });
    this.buffer = new PointsBuffer(material);
    this.object = this.buffer.points;
    this.pending = null;
    this.info = null;
  }

  clear() {
    this.pending = null;
    this.info = null;
    this.buffer.commit(0);
  }

  apply(message) {
    this.pending = message;  // decoded on the next frame: a burst of scans costs one decode
    this.info = { t: message.t, count: message.count, points_total: message.points_total };
  }

  update() {
    const message = this.pending;
    if (!message) return;
    this.pending = null;
    const cm = base64ToInt16(message.points_cm);
    const n = Math.floor(cm.length / 3);
    const [sx, sy, sz] = message.p_WS_m || [0, 0, 0];
    this.buffer.reserve(n);
    const out = this.buffer.positions;
    for (let i = 0; i < n; i++) {
      out[3 * i] = sx + cm[3 * i] * 0.01;
      out[3 * i + 1] = sy + cm[3 * i + 1] * 0.01;
      out[3 * i + 2] = sz + cm[3 * i + 2] * 0.01;
    }
    this.buffer.commit(n);
  }

  get count() {
    return this.buffer.count;
  }
}
