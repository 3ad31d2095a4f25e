// Thin client of the designer's JSON API. Every error becomes an Error whose message is the
// server's one-line explanation, with .status and .problems attached.

async function call(method, url, body) {
  const opts = { method, headers: {} };
  if (body !== undefined) {
    opts.headers["Content-Type"] = "application/json";
    opts.body = JSON.stringify(body);
  }
  const res = await fetch(url, opts);
  const type = res.headers.get("content-type") || "";
  const data = type.includes("json") ? await res.json() : await res.text();
  if (!res.ok) {
    const err = new Error((data && data.error) || `${res.status} ${res.statusText}`);
    err.status = res.status;
    err.problems = (data && data.problems) || [];
    throw err;
  }
  return data;
}

export const api = {
  vocabulary: () => call("GET", "/api/vocabulary"),
  validate: (pag) => call("POST", "/api/validate", pag),
  // the text a saved file would hold (JSON one object or relation per line, or YAML)
  convert: async (pag, to) => {
    const res = await fetch(`/api/convert?to=${to}`, {
      method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(pag),
    });
    if (!res.ok) throw new Error((await res.json()).error || res.statusText);
    return res.text();
  },
  solve: (pag, seed, settle) => call("POST", "/api/solve", { pag, seed, settle }),
  job: (id) => call("GET", `/api/jobs/${id}`),
  templates: () => call("GET", "/api/templates"),
  expand: (name, seed) => call("POST", `/api/templates/${encodeURIComponent(name)}/expand`, { seed }),
  files: () => call("GET", "/api/files"),
  load: (name) => call("GET", `/api/files/${encodeURIComponent(name)}`),
  save: (name, pag, overwrite) =>
    call("PUT", `/api/files/${encodeURIComponent(name)}`, { pag, overwrite }),
  assetUrl: (category, variant) =>
    `/api/assets/${encodeURIComponent(category)}.glb` +
    (variant ? `?variant=${encodeURIComponent(variant)}` : ""),
  fileUrl: (job, name) => `/api/jobs/${job}/files/${name}`,
};

// Follow a solve job's server-sent events; handlers: {stage, object, done, error}.
export function follow(job, handlers) {
  const es = new EventSource(`/api/jobs/${job}/events`);
  for (const type of ["stage", "object", "done", "error"]) {
    es.addEventListener(type, (ev) => {
      const data = JSON.parse(ev.data);
      if (type === "done" || type === "error") es.close();
      if (handlers[type]) handlers[type](data);
    });
  }
  es.onerror = () => {
    if (es.readyState === EventSource.CLOSED) return;
    es.close();
    if (handlers.error) handlers.error({ message: "lost the connection to the server" });
  };
  return es;
}
