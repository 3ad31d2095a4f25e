// Build the designer's front end into the Python package (src/parse3d/web/static/):
// copies our modules, and three.js with the few addons we use from node_modules into
// static/vendor/, so that installing parse3d needs no node and the page needs no CDN.
import { cpSync, mkdirSync, rmSync, readdirSync, readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const out = join(here, "..", "src", "parse3d", "web", "static");
const three = join(here, "node_modules", "three");
const ADDONS = ["controls/OrbitControls.js", "loaders/GLTFLoader.js", "utils/BufferGeometryUtils.js"];

rmSync(out, { recursive: true, force: true });
mkdirSync(join(out, "vendor", "addons"), { recursive: true });
for (const f of readdirSync(join(here, "src"))) cpSync(join(here, "src", f), join(out, f));
cpSync(join(three, "build", "three.module.min.js"), join(out, "vendor", "three.module.min.js"));
cpSync(join(three, "LICENSE"), join(out, "vendor", "LICENSE"));
for (const a of ADDONS) {
  mkdirSync(dirname(join(out, "vendor", "addons", a)), { recursive: true });
  cpSync(join(three, "examples", "jsm", a), join(out, "vendor", "addons", a));
}
const version = JSON.parse(readFileSync(join(three, "package.json"), "utf8")).version;
console.log(`built ${out} with three.js ${version}`);
