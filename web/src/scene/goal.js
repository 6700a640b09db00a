// The goal pose from /goal: a sphere at p_WE with an axes triad and an arrow along the goal's x.

import * as THREE from 'three';

export class GoalLayer {
  constructor() {
    this.object = new THREE.Group();
    this.object.visible = false;
    const sphere = new THREE.Mesh(
      new THREE.SphereGeometry(0.04, 16, 12),
      new THREE.MeshLambertMaterial({ color: 0xffe14d, emissive: 0x332b00 }),
    );
    this.object.add(sphere);
    this.object.add(new THREE.AxesHelper(0.2));
    this.object.add(new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 0, 0),
      0.35, 0xffe14d, 0.08, 0.05));
    this.present = 0;
    this.info = null;
  }

  clear() {
    this.object.visible = false;
    this.present = 0;
    this.info = null;
  }

  apply(message) {
    const p = message.p_WE_m;
    const q = message.quat_WE || [1, 0, 0, 0];
    if (!p) return;
    this.object.position.set(p[0], p[1], p[2]);
    this.object.quaternion.set(q[1], q[2], q[3], q[0]);
    this.object.visible = true;
    this.present = 1;
    this.info = message;
  }
}
