// The Khronos glTF validator (npm "gltf-validator") over GLB files: `node web/validate_glb.mjs <file or
// folder>...` (a folder: every *.glb under it).  One line per file (errors, warnings, infos, the first
// messages); exit 1 when any file has an error or a warning, 2 when no GLB was given.
import { validateBytes } from "gltf-validator";
import { readFileSync, readdirSync, statSync } from "node:fs";
import { join } from "node:path";

function glbs(path) {
  if (!statSync(path).isDirectory()) return [path];
  return readdirSync(path, { withFileTypes: true }).sort((a, b) => (a.name < b.name ? -1 : 1)).flatMap(d =>
    d.isDirectory() && !d.name.startsWith(".") ? glbs(join(path, d.name)) : d.name.endsWith(".glb") ? [join(path, d.name)] : []);
}

const files = process.argv.slice(2).flatMap(glbs);
if (!files.length) { console.error("validate_glb: no GLB file given"); process.exit(2); }
let bad = 0;
for (const f of files) {
  const r = await validateBytes(new Uint8Array(readFileSync(f)), { maxIssues: 20 });
  const i = r.issues;
  const first = i.messages.filter(m => m.severity <= 1).slice(0, 3).map(m => `${m.code} ${m.pointer || ""}: ${m.message}`);
  if (i.numErrors || i.numWarnings) bad++;
  console.log(`${f}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos` + (first.length ? "; " + first.join("; ") : ""));
}
console.log(`${files.length} GLB file(s), ${bad} with errors or warnings`);
process.exit(bad ? 1 : 0);
