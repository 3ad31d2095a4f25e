// A 3-D preview of one asset in which the user picks a part and one of its surfaces.
// Parts light up under the pointer; the selected part shows its six directional surfaces as
// arrows. Clicking a part picks the part only (the relation's default surface applies);
// clicking an arrow, or a surface button, picks that surface explicitly. The preview GLB's nodes carry {part, label, k, count, surfaces} in extras.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { api } from "./api.js";
import { antialias } from "./gl.js";

export const SURFACE_COLOURS = {
  top: 0xe53e3e, bottom: 0x3182ce, front: 0x38a169, back: 0xd69e2e, right: 0x805ad5, left: 0xdd6b20,
};
const HOVER = new THREE.Color(0xffd54a);
const SELECTED = new THREE.Color(0x4fc3f7);

export class AssetPicker {
  constructor(container, { onPick, onHover } = {}) {
    this.container = container;
    this.onPick = onPick || (() => {});
    this.onHover = onHover || (() => {});
    this.renderer = new THREE.WebGLRenderer({ antialias: antialias(), preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(0xf4f5f7);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x888888, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(2, 4, -3);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener("change", () => this.render());
    this.raycaster = new THREE.Raycaster();
    this.root = null;
    this.parts = [];      // meshes, each with userData from the GLB extras
    this.arrows = new THREE.Group();
    this.scene.add(this.arrows);
    this.hovered = null;
    this.selected = null; // {mesh, surface}
    this.size = 1;
    this._down = null;
    const el = this.renderer.domElement;
    el.addEventListener("pointermove", (e) => this._move(e));
    el.addEventListener("pointerdown", (e) => { this._down = [e.clientX, e.clientY]; });
    el.addEventListener("pointerup", (e) => this._up(e));
    el.addEventListener("pointerleave", () => this._hover(null));
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = this.container.clientWidth || 300, h = this.container.clientHeight || 220;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    if (this._pending) return;
    this._pending = true;
    requestAnimationFrame(() => {
      this._pending = false;
      this.renderer.render(this.scene, this.camera);
      this.lastFrame = performance.now();
    });
  }

  clear() {
    if (this.root) this.scene.remove(this.root);
    this.root = null;
    this.parts = [];
    this.selected = this.hovered = null;
    this.arrows.clear();
    this.render();
  }

  async load(category, variant) {
    const key = `${category}/${variant || ""}`;
    if (this.key === key && this.root) return;
    this.key = key;
    const gltf = await new GLTFLoader().loadAsync(api.assetUrl(category, variant));
    if (this.key !== key) return; // a newer load won
    this.clear();
    this.root = gltf.scene;
    this.root.traverse((o) => {
      if (o.isMesh) {
        const info = o.userData && o.userData.part ? o.userData : o.parent.userData;
        o.userData = { ...info };
        o.material = o.material.clone();
        o.material.emissive = new THREE.Color(0x000000);
        this.parts.push(o);
      }
    });
    this.scene.add(this.root);
    const box = new THREE.Box3().setFromObject(this.root);
    const centre = box.getCenter(new THREE.Vector3());
    this.size = box.getSize(new THREE.Vector3()).length();
    // the asset's front faces -Z in glTF's Y-up frame: look at it from front-right, above
    this.camera.position.copy(centre).add(new THREE.Vector3(0.75, 0.75, -1.25).multiplyScalar(this.size * 0.95));
    this.camera.near = this.size / 100;
    this.camera.far = this.size * 20;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.loaded = key;
    this.render();
  }

  _ndc(e) {
    const r = this.renderer.domElement.getBoundingClientRect();
    return new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
  }

  _hit(e) {
    // matrices are otherwise only brought up to date by a render, which may not have happened yet
    this.scene.updateMatrixWorld();
    this.camera.updateMatrixWorld();
    this.raycaster.setFromCamera(this._ndc(e), this.camera);
    // arrow heads only: a line's pick threshold is in world units and would swallow clicks
    const arrowHit = this.raycaster.intersectObjects(this.arrows.children.map((a) => a.cone), false)[0];
    if (arrowHit) return { arrow: arrowHit.object.parent.userData.surface };
    const hit = this.raycaster.intersectObjects(this.parts, false)[0];
    return hit ? { mesh: hit.object, face: hit.face } : null;
  }

  _move(e) {
    const h = this._hit(e);
    this._hover(h && h.mesh ? h.mesh : null, h && h.arrow, h && h.mesh ? this._faceSurface(h) : null);
  }

  _hover(mesh, arrow, surface) {
    if (this.hovered !== mesh) {
      this.hovered = mesh;
      this._paint();
    }
    this.renderer.domElement.style.cursor = mesh || arrow ? "pointer" : "grab";
    this.onHover(mesh ? mesh.userData : null, arrow || null, surface || null);
  }

  // The surface label whose normal is closest to the normal of the triangle hit.
  _faceSurface(hit) {
    const n = hit.face.normal.clone().transformDirection(hit.mesh.matrixWorld);
    let best = null, bestDot = -2;
    for (const [label, s] of Object.entries(hit.mesh.userData.surfaces || {})) {
      const d = n.dot(new THREE.Vector3(...s.normal));
      if (d > bestDot) { bestDot = d; best = label; }
    }
    return best;
  }

  _paint() {
    for (const m of this.parts) {
      const c = this.selected && this.selected.mesh === m ? SELECTED : m === this.hovered ? HOVER : null;
      m.material.emissive.set(c || 0x000000);
      m.material.emissiveIntensity = c ? 0.45 : 0;
    }
    this.render();
  }

  _up(e) {
    if (!this._down) return;
    const moved = Math.hypot(e.clientX - this._down[0], e.clientY - this._down[1]);
    this._down = null;
    if (moved > 4) return; // an orbit drag, not a click
    this.lastClick = e.timeStamp; // click-to-feedback latency: lastFrame - lastClick
    const h = this._hit(e);
    if (!h) return;
    if (h.arrow) {
      if (this.selected) this.select(this.selected.mesh.userData.part, h.arrow);
      return;
    }
    // the part, not the face clicked: a mug clicked on its side is still ON by its bottom
    this.select(h.mesh.userData.part, null);
  }

  // Select a part by name (and a surface label, or null); shows its arrows; calls onPick.
  select(partName, surface, { silent = false } = {}) {
    const mesh = this.parts.find((m) => m.userData.part === partName);
    if (!mesh) return;
    this.selected = { mesh, surface };
    this._arrows(mesh, surface);
    this._paint();
    if (!silent) this.onPick({ ...mesh.userData, surface });
  }

  unselect() {
    this.selected = null;
    this.arrows.clear();
    this._paint();
  }

  _arrows(mesh, chosen) {
    this.arrows.clear();
    const len = this.size * 0.22;
    for (const [label, s] of Object.entries(mesh.userData.surfaces || {})) {
      const dir = new THREE.Vector3(...s.normal).normalize();
      const origin = new THREE.Vector3(...s.origin);
      const on = label === chosen;
      const arrow = new THREE.ArrowHelper(dir, origin, on ? len * 1.35 : len, SURFACE_COLOURS[label],
        len * 0.35, len * 0.22);
      arrow.userData.surface = label;
      arrow.line.material.linewidth = 2;
      if (!on && chosen) { arrow.line.material.transparent = arrow.cone.material.transparent = true;
        arrow.line.material.opacity = arrow.cone.material.opacity = 0.45; }
      this.arrows.add(arrow);
    }
    this.arrows.updateMatrixWorld(true);
  }

  // Page coordinates (CSS px) of a part's centre, or of the head of one of its arrows: what a
  // user would click. Used by the browser tests and the benchmark.
  screenPoint(partName, surface) {
    let p;
    if (surface) {
      const a = this.arrows.children.find((x) => x.userData.surface === surface);
      if (!a) return null;
      // a point inside the arrow's head, 60 % of the way back from its tip
      p = a.localToWorld(new THREE.Vector3(0, a.cone.position.y - 0.6 * a.cone.scale.y, 0));
    } else {
      const mesh = this.parts.find((m) => m.userData.part === partName);
      if (!mesh) return null;
      p = new THREE.Box3().setFromObject(mesh).getCenter(new THREE.Vector3());
    }
    this.camera.updateMatrixWorld();
    p.project(this.camera);
    const r = this.renderer.domElement.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }
}
