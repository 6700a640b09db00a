// The 3D view: renderer, Z-up camera with orbit controls, ground grid, lights and the
// requestAnimationFrame loop. Moving layers add their objects to `viewer.scene`; the heavy static
// ones (the map) to `viewer.staticScene`, which is re-rendered only when invalidateStatic() is
// called or the camera moves (static-cache.js). Per-frame work registers with `onFrame`. If WebGL
// cannot be created the page keeps working without the 3D view.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { StaticCache, makeGrid, rawColor } from './static-cache.js';

export class Viewer {
  constructor(container, errorElement) {
    this.container = container;
    this.cache = new StaticCache();
    this.staticScene = this.cache.scene;
    this.staticScene.background = rawColor(0x1b1e24);  // the static scene's colours are raw
    this.scene = new THREE.Scene();  // drawn over the cached static pass: no background
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.05, 500);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(-7, -9, 7);
    this.camera.lookAt(0, 0, 0);
    this.frameCallbacks = [];
    this.frames = 0;
    this.fps = 0;
    this.fpsWindowStart = performance.now();
    this.fpsWindowFrames = 0;
    this.renderer = null;
    this.controls = null;

    try {
      // No MSAA: with software GL (headless Chromium) it costs about half the frame rate, and the
      // map (the cached pass, without MSAA) would not gain from it.
      this.renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
      this.renderer.autoClear = false;  // StaticCache clears
    } catch (error) {
      errorElement.textContent = `3D view unavailable: WebGL could not be created (${error.message}). ` +
        'The panels still work.';
      errorElement.hidden = false;
    }

    this.#addGrid();
    this.#addLights();

    if (this.renderer) {
      this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
      container.appendChild(this.renderer.domElement);
      this.controls = new OrbitControls(this.camera, this.renderer.domElement);
      this.controls.target.set(0, 0, 0.5);
      this.controls.enableDamping = true;
      this.controls.update();
      this.#resize();
      new ResizeObserver(() => this.#resize()).observe(container);
    }
    this.loop = (now) => this.#frame(now);
    requestAnimationFrame(this.loop);
  }

  /** The static scene's content changed: re-render it on the next frame. */
  invalidateStatic() {
    this.cache.invalidate();
  }

  /** Calls fn(nowMs) before every rendered frame. */
  onFrame(fn) {
    this.frameCallbacks.push(fn);
  }

  #addGrid() {
    this.staticScene.add(makeGrid(40, 40, 0x556070, 0x343a44));
    this.staticScene.add(new THREE.AxesHelper(1));
  }

  #addLights() {
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x404050, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(5, -3, 10);
    this.scene.add(sun);
  }

  #resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.renderer.domElement.style.width = '100%';
    this.renderer.domElement.style.height = '100%';
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
  }

  #frame(now) {
    requestAnimationFrame(this.loop);
    for (const fn of this.frameCallbacks) fn(now);
    if (this.renderer) {
      this.controls.update();
      this.cache.draw(this.renderer, this.camera);
      this.renderer.render(this.scene, this.camera);
    }
    this.frames++;
    this.fpsWindowFrames++;
    const elapsed = now - this.fpsWindowStart;
    if (elapsed >= 1000) {
      this.fps = (this.fpsWindowFrames * 1000) / elapsed;
      this.fpsWindowStart = now;
      this.fpsWindowFrames = 0;
    }
  }
}
