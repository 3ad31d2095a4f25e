// A live drawing of the PAG, after the paper's Fig. 2, laid out by support tree so that a
// room of 60 objects and more fits the panel without scrolling and without shrinking: the
// support trees are listed as indented outlines, one object a line (its circle, its label on
// the right), each room element that supports something heading its trees, and the lines
// flow into as many columns side by side as the panel's height asks for. A supporter stands
// above what it holds, linked by an elbow; parts that relations name are small dark circles
// on their object's left; other relations are curves coloured by kind (support solid blue,
// part-level dashed orange, object-level dotted green).
const NS = "http://www.w3.org/2000/svg";
export const KIND_COLOURS = { support: "#2b6cb0", part: "#dd6b20", object: "#38a169" };
const DASH = { support: "", part: "6 4", object: "2 4" };

const el = (tag, attrs = {}, text) => {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
};

function parseRef(text) {
  const m = /^([^:@#]+)(?::([^@#]+)(?:#(\d+))?)?(?:@(\w+))?$/.exec(String(text || ""));
  return m ? { object: m[1], part: m[2] || null, k: m[3], surface: m[4] || null } : null;
}
const roomOrder = (a, b) => {
  const key = (id) => (id === "floor" ? [0, 0] : id === "wall" ? [1, -1] : id.startsWith("wall_") ? [1, Number(id.slice(5))] : [2, 0]);
  const [x, y] = [key(a), key(b)];
  return x[0] - y[0] || x[1] - y[1];
};
const isRoom = (id) => id === "floor" || id === "ceiling" || id === "wall" || /^wall_\d+$/.test(id);

// Layout sizes, in px (the drawing is never scaled down)
const LINE = 26;     // vertical step between two outline lines (an object or a band header)
const R = 12;        // object radius
const INDENT = 10;   // horizontal step per support level
const MAX_DEPTH = 3; // deeper levels keep this indent (the elbows still show the tree)
const LEGEND = 24;   // height of the legend line
const CHAR = 6.2;    // px per label character at 10 px (labels are cut to their column)
const COLUMN_MIN = 112;

export function drawGraph(svg, doc, relations) {
  svg.replaceChildren();
  const kindOf = Object.fromEntries(relations.map((r) => [r.name, r.kind]));
  const objects = (doc.objects || []).map((o) => o.id).filter(Boolean);
  const known = new Set(objects);
  const rels = (doc.relations || []).map((r, i) => ({ ...r, i, c: parseRef(r.child), p: parseRef(r.parent) }))
    .filter((r) => r.c && r.p);
  // the support tree: each object under its (first) supporter; cycles and unknown supporters
  // leave an object at the top of its own tree
  const supporter = {};
  for (const r of rels) {
    if (kindOf[r.relation] === "support" && known.has(r.c.object) && !(r.c.object in supporter) &&
        (known.has(r.p.object) || isRoom(r.p.object))) supporter[r.c.object] = r.p.object;
  }
  const rootOf = (id) => {
    const seen = new Set();
    while (id in supporter && !isRoom(supporter[id]) && !seen.has(id)) { seen.add(id); id = supporter[id]; }
    return seen.has(id) ? null : id;
  };
  const kids = {};
  const tops = [];
  for (const id of objects) {
    const sup = supporter[id];
    if (sup && !isRoom(sup) && rootOf(id) !== null) (kids[sup] ||= []).push(id);
    else tops.push(id);
  }
  const bands = {};
  for (const id of tops) (bands[supporter[id] && isRoom(supporter[id]) ? supporter[id] : ""] ||= []).push(id);
  const order = Object.keys(bands).sort((a, b) => (a === "" ? 1 : b === "" ? -1 : roomOrder(a, b)));

  // the outline: band headers and objects, depth first
  const lines = [];
  const walk = (id, depth) => {
    lines.push({ id, depth });
    for (const k of kids[id] || []) walk(k, depth + 1);
  };
  for (const band of order) {
    if (band) lines.push({ band });
    for (const id of bands[band]) walk(id, 0);
  }
  // columns: as few as fit the panel's height, as many as its width allows
  const W = Math.max(360, svg.clientWidth || svg.parentElement?.clientWidth || 420);
  const box = svg.parentElement;
  const maxH = box ? parseFloat(getComputedStyle(box).maxHeight) || 0 : 0;
  const room = Math.max(LINE * 6, (maxH || 600) - LEGEND - 8);
  const widest = Math.max(1, Math.floor((W - 8) / COLUMN_MIN));
  const cols = Math.min(widest, Math.max(1, Math.ceil((lines.length * LINE) / room)));
  const perCol = Math.ceil(lines.length / cols);
  const colW = (W - 8) / cols;
  const pos = {}, roomBox = {}, fit = {};
  lines.forEach((ln, k) => {
    const col = Math.floor(k / perCol), row = k % perCol;
    const x0 = 4 + col * colW, y = LEGEND + row * LINE + LINE / 2;
    if (ln.band) (roomBox[ln.band] ||= []).push([x0 + 2, y - 9, colW - 8, 18]);
    else {
      pos[ln.id] = [x0 + 14 + Math.min(ln.depth, MAX_DEPTH) * INDENT + R, y];
      fit[ln.id] = Math.max(4, Math.floor((x0 + colW - pos[ln.id][0] - R - 10) / CHAR));
    }
  });
  const H = LEGEND + perCol * LINE + 6;
  svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
  svg.style.height = `${H}px`;

  // part nodes: on their object's left, fanned from above to below it
  const partPos = {};
  const parts = {};
  for (const r of rels) for (const ref of [r.c, r.p]) if (ref.part && pos[ref.object]) (parts[ref.object] ||= new Set()).add(ref.part);
  for (const [id, set] of Object.entries(parts)) {
    [...set].forEach((part, k) => {
      const a = Math.PI + (-0.4 + (0.8 * (k + 0.5)) / set.size) * Math.PI;
      partPos[`${id}:${part}`] = [pos[id][0] + (R + 6) * Math.cos(a), pos[id][1] + (R + 6) * Math.sin(a)];
    });
  }
  const at = (ref) => (ref.part && partPos[`${ref.object}:${ref.part}`]) || pos[ref.object];
  const defs = el("defs");
  for (const [kind, colour] of Object.entries(KIND_COLOURS)) {
    const m = el("marker", { id: `arrow-${kind}`, viewBox: "0 0 10 10", refX: 10, refY: 5, markerWidth: 6, markerHeight: 6, orient: "auto-start-reverse" });
    m.append(el("path", { d: "M 0 0 L 10 5 L 0 10 z", fill: colour }));
    defs.append(m);
  }
  svg.append(defs);
  const bandsG = el("g"), edges = el("g"), nodes = el("g");
  svg.append(bandsG, edges, nodes);
  for (const [key, [x, yy]] of Object.entries(partPos)) {
    const [id] = key.split(":");
    edges.append(el("line", { x1: pos[id][0], y1: pos[id][1], x2: x, y2: yy, stroke: "#333", "stroke-width": 1 }));
  }
  for (const r of rels) {
    const kind = kindOf[r.relation] || "object";
    const g = el("g", { class: `edge edge-${kind}`, "data-index": r.i });
    g.append(el("title", {}, `${r.child} ${r.relation} ${r.parent}`));
    if (kind === "support" && supporter[r.c.object] === r.p.object && pos[r.c.object]) {
      // the outline's own link: an elbow from the supporter (or the room element's header)
      // down its indent
      const c = pos[r.c.object];
      let p = pos[r.p.object];
      if (!p && roomBox[r.p.object]) { // from the room element's header, in the same column
        const [bx, by, bw, bh] = roomBox[r.p.object][0];
        if (c[0] < bx || c[0] > bx + bw) continue;
        p = [c[0] - R - INDENT, by + bh - R];
      }
      if (!p || c[0] <= p[0] || Math.abs(c[0] - p[0]) > INDENT * 2 + R || c[1] <= p[1]) continue;
      g.append(el("path", { d: `M ${p[0]} ${p[1] + R} V ${c[1]} H ${c[0] - R}`, fill: "none", stroke: KIND_COLOURS.support,
        "stroke-width": 2, "marker-end": "url(#arrow-support)" }));
      edges.append(g);
      continue;
    }
    let a = at(r.c), b = at(r.p);
    if (!b && isRoom(r.p.object) && roomBox[r.p.object] && a) {
      const [bx, by, , bh] = roomBox[r.p.object][0];
      b = [bx + 40, by + bh];
    }
    if (!a || !b) continue;
    const bend = kind === "support" ? 0 : Math.min(60, Math.hypot(b[0] - a[0], b[1] - a[1]) * 0.25);
    const mx = (a[0] + b[0]) / 2 + bend, my = (a[1] + b[1]) / 2 - bend * 0.5;
    g.append(el("path", { d: `M ${a[0]} ${a[1]} Q ${mx} ${my} ${b[0]} ${b[1]}`, fill: "none", stroke: KIND_COLOURS[kind],
      "stroke-width": kind === "support" ? 2.5 : 1.6, "stroke-dasharray": DASH[kind], "marker-end": `url(#arrow-${kind})`, opacity: 0.85 }));
    if (kind !== "support") g.append(el("text", { x: mx, y: my, fill: KIND_COLOURS[kind], "font-size": 9, "text-anchor": "middle", class: "edge-label" }, r.relation));
    edges.append(g);
  }
  for (const [id, heads] of Object.entries(roomBox)) {
    for (const [x, yy, w, hh] of heads) {
      const g = el("g", { class: "node room", "data-id": id });
      g.append(el("rect", { x, y: yy, width: w, height: hh, rx: 3, fill: "#e2e8f0", stroke: "#4a5568" }));
      g.append(el("text", { x: x + 8, y: yy + hh / 2 + 4, "font-size": 11, "font-weight": 600 }, id));
      nodes.append(g);
    }
  }
  for (const id of objects) {
    if (!pos[id]) continue;
    const [x, yy] = pos[id];
    const g = el("g", { class: "node object", "data-id": id });
    g.append(el("circle", { cx: x, cy: yy, r: R, fill: id in supporter ? "#fefcbf" : "#fed7d7", stroke: "#744210" }));
    g.append(el("text", { x: x + R + 4, y: yy + 4, "font-size": 10, class: "label" },
      id.length > fit[id] ? id.slice(0, fit[id] - 1) + "…" : id));
    g.append(el("title", {}, id));
    nodes.append(g);
  }
  const small = objects.length <= 20;
  for (const [key, [x, yy]] of Object.entries(partPos)) {
    const g = el("g", { class: "node part", "data-id": key });
    g.append(el("circle", { cx: x, cy: yy, r: 4, fill: "#2d3748" }));
    // part names label the dots of a small graph; in a large one they are the dot's tooltip
    if (small) g.append(el("text", { x: x + 6, y: yy - 3, "font-size": 9, fill: "#2d3748" }, key.split(":")[1]));
    g.append(el("title", {}, key));
    nodes.append(g);
  }
  const legend = el("g", { transform: "translate(8,12)" });
  Object.entries(KIND_COLOURS).forEach(([kind, colour], k) => {
    legend.append(el("line", { x1: k * 95, y1: 0, x2: k * 95 + 22, y2: 0, stroke: colour, "stroke-width": 2.5, "stroke-dasharray": DASH[kind] }));
    legend.append(el("text", { x: k * 95 + 27, y: 4, "font-size": 10 }, kind));
  });
  svg.append(legend);
}
