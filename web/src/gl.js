// Whether to ask WebGL for multisampling. A software renderer (SwiftShader, llvmpipe: a machine
// without a GPU) pays for it on every frame, so it is off there; `?aa=1` or `?aa=0` in the page
// address decides instead.
let cached = null;

export function antialias() {
  if (cached !== null) return cached;
  const forced = new URLSearchParams(location.search).get("aa");
  if (forced === "0" || forced === "1") return (cached = forced === "1");
  let renderer = "";
  try {
    const gl = document.createElement("canvas").getContext("webgl2");
    const info = gl && gl.getExtension("WEBGL_debug_renderer_info");
    if (info) renderer = String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL));
    const lose = gl && gl.getExtension("WEBGL_lose_context");
    if (lose) lose.loseContext();
  } catch (e) {
    renderer = "";
  }
  return (cached = !/swiftshader|llvmpipe|software/i.test(renderer));
}
