// A cached pass for the heavy, rarely changing part of the scene (the occupancy map and the grid):
// it is rendered into an offscreen colour + depth target only when its content, the camera or the
// view size changed; every frame then copies that target to the screen (colour and depth, one
// full-screen quad that writes gl_FragDepth) and the moving objects are drawn over it with correct
// occlusion. With software GL (headless Chromium) a 100k-point map costs tens of milliseconds a
// draw; a still camera pays it once, and the copy costs a few.
//
// The copy is byte for byte (no colour-space conversion, which costs as much again per pixel in
// software), so the static scene is rendered "display-encoded": its colours are sRGB values
// written unconverted (three writes working-space values into a render target unchanged).
// Objects of the static scene must therefore use raw colours: vertex colours holding sRGB values,
// or rawColor(hex) (see makeGrid). (A blitFramebuffer of colour + depth measured about twice as
// slow as this quad in SwiftShader: the canvas's depth buffer is DEPTH24_STENCIL8.)

import * as THREE from 'three';

const VERTEX = /* glsl */ `
varying vec2 vUv;
void main() {
  vUv = uv;
  gl_Position = vec4(position.xy, 0.0, 1.0);
}`;

const FRAGMENT = /* glsl */ `
uniform sampler2D tColor;
uniform sampler2D tDepth;
varying vec2 vUv;
void main() {
  gl_FragColor = texture2D(tColor, vUv);   // already display-encoded: no conversion
  gl_FragDepth = texture2D(tDepth, vUv).x;
}`;

/** Raw (display-encoded) colour from a hex number, for the static scene. */
export function rawColor(hex) {
  return new THREE.Color().setRGB(((hex >> 16) & 255) / 255, ((hex >> 8) & 255) / 255, (hex & 255) / 255,
    THREE.LinearSRGBColorSpace);
}

/** A ground grid in the XY plane with raw colours (THREE.GridHelper converts its colours). */
export function makeGrid(size, divisions, centerHex, lineHex) {
  const half = size / 2, step = size / divisions;
  const center = rawColor(centerHex), line = rawColor(lineHex);
  const positions = [], colors = [];
  for (let i = 0; i <= divisions; i++) {
    const k = -half + i * step;
    const c = Math.abs(k) < 1e-9 ? center : line;
    positions.push(-half, k, 0, half, k, 0, k, -half, 0, k, half, 0);
    for (let n = 0; n < 4; n++) colors.push(c.r, c.g, c.b);
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.setAttribute('color', new THREE.Float32BufferAttribute(colors, 3));
  return new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: true }));
}

export class StaticCache {
  constructor() {
    this.scene = new THREE.Scene();
    this.target = new THREE.WebGLRenderTarget(1, 1, {
      depthTexture: new THREE.DepthTexture(1, 1),
      minFilter: THREE.NearestFilter,
      magFilter: THREE.NearestFilter,
      generateMipmaps: false,
    });
    this.quadCamera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
    this.quadScene = new THREE.Scene();
    const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), new THREE.ShaderMaterial({
      uniforms: { tColor: { value: this.target.texture }, tDepth: { value: this.target.depthTexture } },
      vertexShader: VERTEX,
      fragmentShader: FRAGMENT,
      depthTest: true,
      depthFunc: THREE.AlwaysDepth,  // write the cached depth whatever is there
      depthWrite: true,
    }));
    quad.frustumCulled = false;
    this.quadScene.add(quad);
    this.dirty = true;
    this.lastView = new THREE.Matrix4();
    this.lastProjection = new THREE.Matrix4();
    this.size = new THREE.Vector2();
    this.renders = 0;  // times the cached pass was rendered (for diagnostics)
  }

  /** The cached content changed (a map update, a layer toggled). */
  invalidate() {
    this.dirty = true;
  }

  /** Draws the cached pass (re-rendering it if needed) into the canvas's framebuffer. */
  draw(renderer, camera) {
    renderer.getDrawingBufferSize(this.size);
    if (this.target.width !== this.size.x || this.target.height !== this.size.y) {
      this.target.setSize(this.size.x, this.size.y);
      this.dirty = true;
    }
    camera.updateMatrixWorld();
    if (!this.lastView.equals(camera.matrixWorld) || !this.lastProjection.equals(camera.projectionMatrix)) {
      this.lastView.copy(camera.matrixWorld);
      this.lastProjection.copy(camera.projectionMatrix);
      this.dirty = true;
    }
    if (this.dirty) {
      this.dirty = false;
      this.renders++;
      renderer.setRenderTarget(this.target);
      renderer.clear();
      renderer.render(this.scene, camera);
      renderer.setRenderTarget(null);
    }
    renderer.clear();
    renderer.render(this.quadScene, this.quadCamera);
  }
}
