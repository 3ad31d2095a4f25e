// A live drawing of the PAG, after the paper's Fig. 2: objects as circles layered by support
// depth above the room elements (squares), the parts that relations name as small dark
// circles beside their object, and relation edges coloured by kind.
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
const MAX_ROW = 8;
const roomOrder = (a, b) => {
  const key = (id) => (id === "floor" ? [0, 0] : id === "wall" ? [1, -1] : id.startsWith("wall_") ? [1, Number(id.slice(5))] : [2, 0]);
  const [x, y] = [key(a), key(b)];
  return x[0] - y[0] || x[1] - y[1];
};
const isRoom = (id) => id === "floor" || id === "ceiling" || id === "wall" || /^wall_\d+$/.test(id);

export function drawGraph(svg, doc, relations) {
  svg.replaceChildren();
  const kindOf = Object.fromEntries(relations.map((r) => [r.name, r.kind]));
  const objects = (doc.objects || []).map((o) => o.id).filter(Boolean);
  const rels = (doc.relations || []).map((r, i) => ({ ...r, i, c: parseRef(r.child), p: parseRef(r.parent) }))
    .filter((r) => r.c && r.p);
  // support depth: room elements 0, an object one above its supporter
  const supporter = {};
  for (const r of rels) if (kindOf[r.relation] === "support" && !(r.c.object in supporter)) supporter[r.c.object] = r.p.object;
  const depth = {};
  const depthOf = (id, seen = new Set()) => {
    if (isRoom(id)) return 0;
    if (id in depth) return depth[id];
    if (seen.has(id) || !(id in supporter)) return 1;
    seen.add(id);
    return (depth[id] = depthOf(supporter[id], seen) + 1);
  };
  const rooms = [...new Set(rels.filter((r) => isRoom(r.p.object)).map((r) => r.p.object))].sort(roomOrder);
  const byDepth = {};
  for (const id of objects) (byDepth[depthOf(id)] ||= []).push(id);
  // long layers wrap onto several rows, so a 50-object room stays legible
  const rows = [rooms];
  const pos = {};
  const place = (ids, y, W) => ids.forEach((id, k) => { pos[id] = [((k + 0.5) * W) / ids.length, y]; });
  const layers = Object.keys(byDepth).map(Number).sort((a, b) => a - b);
  for (const d of layers) {
    const ids = byDepth[d];
    for (let k = 0; k < ids.length; k += MAX_ROW) rows.push(ids.slice(k, k + MAX_ROW));
  }
  const W = Math.max(420, 92 * Math.max(...rows.map((r) => r.length))), rowH = 78;
  const H = rowH * rows.length + 30;
  svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
  svg.style.height = `${Math.min(720, Math.max(220, ((svg.clientWidth || 420) * H) / W))}px`;
  rows.forEach((row, r) => {
    if (r > 0) row.sort((a, b) => ((pos[supporter[a]] || [W / 2])[0]) - ((pos[supporter[b]] || [W / 2])[0]));
    place(row, H - 24 - r * rowH, W);
  });
  // part nodes: beside their object, fanned out
  const partPos = {};
  const parts = {};
  for (const r of rels) for (const ref of [r.c, r.p]) if (ref.part && pos[ref.object]) (parts[ref.object] ||= new Set()).add(ref.part);
  for (const [id, set] of Object.entries(parts)) {
    [...set].forEach((part, k) => {
      const a = -Math.PI / 2 + (k - (set.size - 1) / 2) * 0.75;
      partPos[`${id}:${part}`] = [pos[id][0] + 34 * Math.cos(a) + 30, pos[id][1] + 26 * Math.sin(a) + 20];
    });
  }
  const at = (ref) => (ref.part && partPos[`${ref.object}:${ref.part}`]) || pos[ref.object];
  const defs = el("defs");
  for (const [kind, colour] of Object.entries(KIND_COLOURS)) {
    const m = el("marker", { id: `arrow-${kind}`, viewBox: "0 0 10 10", refX: 15, refY: 5, markerWidth: 7, markerHeight: 7, orient: "auto-start-reverse" });
    m.append(el("path", { d: "M 0 0 L 10 5 L 0 10 z", fill: colour }));
    defs.append(m);
  }
  svg.append(defs);
  const edges = el("g"), nodes = el("g");
  svg.append(edges, nodes);
  for (const [key, [x, y]] of Object.entries(partPos)) {
    const [id] = key.split(":");
    edges.append(el("line", { x1: pos[id][0], y1: pos[id][1], x2: x, y2: y, stroke: "#333", "stroke-width": 1 }));
  }
  for (const r of rels) {
    const a = at(r.c), b = at(r.p);
    if (!a || !b) continue;
    const kind = kindOf[r.relation] || "object";
    const g = el("g", { class: `edge edge-${kind}`, "data-index": r.i });
    g.append(el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: KIND_COLOURS[kind],
      "stroke-width": kind === "support" ? 3 : 2, "stroke-dasharray": DASH[kind], "marker-end": `url(#arrow-${kind})` }));
    g.append(el("text", { x: (a[0] + b[0]) / 2 + 4, y: (a[1] + b[1]) / 2 - 3, fill: KIND_COLOURS[kind], "font-size": 10 }, r.relation));
    g.append(el("title", {}, `${r.child} ${r.relation} ${r.parent}`));
    edges.append(g);
  }
  for (const id of rooms) {
    const [x, y] = pos[id];
    const g = el("g", { class: "node room", "data-id": id });
    g.append(el("rect", { x: x - 26, y: y - 13, width: 52, height: 26, rx: 3, fill: "#cbd5e0", stroke: "#4a5568" }));
    g.append(el("text", { x, y: y + 4, "text-anchor": "middle", "font-size": 11 }, id));
    nodes.append(g);
  }
  for (const id of objects) {
    if (!pos[id]) continue;
    const [x, y] = pos[id];
    const g = el("g", { class: "node object", "data-id": id });
    g.append(el("circle", { cx: x, cy: y, r: 22, fill: id in supporter ? "#fefcbf" : "#fed7d7", stroke: "#744210" }));
    g.append(el("text", { x, y: y + 4, "text-anchor": "middle", "font-size": 10 }, id.length > 10 ? id.slice(0, 9) + "…" : id));
    g.append(el("title", {}, id));
    nodes.append(g);
  }
  for (const [key, [x, y]] of Object.entries(partPos)) {
    const g = el("g", { class: "node part", "data-id": key });
    g.append(el("circle", { cx: x, cy: y, r: 5, fill: "#2d3748" }));
    g.append(el("text", { x: x + 7, y: y + 3, "font-size": 9, fill: "#2d3748" }, key.split(":")[1]));
    nodes.append(g);
  }
  const legend = el("g", { transform: "translate(8,14)" });
  Object.entries(KIND_COLOURS).forEach(([kind, colour], k) => {
    legend.append(el("line", { x1: k * 95, y1: 0, x2: k * 95 + 22, y2: 0, stroke: colour, "stroke-width": 2.5, "stroke-dasharray": DASH[kind] }));
    legend.append(el("text", { x: k * 95 + 27, y: 4, "font-size": 10 }, kind));
  });
  svg.append(legend);
}
