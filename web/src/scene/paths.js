// Candidate topological paths from /planner/paths: thin lines on the ground, the chosen one
// highlighted and drawn a little higher so it stays on top.

import * as THREE from 'three';
import { clearGroup, makeLine } from './lines.js';

export class PathsLayer {
  constructor() {
    this.object = new THREE.Group();
    this.otherMaterial = new THREE.LineBasicMaterial({ color: 0x6f8fb8, transparent: true, opacity: 0.7 });
    this.chosenMaterial = new THREE.LineBasicMaterial({ color: 0x4dff7a });
    this.count = 0;
    this.info = null;
  }

  clear() {
    clearGroup(this.object);
    this.count = 0;
    this.info = null;
  }

  apply(message) {
    clearGroup(this.object);
    const paths = message.paths || [];
    for (const path of paths) {
      const points = path.points_m || [];
      if (points.length < 2) continue;
      const material = path.chosen ? this.chosenMaterial : this.otherMaterial;
      this.object.add(makeLine(points, path.chosen ? 0.035 : 0.01, material));
    }
    this.count = paths.length;
    this.info = { t: message.t, goal_id: message.goal_id, trajectory_id: message.trajectory_id };
  }
}
