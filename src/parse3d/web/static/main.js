// The PAG designer: room, objects, a relation editor that picks parts and surfaces by clicking
// 3-D previews, a live graph, inline validation, solving with progress and a scene viewer.
import { api, follow } from "./api.js";
import { AssetPicker } from "./picker.js";
import { SceneViewer } from "./viewer.js";
import { drawGraph, KIND_COLOURS } from "./graph.js";
import { counterClockwise, FootprintPad, formatFootprint, parseFootprint, signedArea } from "./room.js";

const $ = (sel, root = document) => root.querySelector(sel);
const h = (tag, attrs = {}, ...kids) => {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else if (v === true) e.setAttribute(k, "");
    else if (v !== false && v !== null && v !== undefined) e.setAttribute(k, v);
  }
  for (const kid of kids.flat()) if (kid !== null && kid !== undefined) e.append(kid);
  return e;
};
const SURFACES = ["top", "bottom", "front", "back", "left", "right"];
const isRoom = (id) => id === "floor" || id === "ceiling" || id === "wall" || /^wall_\d+$/.test(id);
const refObject = (ref) => String(ref || "").split(/[:@#]/)[0];

const newDoc = () => ({
  format: "pag/1", name: "my-room",
  room: { type: "study", footprint: [[0, 0], [4, 0], [4, 3.5], [0, 3.5]], height: 2.7 },
  objects: [], relations: [],
});

const state = {
  doc: newDoc(), vocab: null, relations: {}, problems: [], validating: 0,
  job: null, result: null,
  ed: { child: {}, parent: {}, relation: "ON" },
};
window.designer = { state };

// ------------------------------------------------------------------ messages
function say(text, kind = "info") {
  const box = $("#message");
  box.textContent = text;
  box.className = `message ${kind}`;
}

// ------------------------------------------------------------------ undo / redo
// Snapshots of the PAG document: every change is one step (typing into one field within a
// moment is one step, not one per key); undo and redo restore the document and re-render,
// leaving the relation editor's picks alone.
const history = { past: [], future: [], current: null, at: 0, field: null };
window.designer.history = history;

function remember({ coalesce = false } = {}) {
  const snap = JSON.stringify(state.doc);
  if (snap === history.current) return;
  const now = performance.now();
  if (history.current !== null && !(coalesce && history.field && now - history.at < 800)) {
    history.past.push(history.current);
    if (history.past.length > 300) history.past.shift();
  }
  history.current = snap;
  history.future = [];
  history.at = now;
  history.field = coalesce;
  updateUndo();
}

function resetHistory() {
  history.past = []; history.future = [];
  history.current = JSON.stringify(state.doc);
  history.field = null;
  updateUndo();
}

function updateUndo() {
  $("#undo").disabled = !history.past.length;
  $("#redo").disabled = !history.future.length;
}

function travel(from, to, verb) {
  if (!from.length) return;
  to.push(history.current);
  history.current = from.pop();
  history.field = null;
  state.doc = JSON.parse(history.current);
  renderRoom();
  changed({ record: false });
  updateUndo();
  say(`${verb} (${history.past.length} step${history.past.length === 1 ? "" : "s"} to undo)`);
}
const undo = () => travel(history.past, history.future, "undone");
const redo = () => travel(history.future, history.past, "redone");

function setupUndo() {
  $("#undo").addEventListener("click", undo);
  $("#redo").addEventListener("click", redo);
  document.addEventListener("keydown", (e) => {
    if (!(e.ctrlKey || e.metaKey)) return;
    // inside a text field the browser's own undo edits the text being typed
    const t = e.target;
    if (t && (t.tagName === "TEXTAREA" || (t.tagName === "INPUT" && !["checkbox", "button", "file"].includes(t.type)))) return;
    const key = e.key.toLowerCase();
    if (key === "z" && !e.shiftKey) { e.preventDefault(); undo(); }
    else if ((key === "z" && e.shiftKey) || key === "y") { e.preventDefault(); redo(); }
  });
  updateUndo();
}

// ------------------------------------------------------------------ validation
let validateTimer = null;
function changed({ structure = true, record = true } = {}) {
  state.dirty = true;
  if (record) remember({ coalesce: !structure });
  if (structure) { renderObjects(); renderRelations(); renderEditorChoices(); }
  drawGraph($("#graph"), state.doc, state.vocab.relations);
  clearTimeout(validateTimer);
  validateTimer = setTimeout(validate, 150);
}

async function validate() {
  const n = ++state.validating;
  try {
    const res = await api.validate(state.doc);
    if (n !== state.validating) return;
    state.problems = res.problems;
  } catch (e) {
    state.problems = [{ pointer: "/", message: e.message, kind: "syntax" }];
  }
  showProblems();
}

// Each problem goes next to the field whose data-pointer is the longest prefix of its pointer.
function showProblems() {
  document.querySelectorAll(".problem").forEach((p) => p.remove());
  document.querySelectorAll(".has-problem").forEach((p) => p.classList.remove("has-problem"));
  const fields = [...document.querySelectorAll("[data-pointer]")];
  for (const pr of state.problems) {
    const ptr = pr.pointer === "/" ? "" : pr.pointer;
    let best = null;
    for (const f of fields) {
      const fp = f.dataset.pointer;
      if ((ptr === fp || ptr.startsWith(fp + "/")) && (!best || fp.length > best.dataset.pointer.length)) best = f;
    }
    const msg = h("div", { class: "problem", "data-for": pr.pointer, role: "alert" }, pr.message);
    if (best) {
      best.classList.add("has-problem");
      (best.closest(".row") && best.closest(".row") !== best ? best.closest(".row") : best).after(msg);
    } else $("#problems-general").append(msg);
  }
  const n = state.problems.length;
  const badge = $("#validity");
  badge.textContent = n ? `${n} problem${n > 1 ? "s" : ""}` : "valid";
  badge.className = n ? "badge bad" : "badge good";
}

// ------------------------------------------------------------------ room
let pad;
function renderRoom() {
  const r = state.doc.room;
  $("#pag-name").value = state.doc.name || "";
  $("#room-type").value = r.type || "";
  $("#room-height").value = r.height ?? "";
  $("#footprint").value = formatFootprint(r.footprint || []);
  pad.set(r.footprint || []);
  $("#reverse").hidden = !(r.footprint && r.footprint.length >= 3 && signedArea(r.footprint) < 0);
}

function setupRoom() {
  pad = new FootprintPad($("#pad"), {
    onChange: (pts) => { state.doc.room.footprint = pts; renderRoom(); renderEditorChoices(); changed({ structure: false }); },
  });
  $("#pag-name").addEventListener("input", (e) => { state.doc.name = e.target.value; changed({ structure: false }); });
  $("#room-type").addEventListener("input", (e) => { state.doc.room.type = e.target.value; changed({ structure: false }); });
  $("#room-height").addEventListener("input", (e) => {
    state.doc.room.height = e.target.value === "" ? null : Number(e.target.value); changed({ structure: false });
  });
  $("#footprint").addEventListener("change", (e) => {
    const pts = parseFootprint(e.target.value);
    if (!pts) return say("footprint: write one 'x, y' pair of metres per line", "bad");
    state.doc.room.footprint = pts;
    renderRoom(); renderEditorChoices(); changed({ structure: false });
  });
  $("#draw").addEventListener("click", () => { pad.start(); say("click the corners on the grid; click the first corner again to close"); });
  $("#draw-done").addEventListener("click", () => pad.finish());
  $("#reverse").addEventListener("click", () => {
    state.doc.room.footprint = counterClockwise(state.doc.room.footprint);
    renderRoom(); renderEditorChoices(); changed({ structure: false });
  });
  for (const t of state.vocab.room_types) $("#room-types").append(h("option", { value: t }));
}

// ------------------------------------------------------------------ objects
function uniqueId(base) {
  const ids = new Set(state.doc.objects.map((o) => o.id));
  base = base.replace(/[^A-Za-z0-9_-]/g, "_").replace(/^([^A-Za-z_])/, "_$1");
  if (!ids.has(base)) return base;
  for (let k = 2; ; k++) if (!ids.has(`${base}_${k}`)) return `${base}_${k}`;
}

function addObject(category) {
  category = category.trim();
  if (!category) return;
  const known = state.vocab.categories.some((c) => c.name === category);
  const id = uniqueId(category);
  state.doc.objects.push({ id, category });
  $("#add-category").value = "";
  changed();
  say(known ? `added ${id}` : `added ${id}: '${category}' is not a known category (see the problem below)`, known ? "info" : "bad");
  return id;
}

function renameRefs(oldId, newId) {
  for (const r of state.doc.relations) {
    for (const key of ["child", "parent"]) {
      if (refObject(r[key]) === oldId) r[key] = newId + String(r[key]).slice(oldId.length);
    }
  }
}

function renderObjects() {
  const list = $("#objects");
  list.replaceChildren();
  state.doc.objects.forEach((o, i) => {
    const cats = Array.isArray(o.category) ? o.category.join(", ") : o.category || "";
    const scale = o.scale || ["", ""];
    const row = h("div", { class: "row object", "data-pointer": `/objects/${i}`, "data-id": o.id },
      h("input", { class: "obj-id", value: o.id, "data-pointer": `/objects/${i}/id`, title: "object id", size: 10,
        onchange: (e) => { const old = o.id; o.id = e.target.value.trim(); renameRefs(old, o.id); changed(); } }),
      h("input", { class: "obj-cat", value: cats, list: "categories", "data-pointer": `/objects/${i}/category`,
        title: "category, or several candidates separated by commas (the solver picks one)",
        onchange: (e) => {
          const parts = e.target.value.split(",").map((s) => s.trim()).filter(Boolean);
          o.category = parts.length === 1 ? parts[0] : parts;
          changed();
        } }),
      h("span", { class: "scale", "data-pointer": `/objects/${i}/scale`, title: "scale factor range [low, high] (empty: none)" }, "×",
        ...[0, 1].map((k) => h("input", { type: "number", step: "0.05", min: "0.05", value: scale[k], class: `scale-${k}`, size: 4,
          onchange: (e) => {
            const lo = $(".scale-0", row).value, hi = $(".scale-1", row).value;
            if (lo === "" && hi === "") delete o.scale;
            else o.scale = [Number(lo || hi), Number(hi || lo)];
            changed({ structure: false });
          } }))),
      h("button", { class: "small", title: "relate this object to another", onclick: () => chooseChild(o.id) }, "relate"),
      h("button", { class: "small danger", title: "remove the object and its relations", onclick: () => {
        const before = state.doc.relations.length;
        state.doc.objects.splice(i, 1);
        state.doc.relations = state.doc.relations.filter((r) => refObject(r.child) !== o.id && refObject(r.parent) !== o.id);
        changed();
        say(`removed ${o.id} and ${before - state.doc.relations.length} relation(s)`);
      } }, "✕"));
    list.append(row);
  });
  $("#objects-empty").hidden = state.doc.objects.length > 0;
}

// ------------------------------------------------------------------ relations list
function formatParam(v) {
  return Array.isArray(v) ? v.join(", ") : v === undefined ? "" : String(v);
}
function parseParam(text) {
  const t = text.trim();
  if (t === "") return undefined;
  const nums = t.split(/[\s,]+/).map(Number);
  if (nums.every(Number.isFinite)) return nums.length === 1 ? nums[0] : nums;
  return t;
}

function renderRelations() {
  const list = $("#relations");
  list.replaceChildren();
  state.doc.relations.forEach((r, i) => {
    const rel = state.relations[r.relation];
    const paramKeys = [...new Set([...(rel ? rel.params.map((p) => p.name) : []),
      ...Object.keys(r).filter((k) => !["relation", "child", "parent"].includes(k))])];
    const kind = rel ? rel.kind : "object";
    const row = h("div", { class: `row relation kind-${kind}`, "data-pointer": `/relations/${i}`, style: `border-left-color:${KIND_COLOURS[kind]}` },
      h("input", { class: "rel-child", value: r.child ?? "", "data-pointer": `/relations/${i}/child`, size: 16,
        onchange: (e) => { r.child = e.target.value.trim(); changed(); } }),
      h("select", { class: "rel-name", "data-pointer": `/relations/${i}/relation`,
        onchange: (e) => { r.relation = e.target.value; changed(); } },
        ...Object.keys(state.relations).map((n) => h("option", { value: n, selected: n === r.relation }, n)),
        rel ? null : h("option", { value: r.relation, selected: true }, String(r.relation))),
      h("input", { class: "rel-parent", value: r.parent ?? "", "data-pointer": `/relations/${i}/parent`, size: 16,
        onchange: (e) => { r.parent = e.target.value.trim(); changed(); } }),
      ...paramKeys.map((k) => {
        const p = rel && rel.params.find((q) => q.name === k);
        return h("label", { class: "param", "data-pointer": `/relations/${i}/${k}` }, `${k}`,
          h("input", { value: formatParam(r[k]), size: 6, placeholder: p && p.default !== null ? formatParam(p.default) : "required",
            title: p ? `${p.doc} (${p.unit || p.type}${p.low !== null ? `, ${p.low}–${p.high}` : ""})` : "not a parameter of this relation",
            onchange: (e) => { const v = parseParam(e.target.value); if (v === undefined) delete r[k]; else r[k] = v; changed({ structure: false }); } }),
          p && p.unit ? h("span", { class: "unit" }, p.unit) : null);
      }),
      h("button", { class: "small danger", title: "remove the relation", onclick: () => { state.doc.relations.splice(i, 1); changed(); } }, "✕"));
    list.append(row);
  });
  $("#relations-empty").hidden = state.doc.relations.length > 0;
}

// ------------------------------------------------------------------ relation editor
const pickers = {};

function refOf(sel, objectLevel) {
  if (!sel.object) return "";
  if (objectLevel || isRoom(sel.object) || !sel.part) return sel.object;
  return `${sel.object}:${sel.part}${sel.exact && sel.count > 1 ? `#${sel.k}` : ""}${sel.surface ? `@${sel.surface}` : ""}`;
}

function renderEditorChoices() {
  const ids = state.doc.objects.map((o) => o.id);
  const n = (state.doc.room.footprint || []).length;
  const walls = Array.from({ length: n }, (_, i) => `wall_${i}`);
  for (const side of ["child", "parent"]) {
    const sel = $(`#${side}-object`);
    const current = state.ed[side].object || "";
    const opts = [h("option", { value: "" }, side === "child" ? "— child object —" : "— parent —")];
    opts.push(h("optgroup", { label: "objects" }, ...ids.map((id) => h("option", { value: id, selected: id === current }, id))));
    if (side === "parent") {
      opts.push(h("optgroup", { label: "room" }, ...["floor", "ceiling", "wall", ...walls].map((id) =>
        h("option", { value: id, selected: id === current }, id))));
    }
    sel.replaceChildren(...opts);
    if (current && !ids.includes(current) && !(side === "parent" && isRoom(current))) setSide(side, "");
  }
  updateReadouts();
}

function candidatesOf(id) {
  const o = state.doc.objects.find((x) => x.id === id);
  if (!o) return [];
  return (Array.isArray(o.category) ? o.category : [o.category]).filter((c) => state.vocab.categories.some((k) => k.name === c));
}

async function setSide(side, id) {
  const ed = state.ed[side] = { object: id };
  const picker = pickers[side];
  const box = $(`#${side}-preview`);
  const variantSel = $(`#${side}-variant`);
  variantSel.replaceChildren();
  updateReadouts();
  if (!id || isRoom(id)) {
    picker.clear();
    box.classList.add("empty");
    $(`#${side}-hint`).textContent = id ? `${id} is a room element: no parts to pick` : "";
    return;
  }
  const cands = candidatesOf(id);
  if (!cands.length) { picker.clear(); $(`#${side}-hint`).textContent = "unknown category: no preview"; return; }
  for (const c of cands) {
    const cat = state.vocab.categories.find((k) => k.name === c);
    for (const v of cat.variants) variantSel.append(h("option", { value: `${c}|${v}` }, cands.length > 1 ? `${c} · ${v}` : v));
  }
  box.classList.remove("empty");
  $(`#${side}-hint`).textContent = "loading preview…";
  await loadPreview(side);
  if (state.ed[side] === ed) $(`#${side}-hint`).textContent = "click a part; then an arrow to choose a surface other than the default";
}

async function loadPreview(side) {
  const [category, variant] = $(`#${side}-variant`).value.split("|");
  const picker = pickers[side];
  try {
    await picker.load(category, variant);
    const sel = state.ed[side];
    if (sel.part) {
      const mesh = picker.parts.find((m) => m.userData.label === sel.part && m.userData.k === (sel.k || 0)) ||
        picker.parts.find((m) => m.userData.label === sel.part);
      if (mesh) picker.select(mesh.userData.part, sel.surface, { silent: true }); else picker.unselect();
    }
    picker.loadedAt = performance.now();
  } catch (e) {
    say(`preview of ${category}: ${e.message}`, "bad");
  }
}

function chooseChild(id) {
  $("#child-object").value = id;
  setSide("child", id);
  $("#editor").scrollIntoView({ block: "nearest" });
}

function updateReadouts() {
  const rel = state.relations[state.ed.relation];
  const objectLevel = rel && rel.kind === "object";
  for (const side of ["child", "parent"]) {
    const sel = state.ed[side];
    const text = refOf(sel, objectLevel);
    const out = $(`#${side}-ref`);
    out.textContent = text || "—";
    out.dataset.ref = text;
    const part = !!(sel.part && !objectLevel && !isRoom(sel.object || ""));
    document.querySelectorAll(`#${side}-surfaces button`).forEach((b) => {
      b.disabled = !part;
      b.classList.toggle("on", !!(part && (b.dataset.surface || null) === (sel.surface || null)));
    });
    $(`#${side}-exact-wrap`).hidden = !(part && sel.count > 1);
    $(`#${side}-exact`).checked = !!sel.exact;
    if (sel.exact !== undefined) $(`#${side}-exact-k`).textContent = `#${sel.k}`;
  }
  $("#kind-note").textContent = rel ? `${rel.kind}: ${rel.meaning} — ${rel.constraints}` +
    (objectLevel ? " (relates whole objects: parts and surfaces are not used)" : "") +
    (rel.child_surface ? ` · default surfaces ${rel.child_surface} → ${rel.parent_surface}` : "") : "";
  // room elements the relation cannot use as parent are greyed out (ON: only the floor, ...)
  const allowed = new Set(rel ? rel.room_parents : []);
  for (const opt of document.querySelectorAll("#parent-object optgroup[label='room'] option")) {
    const key = /^wall_\d+$/.test(opt.value) ? "wall_i" : opt.value;
    opt.disabled = !allowed.has(key);
  }
  const parentOk = !isRoom(state.ed.parent.object || "") || allowed.has(/^wall_\d+$/.test(state.ed.parent.object) ? "wall_i" : state.ed.parent.object);
  $("#add-relation").disabled = !(state.ed.child.object && state.ed.parent.object && parentOk);
  $("#add-relation").title = parentOk ? "" : `${state.ed.relation} cannot use ${state.ed.parent.object} as parent`;
}

function renderParams() {
  const rel = state.relations[state.ed.relation];
  const box = $("#params");
  box.replaceChildren();
  for (const p of rel.params) {
    const range = p.low !== null ? ` (${p.low}–${p.high}${p.unit ? " " + p.unit : ""})` : "";
    let input;
    if (p.type === "enum") {
      input = h("select", { "data-param": p.name },
        p.required ? h("option", { value: "" }, "— choose —") : null,
        ...p.choices.map((c) => h("option", { value: c, selected: c === p.default }, c)));
    } else if (p.type === "range") {
      input = h("span", { class: "range", "data-param": p.name },
        ...[0, 1].map((k) => h("input", { type: "number", step: "any", min: p.low, max: p.high, value: p.default[k], "data-k": k, size: 5 })));
    } else {
      input = h("input", { type: "number", step: "any", min: p.low, max: p.high, value: p.default ?? "", "data-param": p.name, size: 6 });
    }
    box.append(h("label", { class: "param-field", title: p.doc }, `${p.name}${p.required ? " *" : ""}`, input,
      h("span", { class: "unit" }, `${p.unit}${range}`), h("small", {}, p.doc)));
  }
  if (!rel.params.length) box.append(h("small", {}, "no parameters"));
}

function readParams() {
  const rel = state.relations[state.ed.relation];
  const out = {};
  for (const p of rel.params) {
    const el = $(`[data-param="${p.name}"]`, $("#params"));
    let v;
    if (p.type === "range") {
      const [a, b] = [...el.querySelectorAll("input")].map((i) => Number(i.value));
      v = a === b ? a : [a, b];
      if (Array.isArray(p.default) && a === p.default[0] && b === p.default[1]) continue;
    } else if (p.type === "enum") {
      if (!el.value) continue;
      v = el.value;
      if (v === p.default) continue;
    } else {
      if (el.value === "") continue;
      v = Number(el.value);
      if (v === p.default) continue;
    }
    out[p.name] = v;
  }
  return out;
}

function addRelation() {
  const rel = state.relations[state.ed.relation];
  const objectLevel = rel.kind === "object";
  const r = { relation: rel.name, child: refOf(state.ed.child, objectLevel), parent: refOf(state.ed.parent, objectLevel), ...readParams() };
  state.doc.relations.push(r);
  changed();
  say(`added ${r.child} ${r.relation} ${r.parent}`);
}

function setupEditor() {
  const relSel = $("#relation");
  for (const kind of ["support", "part", "object"]) {
    relSel.append(h("optgroup", { label: kind },
      ...state.vocab.relations.filter((r) => r.kind === kind).map((r) => h("option", { value: r.name, title: r.meaning }, r.name))));
  }
  relSel.value = state.ed.relation;
  relSel.addEventListener("change", () => { state.ed.relation = relSel.value; renderParams(); updateReadouts(); });
  renderParams();
  for (const side of ["child", "parent"]) {
    pickers[side] = new AssetPicker($(`#${side}-preview`), {
      onPick: (info) => {
        const sel = state.ed[side];
        Object.assign(sel, { part: info.label, k: info.k, count: info.count, surface: info.surface });
        updateReadouts();
        sel.pickedAt = performance.now();
      },
      onHover: (info, arrow) => {
        $(`#${side}-hint`).textContent = arrow ? `surface: ${arrow} (click to choose it)` :
          info ? `${info.label}${info.count > 1 ? ` (${info.part})` : ""} · click to pick the part` :
          "click a part; then an arrow to choose a surface other than the default";
      },
    });
    $(`#${side}-object`).addEventListener("change", (e) => setSide(side, e.target.value));
    $(`#${side}-variant`).addEventListener("change", () => loadPreview(side));
    const bar = $(`#${side}-surfaces`);
    bar.append(h("button", { class: "small", "data-surface": "", title: "the relation's default surface", onclick: () => pickSurface(side, null) }, "default"));
    for (const s of SURFACES) bar.append(h("button", { class: `small surf surf-${s}`, "data-surface": s, onclick: () => pickSurface(side, s) }, s));
    $(`#${side}-whole`).addEventListener("click", () => { const o = state.ed[side].object; state.ed[side] = { object: o }; pickers[side].unselect(); updateReadouts(); });
    $(`#${side}-exact`).addEventListener("change", (e) => { state.ed[side].exact = e.target.checked; updateReadouts(); });
  }
  $("#add-relation").addEventListener("click", addRelation);
}

function pickSurface(side, surface) {
  const sel = state.ed[side];
  if (!sel.part) return;
  sel.surface = surface;
  const picker = pickers[side];
  if (picker.selected) picker.select(picker.selected.mesh.userData.part, surface, { silent: true });
  updateReadouts();
}

// ------------------------------------------------------------------ files and templates
function download(name, text, type) {
  const a = h("a", { href: URL.createObjectURL(new Blob([text], { type })), download: name });
  document.body.append(a);
  a.click();
  a.remove();
}

async function refreshFiles() {
  const res = await api.files();
  $("#files").replaceChildren(h("option", { value: "" }, res.files.length ? "— open a file —" : "(no PAG files yet)"),
    ...res.files.map((f) => h("option", { value: f.name }, f.name)));
  $("#workdir").textContent = res.workdir;
}

function setDoc(doc) {
  const shape = (k, ok) => doc[k] === undefined || ok(doc[k]);
  if (!shape("objects", Array.isArray) || !shape("relations", Array.isArray) ||
      !shape("room", (r) => r && typeof r === "object" && !Array.isArray(r)) ||
      (doc.room && doc.room.footprint !== undefined && !Array.isArray(doc.room.footprint))) {
    throw new Error("this file's objects, relations or room are not shaped like a PAG: fix it in a text editor (parse3d validate FILE says where)");
  }
  state.doc = doc;
  state.doc.objects ||= [];
  state.doc.relations ||= [];
  state.doc.room ||= { type: "", footprint: [], height: 2.7 };
  state.doc.room.footprint ||= [];
  for (const o of state.doc.objects) if (!o || typeof o !== "object") throw new Error("an object of this file is not a JSON object");
  for (const r of state.doc.relations) if (!r || typeof r !== "object") throw new Error("a relation of this file is not a JSON object");
  state.ed = { child: {}, parent: {}, relation: state.ed.relation };
  setSide("child", ""); setSide("parent", "");
  renderRoom();
  changed({ record: false });
  resetHistory();
  state.dirty = false;
}

// Unsaved edits are never dropped silently.
const discardOk = () => !state.dirty || confirm("The PAG has unsaved changes. Discard them?");

function setupFiles() {
  $("#save").addEventListener("click", async () => {
    const name = $("#file-name").value.trim();
    try {
      let res;
      try {
        res = await api.save(name, state.doc, false);
      } catch (e) {
        if (e.status !== 409 || !confirm(`${name} exists. Replace it?`)) throw e;
        res = await api.save(name, state.doc, true);
      }
      state.dirty = false;
      say(`saved ${res.name} (${res.bytes} bytes)${res.valid ? "" : ` — it has ${res.problems.length} problem(s)`}`, res.valid ? "good" : "bad");
      refreshFiles();
    } catch (e) { say(`save: ${e.message}`, "bad"); }
  });
  $("#open").addEventListener("click", async () => {
    const name = $("#files").value;
    if (!name || !discardOk()) return;
    try {
      const res = await api.load(name);
      if (!res.pag || typeof res.pag !== "object" || Array.isArray(res.pag)) throw new Error("the file does not hold a PAG object");
      setDoc(res.pag);
      $("#file-name").value = name;
      say(`opened ${name}`);
    } catch (e) { say(`open: ${e.message}`, "bad"); }
  });
  for (const fmt of ["json", "yaml"]) {
    $(`#download-${fmt}`).addEventListener("click", async () => {
      try {
        const text = await api.convert(state.doc, fmt);
        download(`${state.doc.name || "pag"}.${fmt}`, text, fmt === "json" ? "application/json" : "application/yaml");
      } catch (e) { say(`download: ${e.message}`, "bad"); }
    });
  }
  $("#new").addEventListener("click", () => { if (discardOk()) setDoc(newDoc()); });
  window.addEventListener("beforeunload", (e) => { if (state.dirty) { e.preventDefault(); e.returnValue = ""; } });
  $("#load-templates").addEventListener("click", async () => {
    const ts = await api.templates();
    const groups = {};
    for (const t of ts) (groups[t.room_type] ||= []).push(t);
    $("#templates").replaceChildren(...Object.entries(groups).map(([rt, list]) =>
      h("optgroup", { label: rt }, ...list.map((t) => h("option", { value: t.name, title: t.description }, t.name)))));
    $("#templates-row").hidden = false;
    $("#load-templates").hidden = true;
  });
  $("#expand").addEventListener("click", async () => {
    const name = $("#templates").value;
    try {
      const doc = await api.expand(name, Number($("#template-seed").value || 0));
      if (!discardOk()) return;
      setDoc(doc);
      $("#file-name").value = `${doc.name}.json`;
      say(`expanded ${name}: ${doc.objects.length} objects, ${doc.relations.length} relations`);
    } catch (e) { say(`template: ${e.message}`, "bad"); }
  });
  refreshFiles();
}

// ------------------------------------------------------------------ solving and viewing
let viewer;
function solve(seed) {
  $("#seed").value = seed;
  const stages = $("#stages");
  stages.replaceChildren(...state.vocab.stages.map((s) => h("li", { "data-stage": s, class: "pending" }, s, h("span", { class: "secs" }))));
  $("#solve").disabled = $("#solve-again").disabled = true;
  $("#solve-status").textContent = "solving…";
  $("#scene-info").replaceChildren();
  const t0 = performance.now();
  const settle = $("#settle").checked;
  const done = () => { $("#solve").disabled = $("#solve-again").disabled = false; };
  api.solve(state.doc, seed, settle).then(({ job }) => {
    state.job = job;
    let placed = 0;
    follow(job, {
      stage: (ev) => {
        const li = $(`li[data-stage="${ev.stage}"]`, stages);
        if (!li) return;
        li.className = ev.status;
        if (ev.seconds !== undefined) $(".secs", li).textContent = ` ${ev.seconds.toFixed(2)} s`;
      },
      object: (ev) => { if (ev.status === "placed") placed++; $("#solve-status").textContent = `placed ${placed}…`; },
      error: (ev) => {
        done();
        $("#solve-status").textContent = `failed: ${ev.message}`;
        if (ev.problems && ev.problems.length) { state.problems = ev.problems; showProblems(); }
        const li = ev.stage && $(`li[data-stage="${ev.stage}"]`, stages);
        if (li) li.className = "failed";
      },
      done: async (ev) => {
        const res = await api.job(job);
        state.result = res.result;
        await viewer.load(api.fileUrl(job, "scene.glb"), res.result);
        done();
        const secs = ((performance.now() - t0) / 1000).toFixed(2);
        $("#solve-status").textContent = `${ev.placed}/${ev.objects} objects placed` +
          (ev.failed.length ? ` — failed: ${ev.failed.map((f) => `${f.id} (${f.reason})`).join("; ")}` : "") + ` · ${secs} s`;
        $("#solve-status").dataset.done = "1";
        $("#downloads").replaceChildren(...res.result.files.map((f) => h("a", { href: api.fileUrl(job, f), download: f }, f)));
        window.designer.lastSolveMs = performance.now() - t0;
      },
    });
  }).catch((e) => { done(); $("#solve-status").textContent = `failed: ${e.message}`; });
}

function showSelection(sel) {
  const box = $("#scene-info");
  if (!sel) return box.replaceChildren(h("small", {}, "click an object to see its relations"));
  const o = sel.object || {};
  const mark = (v) => (v === true ? h("span", { class: "ok" }, "✓") : v === false ? h("span", { class: "no" }, "✗") : h("span", {}, "–"));
  box.replaceChildren(
    h("h4", {}, `${o.id} `, h("small", {}, `${o.category} · ${o.status}${o.reason ? `: ${o.reason}` : ""}`)),
    h("table", { class: "checks" },
      h("tr", {}, h("th", {}, "relation"), h("th", {}, "solved"), h("th", {}, "settled")),
      ...sel.relations.map((r) => h("tr", { title: r.detail || "" },
        h("td", {}, `${r.child} ${r.relation} ${r.parent}`), h("td", {}, mark(r.holds)), h("td", {}, mark(r.holds_settled))))),
    h("div", {}, h("small", {}, `${sel.contacts.length} part contact(s): `),
      h("small", {}, sel.contacts.map((c) => `${c.a} – ${c.b}`).join(", "))));
}

function setupSolve() {
  viewer = new SceneViewer($("#viewer"), { onSelect: showSelection });
  window.designer.viewer = viewer;
  $("#solve").addEventListener("click", () => solve(Number($("#seed").value || 0)));
  $("#solve-again").addEventListener("click", () => solve(Number($("#seed").value || 0) + 1));
  $("#contacts").addEventListener("change", (e) => viewer.showContacts(e.target.checked));
  showSelection(null);
}

// ------------------------------------------------------------------ reference image
// A photo of the room to design from (the paper's workflow: a PAG written from a real image),
// kept beside the scene viewer. It stays in this browser (session storage), not in the PAG.
const REFERENCE_KEY = "parse3d-reference";

function showReference(url, name) {
  const box = $("#reference");
  box.replaceChildren();
  box.classList.toggle("empty", !url);
  $("#reference-clear").hidden = !url;
  if (!url) {
    box.append(h("small", {}, "Load a photo of the room (or drop or paste one here) to design its PAG beside it."));
    return;
  }
  const img = h("img", { src: url, alt: name || "reference image", id: "reference-img" });
  img.addEventListener("load", () => { window.designer.referenceLoaded = name || "image"; });
  box.append(img);
}

function loadReference(file) {
  if (!file || !file.type.startsWith("image/")) return say("reference: choose an image file (PNG, JPEG, …)", "bad");
  const reader = new FileReader();
  reader.onload = () => {
    showReference(reader.result, file.name);
    try { sessionStorage.setItem(REFERENCE_KEY, JSON.stringify({ url: reader.result, name: file.name })); } catch { /* too large to keep */ }
    say(`reference image: ${file.name}`);
  };
  reader.onerror = () => say(`reference: could not read ${file.name}`, "bad");
  reader.readAsDataURL(file);
}

function setupReference() {
  $("#reference-file").addEventListener("change", (e) => loadReference(e.target.files[0]));
  $("#reference-clear").addEventListener("click", () => {
    sessionStorage.removeItem(REFERENCE_KEY);
    $("#reference-file").value = "";
    showReference(null);
  });
  const box = $("#reference");
  box.addEventListener("dragover", (e) => e.preventDefault());
  box.addEventListener("drop", (e) => { e.preventDefault(); loadReference(e.dataTransfer.files[0]); });
  document.addEventListener("paste", (e) => {
    const item = [...(e.clipboardData?.items || [])].find((i) => i.type.startsWith("image/"));
    if (item) loadReference(item.getAsFile());
  });
  let kept = null;
  try { kept = JSON.parse(sessionStorage.getItem(REFERENCE_KEY) || "null"); } catch { kept = null; }
  showReference(kept && kept.url, kept && kept.name);
}

// ------------------------------------------------------------------ start
async function main() {
  state.vocab = await api.vocabulary();
  state.relations = Object.fromEntries(state.vocab.relations.map((r) => [r.name, r]));
  for (const c of state.vocab.categories) $("#categories").append(h("option", { value: c.name }, `${c.name} — ${c.placement}; parts: ${c.parts.join(", ")}`));
  setupRoom();
  setupEditor();
  setupFiles();
  setupSolve();
  setupUndo();
  setupReference();
  window.designer.pickers = pickers;
  $("#add-object").addEventListener("click", () => addObject($("#add-category").value));
  $("#add-category").addEventListener("keydown", (e) => { if (e.key === "Enter") addObject(e.target.value); });
  renderRoom();
  changed({ record: false });
  resetHistory();
  state.dirty = false;
  document.body.dataset.ready = "1";
  window.designer.readyAt = performance.now();
}

main().catch((e) => say(`could not start: ${e.message}`, "bad"));
