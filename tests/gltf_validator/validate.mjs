// Validate glTF/GLB files with the Khronos glTF validator; prints one JSON report per file.
// Usage: node validate.mjs FILE.glb [FILE.glb ...]
import { readFile } from "node:fs/promises";
import validator from "gltf-validator";

const reports = [];
for (const file of process.argv.slice(2)) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, { maxIssues: 100 });
  reports.push({ file, issues: report.issues });
}
process.stdout.write(JSON.stringify(reports) + "\n");
