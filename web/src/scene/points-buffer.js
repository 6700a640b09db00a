// A THREE.Points whose position / colour buffers are reused and only reallocated (grown by half)
// when a larger cloud arrives, so updating a cloud allocates nothing in the steady state.

import * as THREE from 'three';

export class PointsBuffer {
  constructor(material) {
    this.capacity = 0;
    this.count = 0;
    this.positions = new Float32Array(0);
    this.colors = material.vertexColors ? new Float32Array(0) : null;
    this.points = new THREE.Points(new THREE.BufferGeometry(), material);
    this.points.frustumCulled = false;  // the cloud changes every update; skip bounding spheres
  }

  /** Makes room for n points (content is kept only when no reallocation is needed). */
  reserve(n) {
    if (n <= this.capacity) return;
    this.capacity = Math.max(1024, Math.ceil(n * 1.5));
    this.positions = new Float32Array(3 * this.capacity);
    if (this.colors) this.colors = new Float32Array(3 * this.capacity);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(this.positions, 3));
    if (this.colors) geometry.setAttribute('color', new THREE.BufferAttribute(this.colors, 3));
    this.points.geometry.dispose();
    this.points.geometry = geometry;
  }

  /** Marks the first n points as drawn and uploads them. */
  commit(n) {
    this.count = n;
    const geometry = this.points.geometry;
    geometry.setDrawRange(0, n);
    const position = geometry.getAttribute('position');
    if (!position) return;
    position.clearUpdateRanges();
    position.addUpdateRange(0, 3 * n);
    position.needsUpdate = true;
    const color = geometry.getAttribute('color');
    if (color) {
      color.clearUpdateRanges();
      color.addUpdateRange(0, 3 * n);
      color.needsUpdate = true;
    }
  }
}
