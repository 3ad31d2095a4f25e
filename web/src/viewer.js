// The solved scene in three.js: orbit, ceiling hidden, click an object to see its relations
// and whether each held after settling, and the part-level contact graph as an overlay.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { antialias } from "./gl.js";

// The exporter's node name of "<object_id>:<part_name>": "desk__leg_0" (three.js would strip a
// colon: its PropertyBinding drops [ ] . : / from node names), as parse3d.export.walk.node_name.
const nodeName = (key) => {
  const s = key.replace(":", "__").replace(/[^A-Za-z0-9_]/g, "_") || "_";
  return /^[0-9]/.test(s) ? "_" + s : s;
};

// Which object and part a mesh shows: from the node's extras when the exporter writes them
// (object id and part name, in userData), else from its node name; a mesh under a part node
// inherits the part.
function refOf(node, names) {
  for (let n = node; n; n = n.parent) {
    const x = n.userData || {};
    const object = x.object_id || x.object;
    if (object && object !== "room") {
      let part = x.part_name || x.part || x.name || null;
      if (part && part.includes(":")) part = part.slice(part.indexOf(":") + 1);
      return { object, part };
    }
    const key = names.get(n.name) || names.get(n.name.replace(/_\d+$/, ""));
    if (key) return key;
  }
  return null;
}

