// Ground-truth contacts from /sim/contacts: red spheres of radius_m at p_W_m, one instanced mesh.
// Each message carries the whole list (the last 500), so it replaces the previous one.

import * as THREE from 'three';

export class ContactsLayer {
  constructor() {
    this.object = new THREE.Group();
    this.geometry = new THREE.SphereGeometry(1, 16, 12);
    this.material = new THREE.MeshLambertMaterial({
      color: 0xff2a2a, emissive: 0x400000, transparent: true, opacity: 0.75,
    });
    this.mesh = null;
    this.capacity = 0;
    this.count = 0;
    this.total = 0;
    this.matrix = new THREE.Matrix4();
    this.position = new THREE.Vector3();
    this.rotation = new THREE.Quaternion();
    this.scale = new THREE.Vector3();
  }

  #reserve(n) {
    if (n <= this.capacity) return;
    this.capacity = Math.max(64, n);
    if (this.mesh) {
      this.object.remove(this.mesh);
      this.mesh.dispose();
    }
    this.mesh = new THREE.InstancedMesh(this.geometry, this.material, this.capacity);
    this.mesh.frustumCulled = false;
    this.object.add(this.mesh);
  }

  clear() {
    this.apply({ count: 0, contacts: [] });
  }

  apply(message) {
    const contacts = message.contacts || [];
    this.#reserve(contacts.length);
    for (let i = 0; i < contacts.length; i++) {
      const c = contacts[i];
      const r = Math.max(0.01, c.radius_m || 0.05);
      this.position.set(c.p_W_m[0], c.p_W_m[1], c.p_W_m[2]);
      this.scale.set(r, r, r);
      this.matrix.compose(this.position, this.rotation, this.scale);
      this.mesh.setMatrixAt(i, this.matrix);
    }
    if (this.mesh) {
      this.mesh.count = contacts.length;
      this.mesh.instanceMatrix.needsUpdate = true;
    }
    this.count = contacts.length;
    this.total = message.count ?? contacts.length;
  }
}
