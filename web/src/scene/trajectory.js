// The planned trajectory from /planner/trajectory: the base path on the ground (z = 0.02) and the
// end effector's path in space.

import * as THREE from 'three';
import { clearGroup, makeLine } from './lines.js';

const BASE_PATH_Z = 0.02;

export class TrajectoryLayer {
  constructor() {
    this.object = new THREE.Group();
    this.baseMaterial = new THREE.LineBasicMaterial({ color: 0xffa630 });
    this.eeMaterial = new THREE.LineBasicMaterial({ color: 0xff4fd8 });
    this.basePoints = 0;
    this.eePoints = 0;
    this.info = null;
  }

  clear() {
    clearGroup(this.object);
    this.basePoints = 0;
    this.eePoints = 0;
    this.info = null;
  }

  apply(message) {
    clearGroup(this.object);
    const base = message.base_path_m || [];
    const ee = message.ee_path_m || [];
    if (base.length > 1) this.object.add(makeLine(base, BASE_PATH_Z, this.baseMaterial));
    if (ee.length > 1) this.object.add(makeLine(ee, 0, this.eeMaterial));
    this.basePoints = base.length;
    this.eePoints = ee.length;
    this.info = {
      trajectory_id: message.trajectory_id, goal_id: message.goal_id, start_t: message.start_t,
      duration_s: message.duration_s,
    };
  }
}
