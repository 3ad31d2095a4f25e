"""A self-contained three.js page showing a scene: the notebook view and ``Scene.show()``.

The page holds everything it needs, so it works offline and from a single file: the scene as
GLB and the three.js modules the designer ships (``parse3d/web/static/vendor/``), each
base64-encoded in a ``<script type="application/octet-stream">`` block and loaded as a module
from a ``blob:`` URL. Drag to orbit, scroll to zoom; hovering a mesh names its object and
part. Notebooks get the page inside an ``<iframe srcdoc>``, where its scripts run.
"""

from __future__ import annotations

import base64
import html
from pathlib import Path

__all__ = ["VENDOR", "viewer_page", "viewer_iframe"]

#: The vendored three.js release of the web designer.
VENDOR = Path(__file__).resolve().parent.parent / "web" / "static" / "vendor"
_MODULES = {"p3d-three": "three.module.min.js",
            "p3d-bgu": "addons/utils/BufferGeometryUtils.js",
            "p3d-gltf": "addons/loaders/GLTFLoader.js",
            "p3d-orbit": "addons/controls/OrbitControls.js"}

_SCRIPT = r"""
(async () => {
  const bytes = (id) => Uint8Array.from(atob(document.getElementById(id).textContent.trim()),
                                        (c) => c.charCodeAt(0));
  const text = (id) => new TextDecoder().decode(bytes(id));
  const url = (src) => URL.createObjectURL(new Blob([src], { type: "text/javascript" }));
  const three = url(text("p3d-three"));
  const fix = (src) => src.replace(/from\s*(['"])three\1/g, () => `from "${three}"`);
  const bgu = url(fix(text("p3d-bgu")));
  const gltfUrl = url(fix(text("p3d-gltf")).replace(
    /(['"])\.\.\/utils\/BufferGeometryUtils\.js\1/g, () => `"${bgu}"`));
  const [THREE, { GLTFLoader }, { OrbitControls }] = await Promise.all(
    [import(three), import(gltfUrl), import(url(fix(text("p3d-orbit"))))]);
  const box = document.getElementById("p3d-view"), label = document.getElementById("p3d-label");
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setClearColor(0xe8ebef);
  box.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x7a7a7a, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(3, 8, 2);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(50, 1, 0.05, 200);
  const controls = new OrbitControls(camera, renderer.domElement);
  const draw = () => renderer.render(scene, camera);
  controls.addEventListener("change", draw);
  const resize = () => {
    const w = box.clientWidth || 640, h = box.clientHeight || 480;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    draw();
  };
  new ResizeObserver(resize).observe(box);
  const gltf = await new GLTFLoader().parseAsync(bytes("p3d-glb").buffer, "");
  scene.add(gltf.scene);
  // the object and part a mesh shows, from the exporter's node extras, else its node names
  const nameOf = (node) => {
    let object = null, part = null;
    for (let n = node; n; n = n.parent) {
      const x = n.userData || {};
      part = part || x.part_name || x.part || null;
      if (x.object_id) { object = x.object_id; break; }
    }
    if (!object) return node.parent && node.parent.name ? node.parent.name : node.name;
    if (part && part.includes(":")) part = part.slice(part.indexOf(":") + 1);
    return part ? `${object} : ${part}` : object;
  };
  const meshes = [];
  gltf.scene.traverse((n) => { if (n.isMesh) meshes.push(n); });
  const bounds = new THREE.Box3().setFromObject(gltf.scene);
  const c = bounds.getCenter(new THREE.Vector3()), s = bounds.getSize(new THREE.Vector3());
  const d = Math.max(s.x, s.z) * 0.75 + 0.8;
  camera.position.set(c.x + d * 0.45, c.y + d * 0.9, c.z + d * 0.9);
  controls.target.copy(c);
  controls.update();
  const ray = new THREE.Raycaster(), at = new THREE.Vector2();
  renderer.domElement.addEventListener("pointermove", (e) => {
    const r = renderer.domElement.getBoundingClientRect();
    at.set(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
    ray.setFromCamera(at, camera);
    const hit = ray.intersectObjects(meshes, false)[0];
    label.textContent = hit ? nameOf(hit.object) : "";
  });
  resize();
  window.parse3dViewer = { names: [...new Set(meshes.map(nameOf))], meshes: meshes.length };
  document.body.dataset.ready = "1";
})().catch((e) => {
  document.getElementById("p3d-label").textContent = "the viewer failed: " + e;
  document.body.dataset.ready = "error";
});
"""


def _b64(data: bytes) -> str:
    return base64.b64encode(data).decode("ascii")


def viewer_page(glb: bytes, title: str = "parse3d scene") -> str:
    """A complete HTML page showing the GLB scene ``glb`` (offline, one file)."""
    blocks = [f'<script id="{i}" type="application/octet-stream">{_b64((VENDOR / f).read_bytes())}'
              "</script>" for i, f in _MODULES.items()]
    blocks.append(f'<script id="p3d-glb" type="application/octet-stream">{_b64(glb)}</script>')
    return ("<!doctype html>\n<html><head><meta charset=\"utf-8\">"
            f"<title>{html.escape(title)}</title><style>"
            "html,body{margin:0;height:100%;font:13px sans-serif}"
            "#p3d-view{position:absolute;inset:0}"
            "#p3d-label{position:absolute;left:8px;top:6px;pointer-events:none;color:#222}"
            "</style></head><body>"
            '<div id="p3d-view"></div><div id="p3d-label"></div>\n'
            + "\n".join(blocks) + f"\n<script>{_SCRIPT}</script>\n"
            "<!-- three.js (MIT licence): parse3d/web/static/vendor/LICENSE -->\n"
            "</body></html>\n")


def viewer_iframe(page: str, *, height: int = 480) -> str:
    """``page`` inside an ``<iframe srcdoc>``: HTML a notebook output shows with its scripts."""
    return (f'<iframe srcdoc="{html.escape(page, quote=True)}" style="width:100%;'
            f'height:{int(height)}px;border:1px solid #ccc" title="parse3d scene"></iframe>')
