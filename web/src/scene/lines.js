// Helpers for polylines built from JSON point lists.

import * as THREE from 'three';

/** A THREE.Line through [[x, y(, z)], ...]; 2D points get height z. */
export function makeLine(points, z, material) {
  const positions = new Float32Array(3 * points.length);
  for (let i = 0; i < points.length; i++) {
    const p = points[i];
    positions[3 * i] = p[0];
    positions[3 * i + 1] = p[1];
    positions[3 * i + 2] = p.length > 2 ? p[2] : z;
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  const line = new THREE.Line(geometry, material);
  line.frustumCulled = false;
  return line;
}

/** Removes and disposes the children of a group (materials are shared and kept). */
export function clearGroup(group) {
  for (const child of [...group.children]) {
    group.remove(child);
    child.geometry?.dispose();
  }
}
