// The room's footprint, typed or drawn: an SVG pad in metres (y up) where clicks add
// vertices snapped to 10 cm; clicking the first vertex again (or "Done") closes the outline.
// Walls are labelled wall_0 ... wall_{n-1} as the PAG numbers them.
const NS = "http://www.w3.org/2000/svg";
const el = (tag, attrs = {}, text) => {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
};

export function signedArea(pts) {
  let a = 0;
  for (let i = 0; i < pts.length; i++) {
    const [x1, y1] = pts[i], [x2, y2] = pts[(i + 1) % pts.length];
    a += x1 * y2 - x2 * y1;
  }
  return a / 2;
}

// The same outline the other way round, from the same first vertex.
export const counterClockwise = (pts) => [pts[0], ...pts.slice(1).reverse()];

export function parseFootprint(text) {
  const pts = [];
  for (const line of text.split(/\n|;/)) {
    if (!line.trim()) continue;
    const nums = line.split(/[\s,]+/).filter(Boolean).map(Number);
    if (nums.length !== 2 || nums.some((v) => !Number.isFinite(v))) return null;
    pts.push(nums);
  }
  return pts;
}

export const formatFootprint = (pts) => pts.map(([x, y]) => `${+x.toFixed(3)}, ${+y.toFixed(3)}`).join("\n");

export class FootprintPad {
  constructor(svg, { onChange }) {
    this.svg = svg;
    this.onChange = onChange;
    this.points = [];
    this.drawing = null;
    svg.addEventListener("click", (e) => this._click(e));
  }

  set(points) {
    this.points = points || [];
    this.draw();
  }

  start() {
    this.drawing = [];
    this.draw();
  }

  finish() {
    if (!this.drawing) return;
    let pts = this.drawing;
    this.drawing = null;
    if (pts.length >= 3) {
      if (signedArea(pts) < 0) pts = counterClockwise(pts); // walls are numbered counter-clockwise
      this.points = pts;
      this.onChange(pts);
    }
    this.draw();
  }

  _view() {
    const all = [...this.points, ...(this.drawing || []), [0, 0], [8, 6]];
    const xs = all.map((p) => p[0]), ys = all.map((p) => p[1]);
    const x0 = Math.floor(Math.min(...xs)) - 1, y0 = Math.floor(Math.min(...ys)) - 1;
    const size = Math.ceil(Math.max(Math.max(...xs) - x0, Math.max(...ys) - y0)) + 1;
    return { x0, y0, size };
  }

  _click(e) {
    if (!this.drawing) return;
    const pt = this.svg.createSVGPoint();
    pt.x = e.clientX; pt.y = e.clientY;
    const p = pt.matrixTransform(this.svg.getScreenCTM().inverse());
    const { y0, size } = this.v;
    const x = Math.round(p.x * 10) / 10, y = Math.round((2 * y0 + size - p.y) * 10) / 10;
    const first = this.drawing[0];
    if (first && this.drawing.length >= 3 && Math.hypot(first[0] - x, first[1] - y) < 0.25) return this.finish();
    this.drawing.push([x, y]);
    this.draw();
  }

  draw() {
    const v = (this.v = this._view());
    const { x0, y0, size } = v;
    const Y = (y) => 2 * y0 + size - y; // flip: y up
    this.svg.setAttribute("viewBox", `${x0} ${y0} ${size} ${size}`);
    this.svg.replaceChildren();
    const grid = el("g", { stroke: "#e2e8f0", "stroke-width": 0.02 });
    for (let k = 0; k <= size; k++) {
      grid.append(el("line", { x1: x0 + k, y1: y0, x2: x0 + k, y2: y0 + size }));
      grid.append(el("line", { x1: x0, y1: y0 + k, x2: x0 + size, y2: y0 + k }));
    }
    this.svg.append(grid);
    this.svg.append(el("text", { x: x0 + 0.1, y: Y(y0) - 0.1, "font-size": 0.3, fill: "#718096" }, "1 m grid"));
    const pts = this.drawing || this.points;
    if (pts.length) {
      const d = pts.map(([x, y]) => `${x},${Y(y)}`).join(" ");
      this.svg.append(el(this.drawing ? "polyline" : "polygon", { points: d, fill: this.drawing ? "none" : "#ebf8ff",
        stroke: this.drawing ? "#dd6b20" : "#2b6cb0", "stroke-width": 0.05 }));
      if (!this.drawing) {
        pts.forEach(([x, y], i) => {
          const [x2, y2] = pts[(i + 1) % pts.length];
          this.svg.append(el("text", { x: (x + x2) / 2, y: Y((y + y2) / 2), "font-size": 0.32, fill: "#2c5282",
            "text-anchor": "middle", "dominant-baseline": "middle" }, `wall_${i}`));
        });
      }
      for (const [x, y] of pts) this.svg.append(el("circle", { cx: x, cy: Y(y), r: 0.08, fill: "#2d3748" }));
    }
  }
}
