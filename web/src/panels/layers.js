// The layer checkboxes (#layer-<name>): each shows or hides one object of the 3D scene;
// onChange(name, visible) follows every change.

export class LayerToggles {
  /** @param layers { name: THREE.Object3D } ; the checkbox of each is #layer-<name> */
  constructor(layers, onChange = () => {}) {
    this.visible = {};
    for (const [name, object] of Object.entries(layers)) {
      const box = document.getElementById(`layer-${name}`);
      const apply = () => {
        object.visible = box.checked;
        this.visible[name] = box.checked;
        onChange(name, box.checked);
      };
      box.addEventListener('change', apply);
      apply();
    }
  }
}
