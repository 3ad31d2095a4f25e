// A live drawing of the PAG, after the paper's Fig. 2, laid out by support tree so that it
// stays readable at 60 objects and more: each room element that supports something heads a
// band; in it, every object it supports heads a cluster with the objects on (in, under) it
// in rows below, and so on down the support tree. Clusters wrap onto new rows at the panel's
// width and the drawing grows downwards (the panel scrolls) instead of shrinking, so labels
// keep their size. Parts that relations name are small dark circles beside their object;
// support edges are short links inside a cluster, other relations are curves coloured by
// kind (support solid blue, part-level dashed orange, object-level dotted green).
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
const SLOT = 74;     // horizontal room of one object
const LEVEL = 62;    // vertical step from an object to those it supports
const R = 15;        // object radius
const BAND = 30;     // height of a room element's band header
const GAP = 14;      // between clusters
const LABEL = 11;    // characters of an object label

// A cluster: an object and, below it, what it supports; returns its size and places it.
function measure(id, kids, maxW) {
  const sub = (kids[id] || []).map((k) => measure(k, kids, maxW));
  // children in rows no wider than the panel
  const rows = [];
  let row = [], w = 0;
  for (const c of sub) {
    if (row.length && w + c.w > maxW) { rows.push({ items: row, w: w - GAP }); row = []; w = 0; }
    row.push(c); w += c.w + GAP;
  }
  if (row.length) rows.push({ items: row, w: w - GAP });
  const width = Math.max(SLOT, ...rows.map((r) => r.w));
  const height = LEVEL * (rows.length ? 1 : 0) + rows.reduce((s, r) => s + Math.max(...r.items.map((c) => c.h)), 0) + (rows.length ? (rows.length - 1) * 10 : 0);
  return { id, w: width, h: Math.max(LEVEL, height), rows };
}

function place(c, x, y, pos) {
  pos[c.id] = [x + c.w / 2, y + R + 2];
  let yy = y + LEVEL;
  for (const r of c.rows) {
    let xx = x + (c.w - r.w) / 2;
    for (const item of r.items) { place(item, xx, yy, pos); xx += item.w + GAP; }
    yy += Math.max(...r.items.map((i) => i.h)) + 10;
  }
}

export function drawGraph(svg, doc, relations) {
  svg.replaceChildren();
  const kindOf = Object.fromEntries(relations.map((r) => [r.name, r.kind]));
  const objects = (doc.objects || []).map((o) => o.id).filter(Boolean);
  const known = new Set(objects);
  const rels = (doc.relations || []).map((r, i) => ({ ...r, i, c: parseRef(r.child), p: parseRef(r.parent) }))
    .filter((r) => r.c && r.p);
  // the support tree: each object under its (first) supporter; cycles and unknown supporters
  // leave an object at the top of its own cluster
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

  const W = Math.max(360, svg.clientWidth || svg.parentElement?.clientWidth || 420);
  const pos = {}, roomBox = {};
  let y = 26; // below the legend
  for (const band of order) {
    if (band) roomBox[band] = [8, y, W - 16, BAND - 6];
    y += band ? BAND : 6;
    let x = 8, rowH = 0;
    for (const id of bands[band]) {
      const c = measure(id, kids, W - 16);
      if (x > 8 && x + c.w > W - 8) { x = 8; y += rowH + GAP; rowH = 0; }
      place(c, x, y, pos);
      x += c.w + GAP;
      rowH = Math.max(rowH, c.h);
    }
    y += rowH + GAP;
  }
  const H = y + 4;
  svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
  svg.style.height = `${H}px`;

  // part nodes: beside their object, fanned out below it
  const partPos = {};
  const parts = {};
  for (const r of rels) for (const ref of [r.c, r.p]) if (ref.part && pos[ref.object]) (parts[ref.object] ||= new Set()).add(ref.part);
  for (const [id, set] of Object.entries(parts)) {
    [...set].forEach((part, k) => {
      // on the object's right, from above to below it
      const a = (-0.45 + (0.9 * (k + 0.5)) / set.size) * Math.PI;
      partPos[`${id}:${part}`] = [pos[id][0] + (R + 10) * Math.cos(a), pos[id][1] + (R + 10) * Math.sin(a)];
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
    if (kind === "support" && isRoom(r.p.object) && roomBox[r.p.object] && pos[r.c.object]) {
      // to the band above: a short tick, not a line across the drawing
      const [x, yy] = at(r.c);
      const top = roomBox[r.p.object][1] + roomBox[r.p.object][3];
      const from = pos[r.c.object][1] - R;
      if (supporter[r.c.object] !== r.p.object || from - top > LEVEL) continue; // drawn by its band
      g.append(el("line", { x1: x, y1: Math.min(yy, from), x2: x, y2: top, stroke: KIND_COLOURS.support, "stroke-width": 2, "marker-end": "url(#arrow-support)" }));
      edges.append(g);
      continue;
    }
    let a = at(r.c), b = at(r.p);
    if (!b && isRoom(r.p.object) && roomBox[r.p.object] && a) b = [a[0], roomBox[r.p.object][1] + roomBox[r.p.object][3]];
    if (!a || !b) continue;
    const bend = kind === "support" ? 0 : Math.min(60, Math.hypot(b[0] - a[0], b[1] - a[1]) * 0.25);
    const mx = (a[0] + b[0]) / 2 + bend, my = (a[1] + b[1]) / 2 - bend * 0.5;
    g.append(el("path", { d: `M ${a[0]} ${a[1]} Q ${mx} ${my} ${b[0]} ${b[1]}`, fill: "none", stroke: KIND_COLOURS[kind],
      "stroke-width": kind === "support" ? 2.5 : 1.6, "stroke-dasharray": DASH[kind], "marker-end": `url(#arrow-${kind})`, opacity: 0.85 }));
    if (kind !== "support") g.append(el("text", { x: mx, y: my, fill: KIND_COLOURS[kind], "font-size": 9, "text-anchor": "middle", class: "edge-label" }, r.relation));
    edges.append(g);
  }
  for (const [id, [x, yy, w, hh]] of Object.entries(roomBox)) {
    const g = el("g", { class: "node room", "data-id": id });
    g.append(el("rect", { x, y: yy, width: w, height: hh, rx: 3, fill: "#e2e8f0", stroke: "#4a5568" }));
    g.append(el("text", { x: x + 8, y: yy + hh / 2 + 4, "font-size": 11, "font-weight": 600 }, id));
    nodes.append(g);
  }
  for (const id of objects) {
    if (!pos[id]) continue;
    const [x, yy] = pos[id];
    const g = el("g", { class: "node object", "data-id": id });
    g.append(el("circle", { cx: x, cy: yy, r: R, fill: id in supporter ? "#fefcbf" : "#fed7d7", stroke: "#744210" }));
    g.append(el("text", { x, y: yy + R + 11, "text-anchor": "middle", "font-size": 10, class: "label" },
      id.length > LABEL ? id.slice(0, LABEL - 1) + "…" : id));
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