export class SceneViewer {
  constructor(container, { onSelect } = {}) {
    this.container = container;
    this.onSelect = onSelect || (() => {});
    this.renderer = new THREE.WebGLRenderer({ antialias: antialias(), preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(0xe8ebef);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x7a7a7a, 2.0));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5);
    sun.position.set(3, 8, 2);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.05, 200);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener("change", () => this.render());
    this.raycaster = new THREE.Raycaster();
    this.overlay = new THREE.Group();
    this.overlay.visible = false;
    this.scene.add(this.overlay);
    this.root = null;
    this.meshes = [];
    this._down = null;
    const el = this.renderer.domElement;
    el.addEventListener("pointerdown", (e) => { this._down = [e.clientX, e.clientY]; });
    el.addEventListener("pointerup", (e) => this._up(e));
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = this.container.clientWidth || 400, h = this.container.clientHeight || 300;
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
      this._cutaway();
      this.renderer.render(this.scene, this.camera);
      this.rendered = (this.rendered || 0) + 1;
    });
  }

  // Hide the walls the camera is behind, so the room is seen from inside: the camera is outside
  // wall_i when it is on the outer side of the line from footprint vertex i to vertex i+1.
  _cutaway() {
    const fp = this.result && this.result.room && this.result.room.footprint;
    if (!fp || !this.walls) return;
    const cx = this.camera.position.x, cy = -this.camera.position.z; // glTF (x, z) -> world (x, -y)
    for (const [i, meshes] of this.walls) {
      const [x1, y1] = fp[i], [x2, y2] = fp[(i + 1) % fp.length];
      const inside = (cx - x1) * -(y2 - y1) + (cy - y1) * (x2 - x1) > 0;
      for (const m of meshes) m.visible = inside;
    }
  }

  // Load scene.glb and the job's results ({objects, relations, contacts}).
  async load(url, result) {
    const gltf = await new GLTFLoader().loadAsync(url);
    if (this.root) this.scene.remove(this.root);
    this.root = gltf.scene;
    this.result = result;
    const names = new Map();
    for (const o of result.objects) {
      for (const p of o.parts || []) names.set(nodeName(`${o.id}:${p.name}`), { object: o.id, part: p.name });
    }
    this.meshes = [];
    this.walls = new Map();
    this.root.traverse((node) => {
      // the shell: nodes "room__floor", "room__wall_3", "room__ceiling", extras object_id "room"
      const shellName = /^room__(floor|ceiling|wall_\d+)(_\d+)?$/.exec(node.name);
      const shell = node.userData.object_id === "room" || !!shellName;
      const inRoom = shell || (node.parent && node.parent.userData.room);
      node.userData.room = !!inRoom;
      const element = node.userData.object_id === "room" ? node.userData.part : shellName && shellName[1];
      const wall = element ? /^wall_(\d+)$/.exec(element) : null;
      if (wall) {
        const i = Number(wall[1]);
        if (!this.walls.has(i)) this.walls.set(i, []);
        this.walls.get(i).push(node); // a node or its mesh: children follow their parent
      }
      if (element === "ceiling") node.visible = false;
      if (node.isMesh) {
        node.material = node.material.clone();
        node.userData.ref = inRoom ? null : refOf(node, names);
        this.meshes.push(node);
      }
    });
    this.scene.add(this.root);
    const box = new THREE.Box3();
    const shown = (o) => { for (; o; o = o.parent) if (!o.visible) return false; return true; };
    for (const m of this.meshes) if (m.userData.room && shown(m)) box.expandByObject(m);
    if (box.isEmpty()) box.setFromObject(this.root);
    const c = box.getCenter(new THREE.Vector3()), s = box.getSize(new THREE.Vector3());
    const d = Math.max(s.x, s.z) * 0.75 + 0.8;
    if (!this._framed) {
      this.camera.position.set(c.x + d * 0.45, c.y + d * 0.9, c.z + d * 0.9);
      this.controls.target.copy(c);
      this._framed = true;
    }
    this.controls.update();
    this._buildOverlay();
    this.select(null);
    this.render();
  }

  _partBox(ref) {
    const box = new THREE.Box3();
    for (const m of this.meshes) {
      const r = m.userData.ref;
      if (r && r.object === ref.object && (!ref.part || r.part === ref.part)) box.expandByObject(m);
    }
    return box;
  }

  _buildOverlay() {
    this.overlay.clear();
    const contacts = (this.result && this.result.contacts) || [];
    const pts = [], dots = [];
    const centre = (id, other) => {
      const [object, part] = id.split(":");
      if (object === "room") {
        // a contact with the shell: drop the other part's centre onto that element
        const b = this._partBox({ object: other.split(":")[0], part: other.split(":")[1] });
        const p = b.getCenter(new THREE.Vector3());
        if (part === "floor") p.y = 0.01;
        return p;
      }
      return this._partBox({ object, part }).getCenter(new THREE.Vector3());
    };
    for (const c of contacts) {
      const a = centre(c.a, c.b), b = centre(c.b, c.a);
      pts.push(a, b);
      dots.push(a, b);
    }
    const lines = new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(pts),
      new THREE.LineBasicMaterial({ color: 0xe53e3e, depthTest: false }));
    lines.renderOrder = 10;
    const points = new THREE.Points(new THREE.BufferGeometry().setFromPoints(dots),
      new THREE.PointsMaterial({ color: 0xc53030, size: 7, sizeAttenuation: false, depthTest: false }));
    points.renderOrder = 11;
    this.overlay.add(lines, points);
    for (const m of this.meshes) if (!m.userData.room) {
      m.material.transparent = this.overlay.visible;
      m.material.opacity = this.overlay.visible ? 0.55 : 1;
    }
  }

  showContacts(on) {
    this.overlay.visible = on;
    this._buildOverlay();
    this.render();
  }

  _up(e) {
    if (!this._down) return;
    const moved = Math.hypot(e.clientX - this._down[0], e.clientY - this._down[1]);
    this._down = null;
    if (moved > 4) return;
    const r = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
    // matrices are otherwise only brought up to date by a render, which may not have happened yet
    this.scene.updateMatrixWorld();
    this.camera.updateMatrixWorld();
    this.raycaster.setFromCamera(ndc, this.camera);
    const hit = this.raycaster.intersectObjects(this.meshes.filter((m) => m.visible && m.userData.ref), false)[0];
    this.select(hit ? hit.object.userData.ref.object : null);
  }

  // Highlight one object (or none) and report it with its relations and contacts.
  select(objectId) {
    for (const m of this.meshes) {
      if (!m.material.emissive) continue;
      const on = objectId && m.userData.ref && m.userData.ref.object === objectId;
      m.material.emissive.set(on ? 0x2b6cb0 : 0x000000);
      m.material.emissiveIntensity = on ? 0.5 : 0;
    }
    this.render();
    if (!objectId || !this.result) return this.onSelect(null);
    const obj = this.result.objects.find((o) => o.id === objectId);
    const of = (ref) => ref.split(/[:@#]/)[0];
    const relations = this.result.relations.filter((r) => of(r.child) === objectId || of(r.parent) === objectId);
    const contacts = (this.result.contacts || []).filter((c) => of(c.a) === objectId || of(c.b) === objectId);
    this.onSelect({ object: obj, relations, contacts });
  }

  // Page coordinates of an object's centre (for tests and the benchmark).
  screenPoint(objectId) {
    this.camera.updateMatrixWorld();
    const p = this._partBox({ object: objectId }).getCenter(new THREE.Vector3()).project(this.camera);
    const r = this.renderer.domElement.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }
}
