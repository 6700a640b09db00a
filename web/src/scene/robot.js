// The robot from /robot/description (box / cylinder / sphere visuals per link), posed by
// /robot/state: each link is a group at X_WL, its visuals children at X_LV, so a visual is drawn at
// X_WL * X_LV.

import * as THREE from 'three';

function makeGeometry(visual) {
  const [sx, sy, sz] = visual.size_m;
  switch (visual.shape) {
    case 'box':
      return new THREE.BoxGeometry(sx, sy, sz);
    case 'cylinder': {
      const geometry = new THREE.CylinderGeometry(sx / 2, sx / 2, sz, 24);
      geometry.rotateX(Math.PI / 2);  // three's cylinder axis is y; the description's is z
      return geometry;
    }
    case 'sphere':
      return new THREE.SphereGeometry(sx / 2, 20, 14);
    default:
      return null;
  }
}

function makeMaterial(rgba) {
  const [r, g, b, a] = rgba || [0.6, 0.6, 0.6, 1];
  return new THREE.MeshLambertMaterial({
    color: new THREE.Color(r, g, b),
    transparent: a < 1,
    opacity: a,
  });
}

export class RobotLayer {
  constructor() {
    this.object = new THREE.Group();
    this.object.visible = false;  // until a state places the links
    this.links = [];              // THREE.Group per description link
    this.meshes = 0;
    this.description = null;
    this.state = null;
  }

  setDescription(description) {
    for (const link of this.links) {
      link.traverse((child) => {
        if (child.isMesh) {
          child.geometry.dispose();
          child.material.dispose();
        }
      });
      this.object.remove(link);
    }
    this.links = [];
    this.meshes = 0;
    this.description = description;
    for (const link of description.links || []) {
      const group = new THREE.Group();
      group.name = link.name;
      for (const visual of link.visuals || []) {
        const geometry = makeGeometry(visual);
        if (!geometry) continue;
        const mesh = new THREE.Mesh(geometry, makeMaterial(visual.rgba));
        const p = visual.p_LV_m || [0, 0, 0];
        const q = visual.quat_LV || [1, 0, 0, 0];
        mesh.position.set(p[0], p[1], p[2]);
        mesh.quaternion.set(q[1], q[2], q[3], q[0]);
        group.add(mesh);
        this.meshes++;
      }
      this.links.push(group);
      this.object.add(group);
    }
    if (this.state) this.setState(this.state);
  }

  setState(state) {
    this.state = state;
    const poses = state.links || [];
    const n = Math.min(poses.length, this.links.length);
    for (let i = 0; i < n; i++) {
      const p = poses[i].p_WL_m;
      const q = poses[i].quat_WL;
      this.links[i].position.set(p[0], p[1], p[2]);
      this.links[i].quaternion.set(q[1], q[2], q[3], q[0]);
    }
    this.object.visible = n > 0;
  }
}
